"""Loading a model of thousands of extruded polygons under nested transforms.

Issue 22 measured a real model of 392 polygons extruded into 6637 prisms under nested
transforms at 97.5 s to load; after transforms composed once per leaf, 22-33 s, 60 % of it in
one convex hull per prism. This benchmark writes a model of the same kind (non-convex star
polygons, about 17 convex pieces each, in groups under five nested ``multmatrix`` levels) and
times ``loads_openscad`` of it, the number of prisms and the convex-hull builds::

    python benchmarks/extrude_prisms.py              # 392 polygons, 3 repeats
    python benchmarks/extrude_prisms.py --polygons 50 --repeats 1
"""

from __future__ import annotations

import argparse
import math
import statistics
import time

import numpy as np


def model(polygons: int, points: int = 28, depth: int = 5, seed: int = 0) -> str:
    """A ``.csg`` text: ``polygons`` star polygons, each extruded, in groups of 8 under ``depth``
    nested multmatrix nodes (rotations about z, translations)."""
    rng = np.random.default_rng(seed)
    groups = []
    for g in range(0, polygons, 8):
        body = []
        for i in range(g, min(g + 8, polygons)):
            ang = np.linspace(0, 2 * math.pi, points, endpoint=False)
            r = np.where(np.arange(points) % 2 == 0, 3.0, 1.2) * rng.uniform(0.8, 1.2, points)
            pts = ", ".join(f"[{x:.6f}, {y:.6f}]" for x, y in zip(r * np.cos(ang) + 8 * (i % 8), r * np.sin(ang)))
            body.append(f"linear_extrude(height = {1 + i % 3}) {{ polygon(points = [{pts}]); }}")
        text = " ".join(body)
        for k in range(depth):
            a = math.radians(7 * (k + g))
            c, s = math.cos(a), math.sin(a)
            rows = [f"[{c:.9f}, {-s:.9f}, 0, {k + g * 0.5}]", f"[{s:.9f}, {c:.9f}, 0, {g * 0.25}]", f"[0, 0, 1, {k}]"]
            m = "[" + ", ".join([*rows, "[0, 0, 0, 1]"]) + "]"
            text = f"multmatrix({m}) {{ {text} }}"
        groups.append(text)
    return "union() { " + " ".join(groups) + " }"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--polygons", type=int, default=392)
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()

    import isocsg.kinds.polyhedron as poly
    from isocsg.csg import leaves
    from isocsg.openscad import loads_openscad

    text = model(args.polygons)
    hulls = 0
    real = poly._hull

    def counted(*a, **k):  # type: ignore[no-untyped-def]
        nonlocal hulls
        hulls += 1
        return real(*a, **k)

    poly._hull = counted  # type: ignore[assignment]
    loads_openscad("cube(1);")  # imports warm
    times, cpu = [], []
    for _ in range(args.repeats):
        hulls = 0
        t0, c0 = time.perf_counter(), time.process_time()
        solid = loads_openscad(text)
        times.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
    n = sum(1 for _ in leaves(solid))
    print(f"{args.polygons} polygons -> {n} prisms: load {statistics.median(times):.2f} s "
          f"(median of {args.repeats}; min {min(times):.2f} s; CPU {statistics.median(cpu):.2f} s), "
          f"{hulls} convex-hull builds per load")


if __name__ == "__main__":
    main()
