"""Exact plane sections of solids by horizontal planes, as 2D shapes: ``projection(cut = true)``.

Sections commute with the Booleans, so the section of a tree is the same 2D tree over its
leaves' sections, each exact: a sphere or an ellipsoid cuts into a circle or an ellipse, a
cylinder into an ellipse clipped by its end lines, a cone or frustum into an ellipse (a plane
steeper than its sides: a parabola or hyperbola, polygonised), a convex polyhedron into a convex
polygon, a torus about z into an annulus, a mesh into its exact polygons. A face lying in the
plane counts, as OpenSCAD's closed intersection with the plane keeps it: the section is the union
of the limits from just above and just below the plane, each evaluated leaf by leaf.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..csg import CSGNode, Difference, Intersection
from ..csg.tree import distinct_postorder
from ..errors import InvalidGeometryError
from ..kinds import Solid
from ..kinds.forms import AffineBall, AffineFrustum, PointHull, RingTorus, TriangleSurface
from .leaves import Circle, ConvexPolygon
from .region import shape_from_region
from .shape import EMPTY, Shape2D, difference2d, intersection2d, union2d

__all__ = ["section_at", "leaf_section_at", "CURVE_RESOLUTION"]

#: Resolution (segments per turn) of the few curves that are no leaf of a 2D shape (conics of a
#: cone cut steeper than its sides, tori off the z axis): inscribed polygons, chord error
#: ``r (1 - cos(pi / n))`` = 1.2e-6 r.
CURVE_RESOLUTION = 2048

_EPS = 1e-12


# --------------------------------------------------------------------------- tree walks


def _children(s: Any) -> tuple[Any, ...] | None:
    return tuple(s.children) if isinstance(s, CSGNode) else None


def _op(s: Any) -> str:
    return "difference" if isinstance(s, Difference) else "intersection" if isinstance(s, Intersection) else "union"


def _leaves(solid: Any) -> list[Any]:
    from ..csg.tree import leaves

    return list(leaves(solid))


def _combine(op: str, shapes: list[Shape2D]) -> Shape2D:
    if op == "union":
        kept = [s for s in shapes if s is not EMPTY]
        return union2d(*kept) if kept else EMPTY
    if op == "intersection":
        return EMPTY if any(s is EMPTY for s in shapes) else intersection2d(*shapes)
    if shapes[0] is EMPTY:
        return EMPTY
    rest = [s for s in shapes[1:] if s is not EMPTY]
    return difference2d(shapes[0], *rest) if rest else shapes[0]


def _fold(solid: Any, leaf_value: Any) -> Shape2D:
    """The 2D tree of ``solid`` over ``leaf_value(leaf)`` (explicit stack; shared subtrees once)."""
    done: dict[int, Shape2D] = {}
    for s in distinct_postorder(solid):
        kids = _children(s)
        done[id(s)] = leaf_value(s) if kids is None else _combine(_op(s), [done[id(c)] for c in kids])
    return done[id(solid)]


# --------------------------------------------------------------------------- sections


def section_at(solid: Solid, z: float = 0.0) -> Shape2D:
    """The exact section of ``solid`` by the plane at height ``z``, as a 2D shape in x and y.

    A face lying in the plane is part of the section (the closed solid meets the plane there), as
    in OpenSCAD's ``projection(cut = true)``.

    Examples
    --------
    >>> from isocsg import Box
    >>> from isocsg.shapes2d import area
    >>> area(section_at(Box((0, 0, 1), (2, 2, 2)), 0.0))  # the bottom face
    4.0
    """
    z = float(z)
    if not math.isfinite(z):
        raise InvalidGeometryError(f"section_at.z must be finite, got {z}")
    sides: dict[int, int] = {}
    for leaf in _leaves(solid):
        lo, hi = np.asarray(leaf.bounds, dtype=np.float64)[:, 2]
        eps = _EPS * max(hi - lo, abs(lo), abs(hi), abs(z), 1.0)
        sides[id(leaf)] = 1 if lo >= z - eps else -1 if hi <= z + eps else 0
    cache: dict[int, Shape2D] = {}

    def leaf_section(leaf: Any) -> Shape2D:
        if id(leaf) not in cache:
            cache[id(leaf)] = leaf_section_at(leaf, z)
        return cache[id(leaf)]

    touching = [k for k, s in sides.items() if s != 0]
    if not touching:
        return _fold(solid, leaf_section)
    # The limits from just above (+1) and just below (-1): a leaf on the other side is absent.
    parts = [_fold(solid, lambda leaf, s=s: EMPTY if sides[id(leaf)] == -s else leaf_section(leaf)) for s in (1, -1)]
    return _combine("union", parts)


def leaf_section_at(leaf: Any, z: float) -> Shape2D:
    """The exact section of one primitive by the plane at height ``z`` (faces in the plane count),
    from its :meth:`~isocsg.kinds.base.Primitive.exact_form`; a kind without one is polygonised
    from its own ``section``."""
    form = leaf.exact_form()
    if isinstance(form, PointHull):
        return _polytope_section(form.vertices, form.edges, z)
    if isinstance(form, AffineBall):
        return _ball_section(form.center, form.linear, z)
    if isinstance(form, AffineFrustum):
        return _frustum_section(leaf, form.center, form.matrix, form.r1, form.r2, z)
    if isinstance(form, RingTorus):
        return _torus_section(leaf, form, z)
    if isinstance(form, TriangleSurface):
        from ..kinds.mesh_section import mesh_section

        return shape_from_region(mesh_section(form.vertices, form.faces, _frame(z)))
    return _polygonised_section(leaf, z)


def _frame(z: float) -> NDArray[np.float64]:
    F = np.eye(4)
    F[2, 3] = z
    return F


def _polygonised_section(leaf: Any, z: float) -> Shape2D:
    return shape_from_region(leaf.section(_frame(z), CURVE_RESOLUTION, False))


def _convex(points: NDArray[np.float64]) -> Shape2D:
    """The convex polygon of points (EMPTY when flat)."""
    import shapely

    if len(points) < 3:
        return EMPTY
    hull = shapely.convex_hull(shapely.multipoints(points))
    if hull.geom_type != "Polygon":
        return EMPTY
    ring = np.asarray(shapely.orient_polygons(hull).exterior.coords)[:-1]
    try:
        return ConvexPolygon(tuple(map(tuple, ring.tolist())))
    except InvalidGeometryError:
        return EMPTY  # no area (an edge or a point of the solid in the plane)


def _polytope_section(V: NDArray[np.float64], E: NDArray[np.int64], z: float) -> Shape2D:
    """A convex polytope's section: the hull of its vertices in the plane and its edges' crossings."""
    h = V[:, 2] - z
    eps = _EPS * max(float(np.ptp(V, axis=0).max()), float(np.abs(V).max()), 1.0)
    on = np.abs(h) <= eps
    a, b = h[E[:, 0]], h[E[:, 1]]
    cross = ((a > eps) & (b < -eps)) | ((a < -eps) & (b > eps))
    e = E[cross]
    t = (h[e[:, 0]] / (h[e[:, 0]] - h[e[:, 1]]))[:, None]
    pts = np.vstack([V[on, :2], V[e[:, 0], :2] + t * (V[e[:, 1], :2] - V[e[:, 0], :2])])
    return _convex(pts)


def _ellipse(center: NDArray[np.float64], L: NDArray[np.float64]) -> Shape2D:
    """The exact ellipse ``center + L u`` (|u| <= 1): a :class:`Circle` when L is a similarity."""
    try:
        return Circle((0.0, 0.0), 1.0)._affine(L, center)
    except InvalidGeometryError:
        return EMPTY  # flat (a point or a segment)


def _ball_section(c: NDArray[np.float64], M: NDArray[np.float64], z: float) -> Shape2D:
    """The section of the ellipsoid ``c + M u`` (|u| <= 1): the disc of the unit ball's plane
    ``m . u = z - c_z`` (m = M's last row), mapped by M."""
    m = M[2]
    norm = float(np.linalg.norm(m))
    d = (z - c[2]) / norm
    if abs(d) >= 1.0:
        return EMPTY
    n = m / norm
    e1 = np.cross(n, [1.0, 0.0, 0.0] if abs(n[0]) < 0.9 else [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    rho = math.sqrt(1.0 - d * d)
    center = c[:2] + M[:2] @ (d * n)
    return _ellipse(center, rho * (M[:2] @ np.column_stack([e1, e2])))


def _half_planes(shape: Shape2D, lines: list[tuple[NDArray[np.float64], float]]) -> Shape2D:
    """``shape`` cut by the half-planes ``g . p <= h`` (each an exact convex polygon around its box)."""
    if shape is EMPTY or not lines:
        return shape
    from .measure import bounds

    x0, y0, x1, y1 = bounds(shape)
    pad = max(x1 - x0, y1 - y0)
    box = np.array([[x0 - pad, y0 - pad], [x1 + pad, y0 - pad], [x1 + pad, y1 + pad], [x0 - pad, y1 + pad]])
    import shapely

    region = shapely.Polygon(box)
    cut = False
    for g, h in lines:
        vals = box @ g - h
        if np.all(vals <= 0):
            continue
        cut = True
        big = 4 * pad * (1 + float(np.abs(box).max()))
        d = g / np.linalg.norm(g)
        p0 = d * (h / np.linalg.norm(g))
        w = np.array([-d[1], d[0]])
        half = shapely.Polygon([p0 + big * w, p0 - big * w, p0 - big * w - big * d, p0 + big * w - big * d])
        region = region.intersection(half)
    if not cut:
        return shape
    if region.is_empty or region.area <= 0:
        return EMPTY
    return _combine("intersection", [shape, _convex(np.asarray(region.exterior.coords)[:-1])])


def _frustum_section(leaf: Any, c: NDArray[np.float64], M: NDArray[np.float64], r1: float, r2: float,
                     z: float) -> Shape2D:
    """The section of the frustum ``c + M (x, y, t)`` (:class:`~isocsg.kinds.forms.AffineFrustum`)."""
    m = M[2]  # z = c_z + m . (x, y, t)
    size = float(np.abs(M).max())
    tol = 1e-13 * size
    w = z - c[2]
    if abs(m[0]) <= tol and abs(m[1]) <= tol:  # ends parallel to the plane: one ellipse
        t = w / m[2]
        if abs(t) > 0.5 * (1 + 1e-12):
            return EMPTY
        r = r2 + (r1 - r2) * (min(max(t, -0.5), 0.5) + 0.5)
        if r <= 0:
            return EMPTY
        return _ellipse(c[:2] + M[:2, 2] * t, r * M[:2, :2])
    if abs(m[2]) <= tol:  # the axis parallel to the plane
        if r1 != r2:
            return _polygonised_section(leaf, z)
        k = m[:2]
        dist = w / float(np.linalg.norm(k))  # the chord x . k/|k| = dist of the disc of radius r1
        if abs(dist) >= r1:
            return EMPTY
        u = k / np.linalg.norm(k)
        half = math.sqrt(r1 * r1 - dist * dist) * np.array([-u[1], u[0]])
        ends = [dist * u + half, dist * u - half]
        pts = [c[:2] + M[:2, :2] @ e + M[:2, 2] * t for e in ends for t in (-0.5, 0.5)]
        return _convex(np.array(pts))
    # t = tau0 + tau . (x, y) on the plane; the point is c' + A (x, y)
    tau0, tau = w / m[2], -m[:2] / m[2]
    A = M[:2, :2] + np.outer(M[:2, 2], tau)
    c0 = c[:2] + M[:2, 2] * tau0
    b = r1 - r2
    k0, k = r2 + b * (tau0 + 0.5), b * tau
    if float(k @ k) >= 1.0 - 1e-12:  # a parabola or hyperbola: no 2D leaf for it
        return _polygonised_section(leaf, z)
    # |x|^2 <= (k0 + k . x)^2: the ellipse (x - x0)^T Q (x - x0) <= rho, Q = I - k k^T
    Q = np.eye(2) - np.outer(k, k)
    x0 = np.linalg.solve(Q, k * k0)
    rho = k0 * k0 + float(x0 @ Q @ x0)
    if rho <= 0:
        return EMPTY
    L = np.linalg.cholesky(np.linalg.inv(Q)) * math.sqrt(rho)
    ellipse = _ellipse(c0 + A @ x0, A @ L)
    # the ends: -1/2 <= tau0 + tau . x <= 1/2 with x = A^-1 (p - c0)
    Ainv = np.linalg.inv(A)
    g = Ainv.T @ tau
    s0 = tau0 - float(g @ c0)
    return _half_planes(ellipse, [(g, 0.5 - s0), (-g, 0.5 + s0)])


def _torus_section(leaf: Any, form: RingTorus, z: float) -> Shape2D:
    c, a = form.center, form.axis
    R, r = form.major, form.minor
    if abs(abs(a[2]) - 1.0) <= 1e-13:  # about z: an annulus
        d = z - c[2]
        if abs(d) >= r:
            return EMPTY
        s = math.sqrt(r * r - d * d)
        return Circle((c[0], c[1]), R + s) - Circle((c[0], c[1]), R - s)
    if abs(a[2]) <= 1e-13 and abs(z - c[2]) <= 1e-13 * R:  # the plane holds the axis: two discs
        u = np.array([-a[1], a[0]]) / math.hypot(a[0], a[1])
        return union2d(Circle(tuple(c[:2] + R * u), r), Circle(tuple(c[:2] - R * u), r))
    return _polygonised_section(leaf, z)
