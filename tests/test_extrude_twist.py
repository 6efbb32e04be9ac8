"""``linear_extrude`` with ``scale``, ``twist`` and ``slices``: closed forms, an independent mesh of
OpenSCAD's slices, and membership through the inverse twist and scale, over drawn outlines."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
import shapely
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon

from isocsg import volume
from isocsg.csg.extrude import prism
from isocsg.errors import InvalidGeometryError
from isocsg.kinds import ConvexPolyhedron
from isocsg.shapes2d import area, circle, linear_extrude, polygon, square, to_shapely
from isocsg.shapes2d.twist import slice_count


def _star(radii, centre=(0.0, 0.0)):
    ang = np.linspace(0, 2 * np.pi, len(radii), endpoint=False)
    r = np.asarray(radii)
    return np.c_[r * np.cos(ang) + centre[0], r * np.sin(ang) + centre[1]]


def _ring_at(p, angle, s, z):
    c, si = math.cos(math.radians(-angle)), math.sin(math.radians(-angle))
    return np.c_[s[0] * (c * p[:, 0] - si * p[:, 1]), s[1] * (si * p[:, 0] + c * p[:, 1]), np.full(len(p), z)]


def _openscad_mesh_volume(region, h, twist, scale, n):
    """The volume of OpenSCAD 2021.01's mesh (``add_slice``: each side quad split along its shorter
    diagonal in the plane, ties by the twist's sign and the ring's orientation), by the divergence
    theorem: side triangles as signed tetrahedra about the origin, the caps as ``z A / 3``."""
    region = shapely.orient_polygons(region)
    total = 0.0
    for j in range(n):
        a0, a1 = twist * j / n, twist * (j + 1) / n
        s0 = (1 - (1 - scale[0]) * j / n, 1 - (1 - scale[1]) * j / n)
        s1 = (1 - (1 - scale[0]) * (j + 1) / n, 1 - (1 - scale[1]) * (j + 1) / n)
        z0, z1 = h * j / n, h * (j + 1) / n
        zero = s1[0] == 0 or s1[1] == 0
        for poly in shapely.get_parts(region):
            for ring, positive in [(poly.exterior, True), *((r, False) for r in poly.interiors)]:
                p = np.asarray(ring.coords)[:-1]
                b, t = _ring_at(p, a0, s0, z0), _ring_at(p, a1, s1, z1)
                for i in range(len(p)):
                    k = (i + 1) % len(p)
                    d1, d2 = np.hypot(*(b[i, :2] - t[k, :2])), np.hypot(*(b[k, :2] - t[i, :2]))
                    sign = 0 if 2 * abs(d1 - d2) * 1e5 <= d1 + d2 else (-1 if d1 < d2 else 1)
                    first = sign == -1 or (sign == 0 and positive == (a1 <= a0))
                    tris = [(b[i], b[k], t[k]), (b[i], t[k], t[i])] if first != zero else [(b[i], b[k], t[i]), (b[k], t[k], t[i])]
                    total += sum(float(np.linalg.det(np.array(tri))) for tri in tris) / 6.0
    a = region.area
    return total + h * a * scale[0] * scale[1] / 3.0  # the bottom cap at z = 0 adds nothing


@settings(max_examples=8, deadline=None)
@given(
    st.lists(st.floats(1.0, 3.0), min_size=5, max_size=8),
    st.tuples(st.floats(-2, 2), st.floats(-2, 2)),
    st.floats(-150, 150),
    st.integers(1, 5),
    st.one_of(st.floats(0.3, 1.8).map(lambda s: (s, s)), st.tuples(st.floats(0.3, 1.8), st.floats(0.3, 1.8))),
    st.booleans(),
)
def test_twisted_polygons_are_openscads_stack_of_slices(radii, centre, twist, n, scale, hole):
    pts = _star(radii, centre)
    shape = polygon(pts)
    if hole:
        shape = shape - square(0.8, center=True).translate(list(centre))
    try:
        solid = linear_extrude(shape, 2.0, twist=twist, slices=n, scale=list(scale))
    except InvalidGeometryError as exc:
        assert "the turn per slice is too large for an exact form" in str(exc)
        assume(False)
    want = _openscad_mesh_volume(to_shapely(shape), 2.0, twist, scale, n)
    assert volume(solid) == pytest.approx(want, rel=1e-9)


@settings(max_examples=4, deadline=None)
@given(st.lists(st.floats(1.0, 3.0), min_size=4, max_size=8), st.floats(-120, 120), st.floats(0.5, 1.5))
def test_membership_follows_the_inverse_twist_and_scale(radii, twist, s):
    """A point (x, y, z) away from the surface is inside iff its un-scaled, un-twisted 2D point is
    inside the outline (shapely); the stack of slices departs from the continuous twist by less
    than ``R (turn per slice)`` (the diagonals of its side quads)."""
    pts = _star(radii, (0.5, -0.3))
    h, n = 3.0, 24
    solid = linear_extrude(polygon(pts), h, twist=twist, slices=n, scale=s)
    rng = np.random.default_rng(len(radii))
    q = np.c_[rng.uniform(-4, 4, 3000), rng.uniform(-4, 4, 3000), rng.uniform(0.01, h - 0.01, 3000)]
    lam = q[:, 2] / h
    k = 1 - (1 - s) * lam
    phi = np.radians(twist * lam)  # the top turned clockwise by twist: turn back counter-clockwise
    x, y = q[:, 0] / k, q[:, 1] / k
    u, v = np.cos(phi) * x - np.sin(phi) * y, np.sin(phi) * x + np.cos(phi) * y
    outline = Polygon(pts)
    inside = shapely.contains_xy(outline, u, v)
    margin = 3.5 * 1.6 * abs(math.radians(twist / n)) + 1e-6  # radius 3 (+0.6 off centre), scale up to 1.5
    far = shapely.distance(shapely.points(u, v), outline.boundary) > margin
    got = solid.contains(q)
    assert far.sum() > 1500
    assert np.array_equal(got[far], inside[far])


@settings(max_examples=15, deadline=None)
@given(st.lists(st.floats(0.5, 3.0), min_size=5, max_size=12), st.floats(0.0, 2.0), st.booleans())
def test_uniformly_scaled_prisms_have_the_closed_form_volume(radii, s, centred):
    shape = polygon(_star(radii, (1.5, 0.5)))
    h = 2.5
    solid = linear_extrude(shape, h, scale=s, center=centred)
    assert volume(solid) == pytest.approx(h * area(shape) * (1 + s + s * s) / 3, rel=1e-9)


@pytest.mark.parametrize("s", [0.0, 0.4, 1.0, 1.7])
@pytest.mark.parametrize("centre", [(0.0, 0.0), (3.0, -1.0)])
def test_scaled_circles_are_frusta(s, centre):
    solid = linear_extrude(circle(2).translate(list(centre)), 3, scale=s)
    assert volume(solid) == pytest.approx(math.pi * 4 * 3 * (1 + s + s * s) / 3, rel=1e-9)
    # near the top the disc's centre and radius are scaled about the axis by k
    z = 3 * (1 - 1e-2)
    k = 1 - (1 - s) * z / 3
    near = np.array([[centre[0] * k, centre[1] * k, z], [centre[0] * k + 2 * k * 1.01, centre[1] * k, z]])
    assert solid.contains(near).tolist() == [True, False]


def test_twisted_circles_keep_the_disc_on_every_slice():
    """Off the axis: a sheared cylinder per slice, the disc's centre on the chord of its helix;
    about the axis: the cylinder itself (a twist changes nothing)."""
    n, h, r, c = 8, 2.0, 1.0, 2.0
    solid = linear_extrude(circle(r).translate([c, 0]), h, twist=90, slices=n)
    assert volume(solid) == pytest.approx(math.pi * r * r * h, rel=1e-12)
    z = np.linspace(0.01, h - 0.01, 40)
    lam = z / h
    j = np.minimum((lam * n).astype(int), n - 1)
    f = lam * n - j
    a0, a1 = np.radians(-90 * j / n), np.radians(-90 * (j + 1) / n)
    cx = c * ((1 - f) * np.cos(a0) + f * np.cos(a1))
    cy = c * ((1 - f) * np.sin(a0) + f * np.sin(a1))
    assert solid.contains(np.c_[cx + 0.99 * r, cy, z]).all()
    assert not solid.contains(np.c_[cx + 1.01 * r, cy, z]).any()
    centred = linear_extrude(circle(1), 2, twist=180)
    assert type(centred).__name__ == "Cylinder"


def test_slice_counts_are_openscad_2021s():
    # Calc::get_helix_slices: $fn turns, else min($fa, $fs along the helix), at least 1 per 120 degrees.
    assert slice_count(5, 0, 10, 90, (1, 1), fn=96) == 24
    assert slice_count(5, 0, 10, 90, (1, 1)) == min(math.ceil(90 / 12), math.ceil(math.hypot(5 * math.pi / 2, 10) / 2))
    assert slice_count(0, 0, 10, 500, (1, 1)) == 5
    assert slice_count(5, 0, 10, 0, (1, 1)) == 1
    assert slice_count(5, 3, 4, 0, (2, 0.5)) == 3  # get_diagonal_slices: ceil(hypot(3, 4) / 2)
    assert slice_count(5, 3, 4, 0, (2, 0.5), fn=7) == 7


def test_prisms_from_known_faces_equal_the_hull():
    p = _star([1, 1.2, 0.9, 1.1, 1.3, 1.0])
    p = np.insert(p, 1, (p[0] + p[1]) / 2, axis=0)  # a straight corner is no hull vertex
    a = prism(p, -0.5, 2.0)
    b = ConvexPolyhedron(np.r_[np.c_[p, np.full(len(p), -0.5)], np.c_[p, np.full(len(p), 2.0)]])
    assert a == b and len(a.hull_vertices) == len(b.hull_vertices) == 12
    assert a.volume == pytest.approx(b.volume, rel=1e-14)
    key = lambda s: sorted(map(tuple, np.round(np.c_[s.face_normals, s.face_offsets], 12)))  # noqa: E731
    assert key(a) == key(b)


BAD = [
    (lambda: linear_extrude(square(1), 1, twist=float("nan")), "linear_extrude.twist must be a finite number"),
    (lambda: linear_extrude(square(1), 1, twist=30, slices=0), "linear_extrude.slices must be >= 1, got 0"),
    (lambda: linear_extrude(square(1), 1, twist=30, slices=2.5), "linear_extrude.slices must be a whole number, got 2.5"),
    (lambda: linear_extrude(square(1), 1, twist=30, slices=20000), "linear_extrude.slices must be <= 10000, got 20000"),
    (lambda: linear_extrude(circle(1), 1, scale=[1, 2]), "linear_extrude.scale must be uniform for a circle or ellipse"),
    (lambda: linear_extrude(circle(1).scale([2, 1]), 1, twist=10), "linear_extrude.twist: a twisted ellipse has no exact form"),
    (lambda: linear_extrude(square(1), 1, twist=10, fs=0), "linear_extrude.fs must be > 0, got 0"),
    (lambda: linear_extrude("square", 1, twist=10), "linear_extrude.shape must be a 2D shape, got str"),
]


@pytest.mark.parametrize("make, message", BAD, ids=[m for _, m in BAD])
def test_errors_name_the_field(make, message):
    with pytest.raises(InvalidGeometryError, match=re.escape(message)):
        make()
