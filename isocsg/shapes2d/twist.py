"""Twisted and non-uniformly scaled ``linear_extrude``: OpenSCAD's stack of slices, exactly.

OpenSCAD (2021.01, ``GeometryEvaluator.cc``: ``extrudePolygon``, ``add_slice``) draws such an
extrusion as ``n`` slices. The outline's vertex ``v`` sits at height ``z_j = z0 + j h / n`` at
``T_j v``, with ``T_j = S_j R(-twist j / n)`` (a positive twist turns clockwise seen from above;
``S_j`` scales x and y by ``1 - (1 - s) j / n``). Between two consecutive rings each outline edge
spans a quad, split into two triangles along its shorter diagonal (measured in the plane; near
ties, within a relative 1e-5, broken by the twist's sign and the outline's orientation; reversed
in the last slice when a scale is 0).

Here each slice of each convex piece of the outline is the convex hull of the piece's two rings
(:class:`isocsg.ConvexPolyhedron`), which triangulates every side quad along its convex diagonal;
where OpenSCAD's diagonal is the other one, the tetrahedron between the two splits is subtracted.
Along a diagonal shared by two pieces, the piece listed first keeps its convex side and the other
subtracts that tetrahedron, so the pieces tile the slice. The result is OpenSCAD's solid, exactly.
This needs each piece's hull to join corresponding corners (the turn per slice below the piece's
sharpest exterior angle); a piece that fails is split into triangles about its centroid, and a
triangle that still fails is refused (more ``slices`` help), and so is a piece two of whose cut
tetrahedra overlap (two of its concave bands cross).

:func:`slice_count` is OpenSCAD 2021.01's number of slices when ``slices`` is not given
(``Calc::get_helix_slices``, ``get_conical_helix_slices``, ``get_diagonal_slices``). Newer
OpenSCAD versions also split long outline edges into segments for such extrusions; 2021.01 does
not.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidGeometryError
from .openscad import GRID_FINE

__all__ = ["slice_count", "twisted_pieces"]

_Key = tuple[float, float]


def _helix(r: float, h: float, twist: float, fn: float, fs: float, fa: float) -> int:
    twist = abs(twist)
    low = max(math.ceil(twist / 120.0), 1)
    if r < GRID_FINE or not math.isfinite(fn):
        return low
    if fn > 0:
        return max(math.ceil(twist / 360.0 * fn), low)
    t = math.radians(twist)
    c = h / t
    length = t * math.sqrt(r * r + c * c)
    return max(min(math.ceil(twist / fa), math.ceil(length / fs)), low)


def _conical(r: float, h: float, twist: float, s: float, fn: float, fs: float, fa: float) -> int:
    twist = abs(twist)
    low = max(math.ceil(twist / 120.0), 1)
    if r < GRID_FINE or not math.isfinite(fn):
        return low
    if fn > 0:
        return max(math.ceil(twist * fn / 360.0), low)
    t = math.radians(twist)
    end = t * s / (s - 1) if s > 1 else t / (1 - s)
    a = r / end

    def arc(theta: float) -> float:
        return 0.5 * a * (theta * math.sqrt(1 + theta * theta) + math.asinh(theta))

    spiral = arc(end) - arc(end - t)
    return max(min(math.ceil(math.hypot(spiral, h) / fs), math.ceil(twist / fa)), low)


def slice_count(
    radius: float, delta: float, height: float, twist: float, scale: tuple[float, float],
    fn: float = 0.0, fs: float = 2.0, fa: float = 12.0,
) -> int:
    """OpenSCAD 2021.01's number of slices of a ``linear_extrude`` without ``slices``.

    Parameters
    ----------
    radius : float
        The largest distance of an outline vertex from the z axis.
    delta : float
        The largest distance a vertex moves under the scale alone (``|v - S v|``).
    height, twist, scale
        The extrusion's.
    fn, fs, fa : float
        OpenSCAD's ``$fn``, ``$fs``, ``$fa``.

    Examples
    --------
    >>> slice_count(10, 0, 10, 360, (1, 1))  # $fa = 12: 30 slices a turn
    30
    >>> slice_count(10, 0, 10, 90, (1, 1), fn=64)
    16
    >>> slice_count(1, 0, 1, 0, (1, 1))
    1
    """
    sx, sy = scale
    if twist != 0.0:
        if (sx == 1.0 and sy == 1.0) or sx != sy:
            return _helix(radius, height, twist, fn, fs, fa)
        return _conical(radius, height, twist, sx, fn, fs, fa)
    if sx != sy:
        if delta < GRID_FINE or not math.isfinite(fn):
            return 1
        if fn > 0:
            return max(int(fn), 1)
        return max(math.ceil(math.hypot(delta, height) / fs), 1)
    return 1


def _ring(p: NDArray[np.float64], angle: float, s: tuple[float, float], z: float) -> NDArray[np.float64]:
    c, si = math.cos(math.radians(-angle)), math.sin(math.radians(-angle))
    out = np.empty((len(p), 3))
    out[:, 0] = s[0] * (c * p[:, 0] - si * p[:, 1])
    out[:, 1] = s[1] * (si * p[:, 0] + c * p[:, 1])
    out[:, 2] = z
    return out


def _longer(v1: NDArray[np.float64], v2: NDArray[np.float64]) -> int:
    """OpenSCAD's ``sgn_vdiff``: -1 if |v1| < |v2|, 1 if greater, 0 within a relative 1e-5."""
    l1, l2 = float(np.hypot(*v1)), float(np.hypot(*v2))
    return (-1 if l1 < l2 else 1) if 2 * abs(l1 - l2) * 1e5 > l1 + l2 else 0


class _Slice:
    """One slice's transform: rings at (angle, scale, z) below and above."""

    def __init__(self, lo: tuple[float, tuple[float, float], float], hi: tuple[float, tuple[float, float], float]):
        self.lo, self.hi = lo, hi
        self.back_twist = hi[0] <= lo[0]
        self.any_zero = hi[1][0] == 0.0 or hi[1][1] == 0.0


def _openscad_first(b: NDArray[np.float64], t: NDArray[np.float64], i: int, j: int, positive: bool, sl: _Slice) -> bool:
    """Whether OpenSCAD splits the quad of edge i -> j along (bottom i, top j)."""
    sign = _longer(b[i, :2] - t[j, :2], b[j, :2] - t[i, :2])
    flip = (not positive) != sl.back_twist
    first = sign == -1 or (sign == 0 and not flip)
    return first != sl.any_zero


def _slice_solid(
    cell: NDArray[np.float64], edges: list[tuple[str, Any]], prio: tuple[int, int], sl: _Slice, scale: float,
) -> Any:
    """The slice of one convex cell, or None when its hull does not join corresponding corners."""
    from ..csg.tree import Difference
    from ..kinds.polyhedron import ConvexPolyhedron

    b = _ring(cell, *sl.lo)
    t = _ring(cell, *sl.hi)
    k = len(cell)
    pts = np.vstack([b, t])
    centre = pts.mean(axis=0)
    flat = 1e-10 * scale**3
    cuts = []
    cut_points: list[NDArray[np.float64]] = []
    for i in range(k):
        j = (i + 1) % k
        o = float(np.linalg.det(np.array([b[j] - b[i], t[j] - b[i], t[i] - b[i]])))
        tris = [(b[i], b[j], t[j]), (b[i], t[j], t[i])] if o < 0 else [(b[i], b[j], t[i]), (b[j], t[j], t[i])]
        for p0, p1, p2 in tris:
            n = np.cross(p1 - p0, p2 - p0)
            if float(n @ n) <= (1e-12 * scale * scale) ** 2:
                continue
            if n @ (centre - p0) > 0:
                n = -n
            if float(np.max((pts - p0) @ n)) > 1e-9 * scale * float(np.linalg.norm(n)):
                return None  # the hull joins other corners: not this slice's bands
        if abs(o) <= flat:
            continue  # a planar quad: both splits agree
        what, info = edges[i]
        if what == "outer":
            first = _openscad_first(b, t, i, j, info, sl)
        else:  # a diagonal shared with another cell: the first-listed cell keeps its convex side
            first = (o < 0) if prio < info else (o > 0)
        if first != (o < 0):
            cuts.append(ConvexPolyhedron(np.array([b[i], b[j], t[j], t[i]])))
            cut_points.append(np.array([b[i], b[j], t[j], t[i]]))
    if sl.hi[1] == (0.0, 0.0):
        pts = np.vstack([b, [[0.0, 0.0, sl.hi[2]]]])
    hull = ConvexPolyhedron(pts)  # type: ignore[arg-type]
    if _any_overlap(cut_points, scale):  # two concave bands of one piece cross: no such solid
        raise InvalidGeometryError(
            "linear_extrude.slices: the turn per slice is too large for an exact form of this outline "
            "(its slices' bands cross); give more slices"
        )
    return Difference((hull, *cuts)) if cuts else hull


def _key(p: Any) -> _Key:
    return (float(p[0]), float(p[1]))


def twisted_pieces(
    cells: list[NDArray[np.float64]], outer: dict[tuple[_Key, _Key], bool], slices: list[_Slice], scale: float,
) -> list[Any]:
    """The slices of every convex cell (see the module notes); ``outer`` maps each directed outline
    edge (inside on the left) to its outline's orientation (True: an outer ring, False: a hole)."""
    owners: dict[frozenset[_Key], list[tuple[int, int]]] = {}
    todo: list[tuple[NDArray[np.float64], tuple[int, int]]] = [(c, (i, 0)) for i, c in enumerate(cells)]
    for c, prio in todo:
        for a in range(len(c)):
            owners.setdefault(frozenset((_key(c[a]), _key(c[(a + 1) % len(c)]))), []).append(prio)
    out: list[Any] = []
    while todo:
        cell, prio = todo.pop()
        edges: list[tuple[str, Any]] = []
        for a in range(len(cell)):
            p, q = _key(cell[a]), _key(cell[(a + 1) % len(cell)])
            if (p, q) in outer:
                edges.append(("outer", outer[(p, q)]))
            else:
                others = [o for o in owners.get(frozenset((p, q)), []) if o != prio]
                edges.append(("inner", others[0] if others else (-1, -1)))
        solids = [_slice_solid(cell, edges, prio, sl, scale) for sl in slices]
        if all(s is not None for s in solids):
            out.extend(solids)
            continue
        if prio[1] != 0:
            raise InvalidGeometryError(
                "linear_extrude.slices: the turn per slice is too large for an exact form of this outline "
                f"({len(slices)} slices); give more slices"
            )
        fan_centre = cell.mean(axis=0)
        for a in range(len(cell)):
            tri = np.array([fan_centre, cell[a], cell[(a + 1) % len(cell)]])
            sub = (prio[0], a + 1)
            todo.append((tri, sub))
            for e in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
                owners.setdefault(frozenset((_key(e[0]), _key(e[1]))), []).append(sub)
        for a in range(len(cell)):  # the cell itself no longer owns its edges
            owners[frozenset((_key(cell[a]), _key(cell[(a + 1) % len(cell)])))].remove(prio)
    return out


def _any_overlap(tetras: list[NDArray[np.float64]], scale: float) -> bool:
    """Whether two of the cut tetrahedra share interior (no separating axis among their face
    normals and edge cross products): then the slice's concave bands cross each other."""
    if len(tetras) < 2:
        return False
    pairs = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)]
    eps = 1e-9 * scale
    for x in range(len(tetras)):
        for y in range(x + 1, len(tetras)):
            a, b = tetras[x], tetras[y]
            lo = np.maximum(a.min(axis=0), b.min(axis=0))
            hi = np.minimum(a.max(axis=0), b.max(axis=0))
            if np.any(hi - lo <= eps):
                continue
            ea = [a[j] - a[i] for i, j in pairs]
            eb = [b[j] - b[i] for i, j in pairs]
            axes = [np.cross(ea[0], ea[1]), np.cross(ea[0], ea[2]), np.cross(ea[1], ea[2]), np.cross(ea[3], ea[4]),
                    np.cross(eb[0], eb[1]), np.cross(eb[0], eb[2]), np.cross(eb[1], eb[2]), np.cross(eb[3], eb[4])]
            axes += [np.cross(u, v) for u in ea for v in eb]
            separated = False
            for n in axes:
                norm = float(np.linalg.norm(n))
                if norm <= 1e-12 * scale * scale:
                    continue
                pa, pb = a @ n / norm, b @ n / norm
                if pa.max() <= pb.min() + eps or pb.max() <= pa.min() + eps:
                    separated = True
                    break
            if not separated:
                return True
    return False


def make_slices(
    n: int, z0: float, z1: float, twist: float, scale: tuple[float, float],
) -> list[_Slice]:
    """OpenSCAD's ``n`` slices: ring j at angle ``twist j / n``, scale ``1 - (1 - s) j / n``, height."""
    rings = []
    for j in range(n + 1):
        s = (1 - (1 - scale[0]) * j / n, 1 - (1 - scale[1]) * j / n)
        rings.append((twist * j / n, s, z0 + (z1 - z0) * j / n))
    return [_Slice(rings[j], rings[j + 1]) for j in range(n)]


def _outer_edges(region: Any) -> dict[tuple[_Key, _Key], bool]:
    """Every directed edge of a shapely region's rings (inside on the left): outer ring or hole."""
    import shapely

    out: dict[tuple[_Key, _Key], bool] = {}
    for poly in shapely.get_parts(region):
        for ring, positive in [(poly.exterior, True), *((r, False) for r in poly.interiors)]:
            pts = np.asarray(ring.coords)[:-1]
            for a in range(len(pts)):
                out[(_key(pts[a]), _key(pts[(a + 1) % len(pts)]))] = positive
    return out


def _round_slices(leaf: Any, slices: list[_Slice], s: tuple[float, float]) -> list[Any]:
    """A circle's slices: frusta whose centres and radii follow the slices' rings (sheared off the axis)."""
    from ..kinds.truncus import Cylinder, Truncus
    from .leaves import Circle

    if not isinstance(leaf, Circle):
        raise InvalidGeometryError("linear_extrude.twist: a twisted ellipse has no exact form here; "
                                   "polygonise it (circle(..., fn=...)) first")
    if s[0] != s[1]:
        raise InvalidGeometryError(
            f"linear_extrude.scale must be uniform for a circle or ellipse (a cone with non-proportional axes "
            f"is not an isocsg kind), got [{s[0]:g}, {s[1]:g}]")
    c = np.array([leaf.center], dtype=np.float64)
    if not c.any():  # about the axis a twist changes nothing: one frustum
        slices = [_Slice(slices[0].lo, slices[-1].hi)]
    out: list[Any] = []
    for sl in slices:
        b, t = _ring(c, *sl.lo)[0], _ring(c, *sl.hi)[0]
        r0, r1 = leaf.radius * sl.lo[1][0], leaf.radius * sl.hi[1][0]
        dz = t[2] - b[2]
        mid = 0.5 * (b + t)
        if np.array_equal(b[:2], t[:2]):
            if r0 == r1:
                out.append(Cylinder(tuple(mid.tolist()), (0.0, 0.0, dz), r0))
            else:
                out.append(Truncus(tuple(mid.tolist()), (0.0, 0.0, dz), r1, r0))
            continue
        base = Truncus((0.0, 0.0, 0.0), (0.0, 0.0, dz), r1, r0)
        A = np.zeros((3, 4))
        A[0, 0] = A[1, 1] = A[2, 2] = 1.0
        A[:2, 2] = (t[:2] - b[:2]) / dz
        A[:, 3] = mid
        out.append(base.transform(A))
    return out


def _reach(shape: Any, s: tuple[float, float]) -> tuple[float, float]:
    """The largest distance of an outline vertex from the axis, and the largest move by the scale."""
    from .leaves import Circle, ConvexPolygon, Ellipse
    from .shape import iter_leaves

    r = d = 0.0
    k = np.array([1.0 - s[0], 1.0 - s[1]])
    for leaf in iter_leaves(shape):
        if isinstance(leaf, ConvexPolygon):
            p = leaf.array
        elif isinstance(leaf, (Circle, Ellipse)):
            phi = np.linspace(0.0, 2 * math.pi, 361)
            p = np.array(leaf.center) + np.column_stack([np.cos(phi), np.sin(phi)]) @ np.array(leaf.matrix).T
        else:
            continue
        r = max(r, float(np.max(np.hypot(p[:, 0], p[:, 1]))))
        d = max(d, float(np.max(np.hypot(*(p * k).T))))
    return r, d


def sliced_extrude(
    shape: Any, z0: float, z1: float, twist: float, s: tuple[float, float], n: int | None,
    details: tuple[float, float, float], combine: Any,
) -> Any:
    """``linear_extrude`` with a twist or a non-uniform scale (see the module notes); None if empty."""
    from ..csg.extrude import merged_triangulation
    from ..csg.tree import Union
    from .leaves import ConvexPolygon
    from .measure import is_polygonal, to_shapely
    from .shape import fold

    if n is None:
        radius, delta = _reach(shape, s)
        fn, fs, fa = details
        n = slice_count(radius, delta, z1 - z0, twist, s, fn=fn, fs=fs, fa=fa)
        if n > 10000:
            raise InvalidGeometryError(f"linear_extrude.slices: {n} slices (from fn, fs, fa) exceed 10000")
    slices = make_slices(n, z0, z1, twist, s)

    def stack(cells: list[NDArray[np.float64]], outer: dict[tuple[_Key, _Key], bool], size: float) -> Any:
        parts = twisted_pieces(cells, outer, slices, size)
        return parts[0] if len(parts) == 1 else Union(tuple(parts))

    if is_polygonal(shape):
        import shapely

        region = shapely.orient_polygons(shapely.normalize(to_shapely(shape)))
        if region.is_empty:
            return None
        x0, y0, x1, y1 = region.bounds
        size = max(x1 - x0, y1 - y0, z1 - z0)
        cells = [c for part in shapely.get_parts(region) for c in merged_triangulation(part, size)]
        return stack(cells, _outer_edges(region), size)

    def leaf(l: Any) -> Any:
        if isinstance(l, ConvexPolygon):
            p = l.array
            size = max(float(np.max(np.ptp(p, axis=0))), z1 - z0)
            outer = {(_key(p[a]), _key(p[(a + 1) % len(p)])): True for a in range(len(p))}
            return stack([p], outer, size)
        parts = _round_slices(l, slices, s)
        return parts[0] if len(parts) == 1 else Union(tuple(parts))

    return fold(shape, leaf, combine)
