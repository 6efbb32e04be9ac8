"""The polygon fill (:func:`~isocsg.rendering.polygons._fill_polys`) vectorised with NumPy.

A small render's first image runs this instead of importing numba
(:mod:`isocsg._jit`): the same polygons, culled and split the same way, the
same rows and spans, each span's depth keys summed one step at a time as the
kernel does, and each pixel kept from the first polygon with the nearest
(front) or farthest (back) key. Every value is computed with the same
floating-point operations in the same order, so the buffers come out with the
same bits. A polygon crossing the near plane is handed to the kernel's own
clipping (``_fill_one``), in sequence with the polygons around it.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray

from .triangles import _fill_one

__all__ = ["fill_polys_numpy"]

_I64 = np.int64


def _ceil_int(x: NDArray[np.float64]) -> NDArray[np.int64]:
    """``int(math.ceil(x))`` elementwise."""
    return np.ceil(x).astype(_I64)


def fill_polys_numpy(
    proj: NDArray[np.float64], polys: NDArray[np.int32], vout: NDArray[np.float32], vin: NDArray[np.float32],
    near: float, perspective: bool, back: bool, tag: int, ox: int, oy: int,
    zf: NDArray[np.float64], vf: NDArray[np.float32], tf: NDArray[np.int32],
    zb: NDArray[np.float64], vb: NDArray[np.float32], bounds: NDArray[np.int64], scratch: NDArray[np.float64],
) -> None:
    """:func:`~isocsg.rendering.polygons._fill_polys`, the same arguments and the same buffers."""
    with np.errstate(all="ignore"):  # the kernel's arithmetic: inf and NaN where it divides by zero
        _fill_all(proj, polys, vout, vin, near, perspective, back, tag, ox, oy, zf, vf, tf, zb, vb, bounds, scratch)


def _fill_all(
    proj: NDArray[np.float64], polys: NDArray[np.int32], vout: NDArray[np.float32], vin: NDArray[np.float32],
    near: float, perspective: bool, back: bool, tag: int, ox: int, oy: int,
    zf: NDArray[np.float64], vf: NDArray[np.float32], tf: NDArray[np.int32],
    zb: NDArray[np.float64], vb: NDArray[np.float32], bounds: NDArray[np.int64], scratch: NDArray[np.float64],
) -> None:
    """Runs of polygons in front of the near plane, vectorised, between the ones crossing it."""
    hd = proj[3]
    quad = polys[:, 3] >= 0
    inside = (hd[polys[:, 0]] >= near) & (hd[polys[:, 1]] >= near) & (hd[polys[:, 2]] >= near)
    inside &= ~quad | (hd[np.where(quad, polys[:, 3], 0)] >= near)
    crossing = np.flatnonzero(~inside)
    start = 0
    for p in [*crossing.tolist(), len(polys)]:  # runs between polygons crossing the near plane, in order
        if p > start:
            _fill_run(proj, polys[start:p], vout[start:p], vin[start:p], bool(back), int(tag), int(ox), int(oy),
                      zf, vf, tf, zb, vb, bounds)
        if p < len(polys):
            _clip_one(proj, polys, p, vout, vin, near, perspective, back, tag, ox, oy, zf, vf, tf, zb, vb, bounds,
                      scratch)
        start = p + 1


def _clip_one(proj: NDArray[np.float64], polys: NDArray[np.int32], p: int, vout: NDArray[np.float32],
              vin: NDArray[np.float32], near: float, perspective: bool, back: bool, tag: int, ox: int, oy: int,
              zf: NDArray[np.float64], vf: NDArray[np.float32], tf: NDArray[np.int32], zb: NDArray[np.float64],
              vb: NDArray[np.float32], bounds: NDArray[np.int64], scratch: NDArray[np.float64]) -> None:
    """The kernel's handling of one polygon crossing the near plane: clipped triangle by triangle."""
    a, b, c, d = (int(i) for i in polys[p])
    rows = tuple(proj[:7])
    px, py, pk = scratch[0], scratch[1], scratch[2]
    for t1, t2 in ((b, c), (c, d)) if d >= 0 else ((b, c),):
        _fill_one(*rows, a, t1, t2, near, perspective, np.bool_(True), back, vout[p], vin[p], tag, ox, oy,
                  zf, vf, tf, zb, vb, px, py, pk)
    h, w = zf.shape
    bounds[0] = min(bounds[0], oy)
    bounds[1] = max(bounds[1], oy + h)
    bounds[2] = min(bounds[2], ox)
    bounds[3] = max(bounds[3], ox + w)


def _extent(t: NDArray[np.float64], polys: NDArray[np.int64], quad: NDArray[np.bool_]) -> tuple[Any, Any]:
    corners = t[polys[:, :3]]
    fourth = t[np.where(quad, polys[:, 3], polys[:, 0])]
    lo = np.minimum(corners.min(axis=1), fourth)
    hi = np.maximum(corners.max(axis=1), fourth)
    return lo, hi


def _fill_run(proj: NDArray[np.float64], polys32: NDArray[np.int32], vout: NDArray[np.float32],
              vin: NDArray[np.float32], back: bool, tag: int, ox: int, oy: int,
              zf: NDArray[np.float64], vf: NDArray[np.float32], tf: NDArray[np.int32], zb: NDArray[np.float64],
              vb: NDArray[np.float32], bounds: NDArray[np.int64]) -> None:
    """Polygons all in front of the near plane: their parts, then their spans."""
    sx, sy, sk = proj[4], proj[5], proj[6]
    h, w = zf.shape
    polys = polys32.astype(_I64)
    quad = polys[:, 3] >= 0
    ymin, ymax = _extent(sy, polys, quad)
    keep = ~((ymax <= float(oy)) | (ymin >= float(oy + h) + 0.5))
    keep &= ~(np.ceil(ymin - 0.5) >= np.ceil(ymax - 0.5))
    a, b, c = polys[:, 0], polys[:, 1], polys[:, 2]
    d = np.where(quad, polys[:, 3], a)
    ax, ay = sx[a], sy[a]
    if not back:
        first = ~((sx[b] - ax) * (sy[c] - ay) - (sy[b] - ay) * (sx[c] - ax) < 0.0)
        second = ~((sx[c] - ax) * (sy[d] - ay) - (sy[c] - ay) * (sx[d] - ax) < 0.0)
        keep &= ~(first & (~quad | second))
    xmin, xmax = _extent(sx, polys, quad)
    keep &= ~((xmax <= float(ox)) | (xmin >= float(ox + w) + 0.5))
    clamp = ~((xmin >= float(ox)) & (xmax <= float(ox + w)))
    # A quad that is not strictly convex on screen goes as its two fan triangles.
    neg = np.zeros(len(polys), _I64)
    pos = np.zeros(len(polys), _I64)
    for k in range(4):
        i0, i1, i2 = polys[:, k], polys[:, (k + 1) % 4], polys[:, (k + 2) % 4]
        crs = (sx[i1] - sx[i0]) * (sy[i2] - sy[i1]) - (sy[i1] - sy[i0]) * (sx[i2] - sx[i1])
        neg += crs < 0.0
        pos += crs > 0.0
    split = quad & (neg != 4) & (pos != 4)
    idx = np.flatnonzero(keep)
    whole = idx[~split[idx]]
    halves = idx[split[idx]]
    # Parts in the kernel's order: polygon by polygon, a split quad's (a, b, c) before its (a, c, d).
    owner = np.concatenate([whole, halves, halves])
    rank = np.concatenate([2 * whole, 2 * halves, 2 * halves + 1])
    ring = np.full((len(owner), 4), -1, _I64)
    ring[: len(whole)] = polys[whole]
    ring[len(whole): len(whole) + len(halves), :3] = polys[halves][:, [0, 1, 2]]
    ring[len(whole) + len(halves):, :3] = polys[halves][:, [0, 2, 3]]
    order = np.argsort(rank, kind="stable")
    owner, ring, clamp = owner[order], ring[order], clamp[owner[order]]
    m = np.where(ring[:, 3] >= 0, 4, 3)
    safe = np.where(ring >= 0, ring, ring[:, :1])
    px, py, pk = sx[safe], sy[safe], sk[safe]
    s2 = np.zeros(len(ring))
    for k in range(4):
        k1 = np.where(k + 1 < m, k + 1, 0)
        term = px[:, k] * py[np.arange(len(ring)), k1] - px[np.arange(len(ring)), k1] * py[:, k]
        s2 = np.where(k < m, s2 + term, s2)
    live = ((s2 < 0.0) | (back & (s2 > 0.0))) & np.isfinite(s2)
    front = s2 < 0.0
    # Clockwise on screen: the ring reversed (the same fan triangles).
    flip = live & ~front
    rev = np.where((m == 4)[:, None], [0, 3, 2, 1], [0, 2, 1, 3])
    for arr in (px, py, pk):
        arr[flip] = np.take_along_axis(arr[flip], rev[flip], axis=1)
    for facing in (True, False):
        sel = np.flatnonzero(live & (front == facing))
        if not len(sel):
            continue
        values = (vout if facing else vin)[owner[sel]]
        zbuf, vbuf = (zf, vf) if facing else (zb, vb)
        _fill_convex(px[sel], py[sel], pk[sel], m[sel], values, clamp[sel], facing, tag, ox, oy,
                     zbuf, vbuf, tf, bounds)


def _top_bottom(px: NDArray[np.float64], py: NDArray[np.float64],
                m: NDArray[np.int64]) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    rows = np.arange(len(m))
    top = np.zeros(len(m), _I64)
    bot = np.zeros(len(m), _I64)
    for k in range(1, 4):
        valid = k < m
        yt, xt = py[rows, top], px[rows, top]
        yb, xb = py[rows, bot], px[rows, bot]
        top = np.where(valid & ((py[:, k] < yt) | ((py[:, k] == yt) & (px[:, k] < xt))), k, top)
        bot = np.where(valid & ((py[:, k] > yb) | ((py[:, k] == yb) & (px[:, k] > xb))), k, bot)
    return top, bot


def _depth_plane(px: NDArray[np.float64], py: NDArray[np.float64], pk: NDArray[np.float64],
                 m: NDArray[np.int64]) -> tuple[Any, ...]:
    """The kernel's ``_depth_plane`` for every part: has-area, gradients, anchor."""
    rows = np.arange(len(m))
    area = (px[:, 1] - px[:, 0]) * (py[:, 2] - py[:, 0]) - (py[:, 1] - py[:, 0]) * (px[:, 2] - px[:, 0])
    area3 = (px[:, 2] - px[:, 0]) * (py[:, 3] - py[:, 0]) - (py[:, 2] - py[:, 0]) * (px[:, 3] - px[:, 0])
    second = (m == 4) & (np.abs(area3) > np.abs(area))
    t1 = np.where(second, 2, 1)
    area = np.where(second, area3, area)
    ok = ~((area == 0.0) | ~np.isfinite(area))
    t2 = t1 + 1
    x1, y1, k1 = px[rows, t1] - px[:, 0], py[rows, t1] - py[:, 0], pk[rows, t1] - pk[:, 0]
    x2, y2, k2 = px[rows, t2] - px[:, 0], py[rows, t2] - py[:, 0], pk[rows, t2] - pk[:, 0]
    gx = (k1 * y2 - k2 * y1) / area
    gy = (k2 * x1 - k1 * x2) / area
    an = np.zeros(len(m), _I64)
    an = np.where(pk[rows, t1] > pk[rows, an], t1, an)
    an = np.where(pk[rows, t2] > pk[rows, an], t2, an)
    return ok, gx, gy, pk[rows, an], px[rows, an], py[rows, an]


def _chain_edge(thr: NDArray[np.int64], top: NDArray[np.int64], bot: NDArray[np.int64], m: NDArray[np.int64],
                step: int, part: NDArray[np.int64], row: NDArray[np.int64]) -> tuple[NDArray[np.int64], ...]:
    """The edge ``(li, ln)`` of a chain (from the top: ``step`` +1 the left, -1 the right) that the
    kernel's walk is on at each ``row`` of ``part``: it moves on while the row has reached the
    threshold ``thr`` (per part and vertex) of the edge's far end, and stops at the bottom."""
    length = (step * (bot - top)) % m + 1  # vertices from the top to the bottom
    chain = (top[:, None] + step * np.arange(4)) % m[:, None]  # the vertex at each position
    far = np.take_along_axis(thr, chain, axis=1)
    last = length[part] - 2
    first = (last >= 1) & (row >= far[:, 1][part])  # flat gathers: 2-d fancy indexing is slower
    second = first & (last >= 2) & (row >= far[:, 2][part])
    at = 4 * part + first + second
    flat = chain.reshape(-1)
    return flat[at], flat[at + 1]


def _fill_convex(px: NDArray[np.float64], py: NDArray[np.float64], pk: NDArray[np.float64], m: NDArray[np.int64],
                 values: NDArray[np.float32], clamp: NDArray[np.bool_], front: bool, tag: int, ox: int, oy: int,
                 zbuf: NDArray[np.float64], vbuf: NDArray[np.float32], tbuf: NDArray[np.int32],
                 bounds: NDArray[np.int64]) -> None:
    """The kernel's ``_fill_convex`` of parts that all face one way, into one pair of buffers."""
    h, w = zbuf.shape
    rows = np.arange(len(m))
    top, bot = _top_bottom(px, py, m)
    lo = np.maximum(float(oy) - 1.0, py[rows, top] - 0.5)
    hi = np.minimum(float(oy + h), py[rows, bot] - 0.5)
    i_start = np.maximum(oy, _ceil_int(lo))
    i_end = np.minimum(oy + h, _ceil_int(hi))
    ok, gx, gy, ka, xa, ya = _depth_plane(px, py, pk, m)
    ok &= i_start < i_end
    cmin, cmax = float(ox) - 1.0, float(ox + w)
    if ok.any():
        sel = np.flatnonzero(ok)
        valid = np.arange(4) < m[sel, None]
        xmin = np.where(valid, px[sel], np.inf).min(axis=1)
        xmax = np.where(valid, px[sel], -np.inf).max(axis=1)
        bounds[0] = min(bounds[0], int(i_start[sel].min()))
        bounds[1] = max(bounds[1], int(i_end[sel].max()))
        c0 = np.maximum(ox, _ceil_int(np.minimum(np.maximum(xmin, cmin), cmax) - 0.5))
        c1 = np.minimum(ox + w, _ceil_int(np.minimum(np.maximum(xmax, cmin), cmax) - 0.5))
        bounds[2] = min(bounds[2], int(c0.min()))
        bounds[3] = max(bounds[3], int(c1.max()))
    count = np.where(ok, i_end - i_start, 0)
    part = np.repeat(rows, count)
    if not len(part):
        return
    row = i_start[part] + (np.arange(len(part)) - np.repeat(np.cumsum(count) - count, count))
    # The kernel's l_thr / r_thr of each vertex: the first row on the edges after it.
    thr = _ceil_int(np.minimum(np.maximum(lo[:, None], py - 0.5), hi[:, None]))
    pyc = row + 0.5
    xs = []
    fx, fy, base = px.reshape(-1), py.reshape(-1), 4 * part
    for step in (1, -1):
        li, ln = _chain_edge(thr, top, bot, m, step, part, row)
        ex, ey = fx[base + li], fy[base + li]
        slope = (fx[base + ln] - ex) / (fy[base + ln] - ey)
        xs.append(ex + (pyc - ey) * slope)
    xl, xr = xs
    cl = clamp[part]
    xl = np.where(cl, np.minimum(np.maximum(xl, cmin), cmax), xl)
    xr = np.where(cl, np.minimum(np.maximum(xr, cmin), cmax), xr)
    j0 = _ceil_int(xl - 0.5)
    j1 = _ceil_int(xr - 0.5)
    j0 = np.where(cl, np.maximum(ox, j0), j0)
    j1 = np.where(cl, np.minimum(ox + w, j1), j1)
    span = j0 < j1
    part, row, j0, j1, pyc = part[span], row[span], j0[span], j1[span], pyc[span]
    q = ka[part] + gx[part] * (j0 + 0.5 - xa[part]) + gy[part] * (pyc - ya[part])
    _write_spans(part, row - oy, j0 - ox, j1 - j0, q, gx[part], values[part], front, tag, zbuf, vbuf, tbuf)


def _write_spans(part: NDArray[np.int64], row: NDArray[np.int64], col: NDArray[np.int64], length: NDArray[np.int64],
                 q: NDArray[np.float64], gx: NDArray[np.float64], values: NDArray[np.float32], front: bool, tag: int,
                 zbuf: NDArray[np.float64], vbuf: NDArray[np.float32], tbuf: NDArray[np.int32]) -> None:
    """Depth-tested spans: each pixel takes the first (in part order) of its nearest keys
    (farthest for back faces) if it beats the buffer, as the kernel's sequence of writes leaves it."""
    if not len(length):
        return
    w = zbuf.shape[1]
    key_parts: list[NDArray[np.float64]] = []
    pixel_parts: list[NDArray[np.int64]] = []
    who_parts: list[NDArray[np.int64]] = []
    # Keys summed one step at a time (np.add.accumulate is sequential along a row), spans grouped
    # by length up to a power of two so that the padded rows at most double the work.
    top = int(length.max())
    edges = [0] + [1 << b for b in range(top.bit_length() + 1)]
    for lo, hi in zip(edges[:-1], edges[1:]):
        sel = np.flatnonzero((length > lo) & (length <= hi))
        if not len(sel) or lo >= top:
            continue
        width = int(length[sel].max())
        steps = np.repeat(gx[sel, None], width, axis=1)
        steps[:, 0] = q[sel]
        acc = np.add.accumulate(steps, axis=1)
        valid = np.arange(width) < length[sel, None]
        key_parts.append(acc[valid])
        pixel_parts.append(((row * w + col)[sel, None] + np.arange(width))[valid])
        who_parts.append(np.repeat(sel, length[sel]))
    keys, pixel, who = np.concatenate(key_parts), np.concatenate(pixel_parts), np.concatenate(who_parts)
    good = ~np.isnan(keys)
    keys, pixel, who = keys[good], pixel[good], who[good]
    # A pixel met by several spans keeps the first of its best keys (the spans are in part order).
    dup = np.bincount(pixel)[pixel] > 1
    if dup.any():
        d = np.flatnonzero(dup)
        d = d[np.lexsort((who[d], keys[d] if front else -keys[d], pixel[d]))]
        lead = np.ones(len(d), bool)
        lead[1:] = pixel[d[1:]] != pixel[d[:-1]]
        pick = np.concatenate([np.flatnonzero(~dup), d[lead]])
        keys, pixel, who = keys[pick], pixel[pick], who[pick]
    r, c = np.divmod(pixel, w)
    old = zbuf[r, c]
    win = keys < old if front else keys > old
    r, c, keys, who = r[win], c[win], keys[win], who[win]
    zbuf[r, c] = keys
    vbuf[r, c] = values[who]
    if front and tag >= 0:
        tbuf[r, c] = np.int32(tag)
