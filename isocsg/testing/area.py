"""Surface area of primitives (closed forms) and of CSG trees (adaptive, with an error estimate).

Primitives
----------
Every kind has an exact area: a sphere ``4 pi r^2``; a truncus ``pi (r1 + r2) s + pi r1^2 + pi
r2^2`` with the slant ``s = sqrt((r1 - r2)^2 + h^2)``; a box ``2 (ab + bc + ca)``; a convex
polyhedron the sum of its faces; an ellipsoid ``4 pi abc R_G(1/a^2, 1/b^2, 1/c^2)`` with Carlson's
symmetric integral ``R_G`` (scipy's ``elliprf``, ``elliprd``); a torus ``4 pi^2 R r``; an elliptic
truncus its two elliptic ends plus a lateral area that is one periodic analytic integral over
the angle (the trapezoidal rule, doubled until two rules agree to 1e-15).

Trees
-----
The boundary of a regularised Boolean is made of pieces of the leaves' surfaces. A point ``p``
on leaf ``i``'s surface is on the result's boundary when the tree, evaluated just outside ``i``
(``i`` out) and just inside it (``i`` in), with every other leaf at its own state at ``p``,
gives two different answers. Each leaf's surface is swept as a family of rings
(:mod:`isocsg.testing.patches`); on each ring the points where another leaf's surface crosses
it are found (exactly for planar faces: the ring meets a plane at closed-form parameters; for
curved leaves by sampling ``samples`` points per ring and narrowing each sign change of the
signed distance to machine precision, 16 sections a step), every piece between crossings is
classified at its midpoint and its area density integrated (Gauss-Legendre), giving the ring's measure ``m(s)``.
``m`` is integrated over the sweep parameter by adaptive Gauss-Kronrod (7-15), split first at
the heights where other leaves start, end or have vertices (on a planar face also where two
other planes meet on it, each on its leaf's surface: the ring measure's kinks), and where the
rings' crossings or boundary pieces change in number (:mod:`isocsg.testing.kinks`: tangencies,
rims, a ring entering another leaf, located by bisection to rounding, and the sweep graded
towards each: the measure's form can change on a scale far below the interval's). All patches of
the tree are refined together, the worst intervals wherever they are, until the Kronrod-Gauss
differences add up to less than ``SAFETY * tol`` times the whole figure (the sum of the absolute
contributions, at least 1e-6 of the swept patches' whole area): a patch with nothing or little on
the boundary (a thin rod's end disc inside another leaf) is not refined to ``tol`` of its own
vanishing contribution. The reported error is that sum plus the area of pieces that could not be
decided (a midpoint on another surface at an angle); an interval whose error is mostly that
is split to ``UNDECIDED_DEPTH`` of its sweep only (a band along another surface is measured
again at every level; a node on a whole ring of another surface moves off it in a split or two).
A box or convex polyhedron whose neighbours are all boxes or convex polyhedra is not swept: its
faces' boundary parts are polygons (:mod:`isocsg.testing.planar`), exact up to a grid of 1e-12
of each face's size, with the area and the volume's share taken in one pass.

Coincident faces
----------------
Where another leaf ``j``'s surface passes through ``p`` (within 1e-11 of the scene's size)
with the same or the opposite normal (a planar leaf's normal is that of its face through
``p``, the one most parallel to ``i``'s where ``p`` is on an edge), ``j`` takes the side its
normal says (in on the side its interior is), so two boxes stacked in a union lose their
shared face and a face common to ``A`` and ``B`` in ``A - B`` is removed. A face shared by
several leaves is counted once, by the leaf of lowest index (the others skip it), and only
where the CSG rule keeps it. Where a curved surface only touches another (a sphere inscribed in
a cylinder), probes on either side tell the tangency from a coincidence, and the points of the
tolerance band take the side the surface is on (``_Tree._tangent_side``). The split test
assumes signed distances that are 1-Lipschitz (exact ones are); two crossings closer than
2**-30 of a ring (tangencies) are not in the error estimate.
"""

from __future__ import annotations

import heapq
import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._validation import integer, scalar
from ..csg.program import Program, combine_masks
from ..csg.section import solid_program
from ..errors import InvalidGeometryError, InvalidParameterError
from ..kinds import Primitive, Solid
from .crossings import curved_crossings, plane_crossings, state
from .kinks import graded, signature_breaks
from .patches import Patch, Rings, leaf_patches
from .planar import Neighbours, PlanarFace, face_boundary

__all__ = ["AreaResult", "boundary_figures", "boundary_volume", "closed_form_area", "surface_area"]

F64 = NDArray[np.float64]

# Gauss-Kronrod 7-15 on [-1, 1]
_XK = np.array([0.991455371120813, 0.949107912342759, 0.864864423359769, 0.741531185599394,
                0.586087235467691, 0.405845151377397, 0.207784955007898, 0.0])
_WK = np.array([0.022935322010529, 0.063092092629979, 0.104790010322250, 0.140653259715525,
                0.169004726639267, 0.190350578064785, 0.204432940075298, 0.209482141084728])
_WG = np.array([0.129484966168870, 0.279705391489277, 0.381830050505119, 0.417959183673469])
GK_X = np.concatenate([-_XK[:-1], _XK[::-1]])
GK_WK = np.concatenate([_WK[:-1], _WK[::-1]])
GK_WG = np.zeros(15)
GK_WG[[1, 3, 5, 7, 9, 11, 13]] = np.concatenate([_WG[:-1], _WG[::-1]])
# Gauss-Legendre on the pieces of a ring (the density is smooth there)
_GL_X, _GL_W = np.polynomial.legendre.leggauss(6)
#: Grid points per ring (pieces stay short, so the density's integral is exact to rounding).
RING_GRID = 17
#: Where another leaf's surface passes within this fraction of the scene's size, it is on it.
COINCIDENT = 1e-11
#: The changes of a patch's rings are located to this fraction of ``tol`` of its sweep (or to rounding).
LOCATE = 1e-9
#: A signed distance within this fraction of the scene's size may have the wrong sign.
ROUNDING = 1e-14
#: The planar faces' overlay is snap-rounded to this fraction of the face's size: GEOS' overlay
#: in floating point can silently lose a piece where edges nearly coincide (a union of three
#: valid polygons 0.03 short of their area, fuzz case 848); snap-rounding is robust.
SNAP = 1e-12
#: The Kronrod-Gauss differences must add up to this fraction of the error asked for: next to
#: the square-root ends of a chord family (a box face cut by a sphere) they understate the error
#: (by a factor 1.7 on a sphere's cap at 1e-9); cheap, since the intervals there shrink fast.
SAFETY = 0.1
#: An interval whose error is mostly undecided area is not split below this fraction of its sweep.
UNDECIDED_DEPTH = 2.0**-6
#: Most sweep intervals per patch before the integration returns what it has.
MAX_INTERVALS = 4000


@dataclass(frozen=True, slots=True)
class AreaResult:
    """A surface area and its error bound.

    Attributes
    ----------
    value : float
        Square metres.
    error : float
        Estimated absolute error (0 for a closed form).
    exact : bool
        Whether ``value`` is a closed form (exact to rounding).
    """

    value: float
    error: float
    exact: bool


def closed_form_area(prim: Primitive) -> float:
    """The exact surface area of a primitive (its :attr:`~isocsg.kinds.base.Primitive.area`).

    Raises
    ------
    InvalidParameterError
        For a kind without a closed form here (a kind registered by user code).

    Examples
    --------
    >>> from isocsg import Cylinder, Sphere
    >>> round(closed_form_area(Sphere((0, 0, 0), 1)) / math.pi, 12)
    4.0
    >>> round(closed_form_area(Cylinder((0, 0, 0), (0, 0, 2), 1)) / math.pi, 12)
    6.0
    """
    return prim.area


def _planes(prim: Primitive) -> tuple[F64, F64] | None:
    """The planes ``n . x = d`` of a leaf's flat parts (a truncus' ends too), or None."""
    planes = prim.flat_face_planes()
    if planes is None:
        return None
    return np.asarray(planes[0], dtype=np.float64), np.asarray(planes[1], dtype=np.float64)


class _Tree:
    """What the ring classification needs of the tree: its program, boxes, planes and tolerance."""

    def __init__(self, prog: Program) -> None:
        self.prog = prog
        self.leaves = prog.leaves
        boxes = np.stack([np.asarray(p.bounds, dtype=np.float64) for p in self.leaves])
        self.lo, self.hi = boxes[:, 0], boxes[:, 1]
        scale = float(max(np.max(self.hi - self.lo), np.max(np.abs(boxes))))
        self.tol = COINCIDENT * scale
        self.step = 1e-7 * scale
        #: the tangency probes' distance: at 1e-4 of the size, sd differences of 5e-9 of the size at
        #: unit relative curvature, far above the tolerance
        self.probe = 1e-4 * scale
        #: below this, a signed distance's sign is rounding (a point's coordinates carry 1e-16 of the size)
        self.rounding = ROUNDING * scale
        self._same: dict[tuple[int, int], bool] = {}
        self.last_inside_minus = np.zeros(0, bool)
        # every part of the surface flat, and the planes all of it (a convex polytope)
        self.planar = [bool(p.polyhedral and p.convex) for p in self.leaves]
        self.planes = [_planes(p) for p in self.leaves]
        self.seeds: list[F64] = []  # points where rings crossed other leaves' surfaces (:mod:`.kinks`)

    def relevant(self, i: int) -> NDArray[np.int64]:
        """The leaves other than ``i`` whose boxes meet ``i``'s (grown by the tolerance)."""
        g = self.tol
        meet = np.all((self.lo <= self.hi[i] + g) & (self.hi >= self.lo[i] - g), axis=1)
        meet[i] = False
        return np.flatnonzero(meet)

    def normals(self, j: int, p: F64, toward: F64 | None = None) -> F64:
        """Leaf ``j``'s outward unit normals at points on its surface. On a planar leaf, the
        normal of a face the point is on (within the tolerance), of those the one most parallel
        to ``toward`` (at an edge, the face that may coincide with the point's own); without
        ``toward`` or off a planar leaf, central differences of its signed distance (O(step^2) on
        curved surfaces; within a step of an edge they would mix two faces)."""
        prim = self.leaves[j]
        faces = self.planes[j]
        if toward is not None and self.planar[j] and faces is not None:
            N, D = faces
            dist = np.abs(p @ N.T - D)
            fit = np.where(dist <= self.tol, np.abs(toward @ N.T), -1.0 - dist)  # else the nearest
            return N[np.argmax(fit, axis=1)]  # type: ignore[no-any-return]
        h = self.step
        g = np.empty_like(p)
        for k in range(3):
            e = np.zeros(3)
            e[k] = h
            g[:, k] = prim.signed_distance(p + e) - prim.signed_distance(p - e)
        n = np.linalg.norm(g, axis=1, keepdims=True)
        g[n[:, 0] == 0] = (0.0, 0.0, 1.0)  # a centre: every direction is a nearest one
        return g / np.where(n > 0, n, 1.0)  # type: ignore[no-any-return]

    def classify(
        self, i: int, rel: NDArray[np.int64], p: F64, n: F64, *, owner: bool = True,
    ) -> tuple[NDArray[np.bool_], NDArray[np.bool_]]:
        """For points ``p`` on leaf ``i`` with its normals ``n``: on the result's boundary (and,
        with ``owner``, counted by ``i``: a coincident leaf of lower index counts it), and undecided."""
        m = len(p)
        plus: dict[int, NDArray[np.bool_]] = {i: np.zeros(m, bool)}
        minus: dict[int, NDArray[np.bool_]] = {i: np.ones(m, bool)}
        skip = np.zeros(m, bool)
        undecided = np.zeros(m, bool)
        for j in rel.tolist():
            sd = self.leaves[j].signed_distance(p)
            ins = sd < 0
            pl, mi = ins.copy(), ins.copy()
            on = np.flatnonzero(np.abs(sd) <= self.tol)
            if len(on):
                d = np.einsum("ij,ij->i", self.normals(j, p[on], n[on]), n[on])
                same, opp = d > 1 - 1e-6, d < -(1 - 1e-6)
                if not (self.planar[i] and self.planar[j]) and not self._equal(i, j):  # planes: coincide or cross
                    side = self._tangent_side(i, j, p[on], n[on], np.where(opp, -1.0, 1.0), same | opp)
                    touch = side != 0
                    pl[on[touch]] = mi[on[touch]] = side[touch] < 0
                    on, same, opp = on[~touch], same[~touch], opp[~touch]
                pl[on] = opp
                mi[on] = same
                if owner and j < i:
                    skip[on[same | opp]] = True
                undecided[on[~(same | opp)]] = True
            plus[j], minus[j] = pl, mi
        empty = np.zeros(m, bool)
        rp = self.prog.evaluate(lambda a, _: plus.get(a, empty), combine_masks)
        rm = self.prog.evaluate(lambda a, _: minus.get(a, empty), combine_masks)
        self.last_inside_minus = rm  # the result's side: outward normal n where it lies on the minus side
        return (rp != rm) & ~skip, undecided

    def _equal(self, i: int, j: int) -> bool:
        """Whether leaves ``i`` and ``j`` are the same primitive (their surfaces coincide everywhere)."""
        key = (min(i, j), max(i, j))
        if key not in self._same:
            self._same[key] = bool(self.leaves[i] == self.leaves[j])
        return self._same[key]

    def _flat_at(self, j: int, p: F64, n: F64) -> NDArray[np.bool_]:
        """Whether leaf ``j``'s surface is flat at points ``p`` on it with normals ``+-n``: on one
        of its planes (a truncus' end too) with that plane's normal."""
        faces = self.planes[j]
        if faces is None:
            return np.zeros(len(p), bool)
        if self.planar[j]:
            return np.ones(len(p), bool)
        N, D = faces
        on = (np.abs(p @ N.T - D) <= self.tol) & (np.abs(n @ N.T) > 1 - 1e-6)
        return np.any(on, axis=1)  # type: ignore[no-any-return]

    def _tangent_side(
        self, i: int, j: int, p: F64, n: F64, sigma: F64, aligned: NDArray[np.bool_],
    ) -> NDArray[np.int8]:
        """For points ``p`` on leaf ``i`` (normals ``n``) within the tolerance of leaf ``j``'s
        surface with (anti)parallel normals (``aligned``; ``sigma`` -1 where opposite): -1 or +1
        (inside or outside ``j``) where the two surfaces only touch there, 0 where they coincide.

        Within the tolerance band of a tangency (about ``sqrt(2 r tol)`` wide: 5e-6 of the size
        at 1e-11, a sphere inscribed in a cylinder along its equator) the points were otherwise
        taken as on a coincident surface and dropped, with an error estimate that cannot see
        them. Probes ``q = p +- delta w`` along two tangent directions ``w``: ``D(q) = sd_j(q) -
        sigma sd_i(q)`` is ``sd_j`` at the point of ``i`` next to ``q``, 0 where the surfaces
        coincide and about ``delta^2 (k_i - k_j) / 2`` at a tangency (the curvatures along
        ``w``). Where both probes of one direction leave ``j`` to the same side, the surfaces touch
        and ``p`` is on that side; where they leave it to opposite sides (a tangency at ``j``'s
        rim, a sphere's equator on a cylinder's end circle), they cross at ``p`` and ``sd_j(p)``
        says its side (exact but for rounding: the band it cannot decide is about 1e-9 of the size
        wide). At the edge of a coincident region only the probe across the edge leaves ``j``.
        Two flat surfaces are coincident or cross: only a pair with a curved one is probed (a
        coincident region of two curved surfaces has smooth edges: their rims)."""
        out = np.zeros(len(p), np.int8)
        sel = np.flatnonzero(aligned & ~(self._flat_at(i, p, n) & self._flat_at(j, p, n)))
        if len(sel) == 0:
            return out
        p, n, sigma = p[sel], n[sel], sigma[sel]
        u = np.cross(n, np.where(np.abs(n[:, :1]) < 0.9, [[1.0, 0.0, 0.0]], [[0.0, 1.0, 0.0]]))
        u /= np.linalg.norm(u, axis=1, keepdims=True)
        v = np.cross(n, u)
        delta = self.probe
        prim_i, prim_j = self.leaves[i], self.leaves[j]
        side = np.zeros(len(p), np.int8)
        cross = np.zeros(len(p), bool)
        smooth, least = np.zeros(len(p), np.int8), np.full(len(p), np.inf)  # the quadratic probe's side
        rows = np.arange(len(p))
        for w in (u, v):
            q = np.concatenate([p + delta * w, p - delta * w])
            D = np.asarray(prim_j.signed_distance(q)) - np.tile(sigma, 2) * np.asarray(prim_i.signed_distance(q))
            s = state(D, self.tol).reshape(2, -1)
            both = (s[0] == s[1]) & (s[0] != 0) & (side == 0)
            side[both] = s[0][both]
            here = (s[0] * s[1]) < 0
            cross |= here
            aD = np.abs(D).reshape(2, -1)
            k = np.argmin(aD, axis=0)
            better = here & (aD[k, rows] < least)
            smooth[better], least[better] = s[k, rows][better], aD[k, rows][better]
        cross &= side == 0
        if cross.any():
            sd = np.asarray(prim_j.signed_distance(p[cross]))
            side[cross] = np.where(np.abs(sd) > self.rounding, np.sign(sd), smooth[cross]).astype(np.int8)
        out[sel] = side
        return out

    def state(self, j: int, p: F64) -> NDArray[np.int8]:
        return state(np.asarray(self.leaves[j].signed_distance(p)), self.tol)


def _ring_measure(
    tree: _Tree, patch: Patch, rel: NDArray[np.int64], planes: tuple[F64, F64] | None,
    curved: list[int], s: F64, samples: int, origin: F64 | None = None,
) -> tuple[F64, F64]:
    """The boundary measure ``m(s)`` of each ring (area per unit ``s``) and its undecided part."""
    rings = patch.rings(s)
    k = len(s)
    u = np.linspace(0.0, 1.0, RING_GRID)
    rs = [np.repeat(np.arange(k), RING_GRID)]
    grid = rings.t0[:, None] + (rings.t1 - rings.t0)[:, None] * u
    # the ends exactly: t0 + (t1 - t0) can round above t1, and the filter below would then drop
    # the ring's last piece (a sixteenth of it) at random rings
    grid[:, 0], grid[:, -1] = rings.t0, rings.t1
    ts = [grid.ravel()]
    ring, t = _with_crossings(tree, rings, planes, curved, samples, rs, ts)
    keep = (t >= rings.t0[ring]) & (t <= rings.t1[ring])
    ring, t = ring[keep], t[keep]
    order = np.lexsort((t, ring))
    ring, t = ring[order], t[order]
    piece = (ring[1:] == ring[:-1]) & (t[1:] > t[:-1])
    pr, a, b = ring[:-1][piece], t[:-1][piece], t[1:][piece]
    mid = 0.5 * (a + b)
    bound, undecided = tree.classify(patch.leaf, rel, rings.points(pr, mid), patch.normal(s[pr], mid))
    half = 0.5 * (b - a)
    tn = (mid[:, None] + half[:, None] * _GL_X[None, :]).ravel()
    orient = np.where(tree.last_inside_minus, 1.0, -1.0)
    sn = np.repeat(s[pr], len(_GL_X))
    dens = patch.weight(sn, tn)
    if origin is not None:  # the flux of x / 3 through the boundary: the volume (divergence theorem)
        pn = rings.points(np.repeat(pr, len(_GL_X)), tn) - origin
        dens = dens * np.einsum("ij,ij->i", pn, patch.normal(sn, tn)) / 3.0 * np.repeat(orient, len(_GL_X))
    w = dens.reshape(-1, len(_GL_X)) @ _GL_W * half
    m = np.bincount(pr, w * bound, minlength=k)
    und = np.bincount(pr, np.abs(w) * undecided, minlength=k)
    return m.astype(np.float64), und.astype(np.float64)


def _with_crossings(
    tree: _Tree, rings: Rings, planes: tuple[F64, F64] | None, curved: list[int], samples: int,
    rs: list[NDArray[np.int64]], ts: list[F64],
) -> tuple[NDArray[np.int64], F64]:
    """The ring numbers and parameters ``rs``, ``ts`` with the rings' crossings of the planar
    leaves' ``planes`` and of the ``curved`` leaves appended, as two flat arrays."""
    if planes is not None:
        r, t = plane_crossings(rings, *planes)
        rs.append(r)
        ts.append(t)
    if curved:
        r, t = curved_crossings(tree, rings, curved, samples)
        rs.append(r)
        ts.append(t)
    return np.concatenate(rs), np.concatenate(ts)


def _ring_signature(
    tree: _Tree, patch: Patch, rel: NDArray[np.int64], planes: tuple[F64, F64] | None,
    curved: list[int], s: F64, samples: int, undecided_only: bool = False,
) -> NDArray[np.int64]:
    """Per ring, an integer that changes where the ring measure's form does (:mod:`.kinks`): its
    crossings and its pieces on the boundary, counted (on a closed ring the piece through ``t = 0``
    once: a crossing passing through it changes nothing). Undecided pieces (on another surface at
    an angle, or within a central-difference step of its edge) are not counted: they flicker
    along coincident surfaces, where the integration's own rule for them applies."""
    rings = patch.rings(s)
    k = len(s)
    rs, ts = [np.arange(k), np.arange(k)], [rings.t0, rings.t1]
    ring, t = _with_crossings(tree, rings, planes, curved, samples, rs, ts)
    keep = (t >= rings.t0[ring]) & (t <= rings.t1[ring])
    crossed = keep.copy()
    crossed[:2 * k] = False
    if crossed.any():
        tree.seeds.append(rings.points(ring[crossed], t[crossed]))
    ring, t = ring[keep], t[keep]
    order = np.lexsort((t, ring))
    ring, t = ring[order], t[order]
    piece = (ring[1:] == ring[:-1]) & (t[1:] > t[:-1])
    pr, a, b = ring[:-1][piece], t[:-1][piece], t[1:][piece]
    if rings.trig and len(pr):  # the last piece of a closed ring is the first one's other half
        last = np.r_[pr[1:] != pr[:-1], True] & np.r_[False, pr[1:] == pr[:-1]]
        pr, a, b = pr[~last], a[~last], b[~last]
    mid = 0.5 * (a + b)
    bound, undecided = tree.classify(patch.leaf, rel, rings.points(pr, mid), patch.normal(s[pr], mid))
    n_piece = np.bincount(pr, minlength=k)
    if undecided_only:  # (the band of a crossing at an angle: :func:`.kinks.centre_bands`)
        return np.bincount(pr, undecided, minlength=k).astype(np.int64)  # type: ignore[no-any-return]
    n_bound = np.bincount(pr, bound & ~undecided, minlength=k).astype(np.int64)
    return n_piece * 65536 + n_bound  # type: ignore[no-any-return]


def _sweep_breaks(tree: _Tree, patch: Patch, rel: NDArray[np.int64]) -> F64:
    br = [patch.breaks]
    if patch.direction is not None and patch.s_of_height is not None:
        for j in rel.tolist():
            br.append(patch.s_of_height(np.asarray(tree.leaves[j].breakpoints(patch.direction), dtype=np.float64)))
    if tree.planar[patch.leaf] and patch.s_of_height is not None and patch.direction is not None:
        br.append(patch.s_of_height(_arrangement_heights(tree, patch, rel)))
    b = np.unique(np.concatenate(br))
    b = b[(b >= patch.s_lo) & (b <= patch.s_hi)]
    return np.unique(np.concatenate([[patch.s_lo, patch.s_hi], b]))


def _arrangement_heights(tree: _Tree, patch: Patch, rel: NDArray[np.int64]) -> F64:
    """Heights along the sweep direction of the points where two other planes meet on a planar
    face, each on its leaf's surface: where the lines that cut the face cross each other or the
    face's edges. The ring measure has kinks there (and only there, between leaves' vertices,
    when every leaf is planar); a Gauss-Kronrod interval across a kink converges slowly and its
    Kronrod-Gauss difference can understate its error."""
    i = patch.leaf
    own = tree.planes[i]
    assert own is not None
    n = patch.normal(np.zeros(1), np.zeros(1))[0]
    c = patch.rings(np.array([0.5 * (patch.s_lo + patch.s_hi)])).c[0]
    d = float(n @ c)
    owners = [j for j in [i, *rel.tolist()] if tree.planes[j] is not None]
    N = np.concatenate([tree.planes[j][0] for j in owners])  # type: ignore[index]
    D = np.concatenate([tree.planes[j][1] for j in owners])  # type: ignore[index]
    leaf = np.concatenate([np.full(len(tree.planes[j][1]), j) for j in owners])  # type: ignore[index]
    # only planes that reach the face (its vertices on both sides, or on the plane), not parallel to it
    r = patch.rings(np.asarray(patch.breaks, dtype=np.float64))
    m = len(r.c)
    corners = r.points(np.concatenate([np.arange(m), np.arange(m)]), np.concatenate([r.t0, r.t1]))
    side = corners @ N.T - D
    reach = (side.min(axis=0) <= tree.tol) & (side.max(axis=0) >= -tree.tol) & (np.abs(N @ n) < 1 - 1e-12)
    N, D, leaf = N[reach], D[reach], leaf[reach]
    a, b = np.triu_indices(len(D), 1)
    if len(a) == 0 or len(a) > 200_000:  # (a face crossed by hundreds of planes: left to the bisection)
        return np.zeros(0)
    M = np.stack([np.broadcast_to(n, (len(a), 3)), N[a], N[b]], axis=1)
    det = np.linalg.det(M)
    ok = np.abs(det) > 1e-12
    a, b, M = a[ok], b[ok], M[ok]
    rhs = np.stack([np.full(len(a), d), D[a], D[b]], axis=1)
    x = np.linalg.solve(M, rhs[:, :, None])[:, :, 0]
    near = 1e-9 * max(float(np.max(tree.hi - tree.lo)), 1.0)
    on = np.abs(np.asarray(tree.leaves[i].signed_distance(x))) <= near
    for j in np.unique(np.concatenate([leaf[a], leaf[b]])).tolist():
        if j == i:
            continue
        sel = np.flatnonzero(on & ((leaf[a] == j) | (leaf[b] == j)))
        if len(sel):
            on[sel] &= np.abs(np.asarray(tree.leaves[j].signed_distance(x[sel]))) <= near
    return x[on] @ patch.direction  # type: ignore[no-any-return]


class _PatchRule:
    """Gauss-Kronrod 7-15 over intervals of one patch's sweep parameter: the ring measure's
    integral, its Kronrod-Gauss difference, and the undecided pieces' area (or, with ``origin``,
    the patch's share of the volume)."""

    def __init__(
        self, tree: _Tree, patch: Patch, rel: NDArray[np.int64], samples: int, origin: F64 | None,
        known: F64 | None = None, resolution: float = 0.0,
    ) -> None:
        """``known``: the break points found for this patch before (the volume's sweep, for the
        area's); ``resolution``: the changes of the rings are located to this fraction of the sweep."""
        faces = [f for f in (tree.planes[j] for j in rel.tolist()) if f is not None]
        self.tree, self.patch, self.rel, self.samples, self.origin = tree, patch, rel, samples, origin
        self.curved = [j for j in rel.tolist() if not tree.planar[j]]
        self.planes = None
        if faces:
            self.planes = (np.concatenate([f[0] for f in faces]), np.concatenate([f[1] for f in faces]))
        br = _sweep_breaks(tree, patch, rel)
        self.span = patch.s_hi - patch.s_lo
        self.signature = lambda s: _ring_signature(tree, patch, rel, self.planes, self.curved, s, samples)
        self.undecided = lambda s: _ring_signature(tree, patch, rel, self.planes, self.curved, s, samples, True)
        self.kinks = np.zeros(0)  # the changes located (:mod:`.kinks`), graded towards before the sweep
        self.known, self.resolution = known is not None, resolution
        if known is not None:
            br = known
        elif len(rel):  # where the ring measure changes its form (kinks, square-root ends, jumps)
            br = self._with(br, signature_breaks(self.signature, br, undecided=self.undecided, resolution=resolution))
        self.breaks = br[np.concatenate([[True], np.diff(br) > 1e-13 * self.span])]

    def _with(self, br: F64, kinks: F64) -> F64:
        kinks = kinks[(kinks > self.patch.s_lo) & (kinks < self.patch.s_hi)]
        self.kinks = np.concatenate([self.kinks, kinks])
        return np.unique(np.concatenate([br, kinks]))

    def grade(self) -> None:
        """Break points added next to each located change (:func:`.kinks.graded`) whose rings near
        it have no undecided piece."""
        pts, near, owner = graded(self.breaks, self.kinks)
        if len(pts) == 0:
            return
        banded = np.unique(owner[self.undecided(near) > 0])  # (changes next to an undecided band)
        br = np.unique(np.concatenate([self.breaks, pts[~np.isin(owner, banded)]]))
        self.breaks = br[np.concatenate([[True], np.diff(br) > 1e-13 * self.span])]

    def add_seeds(self, points: F64) -> None:
        """Search the sweep again at the heights of ``points`` on this patch's leaf (where other
        patches' rings crossed it): a feature between the grid's rings is found from there."""
        patch, tree = self.patch, self.tree
        if patch.direction is None or patch.s_of_height is None or len(points) == 0 or len(self.rel) == 0:
            return
        near = 1e-9 * max(float(np.max(tree.hi - tree.lo)), 1.0)
        on = np.abs(np.asarray(tree.leaves[patch.leaf].signed_distance(points))) <= near
        s = np.asarray(patch.s_of_height(points[on] @ patch.direction), dtype=np.float64)
        s = s[(s > patch.s_lo) & (s < patch.s_hi)]
        if len(s) == 0:
            return
        s = np.unique(np.round((s - patch.s_lo) / (1e-7 * self.span))) * (1e-7 * self.span) + patch.s_lo
        s = s[(s > patch.s_lo) & (s < patch.s_hi)][:4096]
        # only the heights whose rings differ from their interval's middle: a feature unseen so far
        br = self.breaks
        mids = 0.5 * (br[:-1] + br[1:])
        where = np.clip(np.searchsorted(br, s) - 1, 0, len(mids) - 1)
        wide = (br[1:] - br[:-1])[where] > 1e-6 * self.span  # (a narrow one: a change located already)
        s, where = s[wide], where[wide]
        if len(s) == 0:
            return
        new = s[self.signature(s) != self.signature(mids)[where]][:64]
        if len(new) == 0:
            return
        grid = np.unique(np.concatenate([br, new]))
        found = signature_breaks(self.signature, self.breaks, grid, self.undecided, self.resolution)
        br = self._with(self.breaks, found)
        self.breaks = br[np.concatenate([[True], np.diff(br) > 1e-13 * self.span])]

    def __call__(self, a: F64, b: F64) -> tuple[F64, F64, F64]:
        c, h = 0.5 * (a + b), 0.5 * (b - a)
        s = (c[:, None] + h[:, None] * GK_X[None, :]).ravel()
        m, und = _ring_measure(self.tree, self.patch, self.rel, self.planes, self.curved, s, self.samples, self.origin)
        m, und = m.reshape(-1, 15), und.reshape(-1, 15)
        k_, g_ = (m @ GK_WK) * h, (m @ GK_WG) * h
        return k_, np.abs(k_ - g_), (und @ GK_WK) * h


#: An interval of the sweep: (-its error, patch, a, b, value, undecided area); the error is the
#: Kronrod-Gauss difference plus the undecided area.
_Interval = tuple[float, int, float, float, float, float]


def _sweep(rules: list[_PatchRule], tol: float, scale: float, floor: float) -> tuple[float, float]:
    """Adaptive Gauss-Kronrod over every patch at once: the intervals whose errors carry half of
    the sum are split (all patches in one pass each), until that sum is at most ``SAFETY * tol``
    times the whole figure's size (``scale``, the closed and planar parts' absolute values, plus
    the absolute values of every interval; at least ``floor``). Effort goes where the errors are,
    whichever patch they are on: a patch with little or nothing on the boundary is not refined to
    ``tol`` of its own (vanishing) contribution. An interval whose error is mostly undecided
    area is split down to ``UNDECIDED_DEPTH`` of its patch's sweep only: a node on a curve where
    another surface meets the patch (a whole ring undecided) moves off it after a split or two,
    while a band along another surface (a thin rod's end disc inside the rod's copy) is measured
    again at every level. Returns (value, error)."""
    heap: list[_Interval] = []
    for k, rule in enumerate(rules):
        a, b = rule.breaks[:-1], rule.breaks[1:]
        val, err, und = rule(a, b)
        heap.extend(zip((-(err + und)).tolist(), [k] * len(a), a.tolist(), b.tolist(), val.tolist(), und.tolist()))
    heapq.heapify(heap)
    count = [len(r.breaks) - 1 for r in rules]
    done: list[_Interval] = []  # intervals that may not be split further (their patch's cap, or too short)
    while heap:
        total = math.fsum(-h[0] for h in heap) + math.fsum(-h[0] for h in done)
        size = scale + math.fsum(abs(h[4]) for h in heap) + math.fsum(abs(h[4]) for h in done)
        if total <= SAFETY * tol * max(size, floor):
            break
        take: dict[int, list[_Interval]] = {}
        acc, n = 0.0, 0
        while heap and (acc < 0.5 * total or n == 0) and n < 512:
            item = heapq.heappop(heap)
            k, x, y, und_k = item[1], item[2], item[3], item[5]
            width = (y - x) / rules[k].span
            if (count[k] >= MAX_INTERVALS or width < 1e-14 or item[0] == 0.0
                    or (2 * und_k > -item[0] and width < UNDECIDED_DEPTH)):
                done.append(item)
                continue
            take.setdefault(k, []).append(item)
            count[k] += 1
            acc, n = acc - item[0], n + 1
        for k, items in take.items():
            xa = np.array([t[2] for t in items])
            ya = np.array([t[3] for t in items])
            mid = 0.5 * (xa + ya)
            lo, hi = np.concatenate([xa, mid]), np.concatenate([mid, ya])
            v2, e2, u2 = rules[k](lo, hi)
            for item in zip((-(e2 + u2)).tolist(), [k] * len(lo), lo.tolist(), hi.tolist(), v2.tolist(), u2.tolist()):
                heapq.heappush(heap, item)
    every = heap + done
    return math.fsum(h[4] for h in every), math.fsum(-h[0] for h in every)


def surface_area(solid: Solid, *, tol: float = 1e-9, samples: int = 64) -> AreaResult:
    """Surface area of a primitive or CSG tree (the boundary of the regularised result).

    See the module docstring for the method. A primitive's area is its closed form; a leaf
    whose box meets no other leaf's contributes its closed form or nothing, as the tree says.

    Parameters
    ----------
    solid : Solid
    tol : float, default 1e-9
        Target relative error of the whole area (the cut patches' error estimates together), in [1e-13, 0.1].
    samples : int, default 64
        Samples per ring at which crossings of curved leaves are looked for, 8 .. 4096.

    Returns
    -------
    AreaResult

    Raises
    ------
    InvalidParameterError
        On a bad ``tol`` or ``samples``, or a leaf of a kind without a parametrisation.

    Examples
    --------
    >>> from isocsg import Box, Sphere
    >>> r = surface_area(Sphere((0, 0, 0), 1) & Box((0, 0, 2), (4, 4, 4)))  # a hemisphere
    >>> abs(r.value / (3 * math.pi) - 1) < 1e-9
    True
    """
    tol_ = scalar("tol", tol, low=1e-13, high=0.1, error=InvalidParameterError)
    samples_ = integer("samples", samples, low=8, high=4096, error=InvalidParameterError)
    return _boundary_integral(solid, tol_, samples_, volume=False)


def boundary_volume(solid: Solid, *, tol: float = 1e-9, samples: int = 64) -> AreaResult:
    """Volume of a primitive or CSG tree as the flux of ``x / 3`` through its boundary (the
    divergence theorem), integrated over the same boundary pieces as :func:`surface_area`: an
    estimate independent of :func:`isocsg.volume`'s sections, with an error estimate.

    Examples
    --------
    >>> from isocsg import Box, Sphere
    >>> r = boundary_volume(Sphere((0, 0, 0), 1) & Box((0, 0, 2), (4, 4, 4)))  # a hemisphere
    >>> abs(r.value / (2 * math.pi / 3) - 1) < 1e-9
    True
    """
    tol_ = scalar("tol", tol, low=1e-13, high=0.1, error=InvalidParameterError)
    samples_ = integer("samples", samples, low=8, high=4096, error=InvalidParameterError)
    return _boundary_integral(solid, tol_, samples_, volume=True)


def boundary_figures(solid: Solid, *, tol: float = 1e-9, samples: int = 64) -> tuple[AreaResult, AreaResult]:
    """:func:`boundary_volume` and :func:`surface_area` together (a planar leaf's faces are
    classified once for both)."""
    tol_ = scalar("tol", tol, low=1e-13, high=0.1, error=InvalidParameterError)
    samples_ = integer("samples", samples, low=8, high=4096, error=InvalidParameterError)
    cache: dict[int, tuple[float, float, float, float] | None] = {}
    sweeps: dict[tuple[int, int], F64] = {}  # the patches' break points (the search for them costs most)
    return (_boundary_integral(solid, tol_, samples_, volume=True, planar_cache=cache, sweep_cache=sweeps),
            _boundary_integral(solid, tol_, samples_, volume=False, planar_cache=cache, sweep_cache=sweeps))


def _boundary_integral(
    solid: Solid, tol: float, samples: int, *, volume: bool,
    planar_cache: dict[int, tuple[float, float, float, float] | None] | None = None,
    sweep_cache: dict[tuple[int, int], F64] | None = None,
) -> AreaResult:
    prog = solid_program(solid)
    if prog.n_leaves == 0:
        return AreaResult(0.0, 0.0, True)
    if prog.n_leaves == 1:
        prim = prog.leaves[0]
        return AreaResult(float(prim.volume) if volume else closed_form_area(prim), 0.0, True)
    tree = _Tree(prog)
    centre = 0.5 * (tree.lo.min(axis=0) + tree.hi.max(axis=0))
    origin = centre if volume else None
    planar_cache = {} if planar_cache is None else planar_cache
    sweep_cache = {} if sweep_cache is None else sweep_cache
    value, error, exact = 0.0, 0.0, True
    abs_value, closed = 0.0, 0.0  # the closed and planar parts' size; the swept patches' whole area
    rules: list[_PatchRule] = []
    keys: list[tuple[int, int]] = []
    for i, prim in enumerate(prog.leaves):
        rel = tree.relevant(i)
        if len(rel) and tree.planar[i] and all(tree.planar[j] for j in rel.tolist()):
            exact = False
            if i not in planar_cache:  # exact polygons instead of rings; area and volume at once
                planar_cache[i] = _planar_leaf(tree, i, rel, centre)
            if planar_cache[i] is not None:
                a, ae, v, ve = planar_cache[i]  # type: ignore[misc]
                value, error = (value + v, error + ve) if volume else (value + a, error + ae)
                abs_value += abs(v) if volume else a
                continue
        try:
            patches = leaf_patches(i, prim)
        except InvalidGeometryError as exc:  # the kind has no parametrisation
            raise InvalidParameterError(str(exc)) from None
        if len(rel) == 0:  # alone: all of its surface or none of it
            p = patches[0]
            s = np.array([0.5 * (p.s_lo + p.s_hi)])
            r = p.rings(s)
            t = np.array([0.5 * (r.t0[0] + r.t1[0])])
            on, _ = tree.classify(i, rel, r.points(np.zeros(1, np.int64), t), p.normal(s, t))
            if bool(on[0]):
                sign = 1.0 if bool(tree.last_inside_minus[0]) else -1.0
                whole = sign * float(prim.volume) if volume else closed_form_area(prim)
                value, abs_value = value + whole, abs_value + abs(whole)
            continue
        exact = False
        keys.extend((i, k) for k in range(len(patches)))
        rules.extend(_PatchRule(tree, p, rel, samples, origin, sweep_cache.get((i, k)), LOCATE * tol)
                     for k, p in enumerate(patches))
        closed += sum(p.closed_area for p in patches)
    if rules:
        seeds = np.concatenate(tree.seeds) if tree.seeds else np.zeros((0, 3))
        for rule, key in zip(rules, keys):  # features narrower than a patch's grid, seen from the other leaves' rings
            if not rule.known:
                rule.add_seeds(seeds)
                rule.grade()
                sweep_cache[key] = rule.breaks
        size = 1.0 if origin is None else float(np.max(tree.hi - tree.lo))
        v, e = _sweep(rules, tol, abs_value, 1e-6 * closed * size)
        value, error = value + v, error + e
    return AreaResult(value, error, exact)


def _planar_leaf(
    tree: _Tree, i: int, rel: NDArray[np.int64], origin: F64,
) -> tuple[float, float, float, float] | None:
    """A planar leaf whose neighbours are all planar: its faces' boundary parts as polygons
    (:mod:`isocsg.testing.planar`): the area, its rounding bound, the volume's share (the flux of
    ``(x - origin) / 3``) and its bound; None where the overlay fails even on a grid (the
    rings then)."""
    faces = tree.leaves[i].flat_faces()
    nb = Neighbours(rel.tolist(), tree.planes)
    from shapely.errors import GEOSException

    area = area_err = vol = vol_err = 0.0
    for V, n in faces:
        face = PlanarFace(V, n)
        size = float(np.max(np.abs(face.uv)))
        for grid in (SNAP * size, 100 * SNAP * size, None):
            if grid is None:
                return None  # the rings then
            try:
                a, signed, err = face_boundary(tree.prog, i, face, nb, tree.tol, grid=grid)
                break
            except GEOSException:  # a coarser grid
                continue
        h = (face.d - float(n @ origin)) / 3.0  # x / 3 . n is constant on the face
        area, area_err, vol, vol_err = area + a, area_err + err, vol + signed * h, vol_err + err * abs(h)
    return area, area_err, vol, vol_err
