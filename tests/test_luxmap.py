"""Illuminance maps, isolux lines and their PNG.

Judges: Lambert's formula written in the test (unoccluded nodes), similar
triangles (the umbra square of a square occluder under a parallel square
source), exact level sets of linear and radial fields, and a count of the
grid edges whose ends straddle a level (each holds exactly one line point).
"""

from __future__ import annotations

import numpy as np
import pytest
from PIL import Image

from isocsg import Box, InvalidParameterError
from isocsg.lighting.area import AreaLight
from isocsg.shadows.luxmap import LuxGrid, illuminance_map, isolux_lines, nice_levels, save_luxmap_png

SQUARE = [(-0.5, -0.5, 2.0), (-0.5, 0.5, 2.0), (0.5, 0.5, 2.0), (0.5, -0.5, 2.0)]


def _lambert(p, n, poly, L=1.0):
    e = 0.0
    for a, b in zip(poly, np.roll(poly, -1, axis=0)):
        u, v = a - p, b - p
        g = np.cross(u, v)
        e += np.arctan2(np.linalg.norm(g), u @ v) * (n @ (g / np.linalg.norm(g)))
    return abs(L / 2 * e)


def test_unoccluded_map_is_lamberts_formula_on_a_tilted_grid():
    lamp = AreaLight(SQUARE, radiance=3.0)
    grid = LuxGrid((-1.5, -1.0, 0.2), (3.0, 0.0, 0.4), (0.0, 2.5, -0.2), 7, 6)
    m = illuminance_map(grid, lamp)
    pts = grid.points()
    for j in range(grid.ny):
        for i in range(grid.nx):
            assert m.E[j, i] == pytest.approx(_lambert(pts[j, i], grid.normal, np.array(SQUARE), 3.0), rel=1e-9)


def test_umbra_on_the_map_by_similar_triangles():
    lamp = AreaLight(SQUARE)
    a, ho, t = 0.8, 1.0, 0.02
    grid = LuxGrid.from_bounds(-1.5, -1.5, 1.5, 1.5, 0.0, 61, 61)
    m = illuminance_map(grid, lamp, [Box((0, 0, ho), (a, a, t))])
    x_umb = 0.5 + (a / 2 - 0.5) * 2.0 / (2.0 - (ho - t / 2))
    x_pen = -0.5 + (a / 2 + 0.5) * 2.0 / (2.0 - (ho + t / 2))
    p = grid.points()
    r = np.max(np.abs(p[..., :2]), axis=2)
    assert np.all(m.E[r < x_umb - 1e-6] == 0)
    assert np.all(m.E[r > x_umb + 1e-6] > 0)
    full = np.array([[_lambert(q, np.array([0, 0, 1.0]), np.array(SQUARE)) for q in row] for row in p])
    lit = r > x_pen + 1e-6
    np.testing.assert_allclose(m.E[lit], full[lit], rtol=1e-9)
    assert np.all(m.E[~lit] < full[~lit])


def test_isolux_of_a_linear_field_is_exact():
    j, i = np.mgrid[0:20, 0:30].astype(float)
    E = 0.3 * i + 0.7 * j + 1.0
    for level, lines in zip([3.3, 10.0, 15.55], isolux_lines(E, [3.3, 10.0, 15.55])):
        assert len(lines) == 1
        pts, closed = lines[0]
        assert not closed
        np.testing.assert_allclose(0.3 * pts[:, 0] + 0.7 * pts[:, 1] + 1.0, level, atol=1e-12)


def test_isolux_of_a_radial_field_are_closed_rings():
    j, i = np.mgrid[0:81, 0:81].astype(float)
    r = np.hypot(i - 40.3, j - 39.6)
    lines = isolux_lines(-r, [-10.0, -25.0])
    for radius, level_lines in zip([10.0, 25.0], lines):
        assert len(level_lines) == 1
        pts, closed = level_lines[0]
        assert closed
        np.testing.assert_allclose(pts[0], pts[-1])
        # linear interpolation of the cone field along grid edges: error below h^2 / (2 r)
        np.testing.assert_allclose(np.hypot(pts[:, 0] - 40.3, pts[:, 1] - 39.6), radius, atol=1 / (2 * radius) + 1e-9)


@pytest.mark.parametrize("seed", [0, 1, 2], ids=["seed0", "seed1", "seed2"])
def test_every_straddling_edge_holds_one_line_point(seed):
    rng = np.random.default_rng(seed)
    E = rng.normal(size=(12, 15))
    level = 0.1
    above = E > level
    straddle = int(np.sum(above[:, 1:] != above[:, :-1]) + np.sum(above[1:, :] != above[:-1, :]))
    lines = isolux_lines(E, [level])[0]
    pts = [tuple(np.round(p, 12)) for line, closed in lines for p in (line[:-1] if closed else line)]
    assert len(pts) == len(set(pts)) == straddle
    # every point lies on a grid edge at the linearly interpolated level
    for x, y in pts:
        if float(x).is_integer():
            j0 = int(np.floor(y))
            t = y - j0
            val = E[j0, int(x)] * (1 - t) + E[j0 + 1, int(x)] * t if t > 0 else E[j0, int(x)]
        else:
            i0 = int(np.floor(x))
            t = x - i0
            val = E[int(y), i0] * (1 - t) + E[int(y), i0 + 1] * t
        assert val == pytest.approx(level, abs=1e-9)


def test_nice_levels():
    assert nice_levels([0.0, 1.0], 4).tolist() == [0.2, 0.4, 0.6, 0.8]
    lv = nice_levels([0.013, 7.9], 8)
    assert 5 <= len(lv) <= 12 and np.all(np.diff(lv) > 0) and lv[0] > 0.013 and lv[-1] < 7.9
    assert len(nice_levels([1.0, 1.0])) == 0


def test_png_has_the_map_and_coloured_lines(tmp_path):
    lamp = AreaLight(SQUARE)
    m = illuminance_map(LuxGrid.from_bounds(-2, -1.5, 2, 1.5, 0, 41, 31), lamp, [Box((0.3, 0, 1), (0.5, 0.5, 0.05))])
    p = save_luxmap_png(tmp_path / "lux.png", m, levels=5, pixels_per_node=3)
    with Image.open(p) as im:
        a = np.asarray(im.convert("RGB")).astype(int)
    assert a.shape == (31 * 3, 41 * 3, 3)
    red = (a[..., 0] > 150) & (a[..., 1] < 100)
    blue = (a[..., 2] > 150) & (a[..., 0] < 100)
    assert red.sum() > 20 and blue.sum() > 20
    grey = (a[..., 0] == a[..., 1]) & (a[..., 1] == a[..., 2])
    assert a[grey][:, 0].max() == 255  # the brightest node is white
    # the top row of the image is the grid's far edge (v up): the map's last row
    assert len(m.isolux(5)) >= 5


def test_errors_name_the_field():
    with pytest.raises(InvalidParameterError, match="grid.u .* must not be parallel"):
        LuxGrid((0, 0, 0), (1, 0, 0), (2, 0, 0))
    with pytest.raises(InvalidParameterError, match="grid.nx"):
        LuxGrid((0, 0, 0), (1, 0, 0), (0, 1, 0), 1, 4)
    with pytest.raises(InvalidParameterError, match="grid must be a LuxGrid"):
        illuminance_map("floor", AreaLight(SQUARE))
    with pytest.raises(InvalidParameterError, match="E must be a 2-D array"):
        isolux_lines([1.0, 2.0], [1.5])
