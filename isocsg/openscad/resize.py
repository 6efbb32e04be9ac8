"""OpenSCAD's ``resize(newsize, auto)``: a scale about the origin that gives the child's bounding
box the new size, from the child's exact bounds.

OpenSCAD 2021.01 (``PolySet::resize``, ``Polygon2d::resize``, ``CGAL_Nef_polyhedron::resize``)
scales axis ``i`` by ``newsize[i] / size[i]`` where ``newsize[i] > 0`` and keeps it (scale 1)
where it is 0; with ``auto[i]`` true, an axis whose new size is 0 takes the scale of the axis with
the largest new size. OpenSCAD measures its own tessellation (a sphere's polygon is smaller than
the sphere); isocsg measures the exact solid: for polygonal children the two are the same.

Exact bounds: a leaf's own; a union's the union of its parts'; a tree of flat-faced solids the
bounds of its manifold3d Boolean; a 2D tree of polygons and circles those of its exact boundary
(segments and arcs). Other trees (a difference or intersection with curved leaves): the box
of their leaves' boxes under the Booleans, kept when a section a hair inside each face
(``PROBE_RTOL`` of the size) meets the solid; otherwise (a sphere cut flat at the top) the
bounds of a coarse mesh (``MESH_RESOLUTION``) refined by bisection with sections to
``PROBE_RTOL``. A 2D
Boolean of ellipses (not a union) is refused (:class:`~isocsg.errors.NotExactError`).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import NotExactError

__all__ = ["resize_scale", "solid_bounds", "shape_bounds", "resize_solid", "resize_shape", "PROBE_RTOL"]

#: How far inside a candidate face of a box a section probes for the solid, relative to its size.
PROBE_RTOL = 1e-9


def resize_scale(newsize: list[float], auto: list[bool], size: NDArray[np.float64]) -> NDArray[np.float64]:
    """OpenSCAD's per-axis scale of ``resize`` for a child whose bounding box has sizes ``size``.

    Examples
    --------
    >>> resize_scale([20, 0, 0], [True] * 3, np.array([10.0, 5.0, 2.0])).tolist()
    [2.0, 2.0, 2.0]
    >>> resize_scale([20, 0, 0], [False] * 3, np.array([10.0, 5.0, 2.0])).tolist()
    [2.0, 1.0, 1.0]
    """
    n = len(size)
    scale = np.ones(n)
    for i in range(n):
        if newsize[i] > 0 and size[i] > 0:
            scale[i] = newsize[i] / size[i]
    big = max(range(n), key=lambda i: (newsize[i], -i))  # the first of the largest
    auto_scale = scale[big] if newsize[big] > 0 else 1.0
    for i in range(n):
        if auto[i] and not newsize[i] > 0:
            scale[i] = auto_scale
    return scale


def _children(s: Any) -> tuple[Any, ...] | None:
    from ..csg import CSGNode

    return tuple(s.children) if isinstance(s, CSGNode) else None


def solid_bounds(solid: Any) -> NDArray[np.float64]:
    """The exact bounding box ``[[x0, y0, z0], [x1, y1, z1]]`` of a solid (module docs)."""
    from ..csg import Difference, Intersection

    done: dict[int, NDArray[np.float64] | None] = {}
    stack: list[tuple[Any, bool]] = [(solid, False)]
    while stack:
        s, expanded = stack.pop()
        if id(s) in done:
            continue
        kids = _children(s)
        if kids is None:
            done[id(s)] = np.asarray(s.bounds, dtype=np.float64)
            continue
        if isinstance(s, (Difference, Intersection)):
            from ..csg.tree import leaves

            if all(type(leaf).polyhedral for leaf in leaves(s)):
                done[id(s)] = _manifold_bounds(s)
            else:
                done[id(s)] = _probed_bounds(s)
            continue
        if not expanded:
            stack.append((s, True))
            stack.extend((c, False) for c in kids)
            continue
        boxes = [done[id(c)] for c in kids]
        real = [b for b in boxes if b is not None]
        done[id(s)] = np.array([np.min([b[0] for b in real], axis=0), np.max([b[1] for b in real], axis=0)]) \
            if real else None
    out = done[id(solid)]
    if out is None:
        raise NotExactError("resize: the child is empty")
    return out


def _manifold_bounds(s: Any) -> NDArray[np.float64] | None:
    from ..csg.mesh import to_manifold

    m = to_manifold(s)
    if m.is_empty():
        return None
    b = np.asarray(m.bounding_box(), dtype=np.float64)
    return b.reshape(2, 3)


def _probed_bounds(s: Any) -> NDArray[np.float64]:
    """The Boolean box of the leaves' boxes, each face checked by a section a hair inside it; a
    face the solid does not reach is found from a coarse mesh, then refined by sections."""
    from ..csg.program import compile_program

    box = np.asarray(compile_program(s).bounds(), dtype=np.float64).reshape(2, 3)
    size = float(np.max(box[1] - box[0]))
    step = PROBE_RTOL * max(size, float(np.abs(box).max()))
    meshed: NDArray[np.float64] | None = None
    for axis in range(3):
        # a map taking this axis to z (a cyclic permutation: no mirror)
        m = np.eye(4)
        m[:3, :3] = np.roll(np.eye(3), 2 - axis, axis=0)
        turned = s.transform(m)
        for side, sign in ((0, 1.0), (1, -1.0)):
            if _meets(turned, float(box[side, axis]) + sign * step):
                continue
            if meshed is None:
                meshed = _meshed_bounds(s)
            box[side, axis] = _refine(turned, float(meshed[side, axis]), -sign, MESH_SAGITTA * size, step)
    return box


#: Segments per turn of the coarse mesh that locates a face the leaves' box does not give, and
#: the chord sagitta it leaves (relative to a radius): ``1 - cos(pi / 256)``.
MESH_RESOLUTION = 256
MESH_SAGITTA = 1.0 - math.cos(math.pi / MESH_RESOLUTION)


def _meets(turned: Any, z: float) -> bool:
    """Whether the plane at height z cuts the (turned) solid in an area."""
    from ..shapes2d import EMPTY
    from ..shapes2d.measure import to_shapely
    from ..shapes2d.projection import section_at

    cut = section_at(turned, z)
    # inscribed polygons: a cut no deeper than their sagitta (3e-7 of a radius) reads as empty
    return cut is not EMPTY and to_shapely(cut, resolution=4096).area > 0


def _refine(turned: Any, start: float, outward: float, reach: float, step: float) -> float:
    """The last height, going ``outward`` from ``start`` (a height of the mesh's box, inside the
    solid's by at most ``reach``), where the solid is met; bisection to ``step``."""
    inner, outer = start - outward * step, start + outward * 2 * reach
    if not _meets(turned, inner):
        inner = start
    for _ in range(200):
        if abs(outer - inner) <= step:
            break
        mid = 0.5 * (inner + outer)
        if _meets(turned, mid):
            inner = mid
        else:
            outer = mid
    return inner


def _meshed_bounds(s: Any) -> NDArray[np.float64]:
    """The bounds of a mesh of the tree (manifold3d, ``MESH_RESOLUTION`` segments per turn):
    its vertices lie on the surface, so its box is inside the true one by at most a sagitta."""
    from ..csg.mesh import to_manifold

    m = to_manifold(s, MESH_RESOLUTION)
    if m.is_empty():
        raise NotExactError("resize: the child is empty")
    return np.asarray(m.bounding_box(), dtype=np.float64).reshape(2, 3)


def shape_bounds(shape: Any) -> NDArray[np.float64]:
    """The exact bounding box ``[[x0, y0], [x1, y1]]`` of a 2D shape (module docs)."""
    from ..shapes2d import EMPTY, Ellipse
    from ..shapes2d.boundary import boundary_pieces
    from ..shapes2d.measure import bounds, is_polygonal, to_shapely
    from ..shapes2d.shape import Union2D, iter_leaves

    if shape is EMPTY:
        raise NotExactError("resize: the child is empty")
    if not _children2d(shape) or (isinstance(shape, Union2D) and _union_only(shape)):
        b = bounds(shape)
        return np.array([b[:2], b[2:]], dtype=np.float64)
    if is_polygonal(shape):
        b = to_shapely(shape).bounds
        return np.array([b[:2], b[2:]], dtype=np.float64)
    if any(isinstance(leaf, Ellipse) for leaf in iter_leaves(shape)):
        raise NotExactError("resize: the bounds of a 2D Boolean of ellipses are not known exactly")
    pts: list[tuple[float, float]] = []
    for p in boundary_pieces(shape, bounds(shape)):
        pts += [p.a, p.b]
        if p.radius > 0:
            for k in range(-4, 9):  # the axis extremes of the circle inside the arc
                t = k * math.pi / 2
                if p.t0 < t < p.t1:
                    pts.append((p.center[0] + p.radius * math.cos(t), p.center[1] + p.radius * math.sin(t)))
    if not pts:
        raise NotExactError("resize: the child is empty")
    a = np.array(pts, dtype=np.float64)
    return np.array([a.min(axis=0), a.max(axis=0)])


def _children2d(shape: Any) -> bool:
    return bool(getattr(shape, "children", ()))


def _union_only(shape: Any) -> bool:
    from ..shapes2d.shape import Union2D

    todo = [shape]
    while todo:
        s = todo.pop()
        kids = getattr(s, "children", ())
        if kids and not isinstance(s, Union2D):
            return False
        todo.extend(kids)
    return True


def _arguments(lw: Any, call: Any, dim: int) -> tuple[list[float], list[bool]]:
    """``newsize`` and ``auto`` as OpenSCAD reads them (missing entries 0 and false)."""
    value = lw.arg(call, "newsize", 0, None)
    newsize = [0.0] * 3
    if isinstance(value, list):
        for i, v in enumerate(value[:3]):
            newsize[i] = lw.number(call, "newsize", v)
    elif value is not None and not isinstance(value, (int, float)):
        raise lw.fail(call, f"newsize must be a list of numbers, got {value!r}")
    flag = lw.arg(call, "auto", 1, False)
    auto = [False] * 3
    if isinstance(flag, list):
        for i, v in enumerate(flag[:3]):
            auto[i] = bool(v)
    elif isinstance(flag, bool):  # a number is neither (OpenSCAD reads auto = 3 as false)
        auto = [flag] * 3
    return newsize[:dim], auto[:dim]


def resize_solid(lw: Any, call: Any, solid: Any) -> Any:
    """A 3D ``resize`` node's solid: its child scaled about the origin (None: empty or skipped)."""
    if solid is None:
        return None
    newsize, auto = _arguments(lw, call, 3)
    try:
        box = solid_bounds(solid)
    except NotExactError as exc:
        lw.unsupported(call, str(exc).removeprefix("resize: "))
        return None
    scale = resize_scale(newsize, auto, box[1] - box[0])
    if np.all(scale == 1.0):
        return solid
    from ..errors import InvalidGeometryError, InvalidParameterError
    from ..kinds import Primitive

    if isinstance(solid, Primitive):
        # a kind that stays itself under any aspect (an axis-aligned box: a map of that aspect would be
        # refused as ill-conditioned)
        scaled = lw.make(call, solid.axis_scaled, scale)
        if scaled is not None:
            return scaled
    m = np.eye(4)
    m[:3, :3] = np.diag(scale)
    try:
        return solid.transform(m)
    except InvalidParameterError as exc:
        lw.unsupported(call, f"its image is not an exact isocsg solid: {exc}")
        return None
    except InvalidGeometryError as exc:
        raise lw.fail(call, str(exc)) from None


def resize_shape(lw: Any, call: Any, shape: Any) -> Any:
    """A 2D ``resize`` node's shape: its child scaled about the origin."""
    from ..shapes2d import EMPTY

    if shape is EMPTY:
        return EMPTY
    newsize, auto = _arguments(lw, call, 2)
    try:
        box = shape_bounds(shape)
    except NotExactError as exc:
        lw.unsupported(call, str(exc).removeprefix("resize: "))
        return None
    scale = resize_scale(newsize, auto, box[1] - box[0])
    if np.all(scale == 1.0):
        return shape
    return shape.scale(scale.tolist())
