"""Exact forms: what a kind is, as plain data the generic algorithms above read.

A kind's :meth:`~isocsg.kinds.base.Primitive.exact_form` says which of these shapes it is
exactly, so that OpenSCAD's ``projection`` (:mod:`isocsg.shapes2d.projection`) and exact hulls
and Minkowski sums (:mod:`isocsg.csg.hull`) work from the data, not from the kind's class. Forms
are shapes, not kinds: a sphere and an ellipsoid are both an :class:`AffineBall`, every truncus
and elliptic truncus an :class:`AffineFrustum`, a box and a convex polyhedron a
:class:`PointHull`. A kind that is none of them returns None (the algorithms then use its own
members, such as ``section``, or say that the answer is not exact).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = ["AffineBall", "AffineFrustum", "ExactForm", "PointHull", "RingTorus", "TriangleSurface", "frustum_is_prism"]


@dataclass(frozen=True, eq=False)
class PointHull:
    """A convex polytope: the hull of ``vertices`` (n, 3), whose edges are the vertex pairs ``edges`` (m, 2)."""

    vertices: NDArray[np.float64]
    edges: NDArray[np.int64]


@dataclass(frozen=True, eq=False)
class AffineBall:
    """The points ``center + linear @ u`` with ``|u| <= 1``.

    Attributes
    ----------
    center : ndarray, shape (3,)
    linear : ndarray, shape (3, 3)
    radius : float or None
        The radius when the ball is a round one held as such (a sphere: ``linear`` is
        ``radius * I``), else None.
    """

    center: NDArray[np.float64]
    linear: NDArray[np.float64]
    radius: float | None = None


@dataclass(frozen=True, eq=False)
class AffineFrustum:
    """The points ``center + matrix @ (x, y, t)`` with ``t`` in [-1/2, 1/2] and
    ``|(x, y)| <= r2 + (r1 - r2) (t + 1/2)``: the end of radius ``r1`` is at ``t = 1/2``.

    Attributes
    ----------
    center : ndarray, shape (3,)
    matrix : ndarray, shape (3, 3)
        Its third column is the axis (from the ``r2`` end's centre to the ``r1`` end's).
    r1, r2 : float
    normal : ndarray, shape (3,)
        The unit normal of the end discs' planes (towards the ``r1`` end).
    right : bool
        Whether the end discs are circles perpendicular to the axis (a right circular truncus:
        the first two columns of ``matrix`` orthonormal and perpendicular to the axis).
    """

    center: NDArray[np.float64]
    matrix: NDArray[np.float64]
    r1: float
    r2: float
    normal: NDArray[np.float64]
    right: bool


@dataclass(frozen=True, eq=False)
class RingTorus:
    """The points within ``minor`` of the circle of radius ``major`` about ``center`` in the plane
    perpendicular to the unit ``axis``."""

    center: NDArray[np.float64]
    axis: NDArray[np.float64]
    major: float
    minor: float


@dataclass(frozen=True, eq=False)
class TriangleSurface:
    """A closed, consistently oriented triangle mesh: ``vertices`` (n, 3) and ``faces`` (m, 3)."""

    vertices: NDArray[np.float64]
    faces: NDArray[np.int64]


ExactForm = PointHull | AffineBall | AffineFrustum | RingTorus | TriangleSurface


def frustum_is_prism(form: AffineFrustum, direction: NDArray[np.float64], tol: float) -> bool:
    """Whether the frustum is a right prism along the unit ``direction``: equal end radii, the axis
    along ``direction`` and the ends across it (to ``tol`` of its size)."""
    M = form.matrix
    size = float(np.abs(M).max())
    across = np.abs(direction @ M[:, :2])
    off_axis = np.abs(M[:, 2] - direction * float(direction @ M[:, 2]))
    return bool(form.r1 == form.r2 and np.all(across <= tol * size) and np.all(off_axis <= tol * size))
