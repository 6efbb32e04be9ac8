"""A non-convex triangle mesh as a shadow occluder: its exact convex decomposition.

Judged independently of the decomposition:
- the meshes are unions and differences of axis-aligned boxes (meshed by manifold3d), so
  membership has a closed form (the boxes' own inequalities) and the volume one too
  (trimesh's divergence-theorem volume of the same triangles);
- the illuminance under the mesh equals the illuminance under the same solid written as a CSG
  tree of Box kinds, whose occluder pieces come from the boxes' own faces.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import isocsg
from isocsg import AreaLight, Box, TriangleMesh
from isocsg.errors import InvalidParameterError
from isocsg.kinds import mesh_convex

m3d = pytest.importorskip("manifold3d")
trimesh = pytest.importorskip("trimesh")


def box_manifold(lo, hi):
    return m3d.Manifold.cube(list(np.subtract(hi, lo))).translate(list(lo))


def to_mesh(man) -> TriangleMesh:
    m = man.to_mesh()
    return TriangleMesh(np.asarray(m.vert_properties, dtype=np.float64)[:, :3], np.asarray(m.tri_verts))


def in_boxes(points, boxes):
    """Closed-form membership: in the first box and in no later one (add) / minus the rest (sub)."""
    inside = np.zeros(len(points), dtype=bool)
    for lo, hi, sign in boxes:
        hit = np.all((points > lo) & (points < hi), axis=1)
        inside = inside | hit if sign > 0 else inside & ~hit
    return inside


def near_faces(points, boxes, eps):
    """Points within eps of a box's face plane, where the closed form and rounding may disagree."""
    near = np.zeros(len(points), dtype=bool)
    for lo, hi, _ in boxes:
        near |= np.any((np.abs(points - lo) < eps) | (np.abs(points - hi) < eps), axis=1)
    return near


def test_l_prism_shadow_equals_the_same_solid_from_boxes() -> None:
    a, b = ((0, 0, 0), (2, 1, 1)), ((0, 0, 0), (1, 2, 1))
    mesh = to_mesh(box_manifold(*a) + box_manifold(*b))
    boxes = Box((1, 0.5, 0.5), (2, 1, 1)) | Box((0.5, 1, 0.5), (1, 2, 1))
    assert not mesh.is_convex()
    lamp = AreaLight([(-1, -1, 4), (-1, 3, 4), (3, 3, 4), (3, -1, 4)], 1000.0)  # facing down
    xs = np.linspace(-1.5, 3.5, 41)
    X, Y = np.meshgrid(xs, xs)
    pts = np.c_[X.ravel(), Y.ravel(), np.full(X.size, -0.5)]
    nrm = np.tile([0.0, 0.0, 1.0], (len(pts), 1))
    e_mesh = isocsg.illuminance(pts, nrm, [lamp], [mesh])
    e_boxes = isocsg.illuminance(pts, nrm, [lamp], [boxes])
    free = isocsg.illuminance(pts, nrm, [lamp], [])
    assert np.count_nonzero(e_boxes < free * 0.5) > 50
    np.testing.assert_allclose(e_mesh, e_boxes, rtol=1e-10, atol=1e-9 * free.max())


boxes_strategy = st.lists(
    st.tuples(st.tuples(*[st.integers(0, 6)] * 3), st.tuples(*[st.integers(1, 4)] * 3), st.sampled_from([1, -1])),
    min_size=2, max_size=4)


@settings(max_examples=15, deadline=None)
@given(boxes_strategy, st.integers(0, 2**31 - 1))
def test_decomposition_covers_the_mesh_exactly(spec, seed) -> None:
    spec[0] = (spec[0][0], spec[0][1], 1)  # start from a box
    boxes = [(np.array(lo, float) * 0.5, np.array(lo, float) * 0.5 + np.array(sz, float) * 0.5, s)
             for lo, sz, s in spec]
    man = box_manifold(boxes[0][0], boxes[0][1])
    for lo, hi, s in boxes[1:]:
        man = man + box_manifold(lo, hi) if s > 0 else man - box_manifold(lo, hi)
    if man.volume() < 1e-6 or man.genus() < 0:
        return
    try:
        mesh = to_mesh(man)
    except isocsg.InvalidGeometryError:  # several shells touching along an edge: not one valid mesh
        return
    pieces = mesh.convex_pieces()
    m = man.to_mesh()
    tm = trimesh.Trimesh(np.asarray(m.vert_properties)[:, :3], np.asarray(m.tri_verts), process=False)
    assert math.isclose(sum(p.volume for p in pieces), tm.volume, rel_tol=1e-9)
    rng = np.random.default_rng(seed)
    pts = rng.uniform(-0.2, 5.2, (4000, 3))
    pts = pts[~near_faces(pts, boxes, 1e-6)]
    in_pieces = np.zeros(len(pts), dtype=bool)
    for p in pieces:
        in_pieces |= np.all(pts @ p.face_normals.T <= p.face_offsets + 1e-12, axis=1)
    np.testing.assert_array_equal(in_pieces, in_boxes(pts, boxes))


def test_too_large_meshes_are_refused_by_name(monkeypatch) -> None:
    mesh = to_mesh(box_manifold((0, 0, 0), (2, 1, 1)) + box_manifold((0, 0, 0), (1, 2, 1)))
    monkeypatch.setattr(mesh_convex, "MAX_DECOMPOSITION_FACES", 10)
    with pytest.raises(InvalidParameterError, match=r"TriangleMesh\.faces.*too large"):
        mesh.convex_pieces()
    monkeypatch.setattr(mesh_convex, "MAX_DECOMPOSITION_FACES", 20_000)
    monkeypatch.setattr(mesh_convex, "MAX_DECOMPOSITION_CELLS", 2)
    with pytest.raises(InvalidParameterError, match=r"TriangleMesh\.faces.*passed 2 cells"):
        mesh.convex_pieces()
