"""Area and polyhedron light sources of Nishita and Nakamae (uniform Lambertian emitters).

An :class:`AreaLight` is a convex planar polygon that emits on one side only.
Its *lit side* is defined by the winding of ``vertices``: seen from the lit
side the vertices turn counter-clockwise, so the right-hand normal
``(q2 - q1) x (q3 - q1)`` points to the lit side. A clockwise input is not an
error: it is simply the same polygon emitting towards the other side. Points
on the other side (or in the plane) receive nothing from it.

A :class:`PolyhedronLight` is a convex polyhedron whose every face emits
outwards with the same radiance.

Photometric units: radiance (luminance) L in cd/m^2 and lengths in metres
give illuminance E in lux (lm/m^2). A one-sided Lambertian emitter of area A
and radiance L sends out the luminous flux F = pi L A (lumens); ``from_flux``
builds a source from its flux, L = F / (pi A). Only direct light is
modelled: occluders are black and nothing is reflected.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import MAX_INTENSITY, MAX_VERTICES, Vec3, length_floor, points_array, scalar
from ..errors import InvalidGeometryError, InvalidLightError
from ..kinds import ConvexPolyhedron

__all__ = ["AreaLight", "PolyhedronLight", "ShadowLight", "as_light_list"]

#: Planarity tolerance of a source polygon, relative to its size.
PLANARITY_TOL = 1e-9
#: A vertex is convex when its turn (e_i x e_i+1) . n exceeds this many rounding units of the
#: turn: ulps of its edges' product and of the coordinates times the edges (the edges' own
#: rounding). It scales with the polygon's size, position and vertex spacing, so a circle of
#: MAX_VERTICES vertices (turns about (2 pi / m)^3 R^2) passes.
CONVEXITY_ULPS = 64.0


def _radiance(name: str, value: Any) -> float:
    return scalar(name, value, low=0.0, low_inclusive=True, high=MAX_INTENSITY, error=InvalidLightError)


def _newell_normal(p: NDArray[np.float64]) -> NDArray[np.float64]:
    """Area-weighted normal of a (possibly non-planar) closed polygon (Newell's method)."""
    q = np.roll(p, -1, axis=0)
    return 0.5 * np.sum(np.cross(p, q), axis=0)


@dataclass(frozen=True, slots=True)
class AreaLight:
    """A convex planar polygon emitting uniformly (Lambertian) towards its lit side.

    Parameters
    ----------
    vertices : array_like, shape (m, 3)
        At least 3 vertices of a strictly convex planar polygon. Seen from the
        lit side they turn counter-clockwise; equivalently the right-hand
        normal of the winding (``normal``) points to the lit side. Either
        winding is accepted: it chooses the side that is lit.
    radiance : float, default 1
        Radiance (luminance) L in cd/m^2, 0 .. 1e6. A fully visible source
        covering the whole hemisphere above a point would give the
        illuminance pi L lux. See :meth:`from_flux` for a source given by
        its luminous flux in lumens.

    Attributes
    ----------
    normal : tuple of float
        Unit normal pointing to the lit side.
    area : float
        Area of the polygon.

    Raises
    ------
    InvalidLightError
        On fewer than 3 vertices, non-finite values, repeated or collinear
        points (zero area), a non-planar, non-convex or self-intersecting
        polygon, or a negative or non-finite radiance. The message names the
        field (``AreaLight.vertices`` or ``AreaLight.radiance``).

    Examples
    --------
    >>> a = AreaLight([(0, 0, 2), (0, 1, 2), (1, 1, 2), (1, 0, 2)], radiance=3.0)
    >>> a.normal, a.area
    ((0.0, 0.0, -1.0), 1.0)
    >>> AreaLight([(0, 0, 2), (1, 0, 2), (1, 1, 2), (0, 1, 2)]).normal  # other winding: lights upwards
    (0.0, 0.0, 1.0)
    """

    vertices: tuple[Vec3, ...]
    radiance: float = 1.0
    normal: Vec3 = field(init=False, compare=False, hash=False)
    area: float = field(init=False, compare=False, hash=False)
    kind = "area"

    if TYPE_CHECKING:  # what callers pass; the generated __init__ stores the checked tuples
        def __init__(self, vertices: ArrayLike, radiance: float = 1.0) -> None: ...

    if TYPE_CHECKING:  # the constructor as callers call it: array-likes, checked in __post_init__
        def __init__(self, vertices: ArrayLike, radiance: float = 1.0) -> None: ...

    def __post_init__(self) -> None:
        name = "AreaLight.vertices"
        pts = points_array(name, self.vertices, min_rows=3, max_rows=MAX_VERTICES, error=InvalidLightError)
        scale = float(np.max(np.ptp(pts, axis=0)))
        if scale <= 0:
            raise InvalidLightError(f"{name} are all the same point")
        floor = length_floor(pts.min(axis=0), pts.max(axis=0))
        if scale < floor:
            raise InvalidLightError(
                f"{name} must span at least {floor:g} (the "
                f"smallest length at this position), got {scale:g}"
            )
        m = len(pts)
        edges = np.roll(pts, -1, axis=0) - pts
        elen = np.linalg.norm(edges, axis=1)
        if np.any(elen <= 1e-12 * scale):
            i = int(np.argmin(elen))
            raise InvalidLightError(f"{name} has repeated consecutive points (vertex {i} and {(i + 1) % m})")
        rel = pts - pts.mean(axis=0)
        nn = _newell_normal(rel)
        area = float(np.linalg.norm(nn))
        if area <= 1e-12 * scale * scale:
            # Zero signed area: either every point is on one line, or the
            # outline crosses itself (a bow-tie) and its lobes cancel.
            sv = np.linalg.svd(rel, compute_uv=False)
            if sv[1] <= 1e-9 * sv[0]:
                raise InvalidLightError(f"{name} are collinear: the polygon has zero area")
            raise InvalidLightError(
                f"{name} must form a convex polygon, the outline is "
                "self-intersecting (not convex): its signed area is zero"
            )
        n = nn / area
        dev = np.abs((pts - pts.mean(axis=0)) @ n)
        if np.max(dev) > PLANARITY_TOL * scale:
            raise InvalidLightError(
                f"{name} must be planar, vertex {int(np.argmax(dev))} is {float(np.max(dev)):.3g} off the plane"
            )
        # Strict convexity: every turn has the sign of the winding, and the
        # total turning is one full turn (rejects stars such as a pentagram).
        turns = np.cross(edges, np.roll(edges, -1, axis=0)) @ n
        reach = float(np.max(np.abs(pts)))
        elen_next = np.roll(elen, -1)
        rounding = np.finfo(np.float64).eps * (elen * elen_next + reach * (elen + elen_next))
        if np.any(turns <= CONVEXITY_ULPS * rounding):
            i = int(np.argmin(turns))
            raise InvalidLightError(
                f"{name} must form a strictly convex polygon, vertex {(i + 1) % m} is reflex or collinear"
            )
        cosang = np.einsum("ij,ij->i", edges, np.roll(edges, -1, axis=0)) / (elen * elen_next)
        total = float(np.sum(np.arctan2(turns / (elen * elen_next), cosang)))
        if abs(total - 2 * math.pi) > 1e-6:
            raise InvalidLightError(
                f"{name} must form a simple convex polygon, "
                f"it winds {total / (2 * math.pi):.3g} times"
            )
        object.__setattr__(self, "vertices", tuple(tuple(map(float, p)) for p in pts))
        object.__setattr__(self, "radiance", _radiance("AreaLight.radiance", self.radiance))
        object.__setattr__(self, "normal", (float(n[0]), float(n[1]), float(n[2])))
        object.__setattr__(self, "area", area)

    @property
    def vertices_array(self) -> NDArray[np.float64]:
        """The vertices as an (m, 3) float64 array (a copy)."""
        return np.asarray(self.vertices, dtype=np.float64)

    @property
    def normal_array(self) -> NDArray[np.float64]:
        """The unit normal towards the lit side as a float64 array."""
        return np.asarray(self.normal, dtype=np.float64)

    @property
    def centroid(self) -> NDArray[np.float64]:
        """Mean of the vertices (a point inside the convex polygon)."""
        return self.vertices_array.mean(axis=0)

    def emitting_polygons(self) -> list[NDArray[np.float64]]:
        """The emitting convex polygons, each (k, 3), counter-clockwise seen from its lit side."""
        return [self.vertices_array]

    @property
    def flux(self) -> float:
        """Luminous flux F = pi L A in lumens (one-sided Lambertian emitter)."""
        return math.pi * self.radiance * self.area

    @classmethod
    def from_flux(cls, vertices: ArrayLike, flux: float) -> AreaLight:
        """A source of luminous flux ``flux`` (lumens): radiance L = F / (pi A) in cd/m^2.

        Parameters
        ----------
        vertices : array_like, shape (m, 3)
            As for the constructor.
        flux : float
            Luminous flux in lumens, >= 0.

        Raises
        ------
        InvalidLightError
            On bad vertices (as the constructor), or a negative or non-finite
            flux (``AreaLight.flux``).

        Examples
        --------
        >>> panel = AreaLight.from_flux([(0, 0, 3), (0, 0.6, 3), (0.6, 0.6, 3), (0.6, 0, 3)], 3600.0)
        >>> round(panel.radiance, 3), round(panel.flux, 9)
        (3183.099, 3600.0)
        """
        f = scalar("AreaLight.flux", flux, low=0.0, low_inclusive=True, high=MAX_INTENSITY * 1e6,
                   error=InvalidLightError)
        shape = cls(vertices)
        return cls(shape.vertices, f / (math.pi * shape.area))

    def to_dict(self) -> dict[str, Any]:
        """Scene-file mapping ``{"kind": "area", "vertices": [...], "radiance": L}``."""
        return {"kind": "area", "vertices": [list(v) for v in self.vertices], "radiance": self.radiance}


@dataclass(frozen=True, slots=True)
class PolyhedronLight:
    """A convex polyhedron every face of which emits outwards with radiance L.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
        At least 4 points, not coplanar; the source is their convex hull
        (interior points are dropped).
    radiance : float, default 1
        Radiance (luminance) L in cd/m^2 (0 .. 1e6) of every face. See
        :meth:`from_flux` for a source given by its luminous flux.

    Attributes
    ----------
    polyhedron : ConvexPolyhedron
        The hull (faces counter-clockwise seen from outside, outward normals).

    Raises
    ------
    InvalidLightError
        On fewer than 4 points, non-finite values, a flat hull, or a negative
        or non-finite radiance; the message names ``PolyhedronLight.vertices``
        or ``PolyhedronLight.radiance``.

    Examples
    --------
    >>> cube = PolyhedronLight([(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)], radiance=2)
    >>> len(cube.emitting_polygons()), cube.radiance
    (6, 2.0)
    """

    vertices: tuple[Vec3, ...]
    radiance: float = 1.0
    polyhedron: ConvexPolyhedron = field(init=False, repr=False, compare=False, hash=False)
    kind = "polyhedron"

    if TYPE_CHECKING:  # what callers pass; the generated __init__ stores the checked tuples
        def __init__(self, vertices: ArrayLike, radiance: float = 1.0) -> None: ...

    if TYPE_CHECKING:  # the constructor as callers call it: array-likes, checked in __post_init__
        def __init__(self, vertices: ArrayLike, radiance: float = 1.0) -> None: ...

    def __post_init__(self) -> None:
        name = "PolyhedronLight.vertices"
        pts = points_array(name, self.vertices, min_rows=4, max_rows=MAX_VERTICES, error=InvalidLightError)
        try:
            poly = ConvexPolyhedron(pts)
        except InvalidGeometryError as exc:
            raise InvalidLightError(str(exc).replace("ConvexPolyhedron.vertices", name)) from None
        object.__setattr__(self, "vertices", tuple(tuple(map(float, p)) for p in pts))
        object.__setattr__(self, "radiance", _radiance("PolyhedronLight.radiance", self.radiance))
        object.__setattr__(self, "polyhedron", poly)

    @property
    def vertices_array(self) -> NDArray[np.float64]:
        """The input points as an (n, 3) float64 array (a copy)."""
        return np.asarray(self.vertices, dtype=np.float64)

    @property
    def centroid(self) -> NDArray[np.float64]:
        """Mean of the hull vertices (a point inside the polyhedron)."""
        return self.polyhedron.hull_vertices.mean(axis=0)

    def emitting_polygons(self) -> list[NDArray[np.float64]]:
        """The faces, each (k, 3), counter-clockwise seen from outside (their lit side)."""
        return [np.array(f, dtype=np.float64) for f in self.polyhedron.face_polygons()]

    @property
    def area(self) -> float:
        """Total area of the emitting faces (m^2)."""
        return float(sum(np.linalg.norm(_newell_normal(f - f.mean(axis=0))) for f in self.emitting_polygons()))

    @property
    def flux(self) -> float:
        """Luminous flux F = pi L A in lumens, A the total face area (every face emits outwards)."""
        return math.pi * self.radiance * self.area

    @classmethod
    def from_flux(cls, vertices: ArrayLike, flux: float) -> PolyhedronLight:
        """A source of luminous flux ``flux`` (lumens) spread over its faces: L = F / (pi A).

        Raises
        ------
        InvalidLightError
            On bad vertices, or a negative or non-finite flux (``PolyhedronLight.flux``).

        Examples
        --------
        >>> cube = PolyhedronLight.from_flux([(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)], 600.0)
        >>> cube.area, round(cube.radiance * math.pi, 9)
        (6.0, 100.0)
        """
        f = scalar("PolyhedronLight.flux", flux, low=0.0, low_inclusive=True, high=MAX_INTENSITY * 1e6,
                   error=InvalidLightError)
        shape = cls(vertices)
        return cls(shape.vertices, f / (math.pi * shape.area))

    def to_dict(self) -> dict[str, Any]:
        """Scene-file mapping ``{"kind": "polyhedron", "vertices": [...], "radiance": L}``."""
        return {"kind": "polyhedron", "vertices": [list(v) for v in self.vertices], "radiance": self.radiance}


ShadowLight = AreaLight | PolyhedronLight
"""Either kind of extended source."""


def as_light_list(lights: Any) -> list[AreaLight | PolyhedronLight]:
    """Accept one light or a sequence of lights; raise ``InvalidLightError`` otherwise."""
    if isinstance(lights, (AreaLight, PolyhedronLight)):
        return [lights]
    try:
        seq = list(lights)
    except TypeError:
        raise InvalidLightError(
            "lights must be an AreaLight, a PolyhedronLight or "
            f"a sequence of them, got {type(lights).__name__}"
        ) from None
    for i, li in enumerate(seq):
        if not isinstance(li, (AreaLight, PolyhedronLight)):
            raise InvalidLightError(f"lights[{i}] must be an AreaLight or a PolyhedronLight, got {type(li).__name__}")
    return seq
