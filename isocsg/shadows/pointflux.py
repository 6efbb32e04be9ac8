"""Exact flux of an isotropic point source onto planar convex polygons (closed-form solid angles).

An isotropic point source of intensity I at P sends ``I Omega`` lumens onto a
polygon, ``Omega`` the solid angle of the part of the polygon it sees. The
radiosity solve uses it for the mean direct illuminance of a patch,
``I Omega / A``: exact, where Gauss points on the patch would carry the
quadrature error of the ``cos / r^2`` integrand (largest for a source close to
a patch) and of the hard shadow's edge crossing the patch.

The visible part (:func:`visible_solid_angle`): a convex occluder piece K
shades the patch where the segment from P meets K, i.e. by the central
projection from P onto the patch's plane of K's part between that plane and
the parallel plane through P (the slab). That part's vertices are K's
vertices in the slab and its edges' crossings of the slab's planes; the
shadow is the convex hull of their projections. The patch minus the union of
the shadows (shapely, in the patch's plane) is a polygon with holes, whose
solid angle is the signed fan sum below over its rings (exterior counter-
clockwise, holes clockwise: a signed fan over any closed ring integrates
exactly, convex or not).

The solid angle of a convex polygon q_0 .. q_{m-1} is the sum over its fan
triangles (q_0, q_k, q_{k+1}) of Van Oosterom and Strackee's formula
(IEEE Trans. Biomed. Eng. 30, 1983)::

    tan(Omega_t / 2) = a . (c x b) / (|a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|)

with a, b, c the vertices relative to P, taken through ``atan2`` so that no
quadrant is lost. The fan triangles of a convex polygon share one
orientation, so their signed angles add up; the sign says which side of the
polygon P lies on.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .convex_regions import ConvexPiece

__all__ = ["signed_solid_angles", "visible_rings", "visible_solid_angle", "fan_quadrature", "NEAR_SOURCE"]

#: A piece closer to the source than this fraction of the source's height over the patch makes
#: :func:`visible_solid_angle` decline (its shadow would reach out of any bounded window).
NEAR_SOURCE = 1e-6


def signed_solid_angles(apex: NDArray[np.float64], verts: NDArray[np.float64],
                        off: NDArray[np.int64]) -> NDArray[np.float64]:
    """Signed solid angle of each convex polygon seen from ``apex``.

    Parameters
    ----------
    apex : ndarray, shape (3,)
    verts : ndarray, shape (v, 3)
        The polygons' vertices, polygon k being ``verts[off[k]:off[k + 1]]``.
    off : ndarray of int, shape (n + 1,)

    Returns
    -------
    ndarray, shape (n,)
        Positive when ``apex`` lies on the side of the polygon's normal
        (counter-clockwise vertices about it), negative behind; ``|Omega| <= 2 pi``.

    Examples
    --------
    A unit square seen from 0.5 above its centre covers a sixth of the sphere:

    >>> sq = np.array([[-0.5, -0.5, 0], [0.5, -0.5, 0], [0.5, 0.5, 0], [-0.5, 0.5, 0]])
    >>> om = signed_solid_angles(np.array([0, 0, 0.5]), sq, np.array([0, 4]))
    >>> bool(np.isclose(om[0], 4 * np.pi / 6, rtol=1e-14))
    True
    """
    counts = np.diff(off)
    ntri = np.maximum(counts - 2, 0)
    owner = np.repeat(np.arange(len(counts)), ntri)
    first = off[:-1][owner]
    k = np.arange(int(ntri.sum())) - np.repeat(np.cumsum(ntri) - ntri, ntri) + 1
    a = verts[first] - apex
    b = verts[first + k] - apex
    c = verts[first + k + 1] - apex
    la, lb, lc = (np.linalg.norm(x, axis=1) for x in (a, b, c))
    num = np.einsum("ij,ij->i", a, np.cross(c, b))  # > 0 with apex on the normal's side
    den = (la * lb * lc + np.einsum("ij,ij->i", a, b) * lc + np.einsum("ij,ij->i", a, c) * lb
           + np.einsum("ij,ij->i", b, c) * la)
    return np.asarray(np.bincount(owner, weights=2.0 * np.arctan2(num, den), minlength=len(counts)), dtype=np.float64)


def _shadow_points(piece: ConvexPiece, P: NDArray[np.float64], n: NDArray[np.float64], c: float,
                   top: float) -> NDArray[np.float64]:
    """Points whose hull is K's part in the slab ``c <= n.y <= top`` (vertices and edge crossings)."""
    v = piece.vertices
    d = v @ n
    keep = [v[(d >= c) & (d <= top)]]
    e = piece.edges
    da, db = d[e[:, 0]], d[e[:, 1]]
    for level in (c, top):
        cross = (da - level) * (db - level) < 0
        if cross.any():
            a, b = v[e[cross, 0]], v[e[cross, 1]]
            t = ((level - da[cross]) / (db[cross] - da[cross]))[:, None]
            keep.append(a + t * (b - a))
    return np.vstack(keep)


def visible_rings(apex: ArrayLike, polygon: ArrayLike,
                  pieces: Sequence[ConvexPiece]) -> list[NDArray[np.float64]] | None:
    """The part of a convex polygon that ``apex`` sees past the convex pieces, as 3D rings.

    Parameters
    ----------
    apex : array_like, shape (3,)
    polygon : array_like, shape (m, 3)
        Planar, convex, counter-clockwise about its normal.
    pieces : sequence of ConvexPiece
        The occluders' convex pieces (the polygon's own solid left out).

    Returns
    -------
    list of ndarray (k, 3), or None
        The visible region's rings in the polygon's plane, exteriors
        counter-clockwise about its normal and holes clockwise; empty when
        ``apex`` is not in front of the polygon or sees none of it. None when a
        piece comes within :data:`NEAR_SOURCE` of the source's height over the
        polygon's plane (its shadow is then unbounded in practice).
    """
    import shapely
    from shapely.geometry import Polygon
    from shapely.geometry.polygon import orient

    P = np.asarray(apex, dtype=np.float64)
    q = np.asarray(polygon, dtype=np.float64)
    n = np.cross(q[1] - q[0], q[2] - q[0])
    n /= np.linalg.norm(n)
    c = float(n @ q[0])
    h = float(n @ P) - c
    if not h > 0:
        return []
    e1 = (q[1] - q[0]) / np.linalg.norm(q[1] - q[0])
    e2 = np.cross(n, e1)
    lo = np.minimum(q.min(axis=0), P)
    hi = np.maximum(q.max(axis=0), P)
    shadows = []
    for pc in pieces:
        if np.any(pc.vertices.max(axis=0) < lo) or np.any(pc.vertices.min(axis=0) > hi):
            continue
        if float(np.max(pc.normals @ P - pc.offsets)) < NEAR_SOURCE * h:
            return None
        pts = _shadow_points(pc, P, n, c, c + h * (1 - NEAR_SOURCE))
        if len(pts) < 3:
            continue
        proj = P + (pts - P) * (h / (h - (pts @ n - c)))[:, None]
        hull = shapely.convex_hull(shapely.multipoints(np.c_[(proj - q[0]) @ e1, (proj - q[0]) @ e2]))
        if hull.area > 0:
            shadows.append(hull)
    window = Polygon(np.c_[(q - q[0]) @ e1, (q - q[0]) @ e2])
    seen = window.difference(shapely.union_all(shadows)) if shadows else window
    rings: list[NDArray[np.float64]] = []
    for part in shapely.get_parts(seen):
        if part.geom_type != "Polygon" or part.area <= 0:
            continue
        part = orient(part, sign=1.0)
        for ring in (part.exterior, *part.interiors):
            xy = np.asarray(ring.coords)[:-1]
            rings.append(q[0] + xy[:, :1] * e1 + xy[:, 1:2] * e2)
    return rings


def visible_solid_angle(apex: ArrayLike, polygon: ArrayLike, pieces: Sequence[ConvexPiece]) -> float | None:
    """Solid angle of the part of a convex polygon that ``apex`` sees past the convex pieces.

    Parameters
    ----------
    apex, polygon, pieces
        As for :func:`visible_rings`.

    Returns
    -------
    float or None
        0 when ``apex`` is not in front of the polygon; None as for
        :func:`visible_rings`.

    Examples
    --------
    A plate halfway up hides the central quarter of a square's shadow window:

    >>> from isocsg import Box
    >>> from isocsg.shadows import convex_pieces
    >>> floor = np.array([[-2.0, -2, 0], [2, -2, 0], [2, 2, 0], [-2, 2, 0]])
    >>> plate = convex_pieces([Box((0, 0, 1), (1, 1, 1e-9))])
    >>> full = visible_solid_angle((0, 0, 2), floor, [])
    >>> hidden = signed_solid_angles(np.array([0.0, 0, 2]), floor / 2, np.array([0, 4]))[0]
    >>> bool(np.isclose(visible_solid_angle((0, 0, 2), floor, plate), full - hidden, rtol=1e-8))
    True
    """
    rings = visible_rings(apex, polygon, pieces)
    if rings is None:
        return None
    if not rings:
        return 0.0
    off = np.concatenate([[0], np.cumsum([len(r) for r in rings])])
    return float(signed_solid_angles(np.asarray(apex, dtype=np.float64), np.vstack(rings), off).sum())


def fan_quadrature(rings: Sequence[NDArray[np.float64]], normal: ArrayLike,
                   order: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Points and signed weights integrating over the region the planar rings bound.

    Each ring is fanned from its first vertex; each triangle carries the
    collapsed (Duffy) ``order x order`` Gauss-Legendre rule times its signed
    area about ``normal``, so that the triangles outside the region cancel
    (exact for the region's area; for a smooth integrand as accurate as the
    rule on the triangles).

    Examples
    --------
    >>> sq = np.array([[0.0, 0, 0], [2, 0, 0], [2, 2, 0], [0, 2, 0]])
    >>> hole = np.array([[0.5, 0.5, 0], [0.5, 1.5, 0], [1.5, 1.5, 0], [1.5, 0.5, 0]])  # clockwise
    >>> p, w = fan_quadrature([sq, hole], [0, 0, 1], 3)
    >>> round(float(w.sum()), 12), round(float(w @ p[:, 0]), 12)   # area 3, centroid x 1
    (3.0, 3.0)
    """
    g, gw = np.polynomial.legendre.leggauss(order)
    g, gw = (g + 1) / 2, gw / 2
    u, v = (a.ravel() for a in np.meshgrid(g, g, indexing="ij"))
    w = np.outer(gw, gw).ravel() * (1 - v)
    nrm = np.asarray(normal, dtype=np.float64)
    pts, wts = [], []
    for ring in rings:
        a = ring[0]
        for b, c in zip(ring[1:-1], ring[2:], strict=True):
            area2 = float(np.cross(b - a, c - a) @ nrm)
            edge = a + u[:, None] * (b - a)
            pts.append(edge + v[:, None] * (c - edge))
            wts.append(area2 * w)
    if not pts:
        return np.zeros((0, 3)), np.zeros(0)
    return np.vstack(pts), np.concatenate(wts)
