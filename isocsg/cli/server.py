"""``isocsg server status|start|stop``: the warm process that runs the rendering commands."""

from __future__ import annotations

import argparse
import time
from pathlib import Path
from typing import Any

from ..errors import IsocsgError
from . import COMMANDS

__all__ = ["register", "run", "stop_servers", "START_TIMEOUT", "STOP_TIMEOUT"]

#: Seconds ``isocsg server start`` waits for a new server to answer.
START_TIMEOUT = 300.0
#: Seconds ``isocsg server stop`` waits for the servers to leave.
STOP_TIMEOUT = 10.0

DESCRIPTION = """\
The command line keeps a server process with isocsg loaded, so that render, demo and
illuminance start in a few hundredths of a second instead of a few tenths: each command is run
by a child forked from the warm server, with the command's own terminal, directory and
environment. The first command that finds none starts one (and runs itself as before); it
leaves after ISOCSG_SERVER_IDLE seconds without a command (default 600), and when isocsg's files
change. ISOCSG_SERVER=0 keeps every command in its own process. Linux and other POSIX systems.

  status  the servers of this user (each installation and environment has its own)
  start   start this installation's server and wait until it is warm
  stop    stop every server of this user
"""


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add the ``server`` sub-command."""
    p = subparsers.add_parser("server", help=COMMANDS["server"], description=DESCRIPTION,
                              formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("action", choices=("status", "start", "stop"))
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    """Report on, start or stop the servers; prints one line per server."""
    from .server_protocol import runtime_dir

    where = runtime_dir()
    if where is None:
        raise IsocsgError("no usable runtime directory (ISOCSG_RUNTIME_DIR, XDG_RUNTIME_DIR or /tmp/isocsg-<uid>: "
                          "a directory of this user's, mode 0700)")
    folder = Path(where)
    if args.action == "start":
        return _start(folder)
    if args.action == "stop":
        return stop_servers(folder)
    found = 0
    for sock in sorted(folder.glob("*.sock")):
        reply = _ask(sock, "status")
        if reply is not None:
            found += 1
            print(_describe(sock.stem, reply))
    if not found:
        print(f"no server running (in {folder})")
    return 0


def _holder(lock: Path) -> int | None:
    """The pid of the server holding ``lock`` (one warming up too), None if none holds it."""
    import fcntl
    import os

    try:
        fd = os.open(str(lock), os.O_RDONLY)
    except OSError:
        return None
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_SH | fcntl.LOCK_NB)
        except OSError:
            text = os.read(fd, 32).decode("ascii", "replace").strip()
            return int(text) if text.isdigit() else None
        fcntl.flock(fd, fcntl.LOCK_UN)
        return None
    finally:
        os.close(fd)


def stop_servers(folder: Path) -> int:
    """``SIGTERM`` to every server of this user, then wait (up to :data:`STOP_TIMEOUT` s) until each has left."""
    import os
    import signal

    stopping = []
    for lock in sorted(folder.glob("*.lock")):
        pid = _holder(lock)
        if pid is None:
            continue
        try:
            os.kill(pid, signal.SIGTERM)
        except OSError:
            continue
        stopping.append((lock, pid))
    deadline = time.monotonic() + STOP_TIMEOUT
    for lock, pid in stopping:
        while _holder(lock) is not None and time.monotonic() < deadline:
            time.sleep(0.02)
        left = _holder(lock) is None
        print(f"{'stopped' if left else 'still stopping'} server {lock.stem} (pid {pid})")
    if not stopping:
        print(f"no server running (in {folder})")
    return 0


def _ask(sock: Path, op: str) -> dict[str, Any] | None:
    """The server's answer to ``op`` (status), None if none answers."""
    from .server_client import connect
    from .server_protocol import recv_message, send_message

    conn = connect(sock, timeout=5.0)
    if conn is None:
        return None
    with conn:
        try:
            send_message(conn, {"op": op})
            reply, _ = recv_message(conn)
        except (OSError, ValueError, EOFError, TypeError):
            return None
    return reply


def _describe(name: str, reply: dict[str, Any]) -> str:
    from .server_protocol import digest, enabled, fingerprint

    ours = " (this installation)" if enabled() and digest(fingerprint()) == name else ""
    up = time.time() - float(reply.get("started", time.time()))
    return (f"server {name}{ours}: pid {reply.get('pid')}, up {up:.0f} s, {reply.get('served')} commands served, "
            f"{reply.get('running')} running, {float(reply.get('cpu', 0)):.3f} s CPU in commands, "
            f"warm in {float(reply.get('warm', 0)):.2f} s, idle timeout {float(reply.get('idle', 0)):g} s")


def _start(folder: Path) -> int:
    from .server_client import spawn_server
    from .server_protocol import digest, enabled, fingerprint, socket_path

    if not enabled():
        raise IsocsgError("the server is disabled (ISOCSG_SERVER=0, or no fork and UNIX sockets here)")
    name = digest(fingerprint())
    sock = Path(socket_path(str(folder), name))
    reply = _ask(sock, "status")
    if reply is None:
        spawn_server(folder, name)
        deadline = time.monotonic() + START_TIMEOUT
        while reply is None and time.monotonic() < deadline:
            time.sleep(0.05)
            reply = _ask(sock, "status")
        if reply is None:
            raise IsocsgError(f"the server did not answer within {START_TIMEOUT:g} s (see {folder / name}.log)")
    print(_describe(name, reply))
    return 0
