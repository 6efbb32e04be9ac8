"""Cutting a triangle mesh into bands along the level sets of a per-vertex field.

A contour family is a scalar field on the surface (the cosine of the incidence
angle, say) and a sorted list of levels. :func:`split_by_levels` cuts every
triangle along the lines where the (linearly interpolated) field crosses a
level, so that each output triangle lies in exactly one band
``levels[b - 1] <= field <= levels[b]``.

Every cut point is computed once per (edge, level) from the edge's two end
vertices in a fixed order and shared by index between the two triangles of
that edge: the output is as watertight as the input (no T-junctions, no
cracks for the scanline fill).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._jit import njit
from ..errors import InvalidParameterError
from .halfedges import sorted_half_edges

__all__ = ["SplitMesh", "split_by_levels", "mesh_edges", "MAX_PIECES"]

#: Upper bound on the triangles one cut may produce (about 300 MB of indices):
#: beyond it the request (many contours times several lights) is refused, not attempted.
MAX_PIECES = 12_000_000


@dataclass(frozen=True, slots=True, eq=False)
class SplitMesh:
    """Result of :func:`split_by_levels`.

    Attributes
    ----------
    vertices : ndarray, shape (V', 3)
        Input vertices followed by the cut points.
    values : ndarray, shape (V', K)
        The per-vertex columns carried along (linearly interpolated at cut points).
    triangles : ndarray, shape (T', 3), int64
        Output triangles, with the winding of their parent.
    parent : ndarray, shape (T',), int64
        Index of the input triangle each output triangle comes from.
    band : ndarray, shape (T',), int64
        Band index: the number of levels at or below the triangle's field values.
    """

    vertices: NDArray[np.float64]
    values: NDArray[np.float64]
    triangles: NDArray[np.int64]
    parent: NDArray[np.int64]
    band: NDArray[np.int64]


def mesh_edges(triangles: NDArray[np.int64]) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Unique undirected edges of a triangle mesh.

    Returns
    -------
    edges : ndarray, shape (E, 2)
        Vertex pairs with ``edges[:, 0] < edges[:, 1]``, in increasing order
        of ``(edges[:, 0], edges[:, 1])``.
    tri_edge : ndarray, shape (T, 3)
        ``tri_edge[t, j]`` is the edge from corner j to corner j + 1 of triangle t.

    Examples
    --------
    >>> edges, tri_edge = mesh_edges(np.array([[0, 1, 2], [2, 1, 3]]))
    >>> edges.tolist(), tri_edge.tolist()
    ([[0, 1], [0, 2], [1, 2], [1, 3], [2, 3]], [[0, 2, 1], [2, 3, 4]])
    """
    t = np.ascontiguousarray(triangles, dtype=np.int64).reshape(-1, 3)
    n = int(t.max()) + 1 if len(t) else 0
    if len(t) and t.min() < 0:
        raise InvalidParameterError(f"triangles: vertex indices must be >= 0, got {int(t.min())}")
    lo, hi, inverse, count = _edges_kernel(t, n)
    return np.stack([lo[:count], hi[:count]], axis=1), inverse


@njit(cache=True, nogil=True)
def _edges_kernel(
    t: NDArray[np.int64], n: int
) -> tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.int64], int]:
    start, his, owner = sorted_half_edges(t, n)
    nh = 3 * t.shape[0]
    lo = np.empty(nh, np.int64)
    hi = np.empty(nh, np.int64)
    inverse = np.empty((t.shape[0], 3), np.int64)
    flat = inverse.reshape(-1)
    count = 0
    for v in range(n):
        for s in range(start[v], start[v + 1]):
            if s == start[v] or his[s] != his[s - 1]:
                lo[count] = v
                hi[count] = his[s]
                count += 1
            flat[owner[s]] = count - 1
    return lo, hi, inverse, count


@njit(cache=True, nogil=True)
def _split_kernel(
    tri: NDArray[np.int64],
    f: NDArray[np.float64],
    tri_edge: NDArray[np.int64],
    edge_a: NDArray[np.int64],
    edge_k0: NDArray[np.int64],
    edge_off: NDArray[np.int64],
    n_vertices: int,
    levels: NDArray[np.float64],
    kmin: NDArray[np.int64],
    kmax: NDArray[np.int64],
    out_tri: NDArray[np.int64],
    out_parent: NDArray[np.int64],
    out_band: NDArray[np.int64],
) -> int:
    n_levels = len(levels)
    m = 0
    poly = np.empty(8, np.int64)
    for t in range(len(tri)):
        k_lo, k_hi = kmin[t], kmax[t]
        if k_lo >= k_hi:  # no level strictly inside: the triangle stays whole
            out_tri[m, 0] = tri[t, 0]
            out_tri[m, 1] = tri[t, 1]
            out_tri[m, 2] = tri[t, 2]
            out_parent[m] = t
            out_band[m] = k_lo
            m += 1
            continue
        # Slab s lies between levels k_lo + s - 1 and k_lo + s (open-ended at both ends).
        for s in range(k_hi - k_lo + 1):
            k_below = k_lo + s - 1
            k_above = k_lo + s
            lo = -np.inf if s == 0 else levels[k_below]
            hi = np.inf if k_above >= k_hi else levels[k_above]
            if k_above >= n_levels:
                hi = np.inf
            n = 0
            for j in range(3):
                p = tri[t, j]
                q = tri[t, (j + 1) % 3]
                fp, fq = f[p], f[q]
                if lo <= fp <= hi:
                    poly[n] = p
                    n += 1
                e = tri_edge[t, j]
                # Crossing points of this slab's bounding levels strictly inside edge p -> q, in order.
                for step in range(2):
                    if fp < fq:
                        k = k_below if step == 0 else k_above
                    else:
                        k = k_above if step == 0 else k_below
                    if k < k_lo or k >= k_hi:
                        continue
                    lv = levels[k]
                    if min(fp, fq) < lv < max(fp, fq):
                        poly[n] = n_vertices + edge_off[e] + (k - edge_k0[e])
                        n += 1
            for i in range(1, n - 1):
                out_tri[m, 0] = poly[0]
                out_tri[m, 1] = poly[i]
                out_tri[m, 2] = poly[i + 1]
                out_parent[m] = t
                out_band[m] = k_lo + s
                m += 1
    return m


def split_by_levels(
    vertices: NDArray[np.float64],
    triangles: NDArray[np.int64],
    values: NDArray[np.float64],
    column: int,
    levels: NDArray[np.float64],
) -> SplitMesh:
    """Cut a triangle mesh along the level lines of one per-vertex field.

    Parameters
    ----------
    vertices : ndarray, shape (V, 3)
    triangles : ndarray, shape (T, 3)
    values : ndarray, shape (V, K)
        Per-vertex fields; column ``column`` is the one cut, the others are
        interpolated at the cut points (so later families can cut the result).
    column : int
    levels : ndarray, shape (L,)
        Strictly increasing levels.

    Returns
    -------
    SplitMesh

    Raises
    ------
    InvalidParameterError
        When the cut could produce more than :data:`MAX_PIECES` triangles.

    Examples
    --------
    A triangle whose field (here x) goes from 0 to 2, cut at level 1: the
    quadrilateral x <= 1 (two triangles, band 0) and the triangle x >= 1 (band 1):

    >>> v = np.array([[0, 0, 0], [2, 0, 0], [0, 2, 0.0]])
    >>> out = split_by_levels(v, np.array([[0, 1, 2]]), v[:, :1], 0, np.array([1.0]))
    >>> out.band.tolist(), len(out.vertices)
    ([0, 0, 1], 5)
    """
    v = np.ascontiguousarray(vertices, dtype=np.float64)
    t = np.ascontiguousarray(triangles, dtype=np.int64)
    vals = np.array(values, dtype=np.float64, order="C")  # a copy: the cut column is snapped
    lv = np.ascontiguousarray(levels, dtype=np.float64)
    # Values within rounding of a level sit on it: no sliver bands.
    scale = max(1.0, float(np.max(np.abs(lv))) if len(lv) else 1.0)
    _snap(vals, column, lv, 1e-11 * scale)
    f = vals[:, column].copy()

    kmin, kmax, _, inside = _level_ranges(f, t, lv)
    if inside == 0:
        # No level strictly inside any triangle (a sphere's rings are its contour circles), so
        # none strictly inside any edge: every triangle stays whole, as the cut below would leave it.
        return SplitMesh(v.copy(), vals, t.copy(), np.arange(len(t), dtype=np.int64), kmin)
    edges, tri_edge = mesh_edges(t)
    k0, _, off, n_cuts = _level_ranges(f, edges, lv)  # the cut points, edge after edge
    new_v = np.empty((n_cuts, 3))
    new_vals = np.empty((n_cuts, vals.shape[1]))
    _cut_points(v, vals, column, f, edges, lv, k0, off, new_v, new_vals)
    cap = 3 * (inside + len(t))  # k levels cut a triangle into k + 1 polygons of at most 5 corners
    if cap > MAX_PIECES:
        raise InvalidParameterError(
            f"contours: cutting {len(t)} triangles at {len(lv)} levels could give {cap} band triangles "
            f"(more than {MAX_PIECES}); use fewer contours or fewer lights"
        )
    out_tri = np.empty((cap, 3), np.int64)
    out_parent = np.empty(cap, np.int64)
    out_band = np.empty(cap, np.int64)
    m = _split_kernel(t, f, tri_edge, edges[:, 0].copy(), k0, off, len(v), lv, kmin, kmax, out_tri, out_parent,
                      out_band)
    return SplitMesh(
        np.vstack([v, new_v]), np.vstack([vals, new_vals]), out_tri[:m], out_parent[:m], out_band[:m]
    )


@njit(cache=True, nogil=True, inline="always")
def _search(levels: NDArray[np.float64], x: float, right: bool) -> int:
    """``np.searchsorted(levels, x, side="right" if right else "left")``."""
    lo, hi = 0, levels.shape[0]
    while lo < hi:
        mid = (lo + hi) // 2
        if levels[mid] < x or (right and levels[mid] == x):
            lo = mid + 1
        else:
            hi = mid
    return lo


@njit(cache=True, nogil=True)
def _snap(vals: NDArray[np.float64], column: int, levels: NDArray[np.float64], tol: float) -> None:
    """Move the values of ``column`` within ``tol`` of a level onto it (the nearest above first)."""
    n = levels.shape[0]
    if n == 0:
        return
    for i in range(vals.shape[0]):
        x = vals[i, column]
        k = min(_search(levels, x, False), n - 1)
        if abs(x - levels[k]) <= tol:
            x = levels[k]
        k = max(k - 1, 0)
        if abs(x - levels[k]) <= tol:
            x = levels[k]
        vals[i, column] = x


@njit(cache=True, nogil=True)
def _level_ranges(
    f: NDArray[np.float64], rows: NDArray[np.int64], levels: NDArray[np.float64]
) -> tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.int64], int]:
    """Per row of vertex indices (an edge or a triangle): the levels strictly inside ``f``'s range on it.

    They are ``levels[kmin] .. levels[kmax - 1]``. Also each row's offset in
    the list of those levels taken row after row, and the list's length.
    """
    n = rows.shape[0]
    kmin = np.empty(n, np.int64)
    kmax = np.empty(n, np.int64)
    off = np.empty(n, np.int64)
    total = 0
    for i in range(n):
        lo = hi = f[rows[i, 0]]
        for j in range(1, rows.shape[1]):
            x = f[rows[i, j]]
            lo = min(lo, x)
            hi = max(hi, x)
        kmin[i] = _search(levels, lo, True)
        kmax[i] = _search(levels, hi, False)
        off[i] = total
        total += max(kmax[i] - kmin[i], 0)
    return kmin, kmax, off, total


@njit(cache=True, nogil=True)
def _cut_points(
    v: NDArray[np.float64], vals: NDArray[np.float64], column: int, f: NDArray[np.float64], edges: NDArray[np.int64],
    levels: NDArray[np.float64], k0: NDArray[np.int64], off: NDArray[np.int64],
    new_v: NDArray[np.float64], new_vals: NDArray[np.float64],
) -> None:
    """Cut point of edge e at level k, from its lower-indexed end a towards b, at row ``off[e] + k - k0[e]``."""
    for e in range(edges.shape[0]):
        a, b = edges[e, 0], edges[e, 1]
        end = off[e + 1] if e + 1 < edges.shape[0] else new_v.shape[0]
        for r in range(off[e], end):
            lv = levels[k0[e] + r - off[e]]
            w = (lv - f[a]) / (f[b] - f[a])
            for j in range(3):
                new_v[r, j] = v[a, j] + w * (v[b, j] - v[a, j])
            for j in range(vals.shape[1]):
                new_vals[r, j] = vals[a, j] + w * (vals[b, j] - vals[a, j])
            new_vals[r, column] = lv


def _search_numpy(levels: NDArray[np.float64], x: NDArray[np.float64], right: bool) -> NDArray[np.int64]:
    """:func:`_search` of every ``x`` (a NaN, which no comparison passes, at 0 as in the loop)."""
    k = np.searchsorted(levels, x, side="right" if right else "left").astype(np.int64)
    k[np.isnan(x)] = 0
    return k


@_snap.twin
def _snap_numpy(vals: NDArray[np.float64], column: int, levels: NDArray[np.float64], tol: float) -> None:
    """:func:`_snap` of every value at once."""
    n = levels.shape[0]
    if n == 0:
        return
    x = vals[:, column].copy()
    k = np.minimum(_search_numpy(levels, x, False), n - 1)
    x = np.where(np.abs(x - levels[k]) <= tol, levels[k], x)
    k = np.maximum(k - 1, 0)
    vals[:, column] = np.where(np.abs(x - levels[k]) <= tol, levels[k], x)


@_level_ranges.twin
def _level_ranges_numpy(
    f: NDArray[np.float64], rows: NDArray[np.int64], levels: NDArray[np.float64]
) -> tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.int64], int]:
    """:func:`_level_ranges` of every row at once (a field with NaN runs the loop, whose
    ``min`` and ``max`` pass NaN on differently)."""
    vals = f[rows]
    if np.isnan(vals).any():
        return _level_ranges.py_func(f, rows, levels)  # type: ignore[no-any-return]
    kmin = _search_numpy(levels, vals.min(axis=1), True)
    kmax = _search_numpy(levels, vals.max(axis=1), False)
    count = np.maximum(kmax - kmin, 0)
    off = np.cumsum(count) - count
    return kmin, kmax, off, int(count.sum())


@_edges_kernel.twin
def _edges_numpy(
    t: NDArray[np.int64], n: int
) -> tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.int64], int]:
    """:func:`_edges_kernel` on the sorted half-edges at once: an edge where ``(lower, higher)`` changes."""
    start, his, owner = sorted_half_edges(t, n)
    lower = np.repeat(np.arange(n, dtype=np.int64), np.diff(start))
    new = np.ones(len(his), bool)
    new[1:] = (his[1:] != his[:-1]) | (lower[1:] != lower[:-1])
    index = np.cumsum(new) - 1
    inverse = np.empty(3 * t.shape[0], np.int64)
    inverse[owner] = index
    return lower[new], his[new], inverse.reshape(-1, 3), int(new.sum())


@_cut_points.twin
def _cut_points_numpy(
    v: NDArray[np.float64], vals: NDArray[np.float64], column: int, f: NDArray[np.float64], edges: NDArray[np.int64],
    levels: NDArray[np.float64], k0: NDArray[np.int64], off: NDArray[np.int64],
    new_v: NDArray[np.float64], new_vals: NDArray[np.float64],
) -> None:
    """:func:`_cut_points` of every cut at once (the same interpolation, term by term)."""
    count = np.diff(np.append(off, new_v.shape[0]))
    e = np.repeat(np.arange(edges.shape[0]), count)
    lv = levels[k0[e] + np.arange(len(e)) - off[e]]
    a, b = edges[e, 0], edges[e, 1]
    w = ((lv - f[a]) / (f[b] - f[a]))[:, None]
    new_v[:] = v[a] + w * (v[b] - v[a])
    new_vals[:] = vals[a] + w * (vals[b] - vals[a])
    new_vals[:, column] = lv


@_split_kernel.twin
def _split_numpy(
    tri: NDArray[np.int64], f: NDArray[np.float64], tri_edge: NDArray[np.int64], edge_a: NDArray[np.int64],
    edge_k0: NDArray[np.int64], edge_off: NDArray[np.int64], n_vertices: int, levels: NDArray[np.float64],
    kmin: NDArray[np.int64], kmax: NDArray[np.int64],
    out_tri: NDArray[np.int64], out_parent: NDArray[np.int64], out_band: NDArray[np.int64],
) -> int:
    """:func:`_split_kernel` of every (triangle, slab) at once: each slab's corners gathered in
    the kernel's order (a corner, then the edge's crossings), then fanned from the first."""
    n_levels = len(levels)
    cut = kmin < kmax
    slabs = np.where(cut, kmax - kmin + 1, 0)
    t = np.repeat(np.arange(len(tri)), slabs)
    s = np.arange(len(t)) - np.repeat(np.cumsum(slabs) - slabs, slabs)
    k_lo, k_hi = kmin[t], kmax[t]
    k_below, k_above = k_lo + s - 1, k_lo + s
    safe = np.clip(np.concatenate([k_below, k_above]), 0, max(n_levels - 1, 0)).reshape(2, -1)
    lo = np.where(s == 0, -np.inf, levels[safe[0]] if n_levels else -np.inf)
    hi = np.where((k_above >= k_hi) | (k_above >= n_levels), np.inf, levels[safe[1]] if n_levels else np.inf)
    corners, valid = [], []
    for j in range(3):
        p, q = tri[t, j], tri[t, (j + 1) % 3]
        fp, fq = f[p], f[q]
        corners.append(p)
        valid.append((lo <= fp) & (fp <= hi))
        e = tri_edge[t, j]
        for step in range(2):
            k = np.where(fp < fq, k_below if step == 0 else k_above, k_above if step == 0 else k_below)
            lv = levels[np.clip(k, 0, max(n_levels - 1, 0))] if n_levels else np.zeros(len(t))
            corners.append(n_vertices + edge_off[e] + (k - edge_k0[e]))
            valid.append((k >= k_lo) & (k < k_hi) & (np.minimum(fp, fq) < lv) & (lv < np.maximum(fp, fq)))
    cand, ok = np.stack(corners, axis=1), np.stack(valid, axis=1)
    poly = np.take_along_axis(cand, np.argsort(~ok, axis=1, kind="stable"), axis=1)
    n = ok.sum(axis=1)
    fan = np.arange(1, cand.shape[1] - 1) < (n - 1)[:, None]  # triangle (0, i, i + 1) for i < n - 1
    rows = np.nonzero(fan)
    split_tri = np.stack([poly[rows[0], 0], poly[rows[0], rows[1] + 1], poly[rows[0], rows[1] + 2]], axis=1)
    whole = np.flatnonzero(~cut)
    parent = np.concatenate([whole, t[rows[0]]])
    order = np.argsort(parent, kind="stable")  # triangle by triangle, as the loop writes them
    m = len(parent)
    out_tri[:m] = np.concatenate([tri[whole], split_tri])[order]
    out_parent[:m] = parent[order]
    out_band[:m] = np.concatenate([kmin[whole], k_above[rows[0]]])[order]
    return m
