"""Occluder decomposition: pieces are convex, cover the solid exactly and do not overlap.

Judged by point membership of the CSG tree itself (isocsg.csg contains, on the
tessellated primitives) and by exact volumes of the polyhedral results.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

import isocsg
from isocsg import Box, ConvexPolyhedron, Cylinder, Sphere
from isocsg.shadows import convex_pieces

RES = 12


def tess(s):
    """The same solid with curved primitives replaced by their tessellation (what the pieces represent)."""
    if isinstance(s, (Box, ConvexPolyhedron)):
        return s
    if isinstance(s, isocsg.Primitive):
        return s.to_polyhedron(RES)
    return type(s)(*[tess(c) for c in s.children])


SOLIDS = {
    "box": Box((0, 0, 0), (1, 2, 3)),
    "sphere": Sphere((0.1, 0.2, 0.3), 0.8),
    "union": Box((0, 0, 0), (1, 1, 1)) | Sphere((1.2, 0, 0), 0.6),
    "intersection": Box((0, 0, 0), (1.5, 1.5, 1.5)) & Sphere((0.3, 0, 0), 0.9),
    "plate-minus-cylinder": Box((0, 0, 0), (2, 2, 0.2)) - Cylinder((0.2, 0, 0), (0, 0, 1), 0.4),
    "box-minus-two": Box((0, 0, 0), (2, 2, 2)) - Box((1, 1, 1), (1, 1, 1)) - Sphere((-1, -1, -1), 0.7),
    "nested": (Box((0, 0, 0), (2, 2, 2)) - Box((0, 0, 0), (1, 1, 3))) & Box((0.5, 0.5, 0), (2, 2, 1)),
    # overlapping pockets: a region left by one pocket's box split is cut by the next
    "pockets": Box((0, 0, 0), (2, 1, 0.3)) - Sphere((-0.5, 0, 0.15), 0.25) - Sphere((0.5, 0, 0.15), 0.25)
    - Sphere((0.1, 0.2, 0.15), 0.3),
    "minus-a-difference": Box((0, 0, 0), (2, 2, 2)) - (Box((0.5, 0, 0), (2, 1, 1)) - Sphere((0.8, 0, 0), 0.5)),
    "union-minus": (Box((0, 0, 0), (1, 1, 1)) | Box((0.8, 0, 0), (1, 1, 0.6))) - Cylinder((0.4, 0, 0), (0, 0, 2), 0.3),
    "intersection-minus": (Box((0, 0, 0), (2, 2, 2)) & Sphere((0.2, 0, 0), 1.2)) - Box((0.5, 0.5, 0.5), (1, 1, 1)),
}


UNION_OVERLAPS = {"union-minus"}  # the operands of a union overlap: so may their pieces


@pytest.mark.parametrize("name", list(SOLIDS), ids=list(SOLIDS))
def test_pieces_cover_the_solid_without_overlap(name):
    solid = SOLIDS[name]
    pieces = convex_pieces([solid], resolution=RES)
    assert pieces
    ref = tess(solid)
    b = solid.bounds
    rng = np.random.default_rng(5)
    pts = rng.uniform(b[0] - 0.1, b[1] + 0.1, (20000, 3))
    inside = ref.contains(pts)
    counts = np.zeros(len(pts), int)
    for pc in pieces:
        # convexity: every vertex satisfies every face inequality
        assert np.all(pc.vertices @ pc.normals.T <= pc.offsets + 1e-9)
        counts += pc.contains(pts, tol=-1e-9)  # strict interiors
    loose = np.zeros(len(pts), bool)
    for pc in pieces:
        loose |= pc.contains(pts, tol=1e-9)
    # every point strictly inside a piece is in the solid; every point of the solid is in some piece
    assert not np.any((counts > 0) & ~inside)
    assert not np.any(inside & ~loose)
    if name not in UNION_OVERLAPS:
        assert counts.max() <= 1  # interiors are disjoint


def test_volumes_add_up():
    solid = Box((0, 0, 0), (2, 2, 2)) - Box((1, 1, 1), (1, 1, 1))
    vol = sum(ConvexPolyhedron(p.vertices).volume for p in convex_pieces(solid))
    assert vol == pytest.approx(8.0 - 0.5**3, rel=1e-12)  # the cube [0.5, 1.5]^3 overlaps by 0.5^3
    plate = Box((0, 0, 0), (2, 2, 0.2)) - Cylinder((0.2, 0, 0), (0, 0, 1), 0.4)
    vol = sum(ConvexPolyhedron(p.vertices).volume for p in convex_pieces(plate, resolution=RES))
    polygon_area = RES / 2 * 0.4**2 * np.sin(2 * np.pi / RES)
    assert vol == pytest.approx(0.2 * (4 - polygon_area), rel=1e-12)


def test_empty_results_are_dropped():
    assert convex_pieces(Box((0, 0, 0), (1, 1, 1)) & Box((5, 0, 0), (1, 1, 1))) == []
    assert convex_pieces(Box((0, 0, 0), (1, 1, 1)) - Box((0, 0, 0), (2, 2, 2))) == []


def test_bad_occluders():
    with pytest.raises(isocsg.InvalidGeometryError, match=re.escape("occluders[1] must be a primitive or a CSG tree, got str")):
        convex_pieces([Box((0, 0, 0), (1, 1, 1)), "box"])
    with pytest.raises(isocsg.InvalidParameterError, match=re.escape("resolution must be between 3 and 512, got 2")):
        convex_pieces([Sphere((0, 0, 0), 1)], resolution=2)
