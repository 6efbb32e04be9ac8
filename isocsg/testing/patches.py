"""Every leaf's surface as patches, one-parameter families of rings: what the area integration sweeps.

The families themselves are kind data and live with the kinds (:mod:`isocsg.kinds.patches`); each
kind gives its own through :meth:`~isocsg.kinds.base.Primitive.surface_patches`.
"""

from __future__ import annotations

from ..kinds.base import Primitive
from ..kinds.patches import Patch, Rings, ellipsoid_area, elliptic_lateral_area, polygon_patch

__all__ = ["Patch", "Rings", "ellipsoid_area", "elliptic_lateral_area", "leaf_patches", "polygon_patch"]


def leaf_patches(i: int, prim: Primitive) -> list[Patch]:
    """The patches of leaf ``i``'s surface (:meth:`~isocsg.kinds.base.Primitive.surface_patches`).

    Raises
    ------
    InvalidGeometryError
        For a kind whose surface has no parametrisation (a kind registered by user code without one).
    """
    return prim.surface_patches(i)
