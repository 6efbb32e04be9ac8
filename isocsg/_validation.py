"""Input checks shared by every public constructor and function.

Each helper takes the *name* of the field it checks, so that messages name the
offending field: ``Sphere.center must be finite, got (nan, 0.0, 0.0)``.
The error class is chosen by the caller (geometry, light or parameter error).

The documented limits of isocsg live here, so that every module checks the
same numbers before it allocates anything (README, "Errors": limits).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .errors import InvalidGeometryError, InvalidParameterError

__all__ = [
    "MAX_ABS_COORD",
    "MIN_LENGTH",
    "MIN_ASPECT",
    "MIN_TRUNCUS_ASPECT",
    "MAX_INTENSITY",
    "MAX_LIGHTS",
    "MAX_LIGHT_CONTOURS",
    "MAX_PIXELS",
    "MIN_FOV",
    "MAX_RESOLUTION",
    "MAX_VERTICES",
    "MAX_SCENE_FILE_BYTES",
    "vector3",
    "nonzero_vector3",
    "scalar",
    "integer",
    "points_array",
    "length_floor",
    "light_budget",
    "resolution",
    "show",
]

# Sizes beyond this are rejected as absurd: they would overflow float64
# arithmetic in squared distances long before producing a useful image.
MAX_ABS_COORD = 1e12

#: Smallest length (radius, edge, axis, view height) relative to
#: ``max(1, largest |coordinate| of the primitive's centre)``: below it the
#: surface cannot be told apart from its position in float64.
MIN_LENGTH = 1e-9

#: Smallest extent of an ellipsoid or a torus relative to its largest one: thinner solids have hulls
#: too flat to tessellate. Boxes have no such limit (their slabs are exact at any aspect), and trunci
#: have the far smaller :data:`MIN_TRUNCUS_ASPECT`.
MIN_ASPECT = 1e-5

#: Smallest height of a truncus (cylinder, cone, frustum) relative to its larger radius and back: a
#: coin, a 1e-5 x 3 washer or a 0.001 x 128 rod is a real part. Its rays, volume, sections and mesh
#: were measured exact down to 1e-12 (cylinders against the tests' ray caster, cones by their
#: silhouettes; docs/csg.md "Thin parts"); thinner is not tested, so refused.
MIN_TRUNCUS_ASPECT = 1e-12

#: Largest light intensity, radiance, exposure and material coefficient:
#: their products over every light stay far from float32's range.
MAX_INTENSITY = 1e6

#: Largest number of lights in a scene.
MAX_LIGHTS = 16

#: Largest (point and directional lights) x (contours per family): composite
#: contours of several lights multiply the band count.
MAX_LIGHT_CONTOURS = 1024

#: Largest image (width x height) in pixels: 4096 x 4096.
MAX_PIXELS = 4096 * 4096

#: Smallest vertical field of view in degrees (narrower views round every
#: ray to the same direction).
MIN_FOV = 0.01

#: Largest tessellation resolution of curved occluders (segments around).
MAX_RESOLUTION = 512

#: Largest number of vertices of a polyhedron or light source.
MAX_VERTICES = 65536

#: Largest scene file in bytes (16 MiB), checked before it is read.
MAX_SCENE_FILE_BYTES = 16 * 2**20

Vec3 = tuple[float, float, float]


def show(value: Any, limit: int = 60) -> str:
    """A short ``repr`` for messages (huge integers and long lists are cut)."""
    try:
        text = repr(value)
    except ValueError:  # an integer with more digits than Python prints
        text = f"an integer of about {int(value.bit_length() * 0.30103)} digits"
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _non_number(value: Any) -> str | None:
    """Why ``value`` (a number or nested sequence of them) is not numeric, or None.

    Booleans and strings convert silently with numpy (``True`` -> 1.0,
    ``"2"`` -> 2.0); they are refused here. Plain numeric arrays skip the walk.
    """
    if isinstance(value, np.ndarray):
        kind = value.dtype.kind
        if kind in "iuf":
            return None
        if kind == "b":
            return "booleans are not numbers"
        if kind in "USa":
            return "strings are not numbers"
        if kind != "O":
            return f"{value.dtype} values are not real numbers"
        value = value.tolist()
    stack = [value]
    while stack:
        v = stack.pop()
        if isinstance(v, (bool, np.bool_)):
            return "booleans are not numbers"
        if isinstance(v, (str, bytes)):
            return "strings are not numbers"
        if isinstance(v, (list, tuple)):
            stack.extend(v)
        elif isinstance(v, np.ndarray):
            reason = _non_number(v)
            if reason:
                return reason
        elif v is None or isinstance(v, dict):
            return f"{type(v).__name__} is not a number"
    return None


def _float_array(name: str, value: Any, error: type[Exception], what: str) -> NDArray[np.float64]:
    reason = _non_number(value)
    if reason:
        raise error(f"{name} must be {what}, got {show(value)} ({reason})")
    try:
        return np.asarray(value, dtype=np.float64)
    except OverflowError:
        raise error(f"{name} must be finite, got a number too large for a float") from None
    except (TypeError, ValueError):
        raise error(f"{name} must be {what}, got {show(value)}") from None


def vector3(name: str, value: Any, *, error: type[Exception] = InvalidGeometryError) -> Vec3:
    """Return ``value`` as a finite 3-tuple of floats, or raise ``error``."""
    if isinstance(value, (str, bytes)):
        raise error(f"{name} must be 3 numbers, got {show(value)}")
    arr = _float_array(name, value, error, "3 numbers")
    if arr.shape != (3,):
        raise error(f"{name} must have shape (3,), got {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise error(f"{name} must be finite, got {tuple(arr.tolist())}")
    if np.any(np.abs(arr) > MAX_ABS_COORD):
        raise error(f"{name} must lie within +-{MAX_ABS_COORD:g}, got {tuple(arr.tolist())}")
    return (float(arr[0]), float(arr[1]), float(arr[2]))


def nonzero_vector3(name: str, value: Any, *, error: type[Exception] = InvalidGeometryError) -> Vec3:
    """Like :func:`vector3`, and also reject the zero vector."""
    v = vector3(name, value, error=error)
    if math.hypot(*v) <= 1e-300:
        raise error(f"{name} must be a non-zero vector, got {v}")
    return v


def scalar(
    name: str,
    value: Any,
    *,
    low: float | None = None,
    low_inclusive: bool = False,
    high: float | None = None,
    error: type[Exception] = InvalidGeometryError,
) -> float:
    """Return ``value`` as a finite float within the given bounds, or raise ``error``.

    Booleans and strings are refused even where ``float()`` would take them.
    """
    if isinstance(value, (bool, np.bool_, str, bytes)):
        raise error(f"{name} must be a number, got {show(value)}")
    try:
        v = float(value)
    except OverflowError:
        raise error(f"{name} must be finite, got a number too large for a float ({show(value, 24)})") from None
    except (TypeError, ValueError):
        raise error(f"{name} must be a number, got {show(value)}") from None
    if not math.isfinite(v):
        raise error(f"{name} must be finite, got {v}")
    if low is not None:
        if low_inclusive and v < low:
            raise error(f"{name} must be >= {low:g}, got {v:g}")
        if not low_inclusive and v <= low:
            raise error(f"{name} must be > {low:g}, got {v:g}")
    if high is not None and v > high:
        raise error(f"{name} must be <= {high:g}, got {v:g}")
    return v


def integer(
    name: str,
    value: Any,
    *,
    low: int,
    high: int,
    error: type[Exception] = InvalidGeometryError,
) -> int:
    """Return ``value`` as an int in ``[low, high]``, or raise ``error``."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        if isinstance(value, float) and value.is_integer():
            value = int(value)
        else:
            raise error(f"{name} must be an integer, got {show(value)}")
    v = int(value)
    if v < low or v > high:
        raise error(f"{name} must be between {low} and {high}, got {show(v)}")
    return v


def points_array(
    name: str,
    value: ArrayLike,
    *,
    columns: int = 3,
    min_rows: int = 0,
    max_rows: int | None = None,
    error: type[Exception] = InvalidGeometryError,
) -> NDArray[np.float64]:
    """Return ``value`` as a finite float64 array of shape (n, columns)."""
    if isinstance(value, (str, bytes)):
        raise error(f"{name} must be an array of numbers with shape (n, {columns}), got {show(value)}")
    arr = _float_array(name, value, error, f"an array of numbers with shape (n, {columns})")
    if arr.ndim == 1 and arr.shape == (columns,):
        arr = arr[None, :]
    if arr.ndim != 2 or arr.shape[1] != columns:
        raise error(f"{name} must have shape (n, {columns}), got {arr.shape}")
    if arr.shape[0] < min_rows:
        raise error(f"{name} needs at least {min_rows} rows, got {arr.shape[0]}")
    if max_rows is not None and arr.shape[0] > max_rows:
        raise error(f"{name} must have at most {max_rows} rows, got {arr.shape[0]}")
    if not np.all(np.isfinite(arr)):
        bad = int(np.argwhere(~np.isfinite(arr))[0][0])
        raise error(f"{name} must be finite, row {bad} is {arr[bad].tolist()}")
    if np.any(np.abs(arr) > MAX_ABS_COORD):
        raise error(f"{name} must lie within +-{MAX_ABS_COORD:g}")
    return arr


def length_floor(*positions: Any) -> float:
    """The smallest accepted length near ``positions``: ``MIN_LENGTH * max(1, max |coordinate|)``.

    Examples
    --------
    >>> length_floor((0, 0, 0)), length_floor((0, -1e6, 0))
    (1e-09, 0.001)
    """
    big = max((float(np.max(np.abs(np.asarray(p, dtype=np.float64)))) for p in positions), default=0.0)
    return MIN_LENGTH * max(1.0, big)


def light_budget(n_lights: int, n_contour_lights: int, contours: int, *, where: str = "") -> None:
    """Check the documented light limits before any band is built.

    Parameters
    ----------
    n_lights : int
        Every light of the scene (at most :data:`MAX_LIGHTS`).
    n_contour_lights : int
        Its point and directional lights, each a contour family.
    contours : int
        Contours per family; ``n_contour_lights * contours`` is at most
        :data:`MAX_LIGHT_CONTOURS`.
    where : str
        Prefix of the field names (``"scene."`` or ``""``).

    Raises
    ------
    InvalidParameterError
        Naming ``lights`` or ``render.contours``.
    """
    if n_lights > MAX_LIGHTS:
        raise InvalidParameterError(f"{where}lights must hold at most {MAX_LIGHTS} lights, got {n_lights}")
    if n_contour_lights * contours > MAX_LIGHT_CONTOURS:
        most = max(1, MAX_LIGHT_CONTOURS // max(n_contour_lights, 1))
        raise InvalidParameterError(
            f"render.contours must be at most {most} with {n_contour_lights} point or directional lights "
            f"(lights x contours <= {MAX_LIGHT_CONTOURS}), got {contours}"
        )


def resolution(name: str, value: Any) -> int:
    """A tessellation resolution of curved occluders, 3 .. :data:`MAX_RESOLUTION`."""
    return integer(name, value, low=3, high=MAX_RESOLUTION, error=InvalidParameterError)


def normalize_rows(v: NDArray[np.float64]) -> NDArray[np.float64]:
    """Unit vectors along the rows of ``v`` (rows of zero length stay zero)."""
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return np.divide(v, n, out=np.zeros_like(v), where=n > 0)


RGB = tuple[float, float, float]


def parse_color(value: Any, *, name: str = "color") -> RGB:
    """An sRGB triple in [0, 1] from a vector of 3 or 4 numbers in [0, 1] (alpha is dropped), an
    SVG/CSS colour name or a ``"#rgb"``/``"#rrggbb"`` string.

    Raises
    ------
    InvalidParameterError
        Naming ``name`` and the value, for anything else (an unknown name, a number out of [0, 1],
        NaN).

    Examples
    --------
    >>> parse_color("red"), parse_color([0, 0.5, 1, 0.3])
    ((1.0, 0.0, 0.0), (0.0, 0.5, 1.0))
    """
    if isinstance(value, str):
        from PIL import ImageColor

        try:
            r, g, b = ImageColor.getrgb(value.strip())[:3]
        except ValueError:
            raise InvalidParameterError(f"{name} must be a colour name or #rrggbb, got {value!r}") from None
        return (r / 255.0, g / 255.0, b / 255.0)
    wrong = f"{name} must be 3 or 4 numbers in [0, 1] or a colour name, got {show(value)}"
    try:
        v = np.asarray(value, dtype=np.float64).ravel()
    except (TypeError, ValueError):
        raise InvalidParameterError(wrong) from None
    if v.size not in (3, 4) or not np.all(np.isfinite(v)) or v.min() < 0.0 or v.max() > 1.0:
        raise InvalidParameterError(wrong)
    return (float(v[0]), float(v[1]), float(v[2]))
