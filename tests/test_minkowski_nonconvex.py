"""``isocsg.minkowski`` of a non-convex operand: a difference, intersection or union of flat-faced
solids, or a non-convex triangle mesh, sums through its convex pieces
(:mod:`isocsg.csg.flat_pieces`), exactly.

References, independent of the library: a box minus a box is cut here into at most six boxes by
their own coordinates, and each box plus the other operand is manifold3d's hull of the pairwise
vertex sums (the definition of a sum of convex sets), united by manifold3d; round operands as
``SEGMENTS``-gon meshes inscribed (a lower bound) and scaled by ``1 / cos(pi / SEGMENTS)^2``
(containing the exact solid: an upper bound). For a ball also the definition point by point: ``p``
is in ``A + rB`` iff its distance to ``A`` (trimesh's closest point on A's mesh) is at most ``r``.
(manifold3d's own ``minkowski_sum`` was not used: for two random convex polyhedra it returned
17.0155 where the hull of the pairwise vertex sums, scipy's and manifold3d's alike, is 16.9912.)
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference.meshes import manifold_of  # noqa: E402

from isocsg import Box, ConvexPolyhedron, Cylinder, NotExactError, Sphere, loads_openscad, minkowski, volume  # noqa: E402
from isocsg.kinds.mesh import TriangleMesh  # noqa: E402

SEGMENTS = 64


def _frame(w: float, d: float, hole: float, off: tuple[float, float]) -> object:
    """A box with a box cut from it: a notch from its top, through a side or not."""
    return Box((0, 0, 0), (w, w, d)) - Box((off[0], off[1], 0.3 * d), (hole, hole, d))


def _box_pieces(w: float, d: float, hole: float, off: tuple[float, float]) -> list[tuple[np.ndarray, np.ndarray]]:
    """``_frame``'s solid as disjoint boxes ``(lo, hi)``: the outer box cut along x, then y, then z
    by the hole's faces, the hole's own cell left out."""
    lo, hi = np.array([-w / 2, -w / 2, -d / 2]), np.array([w / 2, w / 2, d / 2])
    hc = np.array([off[0], off[1], 0.3 * d])
    h_lo, h_hi = np.maximum(hc - np.array([hole, hole, d]) / 2, lo), np.minimum(hc + np.array([hole, hole, d]) / 2, hi)
    if np.any(h_lo >= h_hi):
        return [(lo, hi)]
    pieces = []
    cur_lo, cur_hi = lo.copy(), hi.copy()
    for k in range(3):
        if cur_lo[k] < h_lo[k]:
            a, b = cur_lo.copy(), cur_hi.copy()
            b[k] = h_lo[k]
            pieces.append((a, b))
        if h_hi[k] < cur_hi[k]:
            a, b = cur_lo.copy(), cur_hi.copy()
            a[k] = h_hi[k]
            pieces.append((a, b))
        cur_lo[k], cur_hi[k] = h_lo[k], h_hi[k]
    return pieces


def _corners(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    return np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])


def _reference_sum(params: tuple[float, float, float, tuple[float, float]], other: np.ndarray) -> float:
    """The volume of the union over the test's own boxes of the hull of their corners plus ``other``'s points."""
    import manifold3d as m3

    hulls = [m3.Manifold.hull_points(((_corners(lo, hi)[:, None] + other[None]).reshape(-1, 3)).tolist())
             for lo, hi in _box_pieces(*params)]
    return float(m3.Manifold.batch_boolean(hulls, m3.OpType.Add).volume())


frame_params = st.tuples(st.floats(2, 5), st.floats(0.5, 3), st.floats(0.5, 1.8),
                         st.tuples(st.floats(-1.5, 1.5), st.floats(-1.5, 1.5)))


@settings(max_examples=4, deadline=None)
@given(params=frame_params, size=st.tuples(st.floats(0.2, 2), st.floats(0.2, 2), st.floats(0.2, 2)),
       seed=st.integers(0, 99))
def test_difference_plus_a_polytope_is_the_union_of_hulls(params: tuple, size: tuple[float, float, float],
                                                          seed: int) -> None:
    rng = np.random.default_rng(seed)
    points = rng.normal(size=(8, 3)) * np.array(size)
    got = volume(minkowski(_frame(*params), ConvexPolyhedron(points)))
    assert got == pytest.approx(_reference_sum(params, points), rel=1e-6)


@settings(max_examples=3, deadline=None)
@given(params=frame_params, r=st.floats(0.1, 1.0), h=st.floats(0.1, 1.0))
def test_difference_plus_a_cylinder_is_between_its_bounds(params: tuple, r: float, h: float) -> None:
    # (a ball is judged point by point below: isocsg.volume of the 100-odd overlapping round
    # pieces of a ball's sum takes about a minute)
    b = Cylinder((0, 0, 0), (0, 0, h), r)
    got = volume(minkowski(_frame(*params), b))
    mesh = manifold_of(b, SEGMENTS).to_mesh()
    inscribed = np.asarray(mesh.vert_properties, dtype=np.float64)[:, :3]
    low = _reference_sum(params, inscribed)
    high = _reference_sum(params, inscribed / math.cos(math.pi / SEGMENTS) ** 2)
    assert low * (1 - 1e-6) <= got <= high * (1 + 1e-6)


def test_a_ball_sum_is_the_set_within_r_point_by_point() -> None:
    params = (4.0, 2.0, 1.5, (0.4, -0.3))
    r = 0.6
    solid = minkowski(_frame(*params), Sphere((0, 0, 0), r))
    points = np.random.default_rng(3).uniform(-3, 3, size=(3000, 3)) * np.array([1, 1, 0.8])
    # the distance to A: to the nearest of its boxes (each by the clamp to its faces)
    distance = np.min([np.linalg.norm(points - np.clip(points, lo, hi), axis=1) for lo, hi in _box_pieces(*params)],
                      axis=0)
    sure = np.abs(distance - r) > 1e-6
    assert np.array_equal(solid.contains(points)[sure], (distance <= r)[sure])


def test_a_non_convex_mesh_sums_through_its_pieces() -> None:
    """An L-shaped prism (a non-convex polyhedron) plus a cube: the L's footprint grown, exactly."""
    pts = [(0, 0, 0), (2, 0, 0), (2, 1, 0), (1, 1, 0), (1, 2, 0), (0, 2, 0)]
    pts += [(x, y, 1) for x, y, _ in pts]
    tris = []
    for k in range(1, 5):  # fan of the bottom (seen from below: clockwise from above) and of the top
        tris += [(0, k + 1, k), (6, 6 + k, 6 + k + 1)]
    for k in range(6):
        n = (k + 1) % 6
        tris += [(k, n, n + 6), (k, n + 6, k + 6)]
    ell = TriangleMesh(np.array(pts, dtype=float), np.array(tris))
    assert not ell.is_convex()
    solid = minkowski(ell, Box((0, 0, 0), (1, 1, 1)))
    want = manifold_of(Box((1, 0.5, 0.5), (2, 1, 1)) | Box((0.5, 1, 0.5), (1, 2, 1))).minkowski_sum(
        manifold_of(Box((0, 0, 0), (1, 1, 1)))).volume()
    assert volume(solid) == pytest.approx(want, rel=1e-9)


def test_openscad_minkowski_of_a_difference_loads() -> None:
    text = ("minkowski() { difference() { cube(size = [4, 4, 2], center = false); "
            "cube(size = [2, 2, 4], center = false); } cube(size = [0.5, 0.5, 0.5], center = false); }")
    # an L (the corner notch through the height) grown by the cube: its notch stays 2 x 2
    assert volume(loads_openscad(text)) == pytest.approx((4.5 * 4.5 - 2 * 2) * 2.5, rel=1e-9)


def test_round_leaves_in_a_difference_stay_refused() -> None:
    with pytest.raises(NotExactError, match="only unions and flat-faced solids split into convex pieces"):
        minkowski(Box((0, 0, 0), (2, 2, 2)) - Sphere((1, 1, 1), 1), Sphere((0, 0, 0), 1))
