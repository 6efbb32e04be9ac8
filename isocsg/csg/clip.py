"""Laminae of CSG trees clipped against the other operands (the seed's future work).

The isoluminance paper ends by proposing CSG through lamina clipping. Since
CSG commutes with plane sections, clipping a lamina of primitive ``A`` against
the rest of the tree is a 2D Boolean in the lamina's own plane: the lamina
polygon intersected with the section of the whole result in that plane
(:func:`isocsg.csg.section.section`).

Ownership (why the renderer does not paint these polygons)
-----------------------------------------------------------
A clipped lamina of ``A`` is a *cross-section of the result*, not a piece of
``A``'s surface. Where the visible surface of ``A & B`` lies on the boundary
of ``B``, ``A``'s clipped laminae still fill that region, at almost the same
depth, carrying ``A``'s intensity: painting them would show ``A``'s shading on
``B``'s surface. Each visible surface point must take the intensity of the
primitive whose boundary it lies on, and inside a difference the subtracted
primitive's boundary is seen with its normal reversed. The renderer
(:mod:`isocsg.rendering`, see ``docs/architecture.md``) therefore fills each
primitive's surface *bands* and resolves ownership per pixel with the tree's
interval program. Clipped laminae are the geometric by-product: inspectable
cross-sections (areas, outlines, SVG figures) and a check of the result's
shape in every contour plane.

Leaves under an odd number of "subtracted" positions carve material: their
clipped laminae are the part of the lamina whose material the leaf removes,
``L n (S(T without the leaf) - S(T))``; this is where the leaf's reversed
surface can be seen.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import shapely
from numpy.typing import NDArray
from shapely.geometry import MultiPolygon, Polygon

from .._validation import integer
from ..errors import InvalidParameterError
from ..kinds import Primitive, Solid
from .program import OP_DIFFERENCE, Program
from .section import Section, combine_sections, plane_frame, polygonal, primitive_section, solid_program

__all__ = ["ClippedLamina", "leaf_polarities", "clip_lamina_set", "clip_laminae"]

_EMPTY = Polygon()


@dataclass(frozen=True, slots=True, eq=False)
class ClippedLamina:
    """The part of one lamina that lies in the CSG result.

    Attributes
    ----------
    lamina : Lamina
        The unclipped lamina (from :func:`isocsg.laminae.build_laminae`).
    leaf : int
        Index of the lamina's primitive among the tree's leaves (program order).
    polarity : int
        ``+1`` for leaves that add material, ``-1`` for leaves that carve it
        (subtracted operands); see the module docstring.
    geometry : shapely.Polygon or shapely.MultiPolygon
        The clipped lamina in the 2D frame of its plane (may be empty).
    frame : ndarray, shape (4, 4)
        Maps ``(x, y, 0, 1)`` of ``geometry`` to 3D (see :func:`plane_frame`).
    """

    lamina: Any
    leaf: int
    polarity: int
    geometry: Polygon | MultiPolygon
    frame: NDArray[np.float64]

    @property
    def intensity(self) -> float:
        """The lamina's constant intensity."""
        return float(self.lamina.intensity)

    @property
    def area(self) -> float:
        """Area of the clipped polygon."""
        return float(self.geometry.area)

    @property
    def is_empty(self) -> bool:
        """True when nothing of the lamina survives the clipping."""
        return bool(self.geometry.is_empty) or self.geometry.area == 0.0

    def rings_3d(self) -> list[NDArray[np.float64]]:
        """Every ring of the clipped polygon as a closed (k, 3) polyline in 3D."""
        return Section(self.geometry, self.frame).rings_3d()


def leaf_polarities(solid: Solid) -> list[int]:
    """``+1`` or ``-1`` per leaf (program order): ``-1`` under an odd number of subtractions.

    Examples
    --------
    >>> from isocsg import Box, Sphere
    >>> a, b, c = Sphere((0, 0, 0), 1), Box((0, 0, 0), (1, 1, 1)), Sphere((0, 0, 0), 0.2)
    >>> leaf_polarities(a - (b - c))
    [1, -1, 1]
    """

    def combine(op: int, parts: list[list[int]]) -> list[int]:
        if op != OP_DIFFERENCE:
            return [s for p in parts for s in p]
        return parts[0] + [-s for p in parts[1:] for s in p]

    return solid_program(solid).evaluate(lambda i, p: [1], combine)


def _lamina_polygon(vertices: NDArray[np.float64], F: NDArray[np.float64]) -> Polygon | MultiPolygon:
    xy = (np.asarray(vertices, dtype=np.float64) - F[:3, 3]) @ F[:3, :2]
    if len(xy) < 3:
        return _EMPTY
    poly = Polygon(xy)
    if not poly.is_valid:
        poly = shapely.make_valid(poly)
    return polygonal(poly)


def _clip_one(
    lamina: Any,
    leaf: int,
    polarity: int,
    prims: Sequence[Primitive],
    prog: Program,
    resolution: int,
) -> ClippedLamina:
    verts = np.asarray(lamina.vertices, dtype=np.float64)
    F = plane_frame(verts.mean(axis=0), np.asarray(lamina.normal, dtype=np.float64))
    poly = _lamina_polygon(verts, F)
    if poly.is_empty:
        return ClippedLamina(lamina, leaf, polarity, _EMPTY, F)
    geoms = [primitive_section(p, F, resolution) for p in prims]
    result = combine_sections(prog, geoms)
    if polarity > 0:
        region = result
    else:
        without = list(geoms)
        without[leaf] = _EMPTY
        region = polygonal(shapely.difference(combine_sections(prog, without), result))
    clipped = _EMPTY if region.is_empty else polygonal(shapely.intersection(poly, region))
    return ClippedLamina(lamina, leaf, polarity, clipped, F)


def clip_lamina_set(
    solid: Solid,
    leaf: int,
    laminae: Sequence[Any],
    *,
    resolution: int = 256,
) -> tuple[ClippedLamina, ...]:
    """Clip given laminae of one leaf of ``solid`` against the whole tree.

    Parameters
    ----------
    solid : Solid
        The CSG tree (or a primitive: then nothing is clipped away).
    leaf : int
        Index of the laminae's primitive among ``solid``'s leaves (program order).
    laminae : sequence of Lamina
        Objects with ``vertices`` (k, 3), ``normal`` (3,) and ``intensity``.
    resolution : int, default 256
        Polygon vertices per full circle of the other operands' sections.

    Returns
    -------
    tuple of ClippedLamina
        One per input lamina, in order (possibly empty geometries).

    Raises
    ------
    InvalidParameterError
        If ``leaf`` is out of range or ``resolution`` is bad.

    Examples
    --------
    >>> from isocsg import Box, Sphere
    >>> from isocsg.laminae.model import Lamina
    >>> square = Lamina(np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0.0]]),
    ...                 np.array([0, 0, 1.0]), 0.5, 0.0, "face", -1)
    >>> tree = Box((0, 0, 0), (2, 2, 2)) - Box((1, 0, 0), (2, 4, 4))
    >>> clip_lamina_set(tree, 0, [square])[0].area
    2.0
    """
    prog = solid_program(solid)
    prims = prog.leaves
    i = integer("leaf", leaf, low=0, high=len(prims) - 1, error=InvalidParameterError)
    res = integer("resolution", resolution, low=8, high=1_000_000, error=InvalidParameterError)
    pol = leaf_polarities(solid)[i]
    return tuple(_clip_one(lam, i, pol, prims, prog, res) for lam in laminae)


def clip_laminae(
    solid: Solid,
    lights: Sequence[Any],
    material: Any = None,
    contours: int = 64,
    *,
    resolution: int = 256,
    keep_empty: bool = False,
) -> tuple[ClippedLamina, ...]:
    """Build every leaf's laminae and clip them against the other operands.

    For each leaf primitive of ``solid`` this calls
    :func:`isocsg.laminae.build_laminae` and clips each lamina in its own
    plane: lamina polygon n section of the result (leaves that add material),
    or lamina polygon n the material the leaf carves away (subtracted leaves).
    See the module docstring for why the renderer resolves visibility per
    pixel instead of painting these polygons.

    Parameters
    ----------
    solid : Solid
        A primitive or CSG tree.
    lights : sequence of PointLight or DirectionalLight
    material : Material, optional
        Defaults to ``Material()``.
    contours : int, default 64
        Isoluminance contours per light family.
    resolution : int, default 256
        Polygon vertices per full circle of the operands' sections.
    keep_empty : bool, default False
        Also return laminae clipped away entirely.

    Returns
    -------
    tuple of ClippedLamina
        Leaf by leaf (program order), laminae in their set's order.

    Raises
    ------
    InvalidGeometryError
        If ``solid`` is not a solid.
    InvalidParameterError
        On bad ``contours`` or ``resolution`` (and whatever ``build_laminae`` rejects).

    Examples
    --------
    >>> from isocsg import Cylinder, PointLight, Sphere
    >>> tree = Sphere((0, 0, 0), 1.0) - Cylinder((0, 0, 0), (0, 0, 3), 0.4)
    >>> clipped = clip_laminae(tree, [PointLight((0, 0, 5))], contours=8)  # doctest: +SKIP
    >>> all(c.polarity == 1 for c in clipped if c.leaf == 0)  # doctest: +SKIP
    True
    """
    from ..laminae import build_laminae

    res = integer("resolution", resolution, low=8, high=1_000_000, error=InvalidParameterError)
    prog = solid_program(solid)
    prims = prog.leaves
    pols = leaf_polarities(solid)
    out: list[ClippedLamina] = []
    for i, prim in enumerate(prims):
        ls = build_laminae(prim, lights, material, contours=contours)
        for lam in ls.laminae:
            c = _clip_one(lam, i, pols[i], prims, prog, res)
            if keep_empty or not c.is_empty:
                out.append(c)
    return tuple(out)
