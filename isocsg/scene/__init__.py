"""Scenes: immutable values and the TOML/JSON scene files (:mod:`.io` reads, :mod:`.writer` writes)."""

from .io import BUILTIN_SCENES, builtin_scene, builtin_scene_path, load_scene, loads_scene, scene_from_dict
from .model import MAX_CONTOURS, RENDER_MODES, RenderSettings, Scene, SceneObject
from .writer import dumps_scene, save_scene, scene_to_dict

__all__ = [
    "Scene",
    "SceneObject",
    "RenderSettings",
    "MAX_CONTOURS",
    "RENDER_MODES",
    "load_scene",
    "loads_scene",
    "save_scene",
    "dumps_scene",
    "scene_from_dict",
    "scene_to_dict",
    "builtin_scene",
    "builtin_scene_path",
    "BUILTIN_SCENES",
]
