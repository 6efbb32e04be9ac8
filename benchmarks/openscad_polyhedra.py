"""Convex polyhedra through OpenSCAD: accuracy and cost of the two 6-digit forms.

Run from the repository root::

    python benchmarks/openscad_polyhedra.py            # 1000 polyhedra, 500 maps of them, 30 trees
    python benchmarks/openscad_polyhedra.py --count 300
    python benchmarks/openscad_polyhedra.py --quick    # 100 polyhedra, 5 trees

Random convex polyhedra (hulls of 4 to 40 points, stretched 0.1 to 10 per axis,
sheared, moved up to 1e4 away; the generator of ``tests/test_openscad_polyhedra.py``),
turns, scales, mirrors and affine maps of half of them, and Boolean trees of them, are
written with ``dumps_openscad(digits=6)`` in both forms of a polyhedron (``"hull"``, the
exact one, and ``"points"``, the rounded one), converted by ``openscad -o x.csg`` (one
run per form, every solid a top-level statement) and read back. Printed: the largest
relative volume error and bounds error (relative to the size) of each form, the trees'
volume error by manifold3d (exact on polyhedra), and the median write and read times
and text sizes per polyhedron, with the ratio hull / points.
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))

from test_openscad_polyhedra import errors, random_polyhedra, transformed  # noqa: E402

from isocsg import Box  # noqa: E402
from isocsg.openscad import dumps_openscad, lower, parse_csg  # noqa: E402


def _through(texts: list[str]) -> tuple[list, float]:
    with tempfile.TemporaryDirectory() as tmp:
        scad, out = Path(tmp) / "m.scad", Path(tmp) / "m.csg"
        scad.write_text("".join(texts))
        subprocess.run(["openscad", "-o", str(out), str(scad)], check=True, capture_output=True)
        calls = parse_csg(out.read_text())
    times, solids = [], []
    for c in calls:
        t0 = time.perf_counter()
        solids.append(lower([c]).solid)
        times.append(time.perf_counter() - t0)
    return solids, statistics.median(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--count", type=int, default=1000, help="random polyhedra (and half as many maps of them)")
    parser.add_argument("--trees", type=int, default=30)
    parser.add_argument("--quick", action="store_true", help="100 polyhedra and 5 trees")
    args = parser.parse_args()
    if args.quick:
        args.count, args.trees = 100, 5
    if shutil.which("openscad") is None:
        sys.exit("the openscad program is not installed")
    polys = random_polyhedra(args.count, seed=11)
    polys += transformed(polys[: args.count // 2], seed=12)
    print(f"{len(polys)} polyhedra ({args.count} random, {args.count // 2} maps of them), "
          f"{int(np.median([len(p.hull_vertices) for p in polys]))} vertices (median)")
    rows = {}
    for form in ("hull", "points"):
        t_write, texts = [], []
        for p in polys:
            t0 = time.perf_counter()
            texts.append(dumps_openscad(p, digits=6, polyhedra=form))
            t_write.append(time.perf_counter() - t0)
        backs, t_read = _through(texts)
        errs = np.array([errors(b, p) for b, p in zip(backs, polys)])
        rows[form] = (errs[:, 0].max(), errs[:, 1].max(), statistics.median(t_write), t_read,
                      statistics.median(len(t) for t in texts))
    print(f"{'form':8} {'max vol err':>12} {'max bounds err':>15} {'write (ms)':>11} {'read (ms)':>10} {'chars':>8}")
    for form, (dv, db, tw, tr, n) in rows.items():
        print(f"{form:8} {dv:12.2e} {db:15.2e} {tw * 1e3:11.2f} {tr * 1e3:10.2f} {n:8.0f}")
    h, p = rows["hull"], rows["points"]
    print(f"{'ratio':8} {'':12} {'':15} {h[2] / p[2]:11.1f} {h[3] / p[3]:10.1f} {h[4] / p[4]:8.1f}   (hull / points)")

    rng = np.random.default_rng(13)
    trees = []
    for _ in range(args.trees):
        a, b, c = random_polyhedra(3, seed=int(rng.integers(1 << 30)))
        mid = a.bounds.mean(axis=0)
        b, c = b.translate(mid - b.bounds.mean(axis=0)), c.translate(mid - c.bounds.mean(axis=0))
        size = np.ptp(a.bounds, axis=0)
        tree = (a - b) | (c & Box(tuple(mid + 0.3 * size), tuple(size * 0.8)))
        trees.append(tree.rotate(rng.uniform(-90, 90, size=3)))
    backs, _ = _through([dumps_openscad(t, digits=6) for t in trees])
    dv = max(abs(b.to_manifold().volume() / t.to_manifold().volume() - 1) for b, t in zip(backs, trees))
    print(f"{len(trees)} trees (a - b) | (c & turned box), turned: max volume error by manifold3d {dv:.2e}")


if __name__ == "__main__":
    main()
