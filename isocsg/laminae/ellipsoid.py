"""The names of :mod:`isocsg.kinds.ellipsoid_bands` under their former path (the code lives there)."""

from __future__ import annotations

from ..kinds.ellipsoid_bands import MAX_LONGITUDES, MIN_LONGITUDES, ellipsoid_surface

__all__ = ["ellipsoid_surface", "MIN_LONGITUDES", "MAX_LONGITUDES"]
