"""Coincident opposite faces of the clipped CSG surface at scale.

References: a brute-force pairing over all triangle pairs (the documented
predicates, evaluated pair by pair), areas by hand, and manifold3d's own
Booleans of its own cubes (volume and area) for grids of touching boxes.
"""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from isocsg import Box, PointLight, union_all
from isocsg.csg.surface import csg_surface
from isocsg.csg.surface.coincident import (
    _SIDE_DIRECTION,
    COINCIDENT_DISTANCE,
    _cancel_partial_overlaps,
    _opposite_pairs,
)

LIGHTS = (PointLight((1.2, -1.6, 5.0)),)


def _keys(p):
    nrm = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    length = np.linalg.norm(nrm, axis=1)
    ok = length > 0
    nrm = nrm / np.where(ok, length, 1.0)[:, None]
    return nrm, ok, np.column_stack([nrm, np.einsum("ij,ij->i", nrm, p[:, 0])])


def _brute_force_pairs(p, tol):
    """Every ordered pair, tested all at once (m^2 of them)."""
    nrm, ok, key = _keys(p)
    lo, hi = p.min(axis=1) - tol, p.max(axis=1) + tol
    near = np.linalg.norm(key[:, None, :] + key[None, :, :], axis=2) <= 1e-3
    meet = np.all(lo[:, None] <= hi[None, :], axis=2) & np.all(lo[None, :] <= hi[:, None], axis=2)
    # every vertex of j within tol of i's plane
    dist = np.abs(np.einsum("ix,jvx->ijv", nrm, p) - key[:, 3][:, None, None])
    flat = np.all(dist <= tol, axis=2)
    good = near & meet & flat & ok[:, None] & ok[None, :]
    np.fill_diagonal(good, False)
    return [tuple(x) for x in np.argwhere(good).tolist()]


def test_opposite_pairs_are_those_of_the_brute_force_pairing():
    """Triangles in planes of both orientations, some with normals almost perpendicular
    to the direction that splits the two kinds (paired across its margin), some tilted
    out of their plane by up to a few 1e-4: the grid pairing finds exactly the pairs
    of the all-pairs test."""
    rng = np.random.default_rng(7)
    d = _SIDE_DIRECTION
    edge_on = np.cross(d, [0.0, 0.0, 1.0])
    planes = [np.array([0.0, 0.0, 1.0]), edge_on / np.linalg.norm(edge_on), np.array([1.0, -1.0, 0.5]) / 1.5]
    tris = []
    for n in planes:
        u = np.cross(n, [0.3, 0.5, 0.7])
        u /= np.linalg.norm(u)
        w = np.cross(n, u)
        for _ in range(120):
            c = rng.uniform(0, 1, 2)
            xy = c + rng.uniform(-0.15, 0.15, (3, 2))
            tilt = rng.choice([0.0, 0.0, 1e-5, 3e-4], 3)  # off the plane along n, per vertex
            tri = 0.2 * n + xy[:, :1] * u + xy[:, 1:] * w + (tilt * rng.uniform(-1, 1, 3))[:, None] * n
            tris.append(tri[::-1] if rng.random() < 0.5 else tri)
    tris.append(np.zeros((3, 3)))  # a degenerate triangle pairs with nothing
    p = np.array(tris)
    tol = 1e-4
    nrm, ok, key = _keys(p)
    assert (np.abs(nrm[ok] @ d) < 4e-3).sum() > 50  # many within the margin of the split
    i, j = _opposite_pairs(p, nrm, ok, key, p.min(axis=1) - tol, p.max(axis=1) + tol, tol)
    expected = _brute_force_pairs(p, tol)
    assert len(expected) > 300
    assert list(zip(i.tolist(), j.tolist())) == sorted(expected)


@pytest.mark.parametrize("k", [3, 12])
def test_partial_overlaps_in_a_grid_cancel_by_hand(k):
    """A k x k grid of unit squares facing +z, two triangles each, and inside each square
    a small triangle facing -z across the diagonal: every overlap cancels, the rest of
    each large triangle stays (total k^2 (1 - 0.02)), the small ones go."""
    verts, tris = [], []
    for a in range(k):
        for b in range(k):
            base = len(verts)
            verts += [[a, b, 0], [a + 1, b, 0], [a + 1, b + 1, 0], [a, b + 1, 0]]
            verts += [[a + 0.2, b + 0.1, 0], [a + 0.4, b + 0.1, 0], [a + 0.2, b + 0.3, 0]]
            tris += [[base, base + 1, base + 2], [base, base + 2, base + 3], [base + 4, base + 6, base + 5]]
    v, t = np.array(verts, float), np.array(tris, np.int64)
    drop = np.zeros(len(t), bool)
    drop[2::3] = True  # the centroid rule already dropped the small ones
    v2, t2, origin, out = _cancel_partial_overlaps(v, t, np.arange(len(t)), drop, COINCIDENT_DISTANCE)
    kept = t2[~out]
    n = np.cross(v2[kept[:, 1]] - v2[kept[:, 0]], v2[kept[:, 2]] - v2[kept[:, 0]])
    assert (n[:, 2] > 0).all() and (origin[~out] % 3 != 2).all()
    assert 0.5 * n[:, 2].sum() == pytest.approx(k * k * (1 - 0.02), rel=1e-12)
    # each large triangle lost what lies in it: the diagonal y = x cuts the small
    # triangle at (0.2, 0.2) and (0.25, 0.25), leaving 0.0025 of it above
    area = np.bincount(origin[~out], 0.5 * n[:, 2], minlength=len(t))
    assert np.allclose(area[0::3], 0.5 - 0.0175, rtol=0, atol=1e-13)
    assert np.allclose(area[1::3], 0.5 - 0.0025, rtol=0, atol=1e-13)


def _manifold_grid(k, cut=None):
    import manifold3d as m3

    cubes = [m3.Manifold.cube((1.0, 1.0, 1.0)).translate((float(i), float(j), 0.0)) for i in range(k) for j in range(k)]
    out = m3.Manifold.batch_boolean(cubes, m3.OpType.Add)
    if cut is not None:
        (x0, y0, z0), (x1, y1, z1) = cut
        box = m3.Manifold.cube((x1 - x0, y1 - y0, z1 - z0)).translate((x0, y0, z0))
        out = out - box
    return out.volume(), out.surface_area()


@pytest.mark.parametrize("cut", [False, True], ids=["union", "minus-a-slab"])
def test_a_grid_of_touching_boxes_has_manifolds_area_and_volume(cut):
    """The union of a 5 x 5 grid of face-sharing unit boxes (and that grid minus the part
    of itself in a slab with the same top and bottom planes): a closed surface with
    manifold3d's volume and area of the same Boolean of its own cubes."""
    k = 5
    grid = union_all([Box((i + 0.5, j + 0.5, 0.5), (1.0, 1.0, 1.0)) for i in range(k) for j in range(k)])
    tree, box = grid, None
    if cut:
        box = ((1.3, -1.0, 0.0), (2.7, k + 1.0, 1.0))
        slab = Box((2.0, k / 2, 0.5), (1.4, k + 2.0, 1.0))
        tree = grid - (grid & slab)
    surf = csg_surface(tree, LIGHTS, contours=16)
    mesh = trimesh.Trimesh(surf.vertices, surf.triangles, process=True)
    volume, area = _manifold_grid(k, box)
    assert mesh.is_watertight
    assert mesh.volume == pytest.approx(volume, rel=1e-9)
    assert mesh.area == pytest.approx(area, rel=1e-9)
