"""Independent Monte Carlo path tracer for interreflected light in a box room with box furniture.

Written without the library's code: rays against axis-aligned boxes (slab
test), Lambertian surfaces, a one-sided rectangular area source facing down.

The indirect illuminance at x (unit normal n) is

    E_ind(x) = int L_out(y) cos dw = E[ rho(y1) H(y1) ]

for y1 the first surface hit along a cosine-distributed direction (pdf cos/pi)
and H the total illuminance there. Unrolled along the path y1, y2, ...:

    E_ind(x) = E[ sum_k (rho_1 ... rho_k) Ed(y_k) ],

Ed(y_k) estimated by one uniform sample of the source (next-event estimation,
shadow ray against the furniture). Paths stop when their throughput
rho_1...rho_k falls below ``cutoff`` (a relative bias below ``cutoff / (1 -
rho_max)``). As in the library, the source neither reflects nor blocks
light, and the room blocks nothing inside it.

The standard error is the spread of the per-path sums over sqrt(N).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass
class MCRoom:
    lo: np.ndarray  # room interior bounds
    hi: np.ndarray
    rho_floor: float
    rho_walls: float
    rho_ceiling: float
    boxes: list  # (lo, hi, rho)
    light_lo: np.ndarray  # horizontal rectangle facing down at height light_z
    light_hi: np.ndarray
    light_z: float
    radiance: float


def _cosine_dirs(n: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    m = len(n)
    u1, u2 = rng.random(m), rng.random(m)
    r, phi = np.sqrt(u1), 2 * np.pi * u2
    local = np.c_[r * np.cos(phi), r * np.sin(phi), np.sqrt(np.maximum(1 - u1, 0))]
    a = np.where(np.abs(n[:, :1]) < 0.9, np.array([[1.0, 0, 0]]), np.array([[0, 1.0, 0]]))
    t = np.cross(n, a)
    t /= np.linalg.norm(t, axis=1)[:, None]
    b = np.cross(n, t)
    return local[:, :1] * t + local[:, 1:2] * b + local[:, 2:] * n


def _box_hit(o, d, lo, hi):
    """Entry distance of rays into a box from outside (inf if missed), and the entry face normal."""
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = (lo - o) / d
        t2 = (hi - o) / d
    tn = np.where(np.isnan(t1), -np.inf, np.minimum(t1, t2))
    tf = np.where(np.isnan(t1), np.inf, np.maximum(t1, t2))
    tenter = tn.max(axis=1)
    texit = tf.min(axis=1)
    hit = (tenter <= texit) & (tenter > 1e-9)
    ax = tn.argmax(axis=1)
    nrm = np.zeros_like(o)
    nrm[np.arange(len(o)), ax] = -np.sign(d[np.arange(len(o)), ax])
    return np.where(hit, tenter, np.inf), nrm


def _blocked(p, q, boxes):
    """Segments p -> q crossing the inside of any box."""
    d = q - p
    out = np.zeros(len(p), dtype=bool)
    for lo, hi, _ in boxes:
        with np.errstate(divide="ignore", invalid="ignore"):
            t1 = (lo - p) / d
            t2 = (hi - p) / d
        tn = np.where(np.isnan(t1), -np.inf, np.minimum(t1, t2)).max(axis=1)
        tf = np.where(np.isnan(t1), np.inf, np.maximum(t1, t2)).min(axis=1)
        inside_par = np.all((d != 0) | ((p > lo) & (p < hi)), axis=1)
        a, b = np.maximum(tn, 1e-9), np.minimum(tf, 1 - 1e-9)
        out |= inside_par & (b - a > 1e-9)
    return out


def _direct(room: MCRoom, y, n, rng):
    m = len(y)
    q = np.c_[room.light_lo[0] + rng.random(m) * (room.light_hi[0] - room.light_lo[0]),
              room.light_lo[1] + rng.random(m) * (room.light_hi[1] - room.light_lo[1]),
              np.full(m, room.light_z)]
    area = float(np.prod(room.light_hi[:2] - room.light_lo[:2]))
    w = q - y
    r2 = np.einsum("ij,ij->i", w, w)
    r = np.sqrt(r2)
    cy = np.einsum("ij,ij->i", n, w) / r
    cl = w[:, 2] / r  # the source faces down: its normal is -z, cos = -(-z).w / r
    ok = (cy > 0) & (cl > 0)
    e = np.where(ok, room.radiance * area * cy * cl / r2, 0.0)
    if ok.any():
        idx = np.nonzero(ok)[0]
        e[idx[_blocked(y[idx], q[idx], room.boxes)]] = 0.0
    return e


def _trace(room: MCRoom, o, d, rng):
    """First hit: position, inward normal and reflectance (room faces from inside, boxes from outside)."""
    m = len(o)
    with np.errstate(divide="ignore"):
        tl = np.where(d < 0, (room.lo - o) / d, np.inf)
        th = np.where(d > 0, (room.hi - o) / d, np.inf)
    t_all = np.minimum(tl, th)
    ax = t_all.argmin(axis=1)
    t = t_all[np.arange(m), ax]
    nrm = np.zeros_like(o)
    nrm[np.arange(m), ax] = -np.sign(d[np.arange(m), ax])
    rho = np.where(ax == 2, np.where(d[:, 2] < 0, room.rho_floor, room.rho_ceiling), room.rho_walls)
    for lo, hi, rb in room.boxes:
        tb, nb = _box_hit(o, d, lo, hi)
        closer = tb < t
        t = np.where(closer, tb, t)
        nrm = np.where(closer[:, None], nb, nrm)
        rho = np.where(closer, rb, rho)
    return o + t[:, None] * d, nrm, rho


def mc_indirect(room: MCRoom, x, n, *, paths: int = 100_000, cutoff: float = 1e-6, seed: int = 7):
    """Indirect illuminance at each point: (estimate, standard error) arrays."""
    rng = np.random.default_rng(seed)
    x = np.atleast_2d(np.asarray(x, float))
    n = np.broadcast_to(np.asarray(n, float), x.shape)
    est, err = np.zeros(len(x)), np.zeros(len(x))
    for i in range(len(x)):
        o = np.repeat(x[i : i + 1], paths, axis=0)
        nn = np.repeat(n[i : i + 1] / np.linalg.norm(n[i]), paths, axis=0)
        total = np.zeros(paths)
        thr = np.ones(paths)
        alive = np.arange(paths)
        while len(alive):
            d = _cosine_dirs(nn, rng)
            y, ny, rho = _trace(room, o, d, rng)
            thr[alive] *= rho
            total[alive] += thr[alive] * _direct(room, y, ny, rng)
            keep = thr[alive] > cutoff
            alive, o, nn = alive[keep], y[keep], ny[keep]
        est[i] = total.mean()
        err[i] = total.std(ddof=1) / np.sqrt(paths)
    return est, err
