"""Writing isocsg solids as OpenSCAD source.

Every kind is written: spheres, cylinders, cones and frusta, boxes (turned ones,
ellipsoids and elliptic trunci as a ``multmatrix`` of a cube, sphere or
cylinder), convex polyhedra and Boolean trees. The text uses only the calls of
OpenSCAD's flattened export (``multmatrix``,
``cube``, ``sphere``, ``cylinder``, ``polyhedron``, ``union``, ``difference``,
``intersection``), so it is both a ``.scad`` model and a ``.csg`` file that
:func:`isocsg.openscad.loads_openscad` reads back without the ``openscad``
program. Numbers are written with ``repr`` (the shortest text that reads back
to the same float), so that round trip keeps every bit.

OpenSCAD 2021 itself prints every number of its ``.csg`` export with 6
significant digits, but keeps nested ``multmatrix`` nodes. With ``digits``
(what :func:`save_openscad` uses for ``.scad`` files) every number has at
most that many digits and the exact values are composed from them, so that
the model comes through ``openscad`` as the same solid (see
:func:`dumps_openscad` and the README's OpenSCAD section). Each kind's
statement comes from its registered ``openscad`` hook.
"""

from __future__ import annotations

import functools
import math
import os
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..csg.tree import CSGNode, Difference, Intersection, Union
from ..errors import InvalidGeometryError, InvalidParameterError
from ..geometry.ellipsoid import Ellipsoid
from ..geometry.elliptic import EllipticTruncus
from ..geometry.primitives import Box, ConvexPolyhedron, Solid, Sphere, Truncus
from ..geometry.registry import hook_for

__all__ = ["dumps_openscad", "save_openscad"]

_OPS = {Union: "union", Intersection: "intersection", Difference: "difference"}


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


def _leaf(solid: Solid, digits: int | None) -> str:
    """One primitive as an OpenSCAD statement, through its kind's ``openscad`` hook."""
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


def polyhedron_scad(solid: ConvexPolyhedron, digits: int | None = None) -> str:
    """``polyhedron(points, faces)`` of the hull.

    With ``digits``: the points in the frame of the polyhedron's principal axes scaled to its
    extents (the frame written exactly, as any map), each coordinate rounded to ``digits``, and
    the faces of the hull of the rounded points, so that the file stays a convex polyhedron. No map of few digits can place
    every vertex of a general polyhedron: its volume keeps about ``digits`` digits.
    """
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


def dumps_openscad(solid: Solid, *, digits: int | None = None) -> str:
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
        corrections. Convex polyhedra keep their vertices to ``digits`` only;
        turned boxes come back as convex polyhedra (a sheared correction) and
        turned trunci as elliptic trunci, of the same volume.

    Returns
    -------
    str
        The model, one statement per line, ending in a newline.

    Raises
    ------
    InvalidParameterError
        For a solid kind that has no OpenSCAD form.

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
        lines.append(pad + _leaf(s, d))
    return "\n".join(lines) + "\n"


def save_openscad(solid: Solid, path: str | os.PathLike[str], *, digits: int | None | str = "auto") -> Path:
    """Write a solid as an OpenSCAD model (``.scad``, also readable as ``.csg``).

    Read it back with :func:`isocsg.load_openscad`: a ``.csg`` name reads it
    directly, a ``.scad`` name goes through the ``openscad`` program, whose
    ``.csg`` export prints 6 significant digits. ``digits="auto"`` (the
    default) therefore writes a ``.scad`` file with 6-digit numbers composed
    so that the export still equals the solid (see :func:`dumps_openscad`;
    measured: volumes within 1e-12), and a ``.csg`` file with every number's
    full ``repr``. ``digits=None`` or an integer chooses either form.

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
    p.write_text(dumps_openscad(solid, digits=digits), encoding="utf-8")  # type: ignore[arg-type]
    return p

