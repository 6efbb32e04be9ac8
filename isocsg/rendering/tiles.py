"""Screen geometry of CSG leaves and the screen tiles of per-pixel CSG.

Per-pixel CSG needs, for every pixel, the depth interval of each leaf that
covers it. Filling every leaf over the object's whole screen rectangle costs
memory and time in leaves x pixels; here the rectangle is cut into square
tiles instead, and each tile holds only the leaves whose screen rectangle
meets it, each over its own part of the tile (so a tile's buffers are the sum
of its leaves' clipped rectangles), with the tree's program pruned to those
leaves as bounding-box pruning does in image-space CSG: a leaf absent from
the tile drops out of a union and out of a difference's subtracted operands,
and empties an intersection or a difference whose first operand it is
(:meth:`isocsg.csg.program.Program.prune`, whose compiled form
:func:`~isocsg.csg.program.prune_arrays` a tile calls).

Everything here is known before any band is built: the leaves' bounding
boxes (:func:`leaf_geometry`), their screen rectangles, the near plane of
each leaf and their unclipped size on screen (:func:`leaf_rects`), the
object's rectangle (:meth:`~isocsg.csg.program.Program.screen_rect`, compiled as
:func:`~isocsg.csg.program.combine_rects`) and the tile plan (:func:`plan_tiles`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._jit import njit
from ..camera import Camera
from ..csg.program import combine_rects, prune_arrays
from ..errors import InvalidGeometryError
from ..kinds.base import Primitive
from .projection import NEAR_RELATIVE

__all__ = [
    "LeafGeometry", "leaf_geometry", "leaf_rects", "leaf_near_keys", "leaf_screen_sizes", "combine_rects",
    "tile_leaves", "TilePlan", "plan_tiles", "open_tile_pixels", "clip_leaves", "hidden_box", "CLIP_MARGIN",
]

#: :func:`clip_leaves` keeps this fraction of the object box's diagonal beyond the box, so that
#: the new ends lie strictly outside it (never on the object's surface, never coincident with it).
CLIP_MARGIN = 1e-3

#: Bytes per pixel of a leaf in the per-pixel CSG buffers: front and back depth
#: keys (float64) and values (float32).
LEAF_PIXEL_BYTES = 24


@dataclass(frozen=True, slots=True, eq=False)
class LeafGeometry:
    """Bounding boxes of a program's leaves, and the spheres among them (arrays over the leaves).

    Attributes
    ----------
    lo, hi : ndarray, shape (n, 3)
        Axis-aligned bounds of each leaf.
    sphere : ndarray of bool, shape (n,)
    center : ndarray, shape (n, 3)
        Sphere and truncus centres (zero for other leaves).
    radius : ndarray, shape (n,)
        Sphere radii, trunci's larger end radius (zero for other leaves).
    """

    lo: NDArray[np.float64]
    hi: NDArray[np.float64]
    sphere: NDArray[np.bool_]
    center: NDArray[np.float64]
    radius: NDArray[np.float64]

    @property
    def nbytes(self) -> int:
        """Bytes held by the arrays."""
        return sum(a.nbytes for a in (self.lo, self.hi, self.sphere, self.center, self.radius))


def leaf_geometry(leaves: Sequence[Primitive]) -> LeafGeometry:
    """The :class:`LeafGeometry` of ``leaves``.

    The leaves of each class are read in one pass by their kind
    (:meth:`~isocsg.kinds.base.Primitive.leaf_boxes`: spheres, trunci and
    axis-aligned boxes from their parameters, vectorised, since a primitive's
    ``bounds`` property costs tens of microseconds, which adds up over 10 000
    leaves). The boxes are those of the primitives' ``bounds``.

    Examples
    --------
    >>> from isocsg import Cylinder, Sphere
    >>> g = leaf_geometry([Sphere((0, 0, 0), 1), Cylinder((1, 0, 0), (0, 0, 2), 0.5)])
    >>> g.lo.tolist(), g.hi.tolist(), g.sphere.tolist()
    ([[-1.0, -1.0, -1.0], [0.5, -0.5, -1.0]], [[1.0, 1.0, 1.0], [1.5, 0.5, 1.0]], [True, False])
    """
    n = len(leaves)
    lo = np.empty((n, 3))
    hi = np.empty((n, 3))
    sphere = np.zeros(n, np.bool_)
    center = np.zeros((n, 3))
    radius = np.zeros(n)
    by_class: dict[type[Primitive], list[int]] = {}
    for i, p in enumerate(leaves):
        by_class.setdefault(type(p), []).append(i)
    for cls, idx in by_class.items():
        lo[idx], hi[idx], sphere[idx], center[idx], radius[idx] = cls.leaf_boxes([leaves[i] for i in idx])
    return LeafGeometry(lo, hi, sphere, center, radius)


Rects = NDArray[np.int64]  # (n, 4): col0, row0, col1, row1, half-open


def leaf_rects(geom: LeafGeometry, cam: Camera) -> tuple[Rects, NDArray[np.float64], NDArray[np.float64]]:
    """Pixel rectangles holding each leaf's projection, its near plane and its size on screen.

    A leaf's rectangle bounds the projection of its bounding box (the hull of
    the corners' projections) and, for a sphere, of the sphere itself (exact,
    from the tangents in the camera's two vertical planes), with one pixel of
    margin, clipped to the image; the whole image when the box reaches behind
    the leaf's near plane.

    Returns
    -------
    rects : ndarray of int64, shape (n, 4)
        ``(col0, row0, col1, row1)``, half-open (empty when off screen).
    near : ndarray, shape (n,)
        The near-plane depth of each leaf: ``raster.NEAR_RELATIVE`` times its
        own farthest depth (bounded through the box's circumscribed sphere),
        so that a far object does not clip a near one.
    extent : ndarray, shape (n,)
        The larger side in pixels of the unclipped rectangle (``inf`` when
        the leaf reaches behind its near plane).
    """
    W, H = cam.width, cam.height
    n = len(geom.lo)
    c0, c1, r0, r1, behind, near = _screen_boxes(geom, cam)
    with np.errstate(invalid="ignore", over="ignore"):
        extent = np.maximum(c1 - c0, r1 - r0) + 2.0
    extent[behind | ~np.isfinite(extent)] = np.inf
    rects = np.empty((n, 4), np.int64)
    big = 4.0 * (W + H) + 16.0  # clamp before the integer conversion
    rects[:, 0] = np.clip(np.floor(np.clip(c0, -big, big)) - 1, 0, W)
    rects[:, 1] = np.clip(np.floor(np.clip(r0, -big, big)) - 1, 0, H)
    rects[:, 2] = np.clip(np.ceil(np.clip(c1, -big, big)) + 1, 0, W)
    rects[:, 3] = np.clip(np.ceil(np.clip(r1, -big, big)) + 1, 0, H)
    rects[behind] = (0, 0, W, H)
    return rects, near, extent


def leaf_near_keys(geom: LeafGeometry, cam: Camera, near: NDArray[np.float64]) -> NDArray[np.float64]:
    """The smallest depth key any point of each leaf can have (for occlusion culling).

    The depth key is the fills' (:func:`~isocsg.rendering.raster.project_kernel`):
    ``-1 / depth`` under perspective, the depth itself under an orthographic
    camera; the depth of a leaf's points is bounded below by its box's
    nearest corner, and for a sphere by its centre's depth less its radius.
    ``-inf`` for a leaf that reaches its near plane ``near`` (never culled).

    Examples
    --------
    >>> from isocsg import Camera, Sphere
    >>> cam = Camera((0, -5, 0), (0, 0, 0), width=8, height=8)
    >>> geom = leaf_geometry([Sphere((0, 0, 0), 1.0), Sphere((0, 6, 0), 1.0)])
    >>> (-1 / leaf_near_keys(geom, cam, np.array([1e-9, 1e-9]))).round(9).tolist()
    [4.0, 10.0]
    """
    f = cam.frame[0]
    eye = cam.eye_array
    mid, half = 0.5 * (geom.lo + geom.hi), 0.5 * (geom.hi - geom.lo)
    depth = (mid - eye) @ f - half @ np.abs(f)
    if geom.sphere.any():
        k = np.flatnonzero(geom.sphere)
        depth[k] = np.maximum(depth[k], (geom.center[k] - eye) @ f - geom.radius[k] * np.linalg.norm(f))
    with np.errstate(divide="ignore", invalid="ignore"):
        key = depth if cam.orthographic else -1.0 / depth
    return np.where(np.isfinite(depth) & (depth > near), key, -np.inf)


def leaf_screen_sizes(
    geom: LeafGeometry, cam: Camera, lo: NDArray[np.float64] | None = None, hi: NDArray[np.float64] | None = None,
    *, axial: bool = True,
) -> NDArray[np.float64]:
    """Each leaf's size on screen in pixels, for the level of detail.

    The geometric mean of the sides of the unclipped screen rectangle of the
    leaf's box, the box first cut to ``[lo, hi]`` (the object's box: a hole
    longer than the plate it pierces shows only its part inside the plate),
    plus 2; with ``axial``, for a truncus at most its larger diameter seen at
    its centre's depth, plus 2 (its fields vary mostly around its axis; a
    point light's bending along it is followed by the tessellation). ``inf``
    where the box reaches behind the near plane.

    Examples
    --------
    >>> from isocsg import Box, Camera, Cylinder
    >>> cam = Camera((0, -10, 0), (0, 0, 0), width=100, height=100)
    >>> g = leaf_geometry([Box((0, 0, 0), (0.2, 0.2, 4.0)), Cylinder((0, 0, 0), (0, 0, 4), 0.1)])
    >>> full = leaf_screen_sizes(g, cam)
    >>> cut = leaf_screen_sizes(g, cam, np.array([-1.0, -1.0, -0.2]), np.array([1.0, 1.0, 0.2]))
    >>> bool(cut[0] < full[0]), full.round(1).tolist()  # the cylinder: its diameter (2.7 px) plus 2
    (True, [14.4, 4.7])
    """
    if lo is not None and hi is not None:
        clo = np.minimum(np.maximum(geom.lo, lo), hi)
        chi = np.maximum(np.minimum(geom.hi, hi), lo)
        geom = LeafGeometry(clo, np.maximum(chi, clo), geom.sphere, geom.center, geom.radius)
    c0, c1, r0, r1, behind, near = _screen_boxes(geom, cam)
    with np.errstate(invalid="ignore", over="ignore"):
        size = np.sqrt(np.maximum(c1 - c0, 0.0) * np.maximum(r1 - r0, 0.0)) + 2.0
    trunci = ~geom.sphere & (geom.radius > 0) if axial else np.zeros(0, bool)
    if trunci.any():
        k = np.flatnonzero(trunci)
        depth = (geom.center[k] - cam.eye_array) @ cam.frame[0]
        if cam.orthographic:
            per_m = np.full(len(k), cam.height / cam.height_m)
        else:
            with np.errstate(divide="ignore", invalid="ignore"):
                per_m = np.where(depth > near[k], cam.height / (2.0 * cam.tan_half_fov * depth), np.inf)
        size[k] = np.minimum(size[k], 2.0 * geom.radius[k] * per_m + 2.0)
    size[behind | ~np.isfinite(size)] = np.inf
    return size


def _screen_boxes(geom: LeafGeometry, cam: Camera) -> tuple[NDArray[np.float64], ...]:
    """Unclipped pixel bounds ``c0, c1, r0, r1`` of each leaf's projection, whether it reaches
    behind its near plane, and the near planes (see :func:`leaf_rects`)."""
    W, H = cam.width, cam.height
    f, r, u = cam.frame
    m = np.stack([r, u, f])
    eye = cam.eye_array
    mid, half = 0.5 * (geom.lo + geom.hi), 0.5 * (geom.hi - geom.lo)
    far = np.abs((mid - eye) @ f) + np.linalg.norm(half, axis=1)
    near = NEAR_RELATIVE * np.maximum(np.where(far > 0, far, 1.0), 1e-300)
    signs = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=np.float64)
    corners = mid[:, None, :] + signs[None] * half[:, None, :]  # (n, 8, 3)
    cs = (corners - eye) @ m.T  # camera space (n, 8, 3)
    xr, yu, z = cs[..., 0], cs[..., 1], cs[..., 2]
    behind = ~np.all(np.isfinite(cs), axis=(1, 2)) | (z.min(axis=1) < near)
    with np.errstate(divide="ignore", invalid="ignore"):
        sx, sy = (xr, yu) if cam.orthographic else (xr / z, yu / z)
    box = np.stack([sx.min(axis=1), sx.max(axis=1), sy.min(axis=1), sy.max(axis=1)], axis=1)
    if geom.sphere.any():
        k = np.flatnonzero(geom.sphere & ~behind)
        cc = (geom.center[k] - eye) @ m.T
        rad = geom.radius[k]
        if cam.orthographic:
            ball = np.stack([cc[:, 0] - rad, cc[:, 0] + rad, cc[:, 1] - rad, cc[:, 1] + rad], axis=1)
        else:
            # x / z over the disk the sphere projects to in the (x, z) plane (likewise y): tangent lines.
            cols = []
            for c in (cc[:, 0], cc[:, 1]):
                t0 = np.arctan2(c, cc[:, 2])
                dt = np.arcsin(np.minimum(rad / np.hypot(c, cc[:, 2]), 1.0))
                cols += [np.tan(t0 - dt), np.tan(t0 + dt)]
            ball = np.stack(cols, axis=1)
        sub = box[k]
        box[k] = np.stack([np.maximum(sub[:, 0], ball[:, 0]), np.minimum(sub[:, 1], ball[:, 1]),
                           np.maximum(sub[:, 2], ball[:, 2]), np.minimum(sub[:, 3], ball[:, 3])], axis=1)
    if cam.orthographic:
        half_h = cam.height_m / 2
        sx_scale, sy_scale = 1.0 / (half_h * cam.aspect), 1.0 / half_h
    else:
        sx_scale, sy_scale = 1.0 / (cam.tan_half_fov * cam.aspect), 1.0 / cam.tan_half_fov
    with np.errstate(invalid="ignore", over="ignore"):
        c0 = (box[:, 0] * sx_scale + 1.0) * W / 2
        c1 = (box[:, 1] * sx_scale + 1.0) * W / 2
        r0 = (1.0 - box[:, 3] * sy_scale) * H / 2
        r1 = (1.0 - box[:, 2] * sy_scale) * H / 2
    return c0, c1, r0, r1, behind, near


def hidden_box(lo: NDArray[np.float64], hi: NDArray[np.float64]) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """The box beyond which nothing of an object with box ``[lo, hi]`` can be seen, as
    ``build_bands(hidden=...)`` takes it: the object's box grown by half :data:`CLIP_MARGIN` of
    its diagonal. The object's own boundary may lie on its box (a face of the leaf that spans
    it): with the bare box, rounding could put that face's corners an ulp beyond it, and the
    face would be left uncut, with the ambient value, though it shows. The ends that
    :func:`clip_leaves` makes, a whole :data:`CLIP_MARGIN` out, stay beyond it (uncut).

    Examples
    --------
    >>> hidden_box(np.array([0.0, 0.0, 0.0]), np.array([3.0, 4.0, 0.0]))
    ((-0.0025, -0.0025, -0.0025), (3.0025, 4.0025, 0.0025))
    """
    lo, hi = np.asarray(lo, dtype=np.float64), np.asarray(hi, dtype=np.float64)
    margin = 0.5 * CLIP_MARGIN * float(np.linalg.norm(hi - lo))
    return tuple((lo - margin).tolist()), tuple((hi + margin).tolist())


def clip_leaves(
    leaves: Sequence[Primitive], geom: LeafGeometry, lo: NDArray[np.float64], hi: NDArray[np.float64],
) -> list[Primitive]:
    """The leaves cut down to the slab of the object's box ``[lo, hi]`` where they can be seen.

    A tree's value is inside the box
    :meth:`Program.bounds(lo, hi) <isocsg.csg.program.Program.bounds>` gives
    (a union holds its operands' boxes, an intersection lies in their overlap,
    a difference in its first operand's box), and replacing every leaf ``L``
    by ``L n S`` with ``S`` any set holding that box changes nothing:
    ``f(L n S) = f(L) n S`` for unions, intersections and differences, and
    the value of the cut leaves still lies in the box. So a hole three times
    longer than the plate it pierces can be built for the plate's thickness
    alone (fewer band triangles, a smaller screen rectangle). Cut here: a
    truncus (cylinder, cone) along its axis to the box's extent along that
    axis, and an axis-aligned box to the box, each with a margin of
    :data:`CLIP_MARGIN` of the box's diagonal, so that the new ends lie
    strictly outside the box and never show. A truncus is cut to the
    tighter of two ranges of its axis, each holding all of it that can meet
    the box: the box's extent along the axis, and where the axis runs through
    the box grown by the larger radius (any point of the truncus lies within
    that radius of its axis; the latter is what a tilted hole in a wide plate
    needs). Other kinds, leaves within the slab, and cuts that would give a
    primitive below the documented smallest lengths, are kept as they are.

    Examples
    --------
    >>> from isocsg import Box, Cylinder
    >>> from isocsg.csg.program import compile_program
    >>> prog = compile_program(Box((0, 0, 0), (2, 2, 0.4)) - Cylinder((0, 0, 0), (0, 0, 3), 0.2))
    >>> g = leaf_geometry(prog.leaves)
    >>> hole = clip_leaves(prog.leaves, g, *prog.bounds(g.lo, g.hi))[1]
    >>> type(hole).__name__, round(hole.height, 4), hole.radius
    ('Cylinder', 0.4057, 0.2)
    """
    out = list(leaves)
    lo = np.asarray(lo, dtype=np.float64)
    hi = np.asarray(hi, dtype=np.float64)
    if not (np.all(np.isfinite(lo)) and np.all(np.isfinite(hi)) and np.all(lo <= hi)):
        return out
    margin = CLIP_MARGIN * float(np.linalg.norm(hi - lo))
    glo, ghi = lo - margin, hi + margin
    # Leaves whose box reaches beyond the grown box: only those can be cut.
    beyond = np.flatnonzero(np.any(geom.lo < glo, axis=1) | np.any(geom.hi > ghi, axis=1)).tolist()
    for i in beyond:
        p = leaves[i]
        try:
            out[i] = p.clipped_to_box(glo, ghi)
        except InvalidGeometryError:
            out[i] = p  # too thin or too flat once cut: built whole
    return out


@njit(cache=True, nogil=True)
def tile_leaves(
    op: NDArray[np.int8], arg: NDArray[np.int64], leaves: NDArray[np.int32], n: int, rects: NDArray[np.int64],
    c0: int, r0: int, c1: int, r1: int,
) -> tuple[NDArray[np.int8], NDArray[np.int64], NDArray[np.int64], NDArray[np.int64], NDArray[np.int64],
           NDArray[np.int64], NDArray[np.int64], NDArray[np.int64]]:
    """A tile's pruned program and its leaves' packed rectangles.

    ``leaves`` are the indices (among ``n``) of the leaves whose rectangle
    meets the tile ``(c0, r0, c1, r1)``. Returns :func:`~isocsg.csg.program.prune_arrays`'s
    ``op``, ``arg`` and leaf ids, then per remaining leaf the offset of its
    rectangle in packed buffers, its first row and column and its rows and
    columns (the leaf's rectangle clipped to the tile).
    """
    keep = np.zeros(n, np.bool_)
    for i in leaves:
        keep[i] = True
    pop, parg, ids = prune_arrays(op, arg, keep)
    m = len(ids)
    off = np.empty(m, np.int64)
    lr0 = np.empty(m, np.int64)
    lc0 = np.empty(m, np.int64)
    lh = np.empty(m, np.int64)
    lw = np.empty(m, np.int64)
    pos = 0
    for j in range(m):
        i = ids[j]
        lc0[j] = max(rects[i, 0], c0)
        lr0[j] = max(rects[i, 1], r0)
        lw[j] = min(rects[i, 2], c1) - lc0[j]
        lh[j] = min(rects[i, 3], r1) - lr0[j]
        off[j] = pos
        pos += lw[j] * lh[j]
    return pop, parg, ids, off, lr0, lc0, lh, lw


# ------------------------------------------------------------------ tile plan
#: Tile sides tried, largest first (pixels).
TILE_SIDES = (256, 128, 64, 32, 16, 8)
# Cost model of a tile plan (seconds on the reference machine, measured on
# plates with holes): per tile (Python and the program's pruning, the latter
# per instruction), per leaf in a tile (a compiled call and a pass over the
# leaf's polygons), per pixel and leaf of a tile (the resolution's loop).
_COST_TILE = 40e-6
_COST_INSTRUCTION = 2e-9
_COST_PAIR = 5e-6
_COST_PIXEL_LEAF = 2e-9


@njit(cache=True)
def _tile_counts(
    rects: NDArray[np.int64], ox: int, oy: int, side: int, ntr: int, ntc: int,
) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Per tile: the leaves whose rectangle meets it and the pixels of their clipped rectangles."""
    counts = np.zeros(ntr * ntc, np.int64)
    pixels = np.zeros(ntr * ntc, np.int64)
    for i in range(rects.shape[0]):
        c0, r0, c1, r1 = rects[i, 0], rects[i, 1], rects[i, 2], rects[i, 3]
        if c0 >= c1 or r0 >= r1:
            continue
        for tr in range((r0 - oy) // side, (r1 - 1 - oy) // side + 1):
            ty = oy + tr * side
            h = min(r1, ty + side) - max(r0, ty)
            for tc in range((c0 - ox) // side, (c1 - 1 - ox) // side + 1):
                tx = ox + tc * side
                t = tr * ntc + tc
                counts[t] += 1
                pixels[t] += h * (min(c1, tx + side) - max(c0, tx))
    return counts, pixels


@njit(cache=True)
def _tile_lists(
    rects: NDArray[np.int64], ox: int, oy: int, side: int, ntr: int, ntc: int, counts: NDArray[np.int64],
) -> tuple[NDArray[np.int64], NDArray[np.int32]]:
    """The leaves of each tile in increasing order: ``leaf[start[t]:start[t + 1]]``."""
    start = np.zeros(ntr * ntc + 1, np.int64)
    for t in range(ntr * ntc):
        start[t + 1] = start[t] + counts[t]
    fill = start[:-1].copy()
    leaf = np.empty(start[-1], np.int32)
    for i in range(rects.shape[0]):
        c0, r0, c1, r1 = rects[i, 0], rects[i, 1], rects[i, 2], rects[i, 3]
        if c0 >= c1 or r0 >= r1:
            continue
        for tr in range((r0 - oy) // side, (r1 - 1 - oy) // side + 1):
            for tc in range((c0 - ox) // side, (c1 - 1 - ox) // side + 1):
                t = tr * ntc + tc
                leaf[fill[t]] = i
                fill[t] += 1
    return start, leaf


@dataclass(frozen=True, slots=True, eq=False)
class TilePlan:
    """Square tiles of side ``side`` over the rectangle ``rect`` (col0, row0, col1, row1).

    Tile ``t = tr * cols + tc`` covers rows ``row0 + tr * side ..`` and columns
    ``col0 + tc * side ..`` (clipped to ``rect``); its leaves are
    ``leaf[start[t]:start[t + 1]]``, increasing. ``max_pixels`` is the most
    leaf pixels (the sum of the clipped leaf rectangles) of any tile.
    """

    rect: tuple[int, int, int, int]
    side: int
    rows: int
    cols: int
    start: NDArray[np.int64]
    leaf: NDArray[np.int32]
    max_pixels: int

    def tile(self, t: int) -> tuple[int, int, int, int]:
        """Tile ``t`` as (col0, row0, col1, row1)."""
        tr, tc = divmod(t, self.cols)
        c0, r0 = self.rect[0] + tc * self.side, self.rect[1] + tr * self.side
        return c0, r0, min(c0 + self.side, self.rect[2]), min(r0 + self.side, self.rect[3])


def plan_tiles(rects: Rects, rect: tuple[int, int, int, int], instructions: int, max_bytes: float) -> TilePlan:
    """The tile side of least estimated cost whose tiles' buffers fit ``max_bytes``.

    ``rects`` must lie inside ``rect`` (empty ones are left out).

    Each candidate side of :data:`TILE_SIDES` is costed from its tiles' leaf
    counts and leaf pixels (a fixed cost per tile and per program
    instruction pruned, per leaf in a tile, per pixel and leaf of a tile);
    sides whose fullest tile needs more than ``max_bytes`` of per-pixel CSG
    buffers (:data:`LEAF_PIXEL_BYTES` per leaf pixel) are not taken unless
    none fits, and then the one needing the least.
    """
    ox, oy, x1, y1 = rect
    inside = (rects[:, 0] >= ox) & (rects[:, 1] >= oy) & (rects[:, 2] <= x1) & (rects[:, 3] <= y1)
    empty = (rects[:, 0] >= rects[:, 2]) | (rects[:, 1] >= rects[:, 3])
    if not np.all(inside | empty):
        raise ValueError("leaf rectangles must lie inside the tiled rectangle")
    best: tuple[bool, float, int, NDArray[np.int64], int, int, int] | None = None
    for side in TILE_SIDES:
        ntr, ntc = -(-(y1 - oy) // side), -(-(x1 - ox) // side)
        counts, pixels = _tile_counts(rects, ox, oy, side, ntr, ntc)
        occupied = counts > 0
        areas = (np.minimum(side, (y1 - oy) - side * np.arange(ntr))[:, None]
                 * np.minimum(side, (x1 - ox) - side * np.arange(ntc))[None, :]).reshape(-1)
        cost = (int(occupied.sum()) * (_COST_TILE + _COST_INSTRUCTION * instructions)
                + int(counts.sum()) * _COST_PAIR + float(areas @ counts) * _COST_PIXEL_LEAF)
        worst = int(pixels.max()) if len(pixels) else 0
        fits = worst * LEAF_PIXEL_BYTES <= max_bytes
        key = (not fits, cost if fits else float(worst), side, counts, worst, ntr, ntc)
        if best is None or key[:2] < best[:2]:
            best = key
    assert best is not None
    _, _, side, counts, worst, ntr, ntc = best
    start, leaf = _tile_lists(rects, ox, oy, side, ntr, ntc, counts)
    return TilePlan(rect, side, ntr, ntc, start, leaf, worst)



def open_tile_pixels(rects: Rects, plan: TilePlan, ahead: int) -> int:
    """The most leaf pixels of ``plan``'s tiles open at once when tiles are opened and released by rows.

    ``rects`` are the rectangles of the leaves that get buffers of their own
    (one per group of equal leaves). A tile is open from the moment the first
    leaf meeting it is built (leaves in order of the first row they meet)
    until it is resolved; while the leaves beginning in row ``q`` are built,
    the rows before ``q - ahead`` are resolved. So the tiles open then are
    those of rows ``q - ahead`` up to the last row reached by a leaf
    beginning at or before ``q``, and their buffers hold the sum of their
    leaves' clipped rectangles.

    Examples
    --------
    >>> rects = np.array([[0, 0, 8, 40], [0, 0, 8, 8], [0, 30, 8, 38]])
    >>> plan = plan_tiles(rects, (0, 0, 8, 40), 5, 1 << 30)
    >>> open_tile_pixels(rects, plan, 0) <= 3 * 8 * 40
    True
    """
    ox, oy, _, _ = plan.rect
    _, pixels = _tile_counts(rects, ox, oy, plan.side, plan.rows, plan.cols)
    row_pixels = pixels.reshape(plan.rows, plan.cols).sum(axis=1)
    keep = (rects[:, 0] < rects[:, 2]) & (rects[:, 1] < rects[:, 3])
    first = (rects[keep, 1] - oy) // plan.side
    last = (rects[keep, 3] - 1 - oy) // plan.side
    reach = np.full(plan.rows, -1, np.int64)
    np.maximum.at(reach, first, last)
    reach = np.maximum.accumulate(reach)
    cum = np.concatenate([[0], np.cumsum(row_pixels)])
    q = np.arange(plan.rows)
    lo = np.maximum(q - ahead, 0)
    hi = np.maximum(reach, q) + 1
    return int((cum[hi] - cum[lo]).max()) if plan.rows else 0
