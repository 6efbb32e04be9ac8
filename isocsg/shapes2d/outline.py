"""Outlines (shadows on the xy plane along z) of solids as exact 2D shapes: ``projection(cut = false)``.

A point (x, y) is in the outline when the vertical line through it meets the solid. The outline of
a union is the union of its parts' outlines; a convex leaf's outline is exact (a ball's ellipse, a
truncus's hull of its two end ellipses, a polyhedron's hull). A difference or an intersection is
not the Boolean of its operands' outlines; these rules are exact:

- a difference ``A - B1 - ... - Bn`` (a chain built by ``s = s - b`` in a loop is read as one,
  iteratively, and a subtracted union as its parts): a ``Bi`` that misses ``A``'s box subtracts
  nothing; a ``Bi`` that is a vertical prism through ``A``'s whole height removes its section
  (``proj(A - P) = proj(A) - section(P)``), whatever ``A`` is. When ``A`` is made of vertical
  prisms, it is read slab by slab between the heights of its leaves' ends: each slab ``[lo, hi]``
  is a prism of one section, and a column of it is removed where the ``Bi`` hold all of
  ``[lo, hi]`` there: a convex ``Bi`` alone where it holds both ends, ``section(Bi, lo) &
  section(Bi, hi)``; vertical prisms whose boxes overlap where, in every slab between their
  heights, one of them holds the point (the intersection over those slabs of the union of their
  sections). Groups are the connected sets of overlapping boxes, so the work grows with the
  number of operands, not its square. When ``A`` is a ball or an upright cone or frustum (its
  horizontal sections nested discs), a vertical prism leaf over ``[b0, b1]`` that overlaps no
  other such cut removes its section minus ``A``'s outlines below ``b0`` and above ``b1`` (the
  columns of ``A`` within ``[b0, b1]``);
- an intersection of one solid with vertical prisms through its height: its outline cut to their
  sections;
- any tree whose leaves are all vertical prisms (boxes, polyhedral prisms and cylinders with
  vertical axes, straight extrusions): its section is the same between consecutive leaf heights,
  so the outline is the union of one section per slab.

A tree that none of these reaches and whose leaves are all flat faced takes manifold3d's Boolean
of the polyhedra, projected (exact, but slower on thousands of operands than the rules above).
Any other tree raises :class:`~isocsg.errors.NotExactError` naming the operand that stops it.
"""

from __future__ import annotations

import math
from collections import defaultdict
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..csg.tree import distinct_postorder
from ..errors import NotExactError
from ..kinds import Solid
from ..kinds.forms import AffineBall, AffineFrustum, PointHull, RingTorus, TriangleSurface
from .hull2d import disc_hull
from .leaves import Circle
from .region import shape_from_region
from .sections import _children, _combine, _convex, _ellipse, _op, leaf_section_at, section_at
from .shape import EMPTY, Shape2D

__all__ = ["outline", "leaf_outline"]

#: Relative slack of the height comparisons (a prism "through" a solid, leaves of one height).
_UP = np.array([0.0, 0.0, 1.0])
_SLACK = 1e-9

#: A plan for one node: the nodes whose outlines it needs, and how it makes its own from them.
_Plan = tuple[list[Any], Callable[[list[Shape2D]], Shape2D]]


def outline(solid: Solid) -> Shape2D:
    """The outline (shadow on the xy plane along z) of ``solid``, exactly (see the module docs).

    Raises
    ------
    NotExactError
        For a difference or intersection that no exact rule reaches, naming the operand.

    Examples
    --------
    >>> from isocsg import Box, Cylinder
    >>> from isocsg.shapes2d import area
    >>> round(area(outline(Cylinder((0, 0, 0), (0, 0, 2), 1))) / math.pi, 12)
    1.0
    >>> plate = Box((0, 0, 0), (4, 4, 1))
    >>> blind = Cylinder((1, 1, 0.5), (0, 0, 0.6), 0.5)   # from the top, not through
    >>> through = Cylinder((-1, -1, 0), (0, 0, 2), 0.5)
    >>> round(area(outline(plate - blind - through)) + math.pi / 4, 12)
    16.0
    """
    facts = _Facts(solid)
    done: dict[int, Shape2D] = {}
    plans: dict[int, _Plan] = {}
    stack: list[Any] = [solid]
    while stack:
        s = stack[-1]
        if id(s) in done:
            stack.pop()
            continue
        if _children(s) is None:
            done[id(s)] = leaf_outline(s)
            stack.pop()
            continue
        if id(s) not in plans:
            plans[id(s)] = _plan(s, facts)
        needs, finish = plans[id(s)]
        missing = [c for c in needs if id(c) not in done]
        if missing:
            stack.extend(missing)
            continue
        done[id(s)] = finish([done[id(c)] for c in needs])
        stack.pop()
    return done[id(solid)]


# --------------------------------------------------------------------------- what each node is


class _Facts:
    """What the rules ask of every node and leaf, from one post-order pass (by ``id``): flat faced,
    every leaf a vertical prism, the heights over which all its leaves are vertical prisms, the one
    height range all its leaves span when they are prisms over the same one, and a bounding box
    (leaves' boxes read in one vectorised pass per kind)."""

    def __init__(self, root: Any) -> None:
        self.flat: dict[int, bool] = {}
        self.prismatic: dict[int, bool] = {}
        self.range: dict[int, tuple[float, float] | None] = {}
        self.uniform: dict[int, tuple[float, float] | None] = {}
        self.box: dict[int, NDArray[np.float64]] = {}
        order = distinct_postorder(root)
        self._read_leaves([s for s in order if _children(s) is None])
        for s in order:
            kids = _children(s)
            if kids is not None:
                self._read_node(s, kids)

    def _read_leaves(self, leaves: list[Any]) -> None:
        by_kind: dict[type, list[Any]] = defaultdict(list)
        for leaf in leaves:
            by_kind[type(leaf)].append(leaf)
        for kind, group in by_kind.items():
            lo, hi = (np.asarray(a, dtype=np.float64) for a in kind.leaf_boxes(group)[:2])  # type: ignore[attr-defined]
            for k, leaf in enumerate(group):
                key = id(leaf)
                self.box[key] = np.array([lo[k], hi[k]])
                self.flat[key] = bool(kind.polyhedral)  # type: ignore[attr-defined]
                upright = _upright(leaf)
                self.prismatic[key] = upright
                r = (float(lo[k, 2]), float(hi[k, 2])) if upright else None
                self.range[key] = self.uniform[key] = r

    def _read_node(self, s: Any, kids: tuple[Any, ...]) -> None:
        key, op = id(s), _op(s)
        self.flat[key] = all(self.flat[id(c)] for c in kids)
        self.prismatic[key] = all(self.prismatic[id(c)] for c in kids)
        ranges = [self.range[id(c)] for c in kids]
        if any(r is None for r in ranges):
            self.range[key] = None
        else:
            lo, hi = max(r[0] for r in ranges), min(r[1] for r in ranges)  # type: ignore[index]
            self.range[key] = (lo, hi) if lo < hi else None
        spans = [self.uniform[id(c)] for c in kids]
        first = spans[0]
        same = first is not None and all(r is not None and _same_range(r, first) for r in spans)
        self.uniform[key] = first if same else None
        boxes = np.array([self.box[id(c)] for c in kids])
        if op == "union":
            self.box[key] = np.array([boxes[:, 0].min(axis=0), boxes[:, 1].max(axis=0)])
        elif op == "intersection":
            lo3, hi3 = boxes[:, 0].max(axis=0), boxes[:, 1].min(axis=0)
            self.box[key] = np.array([lo3, np.maximum(lo3, hi3)])
        else:
            self.box[key] = boxes[0]


def _same_range(a: tuple[float, float], b: tuple[float, float]) -> bool:
    tol = _SLACK * max(abs(a[0]), abs(a[1]), a[1] - a[0], 1.0)
    return abs(a[0] - b[0]) <= tol and abs(a[1] - b[1]) <= tol


def _upright(leaf: Any) -> bool:
    """Whether a leaf is a vertical prism: its section the same at every height it spans."""
    return _children(leaf) is None and bool(leaf.is_prism_along(_UP, 1e-12))


# --------------------------------------------------------------------------- plans


def _plan(s: Any, facts: _Facts) -> _Plan:
    op, kids = _op(s), tuple(_children(s) or ())
    if op == "union":
        return list(kids), lambda shapes: _combine("union", shapes)
    try:  # the rules on vertical prisms first: near-linear in the operands, where manifold3d's Boolean is not
        if op == "intersection":
            if facts.prismatic[id(s)]:
                return [], lambda _: _slab_outline(s, facts)
            return _plan_intersection(kids, facts)
        return _plan_difference(s, facts)
    except NotExactError:
        if facts.flat[id(s)]:
            return [], lambda _: _manifold_outline(s)
        raise


def _difference_chain(s: Any) -> tuple[Any, list[Any]]:
    """``A - B1 - ... - Bn`` read from nested differences (left operands) and subtracted unions
    (their parts), iteratively: the first operand and the list of what is subtracted."""
    subs: list[Any] = []
    core = s
    while _children(core) is not None and _op(core) == "difference":
        kids = _children(core) or ()
        subs.extend(kids[1:])
        core = kids[0]
    out: list[Any] = []
    while subs:
        k = subs.pop()
        if _children(k) is not None and _op(k) == "union":
            subs.extend(_children(k) or ())
        else:
            out.append(k)
    return core, out


def _slack(lo: float, hi: float) -> float:
    return _SLACK * max(hi - lo, abs(lo), abs(hi), 1.0)


def _section_inside(s: Any, z: float, facts: _Facts) -> Shape2D:
    """The section at a height strictly inside ``s``'s prism range (no face lies in the plane)."""
    form = s.exact_form() if _children(s) is None and facts.prismatic[id(s)] else None
    if isinstance(form, AffineFrustum) and form.right:  # the common hole: its disc, read off directly
        return Circle((float(form.center[0]), float(form.center[1])), form.r1)
    return leaf_section_at(s, z) if _children(s) is None else section_at(s, z)


def _plan_difference(s: Any, facts: _Facts) -> _Plan:
    core, subs = _difference_chain(s)
    cb = facts.box[id(core)]
    lo, hi = float(cb[0, 2]), float(cb[1, 2])
    boxes = np.array([facts.box[id(k)] for k in subs]).reshape(-1, 2, 3)
    hit = np.all(boxes[:, 0] < cb[1], axis=1) & np.all(cb[0] < boxes[:, 1], axis=1)
    subs, boxes = [k for k, h in zip(subs, hit) if h], boxes[hit]
    if not facts.prismatic[id(core)]:
        return [core], _cut_curved(core, subs, lo, hi, facts)
    # a first operand of vertical prisms: one layer per slab between the heights of its leaves' ends
    pieces = []
    heights = _heights([core], facts, lo, hi)
    for z0, z1 in zip(heights, heights[1:]):
        layer = _section_inside(core, 0.5 * (z0 + z1), facts)
        if layer is EMPTY:
            continue
        here = (boxes[:, 0, 2] < z1) & (boxes[:, 1, 2] > z0)
        pieces.append(_cut_layer(layer, [k for k, h in zip(subs, here) if h], z0, z1, facts))
    result = _combine("union", pieces)
    return [], lambda _: result


def _cut_curved(core: Any, subs: list[Any], lo: float, hi: float,
                facts: _Facts) -> Callable[[list[Shape2D]], Shape2D]:
    """A first operand that is not made of vertical prisms: vertical prisms through it take their
    sections out. When its horizontal sections are nested discs (a ball, an upright cone or
    frustum), a vertical prism leaf over ``[b0, b1]`` that does not overlap another such cut also
    takes out the part of its section where the first operand's column lies within ``[b0, b1]``:
    its section minus the outlines of the first operand below ``b0`` and above ``b1``."""
    slack = _slack(lo, hi)
    cuts: list[Shape2D] = []
    partial: list[Any] = []
    nested = _nested_discs(core)
    for k in subs:
        r = facts.range[id(k)]
        if r is not None and r[0] <= lo + slack and r[1] >= hi - slack:
            cuts.append(_section_inside(k, 0.5 * (max(lo, r[0]) + min(hi, r[1])), facts))
        elif nested and r is not None and _children(k) is None:
            partial.append(k)
        else:
            what = "not a vertical prism" if r is None else f"a vertical prism over z in [{r[0]:g}, {r[1]:g}], not"
            raise NotExactError(
                f"projection: the outline of a difference whose operand {type(k).__name__} is {what} through the "
                f"first operand (z in [{lo:g}, {hi:g}]), which is not a vertical prism, is not computed exactly; "
                "a projection of a difference is not the difference of projections")
    for group in _overlap_groups([facts.box[id(k)] for k in partial]):
        if len(group) > 1:
            raise NotExactError(
                f"projection: the outline of a difference of a {type(core).__name__} and {len(group)} overlapping "
                f"vertical prisms ({type(partial[group[0]]).__name__}, ...) that do not run through it is not "
                "computed exactly")
        k = partial[group[0]]
        b0, b1 = facts.range[id(k)]  # type: ignore[misc]
        caps = ([_cap_outline(core, lo, min(b0, hi))] if b0 > lo + slack else []) + (
            [_cap_outline(core, max(b1, lo), hi)] if b1 < hi - slack else [])
        cuts.append(_combine("difference", [_section_inside(k, 0.5 * (max(lo, b0) + min(hi, b1)), facts), *caps]))
    return lambda shapes: _combine("difference", [shapes[0], *cuts])


def _nested_discs(leaf: Any) -> bool:
    """Whether a leaf's horizontal sections are concentric discs: a ball, an upright truncus."""
    form = leaf.exact_form() if _children(leaf) is None else None
    if isinstance(form, AffineBall):
        return form.radius is not None
    if isinstance(form, AffineFrustum) and form.right:
        ax, ay, az = (float(v) for v in form.matrix[:, 2])
        return max(abs(ax), abs(ay)) <= 1e-12 * abs(az)
    return False


def _cap_outline(core: Any, z0: float, z1: float) -> Shape2D:
    """The outline of the part of ``core`` (:func:`_nested_discs`) between heights ``z0`` and ``z1``:
    its widest section there (a ball's nearest its centre, a truncus's at one of the two ends)."""
    form = core.exact_form()
    if isinstance(form, AffineBall):
        return leaf_section_at(core, min(max(float(form.center[2]), z0), z1))
    return _combine("union", [leaf_section_at(core, z0), leaf_section_at(core, z1)])


def _cut_layer(layer: Shape2D, subs: list[Any], lo: float, hi: float, facts: _Facts) -> Shape2D:
    """The outline of the prism of section ``layer`` over ``[lo, hi]`` minus ``subs``: the sections
    of those through it, and the columns the others hold together (:func:`_covered`)."""
    slack = _slack(lo, hi)
    cuts: list[Shape2D] = []
    partial: list[Any] = []
    for k in subs:
        r = facts.range[id(k)]
        if r is not None and r[0] <= lo + slack and r[1] >= hi - slack:
            cuts.append(_section_inside(k, 0.5 * (max(lo, r[0]) + min(hi, r[1])), facts))
        elif facts.prismatic[id(k)] or (_children(k) is None and type(k).convex):
            partial.append(k)
        else:
            raise NotExactError(
                f"projection: the outline of a difference whose operand {type(k).__name__} is neither a vertical "
                f"prism nor a convex solid, and does not run through the first operand (z in [{lo:g}, {hi:g}]), is "
                "not computed exactly")
    for group in _overlap_groups([facts.box[id(k)] for k in partial]):
        region = _covered([partial[i] for i in group], lo, hi, facts)
        if region is not EMPTY:
            cuts.append(region)
    return _combine("difference", [layer, *cuts])


def _plan_intersection(kids: tuple[Any, ...], facts: _Facts) -> _Plan:
    """One operand that is not a vertical prism, cut to the sections of the others, which must be
    vertical prisms through its whole height."""
    others = [k for k in kids if facts.range[id(k)] is None]
    if len(others) > 1:
        raise NotExactError(
            f"projection: the outline of an intersection of {len(others)} solids that are not vertical prisms "
            f"({', '.join(type(k).__name__ for k in others)}) is not computed exactly")
    core = others[0] if others else kids[0]
    cb = facts.box[id(core)]
    lo, hi = float(cb[0, 2]), float(cb[1, 2])
    slack = _slack(lo, hi)
    cuts = []
    for k in kids:
        if k is core:
            continue
        r = facts.range[id(k)]
        if r is None or r[0] > lo + slack or r[1] < hi - slack:
            what = "not a vertical prism" if r is None else f"a vertical prism over z in [{r[0]:g}, {r[1]:g}], not"
            raise NotExactError(
                f"projection: the outline of an intersection whose operand {type(k).__name__} is {what} through the "
                f"operand {type(core).__name__} (z in [{lo:g}, {hi:g}]) is not computed exactly")
        cuts.append(_section_inside(k, 0.5 * (max(lo, r[0]) + min(hi, r[1])), facts))
    return [core], lambda shapes: _combine("intersection", [shapes[0], *cuts])


# --------------------------------------------------------------------------- columns covered


def _overlap_groups(boxes: list[NDArray[np.float64]]) -> list[list[int]]:
    """Indices grouped into the connected sets of boxes that overlap in x and y (touching counts)."""
    n = len(boxes)
    if n == 0:
        return []
    import shapely

    b = np.array(boxes)
    rects = shapely.box(b[:, 0, 0], b[:, 0, 1], b[:, 1, 0], b[:, 1, 1])
    pairs = shapely.STRtree(rects).query(rects, predicate="intersects")
    parent = list(range(n))

    def root(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for i, j in zip(pairs[0].tolist(), pairs[1].tolist()):
        a, c = root(i), root(j)
        if a != c:
            parent[a] = c
    groups: dict[int, list[int]] = defaultdict(list)
    for i in range(n):
        groups[root(i)].append(i)
    return list(groups.values())


def _covered(members: list[Any], lo: float, hi: float, facts: _Facts) -> Shape2D:
    """Where the union of ``members`` holds the whole column ``[lo, hi]``: a convex leaf alone
    where it holds both ends; vertical prisms where each slab between their heights is held."""
    slack = _slack(lo, hi)
    boxes = [facts.box[id(m)] for m in members]
    if min(b[0, 2] for b in boxes) > lo + slack or max(b[1, 2] for b in boxes) < hi - slack:
        return EMPTY
    if len(members) == 1 and not facts.prismatic[id(members[0])]:
        m = members[0]
        if boxes[0][0, 2] > lo + slack or boxes[0][1, 2] < hi - slack:
            return EMPTY
        return _combine("intersection", [leaf_section_at(m, lo), leaf_section_at(m, hi)])
    bad = [m for m in members if not facts.prismatic[id(m)]]
    if bad:
        raise NotExactError(
            f"projection: the outline of a difference whose operand {type(bad[0]).__name__}, not a vertical prism, "
            f"overlaps {len(members) - 1} other operand(s) that do not run through the first one (z in "
            f"[{lo:g}, {hi:g}]) is not computed exactly")
    heights = _heights(members, facts, lo, hi)
    layers = []
    for z0, z1 in zip(heights, heights[1:]):
        mid = 0.5 * (z0 + z1)
        held = [_section_inside(m, mid, facts) for m, b in zip(members, boxes) if b[0, 2] < mid < b[1, 2]]
        layer = _combine("union", held)
        if layer is EMPTY:
            return EMPTY
        layers.append(layer)
    return _combine("intersection", layers)


def _heights(nodes: list[Any], facts: _Facts, lo: float = -math.inf, hi: float = math.inf) -> list[float]:
    """The distinct heights of the nodes' leaves' ends within ``[lo, hi]`` (which are included when
    finite), merged within the slack: the slabs' ends."""
    from .sections import _leaves

    zs = {float(z) for n in nodes for leaf in _leaves(n) for z in facts.box[id(leaf)][:, 2]}
    zs = {min(max(z, lo), hi) for z in zs} | ({lo, hi} if math.isfinite(lo) and math.isfinite(hi) else set())
    out: list[float] = []
    for z in sorted(zs):
        if not out or z - out[-1] > _slack(out[-1], z):
            out.append(z)
    return out


def _slab_outline(s: Any, facts: _Facts) -> Shape2D:
    """The outline of a tree of vertical prisms: the union of its sections, one per slab between
    consecutive heights of its leaves' ends."""
    heights = _heights([s], facts)
    return _combine("union", [section_at(s, 0.5 * (z0 + z1)) for z0, z1 in zip(heights, heights[1:])])


def _manifold_outline(s: Any) -> Shape2D:
    """The outline of a tree of flat-faced solids: manifold3d's Boolean, projected."""
    from ..csg.mesh import to_manifold
    from .region import fill

    rings = to_manifold(s).project().to_polygons()
    if not rings:
        return EMPTY
    return shape_from_region(fill([np.asarray(r, dtype=np.float64) for r in rings], "nonzero"))


# --------------------------------------------------------------------------- leaves


def leaf_outline(leaf: Any) -> Shape2D:
    """The exact outline of one primitive on the xy plane, from its
    :meth:`~isocsg.kinds.base.Primitive.exact_form`.

    Raises
    ------
    NotExactError
        For a kind without an exact form (or a torus whose axis is not vertical).
    """
    form = leaf.exact_form()
    if isinstance(form, PointHull):
        return _convex(form.vertices[:, :2])
    if isinstance(form, AffineBall) and form.radius is not None:
        return Circle((float(form.center[0]), float(form.center[1])), form.radius)
    if isinstance(form, AffineBall):
        P = form.linear[:2]  # the shadow of c + R u is c + P u: the ellipse whose matrix L has L L^T = P P^T
        L = np.asarray(np.linalg.cholesky(P @ P.T), dtype=np.float64)
        return _ellipse(form.center[:2], L)
    if isinstance(form, AffineFrustum):
        return _frustum_outline(form.center, form.matrix, form.r1, form.r2)
    if isinstance(form, RingTorus):
        if abs(abs(form.axis[2]) - 1.0) <= 1e-13:
            xy = (float(form.center[0]), float(form.center[1]))
            return Circle(xy, form.major + form.minor) - Circle(xy, form.major - form.minor)
        raise NotExactError("projection: the outline of a torus whose axis is not vertical is not computed exactly")
    if isinstance(form, TriangleSurface):
        import shapely

        tri = np.asarray(form.vertices, dtype=np.float64)[np.asarray(form.faces)][:, :, :2]
        polys = shapely.polygons(np.concatenate([tri, tri[:, :1]], axis=1))
        polys = polys[shapely.area(polys) > 0]
        return shape_from_region(shapely.union_all(polys)) if len(polys) else EMPTY
    raise NotExactError(f"projection: the outline of a {type(leaf).__name__} is not computed exactly")


def _frustum_outline(c: NDArray[np.float64], M: NDArray[np.float64], r1: float, r2: float) -> Shape2D:
    """The hull of the two end ellipses ``c +- M[:, 2] / 2 + r M[:2, :2] u``: the same map B makes
    both circles, so the hull is B's image of the hull of two discs (exact)."""
    B = M[:2, :2]
    ends = np.array([c[:2] + M[:2, 2] / 2, c[:2] - M[:2, 2] / 2])
    radii = np.array([r1, r2], dtype=np.float64)
    size = float(np.abs(M).max())
    if abs(float(np.linalg.det(B))) <= 1e-12 * size * size:  # the ends seen edge on: segments
        U, S, _ = np.linalg.svd(B)
        reach = U[:, 0] * S[0]
        pts = [e + s * r * reach for e, r in zip(ends, radii) for s in (-1.0, 1.0)]
        return _convex(np.array(pts))
    Binv = np.linalg.inv(B)
    hull = disc_hull(ends @ Binv.T, radii)
    from .transforms import transform2d

    return transform2d(hull, np.hstack([B, np.zeros((2, 1))]))
