"""What the band math reads of a light and a material, as protocols.

The band math sits below the kinds, and the light classes (:mod:`isocsg.lighting`) above them
(a polyhedron light holds a :class:`~isocsg.kinds.ConvexPolyhedron`), so it names no light class:
a light is anything with a ``kind`` (``"point"`` or ``"directional"``) and an ``intensity``, plus
a ``position`` (point light) or a ``unit_direction`` (directional light), as
:class:`~isocsg.lighting.PointLight` and :class:`~isocsg.lighting.DirectionalLight` have.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:  # pragma: no cover
    from typing_extensions import TypeIs

__all__ = ["PointLike", "DirectionalLike", "Light", "MaterialLike", "is_directional", "is_point", "light_axis"]


class PointLike(Protocol):
    """A point light: ``kind == "point"``, a position and an intensity."""

    @property
    def kind(self) -> str: ...

    @property
    def position(self) -> tuple[float, float, float]: ...

    @property
    def intensity(self) -> float: ...


class DirectionalLike(Protocol):
    """A light at infinity: ``kind == "directional"``, the unit direction towards it and an intensity."""

    @property
    def kind(self) -> str: ...

    @property
    def unit_direction(self) -> NDArray[np.float64]: ...

    @property
    def intensity(self) -> float: ...


#: A light the bands are built for.
Light = PointLike | DirectionalLike


class MaterialLike(Protocol):
    """The Phong coefficients the contour families weigh their bands with."""

    @property
    def kd(self) -> float: ...

    @property
    def ks(self) -> float: ...

    @property
    def shininess(self) -> float: ...


def is_directional(light: object) -> TypeIs[DirectionalLike]:
    """Whether ``light`` is a light at infinity."""
    return getattr(light, "kind", None) == "directional"


def is_point(light: object) -> TypeIs[PointLike]:
    """Whether ``light`` is a point light."""
    return getattr(light, "kind", None) == "point"


def light_axis(center: NDArray[np.float64], light: Light | None) -> NDArray[np.float64]:
    """Unit axis from the centre towards the light (+z without a light or for a light at the centre)."""
    if light is None:
        return np.array([0.0, 0.0, 1.0])
    if is_directional(light):
        return light.unit_direction
    d = np.asarray(light.position, dtype=np.float64) - center
    n = float(np.linalg.norm(d))
    return d / n if n > 0 else np.array([0.0, 0.0, 1.0])
