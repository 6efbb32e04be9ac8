"""isocsg: isoluminance-contour rendering of CSG solids and exact soft shadows.

The public API is re-exported here and imported on first use (PEP 562): ``import isocsg``
costs a few milliseconds, and a program, or a command of the ``isocsg`` command line,
loads only the modules (numba kernels, shapely, scipy, pyvista) of what it calls.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from . import _late
from ._lazy import lazy_exports

__version__ = "0.1.0"

# Each public name and the module that defines it.
_EXPORTS: dict[str, str] = {
    **dict.fromkeys(["Camera"], ".camera"),
    **dict.fromkeys([
        "IsocsgError", "InvalidGeometryError", "InvalidLightError", "InvalidParameterError",
        "SceneFileError", "MissingDependencyError", "OpenSCADError", "UnsupportedOpenSCADError",
        "ResourceLimitError", "NotExactError",
    ], ".errors"),
    **dict.fromkeys([
        "Solid", "Primitive", "RayHits", "Sphere", "Truncus", "Cylinder", "Cone", "Box", "ConvexPolyhedron",
        "Ellipsoid", "EllipticTruncus",
    ], ".kinds"),
    "Torus": ".kinds",
    "TriangleMesh": ".kinds",
    "extrude": ".csg.extrude",
    **dict.fromkeys(["hull", "minkowski"], ".csg.hull"),
    **dict.fromkeys(["PointLight", "DirectionalLight", "Material", "shade"], ".lighting"),
    **dict.fromkeys(["Scene", "SceneObject", "RenderSettings", "load_scene", "loads_scene", "save_scene", "dumps_scene",
                     "builtin_scene", "builtin_scene_path"], ".scene"),
    **dict.fromkeys([
        "CSGNode", "Union", "Intersection", "Difference", "union", "intersection", "difference", "union_all",
    ], ".csg"),
    "section": ".csg.section",
    "volume": ".csg.volume",
    **dict.fromkeys(["to_manifold", "to_trimesh"], ".csg.mesh"),
    "clip_laminae": ".csg.clip",
    **dict.fromkeys(["build_laminae", "Lamina", "LaminaSet", "BandMesh"], ".laminae"),
    **dict.fromkeys(["render", "Renderer", "RenderResult", "save_scene_svg"], ".rendering"),
    **dict.fromkeys(["save_png", "save_npy"], ".rendering.image"),
    "show": ".view",
    **dict.fromkeys(["render_views", "turntable", "illuminance_grid"], ".batch"),
    **dict.fromkeys(["ShadedSurface", "object_surface", "scene_surfaces"], ".interop.bands"),
    **dict.fromkeys(["export_glb", "save_gltf"], ".interop.gltf"),
    "to_pyvista": ".interop.pyvista",
    **dict.fromkeys(["AreaLight", "PolyhedronLight"], ".lighting.area"),
    **dict.fromkeys(["Photometry", "PhotometryFileError", "read_photometry"], ".lighting.photometry"),
    "PhotometricLight": ".lighting.luminaire",
    **dict.fromkeys(["illuminance", "shadow_state", "illuminance_and_state"], ".shadows.direct"),
    **dict.fromkeys(["Interreflections", "RadiositySolution", "solve_radiosity"], ".shadows.radiosity"),
    "Room": ".shadows.patches",
    **dict.fromkeys(["render_halftone", "HalftoneResult"], ".shadows.halftone"),
    "shadow_volumes": ".shadows.volumes",
    **dict.fromkeys(["LuxGrid", "LuxMap", "illuminance_map", "save_luxmap_png"], ".shadows.luxmap"),
    **dict.fromkeys(["LuxStats", "lux_statistics", "save_luxmap_csv"], ".shadows.luxstats"),
    "save_luxmap_figure": ".shadows.luxplot",
    **dict.fromkeys(["load_openscad", "loads_openscad", "read_openscad", "save_openscad", "dumps_openscad",
                     "OpenSCADSkipWarning"], ".openscad"),
    **dict.fromkeys(["memory_budget", "set_memory_budget"], ".limits"),
    "compile_kernels": ".kernels",
    **dict.fromkeys([
        "Shape2D", "ConvexPolygon", "Circle", "Ellipse", "Union2D", "Intersection2D", "Difference2D", "polygon",
        "square", "circle", "text", "offset", "linear_extrude", "union_all2d", "to_shapely",
    ], ".shapes2d"),
    "rotate_extrude": ".shapes2d.revolve",
}

# Written out for linters and type checkers: the keys of _EXPORTS (tests/test_public_api.py).
__all__ = [
    "AreaLight",
    "BandMesh",
    "Box",
    "CSGNode",
    "Camera",
    "Circle",
    "Cone",
    "ConvexPolygon",
    "ConvexPolyhedron",
    "Cylinder",
    "Difference",
    "Difference2D",
    "DirectionalLight",
    "Ellipse",
    "Ellipsoid",
    "EllipticTruncus",
    "HalftoneResult",
    "Interreflections",
    "Intersection",
    "Intersection2D",
    "InvalidGeometryError",
    "InvalidLightError",
    "InvalidParameterError",
    "IsocsgError",
    "Lamina",
    "LaminaSet",
    "LuxGrid",
    "LuxMap",
    "LuxStats",
    "Material",
    "MissingDependencyError",
    "NotExactError",
    "OpenSCADError",
    "OpenSCADSkipWarning",
    "PhotometricLight",
    "Photometry",
    "PhotometryFileError",
    "PointLight",
    "PolyhedronLight",
    "Primitive",
    "RadiositySolution",
    "RayHits",
    "RenderResult",
    "RenderSettings",
    "Renderer",
    "ResourceLimitError",
    "Room",
    "Scene",
    "SceneFileError",
    "SceneObject",
    "ShadedSurface",
    "Shape2D",
    "Solid",
    "Sphere",
    "Torus",
    "TriangleMesh",
    "Truncus",
    "Union",
    "Union2D",
    "UnsupportedOpenSCADError",
    "__version__",
    "build_laminae",
    "builtin_scene",
    "builtin_scene_path",
    "circle",
    "clip_laminae",
    "compile_kernels",
    "difference",
    "dumps_openscad",
    "dumps_scene",
    "export_glb",
    "extrude",
    "hull",
    "illuminance",
    "illuminance_and_state",
    "illuminance_grid",
    "illuminance_map",
    "intersection",
    "linear_extrude",
    "load_openscad",
    "load_scene",
    "loads_openscad",
    "loads_scene",
    "lux_statistics",
    "memory_budget",
    "minkowski",
    "object_surface",
    "offset",
    "polygon",
    "read_openscad",
    "read_photometry",
    "render",
    "render_halftone",
    "render_views",
    "rotate_extrude",
    "save_gltf",
    "save_luxmap_csv",
    "save_luxmap_figure",
    "save_luxmap_png",
    "save_npy",
    "save_openscad",
    "save_png",
    "save_scene",
    "save_scene_svg",
    "scene_surfaces",
    "section",
    "set_memory_budget",
    "shade",
    "shadow_state",
    "shadow_volumes",
    "show",
    "solve_radiosity",
    "square",
    "text",
    "to_manifold",
    "to_pyvista",
    "to_shapely",
    "to_trimesh",
    "turntable",
    "union",
    "union_all",
    "union_all2d",
    "volume"
]

__getattr__, __dir__ = lazy_exports(globals(), _EXPORTS)


# The operations lower layers offer and upper ones implement (isocsg/_late.py): Solid's Boolean
# operators (csg/tree.py), Program's membership and nodes (csg/membership.py, csg/tree.py) and
# the notebook display of solids, scenes, renders and half-tone images (interop/notebook.py).
# Bound here, before any submodule runs; each imports its module on first call.
def _union(*solids: Any) -> Any:
    from .csg.tree import union

    return union(*solids)


def _intersection(*solids: Any) -> Any:
    from .csg.tree import intersection

    return intersection(*solids)


def _difference(first: Any, *others: Any) -> Any:
    from .csg.tree import difference

    return difference(first, *others)


def _contains_program(program: Any, points: Any, tol: Any) -> Any:
    from .csg.membership import contains_program

    return contains_program(program, points, tol)


def _csg_node(name: str, *operands: Any) -> Any:
    from .csg.tree import NODE_TYPES

    return NODE_TYPES[name](*operands)


def _mimebundle(obj: Any, include: Any = None, exclude: Any = None) -> dict[str, Any]:
    from .interop.notebook import mimebundle

    return mimebundle(obj, include, exclude)


for _name, _fn in (("union", _union), ("intersection", _intersection), ("difference", _difference),
                   ("contains_program", _contains_program), ("csg_node", _csg_node), ("mimebundle", _mimebundle)):
    _late.bind(_name, _fn)
del _name, _fn


if TYPE_CHECKING:  # what the names are, for type checkers and editors
    from .batch import illuminance_grid, render_views, turntable
    from .camera import Camera
    from .csg import (
        CSGNode,
        Difference,
        Intersection,
        Union,
        difference,
        intersection,
        union,
        union_all,
    )
    from .csg.clip import clip_laminae
    from .csg.extrude import extrude
    from .csg.mesh import to_manifold, to_trimesh
    from .csg.section import section
    from .csg.volume import volume
    from .errors import (
        InvalidGeometryError,
        InvalidLightError,
        InvalidParameterError,
        IsocsgError,
        MissingDependencyError,
        OpenSCADError,
        ResourceLimitError,
        SceneFileError,
        UnsupportedOpenSCADError,
    )
    from .interop.bands import ShadedSurface, object_surface, scene_surfaces
    from .interop.gltf import export_glb, save_gltf
    from .interop.pyvista import to_pyvista
    from .kernels import compile_kernels
    from .kinds import (
        Box,
        Cone,
        ConvexPolyhedron,
        Cylinder,
        Ellipsoid,
        EllipticTruncus,
        Primitive,
        RayHits,
        Solid,
        Sphere,
        Torus,
        TriangleMesh,
        Truncus,
    )
    from .laminae import BandMesh, Lamina, LaminaSet, build_laminae
    from .lighting import DirectionalLight, Material, PointLight, shade
    from .lighting.area import AreaLight, PolyhedronLight
    from .lighting.luminaire import PhotometricLight
    from .lighting.photometry import Photometry, PhotometryFileError, read_photometry
    from .limits import memory_budget, set_memory_budget
    from .openscad import (
        OpenSCADSkipWarning,
        dumps_openscad,
        load_openscad,
        loads_openscad,
        read_openscad,
        save_openscad,
    )
    from .rendering import Renderer, RenderResult, render, save_scene_svg
    from .rendering.image import save_npy, save_png
    from .scene import (
        RenderSettings,
        Scene,
        SceneObject,
        builtin_scene,
        builtin_scene_path,
        dumps_scene,
        load_scene,
        loads_scene,
        save_scene,
    )
    from .shadows.direct import illuminance, illuminance_and_state, shadow_state
    from .shadows.halftone import HalftoneResult, render_halftone
    from .shadows.luxmap import LuxGrid, LuxMap, illuminance_map, save_luxmap_png
    from .shadows.luxplot import save_luxmap_figure
    from .shadows.luxstats import LuxStats, lux_statistics, save_luxmap_csv
    from .shadows.patches import Room
    from .shadows.radiosity import Interreflections, RadiositySolution, solve_radiosity
    from .shadows.volumes import shadow_volumes
    from .shapes2d import (
        Circle,
        ConvexPolygon,
        Difference2D,
        Ellipse,
        Intersection2D,
        Shape2D,
        Union2D,
        circle,
        linear_extrude,
        offset,
        polygon,
        square,
        text,
        to_shapely,
        union_all2d,
    )
    from .shapes2d.revolve import rotate_extrude
