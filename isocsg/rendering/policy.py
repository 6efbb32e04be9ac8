"""The renderer's tunables, in one place: cache sizes, when a CSG object gets a clipped
surface, the level of detail, per-pixel CSG buffers and the fill threads.

Everything here is read at call time (``policy.NAME``), so a test or a user may
change a value for one run.
"""

from __future__ import annotations

import os

__all__ = [
    "CSG_METHODS", "SURFACE_BUILDS", "PREPARED_CACHE_BYTES", "SURFACE_CACHE_BYTES", "GEOMETRY_CACHE_BYTES",
    "SURFACE_MAX_LEAVES", "LARGE_SURFACE_SHARE", "LOD_MEMORY", "SURFACE_MAX_TRIANGLES", "DENSE_MAX_LEAVES",
    "DENSE_MAX_BYTES", "TILE_MAX_BYTES", "IMAGE_PIXEL_BYTES", "LOD_PIXELS", "LOD_MIN_LEAVES", "MIN_CONTOURS",
    "CHORD_PIXELS", "MIN_SEGMENTS", "TABLE_LEAVES", "STRIPES", "STRIPE_MIN_PIXELS", "UNION_SPLIT_PIXELS",
    "LAST_CHUNKS", "ROWS_AHEAD", "CSG_SEEN_MEMORY", "RAY_LEAF_SIZE", "RAY_LEAF_PIXELS",
]

#: The ways a :class:`~isocsg.rendering.Renderer` resolves CSG objects (see its ``csg`` parameter).
CSG_METHODS = ("auto", "surface", "pixel")
#: Where its clipped surfaces are built (see its ``surface_build`` parameter).
SURFACE_BUILDS = ("background", "now")

#: Bytes kept by a renderer's caches of prepared band meshes (their arrays,
#: shared with the lamina cache's band meshes, and the quads and projection
#: made from them; never more than a quarter of the memory budget), CSG
#: surfaces and leaf geometry (each never more than an eighth of it).
PREPARED_CACHE_BYTES = 1 << 30
SURFACE_CACHE_BYTES = 512 << 20
GEOMETRY_CACHE_BYTES = 64 << 20
#: Under ``csg="auto"``, trees of at most this many leaves whose bands have at
#: most :data:`SURFACE_MAX_TRIANGLES` triangles in all get the clipped surface
#: from their second view on (its build started by that view). Larger trees
#: get it too, on the terms of :data:`LARGE_SURFACE_SHARE`.
SURFACE_MAX_LEAVES = 64
#: Trees of more than :data:`SURFACE_MAX_LEAVES` leaves: their clipped surface is
#: always built in the background (started once the second view is done,
#: whatever ``surface_build`` says, on a daemon thread that a process ending
#: meanwhile does not wait for; one such build at a time), its operands trimmed to the boxes where they matter
#: (:func:`isocsg.csg.surface.surface_from_bands`, ``trim``), and given up, the tree
#: staying per pixel, when its Booleans would need more than this fraction of
#: the memory budget (the views go on meanwhile and need the rest). Every view
#: until it is ready is per pixel; a view whose level of detail asks more
#: contours of a leaf than the surface has, or more than twice its segments, is
#: per pixel and starts a new build (at the finer of both counts).
LARGE_SURFACE_SHARE = 0.5
#: Leaves whose level-of-detail count a renderer remembers (the oldest are forgotten).
LOD_MEMORY = 1 << 18
SURFACE_MAX_TRIANGLES = 1_000_000
#: Per-pixel CSG over the object's whole screen rectangle (one buffer per
#: leaf) for at most this many leaves and bytes; screen tiles otherwise.
DENSE_MAX_LEAVES = 8
DENSE_MAX_BYTES = 256 << 20
#: Most bytes of one tile's per-pixel CSG buffers (each thread has its own).
TILE_MAX_BYTES = 32 << 20
#: Bytes per pixel of the image buffers (depth key, label and value).
IMAGE_PIXEL_BYTES = 16
#: Level of detail (``Renderer(adaptive_contours=True)``, the default): a leaf
#: whose unclipped screen rectangle spans ``e`` pixels needs about
#: ``N * e / LOD_PIXELS`` contours (at the default N = 64, bands about two
#: pixels apart); it gets ``N`` where that need is over ``N / 2``, and ``N / 2``
#: (never fewer than :data:`MIN_CONTOURS`, nor more than ``N``) where it is
#: not, so a small change of view rarely changes the count. Every count is
#: ``N`` or ``N / 2`` (or the floor, for N < 32): proportional to
#: ``N``, so the error still shrinks as ``N`` grows however small the leaf;
#: the floor keeps each band's value step (about range / 16) within the 0.05
#: accuracy bar.
LOD_PIXELS = 128.0
#: The level of detail applies to CSG objects of more than this many leaves, where
#: band builds dominate a render; a single primitive or a small tree gets the
#: requested count and the full tessellation (on a small object a 2x step in N
#: can leave the error where it was: a specular sphere's mean error was 0.00066 at
#: 16 contours and 0.00067 at 32, 0.00052 at 64).
LOD_MIN_LEAVES = 64
MIN_CONTOURS = 16
#: Tessellation by screen size (with the level of detail, default builder only):
#: a curved primitive ``e`` pixels across (radius about ``e / 2``) gets the
#: segments around it that keep the chord error ``r (1 - cos(pi / m))`` under
#: ``CHORD_PIXELS``, rounded up to a power of two, at least 16; at 128 (the
#: full tessellation, :data:`isocsg.laminae.builder.DEFAULT_SEGMENTS`) from
#: about 21 pixels on. The silhouette of a latitude-longitude mesh lies inside
#: the surface by more than one chord's sagitta (its faces span a ring gap and a
#: longitude gap, seen from any side): a sphere 47 pixels across on 64
#: segments (chord error 0.028 pixel) lost 24 of its 1748 pixels, below the
#: IoU bar of 0.99, so the bound is a fraction of what the silhouette may lose.
CHORD_PIXELS = 0.0125
MIN_SEGMENTS = 16

#: Under the level of detail (default builder), the leaves of a tree resolved in screen tiles
#: at most this many pixels across (their level-of-detail size, a bound of about twice a
#: hole's or a rod's diameter on screen) are drawn by exact rays, not bands
#: (:mod:`isocsg.rendering.small_leaves`), if their screen rectangle holds at most
#: :data:`RAY_LEAF_PIXELS` pixels: a leaf about a pixel across costs next to nothing.
RAY_LEAF_SIZE = 4.0
RAY_LEAF_PIXELS = 4096

#: Objects with at most this many leaves are resolved through a truth table of their program.
TABLE_LEAVES = 16
#: CSG objects whose per-pixel-or-surface decision a renderer remembers (the oldest are forgotten).
CSG_SEEN_MEMORY = 256

#: Stripes filled concurrently for one primitive on images of at least ``STRIPE_MIN_PIXELS``.
STRIPES = max(1, min(4, os.cpu_count() or 1))
STRIPE_MIN_PIXELS = 512 * 512
#: A leaf of a union is filled by several threads (row bands) from this many pixels per thread.
UNION_SPLIT_PIXELS = 1024
#: Row chunks of the last CSG leaf, shared by the main thread and the leaf worker.
LAST_CHUNKS = 6
#: Rows of tiles the main thread may build ahead of the tiles done.
ROWS_AHEAD = 2
