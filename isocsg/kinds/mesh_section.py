"""Exact plane sections of a closed triangle mesh.

Each vertex's height above the plane decides its side; a height of exactly zero counts as
above (a symbolic shift of the plane downwards by an infinitesimal), so every face is either
cut in one segment or not at all, and the segments close into loops. A cut point is computed
from its edge taken in one canonical direction (lower vertex index first), so the two faces
sharing an edge produce the bit-identical point and the loops join exactly. The loops are
polygonised by shapely and combined even-odd (holes, nested islands).
"""

from __future__ import annotations

import numpy as np
import shapely
from numpy.typing import NDArray
from shapely.geometry import Polygon

__all__ = ["mesh_section"]


def mesh_section(vertices: NDArray[np.float64], faces: NDArray[np.int64], F: NDArray[np.float64]) -> Polygon:
    """The section of the mesh by the plane of the frame ``F`` (columns u, v, n, origin) in its 2D
    coordinates, as a shapely polygon or multipolygon (empty when the plane misses)."""
    from .planar import EMPTY

    o, u, v, n = F[:3, 3], F[:3, 0], F[:3, 1], F[:3, 2]
    h = (vertices - o) @ n
    above = h >= 0.0
    fa = above[faces]
    cut = fa.any(axis=1) & ~fa.all(axis=1)
    if not cut.any():
        return EMPTY
    tri = faces[cut]
    side = above[tri]
    # the two edges of each cut face that cross: those whose ends lie on different sides
    ends = []
    for i, j in ((0, 1), (1, 2), (2, 0)):
        crosses = side[:, i] != side[:, j]
        ends.append((crosses, tri[:, i], tri[:, j]))
    pts = []
    for crosses, a, b in ends:
        lo_i, hi_i = np.minimum(a, b), np.maximum(a, b)
        p, q = vertices[lo_i], vertices[hi_i]
        hp, hq = h[lo_i], h[hi_i]
        with np.errstate(invalid="ignore", divide="ignore"):
            s = hp / (hp - hq)
            x = p + s[:, None] * (q - p)
        pts.append(np.where(crosses[:, None], x, np.nan))
    P = np.stack(pts, axis=1)  # (k, 3 edges, 3), NaN on the edge that does not cross
    ok = np.isfinite(P[:, :, 0])
    seg = P[ok].reshape(-1, 2, 3)
    seg2 = np.stack([(seg - o) @ u, (seg - o) @ v], axis=-1)
    lines = shapely.linestrings(seg2)
    merged = shapely.union_all(lines)
    faces2 = shapely.get_parts(shapely.polygonize(shapely.get_parts(merged)))
    if not len(faces2):
        return EMPTY
    # even-odd: a polygonised face is in the section when it is nested in an odd number of faces'
    # outlines (polygonize cuts an inner face out of the one around it: compare with shells)
    shells = shapely.polygons(shapely.get_exterior_ring(faces2))
    tree = shapely.STRtree(shells)
    reps = shapely.point_on_surface(faces2)
    pairs = tree.query(reps, predicate="within")
    depth = np.bincount(pairs[0], minlength=len(faces2))
    keep = faces2[depth % 2 == 1]
    out = shapely.union_all(keep)
    return out if not out.is_empty else EMPTY
