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

OpenSCAD 2021 itself prints at most 6 significant digits when it exports
``.csg``; a model that goes through ``openscad`` keeps its numbers to that
precision only (see the README's OpenSCAD section).
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..csg.tree import CSGNode, Difference, Intersection, Union
from ..errors import InvalidParameterError
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


def _leaf(solid: Solid) -> str:
    """One primitive as an OpenSCAD statement, through its kind's ``openscad`` hook."""
    hook = hook_for(solid, "openscad")
    if hook is None:
        raise InvalidParameterError(f"save_openscad: cannot write a {type(solid).__name__} (kind {getattr(solid, 'kind', '?')!r})")
    return hook(solid)  # type: ignore[no-any-return]


# ----------------------------------------------------------------------------- the built-in kinds' hooks


def sphere_scad(solid: Sphere) -> str:
    """``sphere(r)``, moved to the centre."""
    return _translated(np.asarray(solid.center), f"sphere(r = {_num(solid.radius)});")


def truncus_scad(solid: Truncus) -> str:
    """A centred ``cylinder(h, r1, r2)`` turned onto the axis and moved."""
    # OpenSCAD's r1 is at z = 0, the truncus' r1 at center + axis / 2: the cylinder's +z runs along the axis.
    body = f"cylinder(h = {_num(solid.height)}, r1 = {_num(solid.r2)}, r2 = {_num(solid.r1)}, center = true);"
    axis = np.asarray(solid.axis, dtype=np.float64)
    if axis[0] == 0 and axis[1] == 0 and axis[2] > 0:
        return _translated(np.asarray(solid.center), body)
    return f"multmatrix({_mat(_frame(axis, np.asarray(solid.center)))}) {{ {body} }}"


def box_scad(solid: Box) -> str:
    """A centred ``cube(size)``, turned by the orientation and moved."""
    body = f"cube(size = {_vec(solid.size)}, center = true);"
    if solid.axis_aligned:
        return _translated(np.asarray(solid.center), body)
    m = np.eye(4)
    m[:3, :3] = np.asarray(solid.orientation, dtype=np.float64)  # columns: the box's own axes
    m[:3, 3] = solid.center
    return f"multmatrix({_mat(m)}) {{ {body} }}"


def ellipsoid_scad(solid: Ellipsoid) -> str:
    """The unit sphere mapped by orientation x diag(radii), then moved to the centre."""
    m = np.eye(4)
    m[:3, :3] = np.asarray(solid.orientation, dtype=np.float64) * np.asarray(solid.radii, dtype=np.float64)
    m[:3, 3] = solid.center
    return f"multmatrix({_mat(m)}) {{ sphere(r = 1); }}"


def elliptic_truncus_scad(solid: EllipticTruncus) -> str:
    """The canonical truncus (unit height along z, E1 of radius r1 at z = +1/2) mapped by ``matrix``."""
    m = np.eye(4)
    m[:3, :3] = np.asarray(solid.matrix, dtype=np.float64)
    m[:3, 3] = solid.center
    body = f"cylinder(h = 1, r1 = {_num(solid.r2)}, r2 = {_num(solid.r1)}, center = true);"
    return f"multmatrix({_mat(m)}) {{ {body} }}"


def polyhedron_scad(solid: ConvexPolyhedron) -> str:
    """``polyhedron(points, faces)`` of the hull."""
    pts = ", ".join(_vec(p) for p in solid.hull_vertices)
    # OpenSCAD wants each face clockwise seen from outside; isocsg's are counter-clockwise.
    faces = ", ".join("[" + ", ".join(str(int(i)) for i in reversed(f)) + "]" for f in solid.faces)
    return f"polyhedron(points = [{pts}], faces = [{faces}]);"


def dumps_openscad(solid: Solid) -> str:
    """OpenSCAD source of a solid (see the module docstring).

    Parameters
    ----------
    solid : Solid
        A primitive or CSG tree.

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
        lines.append(pad + _leaf(s))
    return "\n".join(lines) + "\n"


def save_openscad(solid: Solid, path: str | os.PathLike[str]) -> Path:
    """Write a solid as an OpenSCAD model (``.scad``, also readable as ``.csg``).

    Numbers keep full float precision. Read it back with
    :func:`isocsg.load_openscad` (a ``.csg`` name reads it directly; a
    ``.scad`` name goes through the ``openscad`` program, which rounds to 6
    significant digits).

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
    p.write_text(dumps_openscad(solid), encoding="utf-8")
    return p

