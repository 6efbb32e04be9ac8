"""2D drawings from files: OpenSCAD's ``import("drawing.dxf")``, read with ezdxf.

The file is read with `ezdxf <https://ezdxf.mozman.at>`_ (a maintained DXF library: every DXF
version, binary and ASCII, blocks), and turned into the region OpenSCAD 2021.01 makes of it
(``src/dxfdata.cc``), so that a model reads as OpenSCAD draws it:

- the entities read are ``LINE``, ``LWPOLYLINE`` (straight segments: bulges are ignored, as
  OpenSCAD ignores them), ``CIRCLE``, ``ARC``, ``ELLIPSE`` and ``INSERT`` of blocks made of
  those; other entities are counted in :attr:`Drawing.unsupported` (OpenSCAD warns of them);
- circles and arcs become OpenSCAD's polygons: ``n`` segments from ``$fn``, ``$fa`` and ``$fs``
  (:func:`fragments`), an arc ``ceil(n * angle / 360)`` of them;
- coordinates are ``(x - origin) * scale``; only the entities on ``layer`` are read when it is
  given;
- segments are joined at shared end points (within OpenSCAD's grid, :data:`GRID`) into paths; an
  open path is closed by its first point; the region is what the paths fill by the even-odd
  rule (OpenSCAD's Clipper union with the even-odd fill).

A drawing with no closed area raises :class:`~isocsg.errors.InvalidGeometryError` naming the
file and layer.
"""

from __future__ import annotations

import math
import os
from collections import Counter, defaultdict
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InvalidGeometryError, InvalidParameterError, MissingDependencyError
from .constructors import polygon
from .shape import Shape2D

__all__ = ["Drawing", "read_dxf", "import_dxf", "fragments", "GRID"]

#: OpenSCAD's coarse grid: end points closer than this are one point (``GRID_COARSE``).
GRID = 0.0009765625
#: OpenSCAD's smallest radius that gets more than 3 segments (``GRID_FINE``).
_GRID_FINE = 0.00000095367431640625


def fragments(r: float, fn: float = 0.0, fs: float = 2.0, fa: float = 12.0) -> int:
    """OpenSCAD 2021.01's segment count of a circle of radius ``r`` (``get_fragments_from_r``)."""
    if r < _GRID_FINE or not math.isfinite(fn):
        return 3
    if fn > 0.0:
        return int(fn if fn >= 3 else 3)
    return int(math.ceil(max(min(360.0 / fa, r * 2 * math.pi / fs), 5)))


@dataclass(frozen=True)
class Drawing:
    """A DXF drawing read as OpenSCAD reads it.

    Attributes
    ----------
    paths : tuple of ndarray, each shape (k, 2)
        The joined paths (open ones are closed by their first point when filled).
    unsupported : dict of str to int
        Entities that were not read, by type.
    """

    paths: tuple[np.ndarray, ...]
    unsupported: dict[str, int]

    def shape(self, where: str = "drawing") -> Shape2D:
        """The region the paths fill by the even-odd rule, as exact convex pieces."""
        rings = [p for p in self.paths if len(p) >= 3]
        if not rings:
            raise InvalidGeometryError(f"{where}: no closed area (no path of 3 or more points)")
        points = np.vstack(rings)
        starts = np.cumsum([0] + [len(r) for r in rings])
        paths = [list(range(int(a), int(b))) for a, b in zip(starts[:-1], starts[1:])]
        try:
            return polygon(points, paths)
        except InvalidGeometryError as exc:
            raise InvalidGeometryError(f"{where}: {exc}") from None


def _segments(entity: Any, fn: float, fs: float, fa: float) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """The straight segments OpenSCAD makes of one entity, in the entity's own coordinates."""
    kind = entity.dxftype()
    out: list[tuple[tuple[float, float], tuple[float, float]]] = []
    if kind == "LINE":
        s, e = entity.dxf.start, entity.dxf.end
        out.append(((s[0], s[1]), (e[0], e[1])))
    elif kind == "LWPOLYLINE":
        pts = [(p[0], p[1]) for p in entity.get_points("xy")]
        out.extend(zip(pts[:-1], pts[1:]))
        if entity.closed and len(pts) > 1:
            out.append((pts[-1], pts[0]))
    elif kind in ("CIRCLE", "ARC"):
        c, r = entity.dxf.center, float(entity.dxf.radius)
        n = fragments(r, fn, fs, fa)
        start, sweep = 0.0, 360.0
        if kind == "ARC":
            start, stop = float(entity.dxf.start_angle), float(entity.dxf.end_angle)
            while start > stop:
                stop += 360.0
            sweep = stop - start
            n = int(math.ceil(n * sweep / 360.0))
        a = np.radians(start + sweep * np.arange(n + 1) / max(n, 1))
        pts = list(zip(c[0] + r * np.cos(a), c[1] + r * np.sin(a)))
        out.extend(zip(pts[:-1], pts[1:]))
    elif kind == "ELLIPSE":
        c, major, ratio = entity.dxf.center, entity.dxf.major_axis, float(entity.dxf.ratio)
        start, stop = float(entity.dxf.start_param), float(entity.dxf.end_param)
        while start > stop:
            stop += 2 * math.pi
        r_major = math.hypot(major[0], major[1])
        rot = math.atan2(major[1], major[0])
        n = int(math.ceil(fragments(r_major, fn, fs, fa) * (stop - start) / (2 * math.pi)))
        t = start + (stop - start) * np.arange(n + 1) / max(n, 1)
        x, y = r_major * np.cos(t), r_major * ratio * np.sin(t)
        px = c[0] + math.cos(rot) * x - math.sin(rot) * y
        py = c[1] + math.sin(rot) * x + math.cos(rot) * y
        pts = list(zip(px, py))
        out.extend(zip(pts[:-1], pts[1:]))
    return out


def _aligned(segments: np.ndarray) -> np.ndarray:
    """End points as OpenSCAD's ``Grid2d::align`` places them, in the order it meets them: on the
    grid of :data:`GRID`, or on an earlier point in a neighbouring cell (the nearest by cell
    steps), so that end points a little apart become one point. Returns grid indices (n, 2, 2)."""
    cells: set[tuple[int, int]] = set()
    flat = np.rint(segments.reshape(-1, 2) / GRID).astype(np.int64)
    out = np.empty_like(flat)
    for k, (ix, iy) in enumerate(flat.tolist()):
        if (ix, iy) not in cells:
            best, dist = (ix, iy), 10
            for jx in (ix - 1, ix, ix + 1):
                for jy in (iy - 1, iy, iy + 1):
                    d = abs(ix - jx) + abs(iy - jy)
                    if (jx, jy) in cells and d < dist:
                        best, dist = (jx, jy), d
            ix, iy = best
        cells.add((ix, iy))
        out[k] = (ix, iy)
    return out.reshape(-1, 2, 2)


def _join(segments: np.ndarray) -> list[np.ndarray]:
    """Paths through segments that share end points (after :func:`_aligned`): open paths first,
    from their ends, then closed loops; iterative, each segment used once."""
    cells = _aligned(segments).reshape(-1, 2)
    _, ids = np.unique(cells, axis=0, return_inverse=True)
    ids = ids.reshape(-1, 2)
    at: dict[int, list[int]] = defaultdict(list)
    for k, (a, b) in enumerate(ids.tolist()):
        at[a].append(k)
        at[b].append(k)
    used = np.zeros(len(ids), dtype=bool)
    place = {int(i): cells[j] * GRID for j, i in enumerate(ids.ravel())}
    paths: list[np.ndarray] = []
    ends = [p for p, ks in at.items() if len(ks) == 1]
    for start in ends + [int(ids[k, 0]) for k in range(len(ids))]:
        free = [k for k in at[start] if not used[k]]
        if not free:
            continue
        path, here = [start], start
        while free:
            k = free[0]
            used[k] = True
            here = int(ids[k, 1] if ids[k, 0] == here else ids[k, 0])
            path.append(here)
            free = [j for j in at[here] if not used[j]]
        if len(path) > 1 and path[-1] == path[0]:
            path.pop()
        paths.append(np.array([place[i] for i in path]))
    return paths


def read_dxf(path: str | os.PathLike[str], *, layer: str | None = None, origin: tuple[float, float] = (0.0, 0.0),
             scale: float = 1.0, fn: float = 0.0, fs: float = 2.0, fa: float = 12.0) -> Drawing:
    """Read a DXF file's paths as OpenSCAD's ``import`` does (see the module's notes).

    Parameters
    ----------
    path : str or path-like
    layer : str, optional
        Read only this layer's entities (all layers by default).
    origin : (float, float), default (0, 0)
        Subtracted from every coordinate, before ``scale``.
    scale : float, default 1
    fn, fs, fa : float
        OpenSCAD's ``$fn``, ``$fs``, ``$fa`` for circles, arcs and ellipses.

    Raises
    ------
    InvalidParameterError
        If the file cannot be read or is not DXF (naming the file), or on a non-finite
        ``scale``/``origin``.
    MissingDependencyError
        If ezdxf is not installed.
    """
    try:
        import ezdxf
    except ImportError:  # pragma: no cover - a dependency of the package
        raise MissingDependencyError("reading DXF drawings needs ezdxf: pip install 'isocsg[drawings]'") from None
    p = Path(path)
    if not (math.isfinite(scale) and all(math.isfinite(float(v)) for v in origin)):
        raise InvalidParameterError(f"{p}: import's scale and origin must be finite, got {scale}, {origin}")
    try:
        doc = ezdxf.readfile(str(p))
    except (OSError, ezdxf.DXFError) as exc:
        raise InvalidParameterError(f"{p}: not a readable DXF file ({exc})") from None
    segments: list[tuple[tuple[float, float], tuple[float, float]]] = []
    unsupported: Counter[str] = Counter()
    # In file order (the order fixes where close end points meet); blocks inside blocks through an
    # explicit stack, children pushed in reverse so that they come out in order.
    todo = [(e, np.eye(3)) for e in doc.modelspace() if layer is None or e.dxf.get("layer") == layer][::-1]
    while todo:
        entity, m = todo.pop()
        kind = entity.dxftype()
        if kind == "INSERT":
            block = doc.blocks.get(entity.dxf.name)
            if block is None:
                unsupported["INSERT of a missing block"] += 1
                continue
            a = math.radians(float(entity.dxf.get("rotation", 0.0)))
            xs, ys = float(entity.dxf.get("xscale", 1.0)), float(entity.dxf.get("yscale", 1.0))
            ins = entity.dxf.insert
            local = np.array([[math.cos(a) * xs, -math.sin(a) * ys, ins[0]],
                              [math.sin(a) * xs, math.cos(a) * ys, ins[1]], [0.0, 0.0, 1.0]])
            todo.extend((child, m @ local) for child in list(block)[::-1])
            continue
        got = _segments(entity, fn, fs, fa)
        if not got and kind not in ("LINE", "LWPOLYLINE", "CIRCLE", "ARC", "ELLIPSE"):
            unsupported[kind] += 1
        for s, e in got:
            a2 = m @ np.array([s[0], s[1], 1.0])
            b2 = m @ np.array([e[0], e[1], 1.0])
            segments.append(((a2[0], a2[1]), (b2[0], b2[1])))
    if not segments:
        return Drawing((), dict(unsupported))
    seg = (np.array(segments, dtype=np.float64) - np.asarray(origin, dtype=np.float64)) * scale
    return Drawing(tuple(_join(seg)), dict(unsupported))


def import_dxf(path: str | os.PathLike[str], *, layer: str | None = None, origin: tuple[float, float] = (0.0, 0.0),
               scale: float = 1.0, fn: float = 0.0, fs: float = 2.0, fa: float = 12.0) -> Shape2D:
    """OpenSCAD's ``import("drawing.dxf", layer, origin, scale)``: the drawing's region.

    See :func:`read_dxf` for the parameters.

    Raises
    ------
    InvalidGeometryError
        If the drawing (or its layer) encloses no area, naming the file and layer.
    """
    where = f"{path}" + (f" (layer {layer!r})" if layer is not None else "")
    return read_dxf(path, layer=layer, origin=origin, scale=scale, fn=fn, fs=fs, fa=fa).shape(where)
