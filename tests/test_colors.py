"""Colours: OpenSCAD's ``color()`` and ``SceneObject.color`` carried to images, scene files and glTF.

Each band keeps one flat shade: a coloured pixel is the grey intensity of the same render times
its leaf's colour, so the checks compare against the grey render itself and against the colours
written in the test.
"""

from __future__ import annotations

import io
import json
import struct
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from isocsg import (
    Box,
    Camera,
    Cylinder,
    InvalidParameterError,
    PointLight,
    Scene,
    SceneFileError,
    SceneObject,
    Sphere,
    dumps_scene,
    load_openscad,
    loads_scene,
    render,
)
from isocsg._validation import parse_color
from isocsg.cli import main
from isocsg.openscad import read_openscad
from isocsg.rendering.colors import colored_image

CAMERA = Camera((3.0, -4.0, 3.0), (0.5, 0.5, 0.3), width=96, height=72)
LIGHT = PointLight((2.0, -3.0, 4.0))


@pytest.mark.parametrize("value, rgb", [
    ("red", (1.0, 0.0, 0.0)), ("SteelBlue", (70 / 255, 130 / 255, 180 / 255)), ("#ff8000", (1.0, 128 / 255, 0.0)),
    ([0.1, 0.2, 0.3], (0.1, 0.2, 0.3)), ((0.0, 1.0, 0.5, 0.25), (0.0, 1.0, 0.5)),
])
def test_colours_read_as_openscad_writes_them(value: object, rgb: tuple[float, float, float]) -> None:
    assert parse_color(value) == pytest.approx(rgb)


@pytest.mark.parametrize("value", ["notacolour", [1.5, 0, 0], [float("nan"), 0, 0], [1, 0], None, {"r": 1}])
def test_bad_colours_name_the_field(value: object) -> None:
    with pytest.raises(InvalidParameterError, match="SceneObject.color"):
        SceneObject(Sphere((0, 0, 0), 1), color=value if value is not None else [])  # type: ignore[arg-type]


def test_a_coloured_object_is_its_grey_render_times_its_colour() -> None:
    plate = Box((0.5, 0.5, 0.0), (1.6, 1.6, 0.4)) - Cylinder((0.5, 0.5, 0.0), (0.0, 0.0, 1.0), 0.35)
    ball = Sphere((1.6, 1.2, 0.5), 0.4)
    scene = Scene(CAMERA, [LIGHT], [SceneObject(plate, leaf_colors=[None, (0.0, 0.0, 1.0)], color="orange"),
                                   SceneObject(ball)])
    result = render(scene)
    rgb = colored_image(result, scene.objects)
    grey = result.image
    on_box = (result.object_index == 0) & (result.primitive_index == 0)
    on_hole = (result.object_index == 0) & (result.primitive_index == 1)
    on_ball = result.object_index == 1
    assert on_box.sum() > 200 and on_hole.sum() > 10 and on_ball.sum() > 100
    orange = np.array([1.0, 165 / 255, 0.0], dtype=np.float32)
    assert np.allclose(rgb[on_box], grey[on_box][:, None] * orange, atol=1e-6)
    assert np.allclose(rgb[on_hole], grey[on_hole][:, None] * np.array([0, 0, 1], np.float32), atol=1e-6)
    assert np.array_equal(rgb[on_ball], np.repeat(grey[on_ball][:, None], 3, axis=1))
    assert np.isnan(rgb[result.object_index < 0]).all()


def test_too_many_leaf_colours_are_refused_when_drawn() -> None:
    scene = Scene(CAMERA, [LIGHT], [SceneObject(Sphere((0, 0, 0), 1), leaf_colors=["red", "blue"])])
    with pytest.raises(InvalidParameterError, match="leaf_colors has 2 colours for 1 leaves"):
        colored_image(render(scene), scene.objects)


MODEL = """color([0.27, 0.51, 0.71, 1]) difference() {
  cube(size = [4, 4, 1], center = true);
  color("orange") cylinder(h = 3, r = 1, center = true);
}
color([0.2, 0.8, 0.2, 1]) multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 1.5], [0, 0, 0, 1]]) sphere(r = 1);
multmatrix([[1, 0, 0, 2.5], [0, 1, 0, 2.5], [0, 0, 1, 0], [0, 0, 0, 1]]) cube(size = 1);
"""


def test_openscad_colours_go_to_the_leaves_innermost_first(tmp_path: Path) -> None:
    p = tmp_path / "m.csg"
    p.write_text(MODEL)
    model = read_openscad(p)
    expected = [(0.27, 0.51, 0.71), (1.0, 165 / 255, 0.0), (0.2, 0.8, 0.2), None]
    assert len(model.leaf_colors) == 4 and model.leaf_colors[3] is None
    for got, want in zip(model.leaf_colors[:3], expected[:3], strict=True):
        assert got == pytest.approx(want)
    assert load_openscad(p) is not None  # colours do not change the solid


def test_the_command_line_writes_the_colours(tmp_path: Path) -> None:
    p = tmp_path / "m.csg"
    p.write_text(MODEL)
    out = tmp_path / "m.png"
    assert main(["render", str(p), "-o", str(out), "--size", "120x90", "--no-progress"]) == 0
    img = np.asarray(Image.open(out))
    assert img.shape == (90, 120, 3)
    green = (img[..., 1] > img[..., 0] + 40) & (img[..., 1] > img[..., 2] + 40)  # the sphere
    orange = (img[..., 0] > img[..., 2] + 60) & (img[..., 1] > img[..., 2] + 20)  # the hole's wall
    grey = (img[..., 0] == img[..., 1]) & (img[..., 1] == img[..., 2]) & (img[..., 0] > 0)  # the plain cube
    assert green.sum() > 100 and orange.sum() > 5 and grey.sum() > 20


def test_scene_files_keep_colours() -> None:
    tree = Box((0, 0, 0), (1, 1, 1)) - Sphere((0.5, 0.5, 0.5), 0.6)
    scene = Scene(CAMERA, [LIGHT], [SceneObject(tree, color="red", leaf_colors=[None, "blue"])])
    for fmt in ("toml", "json"):
        back = loads_scene(dumps_scene(scene, format=fmt), format=fmt)
        assert back.objects[0].color == (1.0, 0.0, 0.0)
        assert back.objects[0].leaf_colors == (None, (0.0, 0.0, 1.0))
    bad = dumps_scene(scene, format="json").replace('"leaf_colors": {\n        "1"', '"leaf_colors": {\n        "x"')
    assert '"x"' in bad
    with pytest.raises(SceneFileError, match="leaf_colors"):
        loads_scene(bad, format="json")


def _glb_colors(data: bytes) -> np.ndarray:
    """The first mesh's COLOR_0 accessor of a GLB, read from the glTF 2.0 layout."""
    length = struct.unpack_from("<I", data, 12)[0]
    doc = json.loads(data[20:20 + length])
    binary = data[20 + length + 8:]
    acc = doc["accessors"][doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"]]
    view = doc["bufferViews"][acc["bufferView"]]
    start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
    return np.frombuffer(binary[start:start + acc["count"] * 16], dtype=np.float32).reshape(-1, 4)


def test_gltf_triangles_take_their_leaf_colour() -> None:
    from isocsg.interop import export_glb
    from isocsg.interop.gltf import srgb_to_linear

    scene = Scene(CAMERA, [LIGHT], [SceneObject(Sphere((0, 0, 0), 1), color=(1.0, 0.5, 0.0))])
    grey_scene = Scene(CAMERA, [LIGHT], [SceneObject(Sphere((0, 0, 0), 1))])
    colors = _glb_colors(export_glb(scene, contours=8))
    grey = _glb_colors(export_glb(grey_scene, contours=8))
    assert colors.shape == grey.shape
    # Red is the grey's own channel (the intensity), green half of it in sRGB, blue none.
    from isocsg.interop.gltf import linear_to_srgb

    v = linear_to_srgb(grey[:, 0])
    assert np.allclose(colors[:, 0], grey[:, 0], atol=1e-6)
    assert np.allclose(colors[:, 1], srgb_to_linear(0.5 * v), atol=1e-6)
    assert np.allclose(colors[:, 2], 0.0)


def test_the_preview_shows_the_colours(tmp_path: Path) -> None:
    from isocsg.preview import OrbitView, PreviewSession

    p = tmp_path / "m.csg"
    p.write_text(MODEL)
    session = PreviewSession(p, watch=False)
    first = session.initial_view()
    png = session.render(OrbitView(first.azimuth, first.elevation, 1.0, 120, 90)).png
    img = np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(int)
    assert ((img[..., 1] > img[..., 0] + 40) & (img[..., 1] > img[..., 2] + 40)).sum() > 100
