"""2D shapes as values: the base class and the Boolean nodes of a 2D CSG tree.

A 2D shape is a tree of regularised Booleans over exact convex leaves (convex
polygons, circles and ellipses, :mod:`isocsg.shapes2d.leaves`). Transforms are
applied to the leaves at once (a transformed tree is the same tree over
transformed leaves), so a tree holds no transform nodes.

Nodes are n-ary and flattened on construction: ``a | b | c`` is one union of
three children, ``(a - b) - c`` one difference ``a - b - c``. Equality is exact
and structural, hashing is computed once per node from its children's hashes,
and every walk over a tree uses an explicit stack: trees of many thousands of
nodes never reach Python's recursion limit.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from typing import Any, TypeVar

from ..errors import InvalidGeometryError

__all__ = [
    "Shape2D",
    "Union2D",
    "Intersection2D",
    "Difference2D",
    "EMPTY",
    "union2d",
    "intersection2d",
    "difference2d",
    "union_all2d",
    "fold",
    "iter_leaves",
]

T = TypeVar("T")


class Shape2D:
    """Base class of 2D shapes: leaves (:class:`~isocsg.shapes2d.ConvexPolygon`, ...) and Boolean nodes.

    Operators: ``a | b`` union, ``a & b`` intersection, ``a - b`` difference.
    Methods are facades over the functions of :mod:`isocsg.shapes2d`.
    """

    __slots__ = ()

    # ----------------------------------------------------------- Booleans
    def __or__(self, other: Shape2D) -> Shape2D:
        return union2d(self, other)

    def __and__(self, other: Shape2D) -> Shape2D:
        return intersection2d(self, other)

    def __sub__(self, other: Shape2D) -> Shape2D:
        return difference2d(self, other)

    # --------------------------------------------------------- transforms
    def transform(self, matrix: Any) -> Shape2D:
        """The image under ``x -> A x + t``, ``matrix`` a 2x3 ``[A | t]`` or 3x3 affine matrix."""
        return OPERATIONS["transform2d"](self, matrix)

    def translate(self, v: Any) -> Shape2D:
        """The shape moved by ``v = [x, y]``."""
        return OPERATIONS["translate2d"](self, v)

    def rotate(self, angle: Any) -> Shape2D:
        """The shape rotated counter-clockwise by ``angle`` degrees about the origin."""
        return OPERATIONS["rotate2d"](self, angle)

    def scale(self, s: Any) -> Shape2D:
        """The shape scaled about the origin by ``s`` (a number or ``[sx, sy]``)."""
        return OPERATIONS["scale2d"](self, s)

    def mirror(self, v: Any) -> Shape2D:
        """The mirror image across the line through the origin with normal ``v`` (OpenSCAD's ``mirror``)."""
        return OPERATIONS["mirror2d"](self, v)

    def offset(self, r: Any = None, *, delta: Any = None, chamfer: bool = False, tolerance: Any = None) -> Shape2D:
        """OpenSCAD's ``offset`` (see :func:`~isocsg.shapes2d.offset`)."""
        return OPERATIONS["offset"](self, r, delta=delta, chamfer=chamfer, tolerance=tolerance)

    def linear_extrude(self, height: Any, *, center: bool = False, scale: Any = 1.0) -> Any:
        """The exact 3D solid swept along +z (see :func:`~isocsg.shapes2d.linear_extrude`)."""
        return OPERATIONS["linear_extrude"](self, height, center=center, scale=scale)

    # -------------------------------------------------------- conversions
    @property
    def bounds(self) -> tuple[float, float, float, float]:
        """``(xmin, ymin, xmax, ymax)`` of a box that contains the shape (see :func:`~isocsg.shapes2d.bounds`)."""
        return OPERATIONS["bounds"](self)

    @property
    def area(self) -> float:
        """The area (see :func:`~isocsg.shapes2d.area`)."""
        return OPERATIONS["area"](self)

    def to_shapely(self, resolution: int = 128) -> Any:
        """A shapely polygon of the shape, circles as inscribed polygons (see :func:`~isocsg.shapes2d.to_shapely`)."""
        return OPERATIONS["to_shapely"](self, resolution=resolution)


#: The functions behind the methods, by name. ``isocsg/shapes2d/__init__.py`` fills it in, so that
#: this module, at the bottom of the package, imports none of the modules above it.
OPERATIONS: dict[str, Callable[..., Any]] = {}


def _check_children(name: str, children: Iterable[Any]) -> tuple[Shape2D, ...]:
    out = tuple(children)
    for k, c in enumerate(out):
        if not isinstance(c, Shape2D):
            raise InvalidGeometryError(f"{name}.children[{k}] must be a 2D shape, got {type(c).__name__}")
    return out


@dataclass(frozen=True, slots=True, eq=False, repr=False)
class _Node(Shape2D):
    """An n-ary Boolean node; see the subclasses."""

    children: tuple[Shape2D, ...]
    _hash: int = field(init=False, default=0, compare=False)
    op = "node"

    def __post_init__(self) -> None:
        name = type(self).__name__
        kids = _check_children(name, self.children)
        flat: list[Shape2D] = []
        for k, c in enumerate(kids):
            splice = type(c) is type(self) and (self.op != "difference" or k == 0)
            flat.extend(c.children if splice else (c,))  # type: ignore[attr-defined]
        object.__setattr__(self, "children", tuple(flat))
        object.__setattr__(self, "_hash", hash((self.op, tuple(hash(c) for c in flat))))

    def __hash__(self) -> int:
        return self._hash

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Shape2D):
            return NotImplemented
        stack: list[tuple[Shape2D, Shape2D]] = [(self, other)]
        while stack:
            a, b = stack.pop()
            if a is b:
                continue
            if type(a) is not type(b) or hash(a) != hash(b):
                return False
            if isinstance(a, _Node):
                if len(a.children) != len(b.children):  # type: ignore[attr-defined]
                    return False
                stack.extend(zip(a.children, b.children))  # type: ignore[attr-defined]
            elif a != b:
                return False
        return True

    def __repr__(self) -> str:
        out: list[str] = []
        stack: list[Any] = [self]
        while stack:  # tokens and shapes, written left to right in linear time
            item = stack.pop()
            if isinstance(item, str):
                out.append(item)
            elif isinstance(item, _Node):
                out.append(f"{type(item).__name__}((")
                stack.append(",))" if len(item.children) == 1 else "))")
                for j in range(len(item.children) - 1, -1, -1):
                    stack.append(item.children[j])
                    if j > 0:
                        stack.append(", ")
            else:
                out.append(repr(item))
        return "".join(out)

    def __reduce__(self) -> Any:
        return (type(self), (self.children,))


@dataclass(frozen=True, slots=True, eq=False, repr=False)
class Union2D(_Node):
    """The union of its children; ``Union2D(())`` is the empty shape (:data:`EMPTY`).

    Examples
    --------
    >>> from isocsg.shapes2d import square, circle
    >>> u = square(2) | circle(1)
    >>> type(u).__name__, len(u.children)
    ('Union2D', 2)
    """

    op = "union"


@dataclass(frozen=True, slots=True, eq=False, repr=False)
class Intersection2D(_Node):
    """The intersection of its children (at least one)."""

    op = "intersection"

    def __post_init__(self) -> None:
        _Node.__post_init__(self)
        if not self.children:
            raise InvalidGeometryError("Intersection2D.children must hold at least one shape, got none")


@dataclass(frozen=True, slots=True, eq=False, repr=False)
class Difference2D(_Node):
    """The first child minus all the others (``(a - b) - c`` is flattened to ``a - b - c``)."""

    op = "difference"

    def __post_init__(self) -> None:
        _Node.__post_init__(self)
        if not self.children:
            raise InvalidGeometryError("Difference2D.children must hold at least one shape, got none")


#: The empty 2D shape (a union of nothing).
EMPTY = Union2D(())


def union2d(*shapes: Shape2D) -> Shape2D:
    """The union of shapes (``a | b``); a single shape is returned as is."""
    return shapes[0] if len(shapes) == 1 and isinstance(shapes[0], Shape2D) else Union2D(shapes)


def union_all2d(shapes: Iterable[Shape2D]) -> Shape2D:
    """The union of an iterable of shapes (:data:`EMPTY` when it is empty).

    Examples
    --------
    >>> from isocsg.shapes2d import square
    >>> u = union_all2d(square(1).translate([2 * k, 0]) for k in range(1000))
    >>> len(u.children), round(u.area, 9)
    (1000, 1000.0)
    """
    return union2d(*tuple(shapes)) if not isinstance(shapes, Shape2D) else shapes


def intersection2d(*shapes: Shape2D) -> Shape2D:
    """The intersection of shapes (``a & b``)."""
    return shapes[0] if len(shapes) == 1 and isinstance(shapes[0], Shape2D) else Intersection2D(shapes)


def difference2d(first: Shape2D, *others: Shape2D) -> Shape2D:
    """``first`` minus all ``others`` (``a - b``)."""
    return first if not others and isinstance(first, Shape2D) else Difference2D((first, *others))


def fold(shape: Shape2D, leaf: Callable[[Shape2D], T], node: Callable[[str, Shape2D, list[T]], T]) -> T:
    """Evaluate a tree bottom-up with an explicit stack: ``leaf(l)`` at leaves, ``node(op, n, values)`` at nodes.

    A subtree shared by several parents (the same object) is evaluated once.
    """
    if not isinstance(shape, Shape2D):
        raise InvalidGeometryError(f"shape must be a 2D shape, got {type(shape).__name__}")
    memo: dict[int, T] = {}
    stack: list[tuple[Shape2D, bool]] = [(shape, False)]
    while stack:
        s, expanded = stack.pop()
        key = id(s)
        if key in memo:
            continue
        if not isinstance(s, _Node):
            memo[key] = leaf(s)
        elif expanded:
            memo[key] = node(s.op, s, [memo[id(c)] for c in s.children])
        else:
            stack.append((s, True))
            stack.extend((c, False) for c in reversed(s.children) if id(c) not in memo)
    return memo[id(shape)]


def iter_leaves(shape: Shape2D) -> Iterator[Shape2D]:
    """The leaves of a tree, left to right (shared subtrees once per occurrence)."""
    stack: list[Shape2D] = [shape]
    while stack:
        s = stack.pop()
        if isinstance(s, _Node):
            stack.extend(reversed(s.children))
        else:
            yield s
