"""Preview benchmark: OpenSCAD's own preview, isocsg and manifold3d + pyvista on models of growing size.

Run from the repository root::

    python benchmarks/preview.py             # every model, 3 repeats
    python benchmarks/preview.py --quick     # the smaller models, 1 repeat

Each model is an OpenSCAD file written by this script (plates with n x n holes in loops, from 17
to 1025 leaves; intersections of unions, whose sum-of-products form OpenSCAD's preview must build,
up to the size where it gives up), plus the corpus models named by ``--corpus``. Per model, each
peer runs in a fresh process, end to end, at 512 x 512:

- ``openscad``: ``openscad --preview -o view.png`` on one virtual X display (Xvfb, started once, so
  its start-up is not counted); "gave up" when OpenSCAD prints that its normalised tree grew past
  its limit (the image then lacks the model);
- ``isocsg render``: the command line, ``isocsg render model.scad -o view.png`` (start-up, the
  ``openscad -o model.csg`` conversion, loading, the first image);
- ``isocsg view``: a preview session (what ``isocsg view`` keeps running): its first view (kernels
  loaded, the model read), then later views from other angles (the median of four), and the
  session's peak memory;
- ``manifold + pyvista``: the lowered model tessellated at 64 segments and combined by manifold3d
  (``isocsg.to_manifold``), then pyvista's off-screen first frame.

Printed: medians over repeats, peak resident memory, and each peer's time over isocsg's (above
1: isocsg is faster).
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from _common import fmt_seconds, print_table, run_child  # noqa: E402

SIZE = 512


def plate(n: int) -> str:
    """A plate with n x n round holes, written with loops (n * n + 1 leaves)."""
    return (f"difference() {{\n  cube([{n + 1}, {n + 1}, 1]);\n"
            f"  for (i = [1:{n}], j = [1:{n}]) translate([i, j, -1]) cylinder(r = 0.3, h = 3, $fn = 96);\n}}\n")


def products(k: int, n: int) -> str:
    """The intersection of k unions of n spheres: n**k products in OpenSCAD's normal form."""
    unions = "\n".join(
        f"  union() {{ for (i = [0:{n - 1}]) translate([i * 0.25, {u} * 0.2, 0]) sphere(r = 1.2, $fn = 96); }}"
        for u in range(k))
    return f"intersection() {{\n{unions}\n}}\n"


MODELS = {
    "plate 2x2": plate(2), "plate 4x4": plate(4), "plate 8x8": plate(8), "plate 16x16": plate(16),
    "plate 32x32": plate(32),
    "products 3x20": products(3, 20), "products 3x60": products(3, 60),
}
QUICK = ("plate 2x2", "plate 8x8", "products 3x60")

ISOCSG_VIEW = f"""
import json, resource, sys, time
t0 = time.perf_counter()
from isocsg.preview import OrbitView, PreviewSession
session = PreviewSession(sys.argv[1], watch=False)
first = session.initial_view()
view = lambda az: OrbitView(first.azimuth + az, first.elevation, 1.0, {SIZE}, {SIZE})
session.render(view(0.0))
t1 = time.perf_counter()
later = []
for az in (20.0, 40.0, 60.0, 80.0):
    s = time.perf_counter(); session.render(view(az)); later.append(time.perf_counter() - s)
later.sort()
print(json.dumps({{"first": t1 - t0, "later": (later[1] + later[2]) / 2,
                  "maxrss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}}))
"""

MANIFOLD_PYVISTA = f"""
import json, os, resource, sys, time
os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
t0 = time.perf_counter()
import isocsg, numpy as np, pyvista as pv
solid = isocsg.load_openscad(sys.argv[1])
mesh = isocsg.to_manifold(solid, resolution=64).to_mesh()
faces = np.hstack([np.full((len(mesh.tri_verts), 1), 3), mesh.tri_verts]).ravel()
plotter = pv.Plotter(off_screen=True, window_size=({SIZE}, {SIZE}))
plotter.add_mesh(pv.PolyData(np.asarray(mesh.vert_properties[:, :3]), faces), color="white")
plotter.screenshot(sys.argv[2])
print(json.dumps({{"first": time.perf_counter() - t0,
                  "maxrss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}}))
"""


def _timed(argv: list[str], env: dict[str, str], timeout: float) -> tuple[float | None, str, float]:
    """Wall time of a fresh process, its status, and its peak memory in MB."""
    t0 = time.perf_counter()
    records, status, peak = run_child(argv, timeout, env=env)
    return (time.perf_counter() - t0 if status == "ok" else None), status, peak


def _openscad(model: Path, env: dict[str, str], timeout: float) -> tuple[float | None, str, float]:
    """``openscad --preview``: wall time, and "gave up" when its normalised tree outgrew its limit."""
    out = model.with_suffix(".openscad.png")
    t0 = time.perf_counter()
    run = subprocess.run(["openscad", "--preview", f"--imgsize={SIZE},{SIZE}", "-o", str(out), str(model)],
                         env=env, capture_output=True, text=True, timeout=timeout)
    seconds = time.perf_counter() - t0
    if "Normalized tree is growing past" in run.stderr or "Normalized tree is growing past" in run.stdout:
        return seconds, "gave up", 0.0
    return (seconds, "ok", 0.0) if run.returncode == 0 else (None, f"exit {run.returncode}", 0.0)


def _median(values: list[float | None]) -> float | None:
    good = [v for v in values if v is not None]
    return statistics.median(good) if good else None


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="the smaller models, one repeat")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--timeout", type=float, default=300.0)
    parser.add_argument("--corpus", nargs="*", default=[], help="more .scad models to time")
    args = parser.parse_args()
    repeats = 1 if args.quick else args.repeats
    names = QUICK if args.quick else tuple(MODELS)
    env = dict(os.environ)
    xvfb = None
    if shutil.which("openscad") and shutil.which("Xvfb") and "DISPLAY" not in env:
        xvfb = subprocess.Popen(["Xvfb", ":97", "-screen", "0", "1024x768x24"], stderr=subprocess.DEVNULL)
        env["DISPLAY"] = ":97"
        time.sleep(1.0)
    have_openscad = shutil.which("openscad") is not None and "DISPLAY" in env
    isocsg_cli = [sys.executable, "-m", "isocsg"]
    subprocess.run([*isocsg_cli, "warmup"], capture_output=True, check=False)  # kernels compiled, not timed
    rows = []
    try:
        with tempfile.TemporaryDirectory() as tmp:
            models = [(n, Path(tmp) / f"{n.replace(' ', '_')}.scad") for n in names]
            for _, path in models:
                path.write_text(MODELS[path.stem.replace("_", " ")])
            models += [(Path(c).stem, Path(c)) for c in args.corpus]
            for name, path in models:
                osc, cli, first, later, mp, mem_view, mem_mp, status = [], [], [], [], [], 0.0, 0.0, "ok"
                for _ in range(repeats):
                    if have_openscad:
                        t, status, _ = _openscad(path, env, args.timeout)
                        osc.append(t)
                    t, _, _ = _timed([*isocsg_cli, "render", str(path), "-o", str(Path(tmp) / "i.png"),
                                      "--size", f"{SIZE}x{SIZE}", "--no-progress"], env, args.timeout)
                    cli.append(t)
                    records, _, peak = run_child([sys.executable, "-c", ISOCSG_VIEW, str(path)], args.timeout, env=env)
                    if records:
                        first.append(records[0]["first"])
                        later.append(records[0]["later"])
                        mem_view = max(mem_view, peak)
                    records, _, peak = run_child([sys.executable, "-c", MANIFOLD_PYVISTA, str(path),
                                                  str(Path(tmp) / "m.png")], args.timeout, env=env)
                    if records:
                        mp.append(records[0]["first"])
                        mem_mp = max(mem_mp, peak)
                o, c, f, later_view, m = (_median(x) for x in (osc, cli, first, later, mp))
                ratio = lambda peer, own: f"{peer / own:.2f}" if peer and own else "-"  # noqa: E731
                rows.append([name, fmt_seconds(o) + ("" if status == "ok" else f" ({status})"), fmt_seconds(c),
                             ratio(o, c), fmt_seconds(f), fmt_seconds(later_view), f"{mem_view:.0f} MB",
                             fmt_seconds(m), f"{mem_mp:.0f} MB", ratio(m, f)])
                print(f"{name}: done", file=sys.stderr, flush=True)
    finally:
        if xvfb is not None:
            xvfb.terminate()
    print_table(
        f"Preview at {SIZE} x {SIZE}, medians of {repeats} fresh processes each "
        "(ratios: the peer's time over isocsg's; above 1, isocsg is faster)",
        ["model", "openscad --preview", "isocsg render", "openscad/isocsg", "isocsg view: first", "later views",
         "view memory", "manifold+pyvista", "its memory", "m+p / isocsg first"],
        rows)


if __name__ == "__main__":
    main()
