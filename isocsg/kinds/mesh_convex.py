"""An exact convex decomposition of a closed triangle mesh: the inside cells of a BSP tree.

Shadow occluders are unions of convex pieces (:mod:`~isocsg.shadows.occluders`). A
non-convex :class:`~isocsg.kinds.mesh.TriangleMesh` is cut into such pieces by a binary
space partition whose splitting planes are the mesh's own face planes (an *autopartition*):
starting from the mesh's bounding box, a cell holding pieces of faces is split by the plane
of one of them; face pieces in that plane lie on the cut and leave the cell, the others go to
the side they lie on (a piece crossing the plane is clipped in two). A cell that holds no
face piece is wholly inside or wholly outside the mesh (no part of the surface passes
through it), decided by the mesh's own membership at the cell's Chebyshev centre. The inside
cells are convex, their interiors are disjoint, and their union is the solid exactly (to
rounding): no tessellation is involved.

Each split removes at least the splitting face's piece, so the partition ends. Its size
depends on the mesh: a few cells for a machined part, more for a finely tessellated curved
mesh; :data:`MAX_DECOMPOSITION_FACES` and :data:`MAX_DECOMPOSITION_CELLS` bound the work and
raise :class:`~isocsg.errors.InvalidParameterError` past them. The splitting plane of a cell
is the candidate (among a few of its face pieces) that cuts the fewest other pieces.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidParameterError

__all__ = ["convex_cells", "MAX_DECOMPOSITION_FACES", "MAX_DECOMPOSITION_CELLS"]

#: The most faces a non-convex mesh may have to be decomposed (a shadow occluder).
MAX_DECOMPOSITION_FACES = 20_000
#: The most cells the partition may visit before it gives up.
MAX_DECOMPOSITION_CELLS = 100_000
_CANDIDATES = 8  # splitting planes tried per cell


_Polys = tuple[NDArray[np.float64], NDArray[np.int64]]  # all vertices, and where each polygon starts (+ end)


def _polys(blocks: list[NDArray[np.float64]]) -> _Polys:
    """Polygons as one vertex array and their start offsets."""
    if not blocks:
        return np.zeros((0, 3)), np.zeros(1, dtype=np.int64)
    sizes = np.array([len(b) for b in blocks], dtype=np.int64)
    return np.concatenate(blocks), np.concatenate([[0], np.cumsum(sizes)]).astype(np.int64)


def _signed(polys: _Polys, nrm: NDArray[np.float64], off: float, eps: float,
            ) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Each vertex's signed distance to a plane (0 within ``eps``), and each polygon's min and max."""
    P, st = polys
    s = P @ nrm - off
    s[np.abs(s) <= eps] = 0.0
    return s, np.minimum.reduceat(s, st[:-1]), np.maximum.reduceat(s, st[:-1])


def _clip(poly: NDArray[np.float64], s: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The parts of a convex polygon with ``s <= 0`` and ``s >= 0`` (``s`` its vertices' signed distances)."""
    neg: list[NDArray[np.float64]] = []
    pos: list[NDArray[np.float64]] = []
    n = len(poly)
    for i in range(n):
        p, q, sp, sq = poly[i], poly[(i + 1) % n], s[i], s[(i + 1) % n]
        if sp <= 0:
            neg.append(p)
        if sp >= 0:
            pos.append(p)
        if (sp < 0 < sq) or (sq < 0 < sp):
            x = p + (q - p) * (sp / (sp - sq))
            neg.append(x)
            pos.append(x)
    return np.array(neg), np.array(pos)


class _Sides(NamedTuple):
    """Polygons sorted to the two sides of a plane, which polygon each came from, and the points on the plane."""

    neg: list[NDArray[np.float64]]
    pos: list[NDArray[np.float64]]
    neg_from: NDArray[np.int64]
    pos_from: NDArray[np.int64]
    on: list[NDArray[np.float64]]


def _divide(polys: _Polys, nrm: NDArray[np.float64], off: float, eps: float) -> _Sides:
    """Polygons sorted to the two sides of a plane (those crossing it clipped in two; those in it dropped)."""
    P, st = polys
    s, lo, hi = _signed(polys, nrm, off, eps)
    flat = (lo == 0) & (hi == 0)
    cross = np.nonzero((lo < 0) & (hi > 0))[0]
    neg_i = np.nonzero((hi <= 0) & ~flat)[0]
    pos_i = np.nonzero((lo >= 0) & ~flat)[0]
    neg = [P[st[i]:st[i + 1]] for i in neg_i]
    pos = [P[st[i]:st[i + 1]] for i in pos_i]
    on = [P[s == 0]]
    for i in cross:
        a, c = _clip(P[st[i]:st[i + 1]], s[st[i]:st[i + 1]])
        neg.append(a)
        pos.append(c)
        on.append(a[np.abs(a @ nrm - off) <= eps])
    return _Sides(neg, pos, np.concatenate([neg_i, cross]), np.concatenate([pos_i, cross]), on)


def _split_choice(frags: _Polys, owner: NDArray[np.int64], planes: NDArray[np.float64], eps: float) -> int:
    """The face (a row of ``planes``) whose plane crosses the fewest of the cell's face pieces, among a few
    candidates."""
    k = len(owner)
    best: tuple[int, int] | None = None
    for f in owner[np.unique(np.linspace(0, k - 1, min(k, _CANDIDATES)).astype(np.int64))]:
        _, lo, hi = _signed(frags, planes[f, :3], planes[f, 3], eps)
        crossings = int(np.count_nonzero((lo < 0) & (hi > 0)))
        if best is None or crossings < best[0]:
            best = (crossings, int(f))
            if crossings == 0:
                break
    assert best is not None
    return best[1]


def _cap(points: NDArray[np.float64], nrm: NDArray[np.float64], eps: float) -> NDArray[np.float64] | None:
    """The convex polygon of the points where a cut plane meets a cell's faces, ordered around it."""
    if len(points) < 3:
        return None
    u = np.cross(nrm, [1.0, 0.0, 0.0] if abs(nrm[0]) < 0.9 else [0.0, 1.0, 0.0])
    u /= np.linalg.norm(u)
    v = np.cross(nrm, u)
    uv = np.c_[points @ u, points @ v]
    c = uv.mean(axis=0)
    order = np.argsort(np.arctan2(uv[:, 1] - c[1], uv[:, 0] - c[0]))
    P, uv = points[order], uv[order]
    # Each point where the plane cuts a cell edge comes twice (once from each face): keep one.
    far = np.linalg.norm(uv - np.roll(uv, 1, axis=0), axis=1) > eps
    if not far.any():
        return None
    P = P[far]
    return P if len(P) >= 3 else None


def _box_cell(lo: NDArray[np.float64], hi: NDArray[np.float64]) -> list[NDArray[np.float64]]:
    """The six faces of an axis-aligned box."""
    c = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
    quads = [(0, 1, 3, 2), (4, 5, 7, 6), (0, 1, 5, 4), (2, 3, 7, 6), (0, 2, 6, 4), (1, 3, 7, 5)]
    return [c[list(q)] for q in quads]


def convex_cells(
    vertices: NDArray[np.float64], faces: NDArray[np.int64],
    inside: Callable[[NDArray[np.float64]], NDArray[np.bool_]],
) -> list[NDArray[np.float64]]:
    """The vertices of convex cells whose union is the closed mesh's solid.

    Parameters
    ----------
    vertices, faces : ndarray
        A closed, consistently oriented triangle mesh (as :class:`~isocsg.kinds.mesh.TriangleMesh` holds).
    inside : callable
        The mesh's membership of ``(k, 3)`` points (called once, on one point of each empty cell).

    Returns
    -------
    list of ndarray
        One ``(p, 3)`` vertex array per inside cell.

    Raises
    ------
    InvalidParameterError
        If the mesh has more than :data:`MAX_DECOMPOSITION_FACES` faces (``TriangleMesh.faces``) or the
        partition passes :data:`MAX_DECOMPOSITION_CELLS` cells.
    """
    if len(faces) > MAX_DECOMPOSITION_FACES:
        raise InvalidParameterError(
            f"TriangleMesh.faces: a non-convex mesh of {len(faces)} faces is too large to decompose into "
            f"convex shadow occluders (at most {MAX_DECOMPOSITION_FACES})")
    lo, hi = vertices.min(axis=0), vertices.max(axis=0)
    size = float(np.linalg.norm(hi - lo))
    eps = 1e-10 * size
    margin = 0.01 * size
    tri = vertices[faces]
    nrm = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    nrm /= np.linalg.norm(nrm, axis=1)[:, None]
    planes = np.c_[nrm, np.einsum("ij,ij->i", nrm, tri.mean(axis=1))]
    start = (tri.reshape(-1, 3), np.arange(0, 3 * len(faces) + 1, 3, dtype=np.int64))
    stack: list[tuple[_Polys, _Polys, NDArray[np.int64]]] = [
        (_polys(_box_cell(lo - margin, hi + margin)), start, np.arange(len(faces), dtype=np.int64))]
    empty: list[NDArray[np.float64]] = []
    visited = 0
    while stack:  # iterative: the partition can be deep
        cell, frags, owner = stack.pop()
        visited += 1
        if visited > MAX_DECOMPOSITION_CELLS:
            raise InvalidParameterError(
                f"TriangleMesh.faces: the convex decomposition passed {MAX_DECOMPOSITION_CELLS} cells; "
                "the mesh is too finely curved to be a shadow occluder (simplify it or model it from convex kinds)")
        if not len(owner):
            empty.append(cell[0])
            continue
        f = _split_choice(frags, owner, planes, eps)
        n, off = planes[f, :3], float(planes[f, 3])
        pieces = _divide(frags, n, off, eps)
        side = cell[0] @ n - off
        if side.max() <= eps or side.min() >= -eps:  # the plane only touches the cell: nothing to cut
            stack.append((cell, _polys(pieces.neg + pieces.pos),
                          owner[np.concatenate([pieces.neg_from, pieces.pos_from])]))
            continue
        walls = _divide(cell, n, off, eps)
        cap = _cap(np.concatenate(walls.on), n, eps)
        if cap is not None:
            walls.neg.append(cap)
            walls.pos.append(cap)
        stack.append((_polys(walls.neg), _polys(pieces.neg), owner[pieces.neg_from]))
        stack.append((_polys(walls.pos), _polys(pieces.pos), owner[pieces.pos_from]))
    if not empty:
        return []
    centres = np.array([c.mean(axis=0) for c in empty])
    return [c for c, is_in in zip(empty, inside(centres)) if is_in]
