"""``isocsg illuminance SCENE -o MAP.png``: an illuminance map with isolux lines.

The grid lies on a plane given on the command line (``--origin``, ``--u``,
``--v``), or in the scene file's optional ``[illuminance]`` table::

    [illuminance]
    origin = [-3.0, -3.0, 0.0]     # corner of the grid
    u = [6.0, 0.0, 0.0]            # edge vectors; receivers face normalize(u x v)
    v = [0.0, 6.0, 0.0]
    nx = 96                        # optional, nodes along u (default 64)
    ny = 96                        # optional, nodes along v (default 64)
    levels = 8                     # optional: how many isolux lines (1 .. 1000), or a list of values

or, by default, the scene's floor: the top face of the box with the largest
horizontal footprint (else the bottom of the scene's bounding box).
Only the scene's area and polyhedron lights count, and the luminaires of a
``[study]`` table (as ``isocsg report`` reads them); its objects occlude.

With ``--room CX CY CZ SX SY SZ`` (or a scene table ``[interreflections]``
with ``room_center``, ``room_size``, ``floor``, ``walls``, ``ceiling``,
``reflectances``, ``patch_size``, ...; see docs/interreflections.md) the light
reflected by the room and the objects is added to the direct light;
``--direct-only`` ignores the table.
"""

from __future__ import annotations

import argparse
import math
import re
import sys
from pathlib import Path
from typing import Any

import numpy as np

from .._validation import MAX_RESOLUTION, integer, resolution, show
from ..errors import InvalidLightError, InvalidParameterError, SceneFileError
from ..lighting.area import AreaLight, PolyhedronLight
from ..scene.io import (
    decode_scene_text,
    read_scene_file,
    read_scene_stream,
    scene_from_dict,
)
from ..scene.model import Scene
from ..shadows.luxmap import LuxGrid, illuminance_map, save_luxmap_png
from ..shadows.luxstats import lux_statistics, save_luxmap_csv
from . import COMMANDS

__all__ = ["floor_grid", "load_scene_and_grid", "register", "run"]

DESCRIPTION = """\
Compute the illuminance E in lux on a grid over a plane (exact soft shadows
from the scene's area and polyhedron lights, radiance in cd/m^2, the objects
occluding; direct light only, black occluders) and write a PNG map with isolux
lines (or, for -o GRID.csv, the grid as CSV), and optionally the float64 array
E (ny, nx) as .npy, the grid as CSV and a report figure. Prints Emin, Eavg, Emax
and the uniformity U0 = Emin / Eavg over the grid (or --area), leaving out the
nodes inside occluders.
Default plane: the scene's [illuminance] table, else the top of its floor.
"""

_TABLE_FIELDS = {"origin", "u", "v", "nx", "ny", "levels"}

#: Largest number of isolux lines (a count, or the length of a list of levels).
MAX_LEVELS = 1000

#: Grid nodes along u and v when neither the command line nor the table says.
DEFAULT_NODES = 64


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add the ``illuminance`` sub-command."""
    p = subparsers.add_parser("illuminance", help=COMMANDS["illuminance"], description=DESCRIPTION)
    p.add_argument("scene", metavar="SCENE", help="scene file, .toml or .json, or - to read it from standard input")
    p.add_argument("-o", "--output", required=True, metavar="MAP.png",
                   help="PNG map to write, or GRID.csv for the grid as CSV")
    p.add_argument("--npy", metavar="E.npy", help="also write E (ny, nx) as .npy")
    p.add_argument("--csv", metavar="GRID.csv", help="also write the grid as CSV (i, j, x_m, y_m, z_m, E_lx, occluded)")
    p.add_argument(
        "--figure", metavar="FIG.png",
        help="also draw a report figure (.png, .pdf or .svg; colour bar in lux, labelled isolux lines; "
             "needs matplotlib)",
    )
    p.add_argument(
        "--area", nargs=4, type=float, metavar=("X0", "Y0", "X1", "Y1"),
        help="task area for the statistics: the rectangle [X0, X1] x [Y0, Y1] on a horizontal grid (default: the grid)",
    )
    p.add_argument("--grid", nargs=2, type=int, metavar=("NX", "NY"), help="grid nodes along u and v (default 64 64)")
    p.add_argument("--origin", nargs=3, type=float, metavar=("X", "Y", "Z"), help="corner of the grid")
    p.add_argument("--u", nargs=3, type=float, metavar=("UX", "UY", "UZ"), help="first edge vector of the grid")
    p.add_argument("--v", nargs=3, type=float, metavar=("VX", "VY", "VZ"), help="second edge vector of the grid")
    p.add_argument("--levels", type=int, metavar="N", help=f"number of isolux lines, 1 .. {MAX_LEVELS} (default 8)")
    p.add_argument(
        "--resolution", type=int, default=32, metavar="R",
        help=f"tessellation of curved occluders, 3 .. {MAX_RESOLUTION} (default 32)",
    )
    p.add_argument(
        "--room", nargs=6, type=float, metavar=("CX", "CY", "CZ", "SX", "SY", "SZ"),
        help="add interreflections in this box room (centre and size; see docs/interreflections.md)",
    )
    p.add_argument(
        "--reflectances", nargs=3, type=float, metavar=("FLOOR", "WALLS", "CEILING"),
        help="the room's reflectances with --room (default 0.2 0.5 0.7)",
    )
    p.add_argument("--object-reflectance", type=float, metavar="RHO",
                   help="reflectance of the scene's boxes and convex polyhedra with --room (default 0)")
    p.add_argument("--patch-size", type=float, metavar="M", help="radiosity patch size in metres (default 0.5)")
    p.add_argument("--direct-only", action="store_true", help="ignore the scene's [interreflections] table")
    p.add_argument("--no-progress", action="store_true", help="do not show the progress bar on stderr")
    p.set_defaults(func=run)
    return p


def floor_grid(scene: Scene, nx: int = 64, ny: int = 64) -> LuxGrid:
    """The default grid: the top face of the box with the largest horizontal footprint.

    Without boxes, the bottom face of the objects' bounding box.

    Examples
    --------
    >>> from isocsg import Box, Camera, Scene
    >>> s = Scene(Camera((0, -5, 2), (0, 0, 0)), [], [Box((0, 0, -0.05), (4, 2, 0.1)), Box((0, 0, 1), (1, 1, 1))])
    >>> g = floor_grid(s, 3, 3)
    >>> g.origin, g.u, g.v
    ((-2.0, -1.0, 0.0), (4.0, 0.0, 0.0), (0.0, 2.0, 0.0))
    """
    # boxes: the scene files' kind "box" (read by its registered name, whatever its class)
    boxes: list[Any] = [o.shape for o in scene.objects if getattr(o.shape, "kind", None) == "box"]
    if boxes:
        b = max(boxes, key=lambda x: x.size[0] * x.size[1])
        lo, hi = b.bounds
        return LuxGrid.from_bounds(lo[0], lo[1], hi[0], hi[1], hi[2], nx, ny)
    bs = np.array([o.shape.bounds for o in scene.objects])
    lo, hi = bs[:, 0].min(axis=0), bs[:, 1].max(axis=0)
    return LuxGrid.from_bounds(lo[0], lo[1], hi[0], hi[1], lo[2], nx, ny)


def _name(path: str | Path) -> str:
    """The file's name in messages; ``<stdin>`` for ``-``."""
    return "<stdin>" if str(path) == "-" else Path(path).name


def load_scene_and_grid(path: str | Path) -> tuple[Scene, dict[str, Any] | None]:
    """Read a scene file and its optional ``[illuminance]`` table (raw mapping).

    See :func:`load_scene_grid_and_interreflections`.
    """
    scene, table, *_ = load_scene_grid_and_interreflections(path)
    return scene, table


def load_scene_grid_and_interreflections(path: str | Path) -> tuple[Scene, dict[str, Any] | None, Any, list[Any]]:
    """Read a scene file, its optional ``[illuminance]`` table, ``[interreflections]`` table and luminaires.

    The third is an :class:`~isocsg.shadows.radiosity.Interreflections` or
    None, the last the lights of a ``[study]`` table's luminaires (read as
    ``isocsg report`` reads them: :func:`isocsg.interop.study.pop_lighting_tables`).

    The file is read as :func:`isocsg.scene.load_scene` reads it: ``.toml``
    or ``.json`` only, a regular UTF-8 file of at most 16 MiB; ``-`` reads
    standard input (:func:`isocsg.scene.io.read_scene_stream`). The table's
    ``nx``, ``ny`` and ``levels`` are checked here.

    Raises
    ------
    SceneFileError
        On unreadable files or a malformed ``[illuminance]`` table.
    """
    if str(path) == "-":  # standard input, read as a file is
        p: Any = "<stdin>"
        text, fmt = read_scene_stream(sys.stdin.buffer, source=p)
    else:
        p = Path(path)
        text, fmt = read_scene_file(p)
    doc = decode_scene_text(text, format=fmt, source=p)
    table = None
    if isinstance(doc, dict) and "illuminance" in doc:
        table = doc.pop("illuminance")
        if not isinstance(table, dict):
            raise SceneFileError(f"{p}: illuminance: must be a table, got {type(table).__name__}")
        unknown = sorted(set(table) - _TABLE_FIELDS)
        if unknown:
            raise SceneFileError(
                f"{p}: illuminance.{unknown[0]}: unknown field "
                f"(expected {', '.join(sorted(_TABLE_FIELDS))})"
            )
        missing = [k for k in ("origin", "u", "v") if k not in table]
        if missing:
            raise SceneFileError(f"{p}: illuminance.{missing[0]}: missing")
        try:
            for key in ("nx", "ny"):
                if key in table:
                    table[key] = integer(f"illuminance.{key}", table[key], low=2, high=4096,
                                         error=InvalidParameterError)
            if "levels" in table:
                table["levels"] = _levels("illuminance.levels", table["levels"])
        except InvalidParameterError as exc:
            field, _, rest = str(exc).partition(" ")
            raise SceneFileError(f"{p}: {field}: {rest}") from None
    from ..interop.study import pop_lighting_tables

    tables = pop_lighting_tables(doc, base=Path.cwd() if isinstance(p, str) else p.parent, source=_name(path))
    scene = scene_from_dict(doc, source=p if isinstance(p, str) else p.name)
    return scene, table, tables.interreflections, tables.luminaire_lights()


def _interreflections(args: argparse.Namespace, inter: Any) -> Any:
    """The scene's [interreflections] settings with the command line's overrides (None: direct only)."""
    from dataclasses import replace

    from ..shadows.patches import Room
    from ..shadows.radiosity import Interreflections

    if args.direct_only:
        return None
    if args.room is not None:
        rho = dict(zip(("floor", "walls", "ceiling"), args.reflectances or (0.2, 0.5, 0.7), strict=True))
        room = Room(args.room[:3], args.room[3:], **rho)
        inter = replace(inter, room=room) if inter is not None else Interreflections(room=room)
    elif args.reflectances is not None or args.object_reflectance is not None or args.patch_size is not None:
        if inter is None:
            raise InvalidParameterError("--reflectances, --object-reflectance and --patch-size need --room "
                                        "or an [interreflections] table")
    if inter is None:
        return None
    if args.reflectances is not None and args.room is None and inter.room is not None:
        inter = replace(inter, room=replace(inter.room, **dict(zip(("floor", "walls", "ceiling"), args.reflectances,
                                                                    strict=True))))
    if args.object_reflectance is not None:
        inter = replace(inter, reflectances=args.object_reflectance)
    if args.patch_size is not None:
        inter = replace(inter, patch_size=args.patch_size)
    return inter


def _levels(name: str, value: Any) -> int | list[float]:
    """A count of isolux lines (1 .. MAX_LEVELS) or a list of finite levels."""
    if isinstance(value, list):
        if not 1 <= len(value) <= MAX_LEVELS:
            raise InvalidParameterError(f"{name} must list 1 to {MAX_LEVELS} values, got {len(value)}")
        out = []
        for i, x in enumerate(value):
            if isinstance(x, bool) or not isinstance(x, (int, float)):
                raise InvalidParameterError(f"{name} must be a list of numbers, item {i} is {show(x)}")
            try:
                v = float(x)
            except OverflowError:
                v = math.inf
            if not math.isfinite(v):
                raise InvalidParameterError(f"{name} must be finite numbers, item {i} is {show(x)}")
            out.append(v)
        return out
    if isinstance(value, bool) or not isinstance(value, int):
        raise InvalidParameterError(
            f"{name} must be a number of isolux lines (1 .. {MAX_LEVELS}) or a list of values, got {show(value)}"
        )
    return integer(name, value, low=1, high=MAX_LEVELS, error=InvalidParameterError)


def _grid_from_table(path: str, table: dict[str, Any], nx: int | None, ny: int | None) -> LuxGrid:
    nx = table.get("nx", DEFAULT_NODES) if nx is None else nx
    ny = table.get("ny", DEFAULT_NODES) if ny is None else ny
    try:
        return LuxGrid(table["origin"], table["u"], table["v"], nx, ny)
    except InvalidParameterError as exc:
        text = str(exc)
        one_field = re.match(r"^grid\.(\w+) (must .*)$", text, flags=re.DOTALL)
        if one_field is not None:
            raise SceneFileError(f"{_name(path)}: illuminance.{one_field.group(1)}: {one_field.group(2)}") from None
        raise SceneFileError(f"{_name(path)}: illuminance: {text.replace('grid.', '')}") from None


def run(args: argparse.Namespace) -> int:
    """Load, compute, write; prints the files written and the range of E."""
    from ._common import check_outputs, compile_notice, progress_bar

    out = Path(args.output)
    as_csv = out.suffix.lower() == ".csv"
    if out.suffix.lower() not in (".png", ".csv"):
        raise InvalidParameterError(f"output file {str(args.output)!r} must end in .png or .csv")
    check_outputs(None if as_csv else args.output, args.npy)
    for flag, path, suffixes in (("--csv", args.csv, (".csv",)), ("--figure", args.figure, (".png", ".pdf", ".svg"))):
        if path is not None and Path(path).suffix.lower() not in suffixes:
            raise InvalidParameterError(f"{flag} {str(path)!r} must end in {' or '.join(suffixes)}")
    for path in (out, args.csv, args.figure):
        if path is not None and Path(path).is_dir():
            raise InvalidParameterError(f"output file {str(path)!r} is a directory")
    given = [args.origin is not None, args.u is not None, args.v is not None]
    if any(given) and not all(given):
        raise InvalidParameterError("--origin, --u and --v must be given together")
    # Every size is checked before the scene is read or anything is allocated.
    nx, ny = args.grid if args.grid is not None else (None, None)
    for name, n in (("grid.nx", nx), ("grid.ny", ny)):
        if n is not None:
            integer(name, n, low=2, high=4096, error=InvalidParameterError)
    if args.levels is not None:
        _levels("--levels", args.levels)
    res = resolution("--resolution", args.resolution)
    scene, table, inter, luminaires = load_scene_grid_and_interreflections(args.scene)
    inter = _interreflections(args, inter)
    lights = [li for li in scene.lights if isinstance(li, (AreaLight, PolyhedronLight))] + luminaires
    if not lights:
        raise InvalidLightError(f"{_name(args.scene)} has no area or polyhedron light nor a [study] luminaire")
    if all(given):
        nodes_x = DEFAULT_NODES if nx is None else nx
        nodes_y = DEFAULT_NODES if ny is None else ny
        grid = LuxGrid(args.origin, args.u, args.v, nodes_x, nodes_y)
    elif table is not None:
        grid = _grid_from_table(args.scene, table, nx, ny)
    else:
        grid = floor_grid(scene, DEFAULT_NODES if nx is None else nx, DEFAULT_NODES if ny is None else ny)
    levels: Any = args.levels if args.levels is not None else (table or {}).get("levels", 8)
    compile_notice("halftone")
    with progress_bar("illuminance", enabled=not args.no_progress) as progress:
        m = illuminance_map(grid, lights, [o.shape for o in scene.objects], resolution=res, progress=progress)
    if inter is not None:
        from dataclasses import replace

        from ..shadows.radiosity import solve_radiosity

        sol = solve_radiosity(lights, [o.shape for o in scene.objects], inter, resolution=res)
        pts = grid.points().reshape(-1, 3)
        indirect = sol.indirect_illuminance(pts, grid.normal).reshape(m.E.shape)
        m = replace(m, E=m.E + np.where(np.asarray(m.occluded, dtype=bool), 0.0, indirect))
        residual = sol.residuals[-1] if sol.shots else 0.0
        print(f"interreflections: {len(sol.patches)} patches, {sol.shots} shots, residual {residual:.2g}")
    area = None
    if args.area is not None:
        x0, y0, x1, y1 = args.area
        z = grid.origin[2]
        area = [(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)]
    stats = lux_statistics(m, area)  # checks the area before anything is written
    if args.figure is not None:
        from ..shadows.luxplot import save_luxmap_figure

        save_luxmap_figure(args.figure, m, levels=levels, area=area)  # matplotlib missing: fails before writing
    out.parent.mkdir(parents=True, exist_ok=True)
    if as_csv:
        save_luxmap_csv(out, m)
    else:
        save_luxmap_png(out, m, levels=levels)
    print(f"wrote {out}")
    if args.npy is not None:
        npy = Path(args.npy)
        npy.parent.mkdir(parents=True, exist_ok=True)
        np.save(npy, m.E, allow_pickle=False)
        print(f"wrote {npy}")
    if args.csv is not None:
        Path(args.csv).parent.mkdir(parents=True, exist_ok=True)
        print(f"wrote {save_luxmap_csv(args.csv, m)}")
    if args.figure is not None:
        print(f"wrote {args.figure}")
    print(stats.summary())
    return 0
