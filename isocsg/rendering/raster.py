"""Compiled triangle fill: nearest and farthest surface per pixel.

Triangles are given in world space and projected by a :class:`~isocsg.camera.Camera`
to homogeneous screen coordinates ``(X, Y, W, D)`` that are affine in the world
point: ``col = X / W``, ``row = Y / W`` and ``D`` is the camera depth (distance
along the forward axis). For the pinhole camera ``W = D``; for the orthographic
camera ``W = 1``. Because all four are affine, triangles are clipped against the
near plane ``D >= near`` *before* the division (nothing is dropped, nothing
wraps around behind the eye). The depth buffers hold a *depth key* that is
linear in screen space and grows with depth, ``-1 / D`` for the pinhole camera
and ``D`` for the orthographic one, so interpolating it across a triangle
gives the perspective-correct depth.

Coverage follows the top-left rule of scanline fill (a pixel centre belongs
to a triangle when ``y_top <= row < y_bottom`` and ``x_left <= col < x_right``
on its row) with each edge's crossing of a row computed from its ends in a
canonical order, so two triangles that share an edge split every row at the
same column: a pixel centre on the shared edge belongs to exactly one of them,
and none is missed. Pixel ``(i, j)`` (row, column) has its centre at
``(col, row) = (j + 0.5, i + 0.5)``.

Front-facing triangles (counter-clockwise seen from the eye, i.e. outward
normals towards the eye) write the *front* buffers with a nearest-depth test
and their ``value_out``; back-facing triangles write the *back* buffers with a
farthest-depth test and their ``value_in``. For a closed convex mesh this is
exactly the entry and exit of each pixel's ray.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..camera import Camera
from ..errors import InvalidGeometryError, InvalidParameterError
from .projection import homogeneous, key_to_depth, near_distance
from .triangles import fill_kernel

__all__ = ["Raster", "rasterize"]

@dataclass(frozen=True, slots=True, eq=False)
class Raster:
    """Per-pixel result of :func:`rasterize`.

    Attributes
    ----------
    front_depth : ndarray, shape (H, W), float64
        Camera depth of the nearest surface (``inf`` where nothing is drawn).
    front_value : ndarray, shape (H, W), float32
        ``value_out`` of the nearest triangle (NaN where nothing is drawn).
    back_depth, back_value : ndarray or None
        Farthest surface and its ``value_in`` (``-inf`` / NaN where nothing),
        present when ``value_in`` was given.
    """

    front_depth: NDArray[np.float64]
    front_value: NDArray[np.float32]
    back_depth: NDArray[np.float64] | None
    back_value: NDArray[np.float32] | None

    @property
    def covered(self) -> NDArray[np.bool_]:
        """Pixels with a front surface."""
        return np.isfinite(self.front_depth)


def rasterize(
    camera: Camera,
    vertices: ArrayLike,
    triangles: ArrayLike,
    value_out: ArrayLike,
    value_in: ArrayLike | None = None,
    *,
    cull: bool = True,
) -> Raster:
    """Fill triangles with constant values and keep the nearest (and farthest) surface.

    Parameters
    ----------
    camera : Camera
    vertices : array_like, shape (V, 3)
        World-space vertices.
    triangles : array_like of int, shape (T, 3)
        Counter-clockwise seen from the outside (outward normals).
    value_out : array_like, shape (T,)
        Value written by a triangle seen from outside (front buffers).
    value_in : array_like, shape (T,), optional
        Value written by a triangle seen from inside (back buffers). When
        omitted, only the front buffers are computed.
    cull : bool, default True
        Send front-facing triangles to the front buffers and back-facing ones
        to the back buffers. With ``False`` every triangle is tested against
        both (nearest and farthest of all triangles, whatever their facing).

    Returns
    -------
    Raster

    Raises
    ------
    InvalidGeometryError
        On non-finite vertices, bad shapes or out-of-range triangle indices.
    InvalidParameterError
        When a value array does not have one entry per triangle.

    Examples
    --------
    >>> cam = Camera((0, 0, 5), (0, 0, 0), up=(0, 1, 0), width=8, height=8,
    ...              orthographic=True, height_m=8)
    >>> square = [(-4, -4, 0), (4, -4, 0), (4, 4, 0), (-4, 4, 0)]
    >>> r = rasterize(cam, square, [(0, 1, 2), (0, 2, 3)], [0.25, 0.75])
    >>> int(r.covered.sum()), float(r.front_depth[7, 7])
    (64, 5.0)
    >>> sorted(np.unique(r.front_value, return_counts=True)[1].tolist())  # the diagonal once
    [28, 36]
    """
    v = np.asarray(vertices, dtype=np.float64)
    if v.ndim != 2 or v.shape[1] != 3:
        raise InvalidGeometryError(f"vertices must have shape (V, 3), got {v.shape}")
    if not np.all(np.isfinite(v)):
        raise InvalidGeometryError("vertices must be finite")
    t = np.asarray(triangles)
    if t.ndim != 2 or t.shape[1] != 3 or (t.size and not np.issubdtype(t.dtype, np.integer)):
        raise InvalidGeometryError(f"triangles must be integers of shape (T, 3), got {t.dtype} {t.shape}")
    if t.size and (t.min() < 0 or t.max() >= len(v)):
        raise InvalidGeometryError(f"triangles index vertices 0..{len(v) - 1}, got {t.min()}..{t.max()}")
    t = np.ascontiguousarray(t, dtype=np.int32)
    vo = np.asarray(value_out, dtype=np.float32).reshape(-1)
    if len(vo) != len(t):
        raise InvalidParameterError(f"value_out must have one entry per triangle ({len(t)}), got {len(vo)}")
    do_back = value_in is not None
    vi = np.asarray(value_in if do_back else vo, dtype=np.float32).reshape(-1)
    if len(vi) != len(t):
        raise InvalidParameterError(f"value_in must have one entry per triangle ({len(t)}), got {len(vi)}")
    h = homogeneous(camera, v)
    persp = not camera.orthographic
    H, W = camera.height, camera.width
    zf = np.full((H, W), np.inf)
    vf = np.full((H, W), np.nan, dtype=np.float32)
    tf = np.full((H, W), -1, dtype=np.int32)
    zb = np.full((H, W) if do_back else (1, 1), -np.inf)
    vb = np.full(zb.shape, np.nan, dtype=np.float32)
    fill_kernel(
        h[0], h[1], h[2], h[3], t, vo, vi, near_distance(h[3]), persp, bool(cull), do_back, 0, 0, 0, zf, vf, tf, zb, vb,
    )
    key_to_depth(zf, persp, zf)
    if do_back:
        key_to_depth(zb, persp, zb)
    return Raster(zf, vf, zb if do_back else None, vb if do_back else None)
