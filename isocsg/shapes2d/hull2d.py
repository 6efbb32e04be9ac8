"""The exact convex hull of discs in the plane.

The hull of discs (and points: discs of radius 0) is the union of the discs and the convex
polygon of the points where the hull's outer tangent lines touch them: every boundary piece of
the hull is an arc of one disc or a segment of a common outer tangent. Used by OpenSCAD's 2D
``hull`` and by the outlines of projected cylinders and cones (an affine map makes their two end
ellipses circles).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from .shape import EMPTY, Shape2D, union2d

__all__ = ["disc_hull"]


def disc_hull(centres: NDArray[np.float64], radii: NDArray[np.float64]) -> Shape2D:
    """The convex hull of discs (radius 0: points), exactly: the discs together with the convex
    polygon of the points where the hull's outer tangent lines touch them."""
    import shapely

    from .constructors import circle, polygon

    size = float(np.ptp(centres, axis=0).max() + 2 * radii.max())
    touch = []
    for i in range(len(centres)):
        d = centres - centres[i]
        length = np.hypot(d[:, 0], d[:, 1])
        for j in np.nonzero(length > np.abs(radii[i] - radii))[0]:
            u = d[j] / length[j]
            a = (radii[i] - radii[j]) / length[j]
            n = a * u - math.sqrt(max(0.0, 1.0 - a * a)) * np.array([-u[1], u[0]])  # outward, on the right
            if np.all(centres @ n + radii <= centres[i] @ n + radii[i] + 1e-12 * size):
                touch += [centres[i] + radii[i] * n, centres[j] + radii[j] * n]
    hull = shapely.convex_hull(shapely.multipoints(np.array(touch))) if touch else None
    discs = [circle(float(r)).translate(c.tolist()) for c, r in zip(centres, radii) if r > 0]
    parts = list(discs)
    if hull is not None and hull.geom_type == "Polygon" and hull.area > 0:
        parts.append(polygon(np.asarray(hull.exterior.coords)[:-1].tolist()))
    return union2d(*parts) if parts else EMPTY
