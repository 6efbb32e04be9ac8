"""Batches on Dask: a 16-view turntable and a 2001 x 2001 lux grid, serial against a 2-process local cluster.

The serial runs are :func:`isocsg.batch.render_views` with ``workers=1`` and
:func:`isocsg.shadows.luxmap.illuminance_map`; the cluster runs are the same
calls with a ``dask.distributed`` client of two worker processes (one thread
each; each worker loads its kernels once before its tasks and gets one task, a
contiguous run of the views, while the lux grid's row blocks are one task
each). Both must give equal arrays (checked). Each process first renders two
views with 4 contours and a small grid (its numba kernels are loaded from the disk cache, not
timed); the timed turntable (12 contours) then starts from no band mesh or CSG
surface in either, as a new scene's would: the first view of each process
resolves the CSG part per pixel, the second builds its clipped surface, later
views are plain fills (milliseconds). The serial lux grid runs in one process
whose illuminance kernel uses numba's threads; so does each worker's.
Printed: wall-clock medians, CPU seconds (this process, or this process plus
both workers), the speed-up, and the machine's load average before and after,
since a shared machine's other work takes from both.

    .venv/bin/python benchmarks/batch.py                 # 16 views, 2001 x 2001 nodes, 1 repeat
    .venv/bin/python benchmarks/batch.py --quick         # 8 views, 401 x 401 nodes
"""

from __future__ import annotations

import argparse
import logging
import os
import resource
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from _common import fmt_seconds, print_table  # noqa: E402

from isocsg import Box, Sphere  # noqa: E402
from isocsg.batch import illuminance_grid, render_views, turntable  # noqa: E402
from isocsg.scene.io import builtin_scene_path, load_scene  # noqa: E402
from isocsg.shadows import AreaLight  # noqa: E402
from isocsg.shadows.luxmap import LuxGrid, illuminance_map  # noqa: E402

LAMPS = [
    AreaLight([(-1.5, -0.5, 2.5), (-1.5, 0.5, 2.5), (-0.5, 0.5, 2.5), (-0.5, -0.5, 2.5)], radiance=1000.0),
    AreaLight([(0.8, -0.3, 2.2), (0.8, 0.3, 2.2), (1.4, 0.3, 2.2), (1.4, -0.3, 2.2)], radiance=1500.0),
]
OCCLUDERS = [Box((0.2, 0.6, 0.4), (0.6, 0.4, 0.8)), Sphere((-0.8, -0.6, 0.6), 0.3)]


def _cpu_self() -> float:
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def _timed(fn, cpu):
    """Wall seconds, CPU seconds (from ``cpu()``) and the result of ``fn()``."""
    c0, t0 = cpu(), time.perf_counter()
    out = fn()
    return time.perf_counter() - t0, cpu() - c0, out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--views", type=int, default=None)
    ap.add_argument("--nodes", type=int, default=None)
    args = ap.parse_args(argv)
    import distributed

    n_views = args.views or (8 if args.quick else 16)
    nodes = args.nodes or (401 if args.quick else 2001)
    scene = load_scene(builtin_scene_path("demo"))
    cams = turntable(scene.camera, n_views)
    grid = LuxGrid.from_bounds(-3, -3, 3, 3, 0, nodes, nodes)
    small = LuxGrid.from_bounds(-3, -3, 3, 3, 0, 9, 9)
    load_before = os.getloadavg()

    # Serial (this process; warmed by a first small run).
    render_views(scene, cams[:2], contours=4, workers=1)
    illuminance_map(small, LAMPS, OCCLUDERS)
    sv_wall, sv_cpu, serial_views = _timed(lambda: render_views(scene, cams, workers=1), _cpu_self)
    sg_wall, sg_cpu, serial_map = _timed(lambda: illuminance_map(grid, LAMPS, OCCLUDERS), _cpu_self)

    rows = []
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                  silence_logs=logging.CRITICAL) as cluster:
        with distributed.Client(cluster) as client:

            def cpu_all() -> float:
                return _cpu_self() + sum(client.run(_cpu_self).values())

            render_views(scene, cams[:2], contours=4, client=client)  # both workers load their kernels
            illuminance_grid(small, LAMPS, OCCLUDERS, rows_per_task=2, client=client)
            dv_wall, dv_cpu, views = _timed(lambda: render_views(scene, cams, client=client), cpu_all)
            dg_wall, dg_cpu, lux = _timed(lambda: illuminance_grid(grid, LAMPS, OCCLUDERS, client=client), cpu_all)
    same_views = all(np.array_equal(a.image, b.image, equal_nan=True) for a, b in zip(views, serial_views))
    same_map = np.array_equal(lux.E, serial_map.E) and np.array_equal(lux.occluded, serial_map.occluded)
    w, h = scene.camera.width, scene.camera.height
    rows.append([f"turntable, {n_views} views of {w} x {h}", fmt_seconds(sv_wall), fmt_seconds(sv_cpu),
                 fmt_seconds(dv_wall), fmt_seconds(dv_cpu), f"{sv_wall / dv_wall:.2f}x", "yes" if same_views else "NO"])
    rows.append([f"lux grid, {nodes} x {nodes} nodes", fmt_seconds(sg_wall), fmt_seconds(sg_cpu),
                 fmt_seconds(dg_wall), fmt_seconds(dg_cpu), f"{sg_wall / dg_wall:.2f}x", "yes" if same_map else "NO"])
    load_after = os.getloadavg()
    print_table(
        f"batches: serial vs a local Dask cluster of 2 worker processes x 1 thread ({os.cpu_count()} CPUs; "
        f"load average {load_before[0]:.2f} before, {load_after[0]:.2f} after)",
        ["job", "serial wall", "serial CPU", "cluster wall", "cluster CPU (all processes)", "speed-up (wall)", "equal"],
        rows,
    )
    return 0 if same_views and same_map else 1


if __name__ == "__main__":
    raise SystemExit(main())
