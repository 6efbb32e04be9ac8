"""Lux maps for reports: contourpy isolux lines, statistics over a task area, CSV, figures, flux.

Judges: the pure-Python marching-squares tracer kept in ``tests/reference``
(the lines), statistics recomputed in the test from node coordinates and a
footprint written here (the occluded nodes), the inverse-square law of a small
Lambertian source (the flux), and the CSV read back with the csv module.
"""

from __future__ import annotations

import csv
import io
import math
import re
import sys
from pathlib import Path

import numpy as np
import pytest

from isocsg import Box, InvalidLightError, InvalidParameterError, MissingDependencyError
from isocsg.cli import main
from isocsg.shadows import AreaLight, PolyhedronLight, illuminance
from isocsg.shadows.luxmap import LuxGrid, LuxMap, illuminance_map, isolux_lines
from isocsg.shadows.luxstats import CSV_COLUMNS, lux_statistics, save_luxmap_csv

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference.marching_squares import marching_squares  # noqa: E402

LAMP = [(-0.5, -0.5, 2.5), (-0.5, 0.5, 2.5), (0.5, 0.5, 2.5), (0.5, -0.5, 2.5)]
# A box standing on the floor z = 0 with its footprint between grid nodes (spacing 0.1).
PILLAR = Box((0.35, 0.25, 0.4), (0.6, 0.6, 0.8))
FOOTPRINT = ((0.05, 0.65), (-0.05, 0.55))
FLOOR = Box((0, 0, -0.05), (6, 6, 0.1))


@pytest.fixture(scope="module")
def luxmap() -> LuxMap:
    lamp = AreaLight(LAMP, radiance=1000.0)
    return illuminance_map(LuxGrid.from_bounds(-2, -2, 2, 2, 0, 41, 41), lamp, [PILLAR, FLOOR])


# ----------------------------------------------------------------------------- isolux lines


def _canonical(lines):
    """Polylines without zero-length steps, open ones from their smaller end, closed ones
    from their smallest point in their smaller direction; sorted (order decisions on
    coordinates rounded to 1e-9, comparisons on the exact ones)."""
    def key(p):
        return tuple(np.round(p, 9) + 0.0)

    out = []
    for pts, closed in lines:
        p = np.asarray(pts, dtype=np.float64)
        p = p[np.r_[True, np.abs(np.diff(p, axis=0)).max(axis=1) > 1e-12]]
        if closed and len(p) > 2:
            q = p[:-1] if np.abs(p[-1] - p[0]).max() <= 1e-12 else p
            q = np.roll(q, -min(range(len(q)), key=lambda k: key(q[k])), axis=0)
            r = np.roll(q[::-1], 1, axis=0)
            p = r if key(r[1]) < key(q[1]) else q
        elif key(p[-1]) < key(p[0]):
            p = p[::-1]
        out.append((bool(closed), p))
    return sorted(out, key=lambda t: (t[0], len(t[1]), key(t[1][0])))


def _segments(lines):
    out = set()
    for pts, _ in lines:
        p = np.round(np.asarray(pts), 9) + 0.0
        out |= {tuple(sorted((tuple(a), tuple(b)))) for a, b in zip(p[:-1], p[1:]) if (a != b).any()}
    return out


def _fields():
    rng = np.random.default_rng(7)
    y, x = np.mgrid[0:60, 0:70] / 60.0
    yield "waves", np.sin(7 * x) * np.cos(5 * y) + 0.3 * np.sin(23 * x * y), np.linspace(-0.9, 0.9, 7)
    yield "noise", rng.random((23, 31)), [0.2, 0.5, 0.77]
    holes = rng.random((30, 25))
    holes[rng.random(holes.shape) < 0.08] = np.nan
    yield "noise-with-nan", holes, [0.3, 0.6]
    # Levels that cross small parts of the grid (traced on their own rectangles of nodes):
    # a peak whose lines end on the grid's edges near a corner, and one with a hole of NaN.
    yield "corner-peak", np.exp(-20 * ((x - 0.1) ** 2 + (y - 0.9) ** 2)), [0.05, 0.3, 0.6, 0.9, 0.999]
    peak = np.exp(-30 * ((x - 0.6) ** 2 + (y - 0.5) ** 2))
    peak[28:33, 40:44] = np.nan
    yield "peak-with-nan", peak, [0.02, 0.2, 0.5, 0.8]


@pytest.mark.parametrize("name,E,levels", list(_fields()), ids=[f[0] for f in _fields()])
def test_isolux_lines_equal_the_marching_squares_reference(name, E, levels):
    for lv, ours, ref in zip(levels, isolux_lines(E, levels), marching_squares(E, levels)):
        a, b = _canonical(ours), _canonical(ref)
        assert len(a) == len(b), lv
        for (ca, pa), (cb, pb) in zip(a, b):
            assert ca == cb and pa.shape == pb.shape
            np.testing.assert_allclose(pa, pb, rtol=0, atol=1e-12)


def test_isolux_lines_equal_the_reference_on_a_lux_map(luxmap):
    levels = [20.0, 50.0, 100.0, 140.0]
    E = np.where(luxmap.occluded, np.nan, luxmap.E)
    for ours, ref in zip(isolux_lines(E, levels), marching_squares(E, levels)):
        a, b = _canonical(ours), _canonical(ref)
        assert [(c, len(p)) for c, p in a] == [(c, len(p)) for c, p in b]
        for (_, pa), (_, pb) in zip(a, b):
            np.testing.assert_allclose(pa, pb, rtol=0, atol=1e-12)


def test_nodes_exactly_on_a_level_give_the_same_segments():
    # Lines through nodes may be split differently at those nodes; their pieces are the same.
    E = np.round(np.random.default_rng(3).random((27, 33)) * 4) / 4
    for ours, ref in zip(isolux_lines(E, [0.25, 0.5]), marching_squares(E, [0.25, 0.5])):
        assert _segments(ours) == _segments(ref) and _segments(ours)


# ----------------------------------------------------------------------------- statistics and CSV


def test_occluded_nodes_are_the_footprint(luxmap):
    p = luxmap.grid.points()
    (x0, x1), (y0, y1) = FOOTPRINT
    expect = (p[..., 0] > x0) & (p[..., 0] < x1) & (p[..., 1] > y0) & (p[..., 1] < y1)
    np.testing.assert_array_equal(luxmap.occluded, expect)
    assert expect.sum() == 36


def test_statistics_leave_occluded_nodes_out(luxmap):
    s = lux_statistics(luxmap)
    lit = luxmap.E[~luxmap.occluded]
    assert (s.e_min, s.e_max) == (lit.min(), lit.max())
    assert s.e_avg == pytest.approx(lit.mean(), rel=1e-15)
    assert s.u0 == pytest.approx(lit.min() / lit.mean(), rel=1e-15)
    assert (s.nodes, s.occluded) == (41 * 41 - 36, 36)
    # a task area away from the pillar: its own nodes only
    area = [(-1.5, -1.5, 0), (-0.5, -1.5, 0), (-0.5, -0.5, 0), (-1.5, -0.5, 0)]
    p = luxmap.grid.points()
    inside = (p[..., 0] >= -1.5 - 1e-9) & (p[..., 0] <= -0.5 + 1e-9) & (p[..., 1] >= -1.5 - 1e-9) & (p[..., 1] <= -0.5 + 1e-9)
    t = lux_statistics(luxmap, area)
    assert (t.nodes, t.occluded) == (121, 0)
    assert (t.e_min, t.e_max) == (luxmap.E[inside].min(), luxmap.E[inside].max())
    assert 0 < t.u0 < 1 and "lx" in t.summary()


def test_csv_round_trip(tmp_path, luxmap):
    path = save_luxmap_csv(tmp_path / "grid.csv", luxmap)
    rows = list(csv.DictReader(io.StringIO(path.read_text())))
    assert tuple(rows[0]) == CSV_COLUMNS and len(rows) == 41 * 41
    p = luxmap.grid.points()
    for r in rows[:: 37]:
        i, j = int(r["i"]), int(r["j"])
        np.testing.assert_allclose([float(r["x_m"]), float(r["y_m"]), float(r["z_m"])], p[j, i], atol=1e-9)
        if r["occluded"] == "1":
            assert r["E_lx"] == "" and luxmap.occluded[j, i]
        else:
            assert float(r["E_lx"]) == pytest.approx(luxmap.E[j, i], abs=1e-9)
    assert sum(r["occluded"] == "1" for r in rows) == 36


# ----------------------------------------------------------------------------- flux and units


def test_from_flux_follows_the_inverse_square_law():
    # A 5 cm square source of flux F facing down at height d: intensity I = L A = F / pi
    # on its axis, E = I / d^2 below it (the small-source limit of Lambert's formula).
    F, d, a = 1000.0, 20.0, 0.05
    panel = AreaLight.from_flux([(0, 0, d), (0, a, d), (a, a, d), (a, 0, d)], F)
    assert panel.flux == pytest.approx(F, rel=1e-12)
    assert panel.radiance == pytest.approx(F / (math.pi * a * a), rel=1e-12)
    E = illuminance([(a / 2, a / 2, 0)], (0, 0, 1), [panel])[0]
    assert E == pytest.approx(F / math.pi / d**2, rel=1e-5)  # (a / d)^2 = 6e-6
    cube = PolyhedronLight.from_flux([(x, y, z) for x in (0, 2) for y in (0, 2) for z in (0, 2)], 2400.0)
    assert cube.area == pytest.approx(24.0) and cube.radiance * math.pi * 24.0 == pytest.approx(2400.0)
    with pytest.raises(InvalidLightError, match=re.escape("AreaLight.flux must be")):
        AreaLight.from_flux(LAMP, -1.0)


def test_scene_files_take_flux_or_radiance():
    from isocsg import SceneFileError
    from isocsg.scene.io import scene_from_dict

    doc = {
        "camera": {"eye": [0, -5, 2], "target": [0, 0, 0]},
        "objects": [{"shape": {"sphere": {"center": [0, 0, 0], "radius": 1}}}],
        "lights": [{"kind": "area", "vertices": [[0, 0, 3], [0, 2, 3], [2, 2, 3], [2, 0, 3]], "flux": 3000.0}],
    }
    assert scene_from_dict(doc).lights[0].radiance == pytest.approx(3000.0 / (math.pi * 4.0), rel=1e-12)
    doc["lights"][0]["flux"] = -1
    with pytest.raises(SceneFileError, match=re.escape("lights[0].flux: must be >= 0, got -1")):
        scene_from_dict(doc)
    doc["lights"][0].update(flux=10.0, radiance=2.0)
    with pytest.raises(SceneFileError, match=re.escape("lights[0]: give radiance (cd/m^2) or flux (lm), not both")):
        scene_from_dict(doc)


# ----------------------------------------------------------------------------- figures


def test_figure_has_a_lux_colour_bar_labelled_isolux_and_metres(tmp_path, luxmap):
    pytest.importorskip("matplotlib")
    from isocsg.shadows.luxplot import plot_luxmap, save_luxmap_figure

    area = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]
    fig = plot_luxmap(luxmap, levels=[25.0, 50.0, 100.0], area=area)
    ax, bar = fig.axes
    assert bar.get_ylabel() == "illuminance E (lx)"
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("x (m)", "y (m)")
    assert ax.get_xlim() == pytest.approx((-2.05, 2.05))
    labels = {t.get_text() for t in ax.texts}
    assert {"25", "50", "100"} <= labels
    s = lux_statistics(luxmap, area)
    assert f"Emin {s.e_min:.4g} lx" in ax.get_title() and f"U0 {s.u0:.2f}" in ax.get_title()
    out = save_luxmap_figure(tmp_path / "lux.png", luxmap, levels=4)
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    import matplotlib.pyplot as plt

    plt.close("all")


def test_missing_matplotlib_names_the_extra(monkeypatch, luxmap):
    from isocsg.shadows.luxplot import plot_luxmap

    monkeypatch.setitem(sys.modules, "matplotlib", None)
    with pytest.raises(MissingDependencyError, match=re.escape("pip install 'isocsg[plot]'")):
        plot_luxmap(luxmap)


def test_errors():
    g = LuxGrid.from_bounds(0, 0, 1, 1, 0, 3, 3)
    with pytest.raises(InvalidParameterError, match=re.escape("E must have shape (3, 3) (ny, nx), got (2, 3)")):
        LuxMap(g, np.zeros((2, 3)))
    with pytest.raises(InvalidParameterError, match="area must be a simple polygon"):
        lux_statistics(LuxMap(g, np.zeros((3, 3))), [(0, 0, 0), (1, 1, 0), (2, 2, 0)])


# ----------------------------------------------------------------------------- command line


def test_cli_prints_statistics_and_writes_csv(tmp_path, capsys):
    import json

    doc = {
        "camera": {"eye": [3, -5, 3], "target": [0, 0, 0], "width": 32, "height": 24},
        "render": {"mode": "halftone"},
        "lights": [{"kind": "area", "vertices": [list(v) for v in LAMP], "radiance": 1000.0}],
        "objects": [{"shape": {"box": {"center": [0, 0, -0.05], "size": [4, 4, 0.1]}}},
                    {"shape": {"box": {"center": list(PILLAR.center), "size": list(PILLAR.size)}}}],
    }
    scene = tmp_path / "s.json"
    scene.write_text(json.dumps(doc))
    out, npy = tmp_path / "grid.csv", tmp_path / "e.npy"
    argv = ["illuminance", str(scene), "--grid", "41", "41", "-o", str(out), "--npy", str(npy), "--no-progress",
            "--area", "-1", "-1", "1", "1"]
    assert main(argv) == 0
    text = capsys.readouterr().out
    rows = list(csv.DictReader(io.StringIO(out.read_text())))
    E = np.load(npy)
    lit = np.array([float(r["E_lx"]) for r in rows if r["E_lx"] and abs(float(r["x_m"])) <= 1 + 1e-9
                    and abs(float(r["y_m"])) <= 1 + 1e-9])
    m = re.search(r"Emin (\S+) lx  Eavg (\S+) lx  Emax (\S+) lx  U0 (\S+)", text)
    assert m is not None, text
    emin, eavg, emax, u0 = map(float, m.groups())
    assert emin == pytest.approx(lit.min(), rel=1e-5) and emax == pytest.approx(lit.max(), rel=1e-5)
    assert eavg == pytest.approx(lit.mean(), rel=1e-5) and u0 == pytest.approx(lit.min() / lit.mean(), abs=1e-3)
    assert len(rows) == E.size and f"wrote {out}" in text
