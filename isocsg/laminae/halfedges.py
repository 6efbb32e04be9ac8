"""Half-edges of a triangle mesh sorted by their undirected edge, in linear time."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from .._jit import njit

__all__ = ["sorted_half_edges"]


@njit(cache=True, nogil=True)
def sorted_half_edges(
    t: NDArray[np.int64], n_vertices: int
) -> tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.int64]]:
    """The half-edges of triangles ``t`` (T, 3) in increasing order of (lower, higher) vertex.

    Half-edge ``3 * i + j`` runs from corner j to corner j + 1 of triangle i.
    They are bucketed by their lower vertex (a counting sort) and each bucket,
    a vertex's few neighbours, is sorted by the higher one (insertion sort,
    stable): the order of a stable sort by ``(lower, higher)`` without its
    ``log`` factor.

    Returns
    -------
    start : ndarray, shape (V + 1,)
        Bucket ``v`` (lower vertex ``v``) is ``start[v] .. start[v + 1] - 1``.
    higher : ndarray, shape (3 T,)
        The higher vertex of each sorted half-edge.
    owner : ndarray, shape (3 T,)
        Its index ``3 * i + j``.
    """
    nh = 3 * t.shape[0]
    start = np.zeros(n_vertices + 1, np.int64)
    for i in range(t.shape[0]):
        for j in range(3):
            start[min(t[i, j], t[i, (j + 1) % 3]) + 1] += 1
    for v in range(n_vertices):
        start[v + 1] += start[v]
    nxt = start[:-1].copy()
    higher = np.empty(nh, np.int64)
    owner = np.empty(nh, np.int64)
    for i in range(t.shape[0]):
        for j in range(3):
            a, b = t[i, j], t[i, (j + 1) % 3]
            s = nxt[min(a, b)]
            higher[s] = max(a, b)
            owner[s] = 3 * i + j
            nxt[min(a, b)] = s + 1
    for v in range(n_vertices):
        s0, s1 = start[v], start[v + 1]
        for s in range(s0 + 1, s1):
            h, o = higher[s], owner[s]
            r = s - 1
            while r >= s0 and higher[r] > h:
                higher[r + 1] = higher[r]
                owner[r + 1] = owner[r]
                r -= 1
            higher[r + 1] = h
            owner[r + 1] = o
    return start, higher, owner


@sorted_half_edges.twin
def _sorted_half_edges_numpy(
    t: NDArray[np.int64], n_vertices: int
) -> tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.int64]]:
    """:func:`sorted_half_edges` with NumPy's stable sort: the same order, the same arrays."""
    a = t.reshape(-1)
    b = t[:, [1, 2, 0]].reshape(-1)
    lower, higher = np.minimum(a, b), np.maximum(a, b)
    owner = np.lexsort((higher, lower))  # stable: ties keep the half-edges' order
    start = np.zeros(n_vertices + 1, np.int64)
    np.cumsum(np.bincount(lower, minlength=n_vertices)[:n_vertices], out=start[1:])
    return start, higher[owner], owner.astype(np.int64)
