"""The primitive kinds under their former import path (modules outside :mod:`isocsg.kinds` that
still import from here; new code imports from :mod:`isocsg.kinds`)."""

from ..kinds.base import DEFAULT_RESOLUTION, Primitive, RayHits, Solid
from ..kinds.box import Box
from ..kinds.polyhedron import ConvexPolyhedron
from ..kinds.sphere import Sphere
from ..kinds.truncus import Cone, Cylinder, Truncus

__all__ = ["Solid", "Primitive", "Sphere", "Truncus", "Cylinder", "Cone", "Box", "ConvexPolyhedron", "RayHits", "DEFAULT_RESOLUTION"]
