"""Convex solids as intersections of half-spaces ``n . x <= d``: rays and tangent cones
(shared by the polyhedral kinds, :mod:`~isocsg.kinds.box` and :mod:`~isocsg.kinds.polyhedron`)."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from .base import RayHits, TangentCone

__all__ = ["polyhedral_tangent", "ray_halfspaces"]


def ray_halfspaces(
    o: NDArray[np.float64], d: NDArray[np.float64], normals: NDArray[np.float64], offsets: NDArray[np.float64]
) -> RayHits:
    """Clip rays against the convex solid {x : normals @ x <= offsets}."""
    num = offsets[None, :] - o @ normals.T  # (n, k): >= 0 where the origin is inside plane k
    den = d @ normals.T
    with np.errstate(divide="ignore", invalid="ignore"):
        t = num / den
    entering = den < 0
    leaving = den > 0
    t_enter = np.where(entering, t, -np.inf)
    t_leave = np.where(leaving, t, np.inf)
    i_in = np.argmax(t_enter, axis=1)
    i_out = np.argmin(t_leave, axis=1)
    rows = np.arange(len(o))
    t_in = t_enter[rows, i_in]
    t_out = t_leave[rows, i_out]
    parallel_out = np.any((den == 0) & (num < 0), axis=1)
    miss = parallel_out | (t_in > t_out) | ~np.isfinite(t_in) | ~np.isfinite(t_out)
    n_in = np.where(miss[:, None], 0.0, normals[i_in])
    n_out = np.where(miss[:, None], 0.0, normals[i_out])
    return RayHits(np.where(miss, np.inf, t_in), np.where(miss, -np.inf, t_out), n_in, n_out)


def polyhedral_tangent(
    normals: NDArray[np.float64], offsets: NDArray[np.float64], p: NDArray[np.float64], tol: float
) -> TangentCone:
    """The tangent cone of a convex polyhedron (or box) at points: its faces within ``tol``."""
    m = len(p)
    dist = p @ normals.T - offsets
    valid = np.abs(dist) <= tol
    V = np.broadcast_to(normals, (m, len(normals), 3))
    return V, np.zeros((m, len(normals))), valid
