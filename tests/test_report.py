"""Lighting studies from scene files and their HTML / PDF reports."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from isocsg.cli import main
from isocsg.errors import SceneFileError
from isocsg.interop.report import figures_rows, write_report
from isocsg.interop.study import load_study, run_study, study_from_table

pytest.importorskip("matplotlib")
pytest.importorskip("photompy")

ISO_IES = "\r\n".join([
    "IES:LM-63-2002", "[TEST] t", "[LUMINAIRE] isotropic 500 cd", "TILT=NONE",
    "1 6283.185307179586 1 3 1 1 2 0 0 0", "1 1 10", "0 90 180", "0", "500 500 500",
]) + "\r\n"

SCENE = """
[camera]
eye = [5.0, -5.0, 4.0]
target = [1.5, 1.0, 0.0]

[[objects]]
shape = { box = { center = [1.5, 1.0, -0.05], size = [3.0, 2.0, 0.1] } }

[study]
title = "Test room"
room = [0.0, 0.0, 3.0, 2.0]
height = 0.75
maintenance_factor = 0.8
wall_band = 0.5
cylindrical_height = 1.2
vertical = { height = 1.5, azimuths = [0, 90] }

[[study.tasks]]
name = "desk"
rect = [0.6, 0.6, 1.8, 1.4]
em = 500
u0 = 0.6

[[study.luminaires]]
name = "L1"
file = "iso.ies"
position = [1.2, 1.0, 2.75]
"""


@pytest.fixture
def scene_file(tmp_path: Path) -> Path:
    (tmp_path / "iso.ies").write_text(ISO_IES)
    p = tmp_path / "room.toml"
    p.write_text(SCENE)
    return p


def centres(x0, y0, x1, y1):
    d = max(x1 - x0, y1 - y0)
    p = min(10.0, 0.2 * 5 ** math.log10(d))
    nx, ny = math.ceil((x1 - x0) / p - 1e-9), math.ceil((y1 - y0) / p - 1e-9)
    x = x0 + (np.arange(nx) + 0.5) * (x1 - x0) / nx
    y = y0 + (np.arange(ny) + 0.5) * (y1 - y0) / ny
    return np.meshgrid(x, y)


def test_study_figures_against_the_inverse_square_law(scene_file):
    scene, spec = load_study(scene_file)
    r = run_study(spec, scene, map_nodes=30)
    by_name = {f.name: f for f in r.figures}
    h = 2.75 - 0.75
    for name, rect in (("room", (0.5, 0.5, 2.5, 1.5)), ("desk", (0.6, 0.6, 1.8, 1.4))):
        X, Y = centres(*rect)
        ref = 0.8 * 500 * h / ((X - 1.2) ** 2 + (Y - 1.0) ** 2 + h * h) ** 1.5
        f = by_name[name]
        assert f.points == X.size
        assert f.e_mean == pytest.approx(ref.mean(), rel=1e-12)
        assert f.u0 == pytest.approx(ref.min() / ref.mean(), rel=1e-12)
    assert by_name["desk"].required.em == 500 and by_name["desk surrounding"].required.em == 300
    # cylindrical: I sin(alpha) / (pi r^2) at 1.2 m over the room's grid
    X, Y = centres(0.5, 0.5, 2.5, 1.5)
    d, hz = np.hypot(X - 1.2, Y - 1.0), 2.75 - 1.2
    ez = 0.8 * 500 * d / (math.pi * (d * d + hz * hz) ** 1.5)
    assert r.cylindrical.e_mean == pytest.approx(ez.mean(), rel=1e-12)
    # vertical: I max(0, n . l) / r^2 with n horizontal, at 1.5 m
    hv = 2.75 - 1.5
    for az, f in zip((0, 90), r.vertical):
        n = (math.cos(math.radians(az)), math.sin(math.radians(az)))
        dx, dy = 1.2 - X, 1.0 - Y
        rr = np.sqrt(dx * dx + dy * dy + hv * hv)
        ev = 0.8 * 500 * np.maximum(0, n[0] * dx + n[1] * dy) / rr**3
        assert f.e_mean == pytest.approx(ev.mean(), rel=1e-12, abs=1e-12)
        assert f.e_max == pytest.approx(ev.max(), rel=1e-12)
    # the plan map: maintained values at its nodes
    node = r.plan.grid.points()[5, 7]
    e = 0.8 * 500 * h / np.sum((node - [1.2, 1.0, 2.75]) ** 2) ** 1.5
    assert r.plan.E[5, 7] == pytest.approx(e, rel=1e-12)


def test_html_and_pdf_reports(scene_file, tmp_path):
    scene, spec = load_study(scene_file)
    r = run_study(spec, scene, map_nodes=30)
    html = write_report(tmp_path / "r.html", r, plan_png=tmp_path / "plan.png").read_text()
    for row in figures_rows(r):
        assert all(cell.replace("&", "&amp;") in html for cell in row)
    assert "data:image/png;base64," in html and "L1" in html and "iso.ies" in html
    pdf = write_report(tmp_path / "r.pdf", r).read_bytes()
    assert pdf.startswith(b"%PDF") and len(re.findall(rb"/Type\s*/Page[^s]", pdf)) == 2
    assert (tmp_path / "plan.png").read_bytes().startswith(b"\x89PNG")


def test_report_command(scene_file, tmp_path, capsys):
    out = tmp_path / "cli.html"
    assert main(["report", str(scene_file), "-o", str(out)]) == 0
    assert out.exists() and "desk: Ebar" in capsys.readouterr().out
    assert main(["report", str(scene_file), "-o", str(tmp_path / "x.docx")]) == 2
    assert "must end in .html or .pdf" in capsys.readouterr().err


@pytest.mark.parametrize(
    ("table", "match"),
    [
        ({}, r"study\.room: missing required field"),
        ({"room": [0, 0, 3, 2], "colour": 1}, r"study\.colour: unknown field"),
        ({"room": [0, 0, 3, 2], "maintenance_factor": 1.5}, r"study\.maintenance_factor: must be in \(0, 1\]"),
        ({"room": [3, 0, 0, 2]}, r"study\.room: must have x1 > x0"),
        ({"room": [0, 0, 3, 2], "luminaires": [{"file": "nope.ldt", "position": [1, 1, 2]}]},
         r"study\.luminaires\[0\]\.file: nope\.ldt: cannot read"),
        ({"room": [0, 0, 3, 2], "luminaires": [{"file": "iso.ies", "position": [1, 1]}]},
         r"study\.luminaires\[0\]\.position: must be an array of 3 numbers"),
        ({"room": [0, 0, 3, 2], "luminaires": [{"file": "iso.ies", "position": [1, 1, 2], "model": "opening"}]},
         r"study\.luminaires\[0\]: .*no luminous area"),
        ({"room": [0, 0, 3, 2], "luminaires": [{"file": "iso.ies", "position": [1, 1, 2], "tilt": 270}]},
         r"study\.luminaires\[0\]\.tilt: PhotometricLight\.tilt must be"),
        ({"room": [0, 0, 3, 2], "tasks": [{"name": "a", "rect": [0, 0, 1, 1], "requirement": "reading"}]},
         r"study\.tasks\[0\]\.requirement: unknown row 'reading'"),
    ],
)
def test_study_table_errors_name_the_field(scene_file, table, match):
    with pytest.raises(SceneFileError, match=match):
        study_from_table(table, base=scene_file.parent, source="room.toml")
