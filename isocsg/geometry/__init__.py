"""Analytic solids: the convex primitives (and, in :mod:`isocsg.csg`, their Boolean trees)."""

from .primitives import Box, Cone, ConvexPolyhedron, Cylinder, Primitive, RayHits, Solid, Sphere, Truncus

__all__ = ["Solid", "Primitive", "RayHits", "Sphere", "Truncus", "Cylinder", "Cone", "Box", "ConvexPolyhedron"]
