"""A bounding-volume hierarchy over a triangle mesh: rays to depth intervals, points to nearest faces.

The hierarchy is built once per mesh, iteratively (an explicit stack of index ranges, each
split at the median centroid along its widest axis until at most :data:`LEAF_SIZE`
triangles remain). Nodes are flat arrays: ``lo, hi (m, 3)`` boxes, ``left`` (the first child,
the second is ``left + 1``; -1 for a leaf) and ``start, count`` (the leaf's range of ``order``).

Rays (:func:`bvh_ray_intervals`) are intersected over the whole line (``t`` of either sign) with
the watertight test of Woop, Benthin and Wald (2013): the ray's frame is sheared so that it runs
along +z, each triangle's corners are projected once per ray, and the three edge functions
``E = p_x q_y - p_y q_x`` decide coverage. A shared edge's function is computed from the same
projected corners in both triangles and is exactly the negation of the other's, so no ray slips
through a crack between faces. **Degenerate hits**: when an edge function is exactly zero (the
ray passes through an edge or a vertex), the edge counts as covered only if its direction in the
triangle's counter-clockwise order (as seen along the ray) satisfies ``dy > 0 or (dy == 0 and
dx < 0)`` (a top-left rule). The rule is antisymmetric in the edge's direction, so a ray through
an edge shared by two faces of one sheet is counted by exactly one of them, and a ray through a
vertex by exactly one face of its fan; a ray grazing a silhouette edge is counted by both faces
or by neither, and those two hits (one entering, one leaving, at the same depth) cancel.
Triangles seen edge-on (zero projected area) are never hit.

Each hit carries a sign, +1 where the ray enters (its direction against the face's outward
normal) and -1 where it leaves. Sorted by depth, the running sum is the winding number of the
ray's points; intervals are where it is positive (for a valid mesh it is 0 or 1: parity).
Touching intervals (one ends where the next begins) are merged and empty ones dropped.

Points (:func:`bvh_nearest`) find their nearest triangle exactly (Ericson's closest point on a
triangle, nearer boxes first); edges (:func:`bvh_edge_crossing`) find a face they pass through,
the mesh's self-intersection test.
"""

from __future__ import annotations

import os
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._jit import njit

__all__ = ["BOX_PADDING", "LEAF_SIZE", "bvh_edge_crossing", "build_bvh", "bvh_ray_intervals", "bvh_nearest",
           "bvh_winding_parity"]

#: Triangles per leaf of the hierarchy at most.
LEAF_SIZE = 4

#: How much every box of the hierarchy is grown, relative to the mesh's size and coordinates.
BOX_PADDING = 1e-9

@njit(cache=True, nogil=True)
def _build(tri_lo: Any, tri_hi: Any, cen: Any, leaf: Any) -> Any:
    n = cen.shape[0]
    cap = max(2 * n, 1)
    lo = np.empty((cap, 3))
    hi = np.empty((cap, 3))
    left = np.full(cap, -1, np.int64)
    start = np.zeros(cap, np.int64)
    count = np.zeros(cap, np.int64)
    order = np.arange(n)
    stack = np.empty((cap, 3), np.int64)  # node, first, last (exclusive)
    stack[0, 0], stack[0, 1], stack[0, 2] = 0, 0, n
    top = 1
    nodes = 1
    while top > 0:
        top -= 1
        node, a, b = stack[top, 0], stack[top, 1], stack[top, 2]
        for k in range(3):
            lo[node, k] = np.inf
            hi[node, k] = -np.inf
        clo = np.full(3, np.inf)
        chi = np.full(3, -np.inf)
        for i in range(a, b):
            t = order[i]
            for k in range(3):
                lo[node, k] = min(lo[node, k], tri_lo[t, k])
                hi[node, k] = max(hi[node, k], tri_hi[t, k])
                clo[k] = min(clo[k], cen[t, k])
                chi[k] = max(chi[k], cen[t, k])
        if b - a <= leaf:
            start[node], count[node] = a, b - a
            continue
        axis = 0
        for k in range(1, 3):
            if chi[k] - clo[k] > chi[axis] - clo[axis]:
                axis = k
        seg = order[a:b].copy()
        keys = cen[seg, axis]
        seg = seg[np.argsort(keys, kind="mergesort")]
        order[a:b] = seg
        mid = (a + b) // 2
        left[node] = nodes
        stack[top, 0], stack[top, 1], stack[top, 2] = nodes, a, mid
        stack[top + 1, 0], stack[top + 1, 1], stack[top + 1, 2] = nodes + 1, mid, b
        top += 2
        nodes += 2
    return lo[:nodes].copy(), hi[:nodes].copy(), left[:nodes].copy(), start[:nodes].copy(), count[:nodes].copy(), order


def build_bvh(vertices: NDArray[np.float64], faces: NDArray[np.int64]) -> tuple[NDArray[np.float64], ...]:
    """The hierarchy of the triangles ``vertices[faces]``: ``(lo, hi, left, start, count, order)``."""
    tri = vertices[faces]
    lo, hi, left, start, count, order = _build(tri.min(axis=1), tri.max(axis=1), tri.mean(axis=1), LEAF_SIZE)
    # Boxes grown by BOX_PADDING of the mesh's size: a ray through a vertex or an edge on a box's
    # boundary must not miss the box by a rounding of the slab test (the triangles decide exactly).
    pad = BOX_PADDING * max(float(np.max(np.ptp(vertices, axis=0))), float(np.max(np.abs(vertices))))
    return lo - pad, hi + pad, left, start, count, order


@njit(cache=True, nogil=True)
def _slab(o: Any, inv: Any, lo: Any, hi: Any, node: Any) -> Any:
    """Whether the line ``o + t d`` (``inv = 1 / d``) meets the node's box (any t)."""
    t0 = -np.inf
    t1 = np.inf
    for k in range(3):
        if inv[k] == np.inf or inv[k] == -np.inf:
            if o[k] < lo[node, k] or o[k] > hi[node, k]:
                return False
            continue
        a = (lo[node, k] - o[k]) * inv[k]
        b = (hi[node, k] - o[k]) * inv[k]
        if a > b:
            a, b = b, a
        t0 = max(t0, a)
        t1 = min(t1, b)
    return t0 <= t1


@njit(cache=True, nogil=True)
def _covered(e: Any, px: Any, py: Any, qx: Any, qy: Any, s: Any) -> Any:
    """Edge function ``e`` of the edge p -> q of a triangle of orientation ``s`` (+-1): inside, with
    the top-left rule on exact zeros (see the module docstring)."""
    if e * s > 0.0:
        return True
    if e != 0.0:
        return False
    dx = (qx - px) * s
    dy = (qy - py) * s
    return dy > 0.0 or (dy == 0.0 and dx < 0.0)


@njit(cache=True, nogil=True)
def _ray_hits(o: Any, d: Any, V: Any, F: Any, lo: Any, hi: Any, left: Any, start: Any, count: Any,
              order: Any, stack: Any, ts: Any, signs: Any) -> Any:
    """Signed hits of one ray (any t) into ``ts``/``signs``; returns how many (they may exceed the
    buffers' length: the caller grows them and asks again)."""
    kz = 0
    for k in range(1, 3):
        if abs(d[k]) > abs(d[kz]):
            kz = k
    kx = (kz + 1) % 3
    ky = (kx + 1) % 3
    if d[kz] < 0.0:
        kx, ky = ky, kx  # keep the frame right-handed
    sx = d[kx] / d[kz]
    sy = d[ky] / d[kz]
    sz = 1.0 / d[kz]
    inv = np.empty(3)
    for k in range(3):
        inv[k] = 1.0 / d[k] if d[k] != 0.0 else np.inf
    m = 0
    top = 1
    stack[0] = 0
    cap = ts.shape[0]
    while top > 0:
        top -= 1
        node = stack[top]
        if not _slab(o, inv, lo, hi, node):
            continue
        if left[node] >= 0:
            stack[top] = left[node]
            stack[top + 1] = left[node] + 1
            top += 2
            continue
        for i in range(start[node], start[node] + count[node]):
            f = order[i]
            a, b, c = F[f, 0], F[f, 1], F[f, 2]
            az = V[a, kz] - o[kz]
            bz = V[b, kz] - o[kz]
            cz = V[c, kz] - o[kz]
            ax = V[a, kx] - o[kx] - sx * az
            ay = V[a, ky] - o[ky] - sy * az
            bx = V[b, kx] - o[kx] - sx * bz
            by = V[b, ky] - o[ky] - sy * bz
            cx = V[c, kx] - o[kx] - sx * cz
            cy = V[c, ky] - o[ky] - sy * cz
            eab = ax * by - ay * bx
            ebc = bx * cy - by * cx
            eca = cx * ay - cy * ax
            det = eab + ebc + eca
            if det == 0.0:
                continue
            s = 1.0 if det > 0.0 else -1.0
            if not (_covered(eab, ax, ay, bx, by, s) and _covered(ebc, bx, by, cx, cy, s)
                    and _covered(eca, cx, cy, ax, ay, s)):
                continue
            if m < cap:
                ts[m] = (ebc * az + eca * bz + eab * cz) * sz / det
                # counter-clockwise seen along +z (the ray) means the normal points along the ray: leaving
                signs[m] = -1 if det > 0.0 else 1
            m += 1
    return m


@njit(cache=True, nogil=True)
def _intervals_of(ts: Any, signs: Any, m: Any, out: Any, row: Any) -> Any:
    """Sorted hits to intervals where the winding number is positive; returns how many."""
    idx = np.argsort(ts[:m])
    w = 0
    k = 0
    kmax = out.shape[1]
    t_open = 0.0
    for j in range(m):
        t = ts[idx[j]]
        before = w
        w += signs[idx[j]]
        if before <= 0 and w > 0:
            if k > 0 and k <= kmax and out[row, k - 1, 1] >= t:  # touching the previous: merge
                k -= 1
                t_open = out[row, k, 0]
            else:
                t_open = t
        elif before > 0 and w <= 0:
            if t > t_open:
                if k < kmax:
                    out[row, k, 0] = t_open
                    out[row, k, 1] = t
                k += 1
    return k


@njit(cache=True, nogil=True)
def _all_intervals(O: Any, D: Any, V: Any, F: Any, lo: Any, hi: Any, left: Any, start: Any, count: Any,
                   order: Any, out: Any, need: Any) -> Any:
    stack = np.empty(256, np.int64)  # a median split of 20 million faces is 23 levels deep
    ts = np.empty(64)
    signs = np.empty(64, np.int64)
    for r in range(O.shape[0]):
        m = _ray_hits(O[r], D[r], V, F, lo, hi, left, start, count, order, stack, ts, signs)
        if m > ts.shape[0]:  # more hits than room: grow and trace again
            ts = np.empty(2 * m)
            signs = np.empty(2 * m, np.int64)
            m = _ray_hits(O[r], D[r], V, F, lo, hi, left, start, count, order, stack, ts, signs)
        need[r] = _intervals_of(ts, signs, m, out, r)


#: Rays per task when a call holds many (the kernels release the GIL: tasks run on several cores).
RAY_CHUNK = 16384


def _traced(O: Any, D: Any, V: Any, F: Any, bvh: tuple[NDArray[np.float64], ...], out: Any, need: Any) -> None:
    """:func:`_all_intervals` over blocks of rays, on a thread pool when there are several blocks."""
    lo, hi, left, start, count, order = bvh
    n = O.shape[0]
    blocks = [(s, min(s + RAY_CHUNK, n)) for s in range(0, n, RAY_CHUNK)]

    def run(block: tuple[int, int]) -> None:
        a, b = block
        _all_intervals(O[a:b], D[a:b], V, F, lo, hi, left, start, count, order, out[a:b], need[a:b])

    if len(blocks) <= 1:
        for block in blocks:
            run(block)
        return
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(max_workers=min(len(blocks), os.cpu_count() or 1)) as pool:
        list(pool.map(run, blocks))


def bvh_ray_intervals(
    bvh: tuple[NDArray[np.float64], ...], vertices: NDArray[np.float64], faces: NDArray[np.int64],
    origins: NDArray[np.float64], directions: NDArray[np.float64], width: int = 4,
) -> NDArray[np.float64]:
    """Every depth interval of each line ``o + t d`` in the solid, ``(n, k, 2)`` NaN padded, with
    ``k`` the most any of the given rays needs (at least 1)."""
    n = len(origins)
    O = np.ascontiguousarray(origins, np.float64)
    D = np.ascontiguousarray(directions, np.float64)
    out = np.full((n, max(width, 1), 2), np.nan)
    need = np.zeros(n, np.int64)
    _traced(O, D, vertices, faces, bvh, out, need)
    most = int(need.max()) if n else 0
    if most > out.shape[1]:  # some rays need more columns: those rays again, wider
        rows = np.nonzero(need > out.shape[1])[0]
        wide = np.full((len(rows), most, 2), np.nan)
        _traced(O[rows], D[rows], vertices, faces, bvh, wide, np.zeros(len(rows), np.int64))
        grown = np.full((n, most, 2), np.nan)
        grown[:, : out.shape[1]] = out
        grown[rows] = wide
        out = grown
    return out[:, : max(most, 1)]


@njit(cache=True, nogil=True)
def _closest_on_triangle(p: Any, a: Any, b: Any, c: Any) -> Any:
    """The point of triangle abc nearest p (Ericson, Real-Time Collision Detection, 5.1.5)."""
    ab = b - a
    ac = c - a
    ap = p - a
    d1 = ab @ ap
    d2 = ac @ ap
    if d1 <= 0.0 and d2 <= 0.0:
        return a
    bp = p - b
    d3 = ab @ bp
    d4 = ac @ bp
    if d3 >= 0.0 and d4 <= d3:
        return b
    vc = d1 * d4 - d3 * d2
    if vc <= 0.0 and d1 >= 0.0 and d3 <= 0.0:
        return a + (d1 / (d1 - d3)) * ab
    cp = p - c
    d5 = ab @ cp
    d6 = ac @ cp
    if d6 >= 0.0 and d5 <= d6:
        return c
    vb = d5 * d2 - d1 * d6
    if vb <= 0.0 and d2 >= 0.0 and d6 <= 0.0:
        return a + (d2 / (d2 - d6)) * ac
    va = d3 * d6 - d5 * d4
    if va <= 0.0 and (d4 - d3) >= 0.0 and (d5 - d6) >= 0.0:
        return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b)
    denom = 1.0 / (va + vb + vc)
    return a + ab * (vb * denom) + ac * (vc * denom)


@njit(cache=True, nogil=True)
def _box_distance2(p: Any, lo: Any, hi: Any, node: Any) -> Any:
    s = 0.0
    for k in range(3):
        if p[k] < lo[node, k]:
            s += (lo[node, k] - p[k]) ** 2
        elif p[k] > hi[node, k]:
            s += (p[k] - hi[node, k]) ** 2
    return s


@njit(cache=True, nogil=True)
def _nearest(P: Any, V: Any, F: Any, lo: Any, hi: Any, left: Any, start: Any, count: Any, order: Any,
             dist: Any, face: Any) -> Any:
    for r in range(P.shape[0]):
        p = P[r].copy()
        stack = np.empty(256, np.int64)
        top = 1
        stack[0] = 0
        best = np.inf
        arg = -1
        while top > 0:
            top -= 1
            node = stack[top]
            if _box_distance2(p, lo, hi, node) >= best:
                continue
            if left[node] >= 0:
                a, b = left[node], left[node] + 1
                # the nearer child last: popped first
                if _box_distance2(p, lo, hi, a) < _box_distance2(p, lo, hi, b):
                    a, b = b, a
                stack[top] = a
                stack[top + 1] = b
                top += 2
                continue
            for i in range(start[node], start[node] + count[node]):
                f = order[i]
                q = _closest_on_triangle(p, V[F[f, 0]], V[F[f, 1]], V[F[f, 2]])
                d2 = 0.0
                for k in range(3):
                    d2 += (q[k] - p[k]) ** 2
                if d2 < best:
                    best = d2
                    arg = f
        dist[r] = np.sqrt(best)
        face[r] = arg


def bvh_nearest(
    bvh: tuple[NDArray[np.float64], ...], vertices: NDArray[np.float64], faces: NDArray[np.int64],
    points: NDArray[np.float64],
) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """The distance from each point to the nearest triangle and that triangle's index (exact)."""
    P = np.ascontiguousarray(points, np.float64)
    dist = np.empty(len(P))
    face = np.empty(len(P), np.int64)
    if len(P):
        lo, hi, left, start, count, order = bvh
        _nearest(P, vertices, faces, lo, hi, left, start, count, order, dist, face)
    return dist, face


#: The direction of the rays that decide inside from outside (irrational slopes: no axis, no face of
#: a gridded mesh is parallel to it).
PARITY_DIRECTION = np.array([0.5390536291, 0.6187223817, 0.5715066218])


def bvh_winding_parity(
    bvh: tuple[NDArray[np.float64], ...], vertices: NDArray[np.float64], faces: NDArray[np.int64],
    points: NDArray[np.float64],
) -> NDArray[np.bool_]:
    """Whether each point lies inside: in one of the intervals of the line through it along
    :data:`PARITY_DIRECTION` (its parameter 0)."""
    d = np.broadcast_to(PARITY_DIRECTION / np.linalg.norm(PARITY_DIRECTION), points.shape)
    iv = bvh_ray_intervals(bvh, vertices, faces, points, d)
    with np.errstate(invalid="ignore"):
        return np.any((iv[:, :, 0] <= 0.0) & (iv[:, :, 1] >= 0.0), axis=1)  # type: ignore[no-any-return]


@njit(cache=True, nogil=True)
def _segment_box(p: Any, d: Any, lo: Any, hi: Any, node: Any) -> Any:
    """Whether the segment ``p + t d``, ``0 <= t <= 1``, meets the node's box."""
    t0 = 0.0
    t1 = 1.0
    for k in range(3):
        if d[k] == 0.0:
            if p[k] < lo[node, k] or p[k] > hi[node, k]:
                return False
            continue
        a = (lo[node, k] - p[k]) / d[k]
        b = (hi[node, k] - p[k]) / d[k]
        if a > b:
            a, b = b, a
        t0 = max(t0, a)
        t1 = min(t1, b)
    return t0 <= t1


@njit(cache=True, nogil=True)
def _edge_crossings(V: Any, F: Any, E: Any, lo: Any, hi: Any, left: Any, start: Any, count: Any, order: Any,
                    tol: Any) -> Any:
    """The first edge ``E[i] = (a, b)`` that passes through a face without either end, its ends more
    than ``tol`` x its size off the face's plane on either side (Moller-Trumbore, edges of the face
    inclusive): ``(i, face)``, or ``(-1, -1)``."""
    stack = np.empty(256, np.int64)
    d = np.empty(3)
    for i in range(E.shape[0]):
        a, b = E[i, 0], E[i, 1]
        p = V[a]
        for k in range(3):
            d[k] = V[b, k] - p[k]
        top = 1
        stack[0] = 0
        while top > 0:
            top -= 1
            node = stack[top]
            if not _segment_box(p, d, lo, hi, node):
                continue
            if left[node] >= 0:
                stack[top] = left[node]
                stack[top + 1] = left[node] + 1
                top += 2
                continue
            for j in range(start[node], start[node] + count[node]):
                f = order[j]
                if F[f, 0] == a or F[f, 1] == a or F[f, 2] == a or F[f, 0] == b or F[f, 1] == b or F[f, 2] == b:
                    continue
                v0, v1, v2 = V[F[f, 0]], V[F[f, 1]], V[F[f, 2]]
                e1x, e1y, e1z = v1[0] - v0[0], v1[1] - v0[1], v1[2] - v0[2]
                e2x, e2y, e2z = v2[0] - v0[0], v2[1] - v0[1], v2[2] - v0[2]
                sx, sy, sz = p[0] - v0[0], p[1] - v0[1], p[2] - v0[2]
                # The edge's ends must lie on opposite sides of the face's plane, each clearly off it:
                # an edge in (or rounding-close to) the plane of a coplanar neighbour never crosses it.
                nx, ny, nz = e1y * e2z - e1z * e2y, e1z * e2x - e1x * e2z, e1x * e2y - e1y * e2x
                nn = np.sqrt(nx * nx + ny * ny + nz * nz)
                if nn == 0.0:
                    continue  # a degenerate face
                s0 = (sx * nx + sy * ny + sz * nz) / nn
                s1 = s0 + (d[0] * nx + d[1] * ny + d[2] * nz) / nn
                scale = np.sqrt(max(d[0] * d[0] + d[1] * d[1] + d[2] * d[2],
                                    e1x * e1x + e1y * e1y + e1z * e1z, e2x * e2x + e2y * e2y + e2z * e2z))
                if not ((s0 < -tol * scale and s1 > tol * scale) or (s0 > tol * scale and s1 < -tol * scale)):
                    continue
                px, py, pz = d[1] * e2z - d[2] * e2y, d[2] * e2x - d[0] * e2z, d[0] * e2y - d[1] * e2x
                det = e1x * px + e1y * py + e1z * pz
                if det == 0.0:
                    continue  # the edge is parallel to the face's plane
                inv = 1.0 / det
                u = (sx * px + sy * py + sz * pz) * inv
                if u < 0.0 or u > 1.0:
                    continue
                qx, qy, qz = sy * e1z - sz * e1y, sz * e1x - sx * e1z, sx * e1y - sy * e1x
                v = (d[0] * qx + d[1] * qy + d[2] * qz) * inv
                if v < 0.0 or u + v > 1.0:
                    continue
                t = (e2x * qx + e2y * qy + e2z * qz) * inv
                if tol < t < 1.0 - tol:
                    return i, f
    return -1, -1


def bvh_edge_crossing(
    bvh: tuple[NDArray[np.float64], ...], vertices: NDArray[np.float64], faces: NDArray[np.int64],
    edges: NDArray[np.int64], tol: float = 1e-9,
) -> tuple[int, int]:
    """An edge that passes through a face not incident to it, ``(edge row, face)``, or ``(-1, -1)``.

    Two triangles that cross (not in one plane) meet in a segment whose ends lie on edges, so every
    such pair has an edge of one through the other: this finds every transversal self-intersection
    of a mesh (faces overlapping within one plane are not seen)."""
    lo, hi, left, start, count, order = bvh
    i, f = _edge_crossings(vertices, faces, np.ascontiguousarray(edges, np.int64), lo, hi, left, start, count, order,
                           float(tol))
    return int(i), int(f)
