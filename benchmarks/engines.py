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

isocsg's work on a tree (reference, comparisons) has ``--budget`` seconds; each engine has
``--engine-budget`` seconds of its own, and one past it (VTK's Booleans hang now and then) is
recorded as over the budget for that tree while the others are still judged. ``--only K,K,...``
judges only those trees.

``--rejudge-topology RESULTS --rejudged OUT`` (with the arguments or ``--cases`` that drew the
trees) judges only the topology again, with the current truth (``isocsg.testing.true_topology``:
an all-planar tree's from its exact boundary polygons), for the all-planar trees of a results
file: each engine's mesh is computed again, no volume, area or distance; the other records are
copied as they are.
"""

from __future__ import annotations

import argparse
import json
import os
import pickle
import signal
import sys
import time
import warnings
from collections import Counter
from typing import Any

import numpy as np

from isocsg.csg.mesh import to_manifold
from isocsg.csg.program import OP_INTERSECTION, OP_UNION
from isocsg.csg.section import solid_program
from isocsg.testing import compare_mesh, reference, to_python
from isocsg.testing.compare import as_trimesh, compare_topology, true_topology
from isocsg.testing.strategies import manifold_fuzz, trees


def draw_trees(n: int, seed: int, fuzz: float, max_cubes: int, max_leaves: int, max_transforms: int = 3) -> list[Any]:
    """``n`` distinct trees drawn by hypothesis (a seeded generate phase: the same list every run)."""
    from hypothesis import HealthCheck, Phase, given, settings
    from hypothesis import seed as hseed

    out: list[Any] = []
    seen: set[Any] = set()

    class Enough(Exception):
        """Raised once ``count`` trees are in: hypothesis would otherwise draw all its examples."""

    def collect(strategy: Any, count: int, s: int) -> None:
        before = len(out)
        if count <= 0:
            return

        @hseed(s)
        @settings(max_examples=count * 3, database=None, phases=[Phase.generate], deadline=None,
                  suppress_health_check=list(HealthCheck))
        @given(strategy)
        def run(t: Any) -> None:
            if t not in seen and solid_program(t).n_leaves > 1:
                seen.add(t)
                out.append(t)
            if len(out) >= before + count:
                raise Enough

        try:
            run()
        except Enough:
            pass
        del out[before + count:]

    n_fuzz = int(round(n * fuzz))
    collect(trees(max_leaves=max_leaves), n - n_fuzz, seed)
    if n_fuzz:
        collect(manifold_fuzz(max_ops=max_cubes, max_transforms=max_transforms), n_fuzz, seed + 1)
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


class EngineOverBudget(RuntimeError):
    """The engine did not return within its own time budget (``--engine-budget``)."""


def raise_timeout(*_: Any) -> None:
    """The ``SIGALRM`` handler of every time budget here."""
    raise TimeoutError


class Clock:
    """Seconds left for one tree's isocsg work (its reference and comparisons, ``--budget``):
    ``with clock:`` runs a phase under ``SIGALRM`` for what is left and counts the time it took,
    so that an engine's own time (``engine_timer``) is not charged to the tree."""

    def __init__(self, seconds: float) -> None:
        self.left = float(seconds)

    def __enter__(self) -> Clock:
        if self.left <= 0:
            raise TimeoutError
        self.t0 = time.time()
        signal.setitimer(signal.ITIMER_REAL, self.left)
        return self

    def __exit__(self, *exc: Any) -> None:
        signal.setitimer(signal.ITIMER_REAL, 0)
        self.left -= time.time() - self.t0


def engine_timer(eng: str, tree: Any, mf: list[Any], seconds: float) -> Any:
    """:func:`engine_mesh` under its own ``SIGALRM`` of ``seconds`` (a forked engine gets that as its
    timeout and a few seconds more to be stopped); :class:`EngineOverBudget` past it."""
    signal.setitimer(signal.ITIMER_REAL, seconds + 10.0)
    try:
        return engine_mesh(eng, tree, mf, seconds)
    except TimeoutError:
        raise EngineOverBudget(f"over its budget of {seconds:.0f} s") from None
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)


def isolated(fn: Any, *args: Any, timeout: float = 120.0) -> Any:
    """``fn(*args)`` (a mesh) computed in a forked process: an engine that crashes (VTK's Booleans
    can end in a segmentation fault) or hangs becomes a finding instead of ending the run. The
    wait ends as soon as the process has sent its mesh or has died (its sentinel): a crash is not
    waited for until the timeout."""
    import multiprocessing as mp
    from multiprocessing.connection import wait

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

    proc = ctx.Process(target=target, daemon=True)  # never keeps the run from ending
    proc.start()
    send.close()  # the child's copy is the only writer left: its death closes the pipe
    res, ready = None, []
    try:
        ready = wait([recv, proc.sentinel], timeout)
        if recv in ready or recv.poll(0):
            try:
                res = recv.recv()
            except EOFError:  # died without a word
                res = None
        proc.join(5)
    finally:  # also when the tree's time budget interrupts the wait: no process left behind
        if proc.is_alive():
            proc.kill()
            proc.join()
        recv.close()
    if res is None:
        if not ready:
            raise EngineOverBudget(f"hung over {timeout:.0f} s")
        raise EngineCrash(f"crashed (exit code {proc.exitcode})")
    if res[0] == "raised":
        raise RuntimeError(res[1])
    if res[1] is None:
        return trimesh.Trimesh(np.zeros((0, 3)), np.zeros((0, 3), int))
    return trimesh.Trimesh(res[1][0], res[1][1], process=False)


def judge_tree(k: int, tree: Any, args: Any, engines: list[str]) -> tuple[dict[str, Any], list[str]]:
    """One tree: its reference, every engine's result and its comparison; the record written to
    the results file and the findings (reproducers) of the cases judged wrong, raised, crashed
    or over the budget.

    isocsg's work on the tree (reference, leaf meshes, comparisons) has ``args.budget`` seconds
    in all (``TimeoutError`` past it: the tree is not judged); each engine has
    ``args.engine_budget`` seconds of its own, and one that takes longer is recorded as over the
    budget for this tree while the other engines are still judged."""
    t0 = time.time()
    signal.signal(signal.SIGALRM, raise_timeout)
    clock = Clock(args.budget)
    with clock:
        ref = reference(tree, tol=args.tol)
    rec: dict[str, Any] = {"k": k, "leaves": solid_program(tree).n_leaves, "ref_seconds": time.time() - t0,
                           "engines": {}}
    notes: list[str] = []
    prog = solid_program(tree)
    with clock:
        mf = [to_manifold(p, args.segments) for p in prog.leaves]
    size = float(np.max(ref.bounds[1] - ref.bounds[0]))
    if not size > 0:  # an empty result's box: the leaves' scale
        size = max(float(np.max(np.asarray(p.bounds)[1] - np.asarray(p.bounds)[0])) for p in prog.leaves)
    for eng in engines:
        t1 = time.time()
        try:
            mesh = engine_timer(eng, tree, mf, getattr(args, "engine_budget", None) or args.budget)
        except Exception as exc:  # noqa: BLE001 - an engine's failure is a finding
            status = ("over budget" if isinstance(exc, EngineOverBudget) else
                      "crashed" if isinstance(exc, EngineCrash) else "raised")
            what = f"raised {type(exc).__name__}: {exc}" if status == "raised" else str(exc)
            rec["engines"][eng] = {"status": status, "what": what[:300], "stopped_after": time.time() - t1}
            notes.append(f"# case {k}, {eng}: {what}\n{to_python(tree)}\n")
            continue
        dt = time.time() - t1
        with clock:
            c = compare_mesh(mesh, tree, segments=args.segments, samples=args.samples, ref=ref, seed=k)
        vol_rel = abs(c.volume_error) / ref.volume if ref.volume > 0 else abs(c.volume_error) / size**3
        area_rel = abs(c.area_error) / ref.area if ref.area > 0 else abs(c.area_error) / size**2
        rec["engines"][eng] = {
            "status": "ok" if c.ok else "wrong", "verdicts": dict(c.verdicts), "volume": vol_rel,
            "area": area_rel, "hausdorff": max(c.hausdorff_mesh_to_true, c.hausdorff_true_to_mesh) / size,
            "seconds": dt,
        }
        if not c.ok:
            notes.append(f"# case {k}, {eng}: wrong {', '.join(c.wrong)}\n# "
                         + c.summary().replace("\n", "\n# ") + f"\n{to_python(tree)}\n")
    rec["seconds"] = time.time() - t0
    rec["isocsg_seconds"] = args.budget - clock.left
    return rec, notes


def engine_mesh(eng: str, tree: Any, mf: list[Any], timeout: float = 120.0) -> Any:
    """One engine's result for ``tree`` from the leaf meshes ``mf`` (manifold3d solids); pyvista's
    in a forked process stopped after ``timeout`` seconds."""
    import pyvista as pv

    if eng == "manifold3d":
        mesh = run_manifold(tree, mf)
        mesh.num_tri()  # manifold3d evaluates lazily: time the Booleans, not the tree
        return mesh
    if eng.startswith("trimesh-"):
        return run_trimesh(tree, [as_trimesh(m) for m in mf], eng.split("-", 1)[1])
    return isolated(run_pyvista, tree, [pv.wrap(as_trimesh(m)) for m in mf], timeout=timeout)


def rejudge_topology(cases: list[Any], records: list[dict[str, Any]], args: Any, out: str) -> None:
    """The topology verdicts of the all-planar trees of ``records`` judged again against
    :func:`~isocsg.testing.compare.true_topology` (written to ``out``, one JSON line per tree,
    resuming); every other record is copied. An engine's record keeps its other verdicts and
    gains ``topology_before`` (the verdict it had), and the tree's record ``topology_truth``."""
    done: set[int] = set()
    if os.path.exists(out):
        done = {json.loads(line)["k"] for line in open(out) if line.strip()}

    def alarm(*_: Any) -> None:
        raise TimeoutError

    signal.signal(signal.SIGALRM, alarm)
    changed: Counter[str] = Counter()
    for rec in records:
        k = rec["k"]
        if k in done:
            continue
        tree = cases[k]
        prog = solid_program(tree)
        judged = [e for e, r in rec.get("engines", {}).items() if r.get("status") in ("ok", "wrong")]
        if judged and all(p.polyhedral and p.convex for p in prog.leaves):
            signal.alarm(args.budget)
            try:
                t0 = time.time()
                truth = true_topology(tree)
                rec["topology_truth"] = {"source": truth.source, "components": truth.components,
                                         "genus": truth.genus, "voids": truth.voids, "touching": truth.touching,
                                         "seconds": time.time() - t0}
                mf = [to_manifold(p, args.segments) for p in prog.leaves]
                for eng in judged:
                    r = rec["engines"][eng]
                    topo, _, verdict = compare_topology(engine_mesh(eng, tree, mf), tree, segments=args.segments)
                    r["topology_before"] = r["verdicts"].get("topology")
                    r["verdicts"]["topology"] = verdict
                    r["topology"] = {"components": topo.components, "genus": topo.genus, "voids": topo.voids}
                    r["status"] = "wrong" if "wrong" in r["verdicts"].values() else "ok"
                    changed[f"{eng}: {r['topology_before']} -> {verdict}"] += 1
            except Exception as exc:  # noqa: BLE001 - kept as it was, with the reason
                rec["rejudge_failed"] = f"{type(exc).__name__}: {exc}"[:300]
                changed["failed"] += 1
            finally:
                signal.alarm(0)
        with open(out, "a") as fh:
            fh.write(json.dumps(rec) + "\n")
    for key, n in sorted(changed.items()):
        print(f"{n:5d}  {key}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=20, help="number of trees (1000 for the full run)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--segments", type=int, default=32)
    ap.add_argument("--fuzz", type=float, default=0.2, help="share of trees from manifold's fuzz domain")
    ap.add_argument("--max-cubes", type=int, default=100, help="most cube operations of a fuzz tree")
    ap.add_argument("--max-transforms", type=int, default=3, help="most transforms of a fuzz cube (manifold: 20)")
    ap.add_argument("--max-leaves", type=int, default=5)
    ap.add_argument("--samples", type=int, default=1500)
    ap.add_argument("--tol", type=float, default=1e-5, help="relative accuracy of the reference figures")
    ap.add_argument("--engines", default="manifold3d,trimesh-manifold,pyvista")
    ap.add_argument("--budget", type=int, default=60,
                    help="seconds for isocsg's work on one tree (reference and comparisons; the engines' time aside)")
    ap.add_argument("--engine-budget", type=int, default=None,
                    help="seconds for one engine on one tree (default: --budget); past it that engine is recorded "
                         "as over the budget and the others are still judged")
    ap.add_argument("--only", default=None, help="judge only these trees: K,K,... (their positions in the list)")
    ap.add_argument("--findings", default=None, help="append every wrong case with its reproducer here")
    ap.add_argument("--results", default=None,
                    help="append one JSON line per tree here; trees already in it are skipped (a run resumes)")
    ap.add_argument("--cases", default=None,
                    help="keep the drawn trees in this pickle (drawing 1000 takes minutes): shards share them")
    ap.add_argument("--shard", default="0/1", help="i/n: judge only the trees k with k %% n == i")
    ap.add_argument("--rejudge-topology", default=None, metavar="RESULTS",
                    help="only judge the topology of the all-planar trees of this results file again (the "
                         "trees drawn by the other arguments or read from --cases); written to --rejudged")
    ap.add_argument("--rejudged", default=None, help="the results file --rejudge-topology writes")
    ap.add_argument("--report", nargs="*", default=None, help="only print the tables of these results files")
    ap.add_argument("--collect", nargs="*", default=None,
                    help="only gather these findings files into FUZZ_OUT and RANDOM_OUT given by --collect-to")
    ap.add_argument("--collect-to", default="docs/testing_engines_findings",
                    help="the directory --collect writes trees.py and fuzz.py to")
    ap.add_argument("--phases", default=None,
                    help="only time the phases of a few trees: the first 3 random trees and the fuzz trees "
                         "nearest these cube counts (e.g. 10,30,100)")
    args = ap.parse_args()
    if args.collect is not None:
        collect_findings(args.collect, args.n - int(round(args.n * args.fuzz)), args.collect_to)
        return
    if args.report is not None:
        records = [json.loads(line) for f in args.report for line in open(f) if line.strip()]
        report(args.engines.split(","), records, f"{len(records)} trees from {', '.join(args.report)}")
        return
    warnings.simplefilter("ignore")
    import faulthandler

    faulthandler.enable()  # an engine that crashes the process says where
    shard, shards = (int(x) for x in args.shard.split("/"))
    t0 = time.time()
    if args.cases and os.path.exists(args.cases):
        with open(args.cases, "rb") as fh:
            cases = pickle.load(fh)
    else:
        cases = draw_trees(args.n, args.seed, args.fuzz, args.max_cubes, args.max_leaves, args.max_transforms)
        if args.cases:
            with open(args.cases, "wb") as fh:
                pickle.dump(cases, fh)
    print(f"{len(cases)} trees drawn in {time.time() - t0:.1f} s; segments {args.segments}", flush=True)
    signal.signal(signal.SIGALRM, raise_timeout)
    engines = args.engines.split(",")
    if args.rejudge_topology:
        if not args.rejudged:
            ap.error("--rejudge-topology needs --rejudged OUT")
        records = [json.loads(line) for line in open(args.rejudge_topology) if line.strip()]
        rejudge_topology(cases, records, args, args.rejudged)
        return
    if args.phases:
        picks = None if args.only is None else [int(x) for x in args.only.split(",") if x.strip()]
        time_phases(cases, len(cases) - int(round(len(cases) * args.fuzz)), [int(x) for x in args.phases.split(",")],
                    args, engines, picks)
        return
    done: set[int] = set()
    if args.results and os.path.exists(args.results):
        done = {json.loads(line)["k"] for line in open(args.results) if line.strip()}
    records: list[dict[str, Any]] = []

    def write(path: str | None, text: str) -> None:  # written as found: a stopped run keeps its work
        if path:
            with open(path, "a") as fh:
                fh.write(text + "\n")

    n_random = len(cases) - int(round(len(cases) * args.fuzz))
    only = None if args.only is None else {int(x) for x in args.only.split(",") if x.strip()}
    for k in judging_order(len(cases), n_random):
        tree = cases[k]
        if k % shards != shard or k in done or (only is not None and k not in only):
            continue
        try:
            rec, notes = judge_tree(k, tree, args, engines)
        except TimeoutError:
            rec, notes = {"k": k, "leaves": solid_program(tree).n_leaves, "skipped": f"over {args.budget} s"}, [
                f"# case {k}: over {args.budget} s, skipped\n{to_python(tree)}\n"]
        except Exception as exc:  # noqa: BLE001 - the reference or the comparison failed: a finding on isocsg
            rec, notes = {"k": k, "skipped": f"{type(exc).__name__}: {exc}"[:300]}, [
                f"# case {k}: isocsg raised {type(exc).__name__}: {exc}\n{to_python(tree)}\n"]
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
        rec["fuzz"] = k >= n_random
        records.append(rec)
        write(args.results, json.dumps(rec))
        for text in notes:
            write(args.findings, text)
            if not args.findings:
                print(text)
        if len(records) % 20 == 0:
            report(engines, records, f"after {len(records)} trees, {time.time() - t0:.0f} s")
            sys.stdout.flush()
    report(engines, records, f"{len(records)} trees in {time.time() - t0:.0f} s")


def time_phases(
    cases: list[Any], n_random: int, counts: list[int], args: Any, engines: list[str], only: list[int] | None = None,
) -> None:
    """Where one tree's time goes: the reference, each engine (its Booleans, or the time until it
    raised, crashed or went over its budget: the status follows the seconds), and the rest: the
    comparisons (tessellation reference meshes, sampling, distances). The trees are ``only``, or
    the first 3 random ones and the fuzz trees nearest the cube ``counts``; a tree whose isocsg
    work goes over ``--budget`` prints ``over``."""
    picks = list(range(min(3, n_random))) if only is None else list(only)
    fuzz = list(range(n_random, len(cases)))
    for c in counts if only is None else []:
        if fuzz:
            picks.append(min(fuzz, key=lambda k: abs(solid_program(cases[k]).n_leaves - c)))
    print("| tree | leaves | reference s | " + " | ".join(f"{e} s" for e in engines) + " | rest s | total s |")
    print("|---|---|---|" + "---|" * len(engines) + "---|---|")
    for k in picks:
        kind = "fuzz" if k >= n_random else "random"
        try:
            rec, _ = judge_tree(k, cases[k], args, engines)
        except TimeoutError:
            print(f"| {kind} {k} | {solid_program(cases[k]).n_leaves} | over {args.budget} s |", flush=True)
            continue
        eng = [rec["engines"][e].get("seconds", rec["engines"][e].get("stopped_after", float("nan"))) for e in engines]
        rest = rec["seconds"] - rec["ref_seconds"] - sum(x for x in eng if x == x)
        status = [rec["engines"][e]["status"] for e in engines]
        cells = [f"{x:.2f}" + ("" if st in ("ok", "wrong") else f" ({st})") for x, st in zip(eng, status)]
        print(f"| {kind} {k} | {rec['leaves']} | {rec['ref_seconds']:.2f} | " + " | ".join(cells)
              + f" | {rest:.2f} | {rec['seconds']:.2f} |", flush=True)


def collect_findings(paths: list[str], n_random: int, out_dir: str) -> None:
    """The findings files of the shards as two modules of reproducers, ``trees.py`` (the random
    trees) and ``fuzz.py``: one function ``case_K()`` per case, returning its tree, with what was
    found as comments above it; pyvista's refusals ("raised") are left out (most trees)."""
    cases: dict[int, tuple[list[str], str]] = {}
    for path in paths:
        for block in open(path).read().split("\n# case ")[0:]:
            block = block.strip()
            if not block:
                continue
            block = block if block.startswith("# case ") else "# case " + block
            head = block.split("\n", 1)[0]
            if ", pyvista: raised" in head:
                continue
            k = int(head[len("# case "):].split(",")[0].split(":")[0])
            comments = [ln for ln in block.splitlines() if ln.startswith("#")]
            code = "\n".join(ln for ln in block.splitlines() if not ln.startswith("#") and not ln.startswith("from "))
            old = cases.get(k, ([], code))
            cases[k] = (old[0] + comments, code)
    for name, sel in (("trees.py", lambda k: k < n_random), ("fuzz.py", lambda k: k >= n_random)):
        lines = ['"""Findings of benchmarks/engines.py (docs/testing_engines.md): each function rebuilds the tree',
                 'of one case (its number in the list the command draws); the comments say what was found."""',
                 "", "from isocsg import *  # noqa: F403", ""]
        for k in sorted(c for c in cases if sel(c)):
            comments, code = cases[k]
            lines += ["", *comments, f"def case_{k}():"] + ["    " + ln for ln in code.strip().splitlines()]
            lines += ["    return tree", ""]
        with open(os.path.join(out_dir, name), "w") as fh:
            fh.write("\n".join(lines))


def judging_order(n: int, n_random: int) -> list[int]:
    """The trees' indices in the order they are judged: the random trees (the first
    ``n_random``) and the fuzz trees interleaved in proportion, so that a run stopped early has
    judged the same share of each list (its first trees), not only random ones."""
    def position(k: int) -> float:
        return (k + 0.5) / n_random if k < n_random else (k - n_random + 0.5) / (n - n_random)

    return sorted(range(n), key=position)


def report(engines: list[str], records: list[dict[str, Any]], title: str) -> None:
    """The tables of the records, for the random trees and the fuzz trees apart (``fuzz``)."""
    groups = [(False, "random trees"), (True, "manifold's fuzz domain")]
    present = [(g, name) for g, name in groups if any(bool(r.get("fuzz")) == g for r in records)]
    for g, name in present:
        part = [r for r in records if bool(r.get("fuzz")) == g]
        report_group(engines, part, f"{title}: {len(part)} {name}" if len(present) > 1 else title)


def report_group(engines: list[str], records: list[dict[str, Any]], title: str) -> None:
    skipped = sum(1 for r in records if "skipped" in r)
    stopped = sum(1 for r in records if "skipped" not in r and any(
        _over(e) for e in r.get("engines", {}).values()))
    print(f"\n{title} ({skipped} over the time budget: not judged; {stopped} judged with an engine over "
          "its budget)\n")
    print("| engine | judged | raised | crashed | over the budget | OK | wrong | wrong volume | wrong area "
          "| wrong hausdorff | wrong topology | topology not comparable |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for eng in engines:
        rs = [r["engines"][eng] for r in records if eng in r.get("engines", {})]
        st = Counter("over budget" if _over(r) else r["status"] for r in rs)
        bad = Counter(name for r in rs for name, v in r.get("verdicts", {}).items() if v == "wrong")
        nc = sum(1 for r in rs if r.get("verdicts", {}).get("topology") == "not comparable")
        print(f"| {eng} | {st['ok'] + st['wrong']} | {st['raised']} | {st['crashed']} | {st['over budget']} | "
              f"{st['ok']} | {st['wrong']} | "
              f"{bad['volume']} | {bad['area']} | {bad['hausdorff']} | {bad['topology']} | {nc} |")
    print("\n| engine | figure | median | 90 % | 99 % | max |")
    print("|---|---|---|---|---|---|")
    for eng in engines:
        rs = [r["engines"][eng] for r in records if eng in r.get("engines", {})]
        for fig in ("volume", "area", "hausdorff", "seconds"):
            v = np.asarray([r[fig] for r in rs if fig in r], dtype=np.float64)
            if len(v):
                q = np.quantile(v, [0.5, 0.9, 0.99, 1.0], method="higher")
                print(f"| {eng} | {fig} | " + " | ".join(f"{x:.2e}" for x in q) + " |")
    print_times(records)


def _over(engine_record: dict[str, Any]) -> bool:
    """An engine that went over its own budget (earlier runs: the tree's alarm inside the engine)."""
    return bool(engine_record.get("status") == "over budget"
                or engine_record.get("what", "").startswith("raised TimeoutError"))


def print_times(records: list[dict[str, Any]]) -> None:
    """Wall seconds per judged tree (reference, engines and comparisons) and for the reference
    alone, by leaf count."""
    done = [r for r in records if "seconds" in r]
    if not done:
        return
    print("\n| leaves | trees judged | over the budget | seconds a tree: median | 90 % | reference: median | 90 % |")
    print("|---|---|---|---|---|---|---|")
    bins = [(2, 5), (6, 10), (11, 30), (31, 60), (61, 100)]
    for lo, hi in bins + [(2, 10**9)]:
        rs = [r for r in done if lo <= r.get("leaves", 0) <= hi]
        over = sum(1 for r in records if "skipped" in r and lo <= r.get("leaves", 0) <= hi)
        if not rs:
            continue
        t = np.quantile([r["seconds"] for r in rs], [0.5, 0.9], method="higher")
        f = np.quantile([r["ref_seconds"] for r in rs], [0.5, 0.9], method="higher")
        label = "all" if hi == 10**9 else f"{lo}-{hi}"
        print(f"| {label} | {len(rs)} | {over} | {t[0]:.1f} | {t[1]:.1f} | {f[0]:.2f} | {f[1]:.2f} |")


if __name__ == "__main__":
    main()
