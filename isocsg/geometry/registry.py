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
  section (:func:`isocsg.csg.section.primitive_section`; default: the section
  of ``to_polyhedron``),
- ``surface(prim, lights, contours, eye, shininess, weights, segments) -> Surface``:
  the base mesh its isoluminance bands are cut from (:mod:`isocsg.laminae`);
  ``segments`` is None or a renderer's tessellation hint for a leaf small on
  screen (the least segments around a curved kind; others may ignore it),
- ``laminae(prim, light, contours) -> list`` and ``family(prim, light, contours)
  -> (normal, offsets, levels)``: the seed's planar contour laminae of one light
  and their planes (optional; curved kinds without planar contours have none
  and their bands carry the image),
- ``manifold(prim, resolution, shapes) -> manifold3d.Manifold`` (optional; by
  default the hull of ``to_polyhedron``; ``shapes`` is a dict a hook may use to
  build equal shapes once),
- ``distance(prim, points)`` and ``tangent(prim, points, tol)``: the signed
  distance and the tangent cone at boundary points that CSG membership uses
  (:mod:`isocsg.csg.membership`; defaults: the class's ``signed_distance`` and
  the tangent half-space of ``normals_at``),
- ``openscad(prim) -> str``: its OpenSCAD statement (:mod:`isocsg.openscad.writer`).

Hooks are given as ``"module:function"`` strings and imported on first use, so
that registering a kind imports nothing heavy and no cycle. A new kind is then
one module and one registration: the modules that dispatch on kinds (scene
files, sections, membership, bands, meshes, the OpenSCAD writer) call the hooks
of this table, for the built-in kinds too (their vectorised code is their
hooks). Hooks are looked up along the class's inheritance, so ``Cylinder`` and
``Cone`` use the hooks registered for ``Truncus``. Shadows' convex pieces come
from ``to_polyhedron``; the batched leaf tables of :mod:`isocsg.csg.section`
keep vectorised columns for spheres, trunci and axis-aligned boxes and reach
every other kind through ``extent`` and its ``section`` hook.
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
    section, surface, laminae, family, manifold, distance, tangent, openscad : str or None
        ``"module:function"`` hooks (see the module docstring); None where the
        kind has none (then a parent class's hook, or the dispatching module's
        default, applies).
    """

    name: str
    cls: type
    required: tuple[str, ...]
    optional: tuple[str, ...] = ()
    section: str | None = None
    surface: str | None = None
    laminae: str | None = None
    family: str | None = None
    manifold: str | None = None
    distance: str | None = None
    tangent: str | None = None
    openscad: str | None = None

    def hook(self, which: str) -> Callable[..., Any] | None:
        """The hook ``which`` (``"section"``, ``"surface"``, ...) as a function, or None."""
        ref = getattr(self, which)
        if ref is None:
            return None
        fn = _RESOLVED.get(ref)
        if fn is None:
            module, _, func = ref.partition(":")
            fn = _RESOLVED[ref] = getattr(importlib.import_module(module), func)
        return fn


_BY_NAME: dict[str, PrimitiveKind] = {}
_BY_CLASS: dict[type, PrimitiveKind] = {}
_RESOLVED: dict[str, Callable[..., Any]] = {}  # "module:function" -> the function, imported once


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
    """The hook ``which`` of ``prim``'s kind, or of the nearest registered parent class
    that has one (``Cylinder`` -> ``Truncus``); None when none has (the caller's default)."""
    for c in type(prim).__mro__:
        k = _BY_CLASS.get(c)
        if k is not None and getattr(k, which) is not None:
            return k.hook(which)
    return None


def _register_builtins() -> None:
    from .ellipsoid import Ellipsoid
    from .elliptic import EllipticTruncus
    from .primitives import Box, Cone, ConvexPolyhedron, Cylinder, Sphere, Truncus

    sec, mem, msh, lam, scad = "isocsg.csg.section", "isocsg.csg.membership", "isocsg.csg.mesh", "isocsg.laminae.kinds", "isocsg.openscad.writer"
    register_kind(
        PrimitiveKind(
            "sphere", Sphere, ("center", "radius"),
            section=f"{sec}:_sphere_section", surface=f"{lam}:sphere_band_surface",
            laminae=f"{lam}:sphere_contour_laminae", family=f"{lam}:sphere_family", manifold=f"{msh}:sphere_manifold",
            distance=f"{mem}:sphere_distance", tangent=f"{mem}:sphere_tangent", openscad=f"{scad}:sphere_scad",
        )
    )
    register_kind(
        PrimitiveKind(
            "truncus", Truncus, ("center", "axis", "r1", "r2"),
            section=f"{sec}:_truncus_section", surface=f"{lam}:truncus_band_surface",
            laminae=f"{lam}:truncus_contour_laminae", family=f"{lam}:truncus_family", manifold=f"{msh}:truncus_manifold",
            distance=f"{mem}:truncus_distance", tangent=f"{mem}:truncus_tangent", openscad=f"{scad}:truncus_scad",
        )
    )
    # Cylinders and cones are trunci: they inherit the truncus's hooks.
    register_kind(PrimitiveKind("cylinder", Cylinder, ("center", "axis", "radius")))
    register_kind(PrimitiveKind("cone", Cone, ("center", "axis", "radius")))
    register_kind(
        PrimitiveKind(
            "box", Box, ("center", "size"), ("orientation",),
            section=f"{sec}:_box_section", surface=f"{lam}:polyhedron_band_surface",
            laminae=f"{lam}:polyhedron_face_laminae", manifold=f"{msh}:box_manifold",
            distance=f"{mem}:box_distance", tangent=f"{mem}:polyhedral_tangent", openscad=f"{scad}:box_scad",
        )
    )
    register_kind(
        PrimitiveKind(
            "polyhedron", ConvexPolyhedron, ("vertices",),
            section=f"{sec}:_polyhedron_section", surface=f"{lam}:polyhedron_band_surface",
            laminae=f"{lam}:polyhedron_face_laminae", manifold=f"{msh}:polyhedron_manifold",
            distance=f"{mem}:polyhedron_distance", tangent=f"{mem}:polyhedral_tangent", openscad=f"{scad}:polyhedron_scad",
        )
    )
    register_kind(
        PrimitiveKind(
            "ellipsoid",
            Ellipsoid,
            ("center", "radii"),
            ("orientation",),
            section="isocsg.geometry.ellipsoid:ellipsoid_section",
            surface="isocsg.laminae.ellipsoid:ellipsoid_surface",
            manifold="isocsg.geometry.ellipsoid:ellipsoid_manifold",
            openscad=f"{scad}:ellipsoid_scad",
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
            openscad=f"{scad}:elliptic_truncus_scad",
        )
    )


_register_builtins()
