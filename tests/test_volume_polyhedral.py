"""``isocsg.volume`` of polyhedral trees (every leaf flat-faced): the exact mesh Boolean path.

Judged by closed forms (the Menger sponge keeps (20/27)^n of its cube, turned or not, and a
plane through its centre halves it by its central symmetry) and, on random trees of turned
boxes and polyhedra, by the independent section integration (``method="sections"``).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import isocsg
from isocsg import Box, ConvexPolyhedron
from isocsg.errors import InvalidParameterError


def menger(level: int, D: float = 3.0):
    """OpenSCAD's example024 sponge (without the cut): a cube minus three families of crossed bars."""
    bars = []
    work = [(D, (0.0, 0.0), 1)]
    while work:  # the recursion of menger_negative, as a work list
        side, (cy, cz), lvl = work.pop()
        l_ = side / 3
        bars.append(Box((0.0, cy, cz), (D * 1.1, l_, l_)))
        if lvl < level:
            work.extend((l_, (cy + i * l_, cz + j * l_), lvl + 1)
                        for i in (-1, 0, 1) for j in (-1, 0, 1) if i or j)
    negative = isocsg.union_all(bars)
    turned = [negative, negative.rotate((0, 0, 90)), negative.rotate((0, 90, 0))]
    return Box((0, 0, 0), (D, D, D)) - isocsg.union_all(turned)


@pytest.mark.parametrize("level", [1, 2])  # level 3 (221 leaves) is in docs/csg.md
def test_menger_sponge_turned_and_halved_against_its_closed_form(level: int) -> None:
    D = 3.0
    exact = (20 / 27) ** level * D**3
    sponge = menger(level, D).rotate((45, math.degrees(math.atan(1 / math.sqrt(2))), 0))
    assert isocsg.volume(sponge) == pytest.approx(exact, rel=1e-11)
    half = sponge - Box((0, 0, -D), (2 * D, 2 * D, 2 * D))
    assert isocsg.volume(half) == pytest.approx(exact / 2, rel=1e-11)


def _turned_box(c, s, angles):
    return Box(c, s).rotate(angles)


leaf = st.builds(
    _turned_box,
    st.tuples(*[st.floats(-1, 1)] * 3),
    st.tuples(*[st.floats(0.3, 1.5)] * 3),
    st.tuples(*[st.floats(0, 90)] * 3),
)
def _polyhedron(pts, c):
    try:
        return ConvexPolyhedron(np.asarray(pts) + np.asarray(c))
    except isocsg.InvalidGeometryError:  # a flat draw
        return None


poly = st.builds(
    _polyhedron,
    st.lists(st.tuples(*[st.floats(-0.8, 0.8)] * 3), min_size=8, max_size=12),
    st.tuples(*[st.floats(-0.5, 0.5)] * 3),
).filter(lambda p: p is not None)


@settings(max_examples=8, deadline=None)
@given(st.lists(st.one_of(leaf, poly), min_size=2, max_size=5), st.lists(st.sampled_from("|&-"), min_size=4, max_size=4))
def test_polyhedral_trees_match_the_section_integration(leaves, ops) -> None:
    try:
        tree = leaves[0]
        for p, op in zip(leaves[1:], ops):
            tree = tree | p if op == "|" else tree & p if op == "&" else tree - p
    except isocsg.InvalidGeometryError:
        return
    fast = isocsg.volume(tree)
    slow = isocsg.volume(tree, tol=1e-5, method="sections")
    scale = max(float(np.ptp(np.asarray(p.bounds), axis=0).max()) for p in leaves) ** 3
    assert fast == pytest.approx(slow, rel=2e-5, abs=1e-9 * scale)  # the sections stop at tol / 4


def test_method_is_checked_by_name() -> None:
    with pytest.raises(InvalidParameterError, match="method"):
        isocsg.volume(Box((0, 0, 0), (1, 1, 1)) - Box((0.5, 0, 0), (1, 1, 1)), method="mesh")
