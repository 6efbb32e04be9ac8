"""isocsg.testing's signed distances against closed forms and dense sampling of the true surface."""

from __future__ import annotations

import math

import numpy as np

from isocsg import Box, Cylinder, Sphere
from isocsg.testing import signed_distance
from isocsg.testing.compare import _true_surface_points


def test_leaves_are_exact():
    rng = np.random.default_rng(1)
    p = rng.uniform(-3, 3, (500, 3))
    d = signed_distance(Sphere((0.5, 0, 0), 1.2), p)
    assert np.allclose(d.value, np.linalg.norm(p - (0.5, 0, 0), axis=1) - 1.2, atol=1e-14)
    assert d.exact.mean() > 0.99  # all but the centre's neighbourhood: the projection is on the surface
    q = np.abs(p) - 1.0  # the cube [-1, 1]^3
    box = np.linalg.norm(np.maximum(q, 0), axis=1) + np.minimum(q.max(axis=1), 0)
    assert np.allclose(signed_distance(Box((0, 0, 0), (2, 2, 2)), p).value, box, atol=1e-14)


def test_union_of_disjoint_spheres_is_exact_everywhere():
    s = Sphere((0, 0, 0), 1) | Sphere((3, 0, 0), 1)
    p = np.array([[0.0, 0, 0.5], [1.5, 0, 0], [3, 2, 0], [-2, 0, 0]])
    exact = np.minimum(np.linalg.norm(p, axis=1) - 1, np.linalg.norm(p - (3, 0, 0), axis=1) - 1)
    d = signed_distance(s, p)
    assert np.allclose(d.value, exact, atol=1e-14) and d.exact.all()


def test_bounds_hold_against_dense_sampling():
    # (box minus a cylinder) | a sphere: dense true-surface points give an upper bound of every
    # distance; the certified lower bound never exceeds it, the upper bound never falls below the
    # nearest sample by more than the sampling spacing, and exact values match it
    s = (Box((0, 0, 0), (2, 2, 1)) - Cylinder((0, 0, 0), (0, 0, 2), 0.5)) | Sphere((1, 1, 0.5), 0.6)
    rng = np.random.default_rng(3)
    surface = _true_surface_points(s, 100_000, rng)
    assert len(surface) > 75_000
    spacing = 3 * math.sqrt(20.0 / len(surface))
    p = rng.uniform(-1.6, 1.6, (300, 3))
    near = np.array([np.min(np.linalg.norm(surface - q, axis=1)) for q in p])
    d = signed_distance(s, p)
    assert np.all(d.lower <= near + 1e-12)
    assert np.all(d.upper >= near - spacing)
    assert np.all(np.abs(d.lower[d.exact] - near[d.exact]) <= spacing)
    assert d.exact.mean() > 0.5
    inside = s.contains(p)
    assert np.array_equal(d.value < 0, inside & (d.value != 0))
