"""Exact areas of polygonal regions cut by discs (closed forms, no polygonisation).

The area of a region R (oriented rings, interior on the left) inside a disc
of centre c and radius r is the sum over the directed edges (a, b) of the
signed area of the triangle (c, a, b) inside the disc: each is a sector, a
triangle and a sector (the parts of the edge outside, inside and outside the
circle). This gives exact areas of a polygon with circular holes, a polygon
intersected with a disc, and a polygon united with discs, when the discs do
not overlap one another.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

__all__ = ["region_disc_area", "discs_disjoint"]


def _sector(u: NDArray[np.float64], v: NDArray[np.float64], r: float) -> float:
    return 0.5 * r * r * math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1])


def _edge(a: NDArray[np.float64], b: NDArray[np.float64], r: float) -> float:
    """Signed area of the triangle (0, a, b) inside the disc of radius r about 0."""
    d = b - a
    A = float(d @ d)
    if A == 0.0:
        return 0.0
    B = float(a @ d)
    C = float(a @ a) - r * r
    disc = B * B - A * C
    if disc <= 0.0:
        return _sector(a, b, r)
    s = math.sqrt(disc)
    t1, t2 = (-B - s) / A, (-B + s) / A
    if t2 <= 0.0 or t1 >= 1.0:
        return _sector(a, b, r)
    p1 = a + max(t1, 0.0) * d
    p2 = a + min(t2, 1.0) * d
    tri = 0.5 * (p1[0] * p2[1] - p1[1] * p2[0])
    return _sector(a, p1, r) + tri + _sector(p2, b, r)


def region_disc_area(region: Any, center: Sequence[float], radius: float) -> float:
    """The exact area of a shapely region inside the disc (``center``, ``radius``).

    Examples
    --------
    >>> from shapely.geometry import box
    >>> round(region_disc_area(box(0, 0, 2, 2), (0, 0), 1) / math.pi, 12)
    0.25
    """
    import shapely

    total: list[float] = []
    c = np.asarray(center, dtype=np.float64)
    for poly in shapely.get_parts(shapely.orient_polygons(region)):
        if poly.is_empty:
            continue
        for ring in [poly.exterior, *poly.interiors]:
            pts = np.asarray(ring.coords, dtype=np.float64) - c
            total.extend(_edge(pts[i], pts[i + 1], radius) for i in range(len(pts) - 1))
    return math.fsum(total)


def discs_disjoint(discs: Sequence[tuple[tuple[float, float], float]]) -> bool:
    """Whether no two discs ``((x, y), r)`` overlap with an interior (a sweep along x)."""
    order = sorted(range(len(discs)), key=lambda k: discs[k][0][0] - discs[k][1])
    active: list[int] = []
    for k in order:
        (x, y), r = discs[k]
        active = [j for j in active if discs[j][0][0] + discs[j][1] > x - r]
        for j in active:
            (xj, yj), rj = discs[j]
            if math.hypot(x - xj, y - yj) < r + rj:
                return False
        active.append(k)
    return True
