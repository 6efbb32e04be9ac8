"""EN 12464-1 grids and figures, vertical and cylindrical illuminance, against closed forms."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from isocsg import Box
from isocsg.errors import InvalidParameterError
from isocsg.lighting.area import AreaLight
from isocsg.lighting.luminaire import PhotometricLight
from isocsg.lighting.photometry import Photometry
from isocsg.shadows.en12464 import (
    REQUIREMENTS,
    CellGrid,
    area_figures,
    cylindrical_illuminance,
    grid_spacing,
    room_area,
    task_areas,
    vertical_illuminance,
)


def test_spacing_rule_values():
    # p = 0.2 x 5^log10(d): 0.2 m at 1 m, 1 m at 10 m, 5 m at 100 m; capped at 10 m
    for d, p in ((1.0, 0.2), (10.0, 1.0), (100.0, 5.0), (1000.0, 10.0), (0.1, 0.04)):
        assert grid_spacing(d) == pytest.approx(p, rel=1e-12)
    d_cap = 10 ** (math.log(50) / math.log(5))  # 5^log10(d) = 50
    assert grid_spacing(d_cap * 0.999) < 10.0 and grid_spacing(d_cap * 1.001) == 10.0


@settings(max_examples=40, deadline=None)
@given(st.floats(0.05, 300), st.floats(0.05, 300), st.floats(-50, 50), st.floats(-50, 50))
def test_points_at_cell_centres(a, b, x0, y0):
    g = CellGrid.standard((x0, y0, x0 + a, y0 + b), 0.8)
    p = 0.2 * 5 ** math.log10(max(a, b))
    p = min(p, 10.0)
    assert (g.nx, g.ny) == (max(1, math.ceil(a / p - 1e-9)), max(1, math.ceil(b / p - 1e-9)))
    px, py = g.spacing
    assert px <= p * (1 + 1e-9) and py <= p * (1 + 1e-9)
    pts = g.points()
    # centres: half a cell from the edges, a cell apart, centred on the rectangle
    assert pts[0, 0, 0] - x0 == pytest.approx(px / 2) and pts[0, 0, 1] - y0 == pytest.approx(py / 2)
    assert pts[..., 0].mean() == pytest.approx(x0 + a / 2) and pts[..., 1].mean() == pytest.approx(y0 + b / 2)
    assert np.allclose(np.diff(pts[0, :, 0]), px)


def test_wall_band_and_bands_around_a_task():
    room = (0.0, 0.0, 8.0, 6.0)
    r = room_area(room, 0.8)
    assert r.grid.rect == (0.5, 0.5, 7.5, 5.5)
    areas = task_areas("desk", (1.0, 1.0, 2.6, 1.8), room, 0.8, REQUIREMENTS["filing_copying"])
    kinds = [a.kind for a in areas]
    assert kinds == ["task", "surrounding", "background"]
    sur, bg = areas[1], areas[2]
    assert sur.grid.rect == (0.5, 0.5, 3.1, 2.3)
    assert bg.grid.rect == (0.0, 0.0, 6.1, 5.3)
    for area, hole in ((sur, (1.0, 1.0, 2.6, 1.8)), (bg, sur.grid.rect)):
        q = area.grid.kept_points()
        inside = (q[:, 0] > hole[0]) & (q[:, 0] < hole[2]) & (q[:, 1] > hole[1]) & (q[:, 1] < hole[3])
        assert not inside.any() and len(q) > 0
    assert sur.required.em == 200.0 and sur.required.u0 == 0.40
    assert bg.required.em == pytest.approx(200.0 / 3) and bg.required.u0 == 0.10
    with pytest.raises(InvalidParameterError, match="must lie in the room"):
        task_areas("desk", (7.0, 1.0, 9.0, 2.0), room, 0.8)


def test_figures_against_the_inverse_square_law():
    lamp = PhotometricLight((2.0, 1.5, 3.0), Photometry.isotropic(800.0))
    area = room_area((0.0, 0.0, 4.0, 3.0), 0.8)
    figs, E = area_figures(area, [lamp], maintenance_factor=0.8)
    q = area.grid.points()
    h = 3.0 - 0.8
    r2 = (q[..., 0] - 2) ** 2 + (q[..., 1] - 1.5) ** 2 + h * h
    ref = 0.8 * 800.0 * h / r2**1.5
    np.testing.assert_allclose(E, ref, rtol=1e-12)
    assert figs.e_mean == pytest.approx(ref.mean(), rel=1e-12)
    assert figs.e_min == pytest.approx(ref.min(), rel=1e-12) and figs.e_max == pytest.approx(ref.max(), rel=1e-12)
    assert figs.u0 == pytest.approx(ref.min() / ref.mean(), rel=1e-12)
    assert figs.min_max == pytest.approx(ref.min() / ref.max(), rel=1e-12)
    assert figs.points == q.shape[0] * q.shape[1]
    with pytest.raises(InvalidParameterError, match="maintenance_factor"):
        area_figures(area, [lamp], maintenance_factor=1.5)


def test_points_inside_occluders_are_left_out():
    lamp = PhotometricLight((2.0, 1.5, 3.0), Photometry.isotropic(800.0))
    area = room_area((0.0, 0.0, 4.0, 3.0), 0.8, band=0.0)
    desk = Box((1.0, 1.0, 0.5), (1.0, 1.0, 1.0))  # 0 .. 1 m high under part of the grid
    figs, E = area_figures(area, [lamp], [desk])
    q = area.grid.points()
    under = (np.abs(q[..., 0] - 1.0) < 0.5) & (np.abs(q[..., 1] - 1.0) < 0.5)
    assert under.any() and np.isnan(E[under]).all() and np.isfinite(E[~under]).all()
    assert figs.points == int((~under).sum())


@settings(max_examples=15, deadline=None)
@given(st.floats(-5, 5), st.floats(-5, 5), st.floats(0.3, 4), st.floats(0, 360))
def test_cylindrical_point_source_is_the_mean_vertical_illuminance(x, y, h, rot):
    G = np.linspace(0, 180, 37)
    ph = Photometry([0, 90, 180, 270, 360], G,
                    np.outer([1.0, 1.5, 1.0, 0.5, 1.0], 300 + 200 * np.cos(np.radians(G))))
    lamp = PhotometricLight((0.0, 0.0, h), ph, rotation=rot)
    p = np.array([[x, y, 0.0]])
    ez = cylindrical_illuminance(p, [lamp])[0]
    # independent: the mean of the vertical illuminance over 2048 azimuths (cosine law per plane)
    n = 2048
    ev = [vertical_illuminance(p, 360 * (k + 0.5) / n, [lamp])[0] for k in range(0, n, 8)]
    # the sub-sampled mean (256 planes) converges as 1/N^2 at the one kink of max(0, cos)
    assert ez == pytest.approx(np.mean(ev), rel=1e-4, abs=1e-12)


def test_cylindrical_area_source_against_a_source_quadrature():
    L = 1000.0
    lamp = AreaLight([(1, -0.5, 3), (1, 0.5, 3), (2, 0.5, 3), (2, -0.5, 3)], L)  # facing down
    p = np.array([[0.0, 0.0, 0.0]])
    ez = cylindrical_illuminance(p, [lamp], directions=256)[0]
    # Ez = (1/pi) int_A L cos(theta_s) sin(alpha) / r^2 dA  (midpoint rule over the source)
    m = 800
    u = (np.arange(m) + 0.5) / m
    X, Y = np.meshgrid(1 + u, -0.5 + u)
    r2 = X**2 + Y**2 + 9
    ref = np.sum(L * (3 / np.sqrt(r2)) * (np.hypot(X, Y) / np.sqrt(r2)) / r2) / m**2 / math.pi
    assert ez == pytest.approx(ref, rel=1e-5)
