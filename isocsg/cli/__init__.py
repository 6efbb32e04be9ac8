"""The ``isocsg`` command line.

Each sub-command lives in its own module with a ``register(subparsers)``
function; :func:`main` wires them together. Errors of isocsg (and bad
arguments) end the program with exit code 2 and a one-line message.
"""

from __future__ import annotations

import importlib
import importlib.util
import sys
from collections.abc import Sequence

from .. import __version__
from ..errors import IsocsgError
from . import demo, render, warmup
from ._common import ArgumentParser

__all__ = ["main", "build_parser"]

# Sub-commands provided by optional modules of this package, registered when present.
_OPTIONAL_COMMANDS = ("illuminance",)


def build_parser() -> ArgumentParser:
    """The top-level parser with every available sub-command."""
    parser = ArgumentParser(
        prog="isocsg",
        description="Isoluminance-contour rendering of CSG solids and soft shadows from area light sources.",
    )
    parser.add_argument("--version", action="version", version=f"isocsg {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", title="commands")
    render.register(sub)
    demo.register(sub)
    warmup.register(sub)
    for name in _OPTIONAL_COMMANDS:
        if importlib.util.find_spec(f"{__name__}.{name}") is not None:
            importlib.import_module(f"{__name__}.{name}").register(sub)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit code (0 success, 2 error).

    Examples
    --------
    >>> main(["render", "--help"])  # doctest: +ELLIPSIS
    usage: isocsg render ...
    0
    """
    parser = build_parser()
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
