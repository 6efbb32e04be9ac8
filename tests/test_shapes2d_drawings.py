"""DXF drawings read as OpenSCAD's ``import`` reads them.

The judges are independent of the reader: areas of the polygons OpenSCAD makes of circles and
arcs, computed here from OpenSCAD's segment rule; the shoelace area of rings written as shuffled
lines; shapely's even-odd area; and, where the ``openscad`` program is installed, the volume of
``linear_extrude(height = 1) import(...)`` exported by OpenSCAD itself.
"""

from __future__ import annotations

import math
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

ezdxf = pytest.importorskip("ezdxf")

from isocsg import InvalidGeometryError, InvalidParameterError  # noqa: E402
from isocsg.shapes2d.drawings import GRID, import_dxf, read_dxf  # noqa: E402


def segments_of(r: float, fn: float = 0, fs: float = 2, fa: float = 12) -> int:
    """OpenSCAD 2021.01's get_fragments_from_r, written again from its source."""
    if fn > 0:
        return int(max(fn, 3))
    return math.ceil(max(min(360 / fa, r * 2 * math.pi / fs), 5))


def shoelace(p: np.ndarray) -> float:
    x, y = p[:, 0], p[:, 1]
    return 0.5 * abs(float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))


def regular(n: int, r: float, start: float = 0.0, sweep: float = 360.0, center=(0.0, 0.0)) -> np.ndarray:  # noqa: ANN001
    """OpenSCAD's points of a circle or arc, on its grid of 1/1024 (it snaps every end point)."""
    a = np.radians(start + sweep * np.arange(n + 1) / n)
    p = np.column_stack([center[0] + r * np.cos(a), center[1] + r * np.sin(a)])
    return np.rint(p / GRID) * GRID


@pytest.fixture
def doc():  # noqa: ANN201 - an ezdxf document
    return ezdxf.new()


def test_square_with_a_round_hole(doc, tmp_path: Path) -> None:  # noqa: ANN001
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (10, 0), (10, 10), (0, 10)], close=True)
    msp.add_circle((5, 5), 3)
    doc.saveas(tmp_path / "a.dxf")
    hole = shoelace(regular(segments_of(3), 3, center=(5, 5))[:-1])
    assert import_dxf(tmp_path / "a.dxf").area == pytest.approx(100 - hole, rel=1e-12)
    # $fn decides the segments when given, as in OpenSCAD
    hole6 = shoelace(regular(6, 3, center=(5, 5))[:-1])
    assert import_dxf(tmp_path / "a.dxf", fn=6).area == pytest.approx(100 - hole6, rel=1e-12)


def test_an_arc_closed_by_a_line(doc, tmp_path: Path) -> None:  # noqa: ANN001
    msp = doc.modelspace()
    msp.add_arc((0, 0), 4, 0, 180)  # counter-clockwise from 0 to 180 degrees
    msp.add_line((-4, 0), (4, 0))
    doc.saveas(tmp_path / "d.dxf")
    n = math.ceil(segments_of(4) * 180 / 360)
    expected = shoelace(regular(n, 4, 0, 180))
    assert import_dxf(tmp_path / "d.dxf").area == pytest.approx(expected, rel=1e-12)


def test_layers_blocks_origin_and_scale(doc, tmp_path: Path) -> None:  # noqa: ANN001
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (2, 0), (2, 1), (0, 1)], close=True, dxfattribs={"layer": "small"})
    msp.add_lwpolyline([(0, 0), (5, 0), (5, 4), (0, 4)], close=True, dxfattribs={"layer": "big"})
    block = doc.blocks.new(name="TRI")
    block.add_lwpolyline([(0, 0), (1, 0), (0, 1)], close=True)
    msp.add_blockref("TRI", (20, 20), dxfattribs={"layer": "blocks", "xscale": 3, "yscale": 2, "rotation": 30})
    doc.saveas(tmp_path / "l.dxf")
    assert import_dxf(tmp_path / "l.dxf", layer="small").area == pytest.approx(2.0)
    assert import_dxf(tmp_path / "l.dxf", layer="big").area == pytest.approx(20.0)
    c, sn = math.cos(math.radians(30)), math.sin(math.radians(30))
    tri = np.array([(20 + c * 3 * x - sn * 2 * y, 20 + sn * 3 * x + c * 2 * y) for x, y in [(0, 0), (1, 0), (0, 1)]])
    expected = shoelace(np.rint(tri / GRID) * GRID)
    assert expected == pytest.approx(3.0, rel=1e-3)
    assert import_dxf(tmp_path / "l.dxf", layer="blocks").area == pytest.approx(expected, rel=1e-12)
    moved = import_dxf(tmp_path / "l.dxf", layer="big", origin=(1, 1), scale=2)
    assert moved.area == pytest.approx(80.0)
    assert np.allclose(np.ravel(moved.bounds), [-2, -2, 8, 6])
    with pytest.raises(InvalidGeometryError, match="layer 'nothing'"):
        import_dxf(tmp_path / "l.dxf", layer="nothing")


def test_malformed_files_name_the_file(tmp_path: Path) -> None:
    bad = tmp_path / "bad.dxf"
    bad.write_text("this is not a drawing\n")
    with pytest.raises(InvalidParameterError, match="bad.dxf"):
        read_dxf(bad)
    with pytest.raises(InvalidParameterError, match="missing.dxf"):
        read_dxf(tmp_path / "missing.dxf")
    with pytest.raises(InvalidParameterError, match="finite"):
        read_dxf(bad, scale=float("nan"))


@settings(max_examples=25, deadline=None)
@given(
    n=st.integers(3, 12),
    radii=st.lists(st.floats(1.0, 5.0), min_size=12, max_size=12),
    order=st.randoms(use_true_random=False),
)
def test_shuffled_lines_join_into_their_ring(n: int, radii: list[float], order) -> None:  # noqa: ANN001
    # A star-shaped ring on OpenSCAD's grid, written as lines in random order and direction.
    a = 2 * np.pi * np.arange(n) / n
    ring = np.rint(np.column_stack([radii[:n] * np.cos(a), radii[:n] * np.sin(a)]) / GRID) * GRID
    doc = ezdxf.new()
    msp = doc.modelspace()
    edges = [(ring[i], ring[(i + 1) % n]) for i in range(n)]
    order.shuffle(edges)
    for p, q in edges:
        if order.random() < 0.5:
            p, q = q, p
        msp.add_line(tuple(p), tuple(q))
    import tempfile

    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "r.dxf"
        doc.saveas(path)
        assert import_dxf(path).area == pytest.approx(shoelace(ring), rel=1e-9)


@pytest.mark.skipif(shutil.which("openscad") is None, reason="the openscad program is not installed")
def test_areas_agree_with_openscads_own_import(doc, tmp_path: Path) -> None:  # noqa: ANN001
    trimesh = pytest.importorskip("trimesh")
    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (30, 0), (30, 20), (0, 20)], close=True, dxfattribs={"layer": "plate"})
    msp.add_circle((8, 10), 4.3, dxfattribs={"layer": "plate"})
    msp.add_arc((22, 10), 5, 90, 270, dxfattribs={"layer": "plate"})
    msp.add_line((22, 15), (26, 15), dxfattribs={"layer": "plate"})
    msp.add_line((26, 15), (26, 5), dxfattribs={"layer": "plate"})
    msp.add_line((26, 5), (22, 5), dxfattribs={"layer": "plate"})
    msp.add_ellipse((15, 3), major_axis=(3, 1), ratio=0.4, dxfattribs={"layer": "plate"})
    doc.saveas(tmp_path / "p.dxf")
    (tmp_path / "p.scad").write_text('linear_extrude(height = 1) import(file = "p.dxf", layer = "plate");\n')
    subprocess.run(["openscad", "-o", str(tmp_path / "p.stl"), str(tmp_path / "p.scad")], check=True,
                   capture_output=True, timeout=120)
    expected = trimesh.load(tmp_path / "p.stl").volume
    assert import_dxf(tmp_path / "p.dxf", layer="plate").area == pytest.approx(expected, rel=1e-5)


def test_openscad_models_extrude_imported_drawings(doc, tmp_path: Path) -> None:  # noqa: ANN001
    from isocsg import load_openscad, volume

    msp = doc.modelspace()
    msp.add_lwpolyline([(0, 0), (6, 0), (6, 4), (0, 4)], close=True, dxfattribs={"layer": "base"})
    msp.add_lwpolyline([(2, 1), (4, 1), (4, 3), (2, 3)], close=True, dxfattribs={"layer": "base"})
    (tmp_path / "parts").mkdir()
    doc.saveas(tmp_path / "parts" / "base.dxf")
    model = tmp_path / "m.csg"
    # The file is found relative to the model's folder, as OpenSCAD finds it.
    model.write_text('linear_extrude(height = 2.5, center = false) import(file = "parts/base.dxf", layer = "base", '
                     'origin = [0, 0], scale = 2, $fn = 0, $fa = 12, $fs = 2);\n')
    assert volume(load_openscad(model)) == pytest.approx((24 - 4) * 4 * 2.5, rel=1e-12)
    from isocsg.openscad import OpenSCADLenientWarning

    for name in ("missing.dxf", "base.svg", "base.eps"):  # missing, or a type OpenSCAD does not read: nothing
        model.write_text(f'linear_extrude(height = 1) import(file = "parts/{name}");\ncube(size = 1);\n')
        with pytest.warns(OpenSCADLenientWarning, match=name):
            assert volume(load_openscad(model)) == pytest.approx(1.0, rel=1e-12)


def test_the_old_forms_name_their_drawing_themselves(doc, tmp_path: Path) -> None:  # noqa: ANN001
    from isocsg import load_openscad, volume

    doc.modelspace().add_lwpolyline([(1, 0), (3, 0), (3, 2), (1, 2)], close=True)
    doc.saveas(tmp_path / "r.dxf")
    model = tmp_path / "m.csg"
    model.write_text('linear_extrude(file = "r.dxf", layer = "", origin = [0, 0], height = 3, center = false, '
                     'scale = [1, 1], $fn = 0, $fa = 12, $fs = 2);\n')
    assert volume(load_openscad(model)) == pytest.approx(4 * 3, rel=1e-12)
    model.write_text('rotate_extrude(file = "r.dxf", layer = "", origin = [0, 0], scale = 1, angle = 360, '
                     '$fn = 0, $fa = 12, $fs = 2);\n')
    # Pappus: the square from x = 1 to 3 turned once about the axis
    assert volume(load_openscad(model)) == pytest.approx(2 * np.pi * 2.0 * 4.0, rel=1e-9)
