"""Umbra and penumbra regions on receiving faces.

Judges: similar triangles (square source parallel to a square occluder) and the
exact per-point shadow states of :func:`isocsg.shadows.shadow_state` at sample
points of the faces.
"""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from isocsg import Box, ConvexPolyhedron, InvalidGeometryError, Sphere
from isocsg.lighting.area import AreaLight, PolyhedronLight
from isocsg.shadows import shadow_state
from isocsg.shadows.classify import FaceType
from isocsg.shadows.regions import face_frame, face_shadow_regions, solid_shadow_regions


def _square(cx, cy, z, s, down=True):
    h = s / 2
    pts = [(cx - h, cy - h, z), (cx - h, cy + h, z), (cx + h, cy + h, z), (cx + h, cy - h, z)]
    return pts if down else pts[::-1]


FLOOR = np.array(_square(0, 0, 0.0, 8.0, down=False))
S, HS, HO, T = 1.0, 2.0, 1.0, 0.02


def _edges(a):
    ztop, zbot = HO + T / 2, HO - T / 2
    x_pen = -S / 2 + (a / 2 + S / 2) * HS / (HS - ztop)
    x_umb = S / 2 + (a / 2 - S / 2) * HS / (HS - zbot) if S / 2 >= a / 2 else S / 2 + (a / 2 - S / 2) * HS / (HS - ztop)
    return x_umb, x_pen


@pytest.mark.parametrize("a", [0.8, 1.3], ids=["occluder-smaller", "occluder-larger"])
def test_square_regions_by_similar_triangles(a):
    light = AreaLight(_square(0, 0, HS, S))
    fs = face_shadow_regions(FLOOR, light, [Box((0, 0, HO), (a, a, T))])
    x_umb, x_pen = _edges(a)
    to_world = fs.frame
    # regions are axis-aligned squares centred on the axis
    for geom, edge in ((fs.umbra, x_umb), (fs.penumbra, x_pen)):
        corners = np.array(geom.exterior.coords)[:, :2] if geom.geom_type == "Polygon" else None
        assert corners is not None
        world = np.column_stack([corners, np.zeros(len(corners)), np.ones(len(corners))]) @ to_world.T
        assert world[:, 0].max() == pytest.approx(edge, abs=1e-9)
        assert world[:, 0].min() == pytest.approx(-edge, abs=1e-9)
        assert world[:, 1].max() == pytest.approx(edge, abs=1e-9)
    assert fs.umbra.area == pytest.approx((2 * x_umb) ** 2, rel=1e-9)
    assert fs.penumbra.area == pytest.approx((2 * x_pen) ** 2 - (2 * x_umb) ** 2, rel=1e-9)
    assert fs.overlap.is_empty
    assert fs.face_type == FaceType.A


def _scenes():
    lamp = AreaLight(_square(0.2, -0.1, 2.5, 1.0))
    tri = np.array([(-0.5, -0.4, 2.4), (0.6, 0.4, 2.5), (0.5, -0.5, 2.2)])
    tilted = AreaLight(tri if np.cross(tri[1] - tri[0], tri[2] - tri[0])[2] < 0 else tri[::-1])
    prism = PolyhedronLight([(x, y, z) for x in (-0.3, 0.3) for y in (-0.6, 0.6) for z in (2.3, 2.6)])
    occs = [Box((-0.4, 0.0, 1.0), (0.5, 0.6, 0.2)), Box((0.35, 0.1, 1.3), (0.4, 0.5, 0.3)), Sphere((0.2, 0.8, 0.7), 0.3)]
    tilt_floor = np.array([(-3, -3, -0.3), (3, -3, 0.2), (3, 3, 0.4), (-3, 3, -0.1)])
    # a wall whose plane cuts the source (type B)
    wall = np.array([(0.3, -3, -0.5), (0.3, 3, -0.5), (0.3, 3, 1.8), (0.3, -3, 1.8)])
    if np.cross(wall[1] - wall[0], wall[2] - wall[0])[0] < 0:
        wall = wall[::-1]
    return [
        ("area-floor", lamp, occs, FLOOR),
        ("area-tilted-floor", tilted, occs, tilt_floor[::-1] if np.cross(tilt_floor[1] - tilt_floor[0], tilt_floor[2] - tilt_floor[0])[2] < 0 else tilt_floor),
        ("area-wall-type-B", lamp, occs[:2], wall),
        ("prism-floor", prism, occs, FLOOR),
    ]


SCENES = _scenes()


@pytest.mark.parametrize("name,light,occs,face", SCENES, ids=[s[0] for s in SCENES])
def test_regions_agree_with_shadow_state(name, light, occs, face):
    fs = face_shadow_regions(face, light, occs, resolution=16)
    rng = np.random.default_rng(2)
    # sample around the shadows (plus a lit margin), inside the face
    minx, miny, maxx, maxy = shapely.union_all([fs.umbra, fs.penumbra]).buffer(0.3).bounds
    p2 = rng.uniform([minx, miny], [maxx, maxy], size=(6000, 2))
    pts = shapely.points(p2)
    inside = shapely.contains(fs.polygon, pts)
    boundary = shapely.union_all([shapely.boundary(g) for g in (fs.umbra, fs.penumbra, fs.overlap) if not g.is_empty])
    far = inside & (shapely.distance(boundary, pts) > 1e-6) if not boundary.is_empty else inside
    p2 = p2[far]
    in_overlap = shapely.covers(fs.overlap, shapely.points(p2)) if not fs.overlap.is_empty else np.zeros(len(p2), bool)
    world = fs.to_3d(p2)
    np.testing.assert_allclose(fs.to_2d(world), p2, atol=1e-9)
    expected = shadow_state(world, fs.normal, light, occs, resolution=16)
    quick = fs.classify(p2)
    # outside the overlaps the polygons are exact; inside them the union of umbrae is a lower bound
    np.testing.assert_array_equal(quick[~in_overlap], expected[~in_overlap])
    assert np.all(quick[in_overlap] <= expected[in_overlap])
    np.testing.assert_array_equal(fs.classify(p2, exact=True), expected)
    assert np.bincount(expected, minlength=3).min() >= 20, np.bincount(expected, minlength=3)


def test_type_B_face_uses_the_part_of_the_source_in_front():
    name, light, occs, wall = SCENES[2]
    fs = face_shadow_regions(wall, light, occs)
    assert fs.face_type == FaceType.B


def test_true_umbra_of_two_touching_occluders_lies_in_the_overlap():
    """Two halves of a 0.8 square: neither has an umbra, together they have the 0.8 square's."""
    light = AreaLight(_square(0, 0, HS, S))
    halves = [Box((-0.2, 0, HO), (0.4, 0.8, T)), Box((0.2, 0, HO), (0.4, 0.8, T))]
    fs = face_shadow_regions(FLOOR, light, halves)
    assert fs.umbra.is_empty
    x_umb, _ = _edges(0.8)
    # the true umbra along y = 0 is the whole square's: |x| < x_umb
    xs = np.array([0.0, x_umb - 1e-4, x_umb + 1e-4])
    p2 = fs.to_2d(np.column_stack([xs, np.zeros(3), np.zeros(3)]))
    assert np.all(shapely.covers(fs.overlap, shapely.points(p2[:2])))
    assert fs.classify(p2).tolist() == [1, 1, 1]
    assert fs.classify(p2, exact=True).tolist() == [2, 2, 1]


def test_type_C_face_has_no_regions_and_solid_faces():
    light = AreaLight(_square(0, 0, HS, S))
    ceiling_down = np.array(_square(0, 0, 3.0, 2.0))
    fs = face_shadow_regions(ceiling_down[::-1], light, [Box((0, 0, 1), (1, 1, 1))])
    assert fs.face_type == FaceType.C and fs.umbra.is_empty and fs.penumbra.is_empty
    slab = Box((0, 0, -0.5), (8, 8, 1))
    regions = solid_shadow_regions(slab, light, [slab, Box((0, 0, HO), (0.8, 0.8, T))])
    top = [r for r in regions if r.normal[2] > 0.5][0]
    assert top.umbra.area == pytest.approx((2 * _edges(0.8)[0]) ** 2, rel=1e-9)
    assert len(top.shadowing) == 1  # the slab never shadows its own face (eq. 5)


def test_frame_is_orthonormal_and_maps_the_face():
    face = np.array([(1, 0, 0), (0, 1, 0.5), (-1, 0, 1), (0, -1, 0.5)], dtype=float)
    m = face_frame(face)
    np.testing.assert_allclose(m[:3, :3].T @ m[:3, :3], np.eye(3), atol=1e-12)
    assert np.linalg.det(m[:3, :3]) == pytest.approx(1.0)
    local = np.linalg.solve(m, np.column_stack([face, np.ones(4)]).T).T
    np.testing.assert_allclose(local[:, 2], 0, atol=1e-12)


def test_errors():
    light = AreaLight(_square(0, 0, HS, S))
    with pytest.raises(InvalidGeometryError, match="occluders\\[0\\]"):
        face_shadow_regions(FLOOR, light, ["box"])
    with pytest.raises(InvalidGeometryError, match="face"):
        face_shadow_regions([(0, 0, 0), (1, 0, 0)], light, [])
    poly = ConvexPolyhedron([(0, 0, 1), (1, 0, 1), (0, 1, 1), (0, 0, 1.5)])
    assert face_shadow_regions(FLOOR, light, poly).penumbra.area > 0
