"""A numpy CSG ray caster with exact shading: the benchmarks' reference image.

Every leaf is convex, so a ray meets it in one interval ``[t_in, t_out]``
(the primitives' analytic ``intersect_rays``). The CSG result along a ray can
only change at those 2k depths; the visible point is the first depth ``t >= 0``
just after which the tree's program says "inside". If that depth is
leaf j's entry, the normal is j's outward normal; if it is j's exit (the wall
of a cut), the normal is reversed. The pixel gets the conventions' shading
formula (``isocsg.shade``) at that point.
"""

from __future__ import annotations

import numpy as np

from isocsg import Camera, Material, shade
from isocsg.csg.program import combine_masks
from isocsg.csg.section import solid_program

__all__ = ["raycast"]


def _run(prog, inside: np.ndarray) -> np.ndarray:
    """Evaluate a CSG program on per-leaf membership columns ``inside`` (n, k)."""
    return prog.evaluate(lambda i, _: inside[:, i], combine_masks)


def raycast(solid, camera: Camera, lights, material: Material | None = None) -> np.ndarray:
    """The exact float32 image ``(H, W)`` of one solid, NaN where nothing is hit."""
    prog = solid_program(solid)
    prims = prog.leaves
    d = camera.ray_directions().reshape(-1, 3)
    o = camera.ray_origins().reshape(-1, 3)
    n_rays, k = len(d), len(prims)
    t_in = np.empty((n_rays, k))
    t_out = np.empty((n_rays, k))
    n_in = np.empty((n_rays, k, 3))
    n_out = np.empty((n_rays, k, 3))
    for j, p in enumerate(prims):
        h = p.intersect_rays(o, d)
        t_in[:, j], t_out[:, j], n_in[:, j], n_out[:, j] = h.t_in, h.t_out, h.n_in, h.n_out
    hit_any = np.any(np.isfinite(t_in) & (t_in <= t_out), axis=1)
    img = np.full(n_rays, np.nan)
    rows = np.nonzero(hit_any)[0]
    if len(rows) == 0:
        return img.reshape(camera.height, camera.width).astype(np.float32)
    ti, to = t_in[rows], t_out[rows]
    cand = np.concatenate([ti, to], axis=1)  # (m, 2k): column c < k is leaf c's entry, else exit
    order = np.argsort(cand, axis=1)
    found = np.full(len(rows), -1)
    t_vis = np.full(len(rows), np.inf)
    for c in range(2 * k):
        col = order[:, c]
        t = cand[np.arange(len(rows)), col]
        todo = (found < 0) & np.isfinite(t) & (t >= 0)
        if not todo.any():
            continue
        # membership just after t: entering leaves count, leaving ones do not
        inside = (ti <= t[:, None]) & (t[:, None] < to)
        is_entry = col < k
        leaf = col % k
        r = np.arange(len(rows))
        inside[r, leaf] = is_entry
        res = _run(prog, inside) & todo
        found = np.where(res, col, found)
        t_vis = np.where(res, t, t_vis)
    ok = found >= 0
    sel = rows[ok]
    col = found[ok]
    leaf = col % k
    normals = np.where((col < k)[:, None], n_in[sel, leaf], -n_out[sel, leaf])
    pts = o[sel] + t_vis[ok, None] * d[sel]
    img[sel] = shade(pts, normals, camera.eye, lights, material)
    return img.reshape(camera.height, camera.width).astype(np.float32)
