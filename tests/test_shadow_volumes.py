"""Shadow volumes (penumbra = hull of the vertex volumes, umbra = their intersection).

Judges: the exact per-point shadow states of :func:`isocsg.shadows.shadow_state`
(visible part of the source from each point), similar triangles for a square
source over a square occluder, and the definition of the vertex volumes
(segment from the vertex to the point meets the occluder) checked by sampling
the segment.
"""

from __future__ import annotations

import numpy as np
import pytest

from isocsg import Box, ConvexPolyhedron, InvalidGeometryError, InvalidParameterError
from isocsg.lighting.area import AreaLight, PolyhedronLight
from isocsg.shadows import shadow_state
from isocsg.shadows.volumes import (
    ConvexVolume,
    may_cast_shadow,
    penumbra_volume,
    shadow_volumes,
    umbra_volume,
    vertex_shadow_volume,
)


def _square(cx: float, cy: float, z: float, s: float, down: bool = True) -> list[tuple[float, float, float]]:
    h = s / 2
    pts = [(cx - h, cy - h, z), (cx - h, cy + h, z), (cx + h, cy + h, z), (cx + h, cy - h, z)]
    return pts if down else pts[::-1]


def _rotation(seed: int) -> np.ndarray:
    q, _ = np.linalg.qr(np.random.default_rng(seed).normal(size=(3, 3)))
    return q * np.sign(np.linalg.det(q))


def _cases():
    rng = np.random.default_rng(7)
    rot = _rotation(3)
    tilt = np.array([(-0.6, -0.4, 2.5), (0.7, -0.5, 2.2), (0.2, 0.6, 2.6)])  # a tilted triangle facing down
    blob = rng.normal(size=(12, 3)) * [0.5, 0.4, 0.25] + [0.2, 0.1, 1.2]
    prism = [(x, y, z) for x in (-0.3, 0.3) for y in (-0.8, 0.8) for z in (2.4, 2.7)]
    tet = [(0, 0, 2.2), (0.6, 0.1, 2.6), (-0.3, 0.5, 2.7), (-0.2, -0.6, 2.5)]
    return [
        ("area-square-box", AreaLight(_square(0, 0, 2.0, 1.0)), Box((0.1, 0, 1.0), (0.8, 0.6, 0.3))),
        ("area-tilted-blob", AreaLight(tilt if np.cross(tilt[1] - tilt[0], tilt[2] - tilt[0])[2] < 0 else tilt[::-1]),
         ConvexPolyhedron(blob)),
        ("area-rotated", AreaLight(np.array(_square(0, 0, 2.0, 0.5)) @ rot.T),
         ConvexPolyhedron(np.array([(x, y, z) for x in (-.3, .3) for y in (-.3, .3) for z in (.8, 1.1)]) @ rot.T)),
        # the source plane cuts the occluder: H(S_e, V) = 0
        ("area-plane-cuts-occluder", AreaLight(_square(0, 0, 2.0, 1.0)), Box((1.3, 0, 1.8), (0.8, 0.8, 0.8))),
        ("prism-box", PolyhedronLight(prism), Box((0.1, 0.1, 1.2), (1.0, 1.2, 0.2))),
        ("tet-blob", PolyhedronLight(tet), ConvexPolyhedron(blob * [1, 1, 0.8])),
    ]


CASES = _cases()


def _samples(light, occ, n=6000, seed=0):
    """Random receiver points around the occluder with normals that see the whole source."""
    rng = np.random.default_rng(seed)
    src = np.asarray(light.vertices, dtype=float)
    lo = np.minimum(src.min(0), occ.bounds[0]) - 1.5
    hi = np.maximum(src.max(0), occ.bounds[1]) + 1.5
    p = rng.uniform(lo, hi, size=(n, 3))
    c = src.mean(0)
    nrm = c - p
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
    # every source vertex in front of the receiving plane (type A receivers only)
    front = np.all(np.einsum("nkj,nj->nk", src[None] - p[:, None], nrm) > 1e-3, axis=1)
    keep = front & ~occ.contains(p)
    if isinstance(light, AreaLight):
        keep &= (p - src[0]) @ np.asarray(light.normal) > 1e-3
    else:
        keep &= ~light.polyhedron.contains(p)
    return p[keep], nrm[keep]


@pytest.mark.parametrize("name,light,occ", CASES, ids=[c[0] for c in CASES])
def test_volumes_classify_like_shadow_state(name, light, occ):
    p, nrm = _samples(light, occ)
    sv = shadow_volumes(light, occ)
    assert sv is not None
    eps = 1e-6 * 10
    far = (np.abs(sv.penumbra.signed_distance(p)) > eps) & (np.abs(sv.umbra.signed_distance(p)) > eps)
    p, nrm = p[far], nrm[far]
    expected = shadow_state(p, nrm, light, [occ])
    got = sv.classify(p)
    mismatch = np.nonzero(got != expected)[0]
    assert len(mismatch) == 0, (name, len(mismatch), p[mismatch[:5]], got[mismatch[:5]], expected[mismatch[:5]])
    # the test is not vacuous: all three states occur
    counts = np.bincount(expected, minlength=3)
    assert np.all(counts >= 20), counts


@pytest.mark.parametrize("name,light,occ", CASES, ids=[c[0] for c in CASES])
def test_table1_umbra_equals_intersection_of_vertex_volumes(name, light, occ):
    a = shadow_volumes(light, occ, umbra_rule="intersection").umbra
    b = shadow_volumes(light, occ, umbra_rule="table1").umbra
    p, _ = _samples(light, occ, n=4000, seed=1)
    far = (np.abs(a.signed_distance(p)) > 1e-5) & (np.abs(b.signed_distance(p)) > 1e-5)
    assert far.sum() > 1000
    np.testing.assert_array_equal(a.contains(p[far]), b.contains(p[far]))


@pytest.mark.parametrize("name,light,occ", CASES, ids=[c[0] for c in CASES])
def test_penumbra_volume_contains_umbra_volume(name, light, occ):
    sv = shadow_volumes(light, occ)
    src = np.asarray(light.vertices, dtype=float)
    bounds = np.array([np.minimum(src.min(0), occ.bounds[0]) - 3, np.maximum(src.max(0), occ.bounds[1]) + 3])
    v = sv.umbra.vertices(bounds)
    assert v is not None and len(v) >= 4
    # a convex set is inside a convex set iff its vertices are
    assert np.all(sv.penumbra.clipped(bounds).signed_distance(v) <= 1e-7)
    mu = sv.umbra.to_trimesh(bounds)
    mp = sv.penumbra.to_trimesh(bounds)
    assert mu.is_watertight and mp.is_watertight
    assert mp.volume > mu.volume > 0


@pytest.mark.parametrize("name,light,occ", CASES, ids=[c[0] for c in CASES])
def test_vertex_volume_is_the_set_of_points_whose_segment_meets_the_occluder(name, light, occ):
    rng = np.random.default_rng(5)
    q = np.asarray(light.vertices, dtype=float)[0]
    u = vertex_shadow_volume(q, occ)
    lo, hi = occ.bounds[0] - 2, occ.bounds[1] + 2
    p = rng.uniform(lo, hi, size=(3000, 3))
    t = np.linspace(0, 1, 801)
    seg = q[None, None, :] + t[None, :, None] * (p[:, None, :] - q[None, None, :])
    hits = occ.contains(seg.reshape(-1, 3)).reshape(len(p), len(t)).any(axis=1)
    far = np.abs(u.signed_distance(p)) > 0.02  # the sampled segment test resolves 1/800 of its length
    assert far.sum() > 1500 and hits[far].sum() > 50
    np.testing.assert_array_equal(u.contains(p[far]), hits[far])


# ----------------------------------------------------------------------------- closed form

S, A, HS, HO, T = 1.0, 0.8, 2.0, 1.0, 0.02  # source side, occluder side, heights, thickness


def _similar_triangles():
    """Floor (z = 0) boundaries along y = 0 for a square source over a thin square occluder."""
    ztop, zbot = HO + T / 2, HO - T / 2
    # penumbra edge: ray from the far source edge (-S/2) over the occluder's top corner (A/2, ztop)
    x_pen = -S / 2 + (A / 2 + S / 2) * HS / (HS - ztop)
    # umbra edge: ray from the near source edge (S/2 > A/2) under the occluder's bottom corner (A/2, zbot)
    x_umb = S / 2 + (A / 2 - S / 2) * HS / (HS - zbot)
    return x_umb, x_pen


def test_square_source_over_square_occluder_closed_form():
    light = AreaLight(_square(0, 0, HS, S))
    occ = Box((0, 0, HO), (A, A, T))
    sv = shadow_volumes(light, occ)
    x_umb, x_pen = _similar_triangles()
    assert 0 < x_umb < A / 2 < x_pen
    d = 1e-6
    xs = np.array([0, x_umb - d, x_umb + d, x_pen - d, x_pen + d, -x_umb + d, -x_umb - d, -x_pen + d, -x_pen - d])
    pts = np.column_stack([xs, np.zeros_like(xs), np.zeros_like(xs)])
    assert sv.classify(pts).tolist() == [2, 2, 1, 1, 0, 2, 1, 1, 0]
    # the same along y (the configuration is symmetric under x <-> y)
    assert sv.classify(pts[:, [1, 0, 2]]).tolist() == [2, 2, 1, 1, 0, 2, 1, 1, 0]
    # and the floor section of the closed meshes spans exactly these lengths along y = 0
    bounds = [[-4, -4, 0], [4, 4, 3]]  # the floor closes the meshes
    for vol, edge in ((sv.umbra, x_umb), (sv.penumbra, x_pen)):
        mesh = vol.to_trimesh(bounds)
        sec = mesh.section(plane_normal=[0, 1, 0], plane_origin=[0, 0, 0])
        v = sec.vertices
        floor = v[np.abs(v[:, 2]) < 1e-9]
        assert floor[:, 0].max() == pytest.approx(edge, abs=1e-9)
        assert floor[:, 0].min() == pytest.approx(-edge, abs=1e-9)


def test_polyhedron_source_closed_form_flat_box_source():
    """A thin box source: its bottom square binds both edges (lower source points throw farther)."""
    light = PolyhedronLight([(x, y, z) for x in (-S / 2, S / 2) for y in (-S / 2, S / 2) for z in (HS, HS + 1e-3)])
    sv = shadow_volumes(light, Box((0, 0, HO), (A, A, T)))
    x_umb, x_pen = _similar_triangles()
    d = 1e-6
    xs = np.array([x_umb - d, x_umb + d, x_pen - d, x_pen + d])
    pts = np.column_stack([xs, np.zeros(4), np.zeros(4)])
    assert sv.classify(pts).tolist() == [2, 1, 1, 0]


# ----------------------------------------------------------------------------- eqs. 5 and 6


@pytest.mark.parametrize("name,light,occ", CASES, ids=[c[0] for c in CASES])
def test_may_cast_shadow_agrees_with_shadow_state_on_faces(name, light, occ):
    rng = np.random.default_rng(11)
    src = np.asarray(light.vertices, dtype=float)
    checked = {True: 0, False: 0}
    for k in range(40):
        c = rng.uniform(occ.bounds[0] - 2.5, occ.bounds[1] + 0.5)
        c[2] = rng.uniform(-1.0, occ.bounds[0][2])  # receivers below the occluder
        n = src.mean(0) - c
        n /= np.linalg.norm(n)
        e1 = np.cross(n, [1.0, 0.3, 0.1])
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(n, e1)
        r = rng.uniform(0.2, 0.8)
        face = np.array([c + r * (np.cos(a) * e1 + np.sin(a) * e2) for a in np.linspace(0, 2 * np.pi, 6, endpoint=False)])
        if np.min((src - c) @ n) <= 1e-3:
            continue  # keep type-A receivers (the whole source in front)
        if hasattr(light, "normal") and (c - src[0]) @ np.asarray(light.normal) <= 1e-3:
            continue  # behind the emitting side: nothing reaches it (state 2), whatever the occluder
        g = rng.uniform(0, 1, size=(400, 6))
        g /= g.sum(1, keepdims=True)
        pts = g @ face
        states = shadow_state(pts, np.broadcast_to(n, pts.shape), light, [occ])
        possible = may_cast_shadow(face, occ, light)
        if not possible:
            assert np.all(states == 0), (k, np.bincount(states))
        if np.any(states > 0):
            assert possible
        checked[possible] += 1
    assert checked[True] >= 3 and checked[False] >= 3, checked


def test_may_cast_shadow_occluder_behind_face_or_source():
    light = AreaLight(_square(0, 0, 2.0, 1.0))
    floor = np.array(_square(0, 0, 0.0, 4.0, down=False))
    assert may_cast_shadow(floor, Box((0, 0, 1), (0.5, 0.5, 0.5)), light)
    assert not may_cast_shadow(floor, Box((0, 0, -1), (0.5, 0.5, 0.5)), light)  # eq. (5)
    assert not may_cast_shadow(floor, Box((0, 0, 3), (0.5, 0.5, 0.5)), light)  # behind the source
    assert shadow_volumes(light, Box((0, 0, 3), (0.5, 0.5, 0.5))) is None
    assert penumbra_volume(light, Box((0, 0, 3), (0.5, 0.5, 0.5))) is None
    assert umbra_volume(light, Box((0, 0, 3), (0.5, 0.5, 0.5))) is None


# ----------------------------------------------------------------------------- errors


def test_errors_name_the_field():
    light = AreaLight(_square(0, 0, 2.0, 1.0))
    with pytest.raises(InvalidParameterError, match="umbra_rule"):
        shadow_volumes(light, Box((0, 0, 1), (1, 1, 1)), umbra_rule="hull")
    with pytest.raises(InvalidGeometryError, match="inside the occluder"):
        vertex_shadow_volume((0, 0, 1), Box((0, 0, 1), (1, 1, 1)))
    with pytest.raises(InvalidGeometryError, match="occluder must be"):
        shadow_volumes(light, "box")
    with pytest.raises(InvalidParameterError, match="bounds must be"):
        ConvexVolume(np.array([[0.0, 0, 1]]), np.array([0.0])).to_trimesh([[0, 0, 0], [0, 0, 0]])
