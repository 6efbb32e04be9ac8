"""The ellipsoid: the image of a ball under any affine map.

An :class:`Ellipsoid` has a ``center``, three ``radii`` (semi-axes, > 0) and an
``orientation`` (a rotation whose columns are its own axes in world
coordinates). Writing ``R`` for the orientation and ``S = diag(radii)``, its
points are ``center + R S u`` for ``|u| <= 1``: every computation maps to that
unit ball ("the primitive's own frame") and back. Ray parameters are unchanged
by the map, and the outward normal at ``center + R S u`` is ``R S^-1 u``
normalised.

A :class:`~isocsg.kinds.sphere.Sphere` under a map that is not a
similarity becomes an ellipsoid (:meth:`Ellipsoid.from_affine`), and an
ellipsoid under any affine map stays one.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import MAX_ABS_COORD, MIN_ASPECT, Vec3, length_floor, vector3
from ..errors import InvalidGeometryError
from .base import (
    DEFAULT_RESOLUTION,
    IDENTITY3,
    LeafForm,
    LeafRow,
    Primitive,
    RayHits,
    _as_rays,
    rotation3,
)
from .forms import AffineBall
from .meshing import manifold3d_module
from .patches import Patch, affine_ball_patches, ellipsoid_area
from .polyhedron import ConvexPolyhedron
from .registry import register_kind
from .scad import encoded, mat
from .sphere import Sphere

if TYPE_CHECKING:  # pragma: no cover
    from shapely.geometry import Polygon

    from ..bands.surface import Surface

__all__ = ["Ellipsoid"]


@register_kind("ellipsoid", required=("center", "radii"), optional=("orientation",))
@dataclass(frozen=True, slots=True)
class Ellipsoid(Primitive):
    """A solid ellipsoid.

    Parameters
    ----------
    center : array_like, shape (3,)
    radii : array_like, shape (3,)
        Semi-axes along the ellipsoid's own x, y and z axes, each > 0.
    orientation : array_like, shape (3, 3), optional
        A rotation whose columns are the ellipsoid's own axes in world
        coordinates (default the identity).

    Raises
    ------
    InvalidGeometryError
        On non-finite values, radii that are not > 0 (or whose smallest is
        below ``MIN_ASPECT`` times the largest), or an orientation that is
        not a rotation.

    Examples
    --------
    >>> e = Ellipsoid((0, 0, 0), (2, 1, 0.5))
    >>> round(e.volume, 6), e.contains([[1.9, 0, 0], [0, 1.1, 0]]).tolist()
    (4.18879, [True, False])
    """

    center: Vec3
    radii: Vec3
    orientation: tuple[Vec3, Vec3, Vec3] = IDENTITY3
    kind: ClassVar[str] = "ellipsoid"

    if TYPE_CHECKING:  # the constructor as callers call it: array-likes, checked in __post_init__
        def __init__(self, center: ArrayLike, radii: ArrayLike, orientation: ArrayLike = IDENTITY3) -> None: ...

    def __post_init__(self) -> None:
        center = vector3("Ellipsoid.center", self.center)
        radii = vector3("Ellipsoid.radii", self.radii)
        if min(radii) <= 0:
            raise InvalidGeometryError(f"Ellipsoid.radii must be > 0 in every axis, got {radii}")
        if max(radii) > MAX_ABS_COORD:
            raise InvalidGeometryError(f"Ellipsoid.radii must be <= {MAX_ABS_COORD:g}, got {radii}")
        floor = length_floor(center)
        if min(radii) < floor:
            raise InvalidGeometryError(
                f"Ellipsoid.radii must be >= {floor:g} in every axis "
                f"(the smallest length at this position), got {radii}"
            )
        if min(radii) < MIN_ASPECT * max(radii):
            raise InvalidGeometryError(
                f"Ellipsoid.radii must have its smallest at least {MIN_ASPECT:g} x its largest, got {radii}"
            )
        object.__setattr__(self, "center", center)
        object.__setattr__(self, "radii", radii)
        object.__setattr__(self, "orientation", rotation3("Ellipsoid.orientation", self.orientation))

    def __repr__(self) -> str:
        extra = "" if self.orientation == IDENTITY3 else f", orientation={self.orientation}"
        return f"Ellipsoid(center={self.center}, radii={self.radii}{extra})"

    # ------------------------------------------------------------ construction
    @staticmethod
    def from_affine(A: ArrayLike, center: ArrayLike) -> Ellipsoid:
        """The image ``{center + A u : |u| <= 1}`` of the unit ball under an invertible ``A``.

        Examples
        --------
        >>> Ellipsoid.from_affine([[0, 2, 0], [1, 0, 0], [0, 0, 3]], (0, 0, 0)).radii
        (2.0, 1.0, 3.0)
        """
        a = np.asarray(A, dtype=np.float64)
        c = tuple(np.asarray(center, dtype=np.float64))
        u, s, _ = np.linalg.svd(a)  # A A^T = U S^2 U^T: the image depends on U and S only
        u[np.abs(u) <= 1e-15] = 0.0
        one = np.abs(np.abs(u) - 1.0) <= 1e-15
        u[one] = np.sign(u[one])
        perm = np.abs(u)
        if np.all((perm == 0.0) | (perm == 1.0)):  # axes along the world's: axis-aligned, radii permuted
            return Ellipsoid(c, tuple(perm @ s))
        # an ellipsoid is symmetric in its own planes: each axis points where its largest entry is
        # positive, the last one flipped if needed to make a rotation
        big = np.argmax(np.abs(u), axis=0)
        u = u * np.sign(u[big, np.arange(3)])
        if np.linalg.det(u) < 0:
            u[:, 2] = -u[:, 2]
        return Ellipsoid(c, tuple(s), u)

    # ------------------------------------------------------------ frame
    @property
    def center_array(self) -> NDArray[np.float64]:
        """The centre as a float64 array."""
        return np.asarray(self.center, dtype=np.float64)

    @property
    def rotation(self) -> NDArray[np.float64]:
        """The orientation as a (3, 3) array (columns: the ellipsoid's own axes)."""
        return np.asarray(self.orientation, dtype=np.float64)

    @property
    def radii_array(self) -> NDArray[np.float64]:
        """The semi-axes as a float64 array."""
        return np.asarray(self.radii, dtype=np.float64)

    @property
    def matrix(self) -> NDArray[np.float64]:
        """The linear map ``R S`` from the unit ball (own frame) to the ellipsoid (about its centre)."""
        return self.rotation * self.radii_array

    def to_unit(self, points: ArrayLike) -> NDArray[np.float64]:
        """Points in the unit-ball frame: ``S^-1 R^T (p - center)``."""
        p = np.asarray(points, dtype=np.float64).reshape(-1, 3) - self.center_array
        return (p @ self.rotation) / self.radii_array

    def normals_at(self, points: ArrayLike) -> NDArray[np.float64]:
        """Outward unit normals at surface points (the gradient of the implicit form)."""
        u = self.to_unit(self._points(points))
        n = (u / self.radii_array) @ self.rotation.T
        return n / np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)

    def signed_distance(self, points: ArrayLike) -> NDArray[np.float64]:
        """Signed distance to the surface, exact on it to first order.

        ``k0 (k0 - 1) / k1`` with ``k0 = |S^-1 q|`` and ``k1 = |S^-2 q|`` for
        ``q`` the point in the ellipsoid's own frame: the implicit function
        over its gradient's length, exact for a sphere and within a relative
        ``O(d / r)`` of the true distance ``d`` near the surface, which is what
        the boundary tolerance of :meth:`contains` needs.
        """
        q = np.asarray(points, dtype=np.float64).reshape(-1, 3) - self.center_array
        q = q @ self.rotation
        r = self.radii_array
        k0 = np.linalg.norm(q / r, axis=1)
        k1 = np.linalg.norm(q / (r * r), axis=1)
        with np.errstate(divide="ignore", invalid="ignore"):
            d = np.where(k1 > 0, k0 * (k0 - 1.0) / k1, -float(r.min()))
        return d

    # ------------------------------------------------------------ the primitive interface
    @property
    def bounds(self) -> NDArray[np.float64]:
        """Axis-aligned bounds, shape (2, 3) (exact: ``|R S|`` row norms)."""
        ext = np.linalg.norm(self.matrix, axis=1)
        return np.stack([self.center_array - ext, self.center_array + ext])

    def extent(self, n: ArrayLike) -> tuple[float, float]:
        """Exact extent ``(lo, hi)`` of the solid along the unit vector ``n`` (its support)."""
        v = np.asarray(n, dtype=np.float64)
        c = float(self.center_array @ v)
        h = float(np.linalg.norm(self.matrix.T @ v))
        return c - h, c + h

    @property
    def volume(self) -> float:
        """Exact volume, 4/3 pi a b c."""
        a, b, c = self.radii
        return 4.0 / 3.0 * math.pi * a * b * c

    def intersect_rays(self, origins: ArrayLike, directions: ArrayLike) -> RayHits:
        """Analytic ray-ellipsoid intersection in the unit-ball frame; see :class:`RayHits`."""
        o, d = _as_rays(origins, directions)
        R, r = self.rotation, self.radii_array
        oc = ((o - self.center_array) @ R) / r
        dl = (d @ R) / r
        a = np.einsum("ij,ij->i", dl, dl)
        b = np.einsum("ij,ij->i", oc, dl)
        c = np.einsum("ij,ij->i", oc, oc) - 1.0
        disc = b * b - a * c
        ok = (disc >= 0) & (a > 0)
        sq = np.sqrt(np.where(ok, disc, 0.0))
        with np.errstate(divide="ignore", invalid="ignore"):
            t0 = np.where(ok, (-b - sq) / a, np.inf)
            t1 = np.where(ok, (-b + sq) / a, -np.inf)

        def normal(t: NDArray[np.float64]) -> NDArray[np.float64]:
            u = oc + np.where(ok, t, 0.0)[:, None] * dl
            n = (u / r) @ R.T
            n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)
            return np.where(ok[:, None], n, 0.0)

        return RayHits(t0, t1, normal(t0), normal(t1))

    def to_polyhedron(self, resolution: int = DEFAULT_RESOLUTION) -> ConvexPolyhedron:
        """Inscribed polyhedron: the image of the sphere's UV polyhedron (vertices on the surface)."""
        unit = Sphere((0.0, 0.0, 0.0), 1.0).to_polyhedron(resolution).vertices
        return ConvexPolyhedron(np.asarray(unit) @ self.matrix.T + self.center_array)

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> Primitive:
        out = Ellipsoid.from_affine(A @ self.matrix, A @ self.center_array + t)
        r = np.asarray(out.radii)
        if float(r.max() - r.min()) <= 1e-12 * float(r.max()):  # a ball again
            return Sphere(out.center, float(r.mean()))
        return out

    # ------------------------------------------------------------ the kind interface
    @property
    def area(self) -> float:
        """Exact surface area (Carlson's symmetric form: :func:`~isocsg.kinds.patches.ellipsoid_area`)."""
        return ellipsoid_area(*(float(x) for x in self.radii))

    def exact_form(self) -> AffineBall:
        """An :class:`~isocsg.kinds.forms.AffineBall` of linear map ``R S``."""
        return AffineBall(self.center_array, self.matrix)

    def surface_patches(self, leaf: int) -> list[Patch]:
        """The unit sphere's rings, mapped (:func:`~isocsg.kinds.patches.affine_ball_patches`)."""
        return affine_ball_patches(leaf, self.center_array, np.asarray(self.matrix, dtype=np.float64), self.radii_array)

    def leaf_row(self) -> LeafRow:
        """A :attr:`LeafForm.GENERIC` row about its centre."""
        return LeafRow(LeafForm.GENERIC, center=self.center_array)

    def section(self, frame: NDArray[np.float64], resolution: int, area_exact: bool = False) -> Polygon:
        """The exact section of an ellipsoid by the plane of the frame ``F`` (an ellipse) as a polygon.

        In the unit-ball frame the plane is ``q0 + a U + b V``; ``|q|^2 <= 1`` is a
        quadratic in the plane coordinates ``(a, b)`` whose minimum sits at
        ``-G^-1 h`` (``G`` the Gram matrix of ``U, V``, ``h = (q0.U, q0.V)``). The
        ellipse is the image of a circle's ring (inscribed, or of the exact area
        with ``area_exact``: an affine map keeps area ratios).
        """
        import shapely

        from .planar import EMPTY, circle_ring

        e, F = self, frame
        R, r = e.rotation, e.radii_array
        o, u, v = F[:3, 3], F[:3, 0], F[:3, 1]
        q0 = ((o - e.center_array) @ R) / r
        U, V = (u @ R) / r, (v @ R) / r
        G = np.array([[U @ U, U @ V], [U @ V, V @ V]])
        h = np.array([q0 @ U, q0 @ V])
        ab = -np.linalg.solve(G, h)
        m = float(q0 @ q0 + h @ ab)
        if m >= 1.0:
            return EMPTY
        lam, W = np.linalg.eigh(G)
        axes = W * np.sqrt((1.0 - m) / lam)  # columns: the ellipse's semi-axes in (a, b)
        ring = circle_ring(np.zeros((1, 2)), np.ones(1), resolution, area_exact)[0]
        return shapely.Polygon(ring @ axes.T + ab)

    def manifold(self, resolution: int, shapes: dict[tuple[Any, ...], Any] | None = None) -> Any:
        """manifold3d's sphere mapped by ``R S`` (vertices on the surface)."""
        ball = manifold3d_module().Manifold.sphere(1.0, max(int(resolution), 4))
        return ball.transform(np.column_stack([self.matrix, self.center_array]).tolist())

    def band_surface(
        self, lights: list[Any], contours: int, eye: NDArray[np.float64] | None, shininess: float,
        weights: tuple[float, float] = (1.0, 1.0), segments: int | None = None, *,
        hidden: tuple[Any, Any] | None = None,
    ) -> Surface:
        """Latitude-longitude mesh fine enough for every field (:mod:`isocsg.kinds.ellipsoid_bands`)."""
        from .ellipsoid_bands import ellipsoid_surface

        return ellipsoid_surface(self, lights, contours, eye, shininess, weights, segments)

    def to_openscad(self, digits: int | None = None, *, exact: bool = True) -> str:
        """The unit sphere mapped by orientation x diag(radii), then moved to the centre."""
        L = np.asarray(self.orientation, dtype=np.float64) * np.asarray(self.radii, dtype=np.float64)
        if digits is not None:
            return encoded("sphere(r = 1);", L, self.center_array, digits)
        m = np.eye(4)
        m[:3, :3] = L
        m[:3, 3] = self.center
        return f"multmatrix({mat(m)}) {{ sphere(r = 1); }}"

    def to_dict(self) -> dict[str, Any]:
        """``{"ellipsoid": {"center", "radii"}}``, plus ``"orientation"`` (3 rows) when not the identity."""
        out: dict[str, Any] = {"center": list(self.center), "radii": list(self.radii)}
        if self.orientation != IDENTITY3:
            out["orientation"] = [list(r) for r in self.orientation]
        return {"ellipsoid": out}
