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

from isocsg import Box, Camera, Cylinder, InvalidParameterError, PointLight, Scene, Sphere
from isocsg.cli import main
from isocsg.render import render
from isocsg.render.image import to_uint8
from isocsg.render.svg import save_scene_svg, scene_polygons

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
    "three_objects": Scene(
        Camera((1.0, -6, 2.0), (0, 0, 0), width=120, height=90), [PointLight((3, -4, 5)), PointLight((-4, -2, 2), 0.5)],
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
    assert agree.mean() > 0.995, f"{name}: {agree.mean():.4f} of interior pixels agree"


def test_svg_polygon_count_and_order_follow_the_bands() -> None:
    scene = SCENES["three_objects"]
    polys, values = scene_polygons(scene)
    assert len(polys) == len(values) > 100
    assert all(p.shape == (3, 2) for p in polys)


def test_svg_rejects_csg_objects() -> None:
    scene = Scene(Camera((0, -5, 0), (0, 0, 0), width=32, height=32), [PointLight((3, -4, 5))],
                  [Sphere((0, 0, 0), 1.0) - Box((1, 0, 0), (1, 1, 1))])
    with pytest.raises(InvalidParameterError, match=r"objects\[0\]"):
        scene_polygons(scene)


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
    assert len(polys) > 50 and out.exists()
    assert main(["render", str(scene_file), "-o", str(out), "--svg", str(tmp_path / "o.txt"), "--no-progress"]) == 2
    assert "--svg" in capsys.readouterr().err
