"""The names of :mod:`isocsg.bands.surface` under their former path (the code lives there)."""

from __future__ import annotations

from ..bands.surface import (
    Surface,
    curvature_spacing,
    eye_reference_distance,
    light_reference_distance,
    mixed_spacing,
    orient_outward,
    pieces,
    refinement,
    ring_triangles,
    specular_refinement,
)

__all__ = [
    "Surface", "orient_outward", "light_reference_distance", "refinement", "specular_refinement",
    "eye_reference_distance", "curvature_spacing", "mixed_spacing", "pieces", "ring_triangles",
]
