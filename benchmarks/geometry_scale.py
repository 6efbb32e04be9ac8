"""Timings of volume(), section() and contains() on large trees (medians of repeated runs).

Usage: ``python benchmarks/geometry_scale.py [--repeat 3] [--points 1000000]``

- the 56-primitive machined part of ``tests/test_geometry_scale.py``: ``volume`` at its default
  tolerance and at 1e-6;
- plates 100 x 100 x 10 minus 1024 and 10 000 disjoint through holes: ``section`` across the
  holes (inscribed and exact-area polygons), ``volume``, and ``contains`` of uniformly random
  points in a box around the plate.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from test_geometry_scale import machined_part, plate  # noqa: E402

from isocsg.csg.section import section  # noqa: E402
from isocsg.csg.volume import volume  # noqa: E402


def median_time(fn, repeat: int) -> tuple[float, object]:
    times, out = [], None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--points", type=int, default=1_000_000)
    args = ap.parse_args()
    part = machined_part()
    for tol in (1e-4, 1e-6):
        t, v = median_time(lambda: volume(part, tol=tol), args.repeat)
        print(f"machined part (56 leaves): volume tol={tol:g}: {t:.3f} s  ({v:.4f} m^3)")
    rng = np.random.default_rng(1)
    pts = rng.uniform([-55, -55, -6], [55, 55, 6], size=(args.points, 3))
    for n_side in (32, 100):
        tree = plate(n_side)[0]
        n = tree.program().n_leaves
        for exact in (False, True):
            t, s = median_time(lambda: section(tree, (0, 0, 0.3), (0, 0, 1), area_exact=exact), args.repeat)
            print(f"plate ({n} leaves): section area_exact={exact}: {t:.3f} s  (area {s.area:.6f})")
        t, v = median_time(lambda: volume(tree), args.repeat)
        print(f"plate ({n} leaves): volume: {t:.3f} s  ({v:.6f} m^3)")
        t, m = median_time(lambda: tree.contains(pts), args.repeat)
        print(f"plate ({n} leaves): contains of {len(pts)} points: {t:.3f} s  ({int(m.sum())} inside)")


if __name__ == "__main__":
    main()
