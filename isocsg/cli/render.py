"""``isocsg render SCENE -o OUT.png``: render a scene file."""

from __future__ import annotations

import argparse
from typing import Any

from ..scene.io import load_scene
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
Render a scene file (.toml or .json) to a PNG image. The scene's render.mode
chooses the method: "isoluminance" (contour bands, point and directional lights)
or "halftone" (exact illuminance and soft shadows from area and polyhedron lights).
"""


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add the ``render`` sub-command."""
    p = subparsers.add_parser("render", help="render a scene file to PNG", description=DESCRIPTION)
    p.add_argument("scene", metavar="SCENE", help="scene file, .toml or .json")
    p.add_argument("-o", "--output", required=True, metavar="OUT.png", help="PNG file to write")
    p.add_argument("--npy", metavar="OUT.npy", help="also write the float32 image (NaN background) as .npy")
    add_common_render_options(p)
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    """Load, render, write; prints the files written."""
    check_outputs(args.output, args.npy)
    scene = apply_overrides(load_scene(args.scene), size=args.size, contours=args.contours)
    with progress_bar(f"render {scene.render.mode}", enabled=not args.no_progress) as progress:
        result = render_scene(scene, progress=progress)
    for path in write_outputs(result.image, args.output, args.npy):
        print(f"wrote {path}")
    return 0
