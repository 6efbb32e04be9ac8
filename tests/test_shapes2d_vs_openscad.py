"""2D shapes against the openscad program's own exports (skipped where it is not installed).

OpenSCAD draws circles and glyph curves as polygons: with ``$fn`` high the exact shapes must
agree within its tessellation error; with OpenSCAD's own polygons (``circle($fn=n)``, ``text``
with its chords per curve) closely.
"""

from __future__ import annotations

import math
import shutil
import subprocess

import pytest

from isocsg.shapes2d import area, bounds, circle, font_path, offset, polygon, square, text, text_segments

trimesh = pytest.importorskip("trimesh")
pytestmark = pytest.mark.skipif(shutil.which("openscad") is None, reason="the openscad program is not installed")


def _openscad(tmp_path, body: str):
    src = tmp_path / "model.scad"
    out = tmp_path / "model.stl"
    src.write_text(f"use <{font_path()}>\nlinear_extrude(1) {body};\n")
    run = subprocess.run(["openscad", "-o", str(out), str(src)], capture_output=True, text=True, timeout=300)
    if run.returncode != 0 or not out.exists():
        pytest.skip(f"openscad failed: {run.stderr[-300:]}")
    return trimesh.load(str(out))


CASES = [
    ("hexagon", "circle(r=2, $fn=6)", circle(2, fn=6), 1e-6),  # STL files hold single precision
    ("fine circle", "circle(r=2, $fn=720)", circle(2), 2e-5),
    ("holed polygon", "polygon([[0,0],[10,0],[10,10],[0,10],[2,2],[4,2],[4,4],[2,4]], [[0,1,2,3],[4,5,6,7]])",
     polygon([(0, 0), (10, 0), (10, 10), (0, 10), (2, 2), (4, 2), (4, 4), (2, 4)], [[0, 1, 2, 3], [4, 5, 6, 7]]), 1e-6),
    ("rounded square", "offset(r=1, $fn=720) square(4)", offset(square(4), 1), 2e-5),
    ("mitred L", "offset(delta=0.5) polygon([[0,0],[4,0],[4,1],[1,1],[1,4],[0,4]])",
     offset(polygon([(0, 0), (4, 0), (4, 1), (1, 1), (1, 4), (0, 4)]), delta=0.5), 1e-6),
    ("chamfered square", "offset(delta=1, chamfer=true) square(2)", offset(square(2), delta=1, chamfer=True), 1e-6),
    ("plate", "difference() { square(10, center=true); circle(r=2, $fn=720); }", square(10, center=True) - circle(2), 1e-5),
]


@pytest.mark.parametrize("scad, shape, rel", [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_areas_match_openscad(tmp_path, scad, shape, rel):
    mesh = _openscad(tmp_path, scad)
    assert mesh.volume == pytest.approx(area(shape), rel=rel)


@pytest.mark.parametrize(
    "string, size, halign, valign",
    [("Hello", 10, "left", "baseline"), ("Ag", 7, "center", "center"), ("OpenSCAD 2021", 5, "right", "top"), ("gjq", 10, "left", "bottom")],
)
def test_text_matches_openscad(tmp_path, string, size, halign, valign):
    version = subprocess.run(["openscad", "--version"], capture_output=True, text=True).stderr
    mesh = _openscad(tmp_path, f'text("{string}", size={size}, font="DejaVu Sans", halign="{halign}", valign="{valign}")')
    ours = text(string, size, halign=halign, valign=valign, segments=text_segments(size), legacy_metrics="2021." in version)
    assert mesh.volume == pytest.approx(area(ours), rel=1e-3)
    got = mesh.bounds[:, :2].ravel()[[0, 1, 2, 3]]
    assert [round(v, 2) for v in got] == pytest.approx([round(v, 2) for v in bounds(ours)], abs=0.02 * size / 10 + 1e-9)
    assert math.isfinite(area(ours))
