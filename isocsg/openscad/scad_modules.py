"""OpenSCAD 2021.01's built-in modules as its ``.csg`` export writes them, for
:mod:`isocsg.openscad.evaluate`.

Each module reads its arguments as ``primitives.cc``, ``transform.cc`` and ``color.cc`` read
them (positional ones in OpenSCAD's order, defaults, ``d`` for ``r``) and returns the
:class:`~isocsg.openscad.parser.CSGCall` that :func:`~isocsg.openscad.parser.parse_csg` reads
from the export: ``cube(size = [x, y, z], center = ...)``, ``sphere($fn = ..., $fa = ...,
$fs = ..., r = ...)``, a ``multmatrix`` of the matrix OpenSCAD computes for ``translate``,
``rotate``, ``scale`` and ``mirror``, ``color([r, g, b, a])`` in single precision, ... An
argument that OpenSCAD would warn about, and a colour name, raise
:class:`~isocsg.openscad.scad_syntax.Declined`.
"""

from __future__ import annotations

import math
from typing import Any, Protocol

import numpy as np

from .parser import CSGCall
from .scad_colors import COLOR_NAMES
from .scad_syntax import Declined
from .scad_values import Scope, cos_degrees, export_number, export_value, sin_degrees


class _Evaluates(Protocol):
    """What the built-in modules need of the evaluator: expressions and scopes."""

    def expr(self, e: Any, f: Scope) -> Any: ...

    def scope(self, statements: list[Any], f: Scope) -> list[CSGCall]: ...

__all__ = ["builtin_module"]

_F_MINIMUM = 0.01
_SIGNATURES: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    "cube": (("size", "center"), ()),
    "sphere": (("r",), ("d",)),
    "cylinder": (("h", "r1", "r2", "center"), ("r", "d", "d1", "d2")),
    "polyhedron": (("points", "faces", "convexity"), ()),
    "square": (("size", "center"), ()),
    "circle": (("r",), ("d",)),
    "polygon": (("points", "paths", "convexity"), ()),
    "translate": (("v",), ()), "scale": (("v",), ()), "mirror": (("v",), ()),
    "rotate": (("a", "v"), ()), "multmatrix": (("m",), ()), "color": (("c", "alpha"), ()),
    "linear_extrude": (("height",), ("center", "convexity", "twist", "slices", "scale")),
    "rotate_extrude": ((), ("angle", "convexity")),
    "offset": (("r",), ("delta", "chamfer")),
    "union": ((), ()), "difference": ((), ()), "intersection": ((), ()), "hull": ((), ()),
    "minkowski": (("convexity",), ()),
}
_LEAVES = ("cube", "sphere", "cylinder", "polyhedron", "square", "circle", "polygon")


def _arguments(ev: _Evaluates, name: str, args: list[Any], f: Scope) -> tuple[dict[str, Any], dict[str, Any]]:
    positional, optional = _SIGNATURES[name]
    values: dict[str, Any] = {}
    specials: dict[str, Any] = {}
    for i, (arg_name, x) in enumerate(args):
        if arg_name is None:
            # OpenSCAD counts a positional argument after named ones among the positional only
            if i >= len(positional) or any(n is not None for n, _ in args[:i]):
                raise Declined(f"a positional argument of {name} out of place")
            key = positional[i]
        else:
            key = arg_name
        target = specials if key.startswith("$") else values
        if key in target or (target is values and key not in positional + optional):
            raise Declined(f"argument {key} of {name}")
        target[key] = ev.expr(x, f)
    return values, specials


def _positive(v: Any) -> bool:
    return type(v) is float and math.isfinite(v) and v > 0


def _numbers(v: Any, sizes: tuple[int, ...]) -> list[float] | None:
    if isinstance(v, list) and len(v) in sizes and all(type(x) is float and math.isfinite(x) for x in v):
        return list(v)
    return None


def _center(v: Any) -> bool:
    if v is None or type(v) is bool:
        return bool(v)
    raise Declined("center not a boolean")


def _radius(values: dict[str, Any], d: str, r: str) -> float | None:
    """``lookup_radius``: the diameter's half, else the radius, else None."""
    dv, rv = values.get(d), values.get(r)
    for v in (dv, rv):
        if v is not None and type(v) is not float:
            raise Declined(f"{r} or {d} not a number")
    if dv is not None:
        if rv is not None:
            raise Declined(f"both {r} and {d}")
        return float(dv / 2.0)
    return rv  # type: ignore[no-any-return]


def _fragments(frame: Scope) -> dict[str, float]:
    out = {}
    for key in ("$fn", "$fa", "$fs"):
        v = frame.lookup(key)
        if type(v) is not float or not math.isfinite(v) or (key != "$fn" and v < _F_MINIMUM):
            raise Declined(f"{key} not a number or too small")
        out[key] = v
    return out


def _leaf(name: str, values: dict[str, Any], frame: Scope) -> dict[str, Any]:
    """The export's arguments of a primitive, before rounding."""
    if name in ("cube", "square"):
        n = 3 if name == "cube" else 2
        size = values.get("size")
        if size is None:
            dims = [1.0] * n
        elif _positive(size):
            dims = [size] * n
        else:
            dims = _numbers(size, (n,)) or []
            if len(dims) != n or not all(x > 0 for x in dims):
                raise Declined(f"{name} size")
        return {"size": dims, "center": _center(values.get("center"))}
    if name in ("sphere", "circle"):
        r = _radius(values, "d", "r")
        r = 1.0 if r is None else r
        if not _positive(r):
            raise Declined(f"{name} radius")
        return {**_fragments(frame), "r": r}
    if name == "cylinder":
        return _cylinder(values, frame)
    convexity = values.get("convexity")
    if convexity is not None and (type(convexity) is not float or not abs(convexity) < 2**31):
        raise Declined("convexity")
    count = float(max(1, int(convexity or 0.0)))
    if name == "polyhedron":
        points, faces = values.get("points"), values.get("faces")
        if not isinstance(points, list) or not points or any(_numbers(p, (3,)) is None for p in points):
            raise Declined("polyhedron points")
        if not isinstance(faces, list) or not faces or any(_indices(face, len(points)) is None for face in faces):
            raise Declined("polyhedron faces")
        return {"points": points, "faces": faces, "convexity": count}
    points, paths = values.get("points"), values.get("paths")  # polygon
    if not isinstance(points, list) or not points or any(_numbers(p, (2,)) is None for p in points):
        raise Declined("polygon points")
    if paths is not None and (not isinstance(paths, list) or any(_indices(p, len(points)) is None for p in paths)):
        raise Declined("polygon paths")
    return {"points": points, "paths": paths, "convexity": count}


def _indices(v: Any, n: int) -> list[float] | None:
    if isinstance(v, list) and len(v) >= 3 and all(type(i) is float and i == int(i) and 0 <= i < n for i in v):
        return v
    return None


def _cylinder(values: dict[str, Any], frame: Scope) -> dict[str, Any]:
    h = values.get("h")
    h = 1.0 if h is None else h
    r, r1, r2 = _radius(values, "d", "r"), _radius(values, "d1", "r1"), _radius(values, "d2", "r2")
    if r is not None and (r1 is not None or r2 is not None):
        raise Declined("cylinder parameters ambiguous")
    lo = hi = 1.0 if r is None else r
    lo = lo if r1 is None else r1
    hi = hi if r2 is None else r2
    if not _positive(h) or not (math.isfinite(lo) and math.isfinite(hi)) or lo < 0 or hi < 0 or lo == hi == 0:
        raise Declined("cylinder sizes")
    return {**_fragments(frame), "h": h, "r1": lo, "r2": hi, "center": _center(values.get("center"))}


def _vec3(v: Any, default: float, what: str) -> list[float]:
    xs = _numbers(v, (2, 3))
    if xs is None:
        raise Declined(f"{what} not a vector of 2 or 3 numbers")
    return xs if len(xs) == 3 else [*xs, default]


def _rotation(values: dict[str, Any]) -> list[list[float]]:
    a, v = values.get("a"), values.get("v")
    if isinstance(a, list):
        angles = _numbers(a, (0, 1, 2, 3))
        if angles is None or v is not None:
            raise Declined("rotate angles")
        sx, sy, sz, cx, cy, cz = 0.0, 0.0, 0.0, 1.0, 1.0, 1.0
        if len(angles) > 2:
            sz, cz = sin_degrees(angles[2]), cos_degrees(angles[2])
        if len(angles) > 1:
            sy, cy = sin_degrees(angles[1]), cos_degrees(angles[1])
        if len(angles) > 0:
            sx, cx = sin_degrees(angles[0]), cos_degrees(angles[0])
        return [[cy * cz, cz * sx * sy - cx * sz, cx * cz * sy + sx * sz],
                [cy * sz, cx * cz + sx * sy * sz, -cz * sx + cx * sy * sz],
                [-sy, cy * sx, cx * cy]]
    if type(a) is not float or not math.isfinite(a):
        raise Declined("rotate angle")
    x, y, z = [0.0, 0.0, 1.0] if v is None else _vec3(v, 0.0, "rotate axis")
    s, c = sin_degrees(a), cos_degrees(a)
    m = x * x + y * y + z * z
    if not m > 0:
        return [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    k = (1 - c) / m
    cv = [x * k, y * k, z * k]
    n = math.sqrt(m)
    us = [x / n * s, y / n * s, z / n * s]
    return [[cv[0] * x + c, cv[1] * x - us[2], cv[2] * x + us[1]],
            [cv[0] * y + us[2], cv[1] * y + c, cv[2] * y - us[0]],
            [cv[0] * z - us[1], cv[1] * z + us[0], cv[2] * z + c]]


def _matrix(name: str, values: dict[str, Any]) -> list[list[float]]:
    """The 4x4 matrix of a map, as ``transform.cc`` computes it."""
    eye = [[1.0 if i == j else 0.0 for j in range(4)] for i in range(4)]
    if name == "translate":
        t = _vec3(values.get("v"), 0.0, "translate")
        for i in range(3):
            eye[i][3] = t[i]
    elif name == "scale":
        v = values.get("v")
        s = [v] * 3 if type(v) is float else _vec3(v, 1.0, "scale")
        if not all(math.isfinite(x) and x != 0 for x in s):
            raise Declined("scale by zero or not finite")
        for i in range(3):
            eye[i][i] = s[i]
    elif name == "mirror":
        x, y, z = _vec3(values.get("v"), 0.0, "mirror")
        if x != 0.0 or y != 0.0 or z != 0.0:
            a = x * x + y * y + z * z
            eye[:3] = [[1 - 2 * x * x / a, -2 * y * x / a, -2 * z * x / a, 0.0],
                       [-2 * x * y / a, 1 - 2 * y * y / a, -2 * z * y / a, 0.0],
                       [-2 * x * z / a, -2 * y * z / a, 1 - 2 * z * z / a, 0.0]]
    elif name == "rotate":
        for i, row in enumerate(_rotation(values)):
            eye[i][:3] = row
    else:  # multmatrix
        m = values.get("m")
        if not isinstance(m, list) or not 3 <= len(m) <= 4 or any(_numbers(r, (4,)) is None for r in m):
            raise Declined("multmatrix of other than 3 or 4 rows of 4 numbers")
        if len(m) == 4 and m[3] != [0.0, 0.0, 0.0, 1.0]:
            raise Declined("multmatrix with a projective row")
        eye[:3] = [list(r) for r in m[:3]]
    return eye


def _named_color(name: str) -> list[float]:
    """A colour name or ``#rgb``, ``#rgba``, ``#rrggbb``, ``#rrggbbaa`` as ``color.cc`` reads it (floats)."""
    name = name.lower()
    if name in COLOR_NAMES:
        return [float(np.float32(x) / np.float32(255.0)) for x in COLOR_NAMES[name]]
    digits = name[1:]
    if name[:1] != "#" or len(digits) not in (3, 4, 6, 8) or not all(ch in "0123456789abcdef" for ch in digits):
        raise Declined(f"colour {name!r}")
    stride = 1 if len(digits) in (3, 4) else 2
    top = np.float32(15.0 if stride == 1 else 255.0)
    rgba = [float(np.float32(int(digits[i:i + stride], 16)) / top) for i in range(0, len(digits), stride)]
    return [*rgba, 1.0][:4]


def _color(values: dict[str, Any]) -> list[float]:
    c, alpha = values.get("c"), values.get("alpha")
    if type(c) is str:
        rgba = _named_color(c)
    else:
        numbers = _numbers(c, (3, 4))
        if numbers is None:
            raise Declined("color other than a name or a vector of 3 or 4 numbers")
        rgba = [*numbers, 1.0][:4]
    if alpha is not None:
        if type(alpha) is not float:
            raise Declined("color alpha")
        rgba[3] = alpha
    if not all(0 <= x <= 1 for x in rgba):
        raise Declined("color component outside [0, 1]")
    return [float(np.float32(x)) for x in rgba]  # ColorNode keeps floats


def _finite(v: Any, default: float, what: str) -> float:
    if v is None:
        return default
    if type(v) is not float or not math.isfinite(v):
        raise Declined(f"{what} not a finite number")
    return v


def _linear_extrude(values: dict[str, Any], frame: Scope) -> dict[str, Any]:
    """``linear_extrude``'s export (``linearextrude.cc``); a positional height only, no file."""
    height = _finite(values.get("height"), 100.0, "linear_extrude height")
    scale = values.get("scale", 1.0)
    sxy = [scale, scale] if type(scale) is float else _numbers(scale, (2,))
    if sxy is None or not all(math.isfinite(x) and x >= 0 for x in sxy) or height <= 0:
        raise Declined("linear_extrude height or scale")
    slices = int(_finite(values.get("slices"), 0.0, "slices"))
    twist = _finite(values.get("twist"), 0.0, "twist")
    convexity = int(_finite(values.get("convexity"), 0.0, "convexity"))
    out: dict[str, Any] = {"height": export_number(height), "center": _center(values.get("center")),
                           "convexity": float(max(convexity, 1))}
    if twist != 0.0:
        out["twist"] = export_number(twist)
    if slices > 0:
        out["slices"] = float(slices)
    out["scale"] = [export_number(x) for x in sxy]
    if slices <= 0:
        out.update({k: export_number(v) for k, v in _fragments(frame).items()})
    return out


def _rotate_extrude(values: dict[str, Any], frame: Scope) -> dict[str, Any]:
    """``rotate_extrude``'s export (``rotateextrude.cc``, 2021.01: no ``start``)."""
    angle = _finite(values.get("angle"), 360.0, "rotate_extrude angle")
    if angle <= -360 or angle > 360:
        angle = 360.0
    convexity = int(_finite(values.get("convexity"), 0.0, "convexity"))
    return {"angle": export_number(angle), "convexity": float(convexity if convexity > 0 else 2),
            **{k: export_number(v) for k, v in _fragments(frame).items()}}


def _offset(values: dict[str, Any], frame: Scope) -> dict[str, Any]:
    """``offset``'s export (``offset.cc``): ``r`` (round, 1 by default) or ``delta`` and ``chamfer``."""
    r, delta, chamfer = values.get("r"), values.get("delta"), values.get("chamfer")
    if (r is not None and delta is not None) or (chamfer is not None and type(chamfer) is not bool):
        raise Declined("offset arguments")
    fragments = {k: export_number(v) for k, v in _fragments(frame).items()}
    if delta is None:
        return {"r": export_number(_finite(r, 1.0, "offset r")), **fragments}
    return {"delta": export_number(_finite(delta, 1.0, "offset delta")), "chamfer": bool(chamfer), **fragments}


def _printed(key: str, v: Any) -> Any:
    """A primitive's argument as the export prints it: lists of points, faces and paths as
    OpenSCAD values, the node's own numbers through a C++ stream (:func:`export_number`)."""
    if type(v) is bool or v is None:
        return v
    if key in ("points", "faces", "paths"):
        return export_value(v)
    if isinstance(v, list):
        return [export_number(x) for x in v]
    return export_number(v)


def builtin_module(ev: _Evaluates, name: str, args: list[Any], children: list[Any], f: Scope,
                   line: int) -> CSGCall:
    """The export's node of a built-in module call (module docstring)."""
    if name not in _SIGNATURES:
        raise Declined(f"module {name}")
    values, specials = _arguments(ev, name, args, f)
    frame = Scope(f, f, specials)
    if name in _LEAVES:
        if children:
            raise Declined(f"{name} with children")
        kwargs = {k: _printed(k, v) for k, v in _leaf(name, values, frame).items()}
        return CSGCall(name, kwargs=kwargs, line=line)
    out = CSGCall(name, line=line)
    if name in ("translate", "rotate", "scale", "mirror", "multmatrix"):
        out.name = "multmatrix"
        out.args = [[[export_number(x, value=True) for x in row] for row in _matrix(name, values)]]
    elif name == "color":
        out.args = [[export_number(x) for x in _color(values)]]
    elif name == "linear_extrude":
        out.kwargs = _linear_extrude(values, frame)
    elif name == "rotate_extrude":
        out.kwargs = _rotate_extrude(values, frame)
    elif name == "offset":
        out.kwargs = _offset(values, frame)
    elif name == "minkowski":  # cgaladv.cc: an int, 0 unless a number is given (a negative one wraps)
        convexity = _finite(values.get("convexity"), 0.0, "convexity")
        if not 0 <= convexity < 2**31:
            raise Declined("minkowski convexity")
        out.kwargs = {"convexity": float(int(convexity))}
    elif values:
        raise Declined(f"arguments of {name}")
    # OpenSCAD's Boolean modules bind no arguments: their $ arguments do not reach their children
    boolean = name in ("union", "difference", "intersection")
    out.children = ev.scope(children, Scope(f, f) if boolean else frame)
    return out
