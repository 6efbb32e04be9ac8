"""Measures and conversions of 2D shapes: ``to_shapely``, ``area``, ``area_bounds``, ``bounds``.

Areas are exact where the tree allows it (a leaf: shoelace, ``pi r^2``,
``pi |det M|``; a union of parts whose bounding boxes do not overlap: the sum;
a difference whose subtracted parts miss the first's box: the first's area; a
node whose children are polygons and circles that do not overlap one another:
closed forms of polygon-disc intersections, :mod:`isocsg.shapes2d.discarea`),
exact to rounding for trees of polygons only (shapely's overlay on the exact
pieces) and for any tree of polygons and circles (Green's theorem over its
exact boundary of segments and arcs), and with ellipses estimated from two
polygonisations of every curved leaf, inscribed and circumscribed (see
:func:`area`); :func:`area_bounds` brackets the true area rigorously.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidGeometryError
from ._checks import MAX_SEGMENTS, number
from .leaves import Circle, ConvexPolygon, Ellipse
from .shape import Shape2D, _Node, fold, iter_leaves

__all__ = ["to_shapely", "area", "area_bounds", "bounds", "is_polygonal", "DEFAULT_AREA_RESOLUTION"]

#: Segments per full circle of the polygonisations behind :func:`area` on trees that mix arcs and Booleans.
DEFAULT_AREA_RESOLUTION = 4096

Box = tuple[float, float, float, float]


def _resolution(name: str, value: Any) -> int:
    n = number(name, value, low=3.0, high=MAX_SEGMENTS, strict=False)
    if n != int(n):
        raise InvalidGeometryError(f"{name} must be an integer, got {value!r}")
    return int(n)


def _curve_ring(leaf: Shape2D, n: int, outer: bool) -> NDArray[np.float64]:
    """An n-gon inscribed in (``outer`` False) or circumscribed about (True) a circle or ellipse."""
    t = 2.0 * np.pi * np.arange(n) / n
    u = np.stack([np.cos(t), np.sin(t)], axis=1)
    if outer:
        u /= math.cos(math.pi / n)
    M = np.array(leaf.matrix, dtype=np.float64)  # type: ignore[attr-defined]
    return u @ M.T + np.array(leaf.center)  # type: ignore[attr-defined]


def _leaf_polygon(leaf: Shape2D, n: int, outer: bool) -> Any:
    import shapely

    if isinstance(leaf, ConvexPolygon):
        return shapely.Polygon(leaf.vertices)
    if isinstance(leaf, (Circle, Ellipse)):
        return shapely.Polygon(_curve_ring(leaf, n, outer))
    raise InvalidGeometryError(f"shape must be a 2D shape, got a leaf of type {type(leaf).__name__}")


def _combine(op: str, values: list[Any]) -> Any:
    import shapely

    if op == "union":
        return shapely.union_all(values) if values else shapely.Polygon()
    if op == "intersection":
        out = values[0]
        for v in values[1:]:
            out = shapely.intersection(out, v)
        return out
    rest = shapely.union_all(values[1:]) if len(values) > 1 else shapely.Polygon()
    return shapely.difference(values[0], rest)


def _signed_region(shape: Shape2D, leaf_fn: Callable[[Shape2D, int], Any]) -> Any:
    """The shapely region of the tree, each leaf given by ``leaf_fn(leaf, sign)``.

    ``sign`` is +1 where the leaf adds to the region and -1 where it is subtracted
    (an odd number of times on the right of a difference).
    """
    memo: dict[tuple[int, int], Any] = {}
    stack: list[tuple[Shape2D, int, bool]] = [(shape, 1, False)]
    while stack:
        s, sign, expanded = stack.pop()
        key = (id(s), sign)
        if key in memo:
            continue
        if not isinstance(s, _Node):
            memo[key] = leaf_fn(s, sign)
            continue
        signs = [sign] + [(-sign if s.op == "difference" else sign)] * (len(s.children) - 1)
        if expanded:
            memo[key] = _combine(s.op, [memo[(id(c), g)] for c, g in zip(s.children, signs)])
        else:
            stack.append((s, sign, True))
            stack.extend((c, g, False) for c, g in zip(reversed(s.children), reversed(signs)))
    return memo[(id(shape), 1)]


def to_shapely(shape: Shape2D, *, resolution: int = 128, circumscribed: bool = False) -> Any:
    """The shape as a shapely Polygon or MultiPolygon (for display and checks).

    Parameters
    ----------
    shape : Shape2D
    resolution : int, default 128
        Segments per full circle of each circle or ellipse (3 to 2**20).
    circumscribed : bool, default False
        Curved leaves as circumscribed polygons instead of inscribed ones.

    Examples
    --------
    >>> from isocsg.shapes2d import square, circle
    >>> to_shapely(square(2) - square(1)).area
    3.0
    >>> round(to_shapely(circle(1), resolution=4).area, 12)
    2.0
    """
    n = _resolution("to_shapely.resolution", resolution)
    region = _signed_region(shape, lambda leaf, sign: _leaf_polygon(leaf, n, circumscribed))
    return _clean(region)


#: Holes and parts of a converted region smaller than this fraction of its box's squared size are
#: overlay slivers (GEOS leaves zero-width holes along edges shared by pieces) and are dropped.
SLIVER_RTOL = 1e-12


def _clean(region: Any) -> Any:
    import shapely
    from shapely.geometry import MultiPolygon, Polygon

    if region.is_empty:
        return shapely.normalize(region)
    x0, y0, x1, y1 = region.bounds
    eps = SLIVER_RTOL * max(x1 - x0, y1 - y0) ** 2
    parts = []
    for poly in shapely.get_parts(region):
        if not isinstance(poly, Polygon) or poly.area <= eps:
            continue
        holes = [h for h in poly.interiors if Polygon(h).area > eps]
        parts.append(Polygon(poly.exterior, holes) if len(holes) != len(poly.interiors) else poly)
    out = parts[0] if len(parts) == 1 else MultiPolygon(parts) if parts else Polygon()
    return shapely.normalize(out)


def is_polygonal(shape: Shape2D) -> bool:
    """Whether every leaf is a convex polygon (no circles or ellipses)."""
    return all(isinstance(leaf, ConvexPolygon) for leaf in iter_leaves(shape))


def _disjoint(boxes: list[Box]) -> bool:
    """Whether no two boxes overlap with an interior (a sweep along x)."""
    order = sorted(range(len(boxes)), key=lambda k: boxes[k][0])
    active: list[int] = []
    for k in order:
        x0, y0, x1, y1 = boxes[k]
        active = [j for j in active if boxes[j][2] > x0]
        if any(boxes[j][1] < y1 and y0 < boxes[j][3] for j in active):
            return False
        active.append(k)
    return True


def _overlap(a: Box, b: Box) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


_Fact = tuple[Box | None, float | None, bool]  # (box, exact area or None, polygons only)


def _exact(shape: Shape2D) -> tuple[Box | None, float | None]:
    """(box, exact area or None) of a tree, by the rules of the module docstring."""

    def leaf(s: Shape2D) -> _Fact:
        return s.bounds, s.area, isinstance(s, ConvexPolygon)

    def node(op: str, s: Shape2D, kids: list[_Fact]) -> _Fact:
        box = _box(op, [k[0] for k in kids])
        poly = all(k[2] for k in kids)
        present = [k for k in kids if k[0] is not None]
        if op == "union":
            if all(k[1] is not None for k in present) and _disjoint([k[0] for k in present]):  # type: ignore[misc]
                return box, math.fsum(k[1] for k in present), poly  # type: ignore[misc]
        elif op == "difference":
            first = kids[0]
            if first[0] is None:
                return None, 0.0, poly
            if first[1] is not None and not any(k[0] is not None and _overlap(first[0], k[0]) for k in kids[1:]):
                return box, first[1], poly
        elif len(kids) == 1:
            return kids[0]
        if box is None:
            return None, 0.0, poly
        return box, (None if poly else _with_discs(op, s, [k[2] for k in kids])), poly  # type: ignore[attr-defined]

    box, exact, _ = fold(shape, leaf, node)
    return box, exact


def _with_discs(op: str, node: Any, polygonal: list[bool]) -> float | None:
    """Exact area of a node of polygonal children and circles that do not overlap one another, else None."""
    from .discarea import discs_disjoint, region_disc_area

    kids = node.children
    circles = [c for c, p in zip(kids, polygonal) if not p]
    if not all(isinstance(c, Circle) for c in circles) or not discs_disjoint([(c.center, c.radius) for c in circles]):
        return None
    polys = [c for c, p in zip(kids, polygonal) if p]
    if op == "difference":
        if not polygonal[0]:
            return None
        region = _combine("difference", [to_shapely(c) for c in polys])
        return float(region.area) - math.fsum(region_disc_area(region, c.center, c.radius) for c in circles)
    if op == "union":
        region = _combine("union", [to_shapely(c) for c in polys])
        return float(region.area) + math.fsum(c.area - region_disc_area(region, c.center, c.radius) for c in circles)
    if len(circles) == 1 and polys:
        region = _combine("intersection", [to_shapely(c) for c in polys])
        return region_disc_area(region, circles[0].center, circles[0].radius)
    return None


def _box(op: str, boxes: list[Box | None]) -> Box | None:
    if op == "difference":
        return boxes[0]
    if op == "union":
        real = [b for b in boxes if b is not None]
        if not real:
            return None
        return (min(b[0] for b in real), min(b[1] for b in real), max(b[2] for b in real), max(b[3] for b in real))
    if any(b is None for b in boxes):
        return None
    x0, y0 = max(b[0] for b in boxes), max(b[1] for b in boxes)  # type: ignore[index]
    x1, y1 = min(b[2] for b in boxes), min(b[3] for b in boxes)  # type: ignore[index]
    return (x0, y0, x1, y1) if x0 < x1 and y0 < y1 else None


def bounds(shape: Shape2D) -> tuple[float, float, float, float]:
    """``(xmin, ymin, xmax, ymax)`` of a box that contains the shape; NaNs for a shape known to be empty.

    Exact for leaves and unions; for intersections and differences it is the
    box of the operands' boxes (it may be larger than the shape's own box:
    ``to_shapely(shape).bounds`` is tight).

    Examples
    --------
    >>> from isocsg.shapes2d import square, circle
    >>> bounds(square(2) | circle(1).translate([3, 0]))
    (0.0, -1.0, 4.0, 2.0)
    """
    box = fold(shape, lambda s: s.bounds, lambda op, s, kids: _box(op, kids))
    return (math.nan,) * 4 if box is None else tuple(float(v) for v in box)  # type: ignore[return-value]


def area_bounds(shape: Shape2D, *, resolution: int = 1024) -> tuple[float, float]:
    """A rigorous bracket ``(lo, hi)`` of the area (to rounding) from inscribed and circumscribed polygonisations.

    Curved leaves that add to the region are inscribed for ``lo`` and
    circumscribed for ``hi``; those subtracted the other way round. Its width
    falls as ``resolution**-2``.

    Examples
    --------
    >>> from isocsg.shapes2d import circle
    >>> lo, hi = area_bounds(circle(1) - circle(0.5).translate([1, 0]))
    >>> lo < hi and hi - lo < 1e-4
    True
    """
    n = _resolution("area_bounds.resolution", resolution)
    lo = _signed_region(shape, lambda leaf, sign: _leaf_polygon(leaf, n, sign < 0)).area
    hi = _signed_region(shape, lambda leaf, sign: _leaf_polygon(leaf, n, sign > 0)).area
    return float(lo), float(hi)


def area(shape: Shape2D, *, resolution: int | None = None) -> float:
    """The area of a 2D shape.

    Exact (closed forms, to rounding) for every tree of polygons and circles:
    leaves, unions of parts with disjoint boxes and differences whose
    subtracted parts miss the first part's box directly; trees of polygons
    through shapely's overlay of the exact pieces; polygons with circles that
    do not overlap one another through polygon-disc closed forms; any other
    tree of polygons and circles from its exact boundary of segments and arcs
    (:mod:`isocsg.shapes2d.boundary`), checked to chain into closed loops and
    to fall in the bracket of :func:`area_bounds` at 256 segments per circle. Trees with ellipses (and a
    boundary that would fail that check) take the estimate
    ``(A_in + 2 A_out) / 3`` of the areas with every curved leaf inscribed
    (``A_in``) and circumscribed (``A_out``) by ``resolution``-gons: along every
    arc the two errors are ``-2e`` and ``+e`` (chord and tangent segments), so
    their weighted mean cancels the leading ``resolution**-2`` term.

    Parameters
    ----------
    shape : Shape2D
    resolution : int, optional
        Segments per full circle of that estimate (default :data:`DEFAULT_AREA_RESOLUTION`).

    Examples
    --------
    >>> from isocsg.shapes2d import circle, square
    >>> area(circle(1)) == math.pi
    True
    >>> half = circle(1) & square(2, center=True).translate([1, 0])
    >>> area(half) == math.pi / 2
    True
    >>> lens = circle(1) & circle(1).translate([1, 0])
    >>> abs(area(lens) - (2 * math.pi / 3 - math.sqrt(3) / 2)) < 1e-15
    True
    """
    n = DEFAULT_AREA_RESOLUTION if resolution is None else _resolution("area.resolution", resolution)
    box, exact = _exact(shape)
    if exact is not None:
        return float(exact)
    if is_polygonal(shape):
        return float(to_shapely(shape).area)
    if box is not None and not any(isinstance(leaf, Ellipse) for leaf in iter_leaves(shape)):
        from .boundary import boundary_area

        value = boundary_area(shape, box)
        if value is not None:
            lo, hi = area_bounds(shape, resolution=256)
            slack = 1e-9 * max(box[2] - box[0], box[3] - box[1]) ** 2
            if lo - slack <= value <= hi + slack:
                return value
    a_in = _signed_region(shape, lambda leaf, sign: _leaf_polygon(leaf, n, False)).area
    a_out = _signed_region(shape, lambda leaf, sign: _leaf_polygon(leaf, n, True)).area
    return float((a_in + 2.0 * a_out) / 3.0)
