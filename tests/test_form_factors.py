"""Polygon-to-polygon and point-to-polygon form factors against closed forms and identities.

References, all written here independently of the library:

- Howell's catalogue C-11 (directly opposed parallel rectangles) and C-14
  (perpendicular rectangles with a common edge);
- the general closed form for parallel rectangles of any offset (the
  corner superposition of Gross, Spindler and Hahne 1981);
- the summation rule of a closed convex enclosure (sum_j F_ij = 1 over the
  inner faces of a convex polyhedron), which exercises edges at every angle;
- reciprocity A_i F_ij = A_j F_ji;
- a brute-force double Gauss quadrature of cos cos / (pi r^2) for polygons
  far apart (smooth integrand).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.spatial import ConvexHull

from isocsg.errors import InvalidGeometryError
from isocsg.shadows.form_factors import point_form_factor, polygon_form_factor


def howell_c11(a: float, b: float, c: float) -> float:
    X, Y = a / c, b / c
    return 2 / (math.pi * X * Y) * (
        0.5 * math.log((1 + X * X) * (1 + Y * Y) / (1 + X * X + Y * Y))
        + X * math.sqrt(1 + Y * Y) * math.atan(X / math.sqrt(1 + Y * Y))
        + Y * math.sqrt(1 + X * X) * math.atan(Y / math.sqrt(1 + X * X))
        - X * math.atan(X) - Y * math.atan(Y))


def howell_c14(l: float, h: float, w: float) -> float:
    """From the plate of width w to the plate of height h, common edge of length l, at 90 degrees."""
    H, W = h / l, w / l
    HW = H * H + W * W
    a = (1 + W * W) * (1 + H * H) / (1 + HW)
    b = (W * W * (1 + HW) / ((1 + W * W) * HW)) ** (W * W)
    c = (H * H * (1 + HW) / ((1 + H * H) * HW)) ** (H * H)
    return (W * math.atan(1 / W) + H * math.atan(1 / H) - math.sqrt(HW) * math.atan(1 / math.sqrt(HW))
            + 0.25 * math.log(a * b * c)) / (math.pi * W)


def parallel_general(x, y, xi, eta, z):
    """F from [x0,x1]x[y0,y1] at height 0 to [xi0,xi1]x[eta0,eta1] at height z (corner superposition)."""
    def G(u, v):
        out = -0.5 * z * z * math.log(u * u + v * v + z * z)
        ru, rv = math.sqrt(u * u + z * z), math.sqrt(v * v + z * z)
        if v != 0:
            out += v * ru * math.atan(v / ru)
        if u != 0:
            out += u * rv * math.atan(u / rv)
        return out / (2 * math.pi)
    total = 0.0
    for i in range(2):
        for j in range(2):
            for k in range(2):
                for m in range(2):
                    total += (-1) ** (i + j + k + m) * G(xi[k] - x[i], eta[m] - y[j])
    return total / ((x[1] - x[0]) * (y[1] - y[0]))


def rect_z(x, y, z, up=True):
    q = [(x[0], y[0], z), (x[1], y[0], z), (x[1], y[1], z), (x[0], y[1], z)]
    return q if up else q[::-1]


@pytest.mark.parametrize("a,b,c", [(1, 1, 1), (2, 0.5, 1), (0.1, 3, 0.7), (5, 5, 0.2), (0.3, 0.2, 4)])
def test_parallel_rectangles_howell_c11(a, b, c):
    f = polygon_form_factor(rect_z((0, a), (0, b), 0), rect_z((0, a), (0, b), c, up=False))
    assert f == pytest.approx(howell_c11(a, b, c), rel=1e-9)


@pytest.mark.parametrize("l,h,w", [(1, 1, 1), (2, 0.5, 1), (0.3, 2, 0.7), (4, 0.1, 3)])
def test_perpendicular_rectangles_howell_c14(l, h, w):
    floor = rect_z((0, l), (0, w), 0)
    wall = [(0, 0, 0), (0, 0, h), (l, 0, h), (l, 0, 0)]  # y = 0, facing +y
    assert polygon_form_factor(floor, wall) == pytest.approx(howell_c14(l, h, w), rel=1e-9)
    assert polygon_form_factor(wall, floor) == pytest.approx(howell_c14(l, w, h), rel=1e-9)


def test_general_parallel_formula_matches_c11():
    assert parallel_general((0, 2), (0, 0.5), (0, 2), (0, 0.5), 1.0) == pytest.approx(howell_c11(2, 0.5, 1), rel=1e-12)


@settings(max_examples=40, deadline=None)
@given(
    st.lists(st.floats(-3, 3), min_size=4, max_size=4),
    st.lists(st.floats(0.05, 3), min_size=4, max_size=4),
    st.floats(0.05, 3),
)
def test_parallel_rectangles_any_offset(pos, sizes, z):
    x = (pos[0], pos[0] + sizes[0])
    y = (pos[1], pos[1] + sizes[1])
    xi = (pos[2], pos[2] + sizes[2])
    eta = (pos[3], pos[3] + sizes[3])
    ref = parallel_general(x, y, xi, eta, z)
    f = polygon_form_factor(rect_z(x, y, 0), rect_z(xi, eta, z, up=False))
    assert f == pytest.approx(ref, rel=1e-6, abs=1e-12)
    g = polygon_form_factor(rect_z(xi, eta, z, up=False), rect_z(x, y, 0))
    assert sizes[0] * sizes[1] * f == pytest.approx(sizes[2] * sizes[3] * g, rel=1e-9, abs=1e-14)


@settings(max_examples=20, deadline=None)
@given(
    st.lists(st.floats(0.05, 3), min_size=4, max_size=4),
    st.floats(-2, 2), st.floats(-2, 0.5),
)
def test_perpendicular_rectangles_reciprocity(sizes, ox, oy):
    """Perpendicular rectangles anywhere (touching, apart, overlapping the other's plane)."""
    a = rect_z((0, sizes[0]), (0, sizes[1]), 0)
    b = [(ox, oy, 0.0), (ox, oy, sizes[3]), (ox + sizes[2], oy, sizes[3]), (ox + sizes[2], oy, 0.0)]
    fab, fba = polygon_form_factor(a, b), polygon_form_factor(b, a)
    assert sizes[0] * sizes[1] * fab == pytest.approx(sizes[2] * sizes[3] * fba, rel=1e-9, abs=1e-14)
    if oy <= -0.5:  # apart: the double quadrature converges
        assert fab == pytest.approx(_brute(a, b, n=32), rel=1e-6)


def _gauss_polygon(q, n):
    """Gauss points and weights over a convex polygon (fan of collapsed squares)."""
    x, w = np.polynomial.legendre.leggauss(n)
    x, w = 0.5 * (x + 1), 0.5 * w
    u, v = np.meshgrid(x, x, indexing="ij")
    wu = np.outer(w, w).ravel()
    u, v = u.ravel(), v.ravel()
    pts, wts = [], []
    q = np.asarray(q, float)
    for t in range(1, len(q) - 1):
        a, b, c = q[0], q[t], q[t + 1]
        area2 = np.linalg.norm(np.cross(b - a, c - a))
        e = a + u[:, None] * (b - a)
        pts.append(e + v[:, None] * (c - e))
        wts.append(area2 * wu * (1 - v))
    return np.vstack(pts), np.concatenate(wts)


def _normal(q):
    q = np.asarray(q, float)
    n = np.sum(np.cross(q, np.roll(q, -1, axis=0)), axis=0)
    return n / np.linalg.norm(n), 0.5 * np.linalg.norm(n)


def _brute(p, q, n=16):
    """F(p -> q) = (1/A_p) int int cos+ cos+ / (pi r^2): double Gauss quadrature."""
    xp, wp = _gauss_polygon(p, n)
    xq, wq = _gauss_polygon(q, n)
    np_, ap = _normal(p)
    nq, _ = _normal(q)
    d = xq[None, :, :] - xp[:, None, :]
    r2 = np.einsum("ijk,ijk->ij", d, d)
    ci = np.maximum(d @ np_, 0) / np.sqrt(r2)
    cj = np.maximum(-(d @ nq), 0) / np.sqrt(r2)
    return float(wp @ (ci * cj / (np.pi * r2)) @ wq) / ap


@settings(max_examples=12, deadline=None)
@given(st.integers(0, 10**6))
def test_far_apart_polygons_against_double_quadrature(seed):
    """Random convex polygons at any angle, at least three sizes apart: a smooth integrand."""
    rng = np.random.default_rng(seed)

    def polygon(center):
        k = rng.integers(3, 7)
        ang = np.sort(rng.uniform(0, 2 * np.pi, k))
        if np.max(np.diff(np.r_[ang, ang[0] + 2 * np.pi])) > 2.5:
            ang = np.linspace(0, 2 * np.pi, k, endpoint=False) + rng.uniform(0, 1)
        r = rng.uniform(0.3, 1.0)
        flat = np.c_[r * np.cos(ang), r * np.sin(ang), np.zeros(k)]
        rot = np.linalg.qr(rng.normal(size=(3, 3)))[0]
        return flat @ rot.T + center

    p = polygon(np.zeros(3))
    q = polygon(rng.normal(size=3) / 0.4 * 1.2 + 0)  # about 3 units away
    if np.linalg.norm(q.mean(0) - p.mean(0)) < 3.0:
        q = q + (3.0 - np.linalg.norm(q.mean(0) - p.mean(0)) + 0.1) * (q.mean(0) - p.mean(0)) / max(
            np.linalg.norm(q.mean(0) - p.mean(0)), 1e-9)
    for a, b in ((p, q), (q, p)):  # each wholly on one side of the other's plane: a smooth integrand
        side = (b - a.mean(0)) @ _normal(a)[0]
        assume(np.all(side > 0.05) or np.all(side < -0.05))
    p = p if np.all((q - p.mean(0)) @ _normal(p)[0] > 0) else p[::-1]
    q = q if np.all((p - q.mean(0)) @ _normal(q)[0] > 0) else q[::-1]
    ref = _brute(p, q)
    f = polygon_form_factor(p, q)
    scale = (_normal(q)[1] / (np.pi * np.sum((q.mean(0) - p.mean(0)) ** 2)))  # F's order of magnitude
    assert abs(f - ref) <= 1e-7 * scale + 1e-6 * ref


def _inner_faces(points):
    hull = ConvexHull(points)
    faces = []
    for simplex, eq in zip(hull.simplices, hull.equations, strict=True):
        tri = points[simplex]
        n = np.cross(tri[1] - tri[0], tri[2] - tri[0])
        if n @ eq[:3] > 0:  # outward: reverse for the inner side
            tri = tri[::-1]
        faces.append(tri)
    return faces


@settings(max_examples=8, deadline=None)
@given(st.integers(0, 10**6))
def test_closed_convex_enclosure_sums_to_one(seed):
    """Inside a convex polyhedron every face sees the others entirely: sum_j F_ij = 1."""
    rng = np.random.default_rng(seed)
    pts = rng.normal(size=(int(rng.integers(4, 9)), 3)) * rng.uniform(0.2, 3, size=3)
    faces = _inner_faces(pts)
    areas = [_normal(f)[1] for f in faces]
    F = np.array([[polygon_form_factor(a, b) if i != j else 0.0 for j, b in enumerate(faces)]
                  for i, a in enumerate(faces)])
    assert F.sum(axis=1) == pytest.approx(np.ones(len(faces)), rel=1e-9, abs=1e-9)
    A = np.array(areas)
    assert A[:, None] * F == pytest.approx((A[:, None] * F).T, rel=1e-9, abs=1e-12 * A.max())


def test_box_interior_sums_to_one():
    lo, hi = np.zeros(3), np.array([4.0, 3.0, 2.5])
    faces = []
    for ax in range(3):
        u, v = (ax + 1) % 3, (ax + 2) % 3
        for side, sign in ((lo, 1), (hi, -1)):
            q = np.zeros((4, 3))
            for m, (a, b) in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)]):
                q[m, ax] = side[ax]
                q[m, u] = lo[u] + a * (hi[u] - lo[u])
                q[m, v] = lo[v] + b * (hi[v] - lo[v])
            faces.append(q if sign > 0 else q[::-1])
    for i, a in enumerate(faces):
        s = sum(polygon_form_factor(a, b) for j, b in enumerate(faces) if j != i)
        assert s == pytest.approx(1.0, rel=1e-10)  # the closed forms' cancellation: about 4e-12


def test_point_factor_unit_square_and_occlusion():
    sq = [(0, 0, 1), (0, 1, 1), (1, 1, 1), (1, 0, 1)]
    f = point_form_factor([[0, 0, 0]], [[0, 0, 1]], sq)[0]
    # Howell B-3 (element to a parallel rectangle at a corner): a = b = c = 1
    X = Y = 1.0
    ref = (X / math.sqrt(1 + X * X) * math.atan(Y / math.sqrt(1 + X * X))
           + Y / math.sqrt(1 + Y * Y) * math.atan(X / math.sqrt(1 + Y * Y))) / (2 * math.pi)
    assert f == pytest.approx(ref, rel=1e-12)
    from isocsg import Box
    assert point_form_factor([[0.5, 0.5, 0]], [[0, 0, 1]], sq, [Box((0.5, 0.5, 0.5), (3, 3, 0.1))])[0] == 0.0


def test_point_factor_integrates_to_polygon_factor():
    """The mean over the receiver of the point factor is the polygon factor (separated plates)."""
    a = rect_z((0, 1), (0, 2), 0)
    b = rect_z((0.5, 1.5), (-1, 1), 1.3, up=False)
    xs, ws = _gauss_polygon(a, 20)
    pf = point_form_factor(xs, [0, 0, 1], b)
    assert float(ws @ pf) / 2.0 == pytest.approx(polygon_form_factor(a, b), rel=1e-9)


@pytest.mark.parametrize("bad,msg", [
    ([(0, 0, 0), (1, 0, 0), (2, 0, 0)], "source must be a polygon of non-zero area"),
    ([(0, 0, 0), (1, 0, 0), (1, 1, 1), (0, 1, 0)], "source must be planar"),
    ([(0, 0, float("nan")), (1, 0, 0), (0, 1, 0)], "source"),
])
def test_bad_polygons_raise(bad, msg):
    with pytest.raises(InvalidGeometryError, match=msg):
        polygon_form_factor(bad, rect_z((0, 1), (0, 1), 1, up=False))
