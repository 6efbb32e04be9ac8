"""OpenSCAD's own polygonal solid where a node has no exact form (opt-in).

``read_openscad(path, polygonal=True)``: where a ``hull()`` or ``minkowski()`` node is not an
exact union of isocsg kinds (a sphere beside a cylinder off its axis, a sum with a difference,
...), its children are lowered again with every sphere, cylinder and circle as OpenSCAD's polygon
at the node's ``$fn``/``$fa``/``$fs`` (``get_fragments_from_r``), and the node becomes what
OpenSCAD computes from them:

- ``hull``: the :class:`~isocsg.ConvexPolyhedron` of the children's vertices (OpenSCAD's hull of
  the same points, so the same solid);
- ``minkowski``: for convex children the :class:`~isocsg.ConvexPolyhedron` of the pairwise sums of
  their vertices (as OpenSCAD sums convex parts); with one non-convex child ``A`` (a difference, a
  union), ``A`` shifted by a corner of the convex sum ``K`` and, over each triangle ``T`` of
  ``A``'s boundary, the convex polyhedron ``T + K`` (the same set as OpenSCAD's sum over convex
  parts). Two non-convex children are refused.

A 2D ``minkowski`` becomes the union of the hulls of pairwise vertex sums of its children's
convex pieces (:func:`polygonal_minkowski2d`). A ``rotate_extrude`` whose exact solid is refused
(an ellipse off the axis, a torus under a non-uniform scale) becomes OpenSCAD's faceted solid
likewise (:func:`isocsg.openscad.lowering._revolved`). Each such node is listed in
:attr:`~isocsg.openscad.LoweredModel.polygonal` (``"model.csg:12: hull(): ..."``). Without the
option those nodes stay refused with the reason, as the default.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidGeometryError, NotExactError
from ..kinds import ConvexPolyhedron, Solid

if TYPE_CHECKING:
    from .parser import CSGCall

#: Lowers one child under a map: the lowering's walk, passed in (this module sits beside it).
LowerChild = Callable[["CSGCall", "NDArray[np.float64] | None"], "Solid | None"]

__all__ = ["polygonal_node", "polygonal_minkowski2d"]


def _faceted_children(lw: Any, call: CSGCall, m: NDArray[np.float64] | None, lower_child: LowerChild) -> list[Solid]:
    """Each kept child of ``call`` lowered again with OpenSCAD's polygons for round leaves."""
    was = lw.faceted
    lw.faceted = True
    try:
        out = []
        for child in call.children:
            if "%" in child.modifiers or "*" in child.modifiers:
                continue
            value = lower_child(child, m)
            if value is not None:
                out.append(value)
        return out
    finally:
        lw.faceted = was


def _mesh_of(solids: list[Solid]) -> Any:
    """The manifold3d solid of flat-faced solids (their union)."""
    from ..csg.mesh import to_manifold

    meshes = [to_manifold(s) for s in solids]
    total = meshes[0]
    for m in meshes[1:]:
        total = total + m
    return total


def _arrays(manifold: Any) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    mesh = manifold.to_mesh64()  # double precision: the vertices as given
    return np.asarray(mesh.vert_properties, dtype=np.float64)[:, :3], np.asarray(mesh.tri_verts, dtype=np.int64)


def _corners(solid: Solid) -> NDArray[np.float64] | None:
    """A convex flat-faced leaf's corners (its :class:`~isocsg.kinds.forms.PointHull`), else None."""
    from ..kinds.base import Primitive
    from ..kinds.forms import PointHull

    form = solid.exact_form() if isinstance(solid, Primitive) else None
    return np.asarray(form.vertices, dtype=np.float64) if isinstance(form, PointHull) else None


def _convex(solid: Solid) -> bool:
    return _corners(solid) is not None


def _hull(solids: list[Solid]) -> Solid | None:
    vertices, _ = _arrays(_mesh_of(solids).hull())
    if len(vertices) < 4:
        return None
    try:
        return ConvexPolyhedron(vertices)
    except InvalidGeometryError:
        return None  # flat: no volume, as in OpenSCAD


def _minkowski(solids: list[Solid]) -> Solid | None:
    """``A + K``: ``K`` the sum of the convex children (the hull of the pairwise sums of their
    corners, as OpenSCAD sums convex parts); ``A`` the one non-convex child, if any, as
    ``(A + k0) u (T_i + K)`` over the triangles ``T_i`` of its boundary (each a hull of corner
    sums): a point of ``A + K`` off ``A + k0`` is a boundary point of ``A`` plus a point of ``K``."""
    from ..csg import Union
    from ..csg.hull import MAX_MINKOWSKI_TERMS
    from ..csg.mesh import to_manifold

    others = [s for s in solids if not _convex(s)]
    if len(others) > 1:
        raise NotExactError(f"{len(others)} children are not convex (a polygonal sum takes at most one)")
    points = np.zeros((1, 3))
    for s in solids:
        corners = _corners(s)
        if corners is not None:
            points = (points[:, None, :] + corners[None]).reshape(-1, 3)
            if len(points) > 64:  # only the sum's corners matter
                points = np.asarray(ConvexPolyhedron(points).hull_vertices, dtype=np.float64)
    if not others:
        return ConvexPolyhedron(points)
    vertices, faces = _arrays(to_manifold(others[0]))
    if len(faces) > MAX_MINKOWSKI_TERMS:
        raise NotExactError(f"the non-convex child has {len(faces)} triangles, over MAX_MINKOWSKI_TERMS = "
                            f"{MAX_MINKOWSKI_TERMS}")
    sums = vertices[faces][:, :, None, :] + points[None, None]  # (triangles, 3, corners, 3)
    pieces = [ConvexPolyhedron(t.reshape(-1, 3)) for t in sums]
    return Union(others[0].translate(points[0]), *pieces)


def polygonal_node(lw: Any, call: CSGCall, m: NDArray[np.float64] | None, reason: str,
                   lower_child: LowerChild) -> Solid | None:
    """OpenSCAD's polygonal solid of a ``hull`` or ``minkowski`` node (None: no volume), recorded
    in ``lw.polygonal_nodes`` with the reason it has no exact form; ``lower_child`` is the
    lowering's walk of one child under a map."""
    solids = _faceted_children(lw, call, m, lower_child)
    if not solids:
        return None
    try:
        result = _hull(solids) if call.name == "hull" else solids[0] if len(solids) == 1 else _minkowski(solids)
    except NotExactError as exc:
        lw.unsupported(call, f"{reason}; nor OpenSCAD's polygonal {call.name}: {exc}")
        return None
    except InvalidGeometryError as exc:
        raise lw.fail(call, f"OpenSCAD's polygonal {call.name}: {exc}") from None
    lw.polygonal_nodes.append(f"{lw.where(call)}{call.name}(): {reason}")
    return result  # a minkowski's caller takes the maps' shift back


def polygonal_minkowski2d(lw: Any, call: CSGCall, shape_of: Callable[..., Any]) -> Any:
    """A 2D ``minkowski`` as OpenSCAD draws it: each child's shape with circles as OpenSCAD's
    polygons (``shape_of``: :func:`~isocsg.openscad.flat.shape_of`, passed in), cut into convex
    pieces, the hull of each pair of pieces' vertex sums, united; recorded in ``lw.polygonal_nodes``."""
    import shapely
    from shapely.geometry import MultiPoint

    from ..csg.hull import MAX_MINKOWSKI_TERMS
    from ..shapes2d import EMPTY, to_shapely
    from ..shapes2d.region import convex_pieces, shape_from_region
    from .parser import CSGCall

    shapes = []
    for child in call.children:
        if "%" in child.modifiers or "*" in child.modifiers:
            continue
        shape = shape_of(lw, CSGCall("union", children=[child], line=child.line), polygonal=True)
        if shape is not None and shape is not EMPTY:
            shapes.append(shape)
    if not shapes:
        return EMPTY
    region = to_shapely(shapes[0])
    for shape in shapes[1:]:
        a, b = convex_pieces(region), convex_pieces(to_shapely(shape))
        if len(a) * len(b) > MAX_MINKOWSKI_TERMS:
            lw.unsupported(call, f"a 2D Minkowski sum of {len(a)} by {len(b)} convex pieces is over "
                                 f"MAX_MINKOWSKI_TERMS = {MAX_MINKOWSKI_TERMS}")
            return None
        region = shapely.union_all([MultiPoint((p[:, None, :] + q[None]).reshape(-1, 2)).convex_hull
                                    for p in a for q in b])
    lw.polygonal_nodes.append(f"{lw.where(call)}minkowski(): a 2D Minkowski sum has no exact form here")
    return shape_from_region(region)
