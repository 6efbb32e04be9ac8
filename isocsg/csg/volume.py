"""Volumes of CSG trees: closed forms where the pieces are disjoint, else exact-area sections.

``V = integral A(z) dz`` where ``A(z)`` is the area of the section by the plane
``axis . x = z``. Three ways, tried in this order:

1. **Closed forms.** A primitive's volume is known. A union of operands whose
   bounding boxes do not overlap is the sum of their volumes; a difference
   whose subtracted operands have pairwise non-overlapping boxes, each inside
   its convex first operand (all eight corners of its box), is the first
   operand's volume minus theirs; subtracted operands whose boxes miss the
   first operand's box drop out. A prism along the axis minus prisms along
   it (boxes, cylinders) with non-overlapping boxes, holes of any depths in a
   plate, is the prism minus the overlap of each hole's section with the
   plate's times the overlap of their extents. When the whole tree reduces
   this way the result is exact to rounding (the holes' sections are exact-
   area polygons where they cross the plate's outline).
2. **Splitting into parts.** A union of spheres, or of axis-aligned boxes,
   in which no three leaves overlap pairwise is ``sum V(i) - sum V(i & j)``
   (inclusion-exclusion stops at pairs) with the closed forms of a ball lens
   and a box overlap: a lattice of overlapping balls is exact. Otherwise the
   operands of a union are grouped into clusters of overlapping boxes
   (connected components of the overlap graph, found with an R-tree): the
   union is the sum of its clusters. ``P - Q1 - ... - Qn`` is
   ``V(P) - sum V(P & C)`` over the clusters ``C`` of the ``Qi`` that meet
   ``P``, each ``P & C`` keeping only the leaves of ``P`` whose boxes meet
   ``C``'s. Each part is a closed form or splits again (a work list, no
   recursion), or is integrated on its own, with its own breakpoints; the
   adaptive rule's ``tol`` then holds for each part.
3. **Polyhedral parts.** A part whose leaves all have flat faces only (boxes, convex
   polyhedra, triangle meshes: the kinds' ``polyhedral`` flag) is a polyhedron: its volume is
   that of manifold3d's mesh Boolean of the leaves' exact meshes (double precision; exact to
   rounding, about 1e-12 relative), in milliseconds where sections would need one at every
   height where two faces cross (OpenSCAD's rotated Menger sponge: 221 leaves). With
   ``method="sections"`` such parts are integrated as below instead (the tests compare the two).
4. **Integration over sections.** The axis is split at every leaf's
   breakpoints (its extent, the heights of its vertices, end centres and end circles' lowest and highest points), so
   that no leaf starts, ends or turns a corner inside a piece, and where a flat face meets a
   quadric leaf (:mod:`isocsg.csg.face_events`: the sweep plane tangent to their conic, a rim
   crossing the face, an edge piercing the quadric). Each piece
   keeps only the leaves present in it (:meth:`Program.prune`):

   - where every present leaf is a prism along the axis (boxes and convex
     prisms with faces along or across it, cylinders along it) ``A`` is
     constant: one section at the middle of the piece is exact;
   - elsewhere a 3-point Gauss-Legendre rule per interval, compared with the
     rule on the two halves; the interval with the largest difference is
     halved until the differences sum to ``tol / 4`` of the volume. Areas
     that are polynomials of degree <= 5 along the axis (spheres, cones and
     frusta along it, nested or disjoint) are integrated exactly at once.

   Sections are built with polygons of the exact area of each leaf's section
   (:func:`isocsg.csg.section.primitive_section` with ``area_exact=True``):
   circles are regular polygons of the circle's area, other curves use
   Simpson-pushed midpoints. The only area error left is where two curved
   boundaries cross, O(h^3) per crossing for segments of length h.
"""

from __future__ import annotations

import heapq
import math
import warnings
from collections.abc import Callable

import numpy as np
import shapely
from numpy.typing import ArrayLike, NDArray

from .._validation import integer, nonzero_vector3, scalar
from ..errors import InvalidParameterError
from ..kinds.base import LeafForm, Solid
from ..kinds.planar import circle_ring
from .face_events import face_events
from .mesh import program_manifold
from .program import OP_DIFFERENCE, OP_LEAF, OP_UNION, Program
from .section import (
    combine_sections,
    leaf_sections,
    leaf_table,
    plane_frame,
    solid_program,
)
from .volume_parts import leaf_boxes, lens_volume, pairwise_union, split_parts

__all__ = ["volume", "section_areas", "breakpoints", "closed_form_volume"]

# 3-point Gauss-Legendre on [-1, 1]: exact for polynomials of degree <= 5
_GL_X = np.array([-math.sqrt(0.6), 0.0, math.sqrt(0.6)])
_GL_W = np.array([5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0])
#: The most intervals the adaptive rule halves before it returns what it has.
MAX_SPLITS = 4000


def _unit(axis: ArrayLike) -> NDArray[np.float64]:
    w = np.asarray(nonzero_vector3("axis", axis, error=InvalidParameterError))
    return w / np.linalg.norm(w)


def breakpoints(solid: Solid, axis: ArrayLike = (0.0, 0.0, 1.0)) -> NDArray[np.float64]:
    """Sorted, distinct axial positions where a leaf starts, ends or turns a corner.

    Parameters
    ----------
    solid : Solid
    axis : array_like, shape (3,)
        Direction of the plane normals (normalised here).

    Returns
    -------
    ndarray
        The first and last entries bound the leaves along ``axis``.

    Examples
    --------
    >>> from isocsg import Sphere
    >>> breakpoints(Sphere((0, 0, 1), 2.0)).tolist()
    [-1.0, 3.0]
    """
    return _breakpoints(solid_program(solid), _unit(axis))


def _breakpoints(prog: Program, w: NDArray[np.float64]) -> NDArray[np.float64]:
    tab = leaf_table(prog)
    lo, hi = tab.extents(w)
    z = np.unique(tab.breakpoints(w))
    z = z[(z >= lo.min()) & (z <= hi.max())]
    scale = max(float(z[-1] - z[0]), float(np.max(np.abs(z))), 1e-300)
    keep = np.concatenate([[True], np.diff(z) > 1e-12 * scale])
    return z[keep]


def _radii(tab, ids: NDArray[np.int64], z: NDArray[np.float64], w: NDArray[np.float64]) -> NDArray[np.float64]:
    """Section radii at heights ``z`` of round leaves ``ids`` (spheres, trunci along ``w``)."""
    cz = np.einsum("...j,j->...", tab.center[ids], w)
    rel = z - cz
    sph = tab.kind[ids] == LeafForm.BALL
    out = np.sqrt(np.maximum(tab.radius[ids] ** 2 - rel**2, 0.0))
    h = np.maximum(tab.height[ids], 1e-300)
    sgn = np.sign(np.einsum("...j,j->...", tab.axis[ids], w))
    t = np.clip(rel * sgn + h / 2, 0.0, h) / h
    return np.where(sph, out, tab.r2[ids] + (tab.r1[ids] - tab.r2[ids]) * t)


def _crossing_events(
    prog: Program, w: NDArray[np.float64], lo: NDArray[np.float64], hi: NDArray[np.float64],
) -> NDArray[np.float64]:
    """Heights where a varying circle section (sphere, cone or frustum along ``w``) starts or stops
    crossing another leaf's section: tangent to another circle (outside or inside it, concentric
    circles where their radii are equal), to an edge line of a prism's
    polygon, or through one of its corners. The area is not smooth there."""
    tab = leaf_table(prog)
    k = tab.kind
    along = np.abs(tab.axis @ w) >= 1.0 - 1e-13
    round_ = (k == LeafForm.BALL) | ((k == LeafForm.FRUSTUM) & along)
    varying = (k == LeafForm.BALL) | ((k == LeafForm.FRUSTUM) & along & (tab.r1 != tab.r2))
    if not varying.any():
        return np.zeros(0)
    prism = _prismatic(prog, w) & ~round_
    from .section import primitive_section

    F0 = plane_frame(np.zeros(3), w)
    u, v = F0[:3, 0], F0[:3, 1]
    c2 = np.column_stack([tab.center @ u, tab.center @ v])
    boxes = leaf_boxes(prog)
    vi = np.nonzero(varying)[0]
    partners = np.nonzero(round_ | prism)[0]
    # candidate pairs: boxes overlapping
    lo_box, hi_box = boxes[:, 0], boxes[:, 1]
    ov = np.all((lo_box[vi, None] < hi_box[None, partners]) & (lo_box[None, partners] < hi_box[vi, None]), axis=2)
    I, J = np.nonzero(ov)
    I, J = vi[I], partners[J]
    keep = I != J
    I, J = I[keep], J[keep]
    rows_i: list[NDArray[np.int64]] = []
    rows_j: list[NDArray[np.int64]] = []
    rows_d: list[NDArray[np.float64]] = []
    rows_m: list[NDArray[np.int64]] = []
    rr = round_[J]
    if rr.any():  # circle and circle: outer and inner tangency
        d = np.linalg.norm(c2[I[rr]] - c2[J[rr]], axis=1)
        for mode in (1, 2, 3):
            rows_i.append(I[rr])
            rows_j.append(J[rr])
            rows_d.append(d)
            rows_m.append(np.full(len(d), mode))
    polys: dict[int, NDArray[np.float64]] = {}
    for a, b in zip(I[~rr].tolist(), J[~rr].tolist()):
        if b not in polys:
            sec = primitive_section(prog.leaves[b], plane_frame(0.5 * (lo[b] + hi[b]) * w, w))
            polys[b] = np.asarray(sec.exterior.coords)[:-1] if not sec.is_empty else np.zeros((0, 2))
        P = polys[b]
        if not len(P):
            continue
        Q = np.roll(P, -1, axis=0)
        e = Q - P
        n = np.column_stack([e[:, 1], -e[:, 0]]) / np.maximum(np.linalg.norm(e, axis=1, keepdims=True), 1e-300)
        dl = np.abs(np.einsum("ij,ij->i", n, c2[a] - P))
        dv = np.linalg.norm(P - c2[a], axis=1)
        d = np.concatenate([dl, dv])
        rows_i.append(np.full(len(d), a))
        rows_j.append(np.full(len(d), -1))
        rows_d.append(d)
        rows_m.append(np.zeros(len(d), np.int64))
    if not rows_i:
        return np.zeros(0)
    Ii, Jj, M = np.concatenate(rows_i), np.concatenate(rows_j), np.concatenate(rows_m)
    D = np.concatenate(rows_d)
    Jc = np.where(Jj >= 0, Jj, Ii)
    z0 = np.maximum(lo[Ii], np.where(Jj >= 0, lo[Jc], -np.inf))
    z1 = np.minimum(hi[Ii], np.where(Jj >= 0, hi[Jc], np.inf))
    ok = z1 > z0
    Ii, Jj, Jc, M = Ii[ok], Jj[ok], Jc[ok], M[ok]
    D, z0, z1 = D[ok], z0[ok], z1[ok]

    def g(z: NDArray[np.float64]) -> NDArray[np.float64]:
        ri = _radii(tab, Ii[:, None] if z.ndim == 2 else Ii, z, w)
        rj = _radii(tab, Jc[:, None] if z.ndim == 2 else Jc, z, w)
        Mm = M[:, None] if z.ndim == 2 else M
        Dd = D[:, None] if z.ndim == 2 else D
        f = np.where(Mm == 0, ri, np.where(Mm == 1, ri + rj, np.where(Mm == 2, ri - rj, rj - ri)))
        return Dd - f

    t = np.linspace(0.0, 1.0, 65)
    Z = z0[:, None] + (z1 - z0)[:, None] * t[None, :]
    G = g(Z)
    r, c = np.nonzero((np.sign(G[:, :-1]) * np.sign(G[:, 1:])) < 0)
    if not len(r):
        return np.zeros(0)
    sel = r
    a, b = Z[r, c], Z[r, c + 1]
    ga = G[r, c]
    # g reads these names when called: from here on, the bracketed rows only
    Ii, Jj, Jc, M, D = Ii[sel], Jj[sel], Jc[sel], M[sel], D[sel]
    for _ in range(60):
        m = 0.5 * (a + b)
        gm = g(m)
        left = np.sign(gm) == np.sign(ga)
        a = np.where(left, m, a)
        ga = np.where(left, gm, ga)
        b = np.where(left, b, m)
    return 0.5 * (a + b)


def _prismatic(prog: Program, w: NDArray[np.float64]) -> NDArray[np.bool_]:
    """Leaves whose section along ``w`` does not change between their ends."""
    tab = leaf_table(prog)
    k = tab.kind
    out = np.zeros(len(k), dtype=bool)
    aligned = float(np.max(np.abs(w))) >= 1.0 - 1e-13
    out[k == LeafForm.AXIS_BOX] = aligned
    out[(k == LeafForm.FRUSTUM) & (tab.r1 == tab.r2) & (np.abs(tab.axis @ w) >= 1.0 - 1e-13)] = True
    for i in np.nonzero(k == LeafForm.HULL)[0].tolist():
        faces = prog.leaves[i].planar_faces()
        if faces is not None:
            d = np.abs(faces[0] @ w)
            out[i] = bool(np.all((d <= 1e-13) | (d >= 1.0 - 1e-13)))
    return out



def _disjoint_boxes(lo: NDArray[np.float64], hi: NDArray[np.float64]) -> bool:
    """True when no two boxes overlap with positive volume (touching is fine)."""
    n = len(lo)
    if n < 2:
        return True
    if n <= 64:
        ov = np.all((lo[:, None, :] < hi[None, :, :]) & (lo[None, :, :] < hi[:, None, :]), axis=2)
        np.fill_diagonal(ov, False)
        return not ov.any()
    rects = shapely.box(lo[:, 0], lo[:, 1], hi[:, 0], hi[:, 1])
    tree = shapely.STRtree(rects)
    for start in range(0, n, 1024):  # in chunks: an overlapping set usually shows it in the first
        i, j = tree.query(rects[start : start + 1024])
        i = i + start
        sel = i != j
        i, j = i[sel], j[sel]
        if np.any(np.all((lo[i] < hi[j]) & (lo[j] < hi[i]), axis=1)):
            return False
    return True


def closed_form_volume(solid: Solid) -> float | None:
    """The volume from closed forms alone, or None when the tree does not reduce to them.

    See the module docstring (rule 1): primitives, unions of operands with
    non-overlapping boxes, differences of such operands inside a convex first
    operand.

    Examples
    --------
    >>> from isocsg import Box, Sphere
    >>> v = closed_form_volume(Box((0, 0, 0), (4, 4, 4)) - Sphere((-1, 0, 0), 0.5) - Sphere((1, 0, 0), 0.5))
    >>> round(v, 12) == round(64 - 2 * 4 / 3 * math.pi * 0.125, 12)
    True
    >>> closed_form_volume(Box((0, 0, 0), (4, 4, 4)) - Sphere((2, 0, 0), 1)) is None
    True
    """
    return _closed_form(solid_program(solid))


def _closed_form(prog: Program) -> float | None:
    boxes = leaf_boxes(prog)
    leaves = prog.leaves
    # operands are compared by interned keys: equal subtrees get the same integer
    keys: dict[object, int] = {}
    nodes: dict[int, tuple[int, tuple[int, ...]]] = {}

    def key(k: object) -> int:
        return keys.setdefault(k, len(keys))

    def leaf(i, p):
        return (float(p.volume), boxes[i, 0], boxes[i, 1], i, key(p))

    def combine(op, xs):
        if op != OP_DIFFERENCE:
            seen: set[int] = set()
            xs = [x for x in xs if not (x[4] in seen or seen.add(x[4]))]  # A | A = A & A = A
            if len(xs) == 1:
                return xs[0]
        k = key((op, tuple(x[4] for x in xs)))
        nodes.setdefault(k, (op, tuple(x[4] for x in xs)))
        lo = np.array([x[1] for x in xs])
        hi = np.array([x[2] for x in xs])
        if op == OP_UNION:
            ok = all(x[0] is not None for x in xs) and _disjoint_boxes(lo, hi)
            return (sum(x[0] for x in xs) if ok else None, lo.min(axis=0), hi.max(axis=0), -1, k)
        if op == OP_DIFFERENCE:
            first = xs[0]
            rest_keys = {x[4] for x in xs[1:]}
            fn = nodes.get(first[4], (None, ()))
            if first[4] in rest_keys or (fn[0] == OP_UNION and set(fn[1]) <= rest_keys) or any(
                nodes.get(x[4], (None, ()))[0] == OP_DIFFERENCE
                and nodes[x[4]][1][0] == first[4]
                and set(nodes[x[4]][1][1:]) <= rest_keys
                for x in xs[1:]
            ):
                return (0.0, first[1], first[2], -1, k)  # A - A (any flattening of it) is empty
            meet = np.all((lo[1:] < first[2]) & (hi[1:] > first[1]), axis=1)
            rest = [x for x, m in zip(xs[1:], meet) if m]
            if not rest:
                return first
            ok = first[0] is not None and first[3] >= 0 and all(x[0] is not None for x in rest)
            if ok:
                rlo = np.array([x[1] for x in rest])
                rhi = np.array([x[2] for x in rest])
                ok = _disjoint_boxes(rlo, rhi)
            if ok:
                signs = np.array([[a, b, c] for a in (0, 1) for b in (0, 1) for c in (0, 1)], dtype=bool)
                corners = np.where(signs[None, :, :], rhi[:, None, :], rlo[:, None, :]).reshape(-1, 3)
                ok = bool(np.all(leaves[first[3]].contains(corners, tol=0.0)))
            vol = first[0] - sum(x[0] for x in rest) if ok else None
            return (vol, first[1], first[2], -1, k)
        box_lo, box_hi = lo.max(axis=0), np.maximum(hi.min(axis=0), lo.max(axis=0))
        if len(xs) == 2 and xs[0][3] >= 0 and xs[1][3] >= 0:
            a, b = leaves[xs[0][3]].leaf_row(), leaves[xs[1][3]].leaf_row()
            if a.form == LeafForm.BALL and b.form == LeafForm.BALL:  # a lens
                d = math.dist(a.center, b.center)  # type: ignore[arg-type]
                lens = lens_volume(np.array(a.radius), np.array(b.radius), np.array(d))
                return (float(lens), box_lo, box_hi, -1, k)
        # an operand whose box lies inside every other operand, each a (convex) primitive, is the result
        small = int(np.argmin(np.prod(hi - lo, axis=1)))
        x = xs[small]
        others = [y for j, y in enumerate(xs) if j != small]
        if x[0] is not None and all(y[3] >= 0 for y in others):
            signs = np.array([[a, b, c] for a in (0, 1) for b in (0, 1) for c in (0, 1)], dtype=bool)
            corners = np.where(signs, x[2], x[1])
            if all(np.all(leaves[y[3]].contains(corners, tol=0.0)) for y in others):
                return (x[0], x[1], x[2], x[3], k)
        return (None, box_lo, box_hi, -1, k)

    v = prog.evaluate(leaf, combine)[0]
    return None if v is None else max(float(v), 0.0)


def _resolution(tol: float) -> int:
    """Polygon vertices per full circle for a relative accuracy ``tol``.

    Exact-area polygons only err where two curved boundaries cross: about
    ``r^2 h^3 / 24`` per crossing for segments of angle ``h``; ``h`` is chosen as ``(24 tol)^(1/3)``.
    """
    h = (24.0 * tol) ** (1.0 / 3.0)
    return int(min(max(2 * math.ceil(2 * math.pi / h), 64), 8192))


def _area_fn(prog: Program, w: NDArray[np.float64], res: int):
    def area(z: float, sub: Program, ids: NDArray[np.int64]) -> float:
        F = plane_frame(z * w, w)
        geoms = leaf_sections(prog, F, res, area_exact=True, ids=ids)
        return float(combine_sections(sub, geoms, area_only=True))

    return area


def section_areas(
    solid: Solid,
    positions: ArrayLike,
    axis: ArrayLike = (0.0, 0.0, 1.0),
    *,
    resolution: int = 256,
) -> NDArray[np.float64]:
    """Areas of the sections by the planes ``axis . x = positions[i]`` (exact-area polygons).

    Parameters
    ----------
    solid : Solid
    positions : array_like, shape (n,)
        Signed plane positions along the unit ``axis``.
    axis : array_like, shape (3,)
    resolution : int, default 256
        Polygon vertices per full circle.

    Returns
    -------
    ndarray, shape (n,)

    Examples
    --------
    >>> from isocsg import Box, Sphere
    >>> section_areas(Box((0, 0, 0), (1, 2, 3)), [0.0, 1.4, 2.0]).tolist()
    [2.0, 2.0, 0.0]
    >>> a = section_areas(Sphere((0, 0, 0), 1), [0.6], resolution=64)[0]
    >>> bool(abs(a / (math.pi * 0.64) - 1) < 1e-14)
    True
    """
    from .section import program_section

    w = _unit(axis)
    res = integer("resolution", resolution, low=8, high=1_000_000, error=InvalidParameterError)
    z = np.atleast_1d(np.asarray(positions, dtype=np.float64))
    if z.ndim != 1 or not np.all(np.isfinite(z)):
        raise InvalidParameterError(f"positions must be a 1-D array of finite numbers, got shape {z.shape}")
    prog = solid_program(solid)
    return np.array([program_section(prog, plane_frame(zi * w, w), res, area_exact=True, area_only=True) for zi in z])


def volume(
    solid: Solid,
    *,
    tol: float = 1e-4,
    axis: ArrayLike = (0.0, 0.0, 1.0),
    resolution: int | None = None,
    progress: Callable[[int, int], None] | None = None,
    method: str = "auto",
) -> float:
    """Volume of a primitive or CSG tree: closed forms, else exact mesh Booleans of polyhedral parts,
    else exact-area sections.

    See the module docstring for the method. Closed-form trees (primitives,
    disjoint unions, differences of disjoint solids inside a convex one,
    unions of spheres or boxes of which no three overlap pairwise) and
    trees whose section areas are piecewise polynomials of degree <= 5 along
    ``axis`` (prisms along it, spheres, cones and cylinders along it, nested
    or disjoint) come out exact to rounding; elsewhere the adaptive rule
    stops at the relative accuracy ``tol``.

    Parameters
    ----------
    solid : Solid
        A primitive or CSG tree (an empty result has volume 0).
    tol : float, default 1e-4
        Target relative accuracy, in (0, 0.1].
    axis : array_like, shape (3,), default (0, 0, 1)
        Normal of the section planes.
    resolution : int, optional
        Polygon vertices per full circle; overrides the choice from ``tol``
        (94 at the default ``tol``, 436 at 1e-6).
    progress : callable, optional
        Called as ``progress(done, total)``: after each integrated part when
        the tree splits into several (``total`` parts), else after each piece
        of the axis and while the adaptive rule refines (``total`` then
        grows); the last call has ``done == total``.
    method : {"auto", "sections"}, default "auto"
        ``"auto"`` takes a part whose leaves are all polyhedral from its exact mesh Boolean;
        ``"sections"`` integrates every part that has no closed form over plane sections.

    Returns
    -------
    float
        Cubic metres.

    Raises
    ------
    InvalidGeometryError
        If ``solid`` is not a solid.
    InvalidParameterError
        On a bad ``tol``, ``axis``, ``resolution`` or ``method``.

    Examples
    --------
    >>> from isocsg import Cylinder, Sphere
    >>> R, r = 1.0, 0.5
    >>> v = volume(Sphere((0, 0, 0), R) - Cylinder((0, 0, 0), (0, 0, 3), r), tol=1e-6)
    >>> exact = 4 / 3 * math.pi * (R**2 - r**2) ** 1.5
    >>> abs(v / exact - 1) < 1e-6
    True
    >>> v = volume(Sphere((0, 0, 0), 1) | Sphere((0, 0, 0.5), 0.2))  # nested: exact
    >>> abs(v / (4 / 3 * math.pi) - 1) < 1e-13
    True
    """
    tol_ = scalar("tol", tol, low=0.0, high=0.1, error=InvalidParameterError)
    if resolution is None:
        res = _resolution(tol_)
    else:
        res = integer("resolution", resolution, low=8, high=1_000_000, error=InvalidParameterError)
    if method not in ("auto", "sections"):
        raise InvalidParameterError(f'volume: method must be "auto" or "sections", got {method!r}')
    w = _unit(axis)
    prog = solid_program(solid)
    # a work list (no recursion): each program is a closed form, splits into signed parts, or is
    # integrated; the integrals run last so that progress can count them
    total = 0.0
    work: list[tuple[Program, float]] = [(prog, 1.0)]
    integrals: list[tuple[Program, float]] = []
    while work:
        p, sign = work.pop()
        exact = _closed_form(p)
        if exact is None:
            exact = _prism_minus_disjoint_prisms(p, w, res)
        if exact is None:
            exact = pairwise_union(p)
        if exact is not None:
            total += sign * exact
            continue
        parts = split_parts(p)
        if parts is None and method == "auto" and all(type(leaf).polyhedral for leaf in p.leaves):
            total += sign * program_manifold(p, 8).volume()
        elif parts is None:
            integrals.append((p, sign))
        else:
            work.extend((q, sign * s) for q, s in parts)
    m = len(integrals)
    for k, (p, sign) in enumerate(integrals):
        inner = progress if m == 1 else None
        total += sign * _integrate(p, w, tol_, res, inner)
        if progress is not None and m > 1:
            progress(k + 1, m)
    if progress is not None and m == 0:
        progress(1, 1)
    return max(float(total), 0.0)


def _prism_minus_disjoint_prisms(prog: Program, w: NDArray[np.float64], res: int) -> float | None:
    """``P - Q1 - ... - Qn`` of prisms along ``w`` (boxes, cylinders along it) whose boxes do not
    overlap each other: ``V(P) - sum V(P & Qi)``, each ``V(P & Qi)`` the area of the two sections'
    overlap times the overlap of their extents (holes of any depths in a plate, all at once).
    None when the tree is not of that form."""
    n = len(prog.leaves)
    if n < 3 or prog.op[-1] != OP_DIFFERENCE or int(prog.arg[-1]) != n or np.any(prog.op[:-1] != OP_LEAF):
        return None
    tab = leaf_table(prog)
    prism = _prismatic(prog, w)
    kind = tab.kind
    cyl = (kind == LeafForm.FRUSTUM) & prism
    if not prism[0] or not np.all(cyl[1:] | (kind[1:] == LeafForm.AXIS_BOX) & prism[1:]):
        return None
    boxes = leaf_boxes(prog)
    order = np.asarray(prog.arg[:-1])  # leaf index of each operand, first operand first
    first, rest = int(order[0]), order[1:]
    meet = np.all((boxes[rest, 0] < boxes[first, 1]) & (boxes[rest, 1] > boxes[first, 0]), axis=1)
    rest = rest[meet]
    if not _disjoint_boxes(boxes[rest, 0], boxes[rest, 1]):
        return None
    lo, hi = tab.extents(w)
    F = plane_frame(0.5 * (lo[first] + hi[first]) * w, w)
    base = leaf_sections(prog, F, res, area_exact=True, ids=np.array([first]))[0]
    length = np.minimum(hi[rest], hi[first]) - np.maximum(lo[rest], lo[first])
    # each hole's section, built in a plane through the middle of its own extent
    u, v = F[:3, 0], F[:3, 1]
    c2 = np.column_stack([tab.center[rest] @ u, tab.center[rest] @ v])
    area = np.zeros(len(rest))
    rc = cyl[rest]
    if rc.any():
        r = tab.r1[rest][rc]
        circles = shapely.polygons(circle_ring(c2[rc], r, res, True))
        shapely.prepare(base)
        inner = shapely.contains_properly(base, circles)
        cut = np.where(inner, math.pi * r * r, 0.0)
        if (~inner).any():
            cut[~inner] = shapely.area(shapely.intersection(base, circles[~inner]))
        area[rc] = cut
    rb = ~rc
    if rb.any():
        half = tab.half[rest][rb]
        hu, hv = half @ np.abs(u), half @ np.abs(v)
        rects = shapely.box(c2[rb, 0] - hu, c2[rb, 1] - hv, c2[rb, 0] + hu, c2[rb, 1] + hv)
        area[rb] = shapely.area(shapely.intersection(base, rects))
    total = float(base.area) * float(hi[first] - lo[first]) - float(np.sum(area * np.maximum(length, 0.0)))
    return max(total, 0.0)


def _integrate(
    prog: Program, w: NDArray[np.float64], tol: float, res: int, progress: Callable[[int, int], None] | None
) -> float:
    tab = leaf_table(prog)
    lo, hi = tab.extents(w)
    z = _breakpoints(prog, w)
    ev = np.concatenate([_crossing_events(prog, w, lo, hi), face_events(prog, w)])
    if len(ev):
        z = np.unique(np.concatenate([z, ev[(ev > z[0]) & (ev < z[-1])]]))
        scale = max(float(z[-1] - z[0]), float(np.max(np.abs(z))), 1e-300)
        z = z[np.concatenate([[True], np.diff(z) > 1e-12 * scale])]
    n_pieces = len(z) - 1
    if n_pieces < 1:
        return 0.0
    scale = max(float(z[-1] - z[0]), float(np.max(np.abs(z))), 1e-300)
    eps = 1e-12 * scale
    # piece k is [z[k], z[k+1]]; leaf i is present in pieces k0[i] <= k < k1[i]
    k0 = np.searchsorted(z, lo + 2 * eps, side="right") - 1
    k1 = np.searchsorted(z, hi - 2 * eps, side="left")
    starts = np.argsort(k0, kind="stable")
    ends = np.argsort(k1, kind="stable")
    prism = _prismatic(prog, w)
    area = _area_fn(prog, w, res)
    # an absolute floor for results near 0, from the result's box (a difference's first operand's,
    # an intersection's overlap), not the leaves': a small part cut by a big box keeps its tol
    boxes = leaf_boxes(prog)
    span = float(np.max(np.diff(prog.bounds(boxes[:, 0], boxes[:, 1]), axis=0)))
    floor = 1e-3 * tol * span**3

    present = np.zeros(len(prog.leaves), dtype=bool)
    si = ei = 0
    exact_total = 0.0
    heap: list[tuple[float, int, float, float, float, float, float, int]] = []
    pieces: list[tuple[Program, NDArray[np.int64]]] = []
    total = 0.0
    total_err = 0.0
    pr: tuple[Program, NDArray[np.int64]] | None = None
    changed = True
    counter = 0

    def gl(a: float, b: float, sub: Program, ids: NDArray[np.int64]) -> float:
        h = 0.5 * (b - a)
        m = 0.5 * (a + b)
        return h * sum(wt * area(m + h * x, sub, ids) for x, wt in zip(_GL_X, _GL_W))

    for k in range(n_pieces):
        while si < len(starts) and k0[starts[si]] <= k:
            if k1[starts[si]] > k:
                present[starts[si]] = True
                changed = True
            si += 1
        while ei < len(ends) and k1[ends[ei]] <= k:
            if present[ends[ei]]:
                present[ends[ei]] = False
                changed = True
            ei += 1
        if changed:
            pr = prog.prune(present) if present.any() else None
            changed = False
        a, b = float(z[k]), float(z[k + 1])
        if pr is not None and b > a:
            sub, ids = pr
            if prism[ids].all():
                exact_total += area(0.5 * (a + b), sub, ids) * (b - a)
            else:
                pieces.append(pr)
                q = gl(a, b, sub, ids)
                m = 0.5 * (a + b)
                ql, qr = gl(a, m, sub, ids), gl(m, b, sub, ids)
                err = abs(q - (ql + qr))
                heapq.heappush(heap, (-err, counter, a, b, ql + qr, ql, qr, len(pieces) - 1))
                counter += 1
                total += ql + qr
                total_err += err
        if progress is not None:
            progress(k + 1, n_pieces)
    splits = 0
    while heap and total_err > 0.25 * tol * abs(exact_total + total) + floor:
        if splits >= MAX_SPLITS:
            warnings.warn(
                f"volume: stopped after {MAX_SPLITS} interval splits with an estimated error of "
                f"{total_err:.3g} m^3 (tol asks for {0.25 * tol * abs(exact_total + total):.3g})",
                RuntimeWarning,
                stacklevel=3,
            )
            break
        negerr, _, a, b, val, ql, qr, p = heapq.heappop(heap)
        total -= val
        total_err += negerr
        sub, ids = pieces[p]
        m = 0.5 * (a + b)
        for aa, bb, q in ((a, m, ql), (m, b, qr)):
            mm = 0.5 * (aa + bb)
            l2, r2 = gl(aa, mm, sub, ids), gl(mm, bb, sub, ids)
            err = abs(q - (l2 + r2))
            heapq.heappush(heap, (-err, counter, aa, bb, l2 + r2, l2, r2, p))
            counter += 1
            total += l2 + r2
            total_err += err
        splits += 1
        if progress is not None:
            progress(n_pieces + splits, n_pieces + splits + 1)
    if progress is not None:
        progress(n_pieces + splits, n_pieces + splits)
    # re-add the accepted values exactly (the running sum drifts by rounding)
    return float(max(exact_total + sum(item[4] for item in heap), 0.0))
