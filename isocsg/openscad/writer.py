"""Writing isocsg solids as OpenSCAD source.

Every kind is written: spheres, cylinders, cones and frusta, boxes (turned ones,
ellipsoids and elliptic trunci as a ``multmatrix`` of a cube, sphere or
cylinder), convex polyhedra and Boolean trees. The text uses only the calls of
OpenSCAD's flattened export (``multmatrix``, ``cube``, ``sphere``, ``cylinder``,
``polyhedron``, ``union``, ``difference``, ``intersection``, and ``hull`` for the
exact form of a convex polyhedron), so it is both a ``.scad`` model and a ``.csg``
file that :func:`isocsg.openscad.loads_openscad` reads back without the ``openscad``
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
statement comes from its own ``to_openscad`` (the number encodings are :mod:`isocsg.kinds.scad`).
"""

from __future__ import annotations

import os
from pathlib import Path

from ..csg.tree import NODE_TYPES, CSGNode
from ..errors import InvalidParameterError
from ..kinds.base import Primitive, Solid

__all__ = ["dumps_openscad", "save_openscad"]

# OpenSCAD's Boolean modules have isocsg's operation names.
_OPS = {cls: name for name, cls in NODE_TYPES.items()}


def _leaf(solid: Solid, digits: int | None, polyhedra: str = "hull") -> str:
    """One primitive as an OpenSCAD statement: its kind's ``to_openscad`` (``polyhedra="points"``:
    the plain ``polyhedron`` form of a kind that has one)."""
    if not isinstance(solid, Primitive):
        raise InvalidParameterError(f"save_openscad: cannot write a {type(solid).__name__}")
    return solid.to_openscad(digits, exact=polyhedra != "points")


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

