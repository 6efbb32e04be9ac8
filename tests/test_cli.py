"""The ``isocsg`` command line: help, exit codes, one-line errors, and end-to-end renders."""

from __future__ import annotations

import io
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from isocsg.cli import build_parser, main
from isocsg.cli._common import compile_notice, kernels_cached, parse_size, progress_bar
from isocsg.scene import builtin_scene_path, load_scene

SCRIPT = Path(sys.executable).with_name("isocsg")

SMALL_SCENE = {
    "camera": {"eye": [0, -6, 2], "target": [0, 0, 0], "width": 48, "height": 36, "fov": 30},
    "render": {"contours": 6},
    "lights": [{"kind": "point", "position": [3, -4, 5]}],
    "objects": [{"shape": {"difference": [
        {"box": {"center": [0, 0, 0], "size": [2, 2, 2]}},
        {"sphere": {"center": [0.6, -0.6, 0.6], "radius": 0.8}},
    ]}}],
}


def _write_scene(tmp_path: Path, doc: dict = SMALL_SCENE, name: str = "scene.json") -> Path:
    path = tmp_path / name
    path.write_text(json.dumps(doc))
    return path


def _renderer_available() -> bool:
    try:
        from isocsg.rendering import render  # noqa: F401
        from isocsg.rendering.image import save_npy, save_png  # noqa: F401
    except ImportError:
        return False
    return True


needs_renderer = pytest.mark.skipif(not _renderer_available(), reason="isocsg.rendering is not available")


# ----------------------------------------------------------------------------- help and usage


@pytest.mark.parametrize("argv", [["--help"], ["render", "--help"], ["demo", "--help"]], ids=["top", "render", "demo"])
def test_help_exits_zero(argv: list[str], capsys: pytest.CaptureFixture[str]) -> None:
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert out.startswith("usage: isocsg")


def test_every_registered_command_has_help(capsys: pytest.CaptureFixture[str]) -> None:
    parser = build_parser()
    sub = next(a for a in parser._actions if a.dest == "command")
    assert {"render", "demo"} <= set(sub.choices)
    for name in sub.choices:
        assert main([name, "--help"]) == 0
        assert capsys.readouterr().out.startswith(f"usage: isocsg {name}")


def test_version(capsys: pytest.CaptureFixture[str]) -> None:
    import isocsg

    assert main(["--version"]) == 0
    assert capsys.readouterr().out.strip() == f"isocsg {isocsg.__version__}"


@pytest.mark.parametrize("how", ["python -m isocsg", "console script"])
def test_version_from_a_shell(how: str) -> None:
    import isocsg

    if how == "console script" and not SCRIPT.exists():
        pytest.skip("the isocsg console script is not installed next to this interpreter")
    cmd = [sys.executable, "-m", "isocsg"] if how == "python -m isocsg" else [str(SCRIPT)]
    env = dict(os.environ, PYTHONPATH=str(Path(isocsg.__file__).resolve().parents[1]))
    proc = subprocess.run(cmd + ["--version"], capture_output=True, text=True, timeout=120, env=env)
    assert (proc.returncode, proc.stdout, proc.stderr) == (0, f"isocsg {isocsg.__version__}\n", "")


def test_no_command_prints_help_and_fails(capsys: pytest.CaptureFixture[str]) -> None:
    assert main([]) == 2
    assert "usage: isocsg" in capsys.readouterr().err


@pytest.mark.parametrize(
    "argv, message",
    [
        (["render"], "isocsg render: error: the following arguments are required: SCENE, -o/--output (see isocsg render --help)"),
        (["render", "s.toml", "-o", "x.png", "--size", "12"],
         "isocsg render: error: argument --size: expected WIDTHxHEIGHT such as 640x480, got '12' (see isocsg render --help)"),
        (["render", "s.toml", "-o", "x.png", "--contours", "many"],
         "isocsg render: error: argument --contours: invalid int value: 'many' (see isocsg render --help)"),
        (["frobnicate"], "isocsg: error: argument COMMAND: invalid choice: 'frobnicate'"),
        (["render", "missing.toml", "-o", "x.png"],
         "isocsg render: error: missing.toml: cannot read the file: No such file or directory"),
        (["render", "s.toml", "-o", "x.jpg"], "isocsg render: error: output file 'x.jpg' must end in .png, .glb or .gltf"),
        (["render", "s.toml", "-o", "x.png", "--npy", "x.bin"], "isocsg render: error: output file 'x.bin' must end in .npy"),
        (["demo", "-o", "demo.gif"], "isocsg demo: error: output file 'demo.gif' must end in .png"),
    ],
    ids=["missing-args", "bad-size", "bad-contours", "unknown-command", "missing-file", "png-suffix", "npy-suffix", "demo-suffix"],
)
def test_usage_errors_exit_2_with_one_line(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], argv: list[str], message: str
) -> None:
    monkeypatch.chdir(tmp_path)
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert err.startswith(message)
    assert not list(tmp_path.glob("x.*")), "nothing is written on errors"


@pytest.mark.parametrize(
    "edit, argv_extra, message",
    [
        ({"objects": [{"shape": {"sphere": {"center": [0, 0, 0], "radius": -1}}}]}, [],
         "isocsg render: error: scene.json: objects[0].shape.sphere.radius: must be > 0, got -1"),
        ({}, ["--contours", "0"], "isocsg render: error: render.contours must be between 1 and 4096, got 0"),
        ({}, ["--contours", "100000"], "isocsg render: error: render.contours must be between 1 and 4096, got 100000"),
        ({}, ["--size", "0x10"], "isocsg render: error: camera.width must be between 1 and 16384, got 0"),
        ({}, ["--size", "99999x10"], "isocsg render: error: camera.width must be between 1 and 16384, got 99999"),
    ],
    ids=["bad-scene", "contours-zero", "contours-absurd", "size-zero", "size-absurd"],
)
def test_isocsg_errors_exit_2_with_one_line(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], edit: dict, argv_extra: list[str], message: str
) -> None:
    monkeypatch.chdir(tmp_path)
    _write_scene(Path("."), {**SMALL_SCENE, **edit})
    assert main(["render", "scene.json", "-o", "out.png", *argv_extra]) == 2
    err = capsys.readouterr().err
    assert err == message + "\n"
    assert not Path("out.png").exists()


def test_console_script_reports_errors_without_traceback(tmp_path: Path) -> None:
    if not SCRIPT.exists():
        pytest.skip("the isocsg console script is not installed next to this interpreter")
    proc = subprocess.run(
        [str(SCRIPT), "render", "missing.toml", "-o", "x.png"], cwd=tmp_path, capture_output=True, text=True, timeout=120
    )
    assert proc.returncode == 2
    assert proc.stderr == "isocsg render: error: missing.toml: cannot read the file: No such file or directory\n"


def test_demo_print_scene(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["demo", "--print-scene"]) == 0
    assert Path(capsys.readouterr().out.strip()) == builtin_scene_path("demo")
    assert main(["demo", "--halftone", "--print-scene"]) == 0
    assert Path(capsys.readouterr().out.strip()) == builtin_scene_path("halftone")


# ----------------------------------------------------------------------------- helpers


@pytest.mark.parametrize("text, size", [("640x480", (640, 480)), ("12X7", (12, 7)), ("1x1", (1, 1))], ids=["vga", "upper-x", "one"])
def test_parse_size(text: str, size: tuple[int, int]) -> None:
    assert parse_size(text) == size


def test_progress_bar_follows_the_callback() -> None:
    buf = io.StringIO()
    with progress_bar("render", file=buf, delay=0) as progress:
        for done in range(0, 11):
            progress(done, 10)
    text = buf.getvalue()
    assert "render" in text and "10/10" in text


def test_progress_bar_can_be_silenced() -> None:
    buf = io.StringIO()
    with progress_bar("render", file=buf, delay=0, enabled=False) as progress:
        progress(5, 10)
    assert buf.getvalue() == ""


class _Stream(io.StringIO):
    def __init__(self, terminal: bool) -> None:
        super().__init__()
        self.terminal = terminal

    def isatty(self) -> bool:
        return self.terminal


@pytest.mark.parametrize("terminal", [True, False], ids=["terminal", "pipe"])
def test_progress_bar_is_drawn_on_a_terminal_only(monkeypatch: pytest.MonkeyPatch, terminal: bool) -> None:
    """A bar redrawn with carriage returns would litter a log: stderr that is no terminal gets none."""
    err = _Stream(terminal)
    monkeypatch.setattr(sys, "stderr", err)
    with progress_bar("render", delay=0) as progress:
        for done in range(0, 11):
            progress(done, 10)
    if terminal:
        assert "\r" in err.getvalue() and "10/10" in err.getvalue()
    else:
        assert err.getvalue() == ""


# ----------------------------------------------------------------------------- end to end


def _png_from_float(image: np.ndarray) -> np.ndarray:
    """The conventions' 8-bit mapping: [0, 1] -> [0, 255] clipped, background 0."""
    v = np.clip(np.nan_to_num(image, nan=0.0), 0.0, 1.0) * 255.0
    return v


@needs_renderer
def test_render_writes_png_and_npy(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    scene_path = _write_scene(tmp_path)
    png, npy = tmp_path / "sub" / "out.png", tmp_path / "out.npy"
    assert main(["render", str(scene_path), "-o", str(png), "--npy", str(npy), "--no-progress"]) == 0
    assert capsys.readouterr().out == f"wrote {png}\nwrote {npy}\n"
    image = np.load(npy)
    assert image.dtype == np.float32 and image.shape == (36, 48)
    hit = np.isfinite(image)
    assert 0 < hit.sum() < hit.size  # the object and the background are both in view
    with Image.open(png) as im:
        assert im.size == (48, 36)
        pixels = np.asarray(im.convert("L"), dtype=np.float64)
    assert np.abs(pixels - _png_from_float(image)).max() <= 1.0


@needs_renderer
def test_render_options_override_the_scene(tmp_path: Path) -> None:
    scene_path = _write_scene(tmp_path)
    npy = tmp_path / "o.npy"
    assert main(["render", str(scene_path), "-o", str(tmp_path / "o.png"), "--npy", str(npy), "--size", "30x20", "--contours", "2",
                 "--no-progress"]) == 0
    coarse = np.load(npy)
    assert coarse.shape == (20, 30)
    assert main(["render", str(scene_path), "-o", str(tmp_path / "o.png"), "--npy", str(npy), "--size", "30x20", "--contours", "40",
                 "--no-progress"]) == 0
    fine = np.load(npy)
    # More contours, more distinct intensity levels on the lit surfaces.
    levels = lambda im: len(np.unique(im[np.isfinite(im)]))  # noqa: E731
    assert levels(fine) > levels(coarse)


@needs_renderer
def test_demo_renders_and_prints_the_path(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.chdir(tmp_path)
    assert main(["demo", "--size", "64x48", "--no-progress"]) == 0
    out = capsys.readouterr().out
    target = tmp_path / "isocsg-demo.png"
    assert out.startswith(f"wrote {target.resolve()} (64x48 pixels")
    with Image.open(target) as im:
        assert im.size == (64, 48)
        assert np.ptp(np.asarray(im.convert("L"))) > 0


@needs_renderer
def test_halftone_scene_renders(tmp_path: Path) -> None:
    pytest.importorskip("isocsg.shadows.halftone")
    npy = tmp_path / "h.npy"
    assert main(["render", str(builtin_scene_path("halftone")), "-o", str(tmp_path / "h.png"), "--npy", str(npy),
                 "--size", "40x30", "--no-progress"]) == 0
    image = np.load(npy)
    assert image.shape == (30, 40) and np.isfinite(image).any()


@needs_renderer
def test_halftone_png_applies_the_scene_exposure(tmp_path: Path) -> None:
    # A room in real units: E of hundreds of lux, shown through render.exposure.
    pytest.importorskip("isocsg.shadows.halftone")
    from PIL import Image

    text = builtin_scene_path("halftone").read_text().replace("radiance = 5.0", "radiance = 500.0")
    text = text.replace("exposure = 1.0", "exposure = 0.002")
    scene = tmp_path / "room.toml"
    scene.write_text(text)
    png, npy = tmp_path / "room.png", tmp_path / "room.npy"
    assert main(["render", str(scene), "-o", str(png), "--npy", str(npy), "--size", "40x30", "--no-progress"]) == 0
    E = np.load(npy)
    shown = np.asarray(Image.open(png).convert("L"), dtype=float)
    lit = np.isfinite(E)
    assert np.nanmax(E) > 100  # the raw illuminance, unscaled, in the NPY file
    expected = np.clip(E[lit] * 0.002, 0, 1) * 255
    assert np.abs(shown[lit] - expected).max() <= 1.0
    assert (shown[lit] < 255).mean() > 0.9  # not washed out


class _Stdin:
    """Standard input holding bytes (``sys.stdin.buffer`` is what the command line reads)."""

    def __init__(self, data: bytes) -> None:
        self.buffer = io.BytesIO(data)


@needs_renderer
@pytest.mark.parametrize("fmt", ["json", "toml"])
def test_render_reads_the_scene_from_standard_input(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, fmt: str) -> None:
    from isocsg.scene import dumps_scene

    scene_path = _write_scene(tmp_path)
    text = json.dumps(SMALL_SCENE) if fmt == "json" else dumps_scene(load_scene(scene_path))
    from_file, from_stdin = tmp_path / "file.npy", tmp_path / "stdin.npy"
    assert main(["render", str(scene_path), "-o", str(tmp_path / "f.png"), "--npy", str(from_file), "--no-progress"]) == 0
    monkeypatch.setattr(sys, "stdin", _Stdin(text.encode()))
    assert main(["render", "-", "-o", str(tmp_path / "s.png"), "--npy", str(from_stdin), "--no-progress"]) == 0
    np.testing.assert_array_equal(np.load(from_stdin), np.load(from_file))


@pytest.mark.parametrize(
    "data, message",
    [
        (b"[camera\n", "isocsg render: error: <stdin>: invalid TOML: "),
        (b"{\"camera\": 1", "isocsg render: error: <stdin>: invalid JSON: "),
        (b"\xff\xfe", "isocsg render: error: <stdin>: not a UTF-8 text file (byte 0xff at offset 0)"),
    ],
    ids=["toml", "json", "binary"],
)
def test_bad_standard_input_is_one_line_naming_stdin(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], data: bytes, message: str
) -> None:
    monkeypatch.setattr(sys, "stdin", _Stdin(data))
    assert main(["render", "-", "-o", str(tmp_path / "s.png"), "--no-progress"]) == 2
    err = capsys.readouterr().err
    assert err.startswith(message) and err.count("\n") == 1


def test_warmup_renders_the_built_in_scenes_and_says_so(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["warmup"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0].startswith("isocsg warmup: compiling kernels")
    assert out[-1].startswith("isocsg warmup: done in") and out[-1].endswith(" s")


def test_warm_cache_is_recognised_so_nothing_is_said(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["warmup"]) == 0
    capsys.readouterr()
    err = io.StringIO()
    assert kernels_cached("isoluminance") and kernels_cached("halftone")
    assert not compile_notice("isoluminance", file=err) and err.getvalue() == ""


def test_empty_cache_is_recognised(tmp_path: Path) -> None:
    """A new install (an empty numba cache) is recognised without compiling anything (tests/test_kernels.py
    checks what is then compiled and said)."""
    code = (
        "from isocsg.cli._common import kernels_cached; "
        "print(kernels_cached('isoluminance'), kernels_cached('halftone'))"
    )
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path)}
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines() == ["False False"]
    assert not list(tmp_path.rglob("*.nbc")), "the check compiles nothing"
