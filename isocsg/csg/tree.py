"""Immutable CSG trees: n-ary union, intersection and difference of solids.

Trees are regularised set operations over convex primitives. Each node is a
frozen dataclass holding a tuple of children; the operators ``|``, ``&`` and
``-`` build them in constant time, so a modelling loop
(``for h in holes: part = part - h``) nests one level per operation.

Nothing here recurses over the tree: construction, ``hash``, ``==``, pickling,
``repr`` and ``to_dict`` walk it with explicit stacks, and everything that
evaluates it (``contains``, ``bounds``, sections, volumes, meshes, rendering)
goes through its flat :class:`~isocsg.csg.program.Program`, compiled once
per node and kept. Trees of any depth and width work, short of memory.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import InvalidGeometryError
from ..kinds import Primitive, Solid
from .program import OP_DIFFERENCE, OP_INTERSECTION, OP_LEAF, OP_NAMES, OP_UNION, Program, compile_program

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
    "distinct_postorder",
    "OP_UNION",
    "OP_INTERSECTION",
    "OP_DIFFERENCE",
    "NODE_TYPES",
]

#: Trees with more leaves than this print as a summary (their full repr would be huge).
REPR_LEAVES = 16


def _check_children(name: str, children: Iterable[Any]) -> tuple[Solid, ...]:
    kids = tuple(children)
    if len(kids) == 0:
        raise InvalidGeometryError(f"{name} needs at least one operand, got none")
    for i, k in enumerate(kids):
        if not isinstance(k, Solid):
            raise InvalidGeometryError(
                f"{name} operand {i} must be a solid (primitive "
                f"or CSG node), got {type(k).__name__}"
            )
    return kids


def _postorder(root: Solid) -> Iterator[Solid]:
    """Every node and leaf of the tree, children before their parent, without recursion."""
    todo: list[tuple[Solid, bool]] = [(root, False)]
    while todo:
        s, expanded = todo.pop()
        if expanded or not isinstance(s, CSGNode):
            yield s
            continue
        todo.append((s, True))
        todo.extend((c, False) for c in reversed(s.children))


@dataclass(frozen=True, slots=True, eq=False, repr=False, init=False)
class CSGNode(Solid):
    """Base of the Boolean nodes; ``children`` is a non-empty tuple of solids."""

    children: tuple[Solid, ...]
    # Computed once, on first use: the structural hash and the flat program.
    _hash: int | None = field(default=None, compare=False, repr=False)
    _program: Program | None = field(default=None, compare=False, repr=False)
    kind = "csg"
    opcode = 0

    def __init__(self, *children: Solid | Iterable[Solid]) -> None:
        # Accept Union(a, b, c) as well as Union([a, b, c]).
        if len(children) == 1 and not isinstance(children[0], Solid):
            if not isinstance(children[0], Iterable) or isinstance(children[0], (str, bytes)):
                raise InvalidGeometryError(
                    f"{type(self).__name__} operand 0 must be a solid (primitive or CSG node), "
                    f"got {type(children[0]).__name__}"
                )
            children = tuple(children[0])  # type: ignore[arg-type]
        object.__setattr__(self, "children", _check_children(type(self).__name__, children))
        object.__setattr__(self, "_hash", None)
        object.__setattr__(self, "_program", None)

    # ------------------------------------------------------------ identity
    def __hash__(self) -> int:
        if self._hash is None:
            for s in _postorder_unhashed(self):
                object.__setattr__(s, "_hash", hash((s.kind, tuple(map(hash, s.children)))))  # type: ignore[attr-defined]
        return self._hash  # type: ignore[return-value]

    def __eq__(self, other: object) -> bool:
        if self is other:
            return True
        if not isinstance(other, CSGNode):
            return NotImplemented
        if hash(self) != hash(other):
            return False
        pairs: list[tuple[Solid, Solid]] = [(self, other)]
        while pairs:
            a, b = pairs.pop()
            if a is b:
                continue
            if isinstance(a, CSGNode) or isinstance(b, CSGNode):
                if type(a) is not type(b) or len(a.children) != len(b.children) or hash(a) != hash(b):  # type: ignore[attr-defined]
                    return False
                pairs.extend(zip(a.children, b.children))  # type: ignore[attr-defined]
            elif a != b:
                return False
        return True

    def __reduce__(self) -> tuple[Any, ...]:
        # The structure as flat lists (pickle's own recursion would follow the nesting).
        kinds: list[str] = []
        arity: list[int] = []
        prims: list[Primitive] = []
        for s in _postorder(self):
            if isinstance(s, CSGNode):
                kinds.append(s.kind)
                arity.append(len(s.children))
            else:
                kinds.append("")
                arity.append(0)
                prims.append(s)  # type: ignore[arg-type]
        return (_rebuild, (kinds, arity, prims))

    def __repr__(self) -> str:
        n = self.program().n_leaves
        if n > REPR_LEAVES:
            return f"<{type(self).__name__} of {len(self.children)} operands, {n} leaves>"
        # Tokens in preorder, joined once (no nested string building).
        out: list[str] = []
        todo: list[Any] = [self]
        while todo:
            s = todo.pop()
            if isinstance(s, str):
                out.append(s)
            elif isinstance(s, CSGNode):
                out.append(f"{type(s).__name__}(")
                todo.append(")")
                for i, c in enumerate(reversed(s.children)):
                    todo.append(c)
                    if i < len(s.children) - 1:
                        todo.append(", ")
            else:
                out.append(repr(s))
        return "".join(out)

    # ------------------------------------------------------------ evaluation
    def program(self) -> Program:
        """The tree's flat program (:func:`isocsg.csg.program.compile_program`), made once."""
        if self._program is None:
            object.__setattr__(self, "_program", compile_program(self))
        return self._program  # type: ignore[return-value]

    def contains(self, points: ArrayLike, *, tol: float | None = None) -> NDArray[np.bool_]:
        """Point membership of the closed, regularised result within ``tol`` (metres, >= 0).

        See :meth:`isocsg.csg.program.Program.contains` for the boundary semantics and the default tolerance.
        """
        return self.program().contains(points, tol=tol)

    @property
    def bounds(self) -> NDArray[np.float64]:
        """A conservative axis-aligned bounding box, shape (2, 3).

        Empty results (e.g. disjoint intersections) may still report a box.
        """
        return self.program().bounds()

    def leaves(self) -> list[Primitive]:
        """The primitives of the tree, depth first, left to right (repeats kept)."""
        return leaves(self)

    def to_manifold(self, resolution: int = 64) -> manifold3d.Manifold:  # type: ignore[name-defined]  # noqa: F821
        """The solid as a manifold3d ``Manifold`` (leaves tessellated with ``resolution`` segments).

        See :func:`isocsg.csg.mesh.to_manifold`.
        """
        from .mesh import to_manifold

        return to_manifold(self, resolution)

    def to_trimesh(self, resolution: int = 64) -> trimesh.Trimesh:  # type: ignore[name-defined]  # noqa: F821
        """The solid as a watertight ``trimesh.Trimesh`` through manifold3d's Booleans.

        See :func:`isocsg.csg.mesh.to_trimesh`.
        """
        from .mesh import to_trimesh

        return to_trimesh(self, resolution)

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> Solid:
        """The image under ``x -> A x + t``: the tree mapped leaf by leaf into a tree of the same
        shape, without recursion (see :meth:`~isocsg.kinds.base.Solid.transform`)."""
        done: dict[int, Any] = {}
        for s in _postorder(self):
            key = id(s)
            if key in done:
                continue  # a leaf or subtree shared in several places is mapped once
            if isinstance(s, CSGNode):
                done[key] = NODE_TYPES[s.kind](*[done[id(c)] for c in s.children])
            else:
                done[key] = s._affine(A, t)
        return done[id(self)]

    def to_dict(self) -> dict[str, Any]:
        """``{"union": [child, ...]}`` etc. for scene files (built without recursion)."""
        done: dict[int, dict[str, Any]] = {}
        for s in _postorder(self):
            if isinstance(s, CSGNode):
                done[id(s)] = {s.kind: [done[id(c)] for c in s.children]}
            else:
                done[id(s)] = s.to_dict()  # type: ignore[attr-defined]
        return done[id(self)]


def _postorder_unhashed(root: CSGNode) -> Iterator[CSGNode]:
    """The nodes of ``root`` whose hash is not known yet, children first."""
    todo: list[tuple[CSGNode, bool]] = [(root, False)]
    while todo:
        s, expanded = todo.pop()
        if expanded:
            yield s
            continue
        todo.append((s, True))
        todo.extend((c, False) for c in reversed(s.children) if isinstance(c, CSGNode) and c._hash is None)


def _rebuild(kinds: list[str], arity: list[int], prims: list[Solid]) -> Solid:
    """Inverse of :meth:`CSGNode.__reduce__`: the postorder read as a program (nested nodes of
    one operation kept apart, not flattened) and evaluated into nodes."""
    code = {name: op for op, name in OP_NAMES.items()}
    leaf = np.cumsum([not k for k in kinds]) - 1
    op = np.array([code[k] if k else OP_LEAF for k in kinds], np.int8)
    arg = np.array([a if k else leaf[j] for j, (k, a) in enumerate(zip(kinds, arity))], np.int64)
    return Program(tuple(prims), op, arg).to_solid()  # type: ignore[arg-type]


@dataclass(frozen=True, slots=True, eq=False, repr=False, init=False)
class Union(CSGNode):
    """All points in any operand.

    Examples
    --------
    >>> from isocsg import Sphere
    >>> u = Union(Sphere((0, 0, 0), 1), Sphere((1.5, 0, 0), 1))
    >>> u.contains([[2.4, 0, 0], [0, 2, 0]]).tolist()
    [True, False]
    """

    kind = OP_NAMES[OP_UNION]
    opcode = OP_UNION


@dataclass(frozen=True, slots=True, eq=False, repr=False, init=False)
class Intersection(CSGNode):
    """The points common to every operand."""

    kind = OP_NAMES[OP_INTERSECTION]
    opcode = OP_INTERSECTION


@dataclass(frozen=True, slots=True, eq=False, repr=False, init=False)
class Difference(CSGNode):
    """The first operand minus all the others."""

    kind = OP_NAMES[OP_DIFFERENCE]
    opcode = OP_DIFFERENCE


#: The node class of each operation, by its name (:data:`~isocsg.csg.program.OP_NAMES`: scene
#: files, ``to_dict``, pickles).
NODE_TYPES: dict[str, type[CSGNode]] = {cls.kind: cls for cls in (Union, Intersection, Difference)}


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


def distinct_postorder(root: Solid) -> list[Solid]:
    """Every distinct node and leaf of the tree (by identity: a shared subtree once), children
    before their parents, without recursion: the order for folding a tree bottom up.

    Examples
    --------
    >>> from isocsg import Sphere
    >>> a = Sphere((0, 0, 0), 1)
    >>> [type(s).__name__ for s in distinct_postorder((a | a) - a)]
    ['Sphere', 'Union', 'Difference']
    """
    order: list[Solid] = []
    seen: set[int] = set()
    todo: list[tuple[Solid, bool]] = [(root, False)]
    while todo:
        s, expanded = todo.pop()
        if id(s) in seen:
            continue
        if expanded or not isinstance(s, CSGNode):
            seen.add(id(s))
            order.append(s)
            continue
        todo.append((s, True))
        todo.extend((c, False) for c in reversed(s.children) if id(c) not in seen)
    return order


def leaves(solid: Solid) -> list[Primitive]:
    """The primitives of a solid, depth first (a primitive is its own single leaf)."""
    if isinstance(solid, Primitive):
        return [solid]
    if isinstance(solid, CSGNode):
        return list(solid.program().leaves)
    raise InvalidGeometryError(f"not a solid: {type(solid).__name__}")
