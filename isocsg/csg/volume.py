"""Volumes of CSG trees from their cross-sections (laminae of parallel planes).

``V = integral A(z) dz`` where ``A(z)`` is the area of the section by the
plane ``axis . x = z`` (:func:`isocsg.csg.section.section`). For trees of
spheres, frusta and polyhedra ``A`` is piecewise smooth: its kinks and square-
root endpoint singularities sit at the primitives' extents along the axis
(poles of spheres, rims of end circles, polyhedron vertices) and at the
extremes of the curves where two surfaces meet. The extents are passed as
breakpoints to an adaptive Gauss-Kronrod rule (QUADPACK's QAGP, which also
extrapolates away endpoint singularities); the remaining kinks are found by
its adaptive bisection.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray
from shapely.geometry import Polygon

from .._validation import integer, nonzero_vector3, scalar
from ..errors import InvalidParameterError
from ..geometry.primitives import Box, ConvexPolyhedron, Primitive, Solid, Sphere, Truncus
from .program import Program
from .section import combine_sections, plane_frame, primitive_section, solid_program

__all__ = ["volume", "section_areas", "breakpoints"]

_EMPTY = Polygon()


def _extents(prim: Primitive, w: NDArray[np.float64]) -> list[float]:
    """Axial positions where the section area of ``prim`` along ``w`` is not smooth."""
    if isinstance(prim, Sphere):
        c = float(prim.center_array @ w)
        return [c - prim.radius, c + prim.radius]
    if isinstance(prim, Truncus):
        a = prim.unit_axis
        ext = math.sqrt(max(0.0, 1.0 - float(a @ w) ** 2))  # half-extent of a unit end circle along w
        out = []
        for c, r in zip(prim.end_centers, (prim.r1, prim.r2)):
            z = float(c @ w)
            out.extend([z - r * ext, z + r * ext])
        return out
    if isinstance(prim, Box):
        return (prim.corners @ w).tolist()
    if isinstance(prim, ConvexPolyhedron):
        return (prim.hull_vertices @ w).tolist()
    b = prim.bounds
    return [float(b[0] @ w), float(b[1] @ w)]  # pragma: no cover - every primitive is handled above


def breakpoints(solid: Solid, axis: ArrayLike = (0.0, 0.0, 1.0)) -> NDArray[np.float64]:
    """Sorted, distinct axial positions where the section area may have a kink.

    Parameters
    ----------
    solid : Solid
    axis : array_like, shape (3,)
        Direction of the plane normals (normalised here).

    Returns
    -------
    ndarray
        The first and last entries bound the solid along ``axis``.

    Examples
    --------
    >>> from isocsg import Sphere
    >>> breakpoints(Sphere((0, 0, 1), 2.0)).tolist()
    [-1.0, 3.0]
    """
    w = np.asarray(nonzero_vector3("axis", axis, error=InvalidParameterError))
    w = w / np.linalg.norm(w)
    prims = solid_program(solid).leaves
    z = np.unique(np.concatenate([_extents(p, w) for p in prims]))
    scale = max(float(z[-1] - z[0]), 1e-300)
    keep = np.concatenate([[True], np.diff(z) > 1e-9 * scale])
    return z[keep]


def section_areas(
    solid: Solid,
    positions: ArrayLike,
    axis: ArrayLike = (0.0, 0.0, 1.0),
    *,
    resolution: int = 256,
) -> NDArray[np.float64]:
    """Areas of the sections by the planes ``axis . x = positions[i]``.

    Parameters
    ----------
    solid : Solid
    positions : array_like, shape (n,)
        Signed plane positions along the unit ``axis``.
    axis : array_like, shape (3,)
    resolution : int, default 256
        Polygon vertices per full circle.

    Returns
    -------
    ndarray, shape (n,)

    Examples
    --------
    >>> from isocsg import Box
    >>> section_areas(Box((0, 0, 0), (1, 2, 3)), [0.0, 1.4, 2.0]).tolist()
    [2.0, 2.0, 0.0]
    """
    w = np.asarray(nonzero_vector3("axis", axis, error=InvalidParameterError))
    w = w / np.linalg.norm(w)
    res = integer("resolution", resolution, low=8, high=1_000_000, error=InvalidParameterError)
    z = np.atleast_1d(np.asarray(positions, dtype=np.float64))
    if z.ndim != 1 or not np.all(np.isfinite(z)):
        raise InvalidParameterError(f"positions must be a 1-D array of finite numbers, got shape {z.shape}")
    prog = solid_program(solid)
    prims = prog.leaves
    return np.array([_area(prims, prog, w, float(zi), res) for zi in z])


def _area(
    prims: list[Primitive],
    prog: Program,
    w: NDArray[np.float64],
    z: float,
    res: int,
    spans: list[tuple[float, float]] | None = None,
) -> float:
    F = plane_frame(z * w, w)
    if spans is None:
        geoms = [primitive_section(p, F, res) for p in prims]
    else:
        # leaves whose extent along w excludes z have an empty section: skip the work
        geoms = [primitive_section(p, F, res) if lo < z < hi else _EMPTY for p, (lo, hi) in zip(prims, spans)]
    return float(combine_sections(prog, geoms).area)


def volume(
    solid: Solid,
    *,
    tol: float = 1e-4,
    axis: ArrayLike = (0.0, 0.0, 1.0),
    resolution: int | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> float:
    """Volume of a primitive or CSG tree, integrated from its cross-sections.

    Parameters
    ----------
    solid : Solid
        A primitive or CSG tree (an empty result has volume 0).
    tol : float, default 1e-4
        Target relative accuracy, in (0, 0.1]. The section polygons get
        enough vertices that their inscribed-polygon deficit stays below
        ``tol / 4``, and the quadrature is asked for ``tol / 4``.
    axis : array_like, shape (3,), default (0, 0, 1)
        Normal of the section planes.
    resolution : int, optional
        Polygon vertices per full circle; overrides the choice from ``tol``.
    progress : callable, optional
        Called as ``progress(done, total)`` after each integration interval.

    Returns
    -------
    float
        Cubic metres.

    Raises
    ------
    InvalidGeometryError
        If ``solid`` is not a solid.
    InvalidParameterError
        On a bad ``tol``, ``axis`` or ``resolution``.

    Examples
    --------
    >>> from isocsg import Cylinder, Sphere
    >>> R, r = 1.0, 0.5
    >>> v = volume(Sphere((0, 0, 0), R) - Cylinder((0, 0, 0), (0, 0, 3), r))
    >>> exact = 4 / 3 * math.pi * (R**2 - r**2) ** 1.5
    >>> abs(v / exact - 1) < 1e-4
    True
    """
    from scipy.integrate import IntegrationWarning, quad

    tol_ = scalar("tol", tol, low=0.0, high=0.1, error=InvalidParameterError)
    if resolution is None:
        # inscribed n-gon deficit ~ (2 pi / n)^2 / 6 of the curved part
        res = int(min(max(math.ceil(2 * math.pi / math.sqrt(6 * tol_ / 4)), 64), 8192))
    else:
        res = integer("resolution", resolution, low=8, high=1_000_000, error=InvalidParameterError)
    w = np.asarray(nonzero_vector3("axis", axis, error=InvalidParameterError))
    w = w / np.linalg.norm(w)
    prog = solid_program(solid)
    prims = prog.leaves
    z = breakpoints(solid, w)
    if len(z) < 2:
        return 0.0
    # absolute floor: a fraction of the bounding slab so that empty results terminate
    b = np.array([p.bounds for p in prims])
    span = float(np.max(b[:, 1] - b[:, 0]))
    abs_floor = 1e-3 * tol_ * span**3

    spans = [(min(e), max(e)) for e in (_extents(p, w) for p in prims)]

    def f(x: float) -> float:
        return _area(prims, prog, w, x, res, spans)

    total = 0.0
    n = len(z) - 1
    with warnings.catch_warnings():
        # the polygonised area has tiny steps; QUADPACK may warn near its round-off limit
        warnings.simplefilter("ignore", IntegrationWarning)
        for i in range(n):
            lo, hi = float(z[i]), float(z[i + 1])
            val, _ = quad(f, lo, hi, epsrel=tol_ / 4, epsabs=abs_floor / n, limit=100)
            total += val
            if progress is not None:
                progress(i + 1, n)
    return float(max(total, 0.0))
