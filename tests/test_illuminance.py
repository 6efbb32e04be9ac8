"""Exact illuminance and shadow states against an independent Monte Carlo reference.

Every point's exact value must lie in the estimator's 4-sigma interval. The
expected shadow state is decided independently of the library:

- lit (0): the pyramid from p over the part of the source in front of p's
  plane is separated from every occluder's convex hull by more than 1e-6
  (a linear program: the largest ball in pyramid n hull has "radius" < -1e-6);
- umbra (2): no Monte Carlo sample is visible, and one convex occluder is
  crossed more than 1e-6 deep by the segment from p to every source vertex
  (so by every segment to the convex source);
- penumbra (1): some samples are visible and some are blocked (exact ray tests);
- umbra (2) too where no part of the source lies in front of p's receiving
  plane (the conventions: none of the source reaches p);
- anything else is too close to a boundary to judge, and is skipped (few).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
from scipy.optimize import linprog
from scipy.spatial import ConvexHull

import isocsg
from isocsg.shadows import AreaLight, PolyhedronLight, illuminance_and_state

sys.path.insert(0, str(Path(__file__).resolve().parent))

from mc_reference import MCOccluder, box_halfspaces, convex, hull_halfspaces, mc_illuminance  # noqa: E402

MARGIN = 1e-6
RES = 16  # tessellation of curved occluders, shared by the library and the reference


def _clip(poly, p, n):
    out = []
    for i in range(len(poly)):
        a, b = poly[i], poly[(i + 1) % len(poly)]
        da, db = n @ (a - p), n @ (b - p)
        if da >= 0:
            out.append(a)
        if (da >= 0) != (db >= 0):
            out.append(a + da / (da - db) * (b - a))
    return np.array(out)


def _front_parts(p, n, polygons):
    """The emitting polygons facing p, clipped by p's receiving plane (those with area)."""
    parts = []
    for q in polygons:
        q = np.asarray(q, float)
        N = np.cross(q[1] - q[0], q[2] - q[0])
        if N @ (p - q[0]) <= 1e-12:
            continue
        c = _clip(q, p, n)
        if len(c) >= 3 and np.linalg.norm(np.cross(c[1] - c[0], c[2] - c[0])) + len(c) > 3:
            area = 0.5 * np.linalg.norm(sum(np.cross(c[i], c[(i + 1) % len(c)]) for i in range(len(c))))
            if area > 1e-12:
                parts.append(c)
    return parts


def _ball_radius(a, b):
    """Signed radius of the largest ball in {a x <= b} (negative: separated by about that much)."""
    norms = np.linalg.norm(a, axis=1)
    res = linprog([0, 0, 0, -1], A_ub=np.c_[a, norms], b_ub=b, bounds=[(None, None)] * 4, method="highs")
    return res.x[3] if res.status == 0 else -np.inf


def _pyramid_meets(p, part, hs):
    h = ConvexHull(np.vstack([p, part]))
    a = np.vstack([h.equations[:, :3], hs[0]])
    b = np.concatenate([-h.equations[:, 3], hs[1]])
    return _ball_radius(a, b)


def _segment_depth(p, q, hs):
    """Largest r such that some point of segment p-q is r deep inside {a x <= b}."""
    a, b = hs
    norms = np.linalg.norm(a, axis=1)
    d = q - p
    res = linprog([0, -1], A_ub=np.c_[a @ d, norms], b_ub=b - a @ p, bounds=[(0, 1), (None, None)], method="highs")
    return res.x[1] if res.status == 0 else -np.inf


def expected_states(points, normals, polygon_sets, mc_frac, hull_vertices, solid_hull_vertices):
    """Independent expected states (-1: too close to a boundary to judge).

    ``hull_vertices``: vertex arrays of convex sets containing the occluders;
    ``solid_hull_vertices``: those of convex occluders (solid throughout).
    """
    out = np.full(len(points), -1)
    all_hs = [hull_halfspaces(v) for v in hull_vertices]
    solid_hulls = [hull_halfspaces(v) for v in solid_hull_vertices]
    for i, (p, n) in enumerate(zip(points, normals)):
        # an occluder wholly behind the receiving plane cannot block anything in front of it
        hulls = [hs for hs, v in zip(all_hs, hull_vertices) if np.max((v - p) @ n) > 1e-12]
        per_light = []
        for polys in polygon_sets:
            parts = _front_parts(p, n, polys)
            if not parts:  # the receiving plane cuts the whole source away: none of it reaches p
                per_light.append(2)
                continue
            radii = [_pyramid_meets(p, part, hs) for part in parts for hs in hulls]
            if all(r < -MARGIN for r in radii):
                per_light.append(0)
            elif mc_frac[i] == 0 and all(
                any(all(_segment_depth(p, q, hs) > MARGIN for q in part) for hs in solid_hulls) for part in parts
            ):
                per_light.append(2)
            elif 0 < mc_frac[i] < 1 and any(r > MARGIN for r in radii):
                per_light.append(1)
            else:
                per_light.append(-1)
        out[i] = -1 if -1 in per_light else max(per_light)
    return out


def check(points, normals, lights, occluders, mc_occluders, hulls, solid_hulls, *, k=12, replicates=64, min_judged=0.9):
    """Compare with Monte Carlo; ``hulls``/``solid_hulls`` are vertex arrays (see expected_states)."""
    points = np.asarray(points, float)
    normals = np.broadcast_to(np.asarray(normals, float), points.shape)
    normals = normals / np.linalg.norm(normals, axis=1, keepdims=True)
    E, S = illuminance_and_state(points, normals, lights, occluders, resolution=RES)
    sources = [(light.emitting_polygons(), light.radiance) for light in lights]
    mc = mc_illuminance(points, normals, sources, mc_occluders, k=k, replicates=replicates)
    tol = mc.tolerance(E)
    bad = np.abs(E - mc.mean) > tol
    assert not bad.any(), (
        f"{bad.sum()} points outside 4 sigma: exact {E[bad][:5]}, mc {mc.mean[bad][:5]} +- {mc.se[bad][:5]}"
    )
    polygon_sets = [light.emitting_polygons() for light in lights]
    exp = expected_states(points, normals, polygon_sets, mc.visible_fraction, hulls, solid_hulls)
    judged = exp >= 0
    assert judged.mean() > min_judged, f"only {judged.mean():.0%} of the points could be judged"
    mism = judged & (exp != S)
    assert not mism.any(), f"states differ at {points[mism][:5]}: exact {S[mism][:5]}, expected {exp[mism][:5]}"
    return E, S, exp


def grid(x0, x1, y0, y1, z, m):
    xs, ys = np.linspace(x0, x1, m), np.linspace(y0, y1, m)
    return np.array([(x, y, z) for x in xs for y in ys])


def square_light(cx, cy, z, a, b, L=1.0):
    return AreaLight([(cx - a, cy - b, z), (cx - a, cy + b, z), (cx + a, cy + b, z), (cx + a, cy - b, z)], L)


def test_box_under_square_source():
    lamp = square_light(0, 0, 3.0, 0.5, 0.5, 2.0)
    box = isocsg.Box((0.2, 0.1, 1.2), (0.8, 0.6, 0.4))
    hs = box_halfspaces(box.center, box.size)
    P = grid(-2, 2, -2, 2, 0.0, 15)
    _, S, _ = check(P, [0, 0, 1], [lamp], [box], [convex(*hs)], [box.corners], [box.corners])
    assert set(S.tolist()) == {0, 1, 2}


def test_two_occluders_with_overlapping_penumbrae():
    lamp = square_light(0, 0, 3.0, 0.6, 0.4, 1.0)
    b1 = isocsg.Box((-0.35, 0.0, 1.0), (0.5, 0.5, 0.3))
    b2 = isocsg.Box((0.3, 0.1, 1.8), (0.4, 0.7, 0.2))
    hs = [box_halfspaces(b.center, b.size) for b in (b1, b2)]
    P = grid(-1.5, 1.5, -1.2, 1.2, 0.0, 13)
    cs = [b1.corners, b2.corners]
    E, S, _ = check(P, [0, 0, 1], [lamp], [b1, b2], [convex(*h) for h in hs], cs, cs)
    assert (S == 1).sum() > 20


def test_tilted_triangle_source_cut_by_receiving_planes():
    """Type B: every receiving plane cuts the tilted triangle source."""
    tri = np.array([(-1.0, -0.6, 1.0), (1.2, -0.2, 1.6), (-0.2, 1.1, 2.2)])
    lamp = AreaLight(tri, 3.0)
    if lamp.normal[2] > 0:
        lamp = AreaLight(tri[::-1], 3.0)
    occ = isocsg.Box((0.1, 0.2, 0.7), (0.3, 0.3, 0.2))
    hs = box_halfspaces(occ.center, occ.size)
    P = grid(-0.9, 0.9, -0.9, 0.9, 0.0, 9)
    rng = np.random.default_rng(3)
    N = np.c_[rng.uniform(-4.0, 4.0, (len(P), 2)), np.ones(len(P))]
    N /= np.linalg.norm(N, axis=1, keepdims=True)
    cut = [np.any((tri - p) @ n < 0) and np.any((tri - p) @ n > 0) for p, n in zip(P, N)]
    assert np.mean(cut) > 0.5
    check(P, N, [lamp], [occ], [convex(*hs)], [occ.corners], [occ.corners])


def test_cube_source_with_tetrahedron_occluder():
    cube = PolyhedronLight([(x, y, z) for x in (-0.3, 0.3) for y in (-0.3, 0.3) for z in (2.0, 2.6)], 1.5)
    tet_v = np.array([(-0.4, -0.3, 1.0), (0.5, -0.2, 1.1), (0.0, 0.5, 0.9), (0.05, 0.0, 1.6)])
    tet = isocsg.ConvexPolyhedron(tet_v)
    hs = hull_halfspaces(tet_v)
    floor = grid(-2, 2, -2, 2, 0.0, 11)
    wall = np.array([(1.5, y, z) for y in np.linspace(-1.5, 1.5, 7) for z in np.linspace(0.2, 3.0, 7)])
    P = np.vstack([floor, wall])
    N = np.vstack([np.tile([0, 0, 1.0], (len(floor), 1)), np.tile([-1.0, 0, 0], (len(wall), 1))])
    _, S, _ = check(P, N, [cube], [tet], [convex(*hs)], [tet_v], [tet_v], k=10)
    assert (S == 1).sum() > 5


def test_csg_occluder_plate_with_a_hole():
    lamp = square_light(0, 0, 3.0, 0.4, 0.4, 1.0)
    plate = isocsg.Box((0, 0, 1.2), (1.4, 1.4, 0.1))
    hole = isocsg.Cylinder((0.1, 0.0, 1.2), (0, 0, 0.4), 0.3)
    occ = plate - hole
    hp = box_halfspaces(plate.center, plate.size)
    hh = hull_halfspaces(hole.to_polyhedron(RES).hull_vertices)
    mc_occ = [MCOccluder(plus=[hp], minus=[hh])]
    P = grid(-1.5, 1.5, -1.5, 1.5, 0.0, 13)
    # umbrae of a holed plate are not certified independently (no convex solid to test against)
    E, S, _ = check(P, [0, 0, 1], [lamp], [occ], mc_occ, [plate.corners], [], min_judged=0.6)
    assert set(S.tolist()) == {0, 1, 2}
    centre = np.argmin(np.linalg.norm(P[:, :2] - [0.1, 0.0], axis=1))
    assert E[centre] > 0  # light comes through the hole


def table_scene():
    lamp = square_light(0.0, 0.0, 2.8, 0.6, 0.3, 1000.0)
    lamp = AreaLight(lamp.vertices, 1000.0)
    top = isocsg.Box((0.3, 0.2, 0.73), (1.2, 0.8, 0.04))
    legs = [isocsg.Box((0.3 + sx * 0.55, 0.2 + sy * 0.35, 0.355), (0.05, 0.05, 0.71)) for sx in (-1, 1) for sy in (-1, 1)]
    return lamp, [top, *legs]


def test_room_floor_under_a_luminaire_and_a_table():
    lamp, boxes = table_scene()
    hs = [box_halfspaces(b.center, b.size) for b in boxes]
    P = grid(-2, 2, -2, 2, 0.0, 15)
    cs = [b.corners for b in boxes]
    E, S, _ = check(P, [0, 0, 1], [lamp], boxes, [convex(*h) for h in hs], cs, cs)
    assert {0, 1, 2} <= set(S.tolist())


def test_table_top_points_and_several_lights():
    lamp, boxes = table_scene()
    lamp2 = square_light(1.5, -1.0, 2.5, 0.2, 0.2, 500.0)
    hs = [box_halfspaces(b.center, b.size) for b in boxes]
    top = grid(-0.25, 0.85, -0.15, 0.55, 0.75, 6)  # on the table top: its own box must not shadow it
    side = np.array([(0.95, y, z) for y in np.linspace(-0.1, 0.5, 4) for z in (0.2, 0.5)])  # beside the legs
    P = np.vstack([top, side])
    N = np.vstack([np.tile([0, 0, 1.0], (len(top), 1)), np.tile([1.0, 0, 0], (len(side), 1))])
    cs = [b.corners for b in boxes]
    E, S, _ = check(P, N, [lamp, lamp2], boxes, [convex(*h) for h in hs], cs, cs)
    assert np.all(S[: len(top)] == 0)


def test_receiving_plane_cutting_away_the_whole_source_is_umbra():
    """None of the source in front of the receiving plane: E = 0 and state 2 (the conventions)."""
    lamp = square_light(0, 0, 3.0, 0.5, 0.5, 2.0)
    cube = PolyhedronLight([(x, y, z) for x in (2.7, 3.3) for y in (-0.3, 0.3) for z in (1.7, 2.3)], 1.5)
    box = isocsg.Box((0.2, 0.1, 1.2), (0.8, 0.6, 0.4))
    hs = box_halfspaces(box.center, box.size)
    P = np.array([
        (-1.5, 0.0, 0.0), (0.0, 0.0, 0.0),  # facing +x (lit by the square), facing up (under the box)
        (1.5, 1.5, 0.0),  # facing down, under the square source: type C
        (0.3, -0.2, 3.5),  # above the square source, facing up: behind its emitting side
        (0.2, 0.3, 3.0),  # in the source's plane, outside the polygon
        (1.8, 0.0, 0.5),  # tilted so that its plane passes above every source vertex
        (3.0, 0.0, 0.5),  # under the cube source, facing down
        (3.0, 0.0, 0.0),  # under the cube, facing up: lit by the cube
    ])
    N = np.array([
        (1.0, 0.0, 0.0), (0.0, 0.0, 1.0),
        (0.0, 0.0, -1.0),
        (0.0, 0.0, 1.0),
        (1.0, 0.0, 0.0),
        (0.9, 0.0, -0.1),
        (0.0, 0.0, -1.0),
        (0.0, 0.0, 1.0),
    ])
    N /= np.linalg.norm(N, axis=1, keepdims=True)
    # the square alone: points 2..5 have nothing of it in front of their planes
    E, S, exp = check(P[:6], N[:6], [lamp], [box], [convex(*hs)], [box.corners], [box.corners])
    np.testing.assert_array_equal(S[2:6], 2)
    np.testing.assert_array_equal(E[2:6], 0.0)
    assert E[0] > 0 and S[0] == 0
    # the cube alone: facing away from it is state 2, facing it is lit
    E, S, _ = check(P[6:], N[6:], [cube], [], [], [], [])
    assert S.tolist() == [2, 0] and E[0] == 0.0 and E[1] > 0
    # both lights: the worst state over the lights; the square lights this point, the cube is behind its plane
    p, n = np.array([(1.5, 0.0, 1.0)]), np.array([(-1.0, 0.0, 0.2)])
    E, S, _ = check(p, n, [lamp, cube], [box], [convex(*hs)], [box.corners], [box.corners])
    assert S.tolist() == [2] and E[0] > 0
