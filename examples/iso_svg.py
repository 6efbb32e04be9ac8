"""Vector output: the visible bands of a few primitives as SVG polygons.

A sphere in front of a box, and a cone beside them. Each object's front band
triangles are written farthest first, and the objects back to front (the box
behind the sphere first), so an SVG viewer that paints in file order draws the
same picture as the PNG, at any zoom.

Run ``python examples/iso_svg.py`` (writes to ``out/examples``).
"""

from __future__ import annotations

import sys
from pathlib import Path

from isocsg import (
    Box,
    Camera,
    Cone,
    PointLight,
    Scene,
    Sphere,
    render,
    save_png,
    save_scene_svg,
)

#: Where ``run()`` writes when given no folder (``out/`` is git-ignored).
DEFAULT_OUTPUT = Path("out") / "examples"


def run(output_dir: str | Path | None = None, *, contours: int = 10) -> list[Path]:
    """Write the scene as SVG and as PNG; returns both paths."""
    out = Path(output_dir) if output_dir is not None else DEFAULT_OUTPUT
    out.mkdir(parents=True, exist_ok=True)
    camera = Camera((1.5, -7.0, 2.5), (0, 0, 0.3), fov=36, width=320, height=240)
    scene = Scene(
        camera,
        [PointLight((4.0, -5.0, 6.0))],
        [
            Sphere((-0.4, -1.2, 0.5), 0.9),
            Box((0.2, 1.0, 0.3), (2.4, 1.2, 1.6)),
            Cone((2.0, -0.5, 0.3), (0, 0, -1.6), 0.6),
        ],
    )
    svg = out / "iso_svg.svg"
    save_scene_svg(svg, scene, contours=contours)
    png = out / "iso_svg.png"
    save_png(png, render(scene, contours=contours).image)
    return [svg, png]


if __name__ == "__main__":
    for p in run(sys.argv[1] if len(sys.argv) > 1 else None):
        print(p)
