"""What a primitive kind must provide, in one place, and the table of kinds.

A primitive kind is a frozen dataclass deriving from
:class:`~isocsg.geometry.primitives.Primitive` that implements, as methods:

- ``bounds`` (exact axis-aligned box) and ``extent(n)`` (support along a unit vector),
- ``contains(points, tol=...)`` and ``signed_distance(points)`` (the inside test),
- ``intersect_rays(origins, directions) -> RayHits`` (ray hits and outward normals),
- ``normals_at(points)`` (outward unit normals at surface points),
- ``volume`` (closed form),
- ``to_polyhedron(resolution)`` (an inscribed convex polyhedron: meshes and the
  convex pieces of shadows),
- ``to_dict()`` and the constructor's keyword fields (the scene-file form),
- ``_affine(A, t)`` (its image under an affine map, see :mod:`~isocsg.geometry.transforms`),

and registers, with :func:`register_kind`, its scene-file name and fields and
the functions that live next to the machinery they extend:

- ``section(prim, frame, resolution, area_exact) -> shapely Polygon``: the plane
  section (:func:`isocsg.csg.section.primitive_section`),
- ``surface(prim, lights, contours, eye, shininess) -> Surface``: the base mesh
  its isoluminance bands are cut from (:mod:`isocsg.laminae`),
- ``manifold(prim, resolution) -> manifold3d.Manifold`` (optional; by default the
  hull of ``to_polyhedron``).

Hooks are given as ``"module:function"`` strings and imported on first use, so
that registering a kind imports nothing heavy and no cycle. A new kind is then
one module and one registration: the modules that dispatch on kinds (scene
files, sections, membership, bands, meshes, shadows) consult this table for
any kind they do not handle themselves.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from ..errors import InvalidParameterError

__all__ = ["PrimitiveKind", "register_kind", "kind_of", "kind_named", "registered_kinds"]


@dataclass(frozen=True, slots=True)
class PrimitiveKind:
    """One registered primitive kind.

    Attributes
    ----------
    name : str
        The scene-file tag (``"sphere"``, ``"ellipsoid"``, ...).
    cls : type
        The primitive class (subclasses such as ``Cylinder`` register their own kind).
    required, optional : tuple of str
        The constructor's keyword fields as written in scene files.
    section, surface, manifold : str or None
        ``"module:function"`` hooks (see the module docstring); None where the
        dispatching module handles the kind itself.
    """

    name: str
    cls: type
    required: tuple[str, ...]
    optional: tuple[str, ...] = ()
    section: str | None = None
    surface: str | None = None
    manifold: str | None = None

    def hook(self, which: str) -> Callable[..., Any] | None:
        """The hook ``which`` (``"section"``, ``"surface"``, ``"manifold"``) as a function, or None."""
        ref = getattr(self, which)
        if ref is None:
            return None
        module, _, func = ref.partition(":")
        return getattr(importlib.import_module(module), func)  # type: ignore[no-any-return]


_BY_NAME: dict[str, PrimitiveKind] = {}
_BY_CLASS: dict[type, PrimitiveKind] = {}


def register_kind(kind: PrimitiveKind) -> PrimitiveKind:
    """Add a kind to the table; a name or class registered twice is refused.

    Raises
    ------
    InvalidParameterError
        If the name or the class is already registered.
    """
    if kind.name in _BY_NAME:
        raise InvalidParameterError(f"kind.name {kind.name!r} is already registered")
    if kind.cls in _BY_CLASS:
        raise InvalidParameterError(f"kind.cls {kind.cls.__name__} is already registered")
    _BY_NAME[kind.name] = kind
    _BY_CLASS[kind.cls] = kind
    return kind


def kind_of(prim: Any) -> PrimitiveKind | None:
    """The registered kind of a primitive, chosen by its class's inheritance (None if none)."""
    for c in type(prim).__mro__:
        k = _BY_CLASS.get(c)
        if k is not None:
            return k
    return None


def kind_named(name: str) -> PrimitiveKind | None:
    """The kind registered under a scene-file name, or None."""
    return _BY_NAME.get(name)


def registered_kinds() -> tuple[PrimitiveKind, ...]:
    """Every registered kind, in registration order."""
    return tuple(_BY_NAME.values())


def hook_for(prim: Any, which: str) -> Callable[..., Any] | None:
    """The hook ``which`` of ``prim``'s kind, or None when it has none (the caller handles it)."""
    k = kind_of(prim)
    return None if k is None else k.hook(which)


def _register_builtins() -> None:
    from .ellipsoid import Ellipsoid
    from .elliptic import EllipticTruncus
    from .primitives import Box, Cone, ConvexPolyhedron, Cylinder, Sphere, Truncus

    register_kind(PrimitiveKind("sphere", Sphere, ("center", "radius")))
    register_kind(PrimitiveKind("truncus", Truncus, ("center", "axis", "r1", "r2")))
    register_kind(PrimitiveKind("cylinder", Cylinder, ("center", "axis", "radius")))
    register_kind(PrimitiveKind("cone", Cone, ("center", "axis", "radius")))
    register_kind(PrimitiveKind("box", Box, ("center", "size"), ("orientation",)))
    register_kind(PrimitiveKind("polyhedron", ConvexPolyhedron, ("vertices",)))
    register_kind(
        PrimitiveKind(
            "ellipsoid",
            Ellipsoid,
            ("center", "radii"),
            ("orientation",),
            section="isocsg.geometry.ellipsoid:ellipsoid_section",
            surface="isocsg.laminae.ellipsoid:ellipsoid_surface",
            manifold="isocsg.geometry.ellipsoid:ellipsoid_manifold",
        )
    )
    register_kind(
        PrimitiveKind(
            "elliptic_truncus",
            EllipticTruncus,
            ("center", "matrix", "r1", "r2"),
            section="isocsg.geometry.elliptic:elliptic_section",
            surface="isocsg.laminae.elliptic:elliptic_surface",
            manifold="isocsg.geometry.elliptic:elliptic_manifold",
        )
    )


_register_builtins()
