"""The names of :mod:`isocsg.kinds.elliptic_bands` under their former path (the code lives there)."""

from __future__ import annotations

from ..kinds.elliptic_bands import elliptic_surface

__all__ = ["elliptic_surface"]
