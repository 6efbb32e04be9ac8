"""Signed distance from points to the boundary of a primitive or CSG tree, with a certified bound.

For a leaf, the kind's :meth:`~isocsg.kinds.base.Primitive.signed_distance` (exact for spheres,
boxes and trunci; for a convex polyhedron exact inside and a lower bound outside).

For a tree, the CSG combination of the leaves' values (``min`` for a union, ``max`` for an
intersection, ``max(a, -b)`` for a difference) has the right sign and never exceeds the true
distance in magnitude: it is a *lower bound* ``|f| <= d``. It is exact wherever the leaf that
attains it has its nearest surface point on the result's boundary, and not elsewhere (inside a
union near where two operands overlap, outside an intersection near its edges). So each point
also gets an *upper bound*: the attaining leaf's nearest surface point ``q = p - f grad f`` is
(and in trees of up to 16 leaves every leaf's) checked to lie on the result's boundary (by the same classification as
:mod:`isocsg.testing.area`), and then ``d <= |p - q|``. Where the two bounds agree (to 1e-9 of
the scene's size) the distance is certified exact; elsewhere the true value lies between them
(the upper bound is ``inf`` when the projection is not on the boundary).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import points_array
from ..csg.program import OP_DIFFERENCE, OP_INTERSECTION, OP_UNION
from ..csg.section import solid_program
from ..errors import InvalidParameterError
from ..kinds import Solid
from .area import _Tree

__all__ = ["DistanceResult", "signed_distance"]

F64 = NDArray[np.float64]
#: Up to this many leaves every leaf's nearest point is tried for the upper bound.
SMALL_TREE = 16


@dataclass(frozen=True, slots=True, eq=False)
class DistanceResult:
    """Signed distances of points to a solid's boundary (negative inside).

    Attributes
    ----------
    value : ndarray, shape (n,)
        The CSG combination: right sign, ``|value| <= `` the true distance.
    upper : ndarray, shape (n,)
        A certified upper bound of the true unsigned distance (``inf`` where none was found).
    exact : ndarray of bool, shape (n,)
        Where ``|value|`` equals the true distance (the bounds agree).
    """

    value: F64
    upper: F64
    exact: NDArray[np.bool_]

    @property
    def lower(self) -> F64:
        """The certified lower bound of the unsigned distance, ``|value|``."""
        return np.abs(self.value)


def _combine(op: int, xs: list[tuple[F64, NDArray[np.int64]]]) -> tuple[F64, NDArray[np.int64]]:
    vals = np.stack([x[0] for x in xs])
    ids = np.stack([x[1] for x in xs])
    if op == OP_DIFFERENCE:
        vals = np.concatenate([vals[:1], -vals[1:]])
    if op == OP_UNION:
        k = np.argmin(vals, axis=0)
    elif op in (OP_INTERSECTION, OP_DIFFERENCE):
        k = np.argmax(vals, axis=0)
    else:  # pragma: no cover
        raise ValueError(op)
    cols = np.arange(vals.shape[1])
    return vals[k, cols], ids[k, cols]


def signed_distance(solid: Solid, points: ArrayLike) -> DistanceResult:
    """Signed distance with certified bounds (see the module docstring).

    Parameters
    ----------
    solid : Solid
    points : array_like, shape (n, 3)

    Returns
    -------
    DistanceResult

    Raises
    ------
    InvalidParameterError
        On malformed points (the message names ``points``).

    Examples
    --------
    >>> from isocsg import Sphere
    >>> r = signed_distance(Sphere((0, 0, 0), 1) | Sphere((3, 0, 0), 1), [[0, 0, 0], [1.5, 0, 0]])
    >>> r.value.tolist(), r.exact.tolist()
    ([-1.0, 0.5], [True, True])
    """
    p = points_array("points", points, error=InvalidParameterError)
    prog = solid_program(solid)
    n = len(p)
    if prog.n_leaves == 0 or n == 0:
        return DistanceResult(np.full(n, np.inf), np.full(n, np.inf), np.zeros(n, bool))
    tree = _Tree(prog)
    value, leaf = prog.evaluate(
        lambda i, prim: (np.asarray(prim.signed_distance(p), dtype=np.float64), np.full(n, i, np.int64)), _combine,
    )
    # upper bounds: the nearest surface point of each leaf (of the attaining leaf only in large
    # trees), kept where it lies on the result's boundary
    upper = np.full(n, np.inf)
    every = np.arange(prog.n_leaves)
    for i in (every if prog.n_leaves <= SMALL_TREE else np.unique(leaf)).tolist():
        sel = np.arange(n) if prog.n_leaves <= SMALL_TREE else np.flatnonzero(leaf == i)
        prim = prog.leaves[i]
        f = np.asarray(prim.signed_distance(p[sel]), dtype=np.float64)
        g = tree.normals(i, p[sel])
        q = p[sel] - f[:, None] * g
        on_leaf = np.abs(np.asarray(prim.signed_distance(q))) <= 1e3 * tree.tol
        bound, _ = tree.classify(i, every[every != i], q, tree.normals(i, q), owner=False)
        ok = on_leaf & bound
        upper[sel[ok]] = np.minimum(upper[sel[ok]], np.linalg.norm(p[sel[ok]] - q[ok], axis=1))
    exact = np.abs(upper - np.abs(value)) <= 100 * tree.tol
    return DistanceResult(value, np.maximum(upper, np.abs(value)), exact)
