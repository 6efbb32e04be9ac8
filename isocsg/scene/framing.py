"""A default camera and light for a model that comes without them (OpenSCAD files).

The camera looks at the centre of the model's bounding box from the front,
right and above (the direction of the built-in demo's view), far enough away
that the bounding sphere fits the narrower field of view with a margin; one
directional light comes from over the viewer's left shoulder.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from ..camera import Camera
from ..kinds import Solid
from ..lighting.lights import DirectionalLight
from .model import RenderSettings, Scene, SceneObject

__all__ = ["frame_camera", "framed_scene", "VIEW_DIRECTION", "LIGHT_DIRECTION"]

#: From the target towards the eye (the demo scene's view).
VIEW_DIRECTION = (0.55, -0.75, 0.5)
#: From the scene towards the light.
LIGHT_DIRECTION = (0.3, -1.0, 0.9)


def frame_camera(bounds: np.ndarray, *, width: int = 512, height: int = 512, fov: float = 40.0,
                 margin: float = 1.1) -> Camera:
    """A camera that frames an axis-aligned box ``bounds`` (shape (2, 3)).

    The bounding sphere of the box fits inside the narrower of the vertical and
    horizontal fields of view, enlarged by ``margin``.

    Examples
    --------
    >>> cam = frame_camera(np.array([[-1.0, -1, -1], [1, 1, 1]]), width=64, height=48)
    >>> cam.target
    (0.0, 0.0, 0.0)
    """
    b = np.asarray(bounds, dtype=np.float64)
    center = (b[0] + b[1]) / 2
    radius = max(float(np.linalg.norm(b[1] - b[0])) / 2, 1e-6 * max(1.0, float(np.abs(center).max())))
    half_v = math.radians(fov) / 2
    half_h = math.atan(math.tan(half_v) * width / height)
    distance = margin * radius / math.sin(min(half_v, half_h))
    d = np.asarray(VIEW_DIRECTION) / np.linalg.norm(VIEW_DIRECTION)
    return Camera(eye=tuple(center + distance * d), target=tuple(center), fov=fov, width=width, height=height)


def framed_scene(solids: Solid | SceneObject | Sequence[Solid | SceneObject], *, width: int = 512, height: int = 512,
                 contours: int = 64) -> Scene:
    """A scene of the solids (or scene objects, with their materials and colours) with
    :func:`frame_camera` and one directional light.

    Examples
    --------
    >>> from isocsg import Sphere
    >>> scene = framed_scene(Sphere((0, 0, 0), 1), width=32, height=32)
    >>> len(scene.lights), scene.camera.target
    (1, (0.0, 0.0, 0.0))
    """
    items = [solids] if isinstance(solids, (Solid, SceneObject)) else list(solids)
    objects = [s if isinstance(s, SceneObject) else SceneObject(s) for s in items]
    bounds = np.stack([o.shape.bounds for o in objects])
    box = np.stack([bounds[:, 0].min(axis=0), bounds[:, 1].max(axis=0)])
    camera = frame_camera(box, width=width, height=height)
    return Scene(camera, [DirectionalLight(LIGHT_DIRECTION)], objects, RenderSettings(contours=contours))
