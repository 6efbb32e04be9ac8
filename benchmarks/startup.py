"""Start-up benchmark: a small model's first image from a fresh process.

Run from the repository root (OpenSCAD's preview and pyvista need a display; ``xvfb-run``
gives one)::

    xvfb-run -a python benchmarks/startup.py             # the default models, 5 repeats of each
    xvfb-run -a python benchmarks/startup.py --repeats 9
    xvfb-run -a python benchmarks/startup.py --models all      # cube(1) and every Basics example
    xvfb-run -a python benchmarks/startup.py --models cube,CSG,example019
    xvfb-run -a python benchmarks/startup.py --root /tmp/old   # another checkout's isocsg (before / after)
    python benchmarks/startup.py --import-only           # isocsg's imports only (python -X importtime)
    xvfb-run -a python benchmarks/startup.py --realworld DIR   # people's models: warm isocsg against OpenSCAD
    xvfb-run -a python benchmarks/startup.py --realworld DIR --before /tmp/old   # and an older checkout beside it

Each contender draws a model at 512 x 512 to a PNG in a new process, the way a user's command
does. The default models: ``cube(1)``, ``sphere(10)``, ``cylinder(h=10, r=3)``, a cube minus a
sphere, OpenSCAD's ``Basics/CSG.scad`` (6 leaves) and ``Old/example019.scad`` (41 leaves, round
ones). ``--models`` names others (OpenSCAD's own examples, ``examples/Basics`` and
``examples/Old`` of its installation, by file name; ``all``: every Basics example isocsg loads):

- ``isocsg render model.scad -o out.png`` (the command line, which runs ``openscad`` to read a
  ``.scad`` file that is not plain; kernels already in numba's cache, bytecode already written
  as an installed package has it: ``PYTHONDONTWRITEBYTECODE`` is dropped for the child), cold:
  ``ISOCSG_SERVER=0``, the whole command in the new process;
- the same with ``ISOCSG_JIT=numba`` (every kernel compiled, as before :mod:`isocsg._jit`);
- the same, warm: through the command line's server (``isocsg server start`` once before the
  first model, in a private runtime directory, ``isocsg server stop`` after the last); its CPU
  seconds are the client's plus those of the server's child that ran the command (``isocsg
  server status``);
- ``openscad --preview -o out.png model.scad`` (OpenSCAD's preview: OpenCSG, no CGAL);
- for the cube, manifold3d + pyvista: a Python process that imports both, builds the cube and
  saves an off-screen render.

``--realworld DIR`` times people's own models instead: those of the sample list of
``benchmarks/openscad_realworld.py`` (under ``DIR``, laid out as that script says) whose ``.csg``
export has 1 to 292 leaves (primitives, extrusions, imports), the issue's range; each drawn at
512 x 512 by the warm server and by OpenSCAD's preview (``--repeats`` runs after one, default 1
here; at most ``--timeout`` seconds a run); with ``--before ROOT`` another checkout's isocsg too,
through a server of its own, each model drawn by each contender in turn (the machine's load
falls on all alike). Printed: a row per model, then the medians and the median and quartiles of
each isocsg's per-model ratio to OpenSCAD (and of the new to the old).

Printed: medians over the repeats of wall-clock and CPU seconds (user + system of the child
process and its children), and the cold and the warm isocsg's ratios to each of the others (> 1:
isocsg is slower),
with the machine's load average before and after. The load shows in wall-clock times; CPU
seconds are steadier. ``--import-only`` prints
the modules that take most of isocsg's import time for the command (self time, from
``-X importtime``).
"""

from __future__ import annotations

import argparse
import glob
import os
import re
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
#: Small models written for the run (``cube`` also as ``.csg`` for ``--import-only``).
BUILT_IN = {
    "cube": "cube(1);\n",
    "sphere": "sphere(10);\n",
    "cylinder": "cylinder(h=10, r=3);\n",
    "difference": "difference() { cube(10, center=true); sphere(6.5); }\n",
}
DEFAULT_MODELS = "cube,sphere,cylinder,difference,CSG,example019"
EXAMPLES = "/usr/share/openscad/examples"
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


def timed(argv: list[str], env: dict[str, str], cwd: str | None = None) -> tuple[float, float]:
    """Wall-clock and CPU seconds (user + system) of one child process and its children; raises if it fails."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    proc = subprocess.run(argv, env=env, capture_output=True, text=True, cwd=cwd)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        raise RuntimeError(f"{argv[0]} exited {proc.returncode}: {proc.stderr.strip().splitlines()[-1:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def medians(argv: list[str], env: dict[str, str], repeats: int, cwd: str | None = None) -> tuple[float, float]:
    """Median wall-clock and CPU seconds over ``repeats`` runs (after one run that warms disk caches)."""
    timed(argv, env, cwd)
    runs = [timed(argv, env, cwd) for _ in range(repeats)]
    return statistics.median(r[0] for r in runs), statistics.median(r[1] for r in runs)


def served_medians(argv: list[str], env: dict[str, str], repeats: int, cwd: str | None = None) -> tuple[float, float]:
    """Median wall-clock and CPU seconds of a command the server runs: the client's CPU time plus
    that of the server's child (after one run, as :func:`medians`)."""
    timed(argv, env, cwd)
    runs = []
    for _ in range(repeats):
        before = commands_cpu(env)
        wall, cpu = timed(argv, env, cwd)
        runs.append((wall, cpu + commands_cpu(env) - before))
    return statistics.median(r[0] for r in runs), statistics.median(r[1] for r in runs)


def commands_cpu(env: dict[str, str]) -> float:
    """CPU seconds of the commands the running server has finished (waits for those running)."""
    deadline = time.monotonic() + 30
    while True:
        status = subprocess.run([sys.executable, "-m", "isocsg", "server", "status"], env=env,
                                capture_output=True, text=True, cwd="/").stdout
        found = re.search(r"this installation\).*? (\d+) running, ([\d.]+) s CPU in commands", status)
        if found is None:
            raise RuntimeError(f"no server answers: {status.strip()}")
        if found.group(1) == "0" or time.monotonic() > deadline:
            return float(found.group(2))
        time.sleep(0.05)


def start_server(env: dict[str, str]) -> bool:
    """Start the command line's server of ``env`` (waits until it is warm); whether it runs."""
    proc = subprocess.run([sys.executable, "-m", "isocsg", "server", "start"], env=env, capture_output=True,
                          text=True, cwd="/")  # not a checkout's directory: its isocsg would come first
    print(proc.stdout.strip() or f"no server: {proc.stderr.strip()}")
    return proc.returncode == 0


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


def models(work: Path, env: dict[str, str], only: str) -> dict[str, Path]:
    """The models by name: the built-in ones and OpenSCAD's examples that isocsg loads (each tried once)."""
    found: dict[str, Path] = {}
    for name, text in BUILT_IN.items():
        if only == "all" and name == "cube" or name in only.split(","):
            (work / f"{name}.scad").write_text(text)
            found[name] = work / f"{name}.scad"
    pattern = "Basics/*.scad" if only == "all" else "*/*.scad"
    for path in sorted(glob.glob(os.path.join(EXAMPLES, pattern))):
        name = Path(path).stem
        if only != "all" and name not in only.split(","):
            continue
        argv = [sys.executable, "-m", "isocsg", "render", path, "-o", str(work / "try.png"), "--no-progress"]
        proc = subprocess.run(argv, env=env, capture_output=True, text=True, cwd=str(Path(path).parent))
        if proc.returncode == 0:
            found[name] = Path(path)
        else:
            print(f"{name}: left out ({(proc.stderr.strip().splitlines() or ['?'])[-1]})")
    return found


COLD, WARM = "isocsg render", "isocsg render, warm server"


def contenders(model: Path, work: Path, cube: bool, served: dict[str, str] | None,
               ) -> dict[str, tuple[list[str], dict[str, str]]]:
    """Command lines (and extra environment) that draw ``model``."""
    isocsg = [sys.executable, "-m", "isocsg", "render", str(model), "-o", str(work / "isocsg.png"), "--no-progress"]
    found = {COLD: (isocsg, {}), "isocsg render, ISOCSG_JIT=numba": (isocsg, {"ISOCSG_JIT": "numba"})}
    if served is not None:
        found[WARM] = (isocsg, served)
    openscad = shutil.which("openscad")
    display = bool(os.environ.get("DISPLAY"))
    if openscad and display:
        found["openscad --preview"] = ([openscad, "--preview", "--imgsize=512,512", "-o", str(work / "openscad.png"),
                                        str(model)], {})
    if display and cube:
        found["manifold3d + pyvista"] = ([sys.executable, str(work / "peer.py"), str(work / "peer.png")], {})
    return found


def measure(name: str, model: Path, work: Path, env: dict[str, str], served: dict[str, str] | None,
            repeats: int) -> list[list[str]]:
    """The table's rows of one model: each contender's medians, and the cold and warm isocsg's
    ratios to the others."""
    results = {}
    for who, (argv, extra) in contenders(model, work, name == "cube", served).items():
        timing = served_medians if who == WARM else medians
        try:
            results[who] = timing(argv, {**env, **extra}, repeats, cwd=str(model.parent))
        except (RuntimeError, OSError) as exc:
            print(f"{name}, {who}: not measured ({exc})")
    rows = []
    for who, (wall, cpu) in results.items():
        ratios = []
        for ours in (COLD, WARM):
            mine = results.get(ours)
            mine_too = who.startswith("isocsg render")
            ratios.append("" if mine is None or mine_too else f"{mine[0] / wall:.2f}x / {mine[1] / cpu:.2f}x")
        rows.append([name, who, fmt_seconds(wall), fmt_seconds(cpu), *ratios])
    return rows


LEAF = re.compile(r"\b(cube|sphere|cylinder|polyhedron|linear_extrude|rotate_extrude|import|surface)\(")
REALWORLD_LEAVES = (1, 292)


def realworld_models(root: Path, work: Path) -> list[tuple[str, Path, int]]:
    """The sample's models under ``root`` with 1..292 leaves in their ``.csg`` export: (name, path, leaves)."""
    sample = ROOT / "benchmarks" / "openscad_realworld_sample.txt"
    found = []
    for line in sample.read_text().splitlines():
        if not line.strip():
            continue
        repo, _commit, path = line.strip().split(maxsplit=2)
        model = root / repo.replace("/", "+") / path
        if not model.exists():
            continue
        csg = work / "export.csg"
        csg.unlink(missing_ok=True)
        try:
            subprocess.run(["openscad", "-o", str(csg), str(model)], capture_output=True, cwd=str(model.parent),
                           timeout=60)
        except subprocess.TimeoutExpired:
            continue
        leaves = len(LEAF.findall(csg.read_text())) if csg.exists() else 0
        if REALWORLD_LEAVES[0] <= leaves <= REALWORLD_LEAVES[1]:
            found.append((f"{repo}/{path}", model, leaves))
    return found


def realworld(root: Path, work: Path, servers: dict[str, dict[str, str]], repeats: int, timeout: float) -> None:
    """Warm isocsg (one or two checkouts, each through its own server: ``servers`` maps a name to
    the command's environment) against OpenSCAD's preview on people's models, model by model in
    turn (see the module's docstring)."""
    openscad = shutil.which("openscad")
    if openscad is None or not os.environ.get("DISPLAY"):
        print("--realworld needs openscad and a display (xvfb-run -a)")
        return
    names = [*servers, "openscad"]
    rows: list[list[str]] = []
    timings: list[dict[str, float]] = []
    for name, model, leaves in realworld_models(root, work):
        argvs = {who: ([sys.executable, "-m", "isocsg", "render", str(model), "-o", str(work / "isocsg.png"),
                        "--no-progress"], run_env) for who, run_env in servers.items()}
        argvs["openscad"] = ([openscad, "--preview", "--imgsize=512,512", "-o", str(work / "openscad.png"),
                              str(model)], servers[next(iter(servers))])
        times: dict[str, float | str] = {}
        for who, (argv, run_env) in argvs.items():
            try:
                runs = [time_limited(argv, run_env, str(model.parent), timeout) for _ in range(repeats + 1)][1:]
                times[who] = statistics.median(runs)
            except (RuntimeError, OSError, subprocess.TimeoutExpired) as exc:
                times[who] = type(exc).__name__
        cells = [fmt_seconds(t) if isinstance(t, float) else t for t in times.values()]
        done = {k: v for k, v in times.items() if isinstance(v, float)}
        shown = [f"{done[w] / done['openscad']:.2f}x" if w in done and "openscad" in done else "" for w in servers]
        rows.append([name, str(leaves), *cells, *shown])
        if len(done) == len(names):
            timings.append(done)
        print(" | ".join(rows[-1]), flush=True)
    print_table(f"people's models at 512 x 512, warm isocsg against OpenSCAD's preview ({len(rows)} models; "
                f"medians of {repeats} after one)",
                ["model", "leaves", *names, *(f"{w} / openscad" for w in servers)], rows)
    if not timings:
        return
    theirs = fmt_seconds(statistics.median(t["openscad"] for t in timings))
    print(f"{len(timings)} models drawn by all: median openscad {theirs}")
    for who in servers:
        ratios = sorted(t[who] / t["openscad"] for t in timings)
        q = statistics.quantiles(ratios, n=4) if len(ratios) > 1 else [ratios[0]] * 3
        print(f"  {who}: median {fmt_seconds(statistics.median(t[who] for t in timings))}; {who} / openscad per model: "
              f"median {statistics.median(ratios):.2f}x, quartiles {q[0]:.2f}x-{q[2]:.2f}x, "
              f"{sum(r <= 1 for r in ratios)} at or below 1x")
    if len(servers) == 2:
        a, b = servers
        ratios = sorted(t[a] / t[b] for t in timings)
        print(f"  {a} / {b} per model: median {statistics.median(ratios):.2f}x")


def time_limited(argv: list[str], env: dict[str, str], cwd: str, timeout: float) -> float:
    """Wall-clock seconds of one run (raises if it fails or takes longer than ``timeout``)."""
    t0 = time.perf_counter()
    proc = subprocess.run(argv, env=env, capture_output=True, text=True, cwd=cwd, timeout=timeout)
    if proc.returncode != 0:
        raise RuntimeError(f"{argv[0]} exited {proc.returncode}")
    return time.perf_counter() - t0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--import-only", action="store_true")
    parser.add_argument("--root", type=Path, default=ROOT, help="the checkout whose isocsg is timed")
    parser.add_argument("--models", default=DEFAULT_MODELS,
                        help=f"comma-separated names, or all (default: {DEFAULT_MODELS})")
    parser.add_argument("--realworld", type=Path, metavar="DIR",
                        help="people's models (benchmarks/openscad_realworld.py's sample under DIR) instead")
    parser.add_argument("--timeout", type=float, default=30.0, help="--realworld: seconds a run may take")
    parser.add_argument("--before", type=Path, metavar="ROOT",
                        help="--realworld: also another checkout's isocsg (its own server), model by model in turn")
    args = parser.parse_args()
    if args.realworld is not None and "--repeats" not in sys.argv:
        args.repeats = 1
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONDONTWRITEBYTECODE", "ISOCSG_JIT")}
    env["PYTHONPATH"] = str(args.root) + os.pathsep + os.environ.get("PYTHONPATH", "")
    env["ISOCSG_SERVER"] = "0"
    if not os.environ.get("DISPLAY"):
        print("no display (DISPLAY unset): OpenSCAD's preview and pyvista not measured; run under xvfb-run -a\n")
    rows = []
    load_before = os.getloadavg()
    with tempfile.TemporaryDirectory() as tmp, tempfile.TemporaryDirectory(prefix="isrv-", dir="/tmp") as runtime:
        work = Path(tmp)
        (work / "cube.csg").write_text(CSG)
        (work / "peer.py").write_text(PEER)
        if args.realworld is None:
            import_profile(work, env)
        if args.import_only:
            return 0
        served: dict[str, str] | None = {"ISOCSG_SERVER": "1", "ISOCSG_RUNTIME_DIR": runtime}
        if not start_server({**env, **served}):
            served = None
        try:
            if args.realworld is not None:
                if served is not None:
                    servers: dict[str, dict[str, str]] = {"isocsg": {**env, **served}}
                    if args.before is not None:  # a second checkout's own server, in a directory of its own
                        other = tempfile.mkdtemp(prefix="isrv-", dir="/tmp")
                        before = {**env, "PYTHONPATH": str(args.before) + os.pathsep + os.environ.get("PYTHONPATH", ""),
                                  "ISOCSG_SERVER": "1", "ISOCSG_RUNTIME_DIR": other}
                        if start_server(before):
                            servers["before"] = before
                    try:
                        realworld(args.realworld, work, servers, args.repeats, args.timeout)
                    finally:
                        if "before" in servers:
                            subprocess.run([sys.executable, "-m", "isocsg", "server", "stop"], env=servers["before"],
                                           capture_output=True, cwd="/")
                return 0
            for name, model in models(work, env, args.models).items():
                rows += measure(name, model, work, env, served, args.repeats)
        finally:
            if served is not None:
                subprocess.run([sys.executable, "-m", "isocsg", "server", "stop"], env={**env, **served},
                               capture_output=True, cwd="/")
    load = ", ".join(f"{a:.1f} -> {b:.1f}" for a, b in zip(load_before, os.getloadavg()))
    print_table(f"first image of a new process at 512 x 512 (medians of {args.repeats}; isocsg from {args.root}; "
                f"load average 1/5/15 min before -> after: {load}; {os.cpu_count()} cores)",
                ["model", "contender", "wall", "CPU", "cold isocsg / it (wall / CPU)", "warm isocsg / it"], rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
