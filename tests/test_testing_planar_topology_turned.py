"""The true topology of all-planar trees from their boundary polygons
(isocsg.testing.planar_topology) on configurations of known topology by construction, turned by
random rotations so that no vertex is on a grid: disjoint cubes (k components), a slab with k
tunnels (genus k), cubes sharing a face, an edge or a corner, holes and pockets that touch along
an edge (a face polygon whose holes touch at a vertex: its corners there are the sectors between
its edges); and demonstration trees that were refused before."""

from __future__ import annotations

import runpy
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from isocsg import Box
from isocsg.csg.mesh import to_manifold
from isocsg.testing.compare import topology
from isocsg.testing.planar_topology import refusal

CUBE = Box((0, 0, 0), (1, 1, 1))
SLAB = Box((0, 0, 0), (9, 3, 1))
WIDE = Box((0, 0, 0), (4, 4, 1))


def _disjoint(k):
    out = CUBE
    for i in range(1, k):
        out = out | Box((2.0 * i, 0.3 * i, 0), (1, 1, 1)).rotate((10.0 * i, 20.0 * i, 5.0 * i))
    return out


def _tunnels(k):
    out = SLAB
    for i in range(k):
        out = out - Box((-3.0 + 2.0 * i, 0.1 * i, 0), (1, 1, 2)).rotate((0, 0, 15.0 * i))
    return out


# (tree, components, genus, voids, touching): each known by construction; where sheets touch,
# they are kept apart across the solid (the solid shrunk by an infinitesimal amount)
KNOWN = {
    "1 cube": (_disjoint(1), 1, 0, 0, False),
    "3 disjoint cubes": (_disjoint(3), 3, 0, 0, False),
    "slab": (_tunnels(0), 1, 0, 0, False),
    "slab with 1 tunnel": (_tunnels(1), 1, 1, 0, False),
    "slab with 3 tunnels": (_tunnels(3), 1, 3, 0, False),
    "cubes sharing a face": (CUBE | Box((1, 0, 0), (1, 1, 1)), 1, 0, 0, False),
    "cubes sharing an edge": (CUBE | Box((1, 1, 0), (1, 1, 1)), 2, 0, 0, True),
    "cubes sharing a corner": (CUBE | Box((1, 1, 1), (1, 1, 1)), 2, 0, 0, True),
    "cube with a cavity": (Box((0, 0, 0), (3, 3, 3)) - Box((0.2, 0.1, 0), (1, 1, 1)), 2, 0, 1, False),
    # two square holes touching along an edge: one tunnel, the material wedges apart
    "holes along an edge": (WIDE - Box((-0.5, -0.5, 0), (1, 1, 2)) - Box((0.5, 0.5, 0), (1, 1, 2)), 1, 1, 0, True),
    # two pockets touching along an edge: one dent
    "pockets along an edge": (Box((0, 0, 0), (4, 4, 2)) - Box((-0.5, -0.5, 1), (1, 1, 2))
                              - Box((0.5, 0.5, 1), (1, 1, 2)), 1, 0, 0, True),
}


def _topology(tree):
    t = refusal(tree)
    assert not isinstance(t, str), t
    return t.components, t.genus, t.voids, t.touching


@pytest.mark.parametrize("name", sorted(KNOWN))
def test_known_topology(name):
    tree, *want = KNOWN[name]
    assert _topology(tree) == tuple(want)


angle = st.floats(0.0, 360.0, allow_nan=False)
shift = st.floats(-5.0, 5.0, allow_nan=False)


@settings(max_examples=8, deadline=None, suppress_health_check=list(HealthCheck))
@given(st.sampled_from(sorted(KNOWN)), st.tuples(angle, angle, angle), st.tuples(shift, shift, shift))
def test_known_topology_turned_and_moved(name, angles, offset):
    tree, *want = KNOWN[name]
    assert _topology(tree.rotate(angles).translate(offset)) == tuple(want)


@pytest.mark.parametrize(("case", "want"), [(939, (3, 1, 1)), (929, (12, 3, 0))])
def test_refused_demonstration_trees_agree_with_manifold3d(case, want):
    # manifold3d's exact Boolean is an independent answer here: its mesh is watertight, and its
    # components have the polygons' volumes and genera
    data = Path(__file__).parent / "data" / "planar_topology" / f"fuzz_{case}.py"
    tree = runpy.run_path(str(data))["tree"]
    t = refusal(tree)
    assert not isinstance(t, str), t
    assert all(c % 2 == 0 for c in t.component_euler)
    m = topology(to_manifold(tree, 8))
    assert m.watertight
    assert (t.components, t.genus, t.voids) == (m.components, int(np.rint(m.genus)), m.voids) == want
