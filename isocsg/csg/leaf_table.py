"""The leaves of a program as arrays: vectorised extents and breakpoints along a direction.

Sections (:mod:`isocsg.csg.section`) and volumes (:mod:`isocsg.csg.volume`) read every leaf's exact
extent along a plane's normal at once from this table instead of asking each leaf in turn.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..kinds.base import LeafForm
from .program import Program

__all__ = ["LeafTable", "leaf_table"]


@dataclass(frozen=True, slots=True, eq=False)
class LeafTable:
    """The leaves of a program as arrays, for vectorised extents and batched sections.

    Each leaf's row comes from its kind (:meth:`~isocsg.kinds.base.Primitive.leaf_row`):
    ``kind`` holds its :class:`~isocsg.kinds.base.LeafForm` code (``BALL``, ``FRUSTUM``,
    ``AXIS_BOX``, ``HULL`` or ``GENERIC``) and the other columns that form's values; unused
    entries are 0. ``GENERIC`` leaves are reached through their own members (``extent``,
    ``breakpoints``, ``section``, ``signed_distance``).
    """

    kind: NDArray[np.int8]  # LeafForm codes
    center: NDArray[np.float64]  # BALL, FRUSTUM, AXIS_BOX centre (others: their box's centre)
    radius: NDArray[np.float64]  # sphere radius
    axis: NDArray[np.float64]  # truncus unit axis
    height: NDArray[np.float64]  # truncus height
    r1: NDArray[np.float64]
    r2: NDArray[np.float64]
    half: NDArray[np.float64]  # box half sizes
    poly_vertices: NDArray[np.float64]  # hull vertices of all polyhedra, concatenated
    poly_start: NDArray[np.int64]  # per leaf: start of its vertices (polyhedra only), -1 otherwise
    poly_count: NDArray[np.int64]
    others: dict[int, Any]  # leaf index -> primitive, for GENERIC leaves

    def extents(self, n: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Exact extents ``(lo, hi)`` of every leaf along the unit vector ``n``."""
        c = self.center @ n
        lo = np.empty(len(self.kind))
        hi = np.empty(len(self.kind))
        k = self.kind
        sph = k == LeafForm.BALL
        lo[sph], hi[sph] = c[sph] - self.radius[sph], c[sph] + self.radius[sph]
        tr = k == LeafForm.FRUSTUM
        if tr.any():
            an = self.axis[tr] @ n
            ext = np.sqrt(np.clip(1.0 - an * an, 0.0, 1.0))
            e1 = c[tr] + an * self.height[tr] / 2
            e2 = c[tr] - an * self.height[tr] / 2
            lo[tr] = np.minimum(e1 - self.r1[tr] * ext, e2 - self.r2[tr] * ext)
            hi[tr] = np.maximum(e1 + self.r1[tr] * ext, e2 + self.r2[tr] * ext)
        bx = k == LeafForm.AXIS_BOX
        if bx.any():
            h = self.half[bx] @ np.abs(n)
            lo[bx], hi[bx] = c[bx] - h, c[bx] + h
        ph = np.nonzero(k == LeafForm.HULL)[0]
        if len(ph):
            proj = self.poly_vertices @ n
            starts = self.poly_start[ph]
            lo[ph] = np.minimum.reduceat(proj, starts)
            hi[ph] = np.maximum.reduceat(proj, starts)
        for i in np.nonzero(k == LeafForm.GENERIC)[0].tolist():  # other kinds: their own exact support
            lo[i], hi[i] = self.others[i].extent(n)
        return lo, hi

    def breakpoints(self, n: NDArray[np.float64]) -> NDArray[np.float64]:
        """Every leaf's extents along ``n`` and the heights where its sections' area can have a
        kink (vertices, rims; ``GENERIC`` leaves: their own ``breakpoints``), unsorted."""
        lo, hi = self.extents(n)
        out = [lo, hi]
        k = self.kind
        tr = k == LeafForm.FRUSTUM
        if tr.any():
            # The end circles' centres (where a cap's section starts or stops widening) and
            # their lowest and highest points (where a tilted cap starts or stops cutting the
            # sections: the section's area has a kink there).
            c = self.center[tr] @ n
            un = self.axis[tr] @ n
            an = un * self.height[tr] / 2
            ext = np.sqrt(np.clip(1.0 - un * un, 0.0, 1.0))
            out += [c + an, c - an, c + an - self.r1[tr] * ext, c + an + self.r1[tr] * ext,
                    c - an - self.r2[tr] * ext, c - an + self.r2[tr] * ext]
        bx = k == LeafForm.AXIS_BOX
        if bx.any():
            signs = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=np.float64)
            out.append(((self.center[bx] @ n)[:, None] + (self.half[bx][:, None, :] * signs) @ n).ravel())
        if (k == LeafForm.HULL).any():
            out.append(self.poly_vertices @ n)
        for i in np.nonzero(k == LeafForm.GENERIC)[0].tolist():
            out.append(np.asarray(self.others[i].breakpoints(n), dtype=np.float64).ravel())
        return np.concatenate(out)


@functools.lru_cache(maxsize=16)
def leaf_table(prog: Program) -> LeafTable:
    """The :class:`LeafTable` of a program (cached for the last few programs)."""
    n = len(prog.leaves)
    kind = np.zeros(n, np.int8)
    center = np.zeros((n, 3))
    radius = np.zeros(n)
    axis = np.zeros((n, 3))
    height = np.zeros(n)
    r1 = np.zeros(n)
    r2 = np.zeros(n)
    half = np.zeros((n, 3))
    pv: list[NDArray[np.float64]] = []
    others: dict[int, Any] = {}
    pstart = -np.ones(n, np.int64)
    pcount = np.zeros(n, np.int64)
    total = 0
    for i, p in enumerate(prog.leaves):
        row = p.leaf_row()
        kind[i] = row.form
        if row.center is not None:
            center[i] = row.center
        if row.form == LeafForm.BALL:
            radius[i] = row.radius
        elif row.form == LeafForm.FRUSTUM:
            axis[i], height[i], r1[i], r2[i] = row.axis, row.height, row.r1, row.r2
        elif row.form == LeafForm.AXIS_BOX:
            half[i] = row.half
        elif row.form == LeafForm.HULL:
            hv = np.asarray(row.vertices, dtype=np.float64)
            pv.append(hv)
            pstart[i], pcount[i] = total, len(hv)
            total += len(hv)
        else:
            others[i] = p
    poly = np.vstack(pv) if pv else np.zeros((0, 3))
    return LeafTable(kind, center, radius, axis, height, r1, r2, half, poly, pstart, pcount, others)
