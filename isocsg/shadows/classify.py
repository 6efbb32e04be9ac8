"""The functions F and H of Nishita and Nakamae and the face types A, B, C.

Seed paper 001, section 2.1:

- ``F`` (eq. 1) is the signed plane function of a face: positive on the side
  its outward normal points to. Here the normal is a unit vector, so ``F`` is
  the signed distance to the face's plane.
- ``H`` (eq. 2) places a point set (a polyhedron's or a face's vertices)
  against a face's plane: ``1`` all on the positive side (or on the plane),
  ``-1`` all on the negative side, ``0`` when the plane cuts the set. As in
  the paper the first case wins, so a set lying in the plane gets ``1``.
- Face types (eqs. 3 and 4): a receiving face of type ``A`` sees the whole
  source, ``B`` a part of it (the face's plane cuts the source), ``C`` none.

Faces are convex planar polygons given by their vertices, counter-clockwise
seen from outside (the right-hand rule gives the outward normal), the order of
:meth:`isocsg.ConvexPolyhedron.face_polygons`. The paper lists vertices
clockwise with a left-handed normal; the resulting normals are the same.
"""

from __future__ import annotations

import enum
from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import points_array
from ..errors import InvalidGeometryError, InvalidLightError

__all__ = [
    "FaceType",
    "Plane",
    "face_plane",
    "F",
    "H",
    "H_planes",
    "default_tolerance",
    "face_type_area",
    "face_type_polyhedron",
    "classify_face",
    "classify_faces",
    "solid_faces",
    "source_points",
]

# Relative tolerance of H: vertices within this fraction of the point sets'
# size from a plane count as lying on it.
REL_TOL = 1e-9


class FaceType(enum.IntEnum):
    """Types of a receiving face with respect to a source (eqs. 3 and 4).

    ``A``: lit by the whole source; ``B``: by the part of the source on the
    positive side of the face's plane; ``C``: not lit at all.
    """

    A = 0
    B = 1
    C = 2


class Plane(tuple):
    """A plane ``normal . x = offset`` with a unit ``normal`` (a 2-tuple).

    Examples
    --------
    >>> p = Plane((0.0, 0.0, 1.0), 2.0)
    >>> p.normal.tolist(), p.offset
    ([0.0, 0.0, 1.0], 2.0)
    """

    __slots__ = ()

    def __new__(cls, normal: ArrayLike, offset: float) -> Plane:
        return super().__new__(cls, (tuple(float(x) for x in np.asarray(normal, dtype=np.float64)), float(offset)))

    @property
    def normal(self) -> NDArray[np.float64]:
        """The unit normal as an array."""
        return np.asarray(self[0], dtype=np.float64)

    @property
    def offset(self) -> float:
        """The offset ``d`` of ``n . x = d``."""
        return float(self[1])


def _polygon(name: str, polygon: ArrayLike) -> NDArray[np.float64]:
    poly = points_array(name, polygon, min_rows=3)
    return poly


def face_plane(polygon: ArrayLike) -> Plane:
    """The oriented plane of a planar polygon (Newell's normal, right-hand rule).

    Parameters
    ----------
    polygon : array_like, shape (k, 3)
        Vertices in order, ``k >= 3``; counter-clockwise seen from the side
        the normal points to.

    Returns
    -------
    Plane
        Unit normal and offset.

    Raises
    ------
    InvalidGeometryError
        If the polygon has fewer than 3 vertices or no area.

    Examples
    --------
    >>> face_plane([(0, 0, 1), (1, 0, 1), (0, 1, 1)])
    ((0.0, 0.0, 1.0), 1.0)
    """
    p = _polygon("polygon", polygon)
    q = np.roll(p, -1, axis=0)
    # Newell's method: robust for any planar polygon, also slightly non-planar ones.
    n = np.array(
        [
            np.sum((p[:, 1] - q[:, 1]) * (p[:, 2] + q[:, 2])),
            np.sum((p[:, 2] - q[:, 2]) * (p[:, 0] + q[:, 0])),
            np.sum((p[:, 0] - q[:, 0]) * (p[:, 1] + q[:, 1])),
        ]
    )
    length = float(np.linalg.norm(n))
    scale = float(np.max(np.ptp(p, axis=0)))
    if length <= 1e-12 * max(scale, 1e-300) ** 2:
        raise InvalidGeometryError(f"polygon has no area (its {len(p)} vertices are collinear or repeated)")
    n = n / length
    return Plane(n, float(np.mean(p @ n)))


def _as_plane(face: Any) -> Plane:
    if isinstance(face, Plane):
        return face
    return face_plane(face)


def F(face: Any, points: ArrayLike) -> NDArray[np.float64]:
    """Signed distance of points to a face's plane (eq. 1 with a unit normal).

    Parameters
    ----------
    face : array_like, shape (k, 3), or Plane
        A planar polygon (oriented by the right-hand rule) or a :class:`Plane`.
    points : array_like, shape (n, 3) or (3,)

    Returns
    -------
    ndarray, shape (n,)
        ``> 0`` on the side the normal points to (positive space), ``< 0`` on
        the other side, ``0`` on the plane.

    Examples
    --------
    >>> square = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    >>> F(square, [(0.5, 0.5, 2.0), (3, 3, -1)]).tolist()
    [2.0, -1.0]
    """
    pl = _as_plane(face)
    p = points_array("points", points)
    return p @ pl.normal - pl.offset


def default_tolerance(*point_sets: ArrayLike) -> float:
    """The tolerance used by :func:`H` when none is given: ``1e-9`` of the sets' extent.

    Examples
    --------
    >>> default_tolerance([(0, 0, 0), (2, 0, 0)])
    2e-09
    """
    pts = np.vstack([np.asarray(s, dtype=np.float64).reshape(-1, 3) for s in point_sets])
    scale = float(np.max(np.abs(pts))) if len(pts) else 1.0
    extent = float(np.max(np.ptp(pts, axis=0))) if len(pts) else 1.0
    return REL_TOL * max(scale, extent, 1e-300)


def H(face: Any, vertices: ArrayLike, *, tol: float | None = None) -> int:
    """Position of a point set (polyhedron or face vertices) against a face's plane (eq. 2).

    Parameters
    ----------
    face : array_like, shape (k, 3), or Plane
        The face whose plane is tested.
    vertices : array_like, shape (n, 3)
        Vertices of the polyhedron or face ``V``.
    tol : float, optional
        Distances within ``tol`` of the plane count as on it. Default
        :func:`default_tolerance` of the face and the vertices.

    Returns
    -------
    int
        ``1`` if every vertex has ``F >= -tol`` (V in the positive space; this
        case wins when every vertex is on the plane), ``-1`` if every vertex
        has ``F <= tol``, else ``0`` (the plane cuts V).

    Examples
    --------
    >>> floor = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    >>> H(floor, [(0, 0, 1), (1, 0, 2)]), H(floor, [(0, 0, -1)]), H(floor, [(0, 0, -1), (0, 0, 1)])
    (1, -1, 0)
    """
    v = points_array("vertices", vertices)
    if tol is None:
        tol = default_tolerance(v) if isinstance(face, Plane) else default_tolerance(v, face)
    f = F(face, v)
    if np.all(f >= -tol):
        return 1
    if np.all(f <= tol):
        return -1
    return 0


def H_planes(normals: ArrayLike, offsets: ArrayLike, vertices: ArrayLike, *, tol: float) -> NDArray[np.int64]:
    """Vectorised :func:`H` for many planes ``normals . x = offsets`` at once.

    Returns an int array of shape (k,) with values 1, -1 or 0.

    Examples
    --------
    >>> H_planes([[0, 0, 1], [0, 0, -1], [1, 0, 0]], [0, 0, 0.5], [[0, 0, 1], [1, 0, 2]], tol=1e-9).tolist()
    [1, -1, 0]
    """
    n = np.asarray(normals, dtype=np.float64).reshape(-1, 3)
    d = np.asarray(offsets, dtype=np.float64).reshape(-1)
    v = np.asarray(vertices, dtype=np.float64).reshape(-1, 3)
    f = v @ n.T - d[None, :]
    pos = np.all(f >= -tol, axis=0)
    neg = np.all(f <= tol, axis=0)
    return np.where(pos, 1, np.where(neg, -1, 0)).astype(np.int64)


def face_type_area(face: Any, source: ArrayLike, *, tol: float | None = None) -> FaceType:
    """Type of a receiving face for an area source ``S_e`` (eq. 3).

    ``A``: ``H(S_f, S_e) = 1`` and ``H(S_e, S_f) != -1``;
    ``B``: ``H(S_f, S_e) = 0`` and ``H(S_e, S_f) != -1``;
    ``C``: ``H(S_f, S_e) = -1`` or ``H(S_e, S_f) = -1``.

    Parameters
    ----------
    face : array_like, shape (k, 3)
        The receiving face (outward normal by the right-hand rule).
    source : array_like, shape (m, 3)
        The source polygon, counter-clockwise seen from the side it lights.
    tol : float, optional
        Tolerance of :func:`H`.

    Returns
    -------
    FaceType

    Examples
    --------
    >>> floor = [(-5, -5, 0), (5, -5, 0), (5, 5, 0), (-5, 5, 0)]
    >>> lamp = [(0, 0, 2), (0, 1, 2), (1, 1, 2), (1, 0, 2)]   # faces down
    >>> face_type_area(floor, lamp).name
    'A'
    >>> ceiling = [(-5, -5, 3), (-5, 5, 3), (5, 5, 3), (5, -5, 3)]   # faces down too
    >>> face_type_area(ceiling, lamp).name
    'C'
    """
    f = _polygon("face", face)
    s = _polygon("source", source)
    if tol is None:
        tol = default_tolerance(f, s)
    h_fs = H(f, s, tol=tol)
    h_sf = H(s, f, tol=tol)
    if h_fs == -1 or h_sf == -1:
        return FaceType.C
    return FaceType.A if h_fs == 1 else FaceType.B


def face_type_polyhedron(face: Any, source_vertices: ArrayLike, *, tol: float | None = None) -> FaceType:
    """Type of a receiving face for a polyhedron source ``V_e`` (eq. 4).

    ``A``: ``H(S_f, V_e) = 1``; ``B``: ``H(S_f, V_e) = 0``; ``C``: ``H(S_f, V_e) = -1``.

    Parameters
    ----------
    face : array_like, shape (k, 3)
    source_vertices : array_like, shape (n, 3)
        Vertices of the convex source polyhedron.
    tol : float, optional

    Returns
    -------
    FaceType

    Examples
    --------
    >>> floor = [(-5, -5, 0), (5, -5, 0), (5, 5, 0), (-5, 5, 0)]
    >>> cube = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (2, 3)]
    >>> face_type_polyhedron(floor, cube).name
    'A'
    """
    f = _polygon("face", face)
    v = points_array("source_vertices", source_vertices, min_rows=1)
    if tol is None:
        tol = default_tolerance(f, v)
    h = H(f, v, tol=tol)
    return {1: FaceType.A, 0: FaceType.B, -1: FaceType.C}[h]


def _light_kind(light: Any) -> str:
    from ..lighting.area import AreaLight, PolyhedronLight

    if isinstance(light, AreaLight):
        return "area"
    if isinstance(light, PolyhedronLight):
        return "polyhedron"
    raise InvalidLightError(f"light must be an AreaLight or a PolyhedronLight, got {type(light).__name__}")


def source_points(light: Any) -> tuple[str, NDArray[np.float64]]:
    """The kind (``"area"`` or ``"polyhedron"``) and the vertices of a source.

    For a polyhedron source the vertices are those of its convex hull.

    Raises
    ------
    InvalidLightError
        If ``light`` is neither an ``AreaLight`` nor a ``PolyhedronLight``.
    """
    kind = _light_kind(light)
    if kind == "polyhedron":
        return kind, np.asarray(light.polyhedron.hull_vertices, dtype=np.float64)
    return kind, np.asarray(light.vertices, dtype=np.float64).reshape(-1, 3)


def classify_face(face: ArrayLike, light: Any, *, tol: float | None = None) -> FaceType:
    """Type of one face (a convex polygon) for an ``AreaLight`` or ``PolyhedronLight``.

    Raises
    ------
    InvalidLightError
        If ``light`` is not an area or polyhedron source.

    Examples
    --------
    >>> from isocsg.lighting.area import AreaLight
    >>> lamp = AreaLight([(0, 0, 2), (0, 1, 2), (1, 1, 2), (1, 0, 2)])
    >>> classify_face([(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)], lamp).name
    'A'
    """
    kind, v = source_points(light)
    if kind == "area":
        return face_type_area(face, v, tol=tol)
    return face_type_polyhedron(face, v, tol=tol)


def solid_faces(solid: Any) -> list[NDArray[np.float64]]:
    """The faces of a polyhedral solid (``Box``, ``ConvexPolyhedron``) or a list of polygons.

    Raises
    ------
    InvalidGeometryError
        If ``solid`` has no planar faces.

    Examples
    --------
    >>> from isocsg import Box
    >>> len(solid_faces(Box((0, 0, 0), (1, 1, 1))))
    6
    """
    if hasattr(solid, "face_polygons"):
        return [np.asarray(f, dtype=np.float64) for f in solid.face_polygons()]
    if isinstance(solid, Sequence) or isinstance(solid, np.ndarray):
        return [_polygon(f"faces[{i}]", f) for i, f in enumerate(solid)]
    raise InvalidGeometryError(
        f"solid must be a Box, a ConvexPolyhedron or a list of polygons, got {type(solid).__name__}"
    )


def classify_faces(solid: Any, light: Any, *, tol: float | None = None) -> list[FaceType]:
    """Types of every face of a polyhedral solid for one source (eqs. 3 and 4).

    Parameters
    ----------
    solid : Box, ConvexPolyhedron or sequence of (k, 3) polygons
        Faces in the order of ``solid.face_polygons()``.
    light : AreaLight or PolyhedronLight
    tol : float, optional
        Tolerance of :func:`H`.

    Returns
    -------
    list of FaceType

    Examples
    --------
    >>> from isocsg import Box
    >>> from isocsg.lighting.area import AreaLight
    >>> lamp = AreaLight([(-1, -1, 3), (-1, 1, 3), (1, 1, 3), (1, -1, 3)])
    >>> sorted(t.name for t in classify_faces(Box((0, 0, 0), (1, 1, 1)), lamp))
    ['A', 'B', 'B', 'B', 'B', 'C']
    """
    return [classify_face(f, light, tol=tol) for f in solid_faces(solid)]
