"""Rich display in Jupyter: small PNG (and SVG) images of solids, scenes and render results.

IPython asks an object for ``_repr_mimebundle_`` (or ``_repr_png_``) when it
is the value of a cell. Solids are drawn with :func:`framing_camera` (a
camera that frames their bounding box) and :func:`default_light`; scenes
with their own camera and lights, scaled down to fit
:data:`DISPLAY_SIZE`; render results show their image. The text reprs stay
as they are (IPython shows them in plain-text front ends).
"""

from __future__ import annotations

import io
import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ..camera import Camera
from ..errors import InvalidParameterError, IsocsgError
from ..lighting.lights import PointLight

__all__ = [
    "DISPLAY_SIZE", "DISPLAY_CONTOURS", "SVG_MAX_CHARS", "framing_camera", "default_light", "png_bytes",
    "solid_png", "scene_png", "scene_svg", "mimebundle",
]

#: Largest (width, height) of a displayed image in pixels: small, so display is fast.
DISPLAY_SIZE = (320, 240)
#: Largest SVG (characters) put in a display bundle; larger scenes show their PNG only.
SVG_MAX_CHARS = 1 << 20
#: Contours per light of displayed solids.
DISPLAY_CONTOURS = 24
# The default view direction (from the target towards the eye): in front, right, above.
_VIEW = np.array([0.55, -1.0, 0.7])
# The default light: above, to the left of the eye, so the bands are graded across the object.
_LIGHT = np.array([-0.3, -0.8, 1.4])


def _box(bounds: ArrayLike) -> tuple[np.ndarray, float]:
    b = np.asarray(bounds, dtype=np.float64)
    if b.shape != (2, 3) or not np.all(np.isfinite(b)) or np.any(b[1] < b[0]):
        raise InvalidParameterError(f"bounds must be a finite [[lo], [hi]] box of shape (2, 3), got {b.tolist()}")
    centre = 0.5 * (b[0] + b[1])
    radius = max(0.5 * float(np.linalg.norm(b[1] - b[0])), 1e-6 * max(1.0, float(np.abs(centre).max())))
    return centre, radius


def framing_camera(
    bounds: ArrayLike, *, width: int = DISPLAY_SIZE[0], height: int = DISPLAY_SIZE[1], fov: float = 30.0,
) -> Camera:
    """A camera that sees the whole box ``bounds`` from the front right, above.

    The box's bounding sphere fits in the narrower of the two fields of view.

    Examples
    --------
    >>> cam = framing_camera([[-1, -1, -1], [1, 1, 1]], width=64, height=48)
    >>> x, y, depth = cam.project([[1, 1, 1], [-1, -1, -1], [1, -1, 1], [-1, 1, -1]])
    >>> bool(((x >= 0) & (x < 64) & (y >= 0) & (y < 48)).all())
    True
    """
    centre, radius = _box(bounds)
    half = math.radians(fov) / 2
    narrow = min(half, math.atan(math.tan(half) * width / height))
    distance = 1.05 * radius / math.sin(narrow)
    eye = centre + distance * _VIEW / np.linalg.norm(_VIEW)
    return Camera(tuple(eye.tolist()), tuple(centre.tolist()), fov=fov, width=width, height=height)


def default_light(bounds: ArrayLike) -> PointLight:
    """A point light above and to the front left of the box ``bounds``, four radii from its centre.

    Examples
    --------
    >>> default_light([[-1, -1, -1], [1, 1, 1]]).position[2] > 1
    True
    """
    centre, radius = _box(bounds)
    return PointLight(tuple((centre + 4.0 * radius * _LIGHT / np.linalg.norm(_LIGHT)).tolist()))


def png_bytes(image: ArrayLike) -> bytes:
    """An intensity image (H, W) (NaN background) as 8-bit grey PNG bytes.

    The grey levels are those of :func:`isocsg.rendering.image.to_uint8`.
    """
    from PIL import Image

    from ..rendering.image import to_uint8

    buf = io.BytesIO()
    Image.fromarray(to_uint8(image), mode="L").save(buf, format="PNG")
    return buf.getvalue()


def _fit(camera: Camera) -> Camera:
    w, h = camera.width, camera.height
    k = min(1.0, DISPLAY_SIZE[0] / w, DISPLAY_SIZE[1] / h)
    return camera if k >= 1.0 else camera.with_size(max(1, round(w * k)), max(1, round(h * k)))


def _solid_scene(solid: Any) -> Any:
    from ..scene.model import RenderSettings, Scene

    b = solid.bounds
    return Scene(framing_camera(b), [default_light(b)], [solid], RenderSettings(contours=DISPLAY_CONTOURS))


def solid_png(solid: Any) -> bytes:
    """A PNG of a solid (primitive or CSG tree) framed by :func:`framing_camera`, lit by :func:`default_light`."""
    from ..rendering import render

    return png_bytes(render(_solid_scene(solid)).image)


def scene_png(scene: Any) -> bytes:
    """A PNG of a scene from its camera, at most :data:`DISPLAY_SIZE` pixels (aspect kept)."""
    import dataclasses

    small = dataclasses.replace(scene, camera=_fit(scene.camera))
    if scene.render.mode == "halftone":
        from ..shadows.halftone import render_halftone

        return png_bytes(render_halftone(small).display)
    from ..rendering import render

    return png_bytes(render(small).image)


def scene_svg(scene: Any) -> str | None:
    """The SVG of a scene of single primitives, at most :data:`SVG_MAX_CHARS` long.

    None where no vector image exists (CSG, half-tone, interpenetrating
    objects) or where it would be longer.
    """
    import dataclasses
    import os
    import tempfile

    from ..kinds import Primitive

    if scene.render.mode != "isoluminance" or not all(isinstance(o.shape, Primitive) for o in scene.objects):
        return None
    from ..rendering.svg import save_scene_svg

    small = dataclasses.replace(scene, camera=_fit(scene.camera))
    fd, path = tempfile.mkstemp(suffix=".svg")
    os.close(fd)
    try:
        save_scene_svg(path, small, decimals=1)
        if os.path.getsize(path) > SVG_MAX_CHARS:
            return None
        with open(path, encoding="utf-8") as f:
            return f.read()
    except IsocsgError:  # interpenetrating objects have no back-to-front order
        return None
    finally:
        os.unlink(path)


def mimebundle(obj: Any, include: Any = None, exclude: Any = None) -> dict[str, Any]:
    """The ``_repr_mimebundle_`` of solids, scenes and render results.

    ``text/plain`` is the object's own repr; ``image/png`` its picture;
    ``image/svg+xml`` too for scenes that have a vector image.
    """
    from ..kinds import Solid
    from ..scene.model import Scene

    out: dict[str, Any] = {"text/plain": repr(obj)}

    def want(mime: str) -> bool:
        return (include is None or mime in include) and (exclude is None or mime not in exclude)

    # A picture that cannot be made (a scene outside the limits, say) leaves the text repr alone.
    try:
        if isinstance(obj, Solid):
            if want("image/png"):
                out["image/png"] = solid_png(obj)
        elif isinstance(obj, Scene):
            if want("image/svg+xml"):
                svg = scene_svg(obj)
                if svg is not None:
                    out["image/svg+xml"] = svg
            if want("image/png"):
                out["image/png"] = scene_png(obj)
        elif want("image/png"):
            out["image/png"] = png_bytes(getattr(obj, "display", obj.image))
    except IsocsgError:
        pass
    return out
