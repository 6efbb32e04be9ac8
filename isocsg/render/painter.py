"""Isoluminance rendering of a scene: band fill, per-pixel CSG, depth test.

Each primitive's surface bands (planar triangles of constant value, built by
:func:`isocsg.laminae.build_bands` and cached there because they do not
depend on the viewpoint) are filled with :mod:`isocsg.render.raster`:

- an object that is a single primitive needs its front surface only (back
  faces are culled), filled straight into the image with a depth test;
- an object that is a CSG tree fills the front *and* back surface of every
  leaf (the ray's interval ``[front, back]`` through the convex leaf) inside
  the leaf's screen rectangle (known from the tree before any band is
  built, so that a worker fills each leaf while the next one is built), then
  the tree's postfix program is evaluated
  per pixel on those intervals: the first depth where the result turns from
  outside to inside is the visible point. If it is leaf i's front the pixel
  shows i's ``value_out``; if it is leaf i's back (the inside of a cut), i's
  ``value_in``. Results that are empty along the ray stay background. Small
  trees use buffers over the object's whole rectangle; larger ones screen
  tiles that each hold only the leaves meeting them, with the program pruned
  to those (:mod:`isocsg.render.tiles`), so that memory grows with the pixels
  and the leaves' screen footprints, not with leaves x pixels;
- each primitive gets as many contours as its size on screen can show
  (:func:`screen_contours`), so that leaves of a few pixels cost little.

Several objects: the nearest visible point wins.
"""

from __future__ import annotations

import functools
import math
import os
import sys
import threading
import time
from collections import OrderedDict, deque
from collections.abc import Callable, Sequence
from concurrent.futures import Future, ThreadPoolExecutor, wait
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numba import njit
from numpy.typing import NDArray

from .._validation import integer, light_budget
from ..camera import Camera
from ..csg.surface import BYTES_PER_BOOLEAN_TRIANGLE, _release_freed_memory, surface_from_bands, untrimmed_groups
from ..csg.program import OP_LEAF, OP_UNION, Program, evaluate_mask
from ..csg.tree import CSGNode
from ..errors import InvalidGeometryError, InvalidParameterError, ResourceLimitError
from ..geometry.primitives import Primitive, Sphere
from ..lighting.lights import DirectionalLight, PointLight
from ..laminae.builder import DEFAULT_SEGMENTS
from ..laminae.model import BandMesh
from ..limits import check_memory, memory_budget
from ..scene.model import MAX_CONTOURS, Scene
from .raster import (
    _RAW, camera_affine, fill_front_kernel, fill_front_runs, fill_projected, fill_rect, key_to_depth, pair_quads,
    ball_covered, camera_rays, project_kernel,
)
from .scratch import SCRATCH
from .tiles import (
    LEAF_PIXEL_BYTES, LeafGeometry, clip_leaves, combine_rects, hidden_box, leaf_geometry,
    leaf_near_keys, leaf_rects, leaf_screen_sizes, open_tile_pixels, plan_tiles, tile_leaves,
)

__all__ = ["RenderResult", "RenderTimings", "Renderer", "render", "default_renderer"]

#: The ways a :class:`Renderer` resolves CSG objects (see its ``csg`` parameter).
CSG_METHODS = ("auto", "surface", "pixel")
SURFACE_BUILDS = ("background", "now")

#: ``build(primitive, lights, material, contours, eye=...) -> LaminaSet`` (or a BandMesh).
BandBuilder = Callable[..., Any]


@dataclass(frozen=True, slots=True)
class RenderTimings:
    """Wall-clock seconds spent in one render.

    Attributes
    ----------
    build : float
        Obtaining the band meshes (building them, or fetching them from cache).
        For a CSG object resolved per pixel, the leaves built first are filled
        by a worker thread meanwhile.
    fill : float
        The rest: projection, triangle fill, per-pixel CSG and composition of
        the image (``total`` is the render's wall-clock time).
    """

    build: float
    fill: float

    @property
    def total(self) -> float:
        """``build + fill``."""
        return self.build + self.fill


@dataclass(frozen=True, slots=True, eq=False)
class RenderResult:
    """An isoluminance image and what each pixel shows.

    Attributes
    ----------
    image : ndarray, shape (H, W), float32
        Intensity; NaN where no object is visible.
    timings : RenderTimings
    camera : Camera
        The camera the image was rendered with.

    The per-pixel indices and the depth are computed when first read (the
    fill itself only keeps one label per pixel).
    """

    image: NDArray[np.float32]
    timings: RenderTimings
    camera: Camera
    _label: NDArray[np.int32] = field(repr=False)
    _key: NDArray[np.float64] = field(repr=False)
    _object_of: NDArray[np.int32] = field(repr=False)
    _leaf_of: NDArray[np.int32] = field(repr=False)
    _lazy: dict[str, NDArray[Any]] = field(default_factory=dict, repr=False)

    @property
    def object_index(self) -> NDArray[np.int32]:
        """Index into ``scene.objects`` of the visible object per pixel, -1 on the background (int32)."""
        if "object" not in self._lazy:
            self._lazy["object"] = self._object_of[self._label + 1]
        return self._lazy["object"]

    @property
    def primitive_index(self) -> NDArray[np.int32]:
        """Index of the visible leaf in its object's ``CSGNode.program()`` leaves (0 for a
        primitive object), -1 on the background (int32)."""
        if "leaf" not in self._lazy:
            self._lazy["leaf"] = self._leaf_of[self._label + 1]
        return self._lazy["leaf"]

    def _repr_mimebundle_(self, include: Any = None, exclude: Any = None) -> dict[str, Any]:
        """Rich display in Jupyter: a small PNG image (see :mod:`isocsg.interop.notebook`)."""
        from ..interop.notebook import mimebundle

        return mimebundle(self, include, exclude)

    def _repr_png_(self) -> bytes | None:
        """A small PNG image of the object (see :mod:`isocsg.interop.notebook`)."""
        from ..interop.notebook import mimebundle

        return mimebundle(self, ("image/png",)).get("image/png")

    @property
    def depth(self) -> NDArray[np.float64]:
        """Camera depth (along the view direction) of the visible point; ``inf`` on the background."""
        if "depth" not in self._lazy:
            d = np.empty(self._key.shape)
            key_to_depth(np.where(self._label >= 0, self._key, np.inf), not self.camera.orthographic, d)
            self._lazy["depth"] = d
        return self._lazy["depth"]


# --------------------------------------------------------------------- kernels
#: Objects with at most this many leaves are resolved through a truth table of their program.
_TABLE_LEAVES = 16


@njit(cache=True)
def truth_table(op: NDArray[np.int8], arg: NDArray[np.int64], n: int) -> NDArray[np.bool_]:
    """The program's value for every inside-mask of ``n`` leaves (bit i: inside leaf i)."""
    table = np.zeros(1 << n, np.bool_)
    inside = np.zeros(max(n, 1), np.bool_)
    stack = np.zeros(max(len(op), 1), np.bool_)
    for m in range(1 << n):
        for i in range(n):
            inside[i] = (m >> i) & 1 == 1
        table[m] = evaluate_mask(op, arg, inside, stack)
    return table


@functools.lru_cache(maxsize=64)
def _cached_table(op: bytes, arg: bytes, n: int) -> NDArray[np.bool_]:
    # 2**n evaluations of the program (milliseconds at 16 leaves): once per tree, not per render.
    return truth_table(np.frombuffer(op, np.int8), np.frombuffer(arg, np.int64), n)


def _table(op: NDArray[np.int8], arg: NDArray[np.int64], n: int) -> NDArray[np.bool_]:
    """The truth table of a program of ``n`` leaves if ``n`` is at most :data:`_TABLE_LEAVES`, else empty."""
    if n > _TABLE_LEAVES:
        return np.zeros(0, np.bool_)
    return _cached_table(op.tobytes(), arg.tobytes(), n)


@njit(cache=True, inline="always")
def _state(table: NDArray[np.bool_], op: NDArray[np.int8], arg: NDArray[np.int64], inside: NDArray[np.bool_],
           stack: NDArray[np.bool_], mask: int) -> bool:
    if len(table):
        return table[mask]
    return evaluate_mask(op, arg, inside, stack)


#: Relative depth-key difference below which surfaces of different leaves coincide.
_COINCIDENT = 1e-9


@njit(cache=True, nogil=True)
def resolve_csg(
    kf: NDArray[np.float64], vf: NDArray[np.float32], kb: NDArray[np.float64], vb: NDArray[np.float32],
    op: NDArray[np.int8], arg: NDArray[np.int64], table: NDArray[np.bool_], gid_base: int, ox: int, oy: int,
    zkey: NDArray[np.float64], value: NDArray[np.float32], gid: NDArray[np.int32],
) -> None:
    """Per-pixel CSG on leaf intervals, depth-tested into the image buffers.

    ``op`` and ``arg`` are the object's :class:`~isocsg.csg.program.Program`
    arrays; ``table`` is their :func:`truth_table` (or empty: the program
    is then evaluated on each event).

    ``kf``/``kb`` (n, h, w) are the depth keys of each leaf's front (``+inf``
    where none) and back (``-inf`` where none) over the viewport at
    ``(oy, ox)``; a back without a front means the eye is inside that leaf.
    The leaves' surfaces are visited nearest first; all events at the same
    depth (within a relative ``1e-9``: coincident faces of different leaves
    are different triangles) are applied together (regularised operations:
    touching or coincident surfaces do not show), and the first depth where the program
    turns from outside to inside is the visible point. If a leaf enters there,
    the pixel shows that leaf's front value, otherwise the back value of a leaf
    that leaves.
    """
    n, h, w = kf.shape
    lr0 = np.full(n, oy, np.int64)
    lc0 = np.full(n, ox, np.int64)
    lh = np.full(n, h, np.int64)
    lw = np.full(n, w, np.int64)
    off = np.arange(n) * (h * w)
    _resolve_packed(np.ascontiguousarray(kf).reshape(-1), np.ascontiguousarray(vf).reshape(-1),
                    np.ascontiguousarray(kb).reshape(-1), np.ascontiguousarray(vb).reshape(-1),
                    off, lr0, lc0, lh, lw, np.arange(n), op, arg, table, gid_base, oy, oy + h, ox, ox + w,
                    zkey, value, gid, np.empty(n), np.empty(n, np.int8), np.zeros(n, np.bool_),
                    np.zeros(max(len(op), 1), np.bool_), np.zeros(n, np.int64))


# Without reference counting (see isocsg.render.raster): the per-pixel loop
# passes arrays to inlined helpers, two atomic operations each otherwise.
@njit(**_RAW)
def _resolve_packed(
    kf: NDArray[np.float64], vf: NDArray[np.float32], kb: NDArray[np.float64], vb: NDArray[np.float32],
    off: NDArray[np.int64], lr0: NDArray[np.int64], lc0: NDArray[np.int64], lh: NDArray[np.int64], lw: NDArray[np.int64],
    ids: NDArray[np.int64], op: NDArray[np.int8], arg: NDArray[np.int64], table: NDArray[np.bool_], gid_base: int,
    row0: int, row1: int, col0: int, col1: int,
    zkey: NDArray[np.float64], value: NDArray[np.float32], gid: NDArray[np.int32],
    nxt: NDArray[np.float64], phase: NDArray[np.int8], inside: NDArray[np.bool_], stack: NDArray[np.bool_],
    loc: NDArray[np.int64],
) -> None:
    """:func:`resolve_csg` over image rows ``row0 .. row1`` and columns ``col0 .. col1``
    with each leaf's buffers packed: leaf ``i`` covers the rectangle of
    ``lh[i]`` rows and ``lw[i]`` columns at ``(lr0[i], lc0[i])``, stored row by
    row from ``off[i]`` in the flat ``kf``, ``vf``, ``kb``, ``vb``; outside it
    the leaf is absent. Pixels take the label ``gid_base + ids[i]``. The last
    five arrays are scratch (``n`` entries each, ``stack`` one per instruction)."""
    # phase: 0 before the leaf's front, 1 inside, 2 past its back.
    n = off.shape[0]
    use_table = len(table) > 0
    for rr in range(row0, row1):
        for cc in range(col0, col1):
            covered = False
            mask = 0
            for i in range(n):
                dr = rr - lr0[i]
                dc = cc - lc0[i]
                if dr < 0 or dr >= lh[i] or dc < 0 or dc >= lw[i]:
                    inside[i] = False
                    phase[i] = 2
                    nxt[i] = np.inf
                    continue
                k = off[i] + dr * lw[i] + dc
                loc[i] = k
                f = kf[k]
                b = kb[k]
                if b == -np.inf:  # no interval (a front without a back is a zero-width sliver)
                    inside[i] = False
                    phase[i] = 2
                    nxt[i] = np.inf
                elif f == np.inf:  # entered behind the near plane
                    inside[i] = True
                    if use_table:
                        mask |= 1 << i
                    phase[i] = 1
                    nxt[i] = b
                    covered = True
                else:
                    inside[i] = False
                    phase[i] = 0
                    nxt[i] = f
                    covered = True
            if not covered:
                continue
            state = _state(table, op, arg, inside, stack, mask)
            limit = zkey[rr, cc]
            while True:
                key = np.inf
                for i in range(n):
                    if nxt[i] < key:
                        key = nxt[i]
                if key == np.inf or key >= limit:
                    break  # no more surfaces, or something nearer is already drawn
                # Coincident surfaces of different leaves (a cutter's face on the
                # solid's face) come from different triangles: their keys agree only
                # to rounding, so events this close are one event.
                group = key + _COINCIDENT * abs(key)
                shown = -1
                shown_front = False
                for i in range(n):
                    if nxt[i] > group:
                        continue
                    if phase[i] == 0:
                        inside[i] = True
                        phase[i] = 1
                        nxt[i] = kb[loc[i]]
                        if nxt[i] <= group:  # zero width: in and out at once
                            inside[i] = False
                            phase[i] = 2
                            nxt[i] = np.inf
                        if not shown_front:
                            shown = i
                            shown_front = True
                    else:
                        inside[i] = False
                        phase[i] = 2
                        nxt[i] = np.inf
                        if shown < 0:
                            shown = i
                    if use_table:
                        mask = (mask | (1 << i)) if inside[i] else (mask & ~(1 << i))
                now = _state(table, op, arg, inside, stack, mask)
                if now and not state:
                    zkey[rr, cc] = key
                    value[rr, cc] = vf[loc[shown]] if shown_front else vb[loc[shown]]
                    gid[rr, cc] = gid_base + ids[shown]
                    break
                state = now


# ------------------------------------------------------------------- renderer
_QUADS_LOCK = threading.Lock()


class _Projected:
    """A mesh's projection scratch: one (7, V) array per fill thread, made on first use and reused."""

    __slots__ = ()
    vertices: NDArray[np.float64]
    projs: list[NDArray[np.float64]]

    def proj(self, k: int = 0) -> NDArray[np.float64]:
        while len(self.projs) <= k:
            self.projs.append(np.empty((7, len(self.vertices))))
        return self.projs[k]


@dataclass(frozen=True, slots=True, eq=False)
class _Prepared(_Projected):
    vertices: NDArray[np.float64]
    triangles: NDArray[np.int32]
    value_out: NDArray[np.float32]
    value_in: NDArray[np.float32]
    projs: list[NDArray[np.float64]]  # (7, V) scratch of project_kernel per fill thread, reused
    _quads: list[tuple[NDArray[np.int32], NDArray[np.float32], NDArray[np.float32]]] = field(default_factory=list)

    def quads(self) -> tuple[NDArray[np.int32], NDArray[np.float32], NDArray[np.float32]]:
        """pair_quads of the triangles and their ``value_out`` and ``value_in`` (made when first needed)."""
        if not self._quads:
            with _QUADS_LOCK:  # made once, by whichever thread asks first
                if not self._quads:
                    quads, source = pair_quads(self.vertices, self.triangles, self.value_out, self.value_in)
                    self._quads.append((quads, self.value_out[source], self.value_in[source]))
        return self._quads[0]

    @property
    def nbytes(self) -> int:
        """About the bytes held: the arrays, the quads (made or to be made: about 12 bytes per
        triangle, half as many quads as triangles at 24 bytes) and the projections made so far
        (a tiled fill projects into its own scratch; a plain fill keeps one per thread)."""
        nv, nt = len(self.vertices), len(self.triangles)
        quads = sum(a.nbytes for a in self._quads[0]) if self._quads else 12 * nt
        projs = sum(p.nbytes for p in self.projs) if self.projs else 56 * nv
        return self.vertices.nbytes + self.triangles.nbytes + 8 * nt + quads + projs

    @property
    def tiled_nbytes(self) -> int:
        """:attr:`nbytes` of a mesh filled only in screen tiles (which project into their own scratch)."""
        return self.nbytes - (0 if self.projs else 56 * len(self.vertices))


@dataclass(frozen=True, slots=True, eq=False)
class _Front:
    """What the front-face fill of a union's leaf needs of its band mesh: the vertices, the
    quads and their outside values (about half the bytes of a :class:`_Prepared`, so that
    twice as many leaves stay cached)."""

    vertices: NDArray[np.float64]
    polys: NDArray[np.int32]
    values: NDArray[np.float32]

    @property
    def nbytes(self) -> int:
        return self.vertices.nbytes + self.polys.nbytes + self.values.nbytes


@dataclass(eq=False)
class _Runs(_Projected):
    """A large tree's clipped surface as one mesh to fill: the leaves' parts' quads in
    consecutive runs, one per leaf, so a view projects and fills it in one call each."""

    vertices: NDArray[np.float64]
    polys: NDArray[np.int32]
    values: NDArray[np.float32]
    starts: NDArray[np.int64]  # run r: polys starts[r] .. starts[r + 1]
    vstarts: NDArray[np.int64]  # run r's polygons use vertices vstarts[r] .. vstarts[r + 1]
    leaves: NDArray[np.int64]  # the leaf of each run
    projs: list[NDArray[np.float64]] = field(default_factory=list)

    @classmethod
    def of(cls, parts: list[tuple[int, _Prepared]]) -> "_Runs":
        if not parts:  # an empty result
            return cls(np.zeros((0, 3)), np.zeros((0, 4), np.int32), np.zeros(0, np.float32), np.zeros(1, np.int64),
                       np.zeros(1, np.int64), np.zeros(0, np.int64))
        nv = np.cumsum([0] + [len(p.vertices) for _, p in parts])
        quads = [p.quads() for _, p in parts]
        polys = np.vstack([np.where(q[0] >= 0, q[0] + np.int32(o), -1) for q, o in zip(quads, nv[:-1])]).astype(np.int32)
        values = np.concatenate([q[1] for q in quads]).astype(np.float32)
        starts = np.cumsum([0] + [len(q[0]) for q in quads]).astype(np.int64)
        vertices = np.vstack([p.vertices for _, p in parts])
        return cls(vertices, polys, values, starts, nv.astype(np.int64), np.array([i for i, _ in parts], np.int64))

    def quads(self) -> tuple[NDArray[np.int32], NDArray[np.float32]]:
        return self.polys, self.values

    @property
    def nbytes(self) -> int:
        """The arrays and the projection scratch (made or to be made, one per fill thread)."""
        arrays = sum(a.nbytes for a in (self.vertices, self.polys, self.values, self.starts, self.vstarts, self.leaves))
        return arrays + max(len(self.projs), _STRIPES) * 56 * len(self.vertices)


def _mesh_bytes(bands: BandMesh) -> int:
    """Bytes of a band mesh's arrays."""
    return sum(a.nbytes for a in (bands.vertices, bands.triangles, bands.value_out, bands.value_in, bands.band))


def _band_bytes(bands: BandMesh) -> int:
    """Bytes of a band mesh's arrays that a prepared mesh does not share."""
    return sum(a.nbytes for a in (bands.value_out, bands.value_in, bands.band))


class _ByteCache:
    """A mapping bounded by the bytes of its values (as told on insertion).

    Least recently used entries go first. A scan-resistant cache (the prepared
    band meshes) is more careful: entries remember the pass (a render, see :meth:`new_pass`) that last used
    them. Room for a new entry is made by dropping the least recently used
    entries that neither this pass nor the previous one used; when only such
    entries are left, the new one is not kept. So a model whose working set is
    larger than the cache keeps a stable part of it from one view to the next
    (plain LRU under the cyclic order of a render would drop exactly what the
    next view needs first), and a model that fits is never rebuilt; an entry
    alone over the limit is not kept. Otherwise the newest entry is kept, even
    over the limit, when the cache is otherwise empty.
    """

    def __init__(self, limit: int, *, scan_resistant: bool = False, share: int = 8) -> None:
        self.limit = int(limit)
        self.share = int(share)  # never more than this fraction (1 / share) of the memory budget
        self.scan_resistant = bool(scan_resistant)
        self.nbytes = 0
        self.generation = 0
        self._items: OrderedDict[Any, tuple[Any, int, int]] = OrderedDict()

    def __len__(self) -> int:
        return len(self._items)

    def new_pass(self) -> None:
        """Begin a pass (a render): what the previous pass used stays protected during this one."""
        self.generation += 1

    def get(self, key: Any) -> Any:
        hit = self._items.get(key)
        if hit is None:
            return None
        self._items.move_to_end(key)
        if hit[2] != self.generation:
            self._items[key] = (hit[0], hit[1], self.generation)
        return hit[0]

    def put(self, key: Any, value: Any, nbytes: int) -> bool:
        """Keep ``value`` under ``key``; returns whether it was kept."""
        old = self._items.pop(key, None)
        if old is not None:
            self.nbytes -= old[1]
        nbytes = int(nbytes)
        limit = min(self.limit, memory_budget() // self.share)
        if self.scan_resistant and nbytes > limit:
            return False  # alone over the limit: it would only block the entries that fit
        items = self._items
        while self.nbytes + nbytes > limit and items:
            first = next(iter(items.values()))
            if self.scan_resistant and first[2] >= self.generation - 1:
                return False  # everything left is in use by this pass or the previous one
            self.nbytes -= items.popitem(last=False)[1][1]
        items[key] = (value, nbytes, self.generation)
        self.nbytes += nbytes
        return True

    def clear(self) -> None:
        self._items.clear()
        self.nbytes = 0


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
_SEGMENT_SHIFT = 16
_CONTOUR_MASK = (1 << _SEGMENT_SHIFT) - 1


def screen_contours(extent: NDArray[np.float64], contours: int) -> NDArray[np.int64]:
    """Contour count of each leaf from its screen size in pixels (see :data:`LOD_PIXELS`).

    Parameters
    ----------
    extent : ndarray, shape (n,)
        The larger side of each leaf's unclipped screen rectangle in pixels
        (``inf`` for a leaf reaching behind the eye).
    contours : int
        N, the requested count.

    Returns
    -------
    ndarray of int64, shape (n,)

    Examples
    --------
    >>> screen_contours(np.array([3.0, 40.0, 64.0, 65.0, 1000.0, np.inf]), 64).tolist()
    [32, 32, 32, 64, 64, 64]
    >>> screen_contours(np.array([3.0, 40.0, 64.0, 65.0, 1000.0]), 256).tolist()
    [128, 128, 128, 256, 256]
    >>> screen_contours(np.array([3.0, 40.0, 1000.0]), 16).tolist()
    [16, 16, 16]
    >>> screen_contours(np.array([3.0, 40.0]), 8).tolist()
    [8, 8]
    """
    e = np.nan_to_num(np.asarray(extent, dtype=np.float64), nan=np.inf, posinf=np.inf)
    need = contours * e / LOD_PIXELS
    half = min(contours, max(MIN_CONTOURS, (contours + 1) // 2))
    return np.where(need > contours / 2, contours, half).astype(np.int64)


def screen_segments(extent: NDArray[np.float64]) -> NDArray[np.int64]:
    """Tessellation segments of each leaf from its screen size in pixels (see :data:`CHORD_PIXELS`).

    Examples
    --------
    >>> screen_segments(np.array([4.0, 20.0, 60.0, 200.0, 400.0, np.inf])).tolist()
    [32, 64, 128, 128, 128, 128]
    """
    r = np.nan_to_num(np.asarray(extent, dtype=np.float64), nan=np.inf, posinf=np.inf) / 2
    with np.errstate(invalid="ignore", over="ignore"):
        m = np.pi * np.sqrt(np.maximum(r, 1.0) / (2.0 * CHORD_PIXELS))  # sagitta r pi^2 / (2 m^2)
        m = np.exp2(np.ceil(np.log2(np.minimum(m, 1e6))))
    return np.clip(m, MIN_SEGMENTS, DEFAULT_SEGMENTS).astype(np.int64)


@njit(cache=True, nogil=True)
def _fill_leaf(
    kf: NDArray[np.float64], vf: NDArray[np.float32], kb: NDArray[np.float64], vb: NDArray[np.float32],
    off: int, r0: int, c0: int, h: int, w: int, proj: NDArray[np.float64], quads: NDArray[np.int32],
    vout: NDArray[np.float32], vin: NDArray[np.float32], near: float, perspective: bool,
) -> None:
    """One leaf's front and back surfaces into its packed rectangle (see :func:`_resolve_packed`)."""
    zf = kf[off : off + h * w].reshape((h, w))
    zb = kb[off : off + h * w].reshape((h, w))
    zf[:] = np.inf
    zb[:] = -np.inf
    fill_projected(proj, quads, vout, vin, near, perspective, c0, r0, zf, vf[off : off + h * w].reshape((h, w)),
                   zb, vb[off : off + h * w].reshape((h, w)))


_HUGE_PAGE = 2 << 20


def _staggered_empty(shape: tuple[int, ...], dtype: Any, k: int) -> NDArray[Any]:
    """A zeroed ``(shape, dtype)`` array starting ``64 * (k % 37) + 64`` bytes into a page.

    Large allocations all start at the same offset within a 4 KiB page; a loop
    that reads one such buffer and writes another at the same index then
    stalls on every store (4K aliasing: the processor cannot tell the
    addresses apart by their low 12 bits). Staggering the starts avoids it.
    """
    dt = np.dtype(dtype)
    nbytes = math.prod(shape) * dt.itemsize
    # Large buffers start on a 2 MiB boundary (plus the stagger), so that the
    # kernel can back them with huge pages: a fill walks down many rows at
    # once, and with 4 KiB pages every row is another TLB entry.
    align = _HUGE_PAGE if nbytes >= 2 * _HUGE_PAGE else 4096
    raw = np.empty(nbytes + align + 4096, np.uint8)
    # Touch every page now: reading pages that were never written (the value
    # buffer outside the objects) page-faults on every pass on some kernels.
    raw.fill(0)
    start = (-raw.ctypes.data) % align + 64 * (k % 37) + 64
    return raw[start : start + nbytes].view(dt).reshape(shape)


class Renderer:
    """Renders scenes with the isoluminance method, reusing band meshes.

    Parameters
    ----------
    build_laminae : callable, optional
        ``build_laminae(primitive, lights, material, contours, eye=eye)``
        returning a :class:`~isocsg.laminae.model.LaminaSet` (or a
        :class:`~isocsg.laminae.model.BandMesh`). Defaults to
        :func:`isocsg.laminae.build_bands` (the bands of
        :func:`~isocsg.laminae.build_laminae` without the laminae), which caches the
        view-independent bands, so rendering from a new viewpoint only fills.
        The band mesh must lie within the primitive (CSG screen tiles and
        occlusion culling bound it by the primitive's box and ball).
    csg : {"auto", "surface", "pixel"}, default "auto"
        How CSG objects are resolved. ``"pixel"``: per pixel on the leaves'
        depth intervals (exact, nothing to build). ``"surface"``: the leaves'
        bands clipped once in 3D (:func:`isocsg.csg.surface.surface_from_bands`,
        manifold3d Booleans) and cached, so that every later view is a plain
        fill. ``"auto"``: per pixel the first time an object is rendered; from
        its second render on (a new viewpoint of the same bands), the surface,
        built then and cached, if the tree has at most
        :data:`SURFACE_MAX_LEAVES` leaves and its bands at most
        :data:`SURFACE_MAX_TRIANGLES` triangles. Larger trees get it too,
        always built in the background with their operands trimmed, and only
        if its Booleans fit :data:`LARGE_SURFACE_SHARE` of the memory budget
        (else they stay per pixel). Objects with view-dependent (specular)
        bands use ``"pixel"`` under ``"auto"``. A union of leaves needs
        neither under ``"auto"`` and ``"pixel"``: its leaves are filled by the
        depth test, nearest first, and those hidden by nearer ones are skipped
        before their bands are built (occlusion culling).
    surface_build : {"background", "now"}, default "background"
        Under ``csg="auto"``, where the clipped surface is built.
        ``"background"``: on a thread of its own, started by the object's
        second view, which is resolved per pixel like the first (so no view
        waits for a Boolean); the first view after the surface is ready uses
        it (:meth:`wait_surfaces` waits for it). ``"now"``: on the second
        view's own path, which it delays by the build.
    adaptive_contours : bool, default True
        The level of detail, for CSG objects of more than
        :data:`LOD_MIN_LEAVES` (64) leaves. ``True``: each of their leaves
        gets contours by its size on screen (:func:`screen_contours`): a
        primitive ``e`` pixels across needs about ``N * e / 128`` (bands about
        two pixels apart at N = 64) and gets ``N``, or ``N / 2`` where that
        need allows (never fewer than :data:`MIN_CONTOURS`, 16, which keeps
        every pixel within 0.05 of the range, nor more than ``N``);
        primitives 64 pixels across or more get ``N`` (at N = 64). Every count
        is ``N`` or ``N / 2``, so the error still shrinks as ``N`` grows. A
        primitive keeps the larger count an earlier view of this renderer gave
        it (its bands are then reused). The default builder also coarsens
        the tessellation by the same screen size (see
        :func:`isocsg.laminae.build_bands`, ``pixels``). ``False``: every
        primitive gets the requested count and the full tessellation.

    Examples
    --------
    Any builder with the same call signature works, e.g. one face value per
    box face (the box's own triangles, outward and counter-clockwise):

    >>> from isocsg import Box, Camera, PointLight, Scene
    >>> from isocsg.laminae.model import BandMesh
    >>> def faces(primitive, lights, material, contours, *, eye):
    ...     poly = primitive.to_polyhedron()
    ...     t = np.asarray(poly.triangles, dtype=np.int32)
    ...     level = np.arange(len(t)) // 2 / 10.0  # two triangles per face
    ...     return BandMesh(poly.hull_vertices, t, level, level, np.zeros(len(t), np.int32))
    >>> cam = Camera((0, -5, 0), (0, 0, 0), width=32, height=32)
    >>> scene = Scene(cam, [PointLight((3, -5, 4))], [Box((0, 0, 0), (1, 1, 1))])
    >>> result = Renderer(build_laminae=faces).render(scene)
    >>> result.image.shape, int(np.isfinite(result.image).sum()) > 0
    ((32, 32), True)
    >>> int(result.object_index.max()), int(result.primitive_index.min())
    (0, -1)
    """

    def __init__(
        self, build_laminae: BandBuilder | None = None, *, csg: str = "auto", adaptive_contours: bool = True,
        surface_build: str = "background",
    ) -> None:
        if csg not in CSG_METHODS:
            raise InvalidParameterError(f"csg must be one of {', '.join(CSG_METHODS)}, got {csg!r}")
        if surface_build not in SURFACE_BUILDS:
            raise InvalidParameterError(
                f"surface_build must be one of {', '.join(SURFACE_BUILDS)}, got {surface_build!r}")
        self.surface_build = surface_build
        # Surfaces being built in the background: key -> future (guarded by _surface_lock).
        self._building: dict[tuple[Any, ...], Future[None]] = {}
        self._surface_lock = threading.Lock()
        self._build = build_laminae
        self.csg = csg
        self.adaptive_contours = bool(adaptive_contours)
        # (leaf, lights, material, N) -> the contour count its last view used under the
        # level of detail (below N only): a later view needing fewer reuses those bands.
        self._lod: OrderedDict[tuple[Any, ...], tuple[int, int]] = OrderedDict()
        # CSG surfaces (leaf band meshes clipped in 3D), keyed by the leaves' band
        # meshes and the program: (band meshes kept alive, leaf parts).
        self._surfaces = _ByteCache(SURFACE_CACHE_BYTES)
        # Arrays converted for the kernels, keyed by the band mesh's identity: (band mesh, prepared).
        self._prepared = _ByteCache(PREPARED_CACHE_BYTES, scan_resistant=True, share=4)
        # The default builder's view-independent bands are kept here by request
        # (primitive, lights, material, contours), so a new view asks it for nothing.
        self._by_request = build_laminae is None
        # Leaves' bounding boxes, keyed by the program's identity: (program, LeafGeometry).
        self._geometry = _ByteCache(GEOMETRY_CACHE_BYTES)
        # Image-sized buffers reused from one render to the next once no result
        # refers to them any more: fresh pages cost more than the fill itself.
        self._pool: OrderedDict[tuple[str, tuple[int, ...], str], list[NDArray[Any]]] = OrderedDict()
        self._lock = threading.Lock()
        # id of a pooled buffer -> (row0, row1, col0, col1) that may differ from its background.
        self._dirty: dict[int, tuple[int, int, int, int]] = {}
        # CSG objects already resolved per pixel -> whether they stay per pixel (view-dependent
        # bands, or a surface too large to build). Keys only: bounded by a count.
        self._csg_seen: OrderedDict[tuple[Any, ...], bool] = OrderedDict()
        # Large trees' surface builds decided by the render in progress, started at its end.
        self._deferred: dict[tuple[Any, ...], tuple[Any, ...]] = {}

    def _buffer(self, name: str, shape: tuple[int, ...], dtype: Any) -> NDArray[Any]:
        key = (name, shape, np.dtype(dtype).str)
        pool = self._pool.setdefault(key, [])
        self._pool.move_to_end(key)
        for a in pool:
            # Held only by the pool, this loop and getrefcount's argument: free to reuse.
            if sys.getrefcount(a) <= 3:
                return a
        a = _staggered_empty(shape, dtype, sum(len(p) for p in self._pool.values()))
        pool.append(a)
        if len(pool) > 3:
            self._dirty.pop(id(pool.pop(0)), None)
        while len(self._pool) > 24:
            for old in self._pool.popitem(last=False)[1]:
                self._dirty.pop(id(old), None)
        return a

    def _stale(self, name: str, shape: tuple[int, int], dtype: Any) -> tuple[NDArray[Any], tuple[int, int, int, int]]:
        """A pooled private buffer and the rectangle that must be reset to its background
        (what its last render wrote; all of it for a fresh buffer)."""
        a = self._buffer(name, shape, dtype)
        rect = self._dirty.pop(id(a), (0, shape[0], 0, shape[1]))
        # Until the render records what it wrote, assume everything.
        self._dirty[id(a)] = (0, shape[0], 0, shape[1])
        return a, rect

    def _builder(self) -> BandBuilder:
        if self._build is None:
            from ..laminae import build_bands

            self._build = build_bands
        return self._build

    def bands(self, primitive: Primitive, lights: Sequence[Any], material: Any, contours: int, eye: Any) -> BandMesh:
        """The band mesh of one primitive (from the builder and its cache)."""
        return self._bands(primitive, lights, material, contours, eye)[0]

    def _bands(
        self, primitive: Primitive, lights: Sequence[Any], material: Any, contours: int, eye: Any,
        hidden: Any = None,
    ) -> tuple[BandMesh, bool]:
        # ``contours`` may carry the tessellation's segments above _SEGMENT_SHIFT (see _contours);
        # ``hidden`` (the default builder only, see _visible_leaves) the box outside which nothing shows.
        n, segments = int(contours) & _CONTOUR_MASK, int(contours) >> _SEGMENT_SHIFT
        extra: dict[str, Any] = {}
        if segments:
            extra["segments"] = segments
        if hidden is not None:
            # A large tree's bands are kept here, by request, and only here: the lamina cache
            # would hold another share of the same model (the union of 1000 spheres peaked at
            # 1.47 GB with both, 1.20 GB without).
            extra["hidden"] = hidden
            extra["keep"] = False
        out = self._builder()(primitive, tuple(lights), material, n, eye=eye, **extra)
        bands = getattr(out, "bands", out)
        if not isinstance(bands, BandMesh):
            raise InvalidParameterError(f"build_laminae must return a LaminaSet or BandMesh, got {type(out).__name__}")
        return bands, bool(getattr(out, "view_dependent", False))

    def _leaf_geometry(self, program: Program) -> LeafGeometry:
        """The leaves' bounding boxes (kept per program: a tree is usually rendered again)."""
        hit = self._geometry.get(id(program))
        if hit is not None and hit[0] is program:
            return hit[1]
        geom = leaf_geometry(program.leaves)
        self._geometry.put(id(program), (program, geom), geom.nbytes + 64 * program.n_leaves)
        return geom

    def _visible_leaves(self, program: Program, geom: LeafGeometry) -> tuple[list[Primitive], LeafGeometry, Any]:
        """The leaves of a tree under the level of detail cut to where they can be seen, their
        geometry and the object's box (:func:`~isocsg.render.tiles.clip_leaves`): the bands of a
        hole through a plate are built for the plate's thickness, and the parts of a leaf outside
        the object's box (the hole's ends) are not cut into bands (``build_bands(hidden=...)``).
        The image is the same solid's; band values follow each leaf's visible range. Kept per
        program, as the leaf geometry is (it does not depend on the view)."""
        key = ("visible", id(program))
        hit = self._geometry.get(key)
        if hit is not None and hit[0] is program:
            return hit[1]
        lo, hi = program.bounds(geom.lo, geom.hi)
        leaves = clip_leaves(program.leaves, geom, lo, hi)
        changed = any(a is not b for a, b in zip(leaves, program.leaves))
        geom_v = leaf_geometry(leaves) if changed else geom
        plan = (leaves, geom_v, hidden_box(lo, hi))
        self._geometry.put(key, (program, plan), geom_v.nbytes + 256 * program.n_leaves)
        return plan

    def _contours(
        self, leaves: Sequence[Primitive], lights: Any, material: Any, geom: LeafGeometry, cam: Camera,
        program: Program | None, contours: int,
    ) -> NDArray[np.int64]:
        """Each leaf's contour count: :func:`screen_contours` of its size on screen (its box cut
        to the object's, :func:`~isocsg.render.tiles.leaf_screen_sizes`), or more when an earlier
        view used more (up to ``contours``): those bands are likely still cached, and a leaf that
        shrank on screen is only more accurate with them than it needs to be."""
        if not self.adaptive_contours or program is None or program.n_leaves <= LOD_MIN_LEAVES:
            return np.full(len(leaves), contours, np.int64)
        box = (None, None) if program is None else program.bounds(geom.lo, geom.hi)
        # A truncus's diameter caps its size (holes, rods), alone or in a tree alike, so that
        # a primitive and a tree of it (A | A) get the same bands.
        sizes = leaf_screen_sizes(geom, cam, *box)
        counts = screen_contours(sizes, contours)
        # The tessellation by the same size, for the default builder only (its signature has segments).
        segs = screen_segments(sizes) if self._by_request else np.full(len(leaves), DEFAULT_SEGMENTS, np.int64)
        out, seg = counts.tolist(), segs.tolist()
        used = self._lod
        for i, leaf in enumerate(leaves):
            key = (leaf, lights, material, contours)
            before = used.get(key)
            if before is not None:
                out[i], seg[i] = max(out[i], before[0]), max(seg[i], before[1])
            if before != (out[i], seg[i]):
                used[key] = (out[i], seg[i])
        while len(used) > LOD_MEMORY:
            used.popitem(last=False)
        codes = np.asarray(out, np.int64)
        seg_a = np.asarray(seg, np.int64)
        return np.where(seg_a < DEFAULT_SEGMENTS, codes | (seg_a << _SEGMENT_SHIFT), codes)

    def _per_pixel(self, key: tuple[Any, ...], n_leaves: int) -> bool:
        """Whether the CSG object ``(shape, lights, material, contours)`` is resolved per pixel,
        decided before its bands are built: ``"pixel"``; under ``"auto"`` on its first render,
        for trees of more than :data:`SURFACE_MAX_LEAVES` leaves, or when an earlier render
        found its bands view-dependent or too many for a surface."""
        if self.csg != "auto":
            return self.csg == "pixel"
        if n_leaves > SURFACE_MAX_LEAVES:
            return True
        seen = self._csg_seen.get(key)
        if seen is not None:
            self._csg_seen.move_to_end(key)
        return seen is None or seen

    def _seen(self, key: tuple[Any, ...], per_pixel: bool) -> None:
        self._csg_seen[key] = per_pixel
        self._csg_seen.move_to_end(key)
        while len(self._csg_seen) > 256:
            self._csg_seen.popitem(last=False)

    def _surface(
        self, program: Program, built: list[tuple[BandMesh, bool]]
    ) -> list[tuple[int, _Prepared]] | None:
        """The leaf parts of a CSG object's clipped surface, or None to resolve it per pixel.

        Called once :meth:`_per_pixel` has declined: under ``csg="auto"`` from
        the second render of an object with view-independent bands (a first
        render costs no Boolean) and few enough band triangles, under
        ``"surface"`` always (for specular bands: built every time). Surfaces
        of view-independent bands are kept. Under ``"auto"`` with
        ``surface_build="background"`` a surface not built yet is started on
        the surface thread and ``_PENDING`` returned (this view per pixel).
        """
        bands = tuple(b for b, _ in built)
        view_dependent = any(v for _, v in built)
        if self.csg == "auto" and (view_dependent or sum(len(b.triangles) for b in bands) > SURFACE_MAX_TRIANGLES):
            return None
        key = (tuple(id(b) for b in bands), program.op.tobytes(), program.arg.tobytes())
        with self._surface_lock:
            hit = self._surfaces.get(key)
            # The ids of band meshes that were dropped may be reused: compare the objects too.
            if hit is not None and all(x is y for x, y in zip(hit[0], bands)):
                return hit[1]
            if self.csg == "auto" and self.surface_build == "background":
                if key not in self._building:
                    self._building[key] = _surface_pool().submit(self._build_surface, key, program, bands)
                return _PENDING
        return self._build_surface(key, program, bands, view_dependent)

    def _large_surface(
        self, seen_key: tuple[Any, ...], program: Program, lights: Sequence[Any], material: Any,
        counts: NDArray[np.int64], eye: Any,
    ) -> _Runs | None:
        """The clipped surface of a tree of more than :data:`SURFACE_MAX_LEAVES` leaves, if ready
        (see :data:`LARGE_SURFACE_SHARE`); else None, and its background build is started when
        an earlier view found the tree's bands view-independent."""
        key = ("tree", seen_key)
        with self._surface_lock:
            hit = self._surfaces.get(key)
            if hit is not None:
                if hit[1] is None:
                    return None  # too large (or not closed): per pixel for good
                if _covers(hit[0], counts):
                    return hit[1]
                counts = _merge_counts(hit[0], counts)  # a finer surface, built for this view's needs
            if self._csg_seen.get(seen_key) is not False or key in self._building or key in self._deferred:
                return None  # a first view, view-dependent bands, or being built
        # Started once this view is done (see _render): the build's Python work would
        # otherwise hold the interpreter lock against this view's own.
        self._deferred[key] = (program, lights, material, counts.copy(), eye)
        return None

    def _build_large_surface(
        self, key: tuple[Any, ...], program: Program, lights: Sequence[Any], material: Any,
        counts: NDArray[np.int64], eye: Any,
    ) -> None:
        """On a thread of its own: the bands (from the caches, or built here), the trimmed
        Booleans within the share of the budget, and the parts ready to fill."""
        try:
            with _LARGE_LOCK:  # one large build at a time: each may take its share of the budget
                self._build_large_surface_locked(key, program, lights, material, counts, eye)
        finally:
            with self._surface_lock:
                self._building.pop(key, None)

    def _build_large_surface_locked(
        self, key: tuple[Any, ...], program: Program, lights: Sequence[Any], material: Any,
        counts: NDArray[np.int64], eye: Any,
    ) -> None:
        try:
            leaves, codes = program.leaves, counts.tolist()
            # Leaves that no trim can shrink first, Boolean by Boolean: a tree whose
            # untrimmable part alone is over the bound (a union of many overlapping
            # leaves) is given up before the rest of its bands is asked for.
            geom = leaf_geometry(leaves)
            # The parts of a leaf beyond the object's box (a hole's ends) cannot be on the
            # result's boundary: they are built uncut (a few triangles instead of their bands)
            # and then trimmed away or kept as they are, and these bands are kept by no cache.
            hidden = None
            if self._by_request:
                hidden = hidden_box(*program.bounds(geom.lo, geom.hi))
            most = LARGE_SURFACE_SHARE * memory_budget() / BYTES_PER_BOOLEAN_TRIANGLE
            built: dict[int, tuple[BandMesh, bool]] = {}
            for group in untrimmed_groups(program, geom.lo, geom.hi):
                n_tri = 0
                for k, i in enumerate(group, 1):
                    if i not in built:
                        built[i] = self._bands(leaves[i], lights, material, codes[i], eye, hidden)
                    n_tri += len(built[i][0].triangles)
                    # Over the bound, or clearly bound to be at this rate (four times over
                    # after a sample of eight leaves): given up without the rest.
                    if n_tri > most or (k >= 8 and n_tri * len(group) > 4 * most * k):
                        raise ResourceLimitError(f"{n_tri} band triangles of {k} leaves in one Boolean, over the bound")
            # The bands are all held while the Booleans run: given up when they alone would
            # pass a third of the share (or are bound to, at this rate, after a sample of 64
            # leaves), and the Booleans get what the share leaves.
            share = LARGE_SURFACE_SHARE * memory_budget()
            held = 0
            for k, i in enumerate(range(len(leaves)), 1):
                if i not in built:
                    built[i] = self._bands(leaves[i], lights, material, codes[i], eye, hidden)
                held += _mesh_bytes(built[i][0])
                if held > share / 3 or (k >= 64 and held * len(leaves) > share / 3 * k):
                    raise ResourceLimitError(f"{held} bytes of bands for {k} of {len(leaves)} leaves, over the bound")
            if any(vd for _, vd in built.values()):
                raise InvalidGeometryError("view-dependent bands")
            bands = [built[i][0] for i in range(len(leaves))]
            del built
            surface = surface_from_bands(program, bands, trim=True, max_bytes=int(share - held))
            del bands  # no cache holds them: gone before the parts below are made
        except (InvalidGeometryError, ResourceLimitError):
            with self._surface_lock:  # too large, or bands that do not close: per pixel from now on
                self._surfaces.put(key, (counts, None), 64)
            return
        parts = [(int(i), self._prepare(surface.leaf_bands(int(i)), True)) for i in np.unique(surface.leaf)]
        del surface
        runs = _Runs.of(parts)
        del parts
        # What the parts and the Booleans freed goes back to the system before any view runs.
        _release_freed_memory()
        runs.proj(_STRIPES - 1)  # pages touched here, not by the first view that fills it
        for scratch in runs.projs:
            scratch.fill(0.0)
        with self._surface_lock:
            if not self._surfaces.put(key, (counts, runs), runs.nbytes):
                self._surfaces.put(key, (counts, None), 64)  # more than the cache keeps: not again

    def _build_surface(
        self, key: tuple[Any, ...], program: Program, bands: tuple[BandMesh, ...], view_dependent: bool = False,
    ) -> list[tuple[int, _Prepared]] | None:
        """Build (and keep, for view-independent bands) one clipped surface; on the
        calling thread or, under ``surface_build="background"``, on the surface thread."""
        try:
            try:
                surface = surface_from_bands(program, bands)
            except (InvalidGeometryError, ResourceLimitError):
                if self.csg != "auto":
                    raise
                # Bands that do not close (extreme frames) or a surface over the memory budget:
                # this object stays per pixel, and the failure is remembered so no view retries it.
                with self._surface_lock:
                    self._surfaces.put(key, (bands, None), 64 * len(bands))
                return None
            parts = [(int(i), self._prepare(surface.leaf_bands(int(i)), True)) for i in np.unique(surface.leaf)]
            for _, p in parts:
                # Quads and projection scratch (pages touched) made here, on the surface thread
                # in the background, rather than by the first view that fills the surface.
                p.quads()
                p.proj(_STRIPES - 1)
                for scratch in p.projs:
                    scratch.fill(0.0)
            if not view_dependent:
                nbytes = sum(p.nbytes for _, p in parts) + sum(b.vertices.nbytes + 28 * len(b.triangles) for b in bands)
                with self._surface_lock:
                    self._surfaces.put(key, (bands, parts), nbytes)
            return parts
        finally:
            with self._surface_lock:
                self._building.pop(key, None)

    def wait_surfaces(self, timeout: float | None = None) -> bool:
        """Wait for the clipped surfaces being built in the background; returns whether all are done.

        Under ``surface_build="background"`` the next render after this uses them.

        Examples
        --------
        >>> Renderer().wait_surfaces()
        True
        """
        with self._surface_lock:
            pending = list(self._building.values())
        done, left = wait(pending, timeout=timeout)
        for f in done:
            f.result()
        return not left

    def _leaf(
        self, primitive: Primitive, lights: Sequence[Any], material: Any, contours: int, eye: Any,
        built: tuple[BandMesh, bool] | None = None, *, tiled: bool = False, hidden: Any = None,
    ) -> tuple[_Prepared, bool]:
        """One primitive's prepared band mesh and whether it depends on the view (``tiled``: for
        the screen tiles only, which keep no projection with it)."""
        key = ("request", primitive, tuple(lights), material, int(contours), hidden) if self._by_request else None
        if key is not None:
            hit = self._prepared.get(key)
            if hit is not None:
                return hit[1], False
        bands, view_dependent = built if built is not None else self._bands(
            primitive, lights, material, contours, eye, hidden)
        return self._prepare(bands, view_dependent, key, tiled=tiled), view_dependent

    def _front(
        self, primitive: Primitive, lights: Sequence[Any], material: Any, contours: int, eye: Any, hidden: Any = None,
    ) -> _Front:
        """One primitive's band mesh as its front-face fill needs it (a union's leaf), cached
        apart from the prepared meshes of per-pixel CSG (:class:`_Front`)."""
        key: Any = ("front", primitive, tuple(lights), material, int(contours), hidden)
        if self._by_request:
            hit = self._prepared.get(key)
            if hit is not None:
                return hit[1]
        bands, view_dependent = self._bands(primitive, lights, material, contours, eye, hidden)
        if not self._by_request:  # another builder's meshes are known by their identity
            key = ("front", id(bands))
            hit = self._prepared.get(key)
            if hit is not None and hit[0] is bands:
                return hit[1]
        quads, values, _ = self._prepare(bands, view_dependent, keep=False).quads()
        front = _Front(np.ascontiguousarray(bands.vertices, dtype=np.float64), quads, values)
        if not view_dependent:
            # The default builder's meshes are found by request: the band mesh itself is not
            # kept (it holds twice the front's bytes); another builder's is, to know it again.
            if self._by_request:
                self._prepared.put(key, (None, front), front.nbytes)
            else:
                self._prepared.put(key, (bands, front), front.nbytes + _mesh_bytes(bands))
        return front

    def _prepare(
        self, bands: BandMesh, view_dependent: bool, request: Any = None, *, tiled: bool = False, keep: bool = True,
    ) -> _Prepared:
        # View-independent meshes come back from the builder's cache as the same
        # objects: keep their converted arrays too (under the request that gave
        # them, for the default builder). View-dependent ones are new every
        # time and are not kept.
        key = id(bands) if request is None else request
        hit = self._prepared.get(key)
        if hit is not None and (request is not None or hit[0] is bands):
            return hit[1]
        vertices = np.ascontiguousarray(bands.vertices, dtype=np.float64)
        triangles = np.ascontiguousarray(bands.triangles, dtype=np.int32)
        value_out = np.ascontiguousarray(bands.value_out, dtype=np.float32)
        value_in = np.ascontiguousarray(bands.value_in, dtype=np.float32)
        nt, nv = len(triangles), len(vertices)
        if (
            vertices.ndim != 2 or vertices.shape[1] != 3 or triangles.ndim != 2
            or triangles.shape[1] != 3 or value_out.shape != (nt,) or value_in.shape != (nt,)
            or (nt and (triangles.min() < 0 or triangles.max() >= nv))
        ):
            raise InvalidParameterError(
                f"band mesh of {nv} vertices and {nt} triangles is malformed: vertices {vertices.shape}, "
                f"triangles {triangles.shape}, value_out {value_out.shape}, value_in {value_in.shape}"
            )
        prep = _Prepared(vertices, triangles, value_out, value_in, [])
        if keep and not view_dependent:
            size = prep.tiled_nbytes if tiled else prep.nbytes
            self._prepared.put(key, (bands, prep), size + (0 if request is None else _band_bytes(bands)))
        return prep

    def clear_caches(self) -> None:
        """Forget the prepared band meshes, CSG surfaces and leaf geometry this renderer keeps."""
        with self._lock:
            self._prepared.clear()
            with self._surface_lock:
                self._surfaces.clear()
            self._geometry.clear()
            self._csg_seen.clear()
            self._lod.clear()

    def cache_info(self) -> dict[str, int]:
        """Entries and bytes of the renderer's caches (``prepared``, ``surfaces``, ``geometry``).

        Examples
        --------
        >>> sorted(Renderer().cache_info())
        ['geometry', 'geometry_bytes', 'prepared', 'prepared_bytes', 'surfaces', 'surfaces_bytes']
        """
        out: dict[str, int] = {}
        for name, cache in (("prepared", self._prepared), ("surfaces", self._surfaces), ("geometry", self._geometry)):
            out[name] = len(cache)
            out[f"{name}_bytes"] = cache.nbytes
        return out

    def render(
        self,
        scene: Scene,
        *,
        camera: Camera | None = None,
        contours: int | None = None,
        progress: Callable[[int, int], None] | None = None,
    ) -> RenderResult:
        """Render ``scene`` (optionally from another camera or with another contour count).

        Parameters
        ----------
        scene : Scene
        camera : Camera, optional
            Defaults to ``scene.camera``.
        contours : int, optional
            Contours per light family; defaults to ``scene.render.contours``.
        progress : callable, optional
            Called as ``progress(done, total)`` as the primitives (CSG leaves
            included) are built and filled, ``total`` being their number; the
            last call is ``progress(total, total)``.

        Returns
        -------
        RenderResult

        Raises
        ------
        InvalidParameterError
            On a non-scene argument, a bad camera or contour count.
        ResourceLimitError
            When the image's buffers, or the per-pixel CSG buffers of a tile
            of the smallest size, would exceed :func:`isocsg.limits.memory_budget`
            (raised before they are allocated).
        """
        with self._lock:
            self._prepared.new_pass()
            self._deferred.clear()
            try:
                return self._render(scene, camera, contours, progress)
            finally:
                with self._surface_lock:
                    for key, args in self._deferred.items():
                        if key not in self._building:
                            self._building[key] = _in_daemon(self._build_large_surface, key, *args)
                self._deferred.clear()

    def _render(
        self, scene: Scene, camera: Camera | None, contours: int | None, progress: Callable[[int, int], None] | None,
    ) -> RenderResult:
        if not isinstance(scene, Scene):
            raise InvalidParameterError(f"scene must be a Scene, got {type(scene).__name__}")
        cam = scene.camera if camera is None else camera
        if not isinstance(cam, Camera):
            raise InvalidParameterError(f"camera must be a Camera, got {type(cam).__name__}")
        n_contours = scene.render.contours if contours is None else contours
        n_contours = integer("contours", n_contours, low=1, high=MAX_CONTOURS, error=InvalidParameterError)
        # The scene checked its own contour count; an override is checked here.
        families = sum(isinstance(li, (PointLight, DirectionalLight)) for li in scene.lights)
        light_budget(len(scene.lights), families, n_contours)

        t0 = time.perf_counter()
        H, W = cam.height, cam.width
        check_memory(f"render: {W} x {H} image", H * W * IMAGE_PIXEL_BYTES)
        persp = not cam.orthographic
        a, b = camera_affine(cam)
        eye = cam.eye_array
        # Depth keys and labels are private: only the rectangle the previous
        # render wrote needs resetting. The image is the caller's, so all of it
        # is reset (the fills write each visible value straight into it).
        zkey, key_rect = self._stale("key", (H, W), np.float64)
        gid, gid_rect = self._stale("label", (H, W), np.int32)
        value = self._buffer("image", (H, W), np.float32)
        resets = [(value, (0, H, 0, W), np.float32(np.nan)), (zkey, key_rect, np.inf), (gid, gid_rect, np.int32(-1))]
        dirty = [H, 0, W, 0]  # rows [dirty[0], dirty[1]), columns [dirty[2], dirty[3])

        def grow(rect: Sequence[int]) -> None:
            if rect[0] < rect[1] and rect[2] < rect[3]:
                dirty[:] = [min(dirty[0], rect[0]), max(dirty[1], rect[1]), min(dirty[2], rect[2]), max(dirty[3], rect[3])]

        build = 0.0  # seconds spent obtaining band meshes
        # Labels: one per (object, leaf); a pixel's label maps to both.
        obj_of: list[int] = []
        leaf_of: list[int] = []
        plain: list[tuple[_Prepared, int, float]] = []  # front fills: (mesh, label, near plane)
        programs = [obj.shape.program() if isinstance(obj.shape, CSGNode) else None for obj in scene.objects]
        total = sum(1 if prog is None else prog.n_leaves for prog in programs)
        report = _Progress(progress, total)
        for k, (obj, prog) in enumerate(zip(scene.objects, programs)):
            base = len(obj_of)
            if prog is None:
                obj_of.append(k)
                leaf_of.append(0)
                geom = leaf_geometry([obj.shape])
                rects, nears, _ = leaf_rects(geom, cam)
                if rects[0, 0] < rects[0, 2] and rects[0, 1] < rects[0, 3]:  # on screen
                    t = time.perf_counter()
                    n_k = int(self._contours([obj.shape], scene.lights, obj.material, geom, cam, None, n_contours)[0])
                    plain.append((self._leaf(obj.shape, scene.lights, obj.material, n_k, cam.eye)[0], base, float(nears[0])))
                    build += time.perf_counter() - t
                report.add(1)
                continue
            leaves, program = prog.leaves, prog
            obj_of.extend([k] * len(leaves))
            leaf_of.extend(range(len(leaves)))
            geom = self._leaf_geometry(program)
            counts = self._contours(leaves, scene.lights, obj.material, geom, cam, program, n_contours)
            hidden = None
            if self._by_request and self.adaptive_contours and program.n_leaves > LOD_MIN_LEAVES:
                # Sizes (hence counts) came from the whole leaves; what is built is their visible part.
                leaves, geom, hidden = self._visible_leaves(program, geom)
            rects, nears, _ = leaf_rects(geom, cam)
            rect = tuple(int(x) for x in combine_rects(program.op, program.arg, rects))
            seen_key = (obj.shape, scene.lights, obj.material, n_contours)
            built: list[tuple[BandMesh, bool]] | None = None
            parts = None
            if not (rect[0] < rect[2] and rect[1] < rect[3]):  # off screen
                report.add(len(leaves))
                continue
            if self.csg != "surface" and _is_union(program):
                # A union needs no per-pixel CSG and no clipped surface: its surface is the
                # nearest front face of its leaves, which the depth test finds.
                if resets:
                    _reset(resets)
                    resets = []
                build += self._render_union(leaves, scene.lights, obj.material, counts, cam, geom, rects, nears, base,
                                            zkey, value, gid, report, hidden)
                grow((rect[1], rect[3], rect[0], rect[2]))
                continue
            if len(leaves) > SURFACE_MAX_LEAVES and self.csg == "auto":
                runs = self._large_surface(seen_key, program, scene.lights, obj.material, counts, cam.eye)
                if runs is not None:
                    plain.append((runs, base + runs.leaves, nears[runs.leaves]))
                    report.add(len(leaves))
                    continue
            if not self._per_pixel(seen_key, len(leaves)):
                t = time.perf_counter()
                built = [self._bands(p, scene.lights, obj.material, c, cam.eye, hidden)
                         for p, c in zip(leaves, counts.tolist())]
                build += time.perf_counter() - t
                parts = self._surface(program, built)
                if parts is None and self.csg == "auto":
                    self._seen(seen_key, True)  # view-dependent or too large: per pixel from now on
                elif parts is _PENDING:
                    parts = None  # being built in the background: this view per pixel
            if parts is not None:
                plain.extend((prep, base + i, float(nears[i])) for i, prep in parts)
                report.add(len(leaves))
                continue
            if resets:  # the image buffers must be clean before an object is resolved into them
                _reset(resets)
                resets = []
            n = len(leaves)
            w, h = rect[2] - rect[0], rect[3] - rect[1]
            if n <= DENSE_MAX_LEAVES and n * h * w * LEAF_PIXEL_BYTES <= min(DENSE_MAX_BYTES, memory_budget() // 4):
                seconds, view_dependent = self._render_per_pixel(
                    leaves, program, scene.lights, obj.material, counts, cam, rect, nears, base, zkey, value, gid,
                    built, report, hidden,
                )
            else:
                seconds, view_dependent = self._render_tiled(
                    leaves, program, scene.lights, obj.material, counts, cam, rects, rect, nears, base,
                    zkey, value, gid, built, report, hidden,
                )
            build += seconds
            grow((rect[1], rect[3], rect[0], rect[2]))
            if view_dependent is not None and seen_key not in self._csg_seen:
                # Under "auto": the surface on the next render, unless the bands depend on the view.
                self._seen(seen_key, view_dependent)
        # Front fills of the plain meshes (and of CSG surfaces), in row stripes.
        n = _STRIPES if H * W >= _STRIPE_MIN_PIXELS and H >= 2 * _STRIPES else 1
        for p, _, _ in plain:
            p.proj(n - 1)  # scratch for every thread, allocated here (not in the threads)
        grow(self._fill_primitives(plain, resets, key_rect, a, b, eye, persp, n, zkey, value, gid))
        report.finish()
        self._dirty[id(zkey)] = self._dirty[id(gid)] = tuple(dirty)
        t2 = time.perf_counter()
        # Label -1 (background) maps to -1 through the leading entry of each table.
        object_of = np.asarray([-1] + obj_of, np.int32)
        leaf_of_arr = np.asarray([-1] + leaf_of, np.int32)
        # Read-only views: the pooled buffers must keep their background outside the dirty rectangle.
        key_view, label_view = zkey.view(), gid.view()
        key_view.flags.writeable = False
        label_view.flags.writeable = False
        return RenderResult(value, RenderTimings(build, t2 - t0 - build), cam, label_view, key_view, object_of, leaf_of_arr)

    def _fill_primitives(
        self, plain: list[tuple[_Prepared, int, float]], resets: Any, key_rect: tuple[int, int, int, int],
        a: NDArray[np.float64], b: NDArray[np.float64], eye: NDArray[np.float64], persp: bool, n: int,
        zkey: NDArray[np.float64], value: NDArray[np.float32], gid: NDArray[np.int32],
    ) -> list[int]:
        """Meshes filled by their front faces, in one pass of ``n`` concurrent row stripes.

        ``plain`` holds (mesh, label, near plane) triples: plain primitives and
        the leaf parts of CSG surfaces. Each stripe resets its rows of the
        buffers, projects the meshes itself (cheaper than waiting for a shared
        projection) and fills their front faces with the depth test. Returns
        the rectangle written.
        """
        H, W = zkey.shape
        bounds = np.empty((n, 4), np.int64)
        bounds[:] = (H, 0, W, 0)
        meshes = [(p, base, near, *p.quads()[:2]) for p, base, near in plain]  # quads made here, not in the threads

        def stripe(k: int, r0: int, r1: int) -> None:
            for buf, (q0, q1, c0, c1), bg in resets:
                if max(q0, r0) < min(q1, r1) and c0 < c1:
                    fill_rect(buf, max(q0, r0), min(q1, r1), c0, c1, bg)
            for p, base, near, quads, quad_value in meshes:
                proj = p.proj(k)
                project_kernel(p.vertices, eye, a, b, persp, proj, 0, len(p.vertices))
                if isinstance(p, _Runs):  # labels and near planes per run (leaf)
                    fill_front_runs(proj, quads, quad_value, p.starts, p.vstarts, base, near, persp, r0, zkey[r0:r1],
                                    value[r0:r1], gid[r0:r1], bounds[k])
                    continue
                fill_front_kernel(
                    proj, quads, quad_value, near, persp, base, r0, zkey[r0:r1], value[r0:r1], gid[r0:r1], bounds[k],
                )

        # Balance the stripes over the rows written last time (a re-render from a nearby view).
        r_top, r_bot = (key_rect[0], key_rect[1]) if key_rect[0] < key_rect[1] else (0, H)
        cuts = [r_top + (r_bot - r_top) * k // n for k in range(n + 1)]
        cuts[0], cuts[-1] = 0, H
        futures = [_pool().submit(stripe, k, r0, r1) for k, (r0, r1) in enumerate(zip(cuts[1:-1], cuts[2:]), 1)]
        stripe(0, cuts[0], cuts[1])
        for f in futures:
            f.result()
        return [int(bounds[:, 0].min()), int(bounds[:, 1].max()), int(bounds[:, 2].min()), int(bounds[:, 3].max())]

    def _render_union(
        self, leaves: Sequence[Primitive], lights: Sequence[Any], material: Any, counts: NDArray[np.int64],
        cam: Camera, geom: LeafGeometry, rects: NDArray[np.int64], nears: NDArray[np.float64], base: int,
        zkey: NDArray[np.float64], value: NDArray[np.float32], gid: NDArray[np.int32], report: _Progress,
        hidden: Any = None,
    ) -> float:
        """Fill a union of leaves by the depth test, nearest leaves first, skipping hidden ones.

        The leaves are taken in the order of their nearest possible depth
        (:func:`~isocsg.render.tiles.leaf_near_keys`); a leaf whose bounding
        ball is hidden everywhere by what is already drawn
        (:func:`~isocsg.render.raster.ball_covered`) is skipped without its
        bands being built or filled (occlusion culling: in a lattice of 1000
        spheres, 729 are hidden from any corner view). The others' front
        faces are filled into the image buffers, each leaf's rows split
        between the fill threads. Returns the seconds spent obtaining bands.
        """
        keys = leaf_near_keys(geom, cam, nears)
        # Each leaf's bounding ball: the sphere itself, or its box's circumscribed ball.
        centers = np.where(geom.sphere[:, None], geom.center, 0.5 * (geom.lo + geom.hi))
        radii = np.where(geom.sphere, geom.radius, 0.5 * np.linalg.norm(geom.hi - geom.lo, axis=1))
        ray = camera_rays(cam)
        persp = not cam.orthographic
        a, b = camera_affine(cam)
        eye = cam.eye_array
        H, W = zkey.shape
        bounds = np.empty((_STRIPES, 4), np.int64)
        bounds[:] = (H, 0, W, 0)
        # One projection scratch for all leaves (grown as needed), not one kept with each mesh.
        proj = np.empty((7, 0))

        def fill(quads: NDArray[np.int32], quad_value: NDArray[np.float32], i: int, r0: int, r1: int, k: int) -> None:
            fill_front_kernel(proj, quads, quad_value, float(nears[i]), persp, base + i, r0, zkey[r0:r1], value[r0:r1],
                              gid[r0:r1], bounds[k])

        seconds = 0.0
        for i in np.argsort(keys, kind="stable").tolist():
            c0, r0, c1, r1 = rects[i].tolist()
            if c0 < c1 and r0 < r1 and not ball_covered(zkey, r0, r1, c0, c1, float(keys[i]), float(nears[i]), ray,
                                                        centers[i], float(radii[i])):
                t = time.perf_counter()
                front = self._front(leaves[i], lights, material, int(counts[i]), cam.eye, hidden)
                seconds += time.perf_counter() - t
                nv = len(front.vertices)
                if proj.shape[1] < nv:
                    proj = np.empty((7, max(nv, 2 * proj.shape[1])))
                project_kernel(front.vertices, eye, a, b, persp, proj, 0, nv)
                quads, quad_value = front.polys, front.values
                # Rows split between threads when the leaf is large enough to pay for the hand-over.
                parts = max(1, min(_STRIPES, (r1 - r0) * (c1 - c0) // _UNION_SPLIT_PIXELS, r1 - r0))
                cuts = [r0 + (r1 - r0) * k // parts for k in range(parts + 1)]
                jobs = [_pool().submit(fill, quads, quad_value, i, cuts[k], cuts[k + 1], k) for k in range(1, parts)]
                fill(quads, quad_value, i, cuts[0], cuts[1], 0)
                for job in jobs:
                    job.result()
            report.add(1)
        return seconds

    def _render_per_pixel(
        self, leaves: Sequence[Primitive], program: Program, lights: Sequence[Any], material: Any,
        counts: NDArray[np.int64], cam: Camera, rect: tuple[int, int, int, int], nears: NDArray[np.float64], base: int,
        zkey: NDArray[np.float64], value: NDArray[np.float32], gid: NDArray[np.int32],
        built: list[tuple[BandMesh, bool]] | None, report: _Progress, hidden: Any = None,
    ) -> tuple[float, bool | None]:
        """Resolve a small CSG object per pixel over its whole screen rectangle, into the image buffers.

        Each leaf's front and back surfaces are filled into buffers of the
        object's screen rectangle (known before any band exists), then row
        stripes resolve the program per pixel. When the leaves' bands are not
        given they are obtained here, leaf by leaf, and each leaf is filled by
        a worker thread while the next one is built; the last leaf's rows are
        shared by both threads. Returns the seconds spent obtaining bands and
        whether any was view-dependent.
        """
        ox, oy, x1, y1 = rect
        w, h = x1 - ox, y1 - oy
        n = len(leaves)
        persp = not cam.orthographic
        a, b = camera_affine(cam)
        eye = cam.eye_array
        table = _table(program.op, program.arg, n)
        # One worker fills the leaves in order (they share projection scratch
        # when a primitive repeats): the kernels release the GIL, so building
        # the next leaf's bands goes on meanwhile.
        concurrent = _STRIPES > 1 and w * h >= _STRIPE_MIN_PIXELS // 4
        jobs: list[Future[None]] = []
        # Buffers of the object's rectangle (not the image), lent for this object only.
        with SCRATCH.borrow([((n, h, w), np.float64)] * 2 + [((n, h, w), np.float32)] * 2) as (kf, kb, vf, vb):

            def fill_rows(i: int, p: _Prepared, proj: NDArray[np.float64], r0: int, r1: int) -> None:
                fill_rect(kf[i], r0, r1, 0, w, np.inf)
                fill_rect(kb[i], r0, r1, 0, w, -np.inf)
                fill_projected(proj, *p.quads(), float(nears[i]), persp, ox, oy + r0, kf[i, r0:r1], vf[i, r0:r1],
                               kb[i, r0:r1], vb[i, r0:r1])

            def leaf(i: int, p: _Prepared) -> None:
                proj = p.proj()
                project_kernel(p.vertices, eye, a, b, persp, proj, 0, len(p.vertices))
                fill_rows(i, p, proj, 0, h)

            def shared_leaf(i: int, p: _Prepared) -> None:
                # The last leaf: nothing left to build, so this thread and the worker
                # (once it is done with the earlier leaves) take row chunks in turn.
                proj = p.proj(1)  # not the worker's scratch: it may still fill this mesh for an earlier leaf
                project_kernel(p.vertices, eye, a, b, persp, proj, 0, len(p.vertices))
                p.quads()  # made here, not by both threads at once
                chunks = [(h * k // _LAST_CHUNKS, h * (k + 1) // _LAST_CHUNKS) for k in range(_LAST_CHUNKS)]
                lock = threading.Lock()

                def drain() -> None:
                    while True:
                        with lock:
                            if not chunks:
                                return
                            r0, r1 = chunks.pop(0)
                        fill_rows(i, p, proj, r0, r1)

                jobs.append(_leaf_pool().submit(drain))
                drain()

            seconds = 0.0
            view_dependent = False
            # Spheres last: their bands take longer to build than to fill, other
            # leaves' the other way round (Johnson's rule for a two-stage line).
            order = sorted(range(n), key=lambda i: isinstance(leaves[i], Sphere)) if built is None else range(n)
            seen: set[int] = set()
            try:
                for k, i in enumerate(order):
                    t = time.perf_counter()
                    prep, vd = self._leaf(leaves[i], lights, material, counts[i], cam.eye,
                                          None if built is None else built[i], hidden=hidden)
                    view_dependent |= vd
                    seconds += time.perf_counter() - t
                    if not concurrent:
                        leaf(i, prep)
                    elif k == n - 1 and id(prep) not in seen and h >= _LAST_CHUNKS:
                        shared_leaf(i, prep)
                    else:
                        jobs.append(_leaf_pool().submit(leaf, i, prep))
                    seen.add(id(prep))
                    report.add(1)
            finally:
                wait(jobs)  # never give back buffers that a worker still writes
            for job in jobs:
                job.result()
            flat = [x.reshape(-1) for x in (kf, vf, kb, vb)]
            lr0, lc0 = np.full(n, oy, np.int64), np.full(n, ox, np.int64)
            lh, lw = np.full(n, h, np.int64), np.full(n, w, np.int64)
            off, ids = np.arange(n, dtype=np.int64) * (h * w), np.arange(n, dtype=np.int64)

            def stripe(r0: int, r1: int) -> None:
                _resolve_packed(*flat, off, lr0, lc0, lh, lw, ids, program.op, program.arg, table, base,
                                oy + r0, oy + r1, ox, x1, zkey, value, gid, *_resolve_scratch(n, len(program.op)))

            cuts = [h * k // _STRIPES for k in range(_STRIPES + 1)] if concurrent and h >= 2 * _STRIPES else [0, h]
            futures = [_pool().submit(stripe, r0, r1) for r0, r1 in zip(cuts[1:-1], cuts[2:])]
            stripe(cuts[0], cuts[1])
            for f in futures:
                f.result()
        return seconds, view_dependent

    def _render_tiled(
        self, leaves: Sequence[Primitive], program: Program, lights: Sequence[Any], material: Any,
        counts: NDArray[np.int64], cam: Camera, rects: NDArray[np.int64], rect: tuple[int, int, int, int],
        nears: NDArray[np.float64], base: int, zkey: NDArray[np.float64], value: NDArray[np.float32],
        gid: NDArray[np.int32], built: list[tuple[BandMesh, bool]] | None, report: _Progress, hidden: Any = None,
    ) -> tuple[float, bool | None]:
        """Resolve a CSG object per pixel in screen tiles (see :mod:`isocsg.render.tiles`).

        Equal leaves (the same primitive at the same contour count, e.g. a
        hole subtracted again and again by a modelling loop) form one group:
        its bands are obtained, projected and filled once per tile, and the
        equal leaves of a tile read the same buffers. Groups are built in
        the order of the first row of tiles their rectangle meets
        (:func:`~isocsg.render.tiles.plan_tiles`). A tile's buffers (its
        groups' clipped rectangles, packed) are allocated when the first
        group meeting it is built; each group is filled into all its tiles
        at once and its mesh and projection are dropped right after, so the
        meshes alive are only those waiting to be filled, never one per
        leaf. Once every group meeting a tile is filled and its row closed,
        the tile resolves the program pruned to its leaves and releases its
        buffers. Fills and tiles are taken from one queue by the other
        threads and by the main thread whenever too many fills wait or when
        more than :data:`_ROWS_AHEAD` rows are open behind the row it builds.
        What is alive therefore grows with the image and the leaves' screen
        footprints (bounded before anything is allocated, see
        :func:`~isocsg.render.tiles.open_tile_pixels`). Leaves off screen are
        never built. Returns the seconds spent obtaining bands and whether any
        was view-dependent (None if none was built).
        """
        n = len(leaves)
        persp = not cam.orthographic
        a, b = camera_affine(cam)
        eye = cam.eye_array
        budget = memory_budget()
        # Leaves clipped to the object's rectangle (the tiles' domain); those outside it are empty.
        rects = rects.copy()
        np.clip(rects[:, 0::2], rect[0], rect[2], out=rects[:, 0::2])
        np.clip(rects[:, 1::2], rect[1], rect[3], out=rects[:, 1::2])
        plan = plan_tiles(rects, rect, len(program.op), min(TILE_MAX_BYTES, budget // 8))
        side, ox, oy = plan.side, rect[0], rect[1]
        on = np.flatnonzero((rects[:, 0] < rects[:, 2]) & (rects[:, 1] < rects[:, 3]))
        # Groups of equal leaves (equal leaves have equal rectangles), in order of their first row.
        group_of = np.full(n, -1, np.int64)
        members: list[list[int]] = []
        index: dict[Any, int] = {}
        counts_l = counts.tolist()
        for i in on.tolist():
            key = (leaves[i], counts_l[i])
            g = index.setdefault(key, len(members))
            if g == len(members):
                members.append([])
            members[g].append(i)
            group_of[i] = g
        reps = np.array([m[0] for m in members], np.int64)
        first = (rects[reps, 1] - oy) // side
        order = np.argsort(first, kind="stable").tolist()
        first_l = first.tolist()
        H, W = zkey.shape
        peak = open_tile_pixels(rects[reps], plan, _ROWS_AHEAD)
        check_memory(
            f"render: per-pixel CSG of {n} leaves ({len(members)} distinct) in {plan.side}-pixel tiles "
            f"({peak} leaf pixels open at once)",
            peak * LEAF_PIXEL_BYTES + H * W * IMAGE_PIXEL_BYTES,
        )
        occupied = np.diff(plan.start) > 0
        row_tiles = [np.flatnonzero(occupied[r * plan.cols : (r + 1) * plan.cols]) + r * plan.cols for r in range(plan.rows)]
        nears_l = nears.tolist()
        op_all, arg_all = program.op, program.arg
        # Per open tile: (buffers, pruned op, arg, leaf ids, offsets, rows0, cols0, rows, cols).
        tiles: dict[int, tuple[Any, ...]] = {}
        slots: list[list[tuple[int, int]]] = [[] for _ in members]  # per group: (tile, slot) to fill
        pending: dict[int, int] = {}  # per open tile: groups not filled yet, plus one until its row closes
        cond = threading.Condition()
        queue: deque[tuple[Any, ...]] = deque()
        left = [len(t) for t in row_tiles]  # tiles of each row not resolved yet
        state: dict[str, Any] = {"error": None, "queued": 0, "done": 0, "fills": 0, "open": True}

        def open_tile(t: int) -> None:
            # Main thread only. Equal leaves of the tile share one slot of its buffers.
            c0, r0, c1, r1 = plan.tile(t)
            op, arg, ids, off, lr0, lc0, lh, lw = tile_leaves(
                op_all, arg_all, plan.leaf[plan.start[t] : plan.start[t + 1]], n, rects, c0, r0, c1, r1)
            groups = group_of[ids]
            _, rep, inv = np.unique(groups, return_index=True, return_inverse=True)
            sizes = (lh * lw)[rep]
            starts = np.concatenate([[0], np.cumsum(sizes)])
            off = starts[:-1][inv].astype(np.int64)
            total = max(int(starts[-1]), 1)
            bufs = (np.empty(total), np.empty(total, np.float32), np.empty(total), np.empty(total, np.float32))
            tiles[t] = (bufs, op, arg, ids, off, lr0, lc0, lh, lw)
            for j in rep.tolist():
                slots[int(groups[j])].append((t, j))
            pending[t] = len(rep) + 1

        def ready(t: int) -> None:
            # Under the lock: one more of the tile's groups filled (or its row closed).
            pending[t] -= 1
            if pending[t] == 0:
                queue.appendleft(("tile", t))  # before waiting fills: it releases memory

        def fill(g: int, prep: _Prepared) -> None:
            # Projection and quads here, on a worker, while the main thread builds the next group.
            proj = np.empty((7, len(prep.vertices)))
            project_kernel(prep.vertices, eye, a, b, persp, proj, 0, len(prep.vertices))
            quads, vout, vin = prep.quads()
            near = nears_l[members[g][0]]
            done = []
            for t, j in slots[g]:
                (kf, vf, kb, vb), _, _, _, off, lr0, lc0, lh, lw = tiles[t]
                _fill_leaf(kf, vf, kb, vb, int(off[j]), int(lr0[j]), int(lc0[j]), int(lh[j]), int(lw[j]),
                           proj, quads, vout, vin, near, persp)
                done.append(t)
            with cond:
                state["fills"] -= 1
                for t in done:
                    ready(t)
                cond.notify_all()

        def resolve(t: int) -> None:
            c0, r0, c1, r1 = plan.tile(t)
            (kf, vf, kb, vb), op, arg, ids, off, lr0, lc0, lh, lw = tiles[t]
            if len(ids):
                _resolve_packed(kf, vf, kb, vb, off, lr0, lc0, lh, lw, ids, op, arg, _table(op, arg, len(ids)),
                                base, r0, r1, c0, c1, zkey, value, gid, *_resolve_scratch(len(ids), len(op)))
            with cond:
                del tiles[t], pending[t]
                left[t // plan.cols] -= 1
                while state["done"] < state["queued"] and left[state["done"]] == 0:
                    state["done"] += 1
                cond.notify_all()

        def work(wait_for_more: bool, limit: int = -1) -> None:
            """Take tasks from the queue until it is empty (and closed, if ``wait_for_more``), ``limit`` at most."""
            while limit != 0:
                with cond:
                    while not queue and state["open"] and wait_for_more and state["error"] is None:
                        cond.wait()
                    if not queue or state["error"] is not None:
                        return
                    task = queue.popleft()
                try:
                    if task[0] == "tile":
                        resolve(task[1])
                    else:
                        fill(*task[1:])
                except BaseException as exc:  # handed to the main thread
                    with cond:
                        state["error"] = state["error"] or exc
                        queue.clear()
                        cond.notify_all()
                    return
                limit -= 1

        def help_until(condition: Callable[[], bool]) -> None:
            # Main thread: run queued tasks (or wait for the workers) until ``condition()`` holds.
            while True:
                with cond:
                    while not condition() and not queue and state["error"] is None:
                        cond.wait()
                    if condition() or state["error"] is not None:
                        return
                work(False, 1)

        seconds = 0.0
        view_dependent: bool | None = None
        threads = max(1, _STRIPES)
        workers = [_pool().submit(work, True) for _ in range(1, threads)]
        try:
            pos = 0
            for row in range(plan.rows):
                # At most _ROWS_AHEAD rows behind this one still open: bounds the tiles alive.
                help_until(lambda: state["done"] >= row - _ROWS_AHEAD)
                if state["error"] is not None:
                    break
                while pos < len(order) and first_l[order[pos]] <= row:
                    g = order[pos]
                    pos += 1
                    i = members[g][0]
                    c0, r0, c1, r1 = rects[i].tolist()
                    for tr in range((r0 - oy) // side, (r1 - 1 - oy) // side + 1):
                        for tc in range((c0 - ox) // side, (c1 - 1 - ox) // side + 1):
                            if tr * plan.cols + tc not in tiles:
                                open_tile(tr * plan.cols + tc)
                    t = time.perf_counter()
                    prep, vd = self._leaf(leaves[i], lights, material, counts_l[i], cam.eye,
                                          None if built is None else built[i], tiled=True, hidden=hidden)
                    seconds += time.perf_counter() - t
                    view_dependent = bool(view_dependent) or vd
                    with cond:
                        queue.append(("fill", g, prep))
                        state["fills"] += 1
                        cond.notify_all()
                    del prep
                    report.add(len(members[g]))
                    # Waiting fills hold their meshes: help once there are more than a few.
                    help_until(lambda: state["fills"] <= 2 * threads)
                    if state["error"] is not None:
                        break
                with cond:
                    if state["error"] is not None:
                        break
                    for t in row_tiles[row].tolist():
                        if t not in tiles:  # no group reached it (cannot happen: occupied tiles have leaves)
                            open_tile(t)
                        ready(t)
                    state["queued"] = row + 1
                    while state["done"] < state["queued"] and left[state["done"]] == 0:
                        state["done"] += 1
                    cond.notify_all()
        finally:
            with cond:
                if sys.exc_info()[0] is not None:
                    queue.clear()
                    state["error"] = state["error"] or sys.exc_info()[1]
            if state["error"] is None:
                help_until(lambda: state["done"] >= plan.rows)
            with cond:
                state["open"] = False
                cond.notify_all()
            wait(workers)  # never return while a worker still writes the image
        for f in workers:
            f.result()
        if state["error"] is not None:
            raise state["error"]
        report.add(n - len(on))  # leaves off screen: nothing to build
        return seconds, view_dependent


class _Progress:
    """``progress(done, total)`` calls, at most about 200 per render and always the last."""

    def __init__(self, callback: Callable[[int, int], None] | None, total: int) -> None:
        self.callback = callback
        self.total = total
        self.done = 0
        self._step = max(1, total // 200)
        self._last = -1

    def add(self, k: int) -> None:
        self.done += k
        if self.callback is not None and k and (self.done - self._last >= self._step or self.done >= self.total):
            self._last = self.done
            self.callback(self.done, self.total)

    def finish(self) -> None:
        if self.callback is not None and self._last < self.total:
            self._last = self.total
            self.callback(self.total, self.total)


@njit(cache=True, nogil=True)
def _resolve_scratch(
    n: int, n_op: int,
) -> tuple[NDArray[np.float64], NDArray[np.int8], NDArray[np.bool_], NDArray[np.bool_], NDArray[np.int64]]:
    """The scratch arrays of :func:`_resolve_packed` for ``n`` leaves and ``n_op`` instructions."""
    return (np.empty(n), np.empty(n, np.int8), np.zeros(n, np.bool_), np.zeros(max(n_op, 1), np.bool_),
            np.zeros(n, np.int64))


Rect = tuple[int, int, int, int]  # (col0, row0, col1, row1), half-open


def _screen_rect(program: Program, cam: Camera) -> Rect:
    """A pixel rectangle holding the projection of a solid, known before its bands exist.

    A primitive's rectangle bounds the projection of its bounding box (the
    hull of the corners' projections) and, for a sphere, of the sphere itself
    (exact, from the tangents in the camera's two vertical planes); a union
    takes the hull of its operands', an intersection their overlap, a
    difference its first operand's. The whole image when anything reaches
    behind its near plane (:func:`isocsg.render.tiles.leaf_rects`).
    """
    rects, _, _ = leaf_rects(leaf_geometry(program.leaves), cam)
    return tuple(int(x) for x in combine_rects(program.op, program.arg, rects))  # type: ignore[return-value]


def _is_union(program: Program) -> bool:
    """Whether a program is a union of leaves (flattened, so one union instruction at most)."""
    return bool(np.all((program.op == OP_LEAF) | (program.op == OP_UNION)))


def _reset(resets: Sequence[tuple[NDArray[Any], tuple[int, int, int, int], Any]]) -> None:
    """Fill rectangles of buffers with their background, in concurrent row shares."""
    n = _STRIPES

    def share(k: int) -> None:
        for buf, (r0, r1, c0, c1), bg in resets:
            if r0 < r1 and c0 < c1:
                fill_rect(buf, r0 + (r1 - r0) * k // n, r0 + (r1 - r0) * (k + 1) // n, c0, c1, bg)

    futures = [_pool().submit(share, k) for k in range(1, n)]
    share(0)
    for f in futures:
        f.result()


_DEFAULT: Renderer | None = None

#: Stripes filled concurrently for one primitive on images of at least ``_STRIPE_MIN_PIXELS``.
_STRIPES = max(1, min(4, os.cpu_count() or 1))
_STRIPE_MIN_PIXELS = 512 * 512
#: A leaf of a union is filled by several threads (row bands) from this many pixels per thread.
_UNION_SPLIT_PIXELS = 1024
#: Row chunks of the last CSG leaf, shared by the main thread and the leaf worker.
_LAST_CHUNKS = 6
#: Rows of tiles the main thread may build ahead of the tiles done.
_ROWS_AHEAD = 2
_POOL: ThreadPoolExecutor | None = None


def _pool() -> ThreadPoolExecutor:
    global _POOL
    if _POOL is None:
        _POOL = ThreadPoolExecutor(max_workers=max(_STRIPES - 1, 1), thread_name_prefix="isocsg-fill")
    return _POOL


_LEAF_POOL: ThreadPoolExecutor | None = None


def _split_counts(codes: NDArray[np.int64]) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Contours and segments of :meth:`Renderer._contours`'s codes (segments 0: the default)."""
    segs = codes >> _SEGMENT_SHIFT
    return codes & _CONTOUR_MASK, np.where(segs == 0, DEFAULT_SEGMENTS, segs)


def _covers(have: NDArray[np.int64], need: NDArray[np.int64]) -> bool:
    """Whether a large tree's surface built at ``have`` serves a view asking ``need``: every
    leaf has the contours asked and at least half the segments (a chord error within four
    times :data:`CHORD_PIXELS`, 0.05 pixel), so a view that finds a few leaves grown on
    screen does not wait for a new Boolean of the whole tree."""
    (c0, s0), (c1, s1) = _split_counts(have), _split_counts(need)
    return bool(np.all(c0 >= c1) and np.all(2 * s0 >= s1))


def _merge_counts(a: NDArray[np.int64], b: NDArray[np.int64]) -> NDArray[np.int64]:
    """The finer of two count codes, leaf by leaf."""
    (c0, s0), (c1, s1) = _split_counts(a), _split_counts(b)
    c, seg = np.maximum(c0, c1), np.maximum(s0, s1)
    return np.where(seg < DEFAULT_SEGMENTS, c | (seg << _SEGMENT_SHIFT), c)


#: Large trees' surface builds run one at a time (each may take its share of the budget).
_LARGE_LOCK = threading.Lock()


def _in_daemon(fn: Callable[..., None], *args: Any) -> Future[None]:
    """Run ``fn(*args)`` on a daemon thread: a large tree's surface build can take a minute,
    and a process that ends meanwhile does not wait for it (its result would only be cached)."""
    fut: Future[None] = Future()

    def run() -> None:
        if not fut.set_running_or_notify_cancel():
            return
        try:
            fut.set_result(fn(*args))
        except BaseException as exc:  # noqa: BLE001 - handed to whoever waits
            fut.set_exception(exc)

    threading.Thread(target=run, name="isocsg-large-surface", daemon=True).start()
    return fut


_SURFACE_POOL: ThreadPoolExecutor | None = None
#: What :meth:`Renderer._surface` returns while a surface is built in the background.
_PENDING: Any = object()


def _surface_pool() -> ThreadPoolExecutor:
    # One thread: surfaces are built one at a time, off the views' critical path.
    global _SURFACE_POOL
    if _SURFACE_POOL is None:
        _SURFACE_POOL = ThreadPoolExecutor(max_workers=1, thread_name_prefix="isocsg-surface")
    return _SURFACE_POOL


def _leaf_pool() -> ThreadPoolExecutor:
    """The single worker that fills CSG leaves while the next leaf is built."""
    global _LEAF_POOL
    if _LEAF_POOL is None:
        _LEAF_POOL = ThreadPoolExecutor(max_workers=1, thread_name_prefix="isocsg-leaf")
    return _LEAF_POOL


def default_renderer() -> Renderer:
    """The module-wide :class:`Renderer` used by :func:`render`."""
    global _DEFAULT
    if _DEFAULT is None:
        _DEFAULT = Renderer()
    return _DEFAULT


def render(
    scene: Scene,
    *,
    camera: Camera | None = None,
    contours: int | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> RenderResult:
    """Render a scene with isoluminance bands; see :meth:`Renderer.render`.

    Examples
    --------
    >>> from isocsg import Camera, PointLight, Scene, Sphere
    >>> scene = Scene(Camera((0, -5, 0), (0, 0, 0), width=32, height=32),
    ...               [PointLight((3, -5, 4))], [Sphere((0, 0, 0), 1)])
    >>> result = render(scene, contours=16)  # doctest: +SKIP
    """
    return default_renderer().render(scene, camera=camera, contours=contours, progress=progress)
