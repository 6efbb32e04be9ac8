"""Exact convex hulls and Minkowski sums of solids, as unions of isocsg kinds.

Every convex operand is read as a *point set plus at most one round generator*:

- a polytope (:class:`~isocsg.Box`, :class:`~isocsg.ConvexPolyhedron`): its corners;
- a ball (:class:`~isocsg.Sphere`, :class:`~isocsg.Ellipsoid`): its centre plus ``L B``, the
  image of the unit ball under a linear map ``L``;
- a cylinder (:class:`~isocsg.Cylinder`, an :class:`~isocsg.EllipticTruncus` with equal end
  radii): the segment between its end centres plus ``L D``, the image of the unit disc.

**hull**: the hull of ``c_i + K`` for one body ``K`` is ``hull(c_i) + K``. So a hull of balls of
one shape (spheres of one radius, or ellipsoids of one shape and orientation), or of cylinders
whose discs are one ellipse (parallel cylinders of one radius), is the hull of the centres or
segments grown by that ball or disc (:mod:`isocsg.csg.hull_grow`, mapped by ``L`` when it is not
a similarity). A hull of polytopes is the :class:`~isocsg.ConvexPolyhedron` of their corners;
a difference whose cuts keep every corner of its polytopal first operand's hull is that operand.
Balls of any radii (spheres, or ellipsoids of one shape and any size) with any polytopes'
corners (balls of radius 0) are exact through :mod:`isocsg.csg.hull_balls`: a polyhedron, the
frusta of the tangent cones between balls and the spheres. Cylinders, cones and frusta on one
axis, with spheres centred on it or not, are the frusta under the straight edges of their
meridian's hull and the spheres under its arcs. Parallel cylinders of any radii between the
same two planes are the prism over the 2D hull of their discs and the cylinders; cylinders,
cones and frusta on parallel axes in general, with polytopes' corners, are the hull of their
end discs (:mod:`isocsg.csg.hull_discs`: a polyhedron and oblique frusta).

**minkowski**: sums of corners add (the sum of two polytopes is the hull of the pairwise sums
of their corners), centres add, balls of one shape add (``L1 B + k L1 B = (1 + k) L1 B``) and so
do discs in one plane; the sum is then a polytope grown by at most one ball or one disc, as for
the hull. A sphere plus a cylinder (a rounded cylinder) is exact too: two cylinders and two
tori (:class:`~isocsg.Torus`, which needs the cylinder's radius above the sphere's). A union
operand distributes, ``(A u B) + K = (A + K) u (B + K)``; a difference or an intersection does
not and is refused.

Anything else (a hull of a sphere and a cylinder off its axis, of cylinders or cones on axes
that are not parallel; a sum of a sphere and an ellipsoid;
non-parallel cylinders; a torus) raises
:class:`~isocsg.errors.NotExactError` naming what stops it. Radii and shapes count as equal to
1e-9, relatively.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidGeometryError, NotExactError, ResourceLimitError
from ..kinds import ConvexPolyhedron, Cylinder, Primitive, Solid, Sphere, Torus, Truncus
from ..kinds.affine import similarity_factor
from ..kinds.forms import AffineBall, AffineFrustum
from .flat_pieces import flat_convex_pieces
from .hull_balls import ball_hull, disc_hull_prism, upper_disc_hull
from .hull_discs import parallel_disc_hull
from .hull_grow import grow_ball, grow_disc, polytope
from .tree import CSGNode, Difference, Union

__all__ = ["hull", "minkowski", "hull_pieces", "minkowski_pieces", "MAX_MINKOWSKI_TERMS"]

#: The most pairs of convex pieces a Minkowski sum of unions may expand into.
MAX_MINKOWSKI_TERMS = 4096
#: Relative tolerance for equal radii, shapes and parallel directions.
SHAPE_TOLERANCE = 1e-9


@dataclass(frozen=True)
class _Convex:
    """A convex operand: ``hull(points) + L K`` (K the unit ball or disc, or nothing)."""

    points: NDArray[np.float64]
    round: Literal["ball", "disc"] | None = None
    linear: NDArray[np.float64] | None = None  # L; for a disc, its third column is the unit normal


def _name(solid: Solid) -> str:
    return type(solid).__name__


def _article(word: str) -> str:
    return f"{'an' if word[0].lower() in 'aeiou' else 'a'} {word}"


def _union_leaves(solid: Solid, operation: str) -> list[Primitive]:
    """The primitives whose union ``solid`` is; another CSG node is refused, naming it."""
    out: list[Primitive] = []
    todo = [solid]
    while todo:
        s = todo.pop()
        if isinstance(s, Union):
            todo.extend(reversed(s.children))
        elif operation == "minkowski" and isinstance(s, Primitive) and s.polyhedral and not s.convex:
            out.extend(s.convex_pieces())  # a non-convex flat-faced kind sums through its exact convex pieces
        elif operation == "hull" and isinstance(s, Difference) and _cuts_no_corner(s):
            todo.append(s.children[0])
        elif isinstance(s, Primitive):
            out.append(s)
        elif isinstance(s, CSGNode):
            pieces = flat_convex_pieces(s) if operation == "minkowski" else None
            if pieces is None:
                flat = " and flat-faced solids" if operation == "minkowski" else ""
                raise NotExactError(
                    f"{operation}: a {operation} of {_article(_name(s).lower())} is not supported (only unions"
                    f"{flat} split into convex pieces exactly: a {operation} does not distribute over it)"
                )
            out.extend(pieces)
        else:
            raise InvalidGeometryError(f"{operation}: operands must be isocsg solids, got {_name(s)}")
    return out


def _cuts_no_corner(d: Difference) -> bool:
    """Whether ``hull(d) == hull(d.children[0])``: the first operand is a union of polytopes and
    no other operand comes within rounding of a corner of its hull. The hull of a set is the hull
    of its extreme points; these are corners of the first operand's hull, and each one kept (and
    a neighbourhood of it within the first operand) stays in the difference."""
    corners: list[NDArray[np.float64]] = []
    todo: list[Solid] = [d.children[0]]
    while todo:
        s = todo.pop()
        if isinstance(s, Union):
            todo.extend(s.children)
            continue
        pts = s.hull_points() if isinstance(s, Primitive) else None
        if pts is None:
            return False  # a round or non-convex piece: its extreme points are not a finite set here
        corners.append(np.asarray(pts, dtype=np.float64))
    q = polytope(np.vstack(corners))
    if q.solid is None:
        return False
    v = np.asarray(q.vertices, dtype=np.float64)
    margin = 1e-9 * max(float(np.max(np.ptp(v, axis=0))), float(np.max(np.abs(v))))
    for cut in d.children[1:]:
        if not isinstance(cut, (Primitive, CSGNode)) or np.any(cut.contains(v, tol=margin)):
            return False
    return True


def _convex(p: Primitive, operation: str) -> _Convex:
    """A convex primitive as points plus a round generator (its corners, or its
    :meth:`~isocsg.kinds.base.Primitive.exact_form`: a ball, or a frustum of equal end radii);
    refuses the kinds that are not."""
    corners = p.hull_points()
    if corners is not None:
        return _Convex(np.asarray(corners, dtype=np.float64))
    form = p.exact_form()
    if isinstance(form, AffineBall):
        return _Convex(form.center[None], "ball", form.linear)
    if isinstance(form, AffineFrustum) and form.r1 == form.r2:
        m = form.matrix
        ends = np.stack([form.center + m[:, 2] / 2, form.center - m[:, 2] / 2])
        return _Convex(ends, "disc", np.column_stack([form.r1 * m[:, :2], form.normal]))
    why = "a cone or frustum" if isinstance(form, AffineFrustum) else _article(_name(p))
    raise NotExactError(f"{operation}: a {operation} of {why} is not an exact union of isocsg kinds "
                        "(only polytopes, balls and cylinders are)")


def _gram(c: _Convex) -> NDArray[np.float64]:
    """The shape of the round generator as a set: ``L L^T`` (ball) or ``L2 L2^T`` (disc)."""
    lin = c.linear
    assert lin is not None
    part = lin if c.round == "ball" else lin[:, :2]
    return part @ part.T  # type: ignore[no-any-return]


def _same(g1: NDArray[np.float64], g2: NDArray[np.float64]) -> bool:
    scale = max(float(np.abs(g1).max()), float(np.abs(g2).max()))
    return bool(np.abs(g1 - g2).max() <= SHAPE_TOLERANCE * scale)


def _grown(points: NDArray[np.float64], c: _Convex) -> list[Primitive]:
    """``hull(points) + L K`` as pieces: in the world when ``K``'s image is a round ball or
    disc, else in ``L``'s frame, mapped back by ``L``."""
    lin = c.linear
    assert lin is not None
    if c.round == "ball":
        r = similarity_factor(lin)
        if r is not None:
            return grow_ball(points, r)
    else:
        g = lin[:, :2].T @ lin[:, :2]
        r = math.sqrt(g[0, 0])
        if abs(g[0, 1]) <= SHAPE_TOLERANCE * g[0, 0] and abs(g[1, 1] - g[0, 0]) <= SHAPE_TOLERANCE * g[0, 0]:
            return grow_disc(points, lin[:, 2], r)
    origin = points[0]
    local = np.linalg.solve(lin, (points - origin).T).T
    unit = grow_ball(local, 1.0) if c.round == "ball" else grow_disc(local, np.array([0.0, 0.0, 1.0]), 1.0)
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = lin, origin
    return [p.transform(m) for p in unit]  # type: ignore[misc]


def _polyhedron(points: NDArray[np.float64]) -> list[Primitive]:
    """The hull of points as one polyhedron; empty when flat."""
    q = polytope(points)
    return [ConvexPolyhedron(q.vertices)] if q.solid is not None else []


def hull_pieces(*solids: Solid) -> list[Primitive]:
    """The convex hull of ``solids`` as a list of primitives whose union it is (empty: no volume).

    See :func:`hull`, which returns them as one solid.
    """
    leaves = [leaf for s in solids for leaf in _union_leaves(s, "hull")]
    if not leaves:
        raise InvalidGeometryError("hull: needs at least one solid")
    forms = [p.exact_form() for p in leaves]
    right = [f for f in forms if isinstance(f, AffineFrustum) and f.right]
    spheres = [f for f in forms if isinstance(f, AffineBall) and f.radius is not None]
    if len(right) == len(forms):
        coaxial = _coaxial_hull(right)
        if coaxial is not None:
            return coaxial
    elif right and len(right) + len(spheres) == len(forms):
        coaxial = _coaxial_with_spheres(right, spheres)
        if coaxial is not None:
            return coaxial
    try:
        parts = [_convex(p, "hull") for p in leaves]
    except NotExactError:
        parallel = _parallel_hull(leaves)  # cones and frusta on parallel axes
        if parallel is None:
            raise
        return parallel
    rounds = [c for c in parts if c.round is not None]
    if not rounds:
        return _polyhedron(np.vstack([c.points for c in parts]))
    first = rounds[0]
    if len(rounds) == len(parts) and all(c.round == first.round and _same(_gram(c), _gram(first)) for c in rounds):
        return _grown(np.vstack([c.points for c in rounds]), first)
    pieces = _balls_hull(parts)
    if pieces is None:
        pieces = _cylinders_hull(parts)
    if pieces is None:
        pieces = _parallel_hull(leaves)
    if pieces is not None:
        return pieces
    shown = ", ".join(sorted({_name(p) for p in leaves}))
    raise NotExactError(
        f"hull: a hull of {shown} of different shapes or directions is not an exact union of isocsg kinds (only "
        "polytopes with spheres of any radii or ellipsoids of one shape, polytopes with cylinders and cones on "
        "parallel axes, and trunci with spheres on one axis are)"
    )


def _balls_hull(parts: list[_Convex]) -> list[Primitive] | None:
    """The hull of balls of one shape up to size (spheres of any radii, or ellipsoids ``s_k L B``)
    and polytopes' corners (balls of radius 0), through :func:`ball_hull` in ``L``'s frame; None
    when an operand is a disc or the balls' shapes differ."""
    if any(c.round == "disc" for c in parts):
        return None
    balls = [c for c in parts if c.round == "ball"]
    g1 = _gram(balls[0])
    scales = [float(np.trace(_gram(c)) / np.trace(g1)) for c in balls]
    if not all(_same(_gram(c), k * g1) for c, k in zip(balls, scales)):
        return None
    lin = balls[0].linear
    assert lin is not None
    corners = [c.points for c in parts if c.round is None]
    if corners:  # only the corners of the polytopes' hull matter
        corners = [polytope(np.vstack(corners)).vertices]
    centres = np.vstack([c.points for c in balls] + corners)
    radii = np.concatenate([np.sqrt(scales), np.zeros(len(centres) - len(balls))])
    r1 = similarity_factor(lin)
    if r1 is not None:
        return ball_hull(centres, radii * r1)
    origin = centres[0]
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = lin, origin
    local = np.linalg.solve(lin, (centres - origin).T).T
    return [p.transform(m) for p in ball_hull(local, radii)]  # type: ignore[misc]


def _cylinders_hull(parts: list[_Convex]) -> list[Primitive] | None:
    """The hull of right circular cylinders on one axis direction whose ends lie on the same two
    planes (any radii): the prism over the 2D hull of their discs; None otherwise."""
    if any(c.round != "disc" for c in parts):
        return None
    axis = parts[0].linear[:, 2]  # type: ignore[index]
    frame = np.column_stack([*_plane_frame(axis), axis])
    radii, feet, heights = [], [], []
    for c in parts:
        lin = c.linear
        assert lin is not None
        g = lin[:, :2].T @ lin[:, :2]
        if abs(abs(float(lin[:, 2] @ axis)) - 1) > SHAPE_TOLERANCE or not _same(g, g[0, 0] * np.eye(2)):
            return None
        local = c.points @ frame
        if np.abs(local[0, :2] - local[1, :2]).max() > SHAPE_TOLERANCE * abs(local[0, 2] - local[1, 2]):
            return None  # an oblique cylinder
        radii.append(math.sqrt(g[0, 0]))
        feet.append(local[0, :2])
        heights.append(sorted(local[:, 2]))
    span = np.array(heights)
    if np.ptp(span, axis=0).max() > SHAPE_TOLERANCE * float(np.ptp(span) + max(radii)):
        return None
    return disc_hull_prism(np.array(feet), np.array(radii), frame, float(span[:, 0].min()), float(span[:, 1].max()))


def _parallel_hull(leaves: list[Primitive]) -> list[Primitive] | None:
    """The hull of cylinders, cones and frusta whose end discs lie in parallel planes (any radii,
    any heights; right ones, or elliptic ones under one map) and polytopes' corners, as the hull
    of their end discs (:mod:`isocsg.csg.hull_discs`); None when another kind is there or the
    discs are not parallel circles (in the frame of the first elliptic one's map)."""
    forms = [p.exact_form() for p in leaves]
    rounds = [f for f in forms if isinstance(f, AffineFrustum)]
    if not rounds:
        return None
    first = next((f for f in rounds if not f.right), None)
    m = np.eye(3) if first is None else np.asarray(first.matrix, dtype=np.float64).copy()
    m[:, 2] = np.cross(m[:, 0], m[:, 1])  # the discs' frame; their normal in the world when a similarity
    origin = np.zeros(3) if first is None else first.center
    inverse = np.linalg.inv(m)
    axis = inverse @ (rounds[0].normal if first is None else m[:, 2])
    axis /= np.linalg.norm(axis)
    centres: list[NDArray[np.float64]] = []
    radii: list[float] = []
    for p, f in zip(leaves, forms):
        if isinstance(f, AffineFrustum):
            lin = _right_matrix(f) if f.right else f.matrix
            local = inverse @ lin
            disc = local[:, :2] - np.outer(axis, axis @ local[:, :2])
            g = disc.T @ disc
            tilted = np.abs(axis @ local[:, :2]).max() > SHAPE_TOLERANCE * math.sqrt(g[0, 0])
            if tilted or not _same(g, g[0, 0] * np.eye(2)):
                return None
            c = inverse @ (f.center - origin)
            centres.extend((c + local[:, 2] / 2, c - local[:, 2] / 2))
            radii.extend((f.r1 * math.sqrt(g[0, 0]), f.r2 * math.sqrt(g[0, 0])))
        elif (corners := p.hull_points()) is not None:
            centres.extend((np.asarray(corners, dtype=np.float64) - origin) @ inverse.T)
            radii.extend([0.0] * len(corners))
        else:
            return None
    pieces = parallel_disc_hull(np.array(centres), np.array(radii), axis)
    if first is None:
        return pieces
    back = np.eye(4)
    back[:3, :3], back[:3, 3] = m, origin
    return [p.transform(back) for p in pieces]  # type: ignore[misc]


def _right_matrix(f: AffineFrustum) -> NDArray[np.float64]:
    """A right frustum's frame in this module's convention: two unit vectors across its axis and
    the axis (the ``r2`` end's centre to the ``r1`` end's)."""
    u, v = _plane_frame(f.normal)
    e1, e2 = _ends(f)
    return np.column_stack([u, v, e1 - e2])


def _ends(f: AffineFrustum) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The centres of the ``r1`` end and the ``r2`` end."""
    return f.center + f.matrix[:, 2] / 2, f.center - f.matrix[:, 2] / 2


def _plane_frame(axis: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    helper = np.eye(3)[int(np.argmin(np.abs(axis)))]
    u = np.cross(axis, helper)
    u /= np.linalg.norm(u)
    return u, np.cross(axis, u)


def _coaxial_hull(trunci: list[AffineFrustum]) -> list[Primitive] | None:
    """The hull of trunci on one axis (cylinders, cones, frusta), or None when they are not: a
    solid of revolution whose meridian is the upper hull of the ends' (position, radius) points,
    so frusta between consecutive vertices of that hull."""
    axis = trunci[0].normal
    origin = trunci[0].center
    ends = np.array([e for t in trunci for e in _ends(t)])
    radii = np.array([r for t in trunci for r in (t.r1, t.r2)])
    s = (ends - origin) @ axis
    reach = float(np.ptp(s) + radii.max())
    off_line = np.linalg.norm(ends - origin - s[:, None] * axis, axis=1)
    if off_line.max() > SHAPE_TOLERANCE * reach:
        return None
    points: list[tuple[float, float]] = []
    for k in np.argsort(s, kind="stable"):  # one point per position (to rounding): the widest
        if points and s[k] - points[-1][0] <= SHAPE_TOLERANCE * reach:
            points[-1] = (points[-1][0], max(points[-1][1], float(radii[k])))
        else:
            points.append((float(s[k]), float(radii[k])))
    hull: list[tuple[float, float]] = []
    for point in points:  # Andrew's monotone chain, upper half
        while len(hull) >= 2 and _turn(hull[-2], hull[-1], point) >= 0:
            hull.pop()
        hull.append(point)
    if len(hull) == 1:
        return None  # every end at one position: no length (not reached for valid trunci)
    pieces: list[Primitive] = []
    for (s0, r0), (s1, r1) in itertools.pairwise(hull):
        if max(r0, r1) > 0:
            a, b = origin + s0 * axis, origin + s1 * axis
            pieces.append(Cylinder((a + b) / 2, b - a, r1) if r0 == r1 else Truncus((a + b) / 2, b - a, r1, r0))
    return pieces


def _coaxial_with_spheres(trunci: list[AffineFrustum], balls: list[AffineBall]) -> list[Primitive] | None:
    """The hull of trunci on one axis and spheres centred on it (a dome on a cylinder, a cone
    with a ball): a solid of revolution whose meridian is the upper hull of the ends' rims
    (points) and the spheres' discs; frusta under its straight edges, spheres under its arcs.
    None when they are not on one axis."""
    axis, origin = trunci[0].normal, trunci[0].center
    centres = np.array([e for t in trunci for e in _ends(t)] + [b.center for b in balls])
    radii = np.array([r for t in trunci for r in (t.r1, t.r2)] + [b.radius for b in balls])
    s = (centres - origin) @ axis
    off_line = np.linalg.norm(centres - origin - s[:, None] * axis, axis=1)
    if off_line.max() > SHAPE_TOLERANCE * float(np.ptp(s) + radii.max()):
        return None
    rims = 2 * len(trunci)
    points = np.column_stack([s, np.where(np.arange(len(s)) < rims, radii, 0.0)])
    edges, discs = upper_disc_hull(points, np.where(np.arange(len(s)) < rims, 0.0, radii))
    pieces: list[Primitive] = []
    for (s0, r0), (s1, r1) in edges:
        a, b = origin + s0 * axis, origin + s1 * axis
        try:
            pieces.append(Cylinder((a + b) / 2, b - a, r1) if r0 == r1 else Truncus((a + b) / 2, b - a, r1, r0))
        except InvalidGeometryError:
            pass  # no length (a flat end) or too thin a sliver to be a kind
    pieces.extend(Sphere(centres[k], radii[k]) for k in discs if k >= rims)
    return pieces


def _turn(o: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
    """The cross product of ``a - o`` and ``b - o``: > 0 for a left (counter-clockwise) turn."""
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def hull(*solids: Solid) -> Solid:
    """The convex hull of solids, exactly, as a union of isocsg kinds.

    Parameters
    ----------
    *solids : Solid
        Primitives or unions of them: polytopes (boxes, convex polyhedra) with spheres of any
        radii (or ellipsoids of one shape), parallel cylinders of one radius or of any radii
        between two planes, cylinders and cones on one axis with spheres centred on it (see
        :mod:`isocsg.csg.hull`).

    Returns
    -------
    Solid
        One primitive, or the :class:`~isocsg.Union` of the pieces (e.g. a convex polyhedron,
        prisms on its faces, cylinders on its edges and spheres at its corners).

    Raises
    ------
    NotExactError
        When the hull is no exact union of isocsg kinds (a sphere with a cylinder off its axis,
        cones off one axis, a difference); the message names what stops it.
    ResourceLimitError
        When the balls and corners make too many planes to test
        (:data:`~isocsg.csg.hull_balls.MAX_HULL_WORK`).
    InvalidGeometryError
        When the hull has no volume (flat polytopes), or on no operand.

    Examples
    --------
    >>> from isocsg import Sphere, hull, volume
    >>> capsule = hull(Sphere((0, 0, 0), 1), Sphere((2, 0, 0), 1))
    >>> sorted(type(p).__name__ for p in capsule.children)
    ['Cylinder', 'Sphere', 'Sphere']
    >>> round(volume(capsule) / math.pi, 3)  # 2 pi r^2 + 4/3 pi r^3
    3.333
    """
    return _one(hull_pieces(*solids), "hull")


def _one(pieces: list[Primitive], operation: str) -> Solid:
    if not pieces:
        raise InvalidGeometryError(f"{operation}: the result has no volume (flat)")
    return pieces[0] if len(pieces) == 1 else Union(*pieces)


def minkowski_pieces(*solids: Solid) -> list[Primitive]:
    """The Minkowski sum of ``solids`` as primitives whose union it is (empty: no volume).

    See :func:`minkowski`, which returns them as one solid.
    """
    if not solids:
        raise InvalidGeometryError("minkowski: needs at least one solid")
    operands = [[_convex(p, "minkowski") for p in _union_leaves(s, "minkowski")] for s in solids]
    count = math.prod(len(o) for o in operands)
    if count > MAX_MINKOWSKI_TERMS:
        raise ResourceLimitError(
            f"minkowski: the operands' convex pieces make {count} sums, "
            f"over MAX_MINKOWSKI_TERMS = {MAX_MINKOWSKI_TERMS}"
        )
    pieces: list[Primitive] = []
    for terms in itertools.product(*operands):
        pieces.extend(_sum(terms))
    return pieces


def _sum(terms: tuple[_Convex, ...]) -> list[Primitive]:
    """One sum of convex operands: the corners add, the round generators of one shape add."""
    points = np.zeros((1, 3))
    ball: _Convex | None = None
    disc: _Convex | None = None
    for c in terms:
        points = (points[:, None, :] + c.points[None]).reshape(-1, 3)
        if len(points) > 64:
            points = polytope(points).vertices
        if c.round == "ball":
            ball = c if ball is None else _add_round(ball, c)
        elif c.round == "disc":
            disc = c if disc is None else _add_round(disc, c)
    if ball is not None and disc is not None:
        return _rounded_cylinder(points, ball, disc)
    if ball is not None or disc is not None:
        return _grown(points, ball or disc)  # type: ignore[arg-type]
    return _polyhedron(points)


def _add_round(a: _Convex, b: _Convex) -> _Convex:
    """``L1 K + L2 K`` when ``L2 K = k L1 K``: ``(1 + k) L1 K``; refused otherwise."""
    ga, gb = _gram(a), _gram(b)
    k2 = float(np.trace(gb) / np.trace(ga))
    if not _same(gb, k2 * ga):
        what = "ellipsoids or spheres of different shapes" if a.round == "ball" else "cylinders that are not parallel"
        raise NotExactError(f"minkowski: a sum of {what} is not an exact union of isocsg kinds")
    lin = a.linear.copy()  # type: ignore[union-attr]
    scale = 1.0 + math.sqrt(k2)
    lin[:, : 3 if a.round == "ball" else 2] *= scale
    return _Convex(a.points, a.round, lin)


def _rounded_cylinder(points: NDArray[np.float64], ball: _Convex, disc: _Convex) -> list[Primitive]:
    """A segment along a disc's normal (or a point) plus the disc plus a ball: cylinders and tori."""
    lin_b, lin_d = ball.linear, disc.linear
    assert lin_b is not None and lin_d is not None
    r = similarity_factor(lin_b)
    g = lin_d[:, :2].T @ lin_d[:, :2]
    big = math.sqrt(g[0, 0])
    circular = abs(g[0, 1]) <= SHAPE_TOLERANCE * g[0, 0] and abs(g[1, 1] - g[0, 0]) <= SHAPE_TOLERANCE * g[0, 0]
    q = polytope(points)
    normal = lin_d[:, 2]
    along = q.dim == 0 or (q.dim == 1 and np.linalg.norm(np.cross(q.edges[0][1] - q.edges[0][0], normal))
                           <= SHAPE_TOLERANCE * np.linalg.norm(q.edges[0][1] - q.edges[0][0]))
    if r is None or not circular or not along:
        raise NotExactError(
            "minkowski: a ball plus a disc is exact only as a sphere plus a round cylinder (a rounded cylinder); "
            "with a polytope, an ellipsoid or an oblique cylinder it is not an exact union of isocsg kinds"
        )
    if r >= big:
        raise NotExactError(
            f"minkowski: a sphere of radius {r:g} plus a cylinder of radius {big:g} needs a spindle torus "
            "(the sphere's radius must be below the cylinder's)"
        )
    if q.dim == 0:
        c = q.vertices[0]
        return [Cylinder(c, 2 * r * normal, big), Torus(c, normal, big, r)]
    e0, e1 = q.edges[0]
    w = e1 - e0
    unit = w / np.linalg.norm(w)
    return [
        Cylinder((e0 + e1) / 2, w, big + r),
        Cylinder((e0 + e1) / 2, w + 2 * r * unit, big),
        Torus(e0, normal, big, r),
        Torus(e1, normal, big, r),
    ]


def minkowski(a: Solid, b: Solid, *more: Solid) -> Solid:
    """The Minkowski sum ``{x + y + ...}`` of solids, exactly, as a union of isocsg kinds.

    Parameters
    ----------
    a, b, *more : Solid
        Unions of convex primitives: polytopes (boxes, convex polyhedra), balls (spheres,
        ellipsoids) and cylinders of equal end radii (see :mod:`isocsg.csg.hull`).

    Returns
    -------
    Solid
        One primitive, or the :class:`~isocsg.Union` of the pieces.

    Raises
    ------
    NotExactError
        When the sum is no exact union of isocsg kinds (a difference or intersection operand,
        cones, tori, a sphere plus an ellipsoid, non-parallel cylinders, a box plus a sphere
        plus a cylinder); the message names what stops it.
    ResourceLimitError
        When the unions expand into more than :data:`MAX_MINKOWSKI_TERMS` sums.
    InvalidGeometryError
        When the sum has no volume.

    Examples
    --------
    >>> from isocsg import Box, Sphere, minkowski, volume
    >>> rounded = minkowski(Box((0, 0, 0), (2, 2, 2)), Sphere((0, 0, 0), 1))
    >>> abs(volume(rounded) / (8 + 24 + 6 * math.pi + 4 / 3 * math.pi) - 1) < 1e-4  # Steiner's formula
    True
    """
    return _one(minkowski_pieces(a, b, *more), "minkowski")
