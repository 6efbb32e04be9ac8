"""The lamina hooks of the built-in kinds (sphere, truncus, box, convex polyhedron).

Registered in :mod:`isocsg.geometry.registry` like any other kind's, and
called by :mod:`isocsg.laminae.builder` through that table:

- ``surface``: the base mesh the isoluminance bands are cut from;
- ``laminae``: the seed's planar contour laminae of one light, each as
  ``(vertices, normal, cosine, role)``;
- ``family``: the plane normal, offsets and levels of one light's contour
  family (what ``LaminaSet.families`` describes).

A curved kind without planar contours (an ellipsoid) registers a surface
only: its bands carry the image.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from ..geometry.primitives import Box, ConvexPolyhedron, Sphere, Truncus
from ..lighting.lights import DirectionalLight, PointLight
from .families import diffuse_levels
from .polyhedron import face_laminae, polyhedron_surface
from .sphere import LONGITUDES, contour_heights, light_axis, sphere_laminae, sphere_surface
from .surface import Surface
from .truncus import GENERATORS, light_frame, paper_levels, truncus_laminae, truncus_surface

__all__ = [
    "sphere_band_surface", "truncus_band_surface", "polyhedron_band_surface",
    "sphere_contour_laminae", "truncus_contour_laminae", "polyhedron_face_laminae",
    "sphere_family", "truncus_family",
]

Light = PointLight | DirectionalLight
Laminae = list[tuple[NDArray[np.float64], NDArray[np.float64], float, str]]
Family = tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]


def sphere_band_surface(
    s: Sphere, lights: list[Light], n: int, eye: NDArray[np.float64] | None, shininess: float,
    weights: tuple[float, float] = (1.0, 1.0), segments: int | None = None,
) -> Surface:
    """Latitude-longitude mesh about the first light's axis, its contour circles as mesh edges
    (``segments`` longitudes, by default ``sphere.LONGITUDES``)."""
    levels = diffuse_levels(np.array([-1.0, 1.0]), n)
    return sphere_surface(s, lights[0] if lights else None, levels, LONGITUDES if segments is None else segments)


def truncus_band_surface(
    t: Truncus, lights: list[Light], n: int, eye: NDArray[np.float64] | None, shininess: float,
    weights: tuple[float, float] = (1.0, 1.0), segments: int | None = None, *, hidden: tuple | None = None,
) -> Surface:
    """Side and end meshes of a truncus (:func:`~isocsg.laminae.truncus.truncus_surface`), with at
    least ``segments`` generators (by default ``truncus.GENERATORS``); ends outside the box
    ``hidden`` (see :func:`~isocsg.laminae.build_bands`) are not refined."""
    seg = GENERATORS if segments is None else segments
    return truncus_surface(t, lights, n, eye=eye, shininess=shininess, weights=weights, segments=seg, hidden=hidden)


def polyhedron_band_surface(
    p: Box | ConvexPolyhedron, lights: list[Light], n: int, eye: NDArray[np.float64] | None, shininess: float,
    weights: tuple[float, float] = (1.0, 1.0), segments: int | None = None,
) -> Surface:
    """Faces (flat: ``segments`` does not apply), subdivided where a point light or a highlight varies across them."""
    return polyhedron_surface(p, lights, n, eye=eye, shininess=shininess, weights=weights)


def sphere_contour_laminae(s: Sphere, light: Light, n: int) -> Laminae:
    """The seed's contour discs."""
    return [(v, nrm, c, "contour") for v, nrm, c in sphere_laminae(s, light, n)]


def truncus_contour_laminae(t: Truncus, light: Light, n: int) -> Laminae:
    """The appendix's quads and end laminae."""
    return truncus_laminae(t, light, n)


def polyhedron_face_laminae(p: Box | ConvexPolyhedron, light: Light, n: int) -> Laminae:
    """One lamina per face."""
    return [(v, nrm, c, "face") for v, nrm, c in face_laminae(p, light)]


def sphere_family(s: Sphere, light: Light, n: int) -> Family:
    """Contour planes across the centre-light axis at the heights of cosines ``k / N``."""
    cos_k = np.arange(n + 1) / n
    c = s.center_array
    w = light_axis(c, light)
    t = contour_heights(s, light, cos_k)
    return w, float(w @ c) + s.radius * t, cos_k


def truncus_family(t: Truncus, light: Light, n: int) -> Family:
    """The quads' planes: cosine-spaced offsets across the axis, the seed's levels."""
    ct = t.center_array
    ln = light.unit_direction if isinstance(light, DirectionalLight) else light_axis(ct, light)
    w, _ = light_frame(t.unit_axis, ln)
    r = max(t.r1, t.r2)
    offsets = float(w @ ct) + np.cos(np.pi * np.arange(n + 1) / n) * r
    return w, offsets, paper_levels(t, light, n)
