"""The true topology of all-planar trees from their exact boundary polygons
(isocsg.testing.planar_topology), judged by closed forms (genus of a box with k through holes,
components, cavities) and cross-checked against manifold3d's exact Boolean on random trees
where no sheets touch: the truth is not read from manifold3d, so the agreement is evidence."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from isocsg import Box, ConvexPolyhedron
from isocsg.csg.mesh import to_manifold
from isocsg.testing import compare_mesh
from isocsg.testing.compare import compare_topology, topology, true_topology
from isocsg.testing.planar_topology import planar_topology, refusal
from isocsg.testing.strategies import manifold_cube, manifold_fuzz

SLAB = Box((0, 0, 0), (7, 3, 1))


def _holes(k):
    """The slab minus ``k`` square through holes (genus ``k``)."""
    out = SLAB
    for i in range(k):
        out = out - Box((-2.0 + 2.0 * i, 0, 0), (1, 1, 2))
    return out


@pytest.mark.parametrize("k", [0, 1, 2, 3])
def test_genus_of_a_slab_with_through_holes(k):
    t = planar_topology(_holes(k))
    assert (t.components, t.genus, t.euler, t.voids, t.touching) == (1, k, 2 - 2 * k, 0, False)


def test_components_voids_and_turned_holes():
    two = planar_topology(Box((0, 0, 0), (1, 1, 1)) | Box((3, 0, 0), (1, 1, 1)))
    assert (two.components, two.genus, two.voids) == (2, 0, 0)
    cavity = planar_topology(Box((0, 0, 0), (3, 3, 3)) - Box((0.2, 0.1, 0), (1, 1, 1)))
    assert (cavity.components, cavity.genus, cavity.voids) == (2, 0, 1)  # the outer shell and the void's
    nested = Box((0, 0, 0), (5, 5, 5)) - Box((0, 0, 0), (3, 3, 3)) | Box((0, 0, 0), (1, 1, 1))
    t = planar_topology(nested)  # a ball in a cavity: three shells, one of them a void
    assert (t.components, t.genus, t.voids) == (3, 0, 1)
    turned = Box((0, 0, 0), (3, 3, 1)) - Box((0, 0, 0), (1, 1, 2)).rotate((0, 0, 30))
    assert (planar_topology(turned).components, planar_topology(turned).genus) == (1, 1)
    tetra = ConvexPolyhedron([(0, 0, 0), (2, 0, 0), (0, 2, 0), (0, 0, 2)])
    pierced = tetra - Box((0.4, 0.4, 0), (0.3, 0.3, 3))  # a tetrahedron pierced from base to side faces
    assert (planar_topology(pierced).components, planar_topology(pierced).genus) == (1, 1)
    # faces cut by different neighbours meet at T-junctions
    step = Box((0, 0, 0), (2, 1, 1)) | Box((0.5, 0, 1), (1, 1, 1)) | Box((-0.25, 0, -1), (0.5, 0.5, 1))
    assert (planar_topology(step).components, planar_topology(step).genus) == (1, 0)
    empty = planar_topology(Box((0, 0, 0), (1, 1, 1)) - Box((0, 0, 0), (1, 1, 1)))
    assert (empty.components, empty.genus) == (0, 0)


def test_touching_sheets_are_kept_apart_and_flagged():
    a = Box((0, 0, 0), (1, 1, 1))
    edge = planar_topology(a | Box((1, 1, 0), (1, 1, 1)))  # two cubes along one edge
    corner = planar_topology(a | Box((1, 1, 1), (1, 1, 1)))  # at one corner
    for t in (edge, corner):
        assert (t.components, t.genus, t.euler, t.touching) == (2, 0, 4, True)
    glued = planar_topology(a | Box((1, 0, 0), (1, 1, 1)))  # along a whole face: one box
    assert (glued.components, glued.genus, glued.touching) == (1, 0, False)  # coincident faces: exact
    # a corner of one box on the middle of the other's face: a contact, flagged
    corner_down = Box((0, 0, 0), (1, 1, 1)).rotate((45, 35.26438968275466, 0))  # a diagonal along z
    poke = a | corner_down.translate((0.1, 0.05, 0.5 - float(corner_down.bounds[0][2])))
    assert planar_topology(poke).touching
    # two holes along one edge: across the solid the cavities join into one void
    voids = planar_topology(Box((0, 0, 0), (3, 3, 3)) - Box((-0.5, -0.5, 0), (1, 1, 1)) - Box((0.5, 0.5, 0), (1, 1, 1)))
    assert (voids.components, voids.voids, voids.touching) == (2, 1, True)


def test_truth_needs_no_mesh_engine(monkeypatch):
    import isocsg.testing.compare as C

    def refuse(*_a, **_k):
        raise AssertionError("the truth of a planar tree read a manifold3d mesh")

    monkeypatch.setattr(C, "to_manifold", refuse)
    t = true_topology(_holes(2))
    assert (t.source, t.components, t.genus) == ("polygons", 1, 2.0)


def test_compare_mesh_judges_planar_topology_by_polygons():
    import trimesh

    tree = _holes(2)
    good = compare_mesh(to_manifold(tree, 8), tree, samples=200)
    assert good.ok and good.topology_true.source == "polygons" and dict(good.verdicts)["topology"] == "exact"
    assert "from polygons" in good.summary()
    # the mesh of a tree with one hole fewer: closed, but of genus 1
    m = to_manifold(_holes(1), 8).to_mesh()
    wrong = trimesh.Trimesh(np.asarray(m.vert_properties)[:, :3], np.asarray(m.tri_verts), process=False)
    topo, true, verdict = compare_topology(wrong, tree)
    assert (topo.genus, true.genus, verdict) == (1.0, 2.0, "wrong")


def _planar_leaf(draw):
    # coordinates in general position: a contact (a corner on another leaf's face plane) makes
    # the truth "touching", where a mesh may separate or join the sheets either way
    k = st.floats(-0.8, 0.8, allow_nan=False).map(lambda x: x + 1e-3 * np.sin(1e3 * x))
    s = st.floats(0.3, 1.6, allow_nan=False)
    c = (draw(k), draw(k), draw(k))
    kind = draw(st.sampled_from(["box", "turned", "poly"]))
    if kind == "poly":
        pts = np.asarray(draw(st.lists(st.tuples(k, k, k), min_size=4, max_size=8)), dtype=float)
        if abs(np.linalg.det(np.cov(pts.T))) < 1e-6:
            return Box(c, (draw(s), draw(s), draw(s)))
        return ConvexPolyhedron(pts)
    box = Box(c, (draw(s), draw(s), draw(s)))
    angles = (draw(st.floats(0, 90)), draw(st.floats(0, 90)), draw(st.floats(0, 90)))
    return box.rotate(angles) if kind == "turned" else box


@st.composite
def planar_trees(draw, max_leaves=5):
    parts = [_planar_leaf(draw) for _ in range(draw(st.integers(2, max_leaves)))]
    while len(parts) > 1:
        i = draw(st.integers(0, len(parts) - 2))
        op = draw(st.sampled_from(["|", "&", "-"]))
        a, b = parts[i], parts[i + 1]
        parts[i: i + 2] = [a | b if op == "|" else a & b if op == "&" else a - b]
    return parts[0]


def _agree_with_manifold3d(tree, may_refuse=False):
    truth = refusal(tree)
    if isinstance(truth, str):  # documented: then the truth is read from manifold3d's mesh, and says so
        assert may_refuse, truth
        assert true_topology(tree).source == "mesh"
        return
    mesh = topology(to_manifold(tree, 8))
    if not (truth.touching or mesh.touching):
        assert (truth.components, truth.genus, truth.voids) == (mesh.components, mesh.genus, mesh.voids), (truth, mesh)


@settings(max_examples=25, deadline=None, suppress_health_check=list(HealthCheck))
@given(planar_trees())
def test_random_planar_trees_against_manifold3d(tree):
    _agree_with_manifold3d(tree)


@settings(max_examples=6, deadline=None, suppress_health_check=list(HealthCheck))
@given(manifold_fuzz(max_ops=12, max_transforms=20))
def test_fuzz_trees_of_twenty_transforms_against_manifold3d(tree):
    _agree_with_manifold3d(tree, may_refuse=True)


def test_twenty_transforms_compose_once_as_manifold3d_does():
    # a cube moved by 20 transforms, against manifold3d applying them one by one; and a tree of
    # such cubes: the reference's volume against manifold3d's exact Boolean
    import manifold3d

    from isocsg.testing import reference

    rng = np.random.default_rng(20)
    cubes = []
    for _ in range(3):
        steps = []
        for _ in range(20):
            v = rng.uniform(0.1, 1.5, 3) * rng.choice([-1.0, 1.0], 3)
            kind = str(rng.choice(["translate", "rotate", "scale"]))
            steps.append((kind, tuple(float(x) for x in (np.abs(v) if kind == "scale" else v))))
        ours = manifold_cube(steps)
        theirs = manifold3d.Manifold.cube()
        for kind, v in steps:
            theirs = getattr(theirs, kind)(v)
        assert abs(float(ours.volume) - theirs.volume()) <= 1e-9 * theirs.volume()
        cubes.append(ours)
    tree = (cubes[0] | cubes[1]) - cubes[2]
    ref = reference(tree, tol=1e-9)
    exact = to_manifold(tree, 8)
    assert abs(ref.volume - exact.volume()) <= 1e-9 * exact.volume() + 2 * ref.volume_error
    _agree_with_manifold3d(tree)
