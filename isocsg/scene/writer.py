"""Writing scenes as TOML or JSON scene files (the inverse of :mod:`isocsg.scene.io`).

Shapes are written through their kinds' ``to_dict``; trees nested deeper than
:data:`MAX_FILE_DEPTH` are written flattened.
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from ..errors import SceneFileError
from .io import scene_format
from .model import Scene

__all__ = ["MAX_FILE_DEPTH", "dumps_scene", "save_scene", "scene_to_dict"]


def _light_to_dict(light: Any) -> dict[str, Any]:
    if hasattr(light, "to_dict"):
        d = dict(light.to_dict())
    else:  # a source without its own mapping: the documented fields
        d = {"vertices": [list(map(float, v)) for v in light.vertices], "radiance": float(light.radiance)}
    d.setdefault("kind", getattr(light, "kind", None))
    # `kind` first reads best in files.
    return {"kind": d.pop("kind"), **d}


#: Deepest shape nesting written to a scene file: the standard TOML and JSON decoders
#: recurse per level. Deeper trees are written flattened (nested nodes of one
#: operation merged, see :func:`isocsg.csg.program.compile_program`).
MAX_FILE_DEPTH = 100


def _nesting(shape: Any) -> int:
    """Depth of a shape tree (a primitive is 1), without recursion."""
    deepest, todo = 0, [(shape, 1)]
    while todo:
        s, d = todo.pop()
        deepest = max(deepest, d)
        todo.extend((c, d + 1) for c in getattr(s, "children", ()))
    return deepest


def _file_shape(shape: Any, where: str) -> dict[str, Any]:
    """``shape.to_dict()``, flattened when it nests deeper than :data:`MAX_FILE_DEPTH`."""
    if _nesting(shape) > MAX_FILE_DEPTH:
        shape = shape.program().to_solid()
        depth = _nesting(shape)
        if depth > MAX_FILE_DEPTH:
            raise SceneFileError(
                f"{where}: the tree nests {depth} levels deep even with nested nodes of one operation merged; "
                f"scene files hold at most {MAX_FILE_DEPTH} (the TOML and JSON decoders recurse per level)"
            )
    return shape.to_dict()


def scene_to_dict(scene: Scene) -> dict[str, Any]:
    """The scene-file document of a scene (the inverse of :func:`scene_from_dict`).

    Parameters
    ----------
    scene : Scene

    Returns
    -------
    dict
        Plain lists, numbers and strings, ready for ``json.dump`` or
        :func:`dumps_scene`. A tree nested deeper than :data:`MAX_FILE_DEPTH`
        levels is written flattened (the same solid, with nested nodes of one
        operation merged).

    Raises
    ------
    SceneFileError
        If a tree still nests deeper than :data:`MAX_FILE_DEPTH` once flattened
        (operations that alternate level after level).

    Examples
    --------
    >>> from isocsg import Camera, Sphere, Box, PointLight
    >>> from isocsg.scene import scene_from_dict
    >>> s = Scene(Camera((0, -5, 0), (0, 0, 0)), [PointLight((0, -5, 5))],
    ...           [Box((0, 0, 0), (2, 2, 2)) - Sphere((1, 1, 1), 1)])
    >>> scene_from_dict(scene_to_dict(s)) == s
    True
    """
    cam = scene.camera
    camera = cam.to_dict()
    if cam.orthographic:
        camera.update(orthographic=True, height_m=cam.height_m)
    rs = scene.render
    return {
        "camera": camera,
        "render": {"contours": rs.contours, "mode": rs.mode, "exposure": rs.exposure, "interval": rs.interval},
        "lights": [_light_to_dict(light) for light in scene.lights],
        "objects": [_object_to_dict(k, o) for k, o in enumerate(scene.objects)],
    }


def _object_to_dict(k: int, o: Any) -> dict[str, Any]:
    out: dict[str, Any] = {"material": o.material.to_dict(), "shape": _file_shape(o.shape, f"objects[{k}].shape")}
    if o.color is not None:
        out["color"] = list(o.color)
    if o.leaf_colors:
        out["leaf_colors"] = {str(i): list(c) for i, c in enumerate(o.leaf_colors) if c is not None}
    return out


def _toml_value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        import json  # here: reading a model does not load it

        return json.dumps(v)  # a JSON string is a valid TOML basic string
    if isinstance(v, Mapping):
        return "{ " + ", ".join(f"{k} = {_toml_value(x)}" for k, x in v.items()) + " }"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    raise SceneFileError(f"cannot write {type(v).__name__} to TOML")


def dumps_scene(scene: Scene, *, format: str = "toml") -> str:
    """Scene-file text of a scene, in ``"toml"`` or ``"json"``.

    Examples
    --------
    >>> from isocsg import Camera, Sphere
    >>> from isocsg.scene import loads_scene
    >>> s = Scene(Camera((0, -5, 0), (0, 0, 0)), [], [Sphere((0, 0, 0), 1)])
    >>> loads_scene(dumps_scene(s)) == s
    True
    """
    doc = scene_to_dict(scene)
    if format == "json":
        import json

        return json.dumps(doc, indent=2) + "\n"
    if format != "toml":
        raise SceneFileError(f"unknown scene format {format!r} (expected 'toml' or 'json')")
    lines: list[str] = []
    for table in ("camera", "render"):
        lines.append(f"[{table}]")
        lines += [f"{k} = {_toml_value(v)}" for k, v in doc[table].items()]
        lines.append("")
    for table in ("lights", "objects"):
        for item in doc[table]:
            lines.append(f"[[{table}]]")
            lines += [f"{k} = {_toml_value(v)}" for k, v in item.items()]
            lines.append("")
    return "\n".join(lines)


def save_scene(scene: Scene, path: str | os.PathLike[str]) -> Path:
    """Write a scene file; the format follows the extension (``.toml`` or ``.json``).

    Returns
    -------
    pathlib.Path
        The path written.

    Raises
    ------
    SceneFileError
        On an unknown extension.
    """
    p = Path(path)
    p.write_text(dumps_scene(scene, format=scene_format(p)), encoding="utf-8")
    return p
