"""The exact leaves of 2D shapes: convex polygons, circles (discs) and ellipses.

Each leaf is a frozen value, validated on construction (messages name the
field), with its exact area and bounds and its exact image under an affine map
(``_affine``): a convex polygon stays a convex polygon, a circle stays a circle
under a similarity and becomes an :class:`Ellipse` otherwise.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidGeometryError
from ._checks import points2, positive, vector2
from .shape import Shape2D

__all__ = ["ConvexPolygon", "Circle", "Ellipse", "convex_polygon", "is_similarity"]

Vec2 = tuple[float, float]

#: Relative tolerance of the convexity check (a corner may turn right by this much of the size squared).
CONVEX_RTOL = 1e-12


def _cross(o: NDArray[np.float64], a: NDArray[np.float64], b: NDArray[np.float64]) -> NDArray[np.float64]:
    return (a[..., 0] - o[..., 0]) * (b[..., 1] - o[..., 1]) - (a[..., 1] - o[..., 1]) * (b[..., 0] - o[..., 0])


@dataclass(frozen=True, slots=True)
class ConvexPolygon(Shape2D):
    """A convex polygon: its vertices counter-clockwise (collinear vertices allowed).

    Parameters
    ----------
    vertices : tuple of (x, y)
        At least 3 vertices, counter-clockwise, convex, enclosing an area > 0.
        :func:`convex_polygon` builds one from points in any order.

    Raises
    ------
    InvalidGeometryError
        On non-finite coordinates, fewer than 3 vertices, a clockwise or
        non-convex ring, or a zero area.

    Examples
    --------
    >>> p = ConvexPolygon(((0, 0), (2, 0), (2, 1), (0, 1)))
    >>> p.area, p.bounds
    (2.0, (0.0, 0.0, 2.0, 1.0))
    """

    vertices: tuple[Vec2, ...]

    def __post_init__(self) -> None:
        pts = points2("ConvexPolygon.vertices", self.vertices, minimum=3)
        object.__setattr__(self, "vertices", tuple((float(x), float(y)) for x, y in pts))
        size = float(np.max(np.ptp(pts, axis=0)))
        turns = _cross(np.roll(pts, 1, axis=0), pts, np.roll(pts, -1, axis=0))
        if size <= 0 or _shoelace(pts) <= CONVEX_RTOL * size * size:
            raise InvalidGeometryError(
                f"ConvexPolygon.vertices must enclose an area > 0 counter-clockwise, got area {_shoelace(pts):g}"
            )
        if np.any(turns < -CONVEX_RTOL * size * size):
            k = int(np.argmin(turns))
            raise InvalidGeometryError(f"ConvexPolygon.vertices must be convex, got a right turn at vertex {k}")

    @property
    def array(self) -> NDArray[np.float64]:
        """The vertices as an (n, 2) float64 array."""
        return np.array(self.vertices, dtype=np.float64)

    @property
    def area(self) -> float:  # type: ignore[override]
        """The exact (shoelace) area."""
        return _shoelace(self.array)

    @property
    def bounds(self) -> tuple[float, float, float, float]:  # type: ignore[override]
        a = self.array
        return (float(a[:, 0].min()), float(a[:, 1].min()), float(a[:, 0].max()), float(a[:, 1].max()))

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> ConvexPolygon:
        pts = self.array @ A.T + t
        return ConvexPolygon(tuple(map(tuple, pts[::-1] if np.linalg.det(A) < 0 else pts)))


def _shoelace(pts: NDArray[np.float64]) -> float:
    c = pts - pts[0]
    return float(0.5 * np.sum(c[:-1, 0] * c[1:, 1] - c[:-1, 1] * c[1:, 0]))


def convex_polygon(points: Any, *, name: str = "convex_polygon.points") -> ConvexPolygon:
    """The convex polygon of points that form a convex ring in either orientation (duplicates dropped).

    Examples
    --------
    >>> convex_polygon([(0, 0), (0, 1), (1, 0)]).vertices
    ((1.0, 0.0), (0.0, 1.0), (0.0, 0.0))
    """
    pts = points2(name, points, minimum=3)
    keep = np.ones(len(pts), dtype=bool)
    keep[1:] = np.any(pts[1:] != pts[:-1], axis=1)
    pts = pts[keep]
    if len(pts) > 1 and np.all(pts[-1] == pts[0]):
        pts = pts[:-1]
    if len(pts) >= 3 and _shoelace(pts) < 0:
        pts = pts[::-1]
    try:
        return ConvexPolygon(tuple(map(tuple, pts)))
    except InvalidGeometryError as exc:
        raise InvalidGeometryError(str(exc).replace("ConvexPolygon.vertices", name)) from None


def is_similarity(A: NDArray[np.float64]) -> float | None:
    """The scale factor ``s`` when ``A^T A = s^2 I`` (to rounding), else ``None``."""
    g = A.T @ A
    s2 = 0.5 * (g[0, 0] + g[1, 1])
    if s2 > 0 and abs(g[0, 0] - g[1, 1]) <= 1e-12 * s2 and abs(g[0, 1]) <= 1e-12 * s2:
        return float(np.hypot(A[0, 0], A[1, 0]))
    return None


@dataclass(frozen=True, slots=True)
class Circle(Shape2D):
    """An exact disc: ``center`` and ``radius`` > 0.

    Examples
    --------
    >>> c = Circle((1, 0), 2)
    >>> round(c.area, 12) == round(4 * math.pi, 12), c.bounds
    (True, (-1.0, -2.0, 3.0, 2.0))
    """

    center: Vec2
    radius: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "center", vector2("Circle.center", self.center))
        object.__setattr__(self, "radius", positive("Circle.radius", self.radius))

    @property
    def area(self) -> float:  # type: ignore[override]
        """``pi r^2``."""
        return math.pi * self.radius**2

    @property
    def bounds(self) -> tuple[float, float, float, float]:  # type: ignore[override]
        (x, y), r = self.center, self.radius
        return (x - r, y - r, x + r, y + r)

    @property
    def matrix(self) -> tuple[Vec2, Vec2]:
        """The linear part that maps the unit disc onto this one (``r I``)."""
        return ((self.radius, 0.0), (0.0, self.radius))

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> Shape2D:
        c = A @ np.array(self.center) + t
        s = is_similarity(A)
        if s is not None:
            return Circle((float(c[0]), float(c[1])), self.radius * s)
        return Ellipse((float(c[0]), float(c[1])), _pair(A * self.radius))


def _pair(M: NDArray[np.float64]) -> tuple[Vec2, Vec2]:
    return ((float(M[0, 0]), float(M[0, 1])), (float(M[1, 0]), float(M[1, 1])))


@dataclass(frozen=True, slots=True)
class Ellipse(Shape2D):
    """An exact ellipse: the image ``center + M u`` of the unit disc ``|u| <= 1`` under an invertible ``matrix`` M.

    It is what a circle becomes under a non-uniform scale or a shear. Its
    area is ``pi |det M|``. Offsets of ellipses are not ellipses: :func:`~isocsg.shapes2d.offset`
    refuses them unless given a ``tolerance``.

    Examples
    --------
    >>> e = Ellipse((0, 0), ((2, 0), (0, 1)))
    >>> round(e.area / math.pi, 12), e.bounds
    (2.0, (-2.0, -1.0, 2.0, 1.0))
    """

    center: Vec2
    matrix: tuple[Vec2, Vec2]

    def __post_init__(self) -> None:
        object.__setattr__(self, "center", vector2("Ellipse.center", self.center))
        m = points2("Ellipse.matrix", self.matrix, minimum=2)
        if m.shape != (2, 2):
            raise InvalidGeometryError(f"Ellipse.matrix must have shape (2, 2), got {m.shape}")
        det = float(np.linalg.det(m))
        scale = float(np.max(np.abs(m)))
        if not abs(det) > 1e-12 * scale * scale:
            raise InvalidGeometryError(f"Ellipse.matrix must be invertible, got determinant {det:g}")
        object.__setattr__(self, "matrix", _pair(m))

    @property
    def area(self) -> float:  # type: ignore[override]
        """``pi |det M|``."""
        return math.pi * abs(float(np.linalg.det(np.array(self.matrix))))

    @property
    def bounds(self) -> tuple[float, float, float, float]:  # type: ignore[override]
        m = np.array(self.matrix)
        hx, hy = float(np.hypot(m[0, 0], m[0, 1])), float(np.hypot(m[1, 0], m[1, 1]))
        x, y = self.center
        return (x - hx, y - hy, x + hx, y + hy)

    def _affine(self, A: NDArray[np.float64], t: NDArray[np.float64]) -> Shape2D:
        c = A @ np.array(self.center) + t
        M = A @ np.array(self.matrix)
        s = is_similarity(M)
        if s is not None:
            return Circle((float(c[0]), float(c[1])), s)
        return Ellipse((float(c[0]), float(c[1])), _pair(M))
