"""Per-pixel CSG: a tree's program evaluated along each pixel's ray on its leaves' depth intervals.

Each leaf's front and back surfaces are filled into buffers (the ray's
interval ``[front, back]`` through the convex leaf); the kernels here visit
those surfaces nearest first and find the first depth where the program turns
from outside to inside: the visible point. A leaf a ray meets in several
intervals (a non-convex kind) comes as the union of its interval layers
(:mod:`isocsg.rendering.layers`), each one such leaf to these kernels.
"""

from __future__ import annotations

import functools

import numpy as np
from numpy.typing import NDArray

from .._jit import njit
from ..csg.program import evaluate_mask
from . import policy
from .jit import RAW
from .polygons import fill_projected

__all__ = ["truth_table", "table_of", "resolve_csg", "resolve_packed", "resolve_scratch", "fill_leaf"]


@njit(cache=True)
def truth_table(op: NDArray[np.int8], arg: NDArray[np.int64], n: int) -> NDArray[np.bool_]:
    """The program's value for every inside-mask of ``n`` leaves (bit i: inside leaf i)."""
    table = np.zeros(1 << n, np.bool_)
    inside = np.zeros(max(n, 1), np.bool_)
    stack = np.zeros(max(len(op), 1), np.bool_)
    for m in range(1 << n):
        for i in range(n):
            inside[i] = (m >> i) & 1 == 1
        table[m] = evaluate_mask(op, arg, inside, stack)
    return table


@functools.lru_cache(maxsize=64)
def _cached_table(op: bytes, arg: bytes, n: int) -> NDArray[np.bool_]:
    # 2**n evaluations of the program (milliseconds at 16 leaves): once per tree, not per render.
    return truth_table(np.frombuffer(op, np.int8), np.frombuffer(arg, np.int64), n)


def table_of(op: NDArray[np.int8], arg: NDArray[np.int64], n: int) -> NDArray[np.bool_]:
    """The truth table of a program of ``n`` leaves if ``n`` is at most
    :data:`~isocsg.rendering.policy.TABLE_LEAVES`, else empty."""
    if n > policy.TABLE_LEAVES:
        return np.zeros(0, np.bool_)
    return _cached_table(op.tobytes(), arg.tobytes(), n)


@njit(cache=True, inline="always")
def _state(table: NDArray[np.bool_], op: NDArray[np.int8], arg: NDArray[np.int64], inside: NDArray[np.bool_],
           stack: NDArray[np.bool_], mask: int) -> bool:
    if len(table):
        return table[mask]
    return evaluate_mask(op, arg, inside, stack)


#: Relative depth-key difference below which surfaces of different leaves coincide.
_COINCIDENT = 1e-9


@njit(cache=True, nogil=True)
def resolve_csg(
    kf: NDArray[np.float64], vf: NDArray[np.float32], kb: NDArray[np.float64], vb: NDArray[np.float32],
    op: NDArray[np.int8], arg: NDArray[np.int64], table: NDArray[np.bool_], gid_base: int, ox: int, oy: int,
    zkey: NDArray[np.float64], value: NDArray[np.float32], gid: NDArray[np.int32],
) -> None:
    """Per-pixel CSG on leaf intervals, depth-tested into the image buffers.

    ``op`` and ``arg`` are the object's :class:`~isocsg.csg.program.Program`
    arrays; ``table`` is their :func:`truth_table` (or empty: the program
    is then evaluated on each event).

    ``kf``/``kb`` (n, h, w) are the depth keys of each leaf's front (``+inf``
    where none) and back (``-inf`` where none) over the viewport at
    ``(oy, ox)``; a back without a front means the eye is inside that leaf.
    The leaves' surfaces are visited nearest first; all events at the same
    depth (within a relative ``1e-9``: coincident faces of different leaves
    are different triangles) are applied together (regularised operations:
    touching or coincident surfaces do not show), and the first depth where the program
    turns from outside to inside is the visible point. If a leaf enters there,
    the pixel shows that leaf's front value, otherwise the back value of a leaf
    that leaves.
    """
    n, h, w = kf.shape
    lr0 = np.full(n, oy, np.int64)
    lc0 = np.full(n, ox, np.int64)
    lh = np.full(n, h, np.int64)
    lw = np.full(n, w, np.int64)
    off = np.arange(n) * (h * w)
    resolve_packed(np.ascontiguousarray(kf).reshape(-1), np.ascontiguousarray(vf).reshape(-1),
                    np.ascontiguousarray(kb).reshape(-1), np.ascontiguousarray(vb).reshape(-1),
                    off, lr0, lc0, lh, lw, np.arange(n), op, arg, table, gid_base, oy, oy + h, ox, ox + w,
                    zkey, value, gid, np.empty(n), np.empty(n, np.int8), np.zeros(n, np.bool_),
                    np.zeros(max(len(op), 1), np.bool_), np.zeros(n, np.int64))


# Without reference counting (see isocsg.rendering.jit): the per-pixel loop
# passes arrays to inlined helpers, two atomic operations each otherwise.
@njit(**RAW)
def resolve_packed(
    kf: NDArray[np.float64], vf: NDArray[np.float32], kb: NDArray[np.float64], vb: NDArray[np.float32],
    off: NDArray[np.int64], lr0: NDArray[np.int64], lc0: NDArray[np.int64], lh: NDArray[np.int64],
    lw: NDArray[np.int64], ids: NDArray[np.int64], op: NDArray[np.int8], arg: NDArray[np.int64],
    table: NDArray[np.bool_], gid_base: int,
    row0: int, row1: int, col0: int, col1: int,
    zkey: NDArray[np.float64], value: NDArray[np.float32], gid: NDArray[np.int32],
    nxt: NDArray[np.float64], phase: NDArray[np.int8], inside: NDArray[np.bool_], stack: NDArray[np.bool_],
    loc: NDArray[np.int64],
) -> None:
    """:func:`resolve_csg` over image rows ``row0 .. row1`` and columns ``col0 .. col1``
    with each leaf's buffers packed: leaf ``i`` covers the rectangle of
    ``lh[i]`` rows and ``lw[i]`` columns at ``(lr0[i], lc0[i])``, stored row by
    row from ``off[i]`` in the flat ``kf``, ``vf``, ``kb``, ``vb``; outside it
    the leaf is absent. Pixels take the label ``gid_base + ids[i]``. The last
    five arrays are scratch (``n`` entries each, ``stack`` one per instruction)."""
    # phase: 0 before the leaf's front, 1 inside, 2 past its back.
    n = off.shape[0]
    use_table = len(table) > 0
    for rr in range(row0, row1):
        for cc in range(col0, col1):
            covered = False
            mask = 0
            for i in range(n):
                dr = rr - lr0[i]
                dc = cc - lc0[i]
                if dr < 0 or dr >= lh[i] or dc < 0 or dc >= lw[i]:
                    inside[i] = False
                    phase[i] = 2
                    nxt[i] = np.inf
                    continue
                k = off[i] + dr * lw[i] + dc
                loc[i] = k
                f = kf[k]
                b = kb[k]
                if b == -np.inf:  # no interval (a front without a back is a zero-width sliver)
                    inside[i] = False
                    phase[i] = 2
                    nxt[i] = np.inf
                elif f == np.inf:  # entered behind the near plane
                    inside[i] = True
                    if use_table:
                        mask |= 1 << i
                    phase[i] = 1
                    nxt[i] = b
                    covered = True
                else:
                    inside[i] = False
                    phase[i] = 0
                    nxt[i] = f
                    covered = True
            if not covered:
                continue
            state = _state(table, op, arg, inside, stack, mask)
            limit = zkey[rr, cc]
            while True:
                key = np.inf
                for i in range(n):
                    if nxt[i] < key:
                        key = nxt[i]
                if key == np.inf or key >= limit:
                    break  # no more surfaces, or something nearer is already drawn
                # Coincident surfaces of different leaves (a cutter's face on the
                # solid's face) come from different triangles: their keys agree only
                # to rounding, so events this close are one event.
                group = key + _COINCIDENT * abs(key)
                shown = -1
                shown_front = False
                for i in range(n):
                    if nxt[i] > group:
                        continue
                    if phase[i] == 0:
                        inside[i] = True
                        phase[i] = 1
                        nxt[i] = kb[loc[i]]
                        if nxt[i] <= group:  # zero width: in and out at once
                            inside[i] = False
                            phase[i] = 2
                            nxt[i] = np.inf
                        if not shown_front:
                            shown = i
                            shown_front = True
                    else:
                        inside[i] = False
                        phase[i] = 2
                        nxt[i] = np.inf
                        if shown < 0:
                            shown = i
                    if use_table:
                        mask = (mask | (1 << i)) if inside[i] else (mask & ~(1 << i))
                now = _state(table, op, arg, inside, stack, mask)
                if now and not state:
                    zkey[rr, cc] = key
                    value[rr, cc] = vf[loc[shown]] if shown_front else vb[loc[shown]]
                    gid[rr, cc] = gid_base + ids[shown]
                    break
                state = now


@njit(cache=True, nogil=True)
def resolve_scratch(
    n: int, n_op: int,
) -> tuple[NDArray[np.float64], NDArray[np.int8], NDArray[np.bool_], NDArray[np.bool_], NDArray[np.int64]]:
    """The scratch arrays of :func:`resolve_packed` for ``n`` leaves and ``n_op`` instructions."""
    return (np.empty(n), np.empty(n, np.int8), np.zeros(n, np.bool_), np.zeros(max(n_op, 1), np.bool_),
            np.zeros(n, np.int64))


@njit(cache=True, nogil=True)
def fill_leaf(
    kf: NDArray[np.float64], vf: NDArray[np.float32], kb: NDArray[np.float64], vb: NDArray[np.float32],
    off: int, r0: int, c0: int, h: int, w: int, proj: NDArray[np.float64], quads: NDArray[np.int32],
    vout: NDArray[np.float32], vin: NDArray[np.float32], near: float, perspective: bool,
) -> None:
    """One leaf's front and back surfaces into its packed rectangle (see :func:`resolve_packed`)."""
    zf = kf[off : off + h * w].reshape((h, w))
    zb = kb[off : off + h * w].reshape((h, w))
    zf[:] = np.inf
    zb[:] = -np.inf
    fill_projected(proj, quads, vout, vin, near, perspective, c0, r0, zf, vf[off : off + h * w].reshape((h, w)),
                   zb, vb[off : off + h * w].reshape((h, w)))


def _states_numpy(table: NDArray[np.bool_], op: NDArray[np.int8], arg: NDArray[np.int64],
                  inside: NDArray[np.bool_]) -> NDArray[np.bool_]:
    """The program's value for each row of ``inside`` (P, n): its truth table, else the program run on columns."""
    if len(table):
        return table[inside.astype(np.int64) @ (np.int64(1) << np.arange(inside.shape[1], dtype=np.int64))]
    stack: list[NDArray[np.bool_]] = []
    for o, k in zip(op.tolist(), arg.tolist()):
        if o == 0:
            stack.append(inside[:, k])
            continue
        operands = stack[len(stack) - k:]
        del stack[len(stack) - k:]
        if o == 1:
            r = np.logical_or.reduce(operands)
        elif o == 2:
            r = np.logical_and.reduce(operands)
        else:
            r = operands[0] & ~np.logical_or.reduce(operands[1:]) if k > 1 else operands[0]
        stack.append(r)
    return stack[0].copy()  # not a view of ``inside``, which the caller changes in place


@resolve_packed.twin
def _resolve_packed_numpy(
    kf: NDArray[np.float64], vf: NDArray[np.float32], kb: NDArray[np.float64], vb: NDArray[np.float32],
    off: NDArray[np.int64], lr0: NDArray[np.int64], lc0: NDArray[np.int64], lh: NDArray[np.int64],
    lw: NDArray[np.int64], ids: NDArray[np.int64], op: NDArray[np.int8], arg: NDArray[np.int64],
    table: NDArray[np.bool_], gid_base: int,
    row0: int, row1: int, col0: int, col1: int,
    zkey: NDArray[np.float64], value: NDArray[np.float32], gid: NDArray[np.int32],
    nxt: NDArray[np.float64], phase: NDArray[np.int8], inside: NDArray[np.bool_], stack: NDArray[np.bool_],
    loc: NDArray[np.int64],
) -> None:
    """:func:`resolve_packed` on all pixels at once, event after event (blocks of rows bound the memory)."""
    n = off.shape[0]
    # Only the pixels some leaf's rectangle covers can change.
    r0, r1 = max(row0, int(lr0.min(initial=row1))), min(row1, int((lr0 + lh).max(initial=row0)))
    c0, c1 = max(col0, int(lc0.min(initial=col1))), min(col1, int((lc0 + lw).max(initial=col0)))
    if n == 0 or r0 >= r1 or c0 >= c1:
        return
    block = max(1, (1 << 21) // (n * (c1 - c0)))
    cols = np.arange(c0, c1)
    with np.errstate(all="ignore"):
        for top in range(r0, r1, block):
            rr, cc = np.divmod(np.arange((min(r1, top + block) - top) * len(cols)), len(cols))
            _resolve_block(kf, vf, kb, vb, off, lr0, lc0, lh, lw, ids, op, arg, table, gid_base,
                           rr + top, cols[cc], zkey, value, gid)


def _resolve_block(
    kf: NDArray[np.float64], vf: NDArray[np.float32], kb: NDArray[np.float64], vb: NDArray[np.float32],
    off: NDArray[np.int64], lr0: NDArray[np.int64], lc0: NDArray[np.int64], lh: NDArray[np.int64],
    lw: NDArray[np.int64], ids: NDArray[np.int64], op: NDArray[np.int8], arg: NDArray[np.int64],
    table: NDArray[np.bool_], gid_base: int, rr: NDArray[np.int64], cc: NDArray[np.int64],
    zkey: NDArray[np.float64], value: NDArray[np.float32], gid: NDArray[np.int32],
) -> None:
    """The kernel's loop for the pixels ``(rr, cc)``: the same events, the same groups, the same choice."""
    dr = rr[:, None] - lr0
    dc = cc[:, None] - lc0
    present = (dr >= 0) & (dr < lh) & (dc >= 0) & (dc < lw)
    loc = np.where(present, off + dr * lw + dc, 0)
    f = np.where(present, kf[loc], np.inf)
    b = np.where(present, kb[loc], -np.inf)
    gone = b == -np.inf
    # The kernel's phase 1 is ``inside``, phase 2 ``done``, phase 0 neither.
    inside = ~gone & (f == np.inf)
    done = gone
    nxt = np.where(gone, np.inf, np.where(inside, b, f))
    live = np.flatnonzero((~gone).any(axis=1))
    rr, cc, loc, inside, done, nxt = rr[live], cc[live], loc[live], inside[live], done[live], nxt[live]
    state = _states_numpy(table, op, arg, inside)
    limit = zkey[rr, cc]
    while len(rr):
        key = np.fmin.reduce(nxt, axis=1, initial=np.inf)  # the loop's running minimum skips a NaN
        go = np.flatnonzero(~((key == np.inf) | (key >= limit)))
        if len(go) < len(rr):
            rr, cc, loc, inside, done, nxt = rr[go], cc[go], loc[go], inside[go], done[go], nxt[go]
            state, limit, key = state[go], limit[go], key[go]
        group = (key + _COINCIDENT * np.abs(key))[:, None]
        event = ~(nxt > group)
        enter = event & ~inside & ~done
        leave = event & (inside | done)
        nxt[enter] = kb[loc[enter]]
        out = leave | (enter & (nxt <= group))  # leaving, or zero width: in and out at once
        inside |= enter
        inside &= ~out
        done |= out
        nxt[out] = np.inf
        shown_front = enter.any(axis=1)
        shown = np.where(shown_front, np.argmax(enter, axis=1), np.argmax(event, axis=1))
        now = _states_numpy(table, op, arg, inside)
        hit = now & ~state
        if hit.any():
            h = np.flatnonzero(hit)
            at = loc[h, shown[h]]
            zkey[rr[h], cc[h]] = key[h]
            value[rr[h], cc[h]] = np.where(shown_front[h], vf[at], vb[at])
            gid[rr[h], cc[h]] = (gid_base + ids[shown[h]]).astype(np.int32)
            rest = np.flatnonzero(~hit)
            rr, cc, loc, inside, done, nxt = rr[rest], cc[rest], loc[rest], inside[rest], done[rest], nxt[rest]
            state, limit = now[rest], limit[rest]
        else:
            state = now


@truth_table.twin
def _truth_table_numpy(op: NDArray[np.int8], arg: NDArray[np.int64], n: int) -> NDArray[np.bool_]:
    """:func:`truth_table` with every mask at once."""
    masks = np.arange(1 << n, dtype=np.int64)
    inside = ((masks[:, None] >> np.arange(max(n, 1))) & 1).astype(np.bool_)
    if n == 0:
        inside[:] = False
    return _states_numpy(np.zeros(0, np.bool_), op, arg, inside)


# The entry points' own Python is a few lines around the kernels above: as written, whatever their size.
for _entry in (resolve_csg, fill_leaf):
    _entry.twin(_entry.py_func)
