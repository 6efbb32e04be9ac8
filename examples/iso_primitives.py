"""Every primitive of isocsg, shaded with isoluminance contours.

Renders a sphere, a cylinder, a cone, a frustum, a disc, a rod, a box and a
convex polyhedron (an octahedron) under one point light, each in its own PNG,
plus a contact sheet of all of them.

Run ``python examples/iso_primitives.py`` (writes to ``out/examples``).
"""

from __future__ import annotations

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
    render,
    save_png,
)

SIZE = (160, 120)

PRIMITIVES = {
    "sphere": Sphere((0, 0, 0), 1.0),
    "cylinder": Cylinder((0, 0, 0), (0, 0, 1.6), 0.8),
    "cone": Cone((0, 0, 0), (0, 0, -1.6), 0.9),
    "frustum": Truncus((0, 0, 0), (0, 0, 1.4), 0.5, 0.9),
    "disc": Cylinder((0, 0, 0), (0.2, 0.3, 0.25), 1.0),
    "rod": Truncus((0, 0, 0), (1.6, 1.2, 1.4), 0.18, 0.18),
    "box": Box((0, 0, 0), (1.4, 1.0, 1.2)),
    "polyhedron": ConvexPolyhedron([(1.1, 0, 0), (-1.1, 0, 0), (0, 1.1, 0), (0, -1.1, 0), (0, 0, 1.1), (0, 0, -1.1)]),
}

#: Where ``run()`` writes when given no folder (``out/`` is git-ignored).
DEFAULT_OUTPUT = Path("out") / "examples"

def tile(images: list[np.ndarray], columns: int, gap: int = 4) -> np.ndarray:
    """Lay equally sized float images out on a grid, background (NaN) between them."""
    h, w = images[0].shape
    rows = -(-len(images) // columns)
    sheet = np.full((rows * h + (rows - 1) * gap, columns * w + (columns - 1) * gap), np.nan, dtype=np.float32)
    for k, img in enumerate(images):
        r, c = divmod(k, columns)
        sheet[r * (h + gap) : r * (h + gap) + h, c * (w + gap) : c * (w + gap) + w] = img
    return sheet


def run(output_dir: str | Path | None = None, *, contours: int = 10) -> list[Path]:
    """Render each primitive; returns the PNG paths written (contact sheet last)."""
    out = Path(output_dir) if output_dir is not None else DEFAULT_OUTPUT
    out.mkdir(parents=True, exist_ok=True)
    camera = Camera((3.2, -4.2, 2.6), (0, 0, 0), fov=38, width=SIZE[0], height=SIZE[1])
    light = PointLight((4.0, -2.0, 6.0))
    paths, images = [], []
    for name, solid in PRIMITIVES.items():
        result = render(Scene(camera, [light], [solid]), contours=contours)
        path = out / f"iso_primitive_{name}.png"
        save_png(path, result.image)
        paths.append(path)
        images.append(result.image)
    sheet = out / "iso_primitives.png"
    save_png(sheet, tile(images, columns=4))
    paths.append(sheet)
    return paths


if __name__ == "__main__":
    for p in run(sys.argv[1] if len(sys.argv) > 1 else None):
        print(p)
