"""Two revisions of isocsg side by side in one run: the same workloads, interleaved, ratios printed.

A redesign must not make anything slower. This script checks out two git revisions into
temporary worktrees and runs each workload on both, alternating old and new, each
measurement in a fresh process (so that no cache of one measurement helps the next).
A child imports the revision under test, warms its compiled kernels on a small scene of
the same kind (numba's on-disk cache is per checkout: the first child of a revision
compiles them, which is not timed; ``ISOCSG_JIT=numba``, so that a revision with lazy kernels
compiles too), then times the workload once and prints the seconds.
Printed: the median over the repeats for each revision and the ratio new / old
(< 1: the new revision is faster), with the spread (min-max) so that noise shows.

Run from the repository root::

    python benchmarks/revisions.py                       # 1b9295c (before the redesign) vs HEAD
    python benchmarks/revisions.py --old A --new B --repeats 7
    python benchmarks/revisions.py --only part_render,volume_part

The workloads use only API that both revisions have (``render``, ``volume``,
``illuminance`` and the primitive values), so the old revision runs them unchanged.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

from _common import fmt_seconds, print_table

ROOT = Path(__file__).resolve().parent.parent
DEFAULT_OLD = "1b9295c"

# Run inside the child: `SETUP` builds the inputs (untimed), `WARM` runs a small case of the same
# kind (untimed, loads kernels), `RUN` is timed.
_PRELUDE = """
import json, sys, time
import numpy as np
import isocsg
from isocsg import Box, Camera, Cylinder, PointLight, Scene, Sphere, Truncus, AreaLight
try:
    from isocsg import render as _render
    if not callable(_render):
        raise ImportError
except ImportError:
    from isocsg.render import render as _render
render = _render

def part():
    plate = Box(center=(0, 0, 0), size=(4, 3, 0.8))
    boss = Cylinder(center=(-0.6, 0, 0.9), axis=(0, 0, 1.8), radius=1.1)
    hole = Cylinder(center=(-0.6, 0, 0.9), axis=(0, 0, 3.0), radius=0.5)
    return (plate | boss) - hole - Sphere((1.4, -0.6, 0.45), 0.7)

def plate_with_holes(n):
    k = int(round(n ** 0.5))
    solid = Box(center=(0, 0, 0), size=(k, k, 0.5))
    for i in range(k):
        for j in range(k):
            solid = solid - Cylinder(center=(i - k / 2 + 0.5, j - k / 2 + 0.5, 0), axis=(0, 0, 1), radius=0.3)
    return solid

def camera(w, h, eye=(6, -8, 5.5), target=(0, 0, 0.4)):
    return Camera(eye=eye, target=target, fov=34, width=w, height=h)

def room():
    lamp = AreaLight([(-0.6, -0.3, 2.8), (-0.6, 0.3, 2.8), (0.6, 0.3, 2.8), (0.6, -0.3, 2.8)], 1000.0)
    top = Box((0.3, 0.2, 0.73), (1.2, 0.8, 0.04))
    legs = [Box((0.3 + sx * 0.55, 0.2 + sy * 0.35, 0.355), (0.05, 0.05, 0.71)) for sx in (-1, 1) for sy in (-1, 1)]
    return lamp, [top, *legs]

def floor(m):
    xs = np.linspace(-2.0, 2.0, m)
    X, Y = np.meshgrid(xs, xs, indexing="ij")
    return np.c_[X.ravel(), Y.ravel(), np.zeros(m * m)], np.tile([0.0, 0.0, 1.0], (m * m, 1))
"""

WORKLOADS: dict[str, tuple[str, str, str, str]] = {
    # name: (description, setup, warm, run)
    "part_render": (
        "README part, 1024 x 768, 16 contours",
        "scene = Scene(camera(1024, 768), [PointLight((6, -4, 9))], [part()])",
        "render(Scene(camera(64, 48), [PointLight((6, -4, 9))], [part() - Sphere((0, 0, 0), 0.3)]), contours=8)",
        "render(scene, contours=16)",
    ),
    "holes_400_render": (
        "plate minus 400 cylinders, 512 x 512",
        ("scene = Scene(camera(512, 512, eye=(14, -18, 16), target=(0, 0, 0)), [PointLight((10, -6, 20))],"
        " [plate_with_holes(400)])"),
        ("render(Scene(camera(64, 64, eye=(14, -18, 16), target=(0, 0, 0)), [PointLight((10, -6, 20))],"
        " [plate_with_holes(16)]), contours=8)"),
        "render(scene, contours=8)",
    ),
    "lattice_2000_render": (
        "union of 2000 spheres, 512 x 512",
        ("spheres = [Sphere((i % 20 - 10, (i // 20) % 10 - 5, i // 200 - 5), 0.45) for i in range(2000)]\n"
        "scene = Scene(camera(512, 512, eye=(30, -40, 30), target=(0, 0, 0)), [PointLight((20, -10, 40))],"
        " [isocsg.union_all(spheres)])"),
        ("render(Scene(camera(64, 64, eye=(30, -40, 30), target=(0, 0, 0)), [PointLight((20, -10, 40))],"
        " [isocsg.union_all([Sphere((i, 0, 0), 0.45) for i in range(8)])]), contours=8)"),
        "render(scene, contours=8)",
    ),
    "volume_part": (
        "isocsg.volume of the README part",
        "solid = part()",
        "isocsg.volume(Box((0, 0, 0), (1, 1, 1)) - Sphere((0.5, 0, 0), 0.3))",
        "isocsg.volume(solid)",
    ),
    "volume_holes_400": (
        "isocsg.volume of the plate minus 400 cylinders",
        "solid = plate_with_holes(400)",
        "isocsg.volume(plate_with_holes(4))",
        "isocsg.volume(solid)",
    ),
    "illuminance_room": (
        "exact illuminance, 201 x 201 floor under a table",
        "lamp, table = room()\npts, nrm = floor(201)",
        "isocsg.illuminance(floor(11)[0], floor(11)[1], [lamp], table)",
        "isocsg.illuminance(pts, nrm, [lamp], table)",
    ),
}


def _child_source(setup: str, warm: str, run: str) -> str:
    return (
        _PRELUDE
        + f"\n{setup}\n{warm}\n"
        + "t0 = time.perf_counter()\n"
        + f"{run}\n"
        + "print(json.dumps({'seconds': time.perf_counter() - t0}))\n"
    )


def _measure(checkout: Path, name: str, timeout: float) -> float | None:
    _, setup, warm, run = WORKLOADS[name]
    # Compiled kernels from the start: a revision with lazy kernels would otherwise run the warm-up
    # and the start of the workload in Python (that first-call cost is benchmarks/startup.py's
    # subject); the older revisions always compile and ignore the variable.
    env = dict(os.environ, PYTHONPATH=str(checkout), ISOCSG_PROGRESS="0", ISOCSG_JIT="numba")
    try:
        proc = subprocess.run([sys.executable, "-c", _child_source(setup, warm, run)], cwd=checkout,
                              env=env, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None
    for line in reversed(proc.stdout.splitlines()):
        if line.startswith("{"):
            return float(json.loads(line)["seconds"])
    print(f"  {name} failed in {checkout.name}: {proc.stderr.strip().splitlines()[-1:]}", file=sys.stderr)
    return None


def _checkout(rev: str, into: Path) -> Path:
    path = into / rev.replace("/", "_")
    subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", "-f", str(path), rev],
                   check=True, capture_output=True)
    return path


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--old", default=DEFAULT_OLD, help=f"the earlier revision (default {DEFAULT_OLD})")
    parser.add_argument("--new", default="HEAD", help="the later revision (default HEAD)")
    parser.add_argument("--repeats", type=int, default=5, help="fresh processes per workload and revision")
    parser.add_argument("--only", default="", help="comma-separated workload names")
    parser.add_argument("--timeout", type=float, default=600.0, help="seconds before a child is stopped")
    args = parser.parse_args()
    names = [n for n in args.only.split(",") if n] or list(WORKLOADS)
    unknown = sorted(set(names) - set(WORKLOADS))
    if unknown:
        parser.error(f"unknown workloads {unknown}; known: {sorted(WORKLOADS)}")

    tmp = Path(tempfile.mkdtemp(prefix="isocsg-revisions-"))
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))  # a stopped run still removes its worktrees
    try:
        old, new = _checkout(args.old, tmp), _checkout(args.new, tmp)
        rows = []
        for name in names:
            times: dict[str, list[float]] = {"old": [], "new": []}
            # One untimed child each: compiles the revision's kernels into its own numba cache.
            _measure(old, name, args.timeout)
            _measure(new, name, args.timeout)
            for _ in range(args.repeats):
                for label, checkout in (("old", old), ("new", new)):
                    t = _measure(checkout, name, args.timeout)
                    if t is not None:
                        times[label].append(t)
                print(f"  {name}: old {times['old'][-1:]} new {times['new'][-1:]}", file=sys.stderr, flush=True)
            med = {k: statistics.median(v) if v else None for k, v in times.items()}
            spread = {k: f"{fmt_seconds(min(v))}-{fmt_seconds(max(v))}" if v else "-" for k, v in times.items()}
            ratio = f"{med['new'] / med['old']:.2f}" if med["old"] and med["new"] else "-"
            rows.append([name, WORKLOADS[name][0], fmt_seconds(med["old"]), spread["old"],
                         fmt_seconds(med["new"]), spread["new"], ratio])
        print_table(
            f"isocsg {args.old} (old) against {args.new} (new): median of {args.repeats} fresh processes each",
            ["workload", "what", "old", "old min-max", "new", "new min-max", "new / old"], rows)
        print(f"load average at the end: {os.getloadavg()[0]:.2f} (2-core machine: above 2 the numbers are noisy)")
    finally:
        for path in tmp.iterdir():
            subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(path)], capture_output=True)
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
