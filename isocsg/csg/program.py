"""The flat program of a CSG tree: one representation, one evaluator.

Every consumer of a CSG tree (point membership, bounds, sections, volumes,
meshes, the renderer's per-pixel resolution, the clipped band surface, the
half-tone renderer and the shadows' convex pieces) reads the tree through a
:class:`Program`: a postfix list of instructions held in two arrays,

- ``op[k]``: :data:`OP_LEAF` (push leaf ``arg[k]``) or one of
  :data:`OP_UNION`, :data:`OP_INTERSECTION`, :data:`OP_DIFFERENCE`
  (pop ``arg[k]`` operands, push the result; a difference is its first
  operand minus all the others),

and the tuple of leaves (primitives, repeats kept) that ``OP_LEAF`` indexes.

:func:`compile_program` builds it once per tree, iteratively (no Python
recursion, so trees built by a loop of 100 000 operations are fine), and
flattens nested nodes of the same operation on the way:
``(a | b) | c`` is one union of three, ``(a - b) - c`` is ``a - b - c`` and
``a - (b | c)`` is ``a - b - c`` too. :meth:`Program.evaluate` is the one
generic evaluator; :func:`evaluate_mask` is its compiled form for inside
masks (per pixel); :meth:`Program.prune` (compiled: :func:`prune_arrays`)
drops the leaves that are absent from a region (a screen tile, a plane, a group of receivers), simplifying
the program the way bounding-box pruning does in image-space CSG.

There is no limit on depth or width short of memory.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._jit import njit
from .._late import late
from .._validation import points_array
from ..errors import InvalidGeometryError
from ..kinds.base import RELATIVE_TOLERANCE

if TYPE_CHECKING:  # pragma: no cover
    from ..kinds import Primitive, Solid

__all__ = [
    "OP_LEAF",
    "OP_UNION",
    "OP_INTERSECTION",
    "OP_DIFFERENCE",
    "OP_NAMES",
    "Program",
    "compile_program",
    "default_tolerance",
    "combine_masks",
    "combine_rects",
    "evaluate_mask",
    "prune_arrays",
]

OP_LEAF = 0
OP_UNION = 1
OP_INTERSECTION = 2
OP_DIFFERENCE = 3
#: Operation names by opcode (the node kinds of scene files).
OP_NAMES = {OP_UNION: "union", OP_INTERSECTION: "intersection", OP_DIFFERENCE: "difference"}

T = TypeVar("T")


@dataclass(frozen=True, slots=True, eq=False)
class Program:
    """A CSG tree as a flat postfix program (see the module docstring).

    Attributes
    ----------
    leaves : tuple of Primitive
        The primitives, in the order their ``OP_LEAF`` instructions appear.
    op : ndarray of int8, shape (n,)
        Opcode of each instruction (read-only).
    arg : ndarray of int64, shape (n,)
        Leaf index of an ``OP_LEAF``, operand count of an operation (read-only).

    Examples
    --------
    >>> from isocsg import Box, Sphere
    >>> a, b, c = Sphere((0, 0, 0), 1), Box((0, 0, 0), (1, 1, 1)), Sphere((2, 0, 0), 1)
    >>> prog = compile_program((a - b) - c)
    >>> prog.op.tolist(), prog.arg.tolist()
    ([0, 0, 0, 3], [0, 1, 2, 3])
    >>> prog.contains([[0.9, 0, 0], [0, 0, 0]]).tolist()
    [True, False]
    """

    leaves: tuple[Primitive, ...]
    op: NDArray[np.int8]
    arg: NDArray[np.int64]

    def __len__(self) -> int:
        return len(self.op)

    def __repr__(self) -> str:
        return f"Program({len(self.leaves)} leaves, {len(self.op)} instructions)"

    @property
    def n_leaves(self) -> int:
        """Number of leaves (``OP_LEAF`` instructions)."""
        return len(self.leaves)

    @property
    def stack_size(self) -> int:
        """The deepest the evaluation stack gets (what a compiled evaluator must allocate)."""
        if len(self.op) == 0:
            return 0
        delta = np.where(self.op == OP_LEAF, 1, 1 - self.arg)
        return int(np.cumsum(delta).max())

    def evaluate(
        self,
        leaf: Callable[[int, Primitive], T],
        combine: Callable[[int, list[T]], T],
    ) -> T:
        """Evaluate the program bottom up with a stack (the one generic evaluator).

        Parameters
        ----------
        leaf : callable
            ``leaf(index, primitive) -> value`` for each ``OP_LEAF``.
        combine : callable
            ``combine(opcode, operands) -> value`` for each operation; for a
            difference the first operand is the one the others are taken from.

        Returns
        -------
        The value of the whole program.

        Examples
        --------
        >>> from isocsg import Sphere
        >>> prog = compile_program(Sphere((0, 0, 0), 1) | Sphere((3, 0, 0), 1) | Sphere((6, 0, 0), 1))
        >>> prog.evaluate(lambda i, p: [i], lambda op, xs: [OP_NAMES[op]] + [x for v in xs for x in v])
        ['union', 0, 1, 2]
        """
        stack: list[T] = []
        leaves = self.leaves
        for o, a in zip(self.op.tolist(), self.arg.tolist()):
            if o == OP_LEAF:
                stack.append(leaf(a, leaves[a]))
            else:
                args = stack[len(stack) - a :]
                del stack[len(stack) - a :]
                stack.append(combine(o, args))
        return stack[-1]

    def contains(self, points: ArrayLike, *, tol: float | None = None) -> NDArray[np.bool_]:
        """Point membership of the closed, regularised result, within ``tol``.

        The result is ``closure(interior(R))`` of the Boolean ``R`` of the
        closed leaves: a point on the cut face of ``A - B`` is inside (on the
        result's boundary), a point where ``A & B`` only touch is outside, and
        points within ``tol`` of a leaf's boundary count as on it (the leaf is
        replaced by its tangent cone there). See
        :mod:`isocsg.csg.membership` for the full statement.

        Parameters
        ----------
        points : array_like, shape (n, 3) or (3,)
        tol : float, optional
            Absolute tolerance in metres, >= 0. Default
            :meth:`default_tolerance`: 1e-12 of the largest extent or
            coordinate magnitude of the leaves' boxes.

        Returns
        -------
        ndarray of bool, shape (n,)

        Raises
        ------
        InvalidGeometryError
            If ``points`` is not an (n, 3) array of finite numbers.
        InvalidParameterError
            If ``tol`` is negative or not a finite number.

        Examples
        --------
        >>> from isocsg import Box
        >>> prog = compile_program(Box((0, 0, 0), (2, 2, 2)) - Box((1, 0, 0), (2, 2, 2)))
        >>> prog.contains([[0.0, 0, 0], [-1e-13, 0, 0], [1e-13, 0, 0], [1e-9, 0, 0]]).tolist()
        [True, True, True, False]
        >>> prog.contains([[1e-6, 0, 0]], tol=1e-5).tolist()
        [True]
        """
        pts = points_array("contains(points)", points)
        # csg/membership.py (above this module: it reads the leaf tables of csg/section.py)
        inside: NDArray[np.bool_] = late("contains_program")(self, pts, tol)
        return inside

    def default_tolerance(self) -> float:
        """The default ``tol`` of :meth:`contains`: 1e-12 of the largest extent or
        coordinate magnitude of the leaves' boxes (metres)."""
        boxes = np.array([np.asarray(p.bounds, dtype=np.float64) for p in self.leaves]).reshape(-1, 2, 3)
        return default_tolerance(boxes)

    def bounds(self, lo: ArrayLike | None = None, hi: ArrayLike | None = None) -> NDArray[np.float64]:
        """A conservative axis-aligned box ``(2, 3)``: unions take the hull,
        intersections the overlap (collapsed to a point where there is none),
        differences their first operand's.

        Parameters
        ----------
        lo, hi : array_like, shape (n_leaves, 3), optional
            The leaves' boxes (e.g. the renderer's, of the leaves as drawn);
            by default each leaf's own ``bounds``.

        Examples
        --------
        >>> from isocsg import Box, Cylinder
        >>> prog = compile_program(Box((0, 0, 0), (2, 2, 0.4)) - Cylinder((0, 0, 0), (0, 0, 3), 0.2))
        >>> prog.bounds().tolist()
        [[-1.0, -1.0, -0.2], [1.0, 1.0, 0.2]]
        >>> prog.bounds([[0, 0, 0], [-5, -5, -5]], [[1, 1, 1], [5, 5, 5]]).tolist()
        [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]]
        """
        if lo is None or hi is None:
            return self.evaluate(lambda _, p: np.asarray(p.bounds, dtype=np.float64), _combine_boxes)
        lo_ = np.asarray(lo, dtype=np.float64).reshape(-1, 3)
        hi_ = np.asarray(hi, dtype=np.float64).reshape(-1, 3)

        # A leaf stays its index until an operation reads its box: the leaf operands of an
        # operation are read at once, not one row each (trees of 100 000 leaves).
        def box(x: Any) -> Any:
            return (lo_[x], hi_[x]) if isinstance(x, int) else x

        def combine(o: int, xs: list[Any]) -> Any:
            if o == OP_DIFFERENCE:
                return box(xs[0])
            ids = [x for x in xs if isinstance(x, int)]
            nodes = [x for x in xs if not isinstance(x, int)]
            return _combine_boxes(o, [(lo_[ids], hi_[ids])] * bool(ids) + nodes, stacked=True)

        return np.stack(box(self.evaluate(lambda i, _: i, combine)))

    def screen_rect(self, rects: ArrayLike) -> NDArray[np.int64]:
        """The program's screen rectangle ``(c0, r0, c1, r1)`` (pixels, end exclusive) from its
        leaves' rectangles ``(n_leaves, 4)``: a union takes the hull of its non-empty operands, an
        intersection their overlap, a difference its first operand's; an empty one is all zeros.

        Examples
        --------
        >>> from isocsg import Box
        >>> prog = compile_program(Box((0, 0, 0), (1, 1, 1)) & Box((1, 0, 0), (1, 1, 1)))
        >>> prog.screen_rect([[0, 0, 10, 10], [5, 2, 20, 8]]).tolist()
        [5, 2, 10, 8]
        """
        r = np.ascontiguousarray(np.asarray(rects, dtype=np.int64).reshape(-1, 4))
        return combine_rects(self.op, self.arg, r)

    def prune(self, present: ArrayLike) -> tuple[Program, NDArray[np.int64]] | None:
        """The program with the leaves marked absent replaced by the empty set, simplified.

        A region (a screen tile, a plane) where a leaf cannot be present
        evaluates the same program with that leaf empty: an absent operand
        drops out of a union and out of the subtracted operands of a
        difference, and empties an intersection or a difference whose first
        operand it is. Single-operand nodes collapse to their operand.

        Parameters
        ----------
        present : array_like of bool, shape (n_leaves,)

        Returns
        -------
        (Program, ndarray of int64) or None
            The pruned program and, for each of its leaves, the index of that
            leaf in this program; ``None`` when the result is empty.

        Examples
        --------
        >>> from isocsg import Box, Sphere
        >>> plate, hole1, hole2 = Box((0, 0, 0), (4, 1, 1)), Sphere((-1, 0, 0), 0.3), Sphere((1, 0, 0), 0.3)
        >>> prog = compile_program(plate - hole1 - hole2)
        >>> pruned, ids = prog.prune([True, False, True])
        >>> pruned.op.tolist(), ids.tolist()
        ([0, 0, 3], [0, 2])
        >>> prog.prune([False, True, True]) is None
        True
        """
        keep = np.asarray(present, dtype=bool).reshape(-1)
        if keep.shape != (len(self.leaves),):
            raise InvalidGeometryError(f"present must have {len(self.leaves)} entries, got {keep.shape[0]}")
        if keep.all():
            return self, np.arange(len(self.leaves), dtype=np.int64)
        op, arg, ids = prune_arrays(self.op, self.arg, keep)
        if not len(op):
            return None
        return _make(tuple(self.leaves[i] for i in ids.tolist()), op, arg), ids

    def operands(self) -> list[Program]:
        """The programs of the root operation's operands, in order (a leaf program has none).

        Leaves are numbered in the order of their instructions, so each operand's
        instructions and leaves are runs of this program's.

        Examples
        --------
        >>> from isocsg import Box, Sphere
        >>> a, b, c = Sphere((0, 0, 0), 1), Box((0, 0, 0), (1, 1, 1)), Sphere((2, 0, 0), 1)
        >>> [q.op.tolist() for q in compile_program((a & b) | c).operands()]
        [[0, 0, 2], [0]]
        """
        if not len(self.op) or self.op[-1] == OP_LEAF:
            return []
        at = np.flatnonzero(self.op == OP_LEAF)  # each leaf's instruction
        root: list[list[tuple[int, int]]] = []

        def combine(_: int, spans: list[tuple[int, int]]) -> tuple[int, int]:
            root[:] = [spans]  # the last call is the root's
            return spans[0][0], spans[-1][1] + 1

        self.evaluate(lambda i, _: (int(at[i]), int(at[i]) + 1), combine)
        leaf_before = np.concatenate([[0], np.cumsum(self.op == OP_LEAF)])
        out = []
        for s, e in root[0]:
            l0, l1 = int(leaf_before[s]), int(leaf_before[e])
            op = self.op[s:e].copy()
            arg = np.where(op == OP_LEAF, self.arg[s:e] - l0, self.arg[s:e])
            out.append(_make(self.leaves[l0:l1], op, arg.astype(np.int64)))
        return out

    @staticmethod
    def join(op: int, parts: Sequence[Program]) -> Program:
        """One operation ``op`` over programs (one part: that part), their leaves renumbered in order.

        Examples
        --------
        >>> from isocsg import Box, Sphere
        >>> a, b = compile_program(Sphere((0, 0, 0), 1)), compile_program(Box((0, 0, 0), (1, 1, 1)))
        >>> both = Program.join(OP_INTERSECTION, [a, b])
        >>> both.op.tolist(), both.arg.tolist()
        ([0, 0, 2], [0, 1, 2])
        """
        if len(parts) == 1:
            return parts[0]
        offsets = np.cumsum([0] + [p.n_leaves for p in parts[:-1]])
        ops = [p.op for p in parts] + [np.array([op], np.int8)]
        args = [np.where(p.op == OP_LEAF, p.arg + k, p.arg) for p, k in zip(parts, offsets.tolist())]
        args.append(np.array([len(parts)], np.int64))
        leaves = tuple(leaf for p in parts for leaf in p.leaves)
        return _make(leaves, np.concatenate(ops).astype(np.int8), np.concatenate(args).astype(np.int64))

    def to_solid(self) -> Solid:
        """The program as a tree of CSG nodes (flat: one node per operation)."""
        # the node classes of csg/tree.py, which builds on this module
        node = late("csg_node")
        return self.evaluate(lambda _, p: p, lambda o, xs: node(OP_NAMES[o], *xs))


def default_tolerance(boxes: NDArray[np.float64]) -> float:
    """1e-12 of the largest extent or coordinate magnitude of the leaves' boxes ``(n, 2, 3)``."""
    if len(boxes) == 0:
        return 0.0
    lo, hi = boxes[:, 0].min(axis=0), boxes[:, 1].max(axis=0)
    return RELATIVE_TOLERANCE * float(max(np.max(hi - lo), np.max(np.abs(boxes))))


def _make(leaves: tuple[Primitive, ...], op: NDArray[np.int8], arg: NDArray[np.int64]) -> Program:
    op.flags.writeable = False
    arg.flags.writeable = False
    return Program(leaves, op, arg)


def combine_masks(o: int, xs: list[NDArray[np.bool_]]) -> NDArray[np.bool_]:
    """``combine`` for :meth:`Program.evaluate` on boolean arrays (inside masks)."""
    if o == OP_UNION:
        return np.logical_or.reduce(xs)
    if o == OP_INTERSECTION:
        return np.logical_and.reduce(xs)
    out = xs[0].copy()
    for m in xs[1:]:
        out &= ~m
    return out


def _combine_boxes(o: int, xs: list[Any], stacked: bool = False) -> Any:
    """``combine`` for :meth:`Program.evaluate` on boxes ``(lo, hi)``; where ``stacked``, an
    operand may hold several boxes (``lo`` and ``hi`` of shape (k, 3))."""
    if o == OP_DIFFERENCE:
        return xs[0]
    lo = np.vstack([x[0] for x in xs]) if stacked else np.array([x[0] for x in xs])
    hi = np.vstack([x[1] for x in xs]) if stacked else np.array([x[1] for x in xs])
    if o == OP_UNION:
        return np.stack([lo.min(axis=0), hi.max(axis=0)])
    lo, hi = lo.max(axis=0), hi.min(axis=0)
    return np.stack([lo, np.maximum(hi, lo)])


def compile_program(solid: Solid) -> Program:
    """The flat program of a primitive or CSG tree, built without recursion.

    Nested nodes of the same operation become one node: ``(a | b) | c`` and
    ``a | (b | c)`` are one union of three, ``(a & b) & c`` one intersection,
    ``(a - b) - c`` and ``a - (b | c)`` one difference ``a - b - c``.

    Parameters
    ----------
    solid : Solid
        A primitive (the one-instruction program) or a CSG tree.

    Returns
    -------
    Program

    Raises
    ------
    InvalidGeometryError
        If ``solid`` is not a solid.

    Examples
    --------
    >>> from isocsg import Sphere
    >>> parts = Sphere((0, 0, 0), 1)
    >>> for i in range(1, 5):
    ...     parts = parts | Sphere((2 * i, 0, 0), 1)
    >>> prog = compile_program(parts)
    >>> prog.n_leaves, prog.op.tolist()[-1], prog.arg.tolist()[-1]
    (5, 1, 5)
    """
    from ..kinds import Primitive, Solid

    if isinstance(solid, Primitive):
        return _make((solid,), np.zeros(1, np.int8), np.zeros(1, np.int64))
    if not (isinstance(solid, Solid) and _opcode(solid) in OP_NAMES):
        raise InvalidGeometryError(f"solid must be a primitive or CSG node, got {type(solid).__name__}")
    leaves: list[Primitive] = []
    ops: list[int] = []
    args: list[int] = []
    # Explicit stack: a solid to expand, or an operation (opcode, arity) to emit
    # once its operands (pushed above it) have been emitted.
    todo: list[Any] = [solid]
    while todo:
        item = todo.pop()
        if isinstance(item, tuple):
            ops.append(item[0])
            args.append(item[1])
            continue
        if isinstance(item, Primitive):
            ops.append(OP_LEAF)
            args.append(len(leaves))
            leaves.append(item)
            continue
        operands = _operands(item)
        todo.append((item.opcode, len(operands)))
        todo.extend(reversed(operands))
    return _make(tuple(leaves), np.asarray(ops, np.int8), np.asarray(args, np.int64))


def _opcode(solid: object) -> int:
    """The operation of a CSG node (its class's ``opcode``, csg/tree.py); :data:`OP_LEAF` otherwise."""
    return int(getattr(solid, "opcode", OP_LEAF))


def _operands(node: Any) -> list[Solid]:
    """The operands of ``node`` after absorbing nested nodes of the same operation."""
    if node.opcode == OP_DIFFERENCE:
        # (a - b) - c: walk down the chain of first operands.
        subtracted: list[Sequence[Solid]] = []
        first: Solid = node
        while _opcode(first) == OP_DIFFERENCE:
            subtracted.append(first.children[1:])  # type: ignore[attr-defined]
            first = first.children[0]  # type: ignore[attr-defined]
        rest = [c for group in reversed(subtracted) for c in group]
        # a - (b | c): the subtracted unions' operands are subtracted one by one.
        return [first] + _spliced(rest, OP_UNION)
    return _spliced(node.children, node.opcode)


def _spliced(children: Sequence[Solid], op: int) -> list[Solid]:
    """``children`` with every node of operation ``op`` replaced by its operands (at any depth)."""
    out: list[Solid] = []
    todo = list(reversed(children))
    while todo:
        c = todo.pop()
        if _opcode(c) == op:
            todo.extend(reversed(c.children))  # type: ignore[attr-defined]
        else:
            out.append(c)
    return out


# ----------------------------------------------------------------- compiled form
@njit(cache=True, nogil=True, inline="always")
def evaluate_mask(
    op: NDArray[np.int8], arg: NDArray[np.int64], inside: NDArray[np.bool_], stack: NDArray[np.bool_],
) -> bool:
    """The program's value for one inside mask (``inside[i]``: inside leaf i), compiled.

    ``stack`` is scratch of at least :attr:`Program.stack_size` entries.
    """
    sp = 0
    for k in range(len(op)):
        o = op[k]
        if o == 0:
            stack[sp] = inside[arg[k]]
            sp += 1
            continue
        base = sp - arg[k]
        if o == 1:  # union
            r = False
            for s in range(base, sp):
                r = r or stack[s]
        elif o == 2:  # intersection
            r = True
            for s in range(base, sp):
                r = r and stack[s]
        else:  # difference: first minus the others
            r = stack[base]
            for s in range(base + 1, sp):
                r = r and not stack[s]
        stack[base] = r
        sp = base + 1
    return stack[0]


@njit(cache=True)
def combine_rects(op: NDArray[np.int8], arg: NDArray[np.int64], rects: NDArray[np.int64]) -> NDArray[np.int64]:
    """The program's screen rectangle ``(c0, r0, c1, r1)`` from its leaves' (``rects``, (n, 4)),
    compiled: :meth:`Program.screen_rect` over the arrays (the renderer calls it with them).

    A union takes the hull of its operands' rectangles, an intersection their
    overlap, a difference its first operand's. Empty rectangles are empty
    sets (they leave a union's hull alone and empty an intersection).
    """
    stack = np.zeros((max(len(op), 1), 4), np.int64)
    sp = 0
    for k in range(len(op)):
        o = op[k]
        if o == 0:
            # Element by element: a row assignment compiles numba's shape-mismatch message (seconds of compile).
            r = arg[k]
            stack[sp, 0], stack[sp, 1], stack[sp, 2], stack[sp, 3] = rects[r, 0], rects[r, 1], rects[r, 2], rects[r, 3]
            sp += 1
            continue
        base = sp - arg[k]
        c0, r0, c1, r1 = stack[base, 0], stack[base, 1], stack[base, 2], stack[base, 3]
        if o == 1:  # union: hull of the non-empty operands
            empty = not (c0 < c1 and r0 < r1)
            for s in range(base + 1, sp):
                if not (stack[s, 0] < stack[s, 2] and stack[s, 1] < stack[s, 3]):
                    continue
                if empty:
                    c0, r0, c1, r1 = stack[s, 0], stack[s, 1], stack[s, 2], stack[s, 3]
                    empty = False
                else:
                    c0, r0 = min(c0, stack[s, 0]), min(r0, stack[s, 1])
                    c1, r1 = max(c1, stack[s, 2]), max(r1, stack[s, 3])
        elif o == 2:  # intersection
            for s in range(base + 1, sp):
                c0, r0 = max(c0, stack[s, 0]), max(r0, stack[s, 1])
                c1, r1 = min(c1, stack[s, 2]), min(r1, stack[s, 3])
        if not (c0 < c1 and r0 < r1):
            c0, r0, c1, r1 = 0, 0, 0, 0
        stack[base, 0], stack[base, 1], stack[base, 2], stack[base, 3] = c0, r0, c1, r1
        sp = base + 1
    return stack[0].copy()


@njit(cache=True, nogil=True)
def prune_arrays(
    op: NDArray[np.int8], arg: NDArray[np.int64], keep: NDArray[np.bool_],
) -> tuple[NDArray[np.int8], NDArray[np.int64], NDArray[np.int64]]:
    """:meth:`Program.prune` on the program's arrays, compiled (also for compiled callers: a
    screen tile's program).

    Returns the pruned ``op`` and ``arg`` (leaves renumbered in order) and,
    per remaining leaf, its index in the original program; all empty when
    the result is the empty set.
    """
    n = len(op)
    out_op = np.empty(n, np.int8)
    out_arg = np.empty(n, np.int64)
    start = np.empty(n, np.int64)  # per stack entry: where its code begins in the output
    empty = np.empty(n, np.bool_)
    sp = 0
    m = 0  # output length
    for k in range(n):
        o = op[k]
        if o == 0:
            start[sp] = m
            if keep[arg[k]]:
                out_op[m] = 0
                out_arg[m] = arg[k]
                m += 1
                empty[sp] = False
            else:
                empty[sp] = True
            sp += 1
            continue
        base = sp - arg[k]
        kept = 0
        any_empty = False
        for s in range(base, sp):
            if empty[s]:
                any_empty = True
            else:
                kept += 1
        s0 = start[base]
        if kept == 0 or (o == 2 and any_empty) or (o == 3 and empty[base]):
            m = s0  # drop the operands' code: the node is empty
            empty[base] = True
        elif kept > 1:
            out_op[m] = o
            out_arg[m] = kept
            m += 1
            empty[base] = False
        else:
            empty[base] = False  # one operand left: it is the node
        start[base] = s0
        sp = base + 1
    if sp == 0 or empty[0]:
        return np.empty(0, np.int8), np.empty(0, np.int64), np.empty(0, np.int64)
    rop = out_op[:m].copy()
    rarg = out_arg[:m].copy()
    count = 0
    for k in range(m):
        if rop[k] == 0:
            count += 1
    ids = np.empty(count, np.int64)
    j = 0
    for k in range(m):
        if rop[k] == 0:
            ids[j] = rarg[k]
            rarg[k] = j
            j += 1
    return rop, rarg, ids

