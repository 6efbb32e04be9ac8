"""isocsg where users look: a pyvista view, a notebook image, a glTF model and a lux-map report.

Writes ``pyvista_part.png`` (the demo's CSG part in pyvista, the Boolean
result's clipped bands drawn flat and unlit), ``notebook_part.png`` (the image
Jupyter shows for the part), ``part.glb`` (the part's bands as a glTF model
with unlit per-band colours) and ``luxmap_report.png`` (a desk lit by two
ceiling panels given by their luminous flux: colour bar in lux, labelled isolux
lines, Emin, Eavg, Emax and U0 over the task area).

``python examples/ecosystem_figures.py docs/images`` refreshes the README's
figures (the .glb is written too; the README shows the PNGs only).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")

from isocsg import (
    AreaLight,
    Box,
    Camera,
    LuxGrid,
    PointLight,
    Scene,
    builtin_scene,
    illuminance_map,
    save_gltf,
    save_luxmap_figure,
    show,
)

DEFAULT_OUTPUT = Path("out") / "examples"

#: A desk 1.6 m x 0.8 m, its top at 0.75 m; the task area is its central 1.2 m x 0.6 m.
DESK = Box((0.0, 0.0, 0.375), (1.6, 0.8, 0.75))
TASK_AREA = [(-0.6, -0.3, 0.75), (0.6, -0.3, 0.75), (0.6, 0.3, 0.75), (-0.6, 0.3, 0.75)]


def panel(cx: float, cy: float, lumens: float) -> AreaLight:
    """A 0.6 m square ceiling panel at 2.8 m, facing down, of the given luminous flux."""
    h = 0.3
    corners = [(cx - h, cy - h, 2.8), (cx - h, cy + h, 2.8), (cx + h, cy + h, 2.8), (cx + h, cy - h, 2.8)]
    return AreaLight.from_flux(corners, lumens)


def run(output_dir: str | Path | None = None) -> list[Path]:
    """Write the four files; returns their paths."""
    out = Path(output_dir) if output_dir is not None else DEFAULT_OUTPUT
    out.mkdir(parents=True, exist_ok=True)
    paths = []

    part = builtin_scene("demo").objects[0].shape
    light = PointLight((6.0, -4.0, 9.0))
    camera = Camera((6.0, -8.0, 5.5), (0, 0, 0.4), fov=34, width=320, height=240)
    plotter = show(part, [light], contours=24, camera=camera, off_screen=True, window_size=(320, 240))
    paths.append(out / "pyvista_part.png")
    plotter.screenshot(str(paths[-1]))
    plotter.close()

    paths.append(out / "notebook_part.png")
    paths[-1].write_bytes(part._repr_png_())

    paths.append(save_gltf(Scene(camera, [light], [part]), out / "part.glb", contours=24))

    lamps = [panel(-0.7, 0.0, 3400.0), panel(0.9, 0.3, 3400.0)]
    grid = LuxGrid.from_bounds(-0.8, -0.4, 0.8, 0.4, 0.75, 81, 41)  # the desk top
    screen = Box((0.25, 0.32, 1.0), (0.6, 0.05, 0.5))  # a monitor standing on the desk's back edge
    book = Box((-0.45, -0.1, 0.85), (0.3, 0.22, 0.2))
    lux = illuminance_map(grid, lamps, [DESK, screen, book])
    paths.append(save_luxmap_figure(out / "luxmap_report.png", lux, levels=8, area=TASK_AREA, dpi=90,
                                    title="desk top under two 3400 lm panels (direct light)"))
    return paths


if __name__ == "__main__":
    for p in run(sys.argv[1] if len(sys.argv) > 1 else None):
        print(p)
