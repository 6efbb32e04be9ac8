"""Exact illuminance (Lambert over the visible source) against Monte Carlo, in a room.

The scene: a 4 x 4 m floor at z = 0, a 1.2 x 0.6 m luminaire at 2.8 m facing
down, a table of five boxes (top and four legs). Floor grids of 41 x 41 and
201 x 201 points.

For each grid the script measures points per second of the exact method and
of a compiled Monte Carlo estimator (jittered stratified samples over the
source, exact ray-box occlusion) at the sample counts that reach 1 % and
0.1 % RMS error against the exact values (RMS of the error over the RMS of the
exact values, averaged over seeds; the count is searched over k x k grids),
and the points per second where the source is fully visible (no occluders, and
the lit points of the room).

With ``--scale``: the same room whose table carries a CSG plate (a box with
six spherical pockets, spheres at resolution 64) over the 201 x 201 floor,
beside the boxes-only room: the time of the first call (the decomposition of
the plate included, caches emptied), of later calls (the decomposition
reused), the convex pieces the receivers need (over all receiver groups), and
points per second; and the plate alone (no table to hide it). ``--full`` adds
the full convex decomposition of the plate (every piece, nothing left out).

Run: ``python benchmarks/illuminance.py [--quick] [--scale [--full]]``.
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numba
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from _common import fmt_rate, fmt_seconds, median_time, print_table  # noqa: E402

import isocsg  # noqa: E402
from isocsg.shadows import AreaLight, illuminance, illuminance_and_state  # noqa: E402
from isocsg.shadows import occluders as occluder_module  # noqa: E402
from isocsg.shadows.direct import FEW_PIECES, receiver_tiles  # noqa: E402

RADIANCE = 1000.0


def room():
    lamp = AreaLight([(-0.6, -0.3, 2.8), (-0.6, 0.3, 2.8), (0.6, 0.3, 2.8), (0.6, -0.3, 2.8)], RADIANCE)
    top = isocsg.Box((0.3, 0.2, 0.73), (1.2, 0.8, 0.04))
    legs = [isocsg.Box((0.3 + sx * 0.55, 0.2 + sy * 0.35, 0.355), (0.05, 0.05, 0.71))
            for sx in (-1, 1) for sy in (-1, 1)]
    return lamp, [top, *legs]


def floor(m):
    xs = np.linspace(-2.0, 2.0, m)
    X, Y = np.meshgrid(xs, xs, indexing="ij")
    return np.c_[X.ravel(), Y.ravel(), np.zeros(m * m)]


@numba.njit(cache=True, parallel=True)
def mc_kernel(P, corner, ex, ey, L, k, bmin, bmax, seed, out):
    """Stratified Monte Carlo for a rectangle source (corner + s ex + t ey, emitting along ey x ex) and boxes."""
    n = P.shape[0]
    nx = ey[1] * ex[2] - ey[2] * ex[1]
    ny = ey[2] * ex[0] - ey[0] * ex[2]
    nz = ey[0] * ex[1] - ey[1] * ex[0]
    area = math.sqrt(nx * nx + ny * ny + nz * nz)
    nx /= area
    ny /= area
    nz /= area
    w = area / (k * k)
    nb = bmin.shape[0]
    for i in numba.prange(n):
        # The legacy per-thread stream of numba kernels (Generators are not numba-typed here).
        np.random.seed(seed * 7919 + i)  # noqa: NPY002
        px, py, pz = P[i, 0], P[i, 1], P[i, 2]
        acc = 0.0
        for a in range(k):
            for b in range(k):
                s = (a + np.random.random()) / k  # noqa: NPY002
                t = (b + np.random.random()) / k  # noqa: NPY002
                qx = corner[0] + s * ex[0] + t * ey[0]
                qy = corner[1] + s * ex[1] + t * ey[1]
                qz = corner[2] + s * ex[2] + t * ey[2]
                dx, dy, dz = qx - px, qy - py, qz - pz
                r2 = dx * dx + dy * dy + dz * dz
                r = math.sqrt(r2)
                cp = dz / r  # receiving normal +z
                cq = -(nx * dx + ny * dy + nz * dz) / r
                if cp <= 0.0 or cq <= 0.0:
                    continue
                blocked = False
                for j in range(nb):
                    t0, t1 = 1e-9, 1.0 - 1e-9
                    for c in range(3):
                        o = (px, py, pz)[c]
                        d = (dx, dy, dz)[c]
                        if d == 0.0:
                            if o < bmin[j, c] or o > bmax[j, c]:
                                t0, t1 = 1.0, 0.0
                        else:
                            ta = (bmin[j, c] - o) / d
                            tb = (bmax[j, c] - o) / d
                            if ta > tb:
                                ta, tb = tb, ta
                            t0 = max(t0, ta)
                            t1 = min(t1, tb)
                    if t0 < t1:
                        blocked = True
                        break
                if not blocked:
                    acc += cp * cq / r2
        out[i] = L * w * acc


def mc(P, lamp, boxes, k, seed):
    v = lamp.vertices_array
    # corner v0, edges along the winding: emitting side = (v1 - v0) x (v3 - v0) direction
    ex, ey = v[3] - v[0], v[1] - v[0]
    bmin = np.array([b.bounds[0] for b in boxes]).reshape(-1, 3)
    bmax = np.array([b.bounds[1] for b in boxes]).reshape(-1, 3)
    out = np.empty(len(P))
    mc_kernel(P, v[0], ex, ey, lamp.radiance, k, bmin, bmax, seed, out)
    return out


def rms_rel(est, exact):
    return float(np.sqrt(np.mean((est - exact) ** 2)) / np.sqrt(np.mean(exact**2)))


def search_k(P, lamp, boxes, exact, target, seeds):
    """Smallest k (k x k samples) whose mean RMS error over seeds is <= target."""
    ks = sorted({int(round(1.25**j)) for j in range(0, 45)})
    for k in ks:
        err = np.mean([rms_rel(mc(P, lamp, boxes, k, s), exact) for s in seeds])
        if err <= target:
            return k, err
    return None, None


def run(quick: bool) -> None:
    lamp, boxes = room()
    repeats = 3 if quick else 5
    seeds = (1, 2) if quick else (1, 2, 3)
    # compile once
    illuminance(floor(3), [0, 0, 1], [lamp], boxes)
    mc(floor(3), lamp, boxes, 2, 0)
    rows, ratio_rows = [], []
    for m in (41, 201):
        P = floor(m)
        n = len(P)
        t_ex, (E, S) = median_time(lambda: illuminance_and_state(P, [0, 0, 1], [lamp], boxes), repeats)
        rows.append((f"{m}x{m}", "exact", "-", "-", fmt_seconds(t_ex), fmt_rate(n, t_ex)))
        for target in (1e-2, 1e-3):
            k, err = search_k(P, lamp, boxes, E, target, seeds)
            if k is None:
                rows.append((f"{m}x{m}", f"MC {target:.1%}", "not reached", "-", "-", "-"))
                continue
            t_mc, _ = median_time(lambda: mc(P, lamp, boxes, k, 99), repeats)
            rows.append((f"{m}x{m}", f"MC {target:.1%}", f"{k * k}", f"{err:.2%}",
                         fmt_seconds(t_mc), fmt_rate(n, t_mc)))
            ratio_rows.append((f"{m}x{m}", f"{target:.1%}", f"{t_mc / t_ex:.3g}x"))
        counts = np.bincount(S, minlength=3)
        rows.append((f"{m}x{m}", f"states lit/pen/umb {counts[0]}/{counts[1]}/{counts[2]}", "", "", "", ""))
    print_table(
        "Room: floor illuminance, exact vs Monte Carlo (median times)",
        ["grid", "method", "samples", "RMS error", "time", "points/s"],
        rows,
    )
    print_table("Speed-up of the exact method over Monte Carlo", ["grid", "MC accuracy", "MC time / exact time"],
                ratio_rows)

    # fully visible source
    nfull = 200_000 if quick else 1_000_000
    P = np.c_[np.random.default_rng(0).uniform(-2, 2, (nfull, 2)), np.zeros(nfull)]
    t_free, _ = median_time(lambda: illuminance(P, [0, 0, 1], [lamp]), repeats)
    P201 = floor(201)
    _, S = illuminance_and_state(P201, [0, 0, 1], [lamp], boxes)
    lit = P201[S == 0]
    t_lit, _ = median_time(lambda: illuminance(lit, [0, 0, 1], [lamp], boxes), repeats)
    print_table(
        "Fully visible source",
        ["case", "points", "time", "points/s"],
        [
            ("no occluders", nfull, fmt_seconds(t_free), fmt_rate(nfull, t_free)),
            ("lit floor points of the room (table present)", len(lit), fmt_seconds(t_lit), fmt_rate(len(lit), t_lit)),
        ],
    )


def pocket_plate():
    """A 0.9 x 0.5 x 0.06 m plate on the table top with six spherical pockets (radius 5 cm) in its top."""
    solid = isocsg.Box((0.3, 0.2, 0.78), (0.9, 0.5, 0.06))
    for dx in (-0.27, 0.0, 0.27):
        for dy in (-0.11, 0.11):
            solid = solid - isocsg.Sphere((0.3 + dx, 0.2 + dy, 0.81), 0.05)
    return solid


def pieces_used(P, lamp, occluders, resolution):
    """Distinct convex pieces over the receiver groups, and the largest count one group uses."""
    whole = occluder_module.shadow_pieces(occluders, P, lamp.vertices_array, resolution=resolution)
    if len(whole) <= FEW_PIECES:
        return len(whole), len(whole)
    ids, most = set(), 0
    for idx in receiver_tiles(P):
        pcs = occluder_module.shadow_pieces(occluders, P[idx], lamp.vertices_array, resolution=resolution)
        ids.update(id(pc) for pc in pcs)
        most = max(most, len(pcs))
    return len(ids), most


def run_scale(quick: bool, full: bool) -> None:
    import time

    lamp, boxes = room()
    plate = pocket_plate()
    res = 64
    P = floor(201)
    n = len(P)
    repeats = 3 if quick else 5
    illuminance_and_state(floor(3), [0, 0, 1], [lamp], boxes)  # compile
    rows = []
    for label, occ in (
        ("boxes only (table)", boxes),
        ("table + plate with 6 pockets (res 64)", [*boxes, plate]),
        ("plate with 6 pockets alone (res 64)", [plate]),
    ):
        occluder_module.clear_cache()
        t0 = time.perf_counter()
        E, S = illuminance_and_state(P, [0, 0, 1], [lamp], occ, resolution=res)
        t_first = time.perf_counter() - t0
        t_again, _ = median_time(lambda: illuminance_and_state(P, [0, 0, 1], [lamp], occ, resolution=res), repeats)
        used, most = pieces_used(P, lamp, occ, res)
        counts = np.bincount(S, minlength=3)
        rows.append((label, fmt_seconds(t_first), fmt_seconds(t_again), fmt_rate(n, t_again), f"{used} ({most})",
                     f"{counts[0]}/{counts[1]}/{counts[2]}"))
    print_table(
        "CSG furniture at scale: 201 x 201 floor, exact E and states (first call: decomposition included)",
        ["occluders", "first call", "later calls (median)", "points/s", "pieces used (most per group)", "lit/pen/umb"],
        rows,
    )
    if full:
        occluder_module.clear_cache()
        t0 = time.perf_counter()
        pcs = occluder_module.convex_pieces([plate], resolution=res)
        print_table("Full convex decomposition of the plate (every piece)", ["pieces", "time"],
                    [(len(pcs), fmt_seconds(time.perf_counter() - t0))])


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="fewer repeats and seeds")
    ap.add_argument("--scale", action="store_true", help="the room with a CSG plate on the table (201 x 201 floor)")
    ap.add_argument("--full", action="store_true", help="with --scale: also the full decomposition of the plate")
    args = ap.parse_args(argv)
    if args.scale:
        run_scale(args.quick, args.full)
    else:
        run(args.quick)


if __name__ == "__main__":
    main()
