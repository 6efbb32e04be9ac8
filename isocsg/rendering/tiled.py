"""Per-pixel CSG of a large object in screen tiles (see :mod:`isocsg.rendering.tiles` for the plan).

Equal leaves (the same primitive at the same level of detail, e.g. a hole
subtracted again and again by a modelling loop) form one group: its bands are
obtained, projected and filled once per tile, and the equal leaves of a tile
read the same buffers. Groups are built in the order of the first row of tiles
their rectangle meets (:func:`~isocsg.rendering.tiles.plan_tiles`). A tile's
buffers (its groups' clipped rectangles, packed) are allocated when the first
group meeting it is built; each group is filled into all its tiles at once and
its mesh and projection are dropped right after, so the meshes alive are only
those waiting to be filled, never one per leaf. Once every group meeting a tile
is filled and its row closed, the tile resolves the program pruned to its
leaves and releases its buffers. Fills and tiles are taken from one queue by
the other threads and by the main thread whenever too many fills wait or when
more than :data:`~isocsg.rendering.policy.ROWS_AHEAD` rows are open behind the row
it builds. What is alive therefore grows with the image and the leaves' screen
footprints (bounded before anything is allocated, see
:func:`~isocsg.rendering.tiles.open_tile_pixels`). Leaves off screen are never built.
"""

from __future__ import annotations

import sys
import threading
import time
from collections import deque
from collections.abc import Callable
from concurrent.futures import wait
from typing import Any

import numpy as np

from ..limits import check_memory, memory_budget
from . import policy
from .buffers import fill_pool
from .detail import LeafDetail
from .layers import expand_tile, leaf_layers
from .meshes import PreparedMesh
from .pixel_csg import fill_leaf, resolve_packed, resolve_scratch, table_of
from .projection import project_kernel
from .renderpass import CSGObject, RenderPass
from .small_leaves import PixelRays, ray_intervals
from .tiles import LEAF_PIXEL_BYTES, open_tile_pixels, plan_tiles, tile_leaves

__all__ = ["render_tiled"]


def render_tiled(rp: RenderPass, obj: CSGObject) -> tuple[float, bool | None]:
    """Resolve a CSG object per pixel in screen tiles, into the image buffers.

    Returns the seconds spent obtaining bands and whether any was
    view-dependent (None if none was built).
    """
    return _TiledResolve(rp, obj).run()


class _TiledResolve:
    """One object's tiled resolution: the plan, the groups of equal leaves, the open tiles and
    the queue of fills and tile resolutions shared by the threads."""

    def __init__(self, rp: RenderPass, obj: CSGObject) -> None:
        self.rp, self.obj = rp, obj
        rect = obj.rect
        n = self.n = len(obj.leaves)
        budget = memory_budget()
        # Leaves clipped to the object's rectangle (the tiles' domain); those outside it are empty.
        rects = self.rects = obj.rects.copy()
        np.clip(rects[:, 0::2], rect[0], rect[2], out=rects[:, 0::2])
        np.clip(rects[:, 1::2], rect[1], rect[3], out=rects[:, 1::2])
        plan = self.plan = plan_tiles(rects, rect, len(obj.program.op), min(policy.TILE_MAX_BYTES, budget // 8))
        self.side, self.ox, self.oy = plan.side, rect[0], rect[1]
        self.on = np.flatnonzero((rects[:, 0] < rects[:, 2]) & (rects[:, 1] < rects[:, 3]))
        self._group()
        H, W = rp.zkey.shape
        peak = open_tile_pixels(rects[self.reps], plan, policy.ROWS_AHEAD)
        check_memory(
            f"render: per-pixel CSG of {n} leaves ({len(self.members)} distinct) in {plan.side}-pixel tiles "
            f"({peak} leaf pixels open at once)",
            peak * LEAF_PIXEL_BYTES + H * W * policy.IMAGE_PIXEL_BYTES,
        )
        occupied = np.diff(plan.start) > 0
        self.row_tiles = [np.flatnonzero(occupied[r * plan.cols : (r + 1) * plan.cols]) + r * plan.cols
                          for r in range(plan.rows)]
        self.nears_l = obj.nears.tolist()
        # Per open tile: (buffers, pruned op, arg, leaf ids, offsets, rows0, cols0, rows, cols).
        self.tiles: dict[int, tuple[Any, ...]] = {}
        self.slots: list[list[tuple[int, int]]] = [[] for _ in self.members]  # per group: (tile, slot) to fill
        self.pending: dict[int, int] = {}  # per open tile: groups not filled yet, plus one until its row closes
        self.cond = threading.Condition()
        self.queue: deque[tuple[Any, ...]] = deque()
        self.left = [len(t) for t in self.row_tiles]  # tiles of each row not resolved yet
        self.error: BaseException | None = None
        self.queued = 0  # rows of tiles closed
        self.done = 0  # rows of tiles resolved
        self.fills = 0  # fills queued or running
        self.open = True
        self.rays = PixelRays(rp.cam)

    def _group(self) -> None:
        """Groups of equal leaves (equal leaves have equal rectangles), in order of their first row."""
        obj, rects = self.obj, self.rects
        self.group_of = np.full(self.n, -1, np.int64)
        self.members: list[list[int]] = []
        self.details: list[LeafDetail] = list(obj.detail)
        index: dict[Any, int] = {}
        for i in self.on.tolist():
            g = index.setdefault((obj.leaves[i], self.details[i]), len(self.members))
            if g == len(self.members):
                self.members.append([])
            self.members[g].append(i)
            self.group_of[i] = g
        self.reps = np.array([m[0] for m in self.members], np.int64)
        # Groups of leaves a ray meets in several intervals (resolved by layers, see .layers).
        # The kinds present first (one pass in C): trees of convex kinds pay nothing more.
        several = any(getattr(kind, "max_intervals", 1) > 1 for kind in set(map(type, obj.leaves)))
        self.layered = ({g for g, i in enumerate(self.reps.tolist()) if obj.leaves[i].max_intervals > 1}
                        if several else set())
        self.layers: dict[int, dict[int, list[Any]]] = {}  # per tile, per slot of such a group: its layers
        first = (rects[self.reps, 1] - self.oy) // self.side
        self.order = np.argsort(first, kind="stable").tolist()
        self.first_l = first.tolist()

    def open_tile(self, t: int) -> None:
        """Allocate tile ``t``'s buffers (main thread only). Equal leaves of the tile share one slot."""
        c0, r0, c1, r1 = self.plan.tile(t)
        op, arg, ids, off, lr0, lc0, lh, lw = tile_leaves(
            self.obj.program.op, self.obj.program.arg, self.plan.leaf[self.plan.start[t] : self.plan.start[t + 1]],
            self.n, self.rects, c0, r0, c1, r1)
        groups = self.group_of[ids]
        _, rep, inv = np.unique(groups, return_index=True, return_inverse=True)
        sizes = (lh * lw)[rep]
        starts = np.concatenate([[0], np.cumsum(sizes)])
        off = starts[:-1][inv].astype(np.int64)
        total = max(int(starts[-1]), 1)
        bufs = (np.empty(total), np.empty(total, np.float32), np.empty(total), np.empty(total, np.float32))
        self.tiles[t] = (bufs, op, arg, ids, off, lr0, lc0, lh, lw)
        for j in rep.tolist():
            self.slots[int(groups[j])].append((t, j))
        self.pending[t] = len(rep) + 1

    def ready(self, t: int) -> None:
        """Under the lock: one more of tile ``t``'s groups filled (or its row closed)."""
        self.pending[t] -= 1
        if self.pending[t] == 0:
            self.queue.appendleft(("tile", t))  # before waiting fills: it releases memory

    def fill(self, g: int, prep: PreparedMesh) -> None:
        """Group ``g``'s mesh into all its tiles (projection and quads here, on a worker, while
        the main thread builds the next group)."""
        rp = self.rp
        proj = np.empty((7, len(prep.vertices)))
        project_kernel(prep.vertices, rp.eye, rp.a, rp.b, rp.persp, proj, 0, len(prep.vertices))
        quads, vout, vin = prep.quads()
        near = self.nears_l[self.members[g][0]]
        done = []
        for t, j in self.slots[g]:
            (kf, vf, kb, vb), _, _, _, off, lr0, lc0, lh, lw = self.tiles[t]
            if g in self.layered:
                leaf = self.obj.leaves[self.members[g][0]]
                self.layers.setdefault(t, {})[j] = leaf_layers(leaf, prep, self.rays, int(lr0[j]), int(lc0[j]),
                                                               int(lh[j]), int(lw[j]), near)
                done.append(t)
                continue
            fill_leaf(kf, vf, kb, vb, int(off[j]), int(lr0[j]), int(lc0[j]), int(lh[j]), int(lw[j]),
                      proj, quads, vout, vin, near, rp.persp)
            done.append(t)
        with self.cond:
            self.fills -= 1
            for t in done:
                self.ready(t)
            self.cond.notify_all()

    def fill_rays(self, g: int) -> None:
        """Group ``g``'s leaf into all its tiles by exact rays (:mod:`~isocsg.rendering.small_leaves`)."""
        leaf = self.obj.leaves[self.members[g][0]]
        near = self.nears_l[self.members[g][0]]
        done = []
        for t, j in self.slots[g]:
            (kf, vf, kb, vb), _, _, _, off, lr0, lc0, lh, lw = self.tiles[t]
            o, h, w = int(off[j]), int(lh[j]), int(lw[j])
            kf[o : o + h * w], vf[o : o + h * w], kb[o : o + h * w], vb[o : o + h * w] = ray_intervals(
                leaf, self.rays, int(lr0[j]), int(lc0[j]), h, w, near, self.rp.lights, self.obj.material)
            done.append(t)
        with self.cond:
            self.fills -= 1
            for t in done:
                self.ready(t)
            self.cond.notify_all()

    def resolve(self, t: int) -> None:
        """Tile ``t``'s program on its leaves' intervals, into the image; its buffers released."""
        rp = self.rp
        c0, r0, c1, r1 = self.plan.tile(t)
        tile = self.tiles[t] if not self.layered else self._layered_tile(t)
        (kf, vf, kb, vb), op, arg, ids, off, lr0, lc0, lh, lw = tile
        if len(ids):
            resolve_packed(kf, vf, kb, vb, off, lr0, lc0, lh, lw, ids, op, arg, table_of(op, arg, len(ids)),
                           self.obj.base, r0, r1, c0, c1, rp.zkey, rp.value, rp.gid,
                           *resolve_scratch(len(ids), len(op)))
        with self.cond:
            del self.tiles[t], self.pending[t]
            self.layers.pop(t, None)
            self.left[t // self.plan.cols] -= 1
            self._advance()
            self.cond.notify_all()

    def _layered_tile(self, t: int) -> tuple[Any, ...]:
        """Tile ``t`` with its leaves of several intervals as unions of their layers."""
        tile = self.tiles[t]
        groups = self.group_of[tile[3]]
        _, rep, inv = np.unique(groups, return_index=True, return_inverse=True)
        layers_of = {k: self.layers[t][int(rep[inv[k]])] for k in range(len(groups)) if int(groups[k]) in self.layered}
        return expand_tile(tile, layers_of) if layers_of else tile

    def _advance(self) -> None:
        # Under the lock: count the rows whose tiles are all resolved.
        while self.done < self.queued and self.left[self.done] == 0:
            self.done += 1

    def work(self, wait_for_more: bool, limit: int = -1) -> None:
        """Take tasks from the queue until it is empty (and closed, if ``wait_for_more``), ``limit`` at most."""
        cond = self.cond
        while limit != 0:
            with cond:
                while not self.queue and self.open and wait_for_more and self.error is None:
                    cond.wait()
                if not self.queue or self.error is not None:
                    return
                task = self.queue.popleft()
            try:
                if task[0] == "tile":
                    self.resolve(task[1])
                elif task[0] == "rays":
                    self.fill_rays(task[1])
                else:
                    self.fill(*task[1:])
            except BaseException as exc:  # noqa: BLE001  (handed to the main thread)
                with cond:
                    self.error = self.error or exc
                    self.queue.clear()
                    cond.notify_all()
                return
            limit -= 1

    def help_until(self, condition: Callable[[], bool]) -> None:
        """Main thread: run queued tasks (or wait for the workers) until ``condition()`` holds."""
        while True:
            with self.cond:
                while not condition() and not self.queue and self.error is None:
                    self.cond.wait()
                if condition() or self.error is not None:
                    return
            self.work(False, 1)

    def run(self) -> tuple[float, bool | None]:
        """Build the groups row by row of tiles, with the workers filling and resolving behind."""
        self.seconds = 0.0
        self.view_dependent: bool | None = None
        self.threads = max(1, policy.STRIPES)
        workers = [fill_pool().submit(self.work, True) for _ in range(1, self.threads)]
        try:
            pos = 0
            for row in range(self.plan.rows):
                # At most ROWS_AHEAD rows behind this one still open: bounds the tiles alive.
                self.help_until(lambda row=row: self.done >= row - policy.ROWS_AHEAD)  # type: ignore[misc]
                if self.error is not None:
                    break
                pos = self._build_row(row, pos)
                with self.cond:
                    if self.error is not None:
                        break
                    self._close_row(row)
        finally:
            with self.cond:
                if sys.exc_info()[0] is not None:
                    self.queue.clear()
                    self.error = self.error or sys.exc_info()[1]
            if self.error is None:
                self.help_until(lambda: self.done >= self.plan.rows)
            with self.cond:
                self.open = False
                self.cond.notify_all()
            wait(workers)  # never return while a worker still writes the image
        for f in workers:
            f.result()
        if self.error is not None:
            raise self.error
        self.rp.report.add(self.n - len(self.on))  # leaves off screen: nothing to build
        return self.seconds, self.view_dependent

    def _build_row(self, row: int, pos: int) -> int:
        """Build and queue the groups whose first row of tiles is ``row`` (from ``order[pos]``);
        returns the next position."""
        obj, plan, side = self.obj, self.plan, self.side
        while pos < len(self.order) and self.first_l[self.order[pos]] <= row:
            g = self.order[pos]
            pos += 1
            i = self.members[g][0]
            c0, r0, c1, r1 = self.rects[i].tolist()
            for tr in range((r0 - self.oy) // side, (r1 - 1 - self.oy) // side + 1):
                for tc in range((c0 - self.ox) // side, (c1 - 1 - self.ox) // side + 1):
                    if tr * plan.cols + tc not in self.tiles:
                        self.open_tile(tr * plan.cols + tc)
            if obj.by_rays is not None and obj.by_rays[i] and g not in self.layered:
                self._queue(("rays", g), len(self.members[g]))  # a few pixels: no bands
                if self.error is not None:
                    break
                continue
            t = time.perf_counter()
            prep, vd = self.rp.meshes.leaf_mesh(obj.leaves[i], self.rp.lights, obj.material, self.details[i],
                                                self.rp.cam.eye, None if obj.built is None else obj.built[i],
                                                tiled=True, hidden=obj.hidden)
            self.seconds += time.perf_counter() - t
            self.view_dependent = bool(self.view_dependent) or vd
            self._queue(("fill", g, prep), len(self.members[g]))
            del prep
            if self.error is not None:
                break
        return pos

    def _queue(self, task: tuple[Any, ...], leaves: int) -> None:
        """Queue a group's fill (main thread), and help once more than a few fills wait (they hold
        their meshes)."""
        with self.cond:
            self.queue.append(task)
            self.fills += 1
            self.cond.notify_all()
        self.rp.report.add(leaves)
        self.help_until(lambda: self.fills <= 2 * self.threads)

    def _close_row(self, row: int) -> None:
        """Under the lock: row ``row`` of tiles gets no more groups."""
        for t in self.row_tiles[row].tolist():
            if t not in self.tiles:  # no group reached it (cannot happen: occupied tiles have leaves)
                self.open_tile(t)
            self.ready(t)
        self.queued = row + 1
        self._advance()
        self.cond.notify_all()
