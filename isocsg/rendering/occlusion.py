"""Occlusion culling: whether a leaf's bounding ball is hidden by what the image already holds."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from .._jit import njit
from ..camera import Camera
from .jit import RAW

__all__ = ["camera_rays", "ball_covered"]

def camera_rays(camera: Camera) -> NDArray[np.float64]:
    """The camera as :func:`ball_covered` reads it: eye, forward, right, up, the view's
    half-width and half-height (at unit depth under perspective), and 1.0 for a perspective."""
    f, r, u = camera.frame
    if camera.orthographic:
        sy = camera.height_m / 2
    else:
        sy = camera.tan_half_fov
    return np.concatenate([camera.eye_array, f, r, u, [sy * camera.aspect, sy, 0.0 if camera.orthographic else 1.0]])


@njit(**RAW)
def ball_covered(
    zbuf: NDArray[np.float64], r0: int, r1: int, c0: int, c1: int, key: float, near: float,
    ray: NDArray[np.float64], center: NDArray[np.float64], radius: float,
) -> bool:
    """Whether any surface inside the ball ``(center, radius)`` is hidden everywhere by what
    ``zbuf[r0:r1, c0:c1]`` already holds (occlusion culling).

    A pixel can be written only if its ray (through its centre, where the
    fills sample) meets the ball, and then no nearer than where the ray
    enters it; so the ball is hidden where every such pixel already holds a
    depth key below that entry's (``key``, the ball's nearest key, settles
    most pixels at once). A ray that enters the ball behind the near plane
    ``near`` (or inside it) is never hidden. A relative 1e-9 is added to the
    radius for rounding. ``ray`` is :func:`camera_rays`'s: the eye, the unit
    forward, right and up vectors, the half-width and half-height of the
    view (at unit depth under perspective) and whether it is a perspective.
    """
    ex, ey, ez = ray[0], ray[1], ray[2]
    fx, fy, fz, rx, ry, rz, ux, uy, uz = ray[3], ray[4], ray[5], ray[6], ray[7], ray[8], ray[9], ray[10], ray[11]
    sx, sy, persp = ray[12], ray[13], ray[14] > 0.0
    W, H = zbuf.shape[1], zbuf.shape[0]
    vx, vy, vz = center[0] - ex, center[1] - ey, center[2] - ez
    v2 = vx * vx + vy * vy + vz * vz
    reach = radius + 1e-9 * (radius + math.sqrt(v2))
    reach2 = reach * reach
    for i in range(r0, r1):
        y = sy * (1.0 - 2.0 * (i + 0.5) / H)
        for j in range(c0, c1):
            z = zbuf[i, j]
            if z < key:
                continue
            x = sx * (2.0 * (j + 0.5) / W - 1.0)
            if persp:  # points eye + s (f + x r + y u), at depth s
                dx, dy, dz = fx + x * rx + y * ux, fy + x * ry + y * uy, fz + x * rz + y * uz
                d2 = dx * dx + dy * dy + dz * dz
                vd = vx * dx + vy * dy + vz * dz
                disc = vd * vd - d2 * (v2 - reach2)
                if disc < 0.0:
                    continue  # the ray misses the ball
                s = (vd - math.sqrt(disc)) / d2
                if not (s > near and z < -1.0 / s):
                    return False
            else:  # points eye + x r + y u + s f, at depth s
                wx, wy, wz = vx - x * rx - y * ux, vy - x * ry - y * uy, vz - x * rz - y * uz
                t = wx * fx + wy * fy + wz * fz
                p2 = wx * wx + wy * wy + wz * wz - t * t
                if p2 > reach2:
                    continue
                s = t - math.sqrt(reach2 - p2)
                if not (s > near and z < s):
                    return False
    return True
