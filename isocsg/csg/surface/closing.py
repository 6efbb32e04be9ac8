"""Band meshes closed: a leaf's triangle soup welded into a closed manifold mesh.

Band meshes are cut face by face, so equal vertices repeat and a vertex of one
face may lie inside an edge of its neighbour (a T-junction); manifold3d takes
only closed meshes.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from ..._jit import njit
from ...laminae.split import mesh_edges

# Relative distance (to the mesh size) within which a vertex lies on an open edge.
_ON_EDGE_RELATIVE = 1e-9
# Coordinates of magnitude m carry rounding of about eps * m: a vertex on an edge
# may be this many such units away from it (band meshes far from the origin).
_ON_EDGE_ULPS = 64.0


def close_mesh(
    vertices: NDArray[np.float64], triangles: NDArray[np.int64]
) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]:
    """Weld a triangle soup that tiles a closed surface into a closed mesh.

    Band meshes are cut face by face: equal vertices may be repeated, and a
    vertex of one face may lie inside an edge of its neighbour (a
    T-junction). Repeated vertices are merged (also those within the tolerance
    below of each other: a point cut from two faces comes out a few ulps
    apart), and each open edge with such
    vertices inside is split at them (its triangle becomes a fan, in the same
    plane, so the surface and the orientation are unchanged). A vertex lies on
    an edge within 1e-9 of the mesh size, or within the rounding of its
    coordinates where they are large (a mesh far from the origin).

    Parameters
    ----------
    vertices : ndarray, shape (V, 3)
    triangles : ndarray of int, shape (T, 3)

    Returns
    -------
    vertices : ndarray, shape (V', 3)
    triangles : ndarray of int64, shape (T', 3)
    source : ndarray of int64, shape (T',)
        The input triangle each output triangle lies in.

    Examples
    --------
    A unit square whose right half is split at the middle of the shared edge:

    >>> v = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [1, 0.5, 0], [2, 0, 0], [2, 1, 0]], float)
    >>> t = np.array([[0, 1, 2], [0, 2, 3], [1, 5, 4], [4, 5, 6], [4, 6, 2]])
    >>> _, t2, src = close_mesh(v, t)
    >>> len(t2), sorted(src.tolist())
    (6, [0, 0, 1, 2, 3, 4])
    """
    v, t, src, _ = close_soup(vertices, triangles)
    return v, t, src


def close_soup(
    vertices: NDArray[np.float64], triangles: NDArray[np.int64]
) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64], bool]:
    """:func:`close_mesh`, and whether every edge of the result is used by exactly two triangles."""
    v = np.ascontiguousarray(vertices, dtype=np.float64).reshape(-1, 3)
    t = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    src = np.arange(len(t), dtype=np.int64)
    if not len(t):
        return v, t, src, False
    # Bit-equal vertices are one vertex (+0.0: -0.0 == 0.0).
    first, inverse = _equal_rows(np.ascontiguousarray(v + 0.0).view(np.int64))
    v = v[first]
    t = inverse[t]
    size = float(np.ptp(v, axis=0).max())
    magnitude = float(np.abs(v).max())
    tol = max(_ON_EDGE_RELATIVE * size, _ON_EDGE_ULPS * np.finfo(np.float64).eps * magnitude, 1e-300)
    # Vertices within rounding of each other are one vertex too: the same point cut from the two
    # parts meeting at a rim (or a cone's apex) comes out a few ulps apart; a triangle that then
    # repeats a vertex has no area and goes.
    v, t = _merge_near(v, t, tol)
    keep = (t[:, 0] != t[:, 1]) & (t[:, 1] != t[:, 2]) & (t[:, 2] != t[:, 0])
    t, src = t[keep], src[keep]
    closed = False
    for _ in range(8):  # each pass splits one open edge per triangle
        u = t.ravel()
        w = t[:, [1, 2, 0]].ravel()
        open_h = _open_half_edges(t)
        if not len(open_h):
            closed = True
            break
        ends = np.unique(np.concatenate([u[open_h], w[open_h]]))
        split_e, split_v, split_s = _points_on_edges(v, u[open_h], w[open_h], ends, tol)
        if not len(split_e):
            break
        # One open edge per triangle this pass (the others in the next).
        h = open_h[split_e]
        tri = h // 3
        first_e = np.unique(tri, return_index=True)[1]
        keep_edge = np.zeros(len(open_h), bool)
        keep_edge[split_e[first_e]] = True
        sel = keep_edge[split_e]
        split_e, split_v, split_s = split_e[sel], split_v[sel], split_s[sel]
        edges = np.unique(split_e)
        eh = open_h[edges]
        # Chains u -> inner vertices (by position) -> w on every split edge.
        chain_e = np.concatenate([edges, split_e, edges])
        chain_v = np.concatenate([u[eh], split_v, w[eh]])
        chain_s = np.concatenate([np.zeros(len(edges)), split_s, np.ones(len(edges))])
        order = np.lexsort((chain_s, chain_e))
        chain_e, chain_v = chain_e[order], chain_v[order]
        link = np.flatnonzero(chain_e[1:] == chain_e[:-1])
        link_h = open_h[chain_e[link]]
        link_t = link_h // 3
        apex = t[link_t, (link_h % 3 + 2) % 3]
        fan = np.column_stack([chain_v[link], chain_v[link + 1], apex])
        drop = np.zeros(len(t), bool)
        drop[eh // 3] = True
        t = np.vstack([t[~drop], fan])
        src = np.concatenate([src[~drop], src[link_t]])
    else:
        closed = not len(_open_half_edges(t))
    return v, t, src, closed
def _merge_near(
    v: NDArray[np.float64], t: NDArray[np.int64], tol: float,
) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Merge vertices closer than ``tol`` (clusters linked by such pairs) into their first member."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree

    pairs = cKDTree(v).query_pairs(tol, output_type="ndarray")
    if not len(pairs):
        return v, t
    n = len(v)
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n))
    _, label = connected_components(graph, directed=False)
    first = np.full(n, n, np.int64)
    np.minimum.at(first, label, np.arange(n))
    rep = first[label]
    used, new_index = np.unique(rep, return_inverse=True)
    return v[used], new_index.reshape(-1)[t]


@njit(cache=True)
def _equal_rows(bits: NDArray[np.int64]) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Rows of equal bits: the first of each kind (in order) and every row's kind (a hash table)."""
    n = bits.shape[0]
    size = 1
    while size < 2 * n + 2:
        size *= 2
    table = np.full(size, -1, np.int64)
    kind = np.empty(n, np.int64)
    first = np.empty(n, np.int64)
    count = 0
    for r in range(n):
        h = (bits[r, 0] * 0x9E3779B97F4A7C15) ^ (bits[r, 1] * 0xC2B2AE3D27D4EB4F) ^ (bits[r, 2] * 0x165667B19E3779F9)
        slot = (h ^ (h >> 29)) & (size - 1)
        while True:
            k = table[slot]
            if k < 0:
                table[slot] = count
                first[count] = r
                kind[r] = count
                count += 1
                break
            f = first[k]
            if bits[f, 0] == bits[r, 0] and bits[f, 1] == bits[r, 1] and bits[f, 2] == bits[r, 2]:
                kind[r] = k
                break
            slot = (slot + 1) & (size - 1)
    return first[:count], kind


@_equal_rows.twin
def _equal_rows_numpy(bits: NDArray[np.int64]) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """:func:`_equal_rows` by sorting (its hash multiplies past int64, which only compiled code wraps)."""
    if not len(bits):
        return np.empty(0, np.int64), np.empty(0, np.int64)
    _, first, inverse = np.unique(bits, axis=0, return_index=True, return_inverse=True)
    order = np.argsort(first, kind="stable")  # kinds numbered in the order they first appear
    rank = np.empty(len(order), np.int64)
    rank[order] = np.arange(len(order))
    return first[order].astype(np.int64), rank[inverse.reshape(-1)]


def _open_half_edges(t: NDArray[np.int64]) -> NDArray[np.int64]:
    """Half-edges (corner j to j + 1 of each triangle, flattened) whose undirected edge is not used exactly twice."""
    tri_edge = mesh_edges(t)[1].ravel()
    return np.flatnonzero(np.bincount(tri_edge)[tri_edge] != 2)


@njit(cache=True)
def _points_on_edges(
    v: NDArray[np.float64], a: NDArray[np.int64], b: NDArray[np.int64], cand: NDArray[np.int64], tol: float
) -> tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.float64]]:
    """(edge, vertex, parameter) of candidate vertices strictly inside edges ``a -> b``."""
    out_e = []
    out_v = []
    out_s = []
    for e in range(len(a)):
        ax, ay, az = v[a[e], 0], v[a[e], 1], v[a[e], 2]
        dx, dy, dz = v[b[e], 0] - ax, v[b[e], 1] - ay, v[b[e], 2] - az
        length2 = dx * dx + dy * dy + dz * dz
        if length2 == 0.0:
            continue
        lox, hix = min(ax, ax + dx) - tol, max(ax, ax + dx) + tol
        loy, hiy = min(ay, ay + dy) - tol, max(ay, ay + dy) + tol
        loz, hiz = min(az, az + dz) - tol, max(az, az + dz) + tol
        for k in range(len(cand)):
            c = cand[k]
            px, py, pz = v[c, 0], v[c, 1], v[c, 2]
            if px < lox or px > hix or py < loy or py > hiy or pz < loz or pz > hiz or c == a[e] or c == b[e]:
                continue
            rx, ry, rz = px - ax, py - ay, pz - az
            s = (rx * dx + ry * dy + rz * dz) / length2
            # Strictly inside. Vertices within ``tol`` of an end were merged with it, so any other
            # vertex near the line is a T-junction, however close to an end: a relative margin
            # here left open the edges of nearly coplanar faces, whose cuts of a shared edge
            # come out a few nanometres apart (more than ``tol``, less than the margin).
            if s <= 0.0 or s >= 1.0:
                continue
            qx, qy, qz = rx - s * dx, ry - s * dy, rz - s * dz
            if qx * qx + qy * qy + qz * qz <= tol * tol:
                out_e.append(e)
                out_v.append(c)
                out_s.append(s)
    return np.array(out_e, np.int64), np.array(out_v, np.int64), np.array(out_s, np.float64)
