"""Lighting study reports: a plan view with its lux map, the grid table, the figures against the
required values, and the luminaire schedule, as HTML or PDF (matplotlib's PDF backend).

:func:`write_report` takes a :class:`~isocsg.interop.study.StudyResult`
(:func:`~isocsg.interop.study.run_study`); the format follows the extension
(``.html`` or ``.pdf``). The plan view is drawn by
:func:`~isocsg.shadows.luxplot.plot_luxmap` (colour bar in lx, labelled
isolux lines) with the walls' band, the task areas and their surroundings,
the grid points of the room's calculation area and the luminaires on top.
"""

from __future__ import annotations

import base64
import html
import io
import math
import os
from pathlib import Path
from typing import Any

from ..errors import InvalidParameterError
from ..shadows.en12464 import AreaFigures, grid_spacing
from ..shadows.luxplot import _pyplot, plot_luxmap
from .study import StudyResult

__all__ = ["plan_figure", "figures_rows", "schedule_rows", "write_report", "FIGURE_COLUMNS", "SCHEDULE_COLUMNS"]

FIGURE_COLUMNS = ("Area", "Points", "Cells (m)", "p max (m)", "Ebar (lx)", "Emin (lx)", "Emax (lx)", "U0",
                  "Emin/Emax", "Em req. (lx)", "U0 req.", "Result")
SCHEDULE_COLUMNS = ("Name", "File", "Luminaire", "Position (m)", "Rotation / tilt (deg)", "Multiplier",
                    "Flux (lm)", "Lamp flux (lm)", "LOR", "Model")


def _fmt(x: float, digits: int = 4) -> str:
    return "-" if x is None or (isinstance(x, float) and math.isnan(x)) else f"{x:.{digits}g}"


def figures_rows(result: StudyResult) -> list[list[str]]:
    """The figures table, one row of strings per area (columns :data:`FIGURE_COLUMNS`)."""
    rows = []
    figs: list[AreaFigures] = list(result.figures) + ([result.cylindrical] if result.cylindrical else [])
    figs += list(result.vertical)
    for f in figs:
        req = f.required
        ok = f.passes
        # the cylindrical and vertical figures use the room's grid (at their own height)
        grid = next((a.grid for a in result.areas if a.name == f.name), result.areas[0].grid)
        pmax = grid_spacing(max(grid.rect[2] - grid.rect[0], grid.rect[3] - grid.rect[1]))
        rows.append([
            f.name, str(f.points), f"{f.spacing[0]:.3f} x {f.spacing[1]:.3f}", f"{pmax:.3f}", _fmt(f.e_mean),
            _fmt(f.e_min), _fmt(f.e_max), _fmt(f.u0, 3), _fmt(f.min_max, 3),
            _fmt(req.em) if req else "-", _fmt(req.u0, 2) if req else "-",
            "-" if ok is None else ("meets" if ok else "FAILS"),
        ])
    return rows


def schedule_rows(result: StudyResult) -> list[list[str]]:
    """The luminaire schedule, one row of strings per luminaire (columns :data:`SCHEDULE_COLUMNS`)."""
    rows = []
    for lu in result.spec.luminaires:
        li, ph = lu.light, lu.light.photometry
        file = f"{ph.source} ({ph.file_format})" if ph.file_format else ph.source
        position = "(" + ", ".join(f"{v:.3g}" for v in li.position) + ")"
        rows.append([
            lu.name, file, ph.label or "-", position,
            f"{li.rotation:.4g} / {li.tilt:.4g}", f"{li.multiplier:.4g}", _fmt(li.flux, 5), _fmt(ph.lamp_flux, 5),
            _fmt(ph.lor, 3) if math.isfinite(ph.lor) else f"{_fmt(ph.computed_lor, 3)} (computed)", lu.model,
        ])
    return rows


def plan_figure(result: StudyResult, *, levels: int = 8) -> Any:
    """The plan view: lux map (maintained lx), isolux lines, areas, grid points and luminaires."""
    plt = _pyplot()
    x0, y0, x1, y1 = result.spec.room
    w = 9.0
    h = min(8.0, max(3.5, (w - 2.2) * (y1 - y0) / (x1 - x0) + 1.6))
    fig, ax = plt.subplots(figsize=(w, h))
    plot_luxmap(result.plan, levels=levels, ax=ax, stats=False,
                title=f"{result.spec.title}: maintained illuminance at {result.spec.height:g} m "
                      f"(MF {result.spec.maintenance_factor:g})")
    styles = {"room": ("white", ":"), "task": ("cyan", "-"), "surrounding": ("cyan", "--"),
              "background": ("0.85", "-.")}
    for a in result.areas:
        colour, ls = styles[a.kind]
        ax0, ay0, ax1, ay1 = a.grid.rect
        ax.plot([ax0, ax1, ax1, ax0, ax0], [ay0, ay0, ay1, ay1, ay0], color=colour, ls=ls, lw=1.0)
        if a.kind == "task":
            ax.text(ax0, ay1, f" {a.name}", color="cyan", fontsize=7, va="bottom")
    pts = result.areas[0].grid.kept_points()
    ax.plot(pts[:, 0], pts[:, 1], ".", color="black", ms=1.5, alpha=0.6)
    for lu in result.spec.luminaires:
        px, py = lu.light.position[0], lu.light.position[1]
        if lu.model == "opening":  # the luminous opening that stands for the luminaire
            q = lu.light.opening_polygon()
            ax.fill(q[:, 0], q[:, 1], facecolor="none", edgecolor="white", lw=0.8)
        ax.plot([px], [py], marker="X", color="white", mec="black", ms=8)
        ax.text(px, py, f"  {lu.name}", color="white", fontsize=7, va="center")
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    return fig


def _table_page(plt: Any, result: StudyResult) -> Any:
    fig = plt.figure(figsize=(11.69, 8.27))
    fig.suptitle(f"{result.spec.title}: figures (EN 12464-1 grids) and luminaire schedule", fontsize=11)
    ax1 = fig.add_axes((0.03, 0.45, 0.94, 0.45))
    ax1.axis("off")
    ax1.set_title("Maintained illuminance per area (points at cell centres)", fontsize=9, loc="left")
    widths = [0.16] + [0.076] * (len(FIGURE_COLUMNS) - 1)
    t = ax1.table(cellText=figures_rows(result), colLabels=FIGURE_COLUMNS, loc="upper center", cellLoc="center",
                  colWidths=widths)
    t.auto_set_font_size(False)
    t.set_fontsize(7)
    t.scale(1.0, 1.3)
    rows1 = len(figures_rows(result))
    top = 0.9 - 0.45 * min(1.0, (rows1 + 2) / 14)  # below the first table
    ax2 = fig.add_axes((0.03, top - 0.35, 0.94, 0.3))
    ax2.axis("off")
    ax2.set_title("Luminaire schedule", fontsize=9, loc="left")
    rows = schedule_rows(result) or [["-"] * len(SCHEDULE_COLUMNS)]
    widths2 = [0.05, 0.13, 0.22, 0.1, 0.09, 0.06, 0.07, 0.08, 0.1, 0.06]
    t2 = ax2.table(cellText=rows, colLabels=SCHEDULE_COLUMNS, loc="upper center", cellLoc="center",
                   colWidths=widths2)
    t2.auto_set_font_size(False)
    t2.set_fontsize(7)
    t2.scale(1.0, 1.3)
    fig.text(0.03, 0.02, _notes(result), fontsize=6.5, va="bottom", wrap=True)
    return fig


def _notes(result: StudyResult) -> str:
    s = result.spec
    return (
        f"Direct light only (exact; no inter-reflection). Maintenance factor {s.maintenance_factor:g}. "
        f"Grids: p = 0.2 x 5^log10(d) <= 10 m, points at cell centres, {s.wall_band:g} m wall band left out; "
        "immediate surrounding 0.5 m, background 3 m. Required values: the rows cited in docs/lighting_studies.md. "
        f"{result.scene_lights} area light(s) of the scene included."
    )


def _png(fig: Any, dpi: int = 130) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi, bbox_inches="tight")
    return buf.getvalue()


def _html_table(columns: tuple[str, ...], rows: list[list[str]]) -> str:
    head = "".join(f"<th>{html.escape(c)}</th>" for c in columns)
    body = "".join(
        "<tr>" + "".join(
            f'<td class="{"bad" if v == "FAILS" else ("ok" if v == "meets" else "")}">{html.escape(v)}</td>'
            for v in r
        ) + "</tr>"
        for r in rows
    )
    return f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def write_report(
    path: str | os.PathLike[str], result: StudyResult, *, plan_png: str | os.PathLike[str] | None = None,
) -> Path:
    """Write the report (``.html`` or ``.pdf``); optionally the plan view as a PNG too.

    Raises
    ------
    InvalidParameterError
        On another extension.
    MissingDependencyError
        If matplotlib is not installed.
    """
    p = Path(path)
    kind = p.suffix.lower()
    if kind not in (".html", ".pdf"):
        raise InvalidParameterError(f"report must be .html or .pdf, got {p.name!r}")
    plt = _pyplot()
    plan = plan_figure(result)
    try:
        if plan_png is not None:
            plan.savefig(plan_png, dpi=150, bbox_inches="tight")
        if kind == ".pdf":
            from matplotlib.backends.backend_pdf import PdfPages

            tables = _table_page(plt, result)
            try:
                with PdfPages(p) as pdf:
                    pdf.savefig(plan, bbox_inches="tight")
                    pdf.savefig(tables)
            finally:
                plt.close(tables)
        else:
            img = base64.b64encode(_png(plan)).decode("ascii")
            title = html.escape(result.spec.title)
            doc = (
                f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>{title}</title><style>"
                "body{font-family:sans-serif;margin:2em}table{border-collapse:collapse;font-size:12px}"
                "td,th{border:1px solid #999;padding:3px 6px;text-align:center}td.bad{background:#f4b6b6}"
                "td.ok{background:#c8ecc8}img{max-width:100%}</style></head><body>"
                f"<h1>{title}</h1><h2>Plan view</h2><img alt='plan view lux map' src='data:image/png;base64,{img}'>"
                "<h2>Figures per area</h2>" + _html_table(FIGURE_COLUMNS, figures_rows(result))
                + "<h2>Luminaire schedule</h2>" + _html_table(SCHEDULE_COLUMNS, schedule_rows(result))
                + f"<p><small>{html.escape(_notes(result))}</small></p></body></html>"
            )
            p.write_text(doc, encoding="utf-8")
    finally:
        plt.close(plan)
    return p
