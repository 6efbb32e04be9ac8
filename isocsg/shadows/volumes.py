"""Shadow volumes of a convex polyhedron lit by an area or polyhedron source (seed 001, 2.3).

For a source vertex ``Q_l`` and a convex occluder ``V`` the *shadow volume*
``U_l`` is the unclosed convex volume bounded by the planes through ``Q_l``
and the contour-line edges of ``V`` seen from ``Q_l`` (the cone from ``Q_l``
over ``V``) and by the faces of ``V`` that face ``Q_l``: the points ``x``
whose segment ``Q_l x`` meets ``V``.

- The **penumbra volume** is the smallest convex volume holding every
  ``U_l`` (their convex hull). It is built as in the paper's Table 1 from the
  separating planes: ``S^`` (a source vertex and a contour edge of ``V``) and
  ``S~`` (a vertex of ``V`` and an edge of the source) with ``V`` on their
  negative and the source on their positive side, and the faces of ``V``
  that face the whole source (type A).
- The **umbra volume** is the intersection of the ``U_l``.

Both contain ``V`` itself. For one convex occluder and a convex source they
are exact: a point (in front of an area source) is in some shadow of ``V``
iff it lies in the penumbra volume, and in its umbra iff it lies in the umbra
volume, because the set of points whose segment to *some* (resp. *every*)
source point meets ``V`` is the hull (resp. the intersection) of the vertex
volumes. Where the plane of an area source cuts ``V`` (``H(S_e, V) = 0``) only
the part of ``V`` in front of the source casts shadows, and the volumes are
cut by the source plane; an occluder wholly behind an area source
(``H(S_e, V) = -1``) has no shadow volumes.

Volumes are sets of half-spaces ``normals . x <= offsets`` (unbounded);
:meth:`ConvexVolume.to_trimesh` closes them with a bounding box.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import points_array
from ..errors import InvalidGeometryError, InvalidParameterError
from .classify import REL_TOL, H_planes, Plane, _light_kind, face_plane, solid_faces

__all__ = [
    "ConvexVolume",
    "SourceGeometry",
    "ShadowVolumes",
    "as_piece",
    "vertex_shadow_volume",
    "shadow_volumes",
    "penumbra_volume",
    "umbra_volume",
    "may_cast_shadow",
]


# ----------------------------------------------------------------------------- volumes


def _bounds_halfspaces(bounds: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    b = np.asarray(bounds, dtype=np.float64)
    if b.shape != (2, 3) or not np.all(np.isfinite(b)) or np.any(b[1] <= b[0]):
        raise InvalidParameterError(
            f"bounds must be [[xmin, ymin, zmin], [xmax, ymax, zmax]] with min < max, got {b.tolist()}"
        )
    eye = np.eye(3)
    return np.vstack([eye, -eye]), np.concatenate([b[1], -b[0]])


def _chebyshev(normals: NDArray[np.float64], offsets: NDArray[np.float64]) -> tuple[NDArray[np.float64], float]:
    """Centre and radius of the largest ball inside bounded half-spaces (radius < 0 if empty)."""
    from scipy.optimize import linprog

    res = linprog(
        c=np.array([0.0, 0.0, 0.0, -1.0]),
        A_ub=np.column_stack([normals, np.linalg.norm(normals, axis=1)]),
        b_ub=offsets,
        bounds=[(None, None)] * 4,
        method="highs",
    )
    if not res.success:
        return np.zeros(3), -1.0
    return res.x[:3], float(res.x[3])


def _polytope_vertices(normals: NDArray[np.float64], offsets: NDArray[np.float64],
                       tol: float) -> NDArray[np.float64] | None:
    """Vertices of a bounded polytope, or None when it is empty or flat."""
    from scipy.spatial import HalfspaceIntersection, QhullError

    centre, radius = _chebyshev(normals, offsets)
    if radius <= tol:
        return None
    try:
        inter = HalfspaceIntersection(np.column_stack([normals, -offsets]), centre)
    except QhullError:  # pragma: no cover - guarded by the Chebyshev radius
        return None
    v = inter.intersections
    return v[np.all(np.isfinite(v), axis=1)]


@dataclass(frozen=True, slots=True)
class ConvexVolume:
    """A convex (possibly unbounded) volume ``normals @ x <= offsets``.

    Attributes
    ----------
    normals : ndarray, shape (k, 3)
        Unit outward normals of the bounding planes.
    offsets : ndarray, shape (k,)
    tol : float
        Geometric tolerance of the construction (metres).

    Examples
    --------
    >>> v = ConvexVolume(np.array([[0.0, 0, 1], [0, 0, -1]]), np.array([1.0, 0.0]))
    >>> v.contains([[0, 0, 0.5], [0, 0, 2]]).tolist()
    [True, False]
    """

    normals: NDArray[np.float64] = field(compare=False)
    offsets: NDArray[np.float64] = field(compare=False)
    tol: float = 0.0

    @property
    def n_planes(self) -> int:
        """Number of bounding planes."""
        return int(len(self.offsets))

    def signed_distance(self, points: ArrayLike) -> NDArray[np.float64]:
        """``max_i (n_i . x - d_i)``: minus the distance to the boundary inside.

        Outside the volume it is positive and at most the true distance.
        With no planes (the whole space) it is ``-inf``.
        """
        p = points_array("points", points)
        if self.n_planes == 0:
            return np.full(len(p), -np.inf)
        return np.max(p @ self.normals.T - self.offsets[None, :], axis=1)

    def contains(self, points: ArrayLike, *, tol: float = 0.0) -> NDArray[np.bool_]:
        """Points inside or on the volume (within ``tol``)."""
        return self.signed_distance(points) <= tol

    def clipped(self, bounds: ArrayLike) -> ConvexVolume:
        """The volume intersected with an axis-aligned box ``[[lo], [hi]]``."""
        n, d = _bounds_halfspaces(bounds)
        return ConvexVolume(np.vstack([self.normals, n]), np.concatenate([self.offsets, d]), self.tol)

    def vertices(self, bounds: ArrayLike) -> NDArray[np.float64] | None:
        """Vertices of the volume clipped to ``bounds`` (None when that is empty)."""
        c = self.clipped(bounds)
        return _polytope_vertices(c.normals, c.offsets, max(self.tol, 1e-12))

    def reduced(self, bounds: ArrayLike) -> ConvexVolume:
        """The same volume inside ``bounds`` with planes that bound nothing there dropped.

        Points inside ``bounds`` are classified exactly as before; the result
        is empty (one impossible plane) when the clipped volume is.
        """
        v = self.vertices(bounds)
        if v is None:
            return ConvexVolume(np.array([[0.0, 0.0, 1.0]]), np.array([-np.inf]), self.tol)
        slack = v @ self.normals.T - self.offsets[None, :]
        b = np.asarray(bounds, dtype=np.float64)
        tol = max(self.tol, REL_TOL * float(np.max(np.abs(b)))) * 10
        keep = np.max(slack, axis=0) >= -tol
        return ConvexVolume(self.normals[keep], self.offsets[keep], self.tol)

    def to_trimesh(self, bounds: ArrayLike) -> Any:
        """A closed convex triangle mesh of the volume clipped to ``bounds`` (None if empty).

        Examples
        --------
        >>> v = ConvexVolume(np.array([[0.0, 0, 1]]), np.array([0.0]))
        >>> round(float(v.to_trimesh([[-1, -1, -1], [1, 1, 1]]).volume), 6)
        4.0
        """
        import trimesh

        v = self.vertices(bounds)
        if v is None or len(v) < 4:
            return None
        try:
            return trimesh.convex.convex_hull(v)
        except Exception:  # noqa: BLE001  # pragma: no cover - qhull failure on a flat set
            return None


# ----------------------------------------------------------------------------- inputs


@dataclass(frozen=True, slots=True)
class _Piece:
    """Vertices, edges and face planes of a convex polyhedron."""

    vertices: NDArray[np.float64]
    edges: NDArray[np.int64]
    normals: NDArray[np.float64]
    offsets: NDArray[np.float64]


def _piece_from_polyhedron(poly: Any) -> _Piece:
    pairs = set()
    for f in poly.faces:
        f = np.asarray(f)
        for a, b in zip(f, np.roll(f, -1)):
            pairs.add((int(min(a, b)), int(max(a, b))))
    return _Piece(
        np.asarray(poly.hull_vertices, dtype=np.float64),
        np.array(sorted(pairs), dtype=np.int64).reshape(-1, 2),
        np.asarray(poly.face_normals, dtype=np.float64),
        np.asarray(poly.face_offsets, dtype=np.float64),
    )


def as_piece(occluder: Any) -> Any:
    """A convex occluder as a piece with ``vertices``, ``edges``, ``normals``, ``offsets``.

    Parameters
    ----------
    occluder : ConvexPiece, Box, ConvexPolyhedron or array_like of shape (n, 3)
        A convex polyhedron: a piece, a polyhedral primitive (one whose ``hull_points()`` is not
        None), or points (their convex hull).

    Raises
    ------
    InvalidGeometryError
        For anything else, or points whose hull has no volume.

    Examples
    --------
    >>> from isocsg import Box
    >>> as_piece(Box((0, 0, 0), (1, 1, 1))).edges.shape
    (12, 2)
    """
    from ..kinds.base import Primitive
    from ..kinds.polyhedron import ConvexPolyhedron
    from .occluders import ConvexPiece

    if isinstance(occluder, (ConvexPiece, _Piece)):
        return occluder
    if isinstance(occluder, Primitive) and occluder.hull_points() is not None:  # a polyhedral kind
        return _piece_from_polyhedron(occluder.to_polyhedron())
    if isinstance(occluder, (list, tuple, np.ndarray)):
        return _piece_from_polyhedron(ConvexPolyhedron(points_array("occluder", occluder, min_rows=4)))  # type: ignore[arg-type]  # array_like accepted; the field's annotation says tuples
    raise InvalidGeometryError(
        f"occluder must be a ConvexPiece, Box, ConvexPolyhedron or (n, 3) points, got {type(occluder).__name__}"
    )


def _clip_piece(piece: Any, normal: NDArray[np.float64], offset: float, tol: float) -> _Piece | None:
    """``piece`` intersected with ``normal . x >= offset`` (None if nothing of volume is left)."""
    from ..kinds.polyhedron import ConvexPolyhedron

    n = np.vstack([piece.normals, -normal[None, :]])
    d = np.concatenate([piece.offsets, [-offset]])
    v = _polytope_vertices(n, d, tol)
    if v is None:
        return None
    try:
        return _piece_from_polyhedron(ConvexPolyhedron(v))  # type: ignore[arg-type]  # array_like accepted; the field's annotation says tuples
    except InvalidGeometryError:
        return None


@dataclass(frozen=True, slots=True)
class SourceGeometry:
    """The geometry of an extended source that shadow volumes need.

    Attributes
    ----------
    kind : str
        ``"area"`` or ``"polyhedron"``.
    vertices : ndarray, shape (m, 3)
        Polygon vertices (in order) or the polyhedron's hull vertices.
    edges : ndarray of int64, shape (e, 2)
        Vertex index pairs of the edges.
    plane : Plane or None
        The area source's plane, oriented to its lit side.

    Examples
    --------
    >>> from isocsg.lighting.area import AreaLight
    >>> g = SourceGeometry.from_light(AreaLight([(0, 0, 2), (0, 1, 2), (1, 1, 2), (1, 0, 2)]))
    >>> g.kind, g.edges.shape, g.plane.normal.tolist()
    ('area', (4, 2), [0.0, 0.0, -1.0])
    """

    kind: str
    vertices: NDArray[np.float64] = field(compare=False)
    edges: NDArray[np.int64] = field(compare=False)
    plane: Plane | None = None

    @classmethod
    def from_light(cls, light: Any) -> SourceGeometry:
        """The geometry of an ``AreaLight`` or ``PolyhedronLight``.

        Raises
        ------
        InvalidLightError
            If ``light`` is neither.
        """
        if isinstance(light, SourceGeometry):
            return light
        kind = _light_kind(light)
        if kind == "area":
            v = np.asarray(light.vertices, dtype=np.float64)
            m = len(v)
            edges = np.column_stack([np.arange(m), (np.arange(m) + 1) % m]).astype(np.int64)
            return cls("area", v, edges, face_plane(v))
        piece = _piece_from_polyhedron(light.polyhedron)
        return cls("polyhedron", piece.vertices, piece.edges, None)

    def clipped(self, plane: Plane, *, tol: float | None = None) -> SourceGeometry | None:
        """The part of the source on the positive side of ``plane`` (type-B receivers).

        Returns None when no part of positive area (area source) or volume
        (polyhedron source) is left.
        """
        n, d = plane.normal, plane.offset
        if tol is None:
            tol = REL_TOL * max(float(np.max(np.abs(self.vertices))), 1.0)
        f = self.vertices @ n - d
        if np.all(f >= -tol):
            return self
        if np.all(f <= tol):
            return None
        if self.kind == "area":
            poly = _clip_polygon(self.vertices, n, d)
            if len(poly) < 3:
                return None
            try:
                pl = face_plane(poly)
            except InvalidGeometryError:
                return None
            m = len(poly)
            edges = np.column_stack([np.arange(m), (np.arange(m) + 1) % m]).astype(np.int64)
            return SourceGeometry("area", poly, edges, self.plane if self.plane is not None else pl)
        from ..kinds.polyhedron import ConvexPolyhedron

        piece = _clip_piece(_piece_from_polyhedron(ConvexPolyhedron(self.vertices)), -n, -d, tol)  # type: ignore[arg-type]  # array_like accepted; the field's annotation says tuples
        if piece is None:
            return None
        return SourceGeometry("polyhedron", piece.vertices, piece.edges, None)


def _clip_polygon(poly: NDArray[np.float64], n: NDArray[np.float64], d: float) -> NDArray[np.float64]:
    """Sutherland-Hodgman: the part of a convex polygon with ``n . x >= d``."""
    out = []
    f = poly @ n - d
    m = len(poly)
    for i in range(m):
        j = (i + 1) % m
        if f[i] >= 0:
            out.append(poly[i])
        if (f[i] >= 0) != (f[j] >= 0):
            t = f[i] / (f[i] - f[j])
            out.append(poly[i] + t * (poly[j] - poly[i]))
    if not out:
        return np.zeros((0, 3))
    res = np.asarray(out)
    # drop repeated points created when a vertex lies on the plane
    keep = np.linalg.norm(res - np.roll(res, -1, axis=0), axis=1) > 1e-12 * max(1.0, float(np.max(np.abs(res))))
    return res[keep]


# ----------------------------------------------------------------------------- planes


def _planes_through(
    apex: NDArray[np.float64], a: NDArray[np.float64], b: NDArray[np.float64], scale: float
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.bool_]]:
    """Unit normals and offsets of the planes through ``apex`` and segments ``a b`` (broadcast)."""
    n = np.cross(a - apex, b - apex)
    length = np.linalg.norm(n, axis=-1)
    ok = length > 1e-10 * scale * scale
    n = n / np.where(ok, length, 1.0)[..., None]
    return n, np.einsum("...i,...i->...", n, apex), ok


def _supporting(
    normals: NDArray[np.float64], offsets: NDArray[np.float64], ok: NDArray[np.bool_], vertices: NDArray[np.float64],
    tol: float,
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Keep the planes that support ``vertices``, oriented with the vertices on the negative side."""
    n = normals.reshape(-1, 3)[ok.ravel()]
    d = offsets.ravel()[ok.ravel()]
    h = H_planes(n, d, vertices, tol=tol)
    flip = h == 1
    n = np.where(flip[:, None], -n, n)
    d = np.where(flip, -d, d)
    keep = h != 0
    return n[keep], d[keep]


def _scale_tol(*arrays: NDArray[np.float64], tol: float | None) -> tuple[float, float]:
    pts = np.vstack([np.asarray(a).reshape(-1, 3) for a in arrays])
    scale = max(float(np.max(np.ptp(pts, axis=0))), float(np.max(np.abs(pts))), 1e-300)
    return scale, (REL_TOL * scale if tol is None else float(tol))


def _edge_faces(piece: Any, tol: float) -> NDArray[np.int64]:
    """The two faces (indices into ``piece.normals``) that meet at each edge, shape (e, 2)."""
    v = piece.vertices
    on = np.abs(v @ piece.normals.T - piece.offsets[None, :]) <= tol * 10  # (v, f)
    both = on[piece.edges[:, 0]] & on[piece.edges[:, 1]]  # (e, f)
    out = np.full((len(piece.edges), 2), -1, dtype=np.int64)
    for k in range(len(piece.edges)):
        f = np.nonzero(both[k])[0]
        if len(f) >= 2:
            out[k] = f[:2]
    return out


def _silhouette_planes(
    q: NDArray[np.float64], piece: Any, edge_faces: NDArray[np.int64], scale: float, tol: float
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Planes through ``q`` and the contour-line edges of ``piece`` seen from ``q``.

    ``piece`` lies on their negative side.
    """
    front = piece.normals @ q - piece.offsets > tol
    ok_adj = np.all(edge_faces >= 0, axis=1)
    sil = ok_adj & (front[np.maximum(edge_faces[:, 0], 0)] != front[np.maximum(edge_faces[:, 1], 0)])
    # edges whose faces could not be found (never for hull faces) are tested like any other
    cand = sil | ~ok_adj
    e = piece.edges[cand]
    a = piece.vertices[e[:, 0]]
    b = piece.vertices[e[:, 1]]
    n, d, ok = _planes_through(q[None, :], a, b, scale)
    return _supporting(n, d, ok, piece.vertices, tol)


def vertex_shadow_volume(vertex: ArrayLike, occluder: Any, *, tol: float | None = None) -> ConvexVolume:
    """The shadow volume ``U_l`` of a convex occluder seen from one source vertex.

    The points ``x`` whose segment to ``vertex`` meets the occluder: the cone
    from the vertex over the occluder (planes through the vertex and the
    contour-line edges) behind the occluder's faces that face the vertex.

    Parameters
    ----------
    vertex : array_like, shape (3,)
        The source vertex ``Q_l`` (outside the occluder).
    occluder : ConvexPiece, Box, ConvexPolyhedron or (n, 3) points
    tol : float, optional
        Distances below ``tol`` count as zero; default ``1e-9`` of the scene size.

    Returns
    -------
    ConvexVolume

    Raises
    ------
    InvalidGeometryError
        If the vertex lies inside the occluder.

    Examples
    --------
    >>> from isocsg import Box
    >>> u = vertex_shadow_volume((0, 0, 3), Box((0, 0, 1), (1, 1, 0.2)))
    >>> u.contains([[0, 0, 0], [0.7, 0, 0], [0.9, 0, 0]]).tolist()
    [True, True, False]
    """
    q = points_array("vertex", vertex)[0]
    piece = as_piece(occluder)
    scale, tol = _scale_tol(piece.vertices, q, tol=tol)
    fq = piece.normals @ q - piece.offsets
    if np.all(fq <= tol):
        raise InvalidGeometryError(
            f"vertex {tuple(q.tolist())} lies inside the occluder: its shadow volume is undefined"
        )
    sn, sd = _silhouette_planes(q, piece, _edge_faces(piece, tol), scale, tol)
    front = fq > tol
    return ConvexVolume(np.vstack([sn, piece.normals[front]]), np.concatenate([sd, piece.offsets[front]]), tol)


@dataclass(frozen=True, slots=True)
class ShadowVolumes:
    """Penumbra and umbra volumes of one convex occluder and one source.

    Attributes
    ----------
    penumbra : ConvexVolume
        Every point in some shadow of the occluder (umbra or penumbra) and the
        occluder itself.
    umbra : ConvexVolume
        Every point in its umbra, and the occluder itself.
    vertex_volumes : tuple of ConvexVolume
        ``U_l`` for each source vertex.
    occluder : piece
        The occluder actually used (cut by an area source's plane when that
        plane crosses it).
    """

    penumbra: ConvexVolume
    umbra: ConvexVolume
    vertex_volumes: tuple[ConvexVolume, ...] = field(compare=False)
    occluder: Any = field(compare=False, repr=False)

    def classify(self, points: ArrayLike, *, tol: float = 0.0) -> NDArray[np.int8]:
        """0 outside the penumbra volume, 2 inside the umbra volume, 1 between.

        Points inside the occluder itself are classified as umbra.
        """
        pen = self.penumbra.contains(points, tol=tol)
        umb = self.umbra.contains(points, tol=tol)
        return np.where(umb, 2, np.where(pen, 1, 0)).astype(np.int8)

    def reduced(self, bounds: ArrayLike) -> ShadowVolumes:
        """Both volumes with the planes that bound nothing inside ``bounds`` dropped."""
        return ShadowVolumes(self.penumbra.reduced(bounds), self.umbra.reduced(bounds), self.vertex_volumes,
                             self.occluder)


def shadow_volumes(light: Any, occluder: Any, *, tol: float | None = None,
                   umbra_rule: str = "intersection") -> ShadowVolumes | None:
    """Penumbra and umbra volumes of a convex occluder under an area or polyhedron source.

    Follows Table 1 of the seed: the penumbra volume is bounded by the planes
    ``S^`` (a source vertex and a contour edge of ``V``) and ``S~`` (a vertex of
    ``V`` and a source edge) that have ``V`` on their negative and the source on
    their positive side, and by the faces of ``V`` of type A; the umbra volume
    is the intersection of the vertex volumes ``U_l``.

    Parameters
    ----------
    light : AreaLight, PolyhedronLight or SourceGeometry
    occluder : ConvexPiece, Box, ConvexPolyhedron or (n, 3) points
        A convex occluder outside the source.
    tol : float, optional
        Distances below ``tol`` count as zero; default ``1e-9`` of the scene size.
    umbra_rule : {"intersection", "table1"}, keyword-only
        ``"intersection"`` keeps every plane of every ``U_l``; ``"table1"``
        keeps only the planes Table 1 lists (``S^`` with the source on the
        negative side, faces of ``V`` of type A or B). Both give the same set.

    Returns
    -------
    ShadowVolumes or None
        None for an area source with the occluder wholly behind its plane
        (``H(S_e, V) = -1``: no light reaches it) or touching it only.

    Raises
    ------
    InvalidLightError
        If ``light`` is not an extended source.
    InvalidGeometryError
        If a source vertex lies inside the occluder.
    InvalidParameterError
        On an unknown ``umbra_rule``.

    Examples
    --------
    A 1 x 1 occluder at height 1 under a 1 x 1 source at height 2 (both centred
    on the z axis): on the floor the umbra reaches 0.5 from the axis, the
    penumbra 1.5 (similar triangles).

    >>> from isocsg import Box
    >>> from isocsg.lighting.area import AreaLight
    >>> lamp = AreaLight([(-.5, -.5, 2), (-.5, .5, 2), (.5, .5, 2), (.5, -.5, 2)])
    >>> sv = shadow_volumes(lamp, Box((0, 0, 1), (1, 1, 0.01)))
    >>> sv.classify([[0.0, 0, 0], [1.4, 0, 0], [1.6, 0, 0]]).tolist()
    [2, 1, 0]
    """
    if umbra_rule not in ("intersection", "table1"):
        raise InvalidParameterError(f"umbra_rule must be 'intersection' or 'table1', got {umbra_rule!r}")
    src = SourceGeometry.from_light(light)
    piece = as_piece(occluder)
    scale, tol = _scale_tol(piece.vertices, src.vertices, tol=tol)
    extra_n: list[NDArray[np.float64]] = []
    extra_d: list[float] = []
    if src.kind == "area":
        assert src.plane is not None
        ne, de = src.plane.normal, src.plane.offset
        fv = piece.vertices @ ne - de
        if np.all(fv <= tol):
            return None
        if np.any(fv < -tol):  # H(S_e, V) = 0: only the part in front of the source casts shadows
            piece = _clip_piece(piece, ne, de, tol)
            if piece is None:
                return None
        extra_n.append(-ne)
        extra_d.append(-de)
    Q = src.vertices
    V = piece.vertices
    # S^: each source vertex with the contour-line edges of V seen from it.
    edge_faces = _edge_faces(piece, tol)
    for q in Q:
        if np.all(piece.normals @ q - piece.offsets <= tol):
            raise InvalidGeometryError(f"source vertex {tuple(q.tolist())} lies inside the occluder")
    sil = [_silhouette_planes(q, piece, edge_faces, scale, tol) for q in Q]
    s_hat_n = np.vstack([x[0] for x in sil])
    s_hat_d = np.concatenate([x[1] for x in sil])
    h_hat = H_planes(s_hat_n, s_hat_d, Q, tol=tol)
    # S~: every vertex of V with every source edge.
    qa = Q[src.edges[:, 0]][None, :, :]
    qb = Q[src.edges[:, 1]][None, :, :]
    n2, d2, ok2 = _planes_through(V[:, None, :], qa, qb, scale)
    s_til_n, s_til_d = _supporting(n2, d2, ok2, V, tol)
    h_til = H_planes(s_til_n, s_til_d, Q, tol=tol)
    # faces of V against the source
    h_face = H_planes(piece.normals, piece.offsets, Q, tol=tol)

    pen_n = [s_hat_n[h_hat == 1], s_til_n[h_til == 1], piece.normals[h_face == 1]]
    pen_n += [np.reshape(x, (1, 3)) for x in extra_n]
    pen_d = [s_hat_d[h_hat == 1], s_til_d[h_til == 1], piece.offsets[h_face == 1], np.asarray(extra_d)]
    penumbra = ConvexVolume(np.vstack(pen_n), np.concatenate(pen_d), tol)

    vertex_volumes = tuple(
        ConvexVolume(np.vstack([sn, piece.normals[piece.normals @ q - piece.offsets > tol]]),
                     np.concatenate([sd, piece.offsets[piece.normals @ q - piece.offsets > tol]]), tol)
        for q, (sn, sd) in zip(Q, sil)
    )
    if umbra_rule == "intersection":
        umb_n = [u.normals for u in vertex_volumes]
        umb_d = [u.offsets for u in vertex_volumes]
    else:
        umb_n = [s_hat_n[h_hat == -1], piece.normals[h_face != -1]]
        umb_d = [s_hat_d[h_hat == -1], piece.offsets[h_face != -1]]
    umb_n += [np.reshape(x, (1, 3)) for x in extra_n]
    umb_d += [np.asarray(extra_d)]
    umbra = ConvexVolume(np.vstack(umb_n), np.concatenate(umb_d), tol)
    return ShadowVolumes(penumbra, umbra, vertex_volumes, piece)


def penumbra_volume(light: Any, occluder: Any, *, tol: float | None = None) -> ConvexVolume | None:
    """The penumbra volume alone; see :func:`shadow_volumes`.

    Examples
    --------
    >>> from isocsg import Box
    >>> from isocsg.lighting.area import AreaLight
    >>> lamp = AreaLight([(-.5, -.5, 2), (-.5, .5, 2), (.5, .5, 2), (.5, -.5, 2)])
    >>> penumbra_volume(lamp, Box((0, 0, 1), (1, 1, 0.01))).contains([[1.4, 0, 0]]).tolist()
    [True]
    """
    sv = shadow_volumes(light, occluder, tol=tol)
    return None if sv is None else sv.penumbra


def umbra_volume(light: Any, occluder: Any, *, tol: float | None = None) -> ConvexVolume | None:
    """The umbra volume alone; see :func:`shadow_volumes`.

    Examples
    --------
    >>> from isocsg import Box
    >>> from isocsg.lighting.area import AreaLight
    >>> lamp = AreaLight([(-.5, -.5, 2), (-.5, .5, 2), (.5, .5, 2), (.5, -.5, 2)])
    >>> umbra_volume(lamp, Box((0, 0, 1), (1, 1, 0.01))).contains([[0.1, 0, 0.5]]).tolist()
    [True]
    """
    sv = shadow_volumes(light, occluder, tol=tol)
    return None if sv is None else sv.umbra


def may_cast_shadow(face: ArrayLike, occluder: Any, light: Any, *, volumes: ShadowVolumes | None = None,
                    tol: float | None = None) -> bool:
    """Whether a convex occluder may shadow a receiving face (the seed's eqs. 5 and 6).

    Eq. (5): the occluder is not wholly in the negative space of the face.
    The seed writes ``H(S_f, V) = 1``; its stated meaning ("no shadow from any
    polyhedron within the negative space of S_f") is ``H(S_f, V) != -1``,
    which also covers occluders that cross the face's plane.
    Eq. (6): ``H(S~_p, S_f) != 1`` for every face ``S~_p`` of the penumbra
    volume (the face is not wholly outside one of its planes).
    For an area source an occluder wholly behind the source casts nothing.

    A ``True`` answer means a shadow is possible, ``False`` that none exists.

    Parameters
    ----------
    face : array_like, shape (k, 3)
        The receiving convex polygon (outward normal by the right-hand rule).
    occluder : ConvexPiece, Box, ConvexPolyhedron or (n, 3) points
    light : AreaLight or PolyhedronLight
    volumes : ShadowVolumes, optional
        Precomputed :func:`shadow_volumes` of this light and occluder.
    tol : float, optional

    Returns
    -------
    bool

    Examples
    --------
    >>> from isocsg import Box
    >>> from isocsg.lighting.area import AreaLight
    >>> lamp = AreaLight([(-.5, -.5, 2), (-.5, .5, 2), (.5, .5, 2), (.5, -.5, 2)])
    >>> table = Box((0, 0, 1), (1, 1, 0.01))
    >>> near = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]
    >>> far = [(5, -1, 0), (7, -1, 0), (7, 1, 0), (5, 1, 0)]
    >>> may_cast_shadow(near, table, lamp), may_cast_shadow(far, table, lamp)
    (True, False)
    """
    f = solid_faces([face])[0]
    piece = as_piece(occluder)
    _, t = _scale_tol(piece.vertices, f, tol=tol)
    pl = face_plane(f)
    if H_planes(pl.normal[None, :], np.array([pl.offset]), piece.vertices, tol=t)[0] == -1:
        return False
    sv = volumes if volumes is not None else shadow_volumes(light, piece, tol=tol)
    if sv is None:
        return False
    h = H_planes(sv.penumbra.normals, sv.penumbra.offsets, f, tol=t)
    return bool(np.all(h != 1))
