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

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Literal, overload

import numpy as np
import shapely
from numpy.typing import ArrayLike, NDArray
from shapely.geometry import MultiPolygon, Polygon
from shapely.geometry.base import BaseGeometry

from .._validation import integer, nonzero_vector3, points_array, vector3
from ..errors import InvalidGeometryError, InvalidParameterError
from ..kinds.base import LeafForm, Primitive, Solid
from ..kinds.planar import EMPTY as _EMPTY
from ..kinds.planar import circle_ring, to2d
from .leaf_table import LeafTable, leaf_table
from .program import OP_DIFFERENCE, OP_INTERSECTION, OP_UNION, Program, compile_program
from .tree import CSGNode

__all__ = [
    "Section",
    "section",
    "plane_frame",
    "primitive_section",
    "combine_sections",
    "polygonal",
    "solid_program",
    "program_section",
    "leaf_sections",
    "leaf_table",
    "LeafTable",
]



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


def primitive_section(
    prim: Primitive, frame: NDArray[np.float64], resolution: int = 256, *, area_exact: bool = False,
) -> Polygon:
    """The section of one primitive in the plane of ``frame`` (see :func:`plane_frame`).

    Parameters
    ----------
    prim : Primitive
    frame : ndarray, shape (4, 4)
        From :func:`plane_frame`.
    resolution : int, default 256
        Polygon vertices per full circle of curved boundary.
    area_exact : bool, default False
        False: the polygon is inscribed (every vertex on the true boundary).
        True: it has the true area (circles: regular polygons of the
        circle's area; other curves: every other vertex pushed out of its
        chord by a third of its sagitta, Simpson's rule, error O(h^5) per
        segment of length h).

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
    >>> from isocsg import Box, Sphere
    >>> primitive_section(Box((0, 0, 0), (2, 3, 4)), plane_frame((0, 0, 1), (0, 0, 1))).area
    6.0
    >>> F = plane_frame((0, 0, 0), (0, 0, 1))
    >>> round(primitive_section(Sphere((0, 0, 0), 1), F, 64, area_exact=True).area / np.pi, 12)
    1.0
    """
    if not isinstance(prim, Primitive):
        raise InvalidGeometryError(f"primitive_section needs a primitive, got {type(prim).__name__}")
    return prim.section(np.asarray(frame, dtype=np.float64), resolution, area_exact)


# ----------------------------------------------------------------------------- leaf tables


def leaf_sections(
    prog: Program, F: NDArray[np.float64], resolution: int, *, area_exact: bool = False,
    ids: NDArray[np.int64] | None = None,
) -> list[Polygon]:
    """The sections of the leaves ``ids`` (default: all) of ``prog`` in the plane of ``F``.

    Spheres and trunci whose axis is normal to the plane (circles) are built
    in one vectorised batch; the others one by one (:func:`primitive_section`).
    """
    tab = leaf_table(prog)
    idx = np.arange(len(prog.leaves)) if ids is None else np.asarray(ids, dtype=np.int64)
    n, o = F[:3, 2], F[:3, 3]
    out: list[Polygon] = [_EMPTY] * len(idx)
    k = tab.kind[idx]
    d = (tab.center[idx] - o) @ n
    rad = np.full(len(idx), -1.0)
    sph = k == LeafForm.BALL
    left = tab.radius[idx][sph] ** 2 - d[sph] ** 2
    rad[sph] = np.where(left > 0, np.sqrt(np.maximum(left, 0)), 0.0)
    tr = k == LeafForm.FRUSTUM
    an = np.abs(tab.axis[idx] @ n)
    circ = tr & (an >= 1.0 - 1e-13)
    if circ.any():
        s = -d[circ] * np.sign(tab.axis[idx][circ] @ n)  # axial coordinate of the plane
        h2 = tab.height[idx][circ] / 2
        eps = 1e-12 * np.maximum(tab.height[idx][circ], np.maximum(tab.r1[idx][circ], tab.r2[idx][circ]))
        r = tab.r2[idx][circ] + (tab.r1[idx][circ] - tab.r2[idx][circ]) * (np.clip(s, -h2, h2) + h2) / (2 * h2)
        rad[circ] = np.where(np.abs(s) <= h2 + eps, r, 0.0)
    batch = np.nonzero(sph | circ)[0]
    good = batch[rad[batch] > 0]
    if len(good):
        c2 = to2d(tab.center[idx[good]], F)
        rings = circle_ring(c2, rad[good], resolution, area_exact)
        for j, g in zip(good.tolist(), shapely.polygons(rings)):
            out[j] = g
    # boxes cut across a coordinate axis: rectangles (faces in the plane count, see coplanar_sides)
    rect = np.zeros(len(idx), dtype=bool)
    if float(np.max(np.abs(n))) >= 1.0 - 1e-13:
        rect = k == LeafForm.AXIS_BOX
        r_idx = np.nonzero(rect)[0]
        if len(r_idx):
            half = tab.half[idx[r_idx]]
            size = 2 * half.max(axis=1)
            hit = np.abs(d[r_idx]) <= half @ np.abs(n) + 1e-12 * size
            u, v = F[:3, 0], F[:3, 1]
            cu, cv = (tab.center[idx[r_idx]] - o) @ u, (tab.center[idx[r_idx]] - o) @ v
            hu, hv = half @ np.abs(u), half @ np.abs(v)
            boxes = shapely.box(cu - hu, cv - hv, cu + hu, cv + hv)
            for j, g, h in zip(r_idx.tolist(), boxes, hit.tolist()):
                if h:
                    out[j] = g
    for j in np.nonzero(~(sph | circ | rect))[0].tolist():
        out[j] = primitive_section(prog.leaves[int(idx[j])], F, resolution, area_exact=area_exact)
    return out


def coplanar_sides(prog: Program, F: NDArray[np.float64], ids: NDArray[np.int64]) -> NDArray[np.int8]:
    """For the leaves ``ids``: +1 where a planar face of the leaf lies in the plane of ``F`` with
    the leaf on the side of the normal, -1 on the other side, 0 where no face lies in the plane."""
    tab = leaf_table(prog)
    n, o = F[:3, 2], F[:3, 3]
    ids = np.asarray(ids, dtype=np.int64)
    out = np.zeros(len(ids), np.int8)
    kind = tab.kind[ids]
    d = (tab.center[ids] - o) @ n
    # trunci: end discs (E1 at +axis/2 faces +axis, E2 at -axis/2 faces -axis)
    tr = np.nonzero(kind == LeafForm.FRUSTUM)[0]
    if len(tr):
        an = tab.axis[ids[tr]] @ n
        par = np.abs(an) >= 1.0 - 1e-13
        size = np.maximum(tab.height[ids[tr]], np.maximum(tab.r1[ids[tr]], tab.r2[ids[tr]]))
        h2 = tab.height[ids[tr]] / 2
        for sgn, r in ((1.0, tab.r1[ids[tr]]), (-1.0, tab.r2[ids[tr]])):
            hit = par & (r > 0) & (np.abs(d[tr] + sgn * an * h2) <= 1e-12 * size)
            out[tr[hit]] = np.where(sgn * an[hit] > 0, -1, 1)
    # boxes: faces normal to a coordinate axis
    bx = np.nonzero(kind == LeafForm.AXIS_BOX)[0]
    ax = int(np.argmax(np.abs(n)))
    if len(bx) and abs(n[ax]) >= 1.0 - 1e-13:
        half = tab.half[ids[bx], ax]
        size = 2 * tab.half[ids[bx]].max(axis=1)
        for sgn in (1.0, -1.0):  # the face at centre + sgn * half along the axis faces sgn * axis
            hit = np.abs(d[bx] + sgn * half * np.sign(n[ax])) <= 1e-12 * size
            out[bx[hit]] = -1 if sgn > 0 else 1
    for j in np.nonzero((kind == LeafForm.HULL) | (kind == LeafForm.GENERIC))[0].tolist():
        p = prog.leaves[int(ids[j])]
        faces = p.planar_faces()
        if faces is None:
            continue
        normals, offsets = faces
        extent = float(np.max(p.bounds[1] - p.bounds[0]))
        dots = normals @ n
        par = np.abs(dots) >= 1.0 - 1e-13
        if par.any():
            hit = np.abs(offsets[par] - normals[par] @ o) <= 1e-12 * extent
            if hit.any():
                out[j] = -1 if dots[par][hit][0] > 0 else 1
    return out


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


#: A difference or union with at least this many operands checks whether they are
#: pairwise disjoint (then they are combined without a union of all of them).
DISJOINT_CHECK = 8


def _pairwise_disjoint(geoms: list[BaseGeometry]) -> bool:
    """True when no two of the polygons meet (not even at a point)."""
    tree = shapely.STRtree(geoms)
    pairs = tree.query(geoms, predicate="intersects")
    return pairs.shape[1] == len(geoms)


@overload
def combine_sections(
    program: Program, leaf_geoms: Sequence[BaseGeometry], *, area_only: Literal[False] = ...
) -> Polygon | MultiPolygon: ...


@overload
def combine_sections(
    program: Program, leaf_geoms: Sequence[BaseGeometry], *, area_only: bool
) -> Polygon | MultiPolygon | float: ...


def combine_sections(
    program: Program, leaf_geoms: Sequence[BaseGeometry], *, area_only: bool = False
) -> Polygon | MultiPolygon | float:
    """Evaluate a CSG program on 2D leaf geometries with shapely Booleans.

    Unions and differences of many pairwise-disjoint operands (the holes of a
    plate) skip the union of those operands: a difference subtracts them as
    one valid multipolygon.

    Parameters
    ----------
    program : Program
        From :func:`isocsg.csg.program.compile_program`.
    leaf_geoms : sequence of shapely geometries
        One per leaf of the program, in the plane's 2D frame.
    area_only : bool, default False
        Return only the area of the result (the last operation then sums
        areas instead of building the result where its operands are disjoint).

    Returns
    -------
    shapely.Polygon or shapely.MultiPolygon, or float
        Areal parts only (regularised); the area when ``area_only``.

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
    n_ops = int(np.count_nonzero(np.asarray(program.op) != 0))
    calls = [0]
    struct = _Structure()

    # Each value of the walk is (the subtree's interned key, its geometry): equal operands are
    # recognised by their keys.
    def combine(op: int, xs: list[tuple[int, BaseGeometry]]) -> tuple[int, BaseGeometry]:
        calls[0] += 1
        args, empty, key = struct.simplify(op, [k for k, _ in xs], [g for _, g in xs])
        return key, operation(op, args, empty, area_only and calls[0] == n_ops)

    def operation(op: int, args: list[BaseGeometry], empty: bool, last: bool) -> BaseGeometry:
        if empty:
            return _Area(0.0) if last else _EMPTY
        if len(args) == 1:
            return _Area(float(args[0].area)) if last else args[0]
        if op == OP_UNION:
            parts = [g for g in args if not g.is_empty]
            if len(parts) >= DISJOINT_CHECK and _pairwise_disjoint(parts):
                if last:
                    return _Area(float(sum(g.area for g in parts)))
                res = MultiPolygon([q for g in parts for q in getattr(g, "geoms", [g])])
            else:
                res = shapely.union_all(parts) if parts else _EMPTY
        elif op == OP_INTERSECTION:
            res = _EMPTY if any(g.is_empty for g in args) else shapely.intersection_all(args)
        else:
            first, rest = args[0], [g for g in args[1:] if not g.is_empty]
            if first.is_empty or not rest:
                res = first
            else:
                if len(rest) > 1:
                    rest = [g for g, hit in zip(rest, shapely.intersects(first, rest)) if hit]
                if not rest:
                    res = first
                elif len(rest) == 1:
                    res = shapely.difference(first, rest[0])
                elif len(rest) >= DISJOINT_CHECK and _pairwise_disjoint(rest):
                    if last:
                        cut = float(shapely.area(shapely.intersection(first, rest)).sum())
                        return _Area(float(polygonal(first, min_width).area) - cut)
                    res = _subtract_disjoint(first, rest)
                else:
                    res = shapely.difference(first, shapely.union_all(rest))
        return polygonal(res, min_width)

    def leaf(i: int, p: Primitive) -> tuple[int, BaseGeometry]:
        return struct.leaf_key(p), leaf_geoms[i]

    out = program.evaluate(leaf, combine)[1]
    if isinstance(out, _Area):
        return max(out.value, 0.0)
    out = polygonal(out, min_width)
    return float(out.area) if area_only else out


class _Structure:
    """Interned keys of the subtrees met while a program is evaluated, so that equal operands are
    recognised: ``A | A`` and ``A & A`` keep one ``A``; ``A - A`` is empty in each of its flattened
    forms (``A - ... - A``; ``(b | c) - b - c``; ``A - S.. - (A - S..)``). Exact where the 2D
    Booleans would leave slivers. The keys travel with the values of :meth:`Program.evaluate`
    (no stack of its own)."""

    def __init__(self) -> None:
        self.ids: dict[object, int] = {}
        self.nodes: dict[int, tuple[int, tuple[int, ...]]] = {}

    def _key(self, k: object) -> int:
        return self.ids.setdefault(k, len(self.ids))

    def leaf_key(self, prim: object) -> int:
        """The key of a leaf (equal primitives, one key)."""
        return self._key(("leaf", prim))

    def simplify(self, op: int, keys: list[int], args: list) -> tuple[list, bool, int]:
        """Drop repeated operands of a node whose operands have ``keys``: the operands kept, True when
        the result is empty by structure, and the node's key."""
        if op != OP_DIFFERENCE:
            seen: set[int] = set()
            keep = []
            for i, k in enumerate(keys):
                if k not in seen:
                    seen.add(k)
                    keep.append(i)
            keys, args = [keys[i] for i in keep], [args[i] for i in keep]
            empty = False
        else:
            first, rest = keys[0], set(keys[1:])
            fn = self.nodes.get(first, (None, ()))
            empty = first in rest or (fn[0] == OP_UNION and set(fn[1]) <= rest) or any(
                self.nodes.get(k, (None, ()))[0] == OP_DIFFERENCE
                and self.nodes[k][1][0] == first
                and set(self.nodes[k][1][1:]) <= rest
                for k in keys[1:]
            )
        key = keys[0] if len(keys) == 1 else self._key((op, tuple(keys)))
        self.nodes.setdefault(key, (op, tuple(keys)))
        return args, empty, key


def _subtract_disjoint(first: BaseGeometry, rest: list[BaseGeometry]) -> BaseGeometry:
    """``first`` minus pairwise-disjoint polygons: those strictly inside a polygon
    ``first`` become its holes directly, the others are subtracted as one multipolygon."""
    if isinstance(first, Polygon):
        shapely.prepare(first)
        arr = np.asarray(rest, dtype=object)
        take = (shapely.contains_properly(first, arr) & (shapely.get_type_id(arr) == 3)
                & (shapely.get_num_interior_rings(arr) == 0))
        if take.any():
            rest = arr[~take].tolist()
            own = shapely.get_interior_ring(first, np.arange(len(first.interiors)))
            holes = np.concatenate([own, shapely.get_exterior_ring(arr[take])])
            first = shapely.polygons(shapely.get_exterior_ring(first), holes=holes)
    if not rest:
        return first
    parts = [q for g in rest for q in getattr(g, "geoms", [g])]
    return shapely.difference(first, parts[0] if len(parts) == 1 else MultiPolygon(parts))


@dataclass(frozen=True, slots=True)
class _Area:
    """The area of a result that was not built (``combine_sections(area_only=True)``)."""

    value: float


def plane_leaves(prog: Program, F: NDArray[np.float64]) -> NDArray[np.int64]:
    """Indices of the leaves of ``prog`` whose extent along the plane normal contains the plane."""
    lo, hi = leaf_table(prog).extents(F[:3, 2])
    d = float(F[:3, 3] @ F[:3, 2])
    size = np.maximum(hi - lo, 1e-300)
    return np.nonzero((lo <= d + 1e-12 * size) & (hi >= d - 1e-12 * size))[0]


def program_section(
    prog: Program,
    F: NDArray[np.float64],
    resolution: int,
    *,
    area_exact: bool = False,
    area_only: bool = False,
    progress: Callable[[int, int], None] | None = None,
) -> Polygon | MultiPolygon | float:
    """The section of a program in the plane of ``F`` (see :func:`section` for its meaning).

    Only the leaves whose extent meets the plane take part (:meth:`Program.prune`).
    """
    ids = plane_leaves(prog, F)
    if len(ids) == 0:
        return 0.0 if area_only else _EMPTY
    present = np.zeros(len(prog.leaves), dtype=bool)
    present[ids] = True
    pr = prog.prune(present)
    if pr is None:
        return 0.0 if area_only else _EMPTY
    sub, orig = pr
    total = len(orig) + 1
    geoms: list[Polygon] = []
    chunk = 2048
    for k in range(0, len(orig), chunk):
        geoms += leaf_sections(prog, F, resolution, area_exact=area_exact, ids=orig[k : k + chunk])
        if progress is not None:
            progress(min(k + chunk, len(orig)), total)
    sides = coplanar_sides(prog, F, orig)
    if not sides.any():
        out = combine_sections(sub, geoms, area_only=area_only)
    else:
        # A face in the plane: the section is where the solid is on both sides
        # (the limits from above and from below, intersected).
        above = [_EMPTY if sd < 0 else g for g, sd in zip(geoms, sides.tolist())]
        below = [_EMPTY if sd > 0 else g for g, sd in zip(geoms, sides.tolist())]
        a, b = combine_sections(sub, above), combine_sections(sub, below)
        nonempty = [g for g in geoms if not g.is_empty]
        bounds = shapely.total_bounds(nonempty) if nonempty else np.zeros(4)
        min_width = SLIVER_WIDTH * float(max(bounds[2] - bounds[0], bounds[3] - bounds[1]))
        out = polygonal(shapely.intersection(a, b), min_width)
        if area_only:
            out = float(out.area)
    if progress is not None:
        progress(total, total)
    return out


def section(
    solid: Solid,
    plane_origin: ArrayLike,
    plane_normal: ArrayLike,
    *,
    resolution: int = 256,
    area_exact: bool = False,
    progress: Callable[[int, int], None] | None = None,
) -> Section:
    """Cut a primitive or CSG tree by a plane.

    The section is the closure of the part of the plane that lies in the
    interior of the regularised result: where a planar face of a leaf lies in
    the plane, the section is the intersection of the limits of the
    sections from both sides. So a plane that only touches a solid's face
    gives an empty section (area 0), and the shared face of two stacked
    solids in a union is counted once. Elsewhere (almost every plane) it is
    the plain cut. It differs from the points of the plane that
    :meth:`isocsg.csg.program.Program.contains` accepts only where the plane
    holds a face of the result: there ``contains`` (closed) accepts the face,
    the section (area) does not; both have measure zero in the volume.

    Only the leaves whose extent along the normal meets the plane take part
    (the program is pruned to them), so a section of a 10 000-leaf plate
    touches only the leaves it cuts.

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
    area_exact : bool, default False
        False: curved boundaries are inscribed polygons (every vertex on the
        true boundary; the area converges from below, relative deficit about
        ``(2 pi / resolution)**2 / 6`` of the curved parts). True: polygons
        with the true area of each leaf's section (see
        :func:`primitive_section`), what :func:`isocsg.volume` integrates.
    progress : callable, optional
        Called as ``progress(done, total)`` while the leaves' sections are built
        and once at the end.

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
    >>> from isocsg import Box, Cylinder, Sphere
    >>> s = section(Sphere((0, 0, 0), 1) - Cylinder((0, 0, 0), (0, 0, 4), 0.5), (0, 0, 0), (0, 0, 1))
    >>> round(s.area / (np.pi * (1 - 0.25)), 3)
    1.0
    >>> plate, boss = Box((0, 0, 0), (4, 4, 2)), Cylinder((0, 0, 1.5), (0, 0, 1), 1)
    >>> section(plate, (0, 0, 1), (0, 0, 1)).area  # only touches the top face
    0.0
    >>> round(section(plate | boss, (0, 0, 1), (0, 0, 1), area_exact=True).area / np.pi, 9)  # the boss's foot
    1.0
    """
    res = integer("resolution", resolution, low=8, high=1_000_000, error=InvalidParameterError)
    F = plane_frame(plane_origin, plane_normal)
    prog = solid_program(solid)
    geom = program_section(prog, F, res, area_exact=bool(area_exact), progress=progress)
    return Section(geom, F)
