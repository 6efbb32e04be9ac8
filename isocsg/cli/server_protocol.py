"""What the command line and its server agree on: where the socket is, which installation it
serves, and the messages between them.

The socket of a server lives in a per-user directory (``$ISOCSG_RUNTIME_DIR``, else
``$XDG_RUNTIME_DIR/isocsg``, else ``/tmp/isocsg-<uid>``), mode 0700 and owned by the user
(another owner or wider permissions disable the server). Its name is a digest of the
installation (:func:`fingerprint`: the interpreter, isocsg's path and version, the size and
modification time of each of isocsg's files) and of the environment variables read when modules
load (:data:`KEYED_PREFIXES`): an edited or reinstalled isocsg, or another ``ISOCSG_JIT``, finds
no server of its own and never reaches a stale one.

Messages are ``marshal``-ed values (dicts of str, int, list) after a 4-byte length; file
descriptors travel with the first message's length (``SCM_RIGHTS``). This module imports no
numpy: the client's start is the point of the server.
"""

from __future__ import annotations

import marshal
import os
import stat
import sys
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    import socket

__all__ = [
    "SERVED", "KEYED_NAMES", "KEYED_PREFIXES", "PROTOCOL", "MAX_MESSAGE", "enabled", "fingerprint", "digest",
    "runtime_dir", "socket_path", "send_message", "recv_message", "ProtocolError",
]

#: The commands worth a warm process (they import numpy and render); the others run in-process.
SERVED = ("render", "demo", "illuminance")
#: The protocol's version (a request of another version is refused, the client runs in-process).
PROTOCOL = 1
#: Largest message accepted (an environment of a few hundred variables is some kilobytes).
MAX_MESSAGE = 16 << 20
#: Environment variables whose values the modules read once (numba's and BLAS's thread counts,
#: ``ISOCSG_JIT``, the locale of the standard streams, temporary directory, search paths):
#: a server serves only clients with the same values.
KEYED_PREFIXES = ("ISOCSG_", "NUMBA_", "PYTHON", "OMP_", "OPENBLAS_", "MKL_", "GOTO", "VECLIB", "BLIS_",
                  "NUMEXPR_", "VTK_", "PYVISTA", "MPL", "LC_")
KEYED_NAMES = ("LANG", "LANGUAGE", "TMPDIR", "TEMP", "TMP", "HOME", "PATH", "DISPLAY", "XDG_CACHE_HOME",
               "XDG_CONFIG_HOME")
#: Variables of the server itself, not of what it runs.
_UNKEYED = ("ISOCSG_SERVER", "ISOCSG_SERVER_IDLE", "ISOCSG_RUNTIME_DIR")
#: File names of isocsg's that hold code or data its commands read.
_SUFFIXES = (".py", ".so", ".pyd", ".json", ".toml", ".html", ".scad", ".csg")


class ProtocolError(OSError):
    """A message that is not one of the protocol's (cut short, too long, not a dict)."""


def enabled(environ: dict[str, str] | os._Environ[str] | None = None) -> bool:
    """Whether the server may be used here: a POSIX system with ``fork`` and UNIX sockets that
    pass file descriptors, and ``ISOCSG_SERVER`` not ``0`` (nor ``off``, ``no``, ``false``)."""
    env = os.environ if environ is None else environ
    if env.get("ISOCSG_SERVER", "1").strip().lower() in ("0", "off", "no", "false"):
        return False
    import socket  # here: a disabled server costs no import

    return hasattr(os, "fork") and hasattr(socket, "AF_UNIX") and hasattr(socket, "send_fds")


def fingerprint(environ: dict[str, str] | os._Environ[str] | None = None) -> list[Any]:
    """The installation and environment a server was loaded from, as plain values.

    The interpreter (path and version), isocsg's directory and version, each of its files'
    relative path, size and modification time (``.py``, compiled extensions, data; numba's
    caches are left out: numba checks them against their source file's time itself), and the
    keyed environment variables. About 2 ms for isocsg's 220 files.
    """
    from .. import __version__

    env = os.environ if environ is None else environ
    package = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))
    files: list[tuple[str, int, int]] = []
    stack = [package]
    while stack:
        folder = stack.pop()
        with os.scandir(folder) as entries:
            for entry in entries:
                if entry.is_dir(follow_symlinks=False):
                    if entry.name != "__pycache__":
                        stack.append(entry.path)
                elif entry.name.endswith(_SUFFIXES):
                    st = entry.stat()
                    files.append((os.path.relpath(entry.path, package), st.st_mtime_ns, st.st_size))
    files.sort()
    keyed = sorted((k, v) for k, v in env.items()
                   if (k.startswith(KEYED_PREFIXES) or k in KEYED_NAMES) and k not in _UNKEYED)
    return [PROTOCOL, sys.executable, sys.version, package, __version__, files, keyed]


def digest(print_: list[Any]) -> str:
    """A short, stable name of a :func:`fingerprint` (hex)."""
    try:
        from _blake2 import blake2b  # what hashlib's blake2b is, without loading OpenSSL (5 ms)
    except ImportError:  # pragma: no cover - an interpreter without it
        from hashlib import blake2b

    # repr, not marshal: marshal marks objects referenced elsewhere in the process (FLAG_REF), so
    # equal values can give other bytes in two processes (or in one, before and after a warm-up)
    return blake2b(repr(print_).encode("utf-8", "surrogatepass"), digest_size=12).hexdigest()


def runtime_dir(environ: dict[str, str] | os._Environ[str] | None = None, *, create: bool = True) -> str | None:
    """The directory of this user's server sockets, made (mode 0700) if missing; None if it is not
    a directory of this user's that others cannot enter, or cannot be made. (Paths are strings
    here: the client does without pathlib's import.)"""
    env = os.environ if environ is None else environ
    if env.get("ISOCSG_RUNTIME_DIR"):
        path = env["ISOCSG_RUNTIME_DIR"]
    elif env.get("XDG_RUNTIME_DIR"):
        path = os.path.join(env["XDG_RUNTIME_DIR"], "isocsg")
    else:
        path = f"/tmp/isocsg-{os.getuid()}"
    try:
        if create:
            os.makedirs(path, mode=0o700, exist_ok=True)
        st = os.lstat(path)
    except OSError:
        return None
    if not stat.S_ISDIR(st.st_mode) or st.st_uid != os.getuid() or st.st_mode & 0o077:
        return None
    return path


def socket_path(folder: str, name: str) -> str:
    """The socket of the server named ``name`` (a :func:`digest`) in ``folder``."""
    return os.path.join(folder, f"{name}.sock")


def send_message(sock: socket.socket, value: dict[str, Any], fds: list[int] | tuple[int, ...] = ()) -> None:
    """Send one message (and file descriptors with its first bytes)."""
    import socket

    payload = marshal.dumps(value)
    head = len(payload).to_bytes(4, "big")
    if fds:
        socket.send_fds(sock, [head], list(fds))
        sock.sendall(payload)
    else:
        sock.sendall(head + payload)


def _recv_exactly(sock: socket.socket, n: int, got: bytes = b"") -> bytes:
    chunks = [got]
    have = len(got)
    while have < n:
        chunk = sock.recv(min(n - have, 1 << 20))
        if not chunk:
            raise ProtocolError("connection closed in the middle of a message")
        chunks.append(chunk)
        have += len(chunk)
    return b"".join(chunks)


def recv_message(sock: socket.socket, *, maxfds: int = 0) -> tuple[dict[str, Any] | None, list[int]]:
    """The next message and the file descriptors that came with it; ``(None, [])`` if the peer
    closed the connection before a message began.

    Raises
    ------
    ProtocolError
        A message cut short, too long, or not a dict.
    """
    import socket

    fds: list[int] = []
    if maxfds:
        head, fds, _flags, _addr = socket.recv_fds(sock, 4, maxfds)
    else:
        head = sock.recv(4)
    if not head:
        for fd in fds:
            os.close(fd)
        return None, []
    try:
        head = _recv_exactly(sock, 4, head)
        size = int.from_bytes(head, "big")
        if size > MAX_MESSAGE:
            raise ProtocolError(f"message of {size} bytes (at most {MAX_MESSAGE})")
        value = marshal.loads(_recv_exactly(sock, size))
        if not isinstance(value, dict):
            raise ProtocolError(f"message is a {type(value).__name__}, not a dict")
    except BaseException:
        for fd in fds:
            os.close(fd)
        raise
    return value, fds
