"""Per-pixel CSG of a small object over its whole screen rectangle (one buffer per leaf).

Each leaf's front and back surfaces are filled into buffers of the object's
screen rectangle (known before any band exists), then row stripes resolve the
program per pixel (:mod:`isocsg.rendering.pixel_csg`). Larger objects go through
screen tiles (:mod:`isocsg.rendering.tiled`).
"""

from __future__ import annotations

import threading
import time
from concurrent.futures import Future, ThreadPoolExecutor, wait

import numpy as np
from numpy.typing import NDArray

from .. import _workers
from ..kinds.base import LeafForm
from . import policy
from .buffers import fill_pool
from .layers import layer_counts, resolve_dense_layers
from .meshes import PreparedMesh
from .pixel_csg import resolve_packed, resolve_scratch, table_of
from .polygons import fill_projected, fill_rect
from .projection import project_kernel
from .renderpass import CSGObject, RenderPass
from .scratch import SCRATCH

__all__ = ["render_dense", "leaf_pool"]


def leaf_pool() -> ThreadPoolExecutor:
    """The single worker that fills CSG leaves while the next leaf is built."""
    return _workers.pool("leaf", 1)


def render_dense(rp: RenderPass, obj: CSGObject) -> tuple[float, bool | None]:
    """Resolve a small CSG object per pixel over its whole screen rectangle, into the image buffers.

    When the leaves' bands are not given they are obtained here, leaf by
    leaf, and each leaf is filled by a worker thread while the next one is
    built; the last leaf's rows are shared by both threads. Returns the
    seconds spent obtaining bands and whether any was view-dependent.
    """
    ox, oy, x1, y1 = obj.rect
    w, h = x1 - ox, y1 - oy
    n = len(obj.leaves)
    # One worker fills the leaves in order (they share projection scratch
    # when a primitive repeats): the kernels release the GIL, so building
    # the next leaf's bands goes on meanwhile.
    concurrent = policy.STRIPES > 1 and w * h >= policy.STRIPE_MIN_PIXELS // 4
    # Buffers of the object's rectangle (not the image), lent for this object only.
    counts = layer_counts(obj.leaves)  # None unless a leaf has several intervals per ray
    with SCRATCH.borrow([((n, h, w), np.float64)] * 2 + [((n, h, w), np.float32)] * 2) as (kf, kb, vf, vb):
        meshes: dict[int, PreparedMesh] | None = None if counts is None else {}
        seconds, view_dependent = _fill_leaves(rp, obj, concurrent, kf, vf, kb, vb, meshes)
        if meshes is not None and counts is not None:
            resolve_dense_layers(rp, obj, counts, meshes, (kf, vf, kb, vb))
            return seconds, view_dependent
        flat = [x.reshape(-1) for x in (kf, vf, kb, vb)]
        lr0, lc0 = np.full(n, oy, np.int64), np.full(n, ox, np.int64)
        lh, lw = np.full(n, h, np.int64), np.full(n, w, np.int64)
        off, ids = np.arange(n, dtype=np.int64) * (h * w), np.arange(n, dtype=np.int64)
        op, arg = obj.program.op, obj.program.arg
        table = table_of(op, arg, n)

        def stripe(r0: int, r1: int) -> None:
            resolve_packed(*flat, off, lr0, lc0, lh, lw, ids, op, arg, table, obj.base,
                           oy + r0, oy + r1, ox, x1, rp.zkey, rp.value, rp.gid, *resolve_scratch(n, len(op)))

        stripes = policy.STRIPES
        cuts = [h * k // stripes for k in range(stripes + 1)] if concurrent and h >= 2 * stripes else [0, h]
        futures = [fill_pool().submit(stripe, r0, r1) for r0, r1 in zip(cuts[1:-1], cuts[2:])]
        stripe(cuts[0], cuts[1])
        for f in futures:
            f.result()
    return seconds, view_dependent


def _fill_leaves(
    rp: RenderPass, obj: CSGObject, concurrent: bool, kf: NDArray[np.float64], vf: NDArray[np.float32],
    kb: NDArray[np.float64], vb: NDArray[np.float32], meshes: dict[int, PreparedMesh] | None = None,
) -> tuple[float, bool]:
    """Each leaf's front and back surfaces into its buffers ``(kf, vf)``, ``(kb, vb)``; returns
    the seconds spent obtaining bands and whether any was view-dependent. ``meshes``, if given,
    keeps the band meshes of the leaves with several intervals per ray."""
    ox, oy = obj.rect[0], obj.rect[1]
    h, w = kf.shape[1], kf.shape[2]
    n = len(obj.leaves)
    nears = obj.nears
    jobs: list[Future[None]] = []

    def fill_rows(i: int, p: PreparedMesh, proj: NDArray[np.float64], r0: int, r1: int) -> None:
        fill_rect(kf[i], r0, r1, 0, w, np.inf)
        fill_rect(kb[i], r0, r1, 0, w, -np.inf)
        fill_projected(proj, *p.quads(), float(nears[i]), rp.persp, ox, oy + r0, kf[i, r0:r1], vf[i, r0:r1],
                       kb[i, r0:r1], vb[i, r0:r1])

    def leaf(i: int, p: PreparedMesh) -> None:
        proj = p.proj()
        project_kernel(p.vertices, rp.eye, rp.a, rp.b, rp.persp, proj, 0, len(p.vertices))
        fill_rows(i, p, proj, 0, h)

    def shared_leaf(i: int, p: PreparedMesh) -> None:
        # The last leaf: nothing left to build, so this thread and the worker
        # (once it is done with the earlier leaves) take row chunks in turn.
        proj = p.proj(1)  # not the worker's scratch: it may still fill this mesh for an earlier leaf
        project_kernel(p.vertices, rp.eye, rp.a, rp.b, rp.persp, proj, 0, len(p.vertices))
        p.quads()  # made here, not by both threads at once
        last = policy.LAST_CHUNKS
        chunks = [(h * k // last, h * (k + 1) // last) for k in range(last)]
        lock = threading.Lock()

        def drain() -> None:
            while True:
                with lock:
                    if not chunks:
                        return
                    r0, r1 = chunks.pop(0)
                fill_rows(i, p, proj, r0, r1)

        jobs.append(leaf_pool().submit(drain))
        drain()

    seconds = 0.0
    view_dependent = False
    built = obj.built
    # Spheres last: their bands take longer to build than to fill, other
    # leaves' the other way round (Johnson's rule for a two-stage line).
    balls = [p.leaf_row().form == LeafForm.BALL for p in obj.leaves] if built is None else []
    order = sorted(range(n), key=lambda i: balls[i]) if built is None else range(n)
    seen: set[int] = set()
    try:
        for k, i in enumerate(order):
            t = time.perf_counter()
            prep, vd = rp.meshes.leaf_mesh(obj.leaves[i], rp.lights, obj.material, obj.detail[i], rp.cam.eye,
                                           None if built is None else built[i], hidden=obj.hidden)
            view_dependent |= vd
            seconds += time.perf_counter() - t
            if meshes is not None and getattr(obj.leaves[i], "max_intervals", 1) > 1:
                meshes[i] = prep
            if not concurrent:
                leaf(i, prep)
            elif k == n - 1 and id(prep) not in seen and h >= policy.LAST_CHUNKS:
                shared_leaf(i, prep)
            else:
                jobs.append(leaf_pool().submit(leaf, i, prep))
            seen.add(id(prep))
            rp.report.add(1)
    finally:
        wait(jobs)  # never give back buffers that a worker still writes
    for job in jobs:
        job.result()
    return seconds, view_dependent
