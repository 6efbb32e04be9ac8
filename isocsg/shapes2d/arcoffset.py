"""Exact rounded offsets of any tree of polygons and circles, through its boundary of segments and arcs.

The dilation of a region X by r is X together with every point within r of
its boundary; the erosion is X without them. The points within r of a
boundary made of segments and circular arcs (:mod:`isocsg.shapes2d.boundary`)
are the union of, for each segment, the rectangle of half-width r about it,
for each arc of radius R the annular sector between radii ``R - r`` and
``R + r`` over its angles (a circle of radius ``R + r`` cut by convex wedges of
at most 90 degrees, minus the circle of radius ``R - r``), and a disc of
radius r at every end point. Every leaf is a convex polygon or a circle, so
the result is exact: ``offset(offset(shape, r=-1), r=1)`` and the other
idioms that round corners stay exact trees.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .boundary import boundary_pieces, closed
from .leaves import Circle, ConvexPolygon, convex_polygon
from .shape import Difference2D, Intersection2D, Shape2D, Union2D

__all__ = ["boundary_offset"]


def _convex(points: list[Any], scale: float) -> ConvexPolygon | None:
    pts = np.array(points, dtype=np.float64)
    c = pts - pts[0]
    if abs(float(np.sum(c[:-1, 0] * c[1:, 1] - c[:-1, 1] * c[1:, 0]))) <= 1e-13 * scale * scale:
        return None  # a sliver of no area: the end discs cover it to rounding
    return convex_polygon(pts)


def _sector(c: Any, R: float, r: float, t0: float, t1: float, scale: float) -> list[Shape2D]:
    out: list[Shape2D] = []
    k = max(1, math.ceil((t1 - t0) / (math.pi / 2)))
    outer = Circle((float(c[0]), float(c[1])), R + r)
    inner = Circle((float(c[0]), float(c[1])), R - r) if R > r else None
    for i in range(k):
        a, b = t0 + (t1 - t0) * i / k, t0 + (t1 - t0) * (i + 1) / k
        reach = (R + r) / math.cos(0.5 * (b - a)) * (1 + 1e-9)
        ua, ub = np.array([math.cos(a), math.sin(a)]), np.array([math.cos(b), math.sin(b)])
        wedge = _convex([c, c + reach * ua, c + reach * ub], scale)
        if wedge is None:
            continue
        part: Shape2D = Intersection2D((outer, wedge))
        out.append(Difference2D((part, inner)) if inner is not None else part)
    return out


def boundary_offset(shape: Shape2D, d: float) -> Shape2D | None:
    """The exact rounded offset of a tree of polygons and circles (``None`` if its boundary is not closed)."""
    box = shape.bounds
    if math.isnan(box[0]):
        return shape
    scale = max(box[2] - box[0], box[3] - box[1], abs(d))
    pieces = boundary_pieces(shape, box)
    if not closed(pieces, 1e-9 * scale):
        return None
    r = abs(d)
    parts: list[Shape2D] = []
    ends: dict[tuple[int, int], tuple[float, float]] = {}
    q = 1e-12 * scale
    for p in pieces:
        for e in (p.a, p.b):
            ends.setdefault((round(e[0] / q), round(e[1] / q)), e)
        if p.radius == 0.0:
            a, b = np.array(p.a), np.array(p.b)
            t = (b - a) / float(np.hypot(*(b - a)))
            n = np.array([-t[1], t[0]]) * r
            rect = _convex([a + n, b + n, b - n, a - n], scale)
            if rect is not None:
                parts.append(rect)
        else:
            parts.extend(_sector(np.array(p.center), p.radius, r, p.t0, p.t1, scale))
    parts.extend(Circle(e, r) for e in ends.values())
    band = Union2D(tuple(parts))
    return Union2D((shape, band)) if d > 0 else Difference2D((shape, band))
