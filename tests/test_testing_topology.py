"""Topology where the result's sheets touch tangentially: the mesh's own connectivity, and
"not comparable" instead of a false alarm when a triangle soup merges the touching sheets."""

from __future__ import annotations

import math

import numpy as np
import pytest

from isocsg import Sphere, Torus
from isocsg.csg.mesh import to_manifold, to_trimesh
from isocsg.testing import compare_mesh, reference
from isocsg.testing.compare import topology

R, r = 1.0, 0.25
# two coaxial tori stacked so that they touch along the circle of radius R at z = r
STACKED = Torus((0, 0, 0), (0, 0, 1), R, r) | Torus((0, 0, 2 * r), (0, 0, 1), R, r)


@pytest.fixture(scope="module")
def stacked_ref():
    return reference(STACKED, tol=1e-6)


def test_closed_forms_of_touching_tori(stacked_ref):
    # touching along a curve: the union's volume and area are twice one torus's
    assert abs(stacked_ref.volume - 2 * 2 * math.pi**2 * R * r**2) <= 1e-6 * stacked_ref.volume
    assert abs(stacked_ref.area - 2 * 4 * math.pi**2 * R * r) <= 1e-6 * stacked_ref.area


def test_own_connectivity_keeps_touching_sheets_apart():
    m = to_manifold(STACKED, 32)
    own = topology(m)
    assert own.touching and own.watertight and own.winding_consistent and own.nonmanifold_edges == 0
    soup = topology(to_trimesh(STACKED, 32))  # vertices merged by position
    assert not soup.touching and soup.nonmanifold_edges > 0 and not soup.watertight
    assert soup.oriented  # closed and consistently wound at every edge, sheets meeting at some


def test_topology_of_tori_by_closed_form():
    one = topology(to_manifold(Torus((0, 0, 0), (0, 0, 1), R, r), 24))
    assert (one.components, one.genus, one.euler, one.touching) == (1, 1.0, 0, False)
    two = topology(to_manifold(Torus((0, 0, 0), (0, 0, 1), R, r) | Torus((5, 0, 0), (1, 0, 0), R, r), 24))
    assert (two.components, two.genus) == (2, 2.0)
    ball = topology(to_trimesh(Sphere((0, 0, 0), 1), 16))
    assert (ball.components, ball.genus, ball.euler, ball.oriented) == (1, 0.0, 2, True)


def test_touching_sheets_not_a_false_alarm(stacked_ref):
    own = compare_mesh(to_manifold(STACKED, 32), STACKED, segments=32, samples=200, ref=stacked_ref)
    assert own.ok and dict(own.verdicts)["topology"] in ("exact", "tessellation"), own.summary()
    soup = compare_mesh(to_trimesh(STACKED, 32), STACKED, segments=32, samples=200, ref=stacked_ref)
    assert soup.ok and dict(soup.verdicts)["topology"] == "not comparable", soup.summary()
    assert "not comparable" in soup.summary()


def test_defects_still_wrong_where_sheets_touch(stacked_ref):
    import trimesh

    m = to_trimesh(STACKED, 32)
    holed = trimesh.Trimesh(m.vertices.copy(), m.faces[1:].copy(), process=False)
    c = compare_mesh(holed, STACKED, segments=32, samples=200, ref=stacked_ref)
    assert "topology" in c.wrong and not c.topology.oriented
    f = np.array(m.faces)
    f[5] = f[5][::-1]
    c = compare_mesh(trimesh.Trimesh(m.vertices.copy(), f, process=False), STACKED, segments=32, samples=200,
                     ref=stacked_ref)
    assert "topology" in c.wrong


def test_manifold_fuzz_cubes_are_manifolds_cubes():
    # the same transforms applied by manifold3d itself: same volume and same vertices
    import manifold3d

    from isocsg.testing.strategies import manifold_cube

    rng = np.random.default_rng(7)
    for _ in range(12):
        steps = []
        for _ in range(int(rng.integers(0, 5))):
            v = rng.uniform(0.1, 3.0, 3) * rng.choice([-1.0, 1.0], 3)
            steps.append((str(rng.choice(["translate", "rotate", "scale"])), tuple(float(x) for x in v)))
        ours = manifold_cube(steps)
        theirs = manifold3d.Manifold.cube()
        for kind, v in steps:
            theirs = getattr(theirs, kind)(v)
        assert abs(float(ours.volume) - theirs.volume()) <= 1e-9 * max(1.0, theirs.volume())
        pts = np.asarray(theirs.to_mesh().vert_properties)[:, :3]
        lo, hi = np.asarray(ours.bounds[0]), np.asarray(ours.bounds[1])
        assert np.allclose(pts.min(0), lo, atol=1e-6) and np.allclose(pts.max(0), hi, atol=1e-6)


def test_manifold_fuzz_draws_trees():
    from hypothesis import given, settings

    from isocsg.csg.section import solid_program
    from isocsg.testing.strategies import manifold_fuzz

    @settings(max_examples=5, deadline=None)
    @given(manifold_fuzz(max_ops=4, max_transforms=3))
    def check(tree):
        assert 1 <= solid_program(tree).n_leaves <= 4

    check()


def test_empty_mesh_of_a_turned_cube_minus_itself():
    # A - A: the reference's volume is rounding (about 1e-17); an engine's empty mesh is right
    from isocsg.testing.strategies import manifold_cube

    a = manifold_cube([("rotate", (10.0, 20.0, 30.0)), ("translate", (0.1, 0.2, 0.3))])
    empty = to_manifold(a - a, 8)
    c = compare_mesh(empty, a - a, samples=100)
    assert c.ok and c.hausdorff_mesh_to_true == 0.0, c.summary()
