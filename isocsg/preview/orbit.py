"""The orbit of a live preview: a view as azimuth, elevation and zoom about the model's target.

A view is three numbers, so a page can send it in a URL and a link can hold it. Azimuth is
measured about the camera's up axis (z in the conventions), from the x axis towards y;
elevation is the angle above the plane normal to the up axis, kept within
:data:`MAX_ELEVATION` so that the view direction never meets the up vector; zoom divides the
starting distance from the target.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from .._validation import integer, scalar
from ..camera import Camera
from ..errors import InvalidParameterError
from ..lighting.lights import DirectionalLight
from ..scene.model import Scene, SceneLight

__all__ = ["OrbitView", "initial_view", "orbit_scene", "MAX_ELEVATION", "ZOOM_RANGE", "MAX_SIDE"]

#: Elevations are clamped to +- this many degrees (straight down the up axis has no azimuth).
MAX_ELEVATION = 89.0
#: The smallest and largest zoom.
ZOOM_RANGE = (0.05, 50.0)
#: The largest image side a preview renders (larger requests are refused, not shrunk silently).
MAX_SIDE = 4096


@dataclass(frozen=True)
class OrbitView:
    """A view about the scene's target.

    Parameters
    ----------
    azimuth : float
        Degrees about the up axis.
    elevation : float
        Degrees above the horizontal plane, clamped to +-:data:`MAX_ELEVATION`.
    zoom : float, default 1
        The starting distance divided by this, clamped to :data:`ZOOM_RANGE`.
    width, height : int
        Image size in pixels, 1 to :data:`MAX_SIDE`.

    Raises
    ------
    InvalidParameterError
        On a value that is not finite, or an image size out of range (naming the field).
    """

    azimuth: float
    elevation: float
    zoom: float = 1.0
    width: int = 512
    height: int = 512

    def __post_init__(self) -> None:
        az = scalar("azimuth", self.azimuth, error=InvalidParameterError)
        el = scalar("elevation", self.elevation, error=InvalidParameterError)
        zoom = scalar("zoom", self.zoom, low=0.0, error=InvalidParameterError)
        for name in ("width", "height"):
            object.__setattr__(self, name, integer(name, getattr(self, name), low=1, high=MAX_SIDE,
                                                   error=InvalidParameterError))
        object.__setattr__(self, "azimuth", math.remainder(az, 360.0))
        object.__setattr__(self, "elevation", min(max(el, -MAX_ELEVATION), MAX_ELEVATION))
        object.__setattr__(self, "zoom", min(max(zoom, ZOOM_RANGE[0]), ZOOM_RANGE[1]))


def _frame(camera: Camera) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """An orthonormal frame ``(e1, e2, up)`` with ``up`` the camera's up axis."""
    up = np.asarray(camera.up, dtype=np.float64)
    up = up / np.linalg.norm(up)
    seed = np.array([1.0, 0.0, 0.0]) if abs(up[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    e1 = seed - (seed @ up) * up
    e1 /= np.linalg.norm(e1)
    return e1, np.cross(up, e1), up


def initial_view(camera: Camera) -> OrbitView:
    """The orbit view of a camera: its own azimuth and elevation, zoom 1, its image size."""
    e1, e2, up = _frame(camera)
    d = np.asarray(camera.eye, dtype=np.float64) - np.asarray(camera.target, dtype=np.float64)
    d /= np.linalg.norm(d)
    elevation = math.degrees(math.asin(float(np.clip(d @ up, -1.0, 1.0))))
    azimuth = math.degrees(math.atan2(float(d @ e2), float(d @ e1)))
    return OrbitView(azimuth, elevation, 1.0, camera.width, camera.height)


def orbit_scene(scene: Scene, view: OrbitView, *, turn_lights: bool) -> Scene:
    """The scene seen from ``view``: the camera moved on its orbit, at the view's image size.

    Parameters
    ----------
    scene : Scene
        Its camera gives the target, the up axis and the starting distance.
    view : OrbitView
    turn_lights : bool
        Turn the directional lights about the up axis with the camera (a model that came without
        lights keeps its light over the viewer's shoulder); a scene file's own lights stay put.
    """
    camera = scene.camera
    e1, e2, up = _frame(camera)
    target = np.asarray(camera.target, dtype=np.float64)
    distance = float(np.linalg.norm(np.asarray(camera.eye, dtype=np.float64) - target)) / view.zoom
    az, el = math.radians(view.azimuth), math.radians(view.elevation)
    direction = math.cos(el) * (math.cos(az) * e1 + math.sin(az) * e2) + math.sin(el) * up
    moved = camera.with_view(target + distance * direction).with_size(view.width, view.height)
    if camera.orthographic:  # zoom narrows the orthographic window instead of moving the eye
        moved = dataclasses.replace(moved, height_m=camera.height_m / view.zoom)
    lights = scene.lights
    if turn_lights:
        turn = az - math.radians(initial_view(camera).azimuth)
        lights = tuple(_turned(light, up, turn) for light in lights)
    return dataclasses.replace(scene, camera=moved, lights=lights)


def _turned(light: SceneLight, axis: np.ndarray, angle: float) -> SceneLight:
    """A directional light turned by ``angle`` about ``axis`` (Rodrigues); other lights as they are."""
    if not isinstance(light, DirectionalLight):
        return light
    d = np.asarray(light.direction, dtype=np.float64)
    c, s = math.cos(angle), math.sin(angle)
    rotated = d * c + np.cross(axis, d) * s + axis * (axis @ d) * (1 - c)
    return dataclasses.replace(light, direction=(float(rotated[0]), float(rotated[1]), float(rotated[2])))
