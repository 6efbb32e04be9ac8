"""A lighting study from a scene file: luminaires from IES and EULUMDAT files, EN 12464-1 grids, a report.

Reads ``examples/study/office.toml`` (four LED panels from ``panel.ldt``, two
downlights from ``downlight.ies``, a desk and a cabinet), computes the figures
per area (points at cell centres, maintained values) and writes the report as
``office_study.pdf`` and ``office_study.html``, and the plan view as
``office_study_plan.png``. The same as::

    isocsg report examples/study/office.toml -o office_study.pdf --plan office_study_plan.png

Needs the ``[photometry]`` and ``[plot]`` extras.
"""

from __future__ import annotations

import sys
from pathlib import Path

from isocsg.interop.report import write_report
from isocsg.interop.study import load_study, run_study

DEFAULT_OUTPUT = Path("out") / "examples"
SCENE = Path(__file__).resolve().parent / "study" / "office.toml"


def run(output_dir: str | Path | None = None) -> list[Path]:
    """Write the PDF, the HTML and the plan PNG; returns their paths."""
    out = Path(output_dir) if output_dir is not None else DEFAULT_OUTPUT
    out.mkdir(parents=True, exist_ok=True)
    scene, spec = load_study(SCENE)
    result = run_study(spec, scene, map_nodes=90)
    for f in result.figures:
        print(f"{f.name}: Ebar {f.e_mean:.4g} lx, U0 {f.u0:.3f}, meets the requirement: {f.passes}")
    plan = out / "office_study_plan.png"
    return [
        write_report(out / "office_study.pdf", result, plan_png=plan),
        write_report(out / "office_study.html", result),
        plan,
    ]


if __name__ == "__main__":
    for p in run(sys.argv[1] if len(sys.argv) > 1 else None):
        print(p)
