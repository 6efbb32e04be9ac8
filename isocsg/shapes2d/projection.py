"""Solids projected onto the xy plane as exact 2D shapes: OpenSCAD's ``projection``.

- ``cut=True``: the section of the solid by the plane z = 0, exact leaf by leaf, faces lying in
  the plane included (:mod:`isocsg.shapes2d.sections`);
- ``cut=False``: the outline (shadow): exact for unions, flat-faced trees, trees of vertical
  prisms, and differences and intersections whose other operands are vertical prisms through the
  first one, miss it, or (when it is made of vertical prisms) are convex solids or prisms that
  do not run through it, or (when it is a ball or an upright cone) are vertical prisms apart from
  one another (:mod:`isocsg.shapes2d.outline`); any other tree raises
  :class:`~isocsg.errors.NotExactError` naming what stops it.
"""

from __future__ import annotations

from ..kinds import Solid
from .outline import leaf_outline, outline
from .sections import CURVE_RESOLUTION, leaf_section_at, section_at
from .shape import Shape2D

__all__ = ["projection", "section_at", "leaf_section_at", "outline", "leaf_outline", "CURVE_RESOLUTION"]


def projection(solid: Solid, *, cut: bool = False) -> Shape2D:
    """OpenSCAD's ``projection`` of a solid onto the xy plane, as an exact 2D shape.

    Parameters
    ----------
    solid : Solid
        A primitive or a CSG tree.
    cut : bool, default False
        True: the section by the plane z = 0 (faces lying in the plane included). False: the
        outline, the set of points (x, y) above or below which the solid has a point.

    Returns
    -------
    Shape2D
        :data:`~isocsg.shapes2d.EMPTY` when nothing is left.

    Raises
    ------
    NotExactError
        For an outline of a difference or intersection of curved solids that none of the
        exact rules reaches (the message names the operand).

    Examples
    --------
    >>> import math
    >>> from isocsg import Sphere, Box
    >>> from isocsg.shapes2d import area
    >>> round(area(projection(Sphere((0, 0, 0.5), 1), cut=True)) / math.pi, 12)
    0.75
    >>> area(projection(Box((0, 0, 0), (2, 3, 4)) - Box((0, 0, 0), (1, 1, 9))))
    5.0
    """
    return section_at(solid, 0.0) if cut else outline(solid)

