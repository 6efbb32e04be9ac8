"""Compiled triangle fill: nearest and farthest surface per pixel.

Triangles are given in world space and projected by a :class:`~isocsg.camera.Camera`
to homogeneous screen coordinates ``(X, Y, W, D)`` that are affine in the world
point: ``col = X / W``, ``row = Y / W`` and ``D`` is the camera depth (distance
along the forward axis). For the pinhole camera ``W = D``; for the orthographic
camera ``W = 1``. Because all four are affine, triangles are clipped against the
near plane ``D >= near`` *before* the division (nothing is dropped, nothing
wraps around behind the eye). The depth buffers hold a *depth key* that is
linear in screen space and grows with depth, ``-1 / D`` for the pinhole camera
and ``D`` for the orthographic one, so interpolating it across a triangle
gives the perspective-correct depth.

Coverage follows the top-left rule of scanline fill (a pixel centre belongs
to a triangle when ``y_top <= row < y_bottom`` and ``x_left <= col < x_right``
on its row) with each edge's crossing of a row computed from its ends in a
canonical order, so two triangles that share an edge split every row at the
same column: a pixel centre on the shared edge belongs to exactly one of them,
and none is missed. Pixel ``(i, j)`` (row, column) has its centre at
``(col, row) = (j + 0.5, i + 0.5)``.

Front-facing triangles (counter-clockwise seen from the eye, i.e. outward
normals towards the eye) write the *front* buffers with a nearest-depth test
and their ``value_out``; back-facing triangles write the *back* buffers with a
farthest-depth test and their ``value_in``. For a closed convex mesh this is
exactly the entry and exit of each pixel's ray.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numba import njit
from numpy.typing import ArrayLike, NDArray

from ..camera import Camera
from ..errors import InvalidGeometryError, InvalidParameterError
from ..geometry.halfedges import sorted_half_edges

__all__ = ["Raster", "rasterize", "homogeneous", "near_distance", "camera_affine", "pair_quads"]

# Relative near-plane distance: surfaces closer to the eye than this fraction of
# the scene's depth range are clipped away (the ray caster's ``t > 0``).
NEAR_RELATIVE = 1e-9


# Options of the per-polygon kernels. They are compiled without numba's
# reference counting (``_nrt=False``): with it, every array handed to a helper
# or sliced into a row view costs two atomic operations per polygon, which
# was most of the cost of a small polygon (4x the set-up itself). These
# kernels allocate nothing; their thin entry points do.
_RAW = {"cache": True, "nogil": True, "_nrt": False}
# Constant flags are passed to these kernels as ``np.bool_(...)`` and
# ``np.int64(...)``: a bare ``True`` or ``-1`` is typed as a literal, and numba
# compiles one specialisation per literal value (the fill kernels four times
# over, most of a new install's first-render compile time).


def homogeneous(camera: Camera, points: ArrayLike) -> NDArray[np.float64]:
    """Homogeneous screen coordinates of world points.

    Parameters
    ----------
    camera : Camera
    points : array_like, shape (n, 3)

    Returns
    -------
    ndarray, shape (4, n)
        Rows ``X, Y, W, D`` with ``col = X / W``, ``row = Y / W`` (continuous
        pixel coordinates as :meth:`Camera.project`) and ``D`` the depth along
        the view direction. All four are affine in the world point.

    Examples
    --------
    >>> cam = Camera((0, -5, 0), (0, 0, 0), width=4, height=4)
    >>> h = homogeneous(cam, [[0, 0, 0]])
    >>> (h[0] / h[2]).tolist(), (h[1] / h[2]).tolist(), h[3].tolist()
    ([2.0], [2.0], [5.0])
    """
    p = np.asarray(points, dtype=np.float64).reshape(-1, 3) - camera.eye_array
    f, r, u = camera.frame
    m = np.stack([r, u, f])  # camera-space rows
    xr, yu, z = m @ p.T
    w2, h2 = camera.width / 2.0, camera.height / 2.0
    out = np.empty((4, len(p)))
    if camera.orthographic:
        half_h = camera.height_m / 2
        out[0] = (xr / (half_h * camera.aspect) + 1.0) * w2
        out[1] = (1.0 - yu / half_h) * h2
        out[2] = 1.0
    else:
        t = camera.tan_half_fov
        out[0] = (xr / (t * camera.aspect) + z) * w2
        out[1] = (z - yu / t) * h2
        out[2] = z
    out[3] = z
    return out


def near_distance(depths: NDArray[np.float64]) -> float:
    """Near-plane depth for geometry with the given camera depths (tiny, > 0)."""
    scale = float(np.max(np.abs(depths))) if len(depths) else 1.0
    return NEAR_RELATIVE * max(scale, 1e-300)


# --------------------------------------------------------------------- kernels
@njit(**_RAW)
def _fill_triangle(
    x0: float, y0: float, x1: float, y1: float, x2: float, y2: float,
    k0: float, k1: float, k2: float,
    value: float, tag: int, front: bool,
    ox: int, oy: int, zbuf: NDArray[np.float64], vbuf: NDArray[np.float32], tbuf: NDArray[np.int32],
) -> None:
    """Scan-convert one triangle (screen coordinates) into the viewport buffers.

    Fill rule: a pixel centre ``(px, py)`` is inside when ``y_top <= py < y_bottom``
    and ``x_left <= px < x_right`` on its row (top-left rule). Each edge's
    crossing of a row is ``xa + (py - ya) * slope`` with ``a`` the edge's upper
    end and ``slope = (xb - xa) / (yb - ya)``: the two triangles that share the
    edge compute the same number, so rows are split between them exactly.
    ``k`` is the depth key at the vertices (linear in screen space).
    """
    # Sort the vertices by row (then column): v0 top, v2 bottom.
    if y1 < y0 or (y1 == y0 and x1 < x0):
        x0, y0, x1, y1 = x1, y1, x0, y0
        k0, k1 = k1, k0
    if y2 < y1 or (y2 == y1 and x2 < x1):
        x1, y1, x2, y2 = x2, y2, x1, y1
        k1, k2 = k2, k1
        if y1 < y0 or (y1 == y0 and x1 < x0):
            x0, y0, x1, y1 = x1, y1, x0, y0
            k0, k1 = k1, k0
    # Twice the signed area; its sign says on which side the long edge 0-2 lies.
    area = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0)
    if area == 0.0 or not math.isfinite(area):
        return
    h, w = zbuf.shape
    lo = max(float(oy) - 1.0, y0 - 0.5)
    hi = min(float(oy + h), y2 - 0.5)
    i_start = max(oy, int(math.ceil(lo)))
    i_end = min(oy + h, int(math.ceil(hi)))  # rows with py < y2
    if i_start >= i_end:
        return
    i_mid = int(math.ceil(min(max(lo, y1 - 0.5), hi)))  # first row with py >= y1
    long_left = area > 0.0  # the middle vertex lies right of edge 0-2
    s02 = (x2 - x0) / (y2 - y0)
    s01 = (x1 - x0) / (y1 - y0) if y1 > y0 else 0.0
    s12 = (x2 - x1) / (y2 - y1) if y2 > y1 else 0.0
    # Depth-key plane, anchored at the vertex of largest key (the farthest one,
    # never a near-clipped vertex with huge screen coordinates).
    gx = ((k1 - k0) * (y2 - y0) - (k2 - k0) * (y1 - y0)) / area
    gy = ((k2 - k0) * (x1 - x0) - (k1 - k0) * (x2 - x0)) / area
    if k0 >= k1 and k0 >= k2:
        ka, xa, ya = k0, x0, y0
    elif k1 >= k2:
        ka, xa, ya = k1, x1, y1
    else:
        ka, xa, ya = k2, x2, y2
    cmin = float(ox) - 1.0
    cmax = float(ox + w)
    for i in range(i_start, i_end):
        py = i + 0.5
        xe = x0 + (py - y0) * s02
        if i < i_mid:
            xm = x0 + (py - y0) * s01
        else:
            xm = x1 + (py - y1) * s12
        if long_left:
            xl, xr = xe, xm
        else:
            xl, xr = xm, xe
        # Pixels with xl <= j + 0.5 < xr (clamped first so that huge values stay exact).
        xl = min(max(xl, cmin), cmax)
        xr = min(max(xr, cmin), cmax)
        j0 = max(ox, int(math.ceil(xl - 0.5)))
        j1 = min(ox + w, int(math.ceil(xr - 0.5)))
        if j0 >= j1:
            continue
        q = ka + gx * (j0 + 0.5 - xa) + gy * (py - ya)
        row = i - oy
        if front and tag >= 0:
            for j in range(j0 - ox, j1 - ox):
                if q < zbuf[row, j]:
                    zbuf[row, j] = q
                    vbuf[row, j] = value
                    tbuf[row, j] = tag
                q += gx
        elif front:
            for j in range(j0 - ox, j1 - ox):
                if q < zbuf[row, j]:
                    zbuf[row, j] = q
                    vbuf[row, j] = value
                q += gx
        else:
            for j in range(j0 - ox, j1 - ox):
                if q > zbuf[row, j]:
                    zbuf[row, j] = q
                    vbuf[row, j] = value
                q += gx


@njit(cache=True, nogil=True)
def project_vertices(
    hx: NDArray[np.float64], hy: NDArray[np.float64], hw: NDArray[np.float64], hd: NDArray[np.float64],
    near: float, perspective: bool,
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    """Screen column, row and depth key of the vertices in front of the near plane."""
    nv = hx.shape[0]
    sx = np.empty(nv)
    sy = np.empty(nv)
    sk = np.empty(nv)
    for v in range(nv):
        if hd[v] >= near:
            inv = 1.0 / hw[v]
            sx[v] = hx[v] * inv
            sy[v] = hy[v] * inv
            sk[v] = -inv if perspective else hd[v]
    return sx, sy, sk


@njit(cache=True, nogil=True)
def fill_kernel(
    hx: NDArray[np.float64], hy: NDArray[np.float64], hw: NDArray[np.float64], hd: NDArray[np.float64],
    tris: NDArray[np.int32], vout: NDArray[np.float32], vin: NDArray[np.float32],
    near: float, perspective: bool, cull: bool, do_back: bool, tag: int, ox: int, oy: int,
    zf: NDArray[np.float64], vf: NDArray[np.float32], tf: NDArray[np.int32],
    zb: NDArray[np.float64], vb: NDArray[np.float32],
) -> None:
    """Fill triangles into front (and back) buffers; see the module docstring.

    The depth buffers hold a *depth key* that grows with depth and is linear in
    screen space: ``-1 / D`` for the pinhole camera, ``D`` for the orthographic
    one (see :func:`key_to_depth`). ``zf`` starts at +inf, ``zb`` at -inf;
    buffers cover the viewport whose top-left pixel is ``(oy, ox)``. With
    ``cull`` false every triangle goes to the front buffers (and, with
    ``do_back``, to the back ones too). ``tf`` receives ``tag`` wherever the
    front buffers are written (nothing with a negative ``tag``).
    """
    sx, sy, sk = project_vertices(hx, hy, hw, hd, near, perspective)
    _fill_all(hx, hy, hw, hd, sx, sy, sk, tris, vout, vin, near, perspective, cull, do_back, tag, ox, oy, zf, vf, tf, zb, vb,
              np.empty((3, 4)))


@njit(cache=True, nogil=True)
def fill_projected(
    proj: NDArray[np.float64], polys: NDArray[np.int32], vout: NDArray[np.float32], vin: NDArray[np.float32],
    near: float, perspective: bool, ox: int, oy: int,
    zf: NDArray[np.float64], vf: NDArray[np.float32], zb: NDArray[np.float64], vb: NDArray[np.float32],
) -> None:
    """Front and back buffers of convex polygons projected by :func:`project_kernel` (no labels).

    For the leaves of per-pixel CSG: each pixel's nearest front-facing and
    farthest back-facing surface, over the viewport whose top-left pixel is
    ``(oy, ox)``. ``polys`` (P, 4) are the quads of :func:`pair_quads` (the
    last index -1 for a triangle) with their values ``vout`` and ``vin``.
    A quad that projects strictly convex is filled with one span per row into
    the buffers of its facing; any other as its two triangles. The pixels and
    values are those of :func:`fill_kernel` with culling and back buffers on
    the quads' triangles.
    """
    # No labels and no written rectangle for leaves (both discarded).
    _fill_polys(proj, polys, vout, vin, near, perspective, np.bool_(True), np.int64(-1), ox, oy, zf, vf, np.empty((1, 1), np.int32),
                zb, vb, np.empty(4, np.int64), np.empty((3, 4)))


@njit(**_RAW)
def _fill_all(
    hx: NDArray[np.float64], hy: NDArray[np.float64], hw: NDArray[np.float64], hd: NDArray[np.float64],
    sx: NDArray[np.float64], sy: NDArray[np.float64], sk: NDArray[np.float64],
    tris: NDArray[np.int32], vout: NDArray[np.float32], vin: NDArray[np.float32],
    near: float, perspective: bool, cull: bool, do_back: bool, tag: int, ox: int, oy: int,
    zf: NDArray[np.float64], vf: NDArray[np.float32], tf: NDArray[np.int32],
    zb: NDArray[np.float64], vb: NDArray[np.float32], scratch: NDArray[np.float64],
) -> None:
    px, py, pk = scratch[0], scratch[1], scratch[2]  # (3, 4): a clipped triangle has up to 4 corners
    for t in range(tris.shape[0]):
        _fill_one(hx, hy, hw, hd, sx, sy, sk, tris[t, 0], tris[t, 1], tris[t, 2], near, perspective, cull, do_back,
                  vout[t], vin[t], tag, ox, oy, zf, vf, tf, zb, vb, px, py, pk)


@njit(**_RAW)
def _fill_one(
    hx: NDArray[np.float64], hy: NDArray[np.float64], hw: NDArray[np.float64], hd: NDArray[np.float64],
    sx: NDArray[np.float64], sy: NDArray[np.float64], sk: NDArray[np.float64],
    a: int, b: int, c: int, near: float, perspective: bool, cull: bool, do_back: bool,
    value_out: float, value_in: float, tag: int, ox: int, oy: int,
    zf: NDArray[np.float64], vf: NDArray[np.float32], tf: NDArray[np.int32],
    zb: NDArray[np.float64], vb: NDArray[np.float32],
    px: NDArray[np.float64], py: NDArray[np.float64], pk: NDArray[np.float64],
) -> None:
    """Clip one triangle against the near plane, decide its facing and fill it."""
    ina = hd[a] >= near
    inb = hd[b] >= near
    inc = hd[c] >= near
    if ina and inb and inc:
        n = 3
        px[0], py[0], pk[0] = sx[a], sy[a], sk[a]
        px[1], py[1], pk[1] = sx[b], sy[b], sk[b]
        px[2], py[2], pk[2] = sx[c], sy[c], sk[c]
    elif not (ina or inb or inc):
        return
    else:
        # Sutherland-Hodgman against D >= near, in homogeneous space.
        n = 0
        for k in range(3):
            if k == 0:
                p, q = a, b
            elif k == 1:
                p, q = b, c
            else:
                p, q = c, a
            if hd[p] >= near:
                px[n], py[n], pk[n] = sx[p], sy[p], sk[p]
                n += 1
            if (hd[p] >= near) != (hd[q] >= near):
                # Canonical order: the neighbour sharing this edge gets the same point.
                s0, s1 = (p, q) if p < q else (q, p)
                s = (near - hd[s0]) / (hd[s1] - hd[s0])
                inv = 1.0 / (hw[s0] + s * (hw[s1] - hw[s0]))
                px[n] = (hx[s0] + s * (hx[s1] - hx[s0])) * inv
                py[n] = (hy[s0] + s * (hy[s1] - hy[s0])) * inv
                pk[n] = -inv if perspective else near
                n += 1
    # Facing: screen rows grow downwards, so a triangle counter-clockwise
    # seen from the eye has a negative signed area in (col, row).
    s2 = 0.0
    for k in range(n):
        k1 = (k + 1) % n
        s2 += px[k] * py[k1] - px[k1] * py[k]
    is_front = s2 < 0.0
    to_front = is_front or not cull
    to_back = do_back and (not is_front or not cull)
    for k in range(1, n - 1):
        if to_front:
            _fill_triangle(
                px[0], py[0], px[k], py[k], px[k + 1], py[k + 1], pk[0], pk[k], pk[k + 1],
                value_out, tag, np.bool_(True), ox, oy, zf, vf, tf,
            )
        if to_back:
            _fill_triangle(
                px[0], py[0], px[k], py[k], px[k + 1], py[k + 1], pk[0], pk[k], pk[k + 1],
                value_in, tag, np.bool_(False), ox, oy, zb, vb, tf,
            )


@njit(cache=True)
def key_to_depth(key: NDArray[np.float64], perspective: bool, out: NDArray[np.float64]) -> None:
    """Camera depth from the depth key of :func:`fill_kernel` (inf stays inf)."""
    flat = key.ravel()
    o = out.ravel()
    for k in range(flat.shape[0]):
        q = flat[k]
        if not math.isfinite(q):
            o[k] = q if not perspective else (np.inf if q > 0 else -np.inf)
        elif perspective:
            o[k] = -1.0 / q
        else:
            o[k] = q


# ------------------------------------------------- front-surface polygon fill
def camera_affine(camera: Camera) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The affine map of :func:`homogeneous` as a matrix and an offset.

    Parameters
    ----------
    camera : Camera

    Returns
    -------
    a : ndarray, shape (4, 3)
    b : ndarray, shape (4,)
        ``(X, Y, W, D) = a @ (p - camera.eye) + b`` for a world point ``p``.

    Examples
    --------
    >>> cam = Camera((0, -5, 0), (0, 0, 0), width=4, height=4)
    >>> a, b = camera_affine(cam)
    >>> (a @ (np.array([0.0, 0.0, 0.0]) - cam.eye_array) + b).round(12).tolist()
    [10.0, 10.0, 5.0, 5.0]
    """
    # camera.frame in plain floats (numpy's cross on 3-vectors costs more than the projection).
    ex, ey, ez = (float(c) for c in camera.eye)
    tx, ty, tz = (float(c) for c in camera.target)
    ux, uy, uz = (float(c) for c in camera.up)
    fx, fy, fz = tx - ex, ty - ey, tz - ez
    n = math.sqrt(fx * fx + fy * fy + fz * fz)
    fx, fy, fz = fx / n, fy / n, fz / n
    rx, ry, rz = fy * uz - fz * uy, fz * ux - fx * uz, fx * uy - fy * ux
    n = math.sqrt(rx * rx + ry * ry + rz * rz)
    rx, ry, rz = rx / n, ry / n, rz / n
    f = np.array([fx, fy, fz])
    r = np.array([rx, ry, rz])
    u = np.array([ry * fz - rz * fy, rz * fx - rx * fz, rx * fy - ry * fx])
    w2, h2 = camera.width / 2.0, camera.height / 2.0
    a = np.zeros((4, 3))
    b = np.zeros(4)
    if camera.orthographic:
        half_h = camera.height_m / 2
        a[0] = r * (w2 / (half_h * camera.aspect))
        a[1] = -u * (h2 / half_h)
        b[:3] = w2, h2, 1.0
    else:
        t = camera.tan_half_fov
        a[0] = r * (w2 / (t * camera.aspect)) + f * w2
        a[1] = f * h2 - u * (h2 / t)
        a[2] = f
    a[3] = f
    return a, b


@njit(**_RAW)
def project_kernel(
    vertices: NDArray[np.float64], eye: NDArray[np.float64], a: NDArray[np.float64], b: NDArray[np.float64],
    perspective: bool, out: NDArray[np.float64], v0: int, v1: int,
) -> float:
    """Rows ``X, Y, W, D, col, row, key`` of ``out`` (7, V) for vertices ``v0 .. v1 - 1``; returns their ``max |D|``.

    ``col``, ``row`` and the depth key are meaningful only for vertices in
    front of the near plane (the fills never read the others).
    """
    far = 0.0
    # Locals: the stores to ``out`` might alias the matrix, which would be reloaded per vertex.
    ex, ey, ez = eye[0], eye[1], eye[2]
    a00, a01, a02, b0 = a[0, 0], a[0, 1], a[0, 2], b[0]
    a10, a11, a12, b1 = a[1, 0], a[1, 1], a[1, 2], b[1]
    a20, a21, a22, b2 = a[2, 0], a[2, 1], a[2, 2], b[2]
    a30, a31, a32, b3 = a[3, 0], a[3, 1], a[3, 2], b[3]
    for v in range(v0, v1):
        dx = vertices[v, 0] - ex
        dy = vertices[v, 1] - ey
        dz = vertices[v, 2] - ez
        x = a00 * dx + a01 * dy + a02 * dz + b0
        y = a10 * dx + a11 * dy + a12 * dz + b1
        w = a20 * dx + a21 * dy + a22 * dz + b2
        d = a30 * dx + a31 * dy + a32 * dz + b3
        out[0, v] = x
        out[1, v] = y
        out[2, v] = w
        out[3, v] = d
        inv = 1.0 / w if w != 0.0 else 0.0
        out[4, v] = x * inv
        out[5, v] = y * inv
        out[6, v] = -inv if perspective else d
        if abs(d) > far:
            far = abs(d)
    return far


#: Relative distance from the plane of a quad's first triangle within which its
#: fourth vertex counts as coplanar (the quad then shares one depth-key plane).
COPLANAR_RELATIVE = 1e-10


def camera_rays(camera: Camera) -> NDArray[np.float64]:
    """The camera as :func:`ball_covered` reads it: eye, forward, right, up, the view's
    half-width and half-height (at unit depth under perspective), and 1.0 for a perspective."""
    f, r, u = camera.frame
    if camera.orthographic:
        sy = camera.height_m / 2
    else:
        sy = camera.tan_half_fov
    return np.concatenate([camera.eye_array, f, r, u, [sy * camera.aspect, sy, 0.0 if camera.orthographic else 1.0]])


def pair_quads(
    vertices: ArrayLike, triangles: ArrayLike, value_out: ArrayLike, value_in: ArrayLike | None = None,
) -> tuple[NDArray[np.int32], NDArray[np.int32]]:
    """Pair triangles into planar convex quads for the one-span-per-row fill.

    Two triangles are paired when they share an edge (in opposite directions,
    as in a consistently oriented mesh) that no other triangle has, carry the
    same values, lie in one plane (within ``COPLANAR_RELATIVE`` of their size)
    and form a strictly convex quad. Edges are taken in increasing order of
    their (lower, higher) vertex pair, each pairing two triangles that are
    both still single. Band meshes are mostly such quads.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
    triangles : array_like of int, shape (T, 3)
    value_out : array_like, shape (T,)
    value_in : array_like, shape (T,), optional

    Returns
    -------
    quads : ndarray of int32, shape (P, 4)
        Counter-clockwise like the triangles; a quad ``(a, b, c, d)`` is the
        triangles ``(a, b, c)`` and ``(a, c, d)``; an unpaired triangle has
        ``d = -1``. In the order of each quad's first triangle in the mesh.
    source : ndarray of int32, shape (P,)
        A triangle of each quad (for its values).

    Examples
    --------
    >>> square = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    >>> quads, source = pair_quads(square, [(0, 1, 2), (0, 2, 3)], [0.5, 0.5])
    >>> quads.tolist(), source.tolist()
    ([[2, 3, 0, 1]], [0])
    """
    v = np.ascontiguousarray(vertices, dtype=np.float64).reshape(-1, 3)
    t = np.ascontiguousarray(triangles, dtype=np.int64).reshape(-1, 3)
    vo = np.ascontiguousarray(value_out, dtype=np.float64).reshape(-1)
    vi = vo if value_in is None else np.ascontiguousarray(value_in, dtype=np.float64).reshape(-1)
    if len(t) and (t.min() < 0 or t.max() >= len(v)):
        raise InvalidGeometryError("triangles: vertex indices out of range")
    for name, vals in (("value_out", vo), ("value_in", vi)):
        if len(vals) != len(t):
            raise InvalidParameterError(f"{name}: one value per triangle expected, got {len(vals)} for {len(t)}")
    quads, source, count = _pair_kernel(v, t, vo, vi, COPLANAR_RELATIVE)
    return quads[:count], source[:count]


@njit(cache=True, nogil=True)
def _pair_kernel(
    v: NDArray[np.float64], t: NDArray[np.int64], vo: NDArray[np.float64], vi: NDArray[np.float64], tol: float,
) -> tuple[NDArray[np.int32], NDArray[np.int32], int]:
    n_tri = t.shape[0]
    nv = v.shape[0]
    start, his, owner = sorted_half_edges(t, nv)  # edges in increasing (lower, higher) order
    partner = np.full(n_tri, -1, np.int64)
    corner = np.empty((n_tri, 4), np.int64)  # the quad, stored at its lower triangle
    for lo in range(nv):
        s0, s1 = start[lo], start[lo + 1]
        s = s0
        while s < s1:
            e = s + 1
            while e < s1 and his[e] == his[s]:
                e += 1
            if e - s == 2:  # an edge with exactly two half-edges
                h1, h2 = owner[s], owner[s + 1]
                ta, ja = h1 // 3, h1 % 3
                tb, jb = h2 // 3, h2 % 3
                p, q = t[ta, ja], t[ta, (ja + 1) % 3]
                if (
                    ta != tb and partner[ta] < 0 and partner[tb] < 0
                    and t[tb, jb] == q and t[tb, (jb + 1) % 3] == p
                    and vo[ta] == vo[tb] and vi[ta] == vi[tb]
                ):
                    r1, r2 = t[ta, (ja + 2) % 3], t[tb, (jb + 2) % 3]
                    if _planar_convex(v, p, r2, q, r1, tol):
                        partner[ta] = tb
                        partner[tb] = ta
                        m = min(ta, tb)
                        corner[m, 0], corner[m, 1], corner[m, 2], corner[m, 3] = p, r2, q, r1
            s = e
    quads = np.empty((n_tri, 4), np.int32)
    source = np.empty(n_tri, np.int32)
    count = 0
    for i in range(n_tri):
        if partner[i] < 0:
            quads[count, 0], quads[count, 1], quads[count, 2], quads[count, 3] = t[i, 0], t[i, 1], t[i, 2], -1
        elif partner[i] > i:
            for k in range(4):
                quads[count, k] = corner[i, k]
        else:
            continue
        source[count] = i
        count += 1
    return quads, source, count


@njit(cache=True, nogil=True, inline="always")
def _planar_convex(v: NDArray[np.float64], p: int, r2: int, q: int, r1: int, tol: float) -> bool:
    """The quad ``(p, r2, q, r1)``, the triangles ``(p, q, r1)`` and ``(q, p, r2)``, is planar and strictly convex."""
    nx = (v[q, 1] - v[p, 1]) * (v[r1, 2] - v[p, 2]) - (v[q, 2] - v[p, 2]) * (v[r1, 1] - v[p, 1])
    ny = (v[q, 2] - v[p, 2]) * (v[r1, 0] - v[p, 0]) - (v[q, 0] - v[p, 0]) * (v[r1, 2] - v[p, 2])
    nz = (v[q, 0] - v[p, 0]) * (v[r1, 1] - v[p, 1]) - (v[q, 1] - v[p, 1]) * (v[r1, 0] - v[p, 0])
    nlen = math.sqrt(nx * nx + ny * ny + nz * nz)
    if not nlen > 0.0:
        return False
    size = 0.0
    for o in (q, r1, r2):
        size = max(size, math.sqrt((v[o, 0] - v[p, 0]) ** 2 + (v[o, 1] - v[p, 1]) ** 2 + (v[o, 2] - v[p, 2]) ** 2))
    off = abs(nx * (v[r2, 0] - v[p, 0]) + ny * (v[r2, 1] - v[p, 1]) + nz * (v[r2, 2] - v[p, 2]))
    if not off <= tol * size * nlen:
        return False
    ring = (p, r2, q, r1)
    for k in range(4):
        c0, c1, c2 = ring[k], ring[(k + 1) % 4], ring[(k + 2) % 4]
        e0x, e0y, e0z = v[c1, 0] - v[c0, 0], v[c1, 1] - v[c0, 1], v[c1, 2] - v[c0, 2]
        e1x, e1y, e1z = v[c2, 0] - v[c1, 0], v[c2, 1] - v[c1, 1], v[c2, 2] - v[c1, 2]
        turn = (e0y * e1z - e0z * e1y) * nx + (e0z * e1x - e0x * e1z) * ny + (e0x * e1y - e0y * e1x) * nz
        if not turn > 0.0:
            return False
    return True


@njit(**_RAW)
def fill_rect(a: NDArray[Any], r0: int, r1: int, c0: int, c1: int, value: float) -> None:
    """``a[r0:r1, c0:c1] = value`` without the GIL (``a`` C-contiguous)."""
    flat = a.reshape(-1)  # contiguous row pieces: filled with wide stores
    w = a.shape[1]
    for i in range(r0, r1):
        flat[i * w + c0 : i * w + c1] = value


@njit(**_RAW)
def ball_covered(
    zbuf: NDArray[np.float64], r0: int, r1: int, c0: int, c1: int, key: float, near: float,
    ray: NDArray[np.float64], center: NDArray[np.float64], radius: float,
) -> bool:
    """Whether any surface inside the ball ``(center, radius)`` is hidden everywhere by what
    ``zbuf[r0:r1, c0:c1]`` already holds (occlusion culling).

    A pixel can be written only if its ray (through its centre, where the
    fills sample) meets the ball, and then no nearer than where the ray
    enters it; so the ball is hidden where every such pixel already holds a
    depth key below that entry's (``key``, the ball's nearest key, settles
    most pixels at once). A ray that enters the ball behind the near plane
    ``near`` (or inside it) is never hidden. A relative 1e-9 is added to the
    radius for rounding. ``ray`` is :func:`camera_rays`'s: the eye, the unit
    forward, right and up vectors, the half-width and half-height of the
    view (at unit depth under perspective) and whether it is a perspective.
    """
    ex, ey, ez = ray[0], ray[1], ray[2]
    fx, fy, fz, rx, ry, rz, ux, uy, uz = ray[3], ray[4], ray[5], ray[6], ray[7], ray[8], ray[9], ray[10], ray[11]
    sx, sy, persp = ray[12], ray[13], ray[14] > 0.0
    W, H = zbuf.shape[1], zbuf.shape[0]
    vx, vy, vz = center[0] - ex, center[1] - ey, center[2] - ez
    v2 = vx * vx + vy * vy + vz * vz
    reach = radius + 1e-9 * (radius + math.sqrt(v2))
    reach2 = reach * reach
    for i in range(r0, r1):
        y = sy * (1.0 - 2.0 * (i + 0.5) / H)
        for j in range(c0, c1):
            z = zbuf[i, j]
            if z < key:
                continue
            x = sx * (2.0 * (j + 0.5) / W - 1.0)
            if persp:  # points eye + s (f + x r + y u), at depth s
                dx, dy, dz = fx + x * rx + y * ux, fy + x * ry + y * uy, fz + x * rz + y * uz
                d2 = dx * dx + dy * dy + dz * dz
                vd = vx * dx + vy * dy + vz * dz
                disc = vd * vd - d2 * (v2 - reach2)
                if disc < 0.0:
                    continue  # the ray misses the ball
                s = (vd - math.sqrt(disc)) / d2
                if not (s > near and z < -1.0 / s):
                    return False
            else:  # points eye + x r + y u + s f, at depth s
                wx, wy, wz = vx - x * rx - y * ux, vy - x * ry - y * uy, vz - x * rz - y * uz
                t = wx * fx + wy * fy + wz * fz
                p2 = wx * wx + wy * wy + wz * wz - t * t
                if p2 > reach2:
                    continue
                s = t - math.sqrt(reach2 - p2)
                if not (s > near and z < s):
                    return False
    return True


# Inlined into its caller: a call passes seven arrays, each reference-counted.
@njit(**_RAW, error_model="numpy", inline="always")
def _fill_convex(
    px: NDArray[np.float64], py: NDArray[np.float64], pk: NDArray[np.float64], n: int,
    value: float, tag: int, ox: int, oy: int, clamp: bool, front: bool,
    zbuf: NDArray[np.float64], vbuf: NDArray[np.float32], tbuf: NDArray[np.int32], bounds: NDArray[np.int64],
) -> None:
    """Fill of a strictly convex polygon (3 or 4 vertices, negative signed area).

    One span per row between the polygon's left and right chains. Each edge's
    crossing of a row is computed exactly as in :func:`_fill_triangle` (from
    its upper end, with its own slope), so the result is the union of the
    fan triangles pixel for pixel, and neighbours sharing an edge split rows
    identically. The buffers cover the viewport whose top-left pixel is
    ``(oy, ox)``; ``front`` keeps the nearest key (and writes ``tag`` into
    ``tbuf`` unless it is negative), otherwise the farthest. ``clamp`` false
    promises that all columns lie in ``[ox, ox + width]`` (no clamping
    needed). ``bounds`` (row min, row max + 1, column min, column max + 1)
    grows to cover every pixel written.
    """
    h, w = zbuf.shape
    top = 0
    bot = 0
    for k in range(1, n):
        if py[k] < py[top] or (py[k] == py[top] and px[k] < px[top]):
            top = k
        if py[k] > py[bot] or (py[k] == py[bot] and px[k] > px[bot]):
            bot = k
    lo = max(float(oy) - 1.0, py[top] - 0.5)
    hi = min(float(oy + h), py[bot] - 0.5)
    i_start = max(oy, int(math.ceil(lo)))
    i_end = min(oy + h, int(math.ceil(hi)))
    if i_start >= i_end:
        return
    # Depth-key plane through vertices 0, t1, t1 + 1 (the fan triangle of larger
    # area: a corner's turn test and this area round differently, so one of
    # them may be exactly zero), anchored at the farthest of them.
    t1 = 1
    area = (px[1] - px[0]) * (py[2] - py[0]) - (py[1] - py[0]) * (px[2] - px[0])
    if n == 4:
        area3 = (px[2] - px[0]) * (py[3] - py[0]) - (py[2] - py[0]) * (px[3] - px[0])
        if abs(area3) > abs(area):
            t1 = 2
            area = area3
    if area == 0.0 or not math.isfinite(area):
        return  # no area in floating point: no pixel centre strictly inside
    t2 = t1 + 1
    gx = ((pk[t1] - pk[0]) * (py[t2] - py[0]) - (pk[t2] - pk[0]) * (py[t1] - py[0])) / area
    gy = ((pk[t2] - pk[0]) * (px[t1] - px[0]) - (pk[t1] - pk[0]) * (px[t2] - px[0])) / area
    an = 0
    if pk[t1] > pk[an]:
        an = t1
    if pk[t2] > pk[an]:
        an = t2
    ka, xa, ya = pk[an], px[an], py[an]
    # Left chain: increasing index from the top (negative area); right chain: decreasing.
    li = top
    ri = top
    ln = li + 1 if li + 1 < n else 0
    rn = ri - 1 if ri > 0 else n - 1
    l_thr = int(math.ceil(min(max(lo, py[ln] - 0.5), hi)))  # first row on the next left edge's successor
    r_thr = int(math.ceil(min(max(lo, py[rn] - 0.5), hi)))
    cmin = float(ox) - 1.0
    cmax = float(ox + w)
    value32 = np.float32(value)
    tag32 = np.int32(tag)
    # The written rectangle grows by the polygon's pixel box (cheaper than per row).
    xmin = px[0]
    xmax = px[0]
    for k in range(1, n):
        xmin = min(xmin, px[k])
        xmax = max(xmax, px[k])
    bounds[0] = min(bounds[0], i_start)
    bounds[1] = max(bounds[1], i_end)
    bounds[2] = min(bounds[2], max(ox, int(math.ceil(min(max(xmin, cmin), cmax) - 0.5))))
    bounds[3] = max(bounds[3], min(ox + w, int(math.ceil(min(max(xmax, cmin), cmax) - 0.5))))
    i = i_start
    while i < i_end:
        while i >= l_thr:
            li = ln
            ln = li + 1 if li + 1 < n else 0
            l_thr = int(math.ceil(min(max(lo, py[ln] - 0.5), hi))) if li != bot else i_end
        while i >= r_thr:
            ri = rn
            rn = ri - 1 if ri > 0 else n - 1
            r_thr = int(math.ceil(min(max(lo, py[rn] - 0.5), hi))) if ri != bot else i_end
        seg_end = min(i_end, l_thr, r_thr)
        lx, ly = px[li], py[li]
        rx, ry = px[ri], py[ri]
        ls = (px[ln] - lx) / (py[ln] - ly)
        rs = (px[rn] - rx) / (py[rn] - ry)
        for ii in range(i, seg_end):
            pyc = ii + 0.5
            xl = lx + (pyc - ly) * ls
            xr = rx + (pyc - ry) * rs
            if clamp:
                xl = min(max(xl, cmin), cmax)
                xr = min(max(xr, cmin), cmax)
                j0 = max(ox, int(math.ceil(xl - 0.5)))
                j1 = min(ox + w, int(math.ceil(xr - 0.5)))
            else:
                j0 = int(math.ceil(xl - 0.5))
                j1 = int(math.ceil(xr - 0.5))
            if j0 >= j1:
                continue
            row = ii - oy
            q = ka + gx * (j0 + 0.5 - xa) + gy * (pyc - ya)
            zr = zbuf[row]
            vr = vbuf[row]
            if front and tag32 >= 0:
                tr = tbuf[row]
                for j in range(j0 - ox, j1 - ox):
                    if q < zr[j]:
                        zr[j] = q
                        vr[j] = value32
                        tr[j] = tag32
                    q += gx
            elif front:
                for j in range(j0 - ox, j1 - ox):
                    if q < zr[j]:
                        zr[j] = q
                        vr[j] = value32
                    q += gx
            else:
                for j in range(j0 - ox, j1 - ox):
                    if q > zr[j]:
                        zr[j] = q
                        vr[j] = value32
                    q += gx
        i = seg_end


@njit(cache=True, nogil=True)
def fill_front_kernel(
    proj: NDArray[np.float64], polys: NDArray[np.int32], values: NDArray[np.float32],
    near: float, perspective: bool, tag: int, oy: int,
    zf: NDArray[np.float64], vf: NDArray[np.float32], tf: NDArray[np.int32], bounds: NDArray[np.int64],
) -> None:
    """Front faces of convex polygons into rows ``oy ..`` of the image buffers (depth-tested).

    ``proj`` is the output of :func:`project_kernel`; ``polys`` (P, 4) are
    the quads of :func:`pair_quads` (the last index -1 for a triangle). The
    buffers are full-width rows ``oy .. oy + zf.shape[0]`` of the image. A
    quad that projects strictly convex and front-facing is filled with one
    span per row; any other quad as its two triangles; a polygon crossing
    the near plane is clipped first (as :func:`fill_kernel`). ``bounds``
    grows to cover every row and column written.
    """
    _fill_polys(proj, polys, values, values, near, perspective, np.bool_(False), tag, np.int64(0), oy, zf, vf, tf,
                np.empty((1, 1)), np.empty((1, 1), np.float32), bounds, np.empty((3, 4)))


@njit(cache=True, nogil=True)
def fill_front_runs(
    proj: NDArray[np.float64], polys: NDArray[np.int32], values: NDArray[np.float32], starts: NDArray[np.int64],
    vstarts: NDArray[np.int64], tags: NDArray[np.int64], nears: NDArray[np.float64], perspective: bool, oy: int,
    zf: NDArray[np.float64], vf: NDArray[np.float32], tf: NDArray[np.int32], bounds: NDArray[np.int64],
) -> None:
    """:func:`fill_front_kernel` of consecutive runs of polygons in one call, run ``r``
    (polygons ``starts[r]`` to ``starts[r + 1]``, using only vertices ``vstarts[r]`` to
    ``vstarts[r + 1]``) with its own tag and near plane: the parts of a large clipped CSG
    surface (one per leaf) without a call per part. A run whose vertices all lie in front
    of its near plane and outside the buffers' rows or the image's columns is skipped
    whole (a row stripe meets few of a model's leaves)."""
    scratch = np.empty((3, 4))
    zb = np.empty((1, 1))
    vb = np.empty((1, 1), np.float32)
    hd, sx, sy = proj[3], proj[4], proj[5]
    r_lo, r_hi = float(oy), float(oy + zf.shape[0])
    c_hi = float(zf.shape[1])
    for r in range(tags.shape[0]):
        a, b = starts[r], starts[r + 1]
        v0, v1 = vstarts[r], vstarts[r + 1]
        if v1 > v0:
            near_ok = True
            ymin, ymax, xmin, xmax = np.inf, -np.inf, np.inf, -np.inf
            for v in range(v0, v1):
                if not hd[v] >= nears[r]:
                    near_ok = False
                    break
                ymin, ymax = min(ymin, sy[v]), max(ymax, sy[v])
                xmin, xmax = min(xmin, sx[v]), max(xmax, sx[v])
            if near_ok and (ymax <= r_lo or ymin >= r_hi + 0.5 or xmax <= 0.0 or xmin >= c_hi + 0.5):
                continue  # as _fill_polys would cull each of its polygons
        _fill_polys(proj, polys[a:b], values[a:b], values[a:b], nears[r], perspective, np.bool_(False), tags[r],
                    np.int64(0), oy, zf, vf, tf, zb, vb, bounds, scratch)


@njit(cache=True, inline="always")
def _extent(t: NDArray[np.float64], a: int, b: int, c: int, d: int) -> tuple[float, float]:
    """Smallest and largest ``t`` over the corners of a quad (``d < 0``: a triangle)."""
    lo = min(t[a], t[b], t[c])
    hi = max(t[a], t[b], t[c])
    if d >= 0:
        lo, hi = min(lo, t[d]), max(hi, t[d])
    return lo, hi


@njit(**_RAW)
def _fill_polys(
    proj: NDArray[np.float64], polys: NDArray[np.int32], vout: NDArray[np.float32], vin: NDArray[np.float32],
    near: float, perspective: bool, back: bool, tag: int, ox: int, oy: int,
    zf: NDArray[np.float64], vf: NDArray[np.float32], tf: NDArray[np.int32],
    zb: NDArray[np.float64], vb: NDArray[np.float32], bounds: NDArray[np.int64], scratch: NDArray[np.float64],
) -> None:
    """Convex polygons (quads of :func:`pair_quads`) into the viewport whose top-left pixel is ``(oy, ox)``.

    Front-facing polygons go to the nearest-key buffers ``zf, vf`` (and
    ``tag`` into ``tf``); back-facing ones to the farthest-key buffers
    ``zb, vb`` with ``back``, else they are culled. Shared by the plain render
    (:func:`fill_front_kernel`) and the CSG leaves (:func:`fill_projected`).
    """
    hx, hy, hw, hd = proj[0], proj[1], proj[2], proj[3]
    sx, sy, sk = proj[4], proj[5], proj[6]
    h, w = zf.shape
    r_lo, r_hi = float(oy), float(oy + h)
    c_lo, c_hi = float(ox), float(ox + w)
    px, py, pk = scratch[0], scratch[1], scratch[2]
    for p in range(polys.shape[0]):
        a, b, c, d = polys[p, 0], polys[p, 1], polys[p, 2], polys[p, 3]
        n = 3 if d < 0 else 4
        if not (hd[a] >= near and hd[b] >= near and hd[c] >= near and (n == 3 or hd[d] >= near)):
            # Crossing the near plane: clipped triangle by triangle (rare).
            _fill_one(hx, hy, hw, hd, sx, sy, sk, a, b, c, near, perspective, np.bool_(True), back, vout[p], vin[p],
                      tag, ox, oy, zf, vf, tf, zb, vb, px, py, pk)
            if n == 4:
                _fill_one(hx, hy, hw, hd, sx, sy, sk, a, c, d, near, perspective, np.bool_(True), back, vout[p], vin[p],
                          tag, ox, oy, zf, vf, tf, zb, vb, px, py, pk)
            bounds[0] = min(bounds[0], oy)
            bounds[1] = max(bounds[1], oy + h)
            bounds[2] = min(bounds[2], ox)
            bounds[3] = max(bounds[3], ox + w)
            continue
        ymin, ymax = _extent(sy, a, b, c, d)
        if ymax <= r_lo or ymin >= r_hi + 0.5:
            continue  # no pixel centre of the viewport's rows
        if math.ceil(ymin - 0.5) >= math.ceil(ymax - 0.5):
            continue  # no row's centre between its top and bottom: _fill_convex would write nothing
        ax, ay = sx[a], sy[a]
        if not back:
            # Back faces first (about half of a closed mesh): a planar polygon is
            # back-facing when both its fan triangles are (signed area >= 0).
            if not (sx[b] - ax) * (sy[c] - ay) - (sy[b] - ay) * (sx[c] - ax) < 0.0 and (
                n == 3 or not (sx[c] - ax) * (sy[d] - ay) - (sy[c] - ay) * (sx[d] - ax) < 0.0
            ):
                continue
        xmin, xmax = _extent(sx, a, b, c, d)
        if xmax <= c_lo or xmin >= c_hi + 0.5:
            continue
        clamp = not (xmin >= c_lo and xmax <= c_hi)
        # A strictly convex quad is one part; any other quad (seen nearly
        # edge-on) goes as its fan triangles, each with its own facing.
        parts = 1
        if n == 4:
            neg = 0
            pos = 0
            for k in range(4):
                i0 = polys[p, k]
                i1 = polys[p, (k + 1) % 4]
                i2 = polys[p, (k + 2) % 4]
                crs = (sx[i1] - sx[i0]) * (sy[i2] - sy[i1]) - (sy[i1] - sy[i0]) * (sx[i2] - sx[i1])
                if crs < 0.0:
                    neg += 1
                elif crs > 0.0:
                    pos += 1
            if neg != 4 and pos != 4:
                parts = 2
        for part in range(parts):
            m = n if parts == 1 else 3
            for k in range(m):
                v = a if k == 0 else polys[p, k + part]
                px[k], py[k], pk[k] = sx[v], sy[v], sk[v]
            s2 = 0.0
            for k in range(m):
                k1 = (k + 1) % m
                s2 += px[k] * py[k1] - px[k1] * py[k]
            if not (s2 < 0.0 or back and s2 > 0.0) or not math.isfinite(s2):
                continue  # culled, or no area
            front = s2 < 0.0
            if not front:  # clockwise on screen: reverse the ring (the same fan triangles)
                for k in range(1, (m + 1) // 2):
                    k2 = m - k
                    px[k], px[k2] = px[k2], px[k]
                    py[k], py[k2] = py[k2], py[k]
                    pk[k], pk[k2] = pk[k2], pk[k]
            _fill_convex(px, py, pk, m, vout[p] if front else vin[p], tag, ox, oy, clamp, front,
                         zf if front else zb, vf if front else vb, tf, bounds)


# ------------------------------------------------------------------ Python API
@dataclass(frozen=True, slots=True, eq=False)
class Raster:
    """Per-pixel result of :func:`rasterize`.

    Attributes
    ----------
    front_depth : ndarray, shape (H, W), float64
        Camera depth of the nearest surface (``inf`` where nothing is drawn).
    front_value : ndarray, shape (H, W), float32
        ``value_out`` of the nearest triangle (NaN where nothing is drawn).
    back_depth, back_value : ndarray or None
        Farthest surface and its ``value_in`` (``-inf`` / NaN where nothing),
        present when ``value_in`` was given.
    """

    front_depth: NDArray[np.float64]
    front_value: NDArray[np.float32]
    back_depth: NDArray[np.float64] | None
    back_value: NDArray[np.float32] | None

    @property
    def covered(self) -> NDArray[np.bool_]:
        """Pixels with a front surface."""
        return np.isfinite(self.front_depth)


def rasterize(
    camera: Camera,
    vertices: ArrayLike,
    triangles: ArrayLike,
    value_out: ArrayLike,
    value_in: ArrayLike | None = None,
    *,
    cull: bool = True,
) -> Raster:
    """Fill triangles with constant values and keep the nearest (and farthest) surface.

    Parameters
    ----------
    camera : Camera
    vertices : array_like, shape (V, 3)
        World-space vertices.
    triangles : array_like of int, shape (T, 3)
        Counter-clockwise seen from the outside (outward normals).
    value_out : array_like, shape (T,)
        Value written by a triangle seen from outside (front buffers).
    value_in : array_like, shape (T,), optional
        Value written by a triangle seen from inside (back buffers). When
        omitted, only the front buffers are computed.
    cull : bool, default True
        Send front-facing triangles to the front buffers and back-facing ones
        to the back buffers. With ``False`` every triangle is tested against
        both (nearest and farthest of all triangles, whatever their facing).

    Returns
    -------
    Raster

    Raises
    ------
    InvalidGeometryError
        On non-finite vertices, bad shapes or out-of-range triangle indices.
    InvalidParameterError
        When a value array does not have one entry per triangle.

    Examples
    --------
    >>> cam = Camera((0, 0, 5), (0, 0, 0), up=(0, 1, 0), width=8, height=8,
    ...              orthographic=True, height_m=8)
    >>> square = [(-4, -4, 0), (4, -4, 0), (4, 4, 0), (-4, 4, 0)]
    >>> r = rasterize(cam, square, [(0, 1, 2), (0, 2, 3)], [0.25, 0.75])
    >>> int(r.covered.sum()), float(r.front_depth[7, 7])
    (64, 5.0)
    >>> sorted(np.unique(r.front_value, return_counts=True)[1].tolist())  # the diagonal once
    [28, 36]
    """
    v = np.asarray(vertices, dtype=np.float64)
    if v.ndim != 2 or v.shape[1] != 3:
        raise InvalidGeometryError(f"vertices must have shape (V, 3), got {v.shape}")
    if not np.all(np.isfinite(v)):
        raise InvalidGeometryError("vertices must be finite")
    t = np.asarray(triangles)
    if t.ndim != 2 or t.shape[1] != 3 or (t.size and not np.issubdtype(t.dtype, np.integer)):
        raise InvalidGeometryError(f"triangles must be integers of shape (T, 3), got {t.dtype} {t.shape}")
    if t.size and (t.min() < 0 or t.max() >= len(v)):
        raise InvalidGeometryError(f"triangles index vertices 0..{len(v) - 1}, got {t.min()}..{t.max()}")
    t = np.ascontiguousarray(t, dtype=np.int32)
    vo = np.asarray(value_out, dtype=np.float32).reshape(-1)
    if len(vo) != len(t):
        raise InvalidParameterError(f"value_out must have one entry per triangle ({len(t)}), got {len(vo)}")
    do_back = value_in is not None
    vi = np.asarray(value_in if do_back else vo, dtype=np.float32).reshape(-1)
    if len(vi) != len(t):
        raise InvalidParameterError(f"value_in must have one entry per triangle ({len(t)}), got {len(vi)}")
    h = homogeneous(camera, v)
    persp = not camera.orthographic
    H, W = camera.height, camera.width
    zf = np.full((H, W), np.inf)
    vf = np.full((H, W), np.nan, dtype=np.float32)
    tf = np.full((H, W), -1, dtype=np.int32)
    zb = np.full((H, W) if do_back else (1, 1), -np.inf)
    vb = np.full(zb.shape, np.nan, dtype=np.float32)
    fill_kernel(h[0], h[1], h[2], h[3], t, vo, vi, near_distance(h[3]), persp, bool(cull), do_back, 0, 0, 0, zf, vf, tf, zb, vb)
    key_to_depth(zf, persp, zf)
    if do_back:
        key_to_depth(zb, persp, zb)
    return Raster(zf, vf, zb if do_back else None, vb if do_back else None)
