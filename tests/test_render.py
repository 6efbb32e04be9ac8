"""Scene rendering: silhouettes, CSG resolution, depth test and band reuse.

The band meshes here come from a small builder written in this file (the
primitive's inscribed triangle mesh with the exact shading at each face
centre), so these tests check the fill, the per-pixel CSG and the composition
against analytic ray-sphere intervals computed independently below.
"""

from __future__ import annotations

import functools
import itertools
import re

import numpy as np
import pytest

from isocsg import (
    Box,
    Camera,
    Difference,
    Intersection,
    InvalidParameterError,
    Material,
    PointLight,
    Scene,
    SceneObject,
    Sphere,
    Union,
    shade,
)
from isocsg.csg.program import compile_program
from isocsg.laminae.model import BandMesh
from isocsg.rendering import Renderer
from isocsg.rendering import image as imagemod
from isocsg.rendering.pixel_csg import resolve_csg, truth_table

RES = 48  # segments of the inscribed test meshes


def mesh_bands(primitive, lights, material, contours, *, eye):
    """Faceted stand-in for the laminae: constant exact shading per face.

    ``value_in`` is made negative so that a test can tell which side is shown.
    """
    mesh = primitive.to_trimesh(RES)
    v = np.asarray(mesh.vertices, dtype=float)
    t = np.asarray(mesh.faces, dtype=np.int32)
    n = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    c = v[t].mean(axis=1)
    out = shade(c, n, eye, lights, material)
    inside = -1.0 - shade(c, -n, eye, lights, material)
    return BandMesh(v, t, out, inside, np.zeros(len(t), np.int32))


def sphere_intervals(camera: Camera, spheres):
    """Camera depth of entry and exit of every pixel ray for each sphere (inf / -inf on a miss)."""
    o = camera.ray_origins().reshape(-1, 3)
    d = camera.ray_directions().reshape(-1, 3)
    cosf = d @ camera.frame[0]
    fronts, backs, dist = [], [], []
    for s in spheres:
        oc = o - np.asarray(s.center)
        b = np.einsum("ij,ij->i", oc, d)
        disc = b * b - (np.einsum("ij,ij->i", oc, oc) - s.radius**2)
        hit = disc > 0
        sq = np.sqrt(np.where(hit, disc, 0))
        t0, t1 = -b - sq, -b + sq
        fronts.append(np.where(hit & (t0 > 0), t0 * cosf, np.where(hit & (t1 > 0), -np.inf, np.inf)))
        backs.append(np.where(hit & (t1 > 0), t1 * cosf, -np.inf))
        # distance from the centre to the ray line, relative to the radius
        dist.append(np.sqrt(np.maximum(np.einsum("ij,ij->i", oc, oc) - b * b, 0)) / s.radius)
    shape = (camera.height, camera.width)
    return [f.reshape(shape) for f in fronts], [b.reshape(shape) for b in backs], [x.reshape(shape) for x in dist]


LIGHTS = (PointLight((4.0, -6.0, 5.0)),)
CAM = Camera((0.5, -6.0, 1.5), (0, 0, 0), fov=40, width=64, height=56)
ORTHO = Camera((0.5, -6.0, 1.5), (0, 0, 0), width=60, height=50, orthographic=True, height_m=4.0)
CAMS = {"perspective": CAM, "orthographic": ORTHO}
# A pixel whose ray passes this close to a sphere's silhouette (relative) is left out: the
# inscribed mesh of RES segments lies within 1 - cos(pi / RES) of the true surface.
SIL = 0.01


def renderer():
    return Renderer(build_laminae=mesh_bands)


@pytest.mark.parametrize("cam", CAMS.values(), ids=CAMS.keys())
def test_sphere_silhouette_is_the_analytic_disc(cam):
    s = Sphere((0.2, 0.3, -0.1), 1.3)
    res = renderer().render(Scene(cam, LIGHTS, [s]), contours=8)
    _, _, (dist,) = sphere_intervals(cam, [s])
    clear = np.abs(dist - 1) > SIL
    disc = dist < 1
    assert disc[clear].sum() > 200 and (~disc)[clear].sum() > 200
    np.testing.assert_array_equal(np.isfinite(res.image)[clear], disc[clear])
    np.testing.assert_array_equal((res.object_index == 0)[clear], disc[clear])
    np.testing.assert_array_equal(res.primitive_index[clear], np.where(disc, 0, -1)[clear])
    assert np.all(res.image[np.isfinite(res.image)] > 0)  # only outside values of the front surface
    front, _, _ = sphere_intervals(cam, [s])
    ok = clear & disc
    np.testing.assert_allclose(res.depth[ok], front[0][ok], rtol=0.02)
    assert res.image.dtype == np.float32 and res.object_index.dtype == np.int32


def _random_tree(rng, pool, depth):
    if depth == 0 or rng.random() < 0.25:
        return pool[rng.integers(len(pool))]
    kind = rng.choice([Union, Intersection, Difference])
    k = int(rng.integers(2, 4))
    return kind(*[_random_tree(rng, pool, depth - 1) for _ in range(k)])


@pytest.mark.parametrize("use_table", [True, False], ids=["truth-table", "program"])
@pytest.mark.parametrize("seed", range(6), ids=lambda s: f"tree{s}")
def test_csg_resolution_matches_brute_force_on_intervals(seed, use_table):
    rng = np.random.default_rng(seed)
    pool = [Sphere((float(i), 0, 0), 1) for i in range(5)]
    tree = _random_tree(rng, pool, 3)
    if isinstance(tree, Sphere):
        tree = Union(tree, pool[-1])
    program = tree.program()
    n, h, w = program.n_leaves, 12, 10
    # Integer-valued keys: many coincident events exercise the grouping.
    f = rng.integers(0, 8, (n, h, w)).astype(float)
    b = f + rng.integers(0, 5, (n, h, w))
    empty = rng.random((n, h, w)) < 0.25
    eye_inside = rng.random((n, h, w)) < 0.1
    f[empty | eye_inside] = np.inf
    b[empty] = -np.inf
    vf = rng.uniform(0, 1, (n, h, w)).astype(np.float32)
    vb = -rng.uniform(0, 1, (n, h, w)).astype(np.float32)
    zkey = np.full((h, w), np.inf)
    zkey[0, :] = 2.5  # something already nearer in the image on row 0
    value = np.zeros((h, w), np.float32)
    gid = np.full((h, w), -1, np.int32)
    table = truth_table(program.op, program.arg, n) if use_table else np.zeros(0, np.bool_)
    resolve_csg(f, vf, b, vb, program.op, program.arg, table, 10, 0, 0, zkey, value, gid)
    n_visible = 0

    # Brute force: membership on each open stretch between consecutive distinct depths,
    # evaluated on the tree structure itself (not on the postfix program).
    def member(r, c, t):
        flags = [
            ((-np.inf if (f[i, r, c] == np.inf and b[i, r, c] > -np.inf) else f[i, r, c]) < t < b[i, r, c])
            for i in range(n)
        ]
        it = iter(flags)
        return _evaluate_positional(tree, it)

    for r, c in itertools.product(range(h), range(w)):
        ts = np.unique(np.concatenate([f[:, r, c], b[:, r, c]]))
        ts = ts[np.isfinite(ts)]
        expected = None
        prev = member(r, c, -1e9)
        for k, t in enumerate(ts):
            nxt = ts[k + 1] if k + 1 < len(ts) else t + 1.0
            now = member(r, c, (t + nxt) / 2)
            if now and not prev:
                expected = t
                break
            prev = now
        if expected is None or expected >= (2.5 if r == 0 else np.inf):
            assert gid[r, c] == -1
            continue
        n_visible += 1
        assert zkey[r, c] == expected
        leaf = gid[r, c] - 10
        assert 0 <= leaf < n
        # The shown surface is one of that leaf's surfaces at this depth, with the matching value.
        if value[r, c] > 0:
            assert f[leaf, r, c] == expected and value[r, c] == vf[leaf, r, c]
        else:
            assert b[leaf, r, c] == expected and value[r, c] == vb[leaf, r, c]
            # a back face shows only when no leaf enters at that depth
            entering = [i for i in range(n) if f[i, r, c] == expected]
            assert not entering
    assert n_visible > 5


def _evaluate_positional(node, flags):
    if isinstance(node, Sphere):
        return next(flags)
    vals = [_evaluate_positional(c, flags) for c in node.children]
    if isinstance(node, Union):
        return any(vals)
    if isinstance(node, Intersection):
        return all(vals)
    return vals[0] and not any(vals[1:])


def _visible_from_intervals(fronts, backs, tree_eval):
    """Analytic visible surface per pixel: (leaf, is_front, depth) from the exact intervals."""
    h, w = fronts[0].shape
    leaf = np.full((h, w), -1)
    is_front = np.zeros((h, w), bool)
    depth = np.full((h, w), np.inf)
    n = len(fronts)
    for r, c in itertools.product(range(h), range(w)):
        ev = sorted(
            [(fronts[i][r, c], i, True) for i in range(n) if np.isfinite(fronts[i][r, c])]
            + [(backs[i][r, c], i, False) for i in range(n) if np.isfinite(backs[i][r, c])]
        )
        state = [fronts[i][r, c] == -np.inf for i in range(n)]
        prev = tree_eval(state)
        for t, i, enter in ev:
            state[i] = enter
            now = tree_eval(state)
            if now and not prev:
                leaf[r, c], is_front[r, c], depth[r, c] = i, enter, t
                break
            prev = now
    return leaf, is_front, depth


CSG_CASES = {
    "difference": (Difference(Sphere((0, 0, 0), 1.2), Sphere((0.3, -0.9, 0.4), 0.8)), lambda s: s[0] and not s[1]),
    "intersection": (Intersection(Sphere((-0.4, 0, 0), 1.1), Sphere((0.4, 0.1, 0.1), 1.0)), lambda s: s[0] and s[1]),
    "union": (Union(Sphere((-0.5, 0, 0), 0.9), Sphere((0.6, 0.2, 0.1), 0.8)), lambda s: s[0] or s[1]),
}


@pytest.mark.parametrize("cam", CAMS.values(), ids=CAMS.keys())
@pytest.mark.parametrize("case", CSG_CASES.values(), ids=CSG_CASES.keys())
def test_csg_render_matches_analytic_intervals(case, cam):
    tree, tree_eval = case
    leaves = tree.leaves()
    res = renderer().render(Scene(cam, LIGHTS, [tree]), contours=8)
    fronts, backs, dists = sphere_intervals(cam, leaves)
    leaf, is_front, depth = _visible_from_intervals(fronts, backs, tree_eval)
    # Leave out pixels near a silhouette or where two surfaces are nearly at the same depth.
    clear = np.all([np.abs(d - 1) > SIL for d in dists], axis=0)
    ev = np.stack([np.where(np.isfinite(x), x, np.nan) for x in fronts + backs])
    srt = np.sort(ev, axis=0)
    with np.errstate(invalid="ignore"):
        close = np.nanmin(np.where(np.isnan(np.diff(srt, axis=0)), np.inf, np.diff(srt, axis=0)), axis=0) < 0.05
    clear &= ~close
    assert clear.mean() > 0.7
    np.testing.assert_array_equal(res.primitive_index[clear], leaf[clear])
    shown = clear & (leaf >= 0)
    assert shown.sum() > 150
    np.testing.assert_array_equal((res.image[shown] > 0), is_front[shown])
    np.testing.assert_allclose(res.depth[shown], depth[shown], rtol=0.02)
    if tree_eval is CSG_CASES["difference"][1]:
        assert (shown & ~is_front).sum() > 50  # the inside of the cut is really seen


def test_empty_difference_renders_background_only():
    scene = Scene(CAM, LIGHTS, [Sphere((0, 0, 0), 0.5) - Sphere((0, 0, 0), 1.0)])
    res = renderer().render(scene, contours=4)
    assert np.all(np.isnan(res.image))
    assert np.all(res.object_index == -1) and np.all(res.primitive_index == -1)
    assert np.all(np.isinf(res.depth))


@pytest.mark.parametrize("cam", CAMS.values(), ids=CAMS.keys())
def test_several_objects_nearest_wins(cam):
    a = Sphere((-0.3, 0.8, 0.0), 1.0)
    b = Sphere((0.5, -0.6, 0.2), 0.7)
    c = Sphere((0.0, 0.0, 0.0), 0.9) - Sphere((0.0, -0.7, 0.0), 0.5)
    spheres = [a, b] + c.leaves()
    scene = Scene(cam, LIGHTS, [SceneObject(a), SceneObject(b, Material(kd=0.5)), SceneObject(c)])
    res = renderer().render(scene, contours=4)
    fronts, backs, dists = sphere_intervals(cam, spheres)
    # Visible depth of the CSG object from its analytic intervals.
    cl, cf, cd = _visible_from_intervals(fronts[2:], backs[2:], lambda s: s[0] and not s[1])
    cand = np.stack([np.where(np.isfinite(fronts[0]) & (fronts[0] > 0), fronts[0], np.inf),
                     np.where(np.isfinite(fronts[1]) & (fronts[1] > 0), fronts[1], np.inf), cd])
    nearest = np.where(np.isinf(cand.min(axis=0)), -1, cand.argmin(axis=0))
    srt = np.sort(cand, axis=0)
    with np.errstate(invalid="ignore"):
        clear = np.all([np.abs(d - 1) > SIL for d in dists], axis=0) & ~(srt[1] - srt[0] < 0.05)
    assert len(np.unique(nearest[clear])) == 4  # background and all three objects
    np.testing.assert_array_equal(res.object_index[clear], nearest[clear])


def test_progress_reports_every_primitive():
    calls = []
    scene = Scene(CAM, LIGHTS, [Sphere((0, 0, 0), 1), Union(Sphere((2, 0, 0), 1), Sphere((2, 0, 1), 1))])
    renderer().render(scene, contours=4, progress=lambda d, t: calls.append((d, t)))
    assert calls[-1] == (3, 3)
    assert [d for d, _ in calls] == sorted(d for d, _ in calls)


def test_bands_are_reused_from_a_new_viewpoint():
    """The builder caches view-independent bands; a new camera only fills again."""
    built = []

    @functools.cache
    def cached(primitive, lights, material, contours):
        built.append(primitive)
        return mesh_bands(primitive, lights, material, contours, eye=(0.0, 0.0, 0.0))

    def build(primitive, lights, material, contours, *, eye):
        return cached(primitive, lights, material, contours)

    # Every primitive with the requested count (not one by its size on screen).
    r = Renderer(build_laminae=build, adaptive_contours=False)
    scene = Scene(CAM, LIGHTS, [Sphere((0, 0, 0), 1) | Sphere((1, 0, 0), 1), Sphere((0, 2, 0), 0.5)])
    first = r.render(scene, contours=16)
    assert len(built) == 3
    second = r.render(scene, camera=CAM.with_view((3.0, -4.0, 2.0)), contours=16)
    assert len(built) == 3
    assert np.isfinite(second.image).sum() > 100
    assert not np.array_equal(np.isfinite(first.image), np.isfinite(second.image))
    r.render(scene, contours=17)
    assert len(built) == 6


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [({"contours": 0}, "contours"), ({"camera": "cam"}, "camera must be a Camera, got str")],
    ids=["contours", "camera"],
)
def test_bad_arguments_raise(kwargs, message):
    with pytest.raises(InvalidParameterError, match=message):
        renderer().render(Scene(CAM, LIGHTS, [Sphere((0, 0, 0), 1)]), **kwargs)


def test_not_a_scene_raises():
    with pytest.raises(InvalidParameterError, match="scene must be a Scene, got list"):
        renderer().render([Sphere((0, 0, 0), 1)])


# ------------------------------------------------------------------- images
def test_to_uint8_follows_the_conventions():
    from isocsg.rendering.image import to_uint8

    img = np.array([[np.nan, -0.5, 0.0, 0.2], [0.5, 0.999, 1.0, 3.0]], np.float32)
    expected = [[0, 0, 0, round(0.2 * 255)], [round(0.5 * 255), round(0.999 * 255), 255, 255]]
    assert to_uint8(img).dtype == np.uint8
    np.testing.assert_array_equal(to_uint8(img), expected)


def test_png_and_npy_round_trip(tmp_path):
    from PIL import Image

    from isocsg.rendering.image import save_npy, save_png, to_uint8

    res = renderer().render(Scene(CAM, LIGHTS, [Sphere((0, 0, 0), 1)]), contours=8)
    save_png(tmp_path / "a.png", res.image)
    save_npy(tmp_path / "a.npy", res.image)
    png = np.asarray(Image.open(tmp_path / "a.png"))
    assert png.shape == (CAM.height, CAM.width) and png.dtype == np.uint8
    np.testing.assert_array_equal(png, to_uint8(res.image))
    back = np.load(tmp_path / "a.npy")
    assert back.dtype == np.float32
    np.testing.assert_array_equal(np.isnan(back), np.isnan(res.image))
    np.testing.assert_array_equal(back[~np.isnan(back)], res.image[~np.isnan(res.image)])


def test_png_goes_to_a_binary_file_object(tmp_path):
    import io

    from PIL import Image

    from isocsg.rendering.image import save_png, to_uint8

    res = renderer().render(Scene(CAM, LIGHTS, [Sphere((0, 0, 0), 1)]), contours=8)
    buf = io.BytesIO()
    save_png(buf, res.image)
    np.testing.assert_array_equal(np.asarray(Image.open(io.BytesIO(buf.getvalue()))), to_uint8(res.image))
    with open(tmp_path / "b.png", "wb") as fh:  # an open file, as for standard output
        save_png(fh, res.image)
    np.testing.assert_array_equal(np.asarray(Image.open(tmp_path / "b.png")), to_uint8(res.image))
    with pytest.raises(InvalidParameterError, match=re.escape("path must be a path or a binary file object, got the text stream")):
        save_png(io.StringIO(), res.image)
    with pytest.raises(InvalidParameterError, match=re.escape("path must be a path or a binary file object, got int")):
        save_png(3, res.image)


def test_svg_keeps_order_colour_and_fixed_decimals(tmp_path):
    import xml.etree.ElementTree as ET

    from isocsg.rendering.image import save_svg

    polys = [[(0, 0), (10, 0), (10, 10)], [(1.23456, 2), (5, 5), (2, 7.5), (0, 3)]]
    save_svg(tmp_path / "a.svg", polys, [0.0, 1.0], width=10, height=10, decimals=3)
    root = ET.parse(tmp_path / "a.svg").getroot()
    ns = "{http://www.w3.org/2000/svg}"
    got = root.findall(f"{ns}polygon")
    assert [g.get("fill") for g in got] == ["#000000", "#ffffff"]
    assert got[1].get("points") == "1.235,2.000 5.000,5.000 2.000,7.500 0.000,3.000"
    assert root.get("viewBox") == "0 0 10 10"


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda p: imagemod.save_png(p, np.zeros(3)), "image must have shape (H, W) or (H, W, 3), got (3,)"),
        (lambda p: imagemod.save_svg(p, [[(0, 0), (1, 1)]], [0.5], width=2, height=2),
         "polygons[0] must have shape (k, 2) with k >= 3, got (2, 2)"),
        (lambda p: imagemod.save_svg(p, [], [0.5], width=2, height=2),
         "values must have one entry per polygon (0), got 1"),
    ],
    ids=["png-shape", "svg-polygon", "svg-values"],
)
def test_image_writers_reject_bad_input(tmp_path, call, message):
    import re

    with pytest.raises(InvalidParameterError, match=re.escape(message)):
        call(tmp_path / "x")


def test_results_kept_by_the_caller_are_never_overwritten():
    """Buffers are recycled only once no result refers to them."""
    r = renderer()
    scene = Scene(CAM, LIGHTS, [Sphere((0, 0, 0), 1) - Sphere((0.5, -0.5, 0.5), 0.6)])
    first = r.render(scene, contours=8)
    snapshot = (first.image.copy(), first.object_index.copy(), first.primitive_index.copy())
    first_depth = first.depth.copy()
    views = [r.render(scene, camera=CAM.with_view(eye), contours=8) for eye in [(3, -4, 2), (-3, -4, 1), (0, -6, -2)]]
    np.testing.assert_array_equal(first.image, snapshot[0])
    np.testing.assert_array_equal(first.object_index, snapshot[1])
    np.testing.assert_array_equal(first.primitive_index, snapshot[2])
    np.testing.assert_array_equal(first.depth, first_depth)
    assert len({id(v.image) for v in views} | {id(first.image)}) == 4
    # Dropped results give their buffers back: a fresh render from the first view is identical.
    del views
    again = r.render(scene, contours=8)
    np.testing.assert_array_equal(again.image, snapshot[0])


# ------------------------------------------------- with the real laminae bands
def _real_builder():
    try:
        from isocsg.laminae import build_laminae
    except ImportError:  # pragma: no cover - only while the laminae package is incomplete
        pytest.skip("isocsg.laminae.build_laminae is not available")
    return build_laminae


def box_entry(camera: Camera, box_lo, box_hi):
    """Slab-test entry depth of each pixel ray into an axis-aligned box, and the slab margin."""
    o = camera.ray_origins().reshape(-1, 3)
    d = camera.ray_directions().reshape(-1, 3)
    with np.errstate(divide="ignore", invalid="ignore"):
        t0 = (np.asarray(box_lo) - o) / d
        t1 = (np.asarray(box_hi) - o) / d
    tn = np.nanmax(np.minimum(t0, t1), axis=1)
    tf = np.nanmin(np.maximum(t0, t1), axis=1)
    hit = (tn < tf) & (tf > 0)
    shape = (camera.height, camera.width)
    return hit.reshape(shape), ((tf - tn) * (d @ camera.frame[0])).reshape(shape)


def test_real_bands_sphere_silhouette_and_light_side():
    _real_builder()
    s = Sphere((0.1, 0.0, 0.2), 1.2)
    res = Renderer().render(Scene(CAM, LIGHTS, [s]), contours=32)
    front, _, (dist,) = sphere_intervals(CAM, [s])
    clear = np.abs(dist - 1) > 0.03
    np.testing.assert_array_equal(np.isfinite(res.image)[clear], (dist < 1)[clear])
    # Band values follow the exact shading within the width of one band.
    o = CAM.ray_origins().reshape(-1, 3)
    d = CAM.ray_directions().reshape(-1, 3)
    ok = (clear & (dist < 1)).reshape(-1)
    t = front[0].reshape(-1)[ok] / (d[ok] @ CAM.frame[0])
    p = o[ok] + t[:, None] * d[ok]
    exact = shade(p, p - np.asarray(s.center), CAM.eye, LIGHTS)
    err = np.abs(res.image.reshape(-1)[ok] - exact)
    assert np.median(err) < 0.9 / 32 and np.quantile(err, 0.99) < 4 * 0.9 / 32


def test_real_bands_box_silhouette():
    from isocsg import Box

    _real_builder()
    b = Box((0.0, 0.2, -0.1), (1.4, 1.0, 1.6))
    res = Renderer().render(Scene(CAM, LIGHTS, [b]), contours=16)
    lo = np.asarray(b.center) - np.asarray(b.size) / 2
    hit, thickness = box_entry(CAM, lo, lo + np.asarray(b.size))
    # Leave out rays that graze an edge (a thin chord through the box).
    clear = ~hit | (thickness > 0.02)
    np.testing.assert_array_equal(np.isfinite(res.image)[clear], hit[clear])


def test_real_bands_are_not_rebuilt_for_a_new_viewpoint():
    build = _real_builder()
    seen = []

    def spy(primitive, lights, material, contours, *, eye):
        out = build(primitive, lights, material, contours, eye=eye)
        seen.append(getattr(out, "bands", out))
        return out

    scene = Scene(CAM, LIGHTS, [Sphere((0, 0, 0), 1) - Sphere((0.6, -0.6, 0.4), 0.6)])
    r = Renderer(build_laminae=spy)
    r.render(scene, contours=24)
    r.render(scene, camera=CAM.with_view((-3.0, -4.0, 2.5)), contours=24)
    assert len(seen) == 4
    # The very same band meshes come back: nothing was rebuilt for the second view.
    assert seen[2] is seen[0] and seen[3] is seen[1]


def test_malformed_band_mesh_is_reported():
    def bad(primitive, lights, material, contours, *, eye):
        m = mesh_bands(primitive, lights, material, contours, eye=eye)
        return BandMesh(m.vertices, m.triangles + 1, m.value_out, m.value_in, m.band)

    with pytest.raises(InvalidParameterError, match="band mesh of .* is malformed"):
        Renderer(build_laminae=bad).render(Scene(CAM, LIGHTS, [Sphere((0, 0, 0), 1)]), contours=4)


def _concurrency_scenes():
    from isocsg import Cylinder

    plain = Scene(
        Camera((0.4, -5, 1.2), (0, 0, 0), width=640, height=520),
        [PointLight((3, -4, 5))],
        [Sphere((0, 0, 0), 1.0), Box((0.8, 0.6, -0.2), (1.0, 1.0, 1.0))],
    )
    part = (Box((0, 0, 0), (1.6, 1.6, 1.6)) - Cylinder((0, 0, 0), (2.4, 0, 0), 0.45)) & Sphere((0, 0, 0), 1.05)
    csg = Scene(Camera((3, -4, 3), (0, 0, 0), width=420, height=380), [PointLight((4, -3, 5))], [part])
    # Large enough on screen for the leaf worker: the last leaf's rows are shared
    # by both threads, unless its mesh is an earlier leaf's too.
    ball = Sphere((0, 0, 0), 1.0)
    big = Camera((2.2, -2.6, 1.6), (0, 0, 0), width=700, height=640)
    large = Scene(big, [PointLight((4, -3, 5))], [ball - Cylinder((0, 0, 0), (0, 0, 3), 0.45)])
    repeated = Scene(big, [PointLight((4, -3, 5))], [(ball - Cylinder((0, 0, 0), (0, 0, 3), 0.45)) | (ball & Box((0.5, 0, 0), (1, 1, 1)))])
    return {"plain-stripes": plain, "csg-leaves-and-stripes": csg, "csg-large": large, "csg-repeated-leaf": repeated}


@pytest.mark.parametrize("csg", ["pixel", "surface"], ids=str)
@pytest.mark.parametrize("name", ["plain-stripes", "csg-leaves-and-stripes", "csg-large", "csg-repeated-leaf"], ids=str)
def test_concurrent_fill_equals_the_serial_one(name, csg, monkeypatch):
    # Large images of plain primitives are filled in concurrent row stripes; CSG
    # objects fill their leaves and resolve row stripes concurrently (per pixel)
    # or fill their surface's parts in stripes. Every pixel must come out
    # exactly as from one serial pass.
    from isocsg.rendering import dense, policy

    scene = _concurrency_scenes()[name]
    monkeypatch.setattr(policy, "STRIPES", 3)
    calls = []
    fill = dense.fill_projected
    monkeypatch.setattr(dense, "fill_projected", lambda *a: calls.append(a[7]) or fill(*a))  # a[7]: first row
    threaded = Renderer(csg=csg).render(scene)
    if csg == "pixel" and name == "csg-large":  # the sphere (last) in row chunks
        assert len(calls) == 1 + policy.LAST_CHUNKS and len(set(calls)) == policy.LAST_CHUNKS
    if csg == "pixel" and name == "csg-repeated-leaf":  # the last leaf's mesh was filled before: whole
        assert len(calls) == 4
    monkeypatch.setattr(policy, "STRIPES", 1)
    serial = Renderer(csg=csg).render(scene)
    np.testing.assert_array_equal(threaded.image, serial.image)
    np.testing.assert_array_equal(threaded.object_index, serial.object_index)
    np.testing.assert_array_equal(threaded.primitive_index, serial.primitive_index)
    assert np.isfinite(serial.image).sum() > 0.1 * serial.image.size


@pytest.mark.parametrize("method", ["pixel", "surface"], ids=str)
def test_reused_buffers_render_like_fresh_ones(method):
    # The private depth and label buffers are reset only where the previous
    # render wrote: a sequence of views (near, far, plain and CSG objects,
    # results dropped so that buffers are reused) must match fresh renderers.
    scenes = _concurrency_scenes()
    plain, csg = scenes["plain-stripes"], scenes["csg-leaves-and-stripes"]
    mixed = Scene(plain.camera, plain.lights, [*plain.objects, *csg.objects])
    near = Camera((0.3, -2.2, 0.6), (0, 0, 0), width=640, height=520)
    far = Camera((2.0, -14, 3.0), (0, 0, 0), width=640, height=520)
    steps = [(plain, near), (plain, far), (mixed, near), (plain, far), (mixed, far), (plain, near)]
    # Fixed contour counts: with the level of detail a renderer keeps the finer count an
    # earlier (nearer) view gave a primitive, which a fresh renderer would not.
    reused = Renderer(csg=method, adaptive_contours=False)
    for scene, cam in steps:
        got = reused.render(scene, camera=cam)
        want = Renderer(csg=method, adaptive_contours=False).render(scene, camera=cam)
        np.testing.assert_array_equal(got.image, want.image)
        np.testing.assert_array_equal(got.object_index, want.object_index)
        np.testing.assert_array_equal(got.primitive_index, want.primitive_index)
        np.testing.assert_array_equal(got.depth, want.depth)
        del got, want


def test_auto_builds_the_csg_surface_on_the_second_render_only(monkeypatch):
    # "auto" with surface_build="now": the first view of a CSG object is resolved per
    # pixel; the second view builds the clipped surface once, and later views reuse it.
    from isocsg.rendering import surfaces

    scene = _concurrency_scenes()["csg-leaves-and-stripes"]
    views = [scene.camera, scene.camera.with_view((-3.0, -4.0, 2.0)), scene.camera]
    # Fixed contour counts, so that fresh renderers see the same bands as one that keeps
    # the finer counts of earlier views (the level of detail's memory).
    expected = [Renderer(csg=m, adaptive_contours=False).render(scene, camera=c).image
                for m, c in zip(["pixel", "surface", "surface"], views)]
    calls = []
    real = surfaces.surface_from_bands
    monkeypatch.setattr(surfaces, "surface_from_bands", lambda program, bands: calls.append(1) or real(program, bands))
    renderer = Renderer(surface_build="now", adaptive_contours=False)
    counts = []
    for cam, want in zip(views, expected):
        got = renderer.render(scene, camera=cam)
        counts.append(len(calls))
        np.testing.assert_array_equal(got.image, want)
    assert counts == [0, 1, 1]


def test_auto_builds_the_csg_surface_in_the_background(monkeypatch):
    # The default surface_build="background": the second view starts the surface on
    # the surface thread and is resolved per pixel meanwhile (it never waits for the
    # Boolean, held here until the view is done); views after it is ready use it.
    import threading

    from isocsg.rendering import surfaces

    scene = _concurrency_scenes()["csg-leaves-and-stripes"]
    views = [scene.camera, scene.camera.with_view((-3.0, -4.0, 2.0)), scene.camera]
    fixed = {"adaptive_contours": False}  # the same bands in every renderer (see above)
    pixel = [Renderer(csg="pixel", **fixed).render(scene, camera=c).image for c in views[:2]]
    surface = Renderer(csg="surface", **fixed).render(scene, camera=views[2]).image
    release = threading.Event()
    calls = []
    real = surfaces.surface_from_bands

    def held(program, bands):
        calls.append(threading.current_thread().name)
        assert release.wait(60)
        return real(program, bands)

    monkeypatch.setattr(surfaces, "surface_from_bands", held)
    renderer = Renderer(**fixed)
    np.testing.assert_array_equal(renderer.render(scene, camera=views[0]).image, pixel[0])
    np.testing.assert_array_equal(renderer.render(scene, camera=views[1]).image, pixel[1])  # not blocked
    assert not renderer.wait_surfaces(timeout=0.01)
    release.set()
    assert renderer.wait_surfaces(timeout=60)
    np.testing.assert_array_equal(renderer.render(scene, camera=views[2]).image, surface)
    assert len(calls) == 1 and calls[0].startswith("isocsg-surface")


def test_unknown_surface_build_is_refused():
    with pytest.raises(InvalidParameterError, match=re.escape("surface_build must be one of background, now, got 'later'")):
        Renderer(surface_build="later")


def test_unknown_csg_method_is_refused():
    with pytest.raises(InvalidParameterError, match=re.escape("csg must be one of auto, surface, pixel, got 'mesh'")):
        Renderer(csg="mesh")


RECT_CAMERAS = {
    "perspective": Camera((0.4, -5.0, 1.6), (0.3, 0, 0.2), fov=50, width=90, height=70),
    "wide": Camera((2.5, -2.2, 0.9), (0, 0, 0), fov=100, width=80, height=80),
    "orthographic": Camera((0.4, -5.0, 1.6), (0, 0, 0), width=64, height=48, orthographic=True, height_m=4.0),
}


@pytest.mark.parametrize("cam", RECT_CAMERAS.values(), ids=RECT_CAMERAS.keys())
def test_screen_rectangle_holds_every_pixel_of_the_solid(cam):
    # The per-pixel CSG buffers cover a rectangle computed before any band
    # exists; every pixel whose ray meets the solid must lie inside it, and a
    # sphere's rectangle must be tight (one pixel of margin). Rays against
    # spheres and boxes are intersected here, independently of the renderer.
    from isocsg.rendering import renderpass

    s1, s2 = Sphere((0.3, 0.2, -0.1), 0.9), Sphere((-0.8, 0.4, 0.5), 0.6)
    box = Box((0.6, -0.2, 0.3), (1.4, 0.8, 1.1))
    o = cam.ray_origins().reshape(-1, 3)
    d = cam.ray_directions().reshape(-1, 3)

    def hits_sphere(s):
        oc = o - s.center_array
        bq = np.einsum("ij,ij->i", oc, d)
        disc = bq * bq - (np.einsum("ij,ij->i", oc, oc) - s.radius**2) * np.einsum("ij,ij->i", d, d)
        return (disc >= 0) & (-bq + np.sqrt(np.maximum(disc, 0)) > 0)

    def hits_box(bx):
        lo, hi = np.asarray(bx.bounds)
        with np.errstate(divide="ignore", invalid="ignore"):
            t1, t2 = (lo - o) / d, (hi - o) / d
        tn, tx = np.nanmax(np.minimum(t1, t2), axis=1), np.nanmin(np.maximum(t1, t2), axis=1)
        return (tn <= tx) & (tx > 0)

    cases = {
        s1: hits_sphere(s1), box: hits_box(box),
        s1 | s2: hits_sphere(s1) | hits_sphere(s2), s1 & box: hits_sphere(s1) & hits_box(box),
        s1 - box: hits_sphere(s1),
    }
    for solid, hit in cases.items():
        c0, r0, c1, r1 = renderpass.screen_rect(compile_program(solid), cam)
        rows, cols = np.divmod(np.flatnonzero(hit), cam.width)
        assert len(rows) > 20
        assert r0 <= rows.min() and rows.max() < r1 and c0 <= cols.min() and cols.max() < c1, solid
        if isinstance(solid, Sphere):
            assert r0 >= rows.min() - 2 and r1 <= rows.max() + 3 and c0 >= cols.min() - 2 and c1 <= cols.max() + 3
