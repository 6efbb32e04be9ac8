"""Analytic CSG primitives: sphere, generalised truncus, box and convex polyhedron.

Every primitive is an immutable, validated value (a frozen dataclass holding
tuples) that describes a closed convex solid. Arrays are exposed through
properties. All primitives share the :class:`Solid` interface:

- ``contains(points)``: vectorised inside test (the boundary counts as inside),
- ``bounds``: ``(2, 3)`` array of the axis-aligned bounding box,
- ``intersect_rays(origins, directions)``: entry and exit parameters and
  outward normals of rays against the solid (``inf`` where missed),
- ``to_trimesh(resolution)`` and ``to_polyhedron(resolution)``: tessellations,
- ``to_dict()``: a JSON/TOML-ready mapping with a ``kind`` tag.

The ``|``, ``&`` and ``-`` operators build CSG trees (see :mod:`isocsg.csg`).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import MAX_ABS_COORD, MAX_VERTICES, MIN_ASPECT, Vec3, length_floor, nonzero_vector3, points_array, scalar, vector3
from ..errors import InvalidGeometryError

if TYPE_CHECKING:  # pragma: no cover
    import trimesh

__all__ = [
    "Solid",
    "Primitive",
    "Sphere",
    "Truncus",
    "Cylinder",
    "Cone",
    "Box",
    "ConvexPolyhedron",
    "RayHits",
]

DEFAULT_RESOLUTION = 64


@dataclass(frozen=True, slots=True)
class RayHits:
    """Where rays enter and leave a convex solid.

    Attributes
    ----------
    t_in, t_out : ndarray, shape (n,)
        Ray parameters of entry and exit (``inf`` for rays that miss;
        ``t_in`` may be negative when the origin is inside).
    n_in, n_out : ndarray, shape (n, 3)
        Outward unit normals of the solid at entry and exit (zero on misses).
    """

    t_in: NDArray[np.float64]
    t_out: NDArray[np.float64]
    n_in: NDArray[np.float64]
    n_out: NDArray[np.float64]

    @property
    def hit(self) -> NDArray[np.bool_]:
        """Rays whose line meets the solid (``t_in <= t_out``, finite)."""
        return np.isfinite(self.t_in) & (self.t_in <= self.t_out)


class Solid:
    """Base of every solid: primitives and CSG trees.

    Provides the Boolean operators; subclasses implement ``contains``,
    ``bounds`` and ``to_trimesh``.
    """

    __slots__ = ()

    def __or__(self, other: Solid) -> Solid:
        from ..csg import union

        return union(self, other)

    def __and__(self, other: Solid) -> Solid:
        from ..csg import intersection

        return intersection(self, other)

    def __sub__(self, other: Solid) -> Solid:
        from ..csg import difference

        return difference(self, other)

    def _repr_mimebundle_(self, include: Any = None, exclude: Any = None) -> dict[str, Any]:
        """Rich display in Jupyter: a small PNG image (see :mod:`isocsg.interop.notebook`)."""
        from ..interop.notebook import mimebundle

        return mimebundle(self, include, exclude)

    def _repr_png_(self) -> bytes | None:
        """A small PNG image of the object (see :mod:`isocsg.interop.notebook`)."""
        from ..interop.notebook import mimebundle

        return mimebundle(self, ("image/png",)).get("image/png")

    # ------------------------------------------------------------ transforms
    def transform(self, matrix: ArrayLike) -> Solid:
        """The image under an affine map ``x -> A x + t`` given as a 4x4 or 3x4 matrix ``[A | t]``.

        Parameters
        ----------
        matrix : array_like, shape (4, 4) or (3, 4)
            Finite, invertible, with a condition number at most
            :data:`isocsg.geometry.transforms.MAX_CONDITION`.

        Returns
        -------
        Solid
            A new solid; ``self`` is unchanged. Primitives stay exact analytic
            primitives (see :doc:`the transforms section of the README <README>`).

        Raises
        ------
        InvalidParameterError
            If the matrix is malformed, singular or too ill-conditioned (the
            message names ``matrix``).

        Examples
        --------
        >>> Sphere((0, 0, 0), 1).transform([[2, 0, 0, 1], [0, 2, 0, 0], [0, 0, 2, 0]])
        Sphere(center=(1.0, 0.0, 0.0), radius=2.0)
        """
        from .transforms import transform_solid

        return transform_solid(self, matrix)

    def translate(self, v: ArrayLike) -> Solid:
        """The solid moved by ``v`` (metres).

        Examples
        --------
        >>> Sphere((0, 0, 0), 1).translate((1, 2, 3)).center
        (1.0, 2.0, 3.0)
        """
        from .transforms import translation_matrix

        return self.transform(translation_matrix(v))

    def rotate(self, v: ArrayLike, axis: ArrayLike | None = None) -> Solid:
        """The solid turned about the origin (degrees), as OpenSCAD's ``rotate``.

        Parameters
        ----------
        v : array_like, shape (3,), or float
            Euler angles ``[a, b, c]``: ``a`` about x, then ``b`` about y, then
            ``c`` about z. A single number turns about ``axis`` (default z).
        axis : array_like, shape (3,), optional
            The axis of an axis-angle rotation (right-hand rule).

        Examples
        --------
        >>> Box((1, 0, 0), (2, 1, 1)).rotate((0, 0, 90))
        Box(center=(0.0, 1.0, 0.0), size=(1.0, 2.0, 1.0))
        """
        from .transforms import axis_angle_matrix, rotation_matrix

        if axis is not None or np.ndim(v) == 0:
            return self.transform(axis_angle_matrix(v, (0.0, 0.0, 1.0) if axis is None else axis))  # type: ignore[arg-type]
        return self.transform(rotation_matrix(v))

    def scale(self, s: ArrayLike) -> Solid:
        """The solid scaled about the origin by a number or per axis ``[sx, sy, sz]``."""
        from .transforms import scale_matrix

        return self.transform(scale_matrix(s))

    def mirror(self, normal: ArrayLike) -> Solid:
        """The solid reflected in the plane through the origin with ``normal`` (OpenSCAD's ``mirror``)."""
        from .transforms import mirror_matrix

        return self.transform(mirror_matrix(normal))

    # Subclasses override these.
    def contains(self, points: ArrayLike) -> NDArray[np.bool_]:  # pragma: no cover
        raise NotImplementedError

    @property
    def bounds(self) -> NDArray[np.float64]:  # pragma: no cover
        raise NotImplementedError


class Primitive(Solid):
    """Base of the convex analytic primitives."""

    __slots__ = ()
    kind: str = "primitive"

    def _points(self, points: ArrayLike) -> NDArray[np.float64]:
        return points_array(f"{type(self).__name__}.contains(points)", points)

    def intersect_rays(self, origins: ArrayLike, directions: ArrayLike) -> RayHits:  # pragma: no cover
        """Intersect rays with the solid; see :class:`RayHits`."""
        raise NotImplementedError

    def to_manifold(self, resolution: int = DEFAULT_RESOLUTION) -> "manifold3d.Manifold":  # type: ignore[name-defined]  # noqa: F821
        """The primitive as a manifold3d ``Manifold`` (see :func:`isocsg.csg.mesh.to_manifold`)."""
        from ..csg.mesh import to_manifold

        return to_manifold(self, resolution)

    def to_trimesh(self, resolution: int = DEFAULT_RESOLUTION) -> "trimesh.Trimesh":
        """A closed triangle mesh of the solid (vertices on the true surface)."""
        import trimesh

        poly = self.to_polyhedron(resolution)
        return trimesh.Trimesh(poly.hull_vertices, poly.triangles, process=False)

    def to_polyhedron(self, resolution: int = DEFAULT_RESOLUTION) -> "ConvexPolyhedron":  # pragma: no cover
        """A :class:`ConvexPolyhedron` inscribed in the solid."""
        raise NotImplementedError

    def to_dict(self) -> dict[str, Any]:  # pragma: no cover
        """A plain mapping ``{kind: {field: value}}`` for scene files."""
        raise NotImplementedError

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> Primitive:  # pragma: no cover
        """The image under ``x -> A x + t`` (``A`` validated by :func:`~isocsg.geometry.transforms.affine_matrix`)."""
        raise NotImplementedError


def _as_rays(origins: ArrayLike, directions: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    o = points_array("origins", origins)
    d = points_array("directions", directions)
    if o.shape[0] == 1 and d.shape[0] > 1:
        o = np.broadcast_to(o, d.shape)
    if o.shape != d.shape:
        raise InvalidGeometryError(f"origins and directions must have the same shape, got {o.shape} and {d.shape}")
    return o, d


def _check_length(name: str, value: float, *positions: Any, what: str = "") -> None:
    """Reject a length below :func:`~isocsg._validation.length_floor` of the positions."""
    floor = length_floor(*positions)
    if value < floor:
        verb = f"have {what}" if what else "be"
        raise InvalidGeometryError(f"{name} must {verb} >= {floor:g} (the smallest length at this position), got {value:g}")


def _unit(v: Vec3) -> NDArray[np.float64]:
    a = np.asarray(v, dtype=np.float64)
    return a / np.linalg.norm(a)


def _perpendicular_frame(axis: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Two unit vectors that complete ``axis`` (unit) to a right-handed frame."""
    helper = np.array([1.0, 0.0, 0.0]) if abs(axis[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = np.cross(axis, helper)
    u /= np.linalg.norm(u)
    return u, np.cross(axis, u)


IDENTITY3: tuple[Vec3, Vec3, Vec3] = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))

#: How far from orthonormal (max |R^T R - I|) an ``orientation`` may be; it is then made exactly orthonormal.
ROTATION_TOL = 1e-9


def rotation3(name: str, value: Any) -> tuple[Vec3, Vec3, Vec3]:
    """Validate a 3x3 rotation matrix (orthonormal, determinant +1) and return it as row tuples.

    Matrices within :data:`ROTATION_TOL` of a rotation, but further than 1e-12 from one, are
    polished to the nearest rotation.
    """
    if isinstance(value, (str, bytes)):
        raise InvalidGeometryError(f"{name} must be a 3x3 rotation matrix, got {value!r}")
    try:
        r = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise InvalidGeometryError(f"{name} must be a 3x3 rotation matrix of numbers") from None
    if r.shape != (3, 3):
        raise InvalidGeometryError(f"{name} must have shape (3, 3), got {r.shape}")
    if not np.all(np.isfinite(r)):
        raise InvalidGeometryError(f"{name} must be finite, got {r.tolist()}")
    err = float(np.max(np.abs(r.T @ r - np.eye(3))))
    if err > ROTATION_TOL:
        raise InvalidGeometryError(f"{name} must be orthonormal (a rotation), got R^T R - I up to {err:g}")
    if np.linalg.det(r) < 0:
        raise InvalidGeometryError(f"{name} must be a rotation (determinant +1), got a reflection")
    if err > 1e-12:  # polished once; a polished matrix passes unchanged (files read back equal)
        u, _, vt = np.linalg.svd(r)
        r = u @ vt
    return tuple(tuple(float(x) for x in row) for row in r)  # type: ignore[return-value]


def _orthogonal_columns(B: NDArray[np.float64]) -> NDArray[np.float64] | None:
    """Column lengths of ``B`` when its columns are mutually orthogonal (relative 1e-9), else None."""
    out = _orthogonal_columns_cached(np.ascontiguousarray(B, dtype=np.float64).tobytes())
    return None if out is None else out.copy()


@functools.lru_cache(maxsize=64)
def _orthogonal_columns_cached(key: bytes) -> NDArray[np.float64] | None:
    B = np.frombuffer(key, dtype=np.float64).reshape(3, 3)
    norms = np.linalg.norm(B, axis=0)
    g = (B.T @ B) / np.outer(norms, norms)
    if np.max(np.abs(g - np.eye(3))) <= 1e-9:
        return norms
    return None


def _snap_rotation(Q: NDArray[np.float64]) -> NDArray[np.float64]:
    """``Q`` with entries within 1e-15 of 0 or +-1 made exact (so 90-degree turns stay exact)."""
    out = Q.copy()
    out[np.abs(out) <= 1e-15] = 0.0
    one = np.abs(np.abs(out) - 1.0) <= 1e-15
    out[one] = np.sign(out[one])
    return out


# ----------------------------------------------------------------------------- sphere


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
    kind = "sphere"

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

    def contains(self, points: ArrayLike, *, tol: float | None = None) -> NDArray[np.bool_]:
        """Boolean mask of the points inside or on the sphere, within ``tol``.

        A point is inside when its signed distance to the boundary
        (exact) is at most ``tol`` metres (>= 0; default 1e-12 of the
        sphere's size or coordinate magnitude, whichever is larger).
        """
        from ..csg.membership import check_tolerance, primitive_tolerance, signed_distance

        p = self._points(points)
        limit = check_tolerance(f"{type(self).__name__}.contains(tol)", tol, primitive_tolerance(self))
        return signed_distance(self, p) <= limit

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

    def to_polyhedron(self, resolution: int = DEFAULT_RESOLUTION) -> "ConvexPolyhedron":
        """Inscribed UV-sphere polyhedron with ``resolution`` segments around."""
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
        from .transforms import similarity_factor

        c = A @ self.center_array + t
        k = similarity_factor(A)
        if k is not None:
            return Sphere(c, k * self.radius)
        from .ellipsoid import Ellipsoid

        return Ellipsoid.from_affine(A * self.radius, c)

    def to_dict(self) -> dict[str, Any]:
        """``{"sphere": {"center": [...], "radius": r}}``."""
        return {"sphere": {"center": list(self.center), "radius": self.radius}}


# ----------------------------------------------------------------------------- truncus


@dataclass(frozen=True, slots=True)
class Truncus(Primitive):
    """The generalised truncus of the isoluminance paper: a cylinder, cone or frustum.

    End E1 of radius ``r1`` is centred at ``center + axis / 2`` and end E2 of
    radius ``r2`` at ``center - axis / 2``; the length of ``axis`` is the
    height. ``r1 == r2`` gives a cylinder (a disc when short, a rod when long
    and thin), one radius 0 a cone, anything else a frustum.

    Parameters
    ----------
    center : array_like, shape (3,)
    axis : array_like, shape (3,)
        Non-zero; from the E2 end to the E1 end.
    r1, r2 : float
        Radii of the ends, >= 0 and not both 0.

    Raises
    ------
    InvalidGeometryError
        On non-finite values, a zero axis, a negative radius, or both radii 0.

    Examples
    --------
    >>> t = Truncus((0, 0, 0), (0, 0, 2), 1.0, 0.5)
    >>> round(t.height, 3), t.contains([[0, 0, 0.99], [0.9, 0, -0.9]]).tolist()
    (2.0, [True, False])
    """

    center: Vec3
    axis: Vec3
    r1: float
    r2: float
    kind = "truncus"

    def __post_init__(self) -> None:
        name = type(self).__name__
        center = vector3(f"{name}.center", self.center)
        axis = nonzero_vector3(f"{name}.axis", self.axis)
        object.__setattr__(self, "center", center)
        object.__setattr__(self, "axis", axis)
        r1 = scalar(f"{name}.r1", self.r1, low=0.0, low_inclusive=True, high=MAX_ABS_COORD)
        r2 = scalar(f"{name}.r2", self.r2, low=0.0, low_inclusive=True, high=MAX_ABS_COORD)
        if r1 == 0.0 and r2 == 0.0:
            raise InvalidGeometryError(f"{name}.r1 and {name}.r2 must not both be 0")
        # Cylinders and cones are given one `radius`; name that field in their messages.
        one_radius = isinstance(self, (Cylinder, Cone))
        floor = length_floor(center, axis)
        for field_name, r in (("r1", r1), ("r2", r2)):
            if 0.0 < r < floor:
                shown = "radius" if one_radius else field_name
                raise InvalidGeometryError(
                    f"{name}.{shown} must be 0 or >= {floor:g} (the smallest length at this position), got {r:g}"
                )
        height = math.hypot(*axis)
        _check_length(f"{name}.axis", height, center, what="length")
        big = max(r1, r2)
        if height < MIN_ASPECT * big:
            raise InvalidGeometryError(
                f"{name}.axis must be at least {MIN_ASPECT:g} x the larger radius {big:g} long, got length {height:g}"
            )
        if big < MIN_ASPECT * height:
            shown = "radius" if one_radius else ("r1" if r1 >= r2 else "r2")
            raise InvalidGeometryError(
                f"{name}.{shown} must be at least {MIN_ASPECT:g} x the height {height:g}, got {big:g}"
            )
        object.__setattr__(self, "r1", r1)
        object.__setattr__(self, "r2", r2)

    @property
    def height(self) -> float:
        """Length of the axis."""
        return float(math.hypot(*self.axis))

    @property
    def unit_axis(self) -> NDArray[np.float64]:
        """Unit vector from E2 to E1."""
        return _unit(self.axis)

    @property
    def center_array(self) -> NDArray[np.float64]:
        """The centre as a float64 array."""
        return np.asarray(self.center, dtype=np.float64)

    @property
    def end_centers(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Centres of E1 (``center + axis/2``) and E2 (``center - axis/2``)."""
        c, a = self.center_array, np.asarray(self.axis)
        return c + a / 2, c - a / 2

    @property
    def slope(self) -> float:
        """d(radius)/d(s) along the unit axis: ``(r1 - r2) / height``."""
        return (self.r1 - self.r2) / self.height

    def radius_at(self, s: ArrayLike) -> NDArray[np.float64]:
        """Radius at signed axial coordinate ``s`` (0 at the centre, +h/2 at E1)."""
        s = np.asarray(s, dtype=np.float64)
        return self.r2 + self.slope * (s + self.height / 2)

    @property
    def volume(self) -> float:
        """Exact volume, pi h (r1^2 + r1 r2 + r2^2) / 3."""
        return math.pi * self.height * (self.r1**2 + self.r1 * self.r2 + self.r2**2) / 3.0

    def _local(self, p: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
        """Axial coordinate s, radial distance rho and radial unit vector of points."""
        ax = self.unit_axis
        rel = p - self.center_array
        s = rel @ ax
        radial = rel - s[:, None] * ax
        rho = np.linalg.norm(radial, axis=1)
        er = np.divide(radial, rho[:, None], out=np.zeros_like(radial), where=rho[:, None] > 0)
        return s, rho, er

    def contains(self, points: ArrayLike, *, tol: float | None = None) -> NDArray[np.bool_]:
        """Boolean mask of the points inside or on the truncus, within ``tol``.

        A point is inside when its signed distance to the boundary (exact:
        the distance to its trapezoid in the meridian half-plane) is at most
        ``tol`` metres (>= 0; default 1e-12 of the truncus's size or
        coordinate magnitude, whichever is larger).
        """
        from ..csg.membership import check_tolerance, primitive_tolerance, signed_distance

        p = self._points(points)
        limit = check_tolerance(f"{type(self).__name__}.contains(tol)", tol, primitive_tolerance(self))
        return signed_distance(self, p) <= limit

    @property
    def bounds(self) -> NDArray[np.float64]:
        """Axis-aligned bounds, shape (2, 3) (exact for circular ends)."""
        ax = self.unit_axis
        ext = np.sqrt(np.clip(1 - ax**2, 0, 1))  # half-extent of a unit circle normal to ax
        lo, hi = [], []
        for c, r in zip(self.end_centers, (self.r1, self.r2)):
            lo.append(c - r * ext)
            hi.append(c + r * ext)
        return np.stack([np.minimum(*lo), np.maximum(*hi)])

    def side_normals(self, points: ArrayLike) -> NDArray[np.float64]:
        """Exact outward unit normals of the lateral surface at ``points``."""
        p = points_array("points", points)
        _, _, er = self._local(p)
        n = er - self.slope * self.unit_axis
        return n / np.linalg.norm(n, axis=1, keepdims=True)

    def intersect_rays(self, origins: ArrayLike, directions: ArrayLike) -> RayHits:
        """Analytic ray-truncus intersection (lateral quadric and two end caps)."""
        o, d = _as_rays(origins, directions)
        ax = self.unit_axis
        h2 = self.height / 2
        k = self.slope
        rel = o - self.center_array
        s0, ds = rel @ ax, d @ ax
        q0 = rel - s0[:, None] * ax  # radial parts
        qd = d - ds[:, None] * ax
        # lateral surface: |q0 + t qd|^2 = (r0 + k (s0 + t ds))^2 with r0 = radius at s = 0
        r0 = self.radius_at(0.0)
        rs0 = r0 + k * s0
        a = np.einsum("ij,ij->i", qd, qd) - (k * ds) ** 2
        b = np.einsum("ij,ij->i", q0, qd) - rs0 * k * ds
        c = np.einsum("ij,ij->i", q0, q0) - rs0**2
        n = len(o)
        t_in = np.full(n, -np.inf)
        t_out = np.full(n, np.inf)
        n_in = np.zeros((n, 3))
        n_out = np.zeros((n, 3))
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            # --- slab between the end planes
            t_e1 = (h2 - s0) / ds
            t_e2 = (-h2 - s0) / ds
            par = np.abs(ds) < 1e-300
            outside_slab = par & (np.abs(s0) > h2)
            lo_t = np.where(par, -np.inf, np.minimum(t_e1, t_e2))
            hi_t = np.where(par, np.inf, np.maximum(t_e1, t_e2))
            lo_n = np.where((t_e1 < t_e2)[:, None], ax, -ax)
            hi_n = -lo_n
            t_in, t_out = lo_t, hi_t
            n_in = np.where(np.isfinite(lo_t)[:, None], lo_n, 0.0)
            n_out = np.where(np.isfinite(hi_t)[:, None], hi_n, 0.0)
            # --- the (double) cone or cylinder: inside where c(t) = |q|^2 - r(s)^2 <= 0 and r(s) >= 0
            disc = b * b - a * c
            sq = np.sqrt(np.where(disc > 0, disc, 0.0))
            ta = (-b - sq) / a
            tb = (-b + sq) / a
            lin = np.abs(a) < 1e-14 * np.maximum(1.0, np.abs(b))
            # intervals where c(t) <= 0: a > 0 -> [ta, tb]; a < 0 -> outside (tb, ta) i.e. two rays
            c_lo = np.full(n, -np.inf)
            c_hi = np.full(n, np.inf)
            empty = np.zeros(n, dtype=bool)
            pos = (~lin) & (a > 0)
            c_lo[pos], c_hi[pos] = ta[pos], tb[pos]
            empty |= pos & (disc < 0)
            # a < 0 (steep cone lines): the inside set is (-inf, tb] U [ta, inf); the slab picks one
            neg = (~lin) & (a < 0)
            # linear case: 2 b t + c <= 0
            lin_ok = lin & (np.abs(b) > 0)
            tl = -c / (2 * b)
            c_hi = np.where(lin_ok & (b > 0), tl, c_hi)
            c_lo = np.where(lin_ok & (b < 0), tl, c_lo)
            empty |= lin & (np.abs(b) == 0) & (c > 0)
            empty |= neg & (disc < 0) & (c > 0)
        # for a < 0 with real roots, choose the branch on the sheet r(s) >= 0 inside the slab
        # a < 0 with real roots: the inside set (c(t) <= 0) is two rays, one on each nappe
        # of the double cone; keep the one whose part inside the slab lies on r(s) >= 0.
        neg_real = neg & (disc >= 0)
        if np.any(neg_real):
            lo_root, hi_root = np.minimum(ta, tb), np.maximum(ta, tb)
            chosen_lo = np.full(n, np.inf)
            chosen_hi = np.full(n, -np.inf)
            found = np.zeros(n, dtype=bool)
            for cand_lo, cand_hi in ((np.full(n, -np.inf), lo_root), (hi_root, np.full(n, np.inf))):
                lo2, hi2 = np.maximum(cand_lo, t_in), np.minimum(cand_hi, t_out)
                overlap = neg_real & (lo2 <= hi2)
                fin_lo, fin_hi = np.isfinite(lo2), np.isfinite(hi2)
                tm = np.where(fin_lo & fin_hi, 0.5 * (np.where(fin_lo, lo2, 0) + np.where(fin_hi, hi2, 0)),
                              np.where(fin_lo, lo2, np.where(fin_hi, hi2, 0.0)))
                good = overlap & (r0 + k * (s0 + tm * ds) >= 0)
                chosen_lo = np.where(good, cand_lo, chosen_lo)
                chosen_hi = np.where(good, cand_hi, chosen_hi)
                found |= good
            empty |= neg_real & ~found
            c_lo = np.where(neg_real & found, chosen_lo, c_lo)
            c_hi = np.where(neg_real & found, chosen_hi, c_hi)
        # where the whole slab-interval is in the cone (c(t) <= 0 everywhere) c_lo/c_hi stay infinite
        p_lo = o + np.nan_to_num(c_lo, posinf=0, neginf=0)[:, None] * d
        p_hi = o + np.nan_to_num(c_hi, posinf=0, neginf=0)[:, None] * d
        nl = self._side_normals_raw(p_lo)
        nh = self._side_normals_raw(p_hi)
        use_lo = c_lo > t_in
        t_in = np.where(use_lo, c_lo, t_in)
        n_in = np.where(use_lo[:, None], nl, n_in)
        use_hi = c_hi < t_out
        t_out = np.where(use_hi, c_hi, t_out)
        n_out = np.where(use_hi[:, None], nh, n_out)
        # the side on the wrong nappe of a double cone (r(s) < 0) is not part of the solid
        mid = 0.5 * (np.clip(t_in, -1e300, 1e300) + np.clip(t_out, -1e300, 1e300))
        smid = s0 + mid * ds
        bad = empty | outside_slab | (t_in > t_out) | ~np.isfinite(t_in) | ~np.isfinite(t_out)
        bad |= self.radius_at(np.clip(smid, -h2, h2)) < -1e-12
        t_in = np.where(bad, np.inf, t_in)
        t_out = np.where(bad, -np.inf, t_out)
        n_in = np.where(bad[:, None], 0.0, n_in)
        n_out = np.where(bad[:, None], 0.0, n_out)
        return RayHits(t_in, t_out, n_in, n_out)

    def _side_normals_raw(self, p: NDArray[np.float64]) -> NDArray[np.float64]:
        _, _, er = self._local(p)
        n = er - self.slope * self.unit_axis
        return n / np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)

    def to_polyhedron(self, resolution: int = DEFAULT_RESOLUTION) -> "ConvexPolyhedron":
        """Inscribed polyhedron with ``resolution`` points on each end circle."""
        m = max(int(resolution), 3)
        u, v = _perpendicular_frame(self.unit_axis)
        ang = np.linspace(0, 2 * math.pi, m, endpoint=False)
        circle = np.cos(ang)[:, None] * u + np.sin(ang)[:, None] * v
        pts = []
        for c, r in zip(self.end_centers, (self.r1, self.r2)):
            pts.append(c[None, :] if r == 0 else c + r * circle)
        return ConvexPolyhedron(np.vstack(pts))

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> Primitive:
        c = A @ self.center_array + t
        axis = A @ np.asarray(self.axis, dtype=np.float64)
        u, v = _perpendicular_frame(self.unit_axis)
        au, av = A @ u, A @ v
        nu, nv = float(np.linalg.norm(au)), float(np.linalg.norm(av))
        an = float(np.linalg.norm(axis))
        tol = 1e-9
        circular = (
            abs(nu - nv) <= tol * max(nu, nv)
            and abs(au @ av) <= tol * nu * nv
            and abs(au @ axis) <= tol * nu * an
            and abs(av @ axis) <= tol * nv * an
        )
        if circular:  # end circles map to circles normal to the new axis: a right truncus again
            k = 0.5 * (nu + nv)
            if type(self) is Cylinder:
                return Cylinder(c, axis, k * self.r1)
            if type(self) is Cone:
                return Cone(c, axis, k * self.r1)
            return Truncus(c, axis, k * self.r1, k * self.r2)
        from .elliptic import EllipticTruncus

        frame = np.column_stack([u, v, np.asarray(self.axis, dtype=np.float64)])  # canonical -> self
        return EllipticTruncus(tuple(c), A @ frame, self.r1, self.r2)

    def to_dict(self) -> dict[str, Any]:
        """``{"truncus": {"center", "axis", "r1", "r2"}}``."""
        return {"truncus": {"center": list(self.center), "axis": list(self.axis), "r1": self.r1, "r2": self.r2}}


class Cylinder(Truncus):
    """A right circular cylinder: a :class:`Truncus` with ``r1 == r2 == radius``.

    Examples
    --------
    >>> c = Cylinder((0, 0, 0), (0, 0, 2), 0.5)
    >>> c.r1 == c.r2 == c.radius == 0.5
    True
    """

    __slots__ = ()
    kind = "cylinder"

    def __init__(self, center: ArrayLike, axis: ArrayLike, radius: float) -> None:
        r = scalar("Cylinder.radius", radius, low=0.0, high=MAX_ABS_COORD)
        Truncus.__init__(self, center, axis, r, r)  # type: ignore[arg-type]

    @property
    def radius(self) -> float:
        """The common radius of both ends."""
        return self.r1

    def __repr__(self) -> str:
        return f"Cylinder(center={self.center}, axis={self.axis}, radius={self.radius})"

    def to_dict(self) -> dict[str, Any]:
        """``{"cylinder": {"center", "axis", "radius"}}``."""
        return {"cylinder": {"center": list(self.center), "axis": list(self.axis), "radius": self.radius}}


class Cone(Truncus):
    """A right circular cone: base of ``radius`` at ``center + axis/2`` (E1), apex at ``center - axis/2``.

    Examples
    --------
    >>> k = Cone((0, 0, 0), (0, 0, 1), 1.0)
    >>> (k.r1, k.r2)
    (1.0, 0.0)
    """

    __slots__ = ()
    kind = "cone"

    def __init__(self, center: ArrayLike, axis: ArrayLike, radius: float) -> None:
        r = scalar("Cone.radius", radius, low=0.0, high=MAX_ABS_COORD)
        Truncus.__init__(self, center, axis, r, 0.0)  # type: ignore[arg-type]

    @property
    def radius(self) -> float:
        """Radius of the base."""
        return self.r1

    def __repr__(self) -> str:
        return f"Cone(center={self.center}, axis={self.axis}, radius={self.radius})"

    def to_dict(self) -> dict[str, Any]:
        """``{"cone": {"center", "axis", "radius"}}``."""
        return {"cone": {"center": list(self.center), "axis": list(self.axis), "radius": self.radius}}


# ----------------------------------------------------------------------------- polyhedra


def _ray_halfspaces(
    o: NDArray[np.float64], d: NDArray[np.float64], normals: NDArray[np.float64], offsets: NDArray[np.float64]
) -> RayHits:
    """Clip rays against the convex solid {x : normals @ x <= offsets}."""
    num = offsets[None, :] - o @ normals.T  # (n, k): >= 0 where the origin is inside plane k
    den = d @ normals.T
    with np.errstate(divide="ignore", invalid="ignore"):
        t = num / den
    entering = den < 0
    leaving = den > 0
    t_enter = np.where(entering, t, -np.inf)
    t_leave = np.where(leaving, t, np.inf)
    i_in = np.argmax(t_enter, axis=1)
    i_out = np.argmin(t_leave, axis=1)
    rows = np.arange(len(o))
    t_in = t_enter[rows, i_in]
    t_out = t_leave[rows, i_out]
    parallel_out = np.any((den == 0) & (num < 0), axis=1)
    miss = parallel_out | (t_in > t_out) | ~np.isfinite(t_in) | ~np.isfinite(t_out)
    n_in = np.where(miss[:, None], 0.0, normals[i_in])
    n_out = np.where(miss[:, None], 0.0, normals[i_out])
    return RayHits(np.where(miss, np.inf, t_in), np.where(miss, -np.inf, t_out), n_in, n_out)


def _hull(points: NDArray[np.float64], name: str) -> tuple[NDArray[np.float64], list[NDArray[np.int64]], NDArray[np.float64], NDArray[np.float64], NDArray[np.int64]]:
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
    faces, normals, offsets = [], [], []
    for g in range(group.max() + 1):
        members = np.nonzero(group == g)[0]
        n = eq[members[0], :3]
        idx = np.unique(remap[hull.simplices[members].ravel()])
        pts = hv[idx]
        c = pts.mean(axis=0)
        u, v = _perpendicular_frame(n)
        ang = np.arctan2((pts - c) @ v, (pts - c) @ u)
        faces.append(idx[np.argsort(ang)])  # CCW around the outward normal
        normals.append(n)
        offsets.append(-eq[members[0], 3])
    tris = []
    for f in faces:
        for i in range(1, len(f) - 1):
            tris.append((f[0], f[i], f[i + 1]))
    return hv, faces, np.array(normals), np.array(offsets), np.array(tris, dtype=np.int64)


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
    kind = "polyhedron"

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

    def contains(self, points: ArrayLike, *, tol: float | None = None) -> NDArray[np.bool_]:
        """Boolean mask of the points inside or on the polyhedron, within ``tol``.

        A point is inside when its signed distance to the boundary (the
        largest signed distance to its face planes) is at most ``tol``
        metres (>= 0; default 1e-12 of the polyhedron's size or coordinate
        magnitude, whichever is larger).
        """
        from ..csg.membership import check_tolerance, primitive_tolerance, signed_distance

        p = self._points(points)
        limit = check_tolerance(f"{type(self).__name__}.contains(tol)", tol, primitive_tolerance(self))
        return signed_distance(self, p) <= limit

    @property
    def bounds(self) -> NDArray[np.float64]:
        """Axis-aligned bounds, shape (2, 3)."""
        return np.stack([self.hull_vertices.min(axis=0), self.hull_vertices.max(axis=0)])

    @property
    def volume(self) -> float:
        """Exact volume of the hull."""
        v = self.hull_vertices[self.triangles]
        return float(abs(np.einsum("ij,ij->i", v[:, 0], np.cross(v[:, 1], v[:, 2])).sum()) / 6.0)

    def intersect_rays(self, origins: ArrayLike, directions: ArrayLike) -> RayHits:
        """Exact ray-polyhedron intersection by half-space clipping."""
        o, d = _as_rays(origins, directions)
        return _ray_halfspaces(o, d, self.face_normals, self.face_offsets)

    def to_polyhedron(self, resolution: int = DEFAULT_RESOLUTION) -> "ConvexPolyhedron":
        """The polyhedron itself (it is already exact)."""
        return self

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> Primitive:
        # the hull of the mapped points is the image of the hull (affine maps keep convexity)
        return ConvexPolyhedron(np.asarray(self.vertices, dtype=np.float64) @ A.T + t)

    def to_dict(self) -> dict[str, Any]:
        """``{"polyhedron": {"vertices": [...]}}``."""
        return {"polyhedron": {"vertices": [list(v) for v in self.vertices]}}


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
    kind = "box"

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
        if min(size) < MIN_ASPECT * max(size):
            raise InvalidGeometryError(
                f"Box.size must have its smallest edge at least {MIN_ASPECT:g} x its largest, got {size}"
            )
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

    def contains(self, points: ArrayLike, *, tol: float | None = None) -> NDArray[np.bool_]:
        """Boolean mask of the points inside or on the box, within ``tol``.

        A point is inside when its signed distance to the boundary
        (exact) is at most ``tol`` metres (>= 0; default 1e-12 of the
        box's size or coordinate magnitude, whichever is larger).
        """
        from ..csg.membership import check_tolerance, primitive_tolerance, signed_distance

        p = self._points(points)
        limit = check_tolerance(f"{type(self).__name__}.contains(tol)", tol, primitive_tolerance(self))
        return signed_distance(self, p) <= limit

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
        return _ray_halfspaces(o, d, self.face_normals, self.face_offsets)

    def to_polyhedron(self, resolution: int = DEFAULT_RESOLUTION) -> ConvexPolyhedron:
        """The box as a :class:`ConvexPolyhedron` (exact)."""
        return ConvexPolyhedron(self.corners)

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> Primitive:
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

    def to_dict(self) -> dict[str, Any]:
        """``{"box": {"center", "size"}}``, plus ``"orientation"`` (3 rows) when not axis-aligned."""
        out: dict[str, Any] = {"center": list(self.center), "size": list(self.size)}
        if not self.axis_aligned:
            out["orientation"] = [list(r) for r in self.orientation]
        return {"box": out}
