"""Exact illuminance from point luminaires (measured intensity distributions) with hard shadows.

For a :class:`~isocsg.lighting.luminaire.PhotometricLight` at P and a
receiver p with unit normal n, l = (P - p) / r, r = |P - p|:

    E = multiplier I(C, gamma) max(0, n . l) / r^2

with (C, gamma) the type C angles of -l in the luminaire's frame, and E = 0
when the open segment p -> P crosses an occluder: the shadow of a point
source is hard (state 0 lit or 2 umbra, never penumbra). The segment test is
exact for the occluders' convex pieces (:mod:`isocsg.shadows.occluders`;
curved primitives by their tessellation): the segment meets a piece
``N x <= d`` when the parameter interval ``t`` in (0, 1) left by its
half-spaces is not empty. Each piece is shrunk by ``1e-9`` of the scene's
size, so that a segment that only grazes a face or an edge (a receiver lying
on a solid's face, a luminaire mounted on the ceiling) is not blocked.

A point that faces away from the luminaire (n . l <= 0) receives nothing from
it: state 2 for that light, as for area sources behind the receiving plane.
"""

from __future__ import annotations

import numba
import numpy as np
from numpy.typing import NDArray

from ..kinds import Solid
from ..lighting.luminaire import PhotometricLight
from .occluders import ConvexPiece, shadow_pieces

__all__ = ["point_illuminance_and_state", "segment_blocked", "GRAZE_TOL"]

#: Shrink of each occluder piece, relative to the scene's size (grazing segments are not blocked).
GRAZE_TOL = 1e-9


@numba.njit(cache=True, nogil=True)
def _blocked_kernel(P, light, normals, offsets, off, box_lo, box_hi, tol, out):  # pragma: no cover - compiled
    """out[i]: the segment P[i] -> light meets a (shrunk) piece; pieces' bounding boxes reject first."""
    lx, ly, lz = light[0], light[1], light[2]
    for i in range(P.shape[0]):
        px, py, pz = P[i, 0], P[i, 1], P[i, 2]
        dx, dy, dz = lx - px, ly - py, lz - pz
        slo0, shi0 = min(px, lx), max(px, lx)
        slo1, shi1 = min(py, ly), max(py, ly)
        slo2, shi2 = min(pz, lz), max(pz, lz)
        for k in range(off.shape[0] - 1):
            if (shi0 < box_lo[k, 0] or slo0 > box_hi[k, 0] or shi1 < box_lo[k, 1] or slo1 > box_hi[k, 1]
                    or shi2 < box_lo[k, 2] or slo2 > box_hi[k, 2]):
                continue
            t0, t1 = 0.0, 1.0
            hit = True
            for j in range(off[k], off[k + 1]):
                nx, ny, nz = normals[j, 0], normals[j, 1], normals[j, 2]
                a = nx * px + ny * py + nz * pz - offsets[j] + tol
                b = nx * dx + ny * dy + nz * dz
                if b == 0.0:
                    if a > 0.0:
                        hit = False
                        break
                elif b > 0.0:
                    t1 = min(t1, -a / b)
                else:
                    t0 = max(t0, -a / b)
                if t1 <= t0:
                    hit = False
                    break
            if hit:
                out[i] = True
                break


def segment_blocked(
    p: NDArray[np.float64], light: NDArray[np.float64], pieces: list[ConvexPiece], scale: float
) -> NDArray[np.bool_]:
    """Whether the segment from each point of ``p`` (n, 3) to ``light`` (3,) crosses a piece.

    Examples
    --------
    >>> from isocsg import Box
    >>> from isocsg.shadows import convex_pieces
    >>> pcs = convex_pieces([Box((0, 0, 1), (1, 1, 0.2))])
    >>> segment_blocked(np.array([[0.0, 0, 0], [3, 0, 0]]), np.array([0.0, 0, 2]), pcs, 3.0).tolist()
    [True, False]
    """
    out = np.zeros(len(p), dtype=np.bool_)
    if not pieces or len(p) == 0:
        return out
    normals = np.ascontiguousarray(np.vstack([pc.normals for pc in pieces]), dtype=np.float64)
    offsets = np.ascontiguousarray(np.concatenate([pc.offsets for pc in pieces]), dtype=np.float64)
    off = np.zeros(len(pieces) + 1, dtype=np.int64)
    off[1:] = np.cumsum([len(pc.offsets) for pc in pieces])
    box_lo = np.array([pc.vertices.min(axis=0) for pc in pieces], dtype=np.float64)
    box_hi = np.array([pc.vertices.max(axis=0) for pc in pieces], dtype=np.float64)
    _blocked_kernel(np.ascontiguousarray(p, dtype=np.float64), np.ascontiguousarray(light, dtype=np.float64),
                    normals, offsets, off, box_lo, box_hi, GRAZE_TOL * scale, out)
    return out


def point_illuminance_and_state(
    p: NDArray[np.float64],
    n: NDArray[np.float64],
    lights: list[PhotometricLight],
    solids: list[Solid],
    *,
    resolution: int,
    scale: float,
) -> tuple[NDArray[np.float64], NDArray[np.int8]]:
    """Illuminance (lux for intensities in cd) and worst state over ``lights`` at points ``p`` (n, 3).

    ``n`` holds unit normals (n, 3); ``solids`` are validated occluders.
    """
    E = np.zeros(len(p))
    state = np.zeros(len(p), dtype=np.int8)
    for light in lights:
        P = np.asarray(light.position, dtype=np.float64)
        v = P[None, :] - p
        r2 = np.einsum("ij,ij->i", v, v)
        r = np.sqrt(r2)
        ok = r > 0
        lvec = np.divide(v, r[:, None], out=np.zeros_like(v), where=ok[:, None])
        cos = np.einsum("ij,ij->i", n, lvec)
        front = ok & (cos > 0)
        lit = front.copy()
        if solids and front.any():
            pieces = shadow_pieces(solids, p[front], P[None, :], resolution=resolution, scale=scale)
            if pieces:
                lit[front] = ~segment_blocked(p[front], P, pieces, scale)
        e = np.zeros(len(p))
        if lit.any():
            e[lit] = light.intensity_towards(-lvec[lit]) * cos[lit] / r2[lit]
        E += e
        state = np.maximum(state, np.where(lit, 0, 2).astype(np.int8))
    return E, state
