"""The seed's Fig. 5 scenes: soft shadows from area and polyhedron sources.

Five half-tone images (exact illuminance with umbra and penumbra), each
beside the lux map of its floor with isolux lines:

- ``prism_source``: a triangular-prism (polyhedron) source over blocks;
- ``room_window``: a room lit through a window in its wall (a vertical area source);
- ``room_ceiling``: the same room under one ceiling luminaire;
- ``room_two_sources``: the room under two ceiling luminaires;
- ``sphere_vs_point``: a ball-shaped source (a tessellated sphere) and, for
  comparison, a source 2 mm across (practically a point: hard shadows).

The rectangular area source of Fig. 5a is ``examples/shadows_area_source.py``.

Run ``python examples/shadows_fig5.py [OUT_DIR]`` (default ``out/examples``).
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
    PolyhedronLight,
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
WIDTH, HEIGHT = 160, 120
RESOLUTION = 16  # segments per circle of tessellated occluders


def table(x: float, y: float) -> list[Box]:
    """A table: a top 1.2 x 0.8 m at 0.75 m and four legs."""
    legs = [Box((x + sx * 0.52, y + sy * 0.32, 0.35), (0.06, 0.06, 0.7)) for sx in (-1, 1) for sy in (-1, 1)]
    return [Box((x, y, 0.725), (1.2, 0.8, 0.05)), *legs]


def room() -> list[Box]:
    """A 4 x 4 m floor, a back wall and a left wall (2.8 m high), a table."""
    return [
        Box((0, 0, -0.05), (4, 4, 0.1)),
        Box((0, 2.05, 1.4), (4, 0.1, 2.8)),
        Box((-2.05, 0, 1.4), (0.1, 4, 2.8)),
        *table(0.2, 0.3),
    ]


def ceiling_light(x: float, y: float, radiance: float = 4.0) -> AreaLight:
    """A 1.2 x 0.6 m luminaire at 2.8 m facing down (counter-clockwise seen from below)."""
    corners = [(x - 0.6, y - 0.3, 2.8), (x - 0.6, y + 0.3, 2.8), (x + 0.6, y + 0.3, 2.8), (x + 0.6, y - 0.3, 2.8)]
    return AreaLight(corners, radiance=radiance)


def sphere_source(center: tuple[float, float, float], radius: float, radiance: float) -> PolyhedronLight:
    """A ball-shaped source: the convex hull of a latitude-longitude point set."""
    th, ph = np.meshgrid(np.linspace(0.2, np.pi - 0.2, 5), np.linspace(0, 2 * np.pi, 10, endpoint=False))
    pts = np.stack([np.sin(th) * np.cos(ph), np.sin(th) * np.sin(ph), np.cos(th)], -1).reshape(-1, 3)
    pts = np.vstack([pts, [(0, 0, 1), (0, 0, -1)]])
    return PolyhedronLight(np.asarray(center) + radius * pts, radiance=radiance)


ROOM_CAMERA = Camera((3.4, -4.6, 3.2), (-0.2, 0.4, 0.6), fov=45, width=WIDTH, height=HEIGHT)
BLOCKS_CAMERA = Camera((4.5, -6.0, 4.5), (0, 0, 0.3), fov=36, width=WIDTH, height=HEIGHT)


def blocks() -> list:
    return [
        Box((0, 0, -0.05), (6, 5, 0.1)),
        Box((0.5, 0.3, 0.45), (0.7, 0.7, 0.9)),
        ConvexPolyhedron([(-1.4, -0.9, 0), (-0.6, -1.2, 0), (-1.0, -0.3, 0), (-1.0, -0.8, 1.0)]),
        Sphere((-0.6, 1.0, 0.4), 0.4),
    ]


def scenes() -> dict[str, tuple[Scene, LuxGrid]]:
    """Each scene with the floor grid of its lux map."""
    prism = PolyhedronLight([(-0.6, -0.3, 2.6), (0.6, -0.3, 2.6), (0.0, 0.35, 2.6),
                             (-0.6, -0.3, 3.0), (0.6, -0.3, 3.0), (0.0, 0.35, 3.0)], radiance=3.0)
    # The window: 1.4 x 1.0 m in the plane y = 1.99 (in front of the back wall), lighting into the room (-y).
    window = AreaLight([(-0.9, 1.99, 0.9), (0.5, 1.99, 0.9), (0.5, 1.99, 1.9), (-0.9, 1.99, 1.9)], radiance=6.0)
    blocks_grid = LuxGrid.from_bounds(-3, -2.5, 3, 2.5, 0.0, 72, 60)
    room_grid = LuxGrid.from_bounds(-2, -2, 2, 2, 0.0, 64, 64)
    halftone = RenderSettings(mode="halftone", exposure=1.0, interval=4)
    ball_and_point = [sphere_source((-0.8, -0.5, 2.6), 0.35, 2.0),
                      PolyhedronLight(np.array([(1.2, 0.6, 2.6)]) + 0.001 * np.array(
                          [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]), radiance=2.0e5)]
    return {
        "prism_source": (Scene(BLOCKS_CAMERA, [prism], blocks(), halftone), blocks_grid),
        "room_window": (Scene(ROOM_CAMERA, [window], room(), halftone), room_grid),
        "room_ceiling": (Scene(ROOM_CAMERA, [ceiling_light(0.2, 0.3)], room(), halftone), room_grid),
        "room_two_sources": (Scene(ROOM_CAMERA, [ceiling_light(-0.9, -0.6), ceiling_light(1.0, 0.9)], room(), halftone),
                             room_grid),
        "sphere_vs_point": (Scene(BLOCKS_CAMERA, ball_and_point, blocks(), halftone), blocks_grid),
    }


def run(output_dir: str | Path | None = None) -> list[Path]:
    """Render every scene (half-tone PNG and floor lux map PNG); returns the paths written."""
    out = Path(output_dir) if output_dir is not None else DEFAULT_OUTPUT
    out.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, (sc, grid) in scenes().items():
        result = render_halftone(sc, resolution=RESOLUTION)
        image = out / f"shadows_{name}.png"
        save_png(image, result.display)
        lux = illuminance_map(grid, sc.lights, [o.shape for o in sc.objects], resolution=RESOLUTION)
        luxmap = out / f"shadows_{name}_lux.png"
        save_luxmap_png(luxmap, lux, levels=8, pixels_per_node=2)
        paths += [image, luxmap]
    return paths


if __name__ == "__main__":
    for p in run(sys.argv[1] if len(sys.argv) > 1 else None):
        print(p)
