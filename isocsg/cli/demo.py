"""``isocsg demo``: render a built-in scene."""

from __future__ import annotations

import argparse
from typing import Any

from . import COMMANDS
from ._common import (
    add_common_render_options,
    apply_overrides,
    check_outputs,
    progress_bar,
    render_scene,
    write_outputs,
)

__all__ = ["register", "run"]

DESCRIPTION = """\
Render a built-in scene and print where the image went: by default a CSG part
(a plate with a boss, a through hole and pockets) shaded with isoluminance
contours; with --halftone, blocks under a square area light with soft shadows.
"""


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add the ``demo`` sub-command."""
    p = subparsers.add_parser("demo", help=COMMANDS["demo"], description=DESCRIPTION)
    p.add_argument("-o", "--output", metavar="OUT.png",
                   help="PNG file to write (default: isocsg-demo.png or isocsg-halftone.png)")
    p.add_argument("--halftone", action="store_true", help="the soft-shadow scene instead of the CSG part")
    p.add_argument("--print-scene", action="store_true", help="print the scene file's path and exit")
    add_common_render_options(p)
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    """Render the chosen built-in scene; prints the path of the image."""
    from ..scene.io import (  # here: ``isocsg demo --help`` needs none of it
        builtin_scene_path,
        load_scene,
    )

    name = "halftone" if args.halftone else "demo"
    source = builtin_scene_path(name)
    if args.print_scene:
        print(source)
        return 0
    output = args.output or f"isocsg-{name}.png"
    check_outputs(output)
    scene = apply_overrides(load_scene(source), size=args.size, contours=args.contours)
    with progress_bar(f"render {scene.render.mode}", enabled=not args.no_progress) as progress:
        result = render_scene(scene, progress=progress)
    (path,) = write_outputs(result, output)
    w, h = scene.camera.width, scene.camera.height
    print(f"wrote {path.resolve()} ({w}x{h} pixels, scene {source})")
    return 0
