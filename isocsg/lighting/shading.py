"""The exact shading formula of the conventions, vectorised over points.

``I = ambient + sum_lights intensity * (kd cos_i + ks max(0, rf . v)^shininess [cos_i > 0])``
with ``cos_i = max(0, n . l)`` and ``rf = 2 (n . l) n - l``. No shadows, no
distance attenuation. This is the quantity that isoluminance laminae
approximate band by band.

The specular term jumps at the terminator (from 0 to ``ks max(0, -l . v)^s``),
so a cosine of incidence within rounding of 0 must not switch it on: a point
is lit where ``n . l > TERMINATOR_COSINE``. Otherwise a surface that lies on the
terminator (a cylinder's side under a light along its axis) shows the
highlight wherever rounding makes ``n . l`` positive.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import normalize_rows, points_array, vector3
from ..errors import InvalidParameterError
from .lights import Light, Material

__all__ = ["TERMINATOR_COSINE", "shade"]

#: Cosines of incidence at most this far above 0 are the terminator (rounding of unit vectors).
TERMINATOR_COSINE = 1e-9


def shade(
    points: ArrayLike,
    normals: ArrayLike,
    eye: ArrayLike,
    lights: Sequence[Light],
    material: Material | None = None,
) -> NDArray[np.float64]:
    """Exact intensity at surface points.

    Parameters
    ----------
    points, normals : array_like, shape (n, 3)
        Surface points and their outward normals (normalised here).
    eye : array_like, shape (3,)
        The viewpoint (for the specular term).
    lights : sequence of PointLight or DirectionalLight
    material : Material, optional
        Defaults to ``Material()``.

    Returns
    -------
    ndarray, shape (n,)

    Examples
    --------
    >>> from isocsg import PointLight
    >>> shade([[0, 0, 1]], [[0, 0, 1]], (0, 0, 5), [PointLight((0, 0, 10))]).round(3).tolist()
    [0.9]
    """
    p = points_array("points", points, error=InvalidParameterError)
    n = normalize_rows(points_array("normals", normals, error=InvalidParameterError))
    if n.shape != p.shape:
        raise InvalidParameterError(f"normals must have the shape of points {p.shape}, got {n.shape}")
    e = np.asarray(vector3("eye", eye, error=InvalidParameterError))
    m = material or Material()
    out = np.full(len(p), m.ambient)
    v = normalize_rows(e - p)
    for light in lights:
        ldir = light.directions_from(p)
        ndotl = np.einsum("ij,ij->i", n, ldir)
        cos_i = np.maximum(ndotl, 0.0)
        term = m.kd * cos_i
        if m.ks > 0:
            rf = 2 * ndotl[:, None] * n - ldir
            spec = np.maximum(np.einsum("ij,ij->i", rf, v), 0.0) ** m.shininess
            term = term + np.where(ndotl > TERMINATOR_COSINE, m.ks * spec, 0.0)
        out += light.intensity * term
    return out
