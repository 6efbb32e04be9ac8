"""Straight extrusion of planar polygons into exact solids.

A polygon in the xy plane (a shapely ``Polygon`` or ``MultiPolygon``, holes
allowed) swept along +z is the union of the prisms over any partition of the
polygon into convex pieces. Each prism is a :class:`ConvexPolyhedron` (exact),
so the extruded solid is exact too: its volume is the polygon's area times
the height, its faces are the polygon's edges swept straight up.

The convex partition is shapely's constrained Delaunay triangulation (every
triangle inside the polygon, every polygon edge kept) with the triangles merged
across their shared diagonals while the merged piece stays convex
(Hertel-Mehlhorn: at most four times the minimal number of convex pieces).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._validation import MAX_ABS_COORD, MAX_VERTICES, length_floor, scalar
from ..errors import InvalidGeometryError
from ..kinds.base import Solid
from ..kinds.polyhedron import ConvexPolyhedron

__all__ = ["extrude", "extrude_rings", "convex_partition", "merged_triangulation", "prisms", "prism"]


def _polygons(polygon: Any, name: str) -> list[Any]:
    """The non-empty polygons of a shapely Polygon or MultiPolygon, checked."""
    import shapely
    from shapely.geometry import MultiPolygon, Polygon

    if isinstance(polygon, Polygon):
        parts = [polygon]
    elif isinstance(polygon, MultiPolygon):
        parts = list(polygon.geoms)
    else:
        raise InvalidGeometryError(f"{name} must be a shapely Polygon or MultiPolygon, got {type(polygon).__name__}")
    if polygon.is_empty:
        raise InvalidGeometryError(f"{name} must have an area > 0, got an empty polygon")
    coords = shapely.get_coordinates(polygon)
    if not np.all(np.isfinite(coords)):
        raise InvalidGeometryError(f"{name} must have finite coordinates")
    if np.max(np.abs(coords)) > MAX_ABS_COORD:
        raise InvalidGeometryError(f"{name} must have coordinates within +-{MAX_ABS_COORD:g}")
    if len(coords) > MAX_VERTICES:
        raise InvalidGeometryError(f"{name} must have at most {MAX_VERTICES} vertices, got {len(coords)}")
    if not polygon.is_valid:
        reason = shapely.is_valid_reason(polygon)
        raise InvalidGeometryError(f"{name} must be a valid polygon (shapely.make_valid repairs it), got {reason}")
    if polygon.is_empty or polygon.area <= 0:
        raise InvalidGeometryError(f"{name} must have an area > 0, got {polygon.area:g}")
    return [p for p in parts if p.area > 0]


def _cross(o: NDArray[np.float64], a: NDArray[np.float64], b: NDArray[np.float64]) -> float:
    return float((a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]))


def _convex_at(pts: NDArray[np.float64], prev: int, here: int, nxt: int, scale: float) -> bool:
    """A counter-clockwise corner that turns left or goes straight (within rounding). The rounding
    is relative to the corner's own edges, not the polygon's size: a merged piece much smaller than
    its polygon must still pass :class:`~isocsg.shapes2d.ConvexPolygon`'s test at its own size."""
    edges = float(np.linalg.norm(pts[here] - pts[prev]) * np.linalg.norm(pts[nxt] - pts[here]))
    return _cross(pts[prev], pts[here], pts[nxt]) >= -1e-12 * min(scale * scale, edges)


def convex_partition(polygon: Any, *, name: str = "polygon") -> list[NDArray[np.float64]]:
    """Split a polygon into convex pieces that cover it exactly.

    Parameters
    ----------
    polygon : shapely.Polygon or shapely.MultiPolygon
        Valid, with an area > 0; holes allowed.

    Returns
    -------
    list of ndarray, shape (k, 2)
        Each piece's vertices, counter-clockwise. The pieces do not overlap
        and their areas add up to the polygon's.

    Raises
    ------
    InvalidGeometryError
        If ``polygon`` is not a valid polygon with an area.

    Examples
    --------
    >>> from shapely.geometry import Polygon
    >>> ell = Polygon([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)])
    >>> len(convex_partition(ell))
    2
    """
    import shapely

    parts = _polygons(polygon, name)
    pieces: list[NDArray[np.float64]] = []
    for part in parts:
        part = shapely.normalize(part)
        scale = float(max(part.bounds[2] - part.bounds[0], part.bounds[3] - part.bounds[1]))
        pieces.extend(merged_triangulation(part, scale))
    return pieces


def merged_triangulation(part: Any, scale: float) -> list[NDArray[np.float64]]:
    """The convex pieces of one valid shapely Polygon (holes allowed): its constrained Delaunay
    triangles, merged across shared diagonals while the merged piece stays convex
    (Hertel-Mehlhorn). ``scale`` is the polygon's size, for the zero-area and convexity tests."""
    import shapely

    tris = shapely.get_parts(shapely.constrained_delaunay_triangles(part))
    # Shared vertex indices: constrained triangles reuse the polygon's own coordinates exactly.
    index: dict[tuple[float, float], int] = {}
    faces: list[list[int]] = []
    for t in tris:
        ring = np.asarray(t.exterior.coords)[:3]
        if _cross(ring[0], ring[1], ring[2]) < 0:
            ring = ring[::-1]
        if abs(_cross(ring[0], ring[1], ring[2])) <= 1e-14 * scale * scale:
            continue  # a sliver of zero area covers nothing
        faces.append([index.setdefault((float(x), float(y)), len(index)) for x, y in ring])
    pts = np.array(list(index), dtype=np.float64).reshape(-1, 2)
    return [pts[f] for f in _merge_convex(faces, pts, scale)]


def _merge_convex(faces: list[list[int]], pts: NDArray[np.float64], scale: float) -> list[list[int]]:
    """Hertel-Mehlhorn: remove shared diagonals whose two pieces merge into a convex one."""
    alive: dict[int, list[int]] = dict(enumerate(faces))
    owner: dict[tuple[int, int], int] = {}  # directed edge -> the piece that has it
    for k, f in alive.items():
        for i in range(len(f)):
            owner[(f[i], f[(i + 1) % len(f)])] = k
    todo = [e for e in owner if (e[1], e[0]) in owner and e[0] < e[1]]
    for a, b in todo:
        p, q = owner.get((a, b)), owner.get((b, a))
        if p is None or q is None or p == q:
            continue
        fp, fq = alive[p], alive[q]
        ip, iq = fp.index(a), fq.index(b)  # fp has a -> b, fq has b -> a
        # Merged ring: fp from b round to a, then fq from a round to b (both ends excluded).
        ring = [fp[(ip + 1 + j) % len(fp)] for j in range(len(fp))]  # b ... a
        ring += [fq[(iq + 2 + j) % len(fq)] for j in range(len(fq) - 2)]  # after a ... before b
        n = len(ring)
        ia, ib = ring.index(a), ring.index(b)
        if not (
            _convex_at(pts, ring[ia - 1], a, ring[(ia + 1) % n], scale)
            and _convex_at(pts, ring[ib - 1], b, ring[(ib + 1) % n], scale)
        ):
            continue
        del alive[q]
        alive[p] = ring
        for i in range(n):
            owner[(ring[i], ring[(i + 1) % n])] = p
        owner.pop((a, b), None)
        owner.pop((b, a), None)
    return list(alive.values())


def extrude(polygon: Any, height: float, *, center: bool = False) -> Solid:
    """The straight extrusion of a polygon in the xy plane along +z.

    Parameters
    ----------
    polygon : shapely.Polygon or shapely.MultiPolygon
        A valid polygon (holes allowed) with an area > 0.
    height : float
        Extrusion length, > 0.
    center : bool, default False
        Span ``z`` in ``[-height/2, height/2]`` instead of ``[0, height]``.

    Returns
    -------
    Solid
        One :class:`ConvexPolyhedron` for a convex polygon, else the union of
        the prisms over a convex partition (:func:`convex_partition`). Its
        volume is exactly ``polygon.area * height``.

    Raises
    ------
    InvalidGeometryError
        On an invalid or empty polygon, or a height that is not > 0.

    Examples
    --------
    >>> from shapely.geometry import Polygon
    >>> from isocsg import volume
    >>> ring = Polygon([(-2, -2), (2, -2), (2, 2), (-2, 2)], [[(-1, -1), (1, -1), (1, 1), (-1, 1)]])
    >>> solid = extrude(ring, 0.5)
    >>> round(volume(solid), 12)
    6.0
    """
    h = scalar("extrude.height", height, low=0.0, high=MAX_ABS_COORD)
    if not isinstance(center, bool):
        raise InvalidGeometryError(f"extrude.center must be a boolean, got {type(center).__name__}")
    z0, z1 = (-h / 2, h / 2) if center else (0.0, h)
    return prisms(polygon, z0, z1)


def prisms(polygon: Any, z0: float, z1: float) -> Solid:
    """The extrusion of ``polygon`` between the planes ``z = z0`` and ``z = z1 > z0`` (see :func:`extrude`)."""
    from .tree import union_all

    if not (math.isfinite(z0) and math.isfinite(z1)) or z1 <= z0:
        raise InvalidGeometryError(f"extrude.height must be > 0, got {z1 - z0:g}")
    pieces = convex_partition(polygon, name="extrude.polygon")
    solids = [prism(piece, z0, z1) for piece in pieces]
    return solids[0] if len(solids) == 1 else union_all(solids)


def prism(piece: NDArray[np.float64], z0: float, z1: float) -> ConvexPolyhedron:
    """The straight prism over a convex polygon between ``z = z0`` and ``z = z1 > z0``, built from
    its known faces (no convex hull: a model of thousands of extruded polygons spent most of its
    loading time in one hull per prism).

    Parameters
    ----------
    piece : ndarray, shape (k, 2)
        A convex polygon, counter-clockwise (collinear corners allowed).

    Returns
    -------
    ConvexPolyhedron
        Equal to ``ConvexPolyhedron`` of the same ``2k`` points (same ``vertices``); its
        hull vertices are the strict corners, its faces the two ends and one quad per edge.
        A polygon that is not strictly convex and counter-clockwise, or too small for its
        position, goes through the full hull build, which accepts or refuses it.
    """
    p = np.asarray(piece, dtype=np.float64)
    k = len(p)
    verts = np.empty((2 * k, 3))
    verts[:k, :2], verts[:k, 2] = p, z0
    verts[k:, :2], verts[k:, 2] = p, z1
    if k < 3 or not z1 > z0:
        return ConvexPolyhedron(verts)  # type: ignore[arg-type]  # the full build decides
    lo, hi = verts.min(axis=0), verts.max(axis=0)
    size = float(max(hi[0] - lo[0], hi[1] - lo[1]))
    nxt = np.arange(1, k + 1) % k
    e_out = p[nxt] - p
    e_in = e_out[np.arange(-1, k - 1)]
    turn = e_in[:, 0] * e_out[:, 1] - e_in[:, 1] * e_out[:, 0]
    keep = turn > 1e-12 * size * size
    m = int(keep.sum())
    if (
        m < 3 or not (math.isfinite(size) and math.isfinite(z0) and math.isfinite(z1))
        or bool((turn < -1e-12 * size * size).any()) or min(size, z1 - z0) < length_floor(lo, hi)
    ):
        return ConvexPolyhedron(verts)  # type: ignore[arg-type]  # the full build decides
    strict = p[keep]
    hv = np.empty((2 * m, 3))
    hv[:m, :2], hv[:m, 2] = strict, z0
    hv[m:, :2], hv[m:, 2] = strict, z1
    i = np.arange(m)
    j = (i + 1) % m
    edge = strict[j] - strict
    side = np.zeros((m, 3))
    side[:, 0], side[:, 1] = edge[:, 1], -edge[:, 0]  # outward: the inside is on the left
    side /= np.sqrt(side[:, 0] ** 2 + side[:, 1] ** 2)[:, None]
    normals = np.vstack([[0.0, 0.0, -1.0], [0.0, 0.0, 1.0], side])
    quads = np.column_stack([i, j, m + j, m + i])
    faces = [i[::-1].copy(), i + m, *quads]
    offsets = np.concatenate([[-z0, z1], side[:, 0] * strict[:, 0] + side[:, 1] * strict[:, 1]])
    fan = np.arange(1, m - 1)
    tris = np.vstack([
        np.column_stack([np.full(m - 2, m - 1), m - 1 - fan, m - 2 - fan]),  # the bottom, reversed
        np.column_stack([np.full(m - 2, m), m + fan, m + fan + 1]),
        quads[:, [0, 1, 2]], quads[:, [0, 2, 3]],
    ]).astype(np.int64)
    out = object.__new__(ConvexPolyhedron)
    object.__setattr__(out, "vertices", tuple(map(tuple, verts.tolist())))
    for arr in (hv, normals, offsets, tris):
        arr.setflags(write=False)
    for name, value in (("hull_vertices", hv), ("faces", tuple(faces)), ("face_normals", normals),
                        ("face_offsets", offsets), ("triangles", tris)):
        object.__setattr__(out, name, value)
    return out


def _ring(name: str, value: Any) -> NDArray[np.float64]:
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if not isinstance(value, (list, tuple)) or not all(isinstance(p, (list, tuple)) and len(p) == 2 for p in value):
        raise InvalidGeometryError(f"{name} must be a list of [x, y] points, got {type(value).__name__}")
    if len(value) < 3:
        raise InvalidGeometryError(f"{name} must have at least 3 points, got {len(value)}")
    if len(value) > MAX_VERTICES:
        raise InvalidGeometryError(f"{name} must have at most {MAX_VERTICES} points, got {len(value)}")
    for p in value:
        for x in p:
            if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x) or abs(x) > MAX_ABS_COORD:
                raise InvalidGeometryError(f"{name} must hold finite numbers within +-{MAX_ABS_COORD:g}, got {x!r}")
    return np.asarray(value, dtype=np.float64)


def extrude_rings(polygon: Any, height: float, holes: Any = (), center: bool = False) -> Solid:
    """:func:`extrude` of a polygon given as rings of ``[x, y]`` points (the scene files' ``extrude`` node).

    Parameters
    ----------
    polygon : sequence of [x, y]
        The outer ring (at least 3 points; closing point optional).
    height : float
        Extrusion length, > 0.
    holes : sequence of rings, optional
        Inner rings, inside the outer one.
    center : bool, default False
        Span ``z`` in ``[-height/2, height/2]`` instead of ``[0, height]``.

    Raises
    ------
    InvalidGeometryError
        Naming the field (``extrude.polygon``, ``extrude.holes``, ``extrude.height``).
    """
    from shapely.geometry import Polygon

    outer = _ring("extrude.polygon", polygon)
    if not isinstance(holes, (list, tuple)):
        raise InvalidGeometryError(f"extrude.holes must be a list of rings, got {type(holes).__name__}")
    inner = [_ring(f"extrude.holes[{k}]", h) for k, h in enumerate(holes)]
    return extrude(Polygon(outer, inner), height, center=center)
