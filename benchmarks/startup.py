"""Start-up benchmark: a small model's first image from a fresh process.

Run from the repository root (OpenSCAD's preview and pyvista need a display; ``xvfb-run``
gives one)::

    xvfb-run -a python benchmarks/startup.py             # 5 repeats of each
    xvfb-run -a python benchmarks/startup.py --repeats 9
    python benchmarks/startup.py --import-only           # isocsg's imports only (python -X importtime)

Each contender draws ``cube(1)`` at 512 x 512 to a PNG in a new process, the way a user's
command does:

- ``isocsg render cube.csg -o out.png`` (the command line; kernels already in numba's cache);
- ``openscad --preview -o out.png cube.scad`` (OpenSCAD's preview: OpenCSG, no CGAL);
- manifold3d + pyvista: a Python process that imports both, builds the cube and saves an
  off-screen render.

Printed: medians over the repeats of wall-clock and CPU seconds (user + system of the child
process), and isocsg's ratio to each of the others (> 1: isocsg is slower). The machine's load
shows in wall-clock times; CPU seconds are steadier. ``--import-only`` prints the modules that
take most of isocsg's import time for the command (self time, from ``-X importtime``).
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from _common import fmt_seconds, print_table

ROOT = Path(__file__).resolve().parent.parent

CSG = "group() {\n  cube(size = [1, 1, 1], center = false);\n}\n"
SCAD = "cube(1);\n"
PEER = """
import sys
import manifold3d
import numpy as np
import pyvista as pv
mesh = manifold3d.Manifold.cube((1.0, 1.0, 1.0)).to_mesh()
faces = np.hstack([np.full((len(mesh.tri_verts), 1), 3), mesh.tri_verts]).ravel()
surface = pv.PolyData(np.asarray(mesh.vert_properties)[:, :3], faces)
plotter = pv.Plotter(off_screen=True, window_size=(512, 512))
plotter.add_mesh(surface, color="white")
plotter.screenshot(sys.argv[1])
plotter.close()
"""


def timed(argv: list[str], env: dict[str, str]) -> tuple[float, float]:
    """Wall-clock and CPU seconds (user + system) of one child process; raises if it fails."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    proc = subprocess.run(argv, env=env, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        raise RuntimeError(f"{argv[0]} exited {proc.returncode}: {proc.stderr.strip().splitlines()[-1:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def medians(argv: list[str], env: dict[str, str], repeats: int) -> tuple[float, float]:
    """Median wall-clock and CPU seconds over ``repeats`` runs (after one run that warms disk caches)."""
    timed(argv, env)
    runs = [timed(argv, env) for _ in range(repeats)]
    return statistics.median(r[0] for r in runs), statistics.median(r[1] for r in runs)


def import_profile(workdir: Path, env: dict[str, str], top: int = 25) -> None:
    """The modules with the largest self import time of ``isocsg render`` (one run)."""
    argv = [sys.executable, "-X", "importtime", "-m", "isocsg", "render", str(workdir / "cube.csg"),
            "-o", str(workdir / "isocsg.png"), "--no-progress"]
    proc = subprocess.run(argv, env=env, capture_output=True, text=True)
    rows = []
    for line in proc.stderr.splitlines():
        if not line.startswith("import time:") or "self [us]" in line:
            continue
        own, total, name = line[len("import time:"):].split("|")
        rows.append((int(own), int(total), name.strip()))
    rows.sort(reverse=True)
    print_table(f"isocsg render: largest import self times (of {sum(r[0] for r in rows) / 1e6:.2f} s in all)",
                ["module", "self", "with its imports"],
                [[name, fmt_seconds(own / 1e6), fmt_seconds(total / 1e6)] for own, total, name in rows[:top]])


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--import-only", action="store_true")
    args = parser.parse_args()
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        (work / "cube.csg").write_text(CSG)
        (work / "cube.scad").write_text(SCAD)
        (work / "peer.py").write_text(PEER)
        import_profile(work, env)
        if args.import_only:
            return 0
        contenders = {
            "isocsg render (CLI)": [sys.executable, "-m", "isocsg", "render", str(work / "cube.csg"),
                                    "-o", str(work / "isocsg.png"), "--no-progress"],
        }
        openscad = shutil.which("openscad")
        display = bool(os.environ.get("DISPLAY"))
        if openscad and display:
            contenders["openscad --preview"] = [openscad, "--preview", "--imgsize=512,512", "-o",
                                                str(work / "openscad.png"), str(work / "cube.scad")]
        if display:
            contenders["manifold3d + pyvista"] = [sys.executable, str(work / "peer.py"), str(work / "peer.png")]
        results = {}
        for name, argv in contenders.items():
            try:
                results[name] = medians(argv, env, args.repeats)
            except (RuntimeError, OSError) as exc:
                print(f"{name}: not measured ({exc})")
        if not display:
            print("no display (DISPLAY unset): OpenSCAD's preview and pyvista not measured; run under xvfb-run -a\n")
    ours = results.get("isocsg render (CLI)")
    rows = []
    for name, (wall, cpu) in results.items():
        ratio = "" if ours is None or name.startswith("isocsg") else f"{ours[0] / wall:.2f}x / {ours[1] / cpu:.2f}x"
        rows.append([name, fmt_seconds(wall), fmt_seconds(cpu), ratio])
    print_table(f"cube(1) at 512 x 512, first image of a new process (medians of {args.repeats})",
                ["contender", "wall", "CPU", "isocsg / it (wall / CPU)"], rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
