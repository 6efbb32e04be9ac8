"""Lowering of parsed OpenSCAD statements to exact isocsg solids.

What each node becomes:

- ``cube(size, center)`` -> :class:`~isocsg.Box`; ``sphere(r)`` -> :class:`~isocsg.Sphere`;
  ``cylinder(h, r1, r2, center)`` -> :class:`~isocsg.Truncus` (a cylinder, cone or
  frustum); a convex ``polyhedron(points, faces)`` -> :class:`~isocsg.ConvexPolyhedron`.
  ``$fn``, ``$fa`` and ``$fs`` are ignored: the primitives are exact, not tessellated.
- ``multmatrix(m)`` -> ``solid.transform(m)`` of the union of its children.
- ``union``, ``group``, ``render``, ``color`` and the ``#`` and ``!`` modifiers -> a union;
  ``difference`` and ``intersection`` -> the same Boolean.
- ``hull`` of polyhedral children (cubes, polyhedra, under maps and groups) -> the
  :class:`~isocsg.ConvexPolyhedron` of all their corners, exactly (what the writer's
  exact form of a convex polyhedron is); a hull of a curved or cut child is refused. ``%`` (background) and
  ``*`` (disabled) nodes are not part of the model and are left out.
- ``linear_extrude(height, center)`` without twist or scale, of 2D children
  (``square``, ``circle``, ``polygon``, 2D ``multmatrix`` and Booleans). A straight
  extrusion commutes with union, difference, intersection and affine maps of the
  plane, so each 2D leaf is extruded on its own: a ``circle`` becomes an exact
  cylinder, a ``square`` a box (or a prism when rotated), a ``polygon`` the union
  of convex prisms of :func:`~isocsg.csg.extrude.extrude`.

Nodes without an exact equivalent (``hull`` of curved solids, ``minkowski``, ``rotate_extrude``,
twisted or scaled extrusions, ``text``, ``import``, ``surface``, ``projection``,
``offset``, ``resize``, 2D objects outside an extrusion, non-convex polyhedra and
unknown modules) raise :class:`~isocsg.errors.UnsupportedOpenSCADError` naming the
node and its line, or are skipped and counted when ``skip_unsupported=True``.
Objects that OpenSCAD itself renders as nothing (a zero size, a zero radius, a
singular matrix) are empty and are dropped like OpenSCAD drops them.

The walk is iterative (an explicit stack), so nesting depth is bounded by memory.
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..csg import Difference, Intersection, Union
from ..errors import InvalidGeometryError, InvalidParameterError, OpenSCADError, UnsupportedOpenSCADError
from ..kinds import Box, ConvexPolyhedron, Cylinder, Primitive, Solid, Sphere, Truncus
from .parser import CSGCall

__all__ = ["lower", "LoweredModel", "UNSUPPORTED_NODES"]

#: OpenSCAD modules that have no exact isocsg equivalent, with the reason given in errors.
UNSUPPORTED_NODES: dict[str, str] = {
    "minkowski": "Minkowski sums are not exact isocsg solids",
    "rotate_extrude": "surfaces of revolution other than spheres and cones are not isocsg primitives",
    "text": "glyph outlines are not read",
    "import": "meshes and drawings from other files are not read",
    "surface": "height maps are not read",
    "projection": "projections to 2D are not solids",
    "offset": "offset outlines have rounded corners that are not exact prisms",
    "resize": "resize depends on the tessellated bounds",
    "roof": "roofs are not supported",
    "fill": "fill is not supported",
}

_UNION_LIKE = {"union", "group", "render", "color"}
_BOOLEANS = _UNION_LIKE | {"difference", "intersection", "hull"}

#: Why a ``hull`` is refused when a child is not polyhedral.
HULL_OF_CURVED = "a convex hull of curved solids is not an exact isocsg solid"
_LEAVES_3D = {"cube", "sphere", "cylinder", "polyhedron"}
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
    """

    solid: Solid
    skipped: dict[str, int]


@dataclass(slots=True)
class _Extrusion:
    """The 2D context inside a ``linear_extrude``: the z range and the plane's accumulated affine map."""

    z0: float
    z1: float
    affine: NDArray[np.float64]  # 3 x 3, acting on (x, y, 1)


class _Lowerer:
    def __init__(self, source: str | None, skip_unsupported: bool) -> None:
        self.source = source
        self.skip = skip_unsupported
        self.skipped: Counter[str] = Counter()

    # ------------------------------------------------------------------ errors

    def where(self, call: CSGCall) -> str:
        return f"{self.source}:{call.line}: " if self.source else f"line {call.line}: "

    def fail(self, call: CSGCall, message: str) -> OpenSCADError:
        return OpenSCADError(f"{self.where(call)}{call.name}: {message}", line=call.line, node=call.name)

    def unsupported(self, call: CSGCall, reason: str) -> None:
        """Raise, or count the node as skipped."""
        if self.skip:
            self.skipped[call.name] += 1
            return
        raise UnsupportedOpenSCADError(
            f"{self.where(call)}{call.name}() is not supported ({reason}); "
            "load_openscad(..., skip_unsupported=True) skips it",
            line=call.line,
            node=call.name,
        )

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

    def make(self, call: CSGCall, factory: Any, *args: Any) -> Solid:
        """Build a value type; its validation error names the node and line."""
        try:
            return factory(*args)
        except InvalidGeometryError as exc:
            raise self.fail(call, str(exc)) from None

    # ------------------------------------------------------------------ 3D leaves

    def cube(self, call: CSGCall) -> Solid | None:
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
        return self.make(call, Sphere, (0.0, 0.0, 0.0), r) if r > 0 else None

    def cylinder(self, call: CSGCall) -> Solid | None:
        h = self.number(call, "h", self.arg(call, "h", 0, 1.0))
        r = call.kwargs.get("r")
        r1 = self.number(call, "r1", call.kwargs.get("r1", 1.0 if r is None else r))
        r2 = self.number(call, "r2", call.kwargs.get("r2", 1.0 if r is None else r))
        center = self.boolean(call, "center", self.arg(call, "center", None, False))
        if h <= 0 or (r1 <= 0 and r2 <= 0):
            return None
        if r1 < 0 or r2 < 0:
            raise self.fail(call, f"r1 and r2 must be >= 0, got {r1:g} and {r2:g}")
        zc = 0.0 if center else h / 2
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
        enclosed = 0.0
        for f in faces:
            if len(f) < 3:
                continue
            p = pts[f] - pts[0]  # about a point of the solid: no cancellation far from the origin
            enclosed += sum(float(np.dot(p[0], np.cross(p[i], p[i + 1]))) for i in range(1, len(f) - 1)) / 6.0
        used = pts[sorted({i for f in faces for i in f})]
        planar = np.all(np.abs(used @ hull.face_normals.T - hull.face_offsets).min(axis=1) <= off + 1e-9 * max(scale, 1.0))
        # a face off its plane by `off` encloses at most `off` x the hull's area (< 6 scale^2) more or less
        if not planar or abs(abs(enclosed) - hull.volume) > 6 * off * scale**2 + 1e-9 * max(hull.volume, scale**3):
            self.unsupported(call, "a non-convex polyhedron is not an isocsg primitive; split it into convex ones")
            return None
        return hull

    # ------------------------------------------------------------------ 2D leaves

    def square(self, call: CSGCall, ex: _Extrusion) -> Solid | None:
        size = self.vector(call, "size", self.arg(call, "size", 0, 1.0), 2)
        center = self.boolean(call, "center", self.arg(call, "center", 1, False))
        if np.any(size <= 0):
            return None
        lo = -size / 2 if center else np.zeros(2)
        corners = lo + np.array([[0, 0], [1, 0], [1, 1], [0, 1]]) * size
        a = ex.affine
        if abs(a[0, 1]) == 0 and abs(a[1, 0]) == 0:  # axis-aligned: an exact box
            mapped = corners @ a[:2, :2].T + a[:2, 2]
            lo2, hi2 = mapped.min(axis=0), mapped.max(axis=0)
            if np.any(hi2 <= lo2):
                return None
            c = ((lo2 + hi2) / 2).tolist() + [(ex.z0 + ex.z1) / 2]
            s = (hi2 - lo2).tolist() + [ex.z1 - ex.z0]
            return self.make(call, Box, tuple(c), tuple(s))
        return self.prism(call, corners, ex)

    def circle(self, call: CSGCall, ex: _Extrusion) -> Solid | None:
        r = self.arg(call, "r", 0, None)
        if r is None and "d" in call.kwargs:
            r = self.number(call, "d", call.kwargs["d"]) / 2
        r = self.number(call, "r", 1.0 if r is None else r)
        if r <= 0:
            return None
        a = ex.affine
        lin = a[:2, :2]
        h = ex.z1 - ex.z0
        gram = lin.T @ lin
        s2 = (gram[0, 0] + gram[1, 1]) / 2
        if s2 <= 0:
            return None
        zc = (ex.z0 + ex.z1) / 2
        if abs(gram[0, 1]) <= 1e-15 * s2 and abs(gram[0, 0] - gram[1, 1]) <= 1e-15 * s2:  # a similarity
            c = a[:2, 2]
            return self.make(call, Cylinder, (float(c[0]), float(c[1]), zc), (0.0, 0.0, h), r * math.sqrt(s2))
        if abs(np.linalg.det(lin)) <= 1e-15 * s2:
            return None
        m = np.eye(4)
        m[:2, :2] = lin
        m[:2, 3] = a[:2, 2]
        return _transform(self, call, self.make(call, Cylinder, (0.0, 0.0, zc), (0.0, 0.0, h), r), m)

    def polygon(self, call: CSGCall, ex: _Extrusion) -> Solid | None:
        import shapely
        from shapely.geometry import Polygon

        pts = self.points(call, "points", self.arg(call, "points", 0, []), 2)
        paths_value = self.arg(call, "paths", 1, None)
        paths = [list(range(len(pts)))] if paths_value is None else self.index_lists(call, "paths", paths_value, len(pts))
        pts = pts @ ex.affine[:2, :2].T + ex.affine[:2, 2]
        # OpenSCAD fills polygons by the even-odd rule: each path toggles inside and outside.
        area: Any = None
        for path in paths:
            if len(path) < 3:
                continue
            ring = shapely.make_valid(Polygon(pts[path]))
            area = ring if area is None else area.symmetric_difference(ring)
        if area is None:
            return None
        area = shapely.make_valid(area)
        polys = [g for g in shapely.get_parts(area) if g.geom_type in ("Polygon", "MultiPolygon") and g.area > 0]
        if not polys:
            return None
        return self.prism(call, shapely.union_all(polys), ex, transformed=True)

    def prism(self, call: CSGCall, shape: Any, ex: _Extrusion, *, transformed: bool = False) -> Solid | None:
        from shapely.geometry import Polygon

        from ..csg.extrude import prisms

        if not transformed:
            shape = Polygon(np.asarray(shape) @ ex.affine[:2, :2].T + ex.affine[:2, 2])
        if shape.area <= 0:
            return None
        try:
            return prisms(shape, ex.z0, ex.z1)
        except InvalidGeometryError as exc:
            raise self.fail(call, str(exc)) from None

    # ------------------------------------------------------------------ extrusion

    def extrusion(self, call: CSGCall) -> _Extrusion | None:
        """The 2D context of a ``linear_extrude``; None when it is unsupported or empty."""
        if "file" in call.kwargs:
            self.unsupported(call, "extruding an imported drawing is not supported")
            return None
        twist = self.number(call, "twist", call.kwargs.get("twist", 0.0))
        scale = call.kwargs.get("scale", 1.0)
        scale_v = self.vector(call, "scale", scale, 2)
        if twist != 0.0:
            self.unsupported(call, f"a twisted extrusion (twist = {twist:g}) is not a union of prisms")
            return None
        if np.any(scale_v != 1.0):
            self.unsupported(call, f"a scaled extrusion (scale = {_show(scale)}) is not a union of prisms")
            return None
        h = self.number(call, "height", self.arg(call, "height", 0, 100.0))
        center = self.boolean(call, "center", call.kwargs.get("center", False))
        if h <= 0:
            return None
        z0, z1 = (-h / 2, h / 2) if center else (0.0, h)
        return _Extrusion(z0, z1, np.eye(3))


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
    value = lw.arg(call, "m", 0, None)
    if not isinstance(value, list) or len(value) not in (3, 4) or not all(isinstance(r, list) and len(r) == 4 for r in value):
        raise lw.fail(call, f"m must be a 4 x 4 (or 3 x 4) matrix, got {_show(value)}")
    m = np.eye(4)
    m[: len(value)] = [[lw.number(call, "m", x) for x in row] for row in value]
    if not np.array_equal(m[3], [0.0, 0.0, 0.0, 1.0]):
        raise lw.fail(call, f"m must be affine (last row [0, 0, 0, 1]), got {m[3].tolist()}")
    return m


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


def lower(calls: list[CSGCall], *, source: str | None = None, skip_unsupported: bool = False) -> LoweredModel:
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
    lw = _Lowerer(source, skip_unsupported)
    root = CSGCall("union", children=list(calls), line=1)
    # Frames: (call, 2D context or None, results of the children so far).
    stack: list[tuple[CSGCall, _Extrusion | None, list[Solid | None]]] = [(root, None, [])]
    result: Solid | None = None
    while stack:
        call, ex, done = stack[-1]
        if len(done) < len(call.children):
            child = call.children[len(done)]
            value, child_ex, descend = _enter(lw, child, ex)
            if descend:
                stack.append((child, child_ex, []))
            else:
                done.append(value)
            continue
        stack.pop()
        value = _leave(lw, call, ex, done)
        if stack:
            stack[-1][2].append(value)
        else:
            result = value
    if result is None:
        what = f" (skipped: {_counts(lw.skipped)})" if lw.skipped else ""
        raise OpenSCADError(f"{source or 'model'}: the model is empty: nothing of it has a volume{what}")
    return LoweredModel(result, dict(lw.skipped))


def _counts(skipped: Counter[str]) -> str:
    return ", ".join(f"{n} {name}" for name, n in sorted(skipped.items()))


def _enter(lw: _Lowerer, call: CSGCall, ex: _Extrusion | None) -> tuple[Solid | None, _Extrusion | None, bool]:
    """Start a node: ``(value, context, descend)``; a leaf's value is final at once."""
    if "%" in call.modifiers or "*" in call.modifiers:
        return None, ex, False  # background and disabled objects are not part of the model
    name = call.name
    if name in UNSUPPORTED_NODES:
        lw.unsupported(call, UNSUPPORTED_NODES[name])
        return None, ex, False
    if name == "hull" and ex is not None:
        lw.unsupported(call, "a 2D hull is not supported")
        return None, ex, False
    if name == "hull":
        pts = _hull_points(lw, call)
        if pts is not _NOT_POINTS:
            return _hull_of(pts), None, False  # type: ignore[arg-type]
    if name in _BOOLEANS:
        return None, ex, True
    if name == "multmatrix":
        m = _matrix(lw, call)
        if ex is None:
            return None, None, True
        # In the plane: OpenSCAD maps 2D points by the matrix' x and y rows.
        a = np.array([[m[0, 0], m[0, 1], m[0, 3]], [m[1, 0], m[1, 1], m[1, 3]], [0.0, 0.0, 1.0]])
        return None, _Extrusion(ex.z0, ex.z1, ex.affine @ a), True
    if name == "linear_extrude":
        if ex is not None:
            raise lw.fail(call, "linear_extrude inside linear_extrude: its children must be 2D")
        inner = lw.extrusion(call)
        if inner is None:
            return None, None, False
        return None, inner, True
    if name in _LEAVES_3D:
        if ex is not None:
            lw.unsupported(call, "a 3D object inside linear_extrude (OpenSCAD ignores it)")
            return None, ex, False
        return getattr(lw, name)(call), None, False
    if name in _LEAVES_2D:
        if ex is None:
            lw.unsupported(call, "a 2D object outside linear_extrude has no volume")
            return None, None, False
        return getattr(lw, name)(call, ex), ex, False
    if name == "rotate_extrude":  # pragma: no cover - listed in UNSUPPORTED_NODES
        return None, ex, False
    lw.unsupported(call, "unknown module")
    return None, ex, False


def _leave(lw: _Lowerer, call: CSGCall, ex: _Extrusion | None, parts: list[Solid | None]) -> Solid | None:
    """Finish a node from its children's solids."""
    name = call.name
    if name == "multmatrix":
        solid = _combine("union", parts)
        if solid is None or ex is not None:
            return solid  # in the plane the map went to the leaves
        m = _matrix(lw, call)
        if np.array_equal(m, np.eye(4)):
            return solid
        if abs(np.linalg.det(m[:3, :3])) <= 1e-15 * max(1.0, float(np.abs(m[:3, :3]).max()) ** 3):
            return None  # flattened to a plane or a line: no volume, as in OpenSCAD
        return _transform(lw, call, solid, m)
    if name in ("difference", "intersection"):
        return _combine(name, parts)
    if name == "hull":
        return _hull(lw, call, parts)
    return _combine("union", parts)


_NOT_POINTS = object()  # a hull's subtree that is not only maps, groups, cubes and polyhedra
_HULL_GROUPS = _UNION_LIKE | {"multmatrix"}


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
                if child.name == "multmatrix":
                    _matrix(lw, child)  # malformed matrices fail here, naming their line
                stack.append((child, kept(child), []))
            elif child.name == "cube":
                box = lw.cube(child)
                got.append(None if box is None else np.asarray(box.corners, dtype=np.float64))  # type: ignore[union-attr]
            elif child.name == "polyhedron":
                got.append(lw.polyhedron_points(child))
            else:
                return _NOT_POINTS
            continue
        stack.pop()
        present = [g for g in got if g is not None]
        pts = np.vstack(present) if present else None
        if node.name == "multmatrix" and pts is not None:
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


def _hull(lw: _Lowerer, call: CSGCall, parts: list[Solid | None]) -> Solid | None:
    """``hull()`` of polyhedral children (boxes, convex polyhedra, their unions): the convex
    polyhedron of all their corners, exactly; a curved or cut child is refused."""
    corners: list[NDArray[np.float64]] = []
    todo = [p for p in parts if p is not None]
    while todo:
        s = todo.pop()
        if isinstance(s, Union):
            todo.extend(s.children)
        elif isinstance(s, Primitive) and (pts := s.hull_points()) is not None:
            corners.append(pts)
        else:
            what = type(s).__name__.lower()
            lw.unsupported(call, HULL_OF_CURVED if isinstance(s, Primitive) else f"a hull of {'an' if what[0] in 'aeiou' else 'a'} {what} is not supported")
            return None
    return _hull_of(np.vstack(corners) if corners else None)
