"""The names of :mod:`isocsg.kinds.truncus_bands` under their former path (the code lives there)."""

from __future__ import annotations

from ..kinds.truncus_bands import (
    GENERATORS,
    appendix_normal,
    light_frame,
    paper_levels,
    side_cosine_coefficients,
    side_levels,
    truncus_laminae,
    truncus_surface,
)

__all__ = [
    "light_frame", "side_cosine_coefficients", "paper_levels", "appendix_normal", "truncus_laminae",
    "truncus_surface", "side_levels", "GENERATORS",
]
