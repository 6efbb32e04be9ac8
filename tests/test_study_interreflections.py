"""Scene files read the same way by ``isocsg report`` and ``isocsg illuminance``.

Both take the ``[study]`` table's luminaires as lights and the
``[interreflections]`` table's reflected light; the radiosity solve takes point
luminaires. References: the inverse-square law, and Sumpner's flux relation
for a closed room of uniform reflectance (every lumen absorbed eventually).
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from isocsg.cli import main
from isocsg.errors import SceneFileError
from isocsg.interop.study import load_study, run_study
from isocsg.lighting.luminaire import PhotometricLight
from isocsg.lighting.photometry import Photometry
from isocsg.shadows.patches import Room
from isocsg.shadows.radiosity import Interreflections, solve_radiosity

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
shape = { box = { center = [2.2, 1.5, 0.3], size = [0.6, 0.4, 0.6] } }

[study]
room = [0.0, 0.0, 3.0, 2.0]
height = 0.75
maintenance_factor = 0.8
wall_band = 0.5
cylindrical_height = 1.2
vertical = { height = 1.5, azimuths = [0] }

[[study.luminaires]]
name = "L1"
file = "iso.ies"
position = [1.2, 1.0, 2.4]
"""

INTER = """
[interreflections]
room_center = [1.5, 1.0, 1.25]
room_size = [3.0, 2.0, 2.5]
floor = 0.3
walls = 0.5
ceiling = 0.7
reflectances = 0.4
patch_size = 1.0
refine = 0
"""


def _write(tmp_path: Path, text: str) -> Path:
    (tmp_path / "iso.ies").write_text(ISO_IES)
    p = tmp_path / "room.toml"
    p.write_text(text)
    return p


def test_study_reads_interreflections_and_adds_them_everywhere(tmp_path):
    scene, spec = load_study(_write(tmp_path, SCENE + INTER))
    assert spec.interreflections is not None and spec.interreflections.room.walls == 0.5
    r = run_study(spec, scene, map_nodes=12)
    sol = r.radiosity
    assert sol is not None and sol.residuals[-1] <= 1e-6
    direct = run_study(spec.__class__(**{**{f: getattr(spec, f) for f in spec.__slots__}, "interreflections": None}),
                       scene, map_nodes=12)
    assert direct.radiosity is None
    # every figure gains the maintained indirect light of the same solve, point by point
    g = r.areas[0].grid
    keep = np.isfinite(direct.grids[0][g.keep])
    pts = g.kept_points()[keep]
    ind = sol.indirect_illuminance(pts, np.tile([0.0, 0.0, 1.0], (len(pts), 1)))
    assert np.all(ind > 0)
    assert r.grids[0][g.keep][keep] == pytest.approx(direct.grids[0][g.keep][keep] + 0.8 * ind, rel=1e-12)
    for with_, without in ((r.figures[0], direct.figures[0]), (r.cylindrical, direct.cylindrical),
                           (r.vertical[0], direct.vertical[0])):
        assert with_.e_mean > without.e_mean and with_.e_min > without.e_min
    assert np.nanmin(r.plan.E - direct.plan.E) >= 0 and np.nanmax(r.plan.E - direct.plan.E) > 0


def test_report_command_prints_the_solve(tmp_path, capsys):
    pytest.importorskip("matplotlib")
    assert main(["report", str(_write(tmp_path, SCENE + INTER)), "-o", str(tmp_path / "r.html")]) == 0
    assert re.search(r"interreflections: \d+ patches, \d+ shots, residual", capsys.readouterr().out)


def test_illuminance_command_lights_the_scene_with_the_study_luminaires(tmp_path):
    """The map without interreflections is the luminaire's inverse-square law, I cos / r^2, at every node."""
    scene = _write(tmp_path, SCENE + '\n[illuminance]\norigin = [0.1, 0.1, 0.0]\nu = [1.0, 0.0, 0.0]\n'
                   'v = [0.0, 0.7, 0.0]\nnx = 5\nny = 4\n')
    npy = tmp_path / "e.npy"
    assert main(["illuminance", str(scene), "-o", str(tmp_path / "m.png"), "--npy", str(npy), "--no-progress"]) == 0
    E = np.load(npy)
    x, y = np.meshgrid(0.1 + np.linspace(0, 1, 5), 0.1 + np.linspace(0, 0.7, 4))
    r2 = (x - 1.2) ** 2 + (y - 1.0) ** 2 + 2.4**2
    assert E == pytest.approx(500.0 * 2.4 / r2**1.5, rel=1e-9)
    # with the table the reflected light comes on top
    scene2 = _write(tmp_path, scene.read_text() + INTER)
    assert main(["illuminance", str(scene2), "-o", str(tmp_path / "m.png"), "--npy", str(npy), "--no-progress"]) == 0
    assert np.all(np.load(npy) > E)


@pytest.mark.parametrize("rho", [0.3, 0.8])
def test_point_luminaire_in_a_closed_room_keeps_sumpners_relation(rho):
    """Sumpner's relation with a point luminaire: the reflected flux is rho / (1 - rho) of the direct flux.

    The direct flux on the walls is the luminaire's flux 4 pi I: an isotropic
    luminaire's patch means are closed forms (the patches' solid angles; the
    Gauss points' mean, used before, was off by 1.3e-7 at 3 x 3 points).
    """
    room = Room((1.5, 1.0, 1.25), (3.0, 2.0, 2.5), floor=rho, walls=rho, ceiling=rho)
    lamp = PhotometricLight((1.2, 1.0, 1.6), Photometry.isotropic(100.0))
    sol = solve_radiosity([lamp], (), Interreflections(room=room, patch_size=0.5, refine=0, order=8,
                                                       tolerance=1e-12))
    a = sol.patches.area
    direct = float(a @ sol.direct)
    assert direct == pytest.approx(4 * math.pi * 100.0, rel=1e-9)
    assert float(a @ (sol.incident - sol.direct)) == pytest.approx(rho / (1 - rho) * direct, rel=1e-9)


def test_malformed_interreflections_in_a_study_name_file_and_field(tmp_path, capsys):
    bad = _write(tmp_path, SCENE + INTER.replace("walls = 0.5", "walls = 1.5"))
    with pytest.raises(SceneFileError, match=r"room\.toml: .*room\.walls"):
        load_study(bad)
    assert main(["report", str(bad), "-o", str(tmp_path / "r.html")]) != 0
    assert "room.walls" in capsys.readouterr().err
