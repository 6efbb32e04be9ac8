"""Compiled triangle fill: nearest and farthest surface per pixel (see :mod:`isocsg.rendering.raster`).

Coverage follows the top-left rule of scanline fill (a pixel centre belongs
to a triangle when ``y_top <= row < y_bottom`` and ``x_left <= col < x_right``
on its row) with each edge's crossing of a row computed from its ends in a
canonical order, so two triangles that share an edge split every row at the
same column. Triangles are clipped against the near plane ``D >= near``
before the division (nothing is dropped, nothing wraps around behind the eye).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from .._jit import njit
from .jit import RAW

__all__ = ["fill_kernel", "project_vertices"]

@njit(**RAW)
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
        if front and tag >= 0:
            for j in range(j0 - ox, j1 - ox):
                if q < zbuf[row, j]:
                    zbuf[row, j] = q
                    vbuf[row, j] = value
                    tbuf[row, j] = tag
                q += gx
        elif front:
            for j in range(j0 - ox, j1 - ox):
                if q < zbuf[row, j]:
                    zbuf[row, j] = q
                    vbuf[row, j] = value
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
    front buffers are written (nothing with a negative ``tag``).
    """
    sx, sy, sk = project_vertices(hx, hy, hw, hd, near, perspective)
    _fill_all(hx, hy, hw, hd, sx, sy, sk, tris, vout, vin, near, perspective, cull, do_back, tag, ox, oy, zf, vf, tf,
              zb, vb, np.empty((3, 4)))


@njit(**RAW)
def _fill_all(
    hx: NDArray[np.float64], hy: NDArray[np.float64], hw: NDArray[np.float64], hd: NDArray[np.float64],
    sx: NDArray[np.float64], sy: NDArray[np.float64], sk: NDArray[np.float64],
    tris: NDArray[np.int32], vout: NDArray[np.float32], vin: NDArray[np.float32],
    near: float, perspective: bool, cull: bool, do_back: bool, tag: int, ox: int, oy: int,
    zf: NDArray[np.float64], vf: NDArray[np.float32], tf: NDArray[np.int32],
    zb: NDArray[np.float64], vb: NDArray[np.float32], scratch: NDArray[np.float64],
) -> None:
    px, py, pk = scratch[0], scratch[1], scratch[2]  # (3, 4): a clipped triangle has up to 4 corners
    for t in range(tris.shape[0]):
        _fill_one(hx, hy, hw, hd, sx, sy, sk, tris[t, 0], tris[t, 1], tris[t, 2], near, perspective, cull, do_back,
                  vout[t], vin[t], tag, ox, oy, zf, vf, tf, zb, vb, px, py, pk)


@njit(**RAW)
def _fill_one(
    hx: NDArray[np.float64], hy: NDArray[np.float64], hw: NDArray[np.float64], hd: NDArray[np.float64],
    sx: NDArray[np.float64], sy: NDArray[np.float64], sk: NDArray[np.float64],
    a: int, b: int, c: int, near: float, perspective: bool, cull: bool, do_back: bool,
    value_out: float, value_in: float, tag: int, ox: int, oy: int,
    zf: NDArray[np.float64], vf: NDArray[np.float32], tf: NDArray[np.int32],
    zb: NDArray[np.float64], vb: NDArray[np.float32],
    px: NDArray[np.float64], py: NDArray[np.float64], pk: NDArray[np.float64],
) -> None:
    """Clip one triangle against the near plane, decide its facing and fill it."""
    ina = hd[a] >= near
    inb = hd[b] >= near
    inc = hd[c] >= near
    if ina and inb and inc:
        n = 3
        px[0], py[0], pk[0] = sx[a], sy[a], sk[a]
        px[1], py[1], pk[1] = sx[b], sy[b], sk[b]
        px[2], py[2], pk[2] = sx[c], sy[c], sk[c]
    elif not (ina or inb or inc):
        return
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
                value_out, tag, np.bool_(True), ox, oy, zf, vf, tf,
            )
        if to_back:
            _fill_triangle(
                px[0], py[0], px[k], py[k], px[k + 1], py[k + 1], pk[0], pk[k], pk[k + 1],
                value_in, tag, np.bool_(False), ox, oy, zb, vb, tf,
            )
