"""Isoluminance accuracy against the analytic ray caster of the tests, scene by scene.

For every scene of the test catalogue (``tests/scenes.py``: 14 single-primitive
and 14 CSG scenes, 160 x 160 pixels) this renders the scene with N = 16, 64
and 256 contours and prints, against the exact image of the independent ray
caster (``tests/reference``): the silhouette IoU, the fraction of compared
pixels within 0.05 (I_max - I_min) of the exact intensity, and the mean
absolute error on the pixels compared at every N. The accuracy tests assert
IoU >= 0.99 and fraction >= 0.98 at N = 64, and that the error shrinks with N.

Run: ``python benchmarks/accuracy.py``
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from _common import print_table  # noqa: E402
from reference import compare, comparison_mask, raycast_scene  # noqa: E402
from scenes import CORE_SCENES, CSG_SCENES, with_contours  # noqa: E402

from isocsg.rendering import Renderer  # noqa: E402

COUNTS = (16, 64, 256)


def main() -> int:
    renderer = Renderer()
    for title, catalogue in (("single primitives", CORE_SCENES), ("CSG trees", CSG_SCENES)):
        rows = []
        for name, scene in catalogue.items():
            ref = raycast_scene(scene)
            images = [renderer.render(with_contours(scene, n)).image for n in COUNTS]
            results = [compare(img, ref) for img in images]
            keep = np.logical_and.reduce([comparison_mask(img, ref) for img in images])
            errs = [float(np.abs(img[keep] - ref.image[keep]).mean()) if keep.any() else float("nan") for img in images]
            row = [name]
            row += [f"{r.iou:.4f}" for r in results]
            row += [f"{r.fraction:.4f}" for r in results]
            row += [f"{e:.2e}" for e in errs]
            rows.append(row)
        head = (["scene"] + [f"IoU N={n}" for n in COUNTS] + [f"within 5% N={n}" for n in COUNTS]
                + [f"mean |err| N={n}" for n in COUNTS])
        print_table(f"{title}: against the analytic ray caster", head, rows)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
