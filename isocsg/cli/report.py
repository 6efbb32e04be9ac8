"""``isocsg report SCENE -o REPORT.html|.pdf``: a lighting study report from a scene file's ``[study]`` table.

An ``[interreflections]`` table in the file adds the reflected light, as for
``isocsg illuminance``.

See :mod:`isocsg.interop.study` for the table (room, working plane, task
areas, luminaires from IES or EULUMDAT files) and :mod:`isocsg.interop.report`
for what the report holds.
"""

from __future__ import annotations

import argparse
from typing import Any

__all__ = ["register", "run"]

_DESCRIPTION = """\
Compute a lighting study (EN 12464-1 grids with points at cell centres, maintained Ebar, Emin, Emax,
U0 and Emin/Emax per area, cylindrical illuminance, exact direct light with shadows) from the scene
file's [study] table and write the report as HTML or PDF: plan view with lux map, colour bar in lx and
isolux lines, the grid table, the figures against the required values, the luminaire schedule.
An [interreflections] table in the scene file adds the light reflected by the room and the objects
(see docs/interreflections.md).
"""


def register(subparsers: Any) -> argparse.ArgumentParser:
    p = subparsers.add_parser("report", help="lighting study report (HTML or PDF)", description=_DESCRIPTION)
    p.add_argument("scene", help="scene file (.toml or .json) with a [study] table")
    p.add_argument("-o", "--output", required=True, metavar="REPORT", help="report to write: .html or .pdf")
    p.add_argument("--plan", metavar="PLAN.png", help="also write the plan view as PNG")
    p.add_argument("--resolution", type=int, default=None, help="tessellation of curved occluders (default 64)")
    p.set_defaults(func=run)
    return p


def run(args: argparse.Namespace) -> int:
    from pathlib import Path

    from .._validation import resolution
    from ..errors import InvalidParameterError
    from ..interop.report import write_report
    from ..interop.study import load_study, run_study
    from ..kinds import DEFAULT_RESOLUTION

    out = Path(args.output)
    if out.suffix.lower() not in (".html", ".pdf"):
        raise InvalidParameterError(f"--output must end in .html or .pdf, got {out.name!r}")
    res = DEFAULT_RESOLUTION if args.resolution is None else resolution("--resolution", args.resolution)
    scene, spec = load_study(args.scene)
    result = run_study(spec, scene, resolution=res)
    if result.radiosity is not None:
        sol = result.radiosity
        print(f"interreflections: {len(sol.patches)} patches, {sol.shots} shots, "
              f"residual {sol.residuals[-1] if sol.shots else 0.0:.2g}")
    for f in result.figures:
        req = "" if f.required is None else f"  (required Em {f.required.em:g} lx, U0 {f.required.u0:g})"
        print(f"{f.name}: Ebar {f.e_mean:.4g} lx  Emin {f.e_min:.4g} lx  Emax {f.e_max:.4g} lx  "
              f"U0 {f.u0:.3f}  Emin/Emax {f.min_max:.3f}  {f.points} points{req}")
    if result.cylindrical is not None:
        c = result.cylindrical
        print(f"{c.name}: Ebar {c.e_mean:.4g} lx  Emin {c.e_min:.4g} lx  "
              f"Emax {c.e_max:.4g} lx  U0 {c.u0:.3f}  {c.points} points")
    for v in result.vertical:
        print(f"{v.name}: Ebar {v.e_mean:.4g} lx  Emin {v.e_min:.4g} lx  "
              f"Emax {v.e_max:.4g} lx  {v.points} points")
    print(f"wrote {write_report(out, result, plan_png=args.plan)}")
    if args.plan:
        print(f"wrote {args.plan}")
    return 0
