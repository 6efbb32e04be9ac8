"""What OpenSCAD 2021.01 draws where a strict reader would refuse (issue 22): nodes it drops with a
warning, mended values, mis-wound meshes, and its own polygonal answer for outlines and twisted
stacks that have no exact form here. Checked against closed forms, and against OpenSCAD's own STL
volume where the program is installed."""

from __future__ import annotations

import math
import shutil
import subprocess
import warnings
from pathlib import Path

import numpy as np
import pytest

from isocsg import volume
from isocsg.errors import OpenSCADError
from isocsg.openscad import OpenSCADLenientWarning, OpenSCADPolygonalWarning, loads_openscad, read_openscad
from isocsg.openscad.lowering import lower
from isocsg.openscad.parser import parse_csg

HAS_OPENSCAD = shutil.which("openscad") is not None
CUBE = "cube(size = [1, 1, 1], center = false);\n"

DROPPED = [
    ("cube(size = [1, inf, 1], center = false);", "size is infinite or NaN"),
    ("sphere($fn = 0, $fa = 12, $fs = 2, r = inf);", "r is infinite or NaN"),
    ("cylinder($fn = 0, $fa = 12, $fs = 2, h = 1, r1 = -nan, r2 = -nan, center = false);", "r1 is infinite or NaN"),
    ("polyhedron(points = undef, faces = undef, convexity = 1);", "no points"),
    (("polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, nan]], faces = [[0, 1, 2], [0, 3, 1], "
      "[0, 2, 3], [1, 3, 2]]);"), "points[3] is not three finite numbers"),
    ("multmatrix([[1, 0, 0, nan], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { cube(size = [5, 5, 5]); }",
     "contains NaN or infinity"),
    ('import(file = "", layer = "", origin = [0, 0], scale = 1, convexity = 1);', "no file name"),
    ('import(file = "nothere.stl", convexity = 1);', "'nothere.stl' does not exist"),
    ('import(file = "part.eps", convexity = 1);', "OpenSCAD reads no .eps files"),
    ('surface(file = "", center = false, invert = false);', "no file name"),
    ('surface(file = "none.dat", center = false, invert = false);', "'none.dat' does not exist"),
    ('linear_extrude(height = 1) { import(file = "none.dxf"); square(size = [5, 5]); }', "'none.dxf' does not exist"),
]


@pytest.mark.parametrize("node, why", DROPPED, ids=[d[1][:30] for d in DROPPED])
def test_what_openscad_draws_as_nothing_is_left_out_with_a_warning(node: str, why: str, tmp_path: Path) -> None:
    """Beside a unit cube, each node adds nothing (OpenSCAD 2021.01's STL of each such model is the
    unit cube alone, volume 1; the linear_extrude keeps its square, which holds the cube: 25), and it is named in a warning."""
    path = tmp_path / "m.csg"
    path.write_text(CUBE + node + "\n")
    with pytest.warns(OpenSCADLenientWarning, match=r"m\.csg:2: ") as record:
        model = read_openscad(path)
    assert any(why in str(w.message) for w in record)
    expected = 25.0 if "square" in node else 1.0  # the square (5 x 5 x 1) holds the unit cube
    assert abs(volume(model.solid) - expected) < 1e-12
    assert any(why in line for line in model.left_out)


def test_infinite_fn_is_three_segments() -> None:
    """``Calc::get_fragments_from_r`` returns 3 for an infinite ``$fn``: a triangular prism of area
    ``3 sqrt(3) / 4 r^2``."""
    with pytest.warns(OpenSCADLenientWarning, match="draws 3 segments"):
        solid = loads_openscad("cylinder($fn = inf, $fa = 12, $fs = 2, h = 2, r1 = 1, r2 = 1, center = false);")
    assert abs(volume(solid) - 3 * math.sqrt(3) / 4 * 2) < 1e-12


def test_colours_outside_0_1_are_clamped() -> None:
    text = "color([2, -0.5, 0.5, 1]) { cube(size = [1, 1, 1]); }\ncolor([-1, -1, -1, 1]) { sphere(r = 1); }"
    with pytest.warns(OpenSCADLenientWarning, match="clamped to"):
        model = lower(parse_csg(text))
    assert model.leaf_colors == ((1.0, 0.0, 0.5), None)


def test_a_projective_last_row_is_ignored_as_openscad_does() -> None:
    """OpenSCAD's transforms are affine: its STL of such a model is the affine part's image: here a 2 x 1 x 1 box moved up by 1."""
    text = "multmatrix([[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 1], [0, 0, -0.5, 1]]) { cube(size = [1, 1, 1]); }"
    with pytest.warns(OpenSCADLenientWarning, match="is not \\[0, 0, 0, 1\\]: ignored"):
        solid = loads_openscad(text)
    assert abs(volume(solid) - 2.0) < 1e-12
    assert np.allclose(solid.bounds, [[0, 0, 1], [2, 1, 2]])  # type: ignore[attr-defined]


def _cube_faces(offset: int) -> list[list[int]]:
    f = [[0, 1, 2, 3], [4, 5, 1, 0], [7, 6, 5, 4], [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3]]
    return [[i + offset for i in face] for face in f]


def _cube_points(x: float, y: float, z: float) -> list[list[float]]:
    return [[x, y, z], [x + 1, y, z], [x + 1, y + 1, z], [x, y + 1, z],
            [x, y, z + 1], [x + 1, y, z + 1], [x + 1, y + 1, z + 1], [x, y + 1, z + 1]]


def test_mis_wound_faces_are_turned_to_one_orientation() -> None:
    """A cube with two faces wound the wrong way (OpenSCAD exports it as a solid): volume 1; two cubes
    sharing an edge (an edge of four faces), one face mis-wound: each body turned, volume 2."""
    faces = _cube_faces(0)
    faces[1] = faces[1][::-1]
    faces[4] = faces[4][::-1]
    text = f"polyhedron(points = {_cube_points(0, 0, 0)}, faces = {faces});"
    with pytest.warns(OpenSCADLenientWarning, match="turned to one outward orientation"):
        assert abs(volume(loads_openscad(text)) - 1.0) < 1e-12
    pts = _cube_points(0, 0, 0) + _cube_points(1, 1, 0)
    pts[8 + 0] = pts[2]  # share the edge (1, 1, 0) - (1, 1, 1)
    pts[8 + 4] = pts[6]
    faces = _cube_faces(0) + _cube_faces(8)
    faces[3] = faces[3][::-1]
    text = f"polyhedron(points = {pts}, faces = {faces});"
    with pytest.warns(OpenSCADLenientWarning):
        assert abs(volume(loads_openscad(text)) - 2.0) < 1e-12


def test_an_open_polyhedron_still_names_the_node() -> None:
    faces = _cube_faces(0)
    faces = faces[:2] + faces[3:]  # no top, and one face mis-wound
    faces[1] = faces[1][::-1]
    with pytest.raises(OpenSCADError, match="line 1: polyhedron: .*does not help: .*an open mesh"):
        loads_openscad(f"polyhedron(points = {_cube_points(0, 0, 0)}, faces = {faces});")


def test_a_projection_without_an_exact_outline_is_openscads_polygon() -> None:
    """The shadow of a sphere (r = 5) minus a ball is OpenSCAD's sphere's widest ring: at ``$fa = 12``,
    ``$fs = 2`` 16 fragments, 8 rings, the widest at the polar angle 78.75 degrees."""
    text = ("linear_extrude(height = 1) { projection(cut = false) { difference() { sphere(r = 5, $fa = 12, $fs = 2); "
            "sphere(r = 1); } } }")
    with warnings.catch_warnings(record=True) as record:
        warnings.simplefilter("always")
        solid = loads_openscad(text, source="m.csg")
    nodes = [w.message for w in record if isinstance(w.message, OpenSCADPolygonalWarning)]
    assert nodes and "m.csg:1: projection()" in nodes[0].nodes[0]
    r = 5 * math.sin(math.radians(78.75))
    area = 8 * r * r * math.sin(math.radians(22.5))
    assert abs(volume(solid) - area) < 1e-8 * area  # manifold3d's 2D outline: points to about 1e-10 of the size


def _openscad_volume(scad: Path) -> float:
    import trimesh

    stl = scad.with_suffix(".stl")
    subprocess.run(["openscad", "-o", str(stl), str(scad)], check=True, capture_output=True, timeout=120)
    return float(trimesh.load(str(stl)).volume)


@pytest.mark.skipif(not HAS_OPENSCAD, reason="the openscad program is not installed (apt install openscad)")
@pytest.mark.parametrize("text", [
    # a twist of 200 degrees in 3 slices: the exact slices' bands cross
    ("linear_extrude(height = 10, twist = 200, slices = 3)\n"
     "  difference() { square(8, center = true); translate([2, 0]) square([5, 2], center = true); }"),
    # example021's part at a coarse $fa: the outline of a sphere minus slanted cones
    ("linear_extrude(height = 1) projection(cut = false) difference() { sphere(r = 5, $fa = 30);\n"
     "  rotate([90, 0, 0]) cylinder(h = 12, r1 = 3, r2 = 1, center = true, $fa = 30);\n"
     "  rotate([0, 90, 0]) cylinder(h = 12, r1 = 3, r2 = 1, center = true, $fa = 30); }"),
], ids=["twist", "projection"])
def test_polygonal_answers_match_openscads_stl(text: str, tmp_path: Path) -> None:
    """OpenSCAD's own STL volume, to its 6 printed digits."""
    scad = tmp_path / "m.scad"
    scad.write_text(text + "\n")
    model = read_openscad(scad)
    assert len(model.polygonal) == 1
    expected = _openscad_volume(scad)
    assert abs(volume(model.solid) - expected) < 2e-5 * expected


def test_mapped_meshes_skip_only_the_crossing_check() -> None:
    """An affine image of a checked mesh is built without the self-intersection check (it cannot
    cross itself); the next mesh built is checked again: two interpenetrating tetrahedra are refused."""
    from isocsg import TriangleMesh
    from isocsg.errors import InvalidGeometryError

    tet = np.array([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)], dtype=float)
    faces = np.array([(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)])
    mapped = TriangleMesh(tet, faces).transform(np.array([[2, 0, 0, 1], [0, 3, 0, 0], [0, 0, 1, 0]], dtype=float))
    assert abs(mapped.volume - 1.0) < 1e-12  # type: ignore[attr-defined]  # 6 x 1/6
    with pytest.raises(InvalidGeometryError, match="intersect themselves"):
        TriangleMesh(np.vstack([tet, tet + 0.2]), np.vstack([faces, faces + 4]))


_TET_AMF = """<?xml version="1.0" encoding="utf-8"?>
<amf unit="inch" version="1.1">{objects}</amf>"""


def _amf_object(points: list[tuple[float, float, float]], volumes: list[list[tuple[int, int, int]]]) -> str:
    vertices = "".join(f"<vertex><coordinates><x>{x}</x><y>{y}</y><z>{z}</z></coordinates></vertex>" for x, y, z in points)
    vols = "".join("<volume>" + "".join(f"<triangle><v1>{a}</v1><v2>{b}</v2><v3>{c}</v3></triangle>" for a, b, c in v)
                   + "</volume>" for v in volumes)
    return f"<object id='1'><mesh><vertices>{vertices}</vertices>{vols}</mesh></object>"


def test_amf_objects_and_volumes(tmp_path: Path) -> None:
    """OpenSCAD's ``import_amf.cc``: units ignored, objects united. A tetrahedron of legs 2 (volume 4/3)
    and, zipped, a second object: a unit cube split in two volumes by its diagonal plane (each 1/2, sharing
    that face), 4 away: volume 4/3 + 1."""
    import zipfile

    tet = _amf_object([(0, 0, 0), (2, 0, 0), (0, 2, 0), (0, 0, 2)], [[(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]])
    cube = [(4 + x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]  # index x + 2 y + 4 z
    half_a = [(0, 2, 1), (4, 5, 6), (0, 1, 5), (0, 5, 4), (0, 4, 6), (0, 6, 2), (1, 2, 6), (1, 6, 5)]
    half_b = [(1, 2, 3), (5, 7, 6), (1, 3, 7), (1, 7, 5), (2, 6, 7), (2, 7, 3), (1, 6, 2), (1, 5, 6)]
    (tmp_path / "tet.amf").write_text(_TET_AMF.format(objects=tet))
    with zipfile.ZipFile(tmp_path / "two.amf", "w") as z:
        z.writestr("two.amf", _TET_AMF.format(objects=tet + _amf_object(cube, [half_a, half_b])))
    for name, expected in (("tet.amf", 4 / 3), ("two.amf", 4 / 3 + 1)):
        (tmp_path / "m.csg").write_text(f'import(file = "{name}", convexity = 1);\n')
        assert abs(volume(read_openscad(tmp_path / "m.csg").solid) - expected) < 1e-12
    (tmp_path / "bad.amf").write_text(_TET_AMF.format(objects=tet.replace("<x>2</x>", "<x>a</x>")))
    (tmp_path / "m.csg").write_text('import(file = "bad.amf");\n')
    with pytest.raises(OpenSCADError, match="m.csg:1: import: .*<x> is not a number, got 'a'"):
        read_openscad(tmp_path / "m.csg")
