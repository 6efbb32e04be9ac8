"""Isoluminance laminae of boxes and convex polyhedra: one lamina per face.

Under a directional light every face is one isoluminance contour with the
exact intensity of its normal. A point light's incidence varies across a
face; the band mesh then subdivides each face (more finely for nearer
lights) so that the face is cut along its exact level lines.
"""

from __future__ import annotations

from typing import Any, Protocol

import numpy as np
from numpy.typing import NDArray

from ..bands.lights import Light, is_directional
from ..bands.surface import (
    Surface,
    curvature_spacing,
    eye_reference_distance,
    light_reference_distance,
    orient_outward,
    pieces,
    refinement,
    specular_refinement,
)

__all__ = ["Faceted", "face_laminae", "polyhedron_surface"]

class Faceted(Protocol):
    """What a polyhedral kind's bands read of it (:class:`~isocsg.kinds.Box`,
    :class:`~isocsg.kinds.ConvexPolyhedron`)."""

    @property
    def bounds(self) -> NDArray[np.float64]: ...

    def local_faces(self) -> tuple[NDArray[np.float64], list[NDArray[np.float64]]]: ...


def _faces(
    poly: Faceted,
) -> tuple[NDArray[np.float64], list[tuple[NDArray[np.float64], NDArray[np.float64]]]]:
    """The kind's local origin and its faces relative to it (counter-clockwise from outside) with
    their unit outward normals (``local_faces`` of a polyhedral kind)."""
    origin, polys = poly.local_faces()
    normals: list[Any] = [None] * len(polys)
    by_size: dict[int, list[int]] = {}
    for i, f in enumerate(polys):
        by_size.setdefault(len(f), []).append(i)
    for which in by_size.values():  # faces of one vertex count at once (the same sums, in the same order)
        # Newell's normal of the counter-clockwise (outward) face, about the face's own centroid.
        f = np.stack([polys[i] for i in which])
        g = f - f.mean(axis=1, keepdims=True)
        h = np.concatenate([g[:, 1:], g[:, :1]], axis=1)
        n = np.stack([g[..., 1] * h[..., 2] - g[..., 2] * h[..., 1], g[..., 2] * h[..., 0] - g[..., 0] * h[..., 2],
                      g[..., 0] * h[..., 1] - g[..., 1] * h[..., 0]], axis=-1).sum(axis=1)
        for i, ni in zip(which, n):
            normals[i] = ni / np.linalg.norm(ni)
    return origin, list(zip(polys, normals))


def face_laminae(
    poly: Faceted, light: Light,
) -> list[tuple[NDArray[np.float64], NDArray[np.float64], float]]:
    """One lamina per face: (vertices, outward normal, incidence cosine at the face centroid)."""
    out = []
    origin, faces = _faces(poly)
    for f, n in faces:
        centroid = f.mean(axis=0)
        if is_directional(light):
            ln = light.unit_direction
        else:
            d = (np.asarray(light.position) - origin) - centroid
            ln = d / max(float(np.linalg.norm(d)), 1e-300)
        out.append((origin + f, n, float(n @ ln)))
    return out


def _subdivided_triangle(
    a: NDArray[np.float64], b: NDArray[np.float64], c: NDArray[np.float64], s: int,
) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Barycentric grid of ``s * s`` triangles; points on an edge depend on that edge's ends only."""
    idx: dict[tuple[int, int], int] = {}
    pts: list[Any] = []
    for i in range(s + 1):
        for j in range(s + 1 - i):
            k = s - i - j
            idx[i, j] = len(pts)
            pts.append((i / s) * a + (j / s) * b + (k / s) * c)
    tris = []
    for i in range(s):
        for j in range(s - i):
            tris.append((idx[i, j], idx[i + 1, j], idx[i, j + 1]))
            if j + i + 1 < s:
                tris.append((idx[i + 1, j], idx[i + 1, j + 1], idx[i, j + 1]))
    return np.array(pts), np.array(tris, dtype=np.int64)


def polyhedron_surface(
    poly: Faceted,
    lights: list[Light],
    contours: int = 64,
    *,
    eye: NDArray[np.float64] | None = None,
    shininess: float = 1.0,
    weights: tuple[float, float] = (1.0, 1.0),
) -> Surface:
    """Faces as fans of triangles relative to the centre, subdivided for point lights and highlights.

    A near point light turns the incidence across a face, and a specular
    material seen from ``eye`` (relative to the centre) makes the Phong term
    vary across it: both need subdivisions
    (:func:`~isocsg.bands.surface.refinement`,
    :func:`~isocsg.bands.surface.specular_refinement`). Each face is a part.
    """
    origin, faces = _faces(poly)
    lo, hi = poly.bounds
    size = 0.5 * float(np.linalg.norm(hi - lo))
    dist = light_reference_distance(lights, 0.5 * (lo + hi), size)
    d_eye = eye_reference_distance(eye, np.zeros(3), size)
    # Under lights at infinity and without a highlight a face's field is one number: no sampling.
    bending = eye is not None or not all(is_directional(light) for light in lights)
    verts, norms, tris, parts = [], [], [], []
    count = 0
    for face, (f, n) in enumerate(faces):
        diam = float(np.max(np.linalg.norm(f - f.mean(axis=0), axis=1))) * 2.0
        s = max(refinement(diam, dist, cap=16), specular_refinement(diam, d_eye, shininess, contours))
        if lights and bending:
            # Sample lines from the centroid to each corner and along each edge: the fields' bending there.
            g = f.mean(axis=0)
            t = np.linspace(0.0, 1.0, 17)[None, :, None]
            spokes = g + t * (f - g)[:, None, :]
            edges = f[:, None, :] + t * (np.roll(f, -1, axis=0) - f)[:, None, :]
            lines = np.concatenate([spokes, edges])
            spacing = curvature_spacing(lines, np.broadcast_to(n, lines.shape), lights, origin, contours,
                                        eye=eye, shininess=shininess, weights=weights)
            s = max(s, pieces(diam, spacing))
        if s == 1:
            fv = f
            ft = np.stack([np.zeros(len(f) - 2, np.int64), np.arange(1, len(f) - 1), np.arange(2, len(f))], axis=1)
        else:
            fan = [_subdivided_triangle(f[0], f[i], f[i + 1], s) for i in range(1, len(f) - 1)]
            allp = np.vstack([p for p, _ in fan])
            offs = np.cumsum([0] + [len(p) for p, _ in fan[:-1]])
            allt = np.vstack([t + o for (_, t), o in zip(fan, offs)])
            # Points shared by neighbouring fan triangles are bitwise equal: merge them.
            fv, inv = np.unique(allp, axis=0, return_inverse=True)
            ft = inv.reshape(-1)[allt]
        verts.append(fv)
        norms.append(np.tile(n, (len(fv), 1)))
        tris.append(ft + count)
        parts.append(np.full(len(fv), face, np.int64))
        count += len(fv)
    vertices = np.vstack(verts)
    normals = np.vstack(norms)
    triangles = orient_outward(vertices, normals, np.vstack(tris).astype(np.int64))
    return Surface(vertices, normals, triangles, origin, np.concatenate(parts))
