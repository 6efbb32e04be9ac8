"""Immutable light and material values for the isoluminance (point light) model."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._validation import MAX_INTENSITY, Vec3, nonzero_vector3, scalar, vector3
from ..errors import InvalidLightError

__all__ = ["PointLight", "DirectionalLight", "Light", "Material"]


@dataclass(frozen=True, slots=True)
class PointLight:
    """A point light at ``position`` with a scalar ``intensity`` multiplier.

    Parameters
    ----------
    position : array_like, shape (3,)
    intensity : float, default 1
        Scales the diffuse and specular terms of this light, 0 .. 1e6.

    Examples
    --------
    >>> PointLight((0, 0, 10)).intensity
    1.0
    """

    position: Vec3
    intensity: float = 1.0
    kind = "point"

    def __post_init__(self) -> None:
        object.__setattr__(self, "position", vector3("PointLight.position", self.position, error=InvalidLightError))
        object.__setattr__(
            self,
            "intensity",
            scalar("PointLight.intensity", self.intensity, low=0.0, low_inclusive=True, high=MAX_INTENSITY,
                   error=InvalidLightError),
        )

    def directions_from(self, points: NDArray[np.float64]) -> NDArray[np.float64]:
        """Unit vectors from ``points`` (n, 3) towards the light."""
        v = np.asarray(self.position) - points
        n = np.linalg.norm(v, axis=-1, keepdims=True)
        return np.divide(v, n, out=np.zeros_like(v), where=n > 0)

    def to_dict(self) -> dict[str, Any]:
        """Scene-file mapping."""
        return {"kind": "point", "position": list(self.position), "intensity": self.intensity}


@dataclass(frozen=True, slots=True)
class DirectionalLight:
    """A light at infinity; ``direction`` points from the scene towards the light.

    Examples
    --------
    >>> DirectionalLight((0, 0, 2)).unit_direction.tolist()
    [0.0, 0.0, 1.0]
    """

    direction: Vec3
    intensity: float = 1.0
    kind = "directional"

    def __post_init__(self) -> None:
        object.__setattr__(
            self, "direction", nonzero_vector3("DirectionalLight.direction", self.direction, error=InvalidLightError)
        )
        object.__setattr__(
            self,
            "intensity",
            scalar("DirectionalLight.intensity", self.intensity, low=0.0, low_inclusive=True, high=MAX_INTENSITY,
                   error=InvalidLightError),
        )

    @property
    def unit_direction(self) -> NDArray[np.float64]:
        """The unit direction towards the light."""
        d = np.asarray(self.direction, dtype=np.float64)
        return d / np.linalg.norm(d)

    def directions_from(self, points: NDArray[np.float64]) -> NDArray[np.float64]:
        """Unit vectors from ``points`` (n, 3) towards the light (all equal)."""
        return np.broadcast_to(self.unit_direction, np.shape(points)).copy()

    def to_dict(self) -> dict[str, Any]:
        """Scene-file mapping."""
        return {"kind": "directional", "direction": list(self.direction), "intensity": self.intensity}


Light = PointLight | DirectionalLight


@dataclass(frozen=True, slots=True)
class Material:
    """Reflectance of a surface: ``I = ambient + kd cos_i + ks cos^shininess``.

    Defaults follow the conventions: ambient 0.1, kd 0.8, ks 0.0, shininess 20.

    Examples
    --------
    >>> Material().kd
    0.8
    """

    ambient: float = 0.1
    kd: float = 0.8
    ks: float = 0.0
    shininess: float = 20.0

    def __post_init__(self) -> None:
        for name in ("ambient", "kd", "ks"):
            v = scalar(f"Material.{name}", getattr(self, name), low=0.0, low_inclusive=True, high=MAX_INTENSITY,
                       error=InvalidLightError)
            object.__setattr__(self, name, v)
        object.__setattr__(
            self, "shininess", scalar("Material.shininess", self.shininess, low=0.0, high=MAX_INTENSITY,
                                      error=InvalidLightError)
        )

    def to_dict(self) -> dict[str, Any]:
        """Scene-file mapping."""
        return {"ambient": self.ambient, "kd": self.kd, "ks": self.ks, "shininess": self.shininess}
