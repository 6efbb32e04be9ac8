"""The memory budget: how much memory one isocsg call may plan to use.

Large requests (a render of many leaves at a large size, a clipped CSG
surface of many band triangles, an illuminance grid) estimate their working
memory before allocating it and raise :class:`~isocsg.errors.ResourceLimitError`
when the estimate is over the budget, instead of running the machine out of
memory. Work that can be split (per-pixel CSG in screen tiles, grids in
chunks) is split to stay under the budget rather than refused.

The budget defaults to half of the machine's physical memory (4 GiB where
that cannot be read) and can be set for the whole process with
:func:`set_memory_budget` or the ``ISOCSG_MEMORY_BUDGET`` environment variable
(bytes, or a number with a ``K``/``M``/``G`` suffix).
"""

from __future__ import annotations

import ctypes
import functools
import os
from collections.abc import Callable

from .errors import InvalidParameterError, ResourceLimitError

__all__ = ["memory_budget", "set_memory_budget", "check_memory", "release_freed_memory"]

_BUDGET: int | None = None


def _physical_memory() -> int:
    try:
        return int(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))
    except (ValueError, OSError, AttributeError):  # pragma: no cover - not POSIX
        return 8 << 30


def _parse(text: str) -> int:
    t = text.strip().upper().removesuffix("B")
    scale = {"K": 1 << 10, "M": 1 << 20, "G": 1 << 30, "T": 1 << 40}.get(t[-1:], 1)
    if scale > 1:
        t = t[:-1]
    try:
        value = float(t) * scale
    except ValueError:
        raise InvalidParameterError(f"ISOCSG_MEMORY_BUDGET must be a number of bytes (e.g. 2G), got {text!r}") from None
    if not value > 0 or value != value or value == float("inf"):
        raise InvalidParameterError(f"ISOCSG_MEMORY_BUDGET must be > 0, got {text!r}")
    return int(value)


def memory_budget() -> int:
    """The memory budget in bytes.

    Examples
    --------
    >>> memory_budget() > 0
    True
    """
    if _BUDGET is not None:
        return _BUDGET
    env = os.environ.get("ISOCSG_MEMORY_BUDGET")
    if env:
        return _parse(env)
    return _physical_memory() // 2


def set_memory_budget(nbytes: int | None) -> None:
    """Set the process-wide memory budget in bytes (``None``: back to the default).

    Raises
    ------
    InvalidParameterError
        If ``nbytes`` is not a positive integer.

    Examples
    --------
    >>> set_memory_budget(2 << 30); memory_budget()
    2147483648
    >>> set_memory_budget(None)
    """
    global _BUDGET
    if nbytes is None:
        _BUDGET = None
        return
    if isinstance(nbytes, bool) or not isinstance(nbytes, int) or nbytes <= 0:
        raise InvalidParameterError(f"memory budget must be a positive number of bytes, got {nbytes!r}")
    _BUDGET = nbytes


def check_memory(what: str, nbytes: float) -> None:
    """Raise :class:`ResourceLimitError` if ``what`` would need more than the budget.

    Examples
    --------
    >>> check_memory("a small request", 1024)
    """
    budget = memory_budget()
    if nbytes > budget:
        raise ResourceLimitError(
            f"{what} needs about {nbytes / 1e9:.2f} GB, over the memory budget of {budget / 1e9:.2f} GB "
            "(isocsg.limits.set_memory_budget or ISOCSG_MEMORY_BUDGET)"
        )


#: Kernels (:mod:`isocsg._jit`) run as plain Python, without numba, for inputs of at most this
#: much work (loop iterations, about a microsecond each as Python): a small model's first image
#: then never imports numba, whose import and first dispatch cost about a second of CPU time.
JIT_PYTHON_WORK = 2048
#: CPU seconds a process may spend running kernels as Python or NumPy (each call small, many calls:
#: a model of many leaves) before later calls compile. About what numba's import and the loading
#: of cached kernels cost (1-1.5 s): switching once that much is spent never costs more than twice
#: the better of the two choices, and the round models of a few dozen leaves that now run as NumPy
#: twins (0.3-0.6 s) stay without numba.
JIT_PYTHON_SECONDS = 1.0
#: The same bound for kernels with a vectorised NumPy twin (work: the elements the twin touches,
#: tens of nanoseconds each).
JIT_TWIN_WORK = 1 << 20


@functools.cache
def _malloc_trim() -> Callable[[int], int] | None:
    try:
        return ctypes.CDLL(None).malloc_trim  # glibc
    except (AttributeError, OSError, TypeError):  # another C library, or no CDLL(None) (Windows)
        return None


def release_freed_memory() -> None:
    """Give the heap memory freed so far back to the system, where the C library allows it (glibc).

    manifold3d allocates on its worker threads, whose malloc arenas keep what
    a Boolean frees; a build that runs its Booleans one result at a time
    (slabs) would otherwise hold every slab's working memory beside the next
    one's: the 1000-hole plate's build in ten slabs grew from 0.76 to 1.10 GB
    resident with 0.74 GB in use, and the renderer's arrays made from the
    surface came on top of that.
    """
    trim = _malloc_trim()
    if trim is not None:
        trim(0)
