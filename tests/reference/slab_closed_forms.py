"""Closed forms for a solid of revolution minus a thin plate parallel to its axis, and a napkin ring.

The solid (a cone, a cylinder or a sphere) has its axis along x in its own frame; the plate is
``|z - z0| < w`` and, for a half plate, ``y > 0`` (its edge on the axis plane), long enough to
cross the whole solid in x. Volume and area of ``solid - plate`` by integrating the exact section
areas and surface strips in z (antiderivatives written out here, independent of isocsg).
"""

from __future__ import annotations

import math
from dataclasses import dataclass


def _clip(z: float, r: float) -> float:
    return min(max(z, -r), r)


def _circle_strip(z: float, r: float) -> float:
    """integral_0^z sqrt(r^2 - t^2) dt (z clipped to [-r, r])."""
    z = _clip(z, r)
    return 0.5 * (z * math.sqrt(max(r * r - z * z, 0.0)) + r * r * math.asin(z / r))


def _cone_section_integral(z: float, r: float) -> float:
    """integral_0^z G(|t|) dt, G(d) = (r sqrt(r^2 - d^2) - d^2 acosh(r / d)) / 2 (odd in z)."""
    s = 1.0 if z >= 0 else -1.0
    z = min(abs(z), r)
    if z == 0.0:
        return 0.0
    root = math.sqrt(max(r * r - z * z, 0.0))
    p = z**3 / 3.0 * math.acosh(r / z) + r / 6.0 * (r * r * math.asin(z / r) - z * root)
    return s * (0.5 * r * _circle_strip(z, r) - 0.5 * p)


def _asin_moment(c: float, r: float) -> float:
    """integral_0^r rho asin(clip(c / rho, -1, 1)) d rho."""
    if abs(c) >= r:
        return math.copysign(math.pi * r * r / 4.0, c)
    return 0.5 * r * r * math.asin(c / r) + 0.5 * c * math.sqrt(r * r - c * c)


@dataclass(frozen=True)
class SlabCut:
    """``kind`` in ('cone', 'cylinder', 'sphere'): radius ``r`` (the cone's base, apex at the
    other end), length ``h`` along the axis (unused for a sphere); plate ``|z - z0| < w``, half
    (``y > 0``) or whole."""

    kind: str
    r: float
    h: float
    z0: float
    w: float
    half: bool

    def _halves(self) -> float:
        return 1.0 if self.half else 2.0

    def solid_volume(self) -> float:
        r, h = self.r, self.h
        return {"cone": math.pi * r * r * h / 3, "cylinder": math.pi * r * r * h,
                "sphere": 4 * math.pi * r**3 / 3}[self.kind]

    def solid_area(self) -> float:
        r, h = self.r, self.h
        return {"cone": math.pi * r * (r + math.hypot(r, h)), "cylinder": 2 * math.pi * r * (r + h),
                "sphere": 4 * math.pi * r * r}[self.kind]

    def _section_integral(self, z: float) -> float:
        """integral_0^z of the half plane section's area (y > 0) at height z."""
        r, h = self.r, self.h
        if self.kind == "cylinder":
            return h * _circle_strip(z, r)
        if self.kind == "sphere":
            z = _clip(z, r)
            return 0.5 * math.pi * (r * r * z - z**3 / 3)
        return (h / r) * _cone_section_integral(z, r)

    def _section(self, z: float) -> float:
        """The half plane section's area at height z."""
        r, h = self.r, self.h
        d = abs(z)
        if d >= r:
            return 0.0
        root = math.sqrt(r * r - d * d)
        if self.kind == "cylinder":
            return h * root
        if self.kind == "sphere":
            return 0.5 * math.pi * (r * r - d * d)
        g = 0.5 * r * r if d == 0 else 0.5 * (r * root - d * d * math.acosh(r / d))
        return (h / r) * g

    def volume(self) -> float:
        lo, hi = self.z0 - self.w, self.z0 + self.w
        removed = self._section_integral(hi) - self._section_integral(lo)
        return self.solid_volume() - self._halves() * removed

    def area(self) -> float:
        r, h, n = self.r, self.h, self._halves()
        lo, hi = self.z0 - self.w, self.z0 + self.w
        faces = n * (self._section(lo) + self._section(hi))
        if self.kind == "sphere":
            lost = n * 0.5 * 2 * math.pi * r * (_clip(hi, r) - _clip(lo, r))  # Archimedes' zone, halved
        elif self.kind == "cylinder":
            side = h * r * (math.asin(_clip(hi, r) / r) - math.asin(_clip(lo, r) / r))
            lost = n * (side + 2 * (_circle_strip(hi, r) - _circle_strip(lo, r)))
        else:
            k = r / h
            side = math.sqrt(1 + k * k) / k * (_asin_moment(hi, r) - _asin_moment(lo, r))
            lost = n * (side + _circle_strip(hi, r) - _circle_strip(lo, r))
        edge = 0.0
        if self.half:  # the plate's edge face on the axis plane, inside the solid
            a, b = _clip(lo, r), _clip(hi, r)
            if self.kind == "cylinder":
                edge = h * (b - a)
            elif self.kind == "sphere":
                edge = 2 * (_circle_strip(b, r) - _circle_strip(a, r))
            else:
                def absint(z: float) -> float:  # integral_0^z |t| dt
                    return math.copysign(z * z / 2, z)
                edge = h * (b - a) - (h / r) * (absint(b) - absint(a))
        return self.solid_area() - lost + faces + edge


def napkin_ring(r: float, a: float) -> tuple[float, float]:
    """Volume and area of a ball of radius ``r`` less a (long) cylinder of radius ``a < r`` through
    its centre: ``4/3 pi h^3`` and ``4 pi (r + a) h``, with ``h = sqrt(r^2 - a^2)``."""
    hh = math.sqrt(r * r - a * a)
    return 4 * math.pi * hh**3 / 3, 4 * math.pi * (r + a) * hh


def half_space_cut_volume(kind: str, apex: tuple[float, float, float], ex: tuple[float, float, float],
                          r: float, h: float, point: tuple[float, float, float],
                          n: tuple[float, float, float], r0: float | None = None) -> float:
    """Volume of the part of a cone (apex ``apex``, unit axis ``ex``, base radius ``r`` at height
    ``h``), cylinder (from ``apex`` along ``ex``, height ``h``) or frustum (``kind="frustum"``:
    radius ``r0`` at ``apex``, ``r`` at height ``h``) where ``(p - point) . n >= 0``.

    Each section across the axis is a disc cut by a line: the circular segment's exact area
    (``rho^2 acos(t / rho) - t sqrt(rho^2 - t^2)``), integrated along the axis by scipy's adaptive
    quadrature split where the line is tangent to the disc (the only kinks). For a sphere use
    :func:`sphere_cap_volume`.
    """
    from scipy.integrate import quad

    a, e, q, nn = (tuple(float(c) for c in v) for v in (apex, ex, point, n))
    along = sum(x * y for x, y in zip(nn, e))  # n . ex
    m = math.sqrt(max(sum(x * x for x in nn) - along * along, 0.0))  # |n across the axis|
    d0 = sum((x - y) * z for x, y, z in zip(a, q, nn))  # (apex - point) . n

    start = {"cone": 0.0, "cylinder": r}.get(kind, r0)
    if start is None:
        raise ValueError(f"kind {kind!r} needs r0")
    slope = (r - start) / h

    def radius(s: float) -> float:
        return start + slope * s

    def section(s: float) -> float:
        rho, level = radius(s), d0 + along * s  # the section's centre's height above the plane
        if rho <= 0.0:
            return 0.0
        if m < 1e-15:
            return math.pi * rho * rho if level >= 0.0 else 0.0
        t = min(max(-level / m, -rho), rho)
        return rho * rho * math.acos(t / rho) - t * math.sqrt(max(rho * rho - t * t, 0.0))

    kinks = []
    for sign in (1.0, -1.0):  # level / m = +-radius(s): linear in s
        k = along / m - sign * slope if m >= 1e-15 else along
        c = d0 / m - sign * start if m >= 1e-15 else d0
        if k != 0.0 and 0.0 < -c / k < h:
            kinks.append(-c / k)
    value, _ = quad(section, 0.0, h, points=sorted(kinks) or None, epsabs=1e-16, epsrel=1e-12, limit=500)
    return float(value)


def sphere_cap_volume(centre: tuple[float, float, float], r: float, point: tuple[float, float, float],
                      n: tuple[float, float, float]) -> float:
    """Volume of the part of a sphere where ``(p - point) . n >= 0`` (``n`` a unit vector): a cap,
    ``pi c^2 (3 r - c) / 3`` with ``c`` the cap's height."""
    level = sum((x - y) * z for x, y, z in zip(centre, point, n))  # the centre's height above the plane
    c = min(max(r + level, 0.0), 2.0 * r)
    return math.pi * c * c * (3.0 * r - c) / 3.0
