"""The command line's server: one warm process, a forked child per command.

A new process pays for Python's start, numpy's import (OpenBLAS) and isocsg's modules before
it draws anything: several times what OpenSCAD's preview costs in all, for a small model. The
server pays once. Started detached by the first command that found none
(:func:`isocsg.cli.server_client.spawn_server`), it imports what the rendering commands use,
draws a few small models as ``isocsg render`` does (with compiled kernels, and the built-in
scenes too, when numba's disk cache holds every listed kernel; else as a new process draws them,
compiling nothing), waits for its pools' threads to end
(:func:`isocsg._workers.quiesce`: a child has none of its parent's threads), and listens on its
socket (:mod:`isocsg.cli.server_protocol`).

For each command it forks a child, which takes the client's standard streams (file
descriptors passed over the socket: a terminal stays a terminal), working directory, umask,
environment, ``sys.path`` and arguments, runs :func:`isocsg.cli.main` as the client would have,
sends the exit code and ends. Every command starts from the same warm state, and commands run
side by side. A child whose client goes away ends. The server reaps its children, and leaves
after ``ISOCSG_SERVER_IDLE`` seconds (default 600) without a command, when isocsg's files
change (checked every few seconds), and on ``SIGTERM`` (``isocsg server stop`` sends it to the
process that holds the server's lock file, whose pid the file holds).
"""

from __future__ import annotations

import contextlib
import io
import os
import select
import signal
import socket
import sys
import tempfile
import threading
import time
import traceback
from pathlib import Path
from typing import Any, NoReturn

from .server_protocol import PROTOCOL, digest, fingerprint, recv_message, send_message, socket_path

__all__ = ["IDLE_SECONDS", "CHECK_SECONDS", "serve"]

#: Seconds without a command after which the server leaves (``ISOCSG_SERVER_IDLE`` overrides).
IDLE_SECONDS = 600.0
#: Seconds between two checks that isocsg's files are still the ones the server loaded.
CHECK_SECONDS = 3.0
#: Longest wait in the loop (reaping children, idle and file checks happen at least this often).
_POLL = 0.5
#: Seconds a client has to send its request, and a child waits for ``go``.
_REQUEST_TIMEOUT = 10.0
#: Models drawn at start, as ``isocsg render`` draws them (``isocsg/data/warm``, read without an
#: ``openscad`` run): the plain subset's primitives, and in OpenSCAD's ``.csg`` export a tree drawn
#: tile by tile (more than ``DENSE_MAX_LEAVES`` leaves) and one of each common 2D and extruded
#: shape, so that a command's child finds their modules (shapely, the 2D shapes, revolution and
#: extrusion) imported and their compiled kernels loaded.
_WARM_MODELS = ("cube.scad", "sphere.scad", "cylinder.scad", "difference.scad", "group.csg", "tiled.csg",
                "shapes.csg")

_stop = threading.Event()


def idle_seconds() -> float:
    """The idle timeout: ``ISOCSG_SERVER_IDLE`` seconds if it is a positive number, else :data:`IDLE_SECONDS`."""
    try:
        value = float(os.environ.get("ISOCSG_SERVER_IDLE", IDLE_SECONDS))
    except ValueError:
        return IDLE_SECONDS
    return value if value > 0 and value == value else IDLE_SECONDS


def serve(folder: str, name: str) -> int:
    """Run the server named ``name`` (the digest of this installation) in ``folder`` until it
    leaves; returns the process's exit code. Another server of the same name already holding
    the lock, or files changed since the client named it, end it at once."""
    import fcntl

    where = Path(folder)
    lock = os.open(str(where / f"{name}.lock"), os.O_RDWR | os.O_CREAT, 0o600)
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        print(f"isocsg server {name}: another server holds the lock; leaving", flush=True)
        return 0
    os.ftruncate(lock, 0)
    os.write(lock, str(os.getpid()).encode())  # whom `isocsg server stop` signals
    if digest(fingerprint()) != name:
        print(f"isocsg server {name}: isocsg's files or environment differ from the client's; leaving", flush=True)
        return 0
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGHUP, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, _leave_now)  # while warming up: unwind (temporary files removed)
    loaded = fingerprint()
    start = time.perf_counter()
    print(f"isocsg server {name}: pid {os.getpid()}, warming up", flush=True)
    compiled = _warm_up()
    signal.signal(signal.SIGTERM, lambda _s, _f: _stop.set())
    now = fingerprint()
    if digest(now) != name:
        print(f"isocsg server {name}: isocsg's files or environment changed while warming up "
              f"({_difference(loaded, now)}); leaving", flush=True)
        return 0
    path = Path(socket_path(str(where), name))
    listener, inode = _listen(path)
    print(f"isocsg server {name}: pid {os.getpid()}, warm in {time.perf_counter() - start:.2f} s "
          f"({'compiled kernels' if compiled else 'kernels as Python'}), idle timeout {idle_seconds():g} s",
          flush=True)
    state = {"started": time.time(), "served": 0, "cpu": 0.0, "warm": time.perf_counter() - start, "lock": lock}
    try:
        _loop(listener, name, state)
    finally:
        _leave(listener, path, inode, lock)
    return 0


def _difference(before: list[Any], after: list[Any]) -> str:
    """What differs between two fingerprints, in a few words (for the log)."""
    if before[-2] != after[-2]:
        changed = sorted(set(map(tuple, before[-2])) ^ set(map(tuple, after[-2])))
        return f"files {changed[:4]}"
    if before[-1] != after[-1]:
        changed = sorted(set(map(tuple, before[-1])) ^ set(map(tuple, after[-1])))
        return f"environment {changed[:6]}"
    return "interpreter or version"


def _leave_now(_signum: int, _frame: Any) -> NoReturn:
    raise SystemExit(0)


def _listen(path: Path) -> tuple[socket.socket, int]:
    """A listening socket at ``path``, bound under a temporary name and renamed (no client ever
    finds a socket that does not accept yet)."""
    listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    temporary = path.with_name(f".{path.name}.{os.getpid()}")
    with contextlib.suppress(FileNotFoundError):
        temporary.unlink()
    listener.bind(str(temporary))
    listener.listen(64)
    os.replace(temporary, path)
    return listener, os.stat(path).st_ino


def _leave(listener: socket.socket, path: Path, inode: int, lock: int) -> None:
    """Remove the socket file (if it is still this server's: a newer one may have replaced it),
    release the lock."""
    import fcntl

    with contextlib.suppress(OSError):
        if os.stat(path).st_ino == inode:
            path.unlink()
    listener.close()
    fcntl.flock(lock, fcntl.LOCK_UN)
    os.close(lock)


def _warm_up() -> bool:
    """Import what the rendering commands use and draw small models, as the commands do (nothing
    printed); returns whether the kernels run compiled.

    With every listed kernel in numba's disk cache, the models are drawn with compiled kernels
    (loaded from the cache), and the built-in scenes too. Else they are drawn with Python and
    NumPy only (no numba, whatever they cost), and the time they spent is forgotten, so that a
    command's child starts as a new process does: compiling is left to the commands that need
    it (they say so) or to ``isocsg warmup``, and a server started in passing spends no minute
    of CPU.
    """
    from .. import _jit, _workers
    from . import demo, illuminance, render  # noqa: F401  # loaded once, for every child

    automatic = _jit.mode() == "auto"
    compiled = automatic and _kernels_cached()
    choice = _jit.use("numba") if compiled else _jit.use("python") if automatic else contextlib.nullcontext()
    sink = io.StringIO()
    with choice, tempfile.TemporaryDirectory() as tmp, contextlib.redirect_stdout(sink), \
            contextlib.redirect_stderr(sink):
        _draw(Path(tmp), compiled)
    if automatic and not compiled:
        _jit.forget_spent()
    _workers.quiesce()
    return _jit.engaged()


def _kernels_cached() -> bool:
    """Whether numba's disk cache holds every listed kernel; asked in a forked child, since
    reading the cache makes numba's dispatchers, after which every kernel of the process would
    run compiled (compiling what the cache lacks)."""
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:
        try:
            os.close(read)
            from ..kernels import PATHS, missing_kernels

            os.write(write, b"1" if not missing_kernels(PATHS) else b"0")
        finally:
            os._exit(0)
    os.close(write)
    with os.fdopen(read, "rb") as answer:
        cached = answer.read(1) == b"1"
    os.waitpid(pid, 0)
    return cached


def _draw(tmp: Path, compiled: bool) -> None:
    from importlib import resources

    from . import main

    for file in _WARM_MODELS:
        (tmp / file).write_bytes(resources.files("isocsg").joinpath("data", "warm", file).read_bytes())
        main(["render", str(tmp / file), "-o", str(tmp / "out.png"), "--no-progress"])
    if compiled:
        main(["demo", "--size", "48x36", "--contours", "8", "-o", str(tmp / "demo.png"), "--no-progress"])
        main(["demo", "--halftone", "--size", "24x18", "-o", str(tmp / "halftone.png"), "--no-progress"])
    import subprocess  # noqa: F401  # what a .scad file that is not plain needs (openscad's run)

    from ..openscad import evaluate, read_openscad  # noqa: F401  # evaluate: .scad files read without openscad


def _loop(listener: socket.socket, name: str, state: dict[str, Any]) -> None:
    children: set[int] = set()
    idle = idle_seconds()
    last = checked = time.monotonic()
    while not _stop.is_set():
        ready, _, _ = select.select([listener], [], [], _POLL)
        _reap(children, state)
        now = time.monotonic()
        if ready:
            _accept(listener, name, state, children)
            last = now
        if children:
            last = now
        if now - last > idle:
            return
        if now - checked > CHECK_SECONDS:
            checked = now
            if digest(fingerprint()) != name:
                return


def _reap(children: set[int], state: dict[str, Any]) -> None:
    """Collect the children that ended; their CPU time is added to ``state["cpu"]``."""
    for pid in list(children):
        try:
            done, _, usage = os.wait4(pid, os.WNOHANG)
        except ChildProcessError:
            done, usage = pid, None
        if done:
            children.discard(pid)
            if usage is not None:
                state["cpu"] += usage.ru_utime + usage.ru_stime


def _accept(listener: socket.socket, name: str, state: dict[str, Any], children: set[int]) -> None:
    try:
        conn, _ = listener.accept()
    except OSError:
        return
    fds: list[int] = []
    with conn:
        try:
            conn.settimeout(_REQUEST_TIMEOUT)
            request, fds = recv_message(conn, maxfds=4)
            op = request.get("op") if request else None
            if op == "status":
                send_message(conn, {"pid": os.getpid(), "name": name, "started": state["started"],
                                    "served": state["served"], "running": len(children),
                                    "idle": idle_seconds(), "warm": state["warm"], "cpu": state["cpu"]})
            elif (op == "run" and request is not None and request.get("protocol") == PROTOCOL
                  and request.get("name") == name and len(fds) == 4):
                sys.stdout.flush()
                sys.stderr.flush()
                pid = os.fork()
                if pid == 0:
                    _child(conn, request, fds, listener, state["lock"])
                children.add(pid)
                state["served"] += 1
            else:
                send_message(conn, {"refused": f"not a request of protocol {PROTOCOL} for {name}"})
        except (OSError, ValueError, EOFError, TypeError):  # a client that left or spoke out of turn
            pass
        finally:
            for fd in fds:
                os.close(fd)


def _child(conn: socket.socket, request: dict[str, Any], fds: list[int], listener: socket.socket,
           lock: int) -> NoReturn:
    """The forked child: wait for ``go``, take the client's place, run the command, send its exit code."""
    try:
        listener.close()
        os.close(lock)
        signal.signal(signal.SIGINT, signal.default_int_handler)
        for s in (signal.SIGTERM, signal.SIGHUP, signal.SIGCHLD):
            signal.signal(s, signal.SIG_DFL)
        send_message(conn, {"pid": os.getpid()})
        go, _ = recv_message(conn)
        if not go or go.get("op") != "go":
            os._exit(0)
        conn.settimeout(None)
        threading.Thread(target=_exit_when_closed, args=(conn,), daemon=True).start()
        _take_over(request, fds)
        code = _run([str(a) for a in request["argv"][1:]])
        send_message(conn, {"exit": code})
    except BaseException:  # noqa: BLE001  # nothing may escape into the server's loop
        with contextlib.suppress(BaseException):
            traceback.print_exc()
            sys.stderr.flush()
    finally:
        os._exit(0)


def _exit_when_closed(conn: socket.socket) -> None:
    """End the child when its client goes away (the client sends nothing after ``go``)."""
    try:
        while conn.recv(4096):
            pass
    except OSError:
        pass
    os._exit(1)


def _take_over(request: dict[str, Any], fds: list[int]) -> None:
    """The client's directory, umask, environment, paths, arguments and standard streams."""
    os.fchdir(fds[3])
    os.umask(int(request["umask"]))
    os.environ.clear()
    os.environ.update({str(k): str(v) for k, v in request["env"].items()})
    sys.path[:] = [str(p) for p in request["path"]]
    sys.argv = [str(a) for a in request["argv"]]
    for target, fd in enumerate(fds[:3]):
        os.dup2(fd, target)
    for fd in fds:
        os.close(fd)
    fds.clear()
    for fd, name in enumerate(("stdin", "stdout", "stderr")):
        stream = _stream(fd, getattr(sys, f"__{name}__"), write=fd > 0)
        setattr(sys, name, stream)
        setattr(sys, f"__{name}__", stream)


def _stream(fd: int, template: Any, *, write: bool) -> io.TextIOWrapper:
    """A standard stream on ``fd`` as Python makes one at start: the template's encoding and
    errors, standard output line-buffered on a terminal, standard error always."""
    raw = open(fd, "wb" if write else "rb", closefd=False)  # noqa: SIM115  # the stream's, not closed here
    return io.TextIOWrapper(
        raw, encoding=getattr(template, "encoding", None) or "utf-8",
        errors=getattr(template, "errors", None) or "strict", newline="\n",
        line_buffering=write and (fd == 2 or os.isatty(fd)),
        write_through=bool(getattr(template, "write_through", False)),
    )


def _run(argv: list[str]) -> int:
    """``main(argv)``'s exit code, as the interpreter would end with it (uncaught: traceback, 1)."""
    from . import main

    try:
        code: Any = main(argv)
    except SystemExit as exc:
        code = exc.code
        if code is not None and not isinstance(code, int):
            print(code, file=sys.stderr)
            code = 1
    except BaseException:  # noqa: BLE001  # as the interpreter reports it
        traceback.print_exc()
        code = 130 if isinstance(sys.exc_info()[1], KeyboardInterrupt) else 1
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(OSError, ValueError):
            stream.flush()
    return int(code or 0)
