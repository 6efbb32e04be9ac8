"""The reference caster's own ray-torus intervals, written independently of the library.

The library solves the ray's quartic (companion matrix, Newton polish); this module never forms
it. It marches along each ray on the exact distance ``sqrt((rho - R)^2 + z^2) - r`` (sphere
tracing: the distance is 1-Lipschitz, so a step of its size never crosses the surface), from
where the ray enters the torus's bounding sphere of radius ``R + r`` to where it leaves it, with
steps of at least ``MIN_STEP`` of the tube radius, and bisects every sign change to the last bit.
Intervals shorter than that smallest step, at grazing incidence, may be missed.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numba import njit
from numpy.typing import NDArray

__all__ = ["MIN_STEP", "torus_intervals", "torus_trace"]

F64 = NDArray[np.float64]

#: The smallest step of the sphere tracing, relative to the tube radius.
MIN_STEP = 1e-6


@njit(cache=True)
def torus_trace(o, d, c, w, R, r, out):  # pragma: no cover - compiled
    """Sphere tracing + bisection of unit rays against a torus: ``out[i, k]`` = [t_in, t_out]."""
    n = o.shape[0]
    for i in range(n):
        q0 = o[i, 0] - c[0]
        q1 = o[i, 1] - c[1]
        q2 = o[i, 2] - c[2]
        d0, d1, d2 = d[i, 0], d[i, 1], d[i, 2]
        b = q0 * d0 + q1 * d1 + q2 * d2
        big = R + r
        # the chord of the bounding sphere from the ray's point nearest the centre (no
        # cancellation for far origins), padded by a little
        n0, n1, n2 = q0 - b * d0, q1 - b * d1, q2 - b * d2
        disc = big * big - (n0 * n0 + n1 * n1 + n2 * n2)
        if disc < 0:
            continue
        sq = np.sqrt(disc) + 1e-9 * big
        ta, tb = -b - sq, -b + sq
        h = MIN_STEP * r
        t = ta
        f = _sd(q0 + t * d0, q1 + t * d1, q2 + t * d2, w, R, r)
        inside = f < 0
        count = 0
        start = 0.0
        if inside:
            start = t
        while t < tb and count < 2:
            t1 = min(t + max(abs(f), h), tb)
            f1 = _sd(q0 + t1 * d0, q1 + t1 * d1, q2 + t1 * d2, w, R, r)
            if (f1 < 0) != inside:
                lo, hi = t, t1
                for _ in range(200):  # bisection to the last bit
                    m = 0.5 * (lo + hi)
                    if m <= lo or m >= hi:
                        break
                    fm = _sd(q0 + m * d0, q1 + m * d1, q2 + m * d2, w, R, r)
                    if (fm < 0) == inside:
                        lo = m
                    else:
                        hi = m
                root = 0.5 * (lo + hi)
                if inside:
                    out[i, count, 0] = start
                    out[i, count, 1] = root
                    count += 1
                else:
                    start = root
                inside = not inside
            t, f = t1, f1
        if inside and count < 2:
            out[i, count, 0] = start
            out[i, count, 1] = tb


@njit(cache=True)
def _sd(x, y, z, w, R, r):  # pragma: no cover - compiled
    h = x * w[0] + y * w[1] + z * w[2]
    px, py, pz = x - h * w[0], y - h * w[1], z - h * w[2]
    rho = np.sqrt(px * px + py * py + pz * pz)
    return np.sqrt((rho - R) ** 2 + h * h) - r


def torus_intervals(torus: Any, origins: Any, directions: Any) -> F64:
    """Up to two depth intervals ``(n, 2, 2)`` (NaN for none) of rays in a torus, by the module's
    own sphere tracing on the exact distance (``t`` in units of each direction's length)."""
    o = np.atleast_2d(np.asarray(origins, dtype=np.float64))
    d = np.atleast_2d(np.asarray(directions, dtype=np.float64))
    o = np.ascontiguousarray(np.broadcast_to(o, d.shape)) if len(o) == 1 else np.ascontiguousarray(o)
    ln = np.linalg.norm(d, axis=1)
    du = np.ascontiguousarray(d / ln[:, None])
    w = np.asarray(torus.axis, dtype=np.float64)
    w = w / np.linalg.norm(w)
    out = np.full((len(o), 2, 2), np.nan)
    torus_trace(o, du, np.asarray(torus.center, dtype=np.float64), w, float(torus.major), float(torus.minor), out)
    return out / ln[:, None, None]
