"""Time ``isocsg.testing.reference(tree, tol)`` over a file of reproducers, against another checkout.

A reproducer file is what ``benchmarks/engines.py`` writes for its findings: blocks that start
with a line ``# case K ...`` followed by Python that builds ``tree``. Without ``--cases`` the
handful of trees below are timed (cases of the 1000-tree run whose reference took over 120 s:
thin rods, discs and plates, coincident leaves, empty results). Each case runs in its own
process, ``--repeats`` times; a run over ``--limit`` seconds stops the case. With ``--against
DIR`` (the root of another checkout, the directory holding its ``isocsg`` package, e.g. an older
commit's ``git archive``) the same cases are timed there too and the table gives the ratio of
the medians and how far apart the two figures are in units of their error estimates::

    python benchmarks/reference_speed.py [--cases FILE] [--against DIR] [--limit 120] [--repeats 3] [--tol 1e-5]
"""

from __future__ import annotations

import argparse
import json
import os
import re
import statistics
import sys
import time
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _common import print_table, run_child  # noqa: E402

HERE = Path(__file__).resolve().parent.parent

#: Trees of the 1000-tree run (``benchmarks/engines.py --n 1000 --seed 1``) whose reference went
#: over 120 s: a 1e-3 rod in a union with its own copy, the same with discs, a cone, a plate and
#: a cylinder, an empty intersection, a sphere's patch inside a torus's difference.
CASES = '''
# case 422
p0 = Cylinder(center=(-0.25, -1.0, 0.5), axis=(2.0, 2.0, 2.0), radius=1.75)
p1 = Cylinder(center=(0.5, 0.25, 0.0), axis=(0.0, 1.0, 0.0), radius=0.001)
tree = Union(Union(p0, p1), Cylinder(center=(0.5, 0.25, 0.0), axis=(0.0, 1.0, 0.0), radius=0.001))

# case 230
p0 = Cylinder(center=(-0.25, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5)
p1 = Cylinder(center=(-0.75, 0.5, -0.75), axis=(0.6, -1.0, 2.0), radius=1.75)
tree = Union(Union(p0, p1), Cylinder(center=(-0.25, -0.25, 0.0), axis=(0.0, 0.0, 0.001), radius=0.5))

# case 174
p0 = Cone(center=(0.25, 0.25, 0.5), axis=(0.3, -0.5, 1.0), radius=0.25)
p1 = Box(center=(0.5, 0.0, 0.75), size=(1.0, 1.0, 0.0001))
p3 = Cylinder(center=(0.5, -0.75, 0.5), axis=(1.0, 1.0, 1.0), radius=0.75)
tree = Union(Intersection(p0, p1), p3)

# case 406
p0 = Cylinder(center=(0.0, 0.25, -0.75), axis=(0.075, -0.125, 0.25), radius=1.5)
p1 = Sphere(center=(0.75, 0.25, -1.0), radius=0.5)
p3 = Cylinder(center=(0.25, 0.25, 0.5), axis=(1.75, 0.0, 0.0), radius=0.5)
p4 = Cone(center=(-0.25, 0.5, 1.0), axis=(0.25, 0.0, 0.0), radius=1.75)
tree = Intersection(Intersection(p0, p1), Intersection(p3, p4))

# case 352
p0 = Torus(center=(0.75, -1.0, 0.75), axis=(0.5773502691896258, 0.5773502691896258, 0.5773502691896258),
           major=1.25, minor=0.25)
p1 = Cylinder(center=(1.0, 1.0, 1.0), axis=(0.0, 0.25, 0.0), radius=1.25)
p2 = Sphere(center=(0.25, 0.75, 0.75), radius=0.5)
tree = Difference(p0, Intersection(Difference(p1, p2), p1))
'''


def parse_cases(text: str) -> list[tuple[str, str]]:
    """The ``(label, code)`` blocks of a reproducer file."""
    out = []
    for block in re.split(r"(?m)^(?=# case )", text):
        m = re.match(r"# case (\S+?):?\s", block)
        if m:
            out.append((m.group(1), block))
    return out


def child(code: str, tol: float, repeats: int) -> None:
    """Build the tree and print one JSON line per timed ``reference`` call."""
    import isocsg
    from isocsg.csg.section import solid_program
    from isocsg.testing import reference

    ns: dict[str, Any] = {}
    exec(code, ns)  # noqa: S102 - the reproducer is the benchmark's own input
    tree = ns["tree"]
    reference(isocsg.Sphere((0, 0, 0), 1) | isocsg.Sphere((0, 0, 1), 1), tol=1e-3)  # imports and compiled kernels
    for _ in range(repeats):
        t0 = time.perf_counter()
        ref = reference(tree, tol=tol)
        dt = time.perf_counter() - t0
        print(json.dumps({"seconds": dt, "leaves": solid_program(tree).n_leaves, "volume": ref.volume,
                          "volume_error": ref.volume_error, "area": ref.area, "area_error": ref.area_error}),
              flush=True)


def time_case(root: Path, code: str, args: Any) -> dict[str, Any]:
    """The median of a case's runs with ``root``'s isocsg (``seconds`` None past the limit)."""
    env = {**os.environ, "PYTHONPATH": str(root)}
    argv = [sys.executable, __file__, "--child", "--tol", str(args.tol), "--repeats", str(args.repeats)]
    env["REFERENCE_SPEED_CODE"] = code
    recs, status, _peak = run_child(argv, args.limit * args.repeats + 60, env=env)
    runs = [r for r in recs if "seconds" in r]
    over = status != "ok" or len(runs) < args.repeats or any(r["seconds"] > args.limit for r in runs)
    out: dict[str, Any] = {"status": status, "seconds": None if over else statistics.median(r["seconds"] for r in runs)}
    if runs:
        out.update({k: runs[-1][k] for k in ("leaves", "volume", "volume_error", "area", "area_error")})
    return out


def _gap(a: dict[str, Any], b: dict[str, Any], key: str) -> str:
    """``|a - b|`` over the larger of the two error estimates (``-`` when one is missing)."""
    if key not in a or key not in b:
        return "-"
    err = max(a[f"{key}_error"], b[f"{key}_error"], 1e-300)
    return f"{abs(a[key] - b[key]) / err:.2g}"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cases", type=Path, help="a reproducer file (default: the cases in this script)")
    ap.add_argument("--against", type=Path, help="root of another checkout to time the same cases with")
    ap.add_argument("--limit", type=float, default=120.0, help="seconds one reference call may take")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--tol", type=float, default=1e-5)
    ap.add_argument("--only", help="comma-separated case labels")
    ap.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child:
        child(os.environ["REFERENCE_SPEED_CODE"], args.tol, args.repeats)
        return
    cases = parse_cases(args.cases.read_text() if args.cases else CASES)
    if args.only:
        keep = set(args.only.split(","))
        cases = [c for c in cases if c[0] in keep]
    header = "from isocsg import *\n"
    rows, ratios = [], []
    total_new = total_old = 0.0
    for label, code in cases:
        new = time_case(HERE, header + code, args)
        old = time_case(args.against, header + code, args) if args.against else {}
        fmt = lambda r: "-" if not r else (f"{r['seconds']:.2f}" if r["seconds"] is not None else f"> {args.limit:g}")  # noqa: E731
        row = [label, new.get("leaves", "-"), fmt(new)]
        if args.against:
            t_new = new["seconds"] if new["seconds"] is not None else args.limit
            t_old = old["seconds"] if old["seconds"] is not None else args.limit
            total_new, total_old = total_new + t_new, total_old + t_old
            ratios.append(t_old / t_new)
            more = ">" if old["seconds"] is None and new["seconds"] is not None else ""
            row += [fmt(old), f"{more}{t_old / t_new:.3g}", _gap(new, old, "volume"), _gap(new, old, "area")]
        rows.append(row)
        print(" | ".join(str(c) for c in row), flush=True)
    headers = ["case", "leaves", "seconds"]
    if args.against:
        headers += [f"seconds ({args.against.name})", "ratio", "volume gap / error", "area gap / error"]
    print()
    title = f"reference(tree, tol={args.tol:g}): median of {args.repeats} runs, limit {args.limit:g} s"
    print_table(title, headers, rows)
    if args.against and ratios:
        print(f"total {total_old:.1f} s -> {total_new:.1f} s (a case over the limit counted as {args.limit:g} s): "
              f"ratio {total_old / total_new:.3g}; median ratio {statistics.median(ratios):.3g}")


if __name__ == "__main__":
    main()
