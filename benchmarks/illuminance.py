"""Exact illuminance (Lambert over the visible source) against Monte Carlo and Mitsuba 3, in a room.

The scene: a 4 x 4 m floor at z = 0, a 1.2 x 0.6 m luminaire at 2.8 m facing
down, a table of five boxes (top and four legs). Floor grids of 41 x 41,
201 x 201 and (without ``--quick``) 1001 x 1001 points.

For each grid the script measures points per second of the exact method, of
a compiled Monte Carlo estimator (jittered stratified samples over the
source, exact ray-box occlusion) and of Mitsuba 3 (``llvm_ad_rgb``: the
same room as Mitsuba shapes, each floor point's irradiance by Mitsuba's own
emitter sampling with its visibility rays, its ``independent`` sampler; the
``[bench]`` extra), at the sample counts that reach 1 % (Monte Carlo also
0.1 %) RMS error against the exact values (RMS of the error over the RMS of
the exact values, averaged over seeds), median times over repeats, and the
ratios. Mitsuba's times include its kernel launches (its kernels are
compiled by a first call that is not timed). Without Mitsuba (not
installed, or its LLVM back end failing) its rows say why.

Then the exact method class by class: the receivers the shadow volumes
prove lit (Lambert's formula alone), in umbra (zero) and the rest
(penumbra: the source clipped by the silhouettes), each timed on its own,
with CPU time per point; and the points per second where the source is
fully visible (no occluders).

``--big``: a 10^7-point floor grid (3163 x 3163), its time and the process's
peak memory (the receivers go through in chunks: the memory beyond the
points and the results stays bounded).

With ``--scale``: the same room whose table carries a CSG plate (a box with
six spherical pockets, spheres at resolution 64) over the 201 x 201 floor,
beside the boxes-only room: the time of the first call (the decomposition of
the plate included, caches emptied), of later calls (the decomposition
reused), the convex pieces the receivers need (over all receiver groups), and
points per second; and the plate alone (no table to hide it). ``--full`` adds
the full convex decomposition of the plate (every piece, nothing left out).

Run: ``python benchmarks/illuminance.py [--quick] [--big] [--scale [--full]]``.
"""

from __future__ import annotations

import argparse
import math
import os
import resource
import sys
import time
from pathlib import Path

import numba
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from _common import fmt_rate, fmt_seconds, median_time, print_table  # noqa: E402

import isocsg  # noqa: E402
from isocsg.shadows import AreaLight, illuminance, illuminance_and_state  # noqa: E402
from isocsg.shadows import occluders as occluder_module  # noqa: E402
from isocsg.shadows.direct import CHUNK_POINTS, FEW_PIECES, receiver_tiles  # noqa: E402

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


def mitsuba_scene(lamp, boxes):
    """The room as a Mitsuba 3 scene (llvm_ad_rgb), or the reason it cannot run here."""
    try:
        import drjit as dr
        import mitsuba as mi

        mi.set_variant("llvm_ad_rgb")
    except (ImportError, AttributeError, RuntimeError) as exc:  # not installed, or no LLVM for its JIT
        return None, f"Mitsuba 3 unavailable: {type(exc).__name__}: {exc}"
    T = mi.ScalarTransform4f
    v = lamp.vertices_array
    c, half = v.mean(axis=0), 0.5 * (v.max(axis=0) - v.min(axis=0))
    # Mitsuba's rectangle: [-1, 1]^2 in z = 0 emitting along +z; turned over to face down
    d = {"type": "scene", "lamp": {
        "type": "rectangle",
        "to_world": T().translate(c.tolist()) @ T().scale([half[0], half[1], 1.0]) @ T().rotate([1, 0, 0], 180),
        "emitter": {"type": "area", "radiance": {"type": "rgb", "value": float(lamp.radiance)}}}}
    for k, b in enumerate(boxes):
        lo, hi = np.asarray(b.bounds)
        to_world = T().translate(((lo + hi) / 2).tolist()) @ T().scale(((hi - lo) / 2).tolist())
        d[f"box{k}"] = {"type": "cube", "to_world": to_world}
    try:
        scene = mi.load_dict(d)
        out = (scene, mi, dr)
        mitsuba_irradiance(out, floor(3), 4, 0)
    except (RuntimeError, ValueError, TypeError) as exc:
        return None, f"Mitsuba 3 failed: {type(exc).__name__}: {exc}"
    return out, ""


def mitsuba_irradiance(ms, P, spp, seed, chunk_lanes=1 << 22):
    """Irradiance at floor points (normal +z) by Mitsuba's emitter sampling, ``spp`` samples a point."""
    scene, mi, dr = ms
    out = np.empty(len(P))
    step = max(1, chunk_lanes // spp)
    for c0 in range(0, len(P), step):
        Q = P[c0:c0 + step].astype(np.float32)
        n = len(Q)
        sampler = mi.load_dict({"type": "independent", "sample_count": spp})
        sampler.seed(seed + c0, n * spp)
        idx = dr.arange(mi.UInt32, n * spp) // spp
        it = dr.zeros(mi.SurfaceInteraction3f)
        it.p = dr.gather(mi.Point3f, mi.Point3f(Q[:, 0], Q[:, 1], Q[:, 2]), idx)
        it.n = mi.Normal3f(0, 0, 1)
        it.sh_frame = mi.Frame3f(it.n)
        it.wi = mi.Vector3f(0, 0, 1)
        ds, w = scene.sample_emitter_direction(it, sampler.next_2d(), True)
        tot = dr.zeros(mi.Float, n)
        dr.scatter_reduce(dr.ReduceOp.Add, tot, w.x * dr.maximum(ds.d.z, 0.0), idx)
        out[c0:c0 + n] = np.array(tot, dtype=np.float64) / spp
    return out


def search_spp(ms, P, exact, target, seeds):
    """Smallest sample count (powers of 2 and 1.5 x them) whose mean RMS error over seeds is <= target."""
    for spp in sorted({int(b * 2**j) for j in range(0, 16) for b in (1, 1.5)}):
        err = np.mean([rms_rel(mitsuba_irradiance(ms, P, spp, s), exact) for s in seeds])
        if err <= target:
            return spp, err
    return None, None


def cpu_time(fn, repeats):
    """Median process CPU seconds of fn() (all threads)."""
    ts = []
    for _ in range(max(1, repeats)):
        c0 = time.process_time()
        fn()
        ts.append(time.process_time() - c0)
    return float(np.median(ts))


def run(quick: bool) -> None:
    lamp, boxes = room()
    repeats = 3 if quick else 5
    seeds = (1, 2) if quick else (1, 2, 3)
    # compile once
    illuminance(floor(3), [0, 0, 1], [lamp], boxes)
    mc(floor(3), lamp, boxes, 2, 0)
    ms, why = mitsuba_scene(lamp, boxes)
    rows, ratio_rows = [], []
    for m in (41, 201) if quick else (41, 201, 1001):
        P = floor(m)
        n = len(P)
        grid = f"{m}x{m}"
        t_ex, (E, S) = median_time(lambda: illuminance_and_state(P, [0, 0, 1], [lamp], boxes), repeats)
        c_ex = cpu_time(lambda: illuminance_and_state(P, [0, 0, 1], [lamp], boxes), repeats)
        rows.append((grid, "exact (isocsg)", "-", "-", fmt_seconds(t_ex), fmt_rate(n, t_ex), fmt_rate(n, c_ex)))
        for target in (1e-2,) if m > 201 else (1e-2, 1e-3):
            k, err = search_k(P, lamp, boxes, E, target, seeds)
            if k is None:
                rows.append((grid, f"MC {target:.1%}", "not reached", "-", "-", "-", "-"))
                continue
            t_mc, _ = median_time(lambda: mc(P, lamp, boxes, k, 99), repeats)
            c_mc = cpu_time(lambda: mc(P, lamp, boxes, k, 99), 1)
            rows.append((grid, f"MC {target:.1%}", f"{k * k}", f"{err:.2%}",
                         fmt_seconds(t_mc), fmt_rate(n, t_mc), fmt_rate(n, c_mc)))
            ratio_rows.append((grid, f"Monte Carlo {target:.1%}", f"{t_mc / t_ex:.3g}x"))
        if ms is None:
            rows.append((grid, "Mitsuba 3 1.0%", why, "-", "-", "-", "-"))
        else:
            spp, err = search_spp(ms, P, E, 1e-2, seeds)
            if spp is None:
                rows.append((grid, "Mitsuba 3 1.0%", "not reached", "-", "-", "-", "-"))
            else:
                mitsuba_irradiance(ms, P, spp, 98)  # its kernels for this size compiled
                t_mi, _ = median_time(lambda: mitsuba_irradiance(ms, P, spp, 99), repeats)
                c_mi = cpu_time(lambda: mitsuba_irradiance(ms, P, spp, 99), 1)
                rows.append((grid, "Mitsuba 3 1.0%", f"{spp}", f"{err:.2%}", fmt_seconds(t_mi), fmt_rate(n, t_mi),
                             fmt_rate(n, c_mi)))
                ratio_rows.append((grid, "Mitsuba 3 (llvm) 1.0%", f"{t_mi / t_ex:.3g}x"))
        counts = np.bincount(S, minlength=3)
        rows.append((grid, f"states lit/pen/umb {counts[0]}/{counts[1]}/{counts[2]}", "", "", "", "", ""))
    print_table(
        "Room: floor illuminance, exact vs Monte Carlo and Mitsuba 3 (median times; CPU: all threads)",
        ["grid", "method", "samples", "RMS error", "time", "points/s", "points/CPU s"],
        rows,
    )
    print_table("Speed-up of the exact method", ["grid", "other method, accuracy", "its time / exact time"],
                ratio_rows)
    run_classes(lamp, boxes, repeats, quick)


def run_classes(lamp, boxes, repeats, quick):
    """The exact method on the receivers of each class, and with no occluders."""
    P = floor(1001 if not quick else 401)
    _, S = illuminance_and_state(P, [0, 0, 1], [lamp], boxes)
    rows = []
    for label, sel in (("lit", S == 0), ("umbra", S == 2), ("penumbra", S == 1)):
        Q = P[sel]
        t, _ = median_time(lambda: illuminance_and_state(Q, [0, 0, 1], [lamp], boxes), repeats)
        c = cpu_time(lambda: illuminance_and_state(Q, [0, 0, 1], [lamp], boxes), repeats)
        rows.append((f"{label} floor points of the room", len(Q), fmt_seconds(t), fmt_rate(len(Q), t),
                     f"{c / len(Q) * 1e9:.0f}"))
    nfull = 200_000 if quick else 1_000_000
    Q = np.c_[np.random.default_rng(0).uniform(-2, 2, (nfull, 2)), np.zeros(nfull)]
    t, _ = median_time(lambda: illuminance(Q, [0, 0, 1], [lamp]), repeats)
    c = cpu_time(lambda: illuminance(Q, [0, 0, 1], [lamp]), repeats)
    rows.append(("no occluders", nfull, fmt_seconds(t), fmt_rate(nfull, t), f"{c / nfull * 1e9:.0f}"))
    print_table(
        f"Exact method by class ({int(math.sqrt(len(P)))}^2 floor; states as the exact method reports them)",
        ["receivers", "points", "time", "points/s", "CPU ns/point"],
        rows,
    )


def run_big() -> None:
    """A 10^7-point floor grid: time and peak memory (the receivers go through in chunks)."""
    lamp, boxes = room()
    illuminance(floor(3), [0, 0, 1], [lamp], boxes)
    m = 3163
    P = floor(m)
    rss0 = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    t0, c0 = time.perf_counter(), time.process_time()
    E, S = illuminance_and_state(P, [0, 0, 1], [lamp], boxes)
    t, c = time.perf_counter() - t0, time.process_time() - c0
    rss1 = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    arrays = (P.nbytes + E.nbytes + S.nbytes) / 2**20
    print_table(
        "10^7 receivers (floor grid 3163 x 3163)",
        ["points", "time", "points/s", "points/CPU s", "peak RSS before", "peak RSS after",
         "points + results", "chunk"],
        [(len(P), fmt_seconds(t), fmt_rate(len(P), t), fmt_rate(len(P), c), f"{rss0:.0f} MiB", f"{rss1:.0f} MiB",
          f"{arrays:.0f} MiB", f"{CHUNK_POINTS} points")],
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


def run_rate(repeats: int = 9) -> None:
    """The goal's figure alone: wall points/s of the exact method on the 1001 x 1001 room floor
    (median of ``repeats`` calls after a warm-up call) and the load average (on 2 idle cores it
    should be near 0)."""
    lamp, boxes = room()
    P = floor(1001)
    t, _ = median_time(lambda: illuminance_and_state(P, [0, 0, 1], [lamp], boxes), repeats, warmup=1)
    print(f"room floor 1001 x 1001: {fmt_seconds(t)} median of {repeats}, {fmt_rate(len(P), t)} points/s, "
          f"load average {os.getloadavg()[0]:.2f}")


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="fewer repeats and seeds")
    ap.add_argument("--scale", action="store_true", help="the room with a CSG plate on the table (201 x 201 floor)")
    ap.add_argument("--full", action="store_true", help="with --scale: also the full decomposition of the plate")
    ap.add_argument("--big", action="store_true", help="a 10^7-point floor grid: time and peak memory")
    ap.add_argument("--rate", action="store_true", help="only the exact method's points/s on the 1001 x 1001 floor")
    args = ap.parse_args(argv)
    if args.rate:
        run_rate()
    elif args.big:
        run_big()
    elif args.scale:
        run_scale(args.quick, args.full)
    else:
        run(args.quick)


if __name__ == "__main__":
    main()
