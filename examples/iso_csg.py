"""A CSG part shaded with isoluminance contours, coarse and fine.

The part is the bracket of the built-in demo scene: a plate and a round boss,
minus a through hole, a spherical pocket and a rounded notch. The visible
surfaces inside the cuts belong to the subtracted primitives, shaded with
their reversed normals. Renders it with 4 and with 32 contours per light.

Run ``python examples/iso_csg.py`` (writes to ``out/examples``).
"""

from __future__ import annotations

import sys
from pathlib import Path

from isocsg import Box, Camera, Cylinder, PointLight, Scene, Sphere, render, save_png

#: Where ``run()`` writes when given no folder (``out/`` is git-ignored).
DEFAULT_OUTPUT = Path("out") / "examples"


def bracket():
    """The part, built with the ``|``, ``-`` and ``&`` operators."""
    body = Box((0, 0, 0), (4.0, 3.0, 0.8)) | Cylinder((-0.6, 0, 0.9), (0, 0, 1.8), 1.1)
    hole = Cylinder((-0.6, 0, 0.9), (0, 0, 3.0), 0.5)
    pocket = Sphere((1.4, -0.6, 0.45), 0.7)
    notch = Box((1.4, 1.0, 0.4), (1.2, 1.2, 1.2)) & Sphere((1.4, 1.0, 0.4), 0.75)
    return body - hole - pocket - notch


def run(output_dir: str | Path | None = None) -> list[Path]:
    """Render the part with 4 and 32 contours; returns the PNG paths written."""
    out = Path(output_dir) if output_dir is not None else DEFAULT_OUTPUT
    out.mkdir(parents=True, exist_ok=True)
    camera = Camera((6.0, -8.0, 5.5), (0, 0, 0.4), fov=34, width=240, height=180)
    scene = Scene(camera, [PointLight((6.0, -4.0, 9.0))], [bracket()])
    paths = []
    for n in (4, 32):
        path = out / f"iso_csg_{n}_contours.png"
        save_png(path, render(scene, contours=n).image)
        paths.append(path)
    return paths


if __name__ == "__main__":
    for p in run(sys.argv[1] if len(sys.argv) > 1 else None):
        print(p)
