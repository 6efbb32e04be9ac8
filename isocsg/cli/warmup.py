"""``isocsg warmup``: compile isocsg's kernels ahead of the first real call."""

from __future__ import annotations

import argparse
import time
from dataclasses import replace
from typing import Any

from . import COMMANDS

__all__ = ["register", "run"]

DESCRIPTION = """\
Compile isocsg's kernels (numba, cached on disk next to the package) for every
kind of render: a CSG image per pixel, later views through its clipped surface,
and soft shadows. The listed kernels are compiled on one process per core (about
45 s of CPU time in all), then the built-in scenes are rendered at a tiny size
to compile anything else they use. Without it, the first render of each kind
compiles its kernels (the command line says so). Later runs find the cache and
take a few seconds.
"""


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add the ``warmup`` sub-command."""
    p = subparsers.add_parser("warmup", help=COMMANDS["warmup"], description=DESCRIPTION)
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    """Compile the listed kernels, render the built-in scenes at a tiny size; prints what it did and how
    long it took."""
    from ..kernels import PATHS, compile_kernels
    from ..rendering import Renderer
    from ..scene.io import builtin_scene_path, load_scene
    from ..shadows.halftone import render_halftone

    start = time.perf_counter()
    print("isocsg warmup: compiling kernels (once per install; later runs read the on-disk cache)", flush=True)

    def say(kernels: int, processes: int, seconds: float) -> None:
        about = max(1, round(seconds))
        print(f"isocsg warmup: {kernels} kernels on {processes} processes (about {about} s on idle cores)",
              flush=True)

    compile_kernels(PATHS, on_start=say)
    scene = load_scene(builtin_scene_path("demo"))
    small = replace(scene, camera=replace(scene.camera, width=48, height=36), render=replace(scene.render, contours=8))
    for csg in ("pixel", "surface"):
        Renderer(csg=csg).render(small)
    shadows = load_scene(builtin_scene_path("halftone"))
    render_halftone(replace(shadows, camera=replace(shadows.camera, width=24, height=18)))
    print(f"isocsg warmup: done in {time.perf_counter() - start:.1f} s")
    return 0
