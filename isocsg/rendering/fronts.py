"""Front-face fills of plain meshes (single primitives, clipped CSG surfaces), in concurrent row stripes."""

from __future__ import annotations

from typing import Any

import numpy as np

from .buffers import Rows, fill_pool
from .meshes import PreparedMesh, SurfaceRuns
from .polygons import fill_front_kernel, fill_front_runs, fill_rect
from .projection import project_kernel
from .renderpass import RenderPass

__all__ = ["fill_fronts", "Plain"]

#: A mesh filled by its front faces: (mesh, its label or the runs' labels, near plane or the runs' near planes).
Plain = tuple[PreparedMesh | SurfaceRuns, Any, Any]


def fill_fronts(rp: RenderPass, plain: list[Plain], key_rect: Rows, n: int) -> list[int]:
    """Meshes filled by their front faces, in one pass of ``n`` concurrent row stripes.

    Each stripe resets its rows of the buffers still to reset
    (``rp.resets``), projects the meshes itself (cheaper than waiting for a
    shared projection) and fills their front faces with the depth test. The
    stripes are balanced over the rows written last time, ``key_rect`` (a
    re-render from a nearby view). Returns the rectangle written (row0, row1,
    col0, col1).
    """
    zkey, value, gid = rp.zkey, rp.value, rp.gid
    H, W = zkey.shape
    bounds = np.empty((n, 4), np.int64)
    bounds[:] = (H, 0, W, 0)
    meshes = [(p, base, near, *p.quads()[:2]) for p, base, near in plain]  # quads made here, not in the threads
    resets = rp.resets

    def stripe(k: int, r0: int, r1: int) -> None:
        for buf, (q0, q1, c0, c1), bg in resets:
            if max(q0, r0) < min(q1, r1) and c0 < c1:
                fill_rect(buf, max(q0, r0), min(q1, r1), c0, c1, bg)
        for p, base, near, quads, quad_value in meshes:
            proj = p.proj(k)
            project_kernel(p.vertices, rp.eye, rp.a, rp.b, rp.persp, proj, 0, len(p.vertices))
            if isinstance(p, SurfaceRuns):  # labels and near planes per run (leaf)
                fill_front_runs(proj, quads, quad_value, p.starts, p.vstarts, base, near, rp.persp, r0, zkey[r0:r1],
                                value[r0:r1], gid[r0:r1], bounds[k])
                continue
            fill_front_kernel(
                proj, quads, quad_value, near, rp.persp, base, r0, zkey[r0:r1], value[r0:r1], gid[r0:r1], bounds[k],
            )

    r_top, r_bot = (key_rect[0], key_rect[1]) if key_rect[0] < key_rect[1] else (0, H)
    cuts = [r_top + (r_bot - r_top) * k // n for k in range(n + 1)]
    cuts[0], cuts[-1] = 0, H
    futures = [fill_pool().submit(stripe, k, r0, r1) for k, (r0, r1) in enumerate(zip(cuts[1:-1], cuts[2:]), 1)]
    stripe(0, cuts[0], cuts[1])
    for f in futures:
        f.result()
    rp.resets = []
    return [int(bounds[:, 0].min()), int(bounds[:, 1].max()), int(bounds[:, 2].min()), int(bounds[:, 3].max())]
