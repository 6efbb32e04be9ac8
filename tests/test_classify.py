"""F (eq. 1), H (eq. 2) and the face types A/B/C (eqs. 3, 4).

Judges: signed distances written out from the plane equation, hand-built
configurations with known answers, and the exact unoccluded illuminance
(a face of type C receives nothing, faces of types A and B receive light; a
type-A face receives the whole source: the same illuminance as the unclipped
Lambert sum written in the test).
"""

from __future__ import annotations

import numpy as np
import pytest

from isocsg import Box, ConvexPolyhedron, InvalidGeometryError, InvalidLightError
from isocsg.lighting.area import AreaLight, PolyhedronLight
from isocsg.shadows import illuminance
from isocsg.shadows.classify import (
    F,
    FaceType,
    H,
    Plane,
    classify_face,
    classify_faces,
    face_plane,
    face_type_area,
    face_type_polyhedron,
    solid_faces,
)


def _lambert_unclipped(p, n, poly, L=1.0):
    """Eq. (7) over the whole polygon (valid when it lies entirely in front of p's plane)."""
    e = 0.0
    for a, b in zip(poly, np.roll(poly, -1, axis=0)):
        u, v = a - p, b - p
        beta = np.arctan2(np.linalg.norm(np.cross(u, v)), u @ v)
        g = np.cross(u, v)
        g /= np.linalg.norm(g)
        e += beta * (n @ g)
    return abs(L / 2 * e)


def test_F_is_the_signed_distance_to_the_tilted_plane():
    rng = np.random.default_rng(0)
    n = np.array([1.0, 2.0, -2.0]) / 3.0
    d = 0.7
    e1 = np.cross(n, [0, 0, 1.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)  # (e1, e2, n) right-handed, so e1 -> e2 is counter-clockwise about n
    face = np.array([d * n + 2 * (np.cos(a) * e1 + np.sin(a) * e2) for a in np.linspace(0, 2 * np.pi, 5, endpoint=False)])
    pts = rng.normal(size=(50, 3)) * 3
    np.testing.assert_allclose(F(face, pts), pts @ n - d, atol=1e-12)
    pl = face_plane(face)
    np.testing.assert_allclose(pl.normal, n, atol=1e-12)
    assert pl.offset == pytest.approx(d, abs=1e-12)
    np.testing.assert_allclose(F(Plane(n, d), pts), pts @ n - d, atol=1e-12)
    # reversing the winding flips the sign
    np.testing.assert_allclose(F(face[::-1], pts), -(pts @ n - d), atol=1e-12)


@pytest.mark.parametrize(
    "zs,expected",
    [([1, 2, 3], 1), ([0, 1, 2], 1), ([0, 0, 0], 1), ([-1, -2, 0], -1), ([-1, 1, 0], 0), ([-1e-3, 5], 0)],
    ids=["above", "touching-above", "in-plane", "below", "crossing", "barely-crossing"],
)
def test_H_cases(zs, expected):
    floor = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    pts = [(0.3 * i, 0.1, z) for i, z in enumerate(zs)]
    assert H(floor, pts) == expected


def test_H_tolerance():
    floor = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    assert H(floor, [(0, 0, -1e-12), (0, 0, 1)]) == 1
    assert H(floor, [(0, 0, -1e-3), (0, 0, 1)], tol=1e-2) == 1
    assert H(floor, [(0, 0, -1e-3), (0, 0, 1)], tol=1e-4) == 0


LAMP = AreaLight([(-1, -1, 3), (-1, 1, 3), (1, 1, 3), (1, -1, 3)])  # faces down


@pytest.mark.parametrize(
    "face,expected",
    [
        ([(-5, -5, 0), (5, -5, 0), (5, 5, 0), (-5, 5, 0)], FaceType.A),  # floor
        ([(-5, -5, 4), (-5, 5, 4), (5, 5, 4), (5, -5, 4)], FaceType.C),  # above the source (behind it)
        ([(-5, -5, 1), (-5, 5, 1), (5, 5, 1), (5, -5, 1)], FaceType.C),  # faces down, away from the source
        ([(0, -5, 0), (0, 5, 0), (0, 5, 2), (0, -5, 2)], FaceType.B),  # a wall through the source's middle
        ([(2, -5, 0), (2, 5, 0), (2, 5, 2), (2, -5, 2)], FaceType.C),  # wall beside the source, turned away
        ([(2, -5, 0), (2, -5, 2), (2, 5, 2), (2, 5, 0)], FaceType.A),  # same wall turned towards it
        ([(0, -5, 2), (0, 5, 2), (0, 5, 4), (0, -5, 4)], FaceType.B),  # crosses the source plane too
    ],
    ids=["floor", "above", "turned-away", "wall-cuts", "wall-away", "wall-towards", "wall-through-plane"],
)
def test_area_face_types_by_hand(face, expected):
    assert face_type_area(face, LAMP.vertices) == expected
    assert classify_face(face, LAMP) == expected


def test_box_faces_under_a_source():
    box = Box((0, 0, 0), (1, 1, 1))
    types = classify_faces(box, LAMP)
    normals = [face_plane(f).normal for f in solid_faces(box)]
    for t, n in zip(types, normals):
        if n[2] > 0.5:
            assert t == FaceType.A
        elif n[2] < -0.5:
            assert t == FaceType.C
        else:
            assert t == FaceType.B  # the source (width 2) straddles every side plane (width 1)


def test_polyhedron_source_types():
    cube = PolyhedronLight([(x, y, z) for x in (0, 1) for y in (0, 1) for z in (2, 3)])
    assert face_type_polyhedron([(-5, -5, 0), (5, -5, 0), (5, 5, 0), (-5, 5, 0)], cube.polyhedron.hull_vertices) == FaceType.A
    assert classify_face([(0.5, -5, 0), (0.5, 5, 0), (0.5, 5, 2), (0.5, -5, 2)], cube) == FaceType.B
    assert classify_face([(-5, -5, 1), (-5, 5, 1), (5, 5, 1), (5, -5, 1)], cube) == FaceType.C


def _random_polygon(rng):
    c = rng.uniform(-2, 2, 3)
    n = rng.normal(size=3)
    n /= np.linalg.norm(n)
    e1 = np.cross(n, rng.normal(size=3))
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    ang = np.sort(rng.uniform(0, 2 * np.pi, 5))
    r = rng.uniform(0.5, 1.5)
    return np.array([c + r * (np.cos(a) * e1 + np.sin(a) * e2) for a in ang]), n


def test_types_agree_with_unoccluded_illuminance():
    """Type C: no light anywhere on the face. A: whole source (unclipped Lambert). B: partial."""
    rng = np.random.default_rng(3)
    seen = {t: 0 for t in FaceType}
    for _ in range(150):
        face, n = _random_polygon(rng)
        src, _ = _random_polygon(rng)
        try:
            light = AreaLight(src)
        except InvalidLightError:
            continue
        t = classify_face(face, light)
        w = rng.dirichlet(np.ones(len(face)), size=300)
        pts = np.vstack([face, w @ face])  # the vertices catch thin slivers in front of the source
        e = illuminance(pts, np.broadcast_to(n, pts.shape), light)
        if t == FaceType.C:
            assert np.all(e == 0)
        else:
            assert np.any(e > 0)
        if t == FaceType.A:
            # points of the face in front of the source get the whole source
            sv = light.vertices_array
            front = (pts - sv[0]) @ light.normal_array > 1e-9
            for p, ei in list(zip(pts[front], e[front]))[:5]:
                assert ei == pytest.approx(_lambert_unclipped(p, n, sv), rel=1e-9, abs=1e-12)
        seen[t] += 1
    assert min(seen.values()) >= 10, seen


def test_errors():
    with pytest.raises(InvalidGeometryError, match="no area"):
        face_plane([(0, 0, 0), (1, 0, 0), (2, 0, 0)])
    with pytest.raises(InvalidGeometryError, match="polygon"):
        face_plane([(0, 0, 0), (1, 0, 0)])
    with pytest.raises(InvalidLightError, match="AreaLight or a PolyhedronLight"):
        classify_face([(0, 0, 0), (1, 0, 0), (0, 1, 0)], "lamp")
    with pytest.raises(InvalidGeometryError, match="solid must be"):
        solid_faces(3.0)
    assert len(solid_faces(ConvexPolyhedron([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]))) == 4
