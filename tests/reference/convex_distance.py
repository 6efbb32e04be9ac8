"""Distances to convex hulls and volumes of grown polytopes, independent of the library.

- :func:`hull_distance`: the distance from points to the hull of a point set, as the smallest
  ``|P^T lam - x|`` over convex weights ``lam`` (non-negative least squares with the weights'
  sum held at 1 by a heavily weighted row);
- :func:`slice_distance`: the same within the plane through ``x`` across an axis (an extra
  weighted row holds the height), the distance that decides membership of a disc-grown hull;
- :func:`ball_grown_volume`: Steiner's formula ``V + S r + M r^2 + 4/3 pi r^3`` from scipy's hull
  (``M`` the sum over edges of length times the angle between the faces' normals, over 2);
- :func:`disc_grown_volume`: ``V + r sum_f A_f |n_f x a| + pi r^2 (extent along a)``, the
  integral over heights of the 2D Steiner formula (a slice's perimeter grows each face's area
  by the sine of its normal's angle to the axis).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import nnls
from scipy.spatial import ConvexHull

F64 = NDArray[np.float64]

__all__ = ["hull_distance", "slice_distance", "ball_grown_volume", "disc_grown_volume"]


def _constrained_distance(points: F64, x: F64, rows: list[tuple[F64, float]]) -> float:
    scale = float(np.ptp(points, axis=0).max()) + float(np.abs(x).max()) + 1.0
    w = 1e4
    a = np.vstack([points.T] + [w * r[None, :] for r, _ in rows])
    b = np.concatenate([x, [w * v for _, v in rows]])
    lam, _ = nnls(a / scale, b / scale, maxiter=50 * len(points))
    return float(np.linalg.norm(points.T @ lam - x))


def hull_distance(points: ArrayLike, xs: ArrayLike) -> F64:
    """Distance from each of ``xs`` (m, 3) to the hull of ``points`` (n, 3)."""
    p = np.asarray(points, dtype=np.float64)
    ones = np.ones(len(p))
    return np.array([_constrained_distance(p, x, [(ones, 1.0)]) for x in np.asarray(xs, dtype=np.float64)])


def slice_distance(points: ArrayLike, axis: ArrayLike, xs: ArrayLike) -> F64:
    """Distance from each of ``xs`` to the hull of ``points`` within the plane through it across ``axis``
    (inf when the plane misses the hull)."""
    p = np.asarray(points, dtype=np.float64)
    a = np.asarray(axis, dtype=np.float64) / np.linalg.norm(axis)
    heights = p @ a
    out = []
    for x in np.asarray(xs, dtype=np.float64):
        h = float(x @ a)
        if h < heights.min() or h > heights.max():
            out.append(math.inf)
            continue
        out.append(_constrained_distance(p, x, [(np.ones(len(p)), 1.0), (heights, h)]))
    return np.array(out)


def _faces(points: F64) -> tuple[ConvexHull, F64, F64]:
    hull = ConvexHull(points)
    tri = points[hull.simplices]
    areas = np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1) / 2
    return hull, areas, hull.equations[:, :3]


def ball_grown_volume(points: ArrayLike, r: float) -> float:
    """Volume of the hull of ``points`` (full-dimensional) grown by a ball of radius ``r``."""
    p = np.asarray(points, dtype=np.float64)
    hull, areas, normals = _faces(p)
    edges: dict[tuple[int, int], list[int]] = {}
    for k, s in enumerate(hull.simplices):
        for i in range(3):
            key = tuple(sorted((int(s[i]), int(s[(i + 1) % 3]))))
            edges.setdefault(key, []).append(k)  # type: ignore[arg-type]
    mean_width_term = 0.0
    for (i, j), (f, g) in edges.items():
        angle = math.acos(float(np.clip(normals[f] @ normals[g], -1.0, 1.0)))
        mean_width_term += float(np.linalg.norm(p[i] - p[j])) * angle / 2
    return float(hull.volume + areas.sum() * r + mean_width_term * r * r + 4 / 3 * math.pi * r**3)


def disc_grown_volume(points: ArrayLike, axis: ArrayLike, r: float) -> float:
    """Volume of the hull of ``points`` (full-dimensional) grown by the disc of radius ``r`` across ``axis``."""
    p = np.asarray(points, dtype=np.float64)
    a = np.asarray(axis, dtype=np.float64) / np.linalg.norm(axis)
    hull, areas, normals = _faces(p)
    sines = np.linalg.norm(np.cross(normals, a), axis=1)
    return float(hull.volume + r * float(areas @ sines) + math.pi * r * r * float(np.ptp(p @ a)))
