"""The triangle mesh kind: a closed, consistently oriented triangle mesh as a solid.

A :class:`TriangleMesh` holds ``vertices (n, 3)`` and ``faces (m, 3)`` (vertex indices,
counter-clockwise seen from outside). It is what OpenSCAD's ``import()`` of STL, OFF, OBJ and
3MF files, its non-convex ``polyhedron`` and its ``surface()`` height maps become.

**Validity** (checked on construction, else :class:`~isocsg.errors.InvalidGeometryError`
naming the problem): finite coordinates, face indices in range, no face that repeats a vertex,
every directed edge used once and its reverse once (closed, edge-manifold and consistently
oriented), a positive volume (outward orientation), and no self-intersection: no edge passes
through a face that does not share one of its ends (every pair of crossing triangles has such an
edge; two faces overlapping within one plane are not detected). A mesh that fails (except for a
self-intersection) can be repaired on request (:meth:`TriangleMesh.repaired`: trimesh merges duplicate
vertices, drops degenerate and duplicate faces, fills holes and makes the winding consistent
and outward); the repaired mesh is checked again.

Every operation is exact for the mesh:

- rays: a bounding-volume hierarchy (:mod:`~isocsg.kinds.mesh_bvh`) gives each line all its
  depth intervals (watertight edge tests, a documented rule for edges and vertices);
- ``max_intervals`` is ``len(faces) // 2``, a true bound (each interval uses two crossings and
  a line crosses a face at most once); :meth:`TriangleMesh.ray_intervals` returns as many
  columns as the rays it is given need;
- volume by the divergence theorem, about the centre of the bounds;
- signed distance: the exact distance to the nearest face, negative where a ray from the point
  has positive winding;
- sections: the plane cuts each face crossing it in one segment, polygonised (even-odd);
- bands: the faces themselves (:mod:`~isocsg.kinds.mesh_bands`), each flat with its normal;
- shadows: a convex mesh is its own occluder; a non-convex mesh is cut into convex pieces by a
  binary space partition along its own face planes (:mod:`~isocsg.kinds.mesh_convex`), exactly.
"""

from __future__ import annotations

import contextvars
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import MAX_ABS_COORD
from ..errors import InvalidGeometryError
from .base import DEFAULT_RESOLUTION, Primitive, RayHits, _as_rays
from .forms import TriangleSurface
from .polyhedron import ConvexPolyhedron
from .registry import register_kind
from .scad import vec

if TYPE_CHECKING:  # pragma: no cover
    from shapely.geometry import Polygon

__all__ = ["TriangleMesh", "MAX_MESH_FACES"]

#: The most faces a mesh may have.
MAX_MESH_FACES = 20_000_000


def _arrays(vertices: ArrayLike, faces: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """The inputs as checked arrays (shapes, finiteness, index range)."""
    try:
        V = np.array(vertices, dtype=np.float64)
    except (TypeError, ValueError):
        raise InvalidGeometryError("TriangleMesh.vertices must be an (n, 3) array of numbers") from None
    if V.ndim != 2 or V.shape[1] != 3:
        raise InvalidGeometryError(f"TriangleMesh.vertices must have shape (n, 3), got {V.shape}")
    if not np.all(np.isfinite(V)):
        bad = int(np.nonzero(~np.all(np.isfinite(V), axis=1))[0][0])
        raise InvalidGeometryError(f"TriangleMesh.vertices must be finite, got {V[bad].tolist()} at row {bad}")
    if len(V) and float(np.max(np.abs(V))) > MAX_ABS_COORD:
        raise InvalidGeometryError(f"TriangleMesh.vertices must lie within {MAX_ABS_COORD:g} of the origin")
    try:
        Fr = np.array(faces)
    except (TypeError, ValueError):
        raise InvalidGeometryError("TriangleMesh.faces must be an (m, 3) array of vertex indices") from None
    if Fr.ndim != 2 or Fr.shape[1] != 3:
        raise InvalidGeometryError(
            f"TriangleMesh.faces must have shape (m, 3) (triangles), got {Fr.shape}")
    if Fr.size and not (np.issubdtype(Fr.dtype, np.integer) or
                        (np.issubdtype(Fr.dtype, np.floating) and np.all(np.mod(Fr, 1) == 0))):
        raise InvalidGeometryError("TriangleMesh.faces must hold integer vertex indices")
    F = Fr.astype(np.int64)
    if len(F) < 4:
        raise InvalidGeometryError(f"TriangleMesh.faces must hold at least 4 triangles (a closed mesh), got {len(F)}")
    if len(F) > MAX_MESH_FACES:
        raise InvalidGeometryError(f"TriangleMesh.faces must hold at most {MAX_MESH_FACES} triangles, got {len(F)}")
    if F.min() < 0 or F.max() >= len(V):
        raise InvalidGeometryError(
            f"TriangleMesh.faces must index the {len(V)} vertices, got indices {int(F.min())} .. {int(F.max())}")
    return V, F


def _check_closed(F: NDArray[np.int64]) -> None:
    """Every directed edge once and its reverse once: closed, edge-manifold, consistently oriented."""
    rep = (F[:, 0] == F[:, 1]) | (F[:, 1] == F[:, 2]) | (F[:, 2] == F[:, 0])
    if rep.any():
        raise InvalidGeometryError(f"TriangleMesh.faces must not repeat a vertex, got face {int(np.argmax(rep))} "
                                   f"{F[int(np.argmax(rep))].tolist()}")
    n = int(F.max()) + 1
    a = F.reshape(-1)
    b = np.roll(F, -1, axis=1).reshape(-1)
    key = a * n + b
    uniq, counts = np.unique(key, return_counts=True)
    if np.any(counts > 1):
        e = int(uniq[np.argmax(counts > 1)])
        raise InvalidGeometryError(
            f"TriangleMesh.faces are not consistently oriented or not manifold: the edge {e // n} -> {e % n} "
            "is used by more than one face in the same direction (the constructor repaired() can fix the orientation)")
    rev = b * n + a
    at = np.minimum(np.searchsorted(uniq, rev), len(uniq) - 1)  # uniq is sorted
    missing = uniq[at] != rev
    if missing.any():
        k = int(np.argmax(missing))
        raise InvalidGeometryError(
            f"TriangleMesh.faces are not closed (watertight): the edge {int(a[k])} -> {int(b[k])} of face {k // 3} "
            "has no face on its other side (the constructor repaired() can fill holes)")


def _signed_volume(V: NDArray[np.float64], F: NDArray[np.int64]) -> float:
    c = 0.5 * (V.min(axis=0) + V.max(axis=0))  # about the centre: no cancellation far from the origin
    a, b, d = V[F[:, 0]] - c, V[F[:, 1]] - c, V[F[:, 2]] - c
    return float(np.einsum("ij,ij->i", a, np.cross(b, d)).sum() / 6.0)


#: Set while building a mesh known not to cross itself (an affine image of a checked mesh, a height
#: map): the self-intersection check, the costly one (45 s for a 200 x 200 height map), is skipped.
_SIMPLE: contextvars.ContextVar[bool] = contextvars.ContextVar("isocsg_mesh_simple", default=False)


@register_kind("mesh", required=("vertices", "faces"))
@dataclass(frozen=True, eq=False)
class TriangleMesh(Primitive):
    """A closed triangle mesh as a solid (see the module docstring for validity and exactness).

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
        Finite coordinates.
    faces : array_like, shape (m, 3)
        Vertex indices of each triangle, counter-clockwise seen from outside; ``m >= 4``.

    Raises
    ------
    InvalidGeometryError
        On non-finite coordinates, bad shapes or indices, an open, non-manifold or inconsistently
        oriented mesh, or a volume that is not positive (faces wound inwards).

    Notes
    -----
    The class is a frozen dataclass without ``__slots__``: each mesh carries its own
    ``max_intervals`` (``len(faces) // 2``) over the class's bound. Equality and hashing use the
    exact bytes of the arrays (a digest), so equal meshes share their render work.

    Examples
    --------
    >>> m = TriangleMesh([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)], [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)])
    >>> round(m.volume, 6), m.contains([[0.1, 0.1, 0.1], [1, 1, 1]]).tolist()
    (0.166667, [True, False])
    """

    vertices: NDArray[np.float64]
    faces: NDArray[np.int64]
    face_normals: NDArray[np.float64] = field(init=False, repr=False)
    kind: ClassVar[str] = "mesh"
    convex: ClassVar[bool] = False
    polyhedral: ClassVar[bool] = True
    #: The bound over every mesh; each mesh's own is ``len(faces) // 2``.
    max_intervals: ClassVar[int] = MAX_MESH_FACES // 2

    if TYPE_CHECKING:  # the constructor as callers call it: array-likes, checked in __post_init__
        def __init__(self, vertices: ArrayLike, faces: ArrayLike) -> None: ...

    def __post_init__(self) -> None:
        V, F = _arrays(self.vertices, self.faces)
        _check_closed(F)
        used = np.zeros(len(V), bool)
        used[F.reshape(-1)] = True
        if not used.all():  # unreferenced vertices: dropped, the faces renumbered
            remap = np.cumsum(used) - 1
            V, F = V[used], remap[F]
        vol = _signed_volume(V, F)
        size = float(np.max(np.ptp(V, axis=0)))
        if not vol > 1e-12 * size**3:
            raise InvalidGeometryError(
                f"TriangleMesh must have a positive volume (faces counter-clockwise seen from outside), got {vol:g}"
                + (" (its faces wind inwards: reverse them)" if vol < 0 else ""))
        object.__setattr__(self, "_bvh", None)
        object.__setattr__(self, "vertices", V)
        object.__setattr__(self, "faces", F)
        if not _SIMPLE.get():
            self._check_crossings()
        cross = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
        norm = np.linalg.norm(cross, axis=1)
        normals = cross / np.where(norm > 0, norm, 1.0)[:, None]
        for arr in (V, F, normals):
            arr.setflags(write=False)
        object.__setattr__(self, "vertices", V)
        object.__setattr__(self, "faces", F)
        object.__setattr__(self, "face_normals", normals)
        object.__setattr__(self, "max_intervals", len(F) // 2)
        object.__setattr__(self, "_volume", vol)
        import hashlib  # here: a model without meshes does not load it

        object.__setattr__(self, "_digest", hashlib.blake2b(V.tobytes() + b"|" + F.tobytes(), digest_size=16).digest())

    @classmethod
    def _simple(cls, vertices: ArrayLike, faces: ArrayLike) -> TriangleMesh:
        """A mesh its caller knows not to cross itself (see ``_SIMPLE``): every other check is made."""
        token = _SIMPLE.set(True)
        try:
            return cls(vertices, faces)
        finally:
            _SIMPLE.reset(token)

    def _check_crossings(self) -> None:
        """Refuse a mesh with an edge through a face that does not share its ends (a self-intersection;
        :func:`~isocsg.kinds.mesh_bvh.bvh_edge_crossing`)."""
        from .mesh_bvh import bvh_edge_crossing

        F = self.faces
        e = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])
        e = e[e[:, 0] < e[:, 1]]  # each edge once (its reverse belongs to the neighbouring face)
        k, face = bvh_edge_crossing(self.bvh, self.vertices, F, e)
        if k >= 0:
            a, b = (int(x) for x in e[k])
            raise InvalidGeometryError(
                f"TriangleMesh.faces intersect themselves: the edge {a} -> {b} passes through face {face} "
                f"{F[face].tolist()} (a self-intersecting mesh is not a valid solid; repair cannot fix it)")

    # ------------------------------------------------------------ value semantics
    def __eq__(self, other: object) -> bool:
        if not isinstance(other, TriangleMesh):
            return NotImplemented
        return bool(self._digest == other._digest and np.array_equal(self.vertices, other.vertices)  # type: ignore[attr-defined]
                    and np.array_equal(self.faces, other.faces))

    def __hash__(self) -> int:
        return hash(self._digest)  # type: ignore[attr-defined]

    def __repr__(self) -> str:
        return f"TriangleMesh(<{len(self.vertices)} vertices>, <{len(self.faces)} faces>)"

    @property
    def vertex_array(self) -> NDArray[np.float64]:
        """The vertices (read-only float64)."""
        return self.vertices

    @property
    def face_array(self) -> NDArray[np.int64]:
        """The faces (read-only int64)."""
        return self.faces

    @property
    def bvh(self) -> tuple[NDArray[np.float64], ...]:
        """The bounding-volume hierarchy (:func:`~isocsg.kinds.mesh_bvh.build_bvh`), built on first use."""
        b = self._bvh  # type: ignore[attr-defined]
        if b is None:
            from .mesh_bvh import build_bvh  # numba on first use only

            b = build_bvh(self.vertices, self.faces)
            object.__setattr__(self, "_bvh", b)
        return b  # type: ignore[no-any-return]

    # ------------------------------------------------------------ constructors
    @classmethod
    def repaired(cls, vertices: ArrayLike, faces: ArrayLike) -> TriangleMesh:
        """A mesh from possibly faulty input, repaired by trimesh: duplicate vertices merged, degenerate
        and duplicate faces dropped, holes filled where trimesh can (``fill_holes``), the winding made
        consistent and outward (``fix_normals``). The result is checked as any mesh.

        Raises
        ------
        InvalidGeometryError
            When the repaired mesh is still not a valid closed solid (e.g. a hole trimesh cannot fill).
        """
        import trimesh

        V, F = _arrays(vertices, faces)
        tm = trimesh.Trimesh(V, F, process=True, validate=True)
        tm.merge_vertices()
        tm.update_faces(tm.nondegenerate_faces())
        tm.update_faces(tm.unique_faces())
        tm.remove_unreferenced_vertices()
        trimesh.repair.fill_holes(tm)
        trimesh.repair.fix_normals(tm, multibody=True)
        return cls(np.asarray(tm.vertices), np.asarray(tm.faces))

    @classmethod
    def from_trimesh(cls, mesh: Any, *, repair: bool = False) -> TriangleMesh:
        """The solid of a ``trimesh.Trimesh`` (``repair``: through :meth:`repaired`)."""
        v, f = np.asarray(mesh.vertices), np.asarray(mesh.faces)
        return cls.repaired(v, f) if repair else cls(v, f)

    # ------------------------------------------------------------ geometry
    @property
    def bounds(self) -> NDArray[np.float64]:
        """Exact axis-aligned bounds, shape (2, 3)."""
        return np.stack([self.vertices.min(axis=0), self.vertices.max(axis=0)])

    def extent(self, n: ArrayLike) -> tuple[float, float]:
        """Exact extent along ``n``: its vertices' support."""
        h = self.vertices @ np.asarray(n, dtype=np.float64)
        return float(h.min()), float(h.max())

    def breakpoints(self, n: ArrayLike) -> NDArray[np.float64]:
        """The heights of its vertices along ``n`` (the section's area is quadratic between them)."""
        return np.unique(self.vertices @ np.asarray(n, dtype=np.float64))  # type: ignore[no-any-return]

    @property
    def volume(self) -> float:
        """Exact volume by the divergence theorem (sum of signed tetrahedra about the bounds' centre)."""
        return float(self._volume)  # type: ignore[attr-defined]

    # ------------------------------------------------------------ membership
    def signed_distance(self, points: ArrayLike) -> NDArray[np.float64]:
        """Exact distance to the nearest face, negative inside (positive winding along a fixed ray)."""
        from .mesh_bvh import bvh_nearest, bvh_winding_parity

        p = self._points(points)
        dist, _ = bvh_nearest(self.bvh, self.vertices, self.faces, p)
        inside = bvh_winding_parity(self.bvh, self.vertices, self.faces, p)
        return np.where(inside, -dist, dist)  # type: ignore[no-any-return]

    def normals_at(self, points: ArrayLike) -> NDArray[np.float64]:
        """The outward normal of the face nearest each point."""
        from .mesh_bvh import bvh_nearest

        p = np.asarray(points, dtype=np.float64).reshape(-1, 3)
        _, face = bvh_nearest(self.bvh, self.vertices, self.faces, p)
        return self.face_normals[face]  # type: ignore[no-any-return]

    def part_index(self, points: NDArray[np.float64], normals: NDArray[np.float64]) -> NDArray[np.int64]:
        """The index of the face nearest each point."""
        from .mesh_bvh import bvh_nearest

        _, face = bvh_nearest(self.bvh, self.vertices, self.faces, np.asarray(points, np.float64).reshape(-1, 3))
        return face

    # ------------------------------------------------------------ rays
    def ray_intervals(self, origins: ArrayLike, directions: ArrayLike) -> NDArray[np.float64]:
        """Every depth interval of each ray's line in the solid, ``(n, k, 2)`` NaN padded, ``t`` in units
        of each direction's length; ``k`` is the most any of these rays needs (at least 1, at most
        ``max_intervals``). See :mod:`~isocsg.kinds.mesh_bvh` for the edge and vertex rule."""
        from .mesh_bvh import bvh_ray_intervals

        o, d = _as_rays(origins, directions)
        good = np.any(d != 0.0, axis=1)
        out = bvh_ray_intervals(self.bvh, self.vertices, self.faces, o, np.where(good[:, None], d, 1.0))
        out[~good] = np.nan
        return out

    def intersect_rays(self, origins: ArrayLike, directions: ArrayLike) -> RayHits:
        """The first depth interval of each ray with the normals at its ends (:meth:`ray_intervals`)."""
        return self.first_interval_hits(origins, directions)

    # ------------------------------------------------------------ sections
    def section(self, frame: NDArray[np.float64], resolution: int, area_exact: bool = False) -> Polygon:
        """The exact section by the plane of ``frame``: each face crossing the plane gives one segment,
        the segments are polygonised and the faces combined even-odd. A vertex exactly in the plane
        counts as above it (so a face lying in the plane gives no segment)."""
        from .mesh_section import mesh_section

        return mesh_section(self.vertices, self.faces, np.asarray(frame, dtype=np.float64))

    def planar_faces(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Every face's plane (outward normal and offset)."""
        n = self.face_normals
        return n, np.einsum("ij,ij->i", n, self.vertices[self.faces[:, 0]])

    def exact_form(self) -> TriangleSurface:
        """A :class:`~isocsg.kinds.forms.TriangleSurface`: its own vertices and faces."""
        return TriangleSurface(self.vertices, self.faces)

    def hull_points(self) -> NDArray[np.float64]:
        """Its vertices (their hull is the hull of the solid)."""
        return np.asarray(self.vertices, dtype=np.float64)

    # ------------------------------------------------------------ meshes and shadows
    def to_polyhedron(self, resolution: int = DEFAULT_RESOLUTION) -> ConvexPolyhedron:
        """The convex hull of its vertices (the solid itself only when it is convex)."""
        return ConvexPolyhedron(self.vertices)

    def is_convex(self) -> bool:
        """Whether the solid equals its convex hull (volumes equal to 1e-9)."""
        return abs(self.to_polyhedron().volume - self.volume) <= 1e-9 * self.volume

    def convex_pieces(self, resolution: int = DEFAULT_RESOLUTION) -> list[ConvexPolyhedron]:
        """Itself when convex (its hull); otherwise the inside cells of a binary space partition by
        its own face planes (:func:`~isocsg.kinds.mesh_convex.convex_cells`): convex pieces whose
        union is the mesh exactly, computed once per mesh.

        Raises
        ------
        InvalidParameterError
            For a non-convex mesh past the decomposition's documented size
            (:data:`~isocsg.kinds.mesh_convex.MAX_DECOMPOSITION_FACES` faces).
        """
        if self.is_convex():
            return [self.to_polyhedron()]
        cached = self.__dict__.get("_convex_pieces")
        if cached is None:
            from .mesh_convex import convex_cells

            pieces = []
            for cell in convex_cells(self.vertex_array, self.face_array, self.contains):
                try:
                    pieces.append(ConvexPolyhedron(cell))
                except InvalidGeometryError:  # a cell flattened to rounding carries no volume
                    continue
            cached = tuple(pieces)
            object.__setattr__(self, "_convex_pieces", cached)
        return list(cached)

    def to_trimesh(self, resolution: int = DEFAULT_RESOLUTION) -> Any:
        """The mesh itself as a ``trimesh.Trimesh``."""
        import trimesh

        return trimesh.Trimesh(np.array(self.vertices), np.array(self.faces), process=False)

    def manifold(self, resolution: int, shapes: dict[tuple[Any, ...], Any] | None = None) -> Any:
        """The mesh as a manifold3d ``Manifold`` (double precision through ``Mesh64`` where available)."""
        from .meshing import manifold3d_module

        m3d = manifold3d_module()
        if hasattr(m3d, "Mesh64"):
            mesh = m3d.Mesh64(vert_properties=np.array(self.vertices, np.float64),  # writable copies
                              tri_verts=np.array(self.faces, np.uint64))
        else:  # pragma: no cover - older manifold3d
            mesh = m3d.Mesh(vert_properties=np.ascontiguousarray(self.vertices, np.float32),
                            tri_verts=np.ascontiguousarray(self.faces, np.uint32))
        return m3d.Manifold(mesh)

    # ------------------------------------------------------------ bands
    def band_surface(
        self, lights: list[Any], contours: int, eye: NDArray[np.float64] | None, shininess: float,
        weights: tuple[float, float] = (1.0, 1.0), segments: int | None = None, *,
        hidden: tuple[Any, Any] | None = None,
    ) -> Any:
        """Its faces, each flat with its own normal (:func:`~isocsg.kinds.mesh_bands.mesh_surface`)."""
        from .mesh_bands import mesh_surface

        return mesh_surface(self, lights, contours, eye, shininess, weights)

    #: The band surface is the surface itself: the renderer may take each hit's values from the band
    #: triangle nearest the exact hit point (:mod:`isocsg.rendering.layers`).
    flat_bands: ClassVar[bool] = True

    # ------------------------------------------------------------ files
    def to_dict(self) -> dict[str, Any]:
        """``{"mesh": {"vertices": [...], "faces": [...]}}``."""
        return {"mesh": {"vertices": self.vertices.tolist(), "faces": self.faces.tolist()}}

    def to_openscad(self, digits: int | None = None, *, exact: bool = True) -> str:
        """``polyhedron(points, faces)``: coordinates by ``repr`` (exact; ``digits`` is not applied, a
        rounded mesh could open or cross itself), faces clockwise seen from outside as OpenSCAD wants."""
        pts = ", ".join(vec(p) for p in self.vertices)
        faces = ", ".join(f"[{int(c)}, {int(b)}, {int(a)}]" for a, b, c in self.faces)
        return f"polyhedron(points = [{pts}], faces = [{faces}]);"

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> Primitive:
        """The mapped vertices; a reflection reverses every face."""
        V = self.vertices @ A.T + t
        F = self.faces[:, ::-1] if np.linalg.det(A) < 0 else self.faces
        return TriangleMesh._simple(V, F)  # an affine image of a mesh that does not cross itself
