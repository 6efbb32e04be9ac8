"""Immutable CSG trees: n-ary union, intersection and difference of solids.

Trees are regularised set operations over convex primitives. Each node is a
frozen dataclass holding a tuple of children. Point membership is evaluated
from the leaves up, and :meth:`CSGNode.program` flattens a tree into a postfix
program that compiled kernels (the renderer) evaluate per pixel.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import InvalidGeometryError
from ..geometry.primitives import Primitive, Solid

__all__ = [
    "CSGNode",
    "Union",
    "Intersection",
    "Difference",
    "union",
    "intersection",
    "difference",
    "union_all",
    "leaves",
    "OP_UNION",
    "OP_INTERSECTION",
    "OP_DIFFERENCE",
]

# Opcodes of the postfix program: a non-negative entry pushes leaf i; a
# negative entry -(op * 1000 + k) pops k operands and pushes the result.
OP_UNION = 1
OP_INTERSECTION = 2
OP_DIFFERENCE = 3


def _check_children(name: str, children: Iterable[Any]) -> tuple[Solid, ...]:
    kids = tuple(children)
    if len(kids) == 0:
        raise InvalidGeometryError(f"{name} needs at least one operand, got none")
    for i, k in enumerate(kids):
        if not isinstance(k, Solid):
            raise InvalidGeometryError(f"{name} operand {i} must be a solid (primitive or CSG node), got {type(k).__name__}")
    return kids


@dataclass(frozen=True, slots=True)
class CSGNode(Solid):
    """Base of the Boolean nodes; ``children`` is a non-empty tuple of solids."""

    children: tuple[Solid, ...]
    kind = "csg"
    opcode = 0

    def __init__(self, *children: Solid | Iterable[Solid]) -> None:
        # Accept Union(a, b, c) as well as Union([a, b, c]).
        if len(children) == 1 and not isinstance(children[0], Solid):
            children = tuple(children[0])  # type: ignore[arg-type]
        object.__setattr__(self, "children", _check_children(type(self).__name__, children))

    def __repr__(self) -> str:
        return f"{type(self).__name__}({', '.join(map(repr, self.children))})"

    def _combine(self, masks: list[NDArray[np.bool_]]) -> NDArray[np.bool_]:  # pragma: no cover
        raise NotImplementedError

    def contains(self, points: ArrayLike) -> NDArray[np.bool_]:
        """Point membership of the (closed) result solid.

        Regularisation only matters on measure-zero sets (shared boundaries);
        points exactly there are classified by the closed operands.
        """
        return self._combine([c.contains(points) for c in self.children])

    @property
    def bounds(self) -> NDArray[np.float64]:
        """A conservative axis-aligned bounding box, shape (2, 3).

        Empty results (e.g. disjoint intersections) may still report a box.
        """
        bs = [c.bounds for c in self.children]
        return self._combine_bounds(bs)

    def _combine_bounds(self, bs: list[NDArray[np.float64]]) -> NDArray[np.float64]:  # pragma: no cover
        raise NotImplementedError

    def leaves(self) -> list[Primitive]:
        """The primitives of the tree, depth first, left to right (repeats kept)."""
        return leaves(self)

    def to_manifold(self, resolution: int = 64) -> "manifold3d.Manifold":  # type: ignore[name-defined]  # noqa: F821
        """The solid as a manifold3d ``Manifold`` (leaves tessellated with ``resolution`` segments).

        See :func:`isocsg.csg.mesh.to_manifold`.
        """
        from .mesh import to_manifold

        return to_manifold(self, resolution)

    def to_trimesh(self, resolution: int = 64) -> "trimesh.Trimesh":  # type: ignore[name-defined]  # noqa: F821
        """The solid as a watertight ``trimesh.Trimesh`` through manifold3d's Booleans.

        See :func:`isocsg.csg.mesh.to_trimesh`.
        """
        from .mesh import to_trimesh

        return to_trimesh(self, resolution)

    def program(self) -> tuple[list[Primitive], NDArray[np.int64]]:
        """Flatten into (leaves, postfix program); see the module docstring."""
        prims: list[Primitive] = []
        prog: list[int] = []

        def walk(s: Solid) -> None:
            if isinstance(s, CSGNode):
                for c in s.children:
                    walk(c)
                prog.append(-(s.opcode * 1000 + len(s.children)))
            elif isinstance(s, Primitive):
                prog.append(len(prims))
                prims.append(s)
            else:  # pragma: no cover - guarded by _check_children
                raise InvalidGeometryError(f"not a solid: {type(s).__name__}")

        walk(self)
        return prims, np.asarray(prog, dtype=np.int64)

    def to_dict(self) -> dict[str, Any]:
        """``{"union": [child, ...]}`` etc. for scene files."""
        return {self.kind: [c.to_dict() for c in self.children]}  # type: ignore[attr-defined]


@dataclass(frozen=True, slots=True, init=False, repr=False)
class Union(CSGNode):
    """All points in any operand.

    Examples
    --------
    >>> from isocsg import Sphere
    >>> u = Union(Sphere((0, 0, 0), 1), Sphere((1.5, 0, 0), 1))
    >>> u.contains([[2.4, 0, 0], [0, 2, 0]]).tolist()
    [True, False]
    """

    kind = "union"
    opcode = OP_UNION

    def _combine(self, masks: list[NDArray[np.bool_]]) -> NDArray[np.bool_]:
        return np.logical_or.reduce(masks)

    def _combine_bounds(self, bs: list[NDArray[np.float64]]) -> NDArray[np.float64]:
        return np.stack([np.min([b[0] for b in bs], axis=0), np.max([b[1] for b in bs], axis=0)])


@dataclass(frozen=True, slots=True, init=False, repr=False)
class Intersection(CSGNode):
    """The points common to every operand."""

    kind = "intersection"
    opcode = OP_INTERSECTION

    def _combine(self, masks: list[NDArray[np.bool_]]) -> NDArray[np.bool_]:
        return np.logical_and.reduce(masks)

    def _combine_bounds(self, bs: list[NDArray[np.float64]]) -> NDArray[np.float64]:
        lo = np.max([b[0] for b in bs], axis=0)
        hi = np.min([b[1] for b in bs], axis=0)
        return np.stack([lo, np.maximum(hi, lo)])


@dataclass(frozen=True, slots=True, init=False, repr=False)
class Difference(CSGNode):
    """The first operand minus all the others."""

    kind = "difference"
    opcode = OP_DIFFERENCE

    def _combine(self, masks: list[NDArray[np.bool_]]) -> NDArray[np.bool_]:
        out = masks[0].copy()
        for m in masks[1:]:
            out &= ~m
        return out

    def _combine_bounds(self, bs: list[NDArray[np.float64]]) -> NDArray[np.float64]:
        return bs[0]


def union(*solids: Solid) -> Union:
    """Union of solids (``a | b``)."""
    return Union(*solids)


def intersection(*solids: Solid) -> Intersection:
    """Intersection of solids (``a & b``)."""
    return Intersection(*solids)


def difference(first: Solid, *others: Solid) -> Difference:
    """``first`` minus all ``others`` (``a - b``)."""
    return Difference(first, *others)


def union_all(solids: Iterable[Solid]) -> Union:
    """Union of an iterable of solids."""
    return Union(tuple(solids))


def leaves(solid: Solid) -> list[Primitive]:
    """The primitives of a solid, depth first (a primitive is its own single leaf)."""
    if isinstance(solid, Primitive):
        return [solid]
    if isinstance(solid, CSGNode):
        out: list[Primitive] = []
        for c in solid.children:
            out.extend(leaves(c))
        return out
    raise InvalidGeometryError(f"not a solid: {type(solid).__name__}")
