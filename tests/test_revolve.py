"""``rotate_extrude``: exact solids of revolution, judged by references written here.

- volumes against Pappus's theorem, ``V = angle * integral of x dA`` (shapely's area and
  centroid of the profile), for hypothesis-drawn non-convex polygons with holes, circles and
  their Booleans, full and partial turns;
- membership against the definition: a point is inside iff ``(sqrt(x^2 + y^2), z)`` is in the
  profile (shapely) and its polar angle is within the turn (points near either boundary skipped);
- OpenSCAD's faceted revolution against its closed form: ``n`` sections of ``delta`` degrees of
  a profile hold ``n sin(delta) integral of x dA``;
- OpenSCAD's conventions (the sign of the angle, the start, a profile on the side x < 0) and the
  errors, each naming its field.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
import shapely
from hypothesis import Phase, given, settings
from hypothesis import strategies as st
from shapely.geometry import Point
from shapely.geometry import Polygon as SPolygon

from isocsg import InvalidGeometryError, Sphere, Torus, rotate_extrude, volume
from isocsg.shapes2d import EMPTY, Ellipse, circle, polygon, square

# ----------------------------------------------------------------------------- references


def _star(cx: float, cy: float, radius: float, angles: list[float], scales: list[float]) -> list[tuple[float, float]]:
    """A star-shaped (usually non-convex) simple polygon about (cx, cy)."""
    phi = np.sort(np.asarray(angles)) * 2 * math.pi
    keep = np.concatenate([[True], np.diff(phi) > 0.05])
    phi = phi[keep]
    r = radius * np.asarray(scales[: len(phi)] + [1.0] * max(0, len(phi) - len(scales)))
    return [(cx + float(a) * math.cos(p), cy + float(a) * math.sin(p)) for a, p in zip(r, phi, strict=True)]


def _pappus(region: shapely.Geometry, angle: float) -> float:
    return math.radians(abs(angle)) * region.area * region.centroid.x


def _polar(points: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    rho = np.hypot(points[:, 0], points[:, 1])
    phi = np.degrees(np.arctan2(points[:, 1], points[:, 0]))
    return rho, points[:, 2], phi


def _in_turn(phi: np.ndarray, start: float, angle: float, margin: float) -> tuple[np.ndarray, np.ndarray]:
    """(inside the turn, clear of its end planes by ``margin`` degrees)."""
    lo = start + min(angle, 0.0)
    rel = np.mod(phi - lo, 360.0)
    span = abs(angle)
    inside = rel <= span
    clear = (np.minimum(np.abs(rel - span), np.minimum(rel, 360.0 - rel)) > margin) | (span >= 360.0)
    return inside | (span >= 360.0), clear


def _check_membership(solid, region, start: float, angle: float, rng: np.random.Generator, n: int = 4000) -> None:
    x0, y0, x1, y1 = region.bounds
    lo, span = start + min(angle, 0.0), min(abs(angle) + 40.0, 360.0)
    phi = np.radians(lo - 20.0 + span * rng.random(n))  # around the turn, and past its ends
    r = 1.1 * x1 * np.sqrt(rng.random(n))
    pts = np.column_stack([r * np.cos(phi), r * np.sin(phi), rng.uniform(y0 - 0.1, y1 + 0.1, n)])
    rho, z, phi = _polar(pts)
    meridian = shapely.points(rho, z)
    in_profile = shapely.contains_xy(region, rho, z)
    size = max(x1 - x0, y1 - y0)
    clear = shapely.distance(region.boundary, meridian) > 1e-3 * size
    in_turn, turn_clear = _in_turn(phi, start, angle, 0.05)
    # near the axis a small angle margin is a tiny distance: keep points whose distance to the end planes is clear too
    plane_clear = turn_clear & (rho * np.sin(np.radians(0.05)) > 1e-6)
    want = in_profile & in_turn
    keep = clear & (plane_clear | ~in_profile | (abs(angle) >= 360.0))
    got = np.asarray(solid.contains(pts[keep]))
    bad = np.flatnonzero(got != want[keep])
    assert len(bad) == 0, (len(bad), pts[keep][bad[:5]], want[keep][bad[:5]])
    assert want[keep].sum() > 20  # the test saw the inside too


# ----------------------------------------------------------------------------- strategies

QUICK = (Phase.explicit, Phase.reuse, Phase.generate, Phase.shrink)  # no slow "explain" phase
coords = st.floats(0.05, 0.95)
profiles = st.fixed_dictionaries({
    "cx": st.floats(2.0, 6.0), "cy": st.floats(-3.0, 3.0), "radius": st.floats(0.5, 1.9),
    "angles": st.lists(coords, min_size=5, max_size=11, unique=True),
    "scales": st.lists(st.floats(0.35, 1.0), min_size=11, max_size=11),
    "hole": st.floats(0.0, 0.3),
})
angles = st.sampled_from([360.0, -360.0, 90.0, -45.0, 180.0, 200.0, -300.0, 17.5])


def _profile(d: dict, *, round_hole: bool = False) -> tuple:
    pts = _star(d["cx"], d["cy"], d["radius"], d["angles"], d["scales"])
    shape, region = polygon(pts), SPolygon(pts)
    r = d["hole"] * d["radius"]
    if r > 0.05 * d["radius"]:  # a hole about the centre (kept only where the star holds it)
        if round_hole:
            hole_shape, hole = circle(r).translate([d["cx"], d["cy"]]), Point(d["cx"], d["cy"]).buffer(r, quad_segs=4096)
        else:
            ring = _star(d["cx"], d["cy"], r, [0.1, 0.3, 0.45, 0.7, 0.9], [1.0, 0.6, 1.0, 0.8, 1.0])
            hole_shape, hole = polygon(ring), SPolygon(ring)
        if region.contains(hole):
            shape, region = shape - hole_shape, region.difference(hole)
    return shape, region


@settings(max_examples=5, deadline=None, phases=QUICK)
@given(profiles, angles)
def test_volume_is_pappus(d: dict, angle: float) -> None:
    shape, region = _profile(d)
    solid = rotate_extrude(shape, angle)
    assert volume(solid, tol=1e-8) == pytest.approx(_pappus(region, angle), rel=1e-8)


@settings(max_examples=12, deadline=None, phases=QUICK)
@given(profiles, angles, st.floats(-180.0, 180.0), st.integers(0, 2**31))
def test_membership_matches_the_definition(d: dict, angle: float, start: float, seed: int) -> None:
    shape, region = _profile(d, round_hole=True)
    solid = rotate_extrude(shape, angle, start=start)
    s = start if abs(angle) < 360 else 0.0
    _check_membership(solid, region, s, angle, np.random.default_rng(seed))


def test_booleans_of_circles_and_polygons() -> None:
    # a disc with a square notch, unioned with a triangle that crosses it, minus a disc
    shape = (circle(2).translate([6, 0]) - square(1.5).translate([6.5, -0.75])) | polygon([(3, -3), (8, -2), (4, 3)])
    shape = shape - circle(0.6).translate([4.5, -1.5])
    region = Point(6, 0).buffer(2, quad_segs=1024).difference(SPolygon([(6.5, -0.75), (8, -0.75), (8, 0.75), (6.5, 0.75)]))
    region = region.union(SPolygon([(3, -3), (8, -2), (4, 3)])).difference(Point(4.5, -1.5).buffer(0.6, quad_segs=1024))
    for angle in (360.0, 135.0, -250.0):
        solid = rotate_extrude(shape, angle)
        _check_membership(solid, region, 0.0, angle, np.random.default_rng(7))
    # (volumes of trees with tori are integrated over sections: one turn, to keep the test fast)
    assert volume(solid, tol=1e-6) == pytest.approx(_pappus(region, -250.0), rel=2e-6)


def test_circle_clear_of_the_axis_is_a_torus_and_on_it_a_sphere() -> None:
    t = rotate_extrude(circle(1.5).translate([4, 2]))
    assert t == Torus((0, 0, 2), (0, 0, 1), 4.0, 1.5)
    assert volume(t) == pytest.approx(2 * math.pi**2 * 4 * 1.5**2, rel=1e-12)
    half = rotate_extrude(circle(3).translate([0, 1]) & square([3, 8]).translate([0, -4]))
    assert Sphere((0, 0, 1), 3.0) in half.children
    assert volume(half) == pytest.approx(4 / 3 * math.pi * 27, rel=1e-9)
    spheroid = rotate_extrude(Ellipse((0, 0), ((2, 0), (0, 5))) & square(10).translate([0, -5]))
    assert volume(spheroid) == pytest.approx(4 / 3 * math.pi * 2 * 2 * 5, rel=1e-9)


def test_convex_pieces_touching_the_axis() -> None:
    cone = rotate_extrude(polygon([(0, 0), (3, 0), (0, 4)]))
    assert volume(cone) == pytest.approx(math.pi * 9 * 4 / 3, rel=1e-12)
    cup = [(0, 0), (6, 0), (6, 6), (5, 6), (5, 1), (0, 1)]
    solid = rotate_extrude(polygon(cup))
    assert volume(solid) == pytest.approx(_pappus(SPolygon(cup), 360), rel=1e-9)
    _check_membership(solid, SPolygon(cup), 0.0, 360.0, np.random.default_rng(3))


# ----------------------------------------------------------------------------- OpenSCAD's conventions


def test_angle_sign_start_and_the_side_x_below_zero() -> None:
    box = square([1, 1]).translate([4, 0])
    # positive angles turn counter-clockwise from start; negative clockwise
    ccw = rotate_extrude(box, 90)
    assert ccw.contains([[3 * math.cos(0.7), 3 * math.sin(0.7), 0.5]]).tolist() == [False]
    assert ccw.contains([[4.5 * math.cos(0.7), 4.5 * math.sin(0.7), 0.5]]).tolist() == [True]
    cw = rotate_extrude(box, -90)
    assert cw.contains([[4.5 * math.cos(-0.7), 4.5 * math.sin(-0.7), 0.5]]).tolist() == [True]
    assert cw.contains([[4.5 * math.cos(0.7), 4.5 * math.sin(0.7), 0.5]]).tolist() == [False]
    turned = rotate_extrude(box, 90, start=90)
    assert turned.contains([[4.5 * math.cos(2.3), 4.5 * math.sin(2.3), 0.5]]).tolist() == [True]
    # OpenSCAD maps (x, y) to (x cos a, x sin a, y): a profile at x < 0 shows on the far side
    left = rotate_extrude(box.mirror([1, 0]), 60)
    p = 4.5 * np.array([math.cos(math.pi + 0.5), math.sin(math.pi + 0.5)])
    assert left.contains([[p[0], p[1], 0.5]]).tolist() == [True]
    assert left.contains([[-p[0], -p[1], 0.5]]).tolist() == [False]


@pytest.mark.parametrize("segments, angle", [(3, 360.0), (6, 360.0), (4, 200.0), (7, -90.0), (1, 120.0), (2, 300.0)])
def test_faceted_sections_hold_their_closed_form(segments: int, angle: float) -> None:
    pts = [(2, 0), (5, -1), (6, 2), (3, 1.5), (4, 4), (1, 3)]  # non-convex
    region = SPolygon(pts)
    solid = rotate_extrude(polygon(pts), angle, segments=segments)
    delta = math.radians(angle / segments)
    want = segments * abs(math.sin(delta)) * region.area * region.centroid.x
    assert volume(solid, tol=1e-8) == pytest.approx(want, rel=1e-9)


@pytest.mark.parametrize("segments, angle", [(2, -200.0), (1, 270.0)])
def test_faceted_circles_and_ellipses_hold_their_closed_form(segments: int, angle: float) -> None:
    # a section between meridians a and b is {alpha u_a + beta u_b + y e_z : alpha, beta >= 0,
    # (alpha + beta, y) in the profile}: volume |sin(b - a)| * integral of x dA
    factor = segments * abs(math.sin(math.radians(angle / segments)))
    ring = rotate_extrude(circle(1.5).translate([4, 1]), angle, segments=segments)
    assert volume(ring, tol=1e-7) == pytest.approx(factor * 4 * math.pi * 1.5**2, rel=1e-7)
    half = rotate_extrude(circle(2).translate([0, 1]) & square(4).translate([0, -1]), angle, segments=segments)
    assert volume(half, tol=1e-7) == pytest.approx(factor * 2 * 2**3 / 3, rel=1e-7)  # half disc: 2 r^3 / 3
    e = Ellipse((5, 0), ((1, 0.3), (0.2, 2)))
    assert volume(rotate_extrude(e, angle, segments=segments), tol=1e-7) == pytest.approx(factor * 5 * e.area, rel=1e-7)


def test_faceted_vertices_lie_on_the_meridians() -> None:
    solid = rotate_extrude(square([1, 2]).translate([3, 0]), 90, start=30, segments=3)
    pts = np.vstack([np.asarray(leaf.vertices) for leaf in solid.children])
    phi = np.degrees(np.arctan2(pts[:, 1], pts[:, 0]))
    assert np.allclose(np.sort(np.unique(np.round(phi, 9))), [30, 60, 90, 120])
    assert np.allclose(np.unique(np.round(np.hypot(pts[:, 0], pts[:, 1]), 9)), [3, 4])


# ----------------------------------------------------------------------------- errors

ERRORS = [
    (lambda: rotate_extrude(square(2, center=True).translate([0.5, 0])), "rotate_extrude.shape must lie on one side"),
    (lambda: rotate_extrude(square(1).translate([2, 0]), 0), "rotate_extrude.angle must be non-zero"),
    (lambda: rotate_extrude(square(1).translate([2, 0]), 400), "rotate_extrude.angle must be"),
    (lambda: rotate_extrude(square(1).translate([2, 0]), float("nan")), "rotate_extrude.angle must be"),
    (lambda: rotate_extrude(circle(2).translate([1, 0]) & square(4).translate([0, -2])), "meets the axis off its centre"),
    (lambda: rotate_extrude(circle(1).translate([1, 0])), "meets the axis off its centre"),
    (lambda: rotate_extrude(Ellipse((4, 0), ((1, 0), (0, 2)))), "an ellipse revolves exactly only when centred"),
    (lambda: rotate_extrude(square(1).translate([3, 0]), segments=0), "rotate_extrude.segments must be an integer"),
    (lambda: rotate_extrude(square(1).translate([3, 0]), segments=2.5), "rotate_extrude.segments must be an integer"),
    (lambda: rotate_extrude(EMPTY), "rotate_extrude.shape must not be empty"),
    (lambda: rotate_extrude(square(1).translate([-2, 0]) & square(1).translate([2, 0])), "must not be empty"),
    (lambda: rotate_extrude("square"), "rotate_extrude.shape must be a 2D shape"),
    (lambda: rotate_extrude(square(1).translate([2, 0]), 90, start=float("inf")), "rotate_extrude.start"),
]


@pytest.mark.parametrize("call, message", ERRORS, ids=[m for _, m in ERRORS])
def test_errors_name_the_field(call, message: str) -> None:
    with pytest.raises(InvalidGeometryError, match=re.escape(message)):
        call()


def test_a_profile_touching_the_axis_from_either_side_is_accepted() -> None:
    right = rotate_extrude(square([2, 1]))
    left = rotate_extrude(square([2, 1]).translate([-2, 0]))
    assert volume(right) == pytest.approx(4 * math.pi) and volume(left) == pytest.approx(4 * math.pi)


def test_a_slab_far_thinner_than_its_radius_revolves_exactly() -> None:
    """A vertex 1e-9 above the base at radius 6.5 (a slab of aspect 1.5e-10, refused while frusta
    stopped at 1e-5): the solid's volume is Pappus's, the profile's area times the path of its
    centroid, computed here by shapely."""
    ring = [(5, 0), (6, 0), (6.5, 1e-9), (6, 1), (5, 1)]
    solid = rotate_extrude(polygon(ring))
    profile = shapely.Polygon(ring)
    expected = profile.area * 2 * np.pi * profile.centroid.x
    assert volume(solid, tol=1e-9) == pytest.approx(expected, rel=1e-9)
