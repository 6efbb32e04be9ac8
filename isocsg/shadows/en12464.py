"""Calculation grids and figures of EN 12464-1 (lighting of indoor work places).

Grid (EN 12464-1:2011, 4.4 and EN 12464-1:2021, as published in the
literature; see docs/lighting_studies.md for the sources):

- the largest cell size is ``p = 0.2 x 5^log10(d)`` metres, ``d`` the longer
  side of the area in metres, and ``p <= 10 m``;
- along each side of length ``s`` the number of points is the smallest whole
  number not below ``s / p`` (at least 1), the cells of a side are equal
  (``s / n``), and the points sit at the CELL CENTRES;
- a band of 0.5 m along the walls is left out of the room's calculation area
  (unless a task area reaches into it).

Areas: the task area, its immediate surrounding (a band at least 0.5 m wide
around it) and the background (a band at least 3 m wide around that, within
the room). Each band is gridded over its bounding rectangle by the same rule
and keeps the cell centres that fall in the band.

Figures per area (:class:`AreaFigures`): maintained illuminance values
``MF x E`` (maintenance factor MF, 0 < MF <= 1), their mean Ebar, Emin, Emax,
``U0 = Emin / Ebar`` and ``Emin / Emax`` (both independent of MF), against
the required values of :data:`REQUIREMENTS` or given ones. Points inside
occluders are left out (no light reaches them).

Vertical illuminance is the illuminance on a vertical plane (a horizontal
normal); cylindrical illuminance ``Ez`` is the mean vertical illuminance over
all horizontal directions around a point. For a point luminaire it is exact:
``Ez = I sin(alpha) / (pi r^2)`` (alpha the light's angle from the vertical,
the mean of ``max(0, cos)`` over a turn being ``1 / pi``); for area sources it
is the mean of the exact vertical illuminances over ``directions`` equally
spaced azimuths (the periodic midpoint rule, error O(1 / directions^2) where
the source crosses a vertical plane).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import integer, scalar
from ..errors import InvalidParameterError
from ..kinds import DEFAULT_RESOLUTION, Solid

__all__ = [
    "grid_spacing", "grid_counts", "CellGrid", "StudyArea", "AreaFigures", "Requirement", "REQUIREMENTS",
    "surrounding_em", "room_area", "task_areas", "area_figures", "vertical_illuminance",
    "cylindrical_illuminance", "inside_occluders", "WALL_BAND", "SURROUNDING_BAND", "BACKGROUND_BAND", "MAX_SPACING",
]

#: Band along the walls left out of the room's calculation area (m).
WALL_BAND = 0.5
#: Width of the immediate surrounding around a task area (m).
SURROUNDING_BAND = 0.5
#: Width of the background around the immediate surrounding (m).
BACKGROUND_BAND = 3.0
#: Largest cell size of the rule (m).
MAX_SPACING = 10.0
#: Largest number of points of one grid.
MAX_POINTS = 4_000_000

Rect = tuple[float, float, float, float]


def grid_spacing(d: float) -> float:
    """Largest cell size ``p = 0.2 x 5^log10(d)`` (m) for an area whose longer side is ``d`` (m), ``p <= 10``.

    Examples
    --------
    >>> round(grid_spacing(10.0), 12), round(grid_spacing(1.0), 12), grid_spacing(1e6)
    (1.0, 0.2, 10.0)
    """
    d = scalar("d", d, low=0.0, high=1e7, error=InvalidParameterError)
    return min(MAX_SPACING, 0.2 * 5.0 ** math.log10(d))


def grid_counts(length: float, width: float) -> tuple[int, int]:
    """Points along the two sides of a rectangle: ``ceil(side / p)``, ``p`` from the longer side.

    Examples
    --------
    >>> grid_counts(5.0, 4.0)  # p = 0.2 x 5^log10(5) = 0.616 m: 8.1 -> 9 and 6.5 -> 7
    (9, 7)
    """
    length = scalar("length", length, low=0.0, high=1e7, error=InvalidParameterError)
    width = scalar("width", width, low=0.0, high=1e7, error=InvalidParameterError)
    p = grid_spacing(max(length, width))
    # a side that is a whole number of cells (to rounding) is not given one more
    return tuple(max(1, math.ceil(s / p - 1e-9)) for s in (length, width))  # type: ignore[return-value]


@dataclass(frozen=True, slots=True)
class CellGrid:
    """Points at the cell centres of a rectangle ``[x0, x1] x [y0, y1]`` at height ``z``, facing up.

    Attributes
    ----------
    rect : tuple (x0, y0, x1, y1)
    z : float
    nx, ny : int
        Cells along x and y.
    keep : ndarray of bool, shape (ny, nx)
        The points that belong to the area (a band keeps those outside its hole).
    """

    rect: Rect
    z: float
    nx: int
    ny: int
    keep: NDArray[np.bool_] = field(compare=False)

    @classmethod
    def standard(cls, rect: Rect, z: float, hole: Rect | None = None) -> CellGrid:
        """The grid of the rule over ``rect``, less the points inside ``hole``."""
        x0, y0, x1, y1 = _rect("rect", rect)
        nx, ny = grid_counts(x1 - x0, y1 - y0)
        if nx * ny > MAX_POINTS:
            raise InvalidParameterError(f"rect {rect} would need {nx} x {ny} points, more than {MAX_POINTS}")
        g = cls((x0, y0, x1, y1), float(z), nx, ny, np.ones((ny, nx), dtype=bool))
        if hole is not None:
            hx0, hy0, hx1, hy1 = _rect("hole", hole)
            pts = g.points()
            inside = (pts[..., 0] > hx0) & (pts[..., 0] < hx1) & (pts[..., 1] > hy0) & (pts[..., 1] < hy1)
            object.__setattr__(g, "keep", ~inside)
        return g

    @property
    def spacing(self) -> tuple[float, float]:
        """Cell sizes along x and y (m)."""
        x0, y0, x1, y1 = self.rect
        return (x1 - x0) / self.nx, (y1 - y0) / self.ny

    def points(self) -> NDArray[np.float64]:
        """All cell centres, shape (ny, nx, 3)."""
        x0, y0, x1, y1 = self.rect
        px, py = self.spacing
        x = x0 + (np.arange(self.nx) + 0.5) * px
        y = y0 + (np.arange(self.ny) + 0.5) * py
        X, Y = np.meshgrid(x, y)
        return np.stack([X, Y, np.full_like(X, self.z)], axis=-1)

    def kept_points(self) -> NDArray[np.float64]:
        """The area's points, shape (k, 3)."""
        return self.points()[self.keep]


@dataclass(frozen=True, slots=True)
class Requirement:
    """Required maintained illuminance ``em`` (lx) and uniformity ``u0`` of an area, and where they come from."""

    em: float
    u0: float
    source: str = ""


#: Rows of the standard's tables that docs/lighting_studies.md cites with their published sources
#: (EN 12464-1:2021's offices row and unknown-task rule; the walls' and ceilings' values for offices).
REQUIREMENTS: dict[str, Requirement] = {
    "filing_copying": Requirement(300.0, 0.40, "EN 12464-1:2021 offices, filing, copying, etc. (Em 300 lx, U0 0.40)"),
    "unknown_task": Requirement(math.nan, 0.40, "EN 12464-1:2021: task area unknown, the whole area U0 >= 0.40"),
    "walls": Requirement(75.0, 0.10, "EN 12464-1, offices: walls Em >= 75 lx, U0 >= 0.10 (as quoted by Trilux)"),
    "ceiling": Requirement(50.0, 0.10, "EN 12464-1, offices: ceiling Em >= 50 lx, U0 >= 0.10 (as quoted by Trilux)"),
}


def surrounding_em(task_em: float) -> float:
    """Required Em of the immediate surrounding for a task area's Em (EN 12464-1:2011, 4.3.2, Table 1).

    >= 750 lx -> 500 lx; 500 -> 300; 300 -> 200; at most 200 -> the task's Em (between the rows,
    the row at or below the task's value).

    Examples
    --------
    >>> [surrounding_em(e) for e in (1000, 750, 500, 300, 200, 100)]
    [500.0, 500.0, 300.0, 200.0, 200.0, 100.0]
    """
    e = scalar("task_em", task_em, low=0.0, high=1e6, error=InvalidParameterError)
    for at_least, value in ((750.0, 500.0), (500.0, 300.0), (300.0, 200.0)):
        if e >= at_least:
            return value
    return e


@dataclass(frozen=True, slots=True)
class StudyArea:
    """A named calculation area: its grid, kind and required values.

    ``kind`` is one of ``"room"``, ``"task"``, ``"surrounding"``, ``"background"``.
    """

    name: str
    kind: str
    grid: CellGrid
    required: Requirement | None = None


def _rect(name: str, rect: Any) -> Rect:
    try:
        r = tuple(float(v) for v in rect)
    except (TypeError, ValueError):
        raise InvalidParameterError(f"{name} must be 4 numbers (x0, y0, x1, y1), got {rect!r}") from None
    if len(r) != 4 or not all(math.isfinite(v) for v in r) or not (r[2] > r[0] and r[3] > r[1]):
        raise InvalidParameterError(f"{name} must be finite (x0, y0, x1, y1) with x1 > x0 and y1 > y0, got {rect!r}")
    return r  # type: ignore[return-value]


def _grow(r: Rect, by: float, within: Rect) -> Rect:
    return (max(within[0], r[0] - by), max(within[1], r[1] - by), min(within[2], r[2] + by), min(within[3], r[3] + by))


def room_area(room: Rect, z: float, *, band: float = WALL_BAND, required: Requirement | None = None) -> StudyArea:
    """The room's calculation area: the room less a band of ``band`` metres along the walls.

    Examples
    --------
    >>> a = room_area((0, 0, 6, 4), 0.8)
    >>> a.grid.rect, (a.grid.nx, a.grid.ny)
    ((0.5, 0.5, 5.5, 3.5), (9, 5))
    """
    x0, y0, x1, y1 = _rect("room", room)
    band = scalar("band", band, low=0.0, low_inclusive=True, high=1e6, error=InvalidParameterError)
    inner = (x0 + band, y0 + band, x1 - band, y1 - band)
    if not (inner[2] > inner[0] and inner[3] > inner[1]):
        raise InvalidParameterError(f"band {band} m leaves nothing of the room {room}")
    return StudyArea("room", "room", CellGrid.standard(inner, z), required)


def task_areas(
    name: str, task: Rect, room: Rect, z: float, required: Requirement | None = None,
    *, surrounding: float = SURROUNDING_BAND, background: float = BACKGROUND_BAND,
) -> list[StudyArea]:
    """A task area, its immediate surrounding and its background (bands clipped to the room).

    The surrounding's requirement follows :func:`surrounding_em` with
    U0 >= 0.40; the background's is a third of the surrounding's Em with
    U0 >= 0.10 (EN 12464-1:2011, 4.3.2 and 4.3.3). A band that the room
    leaves empty is not returned.
    """
    t = _rect(f"{name}.rect", task)
    r = _rect("room", room)
    if not (t[0] >= r[0] - 1e-9 and t[1] >= r[1] - 1e-9 and t[2] <= r[2] + 1e-9 and t[3] <= r[3] + 1e-9):
        raise InvalidParameterError(f"{name}.rect {task} must lie in the room {room}")
    s = _grow(t, surrounding, r)
    b = _grow(s, background, r)
    out = [StudyArea(name, "task", CellGrid.standard(t, z), required)]
    req_s = req_b = None
    if required is not None and math.isfinite(required.em):
        em_s = surrounding_em(required.em)
        req_s = Requirement(em_s, 0.40, "EN 12464-1:2011 4.3.2: immediate surrounding, Table 1, U0 >= 0.40")
        req_b = Requirement(em_s / 3, 0.10, "EN 12464-1:2011 4.3.3: background, Em/3 of the surrounding, U0 >= 0.10")
    for label, kind, outer, inner, req in (("surrounding", "surrounding", s, t, req_s),
                                           ("background", "background", b, s, req_b)):
        g = CellGrid.standard(outer, z, hole=inner)
        if g.keep.any():
            out.append(StudyArea(f"{name} {label}", kind, g, req))
    return out


@dataclass(frozen=True, slots=True)
class AreaFigures:
    """The figures of one area (maintained values, lux).

    Attributes
    ----------
    name, kind : str
    points : int
        Points counted (those inside occluders left out).
    spacing : tuple of 2 floats
        Cell sizes (m).
    e_mean, e_min, e_max : float
        Maintained Ebar, Emin, Emax (lx).
    u0 : float
        ``e_min / e_mean``.
    min_max : float
        ``e_min / e_max``.
    required : Requirement or None
    """

    name: str
    kind: str
    points: int
    spacing: tuple[float, float]
    e_mean: float
    e_min: float
    e_max: float
    u0: float
    min_max: float
    required: Requirement | None = None

    @property
    def passes(self) -> bool | None:
        """Whether Ebar and U0 meet the requirement (None without one)."""
        if self.required is None:
            return None
        ok_em = math.isnan(self.required.em) or self.e_mean >= self.required.em
        return bool(ok_em and self.u0 >= self.required.u0)


def inside_occluders(points: NDArray[np.float64], solids: Sequence[Any]) -> NDArray[np.bool_]:
    """Points (n, 3) inside a solid, each tested 1e-7 m above itself (a point on a floor slab's top is outside)."""
    out = np.zeros(len(points), dtype=bool)
    for s in solids:
        out |= s.contains(points + [0.0, 0.0, 1e-7], tol=0.0)
    return out


def area_figures(
    area: StudyArea,
    lights: Any,
    occluders: Sequence[Solid] | Solid = (),
    *,
    maintenance_factor: float = 1.0,
    resolution: int = DEFAULT_RESOLUTION,
) -> tuple[AreaFigures, NDArray[np.float64]]:
    """Exact illuminance at an area's grid points (facing up) and its figures.

    Returns
    -------
    figures : AreaFigures
    E : ndarray, shape (ny, nx)
        Maintained illuminance at every cell centre (NaN outside the area and
        inside occluders).

    Raises
    ------
    InvalidParameterError
        On a maintenance factor outside (0, 1], or an area with no point
        outside the occluders.
    """
    from .direct import illuminance

    mf = scalar("maintenance_factor", maintenance_factor, low=0.0, high=1.0, error=InvalidParameterError)
    solids = [occluders] if isinstance(occluders, Solid) else list(occluders)
    g = area.grid
    pts = g.kept_points()
    use = ~inside_occluders(pts, solids)
    if not use.any():
        raise InvalidParameterError(f"area {area.name!r}: every grid point lies inside an occluder")
    e = np.full(len(pts), np.nan)
    e[use] = mf * illuminance(pts[use], [0.0, 0.0, 1.0], lights, solids, resolution=resolution)
    E = np.full((g.ny, g.nx), np.nan)
    E[g.keep] = e
    v = e[use]
    mean, lo, hi = float(v.mean()), float(v.min()), float(v.max())
    figs = AreaFigures(area.name, area.kind, int(v.size), g.spacing, mean, lo, hi,
                       lo / mean if mean > 0 else math.nan, lo / hi if hi > 0 else math.nan, area.required)
    return figs, E


def vertical_illuminance(
    points: ArrayLike, azimuth: float, lights: Any, occluders: Sequence[Solid] | Solid = (), *,
    resolution: int = DEFAULT_RESOLUTION,
) -> NDArray[np.float64]:
    """Illuminance on vertical planes facing ``azimuth`` (degrees from +x towards +y) at ``points`` (n, 3)."""
    from .direct import illuminance

    a = math.radians(scalar("azimuth", azimuth, low=-1e6, high=1e6, error=InvalidParameterError))
    return illuminance(points, [math.cos(a), math.sin(a), 0.0], lights, occluders, resolution=resolution)


def cylindrical_illuminance(
    points: ArrayLike, lights: Any, occluders: Sequence[Solid] | Solid = (), *, directions: int = 64,
    resolution: int = DEFAULT_RESOLUTION,
) -> NDArray[np.float64]:
    """Cylindrical illuminance Ez at ``points`` (n, 3): the mean vertical illuminance around each point.

    Point luminaires by the closed form ``I sin(alpha) / (pi r^2)`` with their
    hard shadows; area and polyhedron sources by the mean of the exact
    vertical illuminances over ``directions`` azimuths (module docstring).

    Examples
    --------
    >>> from isocsg.lighting.luminaire import PhotometricLight
    >>> from isocsg.lighting.photometry import Photometry
    >>> lamp = PhotometricLight((0, 0, 3), Photometry.isotropic(100.0))
    >>> round(float(cylindrical_illuminance([[4, 0, 0]], [lamp])[0]), 6)  # 100 * 4 / (pi 5^3)
    1.018592
    """
    from ..lighting.area import as_light_list
    from ..lighting.luminaire import PhotometricLight
    from .direct import illuminance
    from .lambert import _prepare
    from .occluders import occluder_list, shadow_pieces
    from .pointsource import segment_blocked

    p, _ = _prepare(points, [[0.0, 0.0, 1.0]])
    directions = integer("directions", directions, low=4, high=4096, error=InvalidParameterError)
    seq = [lights] if not isinstance(lights, (list, tuple)) else list(lights)
    lums = [li for li in seq if isinstance(li, PhotometricLight)]
    areas = as_light_list([li for li in seq if not isinstance(li, PhotometricLight)])
    solids = occluder_list(occluders, resolution)
    out = np.zeros(len(p))
    allpts = np.vstack([p, *(np.asarray(lu.position)[None] for lu in lums), *(np.asarray(s.bounds) for s in solids)])
    scale = float(max(np.max(np.ptp(allpts, axis=0)), np.max(np.abs(allpts)), 1e-300))
    for lu in lums:
        P = np.asarray(lu.position, dtype=np.float64)
        v = P[None, :] - p
        r2 = np.einsum("ij,ij->i", v, v)
        ok = r2 > 0
        if solids and ok.any():
            pieces = shadow_pieces(solids, p[ok], P[None, :], resolution=resolution, scale=scale)
            if pieces:
                ok[ok] = ~segment_blocked(p[ok], P, pieces, scale)
        if ok.any():
            r = np.sqrt(r2[ok])
            sin_a = np.hypot(v[ok, 0], v[ok, 1]) / r
            out[ok] += lu.intensity_towards(-v[ok] / r[:, None]) * sin_a / (math.pi * r2[ok])
    if areas:
        for k in range(directions):
            a = 2 * math.pi * (k + 0.5) / directions
            out += illuminance(p, [math.cos(a), math.sin(a), 0.0], areas, solids, resolution=resolution) / directions
    return out
