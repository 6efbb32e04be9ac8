"""Pinhole (and optional orthographic) camera, exactly as in the conventions.

Frame: ``f = normalize(target - eye)``, ``r = normalize(f x up)``, ``u = r x f``.
Pixel (row i, column j), row 0 at the top, centres at +0.5::

    x = (2 (j + 0.5) / W - 1) tan(fov/2) (W / H)
    y = (1 - 2 (i + 0.5) / H) tan(fov/2)
    direction = normalize(f + x r + y u)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._validation import (
    MAX_ABS_COORD,
    MAX_PIXELS,
    MIN_FOV,
    Vec3,
    integer,
    length_floor,
    nonzero_vector3,
    scalar,
    show,
    vector3,
)
from .errors import InvalidParameterError

__all__ = ["Camera", "MAX_IMAGE_SIDE", "MAX_PIXELS", "MIN_FOV"]

#: Largest accepted image side in pixels (a 16k x 16k float image is 1 GiB).
MAX_IMAGE_SIDE = 16384


@dataclass(frozen=True, slots=True)
class Camera:
    """A pinhole camera.

    Parameters
    ----------
    eye, target : array_like, shape (3,)
        Viewpoint and the point looked at (distinct).
    up : array_like, shape (3,), default (0, 0, 1)
        Not parallel to ``target - eye``.
    fov : float, default 40
        Vertical field of view in degrees, 0.01 .. 179.
    width, height : int, default 512
        Image size in pixels, 1 .. 16384 each and at most 4096 x 4096
        pixels in all (:data:`MAX_PIXELS`).
    orthographic : bool, default False
        Use parallel rays; ``height_m`` is then the world height of the view.
    height_m : float, default 1
        At least 1e-9 x max(1, largest |coordinate| of the eye), at most 1e12.

    Raises
    ------
    InvalidParameterError
        On non-finite vectors, ``eye == target``, ``up`` parallel to the view
        direction, a field of view outside [0.01, 179], an absurd image size,
        a non-boolean ``orthographic`` or a bad ``height_m``.

    Examples
    --------
    >>> cam = Camera((0, -5, 0), (0, 0, 0), width=4, height=2)
    >>> cam.ray_directions().shape
    (2, 4, 3)
    """

    eye: Vec3
    target: Vec3
    up: Vec3 = (0.0, 0.0, 1.0)
    fov: float = 40.0
    width: int = 512
    height: int = 512
    orthographic: bool = False
    height_m: float = 1.0

    def __post_init__(self) -> None:
        err = InvalidParameterError
        eye = vector3("camera.eye", self.eye, error=err)
        target = vector3("camera.target", self.target, error=err)
        up = nonzero_vector3("camera.up", self.up, error=err)
        if np.linalg.norm(np.subtract(target, eye)) <= 1e-12 * (1 + np.linalg.norm(eye)):
            raise err(f"camera.target must differ from camera.eye, both are {eye}")
        f = np.subtract(target, eye)
        f = f / np.linalg.norm(f)
        un = np.asarray(up) / np.linalg.norm(up)
        if np.linalg.norm(np.cross(f, un)) < 1e-9:
            raise err(f"camera.up {up} must not be parallel to the view direction {tuple(f.round(6).tolist())}")
        object.__setattr__(self, "eye", eye)
        object.__setattr__(self, "target", target)
        object.__setattr__(self, "up", up)
        fov = scalar("camera.fov", self.fov, low=0.0, high=179.0, error=err)
        if fov < MIN_FOV:  # narrower views give every pixel the same ray in float64
            raise err(f"camera.fov must be >= {MIN_FOV:g} degrees, got {fov:g}")
        object.__setattr__(self, "fov", fov)
        width = integer("camera.width", self.width, low=1, high=MAX_IMAGE_SIDE, error=err)
        height = integer("camera.height", self.height, low=1, high=MAX_IMAGE_SIDE, error=err)
        if width * height > MAX_PIXELS:
            raise err(f"camera.width x camera.height must be at most {MAX_PIXELS} pixels, got {width} x {height}")
        object.__setattr__(self, "width", width)
        object.__setattr__(self, "height", height)
        if not isinstance(self.orthographic, (bool, np.bool_)):
            raise err(f"camera.orthographic must be true or false, got {show(self.orthographic)}")
        object.__setattr__(self, "orthographic", bool(self.orthographic))
        height_m = scalar("camera.height_m", self.height_m, low=0.0, high=MAX_ABS_COORD, error=err)
        floor = length_floor(eye)
        if self.orthographic and height_m < floor:  # only an orthographic view uses it
            raise err(f"camera.height_m must be >= {floor:g} (the smallest length at this position), got {height_m:g}")
        object.__setattr__(self, "height_m", height_m)

    # ------------------------------------------------------------------ frame
    @property
    def frame(self) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
        """The unit vectors ``(f, r, u)``: forward, right and up."""
        f = np.subtract(self.target, self.eye)
        f = f / np.linalg.norm(f)
        r = np.cross(f, self.up)
        r = r / np.linalg.norm(r)
        return f, r, np.cross(r, f)

    @property
    def eye_array(self) -> NDArray[np.float64]:
        """The eye as a float64 array."""
        return np.asarray(self.eye, dtype=np.float64)

    @property
    def tan_half_fov(self) -> float:
        """``tan(fov / 2)``."""
        return math.tan(math.radians(self.fov) / 2)

    @property
    def aspect(self) -> float:
        """``width / height``."""
        return self.width / self.height

    def with_view(self, eye: ArrayLike, target: ArrayLike | None = None) -> Camera:
        """The same camera moved to a new eye (and optionally target)."""
        return Camera(
            tuple(np.asarray(eye, dtype=float)),  # type: ignore[arg-type]
            self.target if target is None else tuple(np.asarray(target, dtype=float)),  # type: ignore[arg-type]
            self.up, self.fov, self.width, self.height, self.orthographic, self.height_m,
        )

    def with_size(self, width: int, height: int) -> Camera:
        """The same view at another image size."""
        return Camera(self.eye, self.target, self.up, self.fov, width, height, self.orthographic, self.height_m)

    # ------------------------------------------------------------------- rays
    def pixel_coordinates(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Image-plane ``x`` (shape (W,)) and ``y`` (shape (H,)) of the pixel centres."""
        j = np.arange(self.width) + 0.5
        i = np.arange(self.height) + 0.5
        if self.orthographic:
            half_h = self.height_m / 2
            return (2 * j / self.width - 1) * half_h * self.aspect, (1 - 2 * i / self.height) * half_h
        t = self.tan_half_fov
        return (2 * j / self.width - 1) * t * self.aspect, (1 - 2 * i / self.height) * t

    def ray_directions(self) -> NDArray[np.float64]:
        """Unit ray directions, shape (H, W, 3), row 0 at the top."""
        f, r, u = self.frame
        x, y = self.pixel_coordinates()
        if self.orthographic:
            return np.broadcast_to(f, (self.height, self.width, 3)).copy()
        d = f[None, None, :] + x[None, :, None] * r[None, None, :] + y[:, None, None] * u[None, None, :]
        return d / np.linalg.norm(d, axis=-1, keepdims=True)

    def ray_origins(self) -> NDArray[np.float64]:
        """Ray origins, shape (H, W, 3): the eye, or the image plane when orthographic."""
        if not self.orthographic:
            return np.broadcast_to(self.eye_array, (self.height, self.width, 3)).copy()
        _, r, u = self.frame
        x, y = self.pixel_coordinates()
        return self.eye_array + x[None, :, None] * r + y[:, None, None] * u

    # ------------------------------------------------------------- projection
    def project(self, points: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
        """Project world points to continuous pixel coordinates.

        Returns
        -------
        col, row : ndarray, shape (n,)
            Continuous pixel coordinates; pixel (i, j) has its centre at
            ``(row, col) = (i + 0.5, j + 0.5)``.
        depth : ndarray, shape (n,)
            Distance along the forward axis ``f`` (``<= 0`` behind the eye).
        """
        p = np.asarray(points, dtype=np.float64).reshape(-1, 3) - self.eye_array
        f, r, u = self.frame
        z = p @ f
        xr, yu = p @ r, p @ u
        if self.orthographic:
            half_h = self.height_m / 2
            x, y = xr / (half_h * self.aspect), yu / half_h
        else:
            with np.errstate(divide="ignore", invalid="ignore"):
                x = xr / (z * self.tan_half_fov * self.aspect)
                y = yu / (z * self.tan_half_fov)
        col = (x + 1) * self.width / 2
        row = (1 - y) * self.height / 2
        return col, row, z

    def to_dict(self) -> dict[str, Any]:
        """Scene-file mapping of the ``[camera]`` table."""
        return {
            "eye": list(self.eye), "target": list(self.target), "up": list(self.up),
            "fov": self.fov, "width": self.width, "height": self.height,
        }
