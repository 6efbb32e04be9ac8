"""isocsg.testing's surface areas and boundary volumes against closed forms and manifold3d."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings

from isocsg import Box, Cone, Cylinder, Ellipsoid, Sphere, Torus, Truncus, volume
from isocsg.csg.mesh import to_manifold
from isocsg.testing import boundary_volume, closed_form_area, surface_area
from isocsg.testing.patches import leaf_patches
from isocsg.testing.strategies import trees

REL = 1e-9
TURN = np.array([[0.36, 0.48, -0.8], [-0.8, 0.6, 0.0], [0.48, 0.64, 0.6]])  # a rotation (3-4-5 entries)


def turned(solid):
    m = np.eye(4)
    m[:3, :3] = TURN
    m[:3, 3] = (0.3, -0.2, 0.1)
    return solid.transform(m)


def close(value: float, exact: float, rel: float = REL) -> bool:
    return abs(value - exact) <= rel * abs(exact)


PRIMS = [Sphere((0, 0, 0), 1.3), Box((1, 2, 3), (1, 2, 3)), Cylinder((0, 0, 0), (0, 0, 2), 0.7),
         Cone((0, 1, 0), (1, 1, 1), 0.5), Truncus((0, 0, 0), (0, 2, 0), 0.4, 0.9),
         Ellipsoid((0, 0, 0), (1.0, 2.0, 3.0)), Torus((0, 0, 0), (0, 0, 1), 2.0, 0.5),
         turned(Cylinder((0, 0, 0), (0, 0, 2), 0.7)).scale((1.0, 2.0, 0.5))]


@pytest.mark.parametrize("prim", PRIMS, ids=lambda p: type(p).__name__)
def test_patches_add_up_to_the_closed_form(prim):
    assert close(sum(p.closed_area for p in leaf_patches(0, prim)), closed_form_area(prim), 1e-13)


def test_closed_forms():
    assert close(closed_form_area(Sphere((0, 0, 0), 2)), 16 * math.pi, 1e-15)
    r1, r2, h = 0.4, 0.9, 2.0
    assert close(closed_form_area(Truncus((0, 0, 0), (0, 0, h), r1, r2)),
                 math.pi * (r1 + r2) * math.hypot(r1 - r2, h) + math.pi * (r1 * r1 + r2 * r2), 1e-15)
    assert close(closed_form_area(Torus((0, 0, 0), (0, 0, 1), 2.0, 0.5)), 4 * math.pi**2, 1e-15)
    a, c = 2.0, 1.0  # an oblate spheroid: 2 pi a^2 (1 + (1 - e^2) / e atanh e)
    e = math.sqrt(1 - c * c / (a * a))
    assert close(closed_form_area(Ellipsoid((0, 0, 0), (a, a, c))), 2 * math.pi * a * a * (1 + (1 - e * e) / e * math.atanh(e)), 1e-13)


def test_ellipsoid_closed_form_against_a_double_integral():
    from scipy.integrate import dblquad

    a, b, c = 1.0, 2.0, 3.0

    def dA(t, p):  # |x_t x x_p| of (a sin t cos p, b sin t sin p, c cos t)
        st, ct, sp, cp = math.sin(t), math.cos(t), math.sin(p), math.cos(p)
        return st * math.sqrt((b * c * st * cp) ** 2 + (a * c * st * sp) ** 2 + (a * b * ct) ** 2)

    exact, _ = dblquad(dA, 0, 2 * math.pi, 0, math.pi, epsabs=1e-13, epsrel=1e-13)
    assert close(closed_form_area(Ellipsoid((0, 0, 0), (a, b, c))), exact, 1e-11)


@pytest.mark.parametrize("tilt", [False, True], ids=["axes", "turned"])
def test_sphere_cap(tilt):
    r, h = 1.0, 0.3  # a sphere cut by a box face at height r - h: the cap 2 pi r h and its disc
    s = Sphere((0, 0, 0), r) & Box((0, 0, r - h + 2), (4, 4, 4))
    s = turned(s) if tilt else s
    got = surface_area(s)
    assert close(got.value, 2 * math.pi * r * h + math.pi * (r * r - (r - h) ** 2))
    assert got.error < 1e-8


def test_lens_of_two_spheres():
    r1, r2, d = 1.0, 0.8, 1.2
    a = (d * d + r1 * r1 - r2 * r2) / (2 * d)
    h1, h2 = r1 - a, r2 - (d - a)
    s = turned(Sphere((0, 0, 0), r1) & Sphere((d, 0, 0), r2))
    assert close(surface_area(s).value, 2 * math.pi * (r1 * h1 + r2 * h2))
    lens_volume = math.pi * h1 * h1 * (3 * r1 - h1) / 3 + math.pi * h2 * h2 * (3 * r2 - h2) / 3
    assert close(boundary_volume(s).value, lens_volume)
    union = Sphere((0, 0, 0), r1) | Sphere((d, 0, 0), r2)
    assert close(surface_area(union).value, 4 * math.pi * (r1 * r1 + r2 * r2) - 2 * math.pi * (r1 * h1 + r2 * h2))


def test_cylinder_cut_by_a_box():
    d, H = 0.5, 2.0  # the part x >= d of a unit cylinder: two circular segments, the arc side, the flat cut
    ang = 2 * math.acos(d)
    exact = 2 * 0.5 * (ang - math.sin(ang)) + ang * H + 2 * math.sqrt(1 - d * d) * H
    s = turned(Cylinder((0, 0, 0), (0, 0, H), 1) & Box((d + 2, 0, 0), (4, 4, 4)))
    assert close(surface_area(s).value, exact)


def test_cone_through_a_plane():
    # base radius 1 at z = +1, apex at z = -1; the box keeps z <= 0.5: a cone of radius 0.75, slant from the apex
    s = Cone((0, 0, 0), (0, 0, 2), 1) & Box((0, 0, -1.5), (4, 4, 4))
    rr = 0.75
    exact = math.pi * rr * math.hypot(rr, 1.5) + math.pi * rr * rr
    assert close(surface_area(turned(s)).value, exact)


def test_ellipsoid_and_torus_halves():
    e = Ellipsoid((0, 0, 0), (1.0, 2.0, 3.0)) & Box((0, 0, -5), (10, 10, 10))  # z <= 0: half and an ellipse
    assert close(surface_area(e).value, closed_form_area(Ellipsoid((0, 0, 0), (1.0, 2.0, 3.0))) / 2 + math.pi * 2.0)
    t = Torus((0, 0, 0), (0, 0, 1), 2.0, 0.5) - Box((0, 0, 5), (10, 10, 10))  # the lower half and an annulus
    assert close(surface_area(turned(t)).value, 2 * math.pi**2 * 2.0 * 0.5 + math.pi * (2.5**2 - 1.5**2))


def test_coincident_faces_count_once_or_not_at_all():
    a, b = Box((0, 0, 0), (1, 1, 1)), Box((1, 0, 0), (1, 1, 1))
    assert close(surface_area(a | b).value, 2 * (2 + 1 + 2), 1e-12)  # the shared face is inside
    assert surface_area(a - a).value == 0.0
    assert surface_area(a & b).value == 0.0  # touching only: no solid
    c = Box((0.25, 0, 0), (0.5, 1, 1))  # shares three faces with a
    assert close(surface_area(a - c).value, 2 * (0.5 + 0.5 + 1), 1e-12)
    assert close(surface_area(a | a).value, 6.0, 1e-12)


@settings(max_examples=4, deadline=None)
@given(trees(max_leaves=3, degenerate=False))
def test_random_trees_against_manifold3d(tree):
    got = surface_area(tree, tol=1e-7)
    errors = []
    for seg in (64, 256):
        m = to_manifold(tree, seg)
        errors.append(abs(m.surface_area() - got.value))
    # meshes of the leaves converge as (2 pi / segments)^2: the finer one is closer (or both at rounding)
    assert errors[1] <= max(errors[0], 1e-9 * max(got.value, 1.0)) + 1e-9
    assert errors[1] <= 2e-3 * max(got.value, 1e-3) + 1e-9
    v = boundary_volume(tree, tol=1e-7).value
    assert abs(v - volume(tree, tol=1e-6)) <= 1e-5 * max(v, 1e-3) + 1e-9
