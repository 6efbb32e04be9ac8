"""Scratch memory lent to one render at a time, shared by every renderer of the process.

The first write to fresh memory costs a page fault per 4 KiB page (about
0.7 ms per MB on the reference machine, several times that while another
thread faults or frees memory at the same time): more than filling the
buffers. The per-pixel CSG buffers are needed only while an object is
resolved, so they are lent from a pool and given back afterwards; a new
:class:`~isocsg.rendering.Renderer` reuses the pages of the last one.

Examples
--------
>>> import numpy as np
>>> pool = ScratchPool()
>>> block, (a, b) = pool.lend([((2, 3), np.float64), ((4,), np.float32)])
>>> a.shape, b.dtype.name
((2, 3), 'float32')
>>> pool.give_back(block)  # the next lend of at most its size reuses it
>>> with pool.borrow([((4,), np.int32)]) as (c,):
...     c.shape
(4,)
"""

from __future__ import annotations

import threading
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from typing import Any

import numpy as np
from numpy.typing import NDArray

__all__ = ["ScratchPool", "SCRATCH"]

_PAGE = 4096


class ScratchPool:
    """Blocks of bytes lent out and given back, kept up to a total size.

    Parameters
    ----------
    limit : int, default 512 MiB
        Most bytes kept while not lent (a larger block is freed when given back).
    keep : int, default 4
        Most blocks kept.

    Notes
    -----
    Thread-safe: concurrent renders each get a block of their own.
    """

    def __init__(self, limit: int = 512 << 20, keep: int = 4) -> None:
        self._limit = int(limit)
        self._keep = int(keep)
        self._free: list[NDArray[np.uint8]] = []
        self._lock = threading.Lock()

    def lend(self, specs: Sequence[tuple[tuple[int, ...], Any]]) -> tuple[NDArray[np.uint8], list[NDArray[Any]]]:
        """One block holding an uninitialised array per ``(shape, dtype)`` of ``specs``.

        Each array starts 64 bytes further into a 4 KiB page than the one
        before: arrays at the same offset within a page slow a loop that reads
        one and writes another at the same index (4K aliasing).

        Returns
        -------
        block : ndarray of uint8
            To be handed to :meth:`give_back` once the arrays are no longer used.
        arrays : list of ndarray
            Views into ``block``, C-contiguous.
        """
        sizes = [int(np.prod(shape, dtype=np.int64)) * np.dtype(dt).itemsize for shape, dt in specs]
        need = sum(-(-s // _PAGE) * _PAGE + _PAGE for s in sizes) + _PAGE
        block = self._take(need)
        arrays = []
        pos = (-block.ctypes.data) % _PAGE
        for k, ((shape, dt), size) in enumerate(zip(specs, sizes)):
            start = pos + 64 * (k % 63 + 1)
            arrays.append(block[start : start + size].view(dt).reshape(shape))
            pos += -(-size // _PAGE) * _PAGE + _PAGE
        return block, arrays

    def give_back(self, block: NDArray[np.uint8]) -> None:
        """Return a block from :meth:`lend`; the pool keeps it while under its limits."""
        with self._lock:
            self._free.append(block)
            while self._free and (len(self._free) > self._keep or sum(b.size for b in self._free) > self._limit):
                self._free.pop(0)  # the longest unused

    @contextmanager
    def borrow(self, specs: Sequence[tuple[tuple[int, ...], Any]]) -> Iterator[list[NDArray[Any]]]:
        """:meth:`lend` for the time of a ``with`` block, given back at its end."""
        block, arrays = self.lend(specs)
        try:
            yield arrays
        finally:
            self.give_back(block)

    def clear(self) -> None:
        """Free every block not lent out."""
        with self._lock:
            self._free.clear()

    def _take(self, nbytes: int) -> NDArray[np.uint8]:
        with self._lock:
            fits = [k for k, b in enumerate(self._free) if b.size >= nbytes]
            if fits:
                return self._free.pop(min(fits, key=lambda k: self._free[k].size))
        # A quarter more: the next object may be a little larger.
        return np.empty(nbytes + nbytes // 4, np.uint8)


#: The pool of the per-pixel CSG buffers.
SCRATCH = ScratchPool()
