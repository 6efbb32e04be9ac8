"""What the heavier real-world models needed (``benchmarks/openscad_realworld.py --heavy``).

- the hull of a difference whose cuts keep every corner of the first operand's hull (a drawer's
  block is ``hull() drawer();``, a hollow box): the hull of the first operand, judged by closed
  forms and by OpenSCAD's STL export where ``openscad`` is installed; a cut through a corner is
  still refused;
- polygon faces as whole arrays (:mod:`isocsg.kinds.polygon_faces`): volumes of prisms with convex
  and non-convex faces against closed forms and manifold3d, a star face not taken as a fan.
"""

from __future__ import annotations

import math
import shutil
import subprocess
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from isocsg import Box, NotExactError, OpenSCADError, hull, loads_openscad, volume
from isocsg.kinds.mesh_io import polygon_mesh
from isocsg.kinds.polygon_faces import fan_triangles, signed_volume, triangulate_faces

HAS_OPENSCAD = shutil.which("openscad") is not None


def _openscad_volume(source: str, tmp_path: Path) -> float:
    import trimesh

    scad, stl = tmp_path / "m.scad", tmp_path / "m.stl"
    scad.write_text(source)
    subprocess.run(["openscad", "-o", str(stl), str(scad)], capture_output=True, check=True, timeout=120)
    return float(abs(trimesh.load(str(stl), force="mesh").volume))


def _load_volume(source: str) -> float:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return volume(loads_openscad(source), tol=1e-6)


DRAWER = """
hull() difference() {
    cube([40, 30, 20]);
    translate([2, 2, 2]) cube([36, 26, 30]);    // open at the top: the cut reaches past the hull
    translate([10, -1, 5]) cube([20, 5, 10]);   // a window through the front wall
}
"""


def test_hull_of_a_hollow_box_is_the_box() -> None:
    assert _load_volume(DRAWER) == pytest.approx(40 * 30 * 20, rel=1e-9)


@pytest.mark.skipif(not HAS_OPENSCAD, reason="the openscad program is not installed (apt install openscad)")
def test_hull_of_a_difference_matches_openscad(tmp_path: Path) -> None:
    """Rotated, its STL's corners are printed to 6 significant digits: 1e-5 of the volume."""
    source = "rotate([10, 20, 30]) scale([1, 2, 1]) " + DRAWER.strip()
    got = _load_volume(source)
    assert got == pytest.approx(2 * 40 * 30 * 20, rel=1e-9)
    assert got == pytest.approx(_openscad_volume(source, tmp_path), rel=1e-5)


@given(size=st.tuples(*[st.floats(1.0, 50.0)] * 3), inset=st.floats(0.05, 0.45), through=st.booleans())
@settings(max_examples=25, deadline=None)
def test_hull_of_a_box_less_an_inner_cut_is_the_box(size: tuple[float, float, float], inset: float,
                                                    through: bool) -> None:
    """A cut strictly inside in x and y, through the box in z or not: the hull is the box."""
    s = np.asarray(size)
    cut_size = s * np.array([1 - 2 * inset, 1 - 2 * inset, 2.0 if through else 0.5])
    solid = Box((0, 0, 0), tuple(s)) - Box((0, 0, 0), tuple(cut_size))
    assert volume(hull(solid)) == pytest.approx(float(np.prod(s)), rel=1e-9)


def test_a_cut_through_a_corner_is_still_refused() -> None:
    """The corner is gone: the hull is smaller than the first operand's; no exact form here."""
    solid = Box((0, 0, 0), (2, 2, 2)) - Box((1, 1, 1), (1, 1, 1))
    with pytest.raises(NotExactError, match="difference"):
        hull(solid)


def test_a_cut_touching_a_corner_is_refused() -> None:
    """A cut whose face passes through the corner, within rounding, is not trusted to keep it."""
    solid = Box((0, 0, 0), (2, 2, 2)) - Box((1.5, 1.5, 0), (1, 1, 4))  # its edge through (1, 1, +-1)
    with pytest.raises(NotExactError, match="difference"):
        hull(solid)


# ---------------------------------------------------------------- polygon faces as arrays

def _prism(ring: np.ndarray, h: float) -> tuple[np.ndarray, list[list[int]]]:
    """A right prism over a counter-clockwise ring, faces clockwise seen from outside (OpenSCAD)."""
    n = len(ring)
    pts = np.vstack([np.column_stack([ring, np.zeros(n)]), np.column_stack([ring, np.full(n, h)])])
    bottom = list(range(n))  # clockwise seen from below
    top = list(range(2 * n - 1, n - 1, -1))
    sides = [[i, n + i, n + (i + 1) % n, (i + 1) % n] for i in range(n)]
    return pts, [bottom, top, *sides]


@given(n=st.integers(3, 40), r=st.floats(0.01, 100.0), h=st.floats(0.01, 100.0))
@settings(max_examples=30, deadline=None)
def test_regular_prism_volume_is_the_closed_form(n: int, r: float, h: float) -> None:
    t = 2 * np.pi * np.arange(n) / n
    pts, faces = _prism(np.column_stack([r * np.cos(t), r * np.sin(t)]), h)
    want = 0.5 * n * r * r * math.sin(2 * math.pi / n) * h
    assert -signed_volume(pts, faces) == pytest.approx(want, rel=1e-9)  # clockwise faces: negative
    assert polygon_mesh(pts, faces).volume == pytest.approx(want, rel=1e-9)


def test_non_convex_face_is_triangulated_inside_itself() -> None:
    """An L-shaped prism (area 3) and a comb: no fan, manifold3d's triangulation; volume closed form
    and manifold3d's own volume of the same faces."""
    import manifold3d

    ring = np.array([[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]], dtype=float)
    pts, faces = _prism(ring, 1.5)
    T = triangulate_faces(pts, faces)
    assert len(T) == 2 * (len(ring) - 2) + 2 * len(ring)
    assert polygon_mesh(pts, faces).volume == pytest.approx(3 * 1.5, rel=1e-12)
    m = manifold3d.Manifold(manifold3d.Mesh(vert_properties=pts.astype(np.float32), tri_verts=T[:, ::-1].astype(np.uint32)))
    assert m.volume() == pytest.approx(4.5, rel=1e-6)


def test_star_face_is_not_a_fan() -> None:
    """A pentagram turns left at every corner but goes twice around: a fan would cover its core
    twice; the triangulation covers the area it encloses once (manifold3d's rule for the ring)."""
    t = np.pi / 2 + 4 * np.pi * np.arange(5) / 5
    ring = np.column_stack([np.cos(t), np.sin(t)])
    pts = np.column_stack([ring, np.zeros(5)])
    T = triangulate_faces(pts, [list(range(5))])
    fan = fan_triangles([list(range(5))])
    assert not np.array_equal(np.sort(T, axis=1), np.sort(fan, axis=1))


def test_repeated_points_and_flat_faces_are_dropped() -> None:
    pts = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    faces = [[0, 1, 1, 2], [0, 3, 1], [1, 3, 2], [2, 3, 0], [0, 1, 0], [0, 0, 0, 1]]
    T = triangulate_faces(pts, faces)
    assert len(T) == 4
    assert polygon_mesh(pts, faces).volume == pytest.approx(1 / 6, rel=1e-12)


def test_many_faces_load_as_arrays() -> None:
    """A generated polyhedron of 20 000 quads (a closed grid tube) loads: volume against the
    closed form of its polygonal section."""
    n, m = 200, 100  # around, along
    t = 2 * np.pi * np.arange(n) / n
    z = np.linspace(0.0, 10.0, m)
    pts = np.vstack([np.column_stack([np.cos(t), np.sin(t), np.full(n, zk)]) for zk in z])
    faces = [[k * n + i, (k + 1) * n + i, (k + 1) * n + (i + 1) % n, k * n + (i + 1) % n]
             for k in range(m - 1) for i in range(n)]
    faces += [list(range(n)), list(range(m * n - 1, (m - 1) * n - 1, -1))]
    want = 0.5 * n * math.sin(2 * math.pi / n) * 10.0
    assert abs(signed_volume(pts, faces)) == pytest.approx(want, rel=1e-9)
    assert polygon_mesh(pts, faces).volume == pytest.approx(want, rel=1e-9)


# ---------------------------------------------------------------- lists of numbers read at once

_numbers = st.floats(-1e12, 1e12, allow_nan=False) | st.integers(-10**6, 10**6).map(float)


@given(points=st.lists(st.lists(_numbers, min_size=3, max_size=3), min_size=1, max_size=30),
       style=st.sampled_from(["%r", "%g", "%.6e"]))
@settings(max_examples=40, deadline=None)
def test_number_lists_read_as_written(points: list[list[float]], style: str) -> None:
    """The numbers as written (formatted here, parsed back by Python's float), lines counted past
    a list spread over many lines."""
    from isocsg.openscad.parser import parse_csg

    body = ",\n".join("[" + ", ".join(style % x for x in p) + "]" for p in points)
    text = f"polyhedron(points = [{body}], faces = [[0, 1, 2]]);\ncube(1);\n"
    calls = parse_csg(text)
    want = [[float(style % x) for x in p] for p in points]
    assert calls[0].kwargs["points"] == want
    assert calls[0].kwargs["faces"] == [[0.0, 1.0, 2.0]]
    assert calls[1].line == len(points) + 1


def test_lists_with_other_values_take_the_token_path() -> None:
    from isocsg.openscad.parser import parse_csg

    calls = parse_csg('f(a = [[1, 2], "x", [.5, inf]]);')
    assert calls[0].kwargs["a"] == [[1.0, 2.0], "x", [0.5, math.inf]]
    with pytest.raises(OpenSCADError, match="1e999 in the arguments of f is too large"):
        parse_csg("f(b = [1e999]);")


@given(n=st.integers(3, 64), r=st.floats(0.01, 100.0), h=st.floats(0.01, 100.0))
@settings(max_examples=20, deadline=None)
def test_polygonal_cylinder_faces_wind_around_their_normals(n: int, r: float, h: float) -> None:
    """OpenSCAD's n-sided cylinder as a hull: n + 2 faces (sides and ends, all faces at once),
    each counter-clockwise about its outward normal, triangles covering the closed-form volume."""
    from isocsg import ConvexPolyhedron
    from isocsg.openscad.flat import cylinder_points

    c = ConvexPolyhedron(cylinder_points(n, r, r, 0.0, h))
    assert len(c.faces) == n + 2
    assert sorted(len(f) for f in c.faces) == sorted([4] * n + [n, n])
    for f, normal in zip(c.faces, c.face_normals):
        q = c.hull_vertices[f]
        newell = np.cross(q - q.mean(axis=0), np.roll(q, -1, axis=0) - q.mean(axis=0)).sum(axis=0)
        assert newell @ normal > 0
    want = 0.5 * n * r * r * math.sin(2 * math.pi / n) * h
    assert c.volume == pytest.approx(want, rel=1e-9)
    T = c.triangles
    a, b, d = (c.hull_vertices[T[:, k]] for k in range(3))
    assert float(np.einsum("ij,ij->i", a, np.cross(b, d)).sum()) / 6 == pytest.approx(want, rel=1e-9)
