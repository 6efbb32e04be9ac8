"""OpenSCAD's ``resize(newsize, auto)`` (``isocsg.openscad.resize``).

- The ``resize_*`` models of ``tests/data/openscad/projection22`` against the volumes of
  OpenSCAD's STL exports (``stl_volumes.json``; its ``about`` gives the command): polygonal
  children exactly (the STL's 6 printed digits), round ones within 0.5 % (OpenSCAD scales by
  its 96-gon's box, isocsg by the exact one).
- OpenSCAD 2021.01's rules (``PolySet::resize``): the scale of each axis, ``auto``, zero sizes.
- Exact bounds of trees against manifold3d meshes built here from its own primitives.
"""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from isocsg import Box, Sphere, volume
from isocsg.openscad import read_openscad
from isocsg.openscad.lowering import lower
from isocsg.openscad.parser import parse_csg
from isocsg.openscad.resize import resize_scale, shape_bounds, solid_bounds
from isocsg.shapes2d import circle, square

manifold3d = pytest.importorskip("manifold3d")

DIR = Path(__file__).resolve().parent / "data" / "openscad" / "projection22"
VOLUMES = json.loads((DIR / "stl_volumes.json").read_text())["models"]
MODELS = sorted(p.stem for p in DIR.glob("resize_*.scad"))
POLYGONAL = {"resize_cube", "resize_polygonal", "resize_2d"}


@pytest.mark.parametrize("name", MODELS)
def test_resize_volume_matches_openscad(name: str) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        got = volume(read_openscad(DIR / f"{name}.csg").solid)
    assert got == pytest.approx(VOLUMES[name]["volume"], rel=2e-5 if name in POLYGONAL else 5e-3)


@pytest.mark.parametrize(
    ("newsize", "auto", "want"),
    [
        ([5, 0, 0], [False] * 3, [5, 1, 1]),
        ([5, 0, 0], [True] * 3, [5, 5, 5]),
        ([5, 0, 0], [True, True, False], [5, 5, 1]),
        ([0, 0, 7], [True, True, False], [7, 7, 7]),
        ([5, 0, 20], [False, True, True], [5, 20, 20]),  # auto takes the largest new size's scale
        ([0, 0, 0], [True] * 3, [1, 1, 1]),
        ([-5, 0, 0], [False] * 3, [1, 1, 1]),  # not > 0: kept, as PolySet::resize keeps it
    ],
)
def test_openscad_scale_rules(newsize: list[float], auto: list[bool], want: list[float]) -> None:
    assert resize_scale(newsize, auto, np.ones(3)).tolist() == want


def _box_of(text: str) -> np.ndarray:
    model = lower(parse_csg(text))
    return np.asarray(model.solid.bounds)


def test_resize_scales_about_the_origin_under_the_parents_map() -> None:
    box = _box_of("multmatrix([[1, 0, 0, 10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) "
                  "resize(newsize = [4, 0, 0], auto = [1, 1, 1]) cube(size = [2, 1, 1]);")
    assert box.tolist() == [[10.0, 0.0, 0.0], [14.0, 2.0, 2.0]]
    # a number where a vector belongs, auto = 3: OpenSCAD 2021.01 changes nothing
    assert _box_of("resize(newsize = 5, auto = 3) cube(size = [2, 1, 1]);").tolist() == [[0, 0, 0], [2, 1, 1]]
    # any aspect: a 1e10-high cube squeezed to 0.5
    assert _box_of("resize(newsize = [0, 0, 0.5]) cube(size = [6, 6, 1e10]);")[1].tolist() == [6.0, 6.0, 0.5]


def test_exact_bounds_of_curved_trees() -> None:
    # a sphere cut flat at z = 5: the leaves' box says 10
    b = solid_bounds(Sphere((0, 0, 0), 10) - Box((0, 0, 15), (20, 20, 20)))
    assert b[1, 2] == pytest.approx(5.0, abs=1e-7)
    assert b[0].tolist() == [-10.0, -10.0, -10.0]
    # a 2D union with an arc on the box, and a disc bitten by a square
    assert shape_bounds(square(10) | circle(5).translate([10, 5])).tolist() == [[0, 0], [15, 10]]
    bitten = shape_bounds(circle(5) - square(20).translate([-1, -10]))  # x <= -1 left: top at sqrt(24)
    assert bitten[1, 0] == pytest.approx(-1.0, abs=1e-12)
    assert bitten[1, 1] == pytest.approx(math.sqrt(24.0), abs=1e-12)


@settings(max_examples=10, deadline=None)
@given(st.floats(0.0, 80.0), st.floats(-0.9, 0.9))
def test_bounds_of_a_cut_sphere_in_closed_form(tilt: float, depth: float) -> None:
    """A ball of radius R cut by the tilted plane n . p <= d, n = (sin a, 0, cos a): each bound is
    the ball's own where that extreme point is kept, else the extreme of the cut circle (centre
    d n, radius sqrt(R^2 - d^2), in the plane spanned by (cos a, 0, -sin a) and y)."""
    R, a = 1.5, math.radians(tilt)
    d = depth * R
    n = np.array([math.sin(a), 0.0, math.cos(a)])
    keep = Box((0, 0, -10), (40, 40, 20)).rotate([0, tilt, 0]).translate((d * n).tolist())  # n . p <= d
    got = solid_bounds(Sphere((0, 0, 0), R) & keep)
    rho = math.sqrt(R * R - d * d)
    want = np.empty((2, 3))
    for axis in range(3):
        e1 = np.array([math.cos(a), 0.0, -math.sin(a)])
        reach = rho * math.hypot(e1[axis], 1.0 if axis == 1 else 0.0)
        for side, sign in ((0, -1.0), (1, 1.0)):
            tip = np.zeros(3)
            tip[axis] = sign * R
            want[side, axis] = sign * R if tip @ n <= d else d * n[axis] + sign * reach
    assert np.allclose(got, want, atol=1e-6 * R)
