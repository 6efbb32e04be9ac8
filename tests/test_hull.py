"""``isocsg.hull``: exact hulls of spheres, cylinders and polytopes, judged independently.

- membership: random points in or out of the exact union against the distance to the hull of
  the centres (or segments), computed by non-negative least squares in
  ``tests/reference/convex_distance.py`` (hypothesis-drawn point sets, radii and maps);
- volumes: Steiner's formula from scipy's hull of the centres; manifold3d's hull of ever finer
  sphere meshes converging to the exact volume (spheres of different radii);
- a render of a hull against the analytic ray caster, and the ray caster's depths of the
  pieces against sphere tracing on the exact distance to a box grown by a ball;
- refusals name what stops them.
"""

from __future__ import annotations

import math
import re
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from isocsg import (
    Box,
    Cone,
    ConvexPolyhedron,
    Cylinder,
    InvalidGeometryError,
    NotExactError,
    PointLight,
    Sphere,
    Torus,
    Truncus,
    Union,
    hull,
    minkowski,
    volume,
)
from isocsg.csg.hull import hull_pieces

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference.convex_distance import ball_grown_volume, hull_distance, slice_distance  # noqa: E402

SETTINGS = settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
RNG_SEED = 20261128


def _points_near(solid_bounds: np.ndarray, n: int, seed: int) -> np.ndarray:
    lo, hi = solid_bounds
    pad = 0.1 * (hi - lo)
    return np.random.default_rng(seed).uniform(lo - pad, hi + pad, size=(n, 3))


def _assert_membership(solid, inside: np.ndarray, xs: np.ndarray, margin: np.ndarray) -> None:
    """``solid.contains`` agrees with the independent ``inside`` wherever the margin is clear."""
    got = solid.contains(xs)
    clear = margin > 1e-6
    assert clear.mean() > 0.9
    bad = np.nonzero((got != inside) & clear)[0]
    assert bad.size == 0, f"{bad.size} of {clear.sum()} points disagree, e.g. {xs[bad[:3]]}"
    assert inside[clear].any() and (~inside[clear]).any()


# ----------------------------------------------------------------------------- equal spheres


def test_rounded_box_from_eight_spheres_has_the_closed_form_volume() -> None:
    a, b, c, r = 2.0, 3.0, 1.5, 0.4
    rounded = hull(*[Sphere((x, y, z), r) for x in (0, a) for y in (0, b) for z in (0, c)])
    pieces = rounded.children
    assert sum(isinstance(p, Sphere) for p in pieces) == 8 and sum(isinstance(p, Cylinder) for p in pieces) == 12
    want = a * b * c + 2 * r * (a * b + b * c + c * a) + math.pi * r * r * (a + b + c) + 4 / 3 * math.pi * r**3
    assert volume(rounded) == pytest.approx(want, rel=1e-4)


def test_steiner_formula_for_a_tetrahedron_of_spheres() -> None:
    centres = np.array([[0.0, 0, 0], [2, 0.3, 0], [0.4, 1.7, 0.2], [0.5, 0.6, 1.9]])
    r = 0.6
    got = volume(hull(*[Sphere(c, r) for c in centres]))
    assert got == pytest.approx(ball_grown_volume(centres, r), rel=1e-4)


@SETTINGS
@given(
    centres=st.lists(st.tuples(*[st.floats(-2, 2)] * 3), min_size=1, max_size=7),
    r=st.floats(0.1, 1.5),
    seed=st.integers(0, 2**16),
)
def test_hull_of_equal_spheres_is_the_grown_hull_of_centres(centres, r: float, seed: int) -> None:
    c = np.array(centres)
    solid = hull(*[Sphere(p, r) for p in c])
    xs = _points_near(solid.bounds, 400, seed)
    dist = hull_distance(c, xs)
    _assert_membership(solid, dist <= r, xs, np.abs(dist - r))


@pytest.mark.parametrize(
    "centres",
    [
        [[0.0, 0, 0]] * 3,  # one point: a sphere
        [[0, 0, 0], [1, 1, 1], [3, 3, 3]],  # a segment: a capsule
        [[0, 0, 0], [2, 0, 0], [0, 1.5, 0], [1, 0.5, 0]],  # a polygon: a slab, cylinders, spheres
    ],
    ids=["point", "segment", "polygon"],
)
def test_flat_and_degenerate_centres(centres) -> None:
    c = np.array(centres, dtype=float)
    r = 0.5
    solid = hull(*[Sphere(p, r) for p in c])
    xs = _points_near(solid.bounds, 1500, RNG_SEED)
    dist = hull_distance(c, xs)
    _assert_membership(solid, dist <= r, xs, np.abs(dist - r))
    if len({tuple(p) for p in c}) == 1:
        assert solid == Sphere(c[0], r)


@SETTINGS
@given(
    shear=st.lists(st.floats(-0.45, 0.45), min_size=9, max_size=9),
    centres=st.lists(st.tuples(*[st.floats(-2, 2)] * 3), min_size=1, max_size=5),
    seed=st.integers(0, 2**16),
)
def test_spheres_under_one_map_hull_through_the_map(shear, centres, seed) -> None:
    """Spheres mapped by one affine map are ellipsoids of one shape; their hull is the map of the hull."""
    A = np.eye(3) + np.array(shear).reshape(3, 3)
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = A, (0.3, -0.7, 1.1)
    c = np.array(centres)
    solid = hull(*[Sphere(p, 0.8).transform(m) for p in c])
    xs = _points_near(solid.bounds, 300, seed)
    local = np.linalg.solve(A, (xs - m[:3, 3]).T).T  # back to the spheres' frame
    dist = hull_distance(c, local)
    _assert_membership(solid, dist <= 0.8, xs, np.abs(dist - 0.8) * 0.3)


# ----------------------------------------------------------------------------- parallel cylinders


@SETTINGS
@given(
    feet=st.lists(st.tuples(*[st.floats(-2, 2)] * 3), min_size=1, max_size=5),
    heights=st.lists(st.floats(0.2, 2.0), min_size=5, max_size=5),
    axis=st.tuples(st.floats(-1, 1), st.floats(-1, 1), st.floats(0.3, 1)),
    r=st.floats(0.1, 1.0),
    seed=st.integers(0, 2**16),
)
def test_hull_of_parallel_cylinders_is_the_hull_of_segments_grown_by_the_disc(feet, heights, axis, r, seed) -> None:
    a = np.array(axis) / np.linalg.norm(axis)
    feet_a = np.array(feet)
    ends = [(f, f + h * a) for f, h in zip(feet_a, heights)]
    solid = hull(*[Cylinder((p + q) / 2, q - p, r) for p, q in ends])
    xs = _points_near(solid.bounds, 300, seed)
    dist = slice_distance(np.vstack([np.array(e) for e in ends]), a, xs)
    _assert_membership(solid, dist <= r, xs, np.abs(dist - r))


def test_hull_of_four_cylinders_is_a_rounded_plate() -> None:
    w, d, h, r = 30.0, 18.0, 4.0, 3.0
    plate = hull(*[Cylinder((x, y, h / 2), (0, 0, h), r) for x in (0, w) for y in (0, d)])
    assert volume(plate) == pytest.approx(h * (w * d + 2 * r * (w + d) + math.pi * r * r), rel=1e-4)


# ----------------------------------------------------------------------------- spheres of different radii


def _manifold_hull_volume(spheres: list[tuple[np.ndarray, float]], n: int) -> float:
    import manifold3d

    meshes = [manifold3d.Manifold.sphere(r, n).translate(tuple(c)) for c, r in spheres]
    return float(manifold3d.Manifold.batch_hull(meshes).volume())


@pytest.mark.parametrize(
    "spheres",
    [
        [((0, 0, 0), 1.0), ((3, 1, 0.5), 0.4)],
        [((0, 0, 0), 3.0), ((4, 0, 0), 0.5), ((6, 0, 0), 1.0), ((10, 0, 0), 2.5)],
        [((0, 0, 0), 1.0), ((0.2, 0, 0), 0.5)],  # one inside the other
    ],
    ids=["two", "on_a_line", "nested"],
)
def test_spheres_of_different_radii_converge_with_manifold3d(spheres) -> None:
    s = [(np.array(c, dtype=float), r) for c, r in spheres]
    exact = volume(hull(*[Sphere(c, r) for c, r in s]))
    meshes = [_manifold_hull_volume(s, n) for n in (32, 96, 288)]
    gaps = [abs(v / exact - 1) for v in meshes]
    assert gaps[0] > gaps[1] > gaps[2] and gaps[2] < 1e-3, gaps
    # the mesh's error falls as 1 / n^2: extrapolated, it meets the exact volume
    extrapolated = meshes[2] + (meshes[2] - meshes[1]) / 8
    assert extrapolated == pytest.approx(exact, rel=5e-5)


def test_spheres_on_a_line_leave_the_inner_one_out() -> None:
    solid = hull(Sphere((0, 0, 0), 3), Sphere((4, 0, 0), 0.5), Sphere((6, 0, 0), 1), Sphere((10, 0, 0), 2.5))
    radii = sorted(p.radius for p in solid.children if isinstance(p, Sphere))
    assert radii == [2.5, 3.0]  # the others are inside the tangent cone


# ----------------------------------------------------------------------------- coaxial cylinders, cones, frusta


def _envelope(s_pts: np.ndarray, r_pts: np.ndarray, s: np.ndarray) -> np.ndarray:
    """The concave envelope of the points (s_i, r_i) at s: the best chord over every pair."""
    out = np.full(len(s), -np.inf)
    for i in range(len(s_pts)):
        for j in range(len(s_pts)):
            if s_pts[j] > s_pts[i]:
                w = (s - s_pts[i]) / (s_pts[j] - s_pts[i])
                on = (w >= 0) & (w <= 1)
                out[on] = np.maximum(out[on], (1 - w[on]) * r_pts[i] + w[on] * r_pts[j])
            elif s_pts[j] == s_pts[i]:
                out[s == s_pts[i]] = np.maximum(out[s == s_pts[i]], max(r_pts[i], r_pts[j]))
    return out


@SETTINGS
@given(
    spans=st.lists(st.tuples(st.floats(-3, 3), st.floats(0.2, 2), st.floats(0.05, 2), st.just(0.0) | st.floats(0.05, 2)),
                   min_size=1, max_size=4),
    axis=st.tuples(st.floats(-1, 1), st.floats(-1, 1), st.floats(0.2, 1)),
    seed=st.integers(0, 2**16),
)
def test_hull_of_coaxial_trunci_is_the_revolved_envelope(spans, axis, seed) -> None:
    a = np.array(axis) / np.linalg.norm(axis)
    origin = np.array([0.5, -0.3, 0.2])
    trunci = [Truncus(origin + (s0 + h / 2) * a, h * a, r1, r2) for s0, h, r1, r2 in spans]
    solid = hull(*trunci)
    s_pts = np.array([v for s0, h, _, _ in spans for v in (s0 + h, s0)])
    r_pts = np.array([v for t in trunci for v in (t.r1, t.r2)])
    xs = _points_near(solid.bounds, 600, seed)
    s = (xs - origin) @ a
    rho = np.linalg.norm(xs - origin - s[:, None] * a, axis=1)
    limit = _envelope(s_pts, r_pts, s)
    margin = np.minimum(np.abs(rho - limit), np.minimum(np.abs(s - s_pts.min()), np.abs(s - s_pts.max())))
    _assert_membership(solid, rho <= limit, xs, np.where(np.isfinite(margin), margin, 1.0))


def test_ends_at_one_position_to_rounding_keep_the_widest() -> None:
    """A cone's apex and a cylinder's end at one position (to rounding): the cylinder's rim counts."""
    a = np.array([0.0, 1.0, 0.5]) / math.sqrt(1.25)
    origin = np.array([0.5, -0.3, 0.2])
    solid = hull(Truncus(origin + 0.25 * a, 0.5 * a, 1.0, 0.0), Cylinder(origin + a, 2 * a, 1.0))
    assert isinstance(solid, Cylinder) and solid.radius == 1.0
    assert np.allclose(solid.end_centers, [origin + 2 * a, origin], atol=1e-12)


def test_hull_of_a_cylinder_and_a_coaxial_cone_is_a_cylinder_and_a_frustum() -> None:
    solid = hull(Cylinder((0, 0, 0.5), (0, 0, 1), 2), Cylinder((0, 0, 3), (0, 0, 1), 1))
    assert sorted(type(p).__name__ for p in solid.children) == ["Cylinder", "Truncus"]
    assert volume(solid) == pytest.approx(4 * math.pi + math.pi / 3 * 2.5 * (4 + 2 + 1), rel=1e-6)


# ----------------------------------------------------------------------------- polytopes, errors


def test_hull_of_boxes_is_one_polyhedron() -> None:
    solid = hull(Box((0, 0, 0), (1, 1, 1)), Box((3, 0, 0), (1, 1, 1)))
    assert isinstance(solid, ConvexPolyhedron) and solid.volume == pytest.approx(4.0, rel=1e-14)


@pytest.mark.parametrize(
    "solids, message",
    [
        ((Sphere((0, 0, 0), 1), Cylinder((2, 0, 0), (0, 0, 1), 0.5)),
         "hull: a hull of Cylinder, Sphere of different shapes or directions is not an exact union of isocsg kinds"),
        ((Cylinder((0, 0, 0), (0, 0, 1), 1), Cylinder((3, 0, 0.5), (0, 1, 1), 0.5)),
         "hull: a hull of Cylinder of different shapes or directions is not an exact union"),
        ((Cylinder((0, 0, 0), (0, 0, 1), 1), Cylinder((3, 0, 0), (0, 1, 0), 1)),
         "hull: a hull of Cylinder of different shapes or directions is not an exact union"),
        ((Cone((0, 0, 0), (0, 0, 1), 1), Cone((3, 0, 0), (0, 1, 0), 1)), "hull: a hull of a cone or frustum is not an exact union"),
        ((Torus((0, 0, 0), (0, 0, 1), 2, 0.5),), "hull: a hull of a Torus is not an exact union"),
        ((Box((0, 0, 0), (2, 2, 2)) - Sphere((1, 1, 1), 1),), "hull: a hull of a difference is not supported"),
    ],
    ids=["sphere_cylinder", "unequal_cylinders_crossed", "crossed_cylinders", "cone", "torus", "difference"],
)
def test_refusals_name_what_stops_them(solids, message: str) -> None:
    with pytest.raises(NotExactError, match=re.escape(message)):
        hull(*solids)


def test_no_operand_is_refused_and_a_union_is_its_leaves() -> None:
    with pytest.raises(InvalidGeometryError, match="hull: needs at least one solid"):
        hull()
    assert len(hull_pieces(Union(Box((0, 0, 0), (1, 1, 1)), Box((3, 0, 0), (1, 1, 1))))) == 1


def test_flat_polygons_hull_to_nothing() -> None:
    from isocsg.csg.hull_grow import grow_disc

    square = np.array([[0.0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]])
    assert grow_disc(square, np.array([0.0, 0, 1]), 0.5) == []  # a disc in the square's plane: flat
    assert len(grow_disc(square, np.array([1.0, 0, 0]), 0.5)) > 1  # across it: a slab and cylinders


# ----------------------------------------------------------------------------- rays and renders


def _box_distance(c: np.ndarray, half: np.ndarray, p: np.ndarray) -> np.ndarray:
    q = np.abs(p - c) - half
    return np.linalg.norm(np.maximum(q, 0), axis=-1) + np.minimum(q.max(axis=-1), 0)


def test_reference_ray_depths_match_sphere_tracing_of_the_grown_box() -> None:
    from reference import camera_rays, raycast

    from isocsg import Camera, Material

    c, half, r = np.array([0.2, -0.1, 0.3]), np.array([1.0, 0.6, 0.4]), 0.35
    corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)
    solid = hull(*[Sphere(c + half * s, r) for s in corners])
    cam = Camera((3.5, -4.0, 2.5), tuple(c), width=48, height=40)
    ref = raycast(cam, [(solid, Material())], [PointLight((4, -3, 5))])
    origins, dirs = camera_rays(cam)
    o, d = origins.reshape(-1, 3), dirs.reshape(-1, 3)
    t = np.zeros(len(d))
    for _ in range(400):  # sphere tracing on the exact distance (1-Lipschitz): no surface stepped over
        step = _box_distance(c, half, o + t[:, None] * d) - r
        t += np.where(step > 1e-12, step, 0.0)
    hit = (_box_distance(c, half, o + t[:, None] * d) - r) < 1e-9
    depth = ref.depth.reshape(-1)
    assert np.array_equal(np.isfinite(depth), hit)
    assert np.abs(depth[hit] - t[hit]).max() < 1e-8


@pytest.mark.parametrize(
    "solid",
    [
        hull(Sphere((0, 0, 0), 0.9), Sphere((1.8, 0.4, 0.3), 0.5)),
        minkowski(Box((0.9, 0.2, 0.15), (2, 1.4, 1)), Cylinder((0, 0, 0), (0.3, 0.2, 0.5), 0.3)),
    ],
    ids=["two_spheres", "box_plus_tilted_cylinder"],
)
def test_a_hull_renders_like_the_reference(solid) -> None:
    from reference import compare, raycast_scene
    from scenes import make_scene, render_image

    scene = make_scene((2.5, -4.5, 2.5), [solid], [PointLight((3, -4, 5))], target=(0.9, 0.2, 0.15), size=96)
    result = compare(render_image(scene), raycast_scene(scene))
    assert result.iou >= 0.99 and result.fraction >= 0.98, result.summary()
