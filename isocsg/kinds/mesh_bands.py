"""The band surface of a triangle mesh: its own faces, each flat with its face normal.

Every face is one plane with one outward normal, so under a directional light (and without
a highlight) each face has one luminance per light and the band surface is the mesh itself,
its triangles unshared (each with the exact normal of its face). A point light or a Phong
highlight varies across a face; then every face is split into ``s x s`` similar triangles
(a barycentric grid, :func:`subdivided`) with ``s`` chosen per face as the convex polyhedron
does (the rules of :func:`~isocsg.bands.surface.refinement` from the nearest light's distance
and :func:`~isocsg.bands.surface.specular_refinement` from the eye's), vectorised over faces of
equal ``s``. The families then cut these triangles along their exact level lines: each face at its
own levels (its exact value when constant) up to :data:`MAX_FACE_PARTS` faces, the whole mesh at
common levels beyond (bands of N steps over the mesh's range: the isoluminance approximation).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..bands.surface import Surface, orient_outward

__all__ = ["mesh_surface", "subdivided", "MAX_SPLIT", "MAX_FACE_PARTS"]

#: The most pieces an edge of a face is split into for a point light or a highlight.
MAX_SPLIT = 16

#: Meshes of at most this many faces make each face its own part (cut at its own levels, so a face
#: of constant luminance shows its exact value, as a convex polyhedron's faces do); larger meshes
#: are one part, cut at levels spread over the whole mesh's range (the band machinery loops over
#: parts in Python: one part per face of a 100k-face mesh would take a minute).
MAX_FACE_PARTS = 4096


def _template(s: int) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Barycentric weights ``(P, 3)`` of the grid points and its ``s * s`` triangles."""
    w: list[tuple[float, float, float]] = []
    idx: dict[tuple[int, int], int] = {}
    for i in range(s + 1):
        for j in range(s + 1 - i):
            idx[i, j] = len(w)
            w.append((i / s, j / s, (s - i - j) / s))
    tris = []
    for i in range(s):
        for j in range(s - i):
            tris.append((idx[i, j], idx[i + 1, j], idx[i, j + 1]))
            if i + j + 1 < s:
                tris.append((idx[i + 1, j], idx[i + 1, j + 1], idx[i, j + 1]))
    return np.array(w), np.array(tris, np.int64)


def subdivided(corners: NDArray[np.float64], s: int) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Triangles ``corners (m, 3, 3)`` each split into ``s * s``: points ``(m, P, 3)`` and the
    template's triangles ``(s * s, 3)`` (indices into one face's points)."""
    w, tris = _template(s)
    # written so that the corners come out bit for bit (weight 1 on one corner, 0 elsewhere)
    pts = np.einsum("pk,mkj->mpj", w, corners)
    return pts, tris


def mesh_surface(
    mesh: Any, lights: list[Any], contours: int, eye: NDArray[np.float64] | None, shininess: float,
    weights: tuple[float, float] = (1.0, 1.0),
) -> Any:
    """The mesh's base surface for its bands (see the module docstring), relative to the centre
    of its bounds; each face is its own part (``parts`` holds the face index)."""
    lo, hi = mesh.bounds
    origin = 0.5 * (lo + hi)
    size = 0.5 * float(np.linalg.norm(hi - lo))
    V = mesh.vertex_array - origin
    corners = V[mesh.face_array]  # (m, 3, 3)
    normals = mesh.face_normals
    diam = np.max(np.linalg.norm(corners - np.roll(corners, 1, axis=1), axis=2), axis=1)
    # the reference distances of isocsg.bands.surface, vectorised over faces:
    # the nearest point light's gap to the bounding sphere and the eye's, each at least 5 % of its radius
    dist = min((max(float(np.linalg.norm(np.asarray(light.position) - origin)) - size, 0.05 * size)
                for light in lights if getattr(light, "position", None) is not None), default=np.inf)
    d_eye = np.inf if eye is None else max(float(np.linalg.norm(np.asarray(eye, np.float64))) - size, 0.05 * size)
    split = np.ones(len(corners), np.int64)
    if np.isfinite(dist):
        split = np.clip(np.ceil(16.0 * diam / dist), 1, MAX_SPLIT).astype(np.int64)
    if np.isfinite(d_eye) and weights[1] > 0:
        # specular_refinement's rule, per face: h <= d sqrt(2 / (s N))
        h = d_eye * np.sqrt(2.0 / (max(shininess, 1.0) * min(contours, 256)))
        split = np.maximum(split, np.clip(np.ceil(diam / h), 1, MAX_SPLIT).astype(np.int64))
    verts, norms, tris, parts = [], [], [], []
    count = 0
    for s in np.unique(split).tolist():
        faces = np.nonzero(split == s)[0]
        pts, tmpl = subdivided(corners[faces], int(s))
        per = pts.shape[1]
        verts.append(pts.reshape(-1, 3))
        norms.append(np.repeat(normals[faces], per, axis=0))
        base = count + per * np.arange(len(faces), dtype=np.int64)
        tris.append((base[:, None, None] + tmpl[None, :, :]).reshape(-1, 3))
        parts.append(np.repeat(faces.astype(np.int64), per) if len(corners) <= MAX_FACE_PARTS
                     else np.zeros(per * len(faces), np.int64))
        count += per * len(faces)
    vertices = np.vstack(verts)
    vnormals = np.vstack(norms)
    return Surface(vertices, vnormals, orient_outward(vertices, vnormals, np.vstack(tris)), origin,
                   np.concatenate(parts))
