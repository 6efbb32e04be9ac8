"""The OpenSCAD text helpers the kinds share: numbers, vectors, matrices and exact encodings.

Numbers are written with ``repr`` (the shortest text that reads back to the same float);
with ``digits``, every number has at most that many significant digits and exact values
are composed from such short numbers (see :func:`encoded`).
"""

from __future__ import annotations

import functools
import math

import numpy as np
from numpy.typing import NDArray

__all__ = ["encoded", "frame", "mat", "num", "num_sig", "round_sig", "short_mat", "translated", "truncus_body", "vec"]


def num(x: float) -> str:
    x = float(x)
    if x == 0.0:
        return "0"  # also -0.0
    if x == int(x) and abs(x) < 1e15:
        return str(int(x))
    return repr(x)


def vec(v: NDArray[np.float64] | list[float] | tuple[float, ...]) -> str:
    return "[" + ", ".join(num(x) for x in v) + "]"


def mat(m: NDArray[np.float64]) -> str:
    return "[" + ", ".join(vec(row) for row in m) + "]"


def frame(axis: NDArray[np.float64], center: NDArray[np.float64]) -> NDArray[np.float64]:
    """A rigid map taking +z to the unit ``axis`` and the origin to ``center``."""
    w = axis / np.linalg.norm(axis)
    m = np.eye(4)
    if w[0] == 0.0 and w[1] == 0.0:
        if w[2] < 0:
            m[:3, :3] = np.diag([1.0, -1.0, -1.0])  # a half turn about x
    else:
        helper = np.array([0.0, 0.0, 1.0]) if abs(w[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
        u = np.cross(helper, w)
        u /= np.linalg.norm(u)
        v = np.cross(w, u)
        m[:3, 0], m[:3, 1], m[:3, 2] = u, v, w
    m[:3, 3] = center
    return m


def translated(center: NDArray[np.float64], body: str) -> str:
    if not np.any(center):
        return body
    m = np.eye(4)
    m[:3, 3] = center
    return f"multmatrix({mat(m)}) {{ {body} }}"


# ----------------------------------------------------------------------------- numbers of few digits
#
# OpenSCAD 2021 prints every number of its .csg export (matrix entries, sizes, radii,
# points) with 6 significant digits. A number written with at most that many digits comes
# through unchanged, and nested multmatrix nodes come through as nested nodes, which the
# loader applies one after the other. So an exact value can be written as a sum of short
# numbers (nested translations) or a product of them (nested scales), and a linear map as
# a product of short matrices: L = L_d (I + lower) diag(a b) (I + upper), each factor's
# residual at the next factor's scale. Every term is ~10^-d of the previous one.


def round_sig(x: float, d: int) -> float:
    """``x`` rounded to ``d`` significant decimal digits (what OpenSCAD prints for d = 6)."""
    return float(f"{float(x):.{d - 1}e}")


def num_sig(x: float, d: int) -> str:
    x = round_sig(x, d)
    if x == 0.0:
        return "0"
    return f"{x:.{d}g}"


def split_sum(x: NDArray[np.float64], d: int, terms: int = 3) -> list[NDArray[np.float64]]:
    """Vectors of ``d``-digit entries whose sum is ``x`` (each the rounding of what is left)."""
    out = []
    rest = np.asarray(x, dtype=np.float64).copy()
    for _ in range(terms):
        if not np.any(rest):
            break
        part = np.array([round_sig(v, d) for v in rest])
        out.append(part)
        rest = rest - part  # exact (Sterbenz) while part is the rounding of rest
    return out


@functools.lru_cache(maxsize=4096)
def split_product(x: float, d: int) -> tuple[float, float]:
    """Two ``d``-digit numbers whose product is ``x`` to about ``10**(2 - 2 d)`` relative.

    Every ``d``-digit mantissa ``b`` in [1, 10) is tried with ``a = x / b`` rounded
    to ``d`` digits; the pair whose product is nearest ``x`` wins."""
    if x == 0.0 or round_sig(x, d) == x:
        return x, 1.0
    ax = abs(x)
    b = np.arange(10 ** (d - 1), 10**d, dtype=np.float64) / 10 ** (d - 1)
    q = ax / b
    e = 10.0 ** (np.floor(np.log10(q)) - (d - 1))
    a = np.round(q / e) * e
    i = int(np.argmin(np.abs(a * b - ax)))
    return math.copysign(round_sig(float(a[i]), d), x), float(b[i])


def ratio(r: float, d: int) -> tuple[int, int]:
    """Integers ``(p, q)``, both below ``10**d``, with ``p / q`` the best approximation of
    ``r`` in [0, 1] (continued fractions)."""
    limit = 10**d - 1
    if r <= 0.0:
        return 0, 1
    if r >= 1.0:
        return 1, 1
    h0, h1, k0, k1 = 0, 1, 1, 0
    x = r
    while True:
        a = math.floor(x)
        h2, k2 = a * h1 + h0, a * k1 + k0
        if k2 > limit:
            break
        h0, h1, k0, k1 = h1, h2, k1, k2
        frac = x - a
        if frac == 0.0 or abs(h1 / k1 - r) <= 1e-17 * r:
            break
        x = 1.0 / frac
    return h1, k1


def short_mat(m: NDArray[np.float64], d: int) -> str:
    return "[" + ", ".join("[" + ", ".join(num_sig(x, d) for x in row) + "]" for row in m) + "]"


def encoded(body: str, L: NDArray[np.float64], t: NDArray[np.float64], d: int) -> str:
    """``body`` (a unit primitive whose numbers are short) mapped by ``x -> L x + t``, as
    nested ``multmatrix`` nodes whose entries have at most ``d`` significant digits."""
    L = np.asarray(L, dtype=np.float64)
    linear: list[NDArray[np.float64]] = []  # outermost first
    if np.count_nonzero(L - np.diag(np.diag(L))) == 0:
        diag = np.diag(L).copy()
        upper = None
    else:
        L6 = np.vectorize(lambda v: round_sig(v, d))(L)
        C = np.linalg.solve(L6, L)  # I + O(10^-d)
        lower = np.eye(3)
        for j in range(3):  # Doolittle without pivots: C is close to the identity
            for i in range(j + 1, 3):
                lower[i, j] = round_sig(C[i, j] / C[j, j], d)
        R = np.linalg.solve(L6 @ lower, L)  # diag(D) (I + upper), to the rounding of `lower`
        diag = np.diag(R).copy()
        upper = np.eye(3)
        for i in range(3):
            for j in range(i + 1, 3):
                upper[i, j] = round_sig(R[i, j] / R[i, i], d)
        # what the rounded factors leave on the diagonal
        diag = np.diag(np.linalg.solve(L6 @ lower, L) @ np.linalg.inv(upper)).copy()
        linear += [L6, lower]
    ab = [split_product(float(v), d) for v in diag]  # (10**(d-1) tries each; equal sizes are cached)
    linear += [np.diag([a for a, _ in ab]), np.diag([b for _, b in ab])]
    if upper is not None:
        linear.append(upper)
    factors: list[NDArray[np.float64]] = []
    for part in split_sum(np.asarray(t, dtype=np.float64), d):
        m = np.eye(4)
        m[:3, 3] = part
        factors.append(m)
    for lin in linear:
        m = np.eye(4)
        m[:3, :3] = lin
        factors.append(m)
    out = body
    for m in reversed(factors):
        if not np.array_equal(m, np.eye(4)):
            out = f"multmatrix({short_mat(m, d)}) {{ {out} }}"
    return out


def truncus_body(r_low: float, r_high: float, d: int) -> tuple[str, float]:
    """A unit-height centred cylinder whose radii (OpenSCAD's r1 at z = -1/2, r2 at +1/2) are
    integers in the ratio ``r_low : r_high``, and the radial scale that gives them back."""
    big = max(r_low, r_high)
    p, q = ratio(min(r_low, r_high) / big, d)
    lo, hi = (q, p) if r_low >= r_high else (p, q)
    return f"cylinder(h = 1, r1 = {lo}, r2 = {hi}, center = true);", big / q
