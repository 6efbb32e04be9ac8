"""Isoluminance rendering of a scene: the :class:`Renderer` and its caches, and :func:`render`.

Each primitive's surface bands (planar triangles of constant value, built by
:func:`isocsg.laminae.build_bands` and cached there because they do not
depend on the viewpoint) are filled into the image with a depth test. The
renderer decides, object by object, which path draws it:

- a single primitive, or a CSG object's clipped surface once built
  (:mod:`~isocsg.rendering.surfaces`): its front faces (:mod:`~isocsg.rendering.fronts`);
- a union of leaves: nearest leaves first, hidden ones skipped (:mod:`~isocsg.rendering.union`);
- another CSG tree: per-pixel CSG on its leaves' depth intervals
  (:mod:`~isocsg.rendering.pixel_csg`), over its whole screen rectangle for small
  trees (:mod:`~isocsg.rendering.dense`), in screen tiles for larger ones
  (:mod:`~isocsg.rendering.tiled`);
- each leaf of a large tree gets the contours and tessellation its size on
  screen can show (:mod:`~isocsg.rendering.detail`).

The state of one render travels as a :class:`~isocsg.rendering.renderpass.RenderPass`;
the tunables live in :mod:`~isocsg.rendering.policy`. Several objects: the nearest
visible point wins.
"""

from __future__ import annotations

import threading
import time
from collections import OrderedDict
from collections.abc import Callable, Hashable, Sequence
from typing import Any

import numpy as np

from .. import _workers
from .._cache import ByteCache
from .._validation import integer, light_budget
from ..camera import Camera
from ..csg.program import Program
from ..csg.tree import CSGNode
from ..errors import InvalidParameterError
from ..kinds import Primitive
from ..laminae.model import BandMesh
from ..lighting.lights import DirectionalLight, PointLight
from ..limits import check_memory, memory_budget
from ..scene.model import MAX_CONTOURS, Scene
from . import policy
from .buffers import BufferPool
from .dense import render_dense
from .detail import LeafDetail, LevelOfDetail
from .fronts import Plain, fill_fronts
from .meshes import FrontMesh, PreparedMesh, band_bytes, mesh_bytes, prepare_mesh
from .renderpass import CSGObject, Progress, RenderPass, is_union
from .result import RenderResult, RenderTimings
from .surfaces import PENDING, SurfaceBuilds
from .tiled import render_tiled
from .tiles import (
    LEAF_PIXEL_BYTES,
    LeafGeometry,
    clip_leaves,
    combine_rects,
    hidden_box,
    leaf_geometry,
    leaf_rects,
)
from .union import render_union

__all__ = ["Renderer", "render", "default_renderer", "BandBuilder"]

#: ``build(primitive, lights, material, contours, eye=...) -> LaminaSet`` (or a BandMesh).
BandBuilder = Callable[..., Any]


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
        :data:`~isocsg.rendering.policy.SURFACE_MAX_LEAVES` leaves and its bands at most
        :data:`~isocsg.rendering.policy.SURFACE_MAX_TRIANGLES` triangles. Larger trees get it too,
        always built in the background with their operands trimmed, and only
        if its Booleans fit :data:`~isocsg.rendering.policy.LARGE_SURFACE_SHARE` of the memory budget
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
        :data:`~isocsg.rendering.policy.LOD_MIN_LEAVES` (64) leaves. ``True``: each of their leaves
        gets contours by its size on screen (:func:`~isocsg.rendering.detail.screen_contours`): a
        primitive ``e`` pixels across needs about ``N * e / 128`` (bands about
        two pixels apart at N = 64) and gets ``N``, or ``N / 2`` where that
        need allows (never fewer than :data:`~isocsg.rendering.policy.MIN_CONTOURS`, 16, which keeps
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
        if csg not in policy.CSG_METHODS:
            raise InvalidParameterError(f"csg must be one of {', '.join(policy.CSG_METHODS)}, got {csg!r}")
        if surface_build not in policy.SURFACE_BUILDS:
            raise InvalidParameterError(
                f"surface_build must be one of {', '.join(policy.SURFACE_BUILDS)}, got {surface_build!r}")
        self.surface_build = surface_build
        self._build = build_laminae
        self.csg = csg
        self.adaptive_contours = bool(adaptive_contours)
        # The default builder's view-independent bands are kept here by request
        # (primitive, lights, material, detail), so a new view asks it for nothing.
        self._by_request = build_laminae is None
        self._detail = LevelOfDetail(self.adaptive_contours, tessellate=self._by_request)
        self._surfaces = SurfaceBuilds(csg, surface_build, self._bands, self._by_request)
        # Arrays converted for the kernels, keyed by the band mesh's identity or the request: (band mesh, prepared).
        self._prepared = ByteCache(policy.PREPARED_CACHE_BYTES, scan_resistant=True, share=4)
        # Leaves' bounding boxes, keyed by the program's identity: (program, LeafGeometry).
        self._geometry = ByteCache(policy.GEOMETRY_CACHE_BYTES)
        self._buffers = BufferPool()
        self._lock = threading.Lock()
        # CSG objects already resolved per pixel -> whether they stay per pixel (view-dependent
        # bands, or a surface too large to build). Keys only: bounded by a count.
        self._csg_seen: OrderedDict[Hashable, bool] = OrderedDict()

    def _builder(self) -> BandBuilder:
        if self._build is None:
            from ..laminae import build_bands

            self._build = build_bands
        return self._build

    def bands(self, primitive: Primitive, lights: Sequence[Any], material: Any, contours: int, eye: Any) -> BandMesh:
        """The band mesh of one primitive (from the builder and its cache)."""
        return self._bands(primitive, lights, material, LeafDetail(int(contours)), eye)[0]

    def _bands(
        self, primitive: Primitive, lights: Sequence[Any], material: Any, detail: LeafDetail, eye: Any,
        hidden: Any = None,
    ) -> tuple[BandMesh, bool]:
        # ``hidden`` (the default builder only, see _visible_leaves): the box outside which nothing shows.
        extra: dict[str, Any] = detail.builder_options()
        if hidden is not None:
            # A large tree's bands are kept here, by request, and only here: the lamina cache
            # would hold another share of the same model (the union of 1000 spheres peaked at
            # 1.47 GB with both, 1.20 GB without).
            extra["hidden"] = hidden
            extra["keep"] = False
        out = self._builder()(primitive, tuple(lights), material, detail.contours, eye=eye, **extra)
        bands = getattr(out, "bands", out)
        if not isinstance(bands, BandMesh):
            raise InvalidParameterError(f"build_laminae must return a LaminaSet or BandMesh, got {type(out).__name__}")
        return bands, bool(getattr(out, "view_dependent", False))

    def _leaf_geometry(self, program: Program) -> LeafGeometry:
        """The leaves' bounding boxes (kept per program: a tree is usually rendered again)."""
        hit = self._geometry.get(id(program))
        if hit is not None and hit[0] is program:
            return hit[1]  # type: ignore[no-any-return]
        geom = leaf_geometry(program.leaves)
        self._geometry.put(id(program), (program, geom), geom.nbytes + 64 * program.n_leaves)
        return geom

    def _visible_leaves(self, program: Program, geom: LeafGeometry) -> tuple[list[Primitive], LeafGeometry, Any]:
        """The leaves of a tree under the level of detail cut to where they can be seen, their
        geometry and the object's box (:func:`~isocsg.rendering.tiles.clip_leaves`): the bands of a
        hole through a plate are built for the plate's thickness, and the parts of a leaf outside
        the object's box (the hole's ends) are not cut into bands (``build_bands(hidden=...)``).
        The image is the same solid's; band values follow each leaf's visible range. Kept per
        program, as the leaf geometry is (it does not depend on the view)."""
        key = ("visible", id(program))
        hit = self._geometry.get(key)
        if hit is not None and hit[0] is program:
            return hit[1]  # type: ignore[no-any-return]
        lo, hi = program.bounds(geom.lo, geom.hi)
        leaves = clip_leaves(program.leaves, geom, lo, hi)
        changed = any(a is not b for a, b in zip(leaves, program.leaves))
        geom_v = leaf_geometry(leaves) if changed else geom
        plan = (leaves, geom_v, hidden_box(lo, hi))
        self._geometry.put(key, (program, plan), geom_v.nbytes + 256 * program.n_leaves)
        return plan

    def _per_pixel(self, key: Hashable, n_leaves: int) -> bool:
        """Whether the CSG object ``(shape, lights, material, contours)`` is resolved per pixel,
        decided before its bands are built: ``"pixel"``; under ``"auto"`` on its first render,
        for trees of more than :data:`~isocsg.rendering.policy.SURFACE_MAX_LEAVES` leaves, or when
        an earlier render found its bands view-dependent or too many for a surface."""
        if self.csg != "auto":
            return self.csg == "pixel"
        if n_leaves > policy.SURFACE_MAX_LEAVES:
            return True
        seen = self._csg_seen.get(key)
        if seen is not None:
            self._csg_seen.move_to_end(key)
        return seen is None or seen

    def _seen(self, key: Hashable, per_pixel: bool) -> None:
        self._csg_seen[key] = per_pixel
        self._csg_seen.move_to_end(key)
        while len(self._csg_seen) > policy.CSG_SEEN_MEMORY:
            self._csg_seen.popitem(last=False)

    def wait_surfaces(self, timeout: float | None = None) -> bool:
        """Wait for the clipped surfaces being built in the background; returns whether all are done.

        Under ``surface_build="background"`` the next render after this uses them.

        Examples
        --------
        >>> Renderer().wait_surfaces()
        True
        """
        return self._surfaces.wait(timeout)

    def leaf_mesh(
        self, primitive: Primitive, lights: Sequence[Any], material: Any, detail: LeafDetail, eye: Any,
        built: tuple[BandMesh, bool] | None = None, *, tiled: bool = False, hidden: Any = None,
    ) -> tuple[PreparedMesh, bool]:
        """One primitive's prepared band mesh and whether it depends on the view (``tiled``: for
        the screen tiles only, which keep no projection with it)."""
        key = ("request", primitive, tuple(lights), material, detail, hidden) if self._by_request else None
        if key is not None:
            hit = self._prepared.get(key)
            if hit is not None:
                return hit[1], False
        bands, view_dependent = built if built is not None else self._bands(
            primitive, lights, material, detail, eye, hidden)
        return self._prepare(bands, view_dependent, key, tiled=tiled), view_dependent

    def front_mesh(
        self, primitive: Primitive, lights: Sequence[Any], material: Any, detail: LeafDetail, eye: Any,
        hidden: Any = None,
    ) -> FrontMesh:
        """One primitive's band mesh as its front-face fill needs it (a union's leaf), cached
        apart from the prepared meshes of per-pixel CSG (:class:`~isocsg.rendering.meshes.FrontMesh`)."""
        key: Any = ("front", primitive, tuple(lights), material, detail, hidden)
        if self._by_request:
            hit = self._prepared.get(key)
            if hit is not None:
                return hit[1]  # type: ignore[no-any-return]
        bands, view_dependent = self._bands(primitive, lights, material, detail, eye, hidden)
        if not self._by_request:  # another builder's meshes are known by their identity
            key = ("front", id(bands))
            hit = self._prepared.get(key)
            if hit is not None and hit[0] is bands:
                return hit[1]  # type: ignore[no-any-return]
        quads, values, _ = self._prepare(bands, view_dependent, keep=False).quads()
        front = FrontMesh(np.ascontiguousarray(bands.vertices, dtype=np.float64), quads, values)
        if not view_dependent:
            # The default builder's meshes are found by request: the band mesh itself is not
            # kept (it holds twice the front's bytes); another builder's is, to know it again.
            if self._by_request:
                self._prepared.put(key, (None, front), front.nbytes)
            else:
                self._prepared.put(key, (bands, front), front.nbytes + mesh_bytes(bands))
        return front

    def _prepare(
        self, bands: BandMesh, view_dependent: bool, request: Any = None, *, tiled: bool = False, keep: bool = True,
    ) -> PreparedMesh:
        # View-independent meshes come back from the builder's cache as the same
        # objects: keep their converted arrays too (under the request that gave
        # them, for the default builder). View-dependent ones are new every
        # time and are not kept.
        key = id(bands) if request is None else request
        hit = self._prepared.get(key)
        if hit is not None and (request is not None or hit[0] is bands):
            return hit[1]  # type: ignore[no-any-return]
        prep = prepare_mesh(bands)
        if keep and not view_dependent:
            size = prep.tiled_nbytes if tiled else prep.nbytes
            self._prepared.put(key, (bands, prep), size + (0 if request is None else band_bytes(bands)))
        return prep

    def clear_caches(self) -> None:
        """Forget the prepared band meshes, CSG surfaces and leaf geometry this renderer keeps."""
        with self._lock:
            self._prepared.clear()
            self._surfaces.clear()
            self._geometry.clear()
            self._csg_seen.clear()
            self._detail.clear()

    def cache_info(self) -> dict[str, int]:
        """Entries and bytes of the renderer's caches (``prepared``, ``surfaces``, ``geometry``).

        Examples
        --------
        >>> sorted(Renderer().cache_info())
        ['geometry', 'geometry_bytes', 'prepared', 'prepared_bytes', 'surfaces', 'surfaces_bytes']
        """
        out: dict[str, int] = {}
        for name, cache in (("prepared", self._prepared), ("surfaces", self._surfaces.cache),
                            ("geometry", self._geometry)):
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
        with self._lock, _workers.foreground():
            self._prepared.new_pass()
            self._surfaces.deferred.clear()
            try:
                return self._render(scene, camera, contours, progress)
            finally:
                self._surfaces.start_deferred()

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
        check_memory(f"render: {W} x {H} image", H * W * policy.IMAGE_PIXEL_BYTES)
        # Depth keys and labels are private: only the rectangle the previous
        # render wrote needs resetting. The image is the caller's, so all of it
        # is reset (the fills write each visible value straight into it).
        zkey, key_rect = self._buffers.stale("key", (H, W), np.float64)
        gid, gid_rect = self._buffers.stale("label", (H, W), np.int32)
        value = self._buffers.buffer("image", (H, W), np.float32)
        resets = [(value, (0, H, 0, W), np.float32(np.nan)), (zkey, key_rect, np.inf), (gid, gid_rect, np.int32(-1))]
        programs = [obj.shape.program() if isinstance(obj.shape, CSGNode) else None for obj in scene.objects]
        report = Progress(progress, sum(1 if prog is None else prog.n_leaves for prog in programs))
        rp = RenderPass(cam, tuple(scene.lights), self, zkey, value, gid, report, resets)
        build = 0.0  # seconds spent obtaining band meshes
        # Labels: one per (object, leaf); a pixel's label maps to both.
        obj_of: list[int] = []
        leaf_of: list[int] = []
        plain: list[Plain] = []  # front fills: (mesh, label, near plane)
        for k, (obj, prog) in enumerate(zip(scene.objects, programs)):
            base = len(obj_of)
            obj_of.extend([k] * (1 if prog is None else prog.n_leaves))
            leaf_of.extend(range(1 if prog is None else prog.n_leaves))
            if prog is None:
                build += self._draw_primitive(rp, obj, base, n_contours, plain)
            else:
                build += self._draw_tree(rp, obj, prog, base, n_contours, plain)
        # Front fills of the plain meshes (and of CSG surfaces), in row stripes.
        n = policy.STRIPES if H * W >= policy.STRIPE_MIN_PIXELS and H >= 2 * policy.STRIPES else 1
        for p, _, _ in plain:
            p.proj(n - 1)  # scratch for every thread, allocated here (not in the threads)
        rp.grow(fill_fronts(rp, plain, key_rect, n))
        report.finish()
        self._buffers.written(zkey, tuple(rp.dirty))  # type: ignore[arg-type]
        self._buffers.written(gid, tuple(rp.dirty))  # type: ignore[arg-type]
        t2 = time.perf_counter()
        # Label -1 (background) maps to -1 through the leading entry of each table.
        object_of = np.asarray([-1] + obj_of, np.int32)
        leaf_of_arr = np.asarray([-1] + leaf_of, np.int32)
        # Read-only views: the pooled buffers must keep their background outside the dirty rectangle.
        key_view, label_view = zkey.view(), gid.view()
        key_view.flags.writeable = False
        label_view.flags.writeable = False
        timings = RenderTimings(build, t2 - t0 - build)
        return RenderResult(value, timings, cam, label_view, key_view, object_of, leaf_of_arr)

    def _draw_primitive(self, rp: RenderPass, obj: Any, base: int, contours: int, plain: list[Plain]) -> float:
        """A primitive object: its mesh queued for the front fills (at the requested count and the
        full tessellation). Returns the seconds spent obtaining bands."""
        seconds = 0.0
        rects, nears, _ = leaf_rects(leaf_geometry([obj.shape]), rp.cam)
        if rects[0, 0] < rects[0, 2] and rects[0, 1] < rects[0, 3]:  # on screen
            t = time.perf_counter()
            mesh = self.leaf_mesh(obj.shape, rp.lights, obj.material, LeafDetail(contours), rp.cam.eye)[0]
            plain.append((mesh, base, float(nears[0])))
            seconds += time.perf_counter() - t
        rp.report.add(1)
        return seconds

    def _csg_object(self, rp: RenderPass, obj: Any, program: Program, base: int, contours: int) -> CSGObject:
        """A CSG object as the paths take it: its leaves (cut to where they can be seen under the
        level of detail), their detail, boxes and screen rectangles."""
        leaves: Sequence[Primitive] = program.leaves
        geom = self._leaf_geometry(program)
        detail = self._detail.tree(leaves, rp.lights, obj.material, geom, rp.cam, program, contours)
        hidden = None
        if self._by_request and self._detail.applies(program):
            # Sizes (hence details) came from the whole leaves; what is built is their visible part.
            leaves, geom, hidden = self._visible_leaves(program, geom)
        rects, nears, _ = leaf_rects(geom, rp.cam)
        rect = tuple(int(x) for x in combine_rects(program.op, program.arg, rects))
        return CSGObject(leaves, program, obj.material, detail, geom, rects, rect, nears, base, hidden)  # type: ignore[arg-type]

    def _draw_tree(
        self, rp: RenderPass, obj: Any, program: Program, base: int, contours: int, plain: list[Plain],
    ) -> float:
        """A CSG object: by its union, its clipped surface (queued for the front fills) or per
        pixel. Returns the seconds spent obtaining bands."""
        csg = self._csg_object(rp, obj, program, base, contours)
        n = len(csg.leaves)
        c0, r0, c1, r1 = csg.rect
        if not (c0 < c1 and r0 < r1):  # off screen
            rp.report.add(n)
            return 0.0
        if self.csg != "surface" and is_union(program):
            rp.reset_now()
            seconds = render_union(rp, csg)
            rp.grow(csg.rows)
            return seconds
        seen_key = (obj.shape, rp.lights, obj.material, contours)
        if n > policy.SURFACE_MAX_LEAVES and self.csg == "auto":
            runs = self._surfaces.large_surface(seen_key, self._csg_seen.get(seen_key), program, rp.lights,
                                                obj.material, csg.detail, rp.cam.eye)
            if runs is not None:
                plain.append((runs, base + runs.leaves, csg.nears[runs.leaves]))
                rp.report.add(n)
                return 0.0
        seconds = 0.0
        if not self._per_pixel(seen_key, n):
            t = time.perf_counter()
            csg.built = [self._bands(p, rp.lights, obj.material, d, rp.cam.eye, csg.hidden)
                         for p, d in zip(csg.leaves, csg.detail)]
            seconds += time.perf_counter() - t
            parts = self._surfaces.surface(program, csg.built)
            if parts is None and self.csg == "auto":
                self._seen(seen_key, True)  # view-dependent or too large: per pixel from now on
            elif parts is not None and parts is not PENDING:  # PENDING: built in the background, this view per pixel
                plain.extend((prep, base + i, float(csg.nears[i])) for i, prep in parts)
                rp.report.add(n)
                return seconds
        rp.reset_now()  # the image buffers must be clean before an object is resolved into them
        h, w = r1 - r0, c1 - c0
        dense_bytes = min(policy.DENSE_MAX_BYTES, memory_budget() // 4)
        if n <= policy.DENSE_MAX_LEAVES and n * h * w * LEAF_PIXEL_BYTES <= dense_bytes:
            spent, view_dependent = render_dense(rp, csg)
        else:
            sizes = csg.detail.sizes
            if csg.hidden is not None and csg.built is None and sizes is not None:  # level of detail, default builder
                rects = csg.rects
                area = np.maximum(rects[:, 2] - rects[:, 0], 0) * np.maximum(rects[:, 3] - rects[:, 1], 0)
                csg.by_rays = (sizes <= policy.RAY_LEAF_SIZE) & (area <= policy.RAY_LEAF_PIXELS)
            spent, view_dependent = render_tiled(rp, csg)
        rp.grow(csg.rows)
        if view_dependent is not None and seen_key not in self._csg_seen:
            # Under "auto": the surface on the next render, unless the bands depend on the view.
            self._seen(seen_key, view_dependent)
        return seconds + spent


_DEFAULT: Renderer | None = None
_DEFAULT_LOCK = threading.Lock()


def default_renderer() -> Renderer:
    """The module-wide :class:`Renderer` used by :func:`render`."""
    global _DEFAULT
    with _DEFAULT_LOCK:
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
