"""Membership of the convex hull of balls, with certificates, independent of the library.

``x`` is in the hull of balls ``B(c_k, r_k)`` iff some convex weights ``w`` give
``phi(w) = |x - sum w_k c_k| - sum w_k r_k <= 0`` (then ``x = sum w_k (c_k + r_k v)`` with one
``v``). ``phi`` is convex on the simplex, and by minimax its minimum equals
``max_{|u| = 1} (u . x - h(u))`` with ``h(u) = max_k (c_k . u + r_k)`` the support function. So:

- weights with ``phi(w) <= -eps`` certify ``x`` inside;
- a unit ``u`` with ``u . x - h(u) >= eps`` certifies ``x`` outside (``u`` from the weights'
  residual ``x - sum w c``, and from a dense set of directions);
- neither: too close to the boundary to tell, reported as such.

The weights come from Frank-Wolfe iterations (vectorised over the points).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

F64 = NDArray[np.float64]

__all__ = ["ball_hull_membership", "fibonacci_directions"]


def fibonacci_directions(n: int) -> F64:
    """``n`` nearly uniform unit vectors."""
    k = np.arange(n) + 0.5
    z = 1 - 2 * k / n
    phi = np.pi * (1 + 5**0.5) * k
    s = np.sqrt(1 - z * z)
    return np.column_stack([s * np.cos(phi), s * np.sin(phi), z])


def ball_hull_membership(
    centres: ArrayLike, radii: ArrayLike, xs: ArrayLike, eps: float, iterations: int = 600,
) -> tuple[NDArray[np.bool_], NDArray[np.bool_]]:
    """``(inside, certain)`` for each of ``xs`` (m, 3): ``certain`` where a certificate holds."""
    c = np.asarray(centres, dtype=np.float64)
    r = np.asarray(radii, dtype=np.float64)
    x = np.asarray(xs, dtype=np.float64)
    m, n = len(x), len(r)
    w = np.full((m, n), 1.0 / n)
    best = np.full(m, np.inf)
    for t in range(iterations):
        centre = w @ c
        res = x - centre
        norm = np.linalg.norm(res, axis=1)
        best = np.minimum(best, norm - w @ r)
        unit = res / np.where(norm > 0, norm, 1.0)[:, None]
        grad = -unit @ c.T - r[None, :]  # d phi / d w_k
        vertex = np.argmin(grad, axis=1)
        step = 2.0 / (t + 2.0)
        w *= 1 - step
        w[np.arange(m), vertex] += step
    inside = best <= -eps
    h = lambda u: (u @ c.T + r[None, :]).max(axis=1)  # noqa: E731
    res = x - w @ c
    norm = np.linalg.norm(res, axis=1)
    unit = res / np.where(norm > 0, norm, 1.0)[:, None]
    gap = np.einsum("ij,ij->i", unit, x) - h(unit)
    dirs = fibonacci_directions(4000)
    gap = np.maximum(gap, (x @ dirs.T - (dirs @ c.T + r[None, :]).max(axis=1)[None, :]).max(axis=1))
    outside = gap >= eps
    assert not np.any(inside & outside), "contradictory certificates"
    return inside, inside | outside
