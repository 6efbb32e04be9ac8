"""The truncus kind (the seed's generalised truncus) and its two named forms, cylinder and cone.

End E1 of radius ``r1`` is centred at ``center + axis / 2``, end E2 of radius ``r2`` at
``center - axis / 2``. Rays, distances (in the meridian half-plane), sections (the plane
cut of the lateral cone, solved per generator) and its OpenSCAD form are exact; its
bands are the seed's appendix construction (:mod:`isocsg.kinds.truncus_bands`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import (
    MAX_ABS_COORD,
    MIN_TRUNCUS_ASPECT,
    Vec3,
    length_floor,
    nonzero_vector3,
    points_array,
    scalar,
    vector3,
)
from ..errors import InvalidGeometryError
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
    _perpendicular_frame,
    _unit,
)
from .forms import AffineFrustum, frustum_is_prism
from .meshing import manifold3d_module, rotation_to_axis
from .patches import Patch, frustum_patches
from .registry import kind_class, register_kind
from .scad import encoded, frame, mat, num, translated, truncus_body

if TYPE_CHECKING:  # pragma: no cover
    from shapely.geometry import Polygon

    from ..bands.surface import Surface
    from .polyhedron import ConvexPolyhedron

__all__ = ["Cone", "Cylinder", "Truncus", "truncus_section"]




@register_kind("truncus", required=("center", "axis", "r1", "r2"))
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
    kind: ClassVar[str] = "truncus"

    if TYPE_CHECKING:  # the constructor as callers call it: array-likes, checked in __post_init__
        def __init__(self, center: ArrayLike, axis: ArrayLike, r1: float, r2: float) -> None: ...

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
        if height < MIN_TRUNCUS_ASPECT * big:
            raise InvalidGeometryError(
                f"{name}.axis must be at least {MIN_TRUNCUS_ASPECT:g} x the larger radius {big:g} long, "
                f"got length {height:g}"
            )
        if big < MIN_TRUNCUS_ASPECT * height:
            shown = "radius" if one_radius else ("r1" if r1 >= r2 else "r2")
            raise InvalidGeometryError(
                f"{name}.{shown} must be at least {MIN_TRUNCUS_ASPECT:g} x the height {height:g}, got {big:g}"
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

    def stacked(self, k: int) -> list[Truncus]:
        """``k`` trunci stacked along the axis, E1 first (the slices of a truncus near a point light)."""
        a = np.asarray(self.axis, dtype=np.float64)
        zs = np.linspace(0.5, -0.5, k + 1)
        radii = np.maximum(self.radius_at(zs * self.height), 0.0)
        # An apex stays an apex: the interpolation at an end of radius 0 may round to 1e-17.
        radii[0] = self.r1 if self.r1 == 0.0 else radii[0]
        radii[-1] = self.r2 if self.r2 == 0.0 else radii[-1]
        return [
            Truncus(self.center_array + 0.5 * (z0 + z1) * a, a * (z0 - z1), float(r0), float(r1))
            for z0, z1, r0, r1 in zip(zs[:-1], zs[1:], radii[:-1], radii[1:])
        ]

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

    def to_polyhedron(self, resolution: int = DEFAULT_RESOLUTION) -> ConvexPolyhedron:
        """Inscribed polyhedron with ``resolution`` points on each end circle."""
        # imported here: polyhedra register after this kind (the scene-file order)
        from .polyhedron import ConvexPolyhedron

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
        # an elliptic truncus, looked up by name: kinds/elliptic.py builds on this module
        elliptic = kind_class("elliptic_truncus")

        frame = np.column_stack([u, v, np.asarray(self.axis, dtype=np.float64)])  # canonical -> self
        image: Primitive = elliptic(tuple(c), A @ frame, self.r1, self.r2)
        return image

    # ------------------------------------------------------------ the kind interface
    def extent(self, n: ArrayLike) -> tuple[float, float]:
        """Exact extent along the unit vector ``n``: its end circles' support."""
        w = np.asarray(n, dtype=np.float64)
        an = float(self.unit_axis @ w)
        ext = math.sqrt(min(max(1.0 - an * an, 0.0), 1.0))
        c = float(self.center_array @ w)
        e1, e2 = c + an * self.height / 2, c - an * self.height / 2
        return min(e1 - self.r1 * ext, e2 - self.r2 * ext), max(e1 + self.r1 * ext, e2 + self.r2 * ext)

    def breakpoints(self, n: ArrayLike) -> NDArray[np.float64]:
        """Its extent, its end circles' centres and their lowest and highest points along ``n``."""
        w = np.asarray(n, dtype=np.float64)
        c, un = float(self.center_array @ w), float(self.unit_axis @ w)
        an = un * self.height / 2
        ext = math.sqrt(min(max(1.0 - un * un, 0.0), 1.0))
        return np.array([*self.extent(w), c + an, c - an, c + an - self.r1 * ext, c + an + self.r1 * ext,
                         c - an - self.r2 * ext, c - an + self.r2 * ext])

    def signed_distance(self, points: ArrayLike) -> NDArray[np.float64]:
        """Exact: the distance in the meridian half-plane to the truncus' trapezoid."""
        p = np.asarray(points, dtype=np.float64).reshape(-1, 3)
        prim = self
        s, rho, _ = _truncus_meridian(prim, p)
        h2, r1, r2 = prim.height / 2, prim.r1, prim.r2
        length = math.hypot(2 * h2, r1 - r2)
        side = (rho - prim.radius_at(s)) * (2 * h2) / length  # signed distance to the side line
        inside_d = np.maximum(np.maximum(s - h2, -s - h2), side)
        inside = inside_d <= 0.0
        out = inside_d.copy()
        if not inside.all():
            o = ~inside
            so, ro = s[o], rho[o]
            d1 = _segment_distance(so, ro, h2, -r1, h2, r1)
            d2 = _segment_distance(so, ro, -h2, -r2, -h2, r2)
            d3 = _segment_distance(so, ro, -h2, r2, h2, r1)
            out[o] = np.minimum(np.minimum(d1, d2), d3)
        return out  # type: ignore[no-any-return]

    def tangent_cone(self, points: NDArray[np.float64], tol: float) -> TangentCone:
        """Its ends, its side and, at an apex, a circular cone."""
        p = points
        prim = self
        m = len(p)
        a = prim.unit_axis
        s, rho, er = _truncus_meridian(prim, p)
        h2, k = prim.height / 2, prim.slope
        V = np.zeros((m, 3, 3))
        C = np.zeros((m, 3))
        valid = np.zeros((m, 3), dtype=bool)
        length = math.hypot(1.0, k)
        side = (rho - prim.radius_at(s)) / length
        V[:, 0] = a
        valid[:, 0] = np.abs(s - h2) <= tol
        V[:, 1] = -a
        valid[:, 1] = np.abs(s + h2) <= tol
        near_side = np.abs(side) <= tol
        V[:, 2] = (er - k * a) / length
        valid[:, 2] = near_side
        # the apex of a cone: a circular cone around the axis, half-angle beta
        apex_rows = near_side & (rho <= tol)
        for r_end, s_end, toward in ((prim.r1, h2, -a), (prim.r2, -h2, a)):
            if r_end == 0.0:
                at = apex_rows & (np.abs(s - s_end) <= tol + abs(k) * tol)
                if at.any():
                    beta = math.atan2(max(prim.r1, prim.r2), 2 * h2)
                    V[at, 2] = -toward
                    C[at, 2] = -math.cos(beta)
                    valid[at, 0 if s_end > 0 else 1] = False  # the apex has no cap
        return V, C, valid

    def section(self, frame: NDArray[np.float64], resolution: int, area_exact: bool = False) -> Polygon:
        """See :func:`truncus_section`."""
        return truncus_section(self, frame, resolution, area_exact)

    @property
    def area(self) -> float:
        """Exact surface area, ``pi ((r1 + r2) s + r1^2 + r2^2)`` with the slant ``s``."""
        r1, r2, h = float(self.r1), float(self.r2), float(self.height)
        return math.pi * ((r1 + r2) * math.hypot(r1 - r2, h) + r1 * r1 + r2 * r2)

    def exact_form(self) -> AffineFrustum:
        """A right :class:`~isocsg.kinds.forms.AffineFrustum`: two unit vectors across the axis, then the axis."""
        a = np.asarray(self.axis, dtype=np.float64)
        n = a / np.linalg.norm(a)
        e1 = np.cross(n, [1.0, 0.0, 0.0] if abs(n[0]) < 0.9 else [0.0, 1.0, 0.0])
        e1 /= np.linalg.norm(e1)
        return AffineFrustum(self.center_array, np.column_stack([e1, np.cross(n, e1), a]), self.r1, self.r2,
                             self.unit_axis, True)

    def is_prism_along(self, direction: NDArray[np.float64], tol: float = 1e-12) -> bool:
        """A cylinder along ``direction``."""
        return frustum_is_prism(self.exact_form(), np.asarray(direction, dtype=np.float64), tol)

    def flat_face_planes(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """The planes of its two ends."""
        a, c, h = self.unit_axis, self.center_array, float(self.height)
        return np.stack([a, -a]), np.array([a @ (c + a * h / 2), -a @ (c - a * h / 2)])

    def surface_patches(self, leaf: int) -> list[Patch]:
        """Its side swept along the axis and its end discs (:func:`~isocsg.kinds.patches.frustum_patches`)."""
        h, r1, r2 = float(self.height), float(self.r1), float(self.r2)
        return frustum_patches(leaf, self.center_array, self.unit_axis, h, r1, r2)

    def leaf_row(self) -> LeafRow:
        """A :attr:`LeafForm.FRUSTUM` row."""
        return LeafRow(LeafForm.FRUSTUM, center=self.center_array, axis=self.unit_axis, height=self.height,
                       r1=self.r1, r2=self.r2,
                       axis_vector=np.asarray(self.axis, dtype=np.float64))

    @classmethod
    def leaf_boxes(cls, leaves: Sequence[Primitive]) -> LeafBoxes:
        """Trunci, read from their parameters in one pass: bounds of the end circles, the centre and
        the larger end radius."""
        a = np.asarray([(*p.center, *p.axis, p.r1, p.r2) for p in leaves],  # type: ignore[attr-defined]
                       dtype=np.float64).reshape(-1, 8)
        c, ax, r1, r2 = a[:, :3], a[:, 3:6], a[:, 6:7], a[:, 7:8]
        u = ax / np.linalg.norm(ax, axis=1, keepdims=True)
        ext = np.sqrt(np.clip(1 - u**2, 0, 1))  # half-extent of a unit circle normal to the axis
        e1, e2 = c + ax / 2, c - ax / 2
        lo = np.minimum(e1 - r1 * ext, e2 - r2 * ext)
        hi = np.maximum(e1 + r1 * ext, e2 + r2 * ext)
        return lo, hi, np.zeros(len(a), np.bool_), c, np.maximum(r1, r2)[:, 0]

    def clipped_to_box(self, lo: NDArray[np.float64], hi: NDArray[np.float64]) -> Primitive:
        """The part of the axis within the box's extent along it (and within the box grown by the
        larger radius: any point of the truncus lies within that radius of its axis), with the
        radii there; itself when that part is the whole axis or empty."""
        corners = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
        u = self.unit_axis
        c = self.center_array
        s = (corners - c) @ u  # the box's extent along the axis
        half = 0.5 * self.height
        t0, t1 = _line_in_box(c, u, lo - max(self.r1, self.r2), hi + max(self.r1, self.r2))
        s1, s0 = min(half, float(s.max()), t1), max(-half, float(s.min()), t0)
        if s0 >= s1 or (s1 == half and s0 == -half):
            return self  # off the box altogether (pruned elsewhere), or within the slab
        centre = c + 0.5 * (s0 + s1) * u
        axis = (s1 - s0) * u
        if type(self) is Cylinder:
            return Cylinder(tuple(centre.tolist()), tuple(axis.tolist()), self.r1)
        r1, r0 = (max(float(r), 0.0) for r in self.radius_at(np.array([s1, s0])))
        r1 = self.r1 if s1 == half else r1
        r0 = self.r2 if s0 == -half else r0
        return Truncus(tuple(centre.tolist()), tuple(axis.tolist()), r1, r0)

    def part_index(self, points: NDArray[np.float64], normals: NDArray[np.float64]) -> NDArray[np.int64]:
        """0 on the side, 1 on the end E1 (at +axis/2), 2 on the end E2."""
        s = (points - self.center_array) @ self.unit_axis
        h2 = self.height / 2
        tol = 1e-9 * max(self.height, self.r1, self.r2)
        return np.where(s >= h2 - tol, 1, np.where(s <= -h2 + tol, 2, 0)).astype(np.int64)

    def manifold(self, resolution: int, shapes: dict[tuple[Any, ...], Any] | None = None) -> Any:
        """manifold3d's cylinder, turned onto the axis and moved."""
        # manifold3d's cylinder runs from radius_low at z=-h/2 to radius_high at z=+h/2;
        # the truncus's E2 (r2) is at -axis/2 and E1 (r1) at +axis/2.
        shapes = {} if shapes is None else shapes
        key = ("truncus", self.height, self.r1, self.r2, resolution)
        if key not in shapes:
            shapes[key] = manifold3d_module().Manifold.cylinder(self.height, self.r2, self.r1, resolution, True)
        R = rotation_to_axis(self.unit_axis)
        return shapes[key].transform(np.column_stack([R, self.center_array]).tolist())

    def band_surface(
        self, lights: list[Any], contours: int, eye: NDArray[np.float64] | None, shininess: float,
        weights: tuple[float, float] = (1.0, 1.0), segments: int | None = None, *,
        hidden: tuple[Any, Any] | None = None,
    ) -> Surface:
        """Side and end meshes (:func:`isocsg.kinds.truncus_bands.truncus_surface`), with at least
        ``segments`` generators (by default ``truncus.GENERATORS``); ends outside the box ``hidden``
        are not refined."""
        from .truncus_bands import GENERATORS, truncus_surface

        seg = GENERATORS if segments is None else segments
        return truncus_surface(self, lights, contours, eye=eye, shininess=shininess, weights=weights, segments=seg,
                               hidden=hidden)

    def contour_laminae(
        self, light: Any, contours: int,
    ) -> list[tuple[NDArray[np.float64], NDArray[np.float64], float, str]]:
        """The appendix's quads and end laminae."""
        from .truncus_bands import truncus_laminae

        return truncus_laminae(self, light, contours)

    def contour_family(
        self, light: Any, contours: int,
    ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
        """The quads' planes: cosine-spaced offsets across the axis, the seed's levels."""
        from ..bands.lights import light_axis
        from .truncus_bands import light_frame, paper_levels

        ct = self.center_array
        ln = light_axis(ct, light)  # a directional light's unit direction, else towards the light
        w, _ = light_frame(self.unit_axis, ln)
        r = max(self.r1, self.r2)
        offsets = float(w @ ct) + np.cos(np.pi * np.arange(contours + 1) / contours) * r
        return w, offsets, paper_levels(self, light, contours)

    def to_openscad(self, digits: int | None = None, *, exact: bool = True) -> str:
        """A centred ``cylinder(h, r1, r2)`` turned onto the axis and moved."""
        axis = np.asarray(self.axis, dtype=np.float64)
        if digits is not None:
            body, k = truncus_body(self.r2, self.r1, digits)
            R = np.eye(3) if axis[0] == 0 and axis[1] == 0 and axis[2] > 0 else frame(axis, np.zeros(3))[:3, :3]
            return encoded(body, R * np.array([k, k, self.height]), self.center_array, digits)
        # OpenSCAD's r1 is at z = 0, the truncus' r1 at center + axis / 2: the cylinder's +z runs along the axis.
        body = f"cylinder(h = {num(self.height)}, r1 = {num(self.r2)}, r2 = {num(self.r1)}, center = true);"
        if axis[0] == 0 and axis[1] == 0 and axis[2] > 0:
            return translated(np.asarray(self.center), body)
        return f"multmatrix({mat(frame(axis, np.asarray(self.center)))}) {{ {body} }}"

    def to_dict(self) -> dict[str, Any]:
        """``{"truncus": {"center", "axis", "r1", "r2"}}``."""
        return {"truncus": {"center": list(self.center), "axis": list(self.axis), "r1": self.r1, "r2": self.r2}}


@register_kind("cylinder", required=("center", "axis", "radius"))
class Cylinder(Truncus):
    """A right circular cylinder: a :class:`Truncus` with ``r1 == r2 == radius``.

    Examples
    --------
    >>> c = Cylinder((0, 0, 0), (0, 0, 2), 0.5)
    >>> c.r1 == c.r2 == c.radius == 0.5
    True
    """

    __slots__ = ()
    kind: ClassVar[str] = "cylinder"

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


@register_kind("cone", required=("center", "axis", "radius"))
class Cone(Truncus):
    """A right circular cone: base of ``radius`` at ``center + axis/2`` (E1), apex at ``center - axis/2``.

    Examples
    --------
    >>> k = Cone((0, 0, 0), (0, 0, 1), 1.0)
    >>> (k.r1, k.r2)
    (1.0, 0.0)
    """

    __slots__ = ()
    kind: ClassVar[str] = "cone"

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


def _truncus_meridian(
    prim: Truncus, p: NDArray[np.float64],
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Axial coordinate s, radial distance rho, unit radial direction of points (truncus frame)."""
    a = prim.unit_axis
    rel = p - prim.center_array
    s = rel @ a
    radial = rel - s[:, None] * a
    rho = np.sqrt(np.einsum("ij,ij->i", radial, radial))
    er = np.divide(radial, rho[:, None], out=np.zeros_like(radial), where=rho[:, None] > 0)
    return s, rho, er


def _segment_distance(
    px: NDArray[np.float64], py: NDArray[np.float64], ax: float, ay: float, bx: float, by: float,
) -> NDArray[np.float64]:
    """Distance of 2D points to one segment."""
    dx, dy = bx - ax, by - ay
    ll = dx * dx + dy * dy
    t = np.clip(((px - ax) * dx + (py - ay) * dy) / ll, 0.0, 1.0) if ll > 0 else np.zeros_like(px)
    return np.hypot(px - (ax + t * dx), py - (ay + t * dy))


def truncus_section(t: Truncus, F: NDArray[np.float64], resolution: int, area_exact: bool = False) -> Polygon:
    """The plane cut of the lateral cone, parametrised by the generator angle (each generator meets
    the plane in one point, in closed form), restricted to the slab between the end planes; the
    corners on the end circles are solved exactly. Every vertex lies on the true boundary."""
    from .planar import EMPTY, hull_polygon, refined_parameters, simpson_points, to2d

    o, n = F[:3, 3], F[:3, 2]
    a = t.unit_axis
    helper = np.array([1.0, 0.0, 0.0]) if abs(a[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    e1 = np.cross(a, helper)
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(a, e1)
    c = t.center_array
    h2 = t.height / 2
    k = t.slope
    r0 = float(t.radius_at(0.0))
    D = float(n @ (c - o))
    na, p1, p2 = float(n @ a), float(n @ e1), float(n @ e2)
    rho = math.hypot(p1, p2)
    phi0 = math.atan2(p2, p1)
    size = max(t.height, t.r1, t.r2)
    eps = 1e-12 * size

    def surface(sig: NDArray[np.float64], phi: NDArray[np.float64]) -> NDArray[np.float64]:
        r = r0 + k * sig
        g = np.cos(phi)[:, None] * e1 + np.sin(phi)[:, None] * e2
        return c + sig[:, None] * a + r[:, None] * g

    def sigma(phi: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
        ng = rho * np.cos(phi - phi0)
        den = na + k * ng
        ok = np.abs(den) > 1e-14
        with np.errstate(divide="ignore", invalid="ignore"):
            s = np.where(ok, -(D + r0 * ng) / np.where(ok, den, 1.0), np.inf)
        return s, ok & (np.abs(s) <= h2 + eps)

    pts: list[NDArray[np.float64]] = []
    breaks: list[float] = []
    # corners: generators crossing the plane exactly on an end circle
    for s_end in (h2, -h2):
        r_end = r0 + k * s_end
        lin = D + s_end * na
        if r_end <= 1e-15 * size:
            if abs(lin) <= eps:  # the plane passes through the apex
                pts.append(c + s_end * a)
            continue
        if rho <= 1e-14:
            continue  # plane parallel to the ends: the curve samples give the circle
        q = -lin / (r_end * rho)
        if abs(q) <= 1.0:
            dphi = math.acos(q)
            ph = np.array([phi0 + dphi, phi0 - dphi])
            pts.append(surface(np.full(2, s_end), ph))
            breaks.extend(ph.tolist())
    # asymptotes: generators parallel to the plane (sigma -> infinity)
    if abs(k) > 0 and rho > 1e-14 and abs(na / (k * rho)) <= 1.0:
        dphi = math.acos(-na / (k * rho))
        breaks.extend([phi0 + dphi, phi0 - dphi])
    # sample each valid phi interval between the breakpoints
    two_pi = 2.0 * math.pi
    if breaks:
        b = np.sort(np.mod(np.asarray(breaks) - phi0, two_pi)) + phi0
        b = np.append(b, b[0] + two_pi)
        intervals = [(lo, hi) for lo, hi in zip(b[:-1], b[1:]) if hi - lo > 1e-15]
    else:
        intervals = [(phi0, phi0 + two_pi)]
    for lo, hi in intervals:
        _, ok_mid = sigma(np.array([0.5 * (lo + hi)]))
        if not ok_mid[0]:
            continue
        if not breaks:
            _, ok_all = sigma(np.linspace(lo, hi, 16))
            if not ok_all.all():
                continue
        m = max(int(math.ceil(resolution * (hi - lo) / two_pi / 2)), 2)
        ph = refined_parameters(lambda x: surface(np.clip(sigma(x)[0], -h2, h2), x), lo, hi, m,
                                4 * math.pi / resolution)
        P = surface(np.clip(sigma(ph)[0], -h2, h2), ph)
        pts.append(simpson_points(P, closed=False) if area_exact else P)
    if not pts:
        return EMPTY
    return hull_polygon(to2d(np.vstack(pts), F))


def _line_in_box(
    c: NDArray[np.float64], u: NDArray[np.float64], lo: NDArray[np.float64], hi: NDArray[np.float64],
) -> tuple[float, float]:
    """The parameters ``[t0, t1]`` where the line ``c + t u`` lies in the box ``[lo, hi]`` (slabs;
    an empty range, ``t0 > t1``, when it misses the box)."""
    t0, t1 = -np.inf, np.inf
    for k in range(3):
        if u[k] != 0.0:
            a, b = (lo[k] - c[k]) / u[k], (hi[k] - c[k]) / u[k]
            t0, t1 = max(t0, min(a, b)), min(t1, max(a, b))
        elif not lo[k] <= c[k] <= hi[k]:
            return np.inf, -np.inf
    return float(t0), float(t1)
