"""OpenSCAD's 2D ``minkowski``, exactly (:func:`isocsg.shapes2d.minkowski.minkowski2d`).

Each kept child's shape (``%``/``*`` children left out, 3D ones ignored as in any 2D
operation) is summed exactly: polygons with holes through their convex pieces, circles as
rounded offsets. A sum with no exact form (an ellipse, a curved difference plus a polygon) is
refused naming the node, or with ``polygonal=True`` becomes OpenSCAD's own polygonal sum
(:func:`isocsg.openscad.polygonal.polygonal_minkowski2d`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from ..errors import InvalidGeometryError, NotExactError, ResourceLimitError

if TYPE_CHECKING:
    from .parser import CSGCall

__all__ = ["minkowski_shape"]


def minkowski_shape(lw: Any, call: CSGCall, shape_of: Callable[..., Any], polygonal: bool = False) -> Any:
    """The 2D shape of a ``minkowski`` node (``EMPTY`` without children, None when skipped);
    ``shape_of`` is :func:`~isocsg.openscad.flat.shape_of`, passed in (this module sits beside it)."""
    from ..shapes2d import EMPTY
    from ..shapes2d.minkowski import minkowski2d
    from .parser import CSGCall

    shapes = []
    for child in call.children:
        if "%" in child.modifiers or "*" in child.modifiers:
            continue
        shape = shape_of(lw, CSGCall("union", children=[child], line=child.line), polygonal=polygonal)
        if shape is not None:
            shapes.append(shape)
    if not shapes:
        return EMPTY
    if len(shapes) == 1:
        return shapes[0]
    try:
        return minkowski2d(*shapes)
    except (NotExactError, ResourceLimitError) as exc:
        if lw.polygonal:
            from .polygonal import polygonal_minkowski2d

            return polygonal_minkowski2d(lw, call, shape_of)
        lw.unsupported(call, str(exc).removeprefix("minkowski2d: "))
        return None
    except InvalidGeometryError as exc:
        raise lw.fail(call, str(exc)) from None
