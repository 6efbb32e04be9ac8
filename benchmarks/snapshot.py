"""Render the test catalogue with every CSG method and save or compare the images.

A refactoring keeps images byte-identical; this is the check::

    python benchmarks/snapshot.py save before.npz      # on the old commit
    python benchmarks/snapshot.py save after.npz       # on the new one
    python benchmarks/snapshot.py compare before.npz after.npz

Each scene of ``tests/scenes.py`` (``ALL_SCENES``) is drawn by ``isocsg.render`` and by
``Renderer(csg="pixel")`` and ``Renderer(csg="surface")``.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))


def save(path: str) -> None:
    from scenes import ALL_SCENES

    import isocsg
    from isocsg.rendering import Renderer

    out = {}
    for name, scene in ALL_SCENES.items():
        out[f"{name}/auto"] = isocsg.render(scene).image
        for csg in ("pixel", "surface"):
            out[f"{name}/{csg}"] = Renderer(csg=csg).render(scene).image
    np.savez_compressed(path, **out)
    print(f"{len(out)} images saved to {path}")


def compare(old: str, new: str) -> int:
    a, b = np.load(old), np.load(new)
    different = 0
    for key in a.files:
        x, y = a[key], b[key] if key in b.files else None
        if y is None or x.shape != y.shape or not np.array_equal(x, y, equal_nan=True):
            different += 1
            print(f"{key}: different")
    print(f"identical {len(a.files) - different}, different {different}")
    return 1 if different else 0


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "save":
        save(sys.argv[2])
    elif len(sys.argv) == 4 and sys.argv[1] == "compare":
        sys.exit(compare(sys.argv[2], sys.argv[3]))
    else:
        sys.exit(__doc__)
