"""Lambert's contour integral and the light sources against closed forms and quadrature.

References are independent of the library: trigonometric closed forms derived
here, the classical parallel-rectangle form factor, and adaptive quadrature of
the textbook integrand cos(theta_p) cos(theta_q) / r^2 over the source.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from scipy import integrate

import isocsg
from isocsg.shadows import AreaLight, PolyhedronLight, illuminance, polygon_illuminance, rings_illuminance

REL = 1e-9


def regular_polygon(m, R, h, facing_down=True):
    ang = 2 * np.pi * np.arange(m) / m
    q = np.c_[R * np.cos(ang), R * np.sin(ang), np.full(m, h)]
    return q[::-1] if facing_down else q  # clockwise seen from above = counter-clockwise seen from below


def regular_on_axis(m, R, h, L=1.0):
    """Exact E of a regular m-gon (circumradius R) at height h on its axis.

    By symmetry every edge gives the same term: beta is the angle subtended by
    an edge, cos(beta) = (R^2 cos(2 pi/m) + h^2) / (R^2 + h^2); the triangle
    (p, edge) contains the edge at apothem a = R cos(pi/m) and height h, so the
    angle between its plane and the receiving plane has cos(delta) = a / sqrt(a^2 + h^2).
    """
    beta = math.acos((R * R * math.cos(2 * math.pi / m) + h * h) / (R * R + h * h))
    a = R * math.cos(math.pi / m)
    return 0.5 * L * m * beta * a / math.hypot(a, h)


def rect_corner_ff(a, b, h):
    """Form factor from a differential area to a parallel a x b rectangle at distance h, above one corner."""
    X, Y = a / h, b / h
    sx, sy = math.sqrt(1 + X * X), math.sqrt(1 + Y * Y)
    return (X / sx * math.atan(Y / sx) + Y / sy * math.atan(X / sy)) / (2 * math.pi)


def quad_polygon(p, n, poly, L=1.0):
    """Adaptive quadrature of L cos_p+ cos_q / r^2 over a convex polygon emitting along its right-hand normal."""
    p, n, poly = (np.asarray(x, float) for x in (p, n, poly))
    total = 0.0
    for i in range(1, len(poly) - 1):
        a, b, c = poly[0], poly[i], poly[i + 1]
        cr = np.cross(b - a, c - a)
        area2 = np.linalg.norm(cr)
        N = cr / area2

        def f(v, u, a=a, b=b, c=c, N=N):
            q = a + u * (b - a) + v * (c - a)
            d = q - p
            r2 = d @ d
            r = math.sqrt(r2)
            return max(0.0, n @ d / r) * max(0.0, -(N @ d) / r) / r2

        val, _ = integrate.dblquad(f, 0, 1, 0, lambda u: 1 - u, epsabs=1e-14, epsrel=1e-12)
        total += val * area2
    return L * total


def clip_by_plane(poly, p, n):
    """Part of a convex polygon with n . (x - p) >= 0 (Sutherland-Hodgman), written for the test."""
    out = []
    m = len(poly)
    for i in range(m):
        a, b = poly[i], poly[(i + 1) % m]
        da, db = n @ (a - p), n @ (b - p)
        if da >= 0:
            out.append(a)
        if (da >= 0) != (db >= 0):
            out.append(a + da / (da - db) * (b - a))
    return np.array(out)


@pytest.mark.parametrize("m", [3, 4, 7, 64, 1000], ids=lambda m: f"m{m}")
@pytest.mark.parametrize("R,h", [(1.0, 1.0), (0.3, 2.5), (5.0, 0.2)], ids=["R1h1", "small-far", "wide-near"])
def test_regular_polygon_on_axis(m, R, h):
    q = regular_polygon(m, R, h)
    L = 2.5
    e = illuminance([[0, 0, 0]], [[0, 0, 1]], AreaLight(q, L))[0]
    assert e == pytest.approx(regular_on_axis(m, R, h, L), rel=REL)
    e2 = polygon_illuminance([[0, 0, 0]], [[0, 0, 1]], q, L)[0]
    assert e2 == pytest.approx(regular_on_axis(m, R, h, L), rel=REL)


@pytest.mark.parametrize("R,h", [(1.0, 1.0), (0.5, 3.0), (2.0, 0.5)], ids=["R1h1", "R.5h3", "R2h.5"])
def test_regular_polygon_tends_to_disc(R, h):
    disc = math.pi * R * R / (R * R + h * h)
    m = 20000
    # the closed form itself converges to the disc formula ...
    assert regular_on_axis(m, R, h) == pytest.approx(disc, rel=1e-7)
    # ... and so does the library (the inscribed polygon misses O(1/m^2) of the disc)
    e = illuminance([[0, 0, 0]], [[0, 0, 1]], AreaLight(regular_polygon(m, R, h)))[0]
    assert e == pytest.approx(disc, rel=1e-7)
    assert e < disc


@pytest.mark.parametrize("L", [1.0, 3.7], ids=["L1", "L3.7"])
def test_whole_hemisphere_gives_pi_L(L):
    W = 1e6
    sq = [(-W, -W, 1), (-W, W, 1), (W, W, 1), (W, -W, 1)]
    e = illuminance([[0.3, -0.2, 0.0]], [[0, 0, 1]], AreaLight(sq, L))[0]
    assert e == pytest.approx(math.pi * L, rel=REL)


@pytest.mark.parametrize(
    "p", [(0.0, 0.0), (0.3, 0.2), (1.0, 0.5), (-0.7, 1.9), (2.5, -1.0)], ids=["corner", "inside", "edge", "outside-y", "outside"]
)
def test_rectangle_form_factor(p):
    """E = pi L F; F for a general foot point by superposition of corner rectangles."""
    x0, x1, y0, y1, h, L = 0.0, 1.2, 0.0, 0.6, 0.9, 1.7
    rect = [(x0, y0, h), (x0, y1, h), (x1, y1, h), (x1, y0, h)]
    px, py = p

    def signed(ax, bx, ay, by):  # corner form factor of [ax, bx] x [ay, by] measured from the point's foot
        sx = math.copysign(1, bx - ax) if bx != ax else 0
        return sx

    def F_span(xa, xb, ya, yb):
        # F of the rectangle [xa, xb] x [ya, yb] from a foot point at the origin, xa < xb, ya < yb
        def corner(x, y):
            return math.copysign(1, x) * math.copysign(1, y) * rect_corner_ff(abs(x), abs(y), h) if x and y else 0.0

        return corner(xb, yb) - corner(xa, yb) - corner(xb, ya) + corner(xa, ya)

    F = F_span(x0 - px, x1 - px, y0 - py, y1 - py)
    e = illuminance([[px, py, 0.0]], [[0, 0, 1]], AreaLight(rect, L))[0]
    assert e == pytest.approx(math.pi * L * F, rel=REL)


@pytest.mark.parametrize(
    "p,n",
    [((0.1, 0.2, 0.0), (0, 0, 1)), ((1.5, -0.5, 0.3), (0.2, 0.1, 1.0)), ((-1, 1, 0.5), (0.6, -0.3, 0.7))],
    ids=["flat", "tilted-normal", "oblique"],
)
def test_tilted_polygon_against_quadrature(p, n):
    # a pentagon on a tilted plane, facing down-ish
    c = np.array([0.2, 0.1, 2.0])
    u = np.array([1.0, 0.0, 0.4]) / math.hypot(1, 0.4)
    v = np.cross([0.3, -0.2, 1.0], u)
    v /= np.linalg.norm(v)
    ang = 2 * np.pi * np.arange(5) / 5 + 0.3
    poly = c + np.outer(0.8 * np.cos(ang), u) + np.outer(0.6 * np.sin(ang), v)
    poly = poly[::-1]  # make it emit downwards
    light = AreaLight(poly, 1.3)
    assert light.normal[2] < 0
    n = np.asarray(n, float) / np.linalg.norm(n)
    ref = quad_polygon(p, n, poly, 1.3)
    assert illuminance([p], [n], [light])[0] == pytest.approx(ref, rel=1e-8)


@pytest.mark.parametrize("tilt", [1.0, 3.0, 20.0], ids=["45deg", "steep", "almost-vertical"])
def test_type_b_receiver_clips_the_source(tilt):
    """A receiving plane through the source: only the part in front of it lights p."""
    xy = np.array([(-1.0, -0.5), (-0.8, 0.9), (1.1, 0.7), (0.9, -0.6)])
    poly = np.c_[xy, 1.0 + 0.1 * xy[:, 0] + 0.15 * xy[:, 1]]  # on a tilted plane
    light = AreaLight(poly, 2.0)
    if light.normal[2] > 0:
        poly = poly[::-1]
        light = AreaLight(poly, 2.0)
    p = np.array([0.1, 0.0, 0.0])
    n = np.array([tilt, 0.0, 1.0]) / math.hypot(tilt, 1.0)
    assert np.any((poly - p) @ n < 0) and np.any((poly - p) @ n > 0)  # really type B
    part = clip_by_plane(poly, p, n)
    ref = quad_polygon(p, n, part, 2.0)
    assert illuminance([p], [n], [light])[0] == pytest.approx(ref, rel=1e-8)
    assert polygon_illuminance([p], [n], poly, 2.0)[0] == pytest.approx(ref, rel=1e-8)


def test_points_behind_an_area_light_get_nothing():
    light = AreaLight([(0, 0, 1), (0, 1, 1), (1, 1, 1), (1, 0, 1)])  # emits downwards
    e = illuminance([[0.5, 0.5, 2.0], [0.5, 0.5, 1.0], [0.2, 0.3, 0.0]], [[0, 0, -1], [0, 0, 1], [0, 0, 1]], light)
    assert e[0] == 0.0 and e[1] == 0.0 and e[2] > 0


@pytest.mark.parametrize(
    "p,n",
    [((0.3, 0.2, -1.5), (0, 0, 1)), ((2.0, 0.4, -0.7), (-0.6, 0, 0.8)), ((-1.2, -1.4, 0.6), (0.5, 0.6, 0.1))],
    ids=["below", "below-side", "corner-side"],
)
def test_polyhedron_source_is_the_sum_of_its_front_faces(p, n):
    cube = [(x, y, z) for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (0.0, 1.0)]
    light = PolyhedronLight(cube, 1.5)
    n = np.asarray(n, float) / np.linalg.norm(n)
    p = np.asarray(p, float)
    # faces written out by hand, counter-clockwise seen from outside
    faces = [
        [(-.5, -.5, 0), (-.5, .5, 0), (.5, .5, 0), (.5, -.5, 0)],  # bottom, normal -z
        [(-.5, -.5, 1), (.5, -.5, 1), (.5, .5, 1), (-.5, .5, 1)],  # top, +z
        [(.5, -.5, 0), (.5, .5, 0), (.5, .5, 1), (.5, -.5, 1)],  # +x
        [(-.5, -.5, 0), (-.5, -.5, 1), (-.5, .5, 1), (-.5, .5, 0)],  # -x
        [(-.5, .5, 0), (-.5, .5, 1), (.5, .5, 1), (.5, .5, 0)],  # +y
        [(-.5, -.5, 0), (.5, -.5, 0), (.5, -.5, 1), (-.5, -.5, 1)],  # -y
    ]
    ref = 0.0
    nfront = 0
    for f in faces:
        f = np.array(f, float)
        N = np.cross(f[1] - f[0], f[2] - f[0])
        if N @ (p - f[0]) > 0:  # front face seen from p
            nfront += 1
            ref += quad_polygon(p, n, clip_by_plane(f, p, n) if np.any((f - p) @ n < 0) else f, 1.5)
    assert nfront >= 1
    assert illuminance([p], [n], [light])[0] == pytest.approx(ref, rel=1e-8)


def test_rings_with_holes_and_disjoint_pieces():
    p, n = [[0.1, -0.2, 0.0]], [[0, 0, 1]]
    h = 1.3
    outer = [(-1, -1, h), (-1, 1, h), (1, 1, h), (1, -1, h)]  # counter-clockwise seen from below
    hole = [(-0.4, -0.3, h), (0.5, -0.3, h), (0.5, 0.2, h), (-0.4, 0.2, h)]  # clockwise seen from below
    far = [(2, 2, h), (2, 3, h), (3, 3, h), (3, 2, h)]
    e = rings_illuminance(p, n, [outer, hole, far])[0]

    def rect(x0, x1, y0, y1):
        px, py = 0.1, -0.2
        tot = 0.0
        for sx, x in ((1, x1 - px), (-1, x0 - px)):
            for sy, y in ((1, y1 - py), (-1, y0 - py)):
                tot += sx * sy * math.copysign(1, x) * math.copysign(1, y) * rect_corner_ff(abs(x), abs(y), h)
        return math.pi * tot

    ref = rect(-1, 1, -1, 1) - rect(-0.4, 0.5, -0.3, 0.2) + rect(2, 3, 2, 3)
    assert e == pytest.approx(ref, rel=REL)


def test_several_lights_add_up():
    a = AreaLight(regular_polygon(6, 1.0, 2.0), 1.0)
    b = AreaLight(regular_polygon(9, 0.5, 1.0), 2.0)
    e = illuminance([[0, 0, 0]], [[0, 0, 1]], [a, b])[0]
    assert e == pytest.approx(regular_on_axis(6, 1.0, 2.0, 1.0) + regular_on_axis(9, 0.5, 1.0, 2.0), rel=REL)


def test_point_in_the_source_plane_is_finite():
    light = AreaLight([(0, 0, 1), (0, 1, 1), (1, 1, 1), (1, 0, 1)])
    e = illuminance([[2.0, 0.5, 1.0], [0.5, 0.5, 1.0 - 1e-13]], [[0, 0, 1], [0, 0, 1]], light)
    assert np.all(np.isfinite(e))
    assert e[0] == 0.0
    assert e[1] == pytest.approx(math.pi, rel=1e-9)  # just below the centre: the source fills the hemisphere


# ----------------------------------------------------------------------------- validation


@pytest.mark.parametrize(
    "verts,msg",
    [
        ([(0, 0, 0), (1, 0, 0)], "AreaLight.vertices needs at least 3 rows, got 2"),
        ([(0, 0, 0), (1, 0, 0), (2, 0, 0)], "AreaLight.vertices are collinear: the polygon has zero area"),
        ([(0, 0, 0), (1, 0, 0), (1, 0, 0), (0, 1, 0)], "AreaLight.vertices has repeated consecutive points (vertex 1 and 2)"),
        ([(0, 0, 0), (1, 0, 0), (1, 1, 0.1), (0, 1, 0)], "AreaLight.vertices must be planar"),
        ([(0, 0, 0), (1, 0, 0), (0.2, 0.2, 0), (0, 1, 0)], "AreaLight.vertices must form a strictly convex polygon"),
        ([(0, 0, 0), (1, 0, 0), (2, 0, 0), (1, 1, 0)], "AreaLight.vertices must form a strictly convex polygon"),
        ([(0, 0, np.nan), (1, 0, 0), (0, 1, 0)], "AreaLight.vertices must be finite"),
    ],
    ids=["two", "collinear", "repeated", "non-planar", "reflex", "collinear-vertex", "nan"],
)
def test_area_light_validation(verts, msg):
    with pytest.raises(isocsg.InvalidLightError, match=re.escape(msg)):
        AreaLight(verts)


def test_area_light_rejects_a_pentagram():
    star = [(math.cos(4 * math.pi * k / 5), math.sin(4 * math.pi * k / 5), 0) for k in range(5)]
    with pytest.raises(isocsg.InvalidLightError, match="AreaLight.vertices must form a simple convex polygon"):
        AreaLight(star)


def _circle(m: int, radius: float = 1.0, center: tuple[float, float, float] = (0.0, 0.0, 3.0)) -> np.ndarray:
    t = np.linspace(0.0, 2.0 * np.pi, m, endpoint=False)
    return np.c_[center[0] + radius * np.cos(t), center[1] + radius * np.sin(t), np.full(m, center[2])]


@pytest.mark.parametrize("m", [40_000, 65_536])
@pytest.mark.parametrize("radius,center", [(1.0, (0.0, 0.0, 3.0)), (1e-3, (5.0, -2.0, 3.0)), (300.0, (0.0, 0.0, 3.0))],
                         ids=["unit", "small-off-origin", "large"])
def test_a_fine_circle_up_to_the_vertex_limit_is_a_convex_light(m, radius, center):
    """The convexity tolerance scales with the polygon and its vertex spacing (40 000 vertices were refused)."""
    light = AreaLight(_circle(m, radius, center)[::-1])  # clockwise from above: lights downwards
    assert light.normal == (0.0, 0.0, -1.0)
    assert light.area == pytest.approx(0.5 * m * radius**2 * math.sin(2 * math.pi / m), rel=1e-9)


@pytest.mark.parametrize("m", [1000, 65_536])
def test_a_fine_circle_with_one_reflex_or_collinear_vertex_is_refused(m):
    pts = _circle(m)
    dent = pts.copy()
    dent[m // 3, :2] *= 2 * math.cos(2 * math.pi / m) - 1  # pushed inwards past the chord of its neighbours
    flat = pts.copy()
    flat[m // 3] = 0.5 * (pts[m // 3 - 1] + pts[m // 3 + 1])  # on the chord of its neighbours
    for bad in (dent, flat):
        with pytest.raises(isocsg.InvalidLightError, match=f"vertex {m // 3} is reflex or collinear"):
            AreaLight(bad)


@pytest.mark.parametrize("radiance", [-1.0, float("nan"), float("inf"), "x"], ids=["neg", "nan", "inf", "str"])
def test_radiance_validation(radiance):
    with pytest.raises(isocsg.InvalidLightError, match="AreaLight.radiance"):
        AreaLight([(0, 0, 0), (1, 0, 0), (0, 1, 0)], radiance)
    with pytest.raises(isocsg.InvalidLightError, match="PolyhedronLight.radiance"):
        PolyhedronLight([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)], radiance)


def test_polyhedron_light_validation():
    with pytest.raises(isocsg.InvalidLightError, match=re.escape("PolyhedronLight.vertices are coplanar")):
        PolyhedronLight([(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)])
    with pytest.raises(isocsg.InvalidLightError, match=re.escape("PolyhedronLight.vertices needs at least 4 rows")):
        PolyhedronLight([(0, 0, 0), (1, 0, 0), (0, 1, 0)])


def test_winding_chooses_the_lit_side():
    q = [(0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]  # counter-clockwise seen from above
    up, down = AreaLight(q), AreaLight(q[::-1])
    assert up.normal == (0.0, 0.0, 1.0) and down.normal == (0.0, 0.0, -1.0)
    below = ([[0.5, 0.5, 0.0]], [[0, 0, 1]])
    assert illuminance(*below, up)[0] == 0.0
    assert illuminance(*below, down)[0] > 0.0
    assert up == AreaLight(q) and hash(up) == hash(AreaLight(q))


def test_bad_points_and_normals():
    light = AreaLight([(0, 0, 1), (0, 1, 1), (1, 1, 1), (1, 0, 1)])
    with pytest.raises(isocsg.InvalidParameterError, match=re.escape("points must have shape (n, 3), got (2, 2)")):
        illuminance([[0, 0], [1, 1]], [0, 0, 1], light)
    with pytest.raises(isocsg.InvalidParameterError, match="normals must be non-zero"):
        illuminance([[0, 0, 0]], [0, 0, 0], light)
    with pytest.raises(isocsg.InvalidLightError, match=re.escape("lights[0] must be an AreaLight or a PolyhedronLight")):
        illuminance([[0, 0, 0]], [0, 0, 1], [isocsg.PointLight((0, 0, 1))])
