"""glTF export: read back with trimesh and a plain GLB reader, against the band surfaces."""

from __future__ import annotations

import json
import re
import struct
from pathlib import Path

import numpy as np
import pytest

from isocsg import Box, Camera, Cylinder, InvalidLightError, InvalidParameterError, PointLight, Scene, Sphere
from isocsg.cli import main
from isocsg.csg.surface import csg_surface
from isocsg.interop import ShadedSurface, export_glb, save_gltf
from isocsg.interop.gltf import linear_to_srgb, srgb_to_linear
from isocsg.laminae import build_laminae
from isocsg.shadows import AreaLight

trimesh = pytest.importorskip("trimesh")

LIGHT = PointLight((2.0, -3.0, 4.0))
PLATE = Box((0, 0, 0), (2, 2, 0.4)) - Cylinder((0, 0, 0), (0, 0, 1), 0.5)
BALL = Sphere((2.2, 1.5, 0.2), 0.5)
CAMERA = Camera((3, -4, 3), (0, 0, 0), width=64, height=48)
CONTOURS = 8


def _chunks(glb: bytes) -> tuple[dict, bytes]:
    """A plain GLB reader: header, JSON chunk, BIN chunk (glTF 2.0, section 4.4)."""
    magic, version, length = struct.unpack_from("<4sII", glb, 0)
    assert (magic, version, length) == (b"glTF", 2, len(glb))
    n_json, kind = struct.unpack_from("<I4s", glb, 12)
    assert kind == b"JSON" and n_json % 4 == 0
    doc = json.loads(glb[20 : 20 + n_json])
    n_bin, kind = struct.unpack_from("<I4s", glb, 20 + n_json)
    assert kind == b"BIN\0"
    return doc, glb[28 + n_json : 28 + n_json + n_bin]


def _accessor(doc: dict, data: bytes, k: int) -> np.ndarray:
    acc = doc["accessors"][k]
    view = doc["bufferViews"][acc["bufferView"]]
    dtype = {5126: np.float32, 5125: np.uint32}[acc["componentType"]]
    width = {"SCALAR": 1, "VEC3": 3, "VEC4": 4}[acc["type"]]
    a = np.frombuffer(data, dtype, acc["count"] * width, view["byteOffset"])
    return a.reshape(acc["count"], width) if width > 1 else a


@pytest.fixture(scope="module")
def references() -> list[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """The band surfaces from the library's own builders (vertices, triangles, values)."""
    s = csg_surface(PLATE, [LIGHT], contours=CONTOURS)
    b = build_laminae(BALL, (LIGHT,), None, CONTOURS, eye=CAMERA.eye).bands
    return [(s.vertices, s.triangles, s.value), (b.vertices, b.triangles, b.value_out)]


@pytest.fixture(scope="module")
def glb_path(tmp_path_factory: pytest.TempPathFactory) -> Path:
    path = tmp_path_factory.mktemp("gltf") / "scene.glb"
    save_gltf(Scene(CAMERA, [LIGHT], [PLATE, BALL]), path, contours=CONTOURS)
    return path


def test_trimesh_reads_the_band_geometry_and_one_colour_per_band(glb_path: Path, references: list) -> None:
    loaded = trimesh.load(glb_path, process=False)
    for name, (v, t, value) in zip(("object0", "object1"), references):
        g = loaded.geometry[name]
        assert len(g.faces) == len(t)
        # Positions are float32: equal to the band surface's corners to float32 rounding.
        np.testing.assert_allclose(g.vertices[g.faces], v[t], atol=1e-6 * np.abs(v).max())
        colour = np.asarray(g.visual.vertex_attributes["color"], dtype=np.float64)[g.faces]
        assert np.array_equal(colour[:, 0], colour[:, 1]) and np.array_equal(colour[:, 0], colour[:, 2]), "blended"
        face = colour[:, 0, 0]
        assert len(np.unique(face)) == len(np.unique(value))
        np.testing.assert_allclose(linear_to_srgb(face), np.clip(value, 0, 1), atol=2e-6)


def test_merging_loaders_cannot_blend_bands(glb_path: Path, references: list) -> None:
    # trimesh's default load merges vertices: with no vertex shared between two
    # triangles of different colours, no colour can be averaged.
    loaded = trimesh.load(glb_path)
    for name, (_, _, value) in zip(("object0", "object1"), references):
        g = loaded.geometry[name]
        colour = np.asarray(g.visual.vertex_attributes["color"], dtype=np.float64)[g.faces][:, :, 0]
        assert np.ptp(colour, axis=1).max() == 0.0
        assert len(np.unique(colour[:, 0])) == len(np.unique(value))


def test_unlit_extension_and_exact_intensities(glb_path: Path, references: list) -> None:
    doc, data = _chunks(glb_path.read_bytes())
    assert "KHR_materials_unlit" in doc["extensionsUsed"]
    assert all("KHR_materials_unlit" in m["extensions"] for m in doc["materials"])
    for mesh, (v, t, value) in zip(doc["meshes"], references):
        (prim,) = mesh["primitives"]
        pos = _accessor(doc, data, prim["attributes"]["POSITION"])
        idx = _accessor(doc, data, prim["indices"])
        inten = _accessor(doc, data, prim["attributes"]["_INTENSITY"])
        assert len(np.unique(idx)) == len(idx) == 3 * len(t), "one vertex per triangle corner"
        np.testing.assert_array_equal(pos[idx].reshape(-1, 3, 3), v[t].astype(np.float32))
        np.testing.assert_array_equal(inten.reshape(-1, 3), np.repeat(value.astype(np.float32)[:, None], 3, axis=1))
    # the root turns +z up into glTF's +y up; the camera sits at the scene's eye
    root = doc["nodes"][0]
    np.testing.assert_allclose(root["rotation"], [-np.sqrt(0.5), 0, 0, np.sqrt(0.5)])
    cam = next(n for n in doc["nodes"] if "camera" in n)
    np.testing.assert_allclose(np.reshape(cam["matrix"], (4, 4)).T[:3, 3], CAMERA.eye)
    assert doc["cameras"][0]["perspective"]["yfov"] == pytest.approx(np.radians(CAMERA.fov))


def test_gltf_json_embeds_the_same_buffer(tmp_path: Path) -> None:
    surf = ShadedSurface(np.eye(3), np.array([[0, 1, 2]], np.int32), np.array([0.25]), "tri")
    doc = json.loads(save_gltf(surf, tmp_path / "t.gltf").read_text())
    assert doc["buffers"][0]["uri"].startswith("data:application/octet-stream;base64,")
    glb_doc, _ = _chunks(export_glb([surf]))
    assert glb_doc["accessors"] == doc["accessors"]


def test_srgb_round_trip() -> None:
    x = np.linspace(0, 1, 101)
    np.testing.assert_allclose(linear_to_srgb(srgb_to_linear(x)), x, atol=1e-12)
    # IEC 61966-2-1 check point: sRGB 0.5 is linear 0.2140
    assert srgb_to_linear(0.5) == pytest.approx(0.21404114, abs=1e-8)


def test_errors(tmp_path: Path) -> None:
    with pytest.raises(InvalidParameterError, match=re.escape("path must end in .glb or .gltf, got 'x.obj'")):
        save_gltf([], "x.obj")
    with pytest.raises(InvalidParameterError, match=re.escape("surfaces[0] must be a ShadedSurface, got int")):
        export_glb([1])
    lamp = AreaLight([(-1, -1, 3), (-1, 1, 3), (1, 1, 3), (1, -1, 3)])
    with pytest.raises(InvalidLightError, match="at least one PointLight or DirectionalLight"):
        export_glb(Scene(CAMERA, [lamp], [BALL]))


def test_cli_writes_glb(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    scene = {
        "camera": {"eye": [0, -6, 2], "target": [0, 0, 0], "width": 32, "height": 24},
        "render": {"contours": 5},
        "lights": [{"kind": "point", "position": [3, -4, 5]}],
        "objects": [{"shape": {"sphere": {"center": [0, 0, 0], "radius": 1}}}],
    }
    path = tmp_path / "s.json"
    path.write_text(json.dumps(scene))
    out = tmp_path / "out" / "s.glb"
    assert main(["render", str(path), "-o", str(out), "--no-progress"]) == 0
    assert capsys.readouterr().out.strip() == f"wrote {out}"
    doc, data = _chunks(out.read_bytes())
    b = build_laminae(Sphere((0, 0, 0), 1), (PointLight((3, -4, 5)),), None, 5).bands
    inten = _accessor(doc, data, doc["meshes"][0]["primitives"][0]["attributes"]["_INTENSITY"])
    assert len(np.unique(inten)) == len(np.unique(b.value_out.astype(np.float32)))
