"""``linear_extrude`` of 2D shapes: the same CSG tree over exact 3D leaves.

A straight extrusion commutes with union, intersection and difference, so the
extrusion of a 2D tree is the 3D tree of the same Booleans over the extruded
leaves, built with an explicit stack (trees of many thousands of nodes):

- a convex polygon becomes a :class:`isocsg.ConvexPolyhedron` prism, or with
  ``scale`` the hull of its base and its scaled top (a frustum-prism);
- a circle becomes a :class:`isocsg.Cylinder`, or with a uniform ``scale`` a
  frustum or cone (:class:`isocsg.Truncus`), sheared when the circle is off
  the origin (the top is scaled about the origin, as in OpenSCAD), which
  isocsg keeps as an exact elliptic truncus;
- an ellipse becomes the affine image of a cylinder (or frustum).

With a uniform scale every side face is planar and the solid is exactly
OpenSCAD's. A ``twist`` or a non-uniform ``scale`` is OpenSCAD's stack of
slices (:mod:`isocsg.shapes2d.twist`): exact for polygons, whose outline is
taken as one region (OpenSCAD extrudes the outline, not the tree); a circle
becomes one sheared frustum per slice, its centre and radius following the
slices' chords (OpenSCAD's polygonal circle joins corresponding corners, which
narrows each slice's waist by ``cos(turn / 2)``); a non-uniform scale of a circle
(not a cone) and a twisted ellipse are refused.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import InvalidGeometryError
from ._checks import MAX_ABS_COORD, flag, number, vector2
from .leaves import Circle, ConvexPolygon, Ellipse
from .shape import Shape2D, fold

__all__ = ["linear_extrude", "MAX_SLICES"]

#: The most slices a twisted or non-uniformly scaled extrusion may have.
MAX_SLICES = 10000


def _scale(value: Any) -> tuple[float, float]:
    if isinstance(value, (list, tuple, np.ndarray)):
        sx, sy = vector2("linear_extrude.scale", value)
    else:
        sx = sy = number("linear_extrude.scale", value)
    if sx < 0 or sy < 0:
        raise InvalidGeometryError(f"linear_extrude.scale must be >= 0, got [{sx:g}, {sy:g}]")
    return sx, sy


def _prism(leaf: ConvexPolygon, z0: float, z1: float, s: tuple[float, float]) -> Any:
    from ..csg.extrude import prism
    from ..kinds.polyhedron import ConvexPolyhedron

    p = leaf.array
    if s == (1.0, 1.0):
        return prism(p, z0, z1)
    k = len(p)
    verts = np.empty((2 * k, 3))
    verts[:k, :2], verts[:k, 2] = p, z0
    verts[k:, :2], verts[k:, 2] = p * np.array(s), z1
    if s == (0.0, 0.0):
        verts = verts[: k + 1]
        verts[k] = (0.0, 0.0, z1)
    return ConvexPolyhedron(verts)  # type: ignore[arg-type]  # any (n, 3) array-like


def _round(leaf: Circle | Ellipse, z0: float, z1: float, s: tuple[float, float]) -> Any:
    from ..kinds.truncus import Cylinder, Truncus

    if s[0] != s[1]:
        raise InvalidGeometryError(
            f"linear_extrude.scale must be uniform for a circle or ellipse (an elliptic cone is not supported yet), "
            f"got [{s[0]:g}, {s[1]:g}]"
        )
    k = s[0]
    h = z1 - z0
    zm = 0.5 * (z0 + z1)
    cx, cy = leaf.center
    if isinstance(leaf, Circle) and (k == 1.0 or (cx == 0.0 and cy == 0.0)):
        if k == 1.0:
            return Cylinder((cx, cy, zm), (0.0, 0.0, h), leaf.radius)
        return Truncus((0.0, 0.0, zm), (0.0, 0.0, h), leaf.radius * k, leaf.radius)
    M = np.array(leaf.matrix)
    origin, axis = (0.0, 0.0, 0.0), (0.0, 0.0, h)
    base = Cylinder(origin, axis, 1.0) if k == 1.0 else Truncus(origin, axis, k, 1.0)
    # Unit solid spans z in [-h/2, h/2]; at height z its section is k(z) u with k linear in z.
    # Map: (x, y) -> M (x, y) + c k(z), z -> z + zm, with k(z) = 1 + (k - 1)(z + h/2)/h.
    g = (k - 1.0) / h
    c = np.array([cx, cy])
    A = np.zeros((3, 4))
    A[:2, :2] = M
    A[:2, 2] = c * g
    A[:2, 3] = c * (1.0 + g * h / 2.0)
    A[2, 2], A[2, 3] = 1.0, zm
    return base.transform(A)


def combine_solids(op: str, n: Shape2D, kids: list[Any]) -> Any:
    """One 2D node's Boolean over its children's solids (None: empty), for :func:`fold` (extrusions and
    revolutions distribute over the 2D Booleans)."""
    from ..csg.tree import Difference, Intersection, Union

    if op == "union":
        real = [k for k in kids if k is not None]
        return None if not real else real[0] if len(real) == 1 else Union(tuple(real))
    if op == "intersection":
        if any(k is None for k in kids):
            return None
        return kids[0] if len(kids) == 1 else Intersection(tuple(kids))
    if kids[0] is None:
        return None
    rest = [k for k in kids[1:] if k is not None]
    return kids[0] if not rest else Difference((kids[0], *rest))


def _slices(value: Any) -> int | None:
    if value is None:
        return None
    n = number("linear_extrude.slices", value, low=1.0, high=MAX_SLICES, strict=False)
    if n != int(n):
        raise InvalidGeometryError(f"linear_extrude.slices must be a whole number, got {n:g}")
    return int(n)


def linear_extrude(
    shape: Shape2D, height: Any, *, center: bool = False, scale: Any = 1.0, twist: Any = 0.0,
    slices: Any = None, fn: Any = 0.0, fs: Any = 2.0, fa: Any = 12.0,
) -> Any:
    """OpenSCAD's ``linear_extrude``: the exact solid swept by a 2D shape along +z.

    Parameters
    ----------
    shape : Shape2D
        Any 2D shape (non-convex, with holes, circles).
    height : float
        > 0.
    center : bool, default False
        Span ``z`` in ``[-height/2, height/2]`` instead of ``[0, height]``.
    scale : float or [sx, sy], default 1
        Scale of the top about the z axis (>= 0). Uniform scales are exact for
        every leaf; a non-uniform scale is accepted for polygons only (see the
        module notes).
    twist : float, default 0
        Degrees the top turns, clockwise seen from above for a positive twist
        (as in OpenSCAD), in ``slices`` steps.
    slices : int, optional
        1 to :data:`MAX_SLICES`; by default OpenSCAD 2021.01's count from
        ``fn``, ``fs``, ``fa`` (its ``$fn``, ``$fs``, ``$fa``), see
        :func:`isocsg.shapes2d.twist.slice_count`.

    Returns
    -------
    isocsg.Solid
        A primitive for a single leaf, else the 3D CSG tree of the shape's
        Booleans over the extruded leaves; its volume is ``area * height``
        (``area * height * (1 + s + s^2) / 3`` with a uniform scale ``s``).
        With a twist or a non-uniform scale: OpenSCAD's stack of slices
        (see :mod:`isocsg.shapes2d.twist`).

    Raises
    ------
    InvalidGeometryError
        On an empty shape, a height that is not > 0, a negative scale, a
        non-uniform scale of a circle or ellipse, a twisted ellipse, bad
        ``slices``, ``fn``, ``fs`` or ``fa`` (naming the field).

    Examples
    --------
    >>> from isocsg import volume
    >>> from isocsg.shapes2d import square, circle
    >>> solid = linear_extrude(square(4, center=True) - circle(1), 2)
    >>> abs(volume(solid) - (16 - 3.141592653589793) * 2) < 1e-6
    True
    >>> twisted = linear_extrude(square(2, center=True), 1, twist=90, slices=6)
    >>> type(twisted).__name__, len(twisted.children)  # one convex slice per step
    ('Union', 6)
    """
    h = number("linear_extrude.height", height, low=0.0, high=MAX_ABS_COORD)
    z0, z1 = (-h / 2, h / 2) if flag("linear_extrude.center", center) else (0.0, h)
    s = _scale(scale)
    tw = number("linear_extrude.twist", twist, low=-1e6, high=1e6)
    n = _slices(slices)
    if not isinstance(shape, Shape2D):
        raise InvalidGeometryError(f"linear_extrude.shape must be a 2D shape, got {type(shape).__name__}")
    if tw != 0.0 or s[0] != s[1]:
        from .twist import sliced_extrude

        details = (number("linear_extrude.fn", fn, low=0.0, strict=False), number("linear_extrude.fs", fs, low=0.0),
                   number("linear_extrude.fa", fa, low=0.0))
        solid = sliced_extrude(shape, z0, z1, tw, s, n, details, combine_solids)
    else:
        def leaf(l: Shape2D) -> Any:
            if isinstance(l, ConvexPolygon):
                return _prism(l, z0, z1, s)
            if isinstance(l, (Circle, Ellipse)):
                return _round(l, z0, z1, s)
            raise InvalidGeometryError(f"linear_extrude.shape holds an unknown leaf {type(l).__name__}")

        solid = fold(shape, leaf, combine_solids)
    if solid is None:
        raise InvalidGeometryError("linear_extrude.shape must not be empty")
    return solid
