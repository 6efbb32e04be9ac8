"""Receivers sorted into lit, umbra and the rest by the shadow volumes, tile by tile (seed 001, 2.3).

The exact illuminance (:mod:`isocsg.shadows.visibility`) clips each source
against every occluder piece's silhouette at every point. Most points need
none of it: a point outside every piece's penumbra volume sees the whole
source (Lambert's formula for the unoccluded source, nothing else), and a
point inside one piece's umbra volume sees none of it (zero). This module
proves either of the two for whole tiles of receivers at once, then for the
single points of the tiles that are neither, and leaves the rest (the
penumbra, and points too close to a volume's boundary to decide) to the
exact path. Both proofs are conservative, so every class gives the value the
exact path gives (the lit formula is the exact path's own code with the
silhouettes left out, the umbra gives its zero).

For one convex emitting polygon ``S`` and one convex occluder piece ``V``:

- **Separated** (``V`` casts no shadow on a set ``X`` of receivers): a plane
  with ``S`` on its positive side, ``V`` on its negative side and all of
  ``X`` strictly positive (by ``SEPARATION_MARGIN``): a segment from ``S``
  to ``X`` stays positive and cannot meet ``V``. The candidate planes are
  those that bound the penumbra volume (Table 1 of the seed: a source vertex
  with an edge of ``V``, a vertex of ``V`` with an edge of ``S``, and the
  faces of ``V``); a tile is separated when its bounding box's corners are
  all beyond one plane (the box is convex). Pieces that reach within
  ``NEAR_SOURCE`` of the source plane are never called separated (a
  segment could meet them next to the source, where the margin says
  nothing); pieces wholly behind it never block.
- **Hides** (``X`` in the umbra volume of ``V``): every segment from a corner
  of ``X``'s box to a vertex of ``S`` meets ``V`` shrunk by ``HIDE_MARGIN``,
  at a parameter away from both ends (inside the slab the exact path
  projects). The segments that meet a convex set, from points of one convex
  set to points of another, form a convex condition in each end point, so
  the corners decide for the whole box (as for the hidden pieces of
  :mod:`isocsg.shadows.occluders`).

A receiver is lit when every (source polygon, piece) pair is separated, in
umbra when every source polygon is hidden by some piece (a polygon that
nothing reaches, or that lies behind the receiving plane, gives zero and
state 2 on the exact path too). Tiles are the cells of a grid over the
receivers' bounding box, about ``TILE_POINTS`` points each.
"""

from __future__ import annotations

from typing import Any

import numba
import numpy as np
from numpy.typing import NDArray

from .lambert import edge_term_fast
from .visibility import SourceArrays, _area2, _lambert2, _source_polygon, _threads, run_chunks

__all__ = [
    "ReceiverClasses", "CLASS_LIT", "CLASS_UMBRA", "CLASS_EXACT", "classify_receivers", "lit_illuminance",
    "bounding_box", "class_indices",
]

CLASS_LIT = 0
CLASS_EXACT = 1
CLASS_UMBRA = 2

TILE_POINTS = 64  # receivers per tile (about)
CLASSIFY_CHUNK = 4096  # receivers a chunk of the point-by-point classification takes at least
SEPARATION_MARGIN = 1e-9  # relative to the scene's size: how far beyond a separating plane a receiver must be
PLANE_TOL = 1e-14  # relative: rounding allowed in "S positive, V negative" on a candidate plane
NEAR_SOURCE = 1e-4  # relative: pieces this close to a source plane are never called separated
HIDE_MARGIN = 1e-9  # relative: a hiding piece is shrunk by this
HIDE_T = 1e-6  # the hiding segment parameter stays in [HIDE_T, 1 - HIDE_T] (source at 0, receiver at 1)

# Relation of a (source polygon, piece) pair to a set of receivers
REL_SEPARATED = 0
REL_UNKNOWN = 1
REL_HIDES = 2


class ReceiverClasses:
    """Classes of receivers and the pieces each tile still needs on the exact path.

    Attributes
    ----------
    cls : ndarray of int8, shape (n,)
        ``CLASS_LIT``, ``CLASS_UMBRA`` or ``CLASS_EXACT`` per receiver.
    tile : ndarray of int64, shape (n,)
        The tile of each receiver.
    needed : ndarray of bool, shape (tiles, pieces)
        Pieces that are not separated from the tile for some source polygon.
    """

    def __init__(self, cls: NDArray[np.int8], tile: NDArray[np.int64], needed: NDArray[np.bool_]) -> None:
        self.cls, self.tile, self.needed = cls, tile, needed


def _separating_planes(S: NDArray[np.float64], V: NDArray[np.float64], edges: NDArray[np.int64],
                       fn: NDArray[np.float64], fo: NDArray[np.float64], scale: float,
                       ) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Unit planes ``n . x = d`` with ``S`` on the positive side and ``V`` on the negative side."""
    m = len(S)
    Se = np.stack([S, np.roll(S, -1, axis=0)], axis=1)  # (m, 2, 3) source edges
    Ve = V[edges]  # (e, 2, 3)
    # a source vertex with an edge of V; a vertex of V with an edge of S
    c1 = np.cross(Ve[None, :, 0] - S[:, None], Ve[None, :, 1] - S[:, None])
    n1, d1 = c1.reshape(-1, 3), np.einsum("sej,sj->se", c1, S).ravel()
    c2 = np.cross(Se[None, :, 0] - V[:, None], Se[None, :, 1] - V[:, None])
    n2, d2 = c2.reshape(-1, 3), np.einsum("vej,vj->ve", c2, V).ravel()
    nn = np.vstack([n1, n2, fn])
    dd = np.concatenate([d1, d2, fo])
    ln = np.linalg.norm(nn, axis=1)
    ok = ln > 1e-12 * scale * scale
    nn = nn[ok] / ln[ok, None]
    dd = dd[ok] / ln[ok]
    # V's faces are already unit; their rows were divided by 1 within rounding
    vs = S @ nn.T - dd  # (m, k)
    vv = V @ nn.T - dd
    tol = PLANE_TOL * scale
    pos = (vs.min(axis=0) >= -tol) & (vv.max(axis=0) <= tol)
    neg = (vs.max(axis=0) <= tol) & (vv.min(axis=0) >= -tol)
    sign = np.where(pos, 1.0, -1.0)
    keep = pos | neg
    # the faces of V are kept only in their own orientation (V behind them)
    nf = len(fo)
    keep[len(keep) - nf:] &= pos[len(keep) - nf:]
    nn = nn[keep] * sign[keep, None]
    dd = dd[keep] * sign[keep]
    if m == 0 or len(dd) == 0:
        return np.zeros((0, 3)), np.zeros(0)
    _, first = np.unique(np.round(np.c_[nn, dd / scale], 12), axis=0, return_index=True)
    first.sort()
    return nn[first], dd[first]


_PLANES: dict[tuple, tuple[NDArray[np.float64], NDArray[np.float64]]] = {}


def _planes_cached(S: NDArray[np.float64], pc: Any, scale: float) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """:func:`_separating_planes`, kept for the same source and piece (by content: repeated grids reuse them)."""
    key = (S.tobytes(), pc.vertices.tobytes(), pc.edges.tobytes(), pc.normals.tobytes(), pc.offsets.tobytes(), scale)
    hit = _PLANES.get(key)
    if hit is None:
        if len(_PLANES) > 4096:
            _PLANES.clear()
        hit = _PLANES[key] = _separating_planes(S, pc.vertices, pc.edges, pc.normals, pc.offsets, scale)
    return hit


class _PairTables:
    """Per (source polygon, piece): the separating planes, and the piece's half-spaces for the hiding test."""

    def __init__(self, sources: SourceArrays, pieces: list, scale: float) -> None:
        ns, npc = len(sources.radiance), len(pieces)
        self.kind = np.zeros((ns, npc), dtype=np.int8)  # 0 test, 1 never blocks, 2 never separated
        self.poff = np.zeros(ns * npc + 1, dtype=np.int64)
        planes_n, planes_d = [], []
        for s in range(ns):
            S = sources.verts[sources.off[s]:sources.off[s + 1]]
            N, q0 = sources.normal[s], sources.q0[s]
            for j, pc in enumerate(pieces):
                lev = (pc.vertices - q0) @ N
                if lev.max() < -NEAR_SOURCE * scale:
                    self.kind[s, j] = 1
                    nn, dd = np.zeros((0, 3)), np.zeros(0)
                elif lev.min() < NEAR_SOURCE * scale:
                    self.kind[s, j] = 2
                    nn, dd = np.zeros((0, 3)), np.zeros(0)
                else:
                    nn, dd = _planes_cached(S, pc, scale)
                planes_n.append(nn)
                planes_d.append(dd)
                self.poff[s * npc + j + 1] = self.poff[s * npc + j] + len(dd)
        self.pn = np.ascontiguousarray(np.vstack(planes_n) if planes_n else np.zeros((0, 3)))
        self.pd = np.concatenate(planes_d) if planes_d else np.zeros(0)
        self.hoff = np.zeros(npc + 1, dtype=np.int64)
        self.hoff[1:] = np.cumsum([len(pc.offsets) for pc in pieces])
        self.hA = np.ascontiguousarray(np.vstack([pc.normals for pc in pieces]) if pieces else np.zeros((0, 3)))
        self.hb = (np.concatenate([pc.offsets for pc in pieces]) if pieces else np.zeros(0)) - HIDE_MARGIN * scale
        self.margin = SEPARATION_MARGIN * scale


@numba.njit(cache=True)
def _hides(X, nx, S, hA, hb, h0, h1):
    """Whether the region ``hA[h0:h1] x <= hb`` meets every segment ``S[a] + t (X[j] - S[a])``, t in the HIDE_T
    range (its end points kept out)."""
    for a in range(S.shape[0]):
        for j in range(nx):
            t0 = HIDE_T
            t1 = 1.0 - HIDE_T
            for k in range(h0, h1):
                num = hb[k] - (hA[k, 0] * S[a, 0] + hA[k, 1] * S[a, 1] + hA[k, 2] * S[a, 2])
                den = hA[k, 0] * (X[j, 0] - S[a, 0]) + hA[k, 1] * (X[j, 1] - S[a, 1]) + hA[k, 2] * (X[j, 2] - S[a, 2])
                if den > 0.0:
                    t1 = min(t1, num / den)
                elif den < 0.0:
                    t0 = max(t0, num / den)
                elif num < 0.0:
                    return False
                if t0 > t1:
                    return False
    return True


@numba.njit(cache=True)
def _separated(X, nx, pn, pd, p0, p1, margin):
    """Whether all of ``X[:nx]`` lies beyond one of the planes ``p0 .. p1`` by ``margin``."""
    for k in range(p0, p1):
        ok = True
        for j in range(nx):
            if pn[k, 0] * X[j, 0] + pn[k, 1] * X[j, 1] + pn[k, 2] * X[j, 2] - pd[k] <= margin:
                ok = False
                break
        if ok:
            return True
    return False


@numba.njit(cache=True)
def _relations(X, nx, s_verts, s_off, kind, poff, pn, pd, margin, hA, hb, hoff, cand, rel):
    """Relation of every (source, piece) pair to the receivers ``X[:nx]``; pairs with ``cand`` false skipped.

    Returns the class: lit, umbra or exact.
    """
    ns = kind.shape[0]
    npc = kind.shape[1]
    lit = True
    umbra = True
    for s in range(ns):
        S = s_verts[s_off[s]:s_off[s + 1]]
        hidden = False
        for j in range(npc):
            if not cand[s, j]:
                continue
            r = REL_UNKNOWN
            if kind[s, j] == 1:
                r = REL_SEPARATED
            elif kind[s, j] == 0 and _separated(X, nx, pn, pd, poff[s * npc + j], poff[s * npc + j + 1], margin):
                r = REL_SEPARATED
            elif _hides(X, nx, S, hA, hb, hoff[j], hoff[j + 1]):
                r = REL_HIDES
                hidden = True
            rel[s, j] = r
            if r != REL_SEPARATED:
                lit = False
        if not hidden:
            umbra = False
    if lit:
        return CLASS_LIT
    if umbra:
        return CLASS_UMBRA
    return CLASS_EXACT


@numba.njit(cache=True)
def _classify_tiles(P, tile, ntiles, s_verts, s_off, kind, poff, pn, pd, margin, hA, hb, hoff, needed):
    """Each tile's class from its bounding box, and its relation to each (source, piece) pair."""
    n = P.shape[0]
    ns = kind.shape[0]
    npc = kind.shape[1]
    lo = np.full((ntiles, 3), np.inf)
    hi = np.full((ntiles, 3), -np.inf)
    for i in range(n):
        t = tile[i]
        for c in range(3):
            lo[t, c] = min(lo[t, c], P[i, c])
            hi[t, c] = max(hi[t, c], P[i, c])
    X = np.empty((8, 3))
    rel = np.empty((ntiles, ns, npc), dtype=np.int8)
    tcls = np.empty(ntiles, dtype=np.int8)
    allc = np.ones((ns, npc), dtype=np.bool_)
    for t in range(ntiles):
        if lo[t, 0] > hi[t, 0]:
            tcls[t] = CLASS_EXACT
            continue
        k = 0
        for a in range(2):
            for b in range(2):
                for c in range(2):
                    X[k, 0] = lo[t, 0] if a == 0 else hi[t, 0]
                    X[k, 1] = lo[t, 1] if b == 0 else hi[t, 1]
                    X[k, 2] = lo[t, 2] if c == 0 else hi[t, 2]
                    k += 1
        tcls[t] = _relations(X, 8, s_verts, s_off, kind, poff, pn, pd, margin, hA, hb, hoff, allc, rel[t])
        for j in range(npc):
            needed[t, j] = False
            for s in range(ns):
                if rel[t, s, j] != REL_SEPARATED:
                    needed[t, j] = True
    return tcls, rel


@numba.njit(cache=True, nogil=True)
def _classify_points(P, tile, tcls, rel, s_verts, s_off, kind, poff, pn, pd, margin, hA, hb, hoff, i0, i1, cls):
    """Receivers ``i0 .. i1``: their tile's class, or their own where the tile is neither lit nor umbra."""
    ns = kind.shape[0]
    npc = kind.shape[1]
    X = np.empty((1, 3))
    prel = np.empty((ns, npc), dtype=np.int8)
    cand = np.empty((ns, npc), dtype=np.bool_)
    for i in range(i0, i1):
        t = tile[i]
        if tcls[t] != CLASS_EXACT:
            cls[i] = tcls[t]
            continue
        for s in range(ns):  # only the pairs the tile left open are tested again
            for j in range(npc):
                cand[s, j] = rel[t, s, j] == REL_UNKNOWN
                prel[s, j] = rel[t, s, j]
        X[0, 0] = P[i, 0]
        X[0, 1] = P[i, 1]
        X[0, 2] = P[i, 2]
        _relations(X, 1, s_verts, s_off, kind, poff, pn, pd, margin, hA, hb, hoff, cand, prel)
        lit = True
        umbra = True
        for s in range(ns):
            hidden = False
            for j in range(npc):
                if prel[s, j] != REL_SEPARATED:
                    lit = False
                if prel[s, j] == REL_HIDES:
                    hidden = True
            if not hidden:
                umbra = False
        cls[i] = CLASS_LIT if lit else (CLASS_UMBRA if umbra else CLASS_EXACT)


@numba.njit(cache=True)
def bounding_box(P):
    """(lo, hi) of the rows of P (one pass; numpy's min and max over axis 0 are strided)."""
    lo = np.full(3, np.inf)
    hi = np.full(3, -np.inf)
    for i in range(P.shape[0]):
        for c in range(3):
            x = P[i, c]
            if x < lo[c]:
                lo[c] = x
            if x > hi[c]:
                hi[c] = x
    return lo, hi


@numba.njit(cache=True)
def _tile_keys(P, lo, ext, cells):
    out = np.empty(P.shape[0], dtype=np.int64)
    for i in range(P.shape[0]):
        key = 0
        for c in range(3):
            k = 0
            if ext[c] > 0.0:
                f = (P[i, c] - lo[c]) / ext[c] * cells[c]
                if f >= cells[c] - 1:  # (also an overflow to inf)
                    k = cells[c] - 1
                elif f > 0.0:
                    k = int(f)
            key = key * cells[c] + k
        out[i] = key
    return out


def _tiles(points: NDArray[np.float64], per_tile: int,
           box: NDArray[np.float64] | None = None) -> tuple[NDArray[np.int64], int]:
    """Tile index of each point: cells of a grid over the bounding box (``box`` when the caller
    has it), about ``per_tile`` points each."""
    n = len(points)
    want = max(1, n // max(per_tile, 1))
    lo, hi = bounding_box(points) if box is None else (box[0], box[1])
    ext = hi - lo
    cells = np.ones(3, dtype=np.int64)
    # square-ish cells: split the axis whose cells are longest while the count stays within want
    while True:
        ax = int(np.argmax(ext / cells))
        if not ext[ax] > 0 or np.prod(cells) // cells[ax] * (cells[ax] + 1) > want:
            break
        cells[ax] += 1
    return _tile_keys(points, lo, ext, cells), int(np.prod(cells))


def classify_receivers(
    points: NDArray[np.float64], sources: SourceArrays, pieces: list, scale: float, *, per_tile: int = TILE_POINTS,
    box: NDArray[np.float64] | None = None,
) -> ReceiverClasses:
    """Lit, umbra or exact class of each receiver against the given convex occluder pieces (module docstring).

    Parameters
    ----------
    points : ndarray, shape (n, 3)
    sources : SourceArrays
        The emitting polygons.
    pieces : list of ConvexPiece
        The occluder pieces these receivers see.
    scale : float
        The scene's size (the margins are relative to it).
    per_tile : int, keyword-only
        Receivers per tile (about).
    box : ndarray, shape (2, 3), keyword-only, optional
        The points' bounding box (rows lo, hi), when the caller has it.

    Returns
    -------
    ReceiverClasses
    """
    n = len(points)
    tab = _PairTables(sources, pieces, scale)
    tile, ntiles = _tiles(points, per_tile, box) if n else (np.zeros(0, dtype=np.int64), 1)
    cls = np.empty(n, dtype=np.int8)
    needed = np.zeros((ntiles, len(pieces)), dtype=np.bool_)
    if n:
        P = np.ascontiguousarray(points)
        pairs = (sources.verts, sources.off, tab.kind, tab.poff, tab.pn, tab.pd, tab.margin, tab.hA, tab.hb, tab.hoff)
        tcls, rel = _classify_tiles(P, tile, ntiles, *pairs, needed)
        nchunk = min(8 * _threads(), -(-n // CLASSIFY_CHUNK))
        run_chunks(nchunk, lambda c: _classify_points(P, tile, tcls, rel, *pairs, c * n // nchunk,
                                                      (c + 1) * n // nchunk, cls))
    return ReceiverClasses(cls, tile, needed)



@numba.njit(cache=True)
def class_indices(cls, tile, ntiles):
    """(lit, umbra, exact) receiver indices, the tiles the exact ones use (ascending) and each one's place in them.

    One pass over the receivers: what ``np.nonzero`` per class and ``np.unique(tile[exact],
    return_inverse=True)`` give, without the sort.
    """
    n = cls.shape[0]
    counts = np.zeros(3, dtype=np.int64)
    for i in range(n):
        counts[cls[i]] += 1
    lit = np.empty(counts[CLASS_LIT], dtype=np.int64)
    umbra = np.empty(counts[CLASS_UMBRA], dtype=np.int64)
    exact = np.empty(counts[CLASS_EXACT], dtype=np.int64)
    place = np.full(ntiles, -1, dtype=np.int64)
    k0 = k1 = k2 = 0
    for i in range(n):
        c = cls[i]
        if c == CLASS_LIT:
            lit[k0] = i
            k0 += 1
        elif c == CLASS_UMBRA:
            umbra[k2] = i
            k2 += 1
        else:
            exact[k1] = i
            k1 += 1
            place[tile[i]] = 0
    used = 0
    for t in range(ntiles):
        if place[t] == 0:
            place[t] = used
            used += 1
    tiles_used = np.empty(used, dtype=np.int64)
    local = np.empty(k1, dtype=np.int64)
    for t in range(ntiles):
        if place[t] >= 0:
            tiles_used[place[t]] = t
    for k in range(k1):
        local[k] = place[tile[exact[k]]]
    return lit, umbra, exact, tiles_used, local


@numba.njit(cache=True)
def _whole_sources(s_verts, s_off, s_u, s_w, s_q0):
    """Each source polygon's vertices as the exact path rebuilds them (2D source frame, back to 3D), and its area.

    The arithmetic of :func:`~isocsg.shadows.visibility._source_polygon` and
    :func:`~isocsg.shadows.visibility._lambert2` for a polygon wholly in front of
    the receiving plane, which does not depend on the receiver: done once.
    """
    ns = s_q0.shape[0]
    R = np.empty((s_verts.shape[0], 3))
    area = np.empty(ns)
    for s in range(ns):
        q0 = s_q0[s]
        u = s_u[s]
        w = s_w[s]
        a0 = s_off[s]
        m = s_off[s + 1] - a0
        P2 = np.empty((m, 2))
        for k in range(m):
            qa = s_verts[a0 + k]
            P2[k, 0] = (qa[0] - q0[0]) * u[0] + (qa[1] - q0[1]) * u[1] + (qa[2] - q0[2]) * u[2]
            P2[k, 1] = (qa[0] - q0[0]) * w[0] + (qa[1] - q0[1]) * w[1] + (qa[2] - q0[2]) * w[2]
            R[a0 + k, 0] = q0[0] + P2[k, 0] * u[0] + P2[k, 1] * w[0]
            R[a0 + k, 1] = q0[1] + P2[k, 0] * u[1] + P2[k, 1] * w[1]
            R[a0 + k, 2] = q0[2] + P2[k, 0] * u[2] + P2[k, 1] * w[2]
        area[s] = _area2(P2, m) if m >= 3 else 0.0
    return R, area


LIT_BLOCK = 512  # lit receivers evaluated together, one pass over them per source edge


@numba.njit(cache=True, error_model="numpy")
def _edge_sums(px, py, pz, nx, ny, nz, m, R, a0, a1, val):
    """``val[i]`` = the edge sum of polygon ``R[a0:a1]`` at receivers ``i < m``: a loop over receivers per edge
    (it vectorises)."""
    for i in range(m):
        val[i] = 0.0
    for k in range(a0, a1):
        k1 = k + 1 if k + 1 < a1 else a0
        qax, qay, qaz = R[k, 0], R[k, 1], R[k, 2]
        qbx, qby, qbz = R[k1, 0], R[k1, 1], R[k1, 2]
        for i in range(m):
            val[i] += edge_term_fast(px[i], py[i], pz[i], nx[i], ny[i], nz[i], qax, qay, qaz, qbx, qby, qbz)


@numba.njit(cache=True, nogil=True, error_model="numpy")
def _lit_kernel(P, NR, idx, s_verts, s_off, s_normal, s_u, s_w, s_q0, s_L, s_group, ngroups, scale,
                R, s_area, vmax, b0, b1, E, state):
    """The exact path's arithmetic for receivers ``idx`` that see every source polygon whole (or not at all).

    Blocks ``b0 .. b1`` of ``LIT_BLOCK`` receivers; ``NR`` holds one normal a receiver or a single row for all.
    A source polygon wholly in front of a receiving plane takes the vectorised edge sums; one cut by it
    takes the exact path's own clipping.
    """
    n = idx.shape[0]
    ns = s_L.shape[0]
    one = NR.shape[0] == 1
    P2 = np.empty((vmax, 2))
    px = np.empty(LIT_BLOCK)
    py = np.empty(LIT_BLOCK)
    pz = np.empty(LIT_BLOCK)
    nx = np.empty(LIT_BLOCK)
    ny = np.empty(LIT_BLOCK)
    nz = np.empty(LIT_BLOCK)
    val = np.empty(LIT_BLOCK)
    e = np.empty(LIT_BLOCK)
    whole = np.empty(LIT_BLOCK, dtype=np.bool_)
    seen = np.empty((LIT_BLOCK, max(ngroups, 1)), dtype=np.bool_)
    for b in range(b0, b1):
        i0 = b * LIT_BLOCK
        m = min(n, i0 + LIT_BLOCK) - i0
        for ii in range(m):
            i = idx[i0 + ii]
            px[ii] = P[i, 0]
            py[ii] = P[i, 1]
            pz[ii] = P[i, 2]
            r = 0 if one else i
            nx[ii] = NR[r, 0]
            ny[ii] = NR[r, 1]
            nz[ii] = NR[r, 2]
            e[ii] = 0.0
            for g in range(ngroups):
                seen[ii, g] = False
        for s in range(ns):
            q0 = s_q0[s]
            N = s_normal[s]
            a0 = s_off[s]
            a1 = s_off[s + 1]
            for ii in range(m):
                whole[ii] = True
            for k in range(a0, a1):
                qa = s_verts[k]
                for ii in range(m):
                    d = nx[ii] * (qa[0] - px[ii]) + ny[ii] * (qa[1] - py[ii]) + nz[ii] * (qa[2] - pz[ii])
                    whole[ii] = whole[ii] and d >= 0.0
            usable = a1 - a0 >= 3 and s_area[s] > 0.0
            if usable:
                _edge_sums(px, py, pz, nx, ny, nz, m, R, a0, a1, val)
            g = s_group[s]
            for ii in range(m):
                h = N[0] * (px[ii] - q0[0]) + N[1] * (py[ii] - q0[1]) + N[2] * (pz[ii] - q0[2])
                if h <= 1e-14 * scale:  # as _source_polygon: in or behind the source plane
                    continue
                if whole[ii]:
                    if not usable:
                        continue
                    v = val[ii]
                else:  # cut by the receiving plane: the exact path's own clipping
                    i = idx[i0 + ii]
                    nr = NR[0] if one else NR[i]
                    n2, h2, A0 = _source_polygon(P[i], nr, s, s_verts, s_off, s_normal, s_u, s_w, s_q0, scale, P2)
                    if n2 == 0 or A0 <= 0.0:
                        continue
                    v = _lambert2(P2, n2, P[i], nr, q0, s_u[s], s_w[s])
                e[ii] += 0.5 * s_L[s] * v
                seen[ii, g] = True
        for ii in range(m):
            i = idx[i0 + ii]
            E[i] = e[ii]
            worst = 0
            for g in range(ngroups):
                if not seen[ii, g]:
                    worst = 2
            state[i] = worst


def lit_illuminance(
    points: NDArray[np.float64], normals: NDArray[np.float64], idx: NDArray[np.int64], sources: SourceArrays,
    scale: float, E: NDArray[np.float64], state: NDArray[np.int8],
) -> None:
    """Illuminance and state (into ``E`` and ``state``) of receivers ``idx`` that see every source whole.

    The exact path without silhouettes; ``normals`` has a row a receiver or a single row.
    """
    n = len(idx)
    if n == 0 or len(sources.radiance) == 0:
        return
    msrc = int(np.max(np.diff(sources.off)))
    R, area = _whole_sources(sources.verts, sources.off, sources.u, sources.w, sources.q0)
    args = (np.ascontiguousarray(points), np.ascontiguousarray(normals), np.ascontiguousarray(idx, dtype=np.int64),
            sources.verts, sources.off, sources.normal, sources.u, sources.w, sources.q0, sources.radiance,
            sources.group, sources.ngroups, float(scale), R, area, msrc + 2)
    nblocks = -(-n // LIT_BLOCK)
    nchunk = min(nblocks, 8 * _threads())  # runs of blocks
    run_chunks(nchunk, lambda c: _lit_kernel(*args, c * nblocks // nchunk, (c + 1) * nblocks // nchunk, E, state))
