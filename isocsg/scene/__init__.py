"""Scenes: immutable values and the TOML/JSON scene-file reader."""

from .model import MAX_CONTOURS, RENDER_MODES, RenderSettings, Scene, SceneObject

__all__ = ["Scene", "SceneObject", "RenderSettings", "MAX_CONTOURS", "RENDER_MODES"]
