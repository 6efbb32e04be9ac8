"""``isocsg view MODEL``: a live preview in the browser, re-rendered when the file is saved."""

from __future__ import annotations

import argparse
import sys
import time
from typing import Any

from . import COMMANDS

__all__ = ["register", "run"]

DESCRIPTION = """\
Show a model in a local web page and re-render it whenever its file is saved: an OpenSCAD model
(.scad through the openscad program, or .csg), a scene file (.toml or .json), or a Python script
that binds `scene`, `model` or `solid`. Drag to orbit, use the wheel to zoom, double click for the
first view. OpenSCAD nodes without an exact equivalent are left out and listed on the page.
Stop with Ctrl-C.
"""


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add the ``view`` sub-command."""
    p = subparsers.add_parser("view", help=COMMANDS["view"], description=DESCRIPTION)
    p.add_argument("model", metavar="MODEL", help="model file: .scad, .csg, .toml, .json or .py")
    p.add_argument("--port", type=int, default=0, help="local port (default: a free one)")
    p.add_argument("--no-browser", action="store_true", help="print the address without opening a browser")
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    """Serve until interrupted."""
    from ..preview import preview

    server = preview(args.model, port=args.port)
    print(f"isocsg view: {args.model} at {server.url} (Ctrl-C stops)", flush=True)
    if not args.no_browser:
        import webbrowser

        webbrowser.open(server.url)
    try:
        while True:
            time.sleep(3600)
    except KeyboardInterrupt:
        print("isocsg view: stopped", file=sys.stderr)
    finally:
        server.close()
    return 0
