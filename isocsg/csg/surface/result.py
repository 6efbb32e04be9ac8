"""The clipped surface as a value: :class:`CSGSurface`, and its assembly from pieces."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ...errors import InvalidParameterError
from ...laminae.model import BandMesh


@dataclass(frozen=True, slots=True, eq=False)
class CSGSurface:
    """The boundary of a CSG solid: triangles of constant value, each on one leaf.

    Triangles are kept sorted by leaf (stably: construction sorts them if
    needed), so that :meth:`leaf_bands` finds a leaf's part without a pass
    over the whole surface.

    Attributes
    ----------
    vertices : ndarray, shape (V, 3), float64
    triangles : ndarray, shape (T, 3), int32
        Counter-clockwise seen from outside the result.
    value : ndarray, shape (T,), float64
        The value each triangle shows: its band's ``value_out``, or
        ``value_in`` where the triangle is reversed.
    leaf : ndarray, shape (T,), int32
        Index of the leaf (in ``CSGNode.program()`` order) it lies on; non-decreasing.
    source : ndarray, shape (T,), int32
        Index of the leaf's band triangle it lies in.
    reversed : ndarray, shape (T,), bool
        True where the result's outward normal is the leaf's inward normal.
    """

    vertices: NDArray[np.float64]
    triangles: NDArray[np.int32]
    value: NDArray[np.float64]
    leaf: NDArray[np.int32]
    source: NDArray[np.int32]
    reversed: NDArray[np.bool_]

    def __post_init__(self) -> None:
        leaf = np.asarray(self.leaf)
        if len(leaf) > 1 and bool(np.any(leaf[1:] < leaf[:-1])):
            order = np.argsort(leaf, kind="stable")
            for name in ("triangles", "value", "leaf", "source", "reversed"):
                object.__setattr__(self, name, np.asarray(getattr(self, name))[order])

    @property
    def n_triangles(self) -> int:
        """Number of triangles."""
        return int(len(self.triangles))

    def leaf_bands(self, i: int) -> BandMesh:
        """The part on leaf ``i`` as a :class:`BandMesh` (both values set to the shown value).

        Only the vertices the part uses are kept (renumbered), so the parts of
        a surface of many leaves cost in total what the surface does.
        """
        # Same dtype as the leaf array: otherwise numpy converts all of it on every call.
        lo, hi = np.searchsorted(self.leaf, np.array([i, i + 1], dtype=self.leaf.dtype))
        tri = self.triangles[lo:hi]
        if not len(tri):
            return BandMesh(np.zeros((0, 3)), np.zeros((0, 3), np.int32), np.zeros(0), np.zeros(0),
                            np.zeros(0, np.int32))
        first, last = int(tri.min()), int(tri.max())
        local: NDArray[np.signedinteger[Any]]
        if last - first < 8 * len(tri):
            # A leaf's vertices are mostly contiguous: renumber through a mask of the range.
            mark = np.zeros(last - first + 1, bool)
            mark[tri - first] = True
            used = np.flatnonzero(mark) + first
            local = (np.cumsum(mark, dtype=np.int32) - 1)[tri - first]
        else:
            used, local = np.unique(tri, return_inverse=True)
        shown = self.value[lo:hi]
        return BandMesh(self.vertices[used], local.reshape(-1, 3).astype(np.int32), shown, shown, self.source[lo:hi])


def assemble(pieces: list[tuple[Any, ...]]) -> CSGSurface:
    """One surface from its pieces (vertices, triangles, leaf, source, reversed, value), filled in
    place; each piece is let go once copied (``pieces`` is left holding empty tuples)."""
    if not pieces:
        return empty_surface()
    nv = np.cumsum([0] + [len(p[0]) for p in pieces])
    nt = np.cumsum([0] + [len(p[1]) for p in pieces])
    if nv[-1] >= 2**31:
        raise InvalidParameterError(f"the clipped CSG surface has {nv[-1]} vertices, more than 2**31 - 1")
    verts = np.empty((nv[-1], 3))
    tris = np.empty((nt[-1], 3), np.int32)
    leaf = np.empty(nt[-1], np.int32)
    source = np.empty(nt[-1], np.int32)
    rev = np.empty(nt[-1], bool)
    value = np.empty(nt[-1])
    for k in range(len(pieces)):
        p = pieces[k]
        pieces[k] = ()  # each piece goes once copied (the list is the caller's, and goes next)
        a, b = nt[k], nt[k + 1]
        verts[nv[k] : nv[k + 1]] = p[0]
        np.add(p[1], nv[k], out=tris[a:b], casting="unsafe")
        leaf[a:b], source[a:b], rev[a:b], value[a:b] = p[2], p[3], p[4], p[5]
        del p
    return CSGSurface(verts, tris, value, leaf, source, rev)


def empty_surface() -> CSGSurface:
    return CSGSurface(
        np.zeros((0, 3)), np.zeros((0, 3), np.int32), np.zeros(0), np.zeros(0, np.int32), np.zeros(0, np.int32),
        np.zeros(0, bool),
    )


def triangle_normals(v: NDArray[np.float64], t: NDArray[np.int64]) -> NDArray[np.float64]:
    if not len(t):
        return np.zeros((0, 3))
    return np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
