"""The true topology of an all-planar tree, from its exact boundary polygons (no mesh engine).

Every face of a box or convex polyhedron is cut into the parts on the result's boundary by
:func:`isocsg.testing.planar.face_regions` (shapely's snap-rounded overlay, the same polygons
as the area): each part a polygon with holes, oriented counter-clockwise seen from the result's
outside. These polygons form a complex: their corners, brought to 3D, are merged where they are
within ``MERGE`` of the scene's size (the overlay's grid is 1e-12 of a face's size), and a
corner of one polygon on the inside of another polygon's edge (a T-junction: the two faces
were cut by different neighbours) splits that edge. Then, with no mesh in between,

- every edge of the complex is used by as many polygons in one direction as in the other
  (a closed, oriented surface; otherwise the complex is refused and ``None`` returned);
- an edge of two polygons joins them; an edge of ``2m`` polygons (sheets of the result that
  touch along it) joins each polygon to its neighbour around the edge across the solid: the
  touching sheets are kept apart, as manifold3d keeps them (the boundary of the solid shrunk by
  an infinitesimal amount); the components are the polygons so joined;
- a vertex counts once for each fan of corners joined through those edges (a vertex where sheets
  touch counts once per sheet); where a polygon's rings pass through a vertex more than once (a
  hole touching the outer ring or another hole, as at a corner that many cubes share), its
  corners there are the sectors between its edges in angular order, not the rings' successions;
  where they do not alternate around the vertex (edges that cross within the merging
  tolerance) the polygons are refused;
- ``chi = V - E + sum over polygons of chi(open polygon)`` per component, with
  ``chi(open polygon) = 2 * pieces - walks``: its boundary walks corner by corner bound planar
  pieces, each with one counter-clockwise walk (``1 - h`` for a polygon with ``h`` holes that
  touch nothing); its genus is ``(2 - chi) / 2`` and must be a whole number (else ``None``);
- a component whose enclosed volume (the flux of ``x / 3`` through its polygons) is negative is a
  void: the inner shell of a cavity;
- ``touching`` also where a corner of a leaf lies on another leaf's face plane without a face of
  its own in that plane (a contact at a point or along a line, :func:`_contacts`): there a mesh
  engine may join or separate the sheets either way (and the polygons' counts were not always
  right on grid trees with such contacts).

Where the polygons do not close into an oriented surface, a polygon's edges cross at a vertex
its rings pass twice, or a component's characteristic is odd or above 2, :func:`planar_topology`
returns None and :func:`refusal` says why: the caller (:func:`isocsg.testing.compare.true_topology`)
then reads the topology from a mesh, and says so.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..csg.section import solid_program
from ..kinds import Solid

__all__ = ["BoundaryPolygon", "ComplexTopology", "boundary_polygons", "complex_topology", "planar_topology", "refusal"]

F64 = NDArray[np.float64]
I64 = NDArray[np.int64]
#: A leaf's corner within this fraction of the scene's size of another leaf's face plane is a
#: contact: the result's sheets may touch there (``touching``).
NEAR = 1e-9
#: Polygon corners closer than this fraction of the scene's size are one vertex: three times
#: the overlay's 1e-12 grid at ten times a face's size, and the reference's coincidence
#: tolerance (1e-11 of the scene, ``isocsg.testing.area.COINCIDENT``) twice over: a face that
#: another leaf's face holds within that tolerance is cut as if they were one plane.
MERGE = 3e-11


@dataclass(frozen=True, slots=True)
class ComplexTopology:
    """The topology of a closed polygon complex: ``components`` (closed surfaces, touching
    sheets apart), ``genus`` (summed), ``euler`` (V - E + F, summed), ``voids`` (components
    that bound a cavity), ``touching`` (whether sheets of the result meet at an edge or a
    vertex) and ``component_euler`` (each component's characteristic, in the order found)."""

    components: int
    genus: int
    euler: int
    voids: int
    touching: bool
    component_euler: tuple[int, ...]


@dataclass(frozen=True, slots=True, eq=False)
class BoundaryPolygon:
    """One polygon of the boundary: its rings in 3D (outer first, holes after; counter-clockwise
    seen from ``normal``'s side for the outer ring), the result's outward unit ``normal``, its
    ``area`` and ``offset`` (``normal . x`` on its plane)."""

    rings: tuple[F64, ...]
    normal: F64
    area: float
    offset: float


def boundary_polygons(solid: Solid) -> list[BoundaryPolygon] | None:
    """The polygons of an all-planar tree's boundary (see the module docstring), or None where
    a leaf is not a box or convex polyhedron, or the overlay fails on both grids."""
    import shapely
    from shapely.errors import GEOSException

    from .area import SNAP, _Tree
    from .planar import Neighbours, PlanarFace, face_regions

    prog = solid_program(solid)
    if prog.n_leaves == 0 or not all(p.polyhedral and p.convex for p in prog.leaves):
        return None
    tree = _Tree(prog)
    out: list[BoundaryPolygon] = []
    for i, leaf in enumerate(prog.leaves):
        nb = Neighbours(tree.relevant(i).tolist(), tree.planes)
        for V, n in leaf.flat_faces():
            face = PlanarFace(V, n)
            size = float(np.max(np.abs(face.uv)))
            regions = None
            for grid in (SNAP * size, 100 * SNAP * size):
                try:
                    regions = face_regions(prog, i, face, nb, tree.tol, grid=grid)
                    break
                except GEOSException:
                    continue
            if regions is None:
                return None
            frame = np.stack([face.e1, face.e2])
            for geom, sign in ((regions[0], 1.0), (regions[1], -1.0)):
                for poly in shapely.get_parts(geom):
                    if poly.geom_type != "Polygon" or poly.is_empty or poly.area <= 0:
                        continue
                    poly = shapely.orient_polygons(poly, exterior_cw=sign < 0)  # CCW seen from outside
                    rings = [np.asarray(r.coords)[:-1] for r in (poly.exterior, *poly.interiors)]
                    out.append(BoundaryPolygon(tuple(face.o + r @ frame for r in rings), sign * face.n,
                                               float(poly.area), sign * face.d))
    return out


def _groups(n: int, a: I64, b: I64) -> tuple[int, I64]:
    """Connected components of ``n`` nodes joined by the pairs ``(a, b)``."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    adj = coo_matrix((np.ones(len(a)), (a, b)), shape=(n, n))
    k, labels = connected_components(adj, directed=False)
    return int(k), np.asarray(labels, dtype=np.int64)


def _merged_rings(polys: list[BoundaryPolygon], tol: float) -> tuple[F64, list[list[I64]]]:
    """Vertices merged within ``tol`` and each polygon's rings as vertex ids, with repeated
    neighbours dropped and T-junctions inserted."""
    from scipy.spatial import cKDTree

    pts = np.concatenate([r for p in polys for r in p.rings])
    pairs = cKDTree(pts).query_pairs(tol, output_type="ndarray")
    _, label = _groups(len(pts), pairs[:, 0], pairs[:, 1])
    uniq, first = np.unique(label, return_index=True)
    P = pts[first]
    ids = np.searchsorted(uniq, label)
    rings: list[list[I64]] = []
    k = 0
    for p in polys:
        rs: list[I64] = []
        for h, r in enumerate(p.rings):
            v = ids[k: k + len(r)]
            k += len(r)
            v = v[v != np.roll(v, 1)] if len(v) > 1 else v
            if len(v) >= 3 and (h == 0 or rs):
                rs.append(v)
        rings.append(rs)  # empty where the outer ring collapsed (a sliver narrower than tol)
    return P, _split_edges(P, rings, tol)


def _split_edges(P: F64, rings: list[list[I64]], tol: float) -> list[list[I64]]:
    """Each ring with the vertices that lie inside its edges (within ``tol``) inserted in order."""
    from scipy.spatial import cKDTree

    kd = cKDTree(P)
    out: list[list[I64]] = []
    for rs in rings:
        new: list[I64] = []
        for v in rs:
            a, b = v, np.roll(v, -1)
            mid, half = 0.5 * (P[a] + P[b]), 0.5 * np.linalg.norm(P[b] - P[a], axis=1)
            near = kd.query_ball_point(mid, half + tol)
            seq: list[int] = []
            for e, cand in enumerate(near):
                seq.append(int(a[e]))
                c = np.asarray([x for x in cand if x != a[e] and x != b[e]], dtype=np.int64)
                if len(c) == 0:
                    continue
                d = P[b[e]] - P[a[e]]
                t = (P[c] - P[a[e]]) @ d / (d @ d)
                off = np.linalg.norm(P[c] - P[a[e]] - t[:, None] * d, axis=1)
                keep = (off <= tol) & (t > 0) & (t < 1)
                seq.extend(c[keep][np.argsort(t[keep])].tolist())
            w = _without_spikes(np.asarray(seq, dtype=np.int64))
            if len(w) >= 3 and (not new or len(new[0]) >= 3):
                new.append(w)
            elif not new:
                new.append(w[:0])  # the outer ring is gone: so is the polygon
        out.append(new if new and len(new[0]) >= 3 else [])
    return out


def _without_spikes(w: I64) -> I64:
    """A ring without repeated neighbours and without spikes ``x, y, x`` (a sliver narrower than
    the tolerance, its vertices merged or put on its edges, folds back on itself)."""
    ring = w.tolist()
    changed = True
    while changed and len(ring) >= 3:
        changed = False
        for k in range(len(ring)):
            m = len(ring)
            if ring[k] == ring[(k + 1) % m]:
                del ring[k]
                changed = True
                break
            if ring[k] == ring[(k + 2) % m]:
                for j in sorted({(k + 1) % m, (k + 2) % m}, reverse=True):
                    del ring[j]
                changed = True
                break
    return np.asarray(ring if len(ring) >= 3 else [], dtype=np.int64)


def _pair_around(P: F64, he: list[int], src: I64, dst: I64, normal: F64) -> dict[int, int] | None:
    """The half-edges of one edge shared by more than two polygons paired across the solid: each
    polygon with its neighbour around the edge on its inner side (the side ``-normal``)."""
    lo, hi = min(src[he[0]], dst[he[0]]), max(src[he[0]], dst[he[0]])
    d = P[hi] - P[lo]
    d = d / np.linalg.norm(d)
    x = np.cross(d, np.eye(3)[int(np.argmin(np.abs(d)))])
    x /= np.linalg.norm(x)
    y = np.cross(d, x)
    h = np.asarray(he)
    t = P[dst[h]] - P[src[h]]
    t /= np.linalg.norm(t, axis=1, keepdims=True)
    w = np.cross(normal, t)  # into each polygon from the edge (its rings are counter-clockwise)
    order = h[np.argsort(np.arctan2(w @ y, w @ x))]
    w_of = dict(zip(h.tolist(), range(len(h))))
    ahead = np.einsum("ij,ij->i", np.cross(d, w), -normal) > 0  # the solid follows at growing angle
    k = len(order)
    pos = {int(e): j for j, e in enumerate(order.tolist())}
    mate = {}
    for e in order.tolist():
        j = pos[e]
        mate[e] = int(order[(j + 1) % k] if ahead[w_of[e]] else order[(j - 1) % k])
    if any(mate[mate[e]] != e or src[mate[e]] != dst[e] for e in mate):
        return None
    return mate


def complex_topology(polys: list[BoundaryPolygon], tol: float) -> ComplexTopology | None:
    """The topology of a closed polygon complex (see the module docstring), or None where it is
    not a closed oriented surface (:func:`refusal` says why)."""
    out = _complex(polys, tol)
    return None if isinstance(out, str) else out


def _complex(polys: list[BoundaryPolygon], tol: float) -> ComplexTopology | str:
    if not polys:
        return ComplexTopology(0, 0, 0, 0, False, ())
    P, rings = _merged_rings(polys, tol)
    alive = [f for f, rs in enumerate(rings) if rs]
    polys, rings = [polys[f] for f in alive], [rings[f] for f in alive]
    src_l, dst_l, poly_l, nxt_l = [], [], [], []
    base = 0
    for f, rs in enumerate(rings):
        for v in rs:
            m = len(v)
            src_l.append(v)
            dst_l.append(np.roll(v, -1))
            poly_l.append(np.full(m, f))
            nxt_l.append(base + (np.arange(m) + 1) % m)
            base += m
    if base == 0:
        return ComplexTopology(0, 0, 0, 0, False, ())
    src, dst, poly, nxt = (np.concatenate(a).astype(np.int64) for a in (src_l, dst_l, poly_l, nxt_l))
    normals = np.stack([p.normal for p in polys])
    if not _pinched_corners(P, src, dst, poly, nxt, normals):
        return "a polygon's edges at a vertex its rings pass twice cross within the merging tolerance"
    nv = len(P)
    key = np.minimum(src, dst) * nv + np.maximum(src, dst)
    order = np.argsort(key, kind="stable")
    bounds = np.flatnonzero(np.diff(key[order])) + 1
    mate = np.full(base, -1, dtype=np.int64)
    touching = False
    for grp in np.split(order, bounds):
        if len(grp) % 2 or 2 * np.count_nonzero(src[grp] < dst[grp]) != len(grp):
            return "an edge used more often one way than the other"
        if len(grp) == 2:
            if src[grp[0]] != dst[grp[1]]:
                return "an edge used twice the same way"
            mate[grp[0]], mate[grp[1]] = grp[1], grp[0]
            continue
        touching = True
        pairs = _pair_around(P, grp.tolist(), src, dst, normals[poly[grp]])
        if pairs is None:
            return "the polygons around an edge do not pair across the solid"
        for a, b in pairs.items():
            mate[a] = b
    n_comp, comp = _groups(len(polys), poly, poly[mate])
    n_corner, corner = _groups(base, np.arange(base), nxt[mate])  # the fans of corners at each vertex
    at_vertex = np.zeros(nv, dtype=np.int64)
    np.add.at(at_vertex, src[np.unique(corner, return_index=True)[1]], 1)
    touching = touching or bool(np.any(at_vertex > 1))
    V = np.bincount(comp[poly[np.unique(corner, return_index=True)[1]]], minlength=n_comp)
    E = np.bincount(comp[poly], minlength=n_comp) // 2
    F = np.bincount(comp, weights=_open_euler(P, src, dst, poly, nxt, normals), minlength=n_comp).astype(np.int64)
    chi = V - E + F
    if np.any(chi % 2) or np.any(chi > 2):
        return f"components' Euler characteristics {chi.tolist()}"
    centre = 0.5 * (P.min(axis=0) + P.max(axis=0))
    flux = np.array([p.area * (p.offset - p.normal @ centre) / 3.0 for p in polys])
    vol = np.bincount(comp, weights=flux, minlength=n_comp)
    genus = int(np.sum((2 - chi) // 2))
    tiny = 1e-12 * float(np.max(np.ptp(P, axis=0))) ** 3  # a sliver's sign is rounding
    return ComplexTopology(n_comp, genus, int(chi.sum()), int(np.count_nonzero(vol < -tiny)), touching,
                           tuple(int(c) for c in chi))


def _pinched_corners(P: F64, src: I64, dst: I64, poly: I64, nxt: I64, normals: F64) -> bool:
    """Where a polygon's rings pass through one vertex more than once (a hole touching the outer
    ring or another hole there), its corners at that vertex are the sectors between its edges
    in angular order, not the rings' own successions: each incoming edge is followed (``nxt``,
    in place) by the first outgoing edge clockwise from it, seen from outside (the polygon lies
    to the left of its edges). False where they do not alternate (arriving, leaving) around the
    vertex: a polygon's edges cross there within the merging tolerance."""
    key = poly * len(P) + src
    order = np.argsort(key, kind="stable")
    bounds = np.flatnonzero(np.diff(key[order])) + 1
    prev = np.empty_like(nxt)
    prev[nxt] = np.arange(len(nxt))
    starts = np.concatenate([[0], bounds])
    sizes = np.diff(np.concatenate([starts, [len(order)]]))
    for s0, size in zip(starts[sizes > 1].tolist(), sizes[sizes > 1].tolist()):  # pinched vertices only
        grp = order[s0:s0 + size]
        n = normals[poly[grp[0]]]
        e1 = np.cross(n, np.eye(3)[int(np.argmin(np.abs(n)))])
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(n, e1)
        outs, ins = grp, prev[grp]  # the half-edges leaving the vertex, and those arriving
        d_out = P[dst[outs]] - P[src[outs]]
        d_in = P[src[ins]] - P[dst[ins]]  # from the vertex back along the arriving edge
        ang = np.concatenate([np.arctan2(d_out @ e2, d_out @ e1), np.arctan2(d_in @ e2, d_in @ e1)])
        ang = np.round(ang, 9)  # directions within 1e-9 of each other are one: merged slivers
        ang[ang <= -np.pi] = np.pi
        kind = np.concatenate([np.ones(len(outs), np.int64), np.zeros(len(ins), np.int64)])
        ids = np.concatenate([outs, ins])
        # along one direction an arriving and a leaving edge bound either no sector (the two
        # sides of a slit: arriving first) or a sliver merged flat (leaving first)
        pairs = _sectors(ang, kind, ids, 0)
        pairs = _sectors(ang, kind, ids, 1) if pairs is None else pairs
        if pairs is None:
            return False  # the edges interleave within the tolerance: no sectors
        nxt[list(pairs)] = list(pairs.values())
    return True


def _sectors(ang: F64, kind: I64, ids: I64, first: int) -> dict[int, int] | None:
    """Each arriving edge (``kind`` 0) paired with the leaving edge (1) clockwise from it, with
    the edges of kind ``first`` first at equal angles; None unless they alternate."""
    srt = np.lexsort((kind if first == 0 else 1 - kind, ang))
    k = len(srt)
    pairs = {}
    for j in range(k):
        if kind[srt[j]] == 0:
            o = srt[(j - 1) % k]
            if kind[o] == 1:
                pairs[int(ids[srt[j]])] = int(ids[o])
    alternate = len(pairs) == np.count_nonzero(kind == 0) and len(set(pairs.values())) == np.count_nonzero(kind == 1)
    return pairs if alternate else None


def _open_euler(P: F64, src: I64, dst: I64, poly: I64, nxt: I64, normals: F64) -> F64:
    """Each open polygon's Euler characteristic (with compact support): its boundary walks (the
    cycles of ``nxt``: rings, joined or split where they touch, corner by corner) bound planar
    pieces, each with exactly one walk counter-clockwise seen from outside (positive area) and
    the others its holes; so ``chi = 2 * pieces - walks``: ``1 - h`` for a polygon with ``h``
    holes, 1 where a hole touches the outer ring, 2 where the outer ring is pinched into two."""
    n = len(nxt)
    _, walk = _groups(n, np.arange(n), nxt)
    first = np.full(len(normals), n, dtype=np.int64)
    np.minimum.at(first, poly, np.arange(n))
    o = P[src[first[poly]]]  # a corner of each polygon: small coordinates, exact enough areas
    area = np.einsum("ij,ij->i", np.cross(P[src] - o, P[dst] - o), normals[poly])
    walks = np.unique(walk)
    signed = np.bincount(walk, weights=area, minlength=len(walks))
    owner = np.zeros(len(walks), dtype=np.int64)
    owner[walk] = poly
    chi = np.bincount(owner[walks], weights=np.where(signed[walks] > 0, 2.0, 0.0) - 1.0, minlength=len(normals))
    return np.asarray(chi, dtype=np.float64)


def planar_topology(solid: Solid) -> ComplexTopology | None:
    """The true topology of an all-planar tree from its boundary polygons, or None where a leaf
    is curved, the overlay fails, or the polygons do not close into an oriented surface.

    Examples
    --------
    >>> from isocsg import Box
    >>> ring = Box((0, 0, 0), (3, 3, 1)) - Box((0, 0, 0), (1, 1, 2))
    >>> t = planar_topology(ring)
    >>> (t.components, t.genus, t.voids, t.touching)
    (1, 1, 0, False)
    """
    out = refusal(solid)
    return out if isinstance(out, ComplexTopology) else None


def refusal(solid: Solid) -> ComplexTopology | str:
    """:func:`planar_topology`, or why it is None (a sentence)."""
    polys = boundary_polygons(solid)
    if polys is None:
        return "a curved leaf, or an overlay that failed on both grids"
    from .area import COINCIDENT, _Tree

    tree = _Tree(solid_program(solid))
    out = _complex(polys, MERGE * tree.tol / COINCIDENT)  # MERGE of the scene's size
    if isinstance(out, ComplexTopology) and not out.touching and _contacts(tree, NEAR * tree.tol / COINCIDENT):
        out = ComplexTopology(out.components, out.genus, out.euler, out.voids, True, out.component_euler)
    return out


def _contacts(tree: Any, tol: float) -> bool:
    """Whether a corner of a leaf lies within ``tol`` of the plane of another leaf's face (whose
    box meets it) without a face of its own in that plane: a vertex or an edge on a face, where
    sheets of the result may touch at a point or along a line. Coincident faces (a pocket flush
    with a face) are not contacts: the overlay resolves them exactly."""
    from scipy.spatial import cKDTree

    for i, leaf in enumerate(tree.leaves):
        faces = leaf.flat_faces()
        corners = np.concatenate([V for V, _ in faces])
        normals = np.concatenate([np.broadcast_to(n, V.shape) for V, n in faces])
        same = cKDTree(corners).query_ball_point(corners, tol)  # one corner's copies on its faces
        for j in tree.relevant(i).tolist():
            N, D = tree.planes[j]
            near = np.abs(corners @ N.T - D) <= tol
            parallel = np.abs(normals @ N.T) >= 1.0 - 1e-9
            for c, r in zip(*np.nonzero(near)):
                if not np.any(parallel[same[c], r]):
                    return True
    return False
