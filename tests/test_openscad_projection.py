"""OpenSCAD's ``projection`` (``isocsg.shapes2d.projection``) and the projection/resize corpus.

- The corpus ``tests/data/openscad/projection22``: small models written for these tests, committed
  with ``openscad``'s ``.csg`` export and the volume of its STL export (``stl_volumes.json``, the
  command in its ``about``, with each ``.scad``'s sha256); the exact volume of the loaded ``.csg``
  is within 0.5 % of OpenSCAD's (its round shapes at ``$fn = 96``), models of polygons within the
  STL's 6 printed digits.
- Hypothesis: sections at z = 0 and outlines of drawn trees of spheres, ellipsoids, tilted
  cylinders and cones and turned boxes against manifold3d's ``slice`` and ``project`` of fine
  meshes built here with manifold3d's own primitives (no isocsg code in the reference).
"""

from __future__ import annotations

import hashlib
import json
import math
import shutil
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from isocsg import Box, ConvexPolyhedron, Cylinder, Sphere, Truncus, volume
from isocsg.errors import NotExactError
from isocsg.openscad import read_openscad
from isocsg.shapes2d import EMPTY, area, to_shapely
from isocsg.shapes2d.projection import outline, projection, section_at

manifold3d = pytest.importorskip("manifold3d")

DIR = Path(__file__).resolve().parent / "data" / "openscad" / "projection22"
VOLUMES = json.loads((DIR / "stl_volumes.json").read_text())["models"]
MODELS = sorted(p.stem for p in DIR.glob("*.scad"))
PROJECTION_MODELS = [m for m in MODELS if m.startswith("projection_")]
#: Models with no curve (or only OpenSCAD's own polygons): the STL's 6 printed digits.
POLYGONAL = {"projection_cut_holes", "projection_cut_face", "projection_outline_polyhedra"}
VOLUME_RTOL = 0.005
POLYGONAL_RTOL = 2e-5
SEGMENTS = 256  # of the reference meshes' circles: inscribed, within 7.5e-5 of a radius
#: Absolute tolerance on areas and symmetric differences of shapes about 2 across (the meshes' sagitta
#: times the perimeters, with room).
AREA_TOL = 3e-3


def _load(path: Path):  # type: ignore[no-untyped-def]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return read_openscad(path)


def test_corpus_is_complete() -> None:
    assert sorted(VOLUMES) == MODELS
    assert all((DIR / f"{m}.csg").is_file() for m in MODELS)
    for m in MODELS:
        assert VOLUMES[m]["sha256"] == hashlib.sha256((DIR / f"{m}.scad").read_bytes()).hexdigest(), (
            "regenerate stl_volumes.json (regenerate.py)")


@pytest.mark.parametrize("name", PROJECTION_MODELS)
def test_projection_volume_matches_openscad(name: str) -> None:
    got = volume(_load(DIR / f"{name}.csg").solid)
    want = VOLUMES[name]["volume"]
    assert got == pytest.approx(want, rel=POLYGONAL_RTOL if name in POLYGONAL else VOLUME_RTOL)


@pytest.mark.skipif(shutil.which("openscad") is None, reason="the openscad program is not installed")
def test_scad_loads_through_the_program() -> None:
    model = _load(DIR / "projection_outline_union.scad")
    assert volume(model.solid) == pytest.approx(VOLUMES["projection_outline_union"]["volume"], rel=VOLUME_RTOL)


# ----------------------------------------------------------------------------- exact cases


def test_sections_of_leaves_in_closed_form() -> None:
    assert area(section_at(Sphere((0, 0, 0.6), 1.0))) == pytest.approx(math.pi * 0.64, rel=1e-13)
    c = Cylinder((0, 0, 0), (0, 0, 10), 1.0).rotate([40, 0, 0])  # an ellipse of semi-axes 1, 1 / cos 40
    assert area(section_at(c)) == pytest.approx(math.pi / math.cos(math.radians(40)), rel=1e-9)
    # a cone cut across its axis at mid-height: a disc of the mean radius
    assert area(section_at(Truncus((0, 0, 0), (0, 0, 4), 1.0, 3.0))) == pytest.approx(4 * math.pi, rel=1e-13)


def test_faces_in_the_plane_count_on_either_side() -> None:
    above, below = Box((0, 0, 1), (2, 2, 2)), Box((3, 0, -1), (2, 2, 2))
    assert area(section_at(above)) == 4.0
    assert area(section_at(below)) == 4.0
    assert area(section_at(above | below)) == 8.0
    assert section_at(Sphere((0, 0, 1), 1)) is EMPTY  # a tangent point: no area


def test_outline_of_a_difference_is_not_the_difference_of_outlines() -> None:
    # a box with a pocket that does not run through: its shadow is the whole box
    pocket = Box((0, 0, 0), (4, 4, 2)) - Box((0, 0, 0.5), (2, 2, 2))
    assert area(outline(pocket)) == pytest.approx(16.0, rel=1e-12)
    # a through hole: the shadow has the hole
    hole = Box((0, 0, 0), (4, 4, 2)) - Cylinder((0, 0, 0), (0, 0, 3), 1.0)
    assert area(outline(hole)) == pytest.approx(16.0 - math.pi, rel=1e-12)


def test_outline_that_is_not_exact_is_refused_naming_the_node() -> None:
    with pytest.raises(NotExactError, match="not a vertical prism"):
        outline(Sphere((0, 0, 0), 2) - Sphere((0, 0, 1), 1))
    # OpenSCAD's own outline then (isocsg.openscad.fallback): its sphere of r = 2 has 7 fragments
    # and 4 rings, the widest at the polar angle 67.5 degrees; the shadow is that 7-gon
    text = "linear_extrude(height = 1) projection() difference() { sphere(2); sphere(1); }"
    model = read_openscad_text(text)
    assert len(model.polygonal) == 1 and "not a vertical prism" in model.polygonal[0]
    r = 2 * math.sin(math.radians(67.5))
    assert volume(model.solid) == pytest.approx(3.5 * r * r * math.sin(2 * math.pi / 7), rel=1e-8)


def test_projection_beside_3d_objects_is_ignored() -> None:
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        model = read_openscad_text("cube(1); projection() sphere(3);")
    assert volume(model.solid) == pytest.approx(1.0)
    assert any("projection" in str(w.message) for w in seen)


def read_openscad_text(text: str, skip_unsupported: bool = False):  # type: ignore[no-untyped-def]
    from isocsg.openscad.lowering import lower
    from isocsg.openscad.parser import parse_csg

    return lower(parse_csg(text), skip_unsupported=skip_unsupported)


# ----------------------------------------------------------------------------- hypothesis


def _rotation(ax: float, ay: float, az: float) -> np.ndarray:
    a, b, c = np.radians([ax, ay, az])
    rx = np.array([[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]])
    ry = np.array([[math.cos(b), 0, math.sin(b)], [0, 1, 0], [-math.sin(b), 0, math.cos(b)]])
    rz = np.array([[math.cos(c), -math.sin(c), 0], [math.sin(c), math.cos(c), 0], [0, 0, 1]])
    return rz @ ry @ rx


angles = st.tuples(*[st.floats(-80, 80)] * 3)
offsets = st.tuples(*[st.floats(-0.6, 0.6)] * 3)


@st.composite
def leaves(draw: st.DrawFn, upright: bool = False) -> tuple[object, object]:
    """A leaf as (isocsg solid, manifold3d mesh built independently)."""
    kind = draw(st.sampled_from(["sphere", "ellipsoid", "cylinder", "cone", "box"]))
    R = np.eye(3) if upright else _rotation(*draw(angles))
    t = np.array(draw(offsets))
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = R, t
    m34 = m[:3]
    if kind == "sphere":
        r = draw(st.floats(0.5, 1.5))
        return Sphere(tuple(t), r), manifold3d.Manifold.sphere(r, SEGMENTS).translate(tuple(t))
    if kind == "ellipsoid":
        s = np.array([draw(st.floats(0.5, 1.5)) for _ in range(3)])
        m2 = m.copy()
        m2[:3, :3] = R @ np.diag(s)
        return Sphere((0, 0, 0), 1.0).transform(m2), manifold3d.Manifold.sphere(1.0, SEGMENTS).transform(m2[:3])
    h = draw(st.floats(0.8, 3.0))
    if kind in ("cylinder", "cone"):
        lo = draw(st.floats(0.3, 1.2))
        hi = lo if kind == "cylinder" else draw(st.one_of(st.just(0.0), st.floats(0.2, 1.2)))
        mesh = manifold3d.Manifold.cylinder(h, lo, hi, SEGMENTS, True).transform(m34)
        return Truncus((0, 0, 0), (0, 0, h), hi, lo).transform(m), mesh
    size = np.array([draw(st.floats(0.5, 2.0)) for _ in range(3)])
    return Box((0, 0, 0), tuple(size)).transform(m), manifold3d.Manifold.cube(tuple(size), True).transform(m34)


@st.composite
def trees(draw: st.DrawFn) -> tuple[object, object]:
    parts = draw(st.lists(leaves(), min_size=1, max_size=4))
    solid, mesh = parts[0]
    for s, mm in parts[1:]:
        op = draw(st.sampled_from(["union", "difference", "intersection"]))
        if op == "union":
            solid, mesh = solid | s, mesh + mm
        elif op == "difference":
            solid, mesh = solid - s, mesh - mm
        else:
            solid, mesh = solid & s, mesh ^ mm
    return solid, mesh


def _cross_section_geometry(cs: object) -> object:
    import shapely

    from isocsg.shapes2d.region import fill

    rings = [np.asarray(r, dtype=np.float64) for r in cs.to_polygons()]  # type: ignore[attr-defined]
    return fill(rings, "nonzero") if rings else shapely.Polygon()


def _compare(shape: object, reference: object, tol: float) -> None:
    got = to_shapely(shape, resolution=1024) if shape is not EMPTY else None  # type: ignore[arg-type]
    if got is None:
        assert reference.area <= tol  # type: ignore[attr-defined]
        return
    assert area(shape) == pytest.approx(reference.area, abs=tol)  # type: ignore[arg-type,attr-defined]
    assert got.symmetric_difference(reference).area <= tol  # type: ignore[attr-defined]


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(trees(), st.floats(-0.5, 0.5))
def test_section_matches_manifold_slice(tree: tuple[object, object], z: float) -> None:
    solid, mesh = tree
    shape = section_at(solid, z)  # type: ignore[arg-type]
    reference = _cross_section_geometry(mesh.slice(z))  # type: ignore[attr-defined]
    _compare(shape, reference, AREA_TOL)


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(leaves(), min_size=1, max_size=3), st.lists(leaves(upright=True), max_size=2))
def test_outline_matches_meshes_shadows(parts: list[tuple[object, object]], holes: list[tuple[object, object]]) -> None:
    """Reference: each convex leaf's shadow is the convex hull of its mesh's vertices in xy; a
    vertical prism through everything removes its own section (its mesh sliced)."""
    import shapely

    solid = parts[0][0]
    for s, _ in parts[1:]:
        solid = solid | s
    hulls = [shapely.convex_hull(shapely.multipoints(np.asarray(mm.to_mesh().vert_properties)[:, :2]))
             for _, mm in parts]  # type: ignore[attr-defined]
    reference = shapely.union_all(hulls)
    for s, mm in holes:  # upright cylinders and boxes stretched through the whole height
        if not isinstance(s, (Box, ConvexPolyhedron, Truncus)) or (isinstance(s, Truncus) and s.r1 != s.r2):
            continue
        through = np.diag([1.0, 1.0, 20.0, 1.0])
        solid = solid - s.transform(through)
        reference = reference.difference(_cross_section_geometry(mm.slice(0.0)))  # type: ignore[attr-defined]
    _compare(projection(solid), reference, AREA_TOL)  # type: ignore[arg-type]
