"""The renderer at the scale of real models: screen tiles, pruned programs, bounded memory.

Per-pixel CSG of large trees runs in screen tiles that each hold only the
leaves meeting them, with the program pruned to those leaves; these tests
check the tiled render pixel for pixel against the render over the object's
whole rectangle, the compiled pruning against ``Program.prune``, plates with
hundreds of holes against the analytic ray caster of the tests, the memory
of a 1000-hole plate at 1024 px (in a subprocess), the memory budget, the
near plane of objects far apart, the caches' byte bounds and the rule that
keeps large trees per pixel under ``csg="auto"``.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import textwrap
import tracemalloc
from pathlib import Path

import numpy as np
import pytest

from isocsg import (
    Box,
    Camera,
    Cylinder,
    Difference,
    Intersection,
    Material,
    PointLight,
    RenderSettings,
    Scene,
    SceneObject,
    Sphere,
    Union,
)
from isocsg.csg.program import OP_DIFFERENCE, OP_INTERSECTION, OP_LEAF, compile_program
from isocsg.errors import ResourceLimitError
from isocsg.laminae import build_bands
from isocsg.limits import set_memory_budget
from isocsg.rendering import Renderer, painter, policy, surfaces, tiles
from isocsg.rendering import tiled as tiled_path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference import compare  # noqa: E402
from reference.raycaster import ReferenceImage, camera_rays, first_hit, shade_points  # noqa: E402

LIGHTS = (PointLight((60.0, -80.0, 120.0)),)


def plate(k: int, *, size: float = 100.0, thickness: float = 1.0) -> Difference:
    """A square plate with a k x k grid of cylindrical holes through it."""
    step = size / k
    holes = [
        Cylinder(((i + 0.5) * step - size / 2, (j + 0.5) * step - size / 2, 0.0), (0.0, 0.0, 2.0 * thickness), 0.3 * step)
        for i in range(k) for j in range(k)
    ]
    return Difference(Box((0.0, 0.0, 0.0), (size, size, thickness)), *holes)


def plate_scene(k: int, width: int, height: int, contours: int = 32) -> Scene:
    cam = Camera((20.0, -70.0, 90.0), (0.0, 0.0, 0.0), fov=50, width=width, height=height)
    return Scene(cam, LIGHTS, (SceneObject(plate(k)),), RenderSettings(contours=contours))


def _tiled(monkeypatch, sides=(8,)) -> None:
    """Force screen tiles of the given sides for every CSG object."""
    monkeypatch.setattr(policy, "DENSE_MAX_LEAVES", 0)
    monkeypatch.setattr(tiles, "TILE_SIDES", sides)


def _assert_same(a, b) -> None:
    np.testing.assert_array_equal(a.image, b.image)
    np.testing.assert_array_equal(a.object_index, b.object_index)
    np.testing.assert_array_equal(a.primitive_index, b.primitive_index)
    np.testing.assert_allclose(a.depth, b.depth, rtol=1e-12)


def _trees():
    s1, s2, s3 = Sphere((0.0, 0.0, 0.0), 1.0), Sphere((0.9, 0.3, 0.2), 0.7), Sphere((-1.6, -0.2, 0.1), 0.6)
    box = Box((0.3, -0.2, 0.1), (1.2, 1.5, 0.9))
    cyl = Cylinder((0.0, 0.0, 0.0), (0.2, 0.1, 3.0), 0.35)
    return {
        "plate": plate(4),
        "nested": (box - (cyl | Cylinder((0, 0, 0), (3.0, 0, 0.2), 0.3))) & Sphere((0, 0, 0), 1.0),
        # the intersection's operands meet only in part of the screen: elsewhere tiles prune it to nothing
        "pruned-intersection": Union(Intersection(s1, s2), s3, Difference(box, s3)),
        "nested-differences": Difference(Union(s1, s3), Difference(box, cyl), s2),
    }


@pytest.mark.parametrize("sides", [(8,), (16,), (32,)], ids=lambda s: f"{s[0]}px")
@pytest.mark.parametrize("name", list(_trees()), ids=str)
def test_tiled_render_equals_the_whole_rectangle_render(name, sides, monkeypatch):
    # The same tree resolved over its whole screen rectangle and in tiles of a
    # few pixels (leaves clipped to each tile, the program pruned per tile)
    # must give the same image, labels and (to rounding) depths.
    tree = _trees()[name]
    eye = (20.0, -70.0, 90.0) if name == "plate" else (2.5, -3.5, 2.0)
    cam = Camera(eye, (0, 0, 0), fov=50 if name == "plate" else 45, width=90, height=70)
    scene = Scene(cam, LIGHTS, (SceneObject(tree), SceneObject(Sphere((0.5, 8.0, -1.0), 2.0))), RenderSettings(contours=24))
    whole = Renderer(csg="pixel").render(scene)
    _tiled(monkeypatch, sides)
    calls = []
    real = tiled_path.resolve_packed
    monkeypatch.setattr(tiled_path, "resolve_packed", lambda *a: calls.append(len(a[0])) or real(*a))
    tiled = Renderer(csg="pixel").render(scene)
    assert len(calls) > 1  # resolved tile by tile
    _assert_same(tiled, whole)
    assert np.isfinite(whole.image).sum() > 300


def _pruned_by_hand(prog, keep):
    """The oracle of ``Program.prune``: the program evaluated with absent leaves as the empty set
    (an absent operand leaves a union and a difference's subtracted operands, empties an
    intersection or a difference whose first operand it is; one operand left is the node)."""
    def combine(o, xs):
        if (o == OP_INTERSECTION and None in xs) or (o == OP_DIFFERENCE and xs[0] is None):
            return None
        kept = [x for x in xs if x is not None]
        if len(kept) <= 1:
            return kept[0] if kept else None
        return ([v for x in kept for v in x[0]] + [o], [v for x in kept for v in x[1]] + [len(kept)])

    return prog.evaluate(lambda i, _: ([OP_LEAF], [i]) if keep[i] else None, combine)


def test_program_prune_matches_the_empty_set_rules():
    rng = np.random.default_rng(5)
    pool = [Sphere((float(x), 0.0, 0.0), 1.0) for x in range(7)] + [Box((0, float(y), 0), (1, 1, 1)) for y in range(5)]

    def tree(depth):
        if depth == 0 or rng.random() < 0.3:
            return pool[rng.integers(len(pool))]
        kind = [Union, Intersection, Difference][rng.integers(3)]
        return kind(*[tree(depth - 1) for _ in range(int(rng.integers(2, 5)))])

    checked = 0
    for _ in range(60):
        t = tree(4)
        prog = compile_program(t)
        for _ in range(5):
            keep = rng.random(prog.n_leaves) < 0.6
            want = _pruned_by_hand(prog, keep)
            got = prog.prune(keep)
            if want is None:
                assert got is None
            else:
                op, arg = want
                ids = [a for o, a in zip(op, arg) if o == OP_LEAF]
                renumbered = [ids.index(a) if o == OP_LEAF else a for o, a in zip(op, arg)]
                assert got[0].op.tolist() == op
                assert got[0].arg.tolist() == renumbered
                assert got[1].tolist() == ids
                assert got[0].leaves == tuple(prog.leaves[i] for i in ids)
            checked += want is not None
    assert checked > 50


def test_tiles_prune_absent_leaves(monkeypatch):
    # A plate's tiles hold the plate and only the holes that reach them: the
    # resolution sees programs of a few leaves, never the whole difference.
    _tiled(monkeypatch, (16,))
    sizes = []
    real = tiled_path.resolve_packed
    monkeypatch.setattr(tiled_path, "resolve_packed", lambda *a: sizes.append(len(a[9])) or real(*a))  # a[9]: leaf ids
    scene = plate_scene(10, 128, 96)
    Renderer(csg="pixel").render(scene)
    assert len(sizes) > 20 and max(sizes) <= 16 < 101
    # an intersection whose operands are apart on screen prunes to nothing: no tile resolves
    apart = Intersection(Sphere((-3.0, 0.0, 0.0), 1.0), Sphere((3.0, 0.0, 0.0), 1.0), Box((0, 0, 0), (9, 1, 1)))
    sizes.clear()
    cam = Camera((0.0, -12.0, 0.0), (0, 0, 0), width=96, height=64)
    res = Renderer(csg="pixel").render(Scene(cam, LIGHTS, (SceneObject(apart),)))
    assert sizes == [] and not np.isfinite(res.image).any()


def plate_reference(scene: Scene) -> ReferenceImage:
    """The ray caster's exact image of a :func:`plate` scene.

    The ray caster takes trees of up to 64 leaves; a ray can only meet the
    holes whose cylinder its segment between the cylinders' end planes passes
    within a radius of, so each ray is cast against the plate minus those
    (found here from the holes' parameters), and the leaf indices are mapped
    back to the whole tree's.
    """
    tree = scene.objects[0].shape
    box, holes = tree.children[0], tree.children[1:]
    cam = scene.camera
    origins, dirs = camera_rays(cam)
    o, d = origins.reshape(-1, 3), dirs.reshape(-1, 3)
    centres = np.array([h.center[:2] for h in holes])
    radius = holes[0].r1 * (1 + 1e-9)
    z0, z1 = (holes[0].center[2] + s * holes[0].axis[2] / 2 for s in (-1, 1))
    p0 = o[:, :2] + ((z0 - o[:, 2]) / d[:, 2])[:, None] * d[:, :2]
    p1 = o[:, :2] + ((z1 - o[:, 2]) / d[:, 2])[:, None] * d[:, :2]
    seg = p1 - p0
    rel = centres[None, :, :] - p0[:, None, :]  # (rays, holes, 2)
    u = np.clip(np.einsum("rhk,rk->rh", rel, seg) / np.maximum(np.einsum("rk,rk->r", seg, seg), 1e-300)[:, None], 0, 1)
    near = np.linalg.norm(rel - u[..., None] * seg[:, None, :], axis=2) <= radius
    groups: dict[tuple[int, ...], list[int]] = {}
    for r, row in enumerate(near):
        groups.setdefault(tuple(np.flatnonzero(row).tolist()), []).append(r)
    n = len(d)
    t, normal = np.full(n, np.inf), np.zeros((n, 3))
    leaf, side, part = (np.full(n, -1, np.int64) for _ in range(3))
    for cands, rays in groups.items():
        rays_a = np.asarray(rays)
        solid = Difference(box, *[holes[c] for c in cands]) if cands else box
        fh = first_hit(solid, o[rays_a], d[rays_a])
        t[rays_a], normal[rays_a], side[rays_a], part[rays_a] = fh.t, fh.normal, fh.side, fh.part
        to_tree = np.asarray([0] + [c + 1 for c in cands])
        leaf[rays_a] = np.where(fh.leaf >= 0, to_tree[np.maximum(fh.leaf, 0)], -1)
    hit = leaf >= 0
    image = np.full(n, np.nan)
    pts = o + np.where(hit, t, 0.0)[:, None] * d
    image[hit] = shade_points(pts[hit], normal[hit], np.asarray(cam.eye, float), scene.lights, scene.objects[0].material)
    shape = (cam.height, cam.width)
    return ReferenceImage(image.reshape(shape), t.reshape(shape), normal.reshape(*shape, 3),
                          np.where(hit, 0, -1).reshape(shape), leaf.reshape(shape), side.reshape(shape), part.reshape(shape))


def test_plate_reference_agrees_with_the_ray_caster_on_a_small_plate():
    from reference import raycast_scene

    scene = plate_scene(5, 96, 80)
    ours, full = plate_reference(scene), raycast_scene(scene)
    np.testing.assert_array_equal(ours.leaf, full.leaf)
    np.testing.assert_allclose(ours.image, full.image, rtol=1e-12)


@pytest.mark.parametrize("k", [10, 16], ids=lambda k: f"{k * k}-holes")
def test_plate_with_many_holes_matches_the_ray_caster(k):
    # Plates of 100 and 256 holes (tiled: more leaves than the whole-rectangle
    # path takes) judged by the analytic ray caster as the catalogue scenes are.
    scene = plate_scene(k, 224, 176, contours=64)
    image = Renderer(csg="pixel").render(scene).image
    result = compare(image, plate_reference(scene))
    assert result.iou >= 0.99, result.summary()
    assert result.fraction >= 0.98, result.summary()


def test_leaves_a_few_pixels_across_are_drawn_by_rays_without_bands(monkeypatch):
    # A plate drilled by a long loop, seen from afar: 100 000 holes of a third of a pixel had
    # not rendered after 600 s (each hole's bands were built). Holes at most RAY_LEAF_SIZE
    # pixels across are now drawn by exact rays: none of their bands is built, and the image
    # still matches the ray caster. (benchmarks/scale.py --tiny-holes measures the time per
    # hole from 1 000 to 100 000 holes.)
    built = []
    real = Renderer._bands

    def spy(self, primitive, *a, **kw):
        built.append(primitive)
        return real(self, primitive, *a, **kw)

    monkeypatch.setattr(Renderer, "_bands", spy)
    scene = plate_scene(30, 72, 60, contours=32)  # 901 leaves, holes about a pixel across
    image = Renderer(csg="pixel").render(scene).image
    assert len(built) == 1  # the plate only
    result = compare(image, plate_reference(scene))
    assert result.iou >= 0.99, result.summary()
    assert result.fraction >= 0.98, result.summary()
    # The same tree with the rays turned off builds the bands of every hole on screen.
    monkeypatch.setattr(policy, "RAY_LEAF_SIZE", -1.0)
    built.clear()
    Renderer(csg="pixel").render(scene)
    assert len(built) > 800


def test_small_leaves_get_fewer_contours(monkeypatch):
    # Holes under 64 pixels across are built with fewer contours (half of N);
    # the plate, large on screen, keeps the requested count.
    from isocsg.laminae import build_laminae

    asked = {}

    def build(primitive, lights, material, contours, *, eye):
        asked[primitive] = contours
        return build_laminae(primitive, lights, material, contours, eye=eye)

    monkeypatch.setattr(policy, "LOD_MIN_LEAVES", 0)  # (the rule is for trees of more leaves)
    scene = plate_scene(6, 160, 128, contours=64)
    Renderer(adaptive_contours=True, build_laminae=build).render(scene)
    tree = scene.objects[0].shape
    assert asked[tree.children[0]] == 64
    holes = [asked[h] for h in tree.children[1:]]
    assert set(holes) == {32}
    asked.clear()
    Renderer(build_laminae=build, adaptive_contours=False).render(scene)
    assert set(asked.values()) == {64}


def test_equal_leaves_are_built_once_and_resolved_as_one():
    # A modelling loop subtracting each of 16 holes 40 times (641 leaves, 17
    # distinct): each distinct leaf is built once, and the image is the plate's
    # with each hole once, as the ray caster sees it.
    from isocsg.laminae import build_laminae

    scene = plate_scene(4, 96, 80, contours=32)
    tree = scene.objects[0].shape
    part = tree.children[0]
    for _ in range(40):
        for hole in tree.children[1:]:
            part = part - hole
    built = []

    def build(primitive, lights, material, contours, *, eye):
        built.append(primitive)
        return build_laminae(primitive, lights, material, contours, eye=eye)

    loop = Scene(scene.camera, scene.lights, (SceneObject(part),), scene.render)
    # (the level of detail applies to the loop's 641 leaves and not to the 17 of the flat
    # tree: both without it, so that the images compare bit for bit)
    res = Renderer(csg="pixel", build_laminae=build, adaptive_contours=False).render(loop)
    assert len(built) == 17 and set(built) == set(tree.children)
    np.testing.assert_array_equal(res.image, Renderer(csg="pixel", adaptive_contours=False).render(scene).image)
    result = compare(res.image, plate_reference(scene))
    assert result.iou >= 0.99, result.summary()
    assert result.fraction >= 0.98, result.summary()


def test_open_tile_pixels_bounds_what_a_render_keeps(monkeypatch):
    # Three leaves in a column of 8-pixel tiles: rows are released behind the
    # one being built, so fewer pixels are open than the leaves cover in all.
    rects = np.array([[0, 0, 8, 16], [0, 24, 8, 32], [0, 40, 8, 48]])
    monkeypatch.setattr(tiles, "TILE_SIDES", (8,))
    plan = tiles.plan_tiles(rects, (0, 0, 8, 48), 5, 1 << 30)
    assert plan.side == 8
    # ahead=0: one leaf's rows at a time (the first spans two rows of tiles)
    assert tiles.open_tile_pixels(rects, plan, 0) == 8 * 16
    # ahead=3: the second row built while the first one's still open, and so on
    assert tiles.open_tile_pixels(rects, plan, 3) == 8 * 16 + 8 * 8
    assert tiles.open_tile_pixels(rects, plan, 10) == 3 * 8 * 8 + 8 * 8


_MEMORY_SCRIPT = textwrap.dedent(
    """
    import json, resource, sys, time
    sys.path.insert(0, {tests!r})
    from test_render_scale import plate_scene
    from isocsg.rendering import Renderer
    scene = plate_scene(32, 1024, 1024, contours=64)
    def hwm():  # this process's own high-water mark (ru_maxrss would include the parent's, kept across exec)
        return next(int(l.split()[1]) for l in open("/proc/self/status") if l.startswith("VmHWM:"))
    base = hwm()
    t = time.perf_counter()
    res = Renderer().render(scene)  # default settings (the level of detail by screen size)
    seconds = time.perf_counter() - t
    peak = hwm()
    print(json.dumps({{"base_mb": base / 1024, "peak_mb": peak / 1024, "seconds": seconds,
                      "covered": int((res.image == res.image).sum())}}))
    """
)


def test_thousand_hole_plate_at_1024_px_stays_well_under_1_5_gb():
    # Before screen tiles, each leaf filled buffers over the plate's whole
    # rectangle: about 24 bytes x 1024 x 1024 x 1025 leaves, 25 GB.
    script = _MEMORY_SCRIPT.format(tests=str(Path(__file__).resolve().parent))
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(Path(__file__).resolve().parents[1]), os.environ.get("PYTHONPATH", "")])}
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env, timeout=1200)
    assert out.returncode == 0, out.stderr[-3000:]
    got = json.loads(out.stdout.strip().splitlines()[-1])
    assert got["covered"] > 300_000
    assert got["peak_mb"] < 1500, got


def test_budget_error_is_raised_before_allocating():
    cam = Camera((0.0, -6.0, 0.0), (0, 0, 0), width=4096, height=4096)
    scene = Scene(cam, LIGHTS, (SceneObject(Sphere((0, 0, 0), 1.0) - Box((0, 0, 0), (1, 1, 1))),))
    set_memory_budget(1 << 27)
    tracemalloc.start()
    try:
        with pytest.raises(ResourceLimitError, match=re.escape("render: 4096 x 4096 image needs about 0.27 GB")):
            Renderer().render(scene)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
        set_memory_budget(None)
    assert peak < 16 << 20


def test_budget_error_for_tiles_that_cannot_shrink_enough():
    # 600 spheres over the same pixels: even 8-pixel tiles hold all of them (an intersection:
    # a union needs no per-pixel buffers, see the next test).
    balls = Intersection(*[Sphere((0.0, 0.0, 0.0), 1.0 + 0.001 * i) for i in range(600)])
    cam = Camera((0.0, -6.0, 0.0), (0, 0, 0), width=64, height=64)
    built = []

    def build(*args, **kwargs):  # never reached: the budget is checked before any band is built
        built.append(1)
        raise AssertionError("built")

    set_memory_budget(1 << 20)
    try:
        with pytest.raises(ResourceLimitError, match=re.escape("per-pixel CSG of 600 leaves (600 distinct) in 8-pixel tiles")):
            Renderer(build_laminae=build).render(Scene(cam, LIGHTS, (SceneObject(balls),)))
    finally:
        set_memory_budget(None)
    assert built == []


def test_union_needs_no_per_pixel_buffers_and_skips_hidden_leaves():
    # The same 600 nested spheres as a union, under the same 1 MB budget: filled by the depth
    # test nearest first, so the outermost sphere hides the others, whose bands are never built.
    balls = Union(*[Sphere((0.0, 0.0, 0.0), 1.0 + 0.001 * i) for i in range(600)])
    cam = Camera((0.0, -6.0, 0.0), (0, 0, 0), width=64, height=64)
    built = []

    def build(primitive, *args, **kwargs):
        built.append(primitive)
        return build_bands(primitive, *args, **kwargs)

    set_memory_budget(1 << 20)
    try:
        res = Renderer(build_laminae=build, adaptive_contours=False).render(Scene(cam, LIGHTS, (SceneObject(balls),)))
    finally:
        set_memory_budget(None)
    outer = Sphere((0.0, 0.0, 0.0), 1.599)
    assert built == [outer]
    alone = Renderer().render(Scene(cam, LIGHTS, (SceneObject(outer),)))
    assert np.array_equal(res.image, alone.image, equal_nan=True)
    assert set(np.unique(res.primitive_index).tolist()) == {-1, 599}


@pytest.mark.parametrize("as_csg", [False, True], ids=["objects", "union"])
def test_a_far_object_does_not_clip_a_near_one(as_csg):
    # A sphere 5 m away beside one 3e11 m away: each keeps its own near plane.
    near = Sphere((-1.5, 5.0, 0.0), 1.0)
    far = Sphere((0.9e11, 3e11, 0.0), 5e10)
    cam = Camera((0.0, 0.0, 0.0), (0.0, 1.0, 0.0), fov=60, width=96, height=64)
    objects = (SceneObject(Union(near, far)),) if as_csg else (SceneObject(near), SceneObject(far))
    res = Renderer(csg="pixel").render(Scene(cam, (PointLight((0.0, 0.0, 10.0)),), objects))
    shown = res.primitive_index if as_csg else res.object_index
    left, right = shown[:, :40], shown[:, 56:]
    assert (left == 0).sum() > 300 and (right == 1).sum() > 200
    assert np.isfinite(res.image).sum() == (shown >= 0).sum()
    d = res.depth[shown == 0]
    assert 3.9 < d.min() and d.max() < 5.1


def test_laminae_cache_is_bounded_by_bytes(monkeypatch):
    from isocsg.laminae import builder

    builder.clear_cache()
    one = builder.build_laminae(Sphere((0, 0, 0), 1.0), LIGHTS, Material(), 16)
    size = builder._nbytes(one)
    assert builder.cache_bytes() == size
    monkeypatch.setattr(builder, "CACHE_BYTES", int(2.5 * size))
    for i in range(6):
        builder.build_laminae(Sphere((float(i + 1), 0, 0), 1.0), LIGHTS, Material(), 16)
    info = builder.cache_info()
    assert info["size"] == 2 and builder.cache_bytes() <= 2.5 * size
    # the most recent sets are kept
    assert builder.build_laminae(Sphere((6.0, 0, 0), 1.0), LIGHTS, Material(), 16) is not None
    assert builder.cache_info()["hits"] == info["hits"] + 1
    builder.clear_cache()
    assert builder.cache_bytes() == 0


def test_renderer_caches_are_bounded_by_bytes():
    scene = plate_scene(4, 96, 80)
    # every leaf at the requested count, so that contours=48 below makes new bands for all
    r = Renderer(surface_build="now", adaptive_contours=False)  # "auto": per pixel first, then the surface
    r.render(scene)
    r.render(scene, camera=scene.camera.with_view((-30.0, -65.0, 90.0)))
    info = r.cache_info()
    assert info["prepared"] == 17 and info["surfaces"] == 1 and info["geometry"] == 1
    assert info["prepared_bytes"] > 0 and info["surfaces_bytes"] > 0
    limit = info["prepared_bytes"] // 3
    r._prepared.limit = limit
    r._surfaces.cache.limit = 1
    r.render(scene, contours=48)  # new bands: prepared again, older ones evicted
    r.render(scene, camera=scene.camera.with_view((-30.0, -65.0, 90.0)), contours=48)
    info = r.cache_info()
    assert 0 < info["prepared_bytes"] <= limit and 0 < info["prepared"] < 17
    assert info["surfaces"] == 1  # the newest entry stays, whatever its size
    r.clear_caches()
    assert r.cache_info()["prepared"] == 0


def test_auto_builds_large_trees_in_the_background_within_the_budget_share(monkeypatch):
    """Trees of more than SURFACE_MAX_LEAVES leaves: per pixel on their first view; the
    second starts the trimmed surface's build in the background (also under
    surface_build="now"), which later views fill; a surface over its share of the memory
    budget is given up once, and the tree stays per pixel."""
    calls = []
    real = surfaces.surface_from_bands

    def spy(program, bands, **kw):
        calls.append((program.n_leaves, kw.get("trim", False)))
        return real(program, bands, **kw)

    monkeypatch.setattr(surfaces, "surface_from_bands", spy)
    tiled = []
    real_tiled = painter.render_tiled
    monkeypatch.setattr(painter, "render_tiled", lambda *a, **k: tiled.append(1) or real_tiled(*a, **k))
    big = plate_scene(9, 96, 80)  # 82 leaves
    eyes = [(20.0, -70.0, 90.0), (-30.0, -65.0, 90.0), (35.0, -60.0, 95.0)]
    r = Renderer(surface_build="now")
    first = r.render(big, camera=big.camera.with_view(eyes[0]))
    assert calls == [] and len(tiled) == 1
    r.render(big, camera=big.camera.with_view(eyes[1]))  # per pixel, the build started
    assert r.wait_surfaces(timeout=300)
    assert calls == [(82, True)] and len(tiled) == 2
    again = r.render(big, camera=big.camera.with_view(eyes[0]))  # the surface: no per-pixel resolve
    assert len(tiled) == 2 and calls == [(82, True)]
    view = Scene(big.camera.with_view(eyes[0]), big.lights, big.objects, big.render)
    assert compare(again.image, plate_reference(view)).iou >= 0.99
    np.testing.assert_array_equal(np.isfinite(again.image), np.isfinite(first.image))
    # over its share of the budget: given up, per pixel from then on, not retried
    monkeypatch.setattr(policy, "LARGE_SURFACE_SHARE", 1e-9)
    other = plate_scene(8, 96, 80)  # 65 leaves
    r2 = Renderer()
    for eye in eyes:
        r2.render(other, camera=other.camera.with_view(eye))
        assert r2.wait_surfaces(timeout=300)
    # (given up before the Booleans: the plate alone, which no trim shrinks, is over the share)
    assert calls == [(82, True)] and len(tiled) == 5
    # small trees keep their path: the surface from the second view, untrimmed
    small = plate_scene(2, 96, 80)  # 5 leaves
    r.render(small)
    r.render(small, camera=small.camera.with_view(eyes[1]))
    assert r.wait_surfaces(timeout=120)
    assert calls[1:] == [(5, False)]
    # and under the triangle bound too
    monkeypatch.setattr(policy, "SURFACE_MAX_TRIANGLES", 10)
    other = plate_scene(3, 96, 80)
    r.render(other)
    r.render(other, camera=other.camera.with_view(eyes[1]))
    assert r.wait_surfaces(timeout=120)
    assert len(calls) == 2


def test_a_large_union_over_the_share_is_given_up_before_its_bands_are_all_asked_for(monkeypatch):
    """A union of 80 overlapping spheres (with a notch cut out, so that it is not a plain union,
    which the depth test alone resolves) can be neither trimmed nor parted: its Boolean takes
    every band triangle. The background build asks for the bands of such leaves first and
    gives up (per pixel for good) as soon as they pass the share of the budget, here after
    the first sphere's, instead of building all 80 to find out."""
    from isocsg.laminae import build_bands

    calls = []

    def counting(*a, **kw):
        calls.append(1)
        return build_bands(*a, **kw)

    monkeypatch.setattr(policy, "LARGE_SURFACE_SHARE", 1e-9)
    spheres = [Sphere((0.6 * (i % 5), 0.6 * (i // 5 % 4), 0.6 * (i // 20)), 0.4) for i in range(80)]
    notched = Union(*spheres) - Box((2.4, 0.0, 1.8), (0.3, 0.3, 0.3))
    cam = Camera((6.0, -8.0, 6.0), (1.2, 0.9, 0.9), fov=40, width=64, height=64)
    scene = Scene(cam, LIGHTS, (SceneObject(notched),), RenderSettings(contours=16))
    r = Renderer(build_laminae=counting)
    r.render(scene)
    assert len(calls) == 81  # this builder keeps nothing: each per-pixel view asks for every leaf
    r.render(scene, camera=cam.with_view((-6.0, -8.0, 6.0)))
    assert r.wait_surfaces(timeout=300)
    assert len(calls) == 2 * 81 + 1  # the second view's, and one in the background
    r.render(scene, camera=cam.with_view((6.0, 8.0, 6.0)))
    assert r.wait_surfaces(timeout=300)
    assert len(calls) == 3 * 81 + 1  # the third view per pixel; not tried again


@pytest.mark.parametrize("k", [10], ids=lambda k: f"{k * k}-holes")
def test_large_tree_surface_views_match_the_ray_caster(k, monkeypatch):
    """A plate of 100 holes (101 leaves, more than SURFACE_MAX_LEAVES): once its trimmed
    surface is built, new views fill it (no per-pixel resolve); each is judged by the
    analytic ray caster with the catalogue's bars (IoU >= 0.99, 98 % of compared pixels
    within 0.05)."""
    tiled = []
    real_tiled = painter.render_tiled
    monkeypatch.setattr(painter, "render_tiled", lambda *a, **kw: tiled.append(1) or real_tiled(*a, **kw))
    scene = plate_scene(k, 224, 176, contours=64)
    r = Renderer()
    r.render(scene)
    r.render(scene, camera=scene.camera.with_view((-30.0, -65.0, 90.0)))
    assert r.wait_surfaces(timeout=600)
    assert r.cache_info()["surfaces"] == 1
    for eye in [(20.0, -70.0, 90.0), (-30.0, -65.0, 90.0), (40.0, -60.0, 80.0)]:
        cam = scene.camera.with_view(eye)
        view = Scene(cam, scene.lights, scene.objects, scene.render)
        result = compare(r.render(view).image, plate_reference(view))
        assert result.iou >= 0.99, result.summary()
        assert result.fraction >= 0.98, result.summary()
    assert len(tiled) == 2  # the first two views only


def test_progress_is_reported_as_tiles_build(monkeypatch):
    _tiled(monkeypatch, (16,))
    calls = []
    scene = Scene(plate_scene(6, 96, 80).camera, LIGHTS, (SceneObject(plate(6)), SceneObject(Sphere((0, 60, 0), 5.0))))
    Renderer().render(scene, progress=lambda d, t: calls.append((d, t)))
    assert len(calls) > 5 and calls[-1] == (38, 38)
    done = [d for d, _ in calls]
    assert done == sorted(done) and all(t == 38 for _, t in calls)


def test_a_failing_builder_in_the_tiled_path_leaves_the_renderer_usable(monkeypatch):
    _tiled(monkeypatch, (16,))
    from isocsg.laminae import build_laminae

    count = [0]

    def flaky(primitive, lights, material, contours, *, eye):
        count[0] += 1
        if count[0] == 7:
            raise RuntimeError("builder failed")
        return build_laminae(primitive, lights, material, contours, eye=eye)

    scene = plate_scene(4, 96, 80)
    r = Renderer(build_laminae=flaky, csg="pixel")
    with pytest.raises(RuntimeError, match="builder failed"):
        r.render(scene)
    again = r.render(scene)
    monkeypatch.setattr(policy, "DENSE_MAX_LEAVES", 100)
    # the same builder (the default one also coarsens the tessellation by screen size)
    _assert_same(again, Renderer(build_laminae=build_laminae, csg="pixel").render(scene))
