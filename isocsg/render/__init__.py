"""Isoluminance rendering: compiled band fill, per-pixel CSG and image writers."""

from __future__ import annotations

from .painter import Renderer, RenderResult, RenderTimings, default_renderer, render
from .raster import Raster, homogeneous, rasterize
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
