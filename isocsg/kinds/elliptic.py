"""The elliptic truncus: a truncus under an affine map that is not a similarity.

A stretched, sheared or unevenly scaled cylinder, cone or frustum has
elliptic ends in parallel planes, and its axis (the line through the ends'
centres) may be oblique to them. :class:`EllipticTruncus` represents it
exactly as the affine image of the *canonical truncus*: axis along z from
``z = -1/2`` (end E2, radius ``r2``) to ``z = +1/2`` (end E1, radius ``r1``),

    points = center + matrix @ y,   y in the canonical truncus,

so that ``matrix[:, 2]`` is the axis (E2's centre to E1's), and ``matrix[:, 0]``,
``matrix[:, 1]`` span the ends (their semi-axes per unit radius). Every
computation maps to the canonical frame and back: ray parameters are
unchanged, and a canonical normal ``m`` is ``matrix^-T m`` in the world.
(A similarity of a truncus stays a :class:`~isocsg.kinds.truncus.Truncus`;
see :meth:`~isocsg.kinds.base.Solid.transform`.)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import MAX_ABS_COORD, scalar, vector3
from ..errors import InvalidGeometryError
from .base import DEFAULT_RESOLUTION, LeafForm, LeafRow, Primitive, RayHits, _as_rays
from .forms import AffineFrustum, frustum_is_prism
from .meshing import manifold3d_module
from .patches import Patch, affine_frustum_patches, elliptic_lateral_area
from .polyhedron import ConvexPolyhedron
from .registry import register_kind
from .scad import encoded, mat, num, truncus_body
from .truncus import Truncus

if TYPE_CHECKING:  # pragma: no cover
    from shapely.geometry import Polygon

    from ..bands.surface import Surface

__all__ = ["EllipticTruncus"]

#: Largest condition number of ``matrix`` (as for transforms).
_MAX_CONDITION = 1e6


def _canonical(r1: float, r2: float) -> Truncus:
    return Truncus((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), r1, r2)


@register_kind("elliptic_truncus", required=("center", "matrix", "r1", "r2"))
@dataclass(frozen=True, slots=True)
class EllipticTruncus(Primitive):
    """The affine image of a truncus: elliptic ends in parallel planes, possibly oblique.

    Parameters
    ----------
    center : array_like, shape (3,)
        The midpoint between the ends' centres.
    matrix : array_like, shape (3, 3)
        Invertible (condition number <= 1e6); columns: the ends' unit-radius
        semi-axes and the axis from E2's centre to E1's (see the module docstring).
    r1, r2 : float
        Radii (>= 0, not both 0) of the canonical ends E1 (``+axis/2``) and E2.

    Raises
    ------
    InvalidGeometryError
        On non-finite values, a singular or too ill-conditioned matrix, or bad radii.

    Examples
    --------
    >>> from isocsg import Cylinder
    >>> e = Cylinder((0, 0, 0), (0, 0, 2), 1).scale((2, 1, 1))
    >>> type(e).__name__, round(e.volume / math.pi, 12)
    ('EllipticTruncus', 4.0)
    """

    center: tuple[float, float, float]
    matrix: tuple[tuple[float, float, float], tuple[float, float, float], tuple[float, float, float]]
    r1: float
    r2: float
    kind: ClassVar[str] = "elliptic_truncus"

    if TYPE_CHECKING:  # the constructor as callers call it: array-likes, checked in __post_init__
        def __init__(self, center: ArrayLike, matrix: ArrayLike, r1: float, r2: float) -> None: ...

    def __post_init__(self) -> None:
        center = vector3("EllipticTruncus.center", self.center)
        try:
            m = np.asarray(self.matrix, dtype=np.float64)
        except (TypeError, ValueError):
            raise InvalidGeometryError("EllipticTruncus.matrix must be a 3x3 matrix of numbers") from None
        if m.shape != (3, 3):
            raise InvalidGeometryError(f"EllipticTruncus.matrix must have shape (3, 3), got {m.shape}")
        if not np.all(np.isfinite(m)) or np.any(np.abs(m) > MAX_ABS_COORD):
            raise InvalidGeometryError(
                "EllipticTruncus.matrix must be finite and "
                f"within +-{MAX_ABS_COORD:g}, got {m.tolist()}"
            )
        sv = np.linalg.svd(m, compute_uv=False)
        if not sv[-1] > 0 or sv[0] / sv[-1] > _MAX_CONDITION:
            raise InvalidGeometryError(
                "EllipticTruncus.matrix must be invertible with a "
                f"condition number <= {_MAX_CONDITION:g}, got {m.tolist()}"
            )
        r1 = scalar("EllipticTruncus.r1", self.r1, low=0.0, low_inclusive=True, high=MAX_ABS_COORD)
        r2 = scalar("EllipticTruncus.r2", self.r2, low=0.0, low_inclusive=True, high=MAX_ABS_COORD)
        if max(r1, r2) <= 0:
            raise InvalidGeometryError(f"EllipticTruncus.r1 and r2 must not both be 0, got {r1}, {r2}")
        _canonical(r1, r2)  # the canonical truncus's own checks (aspect)
        object.__setattr__(self, "center", center)
        object.__setattr__(self, "matrix", tuple(tuple(float(x) for x in row) for row in m))
        object.__setattr__(self, "r1", r1)
        object.__setattr__(self, "r2", r2)

    # ------------------------------------------------------------ frame
    @property
    def center_array(self) -> NDArray[np.float64]:
        """The centre as a float64 array."""
        return np.asarray(self.center, dtype=np.float64)

    @property
    def linear(self) -> NDArray[np.float64]:
        """``matrix`` as a (3, 3) array."""
        return np.asarray(self.matrix, dtype=np.float64)

    @property
    def canonical(self) -> Truncus:
        """The canonical truncus (axis z, height 1) this is the image of."""
        return _canonical(self.r1, self.r2)

    @property
    def axis(self) -> NDArray[np.float64]:
        """From E2's centre to E1's."""
        return self.linear[:, 2].copy()

    def to_canonical(self, points: ArrayLike) -> NDArray[np.float64]:
        """Points in the canonical frame: ``matrix^-1 (p - center)``."""
        p = np.asarray(points, dtype=np.float64).reshape(-1, 3) - self.center_array
        return np.asarray(np.linalg.solve(self.linear, p.T).T, dtype=np.float64)

    def _normals_to_world(self, m: NDArray[np.float64]) -> NDArray[np.float64]:
        n = np.linalg.solve(self.linear.T, m.T).T  # M^-T m, row-wise
        return n / np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)

    # ------------------------------------------------------------ the primitive interface
    def signed_distance(self, points: ArrayLike) -> NDArray[np.float64]:
        """A signed distance estimate: the canonical one times the matrix's smallest singular value.

        Its sign is exact; its size is within the matrix's condition number of the true distance.
        """
        d = self.canonical.signed_distance(self.to_canonical(points))
        return d * float(np.linalg.svd(self.linear, compute_uv=False)[-1])

    def normals_at(self, points: ArrayLike) -> NDArray[np.float64]:
        """Outward unit normals at surface points (caps where the canonical point is on an end)."""
        q = self.to_canonical(self._points(points))
        t = self.canonical
        m = t.side_normals(q)
        tol = 1e-9
        m = np.where((q[:, 2] >= 0.5 - tol)[:, None], [0.0, 0.0, 1.0], m)
        m = np.where((q[:, 2] <= -0.5 + tol)[:, None], [0.0, 0.0, -1.0], m)
        return self._normals_to_world(m)

    def extent(self, n: ArrayLike) -> tuple[float, float]:
        """Exact extent ``(lo, hi)`` along the unit vector ``n``: the ends' ellipses' supports."""
        v = np.asarray(n, dtype=np.float64)
        M = self.linear
        c = float(self.center_array @ v)
        a = float(M[:, 2] @ v) / 2
        w = math.hypot(float(M[:, 0] @ v), float(M[:, 1] @ v))
        return min(c + a - self.r1 * w, c - a - self.r2 * w), max(c + a + self.r1 * w, c - a + self.r2 * w)

    def breakpoints(self, n: ArrayLike) -> NDArray[np.float64]:
        """Its extent, its end ellipses' centres and their lowest and highest points along ``n``
        (where an end starts or stops cutting the sections, or the apex of a cone is)."""
        v = np.asarray(n, dtype=np.float64)
        M = self.linear
        c = float(self.center_array @ v)
        a = float(M[:, 2] @ v) / 2
        w = math.hypot(float(M[:, 0] @ v), float(M[:, 1] @ v))
        return np.array([*self.extent(v), c + a, c - a, c + a - self.r1 * w, c + a + self.r1 * w,
                         c - a - self.r2 * w, c - a + self.r2 * w])

    @property
    def bounds(self) -> NDArray[np.float64]:
        """Axis-aligned bounds, shape (2, 3) (exact)."""
        ext = [self.extent(e) for e in np.eye(3)]
        return np.array([[e[0] for e in ext], [e[1] for e in ext]])

    @property
    def volume(self) -> float:
        """Exact volume: the canonical volume times ``|det matrix|``."""
        return self.canonical.volume * abs(float(np.linalg.det(self.linear)))

    def intersect_rays(self, origins: ArrayLike, directions: ArrayLike) -> RayHits:
        """Rays in the canonical frame (same parameters ``t``), normals mapped back."""
        o, d = _as_rays(origins, directions)
        M = self.linear
        ol = np.linalg.solve(M, (o - self.center_array).T).T
        dl = np.linalg.solve(M, d.T).T
        h = self.canonical.intersect_rays(ol, dl)
        hit = h.hit
        n_in = np.where(hit[:, None], self._normals_to_world(h.n_in), 0.0)
        n_out = np.where(hit[:, None], self._normals_to_world(h.n_out), 0.0)
        return RayHits(h.t_in, h.t_out, n_in, n_out)

    def to_polyhedron(self, resolution: int = DEFAULT_RESOLUTION) -> ConvexPolyhedron:
        """Inscribed polyhedron: the image of the canonical truncus's."""
        v = np.asarray(self.canonical.to_polyhedron(resolution).vertices)
        return ConvexPolyhedron(v @ self.linear.T + self.center_array)

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> Primitive:
        return EllipticTruncus.from_affine(self.canonical, A @ self.linear, A @ self.center_array + t)

    @staticmethod
    def from_affine(canonical: Truncus, M: NDArray[np.float64], c: NDArray[np.float64]) -> Primitive:
        """The image ``c + M y`` of the canonical truncus; a right circular truncus where it is one."""
        if _keeps_circles(M):
            k = 0.5 * float(np.linalg.norm(M[:, 0]) + np.linalg.norm(M[:, 1]))
            return Truncus(tuple(c), tuple(M[:, 2]), k * canonical.r1, k * canonical.r2)
        return EllipticTruncus(tuple(c), M, canonical.r1, canonical.r2)

    # ------------------------------------------------------------ the kind interface
    def _end_normal(self) -> NDArray[np.float64]:
        """The ends' planes' normal, not normalised: ``M^-T e_z``."""
        return np.linalg.inv(self.linear).T @ np.array([0.0, 0.0, 1.0])  # type: ignore[no-any-return]

    @property
    def area(self) -> float:
        """Exact surface area: its two elliptic ends and the lateral integral
        (:func:`~isocsg.kinds.patches.elliptic_lateral_area`)."""
        M = self.linear
        scale = abs(float(np.linalg.det(M))) * float(np.linalg.norm(self._end_normal()))
        cap = scale * math.pi * (self.r1**2 + self.r2**2)
        return cap + elliptic_lateral_area(M, float(self.r1), float(self.r2))

    def exact_form(self) -> AffineFrustum:
        """An :class:`~isocsg.kinds.forms.AffineFrustum` of its own matrix (never a right one)."""
        m = self.linear
        normal = np.cross(m[:, 0], m[:, 1])
        return AffineFrustum(self.center_array, m, self.r1, self.r2, normal / np.linalg.norm(normal), False)

    def is_prism_along(self, direction: NDArray[np.float64], tol: float = 1e-12) -> bool:
        """An upright elliptic cylinder along ``direction``."""
        return frustum_is_prism(self.exact_form(), np.asarray(direction, dtype=np.float64), tol)

    def flat_face_planes(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """The planes of its two ends."""
        M, c = self.linear, self.center_array
        nz = self._end_normal()
        nz = nz / np.linalg.norm(nz)
        return np.stack([nz, -nz]), np.array([nz @ (c + M[:, 2] / 2), -nz @ (c - M[:, 2] / 2)])

    def surface_patches(self, leaf: int) -> list[Patch]:
        """Its side and two elliptic ends (:func:`~isocsg.kinds.patches.affine_frustum_patches`)."""
        return affine_frustum_patches(leaf, self.center_array, self.linear, float(self.r1), float(self.r2))

    def leaf_row(self) -> LeafRow:
        """A :attr:`LeafForm.GENERIC` row about its centre."""
        return LeafRow(LeafForm.GENERIC, center=self.center_array)

    def section(self, frame: NDArray[np.float64], resolution: int, area_exact: bool = False) -> Polygon:
        """The plane section: the canonical truncus's section of the preimage plane, mapped back.

        The preimage of the plane ``o + a u + b v`` is ``ol + a ul + b vl`` (``ul = M^-1 u`` ...);
        its canonical section, in an orthonormal frame of that plane, maps to ``(a, b)`` by a 2x2
        linear map (so exact areas stay exact: an affine map keeps area ratios).
        """
        import shapely

        from .planar import EMPTY

        e, F = self, frame
        M = e.linear
        o, u, v = F[:3, 3], F[:3, 0], F[:3, 1]
        ol = np.linalg.solve(M, o - e.center_array)
        ul, vl = np.linalg.solve(M, u), np.linalg.solve(M, v)
        e1 = ul / np.linalg.norm(ul)
        e2 = vl - (vl @ e1) * e1
        e2 /= np.linalg.norm(e2)
        n = np.cross(e1, e2)
        Fl = np.eye(4)
        Fl[:3, 0], Fl[:3, 1], Fl[:3, 2], Fl[:3, 3] = e1, e2, n, ol
        poly = e.canonical.section(Fl, resolution, area_exact)
        if poly.is_empty:
            return EMPTY
        B = np.array([[ul @ e1, vl @ e1], [ul @ e2, vl @ e2]])  # (a, b) -> (x, y) in the local frame
        Binv = np.linalg.inv(B)
        out = shapely.transform(poly, lambda xy: xy @ Binv.T)
        # a sliver (a plane grazing an end) can come back crossing its own chord by a rounding error
        return out if out.is_valid else shapely.make_valid(out).buffer(0)  # type: ignore[no-any-return]

    def manifold(self, resolution: int, shapes: dict[tuple[Any, ...], Any] | None = None) -> Any:
        """manifold3d's truncus (vertices on the surface) mapped by ``[matrix | center]``."""
        solid = manifold3d_module().Manifold.cylinder(1.0, self.r2, self.r1, max(int(resolution), 3), True)
        return solid.transform(np.column_stack([self.linear, self.center_array]).tolist())

    def band_surface(
        self, lights: list[Any], contours: int, eye: NDArray[np.float64] | None, shininess: float,
        weights: tuple[float, float] = (1.0, 1.0), segments: int | None = None, *,
        hidden: tuple[Any, Any] | None = None,
    ) -> Surface:
        """Side and end meshes fine enough for every field (:mod:`isocsg.kinds.elliptic_bands`)."""
        from .elliptic_bands import elliptic_surface

        return elliptic_surface(self, lights, contours, eye, shininess, weights, segments)

    def to_openscad(self, digits: int | None = None, *, exact: bool = True) -> str:
        """The canonical truncus (unit height along z, E1 of radius r1 at z = +1/2) mapped by ``matrix``."""
        if digits is not None:
            body, k = truncus_body(self.r2, self.r1, digits)
            L = np.asarray(self.matrix, dtype=np.float64) * np.array([k, k, 1.0])
            return encoded(body, L, self.center_array, digits)
        m = np.eye(4)
        m[:3, :3] = np.asarray(self.matrix, dtype=np.float64)
        m[:3, 3] = self.center
        body = f"cylinder(h = 1, r1 = {num(self.r2)}, r2 = {num(self.r1)}, center = true);"
        return f"multmatrix({mat(m)}) {{ {body} }}"

    def to_dict(self) -> dict[str, Any]:
        """``{"elliptic_truncus": {"center", "matrix", "r1", "r2"}}``."""
        return {"elliptic_truncus": {"center": list(self.center), "matrix": [list(r) for r in self.matrix],
                                     "r1": self.r1, "r2": self.r2}}


def _keeps_circles(M: NDArray[np.float64]) -> bool:
    """Whether ``M`` maps the canonical (z-axis) truncus onto a right circular one."""
    u, v, a = M[:, 0], M[:, 1], M[:, 2]
    nu, nv, na = (float(np.linalg.norm(x)) for x in (u, v, a))
    tol = 1e-9
    return bool(
        abs(nu - nv) <= tol * max(nu, nv)
        and abs(u @ v) <= tol * nu * nv
        and abs(u @ a) <= tol * nu * na
        and abs(v @ a) <= tol * nv * na
    )
