"""Solids of revolution about the z axis, built exactly from the pieces of a profile.

A profile lies in the half-plane ``x >= 0`` of the (x, y) plane, ``x`` the distance from
the z axis and ``y`` the height (OpenSCAD's ``rotate_extrude``). Revolving is a bijection
of the open half-plane ``x > 0`` onto space minus the axis, so it distributes over union,
intersection and difference: the revolution of a 2D CSG tree is the 3D tree of the same
Booleans over revolved leaves (``isocsg.shapes2d.revolve`` builds that tree). This module
revolves the leaves, given as plain numbers:

- a convex polygon: ``{x <= x_out(y)} - {x < x_in(y)}``, where ``x_out`` (the right chain)
  is concave and ``x_in`` (the left chain) convex and piecewise linear. Each solid
  ``{rho <= f(z)}`` is the union of the frusta (:class:`~isocsg.Truncus`, a cone where a
  radius is 0) over the segments of its chain, stacked without overlap; the inner one is
  prolonged by cylinders above and below the polygon so that the difference never cuts
  along a coincident end face (outside the outer solid, the prolongation removes nothing);
- a disc of centre ``(c, h)`` and radius ``r``: a :class:`~isocsg.Torus` when ``c > r``, a
  :class:`~isocsg.Sphere` when ``c == 0`` (the half of the disc with ``x >= 0``); a disc that
  meets the axis elsewhere revolves into a spindle or horn torus, which is refused;
- an ellipse centred on the axis with axes along x and y: a spheroid
  (:class:`~isocsg.Ellipsoid`); other ellipses are refused;
- a partial angle: the solid cut by a convex wedge (intersected with the wedge when the
  angle is at most 180 degrees, else minus the wedge of the missing angle);
- OpenSCAD's faceted revolution (``segments`` flat sections): a section between the
  meridian planes at angles ``a`` and ``b`` maps ``(x, y, t)`` to ``x((1 - t) u_a + t u_b) +
  y e_z``, linear in ``(x (1 - t), x t, y)``, so the section of a convex polygon is the
  convex hull of the polygon placed at ``a`` and at ``b`` (a :class:`~isocsg.ConvexPolyhedron`),
  and the section of a circle or ellipse is an elliptic cylinder (the affine image of a
  :class:`~isocsg.Cylinder`) along ``alpha - beta`` cut by the wedge ``alpha, beta >= 0``.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._validation import length_floor
from ..errors import InvalidGeometryError
from ..kinds import ConvexPolyhedron, Ellipsoid, Solid, Sphere, Torus, Truncus
from .tree import Difference, Intersection, Union

__all__ = [
    "clip_to_right_half",
    "revolved_polygon",
    "revolved_disc",
    "revolved_ellipse",
    "faceted_polygon",
    "faceted_round",
    "cut_to_angle",
    "sector_angles",
]

#: Relative height below which a chain segment is treated as horizontal (no frustum).
FLAT_RTOL = 1e-12


def clip_to_right_half(vertices: NDArray[np.float64]) -> NDArray[np.float64] | None:
    """The convex polygon (counter-clockwise ``(n, 2)``) cut to ``x >= 0``; None when nothing of area remains."""
    p = np.asarray(vertices, dtype=np.float64)
    if np.all(p[:, 0] >= 0.0):
        return p
    if np.all(p[:, 0] <= 0.0):
        return None
    out: list[tuple[float, float]] = []
    n = len(p)
    for i in range(n):
        a, b = p[i], p[(i + 1) % n]
        if a[0] >= 0.0:
            out.append((float(a[0]), float(a[1])))
        if (a[0] < 0.0) != (b[0] < 0.0) and a[0] != 0.0 and b[0] != 0.0:
            t = a[0] / (a[0] - b[0])
            out.append((0.0, float(a[1] + t * (b[1] - a[1]))))
    q = np.array(out)
    if len(q) < 3:
        return None
    c = q - q[0]
    area = 0.5 * float(np.sum(c[:-1, 0] * c[1:, 1] - c[:-1, 1] * c[1:, 0]))
    size = float(np.max(np.ptp(q, axis=0)))
    return q if area > 1e-12 * size * size else None


def _chains(p: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The right and the left chains of a convex counter-clockwise polygon, each from bottom to top."""
    n = len(p)
    y = p[:, 1]
    ylo, yhi = y.min(), y.max()
    low = np.flatnonzero(y == ylo)
    start = int(low[np.argmax(p[low, 0])])  # bottom-right vertex
    order = [(start + k) % n for k in range(n + 1)]
    right = [order[0]]
    k = 1
    while y[order[k - 1]] != yhi:
        right.append(order[k])
        k += 1
    while y[order[k]] == yhi and k < n:  # along a horizontal top edge, to the top-left vertex
        k += 1
    left = [order[k - 1]]
    while True:
        left.append(order[k])
        if y[order[k]] == ylo:
            break
        k += 1
    return p[right], p[left[::-1]]


def _radius(r: float, z: float) -> float:
    """A radius, with rounding noise next to the axis (below the smallest length there) snapped to 0."""
    return 0.0 if r < length_floor((r, 0.0, z)) else float(r)


def _frusta(chain: NDArray[np.float64], tol: float) -> list[Solid]:
    """``{rho <= f(z)}`` for the piecewise linear ``f`` through ``chain`` (bottom to top): stacked frusta."""
    out: list[Solid] = []
    for (x0, y0), (x1, y1) in zip(chain[:-1], chain[1:], strict=True):
        if y1 - y0 <= tol:
            continue
        r_bottom, r_top = _radius(x0, y0), _radius(x1, y1)
        if r_bottom == 0.0 and r_top == 0.0:
            continue
        try:
            out.append(Truncus((0.0, 0.0, 0.5 * (y0 + y1)), (0.0, 0.0, y1 - y0), r_top, r_bottom))
        except InvalidGeometryError as exc:  # a slab far thinner than its radius (the frusta's aspect limit)
            raise InvalidGeometryError(
                f"rotate_extrude.shape: the slab between the vertex heights {y0:g} and {y1:g} at radius "
                f"{max(x0, x1):g} cannot be a frustum ({exc})"
            ) from None
    return out


def _union(parts: list[Solid]) -> Solid | None:
    return None if not parts else parts[0] if len(parts) == 1 else Union(tuple(parts))


def revolved_polygon(vertices: Any) -> Solid | None:
    """The full revolution about the z axis of a convex polygon in ``x >= 0``.

    Parameters
    ----------
    vertices : array_like, shape (n, 2)
        Counter-clockwise, convex, every ``x >= 0`` (see :func:`clip_to_right_half`).

    Returns
    -------
    Solid or None
        The union of the outer frusta minus the union of the inner ones (None: no volume).
    """
    p = np.asarray(vertices, dtype=np.float64)
    if np.any(p[:, 0] < 0.0):
        raise InvalidGeometryError("rotate_extrude: a revolved polygon must lie in x >= 0")
    height = float(np.ptp(p[:, 1]))
    tol = FLAT_RTOL * max(height, float(np.max(np.abs(p))))
    if height <= tol:
        return None
    right, left = _chains(p)
    outer = _union(_frusta(right, tol))
    if outer is None:
        return None
    inner_parts = _frusta(left, tol)
    ext = 0.25 * height  # prolong the inner solid past the ends: no coincident end faces
    for (x, y), (x_end, _), sign in ((left[0], right[0], -1.0), (left[-1], right[-1], 1.0)):
        r = _radius(x, y)
        if 0.0 < r and x < x_end:  # a flat end (not a corner) at radius > 0
            inner_parts.append(Truncus((0.0, 0.0, y + sign * ext / 2), (0.0, 0.0, ext), r, r))
    inner = _union(inner_parts)
    return outer if inner is None else Difference((outer, inner))


def revolved_disc(center: tuple[float, float], radius: float) -> Solid | None:
    """The revolution of the part with ``x >= 0`` of a disc: a torus, a sphere, or None (nothing there).

    Raises
    ------
    InvalidGeometryError
        When the disc meets the axis off its centre (a spindle, horn or lemon-shaped solid).
    """
    c, h = float(center[0]), float(center[1])
    r = float(radius)
    if c + r <= 0.0:
        return None
    if c == 0.0:
        return Sphere((0.0, 0.0, h), r)
    if c > r:
        return Torus((0.0, 0.0, h), (0.0, 0.0, 1.0), c, r)
    raise InvalidGeometryError(
        f"rotate_extrude: a circle of centre x = {c:g} and radius {r:g} meets the axis off its centre "
        "(its revolution is a spindle or horn torus, not supported); only circles clear of the axis "
        "(x > r) or centred on it (x = 0) revolve exactly"
    )


def revolved_ellipse(center: tuple[float, float], matrix: Any) -> Solid | None:
    """The revolution of an ellipse centred on the axis with axes along x and y: a spheroid.

    Raises
    ------
    InvalidGeometryError
        For any other ellipse that reaches ``x > 0`` (its revolution is no isocsg kind).
    """
    c, h = float(center[0]), float(center[1])
    m = np.asarray(matrix, dtype=np.float64)
    g = m @ m.T  # the ellipse is {c + v : v^T g^-1 v <= 1}
    hx, hy = math.sqrt(g[0, 0]), math.sqrt(g[1, 1])
    if c + hx <= 0.0:
        return None
    if c == 0.0 and abs(g[0, 1]) <= 1e-12 * (g[0, 0] + g[1, 1]):
        return Ellipsoid((0.0, 0.0, h), (hx, hx, hy))
    raise InvalidGeometryError(
        "rotate_extrude: an ellipse revolves exactly only when centred on the axis with axes along x and y "
        f"(a spheroid), got centre x = {c:g}; scale the circle in 3D after revolving instead"
    )


def sector_angles(start: float, angle: float, segments: int) -> NDArray[np.float64]:
    """The ``segments + 1`` meridian angles (radians) of a revolution from ``start`` by ``angle`` (degrees)."""
    return np.radians(start + angle * np.arange(segments + 1) / segments)


def faceted_polygon(vertices: Any, angles: NDArray[np.float64]) -> Solid | None:
    """OpenSCAD's faceted revolution of a convex polygon in ``x >= 0``: one convex hull per section.

    Parameters
    ----------
    vertices : array_like, shape (n, 2)
        Counter-clockwise, convex, every ``x >= 0``.
    angles : ndarray, shape (k + 1,)
        The meridian angles (radians) bounding the ``k`` sections.
    """
    p = np.asarray(vertices, dtype=np.float64)
    pieces: list[Solid] = []
    for a, b in zip(angles[:-1], angles[1:], strict=True):
        if abs(math.sin(b - a)) < 1e-12:
            continue  # a flat section of exactly 180 degrees: no volume
        ends = [np.column_stack([p[:, 0] * math.cos(t), p[:, 0] * math.sin(t), p[:, 1]]) for t in (a, b)]
        pts = np.unique(np.round(np.vstack(ends), 15), axis=0)
        pieces.append(ConvexPolyhedron(pts))  # type: ignore[arg-type]  # any (n, 3) array-like
    return _union(pieces)


def faceted_round(center: tuple[float, float], matrix: Any, angles: NDArray[np.float64]) -> Solid | None:
    """OpenSCAD's faceted revolution of the part with ``x >= 0`` of the ellipse ``center + M u``
    (``|u| <= 1``; a circle is ``M = r I``): per section, an elliptic cylinder cut by the section's wedge.

    In the section's coordinates ``(alpha, beta, y)`` (a point is ``alpha u_a + beta u_b + y e_z``)
    the solid is ``{alpha, beta >= 0, (alpha + beta, y) in the ellipse}``: a cylinder along
    ``alpha - beta`` over the ellipse, cut by ``alpha >= 0`` and ``beta >= 0`` (the wedge, which
    also keeps only ``x = alpha + beta >= 0``).
    """
    from ..kinds import Cylinder

    c, h = float(center[0]), float(center[1])
    m = np.asarray(matrix, dtype=np.float64)
    hx, hy = float(np.hypot(m[0, 0], m[0, 1])), float(np.hypot(m[1, 0], m[1, 1]))
    if c + hx <= 0.0:
        return None
    reach = c + hx
    span = 2.02 * reach  # the cylinder's length along alpha - beta covers |alpha - beta| <= alpha + beta <= reach
    unit = Cylinder((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), 1.0)
    pieces: list[Solid] = []
    for a, b in zip(angles[:-1], angles[1:], strict=True):
        if abs(math.sin(b - a)) < 1e-12:
            continue
        ua = np.array([math.cos(a), math.sin(a), 0.0])
        ub = np.array([math.cos(b), math.sin(b), 0.0])
        # (p, q, s) of the unit cylinder -> x = c + M0.(p, q), y = h + M1.(p, q), alpha - beta = span s
        to_xy = np.column_stack([ua + ub, [0.0, 0.0, 2.0], ua - ub]) / 2.0  # (x, y, alpha - beta) -> world
        A = to_xy @ np.array([[m[0, 0], m[0, 1], 0.0], [m[1, 0], m[1, 1], 0.0], [0.0, 0.0, span]])
        t = to_xy @ np.array([c, h, 0.0])
        tube = unit.transform(np.column_stack([A, t]))
        d = (b - a) % (2 * math.pi)  # the section is the short sector between u_a and u_b (as the hull's)
        lo, sweep = (a, d) if d <= math.pi else (b, 2 * math.pi - d)
        wedge = _wedge(lo, sweep, 1.05 * reach + 0.05 * hy, h - 1.1 * hy, h + 1.1 * hy)
        pieces.append(Intersection((tube, wedge)))
    return _union(pieces)


def _wedge(start: float, span: float, radius: float, zlo: float, zhi: float) -> ConvexPolyhedron:
    """The convex wedge between the meridian half-planes at ``start`` and ``start + span`` (radians,
    ``span <= pi``), reaching beyond ``radius`` and ``[zlo, zhi]``."""
    k = 4
    reach = radius / math.cos(span / (2 * k))  # the polygon's edges stay outside the circle
    phi = start + span * np.arange(k + 1) / k
    ring = np.vstack([np.zeros((1, 2)), reach * np.column_stack([np.cos(phi), np.sin(phi)])])
    verts = np.vstack([np.column_stack([ring, np.full(len(ring), z)]) for z in (zlo, zhi)])
    return ConvexPolyhedron(verts)  # type: ignore[arg-type]


def cut_to_angle(solid: Solid, start: float, angle: float, radius: float, zlo: float, zhi: float) -> Solid:
    """``solid`` (a full revolution within ``radius`` of the axis and ``[zlo, zhi]``) kept between
    the meridian angles ``start`` and ``start + angle`` (degrees, ``0 < |angle| < 360``)."""
    lo = start + min(angle, 0.0)
    span = abs(angle)
    margin = 0.05 * max(radius, zhi - zlo)
    r, z0, z1 = 1.05 * radius + margin, zlo - margin, zhi + margin
    if span <= 180.0:
        return Intersection((solid, _wedge(math.radians(lo), math.radians(span), r, z0, z1)))
    rest = 360.0 - span
    return Difference((solid, _wedge(math.radians(lo + span), math.radians(rest), r, z0, z1)))
