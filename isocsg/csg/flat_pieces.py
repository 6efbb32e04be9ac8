"""Convex pieces of a flat-faced solid, for Minkowski sums of non-convex operands.

A Minkowski sum distributes over unions, ``(P1 u P2) + K = (P1 + K) u (P2 + K)``, so a
non-convex operand sums exactly once it is a union of convex pieces. A CSG tree whose leaves
are all flat-faced (boxes, convex polyhedra, triangle meshes) is a polyhedron: its mesh is
manifold3d's Booleans of the leaves' own faces in double precision (no tessellation), and
:meth:`~isocsg.kinds.mesh.TriangleMesh.convex_pieces` cuts that mesh into the inside cells of a
binary space partition along its own face planes: convex polyhedra whose union is the solid, to
rounding. A tree with a round leaf (a sphere, a cylinder) has no such pieces among the kinds
and is left to the caller to refuse.
"""

from __future__ import annotations

import numpy as np

from ..errors import InvalidGeometryError
from ..kinds import ConvexPolyhedron, Primitive, Solid
from ..kinds.mesh import TriangleMesh
from .tree import leaves

__all__ = ["flat_convex_pieces"]


def _flat(leaf: Primitive) -> bool:
    return leaf.polyhedral or leaf.hull_points() is not None


def flat_convex_pieces(solid: Solid) -> list[ConvexPolyhedron] | None:
    """Convex polyhedra whose union is ``solid`` when every leaf of it is flat-faced (empty: no
    volume); None when a leaf is round.

    Raises
    ------
    InvalidParameterError
        When the solid's mesh is too large to decompose
        (:data:`~isocsg.kinds.mesh_convex.MAX_DECOMPOSITION_FACES`).
    """
    if isinstance(solid, Primitive):
        if solid.polyhedral and not solid.convex:  # a non-convex flat-faced kind: its exact pieces
            return solid.convex_pieces()
        corners = solid.hull_points()
        return [ConvexPolyhedron(corners)] if corners is not None else None
    if not all(_flat(leaf) for leaf in leaves(solid)):
        return None
    from .mesh import to_manifold

    mesh = to_manifold(solid).to_mesh64()
    vertices = np.asarray(mesh.vert_properties, dtype=np.float64)[:, :3]
    faces = np.asarray(mesh.tri_verts, dtype=np.int64)
    if len(faces) == 0:
        return []
    try:
        return TriangleMesh(vertices, faces).convex_pieces()
    except InvalidGeometryError:  # manifold3d's result is closed; a sliver flattened by rounding is not a solid
        return None
