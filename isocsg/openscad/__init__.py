"""OpenSCAD models in and out.

- :func:`load_openscad` reads a ``.csg`` file (OpenSCAD's flattened export) or
  a ``.scad`` file (through the ``openscad`` program) as an exact isocsg solid;
- :func:`save_openscad` writes a solid as OpenSCAD source.

Modules: :mod:`.parser` (the ``.csg`` text), :mod:`.lowering` (nodes to
solids), :mod:`.writer` (solids to text), :mod:`.program` (running ``openscad``).
"""

from __future__ import annotations

import os
import warnings
from pathlib import Path

from ..errors import MissingDependencyError, OpenSCADError
from ..kinds import Solid
from .flat import FN_MAX, MixedDimensionsWarning
from .lenient import OpenSCADLenientWarning
from .lowering import UNSUPPORTED_NODES, LoweredModel, lower
from .parser import MAX_CSG_TEXT, CSGCall, parse_csg
from .program import _INSTALL, export_mesh, find_openscad, scad_to_csg
from .writer import dumps_openscad, save_openscad

__all__ = [
    "load_openscad",
    "loads_openscad",
    "read_openscad",
    "save_openscad",
    "dumps_openscad",
    "OpenSCADSkipWarning",
    "OpenSCADPolygonalWarning",
    "OpenSCADLenientWarning",
    "LoweredModel",
    "CSGCall",
    "parse_csg",
    "lower",
    "scad_to_csg",
    "export_mesh",
    "find_openscad",
    "UNSUPPORTED_NODES",
    "FN_MAX",
    "PlainSubsetWarning",
    "MixedDimensionsWarning",
]


class OpenSCADSkipWarning(UserWarning):
    """Issued by :func:`load_openscad` with ``skip_unsupported=True`` when nodes were skipped.

    The message lists the counts (``skipped 2 unsupported OpenSCAD nodes: 1 hull,
    1 minkowski``); ``skipped`` holds them as a dict.
    """

    def __init__(self, message: str, skipped: dict[str, int]) -> None:
        super().__init__(message)
        self.skipped = skipped


class PlainSubsetWarning(UserWarning):
    """A ``.scad`` file read without the ``openscad`` program, as the plain ``.csg`` subset."""


def _read_text(p: Path) -> str:
    if not p.is_file():
        raise OpenSCADError(f"{p}: not a regular file")
    if p.stat().st_size > MAX_CSG_TEXT:
        raise OpenSCADError(f"{p}: larger than {MAX_CSG_TEXT} bytes")
    data = p.read_bytes()
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise OpenSCADError(
            f"{p}: not a UTF-8 text file (byte 0x{data[exc.start]:02x} at offset {exc.start})"
        ) from None


def read_openscad(path: str | os.PathLike[str], *, skip_unsupported: bool = False,
                  polygonal: bool = False) -> LoweredModel:
    """Read an OpenSCAD model: the solid and the counts of skipped nodes.

    Like :func:`load_openscad`, but returns a :class:`LoweredModel`
    (``.solid``, ``.skipped``, ``.polygonal``: the nodes made OpenSCAD's polygonal solid) and
    issues no warning.
    """
    p = Path(path)
    suffix = p.suffix.lower()
    plain = False
    if suffix == ".scad":
        try:
            text = scad_to_csg(p)
        except MissingDependencyError:
            # without the program: the plain subset (constant arguments, no variables, loops or
            # modules), which is the .csg syntax; said once, so the reader knows which
            warnings.warn(PlainSubsetWarning(f"{p}: openscad is not installed: read as the plain .csg subset "
                                             "(constant arguments, no variables, loops or modules)"), stacklevel=3)
            text = _read_text(p)
            plain = True
    elif suffix == ".csg":
        text = _read_text(p)
    else:
        raise OpenSCADError(f"{p}: expected a .scad or .csg file")
    try:
        calls = parse_csg(text, source=str(p))
    except OpenSCADError as exc:
        if suffix == ".scad" and plain:
            raise MissingDependencyError(f"{exc}: beyond the plain subset, {p} needs the openscad program, "
                                         f"which was not found: {_INSTALL}") from None
        raise
    return lower(calls, source=str(p), skip_unsupported=skip_unsupported, polygonal=polygonal)


def load_openscad(path: str | os.PathLike[str], *, skip_unsupported: bool = False, polygonal: bool = False) -> Solid:
    """Read an OpenSCAD model (``.csg``, or ``.scad`` through ``openscad``) as an exact solid.

    ``cube``, ``sphere``, ``cylinder`` and convex ``polyhedron`` become exact
    primitives (round without ``$fn``; an explicit ``$fn`` up to :data:`FN_MAX`
    makes OpenSCAD's own polygonal solid), ``multmatrix``, ``translate``,
    ``rotate``, ``scale`` and ``mirror`` a map applied once per leaf,
    ``union``/``group``/``difference``/``intersection`` the same Booleans,
    ``color`` and ``render`` pass their children through, ``%`` and ``*``
    children are left out, and ``linear_extrude`` (``center``, ``scale``; no
    twist) of any 2D subtree (polygons with holes, ``text``, ``offset``, 2D
    Booleans) becomes the exact extrusion of :mod:`isocsg.shapes2d`. See
    :mod:`isocsg.openscad.lowering` and ``docs/openscad.md`` for the full table.

    Parameters
    ----------
    path : path-like
        A ``.csg`` file, or a ``.scad`` file, which the ``openscad`` program
        converts to ``.csg`` in a temporary directory first.
    skip_unsupported : bool, default False
        Skip nodes without an exact equivalent (``hull``, ``minkowski``,
        ``rotate_extrude``, ...) instead of raising; an
        :class:`OpenSCADSkipWarning` then reports how many of each were
        skipped (:func:`read_openscad` returns the counts instead).
    polygonal : bool, default False
        Opt-in: a ``hull`` or ``minkowski`` node without an exact form (a sphere with a
        cylinder off its axis, a sum with a difference) becomes OpenSCAD's own polygonal
        solid, its children's spheres, cylinders and circles at their ``$fn``/``$fa``/``$fs``
        (:mod:`isocsg.openscad.polygonal`), instead of raising; an
        :class:`OpenSCADPolygonalWarning` lists those nodes (:func:`read_openscad` returns
        them in ``.polygonal``). Such a node's volume is OpenSCAD's, not the exact one.

    Returns
    -------
    Solid

    Raises
    ------
    UnsupportedOpenSCADError
        On an unsupported node, naming it and its line (unless skipped).
    OpenSCADError
        On malformed text (naming the line), a failed ``openscad`` run, or a
        model with nothing left.
    MissingDependencyError
        For a ``.scad`` file when ``openscad`` is not installed.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from isocsg import volume
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "part.csg"
    >>> _ = path.write_text("difference() { cube(size = [2, 2, 1], center = true); "
    ...                     "cylinder(h = 3, r1 = 0.5, r2 = 0.5, center = true); }")
    >>> round(volume(load_openscad(path)), 9) == round(2 * 2 * 1 - 3.141592653589793 * 0.5**2 * 1, 9)
    True
    """
    model = read_openscad(path, skip_unsupported=skip_unsupported, polygonal=polygonal)
    _warn(model)
    return model.solid


def loads_openscad(text: str, *, source: str | None = None, skip_unsupported: bool = False,
                   polygonal: bool = False) -> Solid:
    """Read ``.csg`` text as a solid (see :func:`load_openscad`)."""
    model = lower(parse_csg(text, source=source), source=source, skip_unsupported=skip_unsupported,
                  polygonal=polygonal)
    _warn(model)
    return model.solid


class OpenSCADPolygonalWarning(UserWarning):
    """Issued by :func:`load_openscad` when nodes were made OpenSCAD's polygonal solid (a
    ``projection`` or twisted ``linear_extrude`` without an exact form; with ``polygonal=True`` also
    a ``hull`` or ``minkowski``); ``nodes`` lists them (``"model.csg:12: hull(): ..."``)."""

    def __init__(self, message: str, nodes: tuple[str, ...]) -> None:
        super().__init__(message)
        self.nodes = nodes


def _warn(model: LoweredModel) -> None:
    if model.polygonal:
        n = len(model.polygonal)
        warnings.warn(OpenSCADPolygonalWarning(
            f"{n} node{'s' if n > 1 else ''} without an exact form made OpenSCAD's polygonal solid: "
            + "; ".join(model.polygonal), model.polygonal), stacklevel=3)
    if model.skipped:
        total = sum(model.skipped.values())
        counts = ", ".join(f"{n} {name}" for name, n in sorted(model.skipped.items()))
        noun = "node" if total == 1 else "nodes"
        warnings.warn(OpenSCADSkipWarning(f"skipped {total} unsupported OpenSCAD {noun}: {counts}", model.skipped),
                      stacklevel=3)
