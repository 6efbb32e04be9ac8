"""Half-tone rendering: first hits, shadows on a floor, the interval speed-up.

Judges: the analytic reference ray caster of the tests (first hits of CSG
trees), similar triangles (umbra and penumbra squares of a square occluder
under a parallel square source), Lambert's formula written in the test for
lit floor points, and the discrete interpolation bound: on a run [a, b] of
pixels interpolated linearly, |E - L| <= (i - a)(b - i) / 2 * max |second
difference of the exact E| over the run.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from isocsg import Box, Camera, ConvexPolyhedron, InvalidLightError, InvalidParameterError, PointLight, Scene, Sphere
from isocsg.lighting.area import AreaLight, PolyhedronLight
from isocsg.scene.model import RenderSettings
from isocsg.shadows.halftone import first_hits, render_halftone

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference.raycaster import camera_rays  # noqa: E402
from reference.raycaster import first_hit as reference_first_hit  # noqa: E402

S, A, HS, HO, T = 1.0, 0.8, 2.0, 1.0, 0.02


def _square(cx, cy, z, s, down=True):
    h = s / 2
    pts = [(cx - h, cy - h, z), (cx - h, cy + h, z), (cx + h, cy + h, z), (cx + h, cy - h, z)]
    return pts if down else pts[::-1]


def _lambert(p, n, poly, L):
    e = 0.0
    for a, b in zip(poly, np.roll(poly, -1, axis=0)):
        u, v = a - p, b - p
        g = np.cross(u, v)
        e += np.arctan2(np.linalg.norm(g), u @ v) * (n @ (g / np.linalg.norm(g)))
    return abs(L / 2 * e)


def _floor_scene(width=64, height=64, interval=1):
    lamp = AreaLight(_square(0, 0, HS, S), radiance=2.0)
    floor = Box((0, 0, -0.05), (6, 6, 0.1))
    occ = Box((0, 0, HO), (A, A, T))
    # between the occluder and the floor, looking down: the umbra lies right under the occluder
    cam = Camera((0.05, 0.1, 0.8), (0.05, 0.1, 0.0), up=(0, 1, 0), fov=120, width=width, height=height)
    return Scene(cam, [lamp], [floor, occ], RenderSettings(mode="halftone", interval=interval, exposure=0.5))


def test_floor_shadows_at_the_similar_triangle_positions():
    scene = _floor_scene()
    r = render_halftone(scene, interval=1)
    o, d = camera_rays(scene.camera)
    o, d = o.reshape(-1, 3), d.reshape(-1, 3)
    ref = reference_first_hit(scene.objects[0].shape, o, d)
    ref_occ = reference_first_hit(scene.objects[1].shape, o, d)
    on_floor = np.isfinite(ref.t) & (ref.t < ref_occ.t) & (ref.normal[:, 2] > 0.99)
    p = o + np.where(on_floor, ref.t, 0)[:, None] * d
    ztop, zbot = HO + T / 2, HO - T / 2
    x_pen = -S / 2 + (A / 2 + S / 2) * HS / (HS - ztop)
    x_umb = S / 2 + (A / 2 - S / 2) * HS / (HS - zbot)
    m = np.max(np.abs(p[:, :2]), axis=1)  # regions are axis-aligned squares
    expected = np.where(m < x_umb, 2, np.where(m < x_pen, 1, 0))
    # floor footprint of each pixel: the distance to its neighbours' floor points
    P = p.reshape(64, 64, 3)
    foot = np.zeros((64, 64))
    foot[:, :-1] = np.maximum(foot[:, :-1], np.linalg.norm(P[:, 1:] - P[:, :-1], axis=2))
    foot[:-1, :] = np.maximum(foot[:-1, :], np.linalg.norm(P[1:] - P[:-1], axis=2))
    pixel = foot.ravel()
    clear = on_floor & (np.abs(m - x_umb) > pixel) & (np.abs(m - x_pen) > pixel)
    shadow = r.shadow.ravel()
    np.testing.assert_array_equal(shadow[clear], expected[clear])
    assert np.bincount(expected[clear], minlength=3).min() > 30
    E = r.image.ravel()
    assert np.all(E[clear & (expected == 2)] == 0)
    lit = np.nonzero(clear & (expected == 0))[0][::17]
    ref_E = [_lambert(p[i], np.array([0, 0, 1.0]), np.array(_square(0, 0, HS, S)), 2.0) for i in lit]
    np.testing.assert_allclose(E[lit], ref_E, rtol=2e-6)  # float32 image
    pen = clear & (expected == 1)
    full = np.array([_lambert(p[i], np.array([0, 0, 1.0]), np.array(_square(0, 0, HS, S)), 2.0) for i in np.nonzero(pen)[0]])
    assert np.all((E[pen] > 0) & (E[pen] < full))
    assert np.isnan(r.image).sum() == (r.object_index < 0).sum()
    np.testing.assert_allclose(r.display[~np.isnan(r.image)], np.clip(r.image[~np.isnan(r.image)] * 0.5, 0, 1))


def _scenes():
    lamp = AreaLight(_square(0.3, -0.2, 2.6, 0.9), radiance=2.0)
    prism = PolyhedronLight([(x, y, z) for x in (-0.4, 0.4) for y in (-0.15, 0.15) for z in (2.3, 2.5)], radiance=2.0)
    objects = [
        Box((0, 0, -0.05), (5, 5, 0.1)),
        Box((0.5, 0.3, 0.5), (0.6, 0.6, 1.0)),
        ConvexPolyhedron([(-1.2, -0.6, 0), (-0.4, -1.0, 0), (-0.8, 0.0, 0), (-0.8, -0.5, 0.9)]),
        Sphere((-0.2, 0.9, 0.45), 0.4) - Box((-0.2, 0.9, 0.85), (0.5, 0.5, 0.3)),
    ]
    cam = Camera((3.5, -5.0, 4.0), (0, 0, 0.3), fov=40, width=96, height=72)
    return [("area", Scene(cam, [lamp], objects)), ("prism", Scene(cam, [prism], objects))]


SCENES = _scenes()


@pytest.mark.parametrize("name,scene", SCENES, ids=[s[0] for s in SCENES])
def test_interval_mode_matches_exact_mode(name, scene):
    ex = render_halftone(scene, interval=1, resolution=16)
    assert ex.exact.all() or np.all(ex.exact[ex.object_index >= 0])
    step = 4
    r = render_halftone(scene, interval=step, resolution=16)
    vis = ex.object_index >= 0
    np.testing.assert_array_equal(r.shadow, ex.shadow)
    # exact pixels are identical
    np.testing.assert_array_equal(r.image[r.exact], ex.image[r.exact])
    # every pixel next to a face or shadow boundary along its scanline is exact
    sid, sh = ex.surface_id, ex.shadow
    change = (sid[:, 1:] != sid[:, :-1]) | (sh[:, 1:] != sh[:, :-1])
    boundary = np.zeros_like(vis)
    boundary[:, 1:] |= change
    boundary[:, :-1] |= change
    assert np.all(r.exact[boundary & vis])
    assert r.exact_fraction < 0.75  # the speed-up does something
    # interpolated pixels obey the discrete interpolation bound of the exact image
    E = ex.image.astype(np.float64)
    d2 = np.full_like(E, np.inf)
    d2[:, 1:-1] = np.abs(E[:, 2:] - 2 * E[:, 1:-1] + E[:, :-2])
    checked = 0
    for row in range(E.shape[0]):
        cols = np.nonzero(r.exact[row] | ~vis[row])[0]
        for a, b in zip(cols[:-1], cols[1:]):
            if b - a < 2 or not vis[row, a] or not vis[row, b]:
                continue
            M = np.max(d2[row, a + 1:b])
            i = np.arange(a + 1, b)
            bound = (i - a) * (b - i) / 2 * M + 1e-6 * (1 + np.abs(E[row, i]))
            assert np.all(np.abs(r.image[row, i] - E[row, i]) <= bound), (row, a, b)
            checked += len(i)
    assert checked > 0.2 * vis.sum()


def test_first_hits_match_the_reference_ray_caster():
    scene = SCENES[0][1]
    o, d = camera_rays(scene.camera)
    o, d = o.reshape(-1, 3), d.reshape(-1, 3)
    mine = first_hits(scene.objects, o, d)
    best = np.full(len(d), np.inf)
    normal = np.zeros((len(d), 3))
    for ob in scene.objects:
        h = reference_first_hit(ob.shape, o, d)
        better = h.t < best
        best[better] = h.t[better]
        normal[better] = h.normal[better]
    hit = np.isfinite(best)
    np.testing.assert_array_equal(np.isfinite(mine.t), hit)
    np.testing.assert_allclose(mine.t[hit], best[hit], rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(mine.normal[hit], normal[hit], atol=1e-9)


def test_errors_and_ignored_point_lights():
    scene = _floor_scene(8, 8)
    with pytest.raises(InvalidParameterError, match="interval"):
        render_halftone(scene, interval=0)
    no_area = Scene(scene.camera, [PointLight((0, 0, 5))], scene.objects)
    with pytest.raises(InvalidLightError, match="scene.lights"):
        render_halftone(no_area)
    mixed = Scene(scene.camera, [PointLight((0, 0, 5)), *scene.lights], scene.objects)
    np.testing.assert_array_equal(render_halftone(mixed).image, render_halftone(scene).image)
    seen = []
    render_halftone(scene, progress=lambda done, total: seen.append((done, total)))
    assert seen[-1] == (8, 8)
