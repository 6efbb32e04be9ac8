"""Pairs of band triangles merged into planar convex quads (half the polygons to fill)."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._jit import njit
from ..errors import InvalidGeometryError, InvalidParameterError
from ..laminae.halfedges import sorted_half_edges

__all__ = ["pair_quads", "COPLANAR_RELATIVE"]

#: Relative distance from the plane of a quad's first triangle within which its
#: fourth vertex counts as coplanar (the quad then shares one depth-key plane).
COPLANAR_RELATIVE = 1e-10


def pair_quads(
    vertices: ArrayLike, triangles: ArrayLike, value_out: ArrayLike, value_in: ArrayLike | None = None,
) -> tuple[NDArray[np.int32], NDArray[np.int32]]:
    """Pair triangles into planar convex quads for the one-span-per-row fill.

    Two triangles are paired when they share an edge (in opposite directions,
    as in a consistently oriented mesh) that no other triangle has, carry the
    same values, lie in one plane (within ``COPLANAR_RELATIVE`` of their size)
    and form a strictly convex quad. Edges are taken in increasing order of
    their (lower, higher) vertex pair, each pairing two triangles that are
    both still single. Band meshes are mostly such quads.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
    triangles : array_like of int, shape (T, 3)
    value_out : array_like, shape (T,)
    value_in : array_like, shape (T,), optional

    Returns
    -------
    quads : ndarray of int32, shape (P, 4)
        Counter-clockwise like the triangles; a quad ``(a, b, c, d)`` is the
        triangles ``(a, b, c)`` and ``(a, c, d)``; an unpaired triangle has
        ``d = -1``. In the order of each quad's first triangle in the mesh.
    source : ndarray of int32, shape (P,)
        A triangle of each quad (for its values).

    Examples
    --------
    >>> square = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    >>> quads, source = pair_quads(square, [(0, 1, 2), (0, 2, 3)], [0.5, 0.5])
    >>> quads.tolist(), source.tolist()
    ([[2, 3, 0, 1]], [0])
    """
    v = np.ascontiguousarray(vertices, dtype=np.float64).reshape(-1, 3)
    t = np.ascontiguousarray(triangles, dtype=np.int64).reshape(-1, 3)
    vo = np.ascontiguousarray(value_out, dtype=np.float64).reshape(-1)
    vi = vo if value_in is None else np.ascontiguousarray(value_in, dtype=np.float64).reshape(-1)
    if len(t) and (t.min() < 0 or t.max() >= len(v)):
        raise InvalidGeometryError("triangles: vertex indices out of range")
    for name, vals in (("value_out", vo), ("value_in", vi)):
        if len(vals) != len(t):
            raise InvalidParameterError(f"{name}: one value per triangle expected, got {len(vals)} for {len(t)}")
    quads, source, count = _pair_kernel(v, t, vo, vi, COPLANAR_RELATIVE)
    return quads[:count], source[:count]


@njit(cache=True, nogil=True)
def _pair_kernel(
    v: NDArray[np.float64], t: NDArray[np.int64], vo: NDArray[np.float64], vi: NDArray[np.float64], tol: float,
) -> tuple[NDArray[np.int32], NDArray[np.int32], int]:
    n_tri = t.shape[0]
    nv = v.shape[0]
    start, his, owner = sorted_half_edges(t, nv)  # edges in increasing (lower, higher) order
    partner = np.full(n_tri, -1, np.int64)
    corner = np.empty((n_tri, 4), np.int64)  # the quad, stored at its lower triangle
    for lo in range(nv):
        s0, s1 = start[lo], start[lo + 1]
        s = s0
        while s < s1:
            e = s + 1
            while e < s1 and his[e] == his[s]:
                e += 1
            if e - s == 2:  # an edge with exactly two half-edges
                h1, h2 = owner[s], owner[s + 1]
                ta, ja = h1 // 3, h1 % 3
                tb, jb = h2 // 3, h2 % 3
                p, q = t[ta, ja], t[ta, (ja + 1) % 3]
                if (
                    ta != tb and partner[ta] < 0 and partner[tb] < 0
                    and t[tb, jb] == q and t[tb, (jb + 1) % 3] == p
                    and vo[ta] == vo[tb] and vi[ta] == vi[tb]
                ):
                    r1, r2 = t[ta, (ja + 2) % 3], t[tb, (jb + 2) % 3]
                    if _planar_convex(v, p, r2, q, r1, tol):
                        partner[ta] = tb
                        partner[tb] = ta
                        m = min(ta, tb)
                        corner[m, 0], corner[m, 1], corner[m, 2], corner[m, 3] = p, r2, q, r1
            s = e
    quads = np.empty((n_tri, 4), np.int32)
    source = np.empty(n_tri, np.int32)
    count = 0
    for i in range(n_tri):
        if partner[i] < 0:
            quads[count, 0], quads[count, 1], quads[count, 2], quads[count, 3] = t[i, 0], t[i, 1], t[i, 2], -1
        elif partner[i] > i:
            for k in range(4):
                quads[count, k] = corner[i, k]
        else:
            continue
        source[count] = i
        count += 1
    return quads, source, count


@njit(cache=True, nogil=True, inline="always")
def _planar_convex(v: NDArray[np.float64], p: int, r2: int, q: int, r1: int, tol: float) -> bool:
    """The quad ``(p, r2, q, r1)``, the triangles ``(p, q, r1)`` and ``(q, p, r2)``, is planar and strictly convex."""
    nx = (v[q, 1] - v[p, 1]) * (v[r1, 2] - v[p, 2]) - (v[q, 2] - v[p, 2]) * (v[r1, 1] - v[p, 1])
    ny = (v[q, 2] - v[p, 2]) * (v[r1, 0] - v[p, 0]) - (v[q, 0] - v[p, 0]) * (v[r1, 2] - v[p, 2])
    nz = (v[q, 0] - v[p, 0]) * (v[r1, 1] - v[p, 1]) - (v[q, 1] - v[p, 1]) * (v[r1, 0] - v[p, 0])
    nlen = math.sqrt(nx * nx + ny * ny + nz * nz)
    if not nlen > 0.0:
        return False
    size = 0.0
    for o in (q, r1, r2):
        size = max(size, math.sqrt((v[o, 0] - v[p, 0]) ** 2 + (v[o, 1] - v[p, 1]) ** 2 + (v[o, 2] - v[p, 2]) ** 2))
    off = abs(nx * (v[r2, 0] - v[p, 0]) + ny * (v[r2, 1] - v[p, 1]) + nz * (v[r2, 2] - v[p, 2]))
    if not off <= tol * size * nlen:
        return False
    ring = (p, r2, q, r1)
    for k in range(4):
        c0, c1, c2 = ring[k], ring[(k + 1) % 4], ring[(k + 2) % 4]
        e0x, e0y, e0z = v[c1, 0] - v[c0, 0], v[c1, 1] - v[c0, 1], v[c1, 2] - v[c0, 2]
        e1x, e1y, e1z = v[c2, 0] - v[c1, 0], v[c2, 1] - v[c1, 1], v[c2, 2] - v[c1, 2]
        turn = (e0y * e1z - e0z * e1y) * nx + (e0z * e1x - e0x * e1z) * ny + (e0x * e1y - e0y * e1x) * nz
        if not turn > 0.0:
            return False
    return True


def _planar_convex_numpy(v: NDArray[np.float64], p: NDArray[np.int64], r2: NDArray[np.int64], q: NDArray[np.int64],
                         r1: NDArray[np.int64], tol: float) -> NDArray[np.bool_]:
    """:func:`_planar_convex` of many quads, the same arithmetic in the same order."""
    vp, vq, v1, v2 = v[p], v[q], v[r1], v[r2]
    nx = (vq[:, 1] - vp[:, 1]) * (v1[:, 2] - vp[:, 2]) - (vq[:, 2] - vp[:, 2]) * (v1[:, 1] - vp[:, 1])
    ny = (vq[:, 2] - vp[:, 2]) * (v1[:, 0] - vp[:, 0]) - (vq[:, 0] - vp[:, 0]) * (v1[:, 2] - vp[:, 2])
    nz = (vq[:, 0] - vp[:, 0]) * (v1[:, 1] - vp[:, 1]) - (vq[:, 1] - vp[:, 1]) * (v1[:, 0] - vp[:, 0])
    nlen = np.sqrt(nx * nx + ny * ny + nz * nz)
    size = np.zeros(len(p))
    for vo in (vq, v1, v2):
        d = vo - vp
        size = np.maximum(size, np.sqrt(d[:, 0] ** 2 + d[:, 1] ** 2 + d[:, 2] ** 2))
    d = v2 - vp
    off = np.abs(nx * d[:, 0] + ny * d[:, 1] + nz * d[:, 2])
    ok = (nlen > 0.0) & (off <= tol * size * nlen)
    ring = (vp, v2, vq, v1)
    for k in range(4):
        e0 = ring[(k + 1) % 4] - ring[k]
        e1 = ring[(k + 2) % 4] - ring[(k + 1) % 4]
        turn = ((e0[:, 1] * e1[:, 2] - e0[:, 2] * e1[:, 1]) * nx + (e0[:, 2] * e1[:, 0] - e0[:, 0] * e1[:, 2]) * ny
                + (e0[:, 0] * e1[:, 1] - e0[:, 1] * e1[:, 0]) * nz)
        ok &= turn > 0.0
    return ok


@_pair_kernel.twin
def _pair_numpy(
    v: NDArray[np.float64], t: NDArray[np.int64], vo: NDArray[np.float64], vi: NDArray[np.float64], tol: float,
) -> tuple[NDArray[np.int32], NDArray[np.int32], int]:
    """:func:`_pair_kernel` with the tests vectorised; the greedy pairing, edge after edge, stays a loop."""
    n_tri = t.shape[0]
    start, his, owner = sorted_half_edges(t, v.shape[0])
    lower = np.repeat(np.arange(v.shape[0]), np.diff(start))
    new = np.ones(len(his) + 1, bool)  # where a run of one undirected edge starts (and the end)
    new[1:-1] = (his[1:] != his[:-1]) | (lower[1:] != lower[:-1])
    runs = np.flatnonzero(new)
    s = runs[:-1][np.diff(runs) == 2]  # edges with exactly two half-edges
    ta, ja = owner[s] // 3, owner[s] % 3
    tb, jb = owner[s + 1] // 3, owner[s + 1] % 3
    p, q = t[ta, ja], t[ta, (ja + 1) % 3]
    r1, r2 = t[ta, (ja + 2) % 3], t[tb, (jb + 2) % 3]
    ok = (ta != tb) & (t[tb, jb] == q) & (t[tb, (jb + 1) % 3] == p) & (vo[ta] == vo[tb]) & (vi[ta] == vi[tb])
    ok[ok] = _planar_convex_numpy(v, p[ok], r2[ok], q[ok], r1[ok], tol)
    partner = np.full(n_tri, -1, np.int64)
    single = [True] * n_tri
    chosen = []
    for e, a, b in zip(np.flatnonzero(ok).tolist(), ta[ok].tolist(), tb[ok].tolist()):
        if single[a] and single[b]:
            single[a] = single[b] = False
            chosen.append(e)
    pick = np.asarray(chosen, np.int64)
    partner[ta[pick]], partner[tb[pick]] = tb[pick], ta[pick]
    corner = np.empty((n_tri, 4), np.int64)
    corner[np.minimum(ta[pick], tb[pick])] = np.stack([p[pick], r2[pick], q[pick], r1[pick]], axis=1)
    rows = np.flatnonzero((partner < 0) | (partner > np.arange(n_tri)))
    quads = np.where((partner[rows] < 0)[:, None], np.column_stack([t[rows], np.full(len(rows), -1)]), corner[rows])
    return quads.astype(np.int32), rows.astype(np.int32), len(rows)
