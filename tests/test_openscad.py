"""OpenSCAD input and output: the .csg parser, the lowering to exact solids, errors, the writer.

These tests read .csg text directly and need no ``openscad`` program (the corpus
tests in ``test_openscad_corpus.py`` run it). Volumes are judged by closed forms
and by manifold3d; errors by their exact messages (node name and line).
"""

from __future__ import annotations

import math
import re
import shutil
import subprocess
import warnings

import numpy as np
import pytest
import shapely

import isocsg
from isocsg import (
    Box,
    Cone,
    ConvexPolyhedron,
    Cylinder,
    MissingDependencyError,
    OpenSCADError,
    Sphere,
    Truncus,
    UnsupportedOpenSCADError,
    volume,
)
from isocsg.openscad import OpenSCADSkipWarning, dumps_openscad, loads_openscad, parse_csg, read_openscad


def load(text: str, **kw):
    return loads_openscad(text, source="m.csg", **kw)


# ----------------------------------------------------------------------------- parser


def test_parser_keeps_lines_arguments_and_modifiers() -> None:
    text = (
        "// exported\n"
        "difference() {\n"
        "\tcube(size = [1, 2, 3], center = true);\n"
        "\t/* a block\n comment */ %sphere($fn = 32, $fa = 12, $fs = 2, r = 0.7);\n"
        "\tpolygon(points = [[0, 0], [1, -1e-06], [0, 1]], paths = undef, convexity = 1);\n"
        "\ttext(text = \"a \\\"b\\\"\", size = 10);\n"
        "}\n"
    )
    (diff,) = parse_csg(text)
    assert (diff.name, diff.line, diff.args, diff.kwargs) == ("difference", 2, [], {})
    cube, sphere, poly, txt = diff.children
    assert cube.kwargs == {"size": [1.0, 2.0, 3.0], "center": True} and cube.line == 3
    assert sphere.modifiers == "%" and sphere.line == 5 and sphere.kwargs["r"] == 0.7 and sphere.kwargs["$fn"] == 32
    assert poly.kwargs["points"] == [[0.0, 0.0], [1.0, -1e-06], [0.0, 1.0]] and poly.kwargs["paths"] is None
    assert txt.kwargs["text"] == 'a "b"'


def test_parser_is_iterative_over_deep_nesting() -> None:
    depth = 20000  # far past Python's recursion limit
    text = "group() {\n" * depth + "cube(size = [1, 1, 1]);\n" + "}\n" * depth
    (top,) = parse_csg(text)
    node, levels = top, 1
    while node.children and node.name == "group":
        node, levels = node.children[0], levels + 1
    assert node.name == "cube" and node.line == depth + 1 and levels == depth + 1
    assert volume(load(text)) == pytest.approx(1.0, rel=1e-12)
    # OpenSCAD draws nothing of a polyhedron whose points are not 3-vectors: left out, warned
    from isocsg.openscad import OpenSCADLenientWarning

    nested = "polyhedron(points = " + "[" * 5000 + "]" * 5000 + ", faces = [[0, 1, 2]]);\ncube(size = 1);"
    with pytest.warns(OpenSCADLenientWarning, match=re.escape("m.csg:1: polyhedron(): points[0] is not three")):
        assert volume(load(nested)) == pytest.approx(1.0, rel=1e-12)


MALFORMED = [
    ("cube(size = [1, 1, 1])\n42;", "m.csg:2: expected ';' or '{' after cube(...), got '42'"),
    ("union() {\n  cube(size = 1);\n", "m.csg:3: the block of union opened at line 1 is not closed"),
    ("cube(size = 1);\n}", "m.csg:2: '}' without an open block"),
    ("cube(size = [1, 1 1]);", "m.csg:1: expected ',' or ']' in a list in the arguments of cube, got '1'"),
    ("cube(size = );", "m.csg:1: expected a value in the arguments of cube, got ')'"),
    ("cube(size = 1, center = true", "m.csg:1: expected ',' or ')' in the arguments of cube, got the end of the file"),
    ("\n\ncube(size = 1, true);\ncube(center = true, 2);", "m.csg:3: positional argument after named ones in the arguments of cube"),
    ("cube(size = 1, size = 2);", "m.csg:1: argument 'size' given twice to cube"),
    ("text(text = \"abc);", "m.csg:1: unterminated string"),
    ("cube(size = 1); /* open", "m.csg:1: unterminated /* comment"),
    ("cube(size = 1);\n  @", "m.csg:2: unexpected character '@'"),
    ("= cube(size = 1);", "m.csg:1: expected a module name such as cube or union, got '='"),
    ("cube(size = 1e999);", "m.csg:1: number 1e999 in the arguments of cube is too large for a float"),
    ("cube(size = [0:1:2]);", "m.csg:1: ranges [a:b] are not supported in the arguments of cube"),
    ("cube(size = - [1]);", "m.csg:1: expected a number after the sign in the arguments of cube, got '['"),
    ("cube(size = \"big\");", "m.csg:1: cube: size must be a number or a list of 3 numbers, got 'big'"),
    ("cube(size = [1, 2]);", "m.csg:1: cube: size must be a number or a list of 3 numbers, got [1.0, 2.0]"),
    ("\nsphere(r = true);", "m.csg:2: sphere: r must be a finite number, got True"),
    ("cylinder(h = 1, r1 = 1, r2 = 1, center = 1);", "m.csg:1: cylinder: center must be true or false, got 1.0"),
    ("multmatrix(m = [[1, 0, 0]]) { cube(size = 1); }", "m.csg:1: multmatrix: m must be a 4 x 4 (or 3 x 4) matrix, got [[1.0, 0.0, 0.0]]"),
    ("polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], faces = [[0, 1, 7]]);", "m.csg:1: polyhedron: faces must hold point indices 0 .. 3, got 7.0"),
    ("", "m.csg: the model is empty: nothing of it has a volume"),
    ("cube(size = 0);\nsphere(r = 0);", "m.csg: the model is empty: nothing of it has a volume"),
]


@pytest.mark.parametrize("text, message", MALFORMED, ids=[m[1].split(": ", 1)[1][:40] for m in MALFORMED])
def test_malformed_text_names_the_line(text: str, message: str) -> None:
    with pytest.raises(OpenSCADError, match=re.escape(message)) as info:
        load(text)
    assert not isinstance(info.value, UnsupportedOpenSCADError)
    # The error comes from the module that reads, never from deep in another library.
    tb = info.tb
    while tb.tb_next is not None:
        tb = tb.tb_next
    assert "isocsg" in tb.tb_frame.f_code.co_filename


def test_line_attribute() -> None:
    with pytest.raises(OpenSCADError) as info:
        load("union() {\n\n  cube(size = [1, 2]);\n}")
    assert info.value.line == 3 and info.value.node == "cube"


# ----------------------------------------------------------------------------- lowering, no transforms


def test_primitives_are_exact() -> None:
    cube = load("cube(size = [1, 2, 3], center = false);")
    assert cube == Box((0.5, 1.0, 1.5), (1, 2, 3))
    assert load("cube(size = 2, center = true);") == Box((0, 0, 0), (2, 2, 2))
    assert load("sphere($fn = 80, $fa = 12, $fs = 2, r = 1.5);") == Sphere((0, 0, 0), 1.5)
    assert load("cylinder($fn = 0, h = 2, r1 = 1, r2 = 1, center = false);") == Cylinder((0, 0, 1), (0, 0, 2), 1)
    # OpenSCAD's r1 is at z = 0: the truncus' r2 end (center - axis / 2).
    cone = load("cylinder(h = 3, r1 = 1, r2 = 0, center = true);")
    assert cone == Truncus((0, 0, 0), (0, 0, 3), 0.0, 1.0)
    assert cone.contains([[0.9, 0, -1.4], [0.9, 0, 1.4]]).tolist() == [True, False]
    frustum = load("cylinder(h = 2, r1 = 0.5, r2 = 1.5, center = false);")
    assert volume(frustum) == pytest.approx(math.pi * 2 * (0.25 + 0.75 + 2.25) / 3, rel=1e-12)


def test_booleans_and_pass_through_nodes() -> None:
    text = """
    color([1, 0, 0, 1]) {
      render(convexity = 2) {
        difference() {
          cube(size = [4, 4, 1], center = true);
          cylinder(h = 2, r1 = 1, r2 = 1, center = true);
          group();
        }
      }
    }
    intersection() { sphere(r = 1); cube(size = [4, 4, 4], center = true); }
    #cube(size = [1, 1, 1], center = false);
    %cube(size = [9, 9, 9], center = false);
    *cube(size = [9, 9, 9], center = false);
    """
    solid = load(text)
    # The plate with a hole, the whole unit sphere, the unit cube in its first octant (overlapping both).
    ref = (Box((0, 0, 0), (4, 4, 1)) - Cylinder((0, 0, 0), (0, 0, 2), 1)) | Sphere((0, 0, 0), 1) | Box((0.5, 0.5, 0.5), (1, 1, 1))
    m = ref.to_manifold(256).volume()
    assert volume(solid) == pytest.approx(m, rel=2e-4)
    assert volume(solid) == pytest.approx(volume(ref), rel=1e-9)


def test_empty_operands_follow_openscad() -> None:
    # A first operand that is empty leaves the difference empty; empty subtrahends are dropped.
    assert load("difference() { cube(size = 0); cube(size = 1); }\ncube(size = 2);") == Box((1, 1, 1), (2, 2, 2))
    assert load("difference() { cube(size = 1); sphere(r = 0); }") == Box((0.5, 0.5, 0.5), (1, 1, 1))
    assert load("intersection() { cube(size = 1); group(); }\nsphere(r = 1);") == Sphere((0, 0, 0), 1)
    assert load("cylinder(h = 0, r1 = 1, r2 = 1);\ncube(size = 1);") == Box((0.5, 0.5, 0.5), (1, 1, 1))


def test_convex_polyhedron() -> None:
    text = "polyhedron(points = [[0, 0, 0], [2, 0, 0], [0, 2, 0], [0, 0, 2], [0.1, 0.1, 0.1]], faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]], convexity = 1);"
    solid = load(text)
    assert isinstance(solid, ConvexPolyhedron)
    assert solid.volume == pytest.approx(8 / 6, rel=1e-12)


def test_extrusion_commutes_with_booleans() -> None:
    text = """
    linear_extrude(height = 2, center = true, convexity = 1, scale = [1, 1], $fn = 8) {
      difference() {
        square(size = [4, 4], center = true);
        circle($fn = 0, r = 1);
        polygon(points = [[1, 1], [2, 1], [2, 2], [1, 2], [1.2, 1.2], [1.8, 1.2], [1.8, 1.8], [1.2, 1.8]], paths = [[0, 1, 2, 3], [4, 5, 6, 7]]);
      }
    }
    """
    solid = load(text)
    box, disc, frame = solid.children
    assert box == Box((0, 0, 0), (4, 4, 2))
    assert disc == Cylinder((0, 0, 0), (0, 0, 2), 1.0)  # exact without an explicit $fn
    assert volume(frame) == pytest.approx((1 - 0.36) * 2, rel=1e-12)
    assert volume(solid) == pytest.approx((16 - math.pi - 0.64) * 2, rel=1e-9)


def test_extrusion_maps_the_plane() -> None:
    # 2D multmatrix: a rotated square becomes a prism, a translated and scaled circle a cylinder.
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    text = f"""
    linear_extrude(height = 1) {{
      multmatrix(m = [[{c!r}, {-s!r}, 0, 5], [{s!r}, {c!r}, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {{ square(size = [2, 1]); }}
      multmatrix(m = [[2, 0, 0, -3], [0, 2, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]]) {{ circle(r = 0.5); }}
      multmatrix(m = [[2, 0, 0, 0], [0, 3, 0, 9], [0, 0, 1, 0], [0, 0, 0, 1]]) {{ square(size = 1, center = true); }}
    }}
    """
    prism, cyl, box = load(text).children
    assert isinstance(prism, ConvexPolyhedron) and prism.volume == pytest.approx(2.0, rel=1e-12)
    assert np.allclose(prism.bounds, [[5 - s, 0, 0], [5 + 2 * c, 2 * s + c, 1]], atol=1e-12)
    assert cyl == Cylinder((-3, 1, 0.5), (0, 0, 1), 1.0)
    assert box == Box((0, 9, 0.5), (2, 3, 1))


# ----------------------------------------------------------------------------- unsupported nodes

UNSUPPORTED = [
    ("hull", "hull() {\n  sphere(r = 1);\n  multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cylinder(h = 2, r1 = 1, r2 = 1);\n}"),
    ("minkowski", "minkowski() {\n  cube(size = 1);\n  cylinder(h = 1, r1 = 0.1, r2 = 0);\n}"),
    ("roof", "linear_extrude(height = 1) {\n  roof() {\n    square(size = 1);\n  }\n}"),
    ("import", "linear_extrude(height = 1) {\n  import(file = \"part.nef3\", layer = \"\", origin = [0, 0], scale = 1);\n}"),
    ("fill", "fill() {\n  cube(size = 1);\n}"),
    ("frobnicate", "frobnicate(size = 3);"),
]


@pytest.mark.parametrize("node, text", UNSUPPORTED, ids=[u[0] for u in UNSUPPORTED])
def test_unsupported_node_names_itself_and_its_line(node: str, text: str) -> None:
    text = "cube(size = [1, 1, 1]);\n" + text
    line = 2 + next(i for i, ln in enumerate(text.splitlines()[1:]) if f"{node}(" in ln)
    with pytest.raises(UnsupportedOpenSCADError, match=re.escape(f"m.csg:{line}: {node}() is not supported")) as info:
        load(text)
    assert (info.value.node, info.value.line) == (node, line)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        solid = load(text, skip_unsupported=True)
    assert solid == Box((0.5, 0.5, 0.5), (1, 1, 1))
    (w,) = [c for c in caught if issubclass(c.category, OpenSCADSkipWarning)]
    assert str(w.message) == f"skipped 1 unsupported OpenSCAD node: 1 {node}"
    assert w.message.skipped == {node: 1}


SPECIAL = [
    (
        "twisted ellipse",
        "linear_extrude(height = 1, twist = 90, slices = 10) {\n  multmatrix([[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) circle(r = 1);\n}",
        "linear_extrude",
        "linear_extrude.twist: a twisted ellipse has no exact form",
    ),
]


@pytest.mark.parametrize("text, node, reason", [s[1:] for s in SPECIAL], ids=[s[0] for s in SPECIAL])
def test_unsupported_uses(text: str, node: str, reason: str) -> None:
    text = "cube(size = [1, 1, 1]);\n" + text
    line = 2 + next(i for i, ln in enumerate(text.splitlines()[1:]) if f"{node}(" in ln)
    with pytest.raises(UnsupportedOpenSCADError, match=re.escape(f"m.csg:{line}: {node}() is not supported ({reason}")):
        load(text)
    model = read_openscad_text(text)
    assert model.skipped == {node: 1}
    assert model.solid == Box((0.5, 0.5, 0.5), (1, 1, 1))


def read_openscad_text(text: str):
    from isocsg.openscad import lower

    return lower(parse_csg(text, source="m.csg"), source="m.csg", skip_unsupported=True)


def test_skip_counts_add_up(tmp_path) -> None:
    text = (
        "difference() {\n  cube(size = [3, 3, 3]);\n  hull() { sphere(r = 1); multmatrix([[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cylinder(h = 1, r1 = 1, r2 = 1); }\n  hull() { sphere(r = 0.5); multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cylinder(h = 2, r1 = 1, r2 = 1); }\n"
        "  minkowski() { cube(size = 1); cylinder(h = 1, r1 = 1, r2 = 0); }\n}\n"
        "linear_extrude(height = 1, twist = 5) { multmatrix([[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) circle(r = 1); }\n"
    )
    path = tmp_path / "m.csg"
    path.write_text(text)
    model = read_openscad(path, skip_unsupported=True)
    assert model.skipped == {"hull": 2, "minkowski": 1, "linear_extrude": 1}
    assert model.solid == Box((1.5, 1.5, 1.5), (3, 3, 3))
    with pytest.warns(OpenSCADSkipWarning, match=re.escape("skipped 4 unsupported OpenSCAD nodes: 2 hull, 1 linear_extrude, 1 minkowski")):
        isocsg.load_openscad(path, skip_unsupported=True)
    with pytest.raises(OpenSCADError, match=re.escape("the model is empty: nothing of it has a volume (skipped: 1 hull)")):
        load("hull() { sphere(r = 1); multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cylinder(h = 2, r1 = 1, r2 = 1); }", skip_unsupported=True)


# ----------------------------------------------------------------------------- files and the program


def test_files_are_checked(tmp_path) -> None:
    with pytest.raises(OpenSCADError, match=re.escape("expected a .scad or .csg file")):
        isocsg.load_openscad(tmp_path / "model.stl")
    with pytest.raises(OpenSCADError, match=re.escape("not a regular file")):
        (tmp_path / "folder.csg").mkdir()
        isocsg.load_openscad(tmp_path / "folder.csg")
    bad = tmp_path / "latin1.csg"
    bad.write_bytes(b"cube(size = 1); // caf\xe9")
    with pytest.raises(OpenSCADError, match=re.escape("not a UTF-8 text file (byte 0xe9 at offset 22)")):
        isocsg.load_openscad(bad)


def test_missing_program(tmp_path, monkeypatch) -> None:
    scad = tmp_path / "m.scad"
    scad.write_text("x = 1;\ncube(x);")  # beyond the plain subset that reads without the program
    monkeypatch.setenv("PATH", str(tmp_path))  # no openscad on this PATH
    monkeypatch.delenv("ISOCSG_OPENSCAD", raising=False)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(MissingDependencyError, match=re.escape("needs the openscad program, which was not found: install OpenSCAD (Debian/Ubuntu: apt install openscad")):
            isocsg.load_openscad(scad)
    assert issubclass(MissingDependencyError, ImportError)


# ----------------------------------------------------------------------------- writer

ROUND_TRIP_PLAIN = {
    "box at origin": Box((0, 0, 0), (1.0 / 3, 2.0 / 7, math.pi)),
    "sphere at origin": Sphere((0, 0, 0), math.sqrt(2)),
    "polyhedron": ConvexPolyhedron([(0.1, 0.2, 0.3), (1 / 3, 0, 0), (0, 2 / 3, 0.01), (0, 0, 1 / 7), (0.3, 0.3, 0.3)]),
}


@pytest.mark.parametrize("name", list(ROUND_TRIP_PLAIN), ids=str)
def test_round_trip_without_transforms(name: str, tmp_path) -> None:
    solid = ROUND_TRIP_PLAIN[name]
    path = isocsg.save_openscad(solid, tmp_path / "m.csg")
    back = isocsg.load_openscad(path)
    assert volume(back) == pytest.approx(volume(solid), rel=1e-12)
    assert np.array_equal(back.bounds, solid.bounds)


ROUND_TRIP = {
    "sphere": Sphere((0.1, -2 / 3, 1e-3), 0.7),
    "tilted frustum": Truncus((1, 2, 3), (0.3, -0.7, 1.1), 0.4, 0.9),
    "cone downwards": Cone((0, 0, 0), (0, 0, -2), 1.0 / 3),
    "cylinder along x": Cylinder((0.5, 0.25, 0), (2, 0, 0), 0.3),
    "box": Box((1 / 3, 0.1, -0.2), (1, 2, 3)),
    "oriented box": Box((1, 2, 3), (1, 2, 3)).rotate([10, 20, 30]),
    "ellipsoid": Sphere((1, 2, 3), 1).scale([1, 2, 0.5]).rotate([10, 20, 30]),
    "elliptic truncus": Truncus((0, 0, 0), (0, 0, 2), 1, 0.4).transform([[1, 0.5, 0, 0], [0, 1, 0.2, 1], [0, 0, 1.5, 0], [0, 0, 0, 1]]),
    "csg": (Box((0, 0, 0), (2, 2, 2)) - Sphere((1, 1, 1), 0.9) - Cylinder((0, 0, 0), (0, 0, 3), 0.5)) | Cone((3, 0, 0), (1, 1, 1), 0.5),
}


@pytest.mark.parametrize("name", list(ROUND_TRIP), ids=str)
def test_round_trip_keeps_the_volume(name: str, tmp_path) -> None:
    solid = ROUND_TRIP[name]
    back = isocsg.load_openscad(isocsg.save_openscad(solid, tmp_path / "m.csg"))
    assert volume(back) == pytest.approx(volume(solid), rel=1e-9)
    assert np.allclose(back.bounds, solid.bounds, rtol=0, atol=1e-12)


def _significant_digits(token: str) -> int:
    """Significant digits of a decimal token (trailing zeros of an integer count: 120000 is 6)."""
    mantissa = token.lstrip("-").split("e")[0]
    digits = mantissa.replace(".", "").lstrip("0")
    return len(digits.rstrip("0")) if "." in mantissa else len(digits)


@pytest.mark.parametrize("name", list(ROUND_TRIP), ids=str)
def test_six_digit_form_keeps_the_volume(name: str) -> None:
    """digits=6: no number longer than OpenSCAD 2021's .csg export prints, the same solid."""
    solid = ROUND_TRIP[name]
    text = dumps_openscad(solid, digits=6)
    numbers = re.findall(r"(?<![\w.])-?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?", text)
    assert numbers and max(_significant_digits(t) for t in numbers) <= 6
    # what OpenSCAD prints of each number (%g, 6 digits) is the number written
    assert all(float(f"{float(t):.6g}") == float(t) for t in numbers)
    back = loads_openscad(text)
    assert volume(back) == pytest.approx(volume(solid), rel=1e-9)
    scale = float(np.abs(solid.bounds).max())
    assert np.allclose(back.bounds, solid.bounds, rtol=0, atol=1e-10 * scale)


def test_six_digit_form_keeps_kinds_where_the_map_allows() -> None:
    """Spheres, axis-aligned boxes, ellipsoids and (turned) trunci come back as their kind."""
    from isocsg import Ellipsoid

    for name, kind in (("sphere", Sphere), ("box", Box), ("ellipsoid", Ellipsoid), ("tilted frustum", Truncus)):
        back = loads_openscad(dumps_openscad(ROUND_TRIP[name], digits=6))
        assert isinstance(back, kind), (name, back)


POLYHEDRAL = {
    # faces of four corners: rounding each coordinate to 6 digits leaves them planar only to 5e-7
    "sheared box far off": Box((0, 0, 0), (1.4, 0.9, 0.6)).transform(
        [[0.9, 0.5, 0.3, 1234.5], [-0.2, 1.1, 0.4, -3.3], [0.1, -0.3, 1.2, 0.1], [0, 0, 0, 1]]),
    "prism": isocsg.extrude(shapely.Polygon([(0, 0), (1 / 3, 0), (0.4, 2 / 7), (0, math.pi / 5)]), 0.7).rotate((10, 20, 30)),
}


@pytest.mark.parametrize("name", list(POLYHEDRAL), ids=str)
def test_six_digit_polyhedra_stay_convex(name: str, tmp_path) -> None:
    """The readable form (``polyhedra="points"``) keeps 6 digits of the vertices (no short map
    places them all): the loader judges flatness to that precision, so the rounded file is still
    a convex polyhedron. The default form (the hull of exactly placed corners) keeps them all."""
    solid = POLYHEDRAL[name]
    back = loads_openscad(dumps_openscad(solid, digits=6, polyhedra="points"))
    assert isinstance(back, ConvexPolyhedron)
    assert volume(back) == pytest.approx(volume(solid), rel=1e-5)
    back = loads_openscad(dumps_openscad(solid, digits=6))
    assert isinstance(back, ConvexPolyhedron)
    assert volume(back) == pytest.approx(volume(solid), rel=1e-12)
    if shutil.which("openscad"):
        back = isocsg.load_openscad(isocsg.save_openscad(solid, tmp_path / "m.scad"))
        assert volume(back) == pytest.approx(volume(solid), rel=1e-12)
        assert np.allclose(back.bounds, solid.bounds, rtol=0, atol=1e-12 * float(np.abs(solid.bounds).max()))


@pytest.mark.skipif(shutil.which("openscad") is None, reason="the openscad program is not installed (apt install openscad)")
@pytest.mark.parametrize("name", list(ROUND_TRIP), ids=str)
def test_round_trip_through_openscad(name: str, tmp_path) -> None:
    """solid -> .scad -> openscad's .csg -> solid keeps the volume to 1e-9.

    OpenSCAD 2021 prints 6 significant digits in its .csg export; save_openscad writes
    a .scad whose numbers have at most 6 (digits="auto"), composed so that the export is
    still the solid (sums of nested translations, products of nested scales).
    """
    solid = ROUND_TRIP[name]
    back = isocsg.load_openscad(isocsg.save_openscad(solid, tmp_path / "m.scad"))
    assert volume(back) == pytest.approx(volume(solid), rel=1e-9)
    scale = float(np.abs(solid.bounds).max())
    assert np.allclose(back.bounds, solid.bounds, rtol=0, atol=1e-10 * scale)


@pytest.mark.skipif(shutil.which("openscad") is None, reason="the openscad program is not installed (apt install openscad)")
def test_openscad_export_prints_six_digits(tmp_path) -> None:
    """Why the .scad form is written with short numbers: full-precision numbers lose digits."""
    scad = tmp_path / "m.scad"
    scad.write_text("multmatrix([[1, 0, 0, 0.123456789], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
                    "cube(size = [0.3333333333333333, 1, 1]); sphere(r = 1.4142135623730951);")
    out = tmp_path / "m.csg"
    subprocess.run(["openscad", "-o", str(out), str(scad)], check=True, capture_output=True)
    text = out.read_text()
    assert "0.123457" in text and "0.333333" in text and "1.41421" in text
    assert "0.123456789" not in text


def test_writer_output_is_the_csg_subset() -> None:
    text = dumps_openscad(ROUND_TRIP["csg"])
    names = {c.name for c in _walk(parse_csg(text))}
    assert names <= {"union", "difference", "intersection", "multmatrix", "cube", "sphere", "cylinder", "polyhedron"}
    # Numbers are written as their shortest exact repr.
    assert repr(1 / 3) in dumps_openscad(ROUND_TRIP["box"])
    assert repr(2 / 3) in dumps_openscad(ROUND_TRIP["sphere"])


def _walk(calls):
    todo = list(calls)
    while todo:
        c = todo.pop()
        yield c
        todo.extend(c.children)


def test_writer_refuses_what_it_cannot_write(tmp_path) -> None:
    from isocsg import InvalidParameterError

    with pytest.raises(InvalidParameterError, match=re.escape("save_openscad: path must end in .scad or .csg, got")):
        isocsg.save_openscad(Sphere((0, 0, 0), 1), tmp_path / "m.stl")
    with pytest.raises(InvalidParameterError, match=re.escape("save_openscad: solid must be an isocsg Solid, got str")):
        dumps_openscad("sphere")


# ----------------------------------------------------------------------------- command line


def test_cli_renders_a_csg_model_with_a_framing_camera(tmp_path, capsys) -> None:
    from PIL import Image

    from isocsg.cli import main

    model = tmp_path / "part.csg"
    model.write_text("difference() { cube(size = [4, 3, 1], center = true); cylinder(h = 2, r1 = 0.8, r2 = 0.8, center = true); }")
    out = tmp_path / "out.png"
    assert main(["render", str(model), "-o", str(out), "--size", "64x48", "--contours", "16", "--no-progress"]) == 0
    assert f"wrote {out}" in capsys.readouterr().out
    image = np.asarray(Image.open(out))
    assert image.shape[:2] == (48, 64)
    lit = image.reshape(48, 64, -1)[..., 0] > 0
    # The model fills a good part of the frame and touches none of its borders.
    assert 0.15 < lit.mean() < 0.9
    assert not (lit[0].any() or lit[-1].any() or lit[:, 0].any() or lit[:, -1].any())


def test_cli_reports_unsupported_nodes(tmp_path, capsys) -> None:
    from isocsg.cli import main

    model = tmp_path / "part.csg"
    model.write_text("cube(size = 1);\nhull() { sphere(r = 1); multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cylinder(h = 2, r1 = 1, r2 = 1); }\n")
    assert main(["render", str(model), "-o", str(tmp_path / "o.png"), "--no-progress"]) == 2
    assert f"isocsg render: error: {model}:2: hull() is not supported" in capsys.readouterr().err
    args = ["render", str(model), "-o", str(tmp_path / "o.png"), "--size", "32x32", "--no-progress", "--skip-unsupported"]
    assert main(args) == 0
    assert "isocsg render: skipped 1 unsupported OpenSCAD node(s): 1 hull" in capsys.readouterr().err


@pytest.mark.skipif(shutil.which("openscad") is None, reason="the openscad program is not installed (apt install openscad)")
def test_cli_renders_a_scad_model(tmp_path) -> None:
    from isocsg.cli import main

    model = tmp_path / "part.scad"
    model.write_text("difference() { cube(2, center = true); rotate([90, 0, 0]) cylinder(h = 3, r = 0.5, center = true); }")
    out = tmp_path / "out.png"
    assert main(["render", str(model), "-o", str(out), "--size", "40x40", "--contours", "8", "--no-progress"]) == 0
    assert out.stat().st_size > 0
