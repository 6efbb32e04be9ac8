"""The visible part of a source seen from a point: the source minus the occluders' silhouettes.

For a receiving point p (unit normal n) and one convex emitting polygon S
(plane Pi, normal N towards p, height h = N . (p - q0) > 0):

1. S is clipped by the receiving plane n . (x - p) >= 0 (type-B receivers),
   giving S_p.
2. For each convex occluder piece V, only its part between p's level and
   the source plane matters (0 <= N . (x - q0) <= h): the segment from p to
   a source point lies in that slab. The vertices of V n slab are V's
   vertices in the slab and its edges' crossings of the two slab planes;
   their central projections from p onto Pi span the blocked region (the
   silhouette seen from p, projected), a convex polygon B_V.
3. The blocked part of S_p is the union of C_V = S_p n B_V. Lambert's
   integral is additive over regions, so the blocked illuminance follows by
   inclusion-exclusion over the convex intersections of the C_V (exact, and
   cheap while few silhouettes overlap at a point); the visible illuminance
   is E(S_p) - E(union). Points where too many silhouettes overlap fall back
   to a 2D Boolean (shapely) of S_p minus the union of the C_V.

The slab's upper plane is lowered by a relative ``1e-9 h`` so that occluder
points level with p (a table leg standing on the floor that p lies on)
project to large but finite positions; the directions lost are those within
about ``1e-9 h / d`` of the plane through p parallel to the source, for an
occluder at distance d from p.

All of it runs compiled (numba): one serial kernel that releases the GIL,
over strided chunks of the points, on this thread and a small thread pool
(numba's ``NUMBA_NUM_THREADS`` threads in all). An occluder piece is skipped
cheaply when its bounding sphere lies outside the cone of directions from p
to S_p. What does not depend on p (each piece vertex's level over the source
plane and its source-frame coordinates, the crossings of the source plane)
is computed once per kernel call with the arithmetic the projection used per
point, so the values are bit for bit the same.
"""

from __future__ import annotations

import itertools
import math
import os
import threading
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor

import numba
import numpy as np
from numpy.typing import NDArray

from .lambert import edge_term_fast

__all__ = ["SourceArrays", "PieceArrays", "visible_illuminance", "blockers_single", "run_chunks", "MAXV", "MAXB"]

MAXV = 256  # vertices of one clipped polygon
MAXB = 24  # blocking silhouettes per point and source before the 2D Boolean fallback
MAXTERMS = 4096  # inclusion-exclusion terms before the fallback
SLAB_TOP = 1.0 - 1e-9  # upper slab plane, relative to h
UMBRA_TOL = 1e-9  # visible area below this fraction of S_p: umbra
SLIVER_TOL = 1e-12  # blocked pieces below this fraction of S_p are dropped

# Status flags of one (point, source) evaluation
ST_NA = -1  # the source has nothing in front of the point's planes
ST_LIT = 0
ST_PEN = 1
ST_UMB = 2
ST_OVERFLOW = 3


class SourceArrays:
    """Emitting convex polygons packed for the compiled kernel (one row per polygon)."""

    def __init__(self, polygons: list[NDArray[np.float64]], radiances: list[float], groups: list[int]) -> None:
        self.off = np.zeros(len(polygons) + 1, dtype=np.int64)
        self.off[1:] = np.cumsum([len(p) for p in polygons])
        self.verts = np.ascontiguousarray(np.vstack(polygons) if polygons else np.zeros((0, 3)))
        ns = len(polygons)
        self.normal = np.zeros((ns, 3))
        self.u = np.zeros((ns, 3))
        self.w = np.zeros((ns, 3))
        self.q0 = np.zeros((ns, 3))
        self.area = np.zeros(ns)
        for k, q in enumerate(polygons):
            c = q.mean(axis=0)
            nn = 0.5 * np.sum(np.cross(q - c, np.roll(q, -1, axis=0) - c), axis=0)
            a = np.linalg.norm(nn)
            N = nn / a
            u = q[1] - q[0]
            u -= N * (u @ N)
            u /= np.linalg.norm(u)
            self.normal[k], self.u[k], self.w[k], self.q0[k], self.area[k] = N, u, np.cross(N, u), c, a
        self.radiance = np.asarray(radiances, dtype=np.float64)
        self.group = np.asarray(groups, dtype=np.int64)
        self.ngroups = int(self.group.max()) + 1 if ns else 0


class PieceArrays:
    """Convex occluder pieces packed for the compiled kernel."""

    def __init__(self, pieces: list) -> None:  # list[ConvexPiece]
        self.voff = np.zeros(len(pieces) + 1, dtype=np.int64)
        self.eoff = np.zeros(len(pieces) + 1, dtype=np.int64)
        self.voff[1:] = np.cumsum([len(p.vertices) for p in pieces])
        self.eoff[1:] = np.cumsum([len(p.edges) for p in pieces])
        self.verts = np.ascontiguousarray(np.vstack([p.vertices for p in pieces]) if pieces else np.zeros((0, 3)))
        self.edges = np.ascontiguousarray(
            np.vstack([p.edges for p in pieces]) if pieces else np.zeros((0, 2), dtype=np.int64)
        ).astype(np.int64)
        self.center = np.zeros((len(pieces), 3))
        self.radius = np.zeros(len(pieces))
        for k, p in enumerate(pieces):
            c = 0.5 * (p.vertices.min(axis=0) + p.vertices.max(axis=0))
            self.center[k] = c
            self.radius[k] = float(np.max(np.linalg.norm(p.vertices - c, axis=1))) * (1 + 1e-12)
        self.maxpts = int(max([len(p.vertices) + 2 * len(p.edges) for p in pieces], default=0)) + 4


# ----------------------------------------------------------------------------- 2D helpers
# The per-point helpers are inlined into the kernel (inline="always"): a compiled call raises and
# lowers the reference count of every array it passes, and a receiver made some twenty such calls;
# inlined, the exact path takes half the time (about 4 s more to compile).


@numba.njit(cache=True, inline="always")
def _area2(P: np.ndarray, n: int) -> float:
    s = 0.0
    for k in range(n):
        k1 = k + 1 if k + 1 < n else 0
        s += P[k, 0] * P[k1, 1] - P[k1, 0] * P[k, 1]
    return 0.5 * s


@numba.njit(cache=True, inline="always")
def _clip_halfplane(P: np.ndarray, n: int, ax: float, ay: float, bx: float, by: float, out: np.ndarray) -> int:
    """Keep the part of polygon P (n vertices) left of the directed line a->b; returns the count (-1 on overflow)."""
    dx = bx - ax
    dy = by - ay
    m = 0
    if n == 0:
        return 0
    prev = n - 1
    sp = dx * (P[prev, 1] - ay) - dy * (P[prev, 0] - ax)
    for k in range(n):
        sk = dx * (P[k, 1] - ay) - dy * (P[k, 0] - ax)
        if sk >= 0.0:
            if sp < 0.0:
                t = sp / (sp - sk)
                if m >= out.shape[0]:
                    return -1
                out[m, 0] = P[prev, 0] + t * (P[k, 0] - P[prev, 0])
                out[m, 1] = P[prev, 1] + t * (P[k, 1] - P[prev, 1])
                m += 1
            if m >= out.shape[0]:
                return -1
            out[m, 0] = P[k, 0]
            out[m, 1] = P[k, 1]
            m += 1
        elif sp >= 0.0:
            t = sp / (sp - sk)
            if m >= out.shape[0]:
                return -1
            out[m, 0] = P[prev, 0] + t * (P[k, 0] - P[prev, 0])
            out[m, 1] = P[prev, 1] + t * (P[k, 1] - P[prev, 1])
            m += 1
        prev = k
        sp = sk
    return m


@numba.njit(cache=True, inline="always")
def _clip_convex(P: np.ndarray, n: int, Q: np.ndarray, nq: int, out: np.ndarray, tmp: np.ndarray) -> int:
    """P n Q for convex P and counter-clockwise convex Q; result in ``out`` (count, -1 on overflow)."""
    m = n
    for k in range(n):
        out[k, 0] = P[k, 0]
        out[k, 1] = P[k, 1]
    a = out  # the passes go back and forth between the two buffers
    b = tmp
    for e in range(nq):
        e1 = e + 1 if e + 1 < nq else 0
        m = _clip_halfplane(a, m, Q[e, 0], Q[e, 1], Q[e1, 0], Q[e1, 1], b)
        if m <= 0:
            return m
        a, b = b, a
    if nq % 2 == 1:
        for k in range(m):
            out[k, 0] = tmp[k, 0]
            out[k, 1] = tmp[k, 1]
    return m


@numba.njit(cache=True)
def _cross(o0: float, o1: float, a0: float, a1: float, b0: float, b1: float) -> float:
    return (a0 - o0) * (b1 - o1) - (a1 - o1) * (b0 - o0)


@numba.njit(cache=True, inline="always")
def _sort_xy(pts: np.ndarray, n: int, o: np.ndarray) -> np.ndarray:
    """Indices of pts[:n] by x, then y, then index (into ``o``, scratch of at least n entries): a stable
    insertion sort.

    The order of two stable argsorts (by y, then by x), written out: numba's
    generic argsort took 2 s of the kernel's compilation. Every stable sort gives
    this one order; insertion sort is the quickest for the few points (a few
    dozen at most) of a silhouette.
    """
    for k in range(n):
        x = pts[k, 0]
        y = pts[k, 1]
        j = k - 1
        # move left past the entries strictly after it: ties keep their order
        while j >= 0 and (x < pts[o[j], 0] or (x == pts[o[j], 0] and y < pts[o[j], 1])):
            o[j + 1] = o[j]
            j -= 1
        o[j + 1] = k
    return o


@numba.njit(cache=True)
def _order_xy(pts: np.ndarray, n: int) -> np.ndarray:
    """:func:`_sort_xy` into a new array."""
    return _sort_xy(pts, n, np.empty(n, dtype=np.int64))


@numba.njit(cache=True, inline="always")
def _hull(pts: np.ndarray, n: int, hull: np.ndarray, order: np.ndarray) -> int:
    """Counter-clockwise convex hull (Andrew's monotone chain) of pts[:n]; returns its size."""
    if n < 3:
        return 0
    o = _sort_xy(pts, n, order)
    k = 0
    for ii in range(n):
        i = o[ii]
        while k >= 2 and _cross(hull[k - 2, 0], hull[k - 2, 1], hull[k - 1, 0], hull[k - 1, 1],
                                pts[i, 0], pts[i, 1]) <= 0.0:
            k -= 1
        hull[k, 0] = pts[i, 0]
        hull[k, 1] = pts[i, 1]
        k += 1
    lower = k + 1
    for ii in range(n - 2, -1, -1):
        i = o[ii]
        while k >= lower and _cross(hull[k - 2, 0], hull[k - 2, 1], hull[k - 1, 0], hull[k - 1, 1],
                                    pts[i, 0], pts[i, 1]) <= 0.0:
            k -= 1
        hull[k, 0] = pts[i, 0]
        hull[k, 1] = pts[i, 1]
        k += 1
    return k - 1


@numba.njit(cache=True, inline="always")
def _lambert2(P: np.ndarray, n: int, p: np.ndarray, nr: np.ndarray, q0: np.ndarray, u: np.ndarray,
              w: np.ndarray) -> float:
    """Edge sum of a 2D polygon of the source frame (counter-clockwise seen from the lit side)."""
    s = 0.0
    if n == 0:
        return s
    # each vertex rebuilt once: an edge's end is the next edge's start
    ax = q0[0] + P[0, 0] * u[0] + P[0, 1] * w[0]
    ay = q0[1] + P[0, 0] * u[1] + P[0, 1] * w[1]
    az = q0[2] + P[0, 0] * u[2] + P[0, 1] * w[2]
    fx, fy, fz = ax, ay, az
    for k in range(n):
        if k + 1 < n:
            bx = q0[0] + P[k + 1, 0] * u[0] + P[k + 1, 1] * w[0]
            by = q0[1] + P[k + 1, 0] * u[1] + P[k + 1, 1] * w[1]
            bz = q0[2] + P[k + 1, 0] * u[2] + P[k + 1, 1] * w[2]
        else:
            bx, by, bz = fx, fy, fz
        s += edge_term_fast(p[0], p[1], p[2], nr[0], nr[1], nr[2], ax, ay, az, bx, by, bz)
        ax, ay, az = bx, by, bz
    return s


# ----------------------------------------------------------------------------- one point, one source


@numba.njit(cache=True, inline="always")
def _source_polygon(p, nr, s, s_verts, s_off, s_normal, s_u, s_w, s_q0, scale, P2):
    """S_p in 2D source coordinates (clipped by the receiving plane); returns (count, h, area)."""
    N = s_normal[s]
    q0 = s_q0[s]
    h = N[0] * (p[0] - q0[0]) + N[1] * (p[1] - q0[1]) + N[2] * (p[2] - q0[2])
    if h <= 1e-14 * scale:  # in (or behind) the source plane
        return 0, h, 0.0
    # 3D Sutherland-Hodgman against the receiving plane, written straight into 2D coordinates
    a0 = s_off[s]
    m = s_off[s + 1] - a0
    cnt = np.int64(0)  # not the literal 0: calls typed with it would compile a second, literal specialisation
    u = s_u[s]
    w = s_w[s]
    for k in range(m):
        qa = s_verts[a0 + k]
        qb = s_verts[a0 + (k + 1) % m]
        da = nr[0] * (qa[0] - p[0]) + nr[1] * (qa[1] - p[1]) + nr[2] * (qa[2] - p[2])
        db = nr[0] * (qb[0] - p[0]) + nr[1] * (qb[1] - p[1]) + nr[2] * (qb[2] - p[2])
        if da >= 0.0:
            P2[cnt, 0] = (qa[0] - q0[0]) * u[0] + (qa[1] - q0[1]) * u[1] + (qa[2] - q0[2]) * u[2]
            P2[cnt, 1] = (qa[0] - q0[0]) * w[0] + (qa[1] - q0[1]) * w[1] + (qa[2] - q0[2]) * w[2]
            cnt += 1
        if (da >= 0.0) != (db >= 0.0):
            t = da / (da - db)
            x0 = qa[0] + t * (qb[0] - qa[0]) - q0[0]
            x1 = qa[1] + t * (qb[1] - qa[1]) - q0[1]
            x2 = qa[2] + t * (qb[2] - qa[2]) - q0[2]
            P2[cnt, 0] = x0 * u[0] + x1 * u[1] + x2 * u[2]
            P2[cnt, 1] = x0 * w[0] + x1 * w[1] + x2 * w[2]
            cnt += 1
    if cnt < 3:
        return 0, h, 0.0
    return cnt, h, _area2(P2, cnt)


@numba.njit(cache=True)
def _in_wider_cone(cang: float, cosmin: float, sin2: float, sa: float) -> bool:
    """Whether the angle acos(cang) is surely below acos(cosmin) + asin(sa), by a margin far above rounding.

    cos(theta + alpha) = cos theta cos alpha - sin theta sin alpha, without the arc
    functions; only for cones narrower than a right angle whose sine is not tiny
    (there the rounding of the sines is well below the margin). False means "not proved".
    """
    if cosmin <= 0.0 or sin2 < 1e-6 or sa >= 1.0:
        return False
    c = cosmin * math.sqrt(1.0 - sa * sa) - math.sqrt(sin2) * sa
    return cang >= c + 1e-12


@numba.njit(cache=True)
def _piece_tables(s_normal, s_u, s_w, s_q0, v_verts, v_voff, v_edges, v_eoff):
    """What :func:`_blockers` needs of each piece that does not depend on the point, per source polygon.

    ``tv[s, k]``: vertex k's level N . (x - q0) over the source plane and its (u, w) coordinates;
    ``te[s, e]``: the (u, w) coordinates of edge e's crossing of the source plane (where it crosses).
    The same arithmetic as the projection at each point, done once.
    """
    ns = s_q0.shape[0]
    nv = v_verts.shape[0]
    tv = np.empty((ns, nv, 3))
    te = np.zeros((ns, v_edges.shape[0], 2))
    for s in range(ns):
        N = s_normal[s]
        q0 = s_q0[s]
        u = s_u[s]
        w = s_w[s]
        for k in range(nv):
            x = v_verts[k]
            tv[s, k, 0] = N[0] * (x[0] - q0[0]) + N[1] * (x[1] - q0[1]) + N[2] * (x[2] - q0[2])
            x0 = x[0] - q0[0]
            x1 = x[1] - q0[1]
            x2 = x[2] - q0[2]
            tv[s, k, 1] = x0 * u[0] + x1 * u[1] + x2 * u[2]
            tv[s, k, 2] = x0 * w[0] + x1 * w[1] + x2 * w[2]
        for j in range(v_voff.shape[0] - 1):
            vb = v_voff[j]
            for e in range(v_eoff[j], v_eoff[j + 1]):
                sa = tv[s, vb + v_edges[e, 0], 0]
                sb = tv[s, vb + v_edges[e, 1], 0]
                if (sa < 0.0 and sb > 0.0) or (sa > 0.0 and sb < 0.0):
                    xa = v_verts[vb + v_edges[e, 0]]
                    xb = v_verts[vb + v_edges[e, 1]]
                    t = (0.0 - sa) / (sb - sa)
                    x0 = xa[0] + t * (xb[0] - xa[0]) - q0[0]
                    x1 = xa[1] + t * (xb[1] - xa[1]) - q0[1]
                    x2 = xa[2] + t * (xb[2] - xa[2]) - q0[2]
                    te[s, e, 0] = x0 * u[0] + x1 * u[1] + x2 * u[2]
                    te[s, e, 1] = x0 * w[0] + x1 * w[1] + x2 * w[2]
    return tv, te


@numba.njit(cache=True, inline="always")
def _blockers(p, nr, s, h, P2, n2, A0, s_normal, s_u, s_w, s_q0,
              v_verts, v_voff, v_edges, v_eoff, v_center, v_radius, sel, tv, te, pts, hull, order, tmp, blk, blk_n):
    """Blocked convex pieces (of the pieces listed in ``sel``) C_V = S_p n B_V.

    ``tv`` and ``te``: :func:`_piece_tables` for source ``s``. Returns their count (-1 when more than MAXB).
    """
    N = s_normal[s]
    q0 = s_q0[s]
    u = s_u[s]
    w = s_w[s]
    # Cone of S_p seen from p: axis towards its vertex mean, half-angle to the farthest vertex.
    cx = 0.0
    cy = 0.0
    for k in range(n2):
        cx += P2[k, 0]
        cy += P2[k, 1]
    cx /= n2
    cy /= n2
    ax = q0[0] + cx * u[0] + cy * w[0] - p[0]
    ay = q0[1] + cx * u[1] + cy * w[1] - p[1]
    az = q0[2] + cx * u[2] + cy * w[2] - p[2]
    al = math.sqrt(ax * ax + ay * ay + az * az)
    ax /= al
    ay /= al
    az /= al
    cosmin = 1.0
    for k in range(n2):
        x0 = q0[0] + P2[k, 0] * u[0] + P2[k, 1] * w[0] - p[0]
        x1 = q0[1] + P2[k, 0] * u[1] + P2[k, 1] * w[1] - p[1]
        x2 = q0[2] + P2[k, 0] * u[2] + P2[k, 1] * w[2] - p[2]
        c = (x0 * ax + x1 * ay + x2 * az) / math.sqrt(x0 * x0 + x1 * x1 + x2 * x2)
        if c < cosmin:
            cosmin = c
    cosmin = min(1.0, max(-1.0, cosmin))
    theta_s = -1.0  # acos(cosmin), taken when a piece's centre lies outside the cone
    sin2 = 1.0 - cosmin * cosmin
    htop = h * SLAB_TOP
    # 2D coordinates of p's foot on the source plane
    px = (p[0] - q0[0]) * u[0] + (p[1] - q0[1]) * u[1] + (p[2] - q0[2]) * u[2]
    py = (p[0] - q0[0]) * w[0] + (p[1] - q0[1]) * w[1] + (p[2] - q0[2]) * w[2]
    nb = 0
    for jj in range(sel.shape[0]):
        j = sel[jj]
        c = v_center[j]
        r = v_radius[j]
        sc = N[0] * (c[0] - q0[0]) + N[1] * (c[1] - q0[1]) + N[2] * (c[2] - q0[2])
        if sc < -r or sc > h + r:
            continue
        dx = c[0] - p[0]
        dy = c[1] - p[1]
        dz = c[2] - p[2]
        dist = math.sqrt(dx * dx + dy * dy + dz * dz)
        if dist > r:
            cang = min(1.0, max(-1.0, (dx * ax + dy * ay + dz * az) / dist))
            # a centre inside the cone (cang >= cosmin: its angle is at most theta_s) is never skipped
            if cang < cosmin and not _in_wider_cone(cang, cosmin, sin2, r / dist):
                if theta_s < 0.0:
                    theta_s = math.acos(cosmin)
                if math.acos(cang) - math.asin(r / dist) > theta_s + 1e-9:
                    continue
        # project the vertices of V n slab
        npt = np.int64(0)  # (as cnt in _source_polygon)
        vb = v_voff[j]
        ve = v_voff[j + 1]
        for k in range(vb, ve):
            sk = tv[k, 0]
            if sk >= 0.0 and sk <= htop:
                f = h / (h - sk)
                pts[npt, 0] = px + (tv[k, 1] - px) * f
                pts[npt, 1] = py + (tv[k, 2] - py) * f
                npt += 1
        for e in range(v_eoff[j], v_eoff[j + 1]):
            sa = tv[vb + v_edges[e, 0], 0]
            sb = tv[vb + v_edges[e, 1], 0]
            for side in range(2):  # the two slab planes
                lev = 0.0 if side == 0 else htop
                if (sa < lev and sb > lev) or (sa > lev and sb < lev):
                    f = h / (h - lev)
                    if side == 0:  # the crossing of the source plane does not depend on p
                        pts[npt, 0] = px + (te[e, 0] - px) * f
                        pts[npt, 1] = py + (te[e, 1] - py) * f
                        npt += 1
                        continue
                    xa = v_verts[vb + v_edges[e, 0]]
                    xb = v_verts[vb + v_edges[e, 1]]
                    t = (lev - sa) / (sb - sa)
                    x0 = xa[0] + t * (xb[0] - xa[0]) - q0[0]
                    x1 = xa[1] + t * (xb[1] - xa[1]) - q0[1]
                    x2 = xa[2] + t * (xb[2] - xa[2]) - q0[2]
                    xu = x0 * u[0] + x1 * u[1] + x2 * u[2]
                    xw = x0 * w[0] + x1 * w[1] + x2 * w[2]
                    pts[npt, 0] = px + (xu - px) * f
                    pts[npt, 1] = py + (xw - py) * f
                    npt += 1
        nh = _hull(pts, npt, hull, order)
        if nh < 3:
            continue
        if nb >= blk.shape[0]:
            return -1
        m = _clip_convex(P2, n2, hull, nh, blk[nb], tmp)
        if m < 0:
            return -1
        if m >= 3 and _area2(blk[nb], m) > SLIVER_TOL * A0:
            blk_n[nb] = m
            nb += 1
    return nb


@numba.njit(cache=True, inline="always")
def _evaluate(p, nr, s, s_verts, s_off, s_normal, s_u, s_w, s_q0, scale,
              v_verts, v_voff, v_edges, v_eoff, v_center, v_radius, sel, tv, te,
              P2, pts, hull, order, tmp, blk, blk_n, stk, stk_n, stk_next):
    """(edge sum of the visible part, status) for one point and one source polygon."""
    n2, h, A0 = _source_polygon(p, nr, s, s_verts, s_off, s_normal, s_u, s_w, s_q0, scale, P2)
    if n2 == 0 or A0 <= 0.0:
        return 0.0, ST_NA
    q0 = s_q0[s]
    u = s_u[s]
    w = s_w[s]
    efull = _lambert2(P2, n2, p, nr, q0, u, w)
    nb = _blockers(p, nr, s, h, P2, n2, A0, s_normal, s_u, s_w, s_q0,
                   v_verts, v_voff, v_edges, v_eoff, v_center, v_radius, sel, tv[s], te[s], pts, hull, order, tmp, blk,
                   blk_n)
    if nb < 0:
        return 0.0, ST_OVERFLOW
    if nb == 0:
        return efull, ST_LIT
    # Inclusion-exclusion over the convex blocked pieces (depth-first over index-increasing subsets).
    eu = 0.0
    au = 0.0
    terms = 0
    for j0 in range(nb):
        m = blk_n[j0]
        for k in range(m):
            stk[0, k, 0] = blk[j0, k, 0]
            stk[0, k, 1] = blk[j0, k, 1]
        stk_n[0] = m
        stk_next[0] = j0 + 1
        eu += _lambert2(stk[0], m, p, nr, q0, u, w)
        au += _area2(stk[0], m)
        d = 0
        while d >= 0:
            if stk_next[d] >= nb:
                d -= 1
                continue
            j = stk_next[d]
            stk_next[d] += 1
            m = _clip_convex(stk[d], stk_n[d], blk[j], blk_n[j], stk[d + 1], tmp)
            if m < 0:
                return 0.0, ST_OVERFLOW
            if m >= 3:
                a = _area2(stk[d + 1], m)
                if a > SLIVER_TOL * A0:
                    d += 1
                    stk_n[d] = m
                    stk_next[d] = j + 1
                    sign = -1.0 if d % 2 == 1 else 1.0
                    eu += sign * _lambert2(stk[d], m, p, nr, q0, u, w)
                    au += sign * a
                    terms += 1
                    if terms > MAXTERMS:
                        return 0.0, ST_OVERFLOW
    if A0 - au <= UMBRA_TOL * A0:
        return 0.0, ST_UMB
    return max(efull - eu, 0.0), ST_PEN


@numba.njit(cache=True, nogil=True)
def _kernel(P, NR, s_verts, s_off, s_normal, s_u, s_w, s_q0, s_L, s_group, ngroups, scale,
            v_verts, v_voff, v_edges, v_eoff, v_center, v_radius, group, g_off, g_idx,
            maxpts, vmax, nchunk, c0, c1, E, state, overflow):
    """Points ``i`` with ``i % nchunk`` in ``[c0, c1)``: strided, so each share holds near and far pixels alike."""
    n = P.shape[0]
    ns = s_L.shape[0]
    P2 = np.empty((vmax, 2))
    pts = np.empty((maxpts, 2))
    hull = np.empty((maxpts + 1, 2))
    order = np.empty(maxpts, dtype=np.int64)
    tmp = np.empty((vmax, 2))
    blk = np.empty((MAXB, vmax, 2))
    blk_n = np.empty(MAXB, dtype=np.int64)
    stk = np.empty((MAXB + 1, vmax, 2))
    stk_n = np.empty(MAXB + 1, dtype=np.int64)
    stk_next = np.empty(MAXB + 1, dtype=np.int64)
    gstat = np.empty(ngroups, dtype=np.int64)
    tv, te = _piece_tables(s_normal, s_u, s_w, s_q0, v_verts, v_voff, v_edges, v_eoff)
    for c in range(c0, c1):
        for i in range(c, n, nchunk):
            p = P[i]
            nr = NR[i]
            sel = g_idx[g_off[group[i]]:g_off[group[i] + 1]]
            for g in range(ngroups):
                gstat[g] = -1  # -1 nothing applicable; bit 1: some lit part, bit 2: some blocked part
            e = 0.0
            for s in range(ns):
                val, st = _evaluate(p, nr, s, s_verts, s_off, s_normal, s_u, s_w, s_q0, scale,
                                    v_verts, v_voff, v_edges, v_eoff, v_center, v_radius, sel, tv, te,
                                    P2, pts, hull, order, tmp, blk, blk_n, stk, stk_n, stk_next)
                if st == ST_OVERFLOW:
                    overflow[i] = True
                    continue
                if st == ST_NA:
                    continue
                e += 0.5 * s_L[s] * val
                g = s_group[s]
                if gstat[g] < 0:
                    gstat[g] = 0
                if st == ST_LIT:
                    gstat[g] |= 1
                elif st == ST_UMB:
                    gstat[g] |= 2
                else:
                    gstat[g] |= 3
            E[i] = e
            worst = 0
            for g in range(ngroups):
                if gstat[g] == 2 or gstat[g] < 0:  # none of the source reaches p (or none is in front of it)
                    worst = max(worst, 2)
                elif gstat[g] == 3:
                    worst = max(worst, 1)
            state[i] = worst


def _vmax(sources: SourceArrays, pieces: PieceArrays) -> int:
    """Vertex capacity of the polygon buffers: the source (plus its receiving-plane cut) and a silhouette."""
    msrc = int(np.max(np.diff(sources.off))) if len(sources.off) > 1 else 0
    return max(MAXV, msrc + 2 + min(pieces.maxpts, 4 * MAXV))


def visible_illuminance(
    points: NDArray[np.float64],
    normals: NDArray[np.float64],
    sources: SourceArrays,
    pieces: PieceArrays,
    scale: float,
    groups: tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.int64]] | None = None,
) -> tuple[NDArray[np.float64], NDArray[np.int8], NDArray[np.bool_]]:
    """Compiled evaluation for many points: (E, state, overflow mask); see the module docstring.

    ``groups`` (optional) restricts each point to some pieces: ``(group, off,
    idx)``, point ``i`` sees the pieces ``idx[off[group[i]]:off[group[i] + 1]]``;
    by default every point sees every piece.

    Points flagged in ``overflow`` still hold partial sums and must be
    recomputed by the 2D Boolean path.
    """
    n = len(points)
    E = np.zeros(n)
    state = np.zeros(n, dtype=np.int8)
    overflow = np.zeros(n, dtype=np.bool_)
    if n == 0 or len(sources.radiance) == 0:
        return E, state, overflow
    if groups is None:
        groups = _all_pieces(n, pieces)
    group, g_off, g_idx = (np.ascontiguousarray(a, dtype=np.int64) for a in groups)
    args = (
        np.ascontiguousarray(points), np.ascontiguousarray(normals),
        sources.verts, sources.off, sources.normal, sources.u, sources.w, sources.q0, sources.radiance,
        sources.group, sources.ngroups, float(scale),
        pieces.verts, pieces.voff, pieces.edges, pieces.eoff, pieces.center, pieces.radius, group, g_off, g_idx,
        pieces.maxpts, _vmax(sources, pieces),
    )
    _run_chunks(args, n, E, state, overflow)
    return E, state, overflow


# The kernel is serial and releases the GIL: threads run its chunks side by side. A
# parallel (prange) kernel did the same but took 2 s more CPU time to compile, and
# numba's "workqueue" threading layer aborts the process when two threads launch
# parallel kernels at once; plain threads are safe under every layer, so callers in
# thread pools and Dask workers need no lock.
CHUNKS_PER_THREAD = 4  # strided chunks per thread: a thread that falls behind (a busy core) takes fewer
MIN_CHUNK = 32  # points per chunk at least (each call allocates its scratch buffers afresh)
_POOL: ThreadPoolExecutor | None = None
_POOL_LOCK = threading.Lock()


def _threads() -> int:
    """Threads that evaluate points: numba's ``NUMBA_NUM_THREADS`` (default: the cores)."""
    # numba.config's settings are set from the environment at import: not in its type stubs.
    return max(1, int(numba.config.NUMBA_NUM_THREADS))  # type: ignore[attr-defined]


def _pool(workers: int) -> ThreadPoolExecutor:
    global _POOL
    with _POOL_LOCK:
        if _POOL is None:
            _POOL = ThreadPoolExecutor(max_workers=workers, thread_name_prefix="isocsg-visibility")
        return _POOL


def _forget_pool() -> None:
    # A forked child has the pool object but not its threads.
    global _POOL, _POOL_LOCK
    _POOL, _POOL_LOCK = None, threading.Lock()


if hasattr(os, "register_at_fork"):
    os.register_at_fork(after_in_child=_forget_pool)


def run_chunks(nchunk: int, run: Callable[[int], object]) -> None:
    """``run(c)`` for chunks ``c = 0 .. nchunk - 1``, taken in turn by this thread and the pool's
    helpers (``run`` calls a kernel that releases the GIL)."""
    threads = _threads()
    if threads == 1 or nchunk <= 1:
        for c in range(nchunk):
            run(c)
        return
    counter = itertools.count()  # next() on a shared count is atomic under the GIL: each chunk once
    stop = [False]  # set when this thread leaves (an exception here): helpers take no more chunks

    def work() -> None:
        for c in counter:
            if c >= nchunk or stop[0]:
                return
            run(c)

    pool = _pool(threads - 1)
    helpers = [pool.submit(work) for _ in range(min(threads, nchunk) - 1)]
    try:
        work()
    finally:
        stop[0] = True
        for h in helpers:  # helpers still queued (the pool busy with other callers' chunks) are not waited for
            if not h.cancel():
                h.result()


def _run_chunks(args: tuple, n: int, E: np.ndarray, state: np.ndarray, overflow: np.ndarray) -> None:
    """Evaluate all points: ``nchunk`` strided chunks taken in turn by this thread and the pool's helpers."""
    nchunk = max(1, min(CHUNKS_PER_THREAD * _threads(), n // MIN_CHUNK))
    # args: the kernel's leading arguments, a tuple whose length mypy cannot count.
    run_chunks(nchunk, lambda c: _kernel(*args, nchunk, c, c + 1, E, state, overflow))  # type: ignore[call-arg]


def _all_pieces(n: int, pieces: PieceArrays) -> tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.int64]]:
    k = len(pieces.radius)
    return np.zeros(n, dtype=np.int64), np.array([0, k], dtype=np.int64), np.arange(k, dtype=np.int64)


@numba.njit(cache=True)
def _single(p, nr, s, s_verts, s_off, s_normal, s_u, s_w, s_q0, scale,
            v_verts, v_voff, v_edges, v_eoff, v_center, v_radius, sel, maxpts, maxb, vmax):
    P2 = np.empty((vmax, 2))
    pts = np.empty((maxpts, 2))
    hull = np.empty((maxpts + 1, 2))
    order = np.empty(maxpts, dtype=np.int64)
    tmp = np.empty((vmax, 2))
    blk = np.empty((maxb, vmax, 2))
    blk_n = np.zeros(maxb, dtype=np.int64)
    n2, h, A0 = _source_polygon(p, nr, s, s_verts, s_off, s_normal, s_u, s_w, s_q0, scale, P2)
    if n2 == 0 or A0 <= 0.0:
        return P2[:0].copy(), blk[:0].copy(), blk_n[:0].copy()
    tv, te = _piece_tables(s_normal, s_u, s_w, s_q0, v_verts, v_voff, v_edges, v_eoff)
    nb = _blockers(p, nr, s, h, P2, n2, A0, s_normal, s_u, s_w, s_q0,
                   v_verts, v_voff, v_edges, v_eoff, v_center, v_radius, sel, tv[s], te[s], pts, hull, order, tmp, blk,
                   blk_n)
    return P2[:n2].copy(), blk[:max(nb, 0)].copy(), blk_n[:max(nb, 0)].copy()


def blockers_single(
    point: NDArray[np.float64], normal: NDArray[np.float64], s: int, sources: SourceArrays, pieces: PieceArrays,
    scale: float, sel: NDArray[np.int64] | None = None,
) -> tuple[NDArray[np.float64], list[NDArray[np.float64]]]:
    """S_p (2D, counter-clockwise) and the blocked convex polygons C_V for one point and source polygon.

    ``sel``: the indices of the pieces to consider (default all).
    """
    npieces = len(pieces.radius)
    sel = np.arange(npieces, dtype=np.int64) if sel is None else np.ascontiguousarray(sel, dtype=np.int64)
    P2, blk, blk_n = _single(
        np.ascontiguousarray(point, dtype=np.float64), np.ascontiguousarray(normal, dtype=np.float64), s,
        sources.verts, sources.off, sources.normal, sources.u, sources.w, sources.q0, float(scale),
        pieces.verts, pieces.voff, pieces.edges, pieces.eoff, pieces.center, pieces.radius, sel, pieces.maxpts,
        max(len(sel), 1), 4 * _vmax(sources, pieces),
    )
    return P2, [blk[k, : blk_n[k]] for k in range(len(blk_n))]
