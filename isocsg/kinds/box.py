"""The box kind: a rectangular cuboid, axis-aligned or turned by an ``orientation``; exact throughout."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import Vec3, length_floor, vector3
from ..errors import InvalidGeometryError
from .base import (
    DEFAULT_RESOLUTION,
    IDENTITY3,
    LeafBoxes,
    LeafForm,
    LeafRow,
    Primitive,
    RayHits,
    TangentCone,
    _as_rays,
    _orthogonal_columns,
    _perpendicular_frame,
    _snap_rotation,
    rotation3,
)
from .forms import PointHull
from .halfspaces import polyhedral_tangent, ray_halfspaces
from .meshing import manifold3d_module
from .patches import Patch, polytope_patches
from .registry import register_kind
from .scad import encoded, mat, translated, vec

if TYPE_CHECKING:  # pragma: no cover
    from shapely.geometry import Polygon

    from ..bands.surface import Surface
    from .polyhedron import ConvexPolyhedron

__all__ = ["Box"]

#: The 12 edges of the corners' order (x slowest, z fastest): corner pairs one bit apart.
_EDGES = np.array([(a, b) for a in range(8) for b in range(a + 1, 8) if bin(a ^ b).count("1") == 1], dtype=np.int64)


@register_kind("box", required=("center", "size"), optional=("orientation",))
@dataclass(frozen=True, slots=True)
class Box(Primitive):
    """A box (rectangular cuboid), axis-aligned unless given an ``orientation``.

    Parameters
    ----------
    center : array_like, shape (3,)
    size : array_like, shape (3,)
        Edge lengths ``[sx, sy, sz]`` along the box's own axes, each > 0.
    orientation : array_like, shape (3, 3), optional
        A rotation matrix whose columns are the box's own x, y and z axes in
        world coordinates (default the identity: an axis-aligned box). A point
        ``p`` of the box's own frame lies at ``center + orientation @ p``.

    Raises
    ------
    InvalidGeometryError
        On non-finite values, a size that is not > 0 in every axis, or an
        orientation that is not a rotation (orthonormal within
        :data:`ROTATION_TOL`, determinant +1).

    Examples
    --------
    >>> b = Box((0, 0, 0), (2, 2, 2))
    >>> b.volume, b.contains([[0.9, 0.9, 0.9], [1.1, 0, 0]]).tolist()
    (8.0, [True, False])
    """

    center: Vec3
    size: Vec3
    orientation: tuple[Vec3, Vec3, Vec3] = IDENTITY3
    kind: ClassVar[str] = "box"
    polyhedral: ClassVar[bool] = True

    if TYPE_CHECKING:  # the constructor as callers call it: array-likes, checked in __post_init__
        def __init__(self, center: ArrayLike, size: ArrayLike, orientation: ArrayLike = IDENTITY3) -> None: ...

    def __post_init__(self) -> None:
        center = vector3("Box.center", self.center)
        object.__setattr__(self, "center", center)
        size = vector3("Box.size", self.size)
        if min(size) <= 0:
            raise InvalidGeometryError(f"Box.size must be > 0 in every axis, got {size}")
        floor = length_floor(center)
        if min(size) < floor:
            raise InvalidGeometryError(
                f"Box.size must be >= {floor:g} in every axis (the smallest length at this position), got {size}"
            )
        # No aspect limit: a box's rays, sections and mesh are its slabs, exact at any aspect
        # (a 0.001 x 5 x 128.4 plate is a real part); only the length floor above applies.
        object.__setattr__(self, "size", size)
        object.__setattr__(self, "orientation", rotation3("Box.orientation", self.orientation))

    def __repr__(self) -> str:
        extra = "" if self.axis_aligned else f", orientation={self.orientation}"
        return f"Box(center={self.center}, size={self.size}{extra})"

    @property
    def axis_aligned(self) -> bool:
        """True when the orientation is the identity."""
        return self.orientation == IDENTITY3

    @property
    def rotation(self) -> NDArray[np.float64]:
        """The orientation as a (3, 3) array (columns: the box's own axes)."""
        return np.asarray(self.orientation, dtype=np.float64)

    @property
    def center_array(self) -> NDArray[np.float64]:
        """The centre as a float64 array."""
        return np.asarray(self.center, dtype=np.float64)

    @property
    def half_size(self) -> NDArray[np.float64]:
        """Half edge lengths (along the box's own axes)."""
        return np.asarray(self.size, dtype=np.float64) / 2

    def to_local(self, points: ArrayLike) -> NDArray[np.float64]:
        """Points in the box's own frame (centre at the origin, edges along the axes)."""
        p = np.asarray(points, dtype=np.float64).reshape(-1, 3) - self.center_array
        return p if self.axis_aligned else p @ self.rotation

    @property
    def corners(self) -> NDArray[np.float64]:
        """The 8 corners, shape (8, 3)."""
        signs = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=np.float64)
        local = signs * self.half_size
        return self.center_array + (local if self.axis_aligned else local @ self.rotation.T)

    @property
    def face_normals(self) -> NDArray[np.float64]:
        """Outward normals of the 6 faces (+x, -x, +y, -y, +z, -z of the box's own axes)."""
        local = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=np.float64)
        return local if self.axis_aligned else local @ self.rotation.T

    @property
    def face_offsets(self) -> NDArray[np.float64]:
        """Plane offsets ``n . x = d`` of the 6 faces."""
        return self.face_normals @ self.center_array + np.repeat(self.half_size, 2)

    def face_polygons(self) -> list[NDArray[np.float64]]:
        """Each face as a (4, 3) array, counter-clockwise seen from outside."""
        return self.to_polyhedron().face_polygons()


    @property
    def bounds(self) -> NDArray[np.float64]:
        """Axis-aligned bounds, shape (2, 3) (exact)."""
        ext = self.half_size if self.axis_aligned else np.abs(self.rotation) @ self.half_size
        return np.stack([self.center_array - ext, self.center_array + ext])

    @property
    def volume(self) -> float:
        """Exact volume."""
        return float(np.prod(self.size))

    def intersect_rays(self, origins: ArrayLike, directions: ArrayLike) -> RayHits:
        """Exact ray-box intersection (slab method)."""
        o, d = _as_rays(origins, directions)
        return ray_halfspaces(o, d, self.face_normals, self.face_offsets)

    def to_polyhedron(self, resolution: int = DEFAULT_RESOLUTION) -> ConvexPolyhedron:
        """The box as a :class:`ConvexPolyhedron` (exact)."""
        # imported here: polyhedra register after this kind (the scene-file order)
        from .polyhedron import ConvexPolyhedron

        return ConvexPolyhedron(self.corners)

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> Primitive:
        # imported here: polyhedra register after this kind (the scene-file order)
        from .polyhedron import ConvexPolyhedron

        c = A @ self.center_array + t
        B = A if self.axis_aligned else A @ self.rotation
        norms = _orthogonal_columns(B)
        if norms is None:  # a shear of the box: a parallelepiped
            return ConvexPolyhedron(self.corners @ A.T + t)
        Q = B / norms
        if np.linalg.det(Q) < 0:  # a reflection: the box is symmetric in its own planes
            Q[:, 0] = -Q[:, 0]
        Q = _snap_rotation(Q)
        size = np.asarray(self.size) * norms
        perm = np.abs(Q)
        if np.all((perm == 0.0) | (perm == 1.0)):  # turned by right angles: axis-aligned again
            return Box(c, perm @ size)
        return Box(c, size, Q)

    # ------------------------------------------------------------ the kind interface
    def extent(self, n: ArrayLike) -> tuple[float, float]:
        """Exact extent along the unit vector ``n``."""
        w = np.asarray(n, dtype=np.float64)
        c = float(self.center_array @ w)
        h = float(self.half_size @ np.abs(w if self.axis_aligned else self.rotation.T @ w))
        return c - h, c + h

    def breakpoints(self, n: ArrayLike) -> NDArray[np.float64]:
        """The heights of its corners along ``n``."""
        return self.corners @ np.asarray(n, dtype=np.float64)  # type: ignore[no-any-return]

    def signed_distance(self, points: ArrayLike) -> NDArray[np.float64]:
        """Exact, in its own frame."""
        q = np.abs(self.to_local(points)) - self.half_size
        outside = np.sqrt(np.einsum("ij,ij->i", np.maximum(q, 0), np.maximum(q, 0)))
        return outside + np.minimum(q.max(axis=1), 0.0)  # type: ignore[no-any-return]

    def tangent_cone(self, points: NDArray[np.float64], tol: float) -> TangentCone:
        """The faces within ``tol`` of each point."""
        return polyhedral_tangent(self.face_normals, self.face_offsets, points, tol)

    def section(self, frame: NDArray[np.float64], resolution: int, area_exact: bool = False) -> Polygon:
        """Exact, from its faces and corners."""
        from .planar import halfspace_section

        return halfspace_section(self.face_normals, self.face_offsets, self.corners, frame)

    def local_faces(self) -> tuple[NDArray[np.float64], list[NDArray[np.float64]]]:
        """Its centre and its faces about it (the same box at the origin: no hull of far-off
        absolute coordinates), for :mod:`isocsg.kinds.polyhedron_bands`."""
        if self.axis_aligned:  # no convex hull (and no scipy.spatial) for the common box
            return self.center_array.copy(), _axis_aligned_faces(self.half_size)
        faces = Box((0.0, 0.0, 0.0), self.size, self.orientation).face_polygons()
        return self.center_array.copy(), [np.asarray(f, dtype=np.float64) for f in faces]

    def planar_faces(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Its six face planes."""
        return self.face_normals, self.face_offsets

    def part_index(self, points: NDArray[np.float64], normals: NDArray[np.float64]) -> NDArray[np.int64]:
        """The face whose outward normal is nearest each point's normal."""
        return np.argmax(normals @ np.asarray(self.face_normals).T, axis=1).astype(np.int64)  # type: ignore[no-any-return]

    def clipped_to_box(self, lo: NDArray[np.float64], hi: NDArray[np.float64]) -> Primitive:
        """An axis-aligned box cut to the box ``[lo, hi]`` (a turned box stays whole)."""
        if not self.axis_aligned:
            return self
        b = self.bounds
        blo, bhi = np.maximum(b[0], lo), np.minimum(b[1], hi)
        if np.all(blo < bhi):
            return Box(tuple((0.5 * (blo + bhi)).tolist()), tuple((bhi - blo).tolist()))
        return self

    def hull_points(self) -> NDArray[np.float64]:
        """Its 8 corners."""
        return np.asarray(self.corners, dtype=np.float64)

    @classmethod
    def leaf_boxes(cls, leaves: Sequence[Primitive]) -> LeafBoxes:
        """Axis-aligned boxes read from their parameters in one pass; turned boxes give ``bounds``."""
        n = len(leaves)
        lo, hi = np.empty((n, 3)), np.empty((n, 3))
        b_idx: list[int] = []
        b_par: list[tuple[float, ...]] = []
        for i, p in enumerate(leaves):
            if p.axis_aligned:  # type: ignore[attr-defined]
                b_idx.append(i)
                b_par.append((*p.center, *p.size))  # type: ignore[attr-defined]
            else:
                lo[i], hi[i] = np.asarray(p.bounds, dtype=np.float64)
        if b_idx:
            a = np.asarray(b_par, dtype=np.float64)
            lo[b_idx] = a[:, :3] - a[:, 3:] / 2
            hi[b_idx] = a[:, :3] + a[:, 3:] / 2
        return lo, hi, np.zeros(n, np.bool_), np.zeros((n, 3)), np.zeros(n)

    @property
    def area(self) -> float:
        """Exact surface area, 2 (ab + bc + ca)."""
        a, b, c = (float(x) for x in self.size)
        return 2.0 * (a * b + b * c + c * a)

    def exact_form(self) -> PointHull:
        """A :class:`~isocsg.kinds.forms.PointHull`: its corners and 12 edges."""
        return PointHull(self.hull_points(), _EDGES)

    def is_prism_along(self, direction: NDArray[np.float64], tol: float = 1e-12) -> bool:
        """One of its own axes along ``direction``."""
        along = np.asarray(direction, dtype=np.float64) @ self.rotation
        return bool(np.any(np.abs(np.abs(along) - 1.0) <= tol))

    def flat_faces(self) -> list[tuple[NDArray[np.float64], NDArray[np.float64]]]:
        """Its six faces (corners (4, 3), outward normal), built directly (a hull would be slow)."""
        R, c, h = self.rotation, self.center_array, self.half_size
        out = []
        for k in range(3):
            u, v = R[:, (k + 1) % 3] * h[(k + 1) % 3], R[:, (k + 2) % 3] * h[(k + 2) % 3]
            for s in (1.0, -1.0):
                fc = c + s * h[k] * R[:, k]
                out.append((np.stack([fc + u + v, fc - u + v, fc - u - v, fc + u - v]), s * R[:, k]))
        return out

    def surface_patches(self, leaf: int) -> list[Patch]:
        """Its six faces (:func:`~isocsg.kinds.patches.polytope_patches`)."""
        return polytope_patches(leaf, self.face_polygons(), self.planar_faces()[0])

    def axis_scaled(self, scale: NDArray[np.float64]) -> Box | None:
        """An axis-aligned box scaled per axis (any aspect); None for a turned one."""
        if not self.axis_aligned:
            return None
        return Box(tuple(np.asarray(self.center) * scale), tuple(np.asarray(self.size) * scale))

    def leaf_row(self) -> LeafRow:
        """An :attr:`LeafForm.AXIS_BOX` row, or a :attr:`LeafForm.HULL` row when turned."""
        if self.axis_aligned:
            return LeafRow(LeafForm.AXIS_BOX, center=self.center_array, half=self.half_size)
        return LeafRow(LeafForm.HULL, center=self.center_array, vertices=self.to_polyhedron().hull_vertices)

    def manifold(self, resolution: int, shapes: dict[tuple[Any, ...], Any] | None = None) -> Any:
        """manifold3d's cube, turned and moved."""
        cube = manifold3d_module().Manifold.cube(tuple(self.size), True)
        if self.axis_aligned:
            return cube.translate(tuple(self.center))
        return cube.transform(np.column_stack([self.rotation, self.center_array]).tolist())

    def band_surface(
        self, lights: list[Any], contours: int, eye: NDArray[np.float64] | None, shininess: float,
        weights: tuple[float, float] = (1.0, 1.0), segments: int | None = None, *,
        hidden: tuple[Any, Any] | None = None,
    ) -> Surface:
        """Its faces, subdivided where a point light or a highlight varies across them."""
        from .polyhedron_bands import polyhedron_surface

        return polyhedron_surface(self, lights, contours, eye=eye, shininess=shininess, weights=weights)

    def contour_laminae(
        self, light: Any, contours: int,
    ) -> list[tuple[NDArray[np.float64], NDArray[np.float64], float, str]]:
        """One lamina per face."""
        from .polyhedron_bands import face_laminae

        return [(v, nrm, c, "face") for v, nrm, c in face_laminae(self, light)]

    def to_openscad(self, digits: int | None = None, *, exact: bool = True) -> str:
        """A centred ``cube(size)``, turned by the orientation and moved."""
        if digits is not None:
            R = np.eye(3) if self.axis_aligned else np.asarray(self.orientation, dtype=np.float64)
            return encoded("cube(size = [1, 1, 1], center = true);", R * np.asarray(self.size), self.center_array,
                           digits)
        body = f"cube(size = {vec(self.size)}, center = true);"
        if self.axis_aligned:
            return translated(np.asarray(self.center), body)
        m = np.eye(4)
        m[:3, :3] = np.asarray(self.orientation, dtype=np.float64)  # columns: the box's own axes
        m[:3, 3] = self.center
        return f"multmatrix({mat(m)}) {{ {body} }}"

    def to_dict(self) -> dict[str, Any]:
        """``{"box": {"center", "size"}}``, plus ``"orientation"`` (3 rows) when not axis-aligned."""
        out: dict[str, Any] = {"center": list(self.center), "size": list(self.size)}
        if not self.axis_aligned:
            out["orientation"] = [list(r) for r in self.orientation]
        return {"box": out}


#: The corners' signs, in the order of :attr:`Box.corners`.
_SIGNS = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=np.float64)


def _axis_aligned_faces(half: NDArray[np.float64]) -> list[NDArray[np.float64]]:
    """The faces of the axis-aligned box ``[-half, half]`` as its convex hull gives them
    (:class:`ConvexPolyhedron`, the face polygons of :meth:`Box.local_faces` for a turned box):
    the hull's face order (its planes sorted: -x, -y, -z, +z, +y, +x) and each face's corners
    sorted by angle about its centre in the same frame, so the band meshes are the same bit
    for bit (tests/test_primitives.py checks it against the hull)."""
    corners = _SIGNS * half
    faces = []
    for k, s in ((0, -1.0), (1, -1.0), (2, -1.0), (2, 1.0), (1, 1.0), (0, 1.0)):
        n = np.zeros(3)
        n[k] = s
        pts = corners[_SIGNS[:, k] == s]
        c = pts.mean(axis=0)
        u, v = _perpendicular_frame(n)
        faces.append(pts[np.argsort(np.arctan2((pts - c) @ v, (pts - c) @ u))])
    return faces
