"""Analytic solids: the convex primitives (and, in :mod:`isocsg.csg`, their Boolean trees)."""

from .primitives import Box, Cone, ConvexPolyhedron, Cylinder, Primitive, RayHits, Solid, Sphere, Truncus
from .ellipsoid import Ellipsoid
from .elliptic import EllipticTruncus
from .registry import PrimitiveKind, kind_named, kind_of, register_kind, registered_kinds

__all__ = [
    "Solid", "Primitive", "RayHits", "Sphere", "Truncus", "Cylinder", "Cone", "Box", "ConvexPolyhedron",
    "Ellipsoid", "EllipticTruncus", "PrimitiveKind", "register_kind", "kind_of", "kind_named", "registered_kinds",
]
