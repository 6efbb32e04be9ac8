"""Lux maps as matplotlib figures for reports: colour bar in lux, labelled isolux lines, axes in metres.

matplotlib is optional (``pip install 'isocsg[plot]'``) and imported when a
figure is drawn. The isolux lines are :func:`isocsg.shadows.luxmap.isolux_lines`
(the same lines as the PNG map and the API), labelled with their value in lux;
nodes inside occluders are shown hatched-grey and left out of the statistics
written above the map (:func:`isocsg.shadows.luxstats.lux_statistics`).
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from ..errors import InvalidParameterError, MissingDependencyError
from .luxmap import LuxMap
from .luxstats import lux_statistics

__all__ = ["plot_luxmap", "save_luxmap_figure", "plane_axes"]


def _pyplot() -> Any:
    try:
        import matplotlib

        if os.environ.get("MPLBACKEND") is None and not os.environ.get("DISPLAY"):
            matplotlib.use("Agg")  # no display: draw into files
        import matplotlib.pyplot as plt
    except ImportError as exc:
        raise MissingDependencyError(
            "lux map figures need matplotlib; install the extra: pip install 'isocsg[plot]'"
        ) from exc
    return plt


def plane_axes(luxmap: LuxMap) -> tuple[np.ndarray, np.ndarray, str, str]:
    """Node coordinates in metres along the figure's axes, and the axis labels.

    A grid whose ``u`` runs along +x and ``v`` along +y is drawn in world
    ``x`` and ``y``; any other grid in distances along ``u`` and ``v`` from
    its origin.
    """
    g = luxmap.grid
    lu, lv = float(np.linalg.norm(g.u)), float(np.linalg.norm(g.v))
    s = np.linspace(0.0, lu, g.nx)
    t = np.linspace(0.0, lv, g.ny)
    ux, vy = np.asarray(g.u) / lu, np.asarray(g.v) / lv
    if np.allclose(ux, (1, 0, 0), atol=1e-12) and np.allclose(vy, (0, 1, 0), atol=1e-12):
        return s + g.origin[0], t + g.origin[1], "x (m)", "y (m)"
    return s, t, "along u (m)", "along v (m)"


def plot_luxmap(
    luxmap: LuxMap,
    *,
    levels: Sequence[float] | int | None = None,
    area: ArrayLike | None = None,
    ax: Any = None,
    cmap: str = "magma",
    title: str | None = None,
    stats: bool = True,
) -> Any:
    """Draw a lux map: colour in lux with a colour bar, labelled isolux lines, axes in metres.

    Parameters
    ----------
    luxmap : LuxMap
    levels : sequence of float or int, keyword-only, optional
        Isolux levels in lux, or how many round levels (default 8).
    area : array_like, shape (k, 3), keyword-only, optional
        Task area polygon on the grid's plane: outlined, and the statistics
        are computed over it.
    ax : matplotlib Axes, keyword-only, optional
        Draw into these axes; default a new figure.
    cmap : str, keyword-only, default "magma"
    title : str, keyword-only, optional
    stats : bool, keyword-only, default True
        Write Emin, Eavg, Emax and U0 in the title.

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    MissingDependencyError
        If matplotlib is not installed.
    InvalidParameterError
        If ``luxmap`` is not a :class:`~isocsg.shadows.luxmap.LuxMap`.
    """
    if not isinstance(luxmap, LuxMap):
        raise InvalidParameterError(f"luxmap must be a LuxMap, got {type(luxmap).__name__}")
    plt = _pyplot()
    xs, ys, xlabel, ylabel = plane_axes(luxmap)
    if ax is None:
        # a figure of the map's aspect, room for the colour bar and the labels
        w = 6.4
        h = min(9.0, max(2.4, (w - 1.6) * (ys[-1] - ys[0]) / max(xs[-1] - xs[0], 1e-12) + 1.4))
        fig, ax = plt.subplots(figsize=(w, h))
    else:
        fig = ax.figure
    occ = np.asarray(luxmap.occluded, dtype=bool)
    E = np.ma.array(luxmap.E, mask=occ | ~np.isfinite(luxmap.E))
    colours = plt.get_cmap(cmap).with_extremes(bad="0.75")
    mesh = ax.pcolormesh(xs, ys, E, shading="gouraud" if E.mask.sum() == 0 else "nearest", cmap=colours, vmin=0.0)
    if occ.any():
        ax.contourf(xs, ys, occ.astype(float), levels=[0.5, 1.5], colors="none", hatches=["///"])
    from mpl_toolkits.axes_grid1 import make_axes_locatable

    # the colour bar as tall as the map
    bar = fig.colorbar(mesh, cax=make_axes_locatable(ax).append_axes("right", size="4%", pad=0.1))
    bar.set_label("illuminance E (lx)")
    # Isolux lines in node units (i, j) mapped to the axes' metres.
    dx = (xs[-1] - xs[0]) / (len(xs) - 1)
    dy = (ys[-1] - ys[0]) / (len(ys) - 1)
    for line in LuxMap(luxmap.grid, np.where(occ, np.nan, luxmap.E)).isolux(levels if levels is not None else 8):
        x = xs[0] + line.ij[:, 0] * dx
        y = ys[0] + line.ij[:, 1] * dy
        ax.plot(x, y, color="white", lw=0.9)
        if len(x) >= 2:
            k = len(x) // 2
            ax.text(x[k], y[k], f"{line.level:g}", color="black", fontsize=7, ha="center", va="center",
                    bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.85})
    if area is not None:
        from .luxstats import task_area_mask

        task_area_mask(luxmap, area)  # checks the polygon
        a = np.asarray(area, dtype=np.float64)
        g = luxmap.grid
        st, *_ = np.linalg.lstsq(np.column_stack([g.u, g.v]), (a - np.asarray(g.origin)).T, rcond=None)
        px = xs[0] + st[0] * (xs[-1] - xs[0])
        py = ys[0] + st[1] * (ys[-1] - ys[0])
        ax.plot(np.r_[px, px[:1]], np.r_[py, py[:1]], color="cyan", lw=1.2, ls="--", label="task area")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_aspect("equal")
    lines = [] if title is None else [title]
    if stats:
        s = lux_statistics(luxmap, area)
        where = "task area" if area is not None else "grid"
        lines.append(f"{where}: Emin {s.e_min:.4g} lx   Eavg {s.e_avg:.4g} lx   Emax {s.e_max:.4g} lx   U0 {s.u0:.2f}")
    if lines:
        ax.set_title("\n".join(lines), fontsize=9)
    return fig


def save_luxmap_figure(path: str | os.PathLike[str], luxmap: LuxMap, *, dpi: int = 150, **kwargs: Any) -> Any:
    """Draw :func:`plot_luxmap` and save it (PNG, PDF or SVG by the extension); returns the path.

    Raises
    ------
    MissingDependencyError
        If matplotlib is not installed.
    """
    from pathlib import Path

    plt = _pyplot()
    fig = plot_luxmap(luxmap, **kwargs)
    p = Path(path)
    fig.savefig(p, dpi=dpi, bbox_inches="tight")
    plt.close(fig)
    return p
