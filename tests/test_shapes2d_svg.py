"""SVG drawings (``isocsg.shapes2d.svg``) read as OpenSCAD 2021.01 reads them.

- The ``svg_*`` models of ``tests/data/openscad/projection22`` (extruded SVG drawings: holes,
  rounded rectangles, circles, ellipses, polygons, group transforms, Béziers, smooth curves,
  arcs, units, ``dpi``, ``center``) against the volumes of OpenSCAD's STL exports
  (``stl_volumes.json``): within 1e-5 (OpenSCAD snaps the drawing to Clipper's integer grid and
  prints 6 digits).
- Closed forms: a rectangle in each page unit, a viewBox scaled into the page, y flipped.
- Refusals that name the element: strokes (open paths, lines, polylines), malformed files.
"""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path

import pytest

from isocsg import volume
from isocsg.errors import InvalidGeometryError
from isocsg.openscad import read_openscad
from isocsg.shapes2d import area, bounds

pytest.importorskip("svgelements")
from isocsg.shapes2d.svg import import_svg  # noqa: E402

DIR = Path(__file__).resolve().parent / "data" / "openscad" / "projection22"
VOLUMES = json.loads((DIR / "stl_volumes.json").read_text())["models"]
MODELS = sorted(p.stem for p in DIR.glob("svg_*.scad"))


@pytest.mark.parametrize("name", MODELS)
def test_svg_volume_matches_openscad(name: str) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        got = volume(read_openscad(DIR / f"{name}.csg").solid)
    assert got == pytest.approx(VOLUMES[name]["volume"], rel=1e-5)


def _svg(tmp_path: Path, body: str, page: str) -> Path:
    p = tmp_path / "d.svg"
    p.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" {page}>{body}</svg>')
    return p


@pytest.mark.parametrize(
    ("page", "mm_per_unit"),
    [
        ('width="100mm" height="50mm"', 1.0),  # no viewBox: a user unit is a millimetre
        ('width="100mm" height="50mm" viewBox="0 0 200 100"', 0.5),
        ('width="4in" height="2in" viewBox="0 0 400 200"', 25.4 / 100),
        ('width="200px" height="100px" viewBox="0 0 200 100"', 25.4 / 96),
        ('width="200" height="100" viewBox="0 0 200 100"', 25.4 / 72),  # unitless: the dpi
        ('width="100mm" height="100mm" viewBox="0 0 200 100"', 0.5),  # meet: the smaller scale
    ],
)
def test_page_units(tmp_path: Path, page: str, mm_per_unit: float) -> None:
    shape = import_svg(_svg(tmp_path, '<rect x="10" y="20" width="30" height="40"/>', page))
    assert area(shape) == pytest.approx(1200 * mm_per_unit**2, rel=1e-12)
    x0, y0, x1, y1 = bounds(shape)
    assert x1 - x0 == pytest.approx(30 * mm_per_unit, rel=1e-12)
    assert y1 - y0 == pytest.approx(40 * mm_per_unit, rel=1e-12)


def test_y_is_flipped_and_center_centres(tmp_path: Path) -> None:
    p = _svg(tmp_path, '<rect x="10" y="20" width="30" height="40"/>', 'width="100mm" height="100mm"')
    assert bounds(import_svg(p)) == pytest.approx((10, 40, 40, 80))  # y = 100 - y_svg
    assert bounds(import_svg(p, center=True)) == pytest.approx((-15, -20, 15, 20))


def test_holes_by_the_even_odd_rule_and_elements_united(tmp_path: Path) -> None:
    body = ('<path d="M 0 0 H 10 V 10 H 0 Z M 2 2 H 8 V 8 H 2 Z"/>'  # same winding: even-odd makes a hole
            '<circle cx="5" cy="5" r="1"/>')
    shape = import_svg(_svg(tmp_path, body, 'width="10mm" height="10mm"'))
    forty_gon = 20 * math.sin(2 * math.pi / 40)  # OpenSCAD's 40 points on a unit circle
    assert area(shape) == pytest.approx(100 - 36 + forty_gon, rel=1e-12)


@pytest.mark.parametrize(
    ("body", "what"),
    [
        ('<path d="M 0 0 L 10 0 L 10 10"/>', "<path>: an open path"),
        ('<line x1="0" y1="0" x2="5" y2="5"/>', "<line> is drawn by OpenSCAD as a stroke"),
        ('<polyline points="0,0 5,5 5,0"/>', "<polyline> is drawn by OpenSCAD as a stroke"),
        ('<path d="M 0 0 L 10"/>', "malformed path data"),
    ],
)
def test_strokes_and_malformed_paths_are_refused_naming_the_element(tmp_path: Path, body: str, what: str) -> None:
    with pytest.raises(InvalidGeometryError, match=what):
        import_svg(_svg(tmp_path, body, 'width="10mm" height="10mm"'))


def test_malformed_files_are_refused(tmp_path: Path) -> None:
    bad = tmp_path / "bad.svg"
    bad.write_text("<svg><rect")
    with pytest.raises(InvalidGeometryError, match="not a well-formed SVG file"):
        import_svg(bad)
    with pytest.raises(InvalidGeometryError, match="not a readable SVG file"):
        import_svg(tmp_path / "missing.svg")
    with pytest.raises(InvalidGeometryError, match="import.dpi"):
        import_svg(bad, dpi=0)
