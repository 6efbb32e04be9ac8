"""A luminaire with a measured intensity distribution: a point source with a photometric table.

A :class:`PhotometricLight` places a :class:`~isocsg.lighting.photometry.Photometry`
at ``position``. Its local frame follows the type C convention of both file
formats: local -z is the nadir (gamma = 0), local +x the C0 direction, local
+y the C90 direction. The frame is turned into the world by

- ``rotation`` (degrees): about the world's vertical axis, counter-clockwise
  seen from above, turning C0 from +x towards +y;
- ``tilt`` (degrees): about the luminaire's C90 axis, swinging the nadir
  towards the C0 direction (0: pointing straight down);

or, instead of both, by ``aim``: a point the nadir axis points at (the C0
plane then holds the aiming direction; aiming straight down leaves C0 on +x).
The world rotation is ``R = Rz(rotation) Ry(-tilt)`` acting on local vectors.

The illuminance it gives at p with unit normal n is
``E = multiplier I(C, gamma) max(0, n . l) / r^2`` (inverse square and cosine
laws; l the unit vector from p to the luminaire, r the distance), where
(C, gamma) are the angles of the direction -l in the luminaire's frame, and 0
where an occluder cuts the segment: exact hard shadows (see
:mod:`isocsg.shadows.pointsource`). ``multiplier`` scales the intensities: a
maintenance factor, a lamp flux other than the measured one, a dimming level.

:meth:`PhotometricLight.opening_light` turns the luminous opening of the file
into an :class:`~isocsg.lighting.area.AreaLight` of the luminaire's flux: it
assumes the opening emits as a uniform Lambertian surface, whatever the
measured distribution says (documented in docs/lighting_studies.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import MAX_INTENSITY, Vec3, scalar, vector3
from ..errors import InvalidLightError
from .area import AreaLight
from .photometry import Photometry

__all__ = ["PhotometricLight", "luminaire_rotation"]

#: Sides of the polygon standing for a circular luminous opening (same area as the circle).
CIRCLE_SIDES = 48


def luminaire_rotation(rotation: float, tilt: float) -> NDArray[np.float64]:
    """The 3x3 matrix ``Rz(rotation) Ry(-tilt)`` (degrees) from the luminaire's frame to the world.

    Examples
    --------
    >>> np.round(luminaire_rotation(0, 90) @ [0, 0, -1], 12).tolist()  # nadir swung to C0 = +x
    [1.0, 0.0, 0.0]
    """
    a, t = math.radians(rotation), math.radians(tilt)
    rz = np.array([[math.cos(a), -math.sin(a), 0.0], [math.sin(a), math.cos(a), 0.0], [0.0, 0.0, 1.0]])
    ry = np.array([[math.cos(t), 0.0, -math.sin(t)], [0.0, 1.0, 0.0], [math.sin(t), 0.0, math.cos(t)]])
    return rz @ ry


@dataclass(frozen=True, slots=True)
class PhotometricLight:
    """A point luminaire with a measured intensity distribution (module docstring).

    Parameters
    ----------
    position : array_like, shape (3,)
        Photometric centre, metres.
    photometry : Photometry
    rotation : float, default 0
        Degrees about the vertical axis (C0 from +x towards +y).
    tilt : float, default 0
        Degrees, nadir swung towards C0; 0 .. 180.
    aim : array_like, shape (3,), optional
        A point the nadir points at; replaces ``rotation`` and ``tilt``
        (which must then be left at 0).
    multiplier : float, default 1
        Scales the intensities, 0 .. 1e6.

    Raises
    ------
    InvalidLightError
        On a non-finite position or angle, a tilt out of range, an aim point
        at the position, ``aim`` given with ``rotation`` or ``tilt``, or a
        ``photometry`` that is not a :class:`Photometry`.

    Examples
    --------
    >>> lamp = PhotometricLight((0, 0, 2), Photometry.isotropic(100.0))
    >>> float(lamp.intensity_towards([[0.0, 0.0, -1.0]])[0])
    100.0
    """

    position: Vec3
    photometry: Photometry
    rotation: float = 0.0
    tilt: float = 0.0
    aim: Vec3 | None = None
    multiplier: float = 1.0
    kind = "photometric"

    def __post_init__(self) -> None:
        err = InvalidLightError
        object.__setattr__(self, "position", vector3("PhotometricLight.position", self.position, error=err))
        if not isinstance(self.photometry, Photometry):
            raise err(f"PhotometricLight.photometry must be a Photometry, got {type(self.photometry).__name__}")
        rot = scalar("PhotometricLight.rotation", self.rotation, low=-360.0, low_inclusive=True, high=360.0, error=err)
        tilt = scalar("PhotometricLight.tilt", self.tilt, low=0.0, low_inclusive=True, high=180.0, error=err)
        if self.aim is not None:
            aim = vector3("PhotometricLight.aim", self.aim, error=err)
            if rot != 0.0 or tilt != 0.0:
                raise err("PhotometricLight.aim replaces rotation and tilt: give one or the other")
            d = np.asarray(aim) - np.asarray(self.position)
            r = float(np.linalg.norm(d))
            if not r > 1e-9 * max(1.0, float(np.max(np.abs(self.position)))):
                raise err(f"PhotometricLight.aim must differ from the position, got {aim}")
            d = d / r
            tilt = math.degrees(math.acos(max(-1.0, min(1.0, -d[2]))))
            rot = math.degrees(math.atan2(d[1], d[0])) if math.hypot(d[0], d[1]) > 1e-12 else 0.0
            object.__setattr__(self, "aim", aim)
        object.__setattr__(self, "rotation", rot)
        object.__setattr__(self, "tilt", tilt)
        object.__setattr__(
            self, "multiplier",
            scalar("PhotometricLight.multiplier", self.multiplier, low=0.0, low_inclusive=True, high=MAX_INTENSITY,
                   error=err),
        )

    @classmethod
    def isotropic(cls, position: ArrayLike, intensity: float) -> PhotometricLight:
        """A plain point light: ``intensity`` cd in every direction (flux ``4 pi I``), hard shadows.

        Raises
        ------
        InvalidLightError
            On a non-finite position or a negative or non-finite intensity.

        Examples
        --------
        >>> lamp = PhotometricLight.isotropic((0, 0, 2), 100.0)
        >>> float(lamp.intensity_towards([[1.0, 0.0, 0.0]])[0]), round(lamp.flux, 6) == round(400 * math.pi, 6)
        (100.0, True)
        """
        candela = scalar("PhotometricLight.intensity", intensity, low=0.0, low_inclusive=True, high=MAX_INTENSITY,
                         error=InvalidLightError)
        return cls(position, Photometry.isotropic(candela))  # type: ignore[arg-type]

    @property
    def matrix(self) -> NDArray[np.float64]:
        """Luminaire frame to world (3x3, columns: C0 axis, C90 axis, zenith)."""
        return luminaire_rotation(self.rotation, self.tilt)

    @property
    def flux(self) -> float:
        """Luminous flux in lm (the distribution's, times the multiplier)."""
        return self.multiplier * self.photometry.flux()

    def angles_towards(self, directions: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Type C angles ``(C, gamma)`` in degrees of world directions (n, 3) leaving the luminaire."""
        d = np.asarray(directions, dtype=np.float64).reshape(-1, 3)
        local = d @ self.matrix  # R^T d, row by row
        nrm = np.linalg.norm(local, axis=1)
        nrm = np.where(nrm > 0, nrm, 1.0)
        gamma = np.degrees(np.arccos(np.clip(-local[:, 2] / nrm, -1.0, 1.0)))
        c = np.mod(np.degrees(np.arctan2(local[:, 1], local[:, 0])), 360.0)
        return c, gamma

    def intensity_towards(self, directions: ArrayLike) -> NDArray[np.float64]:
        """Luminous intensity in cd towards world directions (n, 3), multiplier included."""
        c, gamma = self.angles_towards(directions)
        return self.multiplier * self.photometry.intensity(c, gamma)

    def opening_polygon(self) -> NDArray[np.float64]:
        """The luminous opening as a world polygon (m, 3), counter-clockwise seen from below it.

        A rectangle ``length`` (along C0) x ``width`` centred at the position
        in the luminaire's horizontal plane; a round opening (negative width)
        becomes a polygon of :data:`CIRCLE_SIDES` sides inscribed in a scaled
        ellipse of the same area. The opening's height (luminous sides) is not modelled.

        Raises
        ------
        InvalidLightError
            If the file gives no luminous opening (length or width 0).
        """
        length, width, _ = self.photometry.opening
        if width < 0:  # a round opening: axes length (along C0) and -width
            if not length > 0:
                raise InvalidLightError(
                    f"PhotometricLight.photometry.opening has no luminous area (length {length} m, width {width} m)"
                )
            n = CIRCLE_SIDES
            k = math.sqrt((2 * math.pi / n) / math.sin(2 * math.pi / n))  # polygon area = ellipse area
            ang = -2 * np.pi * np.arange(n) / n
            local = np.c_[0.5 * k * length * np.cos(ang), -0.5 * k * width * np.sin(ang), np.zeros(n)]
        else:
            if not (length > 0 and width > 0):
                raise InvalidLightError(
                    f"PhotometricLight.photometry.opening has no luminous area (length {length} m, width {width} m)"
                )
            a, b = 0.5 * length, 0.5 * width
            local = np.array([[a, b, 0.0], [a, -b, 0.0], [-a, -b, 0.0], [-a, b, 0.0]])  # clockwise from above
        return np.asarray(self.position) + local @ self.matrix.T

    def opening_light(self) -> AreaLight:
        """An :class:`AreaLight` over the luminous opening sending the luminaire's flux downwards.

        Assumes a uniform Lambertian opening (radiance ``flux / (pi A)``):
        the measured distribution's shape is not kept, only its flux.
        """
        return AreaLight.from_flux(self.opening_polygon(), self.flux)

    def to_dict(self) -> dict[str, Any]:
        """Scene-file mapping (the photometry by its source name)."""
        d: dict[str, Any] = {"kind": "photometric", "position": list(self.position), "file": self.photometry.source,
                             "multiplier": self.multiplier}
        if self.aim is not None:
            d["aim"] = list(self.aim)
        else:
            d["rotation"], d["tilt"] = self.rotation, self.tilt
        return d
