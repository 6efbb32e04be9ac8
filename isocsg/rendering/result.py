"""What a render returns: the image, its timings, and what each pixel shows."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._late import late
from ..camera import Camera
from .projection import key_to_depth

__all__ = ["RenderResult", "RenderTimings"]


@dataclass(frozen=True, slots=True)
class RenderTimings:
    """Wall-clock seconds spent in one render.

    Attributes
    ----------
    build : float
        Obtaining the band meshes (building them, or fetching them from cache).
        For a CSG object resolved per pixel, the leaves built first are filled
        by a worker thread meanwhile.
    fill : float
        The rest: projection, triangle fill, per-pixel CSG and composition of
        the image (``total`` is the render's wall-clock time).
    """

    build: float
    fill: float

    @property
    def total(self) -> float:
        """``build + fill``."""
        return self.build + self.fill


@dataclass(frozen=True, slots=True, eq=False)
class RenderResult:
    """An isoluminance image and what each pixel shows.

    Attributes
    ----------
    image : ndarray, shape (H, W), float32
        Intensity; NaN where no object is visible.
    timings : RenderTimings
    camera : Camera
        The camera the image was rendered with.

    The per-pixel indices and the depth are computed when first read (the
    fill itself only keeps one label per pixel).
    """

    image: NDArray[np.float32]
    timings: RenderTimings
    camera: Camera
    _label: NDArray[np.int32] = field(repr=False)
    _key: NDArray[np.float64] = field(repr=False)
    _object_of: NDArray[np.int32] = field(repr=False)
    _leaf_of: NDArray[np.int32] = field(repr=False)
    _lazy: dict[str, NDArray[Any]] = field(default_factory=dict, repr=False)

    @property
    def object_index(self) -> NDArray[np.int32]:
        """Index into ``scene.objects`` of the visible object per pixel, -1 on the background (int32)."""
        if "object" not in self._lazy:
            self._lazy["object"] = self._object_of[self._label + 1]
        return self._lazy["object"]

    @property
    def primitive_index(self) -> NDArray[np.int32]:
        """Index of the visible leaf in its object's ``CSGNode.program()`` leaves (0 for a
        primitive object), -1 on the background (int32)."""
        if "leaf" not in self._lazy:
            self._lazy["leaf"] = self._leaf_of[self._label + 1]
        return self._lazy["leaf"]

    def _repr_mimebundle_(self, include: Any = None, exclude: Any = None) -> dict[str, Any]:
        """Rich display in Jupyter: a small PNG image (see :mod:`isocsg.interop.notebook`)."""
        return late("mimebundle")(self, include, exclude)

    def _repr_png_(self) -> bytes | None:
        """A small PNG image of the object (see :mod:`isocsg.interop.notebook`)."""
        return late("mimebundle")(self, ("image/png",)).get("image/png")

    @property
    def depth(self) -> NDArray[np.float64]:
        """Camera depth (along the view direction) of the visible point; ``inf`` on the background."""
        if "depth" not in self._lazy:
            d = np.empty(self._key.shape)
            key_to_depth(np.where(self._label >= 0, self._key, np.inf), not self.camera.orthographic, d)
            self._lazy["depth"] = d
        return self._lazy["depth"]
