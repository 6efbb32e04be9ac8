"""Immutable scene values: what a scene file describes."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from .._validation import integer, scalar
from ..camera import Camera
from ..errors import InvalidGeometryError, InvalidParameterError
from ..geometry.primitives import Solid
from ..lighting.lights import Material

__all__ = ["SceneObject", "RenderSettings", "Scene", "MAX_CONTOURS", "RENDER_MODES"]

#: Largest accepted number of isoluminance contours per light family.
MAX_CONTOURS = 4096

#: ``isoluminance``: the contour method with point/directional lights;
#: ``halftone``: exact illuminance E from area and polyhedron sources with soft shadows.
RENDER_MODES = ("isoluminance", "halftone")


@dataclass(frozen=True, slots=True)
class SceneObject:
    """A solid (primitive or CSG tree) with its material."""

    shape: Solid
    material: Material = field(default_factory=Material)

    def __post_init__(self) -> None:
        if not isinstance(self.shape, Solid):
            raise InvalidGeometryError(f"SceneObject.shape must be a solid, got {type(self.shape).__name__}")
        if not isinstance(self.material, Material):
            raise InvalidParameterError(f"SceneObject.material must be a Material, got {type(self.material).__name__}")


@dataclass(frozen=True, slots=True)
class RenderSettings:
    """The ``[render]`` table.

    Parameters
    ----------
    contours : int, default 64
        Isoluminance contours per light family, 1 .. 4096.
    mode : {"isoluminance", "halftone"}
    exposure : float, default 1
        Half-tone images show ``E * exposure`` (clipped to [0, 1]).
    interval : int, default 1
        Half-tone speed-up: exact values every ``interval`` pixels along a
        scanline, linear in between (never across face or shadow boundaries);
        1 is the exact mode.
    """

    contours: int = 64
    mode: str = "isoluminance"
    exposure: float = 1.0
    interval: int = 1

    def __post_init__(self) -> None:
        object.__setattr__(
            self, "contours", integer("render.contours", self.contours, low=1, high=MAX_CONTOURS, error=InvalidParameterError)
        )
        if self.mode not in RENDER_MODES:
            raise InvalidParameterError(f"render.mode must be one of {RENDER_MODES}, got {self.mode!r}")
        object.__setattr__(self, "exposure", scalar("render.exposure", self.exposure, low=0.0, error=InvalidParameterError))
        object.__setattr__(self, "interval", integer("render.interval", self.interval, low=1, high=256, error=InvalidParameterError))


@dataclass(frozen=True, slots=True)
class Scene:
    """Camera, lights, objects and render settings."""

    camera: Camera
    lights: tuple[Any, ...]
    objects: tuple[SceneObject, ...]
    render: RenderSettings = field(default_factory=RenderSettings)

    def __post_init__(self) -> None:
        object.__setattr__(self, "lights", tuple(self.lights))
        objs = tuple(o if isinstance(o, SceneObject) else SceneObject(o) for o in self.objects)
        object.__setattr__(self, "objects", objs)
