"""Issue 22's OpenSCAD corpus (``tests/data/openscad/corpus22``): every node the reader gained.

Each model is a small ``.scad`` file written for these tests (offsets, text, scaled
extrusions, 2D Booleans and hulls, explicit small ``$fn``, ``%`` and ``*``, 2D objects beside
3D ones, hand-written transforms, thin plates), committed with ``openscad``'s ``.csg`` export
of it and the volume of ``openscad``'s STL export (``stl_volumes.json``, with the ``.scad``
text's sha256), so that the volume comparison runs without the program:

- the ``.csg`` loads, and its exact volume is within 0.5 % of the STL's (round shapes at
  ``$fn = 96``); models whose curves all have an explicit small ``$fn`` within 2e-5,
  the rounding of the STL's 6-digit vertices;
- where ``openscad`` is installed, the committed ``.csg`` is the program's export of the
  ``.scad`` and the JSON's hash is the ``.scad``'s (regenerate both after editing a model), and
  OpenSCAD's own polygonal solids have exactly the vertices of the loader's (to the 6 digits
  of its OFF export).
"""

from __future__ import annotations

import hashlib
import json
import shutil
import subprocess
import warnings
from pathlib import Path

import numpy as np
import pytest

from isocsg import ConvexPolyhedron, volume
from isocsg.openscad import load_openscad, read_openscad

DIR = Path(__file__).resolve().parent / "data" / "openscad" / "corpus22"
MODELS = sorted(p.stem for p in DIR.glob("*.scad"))
VOLUMES = json.loads((DIR / "stl_volumes.json").read_text())["models"]
HAS_OPENSCAD = shutil.which("openscad") is not None
needs_openscad = pytest.mark.skipif(not HAS_OPENSCAD, reason="the openscad program is not installed (apt install openscad)")

VOLUME_RTOL = 0.005
POLYGONAL_RTOL = 2e-5
#: Models whose every curve has an explicit small $fn: OpenSCAD's polygonal solids exactly.
EXACTLY_POLYGONAL = {
    "fn_circle8", "fn_cone_stack", "fn_frustum", "fn_hex_prism_rotated", "fn_hull_rounded", "fn_nut_traps",
    "fn_octagon_2d_hole", "fn_pyramid", "fn_sphere12", "fn_sphere5", "fn_sphere_cut",
}


def _load(name: str):  # type: ignore[no-untyped-def]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_openscad(DIR / f"{name}.csg")


def test_corpus_is_large_enough_and_complete() -> None:
    assert len(MODELS) >= 30
    assert sorted(VOLUMES) == MODELS
    assert all((DIR / f"{m}.csg").is_file() for m in MODELS)


@pytest.mark.parametrize("name", MODELS)
def test_volume_matches_openscad(name: str) -> None:
    got = volume(_load(name))
    want = VOLUMES[name]["volume"]
    rtol = POLYGONAL_RTOL if name in EXACTLY_POLYGONAL else VOLUME_RTOL
    assert abs(got - want) <= rtol * want, (name, got, want, got / want - 1)


@needs_openscad
@pytest.mark.parametrize("name", MODELS)
def test_committed_export_is_current(name: str, tmp_path: Path) -> None:
    scad = DIR / f"{name}.scad"
    assert VOLUMES[name]["sha256"] == hashlib.sha256(scad.read_bytes()).hexdigest(), "regenerate stl_volumes.json"
    out = tmp_path / "m.csg"
    subprocess.run(["openscad", "-o", str(out), str(scad)], capture_output=True, check=True, timeout=120)
    assert out.read_text() == (DIR / f"{name}.csg").read_text()


POLYGONAL = [
    "sphere(r = 3, $fn = 5);",
    "sphere(d = 10, $fn = 12);",
    "sphere(r = 1, $fn = 3);",
    "sphere(r = 2, $fn = 64);",
    "cylinder(h = 4, r1 = 3, r2 = 1.5, $fn = 5, center = true);",
    "cylinder(h = 10, r1 = 5, r2 = 0, $fn = 4);",
    "cylinder(h = 10, r1 = 0, r2 = 2, $fn = 7);",
    "cylinder(h = 2, r = 6, $fn = 6);",
]


def _off_vertices(path: Path) -> np.ndarray:
    lines = path.read_text().split("\n")
    n = int(lines[1].split()[0]) if lines[0].strip() == "OFF" else int(lines[0].split()[1])
    start = 2 if lines[0].strip() == "OFF" else 1
    return np.array([[float(x) for x in ln.split()] for ln in lines[start : start + n]])


@needs_openscad
@pytest.mark.parametrize("text", POLYGONAL)
def test_polygonal_solids_are_openscads(text: str, tmp_path: Path) -> None:
    scad = tmp_path / "m.scad"
    scad.write_text(text)
    subprocess.run(["openscad", "-o", str(tmp_path / "m.off"), str(scad)], capture_output=True, check=True, timeout=120)
    theirs = _off_vertices(tmp_path / "m.off")
    solid = load_openscad(scad)
    assert isinstance(solid, ConvexPolyhedron)
    ours = np.asarray(solid.hull_vertices)
    assert len(ours) == len(theirs)
    # every vertex of OpenSCAD's (6 digits) is one of ours
    d = np.abs(theirs[:, None, :] - ours[None, :, :]).max(axis=2).min(axis=1)
    assert d.max() <= 5e-6 * max(1.0, float(np.abs(ours).max()))


def test_background_child_of_an_intersection_is_left_out() -> None:
    """Issue 22: a ``%`` child emptied the intersection (a 25 % volume error)."""
    assert volume(_load("bg_intersection")) == pytest.approx(512.0, rel=1e-12)
    assert volume(_load("disabled_intersection")) == pytest.approx(VOLUMES["disabled_intersection"]["volume"], rel=5e-3)


def test_2d_beside_3d_is_ignored_with_openscads_warning() -> None:
    from isocsg.openscad import MixedDimensionsWarning

    with pytest.warns(MixedDimensionsWarning, match="ignoring the 2D object square"):
        solid = load_openscad(DIR / "mixed_2d_3d.csg")
    assert volume(solid) == pytest.approx(125.0)
    with pytest.warns(MixedDimensionsWarning, match="ignoring the 2D object circle"):
        model = read_openscad(DIR / "mixed_in_union.csg")
    assert len(model.left_out) == 1 and "circle(): a 2D object beside 3D ones is ignored" in model.left_out[0]


def test_hand_written_subset_loads_without_openscad() -> None:
    """A hand-written ``.csg`` with ``translate``, ``rotate``, ``scale``, ``mirror`` and children
    without braces loads as OpenSCAD reads it (the issue's bracket lost all but its base plate)."""
    from isocsg.openscad import loads_openscad

    text = """
    // a bracket
    union() {
        cube([40, 30, 8]);
        translate([0, 0, 8]) cube([40, 6, 30]);
        translate([0, 30, 0]) mirror([0, 1, 0]) scale([1, 1, 2]) cube([40, 6, 1]);
        rotate(a = 90, v = [0, 0, 1]) translate([0, -60, 0]) rotate([0, 0, 0]) cube(2);
    }
    """
    solid = loads_openscad(text)
    assert volume(solid) == pytest.approx(40 * 30 * 8 + 40 * 6 * 30 + 8, rel=1e-12)
    lo, hi = np.asarray(solid.bounds)
    assert lo.tolist() == pytest.approx([0, 0, 0]) and hi.tolist() == pytest.approx([60, 30, 38])


def test_transforms_compose_once_per_leaf(monkeypatch: pytest.MonkeyPatch) -> None:
    """Issue 22: 6637 prisms under nested transforms took 97.5 s, most of it re-mapping every
    prism at each level and rebuilding its hull. Now each leaf is built once and mapped once,
    and a mapped convex polyhedron keeps its faces (no new hull)."""
    import isocsg.kinds.polyhedron as poly
    from isocsg.csg import leaves
    from isocsg.openscad import loads_openscad

    depth, count = 12, 6
    head = "".join(f"multmatrix([[0, -1, 0, {k}], [1, 0, 0, 0.5], [0, 0, 1, 0.25], [0, 0, 0, 1]]) {{ " for k in range(depth))
    body = " ".join(
        f"linear_extrude(height = 1) {{ polygon(points = [[{4 * i}, 0], [{4 * i + 2}, 0], [{4 * i + 3}, 2], [{4 * i}, 1]]); }}"
        for i in range(count)
    )
    calls = 0
    real = poly._hull

    def counted(*args, **kwargs):  # type: ignore[no-untyped-def]
        nonlocal calls
        calls += 1
        return real(*args, **kwargs)

    monkeypatch.setattr(poly, "_hull", counted)
    solid = loads_openscad(head + body + " }" * depth)
    assert sum(1 for _ in leaves(solid)) == count
    assert calls == 0  # prisms built from their faces, mapped without a new hull, however deep the maps nest
    assert volume(solid) == pytest.approx(count * 3.5, rel=1e-9)


def test_thin_plate_loads_and_renders() -> None:
    """Issue 22: ``cube([0.001, 5, 128.4])`` was refused by an aspect limit (1e-5); a valid part
    of any aspect loads and renders (a thin fin on a base, seen from the side it faces)."""
    from isocsg.rendering import render
    from isocsg.scene.framing import framed_scene

    solid = _load("thin_plate_union")
    assert volume(solid) == pytest.approx(800 + 0.001 * 5 * 128.4, rel=1e-12)
    fin = _load("thin_plate")
    scene = framed_scene(fin, width=48, height=48, contours=8)
    image = render(scene).image
    hit = np.isfinite(image)
    assert hit.any() and float(np.nanmax(image)) > 0


_CONE_SUM = "a minkowski of a cone or frustum is not an exact union of isocsg kinds (only polytopes, balls and cylinders are)"


def test_skipped_nodes_are_reported_not_dropped_silently(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """``skip_unsupported`` says what it left out: ``LoweredModel.left_out`` (node, line, why), the
    warning of :func:`load_openscad`, and the CLI's render command."""
    from isocsg.cli import main
    from isocsg.openscad import OpenSCADSkipWarning

    path = tmp_path / "m.csg"
    path.write_text("cube(size = [2, 2, 2]);\nminkowski() {\n  cube(size = 1);\n  cylinder(h = 1, r1 = 0.1, r2 = 0);\n}\n")
    model = read_openscad(path, skip_unsupported=True)
    assert model.skipped == {"minkowski": 1}
    assert model.left_out == (f"{path}:2: minkowski(): {_CONE_SUM}",)
    with pytest.warns(OpenSCADSkipWarning, match="skipped 1 unsupported OpenSCAD node: 1 minkowski"):
        load_openscad(path, skip_unsupported=True)
    out = tmp_path / "m.png"
    assert main(["render", str(path), "-o", str(out), "--size", "32x32", "--no-progress", "--skip-unsupported"]) == 0
    err = capsys.readouterr().err
    assert f"left out {path}:2: minkowski(): {_CONE_SUM}" in err


def test_scad_without_the_program_reads_the_plain_subset(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from isocsg.openscad import PlainSubsetWarning

    monkeypatch.setenv("ISOCSG_OPENSCAD", str(tmp_path / "no-such-openscad"))
    monkeypatch.setenv("PATH", str(tmp_path))
    path = tmp_path / "m.scad"
    path.write_text("difference() { cube([4, 4, 2]); translate([1, 1, -1]) cylinder(h = 4, r = 1, $fn = 6); }\n")
    with pytest.warns(PlainSubsetWarning, match="read as the plain .csg subset"):
        solid = load_openscad(path)
    assert volume(solid) == pytest.approx(32 - 3 * np.sqrt(3) / 2 * 2, rel=1e-12)  # a hexagonal hole through 2


def test_root_modifier_keeps_only_its_subtree() -> None:
    """``!`` makes its subtree alone the model, without its parents' maps (OpenSCAD's export of
    ``cube(5); translate([10, 0, 0]) !sphere(2);`` is the bare sphere)."""
    from isocsg import Sphere
    from isocsg.openscad import loads_openscad

    text = "cube(size = 5);\nmultmatrix([[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n  !sphere(r = 2);\n}\n"
    assert loads_openscad(text) == Sphere((0, 0, 0), 2)
    assert volume(loads_openscad("cube(size = 5);\n#cube(size = 1);")) == pytest.approx(125.0)
