"""``isocsg warmup``: compile isocsg's kernels ahead of the first real call."""

from __future__ import annotations

import argparse
import time
from dataclasses import replace
from typing import Any

from ..scene.io import builtin_scene_path, load_scene

__all__ = ["register", "run"]

DESCRIPTION = """\
Compile isocsg's compiled kernels (numba, cached on disk next to the package)
by rendering the built-in scenes at a tiny size: the CSG part per pixel and
through its clipped surface, and the soft-shadow scene. A new install compiles
them on its first render (about 15 s of CPU time for the first CSG image, as
much again for the first soft-shadow image); run this once after installing so
that no later call waits. Later runs find the cache and take a few seconds.
"""


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add the ``warmup`` sub-command."""
    p = subparsers.add_parser("warmup", help="compile the kernels once after installing", description=DESCRIPTION)
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    """Render the built-in scenes at a tiny size; prints what it did and how long it took."""
    from ..render import Renderer
    from ..shadows.halftone import render_halftone

    start = time.perf_counter()
    print("isocsg warmup: compiling kernels (once per install; later runs read the on-disk cache)", flush=True)
    scene = load_scene(builtin_scene_path("demo"))
    small = replace(scene, camera=replace(scene.camera, width=48, height=36), render=replace(scene.render, contours=8))
    for csg in ("pixel", "surface"):
        Renderer(csg=csg).render(small)
    shadows = load_scene(builtin_scene_path("halftone"))
    render_halftone(replace(shadows, camera=replace(shadows.camera, width=24, height=18)))
    print(f"isocsg warmup: done in {time.perf_counter() - start:.1f} s")
    return 0
