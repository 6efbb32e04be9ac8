"""Planning the Booleans: the tree evaluated on boxes, what to cut, slabs and the memory budget.

Operands whose boxes touch nothing they are combined with need no Boolean (a
union keeps them as they are, a difference drops the subtracted operands that
miss its first operand, an intersection drops what lies outside the common
box). What is subtracted and the operands of intersections can be cut to the
boxes where they matter (:func:`trim_to_box`), and a difference of many cuts
is parted into slabs (:meth:`Plan.split_difference`), so that each Boolean
fits the memory bound.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..._jit import njit
from ...errors import InvalidParameterError
from ...laminae.model import BandMesh
from ..program import OP_DIFFERENCE, OP_INTERSECTION, OP_UNION, Program

#: Peak working memory of the Booleans per band triangle that enters manifold3d
#: (manifold3d's half-edge meshes of the operands and the result, the Mesh64
#: copies and the output arrays; measured on the 1000-hole plate's slabs of about
#: 310 k trimmed triangles: 540 to 1100 bytes each, from a slab's first solid to
#: the next slab, more where more of the input is kept), and per triangle passed
#: through unchanged.
BYTES_PER_BOOLEAN_TRIANGLE = 1200
BYTES_PER_PLAIN_TRIANGLE = 200


def estimate_surface_triangles(bands: Sequence[BandMesh]) -> int:
    """About how many triangles the clipped surface of these band meshes has at most.

    The leaves' band triangles: the result keeps at most all of them (each
    split where other operands cut it, which adds about as many as a cut
    removes), so the sum sizes the Booleans' input and a bound for their
    output, known before anything is built.

    Parameters
    ----------
    bands : sequence of BandMesh
        One per leaf.

    Returns
    -------
    int

    Examples
    --------
    >>> from isocsg import PointLight, Sphere
    >>> from isocsg.laminae import build_laminae
    >>> from isocsg.lighting.lights import Material
    >>> b = build_laminae(Sphere((0, 0, 0), 1), (PointLight((0, -4, 3)),), Material(), 8).bands
    >>> estimate_surface_triangles([b, b]) == 2 * b.n_triangles
    True
    """
    return int(sum(int(len(b.triangles)) for b in bands))


def estimate_surface_bytes(bands: Sequence[BandMesh]) -> int:
    """An upper estimate of the working memory of :func:`surface_from_bands`, in bytes.

    Every band triangle is counted as if it entered the Booleans
    (:data:`BYTES_PER_BOOLEAN_TRIANGLE`); leaves that meet no other operand
    cost less (:data:`BYTES_PER_PLAIN_TRIANGLE`), which
    :func:`surface_from_bands` takes into account when it checks the memory
    budget.

    Examples
    --------
    >>> estimate_surface_bytes([]) == 0
    True
    """
    return estimate_surface_triangles(bands) * BYTES_PER_BOOLEAN_TRIANGLE


#: Margin, in the local frame (the leaves' box mapped to [-1, 1]^3), between a
#: trimmed operand's cut and the box it is trimmed to: the cut's caps lie strictly
#: outside everything the operand can still touch.
TRIM_MARGIN = 1e-4


def trim_to_box(
    v: NDArray[np.float64], t: NDArray[np.int64], lo: NDArray[np.float64], hi: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]:
    """A closed triangle soup of a convex solid cut to a box (plus :data:`TRIM_MARGIN`), each cut capped.

    Used for operands whose surface matters only inside a box (what a
    difference subtracts from its first operand, the operands of an
    intersection): the part outside never reaches the result, so it need not
    enter a Boolean. Each plane of the box that crosses the solid cuts it; the
    cut is capped by a fan from the centre of the section, which is convex for
    a convex solid. Cut points are computed from each edge's ends in a fixed
    order, so neighbours that share an edge share the point bit for bit (the
    soup is welded afterwards). Returns vertices, triangles and the source
    triangle of each (a cap takes a source of the triangle it closes).
    """
    src = np.arange(len(t), dtype=np.int64)
    for axis in range(3):
        for side, bound in ((1.0, hi[axis] + TRIM_MARGIN), (-1.0, lo[axis] - TRIM_MARGIN)):
            x = v[:, axis]
            if not len(t) or np.max(side * (x - bound)) <= 0:
                continue
            # Keep the cut away from vertices, so no vertex lies on it.
            step = max(abs(bound), 1.0) * 1e-9
            for _ in range(64):
                if np.abs(x - bound).min() > step:
                    break
                bound += side * 4 * step
            v, t, src = _cut(v, t, src, axis, bound, side)
    return v, t, src


def _cut(
    v: NDArray[np.float64], t: NDArray[np.int64], src: NDArray[np.int64], axis: int, bound: float, side: float
) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]:
    """Keep the part of a closed soup where ``side * (x[axis] - bound) < 0``; cap the cut with a fan."""
    s = side * (v[:, axis] - bound)
    inside = s < 0
    count = inside[t].sum(axis=1)
    whole = count == 3
    if whole.all():
        return v, t, src
    keep_t, keep_s = t[whole], src[whole]
    one, two = count == 1, count == 2
    if not (one.any() or two.any()):
        return v, keep_t, keep_s  # nothing crosses: the soup lies on one side
    # Rotate each crossing triangle so that its odd vertex (alone on its side) comes first.
    ct = t[one | two]
    cs = src[one | two]
    odd_in = inside[ct] == (count[one | two] == 1)[:, None]  # the lone vertex
    first = np.argmax(odd_in, axis=1)
    rows = np.arange(len(ct))[:, None]
    ct = ct[rows, (first[:, None] + np.arange(3)) % 3]
    a, b, c = ct[:, 0], ct[:, 1], ct[:, 2]
    lone_inside = inside[a]

    def point(p: NDArray[np.int64], q: NDArray[np.int64]) -> NDArray[np.float64]:
        # From the inside end to the outside end, whichever triangle asks: bit-equal for neighbours.
        pin = np.where(inside[p], p, q)
        pout = np.where(inside[p], q, p)
        w = s[pin] / (s[pin] - s[pout])
        out = v[pin] + (v[pout] - v[pin]) * w[:, None]
        out[:, axis] = bound
        return out

    m = len(ct)
    nv = len(v)
    ab = nv + np.arange(m)
    ca = nv + m + np.arange(m)
    centre_pts = np.vstack([point(a, b), point(c, a)])
    centre = centre_pts.mean(axis=0)
    centre[axis] = bound
    cidx = nv + 2 * m
    v2 = np.vstack([v, centre_pts, centre[None, :]])
    # Lone vertex inside: the triangle (a, ab, ca), whose cut edge runs ab -> ca.
    # Lone vertex outside: the quad ab, b, c, ca, whose cut edge runs ca -> ab.
    li = lone_inside
    tri_in = np.column_stack([a[li], ab[li], ca[li]])
    lo = ~li
    quad1 = np.column_stack([ab[lo], b[lo], c[lo]])
    quad2 = np.column_stack([ab[lo], c[lo], ca[lo]])
    # The cap: each cut edge reversed, closed to the centre.
    cap = np.vstack([
        np.column_stack([ca[li], ab[li], np.full(int(li.sum()), cidx)]),
        np.column_stack([ab[lo], ca[lo], np.full(int(lo.sum()), cidx)]),
    ])
    cap_s = np.concatenate([cs[li], cs[lo]])
    t2 = np.vstack([keep_t, tri_in, quad1, quad2, cap])
    s2 = np.concatenate([keep_s, cs[li], cs[lo], cs[lo], cap_s])
    used, inv = np.unique(t2, return_inverse=True)
    return v2[used], inv.reshape(-1, 3), s2


@dataclass(slots=True)
class Piece:
    """A box-disjoint piece of an operand's value: a leaf as it is (``ref >= 0``: leaf
    ``ref``) or a planned Boolean (``ref < 0``: node ``-1 - ref``), with its local box."""

    lo: NDArray[np.float64]
    hi: NDArray[np.float64]
    ref: int


class Plan:
    """The tree evaluated on boxes: which Booleans are needed, and on which operands.

    Nodes are created operands first, so building them in order never needs
    a node that is not built yet.
    """

    def __init__(self) -> None:
        self.nodes: list[tuple[str, list[int]]] = []  # (manifold3d operation or "compose", operand refs)
        # Leaves whose surface matters only inside a box (what they are subtracted from, the
        # box common to an intersection's operands): leaf -> (lo, hi) over all such uses.
        self.trim: dict[int, tuple[NDArray[np.float64], NDArray[np.float64]]] = {}
        self.whole: set[int] = set()  # leaves used where all of their surface may matter
        self.boxes: list[tuple[NDArray[np.float64], NDArray[np.float64]]] = []  # each node's box
        self.slabs: dict[int, tuple[int, float, float]] = {}  # "slab" node -> (axis, lo, hi)

    def node(self, op: str, parts: list[Piece], boxes: list[Any] | None = None) -> Piece:
        """A planned operation; ``boxes[k]``, where given, is the box outside which
        operand ``k`` cannot change the result (None: all of it may)."""
        self.nodes.append((op, [p.ref for p in parts]))
        for k, p in enumerate(parts):
            box = None if boxes is None else boxes[k]
            if p.ref < 0:
                continue
            if box is None:
                self.whole.add(p.ref)
            elif p.ref in self.trim:
                lo0, hi0 = self.trim[p.ref]
                self.trim[p.ref] = (np.minimum(lo0, box[0]), np.maximum(hi0, box[1]))
            else:
                self.trim[p.ref] = (np.asarray(box[0], np.float64), np.asarray(box[1], np.float64))
        lo = np.min([p.lo for p in parts], axis=0)
        hi = np.max([p.hi for p in parts], axis=0)
        self.boxes.append((lo, hi))
        return Piece(lo, hi, -len(self.nodes))

    def nodes_of(self, ref: int) -> list[int]:
        """The nodes a piece is built from (itself included), in building order."""
        out, todo = set(), [ref]
        while todo:
            r = todo.pop()
            if r < 0 and -1 - r not in out:
                out.add(-1 - r)
                todo.extend(self.nodes[-1 - r][1])
        return sorted(out)

    def needed(self, refs: list[int]) -> NDArray[np.bool_]:
        """Which nodes the pieces ``refs`` are built from (a node takes only earlier ones)."""
        needed = np.zeros(len(self.nodes), bool)
        for r in refs:
            if r < 0:
                needed[-1 - r] = True
        for k in range(len(self.nodes) - 1, -1, -1):
            if needed[k]:
                for r in self.nodes[k][1]:
                    if r < 0:
                        needed[-1 - r] = True
        return needed

    def split_difference(self, c: Piece, count: Any, most: int, leaf_box: Any) -> list[Piece]:
        """A difference of many box-disjoint cuts as several, each of the first operand's
        slab between two planes that cross no cut (boxes with gaps between them), so that
        each Boolean takes at most about ``most`` triangles (``count(ref)``: a piece's
        triangles); the slabs' cut faces are dropped when the results are read back.
        Returns ``[c]`` when one Boolean is within ``most`` or no plane can part the cuts."""
        op, refs = self.nodes[-1 - c.ref]
        if op != "Subtract" or len(refs) < 3:
            return [c]
        first, cuts = refs[0], refs[1:]
        sizes = np.array([count(r) for r in cuts], np.int64)
        room = most - count(first)
        if count(first) + int(sizes.sum()) <= most or room <= 0:
            return [c]
        box = [leaf_box(r) if r >= 0 else self.boxes[-1 - r] for r in [first] + cuts]
        axis = int(np.argmax(box[0][1] - box[0][0]))
        lo = np.array([b[0][axis] for b in box[1:]])
        hi = np.array([b[1][axis] for b in box[1:]])
        order = np.argsort(lo, kind="stable")
        reach = np.maximum.accumulate(hi[order])  # the farthest end of the cuts so far
        n = len(order)
        cum = np.concatenate([[0], np.cumsum(sizes[order])])
        # Where a plane may pass: after position e - 1 when no cut so far reaches the next one.
        ends = [e for e in range(1, n) if reach[e - 1] < lo[order[e]]] + [n]
        groups, start = [], 0
        while start < n:
            fit = [e for e in ends if e > start and cum[e] - cum[start] <= room]
            end = fit[-1] if fit else next(e for e in ends if e > start)  # the largest that fits, else the least
            groups.append((start, end))
            start = end
        if len(groups) < 2:
            return [c]
        first_comp = Piece(box[0][0], box[0][1], first)
        out = []
        for g, (a, b) in enumerate(groups):
            s_lo = -np.inf if g == 0 else float((reach[a - 1] + lo[order[a]]) / 2)
            s_hi = np.inf if g == len(groups) - 1 else float((reach[b - 1] + lo[order[b]]) / 2)
            slab = self.node("slab", [first_comp])
            self.slabs[-1 - slab.ref] = (axis, s_lo, s_hi)
            slab.lo, slab.hi = slab.lo.copy(), slab.hi.copy()
            slab.lo[axis], slab.hi[axis] = max(slab.lo[axis], s_lo), min(slab.hi[axis], s_hi)
            parts = [Piece(box[1 + x][0], box[1 + x][1], cuts[x]) for x in order[a:b].tolist()]
            d = self.node("Subtract", [slab] + parts, [None] + [(first_comp.lo, first_comp.hi)] * len(parts))
            out.append(Piece(slab.lo, slab.hi, d.ref))
        return out

    def leaves(self, ref: int) -> list[int]:
        """The leaves a piece is made of (a walk of the nodes with a stack), sorted."""
        out, todo, seen = set(), [ref], set()
        while todo:
            r = todo.pop()
            if r >= 0:
                out.add(r)
            elif r not in seen:
                seen.add(r)
                todo.extend(self.nodes[-1 - r][1])
        return sorted(out)

    def combine(self, op: int, args: list[list[Piece]]) -> list[Piece]:
        if len(args) == 1:
            return args[0]
        if op == OP_UNION:
            return self._union([c for a in args for c in a])
        if op == OP_DIFFERENCE:
            return self._difference(args[0], [c for a in args[1:] for c in a])
        if op == OP_INTERSECTION:
            return self._intersection(args)
        raise InvalidParameterError(f"unknown CSG opcode {op}")

    def _union(self, comps: list[Piece]) -> list[Piece]:
        if len(comps) < 2:
            return comps
        label = _groups(len(comps), *_overlapping(comps))
        out: list[Piece] = []
        members: dict[int, list[Piece]] = {}
        for c, g in zip(comps, label.tolist()):
            members.setdefault(g, []).append(c)
        for group in members.values():
            # manifold3d's batch union composes the members whose boxes do not overlap.
            out.append(group[0] if len(group) == 1 else self.node("Add", group))
        return out

    def _difference(self, first: list[Piece], cut: list[Piece]) -> list[Piece]:
        if not first or not cut:
            return first
        i, j = _overlapping(first + cut)
        nf = len(first)
        # Pairs (piece of the first operand, subtracted piece) whose boxes meet.
        a, b = np.minimum(i, j), np.maximum(i, j)
        sel = (a < nf) & (b >= nf)
        a, b = a[sel], b[sel] - nf
        order = np.argsort(a, kind="stable")
        a, b = a[order], b[order]
        starts = np.searchsorted(a, np.arange(nf + 1))
        out: list[Piece] = []
        for k, c in enumerate(first):
            hit = b[starts[k] : starts[k + 1]].tolist()
            if not hit:
                out.append(c)
                continue
            # What is subtracted matters only inside the first operand's box.
            d = self.node("Subtract", [c] + [cut[x] for x in hit], [None] + [(c.lo, c.hi)] * len(hit))
            out.append(Piece(c.lo, c.hi, d.ref))
        return out

    def _intersection(self, args: list[list[Piece]]) -> list[Piece]:
        if any(not a for a in args):
            return []
        lo = np.max([np.min([c.lo for c in a], axis=0) for a in args], axis=0)
        hi = np.min([np.max([c.hi for c in a], axis=0) for a in args], axis=0)
        if np.any(lo > hi):
            return []
        operands = []
        for a in args:
            kept = [c for c in a if np.all(c.lo <= hi) and np.all(c.hi >= lo)]
            if not kept:
                return []
            # The pieces of one operand are box-disjoint: joined without a Boolean.
            operands.append(kept[0] if len(kept) == 1 else self.node("compose", kept, [(lo, hi)] * len(kept)))
        inter = self.node("Intersect", operands, [(lo, hi)] * len(operands))
        return [Piece(np.maximum(inter.lo, lo), np.minimum(inter.hi, hi), inter.ref)]


def _overlapping(comps: list[Piece]) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Pairs of pieces whose (closed) boxes meet."""
    lo = np.array([c.lo for c in comps])
    hi = np.array([c.hi for c in comps])
    # Sweep along the axis where the boxes are spread widest relative to their size.
    spread = np.ptp(lo + hi, axis=0) / np.maximum((hi - lo).mean(axis=0), 1e-300)
    return _box_pairs(lo, hi, int(np.argmax(spread)))


@njit(cache=True)
def _box_pairs(
    lo: NDArray[np.float64], hi: NDArray[np.float64], axis: int
) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Sort and sweep: every pair (i, j) of boxes that meet."""
    n = len(lo)
    order = np.argsort(lo[:, axis])
    out_i = []
    out_j = []
    for a in range(n):
        i = order[a]
        for b in range(a + 1, n):
            j = order[b]
            if lo[j, axis] > hi[i, axis]:
                break
            if (
                lo[j, 0] <= hi[i, 0] and lo[i, 0] <= hi[j, 0] and lo[j, 1] <= hi[i, 1]
                and lo[i, 1] <= hi[j, 1] and lo[j, 2] <= hi[i, 2] and lo[i, 2] <= hi[j, 2]
            ):
                out_i.append(i)
                out_j.append(j)
    return np.array(out_i, np.int64), np.array(out_j, np.int64)


@njit(cache=True)
def _groups(n: int, i: NDArray[np.int64], j: NDArray[np.int64]) -> NDArray[np.int64]:
    """Connected groups of ``n`` items joined by the pairs ``(i, j)`` (union-find): a label per item."""
    parent = np.arange(n)
    for k in range(len(i)):
        a, b = i[k], j[k]
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        while parent[b] != b:
            parent[b] = parent[parent[b]]
            b = parent[b]
        if a != b:
            parent[max(a, b)] = min(a, b)
    for k in range(n):
        r = k
        while parent[r] != r:
            r = parent[r]
        parent[k] = r
    return parent


def untrimmed_groups(program: Program, lo: ArrayLike, hi: ArrayLike) -> list[list[int]]:
    """For each Boolean that ``surface_from_bands(program, bands, trim=True)`` would build
    on leaves within these boxes, the leaves it takes whole (none of their triangles can go).

    Known from the leaves' boxes alone, before any band exists: the sum of their band
    triangles is a lower bound of that Boolean's, e.g. to give up on a union of many
    overlapping leaves without building all their bands.

    Parameters
    ----------
    program : Program
    lo, hi : array_like, shape (n, 3)
        The leaves' bounding boxes.

    Returns
    -------
    list of list of int

    Examples
    --------
    >>> from isocsg import Box, Cylinder, Sphere
    >>> prog = ((Sphere((0, 0, 0), 1) | Sphere((1, 0, 0), 1)) - Cylinder((0, 0, 0), (0, 0, 3), 0.2)).program()
    >>> lo = np.array([[-1, -1, -1], [0, -1, -1], [-0.2, -0.2, -1.5]]); hi = lo + [[2, 2, 2], [2, 2, 2], [0.4, 0.4, 3]]
    >>> untrimmed_groups(prog, lo, hi)
    [[0, 1]]
    """
    lo = np.asarray(lo, np.float64).reshape(-1, 3)
    hi = np.asarray(hi, np.float64).reshape(-1, 3)
    plan = Plan()
    final = program.evaluate(lambda i, _: [Piece(lo[i], hi[i], i)], plan.combine)
    trimmable = set(plan.trim) - plan.whole
    return [[x for x in plan.leaves(c.ref) if x not in trimmable] for c in final if c.ref < 0]
