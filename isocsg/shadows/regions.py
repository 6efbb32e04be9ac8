"""Umbra and penumbra regions on receiving faces (seed 001, section 2.4).

For a receiving convex face ``S_f`` and one source, the occluders that may
shadow it are picked by eqs. (5) and (6); each one's penumbra and umbra
regions on the face are the sections of its penumbra and umbra volumes by the
face's plane, clipped to the face. Regions are shapely geometries in the
face's own 2D frame; :attr:`FaceShadows.frame` maps them back to 3D.

Several occluders:

- ``umbra`` is the union of the per-occluder umbrae;
- ``penumbra`` is the union of the per-occluder penumbrae minus ``umbra``.

Where the penumbrae of two or more occluders overlap, their silhouettes may
together cover the whole source although neither does alone: the *true*
umbra is then larger than the union of the per-occluder umbrae. Those places
lie in :attr:`FaceShadows.overlap`; :meth:`FaceShadows.classify` settles the
points there exactly (per-point visibility of the source) when asked to.

Face types (eqs. 3, 4): a type-B face (its plane cuts the source) is shadowed
with the part of the source in front of its plane, as the seed prescribes. A
type-C face receives no light at all: it has no occluder shadow regions, its
illuminance is 0 everywhere, and its points are in state 2 (none of the
source reaches them), as :func:`isocsg.shadows.shadow_state` reports them and
:meth:`FaceShadows.classify` returns.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import points_array
from ..errors import InvalidGeometryError
from ..kinds import DEFAULT_RESOLUTION, ConvexPolyhedron, Solid
from .classify import FaceType, classify_face, face_plane, solid_faces
from .volumes import ConvexVolume, SourceGeometry, as_piece, may_cast_shadow, shadow_volumes

__all__ = ["FaceShadows", "face_frame", "face_shadow_regions", "solid_shadow_regions"]


def face_frame(face: ArrayLike) -> NDArray[np.float64]:
    """The 4x4 frame of a planar face: ``(x, y, 0, 1) -> 3D``.

    The origin is the face's first vertex, the x axis runs along its first
    edge, the z axis is the outward normal (right-hand rule) and ``y = z x x``.

    Examples
    --------
    >>> m = face_frame([(0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2)])
    >>> (m @ [1.0, 1.0, 0.0, 1.0]).tolist()
    [1.0, 1.0, 2.0, 1.0]
    """
    f = points_array("face", face, min_rows=3)
    n = face_plane(f).normal
    e1 = f[1] - f[0]
    e1 = e1 - (e1 @ n) * n
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    m = np.eye(4)
    m[:3, 0], m[:3, 1], m[:3, 2], m[:3, 3] = e1, e2, n, f[0]
    return m


def _clip_halfplane(poly: NDArray[np.float64], a: NDArray[np.float64], c: float) -> NDArray[np.float64]:
    """The part of a convex 2D polygon with ``a . x <= c``."""
    if len(poly) == 0:
        return poly
    f = poly @ a - c
    out = []
    m = len(poly)
    for i in range(m):
        j = (i + 1) % m
        if f[i] <= 0:
            out.append(poly[i])
        if (f[i] <= 0) != (f[j] <= 0):
            t = f[i] / (f[i] - f[j])
            out.append(poly[i] + t * (poly[j] - poly[i]))
    return np.asarray(out).reshape(-1, 2)


def _section(volume: ConvexVolume, poly2d: NDArray[np.float64], frame: NDArray[np.float64]) -> Any:
    """The part of a face (2D polygon) inside a convex volume, as a shapely polygon."""
    from shapely.geometry import Polygon

    e1, e2, o = frame[:3, 0], frame[:3, 1], frame[:3, 3]
    a = np.column_stack([volume.normals @ e1, volume.normals @ e2])
    c = volume.offsets - volume.normals @ o
    scale = max(float(np.max(np.abs(poly2d))), 1.0)
    poly = poly2d
    for ai, ci in zip(a, c):
        if np.hypot(*ai) <= 1e-12:  # plane parallel to the face: all or nothing
            if ci < -volume.tol:
                return Polygon()
            continue
        poly = _clip_halfplane(poly, ai, ci)
        if len(poly) < 3:
            return Polygon()
    g = Polygon(poly)
    return g if g.area > 1e-14 * scale * scale else Polygon()


@dataclass(frozen=True, slots=True)
class FaceShadows:
    """Shadow regions of one source on one receiving face, in the face's 2D frame.

    Attributes
    ----------
    polygon : shapely.Polygon
        The face in its frame.
    frame : ndarray, shape (4, 4)
        Maps ``(x, y, 0, 1)`` of the frame to 3D (see :func:`face_frame`).
    face_type : FaceType
        Type of the face for the source (eqs. 3, 4).
    umbra : shapely geometry
        Union of the per-occluder umbra regions.
    penumbra : shapely geometry
        Union of the per-occluder penumbra regions minus ``umbra``.
    overlap : shapely geometry
        Where two or more penumbrae overlap outside ``umbra``: the true umbra
        may reach into it (points there need a per-point test).
    shadowing : tuple of int
        Indices (into the occluder pieces) of the occluders that may shadow
        the face (eqs. 5 and 6).
    """

    polygon: Any
    frame: NDArray[np.float64] = field(compare=False)
    face_type: FaceType
    umbra: Any
    penumbra: Any
    overlap: Any
    shadowing: tuple[int, ...]
    light: Any = field(compare=False, repr=False)
    occluders: tuple[Any, ...] = field(compare=False, repr=False)

    @property
    def normal(self) -> NDArray[np.float64]:
        """The face's outward unit normal."""
        return self.frame[:3, 2].copy()

    def to_3d(self, points: ArrayLike) -> NDArray[np.float64]:
        """Frame coordinates (n, 2) to world points (n, 3)."""
        p = points_array("points", points, columns=2)
        return p @ self.frame[:3, :2].T + self.frame[:3, 3]

    def to_2d(self, points: ArrayLike) -> NDArray[np.float64]:
        """World points (n, 3) (projected onto the face's plane) to frame coordinates (n, 2)."""
        p = points_array("points", points)
        return (p - self.frame[:3, 3]) @ self.frame[:3, :2]

    def classify(self, points: ArrayLike, *, exact: bool = False) -> NDArray[np.int8]:
        """Shadow state of face points given in frame coordinates: 0 lit, 1 penumbra, 2 umbra.

        Every point of a type-C face is in state 2 (none of the source reaches it).

        Parameters
        ----------
        points : array_like, shape (n, 2)
        exact : bool, keyword-only
            Settle the points of ``overlap`` by the exact per-point visibility
            of the source (:func:`isocsg.shadows.shadow_state`); otherwise they
            count as penumbra.

        Returns
        -------
        ndarray of int8, shape (n,)
        """
        import shapely

        p = points_array("points", points, columns=2)
        if self.face_type == FaceType.C:  # none of the source reaches the face
            return np.full(len(p), 2, dtype=np.int8)
        pts = shapely.points(p)
        out = np.zeros(len(p), dtype=np.int8)
        out[shapely.covers(self.penumbra, pts)] = 1
        out[shapely.covers(self.umbra, pts)] = 2
        if exact and not self.overlap.is_empty:
            from .direct import shadow_state

            idx = np.nonzero(shapely.covers(self.overlap, pts) & (out != 2))[0]
            if len(idx):
                solids = [self.occluders[i] for i in self.shadowing]
                out[idx] = shadow_state(self.to_3d(p[idx]), self.normal, self.light, solids)
        return out


def _occluder_list(occluders: Any, resolution: int) -> tuple[list[Any], list[Any]]:
    """Convex pieces and, for each, a solid that stands for it in per-point tests."""
    from .occluders import ConvexPiece, convex_pieces

    if isinstance(occluders, (Solid, ConvexPiece)):
        occluders = [occluders]
    pieces, solids = [], []
    for i, o in enumerate(occluders):
        if isinstance(o, Solid):
            for pc in convex_pieces([o], resolution=resolution):
                pieces.append(pc)
                solids.append(ConvexPolyhedron(pc.vertices))  # type: ignore[arg-type]  # array_like accepted; the field's annotation says tuples
        else:
            try:
                pc = as_piece(o)
            except InvalidGeometryError:
                raise InvalidGeometryError(
                    f"occluders[{i}] must be a solid or a convex piece, got {type(o).__name__}"
                ) from None
            pieces.append(pc)
            solids.append(ConvexPolyhedron(pc.vertices))
    return pieces, solids


def face_shadow_regions(
    face: ArrayLike,
    light: Any,
    occluders: Sequence[Any] | Any,
    *,
    resolution: int = DEFAULT_RESOLUTION,
    tol: float | None = None,
) -> FaceShadows:
    """Umbra and penumbra regions of one source on one convex receiving face.

    Parameters
    ----------
    face : array_like, shape (k, 3)
        A convex planar polygon, counter-clockwise seen from its lit side.
    light : AreaLight or PolyhedronLight
    occluders : Solid, ConvexPiece or sequence of them
        Solids are decomposed into convex pieces (curved primitives
        tessellated with ``resolution``).
    resolution : int, keyword-only, default 64
    tol : float, optional
        Geometric tolerance (default ``1e-9`` of the scene size).

    Returns
    -------
    FaceShadows

    Raises
    ------
    InvalidGeometryError
        On a degenerate face or an occluder that is not a solid.
    InvalidLightError
        If ``light`` is not an area or polyhedron source.

    Examples
    --------
    >>> from isocsg import Box
    >>> from isocsg.lighting.area import AreaLight
    >>> lamp = AreaLight([(-.5, -.5, 2), (-.5, .5, 2), (.5, .5, 2), (.5, -.5, 2)])
    >>> floor = [(-3, -3, 0), (3, -3, 0), (3, 3, 0), (-3, 3, 0)]
    >>> fs = face_shadow_regions(floor, lamp, [Box((0, 0, 1), (1, 1, 0.01))])
    >>> round(fs.umbra.area, 3), round(fs.penumbra.area + fs.umbra.area, 2)
    (1.0, 9.12)
    """
    import shapely
    from shapely.geometry import Polygon

    f = points_array("face", face, min_rows=3)
    frame = face_frame(f)
    poly2d = (f - frame[:3, 3]) @ frame[:3, :2]
    face_poly = Polygon(poly2d)
    pieces, solids = _occluder_list(occluders, resolution)
    ftype = classify_face(f, light, tol=tol)
    empty = Polygon()
    if ftype == FaceType.C:
        return FaceShadows(face_poly, frame, ftype, empty, empty, empty, (), light, tuple(solids))
    src = SourceGeometry.from_light(light)
    if ftype == FaceType.B:
        clipped = src.clipped(face_plane(f), tol=tol)
        if clipped is None:  # pragma: no cover - a type-B face always keeps a part of the source
            return FaceShadows(face_poly, frame, FaceType.C, empty, empty, empty, (), light, tuple(solids))
        src = clipped
    umbrae, penumbrae, shadowing = [], [], []
    for i, pc in enumerate(pieces):
        sv = shadow_volumes(src, pc, tol=tol)
        if sv is None or not may_cast_shadow(f, pc, src, volumes=sv, tol=tol):
            continue
        pen = _section(sv.penumbra, poly2d, frame)
        if pen.is_empty:
            continue
        shadowing.append(i)
        penumbrae.append(pen)
        umbrae.append(_section(sv.umbra, poly2d, frame))
    umbra = shapely.union_all(umbrae) if umbrae else empty
    pen_all = shapely.union_all(penumbrae) if penumbrae else empty
    penumbra = pen_all.difference(umbra) if not umbra.is_empty else pen_all
    overlaps = [penumbrae[a].intersection(penumbrae[b])
                for a in range(len(penumbrae)) for b in range(a + 1, len(penumbrae))]
    overlap = shapely.union_all(overlaps).difference(umbra) if overlaps else empty
    if overlap.area <= 0:
        overlap = empty
    return FaceShadows(face_poly, frame, ftype, umbra, penumbra, overlap, tuple(shadowing), light, tuple(solids))


def solid_shadow_regions(
    solid: Any,
    light: Any,
    occluders: Sequence[Any] | Any,
    *,
    resolution: int = DEFAULT_RESOLUTION,
    tol: float | None = None,
) -> list[FaceShadows]:
    """:func:`face_shadow_regions` for every face of a ``Box`` or ``ConvexPolyhedron``.

    The solid itself may be among the occluders: a convex solid never shadows
    its own faces (eq. 5).

    Examples
    --------
    >>> from isocsg import Box
    >>> from isocsg.lighting.area import AreaLight
    >>> lamp = AreaLight([(-.5, -.5, 3), (-.5, .5, 3), (.5, .5, 3), (.5, -.5, 3)])
    >>> slab = Box((0, 0, -0.5), (6, 6, 1))
    >>> regions = solid_shadow_regions(slab, lamp, [slab, Box((0, 0, 1), (1, 1, 0.2))])
    >>> [r.face_type.name for r in regions].count("A"), max(r.umbra.area for r in regions) > 0
    (1, True)
    """
    return [face_shadow_regions(f, light, occluders, resolution=resolution, tol=tol) for f in solid_faces(solid)]
