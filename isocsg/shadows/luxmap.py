"""Illuminance maps of a receiving plane and their isolux lines (lighting design).

A :class:`LuxGrid` spans a parallelogram of a plane: ``origin + s u + t v``
for ``s, t`` in [0, 1], sampled at ``nx`` x ``ny`` nodes (the corners
included). :func:`illuminance_map` evaluates the exact illuminance (soft
shadows included) at the nodes, for receivers facing ``normalize(u x v)``.
:func:`isolux_lines` traces contour lines of the map by marching squares
(saddle cells are split by the cell-centre average), and
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
from ..geometry.primitives import DEFAULT_RESOLUTION

__all__ = ["LuxGrid", "LuxMap", "IsoluxLine", "illuminance_map", "isolux_lines", "nice_levels", "save_luxmap_png"]

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
    def from_bounds(cls, xmin: float, ymin: float, xmax: float, ymax: float, z: float, nx: int = 64, ny: int = 64) -> "LuxGrid":
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
        Illuminance; ``E[j, i]`` at node ``(i, j)``.
    """

    grid: LuxGrid
    E: NDArray[np.float64]

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

    Parameters
    ----------
    grid : LuxGrid
    lights : AreaLight, PolyhedronLight or a sequence of them
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
    >>> from isocsg.shadows.lights import AreaLight
    >>> lamp = AreaLight([(-.5, -.5, 2), (-.5, .5, 2), (.5, .5, 2), (.5, -.5, 2)])
    >>> m = illuminance_map(LuxGrid.from_bounds(-2, -2, 2, 2, 0, 5, 5), lamp)
    >>> m.E.shape, bool(m.E[2, 2] == m.E.max())
    ((5, 5), True)
    """
    from .illuminance import illuminance

    if not isinstance(grid, LuxGrid):
        raise InvalidParameterError(f"grid must be a LuxGrid, got {type(grid).__name__}")
    pts = grid.points()
    n = grid.normal
    E = np.empty((grid.ny, grid.nx))
    step = max(1, 4096 // grid.nx)
    for j0 in range(0, grid.ny, step):
        j1 = min(grid.ny, j0 + step)
        # a solid whose face holds the grid lies behind the receiving plane: it casts nothing on it
        p = pts[j0:j1].reshape(-1, 3)
        E[j0:j1] = illuminance(p, n, lights, occluders, resolution=resolution).reshape(j1 - j0, grid.nx)
        if progress is not None:
            progress(j1, grid.ny)
    return LuxMap(grid, E)


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
    lv = np.arange(first, hi, step)
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


# Marching squares: corners (0: (i, j), 1: (i+1, j), 2: (i+1, j+1), 3: (i, j+1)); edges
# 0: bottom (c0-c1), 1: right (c1-c2), 2: top (c3-c2), 3: left (c0-c3). Case bit k = corner k above.
_SEGMENTS: dict[int, tuple[tuple[int, int], ...]] = {
    1: ((3, 0),), 2: ((0, 1),), 3: ((3, 1),), 4: ((1, 2),), 6: ((0, 2),), 7: ((3, 2),),
    8: ((2, 3),), 9: ((2, 0),), 11: ((2, 1),), 12: ((1, 3),), 13: ((1, 0),), 14: ((0, 3),),
}
# saddles (5: corners 0 and 2 above; 10: corners 1 and 3): (centre above, centre below)
_SADDLES = {5: (((3, 2), (1, 0)), ((3, 0), (1, 2))), 10: (((0, 3), (2, 1)), ((0, 1), (2, 3)))}


def _edge_key(i: int, j: int, e: int) -> tuple[int, int, int]:
    """A cell edge as a key shared by both cells: (i, j, 0) horizontal from (i, j), (i, j, 1) vertical."""
    return {0: (i, j, 0), 1: (i + 1, j, 1), 2: (i, j + 1, 0), 3: (i, j, 1)}[e]


def isolux_lines(E: ArrayLike, levels: ArrayLike) -> list[list[tuple[NDArray[np.float64], bool]]]:
    """Contour lines of a 2D field by marching squares.

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
        node coordinates (i, j), closed)``.

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
    out = []
    for level in np.asarray(levels, dtype=np.float64).reshape(-1):
        above = Z > level
        c = np.stack([above[:-1, :-1], above[:-1, 1:], above[1:, 1:], above[1:, :-1]])  # (4, ny-1, nx-1)
        case = c[0] * 1 + c[1] * 2 + c[2] * 4 + c[3] * 8
        finite = np.isfinite(Z)
        ok = finite[:-1, :-1] & finite[:-1, 1:] & finite[1:, 1:] & finite[1:, :-1]
        cells = np.argwhere(ok & (case != 0) & (case != 15))
        points: dict[tuple[int, int, int], NDArray[np.float64]] = {}
        adj: dict[tuple[int, int, int], list[tuple[int, int, int]]] = {}

        def point(i: int, j: int, e: int) -> tuple[int, int, int]:
            k = _edge_key(i, j, e)
            if k not in points:
                a0, a1 = (k[0], k[1]), ((k[0] + 1, k[1]) if k[2] == 0 else (k[0], k[1] + 1))
                z0, z1 = Z[a0[1], a0[0]], Z[a1[1], a1[0]]
                t = (level - z0) / (z1 - z0)
                points[k] = np.array([a0[0] + t * (a1[0] - a0[0]), a0[1] + t * (a1[1] - a0[1])])
            return k

        for j, i in cells:
            cs = int(case[j, i])
            if cs in _SADDLES:
                centre = 0.25 * (Z[j, i] + Z[j, i + 1] + Z[j + 1, i + 1] + Z[j + 1, i])
                segs = _SADDLES[cs][0 if centre > level else 1]
            else:
                segs = _SEGMENTS[cs]
            for e0, e1 in segs:
                a, b = point(i, j, e0), point(i, j, e1)
                adj.setdefault(a, []).append(b)
                adj.setdefault(b, []).append(a)
        out.append(_chain(points, adj))
    return out


def _chain(points: dict[Any, NDArray[np.float64]], adj: dict[Any, list[Any]]) -> list[tuple[NDArray[np.float64], bool]]:
    """Join segments (an adjacency of edge points) into polylines."""
    seen: set[tuple[Any, Any]] = set()
    lines = []
    # open lines start at points with one neighbour (the grid border); then the closed loops
    starts = [k for k, nb in adj.items() if len(nb) == 1] + list(adj)
    for s in starts:
        for nxt in adj[s]:
            if (s, nxt) in seen:
                continue
            path = [s]
            prev, cur = s, nxt
            seen.add((s, nxt))
            seen.add((nxt, s))
            closed = False
            while True:
                path.append(cur)
                if cur == s:
                    closed = True
                    break
                options = [k for k in adj[cur] if (cur, k) not in seen]
                if not options:
                    break
                prev, cur = cur, options[0]
                seen.add((prev, cur))
                seen.add((cur, prev))
            lines.append((np.array([points[k] for k in path]), closed))
    return lines


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
    >>> from isocsg.shadows.lights import AreaLight
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
    img = Image.fromarray(np.rint(grey[::-1] * 255).astype(np.uint8), mode="L").resize((nx * k, ny * k), Image.NEAREST)
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
