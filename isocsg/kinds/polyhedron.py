"""The convex polyhedron kind: the convex hull of a set of points, exact in every operation.

Rays are clipped by its face half-spaces, sections are the exact convex polygons of
those half-spaces in the plane, its signed distance is the largest face-plane
distance, and its OpenSCAD form places every vertex exactly (the ``hull()`` of
one small tetrahedron per vertex, see :func:`polyhedron_scad`).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import MAX_VERTICES, Vec3, length_floor, points_array
from ..errors import InvalidGeometryError
from .base import (
    DEFAULT_RESOLUTION,
    LeafForm,
    LeafRow,
    Primitive,
    RayHits,
    TangentCone,
    _as_rays,
)
from .forms import PointHull
from .halfspaces import polyhedral_tangent, ray_halfspaces
from .meshing import manifold3d_module
from .patches import Patch, face_normals, polytope_patches
from .polygon_faces import fan_triangles
from .registry import kind_class, register_kind
from .scad import encoded, num_sig, round_sig, short_mat, vec

if TYPE_CHECKING:  # pragma: no cover
    from shapely.geometry import Polygon

    from ..bands.surface import Surface

__all__ = ["ConvexPolyhedron"]



def _hull(
    points: NDArray[np.float64], name: str,
) -> tuple[NDArray[np.float64], list[NDArray[np.int64]], NDArray[np.float64], NDArray[np.float64], NDArray[np.int64]]:
    """Convex hull as merged planar faces.

    Returns hull vertices, faces (vertex indices counter-clockwise seen from
    outside), unit outward normals, plane offsets (``n . x = d``) and a
    triangulation of the faces.
    """
    from scipy.spatial import ConvexHull, QhullError

    scale = float(np.max(np.ptp(points, axis=0))) if len(points) else 0.0
    if scale <= 0:
        raise InvalidGeometryError(f"{name} are all the same point")
    try:
        hull = ConvexHull(points)
    except (QhullError, ValueError):
        raise InvalidGeometryError(f"{name} are coplanar or degenerate: their hull has no volume") from None
    if hull.volume <= 1e-12 * scale**3:
        raise InvalidGeometryError(f"{name} are coplanar or degenerate: their hull has no volume")
    verts_idx = hull.vertices
    remap = -np.ones(len(points), dtype=np.int64)
    remap[verts_idx] = np.arange(len(verts_idx))
    hv = points[verts_idx]
    eq = hull.equations  # n . x + e = 0, n outward unit
    # A face is one of qhull's facets (coplanar ones merged, convex), whose triangles share
    # their plane bit for bit. Grouping nearly coplanar facets by a rounded plane could join
    # a non-convex set of them, whose fan then overlaps itself.
    _, group = np.unique(eq, axis=0, return_inverse=True)
    group = group.ravel()
    # Every face at once (a polygonal cylinder has a face per side): its distinct vertices, each
    # face's first facet's plane, the vertices sorted by angle about the face's centroid.
    n_groups = int(group.max()) + 1
    first = np.unique(group, return_index=True)[1]
    keys = np.unique(group[:, None] * len(hv) + remap[hull.simplices])
    g, idx = keys // len(hv), keys % len(hv)
    count = np.bincount(g, minlength=n_groups).astype(np.float64)
    c = np.stack([np.bincount(g, weights=hv[idx, k], minlength=n_groups) for k in range(3)], axis=1) / count[:, None]
    n = eq[first, :3]
    h = np.where((np.abs(n[:, 0]) < 0.9)[:, None], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
    u = np.cross(n, h)
    u /= np.linalg.norm(u, axis=1)[:, None]
    v = np.cross(n, u)
    d = hv[idx] - c[g]
    ang = np.arctan2(np.einsum("ij,ij->i", d, v[g]), np.einsum("ij,ij->i", d, u[g]))
    order = np.lexsort((ang, g))  # CCW around the outward normal, face by face
    faces = np.split(idx[order], np.cumsum(np.bincount(g, minlength=n_groups))[:-1])
    normals, offsets = n, -eq[first, 3]
    tris = fan_triangles([f.tolist() for f in faces])
    return hv, faces, normals, offsets, tris


@register_kind("polyhedron", required=("vertices",))
@dataclass(frozen=True, slots=True)
class ConvexPolyhedron(Primitive):
    """The convex hull of a set of points.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
        At least 4 points, not all coplanar. Interior points are allowed and
        dropped from ``hull_vertices``.

    Raises
    ------
    InvalidGeometryError
        On fewer than 4 points, non-finite values or a flat (volume-less) hull.

    Examples
    --------
    >>> t = ConvexPolyhedron([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)])
    >>> len(t.faces), round(t.volume, 6)
    (4, 0.166667)
    """

    vertices: tuple[Vec3, ...]
    hull_vertices: NDArray[np.float64] = field(init=False, repr=False, compare=False, hash=False)
    faces: tuple[NDArray[np.int64], ...] = field(init=False, repr=False, compare=False, hash=False)
    face_normals: NDArray[np.float64] = field(init=False, repr=False, compare=False, hash=False)
    face_offsets: NDArray[np.float64] = field(init=False, repr=False, compare=False, hash=False)
    triangles: NDArray[np.int64] = field(init=False, repr=False, compare=False, hash=False)
    kind: ClassVar[str] = "polyhedron"
    polyhedral: ClassVar[bool] = True

    if TYPE_CHECKING:  # the constructor as callers call it: array-likes, checked in __post_init__
        def __init__(self, vertices: ArrayLike) -> None: ...

    def __post_init__(self) -> None:
        name = f"{type(self).__name__}.vertices"
        pts = points_array(name, self.vertices, min_rows=4, max_rows=MAX_VERTICES)
        extent = float(np.max(np.ptp(pts, axis=0)))
        floor = length_floor(pts.min(axis=0), pts.max(axis=0))
        if 0.0 < extent < floor:
            raise InvalidGeometryError(
                f"{name} must span at least {floor:g} (the smallest length at this position), got {extent:g}"
            )
        object.__setattr__(self, "vertices", tuple(tuple(map(float, p)) for p in pts))
        hv, faces, normals, offsets, tris = _hull(pts, name)
        for arr in (hv, normals, offsets, tris):
            arr.setflags(write=False)
        object.__setattr__(self, "hull_vertices", hv)
        object.__setattr__(self, "faces", tuple(faces))
        object.__setattr__(self, "face_normals", normals)
        object.__setattr__(self, "face_offsets", offsets)
        object.__setattr__(self, "triangles", tris)

    def face_polygons(self) -> list[NDArray[np.float64]]:
        """Each face as a (k, 3) array, counter-clockwise seen from outside."""
        return [self.hull_vertices[f] for f in self.faces]


    @property
    def bounds(self) -> NDArray[np.float64]:
        """Axis-aligned bounds, shape (2, 3)."""
        return np.stack([self.hull_vertices.min(axis=0), self.hull_vertices.max(axis=0)])

    @property
    def volume(self) -> float:
        """Exact volume of the hull."""
        v = self.hull_vertices[self.triangles] - self.hull_vertices[0]  # about a vertex: no cancellation far out
        return float(abs(np.einsum("ij,ij->i", v[:, 0], np.cross(v[:, 1], v[:, 2])).sum()) / 6.0)

    def intersect_rays(self, origins: ArrayLike, directions: ArrayLike) -> RayHits:
        """Exact ray-polyhedron intersection by half-space clipping."""
        o, d = _as_rays(origins, directions)
        return ray_halfspaces(o, d, self.face_normals, self.face_offsets)

    def to_polyhedron(self, resolution: int = DEFAULT_RESOLUTION) -> ConvexPolyhedron:
        """The polyhedron itself (it is already exact)."""
        return self

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> Primitive:
        # the hull of the mapped points is the image of the hull (affine maps keep convexity)
        pts = np.asarray(self.vertices, dtype=np.float64) @ A.T + t
        if np.linalg.cond(A) > 1e6:  # nearly flattening maps: the full hull build and its checks
            return ConvexPolyhedron(pts)  # type: ignore[arg-type]  # any (n, 3) array-like
        return _mapped(self, pts, A, t)

    # ------------------------------------------------------------ the kind interface
    def extent(self, n: ArrayLike) -> tuple[float, float]:
        """Exact extent along the unit vector ``n``: its vertices' support."""
        proj = self.hull_vertices @ np.asarray(n, dtype=np.float64)
        return float(proj.min()), float(proj.max())

    def breakpoints(self, n: ArrayLike) -> NDArray[np.float64]:
        """The heights of its vertices along ``n`` (the section's area is smooth between them)."""
        return self.hull_vertices @ np.asarray(n, dtype=np.float64)  # type: ignore[no-any-return]

    def signed_distance(self, points: ArrayLike) -> NDArray[np.float64]:
        """The largest signed distance to the face planes: exact inside, a lower bound outside."""
        p = np.asarray(points, dtype=np.float64).reshape(-1, 3)
        return (p @ self.face_normals.T - self.face_offsets).max(axis=1)  # type: ignore[no-any-return]

    def tangent_cone(self, points: NDArray[np.float64], tol: float) -> TangentCone:
        """The faces within ``tol`` of each point (a half-space, wedge or corner)."""
        return polyhedral_tangent(self.face_normals, self.face_offsets, points, tol)

    def section(self, frame: NDArray[np.float64], resolution: int, area_exact: bool = False) -> Polygon:
        """Exact, from its faces and hull vertices."""
        from .planar import halfspace_section

        return halfspace_section(self.face_normals, self.face_offsets, self.hull_vertices, frame)

    def local_faces(self) -> tuple[NDArray[np.float64], list[NDArray[np.float64]]]:
        """The centre of its bounds and its faces about it, for :mod:`isocsg.kinds.polyhedron_bands`."""
        lo, hi = self.bounds
        origin = 0.5 * (lo + hi)
        return origin, [np.asarray(f, dtype=np.float64) - origin for f in self.face_polygons()]

    def planar_faces(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Its face planes."""
        return self.face_normals, self.face_offsets

    def part_index(self, points: NDArray[np.float64], normals: NDArray[np.float64]) -> NDArray[np.int64]:
        """The face whose outward normal is nearest each point's normal."""
        return np.argmax(normals @ np.asarray(self.face_normals).T, axis=1).astype(np.int64)  # type: ignore[no-any-return]

    def hull_points(self) -> NDArray[np.float64]:
        """Its hull vertices."""
        return np.asarray(self.hull_vertices, dtype=np.float64)

    @property
    def area(self) -> float:
        """Exact surface area: the sum of its faces' areas."""
        v = self.hull_vertices[self.triangles]
        return float(0.5 * np.linalg.norm(np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0]), axis=1).sum())

    def exact_form(self) -> PointHull:
        """A :class:`~isocsg.kinds.forms.PointHull`: its hull vertices and its faces' edges."""
        pairs = {tuple(sorted((int(f[i]), int(f[(i + 1) % len(f)])))) for f in self.faces for i in range(len(f))}
        return PointHull(np.asarray(self.hull_vertices, dtype=np.float64),
                         np.array(sorted(pairs), dtype=np.int64).reshape(-1, 2))

    def is_prism_along(self, direction: NDArray[np.float64], tol: float = 1e-12) -> bool:
        """Every face along ``direction`` or across it."""
        nz = np.abs(np.asarray(self.face_normals, dtype=np.float64) @ np.asarray(direction, dtype=np.float64))
        return bool(np.all((nz <= tol) | (nz >= 1.0 - tol)))

    def flat_faces(self) -> list[tuple[NDArray[np.float64], NDArray[np.float64]]]:
        """Its face polygons with their outward normals."""
        polys = [np.asarray(V, dtype=np.float64) for V in self.face_polygons()]
        return list(zip(polys, face_normals(polys, self.planar_faces()[0])))

    def surface_patches(self, leaf: int) -> list[Patch]:
        """Its faces (:func:`~isocsg.kinds.patches.polytope_patches`)."""
        return polytope_patches(leaf, self.face_polygons(), self.planar_faces()[0])

    def simplest(self) -> Primitive:
        """An axis-aligned box held as eight corners becomes the :class:`~isocsg.kinds.Box` it is."""
        v = self.hull_vertices
        if len(v) != 8:
            return self
        lo, hi = v.min(axis=0), v.max(axis=0)
        if not np.all((v == lo) | (v == hi)) or len({tuple(p) for p in v.tolist()}) != 8:
            return self
        box: Primitive = kind_class("box")(tuple(((lo + hi) / 2).tolist()), tuple((hi - lo).tolist()))
        return box

    def leaf_row(self) -> LeafRow:
        """A :attr:`LeafForm.HULL` row: its hull vertices."""
        return LeafRow(LeafForm.HULL, vertices=self.hull_vertices)

    def manifold(self, resolution: int, shapes: dict[tuple[Any, ...], Any] | None = None) -> Any:
        """The hull of its vertices."""
        return manifold3d_module().Manifold.hull_points(np.asarray(self.hull_vertices, dtype=np.float64).tolist())

    def band_surface(
        self, lights: list[Any], contours: int, eye: NDArray[np.float64] | None, shininess: float,
        weights: tuple[float, float] = (1.0, 1.0), segments: int | None = None, *,
        hidden: tuple[Any, Any] | None = None,
    ) -> Surface:
        """Its faces (flat: ``segments`` does not apply), subdivided where a point light or a
        highlight varies across them (:func:`isocsg.kinds.polyhedron_bands.polyhedron_surface`)."""
        from .polyhedron_bands import polyhedron_surface

        return polyhedron_surface(self, lights, contours, eye=eye, shininess=shininess, weights=weights)

    def contour_laminae(
        self, light: Any, contours: int,
    ) -> list[tuple[NDArray[np.float64], NDArray[np.float64], float, str]]:
        """One lamina per face."""
        from .polyhedron_bands import face_laminae

        return [(v, nrm, c, "face") for v, nrm, c in face_laminae(self, light)]

    def to_openscad(self, digits: int | None = None, *, exact: bool = True) -> str:
        """See :func:`polyhedron_scad`."""
        return polyhedron_scad(self, digits, exact=exact)

    def to_dict(self) -> dict[str, Any]:
        """``{"polyhedron": {"vertices": [...]}}``."""
        return {"polyhedron": {"vertices": [list(v) for v in self.vertices]}}



# ----------------------------------------------------------------------------- OpenSCAD form


def polyhedron_scad(solid: ConvexPolyhedron, digits: int | None = None, *, exact: bool = True) -> str:
    """``polyhedron(points, faces)`` of the hull; with ``digits``, the hull of exactly placed corners.

    With ``digits`` and ``exact`` (the default): ``hull()`` of one spike per vertex, a small
    tetrahedron whose tip is the vertex and whose base lies deep inside the solid. Only the tip
    must be exact, and it is the origin of the spike's frame, moved to the vertex by nested
    translations whose short terms sum to its coordinates (see :func:`_corner_spikes`); the
    base points may keep ``digits`` digits, as they stay well inside (a thin solid's in its
    principal frame). The hull of the spikes is the hull of the vertices: the same solid, every
    vertex to about one unit in the last place. A sliver whose vertices' mean lies within 1e-10
    of its size from a face (thinner than about 1e-9 of its size) is written in the rounded
    form instead.

    With ``digits`` and ``exact=False``: a plain ``polyhedron`` of the points in the frame of the
    principal axes scaled to the extents (the frame written exactly, as any map), each coordinate
    rounded to ``digits``, and the faces of the hull of the rounded points: readable, but the
    volume keeps only about ``digits`` digits (no map of few digits places every vertex of a
    general polyhedron).
    """
    if digits is not None and exact:
        spikes = _corner_spikes(solid, digits)
        if spikes is not None:
            return spikes
    if digits is not None:
        # in the frame of its principal axes, scaled to its extents: every coordinate is O(1), so
        # that rounding it moves the vertex by the same small fraction of the size in every direction
        v = np.asarray(solid.hull_vertices, dtype=np.float64)
        lo, hi = solid.bounds
        c = np.array([round_sig(x, digits) for x in 0.5 * (lo + hi)])
        _, _, axes = np.linalg.svd(v - v.mean(axis=0))
        half = np.ptp((v - c) @ axes.T, axis=0) / 2
        L = axes.T * half
        local = np.vectorize(lambda x: round_sig(x, digits))(np.linalg.solve(L, (v - c).T).T)
        try:
            rounded = ConvexPolyhedron(local)
        except InvalidGeometryError:  # pragma: no cover - rounding flattened a sliver
            rounded = ConvexPolyhedron(np.linalg.solve(L, (v - c).T).T)
        return encoded(polyhedron_scad(rounded), L, c, digits)
    pts = ", ".join(vec(p) for p in solid.hull_vertices)
    # OpenSCAD wants each face clockwise seen from outside; isocsg's are counter-clockwise.
    faces = ", ".join("[" + ", ".join(str(int(i)) for i in reversed(f)) + "]" for f in solid.faces)
    return f"polyhedron(points = [{pts}], faces = [{faces}]);"


#: How deep inside the solid the base of a corner spike must stay (a fraction of the depth of
#: the base's centre): the margin covers the rounding of the base points to ``digits``.
_SPIKE_MARGIN = 0.25


def _exact_translations(x: NDArray[np.float64], d: int) -> list[NDArray[np.float64]]:
    """Vectors of ``d``-digit entries whose sum, added smallest first, is ``x`` to its last bit
    (each the rounding of what is left; every subtraction is exact)."""
    parts: list[NDArray[np.float64]] = []
    rest = np.asarray(x, dtype=np.float64).copy()
    size = float(np.abs(rest).max())
    while np.any(rest) and float(np.abs(rest).max()) > 2.0**-60 * size and len(parts) < 8:
        part = np.array([round_sig(v, d) for v in rest])
        parts.append(part)
        rest = rest - part
    return parts


def _corner_spikes(solid: ConvexPolyhedron, d: int) -> str | None:
    """``hull()`` of one tetrahedron per vertex: the tip exactly at the vertex (nested
    translations), the base three points halfway between the vertices' mean and three extreme
    vertices (those of the principal axes that make the fattest spike).

    A base point halfway to the mean c is inside every face plane by at least half c's depth
    (convexity); rounded to ``d`` digits, every one is checked to stay inside by
    :data:`_SPIKE_MARGIN` of that depth, so that the hull's vertices are the tips alone (in
    OpenSCAD's exact hull and in the loader's). None when a base cannot stay inside.
    """
    v = np.asarray(solid.hull_vertices, dtype=np.float64)
    normals = np.asarray(solid.face_normals, dtype=np.float64)
    offsets = np.asarray(solid.face_offsets, dtype=np.float64)
    size = float(np.max(np.ptp(v, axis=0)))
    c = v.mean(axis=0)
    depth = float(np.min(offsets - normals @ c))  # the radius of the largest ball about c inside
    if not depth > 1e-10 * size:  # the margin below must stay far above the hulls' round-off
        return None
    _, _, axes = np.linalg.svd(v - c)
    along = (v - c) @ axes.T
    extreme = np.unique(np.concatenate([along.argmin(axis=0), along.argmax(axis=0)]))
    if len(extreme) < 4:
        extreme = np.arange(len(v))
    bases = c + 0.5 * (v[extreme] - c)
    triples = np.array([t for t in itertools.combinations(range(len(bases)), 3)])
    # A thin solid's bases are written in its principal frame scaled to its extents (a short
    # matrix that keeps the tip at the origin), so that rounding them moves them across the thin
    # side by a small fraction of its thickness; a plain solid needs no frame.
    frame = np.vectorize(lambda x: round_sig(x, d))(axes.T * (np.ptp(along, axis=0) / 2))
    for framed in (False, True):
        lines = _spikes(v, bases, triples, frame if framed else None, normals, offsets, _SPIKE_MARGIN * depth, d)
        if lines is not None:
            return "\n".join(["hull() {", *lines, "}"])
    return None


def _spikes(
    v: NDArray[np.float64],
    bases: NDArray[np.float64],
    triples: NDArray[np.int64],
    frame: NDArray[np.float64] | None,
    normals: NDArray[np.float64],
    offsets: NDArray[np.float64],
    margin: float,
    d: int,
) -> list[str] | None:
    """One line per vertex of :func:`_corner_spikes`; None when a rounded base point leaves the
    solid's faces by less than ``margin`` or a spike is flat."""
    lines = []
    for p in v:
        spans = bases[triples] - p  # (triples, 3 points, 3)
        best = triples[int(np.argmax(np.abs(np.linalg.det(spans))))]
        if frame is None:
            local = np.vectorize(lambda x: round_sig(x, d))(bases[best] - p)
            rel = local
        else:
            local = np.vectorize(lambda x: round_sig(x, d))(np.linalg.solve(frame, (bases[best] - p).T).T)
            rel = local @ frame.T  # as a reader maps them
        if np.min(offsets[None, :] - (p + rel) @ normals.T) < margin:
            return None
        if abs(float(np.linalg.det(rel))) <= 1e-9 * float(np.ptp(np.vstack([np.zeros(3), rel]), axis=0).max()) ** 3:
            return None  # a flat spike, which a reader drops
        pts = np.vstack([np.zeros(3), local])
        faces = []
        for tri, other in (((0, 1, 2), 3), ((0, 1, 3), 2), ((0, 2, 3), 1), ((1, 2, 3), 0)):
            i, j, k = tri
            inward = float(np.dot(np.cross(pts[j] - pts[i], pts[k] - pts[i]), pts[other] - pts[i])) > 0
            faces.append((i, j, k) if inward else (i, k, j))  # clockwise seen from outside
        body = (
            "polyhedron(points = [" + ", ".join("[" + ", ".join(num_sig(x, d) for x in q) + "]" for q in pts) + "], "
            "faces = [" + ", ".join("[" + ", ".join(map(str, f)) + "]" for f in faces) + "]);"
        )
        if frame is not None:
            m = np.eye(4)
            m[:3, :3] = frame
            body = f"multmatrix({short_mat(m, d)}) {{ {body} }}"
        for part in reversed(_exact_translations(p, d)):  # the smallest term innermost: added first
            m = np.eye(4)
            m[:3, 3] = part
            body = f"multmatrix({short_mat(m, d)}) {{ {body} }}"
        lines.append("  " + body)
    return lines


def _mapped(
    p: ConvexPolyhedron, pts: NDArray[np.float64], A: NDArray[np.float64], t: NDArray[np.float64]
) -> ConvexPolyhedron:
    """The image of ``p`` under a well-conditioned affine map without a new hull: its vertices
    mapped, the same faces (reversed by a reflection), planes through the mapped normals
    ``A^-T n`` (a map of thousands of prisms under nested transforms rebuilt every hull)."""
    out = object.__new__(ConvexPolyhedron)
    object.__setattr__(out, "vertices", tuple(tuple(map(float, q)) for q in pts))
    hv = p.hull_vertices @ A.T + t
    flip = np.linalg.det(A) < 0
    faces = tuple((f[::-1] if flip else f).copy() for f in p.faces)
    n = p.face_normals @ np.linalg.inv(A)  # rows: (A^-T n)^T
    n /= np.linalg.norm(n, axis=1)[:, None]
    offsets = np.array([float(n[k] @ hv[f].mean(axis=0)) for k, f in enumerate(faces)])
    scale = float(np.max(np.ptp(hv, axis=0)))
    flat = 1e-12 * max(scale, float(np.abs(hv).max()))
    if scale < length_floor(hv.min(axis=0), hv.max(axis=0)) or any(
        len(f) > 3 and float(np.ptp(hv[f] @ n[k])) > flat for k, f in enumerate(faces)
    ):  # too small here, or a face merged from nearly coplanar facets: the full build decides
        return ConvexPolyhedron(pts)  # type: ignore[arg-type]
    tris = np.array([(f[0], f[i], f[i + 1]) for f in faces for i in range(1, len(f) - 1)], dtype=np.int64)
    for arr in (hv, n, offsets, tris):
        arr.setflags(write=False)
    for name, value in (("hull_vertices", hv), ("faces", faces), ("face_normals", n), ("face_offsets", offsets),
                        ("triangles", tris)):
        object.__setattr__(out, name, value)
    return out
