"""Compiled fill of convex polygons (the quads of :func:`~isocsg.rendering.quads.pair_quads`).

A quad that projects strictly convex is filled with one span per row between
its left and right chains, each edge's crossing of a row computed exactly as
the triangle fill does (:mod:`isocsg.rendering.triangles`), so the result is the
union of its fan triangles pixel for pixel; any other quad goes as its two
triangles. Front faces keep the nearest depth key, back faces the farthest.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._jit import njit
from .jit import RAW
from .polygon_twins import fill_polys_numpy
from .triangles import _fill_one

__all__ = ["fill_rect", "fill_projected", "fill_front_kernel", "fill_front_runs"]

@njit(**RAW)
def fill_rect(a: NDArray[Any], r0: int, r1: int, c0: int, c1: int, value: float) -> None:
    """``a[r0:r1, c0:c1] = value`` without the GIL (``a`` C-contiguous)."""
    flat = a.reshape(-1)  # contiguous row pieces: filled with wide stores
    w = a.shape[1]
    for i in range(r0, r1):
        flat[i * w + c0 : i * w + c1] = value


# Inlined into their caller: a call passes arrays, each reference-counted.
@njit(**RAW, error_model="numpy", inline="always")
def _top_bottom(px: NDArray[np.float64], py: NDArray[np.float64], n: int) -> tuple[int, int]:
    """The polygon's top and bottom vertices (ties: leftmost on top, rightmost at the bottom)."""
    top = 0
    bot = 0
    for k in range(1, n):
        if py[k] < py[top] or (py[k] == py[top] and px[k] < px[top]):
            top = k
        if py[k] > py[bot] or (py[k] == py[bot] and px[k] > px[bot]):
            bot = k
    return top, bot


@njit(**RAW, error_model="numpy", inline="always")
def _depth_plane(
    px: NDArray[np.float64], py: NDArray[np.float64], pk: NDArray[np.float64], n: int,
) -> tuple[bool, float, float, float, float, float]:
    """The depth-key plane of a convex polygon: whether it has area, its gradients along
    columns and rows, and its anchor (key, column, row).

    The plane goes through vertices 0, t1, t1 + 1 (the fan triangle of larger
    area: a corner's turn test and this area round differently, so one of
    them may be exactly zero), anchored at the farthest of them.
    """
    t1 = 1
    area = (px[1] - px[0]) * (py[2] - py[0]) - (py[1] - py[0]) * (px[2] - px[0])
    if n == 4:
        area3 = (px[2] - px[0]) * (py[3] - py[0]) - (py[2] - py[0]) * (px[3] - px[0])
        if abs(area3) > abs(area):
            t1 = 2
            area = area3
    if area == 0.0 or not math.isfinite(area):
        return False, 0.0, 0.0, 0.0, 0.0, 0.0  # no area in floating point: no pixel centre strictly inside
    t2 = t1 + 1
    gx = ((pk[t1] - pk[0]) * (py[t2] - py[0]) - (pk[t2] - pk[0]) * (py[t1] - py[0])) / area
    gy = ((pk[t2] - pk[0]) * (px[t1] - px[0]) - (pk[t1] - pk[0]) * (px[t2] - px[0])) / area
    an = 0
    if pk[t1] > pk[an]:
        an = t1
    if pk[t2] > pk[an]:
        an = t2
    return True, gx, gy, pk[an], px[an], py[an]


@njit(**RAW, error_model="numpy", inline="always")
def _grow_bounds(
    bounds: NDArray[np.int64], px: NDArray[np.float64], n: int, i_start: int, i_end: int, ox: int, w: int,
    cmin: float, cmax: float,
) -> None:
    """Grow the written rectangle by the polygon's pixel box (cheaper than per row)."""
    xmin = px[0]
    xmax = px[0]
    for k in range(1, n):
        xmin = min(xmin, px[k])
        xmax = max(xmax, px[k])
    bounds[0] = min(bounds[0], i_start)
    bounds[1] = max(bounds[1], i_end)
    bounds[2] = min(bounds[2], max(ox, int(math.ceil(min(max(xmin, cmin), cmax) - 0.5))))
    bounds[3] = max(bounds[3], min(ox + w, int(math.ceil(min(max(xmax, cmin), cmax) - 0.5))))


@njit(**RAW, error_model="numpy", inline="always")
def _fill_span(
    zr: NDArray[np.float64], vr: NDArray[np.float32], tr: NDArray[np.int32], j0: int, j1: int, q: float, gx: float,
    value32: np.float32, tag32: np.int32, front: bool,
) -> None:
    """One row's span ``j0 .. j1`` (buffer columns), the depth key ``q`` at ``j0`` growing by ``gx``."""
    if front and tag32 >= 0:
        for j in range(j0, j1):
            if q < zr[j]:
                zr[j] = q
                vr[j] = value32
                tr[j] = tag32
            q += gx
    elif front:
        for j in range(j0, j1):
            if q < zr[j]:
                zr[j] = q
                vr[j] = value32
            q += gx
    else:
        for j in range(j0, j1):
            if q > zr[j]:
                zr[j] = q
                vr[j] = value32
            q += gx


@_fill_span.twin
def _fill_span_numpy(
    zr: NDArray[np.float64], vr: NDArray[np.float32], tr: NDArray[np.int32], j0: int, j1: int, q: float, gx: float,
    value32: np.float32, tag32: np.int32, front: bool,
) -> None:
    """:func:`_fill_span` vectorised (for small renders without numba): the keys summed one step
    at a time as the loop does (``np.add.accumulate`` is sequential), so the same bits."""
    steps = np.full(j1 - j0, gx)
    steps[0] = q
    keys = np.add.accumulate(steps)
    old = zr[j0:j1]
    hit = keys < old if front else keys > old
    old[hit] = keys[hit]
    vr[j0:j1][hit] = value32
    if front and tag32 >= 0:
        tr[j0:j1][hit] = tag32


@njit(**RAW, error_model="numpy", inline="always")
def _fill_convex(
    px: NDArray[np.float64], py: NDArray[np.float64], pk: NDArray[np.float64], n: int,
    value: float, tag: int, ox: int, oy: int, clamp: bool, front: bool,
    zbuf: NDArray[np.float64], vbuf: NDArray[np.float32], tbuf: NDArray[np.int32], bounds: NDArray[np.int64],
) -> None:
    """Fill of a strictly convex polygon (3 or 4 vertices, negative signed area).

    One span per row between the polygon's left and right chains. Each edge's
    crossing of a row is computed exactly as in
    :func:`~isocsg.rendering.triangles._fill_triangle` (from its upper end, with
    its own slope), so the result is the union of the fan triangles pixel for
    pixel, and neighbours sharing an edge split rows identically. The buffers
    cover the viewport whose top-left pixel is ``(oy, ox)``; ``front`` keeps
    the nearest key (and writes ``tag`` into ``tbuf`` unless it is negative),
    otherwise the farthest. ``clamp`` false promises that all columns lie in
    ``[ox, ox + width]`` (no clamping needed). ``bounds`` (row min, row max + 1,
    column min, column max + 1) grows to cover every pixel written.
    """
    h, w = zbuf.shape
    top, bot = _top_bottom(px, py, n)
    lo = max(float(oy) - 1.0, py[top] - 0.5)
    hi = min(float(oy + h), py[bot] - 0.5)
    i_start = max(oy, int(math.ceil(lo)))
    i_end = min(oy + h, int(math.ceil(hi)))
    if i_start >= i_end:
        return
    has_area, gx, gy, ka, xa, ya = _depth_plane(px, py, pk, n)
    if not has_area:
        return
    # Left chain: increasing index from the top (negative area); right chain: decreasing.
    li = top
    ri = top
    ln = li + 1 if li + 1 < n else 0
    rn = ri - 1 if ri > 0 else n - 1
    l_thr = int(math.ceil(min(max(lo, py[ln] - 0.5), hi)))  # first row on the next left edge's successor
    r_thr = int(math.ceil(min(max(lo, py[rn] - 0.5), hi)))
    cmin = float(ox) - 1.0
    cmax = float(ox + w)
    value32 = np.float32(value)
    tag32 = np.int32(tag)
    _grow_bounds(bounds, px, n, i_start, i_end, ox, w, cmin, cmax)
    i = i_start
    while i < i_end:
        while i >= l_thr:
            li = ln
            ln = li + 1 if li + 1 < n else 0
            l_thr = int(math.ceil(min(max(lo, py[ln] - 0.5), hi))) if li != bot else i_end
        while i >= r_thr:
            ri = rn
            rn = ri - 1 if ri > 0 else n - 1
            r_thr = int(math.ceil(min(max(lo, py[rn] - 0.5), hi))) if ri != bot else i_end
        seg_end = min(i_end, l_thr, r_thr)
        lx, ly = px[li], py[li]
        rx, ry = px[ri], py[ri]
        ls = (px[ln] - lx) / (py[ln] - ly)
        rs = (px[rn] - rx) / (py[rn] - ry)
        for ii in range(i, seg_end):
            pyc = ii + 0.5
            xl = lx + (pyc - ly) * ls
            xr = rx + (pyc - ry) * rs
            if clamp:
                xl = min(max(xl, cmin), cmax)
                xr = min(max(xr, cmin), cmax)
                j0 = max(ox, int(math.ceil(xl - 0.5)))
                j1 = min(ox + w, int(math.ceil(xr - 0.5)))
            else:
                j0 = int(math.ceil(xl - 0.5))
                j1 = int(math.ceil(xr - 0.5))
            if j0 >= j1:
                continue
            row = ii - oy
            q = ka + gx * (j0 + 0.5 - xa) + gy * (pyc - ya)
            _fill_span(zbuf[row], vbuf[row], tbuf[row if front and tag32 >= 0 else 0], j0 - ox, j1 - ox, q, gx,
                       value32, tag32, front)
        i = seg_end


@njit(cache=True, nogil=True)
def fill_projected(
    proj: NDArray[np.float64], polys: NDArray[np.int32], vout: NDArray[np.float32], vin: NDArray[np.float32],
    near: float, perspective: bool, ox: int, oy: int,
    zf: NDArray[np.float64], vf: NDArray[np.float32], zb: NDArray[np.float64], vb: NDArray[np.float32],
) -> None:
    """Front and back buffers of convex polygons projected by :func:`project_kernel` (no labels).

    For the leaves of per-pixel CSG: each pixel's nearest front-facing and
    farthest back-facing surface, over the viewport whose top-left pixel is
    ``(oy, ox)``. ``polys`` (P, 4) are the quads of :func:`pair_quads` (the
    last index -1 for a triangle) with their values ``vout`` and ``vin``.
    A quad that projects strictly convex is filled with one span per row into
    the buffers of its facing; any other as its two triangles. The pixels and
    values are those of :func:`fill_kernel` with culling and back buffers on
    the quads' triangles.
    """
    # No labels and no written rectangle for leaves (both discarded).
    _fill_polys(proj, polys, vout, vin, near, perspective, np.bool_(True), np.int64(-1), ox, oy, zf, vf,
                np.empty((1, 1), np.int32), zb, vb, np.empty(4, np.int64), np.empty((3, 4)))


@njit(cache=True, nogil=True)
def fill_front_kernel(
    proj: NDArray[np.float64], polys: NDArray[np.int32], values: NDArray[np.float32],
    near: float, perspective: bool, tag: int, oy: int,
    zf: NDArray[np.float64], vf: NDArray[np.float32], tf: NDArray[np.int32], bounds: NDArray[np.int64],
) -> None:
    """Front faces of convex polygons into rows ``oy ..`` of the image buffers (depth-tested).

    ``proj`` is the output of :func:`project_kernel`; ``polys`` (P, 4) are
    the quads of :func:`pair_quads` (the last index -1 for a triangle). The
    buffers are full-width rows ``oy .. oy + zf.shape[0]`` of the image. A
    quad that projects strictly convex and front-facing is filled with one
    span per row; any other quad as its two triangles; a polygon crossing
    the near plane is clipped first (as :func:`fill_kernel`). ``bounds``
    grows to cover every row and column written.
    """
    _fill_polys(proj, polys, values, values, near, perspective, np.bool_(False), tag, np.int64(0), oy, zf, vf, tf,
                np.empty((1, 1)), np.empty((1, 1), np.float32), bounds, np.empty((3, 4)))


@njit(cache=True, nogil=True)
def fill_front_runs(
    proj: NDArray[np.float64], polys: NDArray[np.int32], values: NDArray[np.float32], starts: NDArray[np.int64],
    vstarts: NDArray[np.int64], tags: NDArray[np.int64], nears: NDArray[np.float64], perspective: bool, oy: int,
    zf: NDArray[np.float64], vf: NDArray[np.float32], tf: NDArray[np.int32], bounds: NDArray[np.int64],
) -> None:
    """:func:`fill_front_kernel` of consecutive runs of polygons in one call, run ``r``
    (polygons ``starts[r]`` to ``starts[r + 1]``, using only vertices ``vstarts[r]`` to
    ``vstarts[r + 1]``) with its own tag and near plane: the parts of a large clipped CSG
    surface (one per leaf) without a call per part. A run whose vertices all lie in front
    of its near plane and outside the buffers' rows or the image's columns is skipped
    whole (a row stripe meets few of a model's leaves)."""
    scratch = np.empty((3, 4))
    zb = np.empty((1, 1))
    vb = np.empty((1, 1), np.float32)
    hd, sx, sy = proj[3], proj[4], proj[5]
    r_lo, r_hi = float(oy), float(oy + zf.shape[0])
    c_hi = float(zf.shape[1])
    for r in range(tags.shape[0]):
        a, b = starts[r], starts[r + 1]
        v0, v1 = vstarts[r], vstarts[r + 1]
        if v1 > v0:
            near_ok = True
            ymin, ymax, xmin, xmax = np.inf, -np.inf, np.inf, -np.inf
            for v in range(v0, v1):
                if not hd[v] >= nears[r]:
                    near_ok = False
                    break
                ymin, ymax = min(ymin, sy[v]), max(ymax, sy[v])
                xmin, xmax = min(xmin, sx[v]), max(xmax, sx[v])
            if near_ok and (ymax <= r_lo or ymin >= r_hi + 0.5 or xmax <= 0.0 or xmin >= c_hi + 0.5):
                continue  # as _fill_polys would cull each of its polygons
        _fill_polys(proj, polys[a:b], values[a:b], values[a:b], nears[r], perspective, np.bool_(False), tags[r],
                    np.int64(0), oy, zf, vf, tf, zb, vb, bounds, scratch)


@njit(cache=True, inline="always")
def _extent(t: NDArray[np.float64], a: int, b: int, c: int, d: int) -> tuple[float, float]:
    """Smallest and largest ``t`` over the corners of a quad (``d < 0``: a triangle)."""
    lo = min(t[a], t[b], t[c])
    hi = max(t[a], t[b], t[c])
    if d >= 0:
        lo, hi = min(lo, t[d]), max(hi, t[d])
    return lo, hi


@njit(**RAW)
def _fill_polys(
    proj: NDArray[np.float64], polys: NDArray[np.int32], vout: NDArray[np.float32], vin: NDArray[np.float32],
    near: float, perspective: bool, back: bool, tag: int, ox: int, oy: int,
    zf: NDArray[np.float64], vf: NDArray[np.float32], tf: NDArray[np.int32],
    zb: NDArray[np.float64], vb: NDArray[np.float32], bounds: NDArray[np.int64], scratch: NDArray[np.float64],
) -> None:
    """Convex polygons (quads of :func:`pair_quads`) into the viewport whose top-left pixel is ``(oy, ox)``.

    Front-facing polygons go to the nearest-key buffers ``zf, vf`` (and
    ``tag`` into ``tf``); back-facing ones to the farthest-key buffers
    ``zb, vb`` with ``back``, else they are culled. Shared by the plain render
    (:func:`fill_front_kernel`) and the CSG leaves (:func:`fill_projected`).
    """
    hx, hy, hw, hd = proj[0], proj[1], proj[2], proj[3]
    sx, sy, sk = proj[4], proj[5], proj[6]
    h, w = zf.shape
    r_lo, r_hi = float(oy), float(oy + h)
    c_lo, c_hi = float(ox), float(ox + w)
    px, py, pk = scratch[0], scratch[1], scratch[2]
    for p in range(polys.shape[0]):
        a, b, c, d = polys[p, 0], polys[p, 1], polys[p, 2], polys[p, 3]
        n = 3 if d < 0 else 4
        if not (hd[a] >= near and hd[b] >= near and hd[c] >= near and (n == 3 or hd[d] >= near)):
            # Crossing the near plane: clipped triangle by triangle (rare).
            _fill_one(hx, hy, hw, hd, sx, sy, sk, a, b, c, near, perspective, np.bool_(True), back, vout[p], vin[p],
                      tag, ox, oy, zf, vf, tf, zb, vb, px, py, pk)
            if n == 4:
                _fill_one(hx, hy, hw, hd, sx, sy, sk, a, c, d, near, perspective, np.bool_(True), back, vout[p], vin[p],
                          tag, ox, oy, zf, vf, tf, zb, vb, px, py, pk)
            bounds[0] = min(bounds[0], oy)
            bounds[1] = max(bounds[1], oy + h)
            bounds[2] = min(bounds[2], ox)
            bounds[3] = max(bounds[3], ox + w)
            continue
        ymin, ymax = _extent(sy, a, b, c, d)
        if ymax <= r_lo or ymin >= r_hi + 0.5:
            continue  # no pixel centre of the viewport's rows
        if math.ceil(ymin - 0.5) >= math.ceil(ymax - 0.5):
            continue  # no row's centre between its top and bottom: _fill_convex would write nothing
        ax, ay = sx[a], sy[a]
        if not back:
            # Back faces first (about half of a closed mesh): a planar polygon is
            # back-facing when both its fan triangles are (signed area >= 0).
            if not (sx[b] - ax) * (sy[c] - ay) - (sy[b] - ay) * (sx[c] - ax) < 0.0 and (
                n == 3 or not (sx[c] - ax) * (sy[d] - ay) - (sy[c] - ay) * (sx[d] - ax) < 0.0
            ):
                continue
        xmin, xmax = _extent(sx, a, b, c, d)
        if xmax <= c_lo or xmin >= c_hi + 0.5:
            continue
        clamp = not (xmin >= c_lo and xmax <= c_hi)
        # A strictly convex quad is one part; any other quad (seen nearly
        # edge-on) goes as its fan triangles, each with its own facing.
        parts = 1
        if n == 4:
            neg = 0
            pos = 0
            for k in range(4):
                i0 = polys[p, k]
                i1 = polys[p, (k + 1) % 4]
                i2 = polys[p, (k + 2) % 4]
                crs = (sx[i1] - sx[i0]) * (sy[i2] - sy[i1]) - (sy[i1] - sy[i0]) * (sx[i2] - sx[i1])
                if crs < 0.0:
                    neg += 1
                elif crs > 0.0:
                    pos += 1
            if neg != 4 and pos != 4:
                parts = 2
        for part in range(parts):
            m = n if parts == 1 else 3
            for k in range(m):
                v = a if k == 0 else polys[p, k + part]
                px[k], py[k], pk[k] = sx[v], sy[v], sk[v]
            s2 = 0.0
            for k in range(m):
                k1 = (k + 1) % m
                s2 += px[k] * py[k1] - px[k1] * py[k]
            if not (s2 < 0.0 or back and s2 > 0.0) or not math.isfinite(s2):
                continue  # culled, or no area
            front = s2 < 0.0
            if not front:  # clockwise on screen: reverse the ring (the same fan triangles)
                for k in range(1, (m + 1) // 2):
                    k2 = m - k
                    px[k], px[k2] = px[k2], px[k]
                    py[k], py[k2] = py[k2], py[k]
                    pk[k], pk[k2] = pk[k2], pk[k]
            _fill_convex(px, py, pk, m, vout[p] if front else vin[p], tag, ox, oy, clamp, front,
                         zf if front else zb, vf if front else vb, tf, bounds)


# Small renders without numba (isocsg._jit): the polygon loop vectorised, and the entry points,
# whose own Python is a few lines around it, run as written whatever their size.
_fill_polys.twin(fill_polys_numpy)
for _entry in (fill_projected, fill_front_kernel, fill_front_runs):
    _entry.twin(_entry.py_func)
