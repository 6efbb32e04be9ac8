"""Analytic per-pixel ray caster: the exact image of the conventions.

Written independently of the library: it reads the parameters of primitives
(``Sphere.center/.radius``, ``Truncus.center/.axis/.r1/.r2``,
``Box.center/.size``, ``ConvexPolyhedron.vertices``), the ``children`` of CSG
nodes, lights, materials and camera fields, and computes everything else
itself:

- camera rays from the pinhole formula of the conventions,
- ray-primitive intervals in closed form (sphere quadratic; truncus lateral
  quadric on one nappe intersected with the slab between its end planes;
  box and convex polyhedron as intersections of half-spaces, the polyhedron's
  planes from its own ``scipy.spatial.ConvexHull``),
- CSG by interval arithmetic: the boundary events of all leaves are sorted
  along each ray and the tree is evaluated on every segment between them; the
  visible point is the start of the first non-empty segment inside the result,
- several objects by the nearest visible point,
- shading ``ambient + sum_lights intensity (kd cos_i + ks max(0, rf.v)^s)``
  with the exact outward normal where the ray enters a leaf and the reversed
  normal where it leaves one (the inside of a cut).

Besides the image it returns which object, leaf, side (entry/exit) and part
of the leaf (face, cap or lateral surface) each pixel sees, so that
comparisons can leave out the pixels next to a discontinuity of the exact
image.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray
from scipy.spatial import ConvexHull

from isocsg import (
    Box,
    Camera,
    ConvexPolyhedron,
    Difference,
    DirectionalLight,
    Intersection,
    Material,
    PointLight,
    Scene,
    Sphere,
    Truncus,
    Union,
)

__all__ = [
    "Intervals",
    "FirstHit",
    "ReferenceImage",
    "camera_rays",
    "primitive_intervals",
    "first_hit",
    "shade_points",
    "raycast",
    "raycast_scene",
    "SIDE_ENTRY",
    "SIDE_EXIT",
    "PART_LATERAL",
    "PART_CAP1",
    "PART_CAP2",
]

F64 = NDArray[np.float64]
I64 = NDArray[np.int64]

#: The ray enters the leaf (outward normal) or leaves it (reversed normal).
SIDE_ENTRY, SIDE_EXIT = 0, 1
#: Parts of a truncus: lateral surface, end E1 (``center + axis/2``), end E2.
PART_LATERAL, PART_CAP1, PART_CAP2 = 0, 1, 2

_MAX_LEAVES = 64
_MAX_PARTS = 1024


# ----------------------------------------------------------------------------- rays


def camera_rays(camera: Camera) -> tuple[F64, F64]:
    """Ray origins and unit directions of every pixel, each of shape (H, W, 3).

    f = normalize(T - E), r = normalize(f x U), u = r x f; pixel (i, j) has
    x = (2 (j + 0.5) / W - 1) tan(fov/2) W/H, y = (1 - 2 (i + 0.5) / H) tan(fov/2)
    and direction normalize(f + x r + y u); row 0 is the top row. An orthographic
    camera has parallel rays along f from E + x r + y u, with tan(fov/2)
    replaced by height_m / 2.
    """
    eye = np.asarray(camera.eye, dtype=np.float64)
    f = np.asarray(camera.target, dtype=np.float64) - eye
    f /= np.linalg.norm(f)
    r = np.cross(f, np.asarray(camera.up, dtype=np.float64))
    r /= np.linalg.norm(r)
    u = np.cross(r, f)
    w, h = int(camera.width), int(camera.height)
    t = camera.height_m / 2 if camera.orthographic else np.tan(np.radians(camera.fov) / 2)
    x = (2 * (np.arange(w) + 0.5) / w - 1) * t * (w / h)
    y = (1 - 2 * (np.arange(h) + 0.5) / h) * t
    if camera.orthographic:
        o = eye + x[None, :, None] * r + y[:, None, None] * u
        return o, np.broadcast_to(f, o.shape).copy()
    d = f + x[None, :, None] * r + y[:, None, None] * u
    d /= np.linalg.norm(d, axis=-1, keepdims=True)
    return np.broadcast_to(eye, d.shape).copy(), d


# ----------------------------------------------------------------------------- primitives


@dataclass(frozen=True)
class Intervals:
    """The parameter interval in which rays are inside one convex primitive.

    ``t_in = +inf`` and ``t_out = -inf`` where a ray misses. ``n_in``/``n_out``
    are the outward unit normals at entry and exit, ``part_in``/``part_out``
    which part of the surface the ray crosses there (a face index, or
    ``PART_LATERAL``/``PART_CAP1``/``PART_CAP2`` for a truncus).
    """

    t_in: F64
    t_out: F64
    n_in: F64
    n_out: F64
    part_in: I64
    part_out: I64

    @property
    def hit(self) -> NDArray[np.bool_]:
        """Rays whose line meets the primitive."""
        return self.t_in <= self.t_out


def _dot(a: F64, b: F64) -> F64:
    return np.einsum("ij,ij->i", a, b)


def _normalize(v: F64) -> F64:
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return np.divide(v, n, out=np.zeros_like(v), where=n > 0)


def _finish(t_in: F64, t_out: F64, n_in: F64, n_out: F64, p_in: I64, p_out: I64) -> Intervals:
    miss = ~(t_in <= t_out)
    return Intervals(
        np.where(miss, np.inf, t_in),
        np.where(miss, -np.inf, t_out),
        np.where(miss[:, None], 0.0, n_in),
        np.where(miss[:, None], 0.0, n_out),
        np.where(miss, -1, p_in).astype(np.int64),
        np.where(miss, -1, p_out).astype(np.int64),
    )


def _sphere(center: F64, radius: float, o: F64, d: F64) -> Intervals:
    oc = o - center
    a = _dot(d, d)
    b = _dot(oc, d)
    c = _dot(oc, oc) - radius * radius
    disc = b * b - a * c
    ok = disc >= 0
    sq = np.sqrt(np.where(ok, disc, 0.0))
    t0 = np.where(ok, (-b - sq) / a, np.inf)
    t1 = np.where(ok, (-b + sq) / a, -np.inf)
    n0 = (oc + np.where(ok, t0, 0.0)[:, None] * d) / radius
    n1 = (oc + np.where(ok, t1, 0.0)[:, None] * d) / radius
    zero = np.zeros(len(o), dtype=np.int64)
    return _finish(t0, t1, n0, n1, zero, zero)


def _halfspaces(normals: F64, offsets: F64, o: F64, d: F64) -> Intervals:
    """Clip rays against ``{x : normals @ x <= offsets}``; part = plane index."""
    num = offsets[None, :] - o @ normals.T  # >= 0 where the origin is on the inner side
    den = d @ normals.T
    with np.errstate(divide="ignore", invalid="ignore"):
        t = num / den
    lower = np.where(den < 0, t, -np.inf)  # the ray crosses the plane inwards
    upper = np.where(den > 0, t, np.inf)
    k_in = np.argmax(lower, axis=1)
    k_out = np.argmin(upper, axis=1)
    rows = np.arange(len(o))
    t_in = lower[rows, k_in]
    t_out = upper[rows, k_out]
    # parallel to a plane and outside it: no intersection at all
    blocked = np.any((den == 0) & (num < 0), axis=1)
    t_in = np.where(blocked, np.inf, t_in)
    return _finish(t_in, t_out, normals[k_in], normals[k_out], k_in, k_out)


def _box_planes(box: Box) -> tuple[F64, F64]:
    c = np.asarray(box.center, dtype=np.float64)
    h = np.asarray(box.size, dtype=np.float64) / 2
    normals = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=np.float64)
    offsets = normals @ c + np.abs(normals) @ h
    return normals, offsets


def _polyhedron_planes(poly: ConvexPolyhedron) -> tuple[F64, F64]:
    """Distinct face planes of the hull (coplanar facets merged, so a face is one part)."""
    pts = np.asarray(poly.vertices, dtype=np.float64)
    eq = ConvexHull(pts).equations  # n . x + e <= 0 inside, n unit outward
    scale = float(np.max(np.ptp(pts, axis=0)))
    key = np.round(np.column_stack([eq[:, :3], eq[:, 3] / scale]), 6)
    _, first = np.unique(key, axis=0, return_index=True)
    eq = eq[np.sort(first)]
    return eq[:, :3].copy(), -eq[:, 3].copy()


def _truncus(tr: Truncus, o: F64, d: F64) -> Intervals:
    """Slab between the end planes intersected with one nappe of the lateral quadric.

    In the truncus frame (unit axis a, axial coordinate s from the centre) the
    radius is rho(s) = r2 + k (s + H/2) with k = (r1 - r2) / H. Along the ray,
    s(t) = s0 + t ds, the radial offset is p0 + t w and rho(t) = R0 + Rt t.
    The solid is {|s| <= H/2} n {|radial|^2 <= rho^2} n {rho >= 0}; the last
    two sets form one convex nappe (a cylinder when k = 0).
    """
    n = len(o)
    c = np.asarray(tr.center, dtype=np.float64)
    axis = np.asarray(tr.axis, dtype=np.float64)
    height = float(np.linalg.norm(axis))
    a = axis / height
    h2 = height / 2
    k = (tr.r1 - tr.r2) / height
    rel = o - c
    s0 = rel @ a
    ds = d @ a
    p0 = rel - s0[:, None] * a
    w = d - ds[:, None] * a
    r0 = tr.r2 + k * (s0 + h2)
    rt = k * ds

    # slab |s| <= h2
    with np.errstate(divide="ignore", invalid="ignore"):
        ta = (-h2 - s0) / ds  # crossing of the E2 plane
        tb = (h2 - s0) / ds  # crossing of the E1 plane
    par = ds == 0
    slab_lo = np.where(par, np.where(np.abs(s0) <= h2, -np.inf, np.inf), np.minimum(ta, tb))
    slab_hi = np.where(par, np.where(np.abs(s0) <= h2, np.inf, -np.inf), np.maximum(ta, tb))
    # entering through E2 when moving towards +a, through E1 when moving towards -a
    cap_in = np.where(ds > 0, PART_CAP2, PART_CAP1)
    cap_out = np.where(ds > 0, PART_CAP1, PART_CAP2)

    # quadric q(t) = A t^2 + 2 B t + C <= 0
    qa = _dot(w, w) - rt * rt
    qb = _dot(p0, w) - r0 * rt
    qc = _dot(p0, p0) - r0 * r0
    scale = max(tr.r1, tr.r2, height)
    lin = np.abs(qa) <= 1e-13 * np.maximum(_dot(d, d), 1e-300)
    disc = qb * qb - qa * qc
    real = disc >= 0
    sq = np.sqrt(np.where(real, disc, 0.0))
    # numerically stable roots: q1 = -(B + sign(B) sqrt), roots q1 / A and C / q1
    q1 = -(qb + np.where(qb >= 0, 1.0, -1.0) * sq)
    with np.errstate(divide="ignore", invalid="ignore"):
        ra = np.where(qa != 0, q1 / qa, np.inf)
        rb = np.where(q1 != 0, qc / q1, np.where(qa != 0, -qb / qa, np.inf))
    lo_root = np.minimum(ra, rb)
    hi_root = np.maximum(ra, rb)

    inf = np.full(n, np.inf)
    # piece 1 and piece 2 of {q <= 0} (piece 2 empty unless A < 0)
    p1_lo, p1_hi = inf.copy(), -inf.copy()
    p2_lo, p2_hi = inf.copy(), -inf.copy()
    pos = ~lin & (qa > 0) & real
    p1_lo = np.where(pos, lo_root, p1_lo)
    p1_hi = np.where(pos, hi_root, p1_hi)
    neg = ~lin & (qa < 0)
    p1_lo = np.where(neg & real, -np.inf, p1_lo)
    p1_hi = np.where(neg & real, lo_root, p1_hi)
    p2_lo = np.where(neg & real, hi_root, p2_lo)
    p2_hi = np.where(neg & real, np.inf, p2_hi)
    p1_lo = np.where(neg & ~real, -np.inf, p1_lo)  # numerically no roots: all of the line
    p1_hi = np.where(neg & ~real, np.inf, p1_hi)
    # linear: 2 B t + C <= 0
    with np.errstate(divide="ignore", invalid="ignore"):
        tl = -qc / (2 * qb)
    lb0 = lin & (qb == 0)
    p1_lo = np.where(lin & (qb > 0), -np.inf, np.where(lin & (qb < 0), tl, p1_lo))
    p1_hi = np.where(lin & (qb > 0), tl, np.where(lin & (qb < 0), np.inf, p1_hi))
    p1_lo = np.where(lb0, np.where(qc <= 0, -np.inf, np.inf), p1_lo)
    p1_hi = np.where(lb0, np.where(qc <= 0, np.inf, -np.inf), p1_hi)

    # the nappe rho >= 0: R0 + Rt t >= 0
    with np.errstate(divide="ignore", invalid="ignore"):
        tz = -r0 / rt
    h_lo = np.where(rt > 0, tz, np.where(rt < 0, -np.inf, np.where(r0 >= 0, -np.inf, np.inf)))
    h_hi = np.where(rt > 0, np.inf, np.where(rt < 0, tz, np.where(r0 >= 0, np.inf, -np.inf)))
    a1_lo, a1_hi = np.maximum(p1_lo, h_lo), np.minimum(p1_hi, h_hi)
    a2_lo, a2_hi = np.maximum(p2_lo, h_lo), np.minimum(p2_hi, h_hi)
    e1, e2 = a1_lo <= a1_hi, a2_lo <= a2_hi
    # the two pieces on one nappe are the two ends of one convex interval; take their hull
    lat_lo = np.where(e1 & e2, np.minimum(a1_lo, a2_lo), np.where(e1, a1_lo, np.where(e2, a2_lo, np.inf)))
    lat_hi = np.where(e1 & e2, np.maximum(a1_hi, a2_hi), np.where(e1, a1_hi, np.where(e2, a2_hi, -np.inf)))
    del scale

    side_in = lat_lo > slab_lo
    side_out = lat_hi < slab_hi
    t_in = np.maximum(lat_lo, slab_lo)
    t_out = np.minimum(lat_hi, slab_hi)

    def lateral_normal(t: F64) -> F64:
        tt = np.where(np.isfinite(t), t, 0.0)
        radial = p0 + tt[:, None] * w
        er = _normalize(radial)
        return _normalize(er - k * a)

    n_in = np.where(side_in[:, None], lateral_normal(t_in), np.where(cap_in[:, None] == PART_CAP1, a, -a))
    n_out = np.where(side_out[:, None], lateral_normal(t_out), np.where(cap_out[:, None] == PART_CAP1, a, -a))
    part_in = np.where(side_in, PART_LATERAL, cap_in)
    part_out = np.where(side_out, PART_LATERAL, cap_out)
    return _finish(t_in, t_out, n_in, n_out, part_in, part_out)


def primitive_intervals(primitive: Any, origins: Any, directions: Any) -> Intervals:
    """Entry/exit parameters, outward normals and parts of rays against one primitive.

    Parameters
    ----------
    primitive : Sphere, Truncus (Cylinder, Cone), Box or ConvexPolyhedron
    origins, directions : array_like, shape (n, 3)
        Directions need not be unit; ``t`` is in units of their length.

    Returns
    -------
    Intervals
    """
    o = np.atleast_2d(np.asarray(origins, dtype=np.float64))
    d = np.atleast_2d(np.asarray(directions, dtype=np.float64))
    o = np.broadcast_to(o, d.shape) if len(o) == 1 else o
    if isinstance(primitive, Sphere):
        return _sphere(np.asarray(primitive.center, dtype=np.float64), float(primitive.radius), o, d)
    if isinstance(primitive, Truncus):
        return _truncus(primitive, o, d)
    if isinstance(primitive, Box):
        return _halfspaces(*_box_planes(primitive), o, d)
    if isinstance(primitive, ConvexPolyhedron):
        return _halfspaces(*_polyhedron_planes(primitive), o, d)
    raise TypeError(f"unsupported primitive {type(primitive).__name__}")


# ----------------------------------------------------------------------------- CSG


def _leaves(solid: Any) -> list[Any]:
    if isinstance(solid, (Union, Intersection, Difference)):
        out: list[Any] = []
        for child in solid.children:
            out.extend(_leaves(child))
        return out
    return [solid]


def _evaluate(solid: Any, inside: list[NDArray[np.bool_]], counter: list[int]) -> NDArray[np.bool_]:
    """Membership of the tree from the leaves' memberships (leaves in depth-first order)."""
    if isinstance(solid, (Union, Intersection, Difference)):
        kids = [_evaluate(c, inside, counter) for c in solid.children]
        if isinstance(solid, Union):
            return np.logical_or.reduce(kids)
        if isinstance(solid, Intersection):
            return np.logical_and.reduce(kids)
        out = kids[0].copy()
        for m in kids[1:]:
            out &= ~m
        return out
    i = counter[0]
    counter[0] += 1
    return inside[i]


@dataclass(frozen=True)
class FirstHit:
    """The first visible point of a solid along rays (``t = inf`` where none).

    ``normal`` is the outward normal of the result solid there: the leaf's
    outward normal at an entry, the reversed one at an exit. ``leaf`` indexes
    the solid's leaves depth first, ``side`` is ``SIDE_ENTRY``/``SIDE_EXIT``.
    """

    t: F64
    normal: F64
    leaf: I64
    side: I64
    part: I64

    @property
    def hit(self) -> NDArray[np.bool_]:
        """Rays that see the solid."""
        return np.isfinite(self.t)


def first_hit(solid: Any, origins: Any, directions: Any, *, t_min: float = 0.0) -> FirstHit:
    """First visible point of a primitive or CSG tree along rays, by interval arithmetic.

    All entry and exit parameters of the leaves are sorted along each ray; the
    tree is evaluated at the midpoint of every segment of positive length
    between consecutive events (open intervals, so touching boundaries count
    as outside: regularised operations). The visible point is the start of
    the first such segment inside the result that starts beyond ``t_min``.
    """
    o = np.atleast_2d(np.asarray(origins, dtype=np.float64))
    d = np.atleast_2d(np.asarray(directions, dtype=np.float64))
    o = np.broadcast_to(o, d.shape) if len(o) == 1 else o
    leaves = _leaves(solid)
    n_leaves = len(leaves)
    if n_leaves > _MAX_LEAVES:
        raise ValueError(f"at most {_MAX_LEAVES} leaves, got {n_leaves}")
    ivs = [primitive_intervals(p, o, d) for p in leaves]
    n = len(d)
    # misses become empty intervals at +inf so that they sort last
    t_in = np.column_stack([np.where(iv.hit, iv.t_in, np.inf) for iv in ivs])
    t_out = np.column_stack([np.where(iv.hit, iv.t_out, np.inf) for iv in ivs])
    events = np.concatenate([t_in, t_out], axis=1)  # event e: leaf e % L, side e // L
    order = np.argsort(events, axis=1, kind="stable")
    ts = np.take_along_axis(events, order, axis=1)
    lo, hi = ts[:, :-1], ts[:, 1:]
    with np.errstate(invalid="ignore"):
        mid = 0.5 * (lo + hi)
    inside = [(t_in[:, [i]] < mid) & (mid < t_out[:, [i]]) for i in range(n_leaves)]
    member = _evaluate(solid, inside, [0])
    member &= (hi > lo) & (lo > t_min) & np.isfinite(lo)
    hit = member.any(axis=1)
    k = np.argmax(member, axis=1)
    rows = np.arange(n)
    ev = order[rows, k]
    leaf = ev % n_leaves
    side = ev // n_leaves
    t = np.where(hit, ts[rows, k], np.inf)
    n_in = np.stack([iv.n_in for iv in ivs], axis=1)[rows, leaf]
    n_out = np.stack([iv.n_out for iv in ivs], axis=1)[rows, leaf]
    p_in = np.stack([iv.part_in for iv in ivs], axis=1)[rows, leaf]
    p_out = np.stack([iv.part_out for iv in ivs], axis=1)[rows, leaf]
    normal = np.where((side == SIDE_ENTRY)[:, None], n_in, -n_out)
    part = np.where(side == SIDE_ENTRY, p_in, p_out)
    return FirstHit(
        t,
        np.where(hit[:, None], normal, 0.0),
        np.where(hit, leaf, -1).astype(np.int64),
        np.where(hit, side, -1).astype(np.int64),
        np.where(hit, part, -1).astype(np.int64),
    )


# ----------------------------------------------------------------------------- shading


def shade_points(points: F64, normals: F64, eye: F64, lights: Sequence[Any], material: Material) -> F64:
    """``ambient + sum intensity (kd max(0, n.l) + [n.l > 0] ks max(0, rf.v)^shininess)``."""
    p = np.asarray(points, dtype=np.float64)
    nrm = _normalize(np.asarray(normals, dtype=np.float64))
    v = _normalize(np.asarray(eye, dtype=np.float64) - p)
    out = np.full(len(p), float(material.ambient))
    for light in lights:
        if isinstance(light, PointLight):
            l = _normalize(np.asarray(light.position, dtype=np.float64) - p)
        elif isinstance(light, DirectionalLight):
            dl = np.asarray(light.direction, dtype=np.float64)
            l = np.broadcast_to(dl / np.linalg.norm(dl), p.shape)
        else:
            raise TypeError(f"unsupported light {type(light).__name__}")
        ndl = _dot(nrm, l)
        lit = ndl > 0
        term = material.kd * np.maximum(ndl, 0.0)
        if material.ks > 0:
            rf = 2 * ndl[:, None] * nrm - l
            spec = np.maximum(_dot(rf, v), 0.0) ** material.shininess
            term = term + np.where(lit, material.ks * spec, 0.0)
        out += float(light.intensity) * term
    return out


# ----------------------------------------------------------------------------- images


@dataclass(frozen=True)
class ReferenceImage:
    """The exact image and what each pixel sees.

    Attributes
    ----------
    image : ndarray (H, W) float64
        Intensity, NaN where no object is hit.
    depth : ndarray (H, W)
        Ray parameter (distance from the eye) of the visible point, inf on background.
    normal : ndarray (H, W, 3)
        Normal used for shading (reversed inside cuts), zero on background.
    obj, leaf, side, part : ndarray (H, W) int64
        Object index, leaf index (depth first in its tree), ``SIDE_ENTRY`` or
        ``SIDE_EXIT``, and part of the leaf; -1 on background.
    """

    image: F64
    depth: F64
    normal: F64
    obj: I64
    leaf: I64
    side: I64
    part: I64

    @property
    def mask(self) -> NDArray[np.bool_]:
        """Pixels that see an object."""
        return self.obj >= 0

    @property
    def surface_id(self) -> I64:
        """One integer per smooth surface patch (object, leaf, side, part); -1 on background.

        Neighbouring pixels with different ids straddle a discontinuity of the
        exact image (a CSG seam, a box edge, a cap rim or an occluding contour).
        """
        sid = ((self.obj * _MAX_LEAVES + self.leaf) * 2 + self.side) * _MAX_PARTS + self.part
        return np.where(self.mask, sid, -1)


def raycast(camera: Camera, objects: Sequence[tuple[Any, Material]], lights: Sequence[Any]) -> ReferenceImage:
    """Render the exact image of solids with materials under lights.

    Parameters
    ----------
    camera : isocsg.Camera
        A pinhole camera.
    objects : sequence of (solid, Material)
        Primitives or CSG trees; the nearest visible point over them wins.
    lights : sequence of PointLight or DirectionalLight

    Returns
    -------
    ReferenceImage
    """
    origins, dirs = camera_rays(camera)
    h, w = dirs.shape[:2]
    o = origins.reshape(-1, 3)
    d = dirs.reshape(-1, 3)
    n = len(d)
    best_t = np.full(n, np.inf)
    normal = np.zeros((n, 3))
    obj = np.full(n, -1, dtype=np.int64)
    leaf = np.full(n, -1, dtype=np.int64)
    side = np.full(n, -1, dtype=np.int64)
    part = np.full(n, -1, dtype=np.int64)
    for idx, (solid, _) in enumerate(objects):
        fh = first_hit(solid, o, d)
        if fh.part.max(initial=-1) >= _MAX_PARTS:
            raise ValueError(f"object {idx} has more than {_MAX_PARTS} faces")
        closer = fh.t < best_t
        best_t = np.where(closer, fh.t, best_t)
        normal = np.where(closer[:, None], fh.normal, normal)
        obj = np.where(closer, idx, obj)
        leaf = np.where(closer, fh.leaf, leaf)
        side = np.where(closer, fh.side, side)
        part = np.where(closer, fh.part, part)
    image = np.full(n, np.nan)
    hit = obj >= 0
    eye = np.asarray(camera.eye, dtype=np.float64)
    pts = o + np.where(hit, best_t, 0.0)[:, None] * d
    for idx, (_, material) in enumerate(objects):
        sel = obj == idx
        if np.any(sel):
            image[sel] = shade_points(pts[sel], normal[sel], eye, lights, material)
    return ReferenceImage(
        image.reshape(h, w),
        best_t.reshape(h, w),
        normal.reshape(h, w, 3),
        obj.reshape(h, w),
        leaf.reshape(h, w),
        side.reshape(h, w),
        part.reshape(h, w),
    )


def raycast_scene(scene: Scene) -> ReferenceImage:
    """:func:`raycast` of an ``isocsg.Scene`` (camera, lights, objects with materials)."""
    return raycast(scene.camera, [(ob.shape, ob.material) for ob in scene.objects], scene.lights)
