"""CSG tree construction, bad input, programs and empty results."""

from __future__ import annotations

import re

import numpy as np
import pytest

from isocsg import (
    Box,
    Cylinder,
    Difference,
    Intersection,
    InvalidGeometryError,
    InvalidParameterError,
    Sphere,
    Union,
    difference,
    intersection,
    union,
    union_all,
)
from isocsg.csg.mesh import to_manifold, to_trimesh
from isocsg.csg.program import OP_DIFFERENCE, OP_INTERSECTION, OP_LEAF, OP_UNION
from isocsg.csg.section import section
from isocsg.csg.tree import leaves
from isocsg.csg.volume import volume

A = Sphere((0, 0, 0), 1.0)
B = Box((0.5, 0, 0), (1, 1, 1))
C = Cylinder((0, 0, 0), (0, 0, 3), 0.3)


@pytest.mark.parametrize("node", [Union, Intersection, Difference], ids=["union", "intersection", "difference"])
def test_empty_operand_list_is_rejected(node):
    msg = f"{node.__name__} needs at least one operand, got none"
    with pytest.raises(InvalidGeometryError, match=re.escape(msg)):
        node()
    with pytest.raises(InvalidGeometryError, match=re.escape(msg)):
        node([])


def test_union_all_of_nothing_is_rejected():
    with pytest.raises(InvalidGeometryError, match="Union needs at least one operand"):
        union_all([])


@pytest.mark.parametrize(
    ("build", "index", "kind"),
    [
        (lambda: Union(A, B, 3.0), 2, "float"),
        (lambda: Intersection(A, "box"), 1, "str"),
        (lambda: Difference(None, A), 0, "NoneType"),
        (lambda: union(A, [1, 2, 3]), 1, "list"),
    ],
    ids=["union-float", "intersection-str", "difference-none", "union-list"],
)
def test_non_solid_operand_is_named_by_index(build, index, kind):
    with pytest.raises(InvalidGeometryError, match=re.escape(f"operand {index} must be a solid")) as info:
        build()
    assert kind in str(info.value)
    assert isinstance(info.value, ValueError)  # also catchable as the builtin


def test_operators_build_the_named_nodes():
    assert isinstance(A | B, Union) and (A | B).children == (A, B)
    assert isinstance(A & B, Intersection) and (A & B).children == (A, B)
    assert isinstance(A - B, Difference) and (A - B).children == (A, B)
    assert union(A, B, C) == Union(A, B, C) == Union([A, B, C])
    assert intersection(A, B) == A & B
    assert difference(A, B, C) == Difference(A, B, C)


def test_nodes_are_frozen_and_hashable():
    t = (A - B) | C
    with pytest.raises(AttributeError):
        t.children = ()  # type: ignore[misc]
    assert hash(t) == hash((A - B) | C)
    assert len({t, (A - B) | C}) == 1


def test_program_is_postfix_over_the_leaves():
    tree = Difference(Union(A, B), C, Intersection(B, A))
    prog = tree.program()
    assert list(prog.leaves) == [A, B, C, B, A] == leaves(tree)
    L = OP_LEAF
    assert prog.op.tolist() == [L, L, OP_UNION, L, L, L, OP_INTERSECTION, OP_DIFFERENCE]
    assert prog.arg.tolist() == [0, 1, 2, 2, 3, 4, 2, 3]
    assert prog.op.dtype == np.int8 and prog.arg.dtype == np.int64


def test_contains_follows_the_set_operations():
    rng = np.random.default_rng(0)
    p = rng.uniform(-1.5, 1.5, size=(4000, 3))
    a, b, c = A.contains(p), B.contains(p), C.contains(p)
    np.testing.assert_array_equal(Difference(A, B, C).contains(p), a & ~b & ~c)
    np.testing.assert_array_equal(((A | B) & C).contains(p), (a | b) & c)


def _disjoint_intersection():
    return Sphere((0, 0, 0), 1.0) & Sphere((5, 0, 0), 1.0)


@pytest.mark.parametrize(
    "empty",
    [_disjoint_intersection(), A - A, Box((0, 0, 0), (1, 1, 1)) - Box((0, 0, 0), (2, 2, 2))],
    ids=["disjoint-intersection", "a-minus-a", "box-minus-bigger-box"],
)
def test_empty_result_is_a_valid_solid(empty):
    assert volume(empty, tol=1e-3) == 0.0
    for n in [(0, 0, 1), (0.3, -0.4, 0.87)]:
        s = section(empty, (0, 0, 0), n)
        assert s.is_empty and s.area == 0.0
    assert to_manifold(empty, 32).is_empty()
    assert len(to_trimesh(empty, 32).faces) == 0


@pytest.mark.parametrize(
    ("call", "field"),
    [
        (lambda: section(A, (0, 0, 0), (0, 0, 0)), "plane_normal"),
        (lambda: section(A, (0, np.nan, 0), (0, 0, 1)), "plane_origin"),
        (lambda: section(A, (0, 0, 0), (0, 0, 1), resolution=2), "resolution"),
        (lambda: volume(A, tol=0.0), "tol"),
        (lambda: volume(A, axis=(0, 0, 0)), "axis"),
        (lambda: to_manifold(A, resolution=1.5), "resolution"),
    ],
    ids=["zero-normal", "nan-origin", "low-resolution", "zero-tol", "zero-axis", "float-resolution"],
)
def test_bad_parameters_name_the_field(call, field):
    with pytest.raises(InvalidParameterError, match=re.escape(field)):
        call()


@pytest.mark.parametrize("fn", [lambda s: section(s, (0, 0, 0), (0, 0, 1)), volume, to_manifold], ids=["section", "volume", "to_manifold"])
def test_non_solid_input_is_rejected(fn):
    with pytest.raises(InvalidGeometryError, match="must be a primitive or CSG node|must be a solid"):
        fn("not a solid")
