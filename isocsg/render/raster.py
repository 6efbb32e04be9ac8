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

import math
from dataclasses import dataclass

import numpy as np
from numba import njit
from numpy.typing import ArrayLike, NDArray

from ..camera import Camera
from ..errors import InvalidGeometryError, InvalidParameterError

__all__ = ["Raster", "rasterize", "homogeneous", "near_distance"]

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


# --------------------------------------------------------------------- kernels
@njit(cache=True)
def _fill_triangle(
    x0: float, y0: float, x1: float, y1: float, x2: float, y2: float,
    k0: float, k1: float, k2: float,
    value: float, tag: int, front: bool,
    ox: int, oy: int, zbuf: NDArray[np.float64], vbuf: NDArray[np.float32], tbuf: NDArray[np.int32],
) -> None:
    """Scan-convert one triangle (screen coordinates) into the viewport buffers.

    Fill rule: a pixel centre ``(px, py)`` is inside when ``y_top <= py < y_bottom``
    and ``x_left <= px < x_right`` on its row (top-left rule). Each edge's
    crossing of a row is ``xa + (py - ya) * slope`` with ``a`` the edge's upper
    end and ``slope = (xb - xa) / (yb - ya)``: the two triangles that share the
    edge compute the same number, so rows are split between them exactly.
    ``k`` is the depth key at the vertices (linear in screen space).
    """
    # Sort the vertices by row (then column): v0 top, v2 bottom.
    if y1 < y0 or (y1 == y0 and x1 < x0):
        x0, y0, x1, y1 = x1, y1, x0, y0
        k0, k1 = k1, k0
    if y2 < y1 or (y2 == y1 and x2 < x1):
        x1, y1, x2, y2 = x2, y2, x1, y1
        k1, k2 = k2, k1
        if y1 < y0 or (y1 == y0 and x1 < x0):
            x0, y0, x1, y1 = x1, y1, x0, y0
            k0, k1 = k1, k0
    # Twice the signed area; its sign says on which side the long edge 0-2 lies.
    area = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0)
    if area == 0.0 or not math.isfinite(area):
        return
    h, w = zbuf.shape
    lo = max(float(oy) - 1.0, y0 - 0.5)
    hi = min(float(oy + h), y2 - 0.5)
    i_start = max(oy, int(math.ceil(lo)))
    i_end = min(oy + h, int(math.ceil(hi)))  # rows with py < y2
    if i_start >= i_end:
        return
    i_mid = int(math.ceil(min(max(lo, y1 - 0.5), hi)))  # first row with py >= y1
    long_left = area > 0.0  # the middle vertex lies right of edge 0-2
    s02 = (x2 - x0) / (y2 - y0)
    s01 = (x1 - x0) / (y1 - y0) if y1 > y0 else 0.0
    s12 = (x2 - x1) / (y2 - y1) if y2 > y1 else 0.0
    # Depth-key plane, anchored at the vertex of largest key (the farthest one,
    # never a near-clipped vertex with huge screen coordinates).
    gx = ((k1 - k0) * (y2 - y0) - (k2 - k0) * (y1 - y0)) / area
    gy = ((k2 - k0) * (x1 - x0) - (k1 - k0) * (x2 - x0)) / area
    if k0 >= k1 and k0 >= k2:
        ka, xa, ya = k0, x0, y0
    elif k1 >= k2:
        ka, xa, ya = k1, x1, y1
    else:
        ka, xa, ya = k2, x2, y2
    cmin = float(ox) - 1.0
    cmax = float(ox + w)
    for i in range(i_start, i_end):
        py = i + 0.5
        xe = x0 + (py - y0) * s02
        if i < i_mid:
            xm = x0 + (py - y0) * s01
        else:
            xm = x1 + (py - y1) * s12
        if long_left:
            xl, xr = xe, xm
        else:
            xl, xr = xm, xe
        # Pixels with xl <= j + 0.5 < xr (clamped first so that huge values stay exact).
        xl = min(max(xl, cmin), cmax)
        xr = min(max(xr, cmin), cmax)
        j0 = max(ox, int(math.ceil(xl - 0.5)))
        j1 = min(ox + w, int(math.ceil(xr - 0.5)))
        if j0 >= j1:
            continue
        q = ka + gx * (j0 + 0.5 - xa) + gy * (py - ya)
        row = i - oy
        if front:
            for j in range(j0 - ox, j1 - ox):
                if q < zbuf[row, j]:
                    zbuf[row, j] = q
                    vbuf[row, j] = value
                    tbuf[row, j] = tag
                q += gx
        else:
            for j in range(j0 - ox, j1 - ox):
                if q > zbuf[row, j]:
                    zbuf[row, j] = q
                    vbuf[row, j] = value
                q += gx


@njit(cache=True, nogil=True)
def project_vertices(
    hx: NDArray[np.float64], hy: NDArray[np.float64], hw: NDArray[np.float64], hd: NDArray[np.float64],
    near: float, perspective: bool,
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Screen column, row and depth key of the vertices in front of the near plane."""
    nv = hx.shape[0]
    sx = np.empty(nv)
    sy = np.empty(nv)
    sk = np.empty(nv)
    for v in range(nv):
        if hd[v] >= near:
            inv = 1.0 / hw[v]
            sx[v] = hx[v] * inv
            sy[v] = hy[v] * inv
            sk[v] = -inv if perspective else hd[v]
    return sx, sy, sk


@njit(cache=True, nogil=True)
def fill_kernel(
    hx: NDArray[np.float64], hy: NDArray[np.float64], hw: NDArray[np.float64], hd: NDArray[np.float64],
    tris: NDArray[np.int32], vout: NDArray[np.float32], vin: NDArray[np.float32],
    near: float, perspective: bool, cull: bool, do_back: bool, tag: int, ox: int, oy: int,
    zf: NDArray[np.float64], vf: NDArray[np.float32], tf: NDArray[np.int32],
    zb: NDArray[np.float64], vb: NDArray[np.float32],
) -> None:
    """Fill triangles into front (and back) buffers; see the module docstring.

    The depth buffers hold a *depth key* that grows with depth and is linear in
    screen space: ``-1 / D`` for the pinhole camera, ``D`` for the orthographic
    one (see :func:`key_to_depth`). ``zf`` starts at +inf, ``zb`` at -inf;
    buffers cover the viewport whose top-left pixel is ``(oy, ox)``. With
    ``cull`` false every triangle goes to the front buffers (and, with
    ``do_back``, to the back ones too). ``tf`` receives ``tag`` wherever the
    front buffers are written.
    """
    sx, sy, sk = project_vertices(hx, hy, hw, hd, near, perspective)
    _fill_all(hx, hy, hw, hd, sx, sy, sk, tris, vout, vin, near, perspective, cull, do_back, tag, ox, oy, zf, vf, tf, zb, vb)


@njit(cache=True, nogil=True)
def _fill_all(
    hx: NDArray[np.float64], hy: NDArray[np.float64], hw: NDArray[np.float64], hd: NDArray[np.float64],
    sx: NDArray[np.float64], sy: NDArray[np.float64], sk: NDArray[np.float64],
    tris: NDArray[np.int32], vout: NDArray[np.float32], vin: NDArray[np.float32],
    near: float, perspective: bool, cull: bool, do_back: bool, tag: int, ox: int, oy: int,
    zf: NDArray[np.float64], vf: NDArray[np.float32], tf: NDArray[np.int32],
    zb: NDArray[np.float64], vb: NDArray[np.float32],
) -> None:
    px = np.empty(4)
    py = np.empty(4)
    pk = np.empty(4)
    for t in range(tris.shape[0]):
        a = tris[t, 0]
        b = tris[t, 1]
        c = tris[t, 2]
        ina = hd[a] >= near
        inb = hd[b] >= near
        inc = hd[c] >= near
        if ina and inb and inc:
            n = 3
            px[0], py[0], pk[0] = sx[a], sy[a], sk[a]
            px[1], py[1], pk[1] = sx[b], sy[b], sk[b]
            px[2], py[2], pk[2] = sx[c], sy[c], sk[c]
        elif not (ina or inb or inc):
            continue
        else:
            # Sutherland-Hodgman against D >= near, in homogeneous space.
            n = 0
            for k in range(3):
                if k == 0:
                    p, q = a, b
                elif k == 1:
                    p, q = b, c
                else:
                    p, q = c, a
                if hd[p] >= near:
                    px[n], py[n], pk[n] = sx[p], sy[p], sk[p]
                    n += 1
                if (hd[p] >= near) != (hd[q] >= near):
                    # Canonical order: the neighbour sharing this edge gets the same point.
                    s0, s1 = (p, q) if p < q else (q, p)
                    s = (near - hd[s0]) / (hd[s1] - hd[s0])
                    inv = 1.0 / (hw[s0] + s * (hw[s1] - hw[s0]))
                    px[n] = (hx[s0] + s * (hx[s1] - hx[s0])) * inv
                    py[n] = (hy[s0] + s * (hy[s1] - hy[s0])) * inv
                    pk[n] = -inv if perspective else near
                    n += 1
        # Facing: screen rows grow downwards, so a triangle counter-clockwise
        # seen from the eye has a negative signed area in (col, row).
        s2 = 0.0
        for k in range(n):
            k1 = (k + 1) % n
            s2 += px[k] * py[k1] - px[k1] * py[k]
        is_front = s2 < 0.0
        to_front = is_front or not cull
        to_back = do_back and (not is_front or not cull)
        for k in range(1, n - 1):
            if to_front:
                _fill_triangle(
                    px[0], py[0], px[k], py[k], px[k + 1], py[k + 1], pk[0], pk[k], pk[k + 1],
                    vout[t], tag, True, ox, oy, zf, vf, tf,
                )
            if to_back:
                _fill_triangle(
                    px[0], py[0], px[k], py[k], px[k + 1], py[k + 1], pk[0], pk[k], pk[k + 1],
                    vin[t], tag, False, ox, oy, zb, vb, tf,
                )


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


# ------------------------------------------------------------------ Python API
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
    fill_kernel(h[0], h[1], h[2], h[3], t, vo, vi, near_distance(h[3]), persp, bool(cull), do_back, 0, 0, 0, zf, vf, tf, zb, vb)
    key_to_depth(zf, persp, zf)
    if do_back:
        key_to_depth(zb, persp, zb)
    return Raster(zf, vf, zb if do_back else None, vb if do_back else None)
