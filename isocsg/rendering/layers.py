"""Leaves a ray meets in several depth intervals (non-convex kinds) in per-pixel CSG.

The per-pixel kernels (:mod:`isocsg.rendering.pixel_csg`) take one
``[front, back]`` interval per leaf and pixel. A leaf whose kind has
``max_intervals > 1`` (a torus) is therefore resolved as the union of its
*interval layers*: layer ``j`` is, at each pixel, the ``j``-th interval of the
pixel's ray in the leaf (:meth:`~isocsg.kinds.base.Primitive.ray_intervals`,
exact), absent where the ray has fewer. The program is rewritten so that the
leaf's instruction becomes the union of its layers, all labelled as the leaf.

Depth keys are those of the fills (as :mod:`~isocsg.rendering.small_leaves`
writes them). Values are the leaf's band values: an entry takes the outward
value (``value_out``) of the band mesh's triangle nearest to the exact hit,
an exit the reversed one (``value_in``), so the image keeps the isoluminance
bands. Only objects holding such a leaf take this path; others are untouched.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..csg.program import OP_LEAF, OP_UNION
from .meshes import PreparedMesh
from .small_leaves import PixelRays, depth_keys

__all__ = ["layer_counts", "expand_program", "leaf_layers"]


def layer_counts(leaves: Sequence[Any]) -> NDArray[np.int64] | None:
    """Each leaf's most intervals per ray (its ``max_intervals``), or None if every leaf has one (the
    common case: nothing changes). The layers built are as many as the rays at hand need
    (:meth:`~isocsg.kinds.base.Primitive.ray_intervals` may return fewer columns than this bound)."""
    if not any(getattr(kind, "max_intervals", 1) > 1 for kind in set(map(type, leaves))):
        return None
    return np.fromiter((getattr(leaf, "max_intervals", 1) for leaf in leaves), np.int64, len(leaves))


def expand_program(
    op: NDArray[np.int8], arg: NDArray[np.int64], counts: NDArray[np.int64],
) -> tuple[NDArray[np.int8], NDArray[np.int64], NDArray[np.int64], NDArray[np.int64]]:
    """The program with leaf ``i`` replaced by the union of its ``counts[i]`` layers.

    Returns ``(op, arg, owner, first)``: ``owner[k]`` is the leaf of layer ``k`` and
    ``first[i]`` the first layer of leaf ``i`` (its layers are consecutive)."""
    first = np.concatenate([[0], np.cumsum(counts)]).astype(np.int64)
    owner = np.repeat(np.arange(len(counts), dtype=np.int64), counts)
    ops: list[int] = []
    args: list[int] = []
    for o, a in zip(op.tolist(), arg.tolist()):
        if o != OP_LEAF or counts[a] == 1:
            ops.append(o)
            args.append(int(first[a]) if o == OP_LEAF else a)
            continue
        c = int(counts[a])
        ops.extend([OP_LEAF] * c + [OP_UNION])
        args.extend(list(range(int(first[a]), int(first[a]) + c)) + [c])
    return np.asarray(ops, np.int8), np.asarray(args, np.int64), owner, first


class _BandValues:
    """A band mesh's values at surface points: those of the nearest triangle (by centroid), or, for a
    kind whose band surface is its surface (``flat_bands``: a triangle mesh's faces), of the
    triangle nearest the point exactly (a centroid can lie nearer a neighbouring face's point)."""

    def __init__(self, mesh: PreparedMesh, exact: bool = False) -> None:
        tri = mesh.triangles
        self.value_out = mesh.value_out
        self.value_in = mesh.value_in
        if exact:
            from ..kinds.mesh_bvh import build_bvh, bvh_nearest

            v = np.ascontiguousarray(mesh.vertices, np.float64)
            t = np.ascontiguousarray(tri, np.int64)
            bvh = build_bvh(v, t)
            self.nearest = lambda p: bvh_nearest(bvh, v, t, p)[1]
            return
        from scipy.spatial import cKDTree  # on first use: objects without such a leaf never load it

        tree = cKDTree(mesh.vertices[tri].mean(axis=1))
        self.nearest = lambda p: tree.query(p)[1]

    def at(self, points: NDArray[np.float64], outward: bool) -> NDArray[np.float32]:
        if not len(points):
            return np.zeros(0, np.float32)
        k = self.nearest(points)
        return (self.value_out if outward else self.value_in)[k].astype(np.float32)


def leaf_layers(
    leaf: Any, mesh: PreparedMesh, rays: PixelRays, r0: int, c0: int, h: int, w: int, near: float,
) -> list[tuple[NDArray[np.float64], NDArray[np.float32], NDArray[np.float64], NDArray[np.float32]]]:
    """The leaf's interval layers over a rectangle of pixels, each ``(kf, vf, kb, vb)`` flat row by
    row as the fills write them: front key ``+inf`` where none (or behind the near plane
    ``near``), back key ``-inf`` where none."""
    origins, directions = rays.rect(r0, c0, h, w)
    norm = np.linalg.norm(directions, axis=1)
    unit = directions / norm[:, None]
    iv = np.asarray(leaf.ray_intervals(origins, unit), np.float64)
    values = _BandValues(mesh, bool(getattr(leaf, "flat_bands", False)))
    layers = []
    for j in range(iv.shape[1]):
        # Parameters along unit directions; the camera depth is t over the direction's length.
        t_in, t_out = iv[:, j, 0], iv[:, j, 1]
        hit = np.isfinite(t_in) & np.isfinite(t_out)
        d_in = np.where(hit, t_in, 0.0) / norm
        d_out = np.where(hit, t_out, 0.0) / norm
        front, back, kf, kb = depth_keys(d_in, d_out, hit, near, rays.perspective)
        vf = np.zeros(len(norm), np.float32)
        vb = np.zeros(len(norm), np.float32)
        vf[front] = values.at(origins[front] + directions[front] * d_in[front, None], True)
        vb[back] = values.at(origins[back] + directions[back] * d_out[back, None], False)
        layers.append((kf, vf, kb, vb))
    return layers


def resolve_dense_layers(
    rp: Any, obj: Any, counts: NDArray[np.int64], meshes: dict[int, PreparedMesh],
    bufs: tuple[NDArray[np.float64], NDArray[np.float32], NDArray[np.float64], NDArray[np.float32]],
) -> None:
    """Per-pixel CSG of an object over its screen rectangle (:mod:`~isocsg.rendering.dense`) with
    its non-convex leaves as unions of their interval layers. ``bufs`` (kf, vf, kb, vb), each
    (n, h, w), hold every leaf's filled front and back; ``meshes`` the band meshes of the leaves
    with ``counts > 1``."""
    from .pixel_csg import resolve_packed, resolve_scratch, table_of

    ox, oy, x1, y1 = obj.rect
    w, h = x1 - ox, y1 - oy
    rays = PixelRays(rp.cam)
    # a leaf's layers are as many as its rays here need (a mesh: up to len(faces) // 2, rarely many)
    layered = {i: leaf_layers(obj.leaves[i], meshes[i], rays, oy, ox, h, w, float(obj.nears[i]))
               for i in range(len(counts)) if counts[i] > 1}
    counts = counts.copy()
    for i, layers in layered.items():
        counts[i] = len(layers)
    op, arg, owner, first = expand_program(obj.program.op, obj.program.arg, counts)
    m = len(owner)
    filled: list[NDArray[Any]] = list(bufs)
    out = [np.empty((m, h * w), b.dtype) for b in filled]
    for i in range(len(counts)):
        if i not in layered:
            for dst, b in zip(out, filled):
                dst[first[i]] = b[i].reshape(-1)
            continue
        for j, layer in enumerate(layered[i]):
            for o, x in zip(out, layer):
                o[first[i] + j] = x
    lr0, lc0 = np.full(m, oy, np.int64), np.full(m, ox, np.int64)
    lh, lw = np.full(m, h, np.int64), np.full(m, w, np.int64)
    off = np.arange(m, dtype=np.int64) * (h * w)
    resolve_packed(*(o.reshape(-1) for o in out), off, lr0, lc0, lh, lw, owner, op, arg, table_of(op, arg, m),
                   obj.base, oy, y1, ox, x1, rp.zkey, rp.value, rp.gid, *resolve_scratch(m, len(op)))


def expand_tile(tile: tuple[Any, ...], layers_of: dict[int, list[Any]]) -> tuple[Any, ...]:
    """A screen tile of :mod:`~isocsg.rendering.tiled` (``(bufs, op, arg, ids, off, lr0, lc0, lh,
    lw)``) with the leaves at positions ``layers_of`` (position -> its layers over the leaf's
    rectangle in the tile) as unions of their layers: the same form, packed anew."""
    (kf, vf, kb, vb), op, arg, ids, off, lr0, lc0, lh, lw = tile
    counts = np.ones(len(ids), np.int64)
    for k, layers in layers_of.items():
        counts[k] = len(layers)
    op2, arg2, owner, first = expand_program(op, arg, counts)
    sizes = (lh * lw)[owner]
    off2 = np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(np.int64)
    total = max(int(sizes.sum()), 1)
    out: tuple[NDArray[Any], ...] = (np.empty(total), np.empty(total, np.float32), np.empty(total),
                                     np.empty(total, np.float32))
    for k in range(len(ids)):
        size = int(lh[k] * lw[k])
        if k in layers_of:
            for j, layer in enumerate(layers_of[k]):
                o = int(off2[first[k] + j])
                for dst, src in zip(out, layer):
                    dst[o : o + size] = src
            continue
        o, s = int(off2[first[k]]), int(off[k])
        for dst, src in zip(out, (kf, vf, kb, vb)):
            dst[o : o + size] = src[s : s + size]
    return out, op2, arg2, ids[owner], off2, lr0[owner], lc0[owner], lh[owner], lw[owner]
