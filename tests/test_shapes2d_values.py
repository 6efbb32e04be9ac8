"""2D shapes as values: constructors, equality, flattening, transforms, deep trees and errors."""

from __future__ import annotations

import math
import pickle
import re

import numpy as np
import pytest

from isocsg.errors import InvalidGeometryError
from isocsg.shapes2d import (
    EMPTY,
    Circle,
    ConvexPolygon,
    Difference2D,
    Ellipse,
    Intersection2D,
    Union2D,
    area,
    bounds,
    circle,
    convex_polygon,
    polygon,
    square,
    union_all2d,
)
from isocsg.shapes2d.shape import fold


def test_square_and_circle_follow_openscad():
    assert square(2).vertices == ((0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0))
    assert square([4, 2], center=True).bounds == (-2.0, -1.0, 2.0, 1.0)
    assert circle() == Circle((0, 0), 1.0)
    assert circle(d=3) == Circle((0, 0), 1.5)
    assert circle(2, fn=0) == Circle((0, 0), 2.0)


@pytest.mark.parametrize("fn", [1, 3, 4, 5, 6, 8, 30])
def test_circle_fn_is_openscads_regular_polygon(fn):
    p = circle(2, fn=fn)
    n = max(fn, 3)
    assert isinstance(p, ConvexPolygon) and len(p.vertices) == n
    angles = [math.degrees(math.atan2(y, x)) % 360 for x, y in p.vertices]
    assert np.allclose(angles, [360 * i / n for i in range(n)], atol=1e-9)
    assert np.allclose(np.hypot(*np.array(p.vertices).T), 2.0, rtol=1e-15)
    assert math.isclose(area(p), 0.5 * n * 4 * math.sin(2 * math.pi / n), rel_tol=1e-13)


def test_hexagon_vertices_are_exact_at_quarter_turns():
    assert circle(1, fn=4).vertices == ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))


def test_polygon_with_holes_and_paths():
    pts = [(0, 0), (10, 0), (10, 10), (0, 10), (2, 2), (4, 2), (4, 4), (2, 4), (6, 6), (8, 6), (8, 8), (6, 8)]
    shape = polygon(pts, [[0, 1, 2, 3], [4, 5, 6, 7], [8, 9, 10, 11]])
    assert area(shape) == pytest.approx(100 - 4 - 4, abs=1e-12)
    assert all(isinstance(c, ConvexPolygon) for c in shape.children)


def test_polygon_even_odd_of_overlapping_and_self_crossing_rings():
    a = [(0, 0), (2, 0), (2, 2), (0, 2)]
    b = [(1, 1), (3, 1), (3, 3), (1, 3)]
    # Two overlapping squares: the even-odd fill leaves their overlap out.
    assert area(polygon(a + b, [[0, 1, 2, 3], [4, 5, 6, 7]])) == pytest.approx(6.0, abs=1e-12)
    # A bow tie: two triangles of area 1 each.
    assert area(polygon([(0, 0), (2, 2), (2, 0), (0, 2)])) == pytest.approx(2.0, abs=1e-12)


def test_convex_polygon_normalises_orientation_and_flags_non_convex():
    assert convex_polygon([(0, 0), (0, 1), (1, 1), (1, 0)]).area == 1.0
    with pytest.raises(InvalidGeometryError, match=re.escape("ConvexPolygon.vertices must be convex, got a right turn")):
        ConvexPolygon(((0, 0), (2, 0), (1, 0.5), (2, 2), (0, 2)))


def test_nodes_flatten_and_compare_exactly():
    a, b, c = square(1), circle(1), square(2).translate([5, 0])
    assert (a | b | c).children == (a, b, c)
    assert ((a - b) - c).children == (a, b, c)
    assert (a - (b - c)).children == (a, Difference2D((b, c)))
    assert (a & b & c) == Intersection2D((a, b, c))
    assert (a | b) != (b | a)
    assert hash(a | b) == hash(Union2D((a, b)))
    assert pickle.loads(pickle.dumps(a | b - c)) == a | b - c
    assert eval(repr(a | b), {"Union2D": Union2D, "ConvexPolygon": ConvexPolygon, "Circle": Circle}) == a | b


def test_empty_shape():
    assert EMPTY == Union2D(()) and math.isnan(bounds(EMPTY)[0]) and area(EMPTY) == 0.0


def test_transforms_map_leaves_exactly():
    assert circle(1).translate([1, 2]) == Circle((1, 2), 1)
    assert square(1).rotate(90).vertices == ((0.0, 0.0), (0.0, 1.0), (-1.0, 1.0), (-1.0, 0.0))
    assert circle(1).scale(3) == Circle((0, 0), 3)
    assert circle(1).scale([2, 1]) == Ellipse((0, 0), ((2, 0), (0, 1)))
    assert circle(1).scale([2, 1]).scale([0.5, 1]) == Circle((0, 0), 1)
    m = square(1).mirror([1, 0])
    assert isinstance(m, ConvexPolygon) and m.area == 1.0 and m.bounds == (-1.0, 0.0, 0.0, 1.0)
    assert square(1).mirror([0, 0]) == square(1)
    sheared = circle(1).transform([[1, 0.5, 0], [0, 1, 0]])
    assert isinstance(sheared, Ellipse) and math.isclose(sheared.area, math.pi, rel_tol=1e-15)
    tree = (square(2) - circle(0.5)).rotate(30).translate([3, 0])
    assert math.isclose(area(tree), 4 - math.pi / 16, rel_tol=1e-12)  # a quarter disc cut at the corner


def test_deep_trees_need_no_recursion():
    shape = square(1)
    for k in range(3000):  # alternate operations: nothing flattens, the tree is 3000 deep
        shape = (shape | circle(0.1).translate([k, 0])) if k % 2 else (shape - circle(0.05).translate([k, 3]))
    again = square(1)
    for k in range(3000):
        again = (again | circle(0.1).translate([k, 0])) if k % 2 else (again - circle(0.05).translate([k, 3]))
    assert shape == again and hash(shape) == hash(again)
    depth = fold(shape, lambda leaf: 0, lambda op, node, kids: 1 + max(kids))
    assert depth == 3000
    assert len(repr(shape)) > 1000
    moved = shape.translate([1, 1])
    assert bounds(moved)[0] == bounds(shape)[0] + 1


def test_wide_unions_of_disjoint_leaves_have_exact_areas():
    discs = union_all2d(circle(0.4).translate([k, 0]) for k in range(3000))
    assert len(discs.children) == 3000
    assert area(discs) == pytest.approx(3000 * math.pi * 0.16, rel=1e-14)


BAD = [
    (lambda: square(0), "square.size must be > 0 in x and y, got [0, 0]"),
    (lambda: square([1, -2]), "square.size must be > 0 in x and y, got [1, -2]"),
    (lambda: square(float("nan")), "square.size must be a finite number within +-1e+12, got nan"),
    (lambda: square(1, center=1), "square.center must be a boolean, got 1"),
    (lambda: circle(-1), "circle.r must be > 0, got -1"),
    (lambda: circle(d=float("inf")), "circle.d must be a finite number within +-1e+12, got inf"),
    (lambda: circle(1, 2), "circle takes r or d, not both"),
    (lambda: circle(1, fn=2.5), "circle.fn must be an integer, got 2.5"),
    (lambda: circle(1, fn=10**6), "circle.fn must be <= 65536, got 1e+06"),
    (lambda: polygon([(0, 0), (1, 0)]), "polygon.points must have at least 3 points, got 2"),
    (lambda: polygon([(0, 0), (1, 0), (2, 0)]), "polygon.points must enclose an area > 0, got a degenerate polygon"),
    (lambda: polygon([(0, 0), (1, float("nan")), (0, 1)]), "polygon.points must hold finite numbers, got NaN or inf"),
    (lambda: polygon(np.zeros((70000, 2))), "polygon.points must have at most 65536 points, got 70000"),
    (lambda: polygon([(0, 0), (1, 0), (0, 1)], [[0, 1, 5]]), "polygon.paths[0] indices must be in [0, 2], got 5"),
    (lambda: polygon([(0, 0), (1, 0), (0, 1)], [[0, 1]]), "polygon.paths[0] must have at least 3 indices, got 2"),
    (lambda: polygon([(0, 0), (1, 0), (0, 1)], []), "polygon.paths must hold at least one path, got none"),
    (lambda: polygon("abc"), "polygon.points must be a list of [x, y] points, got 'abc'"),
    (lambda: Circle((0, 0), 0), "Circle.radius must be > 0, got 0"),
    (lambda: Circle((0, 1, 2), 1), "Circle.center must be a pair [x, y], got (0, 1, 2)"),
    (lambda: Ellipse((0, 0), ((1, 2), (2, 4))), "Ellipse.matrix must be invertible, got determinant 0"),
    (lambda: ConvexPolygon(((0, 0), (1, 1), (2, 2))), "ConvexPolygon.vertices must enclose an area > 0 counter-clockwise"),
    (lambda: square(1).scale(0), "scale.s must be non-zero in x and y, got [0, 0]"),
    (lambda: square(1).transform([[1, 0], [0, 1]]), "matrix must have shape (2, 3) or (3, 3), got (2, 2)"),
    (lambda: square(1).transform([[1, 2, 0], [2, 4, 0]]), "matrix must be invertible (a shape cannot be flattened)"),
    (lambda: square(1).rotate([10, 0, 0]), "rotate.angle of a 2D shape must be a number or [0, 0, a], got [10.0, 0.0, 0.0]"),
    (lambda: square(1) | 3, "Union2D.children[1] must be a 2D shape, got int"),
    (lambda: Intersection2D(()), "Intersection2D.children must hold at least one shape, got none"),
]


@pytest.mark.parametrize("make, message", BAD, ids=[m for _, m in BAD])
def test_errors_name_the_field(make, message):
    with pytest.raises(InvalidGeometryError, match=re.escape(message)):
        make()


def test_errors_are_value_errors():
    with pytest.raises(ValueError):
        square(-1)


def test_method_facades():
    from isocsg import volume

    shape = square(2) - circle(0.5).translate([1, 1])
    assert shape.offset(0.25) == __import__("isocsg.shapes2d", fromlist=["offset"]).offset(shape, 0.25)
    assert volume(shape.linear_extrude(2)) == pytest.approx(2 * shape.area, rel=1e-6)
    assert shape.to_shapely().area == pytest.approx(shape.area, rel=1e-3)
