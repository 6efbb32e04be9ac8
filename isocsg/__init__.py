"""isocsg: isoluminance-contour rendering of CSG solids and exact soft shadows.

The public API is re-exported here; heavy optional modules (pyvista) load lazily.
"""

from __future__ import annotations

from .camera import Camera
from .errors import (
    InvalidGeometryError,
    InvalidLightError,
    InvalidParameterError,
    IsocsgError,
    MissingDependencyError,
    OpenSCADError,
    SceneFileError,
    UnsupportedOpenSCADError,
)
from .geometry import Box, Cone, ConvexPolyhedron, Cylinder, Ellipsoid, EllipticTruncus, Primitive, RayHits, Solid, Sphere, Truncus
from .lighting import DirectionalLight, Material, PointLight, shade
from .scene import RenderSettings, Scene, SceneObject
from .csg import CSGNode, Difference, Intersection, Union, difference, intersection, union, union_all
from .csg.section import section
from .csg.volume import volume
from .csg.mesh import to_manifold, to_trimesh
from .csg.clip import clip_laminae
from .laminae import BandMesh, Lamina, LaminaSet, build_laminae
from .render import Renderer, RenderResult, render
from .render.image import save_npy, save_png
from .scene import load_scene, save_scene
from .shadows import AreaLight, PolyhedronLight, illuminance, illuminance_and_state, shadow_state
from .view import show
from .batch import illuminance_grid, render_views, turntable
from .interop import ShadedSurface, export_glb, object_surface, save_gltf, scene_surfaces, to_pyvista
from .geometry.extrude import extrude
from .openscad import OpenSCADSkipWarning, dumps_openscad, load_openscad, loads_openscad, read_openscad, save_openscad

__version__ = "0.1.0"

__all__ = [
    "__version__",
    "Camera",
    "IsocsgError", "InvalidGeometryError", "InvalidLightError", "InvalidParameterError",
    "SceneFileError", "MissingDependencyError", "OpenSCADError", "UnsupportedOpenSCADError",
    "Solid", "Primitive", "RayHits", "Sphere", "Truncus", "Cylinder", "Cone", "Box", "ConvexPolyhedron", "Ellipsoid", "EllipticTruncus",
    "PointLight", "DirectionalLight", "Material", "shade",
    "Scene", "SceneObject", "RenderSettings",
    "CSGNode", "Union", "Intersection", "Difference", "union", "intersection", "difference", "union_all",
    "section", "volume", "to_manifold", "to_trimesh", "clip_laminae",
    "build_laminae", "Lamina", "LaminaSet", "BandMesh",
    "render", "Renderer", "RenderResult", "save_png", "save_npy", "show",
    "render_views", "turntable", "illuminance_grid",
    "ShadedSurface", "object_surface", "scene_surfaces", "export_glb", "save_gltf", "to_pyvista",
    "load_scene", "save_scene",
    "AreaLight", "PolyhedronLight", "illuminance", "shadow_state", "illuminance_and_state",
    "extrude",
    "load_openscad", "loads_openscad", "read_openscad", "save_openscad", "dumps_openscad", "OpenSCADSkipWarning",
]
