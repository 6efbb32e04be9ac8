"""The boundary of a CSG solid as isoluminance bands: view-independent CSG.

Each leaf's surface bands (planar triangles of constant value, see
:mod:`isocsg.laminae`) are clipped in 3D against the other operands: the
band meshes are closed (:func:`close_mesh`), turned into manifold3d solids
whose triangles remember their band triangle, and combined with manifold3d's
exact mesh Booleans along the tree. Every triangle of the result lies on one
leaf's band triangle, so it keeps that band's constant value; where the
result's triangle faces the other way (the inside of a cut: the boundary of a
subtracted leaf, or of a leaf of an intersection seen from inside another),
it shows the band's reversed-normal value ``value_in``.

This is the design notes' "clip contour-aligned surface bands" resolution of
lamina ownership: each visible surface point takes the value of the leaf whose
boundary it lies on, decided once in object space. The renderer then fills
the result like any primitive (front faces, depth test), so a new viewpoint
costs a plain fill.

Scale. The tree is evaluated on axis-aligned boxes first: operands whose
boxes touch nothing they are combined with need no Boolean (a union keeps
them as they are, a difference drops the subtracted operands that miss its
first operand, an intersection drops what lies outside the common box), so
a leaf enters manifold3d only where it meets another operand, and the
Booleans that remain are manifold3d batch Booleans. All of it runs in a local
frame (the leaves' box mapped to [-1, 1]^3), since manifold3d's tolerances are
relative to the size and position of its meshes. For large trees
(``trim=True``), what is subtracted and the operands of intersections are cut
to the boxes where they matter first, and a difference of many cuts is parted
into slabs, so that each Boolean fits the memory bound.

Coincident faces. Regularised set operations leave no two coincident faces of
opposite orientation on a boundary, but manifold3d can leave such pairs (zero
volume fins and shells) where operands' faces coincide, e.g. in
``(S | C) - C`` or ``A - A``. Where two leaves have band triangles in one
plane, the result's triangles in those planes are tested, and those lying on
an opposite-facing triangle of the result are dropped
(:data:`COINCIDENT_DISTANCE`); a triangle only partly covered by opposite ones
keeps its part outside them.
"""

from __future__ import annotations

import ctypes
import functools
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numba import njit
from numpy.typing import ArrayLike, NDArray

from ..errors import InvalidGeometryError, InvalidParameterError, ResourceLimitError
from ..laminae.model import BandMesh
from ..laminae.split import mesh_edges
from ..limits import check_memory, memory_budget
from .mesh import _manifold3d
from .program import OP_DIFFERENCE, OP_INTERSECTION, OP_UNION, Program
from .tree import CSGNode

if TYPE_CHECKING:  # pragma: no cover
    from ..lighting.lights import Light, Material

__all__ = [
    "CSGSurface",
    "close_mesh",
    "csg_surface",
    "estimate_surface_bytes",
    "estimate_surface_triangles",
    "surface_from_bands",
    "untrimmed_groups",
]

# Relative distance (to the mesh size) within which a vertex lies on an open edge.
_ON_EDGE_RELATIVE = 1e-9
# Coordinates of magnitude m carry rounding of about eps * m: a vertex on an edge
# may be this many such units away from it (band meshes far from the origin).
_ON_EDGE_ULPS = 64.0
#: Distance, as a fraction of the tree's half-size, within which a triangle of
#: the result lies on an opposite-facing triangle (a zero-volume fin or shell,
#: which a regularised boundary cannot have; both sides are dropped).
COINCIDENT_DISTANCE = 1e-9
#: Peak working memory of the Booleans per band triangle that enters manifold3d
#: (manifold3d's half-edge meshes of the operands and the result, the Mesh64
#: copies and the output arrays; measured on the 1000-hole plate's slabs of about
#: 310 k trimmed triangles: 540 to 1100 bytes each, from a slab's first solid to
#: the next slab, more where more of the input is kept), and per triangle passed
#: through unchanged.
BYTES_PER_BOOLEAN_TRIANGLE = 1200
BYTES_PER_PLAIN_TRIANGLE = 200


@dataclass(frozen=True, slots=True, eq=False)
class CSGSurface:
    """The boundary of a CSG solid: triangles of constant value, each on one leaf.

    Triangles are kept sorted by leaf (stably: construction sorts them if
    needed), so that :meth:`leaf_bands` finds a leaf's part without a pass
    over the whole surface.

    Attributes
    ----------
    vertices : ndarray, shape (V, 3), float64
    triangles : ndarray, shape (T, 3), int32
        Counter-clockwise seen from outside the result.
    value : ndarray, shape (T,), float64
        The value each triangle shows: its band's ``value_out``, or
        ``value_in`` where the triangle is reversed.
    leaf : ndarray, shape (T,), int32
        Index of the leaf (in ``CSGNode.program()`` order) it lies on; non-decreasing.
    source : ndarray, shape (T,), int32
        Index of the leaf's band triangle it lies in.
    reversed : ndarray, shape (T,), bool
        True where the result's outward normal is the leaf's inward normal.
    """

    vertices: NDArray[np.float64]
    triangles: NDArray[np.int32]
    value: NDArray[np.float64]
    leaf: NDArray[np.int32]
    source: NDArray[np.int32]
    reversed: NDArray[np.bool_]

    def __post_init__(self) -> None:
        leaf = np.asarray(self.leaf)
        if len(leaf) > 1 and bool(np.any(leaf[1:] < leaf[:-1])):
            order = np.argsort(leaf, kind="stable")
            for name in ("triangles", "value", "leaf", "source", "reversed"):
                object.__setattr__(self, name, np.asarray(getattr(self, name))[order])

    @property
    def n_triangles(self) -> int:
        """Number of triangles."""
        return int(len(self.triangles))

    def leaf_bands(self, i: int) -> BandMesh:
        """The part on leaf ``i`` as a :class:`BandMesh` (both values set to the shown value).

        Only the vertices the part uses are kept (renumbered), so the parts of
        a surface of many leaves cost in total what the surface does.
        """
        # Same dtype as the leaf array: otherwise numpy converts all of it on every call.
        lo, hi = np.searchsorted(self.leaf, np.array([i, i + 1], dtype=self.leaf.dtype))
        tri = self.triangles[lo:hi]
        if not len(tri):
            return BandMesh(np.zeros((0, 3)), np.zeros((0, 3), np.int32), np.zeros(0), np.zeros(0), np.zeros(0, np.int32))
        first, last = int(tri.min()), int(tri.max())
        if last - first < 8 * len(tri):
            # A leaf's vertices are mostly contiguous: renumber through a mask of the range.
            mark = np.zeros(last - first + 1, bool)
            mark[tri - first] = True
            used = np.flatnonzero(mark) + first
            local = (np.cumsum(mark, dtype=np.int32) - 1)[tri - first]
        else:
            used, local = np.unique(tri, return_inverse=True)
        shown = self.value[lo:hi]
        return BandMesh(self.vertices[used], local.reshape(-1, 3).astype(np.int32), shown, shown, self.source[lo:hi])


def estimate_surface_triangles(bands: Sequence[BandMesh]) -> int:
    """About how many triangles the clipped surface of these band meshes has at most.

    The leaves' band triangles: the result keeps at most all of them (each
    split where other operands cut it, which adds about as many as a cut
    removes), so the sum sizes the Booleans' input and a bound for their
    output, known before anything is built.

    Parameters
    ----------
    bands : sequence of BandMesh
        One per leaf.

    Returns
    -------
    int

    Examples
    --------
    >>> from isocsg import PointLight, Sphere
    >>> from isocsg.laminae import build_laminae
    >>> from isocsg.lighting.lights import Material
    >>> b = build_laminae(Sphere((0, 0, 0), 1), (PointLight((0, -4, 3)),), Material(), 8).bands
    >>> estimate_surface_triangles([b, b]) == 2 * b.n_triangles
    True
    """
    return int(sum(int(len(b.triangles)) for b in bands))


def estimate_surface_bytes(bands: Sequence[BandMesh]) -> int:
    """An upper estimate of the working memory of :func:`surface_from_bands`, in bytes.

    Every band triangle is counted as if it entered the Booleans
    (:data:`BYTES_PER_BOOLEAN_TRIANGLE`); leaves that meet no other operand
    cost less (:data:`BYTES_PER_PLAIN_TRIANGLE`), which
    :func:`surface_from_bands` takes into account when it checks the memory
    budget.

    Examples
    --------
    >>> estimate_surface_bytes([]) == 0
    True
    """
    return estimate_surface_triangles(bands) * BYTES_PER_BOOLEAN_TRIANGLE


def close_mesh(
    vertices: NDArray[np.float64], triangles: NDArray[np.int64]
) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]:
    """Weld a triangle soup that tiles a closed surface into a closed mesh.

    Band meshes are cut face by face: equal vertices may be repeated, and a
    vertex of one face may lie inside an edge of its neighbour (a
    T-junction). Repeated vertices are merged (also those within the tolerance
    below of each other: a point cut from two faces comes out a few ulps
    apart), and each open edge with such
    vertices inside is split at them (its triangle becomes a fan, in the same
    plane, so the surface and the orientation are unchanged). A vertex lies on
    an edge within 1e-9 of the mesh size, or within the rounding of its
    coordinates where they are large (a mesh far from the origin).

    Parameters
    ----------
    vertices : ndarray, shape (V, 3)
    triangles : ndarray of int, shape (T, 3)

    Returns
    -------
    vertices : ndarray, shape (V', 3)
    triangles : ndarray of int64, shape (T', 3)
    source : ndarray of int64, shape (T',)
        The input triangle each output triangle lies in.

    Examples
    --------
    A unit square whose right half is split at the middle of the shared edge:

    >>> v = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [1, 0.5, 0], [2, 0, 0], [2, 1, 0]], float)
    >>> t = np.array([[0, 1, 2], [0, 2, 3], [1, 5, 4], [4, 5, 6], [4, 6, 2]])
    >>> _, t2, src = close_mesh(v, t)
    >>> len(t2), sorted(src.tolist())
    (6, [0, 0, 1, 2, 3, 4])
    """
    v, t, src, _ = _close(vertices, triangles)
    return v, t, src


def _close(
    vertices: NDArray[np.float64], triangles: NDArray[np.int64]
) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64], bool]:
    """:func:`close_mesh`, and whether every edge of the result is used by exactly two triangles."""
    v = np.ascontiguousarray(vertices, dtype=np.float64).reshape(-1, 3)
    t = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    src = np.arange(len(t), dtype=np.int64)
    if not len(t):
        return v, t, src, False
    # Bit-equal vertices are one vertex (+0.0: -0.0 == 0.0).
    first, inverse = _equal_rows(np.ascontiguousarray(v + 0.0).view(np.int64))
    v = v[first]
    t = inverse[t]
    size = float(np.ptp(v, axis=0).max())
    magnitude = float(np.abs(v).max())
    tol = max(_ON_EDGE_RELATIVE * size, _ON_EDGE_ULPS * np.finfo(np.float64).eps * magnitude, 1e-300)
    # Vertices within rounding of each other are one vertex too: the same point cut from the two
    # parts meeting at a rim (or a cone's apex) comes out a few ulps apart; a triangle that then
    # repeats a vertex has no area and goes.
    v, t = _merge_near(v, t, tol)
    keep = (t[:, 0] != t[:, 1]) & (t[:, 1] != t[:, 2]) & (t[:, 2] != t[:, 0])
    t, src = t[keep], src[keep]
    closed = False
    for _ in range(8):  # each pass splits one open edge per triangle
        u = t.ravel()
        w = t[:, [1, 2, 0]].ravel()
        open_h = _open_half_edges(t)
        if not len(open_h):
            closed = True
            break
        ends = np.unique(np.concatenate([u[open_h], w[open_h]]))
        split_e, split_v, split_s = _points_on_edges(v, u[open_h], w[open_h], ends, tol)
        if not len(split_e):
            break
        # One open edge per triangle this pass (the others in the next).
        h = open_h[split_e]
        tri = h // 3
        first_e = np.unique(tri, return_index=True)[1]
        keep_edge = np.zeros(len(open_h), bool)
        keep_edge[split_e[first_e]] = True
        sel = keep_edge[split_e]
        split_e, split_v, split_s = split_e[sel], split_v[sel], split_s[sel]
        edges = np.unique(split_e)
        eh = open_h[edges]
        # Chains u -> inner vertices (by position) -> w on every split edge.
        chain_e = np.concatenate([edges, split_e, edges])
        chain_v = np.concatenate([u[eh], split_v, w[eh]])
        chain_s = np.concatenate([np.zeros(len(edges)), split_s, np.ones(len(edges))])
        order = np.lexsort((chain_s, chain_e))
        chain_e, chain_v = chain_e[order], chain_v[order]
        link = np.flatnonzero(chain_e[1:] == chain_e[:-1])
        link_h = open_h[chain_e[link]]
        link_t = link_h // 3
        apex = t[link_t, (link_h % 3 + 2) % 3]
        fan = np.column_stack([chain_v[link], chain_v[link + 1], apex])
        drop = np.zeros(len(t), bool)
        drop[eh // 3] = True
        t = np.vstack([t[~drop], fan])
        src = np.concatenate([src[~drop], src[link_t]])
    else:
        closed = not len(_open_half_edges(t))
    return v, t, src, closed
def _merge_near(v: NDArray[np.float64], t: NDArray[np.int64], tol: float) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Merge vertices closer than ``tol`` (clusters linked by such pairs) into their first member."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree

    pairs = cKDTree(v).query_pairs(tol, output_type="ndarray")
    if not len(pairs):
        return v, t
    n = len(v)
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n))
    _, label = connected_components(graph, directed=False)
    first = np.full(n, n, np.int64)
    np.minimum.at(first, label, np.arange(n))
    rep = first[label]
    used, new_index = np.unique(rep, return_inverse=True)
    return v[used], new_index.reshape(-1)[t]


@njit(cache=True)
def _equal_rows(bits: NDArray[np.int64]) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Rows of equal bits: the first of each kind (in order) and every row's kind (a hash table)."""
    n = bits.shape[0]
    size = 1
    while size < 2 * n + 2:
        size *= 2
    table = np.full(size, -1, np.int64)
    kind = np.empty(n, np.int64)
    first = np.empty(n, np.int64)
    count = 0
    for r in range(n):
        h = (bits[r, 0] * 0x9E3779B97F4A7C15) ^ (bits[r, 1] * 0xC2B2AE3D27D4EB4F) ^ (bits[r, 2] * 0x165667B19E3779F9)
        slot = (h ^ (h >> 29)) & (size - 1)
        while True:
            k = table[slot]
            if k < 0:
                table[slot] = count
                first[count] = r
                kind[r] = count
                count += 1
                break
            f = first[k]
            if bits[f, 0] == bits[r, 0] and bits[f, 1] == bits[r, 1] and bits[f, 2] == bits[r, 2]:
                kind[r] = k
                break
            slot = (slot + 1) & (size - 1)
    return first[:count], kind


def _open_half_edges(t: NDArray[np.int64]) -> NDArray[np.int64]:
    """Half-edges (corner j to j + 1 of each triangle, flattened) whose undirected edge is not used exactly twice."""
    tri_edge = mesh_edges(t)[1].ravel()
    return np.flatnonzero(np.bincount(tri_edge)[tri_edge] != 2)


@njit(cache=True)
def _points_on_edges(
    v: NDArray[np.float64], a: NDArray[np.int64], b: NDArray[np.int64], cand: NDArray[np.int64], tol: float
) -> tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.float64]]:
    """(edge, vertex, parameter) of candidate vertices strictly inside edges ``a -> b``."""
    out_e = []
    out_v = []
    out_s = []
    for e in range(len(a)):
        ax, ay, az = v[a[e], 0], v[a[e], 1], v[a[e], 2]
        dx, dy, dz = v[b[e], 0] - ax, v[b[e], 1] - ay, v[b[e], 2] - az
        length2 = dx * dx + dy * dy + dz * dz
        if length2 == 0.0:
            continue
        lox, hix = min(ax, ax + dx) - tol, max(ax, ax + dx) + tol
        loy, hiy = min(ay, ay + dy) - tol, max(ay, ay + dy) + tol
        loz, hiz = min(az, az + dz) - tol, max(az, az + dz) + tol
        for k in range(len(cand)):
            c = cand[k]
            px, py, pz = v[c, 0], v[c, 1], v[c, 2]
            if px < lox or px > hix or py < loy or py > hiy or pz < loz or pz > hiz or c == a[e] or c == b[e]:
                continue
            rx, ry, rz = px - ax, py - ay, pz - az
            s = (rx * dx + ry * dy + rz * dz) / length2
            if s <= 1e-7 or s >= 1.0 - 1e-7:  # strictly inside: not an end point
                continue
            qx, qy, qz = rx - s * dx, ry - s * dy, rz - s * dz
            if qx * qx + qy * qy + qz * qz <= tol * tol:
                out_e.append(e)
                out_v.append(c)
                out_s.append(s)
    return np.array(out_e, np.int64), np.array(out_v, np.int64), np.array(out_s, np.float64)




#: Margin, in the local frame (the leaves' box mapped to [-1, 1]^3), between a
#: trimmed operand's cut and the box it is trimmed to: the cut's caps lie strictly
#: outside everything the operand can still touch.
TRIM_MARGIN = 1e-4


def _trim_to_box(
    v: NDArray[np.float64], t: NDArray[np.int64], lo: NDArray[np.float64], hi: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]:
    """A closed triangle soup of a convex solid cut to a box (plus :data:`TRIM_MARGIN`), each cut capped.

    Used for operands whose surface matters only inside a box (what a
    difference subtracts from its first operand, the operands of an
    intersection): the part outside never reaches the result, so it need not
    enter a Boolean. Each plane of the box that crosses the solid cuts it; the
    cut is capped by a fan from the centre of the section, which is convex for
    a convex solid. Cut points are computed from each edge's ends in a fixed
    order, so neighbours that share an edge share the point bit for bit (the
    soup is welded afterwards). Returns vertices, triangles and the source
    triangle of each (a cap takes a source of the triangle it closes).
    """
    src = np.arange(len(t), dtype=np.int64)
    for axis in range(3):
        for side, bound in ((1.0, hi[axis] + TRIM_MARGIN), (-1.0, lo[axis] - TRIM_MARGIN)):
            x = v[:, axis]
            if not len(t) or np.max(side * (x - bound)) <= 0:
                continue
            # Keep the cut away from vertices, so no vertex lies on it.
            step = max(abs(bound), 1.0) * 1e-9
            for _ in range(64):
                if np.abs(x - bound).min() > step:
                    break
                bound += side * 4 * step
            v, t, src = _cut(v, t, src, axis, bound, side)
    return v, t, src


def _cut(
    v: NDArray[np.float64], t: NDArray[np.int64], src: NDArray[np.int64], axis: int, bound: float, side: float
) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]:
    """Keep the part of a closed soup where ``side * (x[axis] - bound) < 0``; cap the cut with a fan."""
    s = side * (v[:, axis] - bound)
    inside = s < 0
    count = inside[t].sum(axis=1)
    whole = count == 3
    if whole.all():
        return v, t, src
    keep_t, keep_s = t[whole], src[whole]
    one, two = count == 1, count == 2
    if not (one.any() or two.any()):
        return v, keep_t, keep_s  # nothing crosses: the soup lies on one side
    # Rotate each crossing triangle so that its odd vertex (alone on its side) comes first.
    ct = t[one | two]
    cs = src[one | two]
    odd_in = inside[ct] == (count[one | two] == 1)[:, None]  # the lone vertex
    first = np.argmax(odd_in, axis=1)
    rows = np.arange(len(ct))[:, None]
    ct = ct[rows, (first[:, None] + np.arange(3)) % 3]
    a, b, c = ct[:, 0], ct[:, 1], ct[:, 2]
    lone_inside = inside[a]

    def point(p: NDArray[np.int64], q: NDArray[np.int64]) -> NDArray[np.float64]:
        # From the inside end to the outside end, whichever triangle asks: bit-equal for neighbours.
        pin = np.where(inside[p], p, q)
        pout = np.where(inside[p], q, p)
        w = s[pin] / (s[pin] - s[pout])
        out = v[pin] + (v[pout] - v[pin]) * w[:, None]
        out[:, axis] = bound
        return out

    m = len(ct)
    nv = len(v)
    ab = nv + np.arange(m)
    ca = nv + m + np.arange(m)
    centre_pts = np.vstack([point(a, b), point(c, a)])
    centre = centre_pts.mean(axis=0)
    centre[axis] = bound
    cidx = nv + 2 * m
    v2 = np.vstack([v, centre_pts, centre[None, :]])
    # Lone vertex inside: the triangle (a, ab, ca), whose cut edge runs ab -> ca.
    # Lone vertex outside: the quad ab, b, c, ca, whose cut edge runs ca -> ab.
    li = lone_inside
    tri_in = np.column_stack([a[li], ab[li], ca[li]])
    lo = ~li
    quad1 = np.column_stack([ab[lo], b[lo], c[lo]])
    quad2 = np.column_stack([ab[lo], c[lo], ca[lo]])
    # The cap: each cut edge reversed, closed to the centre.
    cap = np.vstack([
        np.column_stack([ca[li], ab[li], np.full(int(li.sum()), cidx)]),
        np.column_stack([ab[lo], ca[lo], np.full(int(lo.sum()), cidx)]),
    ])
    cap_s = np.concatenate([cs[li], cs[lo]])
    t2 = np.vstack([keep_t, tri_in, quad1, quad2, cap])
    s2 = np.concatenate([keep_s, cs[li], cs[lo], cs[lo], cap_s])
    used, inv = np.unique(t2, return_inverse=True)
    return v2[used], inv.reshape(-1, 3), s2


@dataclass(slots=True)
class _Comp:
    """A box-disjoint piece of an operand's value: a leaf as it is (``ref >= 0``: leaf
    ``ref``) or a planned Boolean (``ref < 0``: node ``-1 - ref``), with its local box."""

    lo: NDArray[np.float64]
    hi: NDArray[np.float64]
    ref: int


class _Plan:
    """The tree evaluated on boxes: which Booleans are needed, and on which operands.

    Nodes are created operands first, so building them in order never needs
    a node that is not built yet.
    """

    def __init__(self) -> None:
        self.nodes: list[tuple[str, list[int]]] = []  # (manifold3d operation or "compose", operand refs)
        # Leaves whose surface matters only inside a box (what they are subtracted from, the
        # box common to an intersection's operands): leaf -> (lo, hi) over all such uses.
        self.trim: dict[int, tuple[NDArray[np.float64], NDArray[np.float64]]] = {}
        self.whole: set[int] = set()  # leaves used where all of their surface may matter
        self.boxes: list[tuple[NDArray[np.float64], NDArray[np.float64]]] = []  # each node's box
        self.slabs: dict[int, tuple[int, float, float]] = {}  # "slab" node -> (axis, lo, hi)

    def node(self, op: str, parts: list[_Comp], boxes: list[Any] | None = None) -> _Comp:
        """A planned operation; ``boxes[k]``, where given, is the box outside which
        operand ``k`` cannot change the result (None: all of it may)."""
        self.nodes.append((op, [p.ref for p in parts]))
        for k, p in enumerate(parts):
            box = None if boxes is None else boxes[k]
            if p.ref < 0:
                continue
            if box is None:
                self.whole.add(p.ref)
            elif p.ref in self.trim:
                lo0, hi0 = self.trim[p.ref]
                self.trim[p.ref] = (np.minimum(lo0, box[0]), np.maximum(hi0, box[1]))
            else:
                self.trim[p.ref] = (np.asarray(box[0], np.float64), np.asarray(box[1], np.float64))
        lo = np.min([p.lo for p in parts], axis=0)
        hi = np.max([p.hi for p in parts], axis=0)
        self.boxes.append((lo, hi))
        return _Comp(lo, hi, -len(self.nodes))

    def nodes_of(self, ref: int) -> list[int]:
        """The nodes a piece is built from (itself included), in building order."""
        out, todo = set(), [ref]
        while todo:
            r = todo.pop()
            if r < 0 and -1 - r not in out:
                out.add(-1 - r)
                todo.extend(self.nodes[-1 - r][1])
        return sorted(out)

    def split_difference(self, c: _Comp, count: Any, most: int, leaf_box: Any) -> list[_Comp]:
        """A difference of many box-disjoint cuts as several, each of the first operand's
        slab between two planes that cross no cut (boxes with gaps between them), so that
        each Boolean takes at most about ``most`` triangles (``count(ref)``: a piece's
        triangles); the slabs' cut faces are dropped when the results are read back.
        Returns ``[c]`` when one Boolean is within ``most`` or no plane can part the cuts."""
        op, refs = self.nodes[-1 - c.ref]
        if op != "Subtract" or len(refs) < 3:
            return [c]
        first, cuts = refs[0], refs[1:]
        sizes = np.array([count(r) for r in cuts], np.int64)
        room = most - count(first)
        if count(first) + int(sizes.sum()) <= most or room <= 0:
            return [c]
        box = [leaf_box(r) if r >= 0 else self.boxes[-1 - r] for r in [first] + cuts]
        axis = int(np.argmax(box[0][1] - box[0][0]))
        lo = np.array([b[0][axis] for b in box[1:]])
        hi = np.array([b[1][axis] for b in box[1:]])
        order = np.argsort(lo, kind="stable")
        reach = np.maximum.accumulate(hi[order])  # the farthest end of the cuts so far
        n = len(order)
        cum = np.concatenate([[0], np.cumsum(sizes[order])])
        # Where a plane may pass: after position e - 1 when no cut so far reaches the next one.
        ends = [e for e in range(1, n) if reach[e - 1] < lo[order[e]]] + [n]
        groups, start = [], 0
        while start < n:
            fit = [e for e in ends if e > start and cum[e] - cum[start] <= room]
            end = fit[-1] if fit else next(e for e in ends if e > start)  # the largest that fits, else the least
            groups.append((start, end))
            start = end
        if len(groups) < 2:
            return [c]
        first_comp = _Comp(box[0][0], box[0][1], first)
        out = []
        for g, (a, b) in enumerate(groups):
            s_lo = -np.inf if g == 0 else float((reach[a - 1] + lo[order[a]]) / 2)
            s_hi = np.inf if g == len(groups) - 1 else float((reach[b - 1] + lo[order[b]]) / 2)
            slab = self.node("slab", [first_comp])
            self.slabs[-1 - slab.ref] = (axis, s_lo, s_hi)
            slab.lo, slab.hi = slab.lo.copy(), slab.hi.copy()
            slab.lo[axis], slab.hi[axis] = max(slab.lo[axis], s_lo), min(slab.hi[axis], s_hi)
            parts = [_Comp(box[1 + x][0], box[1 + x][1], cuts[x]) for x in order[a:b].tolist()]
            d = self.node("Subtract", [slab] + parts, [None] + [(first_comp.lo, first_comp.hi)] * len(parts))
            out.append(_Comp(slab.lo, slab.hi, d.ref))
        return out

    def leaves(self, ref: int) -> list[int]:
        """The leaves a piece is made of (a walk of the nodes with a stack), sorted."""
        out, todo, seen = set(), [ref], set()
        while todo:
            r = todo.pop()
            if r >= 0:
                out.add(r)
            elif r not in seen:
                seen.add(r)
                todo.extend(self.nodes[-1 - r][1])
        return sorted(out)

    def combine(self, op: int, args: list[list[_Comp]]) -> list[_Comp]:
        if len(args) == 1:
            return args[0]
        if op == OP_UNION:
            return self._union([c for a in args for c in a])
        if op == OP_DIFFERENCE:
            return self._difference(args[0], [c for a in args[1:] for c in a])
        if op == OP_INTERSECTION:
            return self._intersection(args)
        raise InvalidParameterError(f"unknown CSG opcode {op}")

    def _union(self, comps: list[_Comp]) -> list[_Comp]:
        if len(comps) < 2:
            return comps
        label = _groups(len(comps), *_overlapping(comps))
        out: list[_Comp] = []
        members: dict[int, list[_Comp]] = {}
        for c, g in zip(comps, label.tolist()):
            members.setdefault(g, []).append(c)
        for group in members.values():
            # manifold3d's batch union composes the members whose boxes do not overlap.
            out.append(group[0] if len(group) == 1 else self.node("Add", group))
        return out

    def _difference(self, first: list[_Comp], cut: list[_Comp]) -> list[_Comp]:
        if not first or not cut:
            return first
        i, j = _overlapping(first + cut)
        nf = len(first)
        # Pairs (piece of the first operand, subtracted piece) whose boxes meet.
        a, b = np.minimum(i, j), np.maximum(i, j)
        sel = (a < nf) & (b >= nf)
        a, b = a[sel], b[sel] - nf
        order = np.argsort(a, kind="stable")
        a, b = a[order], b[order]
        starts = np.searchsorted(a, np.arange(nf + 1))
        out: list[_Comp] = []
        for k, c in enumerate(first):
            hit = b[starts[k] : starts[k + 1]].tolist()
            if not hit:
                out.append(c)
                continue
            # What is subtracted matters only inside the first operand's box.
            d = self.node("Subtract", [c] + [cut[x] for x in hit], [None] + [(c.lo, c.hi)] * len(hit))
            out.append(_Comp(c.lo, c.hi, d.ref))
        return out

    def _intersection(self, args: list[list[_Comp]]) -> list[_Comp]:
        if any(not a for a in args):
            return []
        lo = np.max([np.min([c.lo for c in a], axis=0) for a in args], axis=0)
        hi = np.min([np.max([c.hi for c in a], axis=0) for a in args], axis=0)
        if np.any(lo > hi):
            return []
        operands = []
        for a in args:
            kept = [c for c in a if np.all(c.lo <= hi) and np.all(c.hi >= lo)]
            if not kept:
                return []
            # The pieces of one operand are box-disjoint: joined without a Boolean.
            operands.append(kept[0] if len(kept) == 1 else self.node("compose", kept, [(lo, hi)] * len(kept)))
        inter = self.node("Intersect", operands, [(lo, hi)] * len(operands))
        return [_Comp(np.maximum(inter.lo, lo), np.minimum(inter.hi, hi), inter.ref)]


def _overlapping(comps: list[_Comp]) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Pairs of pieces whose (closed) boxes meet."""
    lo = np.array([c.lo for c in comps])
    hi = np.array([c.hi for c in comps])
    # Sweep along the axis where the boxes are spread widest relative to their size.
    spread = np.ptp(lo + hi, axis=0) / np.maximum((hi - lo).mean(axis=0), 1e-300)
    return _box_pairs(lo, hi, int(np.argmax(spread)))


@njit(cache=True)
def _box_pairs(
    lo: NDArray[np.float64], hi: NDArray[np.float64], axis: int
) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Sort and sweep: every pair (i, j) of boxes that meet."""
    n = len(lo)
    order = np.argsort(lo[:, axis])
    out_i = []
    out_j = []
    for a in range(n):
        i = order[a]
        for b in range(a + 1, n):
            j = order[b]
            if lo[j, axis] > hi[i, axis]:
                break
            if (
                lo[j, 0] <= hi[i, 0] and lo[i, 0] <= hi[j, 0] and lo[j, 1] <= hi[i, 1]
                and lo[i, 1] <= hi[j, 1] and lo[j, 2] <= hi[i, 2] and lo[i, 2] <= hi[j, 2]
            ):
                out_i.append(i)
                out_j.append(j)
    return np.array(out_i, np.int64), np.array(out_j, np.int64)


@njit(cache=True)
def _groups(n: int, i: NDArray[np.int64], j: NDArray[np.int64]) -> NDArray[np.int64]:
    """Connected groups of ``n`` items joined by the pairs ``(i, j)`` (union-find): a label per item."""
    parent = np.arange(n)
    for k in range(len(i)):
        a, b = i[k], j[k]
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        while parent[b] != b:
            parent[b] = parent[parent[b]]
            b = parent[b]
        if a != b:
            parent[max(a, b)] = min(a, b)
    for k in range(n):
        r = k
        while parent[r] != r:
            r = parent[r]
        parent[k] = r
    return parent


def untrimmed_groups(program: Program, lo: ArrayLike, hi: ArrayLike) -> list[list[int]]:
    """For each Boolean that ``surface_from_bands(program, bands, trim=True)`` would build
    on leaves within these boxes, the leaves it takes whole (none of their triangles can go).

    Known from the leaves' boxes alone, before any band exists: the sum of their band
    triangles is a lower bound of that Boolean's, e.g. to give up on a union of many
    overlapping leaves without building all their bands.

    Parameters
    ----------
    program : Program
    lo, hi : array_like, shape (n, 3)
        The leaves' bounding boxes.

    Returns
    -------
    list of list of int

    Examples
    --------
    >>> from isocsg import Box, Cylinder, Sphere
    >>> prog = ((Sphere((0, 0, 0), 1) | Sphere((1, 0, 0), 1)) - Cylinder((0, 0, 0), (0, 0, 3), 0.2)).program()
    >>> lo = np.array([[-1, -1, -1], [0, -1, -1], [-0.2, -0.2, -1.5]]); hi = lo + [[2, 2, 2], [2, 2, 2], [0.4, 0.4, 3]]
    >>> untrimmed_groups(prog, lo, hi)
    [[0, 1]]
    """
    lo = np.asarray(lo, np.float64).reshape(-1, 3)
    hi = np.asarray(hi, np.float64).reshape(-1, 3)
    plan = _Plan()
    final = program.evaluate(lambda i, _: [_Comp(lo[i], hi[i], i)], plan.combine)
    trimmable = set(plan.trim) - plan.whole
    return [[x for x in plan.leaves(c.ref) if x not in trimmable] for c in final if c.ref < 0]


def surface_from_bands(
    program: Program, bands: Sequence[BandMesh], *, trim: bool = False, max_bytes: int | None = None
) -> CSGSurface:
    """Clip the leaves' band meshes against each other along a CSG program.

    The tree is first evaluated on the leaves' boxes (see the module
    docstring): leaves that meet no operand they are combined with are kept
    as they are, the others go through manifold3d batch Booleans in a local
    frame. The memory that needs is checked against the budget
    (:func:`isocsg.limits.check_memory`) before any Boolean starts.

    Parameters
    ----------
    program : Program
        The tree's flat program (:meth:`isocsg.csg.CSGNode.program`).
    bands : sequence of BandMesh
        One band mesh per leaf, each tiling the leaf's closed surface.
    trim : bool, default False
        Cut each leaf that matters only inside a box (subtracted from an
        operand, or an operand of an intersection) to that box before the
        Booleans, capping the cuts (:data:`TRIM_MARGIN` outside the box): the
        same solid where it counts, with fewer triangles in the Booleans (a
        hole three times longer than its plate is thick keeps 44 % of its band
        triangles at 32 contours: its ends go, the cuts through its strips add
        caps). The Booleans then run one result at a time, and a difference of
        many cuts that does not fit at once is parted into slabs of its first
        operand (:meth:`_Plan.split_difference`). Leaves must be convex, as
        isocsg's primitives are. The result's triangulation may differ from an
        untrimmed build's; under slabs its surface is open along their planes
        (both sides' triangles meet there).
    max_bytes : int, optional
        A bound on the Booleans' working memory besides the budget (e.g. the
        share of it a background build may take).

    Returns
    -------
    CSGSurface
        Empty (no triangles) when the result is empty.

    Raises
    ------
    InvalidGeometryError
        If a band mesh cannot be welded into a closed manifold surface.
    InvalidParameterError
        If the program and the band meshes do not match.
    ResourceLimitError
        If the Booleans would need more than the memory budget (or ``max_bytes``).
    """
    if not isinstance(program, Program) or program.n_leaves != len(bands):
        raise InvalidParameterError(f"{program!r} does not match {len(bands)} band meshes")
    n = len(bands)
    raw_lo = np.full((n, 3), np.inf)
    raw_hi = np.full((n, 3), -np.inf)
    for i, bm in enumerate(bands):
        if len(bm.triangles):
            v = np.asarray(bm.vertices, np.float64).reshape(-1, 3)
            raw_lo[i], raw_hi[i] = v.min(axis=0), v.max(axis=0)
    present = np.isfinite(raw_lo[:, 0])
    if not present.any():
        return _empty()
    # Local frame: the leaves' box mapped to [-1, 1]^3 (manifold3d's tolerances are
    # relative to its meshes' size and distance from the origin).
    glo, ghi = raw_lo[present].min(axis=0), raw_hi[present].max(axis=0)
    centre = (glo + ghi) / 2
    half = float((ghi - glo).max()) / 2
    half = half if half > 0 else 1.0
    pad = COINCIDENT_DISTANCE  # boxes that nearly touch meet: their faces may coincide
    box_lo, box_hi = (raw_lo - centre) / half - pad, (raw_hi - centre) / half + pad

    plan = _Plan()
    final = program.evaluate(
        lambda i, _: [_Comp(box_lo[i], box_hi[i], i)] if present[i] else [], plan.combine
    )
    if not final:
        return _empty()
    members = {c.ref: plan.leaves(c.ref) for c in final if c.ref < 0}
    boolean_leaves = {x for m in members.values() for x in m}
    plain_leaves = [c.ref for c in final if c.ref >= 0]
    # Trimmed leaves, welded in the local frame: leaf -> (vertices, triangles, source).
    trimmed: dict[int, tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]] = {}
    to_trim = sorted(boolean_leaves & set(plan.trim) - plan.whole) if trim else []
    n_plain = sum(len(bands[i].triangles) for i in plain_leaves)
    bound = memory_budget() if max_bytes is None else min(memory_budget(), max_bytes)
    for i in to_trim:
        lo, hi = plan.trim[i]
        bm = bands[i]
        v, t, src = _trim_to_box((np.asarray(bm.vertices, np.float64) - centre) / half,
                                 np.asarray(bm.triangles, np.int64), lo, hi)
        # Welded below, once the budget is known to allow it. Kept whenever the box cut
        # something away, even with as many triangles left or more: a leaf's parts that no view
        # can show may come uncut (``build_bands(hidden=...)``), and cut away they make
        # the same trimmed mesh as its fully cut bands would.
        if len(t) != len(bm.triangles) or not np.array_equal(src, np.arange(len(t))):
            trimmed[i] = (v, t, src)
    size = [len(trimmed[i][1]) if i in trimmed else len(b.triangles) for i, b in enumerate(bands)]
    n_bool = sum(size[i] for i in boolean_leaves)
    if trim:
        # The Booleans run one result at a time (what one holds is released before the
        # next), so a difference of many cuts is parted into slabs that each fit.
        most = max(1, (bound - (n_bool + n_plain) * BYTES_PER_PLAIN_TRIANGLE) // BYTES_PER_BOOLEAN_TRIANGLE)
        counts: dict[int, int] = {}

        def count(ref: int) -> int:
            if ref not in counts:
                counts[ref] = size[ref] if ref >= 0 else sum(size[x] for x in plan.leaves(ref))
            return counts[ref]

        final = [p for c in final for p in (plan.split_difference(c, count, int(most), lambda r: (box_lo[r], box_hi[r]))
                                            if c.ref < 0 else [c])]
        members = {c.ref: plan.leaves(c.ref) for c in final if c.ref < 0}
        largest = max([sum(size[x] for x in m) for m in members.values()], default=0)
        what = (f"the clipped CSG surface ({n_bool} band triangles in Booleans, at most {largest} at a time, "
                f"{n_plain} kept as they are)")
        need = largest * BYTES_PER_BOOLEAN_TRIANGLE + (n_bool + n_plain) * BYTES_PER_PLAIN_TRIANGLE
    else:
        what = f"the clipped CSG surface ({n_bool} band triangles in Booleans, {n_plain} kept as they are)"
        need = n_bool * BYTES_PER_BOOLEAN_TRIANGLE + n_plain * BYTES_PER_PLAIN_TRIANGLE
    check_memory(what, need)
    if need > bound:
        raise ResourceLimitError(f"{what} needs about {need / 1e9:.2f} GB, over the {bound / 1e9:.2f} GB allowed")
    for i in list(trimmed):
        v, t, src = trimmed.pop(i)
        v, t, s2, ok = _close(v, t)
        if ok:  # else the whole leaf (a cut that did not close)
            trimmed[i] = (v, t, src[s2])

    closed: dict[int, tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64], bool]] = {}

    def weld(i: int, keep: bool = True) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64], bool]:
        bm = bands[i]
        key = id(bm)  # a repeated leaf shares its band mesh: weld it once
        if key in closed:
            return closed[key] if keep else closed.pop(key)
        out = _close(bm.vertices, bm.triangles)
        if keep:
            closed[key] = out
        return out

    pieces: list[tuple[Any, ...]] = []
    for k, c in enumerate(final):
        if c.ref < 0:
            continue
        v, t, src, ok = weld(c.ref)
        if not ok:
            # Open edges left after welding: manifold3d merges nearly equal vertices
            # on them, or says the mesh is not closed.
            final[k] = plan.node("as is", [c])
            members[final[k].ref] = [c.ref]
            continue
        vout = np.asarray(bands[c.ref].value_out, np.float64)
        pieces.append((v, t, np.full(len(t), c.ref, np.int32), src, np.zeros(len(t), bool), vout[src]))
    # The nodes the result needs.
    needed = np.zeros(len(plan.nodes), bool)
    for c in final:
        if c.ref < 0:
            needed[-1 - c.ref] = True
    for k in range(len(plan.nodes) - 1, -1, -1):
        if needed[k]:
            for r in plan.nodes[k][1]:
                if r < 0:
                    needed[-1 - r] = True
    if needed.any():
        pieces.extend(_booleans(plan, needed, final, members, bands, weld, centre, half, trimmed, one_at_a_time=trim))
    return _assemble(pieces)


def _booleans(
    plan: _Plan, needed: NDArray[np.bool_], final: list[_Comp], members: dict[int, list[int]], bands: Sequence[BandMesh],
    weld: Any, centre: NDArray[np.float64], half: float, trimmed: dict[int, Any] | None = None,
    one_at_a_time: bool = False,
) -> list[tuple[Any, ...]]:
    """Build the planned Booleans (manifold3d, local frame) and read their results back:
    all at once, or (``one_at_a_time``) result by result, each solid released once the
    last Boolean that takes it is built."""
    m3 = _manifold3d()
    M = m3.Manifold
    trimmed = {} if trimmed is None else trimmed
    # One original id per leaf: manifold3d tags each result triangle with it.
    first_id = int(M.reserve_ids(len(bands)))
    leaf_solid: dict[int, Any] = {}

    def solid(ref: int) -> Any:
        if ref < 0:
            return built[-1 - ref]
        if ref not in leaf_solid:
            if ref in trimmed:
                # Already in the local frame; not needed once its solid exists (a leaf's
                # solid is kept for all the Booleans that take it).
                v, t, src = trimmed.pop(ref)
            else:
                # Welded for this solid only when the Booleans run one result at a time
                # (its solid is kept while a Boolean still takes it).
                v, t, src, _ = weld(ref, not one_at_a_time)
                v = (v - centre) / half
            mesh = m3.Mesh64(
                vert_properties=np.ascontiguousarray(v),
                tri_verts=np.ascontiguousarray(t, dtype=np.uint64),
                face_id=np.ascontiguousarray(src, dtype=np.uint64),
                run_index=np.array([0, 3 * len(t)], dtype=np.uint64),
                run_original_id=np.array([first_id + ref], dtype=np.uint32),
            )
            mesh.merge()  # nearly equal vertices on open edges (rounding of the cuts)
            s = M(mesh)
            if s.status() != m3.Error.NoError:
                raise InvalidGeometryError(f"the band mesh of leaf {ref} is not a closed surface ({s.status()})")
            leaf_solid[ref] = s
        return leaf_solid[ref]

    built: list[Any] = [None] * len(plan.nodes)
    # Consumers of each solid still to come (Booleans, and results to read back).
    uses = np.zeros(len(plan.nodes), np.int64)
    leaf_uses: dict[int, int] = {}
    for k in np.flatnonzero(needed).tolist():
        for r in plan.nodes[k][1]:
            if r < 0:
                uses[-1 - r] += 1
            else:
                leaf_uses[r] = leaf_uses.get(r, 0) + 1
    for c in final:
        if c.ref < 0:
            uses[-1 - c.ref] += 1

    def release(r: int) -> None:
        if not one_at_a_time:
            return
        if r < 0:
            uses[-1 - r] -= 1
            if not uses[-1 - r]:
                built[-1 - r] = None
        else:
            leaf_uses[r] -= 1
            if not leaf_uses[r]:
                leaf_solid.pop(r, None)

    def build(k: int) -> None:
        op, refs = plan.nodes[k]
        parts = [solid(r) for r in refs]
        if op == "as is":
            built[k] = parts[0]
        elif op == "compose":
            built[k] = M.compose(parts)
        elif op == "slab":
            axis, lo, hi = plan.slabs[k]
            out = parts[0]
            normal = np.zeros(3)
            if np.isfinite(lo):  # keeps the side the normal points to
                normal[axis] = 1.0
                out = out.trim_by_plane(tuple(normal), lo)
            if np.isfinite(hi):
                normal[axis] = -1.0
                out = out.trim_by_plane(tuple(normal), -hi)
            built[k] = out
        else:
            built[k] = M.batch_boolean(parts, getattr(m3.OpType, op))
        del parts
        for r in refs:
            release(r)

    # The band triangles each trimmed leaf brings into the Booleans (the others: all of theirs).
    subset = {i: np.unique(trimmed[i][2]) for i in trimmed}
    if not one_at_a_time:
        for k in np.flatnonzero(needed).tolist():
            build(k)
    shared = _shared_planes(bands, sorted({x for m in members.values() for x in m}), centre, half, subset)
    pieces = []
    for c in final:
        if c.ref >= 0:
            continue
        if one_at_a_time:
            for k in plan.nodes_of(c.ref):
                if built[k] is None:
                    build(k)
        out = built[-1 - c.ref].to_mesh64()
        release(c.ref)
        tris = np.asarray(out.tri_verts, dtype=np.int64).reshape(-1, 3)
        if not len(tris):
            continue
        verts = np.asarray(out.vert_properties, dtype=np.float64).reshape(len(out.vert_properties), -1)[:, :3]
        face = np.asarray(out.face_id, dtype=np.int64).reshape(-1)
        run_index = np.asarray(out.run_index, dtype=np.int64) // 3
        run_leaf = np.asarray(out.run_original_id, dtype=np.int64) - first_id
        del out
        leaf = np.repeat(run_leaf, np.diff(run_index)).astype(np.int32)
        ours = (leaf >= 0) & (leaf < len(bands))
        if not ours.all():  # a slab's cut faces: the neighbouring slab's result continues there
            keep_runs = (run_leaf >= 0) & (run_leaf < len(bands))
            tris, face, leaf = tris[ours], face[ours], leaf[ours]
            run_leaf = run_leaf[keep_runs]
            run_index = np.concatenate([[0], np.cumsum(np.diff(run_index)[keep_runs])])
        # The comp's leaves' band triangles (of a trimmed leaf, those it kept), concatenated:
        # global index base[leaf] + the face's position among its leaf's.
        leaves_in = members[c.ref]
        sizes = np.array([len(subset[i]) if i in subset else len(bands[i].triangles) for i in leaves_in], np.int64)
        base = np.zeros(len(bands), np.int64)
        base[leaves_in] = np.concatenate([[0], np.cumsum(sizes)[:-1]])
        pos = face.copy()
        for r0, r1, i in zip(run_index[:-1].tolist(), run_index[1:].tolist(), run_leaf.tolist()):
            if i in subset:
                pos[r0:r1] = np.searchsorted(subset[i], face[r0:r1])
        g = base[leaf] + pos

        def gather(i: int, a: NDArray[Any]) -> NDArray[Any]:
            return a[subset[i]] if i in subset else a

        normals = np.vstack([
            _triangle_normals(np.asarray(bands[i].vertices, np.float64), gather(i, np.asarray(bands[i].triangles, np.int64)))
            for i in leaves_in
        ])
        vin = np.concatenate([gather(i, np.asarray(bands[i].value_in, np.float64)) for i in leaves_in])
        vout = np.concatenate([gather(i, np.asarray(bands[i].value_out, np.float64)) for i in leaves_in])
        on_shared = np.concatenate([shared[i] for i in leaves_in])[g]
        if on_shared.any():
            drop = np.zeros(len(tris), bool)
            cand = np.flatnonzero(on_shared)
            drop[cand] = _on_opposite_face(verts, tris, cand, COINCIDENT_DISTANCE)
            verts, tris, origin, drop = _cancel_partial_overlaps(verts, tris, cand, drop, COINCIDENT_DISTANCE)
            if drop.any():
                keep = np.flatnonzero(~drop)
                tris, leaf, face, g = tris[keep], leaf[origin[keep]], face[origin[keep]], g[origin[keep]]
        rev = np.einsum("ij,ij->i", _triangle_normals(verts, tris), normals[g]) < 0
        pieces.append((verts * half + centre, tris.astype(np.int32), leaf, face.astype(np.int32), rev,
                       np.where(rev, vin[g], vout[g])))
        del verts, tris, leaf, face, rev, g, normals, vin, vout
        if one_at_a_time:
            _release_freed_memory()
    return pieces


@functools.cache
def _malloc_trim() -> Callable[[int], int] | None:
    try:
        return ctypes.CDLL(None).malloc_trim  # glibc
    except (AttributeError, OSError, TypeError):  # another C library, or no CDLL(None) (Windows)
        return None


def _release_freed_memory() -> None:
    """Give the heap memory freed so far back to the system, where the C library allows it (glibc).

    manifold3d allocates on its worker threads, whose malloc arenas keep what
    a Boolean frees; a build that runs its Booleans one result at a time
    (slabs) would otherwise hold every slab's working memory beside the next
    one's: the 1000-hole plate's build in ten slabs grew from 0.76 to 1.10 GB
    resident with 0.74 GB in use, and the renderer's arrays made from the
    surface came on top of that.
    """
    trim = _malloc_trim()
    if trim is not None:
        trim(0)


def _shared_planes(
    bands: Sequence[BandMesh], leaves: list[int], centre: NDArray[np.float64], half: float,
    subset: dict[int, NDArray[np.int64]] | None = None,
) -> dict[int, NDArray[np.bool_]]:
    """For each of ``leaves``, which band triangles (those of ``subset[leaf]`` where given, in
    its order) lie in a plane (either orientation) that a band triangle of another of
    ``leaves`` lies in too: only there can faces coincide.

    Leaf by leaf: a leaf's triangles lie in few planes (a faceted hole in one per facet), so
    only each leaf's distinct plane keys are gathered, and the working memory stays in
    proportion to the planes, not to the triangles of all the leaves at once.
    """
    subset = {} if subset is None else subset
    # Per leaf and per rounding of the offset: its distinct planes, and each triangle's among them.
    distinct: list[list[NDArray[np.int64]]] = [[], []]
    which: dict[int, list[NDArray[np.int32]]] = {}
    flat: dict[int, NDArray[np.bool_]] = {}
    for i in leaves:
        v = (np.asarray(bands[i].vertices, np.float64) - centre) / half
        t = np.asarray(bands[i].triangles, np.int64)
        if i in subset:
            t = t[subset[i]]
        n = _triangle_normals(v, t)
        length = np.linalg.norm(n, axis=1)
        ok = length > 0
        n = n / np.where(ok, length, 1.0)[:, None]
        # One orientation per plane: the first clearly non-zero component positive.
        q = np.round(n * 2.0**20)
        lead = np.where(q[:, 0] != 0, q[:, 0], np.where(q[:, 1] != 0, q[:, 1], q[:, 2]))
        sign = np.where(lead < 0, -1.0, 1.0)
        q *= sign[:, None]
        d = np.einsum("ij,ij->i", n, v[t[:, 0]]) * sign * 2.0**30
        which[i] = []
        for col, off in enumerate((np.floor(d), np.floor(d + 0.5))):  # planes closer than a step share one
            rows = np.ascontiguousarray(np.column_stack([q, off]).astype(np.int64))
            _, first, inv = np.unique(rows.view(np.dtype((np.void, 32))).ravel(), return_index=True,
                                      return_inverse=True)
            distinct[col].append(rows[first])
            which[i].append(inv.reshape(-1).astype(np.int32))
        flat[i] = ok
    out = {i: np.zeros(len(flat[i]), bool) for i in leaves}
    for col in (0, 1):
        if not distinct[col]:
            continue
        # How many leaves have each plane (each leaf's planes are distinct).
        allp = np.ascontiguousarray(np.vstack(distinct[col]))
        _, pinv, pcount = np.unique(allp.view(np.dtype((np.void, 32))).ravel(), return_inverse=True,
                                    return_counts=True)
        many = pcount[pinv.reshape(-1)] > 1
        start = 0
        for i, planes in zip(leaves, distinct[col]):
            out[i] |= many[start : start + len(planes)][which[i][col]]
            start += len(planes)
    for i in leaves:
        out[i] &= flat[i]  # a degenerate triangle has no plane
    return out


@njit(cache=True)
def _grid_entries(
    lo: NDArray[np.float64], hi: NDArray[np.float64], use: NDArray[np.int64], g0: NDArray[np.float64], h: float,
    dims: int, count: int,
) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """The entries of a uniform grid of cell side ``h`` from ``g0`` over the boxes ``[lo[k], hi[k]]``,
    ``k`` in ``use`` (``count`` entries in all): each cell's key, sorted, and the box it holds
    (in ``use``'s order within a cell)."""
    keys = np.empty(count, np.int64)
    tri = np.empty(count, np.int64)
    e = 0
    for k in use:
        i0, j0, l0 = int((lo[k, 0] - g0[0]) / h), int((lo[k, 1] - g0[1]) / h), int((lo[k, 2] - g0[2]) / h)
        i1, j1, l1 = int((hi[k, 0] - g0[0]) / h), int((hi[k, 1] - g0[1]) / h), int((hi[k, 2] - g0[2]) / h)
        for i in range(i0, i1 + 1):
            for j in range(j0, j1 + 1):
                for l in range(l0, l1 + 1):
                    keys[e] = (i * dims + j) * dims + l
                    tri[e] = k
                    e += 1
    order = np.argsort(keys, kind="mergesort")
    return keys[order], tri[order]


@njit(cache=True)
def _on_opposite_face(
    v: NDArray[np.float64], t: NDArray[np.int64], cand: NDArray[np.int64], tol: float
) -> NDArray[np.bool_]:
    """Which candidate triangles to drop: those whose centroid lies, within ``tol``,
    on candidate triangles facing the opposite way that cancel it.

    At a point of a plane where ``a`` layers face one way and ``b`` the other,
    ``min(a, b)`` of each cancel; one of what is left is kept (the layer of
    lowest index). The candidates are found through a uniform grid over their boxes.
    """
    m = len(cand)
    nrm = np.zeros((m, 3))
    off = np.zeros(m)
    cen = np.zeros((m, 3))
    blo = np.zeros((m, 3))
    bhi = np.zeros((m, 3))
    ok = np.zeros(m, np.bool_)
    ext = np.zeros(m)
    for k in range(m):
        a, b, c = t[cand[k], 0], t[cand[k], 1], t[cand[k], 2]
        e1 = v[b] - v[a]
        e2 = v[c] - v[a]
        n = np.array([e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]])
        length = np.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)
        for x in range(3):
            cen[k, x] = (v[a, x] + v[b, x] + v[c, x]) / 3.0
            blo[k, x] = min(v[a, x], v[b, x], v[c, x]) - tol
            bhi[k, x] = max(v[a, x], v[b, x], v[c, x]) + tol
        ext[k] = max(bhi[k, 0] - blo[k, 0], bhi[k, 1] - blo[k, 1], bhi[k, 2] - blo[k, 2])
        if length > 0.0:
            ok[k] = True
            nrm[k] = n / length
            off[k] = nrm[k, 0] * v[a, 0] + nrm[k, 1] * v[a, 1] + nrm[k, 2] * v[a, 2]
    out = np.zeros(m, np.bool_)
    if m < 2:
        return out
    g0 = np.array([blo[:, 0].min(), blo[:, 1].min(), blo[:, 2].min()])
    span = max(bhi[:, 0].max() - g0[0], bhi[:, 1].max() - g0[1], bhi[:, 2].max() - g0[2])
    h = max(np.median(ext), span / 2.0**20, 1e-300)
    while True:  # coarser cells until the entries stay in proportion to the triangles
        count = 0
        for k in range(m):
            c = 1
            for x in range(3):
                c *= int((bhi[k, x] - g0[x]) / h) - int((blo[k, x] - g0[x]) / h) + 1
            count += c
        if count <= 16 * m + 1_000_000:
            break
        h *= 2.0
    dims = int(span / h) + 2
    keys, tri = _grid_entries(blo, bhi, np.arange(m), g0, h, dims, count)
    for k in range(m):
        if not ok[k]:
            continue
        i, j, l = int((cen[k, 0] - g0[0]) / h), int((cen[k, 1] - g0[1]) / h), int((cen[k, 2] - g0[2]) / h)
        key = (i * dims + j) * dims + l
        start = np.searchsorted(keys, key)
        p = cen[k]
        same = 1  # layers over p facing like k (k included), facing the other way,
        other = 0  # and those of the first kind numbered below k
        below = 0
        for e in range(start, len(keys)):
            if keys[e] != key:
                break
            q = tri[e]
            if q == k or not ok[q]:
                continue
            cos = nrm[k, 0] * nrm[q, 0] + nrm[k, 1] * nrm[q, 1] + nrm[k, 2] * nrm[q, 2]
            if abs(cos) < 0.999999:
                continue
            if abs(nrm[q, 0] * p[0] + nrm[q, 1] * p[1] + nrm[q, 2] * p[2] - off[q]) > tol:
                continue
            # Opposite layers count within the tolerance; layers facing like k only
            # where p is strictly inside them: the centroid of a sliver lies within the
            # tolerance of its neighbour's edge, and the neighbour is no second layer.
            inside = True
            for s in range(3):
                va = v[t[cand[q], s]]
                vb = v[t[cand[q], (s + 1) % 3]]
                ex, ey, ez = vb[0] - va[0], vb[1] - va[1], vb[2] - va[2]
                rx, ry, rz = p[0] - va[0], p[1] - va[1], p[2] - va[2]
                # (edge x (p - a)) . n: how far p is inside the edge, times its length
                side = (ey * rz - ez * ry) * nrm[q, 0] + (ez * rx - ex * rz) * nrm[q, 1] + (ex * ry - ey * rx) * nrm[q, 2]
                outside = side < -tol * np.sqrt(ex * ex + ey * ey + ez * ez) if cos < 0 else side <= 0.0
                if outside:
                    inside = False
                    break
            if not inside:
                continue
            if cos > 0:
                same += 1
                if q < k:
                    below += 1
            else:
                other += 1
        # Opposite layers cancel in pairs (the winding number changes by their
        # difference across the plane); of the layers left, one is kept.
        out[k] = other > 0 and below >= min(same - other, 1)
    return out


# A fixed direction no axis-aligned or simple face is perpendicular to: triangles facing
# opposite ways lie on opposite sides of the plane normal to it, except near that plane.
_SIDE_DIRECTION = np.array([1.0, np.e, np.pi]) / np.linalg.norm([1.0, np.e, np.pi])


@njit(cache=True)
def _opposite_box_pairs(
    lo: NDArray[np.float64], hi: NDArray[np.float64], nrm: NDArray[np.float64], first: NDArray[np.bool_],
    second: NDArray[np.bool_],
) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Pairs ``(a, b)``, ``first[a]`` and ``second[b]``, whose boxes ``[lo, hi]`` meet
    (closed boxes) and whose unit normals ``nrm`` are nearly opposite (cosine below
    -0.9), each once, found through a uniform grid over the boxes.

    The work is the sum over grid cells of the product of the two kinds' entries
    there, so the pairs within one plane no longer grow as the product of the
    triangles of its two layers.
    """
    m = len(lo)
    use = np.flatnonzero(first | second)
    if len(use) == 0:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    g0 = np.array([lo[use, 0].min(), lo[use, 1].min(), lo[use, 2].min()])
    span = max(hi[use, 0].max() - g0[0], hi[use, 1].max() - g0[1], hi[use, 2].max() - g0[2])
    ext = np.empty(len(use))
    for u in range(len(use)):
        k = use[u]
        ext[u] = max(hi[k, 0] - lo[k, 0], hi[k, 1] - lo[k, 1], hi[k, 2] - lo[k, 2])
    h = max(np.median(ext), span / 2.0**20, 1e-300)
    while True:  # coarser cells until the entries stay in proportion to the triangles
        count = 0
        for k in use:
            c = 1
            for x in range(3):
                c *= int((hi[k, x] - g0[x]) / h) - int((lo[k, x] - g0[x]) / h) + 1
            count += c
        if count <= 16 * len(use) + 1_000_000:
            break
        h *= 2.0
    dims = int(span / h) + 2
    keys, tri = _grid_entries(lo, hi, use, g0, h, dims, count)
    out_a = np.empty(max(16, m), np.int64)
    out_b = np.empty(max(16, m), np.int64)
    in_a = np.empty(count, np.int64)  # one cell's entries of each kind
    in_b = np.empty(count, np.int64)
    n = 0
    s = 0
    while s < count:
        f = s
        na = 0
        nb = 0
        while f < count and keys[f] == keys[s]:
            if first[tri[f]]:
                in_a[na] = tri[f]
                na += 1
            if second[tri[f]]:
                in_b[nb] = tri[f]
                nb += 1
            f += 1
        cell = keys[s]
        for ea in range(na):
            a = in_a[ea]
            for eb in range(nb):
                b = in_b[eb]
                if b == a or nrm[a, 0] * nrm[b, 0] + nrm[a, 1] * nrm[b, 1] + nrm[a, 2] * nrm[b, 2] > -0.9:
                    continue
                if not (lo[a, 0] <= hi[b, 0] and lo[b, 0] <= hi[a, 0] and lo[a, 1] <= hi[b, 1]
                        and lo[b, 1] <= hi[a, 1] and lo[a, 2] <= hi[b, 2] and lo[b, 2] <= hi[a, 2]):
                    continue
                # each pair once: in the cell of the lower corner of the boxes' overlap
                ci = int((max(lo[a, 0], lo[b, 0]) - g0[0]) / h)
                cj = int((max(lo[a, 1], lo[b, 1]) - g0[1]) / h)
                cl = int((max(lo[a, 2], lo[b, 2]) - g0[2]) / h)
                if (ci * dims + cj) * dims + cl != cell:
                    continue
                if n == len(out_a):
                    grown_a = np.empty(2 * n, np.int64)
                    grown_b = np.empty(2 * n, np.int64)
                    grown_a[:n] = out_a
                    grown_b[:n] = out_b
                    out_a, out_b = grown_a, grown_b
                out_a[n] = a
                out_b[n] = b
                n += 1
        s = f
    return out_a[:n].copy(), out_b[:n].copy()


def _opposite_pairs(
    p: NDArray[np.float64], nrm: NDArray[np.float64], ok: NDArray[np.bool_], key: NDArray[np.float64],
    lo: NDArray[np.float64], hi: NDArray[np.float64], tol: float,
) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Ordered pairs ``(i, j)`` of triangles ``p`` facing opposite ways in one plane
    (``key`` = (n, d) of one within 1e-3 of (-n, -d) of the other), whose boxes meet
    and with every vertex of ``j`` within ``tol`` of ``i``'s plane; sorted by ``(i, j)``.

    Only triangles whose boxes meet are paired (:func:`_opposite_box_pairs`), across
    the sides of :data:`_SIDE_DIRECTION`: normals within 1e-3 of opposite lie on
    opposite sides of it, or within the margin of it on both. Planes with no opposite
    plane near them are left out first, through their distinct keys.
    """
    from scipy.spatial import cKDTree

    if not ok.any():
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    # Distinct keys, rounded to 1e-6: a plane's many triangles become one or two points
    # (a k-d tree over many equal points degenerates); the radius covers the rounding.
    step = 1e-6
    q = np.ascontiguousarray(np.round(key[ok] / step).astype(np.int64))
    _, first, which = np.unique(q.view(np.dtype((np.void, 32))).ravel(), return_index=True, return_inverse=True)
    rounded = q[first] * step
    near = cKDTree(rounded).query_ball_point(-rounded, 1e-3 + 4 * step, return_length=True)
    paired = np.zeros(len(key), bool)
    paired[np.flatnonzero(ok)] = (near > 0)[which.reshape(-1)]
    side = nrm @ _SIDE_DIRECTION
    margin = 4e-3  # > 1e-3, the farthest two paired normals are from opposite
    a, b = _opposite_box_pairs(lo, hi, nrm, paired & (side >= -margin), paired & (side <= margin))
    i = np.concatenate([a, b])
    j = np.concatenate([b, a])
    sel = np.linalg.norm(key[i] + key[j], axis=1) <= 1e-3
    i, j = i[sel], j[sel]
    if len(i):  # a triangle near the margin on both sides: a pair found both ways
        ij = np.unique(np.column_stack([i, j]), axis=0)
        i, j = ij[:, 0], ij[:, 1]
    sel = np.all(np.abs(np.einsum("kvx,kx->kv", p[j], nrm[i]) - key[i, 3][:, None]) <= tol, axis=1)
    return i[sel], j[sel]


def _cancel_partial_overlaps(
    v: NDArray[np.float64], t: NDArray[np.int64], cand: NDArray[np.int64], drop: NDArray[np.bool_], tol: float
) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64], NDArray[np.bool_]]:
    """Cancel opposite layers of a coincident face where they overlap only in part.

    :func:`_on_opposite_face` judges a triangle at its centroid, which is
    right where the opposite layer covers it whole. manifold3d may leave one
    layer as large triangles and the other as small ones (``A - (A & B)``: the
    face of ``A`` and the pieces of ``A & B``'s copy of it cut by ``B``); a
    large triangle half covered is then dropped or kept whole. Such a
    triangle is replaced by its part outside the opposite triangles
    (a fin or shell has one layer each way: they cancel where both are).

    Returns
    -------
    vertices, triangles
        The input with the replacing triangles (and their vertices) appended.
    origin : ndarray of int64
        For every output triangle, the input triangle it lies in.
    drop : ndarray of bool
        Which output triangles to drop (the replaced ones among them).
    """
    import shapely

    n_tri = len(t)
    origin = np.arange(n_tri, dtype=np.int64)
    if len(cand) < 2:
        return v, t, origin, drop
    p = v[t[cand]]  # (m, 3, 3)
    nrm = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    area2 = np.linalg.norm(nrm, axis=1)
    ok = area2 > 0
    nrm = nrm / np.where(ok, area2, 1.0)[:, None]
    off = np.einsum("ij,ij->i", nrm, p[:, 0])
    key = np.column_stack([nrm, off])
    # Opposite orientations: (n, d) of one near (-n, -d) of the other, boxes that meet,
    # and every vertex of the other within tol of the first's plane.
    lo, hi = p.min(axis=1) - tol, p.max(axis=1) + tol
    i, j = _opposite_pairs(p, nrm, ok, key, lo, hi, tol)
    if not len(i):
        return v, t, origin, drop
    # Each pair in the plane of i's triangle, seen along its normal's largest axis (areas in
    # a fixed ratio there); the layers facing one way do not overlap, so pairwise overlaps sum.
    axis = np.argmax(np.abs(nrm), axis=1)
    keep2 = np.array([[1, 2], [0, 2], [0, 1]])[axis]

    def flat(tri: NDArray[np.float64], ax: NDArray[np.int64]) -> Any:
        return shapely.polygons(np.take_along_axis(tri, ax[:, None, :], axis=2))

    # (a triangle with an opposite twin on the same vertices is covered whole)
    same_corners = np.all(np.sort(t[cand[i]], axis=1) == np.sort(t[cand[j]], axis=1), axis=1)
    twin = np.zeros(len(cand), bool)
    twin[i[same_corners]] = True
    i, j = i[~twin[i]], j[~twin[i]]
    own = flat(p[i], keep2[i])
    overlap = shapely.area(shapely.intersection(own, flat(p[j], keep2[i])))
    covered = np.bincount(i, overlap, minlength=len(cand))
    whole = np.zeros(len(cand))  # only the paired triangles' areas are read
    some = np.union1d(i, np.flatnonzero(twin))
    whole[some] = shapely.area(flat(p[some], keep2[some]))
    covered[twin] = whole[twin]
    partial = np.flatnonzero((covered > whole * 1e-9) & (covered < whole * (1 - 1e-9)))
    if not len(partial):
        return v, t, origin, drop
    # The partly covered triangles minus their opposite partners, one partner rank at a time;
    # a partner that only touches is left out: subtracting it is a no-op exactly, but not
    # always in floating point (a sliver's edge, whose result then depended on the order).
    mine = np.isin(i, partial) & (overlap > 0)
    i, j = i[mine], j[mine]
    order = np.argsort(i, kind="stable")
    i, j = i[order], j[order]
    rank = np.arange(len(i)) - np.searchsorted(i, i)
    slot = np.searchsorted(partial, i)
    rest = flat(p[partial], keep2[partial])
    for r in range(int(rank.max()) + 1):
        at = rank == r
        rest[slot[at]] = shapely.difference(rest[slot[at]], flat(p[j[at]], keep2[i[at]]))
    pieces, which = shapely.get_parts(shapely.constrained_delaunay_triangles(rest), return_index=True)
    a = partial[which]
    big = shapely.area(pieces) > whole[a] * 1e-12
    pieces, a = pieces[big], a[big]
    xy = shapely.get_coordinates(shapely.get_exterior_ring(pieces)).reshape(len(pieces), 4, 2)[:, :3]
    # back into the plane of each triangle: the dropped coordinate from n . x = d
    q = np.empty((len(a), 3, 3))
    rows = np.arange(len(a))[:, None]
    q[rows, :, keep2[a]] = np.moveaxis(xy, 2, 1)
    kept_n = np.take_along_axis(nrm[a], keep2[a], axis=1)
    q[rows[:, 0], :, axis[a]] = (off[a][:, None] - np.einsum("tvk,tk->tv", xy, kept_n)) / nrm[a, axis[a]][:, None]
    # each keeps its triangle's own orientation
    flip = np.einsum("ij,ij->i", np.cross(q[:, 1] - q[:, 0], q[:, 2] - q[:, 0]), nrm[a]) < 0
    q[flip] = q[flip, ::-1]
    replaced = np.zeros(n_tri, bool)
    replaced[cand[partial]] = True
    out_drop = np.concatenate([drop | replaced, np.zeros(len(a), bool)])
    return (
        np.vstack([v, q.reshape(-1, 3)]),
        np.vstack([t, len(v) + 3 * np.arange(len(a), dtype=np.int64)[:, None] + np.arange(3)]),
        np.concatenate([origin, cand[a]]),
        out_drop,
    )


def _assemble(pieces: list[tuple[Any, ...]]) -> CSGSurface:
    """One surface from its pieces (vertices, triangles, leaf, source, reversed, value), filled in
    place; each piece is let go once copied (``pieces`` is left holding empty tuples)."""
    if not pieces:
        return _empty()
    nv = np.cumsum([0] + [len(p[0]) for p in pieces])
    nt = np.cumsum([0] + [len(p[1]) for p in pieces])
    if nv[-1] >= 2**31:
        raise InvalidParameterError(f"the clipped CSG surface has {nv[-1]} vertices, more than 2**31 - 1")
    verts = np.empty((nv[-1], 3))
    tris = np.empty((nt[-1], 3), np.int32)
    leaf = np.empty(nt[-1], np.int32)
    source = np.empty(nt[-1], np.int32)
    rev = np.empty(nt[-1], bool)
    value = np.empty(nt[-1])
    for k in range(len(pieces)):
        p = pieces[k]
        pieces[k] = ()  # each piece goes once copied (the list is the caller's, and goes next)
        a, b = nt[k], nt[k + 1]
        verts[nv[k] : nv[k + 1]] = p[0]
        np.add(p[1], nv[k], out=tris[a:b], casting="unsafe")
        leaf[a:b], source[a:b], rev[a:b], value[a:b] = p[2], p[3], p[4], p[5]
        del p
    return CSGSurface(verts, tris, value, leaf, source, rev)


def _empty() -> CSGSurface:
    return CSGSurface(
        np.zeros((0, 3)), np.zeros((0, 3), np.int32), np.zeros(0), np.zeros(0, np.int32), np.zeros(0, np.int32),
        np.zeros(0, bool),
    )


def _triangle_normals(v: NDArray[np.float64], t: NDArray[np.int64]) -> NDArray[np.float64]:
    if not len(t):
        return np.zeros((0, 3))
    return np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])


def csg_surface(
    tree: CSGNode, lights: Sequence[Light], material: Material | None = None, contours: int = 64
) -> CSGSurface:
    """The view-independent band surface of a CSG tree.

    Parameters
    ----------
    tree : CSGNode
    lights : sequence of PointLight or DirectionalLight
    material : Material, optional
        Defaults to ``Material()``. A specular material depends on the eye:
        use :class:`isocsg.rendering.Renderer`, which passes it.
    contours : int, default 64

    Returns
    -------
    CSGSurface

    Examples
    --------
    >>> from isocsg import PointLight, Sphere
    >>> surf = csg_surface(Sphere((0, 0, 0), 1) - Sphere((1, 0, 0), 1), [PointLight((0, -4, 3))], contours=8)
    >>> sorted(set(surf.leaf.tolist())), bool(surf.reversed[surf.leaf == 1].all())
    ([0, 1], True)
    """
    from ..laminae import build_laminae  # the laminae import the CSG package: import on use
    from ..lighting.lights import Material

    if not isinstance(tree, CSGNode):
        raise InvalidGeometryError(f"tree must be a CSG node, got {type(tree).__name__}")
    program = tree.program()
    leaves = program.leaves
    mat = Material() if material is None else material
    bands = [build_laminae(p, tuple(lights), mat, contours).bands for p in leaves]
    return surface_from_bands(program, bands)
