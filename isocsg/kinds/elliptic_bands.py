"""The band surface of an elliptic truncus (the affine image of a truncus).

As for the ellipsoid, its isoluminance curves are not planar: the bands come
from a mesh with its vertices on the surface and the exact normals
(``matrix^-T`` of the canonical truncus's normals), fine enough that every
field is followed within a quarter of a band step
(:func:`~isocsg.bands.surface.curvature_spacing`), cut along the families'
level lines. Parts: the side (0) and the ends E1 (1) and E2 (2), which share
no vertex. Towards a zero-radius end (a cone's apex) the rings are graded as
for the truncus (consecutive radii shrinking by at most 0.6, down to 1 %).
"""

from __future__ import annotations

from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from ..bands.surface import Surface, curvature_spacing, mixed_spacing, orient_outward, pieces

__all__ = ["EllipticFrustum", "elliptic_surface"]

#: Generators at least and at most; rings along the axis and on the ends at most.
MIN_GENERATORS = 128
MAX_GENERATORS = 1024
MAX_RINGS = 256
_SAMPLES = 129


class EllipticFrustum(Protocol):
    """What the elliptic truncus's bands read of it (:class:`~isocsg.kinds.EllipticTruncus`)."""

    @property
    def center_array(self) -> NDArray[np.float64]: ...

    @property
    def linear(self) -> NDArray[np.float64]: ...

    @property
    def r1(self) -> float: ...

    @property
    def r2(self) -> float: ...


def _world(
    e: EllipticFrustum, y: NDArray[np.float64], m: NDArray[np.float64],
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Canonical points and normals -> points relative to the centre and unit world normals."""
    M = e.linear
    pts = y @ M.T
    n = np.asarray(np.linalg.solve(M.T, m.reshape(-1, 3).T).T.reshape(m.shape), dtype=np.float64)
    n /= np.maximum(np.linalg.norm(n, axis=-1, keepdims=True), 1e-300)
    return pts, n


def _side(
    e: EllipticFrustum, z: NDArray[np.float64], phi: NDArray[np.float64],
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    k = e.r1 - e.r2  # canonical height 1
    r = e.r2 + k * (z + 0.5)
    c, s = np.cos(phi), np.sin(phi)
    y = np.stack([r[:, None] * c[None], r[:, None] * s[None], np.broadcast_to(z[:, None], (len(z), len(phi)))], axis=-1)
    m = np.stack([np.broadcast_to(c, y.shape[:2]), np.broadcast_to(s, y.shape[:2]), np.full(y.shape[:2], -k)], axis=-1)
    return _world(e, y, m)


def _grid_triangles(n_rows: int, n_cols: int, start: int) -> NDArray[np.int64]:
    """Triangles of a grid of rows closed around (columns wrap)."""
    j = np.arange(n_cols)
    jn = (j + 1) % n_cols
    a = start + n_cols * np.arange(n_rows - 1)[:, None]
    b = a + n_cols
    lower = np.stack([a + j, b + j, b + jn], axis=-1)
    upper = np.stack([a + j, b + jn, a + jn], axis=-1)
    return np.stack([lower, upper], axis=1).reshape(-1, 3)


def elliptic_surface(
    e: EllipticFrustum, lights: list, contours: int, eye: NDArray[np.float64] | None, shininess: float,
    weights: tuple[float, float] = (1.0, 1.0), segments: int | None = None,
) -> Surface:
    """Side and end meshes of an elliptic truncus, fine enough for every field.

    Parameters
    ----------
    e : EllipticFrustum
    lights : list of PointLight or DirectionalLight
    contours : int
    eye : ndarray, shape (3,), or None
        Relative to the centre.
    shininess : float
    weights : (float, float)
        The material's ``(kd, ks)``, as every kind's surface hook receives them (unused here).
    segments : int, optional
        A renderer's tessellation hint for a leaf small on screen (unused here: the mesh
        is refined by its fields).

    Returns
    -------
    Surface
        Relative to the centre; parts 0 (side), 1 (E1), 2 (E2).
    """
    origin = e.center_array
    # how the fields bend around (rings), along the generators and across the ends
    phi_s = np.linspace(0.0, 2.0 * np.pi, 2 * _SAMPLES)
    z_s = np.linspace(-0.5, 0.5, _SAMPLES)
    h_phi = h_z = h_end = np.inf
    if lights:
        pr, nr = _side(e, np.array([-0.45, -0.25, 0.0, 0.25, 0.45]), phi_s)
        h_phi = curvature_spacing(pr, nr, lights, origin, contours, step=phi_s[1], eye=eye, shininess=shininess)
        pg, ng = _side(e, z_s, 2.0 * np.pi * np.arange(16) / 16)
        h_z = curvature_spacing(pg.transpose(1, 0, 2), ng.transpose(1, 0, 2), lights, origin, contours,
                                step=z_s[1] - z_s[0], eye=eye, shininess=shininess)
        rr = np.linspace(0.0, 1.0, _SAMPLES)
        for zc, r, sgn in ((0.5, e.r1, 1.0), (-0.5, e.r2, -1.0)):
            if r <= 0:
                continue
            ang = 2.0 * np.pi * np.arange(8) / 8
            y = np.stack([r * rr[None] * np.cos(ang)[:, None], r * rr[None] * np.sin(ang)[:, None],
                          np.full((8, _SAMPLES), zc)], axis=-1)
            pe, ne = _world(e, y, np.broadcast_to([0.0, 0.0, sgn], y.shape).copy())
            h_end = min(h_end, curvature_spacing(pe, ne, lights, origin, contours, step=rr[1],
                                                 eye=eye, shininess=shininess))
    n_phi = int(np.clip(pieces(2.0 * np.pi, h_phi, cap=MAX_GENERATORS), MIN_GENERATORS, MAX_GENERATORS))
    if lights:
        # the mixed term of the cells between generators (see mixed_spacing), on a grid at the final n_phi
        zg = np.linspace(-0.5, 0.5, 33)
        phig = 2.0 * np.pi * np.arange(n_phi + 1) / n_phi
        pg, ng = _side(e, zg, phig)
        h_z = min(h_z, mixed_spacing(pg, ng, lights, origin, contours, zg[1] - zg[0], phig[1],
                                     eye=eye, shininess=shininess))
        for zc, r, sgn in ((0.5, e.r1, 1.0), (-0.5, e.r2, -1.0)):
            if r <= 0:
                continue
            rg = np.linspace(0.0, 1.0, 33)
            y = np.stack([r * rg[:, None] * np.cos(phig)[None], r * rg[:, None] * np.sin(phig)[None],
                          np.full((33, len(phig)), zc)], axis=-1)
            pe, ne = _world(e, y, np.broadcast_to([0.0, 0.0, sgn], y.shape).copy())
            h_end = min(h_end, mixed_spacing(pe, ne, lights, origin, contours, rg[1], phig[1],
                                             eye=eye, shininess=shininess))
    n_z = pieces(1.0, h_z, cap=MAX_RINGS)
    n_end = max(pieces(1.0, h_end, cap=MAX_RINGS), 8)
    zs = list(np.linspace(-0.5, 0.5, n_z + 1))
    # graded rings towards a zero-radius end
    for zc, r, step in ((0.5, e.r1, -1.0), (-0.5, e.r2, 1.0)):
        if r == 0.0:
            frac = 1.0 / n_z
            while frac > 0.01:
                frac *= 0.6
                zs.append(zc + step * frac)
    z = np.unique(np.clip(np.array(zs), -0.5, 0.5))
    phi = 2.0 * np.pi * np.arange(n_phi) / n_phi
    sv, sn = _side(e, z, phi)
    verts = [sv.reshape(-1, 3)]
    norms = [sn.reshape(-1, 3)]
    tris = [_grid_triangles(len(z), n_phi, 0)]
    parts = [np.zeros(len(z) * n_phi, np.int64)]
    count = len(z) * n_phi
    for part, (zc, r, sgn) in enumerate(((0.5, e.r1, 1.0), (-0.5, e.r2, -1.0)), start=1):
        if r <= 0:
            continue
        rad = r * np.arange(1, n_end + 1) / n_end  # rings out to the rim, the centre separately
        y = np.stack([rad[:, None] * np.cos(phi)[None], rad[:, None] * np.sin(phi)[None],
                      np.full((n_end, n_phi), zc)], axis=-1)
        y = np.vstack([[[0.0, 0.0, zc]], y.reshape(-1, 3)])
        pe, ne = _world(e, y, np.broadcast_to([0.0, 0.0, sgn], y.shape).copy())
        j = np.arange(n_phi)
        fan = np.stack([np.full(n_phi, count), count + 1 + j, count + 1 + (j + 1) % n_phi], axis=1)
        tris += [fan, _grid_triangles(n_end, n_phi, count + 1)]
        verts.append(pe)
        norms.append(ne)
        parts.append(np.full(len(y), part, np.int64))
        count += len(y)
    vertices = np.vstack(verts)
    normals = np.vstack(norms)
    triangles = np.vstack(tris).astype(np.int64)
    return Surface(vertices, normals, orient_outward(vertices, normals, triangles), origin.copy(),
                   np.concatenate(parts))
