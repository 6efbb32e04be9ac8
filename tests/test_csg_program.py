"""The flat CSG program: flattening, pruning and trees of any depth and width.

Judged by brute force: membership of random points evaluated on the tree's own
nodes (an explicit-stack walk over ``children`` written here), never by the
program judging itself.
"""

from __future__ import annotations

import pickle
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from isocsg import Box, Cylinder, Difference, Intersection, Sphere, Union, difference, union_all
from isocsg.csg.program import OP_DIFFERENCE, OP_INTERSECTION, OP_LEAF, OP_UNION, compile_program
from isocsg.csg.tree import REPR_LEAVES

A = Sphere((0, 0, 0), 1.0)
B = Box((0.5, 0, 0), (1, 1, 1))
C = Cylinder((0, 0, 0), (0, 0, 3), 0.3)
D = Sphere((0.8, 0.3, 0), 0.6)


def brute_contains(solid, points):
    """Membership evaluated on the nodes themselves, with an explicit stack."""
    out: dict[int, np.ndarray] = {}
    todo = [(solid, False)]
    while todo:
        s, ready = todo.pop()
        if not hasattr(s, "children"):
            out[id(s)] = s.contains(points)
            continue
        if not ready:
            todo.append((s, True))
            todo.extend((c, False) for c in s.children)
            continue
        masks = [out[id(c)] for c in s.children]
        if isinstance(s, Union):
            out[id(s)] = np.logical_or.reduce(masks)
        elif isinstance(s, Intersection):
            out[id(s)] = np.logical_and.reduce(masks)
        else:
            out[id(s)] = masks[0] & ~np.logical_or.reduce(masks[1:]) if len(masks) > 1 else masks[0]
    return out[id(solid)]


@pytest.mark.parametrize(
    ("tree", "ops", "args"),
    [
        ((A | B) | C, [0, 0, 0, OP_UNION], [0, 1, 2, 3]),
        (A | (B | C), [0, 0, 0, OP_UNION], [0, 1, 2, 3]),
        ((A & B) & C, [0, 0, 0, OP_INTERSECTION], [0, 1, 2, 3]),
        ((A - B) - C, [0, 0, 0, OP_DIFFERENCE], [0, 1, 2, 3]),
        (A - (B | C), [0, 0, 0, OP_DIFFERENCE], [0, 1, 2, 3]),
        (((A - B) - C) - (D | B), [0, 0, 0, 0, 0, OP_DIFFERENCE], [0, 1, 2, 3, 4, 5]),
        # not flattened: a difference subtracted, a union intersected
        (A - (B - C), [0, 0, 0, OP_DIFFERENCE, OP_DIFFERENCE], [0, 1, 2, 2, 2]),
        ((A | B) & C, [0, 0, OP_UNION, 0, OP_INTERSECTION], [0, 1, 2, 2, 2]),
    ],
    ids=["union-left", "union-right", "intersection", "difference-chain", "minus-union", "mixed-chain",
         "minus-difference", "union-in-intersection"],
)
def test_nested_nodes_of_one_operation_are_flattened(tree, ops, args):
    prog = compile_program(tree)
    assert prog.op.tolist() == ops and prog.arg.tolist() == args
    assert OP_LEAF == 0
    pts = np.random.default_rng(1).uniform(-1.6, 1.6, (3000, 3))
    np.testing.assert_array_equal(prog.contains(pts), brute_contains(tree, pts))


def test_program_arrays_are_read_only():
    prog = compile_program(A - B)
    with pytest.raises(ValueError):
        prog.op[0] = 1
    with pytest.raises(ValueError):
        prog.arg[0] = 1


POOL = [
    Sphere((0, 0, 0), 1.0), Sphere((0.7, 0.2, 0), 0.6), Box((0.4, 0, 0), (1, 1, 1)), Box((-0.5, 0.3, 0.2), (0.8, 0.5, 1.2)),
    Cylinder((0, 0, 0), (0, 0, 3), 0.35), Cylinder((0, -0.2, 0.3), (2, 0, 0), 0.3), Sphere((-0.6, -0.4, 0.1), 0.5),
]


@st.composite
def trees(draw, max_leaves=24):
    """Random trees built bottom up (no recursion), of 1 .. max_leaves leaves."""
    n = draw(st.integers(1, max_leaves))
    nodes = [POOL[draw(st.integers(0, len(POOL) - 1))] for _ in range(n)]
    while len(nodes) > 1:
        k = draw(st.integers(2, min(4, len(nodes))))
        at = draw(st.integers(0, len(nodes) - k))
        kind = draw(st.sampled_from([Union, Intersection, Difference]))
        nodes[at : at + k] = [kind(*nodes[at : at + k])]
    return nodes[0]


@settings(max_examples=60, deadline=None)
@given(trees(), st.lists(st.booleans(), min_size=24, max_size=24))
def test_prune_equals_the_tree_with_absent_leaves_empty(tree, present):
    prog = compile_program(tree)
    keep = np.array(present[: prog.n_leaves])
    pts = np.random.default_rng(2).uniform(-1.6, 1.6, (1500, 3))
    # Brute force: each absent leaf replaced by a solid far away (empty around the points).
    far = Sphere((1e6, 0, 0), 1.0)
    stand_in = [p if k else far for p, k in zip(prog.leaves, keep)]
    rebuilt = prog.evaluate(lambda i, p: stand_in[i], lambda o, xs: {1: Union, 2: Intersection, 3: Difference}[o](*xs))
    expected = brute_contains(rebuilt, pts)
    pruned = prog.prune(keep)
    if pruned is None:
        assert not expected.any()
        return
    sub, ids = pruned
    assert [prog.leaves[i] for i in ids] == list(sub.leaves)
    assert keep[ids].all()
    np.testing.assert_array_equal(sub.contains(pts), expected)
    assert len(sub) <= len(prog)


@settings(max_examples=60, deadline=None)
@given(trees())
def test_program_contains_and_round_trips_agree_with_the_tree(tree):
    pts = np.random.default_rng(3).uniform(-1.6, 1.6, (1500, 3))
    expected = brute_contains(tree, pts)
    np.testing.assert_array_equal(tree.contains(pts), expected)
    np.testing.assert_array_equal(compile_program(tree).to_solid().contains(pts), expected)
    back = pickle.loads(pickle.dumps(tree))
    assert back == tree and hash(back) == hash(tree)
    if hasattr(tree, "children") and tree.program().n_leaves <= REPR_LEAVES:
        assert eval(repr(tree), {k: v for k, v in vars(__import__("isocsg")).items()}) == tree


def test_wide_nodes_keep_every_operand():
    # 1500 operands: more than the 1000 an earlier packed encoding could count.
    holes = [Cylinder((float(i % 50) - 24.5, float(i // 50) - 14.5, 0), (0, 0, 2), 0.2) for i in range(1500)]
    plate = Box((0, 0, 0), (52, 32, 1))
    for part in (difference(plate, *holes), plate - union_all(holes)):
        prog = part.program()
        assert prog.n_leaves == 1501 and prog.arg[-1] == 1501
        centres = np.array([[float(i % 50) - 24.5, float(i // 50) - 14.5, 0.0] for i in range(1500)])
        assert not part.contains(centres).any()
        assert part.contains(centres + [0.5, 0, 0]).all()


def test_trees_built_by_a_loop_of_100000_operations():
    # Far deeper than the interpreter's recursion limit: every walk must be iterative.
    assert sys.getrecursionlimit() < 100_000
    part = Box((0, 0, 0), (1000, 1000, 1))
    holes = []
    for i in range(100_000):
        h = Sphere((float(i % 316) * 3 - 474, float(i // 316) * 3 - 474, 0.5), 0.5)
        holes.append(h)
        part = part - h if i % 2 else part - h | h  # two operations kinds nest alternately
    assert isinstance(part, Difference)
    prog = part.program()
    assert prog.n_leaves == 100_001 + 50_000
    h1 = hash(part)
    back = pickle.loads(pickle.dumps(part))
    assert back == part and hash(back) == h1
    assert part != (part | A)
    assert part.to_dict()  # built without recursion
    assert len(repr(part)) < 200
    np.testing.assert_allclose(part.bounds, [[-500, -500, -0.5], [500, 500, 1.0]])
    # hole 1 was subtracted; hole 0 was subtracted and then added back; between them the plate
    inside = part.contains([[-471.0, -474.0, 0.5], [-474.0, -474.0, 0.5], [-472.5, -474.0, 0.0]])
    assert inside.tolist() == [False, True, True]
