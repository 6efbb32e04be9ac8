"""Isoluminance rendering: compiled band fill, per-pixel CSG and image writers."""

from __future__ import annotations

from .painter import Renderer, default_renderer, render
from .projection import homogeneous
from .raster import Raster, rasterize
from .result import RenderResult, RenderTimings
from .svg import ScenePolygons, save_scene_svg, scene_polygons

__all__ = [
    "render",
    "Renderer",
    "RenderResult",
    "RenderTimings",
    "default_renderer",
    "rasterize",
    "Raster",
    "homogeneous",
    "save_scene_svg",
    "scene_polygons",
    "ScenePolygons",
]
