"""What OpenSCAD 2021.01 drops or mends with a warning, dropped or mended the same way, never silently.

OpenSCAD renders some nodes of its own ``.csg`` export as nothing, or reads a value leniently,
where a strict reader would fail. isocsg does what OpenSCAD does, and says so with an
:class:`OpenSCADLenientWarning` naming the node and its line (the node is also listed in
:attr:`~isocsg.openscad.LoweredModel.left_out` when it is dropped):

- a ``cube``, ``sphere`` or ``cylinder`` with an infinite or NaN size, radius or height: nothing
  (``primitives.cc``: every size must be positive and finite);
- a ``polyhedron`` without points, or with a point that is not three finite numbers: nothing
  (OpenSCAD reports the point and then that the mesh is not closed);
- a ``multmatrix`` (``translate``, ``rotate``, ...) with an infinite or NaN entry: its subtree is
  left out ("Transformation matrix contains Not-a-Number and/or Infinity - removing object");
- an ``import`` or ``surface`` whose ``file`` is empty, does not exist, or is of a type OpenSCAD
  does not read (``.eps``): nothing ("Can't open import file", "The file '' couldn't be opened",
  "Unsupported file format"); NEF3 files, which OpenSCAD reads and isocsg does not, stay refused by
  name;
- an infinite or NaN ``$fn``: 3 segments (``Calc::get_fragments_from_r``);
- a ``multmatrix`` whose last row is not ``[0, 0, 0, 1]``: that row ignored (OpenSCAD's
  transforms are affine: its STL of such a model is the affine part's image);
- a ``color`` component outside [0, 1]: clamped to [0, 1], as the display clamps it (OpenSCAD
  warns "color() expects numbers between 0.0 and 1.0"); OpenSCAD's unset colour
  ``[-1, -1, -1, 1]`` stays no colour.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path
from typing import Any

from .parser import CSGCall

__all__ = ["OpenSCADLenientWarning", "dropped", "color_value", "mesh", "affine_row"]


class OpenSCADLenientWarning(UserWarning):
    """A node that OpenSCAD drops or mends with a warning was dropped or mended the same way
    (:mod:`isocsg.openscad.lenient`); the message names the node and its line."""


_SIZES = {"cube": ("size",), "sphere": ("r", "d"), "cylinder": ("h", "r", "r1", "r2", "d", "d1", "d2")}
_MAPS = {"multmatrix", "translate", "rotate", "scale", "mirror"}
_READ = {".stl", ".off", ".obj", ".ply", ".3mf", ".amf", ".dxf", ".svg", ".dat", ".png"}  # the files read here
_NOT_READ = {".nef3"}  # read by OpenSCAD 2021.01, not here


def _finite(value: Any) -> bool:
    """Every number in ``value`` (a number or nested lists) is finite; other values count as finite."""
    todo = [value]
    while todo:
        v = todo.pop()
        if isinstance(v, list):
            todo.extend(v)
        elif isinstance(v, float) and not math.isfinite(v):
            return False
    return True


def _warn(lw: Any, call: CSGCall, what: str) -> None:
    warnings.warn(OpenSCADLenientWarning(f"{lw.where(call)}{call.name}(): {what}"), stacklevel=5)


def _point3(p: Any) -> bool:
    return (isinstance(p, list) and len(p) == 3
            and all(isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) for x in p))


def _missing_file(lw: Any, call: CSGCall) -> str | None:
    """Why an ``import``'s or ``surface``'s file cannot be opened (None: it can)."""
    value = call.kwargs.get("file", call.args[0] if call.args else None)
    if not isinstance(value, str) or not value:
        return f"no file name (file = {value!r})"
    path = Path(value)
    suffix = path.suffix.lower()
    if suffix not in _READ and suffix not in _NOT_READ:
        return f"OpenSCAD reads no {suffix or 'unnamed'} files (file = {value!r})"
    if suffix in _NOT_READ:
        return None  # a format OpenSCAD reads but isocsg does not: refused by name, found or not
    if not path.is_absolute() and lw.source:
        path = Path(lw.source).parent / path
    return None if path.is_file() else f"the file {value!r} does not exist (looked for {str(path)!r})"


def _why(lw: Any, call: CSGCall) -> str | None:
    name = call.name
    if name in _SIZES:
        bad = [k for k in _SIZES[name] if k in call.kwargs and not _finite(call.kwargs[k])]
        if bad or not _finite(call.args):
            return f"{bad[0] if bad else 'a size'} is infinite or NaN"
    elif name == "polyhedron":
        points = call.kwargs.get("points", call.args[0] if call.args else None)
        faces = call.kwargs.get("faces", call.kwargs.get("triangles", call.args[1] if len(call.args) > 1 else None))
        if not isinstance(points, list) or not points or not isinstance(faces, list) or not faces:
            return "no points" if not isinstance(points, list) or not points else "no faces"
        bad_points = [i for i, p in enumerate(points) if not _point3(p)]
        if bad_points:
            return f"points[{bad_points[0]}] is not three finite numbers"
    elif name in _MAPS:
        if not _finite(call.args) or not _finite(list(call.kwargs.values())):
            return "its transformation contains NaN or infinity (the subtree is removed)"
    elif name in ("import", "surface"):
        return _missing_file(lw, call)
    return None


def dropped(lw: Any, call: CSGCall) -> bool:
    """Whether OpenSCAD draws nothing of ``call`` (then warned and noted in ``lw.left_out``);
    an infinite or NaN ``$fn`` is mended to 3 (warned)."""
    fn = call.kwargs.get("$fn")
    if isinstance(fn, float) and not math.isfinite(fn):
        call.kwargs["$fn"] = 3.0
        _warn(lw, call, f"$fn = {fn}: OpenSCAD draws 3 segments")
    why = _why(lw, call)
    if why is None:
        return False
    lw.note(call, f"{why}: OpenSCAD draws nothing of it")
    _warn(lw, call, f"{why}: left out, as OpenSCAD leaves it out")
    return True


def color_value(lw: Any, call: CSGCall, value: Any) -> Any:
    """``color``'s value with numbers outside [0, 1] clamped (warned); OpenSCAD's unset colour
    ``[-1, -1, -1, 1]`` (and any negative red, green or blue it stands for) is returned as None."""
    if not isinstance(value, list) or not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value):
        return value
    if value[:3] == [-1.0, -1.0, -1.0]:
        return None  # OpenSCAD's export of an unset colour (an unknown name, undef)
    if all(0.0 <= v <= 1.0 for v in value):
        return value
    clamped = [min(max(float(v), 0.0), 1.0) for v in value]
    _warn(lw, call, f"colour {value} has numbers outside [0, 1]: clamped to {clamped}, as OpenSCAD's display does")
    return clamped


def _load_triangles(path: Path) -> tuple[Any, Any]:
    import trimesh

    loaded: Any = trimesh.load(str(path), force="mesh", process=True)  # vertices merged, as read_mesh reads them
    return loaded.vertices, loaded.faces


def mesh(lw: Any, call: CSGCall, build: Any, *args: Any) -> Any:
    """``build(*args)`` (:func:`~isocsg.kinds.mesh_io.polygon_mesh` of a ``polyhedron``,
    :func:`~isocsg.kinds.mesh_io.read_mesh` of an ``import``); where its only fault is faces wound
    the wrong way (OpenSCAD still exports such a mesh), the same faces turned to one outward
    orientation (:func:`~isocsg.kinds.mesh_io.reoriented`), warned. Other faults raise, naming the node."""
    from ..csg import Union
    from ..errors import InvalidGeometryError
    from ..kinds.mesh_io import bodies, polygon_mesh, polygon_triangles, read_mesh, reoriented

    try:
        return build(*args)
    except InvalidGeometryError as exc:
        wound = "not consistently oriented" in str(exc) or "wind inwards" in str(exc)
        if not wound or build not in (polygon_mesh, read_mesh):
            raise lw.fail(call, str(exc)) from None
        first = exc
    try:
        V, F = (args[0], polygon_triangles(*args)) if build is polygon_mesh else _load_triangles(args[0])
        solid: Any
        try:
            solid = reoriented(V, F)
        except InvalidGeometryError:
            parts = bodies(F)  # bodies touching along edges: each one reoriented, united
            if len(parts) < 2:
                raise
            solid = Union(*[reoriented(V, p) for p in parts])
    except InvalidGeometryError as exc:
        raise lw.fail(call, f"{first}; turning its faces to one orientation does not help: {exc}") from None
    _warn(lw, call, f"faces wound inconsistently ({str(first).split(': ', 1)[-1][:80]}...): "
                    "turned to one outward orientation")
    return solid


def affine_row(lw: Any, call: CSGCall, row: Any) -> list[float]:
    """The last row of a ``multmatrix``, which OpenSCAD ignores (its transforms are affine):
    ``[0, 0, 0, 1]``, warned."""
    _warn(lw, call, f"the last row {[float(x) for x in row]} is not [0, 0, 0, 1]: ignored, as OpenSCAD's "
                    "affine transforms ignore it")
    return [0.0, 0.0, 0.0, 1.0]
