"""Triangle meshes of primitives and CSG trees through manifold3d.

Leaves become manifold3d solids (spheres, cylinders and cones from
manifold3d's own constructors, boxes and convex polyhedra from their hulls);
the tree's Booleans are manifold3d's exact mesh Booleans. The result is a
closed, oriented triangle mesh inscribed in the analytic solid: its volume
converges to the true one as ``resolution`` grows.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from .._validation import integer
from ..errors import InvalidGeometryError, InvalidParameterError, MissingDependencyError
from ..geometry.primitives import Box, ConvexPolyhedron, Primitive, Solid, Sphere, Truncus
from ..geometry.registry import hook_for
from .program import OP_INTERSECTION, OP_UNION, compile_program

if TYPE_CHECKING:  # pragma: no cover
    import manifold3d
    import trimesh

__all__ = ["to_manifold", "to_trimesh", "rotation_to_axis"]


def _manifold3d():  # type: ignore[no-untyped-def]
    try:
        import manifold3d
    except ImportError as exc:  # pragma: no cover - manifold3d is a core dependency
        raise MissingDependencyError("to_manifold needs manifold3d: pip install manifold3d") from exc
    return manifold3d


def rotation_to_axis(axis: NDArray[np.float64]) -> NDArray[np.float64]:
    """A rotation matrix that maps +z onto the unit vector ``axis``.

    Parameters
    ----------
    axis : ndarray, shape (3,)
        Unit target direction.

    Returns
    -------
    ndarray, shape (3, 3)
        Orthonormal, determinant +1, with ``R @ (0, 0, 1) == axis``.

    Examples
    --------
    >>> R = rotation_to_axis(np.array([1.0, 0.0, 0.0]))
    >>> np.round(R @ [0, 0, 1], 12).tolist()
    [1.0, 0.0, 0.0]
    """
    a = np.asarray(axis, dtype=np.float64)
    a = a / np.linalg.norm(a)
    helper = np.array([1.0, 0.0, 0.0]) if abs(a[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    x = np.cross(helper, a)
    x /= np.linalg.norm(x)
    y = np.cross(a, x)
    return np.column_stack([x, y, a])


def _leaf(prim: Primitive, resolution: int, shapes: dict[tuple[Any, ...], Any] | None = None) -> "manifold3d.Manifold":
    """A leaf as a manifold3d solid, through its kind's ``manifold`` hook (the hull of its
    inscribed polyhedron when it has none); ``shapes`` keeps the solids at the origin by their
    dimensions, so that many equal spheres or cylinders are built once and moved."""
    shapes = {} if shapes is None else shapes
    hook = hook_for(prim, "manifold")
    if hook is not None:
        return hook(prim, resolution, shapes)
    poly = prim.to_polyhedron(resolution)
    return _manifold3d().Manifold.hull_points(np.asarray(poly.hull_vertices, dtype=np.float64).tolist())


# ----------------------------------------------------------------------------- the built-in kinds' hooks


def sphere_manifold(prim: Sphere, resolution: int, shapes: dict[tuple[Any, ...], Any]) -> "manifold3d.Manifold":
    """manifold3d's sphere (it rounds the segment count up to a multiple of 4), moved."""
    key = ("sphere", prim.radius, resolution)
    if key not in shapes:
        shapes[key] = _manifold3d().Manifold.sphere(prim.radius, resolution)
    return shapes[key].translate(tuple(prim.center))


def truncus_manifold(prim: Truncus, resolution: int, shapes: dict[tuple[Any, ...], Any]) -> "manifold3d.Manifold":
    """manifold3d's cylinder, turned onto the axis and moved."""
    # manifold3d's cylinder runs from radius_low at z=-h/2 to radius_high at z=+h/2;
    # the truncus's E2 (r2) is at -axis/2 and E1 (r1) at +axis/2.
    key = ("truncus", prim.height, prim.r1, prim.r2, resolution)
    if key not in shapes:
        shapes[key] = _manifold3d().Manifold.cylinder(prim.height, prim.r2, prim.r1, resolution, True)
    cyl = shapes[key]
    R = rotation_to_axis(prim.unit_axis)
    mat = np.column_stack([R, prim.center_array])
    return cyl.transform(mat.tolist())


def box_manifold(prim: Box, resolution: int, shapes: dict[tuple[Any, ...], Any]) -> "manifold3d.Manifold":
    """manifold3d's cube, turned and moved."""
    cube = _manifold3d().Manifold.cube(tuple(prim.size), True)
    if prim.axis_aligned:
        return cube.translate(tuple(prim.center))
    return cube.transform(np.column_stack([prim.rotation, prim.center_array]).tolist())


def polyhedron_manifold(prim: ConvexPolyhedron, resolution: int, shapes: dict[tuple[Any, ...], Any]) -> "manifold3d.Manifold":
    """The hull of the polyhedron's vertices."""
    return _manifold3d().Manifold.hull_points(np.asarray(prim.hull_vertices, dtype=np.float64).tolist())


def _build(solid: Solid, resolution: int, path: str) -> "manifold3d.Manifold":
    if not isinstance(solid, Solid):
        raise InvalidGeometryError(f"{path} must be a solid (primitive or CSG node), got {type(solid).__name__}")
    m3 = _manifold3d()
    M = m3.Manifold
    add, sub, meet = m3.OpType.Add, m3.OpType.Subtract, m3.OpType.Intersect

    def combine(op: int, parts: list[Any]) -> Any:
        if len(parts) == 1:
            return parts[0]
        if op == OP_UNION:
            # manifold3d's batch union joins operands whose boxes do not overlap without a Boolean.
            return M.batch_boolean(parts, add)
        if op == OP_INTERSECTION:
            return M.batch_boolean(parts, meet)
        rest = parts[1] if len(parts) == 2 else M.batch_boolean(parts[1:], add)
        return M.batch_boolean([parts[0], rest], sub)

    shapes: dict[tuple[Any, ...], Any] = {}
    return compile_program(solid).evaluate(lambda _, p: _leaf(p, resolution, shapes), combine)


def to_manifold(solid: Solid, resolution: int = 64) -> "manifold3d.Manifold":
    """Convert a primitive or CSG tree to a :class:`manifold3d.Manifold`.

    Parameters
    ----------
    solid : Solid
        A primitive or a CSG tree.
    resolution : int, default 64
        Segments around each circle (spheres, cylinders, cones, frusta), 3 .. 65536.

    Returns
    -------
    manifold3d.Manifold
        Possibly empty (e.g. ``A - A``).

    Raises
    ------
    InvalidGeometryError
        If ``solid`` (or an operand in it) is not a solid.
    InvalidParameterError
        If ``resolution`` is not an integer in range.

    Examples
    --------
    >>> from isocsg import Box, Sphere
    >>> m = to_manifold(Box((0, 0, 0), (2, 2, 2)) - Box((1, 1, 1), (2, 2, 2)))
    >>> round(m.volume(), 9)
    7.0
    """
    res = integer("resolution", resolution, low=3, high=65536, error=InvalidParameterError)
    return _build(solid, res, "solid")


def to_trimesh(solid: Solid, resolution: int = 64) -> "trimesh.Trimesh":
    """Convert a primitive or CSG tree to a closed :class:`trimesh.Trimesh`.

    Parameters
    ----------
    solid : Solid
        A primitive or a CSG tree.
    resolution : int, default 64
        Segments around each circle, see :func:`to_manifold`.

    Returns
    -------
    trimesh.Trimesh
        Float64 vertices and outward-oriented triangles; empty for an empty result.

    Raises
    ------
    InvalidGeometryError
        If ``solid`` (or an operand in it) is not a solid.
    InvalidParameterError
        If ``resolution`` is not an integer in range.

    Examples
    --------
    >>> from isocsg import Sphere
    >>> m = to_trimesh(Sphere((0, 0, 0), 1.0) & Sphere((1, 0, 0), 1.0), resolution=128)
    >>> bool(m.is_watertight), bool(abs(m.volume / (5 * np.pi / 12) - 1) < 0.01)
    (True, True)
    """
    import trimesh

    mesh = to_manifold(solid, resolution).to_mesh()
    verts = np.asarray(mesh.vert_properties, dtype=np.float64)[:, :3]
    tris = np.asarray(mesh.tri_verts, dtype=np.int64)
    return trimesh.Trimesh(verts.reshape(-1, 3), tris.reshape(-1, 3), process=False)
