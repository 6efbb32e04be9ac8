"""linear_extrude: the same CSG tree over exact prisms, cylinders and frusta; volumes against area x height."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from isocsg import ConvexPolyhedron, Cylinder, Difference, Truncus, Union, volume
from isocsg.errors import InvalidGeometryError
from isocsg.shapes2d import EMPTY, area, circle, linear_extrude, polygon, square, text

SHAPES = [
    ("square", square([3, 2])),
    ("holed polygon", polygon([(0, 0), (4, 0), (4, 4), (0, 4), (1, 1), (3, 1), (3, 3), (1, 3)], [[0, 1, 2, 3], [4, 5, 6, 7]])),
    ("plate with a hole", square(4, center=True) - circle(1)),
    ("overlapping discs", circle(1) | circle(1).translate([1.2, 0.3])),
    ("ellipse", circle(1).scale([2, 0.5]).rotate(20).translate([1, 1])),
    ("L minus disc", polygon([(0, 0), (4, 0), (4, 1), (1, 1), (1, 4), (0, 4)]) - circle(0.8).translate([1, 1])),
]


@pytest.mark.parametrize("shape", [s for _, s in SHAPES], ids=[n for n, _ in SHAPES])
def test_volume_is_area_times_height(shape):
    solid = linear_extrude(shape, 1.5)
    assert volume(solid) == pytest.approx(1.5 * area(shape), rel=1e-6)


def test_leaves_are_exact_primitives_and_tree_is_kept():
    solid = linear_extrude(square(4, center=True) - circle(1), 2)
    assert isinstance(solid, Difference)
    prism, cyl = solid.children
    assert isinstance(prism, ConvexPolyhedron) and isinstance(cyl, Cylinder)
    assert cyl.radius == 1.0 and cyl.axis == (0.0, 0.0, 2.0) and cyl.center == (0.0, 0.0, 1.0)
    assert isinstance(linear_extrude(circle(1) | square(1), 1), Union)


def test_center_spans_minus_half_to_half():
    cyl = linear_extrude(circle(1), 4, center=True)
    assert cyl.center == (0.0, 0.0, 0.0) and cyl.axis == (0.0, 0.0, 4.0)


@pytest.mark.parametrize("s", [0.0, 0.5, 1.7])
def test_uniform_scale_volumes(s):
    factor = (1 + s + s * s) / 3
    shape = polygon([(0, 0), (4, 0), (4, 1), (1, 1), (1, 4), (0, 4)]).translate([0.5, -1])
    assert volume(linear_extrude(shape, 2, scale=s)) == pytest.approx(2 * area(shape) * factor, rel=1e-6)
    off_axis = circle(1).translate([3, 1])  # scaled about the origin: a sheared (oblique) frustum
    assert volume(linear_extrude(off_axis, 2, scale=s)) == pytest.approx(2 * math.pi * factor, rel=1e-6)
    on_axis = linear_extrude(circle(1), 2, scale=s)
    assert isinstance(on_axis, Truncus) and on_axis.r1 == pytest.approx(s) and on_axis.r2 == 1.0


def test_non_uniform_scale_of_axis_aligned_rectangle_is_exact():
    sx, sy, h = 0.5, 2.0, 3.0
    rect = square([2, 1]).translate([1, 1])
    exact = 2 * h * (1 + (sx - 1) / 2 + (sy - 1) / 2 + (sx - 1) * (sy - 1) / 3)
    assert volume(linear_extrude(rect, h, scale=[sx, sy])) == pytest.approx(exact, rel=1e-6)


def test_scaled_top_follows_openscad():
    solid = linear_extrude(square(2), 1, scale=0.5)
    top = solid.hull_vertices[solid.hull_vertices[:, 2] == 1.0]
    assert np.allclose(sorted(map(tuple, top[:, :2])), [(0, 0), (0, 1), (1, 0), (1, 1)])


def test_text_extrudes_exactly():
    label = text("Hi", size=5)
    assert volume(linear_extrude(label, 1)) == pytest.approx(area(label), rel=1e-6)


def test_deep_trees_extrude_without_recursion():
    shape = square(1)
    for k in range(1500):  # deeper than Python's recursion limit; cylinders are cheap leaves to build
        shape = (shape | circle(0.4).translate([k, 2])) if k % 2 else (shape - circle(0.1).translate([k, 0.5]))
    solid = linear_extrude(shape, 1)
    assert isinstance(solid, Union)


BAD = [
    (lambda: linear_extrude(square(1), 0), "linear_extrude.height must be > 0, got 0"),
    (lambda: linear_extrude(square(1), -1), "linear_extrude.height must be > 0, got -1"),
    (lambda: linear_extrude(square(1), float("inf")), "linear_extrude.height must be a finite number"),
    (lambda: linear_extrude(square(1), 1, center="no"), "linear_extrude.center must be a boolean, got 'no'"),
    (lambda: linear_extrude(square(1), 1, scale=-1), "linear_extrude.scale must be >= 0, got [-1, -1]"),
    (lambda: linear_extrude(circle(1), 1, scale=[1, 2]), "linear_extrude.scale must be uniform for a circle or ellipse"),
    (lambda: linear_extrude(EMPTY, 1), "linear_extrude.shape must not be empty"),
    (lambda: linear_extrude(square(1) & square(1).translate([5, 0]) & EMPTY, 1), "linear_extrude.shape must not be empty"),
    (lambda: linear_extrude("square", 1), "shape must be a 2D shape, got str"),
]


@pytest.mark.parametrize("make, message", BAD, ids=[m for _, m in BAD])
def test_extrude_errors_name_the_field(make, message):
    with pytest.raises(InvalidGeometryError, match=re.escape(message)):
        make()
