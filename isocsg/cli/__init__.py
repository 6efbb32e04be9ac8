"""The ``isocsg`` command line.

Each sub-command lives in its own module with a ``register(subparsers)``
function; :func:`main` wires them together, importing only the module of the
command it runs (``isocsg --help`` imports none), so a command loads only what
it uses. Errors of isocsg (and bad arguments) end the program with exit code 2
and a one-line message.

Run as a program (``main()`` without arguments: the console script, ``python -m isocsg``), the
commands that render go through a warm server process where there is one
(:mod:`isocsg.cli.server_client`, README "Start-up"); ``main(argv)`` always runs in this process.
"""

from __future__ import annotations

import functools
import importlib
import importlib.util
import sys
from collections.abc import Collection, Sequence
from typing import TYPE_CHECKING

from .. import __version__

if TYPE_CHECKING:
    from ._common import ArgumentParser

__all__ = ["COMMANDS", "build_parser", "main"]

#: Each sub-command (a module of this package of the same name) and its line in ``isocsg --help``.
COMMANDS = {
    "render": "render a scene file to PNG",
    "demo": "render a built-in demo scene",
    "warmup": "compile the kernels once after installing",
    "illuminance": "illuminance map with isolux lines",
    "view": "live preview of a model in the browser, re-rendered on save",
    "report": "lighting study report (HTML or PDF)",
    "server": "the warm process that runs render, demo and illuminance (status, start, stop)",
}


def build_parser(commands: Collection[str] | None = None) -> ArgumentParser:
    """The top-level parser.

    Parameters
    ----------
    commands : collection of str, optional
        The sub-commands whose modules are imported and whose arguments are
        parsed (default: all of :data:`COMMANDS`); the others are listed by
        ``--help`` only. Modules missing from an installation are left out.
    """
    from ._common import ArgumentParser  # here: a command the server runs needs no argparse here

    parser = ArgumentParser(
        prog="isocsg",
        description="Isoluminance-contour rendering of CSG solids and soft shadows from area light sources.",
    )
    parser.add_argument("--version", action="version", version=f"isocsg {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", title="commands")
    for name, help_line in COMMANDS.items():
        if importlib.util.find_spec(f"{__name__}.{name}") is None:
            continue
        if commands is None or name in commands:
            importlib.import_module(f"{__name__}.{name}").register(sub)
        else:
            sub.add_parser(name, help=help_line)
    return parser


@functools.cache
def _parser(command: str) -> ArgumentParser:
    """:func:`build_parser` for one sub-command, built once a process (the server's children
    inherit it: argparse's parsers are not changed by parsing)."""
    return build_parser([command])


def _command_named(argv: Sequence[str]) -> str | None:
    """The sub-command of a command line: its first word that is not an option (the top-level
    options take no values)."""
    return next((a for a in argv if not a.startswith("-")), None)


def _served(argv: Sequence[str]) -> int | None:
    """The exit code of the command run by the server; None if it has not run."""
    from .server_protocol import SERVED, enabled

    if _command_named(argv) not in SERVED or not enabled():
        return None
    from .server_client import run_served

    return run_served(argv)


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit code (0 success, 2 error).

    Without ``argv`` (the program: ``sys.argv``), ``render``, ``demo`` and ``illuminance`` run
    in the server's warm process when one answers, with this process's streams, directory and
    environment (the same output and exit code); else here, and a server is started for the
    next commands. ``ISOCSG_SERVER=0`` keeps every command in this process.

    Examples
    --------
    >>> main(["render", "--help"])  # doctest: +ELLIPSIS
    usage: isocsg render ...
    0
    """
    if argv is None:
        argv = sys.argv[1:]
        served = _served(argv)
        if served is not None:
            return served
    from ..errors import IsocsgError

    parser = _parser(_command_named(argv) or "")
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help, --version and usage errors
        return int(exc.code or 0) if not isinstance(exc.code, str) else 2
    if getattr(args, "func", None) is None:
        parser.print_help(sys.stderr)
        return 2
    try:
        return int(args.func(args) or 0)
    except IsocsgError as exc:
        print(f"isocsg {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except OSError as exc:
        where = f" {exc.filename}" if getattr(exc, "filename", None) else ""
        print(f"isocsg {args.command}: error:{where}: {exc.strerror or exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("isocsg: interrupted", file=sys.stderr)
        return 130
