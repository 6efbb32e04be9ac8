"""Time and peak memory of the clipped CSG surface (``surface_from_bands``) at scale.

One case per process (peak memory is that process's resident set, sampled
every 5 ms while the surface is built, minus what it held before):

    python benchmarks/surface_scale.py spheres 40 128     # K disjoint unit spheres, N contours
    python benchmarks/surface_scale.py plate 100 64       # a plate minus H through holes
    python benchmarks/surface_scale.py grid 16 64         # the union of a k x k grid of touching unit boxes
    python benchmarks/surface_scale.py layers 64          # coincident opposite layers alone (see _layers)
    python benchmarks/surface_scale.py all                # the table of docs/csg.md, one process per case

``--module path/to/surface.py`` (a single-module version) times another implementation of
``surface_from_bands`` (e.g. an older version) on the same band meshes.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import os
import subprocess
import sys
import threading
import time

import numpy as np


def _tree(kind: str, count: int):  # type: ignore[no-untyped-def]
    from isocsg import Box, Cylinder, Sphere, union_all

    if kind == "grid":  # face-sharing boxes: their common planes hold many band triangles each
        return union_all([Box((i + 0.5, j + 0.5, 0.5), (1.0, 1.0, 1.0)) for i in range(count) for j in range(count)])
    side = int(np.ceil(np.sqrt(count)))
    if kind == "spheres":
        return union_all([Sphere((3.0 * (i % side), 3.0 * (i // side), 0.0), 1.0) for i in range(count)])
    pitch = 0.5
    plate = Box(((side - 1) * pitch / 2, (side - 1) * pitch / 2, 0.0), (side * pitch, side * pitch, 0.2))
    holes = [Cylinder((pitch * (i % side), pitch * (i // side), 0.0), (0.0, 0.0, 0.4), 0.15) for i in range(count)]
    out = plate
    for h in holes:  # a modelling loop: one difference per hole
        out = out - h
    return out


def _layers(k: int):  # type: ignore[no-untyped-def]
    """One plane holding two opposite layers: k x k unit squares facing +z (two triangles
    each) and in each square a small triangle facing -z across its diagonal, the input
    of the step that cancels partly overlapping coincident faces."""
    a, b = np.meshgrid(np.arange(k, dtype=float), np.arange(k, dtype=float), indexing="ij")
    corner = np.column_stack([a.ravel(), b.ravel(), np.zeros(k * k)])
    local = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.2, 0.1, 0], [0.4, 0.1, 0], [0.2, 0.3, 0]])
    v = (corner[:, None, :] + local[None]).reshape(-1, 3)
    t = (7 * np.arange(k * k)[:, None, None] + np.array([[0, 1, 2], [0, 2, 3], [4, 6, 5]])[None]).reshape(-1, 3)
    drop = np.zeros(len(t), bool)
    drop[2::3] = True
    return v, t.astype(np.int64), np.arange(len(t)), drop


def _surface_module(module: str | None):
    """``isocsg.csg.surface``, or another version of it read from the file ``module`` (to time
    two versions side by side)."""
    if not module:
        import isocsg.csg.surface as mod

        return mod
    spec = importlib.util.spec_from_file_location("other_surface", module)
    mod = importlib.util.module_from_spec(spec)  # type: ignore[arg-type]
    sys.modules["other_surface"] = mod
    spec.loader.exec_module(mod)  # type: ignore[union-attr]
    return mod


def run_layers(k: int, module: str | None) -> dict:
    """Median seconds of the cancelling step alone on :func:`_layers` (k x k squares)."""
    import statistics

    mod = _surface_module(module)
    cancel = getattr(mod, "coincident", mod)._cancel_partial_overlaps
    cancel(*_layers(2), mod.COINCIDENT_DISTANCE)  # compiled kernels warm
    args = _layers(k)
    times = []
    for _ in range(3):
        t0 = time.perf_counter()
        out = cancel(*args, mod.COINCIDENT_DISTANCE)
        times.append(time.perf_counter() - t0)
    kept = out[1][~out[3]]
    area = 0.5 * np.cross(out[0][kept[:, 1]] - out[0][kept[:, 0]], out[0][kept[:, 2]] - out[0][kept[:, 0]])[:, 2].sum()
    return {"case": "layers", "count": k, "triangles": len(args[1]), "seconds": round(statistics.median(times), 4),
            "us_per_square": round(1e6 * statistics.median(times) / k**2, 1),
            "kept_area_error": float(area - 0.98 * k * k)}


def _peak_rss(fn):  # type: ignore[no-untyped-def]
    import psutil

    proc = psutil.Process()
    base = proc.memory_info().rss
    peak = [base]
    done = threading.Event()

    def sample() -> None:
        while not done.is_set():
            peak[0] = max(peak[0], proc.memory_info().rss)
            time.sleep(0.005)

    th = threading.Thread(target=sample, daemon=True)
    th.start()
    t0 = time.perf_counter()
    out = fn()
    elapsed = time.perf_counter() - t0
    done.set()
    th.join()
    return out, elapsed, max(peak[0], proc.memory_info().rss) - base


def run(kind: str, count: int, contours: int, module: str | None) -> dict:
    from isocsg import PointLight
    from isocsg.laminae import build_laminae
    from isocsg.lighting.lights import Material

    mod = _surface_module(module)
    tree = _tree(kind, count)
    prog = tree.program()
    lights = (PointLight((0.3 * count, -0.4 * count, 5.0)) if kind == "grid" else PointLight((3.0, -4.0, 5.0)),)
    bands = [build_laminae(p, lights, Material(), contours).bands for p in prog.leaves]
    # Warm the compiled kernels on a small case first.
    small = _tree(kind, 2).program()
    mod.surface_from_bands(small, [build_laminae(p, lights, Material(), 8).bands for p in small.leaves])
    # The time spent cancelling partly overlapping coincident faces, where the module has that step.
    cancel = [0.0]
    holder = getattr(mod, "coincident", mod)  # the package's module of that step, or a single module
    inner = getattr(holder, "_cancel_partial_overlaps", None)
    if inner is not None:
        def timed(*args):  # type: ignore[no-untyped-def]
            t0 = time.perf_counter()
            out = inner(*args)
            cancel[0] += time.perf_counter() - t0
            return out

        holder._cancel_partial_overlaps = timed
    surf, seconds, peak = _peak_rss(lambda: mod.surface_from_bands(prog, bands))
    # What the renderer then does with it: one part per leaf.
    t0 = time.perf_counter()
    parts = [surf.leaf_bands(int(i)) for i in np.unique(surf.leaf)]
    split = time.perf_counter() - t0
    return {
        "case": kind, "count": count, "contours": contours, "band_triangles": int(sum(len(b.triangles) for b in bands)),
        "surface_triangles": surf.n_triangles, "seconds": round(seconds, 3),
        "ms_per_leaf": round(1e3 * seconds / len(prog.leaves), 2), "cancel_seconds": round(cancel[0], 3),
        "peak_mb": round(peak / 2**20),
        "split_seconds": round(split, 3), "parts": len(parts),
    }


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("case", choices=["spheres", "plate", "grid", "layers", "all"])
    ap.add_argument("count", type=int, nargs="?", default=0)
    ap.add_argument("contours", type=int, nargs="?", default=64)
    ap.add_argument("--module", default=None)
    args = ap.parse_args()
    if args.case == "layers":
        print(json.dumps(run_layers(args.count, args.module)), flush=True)
        return
    if args.case != "all":
        print(json.dumps(run(args.case, args.count, args.contours, args.module)), flush=True)
        return
    cases = [("spheres", k, n) for n in (64, 128) for k in (5, 10, 20, 40, 100, 200)]
    cases += [("plate", h, n) for n in (64, 128) for h in (10, 100, 1000)]
    cases += [("grid", k, 64) for k in (4, 8, 16, 32)]  # k x k boxes: count is k
    if args.count > 0:  # with a count: only the cases up to that many leaves
        cases = [c for c in cases if c[1] <= args.count]
    for kind, count, n in cases:
        cmd = [sys.executable, __file__, kind, str(count), str(n)] + (["--module", args.module] if args.module else [])
        subprocess.run(cmd, check=False, env=os.environ.copy())


if __name__ == "__main__":
    main()
