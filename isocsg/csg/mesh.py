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

from .._validation import integer
from ..errors import InvalidGeometryError, InvalidParameterError
from ..kinds.base import Primitive, Solid
from ..kinds.meshing import manifold3d_module as _manifold3d
from ..kinds.meshing import rotation_to_axis
from .program import OP_INTERSECTION, OP_UNION, Program, compile_program

if TYPE_CHECKING:  # pragma: no cover
    import manifold3d
    import trimesh

__all__ = ["to_manifold", "to_trimesh", "program_manifold", "rotation_to_axis"]


def _leaf(prim: Primitive, resolution: int, shapes: dict[tuple[Any, ...], Any]) -> manifold3d.Manifold:
    """A leaf as a manifold3d solid, through its kind's :meth:`~isocsg.kinds.base.Primitive.manifold`;
    ``shapes`` keeps the solids at the origin by their dimensions, so that many equal spheres or
    cylinders are built once and moved."""
    return prim.manifold(resolution, shapes)


def _build(solid: Solid, resolution: int, path: str) -> manifold3d.Manifold:
    if not isinstance(solid, Solid):
        raise InvalidGeometryError(f"{path} must be a solid (primitive or CSG node), got {type(solid).__name__}")
    return program_manifold(compile_program(solid), resolution)


def program_manifold(prog: Program, resolution: int) -> manifold3d.Manifold:
    """A compiled program as a manifold3d solid: each leaf through its kind's ``manifold``, the tree's
    Booleans as manifold3d batch Booleans (exact mesh Booleans in double precision)."""
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
    return prog.evaluate(lambda _, p: _leaf(p, resolution, shapes), combine)


def to_manifold(solid: Solid, resolution: int = 64) -> manifold3d.Manifold:
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


def to_trimesh(solid: Solid, resolution: int = 64) -> trimesh.Trimesh:
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
