"""Receivers classified by the shadow volumes (isocsg/shadows/tiles.py) give what the untiled exact path gives.

The untiled path is the exact clipping of every source polygon by every
occluder piece at every point (``visible_illuminance`` over all pieces of
``convex_pieces``, the 2D Boolean fallback where it overflows): no tiles, no
classes, no pieces left out. On drawn scenes (boxes, area and polyhedron
lights, grids on tilted planes, points exactly on shadow boundaries) the
illuminance agrees to 1e-12 of the largest possible value (pi L) and the
shadow states agree exactly. The accuracy of the exact path itself is judged
by the independent references of test_illuminance*.py.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import isocsg
from isocsg.shadows import AreaLight, PolyhedronLight, illuminance_and_state
from isocsg.shadows import direct as direct_module
from isocsg.shadows import tiles as tiles_module
from isocsg.shadows.occluders import convex_pieces
from isocsg.shadows.visibility import PieceArrays, visible_illuminance

REL = 1e-12


def untiled(points, normals, lights, boxes):
    """Every point against every piece: the exact path with nothing classified or left out."""
    p = np.asarray(points, dtype=np.float64)
    n = np.broadcast_to(np.asarray(normals, dtype=np.float64), p.shape)
    n = np.ascontiguousarray(n / np.linalg.norm(n, axis=1, keepdims=True))
    sources = direct_module._sources(list(lights))
    allp = np.vstack([p, sources.verts] + [np.asarray(b.bounds) for b in boxes])
    scale = float(max(np.max(np.ptp(allp, axis=0)), np.max(np.abs(allp)), 1e-300))
    pa = PieceArrays(convex_pieces(boxes))
    E, S, overflow = visible_illuminance(p, n, sources, pa, scale)
    for i in np.nonzero(overflow)[0]:
        E[i], S[i] = direct_module._fallback_point(p[i], n[i], sources, pa, scale)
    return E, S


def boundary_points(lights, boxes, z):
    """Where the rays from the source vertices over the box corners meet the plane at height z."""
    out = []
    for light in lights:
        for q in np.vstack([np.asarray(poly) for poly in light.emitting_polygons()]):
            for b in boxes:
                lo, hi = np.asarray(b.bounds)
                for v in np.array(np.meshgrid(*zip(lo, hi))).T.reshape(-1, 3):
                    d = v - q
                    if d[2] < -1e-9:
                        out.append(q + (z - q[2]) / d[2] * d)
    return np.array(out).reshape(-1, 3)


def check(points, normals, lights, boxes):
    E, S = illuminance_and_state(points, normals, lights, boxes)
    Er, Sr = untiled(points, normals, lights, boxes)
    top = np.pi * sum(li.radiance for li in lights)
    np.testing.assert_allclose(E, Er, rtol=0, atol=REL * top)
    np.testing.assert_array_equal(S, Sr)
    return S


box_st = st.tuples(
    st.floats(-1.5, 1.5), st.floats(-1.5, 1.5), st.floats(0.2, 2.2),
    st.floats(0.05, 1.5), st.floats(0.05, 1.5), st.floats(0.02, 0.8),
)


@settings(max_examples=15, deadline=None)
@given(
    boxes=st.lists(box_st, min_size=1, max_size=4),
    lamp=st.tuples(st.floats(-1, 1), st.floats(-1, 1), st.floats(2.5, 3.5), st.floats(0.1, 1.5), st.floats(0.1, 1.5)),
    tilt=st.floats(-0.4, 0.4),
    m=st.integers(8, 40),
    triangle=st.booleans(),
)
def test_tiled_equals_untiled_on_drawn_rooms(boxes, lamp, tilt, m, triangle):
    cx, cy, cz, hx, hy = lamp
    if triangle:
        verts = [(cx - hx, cy - hy, cz), (cx, cy + hy, cz), (cx + hx, cy - hy, cz)]
    else:
        verts = [(cx - hx, cy - hy, cz), (cx - hx, cy + hy, cz), (cx + hx, cy + hy, cz), (cx + hx, cy - hy, cz)]
    light = AreaLight(verts, 500.0)  # clockwise seen from above: lights downwards
    occ = [isocsg.Box((x, y, z), (sx, sy, sz)) for x, y, z, sx, sy, sz in boxes]
    xs = np.linspace(-3, 3, m)
    X, Y = np.meshgrid(xs, xs, indexing="ij")
    grid = np.c_[X.ravel(), Y.ravel(), tilt * X.ravel()]  # a tilted receiving plane
    edge = boundary_points([light], occ, 0.0)
    edge = np.c_[edge[:, :2], tilt * edge[:, 0]]  # the boundary points moved onto the tilted plane
    normals = np.array([-tilt, 0.0, 1.0])
    check(np.vstack([grid, edge]), normals, [light], occ)
    flat = boundary_points([light], occ, 0.0)  # exactly on the shadow boundaries of the floor z = 0
    if len(flat):
        check(np.vstack([np.c_[X.ravel(), Y.ravel(), 0 * X.ravel()], flat]), [0, 0, 1], [light], occ)


@settings(max_examples=6, deadline=None)
@given(
    boxes=st.lists(box_st, min_size=1, max_size=3),
    seed=st.integers(0, 2**31 - 1),
    size=st.floats(0.1, 0.8),
)
def test_tiled_equals_untiled_polyhedron_light_scattered_normals(boxes, seed, size):
    rng = np.random.default_rng(seed)
    light = PolyhedronLight(rng.normal(size=(8, 3)) * size + [0, 0, 3.0], 300.0)
    occ = [isocsg.Box((x, y, z), (sx, sy, sz)) for x, y, z, sx, sy, sz in boxes]
    P = np.c_[rng.uniform(-3, 3, (600, 2)), rng.uniform(-0.5, 1.0, 600)]
    Nr = rng.normal(size=(600, 3))
    Nr[:, 2] = np.abs(Nr[:, 2]) + 0.2
    check(P, Nr, [light], occ)


def test_classes_of_the_room_are_proved_not_guessed():
    """On the benchmark's room most receivers are classified; every lit or umbra one has that exact state."""
    lamp = AreaLight([(-0.6, -0.3, 2.8), (-0.6, 0.3, 2.8), (0.6, 0.3, 2.8), (0.6, -0.3, 2.8)], 1000.0)
    top = isocsg.Box((0.3, 0.2, 0.73), (1.2, 0.8, 0.04))
    legs = [isocsg.Box((0.3 + sx * 0.55, 0.2 + sy * 0.35, 0.355), (0.05, 0.05, 0.71)) for sx in (-1, 1)
            for sy in (-1, 1)]
    xs = np.linspace(-2, 2, 121)
    X, Y = np.meshgrid(xs, xs, indexing="ij")
    P = np.c_[X.ravel(), Y.ravel(), 0 * X.ravel()]
    S = check(P, [0, 0, 1], [lamp], [top, *legs])
    sources = direct_module._sources([lamp])
    rc = tiles_module.classify_receivers(P, sources, convex_pieces([top, *legs]), 4.0)
    assert np.all(S[rc.cls == tiles_module.CLASS_LIT] == 0)
    assert np.all(S[rc.cls == tiles_module.CLASS_UMBRA] == 2)
    # the classes leave only a thin band around the penumbra to the exact path
    assert np.count_nonzero(rc.cls == tiles_module.CLASS_EXACT) <= 1.2 * np.count_nonzero(S == 1)


def test_chunks_give_the_same_values(monkeypatch):
    """Receivers evaluated in chunks (bounded memory for 10^7 points) give what one pass gives."""
    lamp = AreaLight([(-0.5, -0.5, 2), (-0.5, 0.5, 2), (0.5, 0.5, 2), (0.5, -0.5, 2)], 100.0)
    occ = [isocsg.Box((0.2, 0, 1), (0.6, 0.4, 0.1))]
    rng = np.random.default_rng(3)
    P = np.c_[rng.uniform(-2, 2, (500, 2)), np.zeros(500)]
    N = np.c_[rng.normal(size=(500, 2)) * 0.2, np.ones(500)]
    E1, S1 = illuminance_and_state(P, N, lamp, occ)
    monkeypatch.setattr(direct_module, "CHUNK_POINTS", 37)
    E2, S2 = illuminance_and_state(P, N, lamp, occ)
    np.testing.assert_array_equal(E1, E2)
    np.testing.assert_array_equal(S1, S2)


def test_bad_normals_still_refused():
    lamp = AreaLight([(-0.5, -0.5, 2), (-0.5, 0.5, 2), (0.5, 0.5, 2), (0.5, -0.5, 2)])
    with pytest.raises(isocsg.InvalidParameterError, match="normals must be non-zero, row 1"):
        illuminance_and_state([[0, 0, 0], [1, 0, 0]], [[0, 0, 1], [0, 0, 0]], lamp)
    with pytest.raises(isocsg.InvalidParameterError, match="normals must have the shape"):
        illuminance_and_state([[0, 0, 0], [1, 0, 0], [2, 0, 0]], [[0, 0, 1], [0, 0, 1]], lamp)
