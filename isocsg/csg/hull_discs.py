"""The convex hull of parallel discs of any radii (cylinders, cones and frusta on parallel axes,
and polytopes' corners as discs of radius 0), split exactly into kinds.

Let the discs ``D_k`` (centre ``p_k``, radius ``r_k >= 0``) lie in planes across one unit axis
``a``; ``P`` projects on the plane across ``a``. The support function of ``D_k`` is
``p_k . u + r_k |P u|``: written for directions ``n = m + t a`` with ``|m| = 1`` (every direction
but ``+-a``) it is ``p_k . n + r_k``, the support of a ball of radius ``r_k``, so
:mod:`isocsg.csg.hull_balls`'s argument carries over with the tie *curves* ``|m| = 1``,
``(p_j - p_i) . n = r_i - r_j`` (closed when the discs lie in different planes):

- a boundary point with a normal ``n`` where two discs tie lies on the segment between their
  rims' points ``p + r m``, in ``hull(D_i u D_j)``, which is the frustum of the discs
  interpolated linearly (an oblique :class:`~isocsg.EllipticTruncus`, a
  :class:`~isocsg.Truncus` when ``p_j - p_i`` is along ``a``; a cylinder's lateral surface is
  that of its own two ends), and its segment to ``(1 - s) p_i + s p_j`` stays there;
- a plane tangent to three discs: its tangent points ``p_k + r_k m`` go into the polyhedron;
- the faces across ``a`` (normal ``+-a``) are the 2D hulls of the discs in the top and bottom
  planes: the polygon of their centres and 2D tangent points (in the polyhedron) plus the discs
  (on the boundary, so no interior point lies on their segments to the centres).

So ``hull = Q u F_ij (edges between planes)`` with ``Q`` the convex polyhedron of the centres,
the tangent points of the triple planes and those of the 2D outer tangents of every two discs in
one plane. Edges are found as for balls: the pairs of the faces, and the pairs where one
arbitrary point of their tie curve supports.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidGeometryError, NotExactError, ResourceLimitError
from ..kinds import Cylinder, EllipticTruncus, Primitive, Truncus
from .hull_balls import MAX_HULL_WORK, TIE_TOLERANCE
from .hull_grow import polytope

__all__ = ["parallel_disc_hull"]

_TRIPLE_CHUNK = 8192


def _frame(axis: NDArray[np.float64]) -> NDArray[np.float64]:
    helper = np.eye(3)[int(np.argmin(np.abs(axis)))]
    u = np.cross(axis, helper)
    u /= np.linalg.norm(u)
    return np.column_stack([u, np.cross(axis, u)])


def _triple_points(p: NDArray[np.float64], r: NDArray[np.float64], a: NDArray[np.float64], tol: float,
                   ) -> tuple[NDArray[np.int64], NDArray[np.float64]]:
    """Planes tangent to three discs with every disc on one side: the triples and the unit 2D
    directions ``m`` (3D vectors across ``a``) of their tangent points ``p_k + r_k m``."""
    n, balls = len(r), int(np.count_nonzero(r > 0))
    rows = []
    for i in range(balls):  # discs of radius > 0 come first: three points add no tangent point
        j, k = np.triu_indices(n - i - 1, 1)
        rows.append(np.column_stack([np.full(len(j), i), j + i + 1, k + i + 1]))
    t = np.concatenate(rows) if rows else np.zeros((0, 3), dtype=np.int64)
    if len(t) * n > MAX_HULL_WORK:
        raise ResourceLimitError(
            f"hull: {len(t)} triples of discs to test, over MAX_HULL_WORK = {MAX_HULL_WORK:g} / {n}"
        )
    out_t: list[NDArray[np.int64]] = [np.zeros((0, 3), dtype=np.int64)]
    out_m: list[NDArray[np.float64]] = [np.zeros((0, 3))]
    for start in range(0, len(t), _TRIPLE_CHUNK):  # bounded memory: a chunk's reaches at a time
        got_t, got_m = _chunk_planes(p, r, a, tol, t[start:start + _TRIPLE_CHUNK])
        out_t.extend(got_t)
        out_m.extend(got_m)
    return np.concatenate(out_t), np.concatenate(out_m)


def _chunk_planes(p: NDArray[np.float64], r: NDArray[np.float64], a: NDArray[np.float64], tol: float,
                  t: NDArray[np.int64]) -> tuple[list[NDArray[np.int64]], list[NDArray[np.float64]]]:
    """The supporting tangent planes of the triples ``t`` (see :func:`_triple_points`)."""
    e1, e2 = p[t[:, 1]] - p[t[:, 0]], p[t[:, 2]] - p[t[:, 0]]
    g1, g2 = r[t[:, 0]] - r[t[:, 1]], r[t[:, 0]] - r[t[:, 2]]
    d = np.cross(e1, e2)
    aa, ab, bb = (np.einsum("ij,ij->i", x, y) for x, y in ((e1, e1), (e1, e2), (e2, e2)))
    det = aa * bb - ab * ab
    ok = det > 1e-20 * aa * bb
    det = np.where(ok, det, 1.0)
    n0 = ((bb * g1 - ab * g2) / det)[:, None] * e1 + ((aa * g2 - ab * g1) / det)[:, None] * e2
    pa, pd = n0 - np.outer(n0 @ a, a), d - np.outer(d @ a, a)  # |P(n0 + lam d)| = 1
    qa, qb, qc = np.einsum("ij,ij->i", pd, pd), np.einsum("ij,ij->i", pa, pd), np.einsum("ij,ij->i", pa, pa) - 1.0
    ok &= qa > 1e-20 * np.einsum("ij,ij->i", d, d)  # three discs in one plane across a: no such plane
    disc = qb * qb - qa * qc
    ok &= disc >= 0
    qa = np.where(ok, qa, 1.0)
    out_t: list[NDArray[np.int64]] = []
    out_m: list[NDArray[np.float64]] = []
    for sign in (1.0, -1.0):
        lam = (-qb + sign * np.sqrt(np.clip(disc, 0.0, None))) / qa
        normal = n0 + lam[:, None] * d
        reach = normal @ p.T + r[None, :]
        own = reach[np.arange(len(t))[:, None], t].max(axis=1)
        keep = ok & (reach.max(axis=1) <= own + tol * np.linalg.norm(normal, axis=1))
        m = normal - np.outer(normal @ a, a)
        out_t.append(t[keep])
        out_m.append(m[keep] / np.linalg.norm(m[keep], axis=1)[:, None])
    return out_t, out_m


def _level_points(p: NDArray[np.float64], r: NDArray[np.float64], a: NDArray[np.float64], tol: float,
                  ) -> list[NDArray[np.float64]]:
    """The 2D outer tangent points of every two discs in one plane across ``a``."""
    out = []
    for i, j in itertools.combinations(range(len(r)), 2):
        w = p[j] - p[i]
        if abs(float(w @ a)) > tol or max(r[i], r[j]) == 0.0:
            continue
        w = w - (w @ a) * a
        dist = float(np.linalg.norm(w))
        if dist == 0.0 or abs(r[i] - r[j]) >= dist:
            continue
        nu, e, q = (r[i] - r[j]) / dist, w / dist, np.cross(a, w) / dist
        for sign in (1.0, -1.0):
            m = nu * e + sign * math.sqrt(1.0 - nu * nu) * q
            out.extend([p[i] + r[i] * m, p[j] + r[j] * m])
    return out


def _frustum(pi: NDArray[np.float64], ri: float, pj: NDArray[np.float64], rj: float,
             a: NDArray[np.float64]) -> Primitive:
    """``hull(D_i u D_j)`` of two discs in different planes across ``a``."""
    w = pi - pj
    if np.linalg.norm(w - (w @ a) * a) <= 1e-12 * np.linalg.norm(w):
        return Cylinder((pi + pj) / 2, w, ri) if ri == rj else Truncus((pi + pj) / 2, w, ri, rj)
    try:
        return EllipticTruncus((pi + pj) / 2, np.column_stack([_frame(a), w]), ri, rj)
    except InvalidGeometryError as err:
        raise NotExactError(
            f"hull: the hull of two discs is an oblique frustum too sheared for EllipticTruncus ({err})"
        ) from err


def parallel_disc_hull(centres: NDArray[np.float64], radii: NDArray[np.float64], axis: NDArray[np.float64],
                       ) -> list[Primitive]:
    """The hull of discs across the unit ``axis`` (radius 0: a point) as pieces whose union it is.

    Examples
    --------
    >>> import numpy as np
    >>> ends = np.array([[0.0, 0, 0], [0, 0, 2], [5, 0, 0], [5, 0, 5]])  # two cylinders' ends
    >>> parts = parallel_disc_hull(ends, np.array([2.0, 2, 1, 1]), np.array([0.0, 0, 1]))
    >>> sorted({type(q).__name__ for q in parts})
    ['ConvexPolyhedron', 'Cylinder', 'EllipticTruncus']
    """
    a = np.asarray(axis, dtype=np.float64) / np.linalg.norm(axis)
    p = np.asarray(centres, dtype=np.float64).reshape(-1, 3)
    r = np.asarray(radii, dtype=np.float64).reshape(-1)
    order = np.argsort(r == 0, kind="stable")  # discs first
    p, r = p[order], r[order]
    scale = float(np.ptp(p, axis=0).max() + r.max())
    tol = TIE_TOLERANCE * scale
    triples, dirs = _triple_points(p, r, a, tol)
    pairs = {(int(f[x]), int(f[y])) for f in triples for x, y in ((0, 1), (0, 2), (1, 2))}
    frame = _frame(a)
    discs = int(np.count_nonzero(r > 0))
    for i, j in ((b, c) for b in range(discs) for c in range(b + 1, len(r))):
        w = p[j] - p[i]
        wa = float(w @ a)
        if (i, j) in pairs or abs(wa) <= tol:
            continue
        m = frame[:, 0]
        n = m + (r[i] - r[j] - float(w @ m)) / wa * a  # a point of the tie curve
        reach = p @ n + r
        if reach.max() <= reach[i] + tol * np.linalg.norm(n):
            pairs.add((i, j))
    touch = (p[triples] + r[triples][..., None] * dirs[:, None, :]).reshape(-1, 3)
    core = polytope(np.vstack([p, touch, *_level_points(p, r, a, tol)]))
    pieces: list[Primitive] = [core.solid] if core.solid is not None else []
    for i, j in sorted(pairs):
        if abs(float((p[j] - p[i]) @ a)) > tol and max(r[i], r[j]) > 0:
            pieces.append(_frustum(p[i], float(r[i]), p[j], float(r[j]), a))
    return pieces
