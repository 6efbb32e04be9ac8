"""OpenSCAD's 2D nodes (as a .csg file writes them) mapped onto 2D shapes."""

from __future__ import annotations

import math
import re

import pytest

from isocsg.errors import InvalidGeometryError, UnsupportedOpenSCADError
from isocsg.shapes2d import (
    EMPTY,
    Circle,
    ConvexPolygon,
    area,
    circle,
    fragments,
    from_openscad,
    offset,
    square,
    text,
    text_segments,
)


@pytest.mark.parametrize(
    "r, fn, fs, fa, expected",
    [(10, 0, 2, 12, 30), (1, 0, 2, 12, 5), (100, 0, 2, 12, 30), (10, 0, 0.1, 1, 360), (5, 6, 2, 12, 6), (5, 2, 2, 12, 3)],
)
def test_fragments_follow_openscad(r, fn, fs, fa, expected):
    assert fragments(r, fn, fs, fa) == expected


def test_text_segments_follow_openscad():
    assert text_segments(10) == 4 and text_segments(1) == 2 and text_segments(10, fn=64) == 9


def test_leaves():
    assert from_openscad("square", {"size": [2, 3], "center": False}) == square([2, 3])
    assert from_openscad("circle", {"r": 2, "$fn": 0, "$fa": 12, "$fs": 2}) == Circle((0, 0), 2)
    hexagon = from_openscad("circle", {"r": 2, "$fn": 6})
    assert isinstance(hexagon, ConvexPolygon) and len(hexagon.vertices) == 6
    poly = from_openscad("polygon", {"points": [[0, 0], [2, 0], [0, 2]], "paths": None, "convexity": 1})
    assert area(poly) == 2.0
    label = from_openscad("text", {"text": "I", "size": 10, "font": "", "halign": "left", "valign": "baseline",
                                   "spacing": 1, "$fn": 0, "$fa": 12, "$fs": 2})
    assert label == text("I", segments=4)


def test_multmatrix_and_booleans():
    m = [[0, -1, 0, 5], [1, 0, 0, 1], [0, 0, 1, 0], [0, 0, 0, 1]]
    moved = from_openscad("multmatrix", {"m": m}, [square(1)])
    assert moved.bounds == (4.0, 1.0, 5.0, 2.0)
    plate = from_openscad("difference", {}, [square(4, center=True), circle(1)])
    assert area(plate) == pytest.approx(16 - math.pi, rel=1e-14)
    assert from_openscad("union", {}, []) == EMPTY
    assert from_openscad("difference", {}, [EMPTY, square(1)]) == EMPTY
    assert from_openscad("group", {}, [square(1)]) == square(1)


def test_offset_nodes():
    assert from_openscad("offset", {"r": 1, "delta": 1, "chamfer": False}, [square(2)]) == offset(square(2), 1)
    chamfered = from_openscad("offset", {"r": None, "delta": 1, "chamfer": True}, [square(2)])
    assert chamfered == offset(square(2), delta=1, chamfer=True)


def test_errors():
    with pytest.raises(UnsupportedOpenSCADError, match=re.escape("hull() of 2D shapes is not supported")) as info:
        from_openscad("hull", {}, [square(1)])
    assert info.value.node == "hull"
    with pytest.raises(InvalidGeometryError, match=re.escape("multmatrix.m must keep 2D shapes in the xy plane")):
        from_openscad("multmatrix", {"m": [[1, 0, 0, 0], [0, 0, 1, 0], [0, 1, 0, 0], [0, 0, 0, 1]]}, [square(1)])
