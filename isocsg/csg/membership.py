"""Point membership of primitives and CSG programs, with a documented tolerance.

Boundary semantics
------------------
A CSG result is the *regularised* set ``R* = closure(interior(R))`` of the
Boolean ``R`` of its closed primitives: faces shared by two operands of a union
do not separate it, the cut face of ``A - B`` belongs to the result (it is the
result's boundary), and measure-zero leftovers (``A & B`` of two solids that
only touch, ``A - A``) are empty. :func:`contains` answers for the closed set
``R*`` with a tolerance ``tol >= 0`` (metres):

- every primitive has a signed distance ``f`` (:func:`signed_distance`;
  negative inside). Where every leaf has ``|f| > tol`` at a point, the point's
  ``tol``-ball lies on one side of every leaf's boundary and the program
  decides it exactly;
- a point within ``tol`` of one or more leaf boundaries counts as *on* them:
  those leaves are replaced by their tangent cones at the point (a half-space
  for a smooth face, a wedge at an edge, a circular cone at an apex) and the
  point is inside when the program, evaluated on those cones, has solid in
  some direction (the point is on the boundary or in the interior of the
  regularised result). Directions are probed on a fixed set of 90 directions
  plus the cones' own normals and their pairwise combinations.

So a point on the cut face of ``A - B`` (or ``tol`` from it, on either side)
is inside, a point on the face where ``A & B`` only touch is outside, and a
point on ``A``'s surface is outside ``A - A``.

The default tolerance (:func:`default_tolerance`) is ``1e-12`` of the
largest coordinate magnitude or extent of the leaves' boxes: far above the
rounding of the distance computations, far below any feature.

Scale
-----
The points are sorted into a uniform grid of cells once; each leaf tests only
the points of the cells its (``tol``-grown) box meets, and the program is
evaluated on sorted index sets (union, intersection and difference of the
leaves' inside sets) instead of dense masks, so the cost follows the number
of (point, leaf box) incidences rather than points x leaves.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidParameterError
from ..kinds.base import LeafForm, Primitive, check_tolerance
from .program import OP_INTERSECTION, OP_UNION, Program, default_tolerance

__all__ = ["signed_distance", "default_tolerance", "check_tolerance", "contains_program"]

#: Probed directions are counted inside a tangent cone when they clear each of
#: its faces by this much (cosine of the angle to the face, unit vectors).
DIRECTION_MARGIN = 1e-9
#: Points near a boundary are resolved this many at a time (memory: about 1.2 kB each per leaf
#: whose tangent cone or inside set reaches them).
NEAR_CHUNK = 16384


# ----------------------------------------------------------------------------- distances


def signed_distance(prim: Primitive, points: NDArray[np.float64]) -> NDArray[np.float64]:
    """Signed distance of points to a primitive's boundary (negative inside): its kind's
    :meth:`~isocsg.kinds.base.Primitive.signed_distance`.

    Exact for spheres, boxes and trunci (the distance in the meridian
    half-plane to the truncus' trapezoid); for a convex polyhedron the
    largest signed distance to its face planes (exact inside, a lower bound
    outside, equal to the distance wherever the nearest boundary point is
    inside a face).

    Parameters
    ----------
    prim : Primitive
    points : ndarray, shape (n, 3)

    Returns
    -------
    ndarray, shape (n,)

    Examples
    --------
    >>> from isocsg import Box, Cylinder, Sphere
    >>> pts = np.array([[0.0, 0, 0], [2.0, 0, 0], [2.0, 2.0, 0]])
    >>> signed_distance(Sphere((0, 0, 0), 1), pts).round(6).tolist()
    [-1.0, 1.0, 1.828427]
    >>> signed_distance(Box((0, 0, 0), (2, 2, 2)), pts).round(6).tolist()
    [-1.0, 1.0, 1.414214]
    >>> signed_distance(Cylinder((0, 0, 0), (0, 0, 2), 1), [[0.0, 0, 3], [0.5, 0, 0]]).tolist()
    [2.0, -0.5]
    """
    if not isinstance(prim, Primitive):
        raise InvalidParameterError(f"signed_distance needs a primitive, got {type(prim).__name__}")
    return prim.signed_distance(np.asarray(points, dtype=np.float64).reshape(-1, 3))


def _fixed_directions() -> NDArray[np.float64]:
    lattice = np.array(
        [[i, j, k] for i in (-1, 0, 1) for j in (-1, 0, 1) for k in (-1, 0, 1) if (i, j, k) != (0, 0, 0)], dtype=float
    )
    n = 64
    i = np.arange(n) + 0.5
    z = 1 - 2 * i / n
    r = np.sqrt(1 - z * z)
    phi = i * math.pi * (3 - math.sqrt(5))
    fib = np.column_stack([r * np.cos(phi), r * np.sin(phi), z])
    d = np.vstack([lattice, fib])
    return d / np.linalg.norm(d, axis=1, keepdims=True)


_FIXED = _fixed_directions()
#: At most this many tangent-cone faces per point seed extra probe directions.
_SEEDS = 4


def _probe_directions(seeds: NDArray[np.float64]) -> NDArray[np.float64]:
    """Probe directions per point ``(m, K, 3)``: the fixed set plus combinations of the point's seeds
    (the faces of its tangent cones, unused slots zero): the seeds and their opposites, and for each
    pair their sum, difference, cross product and the cross product tilted inwards."""
    m = len(seeds)
    extra = []
    for j in range(_SEEDS):
        extra.append(-seeds[:, j])
        extra.append(seeds[:, j])
    for j in range(_SEEDS):
        for k in range(j + 1, _SEEDS):
            a, b = seeds[:, j], seeds[:, k]
            cr = np.cross(a, b)
            extra += [-(a + b), a + b, b - a, a - b, cr, -cr, cr - 0.05 * (a + b), -cr - 0.05 * (a + b)]
    E = np.stack(extra, axis=1) if extra else np.zeros((m, 0, 3))
    nrm = np.linalg.norm(E, axis=2, keepdims=True)
    ok = nrm[..., 0] > 1e-9
    E = np.where(ok[..., None], E / np.maximum(nrm, 1e-300), _FIXED[0])
    return np.concatenate([np.broadcast_to(_FIXED, (m, len(_FIXED), 3)), E], axis=1)


# ----------------------------------------------------------------------------- index sets


def _union(xs: list[NDArray[np.int64]]) -> NDArray[np.int64]:
    xs = [x for x in xs if len(x)]
    if not xs:
        return np.zeros(0, np.int64)
    if len(xs) == 1:
        return xs[0]
    return _sorted_unique(np.concatenate(xs))


def _sorted_unique(x: NDArray[np.int64]) -> NDArray[np.int64]:
    """``np.unique`` of integers by sorting (faster here than hashing)."""
    x.sort(kind="stable" if len(x) < 64 else "quicksort")
    keep = np.empty(len(x), dtype=bool)
    keep[:1] = True
    np.not_equal(x[1:], x[:-1], out=keep[1:])
    return x[keep]


def _combine_sets(op: int, xs: list[NDArray[np.int64]]) -> NDArray[np.int64]:
    if op == OP_UNION:
        return _union(xs)
    if op == OP_INTERSECTION:
        xs = sorted(xs, key=len)
        out = xs[0]
        for x in xs[1:]:
            if not len(out):
                break
            out = np.intersect1d(out, x, assume_unique=True)
        return out
    first = xs[0]
    if not len(first):
        return first
    rest = _union(xs[1:])
    if not len(rest):
        return first
    return first[~np.isin(first, rest, assume_unique=True)]


# ----------------------------------------------------------------------------- point grid


class _PointGrid:
    """Points sorted into a uniform grid of cells (about ``per_cell`` points each); box queries
    return positions in the sorted order, ascending within each box."""

    def __init__(self, pts: NDArray[np.float64], per_cell: int = 8, max_cells: int = 1 << 21) -> None:
        n = len(pts)
        self.lo = pts.min(axis=0)
        ext = pts.max(axis=0) - self.lo
        ncell = int(min(max(n // per_cell, 1), max_cells))
        pos = ext > 0
        dims = np.ones(3, dtype=np.int64)
        if pos.any() and ncell > 1:
            h = (float(np.prod(ext[pos])) / ncell) ** (1.0 / int(pos.sum()))
            dims[pos] = np.clip(np.ceil(ext[pos] / h), 1, 4096).astype(np.int64)
            while int(np.prod(dims)) > max_cells:
                dims = np.maximum(dims // 2, 1)
        self.dims = dims
        self.scale = np.where(pos, dims / np.where(pos, ext, 1.0), 0.0)
        c = np.minimum((np.floor((pts - self.lo) * self.scale)).astype(np.int64), dims - 1)
        lin = (c[:, 0] * dims[1] + c[:, 1]) * dims[2] + c[:, 2]
        self.order = np.argsort(lin, kind="stable")
        self.sorted_pts = pts[self.order]
        self.start = np.searchsorted(lin[self.order], np.arange(int(np.prod(dims)) + 1))

    def _cell_ranges(
        self, lo: NDArray[np.float64], hi: NDArray[np.float64],
    ) -> tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.bool_]]:
        d = self.dims
        c0 = np.floor((lo - self.lo) * self.scale).astype(np.int64)
        c1 = np.floor((hi - self.lo) * self.scale).astype(np.int64)
        valid = np.all(c1 >= 0, axis=-1) & np.all(c0 <= d - 1, axis=-1)
        return np.clip(c0, 0, d - 1), np.clip(c1, 0, d - 1), valid

    def pair_counts(self, lo: NDArray[np.float64], hi: NDArray[np.float64]) -> NDArray[np.int64]:
        """Number of grid columns (x, y cells) that each box ``lo[i], hi[i]`` meets."""
        c0, c1, valid = self._cell_ranges(lo, hi)
        return np.where(valid, (c1[:, 0] - c0[:, 0] + 1) * (c1[:, 1] - c0[:, 1] + 1), 0)

    def query_many(
        self, ids: NDArray[np.int64], lo: NDArray[np.float64], hi: NDArray[np.float64]
    ) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
        """Sorted positions of the points in the cells each box ``ids`` meets, and the box of each."""
        d = self.dims
        c0, c1, valid = self._cell_ranges(lo[ids], hi[ids])
        ny = c1[:, 1] - c0[:, 1] + 1
        npairs = np.where(valid, (c1[:, 0] - c0[:, 0] + 1) * ny, 0)
        total = int(npairs.sum())
        if total == 0:
            return np.zeros(0, np.int64), np.zeros(0, np.int64)
        rep = np.repeat(np.arange(len(ids)), npairs)
        k = np.arange(total) - np.repeat(np.cumsum(npairs) - npairs, npairs)
        ix = c0[rep, 0] + k // ny[rep]
        iy = c0[rep, 1] + k % ny[rep]
        base = (ix * d[1] + iy) * d[2]
        st = self.start[base + c0[rep, 2]]
        en = self.start[base + c1[rep, 2] + 1]
        lengths = en - st
        n = int(lengths.sum())
        pos = np.repeat(st - (np.cumsum(lengths) - lengths), lengths) + np.arange(n)
        return pos, np.repeat(ids[rep], lengths)


# ----------------------------------------------------------------------------- programs


def _batched_distance(tab, prog: Program, leaf_of: NDArray[np.int64], q: NDArray[np.float64]) -> NDArray[np.float64]:
    """Signed distances of points ``q`` to the leaves ``leaf_of`` (one leaf per point), vectorised by kind."""
    out = np.empty(len(q))
    kind = tab.kind[leaf_of]
    sel = np.nonzero(kind == LeafForm.BALL)[0]
    if len(sel):
        L = leaf_of[sel]
        d = q[sel] - tab.center[L]
        out[sel] = np.sqrt(np.einsum("ij,ij->i", d, d)) - tab.radius[L]
    sel = np.nonzero(kind == LeafForm.AXIS_BOX)[0]
    if len(sel):
        L = leaf_of[sel]
        e = np.abs(q[sel] - tab.center[L]) - tab.half[L]
        pos = np.maximum(e, 0.0)
        out[sel] = np.sqrt(np.einsum("ij,ij->i", pos, pos)) + np.minimum(e.max(axis=1), 0.0)
    sel = np.nonzero(kind == LeafForm.FRUSTUM)[0]
    if len(sel):
        L = leaf_of[sel]
        a = tab.axis[L]
        rel = q[sel] - tab.center[L]
        s = np.einsum("ij,ij->i", rel, a)
        radial = rel - s[:, None] * a
        rho = np.sqrt(np.einsum("ij,ij->i", radial, radial))
        h2, r1, r2 = tab.height[L] / 2, tab.r1[L], tab.r2[L]
        length = np.hypot(2 * h2, r1 - r2)
        r_s = r2 + (r1 - r2) * (s + h2) / (2 * h2)
        side = (rho - r_s) * (2 * h2) / length
        d = np.maximum(np.maximum(s - h2, -s - h2), side)
        o = d > 0.0
        if o.any():
            so, ro, h, a1, a2 = s[o], rho[o], h2[o], r1[o], r2[o]
            d1 = _segment_distance_v(so, ro, h, -a1, h, a1)
            d2 = _segment_distance_v(so, ro, -h, -a2, -h, a2)
            d3 = _segment_distance_v(so, ro, -h, a2, h, a1)
            d[o] = np.minimum(np.minimum(d1, d2), d3)
        out[sel] = d
    sel = np.nonzero((kind == LeafForm.HULL) | (kind == LeafForm.GENERIC))[0]  # every other leaf by its own distance
    if len(sel):
        L = leaf_of[sel]
        order = np.argsort(L, kind="stable")
        Ls = L[order]
        cuts = np.nonzero(np.diff(Ls))[0] + 1
        for grp in np.split(order, cuts):
            out[sel[grp]] = prog.leaves[int(L[grp[0]])].signed_distance(q[sel[grp]])
    return out


def _segment_distance_v(px, py, ax, ay, bx, by):
    """Distance of points to segments (one segment per point)."""
    dx, dy = bx - ax, by - ay
    ll = dx * dx + dy * dy
    t = np.clip(((px - ax) * dx + (py - ay) * dy) / np.where(ll > 0, ll, 1.0), 0.0, 1.0)
    t = np.where(ll > 0, t, 0.0)
    return np.hypot(px - (ax + t * dx), py - (ay + t * dy))


def contains_program(prog: Program, points: NDArray[np.float64], tol: float | None = None) -> NDArray[np.bool_]:
    """Membership of points in the regularised, closed result of a program (module docstring).

    Parameters
    ----------
    prog : Program
    points : ndarray, shape (n, 3)
        Already validated.
    tol : float or None
        Absolute tolerance >= 0; None for :func:`default_tolerance`.

    Returns
    -------
    ndarray of bool, shape (n,)
    """
    from .section import leaf_table

    n = len(points)
    if n == 0 or len(prog.leaves) == 0:
        return np.zeros(n, dtype=bool)
    tab = leaf_table(prog)
    lo_all = np.empty((len(prog.leaves), 3))
    hi_all = np.empty((len(prog.leaves), 3))
    for j, e in enumerate(np.eye(3)):
        lo_all[:, j], hi_all[:, j] = tab.extents(e)
    boxes = np.stack([lo_all, hi_all], axis=1)
    t = check_tolerance("contains(tol)", tol, default_tolerance(boxes))
    grid = _PointGrid(points)
    P = grid.sorted_pts
    N = len(prog.leaves)
    lo_t, hi_t = boxes[:, 0] - t, boxes[:, 1] + t
    pairs = grid.pair_counts(lo_t, hi_t)
    in_parts: list[tuple[NDArray[np.int64], NDArray[np.int64]]] = []
    near_parts: list[tuple[NDArray[np.int64], NDArray[np.int64]]] = []
    # leaves in chunks of about 100 000 grid columns: candidates, distances, classes
    cum = np.concatenate([[0], np.cumsum(pairs)])
    i0 = 0
    while i0 < N:
        i1 = max(int(np.searchsorted(cum, cum[i0] + 100_000, side="right")) - 1, i0 + 1)
        pos, leaf_of = grid.query_many(np.arange(i0, i1), lo_t, hi_t)
        if len(pos):
            q = P[pos]
            keep = np.all((q >= lo_t[leaf_of]) & (q <= hi_t[leaf_of]), axis=1)
            pos, leaf_of, q = pos[keep], leaf_of[keep], q[keep]
            f = _batched_distance(tab, prog, leaf_of, q)
            m_in = f < -t
            m_near = np.abs(f) <= t
            in_parts.append((pos[m_in], leaf_of[m_in]))
            near_parts.append((pos[m_near], leaf_of[m_near]))
        i0 = i1

    def split(parts: list[tuple[NDArray[np.int64], NDArray[np.int64]]]) -> list[NDArray[np.int64]]:
        if not parts:
            return [np.zeros(0, np.int64)] * N
        pos = np.concatenate([p for p, _ in parts])
        lf = np.concatenate([leaf for _, leaf in parts])
        counts = np.bincount(lf, minlength=N)
        return np.split(pos, np.cumsum(counts)[:-1])  # leaf_of is non-decreasing, positions sorted per leaf

    inside = split(in_parts)
    near = split(near_parts)
    result = prog.evaluate(lambda i, _: inside[i], _combine_sets)
    near_all = _union(near)
    out_sorted = np.zeros(n, dtype=bool)
    out_sorted[result] = True
    for k in range(0, len(near_all), NEAR_CHUNK):
        chunk = near_all[k : k + NEAR_CHUNK]
        if k or len(chunk) < len(near_all):
            lo, hi = chunk[0], chunk[-1]
            sub_in = [x[np.searchsorted(x, lo) : np.searchsorted(x, hi, side="right")] for x in inside]
            sub_near = [x[np.searchsorted(x, lo) : np.searchsorted(x, hi, side="right")] for x in near]
        else:
            sub_in, sub_near = inside, near
        out_sorted[chunk] = _resolve_near(prog, P, chunk, sub_in, sub_near, t)
    out = np.zeros(n, dtype=bool)
    out[grid.order] = out_sorted
    return out


def _resolve_near(
    prog: Program,
    P: NDArray[np.float64],
    near_all: NDArray[np.int64],
    inside: list[NDArray[np.int64]],
    near: list[NDArray[np.int64]],
    tol: float,
) -> NDArray[np.bool_]:
    """Decide the points within ``tol`` of some leaf boundary by their tangent cones."""
    m = len(near_all)
    cons: dict[int, tuple[NDArray[np.int64], NDArray[np.float64], NDArray[np.float64], NDArray[np.bool_]]] = {}
    seeds = np.zeros((m, _SEEDS, 3))
    nseed = np.zeros(m, dtype=np.int64)
    for i, leaf in enumerate(prog.leaves):
        if not len(near[i]):
            continue
        rows = np.searchsorted(near_all, near[i])
        V, C, valid = leaf.tangent_cone(P[near[i]], tol)
        cons[i] = (rows, V, C, valid)
        for j in range(V.shape[1]):
            sel = np.nonzero(valid[:, j])[0]
            if not len(sel):
                continue
            r = rows[sel]
            slot = nseed[r]
            ok = slot < _SEEDS
            r, slot = r[ok], slot[ok]  # rows are distinct within one leaf
            seeds[r, slot] = V[sel[ok], j]
            nseed[r] += 1
    D = _probe_directions(seeds)  # (m, K, 3)
    K = D.shape[1]
    allk = np.arange(K)

    def leaf_set(i: int, _: Primitive) -> NDArray[np.int64]:
        parts = []
        ins = inside[i]
        if len(ins):
            pos = np.searchsorted(ins, near_all)
            hit = pos < len(ins)
            hit[hit] = ins[pos[hit]] == near_all[hit]
            rows_in = np.nonzero(hit)[0]
            if len(rows_in):
                parts.append((rows_in[:, None] * K + allk[None, :]).ravel())
        if i in cons:
            rows, V, C, valid = cons[i]
            dots = np.einsum("mkd,mcd->mkc", D[rows], V)  # (r, K, c)
            ok = (dots < C[:, None, :] - DIRECTION_MARGIN) | ~valid[:, None, :]
            r_idx, k_idx = np.nonzero(ok.all(axis=2))
            parts.append(rows[r_idx] * K + k_idx)
        return _union(parts)

    res = prog.evaluate(leaf_set, _combine_sets)
    out = np.zeros(m, dtype=bool)
    out[res // K] = True
    return out
