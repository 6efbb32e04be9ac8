"""The base surface mesh a primitive's bands are cut from.

Vertices lie exactly on the primitive's surface and carry its exact outward
normal (so the shading fields are exact at every vertex); triangles are
counter-clockwise seen from outside. Each primitive module builds one with
its contour lines for the first light already on mesh edges.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..lighting.lights import PointLight

__all__ = ["Surface", "orient_outward", "light_reference_distance", "refinement"]


@dataclass(frozen=True, slots=True, eq=False)
class Surface:
    """A triangle mesh with exact per-vertex normals.

    Attributes
    ----------
    vertices, normals : ndarray, shape (V, 3)
    triangles : ndarray, shape (T, 3), int64
    """

    vertices: NDArray[np.float64]
    normals: NDArray[np.float64]
    triangles: NDArray[np.int64]


def orient_outward(vertices: NDArray[np.float64], normals: NDArray[np.float64], triangles: NDArray[np.int64]) -> NDArray[np.int64]:
    """Reorder triangle corners so that each is counter-clockwise about its vertex normals.

    Degenerate (zero-area) triangles are left as they are.
    """
    t = np.asarray(triangles, dtype=np.int64).copy()
    a, b, c = vertices[t[:, 0]], vertices[t[:, 1]], vertices[t[:, 2]]
    g = np.cross(b - a, c - a)
    s = np.einsum("ij,ij->i", g, normals[t[:, 0]] + normals[t[:, 1]] + normals[t[:, 2]])
    flip = s < 0
    t[flip, 1], t[flip, 2] = t[flip, 2].copy(), t[flip, 1].copy()
    return t


def light_reference_distance(lights: object, center: NDArray[np.float64], radius: float) -> float:
    """Smallest distance from a point light to the bounding sphere (``inf`` with no point light).

    The primitive modules refine their meshes where a light this close makes
    the incidence angle vary across a face or along a generator.
    """
    d = np.inf
    for light in lights:  # type: ignore[attr-defined]
        if isinstance(light, PointLight):
            gap = float(np.linalg.norm(np.asarray(light.position) - center)) - radius
            d = min(d, max(gap, 0.05 * radius))
    return d


def refinement(size: float, distance: float, per_distance: float = 16.0, cap: int = 48) -> int:
    """Subdivisions of a length ``size`` lit from ``distance``: about ``per_distance`` per unit of distance."""
    if not np.isfinite(distance):
        return 1
    return int(np.clip(np.ceil(per_distance * size / distance), 1, cap))
