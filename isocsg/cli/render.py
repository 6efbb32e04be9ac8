"""``isocsg render SCENE -o OUT.png``: render a scene file."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from ..errors import InvalidParameterError
from . import COMMANDS
from ._common import (
    add_common_render_options,
    apply_overrides,
    check_outputs,
    load_scene_argument,
    progress_bar,
    render_scene,
    write_outputs,
)

__all__ = ["register", "run"]

DESCRIPTION = """\
Render a scene file (.toml or .json) to a PNG image (and optionally .npy and .svg). The scene's render.mode
chooses the method: "isoluminance" (contour bands, point and directional lights)
or "halftone" (exact illuminance and soft shadows from area and polyhedron lights).
An output ending in .glb or .gltf writes the shaded bands as a 3D glTF model instead
(flat unlit colours, one per band; CSG objects as their Boolean result).
An OpenSCAD model (.csg, or .scad through the openscad program) is rendered with a camera that
frames it (512x512 unless --size) and one directional light.
"""

#: Output extensions that write a glTF model instead of an image.
GLTF_SUFFIXES = (".glb", ".gltf")
#: Model files rendered with a default camera and light.
OPENSCAD_SUFFIXES = (".scad", ".csg")


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add the ``render`` sub-command."""
    p = subparsers.add_parser("render", help=COMMANDS["render"], description=DESCRIPTION)
    p.add_argument(
        "scene", metavar="SCENE",
        help="scene file (.toml or .json), OpenSCAD model (.scad or .csg), or - to read a scene from standard input",
    )
    p.add_argument(
        "-o", "--output", required=True, metavar="OUT.png",
        help="PNG file to write; .glb or .gltf: the shaded bands as a glTF model",
    )
    p.add_argument("--npy", metavar="OUT.npy", help="also write the float32 image (NaN background) as .npy")
    p.add_argument(
        "--svg", metavar="OUT.svg",
        help="also write the visible bands as SVG polygons, back to front (isoluminance scenes of primitives)",
    )
    p.add_argument(
        "--skip-unsupported", action="store_true",
        help="OpenSCAD models: skip nodes without an exact equivalent (a hull of a sphere and a cube, SVG "
             "drawings, ...) and say how many",
    )
    p.add_argument(
        "--polygonal", action="store_true",
        help="OpenSCAD models: make a hull or minkowski without an exact form OpenSCAD's own polygonal solid "
             "(spheres, cylinders and circles at the model's $fn/$fa/$fs) instead of refusing it, and list them",
    )
    add_common_render_options(p)
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    """Load, render, write; prints the files written."""
    gltf = Path(args.output).suffix.lower() in GLTF_SUFFIXES
    if Path(args.output).suffix.lower() not in (".png", *GLTF_SUFFIXES):
        raise InvalidParameterError(f"output file {str(args.output)!r} must end in .png, .glb or .gltf")
    check_outputs(None if gltf else args.output, args.npy)
    if gltf and Path(args.output).is_dir():
        raise InvalidParameterError(f"output file {str(args.output)!r} is a directory")
    if args.svg is not None and not str(args.svg).lower().endswith(".svg"):
        raise InvalidParameterError(f"--svg must name a .svg file, got {args.svg!r}")
    if args.svg is not None and Path(args.svg).is_dir():
        raise InvalidParameterError(f"--svg {args.svg!r} is a directory")
    loaded = _load(args.scene, skip_unsupported=args.skip_unsupported, polygonal=args.polygonal)
    scene = apply_overrides(loaded, size=args.size, contours=args.contours)
    if gltf and scene.render.mode != "isoluminance":
        raise InvalidParameterError(
            f"{args.output}: glTF output needs render.mode = \"isoluminance\" (point or directional lights)"
        )
    if args.svg is not None:
        from ..kinds import (
            Primitive,  # here: ``isocsg render --help`` loads no geometry
        )

        if scene.render.mode != "isoluminance":
            raise InvalidParameterError("--svg needs render.mode = \"isoluminance\"")
        for k, obj in enumerate(scene.objects):
            if not isinstance(obj.shape, Primitive):
                raise InvalidParameterError(
                    f"--svg: objects[{k}] is a CSG tree; SVG "
                    "output takes single primitives only"
                )
    if gltf:
        from ..interop.gltf import save_gltf

        out = Path(args.output)
        out.parent.mkdir(parents=True, exist_ok=True)
        save_gltf(scene, out)
        print(f"wrote {out}")
    if not gltf or args.npy is not None:
        with progress_bar(f"render {scene.render.mode}", enabled=not args.no_progress) as progress:
            result = render_scene(scene, progress=progress)
        for path in write_outputs(result, None if gltf else args.output, args.npy, objects=scene.objects):
            print(f"wrote {path}")
    if args.svg is not None:
        from ..rendering.svg import save_scene_svg

        Path(args.svg).parent.mkdir(parents=True, exist_ok=True)
        save_scene_svg(args.svg, scene)
        print(f"wrote {args.svg}")
    return 0


def _load(path: str, *, skip_unsupported: bool = False, polygonal: bool = False) -> Any:
    """A scene file, or an OpenSCAD model in a framed scene."""
    if Path(path).suffix.lower() not in OPENSCAD_SUFFIXES:
        return load_scene_argument(path)
    from ..openscad.plain import read_plain_scad
    from ..scene.framing import framed_scene

    # a file that OpenSCAD's export would leave as it is needs no openscad run (the same model)
    model = read_plain_scad(path, skip_unsupported=skip_unsupported, polygonal=polygonal)
    if model is None:
        from ..openscad import read_openscad

        model = read_openscad(path, skip_unsupported=skip_unsupported, polygonal=polygonal)
    for line in model.polygonal:  # each node made OpenSCAD's polygonal solid, with its line and why
        print(f"isocsg render: polygonal {line}", file=sys.stderr)
    if model.skipped:
        counts = ", ".join(f"{n} {name}" for name, n in sorted(model.skipped.items()))
        skipped = sum(model.skipped.values())
        print(f"isocsg render: skipped {skipped} unsupported OpenSCAD node(s): {counts}", file=sys.stderr)
    for line in getattr(model, "left_out", ()):  # each node left out, with its line and why
        print(f"isocsg render: left out {line}", file=sys.stderr)
    from ..scene.model import SceneObject

    return framed_scene(SceneObject(model.solid, leaf_colors=model.leaf_colors))
