"""OpenSCAD's 2D subtrees (under ``linear_extrude``) as :mod:`isocsg.shapes2d` shapes, and
OpenSCAD's own polygonal solids for an explicit small ``$fn``.

- :func:`shape_of` converts the children of a node into one 2D shape with an explicit stack:
  ``square``, ``circle``, ``polygon`` (non-convex, holes), ``text``, ``offset`` (``r``,
  ``delta``, ``chamfer``), the 2D Booleans, ``multmatrix``/``translate``/``rotate``/``scale``/
  ``mirror``, ``color``, ``render``, and ``hull`` of polygons and circles (exactly: the discs
  and the polygon of the hull's tangent points). ``%`` and ``*`` children are left out, 3D objects are ignored with
  OpenSCAD's warning, other nodes are unsupported (named).
- :func:`extrude` is ``linear_extrude`` with ``center``, ``scale`` (uniform, or per axis: circles
  are then OpenSCAD's own polygons, from ``$fn``, ``$fs``, ``$fa``), ``twist`` and ``slices``
  (by default OpenSCAD 2021.01's count from ``$fn``, ``$fs``, ``$fa``: :mod:`isocsg.shapes2d.twist`).
- :func:`polygonal_sides` says when ``$fn`` asks for OpenSCAD's polygonal circle
  (``0 < $fn <= FN_MAX``); :func:`cylinder_points` and :func:`sphere_points` are the vertices
  of OpenSCAD's polygonal cylinder and sphere (2021.01's ``primitives.cc``: ``n`` points at
  ``360 i / n`` degrees; a sphere has ``(n + 1) / 2`` rings at the polar angles
  ``180 (i + 0.5) / rings``).
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidGeometryError, InvalidParameterError
from .lenient import dropped
from .parser import CSGCall

# The lowering context (lowering._Lowerer) that calls these functions; typed loosely so that this
# module, which lowering imports, does not import it back.
_Lowerer = Any

__all__ = ["FN_MAX", "MixedDimensionsWarning", "shape_of", "extrude", "polygonal_sides", "cylinder_points",
           "sphere_points"]

#: The largest explicit ``$fn`` read as OpenSCAD's polygon (a hexagonal nut trap is ``$fn = 6``);
#: above it, and without ``$fn``, circles, cylinders and spheres are the exact round solids. At
#: ``$fn = 64`` the polygon's area is 0.16 % below the disc's.
FN_MAX = 64


class MixedDimensionsWarning(UserWarning):
    """A 2D object beside 3D ones (or a 3D object in a 2D operation): OpenSCAD ignores it, and so does isocsg."""


#: Positional parameters of the 2D nodes, as OpenSCAD declares them.
_POSITIONAL: dict[str, tuple[str, ...]] = {
    "square": ("size", "center"), "circle": ("r", "d"), "polygon": ("points", "paths", "convexity"),
    "text": ("text", "size", "font", "halign", "valign", "spacing"), "offset": ("r", "delta", "chamfer"),
    "multmatrix": ("m",), "translate": ("v",), "rotate": ("a", "v"), "scale": ("v",), "mirror": ("v",),
}
_DIM3 = {"cube", "sphere", "cylinder", "polyhedron", "linear_extrude", "rotate_extrude", "surface"}
_PASS = {"union", "group", "color", "render", "hull"}


def polygonal_sides(call: CSGCall) -> int | None:
    """OpenSCAD's number of sides when ``$fn`` is explicit and at most :data:`FN_MAX`, else None."""
    fn = call.kwargs.get("$fn", 0)
    if isinstance(fn, bool) or not isinstance(fn, (int, float)) or not math.isfinite(fn) or not 0 < fn <= FN_MAX:
        return None
    return max(int(fn), 3)


def _ring(n: int) -> NDArray[np.float64]:
    phi = 2.0 * math.pi * np.arange(n) / n
    return np.column_stack([np.cos(phi), np.sin(phi)])


def cylinder_points(n: int, r1: float, r2: float, z0: float, z1: float) -> NDArray[np.float64]:
    """Vertices of OpenSCAD's ``cylinder`` of ``n`` sides: radius r1 at z0, r2 at z1 (a zero radius: the apex)."""
    ring = _ring(n)
    rows = []
    for r, z in ((r1, z0), (r2, z1)):
        if r > 0:
            rows.append(np.column_stack([ring * r, np.full(n, z)]))
        else:
            rows.append(np.array([[0.0, 0.0, z]]))
    return np.vstack(rows)


def sphere_points(n: int, r: float) -> NDArray[np.float64]:
    """Vertices of OpenSCAD's ``sphere`` of ``n`` fragments: ``(n + 1) // 2`` rings of n points."""
    rings = (n + 1) // 2
    ring = _ring(n)
    rows = []
    for i in range(rings):
        phi = math.pi * (i + 0.5) / rings
        rows.append(np.column_stack([ring * (r * math.sin(phi)), np.full(n, r * math.cos(phi))]))
    return np.vstack(rows)


def _named(lw: _Lowerer, call: CSGCall) -> dict[str, Any]:
    """The node's arguments by name (positional ones named as OpenSCAD declares them)."""
    args = dict(call.kwargs)
    for name, value in zip(_POSITIONAL.get(call.name, ()), call.args, strict=False):
        args.setdefault(name, value)
    return args


def _empty_leaf(name: str, args: dict[str, Any]) -> bool:
    """A leaf that OpenSCAD draws as nothing (zero size, zero radius, too few points)."""
    def num(v: Any) -> float:
        return float(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else 1.0

    if name == "square":
        size = args.get("size", 1.0)
        return any(num(s) <= 0 for s in (size if isinstance(size, list) else [size]))
    if name == "circle":
        r = args.get("r")
        return (num(r) if r is not None else num(args.get("d", 2.0)) / 2) <= 0
    if name == "polygon":
        pts = args.get("points")
        return not isinstance(pts, list) or len(pts) < 3
    return False


def _disc_hull(centres: NDArray[np.float64], radii: NDArray[np.float64]) -> Any:
    """The exact hull of discs (:func:`isocsg.shapes2d.hull2d.disc_hull`)."""
    from ..shapes2d.hull2d import disc_hull

    return disc_hull(centres, radii)


def _hull2d(lw: _Lowerer, call: CSGCall, body: Any) -> Any:
    """``hull()`` of 2D shapes: polygons and circles exactly (:func:`_disc_hull`); ellipses are refused."""
    from ..shapes2d import EMPTY, Circle, ConvexPolygon
    from ..shapes2d.shape import iter_leaves

    if body is EMPTY:
        return EMPTY
    corners, centres, radii = [], [], []
    for leaf in iter_leaves(body):
        if isinstance(leaf, ConvexPolygon):
            corners.append(leaf.array)
        elif isinstance(leaf, Circle):
            centres.append(leaf.center)
            radii.append(leaf.radius)
        else:
            lw.unsupported(call, "a 2D hull of ellipses is not supported")
            return None
    import shapely

    points = np.zeros((0, 2))
    if corners:
        hull = shapely.convex_hull(shapely.multipoints(np.vstack(corners)))
        points = shapely.get_coordinates(hull)  # its corners (or a segment's ends, or a point)
    if not centres:
        if hull.geom_type != "Polygon" or hull.area <= 0:
            return EMPTY
        from ..shapes2d import polygon

        return polygon(np.asarray(hull.exterior.coords)[:-1].tolist())
    c = np.vstack([np.array(centres, dtype=np.float64), points])
    r = np.concatenate([np.array(radii, dtype=np.float64), np.zeros(len(points))])
    return _disc_hull(c, r)


def drawing_path(lw: _Lowerer, call: CSGCall) -> Path:
    """The file an ``import`` names, relative to the model's own folder (as OpenSCAD resolves it)."""
    args = _named(lw, call)
    name = args.get("file")
    if not isinstance(name, str) or not name:
        raise lw.fail(call, f"import needs a file name, got {name!r}")
    path = Path(name)
    if not path.is_absolute() and lw.source:
        path = Path(lw.source).parent / path
    return path


def import_drawing(lw: _Lowerer, call: CSGCall) -> Any:
    """``import("drawing.dxf", layer, origin, scale)`` or ``import("drawing.svg", dpi, center)`` in
    2D: the drawing's region as OpenSCAD reads it (:func:`isocsg.shapes2d.drawings.import_dxf`,
    :func:`isocsg.shapes2d.svg.import_svg`); other 2D formats are refused by name."""
    from ..shapes2d.drawings import import_dxf

    path = drawing_path(lw, call)
    args = _named(lw, call)
    if path.suffix.lower() == ".svg":
        from ..shapes2d.svg import import_svg

        dpi = args.get("dpi", 72.0)
        center = args.get("center", False)
        try:
            return import_svg(path, dpi=dpi if isinstance(dpi, (int, float)) and dpi >= 0.001 else 72.0,
                              center=center is True)
        except InvalidGeometryError as exc:
            raise lw.fail(call, str(exc)) from None
    if path.suffix.lower() != ".dxf":
        lw.unsupported(call, f"2D drawings in {path.suffix or 'unnamed'} files are not read (DXF and SVG are)")
        return None
    origin = args.get("origin", [0, 0])
    scale = args.get("scale", 1.0)
    if isinstance(scale, list) and scale:
        scale = scale[0]  # linear_extrude(file = ...) reads its drawing at its own scale's x (OpenSCAD 2021.01)
    try:
        return import_dxf(
            path, layer=args.get("layer") or None, origin=(float(origin[0]), float(origin[1])),
            scale=float(scale), fn=float(args.get("$fn", 0) or 0), fs=float(args.get("$fs", 2)),
            fa=float(args.get("$fa", 12)))
    except (InvalidGeometryError, InvalidParameterError, TypeError, ValueError, IndexError) as exc:
        raise lw.fail(call, str(exc)) from None


def _openscad_sides(call: CSGCall, args: dict[str, Any]) -> int:
    """OpenSCAD's number of sides of a ``circle`` node (``Calc::get_fragments_from_r``)."""
    from ..shapes2d import fragments

    def num(key: str, default: float) -> float:
        v = call.kwargs.get(key, default)
        return float(v) if isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) else default

    r = args.get("r")
    if not isinstance(r, (int, float)) or isinstance(r, bool):
        d = args.get("d", 2.0)
        r = d / 2 if isinstance(d, (int, float)) and not isinstance(d, bool) else 1.0
    return fragments(float(r), num("$fn", 0.0), max(num("$fs", 2.0), 0.01), max(num("$fa", 12.0), 0.01))


def _node(lw: _Lowerer, call: CSGCall, kids: list[Any], polygonal: bool = False) -> Any:
    """The shape of one 2D node from its children's shapes (None: skipped)."""
    from ..shapes2d import EMPTY, from_openscad, union2d

    name = call.name
    if name == "import":
        return import_drawing(lw, call)
    if name == "hull":
        return _hull2d(lw, call, union2d(*kids) if kids else EMPTY)
    if name == "resize":
        from .resize import resize_shape

        return resize_shape(lw, call, union2d(*kids) if kids else EMPTY)
    args = _named(lw, call)
    if _empty_leaf(name, args):
        return EMPTY
    if name == "circle" and polygonal_sides(call) is None:
        args["$fn"] = _openscad_sides(call, args) if polygonal else 0  # the exact disc (a large $fn too)
    if name == "translate" and isinstance(args.get("v"), list):
        args["v"] = list(args["v"])[:2]
    if name == "rotate" and "v" in args:
        v = args["v"]
        if not (isinstance(v, list) and len(v) == 3 and v[0] == 0 and v[1] == 0 and v[2] != 0):
            raise lw.fail(call, f"a rotation of 2D shapes must turn about the z axis, got v = {v!r}")
        if v[2] < 0 and isinstance(args.get("a"), (int, float)):
            args["a"] = -args["a"]
    if name == "mirror" and isinstance(args.get("v"), list) and not any(args["v"][:2]):
        return union2d(*kids) if kids else EMPTY  # mirror([0, 0, 0]) or about z: the shape itself
    if name == "scale" and isinstance(args.get("v"), list) and any(s == 0 for s in args["v"][:2]):
        return EMPTY  # flattened to a line: no area
    if name in ("difference", "intersection", "multmatrix", "translate", "rotate", "scale", "mirror") and not kids:
        return EMPTY  # nothing to combine or to move (a 3D child ignored in 2D, a background one)
    try:
        return from_openscad(name, args, kids)
    except InvalidGeometryError as exc:
        raise lw.fail(call, str(exc)) from None


def project(lw: _Lowerer, call: CSGCall) -> Any:
    """``projection(cut)``: the node's 3D children lowered to one solid
    (:meth:`~isocsg.openscad.lowering._Lowerer.solid_of`), projected onto the xy plane exactly
    (:func:`isocsg.shapes2d.projection.projection`); None when skipped."""
    from ..errors import NotExactError
    from ..shapes2d import EMPTY
    from ..shapes2d.projection import projection

    cut = lw.boolean(call, "cut", call.kwargs.get("cut", False))
    solid = lw.solid_of(call)
    if solid is None:
        return EMPTY  # no 3D child (a 2D one is ignored, as OpenSCAD does): nothing to project
    try:
        return projection(solid, cut=cut)
    except NotExactError as exc:
        reason = str(exc).removeprefix("projection: ")
        if cut:
            lw.unsupported(call, reason)
            return None
    except InvalidGeometryError as exc:
        raise lw.fail(call, str(exc)) from None
    from .fallback import polygonal_projection  # what OpenSCAD computes: its polyhedron's shadow

    return polygonal_projection(lw, call, reason)


def _kept(lw: _Lowerer, call: CSGCall) -> list[CSGCall]:
    """The children that count in 2D: ``%``/``*`` ones are left out, 3D ones ignored with a warning."""
    from ..shapes2d.openscad import NODES_2D

    out = []
    for c in call.children:
        if "%" in c.modifiers or "*" in c.modifiers:
            continue
        if c.name in _DIM3:
            lw.note(c, "a 3D object in a 2D operation is ignored (as OpenSCAD does)")
            warnings.warn(MixedDimensionsWarning(
                f"{lw.where(c)}ignoring the 3D object {c.name}() in a 2D operation, as OpenSCAD does"), stacklevel=2)
            continue
        if c.name == "minkowski":
            out.append(c)  # summed exactly (isocsg.openscad.sum2d)
            continue
        if c.name not in NODES_2D and c.name not in _PASS and c.name not in ("import", "projection", "resize"):
            lw.unsupported(c, lw.reason(c.name, "2D"))
            continue
        out.append(c)
    return out


def shape_of(lw: _Lowerer, call: CSGCall, polygonal: bool = False) -> Any:
    """The union of the 2D shapes of ``call``'s children (``EMPTY`` when there are none); with
    ``polygonal``, circles are OpenSCAD's polygons (from ``$fn``, ``$fs``, ``$fa``)."""
    from ..shapes2d import EMPTY, union2d

    stack: list[tuple[CSGCall, list[CSGCall], list[Any]]] = [(call, _kept(lw, call), [])]
    while True:
        node, kids, done = stack[-1]
        if len(done) < len(kids):
            child = kids[len(done)]
            if dropped(lw, child):  # drawn as nothing by OpenSCAD too (warned)
                done.append(EMPTY)
            elif child.name == "projection":  # 3D children: lowered as solids, then projected
                done.append(project(lw, child))
            elif child.name == "minkowski":
                from .sum2d import minkowski_shape

                done.append(minkowski_shape(lw, child, shape_of, polygonal))
            else:
                stack.append((child, _kept(lw, child), []))
            continue
        stack.pop()
        shapes = [s for s in done if s is not None]  # skipped children are absent
        if not stack:
            real = [s for s in shapes if s is not EMPTY]
            return union2d(*real) if real else EMPTY
        if node.name == "intersection" and any(s is EMPTY for s in shapes):
            value = EMPTY
        elif node.name == "difference" and shapes and shapes[0] is EMPTY:
            value = EMPTY
        else:
            value = _node(lw, node, [s for s in shapes if s is not EMPTY], polygonal)
        stack[-1][2].append(value)


def _as_boxes(solid: Any) -> Any:
    """The extruded tree with its axis-aligned rectangles' prisms as the exact boxes they are
    (an explicit stack; nodes are rebuilt only where a leaf changed)."""
    from ..csg import CSGNode
    from ..csg.tree import distinct_postorder

    done: dict[int, Any] = {}
    for s in distinct_postorder(solid):
        if not isinstance(s, CSGNode):
            done[id(s)] = _as_box(s)
            continue
        kids = [done[id(c)] for c in s.children]
        same = all(k is c for k, c in zip(kids, s.children, strict=True))
        done[id(s)] = s if same else type(s)(tuple(kids))
    return done[id(solid)]


def _as_box(solid: Any) -> Any:
    """An extruded axis-aligned rectangle as the exact :class:`~isocsg.Box` it is
    (:meth:`~isocsg.kinds.base.Primitive.simplest`)."""
    from ..kinds import Primitive

    return solid.simplest() if isinstance(solid, Primitive) else solid


def extrude(lw: _Lowerer, call: CSGCall) -> Any:
    """The solid of a ``linear_extrude`` node (None: empty or skipped)."""
    from ..shapes2d import EMPTY, linear_extrude

    twist = lw.number(call, "twist", call.kwargs.get("twist", 0.0) or 0.0)
    h = lw.number(call, "height", lw.arg(call, "height", 0, 100.0))
    center = lw.boolean(call, "center", call.kwargs.get("center", False))
    scale = call.kwargs.get("scale", 1.0)
    scale_v = lw.vector(call, "scale", 1.0 if scale is None else scale, 2)
    slices = call.kwargs.get("slices")
    n = lw.number(call, "slices", slices) if slices is not None else 0.0
    details = {k: lw.number(call, k, call.kwargs.get(k, d)) for k, d in (("$fn", 0.0), ("$fs", 2.0), ("$fa", 12.0))}
    if h <= 0:
        return None
    # The old form names its drawing itself: linear_extrude(file = "x.dxf", layer = ...). A per-axis
    # scale of a disc has no exact isocsg form: OpenSCAD's own polygonal circles then.
    polygonal = scale_v[0] != scale_v[1] or lw.faceted
    shape = import_drawing(lw, call) if "file" in call.kwargs else shape_of(lw, call, polygonal=polygonal)
    if shape is None or shape is EMPTY:
        return None
    s: Any = float(scale_v[0]) if scale_v[0] == scale_v[1] else scale_v.tolist()
    try:
        solid = linear_extrude(
            shape, h, center=center, scale=s, twist=twist,
            slices=int(n) if n >= 1 else None,  # OpenSCAD reads slices < 1 as absent
            fn=max(details["$fn"], 0.0), fs=max(details["$fs"], 0.01), fa=max(details["$fa"], 0.01))
        return _as_boxes(solid)
    except InvalidGeometryError as exc:
        if "turn per slice is too large" in str(exc):
            from .fallback import polygonal_twist  # OpenSCAD's own polygon stack

            polygons = shape_of(lw, call, polygonal=True) if "file" not in call.kwargs else shape
            return polygonal_twist(lw, call, polygons, (-h / 2, h / 2) if center else (0.0, h), twist,
                                   (float(scale_v[0]), float(scale_v[1])), int(n) if n >= 1 else None,
                                   (max(details["$fn"], 0.0), max(details["$fs"], 0.01), max(details["$fa"], 0.01)),
                                   str(exc).removeprefix("linear_extrude.slices: "))
        if "scale" in str(exc) or "twist" in str(exc) or "slices" in str(exc):
            lw.unsupported(call, str(exc))
            return None
        raise lw.fail(call, str(exc)) from None
