"""``import("drawing.svg")``: SVG drawings read as OpenSCAD 2021.01 reads them (its ``libsvg`` and
``import_svg.cc``), path data and transforms lexed by svgelements (``pip install 'isocsg[drawings]'``).

- Elements: ``path`` (every command; cubic and quadratic Béziers as 20 chords, uniform in the
  curve parameter; arcs as ``int(|sweep in degrees| / 18 + 4)`` chords, the W3C centre
  parametrisation), ``rect`` (rounded corners as arcs), ``circle`` and ``ellipse`` (40 points,
  the first at 9 degrees from +y towards +x), ``polygon``; ``transform`` of the element and of
  its groups. Each element's closed paths are filled by the even-odd rule and the elements are
  united (OpenSCAD: ``sanitize``, then a Clipper union).
- Open paths (ends more than 0.1 apart), ``line`` and ``polyline``: OpenSCAD draws their
  strokes (a Clipper offset of the stroke width); isocsg refuses them, naming the element.
- The page: ``width``/``height`` in ``mm``, ``cm``, ``in``, ``pt``, ``pc``, ``px`` (96 per inch)
  or unitless (``dpi`` per inch, 72 by default); with a ``viewBox`` the user units are scaled to
  the page (``preserveAspectRatio``: the smaller scale for ``meet``, the larger for ``slice``,
  aligned min, mid or max); without one, a user unit is a millimetre. The y axis is flipped
  (``y = height - y_svg``), or with ``center`` the drawing's box is centred on the origin.
"""

from __future__ import annotations

import math
import os
import re
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidGeometryError, MissingDependencyError
from .region import fill, shape_from_region
from .shape import EMPTY, Shape2D

__all__ = ["import_svg", "read_svg_paths"]

INCH_TO_MM = 25.4
#: Chords per Bézier curve and points per circle or ellipse, as OpenSCAD 2021.01's libsvg draws them.
CURVE_CHORDS = 20
ELLIPSE_POINTS = 40
#: A path whose ends are further apart than this is open: OpenSCAD draws its stroke.
OPEN_PATH = 0.1
MAX_BYTES = 64 * 1024 * 1024


def _svgelements() -> Any:
    try:
        import svgelements  # type: ignore[import-untyped]
    except ImportError as exc:  # pragma: no cover - the extra is installed in the tests
        raise MissingDependencyError("reading SVG drawings needs svgelements: pip install 'isocsg[drawings]'") from exc
    return svgelements


class _PathBuilder:
    """Receives svgelements' lexed path commands and draws them as OpenSCAD's ``path.cc`` does."""

    def __init__(self, where: str) -> None:
        self.where = where
        self.paths: list[list[tuple[float, float]]] = [[]]
        self.x = self.y = 0.0
        self.ctrl: tuple[float, float] | None = None  # the last cubic's second control point
        self.qctrl: tuple[float, float] | None = None  # the last quadratic's control point
        self.closed = False

    def _xy(self, coord: Any, relative: bool) -> tuple[float, float]:
        return float(coord[0]), float(coord[1])  # the lexer resolves relative points (current_point)

    @property
    def current_point(self) -> Any:
        from types import SimpleNamespace

        return SimpleNamespace(x=self.x, y=self.y)

    def _to(self, p: tuple[float, float]) -> None:
        self.paths[-1].append(p)
        self.x, self.y = p

    def start(self) -> None:
        pass

    def end(self) -> None:
        while len(self.paths) > 1 and not self.paths[-1]:
            self.paths.pop()
        if not self.closed and self.paths[-1] and _is_open(self.paths[-1]):
            raise InvalidGeometryError(f"{self.where}: an open path (drawn as a stroke by OpenSCAD) is not read")

    def move(self, coord: Any, relative: bool = False) -> None:
        p = self._xy(coord, relative)
        if self.paths[-1]:
            if _is_open(self.paths[-1]):
                raise InvalidGeometryError(f"{self.where}: an open path (drawn as a stroke by OpenSCAD) is not read")
            self.paths.append([])
        self._to(p)
        self.ctrl = self.qctrl = None

    def line(self, coord: Any, relative: bool = False) -> None:
        self._to(self._xy(coord, relative))
        self.ctrl = self.qctrl = None

    def horizontal(self, value: Any, relative: bool = False) -> None:
        self._to((self.x + float(value) if relative else float(value), self.y))
        self.ctrl = self.qctrl = None

    def vertical(self, value: Any, relative: bool = False) -> None:
        self._to((self.x, self.y + float(value) if relative else float(value)))
        self.ctrl = self.qctrl = None

    def closed_(self) -> None:
        if self.paths[-1]:
            self._to(self.paths[-1][0])
        self.paths.append([])
        self.closed = True
        self.ctrl = self.qctrl = None

    def cubic(self, c1: Any, c2: Any, end: Any, relative: bool = False) -> None:
        self._cubic(self._xy(c1, relative), self._xy(c2, relative), self._xy(end, relative))

    def smooth_cubic(self, c2: Any, end: Any, relative: bool = False) -> None:
        c1 = (2 * self.x - self.ctrl[0], 2 * self.y - self.ctrl[1]) if self.ctrl else (self.x, self.y)
        self._cubic(c1, self._xy(c2, relative), self._xy(end, relative))

    def _cubic(self, c1: tuple[float, float], c2: tuple[float, float], e: tuple[float, float]) -> None:
        x0, y0 = self.x, self.y
        for i in range(1, CURVE_CHORDS + 1):
            a = i * (1.0 / CURVE_CHORDS)
            t = 1 - a
            self.paths[-1].append((x0 * t**3 + c1[0] * 3 * t * t * a + c2[0] * 3 * t * a * a + e[0] * a**3,
                                   y0 * t**3 + c1[1] * 3 * t * t * a + c2[1] * 3 * t * a * a + e[1] * a**3))
        self.x, self.y = e
        self.ctrl, self.qctrl = c2, None

    def quad(self, c: Any, end: Any, relative: bool = False) -> None:
        self._quad(self._xy(c, relative), self._xy(end, relative))

    def smooth_quad(self, end: Any, relative: bool = False) -> None:
        c = (2 * self.x - self.qctrl[0], 2 * self.y - self.qctrl[1]) if self.qctrl else (self.x, self.y)
        self._quad(c, self._xy(end, relative))

    def _quad(self, c: tuple[float, float], e: tuple[float, float]) -> None:
        x0, y0 = self.x, self.y
        for i in range(1, CURVE_CHORDS + 1):
            a = i * (1.0 / CURVE_CHORDS)
            t = 1 - a
            self.paths[-1].append((x0 * t * t + c[0] * 2 * t * a + e[0] * a * a,
                                   y0 * t * t + c[1] * 2 * t * a + e[1] * a * a))
        self.x, self.y = e
        self.ctrl, self.qctrl = None, c

    def arc(self, rx: Any, ry: Any, rotation: Any, large: Any, sweep: Any, coord: Any, relative: bool = False) -> None:
        e = self._xy(coord, relative)
        self.paths[-1].extend(_arc_points(self.x, self.y, abs(float(rx)), abs(float(ry)), e[0], e[1], float(rotation),
                                          bool(int(large)), bool(int(sweep))))
        self.x, self.y = e
        self.ctrl = self.qctrl = None


def _is_open(path: list[tuple[float, float]]) -> bool:
    return math.hypot(path[0][0] - path[-1][0], path[0][1] - path[-1][1]) > OPEN_PATH


def _angle(ux: float, uy: float, vx: float, vy: float) -> float:
    """libsvg's ``vector_angle``: the angle from u to v in degrees, in [0, 360)."""
    angle = math.degrees(math.atan2(vy, vx)) - math.degrees(math.atan2(uy, ux))
    return angle + 360 if angle < 0 else angle


def _arc_points(x1: float, y1: float, rx: float, ry: float, x2: float, y2: float, angle: float, large: bool,
                sweep: bool) -> list[tuple[float, float]]:
    """OpenSCAD's ``path::arc_to`` (the SVG implementation notes, F.6.5), with its chord count."""
    if rx == 0 or ry == 0:
        return [(x2, y2)]
    cos_r, sin_r = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    dx, dy = (x1 - x2) / 2, (y1 - y2) / 2
    x1_, y1_ = cos_r * dx + sin_r * dy, -sin_r * dx + cos_r * dy
    d = x1_ * x1_ / (rx * rx) + y1_ * y1_ / (ry * ry)
    if d > 1:
        rx, ry = abs(math.sqrt(d) * rx), abs(math.sqrt(d) * ry)
    t1 = max(rx * rx * ry * ry - rx * rx * y1_ * y1_ - ry * ry * x1_ * x1_, 0.0)
    t2 = rx * rx * y1_ * y1_ + ry * ry * x1_ * x1_
    t3 = math.sqrt(t1 / t2) if t2 > 0 else 0.0
    if large == sweep:
        t3 = -t3
    cx_, cy_ = t3 * rx * y1_ / ry, t3 * -ry * x1_ / rx
    cx, cy = cos_r * cx_ - sin_r * cy_ + (x1 + x2) / 2, sin_r * cx_ + cos_r * cy_ + (y1 + y2) / 2
    ux, uy = (x1_ - cx_) / rx, (y1_ - cy_) / ry
    vx, vy = (-x1_ - cx_) / rx, (-y1_ - cy_) / ry
    theta, delta = _angle(1, 0, ux, uy), _angle(ux, uy, vx, vy)
    if not sweep:
        delta -= 360
    steps = int(abs(delta) * 10.0 / 180 + 4)
    out = []
    for a in range(steps + 1):
        phi = math.radians(theta + delta * a / steps)
        out.append((cos_r * math.cos(phi) * rx - sin_r * math.sin(phi) * ry + cx,
                    sin_r * math.cos(phi) * rx + cos_r * math.sin(phi) * ry + cy))
    return out


def _num(el: ET.Element, name: str) -> float:
    value = el.get(name)
    if value is None:
        return 0.0
    m = re.match(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)", value)
    return float(m.group(1)) if m else 0.0


def _ellipse(cx: float, cy: float, rx: float, ry: float) -> list[tuple[float, float]]:
    pts = []
    for i in range(1, ELLIPSE_POINTS + 1):
        a = math.radians(i * 360.0 / ELLIPSE_POINTS)
        pts.append((rx * math.sin(a) + cx, ry * math.cos(a) + cy))
    return pts


def _element_paths(el: ET.Element, tag: str, where: str) -> list[list[tuple[float, float]]]:
    """The closed paths of one element, in its own coordinates."""
    if tag == "path":
        b = _PathBuilder(where)
        b.closed = False
        parser = _svgelements().SVGLexicalParser()
        adapter = type("_Adapter", (), {})()
        for name in ("start", "end", "move", "line", "horizontal", "vertical", "cubic", "smooth_cubic", "quad",
                     "smooth_quad", "arc"):
            setattr(adapter, name, getattr(b, name))
        adapter.closed = lambda relative=False: b.closed_()  # type: ignore[attr-defined]
        type(adapter).current_point = property(lambda _: b.current_point)  # type: ignore[attr-defined]
        try:
            parser.parse(adapter, el.get("d", ""))
        except (ValueError, IndexError, TypeError) as exc:
            raise InvalidGeometryError(f"{where}: malformed path data ({exc or 'a number is missing'})") from None
        b.end()  # the last path: open ones are strokes
        return [p for p in b.paths if p]
    if tag == "rect":
        x, y, w, h = (_num(el, k) for k in ("x", "y", "width", "height"))
        rx, ry = _num(el, "rx"), _num(el, "ry")
        if abs(rx) >= 1e-8 or abs(ry) >= 1e-8:
            rx, ry = (rx or ry), (ry or rx)
            rx, ry = min(rx, w / 2), min(ry, h / 2)
            d = (f"M {x + rx},{y} H {x + w - rx} A {rx},{ry} 0 0,1 {x + w},{y + ry} V {y + h - ry} "
                 f"A {rx},{ry} 0 0,1 {x + w - rx},{y + h} H {x + rx} A {rx},{ry} 0 0,1 {x},{y + h - ry} "
                 f"V {y + ry} A {rx},{ry} 0 0,1 {x + rx},{y} z")
            return _element_paths(ET.Element("path", {"d": d}), "path", where)
        return [[(x, y), (x + w, y), (x + w, y + h), (x, y + h), (x, y)]]
    if tag == "circle":
        r = _num(el, "r")
        return [_ellipse(_num(el, "cx"), _num(el, "cy"), r, r)] if r > 0 else []
    if tag == "ellipse":
        rx, ry = _num(el, "rx"), _num(el, "ry")
        return [_ellipse(_num(el, "cx"), _num(el, "cy"), rx, ry)] if rx > 0 and ry > 0 else []
    if tag == "polygon":
        vals = [float(v) for v in re.findall(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?", el.get("points", ""))]
        pts = list(zip(vals[0::2], vals[1::2], strict=False))
        return [[*pts, pts[0]]] if len(pts) >= 3 else []
    raise InvalidGeometryError(f"{where}: <{tag}> is drawn by OpenSCAD as a stroke; strokes are not read")


_SHAPES = {"path", "rect", "circle", "ellipse", "polygon", "polyline", "line"}


def _matrix(el: ET.Element) -> NDArray[np.float64]:
    text = el.get("transform")
    m = np.eye(3)
    if text:
        t = _svgelements().Matrix(text)
        m[:2] = [[t.a, t.c, t.e], [t.b, t.d, t.f]]
    return m


def read_svg_paths(path: str | os.PathLike[str]) -> tuple[ET.Element, list[list[NDArray[np.float64]]]]:
    """The root element and, per drawn element, its closed paths in user units (transforms applied)."""
    p = Path(path)
    if not p.is_file():
        raise InvalidGeometryError(f"{p}: not a readable SVG file")
    if p.stat().st_size > MAX_BYTES:
        raise InvalidGeometryError(f"{p}: SVG files larger than {MAX_BYTES} bytes are not read")
    try:
        root = ET.parse(p).getroot()
    except ET.ParseError as exc:
        raise InvalidGeometryError(f"{p}: not a well-formed SVG file ({exc})") from None
    if _tag(root) != "svg":
        raise InvalidGeometryError(f"{p}: the root element is <{_tag(root)}>, not <svg>")
    shapes: list[list[NDArray[np.float64]]] = []
    stack: list[tuple[ET.Element, NDArray[np.float64]]] = [(c, np.eye(3)) for c in reversed(list(root))]
    while stack:
        el, parent = stack.pop()
        tag = _tag(el)
        m = parent @ _matrix(el)
        if tag == "g":
            stack.extend((c, m) for c in reversed(list(el)))
        elif tag in _SHAPES:
            where = f"{p.name}: <{tag}{' id=' + repr(el.get('id')) if el.get('id') else ''}>"
            rings = [np.asarray(r, dtype=np.float64) @ m[:2, :2].T + m[:2, 2] for r in _element_paths(el, tag, where)]
            if rings:
                shapes.append(rings)
    return root, shapes


def _tag(el: ET.Element) -> str:
    return el.tag.rsplit("}", 1)[-1]


def _length(value: str | None, viewbox: float | None, dpi: float) -> float:
    """OpenSCAD's ``to_mm`` of a page length."""
    if value is None or not value.strip():
        return viewbox * INCH_TO_MM / dpi if viewbox is not None else 0.0
    m = re.match(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([a-z%]*)", value)
    if not m:
        return viewbox if viewbox is not None else 0.0
    n, unit = float(m.group(1)), m.group(2)
    per_mm = {"": INCH_TO_MM / dpi, "px": INCH_TO_MM / 96.0, "pt": INCH_TO_MM / 72.0, "pc": INCH_TO_MM / 6.0,
              "in": INCH_TO_MM, "cm": 10.0, "mm": 1.0}
    if unit in per_mm:
        return n * per_mm[unit]
    return viewbox if viewbox is not None else 0.0


def import_svg(path: str | os.PathLike[str], *, dpi: float = 72.0, center: bool = False) -> Shape2D:
    """The region of an SVG drawing in millimetres, as OpenSCAD 2021.01's ``import`` reads it.

    Parameters
    ----------
    path : path-like
    dpi : float, default 72
        Dots per inch of unitless page sizes (OpenSCAD's ``dpi`` argument).
    center : bool, default False
        Centre the drawing's box on the origin (OpenSCAD's ``center``).

    Raises
    ------
    InvalidGeometryError
        On a missing or malformed file, or an element OpenSCAD draws as a stroke (open paths,
        lines, polylines), naming the element.
    MissingDependencyError
        Without svgelements.
    """
    if not (isinstance(dpi, (int, float)) and math.isfinite(dpi) and dpi >= 0.001):
        raise InvalidGeometryError(f"import.dpi must be a number >= 0.001, got {dpi!r}")
    root, shapes = read_svg_paths(path)
    vb = [float(v) for v in re.split(r"[\s,]+", (root.get("viewBox") or "").strip()) if v]
    valid = len(vb) == 4 and vb[2] > 0 and vb[3] > 0
    width = _length(root.get("width"), vb[2] if valid else None, dpi)
    height = _length(root.get("height"), vb[3] if valid else None, dpi)
    scale, align, origin = np.ones(2), np.zeros(2), np.zeros(2)
    if valid:
        origin = np.array(vb[:2])
        scale = np.array([width / vb[2], height / vb[3]])
        words = (root.get("preserveAspectRatio") or "xMidYMid meet").split()
        words = [w for w in words if w != "defer"]
        mode = words[0] if words else "xMidYMid"
        if mode != "none":
            s = min(scale) if (len(words) < 2 or words[1] != "slice") else max(scale)
            scale = np.array([s, s])
            for k, (page, box) in enumerate(((width, vb[2]), (height, vb[3]))):
                where = mode[1:4] if k == 0 else mode[5:8]
                align[k] = page / 2 - s * box / 2 if where == "Mid" else page - s * box if where == "Max" else 0.0
    if not shapes:
        return EMPTY
    every = np.vstack([r for rings in shapes for r in rings]) * scale
    if center:
        c = 0.5 * (every.min(axis=0) + every.max(axis=0))
        cx, cy = c[0], c[1]
    else:
        cx, cy = -align[0], height - align[1]
    import shapely

    regions = []
    for rings in shapes:
        mapped = [np.column_stack([scale[0] * (r[:, 0] - origin[0]) - cx, scale[1] * (-origin[1] - r[:, 1]) + cy])
                  for r in rings]
        regions.append(fill(mapped, "evenodd", name="import"))
    return shape_from_region(shapely.union_all(regions))
