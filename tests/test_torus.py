"""The torus kind against independent references.

The references do not use the library's torus math: ray intervals come from the reference
caster's own sphere tracing on the exact distance (``reference.raycaster.torus_intervals``),
volumes from Pappus and manifold3d, sections from closed forms (annuli, pairs of discs,
Villarceau circles) and from scanlines of the reference intervals, the signed distance from
dense sampling of the surface, illuminance from Monte Carlo over the light with the reference
ray test, and images from the reference caster's exact shading.
"""

from __future__ import annotations

import math
import re
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference import compare, raycast_scene  # noqa: E402
from reference.raycaster import torus_intervals  # noqa: E402

import isocsg  # noqa: E402
from isocsg import Box, Camera, PointLight, Scene  # noqa: E402
from isocsg.errors import InvalidGeometryError  # noqa: E402
from isocsg.kinds import Torus, kind_named  # noqa: E402

TILTED = dict(center=(0.1, 0.2, 0.3), axis=(0.3, 0.2, 1.0), major=1.0, minor=0.3)
FLAT = dict(center=(0.0, 0.0, 0.0), axis=(0.0, 0.0, 1.0), major=1.5, minor=0.5)
MIN_IOU, MIN_FRACTION = 0.99, 0.98


def _unit(v):
    v = np.asarray(v, dtype=np.float64)
    return v / np.linalg.norm(v)


# ----------------------------------------------------------------------------- values


def test_fields_and_registration():
    t = Torus(**TILTED)
    assert t.kind == "torus" and kind_named("torus").cls is Torus
    assert not t.convex and t.max_intervals == 2
    assert np.allclose(t.axis, _unit(TILTED["axis"]))
    assert t == Torus(**TILTED) and hash(t) == hash(Torus(**TILTED))


@pytest.mark.parametrize(
    "fields, message",
    [
        (dict(FLAT, center=(0.0, float("nan"), 0.0)), "Torus.center"),
        (dict(FLAT, axis=(0.0, 0.0, 0.0)), "Torus.axis must be a non-zero vector"),
        (dict(FLAT, axis=(0.0, float("inf"), 1.0)), "Torus.axis"),
        (dict(FLAT, major=0.0), "Torus.major"),
        (dict(FLAT, major=-1.0), "Torus.major"),
        (dict(FLAT, major=float("nan")), "Torus.major"),
        (dict(FLAT, minor=0.0), "Torus.minor"),
        (dict(FLAT, minor=-0.5), "Torus.minor"),
        (dict(FLAT, minor=1.5), "Torus.minor must be < Torus.major"),
        (dict(FLAT, minor=2.0), "Torus.minor must be < Torus.major"),
        (dict(FLAT, major="1"), "Torus.major"),
    ],
    ids=["nan-center", "zero-axis", "inf-axis", "zero-major", "negative-major", "nan-major", "zero-minor",
         "negative-minor", "horn", "spindle", "string-major"],
)
def test_malformed(fields, message):
    with pytest.raises(InvalidGeometryError, match=re.escape(message)):
        Torus(**fields)


# ----------------------------------------------------------------------------- geometry


@pytest.mark.parametrize("fields", [TILTED, FLAT], ids=["tilted", "flat"])
def test_volume(fields):
    t = Torus(**fields)
    R, r = fields["major"], fields["minor"]
    assert t.volume == pytest.approx(2 * math.pi**2 * R * r * r, rel=1e-15)
    assert isocsg.volume(t, tol=1e-6) == pytest.approx(t.volume, rel=1e-5)
    assert isocsg.volume(t, tol=1e-6, axis=(1.0, 0.0, 0.0)) == pytest.approx(t.volume, rel=1e-5)
    mesh = t.to_manifold(1024)
    assert mesh.volume() == pytest.approx(t.volume, rel=5e-5)
    assert t.to_trimesh(64).is_watertight


def test_volume_and_section_in_a_tree():
    t = Torus(**FLAT)
    half = Box((-2.0, 0.0, 0.0), (4.0, 5.0, 2.0))  # cuts the torus in half through its axis
    cut = t - half
    assert isocsg.volume(cut, tol=1e-6) == pytest.approx(t.volume / 2, rel=1e-5)
    assert (t.to_manifold(512) - half.to_manifold()).volume() == pytest.approx(t.volume / 2, rel=2e-4)
    s = math.sqrt(t.minor**2 - 0.01)
    area = isocsg.section(cut, (0.0, 0.0, 0.1), (0.0, 0.0, 1.0), resolution=512, area_exact=True).geometry.area
    assert area == pytest.approx(math.pi * ((t.major + s) ** 2 - (t.major - s) ** 2) / 2, rel=1e-9)


def test_bounds_and_extent():
    t = Torus(**TILTED)
    pts = t.to_trimesh(1024).vertices
    assert np.allclose(t.bounds, [pts.min(axis=0), pts.max(axis=0)], atol=2e-5)
    for n in [(1.0, 0.0, 0.0), _unit((0.3, -0.7, 0.2)), _unit(TILTED["axis"])]:
        lo, hi = t.extent(n)
        proj = pts @ np.asarray(n)
        assert lo == pytest.approx(proj.min(), abs=2e-5) and hi == pytest.approx(proj.max(), abs=2e-5)
        bp = t.breakpoints(n)
        assert bp.min() == pytest.approx(lo) and bp.max() == pytest.approx(hi)


def test_signed_distance_against_sampling():
    t = Torus(**TILTED)
    n_u, n_v = 1200, 400
    surf = t.to_trimesh(2 * n_v).vertices  # a fine grid of surface points
    rng = np.random.default_rng(3)
    q = np.asarray(t.center) + rng.uniform(-1.6, 1.6, size=(300, 3))
    from scipy.spatial import cKDTree

    near, _ = cKDTree(surf).query(q)
    sd = t.signed_distance(q)
    spacing = 2 * math.pi * (t.major + t.minor) / max(n_u, 2 * n_v)
    assert np.all(np.abs(sd) <= near + 1e-12)  # exact distance <= distance to any sampled point
    assert np.all(near - np.abs(sd) <= spacing)
    # the sign: inside by the reference rays (an odd number of crossings before the point)
    d = np.tile([0.0, 0.0, 1.0], (len(q), 1))
    iv = torus_intervals(t, q, d)
    inside = np.any((iv[:, :, 0] < 0) & (iv[:, :, 1] > 0), axis=1)
    assert np.array_equal(sd < 0, inside)
    # on the surface
    assert np.max(np.abs(t.signed_distance(surf))) < 1e-14 * 10


# ----------------------------------------------------------------------------- rays


def _same_intervals(a, b, scale, extra=0.0):
    """Intervals equal up to ``1e-9 scale``, leaving out grazing ones (shorter than 1e-3 scale:
    a ray along the top circle touches the surface to fourth order, so its contact is only
    determined to about eps^(1/4) of the size), short ones within 1e-6 scale."""
    for ra, rb in zip(a, b):
        ka = [iv for iv in ra if np.isfinite(iv[0]) and iv[1] - iv[0] > 1e-3 * scale]
        kb = [iv for iv in rb if np.isfinite(iv[0]) and iv[1] - iv[0] > 1e-3 * scale]
        assert len(ka) == len(kb), (ra, rb)
        for x, y in zip(ka, kb):
            tol = 1e-9 if x[1] - x[0] > 1e-2 * scale else 1e-6
            assert np.allclose(x, y, rtol=0, atol=tol * scale + extra), (ra, rb)


def test_rays_special():
    t = Torus(**FLAT)
    R, r = t.major, t.minor
    o = np.array([
        [0.0, 0.0, 5.0],  # along the axis: through the hole
        [-5.0, 0.0, 0.0],  # through both sides of the tube
        [-5.0, 0.0, r],  # tangent to the top circle
        [-5.0, 0.0, 0.3],  # through the hole, off the middle plane
        [R, 0.0, 5.0],  # down the tube's centre circle
        [0.0, -5.0, R + r],  # tangent to the outer equator (one point)
        [1.0, 0.5, 0.1],  # from inside the tube
    ])
    d = np.array([[0, 0, -1], [1, 0, 0], [1, 0, 0], [1, 0, 0], [0, 0, -1], [0, 1, 0], [0.2, 1.0, 0.1]], dtype=float)
    iv = t.ray_intervals(o, d)
    assert iv.shape == (7, 2, 2)
    assert np.isnan(iv[0]).all()
    assert np.allclose(iv[1], [[5 - R - r, 5 - R + r], [5 + R - r, 5 + R + r]], atol=1e-12)
    # tangent: touching points or nothing (a double root bounds no inside segment)
    touch = iv[2][np.isfinite(iv[2][:, 0])]
    assert all(np.isclose(a, b, atol=1e-6) and min(abs(a - 5 + R), abs(a - 5 - R)) < 1e-6 for a, b in touch)
    s = math.sqrt(r * r - 0.09)
    assert np.allclose(iv[3], [[5 - R - s, 5 - R + s], [5 + R - s, 5 + R + s]], atol=1e-12)
    assert np.allclose(iv[4], [[5 - r, 5 + r], [np.nan, np.nan]], atol=1e-12, equal_nan=True)
    hit = iv[5][np.isfinite(iv[5][:, 0])]
    assert len(hit) <= 1 and (len(hit) == 0 or np.allclose(hit[0], [5.0, 5.0], atol=1e-6))
    assert np.any((iv[6, :, 0] < 0) & (iv[6, :, 1] > 0))  # the origin is inside
    _same_intervals(iv, torus_intervals(t, o, d), R + r)
    # scaled directions: t in units of the direction's length
    assert np.allclose(t.ray_intervals(o[1:2], 2 * d[1:2]), iv[1] / 2, atol=1e-12)


@settings(max_examples=60, deadline=None)
@given(
    st.lists(st.floats(-3, 3), min_size=3, max_size=3),
    st.lists(st.floats(-1, 1), min_size=3, max_size=3).filter(lambda v: np.linalg.norm(v) > 1e-3),
    st.lists(st.floats(-1, 1), min_size=3, max_size=3).filter(lambda v: np.linalg.norm(v) > 1e-3),
    st.floats(0.05, 0.95),
    st.floats(0.01, 100.0),
)
def test_rays_random(target, direction, axis, ratio, scale):
    t = Torus(tuple(0.1 * np.asarray(target)), tuple(axis), scale, ratio * scale)
    d = _unit(direction)
    # rays through points near the torus, from far and from near
    aim = np.asarray(t.center) + scale * np.asarray(target) * 0.6
    o = np.array([aim - 20 * scale * d, aim - 0.1 * scale * d, aim])
    dd = np.tile(d, (3, 1))
    _same_intervals(t.ray_intervals(o, dd), torus_intervals(t, o, dd), scale)
    hits = t.intersect_rays(o, dd)
    ok = hits.hit
    p = o[ok] + hits.t_in[ok, None] * dd[ok]
    assert np.allclose(np.abs(hits.n_in[ok]), np.abs(t.normals_at(p)))


@pytest.mark.parametrize("distance", [1e2, 1e4, 1e6])
def test_rays_from_far(distance):
    # the quartic is written from the ray's point nearest the centre: far eyes lose nothing
    t = Torus(**TILTED)
    rng = np.random.default_rng(11)
    aim = np.asarray(t.center) + rng.uniform(-1.2, 1.2, (400, 3))
    d = rng.normal(size=(400, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    o = aim - distance * d
    got, want = t.ray_intervals(o, d), torus_intervals(t, o, d)
    # both lose the rounding of points at distance: a few ulps of it
    _same_intervals(got - distance, want - distance, t.major + t.minor, extra=1e-14 * distance)
    assert np.isfinite(got[:, 0, 0]).sum() > 100


def test_rays_through_hole_and_tangent_batch():
    t = Torus(**TILTED)
    w, c = np.asarray(t.axis), np.asarray(t.center)
    e1 = _unit(np.cross(w, [1.0, 0.0, 0.0]))
    e2 = np.cross(w, e1)
    rng = np.random.default_rng(7)
    # rays in the torus's middle plane and tilted ones crossing the hole
    ang = rng.uniform(0, 2 * np.pi, 500)
    tilt = rng.uniform(-0.5, 0.5, 500)
    dirs = np.cos(ang)[:, None] * e1 + np.sin(ang)[:, None] * e2 + tilt[:, None] * w
    off = rng.uniform(-0.2, 0.2, (500, 1)) * w + rng.uniform(-0.5, 0.5, (500, 1)) * e1
    o = c + off - 4 * dirs
    # rays tangent to the outer equator and to the top circle
    tangent = c + (t.major + t.minor) * e1 - 4 * e2
    top = c + t.minor * w + t.major * e1 - 4 * e2
    o = np.vstack([o, tangent, top])
    dirs = np.vstack([dirs, e2, e2])
    _same_intervals(t.ray_intervals(o, dirs), torus_intervals(t, o, dirs), t.major + t.minor)
    two = np.isfinite(t.ray_intervals(o, dirs)[:, 1, 0])
    assert two.sum() > 100  # many rays cross the tube twice, through the hole


# ----------------------------------------------------------------------------- sections


@pytest.mark.parametrize("z", [0.0, 0.2, -0.29, 0.299, 0.35])
def test_section_across_axis(z):
    t = Torus(**TILTED)
    w = _unit(TILTED["axis"])
    R, r = t.major, t.minor
    sec = isocsg.section(t, np.asarray(t.center) + z * w, w, resolution=512, area_exact=True)
    if abs(z) >= r:
        assert sec.geometry.is_empty
        return
    s = math.sqrt(r * r - z * z)
    assert sec.geometry.area == pytest.approx(math.pi * ((R + s) ** 2 - (R - s) ** 2), rel=1e-12)
    assert len(sec.geometry.interiors) == 1  # an annulus


def test_section_through_axis():
    t = Torus(**TILTED)
    w = _unit(TILTED["axis"])
    n = _unit(np.cross(w, [0.0, 1.0, 0.0]))
    sec = isocsg.section(t, t.center, n, resolution=512, area_exact=True)
    assert sec.geometry.geom_type == "MultiPolygon" and len(sec.geometry.geoms) == 2
    assert sec.geometry.area == pytest.approx(2 * math.pi * t.minor**2, rel=1e-12)


def test_section_villarceau():
    # the bitangent plane through the centre, tilted by asin(r / R): two circles of radius R
    t = Torus(**FLAT)
    R, r = t.major, t.minor
    a = math.asin(r / R)
    n = np.array([math.sin(a), 0.0, math.cos(a)])
    sec = isocsg.section(t, t.center, n, resolution=1024)
    # the symmetric difference of two discs of radius R whose centres are 2 r apart
    dist = 2 * r
    lens = 2 * R * R * math.acos(dist / (2 * R)) - dist / 2 * math.sqrt(4 * R * R - dist * dist)
    assert sec.geometry.area == pytest.approx(2 * math.pi * R * R - 2 * lens, rel=2e-4)


@pytest.mark.parametrize("normal, offset", [((0.3, -0.2, 1.0), 0.1), ((1.0, 0.4, 0.2), 0.35), ((0.0, 1.0, 0.4), -0.2)])
def test_section_tilted_against_reference_scanlines(normal, offset):
    t = Torus(**TILTED)
    n = _unit(normal)
    origin = np.asarray(t.center) + offset * n
    sec = isocsg.section(t, origin, n, resolution=512)
    F = sec.frame
    u, v = F[:3, 0], F[:3, 1]
    # the reference: area by the midpoint rule over 4000 lines of the reference intervals
    ys = np.linspace(-2.0, 2.0, 4001)
    ys = 0.5 * (ys[1:] + ys[:-1])
    o = origin - 3.0 * u + ys[:, None] * v
    iv = torus_intervals(t, o, np.tile(u, (len(ys), 1)))
    area = float(np.nansum(iv[:, :, 1] - iv[:, :, 0])) * (ys[1] - ys[0])
    assert sec.geometry.area == pytest.approx(area, rel=2e-4)
    assert sec.geometry.is_valid


@settings(max_examples=15, deadline=None)
@given(
    st.lists(st.floats(-1, 1), min_size=3, max_size=3).filter(lambda v: np.linalg.norm(v) > 1e-2),
    st.floats(-0.6, 0.6),
)
def test_section_random_planes(normal, offset):
    t = Torus(**TILTED)
    n = _unit(normal)
    origin = np.asarray(t.center) + offset * n
    sec = isocsg.section(t, origin, n, resolution=256)
    F = sec.frame
    u, v = F[:3, 0], F[:3, 1]
    ys = np.linspace(-1.5, 1.5, 3001)
    ys = 0.5 * (ys[1:] + ys[:-1])
    iv = torus_intervals(t, origin - 3.0 * u + ys[:, None] * v, np.tile(u, (len(ys), 1)))
    area = float(np.nansum(iv[:, :, 1] - iv[:, :, 0])) * (ys[1] - ys[0])
    assert sec.geometry.area == pytest.approx(area, rel=2e-3, abs=1e-4)
    assert sec.geometry.is_valid


# ----------------------------------------------------------------------------- images


def _render_compare(scene):
    image = isocsg.render(scene, contours=64).image
    result = compare(image, raycast_scene(scene))
    assert result.iou >= MIN_IOU and result.fraction >= MIN_FRACTION, result.summary()


@pytest.mark.parametrize(
    "eye, light",
    [((3.0, -3.5, 2.5), (3.0, -1.0, 4.0)), ((0.3, 0.2, 4.0), (1.0, 2.0, 3.0)), ((4.0, 0.5, 0.35), (-2.0, -3.0, 1.0))],
    ids=["oblique", "down-the-hole", "edge-on"],
)
def test_render_alone(eye, light):
    scene = Scene(Camera(eye, TILTED["center"], width=96, height=96, fov=45), [PointLight(light)], [Torus(**TILTED)])
    _render_compare(scene)


@pytest.mark.parametrize(
    "lights, material",
    [
        ([PointLight((3.0, -1.0, 4.0))], isocsg.Material(ks=0.4, shininess=30)),
        ([isocsg.DirectionalLight((1.0, -1.0, 2.0))], isocsg.Material()),
        ([PointLight((3.0, -1.0, 4.0)), PointLight((-2.0, 2.0, 1.0), intensity=0.5)], isocsg.Material()),
    ],
    ids=["specular", "directional", "two-lights"],
)
def test_render_alone_lights(lights, material):
    t = Torus(**TILTED)
    scene = Scene(Camera((3.0, -3.5, 2.5), t.center, width=96, height=96, fov=45), lights,
                  [isocsg.scene.SceneObject(t, material)])
    _render_compare(scene)


def test_render_error_shrinks_with_contours():
    scene = Scene(Camera((3.0, -3.5, 2.5), TILTED["center"], width=96, height=96, fov=45), [PointLight((3.0, -1.0, 4.0))],
                  [Torus(**TILTED)])
    ref = raycast_scene(scene)
    errors = [compare(isocsg.render(scene, contours=n).image, ref).mean_error for n in (8, 32, 128)]
    assert errors[0] > errors[1] > errors[2], errors


def test_render_union_with_sphere():
    t = Torus(**FLAT)
    scene = Scene(Camera((3.0, -4.0, 3.0), (0, 0, 0), width=96, height=96, fov=45), [PointLight((2.0, -3.0, 5.0))],
                  [t | isocsg.Sphere((0.0, 0.0, 0.0), 0.6)])
    _render_compare(scene)


@pytest.mark.parametrize(
    "shape, eye",
    [
        (Torus(**FLAT) - Box((1.0, -1.0, 0.5), (2.0, 2.0, 1.0)), (3.0, -4.0, 3.0)),
        (Box((0.0, 0.0, 0.0), (4.0, 4.0, 0.6)) - Torus(**FLAT), (3.0, -4.0, 3.0)),
        (Torus(**FLAT) & isocsg.Sphere((1.5, 0.0, 0.0), 1.0), (3.0, -4.0, 3.0)),
    ],
    ids=["torus-minus-box", "box-minus-torus", "torus-and-sphere"],
)
def test_render_csg_views_with_one_interval_showing(shape, eye):
    # views where no visible point depends on the torus's second interval along the ray
    scene = Scene(Camera(eye, (0, 0, 0), width=96, height=96, fov=45), [PointLight((2.0, -3.0, 5.0))], [shape])
    _render_compare(scene)


@pytest.mark.parametrize("eye", [(-5.0, 0.3, 0.8), (-5.0, -1.0, 0.2)], ids=["edge", "low"])
def test_render_csg_second_interval(eye):
    # the visible point is the entry of the torus's second interval (through the hole, the first
    # interval cut away): the torus takes part in the per-pixel CSG with both its intervals
    shape = Torus(**FLAT) - Box((-2.0, 0.0, 0.0), (4.0, 5.0, 2.0))  # the near half cut away
    scene = Scene(Camera(eye, (0, 0, 0), width=96, height=96, fov=45), [PointLight((-2.0, -3.0, 5.0))], [shape])
    _render_compare(scene)


_HALF_CUT = Box((-2.0, 0.0, 0.0), (4.0, 5.0, 2.0))


@pytest.mark.parametrize(
    "shape, eye, light",
    [
        (Torus(**FLAT) - _HALF_CUT, (-5.0, 0.3, 0.0), (-2.0, -3.0, 5.0)),
        (Torus(**FLAT) - _HALF_CUT, (-5.0, 0.5, 0.6), (0.01, 0.02, 5.0)),
        (Torus(**FLAT) & isocsg.Sphere((0.0, 0.0, 0.0), 1.6), (5.0, 0.4, 0.0), (0.02, 0.0, 4.0)),
        (Torus(**FLAT) & isocsg.Sphere((-1.0, 0.0, 0.0), 1.3), (4.0, -1.5, 1.0), (2.0, -3.0, 5.0)),
        (Box((0.0, 0.0, 0.0), (4.0, 4.0, 0.6)) - Torus(**FLAT), (3.0, -4.0, 1.5), (0.0, 0.01, 5.0)),
        (Box((0.0, 0.0, 0.0), (4.0, 4.0, 0.6)) - Torus(**FLAT), (-5.0, 0.2, 0.0), (1.0, -2.0, 4.0)),
        (Torus(**TILTED) - Box((-1.0, 0.2, 0.3), (2.0, 3.0, 2.0)), (-4.0, 0.5, 1.0), (-2.0, -3.0, 5.0)),
    ],
    ids=["minus-box-eye-in-plane", "minus-box-light-on-axis", "and-sphere-eye-in-plane", "and-sphere-oblique",
         "box-minus-torus-light-on-axis", "box-minus-torus-eye-in-plane", "tilted-minus-box"],
)
def test_render_csg_both_intervals(shape, eye, light):
    # views where visible points lie on the torus's inner surfaces (the exit of the first interval,
    # the entry of the second) against the reference caster's own torus intervals
    scene = Scene(Camera(eye, (0, 0, 0), width=96, height=96, fov=45), [PointLight(light)], [shape])
    _render_compare(scene)


@pytest.mark.parametrize(
    "camera",
    [
        Camera((-5.0, 0.3, 0.8), (0, 0, 0), width=96, height=96, orthographic=True),
        Camera((1.5, -0.1, 0.05), (0.0, 1.5, 0.0), width=96, height=96, fov=60),  # the eye inside the tube
    ],
    ids=["orthographic", "eye-inside"],
)
def test_render_csg_both_intervals_cameras(camera):
    shape = Torus(**FLAT) - (_HALF_CUT if camera.orthographic else Box((0.0, 2.0, 0.0), (1.0, 1.0, 3.0)))
    _render_compare(Scene(camera, [PointLight((0.5, 0.5, 3.0))], [shape]))


@pytest.mark.parametrize(
    "shape, eye",
    [
        (Torus(**FLAT) - _HALF_CUT, (-5.0, 0.3, 0.8)),
        ((Torus(**FLAT) - _HALF_CUT) | isocsg.Sphere((0.0, 0.0, 0.0), 0.3), (-5.0, -1.0, 0.2)),
        (Box((0.0, 0.0, 0.0), (4.0, 4.0, 0.6)) - Torus(**FLAT), (3.0, -4.0, 1.5)),
    ],
    ids=["minus-box", "with-a-union", "box-minus-torus"],
)
def test_render_csg_both_intervals_in_tiles(shape, eye, monkeypatch):
    # the same through the tiled path (screen tiles, groups of equal leaves)
    from isocsg.rendering import policy

    monkeypatch.setattr(policy, "DENSE_MAX_LEAVES", 0)
    scene = Scene(Camera(eye, (0, 0, 0), width=160, height=128, fov=45), [PointLight((-2.0, -3.0, 5.0))], [shape])
    image = isocsg.Renderer(csg="pixel").render(scene, contours=64).image
    result = compare(image, raycast_scene(scene))
    assert result.iou >= MIN_IOU and result.fraction >= MIN_FRACTION, result.summary()


def test_render_csg_layers_keep_the_bands():
    # the torus's inner surfaces take its band values (isoluminance), not smooth shading: the
    # image takes few distinct values on the torus
    shape = Torus(**FLAT) - Box((-2.0, 0.0, 0.0), (4.0, 5.0, 2.0))
    scene = Scene(Camera((-5.0, 0.3, 0.8), (0, 0, 0), width=96, height=96, fov=45), [PointLight((-2.0, -3.0, 5.0))],
                  [shape])
    result = isocsg.render(scene, contours=8)
    shown = result.image[result.primitive_index == 0]
    assert len(shown) > 500
    assert len(np.unique(shown)) <= 64


# ----------------------------------------------------------------------------- shadows


def test_shadows_against_monte_carlo():
    t = Torus((0.0, 0.0, 1.0), (0.2, 0.0, 1.0), 0.6, 0.2)
    light = isocsg.AreaLight([(-1.0, -1.0, 3.0), (-1.0, 1.0, 3.0), (1.0, 1.0, 3.0), (1.0, -1.0, 3.0)], radiance=1.0)
    points = np.array([[0.0, 0.0, 0.0], [0.6, 0.1, 0.0], [-0.7, -0.3, 0.0], [1.4, 0.2, 0.0]])
    normal = np.array([0.0, 0.0, 1.0])
    got = isocsg.illuminance(points, normal, light, [t], resolution=256)
    m = 300
    g = (np.stack(np.meshgrid(np.arange(m), np.arange(m), indexing="ij"), -1).reshape(-1, 2) + 0.5) / m
    samples = np.column_stack([-1.0 + 2.0 * g[:, 0], -1.0 + 2.0 * g[:, 1], np.full(len(g), 3.0)])
    ref, err = [], []
    for p in points:
        v = samples - p
        d2 = (v * v).sum(1)
        iv = torus_intervals(t, np.broadcast_to(p, samples.shape), v)  # t in [0, 1] is the segment
        blocked = np.any((iv[:, :, 1] > 0) & (iv[:, :, 0] < 1), axis=1)
        f = ~blocked * (v[:, 2] / np.sqrt(d2)) ** 2 / d2
        ref.append(4.0 * float(np.mean(f)))
        err.append(4.0 * float(np.std(f)) / math.sqrt(len(f)))
    ref_a, err_a = np.asarray(ref), np.asarray(err)
    assert np.all(ref_a[:3] < isocsg.illuminance(points[:3], normal, light))  # shadowed
    # within the Monte Carlo confidence (stratified: the std bound is generous) and the
    # occluder pieces' documented tessellation error
    assert np.all(np.abs(got - ref_a) <= 3 * err_a + 5e-3 * ref_a + 1e-4), (got, ref_a, err_a)


def test_shadows_in_a_tree():
    t = Torus((0.0, 0.0, 1.0), (0.0, 0.0, 1.0), 0.6, 0.2)
    cut = t - Box((-1.0, 0.0, 1.0), (2.0, 2.0, 1.0))  # the half at x < 0 cut away
    light = isocsg.AreaLight([(-1.0, -1.0, 3.0), (-1.0, 1.0, 3.0), (1.0, 1.0, 3.0), (1.0, -1.0, 3.0)], radiance=1.0)
    points = np.array([[0.6, 0.0, 0.0], [-0.6, 0.0, 0.0]])
    free = isocsg.illuminance(points, (0.0, 0.0, 1.0), light)
    whole = isocsg.illuminance(points, (0.0, 0.0, 1.0), light, [t])
    got = isocsg.illuminance(points, (0.0, 0.0, 1.0), light, [cut])
    assert got[0] == pytest.approx(whole[0], rel=1e-9)  # under the kept half
    assert whole[1] < got[1] == pytest.approx(free[1], rel=1e-9)  # under the cut half: the far half casts no shadow here


def test_convex_pieces():
    t = Torus(**TILTED)
    pieces = t.convex_pieces(64)
    assert len(pieces) == 32
    verts = np.vstack([np.asarray(p.vertices) for p in pieces])
    assert np.max(np.abs(t.signed_distance(verts))) < 1e-12
    # inside the documented bound: points of the pieces are at most (R - r)(1 - cos(pi / m)) outside
    m = 32
    bound = (t.major - t.minor) * (1 - math.cos(math.pi / m))
    for p in pieces[:4]:
        hv = np.asarray(p.hull_vertices)
        mids = 0.5 * (hv[:, None, :] + hv[None, :, :]).reshape(-1, 3)
        assert np.max(t.signed_distance(mids)) <= bound + 1e-12


# ----------------------------------------------------------------------------- files and transforms


def test_scene_file_round_trip(tmp_path):
    t = Torus(**TILTED)
    scene = Scene(Camera((3.0, -3.5, 2.5), (0, 0, 0), width=32, height=32), [PointLight((3.0, -1.0, 4.0))],
                  [t, t - isocsg.Sphere((1.0, 0.0, 0.0), 0.3)])
    again = isocsg.load_scene(isocsg.save_scene(scene, tmp_path / "torus.toml"))
    assert again.objects[0].shape == t
    assert again.objects[1].shape == scene.objects[1].shape
    assert t.to_dict() == {"torus": {"center": list(t.center), "axis": list(t.axis), "major": 1.0, "minor": 0.3}}
    text = (tmp_path / "torus.toml").read_text()
    bad = text.replace("minor = 0.3", "minor = 3.0", 1)
    with pytest.raises(isocsg.SceneFileError, match=re.escape("minor must be < major")):
        isocsg.scene.loads_scene(bad)


def test_openscad_form():
    t = Torus(**FLAT)
    assert t.to_openscad() == (
        "multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
        "{ rotate_extrude() translate([1.5, 0]) circle(r = 0.5); }"
    )
    assert "rotate_extrude" in Torus(**TILTED).to_openscad(6)


def test_transforms():
    t = Torus(**TILTED)
    moved = t.translate((1.0, 2.0, 3.0)).rotate((0.0, 0.0, 90.0)).scale(2.0)
    assert isinstance(moved, Torus)
    assert moved.major == pytest.approx(2.0) and moved.minor == pytest.approx(0.6)
    assert moved.volume == pytest.approx(8 * t.volume)
    p = np.asarray(t.to_trimesh(32).vertices[:50])
    q = ((p + [1.0, 2.0, 3.0]) @ np.array([[0, -1, 0], [1, 0, 0], [0, 0, 1.0]]).T) * 2.0
    assert np.max(np.abs(moved.signed_distance(q))) < 1e-12
    assert isinstance(t.mirror((1.0, 0.0, 0.0)), Torus)
    with pytest.raises(InvalidGeometryError, match="non-uniform scale"):
        t.scale((1.0, 2.0, 1.0))


def test_openscad_six_digit_turns_keep_a_torus() -> None:
    """OpenSCAD's .csg export writes rotate([0, 0, 30]) as a matrix of 6 digits (orthogonal to ~1e-6):
    the torus under it loads, its volume Pappus' 2 pi^2 R r^2, its axis the turned one; a real
    shear is still refused."""
    import math as _math

    import isocsg as _isocsg

    c, s = 0.866025, 0.5  # as OpenSCAD 2021.01 prints cos 30 and sin 30
    text = (f"multmatrix([[1, 0, 0, 0], [0, {c}, -{s}, 0], [0, {s}, {c}, 0], [0, 0, 0, 1]]) "
            "rotate_extrude($fn = 0, $fa = 12, $fs = 2) translate([10, 0, 0]) circle(r = 2);")
    solid = _isocsg.loads_openscad(text)
    assert _math.isclose(_isocsg.volume(solid), 2 * _math.pi**2 * 10 * 2**2, rel_tol=1e-5)
    assert np.allclose(solid.axis_array, [0, -0.5, 0.866025], atol=1e-6)
    with pytest.raises(_isocsg.errors.OpenSCADError, match="non-uniform scale or shear"):
        _isocsg.loads_openscad("multmatrix([[1, 0.001, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
                               "rotate_extrude() translate([10, 0, 0]) circle(r = 2);")
