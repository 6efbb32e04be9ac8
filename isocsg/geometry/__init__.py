"""Solids: the primitive kinds (:mod:`isocsg.kinds`), transforms and extrusions."""

from ..kinds import (
    Box,
    Cone,
    ConvexPolyhedron,
    Cylinder,
    Ellipsoid,
    EllipticTruncus,
    Primitive,
    PrimitiveKind,
    RayHits,
    Solid,
    Sphere,
    Truncus,
    kind_named,
    kind_of,
    register_kind,
    registered_kinds,
)

__all__ = [
    "Solid", "Primitive", "RayHits", "Sphere", "Truncus", "Cylinder", "Cone", "Box", "ConvexPolyhedron",
    "Ellipsoid", "EllipticTruncus", "PrimitiveKind", "register_kind", "kind_of", "kind_named", "registered_kinds",
]
