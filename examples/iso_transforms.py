"""Transforms: turned, stretched and sheared primitives, with isoluminance contours.

A turned box, an ellipsoid (a sphere scaled unevenly), an elliptic cylinder
(a cylinder stretched across its axis) and an oblique cone (a cone sheared
along x), each built with ``rotate``, ``scale``, ``transform`` and ``translate``
as in OpenSCAD, and a CSG part made of transformed pieces. The ellipsoid's
contours are not planar: its bands follow the exact level lines.

Run ``python examples/iso_transforms.py`` (writes to ``out/examples``).
"""

from __future__ import annotations

import sys
from pathlib import Path

from isocsg import (
    Box,
    Camera,
    Cone,
    Cylinder,
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


def shapes() -> list:
    """The transformed primitives and the CSG part, left to right."""
    box = Box((0, 0, 0), (1.2, 0.8, 0.5)).rotate((20, 30, 40)).translate((-3.6, 0, 0.5))
    egg = Sphere((0, 0, 0), 0.6).scale((1.5, 1.0, 0.7)).rotate((0, 0, 30)).translate((-1.8, 0, 0.5))
    tube = Cylinder((0, 0, 0), (0, 0, 1.2), 0.35).scale((1.6, 1, 1)).rotate((25, 0, 0)).translate((0, 0, 0.5))
    shear = [[1, 0, 0.5, 1.6], [0, 1, 0, 0], [0, 0, 1, 0.5]]
    cone = Cone((0, 0, 0), (0, 0, 1.2), 0.5).transform(shear)
    part = (Box((0, 0, 0), (1.2, 1.2, 0.6)).rotate((0, 0, 20))
            - Sphere((0, 0, 0.3), 0.5).scale((1.4, 0.8, 1))).translate((3.6, 0, 0.5))
    return [box, egg, tube, cone, part]


def run(output_dir: str | Path | None = None, *, contours: int = 16) -> list[Path]:
    """Render the row of transformed shapes; returns the PNG path."""
    out = Path(output_dir) if output_dir is not None else DEFAULT_OUTPUT
    out.mkdir(parents=True, exist_ok=True)
    camera = Camera((0.0, -9.0, 4.0), (0, 0, 0.4), fov=36, width=320, height=160)
    objects = [SceneObject(s, Material(ambient=0.08, kd=0.8)) for s in shapes()]
    image = render(Scene(camera, [PointLight((-3.0, -6.0, 6.0))], objects), contours=contours).image
    path = out / "iso_transforms.png"
    save_png(path, image)
    return [path]


if __name__ == "__main__":
    for p in run(sys.argv[1] if len(sys.argv) > 1 else None):
        print(p)
