"""OpenSCAD's 2D primitives as exact shapes: ``polygon``, ``square`` and ``circle``.

``circle`` without ``fn`` is the exact disc; with ``fn`` it is OpenSCAD's
regular polygon (``max(fn, 3)`` vertices at the angles ``360 i / n`` degrees,
the first on the +x axis), the shape OpenSCAD itself draws for an explicit
``$fn``. ``polygon`` fills its paths by the even-odd rule (a path inside
another is a hole) and is split into exact convex pieces.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..errors import InvalidGeometryError
from ._checks import MAX_VERTICES, flag, number, points2, positive, vector2
from .leaves import Circle, ConvexPolygon
from .region import fill, shape_from_region
from .shape import Shape2D

__all__ = ["polygon", "square", "circle", "regular_polygon"]


def _paths(paths: Any, n: int) -> list[list[int]]:
    if isinstance(paths, (str, bytes)) or not hasattr(paths, "__iter__"):
        raise InvalidGeometryError(f"polygon.paths must be a list of index lists, got {type(paths).__name__}")
    out = []
    for k, path in enumerate(paths):
        if isinstance(path, (str, bytes)) or not hasattr(path, "__iter__"):
            raise InvalidGeometryError(f"polygon.paths[{k}] must be a list of point indices, got {path!r}")
        idx = []
        for i in path:
            if isinstance(i, (bool, np.bool_)) or not isinstance(i, (int, np.integer, float)) or int(i) != i:
                raise InvalidGeometryError(f"polygon.paths[{k}] must hold integer indices, got {i!r}")
            if not 0 <= int(i) < n:
                raise InvalidGeometryError(f"polygon.paths[{k}] indices must be in [0, {n - 1}], got {int(i)}")
            idx.append(int(i))
        if len(idx) < 3:
            raise InvalidGeometryError(f"polygon.paths[{k}] must have at least 3 indices, got {len(idx)}")
        out.append(idx)
    if not out:
        raise InvalidGeometryError("polygon.paths must hold at least one path, got none")
    return out


def polygon(points: Any, paths: Any = None) -> Shape2D:
    """OpenSCAD's ``polygon(points, paths)``: a region, non-convex and with holes, as exact convex pieces.

    Parameters
    ----------
    points : array_like, shape (n, 2)
        At least 3 points, finite.
    paths : list of lists of int, optional
        Rings as indices into ``points``; default: all points in order. The
        region is what the rings fill by the even-odd rule (a ring inside
        another is a hole; self-crossing rings are allowed).

    Returns
    -------
    Shape2D
        One :class:`ConvexPolygon`, or the union of the convex pieces of the
        region (they do not overlap; their areas add up to the region's).

    Raises
    ------
    InvalidGeometryError
        On malformed points or paths, or rings that enclose no area.

    Examples
    --------
    >>> ring = polygon([(0, 0), (4, 0), (4, 4), (0, 4), (1, 1), (3, 1), (3, 3), (1, 3)],
    ...                [[0, 1, 2, 3], [4, 5, 6, 7]])
    >>> ring.area
    12.0
    >>> type(polygon([(0, 0), (1, 0), (0, 1)])).__name__
    'ConvexPolygon'
    """
    pts = points2("polygon.points", points, minimum=3)
    rings = [pts] if paths is None else [pts[p] for p in _paths(paths, len(pts))]
    if sum(len(r) for r in rings) > MAX_VERTICES:
        raise InvalidGeometryError(f"polygon.paths must use at most {MAX_VERTICES} points in all")
    region = fill(rings, "evenodd", name="polygon")
    if region.is_empty or region.area <= 0:
        raise InvalidGeometryError("polygon.points must enclose an area > 0, got a degenerate polygon")
    return shape_from_region(region)


def square(size: Any = 1.0, center: bool = False) -> ConvexPolygon:
    """OpenSCAD's ``square(size, center)``: a number or ``[x, y]``, corner at the origin unless ``center``.

    Examples
    --------
    >>> square([2, 1]).vertices
    ((0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (0.0, 1.0))
    >>> square(2, center=True).bounds
    (-1.0, -1.0, 1.0, 1.0)
    """
    if isinstance(size, (list, tuple, np.ndarray)):
        sx, sy = vector2("square.size", size)
    else:
        sx = sy = number("square.size", size)
    if not (sx > 0 and sy > 0):
        raise InvalidGeometryError(f"square.size must be > 0 in x and y, got [{sx:g}, {sy:g}]")
    x0, y0 = (-sx / 2, -sy / 2) if flag("square.center", center) else (0.0, 0.0)
    return ConvexPolygon(((x0, y0), (x0 + sx, y0), (x0 + sx, y0 + sy), (x0, y0 + sy)))


def regular_polygon(radius: float, n: int) -> ConvexPolygon:
    """OpenSCAD's polygon of a circle with ``n`` fragments: vertices ``r (cos, sin)(360 i / n)``."""
    verts = []
    for i in range(n):
        a = 360.0 * i / n
        q, rem = divmod(a, 90.0)
        c, s = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)][int(q) % 4] if rem == 0 else (
            math.cos(math.radians(a)),
            math.sin(math.radians(a)),
        )
        verts.append((radius * c, radius * s))
    return ConvexPolygon(tuple(verts))


def circle(r: Any = None, d: Any = None, *, fn: Any = None) -> Shape2D:
    """OpenSCAD's ``circle(r)`` or ``circle(d=...)``: the exact disc, or its regular polygon for ``fn``.

    Parameters
    ----------
    r, d : float
        Radius or diameter (> 0; give one). With neither, ``r = 1`` (OpenSCAD's default).
    fn : int, optional
        OpenSCAD's ``$fn``: ``None`` or 0 gives the exact disc; ``fn >= 1``
        gives OpenSCAD's regular polygon with ``max(fn, 3)`` vertices, the
        first at angle 0.

    Examples
    --------
    >>> circle(2)
    Circle(center=(0.0, 0.0), radius=2.0)
    >>> circle(d=2, fn=4).vertices
    ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))
    """
    if r is not None and d is not None:
        raise InvalidGeometryError("circle takes r or d, not both")
    radius = positive("circle.d", d) / 2 if d is not None else positive("circle.r", 1.0 if r is None else r)
    if fn is None:
        return Circle((0.0, 0.0), radius)
    n = number("circle.fn", fn, low=0.0, high=MAX_VERTICES, strict=False)
    if n != int(n):
        raise InvalidGeometryError(f"circle.fn must be an integer, got {fn!r}")
    if n == 0:
        return Circle((0.0, 0.0), radius)
    return regular_polygon(radius, max(int(n), 3))
