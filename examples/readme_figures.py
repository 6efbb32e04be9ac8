"""The figures of the top-level README, drawn by isocsg itself.

Writes ``demo.png`` (the built-in demo scene), ``iso_primitives.png`` (every
primitive with 10 contours) and ``iso_csg_contours.png`` (a CSG part with 4
and with 32 contours).

Run ``python examples/readme_figures.py`` from the repository root to refresh
``docs/images/``.
"""

from __future__ import annotations

import dataclasses
import sys
from pathlib import Path

import numpy as np

from isocsg import (
    Box,
    Camera,
    Cone,
    ConvexPolyhedron,
    Cylinder,
    PointLight,
    Scene,
    Sphere,
    Truncus,
    builtin_scene,
    render,
    save_png,
)

#: The README's image folder.
DEFAULT_OUTPUT = Path(__file__).resolve().parent.parent / "docs" / "images"


def tile(images: list[np.ndarray], columns: int, gap: int = 4) -> np.ndarray:
    """Lay equally sized float images out on a grid, background (NaN) between them."""
    h, w = images[0].shape
    rows = -(-len(images) // columns)
    sheet = np.full((rows * h + (rows - 1) * gap, columns * w + (columns - 1) * gap), np.nan, dtype=np.float32)
    for k, img in enumerate(images):
        r, c = divmod(k, columns)
        sheet[r * (h + gap) : r * (h + gap) + h, c * (w + gap) : c * (w + gap) + w] = img
    return sheet


def primitives_sheet() -> np.ndarray:
    """Eight primitives, one tile each."""
    solids = [
        Sphere((0, 0, 0), 1.0),
        Cylinder((0, 0, 0), (0, 0, 1.6), 0.8),
        Cone((0, 0, 0), (0, 0, -1.6), 0.9),
        Truncus((0, 0, 0), (0, 0, 1.4), 0.5, 0.9),
        Cylinder((0, 0, 0), (0.2, 0.3, 0.25), 1.0),
        Truncus((0, 0, 0), (1.6, 1.2, 1.4), 0.18, 0.18),
        Box((0, 0, 0), (1.4, 1.0, 1.2)),
        ConvexPolyhedron([(1.1, 0, 0), (-1.1, 0, 0), (0, 1.1, 0), (0, -1.1, 0), (0, 0, 1.1), (0, 0, -1.1)]),
    ]
    camera = Camera((3.2, -4.2, 2.6), (0, 0, 0), fov=38, width=140, height=120)
    light = PointLight((4.0, -2.0, 6.0))
    return tile([render(Scene(camera, [light], [s]), contours=10).image for s in solids], columns=4)


def run(output_dir: str | Path | None = None) -> list[Path]:
    """Write the README figures; returns the paths written."""
    out = Path(output_dir) if output_dir is not None else DEFAULT_OUTPUT
    out.mkdir(parents=True, exist_ok=True)
    paths = []

    demo = builtin_scene("demo")
    demo = dataclasses.replace(demo, camera=demo.camera.with_size(400, 300))
    paths.append(out / "demo.png")
    save_png(paths[-1], render(demo).image)

    paths.append(out / "iso_primitives.png")
    save_png(paths[-1], primitives_sheet())

    part = builtin_scene("demo").objects[0]
    camera = Camera((6.0, -8.0, 5.5), (0, 0, 0.4), fov=34, width=240, height=180)
    scene = Scene(camera, [PointLight((6.0, -4.0, 9.0))], [part])
    paths.append(out / "iso_csg_contours.png")
    save_png(paths[-1], tile([render(scene, contours=n).image for n in (4, 32)], columns=2))

    return paths


if __name__ == "__main__":
    for p in run(sys.argv[1] if len(sys.argv) > 1 else None):
        print(p)
