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

import numpy as np
from numpy.typing import NDArray

from ..kinds import Solid
from ..lighting.luminaire import PhotometricLight
from .occluders import ConvexPiece, shadow_pieces

__all__ = ["point_illuminance_and_state", "segment_blocked", "GRAZE_TOL"]

#: Shrink of each occluder piece, relative to the scene's size (grazing segments are not blocked).
GRAZE_TOL = 1e-9
#: Receivers per block of the vectorised segment tests (bounds the (block, planes) arrays).
BLOCK = 65536


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
    blocked = np.zeros(len(p), dtype=bool)
    tol = GRAZE_TOL * scale
    for k0 in range(0, len(p), BLOCK):
        q = p[k0 : k0 + BLOCK]
        seg = light[None, :] - q
        out = blocked[k0 : k0 + BLOCK]
        for pc in pieces:
            todo = ~out
            if not todo.any():
                break
            a = q[todo] @ pc.normals.T - pc.offsets[None, :] + tol  # <= 0 inside the shrunk piece
            b = seg[todo] @ pc.normals.T
            with np.errstate(divide="ignore", invalid="ignore"):
                r = -a / b
            lo = np.max(np.where(b < 0, r, -np.inf), axis=1, initial=0.0)
            hi = np.min(np.where(b > 0, r, np.inf), axis=1, initial=1.0)
            parallel_out = np.any((b == 0) & (a > 0), axis=1)
            hit = (hi > lo) & ~parallel_out
            idx = np.nonzero(todo)[0]
            out[idx[hit]] = True
    return blocked


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
