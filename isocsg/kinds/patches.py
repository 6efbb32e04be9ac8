"""Surfaces as one-parameter families of rings: what the area integration of :mod:`isocsg.testing` sweeps.

A *patch* is a smooth piece of a leaf's surface (a sphere, a truncus' side or one of its
end discs, a face of a box or polyhedron, ...) written as ``x(s, t)``: for each sweep
parameter ``s`` in ``[s_lo, s_hi]`` a *ring*, either

- a trigonometric curve ``c(s) + A(s) cos t + B(s) sin t``, ``t`` in ``[0, 2 pi)`` (a circle or
  an ellipse: spheres, ellipsoids, truncus sides, tori), or
- a segment ``c(s) + t A(s)``, ``t`` in ``[t0(s), t1(s)]`` (planar faces and end discs),

with the exact area density ``weight(s, t)`` (``dA = weight ds dt``) and the outward unit
normal. Where the sweep parameter is (a function of) the height along a world direction,
``s_of_height`` maps other leaves' breakpoints (:meth:`~isocsg.kinds.base.Primitive.breakpoints`)
to ``s``: the ring measure can jump there (a box face cutting a sphere's ring).

Each kind's :meth:`~isocsg.kinds.base.Primitive.surface_patches` calls the family of its surface
here with its own data (a ball's centre and radius, a frustum's frame, a torus's radii, a
polytope's faces); none of these functions names a kind.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .affine import perpendicular_frame as _perpendicular_frame

__all__ = [
    "Patch", "Rings", "affine_ball_patches", "ball_patches", "elliptic_lateral_area", "ellipsoid_area",
    "face_normals", "frustum_patches", "affine_frustum_patches", "polygon_patch", "polytope_patches", "torus_patches",
]

F64 = NDArray[np.float64]


@dataclass(frozen=True, slots=True)
class Rings:
    """A batch of rings at sweep parameters ``s`` (k of them): ``c``, ``A``, ``B`` (k, 3) and the
    ``t`` range ``t0``, ``t1`` (k,). ``trig``: ``x = c + A cos t + B sin t``; else ``x = c + t A``."""

    trig: bool
    c: F64
    A: F64
    B: F64
    t0: F64
    t1: F64

    def points(self, ring: NDArray[np.int64], t: F64) -> F64:
        """Points of rings ``ring`` (n,) at parameters ``t`` (n,)."""
        if self.trig:
            return self.c[ring] + self.A[ring] * np.cos(t)[:, None] + self.B[ring] * np.sin(t)[:, None]  # type: ignore[no-any-return]
        return self.c[ring] + self.A[ring] * t[:, None]  # type: ignore[no-any-return]


@dataclass(frozen=True, slots=True)
class Patch:
    """One smooth piece of a leaf's surface as a family of rings (see the module docstring)."""

    leaf: int
    s_lo: float
    s_hi: float
    breaks: F64
    rings: Callable[[F64], Rings]
    weight: Callable[[F64, F64], F64]
    normal: Callable[[F64, F64], F64]
    direction: F64 | None = None
    s_of_height: Callable[[F64], F64] | None = None
    closed_area: float = math.nan  # the patch's whole area, exact


def _unit(v: F64) -> F64:
    return v / np.linalg.norm(v, axis=-1, keepdims=True)  # type: ignore[no-any-return]


def _const(k: int, v: F64) -> F64:
    return np.broadcast_to(np.asarray(v, dtype=np.float64), (k, 3)).copy()


def ball_patches(i: int, c: F64, r: float) -> list[Patch]:
    """A sphere of centre ``c`` and radius ``r``: rings across z."""
    ex, ey, ez = np.eye(3)

    def rings(s: F64) -> Rings:
        rho = np.sqrt(np.maximum(r * r - s * s, 0.0))[:, None]
        k = len(s)
        return Rings(True, c + s[:, None] * ez, rho * ex, rho * ey, np.zeros(k), np.full(k, 2 * math.pi))

    def normal(s: F64, t: F64) -> F64:
        rho = np.sqrt(np.maximum(r * r - s * s, 0.0))
        return np.stack([rho * np.cos(t), rho * np.sin(t), s], axis=1) / r  # type: ignore[no-any-return]

    return [Patch(i, -r, r, np.array([-r, r]), rings, lambda s, t: np.full(len(s), r), normal,
                  ez, lambda h: h - c[2], 4 * math.pi * r * r)]


def affine_ball_patches(i: int, c: F64, L: F64, radii: F64) -> list[Patch]:
    """The ellipsoid ``c + L u`` (``|u| <= 1``) with semi-axes ``radii``: the unit sphere's rings, mapped."""
    det = abs(float(np.linalg.det(L)))
    Linv_t = np.linalg.inv(L).T

    def rings(s: F64) -> Rings:
        rho = np.sqrt(np.maximum(1.0 - s * s, 0.0))[:, None]
        k = len(s)
        return Rings(True, c + s[:, None] * L[:, 2], rho * L[:, 0], rho * L[:, 1], np.zeros(k), np.full(k, 2 * math.pi))

    def grad(s: F64, t: F64) -> F64:
        rho = np.sqrt(np.maximum(1.0 - s * s, 0.0))
        u = np.stack([rho * np.cos(t), rho * np.sin(t), s], axis=1)
        return u @ Linv_t.T  # type: ignore[no-any-return]

    return [Patch(i, -1.0, 1.0, np.array([-1.0, 1.0]), rings,
                  lambda s, t: det * np.linalg.norm(grad(s, t), axis=1), lambda s, t: _unit(grad(s, t)),
                  closed_area=ellipsoid_area(*np.asarray(radii, dtype=np.float64)))]


def ellipsoid_area(a: float, b: float, c: float) -> float:
    """Exact surface area of the ellipsoid with semi-axes ``a, b, c`` (Carlson's symmetric forms:
    ``4 pi a b c R_G(1/a^2, 1/b^2, 1/c^2)``, ``R_G`` from scipy's ``elliprf`` and ``elliprd``)."""
    from scipy.special import elliprd, elliprf

    x, y, z = sorted((1.0 / (a * a), 1.0 / (b * b), 1.0 / (c * c)), reverse=True)  # z smallest: R_D stays tame
    rg = 0.5 * (z * elliprf(x, y, z) - (x - z) * (y - z) * elliprd(x, y, z) / 3.0 + math.sqrt(x * y / z))
    return float(4.0 * math.pi * a * b * c * rg)


def _disc(i: int, centre: F64, e1: F64, e2: F64, n: F64, R: float, scale: float) -> Patch:
    """An end disc of radius ``R`` in the plane spanned by ``e1``, ``e2`` (both of length giving
    ``scale`` = the world area of a unit square of (e1, e2)), swept by ``s = asin(x / R)``."""
    k0 = float(centre @ e1) / float(e1 @ e1)

    def rings(s: F64) -> Rings:
        x = R * np.sin(s)
        h = R * np.cos(s)
        k = len(s)
        return Rings(False, centre + x[:, None] * e1, _const(k, e2), _const(k, e2), -h, h)

    direction = _unit(e1) if abs(float(np.linalg.norm(e1)) - 1.0) < 1e-12 else None

    def s_of_height(hh: F64) -> F64:
        return np.arcsin(np.clip((hh - k0) / R, -1.0, 1.0))  # type: ignore[no-any-return]

    return Patch(i, -math.pi / 2, math.pi / 2, np.array([-math.pi / 2, math.pi / 2]), rings,
                 lambda s, t: R * np.cos(s) * scale, lambda s, t: _const(len(s), n),
                 direction, s_of_height if direction is not None else None, math.pi * R * R * scale)


def frustum_patches(i: int, ct: F64, a: F64, h: float, r1: float, r2: float) -> list[Patch]:
    """A right circular truncus (centre ``ct``, unit axis ``a``, height ``h``, radius ``r1`` at
    ``ct + a h / 2``): its side swept along the axis and its end discs."""
    e1, e2 = _perpendicular_frame(a)
    k = (r1 - r2) / h
    slant = math.sqrt(1.0 + k * k)
    c0 = float(ct @ a)

    def radius(s: F64) -> F64:
        return r2 + (r1 - r2) * (s + h / 2) / h  # type: ignore[no-any-return]

    def rings(s: F64) -> Rings:
        r = radius(s)[:, None]
        m = len(s)
        return Rings(True, ct + s[:, None] * a, r * e1, r * e2, np.zeros(m), np.full(m, 2 * math.pi))

    def normal(s: F64, t: F64) -> F64:
        v = np.cos(t)[:, None] * e1 + np.sin(t)[:, None] * e2 - k * a
        return _unit(v)

    out = [Patch(i, -h / 2, h / 2, np.array([-h / 2, h / 2]), rings, lambda s, t: radius(s) * slant, normal,
                 a, lambda hh: hh - c0, math.pi * (r1 + r2) * math.sqrt((r1 - r2) ** 2 + h * h))]
    if r1 > 0:
        out.append(_disc(i, ct + a * h / 2, e1, e2, a, r1, 1.0))
    if r2 > 0:
        out.append(_disc(i, ct - a * h / 2, e1, -e2, -a, r2, 1.0))
    return out


def affine_frustum_patches(i: int, ct: F64, M: F64, r1: float, r2: float) -> list[Patch]:
    """The image ``ct + M x`` of the canonical truncus (unit height along z, radius ``r1`` at
    ``z = 1/2``): its side swept along the mapped axis and its two elliptic ends."""
    det = abs(float(np.linalg.det(M)))
    Mit = np.linalg.inv(M).T
    dr = r1 - r2

    def radius(s: F64) -> F64:
        return r2 + dr * (s + 0.5)  # type: ignore[no-any-return]

    def rings(s: F64) -> Rings:
        r = radius(s)[:, None]
        m = len(s)
        return Rings(True, ct + s[:, None] * M[:, 2], r * M[:, 0], r * M[:, 1], np.zeros(m), np.full(m, 2 * math.pi))

    def grad(s: F64, t: F64) -> F64:
        return np.stack([np.cos(t), np.sin(t), np.full(len(t), -dr)], axis=1) @ Mit.T  # type: ignore[no-any-return]

    out = [Patch(i, -0.5, 0.5, np.array([-0.5, 0.5]), rings,
                 lambda s, t: det * radius(s) * np.linalg.norm(grad(s, t), axis=1), lambda s, t: _unit(grad(s, t)),
                 closed_area=elliptic_lateral_area(M, r1, r2))]
    nz = Mit @ np.array([0.0, 0.0, 1.0])
    cap = det * float(np.linalg.norm(nz))
    n_top = nz / np.linalg.norm(nz)
    if r1 > 0:
        out.append(_disc(i, ct + M[:, 2] / 2, M[:, 0], M[:, 1], n_top, r1, cap))
    if r2 > 0:
        out.append(_disc(i, ct - M[:, 2] / 2, M[:, 0], -M[:, 1], -n_top, r2, cap))
    return out


def elliptic_lateral_area(M: F64, r1: float, r2: float, n: int = 64) -> float:
    """Lateral area of the image under ``M`` of the canonical truncus (unit height, radii ``r1`` at
    ``z = 1/2``, ``r2`` at ``-1/2``): ``|det M| (r1 + r2) / 2 * integral_0^2pi |M^-T (cos t, sin t,
    r2 - r1)| dt``. The integrand is periodic and analytic, so the trapezoidal rule converges
    geometrically; ``n`` is doubled until two rules agree to 1e-15."""
    det = abs(float(np.linalg.det(M)))
    Mit = np.linalg.inv(np.asarray(M, dtype=np.float64)).T
    prev = math.nan
    while n <= 1 << 20:
        t = np.arange(n) * (2 * math.pi / n)
        g = np.stack([np.cos(t), np.sin(t), np.full(n, r2 - r1)], axis=1) @ Mit.T
        val = float(np.linalg.norm(g, axis=1).sum() * (2 * math.pi / n))
        if abs(val - prev) <= 1e-15 * abs(val):
            break
        prev, n = val, 2 * n
    return det * 0.5 * (r1 + r2) * val


def torus_patches(i: int, c: F64, axis: F64, R: float, r: float) -> list[Patch]:
    """A ring torus (centre ``c``, ``axis``, major radius ``R``, minor ``r``): rings about the axis,
    swept by the tube's angle."""
    a = np.asarray(axis, dtype=np.float64)
    a = a / np.linalg.norm(a)
    e1, e2 = _perpendicular_frame(a)
    c0 = float(c @ a)

    def rings(s: F64) -> Rings:
        rho = (R + r * np.cos(s))[:, None]
        m = len(s)
        return Rings(True, c + (r * np.sin(s))[:, None] * a, rho * e1, rho * e2, np.zeros(m), np.full(m, 2 * math.pi))

    def normal(s: F64, t: F64) -> F64:
        radial = np.cos(t)[:, None] * e1 + np.sin(t)[:, None] * e2
        return np.cos(s)[:, None] * radial + np.sin(s)[:, None] * a  # type: ignore[no-any-return]

    def s_of_height(hh: F64) -> F64:
        z = np.arcsin(np.clip((hh - c0) / r, -1.0, 1.0))
        return np.mod(np.concatenate([z, math.pi - z]), 2 * math.pi)  # type: ignore[no-any-return]

    return [Patch(i, 0.0, 2 * math.pi, np.array([0.0, math.pi / 2, math.pi, 1.5 * math.pi, 2 * math.pi]), rings,
                  lambda s, t: r * (R + r * np.cos(s)), normal, a, s_of_height, 4 * math.pi**2 * R * r)]


def polygon_patch(i: int, V: F64, n: F64) -> Patch:
    """A planar convex polygon ``V`` (k, 3), counter-clockwise seen from outside (normal ``n``)."""
    e1 = _unit(V[1] - V[0])
    e2 = np.cross(n, e1)
    q = np.stack([(V - V[0]) @ e1, (V - V[0]) @ e2], axis=1)
    if float(np.sum(q[:, 0] * np.roll(q[:, 1], -1) - np.roll(q[:, 0], -1) * q[:, 1])) < 0:
        q = q[::-1].copy()  # counter-clockwise in (e1, e2)
    d = np.roll(q, -1, axis=0) - q
    lower, upper = d[:, 0] > 0, d[:, 0] < 0
    qx, qy, dx, dy = q[:, 0], q[:, 1], d[:, 0], d[:, 1]
    k0 = float(V[0] @ e1)
    area = 0.5 * float(np.sum(qx * np.roll(qy, -1) - np.roll(qx, -1) * qy))

    def rings(s: F64) -> Rings:
        with np.errstate(divide="ignore", invalid="ignore"):
            y = qy[None, :] + dy[None, :] * (s[:, None] - qx[None, :]) / dx[None, :]
        t0 = np.max(np.where(lower[None, :], y, -np.inf), axis=1)
        t1 = np.min(np.where(upper[None, :], y, np.inf), axis=1)
        m = len(s)
        return Rings(False, V[0] + s[:, None] * e1, _const(m, e2), _const(m, e2), t0, np.maximum(t1, t0))

    return Patch(i, float(qx.min()), float(qx.max()), np.unique(qx), rings,
                 lambda s, t: np.ones(len(s)), lambda s, t: _const(len(s), n), e1, lambda hh: hh - k0, area)


def polytope_patches(i: int, polys: list[F64], normals: F64) -> list[Patch]:
    """A convex polytope from its face polygons (each counter-clockwise seen from outside) and
    its faces' outward normals (matched to the polygons by their own orientation)."""
    return [polygon_patch(i, np.asarray(V, dtype=np.float64), np.asarray(nv, dtype=np.float64))
            for V, nv in zip(polys, face_normals(polys, normals))]


def face_normals(polys: list[F64], normals: F64) -> list[F64]:
    """The outward normal of each face polygon (matched by its own orientation)."""
    out = []
    for V in polys:
        V = np.asarray(V, dtype=np.float64)
        m = np.cross(V[1:-1] - V[0], V[2:] - V[0]).sum(axis=0)
        m = m / np.linalg.norm(m)
        out.append(np.asarray(normals, dtype=np.float64)[int(np.argmax(np.asarray(normals) @ m))])
    return out
