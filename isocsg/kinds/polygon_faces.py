"""Polygon faces (lists of point indices) as numpy arrays: fans, signed volume, triangulation.

Generated models hand OpenSCAD polyhedra of tens of thousands of faces; these walks are whole-array
numpy operations, one per face size, where a loop over faces took a numpy call per face
(``loxodrome_concat.scad``: 24 000 faces, 30 s in the loops).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = ["fan_triangles", "signed_volume", "triangulate_faces"]


def _flat(faces: list[list[int]]) -> tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.int64]]:
    """The faces' indices end to end, each face's length and its start in that array."""
    lengths = np.fromiter((len(f) for f in faces), dtype=np.int64, count=len(faces))
    flat = np.fromiter((i for f in faces for i in f), dtype=np.int64, count=int(lengths.sum()))
    starts = np.concatenate([[0], np.cumsum(lengths)[:-1]]).astype(np.int64)
    return flat, lengths, starts


def fan_triangles(faces: list[list[int]]) -> NDArray[np.int64]:
    """Each face of at least 3 indices as the fan ``(f[0], f[i], f[i + 1])``, shape ``(m, 3)``, in
    the faces' order. A fan's signed area vector is the planar polygon's, convex or not, so the
    fans of closed faces give the enclosed volume."""
    if not faces:
        return np.zeros((0, 3), dtype=np.int64)
    flat, lengths, starts = _flat(faces)
    count = np.maximum(lengths - 2, 0)
    total = int(count.sum())
    if total == 0:
        return np.zeros((0, 3), dtype=np.int64)
    face = np.repeat(np.arange(len(faces)), count)
    k = 1 + np.arange(total) - np.repeat(np.cumsum(count) - count, count)
    s = starts[face]
    return np.stack([flat[s], flat[s + k], flat[s + k + 1]], axis=1)


def signed_volume(points: NDArray[np.float64], faces: list[list[int]]) -> float:
    """The volume the faces enclose (positive when they wind counter-clockwise seen from outside),
    about ``points[0]``: no cancellation for a solid far from the origin."""
    T = fan_triangles(faces)
    if len(T) == 0:
        return 0.0
    p = points - points[0]
    a, b, c = p[T[:, 0]], p[T[:, 1]], p[T[:, 2]]
    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum()) / 6.0


def _plane_rings(q: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """Polygons ``q`` of shape (F, L, 3) in their own planes, counter-clockwise about Newell's normal
    of their order: (F, L, 2), and which have an area at all."""
    g = q - q.mean(axis=1, keepdims=True)
    n = np.cross(g, np.roll(g, -1, axis=1)).sum(axis=1)
    norm = np.linalg.norm(n, axis=1)
    ok = norm > 0
    n = n / np.where(ok, norm, 1.0)[:, None]
    ref = np.where((np.abs(n[:, 0]) < 0.9)[:, None], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
    u = np.cross(n, ref)
    u /= np.maximum(np.linalg.norm(u, axis=1), 1e-300)[:, None]
    v = np.cross(n, u)
    return np.stack([np.einsum("flk,fk->fl", g, u), np.einsum("flk,fk->fl", g, v)], axis=-1), ok


def _strictly_convex(ring: NDArray[np.float64]) -> NDArray[np.bool_]:
    """Rings (F, L, 2) that turn left at every corner by more than rounding and once around in all
    (not a star such as a pentagram): a fan covers them once."""
    e = np.roll(ring, -1, axis=1) - ring
    f = np.roll(e, -1, axis=1)
    turn = e[..., 0] * f[..., 1] - e[..., 1] * f[..., 0]
    size = np.abs(ring).max(axis=(1, 2))
    left = np.all(turn > 1e-12 * size[:, None] ** 2, axis=1)
    once = np.arctan2(turn, np.einsum("flk,flk->fl", e, f)).sum(axis=1) < 3 * np.pi
    return left & once  # type: ignore[no-any-return]


def triangulate_faces(points: NDArray[np.float64], faces: list[list[int]]) -> NDArray[np.int64]:
    """Planar polygon faces as triangles of their own points, each in the face's winding: triangles
    as they are, strictly convex faces as fans, the others through manifold3d's triangulation in the
    face's plane. A point repeated in turn is taken once; faces left with fewer than 3 distinct
    points, or flat to a line, are dropped (no area)."""
    import manifold3d

    by_length: dict[int, list[list[int]]] = {}
    for f in faces:
        f = [k for i, k in enumerate(f) if k != f[i - 1]]  # a point repeated in turn adds no side
        if len(set(f)) >= 3:
            by_length.setdefault(len(f), []).append(f)
    out: list[NDArray[np.int64]] = []
    for length, group in sorted(by_length.items()):
        F = np.asarray(group, dtype=np.int64)
        if length == 3:
            out.append(F)
            continue
        ring, has_area = _plane_rings(points[F])
        fan = has_area & _strictly_convex(ring)
        k = np.arange(1, length - 1)
        fans = F[fan]
        out.append(np.stack([np.repeat(fans[:, 0], length - 2), fans[:, k].reshape(-1),
                             fans[:, k + 1].reshape(-1)], axis=1))
        for i in np.flatnonzero(has_area & ~fan):
            local = np.asarray(manifold3d.triangulate([ring[i]]), dtype=np.int64).reshape(-1, 3)
            out.append(F[i][local])
    return np.concatenate(out) if out else np.zeros((0, 3), dtype=np.int64)
