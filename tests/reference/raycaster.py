"""Analytic per-pixel ray caster: the exact image of the conventions.

Written independently of the library: it reads the parameters of primitives
(``Sphere.center/.radius``, ``Truncus.center/.axis/.r1/.r2``,
``Box.center/.size/.orientation``, ``Ellipsoid.center/.radii/.orientation``,
``ConvexPolyhedron.vertices``), the ``children`` of CSG
nodes, lights, materials and camera fields, and computes everything else
itself:

- camera rays from the pinhole formula of the conventions,
- ray-primitive intervals in closed form (sphere quadratic; truncus lateral
  quadric on one nappe intersected with the slab between its end planes;
  box and convex polyhedron as intersections of half-spaces, the polyhedron's
  planes from its own ``scipy.spatial.ConvexHull``; a turned box, an
  ellipsoid and an elliptic truncus in their own frames, ``x = center + M y``
  with ``M`` the rotation, times ``diag(radii)`` for the ellipsoid, the
  ``matrix`` of the elliptic truncus: the ray ``M^-1 (o - c) + t M^-1 d``
  meets the axis-aligned box, the unit ball or the truncus of height 1 along
  z at the same ``t``, and a normal ``m`` there is ``M^-T m`` in the world),
- a torus (``Torus.center/.axis/.major/.minor``) by its own root finder, not the
  library's quartic: sphere tracing along the ray on the exact distance
  ``sqrt((rho - R)^2 + z^2) - r`` (a 1-Lipschitz function, so no crossing is
  stepped over, except intervals shorter than ``reference.torus.MIN_STEP`` of the tube radius
  at grazing incidence) from where the ray enters the bounding sphere of radius
  ``R + r`` to where it leaves it, each sign change bisected to the last bit; its up
  to two intervals are two leaves of a union in the tree (disjoint intervals),
- a closed triangle mesh (``TriangleMesh.vertices/.faces``) by brute force over its triangles
  (:mod:`reference.mesh`: Moller-Trumbore, hits paired by parity); its first ``MESH_LAYERS``
  intervals are leaves of a union in the tree,
- CSG by interval arithmetic: the boundary events of all leaves are sorted
  along each ray and the tree is evaluated on every segment between them; the
  visible point is the start of the first non-empty segment inside the result,
- trees of any size: the tree is read once into a postfix program by walking
  ``children`` with an explicit stack (no recursion); rays go in screen tiles
  (or blocks of rays), and a leaf that no ray of a tile can meet where it
  matters (its bounding box, cut by its ancestors' contexts, outside the
  tile's pyramid of rays) is the empty set there, so the program is pruned
  to the leaves present before any interval is computed. Few leaves: the
  tree is evaluated on all segments at once; many: a compiled sweep over the
  sorted events (the same test, segment by segment),
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
from numba import njit
from numpy.typing import NDArray
from scipy.spatial import ConvexHull

from isocsg import (
    Box,
    Camera,
    ConvexPolyhedron,
    Difference,
    DirectionalLight,
    Ellipsoid,
    EllipticTruncus,
    Intersection,
    Material,
    PointLight,
    Scene,
    Sphere,
    Truncus,
    Union,
)
from isocsg.kinds import Torus, TriangleMesh

from .mesh import MESH_LAYERS, mesh_intervals
from .torus import torus_intervals, torus_trace

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
    "torus_intervals",
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

#: Bounds of the surface id's fields (leaves per object, parts per leaf).
_MAX_LEAVES = 1 << 24
_MAX_PARTS = 1024
#: Cosines of incidence within this of 0 lie on the terminator (rounding of unit vectors).
TERMINATOR_COSINE = 1e-9


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

    The batched forms below hold several primitives of one kind at once:
    every array then has a leading axis, one row per primitive.
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
    return np.einsum("...j,...j->...", a, b)


def _normalize(v: F64) -> F64:
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return np.divide(v, n, out=np.zeros_like(v), where=n > 0)


def _rows_dot(v: F64, a: F64) -> F64:
    """``v[i] @ a[i]`` for stacked (k, n, 3) and (k, 3): one matrix-vector product per row."""
    return np.matmul(v, a[:, :, None])[..., 0]


def _finish(t_in: F64, t_out: F64, n_in: F64, n_out: F64, p_in: I64, p_out: I64) -> Intervals:
    miss = ~(t_in <= t_out)
    return Intervals(
        np.where(miss, np.inf, t_in),
        np.where(miss, -np.inf, t_out),
        np.where(miss[..., None], 0.0, n_in),
        np.where(miss[..., None], 0.0, n_out),
        np.where(miss, -1, p_in).astype(np.int64),
        np.where(miss, -1, p_out).astype(np.int64),
    )


def _spheres(centers: F64, radii: F64, o: F64, d: F64) -> Intervals:
    """k spheres (centres (k, 3), radii (k,)) against n rays: arrays (k, n)."""
    oc = o[None, :, :] - centers[:, None, :]
    a = _dot(d, d)[None, :]
    b = _dot(oc, d[None, :, :])
    c = _dot(oc, oc) - (radii * radii)[:, None]
    disc = b * b - a * c
    ok = disc >= 0
    sq = np.sqrt(np.where(ok, disc, 0.0))
    t0 = np.where(ok, (-b - sq) / a, np.inf)
    t1 = np.where(ok, (-b + sq) / a, -np.inf)
    n0 = (oc + np.where(ok, t0, 0.0)[..., None] * d[None, :, :]) / radii[:, None, None]
    n1 = (oc + np.where(ok, t1, 0.0)[..., None] * d[None, :, :]) / radii[:, None, None]
    zero = np.zeros(t0.shape, dtype=np.int64)
    return _finish(t0, t1, n0, n1, zero, zero)


def _halfspaces(normals: F64, offsets: F64, o: F64, d: F64) -> Intervals:
    """Clip rays against k solids ``{x : normals @ x <= offsets[i]}`` sharing the plane normals
    (normals (P, 3), offsets (k, P)): arrays (k, n); part = plane index."""
    num = offsets[:, None, :] - (o @ normals.T)[None, :, :]  # >= 0 where the origin is on the inner side
    den = np.broadcast_to((d @ normals.T)[None, :, :], num.shape)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = num / den
    lower = np.where(den < 0, t, -np.inf)  # the ray crosses the plane inwards
    upper = np.where(den > 0, t, np.inf)
    k_in = np.argmax(lower, axis=-1)
    k_out = np.argmin(upper, axis=-1)
    t_in = np.take_along_axis(lower, k_in[..., None], axis=-1)[..., 0]
    t_out = np.take_along_axis(upper, k_out[..., None], axis=-1)[..., 0]
    # parallel to a plane and outside it: no intersection at all
    blocked = np.any((den == 0) & (num < 0), axis=-1)
    t_in = np.where(blocked, np.inf, t_in)
    return _finish(t_in, t_out, normals[k_in], normals[k_out], k_in, k_out)


_BOX_NORMALS = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=np.float64)


def _box_offsets(box: Box) -> F64:
    c = np.asarray(box.center, dtype=np.float64)
    h = np.asarray(box.size, dtype=np.float64) / 2
    return _BOX_NORMALS @ c + np.abs(_BOX_NORMALS) @ h


def _box_planes(box: Box) -> tuple[F64, F64]:
    return _BOX_NORMALS, _box_offsets(box)


def _polyhedron_planes(poly: ConvexPolyhedron) -> tuple[F64, F64]:
    """Distinct face planes of the hull (coplanar facets merged, so a face is one part)."""
    pts = np.asarray(poly.vertices, dtype=np.float64)
    eq = ConvexHull(pts).equations  # n . x + e <= 0 inside, n unit outward
    scale = float(np.max(np.ptp(pts, axis=0)))
    key = np.round(np.column_stack([eq[:, :3], eq[:, 3] / scale]), 6)
    _, first = np.unique(key, axis=0, return_index=True)
    eq = eq[np.sort(first)]
    return eq[:, :3].copy(), -eq[:, 3].copy()


def _truncus_params(tr: Truncus) -> tuple[F64, F64, float, float, float, float]:
    """Centre, unit axis, half height, slope k = (r1 - r2) / H, r1, r2 of one truncus."""
    c = np.asarray(tr.center, dtype=np.float64)
    axis = np.asarray(tr.axis, dtype=np.float64)
    height = float(np.linalg.norm(axis))
    return c, axis / height, height / 2, (tr.r1 - tr.r2) / height, float(tr.r1), float(tr.r2)


def _trunci(c: F64, a: F64, h2: F64, k: F64, r2: F64, o: F64, d: F64) -> Intervals:
    """k trunci against n rays: arrays (k, n).

    Slab between the end planes intersected with one nappe of the lateral quadric.
    In the truncus frame (unit axis a, axial coordinate s from the centre) the
    radius is rho(s) = r2 + k (s + H/2) with k = (r1 - r2) / H. Along the ray,
    s(t) = s0 + t ds, the radial offset is p0 + t w and rho(t) = R0 + Rt t.
    The solid is {|s| <= H/2} n {|radial|^2 <= rho^2} n {rho >= 0}; the last
    two sets form one convex nappe (a cylinder when k = 0).

    ``c``, ``a`` have shape (k, 3), ``h2``, ``k``, ``r2`` shape (k,).
    """
    m, n = len(c), len(o)
    h2, kk, r2 = h2[:, None], k[:, None], r2[:, None]
    rel = o[None, :, :] - c[:, None, :]
    s0 = _rows_dot(rel, a)
    ds = _rows_dot(np.broadcast_to(d, (m, n, 3)), a)
    ax = a[:, None, :]
    p0 = rel - s0[..., None] * ax
    w = d[None, :, :] - ds[..., None] * ax
    r0 = r2 + kk * (s0 + h2)
    rt = kk * ds

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
    lin = np.abs(qa) <= 1e-13 * np.maximum(_dot(d, d), 1e-300)[None, :]
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

    inf = np.full(qa.shape, np.inf)
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

    side_in = lat_lo > slab_lo
    side_out = lat_hi < slab_hi
    t_in = np.maximum(lat_lo, slab_lo)
    t_out = np.minimum(lat_hi, slab_hi)

    def lateral_normal(t: F64) -> F64:
        tt = np.where(np.isfinite(t), t, 0.0)
        radial = p0 + tt[..., None] * w
        er = _normalize(radial)
        return _normalize(er - kk[..., None] * ax)

    n_in = np.where(side_in[..., None], lateral_normal(t_in), np.where(cap_in[..., None] == PART_CAP1, ax, -ax))
    n_out = np.where(side_out[..., None], lateral_normal(t_out), np.where(cap_out[..., None] == PART_CAP1, ax, -ax))
    part_in = np.where(side_in, PART_LATERAL, cap_in)
    part_out = np.where(side_out, PART_LATERAL, cap_out)
    return _finish(t_in, t_out, n_in, n_out, part_in, part_out)


def _first_row(iv: Intervals) -> Intervals:
    return Intervals(iv.t_in[0], iv.t_out[0], iv.n_in[0], iv.n_out[0], iv.part_in[0], iv.part_out[0])


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
    leaf = _Leaf.of(primitive)
    return _first_row(_batch_intervals([leaf], o, d))


# ----------------------------------------------------------------------------- leaves


_SPHERE, _TRUNCUS, _BOX, _POLY, _LOCAL, _TORUS, _MESH = 0, 1, 2, 3, 4, 5, 6


@dataclass(frozen=True)
class _Leaf:
    """A primitive's kind, parameters and axis-aligned bounding box, read from its fields."""

    kind: int
    params: tuple[Any, ...]
    lo: F64
    hi: F64

    @staticmethod
    def of(p: Any) -> _Leaf:
        if isinstance(p, Sphere):
            c = np.asarray(p.center, dtype=np.float64)
            r = float(p.radius)
            return _Leaf(_SPHERE, (c, r), c - r, c + r)
        if isinstance(p, Truncus):
            c, a, h2, k, r1, r2 = _truncus_params(p)
            # each end disc's extent along a world axis e is r sqrt(1 - (a . e)^2)
            spread = np.sqrt(np.maximum(0.0, 1.0 - a * a))
            ends = [(c + h2 * a, r1), (c - h2 * a, r2)]
            lo = np.min([e - r * spread for e, r in ends], axis=0)
            hi = np.max([e + r * spread for e, r in ends], axis=0)
            return _Leaf(_TRUNCUS, (c, a, h2, k, r1, r2), lo, hi)
        if isinstance(p, EllipticTruncus):
            c = np.asarray(p.center, dtype=np.float64)
            M = np.asarray(p.matrix, dtype=np.float64)
            r1, r2 = float(p.r1), float(p.r2)
            # the ends' ellipses: centre +- axis/2, extent r * hypot of the two radial columns
            spread = np.sqrt(M[:, 0] ** 2 + M[:, 1] ** 2)
            ends = [(c + M[:, 2] / 2, r1), (c - M[:, 2] / 2, r2)]
            lo = np.min([e - r * spread for e, r in ends], axis=0)
            hi = np.max([e + r * spread for e, r in ends], axis=0)
            return _Leaf(_LOCAL, ("truncus", c, M, (r1, r2)), lo, hi)
        if isinstance(p, Ellipsoid):
            c = np.asarray(p.center, dtype=np.float64)
            M = np.asarray(p.orientation, dtype=np.float64) * np.asarray(p.radii, dtype=np.float64)
            ext = np.sqrt((M * M).sum(axis=1))
            return _Leaf(_LOCAL, ("ball", c, M, None), c - ext, c + ext)
        if isinstance(p, Box) and not np.array_equal(np.asarray(p.orientation), np.eye(3)):
            c = np.asarray(p.center, dtype=np.float64)
            M = np.asarray(p.orientation, dtype=np.float64)
            h = np.asarray(p.size, dtype=np.float64) / 2
            ext = np.abs(M) @ h
            return _Leaf(_LOCAL, ("box", c, M, h), c - ext, c + ext)
        if isinstance(p, Box):
            c = np.asarray(p.center, dtype=np.float64)
            h = np.asarray(p.size, dtype=np.float64) / 2
            return _Leaf(_BOX, (_box_offsets(p),), c - h, c + h)
        if isinstance(p, Torus):
            c, w = np.asarray(p.center, dtype=np.float64), np.asarray(p.axis, dtype=np.float64)
            w = w / np.linalg.norm(w)
            ext = float(p.major) * np.sqrt(np.maximum(0.0, 1.0 - w * w)) + float(p.minor)
            return _Leaf(_TORUS, (c, w, float(p.major), float(p.minor), 0), c - ext, c + ext)
        if isinstance(p, ConvexPolyhedron):
            pts = np.asarray(p.vertices, dtype=np.float64)
            return _Leaf(_POLY, (p,), pts.min(axis=0), pts.max(axis=0))
        if isinstance(p, TriangleMesh):  # its interval 0; read_tree adds the others
            V, F = np.asarray(p.vertices, dtype=np.float64), np.asarray(p.faces, dtype=np.int64)
            return _Leaf(_MESH, (V, F, 0), V.min(axis=0), V.max(axis=0))
        raise TypeError(f"unsupported primitive {type(p).__name__}")


_PLANES: dict[int, tuple[Any, tuple[F64, F64]]] = {}


def _planes_of(poly: ConvexPolyhedron) -> tuple[F64, F64]:
    """The polyhedron's planes, computed once per object (keyed by identity, the object kept alive)."""
    hit = _PLANES.get(id(poly))
    if hit is None or hit[0] is not poly:
        if len(_PLANES) > 4096:
            _PLANES.clear()
        hit = (poly, _polyhedron_planes(poly))
        _PLANES[id(poly)] = hit
    return hit[1]


def _local_intervals(params: tuple[Any, ...], o: F64, d: F64) -> Intervals:
    """One turned box or ellipsoid, intersected in its own frame (see the module docstring)."""
    shape, c, M, h = params
    Minv = np.linalg.inv(M)
    ol = (o - c) @ Minv.T
    dl = d @ Minv.T
    if shape == "ball":
        iv = _spheres(np.zeros((1, 3)), np.ones(1), ol, dl)
    elif shape == "truncus":  # axis z, height 1, r1 at z = +1/2, r2 at z = -1/2
        r1, r2 = h
        iv = _trunci(np.zeros((1, 3)), np.array([[0.0, 0.0, 1.0]]), np.array([0.5]), np.array([r1 - r2]), np.array([r2]), ol, dl)
    else:
        iv = _halfspaces(_BOX_NORMALS, (np.abs(_BOX_NORMALS) @ h)[None, :], ol, dl)
    n_in = _normalize(iv.n_in @ Minv)  # M^-T m, row-wise
    n_out = _normalize(iv.n_out @ Minv)
    return Intervals(iv.t_in, iv.t_out, n_in, n_out, iv.part_in, iv.part_out)


def _torus_normal(p: F64, c: F64, w: F64, R: float) -> F64:
    q = p - c
    radial = q - (q @ w)[:, None] * w
    return _normalize(q - R * _normalize(radial))


def _torus_leaf(params: tuple[Any, ...], o: F64, d: F64) -> Intervals:
    """Interval ``k`` of a torus (``params = (c, w, R, r, k)``) as one leaf's intervals."""
    c, w, R, r, k = params
    ln = np.linalg.norm(d, axis=1)
    out = np.full((len(o), 2, 2), np.nan)
    torus_trace(np.ascontiguousarray(o), np.ascontiguousarray(d / ln[:, None]), c, w, R, r, out)
    t_in, t_out = out[:, k, 0] / ln, out[:, k, 1] / ln
    hit = np.isfinite(t_in)
    n_in = _torus_normal(o + np.where(hit, t_in, 0.0)[:, None] * d, c, w, R)
    n_out = _torus_normal(o + np.where(hit, t_out, 0.0)[:, None] * d, c, w, R)
    zero = np.zeros(len(o), dtype=np.int64)
    return _finish(np.where(hit, t_in, np.inf), np.where(hit, t_out, -np.inf), n_in, n_out, zero, zero)


def _mesh_leaf(params: tuple[Any, ...], o: F64, d: F64) -> Intervals:
    """Interval ``k`` of a triangle mesh (``params = (V, F, k)``, :func:`reference.mesh.mesh_intervals`);
    the part is the face hit (modulo the parts' bound)."""
    V, F, k = params
    t_in, t_out, n_in, n_out, f_in, f_out = mesh_intervals(V, F, o, d)
    hit = np.isfinite(t_in[:, k])
    return _finish(np.where(hit, t_in[:, k], np.inf), np.where(hit, t_out[:, k], -np.inf), n_in[:, k], n_out[:, k],
                   f_in[:, k] % _MAX_PARTS, f_out[:, k] % _MAX_PARTS)


def _batch_intervals(leaves: Sequence[_Leaf], o: F64, d: F64) -> Intervals:
    """Intervals of every leaf against every ray: arrays (k, n), rows in the order of ``leaves``."""
    k, n = len(leaves), len(o)
    t_in = np.empty((k, n))
    t_out = np.empty((k, n))
    n_in = np.empty((k, n, 3))
    n_out = np.empty((k, n, 3))
    p_in = np.empty((k, n), dtype=np.int64)
    p_out = np.empty((k, n), dtype=np.int64)
    kinds = np.array([leaf.kind for leaf in leaves], dtype=np.int64)
    step = max(1, CHUNK_CELLS // max(1, n))  # leaves computed together: bounded temporaries
    for kind, rows in ((kd, chunk) for kd in np.unique(kinds).tolist()
                       for all_rows in [np.nonzero(kinds == kd)[0]]
                       for chunk in (all_rows[s : s + step] for s in range(0, len(all_rows), step))):
        group = [leaves[i] for i in rows.tolist()]
        if kind == _SPHERE:
            ivs = [(rows, _spheres(np.array([g.params[0] for g in group]), np.array([g.params[1] for g in group]), o, d))]
        elif kind == _TRUNCUS:
            cols = list(zip(*(g.params for g in group)))
            c, a = np.array(cols[0]), np.array(cols[1])
            h2, kk, r2 = (np.array(cols[i], dtype=np.float64) for i in (2, 3, 5))
            ivs = [(rows, _trunci(c, a, h2, kk, r2, o, d))]
        elif kind == _BOX:
            ivs = [(rows, _halfspaces(_BOX_NORMALS, np.array([g.params[0] for g in group]), o, d))]
        elif kind == _LOCAL:
            ivs = [(np.array([r]), _local_intervals(g.params, o, d)) for r, g in zip(rows.tolist(), group)]
        elif kind == _TORUS:
            ivs = [(np.array([r]), _torus_leaf(g.params, o, d)) for r, g in zip(rows.tolist(), group)]
        elif kind == _MESH:
            ivs = [(np.array([r]), _mesh_leaf(g.params, o, d)) for r, g in zip(rows.tolist(), group)]
        else:
            ivs = []
            for r, g in zip(rows.tolist(), group):
                normals, offsets = _planes_of(g.params[0])
                ivs.append((np.array([r]), _halfspaces(normals, offsets[None, :], o, d)))
        for r, iv in ivs:
            t_in[r], t_out[r], n_in[r], n_out[r] = iv.t_in, iv.t_out, iv.n_in, iv.n_out
            p_in[r], p_out[r] = iv.part_in, iv.part_out
    return Intervals(t_in, t_out, n_in, n_out, p_in, p_out)


# ----------------------------------------------------------------------------- CSG trees

OP_LEAF, OP_UNION, OP_INTER, OP_DIFF = 0, 1, 2, 3


@dataclass(frozen=True)
class _Tree:
    """A CSG tree read once into a postfix program over its leaves.

    ``op[i]``/``arg[i]``: ``(OP_LEAF, leaf index)`` or ``(operation, operand
    count)``; a difference is its first operand minus the others. Leaves are
    numbered depth first, left to right (repeats kept). Nested nodes of the
    same operation are spliced into one (``(a | b) | c`` is a union of three,
    ``(a - b) - c`` is ``a - b - c``): the same set, a shallower program.
    """

    leaves: list[_Leaf]
    op: list[int]
    arg: list[int]


def _op_of(solid: Any) -> int:
    if isinstance(solid, Union):
        return OP_UNION
    if isinstance(solid, Intersection):
        return OP_INTER
    if isinstance(solid, Difference):
        return OP_DIFF
    return OP_LEAF


def _operands(node: Any) -> list[Any]:
    """The operands of a node, same-operation children spliced in (explicit stack, no recursion)."""
    op = _op_of(node)
    if op == OP_DIFF:
        subtracted: list[Any] = []
        first = node
        while _op_of(first) == OP_DIFF:  # (a - b) - c: down the chain of first operands
            subtracted.append(list(first.children[1:]))
            first = first.children[0]
        return [first] + [c for group in reversed(subtracted) for c in group]
    out: list[Any] = []
    todo = list(reversed(node.children))
    while todo:
        c = todo.pop()
        if _op_of(c) == op:
            todo.extend(reversed(c.children))
        else:
            out.append(c)
    return out


def read_tree(solid: Any) -> _Tree:
    """The postfix program of a primitive or CSG tree, walking ``children`` with an explicit stack."""
    leaves: list[_Leaf] = []
    seen: dict[int, _Leaf] = {}
    op: list[int] = []
    arg: list[int] = []
    todo: list[Any] = [solid]
    while todo:
        item = todo.pop()
        if isinstance(item, tuple):
            op.append(item[0])
            arg.append(item[1])
            continue
        kind = _op_of(item)
        if kind == OP_LEAF and isinstance(item, Torus):  # its two intervals: a union of two leaves
            first = _Leaf.of(item)
            second = _Leaf(_TORUS, first.params[:4] + (1,), first.lo, first.hi)
            op.extend([OP_LEAF, OP_LEAF, OP_UNION])
            arg.extend([len(leaves), len(leaves) + 1, 2])
            leaves.extend([first, second])
            continue
        if kind == OP_LEAF and isinstance(item, TriangleMesh):  # MESH_LAYERS intervals: a union of leaves
            first = _Leaf.of(item)
            op.extend([OP_LEAF] * MESH_LAYERS + [OP_UNION])
            arg.extend([len(leaves) + j for j in range(MESH_LAYERS)] + [MESH_LAYERS])
            leaves.extend(_Leaf(_MESH, first.params[:2] + (j,), first.lo, first.hi) for j in range(MESH_LAYERS))
            continue
        if kind == OP_LEAF:
            leaf = seen.get(id(item))
            if leaf is None:
                leaf = seen[id(item)] = _Leaf.of(item)
            op.append(OP_LEAF)
            arg.append(len(leaves))
            leaves.append(leaf)
            continue
        kids = _operands(item)
        todo.append((kind, len(kids)))
        todo.extend(reversed(kids))
    return _Tree(leaves, op, arg)


def _prune(op: Sequence[int], arg: Sequence[int], present: NDArray[np.bool_]) -> tuple[list[int], list[int]] | None:
    """The program with absent leaves replaced by the empty set, simplified; ``None`` if empty.

    An empty operand drops out of a union and out of the subtracted operands of
    a difference; it empties an intersection and a difference whose first
    operand it is. Single-operand nodes become their operand. Leaf arguments
    keep the original leaf indices.
    """
    stack: list[tuple[list[int], list[int]] | None] = []
    for o, a in zip(op, arg):
        if o == OP_LEAF:
            stack.append(([OP_LEAF], [a]) if present[a] else None)
            continue
        args = stack[len(stack) - a :]
        del stack[len(stack) - a :]
        if (o == OP_INTER and any(x is None for x in args)) or (o == OP_DIFF and args[0] is None):
            stack.append(None)
            continue
        kept = [x for x in args if x is not None]
        if not kept:
            stack.append(None)
        elif len(kept) == 1:
            stack.append(kept[0])
        else:
            stack.append(([v for x in kept for v in x[0]] + [o], [v for x in kept for v in x[1]] + [len(kept)]))
    return stack[-1]


def _evaluate(op: Sequence[int], arg: Sequence[int], inside: Sequence[NDArray[np.bool_]]) -> NDArray[np.bool_]:
    """Membership of the program from the leaves' memberships ``inside[leaf]`` (explicit stack)."""
    stack: list[NDArray[np.bool_]] = []
    for o, a in zip(op, arg):
        if o == OP_LEAF:
            stack.append(inside[a])
            continue
        kids = stack[len(stack) - a :]
        del stack[len(stack) - a :]
        if o == OP_UNION:
            stack.append(np.logical_or.reduce(kids))
        elif o == OP_INTER:
            stack.append(np.logical_and.reduce(kids))
        else:
            out = kids[0].copy()
            for m in kids[1:]:
                out &= ~m
            stack.append(out)
    return stack[-1]


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


#: Leaves up to which a block is resolved by evaluating the tree on every segment at once
#: (memory rays x 2k x k); above it, by a sweep over the sorted events.
DENSE_LEAVES = 24


def _node_arrays(op: Sequence[int], arg: Sequence[int], n_leaves: int) -> tuple[I64, I64, I64, I64, I64, int]:
    """Per instruction of a postfix program: parent, position among the parent's operands,
    opcode and arity; the node of each leaf and the root."""
    n_nodes = len(op)
    parent = np.full(n_nodes, -1, dtype=np.int64)
    pos = np.zeros(n_nodes, dtype=np.int64)
    leaf_node = np.zeros(n_leaves, dtype=np.int64)
    stack: list[int] = []
    for i, (o, a) in enumerate(zip(op, arg)):
        if o == OP_LEAF:
            leaf_node[a] = i
        else:
            kids = stack[len(stack) - a :]
            del stack[len(stack) - a :]
            parent[kids] = i
            pos[kids] = np.arange(a)
        stack.append(i)
    return parent, pos, np.asarray(op, dtype=np.int64), np.asarray(arg, dtype=np.int64), leaf_node, stack[-1]


@njit(cache=True)
def _sweep_kernel(parent, pos, kind, arity, leaf_node, root, order, ts, n_leaves, t_min):  # pragma: no cover - compiled
    n, m = ts.shape
    n_nodes = len(parent)
    seg = np.full(n, -1, dtype=np.int64)
    val = np.zeros(n_nodes, dtype=np.bool_)
    cnt = np.zeros(n_nodes, dtype=np.int64)
    first = np.zeros(n_nodes, dtype=np.bool_)
    for r in range(n):
        val[:] = False
        cnt[:] = 0
        first[:] = False
        for j in range(m - 1):
            lo = ts[r, j]
            if lo == np.inf:
                break
            e = order[r, j]
            node = leaf_node[e % n_leaves]
            new = e < n_leaves
            val[node] = new
            while parent[node] >= 0:
                p = parent[node]
                if kind[p] == 3 and pos[node] == 0:
                    first[p] = new
                elif new:
                    cnt[p] += 1
                else:
                    cnt[p] -= 1
                if kind[p] == 1:
                    v = cnt[p] > 0
                elif kind[p] == 2:
                    v = cnt[p] == arity[p]
                else:
                    v = first[p] and cnt[p] == 0
                if v == val[p]:
                    break
                val[p] = v
                node = p
                new = v
            if val[root] and ts[r, j + 1] > lo and ts[r, j + 1] < np.inf and lo > t_min and lo > -np.inf:
                seg[r] = j
                break
    return seg


def _sweep(op: Sequence[int], arg: Sequence[int], order: I64, ts: F64, n_leaves: int, t_min: float) -> I64:
    """The first segment inside the result for each ray, by a sweep over its sorted events.

    The tree's nodes keep, per ray, how many operands are inside (the first
    operand of a difference apart); each event flips one leaf, and the change
    climbs towards the root only while a node's value changes. After the
    events up to position j the state is the tree's value on the segment
    (ts[j], ts[j + 1]): the same test as :func:`_evaluate` at the segment's
    midpoint, for segments of positive length. Returns the segment index,
    -1 where none is inside.
    """
    parent, pos, kind, arity, leaf_node, root = _node_arrays(op, arg, n_leaves)
    return _sweep_kernel(parent, pos, kind, arity, leaf_node, root, np.ascontiguousarray(order),
                         np.ascontiguousarray(ts), n_leaves, float(t_min))


def _resolve(tree: _Tree, op: Sequence[int], arg: Sequence[int], o: F64, d: F64, t_min: float) -> FirstHit:
    """First hits of a (pruned) program along rays; leaves outside it are empty on these rays."""
    ids = sorted({a for x, a in zip(op, arg) if x == OP_LEAF})
    local = {g: i for i, g in enumerate(ids)}
    lop = list(op)
    larg = [local[a] if x == OP_LEAF else a for x, a in zip(op, arg)]
    n_leaves = len(ids)
    iv = _batch_intervals([tree.leaves[g] for g in ids], o, d)
    n = len(d)
    hit_ = iv.t_in <= iv.t_out
    # misses become empty intervals at +inf so that they sort last
    t_in = np.where(hit_, iv.t_in, np.inf).T
    t_out = np.where(hit_, iv.t_out, np.inf).T
    events = np.concatenate([t_in, t_out], axis=1)  # event e: leaf e % L, side e // L
    order = np.argsort(events, axis=1, kind="stable")
    ts = np.take_along_axis(events, order, axis=1)
    rows = np.arange(n)
    if n_leaves <= DENSE_LEAVES:
        lo, hi = ts[:, :-1], ts[:, 1:]
        with np.errstate(invalid="ignore"):
            mid = 0.5 * (lo + hi)
        inside = [(t_in[:, [i]] < mid) & (mid < t_out[:, [i]]) for i in range(n_leaves)]
        member = _evaluate(lop, larg, inside)
        member &= (hi > lo) & (lo > t_min) & np.isfinite(lo)
        hit = member.any(axis=1)
        k = np.argmax(member, axis=1)
    else:
        seg = _sweep(lop, larg, order, ts, n_leaves, t_min)
        hit = seg >= 0
        k = np.maximum(seg, 0)
    ev = order[rows, k]
    leaf = ev % n_leaves
    side = ev // n_leaves
    t = np.where(hit, ts[rows, k], np.inf)
    n_in = iv.n_in[leaf, rows]
    n_out = iv.n_out[leaf, rows]
    p_in = iv.part_in[leaf, rows]
    p_out = iv.part_out[leaf, rows]
    normal = np.where((side == SIDE_ENTRY)[:, None], n_in, -n_out)
    part = np.where(side == SIDE_ENTRY, p_in, p_out)
    gleaf = np.asarray(ids, dtype=np.int64)[leaf]
    return FirstHit(
        t,
        np.where(hit[:, None], normal, 0.0),
        np.where(hit, gleaf, -1).astype(np.int64),
        np.where(hit, side, -1).astype(np.int64),
        np.where(hit, part, -1).astype(np.int64),
    )


def _empty_hits(n: int) -> FirstHit:
    minus = np.full(n, -1, dtype=np.int64)
    return FirstHit(np.full(n, np.inf), np.zeros((n, 3)), minus, minus.copy(), minus.copy())


def _boxes(tree: _Tree) -> tuple[F64, F64]:
    """Per leaf, a box outside which its membership cannot change the tree's: grown by 1e-9
    (relative) so that the culling stays conservative; ``lo > hi`` where nothing is left.

    Bottom up, every node gets a box holding its set for any membership of the
    leaves inside their boxes (unions: the hull; intersections: the overlap;
    differences: the first operand's). Top down, an operand of an
    intersection only matters inside the overlap of its siblings' boxes (else
    a sibling is empty and so is the intersection), and a subtracted operand
    only inside the first operand's box. A leaf's box is its own bounding box
    cut by those of its ancestors' contexts.
    """
    lo = np.array([leaf.lo for leaf in tree.leaves])
    hi = np.array([leaf.hi for leaf in tree.leaves])
    pad = 1e-9 * (np.max(hi - lo) + np.max(np.abs(np.concatenate([lo, hi])))) + 1e-12
    lo, hi = lo - pad, hi + pad
    op, arg = tree.op, tree.arg
    n_nodes = len(op)
    if n_nodes == 1:
        return lo, hi
    parent, pos, _, _, leaf_node, _ = _node_arrays(op, arg, len(tree.leaves))
    blo = np.empty((n_nodes, 3))
    bhi = np.empty((n_nodes, 3))
    kids: list[list[int]] = [[] for _ in range(n_nodes)]
    for i in range(n_nodes):
        if parent[i] >= 0:
            kids[parent[i]].append(i)
    for i, (o, a) in enumerate(zip(op, arg)):  # postfix: children come first
        if o == OP_LEAF:
            blo[i], bhi[i] = lo[a], hi[a]
            continue
        c = kids[i]
        if o == OP_UNION:
            blo[i], bhi[i] = blo[c].min(axis=0), bhi[c].max(axis=0)
        elif o == OP_INTER:
            blo[i], bhi[i] = blo[c].max(axis=0), bhi[c].min(axis=0)
        else:
            blo[i], bhi[i] = blo[c[0]], bhi[c[0]]
    clo = np.full((n_nodes, 3), -np.inf)
    chi = np.full((n_nodes, 3), np.inf)
    for i in range(n_nodes - 1, -1, -1):  # parents come after their children
        o = op[i]
        if o == OP_LEAF:
            continue
        c = kids[i]
        if o == OP_INTER:
            elo, ehi = np.maximum(clo[i], blo[c].max(axis=0)), np.minimum(chi[i], bhi[c].min(axis=0))
            clo[c], chi[c] = elo, ehi
        elif o == OP_DIFF:
            clo[c], chi[c] = clo[i], chi[i]
            clo[c[1:]] = np.maximum(clo[i], blo[c[0]])
            chi[c[1:]] = np.minimum(chi[i], bhi[c[0]])
        else:
            clo[c], chi[c] = clo[i], chi[i]
    return np.maximum(lo, clo[leaf_node]), np.minimum(hi, chi[leaf_node])


#: Ray-leaf pairs resolved together (the intervals keep 10 numbers per pair) and computed
#: together (dozens of temporaries per pair).
BLOCK_CELLS = 1 << 20
CHUNK_CELLS = 1 << 16


def first_hit(solid: Any, origins: Any, directions: Any, *, t_min: float = 0.0) -> FirstHit:
    """First visible point of a primitive or CSG tree along rays, by interval arithmetic.

    All entry and exit parameters of the leaves are sorted along each ray; the
    tree is evaluated at the midpoint of every segment of positive length
    between consecutive events (open intervals, so touching boundaries count
    as outside: regularised operations). The visible point is the start of
    the first such segment inside the result that starts beyond ``t_min``.

    Rays go in blocks; a leaf whose bounding box no ray of a block meets (slab
    test) is the empty set on those rays, and the tree is pruned accordingly.
    """
    o = np.atleast_2d(np.asarray(origins, dtype=np.float64))
    d = np.atleast_2d(np.asarray(directions, dtype=np.float64))
    o = np.ascontiguousarray(np.broadcast_to(o, d.shape) if len(o) == 1 else o)
    tree = read_tree(solid)
    lo, hi = _boxes(tree)
    n = len(d)
    out = _empty_hits(n)
    block = max(1, min(1024, BLOCK_CELLS // max(1, len(tree.leaves))))
    for s in range(0, n, block):
        ob, db = o[s : s + block], d[s : s + block]
        present = _slab_test(lo, hi, ob, db) & ~np.any(lo > hi, axis=1)
        pruned = _prune(tree.op, tree.arg, present)
        if pruned is None:
            continue
        fh = _resolve_limited(tree, *pruned, ob, db, t_min)
        for name in ("t", "normal", "leaf", "side", "part"):
            getattr(out, name)[s : s + block] = getattr(fh, name)
    return out


def _resolve_limited(tree: _Tree, op: Sequence[int], arg: Sequence[int], o: F64, d: F64, t_min: float) -> FirstHit:
    """:func:`_resolve` in chunks of rays small enough for the leaves present."""
    k = sum(1 for x in op if x == OP_LEAF)
    step = max(1, BLOCK_CELLS // max(1, k))
    if len(d) <= step:
        return _resolve(tree, op, arg, o, d, t_min)
    out = _empty_hits(len(d))
    for s in range(0, len(d), step):
        fh = _resolve(tree, op, arg, o[s : s + step], d[s : s + step], t_min)
        for name in ("t", "normal", "leaf", "side", "part"):
            getattr(out, name)[s : s + step] = getattr(fh, name)
    return out


def _slab_test(lo: F64, hi: F64, o: F64, d: F64) -> NDArray[np.bool_]:
    """Leaves whose box some ray meets at t >= 0 (slab test, conservative at the boundary)."""
    present = np.zeros(len(lo), dtype=bool)
    step = max(1, (1 << 22) // max(1, len(o)))
    for s in range(0, len(lo), step):
        blo, bhi = lo[s : s + step, None, :], hi[s : s + step, None, :]
        with np.errstate(divide="ignore", invalid="ignore"):
            inv = 1.0 / d[None, :, :]
            t1 = (blo - o[None]) * inv
            t2 = (bhi - o[None]) * inv
        # a ray parallel to a slab: inside it for every t, or never
        par = d[None, :, :] == 0
        inside_slab = (o[None] >= blo) & (o[None] <= bhi)
        t_lo = np.where(par, np.where(inside_slab, -np.inf, np.inf), np.minimum(t1, t2))
        t_hi = np.where(par, np.where(inside_slab, np.inf, -np.inf), np.maximum(t1, t2))
        enter = t_lo.max(axis=2)
        leave = t_hi.min(axis=2)
        span = np.maximum(np.abs(enter), np.abs(leave))
        slack = 1e-9 * np.where(np.isfinite(span), span, 0.0)
        present[s : s + step] = np.any((enter <= leave + slack) & (leave >= -slack), axis=1)
    return present


# ----------------------------------------------------------------------------- camera tiles


def _corners(lo: F64, hi: F64) -> F64:
    """The 8 corners of each box, shape (k, 8, 3)."""
    sel = np.array([[i & 1, (i >> 1) & 1, (i >> 2) & 1] for i in range(8)], dtype=bool)
    return np.where(sel[None, :, :], hi[:, None, :], lo[:, None, :])


def _pixel_coords(camera: Camera) -> tuple[F64, F64, F64, F64, F64, F64]:
    """Camera frame (f, r, u), eye, and the pixel centres' image-plane coordinates x_j, y_i."""
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
    return eye, f, r, u, x, y


#: Largest tile resolved at once, and the fixed cost of a tile in ray-leaf pairs.
TILE_RAYS = 4096
TILE_OVERHEAD = 3000


def _tile_hits(camera: Camera, solid: Any, o: F64, d: F64, *, t_min: float = 0.0) -> FirstHit:
    """:func:`first_hit` for every pixel of a camera, by screen tiles.

    A tile's rays leave the eye inside the pyramid spanned by its corner
    pixels' rays: ``x_min <= X/Z <= x_max``, ``y_min <= Y/Z <= y_max``,
    ``Z >= 0`` in the camera frame; for an orthographic camera (parallel rays
    from the image plane) inside the slab ``x_min <= X <= x_max``,
    ``y_min <= Y <= y_max``, ``Z >= 0``. A leaf whose bounding box lies entirely
    outside one of those half-spaces is met by no ray of the tile at t >= 0,
    so it is the empty set there (what it does behind the eye changes no
    segment beyond ``t_min >= 0``) and the tree is pruned accordingly. Tiles
    are split in four while that leaves fewer leaves per tile.
    """
    h, w = int(camera.height), int(camera.width)
    tree = read_tree(solid)
    lo, hi = _boxes(tree)
    eye, f, r, u, xs, ys = _pixel_coords(camera)
    rel = _corners(lo, hi) - eye
    X, Y, Z = rel @ r, rel @ u, rel @ f  # (L, 8) camera coordinates of the corners
    void = np.any(lo > hi, axis=1)  # leaves that cannot change the tree anywhere
    slack = 1e-9 * (abs(xs).max() + abs(ys).max() + 1.0)
    out_t = np.full((h, w), np.inf)
    out_n = np.zeros((h, w, 3))
    out_leaf = np.full((h, w), -1, dtype=np.int64)
    out_side = np.full((h, w), -1, dtype=np.int64)
    out_part = np.full((h, w), -1, dtype=np.int64)
    o2, d2 = o.reshape(h, w, 3), d.reshape(h, w, 3)

    def cull(i0: int, i1: int, j0: int, j1: int, ids: I64) -> I64:
        x0, x1 = xs[j0] - slack, xs[j1 - 1] + slack
        y0, y1 = ys[i1 - 1] - slack, ys[i0] + slack
        Xs, Ys, Zs = X[ids], Y[ids], Z[ids]
        if camera.orthographic:  # parallel rays: the bounds do not scale with depth
            Zs = np.ones_like(Zs) * np.where(np.all(Z[ids] < 0, axis=1), -1.0, 1.0)[:, None]
        out = (
            np.all(Xs > x1 * Zs, axis=1) | np.all(Xs < x0 * Zs, axis=1)
            | np.all(Ys > y1 * Zs, axis=1) | np.all(Ys < y0 * Zs, axis=1) | np.all(Zs < 0, axis=1) | void[ids]
        )
        return ids[~out]

    present = np.zeros(len(tree.leaves), dtype=bool)

    def prune(op: Sequence[int], arg: Sequence[int], ids: I64) -> tuple[list[int], list[int]] | None:
        present[ids] = True
        try:
            return _prune(op, arg, present)
        finally:
            present[ids] = False

    # each tile: its pixel rectangle and its parent's pruned program (leaf arguments are global)
    todo: list[tuple[int, int, int, int, Sequence[int], Sequence[int]]] = [(0, h, 0, w, tree.op, tree.arg)]
    while todo:
        i0, i1, j0, j1, op, arg = todo.pop()
        ids = np.asarray(sorted({a for x, a in zip(op, arg) if x == OP_LEAF}), dtype=np.int64)
        ids = cull(i0, i1, j0, j1, ids)
        pruned = prune(op, arg, ids)
        if pruned is None:
            continue
        ids = np.asarray(sorted({a for x, a in zip(*pruned) if x == OP_LEAF}), dtype=np.int64)
        k, n = len(ids), (i1 - i0) * (j1 - j0)
        if n > 1 and (n > TILE_RAYS or n * k > TILE_OVERHEAD):
            # split in four (or two) when the tile is large or the split saves work
            # (ray-leaf pairs, plus a fixed cost per tile)
            im, jm = (i0 + i1) // 2, (j0 + j1) // 2
            kids = [(a, b, c, e) for a, b in ((i0, im), (im, i1)) for c, e in ((j0, jm), (jm, j1)) if b > a and e > c]
            cost = sum(TILE_OVERHEAD + (q[1] - q[0]) * (q[3] - q[2]) * len(cull(*q, ids)) for q in kids)
            if n > TILE_RAYS or cost < TILE_OVERHEAD + n * k:
                todo.extend((*q, *pruned) for q in kids)
                continue
        ob = o2[i0:i1, j0:j1].reshape(-1, 3)
        db = d2[i0:i1, j0:j1].reshape(-1, 3)
        fh = _resolve_limited(tree, *pruned, ob, db, t_min)
        out_t[i0:i1, j0:j1] = fh.t.reshape(i1 - i0, j1 - j0)
        out_n[i0:i1, j0:j1] = fh.normal.reshape(i1 - i0, j1 - j0, 3)
        out_leaf[i0:i1, j0:j1] = fh.leaf.reshape(i1 - i0, j1 - j0)
        out_side[i0:i1, j0:j1] = fh.side.reshape(i1 - i0, j1 - j0)
        out_part[i0:i1, j0:j1] = fh.part.reshape(i1 - i0, j1 - j0)
    return FirstHit(out_t.reshape(-1), out_n.reshape(-1, 3), out_leaf.reshape(-1), out_side.reshape(-1), out_part.reshape(-1))


# ----------------------------------------------------------------------------- shading


def shade_points(points: F64, normals: F64, eye: F64, lights: Sequence[Any], material: Material) -> F64:
    """``ambient + sum intensity (kd max(0, n.l) + [n.l > 0] ks max(0, rf.v)^shininess)``.

    ``n.l`` within the rounding of the hit point counts as 0 (grazing, no highlight): on a
    face whose plane holds a point light the exact ``n.l`` is 0, but a hit point a few ulps off
    the plane gives ``+-1e-16`` and, where positive, the full grazing highlight ``(-l.v)^s``
    at random pixels.
    """
    p = np.asarray(points, dtype=np.float64)
    nrm = _normalize(np.asarray(normals, dtype=np.float64))
    e = np.asarray(eye, dtype=np.float64)
    v = _normalize(e - p)
    out = np.full(len(p), float(material.ambient))
    eps = 64.0 * np.finfo(np.float64).eps
    for light in lights:
        if isinstance(light, PointLight):
            pos = np.asarray(light.position, dtype=np.float64)
            d = pos - p
            dist = np.linalg.norm(d, axis=-1)
            l = _normalize(d)
            # the hit point is off by about eps times the largest coordinate involved
            size = np.maximum(np.maximum(np.linalg.norm(p, axis=-1), np.linalg.norm(e)), np.linalg.norm(pos))
            grazing = eps * (1.0 + size / np.maximum(dist, 1e-300))
        elif isinstance(light, DirectionalLight):
            dl = np.asarray(light.direction, dtype=np.float64)
            l = np.broadcast_to(dl / np.linalg.norm(dl), p.shape)
            grazing = np.full(len(p), eps)
        else:
            raise TypeError(f"unsupported light {type(light).__name__}")
        ndl = _dot(nrm, l)
        # The highlight jumps at the terminator: a cosine within rounding of 0 is not lit
        # (a cylinder's side under a light along its axis has n . l = 0 exactly; far from the
        # origin the hit point's own rounding can exceed TERMINATOR_COSINE).
        lit = ndl > np.maximum(TERMINATOR_COSINE, grazing)
        term = material.kd * np.where(lit, ndl, 0.0)
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
        fh = _tile_hits(camera, solid, o, d)
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
