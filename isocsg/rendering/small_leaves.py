"""Leaves a few pixels across: their depth intervals by exact rays instead of band meshes.

A leaf at most :data:`~isocsg.rendering.policy.RAY_LEAF_SIZE` pixels across
(the holes of a plate drilled by a long modelling loop, seen from afar) costs
more to cut into bands than its few pixels are worth. Its front and back surfaces per pixel are
instead where the pixel's ray (through its centre, where the fills sample)
enters and leaves it (:meth:`~isocsg.kinds.base.Primitive.intersect_rays`,
convex leaves), with the depth keys of the fills and the exact intensity
there (:func:`~isocsg.lighting.shading.shade`; inside, the reversed normal).
So the cost of such a leaf falls with its size on screen.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..camera import Camera
from ..kinds import Primitive
from ..lighting.shading import shade

__all__ = ["PixelRays", "depth_keys", "ray_intervals"]


class PixelRays:
    """The rays through the pixel centres of a camera, for any rectangle of pixels."""

    def __init__(self, cam: Camera) -> None:
        self.cam = cam
        self.f, self.r, self.u = cam.frame
        self.x, self.y = cam.pixel_coordinates()
        self.eye = cam.eye_array
        self.perspective = not cam.orthographic

    def rect(self, r0: int, c0: int, h: int, w: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Origins and directions, shape (h * w, 3), of the pixels of rows ``r0 ..`` and columns ``c0 ..``,
        row by row; the directions have a unit component along the view (``t`` is the camera depth)."""
        x = np.repeat(self.x[None, c0 : c0 + w], h, axis=0).reshape(-1, 1)
        y = np.repeat(self.y[r0 : r0 + h, None], w, axis=1).reshape(-1, 1)
        if self.perspective:
            d = self.f + x * self.r + y * self.u
            return np.broadcast_to(self.eye, d.shape), d
        o = self.eye + x * self.r + y * self.u
        return o, np.broadcast_to(self.f, o.shape)


def depth_keys(
    d_in: NDArray[np.float64], d_out: NDArray[np.float64], hit: NDArray[np.bool_], near: float, perspective: bool
) -> tuple[NDArray[np.bool_], NDArray[np.bool_], NDArray[np.float64], NDArray[np.float64]]:
    """Which ray intervals show a front and a back surface in front of the near plane, and their
    depth keys as the fills write them (``-1/depth`` in perspective, the depth otherwise; ``+inf``
    and ``-inf`` where none)."""
    front = hit & (d_in >= near)
    back = hit & (d_out >= near)
    kf = np.full(len(hit), np.inf)
    kb = np.full(len(hit), -np.inf)
    if perspective:
        kf[front] = -1.0 / d_in[front]
        kb[back] = -1.0 / d_out[back]
    else:
        kf[front] = d_in[front]
        kb[back] = d_out[back]
    return front, back, kf, kb


def ray_intervals(
    leaf: Primitive, rays: PixelRays, r0: int, c0: int, h: int, w: int, near: float, lights: Sequence[Any],
    material: Any,
) -> tuple[NDArray[np.float64], NDArray[np.float32], NDArray[np.float64], NDArray[np.float32]]:
    """Depth keys and values of a leaf's front and back surfaces over a rectangle of pixels, as
    the fills write them (flat, row by row): front key ``+inf`` where none (or behind the near
    plane ``near``), back key ``-inf`` where none."""
    origins, directions = rays.rect(r0, c0, h, w)
    norm = np.linalg.norm(directions, axis=1)
    hits = leaf.intersect_rays(origins, directions / norm[:, None])
    # Parameters along unit directions; the camera depth is t times the direction's view component.
    d_in, d_out = hits.t_in / norm, hits.t_out / norm
    hit = hits.hit
    front, back, kf, kb = depth_keys(d_in, d_out, hit, near, rays.perspective)
    vf = np.zeros(len(norm), np.float32)
    vb = np.zeros(len(norm), np.float32)
    nf = int(front.sum())
    if nf or back.any():  # both surfaces in one call (its fixed cost is most of a small leaf's)
        points = np.concatenate([origins[front] + directions[front] * d_in[front, None],
                                 origins[back] + directions[back] * d_out[back, None]])
        values = shade(points, np.concatenate([hits.n_in[front], -hits.n_out[back]]), rays.eye, lights, material)
        vf[front] = values[:nf]
        vb[back] = values[nf:]
    return kf, vf, kb, vb
