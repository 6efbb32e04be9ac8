"""The numbers lighting designers quote for a lux map, and its grid as CSV.

Over a task area (a polygon on the grid's plane; the whole grid by default),
with the nodes inside occluders left out (no light can reach them; counting
them as 0 lx would lower the minimum and the uniformity of the lit floor):

- ``Emin``, ``Eavg``, ``Emax``: the minimum, the arithmetic mean and the
  maximum of the illuminance at the nodes, in lux;
- ``U0 = Emin / Eavg``: the overall uniformity (EN 12464-1's U0).

Photometric units: source radiance (luminance) L in cd/m^2, illuminance E in
lux (lm/m^2). Scope: direct light from the area and polyhedron sources only;
occluders are black (no reflected or inter-reflected light).
"""

from __future__ import annotations

import csv
import math
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import points_array
from ..errors import InvalidParameterError
from .luxmap import LuxMap

__all__ = ["LuxStats", "lux_statistics", "task_area_mask", "save_luxmap_csv", "CSV_COLUMNS"]

#: Columns of :func:`save_luxmap_csv`, units in the names.
CSV_COLUMNS = ("i", "j", "x_m", "y_m", "z_m", "E_lx", "occluded")


@dataclass(frozen=True, slots=True)
class LuxStats:
    """Illuminance statistics over a task area.

    Attributes
    ----------
    e_min, e_avg, e_max : float
        Minimum, mean and maximum illuminance in lux over the counted nodes
        (NaN when no node counts).
    u0 : float
        Uniformity ``e_min / e_avg`` (NaN when ``e_avg`` is 0 or no node counts).
    nodes : int
        Nodes counted.
    occluded : int
        Nodes of the area left out because they lie inside an occluder.
    """

    e_min: float
    e_avg: float
    e_max: float
    u0: float
    nodes: int
    occluded: int

    def summary(self) -> str:
        """One line: ``Emin ... lx  Eavg ... lx  Emax ... lx  U0 ...``.

        Examples
        --------
        >>> LuxStats(120.0, 300.0, 410.5, 0.4, 100, 4).summary()
        'Emin 120 lx  Eavg 300 lx  Emax 410.5 lx  U0 0.400  (100 nodes; 4 inside occluders left out)'
        """
        return (
            f"Emin {self.e_min:.6g} lx  Eavg {self.e_avg:.6g} lx  Emax {self.e_max:.6g} lx  U0 {self.u0:.3f}"
            f"  ({self.nodes} nodes; {self.occluded} inside occluders left out)"
        )


def task_area_mask(luxmap: LuxMap, area: ArrayLike | None = None) -> NDArray[np.bool_]:
    """Nodes of the map inside (or on the edge of) a task area.

    Parameters
    ----------
    luxmap : LuxMap
    area : array_like, shape (k, 3), optional
        Vertices of a polygon on the grid's plane (world coordinates, metres,
        in order around it); it is projected onto the plane. None: every node.

    Returns
    -------
    ndarray of bool, shape (ny, nx)

    Raises
    ------
    InvalidParameterError
        If ``area`` has fewer than 3 points or no area on the plane.
    """
    import shapely

    g = luxmap.grid
    if area is None:
        return np.ones((g.ny, g.nx), dtype=bool)
    a = points_array("area", area, min_rows=3)
    # (s, t) of each vertex on the plane: origin + s u + t v (least squares drops the normal part).
    basis = np.column_stack([g.u, g.v])
    st, *_ = np.linalg.lstsq(basis, (a - np.asarray(g.origin)).T, rcond=None)
    # node units: i = s (nx - 1), j = t (ny - 1)
    ij = st.T * [g.nx - 1, g.ny - 1]
    poly = shapely.Polygon(ij)
    if not poly.is_valid or poly.area <= 0:
        raise InvalidParameterError(f"area must be a simple polygon with an area on the grid's plane, got {a.tolist()}")
    j, i = np.mgrid[0 : g.ny, 0 : g.nx]
    # a tolerance of 1e-9 node spacings keeps nodes on the area's edge
    return shapely.covers(poly.buffer(1e-9), shapely.points(i.ravel(), j.ravel())).reshape(g.ny, g.nx)


def lux_statistics(luxmap: LuxMap, area: ArrayLike | None = None) -> LuxStats:
    """Emin, Eavg, Emax and U0 over a task area, nodes inside occluders left out.

    Parameters
    ----------
    luxmap : LuxMap
    area : array_like, shape (k, 3), optional
        Task area polygon on the grid's plane (see :func:`task_area_mask`).

    Returns
    -------
    LuxStats

    Raises
    ------
    InvalidParameterError
        If ``luxmap`` is not a :class:`LuxMap`, or on a bad ``area``.

    Examples
    --------
    >>> from isocsg.shadows.luxmap import LuxGrid
    >>> g = LuxGrid.from_bounds(0, 0, 2, 1, 0, 3, 2)
    >>> m = LuxMap(g, np.array([[100.0, 200, 300], [100, 200, 600]]), np.array([[0, 0, 0], [0, 0, 1]], bool))
    >>> s = lux_statistics(m)
    >>> s.e_min, s.e_avg, s.e_max, s.u0, s.nodes, s.occluded
    (100.0, 180.0, 300.0, 0.5555555555555556, 5, 1)
    """
    if not isinstance(luxmap, LuxMap):
        raise InvalidParameterError(f"luxmap must be a LuxMap, got {type(luxmap).__name__}")
    inside = task_area_mask(luxmap, area)
    occ = np.asarray(luxmap.occluded, dtype=bool)
    use = inside & ~occ & np.isfinite(luxmap.E)
    e = luxmap.E[use]
    n_occ = int(np.count_nonzero(inside & occ))
    if e.size == 0:
        return LuxStats(math.nan, math.nan, math.nan, math.nan, 0, n_occ)
    e_min, e_avg, e_max = float(e.min()), float(e.mean()), float(e.max())
    u0 = e_min / e_avg if e_avg > 0 else math.nan
    return LuxStats(e_min, e_avg, e_max, u0, int(e.size), n_occ)


def save_luxmap_csv(path: str | os.PathLike[str], luxmap: LuxMap, *, decimals: int = 9) -> Path:
    """Write the grid as CSV: one row per node, columns :data:`CSV_COLUMNS`.

    ``i, j`` are the node indices along ``u`` and ``v``; ``x_m, y_m, z_m``
    its position in metres; ``E_lx`` the illuminance in lux, empty for nodes
    inside occluders (``occluded`` 1), so that a spreadsheet's MIN and
    AVERAGE leave them out.

    Parameters
    ----------
    path : str or path-like
    luxmap : LuxMap
    decimals : int, keyword-only, default 9
        Decimals of the coordinates and values.

    Returns
    -------
    pathlib.Path

    Examples
    --------
    >>> import os, tempfile
    >>> from isocsg.shadows.luxmap import LuxGrid
    >>> m = LuxMap(LuxGrid.from_bounds(0, 0, 1, 1, 0, 2, 2), np.array([[1.0, 2], [3, 4]]))
    >>> p = save_luxmap_csv(os.path.join(tempfile.mkdtemp(), "grid.csv"), m, decimals=2)
    >>> p.read_text().splitlines()[:3]
    ['i,j,x_m,y_m,z_m,E_lx,occluded', '0,0,0.00,0.00,0.00,1.00,0', '1,0,1.00,0.00,0.00,2.00,0']
    """
    if not isinstance(luxmap, LuxMap):
        raise InvalidParameterError(f"luxmap must be a LuxMap, got {type(luxmap).__name__}")
    pts = luxmap.grid.points()
    occ = np.asarray(luxmap.occluded, dtype=bool)
    fmt = f"{{:.{int(decimals)}f}}"
    p = Path(path)
    with p.open("w", newline="", encoding="utf-8") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(CSV_COLUMNS)
        ny, nx = luxmap.E.shape
        for j in range(ny):
            for i in range(nx):
                x, y, z = (fmt.format(c) for c in pts[j, i])
                e: Any = "" if occ[j, i] else fmt.format(luxmap.E[j, i])
                w.writerow((i, j, x, y, z, e, int(occ[j, i])))
    return p
