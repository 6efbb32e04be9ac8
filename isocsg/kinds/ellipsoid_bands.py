"""The band surface of an ellipsoid.

An ellipsoid's isoluminance curves are not planar in general (not even for a
directional light), so there are no planar contour laminae to place on mesh
edges as for the sphere. The bands come from the general machinery instead: a
latitude-longitude mesh of the unit ball, mapped by ``R S`` onto the surface
(vertices exactly on it, with the exact normals ``R S^-1 u`` normalised), fine
enough that every field (diffuse ``n . l`` per light, Phong terms) is followed
within a quarter of a band step (:func:`~isocsg.bands.surface.curvature_spacing`,
as for the truncus under a point light and for Phong highlights); the families
then cut it along their level lines (:mod:`~isocsg.laminae.split`).

The mesh's pole is the point facing the first light (where ``n . l`` peaks for a
directional light), so that the brightest cap is resolved by whole rings.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from ..bands.lights import is_directional
from ..bands.surface import Surface, curvature_spacing, mixed_spacing, orient_outward, pieces, ring_triangles

__all__ = ["Spheroid", "ellipsoid_surface", "MIN_LONGITUDES", "MAX_LONGITUDES"]

#: Vertices per ring at least (as the sphere: chord sag 3e-4 of the radius) and at most.
MIN_LONGITUDES = 128
MAX_LONGITUDES = 768
#: Samples per line when measuring how the fields bend.
_SAMPLES = 181


class Spheroid(Protocol):
    """What the ellipsoid's bands read of it (:class:`~isocsg.kinds.Ellipsoid`)."""

    @property
    def center_array(self) -> NDArray[np.float64]: ...

    @property
    def radii_array(self) -> NDArray[np.float64]: ...

    @property
    def rotation(self) -> NDArray[np.float64]: ...


def _frame(w: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    helper = np.array([1.0, 0.0, 0.0]) if abs(w[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    e1 = np.cross(w, helper)
    e1 /= np.linalg.norm(e1)
    return e1, np.cross(w, e1)


def _pole(e: Spheroid, lights: list) -> NDArray[np.float64]:
    """Unit-ball direction of the point whose normal faces the first light (+z without lights)."""
    if not lights:
        return np.array([0.0, 0.0, 1.0])
    light = lights[0]
    if is_directional(light):
        ldir = light.unit_direction
    else:
        ldir = np.asarray(light.position, dtype=np.float64) - e.center_array
    w = (ldir @ e.rotation) * e.radii_array  # n ∝ R S^-1 u is parallel to l where u ∝ S R^T l
    n = float(np.linalg.norm(w))
    return w / n if n > 0 else np.array([0.0, 0.0, 1.0])


def _map(e: Spheroid, dirs: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Surface points (relative to the centre) and unit normals of unit-ball directions."""
    R, r = e.rotation, e.radii_array
    pts = (dirs * r) @ R.T
    nrm = (dirs / r) @ R.T
    nrm /= np.linalg.norm(nrm, axis=-1, keepdims=True)
    return pts, nrm


def _grid(w, e1, e2, polar, phi) -> NDArray[np.float64]:
    t, s = np.cos(polar), np.sin(polar)
    ring = np.cos(phi)[:, None] * e1 + np.sin(phi)[:, None] * e2
    return t[:, None, None] * w + s[:, None, None] * ring[None]


def ellipsoid_surface(
    e: Spheroid, lights: list, contours: int, eye: NDArray[np.float64] | None, shininess: float,
    weights: tuple[float, float] = (1.0, 1.0), segments: int | None = None,
) -> Surface:
    """Latitude-longitude mesh of the ellipsoid, fine enough for every field (see the module docstring).

    Parameters
    ----------
    e : Spheroid
    lights : list of PointLight or DirectionalLight
    contours : int
        N, the contours per family.
    eye : ndarray, shape (3,), or None
        The eye relative to the centre, for a specular material.
    shininess : float
    weights : (float, float)
        The material's ``(kd, ks)``, as every kind's surface hook receives them (unused here).
    segments : int, optional
        A renderer's tessellation hint for a leaf small on screen (unused here: the mesh
        is refined by its fields).

    Returns
    -------
    Surface
        Relative to the centre; one smooth part.
    """
    w = _pole(e, lights)
    e1, e2 = _frame(w)
    origin = e.center_array
    # how the fields bend along meridians and rings, in radians of the unit ball's angles
    polar_s = np.linspace(0.0, np.pi, _SAMPLES)
    phi_m = 2.0 * np.pi * np.arange(24) / 24
    mer = _grid(w, e1, e2, polar_s, phi_m).transpose(1, 0, 2)  # (24 meridians, samples, 3)
    phi_s = np.linspace(0.0, 2.0 * np.pi, 2 * _SAMPLES)
    rings = _grid(w, e1, e2, np.pi * (np.arange(1, 16) / 16), phi_s)  # (15 rings, samples, 3)
    h_polar = h_phi = np.inf
    if lights:
        pm, nm = _map(e, mer)
        h_polar = curvature_spacing(pm, nm, lights, origin, contours, eye=eye, shininess=shininess, step=polar_s[1])
        pr, nr = _map(e, rings)
        h_phi = curvature_spacing(pr, nr, lights, origin, contours, eye=eye, shininess=shininess, step=phi_s[1])
    n_lon = int(np.clip(pieces(2.0 * np.pi, h_phi, cap=MAX_LONGITUDES), MIN_LONGITUDES, MAX_LONGITUDES))
    if lights:  # the mixed term of the cells (see mixed_spacing), at the final n_lon
        pg_ = np.linspace(0.0, np.pi, 65)
        phig = 2.0 * np.pi * np.arange(n_lon + 1) / n_lon
        pm, nm = _map(e, _grid(w, e1, e2, pg_, phig))
        h_polar = min(h_polar, mixed_spacing(pm, nm, lights, origin, contours, pg_[1], phig[1], eye=eye,
                                             shininess=shininess))
    n_lat = int(np.clip(pieces(np.pi, h_polar, cap=MAX_LONGITUDES // 2), MIN_LONGITUDES // 2, MAX_LONGITUDES // 2))
    polar = np.pi * np.arange(1, n_lat) / n_lat
    phi = 2.0 * np.pi * np.arange(n_lon) / n_lon
    dirs = np.vstack([w, _grid(w, e1, e2, polar, phi).reshape(-1, 3), -w])
    vertices, normals = _map(e, dirs)
    triangles = ring_triangles(n_lat - 1, n_lon)
    return Surface(vertices, normals, orient_outward(vertices, normals, triangles), origin.copy(),
                   np.zeros(len(vertices), np.int64))
