"""Hulls of balls of different radii (and polytopes' corners, balls of radius 0), judged independently.

- membership against certificates (``tests/reference/ball_hull.py``): convex weights ``w`` with
  ``|x - sum w c| - sum w r < 0`` prove a point inside, a direction ``u`` with
  ``u . x > max_k (c_k . u + r_k)`` proves it outside; hypothesis draws 2-8 balls of random
  radii, with corners (radius 0), equal radii mixed in, coplanar centres and a ball inside the
  hull of the others;
- the certificates catch a split that misses its polyhedron or its frusta;
- volumes: manifold3d's hulls of ever finer sphere meshes converge to the exact volume;
- parallel cylinders of different radii between two planes: membership of each slice against
  the same certificates in the plane;
- a render against the analytic ray caster; refusals name what stops them.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from isocsg import (
    Box,
    ConvexPolyhedron,
    Cylinder,
    NotExactError,
    PointLight,
    ResourceLimitError,
    Sphere,
    Truncus,
    Union,
    hull,
    volume,
)
from isocsg.csg.hull_balls import ball_hull

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference.ball_hull import ball_hull_membership, disc_hull_membership  # noqa: E402

SETTINGS = settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
EPS = 1e-5


def _assert_agrees(solid, centres: np.ndarray, radii: np.ndarray, xs: np.ndarray) -> None:
    inside, certain = ball_hull_membership(centres, radii, xs, EPS)
    got = solid.contains(xs)
    assert certain.mean() > 0.9
    bad = np.nonzero((got != inside) & certain)[0]
    assert bad.size == 0, f"{bad.size} of {certain.sum()} points disagree, e.g. {xs[bad[:3]]}"
    assert inside[certain].any() and (~inside[certain]).any()


def _around(solid, n: int, seed: int) -> np.ndarray:
    lo, hi = solid.bounds
    pad = 0.1 * (hi - lo)
    return np.random.default_rng(seed).uniform(lo - pad, hi + pad, size=(n, 3))


@st.composite
def _balls(draw):
    n = draw(st.integers(2, 8))
    centres = np.array(draw(st.lists(st.tuples(*[st.floats(-2, 2)] * 3), min_size=n, max_size=n)))
    common = draw(st.floats(0.1, 1.5))
    radii = np.array(draw(st.lists(st.just(0.0) | st.just(common) | st.floats(0.05, 1.5), min_size=n, max_size=n)))
    layout = draw(st.sampled_from(["general", "coplanar", "inner"]))
    if layout == "coplanar":
        centres[:, 2] = 0.3
    elif layout == "inner":  # a small ball inside the hull of the others (but inside none of them)
        centres = np.vstack([centres, centres.mean(axis=0)])
        radii = np.append(radii, 0.05)
    if radii.max() == 0.0:
        radii[0] = common
    return centres, radii


@SETTINGS
@given(balls=_balls(), seed=st.integers(0, 2**16))
def test_hull_of_balls_of_any_radii_agrees_with_the_certificates(balls, seed: int) -> None:
    centres, radii = balls
    tetra = 0.3 * np.array([[1.0, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]])
    solids = [Sphere(c, r) if r > 0 else ConvexPolyhedron(c + tetra) for c, r in zip(centres, radii)]
    solid = hull(*solids)  # a radius 0 stands for a small tetrahedron there: four corners
    xs = _around(solid, 400, seed)
    corners = np.array([c + tetra for c, r in zip(centres, radii) if r == 0]).reshape(-1, 3)
    balls_c = np.vstack([centres[radii > 0], corners])
    balls_r = np.concatenate([radii[radii > 0], np.zeros(len(corners))])
    _assert_agrees(solid, balls_c, balls_r, xs)


def test_the_certificates_catch_a_split_missing_its_polyhedron_or_its_frusta() -> None:
    centres = np.array([[0.0, 0, 0], [3, 0.2, 0], [0.5, 2.5, 0.3], [1, 1, 2.2]])
    radii = np.array([1.0, 0.4, 0.6, 0.3])
    pieces = ball_hull(centres, radii)
    xs = _around(Union(*pieces), 3000, 7)
    inside, certain = ball_hull_membership(centres, radii, xs, EPS)
    for kind in (ConvexPolyhedron, Truncus):
        partial = Union(*[p for p in pieces if not isinstance(p, kind)])
        assert np.any((partial.contains(xs) != inside) & certain), kind.__name__


def test_a_box_and_a_sphere_hull_with_cones_to_the_corners() -> None:
    solid = hull(Box((0, 0, 0), (10, 10, 10)), Sphere((0, 0, 12), 4))
    kinds = sorted(type(p).__name__ for p in solid.children)
    assert kinds == ["ConvexPolyhedron", "Sphere", "Truncus", "Truncus", "Truncus", "Truncus"]
    corners = np.array([[x, y, z] for x in (-5, 5) for y in (-5, 5) for z in (-5, 5)], dtype=float)
    xs = _around(solid, 1500, 3)
    _assert_agrees(solid, np.vstack([[0, 0, 12], corners]), np.array([4.0] + [0.0] * 8), xs)


@SETTINGS
@given(
    shear=st.lists(st.floats(-0.4, 0.4), min_size=9, max_size=9),
    sizes=st.lists(st.floats(0.2, 1.5), min_size=3, max_size=5),
    seed=st.integers(0, 2**16),
)
def test_ellipsoids_of_one_shape_and_different_sizes_hull_through_the_map(shear, sizes, seed) -> None:
    a = np.eye(3) + np.array(shear).reshape(3, 3)
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = a, (0.4, -0.2, 0.9)
    rng = np.random.default_rng(seed)
    centres = rng.uniform(-2, 2, (len(sizes), 3))
    solid = hull(*[Sphere(c, r).transform(m) for c, r in zip(centres, sizes)])
    xs = _around(solid, 400, seed)
    local = np.linalg.solve(a, (xs - m[:3, 3]).T).T
    inside, certain = ball_hull_membership(centres, np.array(sizes), local, EPS)
    got = solid.contains(xs)
    assert certain.mean() > 0.9 and not np.any((got != inside) & certain)


def _manifold_hull_volume(spheres, n: int, boxes=()) -> float:
    import manifold3d

    meshes = [manifold3d.Manifold.sphere(r, n).translate(tuple(c)) for c, r in spheres]
    meshes += [manifold3d.Manifold.cube(tuple(s), True).translate(tuple(c)) for c, s in boxes]
    return float(manifold3d.Manifold.batch_hull(meshes).volume())


@pytest.mark.parametrize(
    "spheres, boxes",
    [([((0, 0, 12), 4.0)], [((0, 0, 0), (10, 10, 10))])],
    ids=["box_sphere"],  # four spheres in general position: docs/hull.md (a union's volume takes ~20 s)
)
def test_volumes_converge_with_manifold3d(spheres, boxes) -> None:
    exact = volume(hull(*[Sphere(c, r) for c, r in spheres], *[Box(c, s) for c, s in boxes]), tol=1e-6)
    meshes = [_manifold_hull_volume(spheres, n, boxes) for n in (32, 96, 288)]
    gaps = [abs(v / exact - 1) for v in meshes]
    assert gaps[0] > gaps[1] > gaps[2] and gaps[2] < 1e-3, gaps
    extrapolated = meshes[2] + (meshes[2] - meshes[1]) / 8  # the mesh's error falls as 1 / n^2
    assert extrapolated == pytest.approx(exact, rel=2e-5)


@SETTINGS
@given(
    feet=st.lists(st.tuples(st.floats(-3, 3), st.floats(-3, 3)), min_size=1, max_size=6),
    radii=st.lists(st.floats(0.1, 1.5), min_size=6, max_size=6),
    axis=st.tuples(st.floats(-1, 1), st.floats(-1, 1), st.floats(0.3, 1)),
    heights=st.tuples(st.floats(-1, 0.5), st.floats(0.3, 2)),
    seed=st.integers(0, 2**16),
)
def test_parallel_cylinders_of_any_radii_between_two_planes(feet, radii, axis, heights, seed) -> None:
    a = np.array(axis) / np.linalg.norm(axis)
    u = np.cross(a, [1.0, 0, 0]) if abs(a[0]) < 0.9 else np.cross(a, [0, 1.0, 0])
    u /= np.linalg.norm(u)
    v = np.cross(a, u)
    bottom, height = heights
    f2 = np.array(feet)
    r = np.array(radii[: len(feet)])
    solid = hull(*[Cylinder(x * u + y * v + (bottom + height / 2) * a, height * a, rk) for (x, y), rk in zip(f2, r)])
    xs = _around(solid, 400, seed)
    s = xs @ a
    flat = np.column_stack([xs @ u, xs @ v, np.zeros(len(xs))])  # the slice of a hull of balls in their plane
    inside, certain = ball_hull_membership(np.column_stack([f2, np.zeros(len(f2))]), r, flat, EPS)
    in_span = (s >= bottom) & (s <= bottom + height)
    certain &= np.minimum(np.abs(s - bottom), np.abs(s - bottom - height)) > EPS
    got = solid.contains(xs)
    assert certain.mean() > 0.85
    assert not np.any((got != (inside & in_span)) & certain)


def test_a_plate_with_different_corner_radii_is_a_prism_and_cylinders() -> None:
    plate = hull(*[Cylinder((x, y, 1.5), (0, 0, 3), r) for x, y, r in ((0, 0, 5), (40, 0, 2), (40, 25, 8), (0, 25, 3))])
    assert sorted(type(p).__name__ for p in plate.children) == ["ConvexPolyhedron"] + ["Cylinder"] * 4
    from shapely import Point, union_all

    discs = union_all([Point(x, y).buffer(r, 2048) for x, y, r in ((0, 0, 5), (40, 0, 2), (40, 25, 8), (0, 25, 3))])
    assert volume(plate, tol=1e-6) == pytest.approx(3 * discs.convex_hull.area, rel=1e-5)


@pytest.mark.parametrize(
    "solid",
    [
        hull(Sphere((0, 0, 0), 0.9), Sphere((1.8, 0.4, 0.3), 0.4), Sphere((0.6, 1.5, -0.2), 0.6),
             Box((0.8, 0.6, -0.9), (1.6, 1.2, 0.2))),
        hull(Cylinder((0, 0, -0.5), (0, 0, 0.6), 0.8), Truncus((1.7, 0.3, 0.2), (0, 0, 1.4), 0.2, 0.5),
             Box((0.6, 1.3, -0.3), (0.8, 0.4, 1.0))),
    ],
    ids=["spheres_and_a_box", "cylinder_frustum_box"],
)
def test_a_hull_renders_like_the_reference(solid) -> None:
    from reference import compare, raycast_scene
    from scenes import make_scene, render_image

    scene = make_scene((3.0, -4.0, 2.5), [solid], [PointLight((3, -4, 5))], target=(0.8, 0.5, 0.0), size=96)
    result = compare(render_image(scene), raycast_scene(scene))
    assert result.iou >= 0.99 and result.fraction >= 0.98, result.summary()


@pytest.mark.parametrize(
    "solids, message",
    [
        ((Sphere((0, 0, 0), 1), Sphere((3, 0, 0), 1).transform(np.diag([1.0, 2.0, 1.0, 1.0]))),
         "hull: a hull of Ellipsoid, Sphere of different shapes or directions is not an exact union"),
        ((Sphere((0, 0, 0), 1), Cylinder((2, 0, 0), (0, 0, 1), 0.5)),
         "hull: a hull of Cylinder, Sphere of different shapes or directions is not an exact union"),
        ((Box((0, 0, 0), (1, 1, 1)), Cylinder((3, 0, 0), (0, 0, 1), 0.5), Cylinder((0, 3, 0), (1, 0, 0), 0.5)),
         "hull: a hull of Box, Cylinder of different shapes or directions is not an exact union"),
        ((Sphere((0, 0, 0), 1), Truncus((3, 0, 0), (0, 0, 1), 0.5, 0.2)),
         "hull: a hull of a cone or frustum is not an exact union"),
    ],
    ids=["ellipsoid_sphere", "sphere_cylinder", "box_crossed_cylinders", "sphere_frustum"],
)
def test_refusals_name_what_stops_them(solids, message: str) -> None:
    with pytest.raises(NotExactError, match=re.escape(message)):
        hull(*solids)


def test_too_many_corners_with_balls_is_a_resource_limit() -> None:
    import isocsg.csg.hull_balls as hb

    rng = np.random.default_rng(1)
    points = rng.normal(size=(60, 3))
    points /= np.linalg.norm(points, axis=1)[:, None]
    old = hb.MAX_HULL_WORK
    hb.MAX_HULL_WORK = 1e4
    try:
        with pytest.raises(ResourceLimitError, match="over MAX_HULL_WORK"):
            hull(ConvexPolyhedron(points), Sphere((0, 0, 2), 0.5))
    finally:
        hb.MAX_HULL_WORK = old


@SETTINGS
@given(
    spans=st.lists(st.tuples(st.floats(-3, 3), st.floats(0.2, 2), st.floats(0.05, 2), st.just(0.0) | st.floats(0.05, 2)),
                   min_size=1, max_size=3),
    balls=st.lists(st.tuples(st.floats(-3, 3), st.floats(0.1, 2)), min_size=1, max_size=3),
    axis=st.tuples(st.floats(-1, 1), st.floats(-1, 1), st.floats(0.2, 1)),
    seed=st.integers(0, 2**16),
)
def test_trunci_and_spheres_on_one_axis_hull_as_a_revolved_meridian(spans, balls, axis, seed) -> None:
    """The meridian is the 2D hull of the ends' rims (both sides) and the spheres' discs."""
    a = np.array(axis) / np.linalg.norm(axis)
    origin = np.array([0.5, -0.3, 0.2])
    trunci = [Truncus(origin + (s0 + h / 2) * a, h * a, r1, r2) for s0, h, r1, r2 in spans]
    spheres = [Sphere(origin + s * a, r) for s, r in balls]
    solid = hull(*trunci, *spheres)
    rims = [(s0 + h, r1) for s0, h, r1, _ in spans] + [(s0, r2) for s0, h, _, r2 in spans]
    centres = [(s, side * r, 0.0) for s, r in rims for side in (1, -1)] + [(s, 0.0, 0.0) for s, _ in balls]
    radii = [0.0] * (2 * len(rims)) + [r for _, r in balls]
    xs = _around(solid, 400, seed)
    s = (xs - origin) @ a
    rho = np.linalg.norm(xs - origin - s[:, None] * a, axis=1)
    inside, certain = ball_hull_membership(np.array(centres), np.array(radii), np.column_stack([s, rho, 0 * s]), EPS)
    got = solid.contains(xs)
    assert certain.mean() > 0.9
    assert not np.any((got != inside) & certain)


@pytest.mark.parametrize(
    "centres, radii",
    [
        ([[x, y, z] for x in (0, 4) for y in (0, 3) for z in (0, 2)], [2.0 if z == 0 else 1.0 for _ in (0, 4)
                                                                      for _ in (0, 3) for z in (0, 2)]),
        ([[0, 0, 0], [4, 0, 0], [2, 0, 0], [2, 3, 0]], [1.0, 1.0, 1.0, 0.5]),  # three on a line, one off it
        ([[0, 0, 0], [1e-7, 0, 0], [3, 1, 0], [1, 2, 2]], [1.0, 1.0 - 1e-7, 0.5, 0.7]),  # nearly internally tangent
        ([[0, 0, 0], [3, 0, 0], [0, 3, 0], [0, 0, 3]], [1.0, 1.0, 1.0, 1.0 + 1e-12]),  # equal to rounding
    ],
    ids=["two_layers", "line_and_one", "nearly_nested", "nearly_equal"],
)
def test_degenerate_sets_of_balls(centres, radii) -> None:
    c, r = np.array(centres, dtype=float), np.array(radii)
    solid = hull(*[Sphere(p, q) for p, q in zip(c, r)])
    _assert_agrees(solid, c, r, _around(solid, 1500, 11))


@SETTINGS
@given(
    spans=st.lists(st.tuples(st.floats(-2, 2), st.floats(-2, 2), st.floats(-2, 1), st.floats(0.2, 2.5),
                             st.floats(0.1, 1.5), st.just(0.0) | st.floats(0.1, 1.5)), min_size=1, max_size=4),
    axis=st.tuples(st.floats(-1, 1), st.floats(-1, 1), st.floats(0.3, 1)),
    box=st.booleans(),
    seed=st.integers(0, 2**16),
)
def test_cylinders_and_cones_on_parallel_axes_agree_with_the_certificates(spans, axis, box, seed) -> None:
    a = np.array(axis) / np.linalg.norm(axis)
    u = np.cross(a, [1.0, 0, 0]) if abs(a[0]) < 0.9 else np.cross(a, [0, 1.0, 0])
    u /= np.linalg.norm(u)
    v = np.cross(a, u)
    trunci = [Truncus(x * u + y * v + (z + h / 2) * a, h * a, r1, r2) for x, y, z, h, r1, r2 in spans]
    extra = [Box((0.5, -0.5, 1.5), (1.0, 0.6, 0.8))] if box else []
    solid = hull(*trunci, *extra)
    centres = [e for t in trunci for e in t.end_centers] + [np.array(q) for b in extra for q in b.hull_points()]
    radii = [q for t in trunci for q in (t.r1, t.r2)] + [0.0] * (8 * len(extra))
    xs = _around(solid, 400, seed)
    inside, certain = disc_hull_membership(np.array(centres), np.array(radii), a, xs, EPS)
    got = solid.contains(xs)
    assert certain.mean() > 0.9
    bad = np.nonzero((got != inside) & certain)[0]
    assert bad.size == 0, f"{bad.size} of {certain.sum()} points disagree, e.g. {xs[bad[:3]]}"


@SETTINGS
@given(
    shear=st.lists(st.floats(-0.4, 0.4), min_size=9, max_size=9),
    count=st.integers(2, 3),
    box=st.booleans(),
    seed=st.integers(0, 2**16),
)
def test_parallel_trunci_under_one_map_hull_through_the_map(shear, count, box, seed) -> None:
    """Mapped cylinders and cones are elliptic trunci; their hull is the map of the hull."""
    a = np.eye(3) + np.array(shear).reshape(3, 3)
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = a, (0.3, -0.2, 0.5)
    spans = [(0, 0, 0, 1, 1, 1), (3, 0, 0.5, 2, 0.5, 0.5), (1, 2, -1, 1.5, 0.8, 0.0)][:count]
    trunci = [Truncus((x, y, z + h / 2), (0, 0, h), r1, r2) for x, y, z, h, r1, r2 in spans]
    extra = [Box((1, 0, 0.5), (1, 0.5, 0.5))] if box else []
    solid = hull(*[t.transform(m) for t in trunci], *[b.transform(m) for b in extra])
    centres = [e for t in trunci for e in t.end_centers] + [np.array(q) for b in extra for q in b.hull_points()]
    radii = [q for t in trunci for q in (t.r1, t.r2)] + [0.0] * (8 * len(extra))
    xs = _around(solid, 400, seed)
    local = np.linalg.solve(a, (xs - m[:3, 3]).T).T
    inside, certain = disc_hull_membership(np.array(centres), np.array(radii), [0, 0, 1], local, EPS)
    assert certain.mean() > 0.9 and not np.any((solid.contains(xs) != inside) & certain)
