"""Solids projected onto the xy plane as exact 2D shapes: OpenSCAD's ``projection``.

- ``cut=True``: the section of the solid by the plane z = 0. Sections commute with the Booleans,
  so the section of a tree is the same 2D tree over its leaves' sections, each exact: a sphere
  or an ellipsoid cuts into a circle or an ellipse, a cylinder into an ellipse clipped by its end
  lines, a cone or frustum into an ellipse (a plane steeper than its sides: a parabola or
  hyperbola, polygonised), a convex polyhedron into a convex polygon, a torus about z into an
  annulus, a mesh into its exact polygons. A face lying in the plane counts, as OpenSCAD's
  closed intersection with the plane keeps it: the section is the union of the limits from just
  above and just below the plane, each evaluated leaf by leaf.
- ``cut=False``: the outline (shadow). The outline of a union is the union of its parts'
  outlines; a convex leaf's outline is exact (a ball's ellipse, a truncus's hull of its two end
  ellipses, a polyhedron's hull). A difference or intersection is not the Boolean of its
  operands' outlines; it is exact when what is subtracted (or intersected) is a vertical prism
  running through the other operand's whole height (a through hole: ``proj(A - P) = proj(A) -
  section(P)``), when a subtracted part misses the first one's box, or when every leaf is flat
  faced (the manifold3d Boolean of the polyhedra, projected). Any other tree raises
  :class:`~isocsg.errors.NotExactError` naming what stops it.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidGeometryError, NotExactError
from ..kinds import Solid
from ..kinds.forms import AffineBall, AffineFrustum, PointHull, RingTorus, TriangleSurface
from .hull2d import disc_hull
from .leaves import Circle, ConvexPolygon
from .region import shape_from_region
from .shape import EMPTY, Shape2D, difference2d, intersection2d, union2d

__all__ = ["projection", "section_at", "outline"]

#: Resolution (segments per turn) of the few curves that are no leaf of a 2D shape (conics of a
#: cone cut steeper than its sides, tori off the z axis): inscribed polygons, chord error
#: ``r (1 - cos(pi / n))`` = 1.2e-6 r.
CURVE_RESOLUTION = 2048

_EPS = 1e-12
_UP = np.array([0.0, 0.0, 1.0])


def projection(solid: Solid, *, cut: bool = False) -> Shape2D:
    """OpenSCAD's ``projection`` of a solid onto the xy plane, as an exact 2D shape.

    Parameters
    ----------
    solid : Solid
        A primitive or a CSG tree.
    cut : bool, default False
        True: the section by the plane z = 0 (faces lying in the plane included). False: the
        outline, the set of points (x, y) above or below which the solid has a point.

    Returns
    -------
    Shape2D
        :data:`~isocsg.shapes2d.EMPTY` when nothing is left.

    Raises
    ------
    NotExactError
        For an outline of a difference or intersection of curved solids that none of the
        exact rules reaches (the message names the operand).

    Examples
    --------
    >>> from isocsg import Sphere, Box
    >>> from isocsg.shapes2d import area
    >>> round(area(projection(Sphere((0, 0, 0.5), 1), cut=True)) / math.pi, 12)
    0.75
    >>> area(projection(Box((0, 0, 0), (2, 3, 4)) - Box((0, 0, 0), (1, 1, 9))))
    5.0
    """
    return section_at(solid, 0.0) if cut else outline(solid)


# --------------------------------------------------------------------------- tree walks


def _children(s: Any) -> tuple[Any, ...] | None:
    from ..csg import CSGNode

    return tuple(s.children) if isinstance(s, CSGNode) else None


def _op(s: Any) -> str:
    from ..csg import Difference, Intersection

    return "difference" if isinstance(s, Difference) else "intersection" if isinstance(s, Intersection) else "union"


def _leaves(solid: Any) -> list[Any]:
    from ..csg.tree import leaves

    return list(leaves(solid))


def _combine(op: str, shapes: list[Shape2D]) -> Shape2D:
    if op == "union":
        kept = [s for s in shapes if s is not EMPTY]
        return union2d(*kept) if kept else EMPTY
    if op == "intersection":
        return EMPTY if any(s is EMPTY for s in shapes) else intersection2d(*shapes)
    if shapes[0] is EMPTY:
        return EMPTY
    rest = [s for s in shapes[1:] if s is not EMPTY]
    return difference2d(shapes[0], *rest) if rest else shapes[0]


def _fold(solid: Any, leaf_value: Any) -> Shape2D:
    """The 2D tree of ``solid`` over ``leaf_value(leaf)`` (explicit stack; shared subtrees once)."""
    done: dict[int, Shape2D] = {}
    stack: list[tuple[Any, bool]] = [(solid, False)]
    while stack:
        s, expanded = stack.pop()
        if id(s) in done:
            continue
        kids = _children(s)
        if kids is None:
            done[id(s)] = leaf_value(s)
        elif expanded:
            done[id(s)] = _combine(_op(s), [done[id(c)] for c in kids])
        else:
            stack.append((s, True))
            stack.extend((c, False) for c in kids)
    return done[id(solid)]


# --------------------------------------------------------------------------- sections


def section_at(solid: Solid, z: float = 0.0) -> Shape2D:
    """The exact section of ``solid`` by the plane at height ``z``, as a 2D shape in x and y.

    A face lying in the plane is part of the section (the closed solid meets the plane there), as
    in OpenSCAD's ``projection(cut = true)``.

    Examples
    --------
    >>> from isocsg import Box
    >>> from isocsg.shapes2d import area
    >>> area(section_at(Box((0, 0, 1), (2, 2, 2)), 0.0))  # the bottom face
    4.0
    """
    z = float(z)
    if not math.isfinite(z):
        raise InvalidGeometryError(f"section_at.z must be finite, got {z}")
    sides: dict[int, int] = {}
    for leaf in _leaves(solid):
        lo, hi = np.asarray(leaf.bounds, dtype=np.float64)[:, 2]
        eps = _EPS * max(hi - lo, abs(lo), abs(hi), abs(z), 1.0)
        sides[id(leaf)] = 1 if lo >= z - eps else -1 if hi <= z + eps else 0
    cache: dict[int, Shape2D] = {}

    def leaf_section(leaf: Any) -> Shape2D:
        if id(leaf) not in cache:
            cache[id(leaf)] = leaf_section_at(leaf, z)
        return cache[id(leaf)]

    touching = [k for k, s in sides.items() if s != 0]
    if not touching:
        return _fold(solid, leaf_section)
    # The limits from just above (+1) and just below (-1): a leaf on the other side is absent.
    parts = [_fold(solid, lambda leaf, s=s: EMPTY if sides[id(leaf)] == -s else leaf_section(leaf)) for s in (1, -1)]
    return _combine("union", parts)


def leaf_section_at(leaf: Any, z: float) -> Shape2D:
    """The exact section of one primitive by the plane at height ``z`` (faces in the plane count),
    from its :meth:`~isocsg.kinds.base.Primitive.exact_form`; a kind without one is polygonised
    from its own ``section``."""
    form = leaf.exact_form()
    if isinstance(form, PointHull):
        return _polytope_section(form.vertices, form.edges, z)
    if isinstance(form, AffineBall):
        return _ball_section(form.center, form.linear, z)
    if isinstance(form, AffineFrustum):
        return _frustum_section(leaf, form.center, form.matrix, form.r1, form.r2, z)
    if isinstance(form, RingTorus):
        return _torus_section(leaf, form, z)
    if isinstance(form, TriangleSurface):
        from ..kinds.mesh_section import mesh_section

        return shape_from_region(mesh_section(form.vertices, form.faces, _frame(z)))
    return _polygonised_section(leaf, z)


def _frame(z: float) -> NDArray[np.float64]:
    F = np.eye(4)
    F[2, 3] = z
    return F


def _polygonised_section(leaf: Any, z: float) -> Shape2D:
    return shape_from_region(leaf.section(_frame(z), CURVE_RESOLUTION, False))


def _convex(points: NDArray[np.float64]) -> Shape2D:
    """The convex polygon of points (EMPTY when flat)."""
    import shapely

    if len(points) < 3:
        return EMPTY
    hull = shapely.convex_hull(shapely.multipoints(points))
    if hull.geom_type != "Polygon":
        return EMPTY
    ring = np.asarray(shapely.orient_polygons(hull).exterior.coords)[:-1]
    try:
        return ConvexPolygon(tuple(map(tuple, ring.tolist())))
    except InvalidGeometryError:
        return EMPTY  # no area (an edge or a point of the solid in the plane)


def _polytope_section(V: NDArray[np.float64], E: NDArray[np.int64], z: float) -> Shape2D:
    """A convex polytope's section: the hull of its vertices in the plane and its edges' crossings."""
    h = V[:, 2] - z
    eps = _EPS * max(float(np.ptp(V, axis=0).max()), float(np.abs(V).max()), 1.0)
    on = np.abs(h) <= eps
    a, b = h[E[:, 0]], h[E[:, 1]]
    cross = ((a > eps) & (b < -eps)) | ((a < -eps) & (b > eps))
    e = E[cross]
    t = (h[e[:, 0]] / (h[e[:, 0]] - h[e[:, 1]]))[:, None]
    pts = np.vstack([V[on, :2], V[e[:, 0], :2] + t * (V[e[:, 1], :2] - V[e[:, 0], :2])])
    return _convex(pts)


def _ellipse(center: NDArray[np.float64], L: NDArray[np.float64]) -> Shape2D:
    """The exact ellipse ``center + L u`` (|u| <= 1): a :class:`Circle` when L is a similarity."""
    try:
        return Circle((0.0, 0.0), 1.0)._affine(L, center)
    except InvalidGeometryError:
        return EMPTY  # flat (a point or a segment)


def _ball_section(c: NDArray[np.float64], M: NDArray[np.float64], z: float) -> Shape2D:
    """The section of the ellipsoid ``c + M u`` (|u| <= 1): the disc of the unit ball's plane
    ``m . u = z - c_z`` (m = M's last row), mapped by M."""
    m = M[2]
    norm = float(np.linalg.norm(m))
    d = (z - c[2]) / norm
    if abs(d) >= 1.0:
        return EMPTY
    n = m / norm
    e1 = np.cross(n, [1.0, 0.0, 0.0] if abs(n[0]) < 0.9 else [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    rho = math.sqrt(1.0 - d * d)
    center = c[:2] + M[:2] @ (d * n)
    return _ellipse(center, rho * (M[:2] @ np.column_stack([e1, e2])))


def _half_planes(shape: Shape2D, lines: list[tuple[NDArray[np.float64], float]]) -> Shape2D:
    """``shape`` cut by the half-planes ``g . p <= h`` (each an exact convex polygon around its box)."""
    if shape is EMPTY or not lines:
        return shape
    from .measure import bounds

    x0, y0, x1, y1 = bounds(shape)
    pad = max(x1 - x0, y1 - y0)
    box = np.array([[x0 - pad, y0 - pad], [x1 + pad, y0 - pad], [x1 + pad, y1 + pad], [x0 - pad, y1 + pad]])
    import shapely

    region = shapely.Polygon(box)
    cut = False
    for g, h in lines:
        vals = box @ g - h
        if np.all(vals <= 0):
            continue
        cut = True
        big = 4 * pad * (1 + float(np.abs(box).max()))
        d = g / np.linalg.norm(g)
        p0 = d * (h / np.linalg.norm(g))
        w = np.array([-d[1], d[0]])
        half = shapely.Polygon([p0 + big * w, p0 - big * w, p0 - big * w - big * d, p0 + big * w - big * d])
        region = region.intersection(half)
    if not cut:
        return shape
    if region.is_empty or region.area <= 0:
        return EMPTY
    return _combine("intersection", [shape, _convex(np.asarray(region.exterior.coords)[:-1])])


def _frustum_section(leaf: Any, c: NDArray[np.float64], M: NDArray[np.float64], r1: float, r2: float,
                     z: float) -> Shape2D:
    """The section of the frustum ``c + M (x, y, t)`` (:class:`~isocsg.kinds.forms.AffineFrustum`)."""
    m = M[2]  # z = c_z + m . (x, y, t)
    size = float(np.abs(M).max())
    tol = 1e-13 * size
    w = z - c[2]
    if abs(m[0]) <= tol and abs(m[1]) <= tol:  # ends parallel to the plane: one ellipse
        t = w / m[2]
        if abs(t) > 0.5 * (1 + 1e-12):
            return EMPTY
        r = r2 + (r1 - r2) * (min(max(t, -0.5), 0.5) + 0.5)
        if r <= 0:
            return EMPTY
        return _ellipse(c[:2] + M[:2, 2] * t, r * M[:2, :2])
    if abs(m[2]) <= tol:  # the axis parallel to the plane
        if r1 != r2:
            return _polygonised_section(leaf, z)
        k = m[:2]
        dist = w / float(np.linalg.norm(k))  # the chord x . k/|k| = dist of the disc of radius r1
        if abs(dist) >= r1:
            return EMPTY
        u = k / np.linalg.norm(k)
        half = math.sqrt(r1 * r1 - dist * dist) * np.array([-u[1], u[0]])
        ends = [dist * u + half, dist * u - half]
        pts = [c[:2] + M[:2, :2] @ e + M[:2, 2] * t for e in ends for t in (-0.5, 0.5)]
        return _convex(np.array(pts))
    # t = tau0 + tau . (x, y) on the plane; the point is c' + A (x, y)
    tau0, tau = w / m[2], -m[:2] / m[2]
    A = M[:2, :2] + np.outer(M[:2, 2], tau)
    c0 = c[:2] + M[:2, 2] * tau0
    b = r1 - r2
    k0, k = r2 + b * (tau0 + 0.5), b * tau
    if float(k @ k) >= 1.0 - 1e-12:  # a parabola or hyperbola: no 2D leaf for it
        return _polygonised_section(leaf, z)
    # |x|^2 <= (k0 + k . x)^2: the ellipse (x - x0)^T Q (x - x0) <= rho, Q = I - k k^T
    Q = np.eye(2) - np.outer(k, k)
    x0 = np.linalg.solve(Q, k * k0)
    rho = k0 * k0 + float(x0 @ Q @ x0)
    if rho <= 0:
        return EMPTY
    L = np.linalg.cholesky(np.linalg.inv(Q)) * math.sqrt(rho)
    ellipse = _ellipse(c0 + A @ x0, A @ L)
    # the ends: -1/2 <= tau0 + tau . x <= 1/2 with x = A^-1 (p - c0)
    Ainv = np.linalg.inv(A)
    g = Ainv.T @ tau
    s0 = tau0 - float(g @ c0)
    return _half_planes(ellipse, [(g, 0.5 - s0), (-g, 0.5 + s0)])


def _torus_section(leaf: Any, form: RingTorus, z: float) -> Shape2D:
    c, a = form.center, form.axis
    R, r = form.major, form.minor
    if abs(abs(a[2]) - 1.0) <= 1e-13:  # about z: an annulus
        d = z - c[2]
        if abs(d) >= r:
            return EMPTY
        s = math.sqrt(r * r - d * d)
        return Circle((c[0], c[1]), R + s) - Circle((c[0], c[1]), R - s)
    if abs(a[2]) <= 1e-13 and abs(z - c[2]) <= 1e-13 * R:  # the plane holds the axis: two discs
        u = np.array([-a[1], a[0]]) / math.hypot(a[0], a[1])
        return union2d(Circle(tuple(c[:2] + R * u), r), Circle(tuple(c[:2] - R * u), r))
    return _polygonised_section(leaf, z)


# --------------------------------------------------------------------------- outlines


def outline(solid: Solid) -> Shape2D:
    """The outline (shadow on the xy plane along z) of ``solid``, exactly (see the module docs).

    Raises
    ------
    NotExactError
        For a difference or intersection that no exact rule reaches, naming the operand.

    Examples
    --------
    >>> from isocsg import Cylinder
    >>> from isocsg.shapes2d import area
    >>> round(area(outline(Cylinder((0, 0, 0), (0, 0, 2), 1))) / math.pi, 12)
    1.0
    """
    flat = _flat_faced(solid)
    done: dict[int, Shape2D] = {}
    stack: list[tuple[Any, bool]] = [(solid, False)]
    while stack:
        s, expanded = stack.pop()
        if id(s) in done:
            continue
        kids = _children(s)
        if kids is None:
            done[id(s)] = leaf_outline(s)
            continue
        op = _op(s)
        if op != "union" and flat[id(s)]:
            done[id(s)] = _manifold_outline(s)
            continue
        need = list(kids) if op == "union" else [_core(s, op, kids)]
        if expanded:
            shapes = [done[id(c)] for c in need]
            done[id(s)] = _combine("union", shapes) if op == "union" else _cut_by_prisms(s, op, kids, shapes[0])
        else:
            stack.append((s, True))
            stack.extend((c, False) for c in need)
    return done[id(solid)]


def _flat_faced(solid: Any) -> dict[int, bool]:
    """Whether each node's leaves are all flat-faced, by node id: one post-order pass, so that a
    chain of 100 000 differences is not walked once per level."""
    flat: dict[int, bool] = {}
    stack: list[tuple[Any, bool]] = [(solid, False)]
    while stack:
        s, expanded = stack.pop()
        if id(s) in flat:
            continue
        kids = _children(s)
        if kids is None:
            flat[id(s)] = bool(type(s).polyhedral)
        elif expanded:
            flat[id(s)] = all(flat[id(c)] for c in kids)
        else:
            stack.append((s, True))
            stack.extend((c, False) for c in kids)
    return flat


def _manifold_outline(s: Any) -> Shape2D:
    """The outline of a tree of flat-faced solids: manifold3d's Boolean, projected."""
    from ..csg.mesh import to_manifold
    from .region import fill

    rings = to_manifold(s).project().to_polygons()
    if not rings:
        return EMPTY
    return shape_from_region(fill([np.asarray(r, dtype=np.float64) for r in rings], "nonzero"))


def _zrange(s: Any) -> tuple[float, float]:
    b = np.asarray(s.bounds, dtype=np.float64)
    return float(b[0, 2]), float(b[1, 2])


def _overlap(a: Any, b: Any) -> bool:
    p, q = np.asarray(a.bounds, dtype=np.float64), np.asarray(b.bounds, dtype=np.float64)
    return bool(np.all(p[0] < q[1]) and np.all(q[0] < p[1]))


def _prism_range(s: Any) -> tuple[float, float] | None:
    """The heights over which ``s`` is a vertical prism (every leaf one), or None."""
    lo, hi = -math.inf, math.inf
    for leaf in _leaves(s):
        r = _leaf_prism(leaf)
        if r is None:
            return None
        lo, hi = max(lo, r[0]), min(hi, r[1])
    return (lo, hi) if lo < hi else None


def _leaf_prism(leaf: Any) -> tuple[float, float] | None:
    return _zrange(leaf) if leaf.is_prism_along(_UP, 1e-12) else None


def _core(s: Any, op: str, kids: tuple[Any, ...]) -> Any:
    """The operand whose outline a difference or intersection is cut from: the first one of a
    difference; the one operand of an intersection that is not a vertical prism through it."""
    if op == "difference":
        return kids[0]
    others = [k for k in kids if _prism_range(k) is None]
    if len(others) > 1:
        raise NotExactError(
            f"projection: the outline of an intersection of {len(others)} solids that are not vertical prisms "
            f"({', '.join(type(k).__name__ for k in others)}) is not computed exactly")
    return others[0] if others else kids[0]


def _cut_by_prisms(s: Any, op: str, kids: tuple[Any, ...], core_outline: Shape2D) -> Shape2D:
    """A difference's (intersection's) outline: the core's outline minus (cut to) the sections of
    vertical prisms that run through the core's whole height."""
    core = _core(s, op, kids)
    lo, hi = _zrange(core)
    slack = 1e-9 * max(hi - lo, abs(lo), abs(hi), 1.0)
    cuts = []
    for k in kids:
        if k is core:
            continue
        if op == "difference" and not _overlap(core, k):
            continue  # misses the first operand: subtracts nothing
        r = _prism_range(k)
        if r is None or r[0] > lo + slack or r[1] < hi - slack:
            what = "not a vertical prism" if r is None else (
                f"a vertical prism over z in [{r[0]:g}, {r[1]:g}], not through")
            raise NotExactError(
                f"projection: the outline of a {op} whose operand {type(k).__name__} is {what} the first operand "
                f"(z in [{lo:g}, {hi:g}]) is not computed exactly; a projection of a {op} is not the {op} of "
                "projections")
        cuts.append(section_at(k, 0.5 * (max(lo, r[0]) + min(hi, r[1]))))
    if not cuts:
        return core_outline
    if op == "difference":
        return _combine("difference", [core_outline, *cuts])
    return _combine("intersection", [core_outline, *cuts])


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
