"""Heights where a flat face of a convex polyhedron meets a quadric leaf and the section area
along the sweep is not smooth there.

A sphere, an ellipsoid, a truncus (cylinder, cone, frustum) or an elliptic truncus is the affine
image ``x = c + M y`` of a canonical quadric solid: the unit ball, or the truncus of axis z from
``y_z = -1/2`` (radius ``r2``) to ``y_z = +1/2`` (radius ``r1``), whose lateral surface is
``y_x^2 + y_y^2 = (k y_z + m)^2`` with ``k = r1 - r2``, ``m = (r1 + r2) / 2``. A face's plane
meets it in a conic. The area of the sections ``w . x = z`` of a tree holding both leaves turns a
corner or has a square-root singularity where the sweep plane is tangent to that conic (the
plane's trace in the section touches the quadric's section: a part of the solid starts, ends or
pinches off there), where a rim of the truncus crosses the face, and where an edge of the face
pierces the quadric's surface or an end disc. None of these is a leaf's own breakpoint: without
them a piece of the sweep can hold a sliver of solid that no quadrature node sees.

The tangencies are the points of the conic where the height's gradient within the plane is
normal to the conic: in 2D coordinates ``u`` of the plane, ``q(u) = u^T A u + b . u + c = 0`` and
height ``g . u``; ``g_perp . grad q(u) = 0`` is a line, which meets the conic in at most two points.
Every candidate is kept only when it lies on both solids (within ``1e-9`` of the scene's size): a
spurious height only splits the sweep once more.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..kinds.base import LeafForm, Primitive
from ..kinds.forms import AffineBall, AffineFrustum
from .leaf_table import leaf_table
from .program import Program, combine_masks
from .volume_parts import leaf_boxes

__all__ = ["face_events"]

_F = NDArray[np.float64]


def _canonical_quadric(prog: Program, i: int) -> tuple[NDArray[np.float64], NDArray[np.float64], float, float] | None:
    """``(c, M, r1, r2)`` of a round leaf (``r1 = r2 = nan`` for a ball or ellipsoid), else None."""
    tab = leaf_table(prog)
    k = tab.kind[i]
    if k == LeafForm.BALL:
        return tab.center[i], tab.radius[i] * np.eye(3), np.nan, np.nan
    if k == LeafForm.FRUSTUM:
        a = tab.axis[i]
        e1 = np.cross(a, np.eye(3)[int(np.argmin(np.abs(a)))])
        e1 /= np.linalg.norm(e1)
        M = np.column_stack([e1, np.cross(a, e1), tab.height[i] * a])
        return tab.center[i], M, float(tab.r1[i]), float(tab.r2[i])
    form = prog.leaves[i].exact_form()  # the kind's own affine image of a ball or a truncus
    if isinstance(form, AffineFrustum):
        return form.center, form.matrix, float(form.r1), float(form.r2)
    if isinstance(form, AffineBall):
        return form.center, form.linear, np.nan, np.nan
    return None


def _quadric(r1: float, r2: float) -> tuple[NDArray[np.float64], NDArray[np.float64], float]:
    """``(A, b, c)`` of the canonical surface ``y^T A y + b . y + c = 0``."""
    if np.isnan(r1):
        return np.eye(3), np.zeros(3), -1.0
    k, m = r1 - r2, 0.5 * (r1 + r2)
    return np.diag([1.0, 1.0, -k * k]), np.array([0.0, 0.0, -2.0 * k * m]), -m * m


def _roots(a: NDArray[np.float64], b: NDArray[np.float64], c: NDArray[np.float64]) -> NDArray[np.float64]:
    """Both real roots of ``a t^2 + b t + c`` per row, shape (n, 2) (NaN where none; a linear
    row's one root twice)."""
    disc = b * b - 4.0 * a * c
    big = np.maximum(np.abs(b), np.sqrt(np.abs(a * c)))
    lin = np.abs(a) <= 1e-14 * np.maximum(big, 1e-300)
    s = np.sqrt(np.where(disc >= 0.0, disc, np.nan))
    qq = -0.5 * (b + np.copysign(s, b))  # no cancellation
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        t1 = np.where(lin, -c / b, qq / a)
        t2 = np.where(lin, -c / b, c / qq)
    t = np.column_stack([t1, t2])
    return np.where(np.isfinite(t), t, np.nan)


def _plane_points(A: _F, b: _F, c: float, N: _F, D: _F, G: _F) -> _F:
    """Canonical points of the conics ``{q = 0, N . y = D}`` (one plane per row of ``N``) where the
    height ``G . y`` is stationary along the conic; shape (m, 3), NaN rows where there is none."""
    nn = np.linalg.norm(N, axis=1)
    Nh = N / nn[:, None]
    y0 = Nh * (D / nn)[:, None]
    ref = np.eye(3)[np.argmin(np.abs(Nh), axis=1)]
    e = np.cross(Nh, ref)
    e /= np.linalg.norm(e, axis=1)[:, None]
    f = np.cross(Nh, e)
    Y = np.stack([e, f], axis=2)  # (m, 3, 2)
    A2 = np.einsum("mia,ij,mjb->mab", Y, A, Y)
    b2 = 2.0 * np.einsum("mia,ij,mj->ma", Y, A, y0) + np.einsum("mia,i->ma", Y, b)
    c2 = np.einsum("mi,ij,mj->m", y0, A, y0) + y0 @ b + c
    g = np.einsum("mia,i->ma", Y, G)
    gp = np.column_stack([-g[:, 1], g[:, 0]])
    r = 2.0 * np.einsum("mab,mb->ma", A2, gp)  # the tangency line r . u = s
    s = -np.einsum("ma,ma->m", gp, b2)
    rn = np.linalg.norm(r, axis=1)
    ok = (np.linalg.norm(g, axis=1) > 1e-12 * np.linalg.norm(G)) & (rn > 1e-300)
    rn = np.where(ok, rn, 1.0)
    up = r * (s / rn**2)[:, None]
    v = np.column_stack([-r[:, 1], r[:, 0]]) / rn[:, None]
    qa = np.einsum("ma,mab,mb->m", v, A2, v)
    qb = 2.0 * np.einsum("ma,mab,mb->m", v, A2, up) + np.einsum("ma,ma->m", b2, v)
    qc = np.einsum("ma,mab,mb->m", up, A2, up) + np.einsum("ma,ma->m", b2, up) + c2
    tau = _roots(qa, qb, qc)
    tau[~ok] = np.nan
    u = up[:, None, :] + tau[:, :, None] * v[:, None, :]  # (m, 2, 2)
    return (y0[:, None, :] + np.einsum("mia,mka->mki", Y, u)).reshape(-1, 3)


def _rim_points(r1: float, r2: float, N: _F, D: _F) -> _F:
    """Canonical points where the end circles cross the planes ``N . y = D``."""
    out = []
    for sz, R in ((0.5, r1), (-0.5, r2)):
        if not R > 0.0:
            continue
        L = np.hypot(N[:, 0], N[:, 1])
        Ls = np.where(L > 1e-300, L, 1.0)
        d = np.where(L > 1e-300, (D - N[:, 2] * sz) / Ls, np.nan)
        h = np.sqrt(np.where(np.abs(d) <= R, R * R - d * d, np.nan))
        nx, ny = N[:, 0] / Ls, N[:, 1] / Ls
        for sg in (1.0, -1.0):
            out.append(np.column_stack([nx * d - sg * ny * h, ny * d + sg * nx * h, np.full(len(d), sz)]))
    return np.concatenate(out) if out else np.zeros((0, 3))


def _edge_points(A: _F, b: _F, c: float, r1: float, r2: float, P: _F, dP: _F) -> _F:
    """Canonical points where the segments ``P + t dP`` (t in [0, 1]) pierce the canonical surface
    or, for a truncus, its end discs."""
    qa = np.einsum("mi,ij,mj->m", dP, A, dP)
    qb = 2.0 * np.einsum("mi,ij,mj->m", P, A, dP) + dP @ b
    qc = np.einsum("mi,ij,mj->m", P, A, P) + P @ b + c
    ts = [_roots(qa, qb, qc)]
    if not np.isnan(r1):
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            ts.append(np.column_stack([(0.5 - P[:, 2]) / dP[:, 2], (-0.5 - P[:, 2]) / dP[:, 2]]))
    t = np.concatenate(ts, axis=1)
    t = np.where((t >= -1e-12) & (t <= 1.0 + 1e-12), t, np.nan)
    return (P[:, None, :] + t[:, :, None] * dP[:, None, :]).reshape(-1, 3)


def _on_truncus(y: NDArray[np.float64], r1: float, r2: float, eps: float) -> NDArray[np.bool_]:
    """Canonical points on (or within ``eps`` of) the closed canonical solid."""
    if np.isnan(r1):
        return np.einsum("ij,ij->i", y, y) <= (1.0 + eps) ** 2
    rho = r2 + (r1 - r2) * (y[:, 2] + 0.5)
    return (np.abs(y[:, 2]) <= 0.5 + eps) & (np.hypot(y[:, 0], y[:, 1]) <= rho + eps)


@functools.lru_cache(maxsize=1024)
def _faces(leaf: Any) -> tuple[_F, _F, _F, _F]:
    """Face planes ``(normals, offsets)`` and edges ``(starts, vectors)`` of a convex polyhedron."""
    polys = [np.asarray(p, dtype=np.float64) for p in leaf.face_polygons()]
    normals, offsets, starts, vecs = [], [], [], []
    for p in polys:
        n = np.cross(p[1:-1] - p[0], p[2:] - p[0]).sum(axis=0)
        n /= np.linalg.norm(n)
        normals.append(n)
        offsets.append(float(n @ p.mean(axis=0)))
        starts.append(p)
        vecs.append(np.roll(p, -1, axis=0) - p)
    return np.array(normals), np.array(offsets), np.concatenate(starts), np.concatenate(vecs)


def face_events(prog: Program, w: NDArray[np.float64]) -> NDArray[np.float64]:
    """Heights ``w . x`` (unsorted) of the tangencies, rim crossings and edge piercings between
    every quadric leaf and every convex polyhedral leaf whose boxes overlap (module docstring)."""
    tab = leaf_table(prog)
    k = tab.kind
    flat = np.nonzero((k == LeafForm.AXIS_BOX) | (k == LeafForm.HULL))[0]
    if not len(flat):
        return np.zeros(0)
    # a sphere or a truncus along w against a prism along w: circles against a fixed polygon, whose
    # events volume._crossing_events finds
    round_ = (k == LeafForm.BALL) | ((k == LeafForm.FRUSTUM) & (np.abs(tab.axis @ w) >= 1.0 - 1e-13))
    prism = {j: bool(np.all((d <= 1e-13) | (d >= 1.0 - 1e-13))) for j in flat.tolist()
             for d in [np.abs(_faces(prog.leaves[j])[0] @ w)]}
    todo = [i for i in range(len(k)) if not (round_[i] and all(prism.values()))]
    quads = {i: q for i in todo if (q := _canonical_quadric(prog, i)) is not None}
    if not quads:
        return np.zeros(0)
    boxes = leaf_boxes(prog)
    size = float(np.max(boxes[:, 1] - boxes[:, 0]))
    eps = 1e-9 * max(size, float(np.max(np.abs(boxes))))
    pts: list[NDArray[np.float64]] = []
    pairs: list[NDArray[np.int64]] = []
    for i, (c, M, r1, r2) in quads.items():
        meet = np.all((boxes[i, 0] <= boxes[flat, 1]) & (boxes[flat, 0] <= boxes[i, 1]), axis=1)
        if not meet.any():
            continue
        A, b, c0 = _quadric(r1, r2)
        Minv = np.linalg.inv(M)
        G = M.T @ w
        scale = float(np.max(np.abs(M)))
        for j in flat[meet].tolist():
            if round_[i] and prism[j]:
                continue
            nrm, off, P, dP = _faces(prog.leaves[j])
            N = nrm @ M
            D = off - nrm @ c
            with np.errstate(divide="ignore", invalid="ignore", over="ignore"):  # non-finite rows dropped below
                y = [_plane_points(A, b, c0, N, D, G),
                     _edge_points(A, b, c0, r1, r2, (P - c) @ Minv.T, dP @ Minv.T)]
                if not np.isnan(r1):
                    y.append(_rim_points(r1, r2, N, D))
            Y = np.concatenate(y)
            Y = Y[np.all(np.isfinite(Y), axis=1)]
            Y = Y[_on_truncus(Y, r1, r2, eps / scale)]
            x = c + Y @ M.T
            x = x[np.max(x @ nrm.T - off, axis=1) <= eps]
            pts.append(x)
            pairs.append(np.tile([i, j], (len(x), 1)))
    if not pts:
        return np.zeros(0)
    X, IJ = np.concatenate(pts), np.concatenate(pairs)
    return X[_visible(prog, X, IJ, boxes, eps)] @ w


def _reader(val: NDArray[np.bool_]) -> Callable[[int, Primitive], NDArray[np.bool_]]:
    def leaf(i: int, _p: Primitive) -> NDArray[np.bool_]:
        return val[i]

    return leaf


def _visible(prog: Program, X: NDArray[np.float64], IJ: NDArray[np.int64], boxes: NDArray[np.float64],
             eps: float) -> NDArray[np.bool_]:
    """The points ``X[k]`` (on leaves ``IJ[k]``) near which the tree's result depends on both leaves:
    elsewhere another leaf hides the pair (a point inside a leaf of a union, outside one of an
    intersection) and the area has no kink there. A point within ``eps`` of a third leaf is kept."""
    n = len(prog.leaves)
    inside = np.zeros((n, len(X)), dtype=bool)
    unsure = np.zeros(len(X), dtype=bool)
    for L in range(n):
        near = np.all((X >= boxes[L, 0] - eps) & (X <= boxes[L, 1] + eps), axis=1)
        near &= (IJ[:, 0] != L) & (IJ[:, 1] != L)
        if near.any():
            d = prog.leaves[L].signed_distance(X[near])
            inside[L, near] = d < 0.0
            unsure[near] |= np.abs(d) <= eps
    rows = np.arange(len(X))
    seen: list[NDArray[np.bool_]] = []
    for a, b in ((False, False), (True, False), (False, True), (True, True)):
        val = inside.copy()
        val[IJ[:, 0], rows] = a
        val[IJ[:, 1], rows] = b
        seen.append(prog.evaluate(_reader(val), combine_masks))
    on_i = (seen[0] != seen[1]) | (seen[2] != seen[3])
    on_j = (seen[0] != seen[2]) | (seen[1] != seen[3])
    return unsure | (on_i & on_j)
