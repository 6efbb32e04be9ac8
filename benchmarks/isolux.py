"""Isolux lines: contourpy (the library) against the pure-Python marching-squares tracer.

Both trace the same lines (tests/test_luxreport.py checks the points to
1e-12); this measures the median time of each, side by side, with the ratio,
on a real lux map (two area sources and a box on the floor, the exact
illuminance at n x n nodes, computed once) and on a synthetic field. The
pure-Python tracer's time grows with the number of cells the lines cross,
contourpy's with the nodes it is given per level: isocsg gives it, for each
level, the rectangle of nodes holding that level's lines (or the whole grid
once, for the levels that cross most of it), so few short lines on a large
grid cost little too.

    .venv/bin/python benchmarks/isolux.py            # 128, 256 and 512 nodes a side
    .venv/bin/python benchmarks/isolux.py --quick    # 128 and 512, fewer repeats
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from _common import fmt_seconds, median_time, print_table  # noqa: E402
from reference.marching_squares import marching_squares  # noqa: E402

from isocsg import Box  # noqa: E402
from isocsg.shadows import AreaLight  # noqa: E402
from isocsg.shadows.luxmap import LuxGrid, illuminance_map, isolux_lines, nice_levels  # noqa: E402


def lux_map(n: int) -> np.ndarray:
    """The exact illuminance (lx) on a 6 m x 6 m floor under two panels, a box casting a soft shadow."""
    panels = [
        AreaLight([(-1.5, -0.5, 2.5), (-1.5, 0.5, 2.5), (-0.5, 0.5, 2.5), (-0.5, -0.5, 2.5)], radiance=1000.0),
        AreaLight([(0.8, -0.3, 2.2), (0.8, 0.3, 2.2), (1.4, 0.3, 2.2), (1.4, -0.3, 2.2)], radiance=1500.0),
    ]
    grid = LuxGrid.from_bounds(-3, -3, 3, 3, 0, n, n)
    return illuminance_map(grid, panels, [Box((0.2, 0.6, 0.4), (0.6, 0.4, 0.8))]).E


def field(n: int) -> np.ndarray:
    """A lux-map-like field: a broad peak under a source, a shadow and ripples (n x n nodes)."""
    y, x = np.mgrid[0:n, 0:n] / (n - 1) * 4.0 - 2.0
    peak = 500.0 / (1.0 + (x**2 + y**2) / 2.0) ** 2
    shadow = 1.0 - 0.8 * np.exp(-((x - 0.6) ** 2 + (y - 0.3) ** 2) / 0.08)
    return peak * shadow + 10.0 * np.sin(5 * x) * np.cos(4 * y)


def median_cpu(fn, repeats: int) -> float:
    """Median CPU seconds of ``fn()`` in this process: both tracers run on one thread, and CPU
    time does not count the time slices a loaded machine gives to other processes."""
    times = []
    for _ in range(repeats):
        t0 = time.process_time()
        fn()
        times.append(time.process_time() - t0)
    return statistics.median(times)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args(argv)
    sizes = (128, 512) if args.quick else (128, 256, 512)
    repeats = 5 if args.quick else 15
    rows = []
    for n in sizes:
        for name, E in (("lux map", lux_map(n)), ("synthetic", field(n))):
            for count in (8, 12):
                levels = nice_levels(E, count)
                t_py, ref = median_time(lambda: marching_squares(E, levels), repeats)
                t_cp, ours = median_time(lambda: isolux_lines(E, levels), repeats, warmup=1)
                c_py = median_cpu(lambda: marching_squares(E, levels), repeats)
                c_cp = median_cpu(lambda: isolux_lines(E, levels), repeats)
                points = sum(len(p) for lines in ours for p, _ in lines)
                same = points == sum(len(p) for lines in ref for p, _ in lines)
                rows.append([f"{n} x {n}", name, len(levels), points, fmt_seconds(t_py), fmt_seconds(t_cp),
                             f"{t_py / t_cp:.1f}x", fmt_seconds(c_py), fmt_seconds(c_cp), f"{c_py / c_cp:.1f}x",
                             "yes" if same else "NO"])
    print_table(
        f"isolux lines, medians of {repeats}: pure-Python marching squares vs contourpy (wall clock, then CPU time)",
        ["grid", "field", "levels", "line points", "Python wall", "contourpy wall", "ratio", "Python CPU",
         "contourpy CPU", "ratio", "same point count"],
        rows,
    )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
