"""The in-process evaluator of .scad files (isocsg.openscad.evaluate) against the openscad
program's export, on OpenSCAD's examples and the real-world sample, and the time of each.

    PYTHONPATH=$PWD python benchmarks/scad_evaluate_corpus.py [files...]

With no files: every .scad under /usr/share/openscad/examples and every model of
benchmarks/openscad_realworld_sample.txt found under /tmp/rw/<owner>+<repo>/<path>. For each
file the evaluator accepts, its tree must equal parse_csg(openscad's export) call for call and
float for float; prints the acceptance counts, the mismatches and the median times.
"""

from __future__ import annotations

import statistics
import sys
import time
from pathlib import Path

from isocsg.openscad.evaluate import evaluate_scad
from isocsg.openscad.parser import CSGCall, parse_csg
from isocsg.openscad.program import scad_to_csg

ROOT = Path(__file__).resolve().parent


def same_trees(a: list[CSGCall], b: list[CSGCall]) -> str | None:
    """None if the two trees are the same calls with the same arguments, else where they differ."""
    todo = [(a, b, "")]
    while todo:
        xs, ys, where = todo.pop()
        if len(xs) != len(ys):
            return f"{where}: {[x.name for x in xs]} != {[y.name for y in ys]}"
        for i, (x, y) in enumerate(zip(xs, ys, strict=True)):
            here = f"{where}/{i}:{x.name}"
            if (x.name, x.modifiers, x.args, x.kwargs) != (y.name, y.modifiers, y.args, y.kwargs):
                return f"{here}: {x.args} {x.kwargs} != {y.name} {y.args} {y.kwargs}"
            todo.append((x.children, y.children, here))
    return None


def corpus() -> list[tuple[str, Path]]:
    files = [("examples", p) for p in sorted(Path("/usr/share/openscad/examples").rglob("*.scad"))]
    for line in (ROOT / "openscad_realworld_sample.txt").read_text().splitlines():
        if line.strip():
            repo, _commit, path = line.split(" ", 2)
            p = Path("/tmp/rw") / repo.replace("/", "+") / path
            if p.is_file():
                files.append(("realworld", p))
    return files


def main(argv: list[str]) -> int:
    files = [("given", Path(p)) for p in argv] or corpus()
    counts: dict[str, list[int]] = {}
    mine: list[float] = []
    theirs: list[float] = []
    bad = 0
    for group, path in files:
        text = path.read_text(encoding="utf-8", errors="replace")
        t0 = time.perf_counter()
        calls = evaluate_scad(text, path=path)
        t1 = time.perf_counter()
        seen = counts.setdefault(group, [0, 0])
        seen[1] += 1
        if calls is None:
            continue
        seen[0] += 1
        try:
            t2 = time.perf_counter()
            export = scad_to_csg(path)
            theirs.append(time.perf_counter() - t2)
            mine.append(t1 - t0)
            diff = same_trees(calls, parse_csg(export))
        except Exception as exc:  # noqa: BLE001 (reported, not hidden)
            diff = f"openscad: {exc}"
        if diff is not None:
            bad += 1
            print(f"MISMATCH {path}: {diff}")
    for group, (ok, n) in counts.items():
        print(f"{group}: {ok} of {n} files read in-process")
    if mine:
        print(f"evaluator: median {1e3 * statistics.median(mine):.2f} ms, max {1e3 * max(mine):.1f} ms; "
              f"openscad: median {1e3 * statistics.median(theirs):.1f} ms, min {1e3 * min(theirs):.1f} ms")
        print(f"median evaluator {1e3 * statistics.median(mine):.2f} ms, "
              f"openscad -o x.csg {1e3 * statistics.median(theirs):.1f} ms "
              f"(total {1e3 * sum(mine):.0f} ms vs {1e3 * sum(theirs):.0f} ms over {len(mine)} files)")
    print(f"{bad} mismatches")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
