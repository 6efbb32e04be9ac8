"""Interoperability: the shaded bands in other tools (glTF viewers, pyvista, Jupyter).

The conversions import their heavy dependencies (pyvista, vtk) only when
called, so importing this package stays cheap.
"""

from __future__ import annotations

from .bands import ShadedSurface, object_surface, scene_surfaces
from .gltf import export_glb, save_gltf
from .pyvista import to_pyvista

__all__ = ["ShadedSurface", "object_surface", "scene_surfaces", "export_glb", "save_gltf", "to_pyvista"]

