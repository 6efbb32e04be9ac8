"""The exact boundary of a 2D tree of polygons and circles: line segments and circular arcs.

The boundary of a Boolean combination lies on its leaves' boundaries. Every
leaf edge and circle is split at its crossings with all the others (found
through an STR tree of their boxes); each piece lies either on the boundary
of the result or not, and which is decided at its midpoint by the membership,
in the tree, of two probe points a hair to either side (``PROBE_RTOL`` of the
shape's size). Kept pieces are oriented with the region on their left;
coincident pieces (edges that pieces share, identical circles) are kept once.

The area is then Green's integral over the pieces, in closed form for
segments and arcs: exact to rounding, whatever the Booleans, except that a
feature thinner than the probe distance (a sliver between nearly coincident
edges) may be taken as absent or whole. A piece misjudged that way breaks
the chain of pieces, which :func:`boundary_area` checks (every piece's end is
another's start): it then returns ``None`` and :func:`~isocsg.shapes2d.area`
measures otherwise. Curves that come within ``TANGENT_RTOL`` of the probe
distance of touching are taken as tangent (not split).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .leaves import Circle, ConvexPolygon, Ellipse
from .shape import Shape2D, iter_leaves

__all__ = ["Piece", "boundary_pieces", "boundary_area", "closed", "contains_points", "PROBE_RTOL"]

#: Distance of the probe points from a piece's midpoint, relative to the shape's size.
PROBE_RTOL = 1e-11
#: Curves closer than this fraction of the probe distance to touching are taken as tangent.
TANGENT_RTOL = 1e-3
TWO_PI = 2.0 * math.pi


@dataclass(frozen=True, slots=True)
class Piece:
    """A boundary piece: a segment ``a -> b`` (``radius`` 0) or a counter-clockwise arc of a circle
    from angle ``t0`` to ``t1`` (``t1 > t0``); ``sign`` +1 when the region is on its left, -1 on its right."""

    a: tuple[float, float]
    b: tuple[float, float]
    center: tuple[float, float] = (0.0, 0.0)
    radius: float = 0.0
    t0: float = 0.0
    t1: float = 0.0
    sign: int = 1

    def area_term(self, ox: float = 0.0, oy: float = 0.0) -> float:
        """Green's integral ``1/2 (x dy - y dx)`` along the piece about the origin ``(ox, oy)``, times ``sign``."""
        if self.radius == 0.0:
            (ax, ay), (bx, by) = (self.a[0] - ox, self.a[1] - oy), (self.b[0] - ox, self.b[1] - oy)
            return self.sign * 0.5 * (ax * by - ay * bx)
        (cx, cy), r = (self.center[0] - ox, self.center[1] - oy), self.radius
        s = r * r * (self.t1 - self.t0) + r * (
            cx * (math.sin(self.t1) - math.sin(self.t0)) - cy * (math.cos(self.t1) - math.cos(self.t0))
        )
        return self.sign * 0.5 * s


class _Curves:
    """The leaves' boundary curves and their split points."""

    def __init__(self, shape: Shape2D) -> None:
        segs: list[tuple[NDArray[np.float64], NDArray[np.float64]]] = []
        circles: dict[tuple[float, float, float], None] = {}
        for leaf in iter_leaves(shape):
            if isinstance(leaf, ConvexPolygon):
                p = leaf.array
                segs.extend((p[i], p[(i + 1) % len(p)]) for i in range(len(p)))
            elif isinstance(leaf, Circle):
                circles[(leaf.center[0], leaf.center[1], leaf.radius)] = None
            else:
                raise TypeError(type(leaf).__name__)
        self.segs = [s for s in segs if np.any(s[0] != s[1])]
        self.circles = [(np.array(k[:2]), k[2]) for k in circles]
        self.seg_splits: list[list[tuple[float, NDArray[np.float64]]]] = [[] for _ in self.segs]
        self.circle_splits: list[list[float]] = [[] for _ in self.circles]

    def boxes(self) -> NDArray[np.float64]:
        out = [np.r_[np.minimum(a, b), np.maximum(a, b)] for a, b in self.segs]
        out += [np.r_[c - r, c + r] for c, r in self.circles]
        return np.array(out, dtype=np.float64).reshape(-1, 4)


def _seg_seg(cv: _Curves, i: int, j: int, eps: float) -> None:
    a, b = cv.segs[i]
    c, d = cv.segs[j]
    r, s = b - a, d - c
    den = r[0] * s[1] - r[1] * s[0]
    qa = c - a
    scale = float(np.hypot(*r) * np.hypot(*s))
    if abs(den) <= 1e-14 * scale:  # parallel: split each at the other's endpoints when collinear
        if abs(qa[0] * r[1] - qa[1] * r[0]) > eps * float(np.hypot(*r)):
            return
        for (k, (p, q)), others in (((i, (a, b)), (c, d)), ((j, (c, d)), (a, b))):
            e = q - p
            for o in others:
                t = float((o - p) @ e / (e @ e))
                if 0.0 < t < 1.0:
                    cv.seg_splits[k].append((t, o.copy()))
        return
    t = (qa[0] * s[1] - qa[1] * s[0]) / den
    u = (qa[0] * r[1] - qa[1] * r[0]) / den
    if -1e-12 <= t <= 1 + 1e-12 and -1e-12 <= u <= 1 + 1e-12:
        x = a + t * r
        if 0.0 < t < 1.0:
            cv.seg_splits[i].append((t, x))
        if 0.0 < u < 1.0:
            cv.seg_splits[j].append((u, x))


def _seg_circle(cv: _Curves, i: int, k: int, tangent: float) -> None:
    a, b = cv.segs[i]
    c, R = cv.circles[k]
    d = b - a
    A = float(d @ d)
    B = float((a - c) @ d)
    C = float((a - c) @ (a - c)) - R * R
    disc = B * B - A * C
    # A line within ``tangent`` of touching the circle is taken as tangent: not split (the sliver
    # left out is at most ``tangent`` thick), so rounding never makes hair-thin pieces there.
    gap = R - abs(float(d[0] * (c - a)[1] - d[1] * (c - a)[0])) / math.sqrt(A)
    if disc <= 0.0 or gap <= tangent:
        return
    root = math.sqrt(disc)
    for t in ((-B - root) / A, (-B + root) / A):
        if -1e-12 <= t <= 1 + 1e-12:
            t = min(max(t, 0.0), 1.0)
            x = a + t * d
            if 0.0 < t < 1.0:
                cv.seg_splits[i].append((t, x))
            cv.circle_splits[k].append(math.atan2(x[1] - c[1], x[0] - c[0]) % TWO_PI)


def _circle_circle(cv: _Curves, k: int, m: int, tangent: float) -> None:
    (c1, r1), (c2, r2) = cv.circles[k], cv.circles[m]
    dv = c2 - c1
    dist = float(np.hypot(*dv))
    if dist == 0.0 or dist >= r1 + r2 - tangent or dist <= abs(r1 - r2) + tangent:
        return
    along = (dist * dist + r1 * r1 - r2 * r2) / (2 * dist)
    h = math.sqrt(max(r1 * r1 - along * along, 0.0))
    base = c1 + along * dv / dist
    perp = np.array([-dv[1], dv[0]]) / dist
    for x in (base + h * perp, base - h * perp):
        cv.circle_splits[k].append(math.atan2(x[1] - c1[1], x[0] - c1[0]) % TWO_PI)
        cv.circle_splits[m].append(math.atan2(x[1] - c2[1], x[0] - c2[0]) % TWO_PI)


def _candidates(shape: Shape2D, eps: float) -> list[Piece]:
    import shapely

    cv = _Curves(shape)
    boxes = cv.boxes()
    ns = len(cv.segs)
    if len(boxes):
        geoms = shapely.box(boxes[:, 0] - eps, boxes[:, 1] - eps, boxes[:, 2] + eps, boxes[:, 3] + eps)
        left, right = shapely.STRtree(geoms).query(geoms, predicate="intersects")
        for i, j in zip(left.tolist(), right.tolist()):
            if i >= j:
                continue
            if j < ns:
                _seg_seg(cv, i, j, eps)
            elif i < ns:
                _seg_circle(cv, i, j - ns, eps * TANGENT_RTOL)
            else:
                _circle_circle(cv, i - ns, j - ns, eps * TANGENT_RTOL)
    pieces: list[Piece] = []
    for (a, b), splits in zip(cv.segs, cv.seg_splits):
        pts = [a] + [p for _, p in sorted(splits, key=lambda s: s[0])] + [b]
        for p, q in zip(pts, pts[1:]):
            if float(np.hypot(*(q - p))) > eps * 1e-3:
                pieces.append(Piece((float(p[0]), float(p[1])), (float(q[0]), float(q[1]))))
    for (c, r), angles in zip(cv.circles, cv.circle_splits):
        cut = sorted(set(angles))
        if not cut:
            cut = [0.0]
        cut = cut + [cut[0] + TWO_PI]
        for t0, t1 in zip(cut, cut[1:]):
            if t1 - t0 > 1e-15:
                start = (float(c[0] + r * math.cos(t0)), float(c[1] + r * math.sin(t0)))
                end = (float(c[0] + r * math.cos(t1)), float(c[1] + r * math.sin(t1)))
                pieces.append(Piece(start, end, (float(c[0]), float(c[1])), r, t0, t1))
    return pieces


def contains_points(shape: Shape2D, points: NDArray[np.float64]) -> NDArray[np.bool_]:
    """Whether each point is inside the tree (leaves' interiors; points on a leaf's boundary: either way)."""
    memo: dict[int, NDArray[np.bool_]] = {}
    stack: list[tuple[Shape2D, bool]] = [(shape, False)]
    x, y = points[:, 0], points[:, 1]
    while stack:
        s, expanded = stack.pop()
        if id(s) in memo:
            continue
        if isinstance(s, ConvexPolygon):
            p = s.array
            inside = np.ones(len(points), dtype=bool)
            for i in range(len(p)):
                (ax, ay), (bx, by) = p[i], p[(i + 1) % len(p)]
                inside &= (bx - ax) * (y - ay) - (by - ay) * (x - ax) > 0
            memo[id(s)] = inside
        elif isinstance(s, Circle):
            memo[id(s)] = (x - s.center[0]) ** 2 + (y - s.center[1]) ** 2 < s.radius**2
        elif isinstance(s, Ellipse):
            u = np.linalg.solve(np.array(s.matrix), (points - np.array(s.center)).T)
            memo[id(s)] = np.sum(u * u, axis=0) < 1.0
        elif not expanded:
            stack.append((s, True))
            stack.extend((c, False) for c in s.children if id(c) not in memo)  # type: ignore[attr-defined]
        else:
            kids = [memo[id(c)] for c in s.children]  # type: ignore[attr-defined]
            if s.op == "union":  # type: ignore[attr-defined]
                memo[id(s)] = np.logical_or.reduce(kids) if kids else np.zeros(len(points), dtype=bool)
            elif s.op == "intersection":  # type: ignore[attr-defined]
                memo[id(s)] = np.logical_and.reduce(kids)
            else:
                rest = np.logical_or.reduce(kids[1:]) if len(kids) > 1 else np.zeros(len(points), dtype=bool)
                memo[id(s)] = kids[0] & ~rest
    return memo[id(shape)]


def boundary_pieces(shape: Shape2D, box: tuple[float, float, float, float]) -> list[Piece]:
    """The pieces of the leaves' boundaries that bound the region, each once, with the region's side as ``sign``."""
    size = max(box[2] - box[0], box[3] - box[1])
    eps = PROBE_RTOL * size
    cands = _candidates(shape, eps)
    if not cands:
        return []
    mids: list[NDArray[np.float64]] = []
    normals: list[tuple[float, float]] = []
    for p in cands:
        if p.radius == 0.0:
            a, b = np.array(p.a), np.array(p.b)
            d = (b - a) / float(np.hypot(*(b - a)))
            mids.append(0.5 * (a + b))
            normals.append((float(-d[1]), float(d[0])))
        else:
            t = 0.5 * (p.t0 + p.t1)
            u = np.array([math.cos(t), math.sin(t)])
            mids.append(np.array(p.center) + p.radius * u)
            normals.append((float(-u[0]), float(-u[1])))
    m, n = np.array(mids), np.array(normals)
    inside = contains_points(shape, np.vstack([m + eps * n, m - eps * n]))
    left, right = inside[: len(m)], inside[len(m) :]
    seen: set[tuple[Any, ...]] = set()
    out = []
    q = eps * 10.0
    for p, lft, rgt in zip(cands, left.tolist(), right.tolist()):
        if lft == rgt:
            continue
        if p.radius == 0.0:
            ends = sorted([(round(p.a[0] / q), round(p.a[1] / q)), (round(p.b[0] / q), round(p.b[1] / q))])
            key: tuple[Any, ...] = ("s", *ends)
        else:
            cx, cy, r = round(p.center[0] / q), round(p.center[1] / q), round(p.radius / q)
            key = ("a", cx, cy, r, round(p.t0, 9), round(p.t1, 9))
        if key in seen:
            continue
        seen.add(key)
        out.append(Piece(p.a, p.b, p.center, p.radius, p.t0, p.t1, 1 if lft else -1))
    return out


def closed(pieces: list[Piece], tol: float) -> bool:
    """Whether the oriented pieces chain into closed loops: every end meets a start within ``tol`` and back."""
    from scipy.spatial import cKDTree

    if not pieces:
        return True
    starts = np.array([p.a if p.sign > 0 else p.b for p in pieces])
    ends = np.array([p.b if p.sign > 0 else p.a for p in pieces])
    d1, _ = cKDTree(starts).query(ends)
    d2, _ = cKDTree(ends).query(starts)
    return bool(np.all(d1 <= tol) and np.all(d2 <= tol))


def boundary_area(shape: Shape2D, box: tuple[float, float, float, float]) -> float | None:
    """The area of a tree of polygons and circles from its exact boundary (Green's theorem).

    ``None`` when the kept pieces do not chain into closed loops (a piece misjudged
    next to a nearly coincident curve): the caller then measures otherwise.
    """
    ox, oy = 0.5 * (box[0] + box[2]), 0.5 * (box[1] + box[3])
    pieces = boundary_pieces(shape, box)
    if not closed(pieces, 1e-9 * max(box[2] - box[0], box[3] - box[1])):
        return None
    return math.fsum(p.area_term(ox, oy) for p in pieces)
