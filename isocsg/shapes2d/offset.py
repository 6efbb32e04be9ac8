"""OpenSCAD's ``offset``: exact rounded offsets (``r``), mitred (``delta``) and chamfered ones.

For a polygonal region P with its boundary oriented (interior on the left):

- ``r > 0`` is the Minkowski sum with a disc: P, a rectangle of width r on the
  outer side of every edge, and a disc of radius r at every convex vertex
  (the nearest boundary point of a point outside P is inside an edge, or a
  convex vertex). ``r < 0`` is P minus the rectangles on the inner side and
  discs at the reflex vertices. Every leaf is a convex polygon or a circle:
  the result is exact.
- ``delta`` replaces each disc by the corner piece of a mitre (the vertex, the
  two offset edge ends and the mitre point; a square cut past OpenSCAD's mitre
  limit of 1e6), or with ``chamfer`` by the corner cut square to the bisector
  at distance ``|delta|`` from the vertex (Clipper's square join, which
  OpenSCAD uses for ``chamfer``).

Trees are offset through identities that keep them exact: a dilation
distributes over a union, an erosion over an intersection, and
``(A - B) eroded by r = (A eroded by r) - (B dilated by r)``; circles stay
circles (radius + r, or nothing). Subtrees of polygons only are offset as one
polygonal region. Any other subtree of polygons and circles is offset with
``r`` through its exact boundary of segments and arcs
(:mod:`isocsg.shapes2d.arcoffset`): exact too. What remains (ellipses, and
``delta`` offsets of subtrees with circles that no identity reaches) is
refused, naming the case, unless a ``tolerance`` is given: such subtrees are
then polygonised (every curved leaf inscribed with a chord error at most
``tolerance``) and offset exactly as polygons.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidGeometryError
from ._checks import MAX_SEGMENTS, flag, number
from .leaves import Circle, ConvexPolygon, Ellipse, convex_polygon
from .measure import _disjoint, to_shapely
from .region import shape_from_region
from .shape import EMPTY, Difference2D, Shape2D, Union2D, _Node, fold, iter_leaves

__all__ = ["offset", "MITER_LIMIT"]

#: OpenSCAD's mitre limit (ratio of the mitre length to the offset) for ``delta`` offsets.
MITER_LIMIT = 1e6


def _piece(points: list[NDArray[np.float64]], scale: float) -> ConvexPolygon | None:
    pts = np.array(points, dtype=np.float64)
    c = pts - pts[0]
    area2 = abs(float(np.sum(c[:-1, 0] * c[1:, 1] - c[:-1, 1] * c[1:, 0])))
    if area2 <= 1e-13 * scale * scale:
        return None
    try:
        return convex_polygon(pts)
    except InvalidGeometryError:
        return None


def _corner(v: Any, t1: Any, n1: Any, t2: Any, n2: Any, d: float, mode: str, scale: float) -> Shape2D | None:
    if mode == "round":
        return Circle((float(v[0]), float(v[1])), abs(d))
    p1, p2 = v + d * n1, v + d * n2
    r = 1.0 + float(n1 @ n2)
    if mode == "mitre" and r >= 2.0 / MITER_LIMIT**2:
        return _piece([v, p1, v + d * (n1 + n2) / r, p2], scale)
    b = n1 + n2
    nb = float(np.hypot(b[0], b[1]))
    if nb < 1e-15:  # a spike turning back on itself: the square cut is the cap across both edges
        return _piece([v, p1, p1 - d * t1, p2 + d * t2, p2], scale)
    b = b / nb
    q1 = p1 + t1 * (d * (1.0 - float(n1 @ b)) / float(t1 @ b))
    q2 = p2 + t2 * (d * (1.0 - float(n2 @ b)) / float(t2 @ b))
    return _piece([v, p1, q1, q2, p2], scale)


def _region_offset(region: Any, d: float, mode: str) -> Shape2D:
    """The exact offset of a shapely region (see the module docstring)."""
    import shapely

    region = shapely.orient_polygons(shapely.normalize(region))
    base = shape_from_region(region)
    if region.is_empty:
        return EMPTY
    x0, y0, x1, y1 = region.bounds
    scale = max(x1 - x0, y1 - y0, abs(d))
    parts: list[Shape2D] = []
    for poly in shapely.get_parts(region):
        for ring in [poly.exterior, *poly.interiors]:
            pts = np.asarray(ring.coords, dtype=np.float64)[:-1]
            step = np.roll(pts, -1, axis=0) - pts
            length = np.hypot(step[:, 0], step[:, 1])
            keep = length > 0
            pts, step, length = pts[keep], step[keep], length[keep]
            t = step / length[:, None]
            n = np.stack([t[:, 1], -t[:, 0]], axis=1)  # outward: the interior is on the left
            for i in range(len(pts)):
                a, b = pts[i], pts[(i + 1) % len(pts)]
                rect = _piece([a, b, b + d * n[i], a + d * n[i]], scale)
                if rect is not None:
                    parts.append(rect)
                j = i - 1  # the edge that arrives at vertex i
                turn = float(t[j, 0] * t[i, 1] - t[j, 1] * t[i, 0])
                if turn * d > 1e-15 * abs(d):  # convex vertex when growing, reflex when shrinking
                    c = _corner(pts[i], t[j], n[j], t[i], n[i], d, mode, scale)
                    if c is not None:
                        parts.append(c)
    if d > 0:
        return Union2D((base, *parts))
    return Difference2D((base, Union2D(tuple(parts)))) if parts else base


def _segments(shape: Shape2D, tolerance: float) -> int:
    big = 0.0
    for leaf in iter_leaves(shape):
        if isinstance(leaf, (Circle, Ellipse)):
            big = max(big, float(np.linalg.norm(np.array(leaf.matrix), 2)))
    if big == 0.0:
        return 3
    half = math.acos(max(-1.0, 1.0 - tolerance / big))
    return int(min(MAX_SEGMENTS, max(8, math.ceil(math.pi / half))))


def _direct(s: Shape2D, d: float, mode: str, tol: float | None, polygonal: dict[int, bool]) -> Shape2D | None:
    """The offset of ``s`` when it needs no distribution over children; ``None`` to distribute."""
    if isinstance(s, Circle):
        r = s.radius + d
        return Circle(s.center, r) if r > 0 else EMPTY
    if polygonal[id(s)]:
        return _region_offset(to_shapely(s), d, mode)
    if isinstance(s, _Node):
        if s.op == "union" and d > 0 and (mode == "round" or _disjoint([c.bounds for c in s.children])):
            return None
        if mode == "round" and ((s.op == "intersection" and d < 0) or (s.op == "difference" and d < 0)):
            return None
    if mode == "round" and not any(isinstance(leaf, Ellipse) for leaf in iter_leaves(s)):
        from .arcoffset import boundary_offset

        exact = boundary_offset(s, d)
        if exact is not None:
            return exact
    if tol is None:
        what = type(s).__name__ if not isinstance(s, _Node) else f"{'dilated' if d > 0 else 'eroded'} {s.op}"
        raise InvalidGeometryError(
            f"offset.{'r' if mode == 'round' else 'delta'}: the offset of {'an' if what[0] in 'aeiouE' else 'a'} "
            f"{what} with curved parts has no exact form here; "
            "pass offset(..., tolerance=...) to offset a polygonisation"
        )
    return _region_offset(to_shapely(s, resolution=_segments(s, tol)), d, mode)


def offset(
    shape: Shape2D, r: Any = None, *, delta: Any = None, chamfer: bool = False, tolerance: Any = None
) -> Shape2D:
    """OpenSCAD's ``offset(r=...)`` or ``offset(delta=..., chamfer=...)`` of a 2D shape.

    Parameters
    ----------
    shape : Shape2D
    r : float, optional
        Rounded offset: outward (> 0) the Minkowski sum with a disc of radius r,
        inward (< 0) the erosion. Exact (convex polygons and circles).
    delta : float, optional
        Mitred offset (sharp corners), exact for polygons.
    chamfer : bool, default False
        With ``delta``: cut the corners square at distance ``|delta|`` (ignored
        with ``r``, as in OpenSCAD).
    tolerance : float, optional
        Allow subtrees that have no exact offset here (see the module notes) by
        offsetting their polygonisation with this chord error (> 0).

    Returns
    -------
    Shape2D

    Raises
    ------
    InvalidGeometryError
        On both or neither of ``r`` and ``delta``, non-finite values, or a
        subtree with no exact offset and no ``tolerance`` (the message names it).

    Examples
    --------
    >>> from isocsg.shapes2d import square, circle, area
    >>> abs(area(offset(square(2), 1)) - (4 + 8 + math.pi)) < 1e-9
    True
    >>> offset(circle(1), 0.5)
    Circle(center=(0.0, 0.0), radius=1.5)
    >>> area(offset(square(2), delta=1))
    16.0
    >>> round(area(offset(square(2), delta=1, chamfer=True)), 9)
    15.313708499
    """
    if (r is None) == (delta is None):
        raise InvalidGeometryError("offset takes one of r and delta")
    mode = "round" if r is not None else ("chamfer" if flag("offset.chamfer", chamfer) else "mitre")
    d = number("offset.r" if r is not None else "offset.delta", r if r is not None else delta)
    tol = None if tolerance is None else number("offset.tolerance", tolerance, low=0.0)
    if not isinstance(shape, Shape2D):
        raise InvalidGeometryError(f"offset.shape must be a 2D shape, got {type(shape).__name__}")
    if d == 0:
        return shape
    polygonal: dict[int, bool] = {}

    def mark(s: Shape2D, value: bool) -> bool:
        polygonal[id(s)] = value
        return value

    fold(shape, lambda s: mark(s, isinstance(s, ConvexPolygon)), lambda op, s, kids: mark(s, all(kids)))
    return _walk(shape, d, mode, tol, polygonal)


def _walk(shape: Shape2D, d: float, mode: str, tol: float | None, polygonal: dict[int, bool]) -> Shape2D:
    results: dict[tuple[int, float], Shape2D] = {}
    stack: list[tuple[Shape2D, float, bool]] = [(shape, d, False)]
    while stack:
        s, dd, expanded = stack.pop()
        key = (id(s), dd)
        if key in results and not expanded:
            continue
        kids = s.children if isinstance(s, _Node) else ()
        dists = [dd] + [(-dd if s.op == "difference" else dd)] * (len(kids) - 1) if kids else []  # type: ignore[attr-defined]
        if expanded:
            values = [results[(id(c), cd)] for c, cd in zip(kids, dists)]
            results[key] = type(s)(tuple(values))  # type: ignore[call-arg]
            continue
        direct = _direct(s, dd, mode, tol, polygonal)
        if direct is not None:
            results[key] = direct
            continue
        stack.append((s, dd, True))
        stack.extend((c, cd, False) for c, cd in zip(reversed(kids), reversed(dists)))
    return results[(id(shape), d)]
