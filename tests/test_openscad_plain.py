"""``.scad`` files read in-process (:mod:`isocsg.openscad.plain`) against the ``openscad``
program's own export of the same files."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from isocsg.errors import IsocsgError
from isocsg.openscad import read_openscad
from isocsg.openscad.plain import PLAIN_SCAD_BYTES, plain_calls, read_plain_scad

HAS_OPENSCAD = shutil.which("openscad") is not None

# Numbers as people write them: up to 6 significant digits (OpenSCAD's .csg keeps 6), some
# integers, some tiny or huge.
_digits = st.integers(-999999, 999999).map(float)
_numbers = st.one_of(
    st.integers(-50, 50).map(float),
    st.tuples(_digits, st.integers(-8, 3)).map(lambda t: float(f"{t[0]:.0f}e{t[1]}")),
)
_positive = _numbers.map(abs).filter(lambda x: x > 0)


def _num(x: float) -> str:
    return repr(x) if x != int(x) or abs(x) >= 1e15 else str(int(x))


def _vec(xs: list[float]) -> str:
    return "[" + ", ".join(_num(x) for x in xs) + "]"


_center = st.sampled_from(["", ", center = true", ", center = false"])
_leaf = st.one_of(
    st.builds(lambda s, c: f"cube({_num(s)}{c});", _positive, _center),
    st.builds(lambda s, c: f"cube(size = {_vec(s)}{c});", st.lists(_positive, min_size=3, max_size=3), _center),
    st.builds(lambda r: f"sphere({_num(r)});", _positive),
    st.builds(lambda r: f"sphere(r = {_num(r)});", _positive),
    st.builds(lambda h, r, c: f"cylinder(h = {_num(h)}, r = {_num(r)}{c});", _positive, _positive, _center),
    st.builds(lambda h, r1, r2, c: f"cylinder(h = {_num(h)}, r1 = {_num(r1)}, r2 = {_num(r2)}{c});",
              _positive, _positive, st.sampled_from([0.0, 0.5, 2.0]), _center),
    # statements that leave nothing in the export
    st.builds(lambda x: f'echo("x =", {_num(x)}, [1, 2]);', _numbers),
    st.just("echo(version=version());"),
    st.just("echo (version = version ( ) ) ;"),
)


def _node(children: st.SearchStrategy[str]) -> st.SearchStrategy[str]:
    block = st.lists(children, min_size=1, max_size=3).map(lambda cs: "{ " + " ".join(cs) + " }")
    return st.one_of(
        st.builds(lambda op, b: f"{op}() {b}", st.sampled_from(["union", "difference", "intersection"]), block),
        st.builds(lambda v, c: f"translate({_vec(v)}) {c}", st.lists(_numbers, min_size=3, max_size=3), children),
        st.builds(lambda v, b: f"translate(v = {_vec(v)}) {b}", st.lists(_numbers, min_size=3, max_size=3), block),
    )


_models = st.lists(st.recursive(_leaf, _node, max_leaves=6), min_size=1, max_size=3).map("\n".join)


@pytest.mark.skipif(not HAS_OPENSCAD, reason="the openscad program is not installed (apt install openscad)")
@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(text=_models)
def test_in_process_read_is_the_programs(tmp_path: Path, text: str) -> None:
    """Every file of the subset: the model the program's export gives, to the last bit (or, for
    a model that does not lower, the program's own error)."""
    path = tmp_path / "model.scad"
    path.write_text(text + "\n")
    mine = read_plain_scad(path)
    try:
        theirs = read_openscad(path)
    except IsocsgError:  # a model that does not lower (a cylinder too thin for its radius, ...)
        assert mine is None  # left to the program's read, whose message names the line
        return
    assert mine is not None, text
    assert repr(mine.solid) == repr(theirs.solid)  # repr: every float exactly, -0.0 included
    assert (mine.skipped, mine.left_out, mine.leaf_colors, mine.polygonal) == (
        theirs.skipped, theirs.left_out, theirs.leaf_colors, theirs.polygonal)


@pytest.mark.parametrize("text", [
    "$fn = 12; sphere(1);",  # a variable
    "r = 2; sphere(r);",
    "module m() { cube(1); } m();",
    "for (i = [0:2]) translate([i, 0, 0]) cube(1);",
    "include <other.scad>\ncube(1);",
    "sphere(1, $fn = 12);",  # $ arguments
    "sphere(d = 2);",  # diameters
    "cylinder(3, 1, 2);",  # positional radii (OpenSCAD's r2 then defaults to r)
    "cylinder(h = 3, r = 1, r1 = 2, r2 = 1);",
    "cylinder(h = 3);",
    "cube(1.0000001);",  # more than 6 significant digits
    "translate([-0, 0, 0]) cube(1);",  # -0
    "cube(0);",
    "cube([1, 2]);",
    "cube(1, center = 1);",
    "cube(1, size = 2);",
    "sphere(inf);",
    "sphere(undef);",
    "#cube(1);",  # modifiers
    "!sphere(1);",
    "rotate([0, 0, 30]) cube(1);",  # maps that OpenSCAD prints as rounded matrices
    "scale(2) cube(1);",
    "color(\"red\") cube(1);",
    "Cube(1);",  # not a module OpenSCAD knows
    "cube(1) sphere(1);",  # a leaf with a child
    "translate([1, 0]) cube(1);",
    "",
    "// nothing",
    "echo(version=version());",  # nothing but a message: an empty model, the program's to report
    'echo("a") cube(1);',  # echo with children: a group in the export
    "echo(version=version(1));",
    "echo(v=version_num()); cube(1);",
    "my_echo(version=version()); cube(1);",
])
def test_files_outside_the_subset_are_left_to_the_program(text: str) -> None:
    assert plain_calls(text) is None


def test_unreadable_or_large_files_are_left_to_the_program(tmp_path: Path) -> None:
    big = tmp_path / "big.scad"
    big.write_text("cube(1);\n" * (PLAIN_SCAD_BYTES // 9 + 1))
    latin1 = tmp_path / "latin1.scad"
    latin1.write_bytes(b"// \xe9\ncube(1);\n")
    csg = tmp_path / "model.csg"
    csg.write_text("cube(1);\n")
    for path in (big, latin1, csg, tmp_path / "missing.scad", tmp_path):
        assert read_plain_scad(path) is None


def test_openscads_csg_example_is_read_in_process(tmp_path: Path) -> None:
    """OpenSCAD's examples/Basics/CSG.scad: constant CSG and ``echo(version=version());``."""
    text = ("translate([-24,0,0]) {\n union() {\n  cube(15, center=true);\n  sphere(10);\n }\n}\n"
            "intersection() {\n cube(15, center=true);\n sphere(10);\n}\n"
            "translate([24,0,0]) {\n difference() {\n  cube(15, center=true);\n  sphere(10);\n }\n}\n"
            "\necho(version=version());\n")
    calls = plain_calls(text)
    assert calls is not None and [c.name for c in calls] == ["translate", "intersection", "translate"]
    path = tmp_path / "CSG.scad"
    path.write_text(text)
    mine = read_plain_scad(path)
    assert mine is not None
    if HAS_OPENSCAD:
        assert repr(mine.solid) == repr(read_openscad(path).solid)
