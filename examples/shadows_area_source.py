"""Blocks under a rectangular area source (the seed's Fig. 5a): umbra and penumbra.

A rectangular source lights a floor with a block, a prism and a ball from
above. The half-tone image shows the exact illuminance with soft shadows; a
second image marks the shadow states (lit, penumbra, umbra) found with the
penumbra and umbra volumes; the floor's lux map shows the isolux lines.

Run ``python examples/shadows_area_source.py`` (writes to ``out/examples``).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from isocsg import (
    AreaLight,
    Box,
    Camera,
    ConvexPolyhedron,
    LuxGrid,
    RenderSettings,
    Scene,
    Sphere,
    illuminance_map,
    render_halftone,
    save_luxmap_png,
    save_png,
)

#: Where ``run()`` writes when given no folder (``out/`` is git-ignored).
DEFAULT_OUTPUT = Path("out") / "examples"


def scene(width: int = 200, height: int = 150) -> Scene:
    """Floor, block, prism and ball under a 1.6 m x 0.8 m source at 3 m, lighting downwards."""
    lamp = AreaLight([(-0.8, -0.4, 3.0), (-0.8, 0.4, 3.0), (0.8, 0.4, 3.0), (0.8, -0.4, 3.0)], radiance=3.0)
    objects = [
        Box((0, 0, -0.05), (6, 5, 0.1)),
        Box((0.5, 0.3, 0.45), (0.7, 0.7, 0.9)),
        ConvexPolyhedron([
            (-1.4, -0.9, 0), (-0.6, -1.2, 0), (-1.0, -0.3, 0),
            (-1.4, -0.9, 0.8), (-0.6, -1.2, 0.8), (-1.0, -0.3, 0.8),
        ]),
        Sphere((-0.6, 1.0, 0.4), 0.4),
    ]
    camera = Camera((4.5, -6.0, 4.5), (0, 0, 0.3), fov=36, width=width, height=height)
    return Scene(camera, [lamp], objects, RenderSettings(mode="halftone", exposure=0.9, interval=4))


def run(output_dir: str | Path | None = None) -> list[Path]:
    """Half-tone image, shadow-state image and lux map; returns the PNG paths written."""
    out = Path(output_dir) if output_dir is not None else DEFAULT_OUTPUT
    out.mkdir(parents=True, exist_ok=True)
    sc = scene()
    result = render_halftone(sc, resolution=24)
    paths = [out / f"shadows_area_source{suffix}.png" for suffix in ("", "_states", "_lux")]
    save_png(paths[0], result.display)
    states = np.where(result.shadow < 0, np.nan, 1.0 - 0.4 * result.shadow)  # white lit, grey penumbra, dark umbra
    save_png(paths[1], states)
    grid = LuxGrid.from_bounds(-3, -2.5, 3, 2.5, 0.0, 96, 80)
    lux = illuminance_map(grid, sc.lights, [o.shape for o in sc.objects], resolution=24)
    save_luxmap_png(paths[2], lux, levels=8, pixels_per_node=3)
    return paths


if __name__ == "__main__":
    for p in run(sys.argv[1] if len(sys.argv) > 1 else None):
        print(p)
