"""Isoluminance contours of a sphere (the seed's "lines of latitude").

For a point light P at distance D > R from the centre, the incidence cosine
at a surface point depends only on the polar angle phi from the centre-light
axis (rotational symmetry): with ``t = cos(phi)``,

    cos_i(t) = (D t - R) / sqrt(D**2 + R**2 - 2 D R t),

so every isoluminance contour is a circle about that axis, exactly, for any
D > R (the lit cap ends at ``t = R / D``, not at the equator). Solving
``cos_i(t) = c`` gives the contour heights in closed form,

    t(c) = (R (1 - c**2) + c sqrt(D**2 - R**2 (1 - c**2))) / D,

and for a directional light ``t(c) = c`` (the seed's cosine distribution).
"""

from __future__ import annotations

from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from ..bands.lights import Light, is_directional, light_axis
from ..bands.surface import Surface, orient_outward, ring_triangles

__all__ = ["Ball", "contour_heights", "sphere_surface", "sphere_laminae", "LONGITUDES", "LATITUDES"]

#: Vertices per circle of latitude of the band mesh (chord sag 3e-4 R).
LONGITUDES = 128
#: Uniform polar subdivisions added to the contour circles (for the silhouette).
LATITUDES = 64

class Ball(Protocol):
    """What the sphere's bands read of it (:class:`~isocsg.kinds.Sphere`)."""

    @property
    def center_array(self) -> NDArray[np.float64]: ...

    @property
    def radius(self) -> float: ...


def contour_heights(sphere: Ball, light: Light, cosines: NDArray[np.float64]) -> NDArray[np.float64]:
    """Polar cosines ``t`` of the circles where the incidence cosine equals ``cosines``.

    Parameters
    ----------
    sphere : Sphere
    light : PointLight or DirectionalLight
    cosines : array_like
        Incidence cosines in [-1, 1] (negative values: the reversed normal's
        contours, seen inside a CSG cut).

    Returns
    -------
    ndarray
        ``t`` in [-1, 1]; NaN for every value when a point light is inside or on the sphere.

    Examples
    --------
    >>> from isocsg import PointLight, Sphere
    >>> contour_heights(Sphere((0, 0, 0), 1.0), PointLight((0, 0, 4)), [0.0, 1.0]).tolist()
    [0.25, 1.0]
    """
    c = np.clip(np.asarray(cosines, dtype=np.float64), -1.0, 1.0)
    if is_directional(light):
        return c.copy()
    r = sphere.radius
    d = float(np.linalg.norm(np.asarray(light.position) - sphere.center_array))
    if d <= r:
        return np.full(c.shape, np.nan)
    s = 1.0 - c * c
    return np.clip((r * s + c * np.sqrt(d * d - r * r * s)) / d, -1.0, 1.0)


def _frame(w: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    helper = np.array([1.0, 0.0, 0.0]) if abs(w[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    e1 = np.cross(w, helper)
    e1 /= np.linalg.norm(e1)
    return e1, np.cross(w, e1)


def _rings(t: NDArray[np.float64], latitudes: int = LATITUDES) -> NDArray[np.float64]:
    """Polar cosines of the mesh circles: the contour circles, plus uniformly
    spaced circles in every polar gap wider than ``pi / latitudes`` (near the
    light's pole the contours are far apart in angle, and the silhouette
    needs fine steps everywhere)."""
    polar = np.sort(np.arccos(np.clip(t, -1.0, 1.0)))
    polar = polar[(polar > 1e-9) & (polar < np.pi - 1e-9)]
    edges = np.concatenate([[0.0], polar, [np.pi]])
    step = np.pi / latitudes
    fill = []
    for a, b in zip(edges[:-1], edges[1:]):
        k = int(np.ceil((b - a) / step - 1e-9))
        if k > 1:
            fill.append(a + (b - a) * np.arange(1, k) / k)
    polar = np.sort(np.concatenate([polar, *fill]))
    polar = polar[np.concatenate([[True], np.diff(polar) > 1e-12])]
    return np.cos(polar)



def sphere_surface(
    sphere: Ball, light: Light | None, levels: NDArray[np.float64], segments: int = LONGITUDES,
) -> Surface:
    """Latitude-longitude mesh about the axis of ``light`` with circles at the contour ``levels``.

    ``segments`` longitudes (default ``LONGITUDES``), and circles at most ``2 pi / segments``
    apart in polar angle: a renderer asks for fewer for a sphere small on screen.

    The circles of the first light's contours are mesh edges, so its family
    cuts nothing; other lights cut the mesh along their own level lines.
    """
    c, r = sphere.center_array, sphere.radius
    w = light_axis(c, light)
    e1, e2 = _frame(w)
    th = contour_heights(sphere, light, levels) if light is not None else np.zeros(0)
    m = int(segments)
    t = _rings(th[np.isfinite(th)], max(m // 2, 4))
    s = np.sqrt(1.0 - t * t)
    phi = 2.0 * np.pi * np.arange(m) / m
    ring = np.cos(phi)[:, None] * e1 + np.sin(phi)[:, None] * e2  # (M, 3)
    dirs = (t[:, None, None] * w + s[:, None, None] * ring[None]).reshape(-1, 3)
    normals = np.vstack([w, dirs, -w])
    vertices = r * normals  # relative to the centre
    n_rings = len(t)
    triangles = ring_triangles(n_rings, m)
    return Surface(vertices, normals, orient_outward(vertices, normals, triangles), c.copy(),
                   np.zeros(len(vertices), np.int64))


def sphere_laminae(
    sphere: Ball, light: Light, contours: int
) -> list[tuple[NDArray[np.float64], NDArray[np.float64], float]]:
    """The seed's contour laminae of one light: circles at cosines ``k / N``, k = 0 .. N-1.

    Returns
    -------
    list of (vertices, normal, cosine)
        Each circle as a polygon (more vertices for larger circles, as in the
        seed) with the unit axis as normal and the cosine of the band it
        bounds towards the light (the middle of ``k / N`` and ``(k + 1) / N``).
        Empty when a point light is inside the sphere (its outside is unlit).
    """
    c, r = sphere.center_array, sphere.radius
    w = light_axis(c, light)
    e1, e2 = _frame(w)
    k = np.arange(contours)
    cos_k = k / contours
    t = contour_heights(sphere, light, cos_k)
    ok = np.isfinite(t)
    tk, ck = t[ok], cos_k[ok]
    rho = np.sqrt(np.maximum(1.0 - tk * tk, 0.0))
    nv = np.maximum(8, np.ceil(LONGITUDES * rho).astype(np.int64))
    # All circles in one pass: circle i has nv[i] points at angles 2 pi j / nv[i].
    first = np.concatenate([[0], np.cumsum(nv)])
    j = np.arange(first[-1]) - np.repeat(first[:-1], nv)
    phi = 2.0 * np.pi * j / np.repeat(nv, nv)
    ring = np.cos(phi)[:, None] * e1 + np.sin(phi)[:, None] * e2
    points = c + r * (np.repeat(tk, nv)[:, None] * w + np.repeat(rho, nv)[:, None] * ring)
    polys = np.split(points, first[1:-1])
    return [(poly, w.copy(), float(x + 0.5 / contours)) for poly, x in zip(polys, ck)]
