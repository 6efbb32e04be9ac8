"""Interreflections: patch count against time, memory and accuracy, in a furnished room.

The scene: a 4 x 4 x 3 m room (floor 0.2, walls 0.5, ceiling 0.7), a
1.2 x 0.6 m luminaire at 2.8 m facing down (1000 cd/m^2), a 1.2 x 0.8 x 0.75 m
reflecting box (0.4) standing on the floor. For each patch size the script
prints the patch count, the shots and the final residual of the solve, the
time of the solve and of the indirect illuminance on a 21 x 21 floor grid, the
size of the form-factor columns if all were cached (8 n^2 bytes; the solve keeps
at most ``Interreflections.memory``), the process's peak resident memory so
far, and, with ``--mc``, the error of the indirect illuminance at four points
against the path tracer of ``tests/mc_paths.py`` (that is the discretisation
error of constant radiosity per patch).

Run: ``python benchmarks/radiosity.py [--quick] [--mc]``.
"""

from __future__ import annotations

import argparse
import resource
import sys
import time
from pathlib import Path

import numpy as np

from isocsg import AreaLight, Box
from isocsg.shadows.patches import Room
from isocsg.shadows.radiosity import Interreflections, solve_radiosity

ROOM = Room((0, 0, 1.5), (4, 4, 3), floor=0.2, walls=0.5, ceiling=0.7)
LAMP = AreaLight([(-0.6, -0.3, 2.8), (-0.6, 0.3, 2.8), (0.6, 0.3, 2.8), (0.6, -0.3, 2.8)], radiance=1000.0)
TABLE = Box((0.8, 0.3, 0.375), (1.2, 0.8, 0.75))
POINTS = np.array([[-1.2, -1.0, 0.0], [0.8, 0.3, 0.75], [0.8, -0.5, 0.0], [1.999999, 0.0, 1.2]])
NORMALS = np.array([[0, 0, 1.0], [0, 0, 1.0], [0, 0, 1.0], [-1.0, 0, 0]])


def run(sizes: list[float], mc: bool) -> None:
    ref = None
    if mc:
        sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
        from mc_paths import MCRoom, mc_indirect

        room = MCRoom(np.array([-2, -2, 0.0]), np.array([2, 2, 3.0]), 0.2, 0.5, 0.7,
                      [(np.array([0.2, -0.1, 0.0]), np.array([1.4, 0.7, 0.75]), 0.4)],
                      np.array([-0.6, -0.3]), np.array([0.6, 0.3]), 2.8, 1000.0)
        ref, err = mc_indirect(room, POINTS, NORMALS, paths=200_000, seed=5)
        print("path tracer:", np.round(ref, 3), "+-", np.round(err, 3), "lx")
    solve_radiosity(LAMP, [TABLE], Interreflections(room=ROOM, reflectances=0.4, patch_size=2.0, refine=0))  # compile
    x, y = np.meshgrid(np.linspace(-1.9, 1.9, 21), np.linspace(-1.9, 1.9, 21))
    grid = np.c_[x.ravel(), y.ravel(), np.zeros(x.size)]
    print("patch_size  patches  shots  residual  solve_s  grid_s  columns_MB  peak_RSS_MB"
          + ("  max_rel_err_vs_MC" if mc else ""))
    for size in sizes:
        inter = Interreflections(room=ROOM, reflectances=0.4, patch_size=size, refine=1, tolerance=1e-6)
        t0 = time.perf_counter()
        sol = solve_radiosity(LAMP, [TABLE], inter)
        t1 = time.perf_counter()
        rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024  # kB on Linux
        sol.indirect_illuminance(grid, [0, 0, 1])
        t2 = time.perf_counter()
        line = (f"{size:10.3f}  {len(sol.patches):7d}  {sol.shots:5d}  {sol.residuals[-1]:8.1e}  {t1 - t0:7.1f}  "
                f"{t2 - t1:6.1f}  {8 * len(sol.patches) ** 2 / 2**20:10.1f}  {rss:11.0f}")
        if ref is not None:
            got = sol.indirect_illuminance(POINTS, NORMALS)
            line += f"  {np.max(np.abs(got - ref) / ref):.4f}"
        print(line, flush=True)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="patch sizes 1 and 0.5 only")
    ap.add_argument("--mc", action="store_true", help="also the error against the path tracer (slow)")
    a = ap.parse_args()
    run([1.0, 0.5] if a.quick else [1.0, 0.5, 0.25], a.mc)


if __name__ == "__main__":
    main()
