"""The analytic reference ray caster against closed forms and hand-computed values.

The reference judges every rendering path, so it is itself checked here
against quantities worked out by hand: camera rays, projected sphere
silhouettes, intensities where the normal faces the light, hit depths and
normals of every primitive kind (including cones hit along a generator and
rays parallel to an axis), and CSG identities and reversed normals.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

from isocsg import (
    Box,
    Camera,
    Cone,
    ConvexPolyhedron,
    Cylinder,
    DirectionalLight,
    Material,
    PointLight,
    Scene,
    SceneObject,
    Sphere,
    Truncus,
    intersection,
    union,
)

# the shared helpers live next to the tests (pytest runs with --import-mode=importlib)
sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference import camera_rays, compare, primitive_intervals, raycast, silhouette_iou
from reference.raycaster import PART_CAP1, PART_CAP2, PART_LATERAL, SIDE_ENTRY, SIDE_EXIT, first_hit
from scenes import ALL_SCENES, CSG_SCENES

S2, S3, S5 = math.sqrt(2), math.sqrt(3), math.sqrt(5)


# ----------------------------------------------------------------------------- camera


def test_camera_rays_hand_computed() -> None:
    # eye at the origin looking along +y, fov 90 (tan 45 = 1), 2 x 2 pixels:
    # f = (0, 1, 0), r = f x z = (1, 0, 0), u = r x f = (0, 0, 1); pixel (0, 0) has x = -0.5, y = 0.5
    cam = Camera((0, 0, 0), (0, 1, 0), fov=90, width=2, height=2)
    o, d = camera_rays(cam)
    expected = {
        (0, 0): (-0.5, 1, 0.5), (0, 1): (0.5, 1, 0.5), (1, 0): (-0.5, 1, -0.5), (1, 1): (0.5, 1, -0.5),
    }
    for (i, j), v in expected.items():
        np.testing.assert_allclose(d[i, j], np.array(v) / np.linalg.norm(v), atol=1e-15)
    np.testing.assert_array_equal(o, 0.0)


def test_camera_rays_aspect_and_centre() -> None:
    # 3 x 1 pixels, fov 90: the centre pixel looks at the target, the side ones at x = +-2/3 * 3 = +-... (W/H = 3)
    cam = Camera((1, 2, 3), (1, 2, 0), up=(0, 1, 0), fov=90, width=3, height=1)
    _, d = camera_rays(cam)
    # f = (0, 0, -1), r = f x up = (1, 0, 0), u = r x f = (0, 1, 0); x_j = (2 (j + .5) / 3 - 1) * 3 = -2, 0, 2
    np.testing.assert_allclose(d[0, 1], [0, 0, -1], atol=1e-15)
    np.testing.assert_allclose(d[0, 0], np.array([-2, 0, -1]) / S5, atol=1e-15)
    np.testing.assert_allclose(d[0, 2], np.array([2, 0, -1]) / S5, atol=1e-15)


# ----------------------------------------------------------------------------- sphere silhouette and shading


@pytest.mark.parametrize("dist,radius,size", [(5.0, 1.0, 161), (3.0, 1.3, 120), (8.0, 0.5, 200)],
                         ids=["d5_r1", "d3_r1.3", "d8_r0.5"])
def test_sphere_silhouette_is_the_projected_cone(dist: float, radius: float, size: int) -> None:
    # a pixel sees the sphere iff its ray makes an angle <= asin(R / D) with the axis eye-centre
    eye = np.array([0.3, -dist, 0.2])
    centre = eye + dist * np.array([0.0, 1.0, 0.0])
    cam = Camera(tuple(eye), tuple(centre + [0.1, 0, -0.05]), fov=40, width=size, height=size)
    ref = raycast(cam, [(Sphere(tuple(centre), radius), Material())], [DirectionalLight((0, 0, 1))])
    _, d = camera_rays(cam)
    cos_angle = d @ ((centre - eye) / dist)
    alpha = math.asin(radius / dist)
    inside = cos_angle > math.cos(alpha) + 1e-12
    outside = cos_angle < math.cos(alpha) - 1e-12
    assert np.all(ref.mask[inside]) and not np.any(ref.mask[outside])
    # the silhouette's radius in pixels along the central column, from the exact cone angle
    cam0 = Camera(tuple(eye), tuple(centre), fov=40, width=size, height=size)
    ref0 = raycast(cam0, [(Sphere(tuple(centre), radius), Material())], [DirectionalLight((0, 0, 1))])
    # ray (x, 1, y) in the camera frame is inside the cone iff x^2 + y^2 <= tan(alpha)^2
    tan20 = math.tan(math.radians(20))
    y = (1 - 2 * (np.arange(size) + 0.5) / size) * tan20
    x = (2 * (size // 2 + 0.5) / size - 1) * tan20
    expected = np.count_nonzero(x * x + y * y <= math.tan(alpha) ** 2)
    assert np.count_nonzero(ref0.mask[:, size // 2]) == expected


@pytest.mark.parametrize("ks", [0.0, 0.5], ids=["diffuse", "specular"])
def test_point_facing_light_is_ambient_plus_kd(ks: float) -> None:
    # odd image: the centre pixel sees the point of the sphere facing the eye and the light
    mat = Material(ambient=0.15, kd=0.7, ks=ks, shininess=20)
    cam = Camera((0, -6, 0), (0, 0, 0), width=41, height=41)
    for light in (DirectionalLight((0, -3, 0)), PointLight((0, -20, 0))):
        ref = raycast(cam, [(Sphere((0, 0, 0), 1.0), mat)], [light])
        assert ref.image[20, 20] == pytest.approx(0.15 + 0.7 + ks, abs=1e-12)
        assert ref.depth[20, 20] == pytest.approx(5.0, abs=1e-12)
        assert np.nanmax(ref.image) == pytest.approx(0.15 + 0.7 + ks, abs=1e-12)
        assert np.nanmin(ref.image) >= 0.15 - 1e-12


def test_near_point_light_on_sphere_closed_form() -> None:
    # light at distance D on the z axis: cos_i = (D cos(phi) - R) / |P - p| at polar angle phi
    radius, dist = 1.0, 3.0
    cam = Camera((6, 0, 0), (0, 0, 0), width=61, height=61)
    ref = raycast(cam, [(Sphere((0, 0, 0), radius), Material())], [PointLight((0, 0, dist))])
    o, d = camera_rays(cam)
    hit = ref.mask
    pts = o + np.where(hit, ref.depth, 0.0)[..., None] * d
    p = pts[hit]
    np.testing.assert_allclose(np.linalg.norm(p, axis=1), radius, atol=1e-12)
    cos_phi = p[:, 2] / radius
    cos_i = np.maximum((dist * cos_phi - radius) / np.linalg.norm([0, 0, dist] - p, axis=1), 0)
    np.testing.assert_allclose(ref.image[hit], 0.1 + 0.8 * cos_i, atol=1e-12)
    # the terminator is the circle cos(phi) = R / D
    lit = ref.image[hit] > 0.1 + 1e-9
    np.testing.assert_array_equal(lit, cos_phi > radius / dist + 1e-12)


def test_two_lights_and_intensity_multipliers_add() -> None:
    cam = Camera((0, -6, 0), (0, 0, 0), width=21, height=21)
    mat = Material(ambient=0.2, kd=0.5)
    both = raycast(cam, [(Sphere((0, 0, 0), 1.0), mat)], [DirectionalLight((0, -1, 0)), DirectionalLight((1, 0, 0), 0.5)])
    # centre pixel: normal (0, -1, 0) -> first light cos 1, second cos 0; pixel right of centre sees n.x > 0
    assert both.image[10, 10] == pytest.approx(0.2 + 0.5, abs=1e-12)
    n = both.normal[10, 14]
    assert both.image[10, 14] == pytest.approx(0.2 + 0.5 * max(-n[1], 0) + 0.5 * 0.5 * max(n[0], 0), abs=1e-12)


# ----------------------------------------------------------------------------- primitive intervals


def _one(prim, origin, direction):
    iv = primitive_intervals(prim, [origin], [direction])
    return iv.t_in[0], iv.t_out[0], iv.n_in[0], iv.n_out[0], iv.part_in[0], iv.part_out[0]


CYL = Cylinder((0, 0, 0), (0, 0, 2), 1.0)
CONE = Cone((0, 0, 0), (0, 0, -2), 1.0)  # base r 1 at z = -1 (E1), apex at z = +1 (E2)
FRUSTUM = Truncus((0, 0, 0), (0, 0, 2), 0.5, 1.0)  # r 0.5 at z = +1, r 1 at z = -1
DISC = Truncus((1, 2, 3), (0, 0.1, 0), 2.0, 2.0)
TETRA = ConvexPolyhedron([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)])

HIT_CASES = [
    # primitive, origin, direction, t_in, t_out, n_in, n_out, part_in, part_out
    ("cylinder_side", CYL, (-5, 0, 0), (1, 0, 0), 4, 6, (-1, 0, 0), (1, 0, 0), PART_LATERAL, PART_LATERAL),
    ("cylinder_along_axis", CYL, (0.5, 0, 5), (0, 0, -1), 4, 6, (0, 0, 1), (0, 0, -1), PART_CAP1, PART_CAP2),
    ("cylinder_cap_then_side", CYL, (-0.5, 0, 1.5), (1 / S2, 0, -1 / S2), 0.5 * S2, 1.5 * S2, (0, 0, 1), (1, 0, 0),
     PART_CAP1, PART_LATERAL),
    ("cone_side", CONE, (-5, 0, 0), (1, 0, 0), 4.5, 5.5, (-1 / math.sqrt(1.25), 0, 0.5 / math.sqrt(1.25)),
     (1 / math.sqrt(1.25), 0, 0.5 / math.sqrt(1.25)), PART_LATERAL, PART_LATERAL),
    ("cone_down_axis_through_apex", CONE, (0, 0, 5), (0, 0, -1), 4, 6, None, (0, 0, -1), None, PART_CAP1),
    # parallel to the right generator (1, 0, -2): enters through the left side at (-0.25, 0, 0.5), leaves the base
    ("cone_parallel_to_generator", CONE, (-1, 0, 2), (1 / S5, 0, -2 / S5), 0.75 * S5, 1.5 * S5,
     (-1 / math.sqrt(1.25), 0, 0.5 / math.sqrt(1.25)), (0, 0, -1), PART_LATERAL, PART_CAP1),
    ("cone_up_axis", CONE, (0, 0, -4), (0, 0, 1), 3, 5, (0, 0, -1), None, PART_CAP1, None),
    ("frustum_side", FRUSTUM, (-5, 0, 0), (1, 0, 0), 4.25, 5.75, (-1 / math.sqrt(1.0625), 0, 0.25 / math.sqrt(1.0625)),
     (1 / math.sqrt(1.0625), 0, 0.25 / math.sqrt(1.0625)), PART_LATERAL, PART_LATERAL),
    ("frustum_parallel_axis", FRUSTUM, (0.7, 0, -3), (0, 0, 1), 2, 2 + 1.2, (0, 0, -1), (1 / math.sqrt(1.0625), 0,
     0.25 / math.sqrt(1.0625)), PART_CAP2, PART_LATERAL),
    ("disc_along_axis", DISC, (1.5, -1, 3), (0, 1, 0), 2.95, 3.05, (0, -1, 0), (0, 1, 0), PART_CAP2, PART_CAP1),
    ("disc_edge_on", DISC, (-4, 2.02, 3), (1, 0, 0), 3, 7, (-1, 0, 0), (1, 0, 0), PART_LATERAL, PART_LATERAL),
    ("box_x", Box((0, 0, 0), (2, 2, 2)), (-5, 0.2, 0.3), (1, 0, 0), 4, 6, (-1, 0, 0), (1, 0, 0), 1, 0),
    # x in [0, 2], y in [-1, 3], z in [-1.5, 3.5]: enters through z = -1.5 at s = 1.5, leaves through x = 2 at s = 3
    ("box_diagonal", Box((1, 1, 1), (2, 4, 5)), (-1, -2, -3), (1 / S3, 1 / S3, 1 / S3), 1.5 * S3, 3 * S3,
     (0, 0, -1), (1, 0, 0), 5, 0),
    ("tetra_z", TETRA, (0.2, 0.2, -1), (0, 0, 1), 1, 1.6, (0, 0, -1), (1 / S3, 1 / S3, 1 / S3), None, None),
    ("tetra_x", TETRA, (-2, 0.25, 0.25), (1, 0, 0), 2, 2.5, (-1, 0, 0), (1 / S3, 1 / S3, 1 / S3), None, None),
    ("sphere", Sphere((1, 1, 1), 2), (1, 1, -4), (0, 0, 2), 1.5, 3.5, (0, 0, -1), (0, 0, 1), 0, 0),
]


@pytest.mark.parametrize("case", HIT_CASES, ids=[c[0] for c in HIT_CASES])
def test_primitive_hits_hand_computed(case) -> None:
    _, prim, o, d, t_in, t_out, n_in, n_out, part_in, part_out = case
    ti, to, ni, no, pi, po = _one(prim, o, d)
    assert ti == pytest.approx(t_in, abs=1e-12) and to == pytest.approx(t_out, abs=1e-12)
    if n_in is not None:
        np.testing.assert_allclose(ni, n_in, atol=1e-12)
    if n_out is not None:
        np.testing.assert_allclose(no, n_out, atol=1e-12)
    if part_in is not None:
        assert pi == part_in
    if part_out is not None:
        assert po == part_out


MISS_CASES = [
    ("cylinder_parallel_outside", CYL, (1.2, 0, 5), (0, 0, -1)),
    ("cylinder_above", CYL, (-5, 0, 1.1), (1, 0, 0)),
    ("cone_other_nappe", CONE, (-5, 0, 2.0), (1, 0, 0)),  # the double cone continues above the apex
    ("cone_beside", CONE, (-5, 0.6, 0), (1, 0, 0)),
    ("frustum_parallel_outside", FRUSTUM, (1.05, 0, -3), (0, 0, 1)),
    ("disc_beside", DISC, (-4, 2.06, 3), (1, 0, 0)),
    ("box_parallel_outside", Box((0, 0, 0), (2, 2, 2)), (-5, 1.5, 0), (1, 0, 0)),
    ("tetra_behind_face", TETRA, (0.6, 0.6, -1), (0, 0, 1)),
    ("sphere_tangent_plus", Sphere((0, 0, 0), 1), (-5, 1.001, 0), (1, 0, 0)),
]


@pytest.mark.parametrize("case", MISS_CASES, ids=[c[0] for c in MISS_CASES])
def test_primitive_misses(case) -> None:
    _, prim, o, d = case
    iv = primitive_intervals(prim, [o], [d])
    assert not iv.hit[0]
    assert iv.t_in[0] == np.inf and iv.t_out[0] == -np.inf


def _inside(prim, p):
    """Closed-form point membership, written for this test."""
    p = np.asarray(p, dtype=float)
    if isinstance(prim, Sphere):
        return np.linalg.norm(p - prim.center, axis=-1) <= prim.radius
    if isinstance(prim, Truncus):
        a = np.asarray(prim.axis, float)
        h = np.linalg.norm(a)
        a = a / h
        rel = p - prim.center
        s = rel @ a
        rho = np.linalg.norm(rel - s[..., None] * a, axis=-1)
        return (np.abs(s) <= h / 2) & (rho <= prim.r2 + (prim.r1 - prim.r2) * (s / h + 0.5))
    if isinstance(prim, Box):
        return np.all(np.abs(p - prim.center) <= np.asarray(prim.size) / 2, axis=-1)
    raise TypeError(type(prim))


@pytest.mark.parametrize(
    "prim",
    [Sphere((0.1, 0.2, 0.0), 0.9), CYL, CONE, FRUSTUM, Truncus((0.2, 0, 0.1), (0.8, 0.3, 1.4), 0.2, 0.9),
     Box((0.1, 0, 0), (1.5, 1, 1.2))],
    ids=["sphere", "cylinder", "cone", "frustum", "tilted_frustum", "box"],
)
def test_intervals_agree_with_point_membership(prim) -> None:
    # random rays: points inside (t_in, t_out) are inside the solid and points outside are outside
    rng = np.random.default_rng(7)
    n = 4000
    o = rng.normal(size=(n, 3))
    o *= 4 / np.linalg.norm(o, axis=1, keepdims=True)
    d = rng.uniform(-1.3, 1.3, size=(n, 3)) - o  # t = 1 at a random point near the solid
    iv = primitive_intervals(prim, o, d)
    assert 0.2 < iv.hit.mean() < 0.95
    ts = np.linspace(-0.5, 2.5, 1201)
    pts = o[:, None, :] + ts[None, :, None] * d[:, None, :]
    member = _inside(prim, pts)
    tin, tout = iv.t_in[:, None], iv.t_out[:, None]
    margin = 1e-9
    claimed_in = (ts > tin + margin) & (ts < tout - margin)
    claimed_out = (ts < tin - margin) | (ts > tout + margin)
    assert np.all(member[claimed_in])
    assert not np.any(member[claimed_out & np.isfinite(tin)])
    assert not np.any(member[~iv.hit])


# ----------------------------------------------------------------------------- CSG


CAM = Camera((1.2, -4, 2.5), (0, 0, 0), width=90, height=90)
LIGHTS = [PointLight((3, -4, 5)), DirectionalLight((-1, -0.5, 0.3), 0.4)]


@pytest.mark.parametrize(
    "a",
    [Sphere((0, 0, 0), 1), Cylinder((0, 0, 0), (0.3, 0.2, 1.5), 0.7), Box((0, 0, 0), (1, 1.5, 1)),
     ConvexPolyhedron([(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)])],
    ids=["sphere", "cylinder", "box", "octahedron"],
)
def test_csg_identities(a) -> None:
    alone = raycast(CAM, [(a, Material())], LIGHTS)
    assert alone.mask.any()
    assert not raycast(CAM, [(a - a, Material())], LIGHTS).mask.any()
    for same in (a | a, a & a, a | a | a):
        r = raycast(CAM, [(same, Material())], LIGHTS)
        np.testing.assert_array_equal(r.mask, alone.mask)
        np.testing.assert_allclose(r.image[r.mask], alone.image[alone.mask], atol=1e-12)
        np.testing.assert_array_equal(r.side, alone.side)


def test_csg_commutes_and_matches_interval_algebra() -> None:
    a = Sphere((0, 0, 0), 1.0)
    b = Box((0.4, -0.3, 0.2), (1.2, 1.0, 1.4))
    ab = raycast(CAM, [(a & b, Material())], LIGHTS)
    ba = raycast(CAM, [(b & a, Material())], LIGHTS)
    np.testing.assert_array_equal(ab.mask, ba.mask)
    np.testing.assert_allclose(ab.depth[ab.mask], ba.depth[ba.mask], atol=1e-12)
    np.testing.assert_allclose(ab.image[ab.mask], ba.image[ba.mask], atol=1e-12)
    # A & B = A - (A - B); A | B visible depth = min of both
    amb = raycast(CAM, [(a - (a - b), Material())], LIGHTS)
    np.testing.assert_array_equal(amb.mask, ab.mask)
    np.testing.assert_allclose(amb.depth[ab.mask], ab.depth[ab.mask], atol=1e-12)
    u = raycast(CAM, [(a | b, Material())], LIGHTS)
    sa = raycast(CAM, [(a, Material())], LIGHTS)
    sb = raycast(CAM, [(b, Material())], LIGHTS)
    np.testing.assert_allclose(u.depth, np.minimum(sa.depth, sb.depth), atol=1e-12)


def test_ray_through_sphere_minus_cylinder_sees_reversed_normal() -> None:
    # from (0, 0, 3) towards (0.4, 0, 0): inside the hole until it meets the hole's wall at (0.4, 0, 0)
    solid = Sphere((0, 0, 0), 1.0) - Cylinder((0, 0, 0), (0, 0, 4), 0.4)
    d = np.array([0.4, 0, -3.0])
    fh = first_hit(solid, [(0, 0, 3)], [d / np.linalg.norm(d)])
    assert fh.t[0] == pytest.approx(np.linalg.norm(d), abs=1e-12)
    assert fh.leaf[0] == 1 and fh.side[0] == SIDE_EXIT and fh.part[0] == PART_LATERAL
    np.testing.assert_allclose(fh.normal[0], [-1, 0, 0], atol=1e-12)
    # the same ray off the hole's axis sees the sphere first, from outside
    fh2 = first_hit(solid, [(0, 0.8, 3)], [(0, 0, -1)])
    assert fh2.leaf[0] == 0 and fh2.side[0] == SIDE_ENTRY
    assert fh2.t[0] == pytest.approx(3 - math.sqrt(1 - 0.64), abs=1e-12)
    # shading uses the reversed normal: a light along -x lights the wall fully
    cam = Camera((0, 0, 3), (0.4, 0, 0), width=3, height=3, fov=1)
    ref = raycast(cam, [(solid, Material())], [DirectionalLight((-1, 0, 0))])
    assert ref.image[1, 1] == pytest.approx(0.9, abs=1e-12)
    assert ref.side[1, 1] == SIDE_EXIT


def _inside_tree(solid, p):
    from isocsg import Difference, Intersection, Union

    if isinstance(solid, Union):
        return np.logical_or.reduce([_inside_tree(c, p) for c in solid.children])
    if isinstance(solid, Intersection):
        return np.logical_and.reduce([_inside_tree(c, p) for c in solid.children])
    if isinstance(solid, Difference):
        out = _inside_tree(solid.children[0], p)
        for c in solid.children[1:]:
            out = out & ~_inside_tree(c, p)
        return out
    return _inside(solid, p)


@pytest.mark.parametrize("name", [n for n in CSG_SCENES if n != "frustum_and_polyhedron"], ids=str)
def test_csg_first_hit_agrees_with_dense_sampling(name: str) -> None:
    # along sampled pixel rays: the point just past the hit is inside the tree, points before it are outside
    scene = CSG_SCENES[name]
    o, d = camera_rays(scene.camera)
    sel = np.random.default_rng(3).choice(o.shape[0] * o.shape[1], 400, replace=False)
    o, d = o.reshape(-1, 3)[sel], d.reshape(-1, 3)[sel]
    for ob in scene.objects:
        fh = first_hit(ob.shape, o, d)
        ts = np.linspace(0.5, 12, 2000)
        pts = o[:, None, :] + ts[None, :, None] * d[:, None, :]
        member = _inside_tree(ob.shape, pts)
        before = ts[None, :] < fh.t[:, None] - 1e-9
        assert not np.any(member & before)
        hit = fh.hit
        if hit.any():
            after = o[hit] + (fh.t[hit] + 1e-7)[:, None] * d[hit]
            assert np.all(_inside_tree(ob.shape, after))
            at = o[hit] + (fh.t[hit] - 1e-7)[:, None] * d[hit]
            assert not np.any(_inside_tree(ob.shape, at))
            # the shading normal points towards the outside: a small step back along it leaves the solid
            nudge = o[hit] + fh.t[hit][:, None] * d[hit] + 1e-6 * fh.normal[hit]
            assert not np.any(_inside_tree(ob.shape, nudge))


def test_empty_difference_scene_is_background() -> None:
    ref = raycast(CSG_SCENES["difference_leaves_nothing"].camera,
                  [(o.shape, o.material) for o in CSG_SCENES["difference_leaves_nothing"].objects], [])
    assert not ref.mask.any() and np.all(np.isnan(ref.image))


# ----------------------------------------------------------------------------- metrics


def test_metrics_on_known_perturbations() -> None:
    ref = raycast(CAM, [(Sphere((0, 0, 0), 1), Material())], LIGHTS)
    same = compare(ref.image, ref)
    assert same.iou == 1.0 and same.fraction == 1.0 and same.mean_error == 0.0
    lo, hi = np.nanmin(ref.image), np.nanmax(ref.image)
    shifted = compare(ref.image + 0.06 * (hi - lo), ref)
    assert shifted.fraction == 0.0 and shifted.mean_error == pytest.approx(0.06 * (hi - lo))
    inside = compare(ref.image + 0.04 * (hi - lo), ref)
    assert inside.fraction == 1.0
    # removing one row of object pixels lowers the IoU by exactly that share
    cut = ref.image.copy()
    row = int(np.argmax(ref.mask.sum(axis=1)))
    removed = int(ref.mask[row].sum())
    cut[row] = np.nan
    assert silhouette_iou(cut, ref.image) == pytest.approx(1 - removed / ref.mask.sum())
    assert silhouette_iou(np.full((3, 3), np.nan), np.full((3, 3), np.nan)) == 1.0


def test_catalogue_scenes_render_and_only_the_empty_one_is_empty() -> None:
    # every catalogue scene renders, and only the difference that leaves nothing is empty
    for name, scene in ALL_SCENES.items():
        ref = raycast(scene.camera, [(o.shape, o.material) for o in scene.objects], scene.lights)
        assert ref.image.shape == (scene.camera.height, scene.camera.width)
        assert ref.mask.any() == (name != "difference_leaves_nothing"), name


@pytest.mark.parametrize("orthographic", [False, True], ids=["perspective", "orthographic"])
def test_tiled_reference_equals_untiled_first_hits(orthographic: bool) -> None:
    # Leaves spread over the image, so that screen tiles cull most of them; parallel rays
    # (orthographic) must be culled by a slab, not by the perspective pyramid.
    from reference import raycast_scene

    grid = [Sphere((x, 0.0, z), 0.22) for x in (-1.2, -0.4, 0.4, 1.2) for z in (-1.2, -0.4, 0.4, 1.2)]
    solid = union(
        *grid, Box((-1.0, 0.2, -0.7), (0.5, 0.6, 0.4)),
        intersection(Cylinder((0.3, -0.9, -1.0), (0.2, 0.1, 1.4), 0.5), Box((0.3, -0.9, 0.0), (1.2, 1.2, 1.0))),
    )
    if orthographic:
        cam = Camera((0.8, -7.2, -3.1), (0, 0, 0), (0, 0, 1), width=96, height=96, orthographic=True, height_m=3.2)
    else:
        cam = Camera((0.8, -7.2, -3.1), (0, 0, 0), (0, 0, 1), fov=26.0, width=96, height=96)
    scene = Scene(cam, (PointLight((5.0, -6.0, 4.0)),), (SceneObject(solid, Material()),))
    o, d = camera_rays(cam)
    direct = first_hit(solid, o.reshape(-1, 3), d.reshape(-1, 3)).hit.reshape(96, 96)
    ref = raycast_scene(scene)
    assert direct.sum() > 500
    assert np.array_equal(ref.mask, direct)


@pytest.mark.parametrize("scale", [1.0, 689.0], ids=["unit", "689"])
def test_face_in_a_point_lights_plane_is_ambient(scale: float) -> None:
    # The face z = 0 of this tetrahedron holds the light: n . l = 0 there, so no diffuse term and
    # no highlight (conventions: Phong only where cos_i > 0). Hit points a few ulps off the plane
    # used to light random pixels with the full grazing highlight (-l . v)^s.
    poly = ConvexPolyhedron(scale * np.array([(0, 0, 1.0), (0, 1.0, 0), (0, -1.0, 0), (1.0, 0, 0), (0.2, 0.2, -0.0)]))
    mat = Material(ambient=0.125, kd=0.5, ks=0.2, shininess=2.0)
    cam = Camera(tuple(scale * np.array([0.3, 2.5, -1.66])), (0, 0, 0), width=48, height=48, fov=50)
    ref = raycast(cam, [(poly, mat)], [PointLight((0.0, -1.5 * scale, 0.0))])
    on_face = ref.mask & (np.abs(ref.normal[..., 2] + 1.0) < 1e-12)
    assert on_face.sum() > 100
    assert np.all(ref.image[on_face] == 0.125)
