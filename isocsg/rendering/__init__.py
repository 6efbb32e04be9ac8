"""Isoluminance rendering: compiled band fill, per-pixel CSG and image writers.

Each public name is imported from its module on first use (:mod:`isocsg._lazy`): a command
that renders imports the renderer, not the rasteriser or the SVG writer.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import lazy_exports

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

_EXPORTS = {
    "render": ".painter",
    "Renderer": ".painter",
    "default_renderer": ".painter",
    "homogeneous": ".projection",
    "Raster": ".raster",
    "rasterize": ".raster",
    "RenderResult": ".result",
    "RenderTimings": ".result",
    "ScenePolygons": ".svg",
    "save_scene_svg": ".svg",
    "scene_polygons": ".svg",
}

__getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)

if TYPE_CHECKING:
    from .painter import Renderer, default_renderer, render
    from .projection import homogeneous
    from .raster import Raster, rasterize
    from .result import RenderResult, RenderTimings
    from .svg import ScenePolygons, save_scene_svg, scene_polygons
