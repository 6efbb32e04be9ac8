"""2D affine transforms of shapes, with OpenSCAD's semantics, applied once per leaf.

A transformed tree is the same tree over transformed leaves (affine maps
commute with the Booleans), so :func:`transform2d` rebuilds the tree with an
explicit stack and maps each leaf exactly (see :mod:`isocsg.shapes2d.leaves`).
Angles are in degrees; multiples of 90 degrees give exact matrices.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidGeometryError
from ._checks import number, points2, vector2
from .shape import Shape2D, fold

__all__ = ["transform2d", "translate2d", "rotate2d", "scale2d", "mirror2d", "affine2d", "rotation_matrix"]


def affine2d(matrix: Any, *, name: str = "matrix") -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """``(A, t)`` of a 2x3 ``[A | t]`` or 3x3 affine matrix (last row ``[0, 0, 1]``), ``A`` invertible."""
    try:
        m = np.asarray(matrix, dtype=np.float64)
    except (ValueError, TypeError):
        raise InvalidGeometryError(
            f"{name} must be a 2x3 or 3x3 matrix of numbers, got {type(matrix).__name__}"
        ) from None
    if m.shape not in ((2, 3), (3, 3)):
        raise InvalidGeometryError(f"{name} must have shape (2, 3) or (3, 3), got {m.shape}")
    points2(name, m.reshape(-1, 1).repeat(2, axis=1))  # finite, bounded
    if m.shape == (3, 3) and not np.array_equal(m[2], [0.0, 0.0, 1.0]):
        raise InvalidGeometryError(f"{name} must have the last row [0, 0, 1], got {m[2].tolist()}")
    A, t = m[:2, :2].copy(), m[:2, 2].copy()
    det = float(np.linalg.det(A))
    big = float(np.max(np.abs(A)))
    if not abs(det) > 1e-12 * big * big:
        raise InvalidGeometryError(f"{name} must be invertible (a shape cannot be flattened), got determinant {det:g}")
    return A, t


def transform2d(shape: Shape2D, matrix: Any) -> Shape2D:
    """The image of ``shape`` under ``x -> A x + t`` (``matrix`` as in :func:`affine2d`).

    Examples
    --------
    >>> from isocsg.shapes2d import circle
    >>> transform2d(circle(1), [[2, 0, 1], [0, 2, 0]])
    Circle(center=(1.0, 0.0), radius=2.0)
    >>> type(transform2d(circle(1), [[2, 0, 0], [0, 1, 0]])).__name__
    'Ellipse'
    """
    A, t = affine2d(matrix)
    return _apply(shape, A, t)


def _apply(shape: Shape2D, A: NDArray[np.float64], t: NDArray[np.float64]) -> Shape2D:
    return fold(shape, lambda leaf: leaf._affine(A, t), lambda op, node, kids: type(node)(tuple(kids)))  # type: ignore[attr-defined, call-arg]


def translate2d(shape: Shape2D, v: Any) -> Shape2D:
    """``shape`` moved by ``v = [x, y]``."""
    x, y = vector2("translate.v", v)
    return _apply(shape, np.eye(2), np.array([x, y]))


def _cos_sin(degrees: float) -> tuple[float, float]:
    q, r = divmod(degrees, 90.0)
    if r == 0.0:
        return [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)][int(q) % 4]
    a = math.radians(degrees)
    return math.cos(a), math.sin(a)


def rotation_matrix(angle: float) -> NDArray[np.float64]:
    """The counter-clockwise rotation by ``angle`` degrees (exact at multiples of 90)."""
    c, s = _cos_sin(angle)
    return np.array([[c, -s], [s, c]])


def rotate2d(shape: Shape2D, angle: Any) -> Shape2D:
    """``shape`` rotated counter-clockwise by ``angle`` degrees about the origin.

    OpenSCAD's ``rotate(a)`` and ``rotate([0, 0, a])`` of a 2D object.
    """
    if isinstance(angle, (list, tuple, np.ndarray)):
        vals = [number(f"rotate.angle[{k}]", a) for k, a in enumerate(angle)]
        if len(vals) != 3 or vals[0] != 0 or vals[1] != 0:
            raise InvalidGeometryError(f"rotate.angle of a 2D shape must be a number or [0, 0, a], got {vals}")
        angle = vals[2]
    return _apply(shape, rotation_matrix(number("rotate.angle", angle)), np.zeros(2))


def scale2d(shape: Shape2D, s: Any) -> Shape2D:
    """``shape`` scaled about the origin by a number or ``[sx, sy]`` (non-zero: a flattened shape is refused)."""
    if isinstance(s, (list, tuple, np.ndarray)):
        sx, sy = vector2("scale.s", s[:2] if len(s) == 3 else s)
    else:
        sx = sy = number("scale.s", s)
    if sx == 0 or sy == 0:
        raise InvalidGeometryError(f"scale.s must be non-zero in x and y, got [{sx:g}, {sy:g}]")
    return _apply(shape, np.diag([sx, sy]), np.zeros(2))


def mirror2d(shape: Shape2D, v: Any) -> Shape2D:
    """The mirror image across the line through the origin with normal ``v`` (OpenSCAD's ``mirror([x, y])``)."""
    x, y = vector2("mirror.v", v[:2] if isinstance(v, (list, tuple, np.ndarray)) and len(v) == 3 else v)
    n2 = x * x + y * y
    if n2 == 0:
        return shape  # OpenSCAD: mirror([0, 0]) leaves the object as it is
    n = np.array([x, y])
    return _apply(shape, np.eye(2) - 2.0 * np.outer(n, n) / n2, np.zeros(2))
