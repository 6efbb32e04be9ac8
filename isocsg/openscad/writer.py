"""Writing isocsg solids as OpenSCAD source.

Every kind is written: spheres, cylinders, cones and frusta, boxes (turned ones,
ellipsoids and elliptic trunci as a ``multmatrix`` of a cube, sphere or
cylinder), convex polyhedra and Boolean trees. The text uses only the calls of
OpenSCAD's flattened export (``multmatrix``,
``cube``, ``sphere``, ``cylinder``, ``polyhedron``, ``union``, ``difference``,
``intersection``, and ``hull`` for the exact form of a convex polyhedron), so it is both a ``.scad`` model and a ``.csg`` file that
:func:`isocsg.openscad.loads_openscad` reads back without the ``openscad``
program. Numbers are written with ``repr`` (the shortest text that reads back
to the same float), so that round trip keeps every bit.

OpenSCAD 2021 itself prints every number of its ``.csg`` export with 6
significant digits, but keeps nested ``multmatrix`` nodes. With ``digits``
(what :func:`save_openscad` uses for ``.scad`` files) every number has at
most that many digits and the exact values are composed from them, so that
the model comes through ``openscad`` as the same solid (see
:func:`dumps_openscad` and ``docs/openscad.md``): a convex polyhedron, whose
points the export rounds like any number, as the ``hull()`` of one small
tetrahedron per vertex, its tip moved onto the vertex by nested translations. Each kind's
statement comes from its registered ``openscad`` hook.
"""

from __future__ import annotations

import functools
import itertools
import math
import os
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..csg.tree import NODE_TYPES, CSGNode
from ..errors import InvalidGeometryError, InvalidParameterError
from ..geometry.ellipsoid import Ellipsoid
from ..geometry.elliptic import EllipticTruncus
from ..geometry.primitives import Box, ConvexPolyhedron, Solid, Sphere, Truncus
from ..geometry.registry import hook_for

__all__ = ["dumps_openscad", "save_openscad"]

# OpenSCAD's Boolean modules have isocsg's operation names.
_OPS = {cls: name for name, cls in NODE_TYPES.items()}


def _num(x: float) -> str:
    x = float(x)
    if x == 0.0:
        return "0"  # also -0.0
    if x == int(x) and abs(x) < 1e15:
        return str(int(x))
    return repr(x)


def _vec(v: NDArray[np.float64] | list[float] | tuple[float, ...]) -> str:
    return "[" + ", ".join(_num(x) for x in v) + "]"


def _mat(m: NDArray[np.float64]) -> str:
    return "[" + ", ".join(_vec(row) for row in m) + "]"


def _frame(axis: NDArray[np.float64], center: NDArray[np.float64]) -> NDArray[np.float64]:
    """A rigid map taking +z to the unit ``axis`` and the origin to ``center``."""
    w = axis / np.linalg.norm(axis)
    m = np.eye(4)
    if w[0] == 0.0 and w[1] == 0.0:
        if w[2] < 0:
            m[:3, :3] = np.diag([1.0, -1.0, -1.0])  # a half turn about x
    else:
        helper = np.array([0.0, 0.0, 1.0]) if abs(w[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
        u = np.cross(helper, w)
        u /= np.linalg.norm(u)
        v = np.cross(w, u)
        m[:3, 0], m[:3, 1], m[:3, 2] = u, v, w
    m[:3, 3] = center
    return m


def _translated(center: NDArray[np.float64], body: str) -> str:
    if not np.any(center):
        return body
    m = np.eye(4)
    m[:3, 3] = center
    return f"multmatrix({_mat(m)}) {{ {body} }}"


# ----------------------------------------------------------------------------- numbers of few digits
#
# OpenSCAD 2021 prints every number of its .csg export (matrix entries, sizes, radii,
# points) with 6 significant digits. A number written with at most that many digits comes
# through unchanged, and nested multmatrix nodes come through as nested nodes, which the
# loader applies one after the other. So an exact value can be written as a sum of short
# numbers (nested translations) or a product of them (nested scales), and a linear map as
# a product of short matrices: L = L_d (I + lower) diag(a b) (I + upper), each factor's
# residual at the next factor's scale. Every term is ~10^-d of the previous one.


def _round_sig(x: float, d: int) -> float:
    """``x`` rounded to ``d`` significant decimal digits (what OpenSCAD prints for d = 6)."""
    return float(f"{float(x):.{d - 1}e}")


def _num_sig(x: float, d: int) -> str:
    x = _round_sig(x, d)
    if x == 0.0:
        return "0"
    return f"{x:.{d}g}"


def _split_sum(x: NDArray[np.float64], d: int, terms: int = 3) -> list[NDArray[np.float64]]:
    """Vectors of ``d``-digit entries whose sum is ``x`` (each the rounding of what is left)."""
    out = []
    rest = np.asarray(x, dtype=np.float64).copy()
    for _ in range(terms):
        if not np.any(rest):
            break
        part = np.array([_round_sig(v, d) for v in rest])
        out.append(part)
        rest = rest - part  # exact (Sterbenz) while part is the rounding of rest
    return out


@functools.lru_cache(maxsize=4096)
def _split_product(x: float, d: int) -> tuple[float, float]:
    """Two ``d``-digit numbers whose product is ``x`` to about ``10**(2 - 2 d)`` relative.

    Every ``d``-digit mantissa ``b`` in [1, 10) is tried with ``a = x / b`` rounded
    to ``d`` digits; the pair whose product is nearest ``x`` wins."""
    if x == 0.0 or _round_sig(x, d) == x:
        return x, 1.0
    ax = abs(x)
    b = np.arange(10 ** (d - 1), 10**d, dtype=np.float64) / 10 ** (d - 1)
    q = ax / b
    e = 10.0 ** (np.floor(np.log10(q)) - (d - 1))
    a = np.round(q / e) * e
    i = int(np.argmin(np.abs(a * b - ax)))
    return math.copysign(_round_sig(float(a[i]), d), x), float(b[i])


def _ratio(r: float, d: int) -> tuple[int, int]:
    """Integers ``(p, q)``, both below ``10**d``, with ``p / q`` the best approximation of
    ``r`` in [0, 1] (continued fractions)."""
    limit = 10**d - 1
    if r <= 0.0:
        return 0, 1
    if r >= 1.0:
        return 1, 1
    h0, h1, k0, k1 = 0, 1, 1, 0
    x = r
    while True:
        a = math.floor(x)
        h2, k2 = a * h1 + h0, a * k1 + k0
        if k2 > limit:
            break
        h0, h1, k0, k1 = h1, h2, k1, k2
        frac = x - a
        if frac == 0.0 or abs(h1 / k1 - r) <= 1e-17 * r:
            break
        x = 1.0 / frac
    return h1, k1


def _short_mat(m: NDArray[np.float64], d: int) -> str:
    return "[" + ", ".join("[" + ", ".join(_num_sig(x, d) for x in row) + "]" for row in m) + "]"


def _encoded(body: str, L: NDArray[np.float64], t: NDArray[np.float64], d: int) -> str:
    """``body`` (a unit primitive whose numbers are short) mapped by ``x -> L x + t``, as
    nested ``multmatrix`` nodes whose entries have at most ``d`` significant digits."""
    L = np.asarray(L, dtype=np.float64)
    linear: list[NDArray[np.float64]] = []  # outermost first
    if np.count_nonzero(L - np.diag(np.diag(L))) == 0:
        diag = np.diag(L).copy()
        upper = None
    else:
        L6 = np.vectorize(lambda v: _round_sig(v, d))(L)
        C = np.linalg.solve(L6, L)  # I + O(10^-d)
        lower = np.eye(3)
        for j in range(3):  # Doolittle without pivots: C is close to the identity
            for i in range(j + 1, 3):
                lower[i, j] = _round_sig(C[i, j] / C[j, j], d)
        R = np.linalg.solve(L6 @ lower, L)  # diag(D) (I + upper), to the rounding of `lower`
        diag = np.diag(R).copy()
        upper = np.eye(3)
        for i in range(3):
            for j in range(i + 1, 3):
                upper[i, j] = _round_sig(R[i, j] / R[i, i], d)
        # what the rounded factors leave on the diagonal
        diag = np.diag(np.linalg.solve(L6 @ lower, L) @ np.linalg.inv(upper)).copy()
        linear += [L6, lower]
    ab = [_split_product(float(v), d) for v in diag]  # (10**(d-1) tries each; equal sizes are cached)
    linear += [np.diag([a for a, _ in ab]), np.diag([b for _, b in ab])]
    if upper is not None:
        linear.append(upper)
    factors: list[NDArray[np.float64]] = []
    for part in _split_sum(np.asarray(t, dtype=np.float64), d):
        m = np.eye(4)
        m[:3, 3] = part
        factors.append(m)
    for lin in linear:
        m = np.eye(4)
        m[:3, :3] = lin
        factors.append(m)
    out = body
    for m in reversed(factors):
        if not np.array_equal(m, np.eye(4)):
            out = f"multmatrix({_short_mat(m, d)}) {{ {out} }}"
    return out


def _truncus_body(r_low: float, r_high: float, d: int) -> tuple[str, float]:
    """A unit-height centred cylinder whose radii (OpenSCAD's r1 at z = -1/2, r2 at +1/2) are
    integers in the ratio ``r_low : r_high``, and the radial scale that gives them back."""
    big = max(r_low, r_high)
    p, q = _ratio(min(r_low, r_high) / big, d)
    lo, hi = (q, p) if r_low >= r_high else (p, q)
    return f"cylinder(h = 1, r1 = {lo}, r2 = {hi}, center = true);", big / q


def _leaf(solid: Solid, digits: int | None, polyhedra: str = "hull") -> str:
    """One primitive as an OpenSCAD statement, through its kind's ``openscad`` hook."""
    if polyhedra == "points" and isinstance(solid, ConvexPolyhedron):
        return polyhedron_scad(solid, digits, exact=False)
    hook = hook_for(solid, "openscad")
    if hook is None:
        raise InvalidParameterError(f"save_openscad: cannot write a {type(solid).__name__} (kind {getattr(solid, 'kind', '?')!r})")
    return hook(solid, digits)  # type: ignore[no-any-return]


# ----------------------------------------------------------------------------- the built-in kinds' hooks


def sphere_scad(solid: Sphere, digits: int | None = None) -> str:
    """``sphere(r)``, moved to the centre."""
    if digits is not None:
        return _encoded("sphere(r = 1);", solid.radius * np.eye(3), solid.center_array, digits)
    return _translated(np.asarray(solid.center), f"sphere(r = {_num(solid.radius)});")


def truncus_scad(solid: Truncus, digits: int | None = None) -> str:
    """A centred ``cylinder(h, r1, r2)`` turned onto the axis and moved."""
    if digits is not None:
        body, k = _truncus_body(solid.r2, solid.r1, digits)
        axis = np.asarray(solid.axis, dtype=np.float64)
        R = np.eye(3) if axis[0] == 0 and axis[1] == 0 and axis[2] > 0 else _frame(axis, np.zeros(3))[:3, :3]
        return _encoded(body, R * np.array([k, k, solid.height]), solid.center_array, digits)
    # OpenSCAD's r1 is at z = 0, the truncus' r1 at center + axis / 2: the cylinder's +z runs along the axis.
    body = f"cylinder(h = {_num(solid.height)}, r1 = {_num(solid.r2)}, r2 = {_num(solid.r1)}, center = true);"
    axis = np.asarray(solid.axis, dtype=np.float64)
    if axis[0] == 0 and axis[1] == 0 and axis[2] > 0:
        return _translated(np.asarray(solid.center), body)
    return f"multmatrix({_mat(_frame(axis, np.asarray(solid.center)))}) {{ {body} }}"


def box_scad(solid: Box, digits: int | None = None) -> str:
    """A centred ``cube(size)``, turned by the orientation and moved."""
    if digits is not None:
        R = np.eye(3) if solid.axis_aligned else np.asarray(solid.orientation, dtype=np.float64)
        return _encoded("cube(size = [1, 1, 1], center = true);", R * np.asarray(solid.size), solid.center_array, digits)
    body = f"cube(size = {_vec(solid.size)}, center = true);"
    if solid.axis_aligned:
        return _translated(np.asarray(solid.center), body)
    m = np.eye(4)
    m[:3, :3] = np.asarray(solid.orientation, dtype=np.float64)  # columns: the box's own axes
    m[:3, 3] = solid.center
    return f"multmatrix({_mat(m)}) {{ {body} }}"


def ellipsoid_scad(solid: Ellipsoid, digits: int | None = None) -> str:
    """The unit sphere mapped by orientation x diag(radii), then moved to the centre."""
    if digits is not None:
        L = np.asarray(solid.orientation, dtype=np.float64) * np.asarray(solid.radii, dtype=np.float64)
        return _encoded("sphere(r = 1);", L, solid.center_array, digits)
    m = np.eye(4)
    m[:3, :3] = np.asarray(solid.orientation, dtype=np.float64) * np.asarray(solid.radii, dtype=np.float64)
    m[:3, 3] = solid.center
    return f"multmatrix({_mat(m)}) {{ sphere(r = 1); }}"


def elliptic_truncus_scad(solid: EllipticTruncus, digits: int | None = None) -> str:
    """The canonical truncus (unit height along z, E1 of radius r1 at z = +1/2) mapped by ``matrix``."""
    if digits is not None:
        body, k = _truncus_body(solid.r2, solid.r1, digits)
        L = np.asarray(solid.matrix, dtype=np.float64) * np.array([k, k, 1.0])
        return _encoded(body, L, solid.center_array, digits)
    m = np.eye(4)
    m[:3, :3] = np.asarray(solid.matrix, dtype=np.float64)
    m[:3, 3] = solid.center
    body = f"cylinder(h = 1, r1 = {_num(solid.r2)}, r2 = {_num(solid.r1)}, center = true);"
    return f"multmatrix({_mat(m)}) {{ {body} }}"


def polyhedron_scad(solid: ConvexPolyhedron, digits: int | None = None, *, exact: bool = True) -> str:
    """``polyhedron(points, faces)`` of the hull; with ``digits``, the hull of exactly placed corners.

    With ``digits`` and ``exact`` (the default): ``hull()`` of one spike per vertex, a small
    tetrahedron whose tip is the vertex and whose base lies deep inside the solid. Only the tip
    must be exact, and it is the origin of the spike's frame, moved to the vertex by nested
    translations whose short terms sum to its coordinates (see :func:`_corner_spikes`); the
    base points may keep ``digits`` digits, as they stay well inside (a thin solid's in its
    principal frame). The hull of the spikes is the hull of the vertices: the same solid, every
    vertex to about one unit in the last place. A sliver whose vertices' mean lies within 1e-10
    of its size from a face (thinner than about 1e-9 of its size) is written in the rounded
    form instead.

    With ``digits`` and ``exact=False``: a plain ``polyhedron`` of the points in the frame of the
    principal axes scaled to the extents (the frame written exactly, as any map), each coordinate
    rounded to ``digits``, and the faces of the hull of the rounded points: readable, but the
    volume keeps only about ``digits`` digits (no map of few digits places every vertex of a
    general polyhedron).
    """
    if digits is not None and exact:
        spikes = _corner_spikes(solid, digits)
        if spikes is not None:
            return spikes
    if digits is not None:
        # in the frame of its principal axes, scaled to its extents: every coordinate is O(1), so
        # that rounding it moves the vertex by the same small fraction of the size in every direction
        v = np.asarray(solid.hull_vertices, dtype=np.float64)
        lo, hi = solid.bounds
        c = np.array([_round_sig(x, digits) for x in 0.5 * (lo + hi)])
        _, _, axes = np.linalg.svd(v - v.mean(axis=0))
        half = np.ptp((v - c) @ axes.T, axis=0) / 2
        L = axes.T * half
        local = np.vectorize(lambda x: _round_sig(x, digits))(np.linalg.solve(L, (v - c).T).T)
        try:
            rounded = ConvexPolyhedron(local)
        except InvalidGeometryError:  # pragma: no cover - rounding flattened a sliver
            rounded = ConvexPolyhedron(np.linalg.solve(L, (v - c).T).T)
        return _encoded(polyhedron_scad(rounded), L, c, digits)
    pts = ", ".join(_vec(p) for p in solid.hull_vertices)
    # OpenSCAD wants each face clockwise seen from outside; isocsg's are counter-clockwise.
    faces = ", ".join("[" + ", ".join(str(int(i)) for i in reversed(f)) + "]" for f in solid.faces)
    return f"polyhedron(points = [{pts}], faces = [{faces}]);"


#: How deep inside the solid the base of a corner spike must stay (a fraction of the depth of
#: the base's centre): the margin covers the rounding of the base points to ``digits``.
_SPIKE_MARGIN = 0.25


def _exact_translations(x: NDArray[np.float64], d: int) -> list[NDArray[np.float64]]:
    """Vectors of ``d``-digit entries whose sum, added smallest first, is ``x`` to its last bit
    (each the rounding of what is left; every subtraction is exact)."""
    parts: list[NDArray[np.float64]] = []
    rest = np.asarray(x, dtype=np.float64).copy()
    size = float(np.abs(rest).max())
    while np.any(rest) and float(np.abs(rest).max()) > 2.0**-60 * size and len(parts) < 8:
        part = np.array([_round_sig(v, d) for v in rest])
        parts.append(part)
        rest = rest - part
    return parts


def _corner_spikes(solid: ConvexPolyhedron, d: int) -> str | None:
    """``hull()`` of one tetrahedron per vertex: the tip exactly at the vertex (nested
    translations), the base three points halfway between the vertices' mean and three extreme
    vertices (those of the principal axes that make the fattest spike).

    A base point halfway to the mean c is inside every face plane by at least half c's depth
    (convexity); rounded to ``d`` digits, every one is checked to stay inside by
    :data:`_SPIKE_MARGIN` of that depth, so that the hull's vertices are the tips alone (in
    OpenSCAD's exact hull and in the loader's). None when a base cannot stay inside.
    """
    v = np.asarray(solid.hull_vertices, dtype=np.float64)
    normals = np.asarray(solid.face_normals, dtype=np.float64)
    offsets = np.asarray(solid.face_offsets, dtype=np.float64)
    size = float(np.max(np.ptp(v, axis=0)))
    c = v.mean(axis=0)
    depth = float(np.min(offsets - normals @ c))  # the radius of the largest ball about c inside
    if not depth > 1e-10 * size:  # the margin below must stay far above the hulls' round-off
        return None
    _, _, axes = np.linalg.svd(v - c)
    along = (v - c) @ axes.T
    extreme = np.unique(np.concatenate([along.argmin(axis=0), along.argmax(axis=0)]))
    if len(extreme) < 4:
        extreme = np.arange(len(v))
    bases = c + 0.5 * (v[extreme] - c)
    triples = np.array([t for t in itertools.combinations(range(len(bases)), 3)])
    # A thin solid's bases are written in its principal frame scaled to its extents (a short
    # matrix that keeps the tip at the origin), so that rounding them moves them across the thin
    # side by a small fraction of its thickness; a plain solid needs no frame.
    frame = np.vectorize(lambda x: _round_sig(x, d))(axes.T * (np.ptp(along, axis=0) / 2))
    for framed in (False, True):
        lines = _spikes(v, bases, triples, frame if framed else None, normals, offsets, _SPIKE_MARGIN * depth, d)
        if lines is not None:
            return "\n".join(["hull() {", *lines, "}"])
    return None


def _spikes(
    v: NDArray[np.float64],
    bases: NDArray[np.float64],
    triples: NDArray[np.int64],
    frame: NDArray[np.float64] | None,
    normals: NDArray[np.float64],
    offsets: NDArray[np.float64],
    margin: float,
    d: int,
) -> list[str] | None:
    """One line per vertex of :func:`_corner_spikes`; None when a rounded base point leaves the
    solid's faces by less than ``margin`` or a spike is flat."""
    lines = []
    for p in v:
        spans = bases[triples] - p  # (triples, 3 points, 3)
        best = triples[int(np.argmax(np.abs(np.linalg.det(spans))))]
        if frame is None:
            local = np.vectorize(lambda x: _round_sig(x, d))(bases[best] - p)
            rel = local
        else:
            local = np.vectorize(lambda x: _round_sig(x, d))(np.linalg.solve(frame, (bases[best] - p).T).T)
            rel = local @ frame.T  # as a reader maps them
        if np.min(offsets[None, :] - (p + rel) @ normals.T) < margin:
            return None
        if abs(float(np.linalg.det(rel))) <= 1e-9 * float(np.ptp(np.vstack([np.zeros(3), rel]), axis=0).max()) ** 3:
            return None  # a flat spike, which a reader drops
        pts = np.vstack([np.zeros(3), local])
        faces = []
        for tri, other in (((0, 1, 2), 3), ((0, 1, 3), 2), ((0, 2, 3), 1), ((1, 2, 3), 0)):
            i, j, k = tri
            inward = float(np.dot(np.cross(pts[j] - pts[i], pts[k] - pts[i]), pts[other] - pts[i])) > 0
            faces.append((i, j, k) if inward else (i, k, j))  # clockwise seen from outside
        body = (
            "polyhedron(points = [" + ", ".join("[" + ", ".join(_num_sig(x, d) for x in q) + "]" for q in pts) + "], "
            "faces = [" + ", ".join("[" + ", ".join(map(str, f)) + "]" for f in faces) + "]);"
        )
        if frame is not None:
            m = np.eye(4)
            m[:3, :3] = frame
            body = f"multmatrix({_short_mat(m, d)}) {{ {body} }}"
        for part in reversed(_exact_translations(p, d)):  # the smallest term innermost: added first
            m = np.eye(4)
            m[:3, 3] = part
            body = f"multmatrix({_short_mat(m, d)}) {{ {body} }}"
        lines.append("  " + body)
    return lines


#: The range of ``digits`` (the search of a split product tries 10**(digits - 1) mantissas).
MIN_DIGITS, MAX_DIGITS = 4, 7
#: What OpenSCAD 2021 prints in its .csg export.
OPENSCAD_DIGITS = 6


def _check_digits(digits: object) -> int | None:
    if digits is None:
        return None
    if isinstance(digits, bool) or not isinstance(digits, int) or not MIN_DIGITS <= digits <= MAX_DIGITS:
        raise InvalidParameterError(
            f"save_openscad: digits must be None or an integer from {MIN_DIGITS} to {MAX_DIGITS}, got {digits!r}"
        )
    return digits


#: The forms of a convex polyhedron with ``digits``: exact corners, or rounded points.
POLYHEDRON_FORMS = ("hull", "points")


def _check_polyhedra(polyhedra: object) -> str:
    if polyhedra not in POLYHEDRON_FORMS:
        raise InvalidParameterError(f"save_openscad: polyhedra must be 'hull' or 'points', got {polyhedra!r}")
    return polyhedra  # type: ignore[return-value]


def dumps_openscad(solid: Solid, *, digits: int | None = None, polyhedra: str = "hull") -> str:
    """OpenSCAD source of a solid (see the module docstring).

    Parameters
    ----------
    solid : Solid
        A primitive or CSG tree.
    digits : int or None
        None: every number as its shortest exact ``repr``. An integer (4 to 7):
        no number has more significant digits than that, and the model is
        written so that it still equals the solid to about ``10**(2 - 2 digits)``
        relative (``digits = 6`` for a model that goes through OpenSCAD 2021,
        which prints 6 digits in its ``.csg`` export): positions as sums of
        nested translations, sizes as products of nested scales, turns and
        shears as products of a rounded matrix and unit triangular
        corrections, convex polyhedra as the ``hull()`` of one spike per
        vertex placed exactly (see ``polyhedra``). Turned boxes come back as
        convex polyhedra (a sheared correction) and turned trunci as elliptic
        trunci, of the same volume.
    polyhedra : {"hull", "points"}
        With ``digits``, how a convex polyhedron is written. ``"hull"`` (the
        default): exactly, as the hull of small tetrahedra whose tips are its
        vertices, each moved by nested translations that sum to the vertex to
        its last bit; it comes back as an equal :class:`ConvexPolyhedron`.
        ``"points"``: a plain, readable ``polyhedron`` whose points are
        rounded to ``digits`` (the volume keeps about that many digits).
        Ignored without ``digits``.

    Returns
    -------
    str
        The model, one statement per line, ending in a newline.

    Raises
    ------
    InvalidParameterError
        For a solid kind that has no OpenSCAD form, or a bad ``digits`` or
        ``polyhedra``.

    Examples
    --------
    >>> from isocsg import Box, Sphere
    >>> print(dumps_openscad(Box((0, 0, 0), (2, 2, 2)) - Sphere((1, 1, 1), 1)), end="")
    difference() {
      cube(size = [2, 2, 2], center = true);
      multmatrix([[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 1], [0, 0, 0, 1]]) { sphere(r = 1); }
    }
    """
    if not isinstance(solid, Solid):
        raise InvalidParameterError(f"save_openscad: solid must be an isocsg Solid, got {type(solid).__name__}")
    d = _check_digits(digits)
    form = _check_polyhedra(polyhedra)
    lines: list[str] = []
    # Explicit stack: (solid, depth) to open, or a closing brace at a depth.
    todo: list[tuple[Solid | None, int]] = [(solid, 0)]
    while todo:
        s, depth = todo.pop()
        pad = "  " * depth
        if s is None:
            lines.append(pad + "}")
            continue
        if isinstance(s, CSGNode):
            name = next(op for cls, op in _OPS.items() if isinstance(s, cls))
            lines.append(f"{pad}{name}() {{")
            todo.append((None, depth))
            todo.extend((c, depth + 1) for c in reversed(s.children))
            continue
        lines.extend(pad + line for line in _leaf(s, d, form).split("\n"))
    return "\n".join(lines) + "\n"


def save_openscad(
    solid: Solid, path: str | os.PathLike[str], *, digits: int | None | str = "auto", polyhedra: str = "hull"
) -> Path:
    """Write a solid as an OpenSCAD model (``.scad``, also readable as ``.csg``).

    Read it back with :func:`isocsg.load_openscad`: a ``.csg`` name reads it
    directly, a ``.scad`` name goes through the ``openscad`` program, whose
    ``.csg`` export prints 6 significant digits. ``digits="auto"`` (the
    default) therefore writes a ``.scad`` file with 6-digit numbers composed
    so that the export still equals the solid (see :func:`dumps_openscad`;
    measured: volumes within 1e-12), and a ``.csg`` file with every number's
    full ``repr``. ``digits=None`` or an integer chooses either form.
    ``polyhedra`` chooses how convex polyhedra are written with digits:
    ``"hull"`` (exact) or ``"points"`` (readable, rounded; see
    :func:`dumps_openscad`).

    Returns
    -------
    pathlib.Path
        The path written.

    Raises
    ------
    InvalidParameterError
        For a solid kind that has no OpenSCAD form, or a path that does not end
        in ``.scad`` or ``.csg``.
    """
    p = Path(path)
    if p.suffix.lower() not in (".scad", ".csg"):
        raise InvalidParameterError(f"save_openscad: path must end in .scad or .csg, got {str(p)!r}")
    if digits == "auto":
        digits = OPENSCAD_DIGITS if p.suffix.lower() == ".scad" else None
    p.write_text(dumps_openscad(solid, digits=digits, polyhedra=polyhedra), encoding="utf-8")  # type: ignore[arg-type]
    return p

