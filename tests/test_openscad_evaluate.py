"""``.scad`` programs evaluated in-process (:mod:`isocsg.openscad.evaluate`) against the
``openscad`` program's own export: the committed exports of tests/data/scad_eval/ (written by
benchmarks/make_scad_eval_fixtures.py with OpenSCAD 2021.01), and random programs of the subset
exported by the installed program when there is one."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from isocsg.errors import IsocsgError
from isocsg.openscad import read_openscad
from isocsg.openscad.evaluate import declined_because, evaluate_scad
from isocsg.openscad.lowering import lower
from isocsg.openscad.parser import CSGCall, parse_csg
from isocsg.openscad.plain import read_plain_scad
from isocsg.openscad.program import scad_to_csg

HAS_OPENSCAD = shutil.which("openscad") is not None
DATA = Path(__file__).parent / "data" / "scad_eval"
FIXTURES = sorted(p.stem for p in DATA.glob("*.scad"))


def _difference(a: list[CSGCall], b: list[CSGCall]) -> str | None:
    """None if the trees are the same calls with the same arguments (float for float), else where not."""
    todo = [(a, b, "")]
    while todo:
        xs, ys, where = todo.pop()
        if [x.name for x in xs] != [y.name for y in ys]:
            return f"{where}: {[x.name for x in xs]} != {[y.name for y in ys]}"
        for i, (x, y) in enumerate(zip(xs, ys, strict=True)):
            here = f"{where}/{i}:{x.name}"
            if (x.modifiers, x.args, x.kwargs) != (y.modifiers, y.args, y.kwargs):
                return f"{here}: {x.args} {x.kwargs} != {y.args} {y.kwargs}"
            if list(x.kwargs) != list(y.kwargs):
                return f"{here}: arguments in another order"
            todo.append((x.children, y.children, here))
    return None


def _same_solid(mine: list[CSGCall], theirs: list[CSGCall]) -> None:
    try:
        want = lower(theirs)
    except IsocsgError:
        with pytest.raises(IsocsgError):
            lower(mine)
        return
    got = lower(mine)
    assert repr(got.solid) == repr(want.solid)
    assert (got.skipped, got.leaf_colors) == (want.skipped, want.leaf_colors)


def test_fixtures_are_there() -> None:
    assert len(FIXTURES) >= 40


@pytest.mark.parametrize("name", FIXTURES)
def test_evaluator_gives_the_programs_export(name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    # a program with library files NAME.lib/: OPENSCADPATH and HOME as make_scad_eval_fixtures.py set them
    lib = DATA / f"{name}.lib"
    monkeypatch.setenv("OPENSCADPATH", str(lib / "openscadpath") if (lib / "openscadpath").is_dir() else "")
    if (lib / "home").is_dir():
        monkeypatch.setenv("HOME", str(lib / "home"))
    text = (DATA / f"{name}.scad").read_text()
    theirs = parse_csg((DATA / f"{name}.csg").read_text())
    mine = evaluate_scad(text, path=DATA / f"{name}.scad")
    if name == "vector_ops":  # a negative cube size: OpenSCAD draws nothing without a warning; declined
        assert mine is None and declined_because(text) == "cube size"
        return
    assert mine is not None, declined_because(text, path=DATA / f"{name}.scad")
    assert _difference(mine, theirs) is None, _difference(mine, theirs)
    _same_solid(mine, theirs)


@pytest.mark.parametrize("text", [
    "include <lib.scad>\ncube(1);", "use <lib.scad>\ncube(1);",
    # children(): what OpenSCAD warns about (an index out of range, a bad argument, $children
    # unknown in a caller's block), and what is left to it (children() outside a module)
    "children(); cube(1);", "module m() children(); m() children();", "module m() children(2); m() cube(1);",
    "module m() children(-1); m() cube(1);", "module m() children([0, 5]); m() cube(1);",
    "module m() children(true); m() cube(1);", "module m() children(1e10); m() cube(1);",
    "module m() children(index = 0); m() cube(1);", "module m() children(0, 1); m() { cube(1); cube(2); }",
    "module m() children([5:6]); m() cube(1);", "module m() children(); m() cube($children);",
    "module m() children(); m() { a = $children; cube(1); }", "module m() cube(1); m() { a = undefined_var; cube(1); }",
    "function f() = $children; module m() cube(f() + 1); m() cube(1);", "module children() cube(1); children();",
    "module m() children(); m() cube(1) sphere(1);", "module m() children() cube(1); m() cube(1);",
    # let and list comprehensions: what OpenSCAD warns about, and a syntax error
    "x = let (a = 1, a = 2) a; cube(x);", "let (1) cube(1);", "let (a = 1) { a = 2; cube(a); }",
    "x = 1 + let (a = 1) a; cube(x);", "x = [for (i = [0:3]) i : 3]; cube(1);", "x = [each undef]; cube(1);",
    'x = [each "ab"]; cube(1);', 'x = [for (i = "ab") 1]; cube(1);', 'for (i = "ab") cube(1);', "x = [for () 1]; cube(1);",
    "x = [for (i = 0; i < 3; j = i) i]; cube(1);", "x = [for (i = [0:99999]) i]; cube(1);",
    "each = 1; cube(each);", "let = 1; cube(1);", "$children = 1; cube(1);",
    "module r(n) { if (n > 0) r(n - 1); cube(n + 1); } r(3);",
    "function f(n) = n <= 0 ? 1 : f(n - 1); cube(f(2));",
    'text("hi");', 'import("a.stl");', 'surface("a.dat");',
    "projection() cube(1);", "resize([2, 2, 2]) cube(1);", "assert(true); cube(1);",
    "*cube(1);", "!cube(1);", "#cube(1);", "%cube(1);",
    "cube(x);", "a = 1; a = 2; cube(a);", "a = b; b = 1; cube(a);",
    'color("nosuchcolour") cube(1);', 'color("#ff000") cube(1);', 'color("#ggg") cube(1);', "color([2, 0, 0]) cube(1);",
    "cube([1, 2]);", "cube(-1);", "cube(0);", "sphere(0);", "cylinder(h = 0, r = 1);",
    "cylinder(h = 1, r = 1, r1 = 2);", "sphere(r = 1, d = 2);", "cube(1, center = 1);",
    "cube(1, size = 2);", "cube(1) sphere(1);", "rotate([1, 2, 3], [0, 0, 1]) cube(1);",
    "translate(1) cube(1);", "scale(0) cube(1);", "for (i = [3:1]) cube(i);", "for (i = [5:1:1]) cube(i);", "for (i = [1:-1:5]) cube(i);",
    "module m() children([5:1:1]); m() cube(1);",
    "for (i = [0:0.0001:10]) cube(1);", "cube(1 / 0);", "cube([1, 2, 3] + 1);",
    "x = [1, 2][5]; cube(x);", "cube($preview ? 1 : 2);", "cube($vpd);",
    "linear_extrude(file = \"a.dxf\") square(1);", "rotate_extrude(360) circle(1);",
    "offset(r = 1, delta = 2) square(1);", "x = 2d; cube(1);", "8mm();", "render() cube(1);",
    "function f(x) = x; cube(f(1, 2));", "module m(a) cube(a); m(b = 2);",
    "sphere(1, $fs = 0.001);", "echo(undefined_variable); cube(1);",
    "x = " + "(" * 200 + "1" + ")" * 200 + "; cube(x);",
    "", "// nothing", "echo(1);",
    # cross, minkowski, intersection_for and bare blocks: what OpenSCAD warns about, and syntax errors
    "cube(cross([1, 2], [1, 2, 3]));", 'cube(cross([1, 2, 3], [1, 2, "a"]));', "cube(cross([1, 2, 3, 4], [1, 2, 3, 4]));",
    "cube(cross([1, 2, 3], [1, 2, 1 / 0]));", "cube(cross([1, 2, 3]));", "minkowski(convexity = -1) cube(1);",
    "minkowski(convexity = true) cube(1);", "minkowski(1, 2) cube(1);", "minkowski(size = 1) cube(1);",
    "intersection_for () cube(1);", "intersection_for (1) cube(1);", 'intersection_for (i = "ab") cube(1);',
    "{ a = 1; } a = 2; cube(a);",
    "module m() cube(1); { module m() sphere(1); } m();", "translate([1, 0, 0]) { { module m() cube(1); } m(); }", "{ cube(1);",
    # syntax errors of OpenSCAD's grammar: the program reports them
    "module t(n = $fn) cube(n + 1); t($fn = 8);", "cylinder(h = 2, 0.5, center = true);", "module m(a, b) cube(a + b); m(a = 1, 2);", "cube(1,);", "if (true) { module m() cube(1); m(); }", "translate([1, 0, 0]) { function f() = 1; cube(f()); }",
    "translate([1, 0, 0]) a = 1; cube(1);", "if (true) a = 2; cube(1);", "cube([,1]);", "cube(1,,center = true);",
    # work bounded: an exponential chain of functions, a doubling vector, a huge loop
    "function f0(x) = x;\n" + "".join(f"function f{i}(x) = f{i - 1}(x) + f{i - 1}(x);\n" for i in range(1, 40))
    + "cube(f39(1));",
    "v0 = [1];\n" + "".join(f"v{i} = concat(v{i - 1}, v{i - 1});\n" for i in range(1, 40)) + "cube(len(v39));",
    "for (i = [0:9999], j = [0:9999]) echo(i);",
    "x = [for (i = [0:9999], j = [0:9999]) 0]; cube(1);", "x = [for (i = 0; true; i = i) if (false) 1]; cube(1);",
    "v0 = [1];\n" + "".join(f"v{i} = [each v{i - 1}, each v{i - 1}];\n" for i in range(1, 40)) + "cube(len(v39));",
    "b = [for (i = [0:9999]) i]; c = [for (i = [0:49]) each b]; v = [for (i = [0:9999]) len(concat(c, c))]; cube(1);",
    "b = [for (i = [0:9999]) i]; c = [for (i = [0:49]) each b]; v = [for (i = [0:9999]) len(c + c)]; cube(1);",
    "b = [for (i = [0:9999]) i]; x0 = [for (i = [0:49]) each b];\n"
    + "".join(f"x{i} = [x{i - 1}, x{i - 1}];\n" for i in range(1, 30)) + "cube(x29 == x29 ? 1 : 2);",
])
def test_constructs_outside_the_subset_are_declined(text: str) -> None:
    assert evaluate_scad(text) is None


@pytest.mark.parametrize(("text", "files"), [
    ("include <nothere.scad>\ncube(1);", {}), ("use <nothere.scad>\ncube(1);", {}),
    ("include <a.scad>\ncube(1);", {"a.scad": "include <b.scad>\n", "b.scad": "include <a.scad>\n"}),
    ("include <model.scad>\ncube(1);", {}),
    ("use <a.scad>\nm();", {"a.scad": "use <b.scad>\nmodule m() n();\n", "b.scad": "use <a.scad>\nmodule n() cube(1);\n"}),
    ("module m() { use <a.scad> }\nm();", {"a.scad": "module n() cube(1);\n"}),
    ("module m() { include <a.scad> }\nm();", {"a.scad": "use <b.scad>\n", "b.scad": "module n() cube(1);\n"}),
    ("use <a.scad>\nuse <b.scad>\nn();", {"a.scad": "module n() cube(1);\n", "b.scad": "module n() cube(2);\n"}),
    ("use <a.scad>\nn();", {"a.scad": "$fn = 5;\nmodule n() sphere(1);\n"}),
    ("use <a.scad>\nn();", {"a.scad": "r = $fn + 1;\nmodule n() sphere(r);\n"}),
    ("use <a.scad>\nn();", {"a.scad": "module n() cube(k);\n"}),  # the user's k is not the used file's
    ("k = 1;\nuse <a.scad>\nn();", {"a.scad": "module n() cube(k);\n"}),
    ("use <a.scad>\nm();", {"a.scad": "use <b.scad>\nmodule n() m();\n", "b.scad": "module m() cube(1);\n"}),
    ("use <a.txt>\ncube(1);", {"a.txt": "module n() cube(1);\n"}), ("include <>\ncube(1);", {}),
    ("use <a.scad>\nn();", {"a.scad": "module n() text(\"hi\");\n"}),
    ("include <a.scad>\ncube(1);", {"a.scad": "x = [" + "1, " * 100000 + "1];\n"}),
    ("include <f0.scad>\ncube(1);", {f"f{i}.scad": f"include <f{i + 1}.scad>\n" for i in range(10)} | {"f10.scad": ""}),
    ("use <f0.scad>\nm0();", {f"f{i}.scad": f"use <f{i + 1}.scad>\nmodule m{i}() m{i + 1}();\n" for i in range(10)}
     | {"f10.scad": "module m10() cube(1);\n"}),
])
def test_include_and_use_outside_the_subset_are_declined(tmp_path: Path, text: str, files: dict[str, str]) -> None:
    # a file found nowhere, cycles, use below the top level, a name two used files define, a
    # used file's $ variables at its top level, names a used file does not see, too large a file
    for rel, body in files.items():
        (tmp_path / rel).write_text(body)
    (tmp_path / "model.scad").write_text(text)
    assert evaluate_scad(text, path=tmp_path / "model.scad") is None


def test_in_process_read_uses_the_evaluator(tmp_path: Path) -> None:
    path = tmp_path / "model.scad"
    path.write_text("n = 3;\nfor (i = [0:n - 1]) translate([2 * i, 0, 0]) cube(1);\n")
    model = read_plain_scad(path)
    assert model is not None
    if HAS_OPENSCAD:
        assert repr(model.solid) == repr(read_openscad(path).solid)


def test_in_process_read_follows_include_and_use(tmp_path: Path) -> None:
    (tmp_path / "lib").mkdir()
    (tmp_path / "lib" / "parts.scad").write_text("include <sizes.scad>\nmodule peg() cylinder(h = h, r = 1);\n")
    (tmp_path / "lib" / "sizes.scad").write_text("h = 4;\n")
    path = tmp_path / "model.scad"
    path.write_text("use <lib/parts.scad>\ninclude <lib/sizes.scad>\npeg();\ncube(h);\n")
    assert evaluate_scad(path.read_text()) is None  # without its path: declined
    model = read_plain_scad(path)
    assert model is not None
    if HAS_OPENSCAD:
        assert repr(model.solid) == repr(read_openscad(path).solid)


# Random programs of the subset: variables, a function, modules (one with children), loops, ifs,
# lets, list comprehensions, maps and primitives with expressions at special and generic angles.
_numbers = st.one_of(st.integers(-20, 20).map(str), st.sampled_from(["30", "45", "60", "90", "180", "-270"]),
                     st.floats(-50, 50, allow_nan=False).map(lambda x: f"{x:.{len(repr(x)) % 8}f}"))


def _expressions(names: list[str]) -> st.SearchStrategy[str]:
    leaf = st.one_of(_numbers, st.sampled_from(names))
    return st.recursive(leaf, lambda e: st.one_of(
        st.builds(lambda a, op, b: f"({a} {op} {b})", e, st.sampled_from(["+", "-", "*", "/", "%"]), e),
        st.builds(lambda f, a: f"{f}({a})", st.sampled_from(["sin", "cos", "tan", "abs", "floor", "round", "sqrt"]), e),
        st.builds(lambda a, b: f"atan2({a}, {b})", e, e),
        st.builds(lambda a, b: f"max([{a}, {b}]) ^ 0.5", e, e),
        st.builds(lambda c, a, b: f"({c} > 0 ? {a} : {b})", e, e, e),
        st.builds(lambda a, b: f"let (t = {a}, u = t * 2) (u - {b})", e, e),
        st.builds(lambda a, n: f"[for (k = [0:3]) {a} + k][{n}]", e, st.integers(0, 3)),
        st.builds(lambda a, b: f"max([each [{a}, {b}], for (k = [1:2]) if (k > 1) k * {a} else -k])", e, e),
        st.builds(lambda a: f"len([for (k = 0; k < abs({a}) % 4; k = k + 1) let (j = k) j])", e),
    ), max_leaves=4)


def _positive(names: list[str]) -> st.SearchStrategy[str]:
    return _expressions(names).map(lambda e: f"abs({e}) + 0.5")


def _shapes(names: list[str]) -> st.SearchStrategy[str]:
    p = _positive(names)
    e = _expressions(names)
    leaf = st.one_of(
        st.builds(lambda a, b, c: f"cube([{a}, {b}, 1], center = {c});", p, p, st.sampled_from(["true", "false"])),
        st.builds(lambda r, fn: f"sphere(r = {r}{fn});", p, st.sampled_from(["", ", $fn = 7", ", $fa = 5"])),
        st.builds(lambda h, r: f"cylinder(h = {h}, d1 = {r}, d2 = 1);", p, p),
        st.builds(lambda x: f"part({x});", e),
        st.builds(lambda h, r, fn: f"linear_extrude(height = {h}, twist = {r}{fn}) square([{h}, 1]);", p, e,
                  st.sampled_from(["", ", $fn = 6", ", slices = 3"])),
        st.builds(lambda r, a: f"rotate_extrude(angle = {a}) translate([{r} + 1, 0]) circle(1);", p, e),
    )
    return st.recursive(leaf, lambda s: st.one_of(
        st.builds(lambda a, b, c, k: f"translate([{a}, {b}, {c}]) {k}", e, e, e, s),
        st.builds(lambda a, b, c, k: f"rotate([{a}, {b}, {c}]) {k}", e, e, e, s),
        st.builds(lambda a, b, k: f"rotate({a}, [{b}, 1, 0]) {k}", e, e, s),
        st.builds(lambda a, k: f"mirror([{a}, 1, 0]) {k}", e, s),
        st.builds(lambda a, b, k: f"scale([{a}, {b}]) {k}", p, p, s),
        st.builds(lambda a, b, k: f"color([0.5, {a} / ({a} + {b}), 0.25], {b} / ({a} + {b})) {k}", p, p, s),
        st.builds(lambda a, b, k: f"multmatrix([[1, {a}, 0, {b}], [0, 1, 0, 0], [{b}, 0, 1, 0]]) {k}", e, e, s),
        st.builds(lambda lo, n, k: f"for (i = [{lo}:{lo + n}]) translate([i, 0, 0]) {k}", st.integers(-2, 2),
                  st.integers(0, 3), s),
        st.builds(lambda c, a, b: f"if ({c} > 0) {a} else {b}", e, s, s),
        st.builds(lambda a, k: f"let (w = {a}) translate([w, 0, 0]) {k}", e, s),
        st.builds(lambda a, k: f"wrap({a}) {k}", e, s),
        st.builds(lambda a, k, j: f"wrap({a}) {{ {k} {j} }}", e, s, s),
        st.builds(lambda op, a, b: f"{op}() {{ {a} {b} }}", st.sampled_from(["union", "difference", "hull"]), s, s),
    ), max_leaves=4)


_programs = st.builds(
    lambda a, fn, body: f"a = {a};\n{fn}function f(x) = x * a + 1;\nmodule part(s) {{ cube(abs(f(s)) + 1); }}\n"
    "module wrap(d) { translate([d, 0, 0]) children(0); if ($children > 1) mirror([1, 0, 0]) children([1:$children - 1]); }\n"
    f"{body}\n",
    _numbers, st.sampled_from(["", "$fn = 12;\n"]), _shapes(["a", "f(a)"]),
)


@pytest.mark.skipif(not HAS_OPENSCAD, reason="the openscad program is not installed (apt install openscad)")
@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(text=_programs)
def test_random_programs_give_the_programs_export(tmp_path: Path, text: str) -> None:
    path = tmp_path / "model.scad"
    path.write_text(text)
    mine = evaluate_scad(text)
    if mine is None:  # declined (a warning OpenSCAD would give, a size <= 0, ...): nothing to compare
        return
    theirs = parse_csg(scad_to_csg(path))
    assert _difference(mine, theirs) is None, (text, _difference(mine, theirs))


_pieces = st.sampled_from(["cube(", "sphere(", "translate(", "for (i = ", "if (", "module m(", "function f(", "m(", "f(",
                           "[", "]", "(", ")", "{", "}", ",", ";", "=", ":", "?", "+", "-", "*", "/", "%", "^", "!",
                           "<", ">=", "==", "&&", "||", ".x", "1", "0.5", "-2", "1e400", "i", "a", "$fn", "\"s\"",
                           "true", "undef", " ", "\n", "else ", "0:3", "sin(", "len(", "concat(", "let (", "each ",
                           "children(", "$children", "for (k = [0:2]) ", "; i < 3; i = i + 1"])


@settings(max_examples=200, deadline=None)
@given(text=st.lists(_pieces, max_size=40).map("".join))
def test_any_text_is_read_or_declined(text: str) -> None:
    """Malformed or odd text never raises: it is read, or left to the program."""
    calls = evaluate_scad(text)
    assert calls is None or (calls and all(isinstance(c, CSGCall) for c in calls))
