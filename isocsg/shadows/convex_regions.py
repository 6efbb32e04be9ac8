"""Bounded convex regions ``A x <= b`` with their vertices: the occluders' pieces.

:class:`ConvexPiece` is the public value (a convex polyhedron as half-spaces, vertices and
edges); ``_Convex`` the working region of :mod:`isocsg.shadows.occluders`, which a leaf
(a primitive) fills lazily from its kind's ``convex_pieces``.
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numba
import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidGeometryError
from ..kinds.base import Primitive
from ..kinds.polyhedron import ConvexPolyhedron

# A piece thinner than this (relative to the occluder's size) counts as empty.
EMPTY_TOL = 1e-9
# Regions with at most this many planes get their vertices from plane triples (no linear program).
ENUM_PLANES = 40

HalfSpaces = tuple[NDArray[np.float64], NDArray[np.float64]]  # (normals (k, 3), offsets (k,)): n . x <= d


@dataclass(frozen=True, slots=True)
class ConvexPiece:
    """One convex polyhedron of an occluder: half-spaces, vertices and edges.

    Attributes
    ----------
    normals : ndarray, shape (k, 3)
        Unit outward face normals; the solid is ``normals @ x <= offsets``.
    offsets : ndarray, shape (k,)
    vertices : ndarray, shape (v, 3)
    edges : ndarray of int64, shape (e, 2)
        Vertex index pairs of the polyhedron's edges.

    Examples
    --------
    >>> from isocsg import Box
    >>> from isocsg.shadows import convex_pieces
    >>> piece = convex_pieces([Box((0, 0, 0), (1, 2, 3))])[0]
    >>> piece.vertices.shape, piece.edges.shape, piece.normals.shape
    ((8, 3), (12, 2), (6, 3))
    """

    normals: NDArray[np.float64] = field(compare=False)
    offsets: NDArray[np.float64] = field(compare=False)
    vertices: NDArray[np.float64] = field(compare=False)
    edges: NDArray[np.int64] = field(compare=False)

    @classmethod
    def from_polyhedron(cls, poly: ConvexPolyhedron) -> ConvexPiece:
        """The piece of a :class:`ConvexPolyhedron` (its hull faces and edges)."""
        pairs = set()
        for f in poly.faces:
            f = np.asarray(f)
            for a, b in zip(f, np.roll(f, -1)):
                pairs.add((int(min(a, b)), int(max(a, b))))
        edges = np.array(sorted(pairs), dtype=np.int64).reshape(-1, 2)
        return cls(
            np.array(poly.face_normals, dtype=np.float64),
            np.array(poly.face_offsets, dtype=np.float64),
            np.array(poly.hull_vertices, dtype=np.float64),
            edges,
        )

    @property
    def polyhedron(self) -> ConvexPolyhedron:
        """The piece as a :class:`ConvexPolyhedron`."""
        return ConvexPolyhedron(self.vertices)

    def contains(self, points: Any, *, tol: float = 0.0) -> NDArray[np.bool_]:
        """Points inside or on the piece (within ``tol``)."""
        p = np.atleast_2d(np.asarray(points, dtype=np.float64))
        return np.all(p @ self.normals.T <= self.offsets + tol, axis=1)


def _chebyshev(hs: HalfSpaces) -> tuple[NDArray[np.float64], float]:
    """Centre and radius of the largest ball inside the half-spaces (radius < 0 when empty)."""
    from scipy.optimize import linprog

    a, b = hs
    norms = np.linalg.norm(a, axis=1)
    res = linprog(
        c=np.array([0.0, 0.0, 0.0, -1.0]),
        A_ub=np.column_stack([a, norms]),
        b_ub=b,
        bounds=[(None, None)] * 3 + [(None, None)],
        method="highs",
    )
    if res.status == 3:  # unbounded: cannot happen for pieces of bounded solids
        raise InvalidGeometryError("occluder piece is unbounded")
    if not res.success:
        return np.zeros(3), -1.0
    return res.x[:3], float(res.x[3])


class _Convex:
    """A bounded convex region: unit half-spaces ``A x <= b``, its vertices and bounding box.

    A leaf (a primitive) is materialised lazily: until its half-spaces are
    needed it only offers the primitive's bounding box, which contains its
    tessellation.
    """

    __slots__ = ("_A", "_b", "_index", "_piece", "_poly", "_prim", "_res", "_verts", "hi", "lo")

    def __init__(self, A=None, b=None, verts=None, *, prim=None, res=0, index=0) -> None:
        self._A, self._b, self._verts = A, b, verts
        self._poly: ConvexPolyhedron | None = None
        self._piece: ConvexPiece | bool | None = None
        self._prim, self._res, self._index = prim, res, index
        if verts is not None:
            self.lo, self.hi = verts.min(axis=0), verts.max(axis=0)
        else:
            bounds = np.asarray(prim.bounds, dtype=np.float64)
            self.lo, self.hi = bounds[0].copy(), bounds[1].copy()

    def _materialise(self) -> None:
        if self._A is not None:
            return
        poly = _leaf_pieces(self._prim, self._res)[self._index]
        self._poly = poly
        self._A = np.array(poly.face_normals, dtype=np.float64)
        self._b = np.array(poly.face_offsets, dtype=np.float64)
        self._verts = np.array(poly.hull_vertices, dtype=np.float64)
        self.lo, self.hi = self._verts.min(axis=0), self._verts.max(axis=0)

    @property
    def A(self) -> NDArray[np.float64]:
        self._materialise()
        return self._A

    @property
    def b(self) -> NDArray[np.float64]:
        self._materialise()
        return self._b

    @property
    def verts(self) -> NDArray[np.float64]:
        self._materialise()
        return self._verts

    @property
    def poly(self) -> ConvexPolyhedron:
        self._materialise()
        if self._poly is None:
            self._poly = ConvexPolyhedron(self._verts)
        return self._poly

    def piece(self) -> ConvexPiece | None:
        if self._piece is None:
            try:
                self._piece = ConvexPiece.from_polyhedron(self.poly)
            except InvalidGeometryError:  # flat: it casts no shadow
                self._piece = False
        return self._piece if isinstance(self._piece, ConvexPiece) else None


@functools.lru_cache(maxsize=1024)
def _leaf_pieces(prim: Primitive, resolution: int) -> tuple[ConvexPolyhedron, ...]:
    # exact for polyhedral kinds, inscribed for curved ones; several for a non-convex kind
    return tuple(prim.convex_pieces(resolution))


def _overlap(a: _Convex, b: _Convex, tol: float) -> bool:
    return bool(np.all(a.lo <= b.hi + tol) and np.all(b.lo <= a.hi + tol))


def _make(A: NDArray[np.float64], b: NDArray[np.float64], tol: float) -> _Convex | None:
    """The region ``A x <= b`` (unit rows) with its vertices; None when thinner than ``tol``."""
    if len(b) <= ENUM_PLANES:
        return _make_small(A, b, tol)
    from scipy.spatial import HalfspaceIntersection, QhullError

    centre, r = _chebyshev((A, b))
    if r <= tol:
        return None
    try:
        verts = HalfspaceIntersection(np.column_stack([A, -b]), centre).intersections
    except QhullError:  # pragma: no cover - qhull failing on a region with a ball of radius > tol inside
        return None
    verts = np.unique(np.round(verts / (1e-3 * tol)), axis=0) * (1e-3 * tol)
    # keep the facets (planes through at least three vertices): the rest are redundant
    active = np.count_nonzero(np.abs(A @ verts.T - b[:, None]) <= 10 * tol, axis=1) >= 3
    return _Convex(np.ascontiguousarray(A[active]), b[active].copy(), verts)


@numba.njit(cache=True)
def _enumerate(A, b, tol):
    """Vertices of ``A x <= b`` from plane triples, facet mask, edges; no vertices when flat or empty."""
    k = A.shape[0]
    cap = max(k * (k - 1) * (k - 2) // 6, 1)
    V = np.empty((cap, 3))
    n = 0
    merge = 1e-2 * tol
    for i in range(k):
        for j in range(i + 1, k):
            c0 = A[i, 1] * A[j, 2] - A[i, 2] * A[j, 1]
            c1 = A[i, 2] * A[j, 0] - A[i, 0] * A[j, 2]
            c2 = A[i, 0] * A[j, 1] - A[i, 1] * A[j, 0]
            for m in range(j + 1, k):
                det = A[m, 0] * c0 + A[m, 1] * c1 + A[m, 2] * c2
                if abs(det) <= 1e-12:
                    continue
                # Cramer: x = (b_i (a_j x a_m) + b_j (a_m x a_i) + b_m (a_i x a_j)) / det
                x = np.empty(3)
                for r in range(3):
                    r1 = (r + 1) % 3
                    r2 = (r + 2) % 3
                    jm = A[j, r1] * A[m, r2] - A[j, r2] * A[m, r1]
                    mi = A[m, r1] * A[i, r2] - A[m, r2] * A[i, r1]
                    ij = A[i, r1] * A[j, r2] - A[i, r2] * A[j, r1]
                    x[r] = (b[i] * jm + b[j] * mi + b[m] * ij) / det
                ok = True
                for q in range(k):
                    if A[q, 0] * x[0] + A[q, 1] * x[1] + A[q, 2] * x[2] - b[q] > tol:
                        ok = False
                        break
                if not ok:
                    continue
                for w in range(n):
                    if abs(V[w, 0] - x[0]) <= merge and abs(V[w, 1] - x[1]) <= merge and abs(V[w, 2] - x[2]) <= merge:
                        ok = False
                        break
                if ok:
                    V[n] = x
                    n += 1
    facet = np.zeros(k, dtype=np.bool_)
    empty = (V[:0].copy(), facet, np.zeros((0, 2), dtype=np.int64))
    if n < 4:
        return empty
    inc = np.zeros((k, n), dtype=np.bool_)
    nfacet = 0
    for q in range(k):
        c = 0
        for w in range(n):
            if abs(A[q, 0] * V[w, 0] + A[q, 1] * V[w, 1] + A[q, 2] * V[w, 2] - b[q]) <= 10 * tol:
                inc[q, w] = True
                c += 1
        if c >= 3:
            facet[q] = True
            nfacet += 1
            width = 0.0
            for w in range(n):
                width = max(width, b[q] - (A[q, 0] * V[w, 0] + A[q, 1] * V[w, 1] + A[q, 2] * V[w, 2]))
            if width <= 2 * tol:
                return empty
    if nfacet < 4:
        return empty
    # edges: vertex pairs on two common facets (a diagonal of a face may slip in: harmless for silhouettes)
    E = np.empty((n * (n - 1) // 2, 2), dtype=np.int64)
    ne = 0
    for v in range(n):
        for w in range(v + 1, n):
            c = 0
            for q in range(k):
                if facet[q] and inc[q, v] and inc[q, w]:
                    c += 1
            if c >= 2:
                E[ne, 0] = v
                E[ne, 1] = w
                ne += 1
    return V[:n].copy(), facet, E[:ne].copy()


def _make_small(A: NDArray[np.float64], b: NDArray[np.float64], tol: float) -> _Convex | None:
    """:func:`_make` for few planes: the vertices are the feasible intersections of three planes.

    A region is kept when its width along every facet normal exceeds ``2 tol``.
    """
    V, facet, edges = _enumerate(np.ascontiguousarray(A, dtype=np.float64), np.ascontiguousarray(b, dtype=np.float64),
                                 tol)
    if len(V) == 0:
        return None
    region = _Convex(np.ascontiguousarray(A[facet]), b[facet].copy(), V)
    region._piece = ConvexPiece(region._A, region._b, V, edges)
    return region


def _meets(c: _Convex, d: _Convex, tol: float) -> bool:
    """Whether ``d`` may cut ``c``: boxes overlap, and for materialised regions an inner ball wider than ``tol``."""
    if not _overlap(c, d, -tol):
        return False
    if d._A is None:  # a lazy leaf: its box says it may (conservative: the split stays exact)
        return True
    return _chebyshev((np.vstack([c.A, d.A]), np.concatenate([c.b, d.b])))[1] > tol


def _intersect(regions: Sequence[_Convex], tol: float) -> _Convex | None:
    lo = np.max([r.lo for r in regions], axis=0)
    hi = np.min([r.hi for r in regions], axis=0)
    if np.any(lo > hi + tol):
        return None
    return _make(np.vstack([r.A for r in regions]), np.concatenate([r.b for r in regions]), tol)
