"""The triangle mesh kind (:class:`isocsg.TriangleMesh`) against independent references.

- rays: a brute-force Moller-Trumbore caster over every triangle, written in numpy in
  ``tests/reference/mesh.py`` (no hierarchy, its own parity rule), on hypothesis-drawn
  star-shaped closed meshes under random maps, and rays aimed exactly at edges and vertices of
  gridded meshes (where the intervals must still be those of the solid);
- volumes: closed forms (prisms over polygons by the shoelace formula, a box), manifold3d's own
  volume of the same mesh, and Booleans with a sphere against manifold3d on a fine sphere;
- sections: shoelace areas of prism cuts and trimesh's own plane sections on tilted planes;
- signed distance: the closed-form distance of a box, for a subdivided box mesh;
- validation: open, inconsistently wound, inside-out, non-finite and badly indexed meshes, and the
  documented repair.
"""

from __future__ import annotations

import math
import re
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

sys.path.insert(0, str(Path(__file__).parent))

from reference.mesh import MESH_LAYERS, mesh_intervals  # noqa: E402

import isocsg  # noqa: E402
from isocsg import InvalidGeometryError, Sphere, TriangleMesh  # noqa: E402

# ----------------------------------------------------------------------------- meshes built here


def prism(outline: list[tuple[float, float]], z0: float, z1: float) -> tuple[np.ndarray, np.ndarray]:
    """A prism over a simple counter-clockwise outline: side quads, caps by manifold3d's triangulation."""
    import manifold3d

    P = np.asarray(outline, dtype=np.float64)
    n = len(P)
    V = np.vstack([np.column_stack([P, np.full(n, z0)]), np.column_stack([P, np.full(n, z1)])])
    cap = np.asarray(manifold3d.triangulate([P]), dtype=np.int64).reshape(-1, 3)
    faces = [cap[:, ::-1], cap + n]  # the bottom seen from below, the top from above
    i = np.arange(n)
    j = (i + 1) % n
    faces.append(np.stack([i, j, j + n], axis=1))
    faces.append(np.stack([i, j + n, i + n], axis=1))
    return V, np.vstack(faces)


def shoelace(outline: list[tuple[float, float]]) -> float:
    x, y = np.asarray(outline, dtype=np.float64).T
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


L_OUTLINE = [(0.0, 0.0), (3.0, 0.0), (3.0, 1.0), (1.0, 1.0), (1.0, 2.5), (0.0, 2.5)]
U_OUTLINE = [(0.0, 0.0), (3.0, 0.0), (3.0, 2.0), (2.2, 2.0), (2.2, 0.7), (0.8, 0.7), (0.8, 2.0), (0.0, 2.0)]


def grid_box(n: int, size: float = 2.0) -> tuple[np.ndarray, np.ndarray]:
    """The cube [0, size]^3 with each face an n x n grid of squares, each split along a diagonal."""
    import trimesh

    m = trimesh.creation.box([size] * 3)
    for _ in range(int(math.log2(n))):
        m = m.subdivide()
    m.apply_translation([size / 2] * 3)
    return np.asarray(m.vertices), np.asarray(m.faces)


def star_mesh(radii: np.ndarray, n_lat: int, n_lon: int) -> tuple[np.ndarray, np.ndarray]:
    """A closed star-shaped mesh: a latitude-longitude sphere with radius ``radii[k]`` per vertex."""
    th = np.pi * np.arange(1, n_lat) / n_lat
    ph = 2 * np.pi * np.arange(n_lon) / n_lon
    dirs = np.stack([np.outer(np.sin(th), np.cos(ph)), np.outer(np.sin(th), np.sin(ph)),
                     np.outer(np.cos(th), np.ones(n_lon))], axis=-1).reshape(-1, 3)
    dirs = np.vstack([[0, 0, 1.0], dirs, [0, 0, -1.0]])
    V = dirs * radii[: len(dirs), None]
    faces = []
    ring = lambda r, k: 1 + r * n_lon + (k % n_lon)  # noqa: E731
    for k in range(n_lon):
        faces.append((0, ring(0, k), ring(0, k + 1)))
        last = n_lat - 2
        faces.append((len(V) - 1, ring(last, k + 1), ring(last, k)))
        for r in range(n_lat - 2):
            a, b, c, d = ring(r, k), ring(r + 1, k), ring(r + 1, k + 1), ring(r, k + 1)
            faces += [(a, b, c), (a, c, d)]
    return V, np.asarray(faces, dtype=np.int64)


# ----------------------------------------------------------------------------- rays


def _same_intervals(got: np.ndarray, t_in: np.ndarray, t_out: np.ndarray, scale: float) -> None:
    k = got.shape[1]
    want = np.full((len(got), max(k, MESH_LAYERS), 2), np.nan)
    want[:, :MESH_LAYERS, 0], want[:, :MESH_LAYERS, 1] = t_in, t_out
    pad = np.full((len(got), want.shape[1], 2), np.nan)
    pad[:, :k] = got
    assert np.array_equal(np.isnan(pad), np.isnan(want))
    ok = np.isfinite(want)
    assert np.allclose(pad[ok], want[ok], atol=1e-9 * scale, rtol=0)


@settings(max_examples=25, deadline=None)
@given(
    radii=st.lists(st.floats(0.5, 1.5), min_size=6 * 9 + 2, max_size=6 * 9 + 2),
    angles=st.tuples(st.floats(-3, 3), st.floats(-3, 3), st.floats(-3, 3)),
    scale=st.floats(0.05, 30.0),
    shift=st.tuples(st.floats(-50, 50), st.floats(-50, 50), st.floats(-50, 50)),
    seed=st.integers(0, 2**31 - 1),
)
def test_rays_match_brute_force_on_random_star_meshes(radii, angles, scale, shift, seed) -> None:
    from scipy.spatial.transform import Rotation

    V, F = star_mesh(np.asarray(radii), 7, 9)
    R = Rotation.from_euler("xyz", angles).as_matrix()
    V = (V @ R.T) * scale + np.asarray(shift)
    mesh = TriangleMesh(V, F)
    rng = np.random.default_rng(seed)
    o = np.asarray(shift) + scale * rng.normal(size=(300, 3)) * 3
    target = np.asarray(shift) + scale * rng.normal(size=(300, 3)) * 0.6
    d = (target - o) * rng.uniform(0.2, 5.0, size=(300, 1))
    t_in, t_out, *_ = mesh_intervals(V, F, o, d)
    _same_intervals(mesh.ray_intervals(o, d), t_in, t_out, 1.0)


def test_rays_through_edges_and_vertices_of_a_gridded_box() -> None:
    """Rays along the axes through every grid point (vertices, edges, face diagonals) of a box made of
    8 x 8 squares per face: inside the box each meets it in exactly [entry, exit] of the solid."""
    V, F = grid_box(8)
    mesh = TriangleMesh(V, F)
    g = np.linspace(0.0, 2.0, 17)[1:-1]  # every vertex and every edge midpoint strictly inside a face
    u, v = np.meshgrid(g, g)
    u, v = u.ravel(), v.ravel()
    for axis in range(3):
        o = np.zeros((len(u), 3))
        others = [k for k in range(3) if k != axis]
        o[:, others[0]], o[:, others[1]] = u, v
        o[:, axis] = -3.0
        d = np.zeros_like(o)
        d[:, axis] = 1.0
        for sign in (1.0, -1.0):
            oo = o.copy()
            if sign < 0:
                oo[:, axis] = 5.0
            iv = mesh.ray_intervals(oo, sign * d)
            assert iv.shape[1] == 1
            assert np.allclose(iv[:, 0, 0], 3.0) and np.allclose(iv[:, 0, 1], 5.0)


def test_rays_aimed_at_vertices_of_a_star_mesh() -> None:
    """Each ray from outside aimed exactly at a vertex crosses the surface there: one interval that
    starts at the vertex (the watertight rule counts the vertex once, whatever its fan)."""
    V, F = star_mesh(np.full(5 * 12 + 2, 1.0), 6, 12)
    mesh = TriangleMesh(V, F)
    o = np.zeros_like(V) + V * 4.0
    d = V - o  # from outside, straight towards the centre: t = 1 at the vertex
    iv = mesh.ray_intervals(o, d)
    assert np.all(np.isfinite(iv[:, 0])) and (iv.shape[1] == 1 or np.all(np.isnan(iv[:, 1:])))
    assert np.allclose(iv[:, 0, 0], 1.0, atol=1e-12)
    assert np.allclose(iv[:, 0, 1], 5.0 / 3.0, atol=1e-12)  # out through the opposite vertex, 4 v - 3 t v = -v


def test_ray_intervals_many_and_first_hit() -> None:
    """A comb of teeth: one ray meets it in as many intervals as teeth; intersect_rays gives the first
    interval with the faces' normals."""
    teeth = 6
    outline = [(0.0, 0.0), (2.0 * teeth - 1.0, 0.0)]
    for k in range(teeth - 1, -1, -1):  # tooth k spans x in [2k, 2k + 1], y in [1, 3]
        outline += [(2.0 * k + 1.0, 3.0), (2.0 * k, 3.0)]
        if k > 0:
            outline += [(2.0 * k, 1.0), (2.0 * k - 1.0, 1.0)]
    V, F = prism(outline, 0.0, 1.0)
    mesh = TriangleMesh(V, F)
    assert math.isclose(mesh.volume, shoelace(outline), rel_tol=1e-13)
    iv = mesh.ray_intervals([[-1.0, 2.0, 0.5]], [[1.0, 0.0, 0.0]])
    assert iv.shape == (1, teeth, 2)
    assert np.allclose(iv[0], [[1.0 + 2 * k, 2.0 + 2 * k] for k in range(teeth)])
    hits = mesh.intersect_rays([[-1.0, 2.0, 0.5]], [[1.0, 0.0, 0.0]])
    assert hits.t_in[0] == pytest.approx(1.0) and hits.t_out[0] == pytest.approx(2.0)
    assert np.allclose(hits.n_in[0], [-1, 0, 0]) and np.allclose(hits.n_out[0], [1, 0, 0])
    assert mesh.max_intervals == len(mesh.faces) // 2


# ----------------------------------------------------------------------------- volumes and sections


@pytest.mark.parametrize("outline", [L_OUTLINE, U_OUTLINE], ids=["L", "U"])
def test_prism_volume_and_sections_closed_forms(outline) -> None:
    from isocsg.csg.section import plane_frame

    V, F = prism(outline, -0.5, 1.25)
    mesh = TriangleMesh(V, F)
    area = shoelace(outline)
    assert math.isclose(mesh.volume, area * 1.75, rel_tol=1e-13)
    assert math.isclose(isocsg.volume(mesh), area * 1.75, rel_tol=1e-13)
    for z in (-0.4, 0.0, 1.2):
        g = mesh.section(plane_frame(np.array([0, 0, z]), np.array([0, 0, 1.0])), 64)
        assert math.isclose(g.area, area, rel_tol=1e-12)
    assert math.isclose(isocsg.volume(mesh, axis=(0.3, 0.2, 1.0)), area * 1.75, rel_tol=1e-6)


@pytest.mark.parametrize("normal", [(0.2, 0.3, 1.0), (1.0, -0.4, 0.3), (0.0, 1.0, 0.05)])
def test_sections_match_trimesh(normal) -> None:
    import trimesh

    from isocsg.csg.section import plane_frame

    V, F = star_mesh(1.0 + 0.4 * np.sin(np.arange(7 * 12 + 2) * 1.7), 8, 12)
    mesh = TriangleMesh(V, F)
    n = np.asarray(normal) / np.linalg.norm(normal)
    for h in (-0.3, 0.0, 0.45):
        ours = mesh.section(plane_frame(h * n, n), 64).area
        path = trimesh.Trimesh(V, F, process=False).section(plane_normal=n, plane_origin=h * n)
        theirs = 0.0 if path is None else sum(p.area for p in path.to_2D()[0].polygons_full)
        assert math.isclose(ours, theirs, rel_tol=1e-9, abs_tol=1e-12)


def test_volume_matches_manifold3d_on_a_torus_mesh() -> None:
    import trimesh

    t = trimesh.creation.torus(2.0, 0.6, major_sections=48, minor_sections=20)
    mesh = TriangleMesh(t.vertices, t.faces)
    assert math.isclose(mesh.volume, mesh.to_manifold().volume(), rel_tol=1e-12)
    # the polyhedral torus lies inside the round one, within the sagitta of its polygons
    assert 0.97 * 2 * math.pi**2 * 2.0 * 0.36 < mesh.volume < 2 * math.pi**2 * 2.0 * 0.36


@pytest.mark.parametrize("op", ["difference", "intersection", "union"])
def test_booleans_with_a_sphere_match_manifold3d(op) -> None:
    import manifold3d

    V, F = prism(U_OUTLINE, 0.0, 1.0)
    mesh = TriangleMesh(V, F)
    ball = Sphere((1.5, 0.5, 0.8), 0.7)
    solid = {"difference": mesh - ball, "intersection": mesh & ball, "union": mesh | ball}[op]
    fine = manifold3d.Manifold.sphere(0.7, 720).translate([1.5, 0.5, 0.8])
    ref_m = mesh.to_manifold()
    ref = {"difference": ref_m - fine, "intersection": ref_m ^ fine, "union": ref_m + fine}[op].volume()
    # the fine sphere's polygonal error: 1 - (sin(2 pi / 720) / (2 pi / 720))-like, below 3e-5 of its volume
    assert math.isclose(isocsg.volume(solid, tol=1e-6), ref, rel_tol=1e-4)


@settings(max_examples=15, deadline=None)
@given(
    m=st.lists(st.floats(-2, 2), min_size=9, max_size=9),
    t=st.tuples(st.floats(-10, 10), st.floats(-10, 10), st.floats(-10, 10)),
)
@example(m=[1.0, 0.0, 0.0, 2.0, 1.126673851145637, 0.0, 0.0, 0.375, 1.0], t=(0.0, 0.0, 0.0))  # a shear once read
# as a self-intersection (an edge of the top face judged through a coplanar triangle of it)
def test_affine_maps_scale_the_volume(m, t) -> None:
    A = np.asarray(m).reshape(3, 3)
    det = float(np.linalg.det(A))
    if abs(det) < 0.05 or np.linalg.cond(A) > 1e3:
        return
    V, F = prism(L_OUTLINE, 0.0, 1.0)
    mesh = TriangleMesh(V, F)
    mapped = mesh.transform(np.vstack([np.column_stack([A, t]), [0, 0, 0, 1]]))
    assert isinstance(mapped, TriangleMesh)
    assert math.isclose(mapped.volume, abs(det) * mesh.volume, rel_tol=1e-10)


def test_signed_distance_of_a_box_mesh_is_the_box_distance() -> None:
    V, F = grid_box(4)
    mesh = TriangleMesh(V, F)
    rng = np.random.default_rng(3)
    p = rng.uniform(-1.0, 3.0, size=(2000, 3))
    q = np.abs(p - 1.0) - 1.0  # the box [0, 2]^3 about its centre
    exact = np.linalg.norm(np.maximum(q, 0.0), axis=1) + np.minimum(q.max(axis=1), 0.0)
    assert np.allclose(mesh.signed_distance(p), exact, atol=1e-12)
    assert np.array_equal(mesh.contains(p), exact <= 0)


def test_normals_are_the_faces_outward_normals() -> None:
    V, F = grid_box(2)
    mesh = TriangleMesh(V, F)
    pts = np.array([[1.0, 1.0, 2.0], [0.0, 0.7, 0.3], [1.2, 2.0, 0.5]])
    assert np.allclose(mesh.normals_at(pts), [[0, 0, 1], [-1, 0, 0], [0, 1, 0]])


# ----------------------------------------------------------------------------- validation


def _tetra() -> tuple[np.ndarray, np.ndarray]:
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]])
    F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    return V, F


BAD = [
    ("nan", lambda V, F: (np.where(np.arange(12).reshape(4, 3) == 4, np.nan, V), F), "TriangleMesh.vertices must be finite"),
    ("shape", lambda V, F: (V[:, :2], F), "TriangleMesh.vertices must have shape (n, 3), got (4, 2)"),
    ("quads", lambda V, F: (V, np.hstack([F, F[:, :1]])), "TriangleMesh.faces must have shape (m, 3) (triangles)"),
    ("index", lambda V, F: (V, np.where(F == 3, 7, F)), "TriangleMesh.faces must index the 4 vertices, got indices 0 .. 7"),
    # the last face split in three about its centre, one of the three left out
    ("open", lambda V, F: (np.vstack([V, V[1:].mean(axis=0)]), np.vstack([F[:3], [[1, 2, 4], [2, 3, 4]]])),
     "TriangleMesh.faces are not closed (watertight): the edge 1 -> 3 of face 1 has no face on its other side"),
    ("few", lambda V, F: (V, F[:3]), "TriangleMesh.faces must hold at least 4 triangles"),
    ("flipped_one", lambda V, F: (V, np.vstack([F[:3], F[3:, ::-1]])), "TriangleMesh.faces are not consistently oriented"),
    ("inside_out", lambda V, F: (V, F[:, ::-1]), "TriangleMesh must have a positive volume"),
    ("repeat", lambda V, F: (V, np.vstack([F, [[0, 0, 1]]])), "TriangleMesh.faces must not repeat a vertex"),
    ("fractional", lambda V, F: (V, F + 0.5), "TriangleMesh.faces must hold integer vertex indices"),
]


@pytest.mark.parametrize("name, change, message", BAD, ids=[b[0] for b in BAD])
def test_invalid_meshes_are_refused_naming_the_problem(name, change, message) -> None:
    V, F = change(*_tetra())
    with pytest.raises(InvalidGeometryError, match=re.escape(message)):
        TriangleMesh(V, F)


def test_repair_fills_a_hole_and_fixes_the_winding() -> None:
    V, F = grid_box(2)
    with pytest.raises(InvalidGeometryError, match="not closed"):
        TriangleMesh(V, F[1:])
    fixed = TriangleMesh.repaired(V, F[1:])
    assert math.isclose(fixed.volume, 8.0, rel_tol=1e-12)
    flipped = F.copy()
    flipped[::3] = flipped[::3, ::-1]
    with pytest.raises(InvalidGeometryError, match="consistently oriented"):
        TriangleMesh(V, flipped)
    assert math.isclose(TriangleMesh.repaired(V, flipped).volume, 8.0, rel_tol=1e-12)
    assert math.isclose(TriangleMesh.repaired(V, F[:, ::-1]).volume, 8.0, rel_tol=1e-12)


def test_value_semantics_scene_files_and_openscad_text() -> None:
    V, F = prism(L_OUTLINE, 0.0, 1.0)
    a, b = TriangleMesh(V, F), TriangleMesh(V.tolist(), F.tolist())
    assert a == b and hash(a) == hash(b) and a != TriangleMesh(V + 1e-9, F)
    assert TriangleMesh.from_dict(a.to_dict()["mesh"]) == a
    from isocsg.kinds import kind_named

    assert kind_named("mesh").build(a.to_dict()["mesh"]) == a
    back = isocsg.loads_openscad(a.to_openscad())
    assert isinstance(back, TriangleMesh) and math.isclose(back.volume, a.volume, rel_tol=1e-13)
    assert a.convex is False and not a.is_convex()
    pieces = a.convex_pieces()  # the L prism: a binary space partition along its face planes
    assert len(pieces) >= 2 and math.isclose(sum(p.volume for p in pieces), a.volume, rel_tol=1e-12)
    cube = TriangleMesh(*grid_box(2))
    (piece,) = cube.convex_pieces()
    assert math.isclose(piece.volume, 8.0, rel_tol=1e-12)


def test_scene_files_read_meshes_and_name_their_errors() -> None:
    import json

    from isocsg import SceneFileError

    V, F = _tetra()
    mesh = TriangleMesh(V, F)
    doc = {"camera": {"eye": [3, 3, 3], "target": [0, 0, 0]}, "lights": [{"kind": "directional", "direction": [0, 0, 1]}],
           "objects": [{"shape": mesh.to_dict()}]}
    assert isocsg.loads_scene(json.dumps(doc), format="json").objects[0].shape == mesh
    doc["objects"][0]["shape"]["mesh"]["faces"][0] = [0, 1, 2]
    with pytest.raises(SceneFileError, match=re.escape("objects[0].shape.mesh.faces: are not consistently oriented")):
        isocsg.loads_scene(json.dumps(doc), format="json")


def test_self_intersecting_meshes_are_refused() -> None:
    """Two overlapping boxes in one mesh (each closed and outward): their faces cross. A sphere-like
    mesh whose north pole is pushed out through its south: the pole's fan crosses the south cap."""
    V, F = grid_box(1)
    F2 = np.vstack([F, F + len(V)])
    with pytest.raises(InvalidGeometryError, match=re.escape("TriangleMesh.faces intersect themselves: the edge")):
        TriangleMesh(np.vstack([V, V + 0.5]), F2)
    # apart, the two boxes are one valid mesh of two shells
    assert math.isclose(TriangleMesh(np.vstack([V, V + 3.0]), F2).volume, 16.0, rel_tol=1e-13)
    S, G = star_mesh(np.full(5 * 8 + 2, 1.0), 6, 8)
    TriangleMesh(S, G)
    S[0] = (0.05, 0.02, -1.6)
    with pytest.raises(InvalidGeometryError, match="intersect themselves"):
        TriangleMesh(S, G)
