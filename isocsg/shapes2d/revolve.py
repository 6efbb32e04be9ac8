"""``rotate_extrude`` of 2D shapes: the same CSG tree over exactly revolved leaves.

OpenSCAD's semantics: the profile lies in the (x, y) plane, ``x`` the distance from the z
axis and ``y`` the height, and turns about the z axis from the angle ``start`` by ``angle``
degrees (counter-clockwise seen from +z when positive). A profile on the side ``x <= 0``
is the mirror image turned by 180 degrees (OpenSCAD maps a vertex ``(x, y)`` to
``(x cos a, x sin a, y)`` whatever the sign of ``x``); a profile with area on both sides of
the axis is an error, as in OpenSCAD.

Revolving distributes over the 2D Booleans (see :mod:`isocsg.csg.revolve`), and every leaf
is first cut to the side ``x >= 0``: the profile lies there, so its tree over the cut leaves
is the same set. The leaves revolve into frusta and cones (convex polygons), tori and
spheres (circles), spheroids (ellipses centred on the axis). With ``segments``, OpenSCAD's
faceted solid: convex hulls for polygons, elliptic cylinders cut by wedges for circles and
ellipses (any of them, also across the axis: the section keeps ``x >= 0`` by itself).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..errors import InvalidGeometryError
from ._checks import MAX_ABS_COORD, number
from .extrude import combine_solids
from .leaves import Circle, ConvexPolygon, Ellipse
from .measure import area
from .shape import EMPTY, Shape2D, fold

__all__ = ["rotate_extrude", "profile_side"]

#: Most flat sections of a faceted revolution (OpenSCAD's ``$fn`` times the turned fraction).
MAX_SEGMENTS = 4096


def _half_box(shape: Shape2D, side: float) -> ConvexPolygon:
    x0, y0, x1, y1 = shape.bounds
    reach = 2.0 * max(abs(x0), abs(x1), abs(y0), abs(y1), 1.0)
    return ConvexPolygon(((0.0, -reach), (side * reach, -reach), (side * reach, reach), (0.0, reach))[:: int(side)])


def profile_side(shape: Shape2D) -> float:
    """``+1`` when the profile lies in ``x >= 0``, ``-1`` when in ``x <= 0``.

    Raises
    ------
    InvalidGeometryError
        When it has area on both sides of the axis (OpenSCAD refuses it too), or none.
    """
    x0, y0, x1, y1 = shape.bounds
    if not all(math.isfinite(v) for v in (x0, y0, x1, y1)):  # NaN: an intersection of disjoint parts
        raise InvalidGeometryError("rotate_extrude.shape must not be empty")
    if x0 >= 0.0 and x1 > 0.0:
        return 1.0
    if x1 <= 0.0 and x0 < 0.0:
        return -1.0
    scale = max(x1 - x0, y1 - y0) ** 2
    left = area(shape & _half_box(shape, -1.0))
    right = area(shape & _half_box(shape, 1.0))
    tiny = 1e-12 * scale
    if left > tiny and right > tiny:
        raise InvalidGeometryError(
            "rotate_extrude.shape must lie on one side of the axis x = 0, got area "
            f"{left:g} at x < 0 and {right:g} at x > 0 (OpenSCAD refuses this too)"
        )
    if left <= tiny and right <= tiny:
        raise InvalidGeometryError("rotate_extrude.shape must not be empty")
    return 1.0 if right > tiny else -1.0


def _angle(angle: Any) -> float:
    a = number("rotate_extrude.angle", angle, low=-360.0, high=360.0, strict=False)
    if a == 0.0:
        raise InvalidGeometryError("rotate_extrude.angle must be non-zero, got 0")
    return a


def _segments(value: Any) -> int | None:
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not 1 <= value <= MAX_SEGMENTS:
        raise InvalidGeometryError(f"rotate_extrude.segments must be an integer in [1, {MAX_SEGMENTS}], got {value!r}")
    return int(value)


def rotate_extrude(shape: Shape2D, angle: Any = 360.0, *, start: Any = None, segments: Any = None) -> Any:
    """OpenSCAD's ``rotate_extrude``: the exact solid swept by a 2D profile turning about the z axis.

    Parameters
    ----------
    shape : Shape2D
        The profile: ``x`` is the distance from the axis, ``y`` the height. Any tree of
        polygons (non-convex, with holes) and circles clear of the axis (``x > r``) or
        centred on it; ellipses only centred on the axis with axes along x and y.
        It must lie on one side of the axis.
    angle : float, default 360
        The turned angle in degrees, in ``[-360, 360]``, non-zero; negative turns clockwise.
    start : float, optional
        The angle (degrees, from +x towards +y) where the turn starts. Default as in
        OpenSCAD 2021.01: 180 for a full turn, else 0 (it only matters with ``segments``
        or a partial angle).
    segments : int, optional
        OpenSCAD's faceted solid with this many flat sections over ``angle`` (each section of
        a convex piece is a convex polyhedron, of a circle or ellipse an elliptic cylinder cut
        by a wedge, exactly). Default: the exact round solid.

    Returns
    -------
    isocsg.Solid
        A primitive for a single leaf, else the 3D CSG tree of the profile's Booleans over
        the revolved leaves. Its volume is Pappus's ``angle / 360 * 2 pi x_c A`` (``x_c``
        the distance of the profile's centroid from the axis, ``A`` its area).

    Raises
    ------
    InvalidGeometryError
        On an empty profile, one with area on both sides of the axis, a zero or out-of-range
        angle, a circle that meets the axis off its centre (a spindle or horn torus), an
        ellipse off the axis (both only without ``segments``), or ``segments`` that is not an
        integer in ``[1, 4096]`` (naming the field).

    Examples
    --------
    >>> from isocsg import volume
    >>> from isocsg.shapes2d import square
    >>> tube = rotate_extrude(square([1, 2]).translate([2, 0]))   # r in [2, 3], z in [0, 2]
    >>> abs(volume(tube) - 3.141592653589793 * (9 - 4) * 2) < 1e-9
    True
    """
    from ..csg.revolve import (
        clip_to_right_half,
        cut_to_angle,
        faceted_polygon,
        faceted_round,
        revolved_disc,
        revolved_ellipse,
        revolved_polygon,
        sector_angles,
    )

    if not isinstance(shape, Shape2D):
        raise InvalidGeometryError(f"rotate_extrude.shape must be a 2D shape, got {type(shape).__name__}")
    if shape is EMPTY:
        raise InvalidGeometryError("rotate_extrude.shape must not be empty")
    a = _angle(angle)
    full = abs(a) == 360.0
    s0 = number("rotate_extrude.start", 180.0 if start is None and full else start or 0.0, high=MAX_ABS_COORD)
    n = _segments(segments)
    if profile_side(shape) < 0:
        shape = shape.mirror([1.0, 0.0])  # (x, y) -> (-x, y): the same points turned by 180 degrees
        s0 += 180.0
    angles = None if n is None else sector_angles(s0, a, n)

    def leaf(l: Shape2D) -> Any:
        if isinstance(l, ConvexPolygon):
            p = clip_to_right_half(l.array)
            if p is None:
                return None
            return revolved_polygon(p) if angles is None else faceted_polygon(p, angles)
        if angles is not None and isinstance(l, (Circle, Ellipse)):
            return faceted_round(l.center, l.matrix, angles)
        if isinstance(l, Circle):
            return revolved_disc(l.center, l.radius)
        if isinstance(l, Ellipse):
            return revolved_ellipse(l.center, l.matrix)
        raise InvalidGeometryError(f"rotate_extrude.shape holds an unknown leaf {type(l).__name__}")

    solid = fold(shape, leaf, combine_solids)
    if solid is None:
        raise InvalidGeometryError("rotate_extrude.shape must not be empty")
    if full or angles is not None:
        return solid
    _, y0, x1, y1 = shape.bounds
    return cut_to_angle(solid, s0, a, max(x1, 0.0), y0, y1)
