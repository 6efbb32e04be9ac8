"""Load rate of real-world OpenSCAD models: people's own models from public repositories.

Usage, from the repository root::

    python benchmarks/openscad_realworld.py DIR                # the sample list below, under DIR
    python benchmarks/openscad_realworld.py DIR --scan         # every .scad file under DIR
    python benchmarks/openscad_realworld.py DIR --polygonal    # read_openscad(..., polygonal=True)
    python benchmarks/openscad_realworld.py DIR --heavy --timeout 60   # the heavy sample, load only

``DIR`` holds one folder per repository, named ``owner+name`` (``git archive`` of the commit
given in the sample list, e.g. ``git --git-dir=REPO.git archive COMMIT | tar -x -C DIR/owner+name``;
where a mirror lacks some large blobs, ``git archive`` stops at them: write the files one by one
from ``git ls-tree -r`` and ``git cat-file --batch``, skipping the missing ones).
The sample list, ``benchmarks/openscad_realworld_sample.txt``, has one model per line: ``owner/name
commit path``; it names 114 models from 15 repositories of people's own models that OpenSCAD
2021.01 exports as non-empty 3D solids. How it was drawn: 19 repositories found by name
("openscad", "3d-printing", ...); in each, up to 14 ``.scad`` files at random (seeded by the
repository's name; paths with ``lib``, ``libraries``, ``modules``, ``include``, ``utils``,
``common``, ``threads``, ``BOSL``, ``MCAD``, ``NopSCADlib`` left out), 16 more in the 8
repositories with the best yield; kept when ``openscad -o model.stl`` finished within 60 s (on a
loaded machine) with a non-empty 3D solid. Of 356 files tried, 85 were libraries of modules or
2D drawings ("top level object is empty" or "not a 3D object"), about 95 timed out, the rest
failed on a missing library, file or syntax error. The model files themselves are not in this repository
(their licences are their authors').

The heavy sample, ``benchmarks/openscad_realworld_heavy.txt`` (``--heavy``, which implies
``--load-only``), names 110 other models of the same 19 repositories (at their mirrored commits):
per repository, the ``.scad`` files outside the sample list and outside the library paths above,
shuffled (``random.Random("heavy:" + "owner+name")``), the first 16 tried; kept when ``openscad -o
model.csg`` (30 s) gives a tree with a 3D node and no include or library is missing (213 of 304);
of those, shuffled again (``random.Random("heavy-sample")``), at most 8 a repository, the first
110. No STL is needed (the heavy models are those whose STL export takes OpenSCAD minutes): with
``--load-only`` a model counts when its ``.csg`` export (cached under ``DIR/_csg``) has a 3D node
(cube, sphere, cylinder, polyhedron, an extrusion, ``surface`` or a mesh import), and loads when
``read_openscad`` returns within ``--timeout`` seconds; no volume.

Per model: OpenSCAD's STL (``openscad -o model.stl``, cached under ``DIR/_stl``), then
``isocsg.openscad.read_openscad`` and ``isocsg.volume`` in a child process stopped after
``--timeout`` seconds. Printed: the load rate, the histogram of first refusals (the kind of node
that stopped each model, and in brackets the models where a second try with that node left out
loads: where it is the only blocker), and the agreement of the volumes with the STL's.

OpenSCAD's STL is a tessellation at the model's ``$fn``/``$fa``/``$fs`` (by default 12 degrees
and 2 units a segment: a cylinder of radius 3 is a 9-gon, 7 % below the disc), so exact round
solids differ from it by its tessellation error; polygonal models agree to its printed digits.
"""

from __future__ import annotations

import argparse
import collections
import multiprocessing as mp
import re
import statistics
import sys
import time
import warnings
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from _common import openscad_export  # noqa: E402

SAMPLE = HERE / "openscad_realworld_sample.txt"
HEAVY = HERE / "openscad_realworld_heavy.txt"


def _export(model: Path, root: Path, suffix: str, timeout: float) -> Path | None:
    """``openscad -o model.SUFFIX``, cached under ``DIR/_SUFFIX``; None when it timed out or wrote nothing."""
    out = root / f"_{suffix}" / (str(model.relative_to(root)).replace("/", "__") + f".{suffix}")
    return out if openscad_export(model, out, timeout) else None


def _stl_volume(model: Path, root: Path, timeout: float) -> float | None:
    import trimesh

    out = _export(model, root, "stl", timeout)
    if out is None or out.stat().st_size < 200:
        return None
    mesh = trimesh.load(str(out), force="mesh")
    return float(abs(mesh.volume))


_SOLID_NODE = re.compile(r"\b(cube|sphere|cylinder|polyhedron|linear_extrude|rotate_extrude|surface)\s*\("
                         r"|import\([^)]*\.(stl|off|obj|3mf|amf)\b", re.IGNORECASE)


def _has_3d_tree(model: Path, root: Path, timeout: float) -> bool:
    """Whether ``openscad -o model.csg`` (cached under ``DIR/_csg``) gives a tree with a 3D node."""
    out = _export(model, root, "csg", timeout)
    return out is not None and _SOLID_NODE.search(out.read_text(errors="replace")) is not None


def _kind(message: str) -> str:
    """A short name for the first refusal: the node and the reason, numbers and paths left out."""
    text = message.split("\n")[0]
    text = re.sub(r"^.*?\.scad:\d+: ", "", text)
    text = re.sub(r"^\S+:\d+: ", "", text)
    text = re.sub(r"; load_openscad\(.*$", "", text)
    text = re.sub(r"[-+]?\d[\d.e+-]*", "#", text)
    text = re.sub(r"'[^']*'|\"[^\"]*\"", "'…'", text)
    return text[:110]


def _load(path: str, polygonal: bool, skip: bool, queue: mp.Queue, measure: bool = True) -> None:  # in the child
    warnings.simplefilter("ignore")
    try:
        import isocsg
        from isocsg.openscad import read_openscad

        kwargs = {"polygonal": True} if polygonal else {}
        model = read_openscad(path, skip_unsupported=skip, **kwargs)
        if skip:
            queue.put(("ok", None, sorted(model.skipped)))
            return
        vol = isocsg.volume(model.solid) if measure else None
        queue.put(("ok", vol, getattr(model, "polygonal", ())))
    except Exception as exc:  # noqa: BLE001 - the benchmark records every refusal
        queue.put(("fail", type(exc).__name__, _kind(str(exc))))


def _child(path: Path, polygonal: bool, skip: bool, timeout: float, measure: bool = True) -> tuple[str, object, object]:
    ctx = mp.get_context("fork")
    queue: mp.Queue = ctx.Queue()
    proc = ctx.Process(target=_load, args=(str(path), polygonal, skip, queue, measure))
    proc.start()
    try:
        return queue.get(timeout=timeout)  # type: ignore[no-any-return]
    except Exception:  # noqa: BLE001 - queue.Empty: out of time
        return ("fail", "Timeout", f"no result within {timeout:g} s")
    finally:
        proc.kill()
        proc.join()


def _models(root: Path, scan: bool, sample: Path) -> list[Path]:
    if scan:
        return sorted(root.glob("**/*.scad"))
    out = []
    for line in sample.read_text().splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        repo, _commit, path = line.split(maxsplit=2)
        out.append(root / repo.replace("/", "+") / path)
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("root", type=Path)
    ap.add_argument("--scan", action="store_true", help="every .scad file under ROOT instead of the sample list")
    ap.add_argument("--polygonal", action="store_true", help="read_openscad(..., polygonal=True)")
    ap.add_argument("--timeout", type=float, default=120.0, help="seconds per model (load and volume)")
    ap.add_argument("--only", default="", help="regular expression on the model path")
    ap.add_argument("--no-volume", action="store_true", help="load only (no isocsg.volume): the load rate alone")
    ap.add_argument("--sample", type=Path, default=SAMPLE, help="the sample list (owner/name commit path lines)")
    ap.add_argument("--heavy", action="store_true", help="the heavy sample list (implies --load-only)")
    ap.add_argument("--load-only", action="store_true",
                    help="no STL: a model counts when openscad -o model.csg gives a 3D tree; load only")
    args = ap.parse_args()
    if args.heavy:
        args.sample, args.load_only = HEAVY, True
    (args.root / "_stl").mkdir(exist_ok=True)
    (args.root / "_csg").mkdir(exist_ok=True)
    models = [m for m in _models(args.root, args.scan, args.sample) if re.search(args.only, str(m))]
    import isocsg  # loaded and warmed once here: each model's child process is a fork of this one
    import isocsg.openscad

    isocsg.volume(isocsg.Sphere((0, 0, 0), 1) - isocsg.Box((0, 0, 0), (1, 1, 1)))
    first: collections.Counter[str] = collections.Counter()
    only: collections.Counter[str] = collections.Counter()
    errors: list[float] = []
    loaded = 0
    counted = 0
    t_start = time.perf_counter()
    for model in models:
        if not model.exists():
            print(f"MISSING {model}")
            continue
        if args.load_only:
            ref = None
            if not _has_3d_tree(model, args.root, 120.0):
                print(f"NO-3D   {model}")
                continue
        else:
            ref = _stl_volume(model, args.root, 600.0)
            if ref is None or ref <= 0.0:
                print(f"NO-STL  {model}")
                continue
        counted += 1
        t0 = time.perf_counter()
        status, a, b = _child(model, args.polygonal, False, args.timeout, not (args.no_volume or args.load_only))
        dt = time.perf_counter() - t0
        if status == "ok":
            loaded += 1
            extra = f" polygonal {len(b)}" if b else ""  # type: ignore[arg-type]
            if a is None or ref is None:
                print(f"OK   {dt:6.1f}s {model}{extra}", flush=True)
                continue
            rel = abs(float(a) - ref) / ref  # type: ignore[arg-type]
            errors.append(rel)
            print(f"OK   {dt:6.1f}s rel {rel:9.2e} {model}{extra}", flush=True)
            continue
        key = f"{a}: {b}"
        first[key] += 1
        alone = ""
        if a not in ("Timeout", "OpenSCADError"):
            s2, _, skipped = _child(model, False, True, args.timeout)
            if s2 == "ok" and len(skipped) == 1:  # type: ignore[arg-type]
                only[key] += 1
                alone = " (only blocker)"
        print(f"FAIL {dt:6.1f}s {model}: {key}{alone}", flush=True)
    print(f"\n{loaded}/{counted} load ({100.0 * loaded / max(counted, 1):.1f} %), "
          f"{time.perf_counter() - t_start:.0f} s")
    print("\nfirst refusal (only blocker):")
    for key, n in first.most_common():
        print(f"  {n:3d} ({only[key]:3d})  {key}")
    if errors:
        errors.sort()
        within = {t: sum(e <= t for e in errors) for t in (1e-5, 1e-3, 5e-3, 1e-2, 5e-2)}
        print(f"\nvolume vs OpenSCAD's STL, {len(errors)} loaded models: median {statistics.median(errors):.2e}, "
              + ", ".join(f"<= {t:g}: {n}" for t, n in within.items())
              + f", worst {errors[-1]:.2e}")


if __name__ == "__main__":
    sys.exit(main())
