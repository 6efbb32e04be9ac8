"""manifold3d references for CSG geometry, built here from manifold3d's own constructors.

The tree is read through the ``children`` of its nodes with an explicit stack
(no recursion, so trees built by loops of any length work); each leaf is
manifold3d's sphere, cylinder, cube or hull, and nodes are manifold3d's batch
Booleans. Sections are ``Manifold.slice`` in the plane's frame.
"""

from __future__ import annotations

from typing import Any

import manifold3d as m3
import numpy as np
import shapely
from shapely.geometry import Polygon

from isocsg import Box, ConvexPolyhedron, Difference, Intersection, Sphere, Truncus, Union

__all__ = ["manifold_leaf", "manifold_of", "manifold_slice", "leaf_primitives"]


def manifold_leaf(p: Any, segments: int) -> m3.Manifold:
    """One primitive as a manifold3d solid (circles as ``segments``-gons)."""
    M = m3.Manifold
    if isinstance(p, Sphere):
        return M.sphere(float(p.radius), segments).translate(tuple(float(v) for v in p.center))
    if isinstance(p, Truncus):
        # manifold3d's cylinder: radius_low at z=0, radius_high at z=h; map z to the axis (E2 -> E1)
        axis = np.asarray(p.axis, dtype=np.float64)
        h = float(np.linalg.norm(axis))
        a = axis / h
        x = np.cross(a, [0.3, 0.5, 0.7])
        x /= np.linalg.norm(x)
        y = np.cross(a, x)
        mat = np.column_stack([x, y, a, np.asarray(p.center, dtype=np.float64) - axis / 2])
        return M.cylinder(h, float(p.r2), float(p.r1), segments).transform(mat.tolist())
    if isinstance(p, Box):
        size = np.asarray(p.size, dtype=np.float64)
        return M.cube(tuple(size)).translate(tuple(np.asarray(p.center, dtype=np.float64) - size / 2))
    if isinstance(p, ConvexPolyhedron):
        return M.hull_points([[float(c) for c in v] for v in p.vertices])
    raise TypeError(f"unsupported primitive {type(p).__name__}")


def manifold_of(solid: Any, segments: int = 128) -> m3.Manifold:
    """manifold3d's Boolean of a primitive or CSG tree (post-order walk with an explicit stack).

    Repeated primitive objects are tessellated once.
    """
    leaves: dict[int, m3.Manifold] = {}
    done: list[m3.Manifold] = []
    todo: list[tuple[Any, bool]] = [(solid, False)]
    while todo:
        node, expanded = todo.pop()
        if isinstance(node, (Union, Intersection, Difference)):
            if not expanded:
                todo.append((node, True))
                todo.extend((c, False) for c in reversed(node.children))
                continue
            k = len(node.children)
            kids = done[len(done) - k :]
            del done[len(done) - k :]
            if k == 1:
                done.append(kids[0])
            elif isinstance(node, Union):
                done.append(m3.Manifold.batch_boolean(kids, m3.OpType.Add))
            elif isinstance(node, Intersection):
                done.append(m3.Manifold.batch_boolean(kids, m3.OpType.Intersect))
            else:
                rest = kids[1] if k == 2 else m3.Manifold.batch_boolean(kids[1:], m3.OpType.Add)
                done.append(m3.Manifold.batch_boolean([kids[0], rest], m3.OpType.Subtract))
            continue
        mesh = leaves.get(id(node))
        if mesh is None:
            mesh = leaves[id(node)] = manifold_leaf(node, segments)
        done.append(mesh)
    return done[-1]


def manifold_slice(mesh: m3.Manifold, frame: np.ndarray) -> Polygon:
    """``Manifold.slice`` in the plane of ``frame`` (4 x 4: the plane's axes and origin as columns),
    as a shapely geometry in the plane's 2D frame (rings combined even-odd)."""
    R, o = frame[:3, :3], frame[:3, 3]
    to_frame = np.column_stack([R.T, -R.T @ o])
    rings = [Polygon(r) for r in mesh.transform(to_frame.tolist()).slice(0.0).to_polygons() if len(r) >= 3]
    rings = [shapely.make_valid(r) if not r.is_valid else r for r in rings]
    if not rings:
        return Polygon()
    # even-odd: holes cancel; pairwise, so that n rings cost n log n Booleans
    while len(rings) > 1:
        rings = [rings[i].symmetric_difference(rings[i + 1]) if i + 1 < len(rings) else rings[i]
                 for i in range(0, len(rings), 2)]
    return rings[0]


def leaf_primitives(solid: Any) -> list[Any]:
    """The primitives of a tree, depth first, left to right (explicit stack)."""
    out: list[Any] = []
    todo = [solid]
    while todo:
        node = todo.pop()
        if isinstance(node, (Union, Intersection, Difference)):
            todo.extend(reversed(node.children))
        else:
            out.append(node)
    return out
