"""Soft shadows from area and polyhedron light sources (Nishita and Nakamae 1983).

Light sources live in :mod:`isocsg.shadows.lights`; the exact illuminance and
shadow states in :mod:`isocsg.shadows.illuminance`.
"""

from .lights import AreaLight, PolyhedronLight

__all__ = ["AreaLight", "PolyhedronLight"]
