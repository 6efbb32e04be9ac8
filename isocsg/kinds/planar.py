"""Plane-section helpers the kinds share: 2D frames, circles and convex polygons of half-spaces.

A plane is given by a 4x4 frame ``F`` (:func:`isocsg.csg.section.plane_frame`): columns
``u, v, n, origin``; a point's 2D coordinates are ``((p - origin) . u, (p - origin) . v)``.
"""

from __future__ import annotations

import math

import numpy as np
import shapely
from numpy.typing import NDArray
from shapely.geometry import Polygon

EMPTY = Polygon()


def to2d(points: NDArray[np.float64], F: NDArray[np.float64]) -> NDArray[np.float64]:
    """Points ``(n, 3)`` in the plane's 2D coordinates."""
    return (points - F[:3, 3]) @ F[:3, :2]


def hull_polygon(pts2: NDArray[np.float64]) -> Polygon:
    """The convex hull of 2D points as a polygon (empty when flat)."""
    if len(pts2) < 3:
        return EMPTY
    hull = shapely.convex_hull(shapely.multipoints(pts2))
    return hull if isinstance(hull, Polygon) and hull.area > 0 else EMPTY


def circle_ring(
    centers: NDArray[np.float64], radii: NDArray[np.float64], resolution: int, area_exact: bool,
) -> NDArray[np.float64]:
    """Rings ``(k, resolution, 2)`` of regular polygons for circles: inscribed, or of the circles' exact areas."""
    ang = np.linspace(0.0, 2.0 * math.pi, resolution, endpoint=False)
    a = 2.0 * math.pi / resolution
    scale = math.sqrt(a / math.sin(a)) if area_exact else 1.0
    r = (radii * scale)[:, None]
    return np.stack([centers[:, 0:1] + r * np.cos(ang), centers[:, 1:2] + r * np.sin(ang)], axis=-1)


def halfspace_section(
    normals: NDArray[np.float64], offsets: NDArray[np.float64], verts: NDArray[np.float64], F: NDArray[np.float64]
) -> Polygon:
    """Exact convex polygon {x in plane : normals @ x <= offsets} by Sutherland-Hodgman clipping."""
    o, u, v = F[:3, 3], F[:3, 0], F[:3, 1]
    A = np.column_stack([normals @ u, normals @ v])
    b = offsets - normals @ o
    scale = float(np.max(np.ptp(verts, axis=0)))
    eps = 1e-12 * max(scale, 1e-300)
    v2 = to2d(verts, F)
    lo, hi = v2.min(axis=0) - 0.01 * scale - 1.0, v2.max(axis=0) + 0.01 * scale + 1.0
    poly = np.array([[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]])
    for a_k, b_k in zip(A, b):
        if np.hypot(*a_k) <= 1e-12:
            # face parallel to the plane: all or nothing (the face plane itself counts as inside)
            if b_k < -eps:
                return EMPTY
            continue
        val = poly @ a_k - b_k  # <= 0 inside
        inside = val <= 0.0
        if inside.all():
            continue
        if not inside.any():
            return EMPTY
        nxt_val = np.roll(val, -1)
        nxt = np.roll(poly, -1, axis=0)
        out = []
        for p, q, vp, vq, ip in zip(poly, nxt, val, nxt_val, inside):
            if ip:
                out.append(p)
            if (vp <= 0.0) != (vq <= 0.0):
                t = vp / (vp - vq)
                out.append(p + t * (q - p))
        poly = np.asarray(out)
        if len(poly) < 3:
            return EMPTY
    g = Polygon(poly)
    return g if g.area > 0 else EMPTY


def refined_parameters(curve, lo: float, hi: float, m: int, angle: float) -> NDArray[np.float64]:
    """Parameters ``2 k + 1`` of ``k >= m`` curve segments (ends and midpoints) on ``[lo, hi]``.

    A segment is halved while its two halves turn by more than ``angle`` / 2
    or its midpoint falls off the middle of its chord (the parametrisation
    is far from uniform there: plane cuts of a cone near its asymptotes).
    """
    ph = np.linspace(lo, hi, 2 * m + 1)
    for _ in range(40):
        P = curve(ph)
        p0, pm, p1 = P[0:-1:2], P[1::2], P[2::2]
        d0, d1, ch = pm - p0, p1 - pm, p1 - p0
        l0, l1 = np.linalg.norm(d0, axis=1), np.linalg.norm(d1, axis=1)
        cos = np.einsum("ij,ij->i", d0, d1) / np.maximum(l0 * l1, 1e-300)
        ll = np.einsum("ij,ij->i", ch, ch)
        t = np.einsum("ij,ij->i", pm - p0, ch) / np.maximum(ll, 1e-300)
        size = max(float(np.max(ll)), 1e-300) ** 0.5
        bad = ((cos < math.cos(0.75 * angle)) | (np.abs(t - 0.5) > 0.1)) & (np.sqrt(ll) > 1e-9 * size)
        if not bad.any():
            break
        a, c = ph[0:-1:2][bad], ph[2::2][bad]
        q = (c - a) / 4
        ph = np.sort(np.concatenate([ph, a + q, a + 3 * q]))
    return ph


def simpson_points(P: NDArray[np.float64], closed: bool) -> NDArray[np.float64]:
    """Curve samples with every odd sample pushed away from its chord by a third of its sagitta.

    The polygon through them has the area of the curve up to O(h^5) per
    segment of length h (the parabolic segment is 4/3 of its triangle).
    """
    P = P.copy()
    if closed:
        prev, nxt = np.roll(P, 1, axis=0)[1::2], np.roll(P, -1, axis=0)[1::2]
    else:
        prev, nxt = P[0:-1:2], P[2::2]
    mid = 0.5 * (prev + nxt)
    P[1::2] = mid + (4.0 / 3.0) * (P[1::2] - mid)
    return P
