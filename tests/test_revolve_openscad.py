"""``rotate_extrude`` read from OpenSCAD, judged by OpenSCAD's own exports.

``tests/data/openscad/revolve`` holds small ``.scad`` models written for these tests (a vase,
an O-ring, partial and negative turns, a profile on the side x < 0, a 2D difference, an
offset, a hemisphere, a pulley in an assembly, a profile with a hole, profiles touching the
axis, explicit small ``$fn``, also on a round circle), committed with ``openscad``'s ``.csg`` export and the volume
and centre of mass of its STL export at ``$fn = 96`` (``stl_volumes.json``, with each
``.scad``'s sha256):

- the ``.csg`` loads; its exact volume is within 0.5 % of the STL's (OpenSCAD's 96-gons hold
  0.07 % less per curve), and within 2e-5 where every curve has an explicit small ``$fn``
  (OpenSCAD's faceted solid, to the STL's 6 printed digits);
- its centre of mass is the STL's (to 0.5 % of the model's size): the start and the sign of
  the angle, and a profile on the side x < 0, land where OpenSCAD puts them;
- the solid goes through ``save_openscad`` and back with its volume;
- where ``openscad`` is installed, the committed ``.csg`` is the program's export of the ``.scad``.
"""

from __future__ import annotations

import hashlib
import json
import re
import shutil
import subprocess
import warnings
from pathlib import Path

import numpy as np
import pytest

from isocsg import OpenSCADError, UnsupportedOpenSCADError, dumps_openscad, loads_openscad, to_trimesh, volume
from isocsg.openscad import load_openscad
from isocsg.openscad.lowering import lower
from isocsg.openscad.parser import parse_csg
from isocsg.openscad.revolve import ProfileAcrossAxisWarning

DIR = Path(__file__).resolve().parent / "data" / "openscad" / "revolve"
MODELS = sorted(p.stem for p in DIR.glob("*.scad"))
DATA = json.loads((DIR / "stl_volumes.json").read_text())["models"]
HAS_OPENSCAD = shutil.which("openscad") is not None
needs_openscad = pytest.mark.skipif(not HAS_OPENSCAD, reason="the openscad program is not installed")

VOLUME_RTOL = 0.005
POLYGONAL_RTOL = 2e-5
EXACTLY_POLYGONAL = {"faceted_hex", "faceted_partial", "faceted_ring"}
ROUND_TRIP = ["vase", "oring", "partial90", "left_side", "faceted_partial", "dome"]


def _load(name: str):  # type: ignore[no-untyped-def]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_openscad(DIR / f"{name}.csg")


def test_models_are_complete() -> None:
    assert len(MODELS) >= 12
    assert sorted(DATA) == MODELS
    assert all((DIR / f"{m}.csg").is_file() for m in MODELS)


@pytest.mark.parametrize("name", MODELS)
def test_volume_matches_openscad(name: str) -> None:
    got = volume(_load(name), tol=1e-6)
    want = DATA[name]["volume"]
    rtol = POLYGONAL_RTOL if name in EXACTLY_POLYGONAL else VOLUME_RTOL
    assert abs(got - want) <= rtol * want, (name, got, want, got / want - 1)


@pytest.mark.parametrize("name", ["left_side", "negative_angle", "partial270", "faceted_partial"])
def test_centre_of_mass_matches_openscad(name: str) -> None:
    mesh = to_trimesh(_load(name), 96)
    size = float(np.linalg.norm(np.ptp(mesh.vertices, axis=0)))
    assert np.linalg.norm(mesh.center_mass - np.array(DATA[name]["centroid"])) <= 5e-3 * size


@pytest.mark.parametrize("name", ROUND_TRIP)
def test_round_trip_through_save_openscad(name: str) -> None:
    solid = _load(name)
    again = loads_openscad(dumps_openscad(solid))
    assert volume(again, tol=1e-8) == pytest.approx(volume(solid, tol=1e-8), rel=1e-9)


@needs_openscad
@pytest.mark.parametrize("name", MODELS)
def test_committed_export_is_current(name: str, tmp_path: Path) -> None:
    scad = DIR / f"{name}.scad"
    assert DATA[name]["sha256"] == hashlib.sha256(scad.read_bytes()).hexdigest(), "regenerate stl_volumes.json"
    out = tmp_path / "m.csg"
    subprocess.run(["openscad", "-o", str(out), str(scad)], capture_output=True, check=True, timeout=120)
    assert out.read_text() == (DIR / f"{name}.csg").read_text()


# ----------------------------------------------------------------------------- arguments as OpenSCAD reads them

BOX = "translate([4, 0]) square(1);"


def _v(text: str) -> float:
    return volume(loads_openscad(text), tol=1e-9)


def test_angle_defaults_clamps_and_alias() -> None:
    full = _v(f"rotate_extrude() {BOX}")
    assert full == pytest.approx(np.pi * (25 - 16), rel=1e-12)
    for angle in ("400", "-360", "-1000"):  # outside (-360, 360]: a full turn
        assert _v(f"rotate_extrude(angle = {angle}) {BOX}") == pytest.approx(full, rel=1e-12)
    assert _v(f"rotate_extrude(a = 90) {BOX}") == pytest.approx(full / 4, rel=1e-9)
    assert _v(f"rotate_extrude(90) {BOX}") == pytest.approx(full / 4, rel=1e-9)
    assert volume(loads_openscad(f"cube(1); rotate_extrude(angle = 0) {BOX}")) == pytest.approx(1.0)


def test_faceted_sections_follow_the_version() -> None:
    # 2021.01 (no start argument): floor(fn * |angle| / 360) sections; newer: rounded up
    old = loads_openscad(f"rotate_extrude(angle = 100, $fn = 6) {BOX}")
    new = loads_openscad(f"rotate_extrude(angle = 100, start = 0, $fn = 6) {BOX}")
    area_x = 1 * 4.5  # integral of x dA over the unit square at x in [4, 5]
    for solid, n in ((old, 1), (new, 2)):
        want = n * np.sin(np.radians(100 / n)) * area_x
        assert volume(solid, tol=1e-9) == pytest.approx(want, rel=1e-9)


def test_a_profile_across_the_axis_is_left_out_as_openscad_does() -> None:
    text = "cube(1);\nrotate_extrude() translate([-1, 0]) square(2);"
    with pytest.warns(ProfileAcrossAxisWarning, match=re.escape("line 2: rotate_extrude(): rotate_extrude.shape must lie")):
        model = lower(parse_csg(text))
    assert volume(model.solid) == pytest.approx(1.0)
    assert "left out, as OpenSCAD draws nothing" in model.left_out[0]
    with pytest.raises(OpenSCADError), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        loads_openscad("rotate_extrude() translate([-1, 0]) square(2);")  # nothing left


def test_a_circle_meeting_the_axis_is_unsupported_or_skipped() -> None:
    text = "cube(1);\nrotate_extrude() intersection() { translate([1, 0]) circle(2); square(5); }"
    with pytest.raises(UnsupportedOpenSCADError, match=re.escape("rotate_extrude() is not supported")):
        loads_openscad(text)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        model = lower(parse_csg(text), skip_unsupported=True)
    assert model.skipped == {"rotate_extrude": 1}
    assert "meets the axis" in model.left_out[0]


def test_a_torus_written_by_save_openscad_reads_back_as_a_torus() -> None:
    from isocsg import Torus

    t = Torus((1.0, -2.0, 0.5), (0.0, 0.6, 0.8), 3.0, 0.7)
    again = loads_openscad(dumps_openscad(t))
    assert isinstance(again, Torus)
    assert again.major == pytest.approx(3.0, rel=1e-12) and again.minor == pytest.approx(0.7, rel=1e-12)
    assert np.allclose(again.center, t.center, atol=1e-12) and np.allclose(again.axis, t.axis, atol=1e-12)
