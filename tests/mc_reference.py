"""Independent Monte Carlo reference for illuminance from area and polyhedron sources.

Written without the library's shadow code: the integrand is the textbook one,

    E(p) = L * integral over the source of V(p, q) cos(theta_p)+ cos(theta_q)+ / |q - p|^2 dA,

estimated with jittered stratified samples over the source area (each convex
face fanned into triangles, a k x k grid of strata per triangle mapped with
the area-preserving square-to-triangle warp). A polyhedron source is sampled
over its faces facing p (the others get cos(theta_q) <= 0 and weight 0).

Occlusion is exact: the segment p -> q is clipped against each occluder's
half-spaces (Liang-Barsky); an occluder is a union of convex "plus" parts
minus a union of convex "minus" parts (enough for a primitive and for
``A - B``), so CSG is judged from the primitives' own half-spaces, not from
the library's decomposition. Curved occluders are passed in tessellated at
the library's resolution (``to_polyhedron``), so both sides judge the same
geometry.

The standard error comes from R independent replicates (different jitter):
the mean of the replicates is the estimate, their standard deviation over
sqrt(R) its standard error.

Where no sample at all saw the source, the replicates agree on 0 with a
standard error of 0, and that interval says nothing: a visible sliver smaller
than a stratum is missed by every replicate with a fair probability. There
the interval is the one-sided binomial bound instead (:attr:`MCResult.zero_hit_bound`):
if a sample in stratum j hits with probability p_j and would contribute at
most c (the largest single-sample contribution seen, ``L w cos cos / r^2``,
or ``L w / r^2`` where no sample lay in front of both planes), then
E <= c * sum p_j, and all R replicates miss with probability
prod (1 - p_j)^R <= exp(-R E / c). So zero hits happen with probability
below alpha only if E <= ln(1 / alpha) c / R; alpha = 1e-4, about that of a
4-sigma interval.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numba
import numpy as np

SEG_EPS = 1e-9  # a segment is blocked only if it runs at least this long (in t) inside an occluder
ZERO_HIT_ALPHA = 1e-4  # false-alarm probability of the zero-hit bound (a 4-sigma interval's is 6e-5)


@dataclass
class MCOccluder:
    """Union of convex ``plus`` parts minus the union of convex ``minus`` parts; each part (normals, offsets)."""

    plus: list
    minus: list


def convex(normals, offsets) -> MCOccluder:
    return MCOccluder([(np.asarray(normals, float), np.asarray(offsets, float))], [])


def box_halfspaces(center, size):
    c = np.asarray(center, float)
    h = np.asarray(size, float) / 2
    n = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], float)
    return n, n @ c + np.abs(n) @ h


def hull_halfspaces(points):
    """Half-spaces of the convex hull of points (scipy's qhull, independent of isocsg)."""
    from scipy.spatial import ConvexHull

    h = ConvexHull(np.asarray(points, float))
    return h.equations[:, :3].copy(), -h.equations[:, 3].copy()


def _pack(occluders: list[MCOccluder]):
    parts_n, parts_d, part_off, part_occ, part_sign = [], [], [0], [], []
    for k, o in enumerate(occluders):
        for sign, lst in ((1, o.plus), (-1, o.minus)):
            for n, d in lst:
                parts_n.append(n)
                parts_d.append(d)
                part_off.append(part_off[-1] + len(d))
                part_occ.append(k)
                part_sign.append(sign)
    if not parts_n:
        return np.zeros((0, 3)), np.zeros(0), np.zeros(1, np.int64), np.zeros(0, np.int64), np.zeros(0, np.int64)
    return (np.vstack(parts_n), np.concatenate(parts_d), np.array(part_off, np.int64),
            np.array(part_occ, np.int64), np.array(part_sign, np.int64))


def _triangles(polygons):
    tri = []
    for q in polygons:
        q = np.asarray(q, float)
        for i in range(1, len(q) - 1):
            tri.append((q[0], q[i], q[i + 1]))
    return np.array(tri, float).reshape(-1, 3, 3)


@numba.njit(cache=True)
def _segment_interval(p, q, pn, pd, a, b):
    """[t0, t1] of the segment p + t (q - p), t in [0, 1], inside the convex part pn[a:b] . x <= pd."""
    t0 = 0.0
    t1 = 1.0
    for i in range(a, b):
        num = pd[i] - (pn[i, 0] * p[0] + pn[i, 1] * p[1] + pn[i, 2] * p[2])
        den = pn[i, 0] * (q[0] - p[0]) + pn[i, 1] * (q[1] - p[1]) + pn[i, 2] * (q[2] - p[2])
        if den == 0.0:
            if num < 0.0:
                return 1.0, 0.0
        elif den > 0.0:
            t1 = min(t1, num / den)
        else:
            t0 = max(t0, num / den)
        if t0 >= t1:
            return 1.0, 0.0
    return t0, t1


@numba.njit(cache=True)
def _blocked(p, q, pn, pd, poff, pocc, psign, nocc):
    npart = pocc.shape[0]
    for k in range(nocc):
        for j in range(npart):
            if pocc[j] != k or psign[j] < 0:
                continue
            t0, t1 = _segment_interval(p, q, pn, pd, poff[j], poff[j + 1])
            if t1 - t0 <= SEG_EPS:
                continue
            # subtract the minus parts of occluder k from [t0, t1] (a list of up to 16 intervals)
            lo = np.empty(16)
            hi = np.empty(16)
            lo[0] = t0
            hi[0] = t1
            m = 1
            for jj in range(npart):
                if pocc[jj] != k or psign[jj] > 0:
                    continue
                s0, s1 = _segment_interval(p, q, pn, pd, poff[jj], poff[jj + 1])
                if s1 <= s0:
                    continue
                lo2 = np.empty(16)
                hi2 = np.empty(16)
                m2 = 0
                for r in range(m):
                    if s1 <= lo[r] or s0 >= hi[r]:
                        lo2[m2] = lo[r]
                        hi2[m2] = hi[r]
                        m2 += 1
                        continue
                    if s0 > lo[r]:
                        lo2[m2] = lo[r]
                        hi2[m2] = s0
                        m2 += 1
                    if s1 < hi[r]:
                        lo2[m2] = s1
                        hi2[m2] = hi[r]
                        m2 += 1
                m = m2
                for r in range(m):
                    lo[r] = lo2[r]
                    hi[r] = hi2[r]
            for r in range(m):
                if hi[r] - lo[r] > SEG_EPS:
                    return True
    return False


@numba.njit(cache=True, parallel=True)
def _mc_kernel(P, NR, tris, tri_L, k, R, pn, pd, poff, pocc, psign, nocc, seed, est, nvis, ngeo, cmax):
    n = P.shape[0]
    ntri = tris.shape[0]
    for i in numba.prange(n):
        np.random.seed(seed + i)  # noqa: NPY002 - numba's per-thread generator, seeded per point
        p = P[i]
        nr = NR[i]
        q = np.empty(3)
        for r in range(R):
            acc = 0.0
            for t in range(ntri):
                a = tris[t, 0]
                b = tris[t, 1]
                c = tris[t, 2]
                e1 = b - a
                e2 = c - a
                cx = e1[1] * e2[2] - e1[2] * e2[1]
                cy = e1[2] * e2[0] - e1[0] * e2[2]
                cz = e1[0] * e2[1] - e1[1] * e2[0]
                twice = math.sqrt(cx * cx + cy * cy + cz * cz)
                nx = cx / twice
                ny = cy / twice
                nz = cz / twice
                w = 0.5 * twice / (k * k)
                for si in range(k):
                    for ti in range(k):
                        s = (si + np.random.random()) / k  # noqa: NPY002 - numba's per-thread generator
                        tt = (ti + np.random.random()) / k  # noqa: NPY002 - numba's per-thread generator
                        rs = math.sqrt(s)
                        wa = 1.0 - rs
                        wb = rs * (1.0 - tt)
                        wc = rs * tt
                        for d in range(3):
                            q[d] = wa * a[d] + wb * b[d] + wc * c[d]
                        dx = q[0] - p[0]
                        dy = q[1] - p[1]
                        dz = q[2] - p[2]
                        r2 = dx * dx + dy * dy + dz * dz
                        rl = math.sqrt(r2)
                        cp = (nr[0] * dx + nr[1] * dy + nr[2] * dz) / rl
                        cq = -(nx * dx + ny * dy + nz * dz) / rl  # the triangle emits along its normal
                        if cp <= 0.0 or cq <= 0.0:
                            cmax[i, 1] = max(cmax[i, 1], tri_L[t] * w / r2)
                            continue
                        ngeo[i] += 1
                        cmax[i, 0] = max(cmax[i, 0], tri_L[t] * w * cp * cq / r2)
                        if _blocked(p, q, pn, pd, poff, pocc, psign, nocc):
                            continue
                        nvis[i] += 1
                        acc += tri_L[t] * w * cp * cq / r2
            est[i, r] = acc


@dataclass
class MCResult:
    mean: np.ndarray
    se: np.ndarray
    visible_fraction: np.ndarray  # nan where no sample lies in front of both planes
    zero_hit_bound: np.ndarray  # where no sample saw the source: E below this with probability 1 - ZERO_HIT_ALPHA; else 0

    def tolerance(self, exact, sigmas: float = 4.0) -> np.ndarray:
        """Half-width of the interval that ``exact`` must lie in around :attr:`mean`.

        ``sigmas`` standard errors, widened to the zero-hit bound where no
        sample saw the source (the standard error is 0 there and says nothing),
        plus 1e-12 relative for rounding.
        """
        exact = np.asarray(exact, float)
        return np.maximum(sigmas * self.se, self.zero_hit_bound) + 1e-12 * np.maximum(1.0, np.abs(exact))


def mc_illuminance(points, normals, sources, occluders, *, k=16, replicates=32, seed=1) -> MCResult:
    """Estimate E at points.

    ``sources``: list of (polygons, radiance), each polygon counter-clockwise
    seen from its emitting side (an area light: one polygon; a polyhedron:
    its faces, outward). ``occluders``: list of :class:`MCOccluder`.
    """
    P = np.ascontiguousarray(np.atleast_2d(np.asarray(points, float)))
    NR = np.atleast_2d(np.asarray(normals, float))
    NR = np.ascontiguousarray(np.broadcast_to(NR / np.linalg.norm(NR, axis=1, keepdims=True), P.shape))
    tris, tri_L = [], []
    for polys, L in sources:
        t = _triangles(polys)
        tris.append(t)
        tri_L += [float(L)] * len(t)
    tris = np.ascontiguousarray(np.vstack(tris))
    pn, pd, poff, pocc, psign = _pack(occluders)
    est = np.zeros((len(P), replicates))
    nvis = np.zeros(len(P), np.int64)
    ngeo = np.zeros(len(P), np.int64)
    cmax = np.zeros((len(P), 2))  # largest single-sample contribution: in front of both planes; otherwise L w / r^2
    _mc_kernel(P, NR, tris, np.array(tri_L), k, replicates, np.ascontiguousarray(pn), pd, poff, pocc, psign,
               len(occluders), seed, est, nvis, ngeo, cmax)
    mean = est.mean(axis=1)
    se = est.std(axis=1, ddof=1) / math.sqrt(replicates)
    with np.errstate(invalid="ignore", divide="ignore"):
        frac = np.where(ngeo > 0, nvis / np.maximum(ngeo, 1), np.nan)
    c = np.where(ngeo > 0, cmax[:, 0], cmax[:, 1])
    bound = np.where(nvis == 0, math.log(1.0 / ZERO_HIT_ALPHA) * c / replicates, 0.0)
    return MCResult(mean, se, frac, bound)


def mc_refined(points, normals, sources, occluders, *, k=16, replicates=32, seed=1, rare=0.01, k_fine=48,
               replicates_fine=16) -> MCResult:
    """:func:`mc_illuminance`, re-estimated with finer strata where few samples were visible.

    Where the visible fraction is below ``rare`` (zero included: a visible
    sliver smaller than one stratum can be missed by every replicate, and the
    replicates then agree on 0 with a standard error of 0), the estimate is
    redone with ``k_fine x k_fine`` strata per triangle, so that the interval
    rests on enough visible samples.
    """
    res = mc_illuminance(points, normals, sources, occluders, k=k, replicates=replicates, seed=seed)
    P = np.atleast_2d(np.asarray(points, float))
    NR = np.broadcast_to(np.atleast_2d(np.asarray(normals, float)), P.shape)
    redo = np.nonzero(np.nan_to_num(res.visible_fraction, nan=1.0) < rare)[0]
    if len(redo):
        fine = mc_illuminance(P[redo], NR[redo], sources, occluders, k=k_fine, replicates=replicates_fine, seed=seed + 7919)
        res.mean[redo], res.se[redo], res.visible_fraction[redo] = fine.mean, fine.se, fine.visible_fraction
        res.zero_hit_bound[redo] = fine.zero_hit_bound
    return res


def mc_recheck(points, normals, sources, occluders, exact, result: MCResult, *, sigmas=4.0, k=16, replicates=128,
               seed=104729) -> MCResult:
    """Re-estimate, independently and with more samples, the points outside ``sigmas`` standard errors.

    A 4-sigma interval from 32 replicates is crossed now and then by chance
    (the standard error is itself estimated); a real discrepancy persists in a
    second, independent and more precise estimate, which replaces the first
    at those points.
    """
    exact = np.asarray(exact, float)
    bad = np.nonzero(np.abs(exact - result.mean) > result.tolerance(exact, sigmas))[0]
    if len(bad):
        P = np.atleast_2d(np.asarray(points, float))
        NR = np.broadcast_to(np.atleast_2d(np.asarray(normals, float)), P.shape)
        again = mc_illuminance(P[bad], NR[bad], sources, occluders, k=k, replicates=replicates, seed=seed)
        result.mean[bad], result.se[bad], result.visible_fraction[bad] = again.mean, again.se, again.visible_fraction
        result.zero_hit_bound[bad] = again.zero_hit_bound
    return result
