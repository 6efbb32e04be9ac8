"""Brute-force ray intervals of a closed triangle mesh, for the reference ray caster.

Written independently of :mod:`isocsg.kinds.mesh_bvh`: every ray is tested against every
triangle with the Moller-Trumbore algorithm (barycentric coordinates from the ray's
determinant, edges inclusive), in numpy, without any hierarchy. The hits along each ray are
sorted and de-duplicated (hits closer than ``DUPLICATE`` of the scene size, as a ray through an
edge meets both faces of it), then paired by parity: hit 1 enters, hit 2 leaves, and so on.
Scenes built for the tests keep the pixels' rays off edges and vertices except on sets of
measure zero, so this simple rule is enough for a reference (it is not watertight in general).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = ["MESH_LAYERS", "mesh_intervals"]

F64 = NDArray[np.float64]

#: The intervals per ray the reference follows (a test scene needing more raises).
MESH_LAYERS = 4
#: Hits closer than this fraction of the mesh's size are one (an edge or vertex met twice).
DUPLICATE = 1e-10
#: Rays per block (bounded temporaries: block x triangles).
_BLOCK = 4096


def mesh_intervals(V: F64, F: NDArray[np.int64], o: F64, d: F64) -> tuple[F64, F64, F64, F64, NDArray[np.int64], NDArray[np.int64]]:
    """Intervals ``(n, MESH_LAYERS)`` of rays ``o + t d`` (``t`` > -inf) in the mesh: t_in, t_out,
    normals in/out ``(n, MESH_LAYERS, 3)`` (outward unit normals of the faces hit) and the faces
    hit; NaN and -1 where a ray has fewer intervals."""
    a, b, c = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    e1, e2 = b - a, c - a
    nrm = np.cross(e1, e2)
    nrm /= np.linalg.norm(nrm, axis=1)[:, None]
    size = float(np.max(V.max(axis=0) - V.min(axis=0)))
    n = len(o)
    t_in = np.full((n, MESH_LAYERS), np.nan)
    t_out = np.full((n, MESH_LAYERS), np.nan)
    f_in = np.full((n, MESH_LAYERS), -1, np.int64)
    f_out = np.full((n, MESH_LAYERS), -1, np.int64)
    for s in range(0, n, _BLOCK):
        oo, dd = o[s : s + _BLOCK], d[s : s + _BLOCK]
        p = np.cross(dd[:, None, :], e2[None, :, :])  # (r, m, 3)
        det = np.einsum("mk,rmk->rm", e1, p)
        ok = np.abs(det) > 1e-300
        inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
        tv = oo[:, None, :] - a[None, :, :]
        u = np.einsum("rmk,rmk->rm", tv, p) * inv
        q = np.cross(tv, e1[None, :, :])
        v = np.einsum("rk,rmk->rm", dd, q) * inv
        t = np.einsum("mk,rmk->rm", e2, q) * inv
        hit = ok & (u >= 0) & (v >= 0) & (u + v <= 1)
        tl = np.linalg.norm(dd, axis=1)
        ts = np.where(hit, t, np.inf)
        order = np.argsort(ts, axis=1)
        ts = np.take_along_axis(ts, order, axis=1)
        # a hit within DUPLICATE of the previous one is the same crossing (an edge or a vertex)
        dup = np.zeros_like(hit)
        with np.errstate(invalid="ignore"):  # inf - inf past the last hit
            dup[:, 1:] = np.isfinite(ts[:, 1:]) & ((ts[:, 1:] - ts[:, :-1]) * tl[:, None] <= DUPLICATE * size)
        ts = np.where(dup, np.inf, ts)
        again = np.argsort(ts, axis=1, kind="stable")
        ts = np.take_along_axis(ts, again, axis=1)
        faces = np.take_along_axis(order, again, axis=1)
        count = np.isfinite(ts).sum(axis=1)
        if np.any(count % 2):
            raise ValueError("reference mesh: a ray met the mesh an odd number of times (an edge-on ray)")
        if np.any(count > 2 * MESH_LAYERS):
            raise ValueError(f"reference mesh: a ray has more than MESH_LAYERS = {MESH_LAYERS} intervals")
        width = min(2 * MESH_LAYERS, ts.shape[1])
        ts, faces = ts[:, :width], faces[:, :width]
        k = width // 2
        fin = np.isfinite(ts)
        rows = slice(s, s + len(oo))
        t_in[rows, :k] = np.where(fin[:, 0::2], ts[:, 0::2], np.nan)
        t_out[rows, :k] = np.where(fin[:, 1::2], ts[:, 1::2], np.nan)
        f_in[rows, :k] = np.where(fin[:, 0::2], faces[:, 0::2], -1)
        f_out[rows, :k] = np.where(fin[:, 1::2], faces[:, 1::2], -1)
    n_in = np.where((f_in >= 0)[..., None], nrm[np.maximum(f_in, 0)], 0.0)
    n_out = np.where((f_out >= 0)[..., None], nrm[np.maximum(f_out, 0)], 0.0)
    return t_in, t_out, n_in, n_out, f_in, f_out
