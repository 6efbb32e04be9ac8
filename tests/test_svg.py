"""SVG output: the visible bands as polygons, back to front.

Judged by painting the SVG's polygons in file order at the pixel centres with
an independent point-in-triangle test written here: the result must be the
depth-tested PNG image (away from polygon edges), which only holds if the
order is back to front and every polygon carries its band's grey.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from isocsg import Box, Camera, Cylinder, InvalidParameterError, PointLight, Scene, Sphere
from isocsg.cli import main
from isocsg.laminae import build_laminae
from isocsg.rendering import render
from isocsg.rendering.image import to_uint8
from isocsg.rendering.svg import save_scene_svg, scene_polygons

NS = "{http://www.w3.org/2000/svg}"


def read_svg(path: Path) -> tuple[list[np.ndarray], list[int]]:
    """Polygons (pixel coordinates) and their grey levels, in file order."""
    root = ET.parse(path).getroot()
    polys, greys = [], []
    for el in root.iter(f"{NS}polygon"):
        pts = np.array([[float(v) for v in p.split(",")] for p in el.get("points").split()])
        fill = el.get("fill")
        if fill.startswith("#"):
            grey = int(fill[1:3], 16)
        else:  # rgb(g,g,g)
            grey = int(fill[fill.index("(") + 1 : fill.index(",")])
        polys.append(pts)
        greys.append(grey)
    return polys, greys


def paint(polys: list[np.ndarray], greys: list[int], width: int, height: int) -> np.ndarray:
    """Painter's algorithm at pixel centres: later polygons cover earlier ones (-1: background)."""
    img = np.full((height, width), -1, np.int32)
    for pts, g in zip(polys, greys):
        c0, r0 = np.floor(pts.min(axis=0)).astype(int)
        c1, r1 = np.ceil(pts.max(axis=0)).astype(int)
        c0, r0 = max(c0, 0), max(r0, 0)
        c1, r1 = min(c1 + 1, width), min(r1 + 1, height)
        if c0 >= c1 or r0 >= r1:
            continue
        jj, ii = np.meshgrid(np.arange(c0, c1) + 0.5, np.arange(r0, r1) + 0.5)
        k = len(pts)
        area = sum(pts[m, 0] * pts[(m + 1) % k, 1] - pts[(m + 1) % k, 0] * pts[m, 1] for m in range(k))
        inside = np.ones(jj.shape, bool)
        for m in range(k):
            a, b = pts[m], pts[(m + 1) % k]
            inside &= ((b[0] - a[0]) * (ii - a[1]) - (b[1] - a[1]) * (jj - a[0])) * np.sign(area) >= 0
        img[r0:r1, c0:c1][inside] = g
    return img


def uniform_3x3(a: np.ndarray) -> np.ndarray:
    """True where the 3x3 neighbourhood holds one value (image borders excluded)."""
    out = np.zeros(a.shape, bool)
    c = a[1:-1, 1:-1]
    ok = np.ones(c.shape, bool)
    for di in (0, 1, 2):
        for dj in (0, 1, 2):
            ok &= a[di : di + c.shape[0], dj : dj + c.shape[1]] == c
    out[1:-1, 1:-1] = ok
    return out


CONTOURS = 5

SCENES = {
    "sphere": Scene(Camera((0.5, -5, 1.5), (0, 0, 0), width=96, height=80), [PointLight((3, -4, 5))],
                    [Sphere((0, 0, 0), 1.0)]),
    # Two lights cut each part (box face, cylinder side) at its own levels: bands a few
    # pixels wide, so the image is large enough to hold 300 pixels inside them.
    "three_objects": Scene(
        Camera((1.0, -6, 2.0), (0, 0, 0), width=240, height=180), [PointLight((3, -4, 5)), PointLight((-4, -2, 2), 0.5)],
        [Box((0.9, 1.2, -0.3), (1.2, 1.2, 1.2)), Sphere((-0.5, 0, 0), 0.8), Cylinder((0.6, -1.0, 0), (0, 0, 1.2), 0.4)],
    ),
}


@pytest.mark.parametrize("name", list(SCENES), ids=str)
def test_svg_painted_back_to_front_is_the_rendered_image(name: str, tmp_path: Path) -> None:
    scene = SCENES[name]
    path = tmp_path / "out.svg"
    save_scene_svg(path, scene, contours=CONTOURS, decimals=3)  # few contours: broad bands
    polys, greys = read_svg(path)
    cam = scene.camera
    painted = paint(polys, greys, cam.width, cam.height)
    image = render(scene, contours=CONTOURS).image
    expected = np.where(np.isfinite(image), to_uint8(image).astype(np.int32), -1)
    # Away from band and object boundaries (where a pixel centre may fall on
    # either side of an edge), the painted SVG must be the depth-tested image.
    interior = uniform_3x3(expected)
    assert (interior & (expected >= 0)).sum() > 300
    agree = painted[interior] == expected[interior]
    assert agree.all(), f"{name}: {int((~agree).sum())} of {agree.size} interior pixels differ"


def _independent_front_triangles(scene: Scene, k: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Object k's band triangles projected with ``Camera.project``; front / edge-on decided in 3D.

    Returns screen triangles, values, and a code per triangle: 1 clearly
    front-facing, 0 nearly edge-on (either answer is right), -1 back-facing.
    """
    obj = scene.objects[k]
    bands = build_laminae(obj.shape, scene.lights, obj.material, CONTOURS, eye=scene.camera.eye).bands
    v = np.asarray(bands.vertices)
    t = np.asarray(bands.triangles)
    col, row, _ = scene.camera.project(v)
    tri = np.stack([col, row], axis=1)[t]
    a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
    n = np.cross(b - a, c - a)  # outward: counter-clockwise seen from outside
    to_eye = np.asarray(scene.camera.eye, float) - (a + b + c) / 3
    cos = np.einsum("ij,ij->i", n, to_eye) / (np.linalg.norm(n, axis=1) * np.linalg.norm(to_eye, axis=1) + 1e-300)
    code = np.where(cos > 1e-7, 1, np.where(cos < -1e-7, -1, 0))
    return tri, np.asarray(bands.value_out, float), code


def _keys(tri: np.ndarray) -> list[tuple[float, ...]]:
    return [tuple(np.round(x, 6)) for x in np.reshape(tri, (len(tri), 6))]


@pytest.mark.parametrize("name", list(SCENES), ids=str)
def test_svg_polygons_are_the_front_band_triangles(name: str) -> None:
    scene = SCENES[name]
    out = scene_polygons(scene, contours=CONTOURS)
    assert out.polygons.shape == (len(out), 3, 2) and out.values.shape == out.object_index.shape == (len(out),)
    assert sorted(out.object_order) == list(range(len(scene.objects)))
    for k in range(len(scene.objects)):
        tri, values, code = _independent_front_triangles(scene, k)
        mine = out.object_index == k
        got = dict(zip(_keys(out.polygons[mine]), out.values[mine]))
        assert len(got) == int(mine.sum()), "a triangle is written twice"
        expected_front = dict(zip(_keys(tri[code == 1]), values[code == 1]))
        edge_on = set(_keys(tri[code == 0]))
        assert set(expected_front) <= set(got), f"objects[{k}]: front band triangles missing"
        assert set(got) <= set(expected_front) | edge_on, f"objects[{k}]: back-facing triangles written"
        assert all(got[key] == val for key, val in expected_front.items()), f"objects[{k}]: wrong band values"
        # Within one object: farthest first.
        assert np.all(np.diff(out.depth[mine]) <= 0)
    # Each object's triangles form one contiguous block, in object_order.
    blocks = out.object_index[np.r_[0, np.flatnonzero(np.diff(out.object_index)) + 1]]
    assert tuple(blocks.tolist()) == out.object_order


def test_svg_file_holds_the_polygons_and_their_greys(tmp_path: Path) -> None:
    scene = SCENES["three_objects"]
    path = tmp_path / "o.svg"
    out = save_scene_svg(path, scene, contours=CONTOURS, decimals=3)
    polys, greys = read_svg(path)
    assert len(polys) == len(out)
    np.testing.assert_allclose(np.stack(polys), out.polygons, atol=0.5e-3 + 1e-9)
    assert greys == to_uint8(out.values.reshape(1, -1))[0].tolist()
    root = ET.parse(path).getroot()
    assert (root.get("width"), root.get("height")) == (str(scene.camera.width), str(scene.camera.height))


def test_nearer_object_is_drawn_after_the_farther_one() -> None:
    # The sphere stands between the eye and the box and hides part of it; it is
    # listed first, so only the depth can put it last.
    cam = Camera((0, -8, 0.5), (0, 0, 0), width=80, height=60)
    scene = Scene(cam, [PointLight((3, -6, 5))], [Sphere((0.3, -2.0, 0), 0.8), Box((0, 1.0, 0), (2.5, 1.0, 2.0))])
    out = scene_polygons(scene, contours=CONTOURS)
    assert out.object_order == (1, 0)
    assert out.object_index[0] == 1 and out.object_index[-1] == 0


def test_touching_objects_have_an_order() -> None:
    # A ball resting on a plate: their depths meet along the contact only.
    cam = Camera((2.0, -6, 3.0), (0, 0, 0.3), width=96, height=72)
    scene = Scene(cam, [PointLight((3, -4, 6))], [Sphere((0, 0, 0.9), 0.8), Box((0, 0, 0), (3.0, 2.0, 0.2))])
    out = scene_polygons(scene, contours=CONTOURS)
    assert out.object_order == (1, 0)  # the plate first, the ball on top of it


@pytest.mark.parametrize(
    ("scene", "match"),
    [
        (Scene(Camera((0, -5, 0), (0, 0, 0), width=32, height=32), [PointLight((3, -4, 5))],
               [Sphere((0, 0, 0), 1.0) - Box((1, 0, 0), (1, 1, 1))]), r"objects\[0\] is a CSG tree"),
        (Scene(Camera((0, -6, 0), (0, 0, 0), width=48, height=40), [PointLight((3, -4, 5))],
               [Sphere((0, 0, 0), 1.0), Cylinder((0, 0, 0), (3.0, 2.0, 0), 0.3)]), r"objects\[0\] and objects\[1\].*interpenetrate"),
        (Scene(Camera((0, -3, 0), (0, 0, 0), width=32, height=32), [PointLight((3, -4, 5))],
               [Cylinder((0, -2, 0), (0, 4, 0), 0.5)]), r"objects\[0\] reaches behind the eye"),
    ],
    ids=["csg", "interpenetrating", "behind-eye"],
)
def test_svg_rejects_scenes_without_a_polygon_order(scene: Scene, match: str) -> None:
    with pytest.raises(InvalidParameterError, match=match):
        scene_polygons(scene, contours=CONTOURS)


def test_cli_writes_svg(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    scene_file = tmp_path / "s.toml"
    scene_file.write_text(
        "[camera]\neye = [0, -5, 1]\ntarget = [0, 0, 0]\nwidth = 48\nheight = 40\n"
        "[render]\ncontours = 8\n"
        "[[lights]]\nkind = \"point\"\nposition = [3, -4, 5]\n"
        "[[objects]]\nshape = {sphere = {center = [0, 0, 0], radius = 1}}\n"
    )
    out = tmp_path / "o.png"
    svg = tmp_path / "o.svg"
    assert main(["render", str(scene_file), "-o", str(out), "--svg", str(svg), "--no-progress"]) == 0
    polys, greys = read_svg(svg)
    png = np.asarray(Image.open(out), dtype=np.int32)
    painted = paint(polys, greys, 48, 40)
    interior = uniform_3x3(png) & uniform_3x3(np.where(painted < 0, 0, painted))
    assert interior.sum() > 300 and np.array_equal(np.where(painted < 0, 0, painted)[interior], png[interior])
    capsys.readouterr()
    assert main(["render", str(scene_file), "-o", str(out), "--svg", str(tmp_path / "o.txt"), "--no-progress"]) == 2
    assert "--svg" in capsys.readouterr().err


def test_cli_refuses_svg_of_csg_before_rendering(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    scene_file = tmp_path / "s.toml"
    scene_file.write_text(
        "[camera]\neye = [0, -5, 1]\ntarget = [0, 0, 0]\nwidth = 48\nheight = 40\n"
        "[[lights]]\nkind = \"point\"\nposition = [3, -4, 5]\n"
        "[[objects]]\nshape = {difference = [{sphere = {center = [0, 0, 0], radius = 1}},"
        " {box = {center = [1, 0, 0], size = [1, 1, 1]}}]}\n"
    )
    out = tmp_path / "o.png"
    assert main(["render", str(scene_file), "-o", str(out), "--svg", str(tmp_path / "o.svg"), "--no-progress"]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "objects[0]" in err
    assert not out.exists()
