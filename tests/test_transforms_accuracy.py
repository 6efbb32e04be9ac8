"""Transformed primitives and ellipsoids against the independent references.

- Images: renderings at N = 64 against the analytic ray caster of ``tests/reference``
  (which intersects turned boxes, ellipsoids and elliptic trunci in their own frames
  from their fields), with the catalogue's bars: silhouette IoU >= 0.99 and >= 98 % of
  the compared pixels within 5 % of the exact image's range; the error shrinks with N.
- Hypothesis-drawn transforms of every kind (derandomised under ``CI``;
  ``ISOCSG_SEARCH_EXAMPLES`` examples per kind for longer runs, as in
  ``test_accuracy_random.py``; ``ISOCSG_SEARCH_LOG=file`` appends one line per passing example).
- Volumes and sections against closed forms (4/3 pi a b c, pi a b h, ellipses) and manifold3d.
- Shadows of transformed occluders against the Monte Carlo estimator (``tests/mc_reference.py``).
"""

from __future__ import annotations

import math
import os
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, currently_in_test_context, given, note, settings
from hypothesis import strategies as st

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference import compare, comparison_mask, fraction_within, raycast_scene  # noqa: E402
from reference.ties import silhouette_ties  # noqa: E402
from scenes import render_image  # noqa: E402

from isocsg import (  # noqa: E402
    Box,
    Camera,
    Cone,
    ConvexPolyhedron,
    Cylinder,
    DirectionalLight,
    Ellipsoid,
    EllipticTruncus,
    Material,
    PointLight,
    RenderSettings,
    Scene,
    SceneObject,
    Sphere,
    Truncus,
)
from isocsg.csg.mesh import to_manifold  # noqa: E402
from isocsg.csg.section import section  # noqa: E402
from isocsg.csg.volume import volume  # noqa: E402

MIN_IOU = 0.99
MIN_FRACTION = 0.98
#: As in test_accuracy_random.py: a pixel centre whose exact hit flips when the camera moves by
#: this fraction of a pixel is a tie (closer to the silhouette than the band mesh's chords can be
#: judged), and at most MAX_TIE_FRACTION of a silhouette may be ties.
TIE_PIXELS = 0.01
MAX_TIE_FRACTION = 0.02
CONTOURS = 64
EXAMPLES = int(os.environ.get("ISOCSG_SEARCH_EXAMPLES", "6"))
#: A file that gets one line per judged example (for counting a long search).
LOG = os.environ.get("ISOCSG_SEARCH_LOG")
SEARCH = settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def rx(a):
    c, s = math.cos(math.radians(a)), math.sin(math.radians(a))
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def rz(a):
    c, s = math.cos(math.radians(a)), math.sin(math.radians(a))
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def affine(A, t=(0.0, 0.0, 0.0)):
    m = np.eye(4)
    m[:3, :3] = A
    m[:3, 3] = t
    return m


def scene_of(prim, lights, eye, *, target=(0.0, 0.0, 0.0), material=None, contours=CONTOURS, size=96):
    lo, hi = prim.bounds
    radius = 0.5 * float(np.linalg.norm(hi - lo))
    fov = math.degrees(2 * math.atan(1.3 * radius / np.linalg.norm(np.subtract(eye, target))))
    # off the symmetries of the pixel grid (a pixel centre exactly on a silhouette edge is a tie
    # between the renderer and the reference, see test_accuracy_random.py)
    target = np.asarray(target, dtype=float) + radius * 1e-6 * np.array([0.3183, 0.2718, -0.1414])
    view = unit(target - np.asarray(eye, dtype=float))
    up = (0.0, 0.0, 1.0) if abs(view[2]) < 0.95 else (0.0, 1.0, 0.0)
    cam = Camera(tuple(eye), tuple(target), up, fov=fov, width=size, height=size)
    return Scene(cam, tuple(lights), (SceneObject(prim, material or Material()),), RenderSettings(contours=contours))


def judge(scene):
    ref = raycast_scene(scene)
    img = render_image(scene)
    result = compare(img, ref)
    if result.iou < MIN_IOU:
        # judged again without the pixel centres that lie on the silhouette to within TIE_PIXELS
        ties = silhouette_ties(scene, tie_pixels=TIE_PIXELS)
        a, b = np.isfinite(img) & ~ties, np.isfinite(ref.image) & ~ties
        iou = float((a & b).sum() / max((a | b).sum(), 1))
        if currently_in_test_context():
            note(f"{int(ties.sum())} tie pixels; IoU without them {iou:.4f}")
        assert ties.sum() <= MAX_TIE_FRACTION * result.hit_ref and iou >= MIN_IOU, result.summary()
    # (an image whose exact range is below float32 resolution is judged at a few float32 steps)
    assert fraction_within(img, ref, result) >= MIN_FRACTION, result.summary()
    return result


SHEAR = np.array([[1.0, 0.0, 0.6], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
ELL = Ellipsoid((0, 0, 0), (1.5, 1.0, 0.6)).rotate((20, 30, 40))

CATALOGUE = {
    # rotated boxes: a general turn under a near light; the eye in the plane of a face
    "turned box, near light": (Box((0, 0, 0), (1.5, 1.0, 0.6)).rotate((20, 30, 40)), [PointLight((2, -2, 1.5))], (4, -5, 3)),
    "turned box, eye in a face plane": (
        Box((0, 0, 0), (1.5, 1.0, 0.6), rz(30)), [PointLight((2, -2, 2.5))], tuple(rz(30) @ [0.3, -6.0, 0.3])),
    # tilted and unevenly scaled cylinders and cones
    "tilted cylinder": (Cylinder((0, 0, 0), (0, 0, 2), 0.6).rotate((30, 20, 0)), [PointLight((2, -2, 1.5))], (4, -5, 3)),
    "elliptic cylinder": (Cylinder((0, 0, 0), (0, 0, 2), 0.6).scale((1.8, 1, 1)).rotate((30, 20, 10)),
                          [PointLight((2, -2, 1.5))], (4, -5, 3)),
    "elliptic cylinder, eye in an end plane": (Cylinder((0, 0, 0), (0, 0, 1.5), 0.6).scale((1.7, 1, 1)),
                                               [PointLight((1, -2, 2))], (5, -3, 0.75)),
    "oblique cone": (Cone((0, 0, 0), (0, 0, 2), 0.8).transform(affine(SHEAR)).rotate((0, 0, 30)),
                     [DirectionalLight((1, -1, 2))], (4, -5, 3)),
    "sheared frustum, specular": (
        Truncus((0, 0, 0), (0, 0, 1.6), 0.8, 0.4).transform(affine([[1.3, 0.2, 0.3], [0, 0.8, 0], [0.1, 0, 1]])),
        [PointLight((2, -1.5, 1.2))], (4, -5, 3)),
    # ellipsoids: directional, near and far point lights, a light on an axis, the eye in the
    # plane through the centre across the light
    "ellipsoid, directional": (ELL, [DirectionalLight((1, -1, 2))], (4, -5, 3)),
    "ellipsoid, near light": (ELL, [PointLight((1.6, -1.2, 1.0))], (4, -5, 3)),
    "ellipsoid, far light": (ELL, [PointLight((200, -300, 250))], (4, -5, 3)),
    "ellipsoid, light on an axis": (Ellipsoid((0, 0, 0), (1, 1, 2)), [DirectionalLight((0, 0, 1))], (5, 0.3, 0)),
    "ellipsoid, near light on an axis": (Ellipsoid((0, 0, 0), (0.8, 1.2, 2)), [PointLight((0, 0, 2.6))], (5, 1, 1)),
    "ellipsoid, eye in the plane across the light": (ELL, [DirectionalLight((0, 0, 1))], (6, -2, 0)),
    "ellipsoid, two lights, specular": (ELL, [PointLight((2, -2, 2)), DirectionalLight((-1, -1, 0.5))], (4, -5, 3)),
}
MATERIALS = {
    "sheared frustum, specular": Material(0.1, 0.6, 0.3, 20),
    "ellipsoid, two lights, specular": Material(0.1, 0.5, 0.2, 10),
}


@pytest.mark.parametrize("name", list(CATALOGUE), ids=str)
def test_catalogue_matches_reference(name):
    prim, lights, eye = CATALOGUE[name]
    judge(scene_of(prim, lights, eye, material=MATERIALS.get(name)))


@pytest.mark.parametrize("name", ["ellipsoid, near light", "elliptic cylinder, eye in an end plane", "sheared frustum, specular"])
def test_error_shrinks_with_more_contours(name):
    prim, lights, eye = CATALOGUE[name]
    scenes = [scene_of(prim, lights, eye, material=MATERIALS.get(name), contours=n) for n in (16, 64, 256)]
    ref = raycast_scene(scenes[0])
    images = [render_image(s).astype(np.float64) for s in scenes]
    keep = np.logical_and.reduce([comparison_mask(img, ref) for img in images])
    assert keep.sum() > 0.3 * ref.mask.sum()
    errors = [float(np.abs(img[keep] - ref.image[keep]).mean()) for img in images]
    assert errors[0] > errors[1] > errors[2], errors


@pytest.mark.parametrize("csg", ["pixel", "surface"])
def test_csg_of_transformed_parts_matches_reference(csg):
    from isocsg.rendering import Renderer

    part = Box((0, 0, 0), (2, 2, 2)).rotate((10, 20, 30)) - Sphere((0, 0, 0), 1.2).scale((1, 1, 1.4)).rotate((0, 40, 0))
    tree = part | Cylinder((0, 0, 0), (0, 0, 3), 0.3).scale((1.5, 1, 1)).rotate((60, 0, 0))
    scene = scene_of(tree, [PointLight((3, -2, 4))], (4, -5, 3), size=80)
    result = compare(Renderer(csg=csg).render(scene).image, raycast_scene(scene))
    assert result.iou >= MIN_IOU and result.fraction >= MIN_FRACTION, result.summary()
    # membership of the tree agrees with its leaves' own (the difference and union written out)
    x = np.random.default_rng(5).uniform(-2, 2, (20000, 3))
    a, b, c = tree.leaves()[0], tree.leaves()[1], tree.leaves()[2]
    assert np.array_equal(tree.contains(x), (a.contains(x) & ~b.contains(x)) | c.contains(x))


# ----------------------------------------------------------------------------- hypothesis


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


directions = st.tuples(*[st.floats(-1, 1)] * 3).filter(lambda v: np.linalg.norm(v) > 0.2).map(unit)


@st.composite
def linear_maps(draw):
    """Turn, uneven scale and shear: a matrix with a condition number up to about 6."""
    ang = draw(st.tuples(*[st.floats(-180, 180)] * 3))
    from isocsg.kinds.affine import rotation_array

    scale = np.diag(draw(st.tuples(*[st.floats(0.5, 2.0)] * 3)))
    shear = np.eye(3)
    i, j = draw(st.sampled_from([(0, 1), (0, 2), (1, 2), (2, 0)]))
    shear[i, j] = draw(st.floats(-0.7, 0.7))
    kind = draw(st.sampled_from(["turn", "similarity", "scale", "affine"]))
    R = rotation_array(ang)
    if kind == "turn":
        return R
    if kind == "similarity":
        return float(scale[0, 0]) * R
    if kind == "scale":
        return R @ scale
    return R @ shear @ scale


BASES = {
    "sphere": Sphere((0, 0, 0), 0.8),
    "cylinder": Cylinder((0, 0, 0), (0, 0, 1.6), 0.5),
    "cone": Cone((0, 0, 0), (0, 0, 1.6), 0.7),
    "frustum": Truncus((0, 0, 0), (0, 0, 1.2), 0.7, 0.35),
    "box": Box((0, 0, 0), (1.4, 0.9, 0.6)),
    "polyhedron": ConvexPolyhedron([(-0.7, -0.5, -0.4), (0.8, -0.4, -0.3), (0, 0.7, -0.4), (0.1, 0.1, 0.8), (0.4, 0.5, 0.3)]),
    "ellipsoid": Ellipsoid((0, 0, 0), (1.0, 0.7, 0.45)),
}


@st.composite
def lights_for(draw, radius):
    kind = draw(st.sampled_from(["near", "far", "directional", "two"]))
    d = draw(directions)
    if kind == "near":
        return [PointLight(tuple(d * radius * draw(st.floats(1.3, 2.5))))]
    if kind == "far":
        return [PointLight(tuple(d * radius * 50))]
    if kind == "directional":
        return [DirectionalLight(tuple(d))]
    return [PointLight(tuple(d * radius * 2.0)), DirectionalLight(tuple(draw(directions)))]


@pytest.mark.parametrize("base", list(BASES))
@SEARCH
@given(data=st.data())
def test_random_transforms_match_reference(base, data):
    A = data.draw(linear_maps(), label="A")
    prim = BASES[base].transform(affine(A))
    lo, hi = prim.bounds
    prim = prim.translate(-(lo + hi) / 2)
    radius = 0.5 * float(np.linalg.norm(hi - lo))
    lights = data.draw(lights_for(radius), label="lights")
    eye = data.draw(directions, label="eye direction") * radius * data.draw(st.floats(3.0, 6.0), label="distance")
    specular = data.draw(st.booleans(), label="specular")
    mat = Material(0.1, 0.6, 0.25, 15) if specular else Material()
    note(f"A = {A.tolist()}; {type(prim).__name__}: {prim}")
    scene = scene_of(prim, lights, tuple(eye), material=mat, size=64)
    result = judge(scene)
    note(result.summary())
    if LOG:
        with open(LOG, "a") as fh:
            fh.write(f"{base}\t{type(prim).__name__}\t{result.summary()}\n")


def test_sphere_on_the_pixel_grid_differs_only_at_ties():
    """Regression of the random search (seed 11): a turned and scaled sphere centred on the pixel
    grid put 8 symmetric rim pixel centres 0.0019 px inside its exact silhouette, closer than the
    band mesh's chords; the renderer leaves them out (IoU 0.9877). They are ties, not an error."""
    A = [[0.6272525501756657, -0.00529561649310119, 0.016484169974241392],
         [0.005473950076799328, 0.6274315080404763, -0.006728425095681311],
         [-0.01642581152754394, 0.006869663723173071, 0.627238817000072]]
    prim = BASES["sphere"].transform(affine(A))
    assert isinstance(prim, Sphere)
    lights = [DirectionalLight((1.6509686391750613e-38, -0.8011421113120464, 0.5984741577398949))]
    scene = scene_of(prim, lights, (-2.7939567737776914, -2.7939567737776914, 2.0871589488784066), size=64)
    img, ref = render_image(scene), raycast_scene(scene)
    differ = np.isfinite(img) != np.isfinite(ref.image)
    assert np.all(silhouette_ties(scene, tie_pixels=TIE_PIXELS)[differ])
    judge(scene)


#: Seed-14 search examples: (base, A, light, eye). A turned cylinder (a Truncus) and an elliptic
#: cone (an EllipticTruncus), each lit only in a streak about a pixel wide at the terminator.
SLIVERS = {
    "turned cylinder": ("cylinder", [[-0.2288973089696239, -0.9477660488101057, 0.22213855736756918],
                                     [0.7079251338367294, -0.3187019181104244, -0.6302944488689275],
                                     [0.6681676637107735, 0.012984764750144694, 0.7438974183687359]],
                        (0.0, 0.9888651045741266, -1.6047702749022326), (4.349949089839315, 0.0, 0.0)),
    "elliptic cone": ("cone", [[-0.3930762009497312, -0.686390233877432, 0.21503783700654977],
                               [-1.1301221849878585e-42, 0.03078734678099855, 0.777118093043518],
                               [-0.6967719140772872, 0.3872194904107621, 0.319391120741133]],
                      (-9.91598198800532e-99, 1.2250364928095518, -0.5676449133235947),
                      (-8.812328767696883e-98, -8.812328767696883e-98, -5.0446578115704765)),
}


@pytest.mark.parametrize("case", list(SLIVERS))
def test_terminator_sliver_follows_its_own_band_step(case):
    """Regression of the random search (seed 14): under a near point light the visible side is
    lit only in a streak about a pixel wide at the terminator (cosines below 1e-3; the exact
    image's range 1.0e-3 for the cylinder, 2.5e-3 for the cone). Both were off there by up to
    1e-4 (cylinder) and 3e-4 (cone) at N = 16, 64, 256 and 1024 alike (mean 3.5e-6 and 1.3e-5;
    96.6 % and 94.9 % of the pixels within the bar). The side's reversed normal is lit with
    cosines up to 1, and that range set the mesh spacing of the faint outward field too; each
    family is now meshed within the band step of the image it shows in (mean 4.4e-7 and
    1.1e-6 at N = 64, falling with N)."""
    base, A, light, eye = SLIVERS[case]
    prim = BASES[base].transform(affine(A))
    lo, hi = prim.bounds
    prim = prim.translate(-(lo + hi) / 2)
    errors = [judge(scene_of(prim, [PointLight(light)], eye, contours=n, size=64)).mean_error for n in (16, CONTOURS)]
    assert errors[1] < errors[0], errors

# ----------------------------------------------------------------------------- volumes and sections


def test_ellipsoid_volume_and_sections_closed_forms():
    e = Ellipsoid((0.3, -0.2, 0.5), (2.0, 1.0, 0.5)).rotate((20, 30, 40)).translate((1, 2, 3))
    a, b, c = 2.0, 1.0, 0.5
    assert e.volume == pytest.approx(4 / 3 * math.pi * a * b * c, rel=1e-14)
    assert volume(e) == pytest.approx(4 / 3 * math.pi * a * b * c, rel=1e-14)
    assert to_manifold(e, 256).volume() == pytest.approx(e.volume, rel=1e-3)
    # a central section with unit normal n has area pi a b c / |S R^T n| (R, S read from the fields)
    R, r = np.asarray(e.orientation), np.asarray(e.radii)
    for n in [(0, 0, 1), (1, 1, 0), (0.3, -0.2, 1)]:
        n = unit(n)
        area = section(e, e.center, n, area_exact=True).geometry.area
        assert area == pytest.approx(math.pi * a * b * c / np.linalg.norm(r * (R.T @ n)), rel=1e-9)
    # off-centre: the section at distance d along n scales by 1 - (d / h)^2, h the support along n
    n = unit((0.3, -0.2, 1))
    h = np.linalg.norm((R * r).T @ n)
    area = section(e, np.asarray(e.center) + 0.6 * h * n, n, area_exact=True).geometry.area
    assert area == pytest.approx(math.pi * a * b * c / np.linalg.norm(r * (R.T @ n)) * (1 - 0.36), rel=1e-9)


def test_elliptic_cylinder_volume_and_sections():
    c = Cylinder((0.2, 0, 0), (0, 0, 2), 0.5)
    e = c.scale((2, 1, 1)).rotate((10, 20, 30))
    assert isinstance(e, EllipticTruncus)
    assert e.volume == pytest.approx(math.pi * 1.0 * 0.5 * 2, rel=1e-13)  # pi a b h
    assert volume(e) == pytest.approx(math.pi, rel=1e-12)
    assert to_manifold(e, 256).volume() == pytest.approx(math.pi, rel=1e-3)
    # across the axis: the ellipse pi a b
    assert section(e, e.center, e.axis, area_exact=True).geometry.area == pytest.approx(math.pi * 0.5, rel=1e-7)
    # a sheared (oblique) cylinder keeps its volume and its horizontal sections, moved sideways
    sh = c.transform(affine(SHEAR))
    assert sh.volume == pytest.approx(c.volume, rel=1e-13)
    g = section(sh, (0, 0, 0.5), (0, 0, 1), area_exact=True).geometry
    assert g.area == pytest.approx(math.pi * 0.25, rel=1e-7)
    assert g.centroid.x == pytest.approx(0.2 + 0.6 * 0.5, abs=1e-9)


def test_volumes_of_trees_of_transformed_parts_against_manifold3d():
    tree = (Box((0, 0, 0), (2, 2, 2)).rotate((10, 20, 30))
            - Ellipsoid((0.3, 0, 0), (1.2, 0.8, 0.6)).rotate((0, 40, 0))
            - Cylinder((0, 0, 0), (0, 0, 3), 0.3).scale((1.5, 1, 1)).rotate((60, 0, 0)))
    v = volume(tree, tol=1e-4)
    assert v == pytest.approx(to_manifold(tree, 256).volume(), rel=2e-3)


# ----------------------------------------------------------------------------- shadows


def test_shadow_of_transformed_occluders_against_monte_carlo():
    from mc_reference import MCOccluder, hull_halfspaces, mc_illuminance

    from isocsg import AreaLight
    from isocsg.shadows import illuminance

    res = 16
    lamp = AreaLight([(-0.5, -0.5, 3.0), (-0.5, 0.5, 3.0), (0.5, 0.5, 3.0), (0.5, -0.5, 3.0)], 2.0)
    assert lamp.normal_array[2] < 0  # it lights the floor below
    box = Box((0, 0, 1.5), (0.8, 0.5, 0.1)).rotate(35, axis=(0, 0, 1)).rotate(15, axis=(1, 0, 0))
    ell = Ellipsoid((0.9, 0.3, 1.2), (0.4, 0.2, 0.1)).rotate((10, 20, 30))
    # the box's half-spaces from its fields (independent of the library's faces)
    R, h, c = np.asarray(box.orientation), np.asarray(box.size) / 2, np.asarray(box.center)
    normals = np.vstack([R.T, -R.T])
    offsets = normals @ c + np.concatenate([h, h])
    occ = [MCOccluder([(normals, offsets)], []), MCOccluder([hull_halfspaces(ell.to_polyhedron(res).vertices)], [])]
    xs = np.linspace(-1.5, 2.0, 15)
    pts = np.array([[x, y, 0.0] for x in xs for y in (-0.4, 0.0, 0.35)])
    E = illuminance(pts, [0, 0, 1], [lamp], [box, ell], resolution=res)
    mc = mc_illuminance(pts, np.tile([0.0, 0.0, 1.0], (len(pts), 1)), [(lamp.emitting_polygons(), lamp.radiance)], occ,
                        k=12, replicates=48)
    assert np.all(np.abs(E - mc.mean) <= 4 * mc.se + 1e-9), (E, mc.mean, mc.se)
    assert 0.05 < np.mean(mc.visible_fraction < 1) < 0.95  # the points cover lit, penumbra and shadow


@pytest.mark.parametrize("base", list(BASES))
@SEARCH
@given(data=st.data())
def test_random_transforms_volumes_and_sections(base, data):
    """vol(T(P)) = |det A| vol(P) (closed forms), and sections against manifold3d's slices."""
    from isocsg.csg.section import plane_frame

    A = data.draw(linear_maps(), label="A")
    t = np.array(data.draw(st.tuples(*[st.floats(-3, 3)] * 3), label="t"))
    p = BASES[base]
    q = p.transform(affine(A, t))
    note(f"{type(q).__name__}: {q}")
    assert q.volume == pytest.approx(abs(np.linalg.det(A)) * p.volume, rel=1e-12)
    n = data.draw(directions, label="plane normal")
    lo, hi = q.extent(n) if hasattr(q, "extent") else (np.min(q.to_polyhedron(256).vertices @ n), np.max(q.to_polyhedron(256).vertices @ n))
    frac = data.draw(st.floats(0.2, 0.8), label="height")
    origin = np.asarray(q.bounds).mean(axis=0)
    origin = origin + (lo + frac * (hi - lo) - origin @ n) * n
    got = section(q, origin, n, resolution=256, area_exact=True).area
    m = to_manifold(q, 256).transform(np.linalg.inv(plane_frame(origin, n))[:3].tolist())
    # manifold3d's mesh is inscribed (and float32): away from the ends of the extent its slice is
    # smaller by about (2 pi / 256)^2 / 6 = 1e-4 of the area
    assert got == pytest.approx(m.slice(0.0).area(), rel=1e-3, abs=1e-9 * max(1.0, got))
