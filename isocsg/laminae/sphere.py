"""The names of :mod:`isocsg.kinds.sphere_bands` under their former path (the code lives there)."""

from __future__ import annotations

from ..bands.lights import light_axis
from ..bands.surface import ring_triangles
from ..kinds.sphere_bands import LATITUDES, LONGITUDES, contour_heights, sphere_laminae, sphere_surface

__all__ = [
    "contour_heights", "sphere_surface", "sphere_laminae", "LONGITUDES", "LATITUDES", "light_axis",
    "ring_triangles",
]
