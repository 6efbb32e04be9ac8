"""``isocsg.minkowski``: exact Minkowski sums, judged independently.

Closed forms (a rounded box, a box plus a cylinder, a rounded cylinder), Steiner-type formulas
from scipy's hull (a polytope plus a ball, plus a disc), membership of random points against the
distance to the hull of the corners (``tests/reference/convex_distance.py``), two polytopes
against the hull of their corners' sums checked point by point, a union operand distributing,
the translation of the sum, and the refusals.
"""

from __future__ import annotations

import math
import re
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from scipy.spatial import ConvexHull

from isocsg import (
    Box,
    Cone,
    ConvexPolyhedron,
    Cylinder,
    Ellipsoid,
    InvalidGeometryError,
    NotExactError,
    Sphere,
    Torus,
    Union,
    minkowski,
    volume,
)

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference.convex_distance import disc_grown_volume, hull_distance, slice_distance  # noqa: E402

SETTINGS = settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
CORNERS = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)


def _sample(solid, n: int, seed: int) -> np.ndarray:
    lo, hi = solid.bounds
    pad = 0.1 * (hi - lo)
    return np.random.default_rng(seed).uniform(lo - pad, hi + pad, size=(n, 3))


def _agree(solid, xs: np.ndarray, inside: np.ndarray, margin: np.ndarray) -> None:
    clear = margin > 1e-6
    got = solid.contains(xs)
    bad = np.nonzero((got != inside) & clear)[0]
    assert clear.mean() > 0.9 and bad.size == 0, f"{bad.size} points disagree, e.g. {xs[bad[:3]]}"
    assert inside[clear].any() and (~inside[clear]).any()


def _polyhedron_or_none(pts: np.ndarray) -> ConvexPolyhedron | None:
    try:
        return ConvexPolyhedron(pts)
    except InvalidGeometryError:
        return None


def test_box_plus_sphere_is_the_rounded_box() -> None:
    a, b, c, r = 10.0, 6.0, 4.0, 1.5
    rounded = minkowski(Box((0, 0, 0), (a, b, c)), Sphere((0, 0, 0), r))
    want = a * b * c + 2 * r * (a * b + b * c + c * a) + math.pi * r * r * (a + b + c) + 4 / 3 * math.pi * r**3
    assert volume(rounded) == pytest.approx(want, rel=1e-4)


def test_box_plus_cylinder_rounds_the_edges_along_the_axis() -> None:
    a, b, c, r, h = 10.0, 6.0, 2.0, 2.0, 1.0
    solid = minkowski(Box((5, 3, 1), (a, b, c)), Cylinder((0, 0, 0.5), (0, 0, h), r))
    want = (a * b + 2 * r * (a + b) + math.pi * r * r) * (c + h)
    assert volume(solid) == pytest.approx(want, rel=1e-4)
    lo, hi = solid.bounds
    assert np.allclose(lo, [-2, -2, 0]) and np.allclose(hi, [12, 8, 3])


def test_cylinder_plus_sphere_is_two_cylinders_and_two_tori() -> None:
    R, h, r = 10.0, 4.0, 1.5
    solid = minkowski(Cylinder((0, 0, 2), (0, 0, h), R), Sphere((1, 2, 3), r))
    assert sorted(type(p).__name__ for p in solid.children) == ["Cylinder", "Cylinder", "Torus", "Torus"]
    want = math.pi * (R + r) ** 2 * h + 2 * math.pi * (R * R * r + math.pi * R * r * r / 2 + 2 * r**3 / 3)
    assert volume(solid) == pytest.approx(want, rel=1e-4)
    xs = _sample(solid, 2000, 3) - (1, 2, 3)  # in the frame of the sum without the sphere's offset
    rho, z = np.hypot(xs[:, 0], xs[:, 1]), xs[:, 2]
    # distance from the cylinder (radius R, z in [0, h]) grown by r: an independent closed form
    dz = np.maximum(np.maximum(-z, z - h), 0)
    drho = np.maximum(rho - R, 0)
    dist = np.hypot(dz, drho)
    _agree(solid, xs + (1, 2, 3), dist <= r, np.abs(dist - r))


@SETTINGS
@given(
    corners=st.lists(st.tuples(*[st.floats(-2, 2)] * 3), min_size=4, max_size=8),
    r=st.floats(0.1, 1.2),
    seed=st.integers(0, 2**16),
)
def test_polytope_plus_ball_is_the_grown_polytope(corners, r: float, seed: int) -> None:
    pts = np.array(corners)
    poly = _polyhedron_or_none(pts)
    assume(poly is not None)
    centre = np.array([0.3, -0.2, 0.5])
    solid = minkowski(poly, Sphere(centre, r))
    xs = _sample(solid, 300, seed)
    dist = hull_distance(pts + centre, xs)
    _agree(solid, xs, dist <= r, np.abs(dist - r))


@SETTINGS
@given(
    corners=st.lists(st.tuples(*[st.floats(-2, 2)] * 3), min_size=4, max_size=7),
    axis=st.tuples(st.floats(-1, 1), st.floats(-1, 1), st.floats(0.2, 1)),
    h=st.floats(0.1, 2),
    r=st.floats(0.1, 1.0),
    seed=st.integers(0, 2**16),
)
def test_polytope_plus_cylinder_is_the_swept_polytope_grown_by_the_disc(corners, axis, h, r, seed) -> None:
    pts = np.array(corners)
    poly = _polyhedron_or_none(pts)
    assume(poly is not None)  # flat draws: the hull tests' flat cases
    a = np.array(axis) / np.linalg.norm(axis)
    solid = minkowski(poly, Cylinder(h * a / 2, h * a, r))
    swept = np.vstack([pts, pts + h * a])
    xs = _sample(solid, 300, seed)
    dist = slice_distance(swept, a, xs)
    _agree(solid, xs, dist <= r, np.abs(dist - r))


def test_tilted_prism_plus_cylinder_has_the_sliced_steiner_volume() -> None:
    a = np.array([0.3, -0.4, 0.866])
    a /= np.linalg.norm(a)
    u = np.cross(a, [1.0, 0, 0])
    u /= np.linalg.norm(u)
    v = np.cross(a, u)
    base = np.array([[0.0, 0], [2.0, 0.3], [0.4, 1.8], [-0.5, 1.0]]) @ np.stack([u, v])
    pts = np.vstack([base, base + 1.3 * a])  # a prism along the cylinder's axis, turned
    h, r = 0.8, 0.45
    solid = minkowski(ConvexPolyhedron(pts), Cylinder((0, 0, 0), h * a, r))
    swept = np.vstack([pts - h * a / 2, pts + h * a / 2])
    assert volume(solid) == pytest.approx(disc_grown_volume(swept, a, r), rel=1e-4)


def test_two_polytopes_sum_to_the_hull_of_corner_sums() -> None:
    tet = ConvexPolyhedron([(0, 0, 0), (4, 0, 0), (0, 3, 0), (0, 0, 5)])
    box = Box((0.5, 0.5, 0.5), (2, 1, 3))
    solid = minkowski(tet, box)
    assert isinstance(solid, ConvexPolyhedron)
    sums = (tet.hull_vertices[:, None] + np.asarray(box.hull_points())[None]).reshape(-1, 3)
    xs = _sample(solid, 800, 5)
    planes = ConvexHull(sums).equations  # scipy's own hull of the sums: signed distance to it
    signed = (xs @ planes[:, :3].T + planes[:, 3]).max(axis=1)
    _agree(solid, xs, signed <= 0, np.abs(signed))
    assert minkowski(Box((0, 0, 0), (1, 2, 3)), Box((1, 1, 1), (3, 2, 1))).volume == pytest.approx(64.0)


def test_a_union_distributes_and_the_sum_moves_with_its_operands() -> None:
    ell = Union(Box((5, 1, 1), (10, 2, 2)), Box((1, 5, 1), (2, 10, 2)))
    solid = minkowski(ell, Sphere((0, 0, 0), 1.0))
    xs = _sample(solid, 1500, 7)
    d = np.minimum(hull_distance(CORNERS * (5, 1, 1) + (5, 1, 1), xs), hull_distance(CORNERS * (1, 5, 1) + (1, 5, 1), xs))
    _agree(solid, xs, d <= 1.0, np.abs(d - 1.0))
    moved = minkowski(ell.translate((1, 2, 3)), Sphere((-1, 0, 0.5), 1.0))
    assert np.allclose(moved.bounds, solid.bounds + np.array([0.0, 2, 3.5]))


def test_ellipsoid_plus_box_through_the_ellipsoids_map() -> None:
    A = np.array([[1.2, 0.3, 0.0], [0.0, 0.6, 0.2], [0.2, 0.0, 0.9]])
    solid = minkowski(Box((0, 0, 0), (2, 2, 2)), Ellipsoid.from_affine(A, (0, 0, 0)))
    xs = _sample(solid, 1500, 11)
    dist = hull_distance(np.linalg.solve(A, CORNERS.T).T, np.linalg.solve(A, xs.T).T)  # in the ball's frame
    _agree(solid, xs, dist <= 1.0, np.abs(dist - 1.0) * 0.4)


@pytest.mark.parametrize(
    "operands, message",
    [
        ((Box((0, 0, 0), (2, 2, 2)) - Sphere((1, 1, 1), 1), Sphere((0, 0, 0), 1)),
         "minkowski: a minkowski of a difference is not supported"),
        ((Box((0, 0, 0), (1, 1, 1)), Cone((0, 0, 0), (0, 0, 1), 1)), "minkowski: a minkowski of a cone or frustum"),
        ((Torus((0, 0, 0), (0, 0, 1), 2, 0.5), Sphere((0, 0, 0), 1)), "minkowski: a minkowski of a Torus"),
        ((Sphere((0, 0, 0), 1), Ellipsoid((0, 0, 0), (1, 2, 3))),
         "minkowski: a sum of ellipsoids or spheres of different shapes"),
        ((Cylinder((0, 0, 0), (0, 0, 1), 1), Cylinder((0, 0, 0), (1, 0, 0), 1)),
         "minkowski: a sum of cylinders that are not parallel"),
        ((Cylinder((0, 0, 0), (0, 0, 1), 1), Sphere((0, 0, 0), 1)), "needs a spindle torus"),
        ((Box((0, 0, 0), (1, 1, 1)), Cylinder((0, 0, 0), (0, 0, 1), 1), Sphere((0, 0, 0), 0.2)),
         "minkowski: a ball plus a disc is exact only as a sphere plus a round cylinder"),
    ],
    ids=["difference", "cone", "torus", "sphere_ellipsoid", "crossed_cylinders", "spindle", "box_cylinder_sphere"],
)
def test_refusals_name_what_stops_them(operands, message: str) -> None:
    with pytest.raises(NotExactError, match=re.escape(message)):
        minkowski(*operands)


def test_operands_must_be_solids_and_unions_stay_bounded() -> None:
    from isocsg import ResourceLimitError
    from isocsg.csg.hull import MAX_MINKOWSKI_TERMS

    with pytest.raises(InvalidGeometryError, match=re.escape("minkowski: operands must be isocsg solids, got str")):
        minkowski(Sphere((0, 0, 0), 1), "cube")  # type: ignore[arg-type]
    many = Union(*[Box((3 * i, 0, 0), (1, 1, 1)) for i in range(65)])
    assert 65 * 65 > MAX_MINKOWSKI_TERMS
    with pytest.raises(ResourceLimitError, match=re.escape("minkowski: the operands' convex pieces make 4225 sums")):
        minkowski(many, many)
