"""Timings of transforms of large trees, beside building the same tree and manifold3d's transform.

Usage: ``python benchmarks/transforms.py [--leaves 100000] [--repeat 3]``

Columns: building the union of N leaves (spheres and boxes, the constructors' validation
included), ``rotate`` (a rigid turn: spheres stay spheres, boxes get an orientation),
``scale`` unevenly (spheres become ellipsoids, boxes stay boxes), and, as the peer,
manifold3d's ``Manifold.transform`` of the union's mesh (lazy in manifold3d: it records the
matrix; the time to get the mesh back out, ``to_mesh``, is shown too). Medians; the ratio is
isocsg's transform over building the tree (a transform re-makes every leaf, so it costs about
as much as building them).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from _common import fmt_seconds, median_time, print_table  # noqa: E402

from isocsg import Box, Sphere  # noqa: E402
from isocsg.csg import Union  # noqa: E402


def build(n: int) -> Union:
    return Union([Sphere((float(i), 0.0, 0.0), 0.4) if i % 3 else Box((float(i), 0.0, 0.0), (0.5, 0.5, 0.5))
                  for i in range(n)])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--leaves", type=int, default=100_000)
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    rows = []
    for n in sorted({1000, 10_000, args.leaves}):
        t_build, tree = median_time(lambda: build(n), args.repeat)
        t_rot, _ = median_time(lambda: tree.rotate((10, 20, 30)), args.repeat)
        t_scale, _ = median_time(lambda: tree.scale((1.0, 2.0, 3.0)), args.repeat)
        peer = peer_mesh = None
        if n <= 10_000:
            m = tree.to_manifold(8)
            uneven = [[0.9, 0.1, 0.0, 1.0], [0.0, 1.0, 0.2, 0.0], [0.0, 0.0, 1.1, 0.0]]
            peer, _ = median_time(lambda: m.transform(uneven), args.repeat)
            peer_mesh, _ = median_time(lambda: m.transform(uneven).to_mesh(), args.repeat)
        rows.append([f"{n}", fmt_seconds(t_build), fmt_seconds(t_rot), fmt_seconds(t_scale),
                     f"{t_rot / t_build:.2f}", fmt_seconds(peer), fmt_seconds(peer_mesh)])
    print_table("Transforms of a union of spheres and boxes (medians)",
                ["leaves", "build", "rotate", "scale (uneven)", "rotate / build",
                 "manifold3d transform", "manifold3d transform + to_mesh"], rows)


if __name__ == "__main__":
    main()
