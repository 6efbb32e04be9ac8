"""Lambert's contour integral: illuminance from uniform polygonal sources (seed eq. 7).

For a point p with unit normal n and a polygon q_1..q_m of radiance L seen
from p, the illuminance is

    E = (L / 2) sum_i beta_i (n . g_i),

beta_i the angle between q_i - p and q_{i+1} - p, g_i the unit normal of the
triangle (p, q_i, q_{i+1}). The sum runs over the boundary *edges*, so several
disjoint pieces or pieces with holes are summed edge by edge: outer boundaries
counter-clockwise seen from p, holes clockwise (they subtract).

In this module each edge term is ``beta (n . g)`` with
``g = normalize((q_{i+1} - p) x (q_i - p))``: a boundary that turns
counter-clockwise seen from p gives a positive sum, and ``E = L/2 * sum``.

The formula is valid for the part of the source in front of the receiving
plane (n . (x - p) >= 0); :func:`polygon_illuminance` clips each source by
each point's receiving plane first (the seed's type-B faces).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numba
import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import normalize_rows, points_array, scalar
from ..errors import InvalidGeometryError, InvalidLightError, InvalidParameterError

__all__ = ["edge_terms", "polygon_illuminance", "rings_illuminance"]


def edge_terms(
    points: ArrayLike, normals: ArrayLike, starts: ArrayLike, ends: ArrayLike
) -> NDArray[np.float64]:
    """Per-edge terms ``beta (n . g)`` of Lambert's contour integral (broadcasting).

    Parameters
    ----------
    points, normals : array_like, shape (..., 3)
        Receiving points and their unit normals.
    starts, ends : array_like, shape (..., 3)
        Edge end points, broadcast against ``points``.

    Returns
    -------
    ndarray
        ``beta * (n . g)`` with ``g = normalize((end - p) x (start - p))``;
        an edge through p (or of zero length) gives 0.

    Examples
    --------
    Seen from the origin looking up, +y to +x turns counter-clockwise:

    >>> t = edge_terms([0, 0, 0], [0, 0, 1], [[0, 1, 1], [1, 0, 1]], [[1, 0, 1], [0, -1, 1]])
    >>> bool(np.all(t > 0))
    True
    """
    p = np.asarray(points, dtype=np.float64)
    n = np.asarray(normals, dtype=np.float64)
    a = np.asarray(starts, dtype=np.float64) - p
    b = np.asarray(ends, dtype=np.float64) - p
    c = np.cross(b, a)
    s = np.sqrt(np.einsum("...i,...i->...", c, c))
    d = np.einsum("...i,...i->...", a, b)
    nc = np.einsum("...i,...i->...", n, c)
    beta = np.arctan2(s, d)
    # beta / s -> 1 / d as the edge shrinks to a direction seen from p; s == 0 means n.c == 0.
    with np.errstate(divide="ignore", invalid="ignore"):
        f = np.where(s > 0, beta / np.where(s > 0, s, 1.0), 0.0)
    return f * nc


# Cephes' atan (S. Moshier): a rational function on [0, tan(pi/8)], within 2 ulp of the true value.
_ATAN_P = (-8.750608600031904122785e-1, -1.615753718733365076637e1, -7.500855792314704667340e1,
           -1.228866684490136173410e2, -6.485021904942025371773e1)
_ATAN_Q = (2.485846490142306297962e1, 1.650270098316988542046e2, 4.328810604912902668951e2,
           4.853903996359136964868e2, 1.945506571482613964425e2)
_TAN_PI_8 = 0.41421356237309504880
_PI_4_LO = 3.061616997868382943065e-17  # pi / 4 - float(pi / 4)


@numba.njit(cache=True, inline="always", error_model="numpy")
def atan2_pos(s: float, d: float) -> float:
    """``atan2(s, d)`` for ``s > 0`` (an angle in (0, pi)), without branches: loops over it vectorise.

    The ratio min / max of ``s`` and ``|d|`` lies in [0, 1]; above tan(pi/8) it is
    reduced by atan(x) = pi/4 + atan((x - 1) / (x + 1)); the quadrant follows from the
    comparisons. Within 2 ulp of ``math.atan2`` (libm's is within 1).
    """
    a = abs(d)
    hi = max(s, a)
    x = min(s, a) / (hi if hi > 0.0 else 1.0)  # (no division by zero: callers may raise on it)
    red = x > _TAN_PI_8
    xr = (x - 1.0) / (x + 1.0) if red else x
    z = xr * xr
    p0, p1, p2, p3, p4 = _ATAN_P
    q0, q1, q2, q3, q4 = _ATAN_Q
    z = z * ((((p0 * z + p1) * z + p2) * z + p3) * z + p4) / (((((z + q0) * z + q1) * z + q2) * z + q3) * z + q4)
    r = xr * z + xr
    r = 0.25 * math.pi + (r + _PI_4_LO) if red else r
    r = 0.5 * math.pi - r if s > a else r
    return math.pi - r if d < 0.0 else r


@numba.njit(cache=True, inline="always", error_model="numpy")
def edge_term_fast(px: float, py: float, pz: float, nx: float, ny: float, nz: float,
                   ax: float, ay: float, az: float, bx: float, by: float, bz: float) -> float:
    """:func:`edge_term_nb` with :func:`atan2_pos` and no branch (loops over points vectorise)."""
    ax -= px
    ay -= py
    az -= pz
    bx -= px
    by -= py
    bz -= pz
    cx = by * az - bz * ay
    cy = bz * ax - bx * az
    cz = bx * ay - by * ax
    s = math.sqrt(cx * cx + cy * cy + cz * cz)
    d = ax * bx + ay * by + az * bz
    t = atan2_pos(s, d) / (s if s > 0.0 else 1.0) * (nx * cx + ny * cy + nz * cz)
    return t if s > 0.0 else 0.0


@numba.njit(cache=True, fastmath=False)
def edge_term_nb(px: float, py: float, pz: float, nx: float, ny: float, nz: float,
                 ax: float, ay: float, az: float, bx: float, by: float, bz: float) -> float:
    """Scalar edge term for compiled kernels (same convention as :func:`edge_terms`)."""
    ax -= px
    ay -= py
    az -= pz
    bx -= px
    by -= py
    bz -= pz
    cx = by * az - bz * ay
    cy = bz * ax - bx * az
    cz = bx * ay - by * ax
    s = math.sqrt(cx * cx + cy * cy + cz * cz)
    if s <= 0.0:
        return 0.0
    d = ax * bx + ay * by + az * bz
    return math.atan2(s, d) / s * (nx * cx + ny * cy + nz * cz)


def _prepare(points: ArrayLike, normals: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    p = points_array("points", points, error=InvalidParameterError)
    n = points_array("normals", normals, error=InvalidParameterError)
    if n.shape[0] == 1 and p.shape[0] != 1:
        n = np.broadcast_to(n, p.shape)
    if n.shape != p.shape:
        raise InvalidParameterError(f"normals must have the shape of points {p.shape}, got {n.shape}")
    ln = np.linalg.norm(n, axis=1)
    if np.any(ln <= 1e-300):
        raise InvalidParameterError(f"normals must be non-zero, row {int(np.argmin(ln))} is zero")
    return p, normalize_rows(np.ascontiguousarray(n))


def clipped_polygon_sum(
    p: NDArray[np.float64], n: NDArray[np.float64], q: NDArray[np.float64]
) -> NDArray[np.float64]:
    """Edge sum over polygon ``q`` (m, 3) clipped by each receiving plane (vectorised).

    ``q`` must turn counter-clockwise seen from the points (its lit side).
    The part behind a point's receiving plane is cut off; the closing edge
    along the plane is included. Returns the sums, shape (n,).
    """
    qn = np.roll(q, -1, axis=0)
    d0 = np.einsum("mj,mkj->mk", n, q[None, :, :] - p[:, None, :])  # signed heights above each plane
    d1 = np.roll(d0, -1, axis=1)
    if np.all(d0 >= 0):  # fast path: the whole source is in front of every plane
        return edge_terms(p[:, None, :], n[:, None, :], q[None], qn[None]).sum(axis=1)
    in0, in1 = d0 >= 0, d1 >= 0
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(in0 != in1, d0 / (d0 - d1), 0.0)
    x = q[None] + t[..., None] * (qn - q)[None]  # crossing point on each edge (if any)
    a = np.where(in0[..., None], q[None], x)
    b = np.where(in1[..., None], qn[None], x)
    keep = in0 | in1
    a = np.where(keep[..., None], a, p[:, None, :])
    b = np.where(keep[..., None], b, p[:, None, :])
    total = edge_terms(p[:, None, :], n[:, None, :], a, b).sum(axis=1)
    # Closing edge along the receiving plane: from the exit crossing to the entry crossing.
    exits = in0 & ~in1
    entries = ~in0 & in1
    has = exits.any(axis=1) & entries.any(axis=1)
    rows = np.arange(len(p))
    xe = x[rows, np.argmax(exits, axis=1)]
    xi = x[rows, np.argmax(entries, axis=1)]
    total += np.where(has, edge_terms(p, n, xe, xi), 0.0)
    return total


def polygon_illuminance(
    points: ArrayLike, normals: ArrayLike, vertices: ArrayLike, radiance: float = 1.0
) -> NDArray[np.float64]:
    """Illuminance from a fully visible one-sided convex polygon source.

    Parameters
    ----------
    points, normals : array_like, shape (n, 3)
        Receiving points and normals (normalised here; one normal may serve all).
    vertices : array_like, shape (m, 3)
        A convex planar polygon, counter-clockwise seen from its lit side.
    radiance : float, default 1
        Radiance L of the source.

    Returns
    -------
    ndarray, shape (n,)
        ``E = (L/2) sum beta_i (n . g_i)`` over the part of the source in front
        of each receiving plane; 0 for points on the unlit side of the source.

    Examples
    --------
    A unit square 1 above its corner point, facing it:

    >>> sq = [(0, 0, 1), (0, 1, 1), (1, 1, 1), (1, 0, 1)]
    >>> e = polygon_illuminance([[0, 0, 0]], [[0, 0, 1]], sq)
    >>> round(float(e[0]) / np.pi, 6)  # the form factor of the classical tables
    0.138532
    """
    p, n = _prepare(points, normals)
    q = points_array("vertices", vertices, min_rows=3, error=InvalidLightError)
    L = scalar("radiance", radiance, low=0.0, low_inclusive=True, error=InvalidLightError)
    nn = np.sum(np.cross(q - q.mean(0), np.roll(q, -1, axis=0) - q.mean(0)), axis=0)
    lit = (p - q.mean(0)) @ nn > 0
    out = np.zeros(len(p))
    if np.any(lit):
        out[lit] = 0.5 * L * clipped_polygon_sum(p[lit], n[lit], q)
    return np.maximum(out, 0.0)


def rings_illuminance(
    points: ArrayLike, normals: ArrayLike, rings: Sequence[ArrayLike], radiance: float = 1.0
) -> NDArray[np.float64]:
    """Illuminance from a region given by closed boundary rings (pieces and holes).

    The region must lie in front of every receiving plane. Outer boundaries
    turn counter-clockwise seen from the points, holes clockwise; the edge sums
    of all rings add up (a hole subtracts).

    Parameters
    ----------
    points, normals : array_like, shape (n, 3)
    rings : sequence of array_like, each (k, 3)
        Closed rings (the last vertex connects back to the first).
    radiance : float, default 1

    Returns
    -------
    ndarray, shape (n,)

    Examples
    --------
    A 2 x 2 square with a 1 x 1 hole equals the square minus the hole:

    >>> outer = [(-1, -1, 1), (-1, 1, 1), (1, 1, 1), (1, -1, 1)]
    >>> hole = [(-.5, -.5, 1), (.5, -.5, 1), (.5, .5, 1), (-.5, .5, 1)]
    >>> e = rings_illuminance([[0, 0, 0]], [[0, 0, 1]], [outer, hole])
    >>> full = polygon_illuminance([[0, 0, 0]], [[0, 0, 1]], outer)
    >>> inner = polygon_illuminance([[0, 0, 0]], [[0, 0, 1]], hole[::-1])
    >>> bool(np.isclose(e[0], full[0] - inner[0]))
    True
    """
    p, n = _prepare(points, normals)
    L = scalar("radiance", radiance, low=0.0, low_inclusive=True, error=InvalidLightError)
    total = np.zeros(len(p))
    for i, r in enumerate(rings):
        q = points_array(f"rings[{i}]", r, min_rows=2, error=InvalidGeometryError)
        total += edge_terms(p[:, None, :], n[:, None, :], q[None], np.roll(q, -1, axis=0)[None]).sum(axis=1)
    return 0.5 * L * total
