"""Shadows of CSG furniture at scale: a table with a plate that has six spherical pockets.

Judges:

- the independent Monte Carlo estimator (``mc_reference``: exact ray tests
  against the primitives' own half-spaces, the pockets as "minus" parts),
  every point inside its 4-sigma interval, states judged independently where
  a point is clear of a boundary (``test_illuminance.expected_states``);
- the full convex decomposition (every piece, nothing left out), evaluated by
  the same visibility code: leaving hidden pieces out must not change E
  beyond rounding, nor any state.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

import isocsg
from isocsg.shadows import AreaLight, illuminance_and_state
from isocsg.shadows.direct import _fallback_point, _sources
from isocsg.shadows.occluders import convex_pieces, shadow_pieces
from isocsg.shadows.visibility import PieceArrays, visible_illuminance

sys.path.insert(0, str(Path(__file__).resolve().parent))

from mc_reference import MCOccluder, box_halfspaces, convex, hull_halfspaces, mc_illuminance  # noqa: E402
from test_illuminance import expected_states, grid  # noqa: E402


def lamp():
    return AreaLight([(-0.6, -0.3, 2.8), (-0.6, 0.3, 2.8), (0.6, 0.3, 2.8), (0.6, -0.3, 2.8)], 1000.0)


def table():
    top = isocsg.Box((0.3, 0.2, 0.73), (1.2, 0.8, 0.04))
    legs = [isocsg.Box((0.3 + sx * 0.55, 0.2 + sy * 0.35, 0.355), (0.05, 0.05, 0.71)) for sx in (-1, 1) for sy in (-1, 1)]
    return [top, *legs]


def pocket_plate(center=(0.3, 0.2, 0.78), radius=0.05):
    """A 0.9 x 0.5 x 0.06 plate with six spherical pockets of depth ``radius`` in its top."""
    cx, cy, cz = center
    plate = isocsg.Box(center, (0.9, 0.5, 0.06))
    spheres = [isocsg.Sphere((cx + dx, cy + dy, cz + 0.03), radius) for dx in (-0.27, 0.0, 0.27) for dy in (-0.11, 0.11)]
    solid = plate
    for s in spheres:
        solid = solid - s
    return solid, plate, spheres


def mc_plate(plate, spheres, res):
    minus = [hull_halfspaces(s.to_polyhedron(res).hull_vertices) for s in spheres]
    return MCOccluder(plus=[box_halfspaces(plate.center, plate.size)], minus=minus)


def judge(points, normals, lights, occluders, mc_occluders, hulls, solid_hulls, res, *, min_judged=0.9):
    points = np.asarray(points, float)
    normals = np.broadcast_to(np.asarray(normals, float), points.shape)
    normals = normals / np.linalg.norm(normals, axis=1, keepdims=True)
    E, S = illuminance_and_state(points, normals, lights, occluders, resolution=res)
    sources = [(light.emitting_polygons(), light.radiance) for light in lights]
    mc = mc_illuminance(points, normals, sources, mc_occluders, k=12, replicates=64)
    tol = mc.tolerance(E)
    bad = np.abs(E - mc.mean) > tol
    assert not bad.any(), f"{bad.sum()} points outside 4 sigma: {points[bad][:3]}, exact {E[bad][:3]}, mc {mc.mean[bad][:3]}"
    exp = expected_states(points, normals, [li.emitting_polygons() for li in lights], mc.visible_fraction, hulls, solid_hulls)
    judged = exp >= 0
    assert judged.mean() >= min_judged, f"only {judged.mean():.0%} judged"
    mism = judged & (exp != S)
    assert not mism.any(), f"states differ at {points[mism][:5]}: {S[mism][:5]} vs {exp[mism][:5]}"
    return E, S


def full_decomposition(points, normals, lights, occluders, res):
    """E and states with every convex piece (nothing left out)."""
    p = np.asarray(points, float)
    n = np.broadcast_to(np.asarray(normals, float), p.shape)
    n = np.ascontiguousarray(n / np.linalg.norm(n, axis=1, keepdims=True))
    sources = _sources(list(lights))
    pieces = convex_pieces(occluders, resolution=res)
    allp = np.vstack([p, sources.verts] + [np.asarray(o.bounds, float) for o in occluders])
    scale = float(max(np.max(np.ptp(allp, axis=0)), np.max(np.abs(allp))))
    pa = PieceArrays(pieces)
    E, S, overflow = visible_illuminance(p, n, sources, pa, scale)
    for i in np.nonzero(overflow)[0]:  # many silhouettes at once: the 2D Boolean path
        E[i], S[i] = _fallback_point(p[i], n[i], sources, pa, scale)
    return E, S, len(pieces)


def test_target_room_table_and_pocket_plate_against_monte_carlo():
    """The benchmark scene (resolution 64): floor points around the table, every one within 4 sigma."""
    res = 64
    light = lamp()
    solid, plate, spheres = pocket_plate()
    boxes = table()
    P = np.vstack([grid(-2, 2, -2, 2, 0.0, 13), grid(-1.1, 1.7, -0.9, 1.3, 0.0, 9)])
    mc_occ = [convex(*box_halfspaces(b.center, b.size)) for b in boxes] + [mc_plate(plate, spheres, res)]
    hulls = [b.corners for b in boxes] + [plate.corners]
    E, S = judge(P, [0, 0, 1], [light], [*boxes, solid], mc_occ, hulls, [b.corners for b in boxes], res)
    assert {0, 1, 2} <= set(S.tolist())


def test_pocket_plate_alone_seen_from_the_floor():
    """No table: the pockets are enclosed by the plate's own slabs and never cut (resolution 64)."""
    res = 64
    light = lamp()
    solid, plate, spheres = pocket_plate()
    P = np.vstack([grid(-2, 2, -2, 2, 0.0, 11), grid(-1.0, 1.6, -0.7, 1.1, 0.0, 9)])
    E, S = judge(P, [0, 0, 1], [light], [solid], [mc_plate(plate, spheres, res)], [plate.corners], [], res, min_judged=0.6)
    assert (S == 1).sum() > 10 and (S == 0).sum() > 10
    pieces = shadow_pieces([solid], grid(-2, 2, -2, 2, 0.0, 3), light.vertices_array, resolution=res)
    assert len(pieces) <= 40  # the full decomposition has thousands at this resolution


@pytest.mark.parametrize("where", ["floor", "plate-top-and-pockets", "beside"])
def test_leaving_hidden_pieces_out_changes_nothing(where):
    """Same E (up to rounding) and states as with every piece of the full decomposition (resolution 12)."""
    res = 12
    light = lamp()
    solid, plate, spheres = pocket_plate(radius=0.08)
    occ = [*table(), solid]
    rng = np.random.default_rng(7)
    if where == "floor":
        P = grid(-2, 2, -2, 2, 0.0, 41)
        N = np.tile([0.0, 0.0, 1.0], (len(P), 1))
    elif where == "plate-top-and-pockets":
        # points on the plate's top and on the pockets' surfaces (normals into the pocket's air)
        top = np.c_[rng.uniform(-0.15, 0.75, 300), rng.uniform(-0.05, 0.45, 300), np.full(300, 0.81)]
        k = rng.integers(0, len(spheres), 300)
        d = rng.normal(size=(300, 3))
        d[:, 2] = -np.abs(d[:, 2]) - 0.3
        d /= np.linalg.norm(d, axis=1, keepdims=True)
        c = np.array([spheres[i].center for i in k])
        pocket = c + 0.08 * 0.999 * d
        P = np.vstack([top, pocket])
        N = np.vstack([np.tile([0.0, 0.0, 1.0], (300, 1)), -d])
    else:
        # a wall beside the table, and points under the table top looking sideways
        wall = np.array([(1.6, y, z) for y in np.linspace(-1.0, 1.4, 25) for z in np.linspace(0.05, 1.5, 16)])
        under = np.c_[rng.uniform(-0.2, 0.8, 200), rng.uniform(-0.1, 0.5, 200), rng.uniform(0.05, 0.7, 200)]
        P = np.vstack([wall, under])
        N = np.vstack([np.tile([-1.0, 0.0, 0.2], (len(wall), 1)), rng.normal(size=(200, 3))])
    N /= np.linalg.norm(N, axis=1, keepdims=True)
    E, S = illuminance_and_state(P, N, [light], occ, resolution=res)
    Ef, Sf, nfull = full_decomposition(P, N, [light], occ, res)
    np.testing.assert_allclose(E, Ef, rtol=1e-9, atol=1e-9 * np.max(Ef))
    np.testing.assert_array_equal(S, Sf)
    kept = len(shadow_pieces(occ, P, light.vertices_array, resolution=res))
    assert kept <= nfull


def test_pockets_seen_from_above_against_monte_carlo():
    """Receivers on the plate and inside the pockets: the pockets are cut (resolution 12), judged by Monte Carlo."""
    res = 12
    light = AreaLight([(-0.2, -0.5, 1.6), (-0.2, 0.5, 1.6), (0.8, 0.5, 1.6), (0.8, -0.5, 1.6)], 10.0)
    solid, plate, spheres = pocket_plate(radius=0.08)
    rng = np.random.default_rng(4)
    k = rng.integers(0, len(spheres), 80)
    d = rng.normal(size=(80, 3))
    d[:, 2] = -np.abs(d[:, 2]) - 0.2
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    c = np.array([spheres[i].center for i in k])
    tess = [s.to_polyhedron(res) for s in spheres]
    # put each point on its tessellated pocket wall: along d from the centre to the polyhedron's boundary
    t = np.array([np.min((tp.face_offsets - tp.face_normals @ ci) / np.maximum(tp.face_normals @ di, 1e-12))
                  for tp, ci, di in zip([tess[i] for i in k], c, d)])
    P = c + (t - 1e-7)[:, None] * d
    N = -d
    top = np.c_[rng.uniform(-0.15, 0.75, 40), rng.uniform(-0.05, 0.45, 40), np.full(40, 0.81)]
    P = np.vstack([P, top])
    N = np.vstack([N, np.tile([0.0, 0.0, 1.0], (40, 1))])
    E, S = judge(P, N, [light], [solid], [mc_plate(plate, spheres, res)], [plate.corners], [], res, min_judged=0.5)
    assert (S[:80] == 1).sum() > 5  # pocket walls are partly shadowed by the pocket's rim
