"""Immutable scene values: what a scene file describes."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from .._late import late
from .._validation import MAX_INTENSITY, integer, light_budget, parse_color, scalar, show
from ..camera import Camera
from ..errors import InvalidGeometryError, InvalidLightError, InvalidParameterError
from ..kinds import Solid
from ..lighting.area import AreaLight, PolyhedronLight
from ..lighting.lights import DirectionalLight, Material, PointLight

__all__ = ["SceneObject", "RenderSettings", "Scene", "SceneLight", "MAX_CONTOURS", "RENDER_MODES"]

#: The lights a scene holds.
SceneLight = PointLight | DirectionalLight | AreaLight | PolyhedronLight

#: Largest accepted number of isoluminance contours per light family.
MAX_CONTOURS = 4096

#: ``isoluminance``: the contour method with point/directional lights;
#: ``halftone``: exact illuminance E from area and polyhedron sources with soft shadows.
RENDER_MODES = ("isoluminance", "halftone")


@dataclass(frozen=True, slots=True)
class SceneObject:
    """A solid (primitive or CSG tree) with its material and, optionally, its colour.

    Parameters
    ----------
    shape : Solid
    material : Material, optional
    color : color, optional
        An sRGB colour (3 or 4 numbers in [0, 1], alpha dropped; or an SVG colour name, or
        ``"#rrggbb"``): the object's bands are drawn in it, each band one flat shade
        (:mod:`isocsg.rendering.colors`). None: grey.
    leaf_colors : sequence of colour or None, optional
        One colour (or None: the object's) per leaf of the object's tree, in the order of
        ``CSGNode.leaves()``, as OpenSCAD's ``color()`` colours subtrees; at most one per leaf
        (more is an error when the object is drawn).
    """

    shape: Solid
    material: Material = field(default_factory=Material)
    color: tuple[float, float, float] | None = None
    leaf_colors: tuple[tuple[float, float, float] | None, ...] = ()

    def __post_init__(self) -> None:
        if not isinstance(self.shape, Solid):
            raise InvalidGeometryError(f"SceneObject.shape must be a solid, got {type(self.shape).__name__}")
        if not isinstance(self.material, Material):
            raise InvalidParameterError(f"SceneObject.material must be a Material, got {type(self.material).__name__}")
        if self.color is not None:
            object.__setattr__(self, "color", parse_color(self.color, name="SceneObject.color"))
        if self.leaf_colors:
            colors = tuple(None if c is None else parse_color(c, name=f"SceneObject.leaf_colors[{i}]")
                           for i, c in enumerate(self.leaf_colors))
            object.__setattr__(self, "leaf_colors", colors)
        else:
            object.__setattr__(self, "leaf_colors", ())


@dataclass(frozen=True, slots=True)
class RenderSettings:
    """The ``[render]`` table.

    Parameters
    ----------
    contours : int, default 64
        Isoluminance contours per light family, 1 .. 4096.
    mode : {"isoluminance", "halftone"}
    exposure : float, default 1
        Half-tone images show ``E * exposure`` (clipped to [0, 1]); > 0 and
        at most 1e6.
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
            self, "contours", integer("render.contours", self.contours, low=1, high=MAX_CONTOURS,
                                      error=InvalidParameterError)
        )
        if not isinstance(self.mode, str) or self.mode not in RENDER_MODES:
            raise InvalidParameterError(f"render.mode must be one of {RENDER_MODES}, got {show(self.mode)}")
        object.__setattr__(
            self, "exposure", scalar("render.exposure", self.exposure, low=0.0, high=MAX_INTENSITY,
                                     error=InvalidParameterError)
        )
        object.__setattr__(self, "interval", integer("render.interval", self.interval, low=1, high=256,
                                                     error=InvalidParameterError))


_DEFAULT_RENDER = RenderSettings()


# The constructor is written out (init=False) so that it accepts what users pass, any sequence of
# lights and of objects (solids or SceneObjects), while the fields hold tuples of SceneObjects.
@dataclass(frozen=True, slots=True, init=False)
class Scene:
    """Camera, lights, objects and render settings.

    Parameters
    ----------
    camera : Camera
    lights : sequence of lights
        Point, directional, area and polyhedron lights, at most 16
        (:data:`~isocsg._validation.MAX_LIGHTS`); (point and directional
        lights) x ``render.contours`` is at most 1024
        (:data:`~isocsg._validation.MAX_LIGHT_CONTOURS`).
    objects : sequence of SceneObject or Solid
    render : RenderSettings, optional

    Raises
    ------
    InvalidParameterError
        If ``camera`` or ``render`` has the wrong type, or on too many lights
        for the limits above.
    InvalidLightError
        If a light is not one of the four light types.
    InvalidGeometryError
        If an object is not a solid.
    """

    camera: Camera
    lights: tuple[SceneLight, ...]
    objects: tuple[SceneObject, ...]
    render: RenderSettings = field(default_factory=RenderSettings)

    def __init__(
        self,
        camera: Camera,
        lights: Sequence[SceneLight],
        objects: Sequence[SceneObject | Solid],
        render: RenderSettings = _DEFAULT_RENDER,
    ) -> None:
        object.__setattr__(self, "camera", camera)
        object.__setattr__(self, "lights", lights)
        object.__setattr__(self, "objects", objects)
        object.__setattr__(self, "render", render)
        self.__post_init__()

    def _repr_mimebundle_(self, include: Any = None, exclude: Any = None) -> dict[str, Any]:
        """Rich display in Jupyter: a small PNG image (see :mod:`isocsg.interop.notebook`)."""
        return late("mimebundle")(self, include, exclude)

    def _repr_png_(self) -> bytes | None:
        """A small PNG image of the object (see :mod:`isocsg.interop.notebook`)."""
        return late("mimebundle")(self, ("image/png",)).get("image/png")

    def __post_init__(self) -> None:
        if not isinstance(self.camera, Camera):
            raise InvalidParameterError(f"scene.camera must be a Camera, got {type(self.camera).__name__}")
        if not isinstance(self.render, RenderSettings):
            raise InvalidParameterError(f"scene.render must be RenderSettings, got {type(self.render).__name__}")
        lights = _sequence("scene.lights", self.lights, InvalidLightError)
        for i, light in enumerate(lights):
            if not isinstance(light, _LIGHT_TYPES):
                raise InvalidLightError(
                    f"scene.lights[{i}] must be a PointLight, DirectionalLight, AreaLight or PolyhedronLight, "
                    f"got {type(light).__name__}"
                )
        families = sum(isinstance(li, (PointLight, DirectionalLight)) for li in lights)
        light_budget(len(lights), families, self.render.contours, where="scene.")
        object.__setattr__(self, "lights", lights)
        objects = _sequence("scene.objects", self.objects, InvalidGeometryError)
        objs = tuple(o if isinstance(o, SceneObject) else SceneObject(o) for o in objects)
        object.__setattr__(self, "objects", objs)


_LIGHT_TYPES = (PointLight, DirectionalLight, AreaLight, PolyhedronLight)


def _sequence(name: str, value: Any, error: type[Exception]) -> tuple[Any, ...]:
    """``value`` as a tuple; strings, mappings and non-iterables are refused."""
    if isinstance(value, (str, bytes, dict)):
        raise error(f"{name} must be a sequence, got {type(value).__name__}")
    try:
        return tuple(value)
    except TypeError:
        raise error(f"{name} must be a sequence, got {type(value).__name__}") from None
