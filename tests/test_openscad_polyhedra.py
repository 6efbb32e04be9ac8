"""Convex polyhedra through OpenSCAD: the exact ``hull()`` form of the 6-digit writer.

OpenSCAD 2021 prints every number of its ``.csg`` export with 6 significant digits,
polyhedron points included, so ``save_openscad`` writes a polyhedron as the hull of
one small tetrahedron per vertex, its tip moved onto the vertex by nested translations
(which the export keeps). Judged by the polyhedron's own vertices, by manifold3d's
volume of Boolean trees (exact on polyhedra) and by the mesh OpenSCAD itself renders.
"""

from __future__ import annotations

import re
import shutil
import subprocess

import numpy as np
import pytest

import isocsg
from isocsg import Box, ConvexPolyhedron, InvalidParameterError, UnsupportedOpenSCADError
from isocsg.openscad import dumps_openscad, loads_openscad, lower, parse_csg

needs_openscad = pytest.mark.skipif(shutil.which("openscad") is None, reason="the openscad program is not installed (apt install openscad)")


def random_polyhedra(count: int, seed: int, most: int = 40) -> list[ConvexPolyhedron]:
    """Hulls of 4 to ``most`` points, stretched (0.1 to 10 per axis), sheared and moved up to 1e4 away."""
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(count):
        pts = rng.normal(size=(int(rng.integers(4, most + 1)), 3)) * 10.0 ** rng.uniform(-1, 1, size=3)
        pts = pts @ (np.eye(3) + 0.5 * rng.normal(size=(3, 3))).T + rng.normal(size=3) * 10.0 ** rng.uniform(-2, 4)
        out.append(ConvexPolyhedron(pts))
    return out


def transformed(polys: list[ConvexPolyhedron], seed: int) -> list[ConvexPolyhedron]:
    """Turns, uneven scales, mirrors and general affine maps of the polyhedra."""
    rng = np.random.default_rng(seed)
    out = []
    for i, p in enumerate(polys):
        if i % 3 == 0:
            q = p.rotate(rng.uniform(-180, 180, size=3))
        elif i % 3 == 1:
            q = p.scale(rng.uniform(0.1, 10, size=3) * rng.choice([-1, 1], size=3)).translate(rng.normal(size=3) * 100)
        else:
            m = np.eye(4)
            m[:3, :3] = rng.normal(size=(3, 3))
            m[:3, 3] = rng.normal(size=3) * 1e3
            q = p.transform(m)
        assert isinstance(q, ConvexPolyhedron)
        out.append(q)
    return out


def errors(back: ConvexPolyhedron, solid: ConvexPolyhedron) -> tuple[float, float]:
    """Relative volume error and bounds error relative to the size."""
    size = float(np.ptp(solid.bounds, axis=0).max())
    return abs(back.volume - solid.volume) / solid.volume, float(np.abs(back.bounds - solid.bounds).max()) / size


def test_six_digit_hull_form_is_exact_without_the_program() -> None:
    """Every number has at most 6 digits, and the text read back is the same polyhedron."""
    polys = random_polyhedra(40, seed=1)
    polys += transformed(polys[:20], seed=2)
    for solid in polys:
        text = dumps_openscad(solid, digits=6)
        assert text.startswith("hull() {")
        numbers = re.findall(r"(?<![\w.$])-?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?", text)
        assert all(float(f"{float(t):.6g}") == float(t) for t in numbers)
        back = loads_openscad(text)
        assert isinstance(back, ConvexPolyhedron)
        assert len(back.hull_vertices) == len(solid.hull_vertices)
        # every vertex to its last bits (the tips' translations sum to it)
        assert np.allclose(np.sort(back.hull_vertices, axis=0), np.sort(solid.hull_vertices, axis=0), rtol=0, atol=4e-16 * np.abs(solid.hull_vertices).max())
        dv, db = errors(back, solid)
        assert dv <= 1e-12 and db <= 1e-15


@pytest.mark.parametrize("digits", [4, 5, 7])
def test_hull_form_is_exact_at_every_digit_count(digits: int) -> None:
    for solid in random_polyhedra(8, seed=digits):
        text = dumps_openscad(solid, digits=digits)
        numbers = re.findall(r"(?<![\w.$])-?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?", text)
        assert all(float(f"{float(t):.{digits}g}") == float(t) for t in numbers)
        back = loads_openscad(text)
        assert len(back.hull_vertices) == len(solid.hull_vertices)
        dv, db = errors(back, solid)
        assert dv <= 1e-12 and db <= 1e-15


def test_points_form_stays_readable_and_rounded() -> None:
    """``polyhedra="points"``: one plain polyhedron of 6-digit points, its volume to about 6 digits."""
    (solid,) = random_polyhedra(1, seed=3)
    text = dumps_openscad(solid, digits=6, polyhedra="points")
    assert "hull" not in text and text.count("polyhedron(") == 1
    back = loads_openscad(text)
    assert errors(back, solid)[0] <= 1e-5
    # without digits the plain polyhedron keeps every bit, and the option changes nothing
    assert dumps_openscad(solid, polyhedra="points") == dumps_openscad(solid)
    with pytest.raises(InvalidParameterError, match=re.escape("save_openscad: polyhedra must be 'hull' or 'points', got 'exact'")):
        dumps_openscad(solid, digits=6, polyhedra="exact")


def test_slivers_are_exact_too() -> None:
    """A sliver (1e-7 of its size thick, turned, off the origin): its spikes' bases are written in
    its principal frame, so that rounding keeps them inside, and it still comes back exactly."""
    rng = np.random.default_rng(4)
    for thickness in (1e-4, 1e-7):
        turn = np.linalg.qr(rng.normal(size=(3, 3)))[0]
        solid = ConvexPolyhedron((rng.normal(size=(30, 3)) * [1, 1, thickness]) @ turn.T + [12.5, -3, 0.1])
        text = dumps_openscad(solid, digits=6)
        assert text.startswith("hull() {")
        back = loads_openscad(text)
        assert len(back.hull_vertices) == len(solid.hull_vertices)
        dv, db = errors(back, solid)
        assert dv <= 1e-12 and db <= 1e-15


def test_hull_of_polyhedral_children_loads_as_a_convex_polyhedron() -> None:
    text = (
        "hull() {\n  cube(size = [1, 1, 1], center = true);\n"
        "  multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { union() { cube(size = [1, 1, 1], center = true); } }\n}"
    )
    solid = loads_openscad(text)
    assert isinstance(solid, ConvexPolyhedron)
    assert solid.volume == pytest.approx(4.0, rel=1e-14)  # a 4 x 1 x 1 box
    assert np.array_equal(solid.bounds, [[-0.5, -0.5, -0.5], [3.5, 0.5, 0.5]])
    assert len(solid.vertices) == 8  # the interior corners are not kept
    for child, reason in (
        ("sphere(r = 1); multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cylinder(h = 1, r1 = 1, r2 = 1);",
         "a hull of Box, Cylinder, Sphere of different shapes or directions is not an exact union of isocsg kinds"),
        ("difference() { cube(size = 2); cube(size = 1); }", (
            "a hull of a difference is not supported (only unions split into convex pieces exactly: "
            "a hull does not distribute over it)")),
    ):
        with pytest.raises(UnsupportedOpenSCADError, match=re.escape(f"m.csg:1: hull() is not supported ({reason}")):
            loads_openscad(f"hull() {{ cube(size = 1); {child} }}", source="m.csg")
    with pytest.raises(UnsupportedOpenSCADError, match=re.escape("m.csg:1: hull() is not supported (a 2D hull of ellipses")):
        loads_openscad("linear_extrude(height = 1) { hull() { square(size = 1); "
                       "multmatrix([[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { circle(r = 1); } } }",
                       source="m.csg")
    # a 2D hull of polygons: the convex polygon of their corners
    hull2d = loads_openscad("linear_extrude(height = 2) { hull() { square(size = 1); "
                            "multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) { square(size = 1); } } }")
    assert hull2d == Box((2, 0.5, 1), (4, 1, 2))


def _through_openscad(texts: list[str], tmp_path) -> list:
    """Each text a top-level statement of one .scad file; the solids of openscad's .csg export."""
    scad, out = tmp_path / "m.scad", tmp_path / "m.csg"
    scad.write_text("".join(texts))
    subprocess.run(["openscad", "-o", str(out), str(scad)], check=True, capture_output=True, timeout=600)
    calls = parse_csg(out.read_text())
    assert len(calls) == len(texts)
    return [lower([c]).solid for c in calls]


@needs_openscad
def test_what_the_export_keeps(tmp_path) -> None:
    """The facts the exact form rests on (docs/openscad.md): polyhedron points are rounded to 6
    digits like every number, small numbers keep their exponent, nested maps stay nested, hull stays."""
    tet = "faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]"
    scad = tmp_path / "m.scad"
    scad.write_text(
        f"polyhedron(points = [[0.123456789, 1234.56789, 1e-12], [1, 0, 0], [0, 1, 0], [0, 0, 1.00000012345]], {tet});\n"
        f"hull() {{ translate([1.5e-12, 3.25e-20, -7.77777e-9]) translate([1, 2, 3]) polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], {tet}); }}\n"
    )
    out = tmp_path / "m.csg"
    subprocess.run(["openscad", "-o", str(out), str(scad)], check=True, capture_output=True, timeout=600)
    text = out.read_text()
    assert "[[0.123457, 1234.57, 1e-12], [1, 0, 0], [0, 1, 0], [0, 0, 1]]" in text
    poly, hull = parse_csg(text)
    assert hull.name == "hull"
    outer = hull.children[0]
    inner = outer.children[0]
    assert (outer.name, inner.name, inner.children[0].name) == ("multmatrix", "multmatrix", "polyhedron")
    assert [row[3] for row in outer.args[0][:3]] == [1.5e-12, 3.25e-20, -7.77777e-9]  # multmatrix([[...]]) is positional


@needs_openscad
def test_random_polyhedra_round_trip_through_openscad(tmp_path) -> None:
    """solid -> .scad -> openscad's .csg -> solid keeps volume and bounds to 1e-9 (measured: exact)."""
    polys = random_polyhedra(200, seed=5, most=16)
    polys += transformed(polys[:100], seed=6)
    backs = _through_openscad([dumps_openscad(p, digits=6) for p in polys], tmp_path)
    worst_v = worst_b = 0.0
    for solid, back in zip(polys, backs):
        assert isinstance(back, ConvexPolyhedron)
        dv, db = errors(back, solid)
        worst_v, worst_b = max(worst_v, dv), max(worst_b, db)
    assert worst_v <= 1e-9 and worst_b <= 1e-9, (worst_v, worst_b)


def _leaves(solid):
    todo, out = [solid], []
    while todo:
        s = todo.pop()
        if isinstance(s, isocsg.CSGNode):
            todo.extend(reversed(s.children))
        else:
            out.append(s)
    return out[::-1]


@needs_openscad
def test_trees_of_polyhedra_round_trip_through_openscad(tmp_path) -> None:
    """Boolean trees of polyhedra and boxes: manifold3d's volume (exact on polyhedra) of the tree
    read back equals that of the tree written, to 1e-9; every polyhedron comes back as one."""
    rng = np.random.default_rng(7)
    trees = []
    for _ in range(8):
        a, b, c = random_polyhedra(3, seed=int(rng.integers(1 << 30)))
        # bring the operands together so that the Booleans cut
        b, c = b.translate(a.bounds.mean(axis=0) - b.bounds.mean(axis=0)), c.translate(a.bounds.mean(axis=0) - c.bounds.mean(axis=0))
        size = np.ptp(a.bounds, axis=0)
        box = Box(tuple(a.bounds.mean(axis=0) + 0.3 * size), tuple(size * 0.8))
        trees.append(((a - b) | (c & box)).rotate(rng.uniform(-90, 90, size=3)))
    backs = _through_openscad([dumps_openscad(t, digits=6) for t in trees], tmp_path)
    for tree, back in zip(trees, backs):
        assert back.to_manifold().volume() == pytest.approx(tree.to_manifold().volume(), rel=1e-9)
        for leaf, got in zip(_leaves(tree), _leaves(back)):
            if isinstance(leaf, ConvexPolyhedron) and not isinstance(leaf, Box):
                assert isinstance(got, ConvexPolyhedron)
                dv, db = errors(got, leaf)
                assert dv <= 1e-9 and db <= 1e-9


@needs_openscad
def test_openscad_renders_the_hull_form_as_the_polyhedron(tmp_path) -> None:
    """OpenSCAD's own mesh of the written model has the polyhedron's vertices (to the 6 digits
    its OFF export prints) and its volume."""
    trimesh = pytest.importorskip("trimesh")
    (solid,) = random_polyhedra(1, seed=8)
    scad = isocsg.save_openscad(solid, tmp_path / "m.scad")
    off = tmp_path / "m.off"
    subprocess.run(["openscad", "--render", "-o", str(off), str(scad)], check=True, capture_output=True, timeout=600)
    mesh = trimesh.load(off)
    size = float(np.ptp(solid.bounds, axis=0).max())
    tol = 1e-5 * max(size, float(np.abs(solid.bounds).max()))
    got, want = np.asarray(mesh.vertices), solid.hull_vertices
    assert len(got) == len(want)
    assert np.abs(got[:, None, :] - want[None, :, :]).max(axis=2).min(axis=1).max() <= tol
    assert mesh.is_watertight and abs(mesh.volume) == pytest.approx(solid.volume, rel=1e-4)
