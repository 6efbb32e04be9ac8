"""The compiled triangle fill against an independent per-pixel ray cast.

The reference shoots each pixel's ray (from the camera's own ray definition of
the conventions) at every triangle with the Moller-Trumbore test, so coverage,
depth and the nearest/farthest triangle are computed without any screen-space
arithmetic. Pixels whose centre lies within a hair of an edge are ambiguous
(the fill rule decides them) and are left out of the comparison.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from isocsg import Camera, InvalidGeometryError, InvalidParameterError, Sphere
from isocsg.rendering.polygons import fill_front_kernel
from isocsg.rendering.projection import homogeneous, key_to_depth, near_distance
from isocsg.rendering.quads import pair_quads
from isocsg.rendering.raster import rasterize

EDGE_MARGIN = 1e-7  # barycentric margin that separates "clearly inside" from "on the edge"


def ray_cast(camera: Camera, vertices: np.ndarray, triangles: np.ndarray):
    """Per pixel and triangle: camera depth of the hit (nan if none) and an ambiguity flag."""
    o = camera.ray_origins().reshape(-1, 1, 3)
    d = camera.ray_directions().reshape(-1, 1, 3)
    f = camera.frame[0]
    p0, p1, p2 = (vertices[triangles[:, k]][None] for k in range(3))
    e1, e2 = p1 - p0, p2 - p0
    pv = np.cross(d, e2)
    det = np.einsum("ptk,ptk->pt", e1, pv)
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / det
        tv = o - p0
        u = np.einsum("ptk,ptk->pt", tv, pv) * inv
        qv = np.cross(tv, e1)
        v = np.einsum("ptk,ptk->pt", d, qv) * inv
        t = np.einsum("ptk,ptk->pt", e2, qv) * inv
    w = 1 - u - v
    m = np.minimum(np.minimum(u, v), w)
    hit = (m > EDGE_MARGIN) & (t > 0)
    ambiguous = (np.abs(m) <= EDGE_MARGIN) & (t > 0)
    depth = np.where(hit, t * (d[..., :] @ f), np.nan)
    shape = (camera.height, camera.width, len(triangles))
    return depth.reshape(shape), ambiguous.reshape(shape)


def random_triangles(rng: np.random.Generator, n: int, spread: float = 1.5):
    centres = rng.uniform(-spread, spread, (n, 1, 3))
    verts = (centres + rng.normal(0, 0.8, (n, 3, 3))).reshape(-1, 3)
    return verts, np.arange(3 * n).reshape(n, 3)


CAMERAS = {
    "perspective": Camera((0.7, -6.0, 1.3), (0, 0, 0), fov=45, width=40, height=30),
    "orthographic": Camera((0.7, -6.0, 1.3), (0, 0, 0), width=36, height=28, orthographic=True, height_m=5.0),
}


@pytest.mark.parametrize("cam", CAMERAS.values(), ids=CAMERAS.keys())
@pytest.mark.parametrize("seed", [0, 1, 2], ids=lambda s: f"seed{s}")
def test_nearest_and_farthest_match_ray_cast(cam, seed):
    rng = np.random.default_rng(seed)
    verts, tris = random_triangles(rng, 12)
    vout = rng.uniform(0, 1, len(tris))
    vin = rng.uniform(0, 1, len(tris))
    r = rasterize(cam, verts, tris, vout, vin, cull=False)
    depth, amb = ray_cast(cam, verts, tris)
    any_hit = np.isfinite(depth).any(axis=2)
    # Leave out pixels near any edge, and pixels where two surfaces are nearly at the same depth.
    clear = ~amb.any(axis=2)
    srt = np.sort(np.where(np.isnan(depth), np.inf, depth), axis=2)
    with np.errstate(invalid="ignore"):
        gap_ok = ~(np.abs(srt[..., 1] - srt[..., 0]) < 1e-6)
    assert clear.mean() > 0.9
    np.testing.assert_array_equal(r.covered[clear], any_hit[clear])
    ok = clear & any_hit & gap_ok
    assert ok.sum() > 100
    near_t = np.nanargmin(np.where(np.isnan(depth), np.inf, depth)[ok], axis=1)
    np.testing.assert_allclose(r.front_depth[ok], np.nanmin(depth[ok], axis=1), rtol=1e-9)
    np.testing.assert_array_equal(r.front_value[ok], vout[near_t].astype(np.float32))
    far_t = np.argmax(np.where(np.isnan(depth), -np.inf, depth)[ok], axis=1)
    np.testing.assert_allclose(r.back_depth[ok], np.nanmax(depth[ok], axis=1), rtol=1e-9)
    np.testing.assert_array_equal(r.back_value[ok], vin[far_t].astype(np.float32))
    assert np.all(np.isnan(r.front_value[clear & ~any_hit]))


@pytest.mark.parametrize("cam", CAMERAS.values(), ids=CAMERAS.keys())
def test_closed_mesh_front_and_back_faces(cam):
    """With culling, front faces give the ray's entry, back faces its exit."""
    mesh = Sphere((0.2, 0.1, -0.1), 1.7).to_trimesh(12)
    v, t = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    vals = np.arange(len(t), dtype=float)
    r = rasterize(cam, v, t, vals, vals + 0.5)
    depth, amb = ray_cast(cam, v, t)
    clear = ~amb.any(axis=2)
    hit = np.isfinite(depth).any(axis=2)
    np.testing.assert_array_equal(r.covered[clear], hit[clear])
    np.testing.assert_array_equal(np.isfinite(r.back_depth)[clear], hit[clear])
    ok = clear & hit
    d = depth[ok]
    np.testing.assert_allclose(r.front_depth[ok], np.nanmin(d, axis=1), rtol=1e-9)
    np.testing.assert_allclose(r.back_depth[ok], np.nanmax(d, axis=1), rtol=1e-9)
    np.testing.assert_array_equal(r.front_value[ok], np.nanargmin(np.where(np.isnan(d), np.inf, d), axis=1))
    np.testing.assert_array_equal(r.back_value[ok], np.nanargmax(np.where(np.isnan(d), -np.inf, d), axis=1) + 0.5)


def _ortho_pixel_camera(n: int) -> Camera:
    """Orthographic camera where world (x, y) maps to (col, row) = (x + n/2, n/2 - y) exactly."""
    return Camera((0, 0, 10), (0, 0, 0), up=(0, 1, 0), width=n, height=n, orthographic=True, height_m=float(n))


def _coverage_counts(cam: Camera, verts, tris) -> np.ndarray:
    counts = np.zeros((cam.height, cam.width), int)
    for t in tris:
        counts += rasterize(cam, verts, [t], [1.0], cull=False).covered
    return counts


def test_quad_split_on_pixel_centres_is_covered_exactly_once():
    n = 12
    cam = _ortho_pixel_camera(n)
    # Corners at pixel centres: the diagonal and all four sides run through pixel centres.
    c = np.array([(-4.5, -4.5), (3.5, -4.5), (3.5, 3.5), (-4.5, 3.5)])
    verts = np.column_stack([c, np.zeros(4)])
    for tris in ([(0, 1, 2), (0, 2, 3)], [(0, 1, 3), (1, 2, 3)]):
        counts = _coverage_counts(cam, verts, tris)
        assert counts.max() == 1
        # Independent coverage of the closed square with the half-open rule: x in [-4.5, 3.5), y in (-4.5, 3.5]
        col = np.arange(n) + 0.5 - n / 2  # world x of pixel centres
        row_y = n / 2 - (np.arange(n) + 0.5)
        expected = ((col >= -4.5) & (col < 3.5))[None, :] & ((row_y > -4.5) & (row_y <= 3.5))[:, None]
        np.testing.assert_array_equal(counts, expected.astype(int))


@pytest.mark.parametrize("centre", [(0.5, 0.5), (0.0, 0.0), (0.3, -0.2)], ids=["on-centre", "on-corner", "generic"])
def test_fan_around_a_vertex_has_no_gaps_or_overlaps(centre):
    n = 16
    cam = _ortho_pixel_camera(n)
    k = 7
    ang = np.linspace(0, 2 * np.pi, k, endpoint=False) + 0.1
    ring = np.column_stack([6 * np.cos(ang), 6 * np.sin(ang), np.zeros(k)])
    verts = np.vstack([[centre[0], centre[1], 0.0], ring])
    tris = [(0, 1 + i, 1 + (i + 1) % k) for i in range(k)]
    counts = _coverage_counts(cam, verts, tris)
    assert counts.max() == 1
    # Every pixel centre strictly inside the heptagon (away from its outer sides) is covered once.
    cx = np.arange(n) + 0.5 - n / 2
    cy = n / 2 - (np.arange(n) + 0.5)
    X, Y = np.meshgrid(cx, cy)
    inside = np.ones_like(X, bool)
    for i in range(k):
        a, b = ring[i, :2], ring[(i + 1) % k, :2]
        crs = (b[0] - a[0]) * (Y - a[1]) - (b[1] - a[1]) * (X - a[0])
        inside &= crs > 1e-9
    assert inside.sum() > 50
    assert np.all(counts[inside] == 1)


def test_closed_mesh_front_faces_cover_the_silhouette_once():
    cam = Camera((2.0, -5.0, 1.5), (0, 0, 0), fov=40, width=48, height=40)
    mesh = Sphere((0, 0, 0), 1.2).to_trimesh(10)
    v, t = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    counts = np.zeros((cam.height, cam.width), int)
    for tri in t:
        counts += rasterize(cam, v, [tri], [1.0]).covered  # culled: front faces only
    depth, amb = ray_cast(cam, v, t)
    hit = np.isfinite(depth).any(axis=2)
    assert counts.max() == 1
    clear = ~amb.any(axis=2)
    np.testing.assert_array_equal(counts[clear] == 1, hit[clear])
    # The silhouette (a pixel centre on it is ambiguous for the reference) never doubles up.
    whole = rasterize(cam, v, t, np.ones(len(t))).covered
    np.testing.assert_array_equal(whole, counts == 1)


def test_near_plane_clipping_keeps_the_part_in_front():
    """A floor that passes under and behind the eye: clipped, not dropped."""
    cam = Camera((0.0, 0.0, 1.0), (0.0, 5.0, 0.0), fov=70, width=40, height=32)
    verts = np.array([(-30.0, -20.0, 0.0), (30.0, -20.0, 0.0), (0.0, 40.0, 0.0), (0.0, -1.0, 3.0), (0.5, 0.5, -2.0), (-0.5, 0.8, 2.0)])
    tris = np.array([(0, 1, 2), (3, 4, 5)])  # the second crosses the eye's plane in front and behind
    h = homogeneous(cam, verts)
    assert (h[3] < 0).any() and (h[3] > 0).any()
    r = rasterize(cam, verts, tris, [0.25, 0.75], cull=False)
    depth, amb = ray_cast(cam, verts, tris)
    clear = ~amb.any(axis=2)
    hit = np.isfinite(depth).any(axis=2)
    assert hit[clear].mean() > 0.3
    np.testing.assert_array_equal(r.covered[clear], hit[clear])
    ok = clear & hit
    np.testing.assert_allclose(r.front_depth[ok], np.nanmin(depth[ok], axis=1), rtol=1e-9)
    best = np.nanargmin(np.where(np.isnan(depth[ok]), np.inf, depth[ok]), axis=1)
    np.testing.assert_array_equal(r.front_value[ok], np.array([0.25, 0.75], np.float32)[best])


def test_triangle_entirely_behind_the_eye_draws_nothing():
    cam = Camera((0, 0, 0), (0, 1, 0), width=16, height=16)
    r = rasterize(cam, [(-1, -2, -1), (1, -2, -1), (0, -2, 1)], [(0, 1, 2)], [1.0], cull=False)
    assert not r.covered.any()


@pytest.mark.parametrize(
    ("kwargs", "error", "message"),
    [
        ({"vertices": np.zeros((3, 2))}, InvalidGeometryError, "vertices must have shape (V, 3), got (3, 2)"),
        ({"triangles": [(0, 1, 3)]}, InvalidGeometryError, "triangles index vertices 0..2, got 0..3"),
        ({"value_out": [1.0, 2.0]}, InvalidParameterError, "value_out must have one entry per triangle (1), got 2"),
        ({"value_in": []}, InvalidParameterError, "value_in must have one entry per triangle (1), got 0"),
    ],
    ids=["vertex-shape", "index-range", "value-out-length", "value-in-length"],
)
def test_bad_input_names_the_field(kwargs, error, message):
    args = {"vertices": np.eye(3), "triangles": [(0, 1, 2)], "value_out": [1.0]} | kwargs
    with pytest.raises(error, match=re.escape(message)):
        rasterize(CAMERAS["perspective"], **args)


# ------------------------------------------------ quads: one span per row
def _planar_patch(rng: np.random.Generator, nx: int, ny: int, centre, normal_towards, size: float):
    """A jittered planar grid (convex cells), each cell split along a random diagonal.

    Both triangles of most cells carry one value (they pair into a quad); some
    cells get two values (two lone triangles)."""
    n = np.asarray(normal_towards, float)
    n /= np.linalg.norm(n)
    e1 = np.cross(n, rng.normal(size=3))
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    gx, gy = np.meshgrid(np.arange(nx + 1, dtype=float), np.arange(ny + 1, dtype=float), indexing="ij")
    gx += rng.uniform(-0.25, 0.25, gx.shape)
    gy += rng.uniform(-0.25, 0.25, gy.shape)
    pts = np.asarray(centre) + size * ((gx.ravel() - nx / 2)[:, None] * e1 + (gy.ravel() - ny / 2)[:, None] * e2) / max(nx, ny)
    idx = np.arange((nx + 1) * (ny + 1)).reshape(nx + 1, ny + 1)
    tris, vals = [], []
    for i in range(nx):
        for j in range(ny):
            a, b, c, d = idx[i, j], idx[i + 1, j], idx[i + 1, j + 1], idx[i, j + 1]  # counter-clockwise about n
            v = rng.uniform(0, 1)
            w = v if rng.uniform() < 0.85 else rng.uniform(0, 1)
            if rng.uniform() < 0.5:
                tris += [(a, b, c), (a, c, d)]
            else:
                tris += [(a, b, d), (b, c, d)]
            vals += [v, w]
    return pts, np.array(tris), np.array(vals)


def _scene_mesh(seed: int):
    """Several planar patches facing the camera or away from it, and a sphere: one mesh."""
    rng = np.random.default_rng(seed)
    parts = [_planar_patch(rng, 7, 5, rng.uniform(-1, 1, 3), rng.normal(size=3) + (0, -2, 0), 2.5) for _ in range(4)]
    s = Sphere((0.3, 0.2, -0.1), 0.9).to_trimesh(10)
    parts.append((np.asarray(s.vertices), np.asarray(s.faces), rng.uniform(0, 1, len(s.faces))))
    verts, tris, vals, off = [], [], [], 0
    for v, t, x in parts:
        verts.append(v)
        tris.append(t + off)
        vals.append(x)
        off += len(v)
    return np.vstack(verts), np.vstack(tris), np.concatenate(vals)


def _front_fill(cam: Camera, verts, quads, values, cuts=None):
    """fill_front_kernel on the projection of :func:`homogeneous` (as rasterize), in row stripes."""
    h = homogeneous(cam, verts)
    inv = 1.0 / h[2]
    proj = np.vstack([h, h[0] * inv, h[1] * inv, -inv if not cam.orthographic else h[3]])
    H, W = cam.height, cam.width
    z = np.full((H, W), np.inf)
    v = np.full((H, W), np.nan, np.float32)
    g = np.full((H, W), -1, np.int32)
    bounds = np.array([H, 0, W, 0], np.int64)
    cuts = [0, H] if cuts is None else cuts
    for r0, r1 in zip(cuts[:-1], cuts[1:]):
        fill_front_kernel(proj, quads, np.asarray(values, np.float32), near_distance(h[3]), not cam.orthographic, 7, r0,
                          z[r0:r1], v[r0:r1], g[r0:r1], bounds)
    return z, v, g, bounds


QUAD_CAMERAS = CAMERAS | {
    "near-crossing": Camera((0.2, -1.2, 0.3), (0, 0, 0), fov=100, width=44, height=36),
}


def test_pair_quads_keeps_every_triangle_once():
    verts, tris, vals = _scene_mesh(3)
    quads, source = pair_quads(verts, tris, vals)
    assert (quads[:, 3] >= 0).sum() > 60  # the patches pair up
    # The quads decompose into exactly the input triangles (as oriented cycles).
    def canon(t):
        k = int(np.argmin(t))
        return tuple(t[k:]) + tuple(t[:k])
    got = []
    for a, b, c, d in quads:
        got += [canon((a, b, c))] + ([canon((a, c, d))] if d >= 0 else [])
    assert sorted(got) == sorted(canon(tuple(t)) for t in tris)
    # Paired triangles carry one value, and the values follow the source triangle.
    lookup = {canon(tuple(t)): x for t, x in zip(tris, vals)}
    for (a, b, c, d), s in zip(quads, source):
        assert lookup[canon((a, b, c))] == vals[s]
        if d >= 0:
            assert lookup[canon((a, c, d))] == vals[s]


@pytest.mark.parametrize("cam", QUAD_CAMERAS.values(), ids=QUAD_CAMERAS.keys())
@pytest.mark.parametrize("seed", [0, 1, 2], ids=lambda s: f"seed{s}")
def test_quad_fill_equals_triangle_fill_pixel_for_pixel(cam, seed):
    verts, tris, vals = _scene_mesh(seed)
    quads, source = pair_quads(verts, tris, vals)
    ref = rasterize(cam, verts, tris, vals)  # triangles, culled: the front buffers
    H = cam.height
    z, v, g, bounds = _front_fill(cam, verts, quads, vals[source], cuts=[0, H // 3, H // 3 + 1, H])
    cov = np.isfinite(z)
    assert ref.covered.sum() > 100
    np.testing.assert_array_equal(cov, ref.covered)
    np.testing.assert_array_equal(v, ref.front_value)  # NaN where nothing, in both
    np.testing.assert_array_equal(g[cov], 7)
    assert np.all(g[~cov] == -1)
    d = np.empty_like(z)
    key_to_depth(z, not cam.orthographic, d)
    np.testing.assert_allclose(d[cov], ref.front_depth[cov], rtol=1e-12)
    rows, cols = np.nonzero(cov)
    assert bounds[0] <= rows.min() and bounds[1] > rows.max() and bounds[2] <= cols.min() and bounds[3] > cols.max()


@pytest.mark.parametrize("cam", CAMERAS.values(), ids=CAMERAS.keys())
def test_quads_of_a_patch_cover_it_once(cam):
    """Each quad filled on its own: shared edges give no holes and no pixel twice;
    pixel centres clearly inside the patch (per the ray cast) are all covered."""
    rng = np.random.default_rng(11)
    verts, tris, vals = _planar_patch(rng, 9, 7, (0.1, 0.0, 0.2), cam.eye_array - (0.1, 0.0, 0.2), 4.0)
    vals = np.zeros(len(tris))  # one value: every cell pairs
    quads, source = pair_quads(verts, tris, vals)
    assert np.all(quads[:, 3] >= 0)
    counts = np.zeros((cam.height, cam.width), int)
    for q in quads:
        counts += np.isfinite(_front_fill(cam, verts, q[None], [1.0])[0])
    assert counts.max() == 1
    depth, amb = ray_cast(cam, verts, tris)
    hit = np.isfinite(depth).any(axis=2)
    clear = ~amb.any(axis=2)
    assert hit.sum() > 200
    np.testing.assert_array_equal(counts[clear], hit[clear].astype(int))


@pytest.mark.parametrize("cam", QUAD_CAMERAS.values(), ids=QUAD_CAMERAS.keys())
@pytest.mark.parametrize("mesh", ["triangles", "quads"])
def test_projected_fill_equals_the_triangle_fill_without_labels(cam, mesh):
    """fill_projected (CSG leaves: projection done once, quads, no labels) writes
    the same front and back buffers as fill_kernel with culling and back
    buffers on the triangles."""
    from isocsg.rendering.polygons import fill_projected
    from isocsg.rendering.projection import camera_affine, project_kernel
    from isocsg.rendering.triangles import fill_kernel

    rng = np.random.default_rng(5)
    if mesh == "triangles":
        verts, tris = random_triangles(rng, 40)
        polys = np.column_stack([tris, np.full(len(tris), -1)]).astype(np.int32)
        source = np.arange(len(tris))
    else:
        verts, tris, vals = _scene_mesh(4)
        polys, source = pair_quads(verts, tris, vals)
        assert (polys[:, 3] >= 0).sum() > 60
        # Triangles in the quads' order, so that fill_kernel meets them as fill_projected does.
        fan = [(a, b, c) for a, b, c, d in polys] + [(a, c, d) for a, b, c, d in polys if d >= 0]
        order = list(range(len(polys))) + [k for k, q in enumerate(polys) if q[3] >= 0]
        tris, source = np.asarray(fan), source[order]
    tris = tris.astype(np.int32)
    vo_t = rng.uniform(0, 1, int(source.max()) + 1).astype(np.float32)
    vi_t = rng.uniform(0, 1, len(vo_t)).astype(np.float32)
    vo, vi = vo_t[source], vi_t[source]
    H, W = cam.height, cam.width
    oy, ox, h, w = 3, 5, H - 7, W - 9  # a viewport inside the image
    h4 = homogeneous(cam, verts)
    near = near_distance(h4[3])
    persp = not cam.orthographic

    def buffers():
        return np.full((h, w), np.inf), np.full((h, w), np.nan, np.float32), np.full((h, w), -np.inf), np.full((h, w), np.nan, np.float32)

    zf, vf, zb, vb = buffers()
    labels = np.full((h, w), -1, np.int32)
    fill_kernel(h4[0], h4[1], h4[2], h4[3], tris, vo, vi, near, persp, True, True, 0, ox, oy, zf, vf, labels, zb, vb)
    a, b = camera_affine(cam)
    proj = np.empty((7, len(verts)))
    project_kernel(verts, cam.eye_array, a, b, persp, proj, 0, len(verts))
    zf2, vf2, zb2, vb2 = buffers()
    fill_projected(proj, polys, vo_t[source[: len(polys)]], vi_t[source[: len(polys)]], near, persp, ox, oy,
                   zf2, vf2, zb2, vb2)
    assert np.isfinite(zf).sum() > 50 and np.isfinite(zb).sum() > 50
    np.testing.assert_allclose(zf2, zf, rtol=1e-12)
    np.testing.assert_allclose(zb2, zb, rtol=1e-12)
    np.testing.assert_array_equal(vf2, vf)
    np.testing.assert_array_equal(vb2, vb)


# Screen corners of a sliver triangle met in a random CSG tree (a sphere & a cone,
# 72 x 64 pixels): its shoelace area is non-zero but its area from corner 0
# rounds to exactly zero, which once divided by zero in the convex fill.
SLIVER = [(24.196377711429836, 33.4357774620601), (24.110680500947428, 33.6780741946622),
          (24.127010467874946, 33.631903524604624)]
# A quad whose four corner turns are all negative (strictly convex) while the
# area of its fan triangle (0, 1, 2) rounds to zero.
THIN_CORNER_QUAD = [(16.786617188559035, 27.523620820517905), (16.387070356560514, 26.73321200820501),
                    (16.283059918010277, 26.527451980547127), (13.546332033372328, 28.53620821217879)]


@pytest.mark.parametrize("ring", ["sliver", "sliver reversed", "quad", "quad reversed"])
def test_degenerate_polygons_fill_like_their_triangles(ring):
    """A polygon with a zero-area fan triangle fills as fill_kernel fills its
    triangles (the zero-area one draws nothing), in the leaf and the front fill."""
    from isocsg.rendering.polygons import fill_projected
    from isocsg.rendering.triangles import fill_kernel

    pts = list(THIN_CORNER_QUAD if ring.startswith("quad") else SLIVER)
    if ring.endswith("reversed"):
        pts = pts[::-1]
    sx, sy = np.array(pts).T
    sk = 2.0 + 0.01 * sx + 0.02 * sy  # orthographic depth key = camera depth, on a plane
    n = len(pts)
    proj = np.vstack([sx, sy, np.ones(n), sk, sx, sy, sk])
    poly = np.array([list(range(n)) + [-1] * (4 - n)], np.int32)
    vo, vi = np.array([0.25], np.float32), np.array([0.75], np.float32)
    tris = np.array([[0, k, k + 1] for k in range(1, n - 1)], np.int32)
    H, W = 48, 40

    def buffers():
        return np.full((H, W), np.inf), np.full((H, W), np.nan, np.float32), np.full((H, W), -np.inf), np.full((H, W), np.nan, np.float32)

    zf, vf, zb, vb = buffers()
    labels = np.full((H, W), -1, np.int32)
    fill_kernel(sx, sy, np.ones(n), sk, tris, np.repeat(vo, n - 2), np.repeat(vi, n - 2), 1e-3, False, True, True,
                0, 0, 0, zf, vf, labels, zb, vb)
    zf2, vf2, zb2, vb2 = buffers()
    fill_projected(proj, poly, vo, vi, 1e-3, False, 0, 0, zf2, vf2, zb2, vb2)
    np.testing.assert_allclose(zf2, zf, rtol=1e-12)
    np.testing.assert_allclose(zb2, zb, rtol=1e-12)
    np.testing.assert_array_equal(vf2, vf)
    np.testing.assert_array_equal(vb2, vb)
    if ring.startswith("quad"):
        assert np.isfinite(zf).sum() + np.isfinite(zb).sum() == 2  # the pixels of the fan triangle (0, 2, 3)
    zf3, vf3 = np.full((H, W), np.inf), np.full((H, W), np.nan, np.float32)
    fill_front_kernel(proj, poly, vo, 1e-3, False, 0, 0, zf3, vf3, np.full((H, W), -1, np.int32),
                      np.array([H, 0, W, 0], np.int64))
    np.testing.assert_allclose(zf3, zf, rtol=1e-12)
    np.testing.assert_array_equal(vf3, vf)
