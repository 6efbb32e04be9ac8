"""CSG trees over the primitives (union, intersection, difference).

The clipped band surface of a tree lives in :mod:`isocsg.csg.surface`
(imported on use: it needs the laminae).
"""

from .tree import (
    CSGNode,
    Difference,
    Intersection,
    Union,
    difference,
    intersection,
    leaves,
    union,
    union_all,
)

__all__ = [
    "CSGNode", "Union", "Intersection", "Difference", "union", "intersection", "difference", "union_all", "leaves",
]
