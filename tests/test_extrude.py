"""Straight extrusions: exact volumes (area x height), manifold3d's own extrusion, images against the ray caster."""

from __future__ import annotations

import math
import re
import sys
from pathlib import Path

import manifold3d as m3
import numpy as np
import pytest
from shapely.geometry import MultiPolygon, Point, Polygon

from isocsg import (
    Camera,
    ConvexPolyhedron,
    InvalidGeometryError,
    PointLight,
    Scene,
    SceneObject,
    Union,
    extrude,
    volume,
)
from isocsg.csg.extrude import convex_partition
from isocsg.scene import loads_scene

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference import compare, raycast_scene  # noqa: E402
from scenes import render_image  # noqa: E402


def star(n: int = 5, r_out: float = 2.0, r_in: float = 0.8) -> Polygon:
    ang = np.pi / 2 + np.pi * np.arange(2 * n) / n
    r = np.where(np.arange(2 * n) % 2 == 0, r_out, r_in)
    return Polygon(np.column_stack([r * np.cos(ang), r * np.sin(ang)]))


POLYGONS = {
    "triangle": Polygon([(0, 0), (2, 0), (0, 1.5)]),
    "l_shape": Polygon([(0, 0), (3, 0), (3, 1), (1, 1), (1, 2.5), (0, 2.5)]),
    "frame": Polygon([(0, 0), (4, 0), (4, 3), (0, 3)], [[(1, 1), (3, 1), (3, 2), (1, 2)]]),
    "star": star(),
    "comb": Polygon([(0, 0), (5, 0), (5, 2), (4, 2), (4, 0.5), (3, 0.5), (3, 2), (2, 2), (2, 0.5), (1, 0.5), (1, 2), (0, 2)]),
    "disc_with_offset_hole": Point(0, 0).buffer(1.5, 4) - Point(0.4, 0.2).buffer(0.6, 2),
    "two_parts": MultiPolygon([
        Polygon([(0, 0), (1, 0), (1, 1), (0, 1)]),
        Polygon(np.asarray(star(4, 1.0, 0.4).exterior.coords) + [3.0, 0.0]),
    ]),
}


def manifold_extrusion(poly, height: float) -> m3.Manifold:
    """manifold3d's own extrusion of the polygon's rings (an independent construction)."""
    parts = list(poly.geoms) if isinstance(poly, MultiPolygon) else [poly]
    rings = []
    for p in parts:
        rings.append(np.asarray(p.exterior.coords)[:-1])
        rings += [np.asarray(r.coords)[:-1] for r in p.interiors]
    return m3.CrossSection(rings, m3.FillRule.EvenOdd).extrude(height)


@pytest.mark.parametrize("name", list(POLYGONS), ids=str)
def test_partition_is_convex_and_covers_the_polygon(name: str) -> None:
    poly = POLYGONS[name]
    pieces = [Polygon(p) for p in convex_partition(poly)]
    for p in pieces:
        assert p.is_valid
        assert p.area == pytest.approx(p.convex_hull.area, rel=1e-12)
    assert sum(p.area for p in pieces) == pytest.approx(poly.area, rel=1e-12)
    assert MultiPolygon(pieces).buffer(0).symmetric_difference(poly).area <= 1e-12 * poly.area
    # Hertel-Mehlhorn merges triangles: a simple polygon of n vertices gives at most n - 2 pieces.
    if isinstance(poly, Polygon) and not poly.interiors:
        n_vertices = len(poly.exterior.coords) - 1
        assert len(pieces) <= n_vertices - 2


@pytest.mark.parametrize("center", [False, True], ids=["base", "centered"])
@pytest.mark.parametrize("name", list(POLYGONS), ids=str)
def test_volume_is_area_times_height(name: str, center: bool) -> None:
    poly, h = POLYGONS[name], 0.7
    solid = extrude(poly, h, center=center)
    exact = poly.area * h
    assert volume(solid) == pytest.approx(exact, rel=1e-9)
    # Along a tilted axis the sections are not prisms: the adaptive rule stops at its default tol = 1e-4.
    if len(convex_partition(poly)) <= 12:  # its cost grows with the pieces' breakpoints
        assert volume(solid, axis=(0.3, -0.2, 1.0)) == pytest.approx(exact, rel=1e-4)
    # manifold3d keeps its vertices in float32 precision: its volume agrees to about 1e-8.
    assert manifold_extrusion(poly, h).volume() == pytest.approx(exact, rel=1e-7)
    lo, hi = solid.bounds[:, 2]
    assert (lo, hi) == ((-h / 2, h / 2) if center else (0.0, h))


def test_a_convex_polygon_is_one_prism() -> None:
    s = extrude(Polygon([(0, 0), (2, 0), (2, 1), (0, 1)]), 3.0)
    assert isinstance(s, ConvexPolyhedron)
    assert s.volume == 6.0


@pytest.mark.parametrize("name", ["l_shape", "frame", "star"], ids=str)
def test_points_inside_match_the_polygon(name: str) -> None:
    poly = POLYGONS[name]
    solid = extrude(poly, 1.0)
    rng = np.random.default_rng(7)
    lo, hi = np.array(poly.bounds[:2]), np.array(poly.bounds[2:])
    xy = rng.uniform(lo - 0.2, hi + 0.2, size=(2000, 2))
    z = rng.uniform(-0.2, 1.2, size=2000)
    import shapely

    expected = shapely.contains_xy(poly, xy[:, 0], xy[:, 1]) & (z > 0) & (z < 1)
    # Points within 1e-9 of the boundary are ambiguous; there are none at these random draws.
    d = shapely.distance(poly.boundary, shapely.points(xy))
    keep = (d > 1e-6) & (np.abs(z) > 1e-6) & (np.abs(z - 1) > 1e-6)
    got = solid.contains(np.column_stack([xy, z]))
    assert np.array_equal(got[keep], expected[keep])


def test_cross_checks_with_manifold_booleans() -> None:
    """vol(E & B) from isocsg against manifold3d's Boolean of its own extrusion and box."""
    from isocsg import Box

    poly, h = POLYGONS["frame"], 1.0
    box = Box((1.0, 1.5, 0.5), (2.2, 2.0, 0.6))
    ours = volume(extrude(poly, h) & box, method="sections")  # not manifold3d's own answer
    ref = (manifold_extrusion(poly, h) ^ m3.Manifold.cube((2.2, 2.0, 0.6), True).translate((1.0, 1.5, 0.5))).volume()
    assert ours == pytest.approx(ref, rel=1e-9)


BAD = [
    ("not a polygon", lambda: extrude([(0, 0), (1, 0), (0, 1)], 1.0), "polygon must be a shapely Polygon or MultiPolygon, got list"),
    ("zero height", lambda: extrude(POLYGONS["triangle"], 0.0), "extrude.height must be > 0, got 0"),
    ("bow tie", lambda: extrude(Polygon([(0, 0), (1, 1), (1, 0), (0, 1)]), 1.0), "extrude.polygon must be a valid polygon"),
    ("empty", lambda: extrude(Polygon(), 1.0), "extrude.polygon must have an area > 0"),
    ("nan", lambda: extrude(Polygon([(0, 0), (1, 0), (0, math.nan)]), 1.0), "extrude.polygon must have finite coordinates"),
    ("center", lambda: extrude(POLYGONS["triangle"], 1.0, center=1), "extrude.center must be a boolean, got int"),
]


@pytest.mark.filterwarnings("ignore:invalid value encountered")  # shapely, building the NaN case
@pytest.mark.parametrize("make, message", [b[1:] for b in BAD], ids=[b[0] for b in BAD])
def test_bad_input_names_the_field(make, message: str) -> None:
    with pytest.raises(InvalidGeometryError, match=re.escape(message)):
        make()


SCENE = """
[camera]
eye = [4.0, -5.0, 4.5]
target = [1.5, 1.0, 0.3]
fov = 40
width = 120
height = 96
[[lights]]
kind = "point"
position = [5.0, -3.0, 8.0]
[[objects]]
shape = {{ extrude = {{ {fields} }} }}
"""


def test_scene_file_extrude_node() -> None:
    scene = loads_scene(SCENE.format(fields="polygon = [[0, 0], [4, 0], [4, 3], [0, 3]], holes = [[[1, 1], [3, 1], [3, 2], [1, 2]]], height = 0.6"))
    assert volume(scene.objects[0].shape) == pytest.approx(10 * 0.6, rel=1e-12)


@pytest.mark.parametrize(
    "fields, message",
    [
        ("polygon = [[0, 0], [1, 0]], height = 1", "objects[0].shape.extrude.polygon: must have at least 3 points, got 2"),
        ("polygon = [[0, 0], [1, 0], [0, 1]], height = -1", "objects[0].shape.extrude.height: must be > 0, got -1"),
        ("polygon = [[0, 0], [1, 0], [0, 1]], height = 1, holes = [[[0, 0]]]", "objects[0].shape.extrude.holes[0]: must have at least 3 points, got 1"),
        ("polygon = [[0, 0], [1, 0], [0, \"a\"]], height = 1", "objects[0].shape.extrude.polygon: must hold finite numbers"),
        ("polygon = [[0, 0], [1, 0], [0, 1]]", "objects[0].shape.extrude.height: missing required field"),
        ("polygon = [[0, 0], [1, 0], [0, 1]], height = 1, twist = 3", "objects[0].shape.extrude: unknown key 'twist'"),
    ],
    ids=["few points", "height", "hole", "string", "missing", "unknown"],
)
def test_scene_file_errors_name_the_field(fields: str, message: str) -> None:
    from isocsg import SceneFileError

    with pytest.raises(SceneFileError, match=re.escape(message)):
        loads_scene(SCENE.format(fields=fields))


@pytest.mark.parametrize("name", ["l_shape", "frame", "star", "comb"], ids=str)
def test_image_matches_the_ray_caster(name: str) -> None:
    poly = POLYGONS[name]
    solid = extrude(poly, 0.8)
    assert isinstance(solid, (Union, ConvexPolyhedron))
    c = np.array(poly.centroid.coords[0])
    camera = Camera(eye=(c[0] + 3.5, c[1] - 5.0, 4.5), target=(c[0], c[1], 0.3), fov=45, width=120, height=96)
    scene = Scene(camera, [PointLight((c[0] + 3.0, c[1] - 2.0, 6.0))], [SceneObject(solid)])
    result = compare(render_image(scene), raycast_scene(scene))
    assert result.iou >= 0.99, result.summary()
    assert result.fraction >= 0.98, result.summary()
