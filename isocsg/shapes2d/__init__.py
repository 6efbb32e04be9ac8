"""2D shapes as values, as OpenSCAD has them, designed so that extrusion stays exact.

A 2D shape is a CSG tree (:class:`Union2D`, :class:`Intersection2D`,
:class:`Difference2D`) over exact convex leaves (:class:`ConvexPolygon`,
:class:`Circle`, :class:`Ellipse`). A straight extrusion commutes with the
Booleans, so :func:`linear_extrude` of a tree is the same 3D CSG tree over
exact prisms (:class:`isocsg.ConvexPolyhedron`) and cylinders. See
``docs/shapes2d.md``.
"""

from __future__ import annotations

from . import shape as _shape
from .constructors import circle, polygon, regular_polygon, square
from .extrude import linear_extrude
from .leaves import Circle, ConvexPolygon, Ellipse, convex_polygon
from .measure import area, area_bounds, bounds, to_shapely
from .minkowski import minkowski2d
from .offset import offset
from .openscad import fragments, from_openscad, text_segments
from .region import convex_pieces, fill, shape_from_region
from .revolve import rotate_extrude
from .shape import (
    EMPTY,
    Difference2D,
    Intersection2D,
    Shape2D,
    Union2D,
    difference2d,
    intersection2d,
    union2d,
    union_all2d,
)
from .text import FontFallbackWarning, font_path, text
from .transforms import mirror2d, rotate2d, scale2d, transform2d, translate2d

_shape.OPERATIONS.update(
    transform2d=transform2d, translate2d=translate2d, rotate2d=rotate2d, scale2d=scale2d, mirror2d=mirror2d,
    offset=offset, linear_extrude=linear_extrude, bounds=bounds, area=area, to_shapely=to_shapely,
)

__all__ = [
    "Shape2D", "ConvexPolygon", "Circle", "Ellipse", "Union2D", "Intersection2D", "Difference2D", "EMPTY",
    "convex_polygon", "polygon", "square", "circle", "regular_polygon",
    "union2d", "intersection2d", "difference2d", "union_all2d",
    "transform2d", "translate2d", "rotate2d", "scale2d", "mirror2d",
    "area", "area_bounds", "bounds", "to_shapely", "fill", "convex_pieces", "shape_from_region",
    "offset", "minkowski2d", "linear_extrude", "rotate_extrude", "text", "font_path", "FontFallbackWarning",
    "from_openscad", "fragments", "text_segments",
]
