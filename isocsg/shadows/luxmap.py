"""Illuminance maps of a receiving plane and their isolux lines (lighting design).

A :class:`LuxGrid` spans a parallelogram of a plane: ``origin + s u + t v``
for ``s, t`` in [0, 1], sampled at ``nx`` x ``ny`` nodes (the corners
included). :func:`illuminance_map` evaluates the exact illuminance (soft
shadows included) at the nodes, for receivers facing ``normalize(u x v)``.
:func:`isolux_lines` traces contour lines of the map by marching squares
(contourpy; saddle cells are split by the cell-centre average), and
:func:`save_luxmap_png` draws the map with its isolux lines.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import Vec3, integer, nonzero_vector3, vector3
from ..errors import InvalidParameterError
from ..kinds import DEFAULT_RESOLUTION

__all__ = [
    "LuxGrid", "LuxMap", "IsoluxLine", "illuminance_map", "isolux_lines", "nice_levels", "occluded_nodes",
    "save_luxmap_png",
]

ProgressCallback = Callable[[int, int], None]

#: Largest accepted number of nodes along one side of a grid.
MAX_NODES = 4096


@dataclass(frozen=True, slots=True)
class LuxGrid:
    """A grid of receiving points on a plane.

    Parameters
    ----------
    origin : array_like, shape (3,)
        The corner ``s = t = 0``.
    u, v : array_like, shape (3,)
        Edge vectors (not parallel); receivers face ``normalize(u x v)``.
    nx, ny : int
        Nodes along ``u`` and ``v`` (2 .. 4096).

    Raises
    ------
    InvalidParameterError
        On non-finite or parallel edges, or node counts out of range.

    Examples
    --------
    >>> g = LuxGrid((-1, -1, 0), (2, 0, 0), (0, 2, 0), 3, 2)
    >>> g.points().shape, g.normal.tolist()
    ((2, 3, 3), [0.0, 0.0, 1.0])
    """

    origin: Vec3
    u: Vec3
    v: Vec3
    nx: int = 64
    ny: int = 64

    def __post_init__(self) -> None:
        err = InvalidParameterError
        object.__setattr__(self, "origin", vector3("grid.origin", self.origin, error=err))
        object.__setattr__(self, "u", nonzero_vector3("grid.u", self.u, error=err))
        object.__setattr__(self, "v", nonzero_vector3("grid.v", self.v, error=err))
        c = np.cross(self.u, self.v)
        if np.linalg.norm(c) <= 1e-9 * np.linalg.norm(self.u) * np.linalg.norm(self.v):
            raise err(f"grid.u {self.u} and grid.v {self.v} must not be parallel")
        object.__setattr__(self, "nx", integer("grid.nx", self.nx, low=2, high=MAX_NODES, error=err))
        object.__setattr__(self, "ny", integer("grid.ny", self.ny, low=2, high=MAX_NODES, error=err))

    @property
    def normal(self) -> NDArray[np.float64]:
        """Unit normal ``normalize(u x v)`` the receivers face."""
        c = np.cross(self.u, self.v)
        return c / np.linalg.norm(c)

    def points(self) -> NDArray[np.float64]:
        """Node positions, shape (ny, nx, 3); ``[j, i]`` is ``origin + i/(nx-1) u + j/(ny-1) v``."""
        s = np.linspace(0.0, 1.0, self.nx)
        t = np.linspace(0.0, 1.0, self.ny)
        return np.asarray(self.origin) + s[None, :, None] * np.asarray(self.u) + t[:, None, None] * np.asarray(self.v)

    def to_world(self, ij: ArrayLike) -> NDArray[np.float64]:
        """Fractional node coordinates ``(i, j)`` (n, 2) to world points (n, 3)."""
        a = np.asarray(ij, dtype=np.float64).reshape(-1, 2)
        return (
            np.asarray(self.origin)
            + (a[:, :1] / (self.nx - 1)) * np.asarray(self.u)
            + (a[:, 1:] / (self.ny - 1)) * np.asarray(self.v)
        )

    @classmethod
    def from_bounds(cls, xmin: float, ymin: float, xmax: float, ymax: float, z: float, nx: int = 64,
                    ny: int = 64) -> LuxGrid:
        """A horizontal grid facing up (+z) over ``[xmin, xmax] x [ymin, ymax]`` at height ``z``.

        Examples
        --------
        >>> LuxGrid.from_bounds(0, 0, 4, 3, 0.8, 5, 4).u
        (4.0, 0.0, 0.0)
        """
        return cls((xmin, ymin, z), (xmax - xmin, 0.0, 0.0), (0.0, ymax - ymin, 0.0), nx, ny)


@dataclass(frozen=True, slots=True)
class IsoluxLine:
    """One isolux polyline.

    Attributes
    ----------
    level : float
        Its illuminance.
    ij : ndarray, shape (k, 2)
        Fractional node coordinates ``(i, j)`` along the line.
    points : ndarray, shape (k, 3)
        The same in world coordinates.
    closed : bool
        Whether the line closes on itself.
    """

    level: float
    ij: NDArray[np.float64] = field(compare=False)
    points: NDArray[np.float64] = field(compare=False)
    closed: bool


@dataclass(frozen=True, slots=True, eq=False)
class LuxMap:
    """Illuminance at the nodes of a :class:`LuxGrid`.

    Attributes
    ----------
    grid : LuxGrid
    E : ndarray, shape (ny, nx)
        Illuminance in lux (lx = lm/m^2) for source radiances in cd/m^2;
        ``E[j, i]`` at node ``(i, j)``.
    occluded : ndarray of bool, shape (ny, nx), optional
        Nodes inside an occluder (covered by a solid standing on the
        receiving plane): no light can reach them, and statistics leave them
        out rather than count them as 0 lx. Defaults to none.
    """

    grid: LuxGrid
    E: NDArray[np.float64]
    occluded: NDArray[np.bool_] | None = None

    def __post_init__(self) -> None:
        E = np.asarray(self.E, dtype=np.float64)
        shape = (self.grid.ny, self.grid.nx)
        if E.shape != shape:
            raise InvalidParameterError(f"E must have shape {shape} (ny, nx), got {E.shape}")
        object.__setattr__(self, "E", E)
        occ = np.zeros(shape, dtype=bool) if self.occluded is None else np.asarray(self.occluded, dtype=bool)
        if occ.shape != shape:
            raise InvalidParameterError(f"occluded must have shape {shape} (ny, nx), got {occ.shape}")
        object.__setattr__(self, "occluded", occ)

    def isolux(self, levels: Sequence[float] | int | None = None) -> list[IsoluxLine]:
        """Isolux lines of the map at ``levels`` (or that many :func:`nice_levels`)."""
        lv = _levels(self.E, levels)
        return [
            IsoluxLine(level, ij, self.grid.to_world(ij), closed)
            for level, lines in zip(lv, isolux_lines(self.E, lv))
            for ij, closed in lines
        ]


def illuminance_map(
    grid: LuxGrid,
    lights: Any,
    occluders: Sequence[Any] | Any = (),
    *,
    resolution: int = DEFAULT_RESOLUTION,
    progress: ProgressCallback | None = None,
) -> LuxMap:
    """Exact illuminance (soft shadows included) at the nodes of a grid.

    Direct light only: the sources' light that reaches a node in a straight
    line; occluders are black (they reflect nothing), and nothing is
    inter-reflected. With radiances in cd/m^2 the illuminance is in lux.
    Nodes just inside a solid (tested a hair above the plane, on the side
    the receivers face) are marked in :attr:`LuxMap.occluded`.

    Parameters
    ----------
    grid : LuxGrid
    lights : AreaLight, PolyhedronLight, PhotometricLight or a sequence of them
        Point luminaires (:class:`~isocsg.lighting.luminaire.PhotometricLight`) cast hard shadows.
    occluders : Solid or sequence of Solid, optional
    resolution : int, keyword-only, default 64
        Tessellation of curved occluders.
    progress : callable, optional
        ``progress(done_rows, total_rows)``.

    Returns
    -------
    LuxMap

    Raises
    ------
    InvalidParameterError
        If ``grid`` is not a :class:`LuxGrid`.
    InvalidLightError
        If ``lights`` holds something else than area or polyhedron lights.

    Examples
    --------
    >>> from isocsg.lighting.area import AreaLight
    >>> lamp = AreaLight([(-.5, -.5, 2), (-.5, .5, 2), (.5, .5, 2), (.5, -.5, 2)])
    >>> m = illuminance_map(LuxGrid.from_bounds(-2, -2, 2, 2, 0, 5, 5), lamp)
    >>> m.E.shape, bool(m.E[2, 2] == m.E.max())
    ((5, 5), True)
    """
    from .direct import illuminance

    if not isinstance(grid, LuxGrid):
        raise InvalidParameterError(f"grid must be a LuxGrid, got {type(grid).__name__}")
    pts = grid.points()
    n = grid.normal
    E = np.empty((grid.ny, grid.nx))
    occluded = np.zeros((grid.ny, grid.nx), dtype=bool)
    solids, eps = _probe(grid, occluders)
    step = max(1, 4096 // grid.nx)
    for j0 in range(0, grid.ny, step):
        j1 = min(grid.ny, j0 + step)
        # a solid whose face holds the grid lies behind the receiving plane: it casts nothing on it
        p = pts[j0:j1].reshape(-1, 3)
        E[j0:j1] = illuminance(p, n, lights, occluders, resolution=resolution).reshape(j1 - j0, grid.nx)
        occluded[j0:j1] = _inside(p + eps * n, solids).reshape(j1 - j0, grid.nx)
        if progress is not None:
            progress(j1, grid.ny)
    return LuxMap(grid, E, occluded)


def occluded_nodes(grid: LuxGrid, occluders: Sequence[Any] | Any = ()) -> NDArray[np.bool_]:
    """Nodes of the grid inside a solid occluder, shape (ny, nx).

    Each node is tested a hair (1e-7 of the grid's size) above the plane, on
    the side the receivers face: a solid resting on the plane covers the
    nodes under it, while a floor slab whose top face holds the grid does not.

    Examples
    --------
    >>> from isocsg import Box
    >>> g = LuxGrid.from_bounds(-1, -1, 1, 1, 0, 5, 5)
    >>> occluded_nodes(g, [Box((0, 0, -0.5), (4, 4, 1)), Box((0, 0, 0.5), (0.6, 0.6, 1))]).sum()
    np.int64(1)
    """
    solids, eps = _probe(grid, occluders)
    return _inside(grid.points().reshape(-1, 3) + eps * grid.normal, solids).reshape(grid.ny, grid.nx)


def _probe(grid: LuxGrid, occluders: Any) -> tuple[list[Any], float]:
    """The solid occluders and the height above the plane at which nodes are tested."""
    from ..kinds import Solid

    solids = [occluders] if isinstance(occluders, Solid) else [o for o in occluders if isinstance(o, Solid)]
    return solids, 1e-7 * max(float(np.linalg.norm(grid.u)), float(np.linalg.norm(grid.v)))


def _inside(points: NDArray[np.float64], solids: list[Any]) -> NDArray[np.bool_]:
    out = np.zeros(len(points), dtype=bool)
    for solid in solids:
        out |= solid.contains(points, tol=0.0)
    return out


def nice_levels(E: ArrayLike, count: int = 8) -> NDArray[np.float64]:
    """About ``count`` round contour levels strictly inside the range of ``E``.

    Examples
    --------
    >>> nice_levels([0.0, 1.0], 4).tolist()
    [0.2, 0.4, 0.6, 0.8]
    """
    a = np.asarray(E, dtype=np.float64)
    a = a[np.isfinite(a)]
    count = integer("count", count, low=1, high=10000, error=InvalidParameterError)
    if a.size == 0 or a.max() <= a.min():
        return np.zeros(0)
    lo, hi = float(a.min()), float(a.max())
    raw = (hi - lo) / (count + 1)
    mag = 10 ** math.floor(math.log10(raw))
    step = min((m * mag for m in (1, 2, 2.5, 5, 10) if m * mag >= raw), default=10 * mag)
    first = math.floor(lo / step) * step + step
    lv: NDArray[np.float64] = np.arange(first, hi, step, dtype=np.float64)
    return np.round(lv[(lv > lo) & (lv < hi)], 12)


def _levels(E: NDArray[np.float64], levels: Sequence[float] | int | None) -> NDArray[np.float64]:
    if levels is None:
        return nice_levels(E)
    if isinstance(levels, (int, np.integer)) and not isinstance(levels, bool):
        return nice_levels(E, int(levels))
    lv = np.asarray(levels, dtype=np.float64).reshape(-1)
    if not np.all(np.isfinite(lv)):
        raise InvalidParameterError(f"levels must be finite numbers, got {lv.tolist()}")
    return lv


def isolux_lines(E: ArrayLike, levels: ArrayLike) -> list[list[tuple[NDArray[np.float64], bool]]]:
    """Contour lines of a 2D field by marching squares (contourpy).

    Cells are split by linear interpolation along their edges; a saddle cell
    is resolved by the average of its four corners. Lines are contourpy's
    ``serial`` algorithm without corner masking: the same points, to 1e-12,
    as a plain marching-squares tracer (where a line runs through a node
    lying exactly on the level, the two may split it into polylines
    differently there; the segments are the same).

    Each level is traced on the smallest rectangle of nodes that holds all
    its lines (found from the extremes of each row and column of nodes), or
    on the whole grid when that costs less: contourpy's time grows with the
    nodes it is given, and most levels of a lux map cross a small part of it.
    The lines are those of the whole grid, point for point.

    Parameters
    ----------
    E : array_like, shape (ny, nx)
        Values at grid nodes, ``E[j, i]``; NaN nodes are left out (cells
        touching them have no lines).
    levels : array_like, shape (k,)

    Returns
    -------
    list of list of (ndarray, bool)
        For each level, its polylines as ``(points (m, 2) of fractional
        node coordinates (i, j), closed)``; a closed line repeats its first
        point at the end.

    Raises
    ------
    InvalidParameterError
        If ``E`` is not a 2-D array of at least 2 x 2 values.

    Examples
    --------
    >>> j, i = np.mgrid[0:5, 0:5]
    >>> (line, closed), = isolux_lines(i + 2.0 * j, [3.5])[0]   # the line i + 2 j = 3.5
    >>> closed, bool(np.allclose(line @ [1, 2], 3.5)), len(line)
    (False, True, 6)
    >>> (ring, closed), = isolux_lines(-np.hypot(i - 2.0, j - 2.0), [-1.5])[0]
    >>> closed, len(ring)
    (True, 13)
    """
    Z = np.asarray(E, dtype=np.float64)
    if Z.ndim != 2 or min(Z.shape) < 2:
        raise InvalidParameterError(f"E must be a 2-D array with at least 2 x 2 values, got shape {Z.shape}")
    bad = ~np.isfinite(Z)
    mask = bad if bad.any() else None
    z = np.where(bad, 0.0, Z) if mask is not None else np.ascontiguousarray(Z)
    lv = [float(level) for level in np.asarray(levels, dtype=np.float64).reshape(-1)]
    boxes = _level_boxes(z, lv)
    shared = _shared_levels(boxes, z.size)
    full = None
    out: list[list[tuple[NDArray[np.float64], bool]]] = []
    for k, (level, box) in enumerate(zip(lv, boxes)):
        if box is None:
            out.append([])
            continue
        if k in shared:
            if full is None:
                full = _generator(z, mask, (0, z.shape[0], 0, z.shape[1]))
            gen = full
        else:
            gen = _generator(z, mask, box)
        points, codes = gen.lines(level)
        out.append([
            (np.asarray(pts, dtype=np.float64), bool(len(code) and code[-1] == _CLOSEPOLY))
            for pts, code in zip(points, codes)
        ])
    return out


def _level_boxes(z: NDArray[np.float64], levels: list[float]) -> list[tuple[int, int, int, int] | None]:
    """The node rectangle ``(j0, j1, i0, i1)`` (ends excluded) holding every line of each level, or None.

    A cell row (node rows j and j + 1) holds a line of a level only if the
    level lies between the smallest and the largest value of those two node
    rows (inclusive); so does a cell column. The rectangle of those cell rows
    and columns holds every cell the level crosses, and contourpy traces the
    same lines on it as on the whole grid: no line reaches its edges except
    where the grid's edges are.
    """
    rmin, rmax = z.min(axis=1), z.max(axis=1)
    cmin, cmax = z.min(axis=0), z.max(axis=0)
    row_lo, row_hi = np.minimum(rmin[:-1], rmin[1:]), np.maximum(rmax[:-1], rmax[1:])
    col_lo, col_hi = np.minimum(cmin[:-1], cmin[1:]), np.maximum(cmax[:-1], cmax[1:])
    boxes: list[tuple[int, int, int, int] | None] = []
    for level in levels:
        rows = np.flatnonzero((row_lo <= level) & (level <= row_hi))
        cols = np.flatnonzero((col_lo <= level) & (level <= col_hi))
        if len(rows) == 0 or len(cols) == 0:
            boxes.append(None)
        else:
            boxes.append((int(rows[0]), int(rows[-1]) + 2, int(cols[0]), int(cols[-1]) + 2))
    return boxes


# contourpy's cost per grid node, in units of one level's tracing on the whole grid:
# building a generator (and copying its coordinates) costs about 1.6 traces, so a
# level traced on its own rectangle costs 2.6 traces per node of the rectangle.
# Measured on 512 x 512 grids (benchmarks/isolux.py).
_GENERATOR_COST = 1.6
_CROPPED_COST = 2.6


def _shared_levels(boxes: list[tuple[int, int, int, int] | None], nodes: int) -> set[int]:
    """Indices of the levels cheaper to trace on one generator over the whole grid than on their rectangles.

    Levels whose rectangles are largest move to the shared generator first; the
    number moved is the one of least estimated cost.
    """
    area = [0 if b is None else (b[1] - b[0]) * (b[3] - b[2]) for b in boxes]
    order = sorted(range(len(boxes)), key=lambda k: -area[k])
    cropped = _CROPPED_COST * sum(area)
    best, best_k = cropped, 0
    cost = _GENERATOR_COST * nodes
    for k, idx in enumerate(order, 1):
        cropped -= _CROPPED_COST * area[idx]
        cost += nodes
        if cost + cropped < best:
            best, best_k = cost + cropped, k
    return set(order[:best_k])


def _generator(z: NDArray[np.float64], mask: NDArray[np.bool_] | None, box: tuple[int, int, int, int]) -> Any:
    """contourpy's serial generator on the node rectangle ``box`` (node coordinates are the grid indices)."""
    import contourpy

    j0, j1, i0, i1 = box
    x, y = np.meshgrid(np.arange(i0, i1, dtype=np.float64), np.arange(j0, j1, dtype=np.float64))
    # The generator class itself, not contourpy.contour_generator(): that front
    # end also validates through masked arrays and builds the coordinate grids,
    # which cost as much as tracing a few levels on a 512 x 512 grid.
    return contourpy.SerialContourGenerator(
        x, y, np.ascontiguousarray(z[j0:j1, i0:i1]),
        # None: no mask (contourpy's own front end passes None; its stub says an array).
        None if mask is None else np.ascontiguousarray(mask[j0:j1, i0:i1]),  # type: ignore[arg-type]
        corner_mask=False, quad_as_tri=False, z_interp=contourpy.ZInterp.Linear,
        line_type=contourpy.LineType.SeparateCode, fill_type=contourpy.FillType.OuterCode,
        x_chunk_size=0, y_chunk_size=0,
    )


# contourpy's (matplotlib's) path code that closes a line.
_CLOSEPOLY = 79


def save_luxmap_png(
    path: Any,
    luxmap: LuxMap,
    *,
    levels: Sequence[float] | int | None = None,
    pixels_per_node: int = 4,
    vmax: float | None = None,
) -> Any:
    """Write the map as a grey PNG with its isolux lines drawn (Pillow).

    The image's top row is the grid's ``t = 1`` edge (``v`` points up), its
    left column ``s = 0``. Grey ``E / vmax`` (default the map's maximum);
    lines alternate red and blue by level.

    Parameters
    ----------
    path : str or path-like
    luxmap : LuxMap
    levels : sequence of float or int, optional
        Contour levels, or how many :func:`nice_levels`.
    pixels_per_node : int, keyword-only, default 4
    vmax : float, optional

    Returns
    -------
    pathlib.Path
        The file written.

    Examples
    --------
    >>> import os, tempfile
    >>> from isocsg.lighting.area import AreaLight
    >>> lamp = AreaLight([(-.5, -.5, 2), (-.5, .5, 2), (.5, .5, 2), (.5, -.5, 2)])
    >>> m = illuminance_map(LuxGrid.from_bounds(-2, -2, 2, 2, 0, 9, 9), lamp)
    >>> p = save_luxmap_png(os.path.join(tempfile.mkdtemp(), "lux.png"), m, levels=3)
    >>> p.suffix, p.stat().st_size > 0
    ('.png', True)
    """
    from pathlib import Path

    from PIL import Image, ImageDraw

    k = integer("pixels_per_node", pixels_per_node, low=1, high=64, error=InvalidParameterError)
    E = luxmap.E
    top = float(np.nanmax(E)) if vmax is None else float(vmax)
    if not math.isfinite(top) or top <= 0:
        top = 1.0
    grey = np.clip(np.nan_to_num(E / top), 0, 1)
    ny, nx = E.shape
    grey_img = Image.fromarray(np.rint(grey[::-1] * 255).astype(np.uint8), mode="L")
    img = grey_img.resize((nx * k, ny * k), Image.Resampling.NEAREST)
    img = img.convert("RGB")
    draw = ImageDraw.Draw(img)
    colours = [(220, 40, 40), (40, 90, 230)]
    lines = luxmap.isolux(levels)
    order = {lv: n for n, lv in enumerate(sorted({line.level for line in lines}))}
    for line in lines:
        xy = [(float((i + 0.5) * k), float((ny - 1 - j + 0.5) * k)) for i, j in line.ij]
        if len(xy) >= 2:
            draw.line(xy, fill=colours[order[line.level] % 2], width=max(1, k // 3))
    p = Path(path)
    img.save(p, format="PNG")
    return p
