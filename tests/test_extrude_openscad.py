"""Twisted and scaled ``linear_extrude`` from OpenSCAD (``tests/data/openscad/extrude22``).

Each ``.scad`` model was written for these tests and sets ``$fn = 96``; its ``openscad``
``.csg`` export and the volume of its STL export (``stl_volumes.json``, with the ``.scad``
text's sha256) are committed beside it (``regenerate.py`` rebuilds both). Polygon outlines are
OpenSCAD's own stack of slices, so their volumes agree to the STL's 6-digit rounding; models with
circles (exact discs, not OpenSCAD's 96-gons) within 0.5 %.
"""

from __future__ import annotations

import hashlib
import json
import shutil
import subprocess
import warnings
from pathlib import Path

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from isocsg import volume
from isocsg.openscad import load_openscad
from isocsg.openscad.flat import _disc_hull
from isocsg.shapes2d import area
from isocsg.shapes2d.boundary import contains_points

DIR = Path(__file__).resolve().parent / "data" / "openscad" / "extrude22"
MODELS = sorted(p.stem for p in DIR.glob("*.scad"))
VOLUMES = json.loads((DIR / "stl_volumes.json").read_text())["models"]
ROUND = {
    "scale_circle_off_axis", "twist_circle_off_axis", "twist_scale_disc_minus_square", "hull2d_equal_circles",
    "hull2d_two_circles", "hull2d_circles_and_square", "hull2d_nested_circle",
}


def _load(name: str):  # type: ignore[no-untyped-def]
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # nothing left out
        return load_openscad(DIR / f"{name}.csg")


def test_corpus_is_complete() -> None:
    assert len(MODELS) >= 15 and sorted(VOLUMES) == MODELS
    assert all((DIR / f"{m}.csg").is_file() for m in MODELS)


@pytest.mark.parametrize("name", MODELS)
def test_volume_matches_openscads_stl(name: str) -> None:
    got, want = volume(_load(name)), VOLUMES[name]["volume"]
    rtol = 5e-3 if name in ROUND else 2e-5  # per-axis-scaled circles are OpenSCAD's polygons: 2e-5 too
    assert abs(got - want) <= rtol * want, (name, got, want, got / want - 1)


@pytest.mark.skipif(shutil.which("openscad") is None, reason="the openscad program is not installed")
@pytest.mark.parametrize("name", MODELS[:3])
def test_committed_export_is_current(name: str, tmp_path: Path) -> None:
    scad = DIR / f"{name}.scad"
    assert VOLUMES[name]["sha256"] == hashlib.sha256(scad.read_bytes()).hexdigest(), "run regenerate.py"
    out = tmp_path / "m.csg"
    subprocess.run(["openscad", "-o", str(out), str(scad)], capture_output=True, check=True, timeout=120)
    assert out.read_text() == (DIR / f"{name}.csg").read_text()


@settings(max_examples=10, deadline=None)
@given(st.lists(st.tuples(st.floats(-5, 5), st.floats(-5, 5), st.one_of(st.just(0.0), st.floats(0.1, 3))),
                min_size=2, max_size=6))
def test_2d_hull_of_discs_and_points_is_exact(discs):
    """Against shapely's hull of the discs as fine polygons (8192 sides: area within 1e-7) and the
    distance of sample points to that hull."""
    c = np.array([d[:2] for d in discs])
    r = np.array([d[2] for d in discs])
    fine = shapely.convex_hull(shapely.union_all([shapely.Point(p).buffer(q, quad_segs=2048) if q > 0
                                                  else shapely.Point(p) for p, q in zip(c, r)]))
    if fine.area < 1e-6:
        return
    ours = _disc_hull(c, r)
    assert area(ours) == pytest.approx(fine.area, rel=1e-6)
    rng = np.random.default_rng(len(discs))
    pts = rng.uniform(-9, 9, (2000, 2))
    dist = shapely.distance(shapely.points(pts), fine.boundary)
    far = dist > 1e-3
    assert np.array_equal(contains_points(ours, pts)[far], shapely.contains_xy(fine, pts[:, 0], pts[:, 1])[far])
