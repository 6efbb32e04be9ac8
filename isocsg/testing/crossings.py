"""Where the rings of a patch cross the other leaves' surfaces: planes in closed form, curved
surfaces by sampling and bisection to rounding (:mod:`isocsg.testing.area`)."""

from __future__ import annotations

import math
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from ..kinds import Primitive
from .patches import Rings

__all__ = ["MAX_SPLITS", "SECTIONS", "Sections", "curved_crossings", "plane_crossings", "ring_boxes",
           "section_search", "state"]

F64 = NDArray[np.float64]
#: Most ring intervals per ring kept splitting at one level of the crossing search.
MAX_SPLITS = 64


class Sections(Protocol):
    """The leaves of a tree, its tolerance band and a leaf's state (in, on, out) at points."""

    @property
    def leaves(self) -> tuple[Primitive, ...]: ...

    @property
    def tol(self) -> float: ...

    def state(self, j: int, p: F64) -> NDArray[np.int8]: ...


def plane_crossings(rings: Rings, normals: F64, offsets: F64) -> tuple[NDArray[np.int64], F64]:
    """Where each ring meets each plane ``n . x = d`` (closed forms), as (ring, t) pairs."""
    nc, nA = rings.c @ normals.T, rings.A @ normals.T
    rhs = offsets[None, :] - nc
    k = len(rings.c)
    if rings.trig:
        nB = rings.B @ normals.T
        amp = np.hypot(nA, nB)
        ok = (amp > 0) & (np.abs(rhs) <= amp)
        base = np.arctan2(nB, nA)
        dl = np.arccos(np.clip(rhs / np.where(amp > 0, amp, 1.0), -1.0, 1.0))
        t = np.mod(np.concatenate([base + dl, base - dl], axis=1), 2 * math.pi)
        ok = np.concatenate([ok, ok], axis=1)
    else:
        ok = np.abs(nA) > 1e-14
        t = rhs / np.where(ok, nA, 1.0)
    ring = np.broadcast_to(np.arange(k)[:, None], t.shape)
    return ring[ok], t[ok]


def curved_crossings(
    tree: Sections, rings: Rings, leaves: list[int], samples: int,
) -> tuple[NDArray[np.int64], F64]:
    """Sign changes of curved leaves' signed distances along the rings, bisected to rounding.

    The rings are sampled at ``samples`` points; an interval without a sign change is split again
    while its ends' distances could hide two crossings between them (``|f_a| + |f_b|`` at most
    the arc's length bound: signed distances are 1-Lipschitz), down to 2**-30 of the ring, so that
    thin rods and slots are not stepped over; a ring that runs along a surface (more than
    ``MAX_SPLITS`` such intervals per ring) stops the splitting."""
    k = len(rings.c)
    u = np.linspace(0.0, 1.0, samples + 1)
    T = rings.t0[:, None] + (rings.t1 - rings.t0)[:, None] * u
    speed = np.linalg.norm(rings.A, axis=1) + (np.linalg.norm(rings.B, axis=1) if rings.trig else 0.0)
    lo_r, hi_r = ring_boxes(rings)
    out_r: list[NDArray[np.int64]] = []
    out_t: list[F64] = []
    for j in leaves:
        prim = tree.leaves[j]
        # a ring outside the leaf's box cannot cross its surface: most rings, most leaves
        box = np.asarray(prim.bounds, dtype=np.float64)
        pad = 1e-9 * (1.0 + float(np.max(np.abs(box)))) + tree.tol
        sel = np.flatnonzero(np.all((hi_r >= box[0] - pad) & (lo_r <= box[1] + pad), axis=1))
        if len(sel) == 0:
            continue
        n_sel = len(sel)
        Ts = T[sel]
        f = np.asarray(prim.signed_distance(rings.points(np.repeat(sel, samples + 1), Ts.ravel())))
        f = f.reshape(n_sel, samples + 1)
        r, ta, tb = np.repeat(sel, samples), Ts[:, :-1].ravel(), Ts[:, 1:].ravel()
        fa, fb = f[:, :-1].ravel(), f[:, 1:].ravel()
        found_r, found_a, found_b, found_s = [], [], [], []
        for level in range(30):
            sa, sb = state(fa, tree.tol), state(fb, tree.tol)
            change = sa != sb
            # an end on the surface (a sample on another face of the leaf, e.g. a truncus' end
            # plane on a round grid point) bisects to that end: a crossing between it and the
            # other end would be lost, so such an interval is searched further too
            one_on = (sa == 0) != (sb == 0)
            hidden = (~change | one_on) & (np.abs(fa) + np.abs(fb) <= 1.01 * speed[r] * (tb - ta) + tree.tol)
            hidden &= (np.abs(fa) > tree.tol) | (np.abs(fb) > tree.tol)  # on the surface: coincident
            # a ring that runs along a surface stops the splitting here
            last = not hidden.any() or hidden.sum() > MAX_SPLITS * k or level == 29
            keep = change if last else change & ~hidden  # (a change split further is kept at its last level)
            found_r.append(r[keep])
            found_a.append(ta[keep])
            found_b.append(tb[keep])
            found_s.append(sa[keep])
            if last:
                break
            r, ta, tb, fa, fb = r[hidden], ta[hidden], tb[hidden], fa[hidden], fb[hidden]
            tm = 0.5 * (ta + tb)
            fm = np.asarray(prim.signed_distance(rings.points(r, tm)))
            r = np.concatenate([r, r])
            ta, tb = np.concatenate([ta, tm]), np.concatenate([tm, tb])
            fa, fb = np.concatenate([fa, fm]), np.concatenate([fm, fb])
        ri = np.concatenate(found_r)
        if len(ri) == 0:
            continue
        lo, hi, sl = np.concatenate(found_a), np.concatenate(found_b), np.concatenate(found_s)
        lo, hi = section_search(tree, j, rings, ri, lo, hi, sl)
        out_r.append(ri)
        out_t.append(0.5 * (lo + hi))
    if not out_r:
        return np.zeros(0, np.int64), np.zeros(0)
    return np.concatenate(out_r), np.concatenate(out_t)


#: Points per bracket and step of the crossing search: 16 sections, 4 bits a step.
SECTIONS = 15


def section_search(
    tree: Sections, j: int, rings: Rings, ri: NDArray[np.int64], lo: F64, hi: F64, sl: NDArray[np.int8],
) -> tuple[F64, F64]:
    """Brackets ``[lo, hi]`` on rings ``ri`` whose ends' states differ (``sl`` at ``lo``) shrunk to
    rounding around a change of leaf ``j``'s state: bisection, ``SECTIONS`` points a step (one
    signed-distance call per step costs about the same for 15 points a bracket as for one, and
    takes 4 bits instead of 1: 13 steps instead of 52). The bracket kept is the first section
    whose right end's state differs from ``sl``, so the invariant and the precision are
    bisection's."""
    frac = np.arange(1, SECTIONS + 1) / (SECTIONS + 1)
    for _ in range(20):
        width = hi - lo
        t = lo[:, None] + width[:, None] * frac[None, :]
        st = tree.state(j, rings.points(np.repeat(ri, SECTIONS), t.ravel())).reshape(-1, SECTIONS)
        differs = st != sl[:, None]
        first = np.where(differs.any(axis=1), np.argmax(differs, axis=1), SECTIONS)  # section index 0..SECTIONS
        grid = np.concatenate([lo[:, None], t, hi[:, None]], axis=1)
        rows = np.arange(len(lo))
        lo, hi = grid[rows, first], grid[rows, first + 1]
        if np.all(hi - lo <= 4e-16 * np.maximum(np.abs(hi), 1.0)):
            break
    return lo, hi


def ring_boxes(rings: Rings) -> tuple[F64, F64]:
    """Boxes containing each ring: ``c + A cos t + B sin t`` lies within ``c +- sqrt(A^2 + B^2)``
    per coordinate; a segment ``c + A t`` between its ends."""
    if rings.trig:
        half = np.sqrt(rings.A**2 + rings.B**2)
        return rings.c - half, rings.c + half
    a = rings.c + rings.A * rings.t0[:, None]
    b = rings.c + rings.A * rings.t1[:, None]
    return np.minimum(a, b), np.maximum(a, b)


def state(sd: F64, tol: float) -> NDArray[np.int8]:
    return np.where(np.abs(sd) <= tol, 0, np.sign(sd)).astype(np.int8)  # type: ignore[no-any-return]
