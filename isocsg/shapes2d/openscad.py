"""OpenSCAD's 2D nodes, as a ``.csg`` file writes them, mapped onto 2D shapes.

:func:`from_openscad` takes one node: its name, its named arguments as Python
values (numbers, booleans, strings, lists; ``undef`` as ``None``) and its
children already converted, and returns the 2D shape. It is what an OpenSCAD
reader calls for the 2D subtree under a ``linear_extrude``; it never parses.

``$fn``, ``$fa`` and ``$fs``: a ``circle`` stays the exact disc unless ``$fn``
is explicit (then it is OpenSCAD's regular polygon, see :func:`~isocsg.shapes2d.circle`);
``text`` flattens its curves with OpenSCAD's own number of chords per curve,
``max(fragments(size) / 8 + 1, 2)`` (:func:`text_segments`), so that its glyph
polygons are OpenSCAD's.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from ..errors import InvalidGeometryError, UnsupportedOpenSCADError
from .constructors import circle, polygon, square
from .offset import offset
from .shape import EMPTY, Shape2D, difference2d, intersection2d, union2d
from .text import text

__all__ = ["from_openscad", "fragments", "text_segments", "NODES_2D"]

#: The node names :func:`from_openscad` knows.
NODES_2D = (
    "square", "circle", "polygon", "text", "offset", "union", "group", "difference", "intersection",
    "multmatrix", "translate", "rotate", "scale", "mirror", "color", "render",
)

GRID_FINE = 0.00000095367431640625  # OpenSCAD's GRID_FINE


def fragments(r: float, fn: float = 0.0, fs: float = 2.0, fa: float = 12.0) -> int:
    """OpenSCAD's ``Calc::get_fragments_from_r``: the number of segments of a full circle of radius r.

    Examples
    --------
    >>> fragments(10), fragments(10, fn=6), fragments(1)
    (30, 6, 5)
    """
    if r < GRID_FINE:
        return 3
    if fn > 0:
        return int(fn) if fn >= 3 else 3
    return int(math.ceil(max(min(360.0 / fa, r * 2 * math.pi / fs), 5)))


def text_segments(size: float, fn: float = 0.0, fs: float = 2.0, fa: float = 12.0) -> int:
    """OpenSCAD's chords per glyph curve: ``max(fragments(size) / 8 + 1, 2)`` (integer division).

    >>> text_segments(10)
    4
    """
    return max(fragments(size, fn, fs, fa) // 8 + 1, 2)


def _num(args: dict[str, Any], key: str, default: float) -> float:
    v = args.get(key, default)
    return default if v is None else v


def _matrix(name: str, args: dict[str, Any]) -> Any:
    m = np.asarray(args.get("m", args.get("matrix")), dtype=np.float64)
    if m.shape not in ((4, 4), (3, 4)):
        raise InvalidGeometryError(f"{name}.m must be a 4x4 matrix, got shape {m.shape}")
    if np.any(m[:2, 2] != 0) or np.any(m[2, :2] != 0):
        raise InvalidGeometryError(
            f"{name}.m must keep 2D shapes in the xy plane (no x/y-z mixing), got {m[:3].tolist()}"
        )
    return [[m[0, 0], m[0, 1], m[0, 3]], [m[1, 0], m[1, 1], m[1, 3]]]


def _leaf(name: str, args: dict[str, Any], legacy: bool) -> Shape2D:
    fn = _num(args, "$fn", 0.0)
    if name == "square":
        return square(args.get("size", 1.0), bool(args.get("center", False)))
    if name == "circle":
        r = args.get("r")
        d = args.get("d") if r is None else None
        return circle(r, d, fn=fn if fn and fn > 0 else None)
    if name == "polygon":
        return polygon(args["points"], args.get("paths"))
    size = _num(args, "size", 10.0)
    segments = text_segments(size, fn, _num(args, "$fs", 2.0), _num(args, "$fa", 12.0))
    return text(
        str(args.get("text", "")),
        size,
        args.get("font") or None,
        args.get("halign") or "left",
        args.get("valign") or "baseline",
        _num(args, "spacing", 1.0),
        segments=segments,
        legacy_metrics=legacy,
    )


def from_openscad(
    name: str, args: dict[str, Any], children: Sequence[Shape2D] = (), *, legacy_text_metrics: bool = False
) -> Shape2D:
    """The 2D shape of one OpenSCAD node (see the module notes).

    Parameters
    ----------
    name : str
        One of :data:`NODES_2D`.
    args : dict
        Named arguments, e.g. ``{"size": [2, 1], "center": False}``; ``undef`` as ``None``.
    children : sequence of Shape2D
        The node's children, converted.
    legacy_text_metrics : bool, default False
        Lay ``text`` out as OpenSCAD 2021.01 does (see :func:`~isocsg.shapes2d.text`).

    Raises
    ------
    UnsupportedOpenSCADError
        For another node (``hull``, ``minkowski``, ``projection``, ``import``...).
    InvalidGeometryError
        On malformed arguments, naming the field.

    Examples
    --------
    >>> s = from_openscad("difference", {}, [from_openscad("square", {"size": [4, 4], "center": True}),
    ...                                      from_openscad("circle", {"r": 1, "$fn": 0})])
    >>> round(s.area, 12)
    12.858407346410
    >>> len(from_openscad("circle", {"r": 1, "$fn": 6}).vertices)
    6
    """
    kids = [c for c in children if c is not EMPTY]
    if name in ("square", "circle", "polygon", "text"):
        return _leaf(name, args, legacy_text_metrics)
    if name in ("union", "group", "color", "render"):
        return union2d(*kids) if kids else EMPTY
    if name == "difference":
        return difference2d(*kids) if children and children[0] is not EMPTY else EMPTY
    if name == "intersection":
        return intersection2d(*children) if children else EMPTY
    body = union2d(*kids) if kids else EMPTY
    if name == "offset":
        if args.get("r") is not None:
            return offset(body, args["r"])
        return offset(body, delta=_num(args, "delta", 1.0), chamfer=bool(args.get("chamfer", False)))
    if name == "multmatrix":
        return body.transform(_matrix(name, args))
    if name == "translate":
        v = list(args.get("v", [0, 0]))
        return body.translate(v[:2])
    if name == "rotate":
        return body.rotate(args.get("a", 0))
    if name == "scale":
        v = args.get("v", 1)
        return body.scale(v[:2] if isinstance(v, (list, tuple)) else v)
    if name == "mirror":
        return body.mirror(list(args.get("v", [1, 0]))[:2])
    raise UnsupportedOpenSCADError(f"{name}() of 2D shapes is not supported", node=name)
