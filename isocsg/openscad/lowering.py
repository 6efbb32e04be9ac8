"""Lowering of parsed OpenSCAD statements to exact isocsg solids.

What each node becomes (``docs/openscad.md`` has the table and the reasons):

- ``cube(size, center)`` -> :class:`~isocsg.Box` (of any aspect); ``sphere(r)`` ->
  :class:`~isocsg.Sphere`; ``cylinder(h, r1, r2, center)`` -> :class:`~isocsg.Truncus` (a
  cylinder, cone or frustum); a convex ``polyhedron(points, faces)`` ->
  :class:`~isocsg.ConvexPolyhedron`, a non-convex one -> :class:`~isocsg.TriangleMesh`;
  ``import(file)`` of an STL, OFF, OBJ, PLY or 3MF mesh (relative to the model file's directory)
  and ``surface(file, center, invert)`` (OpenSCAD's height-map solid) -> a ``TriangleMesh``.
  Without ``$fn``, or with ``$fn`` above :data:`~isocsg.openscad.flat.FN_MAX` (64), spheres,
  cylinders and circles are the exact round solids; an explicit ``$fn`` from 1 to 64 makes
  OpenSCAD's own polygonal solid (a hexagonal prism, a pyramid, OpenSCAD's polyhedral sphere) as
  a ``ConvexPolyhedron`` with OpenSCAD's vertices.
- ``multmatrix(m)``, and the hand-written ``translate``, ``rotate``, ``scale``, ``mirror``: maps
  composed on the way down and applied once per leaf, however deep they nest.
- ``union``, ``group``, ``render``, ``color`` and the ``#`` modifier -> a union; a ``!`` (root)
  node makes its subtree alone the model, without its parents' maps, as OpenSCAD does;
  ``difference`` and ``intersection`` -> the same Boolean. ``%`` (background) and ``*``
  (disabled) children are left out as OpenSCAD leaves them out: they neither empty an
  intersection nor stand first in a difference. A 2D object beside 3D ones is ignored with
  OpenSCAD's warning (:class:`~isocsg.openscad.flat.MixedDimensionsWarning`).
- ``hull`` of polyhedral children (cubes, polyhedra, polygonal spheres and cylinders, under maps
  and groups) -> the :class:`~isocsg.ConvexPolyhedron` of all their corners, exactly; ``hull`` of
  round children and ``minkowski`` -> the exact unions of :mod:`isocsg.csg.hull` (spheres of any
  radii with polytopes, parallel cylinders, ...), or refused naming what stops them.
- ``linear_extrude(height, center, scale)`` of any 2D subtree (:mod:`isocsg.openscad.flat`,
  through :mod:`isocsg.shapes2d`): ``square``, ``circle``, ``polygon`` (non-convex, holes),
  ``text``, ``offset``, 2D Booleans, transforms and hulls of polygons; ``rotate_extrude(angle)``
  of the same subtrees (:mod:`isocsg.openscad.revolve`).

- ``projection(cut)`` in 2D (:func:`isocsg.shapes2d.projection.projection`: exact sections at z = 0,
  exact outlines of unions, through holes and flat-faced trees); ``resize(newsize, auto)`` in 2D
  and 3D (:mod:`isocsg.openscad.resize`, from the exact bounds); 2D ``import`` of DXF and SVG
  drawings.

Nodes without an exact equivalent (the ``hull`` and ``minkowski`` that are not exact, outlines of
differences of curved solids that are not through holes, SVG strokes and unknown modules) raise
:class:`~isocsg.errors.UnsupportedOpenSCADError` naming the node and its
line, or are skipped when ``skip_unsupported=True``: :attr:`LoweredModel.skipped` counts them
and :attr:`LoweredModel.left_out` names each (line and reason). Objects that OpenSCAD itself
renders as nothing (a zero size, a zero radius, a singular matrix) are empty and are dropped
like OpenSCAD drops them.

The walk is iterative (an explicit stack), so nesting depth is bounded by memory.
"""

from __future__ import annotations

import math
import warnings
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any, TypeVar

import numpy as np
from numpy.typing import NDArray

from .._validation import parse_color
from ..csg import Difference, Intersection, Union
from ..errors import InvalidGeometryError, InvalidParameterError, NotExactError, OpenSCADError, UnsupportedOpenSCADError
from ..kinds import Box, ConvexPolyhedron, Cylinder, Solid, Sphere, Truncus
from ..kinds.mesh_io import MESH_SUFFIXES, height_map, polygon_mesh, read_height_map, read_mesh
from ..kinds.polygon_faces import signed_volume
from .amf import read_amf
from .flat import MixedDimensionsWarning, cylinder_points, extrude, polygonal_sides, sphere_points
from .lenient import affine_row, color_value, dropped, mesh
from .parser import CSGCall
from .revolve import revolve

__all__ = ["lower", "LoweredModel", "UNSUPPORTED_NODES"]

_SolidT = TypeVar("_SolidT", bound=Solid)

#: OpenSCAD modules that have no exact isocsg equivalent, with the reason given in errors.
UNSUPPORTED_NODES: dict[str, str] = {
    "roof": "roofs are not supported",
    "fill": "fill is not supported",
}

_UNION_LIKE = {"union", "group", "render", "color"}
_BOOLEANS = _UNION_LIKE | {"difference", "intersection", "hull", "minkowski"}

_LEAVES_3D = {"cube", "sphere", "cylinder", "polyhedron", "import", "surface"}
_LEAVES_2D = {"square", "circle", "polygon"}


#: How far a printed number may be from the value it stands for, relative to the magnitude of
#: the coordinates: OpenSCAD 2021 prints 6 significant digits (half a unit of the 6th: 5e-7),
#: with a factor 2 for the rounding of a face's plane through rounded points.
PRINTED_PRECISION = 1e-6

@dataclass(frozen=True, slots=True, eq=False)  # compared by identity: the solid may be a huge tree
class LoweredModel:
    """The result of lowering: the solid and what was skipped.

    Attributes
    ----------
    solid : Solid
        The model.
    skipped : dict of str to int
        How many nodes of each name were skipped (empty unless
        ``skip_unsupported=True`` met an unsupported node).
    left_out : tuple of str
        One line per node left out of the model, skipped or ignored as OpenSCAD ignores it (a 2D
        object beside 3D ones): ``"model.csg:12: import(): meshes and drawings ..."``.
    leaf_colors : tuple of (r, g, b) or None
        The colour ``color()`` gives each leaf of :attr:`solid` (in ``leaves()`` order; the
        innermost ``color`` wins, as in OpenSCAD), or None; empty when nothing is coloured. Pass
        it to :class:`~isocsg.SceneObject` to draw the model in its colours.
    polygonal : tuple of str
        One line per node made OpenSCAD's own polygonal solid because it has no exact form: a
        ``projection`` or twisted ``linear_extrude`` (:mod:`isocsg.openscad.fallback`), and with
        ``polygonal=True`` a ``hull`` or ``minkowski`` (:mod:`isocsg.openscad.polygonal`):
        ``"model.csg:12: hull(): a hull of Cylinder, Sphere ..."``.
    """

    solid: Solid
    skipped: dict[str, int]
    left_out: tuple[str, ...] = ()
    leaf_colors: tuple[tuple[float, float, float] | None, ...] = ()
    polygonal: tuple[str, ...] = ()


class _Lowerer:
    def __init__(self, source: str | None, skip_unsupported: bool, polygonal: bool = False) -> None:
        self.source = source
        self.skip = skip_unsupported
        self.polygonal = polygonal  # a hull or minkowski without an exact form: OpenSCAD's polygons
        self.faceted = False  # lowering such a node's children: round leaves as OpenSCAD's polygons
        self.polygonal_nodes: list[str] = []
        self.skipped: Counter[str] = Counter()
        self.left_out: list[str] = []
        self.colors: dict[int, tuple[float, float, float]] = {}  # by id() of a leaf
        self.resize_maps: dict[int, NDArray[np.float64] | None] = {}  # the map above each open resize node

    def solid_of(self, call: CSGCall) -> Solid | None:
        """The union of a node's children lowered as 3D objects (for ``projection``), None when empty."""
        value = _run(self, CSGCall("union", children=list(call.children), line=call.line))
        return None if value is _DROP else value  # type: ignore[no-any-return]

    # ------------------------------------------------------------------ errors

    def where(self, call: CSGCall) -> str:
        return f"{self.source}:{call.line}: " if self.source else f"line {call.line}: "

    def fail(self, call: CSGCall, message: str) -> OpenSCADError:
        return OpenSCADError(f"{self.where(call)}{call.name}: {message}", line=call.line, node=call.name)

    def unsupported(self, call: CSGCall, reason: str) -> None:
        """Raise, or count the node as skipped."""
        if self.skip:
            self.skipped[call.name] += 1
            self.note(call, reason)
            return
        raise UnsupportedOpenSCADError(
            f"{self.where(call)}{call.name}() is not supported ({reason}); "
            "load_openscad(..., skip_unsupported=True) skips it",
            line=call.line,
            node=call.name,
        )

    def note(self, call: CSGCall, reason: str) -> None:
        """Record a node left out of the model."""
        self.left_out.append(f"{self.where(call)}{call.name}(): {reason}")

    @staticmethod
    def reason(name: str, dim: str = "3D") -> str:
        if dim == "2D" and name == "minkowski":
            return "a 2D Minkowski sum is not supported (a 3D one is)"
        return UNSUPPORTED_NODES.get(name, f"unknown or unsupported {dim} module")

    # ------------------------------------------------------------------ arguments

    def arg(self, call: CSGCall, name: str, position: int | None, default: Any) -> Any:
        if name in call.kwargs:
            return call.kwargs[name]
        if position is not None and position < len(call.args):
            return call.args[position]
        return default

    def number(self, call: CSGCall, name: str, value: Any) -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise self.fail(call, f"{name} must be a finite number, got {_show(value)}")
        return float(value)

    def boolean(self, call: CSGCall, name: str, value: Any) -> bool:
        if value is None:
            return False
        if not isinstance(value, bool):
            raise self.fail(call, f"{name} must be true or false, got {_show(value)}")
        return value

    def vector(self, call: CSGCall, name: str, value: Any, n: int) -> NDArray[np.float64]:
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            return np.full(n, self.number(call, name, value))
        if not isinstance(value, list) or len(value) != n:
            raise self.fail(call, f"{name} must be a number or a list of {n} numbers, got {_show(value)}")
        return np.array([self.number(call, name, v) for v in value])

    def points(self, call: CSGCall, name: str, value: Any, dim: int) -> NDArray[np.float64]:
        if not isinstance(value, list) or not all(isinstance(p, list) and len(p) == dim for p in value):
            raise self.fail(call, f"{name} must be a list of {dim}D points, got {_show(value)}")
        return np.array([[self.number(call, name, x) for x in p] for p in value], dtype=np.float64).reshape(-1, dim)

    def index_lists(self, call: CSGCall, name: str, value: Any, n_points: int) -> list[list[int]]:
        if not isinstance(value, list) or not all(isinstance(f, list) for f in value):
            raise self.fail(call, f"{name} must be a list of index lists, got {_show(value)}")
        out = []
        for f in value:
            idx = []
            for v in f:
                if isinstance(v, bool) or not isinstance(v, (int, float)) or v != int(v) or not 0 <= v < n_points:
                    raise self.fail(call, f"{name} must hold point indices 0 .. {n_points - 1}, got {_show(v)}")
                idx.append(int(v))
            out.append(idx)
        return out

    def make(self, call: CSGCall, factory: Callable[..., _SolidT], *args: Any) -> _SolidT:
        """Build a value type; its validation error names the node and line."""
        try:
            return factory(*args)
        except InvalidGeometryError as exc:
            raise self.fail(call, str(exc)) from None

    def fragments(self, call: CSGCall, r: float) -> int | None:
        """OpenSCAD's segments for a round leaf of radius ``r`` while :attr:`faceted`, else None."""
        if not self.faceted:
            return None
        from ..shapes2d import fragments

        fn, fs, fa = (self.number(call, k, call.kwargs.get(k, d))
                      for k, d in (("$fn", 0.0), ("$fs", 2.0), ("$fa", 12.0)))
        return fragments(r, max(fn, 0.0), max(fs, 0.01), max(fa, 0.01))

    # ------------------------------------------------------------------ 3D leaves

    def cube(self, call: CSGCall) -> Box | None:
        size = self.vector(call, "size", self.arg(call, "size", 0, 1.0), 3)
        center = self.boolean(call, "center", self.arg(call, "center", 1, False))
        if np.any(size <= 0):
            return None
        c = np.zeros(3) if center else size / 2
        return self.make(call, Box, tuple(c), tuple(size))

    def sphere(self, call: CSGCall) -> Solid | None:
        r = self.arg(call, "r", 0, None)
        if r is None and "d" in call.kwargs:
            r = self.number(call, "d", call.kwargs["d"]) / 2
        r = self.number(call, "r", 1.0 if r is None else r)
        if r <= 0:
            return None
        n = polygonal_sides(call) or self.fragments(call, r)
        if n is not None:  # OpenSCAD's polyhedral sphere
            return self.make(call, ConvexPolyhedron, sphere_points(n, r))
        return self.make(call, Sphere, (0.0, 0.0, 0.0), r)

    def cylinder(self, call: CSGCall) -> Solid | None:
        h = self.number(call, "h", self.arg(call, "h", 0, 1.0))
        r = call.kwargs.get("r")
        if r is None and call.kwargs.get("d") is not None:
            r = self.number(call, "d", call.kwargs["d"]) / 2
        r1 = self.number(call, "r1", call.kwargs.get("r1", 1.0 if r is None else r))
        r2 = self.number(call, "r2", call.kwargs.get("r2", 1.0 if r is None else r))
        if call.kwargs.get("d1") is not None:
            r1 = self.number(call, "d1", call.kwargs["d1"]) / 2
        if call.kwargs.get("d2") is not None:
            r2 = self.number(call, "d2", call.kwargs["d2"]) / 2
        center = self.boolean(call, "center", self.arg(call, "center", None, False))
        if h <= 0 or (r1 <= 0 and r2 <= 0):
            return None
        if r1 < 0 or r2 < 0:
            raise self.fail(call, f"r1 and r2 must be >= 0, got {r1:g} and {r2:g}")
        zc = 0.0 if center else h / 2
        n = polygonal_sides(call) or self.fragments(call, max(r1, r2))
        if n is not None:  # OpenSCAD's prism, pyramid or frustum of n sides
            return self.make(call, ConvexPolyhedron, cylinder_points(n, r1, r2, zc - h / 2, zc + h / 2))
        # OpenSCAD's r1 is at the bottom (z = 0); the truncus' r1 is at center + axis / 2 (the top).
        if r1 == r2:
            return self.make(call, Cylinder, (0.0, 0.0, zc), (0.0, 0.0, h), r1)
        return self.make(call, Truncus, (0.0, 0.0, zc), (0.0, 0.0, h), r2, r1)

    def polyhedron_faces(self, call: CSGCall) -> tuple[NDArray[np.float64], list[list[int]]]:
        pts = self.points(call, "points", self.arg(call, "points", 0, []), 3)
        faces_value = call.kwargs.get("faces", call.kwargs.get("triangles", call.args[1] if len(call.args) > 1 else []))
        return pts, self.index_lists(call, "faces", faces_value, len(pts))

    def polyhedron_points(self, call: CSGCall) -> NDArray[np.float64] | None:
        """The points a ``hull`` takes from a polyhedron: those of its faces (its faces' order
        and convexity do not matter to a hull)."""
        pts, faces = self.polyhedron_faces(call)
        used = sorted({i for f in faces for i in f})
        return pts[used] if used else None

    def polyhedron(self, call: CSGCall) -> Solid | None:
        pts, faces = self.polyhedron_faces(call)
        if len(pts) < 4 or not faces:
            return None
        try:
            hull = ConvexPolyhedron(pts)
        except InvalidGeometryError:
            return None  # flat: no volume, as in OpenSCAD
        # Convex when the faces enclose the hull's volume and every face lies on a hull plane, to the
        # precision of the numbers: OpenSCAD's .csg export prints 6 significant digits, which moves a
        # point of a flat face by up to 5e-7 of its coordinates' magnitude.
        scale = float(np.max(np.ptp(hull.hull_vertices, axis=0)))
        reach = max(scale, float(np.max(np.abs(pts))))
        off = PRINTED_PRECISION * reach
        enclosed = signed_volume(pts, faces)
        used = pts[sorted({i for f in faces for i in f})]
        off_plane = np.abs(used @ hull.face_normals.T - hull.face_offsets).min(axis=1)
        planar = np.all(off_plane <= off + 1e-9 * max(scale, 1.0))
        # a face off its plane by `off` encloses at most `off` x the hull's area (< 6 scale^2) more or less
        if not planar or abs(abs(enclosed) - hull.volume) > 6 * off * scale**2 + 1e-9 * max(hull.volume, scale**3):
            return mesh(self, call, polygon_mesh, pts, faces)  # non-convex: a closed triangle mesh
        return hull

    def model_file(self, call: CSGCall, name: str) -> Path:
        """A file named by the node, relative to the model file's directory (the working directory
        for a model without one)."""
        value = self.arg(call, "file", 0, None)
        if not isinstance(value, str) or not value:
            raise self.fail(call, f"{name} must be a file name, got {_show(value)}")
        p = Path(value)
        if not p.is_absolute() and self.source:
            p = Path(self.source).parent / p
        if not p.is_file():
            raise self.fail(call, f"{name} {value!r} not found (looked for {str(p)!r})")
        return p

    def import_file(self, call: CSGCall) -> Solid | None:
        """``import(file)`` of a mesh (``convexity`` and ``layer`` do not matter to a mesh)."""
        value = self.arg(call, "file", 0, None)
        suffix = Path(value).suffix.lower() if isinstance(value, str) else ""
        if isinstance(value, str) and suffix not in MESH_SUFFIXES + (".amf",):
            self.unsupported(call, f"only 3D meshes ({', '.join(MESH_SUFFIXES)}, .amf) are imported, "
                                   f"not {suffix or value!r}")
            return None
        return mesh(self, call, read_amf if suffix == ".amf" else read_mesh, self.model_file(call, "file"))

    def surface(self, call: CSGCall) -> Solid | None:
        """``surface(file, center, invert)``: OpenSCAD's height-map solid (:func:`~isocsg.kinds.mesh_io.height_map`)."""
        p = self.model_file(call, "file")
        center = self.boolean(call, "center", self.arg(call, "center", 1, False))
        invert = self.boolean(call, "invert", call.kwargs.get("invert", False))
        try:
            heights, base = read_height_map(p, invert=invert)
        except InvalidGeometryError as exc:
            raise self.fail(call, str(exc)) from None
        if heights.shape[0] < 2 or heights.shape[1] < 2:
            return None  # OpenSCAD makes no solid of a single line
        return self.make(call, lambda: height_map(heights, center=center, base=base))


def _show(value: Any, limit: int = 60) -> str:
    """A short repr, built iteratively (nested lists may be deeper than the recursion limit)."""
    out: list[str] = []
    size = 0
    todo: list[Any] = [value]
    while todo and size <= limit:
        v = todo.pop()
        if v is _CLOSE:
            piece = "]"
        elif isinstance(v, list):
            piece = "["
            todo.append(_CLOSE)
            for k, item in enumerate(reversed(v)):
                todo.append(item)
                if k < len(v) - 1:
                    todo.append(_SEP)
        elif v is _SEP:
            piece = ", "
        else:
            piece = repr(v)
        out.append(piece)
        size += len(piece)
    text = "".join(out)
    return text if size <= limit and not todo else text[: limit - 3] + "..."


_SEP, _CLOSE = object(), object()  # markers of the iterative repr


def _transform(lw: _Lowerer, call: CSGCall, solid: Solid, m: NDArray[np.float64]) -> Solid | None:
    """``solid.transform(m)``, its validation errors naming the node."""
    method = getattr(solid, "transform", None)
    if method is None:
        raise UnsupportedOpenSCADError(
            f"{lw.where(call)}{call.name}: this isocsg has no transform() for {type(solid).__name__}",
            line=call.line,
            node=call.name,
        )
    try:
        return method(m)  # type: ignore[no-any-return]
    except InvalidParameterError as exc:  # a map whose image is no isocsg primitive
        lw.unsupported(call, f"its image of {type(solid).__name__} is not an exact isocsg solid: {exc}")
        return None
    except InvalidGeometryError as exc:
        raise lw.fail(call, str(exc)) from None


def _matrix(lw: _Lowerer, call: CSGCall) -> NDArray[np.float64]:
    """The 4 x 4 matrix of a ``multmatrix``, ``translate``, ``rotate``, ``scale`` or ``mirror`` node."""
    if call.name != "multmatrix":
        return _hand_matrix(lw, call)
    value = lw.arg(call, "m", 0, None)
    rows_ok = isinstance(value, list) and all(isinstance(r, list) and len(r) == 4 for r in value)
    if not rows_ok or len(value) not in (3, 4):
        raise lw.fail(call, f"m must be a 4 x 4 (or 3 x 4) matrix, got {_show(value)}")
    m = np.eye(4)
    m[: len(value)] = [[lw.number(call, "m", x) for x in row] for row in value]
    if not np.array_equal(m[3], [0.0, 0.0, 0.0, 1.0]):
        m[3] = affine_row(lw, call, m[3])  # OpenSCAD's transforms are affine: it ignores that row
    return m


def _vec3(lw: _Lowerer, call: CSGCall, name: str, value: Any, pad: float) -> NDArray[np.float64]:
    """A 2- or 3-vector (a number for all three), padded as OpenSCAD pads 2-vectors."""
    if isinstance(value, list) and len(value) == 2:
        value = [*value, pad]
    return lw.vector(call, name, value, 3)


def _hand_matrix(lw: _Lowerer, call: CSGCall) -> NDArray[np.float64]:
    """The matrices of hand-written transforms, as OpenSCAD builds them."""
    from ..kinds.affine import axis_angle_matrix, mirror_matrix, rotation_matrix

    name = call.name
    m = np.eye(4)
    if name == "translate":
        m[:3, 3] = _vec3(lw, call, "v", lw.arg(call, "v", 0, [0, 0, 0]), 0.0)
    elif name == "scale":
        m[:3, :3] = np.diag(_vec3(lw, call, "v", lw.arg(call, "v", 0, [1, 1, 1]), 1.0))
    elif name == "mirror":
        v = _vec3(lw, call, "v", lw.arg(call, "v", 0, [1, 0, 0]), 0.0)
        if np.any(v != 0):
            m = mirror_matrix(v)
    else:  # rotate(a) about z, rotate([ax, ay, az]), rotate(a, v) about the axis v
        a = lw.arg(call, "a", 0, 0.0)
        v = lw.arg(call, "v", 1, None)
        if isinstance(a, list):
            m = rotation_matrix(_vec3(lw, call, "a", a, 0.0))
        elif v is not None:
            axis = _vec3(lw, call, "v", v, 0.0)
            m = axis_angle_matrix(lw.number(call, "a", a), axis if np.any(axis != 0) else [0.0, 0.0, 1.0])
        else:
            m = rotation_matrix([0.0, 0.0, lw.number(call, "a", a)])
    return m


def _singular(m: NDArray[np.float64]) -> bool:
    """A map that flattens space to a plane or a line (no volume, as in OpenSCAD)."""
    return bool(abs(np.linalg.det(m[:3, :3])) <= 1e-15 * max(1.0, float(np.abs(m[:3, :3]).max()) ** 3))


def _combine(name: str, parts: list[Solid | None]) -> Solid | None:
    """The Boolean ``name`` of the children's solids (None is empty)."""
    if name == "difference":
        if not parts or parts[0] is None:
            return None
        rest = [p for p in parts[1:] if p is not None]
        return Difference(parts[0], *rest) if rest else parts[0]
    if name == "intersection":
        if not parts or any(p is None for p in parts):
            return None
        return Intersection(*parts) if len(parts) > 1 else parts[0]  # type: ignore[arg-type]
    solids = [p for p in parts if p is not None]
    if not solids:
        return None
    return Union(*solids) if len(solids) > 1 else solids[0]


def lower(calls: list[CSGCall], *, source: str | None = None, skip_unsupported: bool = False,
          polygonal: bool = False) -> LoweredModel:
    """Lower parsed ``.csg`` statements to one isocsg solid.

    Parameters
    ----------
    calls : list of CSGCall
        The top-level statements (see :func:`~isocsg.openscad.parser.parse_csg`);
        their union is the model.
    source : str, optional
        Name that starts every error message.
    skip_unsupported : bool, default False
        Skip unsupported nodes (counted in :attr:`LoweredModel.skipped`)
        instead of raising.
    polygonal : bool, default False
        Make a ``hull`` or ``minkowski`` without an exact form OpenSCAD's own polygonal solid
        (:mod:`isocsg.openscad.polygonal`; listed in :attr:`LoweredModel.polygonal`) instead of
        refusing it.

    Returns
    -------
    LoweredModel

    Raises
    ------
    UnsupportedOpenSCADError
        On an unsupported node (unless skipped), naming the node and its line.
    OpenSCADError
        On malformed arguments, or when nothing of the model is left.
    """
    lw = _Lowerer(source, skip_unsupported, polygonal)
    root = CSGCall("union", children=_root_modified(calls) or list(calls), line=1)
    result = _run(lw, root)
    if result is None or result is _DROP:
        what = f" (skipped: {_counts(lw.skipped)})" if lw.skipped else ""
        raise OpenSCADError(f"{source or 'model'}: the model is empty: nothing of it has a volume{what}")
    return LoweredModel(result, dict(lw.skipped), tuple(lw.left_out), _leaf_colors(lw, result),
                        tuple(lw.polygonal_nodes))


def _run(lw: _Lowerer, root: CSGCall, m0: NDArray[np.float64] | None = None) -> Any:
    """The solid of ``root`` (a union of its children; None or ``_DROP`` when nothing is left),
    under the map ``m0`` when given."""
    # Frames: (call, the map accumulated from the root or None, results of the children so far).
    # Maps compose on the way down and are applied once per leaf, however deep they nest.
    stack: list[tuple[CSGCall, NDArray[np.float64] | None, list[Any]]] = [(root, m0, [])]
    result: Any = None
    while stack:
        call, m, done = stack[-1]
        if len(done) < len(call.children):
            child = call.children[len(done)]
            value, child_m, descend = _enter(lw, child, m)
            if descend:
                stack.append((child, child_m, []))
            else:
                done.append(value)
            continue
        stack.pop()
        value = _leave(lw, call, m, done)
        if stack:
            stack[-1][2].append(value)
        else:
            result = value
    return result


def _color(lw: _Lowerer, call: CSGCall, solid: Any) -> None:
    """Give the leaves of a ``color()`` node's solid its colour, unless an inner one gave them theirs."""
    if not isinstance(solid, Solid):
        return
    value = color_value(lw, call, lw.arg(call, "c", 0, None))  # clamped to [0, 1], as OpenSCAD draws it
    if value is None:
        return  # OpenSCAD exports an unset colour (an unknown name, undef) as [-1, -1, -1, 1]: no colour
    try:
        rgb = parse_color(value, name="color")
    except InvalidParameterError as exc:
        raise lw.fail(call, str(exc)) from None
    from ..csg.tree import leaves

    for leaf in leaves(solid):
        lw.colors.setdefault(id(leaf), rgb)


def _leaf_colors(lw: _Lowerer, solid: Solid) -> tuple[tuple[float, float, float] | None, ...]:
    if not lw.colors:
        return ()
    from ..csg.tree import leaves

    return tuple(lw.colors.get(id(leaf)) for leaf in leaves(solid))


def _root_modified(calls: list[CSGCall]) -> list[CSGCall] | None:
    """The first ``!`` (root) node in file order, alone: OpenSCAD then renders only its subtree,
    without its parents' maps (as its own ``.csg`` export shows)."""
    todo = list(reversed(calls))
    while todo:
        call = todo.pop()
        if "!" in call.modifiers:
            modifiers = call.modifiers.replace("!", "")
            return [CSGCall(call.name, call.args, call.kwargs, call.children, call.line, modifiers)]
        todo.extend(reversed(call.children))
    return None


def _counts(skipped: Counter[str]) -> str:
    return ", ".join(f"{n} {name}" for name, n in sorted(skipped.items()))


#: A child left out as OpenSCAD leaves it out (``%``, ``*``, a 2D object beside 3D ones): unlike
#: an empty child (None), it does not empty an intersection nor stand first in a difference.
_DROP: Any = object()
_TRANSFORMS = {"multmatrix", "translate", "rotate", "scale", "mirror"}
_DIM2 = {"square", "circle", "polygon", "text", "offset", "projection"}


def _placed(lw: _Lowerer, call: CSGCall, solid: Solid | None, m: NDArray[np.float64] | None) -> Solid | None:
    """A leaf's solid under the accumulated map."""
    if solid is None or m is None:
        return solid
    return _transform(lw, call, solid, m)


def _revolved(lw: _Lowerer, call: CSGCall, m: NDArray[np.float64] | None) -> Solid | None:
    """A ``rotate_extrude`` under its map; with ``polygonal``, where the exact solid is refused (an
    ellipse off the axis, a torus under a non-uniform scale), OpenSCAD's faceted one."""
    if not lw.polygonal or lw.faceted:
        return _placed(lw, call, revolve(lw, call), m)
    skip, lw.skip = lw.skip, False
    try:
        return _placed(lw, call, revolve(lw, call), m)
    except OpenSCADError as exc:
        reason = str(exc).removeprefix(lw.where(call)).split("; load_openscad(")[0]
    finally:
        lw.skip = skip
    lw.faceted = True
    try:
        solid = _placed(lw, call, revolve(lw, call), m)
    finally:
        lw.faceted = False
    lw.polygonal_nodes.append(f"{lw.where(call)}rotate_extrude(): {reason}")
    return solid


def _drawing_file(lw: _Lowerer, call: CSGCall) -> bool:
    """An ``import`` of a 2D drawing (DXF, SVG): a 2D object."""
    value = lw.arg(call, "file", 0, None)
    return isinstance(value, str) and Path(value).suffix.lower() in (".dxf", ".svg")


def _enter(lw: _Lowerer, call: CSGCall, m: NDArray[np.float64] | None) -> tuple[Any, NDArray[np.float64] | None, bool]:
    """Start a node: ``(value, map for its children, descend)``; a leaf's value is final at once."""
    if "%" in call.modifiers or "*" in call.modifiers:
        return _DROP, m, False  # background and disabled objects are not part of the model
    name = call.name
    if name in _DIM2 or (name == "import" and _drawing_file(lw, call)):
        lw.note(call, "a 2D object beside 3D ones is ignored (as OpenSCAD does)")
        warnings.warn(MixedDimensionsWarning(
            f"{lw.where(call)}ignoring the 2D object {name}() beside 3D objects, as OpenSCAD does"), stacklevel=4)
        return _DROP, m, False
    if dropped(lw, call):
        return None, m, False  # drawn as nothing by OpenSCAD too (warned)
    if name in UNSUPPORTED_NODES:
        lw.unsupported(call, UNSUPPORTED_NODES[name])
        return None, m, False
    if name == "hull":
        pts = _hull_points(lw, call)
        if pts is not _NOT_POINTS:
            if pts is not None and m is not None:
                pts = pts @ m[:3, :3].T + m[:3, 3]  # type: ignore[operator]
            return _hull_of(pts), None, False  # type: ignore[arg-type]
    if name in _BOOLEANS:
        return None, m, True
    if name == "resize":  # its children in its own frame: the map above applies to the resized solid
        lw.resize_maps[id(call)] = m
        return None, None, True
    if name in _TRANSFORMS:
        local = _matrix(lw, call)
        if _singular(local):
            return None, m, False  # flattened to a plane or a line: no volume, as in OpenSCAD
        if np.array_equal(local, np.eye(4)):
            return None, m, True
        return None, local if m is None else m @ local, True
    if name == "linear_extrude":
        return _placed(lw, call, extrude(lw, call), m), m, False
    if name == "rotate_extrude":
        return _revolved(lw, call, m), m, False
    if name in _LEAVES_3D:
        return _placed(lw, call, getattr(lw, "import_file" if name == "import" else name)(call), m), m, False
    lw.unsupported(call, "unknown module")
    return None, m, False


def _leave(lw: _Lowerer, call: CSGCall, m: NDArray[np.float64] | None, parts: list[Any]) -> Any:
    """Finish a node from its children's solids."""
    kept = [p for p in parts if p is not _DROP]
    if parts and not kept:
        return _DROP  # only left-out children (2D ones beside 3D, background): left out too
    name = call.name
    if name in ("difference", "intersection"):
        return _combine(name, kept)
    if name == "hull":
        return _hull(lw, call, m, kept)
    if name == "minkowski":
        return _minkowski(lw, call, m, kept)
    if name == "resize":
        from .resize import resize_solid

        return _placed(lw, call, resize_solid(lw, call, _combine("union", kept)), lw.resize_maps.pop(id(call)))
    combined = _combine("union", kept)
    if name == "color":
        _color(lw, call, combined)
    return combined


_NOT_POINTS = object()  # a hull's subtree that is not only maps, groups, cubes and polyhedra
_HULL_GROUPS = _UNION_LIKE | {"multmatrix", "translate", "rotate", "scale", "mirror"}


def _hull_points(lw: _Lowerer, call: CSGCall) -> NDArray[np.float64] | None | object:
    """The corners of a ``hull``'s children when they are cubes and polyhedra under maps and
    groups (what the writer's exact polyhedra are): mapped as point arrays, each map applied in
    turn from the innermost as ``transform`` would, without building a solid per node. None when
    nothing has a volume; ``_NOT_POINTS`` for any other subtree (the general walk takes it)."""

    def kept(c: CSGCall) -> list[CSGCall]:
        return [k for k in c.children if "%" not in k.modifiers and "*" not in k.modifiers]

    stack: list[tuple[CSGCall, list[CSGCall], list[NDArray[np.float64] | None]]] = [(call, kept(call), [])]
    while stack:
        node, kids, got = stack[-1]
        if len(got) < len(kids):
            child = kids[len(got)]
            if child.name in _HULL_GROUPS:
                if child.name in _TRANSFORMS:
                    _matrix(lw, child)  # malformed matrices fail here, naming their line
                stack.append((child, kept(child), []))
            elif child.name == "cube":
                box = lw.cube(child)
                got.append(None if box is None else np.asarray(box.corners, dtype=np.float64))
            elif child.name == "polyhedron":
                got.append(lw.polyhedron_points(child))
            elif child.name in ("sphere", "cylinder") and polygonal_sides(child) is not None:
                solid = getattr(lw, child.name)(child)  # OpenSCAD's polygonal solid: its corners
                got.append(None if solid is None else np.asarray(solid.hull_vertices, dtype=np.float64))
            else:
                return _NOT_POINTS
            continue
        stack.pop()
        present = [g for g in got if g is not None]
        pts = np.vstack(present) if present else None
        if node.name in _TRANSFORMS and pts is not None:
            m = _matrix(lw, node)
            if abs(np.linalg.det(m[:3, :3])) <= 1e-15 * max(1.0, float(np.abs(m[:3, :3]).max()) ** 3):
                pts = None  # flattened: no volume, as in OpenSCAD
            elif not np.array_equal(m, np.eye(4)):
                pts = pts @ m[:3, :3].T + m[:3, 3]
        if not stack:
            return pts
        stack[-1][2].append(pts)
    return None  # pragma: no cover - the loop returns at the root


def _hull_of(pts: NDArray[np.float64] | None) -> Solid | None:
    if pts is None:
        return None
    try:
        hull = ConvexPolyhedron(pts)
    except InvalidGeometryError:
        return None  # flat: no volume, as in OpenSCAD
    return ConvexPolyhedron(hull.hull_vertices)  # its vertices alone: interior corners are not kept


def _hull(lw: _Lowerer, call: CSGCall, m: NDArray[np.float64] | None, parts: list[Solid | None]) -> Solid | None:
    """``hull()`` of the children's solids, exactly (:func:`~isocsg.csg.hull.hull_pieces`); the
    maps on the children are affine, and the hull of their images is the image of their hull."""
    from ..csg.hull import hull_pieces

    return _exactly(lw, call, hull_pieces, [p for p in parts if p is not None], m)


def _minkowski(lw: _Lowerer, call: CSGCall, m: NDArray[np.float64] | None, parts: list[Solid | None]) -> Solid | None:
    """``minkowski()`` of the children's solids, exactly (:func:`~isocsg.csg.hull.minkowski_pieces`).
    Each child carries the whole map ``x -> A x + t``; the sum of k images is the image of the sum
    shifted by ``(k - 1) t``, taken back."""
    from ..csg.hull import minkowski_pieces

    solids = [p for p in parts if p is not None]
    if len(solids) < 2:
        return solids[0] if solids else None
    result = _exactly(lw, call, minkowski_pieces, solids, m)
    if result is None or m is None or not np.any(m[:3, 3]):
        return result
    return result.translate(-(len(solids) - 1) * m[:3, 3])


def _lower_child(lw: _Lowerer, child: CSGCall, m: NDArray[np.float64] | None) -> Solid | None:
    value = _run(lw, CSGCall("union", children=[child], line=child.line), m)
    return None if value is _DROP else value  # type: ignore[no-any-return]


def _exactly(lw: _Lowerer, call: CSGCall, build: Any, solids: list[Solid],
             m: NDArray[np.float64] | None) -> Solid | None:
    """The union of ``build(*solids)``'s pieces; None when flat (no volume, as in OpenSCAD).
    Without an exact form: refused, or OpenSCAD's polygonal solid when asked for."""
    if not solids:
        return None
    try:
        pieces = build(*solids)
    except NotExactError as exc:
        reason = str(exc).removeprefix(f"{call.name}: ")
        if lw.polygonal and not lw.faceted:
            from .polygonal import polygonal_node

            return polygonal_node(lw, call, m, reason, lambda child, mm: _lower_child(lw, child, mm))
        lw.unsupported(call, reason)
        return None
    except InvalidGeometryError as exc:
        raise lw.fail(call, str(exc)) from None
    if not pieces:
        return None
    return pieces[0] if len(pieces) == 1 else Union(*pieces)  # type: ignore[no-any-return]
