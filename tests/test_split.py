"""Cutting meshes along level lines: bands, area, watertightness, interpolation.

The expected properties are checked with plain numpy on random closed meshes
(convex hulls of random points) and random open grids, not with the cutter's
own edge tables.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import ConvexHull

from isocsg.errors import InvalidParameterError
from isocsg.laminae import split
from isocsg.laminae.split import split_by_levels


def closed_mesh(rng: np.random.Generator, n: int = 60) -> tuple[np.ndarray, np.ndarray]:
    """Convex hull of points on an ellipsoid: a closed, consistently oriented triangle mesh."""
    p = rng.normal(size=(n, 3))
    p = p / np.linalg.norm(p, axis=1, keepdims=True) * (1.0, 0.7, 1.3)
    hull = ConvexHull(p)
    tri = hull.simplices.copy()
    # Outward winding (ConvexHull does not orient its simplices).
    g = np.cross(p[tri[:, 1]] - p[tri[:, 0]], p[tri[:, 2]] - p[tri[:, 0]])
    flip = np.einsum("ij,ij->i", g, p[tri].mean(axis=1)) < 0
    tri[flip] = tri[flip][:, ::-1]
    return p, tri


def open_grid(rng: np.random.Generator, k: int = 9) -> tuple[np.ndarray, np.ndarray]:
    """A k x k grid over the unit square, jittered inside, lifted to a random height field."""
    x, y = np.meshgrid(np.linspace(0, 1, k), np.linspace(0, 1, k), indexing="ij")
    inner = (x > 0) & (x < 1) & (y > 0) & (y < 1)
    x = x + np.where(inner, rng.uniform(-0.3, 0.3, x.shape) / k, 0)
    y = y + np.where(inner, rng.uniform(-0.3, 0.3, y.shape) / k, 0)
    z = 0.2 * rng.normal(size=x.shape)
    v = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)
    idx = np.arange(k * k).reshape(k, k)
    a, b, c, d = idx[:-1, :-1].ravel(), idx[1:, :-1].ravel(), idx[1:, 1:].ravel(), idx[:-1, 1:].ravel()
    tri = np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)])
    return v, tri


def tri_areas(v: np.ndarray, t: np.ndarray) -> np.ndarray:
    return 0.5 * np.linalg.norm(np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]]), axis=1)


def edge_counts(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    e = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
    return np.unique(e, axis=0, return_counts=True)


def fields(kind: str, v: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Column 0: the field that is cut; column 1: a linear function carried along."""
    lin = v @ np.array([0.3, -1.1, 0.7]) + 0.25
    if kind == "random":
        f = rng.uniform(-1, 1, len(v))
    elif kind == "smooth":
        f = np.sin(2.0 * v[:, 0]) + v[:, 1] * v[:, 2]
    else:  # "on_levels": many vertices exactly on a level, the rest near one
        f = np.round(rng.uniform(-1, 1, len(v)) * 4) / 4
        f[::3] += rng.choice([-1e-13, 0.0, 1e-13], size=len(f[::3]))
    return np.stack([f, lin], axis=1)


def levels_for(kind: str, rng: np.random.Generator) -> np.ndarray:
    if kind == "on_levels":
        return np.arange(-4, 5) / 4.0
    return np.sort(rng.uniform(-1.2, 1.2, 13))


CASES = [(mesh, kind, seed) for mesh in ("closed", "open") for kind in ("random", "smooth", "on_levels") for seed in (0, 1)]


@pytest.mark.parametrize("mesh, kind, seed", CASES, ids=[f"{m}-{k}-{s}" for m, k, s in CASES])
def test_split_invariants(mesh, kind, seed):
    rng = np.random.default_rng(100 + seed)
    v, t = closed_mesh(rng) if mesh == "closed" else open_grid(rng)
    vals = fields(kind, v, rng)
    lv = levels_for(kind, rng)
    out = split_by_levels(v, t, vals, 0, lv)
    ov, ot, f = out.vertices, out.triangles, out.values[:, 0]
    assert len(ot) > len(t)  # the levels do cut

    # Input vertices come first, unchanged.
    np.testing.assert_array_equal(ov[: len(v)], v)

    # Each output triangle's field values lie in its band: levels[b-1] <= f <= levels[b].
    lo = np.concatenate([[-np.inf], lv])[out.band]
    hi = np.concatenate([lv, [np.inf]])[out.band]
    ft = f[ot]
    tol = 1e-11 * max(1.0, np.abs(lv).max())  # values within rounding of a level are snapped onto it
    assert np.all(ft >= lo[:, None] - tol) and np.all(ft <= hi[:, None] + tol)
    # ... and not all three on one level (no empty band triangles).
    assert np.all(np.ptp(ft, axis=1) > 0) or kind == "on_levels"

    # Cut points lie on the input edges where the linear field reaches the level, and
    # the carried linear column equals the linear function at every output vertex.
    lin = ov @ np.array([0.3, -1.1, 0.7]) + 0.25
    np.testing.assert_allclose(out.values[:, 1], lin, atol=1e-12)

    # Area preserved, per parent triangle and in total; winding of the parent kept.
    a_in, a_out = tri_areas(v, t), tri_areas(ov, ot)
    np.testing.assert_allclose(np.bincount(out.parent, a_out, minlength=len(t)), a_in, rtol=1e-10, atol=1e-14)
    assert a_out.sum() == pytest.approx(a_in.sum(), rel=1e-12)
    gp = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])[out.parent]
    g = np.cross(ov[ot[:, 1]] - ov[ot[:, 0]], ov[ot[:, 2]] - ov[ot[:, 0]])
    big = a_out > 1e-12 * a_out.max()
    assert np.all(np.einsum("ij,ij->i", g, gp)[big] > 0)
    # Every output triangle lies in its parent's plane.
    nrm = gp / np.linalg.norm(gp, axis=1, keepdims=True)
    for j in range(3):
        d = np.einsum("ij,ij->i", ov[ot[:, j]] - v[t[out.parent, 0]], nrm)
        np.testing.assert_allclose(d, 0, atol=1e-12)

    # No T-junctions: every output edge inside the input surface is shared by exactly two triangles.
    edges, counts = edge_counts(ot)
    assert counts.max() <= 2
    once = edges[counts == 1]
    if mesh == "closed":
        assert len(once) == 0
    else:
        # Edges used once lie on the boundary of the unit square (both ends on the same side).
        p, q = ov[once[:, 0]], ov[once[:, 1]]
        on_side = np.zeros(len(once), bool)
        for axis in (0, 1):
            for side in (0.0, 1.0):
                on_side |= (np.abs(p[:, axis] - side) < 1e-12) & (np.abs(q[:, axis] - side) < 1e-12)
        assert np.all(on_side)
        # and together they measure the square's perimeter in plan (boundary vertices are not jittered).
        assert np.linalg.norm((q - p)[:, :2], axis=1).sum() == pytest.approx(4.0, rel=1e-12)


def test_band_index_counts_the_levels_below():
    v = np.array([[0.0, 0, 0], [3, 0, 0], [0, 3, 0]])
    out = split_by_levels(v, np.array([[0, 1, 2]]), v[:, :1], 0, np.array([0.5, 1.0, 2.5]))
    # Bands by the x of each triangle's centroid, counted independently.
    cx = out.vertices[out.triangles].mean(axis=1)[:, 0]
    np.testing.assert_array_equal(out.band, np.searchsorted([0.5, 1.0, 2.5], cx))
    assert sorted(set(out.band.tolist())) == [0, 1, 2, 3]
    # Areas of the strips: the triangle below x is the part x' <= x, area (9 - (3 - x)^2) / 2.
    area = tri_areas(out.vertices, out.triangles)
    below = [0.5 * (9 - (3 - x) ** 2) for x in (0.0, 0.5, 1.0, 2.5, 3.0)]
    np.testing.assert_allclose(np.bincount(out.band, area), np.diff(below), rtol=1e-12)


def test_no_levels_and_levels_outside_leave_the_mesh_whole():
    rng = np.random.default_rng(7)
    v, t = closed_mesh(rng, 20)
    f = rng.uniform(0, 1, (len(v), 1))
    for lv, band in ((np.zeros(0), 0), (np.array([-3.0, -2.0]), 2), (np.array([5.0]), 0)):
        out = split_by_levels(v, t, f, 0, lv)
        np.testing.assert_array_equal(out.triangles, t)
        np.testing.assert_array_equal(out.band, band)
        assert len(out.vertices) == len(v)


def test_shared_cut_points_are_one_vertex():
    # Two triangles sharing the edge 1-2, listed in opposite directions: one cut point per level.
    v = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]])
    t = np.array([[0, 1, 2], [2, 1, 3]])
    f = (v[:, 0] + 2 * v[:, 1])[:, None]
    out = split_by_levels(v, t, f, 0, np.array([0.5, 1.5, 2.5]))
    _, counts = edge_counts(out.triangles)
    assert counts.max() == 2
    np.testing.assert_allclose(np.unique(np.round(out.vertices, 12), axis=0).shape[0], len(out.vertices))


def test_too_many_pieces_is_refused(monkeypatch):
    # Lower the limit rather than build a mesh of 12 million pieces.
    monkeypatch.setattr(split, "MAX_PIECES", 100)
    v, t = open_grid(np.random.default_rng(3), 6)
    with pytest.raises(InvalidParameterError, match="contours"):
        split.split_by_levels(v, t, v[:, :1], 0, np.linspace(0.01, 0.99, 50))
    # Under the limit the same call is fine.
    monkeypatch.setattr(split, "MAX_PIECES", 10**6)
    assert len(split.split_by_levels(v, t, v[:, :1], 0, np.linspace(0.01, 0.99, 50)).triangles) > 100


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_sorted_half_edges_match_a_stable_lexicographic_sort(seed):
    from isocsg.laminae.halfedges import sorted_half_edges

    rng = np.random.default_rng(seed)
    t = rng.integers(0, 40, (300, 3)).astype(np.int64)
    start, higher, owner = sorted_half_edges(t, 40)
    u, w = t.ravel(), t[:, [1, 2, 0]].ravel()
    lo, hi = np.minimum(u, w), np.maximum(u, w)
    order = np.lexsort((hi, lo))  # stable: equal edges keep the half-edge order
    np.testing.assert_array_equal(owner, order)
    np.testing.assert_array_equal(higher, hi[order])
    np.testing.assert_array_equal(np.diff(start), np.bincount(lo, minlength=40))


def test_pair_quads_names_a_short_value_array():
    from isocsg.rendering.quads import pair_quads

    square = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    with pytest.raises(InvalidParameterError, match="value_in"):
        pair_quads(square, [(0, 1, 2), (0, 2, 3)], [0.5, 0.5], [0.5])
