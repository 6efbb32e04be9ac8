"""The boundary on a planar face, exactly, where every leaf that meets it is planar.

A face ``F`` of a box or convex polyhedron (leaf ``i``) whose neighbours (the leaves whose boxes
meet ``i``'s) are all boxes or convex polyhedra is cut by them into polygons: a neighbour ``j``
contains a point of ``F``'s plane where all of its half-spaces do, and each half-space meets
the plane in a half-plane, so ``j``'s state on ``F`` is one convex polygon (``F`` clipped by
those half-planes, rebuilt as the convex hull of its vertices: a clip at a vertex can repeat it,
and GEOS takes such a ring as self-intersecting). The tree evaluated on these polygons (shapely's
overlay: union, intersection, difference, snap-rounded to a fine grid where the caller asks:
GEOS' floating overlay can lose pieces where edges nearly coincide) with ``i`` out (the empty
set) and with ``i`` in (all of ``F``) gives the two regions whose symmetric difference is the part
of ``F`` on the result's boundary: the rule of :mod:`isocsg.testing.area`, applied to whole
polygons instead of points on rings, so its area is exact up to the grid and its cost grows
with the number of neighbours, not with the number of rings. The flux of ``x / 3`` through a
planar face is constant per unit area, so the volume's share of the face is its area times
``(n . p - n . origin) / 3``.

Coincident faces follow :mod:`isocsg.testing.area` exactly: a half-space of ``j`` whose plane
holds all of ``F`` (within the tolerance) is decided by the side (just outside ``i``, where
``i`` is out, and just inside, where it is in): ``j`` is out just outside a face with the same
normal and just inside one with the opposite normal; the part of ``F`` on a coincident face of
a leaf of lower index is counted by that leaf, not by ``i``.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..csg.program import OP_INTERSECTION, OP_UNION, Program

__all__ = ["Neighbours", "PlanarFace", "face_boundary", "face_regions"]

F64 = NDArray[np.float64]
#: Relative rounding of the overlay's areas (GEOS' snap-rounded overlay in double precision).
OVERLAY_ROUNDING = 1e-12

_FULL = object()  # all of the face: kept symbolic so that trees of untouched leaves cost nothing


class PlanarFace:
    """One face polygon ``V`` (k, 3), counter-clockwise seen from outside, its outward unit
    normal ``n``, and the 2D frame in which the overlay runs."""

    def __init__(self, V: F64, n: F64) -> None:
        self.V = np.asarray(V, dtype=np.float64)
        self.n = np.asarray(n, dtype=np.float64)
        self.o = self.V.mean(axis=0)  # the frame's origin inside the face: small coordinates
        e1 = self.V[1] - self.V[0]
        e1 = e1 - (e1 @ self.n) * self.n
        self.e1 = e1 / np.linalg.norm(e1)
        self.e2 = np.cross(self.n, self.e1)
        self.uv = (self.V - self.o) @ np.stack([self.e1, self.e2]).T
        self.d = float(self.n @ self.V.mean(axis=0))


def _clip(poly: F64, a: F64, b: float) -> F64:
    """The convex polygon ``poly`` (m, 2) cut to the half-plane ``a . u <= b``."""
    f = poly @ a - b
    out: list[F64] = []
    m = len(poly)
    for k in range(m):
        p, q, fp, fq = poly[k], poly[(k + 1) % m], f[k], f[(k + 1) % m]
        if fp <= 0:
            out.append(p)
        if (fp < 0 < fq) or (fq < 0 < fp):
            out.append(p + (q - p) * (fp / (fp - fq)))
    return np.asarray(out, dtype=np.float64).reshape(-1, 2)


class Neighbours:
    """The half-spaces ``N x <= D`` of the leaves that may meet a face, stacked (``owner``: the
    leaf of each row), so that a face classifies them all in one product."""

    def __init__(self, leaves: Sequence[int], planes: Sequence[tuple[F64, F64] | None]) -> None:
        hs = [planes[j] for j in leaves]
        self.leaves = np.asarray(leaves, dtype=np.int64)
        self.N = np.concatenate([h[0] for h in hs if h is not None]) if leaves else np.zeros((0, 3))
        self.D = np.concatenate([h[1] for h in hs if h is not None]) if leaves else np.zeros(0)
        self.owner = np.concatenate([np.full(len(h[1]), k) for k, h in enumerate(hs) if h is not None]) \
            if leaves else np.zeros(0, np.int64)


def _leaf_states(face: PlanarFace, nb: Neighbours, tol: float) -> list[tuple[int, Any, bool, bool, bool]]:
    """The neighbours that meet ``face``: (leaf, its polygon there or ``_FULL``, out just outside
    the face (a coincident face with the same normal), out just inside (the opposite normal),
    whether it has a face on ``face``'s plane)."""
    m = len(nb.leaves)
    vals = face.V @ nb.N.T - nb.D  # (k, rows)
    lo, hi = vals.min(axis=0), vals.max(axis=0)
    coplanar = (hi <= tol) & (lo >= -tol)
    side = nb.N @ face.n
    crossing = (hi > tol) & ~coplanar

    def per_leaf(mask: NDArray[np.bool_]) -> NDArray[np.bool_]:
        return np.bincount(nb.owner, mask, minlength=m) > 0

    missing = per_leaf(lo > tol)
    out_plus, out_minus = per_leaf(coplanar & (side > 0)), per_leaf(coplanar & (side < 0))
    has_cop, cuts = per_leaf(coplanar), per_leaf(crossing)
    out: list[tuple[int, Any, bool, bool, bool]] = []
    for k in np.flatnonzero(~missing).tolist():
        poly: Any = _FULL
        if cuts[k]:
            poly = face.uv
            for r in np.flatnonzero(crossing & (nb.owner == k)).tolist():
                a = np.array([nb.N[r] @ face.e1, nb.N[r] @ face.e2])
                poly = _clip(poly, a, float(nb.D[r] - nb.N[r] @ face.o))
                if len(poly) < 3:
                    break
            if len(poly) < 3:
                continue
        out.append((int(nb.leaves[k]), poly, bool(out_plus[k]), bool(out_minus[k]), bool(has_cop[k])))
    return out


def _convex_polygon(points: F64) -> Any:
    """The convex polygon with these vertices as a valid shapely polygon (a clipped polygon can
    repeat a vertex, or nearly, where an edge is cut at its end: GEOS takes such a ring as
    self-intersecting and its overlay is then wrong), or None when it has no area."""
    import shapely

    hull = shapely.convex_hull(shapely.multipoints(points))
    return hull if hull.geom_type == "Polygon" and hull.area > 0 else None


def _areal(g: Any) -> Any:
    """The polygons of an overlay's result: snap-rounding can collapse a sliver into a line or a
    point, and GEOS refuses such a mixed collection as the input of the next overlay."""
    import shapely

    if g.geom_type in ("Polygon", "MultiPolygon"):
        return g
    parts = [p for p in shapely.get_parts(g) if p.geom_type == "Polygon" and not p.is_empty]
    return shapely.MultiPolygon(parts) if parts else shapely.Polygon()


def _combiner(face_poly: Any, grid: float | None) -> Any:
    """``combine`` for :meth:`Program.evaluate` on regions of a face: a shapely geometry, None
    (empty) or ``_FULL`` (all of ``face_poly``); ``grid``: the overlay's snapping grid, if any."""
    import shapely

    def combine(op: int, xs: list[Any]) -> Any:
        if op == OP_UNION:
            if any(x is _FULL for x in xs):
                return _FULL
            geoms = [x for x in xs if x is not None]
            if len(geoms) <= 1:
                return geoms[0] if geoms else None
            return _areal(shapely.union_all(geoms, grid_size=grid))
        if op == OP_INTERSECTION:
            if any(x is None for x in xs):
                return None
            geoms = [x for x in xs if x is not _FULL]
            if len(geoms) <= 1:
                return geoms[0] if geoms else _FULL
            out = geoms[0]
            for g in geoms[1:]:  # intersection_all takes no grid: pairwise, snap-rounded
                out = _areal(shapely.intersection(out, g, grid_size=grid))
            return out
        first, rest = xs[0], [x for x in xs[1:] if x is not None]
        if first is None or any(x is _FULL for x in rest):
            return None
        if not rest:
            return first
        return _areal(shapely.difference(face_poly if first is _FULL else first,
                                         _areal(shapely.union_all(rest, grid_size=grid)), grid_size=grid))

    return combine


def face_boundary(
    prog: Program, i: int, face: PlanarFace, nb: Neighbours, tol: float, grid: float | None = None,
) -> tuple[float, float, float]:
    """The part of leaf ``i``'s face on the result's boundary: its area counted by ``i``, the
    same area signed by the result's side (+ where the result is inside ``i``, so its outward
    normal is the face's), and the overlay's rounding bound on the area.

    ``nb``: the leaves other than ``i`` that may meet the face (all planar); every other leaf is
    out on all of it. ``grid``: snap-round the overlay to this grid (GEOS' floating overlay can
    lose pieces where edges nearly coincide); the bound then adds ``grid`` times the polygons'
    perimeters.

    Raises
    ------
    shapely.errors.GEOSException
        Where the overlay fails."""
    inside, outside, err = face_regions(prog, i, face, nb, tol, grid)
    a_in, a_out = float(inside.area), float(outside.area)
    return a_in + a_out, a_in - a_out, err


def face_regions(
    prog: Program, i: int, face: PlanarFace, nb: Neighbours, tol: float, grid: float | None = None,
) -> tuple[Any, Any, float]:
    """The part of leaf ``i``'s face on the result's boundary counted by ``i``, as two shapely
    geometries in the face's frame: where the result is inside ``i`` (its outward normal is the
    face's) and where it is outside (the opposite normal); and the overlay's rounding bound on
    their area (see :func:`face_boundary`).

    Raises
    ------
    shapely.errors.GEOSException
        Where the overlay fails."""
    import shapely

    face_poly = _convex_polygon(face.uv)
    if face_poly is None:
        return shapely.Polygon(), shapely.Polygon(), 0.0
    plus: dict[int, Any] = {i: None}
    minus: dict[int, Any] = {i: _FULL}
    skip: list[Any] = []
    states = _leaf_states(face, nb, tol)
    for j, poly, out_plus, out_minus, coplanar in states:
        g = poly if poly is _FULL else _convex_polygon(poly)
        if g is None:  # the leaf meets the face in a segment or a point
            continue
        plus[j] = None if out_plus else g
        minus[j] = None if out_minus else g
        if coplanar and j < i:
            skip.append(face_poly if g is _FULL else g)
    combine = _combiner(face_poly, grid)
    rp = prog.evaluate(lambda a, _: plus.get(a), combine)
    rm = prog.evaluate(lambda a, _: minus.get(a), combine)

    def geom(x: Any) -> Any:
        return shapely.Polygon() if x is None else face_poly if x is _FULL else x

    if rp is rm or (rp is _FULL and rm is _FULL):
        return shapely.Polygon(), shapely.Polygon(), 0.0
    gp, gm = geom(rp), geom(rm)
    inside = _areal(shapely.difference(gm, gp, grid_size=grid))  # the result inside i
    outside = _areal(shapely.difference(gp, gm, grid_size=grid))  # outside i
    if skip:
        s = _areal(shapely.union_all(skip, grid_size=grid))
        inside = _areal(shapely.difference(inside, s, grid_size=grid))
        outside = _areal(shapely.difference(outside, s, grid_size=grid))
    err = OVERLAY_ROUNDING * float(face_poly.area) * (1 + len(states))
    if grid is not None:
        cuts = [g for g in plus.values() if g is not None and g is not _FULL]
        perimeter = float(face_poly.length) + sum(float(g.length) for g in cuts)
        err += 2.0 * grid * perimeter * (1 + len(states))
    return inside, outside, err
