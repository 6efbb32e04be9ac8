"""Meshes from files and from OpenSCAD: ``import()``, ``surface()`` and non-convex ``polyhedron``.

``tests/data/openscad/mesh22`` holds small models written for these tests with the mesh files
they read (made by its ``generate.py`` from closed forms), ``openscad``'s ``.csg`` export of each
and the volume of ``openscad``'s STL export (``stl_volumes.json``, with the ``.scad``'s sha256):

- the ``.csg`` loads and its volume is OpenSCAD's to the 6-digit rounding of the STL's vertices
  (2e-5) when the model is all meshes, within 0.5 % when it holds a round solid;
- where ``openscad`` is installed, the committed ``.csg`` is the program's export of the ``.scad``;
- each mesh file read alone has the volume of its closed form; malformed, open and missing files,
  2D imports and bad height maps raise errors that name the file (and the node's line).
"""

from __future__ import annotations

import hashlib
import json
import math
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

import isocsg
from isocsg import InvalidGeometryError, OpenSCADError, TriangleMesh
from isocsg.kinds.mesh_io import height_map, polygon_mesh, read_height_map, read_mesh
from isocsg.openscad import load_openscad, loads_openscad

DIR = Path(__file__).resolve().parent / "data" / "openscad" / "mesh22"
MODELS = sorted(p.stem for p in DIR.glob("*.scad"))
VOLUMES = json.loads((DIR / "stl_volumes.json").read_text())["models"]
HAS_OPENSCAD = shutil.which("openscad") is not None
needs_openscad = pytest.mark.skipif(not HAS_OPENSCAD, reason="the openscad program is not installed")
#: Models with a round solid (a sphere at $fn = 96): OpenSCAD's is polygonal.
ROUND = {"polyhedron_dent"}


def test_corpus_is_complete() -> None:
    assert len(MODELS) >= 9
    assert sorted(VOLUMES) == MODELS
    assert all((DIR / f"{m}.csg").is_file() for m in MODELS)


@pytest.mark.parametrize("name", MODELS)
def test_volume_matches_openscad(name: str) -> None:
    got = isocsg.volume(load_openscad(DIR / f"{name}.csg"), tol=1e-6)
    want = VOLUMES[name]["volume"]
    rtol = 0.005 if name in ROUND else 2e-5
    assert abs(got - want) <= rtol * want, (name, got, want, got / want - 1)


@needs_openscad
@pytest.mark.parametrize("name", MODELS)
def test_committed_export_is_current(name: str, tmp_path: Path) -> None:
    scad = DIR / f"{name}.scad"
    assert VOLUMES[name]["sha256"] == hashlib.sha256(scad.read_bytes()).hexdigest(), "run generate.py"
    out = tmp_path / "m.csg"
    subprocess.run(["openscad", "-o", str(out), str(scad)], capture_output=True, check=True, timeout=120)
    strip = lambda t: re.sub(r"timestamp = \d+", "timestamp = 0", t)  # noqa: E731 - files' times
    assert strip(out.read_text()) == strip((DIR / f"{name}.csg").read_text())


def test_scad_file_loads_through_openscad_with_relative_paths(tmp_path: Path) -> None:
    """A ``.scad`` (converted in a temporary directory) still finds its files beside it."""
    if not HAS_OPENSCAD:
        pytest.skip("the openscad program is not installed")
    solid = load_openscad(DIR / "import_stl.scad")
    assert math.isclose(isocsg.volume(solid), VOLUMES["import_stl"]["volume"], rel_tol=2e-5)


# ----------------------------------------------------------------------------- mesh files alone


@pytest.mark.parametrize("name, volume", [
    ("bracket.stl", (30 * 5 + 5 * 15) * 12.0),
    ("steps.obj", (10 * 3 + 4 * 3) * 4.0),
    ("notch.3mf", (64 - 0.5 * 2 * 4) * 2.5),  # the notch: a triangle of base 2 and height 4
])
def test_mesh_files_have_their_closed_form_volumes(name: str, volume: float) -> None:
    mesh = read_mesh(DIR / name)
    assert math.isclose(mesh.volume, volume, rel_tol=1e-6)  # STL keeps float32 coordinates


def test_off_ring_volume_is_the_annulus_prism() -> None:
    mesh = read_mesh(DIR / "ring.off")
    n = 24
    polygon = 0.5 * n * math.sin(2 * math.pi / n)  # a regular n-gon of circumradius 1
    assert math.isclose(mesh.volume, polygon * (7.0**2 - 4.0**2) * 3.0, rel_tol=1e-9)  # the file's digits


def test_height_map_closed_form() -> None:
    """A plane z = a x + b y + c over an n x m grid: the cell centres lie on it, so the top is the
    plane and the volume is the grid's area times the mean height above the base."""
    a, b, c = 0.3, -0.2, 5.0
    x, y = np.meshgrid(np.arange(6), np.arange(4))
    H = a * x + b * y + c
    base = H.min() - 1.0
    mesh = height_map(H)
    mean = a * 2.5 + b * 1.5 + c
    assert math.isclose(mesh.volume, 5 * 3 * (mean - base), rel_tol=1e-13)
    centred = height_map(H, center=True)
    assert np.allclose(centred.bounds, [[-2.5, -1.5, base], [2.5, 1.5, H.max()]])


def test_dat_and_png_readers_follow_openscad(tmp_path: Path) -> None:
    from PIL import Image

    dat = tmp_path / "h.dat"
    dat.write_text("# comment\n\n1 2 3\n4\t5\n")
    H, base = read_height_map(dat)
    assert H.tolist() == [[1, 2, 3], [4, 5, 0]] and base == 0.0  # short rows padded with 0; min(1, min) - 1
    png = tmp_path / "h.png"
    Image.fromarray(np.array([[[255, 0, 0], [0, 255, 0]], [[0, 0, 255], [10, 10, 10]]], np.uint8), "RGB").save(png)
    Z, base = read_height_map(png)
    lum = np.array([[0.0722 * 255, 10.0], [0.2126 * 255, 0.7152 * 255]])  # rows flipped: the image's top is y = 1
    assert np.allclose(Z, 100 / 255 * lum) and math.isclose(base, Z.min() - 1)
    Zi, _ = read_height_map(png, invert=True)
    assert np.allclose(Zi, 100 / 255 * (1 - lum))


def test_polygon_faces_non_convex_and_either_winding() -> None:
    pts = [[0, 0, 0], [4, 0, 0], [4, 1, 0], [1, 1, 0], [1, 3, 0], [0, 3, 0],
           [0, 0, 2], [4, 0, 2], [4, 1, 2], [1, 1, 2], [1, 3, 2], [0, 3, 2]]
    cw = [[0, 1, 2, 3, 4, 5], [11, 10, 9, 8, 7, 6], [6, 7, 1, 0], [7, 8, 2, 1], [8, 9, 3, 2], [9, 10, 4, 3],
          [10, 11, 5, 4], [11, 6, 0, 5]]
    a = polygon_mesh(pts, cw)
    b = polygon_mesh(pts, [f[::-1] for f in cw])
    assert a.volume == b.volume == 12.0


# ----------------------------------------------------------------------------- errors


def _csg(tmp_path: Path, text: str) -> Path:
    p = tmp_path / "m.csg"
    p.write_text("cube(size = [1, 1, 1]);\n" + text + "\n")
    return p


def test_missing_file_is_left_out_naming_the_file_and_line(tmp_path: Path) -> None:
    """OpenSCAD warns "Can't open import file" and draws nothing of the node: so does the reader, warned."""
    from isocsg.openscad import OpenSCADLenientWarning

    p = _csg(tmp_path, 'import(file = "nothing.stl", convexity = 2);')
    with pytest.warns(OpenSCADLenientWarning, match=re.escape("m.csg:2: import(): the file 'nothing.stl' does not exist")):
        load_openscad(p)
    p = _csg(tmp_path, 'surface(file = "none.dat", center = false);')
    with pytest.warns(OpenSCADLenientWarning, match=re.escape("m.csg:2: surface(): the file 'none.dat' does not exist")):
        load_openscad(p)


def test_2d_imports_beside_3d_objects_are_ignored_as_openscad_does(tmp_path: Path) -> None:
    from isocsg.openscad.flat import MixedDimensionsWarning

    p = _csg(tmp_path, 'import(file = "plate.svg");')
    with pytest.warns(MixedDimensionsWarning, match="ignoring the 2D object import"):
        assert isocsg.volume(load_openscad(p)) == 1.0


@pytest.mark.parametrize("content, message", [
    (b"", "holds no triangles"),
    (b"solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 nan\nendloop\nendfacet\nendsolid\n", "mesh file"),
    (b"\x00\x01garbage" * 10, "mesh file"),
], ids=["empty", "nan", "garbage"])
def test_malformed_stl_files_raise_naming_the_file(tmp_path: Path, content: bytes, message: str) -> None:
    f = tmp_path / "bad.stl"
    f.write_bytes(content)
    with pytest.raises(InvalidGeometryError, match=re.escape(message)):
        read_mesh(f)
    with pytest.raises(OpenSCADError, match=re.escape("m.csg:2: import: mesh file")):
        load_openscad(_csg(tmp_path, 'import(file = "bad.stl");'))


def test_open_mesh_file_is_refused_and_repaired_on_request(tmp_path: Path) -> None:
    import trimesh

    box = trimesh.creation.box([1, 2, 3])
    open_box = trimesh.Trimesh(box.vertices, box.faces[1:])
    f = tmp_path / "open.stl"
    open_box.export(f)
    with pytest.raises(InvalidGeometryError, match=re.escape("open.stl': TriangleMesh.faces are not closed")):
        read_mesh(f)
    assert math.isclose(read_mesh(f, repair=True).volume, 6.0, rel_tol=1e-6)
    with pytest.raises(OpenSCADError, match="not closed"):
        load_openscad(_csg(tmp_path, 'import(file = "open.stl");'))


def test_bad_height_maps(tmp_path: Path) -> None:
    f = tmp_path / "h.dat"
    f.write_text("1 2 x\n")
    with pytest.raises(InvalidGeometryError, match=re.escape("h.dat', line 1: not a number")):
        read_height_map(f)
    with pytest.raises(InvalidGeometryError, match="must be finite"):
        height_map([[0.0, 1.0], [np.nan, 2.0]])
    with pytest.raises(InvalidGeometryError, match=re.escape("at least 2 x 2 values, got shape (1, 3)")):
        height_map([[0.0, 1.0, 2.0]])
    f.write_text("1 2 3\n")  # one line: OpenSCAD makes nothing; the model is then empty
    with pytest.raises(OpenSCADError, match="the model is empty"):
        loads_openscad(f'surface(file = "{f}");')


def test_non_convex_polyhedron_text_and_save_round_trip() -> None:
    text = ("polyhedron(points = [[0, 0, 0], [2, 0, 0], [2, 2, 0], [0, 2, 0], [1, 1, 0.5], [0, 0, 2], [2, 0, 2], "
            "[2, 2, 2], [0, 2, 2]], faces = [[0, 4, 1], [1, 4, 2], [2, 4, 3], [3, 4, 0], [5, 6, 7, 8], [0, 1, 6, 5], "
            "[1, 2, 7, 6], [2, 3, 8, 7], [3, 0, 5, 8]]);")
    solid = loads_openscad(text)
    assert isinstance(solid, TriangleMesh)
    assert math.isclose(solid.volume, 8 - 4 * 0.5 / 3, rel_tol=1e-14)
    again = loads_openscad(isocsg.dumps_openscad(solid))
    assert math.isclose(again.volume, solid.volume, rel_tol=1e-14)
