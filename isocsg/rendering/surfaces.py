"""Clipped CSG surfaces (leaves' bands clipped in 3D by manifold3d), built once and filled by every later view.

Under ``Renderer(csg="auto")`` a tree's first view is resolved per pixel; its
second view starts the surface's build, in the background by default, and the
first view after it is ready fills it like a plain mesh. Trees of more than
:data:`~isocsg.rendering.policy.SURFACE_MAX_LEAVES` leaves get a trimmed surface
within :data:`~isocsg.rendering.policy.LARGE_SURFACE_SHARE` of the memory budget,
kept as :class:`~isocsg.rendering.meshes.SurfaceRuns`.

Background builds run on daemon threads (:func:`isocsg._workers.background`):
a process that ends meanwhile does not wait for them, and they stop at their
next check (:func:`isocsg._workers.checkpoint`) once it is ending; they wait
there while a view is rendered, so they never slow a view down. Their Booleans
run in the helper process (:mod:`isocsg._helper`), which the process's exit
kills at once: no thread is left inside manifold3d when the interpreter ends.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Hashable, Sequence
from concurrent.futures import Future, wait
from typing import TYPE_CHECKING, Any

import numpy as np

from .._cache import ByteCache
from .._workers import Cancelled, background, checkpoint, raise_if_cancelled
from ..csg.program import Program
from ..errors import InvalidGeometryError, ResourceLimitError
from ..kinds import Primitive
from ..laminae.model import BandMesh
from ..limits import memory_budget, release_freed_memory
from . import policy
from .detail import LeafDetail, TreeDetail
from .meshes import PreparedMesh, SurfaceRuns, mesh_bytes, prepare_mesh
from .tiles import hidden_box, leaf_geometry

if TYPE_CHECKING:
    from ..csg.surface import CSGSurface

__all__ = ["SurfaceBuilds", "PENDING"]

#: What :meth:`SurfaceBuilds.surface` returns while a surface is built in the background.
PENDING: Any = object()
#: Leaf parts of a clipped surface: (leaf index, its part's mesh).
Parts = list[tuple[int, PreparedMesh]]
#: ``bands(primitive, lights, material, detail, eye, hidden) -> (band mesh, view-dependent)``.
BandsOf = Callable[[Primitive, Sequence[Any], Any, LeafDetail, Any, Any], tuple[BandMesh, bool]]

# Surfaces are built one at a time, off the views' critical path; large trees' builds too
# (each may take its share of the budget).
_SURFACE_LOCK = threading.Lock()
_LARGE_LOCK = threading.Lock()


def surface_from_bands(program: Program, bands: Sequence[BandMesh], **options: Any) -> CSGSurface:
    """:func:`isocsg.csg.surface.surface_from_bands`, its package imported by the first clipped surface
    (a render without one loads none of it)."""
    from ..csg.surface import surface_from_bands as build

    return build(program, bands, **options)


def surface_in_helper(
    program: Program, bands: Sequence[BandMesh], *, give_bands: bool = False, **options: Any
) -> CSGSurface:
    """:func:`surface_from_bands` for a background build: in the helper process
    (:mod:`isocsg._helper`), which the process's exit stops at once, unlike a thread inside
    manifold3d; in this thread when the call cannot be sent there (a kind defined in a script).

    ``give_bands``: ``bands`` (a list no one else holds) is emptied once the helper has read
    it, so that this process's copy is freed while the helper works (a large tree's bands)."""
    from .. import _helper

    received = bands.clear if give_bands and isinstance(bands, list) else None
    try:
        return _helper.run(  # type: ignore[no-any-return]
            surface_from_bands, program, bands, cancelled=raise_if_cancelled, received=received, **options
        )
    except _helper.HelperUnavailable:
        return surface_from_bands(program, bands, **options)


class SurfaceBuilds:
    """A renderer's clipped surfaces: those kept, those being built, those deferred to the pass's end.

    Parameters
    ----------
    csg, surface_build : str
        The renderer's settings (see :class:`~isocsg.rendering.Renderer`).
    bands_of : callable
        The renderer's band meshes (:data:`BandsOf`).
    by_request : bool
        Whether the bands come from the default builder (which takes ``hidden``).
    """

    def __init__(self, csg: str, surface_build: str, bands_of: BandsOf, by_request: bool) -> None:
        self.csg, self.surface_build = csg, surface_build
        self.bands_of, self.by_request = bands_of, by_request
        self.lock = threading.Lock()  # guards the two dicts and the cache
        # Surfaces being built in the background: key -> future.
        self.building: dict[Hashable, Future[Any]] = {}
        # Large trees' surface builds decided by the render in progress, started at its end.
        self.deferred: dict[Hashable, tuple[Any, ...]] = {}
        # CSG surfaces, keyed by the leaves' band meshes and the program: (band meshes kept alive, leaf parts).
        self.cache = ByteCache(lambda: policy.SURFACE_CACHE_BYTES)

    def surface(self, program: Program, built: list[tuple[BandMesh, bool]]) -> Parts | None:
        """The leaf parts of a CSG object's clipped surface, or None to resolve it per pixel.

        Called once the renderer has declined per pixel: under ``csg="auto"``
        from the second render of an object with view-independent bands (a
        first render costs no Boolean) and few enough band triangles, under
        ``"surface"`` always (for specular bands: built every time). Surfaces
        of view-independent bands are kept. Under ``"auto"`` with
        ``surface_build="background"`` a surface not built yet is started in
        the background and :data:`PENDING` returned (this view per pixel).
        """
        bands = tuple(b for b, _ in built)
        view_dependent = any(v for _, v in built)
        if self.csg == "auto" and (
            view_dependent or sum(len(b.triangles) for b in bands) > policy.SURFACE_MAX_TRIANGLES
        ):
            return None
        key = (tuple(id(b) for b in bands), program.op.tobytes(), program.arg.tobytes())
        with self.lock:
            hit = self.cache.get(key)
            # The ids of band meshes that were dropped may be reused: compare the objects too.
            if hit is not None and all(x is y for x, y in zip(hit[0], bands)):
                return hit[1]  # type: ignore[no-any-return]
            if self.csg == "auto" and self.surface_build == "background":
                if key not in self.building:
                    self.building[key] = background("surface", self._build_in_background, key, program, bands)
                return PENDING
        return self._build(key, program, bands, view_dependent)

    def large_surface(
        self, seen_key: Hashable, seen: bool | None, program: Program, lights: Sequence[Any], material: Any,
        detail: TreeDetail, eye: Any,
    ) -> SurfaceRuns | None:
        """The clipped surface of a tree of more than :data:`~isocsg.rendering.policy.SURFACE_MAX_LEAVES`
        leaves, if ready; else None, and its background build is deferred to the pass's end when
        an earlier view found the tree's bands view-independent (``seen`` is False)."""
        key = ("tree", seen_key)
        with self.lock:
            hit = self.cache.get(key)
            if hit is not None:
                if hit[1] is None:
                    return None  # too large (or not closed): per pixel for good
                if hit[0].covers(detail):
                    return hit[1]  # type: ignore[no-any-return]
                detail = hit[0].finer(detail)  # a finer surface, built for this view's needs
            if seen is not False or key in self.building or key in self.deferred:
                return None  # a first view, view-dependent bands, or being built
        # Started once this view is done (start_deferred): the build's Python work would
        # otherwise hold the interpreter lock against this view's own.
        self.deferred[key] = (program, lights, material, detail, eye)
        return None

    def start_deferred(self) -> None:
        """Start the large trees' builds the pass deferred."""
        with self.lock:
            for key, args in self.deferred.items():
                if key not in self.building:
                    self.building[key] = background("large-surface", self._build_large, key, *args)
            self.deferred.clear()

    def wait(self, timeout: float | None = None) -> bool:
        """Wait for the surfaces being built in the background; returns whether all are done."""
        with self.lock:
            pending = list(self.building.values())
        done, left = wait(pending, timeout=timeout)
        for f in done:
            if f.exception() is not None and not isinstance(f.exception(), Cancelled):
                f.result()
        return not left

    def clear(self) -> None:
        """Forget the surfaces kept."""
        with self.lock:
            self.cache.clear()

    def _build_in_background(self, key: Hashable, program: Program, bands: tuple[BandMesh, ...]) -> Parts | None:
        try:
            checkpoint()  # not while a view is rendered
        except Cancelled:
            with self.lock:
                self.building.pop(key, None)
            raise
        with _SURFACE_LOCK:
            return self._build(key, program, bands, in_helper=True)

    def _build(
        self, key: Hashable, program: Program, bands: tuple[BandMesh, ...], view_dependent: bool = False,
        in_helper: bool = False,
    ) -> Parts | None:
        """Build (and keep, for view-independent bands) one clipped surface; a background
        build's Booleans run ``in_helper``."""
        from .._helper import HelperFailed

        try:
            raise_if_cancelled()  # (a build on the view's own path must not wait for views)
            try:
                surface = (surface_in_helper if in_helper else surface_from_bands)(program, bands)
            except (InvalidGeometryError, ResourceLimitError, HelperFailed):
                if self.csg != "auto":
                    raise
                # Bands that do not close (extreme frames) or a surface over the memory budget:
                # this object stays per pixel, and the failure is remembered so no view retries it.
                with self.lock:
                    self.cache.put(key, (bands, None), 64 * len(bands))
                return None
            raise_if_cancelled()
            parts = [(int(i), prepare_mesh(surface.leaf_bands(int(i)))) for i in np.unique(surface.leaf)]
            for _, p in parts:
                # Quads and projection scratch (pages touched) made here, in the background,
                # rather than by the first view that fills the surface.
                p.quads()
                p.proj(policy.STRIPES - 1)
                for scratch in p.projs:
                    scratch.fill(0.0)
            if not view_dependent:
                nbytes = sum(p.nbytes for _, p in parts) + sum(b.vertices.nbytes + 28 * len(b.triangles) for b in bands)
                with self.lock:
                    self.cache.put(key, (bands, parts), nbytes)
            return parts
        finally:
            with self.lock:
                self.building.pop(key, None)

    def _build_large(
        self, key: Hashable, program: Program, lights: Sequence[Any], material: Any, detail: TreeDetail, eye: Any,
    ) -> None:
        """In the background: the bands (from the caches, or built here), the trimmed Booleans
        within the share of the budget, and the parts ready to fill."""
        try:
            with _LARGE_LOCK:
                self._build_large_locked(key, program, lights, material, detail, eye)
        finally:
            with self.lock:
                self.building.pop(key, None)

    def _build_large_locked(
        self, key: Hashable, program: Program, lights: Sequence[Any], material: Any, detail: TreeDetail, eye: Any,
    ) -> None:
        from .._helper import HelperFailed

        try:
            bands, held = self._large_bands(program, lights, material, detail, eye)
            checkpoint()
            share = policy.LARGE_SURFACE_SHARE * memory_budget()
            # No cache holds the bands: this process's copy goes once the helper has it.
            surface = surface_in_helper(program, bands, give_bands=True, trim=True, max_bytes=int(share - held))
            del bands
        except (InvalidGeometryError, ResourceLimitError, HelperFailed):
            with self.lock:  # too large, or bands that do not close: per pixel from now on
                self.cache.put(key, (detail, None), 64)
            return
        checkpoint()
        parts = [(int(i), prepare_mesh(surface.leaf_bands(int(i)))) for i in np.unique(surface.leaf)]
        del surface
        runs = SurfaceRuns.of(parts)
        del parts
        # What the parts freed goes back to the system before any view runs.
        release_freed_memory()
        runs.proj(policy.STRIPES - 1)  # pages touched here, not by the first view that fills it
        for scratch in runs.projs:
            scratch.fill(0.0)
        with self.lock:
            if not self.cache.put(key, (detail, runs), runs.nbytes):
                self.cache.put(key, (detail, None), 64)  # more than the cache keeps: not again

    def _large_bands(
        self, program: Program, lights: Sequence[Any], material: Any, detail: TreeDetail, eye: Any,
    ) -> tuple[list[BandMesh], int]:
        """A large tree's bands for its trimmed surface and their bytes, or
        :class:`~isocsg.errors.ResourceLimitError` as soon as they are bound to pass the share."""
        from ..csg.surface import BYTES_PER_BOOLEAN_TRIANGLE, untrimmed_groups

        leaves = program.leaves
        # Leaves that no trim can shrink first, Boolean by Boolean: a tree whose
        # untrimmable part alone is over the bound (a union of many overlapping
        # leaves) is given up before the rest of its bands is asked for.
        geom = leaf_geometry(leaves)
        # The parts of a leaf beyond the object's box (a hole's ends) cannot be on the
        # result's boundary: they are built uncut (a few triangles instead of their bands)
        # and then trimmed away or kept as they are, and these bands are kept by no cache.
        hidden = hidden_box(*program.bounds(geom.lo, geom.hi)) if self.by_request else None
        most = policy.LARGE_SURFACE_SHARE * memory_budget() / BYTES_PER_BOOLEAN_TRIANGLE
        built: dict[int, tuple[BandMesh, bool]] = {}
        for group in untrimmed_groups(program, geom.lo, geom.hi):
            n_tri = 0
            for k, i in enumerate(group, 1):
                checkpoint()
                if i not in built:
                    built[i] = self.bands_of(leaves[i], lights, material, detail[i], eye, hidden)
                n_tri += len(built[i][0].triangles)
                # Over the bound, or clearly bound to be at this rate (four times over
                # after a sample of eight leaves): given up without the rest.
                if n_tri > most or (k >= 8 and n_tri * len(group) > 4 * most * k):
                    raise ResourceLimitError(f"{n_tri} band triangles of {k} leaves in one Boolean, over the bound")
        # The bands are all held while the Booleans run: given up when they alone would
        # pass a third of the share (or are bound to, at this rate, after a sample of 64
        # leaves), and the Booleans get what the share leaves.
        share = policy.LARGE_SURFACE_SHARE * memory_budget()
        held = 0
        for k, i in enumerate(range(len(leaves)), 1):
            checkpoint()
            if i not in built:
                built[i] = self.bands_of(leaves[i], lights, material, detail[i], eye, hidden)
            held += mesh_bytes(built[i][0])
            if held > share / 3 or (k >= 64 and held * len(leaves) > share / 3 * k):
                raise ResourceLimitError(f"{held} bytes of bands for {k} of {len(leaves)} leaves, over the bound")
        if any(vd for _, vd in built.values()):
            raise InvalidGeometryError("view-dependent bands")
        return [built[i][0] for i in range(len(leaves))], held
