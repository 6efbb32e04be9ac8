"""A union of leaves by the depth test, nearest leaves first, hidden ones skipped (occlusion culling).

A union needs no per-pixel CSG and no clipped surface: its surface is the
nearest front face of its leaves, which the depth test finds.
"""

from __future__ import annotations

import time

import numpy as np
from numpy.typing import NDArray

from . import policy
from .buffers import fill_pool
from .occlusion import ball_covered, camera_rays
from .polygons import fill_front_kernel
from .projection import project_kernel
from .renderpass import CSGObject, RenderPass
from .tiles import leaf_near_keys

__all__ = ["render_union"]


def render_union(rp: RenderPass, obj: CSGObject) -> float:
    """Fill a union of leaves by the depth test, nearest leaves first, skipping hidden ones.

    The leaves are taken in the order of their nearest possible depth
    (:func:`~isocsg.rendering.tiles.leaf_near_keys`); a leaf whose bounding
    ball is hidden everywhere by what is already drawn
    (:func:`~isocsg.rendering.occlusion.ball_covered`) is skipped without its
    bands being built or filled (in a lattice of 1000 spheres, 729 are hidden
    from any corner view). The others' front faces are filled into the image
    buffers, each leaf's rows split between the fill threads. Returns the
    seconds spent obtaining bands.
    """
    geom, nears, rects, base = obj.geom, obj.nears, obj.rects, obj.base
    keys = leaf_near_keys(geom, rp.cam, nears)
    # Each leaf's bounding ball: the sphere itself, or its box's circumscribed ball.
    centers = np.where(geom.sphere[:, None], geom.center, 0.5 * (geom.lo + geom.hi))
    radii = np.where(geom.sphere, geom.radius, 0.5 * np.linalg.norm(geom.hi - geom.lo, axis=1))
    ray = camera_rays(rp.cam)
    zkey, value, gid = rp.zkey, rp.value, rp.gid
    H, W = zkey.shape
    bounds = np.empty((policy.STRIPES, 4), np.int64)
    bounds[:] = (H, 0, W, 0)
    # One projection scratch for all leaves (grown as needed), not one kept with each mesh.
    proj = np.empty((7, 0))

    def fill(quads: NDArray[np.int32], quad_value: NDArray[np.float32], i: int, r0: int, r1: int, k: int) -> None:
        fill_front_kernel(proj, quads, quad_value, float(nears[i]), rp.persp, base + i, r0, zkey[r0:r1], value[r0:r1],
                          gid[r0:r1], bounds[k])

    seconds = 0.0
    for i in np.argsort(keys, kind="stable").tolist():
        c0, r0, c1, r1 = rects[i].tolist()
        if c0 < c1 and r0 < r1 and not ball_covered(zkey, r0, r1, c0, c1, float(keys[i]), float(nears[i]), ray,
                                                    centers[i], float(radii[i])):
            t = time.perf_counter()
            front = rp.meshes.front_mesh(obj.leaves[i], rp.lights, obj.material, obj.detail[i], rp.cam.eye, obj.hidden)
            seconds += time.perf_counter() - t
            nv = len(front.vertices)
            if proj.shape[1] < nv:
                proj = np.empty((7, max(nv, 2 * proj.shape[1])))
            project_kernel(front.vertices, rp.eye, rp.a, rp.b, rp.persp, proj, 0, nv)
            quads, quad_value = front.polys, front.values
            # Rows split between threads when the leaf is large enough to pay for the hand-over.
            parts = max(1, min(policy.STRIPES, (r1 - r0) * (c1 - c0) // policy.UNION_SPLIT_PIXELS, r1 - r0))
            cuts = [r0 + (r1 - r0) * k // parts for k in range(parts + 1)]
            jobs = [fill_pool().submit(fill, quads, quad_value, i, cuts[k], cuts[k + 1], k) for k in range(1, parts)]
            fill(quads, quad_value, i, cuts[0], cuts[1], 0)
            for job in jobs:
                job.result()
        rp.report.add(1)
    return seconds
