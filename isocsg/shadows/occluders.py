"""Occluders as unions of convex polyhedra (the seed treats objects as sets of convex polyhedra).

Boxes and convex polyhedra are exact; spheres and frusta (truncus, cylinder,
cone) are replaced by their inscribed tessellation ``to_polyhedron(resolution)``.
CSG trees decompose into convex pieces:

- a union is the list of its operands' pieces;
- an intersection of convex pieces is convex (the union of their half-spaces);
- A minus a convex B with faces f_1..f_k is the union over j of
  A n (outside f_j) n (inside f_1..f_{j-1}) (disjoint up to boundaries);
- nested trees recursively; empty (or flat) pieces are dropped.

Pieces of one solid may touch along shared faces: the visibility code only
needs the union of their silhouettes, so touching is harmless.
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..csg.program import OP_INTERSECTION, OP_UNION, compile_program
from ..errors import InvalidGeometryError, InvalidParameterError
from ..geometry.primitives import DEFAULT_RESOLUTION, Box, ConvexPolyhedron, Primitive, Solid

__all__ = ["ConvexPiece", "convex_pieces", "halfspace_pieces", "DEFAULT_RESOLUTION"]

# A piece thinner than this (relative to the occluder's size) counts as empty.
EMPTY_TOL = 1e-9

HalfSpaces = tuple[NDArray[np.float64], NDArray[np.float64]]  # (normals (k, 3), offsets (k,)): n . x <= d


@dataclass(frozen=True, slots=True)
class ConvexPiece:
    """One convex polyhedron of an occluder: half-spaces, vertices and edges.

    Attributes
    ----------
    normals : ndarray, shape (k, 3)
        Unit outward face normals; the solid is ``normals @ x <= offsets``.
    offsets : ndarray, shape (k,)
    vertices : ndarray, shape (v, 3)
    edges : ndarray of int64, shape (e, 2)
        Vertex index pairs of the polyhedron's edges.

    Examples
    --------
    >>> from isocsg import Box
    >>> piece = convex_pieces([Box((0, 0, 0), (1, 2, 3))])[0]
    >>> piece.vertices.shape, piece.edges.shape, piece.normals.shape
    ((8, 3), (12, 2), (6, 3))
    """

    normals: NDArray[np.float64] = field(compare=False)
    offsets: NDArray[np.float64] = field(compare=False)
    vertices: NDArray[np.float64] = field(compare=False)
    edges: NDArray[np.int64] = field(compare=False)

    @classmethod
    def from_polyhedron(cls, poly: ConvexPolyhedron) -> ConvexPiece:
        """The piece of a :class:`ConvexPolyhedron` (its hull faces and edges)."""
        pairs = set()
        for f in poly.faces:
            f = np.asarray(f)
            for a, b in zip(f, np.roll(f, -1)):
                pairs.add((int(min(a, b)), int(max(a, b))))
        edges = np.array(sorted(pairs), dtype=np.int64).reshape(-1, 2)
        return cls(
            np.array(poly.face_normals, dtype=np.float64),
            np.array(poly.face_offsets, dtype=np.float64),
            np.array(poly.hull_vertices, dtype=np.float64),
            edges,
        )

    @property
    def polyhedron(self) -> ConvexPolyhedron:
        """The piece as a :class:`ConvexPolyhedron`."""
        return ConvexPolyhedron(self.vertices)

    def contains(self, points: Any, *, tol: float = 0.0) -> NDArray[np.bool_]:
        """Points inside or on the piece (within ``tol``)."""
        p = np.atleast_2d(np.asarray(points, dtype=np.float64))
        return np.all(p @ self.normals.T <= self.offsets + tol, axis=1)


def _leaf_halfspaces(prim: Primitive, resolution: int) -> HalfSpaces:
    poly = prim.to_polyhedron() if isinstance(prim, (Box, ConvexPolyhedron)) else prim.to_polyhedron(resolution)
    return np.array(poly.face_normals, dtype=np.float64), np.array(poly.face_offsets, dtype=np.float64)


def _chebyshev(hs: HalfSpaces) -> tuple[NDArray[np.float64], float]:
    """Centre and radius of the largest ball inside the half-spaces (radius < 0 when empty)."""
    from scipy.optimize import linprog

    a, b = hs
    norms = np.linalg.norm(a, axis=1)
    res = linprog(
        c=np.array([0.0, 0.0, 0.0, -1.0]),
        A_ub=np.column_stack([a, norms]),
        b_ub=b,
        bounds=[(None, None)] * 3 + [(None, None)],
        method="highs",
    )
    if res.status == 3:  # unbounded: cannot happen for pieces of bounded solids
        raise InvalidGeometryError("occluder piece is unbounded")
    if not res.success:
        return np.zeros(3), -1.0
    return res.x[:3], float(res.x[3])


class _Decomposer:
    def __init__(self, resolution: int, scale: float) -> None:
        self.resolution = resolution
        self.tol = EMPTY_TOL * scale

    def nonempty(self, hs: HalfSpaces) -> bool:
        return _chebyshev(hs)[1] > self.tol

    def pieces(self, solid: Solid) -> list[HalfSpaces]:
        if not isinstance(solid, Solid):
            raise InvalidGeometryError(f"occluder must be a primitive or a CSG tree, got {type(solid).__name__}")
        return compile_program(solid).evaluate(lambda _, p: [_leaf_halfspaces(p, self.resolution)], self.combine)

    def combine(self, op: int, parts: list[list[HalfSpaces]]) -> list[HalfSpaces]:
        if op == OP_UNION:
            return [p for c in parts for p in c]
        cur = parts[0]
        if op == OP_INTERSECTION:
            for other in parts[1:]:
                nxt = []
                for p in cur:
                    for q in other:
                        hs = (np.vstack([p[0], q[0]]), np.concatenate([p[1], q[1]]))
                        if self.nonempty(hs):
                            nxt.append(hs)
                cur = nxt
            return cur
        for other in parts[1:]:
            for q in other:
                cur = [r for p in cur for r in self.subtract(p, q)]
        return cur

    def subtract(self, p: HalfSpaces, q: HalfSpaces) -> list[HalfSpaces]:
        both = (np.vstack([p[0], q[0]]), np.concatenate([p[1], q[1]]))
        if not self.nonempty(both):
            return [p]
        out = []
        pa, pb = list(p[0]), list(p[1])
        for n, d in zip(*q):
            hs = (np.vstack(pa + [-n]), np.array(pb + [-d]))  # outside face j ...
            if self.nonempty(hs):
                out.append(hs)
            pa.append(n)  # ... and inside the faces before it
            pb.append(d)
        return out


def halfspace_pieces(solid: Solid, *, resolution: int = DEFAULT_RESOLUTION) -> list[HalfSpaces]:
    """Convex pieces of one solid as half-space sets ``(normals, offsets)`` (``n . x <= d``).

    Examples
    --------
    >>> from isocsg import Box
    >>> len(halfspace_pieces(Box((0, 0, 0), (2, 2, 2)) - Box((1, 1, 1), (1, 1, 1))))
    3
    """
    b = solid.bounds
    scale = float(np.max(b[1] - b[0]))
    return _Decomposer(resolution, max(scale, 1e-300)).pieces(solid)


@functools.lru_cache(maxsize=256)
def _pieces_cached(solid: Solid, resolution: int) -> tuple[ConvexPiece, ...]:
    from scipy.spatial import HalfspaceIntersection

    if isinstance(solid, (Box, ConvexPolyhedron)):
        return (ConvexPiece.from_polyhedron(solid.to_polyhedron()),)
    if isinstance(solid, Primitive):
        return (ConvexPiece.from_polyhedron(solid.to_polyhedron(resolution)),)
    out = []
    for hs in halfspace_pieces(solid, resolution=resolution):
        centre, _ = _chebyshev(hs)
        inter = HalfspaceIntersection(np.column_stack([hs[0], -hs[1]]), centre)
        try:
            poly = ConvexPolyhedron(inter.intersections)
        except InvalidGeometryError:  # flat piece: it casts no shadow
            continue
        out.append(ConvexPiece.from_polyhedron(poly))
    return tuple(out)


def convex_pieces(occluders: Sequence[Solid] | Solid, *, resolution: int = DEFAULT_RESOLUTION) -> list[ConvexPiece]:
    """Decompose occluders (primitives or CSG trees) into convex pieces.

    Parameters
    ----------
    occluders : Solid or sequence of Solid
        Primitives (``Box``, ``ConvexPolyhedron`` exact; ``Sphere``, ``Truncus``,
        ``Cylinder``, ``Cone`` tessellated) and CSG trees over them.
    resolution : int, default 64
        Tessellation resolution of curved primitives (``to_polyhedron``).

    Returns
    -------
    list of ConvexPiece

    Raises
    ------
    InvalidGeometryError
        If an occluder is not a solid.
    InvalidParameterError
        If ``resolution`` is not an integer >= 3.

    Examples
    --------
    >>> from isocsg import Box, Sphere
    >>> pieces = convex_pieces([Box((0, 0, 0), (1, 1, 1)) | Sphere((3, 0, 0), 1)], resolution=16)
    >>> len(pieces)
    2
    """
    if isinstance(resolution, bool) or not isinstance(resolution, (int, np.integer)) or resolution < 3:
        raise InvalidParameterError(f"resolution must be an integer >= 3, got {resolution!r}")
    if isinstance(occluders, Solid):
        occluders = [occluders]
    try:
        seq = list(occluders)
    except TypeError:
        raise InvalidGeometryError(f"occluders must be a sequence of solids, got {type(occluders).__name__}") from None
    out: list[ConvexPiece] = []
    for i, o in enumerate(seq):
        if not isinstance(o, Solid):
            raise InvalidGeometryError(f"occluders[{i}] must be a primitive or a CSG tree, got {type(o).__name__}")
        out.extend(_pieces_cached(o, int(resolution)))
    return out
