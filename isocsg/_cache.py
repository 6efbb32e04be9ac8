"""One mapping bounded by the bytes of its values, for every cache of large arrays.

The renderer's caches (prepared band meshes, clipped surfaces, leaf geometry)
and the lamina cache of :mod:`isocsg.laminae.builder` are all a
:class:`ByteCache`: least recently used entries go first, and no cache holds
more than its share of :func:`isocsg.limits.memory_budget`. A cache is not
thread-safe by itself; its owner holds a lock around it where threads share it.
"""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Callable, Hashable
from typing import Any

from .limits import memory_budget

__all__ = ["ByteCache"]


class ByteCache:
    """A mapping bounded by the bytes of its values (as told on insertion).

    Parameters
    ----------
    limit : int or callable
        Most bytes kept, or a function returning them (read on every insertion,
        so a module-level setting can change it).
    scan_resistant : bool, default False
        See below.
    share : int, default 8
        Never more than ``memory_budget() // share`` bytes.

    Least recently used entries go first. A scan-resistant cache (the prepared
    band meshes) is more careful: entries remember the pass (a render, see
    :meth:`new_pass`) that last used them. Room for a new entry is made by
    dropping the least recently used entries that neither this pass nor the
    previous one used; when only such entries are left, the new one is not
    kept. So a model whose working set is larger than the cache keeps a stable
    part of it from one view to the next (plain LRU under the cyclic order of a
    render would drop exactly what the next view needs first), and a model
    that fits is never rebuilt; an entry alone over the limit is not kept.
    Otherwise the newest entry is kept, even over the limit, when the cache is
    otherwise empty.

    Examples
    --------
    >>> cache = ByteCache(100)
    >>> cache.put("a", 1, 60), cache.put("b", 2, 60)
    (True, True)
    >>> cache.get("a"), cache.get("b"), len(cache), cache.nbytes
    (None, 2, 1, 60)
    """

    def __init__(self, limit: int | Callable[[], int], *, scan_resistant: bool = False, share: int = 8) -> None:
        self._limit = limit if callable(limit) else int(limit)
        self.share = int(share)
        self.scan_resistant = bool(scan_resistant)
        self.nbytes = 0
        self.generation = 0
        self._items: OrderedDict[Hashable, tuple[Any, int, int]] = OrderedDict()

    @property
    def limit(self) -> int:
        """Most bytes kept (before the share of the memory budget)."""
        return int(self._limit()) if callable(self._limit) else self._limit

    @limit.setter
    def limit(self, value: int) -> None:
        self._limit = int(value)

    def __len__(self) -> int:
        return len(self._items)

    def new_pass(self) -> None:
        """Begin a pass (a render): what the previous pass used stays protected during this one."""
        self.generation += 1

    def get(self, key: Hashable) -> Any:
        """The value under ``key`` (now the most recently used), or None."""
        hit = self._items.get(key)
        if hit is None:
            return None
        self._items.move_to_end(key)
        if hit[2] != self.generation:
            self._items[key] = (hit[0], hit[1], self.generation)
        return hit[0]

    def pop(self, key: Hashable) -> Any:
        """Remove and return the value under ``key``, or None."""
        old = self._items.pop(key, None)
        if old is None:
            return None
        self.nbytes -= old[1]
        return old[0]

    def put(self, key: Hashable, value: Any, nbytes: int) -> bool:
        """Keep ``value`` under ``key``; returns whether it was kept."""
        self.pop(key)
        nbytes = int(nbytes)
        limit = min(self.limit, memory_budget() // self.share)
        if self.scan_resistant and nbytes > limit:
            return False  # alone over the limit: it would only block the entries that fit
        items = self._items
        while self.nbytes + nbytes > limit and items:
            first = next(iter(items.values()))
            if self.scan_resistant and first[2] >= self.generation - 1:
                return False  # everything left is in use by this pass or the previous one
            self.nbytes -= items.popitem(last=False)[1][1]
        items[key] = (value, nbytes, self.generation)
        self.nbytes += nbytes
        return True

    def clear(self) -> None:
        """Forget every entry."""
        self._items.clear()
        self.nbytes = 0
