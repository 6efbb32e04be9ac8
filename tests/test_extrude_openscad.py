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

import pytest

from isocsg import volume
from isocsg.openscad import load_openscad

DIR = Path(__file__).resolve().parent / "data" / "openscad" / "extrude22"
MODELS = sorted(p.stem for p in DIR.glob("*.scad"))
VOLUMES = json.loads((DIR / "stl_volumes.json").read_text())["models"]
ROUND = {"scale_circle_off_axis", "twist_circle_off_axis", "twist_scale_disc_minus_square"}


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
    rtol = 5e-3 if name in ROUND else 2e-5
    assert abs(got - want) <= rtol * want, (name, got, want, got / want - 1)


@pytest.mark.skipif(shutil.which("openscad") is None, reason="the openscad program is not installed")
@pytest.mark.parametrize("name", MODELS[:3])
def test_committed_export_is_current(name: str, tmp_path: Path) -> None:
    scad = DIR / f"{name}.scad"
    assert VOLUMES[name]["sha256"] == hashlib.sha256(scad.read_bytes()).hexdigest(), "run regenerate.py"
    out = tmp_path / "m.csg"
    subprocess.run(["openscad", "-o", str(out), str(scad)], capture_output=True, check=True, timeout=120)
    assert out.read_text() == (DIR / f"{name}.csg").read_text()
