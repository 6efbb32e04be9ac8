"""Image writers: 8-bit conversion, PNG, NPY and SVG.

Float images follow the conventions: float32 intensity arrays of shape (H, W)
with NaN where no object is hit. 8-bit images map [0, 1] to [0, 255]
(clipped) and 0 for the background.
"""

from __future__ import annotations

import io
import os
import struct
import zlib
from collections.abc import Sequence
from typing import BinaryIO

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import InvalidParameterError

__all__ = ["to_uint8", "save_png", "png_bytes", "save_npy", "save_svg"]


def _image(name: str, image: ArrayLike, *, rgb: bool = False) -> NDArray[np.float32]:
    shapes = "(H, W) or (H, W, 3)" if rgb else "(H, W)"
    try:
        a = np.asarray(image, dtype=np.float32)
    except (TypeError, ValueError):
        raise InvalidParameterError(
            f"{name} must be a numeric array of shape "
            f"{shapes}, got {type(image).__name__}"
        ) from None
    colour = rgb and a.ndim == 3 and a.shape[2] == 3
    if (a.ndim != 2 and not colour) or a.shape[0] < 1 or a.shape[1] < 1:
        raise InvalidParameterError(f"{name} must have shape {shapes}, got {a.shape}")
    return a


def to_uint8(image: ArrayLike) -> NDArray[np.uint8]:
    """Map intensities [0, 1] to [0, 255] (clipped, rounded); NaN background to 0.

    Parameters
    ----------
    image : array_like, shape (H, W) or (H, W, 3)

    Returns
    -------
    ndarray, uint8, the shape of ``image``

    Raises
    ------
    InvalidParameterError
        If ``image`` is not a 2-D numeric array.

    Examples
    --------
    >>> to_uint8([[0.0, 0.5, 1.2], [np.nan, -1.0, 1.0]]).tolist()
    [[0, 128, 255], [0, 0, 255]]
    """
    a = _image("image", image, rgb=True)
    out = np.rint(np.clip(np.nan_to_num(a, nan=0.0), 0.0, 1.0) * 255.0)
    return out.astype(np.uint8)


def save_png(path: str | os.PathLike[str] | BinaryIO, image: ArrayLike) -> None:
    """Write an 8-bit grey (or RGB) PNG (see :func:`to_uint8`).

    Written with the standard library's ``zlib`` (no Pillow import: a command line's
    first image costs that much less).

    Parameters
    ----------
    path : str, path-like or binary file object
        A file name, or an object with a ``write(bytes)`` method (an open
        file, ``io.BytesIO``, ``sys.stdout.buffer``).
    image : array_like, shape (H, W), or (H, W, 3) for colour

    Raises
    ------
    InvalidParameterError
        If ``image`` is not a 2-D numeric array, or ``path`` is neither a path
        nor a binary file object.

    Examples
    --------
    >>> import io, os, tempfile
    >>> from PIL import Image
    >>> p = os.path.join(tempfile.mkdtemp(), "a.png")
    >>> save_png(p, [[0.0, 1.0]])
    >>> np.asarray(Image.open(p)).tolist()
    [[0, 255]]
    >>> buf = io.BytesIO()
    >>> save_png(buf, [[0.0, 1.0]])
    >>> buf.getvalue()[:8] == b"\\x89PNG\\r\\n\\x1a\\n"
    True
    """
    data = png_bytes(to_uint8(image))
    if hasattr(path, "write"):
        if isinstance(path, io.TextIOBase):
            raise InvalidParameterError(f"path must be a path or a binary file object, got the text stream {path!r}")
        path.write(data)
        return
    try:
        target = os.fspath(path)  # type: ignore[arg-type]
    except TypeError:
        raise InvalidParameterError(f"path must be a path or a binary file object, got {type(path).__name__}") from None
    with open(target, "wb") as f:
        f.write(data)


def png_bytes(eight: NDArray[np.uint8]) -> bytes:
    """The PNG file of an 8-bit image, shape (H, W) grey or (H, W, 3) RGB: each row with
    PNG's "up" filter (the previous row subtracted: flat shading compresses well), one zlib stream."""
    h, w = eight.shape[:2]
    colour = 2 if eight.ndim == 3 else 0
    rows = np.ascontiguousarray(eight).reshape(h, -1)
    up = rows.copy()
    up[1:] -= rows[:-1]  # uint8 arithmetic wraps modulo 256, as the filter asks
    raw = np.empty((h, up.shape[1] + 1), np.uint8)
    raw[:, 0] = 2
    raw[:, 1:] = up

    def chunk(kind: bytes, body: bytes) -> bytes:
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    header = struct.pack(">IIBBBBB", w, h, 8, colour, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw.tobytes(), 6))
            + chunk(b"IEND", b""))


def save_npy(path: str | os.PathLike[str], image: ArrayLike) -> None:
    """Write the float32 image (NaN background kept) as ``.npy``.

    Examples
    --------
    >>> import os, tempfile
    >>> p = os.path.join(tempfile.mkdtemp(), "a.npy")
    >>> save_npy(p, [[0.25, np.nan]])
    >>> np.load(p).dtype, np.load(p).tolist()
    (dtype('float32'), [[0.25, nan]])
    """
    np.save(os.fspath(path), _image("image", image), allow_pickle=False)


def save_svg(
    path: str | os.PathLike[str],
    polygons: Sequence[ArrayLike],
    values: ArrayLike,
    *,
    width: int,
    height: int,
    decimals: int = 2,
) -> None:
    """Write filled polygons, in the given (back-to-front) order, as SVG.

    Parameters
    ----------
    path : str or path-like
    polygons : sequence of array_like, each shape (k, 2), k >= 3
        Vertices in pixel coordinates ``(col, row)``; drawn first to last,
        so pass them back to front.
    values : array_like, shape (n,)
        Intensity of each polygon, shown as grey ``to_uint8(value)``.
    width, height : int
        Image size in pixels (the SVG view box).
    decimals : int, default 2
        Coordinates are written at this fixed precision so files are stable.

    Raises
    ------
    InvalidParameterError
        On a polygon with fewer than 3 vertices or not of shape (k, 2), or a
        ``values`` length that differs from the number of polygons.

    Examples
    --------
    >>> import os, tempfile
    >>> p = os.path.join(tempfile.mkdtemp(), "a.svg")
    >>> save_svg(p, [[(0, 0), (4, 0), (0, 3)]], [0.5], width=4, height=3)
    >>> print(open(p).read().splitlines()[1])
      <polygon points="0.00,0.00 4.00,0.00 0.00,3.00" fill="#808080" />
    """
    vals = np.asarray(values, dtype=np.float64).reshape(-1)
    if len(vals) != len(polygons):
        raise InvalidParameterError(f"values must have one entry per polygon ({len(polygons)}), got {len(vals)}")
    grey = to_uint8(vals.reshape(1, -1))[0] if len(vals) else np.zeros(0, np.uint8)
    import xml.etree.ElementTree as ET  # here: a PNG alone does not load it

    root = ET.Element(
        "svg",
        {
            "xmlns": "http://www.w3.org/2000/svg",
            "width": str(int(width)),
            "height": str(int(height)),
            "viewBox": f"0 0 {int(width)} {int(height)}",
            "shape-rendering": "crispEdges",
        },
    )
    fmt = f"{{:.{int(decimals)}f}}"
    for i, poly in enumerate(polygons):
        p = np.asarray(poly, dtype=np.float64)
        if p.ndim != 2 or p.shape[1] != 2 or len(p) < 3:
            raise InvalidParameterError(f"polygons[{i}] must have shape (k, 2) with k >= 3, got {p.shape}")
        pts = " ".join(f"{fmt.format(x)},{fmt.format(y)}" for x, y in p)
        g = int(grey[i])
        ET.SubElement(root, "polygon", {"points": pts, "fill": f"#{g:02x}{g:02x}{g:02x}"})
    ET.indent(root)
    ET.ElementTree(root).write(os.fspath(path), encoding="unicode")
