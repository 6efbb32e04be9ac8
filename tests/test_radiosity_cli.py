"""``isocsg illuminance`` with interreflections: the --room flags and the [interreflections] table.

The command is a thin wrapper: it must write the direct illuminance plus the
solve's indirect illuminance at the grid nodes (both judged in
tests/test_radiosity.py and tests/test_illuminance.py).
"""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

from isocsg import AreaLight, Box, illuminance
from isocsg.cli import main
from isocsg.cli.illuminance import load_scene_grid_and_interreflections
from isocsg.errors import SceneFileError
from isocsg.shadows.patches import Room
from isocsg.shadows.radiosity import Interreflections, solve_radiosity

LAMP = [[-0.5, -0.5, 2.0], [-0.5, 0.5, 2.0], [0.5, 0.5, 2.0], [0.5, -0.5, 2.0]]
DOC = {
    "camera": {"eye": [3, -5, 3], "target": [0, 0, 0], "width": 32, "height": 24},
    "render": {"mode": "halftone"},
    "lights": [{"kind": "area", "vertices": LAMP, "radiance": 2.0}],
    "objects": [{"shape": {"box": {"center": [0.8, 0.3, 0.5], "size": [0.4, 0.4, 1.0]}}}],
    "illuminance": {"origin": [-1.9, -1.4, 0.0], "u": [3.8, 0, 0], "v": [0, 2.8, 0], "nx": 6, "ny": 5},
}


def _expected(inter):
    xs, ys = np.linspace(-1.9, 1.9, 6), np.linspace(-1.4, 1.4, 5)
    pts = np.array([[x, y, 0.0] for y in ys for x in xs])
    lamp = AreaLight(LAMP, radiance=2.0)
    occ = [Box((0.8, 0.3, 0.5), (0.4, 0.4, 1.0))]
    sol = solve_radiosity(lamp, occ, inter, resolution=32)
    return (illuminance(pts, [0, 0, 1], lamp, occ, resolution=32) + sol.indirect_illuminance(pts, [0, 0, 1])).reshape(5, 6)


def test_room_flags_add_the_indirect_light(tmp_path, capsys):
    scene = tmp_path / "s.json"
    scene.write_text(json.dumps(dict(DOC, interreflections={"refine": 0})))  # the room from the flags
    npy = tmp_path / "e.npy"
    args = ["illuminance", str(scene), "-o", str(tmp_path / "m.png"), "--npy", str(npy), "--no-progress",
            "--room", "0", "0", "1.25", "4", "3", "2.5", "--reflectances", "0.3", "0.6", "0.8",
            "--object-reflectance", "0.5", "--patch-size", "1.0"]
    assert main(args) == 0
    inter = Interreflections(room=Room((0, 0, 1.25), (4, 3, 2.5), floor=0.3, walls=0.6, ceiling=0.8),
                             reflectances=0.5, patch_size=1.0, refine=0)
    np.testing.assert_allclose(np.load(npy), _expected(inter), rtol=1e-12)
    assert "interreflections:" in capsys.readouterr().out


def test_scene_table_and_direct_only(tmp_path):
    doc = dict(DOC, interreflections={"room_center": [0, 0, 1.25], "room_size": [4, 3, 2.5], "walls": 0.6,
                                      "reflectances": [0.5], "patch_size": 1.0, "refine": 0})
    scene = tmp_path / "s.json"
    scene.write_text(json.dumps(doc))
    npy, npy2 = tmp_path / "e.npy", tmp_path / "d.npy"
    assert main(["illuminance", str(scene), "-o", str(tmp_path / "m.png"), "--npy", str(npy), "--no-progress"]) == 0
    inter = Interreflections(room=Room((0, 0, 1.25), (4, 3, 2.5), walls=0.6), reflectances=(0.5,), patch_size=1.0,
                             refine=0)
    np.testing.assert_allclose(np.load(npy), _expected(inter), rtol=1e-12)
    assert main(["illuminance", str(scene), "-o", str(tmp_path / "m.png"), "--npy", str(npy2), "--no-progress",
                 "--direct-only"]) == 0
    assert np.all(np.load(npy2) < np.load(npy))


@pytest.mark.parametrize("table,msg", [
    ({"room_center": [0, 0, 1]}, "interreflections.room_size: missing"),
    ({"walls": 0.5}, "interreflections.room_center: missing"),
    ({"room_center": [0, 0, 1], "room_size": [4, 3, -1]}, "room.size must be > 0"),
    ({"colour": 1}, "interreflections.colour: unknown field"),
])
def test_bad_tables_raise(tmp_path, capsys, table, msg):
    scene = tmp_path / "s.json"
    scene.write_text(json.dumps(dict(DOC, interreflections=table)))
    assert main(["illuminance", str(scene), "-o", str(tmp_path / "m.png"), "--no-progress"]) != 0
    assert msg in capsys.readouterr().err
    with pytest.raises(SceneFileError, match=re.escape(msg)):
        load_scene_grid_and_interreflections(scene)


def test_flags_without_a_room_raise(tmp_path, capsys):
    scene = tmp_path / "s.json"
    scene.write_text(json.dumps(DOC))
    assert main(["illuminance", str(scene), "-o", str(tmp_path / "m.png"), "--no-progress", "--patch-size", "1"]) != 0
    assert "--patch-size need --room" in capsys.readouterr().err
