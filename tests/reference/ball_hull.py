"""Membership of the convex hull of balls, with certificates, independent of the library.

The hull ``H`` of balls ``B(c_k, r_k)`` (``r_k >= 0``) has the support function
``h(u) = max_k (c_k . u + r_k)``. Two one-sided certificates:

- **inside**: ``x`` inside the convex hull (scipy's Qhull) of points *on* the spheres (every
  ball's sphere sampled, plus the centres) by at least ``eps``: those points are in ``H``, so
  their hull is too;
- **outside**: a unit ``u`` (from a dense set of directions) with ``u . x - h(u) >= eps``: the
  plane ``u . y = h(u)`` separates ``x`` from ``H``.

A point with neither is too close to the boundary to tell (the sampling's gap, a few thousandths
of the radius), and reported so.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.spatial import ConvexHull, QhullError

F64 = NDArray[np.float64]

__all__ = ["ball_hull_membership", "disc_hull_membership", "fibonacci_directions"]


def fibonacci_directions(n: int) -> F64:
    """``n`` nearly uniform unit vectors."""
    k = np.arange(n) + 0.5
    z = 1 - 2 * k / n
    phi = np.pi * (1 + 5**0.5) * k
    s = np.sqrt(1 - z * z)
    return np.column_stack([s * np.cos(phi), s * np.sin(phi), z])


def ball_hull_membership(
    centres: ArrayLike, radii: ArrayLike, xs: ArrayLike, eps: float, samples: int = 1200, directions: int = 6000,
) -> tuple[NDArray[np.bool_], NDArray[np.bool_]]:
    """``(inside, certain)`` for each of ``xs`` (m, 3): ``certain`` where a certificate holds."""
    c = np.asarray(centres, dtype=np.float64).reshape(-1, 3)
    r = np.asarray(radii, dtype=np.float64).reshape(-1)
    x = np.asarray(xs, dtype=np.float64).reshape(-1, 3)
    sphere = fibonacci_directions(samples)
    on = np.vstack([c] + [ck + rk * sphere for ck, rk in zip(c, r) if rk > 0])
    try:
        inner = ConvexHull(on)
        inside = (x @ inner.equations[:, :3].T + inner.equations[:, 3]).max(axis=1) <= -eps
    except QhullError:  # flat: no interior to certify (only corners on a plane)
        inside = np.zeros(len(x), dtype=bool)
    dirs = fibonacci_directions(directions)
    support = (dirs @ c.T + r[None, :]).max(axis=1)
    gap = np.full(len(x), -np.inf)
    for start in range(0, len(x), 256):
        block = x[start:start + 256]
        gap[start:start + 256] = (block @ dirs.T - support[None, :]).max(axis=1)
    outside = gap >= eps
    assert not np.any(inside & outside), "contradictory certificates"
    return inside, inside | outside


def disc_hull_membership(
    centres: ArrayLike, radii: ArrayLike, axis: ArrayLike, xs: ArrayLike, eps: float,
    samples: int = 720, directions: int = 6000,
) -> tuple[NDArray[np.bool_], NDArray[np.bool_]]:
    """The same certificates for the hull of discs across the unit ``axis`` (radius 0: a point):
    inside the hull of points sampled on the rims, or beyond a support plane, the support of a
    disc being ``p . u + r |u - (u . a) a|``."""
    c = np.asarray(centres, dtype=np.float64).reshape(-1, 3)
    r = np.asarray(radii, dtype=np.float64).reshape(-1)
    a = np.asarray(axis, dtype=np.float64) / np.linalg.norm(axis)
    x = np.asarray(xs, dtype=np.float64).reshape(-1, 3)
    helper = np.eye(3)[int(np.argmin(np.abs(a)))]
    u = np.cross(a, helper)
    u /= np.linalg.norm(u)
    v = np.cross(a, u)
    angle = 2 * np.pi * np.arange(samples) / samples
    ring = np.outer(np.cos(angle), u) + np.outer(np.sin(angle), v)
    on = np.vstack([c] + [ck + rk * ring for ck, rk in zip(c, r) if rk > 0])
    try:
        inner = ConvexHull(on)
        inside = (x @ inner.equations[:, :3].T + inner.equations[:, 3]).max(axis=1) <= -eps
    except QhullError:
        inside = np.zeros(len(x), dtype=bool)
    dirs = fibonacci_directions(directions)
    across = np.linalg.norm(dirs - np.outer(dirs @ a, a), axis=1)
    support = (dirs @ c.T + np.outer(across, r)).max(axis=1)
    gap = np.full(len(x), -np.inf)
    for start in range(0, len(x), 256):
        block = x[start:start + 256]
        gap[start:start + 256] = (block @ dirs.T - support[None, :]).max(axis=1)
    outside = gap >= eps
    assert not np.any(inside & outside), "contradictory certificates"
    return inside, inside | outside
