"""Mesh Boolean engines judged against the exact answer (docs/testing_engines.md).

Random trees from ``isocsg.testing.strategies`` (``trees``: spheres, boxes, cylinders, cones,
frusta, ellipsoids and tori on a coarse grid, coincident and touching faces, thin rods, discs
and plates; ``cube_fuzz``: manifold's fuzz domain of turned and moved unit cubes). Every leaf is
tessellated once by isocsg at ``--segments`` and the same leaf meshes go to each engine, so that
the engines differ only in their Booleans:

- manifold3d: ``Manifold`` operators ``+``, ``-``, ``^`` one pair at a time;
- trimesh: ``trimesh.boolean.union / difference / intersection`` with each available engine
  (``manifold`` here; Blender is not installed);
- pyvista: ``PolyData.boolean_union / boolean_difference / boolean_intersection`` (VTK's
  ``vtkBooleanOperationPolyDataFilter``), one pair at a time.

Each result is judged by ``isocsg.testing.compare_mesh`` (volume against the certified
tessellation bound, area and Hausdorff distance against the tessellation reference, topology).
The distributions are printed, and every case judged wrong is listed with its reproducer::

    python benchmarks/engines.py --n 200 --seed 1 [--fuzz 0.2] [--max-cubes 100] [--tol 1e-5] [--findings FILE]
"""

from __future__ import annotations

import argparse
import signal
import sys
import time
import warnings
from collections import Counter, defaultdict
from typing import Any

import numpy as np

from isocsg.csg.mesh import to_manifold
from isocsg.csg.program import OP_INTERSECTION, OP_UNION
from isocsg.csg.section import solid_program
from isocsg.testing import compare_mesh, reference, to_python
from isocsg.testing.compare import as_trimesh
from isocsg.testing.strategies import cube_fuzz, trees


def draw_trees(n: int, seed: int, fuzz: float, max_cubes: int, max_leaves: int) -> list[Any]:
    """``n`` distinct trees drawn by hypothesis (a seeded generate phase: the same list every run)."""
    from hypothesis import HealthCheck, Phase, given, settings
    from hypothesis import seed as hseed

    out: list[Any] = []
    seen: set[Any] = set()

    def collect(strategy: Any, count: int, s: int) -> None:
        before = len(out)
        if count <= 0:
            return
        @hseed(s)
        @settings(max_examples=count * 3, database=None, phases=[Phase.generate], deadline=None,
                  suppress_health_check=list(HealthCheck))
        @given(strategy)
        def run(t: Any) -> None:
            if t not in seen and len(out) < before + count and solid_program(t).n_leaves > 1:
                seen.add(t)
                out.append(t)

        run()
        del out[before + count:]

    n_fuzz = int(round(n * fuzz))
    collect(trees(max_leaves=max_leaves), n - n_fuzz, seed)
    if n_fuzz:
        collect(cube_fuzz(max_cubes=max_cubes), n_fuzz, seed + 1)
    return out


def evaluate(tree: Any, leaf_mesh: Any, combine: Any) -> Any:
    return solid_program(tree).evaluate(lambda i, p: leaf_mesh(i), combine)


def run_manifold(tree: Any, leaves: list[Any]) -> Any:
    def combine(op: int, xs: list[Any]) -> Any:
        out = xs[0]
        for x in xs[1:]:
            out = out + x if op == OP_UNION else (out ^ x if op == OP_INTERSECTION else out - x)
        return out

    return evaluate(tree, lambda i: leaves[i], combine)


def run_trimesh(tree: Any, leaves: list[Any], engine: str) -> Any:
    import trimesh

    def combine(op: int, xs: list[Any]) -> Any:
        xs = [x for x in xs]
        if op == OP_UNION:
            return trimesh.boolean.union(xs, engine=engine)
        if op == OP_INTERSECTION:
            return trimesh.boolean.intersection(xs, engine=engine)
        return trimesh.boolean.difference(xs, engine=engine)

    return evaluate(tree, lambda i: leaves[i], combine)


def run_pyvista(tree: Any, leaves: list[Any]) -> Any:
    def combine(op: int, xs: list[Any]) -> Any:
        out = xs[0]
        for x in xs[1:]:
            if op == OP_UNION:
                out = out.boolean_union(x)
            elif op == OP_INTERSECTION:
                out = out.boolean_intersection(x)
            else:
                out = out.boolean_difference(x)
            out = out.triangulate()  # VTK's output may hold polygons; its next input must not
        return out

    return evaluate(tree, lambda i: leaves[i], combine)


class EngineCrash(RuntimeError):
    """The engine killed the process it ran in (a segmentation fault)."""


def isolated(fn: Any, *args: Any, timeout: float = 120.0) -> Any:
    """``fn(*args)`` (a mesh) computed in a forked process: an engine that crashes (VTK's Booleans
    can end in a segmentation fault) or hangs becomes a finding instead of ending the run."""
    import multiprocessing as mp

    import trimesh

    ctx = mp.get_context("fork")
    recv, send = ctx.Pipe(duplex=False)

    def target() -> None:
        try:
            m = fn(*args)
            tm = as_trimesh(m) if m.n_cells else None
            send.send(("ok", None if tm is None else (np.asarray(tm.vertices), np.asarray(tm.faces))))
        except Exception as exc:  # noqa: BLE001 - handed to the parent
            send.send(("raised", f"{type(exc).__name__}: {exc}"))

    proc = ctx.Process(target=target)
    proc.start()
    res = recv.recv() if recv.poll(timeout) else None
    proc.join(5)
    if proc.is_alive():
        proc.kill()
        proc.join()
    if res is None:
        raise EngineCrash(f"crashed (exit code {proc.exitcode})" if proc.exitcode else f"hung over {timeout:.0f} s")
    if res[0] == "raised":
        raise RuntimeError(res[1])
    if res[1] is None:
        return trimesh.Trimesh(np.zeros((0, 3)), np.zeros((0, 3), int))
    return trimesh.Trimesh(res[1][0], res[1][1], process=False)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=20, help="number of trees (1000 for the full run)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--segments", type=int, default=32)
    ap.add_argument("--fuzz", type=float, default=0.2, help="share of trees from manifold's cube fuzz domain")
    ap.add_argument("--max-cubes", type=int, default=20)
    ap.add_argument("--max-leaves", type=int, default=5)
    ap.add_argument("--samples", type=int, default=1500)
    ap.add_argument("--tol", type=float, default=1e-5, help="relative accuracy of the reference figures")
    ap.add_argument("--engines", default="manifold3d,trimesh-manifold,pyvista")
    ap.add_argument("--budget", type=int, default=60, help="seconds for one tree's reference")
    ap.add_argument("--findings", default=None, help="write every wrong case with its reproducer here")
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    import faulthandler

    faulthandler.enable()  # an engine that crashes the process says where
    import pyvista as pv

    t0 = time.time()
    cases = draw_trees(args.n, args.seed, args.fuzz, args.max_cubes, args.max_leaves)
    print(f"{len(cases)} trees drawn in {time.time() - t0:.1f} s; segments {args.segments}")
    engines = args.engines.split(",")
    checks: dict[str, Counter[str]] = defaultdict(Counter)
    rel: dict[str, dict[str, list[float]]] = defaultdict(lambda: defaultdict(list))
    findings: list[str] = []

    def note(text: str) -> None:  # written as found: a run stopped early keeps its findings
        findings.append(text)
        if args.findings:
            with open(args.findings, "a") as fh:
                fh.write(text + "\n")
    skipped = 0

    def alarm(*_: Any) -> None:
        raise TimeoutError

    signal.signal(signal.SIGALRM, alarm)
    for k, tree in enumerate(cases):
        signal.alarm(args.budget)  # the reference's integration, not an engine, is what may run long
        try:
            ref = reference(tree, tol=args.tol)
        except TimeoutError:
            skipped += 1
            findings.append(f"# case {k}: reference over {args.budget} s, skipped\n{to_python(tree)}\n")
            continue
        finally:
            signal.alarm(0)
        prog = solid_program(tree)
        mf = [to_manifold(p, args.segments) for p in prog.leaves]
        size = float(np.max(ref.bounds[1] - ref.bounds[0]))
        for eng in engines:
            t1 = time.time()
            try:
                if eng == "manifold3d":
                    mesh = run_manifold(tree, mf)
                    mesh.num_tri()  # manifold3d evaluates lazily: time the Booleans, not the tree
                elif eng.startswith("trimesh-"):
                    mesh = run_trimesh(tree, [as_trimesh(m) for m in mf], eng.split("-", 1)[1])
                else:
                    mesh = isolated(run_pyvista, tree, [pv.wrap(as_trimesh(m)) for m in mf])
            except Exception as exc:  # noqa: BLE001 - an engine's failure is a finding
                crashed = isinstance(exc, EngineCrash)
                checks[eng]["crashed" if crashed else "raised"] += 1
                what = str(exc) if crashed else f"raised {type(exc).__name__}: {exc}"
                note(f"# case {k}, {eng}: {what}\n{to_python(tree)}\n")
                continue
            dt = time.time() - t1
            c = compare_mesh(mesh, tree, segments=args.segments, samples=args.samples, ref=ref, seed=k)
            checks[eng]["cases"] += 1
            checks[eng]["ok" if c.ok else "wrong"] += 1
            for name in c.wrong:
                checks[eng][f"wrong {name}"] += 1
            vol_rel = abs(c.volume_error) / ref.volume if ref.volume > 0 else abs(c.volume_error)
            rel[eng]["volume"].append(vol_rel)
            rel[eng]["area"].append(abs(c.area_error) / max(ref.area, 1e-300) if ref.area > 0 else abs(c.area_error))
            rel[eng]["hausdorff"].append(max(c.hausdorff_mesh_to_true, c.hausdorff_true_to_mesh) / size)
            rel[eng]["seconds"].append(dt)
            if not c.ok:
                note(f"# case {k}, {eng}: wrong {', '.join(c.wrong)}\n# "
                                + c.summary().replace("\n", "\n# ") + f"\n{to_python(tree)}\n")
        if (k + 1) % 20 == 0:
            report(engines, checks, rel, f"after {k + 1}/{len(cases)} trees, {time.time() - t0:.0f} s")
            sys.stdout.flush()
    took = time.time() - t0
    report(engines, checks, rel, f"{len(cases)} trees in {took:.0f} s ({skipped} skipped: reference over budget)")
    print(f"\n{len(findings)} findings")
    if not args.findings:
        for f in findings:
            print(f)


def report(engines: list[str], checks: Any, rel: Any, title: str) -> None:
    print(f"\n{title}\n")
    print("| engine | judged | raised | crashed | OK | wrong | wrong volume | wrong area | wrong hausdorff "
          "| wrong topology |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for eng in engines:
        c = checks[eng]
        print(f"| {eng} | {c['cases']} | {c['raised']} | {c['crashed']} | {c['ok']} | {c['wrong']} | "
              f"{c['wrong volume']} | "
              f"{c['wrong area']} | {c['wrong hausdorff']} | {c['wrong topology']} |")
    print("\n| engine | figure | median | 90 % | 99 % | max |")
    print("|---|---|---|---|---|---|")
    for eng in engines:
        for fig in ("volume", "area", "hausdorff", "seconds"):
            v = np.asarray(rel[eng][fig])
            if len(v):
                q = np.quantile(v, [0.5, 0.9, 0.99, 1.0], method="higher")
                print(f"| {eng} | {fig} | " + " | ".join(f"{x:.2e}" for x in q) + " |")


if __name__ == "__main__":
    main()
