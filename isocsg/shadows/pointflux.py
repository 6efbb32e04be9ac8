"""Exact flux of an isotropic point source onto planar convex polygons (closed-form solid angles).

An isotropic point source of intensity I at P sends ``I Omega`` lumens onto a
polygon that it sees whole, ``Omega`` the polygon's solid angle from P. The
radiosity solve uses it for the mean direct illuminance of a patch,
``I Omega / A``, where nothing can stand between the source and the patch:
exact, where Gauss points on the patch would carry the quadrature error of
the ``cos / r^2`` integrand (largest for a source close to a patch).

The solid angle of a convex polygon q_0 .. q_{m-1} is the sum over its fan
triangles (q_0, q_k, q_{k+1}) of Van Oosterom and Strackee's formula
(IEEE Trans. Biomed. Eng. 30, 1983)::

    tan(Omega_t / 2) = a . (c x b) / (|a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|)

with a, b, c the vertices relative to P, taken through ``atan2`` so that no
quadrant is lost. The fan triangles of a convex polygon share one
orientation, so their signed angles add up; the sign says which side of the
polygon P lies on.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = ["signed_solid_angles"]


def signed_solid_angles(apex: NDArray[np.float64], verts: NDArray[np.float64],
                        off: NDArray[np.int64]) -> NDArray[np.float64]:
    """Signed solid angle of each convex polygon seen from ``apex``.

    Parameters
    ----------
    apex : ndarray, shape (3,)
    verts : ndarray, shape (v, 3)
        The polygons' vertices, polygon k being ``verts[off[k]:off[k + 1]]``.
    off : ndarray of int, shape (n + 1,)

    Returns
    -------
    ndarray, shape (n,)
        Positive when ``apex`` lies on the side of the polygon's normal
        (counter-clockwise vertices about it), negative behind; ``|Omega| <= 2 pi``.

    Examples
    --------
    A unit square seen from 0.5 above its centre covers a sixth of the sphere:

    >>> sq = np.array([[-0.5, -0.5, 0], [0.5, -0.5, 0], [0.5, 0.5, 0], [-0.5, 0.5, 0]])
    >>> om = signed_solid_angles(np.array([0, 0, 0.5]), sq, np.array([0, 4]))
    >>> bool(np.isclose(om[0], 4 * np.pi / 6, rtol=1e-14))
    True
    """
    counts = np.diff(off)
    ntri = np.maximum(counts - 2, 0)
    owner = np.repeat(np.arange(len(counts)), ntri)
    first = off[:-1][owner]
    k = np.arange(int(ntri.sum())) - np.repeat(np.cumsum(ntri) - ntri, ntri) + 1
    a = verts[first] - apex
    b = verts[first + k] - apex
    c = verts[first + k + 1] - apex
    la, lb, lc = (np.linalg.norm(x, axis=1) for x in (a, b, c))
    num = np.einsum("ij,ij->i", a, np.cross(c, b))  # > 0 with apex on the normal's side
    den = (la * lb * lc + np.einsum("ij,ij->i", a, b) * lc + np.einsum("ij,ij->i", a, c) * lb
           + np.einsum("ij,ij->i", b, c) * la)
    return np.asarray(np.bincount(owner, weights=2.0 * np.arctan2(num, den), minlength=len(counts)), dtype=np.float64)
