"""The names of :mod:`isocsg.bands.families` under their former path (the code lives there)."""

from __future__ import annotations

from ..bands.families import (
    GRAZING,
    FieldFamily,
    band_tables,
    diffuse_family,
    diffuse_levels,
    incidence,
    light_direction_at,
    specular_families,
    specular_levels,
)

__all__ = [
    "FieldFamily", "diffuse_levels", "specular_levels", "incidence", "diffuse_family", "specular_families",
    "light_direction_at", "band_tables", "GRAZING",
]
