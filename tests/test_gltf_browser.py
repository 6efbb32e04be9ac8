"""glTF export seen in a real browser: headless Chromium draws the GLB with WebGL.

The page (``tests/data/gltf_viewer/viewer.html``) is a small glTF viewer in
plain WebGL, written from the glTF 2.0 specification and knowing nothing of
isocsg: node transforms, the file's camera, vertex colours, unlit materials,
back-face culling, sRGB output. Its pixels are compared with isocsg's own
render of the same scene: the silhouettes must agree (IoU), and each pixel
covered by both must show isocsg's grey (the 8-bit value of its PNG), except
where the two rasterisers split a pixel centre lying on a band edge
differently.

Chromium comes from the system (Debian: ``apt-get install chromium``;
``.ci/run`` installs it); without it the test is skipped.
"""

from __future__ import annotations

import base64
import html
import os
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from isocsg import Box, Camera, Cylinder, PointLight, Scene, Sphere
from isocsg.interop import export_glb
from isocsg.rendering import render

VIEWER = Path(__file__).parent / "data" / "gltf_viewer" / "viewer.html"
BROWSERS = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")

LIGHT = PointLight((2.0, -3.0, 4.0))
PLATE = Box((0, 0, 0), (2, 2, 0.4)) - Cylinder((0, 0, 0), (0, 0, 1), 0.5)
BALL = Sphere((1.9, 1.4, 0.2), 0.5)
CAMERA = Camera((3, -4, 3), (0.4, 0.3, 0), width=160, height=120)
CONTOURS = 8


def _browser() -> str | None:
    for name in BROWSERS:
        path = shutil.which(name)
        if path:
            return path
    return None


def _draw_in_browser(glb: bytes, width: int, height: int, tmp_path: Path) -> tuple[np.ndarray, str]:
    """RGBA pixels (height, width, 4) that Chromium's WebGL draws of the GLB, and the page's status line."""
    browser = _browser()
    if browser is None:
        pytest.skip("no Chromium on PATH (Debian: apt-get install chromium); .ci/run installs it")
    page = VIEWER.read_text(encoding="utf-8")
    page = page.replace("__GLB_BASE64__", base64.b64encode(glb).decode("ascii"))
    page = page.replace("__WIDTH__", str(width)).replace("__HEIGHT__", str(height))
    path = tmp_path / "viewer.html"
    path.write_text(page, encoding="utf-8")
    cmd = [
        browser, "--headless", "--no-sandbox", "--disable-gpu-sandbox",
        # WebGL without a GPU: SwiftShader, Chromium's software renderer.
        "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
        "--no-first-run", "--disable-extensions", "--user-data-dir=" + str(tmp_path / "profile"),
        "--dump-dom", path.as_uri(),
    ]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=120, env={**os.environ, "LANG": "C"})
    status = re.search(r'<pre id="status">(.*?)</pre>', proc.stdout, re.S)
    pixels = re.search(r'<pre id="pixels">(.*?)</pre>', proc.stdout, re.S)
    if proc.returncode != 0 or status is None or pixels is None:
        pytest.fail(f"Chromium failed (exit {proc.returncode}): {proc.stderr[-2000:]}")
    text = html.unescape(status.group(1))
    assert text.startswith("drawn "), f"the viewer says: {text}"
    rgba = np.frombuffer(base64.b64decode(pixels.group(1)), np.uint8)
    return rgba.reshape(height, width, 4), text


@pytest.fixture(scope="module")
def drawn(tmp_path_factory: pytest.TempPathFactory) -> tuple[np.ndarray, np.ndarray, str]:
    scene = Scene(CAMERA, [LIGHT], [PLATE, BALL])
    glb = export_glb(scene, contours=CONTOURS)
    rgba, status = _draw_in_browser(glb, CAMERA.width, CAMERA.height, tmp_path_factory.mktemp("browser"))
    image = render(scene, contours=CONTOURS).image
    return rgba, image, status


def test_browser_draws_the_silhouette_of_isocsgs_render(drawn: tuple[np.ndarray, np.ndarray, str]) -> None:
    rgba, image, status = drawn
    assert status == "drawn 2 primitives" or status.startswith("drawn 2 primitives with ")
    ours = np.isfinite(image)
    theirs = rgba[..., 3] > 0
    iou = (ours & theirs).sum() / (ours | theirs).sum()
    assert ours.sum() > 0.1 * ours.size, "the scene fills a good part of the view"
    assert iou >= 0.99, f"silhouette IoU {iou:.4f}"


def test_browser_shows_isocsgs_greys_unlit(drawn: tuple[np.ndarray, np.ndarray, str]) -> None:
    rgba, image, _ = drawn
    both = np.isfinite(image) & (rgba[..., 3] > 0)
    r, g, b = (rgba[..., k].astype(int) for k in range(3))
    assert np.array_equal(r, g) and np.array_equal(g, b), "unlit vertex colours are grey"
    # isocsg's PNG grey of each pixel; the viewer's sRGB encoding of the file's
    # linear colour (float32 in the shader) gives it back to within one step.
    grey = np.rint(np.clip(np.nan_to_num(image), 0, 1) * 255).astype(int)
    close = np.abs(r - grey) <= 1
    assert close[both].mean() >= 0.98, f"{close[both].mean():.4f} of the pixels show isocsg's grey"
    # The differing pixels lie on band edges: each has a neighbour (in isocsg's
    # image) with the grey the browser shows there.
    rows, cols = np.nonzero(both & ~close)
    h, w = image.shape
    for i, j in zip(rows, cols):
        window = grey[max(i - 1, 0) : min(i + 2, h), max(j - 1, 0) : min(j + 2, w)]
        assert (np.abs(window - r[i, j]) <= 1).any(), f"pixel {(i, j)}: browser {r[i, j]}, isocsg {grey[i, j]}"
    # As many greys as the render shows (one per band seen), and no other.
    seen = set(np.unique(grey[both]).tolist())
    shown = set(np.unique(r[both]).tolist())
    assert all(min(abs(s - t) for t in seen) <= 1 for s in shown)
    assert len(shown) >= len(seen) - 2, f"browser {len(shown)} greys, isocsg {len(seen)}"
