"""Correctness at scale: CSG trees of 10 to 100 000 primitives against independent references.

Images are judged by the analytic ray caster of ``tests/reference`` with the
catalogue's bars (silhouette IoU >= 0.99, at least 98 % of the compared
pixels within 0.05 of the reference's intensity range, seams left out as in
``tests/reference/metrics.py``), on the first view of a new
``isocsg.rendering.Renderer`` (per pixel), on its second view from another
viewpoint (the clipped surface, under ``csg="auto"``) and on
``Renderer(csg="pixel")`` from that second viewpoint. Sections and volumes are
judged by closed forms and by manifold3d's Booleans and slices of meshes built
here (``tests/reference/meshes.py``). Nothing is judged by isocsg itself.

Models (``tests/reference/models.py``): plates with n holes built three ways
(a loop ``part = part - h``, ``difference(plate, *holes)`` and
``plate - union_all(holes)``), a lattice of 1000 overlapping spheres, nested
1000-operand unions, intersections and differences, random trees of up to
2000 leaves (hypothesis; derandomized under ``CI``, see ``conftest.py``), and
trees built by loops of 100 000 operations, which no step may meet with a
RecursionError.

Sizes are chosen for CI; ``ISOCSG_SCALE_FULL=1`` adds the largest ones
(10 000 holes at 256 px, loops of 100 000 differences rendered, larger images).
"""

from __future__ import annotations

import math
import os
import pickle
import sys
from functools import lru_cache
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from isocsg import Camera, PointLight, RenderSettings, Scene, Sphere, union_all
from isocsg.csg.section import section
from isocsg.csg.volume import volume
from isocsg.rendering import Renderer

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference import compare, compare_images, raycast_scene  # noqa: E402
from reference import raycaster as rc  # noqa: E402
from reference.meshes import leaf_primitives, manifold_of, manifold_slice  # noqa: E402
from reference.models import loop_tree, nested_model, plate_with_holes, random_tree, sphere_lattice  # noqa: E402

FULL = os.environ.get("ISOCSG_SCALE_FULL") == "1"

MIN_IOU = 0.99
MIN_FRACTION = 0.98
CONTOURS = 64
LIGHTS = (PointLight((3.0, -4.0, 6.0)), PointLight((-4.0, -2.0, 3.0), 0.4))
PLATE_EYES = ((2.5, -4.5, 4.0), (-3.5, -3.0, 4.5))


# ----------------------------------------------------------------------------- helpers


def _scene(solid, eye, size: int, *, target=(0.0, 0.0, 0.0), fov: float = 40.0) -> Scene:
    cam = Camera(tuple(eye), tuple(target), fov=fov, width=size, height=size)
    return Scene(cam, LIGHTS, [solid], RenderSettings(contours=CONTOURS))


def _check(image: np.ndarray, scene: Scene, what: str, ref=None) -> None:
    ref = raycast_scene(scene) if ref is None else ref
    assert image.shape == (scene.camera.height, scene.camera.width)
    result = compare(image, ref)
    assert result.iou >= MIN_IOU, f"{what}: {result.summary()}"
    assert result.fraction >= MIN_FRACTION, f"{what}: {result.summary()}"


def _check_views(solid, eyes, size: int, what: str, *, target=(0.0, 0.0, 0.0), refs=None) -> None:
    """First view, second view (same renderer, new camera) and the per-pixel method on the second view."""
    first, second = (_scene(solid, e, size, target=target) for e in eyes)
    refs = refs or (raycast_scene(first), raycast_scene(second))
    renderer = Renderer()
    _check(renderer.render(first).image, first, f"{what}, first view", refs[0])
    _check(renderer.render(second).image, second, f"{what}, second view (auto)", refs[1])
    _check(Renderer(csg="pixel").render(second).image, second, f"{what}, second view (pixel)", refs[1])


# ----------------------------------------------------------------------------- the reference itself at scale


def _brute_force(solid, scene: Scene, pixels: np.ndarray) -> rc.FirstHit:
    """First hits on chosen pixels with every leaf present (no culling, no pruning)."""
    o, d = rc.camera_rays(scene.camera)
    o, d = o.reshape(-1, 3)[pixels], d.reshape(-1, 3)[pixels]
    tree = rc.read_tree(solid)
    return rc._resolve(tree, tree.op, tree.arg, o, d, 0.0)


@pytest.mark.parametrize("model", ["plate300", "random400", "nested60"], ids=str)
def test_reference_culling_and_sweep_change_nothing(model: str) -> None:
    # The ray caster prunes the tree per screen tile and resolves many leaves by a sweep;
    # on sampled pixels both must agree exactly with the whole tree evaluated on every segment.
    if model == "plate300":
        solid, eye = plate_with_holes(300).loop(), PLATE_EYES[0]
    elif model == "random400":
        solid, eye = random_tree(400, 7), (9.0, -11.0, 7.0)
    else:
        solid, eye = nested_model(60), (1.8, -2.5, 1.5)
    scene = _scene(solid, eye, 96)
    ref = raycast_scene(scene)
    assert ref.mask.any()
    pixels = np.random.default_rng(5).choice(96 * 96, 600, replace=False)
    brute = _brute_force(solid, scene, pixels)
    np.testing.assert_array_equal(ref.depth.reshape(-1)[pixels], brute.t)
    np.testing.assert_array_equal(ref.leaf.reshape(-1)[pixels], brute.leaf)
    np.testing.assert_array_equal(ref.side.reshape(-1)[pixels], brute.side)
    np.testing.assert_array_equal(ref.normal.reshape(-1, 3)[pixels], brute.normal)
    # the same rays through first_hit (blocks of rays culled by a slab test)
    o, d = rc.camera_rays(scene.camera)
    fh = rc.first_hit(solid, o.reshape(-1, 3)[pixels], d.reshape(-1, 3)[pixels])
    np.testing.assert_array_equal(fh.t, brute.t)
    np.testing.assert_array_equal(fh.leaf, brute.leaf)


def test_reference_sweep_equals_dense_evaluation(monkeypatch) -> None:
    # the two evaluators of the ray caster on the same blocks: all segments at once, or a sweep
    scene = _scene(random_tree(120, 3), (6.0, -8.0, 5.0), 80)
    dense = raycast_scene(scene)
    monkeypatch.setattr(rc, "DENSE_LEAVES", 0)
    sweep = raycast_scene(scene)
    assert dense.mask.any()
    for field in ("depth", "normal", "leaf", "side", "part"):
        np.testing.assert_array_equal(getattr(sweep, field), getattr(dense, field), err_msg=field)


def test_reference_reads_every_form_of_a_plate_alike() -> None:
    plate = plate_with_holes(100)
    images = [raycast_scene(_scene(s, PLATE_EYES[0], 96)) for s in (plate.loop(), plate.flat(), plate.grouped())]
    for other in images[1:]:
        np.testing.assert_array_equal(other.depth, images[0].depth)
        np.testing.assert_array_equal(other.leaf, images[0].leaf)


# ----------------------------------------------------------------------------- plates with holes


PLATE_SIZES = {10: 128, 100: 128, 1000: 160}


@lru_cache(maxsize=8)
def _plate_refs(n: int, size: int):
    solid = plate_with_holes(n).flat()  # every form is the same set: one reference per size
    return tuple(raycast_scene(_scene(solid, e, size)) for e in PLATE_EYES)


@pytest.mark.parametrize("form", ["loop", "flat", "grouped"], ids=str)
@pytest.mark.parametrize("n", [10, 100, pytest.param(1000, marks=[pytest.mark.slow, pytest.mark.skipif(
    not FULL, reason="the largest sizes run with ISOCSG_SCALE_FULL=1")])], ids=lambda n: f"{n}holes")
def test_plate_with_holes_matches_reference(n: int, form: str) -> None:
    plate = plate_with_holes(n)
    size = PLATE_SIZES[n]
    _check_views(getattr(plate, form)(), PLATE_EYES, size, f"plate, {n} holes ({form})", refs=_plate_refs(n, size))


@pytest.mark.slow
@pytest.mark.skipif(not FULL, reason="the largest sizes run with ISOCSG_SCALE_FULL=1")
def test_plate_10000_holes_matches_reference() -> None:
    # 10 000 holes at 128 px: holes of about one pixel; the whole plate in view
    plate = plate_with_holes(10_000)
    _check_views(plate.flat(), PLATE_EYES, 128, "plate, 10 000 holes (flat)")


@pytest.mark.parametrize("form", ["loop", "flat", "grouped"], ids=str)
@pytest.mark.parametrize("size", [256], ids=lambda s: f"{s}px")
@pytest.mark.slow
@pytest.mark.skipif(not FULL, reason="the largest sizes run with ISOCSG_SCALE_FULL=1")
def test_plate_10000_holes_full_size(form: str, size: int) -> None:
    plate = plate_with_holes(10_000)
    _check_views(getattr(plate, form)(), PLATE_EYES, size, f"plate, 10 000 holes ({form})", refs=_plate_refs(10_000, size))


# ----------------------------------------------------------------------------- unions, intersections


def test_lattice_of_1000_spheres_matches_reference() -> None:
    _check_views(sphere_lattice(10), ((5.0, -7.0, 5.0), (-6.5, -5.0, 4.0)), 128, "lattice of 1000 spheres")
@pytest.mark.slow
@pytest.mark.skipif(not FULL, reason="the largest sizes run with ISOCSG_SCALE_FULL=1")


def test_nested_1000_operand_nodes_match_reference() -> None:
    size = 160 if FULL else 96
    _check_views(nested_model(1000), ((1.8, -2.5, 1.5), (-2.0, -2.2, -1.4)), size, "nested 1000-operand nodes")


def _random_eyes(n: int) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
    side = 0.9 * n ** (1 / 3)
    d = 1.2 * side + 1.2
    return (0.8 * d, -1.0 * d, 0.6 * d), (-0.9 * d, -0.7 * d, 0.5 * d)


RANDOM_SETTINGS = settings(max_examples=4, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@pytest.mark.slow
@pytest.mark.skipif(not FULL, reason="the largest sizes run with ISOCSG_SCALE_FULL=1")
@RANDOM_SETTINGS
@given(st.integers(2, 2000), st.integers(0, 2**31 - 1))
def test_random_trees_match_reference(n: int, seed: int) -> None:
    _check_views(random_tree(n, seed), _random_eyes(n), 96, f"random tree of {n} leaves (seed {seed})")


# ----------------------------------------------------------------------------- identities on large trees


IDENTITY_SETTINGS = settings(max_examples=3, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _renders(solid, eyes, size: int = 80) -> list[np.ndarray]:
    renderer = Renderer()
    return [renderer.render(_scene(solid, e, size)).image for e in eyes]


@pytest.mark.slow
@pytest.mark.skipif(not FULL, reason="the largest sizes run with ISOCSG_SCALE_FULL=1")
@IDENTITY_SETTINGS
@given(st.integers(50, 600), st.integers(0, 2**31 - 1))
def test_a_minus_a_renders_empty_on_large_trees(n: int, seed: int) -> None:
    a = random_tree(n, seed)
    for k, image in enumerate(_renders(a - a, _random_eyes(n))):
        assert np.isnan(image).all(), f"view {k + 1}: {np.count_nonzero(np.isfinite(image))} object pixels"


@pytest.mark.slow
@pytest.mark.skipif(not FULL, reason="the largest sizes run with ISOCSG_SCALE_FULL=1")
@IDENTITY_SETTINGS
@given(st.integers(50, 600), st.integers(0, 2**31 - 1))
def test_a_union_a_renders_as_a_on_large_trees(n: int, seed: int) -> None:
    a = random_tree(n, seed)
    eyes = _random_eyes(n)
    for k, (aa, alone) in enumerate(zip(_renders(a | a, eyes), _renders(a, eyes))):
        result = compare_images(aa, alone)
        assert result.iou >= MIN_IOU, f"view {k + 1}: A | A vs A: {result.summary()}"
        assert result.fraction >= MIN_FRACTION, f"view {k + 1}: A | A vs A: {result.summary()}"


@pytest.mark.slow
@pytest.mark.skipif(not FULL, reason="the largest sizes run with ISOCSG_SCALE_FULL=1")
@IDENTITY_SETTINGS
@given(st.integers(50, 600), st.integers(0, 2**31 - 1))
def test_intersection_commutes_on_large_trees(n: int, seed: int) -> None:
    a, b = random_tree(n, seed), random_tree(n, seed + 1)
    eyes = _random_eyes(n)
    refs = [raycast_scene(_scene(a & b, e, 80)) for e in eyes]
    for k, (ab, ba, ref) in enumerate(zip(_renders(a & b, eyes), _renders(b & a, eyes), refs)):
        result = compare_images(ab, ba, surface_id=ref.surface_id)
        assert result.iou >= MIN_IOU, f"view {k + 1}: A & B vs B & A: {result.summary()}"
        assert result.fraction >= MIN_FRACTION, f"view {k + 1}: A & B vs B & A: {result.summary()}"


# ----------------------------------------------------------------------------- sections and volumes


def _lens_volume(r: float, d: float) -> float:
    """Volume of the intersection of two balls of radius r whose centres are d apart (d < 2 r)."""
    return math.pi * (4 * r + d) * (2 * r - d) ** 2 / 12


PLATE_SEGMENTS = 64


@lru_cache(maxsize=4)
def _plate_mesh(n: int):
    """manifold3d's plate minus n holes (every form of the plate is this set: one mesh per n)."""
    return manifold_of(plate_with_holes(n).flat(), PLATE_SEGMENTS)


@pytest.mark.parametrize("form", ["loop", "grouped"], ids=str)
@pytest.mark.parametrize("n", [10, 100, 1000], ids=lambda n: f"{n}holes")
def test_plate_volume_and_sections(n: int, form: str) -> None:
    plate = plate_with_holes(n)
    solid = getattr(plate, form)()
    # the volume against its closed form
    tol = 1e-3
    v = volume(solid, tol=tol)
    assert abs(v - plate.volume) <= 2 * tol * plate.volume, f"volume {v} vs exact {plate.volume}"
    # the mid-plane section: the plate's rectangle minus n discs, exactly
    mid = section(solid, (0, 0, 0), (0, 0, 1), resolution=1024)
    # inscribed 1024-gons lose (2 pi / 1024)^2 / 6 of each disc's area
    deficit = n * math.pi * plate.radius**2 * (2 * math.pi / 1024) ** 2 / 6
    assert abs(mid.area - plate.area_mid) <= 1e-9 * plate.area_mid + 2 * deficit, (mid.area, plate.area_mid)
    # against manifold3d's Boolean of the same model, sliced by the same planes
    mesh = _plate_mesh(n)
    sx, sy, sz = plate.size
    # the mesh's inscribed 64-gons remove (2 pi / 64)^2 / 6 less of each hole than the cylinders
    sag = n * math.pi * plate.radius**2 * sz * (2 * math.pi / PLATE_SEGMENTS) ** 2 / 6
    assert abs(v - mesh.volume()) <= 2 * tol * plate.volume + 1.5 * sag
    pitch = sx / math.ceil(math.sqrt(n * 4 / 3))
    for origin, normal in (((0.0, 0.0, 0.05), (0, 0, 1)),  # parallel to the faces
                           ((-sx / 2 + 0.5 * pitch + 0.1 * plate.radius, 0.0, 0.0), (1, 0, 0)),  # through a column of holes
                           ((0.1, 0.05, 0.0), (0.35, -0.5, 0.79))):  # oblique
        s = section(solid, origin, normal, resolution=512)
        ref = manifold_slice(mesh, s.frame)
        assert ref.area > 0
        assert abs(s.area - ref.area) <= 5e-3 * ref.area + 1e-6, (origin, s.area, ref.area)
        assert s.geometry.symmetric_difference(ref).area <= 1e-2 * ref.area + 1e-6, origin


def test_lattice_volume_and_sections() -> None:
    n_side, extent = 10, 3.0
    solid = sphere_lattice(n_side, extent=extent)
    pitch = extent / n_side
    r = 0.6 * pitch
    # neighbours along an axis overlap in a lens; no point is in three spheres (r < pitch / sqrt 2)
    exact = n_side**3 * 4 / 3 * math.pi * r**3 - 3 * n_side**2 * (n_side - 1) * _lens_volume(r, pitch)
    tol = 1e-3
    v = volume(solid, tol=tol)
    assert abs(v - exact) <= 2 * tol * exact, (v, exact)
    for origin, normal in (((0.0, 0.0, 0.1), (0, 0, 1)), ((0.05, 0.0, 0.0), (0.3, 0.9, -0.3))):
        s = section(solid, origin, normal, resolution=1024)
        # manifold3d's union of the spheres the plane meets (the others do not change the cut)
        unit = np.asarray(normal, dtype=np.float64) / np.linalg.norm(normal)
        near = [c for c in solid.children if abs(float(np.dot(np.subtract(c.center, origin), unit))) < c.radius]
        assert 50 < len(near) < len(solid.children)
        ref = manifold_slice(manifold_of(union_all(near), 128), s.frame)
        # 128-gon circles of the mesh lose up to (2 pi / 128)^2 / 6 = 0.04 % of a disc's area
        assert abs(s.area - ref.area) <= 5e-3 * ref.area, (origin, s.area, ref.area)
        assert s.geometry.symmetric_difference(ref).area <= 1e-2 * ref.area, origin


@pytest.mark.parametrize("n,seed", [(200, 11), pytest.param(800, 12, marks=[pytest.mark.slow, pytest.mark.skipif(
    not FULL, reason="the largest sizes run with ISOCSG_SCALE_FULL=1")])], ids=["200leaves", "800leaves"])
def test_random_tree_volume_and_section(n: int, seed: int) -> None:
    solid = random_tree(n, seed)
    mesh = manifold_of(solid, 128)
    scale = sum(m.volume() for m in [manifold_of(p, 128) for p in leaf_primitives(solid)])
    tol = 1e-3
    v = volume(solid, tol=tol)
    # the meshes' inscribed 128-gons lose about (2 pi / 128)^2 / 3 < 1e-3 of each curved leaf
    assert abs(v - mesh.volume()) <= (2 * tol + 1e-3) * scale, (v, mesh.volume(), scale)
    s = section(solid, (0.1, -0.2, 0.05), (0.2, 0.3, 0.93), resolution=1024)
    ref = manifold_slice(mesh, s.frame)
    floor = 1e-3 * max(ref.area, s.area, 1.0)
    assert abs(s.area - ref.area) <= 5e-3 * ref.area + floor
    assert s.geometry.symmetric_difference(ref).area <= 1e-2 * ref.area + floor


# ----------------------------------------------------------------------------- loops of 100 000 operations


def _plate_membership(plate, pts: np.ndarray) -> np.ndarray:
    """Closed-form membership of a plate with grid holes: inside the box, outside every hole."""
    sx, sy, sz = plate.size
    inside = np.all(np.abs(pts) <= np.array([sx, sy, sz]) / 2, axis=1)
    cols = math.ceil(math.sqrt(plate.n * 4 / 3))
    pitch = sx / cols
    j = np.clip(np.floor((pts[:, 0] + sx / 2) / pitch), 0, cols - 1)
    i = np.clip(np.floor((pts[:, 1] + sy / 2) / pitch), 0, math.ceil(plate.n / cols) - 1)
    cx = -sx / 2 + (j + 0.5) * pitch
    cy = -sy / 2 + (i + 0.5) * pitch
    has_hole = i * cols + j < plate.n
    in_hole = has_hole & ((pts[:, 0] - cx) ** 2 + (pts[:, 1] - cy) ** 2 <= plate.radius**2)
    return inside & ~in_hole


@pytest.mark.parametrize(
    "distinct",
    [10_000, pytest.param(None, marks=[pytest.mark.slow, pytest.mark.skipif(
        not FULL, reason="the largest sizes run with ISOCSG_SCALE_FULL=1")])],
    ids=["10000distinct", "100000distinct"],
)
def test_loop_of_100000_operations_has_no_recursion_limit(distinct) -> None:
    # 100 000 differences, nesting 100 000 deep, cycling through ``distinct`` holes
    limit = sys.getrecursionlimit()
    n = 100_000
    solid, plate = loop_tree(n, distinct=distinct)
    assert sys.getrecursionlimit() == limit
    # hash, equality with an equal tree built separately, pickle round trip
    again = plate.plate
    for i in range(n):
        again = again - plate.holes[i % plate.n]
    assert hash(solid) == hash(again) and solid == again
    back = pickle.loads(pickle.dumps(solid))
    assert back == solid and hash(back) == hash(solid)
    assert solid != (again - Sphere((0, 0, 0), 0.1))
    # bounds: the plate's box (the holes are longer than it is thick but subtracted)
    np.testing.assert_allclose(np.asarray(solid.bounds)[:, 2], [-plate.size[2] / 2, plate.size[2] / 2], atol=1e-12)
    # contains, against the closed form, on random points and on points near hole walls
    rng = np.random.default_rng(1)
    sx, sy, sz = plate.size
    pts = rng.uniform(-0.5, 0.5, (600, 3)) * np.array([sx * 1.05, sy * 1.05, sz * 1.2])
    near = np.array([h.center for h in plate.holes[:: plate.n // 200]]) + plate.radius * np.array([0.97, 0.0, 0.0])
    pts = np.vstack([pts, near, near + np.array([0.06 * plate.radius, 0, 0])])
    np.testing.assert_array_equal(solid.contains(pts), _plate_membership(plate, pts))
    repr(solid)
    solid.to_dict()
    # a section across a row of holes: the plate's strip minus the holes' chords, exactly
    y0 = -sy / 2 + 0.5 * (sx / math.ceil(math.sqrt(plate.n * 4 / 3))) + 0.4 * plate.radius
    s = section(solid, (0.0, y0, 0.0), (0, 1, 0), resolution=256)
    cut = [h for h in plate.holes if abs(h.center[1] - y0) < plate.radius]
    chords = sum(2 * math.sqrt(plate.radius**2 - (h.center[1] - y0) ** 2) for h in cut)
    exact = (sx - chords) * sz
    assert len(cut) > 50
    assert abs(s.area - exact) <= 1e-3 * exact, (s.area, exact)


@pytest.mark.slow
@pytest.mark.skipif(not FULL, reason="the largest sizes run with ISOCSG_SCALE_FULL=1")
def test_loop_of_100000_operations_renders() -> None:
    # 100 000 differences cycling through 1000 holes: 100 001 leaves, nested 100 000 deep.
    # Equal leaves are built once and share their tile buffers; meshes are dropped once
    # filled (this render was killed at about 24 GB when every leaf's mesh stayed alive).
    solid, plate = loop_tree(100_000, distinct=1000)
    scene = _scene(solid, PLATE_EYES[0], 64)
    _check(Renderer().render(scene).image, scene, "loop of 100 000 differences")
    assert volume(solid, tol=1e-3) == pytest.approx(plate.volume, rel=2e-3)


@pytest.mark.slow
@pytest.mark.skipif(not FULL, reason="the largest sizes run with ISOCSG_SCALE_FULL=1")
def test_loop_of_100000_distinct_primitives_renders() -> None:
    solid, _ = loop_tree(100_000)
    scene = _scene(solid, PLATE_EYES[0], 128)
    _check(Renderer().render(scene).image, scene, "loop of 100 000 distinct holes")


@pytest.mark.slow
@pytest.mark.skipif(not FULL, reason="the largest sizes run with ISOCSG_SCALE_FULL=1")
def test_union_all_of_10000_spheres_full_size() -> None:
    # 10 000 spheres (22^3 lattice minus a corner) at 256 px, both views
    spheres = [s for s in sphere_lattice(22, extent=4.0).children][:10_000]
    _check_views(union_all(spheres), ((6.5, -9.0, 6.5), (-8.5, -6.5, 5.0)), 256, "union of 10 000 spheres")
