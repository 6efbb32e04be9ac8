"""The names of :mod:`isocsg.kinds.polyhedron_bands` under their former path (the code lives there)."""

from __future__ import annotations

from ..kinds.polyhedron_bands import face_laminae, polyhedron_surface

__all__ = ["face_laminae", "polyhedron_surface"]
