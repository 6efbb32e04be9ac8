"""Input checks shared by every public constructor and function.

Each helper takes the *name* of the field it checks, so that messages name the
offending field: ``Sphere.center must be finite, got (nan, 0.0, 0.0)``.
The error class is chosen by the caller (geometry, light or parameter error).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .errors import InvalidGeometryError

# Sizes beyond this are rejected as absurd: they would overflow float64
# arithmetic in squared distances long before producing a useful image.
MAX_ABS_COORD = 1e12

Vec3 = tuple[float, float, float]


def vector3(name: str, value: Any, *, error: type[Exception] = InvalidGeometryError) -> Vec3:
    """Return ``value`` as a finite 3-tuple of floats, or raise ``error``."""
    try:
        arr = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise error(f"{name} must be 3 numbers, got {value!r}") from None
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
    """Return ``value`` as a finite float within the given bounds, or raise ``error``."""
    if isinstance(value, bool):
        raise error(f"{name} must be a number, got {value!r}")
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise error(f"{name} must be a number, got {value!r}") from None
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
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        if isinstance(value, float) and value.is_integer():
            value = int(value)
        else:
            raise error(f"{name} must be an integer, got {value!r}")
    v = int(value)
    if v < low or v > high:
        raise error(f"{name} must be between {low} and {high}, got {v}")
    return v


def points_array(
    name: str,
    value: ArrayLike,
    *,
    columns: int = 3,
    min_rows: int = 0,
    error: type[Exception] = InvalidGeometryError,
) -> NDArray[np.float64]:
    """Return ``value`` as a finite float64 array of shape (n, columns)."""
    try:
        arr = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise error(f"{name} must be an array of numbers with shape (n, {columns})") from None
    if arr.ndim == 1 and arr.shape == (columns,):
        arr = arr[None, :]
    if arr.ndim != 2 or arr.shape[1] != columns:
        raise error(f"{name} must have shape (n, {columns}), got {arr.shape}")
    if arr.shape[0] < min_rows:
        raise error(f"{name} needs at least {min_rows} rows, got {arr.shape[0]}")
    if not np.all(np.isfinite(arr)):
        bad = int(np.argwhere(~np.isfinite(arr))[0][0])
        raise error(f"{name} must be finite, row {bad} is {arr[bad].tolist()}")
    if np.any(np.abs(arr) > MAX_ABS_COORD):
        raise error(f"{name} must lie within +-{MAX_ABS_COORD:g}")
    return arr


def normalize_rows(v: NDArray[np.float64]) -> NDArray[np.float64]:
    """Unit vectors along the rows of ``v`` (rows of zero length stay zero)."""
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return np.divide(v, n, out=np.zeros_like(v), where=n > 0)
