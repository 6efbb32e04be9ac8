"""Coincident faces: opposite-facing triangles of a Boolean's result in one plane, cancelled.

Regularised set operations leave no two coincident faces of opposite
orientation on a boundary, but manifold3d can leave such pairs (zero volume
fins and shells) where operands' faces coincide, e.g. in ``(S | C) - C`` or
``A - A``. Where two leaves have band triangles in one plane, the result's
triangles in those planes are tested, and those lying on an opposite-facing
triangle of the result are dropped (:data:`COINCIDENT_DISTANCE`); a triangle
only partly covered by opposite ones keeps its part outside them.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..._jit import njit
from ...laminae.model import BandMesh
from .result import triangle_normals

#: Distance, as a fraction of the tree's half-size, within which a triangle of
#: the result lies on an opposite-facing triangle (a zero-volume fin or shell,
#: which a regularised boundary cannot have; both sides are dropped).
COINCIDENT_DISTANCE = 1e-9


def cancel_coincident(
    verts: NDArray[np.float64], tris: NDArray[np.int64], cand: NDArray[np.int64]
) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64] | None]:
    """Drop the triangles of a Boolean's result that lie on an opposite-facing one, among
    ``cand`` (those in a plane two leaves share), keeping the part of a partly covered one
    outside the opposite ones.

    Returns the vertices, the triangles kept, and for each the index of the input triangle
    it comes from (None when nothing was dropped: the input as it is).
    """
    drop = np.zeros(len(tris), bool)
    drop[cand] = _on_opposite_face(verts, tris, cand, COINCIDENT_DISTANCE)
    verts, tris, origin, drop = _cancel_partial_overlaps(verts, tris, cand, drop, COINCIDENT_DISTANCE)
    if not drop.any():
        return verts, tris, None
    keep = np.flatnonzero(~drop)
    return verts, tris[keep], origin[keep]


def shared_planes(
    bands: Sequence[BandMesh], leaves: list[int], centre: NDArray[np.float64], half: float,
    subset: dict[int, NDArray[np.int64]] | None = None,
) -> dict[int, NDArray[np.bool_]]:
    """For each of ``leaves``, which band triangles (those of ``subset[leaf]`` where given, in
    its order) lie in a plane (either orientation) that a band triangle of another of
    ``leaves`` lies in too: only there can faces coincide.

    Leaf by leaf: a leaf's triangles lie in few planes (a faceted hole in one per facet), so
    only each leaf's distinct plane keys are gathered, and the working memory stays in
    proportion to the planes, not to the triangles of all the leaves at once.
    """
    subset = {} if subset is None else subset
    # Per leaf and per rounding of the offset: its distinct planes, and each triangle's among them.
    distinct: list[list[NDArray[np.int64]]] = [[], []]
    which: dict[int, list[NDArray[np.int32]]] = {}
    flat: dict[int, NDArray[np.bool_]] = {}
    for i in leaves:
        v = (np.asarray(bands[i].vertices, np.float64) - centre) / half
        t = np.asarray(bands[i].triangles, np.int64)
        if i in subset:
            t = t[subset[i]]
        n = triangle_normals(v, t)
        length = np.linalg.norm(n, axis=1)
        ok = length > 0
        n = n / np.where(ok, length, 1.0)[:, None]
        # One orientation per plane: the first clearly non-zero component positive.
        q = np.round(n * 2.0**20)
        lead = np.where(q[:, 0] != 0, q[:, 0], np.where(q[:, 1] != 0, q[:, 1], q[:, 2]))
        sign = np.where(lead < 0, -1.0, 1.0)
        q *= sign[:, None]
        d = np.einsum("ij,ij->i", n, v[t[:, 0]]) * sign * 2.0**30
        which[i] = []
        for col, off in enumerate((np.floor(d), np.floor(d + 0.5))):  # planes closer than a step share one
            rows = np.ascontiguousarray(np.column_stack([q, off]).astype(np.int64))
            _, first, inv = np.unique(rows.view(np.dtype((np.void, 32))).ravel(), return_index=True,
                                      return_inverse=True)
            distinct[col].append(rows[first])
            which[i].append(inv.reshape(-1).astype(np.int32))
        flat[i] = ok
    out = {i: np.zeros(len(flat[i]), bool) for i in leaves}
    for col in (0, 1):
        if not distinct[col]:
            continue
        # How many leaves have each plane (each leaf's planes are distinct).
        allp = np.ascontiguousarray(np.vstack(distinct[col]))
        _, pinv, pcount = np.unique(allp.view(np.dtype((np.void, 32))).ravel(), return_inverse=True,
                                    return_counts=True)
        many = pcount[pinv.reshape(-1)] > 1
        start = 0
        for i, planes in zip(leaves, distinct[col]):
            out[i] |= many[start : start + len(planes)][which[i][col]]
            start += len(planes)
    for i in leaves:
        out[i] &= flat[i]  # a degenerate triangle has no plane
    return out


@njit(cache=True)
def _grid_entries(
    lo: NDArray[np.float64], hi: NDArray[np.float64], use: NDArray[np.int64], g0: NDArray[np.float64], h: float,
    dims: int, count: int,
) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """The entries of a uniform grid of cell side ``h`` from ``g0`` over the boxes ``[lo[k], hi[k]]``,
    ``k`` in ``use`` (``count`` entries in all): each cell's key, sorted, and the box it holds
    (in ``use``'s order within a cell)."""
    keys = np.empty(count, np.int64)
    tri = np.empty(count, np.int64)
    e = 0
    for k in use:
        i0, j0, l0 = int((lo[k, 0] - g0[0]) / h), int((lo[k, 1] - g0[1]) / h), int((lo[k, 2] - g0[2]) / h)
        i1, j1, l1 = int((hi[k, 0] - g0[0]) / h), int((hi[k, 1] - g0[1]) / h), int((hi[k, 2] - g0[2]) / h)
        for i in range(i0, i1 + 1):
            for j in range(j0, j1 + 1):
                for l in range(l0, l1 + 1):
                    keys[e] = (i * dims + j) * dims + l
                    tri[e] = k
                    e += 1
    order = np.argsort(keys, kind="mergesort")
    return keys[order], tri[order]


@njit(cache=True)
def _on_opposite_face(
    v: NDArray[np.float64], t: NDArray[np.int64], cand: NDArray[np.int64], tol: float
) -> NDArray[np.bool_]:
    """Which candidate triangles to drop: those whose centroid lies, within ``tol``,
    on candidate triangles facing the opposite way that cancel it.

    At a point of a plane where ``a`` layers face one way and ``b`` the other,
    ``min(a, b)`` of each cancel; one of what is left is kept (the layer of
    lowest index). The candidates are found through a uniform grid over their boxes.
    """
    m = len(cand)
    nrm = np.zeros((m, 3))
    off = np.zeros(m)
    cen = np.zeros((m, 3))
    blo = np.zeros((m, 3))
    bhi = np.zeros((m, 3))
    ok = np.zeros(m, np.bool_)
    ext = np.zeros(m)
    for k in range(m):
        a, b, c = t[cand[k], 0], t[cand[k], 1], t[cand[k], 2]
        e1 = v[b] - v[a]
        e2 = v[c] - v[a]
        n = np.array([e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]])
        length = np.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)
        for x in range(3):
            cen[k, x] = (v[a, x] + v[b, x] + v[c, x]) / 3.0
            blo[k, x] = min(v[a, x], v[b, x], v[c, x]) - tol
            bhi[k, x] = max(v[a, x], v[b, x], v[c, x]) + tol
        ext[k] = max(bhi[k, 0] - blo[k, 0], bhi[k, 1] - blo[k, 1], bhi[k, 2] - blo[k, 2])
        if length > 0.0:
            ok[k] = True
            nrm[k] = n / length
            off[k] = nrm[k, 0] * v[a, 0] + nrm[k, 1] * v[a, 1] + nrm[k, 2] * v[a, 2]
    out = np.zeros(m, np.bool_)
    if m < 2:
        return out
    g0 = np.array([blo[:, 0].min(), blo[:, 1].min(), blo[:, 2].min()])
    span = max(bhi[:, 0].max() - g0[0], bhi[:, 1].max() - g0[1], bhi[:, 2].max() - g0[2])
    h = max(np.median(ext), span / 2.0**20, 1e-300)
    while True:  # coarser cells until the entries stay in proportion to the triangles
        count = 0
        for k in range(m):
            c = 1
            for x in range(3):
                c *= int((bhi[k, x] - g0[x]) / h) - int((blo[k, x] - g0[x]) / h) + 1
            count += c
        if count <= 16 * m + 1_000_000:
            break
        h *= 2.0
    dims = int(span / h) + 2
    keys, tri = _grid_entries(blo, bhi, np.arange(m), g0, h, dims, count)
    for k in range(m):
        if not ok[k]:
            continue
        i, j, l = int((cen[k, 0] - g0[0]) / h), int((cen[k, 1] - g0[1]) / h), int((cen[k, 2] - g0[2]) / h)
        key = (i * dims + j) * dims + l
        start = np.searchsorted(keys, key)
        p = cen[k]
        same = 1  # layers over p facing like k (k included), facing the other way,
        other = 0  # and those of the first kind numbered below k
        below = 0
        for e in range(start, len(keys)):
            if keys[e] != key:
                break
            q = tri[e]
            if q == k or not ok[q]:
                continue
            cos = nrm[k, 0] * nrm[q, 0] + nrm[k, 1] * nrm[q, 1] + nrm[k, 2] * nrm[q, 2]
            if abs(cos) < 0.999999:
                continue
            if abs(nrm[q, 0] * p[0] + nrm[q, 1] * p[1] + nrm[q, 2] * p[2] - off[q]) > tol:
                continue
            # Opposite layers count within the tolerance; layers facing like k only
            # where p is strictly inside them: the centroid of a sliver lies within the
            # tolerance of its neighbour's edge, and the neighbour is no second layer.
            inside = True
            for s in range(3):
                va = v[t[cand[q], s]]
                vb = v[t[cand[q], (s + 1) % 3]]
                ex, ey, ez = vb[0] - va[0], vb[1] - va[1], vb[2] - va[2]
                rx, ry, rz = p[0] - va[0], p[1] - va[1], p[2] - va[2]
                # (edge x (p - a)) . n: how far p is inside the edge, times its length
                side = ((ey * rz - ez * ry) * nrm[q, 0] + (ez * rx - ex * rz) * nrm[q, 1]
                        + (ex * ry - ey * rx) * nrm[q, 2])
                outside = side < -tol * np.sqrt(ex * ex + ey * ey + ez * ez) if cos < 0 else side <= 0.0
                if outside:
                    inside = False
                    break
            if not inside:
                continue
            if cos > 0:
                same += 1
                if q < k:
                    below += 1
            else:
                other += 1
        # Opposite layers cancel in pairs (the winding number changes by their
        # difference across the plane); of the layers left, one is kept.
        out[k] = other > 0 and below >= min(same - other, 1)
    return out


# A fixed direction no axis-aligned or simple face is perpendicular to: triangles facing
# opposite ways lie on opposite sides of the plane normal to it, except near that plane.
_SIDE_DIRECTION = np.array([1.0, np.e, np.pi]) / np.linalg.norm([1.0, np.e, np.pi])


@njit(cache=True)
def _opposite_box_pairs(
    lo: NDArray[np.float64], hi: NDArray[np.float64], nrm: NDArray[np.float64], first: NDArray[np.bool_],
    second: NDArray[np.bool_],
) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Pairs ``(a, b)``, ``first[a]`` and ``second[b]``, whose boxes ``[lo, hi]`` meet
    (closed boxes) and whose unit normals ``nrm`` are nearly opposite (cosine below
    -0.9), each once, found through a uniform grid over the boxes.

    The work is the sum over grid cells of the product of the two kinds' entries
    there, so the pairs within one plane no longer grow as the product of the
    triangles of its two layers.
    """
    m = len(lo)
    use = np.flatnonzero(first | second)
    if len(use) == 0:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    g0 = np.array([lo[use, 0].min(), lo[use, 1].min(), lo[use, 2].min()])
    span = max(hi[use, 0].max() - g0[0], hi[use, 1].max() - g0[1], hi[use, 2].max() - g0[2])
    ext = np.empty(len(use))
    for u in range(len(use)):
        k = use[u]
        ext[u] = max(hi[k, 0] - lo[k, 0], hi[k, 1] - lo[k, 1], hi[k, 2] - lo[k, 2])
    h = max(np.median(ext), span / 2.0**20, 1e-300)
    while True:  # coarser cells until the entries stay in proportion to the triangles
        count = 0
        for k in use:
            c = 1
            for x in range(3):
                c *= int((hi[k, x] - g0[x]) / h) - int((lo[k, x] - g0[x]) / h) + 1
            count += c
        if count <= 16 * len(use) + 1_000_000:
            break
        h *= 2.0
    dims = int(span / h) + 2
    keys, tri = _grid_entries(lo, hi, use, g0, h, dims, count)
    out_a = np.empty(max(16, m), np.int64)
    out_b = np.empty(max(16, m), np.int64)
    in_a = np.empty(count, np.int64)  # one cell's entries of each kind
    in_b = np.empty(count, np.int64)
    n = 0
    s = 0
    while s < count:
        f = s
        na = 0
        nb = 0
        while f < count and keys[f] == keys[s]:
            if first[tri[f]]:
                in_a[na] = tri[f]
                na += 1
            if second[tri[f]]:
                in_b[nb] = tri[f]
                nb += 1
            f += 1
        cell = keys[s]
        for ea in range(na):
            a = in_a[ea]
            for eb in range(nb):
                b = in_b[eb]
                if b == a or nrm[a, 0] * nrm[b, 0] + nrm[a, 1] * nrm[b, 1] + nrm[a, 2] * nrm[b, 2] > -0.9:
                    continue
                if not (lo[a, 0] <= hi[b, 0] and lo[b, 0] <= hi[a, 0] and lo[a, 1] <= hi[b, 1]
                        and lo[b, 1] <= hi[a, 1] and lo[a, 2] <= hi[b, 2] and lo[b, 2] <= hi[a, 2]):
                    continue
                # each pair once: in the cell of the lower corner of the boxes' overlap
                ci = int((max(lo[a, 0], lo[b, 0]) - g0[0]) / h)
                cj = int((max(lo[a, 1], lo[b, 1]) - g0[1]) / h)
                cl = int((max(lo[a, 2], lo[b, 2]) - g0[2]) / h)
                if (ci * dims + cj) * dims + cl != cell:
                    continue
                if n == len(out_a):
                    grown_a = np.empty(2 * n, np.int64)
                    grown_b = np.empty(2 * n, np.int64)
                    grown_a[:n] = out_a
                    grown_b[:n] = out_b
                    out_a, out_b = grown_a, grown_b
                out_a[n] = a
                out_b[n] = b
                n += 1
        s = f
    return out_a[:n].copy(), out_b[:n].copy()


def _opposite_pairs(
    p: NDArray[np.float64], nrm: NDArray[np.float64], ok: NDArray[np.bool_], key: NDArray[np.float64],
    lo: NDArray[np.float64], hi: NDArray[np.float64], tol: float,
) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Ordered pairs ``(i, j)`` of triangles ``p`` facing opposite ways in one plane
    (``key`` = (n, d) of one within 1e-3 of (-n, -d) of the other), whose boxes meet
    and with every vertex of ``j`` within ``tol`` of ``i``'s plane; sorted by ``(i, j)``.

    Only triangles whose boxes meet are paired (:func:`_opposite_box_pairs`), across
    the sides of :data:`_SIDE_DIRECTION`: normals within 1e-3 of opposite lie on
    opposite sides of it, or within the margin of it on both. Planes with no opposite
    plane near them are left out first, through their distinct keys.
    """
    from scipy.spatial import cKDTree

    if not ok.any():
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    # Distinct keys, rounded to 1e-6: a plane's many triangles become one or two points
    # (a k-d tree over many equal points degenerates); the radius covers the rounding.
    step = 1e-6
    q = np.ascontiguousarray(np.round(key[ok] / step).astype(np.int64))
    _, first, which = np.unique(q.view(np.dtype((np.void, 32))).ravel(), return_index=True, return_inverse=True)
    rounded = q[first] * step
    near = cKDTree(rounded).query_ball_point(-rounded, 1e-3 + 4 * step, return_length=True)
    paired = np.zeros(len(key), bool)
    paired[np.flatnonzero(ok)] = (near > 0)[which.reshape(-1)]
    side = nrm @ _SIDE_DIRECTION
    margin = 4e-3  # > 1e-3, the farthest two paired normals are from opposite
    a, b = _opposite_box_pairs(lo, hi, nrm, paired & (side >= -margin), paired & (side <= margin))
    i = np.concatenate([a, b])
    j = np.concatenate([b, a])
    sel = np.linalg.norm(key[i] + key[j], axis=1) <= 1e-3
    i, j = i[sel], j[sel]
    if len(i):  # a triangle near the margin on both sides: a pair found both ways
        ij = np.unique(np.column_stack([i, j]), axis=0)
        i, j = ij[:, 0], ij[:, 1]
    sel = np.all(np.abs(np.einsum("kvx,kx->kv", p[j], nrm[i]) - key[i, 3][:, None]) <= tol, axis=1)
    return i[sel], j[sel]


def _cancel_partial_overlaps(
    v: NDArray[np.float64], t: NDArray[np.int64], cand: NDArray[np.int64], drop: NDArray[np.bool_], tol: float
) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64], NDArray[np.bool_]]:
    """Cancel opposite layers of a coincident face where they overlap only in part.

    :func:`_on_opposite_face` judges a triangle at its centroid, which is
    right where the opposite layer covers it whole. manifold3d may leave one
    layer as large triangles and the other as small ones (``A - (A & B)``: the
    face of ``A`` and the pieces of ``A & B``'s copy of it cut by ``B``); a
    large triangle half covered is then dropped or kept whole. Such a
    triangle is replaced by its part outside the opposite triangles
    (a fin or shell has one layer each way: they cancel where both are).

    Returns
    -------
    vertices, triangles
        The input with the replacing triangles (and their vertices) appended.
    origin : ndarray of int64
        For every output triangle, the input triangle it lies in.
    drop : ndarray of bool
        Which output triangles to drop (the replaced ones among them).
    """
    import shapely

    n_tri = len(t)
    origin = np.arange(n_tri, dtype=np.int64)
    if len(cand) < 2:
        return v, t, origin, drop
    p = v[t[cand]]  # (m, 3, 3)
    nrm = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    area2 = np.linalg.norm(nrm, axis=1)
    ok = area2 > 0
    nrm = nrm / np.where(ok, area2, 1.0)[:, None]
    off = np.einsum("ij,ij->i", nrm, p[:, 0])
    key = np.column_stack([nrm, off])
    # Opposite orientations: (n, d) of one near (-n, -d) of the other, boxes that meet,
    # and every vertex of the other within tol of the first's plane.
    lo, hi = p.min(axis=1) - tol, p.max(axis=1) + tol
    i, j = _opposite_pairs(p, nrm, ok, key, lo, hi, tol)
    if not len(i):
        return v, t, origin, drop
    # Each pair in the plane of i's triangle, seen along its normal's largest axis (areas in
    # a fixed ratio there); the layers facing one way do not overlap, so pairwise overlaps sum.
    axis = np.argmax(np.abs(nrm), axis=1)
    keep2 = np.array([[1, 2], [0, 2], [0, 1]])[axis]

    def flat(tri: NDArray[np.float64], ax: NDArray[np.int64]) -> Any:
        return shapely.polygons(np.take_along_axis(tri, ax[:, None, :], axis=2))

    # (a triangle with an opposite twin on the same vertices is covered whole)
    same_corners = np.all(np.sort(t[cand[i]], axis=1) == np.sort(t[cand[j]], axis=1), axis=1)
    twin = np.zeros(len(cand), bool)
    twin[i[same_corners]] = True
    i, j = i[~twin[i]], j[~twin[i]]
    own = flat(p[i], keep2[i])
    overlap = shapely.area(shapely.intersection(own, flat(p[j], keep2[i])))
    covered = np.bincount(i, overlap, minlength=len(cand))
    whole = np.zeros(len(cand))  # only the paired triangles' areas are read
    some = np.union1d(i, np.flatnonzero(twin))
    whole[some] = shapely.area(flat(p[some], keep2[some]))
    covered[twin] = whole[twin]
    partial = np.flatnonzero((covered > whole * 1e-9) & (covered < whole * (1 - 1e-9)))
    if not len(partial):
        return v, t, origin, drop
    # The partly covered triangles minus their opposite partners, one partner rank at a time;
    # a partner that only touches is left out: subtracting it is a no-op exactly, but not
    # always in floating point (a sliver's edge, whose result then depended on the order).
    mine = np.isin(i, partial) & (overlap > 0)
    i, j = i[mine], j[mine]
    order = np.argsort(i, kind="stable")
    i, j = i[order], j[order]
    rank = np.arange(len(i)) - np.searchsorted(i, i)
    slot = np.searchsorted(partial, i)
    rest = flat(p[partial], keep2[partial])
    for r in range(int(rank.max()) + 1):
        at = rank == r
        rest[slot[at]] = shapely.difference(rest[slot[at]], flat(p[j[at]], keep2[i[at]]))
    pieces, which = shapely.get_parts(shapely.constrained_delaunay_triangles(rest), return_index=True)
    a = partial[which]
    big = shapely.area(pieces) > whole[a] * 1e-12
    pieces, a = pieces[big], a[big]
    xy = shapely.get_coordinates(shapely.get_exterior_ring(pieces)).reshape(len(pieces), 4, 2)[:, :3]
    # back into the plane of each triangle: the dropped coordinate from n . x = d
    q = np.empty((len(a), 3, 3))
    rows = np.arange(len(a))[:, None]
    q[rows, :, keep2[a]] = np.moveaxis(xy, 2, 1)
    kept_n = np.take_along_axis(nrm[a], keep2[a], axis=1)
    q[rows[:, 0], :, axis[a]] = (off[a][:, None] - np.einsum("tvk,tk->tv", xy, kept_n)) / nrm[a, axis[a]][:, None]
    # each keeps its triangle's own orientation
    flip = np.einsum("ij,ij->i", np.cross(q[:, 1] - q[:, 0], q[:, 2] - q[:, 0]), nrm[a]) < 0
    q[flip] = q[flip, ::-1]
    replaced = np.zeros(n_tri, bool)
    replaced[cand[partial]] = True
    out_drop = np.concatenate([drop | replaced, np.zeros(len(a), bool)])
    return (
        np.vstack([v, q.reshape(-1, 3)]),
        np.vstack([t, len(v) + 3 * np.arange(len(a), dtype=np.int64)[:, None] + np.arange(3)]),
        np.concatenate([origin, cand[a]]),
        out_drop,
    )
