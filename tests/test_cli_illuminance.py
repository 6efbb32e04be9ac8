"""``isocsg illuminance``: grids from the floor, the scene's table or the command line; errors.

Judge of the values: Lambert's formula written in the test at nodes outside
every shadow (and the library's own illuminance at every node: the command
is a thin wrapper and must write exactly what it computes).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from isocsg.cli import main
from isocsg.scene import builtin_scene_path, load_scene
from isocsg.shadows import illuminance

LAMP = [[-0.5, -0.5, 2.0], [-0.5, 0.5, 2.0], [0.5, 0.5, 2.0], [0.5, -0.5, 2.0]]
DOC = {
    "camera": {"eye": [3, -5, 3], "target": [0, 0, 0], "width": 32, "height": 24},
    "render": {"mode": "halftone"},
    "lights": [{"kind": "area", "vertices": LAMP, "radiance": 2.0}],
    "objects": [
        {"shape": {"box": {"center": [0, 0, -0.05], "size": [4, 3, 0.1]}}},
        {"shape": {"box": {"center": [0.8, 0.3, 0.5], "size": [0.4, 0.4, 1.0]}}},
    ],
}


def _lambert(p, n, poly, L):
    e = 0.0
    for a, b in zip(poly, np.roll(poly, -1, axis=0)):
        u, v = a - p, b - p
        g = np.cross(u, v)
        e += np.arctan2(np.linalg.norm(g), u @ v) * (n @ (g / np.linalg.norm(g)))
    return abs(L / 2 * e)


def _write(tmp_path: Path, doc=DOC, name="scene.json") -> Path:
    p = tmp_path / name
    p.write_text(json.dumps(doc))
    return p


def test_default_grid_is_the_floor_top(tmp_path, capsys):
    scene = _write(tmp_path)
    png, npy = tmp_path / "map.png", tmp_path / "e.npy"
    assert main(["illuminance", str(scene), "--grid", "21", "16", "-o", str(png), "--npy", str(npy), "--no-progress"]) == 0
    E = np.load(npy)
    assert E.shape == (16, 21)
    xs, ys = np.linspace(-2, 2, 21), np.linspace(-1.5, 1.5, 16)
    pts = np.array([[x, y, 0.0] for y in ys for x in xs])
    # far from the pillar's shadow (x < -0.6): the whole source is seen
    far = pts[:, 0] < -0.6
    ref = np.array([_lambert(p, np.array([0, 0, 1.0]), np.array(LAMP), 2.0) for p in pts[far]])
    np.testing.assert_allclose(E.ravel()[far], ref, rtol=1e-8)
    occ = [o.shape for o in load_scene(scene).objects]
    # the same as the library's illuminance; the visibility tolerances scale with each batch of points
    # (1e-9 of its size), so penumbra values may differ in the 8th digit between batchings
    np.testing.assert_allclose(E.ravel(), illuminance(pts, [0, 0, 1], load_scene(scene).lights, occ, resolution=32), rtol=1e-6)
    with Image.open(png) as im:
        assert im.size == (21 * 4, 16 * 4)
    out = capsys.readouterr().out
    assert f"wrote {png}" in out and f"wrote {npy}" in out and "Emin" in out and "U0" in out


def test_scene_table_and_command_line_plane(tmp_path):
    doc = dict(DOC, illuminance={"origin": [-1, -1, 0.5], "u": [2, 0, 0], "v": [0, 2, 0], "nx": 5, "ny": 4, "levels": [0.5, 1.0]})
    scene = _write(tmp_path, doc, "scene.toml.json")
    npy = tmp_path / "a.npy"
    assert main(["illuminance", str(scene), "-o", str(tmp_path / "a.png"), "--npy", str(npy), "--no-progress"]) == 0
    E = np.load(npy)
    assert E.shape == (4, 5)
    corner = _lambert(np.array([-1.0, -1.0, 0.5]), np.array([0, 0, 1.0]), np.array(LAMP), 2.0)
    assert E[0, 0] == pytest.approx(corner, rel=1e-8)
    # the command line wins over the table; a wall facing -y lit from above at a grazing angle
    npy2 = tmp_path / "b.npy"
    args = ["illuminance", str(scene), "-o", str(tmp_path / "b.png"), "--npy", str(npy2), "--no-progress",
            "--origin", "-1", "-1", "0", "--u", "0", "0", "1", "--v", "2", "0", "0", "--grid", "3", "3"]
    assert main(args) == 0
    E2 = np.load(npy2)
    node = np.array([-1.0, -1.0, 0.0])
    normal = np.cross([0, 0, 1.0], [2, 0, 0]) / 2
    assert E2[0, 0] == pytest.approx(_lambert(node, normal, np.array(LAMP), 2.0), rel=1e-8)


def test_builtin_halftone_scene(tmp_path):
    png = tmp_path / "m.png"
    assert main(["illuminance", str(builtin_scene_path("halftone")), "--grid", "12", "12", "-o", str(png), "--no-progress"]) == 0
    assert png.stat().st_size > 0


@pytest.mark.parametrize(
    "extra,doc_patch,message",
    [
        (["--origin", "0", "0", "0"], None, "--origin, --u and --v must be given together"),
        ([], {"illuminance": {"origin": [0, 0, 0], "u": [1, 0, 0]}}, "illuminance.v: missing"),
        ([], {"illuminance": {"origin": [0, 0, 0], "u": [1, 0, 0], "v": [0, 1, 0], "size": 3}}, "illuminance.size: unknown field"),
        ([], {"illuminance": {"origin": [0, 0, 0], "u": [1, 0, 0], "v": [2, 0, 0]}}, "illuminance: u (1.0, 0.0, 0.0) and v (2.0, 0.0, 0.0) must not be parallel"),
        ([], {"lights": [{"kind": "point", "position": [0, 0, 3]}]}, "has no area or polyhedron light"),
        (["--grid", "1", "5"], None, "grid.nx must be between 2 and 4096, got 1"),
    ],
    ids=["partial-plane", "table-missing", "table-unknown", "table-parallel", "no-area-light", "grid-too-small"],
)
def test_bad_input_exits_2_with_one_line(tmp_path, capsys, extra, doc_patch, message):
    doc = dict(DOC, **(doc_patch or {}))
    scene = _write(tmp_path, doc)
    code = main(["illuminance", str(scene), "-o", str(tmp_path / "x.png"), "--no-progress", *extra])
    err = capsys.readouterr().err
    assert code == 2
    assert message in err and err.count("\n") == 1, err


def test_bad_outputs_and_missing_file(tmp_path, capsys):
    scene = _write(tmp_path)
    assert main(["illuminance", str(scene), "-o", str(tmp_path / "x.jpg")]) == 2
    assert "must end in .png or .csv" in capsys.readouterr().err
    assert main(["illuminance", str(tmp_path / "nope.toml"), "-o", str(tmp_path / "x.png")]) == 2
    assert "cannot read the file" in capsys.readouterr().err


def test_scene_and_table_from_standard_input(tmp_path, monkeypatch):
    import io
    import sys

    doc = dict(DOC, illuminance={"origin": [-1, -1, 0.5], "u": [2, 0, 0], "v": [0, 2, 0], "nx": 5, "ny": 4})
    scene = _write(tmp_path, doc)
    from_file, from_stdin = tmp_path / "f.npy", tmp_path / "s.npy"
    assert main(["illuminance", str(scene), "-o", str(tmp_path / "f.png"), "--npy", str(from_file), "--no-progress"]) == 0
    monkeypatch.setattr(sys, "stdin", type("Stdin", (), {"buffer": io.BytesIO(json.dumps(doc).encode())})())
    assert main(["illuminance", "-", "-o", str(tmp_path / "s.png"), "--npy", str(from_stdin), "--no-progress"]) == 0
    np.testing.assert_array_equal(np.load(from_stdin), np.load(from_file))
    assert np.load(from_stdin).shape == (4, 5)  # the [illuminance] table was read from standard input
