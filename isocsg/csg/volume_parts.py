"""Volumes by parts: a CSG program split into parts whose signed volumes add up, and unions
counted pairwise.

A union whose operands fall into clusters of overlapping boxes is the sum of the clusters;
``P - Q1 - ... - Qn`` is ``V(P) - sum V(P & C)`` over the clusters ``C`` of the ``Qi``; a union
of spheres or boxes of which no three overlap pairwise is ``sum V(i) - sum V(i & j)`` with
closed forms of the pairs (see :mod:`isocsg.csg.volume`).
"""

from __future__ import annotations

import math

import numpy as np
import shapely
from numpy.typing import NDArray

from ..kinds.base import LeafForm
from .leaf_table import leaf_table
from .program import (
    OP_DIFFERENCE,
    OP_INTERSECTION,
    OP_LEAF,
    OP_UNION,
    Program,
    compile_program,
)

__all__ = ["leaf_boxes", "lens_volume", "pairwise_union", "split_parts"]


def leaf_boxes(prog: Program) -> NDArray[np.float64]:
    """Each leaf's axis-aligned box, shape (n, 2, 3)."""
    tab = leaf_table(prog)
    lo = np.empty((len(tab.kind), 3))
    hi = np.empty((len(tab.kind), 3))
    for j, e in enumerate(np.eye(3)):
        lo[:, j], hi[:, j] = tab.extents(e)
    return np.stack([lo, hi], axis=1)



def _overlap_pairs(lo: NDArray[np.float64], hi: NDArray[np.float64]) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Pairs ``i < j`` of boxes that overlap with positive volume (an R-tree in xy, then z)."""
    n = len(lo)
    if n < 2:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    rects = shapely.box(lo[:, 0], lo[:, 1], hi[:, 0], hi[:, 1])
    a, b = shapely.STRtree(rects).query(rects)
    keep = a < b
    a, b = a[keep], b[keep]
    ok = np.all((lo[a] < hi[b]) & (lo[b] < hi[a]), axis=1)
    a, b = a[ok], b[ok]
    return np.minimum(a, b), np.maximum(a, b)


def _clusters(n: int, i: NDArray[np.int64], j: NDArray[np.int64]) -> list[NDArray[np.int64]]:
    """Connected components of the graph on ``n`` nodes with edges ``(i, j)`` (ascending members)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    g = coo_matrix((np.ones(len(i)), (i, j)), shape=(n, n))
    _, label = connected_components(g, directed=False)
    order = np.argsort(label, kind="stable")
    cuts = np.nonzero(np.diff(label[order]))[0] + 1
    return np.split(order, cuts)


def split_parts(prog: Program) -> list[tuple[Program, float]] | None:
    """Parts whose signed volumes add up to the program's, or None when it does not split.

    - a union whose operands fall into several clusters of overlapping boxes is the sum of the
      clusters' unions (they meet in sets of zero volume);
    - ``P - Q1 - ... - Qn`` is ``V(P) - sum V(P & C)`` over the clusters ``C`` (unions) of the
      ``Qi`` that meet ``P``'s box, when there are several; each ``P & C`` keeps only the leaves
      of ``P`` whose boxes meet ``C``'s (elsewhere in ``C`` they are absent).
    """
    root = int(prog.op[-1]) if len(prog.op) else OP_LEAF
    if root not in (OP_UNION, OP_DIFFERENCE):
        return None
    subs = prog.operands()
    if root == OP_UNION:  # A | A = A: equal operands once
        keys = [(q.op.tobytes(), q.arg.tobytes(), q.leaves) for q in subs]
        first_of = dict(zip(reversed(keys), reversed(range(len(keys)))))
        if len(first_of) < len(keys):
            kept = sorted(first_of.values())
            return [(Program.join(OP_UNION, [subs[k] for k in kept]), 1.0)]
    boxes = np.array([s.bounds() for s in subs])  # (m, 2, 3)
    if root == OP_UNION:
        groups = _clusters(len(subs), *_overlap_pairs(boxes[:, 0], boxes[:, 1]))
        if len(groups) < 2:
            return None
        return [(Program.join(OP_UNION, [subs[k] for k in g.tolist()]), 1.0) for g in groups]
    first, pbox = subs[0], boxes[0]
    rest = 1 + np.nonzero(np.all((boxes[1:, 0] < pbox[1]) & (boxes[1:, 1] > pbox[0]), axis=1))[0]
    if not len(rest):
        return [(first, 1.0)]
    groups = _clusters(len(rest), *_overlap_pairs(boxes[rest, 0], boxes[rest, 1]))
    if len(groups) < 2:
        return None
    pleaf = leaf_boxes(first)
    presents = []
    for g in groups:
        members = rest[g]
        clo, chi = boxes[members, 0].min(axis=0), boxes[members, 1].max(axis=0)
        presents.append(np.all((pleaf[:, 0] < chi) & (pleaf[:, 1] > clo), axis=1))
    # when most of P meets every cluster (an intersection of many balls, dimpled all over), the
    # parts would repeat P's leaves once per cluster: integrating the whole is cheaper
    if sum(int(p.sum()) for p in presents) > 4 * len(prog.leaves):
        return None
    parts: list[tuple[Program, float]] = [(first, 1.0)]
    for g, present in zip(groups, presents):
        members = rest[g]
        pruned = first.prune(present) if present.any() else None
        if pruned is None:
            continue
        cut = Program.join(OP_UNION, [subs[k] for k in members.tolist()])
        parts.append((Program.join(OP_INTERSECTION, [pruned[0], cut]), -1.0))
    return parts


def lens_volume(r1: NDArray[np.float64], r2: NDArray[np.float64], d: NDArray[np.float64]) -> NDArray[np.float64]:
    """Volume of the intersection of two balls of radii ``r1``, ``r2`` with centres ``d`` apart."""
    small = 4.0 / 3.0 * math.pi * np.minimum(r1, r2) ** 3
    dd = np.maximum(d, 1e-300)
    lens = math.pi * (r1 + r2 - d) ** 2 * (d * d + 2 * d * (r1 + r2) - 3 * (r1 - r2) ** 2) / (12 * dd)
    return np.where(d <= np.abs(r1 - r2), small, np.where(d >= r1 + r2, 0.0, lens))


def pairwise_union(prog: Program) -> float | None:
    """A union of spheres, or of axis-aligned boxes, in which no three leaves overlap pairwise:
    ``sum V(i) - sum V(i & j)`` exactly (inclusion-exclusion stops at pairs, since every triple
    meets in zero volume), with the closed forms of a ball lens and a box overlap. None otherwise."""
    n = len(prog.leaves)
    if n < 2 or prog.op[-1] != OP_UNION or int(prog.arg[-1]) != n or np.any(prog.op[:-1] != OP_LEAF):
        return None
    tab = leaf_table(prog)
    kind = tab.kind
    if not (np.all(kind == LeafForm.BALL) or np.all(kind == LeafForm.AXIS_BOX)):
        return None
    distinct = list(dict.fromkeys(prog.leaves))  # A | A = A
    if len(distinct) < n:
        if len(distinct) == 1:
            return float(distinct[0].volume)
        n = len(distinct)
        prog = Program.join(OP_UNION, [compile_program(p) for p in distinct])
        tab = leaf_table(prog)
    boxes = leaf_boxes(prog)
    i, j = _overlap_pairs(boxes[:, 0], boxes[:, 1])
    if np.all(kind == LeafForm.BALL):
        d = np.linalg.norm(tab.center[i] - tab.center[j], axis=1)
        r1, r2 = tab.radius[i], tab.radius[j]
        keep = d < r1 + r2
        i, j = i[keep], j[keep]
        vols = 4.0 / 3.0 * math.pi * tab.radius**3
        pair = lens_volume(r1[keep], r2[keep], d[keep])
    else:
        vols = np.prod(boxes[:, 1] - boxes[:, 0], axis=1)
        pair = np.prod(np.minimum(boxes[i, 1], boxes[j, 1]) - np.maximum(boxes[i, 0], boxes[j, 0]), axis=1)
    if len(i) and _has_triangle(n, i, j):
        return None
    return max(float(np.sum(vols) - np.sum(pair)), 0.0)


def _has_triangle(n: int, i: NDArray[np.int64], j: NDArray[np.int64]) -> bool:
    """True when some edge's ends share a neighbour (the graph on ``n`` nodes has a triangle)."""
    from scipy.sparse import csr_matrix

    a = csr_matrix((np.ones(len(i)), (i, j)), shape=(n, n))
    a = a + a.T
    a.data[:] = 1.0
    common = a[i].multiply(a[j]).sum(axis=1)  # neighbours shared by the ends of each edge
    return bool(np.any(np.asarray(common) > 0))
