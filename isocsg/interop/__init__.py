"""Interoperability: the shaded bands in other tools (glTF viewers, pyvista, Jupyter).

The names below are imported on first use, and the conversions import their heavy
dependencies (pyvista, vtk) only when called, so importing this package stays cheap.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from .._lazy import lazy_exports

_EXPORTS: dict[str, str] = {
    **dict.fromkeys(["ShadedSurface", "object_surface", "scene_surfaces"], ".bands"),
    **dict.fromkeys(["export_glb", "save_gltf"], ".gltf"),
    "to_pyvista": ".pyvista",
}

# Written out for linters and type checkers: the keys of _EXPORTS (tests/test_public_api.py).
__all__ = [
    "ShadedSurface",
    "export_glb",
    "object_surface",
    "save_gltf",
    "scene_surfaces",
    "to_pyvista"
]

__getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)

if TYPE_CHECKING:
    from .bands import ShadedSurface, object_surface, scene_surfaces
    from .gltf import export_glb, save_gltf
    from .pyvista import to_pyvista
