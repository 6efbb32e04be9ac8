"""The live preview (``isocsg view``): views, loading, reloading on save, the server and the page.

The page is checked in a real headless Chromium (skipped without one): the pixels it shows
must be the server's render of the view named in the page's address, and after the model file
changes a freshly opened page shows the new model.
"""

from __future__ import annotations

import io
import json
import re
import shutil
import subprocess
import urllib.error
import urllib.request
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from isocsg import Box, Camera, InvalidParameterError, render
from isocsg.cli import main
from isocsg.preview import (
    OrbitView,
    PreviewServer,
    PreviewSession,
    initial_view,
    load_model,
    orbit_scene,
    watched_files,
)
from isocsg.preview.session import BACKGROUND_RGB

PLATE = "difference() { cube([2, 2, 1], center = true); cylinder(h = 3, r = 0.5, center = true); }\n"
BALL = "sphere(r = 1);\n"


@pytest.fixture
def model(tmp_path: Path) -> Path:
    p = tmp_path / "model.csg"
    p.write_text(PLATE)
    return p


def _grey(png: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"))


# ------------------------------------------------------------------ views
@pytest.mark.parametrize("field, kwargs", [
    ("azimuth", {"azimuth": float("nan"), "elevation": 0.0}),
    ("elevation", {"azimuth": 0.0, "elevation": float("inf")}),
    ("zoom", {"azimuth": 0.0, "elevation": 0.0, "zoom": 0.0}),
    ("width", {"azimuth": 0.0, "elevation": 0.0, "width": 0}),
    ("height", {"azimuth": 0.0, "elevation": 0.0, "height": 100_000}),
])
def test_bad_views_are_refused_by_name(field: str, kwargs: dict[str, float]) -> None:
    with pytest.raises(InvalidParameterError, match=field):
        OrbitView(**kwargs)  # type: ignore[arg-type]


def test_views_are_clamped_and_wrapped() -> None:
    v = OrbitView(370.0, 95.0, 1e6)
    assert v.azimuth == pytest.approx(10.0) and v.elevation == 89.0 and v.zoom == 50.0


@pytest.mark.parametrize("eye", [(3.0, -4.0, 2.0), (-1.0, 0.5, -2.0), (0.2, 5.0, 0.0)])
def test_the_first_view_is_the_cameras_own(eye: tuple[float, float, float]) -> None:
    scene = load_model_scene()
    cam = Camera(eye, (0.5, 0.5, 0.5), width=40, height=30)
    scene = scene.__class__(cam, scene.lights, scene.objects, scene.render)
    moved = orbit_scene(scene, initial_view(cam), turn_lights=True)
    assert np.allclose(moved.camera.eye, eye, atol=1e-12)
    assert (moved.camera.width, moved.camera.height) == (40, 30)
    assert np.allclose(moved.lights[0].direction, scene.lights[0].direction, atol=1e-12)


def test_orbit_keeps_the_distance_and_zoom_divides_it() -> None:
    scene = load_model_scene()
    target = np.asarray(scene.camera.target)
    d0 = np.linalg.norm(np.asarray(scene.camera.eye) - target)
    for az, el, zoom in [(0, 0, 1), (123, -40, 2), (-170, 80, 0.5)]:
        cam = orbit_scene(scene, OrbitView(az, el, zoom), turn_lights=False).camera
        d = np.asarray(cam.eye) - target
        assert np.linalg.norm(d) == pytest.approx(d0 / zoom)
        assert np.degrees(np.arcsin(d[2] / np.linalg.norm(d))) == pytest.approx(el)
        assert np.degrees(np.arctan2(d[1], d[0])) == pytest.approx(az)


def load_model_scene():  # noqa: ANN201 - a scene, for the tests above
    from isocsg.scene.framing import framed_scene

    return framed_scene(Box((0, 0, 0), (1, 1, 1)), width=40, height=30)


# ---------------------------------------------------------------- loading
def test_scripts_bind_a_scene_a_model_or_solids(tmp_path: Path) -> None:
    p = tmp_path / "part.py"
    p.write_text("from isocsg import Box, Sphere\nmodel = [Box((0, 0, 0), (1, 1, 1)), Sphere((2, 0, 0), 0.5)]\n")
    assert len(load_model(p).scene.objects) == 2
    p.write_text("x = 1\n")
    with pytest.raises(InvalidParameterError, match="scene, model, solid"):
        load_model(p)
    p.write_text("model = 3\n")
    with pytest.raises(InvalidParameterError, match="model must be"):
        load_model(p)
    with pytest.raises(InvalidParameterError, match="must end in"):
        load_model(tmp_path / "part.stl")


def test_openscad_notes_name_what_was_left_out(tmp_path: Path) -> None:
    p = tmp_path / "m.csg"
    p.write_text("union() { cube(1); projection() cube(1); }\n")
    loaded = load_model(p)
    assert loaded.notes and "projection" in loaded.notes[0]


def test_included_files_are_watched(tmp_path: Path) -> None:
    (tmp_path / "lib").mkdir()
    (tmp_path / "main.scad").write_text("include <lib/a.scad>\nuse <b.scad>\ncube(1);\n")
    (tmp_path / "lib" / "a.scad").write_text("include <c.scad>\n")
    names = sorted(p.name for p in watched_files(tmp_path / "main.scad"))
    assert names == ["a.scad", "b.scad", "c.scad", "main.scad"]


# ----------------------------------------------------------------- session
def test_a_view_is_the_render_of_the_orbited_scene(model: Path) -> None:
    session = PreviewSession(model, watch=False)
    view = OrbitView(-30.0, 25.0, 1.3, 48, 36)
    shown = _grey(session.render(view).png)
    expected = render(orbit_scene(session._model.scene, view, turn_lights=True)).image
    grey = np.rint(np.clip(np.nan_to_num(expected), 0, 1) * 255)
    inside = np.isfinite(expected)
    assert inside.sum() > 100
    assert np.array_equal(shown[..., 0][inside], grey[inside])
    assert (shown[~inside] == BACKGROUND_RGB).all()


def test_saving_the_file_reloads_and_errors_keep_the_last_model(model: Path) -> None:
    session = PreviewSession(model, watch=False)
    first = session.render(OrbitView(0.0, 30.0, 1.0, 32, 32))
    assert session.check() is False and session.version == 1
    model.write_text(BALL + "\n")
    assert session.check() is True and session.version == 2
    ball = session.render(OrbitView(0.0, 30.0, 1.0, 32, 32))
    assert ball.version == 2 and not np.array_equal(_grey(ball.png), _grey(first.png))
    model.write_text("sphere(r = 1;\n")
    assert session.check() is False
    state = session.state()
    assert state["version"] == 2 and "OpenSCADError" in state["error"] and "line" not in state["error"][:0]
    assert np.array_equal(_grey(session.render(OrbitView(0.0, 30.0, 1.0, 32, 32)).png), _grey(ball.png))
    model.write_text(PLATE)
    assert session.check() is True and session.state()["error"] is None and session.version == 3


# ------------------------------------------------------------------ server
def _get(url: str) -> tuple[int, bytes, dict[str, str]]:
    try:
        with urllib.request.urlopen(url, timeout=60) as r:
            return r.status, r.read(), dict(r.headers)
    except urllib.error.HTTPError as e:
        return e.code, e.read(), dict(e.headers)


def test_the_server_routes(model: Path) -> None:
    server = PreviewServer(PreviewSession(model, watch=False))
    url = server.start()
    try:
        status, body, _ = _get(url)
        assert status == 200 and b"<img id=\"image\"" in body
        status, body, _ = _get(url + "state")
        assert status == 200 and json.loads(body)["version"] == 1
        status, body, headers = _get(url + "view.png?az=10&el=20&zoom=1&w=40&h=30")
        assert status == 200 and _grey(body).shape == (30, 40, 3) and headers["X-Isocsg-Version"] == "1"
        status, body, _ = _get(url + "view.png?az=nan")
        assert status == 400 and b"azimuth" in body
        status, body, _ = _get(url + "view.png?w=0")
        assert status == 400 and b"width" in body
        assert _get(url + "nothing")[0] == 404
    finally:
        server.close()


def test_the_command_line_names_the_command_and_refuses_bad_files(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    main(["--help"])
    assert "live preview" in capsys.readouterr().out
    assert main(["view", str(tmp_path / "model.stl"), "--no-browser"]) == 2
    assert "must end in" in capsys.readouterr().err


# ----------------------------------------------------------------- browser
BROWSERS = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")


def _browser() -> str | None:
    return next((b for b in map(shutil.which, BROWSERS) if b), None)


def _chromium(browser: str, url: str, *args: str) -> str:
    # Headless Chromium windows are at least 500 pixels wide; the page's own size is read back.
    run = subprocess.run(
        [browser, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--force-device-scale-factor=1",
         "--window-size=560,420", "--virtual-time-budget=30000", *args, url],
        check=True, capture_output=True, text=True, timeout=120,
    )
    return run.stdout


def _page(browser: str, url: str, out: Path) -> tuple[np.ndarray, str]:
    """The page's pixels, and the image request the page made for ``url`` (whose address fixes
    the image size: drawn at the top left, one image pixel per screen pixel). A second run (the
    page's DOM) checks that the page did render, and which model version."""
    dom = _chromium(browser, url, "--dump-dom")
    version = re.search(r'data-rendered="([0-9]+)"', dom)
    assert version is not None, "the page rendered no image"
    _chromium(browser, url, f"--screenshot={out}")
    page = np.asarray(Image.open(out).convert("RGB"))
    return page, f"{url.split('#', 1)[1]}&v={version.group(1)}"


@pytest.mark.skipif(_browser() is None, reason="no Chromium on this machine")
def test_the_page_shows_the_view_in_its_address_and_the_saved_model(model: Path, tmp_path: Path) -> None:
    browser = _browser()
    assert browser is not None
    server = PreviewServer(PreviewSession(model, watch=False))
    url = server.start()
    try:
        shots = {}
        for az in (-30, 0):  # 90 degrees apart would show the same square plate
            page, query = _page(browser, f"{url}#az={az}&el=20&zoom=1&w=360&h=240", tmp_path / f"s{az}.png")
            _, png, _ = _get(f"{url}view.png?{query}")
            served = _grey(png)
            h, w, _ = served.shape
            assert (w, h) == (360, 240)
            assert np.abs(page[:h, :w].astype(int) - served.astype(int)).max() <= 2
            assert (served != BACKGROUND_RGB).any(axis=2).sum() > 500
            shots[az] = served
        assert not np.array_equal(shots[-30], shots[0])
        model.write_text(BALL)
        assert server.session.check()
        page, query = _page(browser, f"{url}#az=-30&el=20&zoom=1&w=360&h=240", tmp_path / "ball.png")
        assert query.endswith("&v=2")
        ball = _grey(_get(f"{url}view.png?{query}")[1])
        h, w, _ = ball.shape
        assert np.abs(page[:h, :w].astype(int) - ball.astype(int)).max() <= 2
        assert not np.array_equal(ball, shots[-30])
    finally:
        server.close()
