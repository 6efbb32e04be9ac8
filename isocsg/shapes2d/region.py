"""Polygonal regions: fill rules over rings, convex partitions, and 2D shapes from regions.

A set of closed rings fills a region by a rule: ``"evenodd"`` (OpenSCAD's
``polygon`` with several paths) or ``"nonzero"`` (TrueType and CFF glyphs).
:func:`fill` nodes the rings' segments (shapely), takes the faces of the
arrangement and keeps a face when the winding number of the rings around one
of its interior points passes the rule. It is exact up to the rounding of the
crossing points of rings that cross (rings that do not cross keep their own
coordinates).

:func:`convex_pieces` splits a region into convex pieces that cover it
exactly: shapely's constrained Delaunay triangulation (every triangle inside,
every ring edge kept), then Hertel-Mehlhorn merging across diagonals while the
merged piece stays convex (at most four times the minimal number of pieces).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..csg.extrude import merged_triangulation
from ..errors import InvalidGeometryError
from .leaves import ConvexPolygon
from .shape import EMPTY, Shape2D, Union2D

__all__ = ["fill", "winding_numbers", "convex_pieces", "shape_from_region", "RULES"]

RULES = ("evenodd", "nonzero")


def winding_numbers(points: NDArray[np.float64], rings: Sequence[NDArray[np.float64]]) -> NDArray[np.int64]:
    """The winding number of the closed rings around each point (points on an edge: either side)."""
    pts = np.asarray(points, dtype=np.float64).reshape(-1, 2)
    a = np.concatenate([r for r in rings])
    b = np.concatenate([np.roll(r, -1, axis=0) for r in rings])
    w = np.zeros(len(pts), dtype=np.int64)
    for k in range(0, len(pts), 256):  # bounded memory: 256 points x all edges at a time
        p = pts[k : k + 256, None, :]
        side = (b[None, :, 0] - a[None, :, 0]) * (p[..., 1] - a[None, :, 1]) - (p[..., 0] - a[None, :, 0]) * (
            b[None, :, 1] - a[None, :, 1]
        )
        up = (a[None, :, 1] <= p[..., 1]) & (b[None, :, 1] > p[..., 1]) & (side > 0)
        down = (a[None, :, 1] > p[..., 1]) & (b[None, :, 1] <= p[..., 1]) & (side < 0)
        w[k : k + 256] = up.sum(axis=1) - down.sum(axis=1)
    return w


def fill(rings: Sequence[Any], rule: str = "evenodd", *, name: str = "polygon") -> Any:
    """The region the closed ``rings`` fill under ``rule``: a shapely Polygon or MultiPolygon (maybe empty).

    Examples
    --------
    >>> outer = [(0, 0), (4, 0), (4, 4), (0, 4)]
    >>> inner = [(1, 1), (3, 1), (3, 3), (1, 3)]
    >>> fill([outer, inner], "evenodd").area, fill([outer, inner], "nonzero").area
    (12.0, 16.0)
    """
    import shapely

    if rule not in RULES:
        raise InvalidGeometryError(f"{name}.rule must be one of {RULES}, got {rule!r}")
    arrs = []
    for r in rings:
        r = np.asarray(r, dtype=np.float64)
        if len(r) > 1 and np.all(r[0] == r[-1]):
            r = r[:-1]
        keep = np.ones(len(r), dtype=bool)
        keep[1:] = np.any(r[1:] != r[:-1], axis=1)
        r = r[keep]
        if len(r) >= 3:
            arrs.append(r)
    if not arrs:
        return shapely.Polygon()
    lines = [shapely.LineString(np.vstack([r, r[:1]])) for r in arrs]
    noded = shapely.union_all(lines)
    faces = shapely.get_parts(shapely.polygonize(shapely.get_parts(noded)))
    faces = faces[shapely.area(faces) > 0]
    if len(faces) == 0:
        return shapely.Polygon()
    probes = shapely.get_coordinates(shapely.point_on_surface(faces))
    w = winding_numbers(probes, arrs)
    inside = (w % 2 == 1) if rule == "evenodd" else (w != 0)
    region = shapely.union_all(faces[inside]) if np.any(inside) else shapely.Polygon()
    return shapely.normalize(region)


def convex_pieces(region: Any) -> list[NDArray[np.float64]]:
    """Convex pieces (counter-clockwise vertex arrays) that tile a shapely Polygon or MultiPolygon.

    Examples
    --------
    >>> from shapely.geometry import Polygon
    >>> ell = Polygon([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)])
    >>> len(convex_pieces(ell))
    2
    """
    import shapely

    pieces: list[NDArray[np.float64]] = []
    for part in shapely.get_parts(region):
        if part.is_empty or part.area <= 0:
            continue
        x0, y0, x1, y1 = part.bounds
        scale = float(max(x1 - x0, y1 - y0))
        if len(part.interiors) == 0 and _is_convex(np.asarray(part.exterior.coords)[:-1], scale):
            ring = np.asarray(shapely.orient_polygons(part).exterior.coords)[:-1]
            pieces.append(ring)
            continue
        pieces.extend(merged_triangulation(part, scale))
    return pieces


def _is_convex(ring: NDArray[np.float64], scale: float) -> bool:
    turns = (np.roll(ring, -1, 0)[:, 0] - ring[:, 0]) * (np.roll(ring, -2, 0)[:, 1] - ring[:, 1]) - (
        np.roll(ring, -1, 0)[:, 1] - ring[:, 1]
    ) * (np.roll(ring, -2, 0)[:, 0] - ring[:, 0])
    tol = 1e-12 * scale * scale
    return bool(np.all(turns >= -tol) or np.all(turns <= tol))


def shape_from_region(region: Any) -> Shape2D:
    """The 2D shape of a shapely region: one :class:`ConvexPolygon`, a union of convex pieces, or :data:`EMPTY`."""
    leaves = [ConvexPolygon(tuple(map(tuple, p))) for p in convex_pieces(region)]
    if not leaves:
        return EMPTY
    return leaves[0] if len(leaves) == 1 else Union2D(tuple(leaves))
