"""The convex hull of balls of any radii (points are balls of radius 0), split exactly into kinds.

Let ``H`` be the hull of balls ``B_k = B(c_k, r_k)``, ``r_k >= 0``. Its support function is
``h(u) = max_k (c_k . u + r_k)``; its boundary is made of

- sphere patches (one ball alone reaches ``h(u)``),
- conical patches along *edges*: the boundary of ``hull(B_i u B_j)``, the frustum ``F_ij`` between
  the circles where the two balls touch their common tangent cone (a cone when one radius is 0,
  a cylinder when the radii are equal), where ``i`` and ``j`` tie at the maximum,
- planar *faces*: a plane tangent to three (or more) balls with every ball on one side; the face
  is the hull of its tangent points ``c_k + r_k n``.

**The split.** ``H = P u F_ij (edges) u B_k``, with ``P`` the convex polyhedron of all the centres
and all the faces' tangent points. Every piece is the hull of points or balls of ``H``, so lies
in ``H``. Conversely, join each boundary point to a *core* point, a convex combination of
centres: on ball ``k``, ``c_k + r_k u -> c_k`` (inside ``B_k``); on an edge,
``(1 - s)(c_i + r_i u) + s (c_j + r_j u) -> (1 - s) c_i + s c_j`` (inside ``hull(B_i u B_j) =
B_i u B_j u F_ij``); on a face, ``sum w_k (c_k + r_k n) -> sum w_k c_k`` (inside ``P``). The map
agrees where patches meet, so it is a homotopy from the boundary (``lambda = 1``) to a surface in
the hull of the centres (``lambda = 0``) through the union ``U`` of the pieces. A point ``x`` of
``H`` outside the hull of the centres and off ``U`` would be avoided by the whole homotopy: the
boundary's winding number about ``x`` (1) would equal that of a surface inside a convex set not
holding ``x`` (0). So ``U = H``.

**Which edges and faces.** The faces come from every triple of balls: the two planes tangent to
all three, kept when no ball passes beyond them. A pair is an edge when its tie circle (the
directions where ``i`` and ``j`` reach equally far) holds a direction where no ball passes them:
the set of such directions is an intersection of arcs of that circle, so when it is neither
empty nor the whole circle one of its ends is a direction where a third ball ties, a face. The
pairs of the faces and the pairs where one arbitrary point of the circle supports are therefore
all the edges. Both tests keep near ties (to ``TIE_TOLERANCE``): an extra face or edge adds
points or frusta of ``H`` itself, never anything outside it.

Left out, bounded: a frustum shorter than ``MIN_ASPECT`` times its radius or thinner than
``MIN_ASPECT`` times its length (the kinds refuse it). The first lies between two nearly
internally tangent balls and leaves at most a sliver of thickness below ``MIN_ASPECT`` times the
radius uncovered; the second is a needle of radius below ``MIN_ASPECT`` times its length.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidGeometryError, ResourceLimitError
from ..kinds import Cylinder, Primitive, Sphere, Truncus
from .hull_grow import polytope

__all__ = ["ball_hull", "disc_hull_prism", "upper_disc_hull", "MAX_HULL_WORK", "TIE_TOLERANCE"]

#: The most work (triples of balls times balls) a hull may take: its faces are found over every
#: triple holding a ball, so ``m`` balls and ``p`` corners cost about ``m p^3 / 2``.
MAX_HULL_WORK = 2e8
#: Supports within this fraction of the balls' extent count as ties (extra pieces are harmless).
TIE_TOLERANCE = 1e-8
_TRIPLE_CHUNK = 8192


def _outermost(c: NDArray[np.float64], r: NDArray[np.float64]) -> NDArray[np.bool_]:
    """Balls and points not inside another ball (of equal balls, the first); points are taken as
    distinct (the corners of a polytope)."""
    balls = np.nonzero(r > 0)[0]
    gap = np.linalg.norm(c[:, None] - c[None, balls], axis=-1)
    inside = gap + r[:, None] <= r[None, balls]
    inside[balls, np.arange(len(balls))] = False
    same = inside[balls] & inside[balls].T  # equal balls: the later one is inside the earlier
    inside[balls] &= ~(same & (balls[:, None] < balls[None, :]))
    return ~inside.any(axis=1)  # type: ignore[no-any-return]


def _triples(r: NDArray[np.float64]) -> NDArray[np.int64]:
    """Every triple ``i < j < k`` holding a ball of radius > 0 (balls come first in ``r``): the
    planes through three points add no tangent point the centres do not give."""
    n, m = len(r), int(np.count_nonzero(r > 0))
    out = []
    for i in range(m):
        j, k = np.triu_indices(n - i - 1, 1)
        out.append(np.column_stack([np.full(len(j), i), j + i + 1, k + i + 1]))
    return np.concatenate(out) if out else np.zeros((0, 3), dtype=np.int64)


def _faces(c: NDArray[np.float64], r: NDArray[np.float64], tol: float) -> tuple[NDArray[np.int64], NDArray[np.float64]]:
    """The supporting planes tangent to three balls: the triples ``(m, 3)`` and unit normals ``(m, 3)``."""
    triples = _triples(r)
    if len(triples) * len(r) > MAX_HULL_WORK:
        raise ResourceLimitError(
            f"hull: {int(np.count_nonzero(r > 0))} balls and {int(np.count_nonzero(r == 0))} corners make "
            f"{len(triples)} triples of planes to test, over MAX_HULL_WORK = {MAX_HULL_WORK:g} / {len(r)}"
        )
    out_t: list[NDArray[np.int64]] = []
    out_n: list[NDArray[np.float64]] = []
    for start in range(0, len(triples), _TRIPLE_CHUNK):
        t = triples[start:start + _TRIPLE_CHUNK]
        a, b = c[t[:, 1]] - c[t[:, 0]], c[t[:, 2]] - c[t[:, 0]]
        ra, rb = r[t[:, 0]] - r[t[:, 1]], r[t[:, 0]] - r[t[:, 2]]
        m = np.cross(a, b)
        det = np.einsum("ij,ij->i", m, m)  # |a|^2 |b|^2 - (a.b)^2
        scale = np.einsum("ij,ij->i", a, a) * np.einsum("ij,ij->i", b, b)
        ok = det > 1e-20 * scale  # centres on one line: no single tangent plane
        aa, ab, bb = (np.einsum("ij,ij->i", x, y) for x, y in ((a, a), (a, b), (b, b)))
        d = np.where(ok, det, 1.0)
        la, lb = (bb * ra - ab * rb) / d, (aa * rb - ab * ra) / d  # least-norm solution of a.n = ra, b.n = rb
        n0 = la[:, None] * a + lb[:, None] * b
        s2 = 1.0 - np.einsum("ij,ij->i", n0, n0)
        ok &= s2 >= -1e-12  # otherwise no plane touches all three (one is inside the others' cone)
        off = np.sqrt(np.clip(s2, 0.0, None))[:, None] * m / np.sqrt(d)[:, None]
        for sign in (1.0, -1.0):
            normal = n0 + sign * off
            length = np.linalg.norm(normal, axis=1)
            normal /= np.where(ok & (length > 0), length, 1.0)[:, None]
            reach = normal @ c.T + r[None, :]
            own = reach[np.arange(len(t))[:, None], t].max(axis=1)
            keep = ok & (reach.max(axis=1) <= own + tol)
            out_t.append(t[keep])
            out_n.append(normal[keep])
    if not out_t:
        return np.zeros((0, 3), dtype=np.int64), np.zeros((0, 3))
    return np.concatenate(out_t), np.concatenate(out_n)


def _edges(
    c: NDArray[np.float64], r: NDArray[np.float64], faces: NDArray[np.int64], tol: float,
) -> list[tuple[int, int]]:
    """The pairs whose tangent cone bounds the hull (see the module's docstring)."""
    pairs = {(int(f[i]), int(f[j])) for f in faces for i, j in ((0, 1), (0, 2), (1, 2))}
    balls = int(np.count_nonzero(r > 0))  # balls come first; two points make no frustum
    for i, j in ((a, b) for a in range(balls) for b in range(a + 1, len(r))):
        if (i, j) in pairs:
            continue
        w = c[j] - c[i]
        dist = float(np.linalg.norm(w))
        e = w / dist
        nu = (r[i] - r[j]) / dist  # u . e on the tie circle
        if abs(nu) >= 1.0:
            continue
        helper = np.eye(3)[int(np.argmin(np.abs(e)))]
        p = np.cross(e, helper)
        u = nu * e + math.sqrt(1.0 - nu * nu) * p / np.linalg.norm(p)
        reach = c @ u + r
        if reach.max() <= reach[i] + tol:
            pairs.add((i, j))
    return sorted(pairs)


def _frustum(ci: NDArray[np.float64], ri: float, cj: NDArray[np.float64], rj: float) -> Primitive | None:
    """``hull(B_i u B_j)`` minus the balls: the frustum between the circles where the common
    tangent cone touches them; None when it has no volume or is too thin a kind (bounded sliver)."""
    w = cj - ci
    dist = float(np.linalg.norm(w))
    e = w / dist
    nu = (ri - rj) / dist
    if abs(nu) >= 1.0 or max(ri, rj) == 0.0:
        return None
    nr = math.sqrt(1.0 - nu * nu)
    ei, ej = ci + ri * nu * e, cj + rj * nu * e  # the cone's normals nu e + nr p tilt toward the smaller ball
    try:
        if ri == rj:
            return Cylinder((ei + ej) / 2, ei - ej, ri)
        return Truncus((ei + ej) / 2, ei - ej, ri * nr, rj * nr)
    except InvalidGeometryError:
        return None


def ball_hull(centres: NDArray[np.float64], radii: NDArray[np.float64]) -> list[Primitive]:
    """The hull of balls ``B(centres[k], radii[k])`` (radius 0: a point) as pieces whose union it is.

    Parameters
    ----------
    centres : ndarray, shape (n, 3)
    radii : ndarray, shape (n,)
        Non-negative.

    Returns
    -------
    list of Primitive
        The convex polyhedron of the centres and the faces' tangent points (when it has volume),
        the frusta (or cones, cylinders) of the edges and the balls of radius > 0 on the hull.

    Raises
    ------
    ResourceLimitError
        When the faces' search would pass :data:`MAX_HULL_WORK`.

    Examples
    --------
    >>> import numpy as np
    >>> parts = ball_hull(np.array([[0.0, 0, 0], [3, 0, 0], [0, 2, 0]]), np.array([1.0, 0.5, 0.3]))
    >>> sorted(type(p).__name__ for p in parts)
    ['ConvexPolyhedron', 'Sphere', 'Sphere', 'Sphere', 'Truncus', 'Truncus', 'Truncus']
    """
    c = np.asarray(centres, dtype=np.float64).reshape(-1, 3)
    r = np.asarray(radii, dtype=np.float64).reshape(-1)
    keep = _outermost(c, r)
    order = np.argsort(r[keep] == 0, kind="stable")  # balls first
    c, r = c[keep][order], r[keep][order]
    if len(r) == 1:
        return [Sphere(c[0], float(r[0]))] if r[0] > 0 else []
    tol = TIE_TOLERANCE * float(np.ptp(c, axis=0).max() + r.max())
    triples, normals = _faces(c, r, tol)
    pairs = _edges(c, r, triples, tol)
    touch = (c[triples] + r[triples][..., None] * normals[:, None, :]).reshape(-1, 3)
    pieces: list[Primitive] = []
    core = polytope(np.vstack([c, touch]))
    if core.solid is not None:
        pieces.append(core.solid)
    used: set[int] = set()
    for i, j in pairs:
        used.update((i, j))
        piece = _frustum(c[i], float(r[i]), c[j], float(r[j]))
        if piece is not None:
            pieces.append(piece)
    pieces.extend(Sphere(c[k], float(r[k])) for k in sorted(used) if r[k] > 0)
    return pieces


def disc_hull_prism(
    centres: NDArray[np.float64], radii: NDArray[np.float64], frame: NDArray[np.float64], bottom: float, top: float,
) -> list[Primitive]:
    """The hull of parallel cylinders of any radii between the same two planes: the prism over
    the 2D hull of their discs, which is the polygon of the centres and the tangent points of
    the supporting lines plus the discs (the plane case of :func:`ball_hull`: edges are segments
    of the polygon, and no edge needs a frustum).

    ``centres`` are the discs' 2D centres in ``frame`` (3x3: two in-plane unit columns and the
    unit axis), ``bottom`` and ``top`` the planes' heights along the axis.
    """
    c2 = np.asarray(centres, dtype=np.float64).reshape(-1, 2)
    r = np.asarray(radii, dtype=np.float64).reshape(-1)
    keep = _outermost(np.column_stack([c2, np.zeros(len(r))]), r)
    c2, r = c2[keep], r[keep]
    tol = TIE_TOLERANCE * float(np.ptp(c2, axis=0).max() + r.max())
    touch: list[NDArray[np.float64]] = []
    used: set[int] = {0} if len(r) == 1 else set()
    for i, j in itertools.combinations(range(len(r)), 2):
        w = c2[j] - c2[i]
        dist = float(np.linalg.norm(w))
        nu = (r[i] - r[j]) / dist
        if abs(nu) >= 1.0:
            continue
        e, p = w / dist, np.array([-w[1], w[0]]) / dist
        for sign in (1.0, -1.0):
            u = nu * e + sign * math.sqrt(1.0 - nu * nu) * p
            reach = c2 @ u + r
            if reach.max() <= reach[i] + tol:
                used.update((i, j))
                touch.extend([c2[i] + r[i] * u, c2[j] + r[j] * u])
    flat = np.vstack([c2, *touch]) if touch else c2
    base = frame[:, :2] @ flat.T
    pieces: list[Primitive] = []
    axis = frame[:, 2]
    if len(flat) >= 3:
        ring = np.vstack([(base + bottom * axis[:, None]).T, (base + top * axis[:, None]).T])
        q = polytope(ring)
        if q.solid is not None:
            pieces.append(q.solid)
    mid, height = (bottom + top) / 2, top - bottom
    for k in sorted(used):
        centre = frame[:, :2] @ c2[k] + mid * axis
        pieces.append(Cylinder(centre, height * axis, float(r[k])))
    return pieces


def upper_disc_hull(
    points: NDArray[np.float64], radii: NDArray[np.float64],
) -> tuple[list[tuple[NDArray[np.float64], NDArray[np.float64]]], list[int]]:
    """The upper side (``y > 0`` normals) of the 2D hull of discs ``(points[k], radii[k])``
    (radius 0: a point): its straight edges as pairs of tangent points, and the discs it touches.

    A meridian of a solid of revolution: the discs are spheres centred on the axis, the points
    the rims of trunci; under each edge lies a frustum's meridian, under each arc the disc's.
    """
    p = np.asarray(points, dtype=np.float64).reshape(-1, 2)
    r = np.asarray(radii, dtype=np.float64).reshape(-1)
    tol = TIE_TOLERANCE * float(np.ptp(p, axis=0).max() + r.max())
    edges: list[tuple[NDArray[np.float64], NDArray[np.float64]]] = []
    used: set[int] = set()
    for i, j in itertools.combinations(range(len(r)), 2):
        w = p[j] - p[i]
        dist = float(np.linalg.norm(w))
        if dist == 0.0:
            continue
        nu = (r[i] - r[j]) / dist
        if abs(nu) >= 1.0:
            continue
        e, q = w / dist, np.array([-w[1], w[0]]) / dist
        for sign in (1.0, -1.0):
            u = nu * e + sign * math.sqrt(1.0 - nu * nu) * q
            reach = p @ u + r
            if u[1] > 0 and reach.max() <= reach[i] + tol:
                edges.append((p[i] + r[i] * u, p[j] + r[j] * u))
                used.update(k for k in (i, j) if r[k] > 0)
    if not edges:
        used = {int(np.argmax(r))}  # one disc holds everything
    return edges, sorted(used)
