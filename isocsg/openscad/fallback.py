"""OpenSCAD's own answer where an outline or a twisted stack has no exact form here (the default).

Two nodes are computed by OpenSCAD itself from its polygons, so where isocsg has no exact form for
them, the solid OpenSCAD draws is the faithful answer, and it is made by default:

- ``projection(cut = false)`` whose exact outline is refused (:func:`isocsg.shapes2d.projection.projection`):
  the node's 3D children are lowered again with every sphere, cylinder and circle as OpenSCAD's
  polygon at its ``$fn``/``$fa``/``$fs`` (as :mod:`isocsg.openscad.polygonal` does), and the
  outline is the shadow of that polyhedral solid on the xy plane (manifold3d's ``project``): what
  OpenSCAD 2021.01 computes (``projection`` of its own polyhedron).
- ``linear_extrude(twist = ...)`` whose turn per slice is too large for the exact slices
  (:mod:`isocsg.shapes2d.twist`): OpenSCAD's stack of slices itself as a
  :class:`~isocsg.kinds.TriangleMesh`, with the outline's circles as OpenSCAD's polygons, each side
  quad split along OpenSCAD's diagonal (``GeometryEvaluator.cc``'s ``add_slice``) and the two caps
  triangulated without new points.

Each such node is listed in :attr:`~isocsg.openscad.LoweredModel.polygonal`, and
:func:`~isocsg.openscad.load_openscad` issues an
:class:`~isocsg.openscad.OpenSCADPolygonalWarning` naming it: the result is OpenSCAD's
tessellated solid, not an exact one.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidGeometryError
from .parser import CSGCall

__all__ = ["polygonal_projection", "polygonal_twist"]


def _shadow_region(solid: Any) -> Any:
    """The shapely region of a flat-faced solid's shadow on the xy plane: each connected piece of
    manifold3d's projection is its one counter-clockwise ring with its clockwise holes."""
    import shapely
    from shapely.geometry import Polygon

    from ..csg.mesh import to_manifold

    polygons = []
    for piece in to_manifold(solid).project().decompose():
        rings = [np.asarray(p, dtype=np.float64) for p in piece.to_polygons() if len(p) >= 3]
        if not rings:
            continue
        signed = [0.5 * float(np.sum(r[:, 0] * np.roll(r[:, 1], -1) - np.roll(r[:, 0], -1) * r[:, 1])) for r in rings]
        k = int(np.argmax(signed))
        polygons.append(Polygon(rings[k], [r for i, r in enumerate(rings) if i != k]))
    return shapely.normalize(shapely.union_all(polygons)) if polygons else Polygon()


def polygonal_projection(lw: Any, call: CSGCall, reason: str) -> Any:
    """The outline of ``projection(cut = false)`` as OpenSCAD computes it: the shadow of the
    children's polyhedral solid (round leaves as OpenSCAD's polygons); recorded in
    ``lw.polygonal_nodes`` with ``reason`` (why the exact outline is refused)."""
    from ..shapes2d import EMPTY
    from ..shapes2d.region import shape_from_region

    was = lw.faceted
    lw.faceted = True
    try:
        solid = lw.solid_of(call)
    finally:
        lw.faceted = was
    if solid is None:
        return EMPTY
    try:
        region = _shadow_region(solid)
    except InvalidGeometryError as exc:
        raise lw.fail(call, f"OpenSCAD's polygonal outline: {exc}") from None
    lw.polygonal_nodes.append(f"{lw.where(call)}projection(): {reason}")
    return EMPTY if region.is_empty else shape_from_region(region)


def _cap(region: Any, index: dict[tuple[float, float], int]) -> NDArray[np.int64]:
    """The region's triangles (constrained Delaunay, no new points) as indices of its ring points,
    counter-clockwise seen from above."""
    import shapely

    out = []
    for tri in shapely.get_parts(shapely.constrained_delaunay_triangles(region)):
        p = np.asarray(tri.exterior.coords)[:3]
        ids = [index[(float(x), float(y))] for x, y in p]
        area = (p[1, 0] - p[0, 0]) * (p[2, 1] - p[0, 1]) - (p[2, 0] - p[0, 0]) * (p[1, 1] - p[0, 1])
        if area == 0.0:
            continue
        out.append(ids if area > 0 else ids[::-1])
    return np.asarray(out, dtype=np.int64).reshape(-1, 3)


def stack_mesh(region: Any, slices: list[Any]) -> Any:
    """OpenSCAD's stack of slices of a polygonal region (shapely) as a
    :class:`~isocsg.kinds.TriangleMesh`: one ring of the outline's points per slice boundary,
    each side quad split along OpenSCAD's diagonal, the caps triangulated in their planes."""
    import shapely

    from ..kinds import TriangleMesh
    from ..shapes2d.twist import _openscad_first, _ring

    region = shapely.orient_polygons(shapely.normalize(region))  # outer rings counter-clockwise
    rings: list[tuple[NDArray[np.float64], bool]] = []
    for poly in shapely.get_parts(region):
        rings.append((np.asarray(poly.exterior.coords)[:-1], True))
        rings.extend((np.asarray(r.coords)[:-1], False) for r in poly.interiors)
    points = np.vstack([r for r, _ in rings])
    k = len(points)
    index = {(float(x), float(y)): i for i, (x, y) in enumerate(points)}
    if len(index) != k:
        raise InvalidGeometryError("linear_extrude: the outline touches itself at a point; "
                                   "OpenSCAD's polygon stack is then not a closed solid here")
    levels = [_ring(points, *slices[0].lo)] + [_ring(points, *sl.hi) for sl in slices]
    vertices = np.vstack(levels)
    faces: list[NDArray[np.int64]] = []
    start = 0
    for ring, positive in rings:
        n = len(ring)
        i = np.arange(n)
        j = (i + 1) % n
        for level, sl in enumerate(slices):
            b, t = levels[level][start:start + n], levels[level + 1][start:start + n]
            bi, bj = level * k + start + i, level * k + start + j
            ti, tj = bi + k, bj + k
            first = np.array([_openscad_first(b, t, a, int(j[a]), positive, sl) for a in range(n)])
            one = np.where(first[:, None], np.column_stack([bi, bj, tj]), np.column_stack([bi, bj, ti]))
            two = np.where(first[:, None], np.column_stack([bi, tj, ti]), np.column_stack([bj, tj, ti]))
            faces += [one, two]
        start += n
    cap = _cap(region, index)
    faces += [cap[:, ::-1], cap + len(slices) * k]
    F = np.vstack(faces)
    return TriangleMesh(vertices, F)


def polygonal_twist(lw: Any, call: CSGCall, shape: Any, z: tuple[float, float], twist: float,
                    scale: tuple[float, float], slices: int | None, details: tuple[float, float, float],
                    reason: str) -> Any:
    """OpenSCAD's polygon stack of a twisted ``linear_extrude`` (``shape``: the outline with circles
    as OpenSCAD's polygons); recorded in ``lw.polygonal_nodes`` with ``reason``."""
    from ..shapes2d.measure import to_shapely
    from ..shapes2d.twist import _reach, make_slices, slice_count

    if scale[0] == 0.0 or scale[1] == 0.0:
        lw.unsupported(call, f"{reason}; OpenSCAD's polygon stack to a point is not drawn here")
        return None
    n = slices
    if n is None:
        radius, delta = _reach(shape, scale)
        n = slice_count(radius, delta, z[1] - z[0], twist, scale, *details)
    if n > 10000:
        raise lw.fail(call, f"{n} slices (from $fn, $fs, $fa) exceed 10000")
    try:
        mesh = stack_mesh(to_shapely(shape), make_slices(n, z[0], z[1], twist, scale))
    except InvalidGeometryError as exc:
        lw.unsupported(call, f"{reason}; nor OpenSCAD's polygon stack: {exc}")
        return None
    lw.polygonal_nodes.append(f"{lw.where(call)}linear_extrude(): {reason}")
    return mesh
