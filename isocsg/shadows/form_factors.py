"""Form factors between a point and a polygon, and between two polygons.

The form factor from a surface element dA at x (unit normal n) to a polygon P
is the illuminance that P would give at x if it were a Lambertian source of
unit exitance (radiance 1 / pi): ``F(x -> P) = E(x) / (pi L)``. So
:func:`point_form_factor` is Lambert's contour integral over the part of P
that x sees, occluders included, with exactly the machinery of the direct
light (:func:`~isocsg.shadows.direct.illuminance`).

Between two convex polygons with nothing in between, the form factor follows
from Stokes' theorem as a double contour integral (Sparrow 1963; Schroder and
Hanrahan 1993, "On the form factor between two polygons"):

    A_i F_ij = (1 / 2 pi) sum_{edges a of i} sum_{edges b of j} (e_a . e_b) I_ab,
    I_ab = integral over a, integral over b of ln |x_a - x_b| ds dt

(both contours counter-clockwise about their polygon's normal; the sign below
is fixed by that orientation). Only the part of each polygon in front of the
other's plane exchanges light, so both are clipped by the other's plane first
(the integrand's cosines are then positive everywhere and the formula holds).

- Parallel edges (collinear ones included): I_ab is elementary,
  ``g2(s1 - t0) - g2(s0 - t0) - g2(s1 - t1) + g2(s0 - t1)`` with ``g2`` the
  second antiderivative of ``ln sqrt(x^2 + d^2)`` (Schroder and Hanrahan's
  closed form for that case). Every pair of edges of two axis-aligned
  rectangles is parallel or perpendicular (``e_a . e_b = 0``), so the factors
  of Howell's rectangle cases are closed forms here.
- Edges at an angle (sine >= ``CLOSED_FORM_MIN_SIN`` = 0.1): closed form
  (Schroder and Hanrahan's case with dilogarithms, derived here in a form
  that needs Li2 only on the closed unit disc). Measured from the lines'
  closest points (distance d), r^2 = d^2 + u^2 + v^2 - 2 c u v; the map
  x = u - c v, y = v sin turns the edges' parameter rectangle into a
  parallelogram, and the integral of ln sqrt(d^2 + x^2 + y^2) over it is a
  sum over its four edges of signed triangles from the origin. On each, in
  polar coordinates about the foot of the perpendicular (distance p), the
  radial integral is elementary and the angular one is
  ``2 phi ln(p + q) - Im Li2(-k e^(2 i phi)) + Im Li2(-e^(2 i phi))`` with
  ``q = sqrt(p^2 + d^2)``, ``k = (q - p) / (q + p)`` (|k| <= 1, so Li2's
  argument never leaves the unit disc: no branch cuts). Li2 is a compiled
  Bernoulli series in ``-ln(1 - z)`` after the reflection z -> 1 - z when
  Re z > 1/2. Touching and crossing edges (d = 0) need no special case.
- Edges nearly parallel (PARALLEL_TOL <= sine < 0.1): the closed form's
  coordinates grow like 1 / sine^2 and lose digits, so there the inner
  integral over b is closed-form (``g1``) and the outer one over a is
  Gauss-Legendre on intervals graded geometrically towards the point of a
  closest to b's line (the integrand's logarithmic kink), about 1e-13.
  Closed form and quadrature agree to 1e-11 of ``la lb max(1, |ln r|)`` on
  edge pairs at every angle (``tests/test_form_factors_closed.py`` checks the
  closed form against scipy's adaptive ``dblquad`` and symmetry values).
- Each polygon is clipped exactly (no tolerance) by the other's plane; a
  polygon with no vertex more than ``tol`` in front of the other's plane
  gives 0 (this drops coplanar pairs).
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Sequence

import numba
import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import points_array
from ..errors import InvalidGeometryError
from ..kinds import DEFAULT_RESOLUTION, Solid

__all__ = ["point_form_factor", "polygon_form_factor", "pair_form_factors", "PARALLEL_TOL", "CLOSED_FORM_MIN_SIN"]

#: Two edges are treated as parallel when the sine of their angle is below this.
PARALLEL_TOL = 1e-9
#: Non-parallel edges use the dilogarithm closed form when the sine of their angle is at least this
#: (below it, graded quadrature of the closed-form inner integral; see the module docstring).
CLOSED_FORM_MIN_SIN = 0.1

# Gauss-Legendre nodes and weights on [0, 1] for the graded outer quadrature.
_GL_X, _GL_W = np.polynomial.legendre.leggauss(16)
_GL_X = 0.5 * (_GL_X + 1.0)
_GL_W = 0.5 * _GL_W
_GRADE = 0.3  # ratio of successive intervals towards the kink
_LEVELS = 28  # 0.3^28 ~ 2e-15 of the interval: below rounding


@numba.njit(cache=True)
def _g1(x: float, d: float) -> float:
    """Antiderivative in x of ln sqrt(x^2 + d^2)."""
    r2 = x * x + d * d
    if r2 <= 0.0:
        return 0.0
    out = 0.5 * x * math.log(r2) - x
    if d > 0.0:
        out += d * math.atan(x / d)
    return out


@numba.njit(cache=True)
def _g2(x: float, d: float) -> float:
    """Antiderivative in x of :func:`_g1`."""
    r2 = x * x + d * d
    if r2 <= 0.0:
        return 0.0
    out = 0.25 * r2 * math.log(r2) - 0.25 * r2 - 0.5 * x * x - 0.5 * d * d * math.log(r2)
    if d > 0.0:
        out += d * x * math.atan(x / d)
    return out


# Bernoulli numbers B_n / (n + 1)! for n = 0, 1, 2, 4, 6, ... (the odd ones past B_1 vanish).
_BERN = [1 / 6, -1 / 30, 1 / 42, -1 / 30, 5 / 66, -691 / 2730, 7 / 6, -3617 / 510, 43867 / 798, -174611 / 330,
         854513 / 138, -236364091 / 2730, 8553103 / 6, -23749461029 / 870, 8615841276005 / 14322]
_LI2_EVEN = np.array([b / math.factorial(2 * k + 3) for k, b in enumerate(_BERN)])


@numba.njit(cache=True)
def _li2_series(z: complex) -> complex:
    """Li2(z) for |z| <= 1, Re z <= 1/2: the Bernoulli series in u = -ln(1 - z) (|u| < 1.8 < 2 pi)."""
    u = -cmath.log(1.0 - z)
    u2 = u * u
    out = u - 0.25 * u2
    term = u * u2  # u^(2k+3)
    for k in range(_LI2_EVEN.shape[0]):
        out += _LI2_EVEN[k] * term
        term *= u2
    return out


@numba.njit(cache=True)
def _li2(z: complex) -> complex:
    """The dilogarithm for |z| <= 1 (the arguments of :func:`_edge_antiderivative`)."""
    if z.real <= 0.5:
        return _li2_series(z)
    if z == 1.0:
        return math.pi * math.pi / 6.0
    return math.pi * math.pi / 6.0 - cmath.log(z) * cmath.log(1.0 - z) - _li2_series(1.0 - z)


@numba.njit(cache=True)
def _edge_antiderivative(p: float, t: float, d: float) -> float:
    """Antiderivative in t of the integral of ln sqrt(d^2 + rho^2) over the triangle (origin, foot, foot + t e).

    The triangle's edge lies at distance p > 0 from the origin; in polar
    coordinates (phi from the foot of the perpendicular, w = tan phi) the
    radial integral is elementary and the angular one gives
    ``int ln(d^2 + p^2 sec^2 phi) dphi = 2 phi ln(p + q) - Im Li2(-k e^(2 i phi)) + Im Li2(-e^(2 i phi))``
    with ``q = sqrt(p^2 + d^2)``, ``k = (q - p) / (q + p)``.
    """
    phi = math.atan2(t, p)
    q = math.sqrt(p * p + d * d)
    out = 0.25 * (p * t * math.log(q * q + t * t) - 3.0 * p * t + 2.0 * p * q * math.atan2(t, q))
    if d > 0.0:
        e2 = cmath.exp(2j * phi)
        k = (q - p) / (q + p)
        ang = 2.0 * phi * math.log(p + q) - _li2(-k * e2).imag + _li2(-e2).imag
        out += 0.25 * d * d * (ang - 2.0 * math.log(d) * phi)
    return out


@numba.njit(cache=True)
def _skew_closed(w0: np.ndarray, ea: np.ndarray, la: float, eb: np.ndarray, lb: float, dot: float,
                 cx: float, cy: float, cz: float, sin: float) -> float:
    """Integral of ln |a0 + s ea - b0 - t eb| over s in [0, la], t in [0, lb], for non-parallel unit ea, eb.

    With u, v measured from the lines' closest points (distance d), r^2 =
    d^2 + u^2 + v^2 - 2 c u v; the map x = u - c v, y = v sin takes the
    rectangle of (u, v) to a parallelogram P (Jacobian sin), and the
    integral of ln sqrt(d^2 + x^2 + y^2) over P is a sum over its edges of
    signed triangles from the origin (:func:`_edge_antiderivative`).
    """
    dd = ea[0] * w0[0] + ea[1] * w0[1] + ea[2] * w0[2]
    ee = eb[0] * w0[0] + eb[1] * w0[1] + eb[2] * w0[2]
    s2 = sin * sin
    s_ = (dot * ee - dd) / s2
    t_ = ee + dot * s_
    d = abs(w0[0] * cx + w0[1] * cy + w0[2] * cz)  # (cx, cy, cz): the unit common normal
    u0, u1 = -s_, la - s_
    v0, v1 = -t_, lb - t_
    px = np.array([u0 - dot * v0, u1 - dot * v0, u1 - dot * v1, u0 - dot * v1])
    py = np.array([sin * v0, sin * v0, sin * v1, sin * v1])
    total = 0.0
    for k in range(4):
        k1 = (k + 1) % 4
        ex = px[k1] - px[k]
        ey = py[k1] - py[k]
        ln = math.sqrt(ex * ex + ey * ey)
        if ln == 0.0:  # an edge far shorter than its distance to the other line (a clipping sliver)
            continue
        ex /= ln
        ey /= ln
        ps = px[k] * ey - py[k] * ex  # signed distance of the edge's line from the origin
        if ps == 0.0:
            continue
        t1 = px[k] * ex + py[k] * ey
        sg = 1.0 if ps > 0.0 else -1.0
        total += sg * (_edge_antiderivative(abs(ps), t1 + ln, d) - _edge_antiderivative(abs(ps), t1, d))
    # (u, v) -> (x, y) keeps the orientation (its determinant is sin > 0) and the rectangle is counter-clockwise
    return total / sin


@numba.njit(cache=True)
def _inner(a0: np.ndarray, ea: np.ndarray, s: float, b0: np.ndarray, eb: np.ndarray, lb: float) -> float:
    """Integral over t in [0, lb] of ln |a0 + s ea - b0 - t eb| (closed form)."""
    wx = a0[0] + s * ea[0] - b0[0]
    wy = a0[1] + s * ea[1] - b0[1]
    wz = a0[2] + s * ea[2] - b0[2]
    c = wx * eb[0] + wy * eb[1] + wz * eb[2]
    # distance to b's line from the cross product (no cancellation near the line)
    cx = wy * eb[2] - wz * eb[1]
    cy = wz * eb[0] - wx * eb[2]
    cz = wx * eb[1] - wy * eb[0]
    h = math.sqrt(cx * cx + cy * cy + cz * cz)
    return _g1(lb - c, h) - _g1(-c, h)


@numba.njit(cache=True)
def _graded(a0: np.ndarray, ea: np.ndarray, lo: float, hi: float, toward_lo: bool,
            b0: np.ndarray, eb: np.ndarray, lb: float, gx: np.ndarray, gw: np.ndarray) -> float:
    """Integral of :func:`_inner` over s in [lo, hi], intervals shrinking towards one end."""
    length = hi - lo
    if length <= 0.0:
        return 0.0
    total = 0.0
    outer = 1.0
    for lev in range(_LEVELS + 1):
        inner = outer * _GRADE if lev < _LEVELS else 0.0
        for k in range(gx.shape[0]):
            u = inner + (outer - inner) * gx[k]
            s = lo + u * length if toward_lo else hi - u * length
            total += gw[k] * (outer - inner) * length * _inner(a0, ea, s, b0, eb, lb)
        outer = inner
    return total


@numba.njit(cache=True)
def _edge_pair(a0: np.ndarray, a1: np.ndarray, b0: np.ndarray, b1: np.ndarray,
               gx: np.ndarray, gw: np.ndarray, closed: bool = True) -> float:
    """(e_a . e_b) times the integral of ln r over two segments (``closed=False``: quadrature at every angle)."""
    ea = a1 - a0
    eb = b1 - b0
    la = math.sqrt(ea[0] ** 2 + ea[1] ** 2 + ea[2] ** 2)
    lb = math.sqrt(eb[0] ** 2 + eb[1] ** 2 + eb[2] ** 2)
    if la <= 0.0 or lb <= 0.0:
        return 0.0
    ea = ea / la
    eb = eb / lb
    dot = ea[0] * eb[0] + ea[1] * eb[1] + ea[2] * eb[2]
    cx = ea[1] * eb[2] - ea[2] * eb[1]
    cy = ea[2] * eb[0] - ea[0] * eb[2]
    cz = ea[0] * eb[1] - ea[1] * eb[0]
    sin = math.sqrt(cx * cx + cy * cy + cz * cz)
    if abs(dot) < 1e-15:
        return 0.0
    if sin < PARALLEL_TOL:
        sg = 1.0 if dot > 0.0 else -1.0
        w = b0 - a0
        o = w[0] * ea[0] + w[1] * ea[1] + w[2] * ea[2]
        # distance between the lines from the cross product (no cancellation when they nearly meet)
        px = w[1] * ea[2] - w[2] * ea[1]
        py = w[2] * ea[0] - w[0] * ea[2]
        pz = w[0] * ea[1] - w[1] * ea[0]
        d = math.sqrt(px * px + py * py + pz * pz)
        t0 = min(o, o + sg * lb)
        t1 = max(o, o + sg * lb)
        val = _g2(la - t0, d) - _g2(-t0, d) - _g2(la - t1, d) + _g2(-t1, d)
        return sg * val
    if sin >= CLOSED_FORM_MIN_SIN and closed:
        w0 = a0 - b0
        return dot * _skew_closed(w0, ea, la, eb, lb, dot, cx / sin, cy / sin, cz / sin, sin)
    # Kinks of the integrand in s: where a(s) is closest to b's line, and where a(s)
    # projects onto b's end points (they matter when the edges nearly touch).
    w = a0 - b0
    d_ = ea[0] * w[0] + ea[1] * w[1] + ea[2] * w[2]
    e_ = eb[0] * w[0] + eb[1] * w[1] + eb[2] * w[2]
    den = 1.0 - dot * dot
    cuts = np.empty(5)
    cuts[0] = 0.0
    cuts[1] = la
    m = 2
    if den > 1e-12:
        cuts[m] = (dot * e_ - d_) / den
        m += 1
    cuts[m] = -e_ / dot
    cuts[m + 1] = (lb - e_) / dot
    m += 2
    cuts = np.sort(cuts[:m])
    val = 0.0
    for k in range(m - 1):
        lo = min(max(cuts[k], 0.0), la)
        hi = min(max(cuts[k + 1], 0.0), la)
        if hi > lo:
            mid = 0.5 * (lo + hi)
            val += _graded(a0, ea, lo, mid, True, b0, eb, lb, gx, gw)
            val += _graded(a0, ea, mid, hi, False, b0, eb, lb, gx, gw)
    return dot * val


@numba.njit(cache=True)
def _clip_plane(P: np.ndarray, n: int, nx: float, ny: float, nz: float, off: float, out: np.ndarray) -> int:
    """Part of polygon P[:n] with n . x >= off (Sutherland-Hodgman); returns the vertex count."""
    m = 0
    if n == 0:
        return 0
    prev = n - 1
    dp = P[prev, 0] * nx + P[prev, 1] * ny + P[prev, 2] * nz - off
    for k in range(n):
        dk = P[k, 0] * nx + P[k, 1] * ny + P[k, 2] * nz - off
        if dk >= 0.0:
            if dp < 0.0:
                t = dp / (dp - dk)
                out[m] = P[prev] + t * (P[k] - P[prev])
                m += 1
            out[m] = P[k]
            m += 1
        elif dp >= 0.0:
            t = dp / (dp - dk)
            out[m] = P[prev] + t * (P[k] - P[prev])
            m += 1
        prev = k
        dp = dk
    return m


@numba.njit(cache=True)
def _front_extent(P: np.ndarray, n: int, N: np.ndarray, off: float) -> float:
    """Largest signed distance of P[:n]'s vertices in front of the plane N . x = off."""
    out = -math.inf
    for k in range(n):
        out = max(out, N[0] * P[k, 0] + N[1] * P[k, 1] + N[2] * P[k, 2] - off)
    return out


@numba.njit(cache=True)
def _pair(P: np.ndarray, np_: int, NP: np.ndarray, AP: float, Q: np.ndarray, nq: int, NQ: np.ndarray,
          tol: float, gx: np.ndarray, gw: np.ndarray) -> float:
    """F from convex polygon P (unit normal NP, area AP) to Q: both clipped by the other's plane."""
    offq = NQ[0] * Q[0, 0] + NQ[1] * Q[0, 1] + NQ[2] * Q[0, 2]
    offp = NP[0] * P[0, 0] + NP[1] * P[0, 1] + NP[2] * P[0, 2]
    # A polygon with no vertex clearly in front of the other's plane exchanges nothing with it (this
    # also drops coplanar pairs, for which the contour formula does not hold). The clip itself is
    # exact: clipping at a tolerance would shave a sliver off a shared edge, where the kernel's
    # logarithm makes F change by about tol ln(tol) (3e-11 for tol 1e-12).
    if _front_extent(P, np_, NQ, offq) <= tol or _front_extent(Q, nq, NP, offp) <= tol:
        return 0.0
    Pc = np.empty((np_ + 1, 3))
    Qc = np.empty((nq + 1, 3))
    mp = _clip_plane(P, np_, NQ[0], NQ[1], NQ[2], offq, Pc)
    mq = _clip_plane(Q, nq, NP[0], NP[1], NP[2], offp, Qc)
    if mp < 3 or mq < 3:
        return 0.0
    total = 0.0
    for a in range(mp):
        a1 = a + 1 if a + 1 < mp else 0
        for b in range(mq):
            b1 = b + 1 if b + 1 < mq else 0
            total += _edge_pair(Pc[a], Pc[a1], Qc[b], Qc[b1], gx, gw)
    return max(total / (2.0 * math.pi * AP), 0.0)


@numba.njit(cache=True, nogil=True)
def _pairs_kernel(verts: np.ndarray, off: np.ndarray, normal: np.ndarray, area: np.ndarray, tol: np.ndarray,
                  pi: np.ndarray, pj: np.ndarray, gx: np.ndarray, gw: np.ndarray, out: np.ndarray) -> None:
    for k in range(pi.shape[0]):
        i = pi[k]
        j = pj[k]
        out[k] = _pair(verts[off[i]:off[i + 1]], off[i + 1] - off[i], normal[i], area[i],
                       verts[off[j]:off[j + 1]], off[j + 1] - off[j], normal[j], max(tol[i], tol[j]), gx, gw)


def _polygon(name: str, value: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64], float]:
    q = points_array(name, value, min_rows=3, error=InvalidGeometryError)
    c = q.mean(axis=0)
    nn = 0.5 * np.sum(np.cross(q - c, np.roll(q, -1, axis=0) - c), axis=0)
    a = float(np.linalg.norm(nn))
    size = float(np.max(np.ptp(q, axis=0)))
    if not a > 1e-12 * size * size:
        raise InvalidGeometryError(f"{name} must be a polygon of non-zero area, got area {a:g}")
    n = nn / a
    if np.max(np.abs((q - c) @ n)) > 1e-9 * size:
        raise InvalidGeometryError(f"{name} must be planar")
    return np.ascontiguousarray(q), n, a


def pair_form_factors(
    verts: NDArray[np.float64], off: NDArray[np.int64], normals: NDArray[np.float64], areas: NDArray[np.float64],
    pi: NDArray[np.int64], pj: NDArray[np.int64],
) -> NDArray[np.float64]:
    """Unoccluded form factors F(i -> j) for many pairs of packed convex polygons (compiled).

    ``verts[off[k]:off[k+1]]`` is polygon k, counter-clockwise about its unit
    normal ``normals[k]``, of area ``areas[k]``; returns ``F(pi[m] -> pj[m])``.
    """
    out = np.zeros(len(pi))
    if len(pi) == 0:
        return out
    span = np.max(np.maximum.reduceat(np.abs(verts), off[:-1], axis=0), axis=1)
    _pairs_kernel(np.ascontiguousarray(verts), np.ascontiguousarray(off, dtype=np.int64),
                  np.ascontiguousarray(normals), np.ascontiguousarray(areas), 1e-12 * span,
                  np.ascontiguousarray(pi, dtype=np.int64), np.ascontiguousarray(pj, dtype=np.int64),
                  _GL_X, _GL_W, out)
    return out


def polygon_form_factor(source: ArrayLike, target: ArrayLike) -> float:
    """Form factor from a convex polygon to another, with nothing in between.

    Parameters
    ----------
    source, target : array_like, shape (m, 3)
        Convex planar polygons, counter-clockwise seen from the side that
        emits (``source``) or receives (``target``).

    Returns
    -------
    float
        ``F = (1 / A_s) int_s int_t cos cos / (pi r^2) dA dA``: the fraction of
        the light leaving ``source`` (Lambertian) that reaches ``target``; only
        the parts of each polygon in front of the other count. Reciprocity:
        ``A_s F(s -> t) = A_t F(t -> s)``.

    Raises
    ------
    InvalidGeometryError
        If a polygon is malformed, degenerate or not planar.

    Examples
    --------
    Two unit squares facing each other at distance 1 (Howell's C-11: 0.19982):

    >>> lo = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    >>> hi = [(0, 0, 1), (0, 1, 1), (1, 1, 1), (1, 0, 1)]
    >>> round(polygon_form_factor(lo, hi), 5)
    0.19982
    """
    p, npl, ap = _polygon("source", source)
    q, nq, aq = _polygon("target", target)
    verts = np.vstack([p, q])
    off = np.array([0, len(p), len(p) + len(q)], dtype=np.int64)
    f = pair_form_factors(verts, off, np.stack([npl, nq]), np.array([ap, aq]), np.array([0]), np.array([1]))
    return float(f[0])


def point_form_factor(
    points: ArrayLike,
    normals: ArrayLike,
    polygon: ArrayLike,
    occluders: Sequence[Solid] | Solid = (),
    *,
    resolution: int = DEFAULT_RESOLUTION,
) -> NDArray[np.float64]:
    """Form factor from surface elements at points to a polygon, occluders included.

    Parameters
    ----------
    points, normals : array_like, shape (n, 3)
        Receiving elements (normals normalised here; one may serve all).
    polygon : array_like, shape (m, 3)
        A convex planar polygon, counter-clockwise seen from the side that
        faces the points (only that side counts).
    occluders : Solid or sequence of Solid, optional
        As for :func:`~isocsg.shadows.direct.illuminance`.
    resolution : int, keyword-only
        Tessellation of curved occluders.

    Returns
    -------
    ndarray, shape (n,)
        ``F(dA -> P)``, the illuminance from P at unit radiance over pi: the
        same contour integral over the visible part of P as the direct light.

    Examples
    --------
    A unit square 1 above its corner point, facing it (the classical 0.138532):

    >>> sq = [(0, 0, 1), (0, 1, 1), (1, 1, 1), (1, 0, 1)]
    >>> round(float(point_form_factor([[0, 0, 0]], [[0, 0, 1]], sq)[0]), 6)
    0.138532
    """
    from ..lighting.area import AreaLight
    from .direct import illuminance

    q, _, _ = _polygon("polygon", polygon)
    return illuminance(points, normals, [AreaLight(q, radiance=1.0)], occluders, resolution=resolution) / math.pi
