"""Occluders as unions of convex polyhedra (the seed treats objects as sets of convex polyhedra).

Boxes and convex polyhedra are exact; spheres and frusta (truncus, cylinder,
cone) are replaced by their inscribed tessellation; every kind gives its pieces through ``convex_pieces(resolution)``.

A CSG tree is first brought, through its flat program
(:meth:`isocsg.csg.program.Program.evaluate`), into a union of *terms*
``C - (D_1 u ... u D_m)`` with convex ``C`` and ``D_i``:

- a union is the list of its operands' terms;
- ``(C - uD) n (C' - uD') = (C n C') - (uD u uD')``;
- ``(C - uD) - (C' - uD') = (C - (uD u C')) u U_k ((C n C' n D'_k) - (uD u D'_1..D'_{k-1}))``
  (disjoint terms).

Each term is then cut into disjoint convex pieces one subtracted ``D`` at a
time, with ``D``'s bounding box ``b`` (any box that contains ``D``):

- ``C - D = (C - b) u ((C n b) - D)``; ``C - b`` is at most six slabs
  ``C n outside(b_j) n inside(b_1..b_{j-1})`` over the box faces whose planes cut
  ``C`` (the thinnest direction of ``C`` first, so the first slabs span all of
  ``C``), and only the *local* region ``C n b`` sees ``D``;
- ``(C n b) - D`` is the union over the faces ``f`` of ``D`` of
  ``C n b n cone(f) n outside(f)``, ``cone(f)`` the cone from an interior
  point of ``D`` over ``f`` (the cones partition space, and inside ``cone(f)``
  a point is outside ``D`` exactly when it is beyond ``f``'s plane): every
  piece has at most ``|C| + 6 + |f| + 1`` half-spaces.

Pieces thinner than ``1e-9`` of the occluder's size are dropped (they cast no
shadow), and a subtracted ``D`` whose box misses a region is not applied to it.
The operands of a union are kept as they are: where they overlap, so do their
pieces (harmless: shadows need only the union of the silhouettes).

For shadows the decomposition can stop early (:func:`shadow_pieces`): the
illuminance only needs the union of the pieces' silhouettes, so a region
(a local region before it is cut, or a finished piece) can be left out when
every segment from the receivers to it, or from it to the sources, already
crosses another piece that is kept. For convex sets the test is exact on
vertices: with ``X``, ``Y`` and the receivers' box ``R`` convex, "the segment
``r -> x`` meets ``Y``" holds for all ``r`` in ``R`` and ``x`` in ``X`` as
soon as it holds for their vertices (for fixed ``x`` the ``r`` that qualify
form a convex set, the shadow of ``Y`` from ``x``; the same for fixed ``r``).
Regions outside the convex hull of the receivers and the sources are left
out too (no segment from a receiver to the source meets them). Left-out
regions are never cut, which is what makes a plate with pockets seen from
below as cheap as a box.
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from typing import Any

import numba
import numpy as np
from numpy.typing import NDArray

from .. import _validation
from ..csg.program import OP_INTERSECTION, OP_UNION, compile_program
from ..errors import InvalidGeometryError
from ..kinds.base import DEFAULT_RESOLUTION, Primitive, Solid
from .convex_regions import (
    EMPTY_TOL,
    ConvexPiece,
    HalfSpaces,
    _Convex,
    _intersect,
    _leaf_pieces,
    _make,
    _meets,
    _overlap,
)

# Hiding tests: the hiding piece is shrunk by this (relative to the scene's size) ...
HIDE_TOL = 1e-9
# ... and must be met by a receiver's segment at a parameter t >= HIDE_T0 (not only at the receiver).
HIDE_T0 = 1e-6

__all__ = ["ConvexPiece", "convex_pieces", "halfspace_pieces", "shadow_pieces", "clear_cache", "DEFAULT_RESOLUTION"]


# ----------------------------------------------------------------------------- terms and their pieces


class _Node:
    """``region - (pend[0] u pend[1] u ...)``, expanded on demand (memoised)."""

    __slots__ = ("region", "pend", "tol", "_step")

    def __init__(self, region: _Convex, pend: tuple[_Convex, ...], tol: float) -> None:
        self.region, self.tol = region, tol
        # (None,) once expanded into a finished piece, (slabs, local) once split
        self._step: tuple[None] | tuple[list[_Node], _Local | None] | None = None
        self.pend = tuple(d for d in pend if _overlap(region, d, -tol))

    def step(self) -> tuple[list[_Node], _Local | None] | None:
        """None when the region is a finished piece; else the slabs and the local region."""
        if self._step is None:
            c, tol = self.region, self.tol
            k = next((k for k, d in enumerate(self.pend) if _meets(c, d, tol)), None)
            if k is None:
                self._step = (None,)
            else:
                d, rest = self.pend[k], self.pend[k + 1 :]
                slabs, local = _box_split(c, d, tol)
                children = [_Node(s, rest, tol) for s in slabs]
                self._step = (children, None if local is None else _Local(local, d, rest, tol))
        return None if self._step[0] is None else self._step


class _Local:
    """A local region ``L - (d u rest...)`` with ``L`` inside ``d``'s box; cut by ``d``'s face cones on demand."""

    __slots__ = ("region", "d", "rest", "tol", "_pieces")

    def __init__(self, region: _Convex, d: _Convex, rest: tuple[_Convex, ...], tol: float) -> None:
        self.region, self.d, self.rest, self.tol = region, d, rest, tol
        self._pieces: list[_Node] | None = None

    def pieces(self) -> list[_Node]:
        if self._pieces is None:
            self._pieces = [_Node(p, self.rest, self.tol) for p in _cone_split(self.region, self.d, self.tol)]
        return self._pieces


def _box_split(c: _Convex, d: _Convex, tol: float) -> tuple[list[_Convex], _Convex | None]:
    """``c - box(d)`` as slabs, and ``c n box(d)``."""
    A, b = [c.A], [c.b]
    slabs = []
    for ax in np.argsort(c.hi - c.lo, kind="stable"):
        e = np.zeros(3)
        e[ax] = 1.0
        for n, off, beyond in ((-e, -d.lo[ax], c.lo[ax] < d.lo[ax] - tol), (e, d.hi[ax], c.hi[ax] > d.hi[ax] + tol)):
            if not beyond:  # the plane does not cut c: the constraint is redundant
                continue
            s = _make(np.vstack(A + [-n[None, :]]), np.concatenate(b + [[-off]]), tol)
            if s is not None:
                slabs.append(s)
            A.append(n[None, :])
            b.append(np.array([off]))
    if len(A) == 1:
        return slabs, c
    return slabs, _make(np.vstack(A), np.concatenate(b), tol)


class _Cones:
    """The face cones of a convex region D from an interior point g (the mean of its vertices)."""

    def __init__(self, d: _Convex) -> None:
        poly = d.poly
        V = np.asarray(poly.hull_vertices)
        self.g = g = V.mean(axis=0)
        self.normals = np.asarray(poly.face_normals, dtype=np.float64)
        self.offsets = np.asarray(poly.face_offsets, dtype=np.float64)
        self.rho = self.offsets - self.normals @ g  # distance from g to each face plane
        nf = len(poly.faces)
        self.axes, self.alpha = np.zeros((nf, 3)), np.zeros(nf)
        self.planes: list[tuple[NDArray[np.float64], NDArray[np.float64]]] = [None] * nf  # type: ignore[list-item]
        sizes = np.array([len(f) for f in poly.faces])
        for k in np.unique(sizes):  # faces with k vertices at once
            which = np.nonzero(sizes == k)[0]
            loops = V[np.array([poly.faces[i] for i in which])] - g  # (faces, k, 3), from g
            fc = loops.mean(axis=1)
            axis = fc / np.linalg.norm(fc, axis=1, keepdims=True)
            rays = loops / np.linalg.norm(loops, axis=2, keepdims=True)
            cosmin = np.min(np.einsum("fkj,fj->fk", rays, axis), axis=1)
            m = np.cross(loops, np.roll(loops, -1, axis=1))
            m /= np.linalg.norm(m, axis=2, keepdims=True)
            m *= np.where(np.einsum("fkj,fj->fk", m, fc) > 0, -1.0, 1.0)[..., None]  # inside: m . (x - g) <= 0
            self.axes[which] = axis
            self.alpha[which] = np.arccos(np.clip(cosmin, -1.0, 1.0))
            mg = m @ g
            for r, i in enumerate(which):
                self.planes[i] = (m[r], mg[r])


_CONES: dict[int, tuple[_Convex, _Cones]] = {}


def _cones(d: _Convex) -> _Cones:
    hit = _CONES.get(id(d))
    if hit is None or hit[0] is not d:
        if len(_CONES) > 4096:
            _CONES.clear()
        hit = _CONES[id(d)] = (d, _Cones(d))
    return hit[1]


def _cone_split(L: _Convex, d: _Convex, tol: float) -> list[_Convex]:
    """``L - d`` as pieces ``L n cone(f) n outside(f)`` over the faces f of ``d``.

    Faces are skipped when ``L`` lies inside their plane, or when the
    directions from g into ``L`` miss their cone (see :func:`_cone_misses`).
    """
    cones = _cones(d)
    g = cones.g
    LA, Lb, LV = L.A, L.b, L.verts
    cand = np.max(LV @ cones.normals.T, axis=0) > cones.offsets + tol
    near = LA @ g >= Lb - tol  # planes of L that g lies on or beyond (within tol)
    if np.any(near):
        cand &= ~_cone_misses(cones.axes, cones.alpha, LA[near], np.maximum(Lb[near] - LA[near] @ g, 0.0), cones.rho)
    out = []
    for j in np.nonzero(cand)[0]:
        m, mg = cones.planes[j]
        A = np.vstack([LA, -cones.normals[j][None, :], m])
        b = np.concatenate([Lb, [-cones.offsets[j]], mg])
        piece = _make(A, b, tol)
        if piece is not None:
            out.append(piece)
    return out


def _cone_misses(axes, alpha, planes, delta, rho) -> NDArray[np.bool_]:
    """For each face: whether ``L n cone(f) n outside(f)`` is empty by the directions from ``g``.

    ``planes`` (unit rows a, with ``a . g >= b - delta``) bound ``L``: a point
    ``x = g + t u`` of ``L`` has ``t (a . u) <= delta``. Every direction ``u``
    of the cone over ``f`` lies in the cap around its ``axis`` of half-angle
    ``alpha``; where ``a . u >= mu > 0`` on the whole cap, ``t <= delta / mu``,
    while points beyond ``f`` have ``t >= rho`` (the distance from ``g`` to
    ``f``'s plane). Both cannot hold when ``delta / mu < rho``.
    """
    theta = np.arccos(np.clip(planes @ axes.T, -1.0, 1.0))  # (planes, faces)
    edge = theta + alpha[None, :]
    mu = np.cos(np.minimum(edge, np.pi))
    return np.any((edge < 0.5 * np.pi - 1e-9) & (delta[:, None] < 0.5 * rho[None, :] * mu), axis=0)


def _terms(solid: Solid, resolution: int, tol: float) -> list[tuple[_Convex, tuple[_Convex, ...]]]:
    """The solid as disjoint terms ``(C, (D_1, ..., D_m))`` meaning ``C - (D_1 u ... u D_m)``."""

    def leaf(_: int, prim: Primitive) -> list:
        if prim.convex:  # one piece, lazy: tessellated only when cut or kept
            return [(_Convex(prim=prim, res=resolution), ())]
        pieces = _leaf_pieces(prim, resolution)
        return [(_Convex(prim=prim, res=resolution, index=i), ()) for i in range(len(pieces))]

    def combine(op: int, parts: list[list]) -> list:
        if op == OP_UNION:
            return [t for part in parts for t in part]
        cur = parts[0]
        if op == OP_INTERSECTION:
            for other in parts[1:]:
                nxt = []
                for c1, d1 in cur:
                    for c2, d2 in other:
                        c = _intersect([c1, c2], tol)
                        if c is not None:
                            nxt.append((c, tuple(x for x in d1 + d2 if _overlap(c, x, -tol))))
                cur = nxt
            return cur
        for other in parts[1:]:
            for c2, d2 in other:
                nxt = []
                for c, d in cur:
                    if not _overlap(c, c2, -tol):
                        nxt.append((c, d))
                        continue
                    nxt.append((c, d + (c2,)))
                    for k, dk in enumerate(d2):
                        if not _overlap(c, dk, -tol):
                            continue
                        ck = _intersect([c, c2, dk], tol)
                        if ck is not None:
                            nxt.append((ck, tuple(x for x in d + d2[:k] if _overlap(ck, x, -tol))))
                cur = nxt
        return cur

    return compile_program(solid).evaluate(leaf, combine)


@functools.lru_cache(maxsize=256)
def _roots(solid: Solid, resolution: int) -> tuple[_Node, ...]:
    b = np.asarray(solid.bounds, dtype=np.float64)
    tol = EMPTY_TOL * max(float(np.max(b[1] - b[0])), 1e-300)
    return tuple(_Node(c, d, tol) for c, d in _terms(solid, resolution, tol))


def _expand(roots: Sequence[_Node], hide=None) -> list[_Convex]:
    """Finished convex regions of the nodes; ``hide(region, finished)`` may leave local regions uncut."""
    finals: list[_Convex] = []
    work = list(reversed(roots))
    deferred: list[_Local] = []
    while work or deferred:
        if work:
            node = work.pop()
            st = node.step()
            if st is None:
                finals.append(node.region)
                continue
            slabs, local = st
            work.extend(reversed(slabs))
            if local is not None:
                deferred.append(local)
            continue
        loc = deferred.pop()
        if hide is not None and hide(loc.region, finals):
            continue
        work.extend(reversed(loc.pieces()))
    return finals


# ----------------------------------------------------------------------------- public functions


def occluder_list(occluders: Sequence[Solid] | Solid, resolution: Any) -> list[Solid]:
    """The occluders as a list of solids, validated (as :func:`convex_pieces` does).

    Returns
    -------
    list of Solid

    Raises
    ------
    InvalidGeometryError
        If an occluder is not a solid (naming its index).
    InvalidParameterError
        If ``resolution`` is not an integer in 3 .. 512.
    """
    resolution = _validation.resolution("resolution", resolution)
    if isinstance(occluders, Solid):
        occluders = [occluders]
    try:
        seq = list(occluders)
    except TypeError:
        raise InvalidGeometryError(f"occluders must be a sequence of solids, got {type(occluders).__name__}") from None
    for i, o in enumerate(seq):
        if not isinstance(o, Solid):
            raise InvalidGeometryError(f"occluders[{i}] must be a primitive or a CSG tree, got {type(o).__name__}")
    return seq


def clear_cache() -> None:
    """Forget the decompositions kept for solids already seen (they are reused across calls)."""
    _roots.cache_clear()
    _pieces_cached.cache_clear()
    _leaf_pieces.cache_clear()
    _CONES.clear()


def halfspace_pieces(solid: Solid, *, resolution: int = DEFAULT_RESOLUTION) -> list[HalfSpaces]:
    """Convex pieces of one solid as half-space sets ``(normals, offsets)`` (``n . x <= d``).

    Examples
    --------
    >>> from isocsg import Box
    >>> len(halfspace_pieces(Box((0, 0, 0), (2, 2, 2)) - Box((1, 1, 1), (1, 1, 1))))
    3
    """
    if not isinstance(solid, Solid):
        raise InvalidGeometryError(f"occluder must be a primitive or a CSG tree, got {type(solid).__name__}")
    occluder_list([solid], resolution)
    return [(r.A.copy(), r.b.copy()) for r in _expand(_roots(solid, int(resolution)))]


@functools.lru_cache(maxsize=256)
def _pieces_cached(solid: Solid, resolution: int) -> tuple[ConvexPiece, ...]:
    out = []
    for r in _expand(_roots(solid, resolution)):
        pc = r.piece()
        if pc is not None:
            out.append(pc)
    return tuple(out)


def convex_pieces(occluders: Sequence[Solid] | Solid, *, resolution: int = DEFAULT_RESOLUTION) -> list[ConvexPiece]:
    """Decompose occluders (primitives or CSG trees) into convex pieces.

    The pieces of one solid are disjoint (up to shared boundaries) except where
    the operands of a union overlap; their union is the solid.

    Parameters
    ----------
    occluders : Solid or sequence of Solid
        Primitives (``Box``, ``ConvexPolyhedron`` exact; ``Sphere``, ``Truncus``,
        ``Cylinder``, ``Cone`` tessellated) and CSG trees over them.
    resolution : int, default 64
        Tessellation resolution of curved primitives (``convex_pieces``).

    Returns
    -------
    list of ConvexPiece

    Raises
    ------
    InvalidGeometryError
        If an occluder is not a solid.
    InvalidParameterError
        If ``resolution`` is not an integer >= 3.

    Examples
    --------
    >>> from isocsg import Box, Sphere
    >>> pieces = convex_pieces([Box((0, 0, 0), (1, 1, 1)) | Sphere((3, 0, 0), 1)], resolution=16)
    >>> len(pieces)
    2
    """
    out: list[ConvexPiece] = []
    for o in occluder_list(occluders, resolution):
        out.extend(_pieces_cached(o, int(resolution)))
    return out


# ----------------------------------------------------------------------------- pieces for shadows


@numba.njit(cache=True)
def _hider(X, Q, t_lo, t_hi, YA, Yb, Yoff, cand):
    """First ``cand[i]`` whose region ``YA x <= Yb`` meets every segment ``Q[a] + t (X[j] - Q[a])``,
    ``t`` in ``[t_lo, t_hi]``; -1 when none does."""
    for ci in range(cand.shape[0]):
        y = cand[ci]
        ok = True
        for a in range(Q.shape[0]):
            for j in range(X.shape[0]):
                t0 = t_lo
                t1 = t_hi
                for k in range(Yoff[y], Yoff[y + 1]):
                    num = Yb[k] - (YA[k, 0] * Q[a, 0] + YA[k, 1] * Q[a, 1] + YA[k, 2] * Q[a, 2])
                    den = (YA[k, 0] * (X[j, 0] - Q[a, 0]) + YA[k, 1] * (X[j, 1] - Q[a, 1])
                           + YA[k, 2] * (X[j, 2] - Q[a, 2]))
                    if den > 0.0:
                        t1 = min(t1, num / den)
                    elif den < 0.0:
                        t0 = max(t0, num / den)
                    elif num < 0.0:
                        t0 = 1.0
                        t1 = 0.0
                    if t0 > t1:
                        break
                if t0 > t1:
                    ok = False
                    break
            if not ok:
                break
        if ok:
            return y
    return -1


class _Hiding:
    """Which regions no receiver-to-source segment needs (see the module docstring)."""

    def __init__(self, receivers: NDArray[np.float64], sources: NDArray[np.float64], scale: float) -> None:
        from scipy.spatial import ConvexHull, QhullError

        lo, hi = receivers.min(axis=0), receivers.max(axis=0)
        self.R = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
        self.R = np.unique(self.R, axis=0)
        self.S = np.unique(np.asarray(sources, dtype=np.float64).reshape(-1, 3), axis=0)
        self.tol = HIDE_TOL * scale
        pts = np.vstack([self.R, self.S])
        self.rlo, self.rhi = self.R.min(axis=0), self.R.max(axis=0)
        self.slo, self.shi = self.S.min(axis=0), self.S.max(axis=0)
        self.hull: tuple[NDArray[np.float64], NDArray[np.float64]] | None
        try:
            eq = ConvexHull(pts).equations
            self.hull = (eq[:, :3], -eq[:, 3])
        except (QhullError, ValueError):  # flat: no cheap hull test
            self.hull = None
        self.pts = pts
        self.regions: list[_Convex] = []
        self.A = np.zeros((0, 3))
        self.b = np.zeros(0)
        self.off = np.zeros(1, dtype=np.int64)
        self.lo = np.zeros((0, 3))
        self.hi = np.zeros((0, 3))

    def _pack(self, regions: list[_Convex]) -> None:
        new = regions[len(self.regions) :]
        if not new:
            return
        self.regions = list(regions)
        self.A = np.vstack([self.A] + [r.A for r in new])
        self.b = np.concatenate([self.b] + [r.b - self.tol for r in new])  # shrunk: met means met inside
        self.off = np.concatenate([self.off, self.off[-1] + np.cumsum([len(r.b) for r in new])])
        self.lo = np.vstack([self.lo] + [r.lo[None, :] for r in new])
        self.hi = np.vstack([self.hi] + [r.hi[None, :] for r in new])

    def outside(self, X: _Convex) -> bool:
        """No segment from a receiver to a source point runs inside X (a plane keeps them apart).

        X may touch the hull of the receivers' box and the sources (a pocket
        opening in the plane of the receivers): segments can then only graze it.
        """
        if self.hull is None:
            return False
        a, b = self.hull
        if np.any(np.min(X.verts @ a.T - b, axis=0) >= -self.tol):
            return True
        return bool(np.any(np.min(self.pts @ X.A.T - X.b, axis=0) >= -self.tol))

    def hider(self, X: _Convex, present: NDArray[np.bool_] | None = None, skip: int = -1) -> int:
        """Index of a packed region that hides X from the receivers or from the sources; -1 if none."""
        V = X.verts
        xlo, xhi = X.lo, X.hi
        for Q, qlo, qhi, t0, t1 in ((self.R, self.rlo, self.rhi, HIDE_T0, 1.0), (self.S, self.slo, self.shi, 0.0, 1.0)):
            lo, hi = np.minimum(xlo, qlo), np.maximum(xhi, qhi)
            cand = np.all((self.lo <= hi) & (self.hi >= lo), axis=1)
            if present is not None:
                cand &= present
            if 0 <= skip < len(cand):
                cand[skip] = False
            idx = np.nonzero(cand)[0]
            if len(idx) == 0:
                continue
            y = _hider(V, Q, t0, t1, self.A, self.b, self.off, idx.astype(np.int64))
            if y >= 0:
                return int(y)
        return -1

    def hidden_local(self, X: _Convex, finals: list[_Convex]) -> bool:
        if self.outside(X):
            return True
        self._pack(finals)
        return self.hider(X) >= 0 or self.enclosed(X, self.R) or self.enclosed(X, self.S)

    def enclosed(self, X: _Convex, Q: NDArray[np.float64]) -> bool:
        """Whether every face of X that a point of conv(Q) sees is covered by kept pieces beyond it.

        A segment from a point of conv(Q) (outside X) into X enters through
        such a face, and just before it runs inside a covering piece (the
        piece contains the face and lies on its outer side); a segment from X
        to conv(Q) leaves through one and runs inside a covering piece just
        after. Up to segments through the faces' edges (a set of measure
        zero) both are therefore blocked anyway.
        """
        import shapely

        tol = 10 * self.tol
        try:
            poly = X.poly
        except InvalidGeometryError:
            return False
        normals, offsets = np.asarray(poly.face_normals), np.asarray(poly.face_offsets)
        side = Q @ normals.T - offsets  # > 0: outside that face's plane
        if not np.any(np.all(side > tol, axis=0)):  # conv(Q) is not kept apart from X by one of its planes
            return False
        V = np.asarray(poly.hull_vertices)
        near = np.all((self.lo <= X.hi + tol) & (self.hi >= X.lo - tol), axis=1)
        cand = [self.regions[i] for i in np.nonzero(near)[0]]
        for f, n, off in zip(poly.faces, normals, offsets):
            if np.max(Q @ n) - off <= tol:
                continue  # no point of conv(Q) sees this face
            u = np.cross(n, [1.0, 0.0, 0.0] if abs(n[0]) < 0.9 else [0.0, 1.0, 0.0])
            u /= np.linalg.norm(u)
            w = np.cross(n, u)
            face = shapely.Polygon(np.c_[V[f] @ u, V[f] @ w])
            cover = []
            for Y in cand:
                h = Y.verts @ n - off
                if np.min(h) < -tol:
                    continue  # Y is not beyond this face
                on = Y.verts[h <= tol]
                if len(on) >= 3:
                    cover.append(shapely.convex_hull(shapely.MultiPoint(np.c_[on @ u, on @ w])))
            if not cover or face.difference(shapely.union_all(cover)).area > 1e-9 * face.area:
                return False
        return True

    def cull(self, finals: list[_Convex]) -> list[_Convex]:
        """The finished regions that some segment may need (each left-out one is hidden by a kept one)."""
        self._pack(finals)
        present = np.ones(len(finals), dtype=bool)
        vol = np.prod(self.hi - self.lo, axis=1) if len(finals) else np.zeros(0)
        for i in np.argsort(vol, kind="stable"):
            X = finals[i]
            if self.outside(X) or self.hider(X, present, int(i)) >= 0:
                present[i] = False
        return [r for r, k in zip(finals, present) if k]


def shadow_pieces(
    occluders: Sequence[Solid] | Solid,
    receivers: Any,
    sources: Any,
    *,
    resolution: int = DEFAULT_RESOLUTION,
    scale: float | None = None,
) -> list[ConvexPiece]:
    """Convex pieces of the occluders that the shadows of some receivers need.

    The union of the silhouettes of the returned pieces, seen from any point
    of the receivers' bounding box towards any point of the sources' convex
    hull, is that of all the pieces of :func:`convex_pieces`; pieces (and
    regions not yet cut) hidden behind a kept piece, or outside the convex
    hull of the receivers' box and the sources, are left out (see the module
    docstring).

    Parameters
    ----------
    occluders : Solid or sequence of Solid
    receivers : array_like, shape (n, 3)
        Receiving points (only their bounding box is used).
    sources : array_like, shape (m, 3)
        Vertices of the emitting polygons.
    resolution : int, keyword-only, default 64
    scale : float, keyword-only, optional
        Size of the scene, for the tolerances of the tests (by default from
        the receivers' box, the sources and the occluders' bounds).

    Returns
    -------
    list of ConvexPiece

    Raises
    ------
    InvalidGeometryError, InvalidParameterError
        As :func:`convex_pieces`.

    Examples
    --------
    A plate with a pocket on top, seen from the floor below: the pocket is
    hidden by the plate's slab under it and never cut into pieces.

    >>> from isocsg import Box, Sphere
    >>> plate = Box((0, 0, 1), (1, 1, 0.1)) - Sphere((0, 0, 1.05), 0.03)
    >>> floor = [(-2, -2, 0), (2, 2, 0)]
    >>> lamp = [(-0.5, -0.5, 3), (0.5, -0.5, 3), (0.5, 0.5, 3), (-0.5, 0.5, 3)]
    >>> len(convex_pieces(plate, resolution=16)) > len(shadow_pieces(plate, floor, lamp, resolution=16))
    True
    """
    seq = occluder_list(occluders, resolution)
    R = np.asarray(receivers, dtype=np.float64).reshape(-1, 3)
    S = np.asarray(sources, dtype=np.float64).reshape(-1, 3)
    if len(R) == 0 or len(S) == 0 or not seq:
        return convex_pieces(seq, resolution=resolution)
    if scale is None:
        bounds = np.vstack([np.asarray(o.bounds, dtype=np.float64) for o in seq])
        allp = np.vstack([R.min(axis=0), R.max(axis=0), S, bounds])
        scale = float(max(np.max(np.ptp(allp, axis=0)), np.max(np.abs(allp)), 1e-300))
    hiding = _Hiding(R, S, scale)
    roots = [node for o in seq for node in _roots(o, int(resolution))]
    finals = _expand(roots, hiding.hidden_local)
    out = []
    for r in hiding.cull(finals):
        pc = r.piece()
        if pc is not None:
            out.append(pc)
    return out
