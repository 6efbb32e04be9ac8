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
    SceneFileError,
)
from .geometry import Box, Cone, ConvexPolyhedron, Cylinder, Primitive, RayHits, Solid, Sphere, Truncus
from .lighting import DirectionalLight, Material, PointLight, shade
from .scene import RenderSettings, Scene, SceneObject
from .csg import CSGNode, Difference, Intersection, Union, difference, intersection, union, union_all

__version__ = "0.1.0"

__all__ = [
    "__version__",
    "Camera",
    "IsocsgError", "InvalidGeometryError", "InvalidLightError", "InvalidParameterError",
    "SceneFileError", "MissingDependencyError",
    "Solid", "Primitive", "RayHits", "Sphere", "Truncus", "Cylinder", "Cone", "Box", "ConvexPolyhedron",
    "PointLight", "DirectionalLight", "Material", "shade",
    "Scene", "SceneObject", "RenderSettings",
    "CSGNode", "Union", "Intersection", "Difference", "union", "intersection", "difference", "union_all",
]
