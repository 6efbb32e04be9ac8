"""Contour families: per-vertex shading fields, their levels and band values.

Each light contributes a *diffuse family* whose field is the signed cosine of
incidence ``n . l`` at every surface vertex (exact, including the direction
change of a near point light). With a specular material each light adds two
*specular families* (outer and reversed normal), whose field is the Phong
cosine ``rf . v`` where the surface is lit.

Levels are where the surface is cut. The diffuse levels contain the
primitive's own contour positions (the seed's cosine distribution, see the
primitive modules) mirrored for the reversed normal, 0 (the terminator) and
a uniform ``k / N`` grid outside the primitive's range. A band between two
consecutive levels takes the middle of the two values it lies between (the
seed's linear interpolation between contour intensities).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..lighting.lights import DirectionalLight, PointLight
from ..lighting.shading import Material

__all__ = ["FieldFamily", "diffuse_levels", "incidence", "diffuse_family", "specular_families", "light_direction_at"]

Light = PointLight | DirectionalLight


@dataclass(frozen=True, slots=True, eq=False)
class FieldFamily:
    """One contour family as the band builder uses it.

    Attributes
    ----------
    light_index : int
    kind : str
        ``"diffuse"``, ``"specular_out"`` or ``"specular_in"``.
    field : ndarray, shape (V,)
        The per-vertex field that is cut.
    levels : ndarray, shape (L,)
        Increasing cut levels.
    table_out, table_in : ndarray, shape (L + 1,)
        Contribution of band ``b`` to the outward and the reversed-normal intensity.
    exponent : float
        Exact contribution of a triangle whose field is constant ``c``:
        ``weight * max(0, c) ** exponent`` (outward) and, for the diffuse family,
        ``weight * max(0, -c)`` (reversed normal).
    weight_out, weight_in : float
    """

    light_index: int
    kind: str
    field: NDArray[np.float64]
    levels: NDArray[np.float64]
    table_out: NDArray[np.float64]
    table_in: NDArray[np.float64]
    exponent: float
    weight_out: float
    weight_in: float


def light_direction_at(light: Light, points: NDArray[np.float64]) -> NDArray[np.float64]:
    """Unit directions from ``points`` (n, 3) towards ``light`` (a zero vector at the light itself)."""
    if isinstance(light, DirectionalLight):
        return np.broadcast_to(light.unit_direction, points.shape).copy()
    d = np.asarray(light.position, dtype=np.float64) - points
    n = np.linalg.norm(d, axis=1, keepdims=True)
    return np.divide(d, n, out=np.zeros_like(d), where=n > 0)


def incidence(light: Light, points: NDArray[np.float64], normals: NDArray[np.float64]) -> NDArray[np.float64]:
    """Signed cosine of incidence ``n . l`` at each point."""
    return np.einsum("ij,ij->i", normals, light_direction_at(light, points))


def _dedupe(levels: NDArray[np.float64], tol: float = 1e-9) -> NDArray[np.float64]:
    lv = np.sort(levels)
    keep = np.concatenate([[True], np.diff(lv) > tol])
    return lv[keep]


def diffuse_levels(core: Sequence[float] | NDArray[np.float64], contours: int) -> NDArray[np.float64]:
    """Cut levels of a diffuse family.

    Parameters
    ----------
    core : array_like
        The primitive's own contour cosines (any sign).
    contours : int
        N; outside the range of ``core`` the levels continue as ``k / N``.

    Returns
    -------
    ndarray
        Sorted levels in [-1, 1], symmetric about 0, containing 0 and +-1.

    Examples
    --------
    >>> diffuse_levels([0.5, 1.0], 2).tolist()
    [-1.0, -0.5, 0.0, 0.5, 1.0]
    """
    c = np.clip(np.asarray(core, dtype=np.float64), -1.0, 1.0)
    grid = np.arange(-contours, contours + 1) / contours
    if len(c):
        mirrored = np.concatenate([c, -c])
        outside = grid[(grid < mirrored.min()) | (grid > mirrored.max())]
    else:
        mirrored, outside = c, grid
    return np.clip(_dedupe(np.concatenate([mirrored, outside, [-1.0, 0.0, 1.0]])), -1.0, 1.0)


def _band_mid(levels: NDArray[np.float64], lo: float, hi: float) -> NDArray[np.float64]:
    """Middle of each band of ``levels``, the outer bands closed at ``lo`` and ``hi``."""
    edges = np.concatenate([[min(lo, levels[0])], levels, [max(hi, levels[-1])]])
    return 0.5 * (edges[:-1] + edges[1:])


def diffuse_family(
    light_index: int, light: Light, material: Material, field: NDArray[np.float64], levels: NDArray[np.float64]
) -> FieldFamily:
    """The diffuse family of one light: value ``kd * intensity * max(0, +-mid)`` per band."""
    w = float(material.kd * light.intensity)
    mid = _band_mid(levels, -1.0, 1.0)
    return FieldFamily(
        light_index, "diffuse", field, levels, w * np.maximum(mid, 0.0), w * np.maximum(-mid, 0.0), 1.0, w, w
    )


def specular_families(
    light_index: int,
    light: Light,
    material: Material,
    points: NDArray[np.float64],
    normals: NDArray[np.float64],
    eye: NDArray[np.float64],
    contours: int,
) -> list[FieldFamily]:
    """The two Phong families of one light (outward and reversed normal).

    The field is ``rf . v`` (``rf = 2 (n . l) n - l``, ``v`` towards the eye)
    where that side of the surface is lit, and -1 elsewhere; the levels are
    ``(k / N) ** (1 / shininess)`` so that each band spans ``1 / N`` of the
    specular term ``(rf . v) ** shininess``.
    """
    lvec = light_direction_at(light, points)
    ndotl = np.einsum("ij,ij->i", normals, lvec)
    rf = 2.0 * ndotl[:, None] * normals - lvec
    v = eye[None, :] - points
    v /= np.maximum(np.linalg.norm(v, axis=1, keepdims=True), 1e-300)
    rv = np.einsum("ij,ij->i", rf, v)
    n = float(material.shininess)
    s_levels = np.arange(contours) / contours  # 0, 1/N, ..., (N-1)/N
    levels = _dedupe(s_levels ** (1.0 / n))
    s_mid = _band_mid(levels ** n, 0.0, 1.0)
    s_mid[0] = 0.0  # below rf . v = 0: no highlight
    w = float(material.ks * light.intensity)
    table = w * s_mid
    zero = np.zeros_like(table)
    out = FieldFamily(light_index, "specular_out", np.where(ndotl > 0, rv, -1.0), levels, table, zero, n, w, w)
    inn = FieldFamily(light_index, "specular_in", np.where(ndotl < 0, rv, -1.0), levels, zero, table, n, w, w)
    return [out, inn]
