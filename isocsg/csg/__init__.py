"""CSG trees over the primitives (union, intersection, difference)."""

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

__all__ = ["CSGNode", "Union", "Intersection", "Difference", "union", "intersection", "difference", "union_all", "leaves"]
