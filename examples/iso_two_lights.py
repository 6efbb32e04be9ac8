"""Two point lights: each light has its own family of contour planes.

A sphere and a box under two lights, left and right. Where both lights reach
a surface the two families of isoluminance contours cross, and the bands are
the cells between them. Renders each light alone and both together.

Run ``python examples/iso_two_lights.py`` (writes to ``out/examples``).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from isocsg import (
    Box,
    Camera,
    Material,
    PointLight,
    Scene,
    SceneObject,
    Sphere,
    render,
    save_png,
)

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


def run(output_dir: str | Path | None = None, *, contours: int = 8) -> list[Path]:
    """Render with the left light, the right light and both; returns the PNG paths."""
    out = Path(output_dir) if output_dir is not None else DEFAULT_OUTPUT
    out.mkdir(parents=True, exist_ok=True)
    camera = Camera((0.0, -7.0, 3.0), (0, 0, 0.3), fov=36, width=200, height=150)
    material = Material(ambient=0.05, kd=0.5)
    objects = [
        SceneObject(Sphere((-1.0, 0.0, 0.6), 1.0), material),
        SceneObject(Box((1.4, 0.3, 0.4), (1.2, 1.2, 1.2)), material),
    ]
    left, right = PointLight((-5.0, -3.0, 4.0)), PointLight((5.0, -4.0, 3.0))
    paths, images = [], []
    for name, lights in (("left", [left]), ("right", [right]), ("both", [left, right])):
        image = render(Scene(camera, lights, objects), contours=contours).image
        path = out / f"iso_two_lights_{name}.png"
        save_png(path, image)
        paths.append(path)
        images.append(image)
    sheet = out / "iso_two_lights.png"
    save_png(sheet, tile(images, columns=3))
    paths.append(sheet)
    return paths


if __name__ == "__main__":
    for p in run(sys.argv[1] if len(sys.argv) > 1 else None):
        print(p)
