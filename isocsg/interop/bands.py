"""The shaded surface of an object: triangles of constant value, the Boolean result for CSG.

A primitive's surface is its :class:`~isocsg.laminae.model.BandMesh` with the
outward values; a CSG tree's is the clipped band surface of
:func:`isocsg.csg.surface.surface_from_bands` (the boundary of the Boolean
result, each triangle with the value of the leaf it lies on, reversed inside
cuts). Both are what the renderer fills, as plain triangles.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import InvalidLightError, InvalidParameterError
from ..kinds import Primitive, Solid
from ..lighting.lights import DirectionalLight, Material, PointLight

__all__ = ["ShadedSurface", "object_surface", "scene_surfaces"]


@dataclass(frozen=True, slots=True, eq=False)
class ShadedSurface:
    """Triangles on the boundary of a solid, each with one constant intensity.

    Attributes
    ----------
    vertices : ndarray, shape (V, 3), float64
        Metres, world frame (+z up).
    triangles : ndarray, shape (T, 3), int32
        Counter-clockwise seen from outside the solid.
    value : ndarray, shape (T,), float64
        Intensity each triangle shows (the conventions' shading, 0 black, 1 white).
    name : str
        A label for viewers, e.g. ``"object0"``.
    color : ndarray, shape (T, 3), float64, or None
        The sRGB colour each triangle's intensity tints (its object's or leaf's colour,
        :mod:`isocsg.rendering.colors`); None: grey.
    """

    vertices: NDArray[np.float64]
    triangles: NDArray[np.int32]
    value: NDArray[np.float64]
    name: str = "object"
    color: NDArray[np.float64] | None = None

    @property
    def n_triangles(self) -> int:
        """Number of triangles."""
        return int(len(self.triangles))

    @property
    def bounds(self) -> NDArray[np.float64]:
        """Axis-aligned bounds ``[[lo], [hi]]``, shape (2, 3)."""
        if len(self.vertices) == 0:
            return np.zeros((2, 3))
        return np.array([self.vertices.min(axis=0), self.vertices.max(axis=0)])


def _band_lights(lights: Any) -> tuple[Any, ...]:
    items = (lights,) if isinstance(lights, (PointLight, DirectionalLight)) else tuple(lights)
    out = tuple(li for li in items if isinstance(li, (PointLight, DirectionalLight)))
    if not out:
        raise InvalidLightError("lights must hold at least one PointLight or DirectionalLight (isoluminance bands)")
    return out


def object_surface(
    shape: Solid,
    lights: Any,
    material: Material | None = None,
    contours: int = 64,
    *,
    eye: ArrayLike | None = None,
    name: str = "object",
    color: Any = None,
    leaf_colors: Any = (),
) -> ShadedSurface:
    """The shaded band surface of one solid.

    Parameters
    ----------
    shape : Solid
        A primitive or a CSG tree (its Boolean result is built with
        manifold3d, see :func:`isocsg.csg.surface.surface_from_bands`).
    lights : light or sequence of lights
        Point and directional lights make the bands; area and polyhedron
        lights are ignored.
    material : Material, optional
    contours : int, default 64
    eye : array_like, shape (3,), optional
        Needed only by specular materials (view-dependent bands).
    name : str, keyword-only, default "object"
    color, leaf_colors : keyword-only, optional
        The object's colour and its leaves' (as :class:`~isocsg.SceneObject` takes them): each
        triangle gets its leaf's colour, else the object's (:attr:`ShadedSurface.color`).

    Returns
    -------
    ShadedSurface

    Raises
    ------
    InvalidLightError
        If no point or directional light is given.
    InvalidParameterError
        If ``shape`` is not a solid (a primitive or a CSG tree).
    InvalidGeometryError, ResourceLimitError
        From :func:`isocsg.csg.surface.surface_from_bands`, for a CSG tree
        whose bands do not close or whose surface exceeds the memory budget.

    Examples
    --------
    >>> from isocsg import Box, Cylinder, PointLight
    >>> plate = Box((0, 0, 0), (2, 2, 0.2)) - Cylinder((0, 0, 0), (0, 0, 1), 0.4)
    >>> s = object_surface(plate, [PointLight((2, -3, 4))], contours=8)
    >>> s.triangles.shape[1], bool((s.value >= 0).all()), s.bounds[1].tolist()
    (3, True, [1.0, 1.0, 0.1])
    """
    from ..csg.tree import CSGNode
    from ..laminae import build_laminae

    if not isinstance(shape, Solid):
        raise InvalidParameterError(f"shape must be a solid, got {type(shape).__name__}")
    lights_t = _band_lights(lights)
    mat = Material() if material is None else material
    if isinstance(shape, CSGNode):
        from ..csg.surface import surface_from_bands

        program = shape.program()
        bands = [build_laminae(p, lights_t, mat, contours, eye=eye).bands for p in program.leaves]
        surf = surface_from_bands(program, bands)
        return ShadedSurface(
            np.asarray(surf.vertices, np.float64), np.asarray(surf.triangles, np.int32),
            np.asarray(surf.value, np.float64), name,
            _triangle_colors(shape, color, leaf_colors, np.asarray(surf.leaf)),
        )
    if not isinstance(shape, Primitive):  # a solid of a kind of its own, neither primitive nor tree
        raise InvalidParameterError(f"shape must be a primitive or a CSG tree, got {type(shape).__name__}")
    b = build_laminae(shape, lights_t, mat, contours, eye=eye).bands
    return ShadedSurface(
        np.asarray(b.vertices, np.float64), np.asarray(b.triangles, np.int32), np.asarray(b.value_out, np.float64),
        name, _triangle_colors(shape, color, leaf_colors, np.zeros(len(b.triangles), np.int64)),
    )


def _triangle_colors(shape: Solid, color: Any, leaf_colors: Any, leaf: NDArray[Any]) -> NDArray[np.float64] | None:
    """Each triangle's colour from its leaf's (or the object's), or None when nothing is coloured."""
    from ..rendering.colors import leaf_color_table
    from ..scene.model import SceneObject

    table = leaf_color_table([SceneObject(shape, color=color, leaf_colors=tuple(leaf_colors))])
    return None if table is None else np.asarray(table[0], np.float64)[leaf]


def scene_surfaces(scene: Any, *, contours: int | None = None) -> list[ShadedSurface]:
    """The shaded surface of every object of a scene (seen from its camera's eye).

    Parameters
    ----------
    scene : Scene
    contours : int, optional
        Defaults to ``scene.render.contours``.

    Returns
    -------
    list of ShadedSurface
        One per object, named ``object0``, ``object1``, ...

    Raises
    ------
    InvalidParameterError
        If ``scene`` is not a :class:`~isocsg.scene.Scene`.
    InvalidLightError
        If the scene has no point or directional light.
    """
    from ..scene.model import Scene

    if not isinstance(scene, Scene):
        raise InvalidParameterError(f"scene must be a Scene, got {type(scene).__name__}")
    n = scene.render.contours if contours is None else contours
    lights = _band_lights(scene.lights)
    return [
        object_surface(o.shape, lights, o.material, n, eye=scene.camera.eye, name=f"object{k}", color=o.color,
                       leaf_colors=o.leaf_colors)
        for k, o in enumerate(scene.objects)
    ]


def _as_surfaces(item: Any, *, contours: int | None = None) -> Sequence[ShadedSurface]:
    """A scene, a surface or a list of surfaces as a list of surfaces."""
    if isinstance(item, ShadedSurface):
        return [item]
    if isinstance(item, (list, tuple)):
        for i, s in enumerate(item):
            if not isinstance(s, ShadedSurface):
                raise InvalidParameterError(f"surfaces[{i}] must be a ShadedSurface, got {type(s).__name__}")
        return list(item)
    return scene_surfaces(item, contours=contours)
