"""The closed form of the polygon-to-polygon factor for edges at an angle (dilogarithms).

References, each independent of the code under test:

- symmetry: the base of a right pyramid over a regular n-gon sees only its n
  sides, all alike, so ``F(base -> side) = 1 / n`` exactly, whatever the
  height (every base edge meets every side's slanted edges at an angle that
  changes with the height); the faces of a regular tetrahedron see each
  other by a third;
- an adaptive double quadrature (scipy's ``dblquad``) of ``ln r`` over two
  segments, for the edge-pair integral itself;
- reciprocity ``A_p F(p -> q) = A_q F(q -> p)`` on hypothesis-drawn polygon
  pairs (the two directions sum the edge pairs in different orders and
  clip different polygons);
- the enclosure sum of random convex polyhedra's inner faces.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import integrate
from scipy.spatial import ConvexHull

from isocsg.shadows.form_factors import _GL_W, _GL_X, CLOSED_FORM_MIN_SIN, _edge_pair, polygon_form_factor


def _pyramid(n, h, r=1.0):
    ang = 2 * math.pi * np.arange(n) / n
    ring = np.stack([r * np.cos(ang), r * np.sin(ang), np.zeros(n)], axis=1)
    apex = np.array([0.0, 0.0, h])
    base_up = ring  # counter-clockwise about +z: its inner side faces up
    sides = [np.array([ring[(k + 1) % n], ring[k], apex]) for k in range(n)]  # inner side faces the axis
    return base_up, sides


@settings(max_examples=25, deadline=None)
@given(st.integers(3, 8), st.floats(0.02, 50.0))
def test_pyramid_base_sees_each_side_by_one_over_n(n, h):
    base, sides = _pyramid(n, h)
    f = [polygon_form_factor(base, s) for s in sides]
    assert f == pytest.approx(np.full(n, 1.0 / n), rel=1e-12)
    a_base = 0.5 * n * math.sin(2 * math.pi / n)
    a_side = 0.5 * np.linalg.norm(np.cross(sides[0][1] - sides[0][0], sides[0][2] - sides[0][0]))
    assert polygon_form_factor(sides[0], base) == pytest.approx(a_base / (n * a_side), rel=1e-12)


def test_regular_tetrahedron_faces_see_each_other_by_a_third():
    v = np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], dtype=float)
    faces = []
    for skip in range(4):
        tri = [v[k] for k in range(4) if k != skip]
        if np.dot(np.cross(tri[1] - tri[0], tri[2] - tri[0]), v[skip] - tri[0]) < 0:  # inner side
            tri = tri[::-1]
        faces.append(np.array(tri))
    for i in range(4):
        for j in range(4):
            if i != j:
                assert polygon_form_factor(faces[i], faces[j]) == pytest.approx(1 / 3, rel=1e-12)


def _unit(v):
    return v / np.linalg.norm(v)


@settings(max_examples=15, deadline=None)
@given(st.integers(0, 10**6), st.floats(CLOSED_FORM_MIN_SIN, 1.0), st.floats(-3.0, 1.0))
def test_edge_pair_integral_against_adaptive_quadrature(seed, sin, log_gap):
    """int_a int_b ln r (the closed form's job) against scipy's dblquad, any angle above the switch, any gap."""
    rng = np.random.default_rng(seed)
    ea = _unit(rng.normal(size=3))
    perp = _unit(np.cross(ea, rng.normal(size=3)))
    eb = ea * math.sqrt(1 - sin * sin) + perp * sin
    la, lb = rng.uniform(0.05, 2.0, 2)
    a0 = rng.normal(size=3)
    b0 = a0 + _unit(rng.normal(size=3)) * 10**log_gap + ea * rng.uniform(-1, 1) * la
    a1, b1 = a0 + la * ea, b0 + lb * eb
    got = _edge_pair(a0, a1, b0, b1, _GL_X, _GL_W) / float(ea @ eb)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ref, _ = integrate.dblquad(lambda t, s: math.log(np.linalg.norm(a0 + s * ea - b0 - t * eb)), 0, la, 0, lb,
                                   epsabs=1e-15, epsrel=1e-13)
    scale = la * lb * max(1.0, abs(math.log(np.linalg.norm(b0 - a0))))
    assert abs(got - ref) <= 1e-11 * scale


def _random_polygon(rng, m):
    ang = np.sort(rng.uniform(0, 2 * math.pi, m))
    r = rng.uniform(0.2, 1.5)
    pts2 = np.stack([r * np.cos(ang) * rng.uniform(0.5, 1.5), r * np.sin(ang)], axis=1)
    hull = ConvexHull(pts2)
    pts2 = pts2[hull.vertices]
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    return np.column_stack([pts2, np.zeros(len(pts2))]) @ q.T + rng.normal(size=3) * rng.uniform(0, 2)


def _area(p):
    return 0.5 * np.linalg.norm(np.sum(np.cross(p, np.roll(p, -1, axis=0)), axis=0))


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 10**6), st.integers(3, 6), st.integers(3, 6))
def test_reciprocity_on_random_polygon_pairs(seed, m, k):
    rng = np.random.default_rng(seed)
    p, q = _random_polygon(rng, m), _random_polygon(rng, k)
    fpq, fqp = polygon_form_factor(p, q), polygon_form_factor(q, p)
    ap, aq = _area(p), _area(q)
    assert ap * fpq == pytest.approx(aq * fqp, rel=1e-12, abs=1e-14 * max(ap, aq))


@settings(max_examples=10, deadline=None)
@given(st.integers(0, 10**6))
def test_random_convex_enclosures_sum_to_one(seed):
    rng = np.random.default_rng(seed)
    pts = rng.normal(size=(rng.integers(5, 12), 3)) * rng.uniform(0.3, 3.0, 3)
    hull = ConvexHull(pts)
    c = pts[hull.vertices].mean(axis=0)
    faces = []
    for simplex in hull.simplices:  # triangles, wound so that the inner side is their front
        tri = pts[simplex]
        if np.dot(np.cross(tri[1] - tri[0], tri[2] - tri[0]), c - tri[0]) < 0:
            tri = tri[::-1]
        faces.append(tri)
    A = np.array([_area(f) for f in faces])
    F = np.array([[polygon_form_factor(fi, fj) if i != j else 0.0 for j, fj in enumerate(faces)]
                  for i, fi in enumerate(faces)])
    # coplanar triangles of one hull face see nothing of each other: the rows still sum to 1
    assert F.sum(axis=1) == pytest.approx(np.ones(len(faces)), abs=1e-11)
    assert A[:, None] * F == pytest.approx((A[:, None] * F).T, rel=1e-11, abs=1e-13 * A.max())
