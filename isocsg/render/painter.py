"""Isoluminance rendering of a scene: band fill, per-pixel CSG, depth test.

Each primitive's surface bands (planar triangles of constant value, built by
:func:`isocsg.laminae.build_laminae` and cached there because they do not
depend on the viewpoint) are filled with :mod:`isocsg.render.raster`:

- an object that is a single primitive needs its front surface only (back
  faces are culled), filled straight into the image with a depth test;
- an object that is a CSG tree fills the front *and* back surface of every
  leaf (the ray's interval ``[front, back]`` through the convex leaf) inside
  the object's screen rectangle (known from the tree before any band is
  built, so that a worker fills each leaf while the next one is built), then
  the tree's postfix program is evaluated
  per pixel on those intervals: the first depth where the result turns from
  outside to inside is the visible point. If it is leaf i's front the pixel
  shows i's ``value_out``; if it is leaf i's back (the inside of a cut), i's
  ``value_in``. Results that are empty along the ray stay background.

Several objects: the nearest visible point wins.
"""

from __future__ import annotations

import functools
import math
import os
import sys
import threading
import time
from collections import OrderedDict
from collections.abc import Callable, Sequence
from concurrent.futures import Future, ThreadPoolExecutor, wait
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numba import njit
from numpy.typing import NDArray

from .._validation import integer
from ..camera import Camera
from ..csg.surface import surface_from_bands
from ..csg.program import OP_DIFFERENCE, OP_UNION, Program, evaluate_mask
from ..csg.tree import CSGNode
from ..errors import InvalidParameterError
from ..geometry.primitives import Primitive, Sphere
from ..laminae.model import BandMesh
from ..scene.model import MAX_CONTOURS, Scene
from .raster import (
    _RAW, NEAR_RELATIVE, camera_affine, fill_front_kernel, fill_projected, fill_rect, key_to_depth, pair_quads, project_kernel,
)
from .scratch import SCRATCH

__all__ = ["RenderResult", "RenderTimings", "Renderer", "render", "default_renderer"]

#: The ways a :class:`Renderer` resolves CSG objects (see its ``csg`` parameter).
CSG_METHODS = ("auto", "surface", "pixel")

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


def _table(program: Program) -> NDArray[np.bool_]:
    """The program's truth table if it has at most :data:`_TABLE_LEAVES` leaves, else empty."""
    n = program.n_leaves
    if n > _TABLE_LEAVES:
        return np.zeros(0, np.bool_)
    return _cached_table(program.op.tobytes(), program.arg.tobytes(), n)


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
    n = kf.shape[0]
    _resolve_rows(kf, vf, kb, vb, op, arg, table, gid_base, ox, oy, zkey, value, gid,
                  np.empty(n), np.empty(n, np.int8), np.zeros(n, np.bool_), np.zeros(max(len(op), 1), np.bool_))


# Without reference counting (see isocsg.render.raster): the per-pixel loop
# passes arrays to inlined helpers, two atomic operations each otherwise.
@njit(**_RAW)
def _resolve_rows(
    kf: NDArray[np.float64], vf: NDArray[np.float32], kb: NDArray[np.float64], vb: NDArray[np.float32],
    op: NDArray[np.int8], arg: NDArray[np.int64], table: NDArray[np.bool_], gid_base: int, ox: int, oy: int,
    zkey: NDArray[np.float64], value: NDArray[np.float32], gid: NDArray[np.int32],
    nxt: NDArray[np.float64], phase: NDArray[np.int8], inside: NDArray[np.bool_], stack: NDArray[np.bool_],
) -> None:
    # phase: 0 before the leaf's front, 1 inside, 2 past its back.
    n, h, w = kf.shape
    use_table = len(table) > 0
    for r in range(h):
        for c in range(w):
            rr = r + oy
            cc = c + ox
            covered = False
            mask = 0
            for i in range(n):
                f = kf[i, r, c]
                b = kb[i, r, c]
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
                        nxt[i] = kb[i, r, c]
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
                    value[rr, cc] = vf[shown, r, c] if shown_front else vb[shown, r, c]
                    gid[rr, cc] = gid_base + shown
                    break
                state = now


# ------------------------------------------------------------------- renderer
@dataclass(frozen=True, slots=True, eq=False)
class _Prepared:
    vertices: NDArray[np.float64]
    triangles: NDArray[np.int32]
    value_out: NDArray[np.float32]
    value_in: NDArray[np.float32]
    projs: list[NDArray[np.float64]]  # (7, V) scratch of project_kernel per fill thread, reused
    _quads: list[tuple[NDArray[np.int32], NDArray[np.float32], NDArray[np.float32]]] = field(default_factory=list)

    def quads(self) -> tuple[NDArray[np.int32], NDArray[np.float32], NDArray[np.float32]]:
        """pair_quads of the triangles and their ``value_out`` and ``value_in`` (made when first needed)."""
        if not self._quads:
            quads, source = pair_quads(self.vertices, self.triangles, self.value_out, self.value_in)
            self._quads.append((quads, self.value_out[source], self.value_in[source]))
        return self._quads[0]

    def proj(self, k: int = 0) -> NDArray[np.float64]:
        while len(self.projs) <= k:
            self.projs.append(np.empty((7, len(self.vertices))))
        return self.projs[k]


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
        :func:`isocsg.laminae.build_laminae`, which caches the
        view-independent bands, so rendering from a new viewpoint only fills.
    csg : {"auto", "surface", "pixel"}, default "auto"
        How CSG objects are resolved. ``"pixel"``: per pixel on the leaves'
        depth intervals (exact, nothing to build). ``"surface"``: the leaves'
        bands clipped once in 3D (:func:`isocsg.csg.surface.surface_from_bands`,
        manifold3d Booleans) and cached, so that every later view is a plain
        fill. ``"auto"``: per pixel the first time an object is rendered; from
        its second render on (a new viewpoint of the same bands), the surface,
        built then and cached. Objects with view-dependent (specular) bands
        use ``"pixel"`` under ``"auto"``.

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

    def __init__(self, build_laminae: BandBuilder | None = None, *, csg: str = "auto") -> None:
        if csg not in CSG_METHODS:
            raise InvalidParameterError(f"csg must be one of {', '.join(CSG_METHODS)}, got {csg!r}")
        self._build = build_laminae
        self.csg = csg
        # CSG surfaces (leaf band meshes clipped in 3D), keyed by the leaves' band
        # meshes and the program: (band meshes kept alive, leaf parts).
        self._surfaces: OrderedDict[tuple[Any, ...], tuple[tuple[BandMesh, ...], list[tuple[int, _Prepared]]]] = (
            OrderedDict()
        )
        # Arrays converted for the kernels, keyed by the band mesh's identity.
        self._prepared: OrderedDict[int, tuple[BandMesh, _Prepared]] = OrderedDict()
        # Image-sized buffers reused from one render to the next once no result
        # refers to them any more: fresh pages cost more than the fill itself.
        self._pool: OrderedDict[tuple[str, tuple[int, ...], str], list[NDArray[Any]]] = OrderedDict()
        self._lock = threading.Lock()
        # id of a pooled buffer -> (row0, row1, col0, col1) that may differ from its background.
        self._dirty: dict[int, tuple[int, int, int, int]] = {}
        # CSG objects already resolved per pixel -> whether their bands were view-dependent.
        self._csg_seen: OrderedDict[tuple[Any, ...], bool] = OrderedDict()

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
            from ..laminae import build_laminae

            self._build = build_laminae
        return self._build

    def bands(self, primitive: Primitive, lights: Sequence[Any], material: Any, contours: int, eye: Any) -> BandMesh:
        """The band mesh of one primitive (from the builder and its cache)."""
        return self._bands(primitive, lights, material, contours, eye)[0]

    def _bands(
        self, primitive: Primitive, lights: Sequence[Any], material: Any, contours: int, eye: Any
    ) -> tuple[BandMesh, bool]:
        out = self._builder()(primitive, tuple(lights), material, contours, eye=eye)
        bands = getattr(out, "bands", out)
        if not isinstance(bands, BandMesh):
            raise InvalidParameterError(f"build_laminae must return a LaminaSet or BandMesh, got {type(out).__name__}")
        return bands, bool(getattr(out, "view_dependent", False))

    def _per_pixel(self, key: tuple[Any, ...]) -> bool:
        """Whether the CSG object ``(shape, lights, material, contours)`` is resolved per pixel,
        decided before its bands are built: ``"pixel"``; ``"auto"`` on its first render
        or when its bands were view-dependent."""
        if self.csg != "auto":
            return self.csg == "pixel"
        seen = self._csg_seen.get(key)
        if seen is not None:
            self._csg_seen.move_to_end(key)
        return seen is None or seen

    def _surface(
        self, program: Program, built: list[tuple[BandMesh, bool]]
    ) -> list[tuple[int, _Prepared]] | None:
        """The leaf parts of a CSG object's clipped surface, or None to resolve it per pixel.

        Called once :meth:`_per_pixel` has declined: under ``csg="auto"`` from
        the second render of an object with view-independent bands (a first
        render costs no Boolean), under ``"surface"`` always (for specular
        bands: built every time). Surfaces of view-independent bands are kept.
        """
        bands = tuple(b for b, _ in built)
        view_dependent = any(v for _, v in built)
        if view_dependent and self.csg == "auto":
            return None
        key = (tuple(id(b) for b in bands), program.op.tobytes(), program.arg.tobytes())
        hit = self._surfaces.get(key)
        # The ids of band meshes that were dropped may be reused: compare the objects too.
        if hit is not None and all(x is y for x, y in zip(hit[0], bands)):
            self._surfaces.move_to_end(key)
            return hit[1]
        surface = surface_from_bands(program, bands)
        parts = [(int(i), self._prepare(surface.leaf_bands(int(i)), True)) for i in np.unique(surface.leaf)]
        if not view_dependent:
            self._surfaces[key] = (bands, parts)
            while len(self._surfaces) > 64:
                self._surfaces.popitem(last=False)
        return parts

    def _prepare(self, bands: BandMesh, view_dependent: bool) -> _Prepared:
        # View-independent meshes come back from the builder's cache as the same
        # objects: keep their converted arrays too. View-dependent ones are new
        # every time and are not kept.
        key = id(bands)
        hit = self._prepared.get(key)
        if hit is not None and hit[0] is bands:
            self._prepared.move_to_end(key)
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
        if not view_dependent:
            self._prepared[key] = (bands, prep)
            while len(self._prepared) > 256:
                self._prepared.popitem(last=False)
        return prep

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
            Called as ``progress(done, total)`` after each primitive is filled.

        Returns
        -------
        RenderResult

        Raises
        ------
        InvalidParameterError
            On a non-scene argument, a bad camera or contour count.
        """
        with self._lock:
            return self._render(scene, camera, contours, progress)

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

        t0 = time.perf_counter()
        H, W = cam.height, cam.width
        persp = not cam.orthographic
        a, b = camera_affine(cam)
        eye = cam.eye_array
        # Near plane at a tiny fraction of the scene's depth (bounded by the objects' bounding boxes).
        far = max((_far_depth(obj.shape.bounds, a[3], eye) for obj in scene.objects), default=1.0)
        near = NEAR_RELATIVE * max(far if far > 0 else 1.0, 1e-300)
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
        plain: list[tuple[_Prepared, int]] = []  # front fills: (mesh, label)
        programs = [obj.shape.program() if isinstance(obj.shape, CSGNode) else None for obj in scene.objects]
        total = sum(1 if prog is None else prog.n_leaves for prog in programs)
        resolved = 0  # leaves of the objects resolved per pixel so far
        for k, (obj, prog) in enumerate(zip(scene.objects, programs)):
            base = len(obj_of)
            if prog is None:
                obj_of.append(k)
                leaf_of.append(0)
                t = time.perf_counter()
                plain.append((self._prepare(*self._bands(obj.shape, scene.lights, obj.material, n_contours, cam.eye)), base))
                build += time.perf_counter() - t
                continue
            leaves, program = prog.leaves, prog
            obj_of.extend([k] * len(leaves))
            leaf_of.extend(range(len(leaves)))
            seen_key = (obj.shape, scene.lights, obj.material, n_contours)
            built: list[tuple[BandMesh, bool]] | None = None
            parts = None
            if not self._per_pixel(seen_key):
                t = time.perf_counter()
                built = [self._bands(p, scene.lights, obj.material, n_contours, cam.eye) for p in leaves]
                build += time.perf_counter() - t
                parts = self._surface(program, built)
            if parts is not None:
                plain.extend((prep, base + i) for i, prep in parts)
                continue
            if resets:  # the image buffers must be clean before an object is resolved into them
                _reset(resets)
                resets = []
            rect, seconds, built = self._render_per_pixel(
                leaves, program, scene.lights, obj.material, n_contours, cam, near, base, zkey, value, gid, built,
            )
            build += seconds
            grow(rect)
            if built:  # under "auto": the surface on the next render, unless the bands depend on the view
                self._csg_seen[seen_key] = any(v for _, v in built)
                while len(self._csg_seen) > 256:
                    self._csg_seen.popitem(last=False)
            resolved += len(leaves)
            if progress is not None:
                progress(resolved, total)
        # Front fills of the plain meshes (and of CSG surfaces), in row stripes.
        n = _STRIPES if H * W >= _STRIPE_MIN_PIXELS and H >= 2 * _STRIPES else 1
        for p, _ in plain:
            p.proj(n - 1)  # scratch for every thread, allocated here (not in the threads)
        grow(self._fill_primitives(plain, resets, key_rect, a, b, eye, persp, near, n, zkey, value, gid))
        if progress is not None and resolved < total:
            progress(total, total)
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
        self, plain: list[tuple[_Prepared, int]], resets: Any, key_rect: tuple[int, int, int, int],
        a: NDArray[np.float64], b: NDArray[np.float64], eye: NDArray[np.float64], persp: bool, near: float, n: int,
        zkey: NDArray[np.float64], value: NDArray[np.float32], gid: NDArray[np.int32],
    ) -> list[int]:
        """Meshes filled by their front faces, in one pass of ``n`` concurrent row stripes.

        ``plain`` holds (mesh, label) pairs: plain primitives and the leaf
        parts of CSG surfaces. Each stripe resets its rows of the buffers,
        projects the meshes itself (cheaper than waiting for a shared
        projection) and fills their front faces with the depth test. Returns
        the rectangle written.
        """
        H, W = zkey.shape
        bounds = np.empty((n, 4), np.int64)
        bounds[:] = (H, 0, W, 0)
        meshes = [(p, base, *p.quads()[:2]) for p, base in plain]  # quads made here, not in the threads

        def stripe(k: int, r0: int, r1: int) -> None:
            for buf, (q0, q1, c0, c1), bg in resets:
                if max(q0, r0) < min(q1, r1) and c0 < c1:
                    fill_rect(buf, max(q0, r0), min(q1, r1), c0, c1, bg)
            for p, base, quads, quad_value in meshes:
                proj = p.proj(k)
                project_kernel(p.vertices, eye, a, b, persp, proj, 0, len(p.vertices))
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

    def _render_per_pixel(
        self, leaves: Sequence[Primitive], program: Program, lights: Sequence[Any], material: Any,
        contours: int, cam: Camera, near: float, base: int,
        zkey: NDArray[np.float64], value: NDArray[np.float32], gid: NDArray[np.int32],
        built: list[tuple[BandMesh, bool]] | None,
    ) -> tuple[tuple[int, int, int, int], float, list[tuple[BandMesh, bool]]]:
        """Resolve one CSG object per pixel on its leaves' depth intervals, into the image buffers.

        Each leaf's front and back surfaces are filled into buffers of the
        object's screen rectangle (:func:`_screen_rect`, known before any band
        exists), then row stripes resolve the program per pixel. When the
        leaves' bands are not given they are obtained here, leaf by leaf, and
        each leaf is filled by a worker thread while the next one is built;
        the last leaf's rows are shared by both threads.
        Returns the rectangle written (rows, then columns), the seconds spent
        obtaining bands and the bands (none if the object is off screen).
        """
        ox, oy, x1, y1 = _screen_rect(program, cam, near)
        w, h = x1 - ox, y1 - oy
        if w <= 0 or h <= 0:
            return (0, 0, 0, 0), 0.0, built or []
        n = len(leaves)
        persp = not cam.orthographic
        a, b = camera_affine(cam)
        eye = cam.eye_array
        table = _table(program)
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
                fill_projected(proj, *p.quads(), near, persp, ox, oy + r0, kf[i, r0:r1], vf[i, r0:r1], kb[i, r0:r1],
                               vb[i, r0:r1])

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
            # Spheres last: their bands take longer to build than to fill, other
            # leaves' the other way round (Johnson's rule for a two-stage line).
            order = sorted(range(n), key=lambda i: isinstance(leaves[i], Sphere)) if built is None else range(n)
            out: list[tuple[BandMesh, bool] | None] = [None] * n
            seen: set[int] = set()
            try:
                for k, i in enumerate(order):
                    t = time.perf_counter()
                    out[i] = built[i] if built is not None else self._bands(leaves[i], lights, material, contours, cam.eye)
                    prep = self._prepare(*out[i])
                    seconds += time.perf_counter() - t
                    if not concurrent:
                        leaf(i, prep)
                    elif k == n - 1 and id(prep) not in seen and h >= _LAST_CHUNKS:
                        shared_leaf(i, prep)
                    else:
                        jobs.append(_leaf_pool().submit(leaf, i, prep))
                    seen.add(id(prep))
            finally:
                wait(jobs)  # never give back buffers that a worker still writes
            for job in jobs:
                job.result()

            def stripe(r0: int, r1: int) -> None:
                resolve_csg(kf[:, r0:r1], vf[:, r0:r1], kb[:, r0:r1], vb[:, r0:r1], program.op, program.arg, table, base, ox, oy + r0,
                            zkey, value, gid)

            cuts = [h * k // _STRIPES for k in range(_STRIPES + 1)] if concurrent and h >= 2 * _STRIPES else [0, h]
            futures = [_pool().submit(stripe, r0, r1) for r0, r1 in zip(cuts[1:-1], cuts[2:])]
            stripe(cuts[0], cuts[1])
            for f in futures:
                f.result()
        return (oy, y1, ox, x1), seconds, [b for b in out if b is not None]


def _far_depth(bounds: NDArray[np.float64], forward: NDArray[np.float64], eye: NDArray[np.float64]) -> float:
    """Largest camera depth (in absolute value) of a bounding box, bounded through its circumscribed sphere."""
    lo, hi = np.asarray(bounds, dtype=np.float64)
    return abs(float(forward @ (0.5 * (lo + hi) - eye))) + 0.5 * float(np.linalg.norm(hi - lo))


Rect = tuple[int, int, int, int]  # (col0, row0, col1, row1), half-open


def _screen_rect(program: Program, cam: Camera, near: float) -> Rect:
    """A pixel rectangle holding the projection of a solid, known before its bands exist.

    A primitive's rectangle bounds the projection of its bounding box (the
    hull of the corners' projections) and, for a sphere, of the sphere itself
    (exact, from the tangents in the camera's two vertical planes); a union
    takes the hull of its operands', an intersection their overlap, a
    difference its first operand's. The whole image when anything reaches
    behind the near plane.
    """

    def combine(op: int, rects: list[Rect]) -> Rect:
        if op == OP_DIFFERENCE:
            return rects[0]
        pick = (min, max) if op == OP_UNION else (max, min)
        return (pick[0](r[0] for r in rects), pick[0](r[1] for r in rects),
                pick[1](r[2] for r in rects), pick[1](r[3] for r in rects))

    return program.evaluate(lambda _, p: _leaf_rect(p, cam, near), combine)


def _leaf_rect(solid: Primitive, cam: Camera, near: float) -> Rect:
    """:func:`_screen_rect` of one primitive."""
    W, H = cam.width, cam.height
    f, r, u = cam.frame
    m = np.stack([r, u, f])
    lo, hi = np.asarray(solid.bounds, dtype=np.float64)
    corners = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
    xr, yu, z = m @ (corners - cam.eye_array).T  # camera space
    if not np.all(np.isfinite(z)) or z.min() < near:
        return 0, 0, W, H
    sx, sy = (xr / z, yu / z) if not cam.orthographic else (xr, yu)
    box = [sx.min(), sx.max(), sy.min(), sy.max()]
    if isinstance(solid, Sphere):
        cx, cy, cz = m @ (solid.center_array - cam.eye_array)
        rad = solid.radius
        if cam.orthographic:
            ball = [cx - rad, cx + rad, cy - rad, cy + rad]
        else:
            # x / z over the disk the sphere projects to in the (x, z) plane (likewise y): tangent lines.
            ball = []
            for c in (cx, cy):
                t0, dt = math.atan2(c, cz), math.asin(min(rad / math.hypot(c, cz), 1.0))
                ball += [math.tan(t0 - dt), math.tan(t0 + dt)]
        box = [max(box[0], ball[0]), min(box[1], ball[1]), max(box[2], ball[2]), min(box[3], ball[3])]
    if cam.orthographic:
        half_h = cam.height_m / 2
        sx_scale, sy_scale = 1.0 / (half_h * cam.aspect), 1.0 / half_h
    else:
        sx_scale, sy_scale = 1.0 / (cam.tan_half_fov * cam.aspect), 1.0 / cam.tan_half_fov
    c0, c1 = (box[0] * sx_scale + 1.0) * W / 2, (box[1] * sx_scale + 1.0) * W / 2
    r0, r1 = (1.0 - box[3] * sy_scale) * H / 2, (1.0 - box[2] * sy_scale) * H / 2
    return (min(max(int(math.floor(c0)) - 1, 0), W), min(max(int(math.floor(r0)) - 1, 0), H),
            min(max(int(math.ceil(c1)) + 1, 0), W), min(max(int(math.ceil(r1)) + 1, 0), H))


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
#: Row chunks of the last CSG leaf, shared by the main thread and the leaf worker.
_LAST_CHUNKS = 6
_POOL: ThreadPoolExecutor | None = None


def _pool() -> ThreadPoolExecutor:
    global _POOL
    if _POOL is None:
        _POOL = ThreadPoolExecutor(max_workers=max(_STRIPES - 1, 1), thread_name_prefix="isocsg-fill")
    return _POOL


_LEAF_POOL: ThreadPoolExecutor | None = None


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
