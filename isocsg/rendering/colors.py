"""Colours of objects and of the leaves of CSG trees: the grey isoluminance image, tinted.

An isoluminance image is one intensity per pixel. A coloured object (``SceneObject.color``, or one
colour per leaf of its tree, ``SceneObject.leaf_colors``, as OpenSCAD's ``color()`` gives them)
shows that intensity times its colour: each band keeps one flat colour, so the contours stay as
they are. A pixel of a leaf without a colour takes its object's colour, and a pixel of an object
without one stays grey. Colours are sRGB triples in [0, 1]; :func:`parse_color` reads OpenSCAD's
forms (a vector of 3 or 4 numbers, an SVG colour name, ``"#rrggbb"``).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._validation import RGB, parse_color
from ..errors import InvalidParameterError

__all__ = ["RGB", "parse_color", "tint", "colored_image", "leaf_color_table", "is_colored"]

def is_colored(objects: Sequence[Any]) -> bool:
    """True when some object, or some leaf of one, has a colour."""
    return any(getattr(o, "color", None) is not None or getattr(o, "leaf_colors", ()) for o in objects)


def leaf_color_table(objects: Sequence[Any]) -> tuple[NDArray[np.float32], NDArray[np.int64]] | None:
    """Every object's leaf colours in one table: ``(colors (K, 3), start (n_objects,))``, the colour
    of leaf ``j`` of object ``i`` at ``colors[start[i] + j]``; None when nothing is coloured."""
    if not is_colored(objects):
        return None
    from ..csg.tree import leaves

    rows: list[NDArray[np.float32]] = []
    start = np.zeros(len(objects), dtype=np.int64)
    count = 0
    for i, obj in enumerate(objects):
        n = len(leaves(obj.shape))
        own = np.array(obj.color if obj.color is not None else (1.0, 1.0, 1.0), dtype=np.float32)
        table = np.tile(own, (n, 1))
        if len(obj.leaf_colors) > n:
            raise InvalidParameterError(f"objects[{i}].leaf_colors has {len(obj.leaf_colors)} colours for {n} leaves")
        for j, c in enumerate(obj.leaf_colors):
            if c is not None:
                table[j] = c
        rows.append(table)
        start[i] = count
        count += n
    return np.vstack(rows), start


def tint(image: NDArray[np.floating], object_index: NDArray[np.int32], primitive_index: NDArray[np.int32],
         objects: Sequence[Any]) -> NDArray[np.float32]:
    """The image in colour, shape (H, W, 3): each pixel's intensity times its leaf's colour.

    Parameters
    ----------
    image : ndarray, shape (H, W)
        Intensities; NaN where nothing is (kept NaN in all three channels).
    object_index, primitive_index : ndarray of int, shape (H, W)
        What each pixel shows (:attr:`RenderResult.object_index`, :attr:`RenderResult.primitive_index`).
    objects : sequence of SceneObject
        The scene's objects, with their ``color`` and ``leaf_colors``.
    """
    grey = np.asarray(image, dtype=np.float32)
    out = np.repeat(grey[:, :, None], 3, axis=2)
    table = leaf_color_table(objects)
    if table is None:
        return out
    colors, start = table
    seen = (object_index >= 0) & (primitive_index >= 0)
    row = start[object_index[seen]] + primitive_index[seen]
    out[seen] = grey[seen][:, None] * colors[row]
    return out


def colored_image(result: Any, objects: Sequence[Any]) -> NDArray[np.float32]:
    """:func:`tint` of a :class:`~isocsg.RenderResult` with its scene's objects: (H, W, 3), NaN
    background; the grey image in three channels when no object is coloured."""
    return tint(result.image, result.object_index, result.primitive_index, objects)
