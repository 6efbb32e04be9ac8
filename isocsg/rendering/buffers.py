"""Image-sized buffers: pooled from one render to the next, staggered in memory, reset in parallel."""

from __future__ import annotations

import math
import sys
from collections import OrderedDict
from collections.abc import Sequence
from concurrent.futures import ThreadPoolExecutor
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .. import _workers
from . import policy
from .polygons import fill_rect

__all__ = ["BufferPool", "Rows", "fill_pool", "reset_rects", "staggered_empty"]

#: A rectangle of rows and columns, half-open: (row0, row1, col0, col1).
Rows = tuple[int, int, int, int]

_HUGE_PAGE = 2 << 20


def staggered_empty(shape: tuple[int, ...], dtype: Any, k: int) -> NDArray[Any]:
    """A zeroed ``(shape, dtype)`` array starting ``64 * (k % 37) + 64`` bytes into a page.

    Large allocations all start at the same offset within a 4 KiB page; a loop
    that reads one such buffer and writes another at the same index then
    stalls on every store (4K aliasing: the processor cannot tell the
    addresses apart by their low 12 bits). Staggering the starts avoids it.
    """
    dt = np.dtype(dtype)
    nbytes = math.prod(shape) * dt.itemsize
    # Large buffers start on a 2 MiB boundary (plus the stagger), so that the
    # kernel can back them with huge pages: a fill walks down many rows at
    # once, and with 4 KiB pages every row is another TLB entry.
    align = _HUGE_PAGE if nbytes >= 2 * _HUGE_PAGE else 4096
    raw = np.empty(nbytes + align + 4096, np.uint8)
    # Touch every page now: reading pages that were never written (the value
    # buffer outside the objects) page-faults on every pass on some kernels.
    raw.fill(0)
    start = (-raw.ctypes.data) % align + 64 * (k % 37) + 64
    return raw[start : start + nbytes].view(dt).reshape(shape)


def fill_pool() -> ThreadPoolExecutor:
    """The threads that fill row stripes of the image (:data:`~isocsg.rendering.policy.STRIPES` - 1 of them)."""
    return _workers.pool("fill", max(policy.STRIPES - 1, 1))


class BufferPool:
    """Image-sized buffers reused from one render to the next once no result refers to them
    any more (fresh pages cost more than the fill itself), and for the private ones the
    rectangle their last render wrote (only that needs resetting)."""

    def __init__(self) -> None:
        self._pool: OrderedDict[tuple[str, tuple[int, ...], str], list[NDArray[Any]]] = OrderedDict()
        # id of a pooled buffer -> the rectangle that may differ from its background.
        self._dirty: dict[int, Rows] = {}

    def buffer(self, name: str, shape: tuple[int, ...], dtype: Any) -> NDArray[Any]:
        """A buffer ``(shape, dtype)`` that nothing else holds (its content is the last user's)."""
        key = (name, shape, np.dtype(dtype).str)
        pool = self._pool.setdefault(key, [])
        self._pool.move_to_end(key)
        for a in pool:
            # Held only by the pool, this loop and getrefcount's argument: free to reuse.
            if sys.getrefcount(a) <= 3:
                return a
        a = staggered_empty(shape, dtype, sum(len(p) for p in self._pool.values()))
        pool.append(a)
        if len(pool) > 3:
            self._dirty.pop(id(pool.pop(0)), None)
        while len(self._pool) > 24:
            for old in self._pool.popitem(last=False)[1]:
                self._dirty.pop(id(old), None)
        return a

    def stale(self, name: str, shape: tuple[int, int], dtype: Any) -> tuple[NDArray[Any], Rows]:
        """A pooled private buffer and the rectangle that must be reset to its background
        (what its last render wrote; all of it for a fresh buffer)."""
        a = self.buffer(name, shape, dtype)
        rect = self._dirty.pop(id(a), (0, shape[0], 0, shape[1]))
        # Until the render records what it wrote, assume everything.
        self._dirty[id(a)] = (0, shape[0], 0, shape[1])
        return a, rect

    def written(self, buffer: NDArray[Any], rect: Rows) -> None:
        """Record the rectangle a render wrote into a private buffer."""
        self._dirty[id(buffer)] = rect


def reset_rects(resets: Sequence[tuple[NDArray[Any], Rows, Any]]) -> None:
    """Fill rectangles of buffers with their background, in concurrent row shares."""
    n = policy.STRIPES

    def share(k: int) -> None:
        for buf, (r0, r1, c0, c1), bg in resets:
            if r0 < r1 and c0 < c1:
                fill_rect(buf, r0 + (r1 - r0) * k // n, r0 + (r1 - r0) * (k + 1) // n, c0, c1, bg)

    futures = [fill_pool().submit(share, k) for k in range(1, n)]
    share(0)
    for f in futures:
        f.result()
