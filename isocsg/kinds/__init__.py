"""Primitive kinds: one interface (:class:`Primitive`), one module per kind, one table.

- :mod:`~isocsg.kinds.base`: :class:`Solid` and the kind interface :class:`Primitive`;
- :mod:`~isocsg.kinds.registry`: the live table of scene-file names (``register_kind``);
- one module per kind, holding all of its math and registering it where it is defined:
  :mod:`~isocsg.kinds.sphere`, :mod:`~isocsg.kinds.truncus` (with cylinder and cone),
  :mod:`~isocsg.kinds.box`, :mod:`~isocsg.kinds.polyhedron`,
  :mod:`~isocsg.kinds.ellipsoid`, :mod:`~isocsg.kinds.elliptic`,
  :mod:`~isocsg.kinds.torus` (the first non-convex kind), :mod:`~isocsg.kinds.mesh` (closed
  triangle meshes);
- helpers the kinds share: :mod:`~isocsg.kinds.planar` (plane sections),
  :mod:`~isocsg.kinds.meshing` (manifold3d), :mod:`~isocsg.kinds.scad` (OpenSCAD text),
  :mod:`~isocsg.kinds.forms` (exact forms: a kind as plain data, what ``projection`` and exact
  hulls read), :mod:`~isocsg.kinds.patches` (surfaces as families of rings, for the area integrals).

See ``docs/architecture.md`` ("Primitive kinds") for adding a kind.
"""

# isort: skip_file
# (the kinds register as they are imported: in the order of the scene files' table of kinds)
from .base import DEFAULT_RESOLUTION, LeafForm, LeafRow, Primitive, RayHits, Solid, provides
from .forms import AffineBall, AffineFrustum, PointHull, RingTorus, TriangleSurface
from .registry import PrimitiveKind, kind_named, kind_of, register_kind, registered_kinds, unregister_kind
from .sphere import Sphere
from .truncus import Cone, Cylinder, Truncus
from .box import Box
from .polyhedron import ConvexPolyhedron
from .ellipsoid import Ellipsoid
from .elliptic import EllipticTruncus
from .torus import Torus
from .mesh import TriangleMesh

__all__ = [
    "DEFAULT_RESOLUTION",
    "AffineBall",
    "AffineFrustum",
    "Box",
    "Cone",
    "ConvexPolyhedron",
    "Cylinder",
    "Ellipsoid",
    "EllipticTruncus",
    "LeafForm",
    "LeafRow",
    "PointHull",
    "Primitive",
    "PrimitiveKind",
    "RayHits",
    "RingTorus",
    "Solid",
    "Sphere",
    "Torus",
    "TriangleSurface",
    "TriangleMesh",
    "Truncus",
    "kind_named",
    "kind_of",
    "provides",
    "register_kind",
    "registered_kinds",
    "unregister_kind",
]
