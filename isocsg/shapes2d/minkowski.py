"""Exact 2D Minkowski sums ``{a + b}`` of shapes: polygons (non-convex, with holes) and circles.

A sum distributes over unions, ``(A1 u A2) + B = (A1 + B) u (A2 + B)``, and the sum of two
convex polygons is the convex hull of their pairwise vertex sums. So two polygonal regions
(any tree of polygons only: holes, differences, intersections) are cut into convex pieces
(:func:`~isocsg.shapes2d.region.convex_pieces`: shapely's constrained triangulation, merged)
and their sum is the union of the hulls of each pair of pieces' vertex sums, exact up to the
rounding of the points where those hulls cross. A circle ``c + rD`` added to anything is the
rounded offset by ``r`` moved by ``c`` (:func:`~isocsg.shapes2d.offset.offset`, exact for
polygons and circles); a union of polygons and circles sums leaf by leaf, the same way.

What has no exact form here is refused with :class:`~isocsg.errors.NotExactError` naming it:
an ellipse (outside a circle's offset), or a difference or an intersection with curved parts
added to anything but a circle (its convex pieces are not polygons nor circles).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidGeometryError, NotExactError, ResourceLimitError
from .leaves import Circle, ConvexPolygon, Ellipse
from .measure import to_shapely
from .offset import offset
from .region import convex_pieces, shape_from_region
from .shape import EMPTY, Shape2D, _Node, iter_leaves, union2d

__all__ = ["minkowski2d", "MAX_MINKOWSKI2D_TERMS"]

#: The most pairs of convex pieces (or leaves) one 2D sum may expand into.
MAX_MINKOWSKI2D_TERMS = 20_000

# A convex atom of an operand: a convex polygon's counter-clockwise vertices, or a circle.
_Atom = NDArray[np.float64] | Circle


def _polygonal(shape: Shape2D) -> bool:
    """Whether every leaf of ``shape`` is a polygon (its region is then exact in shapely)."""
    return all(isinstance(leaf, ConvexPolygon) for leaf in iter_leaves(shape))


def _atoms(shape: Shape2D) -> list[_Atom] | None:
    """Convex polygons and circles whose union is ``shape``; None when it has none here (an
    ellipse, a difference or an intersection with curved parts)."""
    out: list[_Atom] = []
    todo = [shape]
    while todo:
        s = todo.pop()
        if _polygonal(s):
            out.extend(convex_pieces(to_shapely(s)))
        elif isinstance(s, Circle):
            out.append(s)
        elif isinstance(s, _Node) and s.op == "union":
            todo.extend(s.children)
        else:
            return None
    return out


def _what(shape: Shape2D) -> str:
    if any(isinstance(leaf, Ellipse) for leaf in iter_leaves(shape)):
        return "an ellipse"
    return f"a curved {shape.op}" if isinstance(shape, _Node) else f"a {type(shape).__name__}"


def _grown(shape: Shape2D, disc: Circle) -> Shape2D:
    """``shape + disc``: the rounded offset by the disc's radius, moved by its centre."""
    try:
        grown = offset(shape, disc.radius)
    except InvalidGeometryError:
        raise NotExactError(
            f"minkowski2d: a sum of {_what(shape)} and a circle has no exact form here "
            "(only polygons and circles offset exactly)"
        ) from None
    return grown.translate(disc.center)


def _hulls(a: list[NDArray[np.float64]], b: list[NDArray[np.float64]]) -> Any:
    """The union of the convex hulls of every pair's vertex sums, as one shapely region."""
    import shapely

    polys = []
    for p in a:
        sums = [(p[:, None, :] + q[None]).reshape(-1, 2) for q in b]
        counts = [len(s) for s in sums]
        points = shapely.multipoints(np.vstack(sums), indices=np.repeat(np.arange(len(sums)), counts))
        polys.append(shapely.convex_hull(points))
    return shapely.union_all(np.concatenate(polys))


def _pair(a: Shape2D, b: Shape2D) -> Shape2D:
    """``a + b`` for two shapes, neither empty."""
    if isinstance(b, Circle):
        return _grown(a, b)
    if isinstance(a, Circle):
        return _grown(b, a)
    atoms_a, atoms_b = _atoms(a), _atoms(b)
    for shape, atoms in ((a, atoms_a), (b, atoms_b)):
        if atoms is None:
            raise NotExactError(
                f"minkowski2d: a sum of {_what(shape)} and a shape other than a circle has no exact form here "
                "(only polygons with holes, unions of polygons and circles, and anything plus a circle)"
            )
    assert atoms_a is not None and atoms_b is not None
    count = len(atoms_a) * len(atoms_b)
    if count > MAX_MINKOWSKI2D_TERMS:
        raise ResourceLimitError(
            f"minkowski2d: the operands' convex pieces make {count} sums, over MAX_MINKOWSKI2D_TERMS = "
            f"{MAX_MINKOWSKI2D_TERMS}"
        )
    polys_a = [p for p in atoms_a if not isinstance(p, Circle)]
    polys_b = [q for q in atoms_b if not isinstance(q, Circle)]
    parts: list[Shape2D] = []
    if polys_a and polys_b:
        parts.append(shape_from_region(_hulls(polys_a, polys_b)))
    for atom in atoms_a:
        for other in atoms_b:
            if isinstance(atom, Circle) and isinstance(other, Circle):
                parts.append(Circle(tuple(np.add(atom.center, other.center)), atom.radius + other.radius))
            elif isinstance(atom, Circle) or isinstance(other, Circle):
                disc, poly = (atom, other) if isinstance(atom, Circle) else (other, atom)
                parts.append(_grown(ConvexPolygon(tuple(map(tuple, poly))), disc))  # type: ignore[arg-type]
    parts = [p for p in parts if p is not EMPTY]
    return parts[0] if len(parts) == 1 else union2d(*parts) if parts else EMPTY


def minkowski2d(a: Shape2D, b: Shape2D, *more: Shape2D) -> Shape2D:
    """The Minkowski sum ``{x + y + ...}`` of 2D shapes, exactly.

    Parameters
    ----------
    a, b, *more : Shape2D
        Polygonal shapes (non-convex, with holes: any tree of polygons), circles, and unions
        of polygons and circles; anything plus a circle of polygons and circles.

    Returns
    -------
    Shape2D
        Convex polygons (the merged region of the pairs' hulls) and, where a circle takes
        part, the exact rounded offsets; :data:`~isocsg.shapes2d.EMPTY` when an operand is.

    Raises
    ------
    NotExactError
        When the sum has no exact form here (an ellipse; a difference or an intersection with
        curved parts plus anything but a circle); the message names the operand.
    ResourceLimitError
        When the convex pieces make more than :data:`MAX_MINKOWSKI2D_TERMS` pairs.
    InvalidGeometryError
        When an operand is not a 2D shape.

    Examples
    --------
    >>> import math
    >>> from isocsg.shapes2d import area, circle, polygon, square
    >>> ell = polygon([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)])
    >>> area(minkowski2d(ell, square(1)))
    8.0
    >>> abs(area(minkowski2d(square(2), circle(1))) - (4 + 8 + math.pi)) < 1e-12
    True
    """
    shapes = (a, b, *more)
    for k, s in enumerate(shapes):
        if not isinstance(s, Shape2D):
            raise InvalidGeometryError(f"minkowski2d: operand {k} must be a 2D shape, got {type(s).__name__}")
    total = shapes[0]
    for s in shapes[1:]:
        if total is EMPTY or s is EMPTY:
            return EMPTY
        total = _pair(total, s)
    return total

