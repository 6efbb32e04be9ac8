"""Where a patch's ring measure changes its form: the sweep parameters the integration must split at.

Between two such parameters the pieces of a ring (between its crossings with the other leaves'
surfaces) keep their number and their classification, and the ring measure is smooth; where a
ring becomes tangent to another leaf's surface (a plate's face meeting a cone in a hyperbola,
at its vertex; a cone's ring touching the plate's plane; a sphere's ring entering a rod through
its pole), where a crossing runs into a rim or an edge of either leaf, or where two crossings
meet, it is not: the number of crossings or of pieces on the boundary changes, and the measure
has a kink, a square-root end or a jump there. A Gauss-Kronrod interval across such a point
converges slowly and its Kronrod-Gauss difference can understate its error by orders of
magnitude, so these points are located (the rings' *signature*: crossings, pieces on the
boundary, undecided pieces, compared on a grid of the sweep and bisected to rounding wherever
it differs between neighbours) and become break points of the sweep.

A change that begins and ends between two grid rings (a feature narrower than the grid's step
in the sweep, away from every other break point: a thin rod's footprint on a large leaf) is not
seen on the grid; the integration adds to the grid the heights of the points where the other
patches' rings cross the leaf's surface (a rod's rings, bisected to where they enter the large
leaf, cross it inside the footprint), so that such a feature is found from the other side. A
patch without a sweep direction (an ellipsoid's, an elliptic truncus') takes no such heights.

A break alone is not enough where the measure's form changes on a scale far below the
interval's: next to a cone's ring tangent to a plate's face (where the cone's radius is the
plate's half thickness ``w``), the removed arc ``2 rho asin(w / rho)`` differs from its smooth
continuation only within a few ``w`` of the break, and the Gauss-Kronrod nodes of a long
interval (the nearest 0.4 % of its length from its end) see none of it: case 520 of the
1000-tree run was 1.1e-9 off in area with an error estimate of 5e-11. The sweep is therefore
graded towards each located change (:func:`graded`: points at 4^-1 .. 4^-10 of the neighbouring
intervals, down to 1e-7 of the sweep), so that every scale near it has an interval whose nodes
see it, and its Kronrod-Gauss difference measures it. A change is not graded towards where the
nodes near it would meet rings with undecided pieces (a chord touching the rim of a coincident
disc: the band along the rim, which finer intervals would measure again and again as undecided,
an error that does not shrink).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

__all__ = ["BAND_MAX", "EDGE_GAP", "GRADE_FLOOR", "GRADE_LEVELS", "GRID_PER_INTERVAL", "NEAREST_NODE",
           "centre_bands", "graded", "signature_breaks"]

F64 = NDArray[np.float64]
#: Grid rings per interval between the sweep's given break points.
GRID_PER_INTERVAL = 16
#: Most changes located per patch (a ring family along another surface flickers: no more than these).
MAX_CHANGES = 256
#: Most searches again beyond a located change, per pair of grid rings.
MAX_ROUNDS = 6
#: A change is searched for again this fraction of the sweep beyond the last one located.
SKIP = 1e-8
#: Widest undecided band (a fraction of the sweep) whose centre replaces its edge as a break.
BAND_MAX = 1e-6
#: The sides of a change are looked at this fraction of the sweep away from it (bands are wider).
EDGE_GAP = 1e-13
#: Points of the grading next to a located change, at 4^-1 .. 4^-GRADE_LEVELS of each neighbour interval.
GRADE_LEVELS = 10
#: The Gauss-Kronrod 7-15 nodes nearest an interval's ends lie this fraction of it inside.
NEAREST_NODE = 0.004
#: The grading stops this fraction of the sweep from the change (a feature narrower than that
#: and unseen costs at most its width squared, relative).
GRADE_FLOOR = 1e-7


def signature_breaks(
    signature: Callable[[F64], NDArray[np.int64]], breaks: F64, grid: F64 | None = None,
    undecided: Callable[[F64], NDArray[np.int64]] | None = None, resolution: float = 0.0,
) -> F64:
    """The sweep parameters where ``signature`` (one integer per ring) changes, to rounding (or
    to ``resolution`` of the sweep, where that is coarser: a change misplaced by ``d`` moves the
    integral by about ``d`` of the patch's measure, so a tolerance of 1e-3 needs no rounding).

    ``breaks``: the sweep's break points (sorted, at least two); each interval between them is
    gridded (or ``grid`` is the grid: sorted, from the first break to the last), and every
    neighbouring pair of grid rings with different signatures is bisected; the part beyond a
    located change is searched again (a pair can hide several changes). With ``undecided`` (the
    undecided pieces per ring), a change at the edge of an undecided band is moved to the band's
    centre (:func:`centre_bands`)."""
    if grid is None:
        u = np.linspace(0.0, 1.0, GRID_PER_INTERVAL + 1)[:-1]
        grid = np.concatenate([a + (b - a) * u for a, b in zip(breaks[:-1], breaks[1:])] + [breaks[-1:]])
    sig = signature(grid)
    diff = np.flatnonzero(sig[1:] != sig[:-1])
    a, b, sa, sb = grid[diff], grid[diff + 1], sig[diff], sig[diff + 1]
    span = float(breaks[-1] - breaks[0])
    found: list[F64] = []
    count = rounds = 0
    while len(a) and count < MAX_CHANGES:
        lo, hi, s_hi = a.copy(), b.copy(), sb.copy()
        for _ in range(64):
            wide = hi - lo > np.maximum(4e-16 * np.maximum(np.abs(hi), span), resolution * span)
            if not wide.any():
                break
            mid = 0.5 * (lo + hi)
            sm = signature(mid)
            same = (sm == sa) | ~wide
            lo = np.where(same, mid, lo)
            hi = np.where(same, hi, mid)
            s_hi = np.where(same, s_hi, sm)
        found.append(0.5 * (lo + hi) if undecided is None else centre_bands(undecided, lo, hi, span, resolution))
        count += len(a)
        # another change between the one found and the pair's far end: searched from a little
        # beyond it (a ring through a cone's apex flickers; its neighbourhood is one break)
        nxt = hi + SKIP * span
        more = nxt < b
        a, b, sb = nxt[more], b[more], sb[more]
        sa = signature(a) if len(a) else sb
        more = sa != sb
        a, b, sa, sb = a[more], b[more], sa[more], sb[more]
        rounds += 1
        if rounds >= MAX_ROUNDS:
            break
    return np.concatenate(found) if found else np.zeros(0)


def centre_bands(
    undecided: Callable[[F64], NDArray[np.int64]], lo: F64, hi: F64, span: float, resolution: float = 0.0,
) -> F64:
    """The break points of changes bracketed by ``[lo, hi]`` (to rounding): where one side of a
    bracket has undecided pieces and the other none, the change is at the edge of a tolerance
    band (a ring crossing another surface at an angle lies within the coincidence tolerance of
    it for a short stretch of the sweep, and its pieces there are undecided); the crossing
    itself, where the ring measure jumps, is the band's centre (the band is symmetric about it
    to first order). The band's far edge is found by doubling steps and bisection; a band wider
    than ``BAND_MAX`` of the sweep, or not closed on the far side, keeps the edge found."""
    x = 0.5 * (lo + hi)
    gap = EDGE_GAP * span  # (a ring right at a band's edge has pieces flickering between states)
    u_lo, u_hi = undecided(lo - gap), undecided(hi + gap)
    band = (u_lo > 0) != (u_hi > 0)
    if not band.any():
        return x
    idx = np.flatnonzero(band)
    edge = np.where(u_hi[idx] > 0, hi[idx], lo[idx])
    way = np.where(u_hi[idx] > 0, 1.0, -1.0)  # into the band
    step = np.full(len(idx), gap)
    inside, outside = edge.copy(), np.full(len(idx), np.nan)
    while np.isnan(outside).any():
        open_ = np.isnan(outside) & (step <= BAND_MAX * span)
        if not open_.any():
            break
        q = edge + way * step
        free = undecided(q) == 0
        outside = np.where(open_ & free, q, outside)
        inside = np.where(open_ & ~free, q, inside)
        step = np.where(open_, 2.0 * step, step)
    ok = ~np.isnan(outside)
    a, b = inside[ok], outside[ok]
    for _ in range(64):
        wide = np.abs(b - a) > np.maximum(4e-16 * np.maximum(np.abs(b), span), resolution * span)
        if not wide.any():
            break
        m = 0.5 * (a + b)
        free = undecided(m) == 0
        a, b = np.where(free | ~wide, a, m), np.where(free & wide, m, b)
    far = np.full(len(idx), np.nan)
    far[ok] = 0.5 * (a + b)
    x[idx] = np.where(ok, 0.5 * (edge + far), x[idx])
    return x


def graded(breaks: F64, kinks: F64) -> tuple[F64, F64, NDArray[np.int64]]:
    """Points to add to ``breaks`` (sorted) next to each of ``kinks`` (located changes, among the
    breaks to rounding): at ``4^-k`` (k = 1 .. ``GRADE_LEVELS``) of each neighbouring interval's
    length ``d`` from the change, none closer than ``GRADE_FLOOR`` of the sweep; for each, the
    point ``NEAREST_NODE * d`` from the change (as near as the nodes of the interval between the
    change and the point come to it: where the caller looks for undecided rings), and the index
    of its change in ``kinks``."""
    if len(kinks) == 0 or len(breaks) < 2:
        return np.zeros(0), np.zeros(0), np.zeros(0, np.int64)
    span = float(breaks[-1] - breaks[0])
    i = np.clip(np.searchsorted(breaks, kinks), 1, len(breaks) - 1)
    i = np.where(kinks - breaks[i - 1] < breaks[i] - kinks, i - 1, i)  # the break nearest each change
    b = breaks[i]
    left = np.where(i > 0, b - breaks[np.maximum(i - 1, 0)], 0.0)
    right = np.where(i < len(breaks) - 1, breaks[np.minimum(i + 1, len(breaks) - 1)] - b, 0.0)
    f = 4.0 ** -np.arange(1, GRADE_LEVELS + 1)
    dl, dr = left[:, None] * f, right[:, None] * f
    ok_l, ok_r = dl >= GRADE_FLOOR * span, dr >= GRADE_FLOOR * span
    bb = np.broadcast_to(b[:, None], dl.shape)
    owner = np.broadcast_to(np.arange(len(b))[:, None], dl.shape)
    pts = np.concatenate([(bb - dl)[ok_l], (bb + dr)[ok_r]])
    near = np.concatenate([(bb - NEAREST_NODE * dl)[ok_l], (bb + NEAREST_NODE * dr)[ok_r]])
    return pts, near, np.concatenate([owner[ok_l], owner[ok_r]])
