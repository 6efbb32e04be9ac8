"""The kind interface: what every primitive kind provides, written once.

A primitive kind is a frozen dataclass deriving from :class:`Primitive`, in one
module of :mod:`isocsg.kinds` (or of user code) that holds all of its math and
registers it with :func:`~isocsg.kinds.registry.register_kind`. The machinery
above (plane sections, membership, volumes, bands, meshes, shadows, scene files,
OpenSCAD) only calls the members listed on :class:`Primitive`; none of it tests
for a concrete kind.

The members, by concern:

- geometry: ``bounds``, ``extent(n)``, ``breakpoints(n)``, ``volume``;
- membership: ``signed_distance(points)``, ``tangent_cone(points, tol)``,
  ``tolerance()`` and ``contains(points, tol=...)`` built on them;
- rays: ``ray_intervals(origins, directions)`` (``(n, k, 2)``, several depth
  intervals per ray for non-convex kinds, NaN for none), ``intersect_rays``
  (the first interval with its normals), ``normals_at(points)``;
- bands: ``band_surface(...)`` (the mesh the isoluminance bands are cut
  from), ``contour_laminae`` and ``contour_family`` (the seed's planar laminae);
- sections: ``section(frame, resolution, area_exact)``, ``planar_faces()``,
  ``leaf_row()`` (the kind's row of the batched leaf tables);
- meshes and shadows: ``to_polyhedron(resolution)``, ``manifold(resolution,
  shapes)``, ``convex_pieces(resolution)``;
- files: ``kind`` and ``to_dict()`` / ``from_dict(fields)`` (scene files),
  ``to_openscad(digits)``; ``_affine(A, t)`` (the image under an affine map);
- exact forms: ``exact_form()`` (the kind as plain data, :mod:`isocsg.kinds.forms`: what
  ``projection`` and exact hulls read), ``is_prism_along(direction)``;
- surface measure: ``area``, ``surface_patches(leaf)`` (:mod:`isocsg.kinds.patches`),
  ``flat_face_planes()`` (what :mod:`isocsg.testing` integrates);
- OpenSCAD values: ``axis_scaled(scale)`` (a box of any aspect), ``simplest()`` (an
  axis-aligned polyhedron as a box).

Members with a sound generic answer have a default here (a convex kind's
``ray_intervals`` from ``intersect_rays``, a section and a manifold from
``to_polyhedron``); the others raise ``NotImplementedError`` until a kind
provides them.
"""

from __future__ import annotations

import enum
import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar, Protocol

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._late import late
from .._validation import Vec3, length_floor, points_array
from ..errors import InvalidGeometryError, InvalidParameterError
from .affine import perpendicular_frame as _perpendicular_frame  # noqa: F401  (the kinds import it from here)

if TYPE_CHECKING:  # pragma: no cover
    import manifold3d
    import trimesh
    from shapely.geometry import Polygon

    from ..bands.surface import Surface
    from .forms import ExactForm
    from .patches import Patch

__all__ = [
    "DEFAULT_RESOLUTION",
    "LeafForm",
    "LeafRow",
    "Polytope",
    "Primitive",
    "RayHits",
    "Solid",
    "check_tolerance",
    "provides",
]

DEFAULT_RESOLUTION = 64
#: The relative size of a primitive's default membership tolerance.
RELATIVE_TOLERANCE = 1e-12

class Polytope(Protocol):
    """What the kind interface reads of a convex polyhedron (:class:`~isocsg.kinds.ConvexPolyhedron`,
    which is itself a kind built on this module): the result of :meth:`Primitive.to_polyhedron`."""

    @property
    def vertices(self) -> tuple[Vec3, ...]: ...

    @property
    def hull_vertices(self) -> NDArray[np.float64]: ...

    @property
    def faces(self) -> tuple[NDArray[np.int64], ...]: ...

    @property
    def face_normals(self) -> NDArray[np.float64]: ...

    @property
    def face_offsets(self) -> NDArray[np.float64]: ...

    @property
    def triangles(self) -> NDArray[np.int64]: ...

    @property
    def bounds(self) -> NDArray[np.float64]: ...

    def face_polygons(self) -> list[NDArray[np.float64]]: ...

    def section(self, frame: NDArray[np.float64], resolution: int, area_exact: bool = False) -> Polygon: ...


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

    if TYPE_CHECKING:  # what every subclass implements, declared for the type checker only

        def to_trimesh(self, resolution: int = ...) -> trimesh.Trimesh: ...

    def __or__(self, other: Solid) -> Solid:
        return late("union")(self, other)

    def __and__(self, other: Solid) -> Solid:
        return late("intersection")(self, other)

    def __sub__(self, other: Solid) -> Solid:
        return late("difference")(self, other)

    def _repr_mimebundle_(self, include: Any = None, exclude: Any = None) -> dict[str, Any]:
        """Rich display in Jupyter: a small PNG image (see :mod:`isocsg.interop.notebook`)."""
        return late("mimebundle")(self, include, exclude)

    def _repr_png_(self) -> bytes | None:
        """A small PNG image of the object (see :mod:`isocsg.interop.notebook`)."""
        return late("mimebundle")(self, ("image/png",)).get("image/png")

    # ------------------------------------------------------------ transforms
    def transform(self, matrix: ArrayLike) -> Solid:
        """The image under an affine map ``x -> A x + t`` given as a 4x4 or 3x4 matrix ``[A | t]``.

        Parameters
        ----------
        matrix : array_like, shape (4, 4) or (3, 4)
            Finite, invertible, with a condition number at most
            :data:`isocsg.kinds.affine.MAX_CONDITION`.

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
        >>> from isocsg import Sphere
        >>> Sphere((0, 0, 0), 1).transform([[2, 0, 0, 1], [0, 2, 0, 0], [0, 0, 2, 0]])
        Sphere(center=(1.0, 0.0, 0.0), radius=2.0)
        """
        from .affine import affine_matrix

        m = affine_matrix(matrix)
        return self._affine(m[:3, :3], m[:3, 3])

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> Solid:
        """The image under ``x -> A x + t`` (``A`` validated by :func:`~isocsg.kinds.affine.affine_matrix`):
        each kind maps itself (:meth:`Primitive._affine`), a CSG node maps its leaves."""
        raise InvalidGeometryError(f"transform needs a solid (primitive or CSG node), got {type(self).__name__}")

    def translate(self, v: ArrayLike) -> Solid:
        """The solid moved by ``v`` (metres).

        Examples
        --------
        >>> from isocsg import Sphere
        >>> Sphere((0, 0, 0), 1).translate((1, 2, 3)).center
        (1.0, 2.0, 3.0)
        """
        from .affine import translation_matrix

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
        >>> from isocsg import Box
        >>> Box((1, 0, 0), (2, 1, 1)).rotate((0, 0, 90))
        Box(center=(0.0, 1.0, 0.0), size=(1.0, 2.0, 1.0))
        """
        from .affine import axis_angle_matrix, rotation_matrix

        if axis is not None or np.ndim(v) == 0:
            return self.transform(axis_angle_matrix(v, (0.0, 0.0, 1.0) if axis is None else axis))  # type: ignore[arg-type]
        return self.transform(rotation_matrix(v))

    def scale(self, s: ArrayLike) -> Solid:
        """The solid scaled about the origin by a number or per axis ``[sx, sy, sz]``."""
        from .affine import scale_matrix

        return self.transform(scale_matrix(s))

    def mirror(self, normal: ArrayLike) -> Solid:
        """The solid reflected in the plane through the origin with ``normal`` (OpenSCAD's ``mirror``)."""
        from .affine import mirror_matrix

        return self.transform(mirror_matrix(normal))

    # Subclasses override these.
    def contains(self, points: ArrayLike) -> NDArray[np.bool_]:  # pragma: no cover
        raise NotImplementedError

    @property
    def bounds(self) -> NDArray[np.float64]:  # pragma: no cover
        raise NotImplementedError




class LeafForm(enum.IntEnum):
    """How a leaf is stored in the batched leaf tables of :mod:`isocsg.csg.section`.

    The forms are shapes of table rows, not kinds: a kind chooses the form whose
    vectorised formulas are exact for it (a sphere is a ``BALL``, every truncus a
    ``FRUSTUM``), and ``GENERIC`` reaches any other kind through its own members
    (``extent``, ``breakpoints``, ``section``, ``signed_distance``).
    """

    BALL = 0  # center, radius
    FRUSTUM = 1  # center, axis (unit), height, r1 (the end at +axis/2), r2
    AXIS_BOX = 2  # center, half (half edge lengths along x, y, z)
    HULL = 3  # vertices: the convex hull's vertices
    GENERIC = 4  # the kind's own members


@dataclass(frozen=True, slots=True)
class LeafRow:
    """One kind's row of the leaf tables: its :class:`LeafForm` and that form's columns."""

    form: LeafForm
    center: NDArray[np.float64] | None = None
    radius: float = 0.0
    axis: NDArray[np.float64] | None = None  # unit
    height: float = 0.0
    axis_vector: NDArray[np.float64] | None = None  # FRUSTUM: the axis as given (E2's centre to E1's), bit for bit
    r1: float = 0.0
    r2: float = 0.0
    half: NDArray[np.float64] | None = None
    vertices: NDArray[np.float64] | None = None


def check_tolerance(name: str, tol: float | None, default: float) -> float:
    """``tol`` as a float >= 0, or ``default`` when it is None (errors name the field)."""
    if tol is None:
        return default
    try:
        t = float(tol)
    except (TypeError, ValueError):
        raise InvalidParameterError(f"{name} must be a number >= 0, got {type(tol).__name__}") from None
    if not math.isfinite(t) or t < 0.0:
        raise InvalidParameterError(f"{name} must be a finite number >= 0, got {tol!r}")
    return t


TangentCone = tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.bool_]]
#: :meth:`Primitive.leaf_boxes`: lo, hi (n, 3), ball (n,), center (n, 3), radius (n,).
LeafBoxes = tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.bool_], NDArray[np.float64], NDArray[np.float64]]


class Primitive(Solid):
    """The kind interface: every member a primitive kind provides (see the module docstring).

    Class attributes
    ----------------
    kind : str
        The scene-file name (set by :func:`~isocsg.kinds.registry.register_kind`
        for kinds that do not set it).
    max_intervals : int
        The most depth intervals a ray can have in the solid (1 for convex kinds).
    convex : bool
        Whether the solid is convex (one convex piece, one interval per ray).
    polyhedral : bool
        Whether the surface is made of flat faces only, so that :meth:`manifold` is the solid
        itself, not an inscribed tessellation (what lets ``isocsg.volume`` take a polyhedral
        tree's volume from its exact mesh Boolean).
    """

    __slots__ = ()
    kind: ClassVar[str] = "primitive"
    max_intervals: ClassVar[int] = 1
    convex: ClassVar[bool] = True
    polyhedral: ClassVar[bool] = False

    def _points(self, points: ArrayLike) -> NDArray[np.float64]:
        return points_array(f"{type(self).__name__}.contains(points)", points)

    # ------------------------------------------------------------ geometry
    @property
    def bounds(self) -> NDArray[np.float64]:  # pragma: no cover
        """Exact axis-aligned bounds, shape (2, 3)."""
        raise NotImplementedError

    def extent(self, n: ArrayLike) -> tuple[float, float]:  # pragma: no cover
        """Exact extent ``(min, max)`` of ``x . n`` over the solid, for a unit vector ``n``."""
        raise NotImplementedError

    def breakpoints(self, n: ArrayLike) -> NDArray[np.float64]:
        """Heights along the unit vector ``n`` where the area of the solid's sections can have a
        kink (ends of the extent, vertices, rims); volume integration splits there."""
        return np.asarray(self.extent(n), dtype=np.float64)

    @property
    def volume(self) -> float:  # pragma: no cover
        """The exact volume."""
        raise NotImplementedError

    # ------------------------------------------------------------ membership
    def signed_distance(self, points: ArrayLike) -> NDArray[np.float64]:  # pragma: no cover
        """Signed distance of points ``(n, 3)`` to the boundary (negative inside); exact, or a
        bound that is exact inside and on the boundary (what CSG membership needs)."""
        raise NotImplementedError

    def tangent_cone(self, points: NDArray[np.float64], tol: float) -> TangentCone:
        """The tangent cone at points within ``tol`` of the boundary, as ``V (m, c, 3)``, ``C (m, c)``
        and ``valid (m, c)``: direction u points into the solid when ``V[i, j] . u < C[i, j]`` for
        every valid j. Default: the tangent half-space of ``normals_at`` (a smooth surface)."""
        m = len(points)
        n = self.normals_at(points)
        return n[:, None, :], np.zeros((m, 1)), np.ones((m, 1), dtype=bool)

    def tolerance(self) -> float:
        """The default membership tolerance: 1e-12 of the size or coordinate magnitude."""
        b = np.asarray(self.bounds)
        return RELATIVE_TOLERANCE * float(max(np.max(b[1] - b[0]), np.max(np.abs(b))))

    def contains(self, points: ArrayLike, *, tol: float | None = None) -> NDArray[np.bool_]:
        """Boolean mask of the points inside or on the solid: signed distance at most ``tol``
        metres (>= 0; default :meth:`tolerance`)."""
        p = self._points(points)
        limit = check_tolerance(f"{type(self).__name__}.contains(tol)", tol, self.tolerance())
        return self.signed_distance(p) <= limit

    def normals_at(self, points: ArrayLike) -> NDArray[np.float64]:  # pragma: no cover
        """Outward unit normals at surface points."""
        raise NotImplementedError

    # ------------------------------------------------------------ rays
    def intersect_rays(self, origins: ArrayLike, directions: ArrayLike) -> RayHits:  # pragma: no cover
        """The first depth interval of each ray and its normals; see :class:`RayHits`."""
        raise NotImplementedError

    def first_interval_hits(self, origins: ArrayLike, directions: ArrayLike) -> RayHits:
        """:meth:`intersect_rays` of a kind that has :meth:`ray_intervals` (a non-convex one): each
        ray's first interval, with :meth:`normals_at` at its ends."""
        o, d = _as_rays(origins, directions)
        iv = self.ray_intervals(o, d)
        hit = np.isfinite(iv[:, 0, 0])
        t_in = np.where(hit, iv[:, 0, 0], np.inf)
        t_out = np.where(hit, iv[:, 0, 1], -np.inf)
        n_in = np.zeros((len(o), 3))
        n_out = np.zeros((len(o), 3))
        if hit.any():
            n_in[hit] = self.normals_at(o[hit] + t_in[hit, None] * d[hit])
            n_out[hit] = self.normals_at(o[hit] + t_out[hit, None] * d[hit])
        return RayHits(t_in, t_out, n_in, n_out)

    def ray_intervals(self, origins: ArrayLike, directions: ArrayLike) -> NDArray[np.float64]:
        """Every depth interval of each ray in the solid.

        Returns
        -------
        ndarray, shape (n, max_intervals, 2)
            ``[t_in, t_out]`` pairs in increasing order, NaN where a ray has fewer intervals.
            Default (a convex kind): the one interval of :meth:`intersect_rays`.
        """
        h = self.intersect_rays(origins, directions)
        out = np.full((len(h.t_in), 1, 2), np.nan)
        hit = h.hit
        out[hit, 0, 0], out[hit, 0, 1] = h.t_in[hit], h.t_out[hit]
        return out

    # ------------------------------------------------------------ bands
    def band_surface(
        self, lights: list[Any], contours: int, eye: NDArray[np.float64] | None, shininess: float,
        weights: tuple[float, float] = (1.0, 1.0), segments: int | None = None, *,
        hidden: tuple[Any, Any] | None = None,
    ) -> Surface:  # pragma: no cover
        """The base mesh its isoluminance bands are cut from (:mod:`isocsg.laminae`): exact vertices
        and normals, fine enough for every light's field. ``segments`` is a tessellation hint for a
        leaf small on screen; ``hidden`` a box outside which nothing shows (may be ignored)."""
        raise NotImplementedError

    def contour_laminae(
        self, light: Any, contours: int,
    ) -> list[tuple[NDArray[np.float64], NDArray[np.float64], float, str]]:
        """The seed's planar contour laminae of one light (none by default: the bands carry the image)."""
        return []

    def contour_family(
        self, light: Any, contours: int,
    ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]] | None:
        """The planes of :meth:`contour_laminae`: ``(normal, offsets, levels)``, or None."""
        return None

    # ------------------------------------------------------------ sections
    def section(self, frame: NDArray[np.float64], resolution: int, area_exact: bool = False) -> Polygon:
        """The section in the plane of ``frame`` (:func:`isocsg.csg.section.plane_frame`) as a convex
        shapely polygon (inscribed, or of the true area with ``area_exact``). Default: the section
        of :meth:`to_polyhedron`."""
        return self.to_polyhedron(resolution).section(frame, resolution, area_exact)

    def planar_faces(self) -> tuple[NDArray[np.float64], NDArray[np.float64]] | None:
        """Outward normals and offsets ``n . x = d`` of the planar faces, or None (no planar faces
        that sections must see exactly)."""
        return None

    def part_index(self, points: NDArray[np.float64], normals: NDArray[np.float64]) -> NDArray[np.int64]:
        """Which smooth part of the surface (a face, a cap or the side) each surface point with its
        normal lies on, as small integers (default: one part, 0)."""
        return np.zeros(len(points), dtype=np.int64)

    def clipped_to_box(self, lo: NDArray[np.float64], hi: NDArray[np.float64]) -> Primitive:
        """A primitive equal to this one inside the box ``[lo, hi]`` and no larger than it needs to
        be there (what a large tree's leaves are cut to before rendering); default: itself.

        Raises
        ------
        InvalidGeometryError
            When the cut would be below the documented smallest lengths (keep the leaf whole).
        """
        return self

    def hull_points(self) -> NDArray[np.float64] | None:
        """Points whose convex hull is exactly the solid (a polyhedral kind's vertices), or None
        (a curved kind): what OpenSCAD's ``hull()`` of its children needs."""
        return None

    def exact_form(self) -> ExactForm | None:
        """What the solid is exactly, as one of the shapes of :mod:`isocsg.kinds.forms` (a ball, a
        frustum, a polytope, ... as plain data), or None (default: none of them). OpenSCAD's
        ``projection`` and exact hulls read it; without one a section is polygonised from
        :meth:`section`, and an outline or a hull raises :class:`~isocsg.errors.NotExactError`."""
        return None

    def is_prism_along(self, direction: NDArray[np.float64], tol: float = 1e-12) -> bool:
        """Whether the solid is a right prism along the unit ``direction`` (its sides parallel to it,
        its ends across it, to ``tol``): what makes ``projection`` of a through hole exact.
        Default: False (not known to be one)."""
        return False

    def flat_face_planes(self) -> tuple[NDArray[np.float64], NDArray[np.float64]] | None:
        """Outward normals and offsets ``n . x = d`` of the planes holding the flat parts of its
        surface (a polytope's faces, a truncus's ends), or None: the area integration of
        :mod:`isocsg.testing` finds where a surface crosses them in closed form. Default: a convex
        polyhedral kind's :meth:`planar_faces`, else None."""
        return self.planar_faces() if self.polyhedral and self.convex else None

    def flat_faces(self) -> list[tuple[NDArray[np.float64], NDArray[np.float64]]]:
        """A convex polyhedral kind's faces: each polygon (counter-clockwise seen from outside) with
        its outward unit normal; the exact reference of :mod:`isocsg.testing` overlays them.
        Default: the faces of :meth:`to_polyhedron` (exact for a convex polytope)."""
        from .patches import face_normals

        poly = self.to_polyhedron()
        polys = [np.asarray(V, dtype=np.float64) for V in poly.face_polygons()]
        return list(zip(polys, face_normals(polys, np.asarray(poly.face_normals, dtype=np.float64))))

    @property
    def area(self) -> float:
        """The exact surface area (square metres).

        Raises
        ------
        InvalidParameterError
            For a kind without a closed form (the default).
        """
        raise InvalidParameterError(f"surface area: no closed form for the kind {type(self).__name__}")

    def surface_patches(self, leaf: int) -> list[Patch]:
        """Its surface as smooth patches, each a one-parameter family of rings (see
        :mod:`isocsg.kinds.patches`), labelled with the leaf index ``leaf``: what
        :func:`isocsg.testing.surface_area` integrates over.

        Raises
        ------
        InvalidGeometryError
            For a kind without a parametrisation (the default).
        """
        raise InvalidGeometryError(f"surface area: no surface parametrisation for the kind {type(self).__name__}")

    def axis_scaled(self, scale: NDArray[np.float64]) -> Primitive | None:
        """Its image under ``diag(scale)`` as this kind, for any ratio of the factors (an axis-aligned
        box stays one where the general map of that aspect would be refused as ill-conditioned),
        or None (default: use :meth:`transform`)."""
        return None

    def simplest(self) -> Primitive:
        """The same solid as the simplest kind that is it exactly (a convex polyhedron that is an
        axis-aligned box becomes a :class:`~isocsg.kinds.Box`); default: itself."""
        return self

    def leaf_row(self) -> LeafRow:
        """The kind's row of the batched leaf tables (default: :attr:`LeafForm.GENERIC`)."""
        return LeafRow(LeafForm.GENERIC, center=0.5 * (self.bounds[0] + self.bounds[1]))

    @classmethod
    def leaf_boxes(cls, leaves: Sequence[Primitive]) -> LeafBoxes:
        """Batched over ``leaves`` (all of this class): their bounds, whether each is a ball, and a
        centre and radius (a ball's own; an axial kind's axis centre and largest radius; else zero).
        What the renderer plans with before any band is built (:func:`isocsg.rendering.tiles.leaf_geometry`);
        a kind with many leaves reads its parameters in one vectorised pass. Default: each ``bounds``."""
        n = len(leaves)
        lo = np.empty((n, 3))
        hi = np.empty((n, 3))
        for k, p in enumerate(leaves):
            lo[k], hi[k] = np.asarray(p.bounds, dtype=np.float64)
        return lo, hi, np.zeros(n, np.bool_), np.zeros((n, 3)), np.zeros(n)

    # ------------------------------------------------------------ meshes and shadows
    def to_polyhedron(self, resolution: int = DEFAULT_RESOLUTION) -> Polytope:  # pragma: no cover
        """A :class:`~isocsg.kinds.polyhedron.ConvexPolyhedron` inscribed in the solid (a convex kind)."""
        raise NotImplementedError

    def manifold(self, resolution: int, shapes: dict[tuple[Any, ...], Any] | None = None) -> manifold3d.Manifold:
        """The solid as a manifold3d ``Manifold``; ``shapes`` is a dict a kind may use to build equal
        shapes once (by their dimensions). Default: the hull of :meth:`to_polyhedron`."""
        from .meshing import manifold3d_module

        poly = self.to_polyhedron(resolution)
        return manifold3d_module().Manifold.hull_points(np.asarray(poly.hull_vertices, dtype=np.float64).tolist())

    # Any: the shadows take the pieces as ConvexPolyhedron, a kind module above this one.
    def convex_pieces(self, resolution: int = DEFAULT_RESOLUTION) -> list[Any]:
        """Convex polyhedra whose union is the solid (inscribed for curved kinds): the shadows'
        occluders. Default: ``[to_polyhedron(resolution)]``."""
        return [self.to_polyhedron(resolution)]

    def to_manifold(self, resolution: int = DEFAULT_RESOLUTION) -> manifold3d.Manifold:
        """The primitive as a manifold3d ``Manifold`` (see :meth:`manifold`)."""
        from .._validation import integer

        return self.manifold(integer("resolution", resolution, low=3, high=65536, error=InvalidParameterError), {})

    def to_trimesh(self, resolution: int = DEFAULT_RESOLUTION) -> trimesh.Trimesh:
        """A closed triangle mesh of the solid (vertices on the true surface)."""
        import trimesh

        poly = self.to_polyhedron(resolution)
        return trimesh.Trimesh(poly.hull_vertices, poly.triangles, process=False)

    # ------------------------------------------------------------ files
    def to_dict(self) -> dict[str, Any]:  # pragma: no cover
        """A plain mapping ``{kind: {field: value}}`` for scene files."""
        raise NotImplementedError

    @classmethod
    def from_dict(cls, fields: dict[str, Any]) -> Primitive:
        """The primitive from its scene-file fields (the constructor's keywords)."""
        return cls(**fields)

    def to_openscad(self, digits: int | None = None, *, exact: bool = True) -> str:
        """Its OpenSCAD statement: ``digits`` significant digits per number (None: ``repr``, an exact
        round trip); ``exact=False`` allows a plainer form whose values keep only about ``digits``
        digits (a polyhedron's rounded points; kinds without one ignore it)."""
        raise InvalidGeometryError(f"save_openscad cannot write a {type(self).__name__}: its kind has no OpenSCAD form")

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> Primitive:  # pragma: no cover
        """The image under ``x -> A x + t`` (``A`` validated by :func:`~isocsg.kinds.affine.affine_matrix`)."""
        raise NotImplementedError


def provides(prim: Primitive, member: str) -> bool:
    """Whether ``prim``'s kind implements ``member`` itself (not the base's default or refusal)."""
    return getattr(type(prim), member, None) is not getattr(Primitive, member, None)



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
        raise InvalidGeometryError(
            f"{name} must {verb} >= {floor:g} (the smallest "
            f"length at this position), got {value:g}"
        )


def _unit(v: Vec3) -> NDArray[np.float64]:
    a = np.asarray(v, dtype=np.float64)
    return a / np.linalg.norm(a)


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


