"""A convex polytope grown by a ball or by a disc, split exactly into isocsg kinds.

For a convex polytope ``Q`` (the hull of points, possibly flat: a polygon, a segment or a point)
and a convex body ``K`` containing 0, every point of ``Q + K`` outside ``Q`` is a boundary point
of ``Q`` plus a point of ``K`` (the segment from ``x`` to ``x - k`` leaves ``Q``). The pieces:

- **ball** ``B_r``: a point at distance ``t <= r`` from ``Q`` has its nearest point of ``Q`` in
  the relative interior of a face, an edge or at a vertex, so
  ``Q + B_r = Q  u  prisms(f, f + r n_f)  u  cylinders(edge, r)  u  spheres(vertex, r)``.
  A flat ``Q`` (a polygon of normal ``n``) has the slab ``Q + [-r, r] n`` instead of ``Q`` and its
  prisms; a segment is a capsule; a point a sphere.
- **disc** ``D_r`` perpendicular to the unit axis ``a``: ``D_r`` keeps heights along ``a``, so each
  slice of ``Q + D_r`` is the slice of ``Q`` (a convex polygon) grown by a 2D disc: the polygon,
  a rectangle outward of each side, a disc at each corner. The sides are slices of the faces of
  ``Q`` that are not perpendicular to ``a``, their outward 2D normal the face normal's projection
  ``m_f`` on the plane of the disc; the corners are slices of the edges that are not
  perpendicular to ``a``. So ``Q + D_r = Q  u  prisms(f, f + r m_f)  u  (edge + D_r)``, where an
  edge swept by the disc is a cylinder (:class:`~isocsg.Cylinder`) along ``a`` or an oblique
  one (:class:`~isocsg.EllipticTruncus`) otherwise. Faces and edges perpendicular to ``a`` meet
  a slice at finitely many heights only: no volume, left out. A flat ``Q`` has the slab
  ``Q + [-r, r] m`` and its edges' cylinders; a segment is one swept disc; a ``Q`` perpendicular
  to ``a`` (a horizontal polygon, segment or point) gives no volume.

Two pieces are left out on purpose, each bounded: a cylinder on an edge shorter than
``MIN_ASPECT`` (1e-5) times ``r`` (the kinds refuse it; the spheres at its ends leave uncovered
only a sliver thinner than ``length**2 / (8 r)``, below ``1.25e-11 r``), and a swept disc on an
edge within ``1e-6`` radians of the disc's plane (its matrix is too ill-conditioned for
:class:`~isocsg.EllipticTruncus`; it adds at most ``pi r**2`` times the edge's extent along
``a``, below ``1e-6 pi r**2 |edge|``). A prism over a face too thin for
:class:`~isocsg.ConvexPolyhedron` (volume below 1e-12 of its extent cubed) is left out likewise.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._validation import MIN_ASPECT
from ..errors import InvalidGeometryError
from ..kinds import ConvexPolyhedron, Cylinder, EllipticTruncus, Primitive, Sphere

__all__ = ["Polytope", "polytope", "grow_ball", "grow_disc"]

#: Singular values of the centred points below this fraction of their extent count as zero
#: (the points then span a plane, a line or one point).
FLAT_TOLERANCE = 1e-10
#: A face or an edge whose direction is within this of the disc's plane (sine of the angle) is
#: taken as lying in it: its sweep by the disc has no volume.
LEVEL_TOLERANCE = 1e-12


@dataclass(frozen=True)
class Polytope:
    """The hull of points with its faces: ``dim`` 3 (``solid`` set), 2 (one polygon), 1 or 0.

    ``polygons`` are ``(vertices (k, 3), unit normal)`` pairs (outward for a solid; either
    side for a flat one), ``edges`` an ``(m, 2, 3)`` array, ``vertices`` ``(p, 3)``.
    """

    dim: int
    solid: ConvexPolyhedron | None
    polygons: list[tuple[NDArray[np.float64], NDArray[np.float64]]]
    edges: NDArray[np.float64]
    vertices: NDArray[np.float64]


def polytope(points: NDArray[np.float64]) -> Polytope:
    """The hull of ``points`` (n, 3) with its faces, edges and vertices, of whatever dimension."""
    pts = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    centre = pts.mean(axis=0)
    spread = pts - centre
    extent = float(np.max(np.ptp(pts, axis=0)))
    if extent <= 0.0:
        return Polytope(0, None, [], np.zeros((0, 2, 3)), pts[:1].copy())
    _, sv, vt = np.linalg.svd(spread, full_matrices=False)
    flat = sv <= FLAT_TOLERANCE * extent * np.sqrt(len(pts))
    if len(sv) < 3 or flat[2]:
        if len(sv) < 2 or flat[1]:  # a segment between the extreme points along its direction
            t = spread @ vt[0]
            ends = pts[[int(np.argmin(t)), int(np.argmax(t))]]
            return Polytope(1, None, [], ends[None], ends)
        return _polygon(pts, centre, vt)
    try:
        solid = ConvexPolyhedron(pts)
    except InvalidGeometryError:  # thinner than the polyhedron's own volume floor
        return _polygon(pts, centre, vt)
    hv = solid.hull_vertices
    pairs = {(min(int(f[i]), int(f[i - 1])), max(int(f[i]), int(f[i - 1]))) for f in solid.faces for i in range(len(f))}
    edges = np.array([[hv[i], hv[j]] for i, j in sorted(pairs)])
    polygons = [(hv[f], solid.face_normals[k]) for k, f in enumerate(solid.faces)]
    return Polytope(3, solid, polygons, edges, hv.copy())


def _polygon(pts: NDArray[np.float64], centre: NDArray[np.float64], vt: NDArray[np.float64]) -> Polytope:
    """Points spanning a plane: their 2D hull in it, mapped back onto the plane."""
    from scipy.spatial import ConvexHull

    uv = (pts - centre) @ vt[:2].T
    ring = ConvexHull(uv).vertices  # counter-clockwise
    normal = np.cross(vt[0], vt[1])
    normal /= np.linalg.norm(normal)
    corners = centre + uv[ring] @ vt[:2]  # projected onto the plane: off by at most the flatness
    edges = np.stack([corners, np.roll(corners, -1, axis=0)], axis=1)
    return Polytope(2, None, [(corners, normal)], edges, corners)


def _prism(base: NDArray[np.float64], shift: NDArray[np.float64], back: float = 0.0) -> ConvexPolyhedron | None:
    """The hull of ``base + back * shift`` and ``base + shift``; None when too thin to be a kind."""
    try:
        return ConvexPolyhedron(np.vstack([base + back * shift, base + shift]))
    except InvalidGeometryError:
        return None


def grow_ball(points: NDArray[np.float64], radius: float) -> list[Primitive]:
    """The hull of ``points`` grown by a ball of ``radius`` (> 0), as pieces whose union it is.

    Examples
    --------
    >>> import numpy as np
    >>> parts = grow_ball(np.array([[0.0, 0, 0], [1, 0, 0]]), 0.5)  # a capsule
    >>> sorted(type(p).__name__ for p in parts)
    ['Cylinder', 'Sphere', 'Sphere']
    """
    q = polytope(points)
    pieces: list[Primitive] = []
    if q.solid is not None:
        pieces.append(q.solid)
        for face, normal in q.polygons:
            pieces.append(_prism(face, radius * normal))  # type: ignore[arg-type]
    elif q.dim == 2:
        face, normal = q.polygons[0]
        pieces.append(_prism(face, radius * normal, back=-1.0))  # type: ignore[arg-type]
    for a, b in q.edges:
        if np.linalg.norm(b - a) >= MIN_ASPECT * radius:  # shorter: covered by its end spheres
            pieces.append(Cylinder((a + b) / 2, b - a, radius))
    pieces.extend(Sphere(v, radius) for v in q.vertices)
    return [p for p in pieces if p is not None]


def _disc_frame(axis: NDArray[np.float64]) -> NDArray[np.float64]:
    """Two orthonormal vectors spanning the plane perpendicular to the unit ``axis``, as columns."""
    helper = np.eye(3)[int(np.argmin(np.abs(axis)))]
    u = np.cross(axis, helper)
    u /= np.linalg.norm(u)
    return np.stack([u, np.cross(axis, u)], axis=1)


def swept_disc(
    a: NDArray[np.float64], b: NDArray[np.float64], axis: NDArray[np.float64], radius: float,
) -> Primitive | None:
    """The segment ``ab`` swept by the disc of ``radius`` perpendicular to the unit ``axis``:
    a cylinder when ``ab`` is along the axis, an oblique one otherwise; None when ``ab`` lies in
    the disc's plane (no volume)."""
    w = b - a
    length = float(np.linalg.norm(w))
    along = float(w @ axis)
    if length == 0.0 or abs(along) <= LEVEL_TOLERANCE * length:
        return None
    if np.linalg.norm(w - along * axis) <= LEVEL_TOLERANCE * length:
        return Cylinder((a + b) / 2, w, radius)
    frame = _disc_frame(axis)
    return EllipticTruncus((a + b) / 2, np.column_stack([frame, w]), radius, radius)


def grow_disc(points: NDArray[np.float64], axis: NDArray[np.float64], radius: float) -> list[Primitive]:
    """The hull of ``points`` grown by the disc of ``radius`` perpendicular to ``axis``, as pieces
    whose union it is; empty when the sum has no volume (everything in a plane across ``axis``).

    Examples
    --------
    >>> import numpy as np
    >>> box = np.array([[x, y, z] for x in (0.0, 1) for y in (0.0, 1) for z in (0.0, 1)])
    >>> sorted(type(p).__name__ for p in grow_disc(box, np.array([0.0, 0, 1]), 0.5))[:2]
    ['ConvexPolyhedron', 'ConvexPolyhedron']
    """
    a = np.asarray(axis, dtype=np.float64)
    a = a / np.linalg.norm(a)
    q = polytope(points)
    pieces: list[Primitive | None] = []
    if q.solid is not None:
        pieces.append(q.solid)
    for face, normal in q.polygons:
        side = normal - (normal @ a) * a
        size = float(np.linalg.norm(side))
        if size <= LEVEL_TOLERANCE:
            if q.dim == 2:
                return []  # a polygon across the axis: flat
            continue  # a face across the axis: met by finitely many slices
        pieces.append(_prism(face, radius * side / size, back=-1.0 if q.dim == 2 else 0.0))
    for e0, e1 in q.edges:
        try:
            pieces.append(swept_disc(e0, e1, a, radius))
        except InvalidGeometryError:
            if q.dim == 1:
                raise
            # within 1e-6 rad of the disc's plane: at most pi r^2 x its extent along the axis
    return [p for p in pieces if p is not None]
