"""Plane sections of primitives and CSG trees as shapely polygons.

CSG commutes with plane sections: ``(A op B) n P == (A n P) op (B n P)``. So
the section of a tree is the 2D Boolean (shapely) of its leaves' sections,
and each leaf's section is computed exactly and then polygonised:

- sphere: a disc (centre and radius exact), a regular polygon inscribed in it;
- box and convex polyhedron: the exact convex polygon of the half-spaces
  restricted to the plane;
- truncus (cylinder, cone, frustum): the plane cut of the lateral cone
  parametrised by the generator angle ``phi`` (each generator meets the plane
  in one point, solved in closed form), restricted to the slab between the end
  planes. The corners where the curve meets the end planes are solved exactly,
  and each valid ``phi`` interval is sampled finely between them; the convex
  hull of these boundary points is the polygon.

All polygon vertices lie on the true boundary of the section (polygons are
inscribed), so areas converge from below, with relative error about
``(2 pi / resolution)**2 / 6`` for curved boundaries.

The plane's 2D frame: ``u, v`` orthonormal in the plane with ``u x v = n``;
:attr:`Section.frame` maps ``(x, y, 0, 1)`` to the 3D point
``origin + x u + y v``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import shapely
from numpy.typing import ArrayLike, NDArray
from shapely.geometry import MultiPolygon, Polygon
from shapely.geometry.base import BaseGeometry

from .._validation import integer, nonzero_vector3, points_array, vector3
from ..errors import InvalidGeometryError, InvalidParameterError
from ..geometry.primitives import Box, ConvexPolyhedron, Primitive, Solid, Sphere, Truncus
from .program import OP_INTERSECTION, OP_UNION, Program, compile_program
from .tree import CSGNode

__all__ = [
    "Section",
    "section",
    "plane_frame",
    "primitive_section",
    "combine_sections",
    "polygonal",
    "solid_program",
]

_EMPTY = Polygon()


@dataclass(frozen=True, slots=True, eq=False)
class Section:
    """The cross-section of a solid by a plane.

    Attributes
    ----------
    geometry : shapely.Polygon or shapely.MultiPolygon
        The section in the plane's 2D frame (empty when the plane misses the solid).
    frame : ndarray, shape (4, 4)
        Maps 2D homogeneous points ``(x, y, 0, 1)`` of ``geometry`` to 3D.
        Columns: ``u``, ``v``, the unit normal ``n`` and the plane origin.
    """

    geometry: Polygon | MultiPolygon
    frame: NDArray[np.float64]

    @property
    def area(self) -> float:
        """Area of the section in square metres."""
        return float(self.geometry.area)

    @property
    def is_empty(self) -> bool:
        """True when the section has no area."""
        return bool(self.geometry.is_empty) or self.geometry.area == 0.0

    @property
    def origin(self) -> NDArray[np.float64]:
        """The plane origin (the 3D image of 2D (0, 0))."""
        return self.frame[:3, 3].copy()

    @property
    def normal(self) -> NDArray[np.float64]:
        """The unit plane normal."""
        return self.frame[:3, 2].copy()

    def to_3d(self, xy: ArrayLike) -> NDArray[np.float64]:
        """Map 2D points of the plane's frame to 3D.

        Parameters
        ----------
        xy : array_like, shape (n, 2)

        Returns
        -------
        ndarray, shape (n, 3)
        """
        p = points_array("xy", xy, columns=2, error=InvalidParameterError)
        return self.frame[:3, 3] + p @ self.frame[:3, :2].T

    def rings_3d(self) -> list[NDArray[np.float64]]:
        """Every ring (exteriors and holes) of the section as a closed (k, 3) polyline in 3D."""
        out: list[NDArray[np.float64]] = []
        for poly in getattr(self.geometry, "geoms", [self.geometry]):
            if poly.is_empty:
                continue
            for ring in [poly.exterior, *poly.interiors]:
                out.append(self.to_3d(np.asarray(ring.coords)))
        return out


def plane_frame(plane_origin: ArrayLike, plane_normal: ArrayLike) -> NDArray[np.float64]:
    """The 4x4 frame of a plane: columns ``u``, ``v``, ``n``, ``origin``.

    ``u`` and ``v`` are orthonormal in the plane and ``u x v = n`` (unit).
    ``u`` is the world axis least aligned with ``n``, made orthogonal to ``n``
    (a deterministic choice).

    Parameters
    ----------
    plane_origin : array_like, shape (3,)
    plane_normal : array_like, shape (3,)
        Non-zero; normalised here.

    Returns
    -------
    ndarray, shape (4, 4)

    Raises
    ------
    InvalidParameterError
        If the origin is not 3 finite numbers or the normal is zero.

    Examples
    --------
    >>> F = plane_frame((0, 0, 2), (0, 0, 1))
    >>> (F @ [1.0, 0.0, 0.0, 1.0]).tolist()
    [1.0, 0.0, 2.0, 1.0]
    """
    o = np.asarray(vector3("plane_origin", plane_origin, error=InvalidParameterError))
    n = np.asarray(nonzero_vector3("plane_normal", plane_normal, error=InvalidParameterError))
    n = n / np.linalg.norm(n)
    # u along the world axis least aligned with n, made orthogonal to n
    e = np.zeros(3)
    e[int(np.argmin(np.abs(n)))] = 1.0
    u = e - (e @ n) * n
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    F = np.eye(4)
    F[:3, 0], F[:3, 1], F[:3, 2], F[:3, 3] = u, v, n, o
    return F


#: Parts of a Boolean result whose mean width (2 area / perimeter) is below this
#: fraction of the operands' extent are rounding slivers, not solid: shapely nodes
#: a shared boundary with perturbations of 1e-16, so ``A - (A | B)`` can leave
#: slivers of area 1e-17 where the exact result is empty.
SLIVER_WIDTH = 1e-10


def polygonal(geom: BaseGeometry, min_width: float = 0.0) -> Polygon | MultiPolygon:
    """Keep only the areal parts of a shapely result (drop touching lines and points).

    Regularised set operations have no dangling edges: shapely may return
    a GeometryCollection with lines where two operands touch. Parts of zero
    area, and parts whose mean width ``2 area / perimeter`` is below
    ``min_width``, are dropped.

    Examples
    --------
    >>> from shapely.geometry import box
    >>> polygonal(box(0, 0, 1, 1) & box(1, 0, 2, 1)).is_empty
    True
    >>> polygonal(box(0, 0, 1, 1e-12) | box(2, 0, 3, 1), min_width=1e-9).area
    1.0
    """
    if geom is None or geom.is_empty:
        return _EMPTY
    if isinstance(geom, Polygon):
        candidates = [geom]
    elif isinstance(geom, MultiPolygon):
        candidates = list(geom.geoms)
    else:
        candidates = []
        for g in getattr(geom, "geoms", []):
            if isinstance(g, Polygon):
                candidates.append(g)
            elif isinstance(g, MultiPolygon):
                candidates.extend(g.geoms)
    parts = [p for p in candidates if p.area > 0 and 2.0 * p.area >= min_width * p.length]
    if isinstance(geom, (Polygon, MultiPolygon)) and len(parts) == len(candidates):
        return geom
    if not parts:
        return _EMPTY
    return parts[0] if len(parts) == 1 else MultiPolygon(parts)


# ----------------------------------------------------------------------------- leaves


def _to2d(points: NDArray[np.float64], F: NDArray[np.float64]) -> NDArray[np.float64]:
    return (points - F[:3, 3]) @ F[:3, :2]


def _hull_polygon(pts2: NDArray[np.float64]) -> Polygon:
    if len(pts2) < 3:
        return _EMPTY
    hull = shapely.convex_hull(shapely.multipoints(pts2))
    return hull if isinstance(hull, Polygon) and hull.area > 0 else _EMPTY


def _sphere_section(s: Sphere, F: NDArray[np.float64], resolution: int) -> Polygon:
    c = s.center_array
    d = float((c - F[:3, 3]) @ F[:3, 2])
    rr = s.radius**2 - d * d
    if rr <= 0.0:
        return _EMPTY
    r = math.sqrt(rr)
    c2 = _to2d(c[None, :], F)[0]
    ang = np.linspace(0.0, 2.0 * math.pi, resolution, endpoint=False)
    ring = c2 + r * np.column_stack([np.cos(ang), np.sin(ang)])
    return Polygon(ring)


def _halfspace_section(
    normals: NDArray[np.float64], offsets: NDArray[np.float64], verts: NDArray[np.float64], F: NDArray[np.float64]
) -> Polygon:
    """Exact convex polygon {x in plane : normals @ x <= offsets} by Sutherland-Hodgman clipping."""
    o, u, v = F[:3, 3], F[:3, 0], F[:3, 1]
    A = np.column_stack([normals @ u, normals @ v])
    b = offsets - normals @ o
    scale = float(np.max(np.ptp(verts, axis=0)))
    eps = 1e-12 * max(scale, 1e-300)
    v2 = _to2d(verts, F)
    lo, hi = v2.min(axis=0) - 0.01 * scale - 1.0, v2.max(axis=0) + 0.01 * scale + 1.0
    poly = np.array([[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]])
    for a_k, b_k in zip(A, b):
        if np.hypot(*a_k) <= 1e-12:
            # face parallel to the plane: all or nothing (the face plane itself counts as inside)
            if b_k < -eps:
                return _EMPTY
            continue
        val = poly @ a_k - b_k  # <= 0 inside
        inside = val <= 0.0
        if inside.all():
            continue
        if not inside.any():
            return _EMPTY
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
            return _EMPTY
    g = Polygon(poly)
    return g if g.area > 0 else _EMPTY


def _truncus_section(t: Truncus, F: NDArray[np.float64], resolution: int) -> Polygon:
    o, n = F[:3, 3], F[:3, 2]
    a = t.unit_axis
    helper = np.array([1.0, 0.0, 0.0]) if abs(a[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    e1 = np.cross(a, helper)
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(a, e1)
    c = t.center_array
    h2 = t.height / 2
    k = t.slope
    r0 = float(t.radius_at(0.0))
    D = float(n @ (c - o))
    na, p1, p2 = float(n @ a), float(n @ e1), float(n @ e2)
    rho = math.hypot(p1, p2)
    phi0 = math.atan2(p2, p1)
    size = max(t.height, t.r1, t.r2)
    eps = 1e-12 * size

    def surface(sig: NDArray[np.float64], phi: NDArray[np.float64]) -> NDArray[np.float64]:
        r = r0 + k * sig
        g = np.cos(phi)[:, None] * e1 + np.sin(phi)[:, None] * e2
        return c + sig[:, None] * a + r[:, None] * g

    def sigma(phi: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
        ng = rho * np.cos(phi - phi0)
        den = na + k * ng
        ok = np.abs(den) > 1e-14
        with np.errstate(divide="ignore", invalid="ignore"):
            s = np.where(ok, -(D + r0 * ng) / np.where(ok, den, 1.0), np.inf)
        return s, ok & (np.abs(s) <= h2 + eps)

    pts: list[NDArray[np.float64]] = []
    breaks: list[float] = []
    # corners: generators crossing the plane exactly on an end circle
    for s_end in (h2, -h2):
        r_end = r0 + k * s_end
        lin = D + s_end * na
        if r_end <= 1e-15 * size:
            if abs(lin) <= eps:  # the plane passes through the apex
                pts.append(c + s_end * a)
            continue
        if rho <= 1e-14:
            continue  # plane parallel to the ends: the curve samples give the circle
        q = -lin / (r_end * rho)
        if abs(q) <= 1.0:
            dphi = math.acos(q)
            ph = np.array([phi0 + dphi, phi0 - dphi])
            pts.append(surface(np.full(2, s_end), ph))
            breaks.extend(ph.tolist())
    # asymptotes: generators parallel to the plane (sigma -> infinity)
    if abs(k) > 0 and rho > 1e-14 and abs(na / (k * rho)) <= 1.0:
        dphi = math.acos(-na / (k * rho))
        breaks.extend([phi0 + dphi, phi0 - dphi])
    # sample each valid phi interval between the breakpoints
    two_pi = 2.0 * math.pi
    if breaks:
        b = np.sort(np.mod(np.asarray(breaks) - phi0, two_pi)) + phi0
        b = np.append(b, b[0] + two_pi)
        for lo, hi in zip(b[:-1], b[1:]):
            if hi - lo <= 1e-15:
                continue
            _, ok_mid = sigma(np.array([0.5 * (lo + hi)]))
            if not ok_mid[0]:
                continue
            m = max(int(math.ceil(resolution * (hi - lo) / two_pi)), 2)
            ph = np.linspace(lo, hi, m + 1)[1:-1]
            s, ok = sigma(ph)
            if ok.any():
                pts.append(surface(s[ok], ph[ok]))
    else:
        ph = np.linspace(0.0, two_pi, resolution, endpoint=False)
        s, ok = sigma(ph)
        if ok.any():
            pts.append(surface(s[ok], ph[ok]))
    if not pts:
        return _EMPTY
    return _hull_polygon(_to2d(np.vstack(pts), F))


def primitive_section(prim: Primitive, frame: NDArray[np.float64], resolution: int = 256) -> Polygon:
    """The section of one primitive in the plane of ``frame`` (see :func:`plane_frame`).

    Parameters
    ----------
    prim : Primitive
    frame : ndarray, shape (4, 4)
        From :func:`plane_frame`.
    resolution : int, default 256
        Polygon vertices per full circle of curved boundary.

    Returns
    -------
    shapely.Polygon
        Convex, possibly empty.

    Raises
    ------
    InvalidGeometryError
        If ``prim`` is not a primitive.

    Examples
    --------
    >>> from isocsg import Box
    >>> primitive_section(Box((0, 0, 0), (2, 3, 4)), plane_frame((0, 0, 1), (0, 0, 1))).area
    6.0
    """
    F = np.asarray(frame, dtype=np.float64)
    if isinstance(prim, Sphere):
        return _sphere_section(prim, F, resolution)
    if isinstance(prim, Truncus):
        return _truncus_section(prim, F, resolution)
    if isinstance(prim, Box):
        return _halfspace_section(prim.face_normals, prim.face_offsets, prim.corners, F)
    if isinstance(prim, ConvexPolyhedron):
        return _halfspace_section(prim.face_normals, prim.face_offsets, prim.hull_vertices, F)
    if isinstance(prim, Primitive):
        poly = prim.to_polyhedron(resolution)
        return _halfspace_section(poly.face_normals, poly.face_offsets, poly.hull_vertices, F)
    raise InvalidGeometryError(f"primitive_section needs a primitive, got {type(prim).__name__}")


# ----------------------------------------------------------------------------- trees


def solid_program(solid: Solid) -> Program:
    """The flat program of a primitive or tree (a primitive is the one-leaf program).

    Raises
    ------
    InvalidGeometryError
        If ``solid`` is not a solid.
    """
    if isinstance(solid, CSGNode):
        return solid.program()
    return compile_program(solid)


def combine_sections(program: Program, leaf_geoms: Sequence[BaseGeometry]) -> Polygon | MultiPolygon:
    """Evaluate a CSG program on 2D leaf geometries with shapely Booleans.

    Parameters
    ----------
    program : Program
        From :func:`isocsg.csg.program.compile_program`.
    leaf_geoms : sequence of shapely geometries
        One per leaf of the program, in the plane's 2D frame.

    Returns
    -------
    shapely.Polygon or shapely.MultiPolygon
        Areal parts only (regularised).

    Examples
    --------
    >>> from shapely.geometry import box
    >>> from isocsg import Box
    >>> prog = compile_program(Box((1, 1, 0), (2, 2, 1)) - Box((2, 1, 0), (2, 2, 1)))
    >>> combine_sections(prog, [box(0, 0, 2, 2), box(1, 0, 3, 2)]).area
    2.0
    """
    nonempty = [g for g in leaf_geoms if not g.is_empty]
    bounds = shapely.total_bounds(nonempty) if nonempty else np.zeros(4)
    min_width = SLIVER_WIDTH * float(max(bounds[2] - bounds[0], bounds[3] - bounds[1]))

    def combine(op: int, args: list[BaseGeometry]) -> BaseGeometry:
        if op == OP_UNION:
            nonempty = [g for g in args if not g.is_empty]
            res = shapely.union_all(nonempty) if nonempty else _EMPTY
        elif op == OP_INTERSECTION:
            res = _EMPTY if any(g.is_empty for g in args) else shapely.intersection_all(args)
        else:
            first, rest = args[0], [g for g in args[1:] if not g.is_empty]
            if first.is_empty or not rest:
                res = first
            else:
                res = shapely.difference(first, rest[0] if len(rest) == 1 else shapely.union_all(rest))
        return polygonal(res, min_width)

    return polygonal(program.evaluate(lambda i, _: leaf_geoms[i], combine), min_width)


def section(
    solid: Solid,
    plane_origin: ArrayLike,
    plane_normal: ArrayLike,
    *,
    resolution: int = 256,
) -> Section:
    """Cut a primitive or CSG tree by a plane.

    Parameters
    ----------
    solid : Solid
        A primitive or CSG tree.
    plane_origin : array_like, shape (3,)
        A point of the plane; the origin of its 2D frame.
    plane_normal : array_like, shape (3,)
        Non-zero plane normal (any direction; normalised here).
    resolution : int, default 256
        Polygon vertices per full circle of curved boundary, 8 .. 1_000_000.

    Returns
    -------
    Section
        The shapely geometry in the plane's frame and the 4x4 frame.

    Raises
    ------
    InvalidGeometryError
        If ``solid`` is not a solid.
    InvalidParameterError
        On a bad plane or resolution.

    Examples
    --------
    >>> from isocsg import Cylinder, Sphere
    >>> s = section(Sphere((0, 0, 0), 1) - Cylinder((0, 0, 0), (0, 0, 4), 0.5), (0, 0, 0), (0, 0, 1))
    >>> round(s.area / (np.pi * (1 - 0.25)), 3)
    1.0
    """
    res = integer("resolution", resolution, low=8, high=1_000_000, error=InvalidParameterError)
    F = plane_frame(plane_origin, plane_normal)
    prog = solid_program(solid)
    prims = prog.leaves
    geoms = [primitive_section(p, F, res) for p in prims]
    return Section(combine_sections(prog, geoms), F)
