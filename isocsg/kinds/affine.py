"""Affine transforms of solids: translate, rotate, scale, mirror and general matrices.

The names are manifold3d's and the semantics OpenSCAD's:

- ``translate(v)`` moves by ``v``;
- ``rotate([a, b, c])`` turns by ``a`` degrees about x, then ``b`` about y, then ``c``
  about z (``Rz(c) Ry(b) Rx(a)``), ``rotate(angle)`` about z, and
  ``rotate(angle, axis=v)`` by ``angle`` degrees about ``v`` (right-hand rule);
- ``scale(s)`` scales by a number or per axis;
- ``mirror(n)`` reflects in the plane through the origin with normal ``n``;
- ``transform(m)`` applies a 4x4 or 3x4 affine matrix (``x -> A x + t``).

Multiples of 90 degrees give exact matrices (cosines and sines of 0 and +-1), as
in OpenSCAD, so that a box turned by 90 degrees stays axis-aligned exactly.

A transform of a primitive is again an exact, analytic primitive (each kind's
``_affine``); a transform of a CSG tree applies to its leaves, walked without
recursion (:meth:`isocsg.csg.tree.CSGNode._affine`).
"""

from __future__ import annotations

import functools
import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import MAX_ABS_COORD, _float_array, show, vector3
from ..errors import InvalidParameterError

__all__ = [
    "MAX_CONDITION",
    "perpendicular_frame",
    "affine_matrix",
    "translation_matrix",
    "rotation_matrix",
    "axis_angle_matrix",
    "scale_matrix",
    "mirror_matrix",
    "rotation_array",
    "similarity_factor",
    "SIMILARITY_TOL_DIGITS",
]

#: Largest accepted condition number (ratio of largest to smallest singular value) of the linear
#: part of a transform; beyond it the image of a solid is too thin to be represented faithfully.
MAX_CONDITION = 1e6

#: Relative tolerance under which a linear map counts as a similarity (rotation, reflection,
#: uniform scale) and a 3x3 matrix as a rotation.
SIMILARITY_TOL = 1e-9
#: The looser tolerance of kinds that only a similarity keeps (a torus): OpenSCAD writes matrices
#: with 6 significant digits, so its turns are orthogonal only to about 1e-6; such a map is taken as
#: the similarity it was meant to be (the solid moves by about 1e-6 of its size, OpenSCAD's own digits).
SIMILARITY_TOL_DIGITS = 1e-5


def _array(name: str, value: Any, shape: tuple[int, ...] | None = None) -> NDArray[np.float64]:
    if isinstance(value, (str, bytes)):
        raise InvalidParameterError(f"{name} must be numbers, got {show(value)}")
    # booleans, strings and numbers too large for a float are refused (not converted)
    a = _float_array(name, value, InvalidParameterError, "numbers")
    if shape is not None and a.shape != shape:
        raise InvalidParameterError(f"{name} must have shape {shape}, got {a.shape}")
    if not np.all(np.isfinite(a)):
        raise InvalidParameterError(f"{name} must be finite, got {show(value)}")
    return a


def _degrees_cos_sin(deg: float) -> tuple[float, float]:
    """Cosine and sine of an angle in degrees, exact at multiples of 90 degrees."""
    q = deg / 90.0
    if q == round(q):
        k = int(round(q)) % 4
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[k]
    r = math.radians(deg)
    return math.cos(r), math.sin(r)


def affine_matrix(matrix: ArrayLike, *, name: str = "matrix") -> NDArray[np.float64]:
    """Validate a 4x4 or 3x4 affine matrix and return it as a 4x4 array.

    Parameters
    ----------
    matrix : array_like, shape (4, 4) or (3, 4)
        ``[A | t]`` mapping ``x`` to ``A x + t``; a 4x4 matrix must have the last
        row ``[0, 0, 0, 1]``.
    name : str
        The field named in error messages.

    Returns
    -------
    ndarray, shape (4, 4)

    Raises
    ------
    InvalidParameterError
        If the matrix has another shape, holds non-finite numbers, is not affine
        (bad last row), is singular, or has a condition number above
        :data:`MAX_CONDITION`, or a translation beyond the coordinate limit.

    Examples
    --------
    >>> affine_matrix([[2, 0, 0, 1], [0, 2, 0, 0], [0, 0, 2, 0]])[:, 3].tolist()
    [1.0, 0.0, 0.0, 1.0]
    """
    m = _array(name, matrix)
    if m.shape not in ((4, 4), (3, 4)):
        raise InvalidParameterError(f"{name} must have shape (4, 4) or (3, 4), got {m.shape}")
    if m.shape == (4, 4):
        if not np.array_equal(m[3], [0.0, 0.0, 0.0, 1.0]):
            raise InvalidParameterError(f"{name} must be affine (last row [0, 0, 0, 1]), got {m[3].tolist()}")
    else:
        m = np.vstack([m, [0.0, 0.0, 0.0, 1.0]])
    if np.any(np.abs(m[:3, 3]) > MAX_ABS_COORD):
        raise InvalidParameterError(f"{name} translation must lie within +-{MAX_ABS_COORD:g}, got {m[:3, 3].tolist()}")
    sv = np.linalg.svd(m[:3, :3], compute_uv=False)
    if not sv[-1] > 0.0:
        raise InvalidParameterError(f"{name} must be invertible, got a singular linear part {m[:3, :3].tolist()}")
    cond = float(sv[0] / sv[-1])
    if cond > MAX_CONDITION:
        raise InvalidParameterError(
            f"{name} must have a condition number <= {MAX_CONDITION:g} "
            f"(largest over smallest singular value), got {cond:g}"
        )
    if sv[0] > MAX_ABS_COORD or sv[-1] < 1.0 / MAX_ABS_COORD:
        raise InvalidParameterError(f"{name} scales by {sv[-1]:g} to {sv[0]:g}, outside the limits 1e-12 to 1e12")
    return m


def translation_matrix(v: ArrayLike) -> NDArray[np.float64]:
    """The 4x4 matrix of a translation by ``v``."""
    m = np.eye(4)
    m[:3, 3] = vector3("translate(v)", v, error=InvalidParameterError)
    return m


def rotation_array(degrees: ArrayLike) -> NDArray[np.float64]:
    """The 3x3 rotation ``Rz(c) Ry(b) Rx(a)`` for Euler angles ``[a, b, c]`` in degrees (OpenSCAD)."""
    a, b, c = _array("rotate(v)", degrees, (3,)).tolist()
    ca, sa = _degrees_cos_sin(a)
    cb, sb = _degrees_cos_sin(b)
    cc, sc = _degrees_cos_sin(c)
    rx = np.array([[1.0, 0.0, 0.0], [0.0, ca, -sa], [0.0, sa, ca]])
    ry = np.array([[cb, 0.0, sb], [0.0, 1.0, 0.0], [-sb, 0.0, cb]])
    rz = np.array([[cc, -sc, 0.0], [sc, cc, 0.0], [0.0, 0.0, 1.0]])
    return rz @ ry @ rx


def rotation_matrix(degrees: ArrayLike) -> NDArray[np.float64]:
    """The 4x4 matrix of :func:`rotation_array`."""
    m = np.eye(4)
    m[:3, :3] = rotation_array(degrees)
    return m


def axis_angle_matrix(angle: float, axis: ArrayLike) -> NDArray[np.float64]:
    """The 4x4 matrix of a rotation by ``angle`` degrees about ``axis`` (right-hand rule)."""
    ang = float(_array("rotate(angle)", angle, ()))
    k = _array("rotate(axis)", axis, (3,))
    norm = float(np.linalg.norm(k))
    if not norm > 0.0:
        raise InvalidParameterError(f"rotate(axis) must be a non-zero vector, got {k.tolist()}")
    k = k / norm
    c, s = _degrees_cos_sin(ang)
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    m = np.eye(4)
    m[:3, :3] = c * np.eye(3) + s * K + (1.0 - c) * np.outer(k, k)
    return m


def scale_matrix(s: ArrayLike) -> NDArray[np.float64]:
    """The 4x4 matrix of a scale by a number or by ``[sx, sy, sz]``."""
    a = _array("scale(s)", s)
    if a.shape == ():
        a = np.full(3, float(a))
    if a.shape != (3,):
        raise InvalidParameterError(f"scale(s) must be a number or have shape (3,), got {a.shape}")
    if np.any(a == 0.0):
        raise InvalidParameterError(f"scale(s) must be non-zero in every axis, got {a.tolist()}")
    return np.diag([*a.tolist(), 1.0])


def mirror_matrix(normal: ArrayLike) -> NDArray[np.float64]:
    """The 4x4 matrix of the reflection in the plane through the origin with ``normal``."""
    n = np.asarray(vector3("mirror(normal)", normal, error=InvalidParameterError))
    nn = float(n @ n)
    if not nn > 0.0:
        raise InvalidParameterError(f"mirror(normal) must be a non-zero vector, got {n.tolist()}")
    m = np.eye(4)
    m[:3, :3] -= 2.0 * np.outer(n, n) / nn
    return m


def similarity_factor(A: NDArray[np.float64], tol: float = SIMILARITY_TOL) -> float | None:
    """The scale ``s`` when ``A = s Q`` with ``Q`` orthogonal (rotation or reflection) within the
    relative tolerance ``tol`` (on ``A^T A``), else None."""
    return _similarity(np.ascontiguousarray(A, dtype=np.float64).tobytes(), float(tol))


@functools.lru_cache(maxsize=64)
def _similarity(key: bytes, tol: float) -> float | None:
    # one transform maps every leaf of a tree with the same matrix: decided once
    A = np.frombuffer(key, dtype=np.float64).reshape(3, 3)
    g = A.T @ A
    s2 = float(np.trace(g)) / 3.0
    if np.max(np.abs(g - s2 * np.eye(3))) <= tol * s2:
        return math.sqrt(s2)
    return None


def perpendicular_frame(axis: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Two unit vectors that complete ``axis`` (unit) to a right-handed frame."""
    # np.cross's own products, written out: the same bits, without its overhead per call
    # (a convex hull asks for one frame per face)
    a0, a1, a2 = float(axis[0]), float(axis[1]), float(axis[2])
    h0, h1, h2 = (1.0, 0.0, 0.0) if abs(a0) < 0.9 else (0.0, 1.0, 0.0)
    u = np.array([a1 * h2 - a2 * h1, a2 * h0 - a0 * h2, a0 * h1 - a1 * h0])
    u /= np.linalg.norm(u)
    u0, u1, u2 = float(u[0]), float(u[1]), float(u[2])
    return u, np.array([a1 * u2 - a2 * u1, a2 * u0 - a0 * u2, a0 * u1 - a1 * u0])
