"""The torus: a circle of radius ``minor`` revolved about an axis at distance ``major``.

A :class:`Torus` has a ``center``, a unit ``axis`` and two radii, ``major`` (R, the
distance of the tube's centre circle from the axis) and ``minor`` (r, the tube's
radius). Its points are those within ``r`` of the centre circle. It is the first
non-convex kind: a ray meets it in up to two depth intervals (``max_intervals = 2``).

Only ring tori are accepted, ``minor < major``: a spindle or horn torus (``minor >=
major``) is refused with an :class:`~isocsg.errors.InvalidGeometryError` naming
``Torus.minor``, as OpenSCAD refuses a ``rotate_extrude`` whose profile crosses the axis.

Every computation happens in the torus's own frame, ``q = p - center`` with
``z = q . axis`` and ``rho = |q - z axis|``, scaled by ``major``:

- signed distance: ``sqrt((rho - R)^2 + z^2) - r``, exact everywhere;
- rays: the quartic ``(|x|^2 + R^2 - r^2)^2 = 4 R^2 (x_1^2 + x_2^2)`` along the ray,
  written from the ray's point nearest the centre in units of ``R`` (so that its
  coefficients are O(1) whatever the eye's distance), solved by the eigenvalues of its
  companion matrix, polished by Newton steps, and paired into intervals by testing
  the midpoints between consecutive roots with the exact distance (so a tangent ray's
  double root gives a touching or an empty interval, never a misplaced one);
- sections: exact annuli across the axis and exact pairs of discs through it; any other
  plane (spiric and Villarceau sections) is polygonised by scanlines whose end points
  are exact ray intervals, joined into trapezoids: vertices exactly on the curve, area
  error O(h^2) for line spacing ``h`` (``h`` = the section's width / (2 resolution));
- meshes: a (u, v) grid with vertices on the surface; shadows: ``convex_pieces`` are the
  convex hulls of consecutive tube cross-section polygons (see :meth:`Torus.convex_pieces`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import MAX_ABS_COORD, MIN_ASPECT, Vec3, length_floor, scalar, vector3
from ..errors import InvalidGeometryError
from .base import DEFAULT_RESOLUTION, LeafForm, LeafRow, Primitive, RayHits, _as_rays, _perpendicular_frame
from .forms import RingTorus
from .patches import Patch, torus_patches
from .polyhedron import ConvexPolyhedron
from .registry import register_kind
from .scad import encoded, frame, mat, num

if TYPE_CHECKING:  # pragma: no cover
    import trimesh
    from shapely.geometry import Polygon

    from ..bands.surface import Surface

__all__ = ["Torus", "torus_quartic_roots"]

#: Newton steps that polish each root of the quartic.
NEWTON_STEPS = 3


def torus_quartic_roots(o: NDArray[np.float64], d: NDArray[np.float64], k: float) -> NDArray[np.float64]:
    """Real roots, sorted and NaN-padded ``(n, 4)``, of unit rays ``o + t d`` against the torus of
    major radius 1 and minor radius ``k`` about the z axis through the origin.

    ``o`` should be the ray's point nearest the origin (coefficients O(1)). The quartic
    ``t^4 + c3 t^3 + c2 t^2 + c1 t + c0`` is solved by its companion matrix's eigenvalues;
    roots with an imaginary part below 1e-6 keep their real part and are polished by Newton.
    """
    b = np.einsum("ij,ij->i", o, d)
    c = np.einsum("ij,ij->i", o, o)
    kk = c + 1.0 - k * k
    dxy = d[:, 0] ** 2 + d[:, 1] ** 2
    oxy = o[:, 0] * d[:, 0] + o[:, 1] * d[:, 1]
    rxy = o[:, 0] ** 2 + o[:, 1] ** 2
    c3 = 4.0 * b
    c2 = 4.0 * b * b + 2.0 * kk - 4.0 * dxy
    c1 = 4.0 * b * kk - 8.0 * oxy
    c0 = kk * kk - 4.0 * rxy
    n = len(o)
    comp = np.zeros((n, 4, 4))
    comp[:, 1, 0] = comp[:, 2, 1] = comp[:, 3, 2] = 1.0
    comp[:, 0, 3], comp[:, 1, 3], comp[:, 2, 3], comp[:, 3, 3] = -c0, -c1, -c2, -c3
    ev = np.linalg.eigvals(comp) if n else np.zeros((0, 4), dtype=complex)
    real = np.abs(ev.imag) <= 1e-6 * np.maximum(1.0, np.abs(ev.real))
    t = np.where(real, ev.real, np.nan)
    for _ in range(NEWTON_STEPS):
        p = (((t + c3[:, None]) * t + c2[:, None]) * t + c1[:, None]) * t + c0[:, None]
        dp = ((4.0 * t + 3.0 * c3[:, None]) * t + 2.0 * c2[:, None]) * t + c1[:, None]
        with np.errstate(divide="ignore", invalid="ignore"):
            step = p / dp
        ok = np.isfinite(step) & (np.abs(step) < 1e-3)  # near a double root Newton may wander: keep t
        t = np.where(ok, t - step, t)
    return np.sort(t, axis=1)


@register_kind("torus", required=("center", "axis", "major", "minor"))
@dataclass(frozen=True, slots=True)
class Torus(Primitive):
    """A solid ring torus: the points within ``minor`` of a circle of radius ``major``.

    Parameters
    ----------
    center : array_like, shape (3,)
        The centre of the hole.
    axis : array_like, shape (3,)
        The axis of revolution (non-zero; stored normalised).
    major : float
        R > 0, the radius of the tube's centre circle.
    minor : float
        r > 0, the tube's radius; ``minor < major`` (a ring torus).

    Raises
    ------
    InvalidGeometryError
        On non-finite values, a zero axis, radii that are not > 0, ``minor >= major``
        (spindle and horn tori are not supported), or ``minor`` below ``MIN_ASPECT`` x ``major``.

    Examples
    --------
    >>> t = Torus((0, 0, 0), (0, 0, 1), 2.0, 0.5)
    >>> round(t.volume, 6), t.contains([[2, 0, 0], [0, 0, 0]]).tolist()
    (9.869604, [True, False])
    """

    center: Vec3
    axis: Vec3
    major: float
    minor: float
    kind: ClassVar[str] = "torus"
    convex: ClassVar[bool] = False
    max_intervals: ClassVar[int] = 2

    if TYPE_CHECKING:  # the constructor as callers call it: array-likes, checked in __post_init__
        def __init__(self, center: ArrayLike, axis: ArrayLike, major: float, minor: float) -> None: ...

    def __post_init__(self) -> None:
        center = vector3("Torus.center", self.center)
        axis = vector3("Torus.axis", self.axis)
        norm = math.sqrt(sum(a * a for a in axis))
        if not norm > 0.0:
            raise InvalidGeometryError(f"Torus.axis must be a non-zero vector, got {axis}")
        major = scalar("Torus.major", self.major, low=0.0)
        minor = scalar("Torus.minor", self.minor, low=0.0)
        if major > MAX_ABS_COORD:
            raise InvalidGeometryError(f"Torus.major must be <= {MAX_ABS_COORD:g}, got {major:g}")
        floor = length_floor(center)
        if minor < floor:
            raise InvalidGeometryError(
                f"Torus.minor must be >= {floor:g} (the smallest length at this position), got {minor:g}"
            )
        if minor >= major:
            raise InvalidGeometryError(
                "Torus.minor must be < Torus.major (a ring torus; spindle and horn tori are not supported), "
                f"got minor {minor:g} >= major {major:g}"
            )
        if minor < MIN_ASPECT * major:
            raise InvalidGeometryError(f"Torus.minor must be at least {MIN_ASPECT:g} x Torus.major, got {minor:g}")
        unit = tuple(float(a / norm) for a in axis)
        object.__setattr__(self, "center", center)
        object.__setattr__(self, "axis", unit)
        object.__setattr__(self, "major", major)
        object.__setattr__(self, "minor", minor)

    # ------------------------------------------------------------ frame
    @property
    def center_array(self) -> NDArray[np.float64]:
        """The centre as a float64 array."""
        return np.asarray(self.center, dtype=np.float64)

    @property
    def axis_array(self) -> NDArray[np.float64]:
        """The unit axis as a float64 array."""
        return np.asarray(self.axis, dtype=np.float64)

    @property
    def rotation(self) -> NDArray[np.float64]:
        """A rotation whose columns ``e1, e2, axis`` are the torus's own frame."""
        w = self.axis_array
        e1, e2 = _perpendicular_frame(w)
        return np.column_stack([e1, e2, w])

    def to_local(self, points: ArrayLike) -> NDArray[np.float64]:
        """Points in the torus's own frame (axis along z, centre at the origin), unscaled."""
        p = np.asarray(points, dtype=np.float64).reshape(-1, 3) - self.center_array
        return p @ self.rotation  # type: ignore[no-any-return]

    def _rho_z(self, points: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
        q = np.asarray(points, dtype=np.float64).reshape(-1, 3) - self.center_array
        z = q @ self.axis_array
        radial = q - z[:, None] * self.axis_array
        return np.linalg.norm(radial, axis=1), z, radial

    # ------------------------------------------------------------ geometry
    @property
    def bounds(self) -> NDArray[np.float64]:
        """Exact axis-aligned bounds, shape (2, 3): ``R sqrt(1 - w_i^2) + r`` about the centre."""
        w = self.axis_array
        ext = self.major * np.sqrt(np.clip(1.0 - w * w, 0.0, 1.0)) + self.minor
        return np.stack([self.center_array - ext, self.center_array + ext])

    def extent(self, n: ArrayLike) -> tuple[float, float]:
        """Exact extent along the unit vector ``n`` (support: ``R |n x w| + r`` about the centre)."""
        v = np.asarray(n, dtype=np.float64)
        c = float(self.center_array @ v)
        wn = float(self.axis_array @ v)
        h = self.major * math.sqrt(max(0.0, float(v @ v) - wn * wn)) + self.minor
        return c - h, c + h

    def breakpoints(self, n: ArrayLike) -> NDArray[np.float64]:
        """The heights of the four critical points of ``x . n`` on the surface, ``c.n +- R s +- r``
        with ``s = |n x axis|`` (extent, and the saddles where sections change topology)."""
        v = np.asarray(n, dtype=np.float64)
        c = float(self.center_array @ v)
        wn = float(self.axis_array @ v)
        s = self.major * math.sqrt(max(0.0, float(v @ v) - wn * wn))
        return np.unique(np.array([c - s - self.minor, c - s + self.minor, c + s - self.minor, c + s + self.minor]))

    @property
    def volume(self) -> float:
        """Exact volume (Pappus): ``2 pi^2 R r^2``."""
        return 2.0 * math.pi**2 * self.major * self.minor**2

    # ------------------------------------------------------------ membership
    def signed_distance(self, points: ArrayLike) -> NDArray[np.float64]:
        """Exact signed distance: ``sqrt((rho - R)^2 + z^2) - r``."""
        rho, z, _ = self._rho_z(points)
        return np.hypot(rho - self.major, z) - self.minor  # type: ignore[no-any-return]

    def normals_at(self, points: ArrayLike) -> NDArray[np.float64]:
        """Outward unit normals: from the nearest point of the centre circle towards the point."""
        p = np.asarray(points, dtype=np.float64).reshape(-1, 3)
        rho, _, radial = self._rho_z(p)
        e1 = self.rotation[:, 0]
        dirs = np.where((rho > 0)[:, None], radial / np.maximum(rho, 1e-300)[:, None], e1)
        n = p - self.center_array - self.major * dirs
        return n / np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)  # type: ignore[no-any-return]

    # ------------------------------------------------------------ rays
    def ray_intervals(self, origins: ArrayLike, directions: ArrayLike) -> NDArray[np.float64]:
        """Every depth interval (at most two) of each ray in the torus, ``(n, 2, 2)``, NaN for none.

        See the module docstring for the solver; ``t`` is in units of each direction's length.
        """
        o, d = _as_rays(origins, directions)
        R = self.major
        dn = np.linalg.norm(d, axis=1)
        good = dn > 0
        du = np.where(good[:, None], d / np.where(good, dn, 1.0)[:, None], np.array([0.0, 0.0, 1.0]))
        Q = self.rotation
        ol = ((o - self.center_array) @ Q) / R
        dl = du @ Q
        t0 = -np.einsum("ij,ij->i", ol, dl)  # the point nearest the centre
        near = ol + t0[:, None] * dl
        k = self.minor / R
        roots = torus_quartic_roots(near, dl, k)
        # pair the roots: a segment between consecutive roots is inside where its midpoint is
        lo, hi = roots[:, :-1], roots[:, 1:]
        mid = 0.5 * (lo + hi)
        pts = near[:, None, :] + np.where(np.isfinite(mid), mid, 0.0)[:, :, None] * dl[:, None, :]
        sd = np.hypot(np.hypot(pts[..., 0], pts[..., 1]) - 1.0, pts[..., 2]) - k
        inside = np.isfinite(mid) & (sd < 0)
        out = np.full((len(o), 2, 2), np.nan)
        count = np.zeros(len(o), dtype=np.int64)
        start = np.full(len(o), np.nan)
        for j in range(3):  # runs of inside segments become intervals
            opening = inside[:, j] & ~np.isfinite(start)
            start = np.where(opening, lo[:, j], start)
            closing = inside[:, j] & ~inside[:, j + 1] if j < 2 else inside[:, j]
            rows = np.nonzero(closing & (count < 2))[0]
            out[rows, count[rows], 0] = start[rows]
            out[rows, count[rows], 1] = hi[rows, j]
            count[rows] += 1
            start = np.where(closing, np.nan, start)
        scale = (R / np.where(good, dn, 1.0))[:, None, None]
        out = (out + t0[:, None, None]) * scale
        out[~good] = np.nan
        return out

    def intersect_rays(self, origins: ArrayLike, directions: ArrayLike) -> RayHits:
        """The first depth interval of each ray with the normals at its ends (:meth:`ray_intervals`)."""
        return self.first_interval_hits(origins, directions)

    # ------------------------------------------------------------ sections
    @property
    def area(self) -> float:
        """Exact surface area, 4 pi^2 R r."""
        return 4.0 * math.pi**2 * float(self.major) * float(self.minor)

    def exact_form(self) -> RingTorus:
        """A :class:`~isocsg.kinds.forms.RingTorus`."""
        return RingTorus(self.center_array, np.asarray(self.axis, dtype=np.float64), self.major, self.minor)

    def surface_patches(self, leaf: int) -> list[Patch]:
        """Rings about the axis, swept by the tube's angle (:func:`~isocsg.kinds.patches.torus_patches`)."""
        return torus_patches(leaf, self.center_array, np.asarray(self.axis, dtype=np.float64), float(self.major),
                             float(self.minor))

    def leaf_row(self) -> LeafRow:
        """A :attr:`LeafForm.GENERIC` row about its centre."""
        return LeafRow(LeafForm.GENERIC, center=self.center_array)

    def section(self, frame: NDArray[np.float64], resolution: int, area_exact: bool = False) -> Polygon:
        """The section by the plane of ``frame`` as a shapely polygon (with holes).

        Exact circles (as :func:`~isocsg.kinds.planar.circle_ring` polygons, inscribed or of the
        exact area) for planes across the axis (an annulus) and through it (two discs); any other
        plane by scanlines (see the module docstring): ``2 resolution`` lines across the
        section, each line's end points exact, consecutive lines joined by trapezoids.
        """
        import shapely

        from .planar import EMPTY, circle_ring

        F = np.asarray(frame, dtype=np.float64)
        o, u, v, n = F[:3, 3], F[:3, 0], F[:3, 1], F[:3, 2]
        c, w, R, r = self.center_array, self.axis_array, self.major, self.minor
        res = max(int(resolution), 8)
        wn = float(w @ n)
        h = float((o - c) @ n)  # the plane is x . n = c . n + h
        c2 = np.array([(c - o) @ u, (c - o) @ v])
        if abs(abs(wn) - 1.0) <= 1e-12:  # across the axis: an annulus
            z = h * wn
            if abs(z) >= r:
                return EMPTY
            s = math.sqrt(r * r - z * z)
            rings = circle_ring(np.array([c2, c2]), np.array([R + s, R - s]), res, area_exact)
            return shapely.Polygon(rings[0], [rings[1][::-1]])
        if abs(wn) <= 1e-12 and abs(h) <= 1e-12 * (R + r):  # through the axis: two discs
            e = np.cross(w, n)
            e2 = np.array([e @ u, e @ v])
            e2 /= np.linalg.norm(e2)
            rings = circle_ring(np.array([c2 + R * e2, c2 - R * e2]), np.array([r, r]), res, area_exact)
            return shapely.MultiPolygon([shapely.Polygon(rings[0]), shapely.Polygon(rings[1])])
        return self._scanline_section(o, u, v, res)

    def _scanline_section(
        self, o: NDArray[np.float64], u: NDArray[np.float64], v: NDArray[np.float64], res: int
    ) -> Any:
        import shapely

        from .planar import EMPTY

        lo_v, hi_v = self.extent(v)
        lo_u, _ = self.extent(u)
        lines = 2 * res
        ys = np.linspace(lo_v - float(o @ v), hi_v - float(o @ v), lines + 2)[1:-1]
        start = float(lo_u - o @ u) - 1.0
        origins = o + start * u + ys[:, None] * v
        iv = self.ray_intervals(origins, np.broadcast_to(u, origins.shape)) + start
        count = np.sum(np.isfinite(iv[:, :, 0]), axis=1)
        polys = []
        for k in range(lines - 1):
            a, b = count[k], count[k + 1]
            y0, y1 = ys[k], ys[k + 1]
            if a == b:
                for i in range(a):
                    (p0, p1), (q0, q1) = iv[k, i], iv[k + 1, i]
                    polys.append(shapely.Polygon([(p0, y0), (p1, y0), (q1, y1), (q0, y1)]))
                continue
            ym = 0.5 * (y0 + y1)
            for i in range(a):
                polys.append(shapely.box(iv[k, i, 0], y0, iv[k, i, 1], ym))
            for i in range(b):
                polys.append(shapely.box(iv[k + 1, i, 0], ym, iv[k + 1, i, 1], y1))
        polys = [p for p in polys if p.area > 0]
        if not polys:
            return EMPTY
        return shapely.union_all(polys)

    # ------------------------------------------------------------ meshes and shadows
    def _grid(self, n_u: int, n_v: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Surface points (relative to the centre) and normals of an ``n_u x n_v`` (u, v) grid."""
        Q = self.rotation
        uu = 2.0 * np.pi * np.arange(n_u) / n_u
        vv = 2.0 * np.pi * np.arange(n_v) / n_v
        ring = np.cos(uu)[:, None] * Q[:, 0] + np.sin(uu)[:, None] * Q[:, 1]  # (n_u, 3)
        nrm = np.cos(vv)[None, :, None] * ring[:, None, :] + np.sin(vv)[None, :, None] * Q[:, 2]
        pts = self.major * ring[:, None, :] + self.minor * nrm
        return pts.reshape(-1, 3), nrm.reshape(-1, 3)

    @staticmethod
    def _grid_triangles(n_u: int, n_v: int) -> NDArray[np.int64]:
        """Triangles of the periodic (u, v) grid, counter-clockwise seen from outside."""
        i, j = np.meshgrid(np.arange(n_u), np.arange(n_v), indexing="ij")
        a = i * n_v + j
        b = ((i + 1) % n_u) * n_v + j
        cc = ((i + 1) % n_u) * n_v + (j + 1) % n_v
        d = i * n_v + (j + 1) % n_v
        tri = np.concatenate([np.stack([a, b, cc], -1).reshape(-1, 3), np.stack([a, cc, d], -1).reshape(-1, 3)])
        return tri.astype(np.int64)

    def _mesh_sizes(self, resolution: int) -> tuple[int, int]:
        res = max(int(resolution), 8)
        n_v = max(res // 2, 8)
        n_u = max(int(math.ceil(n_v * min((self.major + self.minor) / self.minor, 8.0))), res)
        return n_u, n_v

    def to_trimesh(self, resolution: int = DEFAULT_RESOLUTION) -> trimesh.Trimesh:
        """A closed, watertight triangle mesh with vertices on the surface (``resolution`` vertices
        per turn around the axis at least, ``resolution / 2`` around the tube)."""
        import trimesh

        n_u, n_v = self._mesh_sizes(resolution)
        pts, _ = self._grid(n_u, n_v)
        return trimesh.Trimesh(pts + self.center_array, self._grid_triangles(n_u, n_v), process=False)

    def manifold(self, resolution: int, shapes: dict[tuple[Any, ...], Any] | None = None) -> Any:
        """The grid mesh of :meth:`to_trimesh` as a manifold3d ``Manifold`` (double precision)."""
        from .meshing import manifold3d_module

        m3d = manifold3d_module()
        n_u, n_v = self._mesh_sizes(resolution)
        pts, _ = self._grid(n_u, n_v)
        tri = self._grid_triangles(n_u, n_v)
        mesh = m3d.Mesh(vert_properties=np.ascontiguousarray(pts + self.center_array, dtype=np.float32),
                        tri_verts=np.ascontiguousarray(tri, dtype=np.uint32))
        return m3d.Manifold(mesh)

    def to_polyhedron(self, resolution: int = DEFAULT_RESOLUTION) -> ConvexPolyhedron:
        """The convex hull of the torus's mesh vertices (a non-convex kind: this hull contains the
        hole; see :meth:`convex_pieces` for the solid itself)."""
        n_u, n_v = self._mesh_sizes(resolution)
        pts, _ = self._grid(n_u, n_v)
        return ConvexPolyhedron(pts + self.center_array)  # type: ignore[arg-type]

    def convex_pieces(self, resolution: int = DEFAULT_RESOLUTION) -> list[ConvexPolyhedron]:
        """The shadows' occluders: ``m = max(6, resolution // 2)`` ring sectors, each the convex hull
        of two consecutive tube cross-sections, regular ``m``-gons inscribed in the tube's circles.

        Their vertices lie on the surface. The union lies inside the torus except that each
        sector's chords cut across the hole side: it reaches at most
        ``(R - r) (1 - cos(pi / m))`` beyond the surface there; elsewhere it misses at most the
        sag ``r (1 - cos(pi / m))`` of the tube polygons and ``(R + r) (1 - cos(pi / m))`` of
        the outer chords.
        """
        m = max(6, int(resolution) // 2)
        pts, _ = self._grid(m, m)
        pts = pts.reshape(m, m, 3) + self.center_array
        return [ConvexPolyhedron(np.vstack([pts[i], pts[(i + 1) % m]])) for i in range(m)]  # type: ignore[arg-type]

    # ------------------------------------------------------------ bands
    def band_surface(
        self, lights: list[Any], contours: int, eye: NDArray[np.float64] | None, shininess: float,
        weights: tuple[float, float] = (1.0, 1.0), segments: int | None = None, *,
        hidden: tuple[Any, Any] | None = None,
    ) -> Surface:
        """A (u, v) grid fine enough for every field (:func:`~isocsg.kinds.torus_bands.torus_surface`)."""
        from .torus_bands import torus_surface

        return torus_surface(self, lights, contours, eye, shininess, weights)

    # ------------------------------------------------------------ files
    def to_dict(self) -> dict[str, Any]:
        """``{"torus": {"center", "axis", "major", "minor"}}``."""
        fields = {"center": list(self.center), "axis": list(self.axis), "major": self.major, "minor": self.minor}
        return {"torus": fields}

    def to_openscad(self, digits: int | None = None, *, exact: bool = True) -> str:
        """``rotate_extrude() translate([R, 0]) circle(r)`` under the frame taking z to the axis."""
        m = frame(self.axis_array, self.center_array)
        body = f"rotate_extrude() translate([{num(self.major)}, 0]) circle(r = {num(self.minor)});"
        if digits is not None:  # the radii's digits are kept: short radii come through unchanged
            return encoded(body, m[:3, :3], self.center_array, digits)
        return f"multmatrix({mat(m)}) {{ {body} }}"

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> Primitive:
        """Rigid maps and uniform scales (with reflections) keep a torus; other maps are refused. A map
        within :data:`~isocsg.kinds.affine.SIMILARITY_TOL_DIGITS` of a similarity (an OpenSCAD
        ``multmatrix`` of a turn, written with 6 digits) counts as one."""
        from .affine import SIMILARITY_TOL_DIGITS, similarity_factor

        k = similarity_factor(A, SIMILARITY_TOL_DIGITS)
        if k is None:
            raise InvalidGeometryError(
                "a Torus can only be moved, turned, mirrored or scaled uniformly: a non-uniform scale or shear "
                "does not keep it a torus"
            )
        axis = A @ self.axis_array
        center = tuple(A @ self.center_array + t)
        return Torus(center, tuple(axis / np.linalg.norm(axis)), k * self.major, k * self.minor)  # type: ignore[arg-type]
