"""Scene files: TOML and JSON readers and writers.

A scene file holds four parts (TOML shown; JSON uses the same structure)::

    [camera]                       # required
    eye = [6, -8, 5]               # required
    target = [0, 0, 0]             # required
    up = [0, 0, 1]                 # optional, default [0, 0, 1]
    fov = 40                       # vertical, degrees
    width = 480
    height = 360

    [render]                       # optional
    contours = 64
    mode = "isoluminance"          # or "halftone"
    exposure = 1.0
    interval = 1

    [[lights]]
    kind = "point"                 # point | directional | area | polyhedron
    position = [5, -5, 8]
    intensity = 1.0

    [[objects]]
    material = { ambient = 0.1, kd = 0.8, ks = 0.0, shininess = 20 }
    shape = { difference = [
        { box = { center = [0, 0, 0], size = [2, 2, 2] } },
        { sphere = { center = [1, 1, 1], radius = 0.8 } },
    ] }

Shape nodes are the primitive kinds of :mod:`isocsg.kinds.registry` (``sphere``,
``truncus``, ``cylinder``, ``cone``, ``box`` with an optional ``orientation``,
``polyhedron``, ``ellipsoid``, ``elliptic_truncus``), the Boolean nodes, and
OpenSCAD's transforms around one ``shape``: ``translate {v}``, ``rotate {a, v?}``,
``scale {v}``, ``mirror {v}``, ``multmatrix {m}`` and ``transform {matrix}``::

    shape = { rotate = { a = [0, 0, 30], shape = { box = { center = [1, 0, 0], size = [2, 1, 1] } } } }

Every error is a :class:`~isocsg.errors.SceneFileError` whose message starts
with the file name and the dotted path of the offending field, e.g.
``scene.toml: objects[0].shape.sphere.radius: must be > 0, got -1``.

Only regular files of at most 16 MiB (:data:`MAX_SCENE_FILE_BYTES`) in
UTF-8 are read; the size and the kind of file are checked before reading, so
that a FIFO or a device such as ``/dev/zero`` is refused at once. Shape trees
are read without recursion; the TOML and JSON decoders themselves stop at a
few hundred levels of nesting, which is reported as an error of the file.
"""

from __future__ import annotations

import os
import re
import stat
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any, BinaryIO

from .._validation import MAX_LIGHTS, MAX_SCENE_FILE_BYTES, show
from ..camera import Camera
from ..csg.extrude import extrude_rings
from ..csg.tree import NODE_TYPES, CSGNode
from ..errors import (
    InvalidGeometryError,
    InvalidLightError,
    InvalidParameterError,
    SceneFileError,
)
from ..kinds import affine as _tf
from ..kinds.base import Solid
from ..kinds.registry import kind_named, registered_kinds
from ..lighting.lights import DirectionalLight, Material, PointLight
from .model import RenderSettings, Scene, SceneObject

__all__ = [
    "load_scene",
    "loads_scene",
    "scene_from_dict",
    "builtin_scene",
    "builtin_scene_path",
    "BUILTIN_SCENES",
    "shape_kinds",
    "LIGHT_KINDS",
    "MAX_SCENE_FILE_BYTES",
    "read_scene_file",
    "read_scene_stream",
    "decode_scene_text",
]

#: Names of the scenes shipped in ``isocsg/data`` (``<name>.toml``).
BUILTIN_SCENES = ("demo", "halftone")

# The straight extrusion of a polygon: a union of convex prisms (isocsg.csg.extrude); a node
# of scene files, not a primitive kind.
_EXTRUDE_FIELDS = (("polygon", "height"), ("holes", "center"))


def _primitive_node(kind: str) -> tuple[tuple[tuple[str, ...], tuple[str, ...]], str, Callable[..., Solid]] | None:
    """The fields, class name (the prefix of the value type's own messages) and constructor of a
    primitive node, read from the table of kinds when a file is read (:mod:`isocsg.kinds.registry`):
    a kind registered at any time is read like a built-in one."""
    if kind == "extrude":
        return _EXTRUDE_FIELDS, "extrude", extrude_rings
    k = kind_named(kind)
    if k is None:
        return None
    return (k.required, k.optional), k.cls.__name__, lambda **fields: k.build(fields)


_CSG_TYPES: dict[str, type[CSGNode]] = NODE_TYPES

#: Every node kind accepted in an object's ``shape`` tree.
#: Transform nodes, OpenSCAD's names and parameters, each around one ``shape``:
#: ``translate {v}``, ``rotate {a, v?}`` (Euler angles ``a = [x, y, z]``, or an angle ``a``
#: about the axis ``v``, default z), ``scale {v}`` (a number or per axis), ``mirror {v}``
#: (the plane's normal), ``multmatrix {m}`` and ``transform {matrix}`` (4x4 or 3x4).
_TRANSFORM_FIELDS: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    "translate": (("v", "shape"), ()),
    "rotate": (("a", "shape"), ("v",)),
    "scale": (("v", "shape"), ()),
    "mirror": (("v", "shape"), ()),
    "multmatrix": (("m", "shape"), ()),
    "transform": (("matrix", "shape"), ()),
}


def shape_kinds() -> tuple[str, ...]:
    """Every node kind accepted in an object's ``shape`` tree, as registered now."""
    return tuple(k.name for k in registered_kinds()) + ("extrude",) + tuple(_CSG_TYPES) + tuple(_TRANSFORM_FIELDS)


def __getattr__(name: str) -> Any:
    if name == "SHAPE_KINDS":  # read live: kinds may be registered after import
        return shape_kinds()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

#: Light kinds and their (required, optional) fields.
_LIGHT_FIELDS: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    "point": (("position",), ("intensity",)),
    "directional": (("direction",), ("intensity",)),
    "area": (("vertices",), ("radiance", "flux")),
    "polyhedron": (("vertices",), ("radiance", "flux")),
}
LIGHT_KINDS = tuple(_LIGHT_FIELDS)

_CAMERA_FIELDS = (("eye", "target"), ("up", "fov", "width", "height", "orthographic", "height_m"))
_RENDER_FIELDS = ((), ("contours", "mode", "exposure", "interval"))
_MATERIAL_FIELDS = ((), ("ambient", "kd", "ks", "shininess"))
_OBJECT_FIELDS = (("shape",), ("material", "color", "leaf_colors"))
_TOP_FIELDS = (("camera", "objects"), ("render", "lights"))

_VALUE_ERRORS = (InvalidGeometryError, InvalidLightError, InvalidParameterError)


# ----------------------------------------------------------------------------- helpers


class _Reader:
    """Walks a decoded document; every error it raises names the file and field."""

    def __init__(self, source: str | None) -> None:
        self.source = source

    def fail(self, path: str, message: str) -> SceneFileError:
        where = f"{path}: " if path else ""
        prefix = f"{self.source}: " if self.source else ""
        return SceneFileError(f"{prefix}{where}{message}")

    def table(self, path: str, value: Any, fields: tuple[tuple[str, ...], tuple[str, ...]]) -> Mapping[str, Any]:
        """Check that ``value`` is a table with the required keys and no unknown ones."""
        if not isinstance(value, Mapping):
            raise self.fail(path, f"must be a table, got {_type_name(value)}")
        required, optional = fields
        unknown = [k for k in value if k not in required and k not in optional]
        if unknown:
            expected = ", ".join(required + optional)
            names = ", ".join(repr(k) for k in unknown)
            word = "key" if len(unknown) == 1 else "keys"
            raise self.fail(path, f"unknown {word} {names} (expected {expected})")
        for k in required:
            if k not in value:
                raise self.fail(_join(path, k), "missing required field")
        return value

    def array(self, path: str, value: Any) -> list[Any]:
        if not isinstance(value, list):
            raise self.fail(path, f"must be an array, got {_type_name(value)}")
        return value

    def construct(self, path: str, class_name: str, factory: Callable[..., Any], **kwargs: Any) -> Any:
        """Call a value type's constructor; re-word its error with the field path.

        The value types say ``Sphere.radius must be > 0, got -1``; the scene
        file says ``objects[0].shape.sphere.radius: must be > 0, got -1``.
        """
        try:
            return factory(**kwargs)
        except _VALUE_ERRORS as exc:
            raise self.fail(*_reword(path, class_name, str(exc))) from None
        except (TypeError, ValueError, ArithmeticError) as exc:  # a value that numpy cannot even convert
            raise self.fail(path, str(exc)) from None


def _join(path: str, key: str) -> str:
    return f"{path}.{key}" if path else key


def _type_name(value: Any) -> str:
    if isinstance(value, Mapping):
        return "a table"
    if isinstance(value, list):
        return "an array"
    if isinstance(value, str):
        return f"a string {value!r}"
    if isinstance(value, bool):
        return f"a boolean {str(value).lower()}"
    return f"{type(value).__name__} {show(value)}"


def _reword(path: str, class_name: str, message: str) -> tuple[str, str]:
    """Turn ``Class.field rest`` into ``(path.field, rest)``."""
    m = re.match(rf"^{re.escape(class_name)}\.(\w+(?:\[\d+\])*) (.*)$", message, flags=re.DOTALL)
    if m is None:
        return path, message
    field, rest = m.group(1), m.group(2)
    if f"{class_name}." in rest:  # a message about several fields stays at the node
        return path, message.replace(f"{class_name}.", "")
    return _join(path, field), rest


# ----------------------------------------------------------------------------- readers


def _camera(r: _Reader, value: Any) -> Camera:
    t = r.table("camera", value, _CAMERA_FIELDS)
    return r.construct("camera", "camera", Camera, **dict(t))


def _render(r: _Reader, value: Any) -> RenderSettings:
    t = r.table("render", value, _RENDER_FIELDS)
    if "mode" in t and not isinstance(t["mode"], str):
        raise r.fail("render.mode", f"must be a string, got {_type_name(t['mode'])}")
    return r.construct("render", "render", RenderSettings, **dict(t))


def _light(r: _Reader, path: str, value: Any) -> Any:
    if not isinstance(value, Mapping):
        raise r.fail(path, f"must be a table, got {_type_name(value)}")
    if "kind" not in value:
        raise r.fail(_join(path, "kind"), f"missing required field (one of {', '.join(LIGHT_KINDS)})")
    kind = value["kind"]
    if not isinstance(kind, str) or kind not in _LIGHT_FIELDS:
        raise r.fail(_join(path, "kind"), f"unknown light kind {kind!r} (expected one of {', '.join(LIGHT_KINDS)})")
    required, optional = _LIGHT_FIELDS[kind]
    t = dict(r.table(path, value, (("kind",) + required, optional)))
    del t["kind"]
    if kind == "point":
        return r.construct(path, "PointLight", PointLight, **t)
    if kind == "directional":
        return r.construct(path, "DirectionalLight", DirectionalLight, **t)
    # Area and polyhedron sources live with the shadow code; import them only when used.
    from ..lighting import area as shadow_lights

    cls = shadow_lights.AreaLight if kind == "area" else shadow_lights.PolyhedronLight
    if "flux" in t:  # luminous flux in lumens instead of radiance in cd/m^2
        if "radiance" in t:
            raise r.fail(path, "give radiance (cd/m^2) or flux (lm), not both")
        return r.construct(path, cls.__name__, cls.from_flux, **t)
    return r.construct(path, cls.__name__, cls, **t)


def _material(r: _Reader, path: str, value: Any) -> Material:
    t = r.table(path, value, _MATERIAL_FIELDS)
    return r.construct(path, "Material", Material, **dict(t))


def _node(r: _Reader, path: str, value: Any) -> tuple[str, str, Any]:
    """Check one shape node ``{kind: body}``; returns ``(kind, path.kind, body)``."""
    kinds = ", ".join(shape_kinds())
    if not isinstance(value, Mapping):
        raise r.fail(path, f"a shape node must be a table with one key ({kinds}), got {_type_name(value)}")
    if len(value) != 1:
        keys = ", ".join(show(k, 40) for k in value)
        got = f"{len(value)} ({keys})" if value else "none"
        raise r.fail(path, f"a shape node must have exactly one key ({kinds}), got {got}")
    ((kind, body),) = value.items()
    if not isinstance(kind, str) or kind not in shape_kinds():
        raise r.fail(path, f"unknown shape {show(kind, 40)} (expected one of {kinds})")
    return kind, _join(path, kind), body


def _transform_matrix(r: _Reader, here: str, kind: str, t: Mapping[str, Any]) -> Any:
    """The 4x4 matrix of a transform node; errors name the node's field."""
    field = {
        "translate": "v", "rotate": "a", "scale": "v", "mirror": "v", "multmatrix": "m", "transform": "matrix",
    }[kind]
    if kind == "rotate":
        a = t["a"]
        if isinstance(a, bool) or not isinstance(a, (int, float, list)):
            raise r.fail(_join(here, "a"), f"must be a number or 3 numbers, got {_type_name(a)}")
        if isinstance(a, list) and "v" in t:
            raise r.fail(_join(here, "v"), "an axis goes with a single angle a, not with 3 Euler angles")
    try:
        if kind == "translate":
            m = _tf.translation_matrix(t["v"])
        elif kind == "rotate":
            if isinstance(a, list):
                m = _tf.rotation_matrix(a)
            else:
                if "v" in t:
                    field = "v"
                m = _tf.axis_angle_matrix(a, t.get("v", [0.0, 0.0, 1.0]))
        elif kind == "scale":
            m = _tf.scale_matrix(t["v"])
        elif kind == "mirror":
            m = _tf.mirror_matrix(t["v"])
        else:
            m = _tf.affine_matrix(t[field])
    except _VALUE_ERRORS as exc:
        # "rotate(axis) must ..." / "matrix must ..." -> "<node>.<field>: must ..."
        msg = str(exc)
        mm = re.match(r"^[\w().]+ (must .*)$", msg, flags=re.DOTALL)
        if kind == "rotate" and msg.startswith("rotate(axis)"):
            field = "v"
        raise r.fail(_join(here, field), mm.group(1) if mm else msg) from None
    except (TypeError, ValueError) as exc:
        raise r.fail(_join(here, field), str(exc)) from None
    return m


def _shape(r: _Reader, path: str, value: Any) -> Solid:
    """Build a shape tree depth first with an explicit stack (no recursion).

    Deep trees must not exhaust Python's recursion limit; each stack entry is
    ``(kind, path, operands, children built so far)``.
    """
    stack: list[tuple[str, str, list[Any], list[Solid], Any]] = []
    todo: tuple[str, Any] | None = (path, value)
    while True:
        assert todo is not None
        kind, here, body = _node(r, *todo)
        if kind in _CSG_TYPES:
            operands = r.array(here, body)
            if not operands:
                raise r.fail(here, "needs at least one operand, got none")
            stack.append((kind, here, operands, [], None))
            todo = (f"{here}[0]", operands[0])
            continue
        if kind in _TRANSFORM_FIELDS:
            t = r.table(here, body, _TRANSFORM_FIELDS[kind])
            stack.append((kind, here, [t["shape"]], [], _transform_matrix(r, here, kind, t)))
            todo = (_join(here, "shape"), t["shape"])
            continue
        node = _primitive_node(kind)
        assert node is not None  # _node accepted the kind
        fields, class_name, build = node
        t = r.table(here, body, fields)
        solid: Solid = r.construct(here, class_name, build, **dict(t))
        # Hand the finished solid to its parent; close every parent that is complete.
        while True:
            if not stack:
                return solid
            kind, here, operands, children, matrix = stack[-1]
            children.append(solid)
            if len(children) < len(operands):
                todo = (f"{here}[{len(children)}]", operands[len(children)])
                break
            stack.pop()
            try:
                solid = children[0].transform(matrix) if matrix is not None else _CSG_TYPES[kind](*children)
            except _VALUE_ERRORS as exc:
                raise r.fail(here, str(exc)) from None


def _object(r: _Reader, path: str, value: Any) -> SceneObject:
    t = r.table(path, value, _OBJECT_FIELDS)
    shape = _shape(r, _join(path, "shape"), t["shape"])
    material = _material(r, _join(path, "material"), t["material"]) if "material" in t else Material()
    color = t.get("color")
    leaf_colors: list[Any] = []
    if "leaf_colors" in t:
        # A table from leaf index (as text: TOML keys are strings) to colour; leaves not named keep the object's.
        table = t["leaf_colors"]
        if not isinstance(table, Mapping):
            raise r.fail(_join(path, "leaf_colors"), "must be a table from leaf index to colour")
        for key, c in table.items():
            if not (isinstance(key, str) and key.isdigit()):
                raise r.fail(_join(path, "leaf_colors"), f"keys must be leaf indices 0, 1, ..., got {key!r}")
            k = int(key)
            leaf_colors.extend([None] * (k + 1 - len(leaf_colors)))
            leaf_colors[k] = c
    try:
        return SceneObject(shape, material, color, tuple(leaf_colors))
    except _VALUE_ERRORS as exc:
        raise r.fail(path, str(exc)) from None


def scene_from_dict(data: Mapping[str, Any], *, source: str | os.PathLike[str] | None = None) -> Scene:
    """Build a :class:`~isocsg.scene.Scene` from a decoded scene document.

    Parameters
    ----------
    data : mapping
        The document, as read from TOML or JSON (see the module docstring).
    source : str or path-like, optional
        Name that starts every error message (usually the file name).

    Returns
    -------
    Scene

    Raises
    ------
    SceneFileError
        On unknown keys, missing fields, wrong types, empty operand lists,
        unknown node or light kinds, and every invalid value; the message
        gives the file name and the dotted path of the field.

    Examples
    --------
    >>> doc = {"camera": {"eye": [0, -5, 0], "target": [0, 0, 0]},
    ...        "lights": [{"kind": "point", "position": [0, -5, 5]}],
    ...        "objects": [{"shape": {"sphere": {"center": [0, 0, 0], "radius": 1}}}]}
    >>> scene = scene_from_dict(doc)
    >>> scene.objects[0].shape
    Sphere(center=(0.0, 0.0, 0.0), radius=1.0)
    >>> doc["objects"][0]["shape"]["sphere"]["radius"] = -1
    >>> scene_from_dict(doc, source="scene.toml")
    Traceback (most recent call last):
    ...
    isocsg.errors.SceneFileError: scene.toml: objects[0].shape.sphere.radius: must be > 0, got -1
    """
    r = _Reader(None if source is None else os.fspath(source))
    if not isinstance(data, Mapping):
        raise r.fail("", f"the document must be a table, got {_type_name(data)}")
    top = r.table("", data, _TOP_FIELDS)
    camera = _camera(r, top["camera"])
    render = _render(r, top["render"]) if "render" in top else RenderSettings()
    lights_doc = r.array("lights", top["lights"]) if "lights" in top else []
    if len(lights_doc) > MAX_LIGHTS:  # before building any of them
        raise r.fail("lights", f"must hold at most {MAX_LIGHTS} lights, got {len(lights_doc)}")
    lights = tuple(_light(r, f"lights[{i}]", v) for i, v in enumerate(lights_doc))
    objects_doc = r.array("objects", top["objects"])
    if not objects_doc:
        raise r.fail("objects", "needs at least one object, got none")
    objects = tuple(_object(r, f"objects[{i}]", v) for i, v in enumerate(objects_doc))
    try:
        return Scene(camera, lights, objects, render)
    except _VALUE_ERRORS as exc:
        # "scene.lights must ..." -> "lights: must ..."; "render.contours must ..." likewise
        m = re.match(r"^(?:scene\.)?([\w.\[\]]+) (.*)$", str(exc), flags=re.DOTALL)
        raise (r.fail(m.group(1), m.group(2)) if m else r.fail("", str(exc))) from None


def loads_scene(text: str, *, format: str = "toml", source: str | os.PathLike[str] | None = None) -> Scene:
    """Parse scene text in ``"toml"`` or ``"json"`` format.

    Parameters
    ----------
    text : str
    format : {"toml", "json"}
    source : str or path-like, optional
        Name that starts every error message.

    Returns
    -------
    Scene

    Raises
    ------
    SceneFileError
        On malformed text or an invalid scene (see :func:`scene_from_dict`).

    Examples
    --------
    >>> text = '''
    ... [camera]
    ... eye = [0, -5, 0]
    ... target = [0, 0, 0]
    ... [[objects]]
    ... shape = { box = { center = [0, 0, 0], size = [1, 1, 1] } }
    ... '''
    >>> loads_scene(text).objects[0].shape.size
    (1.0, 1.0, 1.0)
    """
    name = None if source is None else os.fspath(source)
    return scene_from_dict(decode_scene_text(text, format=format, source=name), source=name)


def decode_scene_text(text: str, *, format: str = "toml", source: str | os.PathLike[str] | None = None) -> Any:
    """Decode TOML or JSON text into plain Python values (no scene checks yet).

    Raises
    ------
    SceneFileError
        On malformed text, integers too long to read, or nesting deeper than
        the decoder allows; the message starts with ``source``.

    Examples
    --------
    >>> decode_scene_text('{"a": [1, 2]}', format="json")
    {'a': [1, 2]}
    """
    name = None if source is None else os.fspath(source)
    prefix = f"{name}: " if name else ""
    if not isinstance(text, str):
        raise SceneFileError(f"{prefix}scene text must be a str, got {type(text).__name__}")
    if format not in ("toml", "json"):
        raise SceneFileError(f"{prefix}unknown scene format {show(format)} (expected 'toml' or 'json')")
    label = format.upper()
    import json  # here, as tomllib: a model that reads no scene file does not load them
    import tomllib

    try:
        return tomllib.loads(text) if format == "toml" else json.loads(text)
    except (tomllib.TOMLDecodeError, json.JSONDecodeError) as exc:
        raise SceneFileError(f"{prefix}invalid {label}: {exc}") from None
    except RecursionError:
        raise SceneFileError(f"{prefix}invalid {label}: nested more deeply than the {label} decoder allows") from None
    except ValueError as exc:  # e.g. an integer with more digits than Python converts
        raise SceneFileError(f"{prefix}invalid {label}: {exc}") from None


def read_scene_file(path: str | os.PathLike[str]) -> tuple[str, str]:
    """Read a scene file's text safely; returns ``(text, format)``.

    The extension must be ``.toml`` or ``.json``; the path must name a regular
    file (not a directory, FIFO or device) of at most
    :data:`MAX_SCENE_FILE_BYTES` bytes, checked before any byte is read, and
    the text must be UTF-8 without NUL characters.

    Raises
    ------
    SceneFileError
        Naming the file and what is wrong with it.

    Examples
    --------
    >>> text, fmt = read_scene_file(builtin_scene_path("demo"))
    >>> fmt, "[camera]" in text
    ('toml', True)
    """
    p = Path(path)
    fmt = _format_of(p)
    try:
        st = os.stat(p)
    except OSError as exc:
        raise SceneFileError(f"{p}: cannot read the file: {exc.strerror or exc}") from None
    _check_regular(p, st)
    try:
        # O_NONBLOCK: should the path be swapped for a FIFO after the check, open() must not wait.
        fd = os.open(p, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as exc:
        raise SceneFileError(f"{p}: cannot read the file: {exc.strerror or exc}") from None
    with os.fdopen(fd, "rb") as f:
        _check_regular(p, os.fstat(f.fileno()))
        try:
            data = f.read(MAX_SCENE_FILE_BYTES + 1)
        except OSError as exc:
            raise SceneFileError(f"{p}: cannot read the file: {exc.strerror or exc}") from None
    if len(data) > MAX_SCENE_FILE_BYTES:
        raise SceneFileError(f"{p}: the file is larger than the limit of {MAX_SCENE_FILE_BYTES} bytes")
    return _decode(data, p), fmt


def read_scene_stream(stream: BinaryIO, *, source: str = "<stdin>") -> tuple[str, str]:
    """Read scene text from a binary stream (standard input); returns ``(text, format)``.

    At most :data:`MAX_SCENE_FILE_BYTES` bytes of UTF-8 without NUL
    characters, as for a file. With no file name to tell the format, the
    text is JSON when its first character other than white space is ``{``,
    TOML otherwise.

    Raises
    ------
    SceneFileError
        Naming ``source`` and what is wrong.

    Examples
    --------
    >>> import io
    >>> read_scene_stream(io.BytesIO(b' {"camera": {}}'))
    (' {"camera": {}}', 'json')
    """
    try:
        data = stream.read(MAX_SCENE_FILE_BYTES + 1)
    except OSError as exc:
        raise SceneFileError(f"{source}: cannot read: {exc.strerror or exc}") from None
    if not isinstance(data, bytes):
        raise SceneFileError(f"{source}: expected a binary stream, got {type(data).__name__} from it")
    if len(data) > MAX_SCENE_FILE_BYTES:
        raise SceneFileError(f"{source}: the input is larger than the limit of {MAX_SCENE_FILE_BYTES} bytes")
    text = _decode(data, source)
    return text, "json" if text.lstrip().startswith("{") else "toml"


def _decode(data: bytes, source: object) -> str:
    """UTF-8 text without NUL characters, or a :class:`SceneFileError` naming ``source``."""
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise SceneFileError(
            f"{source}: not a UTF-8 text file (byte 0x{data[exc.start]:02x} "
            f"at offset {exc.start}); scene files are UTF-8 TOML or JSON"
        ) from None
    if "\x00" in text:
        raise SceneFileError(
            f"{source}: not a text file (NUL byte at offset "
            f"{text.index(chr(0))}); scene files are UTF-8 TOML or JSON"
        )
    return text


def _check_regular(p: Path, st: os.stat_result) -> None:
    if stat.S_ISREG(st.st_mode):
        if st.st_size > MAX_SCENE_FILE_BYTES:
            raise SceneFileError(f"{p}: the file has {st.st_size} bytes, more than the limit of {MAX_SCENE_FILE_BYTES}")
        return
    kind = (
        "a directory" if stat.S_ISDIR(st.st_mode)
        else "a FIFO" if stat.S_ISFIFO(st.st_mode)
        else "a device" if stat.S_ISCHR(st.st_mode) or stat.S_ISBLK(st.st_mode)
        else "a socket" if stat.S_ISSOCK(st.st_mode)
        else "not a regular file"
    )
    raise SceneFileError(f"{p}: cannot read the file: it is {kind}, not a regular file")


def _format_of(path: Path) -> str:
    suffix = path.suffix.lower()
    if suffix == ".toml":
        return "toml"
    if suffix == ".json":
        return "json"
    raise SceneFileError(f"{path}: unknown scene file extension {path.suffix!r} (expected .toml or .json)")


def scene_format(path: str | os.PathLike[str]) -> str:
    """``"toml"`` or ``"json"`` from a file name; raises :class:`SceneFileError` otherwise."""
    return _format_of(Path(path))


def load_scene(path: str | os.PathLike[str]) -> Scene:
    """Read a scene file (``.toml`` or ``.json``).

    Parameters
    ----------
    path : str or path-like

    Returns
    -------
    Scene

    Raises
    ------
    SceneFileError
        If the file cannot be read (missing, not a regular file, larger than
        16 MiB, not UTF-8), is not valid TOML/JSON, or does not describe a
        valid scene; the message starts with the file name and the dotted
        path of the field.

    Examples
    --------
    >>> scene = load_scene(builtin_scene_path("demo"))
    >>> scene.render.mode
    'isoluminance'
    """
    p = Path(path)
    text, fmt = read_scene_file(p)
    return loads_scene(text, format=fmt, source=p)


# ----------------------------------------------------------------------------- built-in scenes


def builtin_scene_path(name: str = "demo") -> Path:
    """Path of a scene shipped with isocsg (see :data:`BUILTIN_SCENES`).

    Raises
    ------
    SceneFileError
        On an unknown name.

    Examples
    --------
    >>> builtin_scene_path("demo").name
    'demo.toml'
    """
    if name not in BUILTIN_SCENES:
        raise SceneFileError(f"unknown built-in scene {name!r} (expected one of {', '.join(BUILTIN_SCENES)})")
    from importlib import resources

    return Path(str(resources.files("isocsg").joinpath("data", f"{name}.toml")))


def builtin_scene(name: str = "demo") -> Scene:
    """Load a scene shipped with isocsg.

    Examples
    --------
    >>> builtin_scene("halftone").render.mode
    'halftone'
    """
    return load_scene(builtin_scene_path(name))
