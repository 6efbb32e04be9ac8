"""OpenSCAD's ``rotate_extrude`` node, lowered through :func:`isocsg.shapes2d.revolve.rotate_extrude`.

The node's arguments as OpenSCAD reads them (2021.01's ``rotateextrude.cc`` and the newer
``RotateExtrudeNode.cc``): ``angle`` (alias ``a``) defaults to 360; a value that is not
finite, or outside ``(-360, 360]``, is 360; 0 makes nothing. ``start`` (exported by newer
versions only) defaults to 180 for a full turn and to 0 otherwise (2021.01 starts every
full turn on -x). An explicit ``$fn`` up to :data:`~isocsg.openscad.flat.FN_MAX` makes
OpenSCAD's faceted solid with ``floor(fn |angle| / 360)`` sections (2021.01; newer versions,
recognised by their ``start`` argument, round up), at least one; otherwise the solid is the
exact round one. A profile with area on both sides of the axis draws nothing, as in OpenSCAD
(which reports an error and goes on): it is left out with a :class:`ProfileAcrossAxisWarning`
and listed in ``LoweredModel.left_out``.
"""

from __future__ import annotations

import math
import warnings
from typing import Any

from ..errors import InvalidGeometryError
from .flat import import_drawing, polygonal_sides, shape_of
from .parser import CSGCall

__all__ = ["revolve", "ProfileAcrossAxisWarning"]


class ProfileAcrossAxisWarning(UserWarning):
    """A ``rotate_extrude`` profile with area on both sides of the axis: left out, as OpenSCAD leaves it out."""


def _angle(value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        return 360.0
    return 360.0 if value <= -360.0 or value > 360.0 else float(value)


def revolve(lw: Any, call: CSGCall) -> Any:
    """The solid of a ``rotate_extrude`` node (None: empty or skipped)."""
    from ..shapes2d import EMPTY
    from ..shapes2d.revolve import rotate_extrude

    raw = call.kwargs.get("angle", call.kwargs.get("a", call.args[0] if call.args else None))
    angle = 360.0 if raw is None else _angle(raw)
    if angle == 0.0:
        return None  # OpenSCAD makes nothing
    modern = "start" in call.kwargs
    start = lw.number(call, "start", call.kwargs["start"]) if modern else (180.0 if angle == 360.0 else 0.0)
    # The old form names its drawing itself: rotate_extrude(file = "x.dxf", layer = ...).
    shape = import_drawing(lw, call) if "file" in call.kwargs else shape_of(lw, call, polygonal=lw.faceted)
    if shape is None or shape is EMPTY:
        return None
    sides = polygonal_sides(call)
    if sides is None and lw.faceted:  # OpenSCAD's sections from the profile's reach (rotateextrude.cc)
        from ..shapes2d import bounds, fragments

        x0, _, x1, _ = bounds(shape)
        sides = fragments(max(abs(x0), abs(x1)), *(max(lw.number(call, k, call.kwargs.get(k, d)), low)
                                                    for k, d, low in (("$fn", 0.0, 0.0), ("$fs", 2.0, 0.01),
                                                                      ("$fa", 12.0, 0.01))))
    segments = None
    if sides is not None:
        turns = sides * abs(angle) / 360.0
        segments = max(math.ceil(turns) if modern else int(turns), 1)
    try:
        return rotate_extrude(shape, angle, start=start, segments=segments)
    except InvalidGeometryError as exc:
        if "meets the axis" in str(exc) or "ellipse" in str(exc):
            lw.unsupported(call, str(exc))
            return None
        if "must lie on one side" in str(exc):
            lw.note(call, f"{exc}; left out, as OpenSCAD draws nothing for it")
            warnings.warn(ProfileAcrossAxisWarning(
                f"{lw.where(call)}rotate_extrude(): {exc}; left out, as OpenSCAD draws nothing for it"), stacklevel=4)
            return None
        raise lw.fail(call, str(exc)) from None
