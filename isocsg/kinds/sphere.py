"""The sphere kind: a solid ball, exact in every operation but its meshes.

Rays, distances and sections are closed forms; its bands are latitude rings about
the light (the seed's construction, :mod:`isocsg.kinds.sphere_bands`); its meshes and
shadow pieces are inscribed UV spheres.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import MAX_ABS_COORD, Vec3, scalar, vector3
from .base import (
    DEFAULT_RESOLUTION,
    LeafBoxes,
    LeafForm,
    LeafRow,
    Primitive,
    RayHits,
    TangentCone,
    _as_rays,
    _check_length,
)
from .forms import AffineBall
from .meshing import manifold3d_module
from .patches import Patch, ball_patches
from .registry import kind_class, register_kind
from .scad import encoded, num, translated

if TYPE_CHECKING:  # pragma: no cover
    from shapely.geometry import Polygon

    from ..bands.surface import Surface
    from .polyhedron import ConvexPolyhedron

__all__ = ["Sphere"]



@register_kind("sphere", required=("center", "radius"))
@dataclass(frozen=True, slots=True)
class Sphere(Primitive):
    """A solid ball.

    Parameters
    ----------
    center : array_like, shape (3,)
        Centre in metres.
    radius : float
        Radius, > 0.

    Raises
    ------
    InvalidGeometryError
        If the centre is not 3 finite numbers or the radius is not > 0.

    Examples
    --------
    >>> s = Sphere((0, 0, 0), 1.0)
    >>> s.contains([[0, 0, 0.5], [0, 0, 2]]).tolist()
    [True, False]
    """

    center: Vec3
    radius: float
    kind: ClassVar[str] = "sphere"

    if TYPE_CHECKING:  # the constructor as callers call it: array-likes, checked in __post_init__
        def __init__(self, center: ArrayLike, radius: float) -> None: ...

    def __post_init__(self) -> None:
        center = vector3("Sphere.center", self.center)
        radius = scalar("Sphere.radius", self.radius, low=0.0, high=MAX_ABS_COORD)
        _check_length("Sphere.radius", radius, center)
        object.__setattr__(self, "center", center)
        object.__setattr__(self, "radius", radius)

    @property
    def center_array(self) -> NDArray[np.float64]:
        """The centre as a float64 array."""
        return np.asarray(self.center, dtype=np.float64)


    @property
    def bounds(self) -> NDArray[np.float64]:
        """Axis-aligned bounds, shape (2, 3)."""
        c = self.center_array
        return np.stack([c - self.radius, c + self.radius])

    @property
    def volume(self) -> float:
        """Exact volume, 4/3 pi r^3."""
        return 4.0 / 3.0 * math.pi * self.radius**3

    def normals_at(self, points: ArrayLike) -> NDArray[np.float64]:
        """Outward unit normals at surface points."""
        p = self._points(points) - self.center_array
        return p / np.linalg.norm(p, axis=1, keepdims=True)

    def intersect_rays(self, origins: ArrayLike, directions: ArrayLike) -> RayHits:
        """Analytic ray-sphere intersection; see :class:`RayHits`."""
        o, d = _as_rays(origins, directions)
        oc = o - self.center_array
        a = np.einsum("ij,ij->i", d, d)
        b = np.einsum("ij,ij->i", oc, d)
        c = np.einsum("ij,ij->i", oc, oc) - self.radius**2
        disc = b * b - a * c
        ok = (disc >= 0) & (a > 0)
        sq = np.sqrt(np.where(ok, disc, 0.0))
        with np.errstate(divide="ignore", invalid="ignore"):
            t0 = np.where(ok, (-b - sq) / a, np.inf)
            t1 = np.where(ok, (-b + sq) / a, -np.inf)
        n0 = np.where(ok[:, None], (oc + np.where(ok, t0, 0.0)[:, None] * d) / self.radius, 0.0)
        n1 = np.where(ok[:, None], (oc + np.where(ok, t1, 0.0)[:, None] * d) / self.radius, 0.0)
        return RayHits(t0, t1, n0, n1)

    def to_polyhedron(self, resolution: int = DEFAULT_RESOLUTION) -> ConvexPolyhedron:
        """Inscribed UV-sphere polyhedron with ``resolution`` segments around."""
        # imported here: polyhedra register after this kind (the scene-file order)
        from .polyhedron import ConvexPolyhedron

        m = max(int(resolution), 4)
        rings = max(m // 2, 2)
        theta = np.linspace(0, math.pi, rings + 1)[1:-1]
        phi = np.linspace(0, 2 * math.pi, m, endpoint=False)
        st, ct = np.sin(theta)[:, None], np.cos(theta)[:, None]
        ring = np.stack(
            [st * np.cos(phi)[None, :], st * np.sin(phi)[None, :], np.broadcast_to(ct, (rings - 1, m))], axis=-1
        ).reshape(-1, 3)
        pts = np.vstack([[0, 0, 1.0], ring, [0, 0, -1.0]]) * self.radius + self.center_array
        return ConvexPolyhedron(pts)

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> Primitive:
        from .affine import similarity_factor

        c = A @ self.center_array + t
        k = similarity_factor(A)
        if k is not None:
            return Sphere(c, k * self.radius)
        # an ellipsoid, looked up by name: kinds/ellipsoid.py builds on this module
        image: Primitive = kind_class("ellipsoid").from_affine(A * self.radius, c)
        return image

    # ------------------------------------------------------------ the kind interface
    def extent(self, n: ArrayLike) -> tuple[float, float]:
        """Exact extent along the unit vector ``n``."""
        c = float(self.center_array @ np.asarray(n, dtype=np.float64))
        return c - self.radius, c + self.radius

    def signed_distance(self, points: ArrayLike) -> NDArray[np.float64]:
        """Exact: distance to the centre minus the radius."""
        d = np.asarray(points, dtype=np.float64).reshape(-1, 3) - self.center_array
        return np.sqrt(np.einsum("ij,ij->i", d, d)) - self.radius  # type: ignore[no-any-return]

    def tangent_cone(self, points: NDArray[np.float64], tol: float) -> TangentCone:
        """The tangent half-space."""
        m = len(points)
        d = points - self.center_array
        n = d / np.maximum(np.linalg.norm(d, axis=1, keepdims=True), 1e-300)
        return n[:, None, :], np.zeros((m, 1)), np.ones((m, 1), dtype=bool)

    def section(self, frame: NDArray[np.float64], resolution: int, area_exact: bool = False) -> Polygon:
        """A disc (centre and radius exact) as a regular polygon."""
        from shapely.geometry import Polygon

        from .planar import EMPTY, circle_ring, to2d

        F = frame
        c = self.center_array
        d = float((c - F[:3, 3]) @ F[:3, 2])
        rr = self.radius**2 - d * d
        if rr <= 0.0:
            return EMPTY
        c2 = to2d(c[None, :], F)
        return Polygon(circle_ring(c2, np.array([math.sqrt(rr)]), resolution, area_exact)[0])

    @property
    def area(self) -> float:
        """Exact surface area, 4 pi r^2."""
        return 4.0 * math.pi * float(self.radius) ** 2

    def exact_form(self) -> AffineBall:
        """A round :class:`~isocsg.kinds.forms.AffineBall` (``radius * I``)."""
        return AffineBall(self.center_array, self.radius * np.eye(3), self.radius)

    def surface_patches(self, leaf: int) -> list[Patch]:
        """Rings across z (:func:`~isocsg.kinds.patches.ball_patches`)."""
        return ball_patches(leaf, self.center_array, float(self.radius))

    def leaf_row(self) -> LeafRow:
        """A :attr:`LeafForm.BALL` row."""
        return LeafRow(LeafForm.BALL, center=self.center_array, radius=self.radius)

    @classmethod
    def leaf_boxes(cls, leaves: Sequence[Primitive]) -> LeafBoxes:
        """Balls, read from their parameters in one pass."""
        a = np.asarray([(*p.center, p.radius) for p in leaves], dtype=np.float64).reshape(-1, 4)  # type: ignore[attr-defined]
        return a[:, :3] - a[:, 3:], a[:, :3] + a[:, 3:], np.ones(len(a), np.bool_), a[:, :3], a[:, 3]

    def manifold(self, resolution: int, shapes: dict[tuple[Any, ...], Any] | None = None) -> Any:
        """manifold3d's sphere (it rounds the segment count up to a multiple of 4), moved."""
        shapes = {} if shapes is None else shapes
        key = ("sphere", self.radius, resolution)
        if key not in shapes:
            shapes[key] = manifold3d_module().Manifold.sphere(self.radius, resolution)
        return shapes[key].translate(tuple(self.center))

    def band_surface(
        self, lights: list[Any], contours: int, eye: NDArray[np.float64] | None, shininess: float,
        weights: tuple[float, float] = (1.0, 1.0), segments: int | None = None, *,
        hidden: tuple[Any, Any] | None = None,
    ) -> Surface:
        """Latitude-longitude mesh about the first light's axis, its contour circles as mesh edges
        (``segments`` longitudes, by default :data:`isocsg.kinds.sphere_bands.LONGITUDES`)."""
        from ..bands.families import diffuse_levels
        from .sphere_bands import LONGITUDES, sphere_surface

        levels = diffuse_levels(np.array([-1.0, 1.0]), contours)
        return sphere_surface(self, lights[0] if lights else None, levels, LONGITUDES if segments is None else segments)

    def contour_laminae(
        self, light: Any, contours: int,
    ) -> list[tuple[NDArray[np.float64], NDArray[np.float64], float, str]]:
        """The seed's contour discs."""
        from .sphere_bands import sphere_laminae

        return [(v, nrm, c, "contour") for v, nrm, c in sphere_laminae(self, light, contours)]

    def contour_family(
        self, light: Any, contours: int,
    ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
        """Contour planes across the centre-light axis at the heights of cosines ``k / N``."""
        from ..bands.lights import light_axis
        from .sphere_bands import contour_heights

        cos_k = np.arange(contours + 1) / contours
        c = self.center_array
        w = light_axis(c, light)
        t = contour_heights(self, light, cos_k)
        return w, float(w @ c) + self.radius * t, cos_k

    def to_openscad(self, digits: int | None = None, *, exact: bool = True) -> str:
        """``sphere(r)``, moved to the centre."""
        if digits is not None:
            return encoded("sphere(r = 1);", self.radius * np.eye(3), self.center_array, digits)
        return translated(np.asarray(self.center), f"sphere(r = {num(self.radius)});")

    def to_dict(self) -> dict[str, Any]:
        """``{"sphere": {"center": [...], "radius": r}}``."""
        return {"sphere": {"center": list(self.center), "radius": self.radius}}
