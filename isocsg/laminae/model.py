"""Data structures of the isoluminance representation.

A :class:`LaminaSet` is everything the first paper computes for one primitive
under given lights and material: the contour families (parallel planes), the
laminae (filled planar contour polygons, inspectable and checked against the
paper's formulas) and the :class:`BandMesh` (the surface strips between
consecutive contours as planar triangles of constant value) that the renderer
fills.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = ["Lamina", "ContourFamily", "BandMesh", "LaminaSet"]


@dataclass(frozen=True, slots=True, eq=False)
class Lamina:
    """One planar polygon of the isoluminance representation.

    Attributes
    ----------
    vertices : ndarray, shape (k, 3)
        Polygon vertices in cyclic order (counter-clockwise about ``normal``).
    normal : ndarray, shape (3,)
        Unit normal of the lamina's plane.
    intensity : float
        The constant intensity assigned to this lamina.
    key : float
        Painter's key: signed position of the plane along its family normal
        (``normal . vertices[0]``); within one family, sorting by the eye's
        side of this key gives an exact back-to-front order.
    kind : str
        ``"contour"`` (sphere circle or truncus quad phi_i), ``"end"`` (truncus
        end lamina) or ``"face"`` (polyhedron face).
    family : int
        Index of the contour family (light) this lamina belongs to; -1 for ends and faces.
    """

    vertices: NDArray[np.float64]
    normal: NDArray[np.float64]
    intensity: float
    key: float
    kind: str
    family: int = 0


@dataclass(frozen=True, slots=True, eq=False)
class ContourFamily:
    """A family of parallel contour planes ``normal . x = offsets[k]``.

    ``levels[k]`` is the shading value on plane k; band k (between planes k
    and k+1) has the constant value ``band_values[k]``.
    """

    normal: NDArray[np.float64]
    offsets: NDArray[np.float64]
    levels: NDArray[np.float64]
    band_values: NDArray[np.float64]
    light_index: int


@dataclass(frozen=True, slots=True, eq=False, repr=False)
class BandMesh:
    """Planar triangles on the surface, each of one constant value.

    Attributes
    ----------
    vertices : ndarray, shape (V, 3), float64
        On (or inscribed in) the true surface.
    triangles : ndarray, shape (T, 3), int32
        Counter-clockwise seen from outside the solid.
    value_out : ndarray, shape (T,), float64
        Value shown where the surface is seen with its outward normal.
    value_in : ndarray, shape (T,), float64
        Value shown where the surface is the inside of a CSG cut (reversed normal).
    band : ndarray, shape (T,), int32
        Band (or composite piece) index of each triangle, for inspection.
    """

    vertices: NDArray[np.float64]
    triangles: NDArray[np.int32]
    value_out: NDArray[np.float64]
    value_in: NDArray[np.float64]
    band: NDArray[np.int32]

    @property
    def n_triangles(self) -> int:
        """Number of triangles."""
        return int(len(self.triangles))

    def __repr__(self) -> str:
        """One line with the array shapes (the arrays themselves are long).

        Examples
        --------
        >>> BandMesh(np.zeros((3, 3)), np.array([[0, 1, 2]], np.int32), np.ones(1), np.ones(1), np.zeros(1, np.int32))
        <BandMesh(vertices.shape=(3, 3), triangles.shape=(1, 3))>
        """
        return f"<BandMesh(vertices.shape={np.shape(self.vertices)}, triangles.shape={np.shape(self.triangles)})>"

    @staticmethod
    def concatenate(meshes: list[BandMesh]) -> BandMesh:
        """Join several band meshes into one."""
        if not meshes:
            return BandMesh(np.zeros((0, 3)), np.zeros((0, 3), np.int32), np.zeros(0), np.zeros(0),
                            np.zeros(0, np.int32))
        offs = np.cumsum([0] + [len(m.vertices) for m in meshes[:-1]])
        return BandMesh(
            np.vstack([m.vertices for m in meshes]),
            np.vstack([m.triangles + o for m, o in zip(meshes, offs)]).astype(np.int32),
            np.concatenate([m.value_out for m in meshes]),
            np.concatenate([m.value_in for m in meshes]),
            np.concatenate([m.band for m in meshes]).astype(np.int32),
        )


@dataclass(frozen=True, slots=True, eq=False, repr=False)
class LaminaSet:
    """The isoluminance representation of one primitive.

    Attributes
    ----------
    primitive : Primitive
    laminae : tuple of Lamina
    families : tuple of ContourFamily
    bands : BandMesh
    view_dependent : bool
        True when a specular term made the set depend on the eye position.
    """

    primitive: object
    laminae: tuple[Lamina, ...]
    families: tuple[ContourFamily, ...]
    bands: BandMesh
    view_dependent: bool = False

    def __repr__(self) -> str:
        """One line of counts (the laminae and bands can be millions of numbers).

        Examples
        --------
        >>> from isocsg import PointLight, Sphere, build_laminae
        >>> build_laminae(Sphere((0, 0, 0), 1), [PointLight((0, 0, 5))], contours=8)  # doctest: +ELLIPSIS
        <LaminaSet(Sphere, 8 laminae, 1 families, ... band triangles, view-independent)>
        """
        kind = "view-dependent" if self.view_dependent else "view-independent"
        return (
            f"<LaminaSet({type(self.primitive).__name__}, {len(self.laminae)} laminae, {len(self.families)} families, "
            f"{len(self.bands.triangles)} band triangles, {kind})>"
        )

    def painter_order(self, eye: NDArray[np.float64]) -> list[int]:
        """Indices of ``laminae`` back to front as seen from ``eye`` (the paper's painter's order).

        Within one family the laminae lie in parallel planes; the ones whose
        plane is farther from the eye along the family normal come first.
        """
        e = np.asarray(eye, dtype=np.float64)
        dist = [abs(float(l.normal @ e) - l.key) for l in self.laminae]
        return sorted(range(len(self.laminae)), key=lambda i: -dist[i])
