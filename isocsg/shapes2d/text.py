"""OpenSCAD's ``text``: glyph outlines as exact convex pieces of their flattened polygons.

Font. The default is DejaVu Sans, the open font that matplotlib ships (its
``mpl-data/fonts/ttf`` folder; Bitstream Vera licence), read with fontTools.
OpenSCAD's own default is Liberation Sans, which isocsg does not ship: the two
are both sans-serif fonts with a cap height of 0.729 em, but their glyphs and
advances differ (DejaVu Sans's lower-case advances are about 10 % wider). ``font`` takes
a path to a ``.ttf`` or ``.otf`` file, or a DejaVu family name with an OpenSCAD
style (``"DejaVu Sans:style=Bold"``, ``"DejaVu Serif"``, ``"DejaVu Sans Mono"``);
other names fall back to DejaVu Sans with a :class:`FontFallbackWarning`.

Size. OpenSCAD sets FreeType's character size to ``1e5`` 26.6 points at
100 dpi and divides the outlines by ``1e5`` (``FreetypeRenderer.cc``), so
one em is ``size * 100 / 72``: a capital letter of DejaVu Sans or Liberation
Sans is about ``1.01 * size`` tall ("the ascent is about size").

Layout. Glyphs follow one another by their advance widths times
``spacing`` (the font's ``hmtx``; OpenSCAD shapes with HarfBuzz, which also
applies the font's kerning: pairs such as "AV" sit a little closer there).
``halign`` moves the text by its total advance (``left`` 0, ``center`` half,
``right`` all); ``valign`` by the ink's ascent and descent (the highest top
and the lowest bottom of the glyphs' control boxes): ``top`` ``-ascent``,
``center`` ``-(ascent + descent) / 2``, ``bottom`` ``-descent``,
``baseline`` 0, as OpenSCAD's ``ShapeResults::calc_offsets_horiz``.

Curves. Glyph outlines are quadratic (TrueType) or cubic (CFF) Bezier curves;
each is flattened into chords (uniform in the curve parameter), by default
enough of them for a chord error at most ``tolerance`` (``size / 1000``),
or exactly ``segments`` chords per curve (OpenSCAD's own flattening uses
``max(fragments(size) / 8 + 1, 2)`` chords; 4 at size 10 with the default
``$fa`` and ``$fs``). Glyphs are polygons then, like OpenSCAD's. The outlines
are filled by the non-zero winding rule of both font formats.
"""

from __future__ import annotations

import functools
import importlib.util
import math
import os
import struct
import warnings
from typing import Any

import numpy as np

from ..errors import InvalidGeometryError, MissingDependencyError
from ._checks import flag, number
from .region import fill, shape_from_region
from .shape import EMPTY, Shape2D

__all__ = ["text", "font_path", "FontFallbackWarning", "EM_PER_SIZE", "DEFAULT_FONT"]

#: One em of the font, in units of ``size`` (OpenSCAD: 100 dpi / 72 points per inch).
EM_PER_SIZE = 100.0 / 72.0
#: The font used when none is given.
DEFAULT_FONT = "DejaVu Sans"
#: Most characters of one ``text``.
MAX_CHARS = 10000

_STYLES = {
    "": "", "regular": "", "book": "", "bold": "-Bold", "oblique": "-Oblique", "italic": "-Oblique",
    "bold oblique": "-BoldOblique", "bold italic": "-BoldOblique",
}
_FAMILIES = {"dejavu sans": "DejaVuSans", "dejavu sans mono": "DejaVuSansMono", "dejavu serif": "DejaVuSerif"}


class FontFallbackWarning(UserWarning):
    """A ``font`` that isocsg does not have: DejaVu Sans is used instead (OpenSCAD also falls back)."""


def _mpl_fonts() -> str:
    spec = importlib.util.find_spec("matplotlib")
    if spec is None or not spec.submodule_search_locations:
        raise MissingDependencyError(
            "text needs the DejaVu fonts that matplotlib ships: pip install 'isocsg[text]' "
            "(or pass font=<path to a .ttf>)"
        )
    return os.path.join(list(spec.submodule_search_locations)[0], "mpl-data", "fonts", "ttf")


def font_path(font: str | None = None) -> str:
    """The font file that ``text(..., font=font)`` reads.

    Examples
    --------
    >>> os.path.basename(font_path("DejaVu Sans:style=Bold"))
    'DejaVuSans-Bold.ttf'
    """
    if font is not None and not isinstance(font, str):
        raise InvalidGeometryError(f"text.font must be a string, got {type(font).__name__}")
    name = DEFAULT_FONT if not font else font
    if os.path.splitext(name)[1].lower() in (".ttf", ".otf") and os.path.isfile(name):
        return name
    family, _, style = name.partition(":")
    style = style.strip()
    if style.lower().startswith("style="):
        style = style[6:]
    stem, suffix = _FAMILIES.get(family.strip().lower()), _STYLES.get(style.strip().lower())
    if family.strip().lower() == "liberation sans" and suffix is not None:
        stem = "DejaVuSans"  # OpenSCAD's default font: documented substitute
    if stem is None or suffix is None:
        warnings.warn(f"text.font {font!r} is not available; using {DEFAULT_FONT}", FontFallbackWarning, stacklevel=3)
        stem, suffix = "DejaVuSans", ""
    if stem == "DejaVuSerif" and suffix.endswith("Oblique"):
        suffix = suffix.replace("Oblique", "Italic")
    return os.path.join(_mpl_fonts(), f"{stem}{suffix}.ttf")


class _Font:
    """A font file's outlines, advances and units per em (fontTools)."""

    def __init__(self, path: str) -> None:
        try:
            from fontTools.ttLib import TTFont, TTLibError  # type: ignore[import-untyped]
        except ImportError:  # pragma: no cover - fontTools comes with matplotlib
            raise MissingDependencyError("text needs fontTools: pip install 'isocsg[text]'") from None
        self.path = path
        try:
            self.tt = TTFont(path, lazy=True)
            self.glyphs = self.tt.getGlyphSet()
            self.cmap = self.tt.getBestCmap() or {}
            self.upem = float(self.tt["head"].unitsPerEm)
            self.hmtx = self.tt["hmtx"]
        except (TTLibError, OSError, ValueError, KeyError, AssertionError, struct.error) as exc:
            raise InvalidGeometryError(f"text.font: cannot read {path!r} ({type(exc).__name__}: {exc})") from None

    def glyph_name(self, ch: str) -> str:
        return self.cmap.get(ord(ch), ".notdef")

    def outline(self, name: str, tolerance: float, segments: int) -> _Outline:
        """(rings in font units, (yMin, yMax) of the control box or None without ink), cached."""
        return _outline(self.path, name, tolerance, segments)


_Outline = tuple[list[np.ndarray], tuple[float, float] | None]


@functools.lru_cache(maxsize=4096)
def _outline(path: str, name: str, tolerance: float, segments: int) -> _Outline:
    from fontTools.pens.boundsPen import ControlBoundsPen  # type: ignore[import-untyped]

    glyphs = _font(path).glyphs
    pen = _FlatPen(glyphs, tolerance, segments)
    glyphs[name].draw(pen)
    box = ControlBoundsPen(glyphs)
    glyphs[name].draw(box)
    ink = None if box.bounds is None or box.bounds[3] <= box.bounds[1] else (box.bounds[1], box.bounds[3])
    return pen.rings, ink


@functools.lru_cache(maxsize=16)
def _font(path: str) -> _Font:
    return _Font(path)


def _pen_base() -> type:
    from fontTools.pens.basePen import BasePen  # type: ignore[import-untyped]

    return BasePen


class _FlatPen(_pen_base()):  # type: ignore[misc]
    """A fontTools pen that flattens curves into closed rings."""

    def __init__(self, glyphs: Any, tolerance: float, segments: int) -> None:
        super().__init__(glyphs)
        self.tol, self.segments = tolerance, segments
        self.rings: list[np.ndarray] = []
        self.cur: list[tuple[float, float]] = []

    def _count(self, second: float, scale: float) -> int:
        if self.segments:
            return self.segments
        return max(1, min(1024, math.ceil(math.sqrt(scale * second / (8.0 * self.tol)))))

    def _moveTo(self, p: Any) -> None:
        self._flush()
        self.cur = [tuple(p)]

    def _lineTo(self, p: Any) -> None:
        self.cur.append(tuple(p))

    def _qCurveToOne(self, p1: Any, p2: Any) -> None:
        p0 = np.array(self.cur[-1])
        a, b = np.array(p1, float), np.array(p2, float)
        n = self._count(float(np.hypot(*(p0 - 2 * a + b))), 2.0)
        t = np.arange(1, n + 1)[:, None] / n
        pts = (1 - t) ** 2 * p0 + 2 * (1 - t) * t * a + t**2 * b
        self.cur.extend(map(tuple, pts))

    def _curveToOne(self, p1: Any, p2: Any, p3: Any) -> None:
        p0 = np.array(self.cur[-1])
        a, b, c = np.array(p1, float), np.array(p2, float), np.array(p3, float)
        second = max(float(np.hypot(*(p0 - 2 * a + b))), float(np.hypot(*(a - 2 * b + c))))
        n = self._count(second, 6.0)
        t = np.arange(1, n + 1)[:, None] / n
        pts = (1 - t) ** 3 * p0 + 3 * (1 - t) ** 2 * t * a + 3 * (1 - t) * t**2 * b + t**3 * c
        self.cur.extend(map(tuple, pts))

    def _closePath(self) -> None:
        self._flush()

    def _endPath(self) -> None:
        self._flush()

    def _flush(self) -> None:
        if len(self.cur) >= 3:
            self.rings.append(np.array(self.cur, dtype=np.float64))
        self.cur = []


_HALIGN = ("left", "center", "right")
_VALIGN = ("baseline", "top", "center", "bottom")


def text(
    string: str,
    size: Any = 10.0,
    font: str | None = None,
    halign: str = "left",
    valign: str = "baseline",
    spacing: Any = 1.0,
    *,
    tolerance: Any = None,
    segments: Any = None,
    legacy_metrics: bool = False,
) -> Shape2D:
    """OpenSCAD's ``text(t, size, font, halign, valign, spacing)`` as a 2D shape (see the module notes).

    Parameters
    ----------
    string : str
        The text (at most 10000 characters); an empty or blank string gives :data:`EMPTY`.
    size : float, default 10
        OpenSCAD's size: one em is ``size * 100 / 72``.
    font : str, optional
        A path to a font file, or a DejaVu family and style; default DejaVu Sans.
    halign : {"left", "center", "right"}
    valign : {"baseline", "top", "center", "bottom"}
    spacing : float, default 1
        Factor on the advances (> 0).
    tolerance : float, optional
        Largest chord error of the flattened curves (default ``size / 1000``).
    segments : int, optional
        Chords per curve instead (OpenSCAD's fixed count).
    legacy_metrics : bool, default False
        OpenSCAD 2021.01's layout: it divided advances and the ascent and
        descent of ``valign`` by 1024 where it divided outlines by 1000, so its
        glyphs sit 2.3 % closer and its alignments shift 2.3 % less (the glyphs
        themselves, and so areas and volumes, are the same).

    Returns
    -------
    Shape2D
        The union of the exact convex pieces of the glyphs' polygons.

    Raises
    ------
    InvalidGeometryError
        On a non-string text, a size or spacing that is not > 0, an unknown
        alignment (naming the field), or an unreadable font file.
    MissingDependencyError
        When the default fonts (matplotlib's) are not installed.

    Examples
    --------
    >>> i = text("I", size=10)
    >>> x0, y0, x1, y1 = i.bounds
    >>> round(y0, 6), round(y1, 3)
    (0.0, 10.125)
    >>> round(text("I", size=10, valign="top").bounds[3], 9)
    0.0
    """
    if not isinstance(string, str):
        raise InvalidGeometryError(f"text.string must be a string, got {type(string).__name__}")
    if len(string) > MAX_CHARS:
        raise InvalidGeometryError(f"text.string must have at most {MAX_CHARS} characters, got {len(string)}")
    s = number("text.size", size, low=0.0)
    sp = number("text.spacing", spacing, low=0.0)
    if halign not in _HALIGN:
        raise InvalidGeometryError(f"text.halign must be one of {_HALIGN}, got {halign!r}")
    if valign not in _VALIGN:
        raise InvalidGeometryError(f"text.valign must be one of {_VALIGN}, got {valign!r}")
    nseg = 0
    if segments is not None:
        nseg = int(number("text.segments", segments, low=1.0, high=1024.0, strict=False))
    legacy = flag("text.legacy_metrics", legacy_metrics)
    f = _font(font_path(font))
    k = s * EM_PER_SIZE / f.upem  # font units -> model units
    m = 1000.0 / 1024.0 if legacy else 1.0  # OpenSCAD 2021.01's advance and metrics divisor
    tol = (s / 1000.0 if tolerance is None else number("text.tolerance", tolerance, low=0.0)) / k
    rings: list[np.ndarray] = []
    pen_x, top, bottom = 0.0, -math.inf, math.inf
    for ch in string:
        name = f.glyph_name(ch)
        outline, ink = f.outline(name, tol, nseg)
        rings.extend(r + (pen_x, 0.0) for r in outline)
        if ink is not None:
            bottom, top = min(bottom, ink[0]), max(top, ink[1])
        pen_x += f.hmtx[name][0] * m * sp
    if not rings or top == -math.inf:
        return EMPTY
    dx = {"left": 0.0, "center": -pen_x / 2.0, "right": -pen_x}[halign]
    if legacy:  # 2021.01 clamps the ascent and descent at the baseline
        top, bottom = max(top, 0.0) * m, min(bottom, 0.0) * m
    dy = {"baseline": 0.0, "top": -top, "center": -(top + bottom) / 2.0, "bottom": -bottom}[valign]
    region = fill([(r + (dx, dy)) * k for r in rings], "nonzero", name="text")
    return shape_from_region(region)
