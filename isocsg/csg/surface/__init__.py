"""The boundary of a CSG solid as isoluminance bands: view-independent CSG.

Each leaf's surface bands (planar triangles of constant value, see
:mod:`isocsg.laminae`) are clipped in 3D against the other operands: the
band meshes are closed (:func:`close_mesh`), turned into manifold3d solids
whose triangles remember their band triangle, and combined with manifold3d's
exact mesh Booleans along the tree. Every triangle of the result lies on one
leaf's band triangle, so it keeps that band's constant value; where the
result's triangle faces the other way (the inside of a cut: the boundary of a
subtracted leaf, or of a leaf of an intersection seen from inside another),
it shows the band's reversed-normal value ``value_in``.

This is the design notes' "clip contour-aligned surface bands" resolution of
lamina ownership: each visible surface point takes the value of the leaf whose
boundary it lies on, decided once in object space. The renderer then fills
the result like any primitive (front faces, depth test), so a new viewpoint
costs a plain fill.

Scale. The tree is evaluated on axis-aligned boxes first: operands whose
boxes touch nothing they are combined with need no Boolean (a union keeps
them as they are, a difference drops the subtracted operands that miss its
first operand, an intersection drops what lies outside the common box), so
a leaf enters manifold3d only where it meets another operand, and the
Booleans that remain are manifold3d batch Booleans. All of it runs in a local
frame (the leaves' box mapped to [-1, 1]^3), since manifold3d's tolerances are
relative to the size and position of its meshes. For large trees
(``trim=True``), what is subtracted and the operands of intersections are cut
to the boxes where they matter first, and a difference of many cuts is parted
into slabs, so that each Boolean fits the memory bound.

Modules: :mod:`.closing` (band meshes welded closed), :mod:`.planning` (the
tree on boxes: which Booleans, what to cut, slabs, the memory budget),
:mod:`.booleans` (manifold3d batch Booleans, results read back),
:mod:`.coincident` (opposite coincident faces cancelled), :mod:`.result`
(:class:`CSGSurface`) and :mod:`.build` (:func:`surface_from_bands`,
:func:`csg_surface`).

Coincident faces. Regularised set operations leave no two coincident faces of
opposite orientation on a boundary, but manifold3d can leave such pairs (zero
volume fins and shells) where operands' faces coincide, e.g. in
``(S | C) - C`` or ``A - A``. Where two leaves have band triangles in one
plane, the result's triangles in those planes are tested, and those lying on
an opposite-facing triangle of the result are dropped
(:data:`COINCIDENT_DISTANCE`); a triangle only partly covered by opposite ones
keeps its part outside them.
"""


from __future__ import annotations

# The renderer gives freed heap memory back after a build.
from .build import csg_surface, surface_from_bands
from .closing import close_mesh
from .coincident import COINCIDENT_DISTANCE
from .planning import (
    BYTES_PER_BOOLEAN_TRIANGLE,
    BYTES_PER_PLAIN_TRIANGLE,
    TRIM_MARGIN,
    estimate_surface_bytes,
    estimate_surface_triangles,
    untrimmed_groups,
)
from .result import CSGSurface

__all__ = [
    "BYTES_PER_BOOLEAN_TRIANGLE",
    "BYTES_PER_PLAIN_TRIANGLE",
    "COINCIDENT_DISTANCE",
    "TRIM_MARGIN",
    "CSGSurface",
    "close_mesh",
    "csg_surface",
    "estimate_surface_bytes",
    "estimate_surface_triangles",
    "surface_from_bands",
    "untrimmed_groups",
]
