"""A helper process for native work done in the background: it can be stopped at once, a thread cannot.

A thread cannot be stopped inside native code. One still inside manifold3d when the
interpreter finalises leaves manifold3d's objects alive: nanobind prints "leaked
instances" at exit. When the call returns during finalisation, the process can end in
``terminate called without an active exception`` (SIGABRT).
Waiting for the call would delay the process's exit by as long as the Boolean takes.

So background work that runs long in native code (a clipped CSG surface's Booleans)
runs here, in one helper process per isocsg process, made on first use. The background
thread sends the call and waits for the answer, in Python, checking every
:data:`POLL` seconds whether the process is ending (:func:`isocsg._workers.raise_if_cancelled`).
When it is, the thread kills the helper and raises :class:`~isocsg._workers.Cancelled`.
At exit, :func:`isocsg._workers.cancel_background` kills the helper too.

- The helper runs the same isocsg (the folder holding the package comes first on the
  helper's ``PYTHONPATH`` unless it is a site directory), with the parent's environment and
  memory budget.
- It has no terminal: its standard error goes to ``/dev/null``, so a caller that captures
  the parent's output never waits for the helper. Warnings raised in the helper are raised
  again in the parent.
- It ends when its parent does (its input closes, or the parent's pid changes).
- A forked child forgets its parent's helper and makes its own when it needs one.

A call whose function or arguments cannot be sent (a kind defined in a script, which the
helper cannot import) raises :class:`HelperUnavailable`; the caller runs the call in its
own thread instead, as before.
"""

from __future__ import annotations

import os
import pickle
import select
import struct
import subprocess
import sys
import threading
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any

from .limits import memory_budget, release_freed_memory, set_memory_budget

__all__ = ["HelperUnavailable", "HelperFailed", "POLL", "run", "close", "helper_pid"]

#: Seconds between two checks, while waiting for the helper, of whether the process is ending.
POLL = 0.05
_HEADER = struct.Struct("<Q")
_CHUNK = 1 << 20

_lock = threading.Lock()  # one call at a time; guards _proc
_proc: list[subprocess.Popen[bytes] | None] = [None]


class HelperUnavailable(Exception):
    """The call cannot be sent to the helper (its function or arguments do not pickle, the
    helper cannot import them, or no helper can be started); the caller runs it in its own
    thread instead."""


class HelperFailed(RuntimeError):
    """The helper gave no answer: it ended (killed by the system, e.g. out of memory), or its
    answer could not be read."""


def helper_pid() -> int | None:
    """The helper process's pid, or None when this process has none running."""
    proc = _proc[0]
    return proc.pid if proc is not None and proc.poll() is None else None


def run(
    fn: Callable[..., Any], *args: Any, cancelled: Callable[[], None], received: Callable[[], None] | None = None,
    **kwargs: Any,
) -> Any:
    """``fn(*args, **kwargs)`` in the helper process; its result, or the exception it raised.

    Parameters
    ----------
    fn : callable
        A module-level function (sent by reference, as :mod:`pickle` does).
    cancelled : callable
        Called every :data:`POLL` seconds while waiting; it raises to stop the call (the
        helper is then killed, and the exception passes on).
    received : callable, optional
        Called once the helper has read the call, before it runs it: the caller may drop
        its own copy of large arguments then (the helper has its own).

    Raises
    ------
    HelperUnavailable
        ``fn`` or the arguments cannot be sent, the helper cannot read them, or no helper
        process can be started (``received`` has not been called).
    HelperFailed
        The helper ended without an answer, or its answer could not be read.
    """
    try:
        call = _Message((fn, args, kwargs, memory_budget()))
    except (pickle.PicklingError, AttributeError, TypeError) as exc:
        raise HelperUnavailable(str(exc)) from exc
    with _lock:
        proc = _proc[0]
        if proc is None or proc.poll() is not None:
            proc = _proc[0] = _start()
        try:
            _send(proc, call)
            del call
            status, detail = _receive(proc, cancelled)
            if status == "unreadable":
                raise HelperUnavailable(detail)
            if received is not None:
                received()
            status, value, caught = _receive(proc, cancelled)
        except HelperUnavailable:
            raise  # the helper waits for the next call
        except BaseException:
            _kill_locked()  # cancelled, or the pipe broke: the helper's state is unknown
            raise
    for message, category, filename, lineno in caught:
        warnings.warn_explicit(message, category, filename, lineno)
    if status == "error":
        raise value
    return value


def close() -> None:
    """Kill the helper, if there is one (it is made again on next use). A call in progress is
    not waited for: the helper is killed first, and the call ends at once with
    :class:`HelperFailed` (or its caller's cancellation)."""
    proc = _proc[0]
    if proc is not None:
        proc.kill()  # before the lock, which a waiting call holds until it sees the helper end
    with _lock:
        _kill_locked()


def _kill_locked() -> None:
    proc, _proc[0] = _proc[0], None
    if proc is not None:
        proc.kill()
        proc.wait()
        for pipe in (proc.stdin, proc.stdout):
            if pipe is not None:
                pipe.close()


def _start() -> subprocess.Popen[bytes]:
    import site

    root = str(Path(__file__).resolve().parent.parent)
    env = dict(os.environ)
    # This isocsg first, unless it is installed: a site directory on PYTHONPATH would come
    # before the standard library (and an old backport there would shadow it).
    if root not in {*site.getsitepackages(), site.getusersitepackages()}:
        env["PYTHONPATH"] = os.pathsep.join(p for p in (root, env.get("PYTHONPATH", "")) if p)
    try:
        return subprocess.Popen(
            [sys.executable, "-c", "from isocsg._helper import serve; serve()"],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, env=env,
            # its own session: a Ctrl-C at the terminal goes to the parent, which then kills it
            start_new_session=True,
        )
    except OSError as exc:  # no interpreter to start (an embedded Python), or no process left
        raise HelperUnavailable(f"no helper process: {exc}") from exc


class _Message:
    """A pickled object with its large buffers (NumPy arrays) out of band: sent from their own
    memory and received into buffers of their own, never copied into one stream of bytes."""

    def __init__(self, obj: Any) -> None:
        buffers: list[pickle.PickleBuffer] = []
        self.meta = pickle.dumps(obj, protocol=5, buffer_callback=buffers.append)
        self.buffers = [b.raw() for b in buffers]

    def write(self, out: Any) -> None:
        sizes = [len(self.meta)] + [b.nbytes for b in self.buffers]
        out.write(_HEADER.pack(len(sizes)) + struct.pack(f"<{len(sizes)}Q", *sizes))
        out.write(self.meta)
        for b in self.buffers:
            out.write(b)
        out.flush()


def _send(proc: subprocess.Popen[bytes], call: _Message) -> None:
    try:
        call.write(proc.stdin)
    except (BrokenPipeError, OSError) as exc:
        raise HelperFailed("the helper process ended before it read the call") from exc


def _receive(proc: subprocess.Popen[bytes], cancelled: Callable[[], None]) -> Any:
    """The helper's next message, waited for in Python and checked with ``cancelled`` every
    :data:`POLL` seconds."""
    assert proc.stdout is not None
    fd = proc.stdout.fileno()

    def exactly(n: int) -> bytearray:
        out, got = bytearray(n), 0  # one buffer of the part's size, filled in place
        while got < n:
            ready, _, _ = select.select([fd], [], [], POLL)
            if not ready:
                cancelled()
                continue
            chunk = os.read(fd, min(_CHUNK, n - got))
            if not chunk:
                raise HelperFailed(f"the helper process ended without an answer (exit status {proc.wait()})")
            out[got:got + len(chunk)] = chunk
            got += len(chunk)
        return out

    try:
        return _read_message(exactly)
    except (pickle.UnpicklingError, TypeError, AttributeError, ImportError, ValueError) as exc:
        # e.g. an exception class whose arguments do not round-trip
        raise HelperFailed(f"the helper's answer could not be read: {type(exc).__name__}: {exc}") from exc


def _read_message(exactly: Callable[[int], bytearray]) -> Any:
    (count,) = _HEADER.unpack(exactly(_HEADER.size))
    sizes = struct.unpack(f"<{count}Q", exactly(8 * count))
    meta = exactly(sizes[0])
    buffers = [exactly(n) for n in sizes[1:]]
    return pickle.loads(meta, buffers=buffers)


def _forget_after_fork() -> None:
    # The child's copy is its parent's helper: leave it to the parent, make another on next use.
    global _lock
    _lock = threading.Lock()
    _proc[0] = None


os.register_at_fork(after_in_child=_forget_after_fork)


# --- the helper's side ---------------------------------------------------------------------------


def serve() -> None:  # pragma: no cover - runs in the helper process (tests/test_helper_process.py)
    """The helper's loop: read a call from standard input, say it was read, run it, answer on
    standard output; until the input closes or the parent ends."""
    import gc

    out = os.fdopen(os.dup(1), "wb")
    os.dup2(2, 1)  # anything a call prints goes where standard error goes, not into the answers
    inp = os.fdopen(0, "rb")
    threading.Thread(target=_watch_parent, args=(os.getppid(),), daemon=True).start()

    def exactly(n: int) -> bytearray:
        buf = bytearray(n)
        view, got = memoryview(buf), 0
        while got < n:
            k = inp.readinto(view[got:])
            if not k:
                raise EOFError
            got += k
        return buf

    while True:
        try:
            call = _read_message(exactly)
        except EOFError:
            return  # the parent closed the pipe (or ended)
        except Exception as exc:  # noqa: BLE001  # e.g. a kind defined in the parent's script
            _Message(("unreadable", f"{type(exc).__name__}: {exc}")).write(out)
            continue
        _Message(("received", None)).write(out)
        _answer(out, *call)
        del call
        gc.collect()
        release_freed_memory()  # what the call freed goes back to the system while the helper waits


def _answer(out: Any, fn: Callable[..., Any], args: Any, kwargs: Any, budget: int) -> None:  # pragma: no cover
    import traceback

    set_memory_budget(budget)
    with warnings.catch_warnings(record=True) as caught:
        try:
            reply: tuple[Any, ...] = ("ok", fn(*args, **kwargs))
        except Exception as exc:  # noqa: BLE001  # handed to the caller, who raises it
            exc.add_note("in isocsg's helper process:\n" + "".join(traceback.format_tb(exc.__traceback__)))
            reply = ("error", exc)
    shown = [(str(w.message), w.category, w.filename, w.lineno) for w in caught]
    try:
        message = _Message((*reply, shown))
    except Exception as exc:  # noqa: BLE001  # an exception that does not pickle: its text
        message = _Message(("error", RuntimeError(f"{reply[1]!r} ({exc})"), shown))
    del reply
    message.write(out)


def _watch_parent(parent: int) -> None:  # pragma: no cover - runs in the helper process
    import time

    while os.getppid() == parent:
        time.sleep(0.5)
    os._exit(0)

