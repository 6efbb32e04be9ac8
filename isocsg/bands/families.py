"""Contour families: per-vertex shading fields, their levels and band values.

Each light contributes a *diffuse family* whose field is the signed cosine of
incidence ``n . l`` at every surface vertex (exact, including the direction
change of a near point light). With a specular material each light adds two
*specular families* (outer and reversed normal), whose field is the Phong
cosine ``rf . v`` where the surface is lit.

Levels are where the surface is cut. They are chosen per smooth part of the
surface (a sphere, a truncus's side or end, a polyhedron's face) from the
range the field takes there, so that ``N`` contours buy the same accuracy on
every kind of primitive: ``N`` equal steps over the lit part of the range
(and ``N`` over the part lit from inside, for the reversed normal), with the
terminator ``0`` always a level. On a sphere this is the seed's cosine
distribution ``k / N``. A band between two consecutive levels takes the
middle of the two values it lies between (the seed's linear interpolation
between contour intensities).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .lights import Light, MaterialLike, is_directional

__all__ = [
    "FieldFamily", "diffuse_levels", "specular_levels", "incidence", "diffuse_family", "specular_families",
    "light_direction_at", "band_tables", "GRAZING",
]

#: Incidence cosines within rounding of 0: a part of the surface whose cosine stays this close
#: to 0 (a face in a point light's plane) is grazed, not lit (no Phong term).
GRAZING = 1e-12


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
    exponent : float
        Exact contribution of a triangle whose field is constant ``c``:
        ``weight * max(0, c) ** exponent`` (outward) and, for the diffuse family,
        ``weight * max(0, -c)`` (reversed normal).
    weight_out, weight_in : float
    """

    light_index: int
    kind: str
    field: NDArray[np.float64]
    exponent: float
    weight_out: float
    weight_in: float

    def levels(self, values: NDArray[np.float64], contours: int) -> NDArray[np.float64]:
        """Cut levels for one part of the surface, whose vertices carry ``values`` of the field."""
        if self.kind == "diffuse":
            return diffuse_levels(values, contours)
        return specular_levels(values, self.exponent, contours)

    def tables(self, levels: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Contribution of each band of ``levels`` to the outward and the reversed-normal intensity."""
        return band_tables(self.kind, levels, self.exponent, self.weight_out, self.weight_in)


def light_direction_at(light: Light, points: NDArray[np.float64],
                       origin: NDArray[np.float64] | None = None) -> NDArray[np.float64]:
    """Unit directions from ``points`` (n, 3) towards ``light`` (a zero vector at the light itself).

    ``points`` are relative to ``origin`` (the world origin when None).
    """
    if is_directional(light):
        return np.broadcast_to(light.unit_direction, points.shape).copy()
    pos = np.asarray(light.position, dtype=np.float64)
    if origin is not None:
        pos = pos - origin
    d = pos - points
    n = np.linalg.norm(d, axis=1, keepdims=True)
    return np.divide(d, n, out=np.zeros_like(d), where=n > 0)


def incidence(
    light: Light, points: NDArray[np.float64], normals: NDArray[np.float64], origin: NDArray[np.float64] | None = None
) -> NDArray[np.float64]:
    """Signed cosine of incidence ``n . l`` at each point (``points`` relative to ``origin``)."""
    return np.einsum("ij,ij->i", normals, light_direction_at(light, points, origin))


def _dedupe(levels: NDArray[np.float64], tol: float = 1e-9) -> NDArray[np.float64]:
    lv = np.sort(levels)
    keep = np.concatenate([[True], np.diff(lv) > tol])
    return lv[keep]


def diffuse_levels(values: NDArray[np.float64], contours: int) -> NDArray[np.float64]:
    """Cut levels of a diffuse family on one part of the surface.

    Parameters
    ----------
    values : array_like
        The incidence cosines at the part's vertices (the cut, a linear
        interpolation between vertices, never leaves their range).
    contours : int
        N: the lit range ``[max(lo, 0), hi]`` is cut into N equal steps, and
        so is the range ``[lo, min(hi, 0)]`` lit for the reversed normal.

    Returns
    -------
    ndarray
        Sorted levels in [-1, 1], containing 0 (the terminator).

    Examples
    --------
    >>> diffuse_levels([-1.0, 1.0], 2).tolist()
    [-1.0, -0.5, 0.0, 0.5, 1.0]
    >>> diffuse_levels([0.4, 0.5], 2).tolist()
    [0.0, 0.4, 0.45, 0.5]
    """
    v = np.clip(np.asarray(values, dtype=np.float64), -1.0, 1.0)
    parts = [np.zeros(1)]
    if len(v):
        lo, hi = float(v.min()), float(v.max())
        if hi > 0:
            parts.append(np.linspace(max(lo, 0.0), hi, contours + 1))
        if lo < 0:
            parts.append(np.linspace(lo, min(hi, 0.0), contours + 1))
        # A range narrower than the merging tolerance must still be closed by levels at its ends
        # and at 0: an open outer band would take the middle of [hi, 1].
        return np.unique(np.concatenate([_dedupe(np.concatenate(parts)), [lo, hi, 0.0]]))
    return _dedupe(np.concatenate(parts))


def specular_levels(values: NDArray[np.float64], shininess: float, contours: int) -> NDArray[np.float64]:
    """Cut levels of a Phong family on one part: N equal steps of ``(rf . v) ** shininess``.

    ``values`` holds the field at the part's vertices (``rf . v`` where lit, -1
    elsewhere). The steps span the range of the specular term over the lit
    vertices; 0 (the edge of the highlight) is always a level.

    Examples
    --------
    >>> specular_levels([-1.0, 0.5, 1.0], 1.0, 2).tolist()
    [0.0, 0.5, 0.75, 1.0]
    """
    x = np.asarray(values, dtype=np.float64)
    s = np.maximum(x[x > 0], 0.0) ** shininess
    parts = [np.zeros(1)]
    if len(s):
        parts.append(np.linspace(float(s.min()), float(s.max()), contours + 1) ** (1.0 / shininess))
        ends = np.clip(np.array([x[x > 0].min(), x.max()]), 0.0, 1.0)  # closed however narrow
        return np.unique(np.concatenate([_dedupe(np.clip(np.concatenate(parts), 0.0, 1.0)), ends]))
    return _dedupe(np.clip(np.concatenate(parts), 0.0, 1.0))


def _band_mid(levels: NDArray[np.float64], lo: float, hi: float) -> NDArray[np.float64]:
    """Middle of each band of ``levels``, the outer bands closed at ``lo`` and ``hi``."""
    edges = np.concatenate([[min(lo, levels[0])], levels, [max(hi, levels[-1])]])
    return 0.5 * (edges[:-1] + edges[1:])


def band_tables(
    kind: str, levels: NDArray[np.float64], exponent: float, weight_out: float, weight_in: float
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Per band of ``levels`` (``len(levels) + 1`` bands), its outward and reversed-normal value.

    Diffuse: ``w * max(0, +-mid)``. Specular: the middle of the band's two
    values of ``(rf . v) ** exponent`` on the family's own side, 0 below the
    level 0 (no highlight).
    """
    if kind == "diffuse":
        mid = _band_mid(levels, -1.0, 1.0)
        return weight_out * np.maximum(mid, 0.0), weight_in * np.maximum(-mid, 0.0)
    s_mid = _band_mid(np.maximum(levels, 0.0) ** exponent, 0.0, 1.0)
    s_mid[0] = 0.0  # below rf . v = 0: no highlight
    table = weight_out * s_mid
    zero = np.zeros_like(table)
    return (table, zero) if kind == "specular_out" else (zero, table)


def diffuse_family(light_index: int, light: Light, material: MaterialLike, field: NDArray[np.float64]) -> FieldFamily:
    """The diffuse family of one light: value ``kd * intensity * max(0, +-mid)`` per band."""
    w = float(material.kd * light.intensity)
    return FieldFamily(light_index, "diffuse", field, 1.0, w, w)


def specular_families(
    light_index: int,
    light: Light,
    material: MaterialLike,
    points: NDArray[np.float64],
    normals: NDArray[np.float64],
    eye: NDArray[np.float64],
    origin: NDArray[np.float64] | None = None,
) -> list[FieldFamily]:
    """The two Phong families of one light (outward and reversed normal).

    The field is ``rf . v`` (``rf = 2 (n . l) n - l``, ``v`` towards the eye)
    at every vertex, lit or not: it is smooth across the terminator, so that a
    cut point on the terminator (a level of the diffuse family, between a lit
    and an unlit vertex) gets the lit side's limit by interpolation. Where the
    side is unlit the band builder gives no highlight and takes no levels from
    it (see ``builder``). ``points`` and ``eye`` are relative to ``origin``.
    """
    lvec = light_direction_at(light, points, origin)
    ndotl = np.einsum("ij,ij->i", normals, lvec)
    rf = 2.0 * ndotl[:, None] * normals - lvec
    v = eye[None, :] - points
    v /= np.maximum(np.linalg.norm(v, axis=1, keepdims=True), 1e-300)
    rv = np.einsum("ij,ij->i", rf, v)
    n = float(material.shininess)
    w = float(material.ks * light.intensity)
    # Smooth across the terminator: with -1 on the unlit side, a cut point on the terminator took
    # a value interpolated towards -1, and the highlight stopped up to a mesh cell short of it at
    # every N. The pieces beyond it take no highlight (the band builder checks the diffuse side).
    out = FieldFamily(light_index, "specular_out", rv.copy(), n, w, w)
    inn = FieldFamily(light_index, "specular_in", rv.copy(), n, w, w)
    return [out, inn]
