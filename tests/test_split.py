"""Cutting meshes along level lines: bands, areas and watertightness."""

from __future__ import annotations

import numpy as np
import pytest

from isocsg import InvalidParameterError
from isocsg.laminae import split


def grid_mesh(n: int, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """A jittered n x n grid of a bumpy surface, two triangles per cell."""
    u, v = np.meshgrid(np.linspace(0, 1, n + 1), np.linspace(0, 1, n + 1))
    u = u + rng.uniform(-0.2, 0.2, u.shape) / n * (0 < u) * (u < 1)
    v = v + rng.uniform(-0.2, 0.2, v.shape) / n * (0 < v) * (v < 1)
    w = 0.2 * np.sin(3 * u) * np.cos(2 * v)
    verts = np.stack([u.ravel(), v.ravel(), w.ravel()], axis=1)
    k = np.arange(n * (n + 1)).reshape(n, n + 1)[:, :n].ravel()
    tris = np.concatenate([np.stack([k, k + 1, k + n + 2], 1), np.stack([k, k + n + 2, k + n + 1], 1)])
    return verts, tris


def areas(v: np.ndarray, t: np.ndarray) -> np.ndarray:
    p = v[t]
    return 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)


def boundary_edges(t: np.ndarray) -> set[tuple[int, int]]:
    e = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
    uniq, counts = np.unique(e, axis=0, return_counts=True)
    assert counts.max() <= 2
    return {tuple(x) for x in uniq[counts == 1]}


@pytest.mark.parametrize("seed", range(4))
def test_cut_mesh_keeps_area_bands_and_watertightness(seed: int) -> None:
    rng = np.random.default_rng(seed)
    v, t = grid_mesh(12, rng)
    field = np.sin(4 * v[:, 0] + 3 * v[:, 1]) + 0.3 * rng.standard_normal(len(v))
    other = rng.standard_normal(len(v))
    levels = np.sort(rng.uniform(-1.2, 1.2, 9))
    levels = np.concatenate([levels, [field[3]]])  # a level through a vertex
    levels.sort()
    out = split.split_by_levels(v, t, np.stack([field, other], 1), 0, levels)

    # Area is preserved, and each piece lies inside its parent triangle's area budget.
    np.testing.assert_allclose(areas(out.vertices, out.triangles).sum(), areas(v, t).sum(), rtol=1e-12)
    per_parent = np.bincount(out.parent, weights=areas(out.vertices, out.triangles), minlength=len(t))
    np.testing.assert_allclose(per_parent, areas(v, t), rtol=1e-9, atol=1e-15)

    # Every piece lies within one band: its vertex values between the band's levels.
    f = out.values[out.triangles, 0]
    lo = np.concatenate([[-np.inf], levels])[out.band]
    hi = np.concatenate([levels, [np.inf]])[out.band]
    assert np.all(f >= lo[:, None] - 1e-12) and np.all(f <= hi[:, None] + 1e-12)

    # Cut points carry exactly their level; the other column is interpolated with the
    # same parameter, so it lies between the edge's end values (checked via its range).
    new = np.arange(len(v), len(out.vertices))
    assert len(new) > 0
    assert np.all(np.isin(out.values[new, 0], levels))
    assert other.min() - 1e-12 <= out.values[new, 1].min() and out.values[new, 1].max() <= other.max() + 1e-12

    # No T-junctions: the only unshared edges are pieces of the grid's outer boundary.
    border = boundary_edges(out.triangles)
    pts = out.vertices
    for a, b in border:
        mid = 0.5 * (pts[a] + pts[b])
        on_border = min(mid[0], mid[1], 1 - mid[0], 1 - mid[1]) < 1e-9
        assert on_border, f"edge {a}-{b} at {mid} is used once inside the mesh"

    # Winding is kept: every piece has the orientation of its parent.
    def normal(vv, tt):
        p = vv[tt]
        return np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])

    big = areas(out.vertices, out.triangles) > 1e-14
    dots = np.sum(normal(out.vertices, out.triangles)[big] * normal(v, t)[out.parent[big]], axis=1)
    assert np.all(dots > 0)


def test_no_level_inside_leaves_the_mesh_alone() -> None:
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0.0]])
    out = split.split_by_levels(v, np.array([[0, 1, 2]]), np.array([[0.1], [0.2], [0.3]]), 0, np.array([-1.0, 5.0]))
    assert out.triangles.tolist() == [[0, 1, 2]] and out.band.tolist() == [1]


def test_refuses_too_many_pieces(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(split, "MAX_PIECES", 100)
    v, t = grid_mesh(6, np.random.default_rng(0))
    with pytest.raises(InvalidParameterError, match="contours"):
        split.split_by_levels(v, t, v[:, :1], 0, np.linspace(0.01, 0.99, 50))
