"""The threads isocsg runs work on: named pools, and background tasks that never delay exit.

Pools are made on first use under one lock (two threads asking at once get
the same pool) and forgotten in a forked child, whose copy of a pool has no
threads behind it. Background tasks (a CSG object's clipped surface, built
while views go on) run on daemon threads: an interpreter that ends meanwhile
does not wait for them, since their results would only be cached. Between
their stages they call :func:`checkpoint`, which waits while a render is in
progress (:func:`foreground`) and, at exit, raises :class:`Cancelled`: they
are asked to stop and given a short while to do so, so that
no thread is left inside native code (manifold3d) while the interpreter
finalises when that can be helped.
"""

from __future__ import annotations

import atexit
import os
import sys
import threading
import time
from collections.abc import Callable, Iterator
from concurrent.futures import Future, ThreadPoolExecutor
from contextlib import contextmanager
from typing import Any

__all__ = [
    "Cancelled", "pool", "background", "foreground", "checkpoint", "raise_if_cancelled", "cancel_background",
    "EXIT_WAIT", "YIELD_WAIT", "quiesce",
]

#: Seconds the interpreter's exit waits, in all, for background tasks to stop at their next check.
EXIT_WAIT = 0.5
#: Most seconds a background task waits at one :func:`checkpoint` for a foreground render to end
#: (so that a render that never ends, or renders back to back, do not starve it for good).
YIELD_WAIT = 2.0

_lock = threading.Lock()
_pools: dict[str, ThreadPoolExecutor] = {}
_tasks: set[threading.Thread] = set()
_cancel = threading.Event()
_idle = threading.Condition(threading.Lock())
_foreground = [0]  # renders in progress


class Cancelled(Exception):  # a state the task is in, not a failure
    """Raised inside a background task asked to stop (the process is ending)."""


def pool(name: str, workers: int) -> ThreadPoolExecutor:
    """The process's pool ``name`` of ``workers`` threads (``isocsg-<name>``), made on first use.

    Examples
    --------
    >>> pool("doc", 1) is pool("doc", 1)
    True
    """
    with _lock:
        p = _pools.get(name)
        if p is None:
            p = _pools[name] = ThreadPoolExecutor(max_workers=max(1, int(workers)), thread_name_prefix=f"isocsg-{name}")
        return p


def background(name: str, fn: Callable[..., Any], *args: Any) -> Future[Any]:
    """Run ``fn(*args)`` on a daemon thread ``isocsg-<name>``; its future holds the result, or
    the exception raised (:class:`Cancelled` for a task stopped at exit).

    Examples
    --------
    >>> background("doc", sum, [1, 2]).result()
    3
    """
    fut: Future[Any] = Future()

    def run() -> None:
        try:
            if not fut.set_running_or_notify_cancel():
                return
            try:
                fut.set_result(fn(*args))
            except BaseException as exc:  # noqa: BLE001  # handed to whoever waits (as concurrent.futures does)
                fut.set_exception(exc)
        finally:
            with _lock:
                _tasks.discard(threading.current_thread())

    thread = threading.Thread(target=run, name=f"isocsg-{name}", daemon=True)
    with _lock:
        _tasks.add(thread)
    thread.start()
    return fut


@contextmanager
def foreground() -> Iterator[None]:
    """Mark a render in progress: background tasks wait at their next :func:`checkpoint` until
    it ends (their Python work would take the interpreter lock, and their Booleans the cores,
    from the view a user waits for).

    Examples
    --------
    >>> with foreground():
    ...     pass
    """
    with _idle:
        _foreground[0] += 1
    try:
        yield
    finally:
        with _idle:
            _foreground[0] -= 1
            if _foreground[0] == 0:
                _idle.notify_all()


def checkpoint() -> None:
    """Between a background task's stages: wait while a render is in progress (up to
    :data:`YIELD_WAIT` seconds), and raise :class:`Cancelled` once the process is ending."""
    deadline = time.monotonic() + YIELD_WAIT
    with _idle:
        while _foreground[0] and not _cancel.is_set():
            left = deadline - time.monotonic()
            if left <= 0:
                break
            _idle.wait(min(left, 0.05))
    raise_if_cancelled()


def raise_if_cancelled() -> None:
    """Raise :class:`Cancelled` if background work is to stop (called between a task's stages)."""
    if _cancel.is_set():
        raise Cancelled()


def cancel_background(timeout: float = EXIT_WAIT) -> bool:
    """Ask every background task to stop and wait up to ``timeout`` seconds in all for them;
    returns whether none is left. Later tasks stop at their first check."""
    _cancel.set()
    _close_helper()  # the Booleans of background builds: stopped at once
    with _lock:
        tasks = list(_tasks)
    deadline = None if timeout is None else time.monotonic() + timeout
    for t in tasks:
        t.join(None if deadline is None else max(0.0, deadline - time.monotonic()))
    return not any(t.is_alive() for t in tasks)


def quiesce(timeout: float = 60.0) -> bool:
    """Wait up to ``timeout`` seconds for the background tasks to finish and shut the pools'
    threads down (new ones start on next use); returns whether no isocsg thread is left.

    For a process about to fork children (the command line's server): a child has none of the
    parent's threads, so no thread of the parent should hold a lock, or half a result, then.
    """
    deadline = time.monotonic() + timeout
    with _lock:
        tasks = list(_tasks)
        pools = list(_pools.values())
        _pools.clear()
    for t in tasks:
        t.join(max(0.0, deadline - time.monotonic()))
    for p in pools:
        p.shutdown(wait=True)
    _close_helper()  # a child makes its own helper
    return not any(t.is_alive() for t in tasks)


def _close_helper() -> None:
    # Only if this process has imported the helper module (whole: another thread may be importing it).
    close = getattr(sys.modules.get("isocsg._helper"), "close", None)
    if close is not None:
        close()


def _after_fork_in_child() -> None:
    # The child has none of the parent's threads: its pools and tasks are empty shells.
    global _lock, _idle
    _lock = threading.Lock()
    _idle = threading.Condition(threading.Lock())
    _foreground[0] = 0
    _pools.clear()
    _tasks.clear()


os.register_at_fork(after_in_child=_after_fork_in_child)
# Runs after the interpreter has joined its non-daemon threads, before it finalises.
atexit.register(cancel_background)
