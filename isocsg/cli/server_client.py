"""The command line's side of the server: a command run by a warm process, or here.

:func:`run_served` hands a command to this installation's server (see
:mod:`isocsg.cli.server_process`): the process's standard streams and working directory (as file
descriptors), its arguments, environment, umask and ``sys.path``. The server forks a child that
runs the command as :func:`isocsg.cli.main` would here and sends back its exit code. Two
phases keep a command from running twice: the child sends its pid and waits; the client answers
``go`` and is committed from then on. Anything that fails before (no server, a refused
connection, a server that died or a message out of protocol) returns None, the caller runs the
command in-process, and a detached server is started for the next commands
(:func:`spawn_server`). Signals the client receives while committed (Ctrl-C, ``SIGTERM``,
``SIGHUP``) are passed on to the child.
"""

from __future__ import annotations

import os
import signal
import socket
import sys
from collections.abc import Sequence
from typing import Any

from .server_protocol import (
    PROTOCOL,
    SERVED,
    ProtocolError,
    digest,
    enabled,
    fingerprint,
    recv_message,
    runtime_dir,
    send_message,
    socket_path,
)

__all__ = ["COMMIT_TIMEOUT", "run_served", "spawn_server", "connect", "server_paths"]

#: Seconds the client waits for the server's child to be ready before it runs the command itself.
COMMIT_TIMEOUT = 10.0
#: Signals passed on to the command's process.
FORWARDED = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)


def server_paths() -> tuple[str, str] | None:
    """This installation's runtime directory and server name, or None when the server is disabled
    or the directory unusable."""
    if not enabled():
        return None
    folder = runtime_dir()
    if folder is None:
        return None
    return folder, digest(fingerprint())


def connect(path: str | os.PathLike[str], timeout: float | None = COMMIT_TIMEOUT) -> socket.socket | None:
    """A connection to the server at ``path``, or None if none answers."""
    sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    sock.settimeout(timeout)
    try:
        sock.connect(str(path))
    except OSError:
        sock.close()
        return None
    return sock


def run_served(argv: Sequence[str]) -> int | None:
    """Run ``isocsg argv`` in this installation's server; its exit code, or None if the command
    was not run (no server, or it failed before the command began: then one is started)."""
    if not argv or next((a for a in argv if not a.startswith("-")), None) not in SERVED:
        return None
    where = server_paths()
    if where is None:
        return None
    folder, name = where
    sock = connect(socket_path(folder, name))
    if sock is None:
        spawn_server(folder, name)
        return None
    with sock:
        pid = _handshake(sock, argv, name)
        if pid is None:
            return None
        return _committed(sock, pid)


def _handshake(sock: socket.socket, argv: Sequence[str], name: str) -> int | None:
    """Send the request; the child's pid once it is ready, None if anything failed (nothing ran)."""
    request = {
        "op": "run", "protocol": PROTOCOL, "name": name, "argv": [sys.argv[0], *argv],
        "env": dict(os.environ), "umask": _umask(), "path": list(sys.path),
    }
    try:
        cwd = os.open(".", os.O_RDONLY)
    except OSError:
        return None
    try:
        send_message(sock, request, [0, 1, 2, cwd])
        reply, _ = recv_message(sock)
    except (OSError, ValueError, EOFError, TypeError):  # refused, closed, timed out, not marshal
        return None
    finally:
        os.close(cwd)
    if reply is None or not isinstance(reply.get("pid"), int):
        return None
    return int(reply["pid"])


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def _committed(sock: socket.socket, pid: int) -> int:
    """Say ``go``, pass signals on, and wait for the exit code."""
    received: list[int] = []

    def forward(signum: int, _frame: Any) -> None:
        received.append(signum)
        try:
            os.kill(pid, signum)
        except OSError:
            pass

    previous = {s: signal.signal(s, forward) for s in FORWARDED}
    try:
        sock.settimeout(None)
        send_message(sock, {"op": "go"})
        while True:
            try:
                reply, _ = recv_message(sock)
            except (ProtocolError, ValueError, EOFError, TypeError):
                reply = None
            if reply is None:
                break
            if "exit" in reply:
                return int(reply["exit"])
    except OSError:
        pass
    finally:
        for s, handler in previous.items():
            signal.signal(s, handler)
    # The child ended without an exit code: killed (by a signal passed on, or another).
    if received and received[-1] != signal.SIGINT:
        signal.signal(received[-1], signal.SIG_DFL)
        os.kill(os.getpid(), received[-1])
    print("isocsg: the command's process ended without an exit code (killed?)", file=sys.stderr)
    return 1


def spawn_server(folder: str | os.PathLike[str], name: str) -> None:
    """Start a detached server named ``name`` in ``folder``; returns at once.

    Double fork: the server is in a session of its own, not this process's child, with standard
    input from ``/dev/null``, its output in ``<name>.log`` and every other descriptor closed, so
    that nothing waiting on this process's pipes (``subprocess.run(capture_output=True)``, CI)
    waits for it. A server already starting holds the lock and the new one leaves at once.
    """
    package_parent = os.path.dirname(os.path.dirname(os.path.dirname(os.path.realpath(__file__))))
    code = (f"import sys; sys.path.insert(0, {package_parent!r}); "
            "from isocsg.cli.server_process import serve; sys.exit(serve(sys.argv[1], sys.argv[2]))")
    argv = [sys.executable, "-c", code, os.fspath(folder), name]
    try:
        sys.stdout.flush()
        sys.stderr.flush()
        pid = os.fork()
    except (OSError, ValueError):
        return
    if pid:
        try:
            os.waitpid(pid, 0)
        except OSError:
            pass
        return
    try:  # the first child: a new session, then the server is its child
        os.setsid()
        if os.fork():
            os._exit(0)
        null = os.open(os.devnull, os.O_RDWR)
        log = os.open(os.path.join(folder, f"{name}.log"), os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
        os.dup2(null, 0)
        os.dup2(log, 1)
        os.dup2(log, 2)
        os.closerange(3, _max_fd())
        os.chdir("/")
        os.execv(sys.executable, argv)
    finally:
        os._exit(127)


def _max_fd() -> int:
    try:
        return int(os.sysconf("SC_OPEN_MAX"))
    except (OSError, ValueError):
        return 1024
