"""Isoluminance laminae (the first paper): contour polygons and the band meshes the renderer fills.

- :func:`build_laminae` builds (and caches) a primitive's :class:`LaminaSet`;
  :func:`build_bands` only its band mesh (what the renderer fills).
- :mod:`~isocsg.laminae.sphere`, :mod:`~isocsg.laminae.truncus` and
  :mod:`~isocsg.laminae.polyhedron` hold the seed's constructions per primitive;
  :mod:`~isocsg.laminae.families` the shading fields and levels;
  :mod:`~isocsg.laminae.split` the cutting of a mesh into bands.
"""

from .builder import MAX_CONTOURS, build_bands, build_laminae, cache_info, clear_cache
from .model import BandMesh, ContourFamily, Lamina, LaminaSet

__all__ = ["build_laminae", "build_bands", "clear_cache", "cache_info", "MAX_CONTOURS", "Lamina", "ContourFamily",
           "BandMesh", "LaminaSet"]
