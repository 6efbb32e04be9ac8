"""The exact figures of a solid, in one value: what a mesh Boolean test compares against."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import nonzero_vector3, scalar, vector3
from ..csg.section import section as _section
from ..errors import InvalidParameterError
from ..kinds import Solid
from .area import boundary_figures
from .distance import DistanceResult, signed_distance

if TYPE_CHECKING:  # pragma: no cover
    from shapely.geometry.base import BaseGeometry

    from ..camera import Camera

__all__ = ["Reference", "SectionReference", "reference"]


@dataclass(frozen=True, slots=True, eq=False)
class SectionReference:
    """A plane section: its exact ``area``, its ``perimeter`` (Richardson-extrapolated from
    inscribed polygons of 2048 and 4096 vertices per circle, ``perimeter_error`` the difference
    between the extrapolation and the finer polygon), and the section ``geometry`` (shapely, in
    the plane's frame ``frame``)."""

    area: float
    perimeter: float
    perimeter_error: float
    geometry: BaseGeometry
    frame: NDArray[np.float64]


@dataclass(frozen=True, slots=True, eq=False)
class Reference:
    """The exact figures of a solid (see :func:`reference`).

    Attributes
    ----------
    solid : Solid
    volume : float
        Cubic metres: closed forms for primitives; for trees the flux of ``x / 3`` through the
        boundary (:func:`isocsg.testing.area.boundary_volume`), independent of
        :func:`isocsg.volume`'s sections.
    volume_error : float
        Its estimated absolute error (0 for a closed form).
    area : float
        Square metres of the result's boundary (:func:`isocsg.testing.area.surface_area`).
    area_error : float
        Its estimated absolute error (0 for a closed form).
    bounds : ndarray, shape (2, 3)
        A box containing the solid (exact for a primitive; for a tree the leaves' boxes
        combined by the tree, which may be larger than the result).
    tol : float
        The relative accuracy asked for.
    """

    solid: Solid
    volume: float
    volume_error: float
    area: float
    area_error: float
    bounds: NDArray[np.float64]
    tol: float
    _cache: dict[str, Any] = field(default_factory=dict, repr=False)

    def section(self, plane_origin: ArrayLike, plane_normal: ArrayLike) -> SectionReference:
        """The section by the plane through ``plane_origin`` with ``plane_normal``."""
        o = vector3("plane_origin", plane_origin, error=InvalidParameterError)
        n = nonzero_vector3("plane_normal", plane_normal, error=InvalidParameterError)
        exact = _section(self.solid, o, n, resolution=4096, area_exact=True)
        p1 = _section(self.solid, o, n, resolution=2048).geometry.length
        p2 = _section(self.solid, o, n, resolution=4096).geometry.length
        per = (4.0 * p2 - p1) / 3.0  # inscribed polygons: error ~ 1/N^2
        return SectionReference(exact.area, float(per), float(abs(per - p2)), exact.geometry, exact.frame)

    def signed_distance(self, points: ArrayLike) -> DistanceResult:
        """Signed distances with certified bounds (:func:`isocsg.testing.distance.signed_distance`)."""
        return signed_distance(self.solid, points)

    def depth(self, camera: Camera) -> NDArray[np.float64]:
        """The camera depth of the visible surface per pixel (``inf`` on the background), through
        the renderer's exact per-pixel CSG."""
        key = f"depth {camera!r}"
        if key not in self._cache:
            from ..lighting import DirectionalLight
            from ..rendering import Renderer
            from ..scene import Scene

            scene = Scene(camera, [DirectionalLight((0.0, 0.0, 1.0))], [self.solid])
            self._cache[key] = Renderer(csg="pixel").render(scene).depth
        return self._cache[key]  # type: ignore[no-any-return]

    def silhouette(self, camera: Camera) -> NDArray[np.bool_]:
        """The pixels whose ray meets the solid (``depth`` finite)."""
        return np.isfinite(self.depth(camera))


def reference(solid: Solid, *, tol: float = 1e-9) -> Reference:
    """The exact figures of a primitive or CSG tree.

    Parameters
    ----------
    solid : Solid
    tol : float, default 1e-9
        Relative accuracy of the integrated figures (volume, area of cut surfaces), in
        [1e-12, 0.1]; closed forms are exact whatever it is.

    Returns
    -------
    Reference

    Raises
    ------
    InvalidParameterError
        On a bad ``tol``, or a leaf of a kind without a surface parametrisation.

    Examples
    --------
    >>> from isocsg import Sphere
    >>> ref = reference(Sphere((0, 0, 0), 1) | Sphere((0, 0, 1.5), 1), tol=1e-9)
    >>> round(ref.area / (2 * math.pi * (2 + 2 * 0.75)), 9)  # two spheres less two caps of height 1/4
    1.0
    """
    tol_ = scalar("tol", tol, low=1e-12, high=0.1, error=InvalidParameterError)
    v, a = boundary_figures(solid, tol=tol_)
    return Reference(solid, v.value, v.error, a.value, a.error, np.asarray(solid.bounds, dtype=np.float64), tol_)


_ = math  # the doctest's namespace
