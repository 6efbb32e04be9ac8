"""Camera projection for the fills: homogeneous screen coordinates and depth keys.

World points map to homogeneous screen coordinates ``(X, Y, W, D)`` that are
affine in the point: ``col = X / W``, ``row = Y / W`` and ``D`` is the camera
depth (distance along the forward axis). For the pinhole camera ``W = D``; for
the orthographic camera ``W = 1``. The depth buffers hold a *depth key* that is
linear in screen space and grows with depth, ``-1 / D`` for the pinhole camera
and ``D`` for the orthographic one (:func:`key_to_depth` turns it back).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._jit import njit
from ..camera import Camera
from .jit import RAW

__all__ = ["homogeneous", "near_distance", "camera_affine", "project_kernel", "key_to_depth", "NEAR_RELATIVE"]

# Relative near-plane distance: surfaces closer to the eye than this fraction of
# the scene's depth range are clipped away (the ray caster's ``t > 0``).
NEAR_RELATIVE = 1e-9


def homogeneous(camera: Camera, points: ArrayLike) -> NDArray[np.float64]:
    """Homogeneous screen coordinates of world points.

    Parameters
    ----------
    camera : Camera
    points : array_like, shape (n, 3)

    Returns
    -------
    ndarray, shape (4, n)
        Rows ``X, Y, W, D`` with ``col = X / W``, ``row = Y / W`` (continuous
        pixel coordinates as :meth:`Camera.project`) and ``D`` the depth along
        the view direction. All four are affine in the world point.

    Examples
    --------
    >>> cam = Camera((0, -5, 0), (0, 0, 0), width=4, height=4)
    >>> h = homogeneous(cam, [[0, 0, 0]])
    >>> (h[0] / h[2]).tolist(), (h[1] / h[2]).tolist(), h[3].tolist()
    ([2.0], [2.0], [5.0])
    """
    p = np.asarray(points, dtype=np.float64).reshape(-1, 3) - camera.eye_array
    f, r, u = camera.frame
    m = np.stack([r, u, f])  # camera-space rows
    xr, yu, z = m @ p.T
    w2, h2 = camera.width / 2.0, camera.height / 2.0
    out = np.empty((4, len(p)))
    if camera.orthographic:
        half_h = camera.height_m / 2
        out[0] = (xr / (half_h * camera.aspect) + 1.0) * w2
        out[1] = (1.0 - yu / half_h) * h2
        out[2] = 1.0
    else:
        t = camera.tan_half_fov
        out[0] = (xr / (t * camera.aspect) + z) * w2
        out[1] = (z - yu / t) * h2
        out[2] = z
    out[3] = z
    return out


def near_distance(depths: NDArray[np.float64]) -> float:
    """Near-plane depth for geometry with the given camera depths (tiny, > 0)."""
    scale = float(np.max(np.abs(depths))) if len(depths) else 1.0
    return NEAR_RELATIVE * max(scale, 1e-300)


def camera_affine(camera: Camera) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The affine map of :func:`homogeneous` as a matrix and an offset.

    Parameters
    ----------
    camera : Camera

    Returns
    -------
    a : ndarray, shape (4, 3)
    b : ndarray, shape (4,)
        ``(X, Y, W, D) = a @ (p - camera.eye) + b`` for a world point ``p``.

    Examples
    --------
    >>> cam = Camera((0, -5, 0), (0, 0, 0), width=4, height=4)
    >>> a, b = camera_affine(cam)
    >>> (a @ (np.array([0.0, 0.0, 0.0]) - cam.eye_array) + b).round(12).tolist()
    [10.0, 10.0, 5.0, 5.0]
    """
    # camera.frame in plain floats (numpy's cross on 3-vectors costs more than the projection).
    ex, ey, ez = (float(c) for c in camera.eye)
    tx, ty, tz = (float(c) for c in camera.target)
    ux, uy, uz = (float(c) for c in camera.up)
    fx, fy, fz = tx - ex, ty - ey, tz - ez
    n = math.sqrt(fx * fx + fy * fy + fz * fz)
    fx, fy, fz = fx / n, fy / n, fz / n
    rx, ry, rz = fy * uz - fz * uy, fz * ux - fx * uz, fx * uy - fy * ux
    n = math.sqrt(rx * rx + ry * ry + rz * rz)
    rx, ry, rz = rx / n, ry / n, rz / n
    f = np.array([fx, fy, fz])
    r = np.array([rx, ry, rz])
    u = np.array([ry * fz - rz * fy, rz * fx - rx * fz, rx * fy - ry * fx])
    w2, h2 = camera.width / 2.0, camera.height / 2.0
    a = np.zeros((4, 3))
    b = np.zeros(4)
    if camera.orthographic:
        half_h = camera.height_m / 2
        a[0] = r * (w2 / (half_h * camera.aspect))
        a[1] = -u * (h2 / half_h)
        b[:3] = w2, h2, 1.0
    else:
        t = camera.tan_half_fov
        a[0] = r * (w2 / (t * camera.aspect)) + f * w2
        a[1] = f * h2 - u * (h2 / t)
        a[2] = f
    a[3] = f
    return a, b


@njit(**RAW)
def project_kernel(
    vertices: NDArray[np.float64], eye: NDArray[np.float64], a: NDArray[np.float64], b: NDArray[np.float64],
    perspective: bool, out: NDArray[np.float64], v0: int, v1: int,
) -> float:
    """Rows ``X, Y, W, D, col, row, key`` of ``out`` (7, V) for vertices ``v0 .. v1 - 1``; returns their ``max |D|``.

    ``col``, ``row`` and the depth key are meaningful only for vertices in
    front of the near plane (the fills never read the others).
    """
    far = 0.0
    # Locals: the stores to ``out`` might alias the matrix, which would be reloaded per vertex.
    ex, ey, ez = eye[0], eye[1], eye[2]
    a00, a01, a02, b0 = a[0, 0], a[0, 1], a[0, 2], b[0]
    a10, a11, a12, b1 = a[1, 0], a[1, 1], a[1, 2], b[1]
    a20, a21, a22, b2 = a[2, 0], a[2, 1], a[2, 2], b[2]
    a30, a31, a32, b3 = a[3, 0], a[3, 1], a[3, 2], b[3]
    for v in range(v0, v1):
        dx = vertices[v, 0] - ex
        dy = vertices[v, 1] - ey
        dz = vertices[v, 2] - ez
        x = a00 * dx + a01 * dy + a02 * dz + b0
        y = a10 * dx + a11 * dy + a12 * dz + b1
        w = a20 * dx + a21 * dy + a22 * dz + b2
        d = a30 * dx + a31 * dy + a32 * dz + b3
        out[0, v] = x
        out[1, v] = y
        out[2, v] = w
        out[3, v] = d
        inv = 1.0 / w if w != 0.0 else 0.0
        out[4, v] = x * inv
        out[5, v] = y * inv
        out[6, v] = -inv if perspective else d
        if abs(d) > far:
            far = abs(d)
    return far


@njit(cache=True)
def key_to_depth(key: NDArray[np.float64], perspective: bool, out: NDArray[np.float64]) -> None:
    """Camera depth from the depth key of :func:`fill_kernel` (inf stays inf)."""
    flat = key.ravel()
    o = out.ravel()
    for k in range(flat.shape[0]):
        q = flat[k]
        if not math.isfinite(q):
            o[k] = q if not perspective else (np.inf if q > 0 else -np.inf)
        elif perspective:
            o[k] = -1.0 / q
        else:
            o[k] = q


@project_kernel.twin
def _project_numpy(
    vertices: NDArray[np.float64], eye: NDArray[np.float64], a: NDArray[np.float64], b: NDArray[np.float64],
    perspective: bool, out: NDArray[np.float64], v0: int, v1: int,
) -> float:
    """:func:`project_kernel` of every vertex at once (the same sums, left to right)."""
    d = vertices[v0:v1] - eye
    dx, dy, dz = d[:, 0], d[:, 1], d[:, 2]
    rows = [a[k, 0] * dx + a[k, 1] * dy + a[k, 2] * dz + b[k] for k in range(4)]
    x, y, w, depth = rows
    with np.errstate(divide="ignore"):
        inv = np.where(w != 0.0, 1.0 / np.where(w != 0.0, w, 1.0), 0.0)
    out[0, v0:v1], out[1, v0:v1], out[2, v0:v1], out[3, v0:v1] = x, y, w, depth
    out[4, v0:v1] = x * inv
    out[5, v0:v1] = y * inv
    out[6, v0:v1] = -inv if perspective else depth
    far = np.abs(depth)
    far = far[far > 0.0]  # the loop keeps the largest |D| above 0 (a NaN never is)
    return float(far.max()) if len(far) else 0.0
