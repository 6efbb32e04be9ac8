"""The band surface of a torus: a periodic (u, v) grid fine enough for every field.

``u`` turns about the axis, ``v`` about the tube. Vertices lie exactly on the surface,
``center + (R + r cos v) e(u) + r sin v w``, with the exact normals
``cos v e(u) + sin v w``. As for the ellipsoid (:mod:`isocsg.kinds.ellipsoid_bands`), the
isoluminance curves of a torus are not planar, so the bands come from the general
machinery: the grid is refined until every field (diffuse ``n . l`` per light, Phong terms)
is followed within a quarter of a band step along the rings, along the tube circles and
across the cells (:func:`~isocsg.bands.surface.curvature_spacing`,
:func:`~isocsg.bands.surface.mixed_spacing`); the families then cut it along their level
lines. The grid is never coarser than a chord sag of about 3e-4 of the tube's radius
(``MIN_TUBE`` vertices around the tube, as many around the axis as keep the outer rings'
sag as small) and never finer than ``MAX_RING`` x ``MAX_TUBE``.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Protocol

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:  # pragma: no cover
    from ..bands.surface import Surface

__all__ = ["Ring", "torus_surface", "MIN_TUBE", "MAX_TUBE", "MAX_RING"]

#: Vertices around the tube at least and at most; around the axis at most.
MIN_TUBE = 128
MAX_TUBE = 384
MAX_RING = 1024
_SAMPLES = 181


class Ring(Protocol):
    """What the torus's bands read of it (:class:`~isocsg.kinds.Torus`)."""

    @property
    def center_array(self) -> NDArray[np.float64]: ...

    @property
    def rotation(self) -> NDArray[np.float64]: ...

    @property
    def major(self) -> float: ...

    @property
    def minor(self) -> float: ...

    def _grid_triangles(self, n_u: int, n_v: int) -> NDArray[np.int64]: ...


def _points(
    t: Ring, uu: NDArray[np.float64], vv: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Points relative to the centre and normals on the grid ``uu x vv`` (shape (len(uu), len(vv), 3))."""
    Q = t.rotation
    ring = np.cos(uu)[:, None] * Q[:, 0] + np.sin(uu)[:, None] * Q[:, 1]
    nrm = np.cos(vv)[None, :, None] * ring[:, None, :] + np.sin(vv)[None, :, None] * Q[:, 2]
    return t.major * ring[:, None, :] + t.minor * nrm, nrm


def _spacings(t: Ring, lights: list[Any], contours: int, eye: NDArray[np.float64] | None, shininess: float,
              weights: tuple[float, float]) -> tuple[float, float]:
    """The largest angular steps in u and v that follow every field (inf where nothing bends)."""
    from ..bands.surface import curvature_spacing

    origin = t.center_array
    R, r = t.major, t.minor
    su = np.linspace(0.0, 2.0 * np.pi, 2 * _SAMPLES)
    sv = np.linspace(0.0, 2.0 * np.pi, _SAMPLES)
    h_u = h_v = np.inf
    # rings at a few tube angles (each with its own radius), tube circles at a few azimuths
    for v0 in 2.0 * np.pi * np.arange(12) / 12:
        p, n = _points(t, su, np.array([v0]))
        radius = R + r * math.cos(v0)
        h = curvature_spacing(p.transpose(1, 0, 2), n.transpose(1, 0, 2), lights, origin, contours,
                              eye=eye, shininess=shininess, step=radius * su[1], weights=weights)
        h_u = min(h_u, h / radius)
    p, n = _points(t, 2.0 * np.pi * np.arange(24) / 24, sv)
    h = curvature_spacing(p, n, lights, origin, contours, eye=eye, shininess=shininess, step=r * sv[1], weights=weights)
    h_v = min(h_v, h / r)
    return h_u, h_v


def torus_surface(
    t: Ring, lights: list[Any], contours: int, eye: NDArray[np.float64] | None, shininess: float,
    weights: tuple[float, float] = (1.0, 1.0),
) -> Surface:
    """The torus's base mesh for its bands (see the module docstring).

    Parameters
    ----------
    t : Ring
    lights : list of PointLight or DirectionalLight
    contours : int
        N, the contours per family.
    eye : ndarray, shape (3,), or None
        The eye relative to the centre, for a specular material.
    shininess : float
    weights : (float, float)
        The material's ``(kd, ks)``.

    Returns
    -------
    Surface
        Relative to the centre; one smooth part.
    """
    from ..bands.surface import Surface, mixed_spacing, orient_outward, pieces

    R, r = t.major, t.minor
    min_v = MIN_TUBE
    min_u = int(min(MAX_RING, math.ceil(MIN_TUBE * math.sqrt((R + r) / r))))
    n_u, n_v = min_u, min_v
    if lights:
        h_u, h_v = _spacings(t, lights, contours, eye, shininess, weights)
        n_u = int(np.clip(pieces(2.0 * np.pi, h_u, cap=MAX_RING), min_u, MAX_RING))
        n_v = int(np.clip(pieces(2.0 * np.pi, h_v, cap=MAX_TUBE), min_v, MAX_TUBE))
        # the cells' mixed term, at the final n_v
        ug = np.linspace(0.0, 2.0 * np.pi, 181)
        vg = 2.0 * np.pi * np.arange(n_v + 1) / n_v
        p, n = _points(t, ug, vg)
        h = mixed_spacing(p, n, lights, t.center_array, contours, ug[1], vg[1], eye=eye, shininess=shininess,
                          weights=weights)
        n_u = int(np.clip(max(n_u, pieces(2.0 * np.pi, h, cap=MAX_RING)), min_u, MAX_RING))
    uu = 2.0 * np.pi * np.arange(n_u) / n_u
    vv = 2.0 * np.pi * np.arange(n_v) / n_v
    p, n = _points(t, uu, vv)
    vertices, normals = p.reshape(-1, 3), n.reshape(-1, 3)
    triangles = t._grid_triangles(n_u, n_v)
    return Surface(vertices, normals, orient_outward(vertices, normals, triangles), t.center_array.copy(),
                   np.zeros(len(vertices), np.int64))
