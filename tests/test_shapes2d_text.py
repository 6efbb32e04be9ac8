"""text: glyph outlines with OpenSCAD's size, alignment and spacing (DejaVu Sans)."""

from __future__ import annotations

import os
import re
import warnings

import pytest

from isocsg.errors import InvalidGeometryError
from isocsg.shapes2d import EMPTY, FontFallbackWarning, area, bounds, font_path, text

pytest.importorskip("fontTools")
if not os.path.isfile(font_path()):
    pytest.skip("the DejaVu fonts of matplotlib are not installed", allow_module_level=True)

EM = 10 * 100 / 72  # one em at size 10
CAP = 1493 / 2048  # DejaVu Sans cap height, em


def test_capital_i_is_a_rectangle_of_the_cap_height():
    i = text("I")
    x0, y0, x1, y1 = bounds(i)
    assert y0 == 0.0 and y1 == pytest.approx(CAP * EM, rel=1e-12)
    assert area(i) == pytest.approx((x1 - x0) * (y1 - y0), rel=1e-12)
    assert 1.3 < x1 - x0 < 1.45  # the stem of DejaVu Sans's I: 0.0986 em


def test_size_scales_linearly():
    a, b = text("e", size=10), text("e", size=25)
    assert area(b) == pytest.approx(area(a) * 6.25, rel=1e-4)
    assert bounds(b)[3] == pytest.approx(bounds(a)[3] * 2.5, rel=1e-9)


def test_halign_moves_by_the_advance():
    left, center, right = (bounds(text("Ag", halign=h)) for h in ("left", "center", "right"))
    shift = left[0] - right[0]
    assert shift > 0
    assert center[0] == pytest.approx(left[0] - shift / 2, abs=1e-9)
    assert right[2] == pytest.approx(left[2] - shift, abs=1e-9)


def test_valign_uses_the_inks_ascent_and_descent():
    base = bounds(text("Ag"))
    assert base[1] < 0 < base[3]
    assert bounds(text("Ag", valign="top"))[3] == pytest.approx(0.0, abs=1e-9)
    assert bounds(text("Ag", valign="bottom"))[1] == pytest.approx(0.0, abs=1e-9)
    c = bounds(text("Ag", valign="center"))
    assert c[1] == pytest.approx(-c[3], abs=1e-9)


def test_spacing_multiplies_the_advances():
    one = bounds(text("I"))
    two = bounds(text("II", spacing=2))
    single = bounds(text("II"))
    advance = single[2] - one[2]
    assert two[2] - one[2] == pytest.approx(2 * advance, rel=1e-12)


def test_holes_follow_the_fill_rule():
    o = text("O")
    x0, y0, x1, y1 = bounds(o)
    assert 0.2 * (x1 - x0) * (y1 - y0) < area(o) < 0.6 * (x1 - x0) * (y1 - y0)


def test_flattening_converges_and_openscad_segments():
    areas = [area(text("S", tolerance=t)) for t in (1e-1, 1e-2, 1e-3, 1e-4)]
    steps = [abs(a - b) for a, b in zip(areas, areas[1:])]
    assert steps[0] > steps[1] > steps[2] and steps[2] < 1e-3 * areas[-1]  # chord error x perimeter
    coarse = area(text("S", segments=4))
    assert coarse == pytest.approx(areas[-1], rel=2e-2)


def test_styles_and_fallbacks():
    assert bounds(text("I", font="DejaVu Sans:style=Bold"))[2] > bounds(text("I"))[2]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        text("I", font="Liberation Sans")  # OpenSCAD's default: DejaVu Sans, documented, no warning
    with pytest.warns(FontFallbackWarning, match="Comic Sans"):
        text("I", font="Comic Sans")
    assert text("I", font=font_path("DejaVu Serif")) != text("I")


def test_blank_text_is_empty():
    assert text("") == EMPTY and text("   ") == EMPTY


BAD = [
    (lambda: text(12), "text.string must be a string, got int"),
    (lambda: text("a", size=0), "text.size must be > 0, got 0"),
    (lambda: text("a", spacing=-1), "text.spacing must be > 0, got -1"),
    (lambda: text("a", halign="middle"), "text.halign must be one of ('left', 'center', 'right'), got 'middle'"),
    (lambda: text("a", valign="up"), "text.valign must be one of ('baseline', 'top', 'center', 'bottom'), got 'up'"),
    (lambda: text("a", segments=0), "text.segments must be >= 1, got 0"),
    (lambda: text("a", tolerance=float("nan")), "text.tolerance must be a finite number"),
    (lambda: text("a", font=3), "text.font must be a string, got int"),
    (lambda: text("a" * 10001), "text.string must have at most 10000 characters, got 10001"),
]


@pytest.mark.parametrize("make, message", BAD, ids=[m for _, m in BAD])
def test_text_errors_name_the_field(make, message):
    with pytest.raises(InvalidGeometryError, match=re.escape(message)):
        make()


def test_unreadable_font_file(tmp_path):
    bad = tmp_path / "broken.ttf"
    bad.write_bytes(b"not a font")
    with pytest.raises(InvalidGeometryError, match=re.escape(f"text.font: cannot read {str(bad)!r}")):
        text("a", font=str(bad))
