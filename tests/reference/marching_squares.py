"""A plain marching-squares tracer in pure Python: the reference for isolux lines.

It was the library's own implementation before contourpy; it is kept here,
independent of contourpy, as the judge of the lines' points and as the peer
in ``benchmarks/isolux.py``. Cells are split by linear interpolation along
their edges; saddle cells by the average of their four corners; cells
touching a NaN node have no lines.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["marching_squares"]


# Marching squares: corners (0: (i, j), 1: (i+1, j), 2: (i+1, j+1), 3: (i, j+1)); edges
# 0: bottom (c0-c1), 1: right (c1-c2), 2: top (c3-c2), 3: left (c0-c3). Case bit k = corner k above.
_SEGMENTS: dict[int, tuple[tuple[int, int], ...]] = {
    1: ((3, 0),), 2: ((0, 1),), 3: ((3, 1),), 4: ((1, 2),), 6: ((0, 2),), 7: ((3, 2),),
    8: ((2, 3),), 9: ((2, 0),), 11: ((2, 1),), 12: ((1, 3),), 13: ((1, 0),), 14: ((0, 3),),
}
# saddles (5: corners 0 and 2 above; 10: corners 1 and 3): (centre above, centre below)
_SADDLES = {5: (((3, 2), (1, 0)), ((3, 0), (1, 2))), 10: (((0, 3), (2, 1)), ((0, 1), (2, 3)))}


def _edge_key(i: int, j: int, e: int) -> tuple[int, int, int]:
    """A cell edge as a key shared by both cells: (i, j, 0) horizontal from (i, j), (i, j, 1) vertical."""
    return {0: (i, j, 0), 1: (i + 1, j, 1), 2: (i, j + 1, 0), 3: (i, j, 1)}[e]


def _edge_point(
    Z: NDArray[np.float64], level: float, points: dict[tuple[int, int, int], NDArray[np.float64]], k: tuple[int, int, int]
) -> tuple[int, int, int]:
    """The edge ``k``'s crossing of ``level``, interpolated once and kept in ``points``; returns ``k``."""
    if k not in points:
        a0, a1 = (k[0], k[1]), ((k[0] + 1, k[1]) if k[2] == 0 else (k[0], k[1] + 1))
        z0, z1 = Z[a0[1], a0[0]], Z[a1[1], a1[0]]
        t = (level - z0) / (z1 - z0)
        points[k] = np.array([a0[0] + t * (a1[0] - a0[0]), a0[1] + t * (a1[1] - a0[1])])
    return k


def marching_squares(E: ArrayLike, levels: ArrayLike) -> list[list[tuple[NDArray[np.float64], bool]]]:
    """Contour lines of a 2D field by marching squares.

    Parameters
    ----------
    E : array_like, shape (ny, nx)
        Values at grid nodes, ``E[j, i]``; NaN nodes are left out (cells
        touching them have no lines).
    levels : array_like, shape (k,)

    Returns
    -------
    list of list of (ndarray, bool)
        For each level, its polylines as ``(points (m, 2) of fractional
        node coordinates (i, j), closed)``.
    """
    Z = np.asarray(E, dtype=np.float64)
    if Z.ndim != 2 or min(Z.shape) < 2:
        raise ValueError(f"E must be a 2-D array with at least 2 x 2 values, got shape {Z.shape}")
    out = []
    for level in np.asarray(levels, dtype=np.float64).reshape(-1):
        above = Z > level
        c = np.stack([above[:-1, :-1], above[:-1, 1:], above[1:, 1:], above[1:, :-1]])  # (4, ny-1, nx-1)
        case = c[0] * 1 + c[1] * 2 + c[2] * 4 + c[3] * 8
        finite = np.isfinite(Z)
        ok = finite[:-1, :-1] & finite[:-1, 1:] & finite[1:, 1:] & finite[1:, :-1]
        cells = np.argwhere(ok & (case != 0) & (case != 15))
        points: dict[tuple[int, int, int], NDArray[np.float64]] = {}
        adj: dict[tuple[int, int, int], list[tuple[int, int, int]]] = {}
        for j, i in cells:
            cs = int(case[j, i])
            if cs in _SADDLES:
                centre = 0.25 * (Z[j, i] + Z[j, i + 1] + Z[j + 1, i + 1] + Z[j + 1, i])
                segs = _SADDLES[cs][0 if centre > level else 1]
            else:
                segs = _SEGMENTS[cs]
            for e0, e1 in segs:
                a = _edge_point(Z, level, points, _edge_key(i, j, e0))
                b = _edge_point(Z, level, points, _edge_key(i, j, e1))
                adj.setdefault(a, []).append(b)
                adj.setdefault(b, []).append(a)
        out.append(_chain(points, adj))
    return out


def _chain(points: dict[Any, NDArray[np.float64]], adj: dict[Any, list[Any]]) -> list[tuple[NDArray[np.float64], bool]]:
    """Join segments (an adjacency of edge points) into polylines."""
    seen: set[tuple[Any, Any]] = set()
    lines = []
    # open lines start at points with one neighbour (the grid border); then the closed loops
    starts = [k for k, nb in adj.items() if len(nb) == 1] + list(adj)
    for s in starts:
        for nxt in adj[s]:
            if (s, nxt) in seen:
                continue
            path = [s]
            prev, cur = s, nxt
            seen.add((s, nxt))
            seen.add((nxt, s))
            closed = False
            while True:
                path.append(cur)
                if cur == s:
                    closed = True
                    break
                options = [k for k in adj[cur] if (cur, k) not in seen]
                if not options:
                    break
                prev, cur = cur, options[0]
                seen.add((prev, cur))
                seen.add((cur, prev))
            lines.append((np.array([points[k] for k in path]), closed))
    return lines


