"""Input checks of the 2D shapes: every message names the field, says what was expected and what came.

The bounds are those of the rest of isocsg (coordinates within +-1e12, at most
65536 vertices per polygon), repeated here so that the 2D package depends on
the public API and :mod:`isocsg.errors` only.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidGeometryError

__all__ = ["MAX_ABS_COORD", "MAX_VERTICES", "MAX_SEGMENTS", "number", "positive", "points2", "vector2", "flag"]

#: Largest absolute coordinate accepted (as in the rest of isocsg).
MAX_ABS_COORD = 1e12
#: Most vertices in one polygon (as in the rest of isocsg).
MAX_VERTICES = 65536
#: Most segments of a polygonised full circle (``resolution`` of conversions).
MAX_SEGMENTS = 1 << 20


def _show(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def number(name: str, value: Any, *, low: float | None = None, high: float | None = None, strict: bool = True) -> float:
    """A finite float; ``low < value`` (``<=`` when not ``strict``) and ``value <= high`` when given."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise InvalidGeometryError(f"{name} must be a number, got {_show(value)}")
    try:
        x = float(value)
    except OverflowError:
        raise InvalidGeometryError(f"{name} must be a finite number, got {_show(value)}") from None
    if not math.isfinite(x) or abs(x) > MAX_ABS_COORD:
        raise InvalidGeometryError(f"{name} must be a finite number within +-{MAX_ABS_COORD:g}, got {_show(value)}")
    if low is not None and (x <= low if strict else x < low):
        raise InvalidGeometryError(f"{name} must be {'>' if strict else '>='} {low:g}, got {x:g}")
    if high is not None and x > high:
        raise InvalidGeometryError(f"{name} must be <= {high:g}, got {x:g}")
    return x


def positive(name: str, value: Any) -> float:
    """A finite number > 0."""
    return number(name, value, low=0.0)


def flag(name: str, value: Any) -> bool:
    """A boolean (numbers are not booleans here)."""
    if not isinstance(value, (bool, np.bool_)):
        raise InvalidGeometryError(f"{name} must be a boolean, got {_show(value)}")
    return bool(value)


def points2(name: str, value: Any, *, minimum: int = 1) -> NDArray[np.float64]:
    """An array of shape (n, 2), finite, within the coordinate bound, ``minimum <= n <= MAX_VERTICES``."""
    if isinstance(value, (str, bytes)):
        raise InvalidGeometryError(f"{name} must be a list of [x, y] points, got {_show(value)}")
    try:
        arr = np.asarray(value)
    except (ValueError, TypeError):
        raise InvalidGeometryError(f"{name} must be a list of [x, y] points, got {_show(value)}") from None
    if arr.dtype == object or arr.dtype.kind not in "iuf":
        raise InvalidGeometryError(f"{name} must hold numbers, got {_show(value)}")
    if arr.ndim != 2 or arr.shape[1] != 2:
        raise InvalidGeometryError(f"{name} must have shape (n, 2), got {arr.shape}")
    if arr.shape[0] < minimum:
        raise InvalidGeometryError(f"{name} must have at least {minimum} points, got {arr.shape[0]}")
    if arr.shape[0] > MAX_VERTICES:
        raise InvalidGeometryError(f"{name} must have at most {MAX_VERTICES} points, got {arr.shape[0]}")
    arr = arr.astype(np.float64)
    if not np.all(np.isfinite(arr)):
        raise InvalidGeometryError(f"{name} must hold finite numbers, got NaN or inf")
    if arr.size and np.max(np.abs(arr)) > MAX_ABS_COORD:
        raise InvalidGeometryError(f"{name} must hold coordinates within +-{MAX_ABS_COORD:g}")
    return arr


def vector2(name: str, value: Any) -> tuple[float, float]:
    """A pair of finite numbers."""
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or len(value) != 2:
        raise InvalidGeometryError(f"{name} must be a pair [x, y], got {_show(value)}")
    return (number(f"{name}[0]", value[0]), number(f"{name}[1]", value[1]))
