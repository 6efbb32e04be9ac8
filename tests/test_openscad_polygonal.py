"""``polygonal=True``: a ``hull`` or ``minkowski`` without an exact form as OpenSCAD's own polygonal solid.

References written here, apart from the library: OpenSCAD's segment count and vertex rings
(``Calc::get_fragments_from_r`` and ``primitives.cc`` of 2021.01, re-derived below), scipy's
convex hull for hulls, and manifold3d's ``minkowski_sum`` of the same polyhedra for sums.
"""

from __future__ import annotations

import math
import shutil
import warnings
from pathlib import Path

import manifold3d
import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.spatial import ConvexHull

from isocsg import UnsupportedOpenSCADError, loads_openscad, volume
from isocsg.openscad import OpenSCADPolygonalWarning, lower, parse_csg


def _segments(r: float, fn: float = 0.0, fs: float = 2.0, fa: float = 12.0) -> int:
    if fn > 0:
        return max(int(fn), 3)
    return int(math.ceil(max(min(360.0 / fa, 2 * math.pi * r / fs), 5)))


def _circle(n: int, r: float, z: float) -> np.ndarray:
    t = 2 * math.pi * np.arange(n) / n
    return np.column_stack([r * np.cos(t), r * np.sin(t), np.full(n, z)])


def _sphere(r: float, **fx: float) -> np.ndarray:
    n = _segments(r, **fx)
    rings = (n + 1) // 2
    return np.vstack([_circle(n, r * math.sin(math.pi * (i + 0.5) / rings), r * math.cos(math.pi * (i + 0.5) / rings))
                      for i in range(rings)])


def _cylinder(r: float, h: float, **fx: float) -> np.ndarray:
    n = _segments(r, **fx)
    return np.vstack([_circle(n, r, 0.0), _circle(n, r, h)])


def _fx(fn: float, fa: float, fs: float) -> str:
    return f"$fn = {fn}, $fa = {fa}, $fs = {fs}"


def _hull_csg(at: tuple[float, float, float], rs: float, rc: float, h: float, fn: float, fa: float, fs: float) -> str:
    return (f"hull() {{ multmatrix([[1, 0, 0, {at[0]}], [0, 1, 0, {at[1]}], [0, 0, 1, {at[2]}], [0, 0, 0, 1]]) "
            f"{{ sphere(r = {rs}, {_fx(fn, fa, fs)}); }} "
            f"cylinder(h = {h}, r1 = {rc}, r2 = {rc}, center = false, {_fx(fn, fa, fs)}); }}")


def _load(text: str) -> object:
    return lower(parse_csg(text), polygonal=True)


def test_default_refuses_naming_the_node() -> None:
    text = "group() {\n" + _hull_csg((10, 0, 0), 3, 2, 8, 0, 12, 2) + "\n}"
    with pytest.raises(UnsupportedOpenSCADError, match=r"line 2: hull\(\) is not supported"):
        loads_openscad(text)


def test_hull_of_a_sphere_and_a_cylinder_is_openscads_polyhedron() -> None:
    model = _load(_hull_csg((10, 0, 0), 3, 2, 8, 0, 12, 2))
    want = ConvexHull(np.vstack([_sphere(3) + (10, 0, 0), _cylinder(2, 8)])).volume
    assert abs(volume(model.solid) - want) <= 1e-9 * want  # type: ignore[attr-defined]
    assert len(model.polygonal) == 1 and "hull()" in model.polygonal[0]  # type: ignore[attr-defined]


def test_load_openscad_warns_with_the_nodes() -> None:
    with warnings.catch_warnings(record=True) as got:
        warnings.simplefilter("always")
        loads_openscad(_hull_csg((10, 0, 0), 3, 2, 8, 0, 12, 2), polygonal=True)
    assert any(isinstance(w.message, OpenSCADPolygonalWarning) and len(w.message.nodes) == 1 for w in got)


def test_an_exact_hull_stays_exact_with_the_option() -> None:
    text = ("hull() { sphere(r = 2, $fn = 0, $fa = 12, $fs = 2); multmatrix([[1, 0, 0, 5], [0, 1, 0, 0], "
            "[0, 0, 1, 0], [0, 0, 0, 1]]) { sphere(r = 2, $fn = 0, $fa = 12, $fs = 2); } }")
    model = _load(text)
    assert model.polygonal == ()  # type: ignore[attr-defined]
    want = math.pi * 4 * 5 + 4 / 3 * math.pi * 8  # a capsule: the exact round solid
    assert abs(volume(model.solid, tol=1e-6) - want) < 1e-5 * want  # type: ignore[attr-defined]


def _manifold_sum(a: manifold3d.Manifold, b_points: np.ndarray) -> float:
    return float(a.minkowski_sum(manifold3d.Manifold.hull_points(b_points)).volume())


def _plate_csg(size: tuple[float, float, float], hole: float, fn_hole: int, ball: float, fn_ball: int) -> str:
    sx, sy, sz = size
    return (f"minkowski() {{ difference() {{ cube(size = [{sx}, {sy}, {sz}], center = false); "
            f"multmatrix([[1, 0, 0, {sx / 2}], [0, 1, 0, {sy / 2}], [0, 0, 1, -1], [0, 0, 0, 1]]) "
            f"{{ cylinder(h = {sz + 2}, r1 = {hole}, r2 = {hole}, center = false, $fn = {fn_hole}, $fa = 12, "
            f"$fs = 2); }} }} sphere(r = {ball}, $fn = {fn_ball}, $fa = 12, $fs = 2); }}")


def _plate_manifold(size: tuple[float, float, float], hole: float, fn_hole: int) -> manifold3d.Manifold:
    sx, sy, sz = size
    box = manifold3d.Manifold.cube(size)
    bore = manifold3d.Manifold.hull_points(_cylinder(hole, sz + 2, fn=fn_hole) + (sx / 2, sy / 2, -1))
    return box - bore


def test_minkowski_of_a_plate_with_a_hole_and_a_ball() -> None:
    model = _load(_plate_csg((10, 8, 3), 2, 12, 1, 10))
    want = _manifold_sum(_plate_manifold((10, 8, 3), 2, 12), _sphere(1, fn=10))
    assert abs(volume(model.solid) - want) <= 1e-6 * want  # type: ignore[attr-defined]


def test_minkowski_under_a_map_takes_the_shift_back_once() -> None:
    plate = _plate_csg((10, 8, 3), 2, 12, 1, 10)
    moved = _load(f"multmatrix([[1, 0, 0, 40], [0, 1, 0, 5], [0, 0, 1, 2], [0, 0, 0, 1]]) {{ {plate} }}")
    here = _load(plate)
    lo = np.asarray(moved.solid.bounds)[0] - np.asarray(here.solid.bounds)[0]  # type: ignore[attr-defined]
    assert np.allclose(lo, (40, 5, 2))


def test_two_non_convex_flat_children_sum_exactly() -> None:
    """Two L-shaped prisms (a cube with a corner cut through): flat-faced, so each sums through its
    convex pieces, by default (isocsg.csg.flat_pieces). By hand: L = [1,4]x[0,4] u [0,1]x[1,4] (x 4
    high); the pairs' sums [2,8]x[0,8], [1,5]x[1,8], [0,2]x[2,8] cover 48 + 7 + 6 = 61, 8 high."""
    plate = "difference() { cube(size = [4, 4, 4], center = false); cube(size = [2, 2, 9], center = true); }"
    model = lower(parse_csg(f"minkowski() {{ {plate} {plate} }}"))
    assert volume(model.solid) == pytest.approx(61 * 8, rel=1e-9)  # type: ignore[attr-defined]


@settings(max_examples=4, deadline=None)
@given(
    at=st.tuples(*[st.floats(-12, 12) for _ in range(3)]),
    rs=st.floats(0.5, 6), rc=st.floats(0.5, 6), h=st.floats(0.5, 15),
    fn=st.sampled_from([0, 5, 8, 13, 30]), fa=st.sampled_from([6, 12, 30]), fs=st.sampled_from([0.5, 2, 5]),
)
def test_random_hulls_match_scipy(at: tuple[float, float, float], rs: float, rc: float, h: float, fn: int,
                                  fa: float, fs: float) -> None:
    assume(math.hypot(at[0], at[1]) > 0.05)  # off the cylinder's axis: no exact form
    model = _load(_hull_csg(at, rs, rc, h, fn, fa, fs))
    assert model.polygonal or fn > 0  # type: ignore[attr-defined]  # an explicit $fn: OpenSCAD's polyhedra already
    fx = {"fn": fn, "fa": fa, "fs": fs}
    want = ConvexHull(np.vstack([_sphere(rs, **fx) + np.array(at), _cylinder(rc, h, **fx)])).volume
    assert abs(volume(model.solid) - want) <= 1e-8 * want  # type: ignore[attr-defined]


@settings(max_examples=4, deadline=None)
@given(
    size=st.tuples(st.floats(4, 12), st.floats(4, 12), st.floats(1, 5)),
    hole=st.floats(0.3, 1.8), fn_hole=st.integers(3, 16), ball=st.floats(0.2, 2), fn_ball=st.integers(3, 12),
)
def test_random_sums_match_manifold(size: tuple[float, float, float], hole: float, fn_hole: int, ball: float,
                                    fn_ball: int) -> None:
    model = _load(_plate_csg(size, hole, fn_hole, ball, fn_ball))
    want = _manifold_sum(_plate_manifold(size, hole, fn_hole), _sphere(ball, fn=fn_ball))
    assert abs(volume(model.solid) - want) <= 1e-6 * want  # type: ignore[attr-defined]


def test_an_unset_colour_leaves_the_leaf_uncoloured() -> None:
    """OpenSCAD exports ``color(undef)`` or an unknown colour name as ``[-1, -1, -1, 1]``."""
    model = lower(parse_csg("color([-1, -1, -1, 1]) { cube(size = [1, 2, 3], center = false); }"))
    assert abs(volume(model.solid) - 6.0) < 1e-12  # type: ignore[attr-defined]
    assert model.leaf_colors == ()  # type: ignore[attr-defined]


def test_a_scaled_torus_is_openscads_faceted_solid() -> None:
    """``scale([1, 1, 0.5]) rotate_extrude() translate([10, 0]) circle(3)``: refused by default (no
    squashed torus kind); with the option, OpenSCAD's 30 sections of its 10-gon, scaled."""
    text = ("multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0.5, 0], [0, 0, 0, 1]]) { rotate_extrude(angle = 360, "
            "convexity = 2, $fn = 0, $fa = 12, $fs = 2) { multmatrix([[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], "
            "[0, 0, 0, 1]]) { circle(r = 3, $fn = 0, $fa = 12, $fs = 2); } } }")
    with pytest.raises(Exception, match="rotate_extrude"):
        lower(parse_csg(text))
    model = _load(text)
    # each of the 30 sections is the hull of the 10-gon turned by 12 degrees: a closed-form sum of
    # prismatoids; checked here by scipy's hull of each section's 20 points
    profile = np.column_stack([10 + 3 * np.cos(2 * np.pi * np.arange(10) / 10), 3 * np.sin(2 * np.pi * np.arange(10) / 10)])
    want = 0.0
    for k in range(30):
        pts = []
        for a in (2 * np.pi * k / 30, 2 * np.pi * (k + 1) / 30):
            pts.append(np.column_stack([profile[:, 0] * np.cos(a), profile[:, 0] * np.sin(a), 0.5 * profile[:, 1]]))
        want += ConvexHull(np.vstack(pts)).volume
    assert abs(volume(model.solid) - want) <= 1e-9 * want  # type: ignore[attr-defined]
    assert "rotate_extrude()" in model.polygonal[0]  # type: ignore[attr-defined]


def test_pieces_of_a_small_dented_edge_on_a_large_outline_are_convex() -> None:
    """A 60-wide region whose top is a chain of 0.2-long edges dented by 1e-6 (turns of 1e-5 rad),
    joined by a thin corridor to a 1000-wide plate (an SVG drawing's outline did this): the merged
    convex pieces are convex at their own size, and their areas add up to shapely's."""
    from shapely.geometry import Polygon

    from isocsg.shapes2d import area
    from isocsg.shapes2d.region import shape_from_region

    xs = np.linspace(60, 0, 301)
    ys = 10 + np.where(np.arange(301) % 2 == 1, -1e-6, 0.0)
    ring = [(0, 0), (100, 0), (100, -1000), (1100, -1000), (1100, 1000), (100, 1000), (100, 0.5), (60, 0.5)]
    poly = Polygon(ring + list(zip(xs.tolist(), ys.tolist())))
    assert poly.is_valid
    shape = shape_from_region(poly)  # raised "must be convex" before
    assert abs(area(shape) - poly.area) <= 1e-12 * poly.area


@settings(max_examples=4, deadline=None)
@given(a=st.floats(0.5, 30), b=st.floats(0.5, 30), r=st.floats(0.2, 8), fn=st.sampled_from([0, 3, 6, 7, 24]),
       h=st.floats(0.5, 10))
def test_a_2d_sum_of_a_rectangle_and_a_circle(a: float, b: float, r: float, fn: int, h: float) -> None:
    """``linear_extrude(h) minkowski() { square([a, b]); circle(r); }``: exact by default (the disc
    Steiner's ``ab + 2 (a + b) r + pi r^2``; with an explicit ``$fn`` OpenSCAD's polygon ``P`` of the
    circle, ``ab + a w_y + b w_x + area(P)`` with its widths ``w_x``, ``w_y`` along the axes), and the
    same with the option (an exact node stays exact)."""
    text = (f"linear_extrude(height = {h}, center = false, convexity = 1, scale = [1, 1], $fn = {fn}, $fa = 12, "
            f"$fs = 2) {{ minkowski(convexity = 0) {{ square(size = [{a}, {b}], center = false); "
            f"circle(r = {r}, $fn = {fn}, $fa = 12, $fs = 2); }} }}")
    if fn == 0:
        want = h * (a * b + 2 * (a + b) * r + math.pi * r * r)
    else:
        ring = _circle(_segments(r, fn=fn), r, 0.0)[:, :2]
        wx, wy = np.ptp(ring, axis=0)
        n = len(ring)
        want = h * (a * b + a * wy + b * wx + n * r * r * math.sin(2 * math.pi / n) / 2)
    for model in (lower(parse_csg(text)), _load(text)):
        assert abs(volume(model.solid) - want) <= 1e-6 * want  # type: ignore[attr-defined]
        assert not model.polygonal  # type: ignore[attr-defined]


def test_a_face_with_a_point_repeated_in_turn_has_no_area() -> None:
    """OpenSCAD's export of generated polyhedra has faces such as ``[4, 7, 4]``: no area, dropped;
    the L-shaped prism (non-convex: a mesh) keeps its volume."""
    pts = [[0, 0, 0], [2, 0, 0], [2, 1, 0], [1, 1, 0], [1, 2, 0], [0, 2, 0]]
    pts += [[x, y, 1] for x, y, _ in pts]
    bottom, top = [0, 1, 2, 3, 4, 5], [11, 10, 9, 8, 7, 6]  # clockwise seen from outside
    sides = [[k, k + 6, (k + 1) % 6 + 6, (k + 1) % 6] for k in range(6)]
    faces = [bottom, top, *sides, [4, 7, 4], [3, 3, 9, 9]]
    text = f"polyhedron(points = {pts}, faces = {faces}, convexity = 1);"
    assert abs(volume(lower(parse_csg(text)).solid) - 3.0) < 1e-12  # type: ignore[attr-defined]


@pytest.mark.skipif(shutil.which("openscad") is None, reason="the openscad program is not installed")
def test_preview_is_false_as_in_a_render(tmp_path: Path) -> None:
    """OpenSCAD's ``.csg`` export runs with ``$preview`` true, its STL export (a render) false; the
    model read is the rendered one (a real model cut itself in half ``if ($preview)``)."""
    from isocsg.openscad import read_openscad

    scad = tmp_path / "m.scad"
    scad.write_text("if ($preview) cube(1); else sphere(1);\n")
    solid = read_openscad(scad).solid
    assert abs(volume(solid, tol=1e-6) - 4 / 3 * math.pi) < 1e-5


@pytest.mark.skipif(shutil.which("openscad") is None, reason="the openscad program is not installed")
def test_preview_is_still_true_in_top_level_assignments(tmp_path: Path) -> None:
    """``-D '$preview=false'`` is applied after the file's own top-level assignments are
    evaluated (OpenSCAD 2021.01): ``x = $preview ? 1 : 2`` is 1 and ``$fn = $preview ? 32 : 128``
    is 32, while an ``if ($preview)`` among the statements sees false (docs/openscad.md)."""
    from isocsg.openscad import read_openscad

    scad = tmp_path / "m.scad"
    scad.write_text("$fn = $preview ? 32 : 128;\nx = $preview ? 1 : 2;\ncube(x);\nif ($preview) sphere(5);\n")
    solid = read_openscad(scad).solid
    assert abs(volume(solid, tol=1e-9) - 1.0) < 1e-9  # the cube of 1, no sphere of 5

