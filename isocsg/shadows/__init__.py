"""Soft shadows from area and polyhedron light sources (Nishita and Nakamae 1983).

Light sources live in :mod:`isocsg.shadows.lights`; Lambert's contour
integral in :mod:`isocsg.shadows.lambert`; occluder decomposition in
:mod:`isocsg.shadows.occluders`; the exact illuminance and shadow states in
:mod:`isocsg.shadows.illuminance`.
"""

from .illuminance import LIT, PENUMBRA, UMBRA, illuminance, illuminance_and_state, shadow_state
from .lambert import edge_terms, polygon_illuminance, rings_illuminance
from .lights import AreaLight, PolyhedronLight
from .occluders import ConvexPiece, convex_pieces, shadow_pieces

__all__ = [
    "AreaLight",
    "PolyhedronLight",
    "illuminance",
    "shadow_state",
    "illuminance_and_state",
    "LIT",
    "PENUMBRA",
    "UMBRA",
    "edge_terms",
    "polygon_illuminance",
    "rings_illuminance",
    "ConvexPiece",
    "convex_pieces",
    "shadow_pieces",
]
