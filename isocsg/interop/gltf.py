"""glTF 2.0 export of the shaded bands: flat, unlit colours that any viewer shows as isocsg does.

Each triangle is written with its own three vertices (no vertex is shared
between triangles), all three carrying the triangle's colour, so a viewer's
interpolation of vertex colours cannot blend two bands. The material
declares ``KHR_materials_unlit``: the viewer adds no lighting of its own and
shows the isoluminance shading, one grey per band value.

Colours. glTF colours are linear; viewers encode them to sRGB for display.
An intensity I (shown as the 8-bit grey ``255 I`` in isocsg's PNG images) is
therefore written as the linear value ``srgb_to_linear(I)``, so the viewer
shows the same grey. The exact intensity is also kept in the
application-specific attribute ``_INTENSITY`` (one float per vertex).

Frames. isocsg is +z up, glTF +y up: the root node turns the scene by -90
degrees about x; the vertex positions themselves are isocsg's world
coordinates in metres. When a scene is exported, its camera is added as a
glTF perspective (or orthographic) camera.

The file is written with the standard library (``json``, ``struct``).
"""

from __future__ import annotations

import base64
import json
import math
import os
import struct
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import InvalidParameterError
from .bands import ShadedSurface, _as_surfaces

__all__ = ["export_glb", "save_gltf", "gltf_document", "srgb_to_linear", "linear_to_srgb"]

_FLOAT, _UINT32 = 5126, 5125
_ARRAY_BUFFER, _ELEMENT_ARRAY_BUFFER = 34962, 34963
# -90 degrees about x: isocsg's +z up becomes glTF's +y up.
_Z_UP_TO_Y_UP = [-math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5)]


def srgb_to_linear(value: ArrayLike) -> NDArray[np.float64]:
    """The sRGB transfer function's inverse (IEC 61966-2-1) on [0, 1] (clipped).

    Examples
    --------
    >>> srgb_to_linear([0.0, 0.5, 1.0]).round(6).tolist()
    [0.0, 0.214041, 1.0]
    """
    c = np.clip(np.asarray(value, dtype=np.float64), 0.0, 1.0)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def linear_to_srgb(value: ArrayLike) -> NDArray[np.float64]:
    """The sRGB transfer function on [0, 1] (clipped); inverse of :func:`srgb_to_linear`.

    Examples
    --------
    >>> linear_to_srgb(srgb_to_linear([0.1, 0.7])).round(12).tolist()
    [0.1, 0.7]
    """
    c = np.clip(np.asarray(value, dtype=np.float64), 0.0, 1.0)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * c ** (1 / 2.4) - 0.055)


class _Buffer:
    """The binary chunk, built view by view (each view 4-byte aligned)."""

    def __init__(self) -> None:
        self.parts: list[bytes] = []
        self.size = 0
        self.views: list[dict[str, Any]] = []
        self.accessors: list[dict[str, Any]] = []

    def add(self, array: NDArray[Any], kind: str, component: int, target: int, bounds: bool = False) -> int:
        data = np.ascontiguousarray(array).tobytes()
        self.views.append({"buffer": 0, "byteOffset": self.size, "byteLength": len(data), "target": target})
        pad = (-len(data)) % 4
        self.parts.append(data + b"\0" * pad)
        self.size += len(data) + pad
        acc: dict[str, Any] = {
            "bufferView": len(self.views) - 1, "componentType": component, "count": int(len(array)), "type": kind,
        }
        if bounds and len(array):
            acc["min"] = [float(x) for x in array.min(axis=0)]
            acc["max"] = [float(x) for x in array.max(axis=0)]
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def data(self) -> bytes:
        return b"".join(self.parts)


def _camera(camera: Any) -> tuple[dict[str, Any], dict[str, Any]]:
    """A glTF camera and the node that places it (in the z-up frame below the root)."""
    f, r, u = (np.asarray(x, dtype=np.float64) for x in camera.frame)
    eye = np.asarray(camera.eye, dtype=np.float64)
    # glTF cameras look along their local -z with +y up: columns r, u, -f, eye (column-major).
    m = np.eye(4)
    m[:3, 0], m[:3, 1], m[:3, 2], m[:3, 3] = r, u, -f, eye
    scale = max(1.0, float(np.linalg.norm(eye - np.asarray(camera.target, dtype=np.float64))))
    if camera.orthographic:
        ymag = 0.5 * float(camera.height_m)
        cam = {"type": "orthographic", "orthographic": {
            "xmag": ymag * camera.width / camera.height, "ymag": ymag, "znear": 0.0, "zfar": 1e3 * scale}}
    else:
        cam = {"type": "perspective", "perspective": {
            "yfov": math.radians(camera.fov), "aspectRatio": camera.width / camera.height, "znear": 1e-3 * scale}}
    node = {"name": "camera", "camera": 0, "matrix": [float(x) for x in m.T.reshape(-1)]}
    return cam, node


def gltf_document(item: Any, *, contours: int | None = None) -> tuple[dict[str, Any], bytes]:
    """The glTF JSON document and its binary buffer.

    Parameters
    ----------
    item : Scene, ShadedSurface or list of ShadedSurface
    contours : int, keyword-only, optional
        For a scene: contours per light (default ``scene.render.contours``).

    Returns
    -------
    (dict, bytes)
        The document (its one buffer has no ``uri`` yet) and the buffer.
    """
    surfaces = _as_surfaces(item, contours=contours)
    buf = _Buffer()
    meshes, nodes = [], []
    for s in surfaces:
        t = np.asarray(s.triangles, dtype=np.int64)
        if len(t) == 0:  # nothing to draw (glTF accessors need at least one element)
            continue
        # One vertex per triangle corner: colours cannot blend across triangles.
        pos = np.asarray(s.vertices, dtype=np.float64)[t.reshape(-1)].astype(np.float32)
        value = np.repeat(np.asarray(s.value, dtype=np.float64), 3)
        if s.color is None:
            grey = srgb_to_linear(value).astype(np.float32)
            rgba = np.column_stack([grey, grey, grey, np.ones_like(grey)])
        else:  # the intensity tints the triangle's colour (the colour of isocsg's own PNG, in linear light)
            tinted = srgb_to_linear(value[:, None] * np.repeat(np.asarray(s.color, np.float64), 3, axis=0))
            rgba = np.column_stack([tinted, np.ones(len(tinted))]).astype(np.float32)
        attributes = {
            "POSITION": buf.add(pos, "VEC3", _FLOAT, _ARRAY_BUFFER, bounds=True),
            "COLOR_0": buf.add(rgba, "VEC4", _FLOAT, _ARRAY_BUFFER),
            "_INTENSITY": buf.add(value.astype(np.float32), "SCALAR", _FLOAT, _ARRAY_BUFFER),
        }
        indices = buf.add(np.arange(len(pos), dtype=np.uint32), "SCALAR", _UINT32, _ELEMENT_ARRAY_BUFFER)
        meshes.append({"name": s.name, "primitives": [
            {"attributes": attributes, "indices": indices, "material": 0, "mode": 4}]})
        nodes.append({"name": s.name, "mesh": len(meshes) - 1})
    children = list(range(1, len(nodes) + 1))
    doc: dict[str, Any] = {
        "asset": {"version": "2.0", "generator": "isocsg"},
        "extensionsUsed": ["KHR_materials_unlit"],
        "materials": [{
            "name": "isoluminance bands (unlit, vertex colours)",
            "pbrMetallicRoughness": {
                "baseColorFactor": [1.0, 1.0, 1.0, 1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0,
            },
            "extensions": {"KHR_materials_unlit": {}},
        }],
        "meshes": meshes,
    }
    camera = None if isinstance(item, (ShadedSurface, list, tuple)) else item.camera
    if camera is not None:
        cam, cam_node = _camera(camera)
        doc["cameras"] = [cam]
        nodes.append(cam_node)
        children.append(len(nodes))
    doc["nodes"] = [{"name": "isocsg (z up)", "rotation": _Z_UP_TO_Y_UP, "children": children}, *nodes]
    doc["scenes"] = [{"nodes": [0]}]
    doc["scene"] = 0
    data = buf.data()
    doc["buffers"] = [{"byteLength": len(data)}]
    doc["bufferViews"] = buf.views
    doc["accessors"] = buf.accessors
    return doc, data


def export_glb(item: Any, *, contours: int | None = None) -> bytes:
    """The shaded bands as a binary glTF (GLB) file's bytes.

    Parameters
    ----------
    item : Scene, ShadedSurface or list of ShadedSurface
        A scene's objects are exported with their clipped CSG surfaces and
        its camera.
    contours : int, keyword-only, optional
        For a scene: contours per light (default ``scene.render.contours``).

    Returns
    -------
    bytes

    Raises
    ------
    InvalidParameterError
        If ``item`` is neither a scene nor shaded surfaces.
    InvalidLightError
        If a scene has no point or directional light.

    Examples
    --------
    >>> from isocsg import Camera, PointLight, Scene, Sphere
    >>> scene = Scene(Camera((0, -4, 1), (0, 0, 0)), [PointLight((2, -3, 4))], [Sphere((0, 0, 0), 1)])
    >>> glb = export_glb(scene, contours=8)
    >>> glb[:4], int.from_bytes(glb[8:12], "little") == len(glb)
    (b'glTF', True)
    """
    doc, data = gltf_document(item, contours=contours)
    text = json.dumps(doc, separators=(",", ":")).encode("utf-8")
    text += b" " * ((-len(text)) % 4)
    data += b"\0" * ((-len(data)) % 4)
    total = 12 + 8 + len(text) + 8 + len(data)
    return b"".join([
        struct.pack("<4sII", b"glTF", 2, total),
        struct.pack("<I4s", len(text), b"JSON"), text,
        struct.pack("<I4s", len(data), b"BIN\0"), data,
    ])


def save_gltf(item: Any, path: str | os.PathLike[str], *, contours: int | None = None) -> Path:
    """Write the shaded bands as ``.glb`` (binary) or ``.gltf`` (JSON, buffer embedded).

    Parameters
    ----------
    item : Scene, ShadedSurface or list of ShadedSurface
    path : str or path-like
        Its extension chooses the format.
    contours : int, keyword-only, optional

    Returns
    -------
    pathlib.Path

    Raises
    ------
    InvalidParameterError
        If ``path`` ends in neither ``.glb`` nor ``.gltf``.
    """
    p = Path(path)
    suffix = p.suffix.lower()
    if suffix not in (".glb", ".gltf"):
        raise InvalidParameterError(f"path must end in .glb or .gltf, got {str(path)!r}")
    if suffix == ".glb":
        p.write_bytes(export_glb(item, contours=contours))
        return p
    doc, data = gltf_document(item, contours=contours)
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode("ascii")
    p.write_text(json.dumps(doc, separators=(",", ":")), encoding="utf-8")
    return p
