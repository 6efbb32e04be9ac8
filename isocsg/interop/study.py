"""A lighting study: a scene file's ``[study]`` table, its luminaires, and its computed figures.

The ``[study]`` table of a scene file (TOML shown; JSON has the same
structure) describes the room, the working plane, the task areas and the
luminaires; the scene's objects occlude and its area and polyhedron lights
shine too (its point and directional lights are rendering lights and are
ignored here)::

    [study]
    title = "Office 2.14"
    room = [0.0, 0.0, 6.0, 4.0]        # x0, y0, x1, y1 of the walls (m)
    height = 0.8                       # working plane (m)
    maintenance_factor = 0.8           # 0 < MF <= 1
    wall_band = 0.5                    # left out along the walls (m)
    cylindrical_height = 1.2           # optional: Ez over the room's grid at this height
    vertical = { height = 1.2, azimuths = [0, 90, 180, 270] }   # optional: Ev facing these azimuths
    map_spacing = 0.05                 # optional: node spacing of the plan-view map (m)

    [[study.tasks]]
    name = "desk 1"
    rect = [1.0, 1.0, 2.6, 1.8]
    requirement = "filing_copying"     # a row of isocsg.shadows.en12464.REQUIREMENTS,
    # or: em = 500, u0 = 0.6, source = "..."

    [[study.luminaires]]
    name = "D1"
    file = "downlight.ldt"             # .ies or .ldt, relative to the scene file;
    # or: intensity = 250.0            #   a plain isotropic point source of 250 cd
    position = [1.5, 1.0, 2.8]
    rotation = 0.0                     # optional; or aim = [x, y, z]
    tilt = 0.0
    multiplier = 1.0
    model = "point"                    # or "opening": the luminous opening as a Lambertian area source

An ``[interreflections]`` table (docs/interreflections.md) adds the light
reflected by the room and the objects to every figure and to the plan view;
both ``isocsg report`` and ``isocsg illuminance`` read it, and both light the
scene with the study's luminaires (:func:`pop_lighting_tables`).

Every error is a :class:`~isocsg.errors.SceneFileError` naming the file and the field
(``scene.toml: study.luminaires[0].file: ...``).
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidLightError, InvalidParameterError, SceneFileError
from ..kinds import DEFAULT_RESOLUTION
from ..lighting.area import AreaLight, PolyhedronLight
from ..lighting.luminaire import PhotometricLight
from ..lighting.photometry import Photometry, read_photometry
from ..scene.io import decode_scene_text, read_scene_file, scene_from_dict
from ..scene.model import Scene
from ..shadows.en12464 import (
    REQUIREMENTS,
    AreaFigures,
    Requirement,
    StudyArea,
    area_figures,
    cylindrical_illuminance,
    inside_occluders,
    room_area,
    task_areas,
    vertical_illuminance,
)
from ..shadows.luxmap import LuxGrid, LuxMap, illuminance_map
from ..shadows.radiosity import Interreflections, RadiositySolution, solve_radiosity

__all__ = ["Task", "Luminaire", "StudySpec", "StudyResult", "LightingTables", "load_study", "study_from_table",
           "pop_lighting_tables", "run_study"]

_STUDY_FIELDS = {"title", "room", "height", "maintenance_factor", "wall_band", "cylindrical_height", "map_spacing",
                 "tasks", "luminaires", "vertical"}
_TASK_FIELDS = {"name", "rect", "requirement", "em", "u0", "source"}
_LUM_FIELDS = {"name", "file", "intensity", "position", "rotation", "tilt", "aim", "multiplier", "model"}
#: Largest number of luminaires and task areas in a study.
MAX_LUMINAIRES = 1000
MAX_TASKS = 100


@dataclass(frozen=True, slots=True)
class Task:
    """A named task area ``rect = (x0, y0, x1, y1)`` with its required values (or none)."""

    name: str
    rect: tuple[float, float, float, float]
    required: Requirement | None = None


@dataclass(frozen=True, slots=True)
class Luminaire:
    """A scheduled luminaire: its name, light, and model (``"point"`` or ``"opening"``)."""

    name: str
    light: PhotometricLight
    model: str = "point"

    def source(self) -> PhotometricLight | AreaLight:
        """The light the computation uses: the point luminaire, or its Lambertian opening."""
        return self.light if self.model == "point" else self.light.opening_light()


@dataclass(frozen=True, slots=True)
class StudySpec:
    """What a study computes (see the module docstring for the fields)."""

    room: tuple[float, float, float, float]
    height: float = 0.8
    maintenance_factor: float = 0.8
    wall_band: float = 0.5
    tasks: tuple[Task, ...] = ()
    luminaires: tuple[Luminaire, ...] = ()
    cylindrical_height: float | None = None
    vertical_height: float | None = None
    vertical_azimuths: tuple[float, ...] = ()
    map_spacing: float | None = None
    title: str = "Lighting study"
    interreflections: Interreflections | None = None


@dataclass(frozen=True, slots=True, eq=False)
class StudyResult:
    """Figures of every area, the plan-view map (maintained lux), and what was computed."""

    spec: StudySpec
    areas: tuple[StudyArea, ...]
    figures: tuple[AreaFigures, ...]
    grids: tuple[NDArray[np.float64], ...] = field(repr=False)
    plan: LuxMap = field(repr=False)
    cylindrical: AreaFigures | None = None
    scene_lights: int = 0
    vertical: tuple[AreaFigures, ...] = ()
    radiosity: RadiositySolution | None = field(default=None, repr=False)


@dataclass(frozen=True, slots=True)
class LightingTables:
    """A scene file's ``[study]`` and ``[interreflections]`` tables, read (either may be absent)."""

    study: StudySpec | None = None
    interreflections: Interreflections | None = None

    def luminaire_lights(self) -> list[PhotometricLight | AreaLight]:
        """The study's luminaires as the computation uses them (points or openings)."""
        return [lu.source() for lu in self.study.luminaires] if self.study is not None else []


def _fail(source: str, path: str, message: str) -> SceneFileError:
    return SceneFileError(f"{source}: {path}: {message}")


def _number(source: str, path: str, value: Any, lo: float, hi: float, *, lo_incl: bool = False) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise _fail(source, path, f"must be a finite number, got {value!r}")
    v = float(value)
    if not ((v >= lo if lo_incl else v > lo) and v <= hi):
        raise _fail(source, path, f"must be in {'[' if lo_incl else '('}{lo:g}, {hi:g}], got {v:g}")
    return v


def _vec(source: str, path: str, value: Any, n: int) -> tuple[float, ...]:
    if not isinstance(value, list) or len(value) != n:
        raise _fail(source, path, f"must be an array of {n} numbers, got {value!r}")
    return tuple(_number(source, f"{path}[{k}]", v, -1e9, 1e9) for k, v in enumerate(value))


def _check_keys(source: str, path: str, table: Any, allowed: set[str], required: tuple[str, ...]) -> Mapping[str, Any]:
    if not isinstance(table, Mapping):
        raise _fail(source, path, f"must be a table, got {type(table).__name__}")
    unknown = sorted(set(table) - allowed)
    if unknown:
        raise _fail(source, f"{path}.{unknown[0]}", f"unknown field (expected {', '.join(sorted(allowed))})")
    for k in required:
        if k not in table:
            raise _fail(source, f"{path}.{k}", "missing required field")
    return table


def _task(source: str, path: str, t: Any) -> Task:
    t = _check_keys(source, path, t, _TASK_FIELDS, ("name", "rect"))
    rect = _vec(source, f"{path}.rect", t["rect"], 4)
    if not (rect[2] > rect[0] and rect[3] > rect[1]):
        raise _fail(source, f"{path}.rect", f"must have x1 > x0 and y1 > y0, got {list(rect)}")
    req = None
    if "requirement" in t:
        if "em" in t or "u0" in t:
            raise _fail(source, path, "give requirement or em and u0, not both")
        if t["requirement"] not in REQUIREMENTS:
            raise _fail(source, f"{path}.requirement",
                        f"unknown row {t['requirement']!r} (expected one of {', '.join(REQUIREMENTS)})")
        req = REQUIREMENTS[t["requirement"]]
    elif "em" in t or "u0" in t:
        if "em" not in t or "u0" not in t:
            raise _fail(source, path, "give both em and u0")
        req = Requirement(_number(source, f"{path}.em", t["em"], 0, 1e6),
                          _number(source, f"{path}.u0", t["u0"], 0, 1, lo_incl=True),
                          str(t.get("source", "given in the study")))
    return Task(str(t["name"]), rect, req)  # type: ignore[arg-type]


def _luminaire(source: str, path: str, t: Any, base: Path, cache: dict[Path, Any]) -> Luminaire:
    t = _check_keys(source, path, t, _LUM_FIELDS, ("position",))
    if ("file" in t) == ("intensity" in t):
        raise _fail(source, path, "give either file (a photometric file) or intensity (an isotropic point, cd)")
    if "intensity" in t:
        photometry = Photometry.isotropic(_number(source, f"{path}.intensity", t["intensity"], 0.0, 1e6,
                                                  lo_incl=True))
    else:
        if not isinstance(t["file"], str):
            raise _fail(source, f"{path}.file", f"must be a string, got {t['file']!r}")
        f = (base / t["file"]).resolve()
        if f not in cache:
            try:
                cache[f] = read_photometry(f)
            except InvalidLightError as exc:
                raise _fail(source, f"{path}.file", str(exc)) from None
        photometry = cache[f]
    model = t.get("model", "point")
    if model not in ("point", "opening"):
        raise _fail(source, f"{path}.model", f"must be 'point' or 'opening', got {model!r}")
    kw: dict[str, Any] = {"position": _vec(source, f"{path}.position", t["position"], 3)}
    for k in ("rotation", "tilt", "multiplier"):
        if k in t:
            kw[k] = _number(source, f"{path}.{k}", t[k], -1e6, 1e6)
    if "aim" in t:
        kw["aim"] = _vec(source, f"{path}.aim", t["aim"], 3)
    try:
        light = PhotometricLight(photometry=photometry, **kw)
        lum = Luminaire(str(t.get("name", f"L{path}")), light, model)
        if model == "opening":
            lum.source()  # the file must give a luminous opening
    except InvalidLightError as exc:
        msg = str(exc)
        field_name = msg.split(" ", 1)[0].removeprefix("PhotometricLight.")
        raise _fail(source, f"{path}.{field_name}" if field_name in _LUM_FIELDS else path, msg) from None
    return lum


def study_from_table(table: Any, *, base: str | os.PathLike[str] = ".", source: str = "<study>") -> StudySpec:
    """Read a ``[study]`` table (module docstring); photometric files relative to ``base``.

    Raises
    ------
    SceneFileError
        Naming ``source`` and the field.
    """
    t = _check_keys(source, "study", table, _STUDY_FIELDS, ("room",))
    room = _vec(source, "study.room", t["room"], 4)
    if not (room[2] > room[0] and room[3] > room[1]):
        raise _fail(source, "study.room", f"must have x1 > x0 and y1 > y0, got {list(room)}")
    kw: dict[str, Any] = {"room": room}
    limits = {"height": (-1e6, 1e6), "maintenance_factor": (0.0, 1.0), "wall_band": (0.0, 1e3),
              "cylindrical_height": (-1e6, 1e6), "map_spacing": (0.0, 1e3)}
    for k, (lo, hi) in limits.items():
        if k in t:
            kw[k] = _number(source, f"study.{k}", t[k], lo, hi, lo_incl=(k in ("height", "wall_band",
                                                                                  "cylindrical_height")))
    if "title" in t:
        kw["title"] = str(t["title"])
    if "vertical" in t:
        v = _check_keys(source, "study.vertical", t["vertical"], {"height", "azimuths"}, ("height", "azimuths"))
        kw["vertical_height"] = _number(source, "study.vertical.height", v["height"], -1e6, 1e6)
        az = v["azimuths"]
        if not isinstance(az, list) or not 1 <= len(az) <= 36:
            raise _fail(source, "study.vertical.azimuths", f"must be an array of 1 to 36 angles, got {az!r}")
        kw["vertical_azimuths"] = tuple(_number(source, f"study.vertical.azimuths[{k}]", a, -360, 360, lo_incl=True)
                                        for k, a in enumerate(az))
    tasks = t.get("tasks", [])
    lums = t.get("luminaires", [])
    for name, seq, most in (("tasks", tasks, MAX_TASKS), ("luminaires", lums, MAX_LUMINAIRES)):
        if not isinstance(seq, list):
            raise _fail(source, f"study.{name}", f"must be an array of tables, got {type(seq).__name__}")
        if len(seq) > most:
            raise _fail(source, f"study.{name}", f"at most {most}, got {len(seq)}")
    kw["tasks"] = tuple(_task(source, f"study.tasks[{i}]", x) for i, x in enumerate(tasks))
    cache: dict[Path, Any] = {}
    kw["luminaires"] = tuple(_luminaire(source, f"study.luminaires[{i}]", x, Path(base), cache)
                             for i, x in enumerate(lums))
    return StudySpec(**kw)


def pop_lighting_tables(doc: Any, *, base: str | os.PathLike[str] = ".", source: str = "<scene>") -> LightingTables:
    """Take the ``[study]`` and ``[interreflections]`` tables out of a decoded scene document and read them.

    What is left is the scene itself (for :func:`~isocsg.scene.io.scene_from_dict`).

    Raises
    ------
    SceneFileError
        On a malformed table, naming ``source`` and the field.
    """
    if not isinstance(doc, dict):
        return LightingTables()
    study = study_from_table(doc.pop("study"), base=base, source=source) if "study" in doc else None
    inter = None
    if "interreflections" in doc:
        try:
            inter = Interreflections.from_dict(doc.pop("interreflections"))
        except InvalidParameterError as exc:
            raise SceneFileError(f"{source}: {exc}") from None
    if study is not None and inter is not None:
        study = replace(study, interreflections=inter)
    return LightingTables(study, inter)


def load_study(path: str | os.PathLike[str]) -> tuple[Scene, StudySpec]:
    """Read a scene file with a ``[study]`` table (and an optional ``[interreflections]`` table).

    Raises
    ------
    SceneFileError
        On an unreadable scene file, a missing or malformed ``[study]`` or
        ``[interreflections]`` table.
    """
    p = Path(path)
    text, fmt = read_scene_file(p)
    doc = decode_scene_text(text, format=fmt, source=p)
    if not isinstance(doc, dict) or "study" not in doc:
        raise SceneFileError(f"{p.name}: study: missing (a lighting study needs a [study] table)")
    tables = pop_lighting_tables(doc, base=p.parent, source=p.name)
    doc.pop("illuminance", None)  # the illuminance command's table: not used here
    scene = scene_from_dict(doc, source=p.name)
    if tables.study is None:  # not reached: the table was there
        raise SceneFileError(f"{p.name}: study: missing")
    return scene, tables.study


def run_study(
    spec: StudySpec, scene: Scene | None = None, *, resolution: int = DEFAULT_RESOLUTION, map_nodes: int = 160,
) -> StudyResult:
    """Compute every area's figures, the cylindrical illuminance and the plan-view map.

    The lights are the study's luminaires and the scene's area and polyhedron
    lights; the scene's objects occlude. Maintained values: every
    illuminance times ``spec.maintenance_factor``. With
    ``spec.interreflections`` the radiosity is solved once and its indirect
    illuminance added everywhere (the indirect part of the cylindrical
    illuminance is the mean over :data:`INDIRECT_AZIMUTHS` azimuths).

    Raises
    ------
    InvalidParameterError
        If there is no light at all, or an area is malformed.
    """
    lights: list[Any] = [lu.source() for lu in spec.luminaires]
    scene_lights = [li for li in (scene.lights if scene else ()) if isinstance(li, (AreaLight, PolyhedronLight))]
    lights += scene_lights
    if not lights:
        raise InvalidParameterError("a study needs at least one luminaire or area light")
    occ = [o.shape for o in scene.objects] if scene else []
    mf = spec.maintenance_factor
    sol = None if spec.interreflections is None else solve_radiosity(lights, occ, spec.interreflections,
                                                                      resolution=resolution)
    areas: list[StudyArea] = [room_area(spec.room, spec.height, band=spec.wall_band,
                                        required=None if spec.tasks else REQUIREMENTS["unknown_task"])]
    for task in spec.tasks:
        areas += task_areas(task.name, task.rect, spec.room, spec.height, task.required)
    figs, grids = [], []
    for a in areas:
        f, E = area_figures(a, lights, occ, maintenance_factor=mf, resolution=resolution)
        if sol is not None:
            f, E = _add_indirect(a, f, E, sol, mf)
        figs.append(f)
        grids.append(E)
    cyl = None
    if spec.cylindrical_height is not None:
        ca = room_area(spec.room, spec.cylindrical_height, band=spec.wall_band)
        cyl = _point_figures(f"room, cylindrical Ez at {spec.cylindrical_height:g} m", "cylindrical", ca, occ, mf,
                             lambda q: cylindrical_illuminance(q, lights, occ, resolution=resolution)
                             + _indirect_cylindrical(sol, q))
    vert = []
    if spec.vertical_height is not None:
        va = room_area(spec.room, spec.vertical_height, band=spec.wall_band)
        for az in spec.vertical_azimuths:
            vert.append(_point_figures(f"room, vertical Ev {az:g} deg at {spec.vertical_height:g} m", "vertical", va,
                                       occ, mf,
                                       lambda q, a=az: vertical_illuminance(q, a, lights, occ, resolution=resolution)
                                       + _indirect_at(sol, q, _azimuth_normal(a))))
    x0, y0, x1, y1 = spec.room
    if spec.map_spacing is not None:
        nx = int(min(4096, max(2, round((x1 - x0) / spec.map_spacing) + 1)))
        ny = int(min(4096, max(2, round((y1 - y0) / spec.map_spacing) + 1)))
    else:
        k = map_nodes / max(x1 - x0, y1 - y0)
        nx, ny = max(2, round((x1 - x0) * k) + 1), max(2, round((y1 - y0) * k) + 1)
    grid = LuxGrid.from_bounds(x0, y0, x1, y1, spec.height, nx, ny)
    m0 = illuminance_map(grid, lights, occ, resolution=resolution)
    e_map = m0.E
    if sol is not None:
        ind = _indirect_at(sol, grid.points().reshape(-1, 3), grid.normal).reshape(e_map.shape)
        e_map = e_map + np.where(np.asarray(m0.occluded, dtype=bool), 0.0, ind)
    plan = LuxMap(grid, mf * e_map, m0.occluded)
    return StudyResult(spec, tuple(areas), tuple(figs), tuple(grids), plan, cyl, len(scene_lights), tuple(vert), sol)


#: Azimuths over which the indirect part of the cylindrical illuminance is averaged.
INDIRECT_AZIMUTHS = 16


def _azimuth_normal(azimuth: float) -> NDArray[np.float64]:
    a = math.radians(azimuth)
    return np.array([math.cos(a), math.sin(a), 0.0])


def _indirect_at(sol: RadiositySolution | None, pts: NDArray[np.float64], normal: Any) -> Any:
    """Indirect illuminance at points facing ``normal`` (0 without a radiosity solve)."""
    if sol is None or len(pts) == 0:
        return 0.0
    return sol.indirect_illuminance(pts, np.broadcast_to(np.asarray(normal, dtype=np.float64), pts.shape))


def _indirect_cylindrical(sol: RadiositySolution | None, pts: NDArray[np.float64]) -> Any:
    """Mean indirect vertical illuminance over :data:`INDIRECT_AZIMUTHS` azimuths (0 without a solve)."""
    if sol is None or len(pts) == 0:
        return 0.0
    az = [360.0 * (k + 0.5) / INDIRECT_AZIMUTHS for k in range(INDIRECT_AZIMUTHS)]
    nrm = np.repeat(np.stack([_azimuth_normal(a) for a in az]), len(pts), axis=0)
    e = sol.indirect_illuminance(np.tile(pts, (INDIRECT_AZIMUTHS, 1)), nrm)
    return e.reshape(INDIRECT_AZIMUTHS, len(pts)).mean(axis=0)


def _add_indirect(area: StudyArea, f: AreaFigures, E: NDArray[np.float64], sol: RadiositySolution,
                  mf: float) -> tuple[AreaFigures, NDArray[np.float64]]:
    """An area's figures and grid with the maintained indirect illuminance added (grid points facing up)."""
    g = area.grid
    e = E[g.keep]
    use = np.isfinite(e)
    e[use] += mf * _indirect_at(sol, g.kept_points()[use], (0.0, 0.0, 1.0))
    E = E.copy()
    E[g.keep] = e
    v = e[use]
    m, lo, hi = float(v.mean()), float(v.min()), float(v.max())
    return replace(f, e_mean=m, e_min=lo, e_max=hi, u0=lo / m if m > 0 else math.nan,
                   min_max=lo / hi if hi > 0 else math.nan), E


def _point_figures(name: str, kind: str, area: StudyArea, occ: list[Any], mf: float, fn: Any) -> AreaFigures:
    """Figures of ``fn`` (maintained by ``mf``) at an area's points outside the occluders."""
    pts = area.grid.kept_points()
    pts = pts[~inside_occluders(pts, occ)]
    if len(pts) == 0:
        raise InvalidParameterError(f"{name}: every grid point lies inside an occluder")
    e = mf * fn(pts)
    m, lo, hi = float(e.mean()), float(e.min()), float(e.max())
    return AreaFigures(name, kind, len(e), area.grid.spacing, m, lo, hi, lo / m if m > 0 else math.nan,
                       lo / hi if hi > 0 else math.nan)
