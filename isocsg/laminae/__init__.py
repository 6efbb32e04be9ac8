"""Isoluminance laminae (the first paper): contour polygons and the band meshes the renderer fills.

- :func:`build_laminae` builds (and caches) a primitive's :class:`LaminaSet`;
  :func:`build_bands` only its band mesh (what the renderer fills).
- :mod:`~isocsg.laminae.split` the cutting of a mesh into bands.

The seed's constructions per primitive live beside each kind (``isocsg/kinds/<kind>_bands.py``)
and the shading fields and levels in :mod:`isocsg.bands`, below the kinds; the modules
``laminae.sphere``, ``truncus``, ``polyhedron``, ``ellipsoid``, ``elliptic``, ``surface`` and
``families`` keep their names under the former paths.
"""

from .builder import MAX_CONTOURS, build_bands, build_laminae, cache_info, clear_cache
from .model import BandMesh, ContourFamily, Lamina, LaminaSet

__all__ = ["build_laminae", "build_bands", "clear_cache", "cache_info", "MAX_CONTOURS", "Lamina", "ContourFamily",
           "BandMesh", "LaminaSet"]
