"""The planned Booleans built with manifold3d batch operations, and their results read back.

Each leaf's closed band mesh becomes a manifold3d solid whose triangles remember
their band triangle (face ids, one original id per leaf); every result triangle
then keeps its band's value, reversed where it faces the other way.

A background build (:mod:`isocsg._workers`) is cancellable between the batches: each
Boolean and each read-back first checks :func:`isocsg._workers.raise_if_cancelled`, so that
a build asked to stop (the process is ending) leaves manifold3d after the batch it is in.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ... import _workers
from ...errors import InvalidGeometryError
from ...laminae.model import BandMesh
from ...limits import release_freed_memory as _release_freed_memory
from ..mesh import _manifold3d
from .coincident import cancel_coincident, shared_planes
from .planning import Piece, Plan
from .result import triangle_normals


def run_booleans(
    plan: Plan, needed: NDArray[np.bool_], final: list[Piece], members: dict[int, list[int]], bands: Sequence[BandMesh],
    weld: Any, centre: NDArray[np.float64], half: float, trimmed: dict[int, Any] | None = None,
    one_at_a_time: bool = False,
) -> list[tuple[Any, ...]]:
    """Build the planned Booleans (manifold3d, local frame) and read their results back:
    all at once, or (``one_at_a_time``) result by result, each solid released once the
    last Boolean that takes it is built."""
    m3 = _manifold3d()
    M = m3.Manifold
    trimmed = {} if trimmed is None else trimmed
    # One original id per leaf: manifold3d tags each result triangle with it.
    first_id = int(M.reserve_ids(len(bands)))
    leaf_solid: dict[int, Any] = {}

    def solid(ref: int) -> Any:
        if ref < 0:
            return built[-1 - ref]
        if ref not in leaf_solid:
            if ref in trimmed:
                # Already in the local frame; not needed once its solid exists (a leaf's
                # solid is kept for all the Booleans that take it).
                v, t, src = trimmed.pop(ref)
            else:
                # Welded for this solid only when the Booleans run one result at a time
                # (its solid is kept while a Boolean still takes it).
                v, t, src, _ = weld(ref, not one_at_a_time)
                v = (v - centre) / half
            mesh = m3.Mesh64(
                vert_properties=np.ascontiguousarray(v),
                tri_verts=np.ascontiguousarray(t, dtype=np.uint64),
                face_id=np.ascontiguousarray(src, dtype=np.uint64),
                run_index=np.array([0, 3 * len(t)], dtype=np.uint64),
                run_original_id=np.array([first_id + ref], dtype=np.uint32),
            )
            mesh.merge()  # nearly equal vertices on open edges (rounding of the cuts)
            s = M(mesh)
            if s.status() != m3.Error.NoError:
                raise InvalidGeometryError(f"the band mesh of leaf {ref} is not a closed surface ({s.status()})")
            leaf_solid[ref] = s
        return leaf_solid[ref]

    built: list[Any] = [None] * len(plan.nodes)
    # Consumers of each solid still to come (Booleans, and results to read back).
    uses = np.zeros(len(plan.nodes), np.int64)
    leaf_uses: dict[int, int] = {}
    for k in np.flatnonzero(needed).tolist():
        for r in plan.nodes[k][1]:
            if r < 0:
                uses[-1 - r] += 1
            else:
                leaf_uses[r] = leaf_uses.get(r, 0) + 1
    for c in final:
        if c.ref < 0:
            uses[-1 - c.ref] += 1

    def release(r: int) -> None:
        if not one_at_a_time:
            return
        if r < 0:
            uses[-1 - r] -= 1
            if not uses[-1 - r]:
                built[-1 - r] = None
        else:
            leaf_uses[r] -= 1
            if not leaf_uses[r]:
                leaf_solid.pop(r, None)

    def build(k: int) -> None:
        _workers.raise_if_cancelled()  # between manifold3d batches
        op, refs = plan.nodes[k]
        parts = [solid(r) for r in refs]
        if op == "as is":
            built[k] = parts[0]
        elif op == "compose":
            built[k] = M.compose(parts)
        elif op == "slab":
            axis, lo, hi = plan.slabs[k]
            out = parts[0]
            normal = np.zeros(3)
            if np.isfinite(lo):  # keeps the side the normal points to
                normal[axis] = 1.0
                out = out.trim_by_plane(tuple(normal), lo)
            if np.isfinite(hi):
                normal[axis] = -1.0
                out = out.trim_by_plane(tuple(normal), -hi)
            built[k] = out
        else:
            built[k] = M.batch_boolean(parts, getattr(m3.OpType, op))
        del parts
        for r in refs:
            release(r)

    # The band triangles each trimmed leaf brings into the Booleans (the others: all of theirs).
    subset = {i: np.unique(trimmed[i][2]) for i in trimmed}
    if not one_at_a_time:
        for k in np.flatnonzero(needed).tolist():
            build(k)
    shared = shared_planes(bands, sorted({x for m in members.values() for x in m}), centre, half, subset)
    pieces = []
    for c in final:
        if c.ref >= 0:
            continue
        if one_at_a_time:
            for k in plan.nodes_of(c.ref):
                if built[k] is None:
                    build(k)
        _workers.raise_if_cancelled()
        out = built[-1 - c.ref].to_mesh64()
        release(c.ref)  # the solid goes before its result is read back
        piece = _read_back(out, members[c.ref], bands, subset, shared, first_id, centre, half)
        del out
        if piece is not None:
            pieces.append(piece)
        del piece
        if one_at_a_time:
            _release_freed_memory()
    return pieces


def _read_back(
    out: Any, leaves_in: list[int], bands: Sequence[BandMesh], subset: dict[int, NDArray[np.int64]],
    shared: dict[int, NDArray[np.bool_]], first_id: int, centre: NDArray[np.float64], half: float,
) -> tuple[Any, ...] | None:
    """One Boolean's result (a manifold3d ``Mesh64`` over the leaves ``leaves_in``) as a piece of
    the surface (vertices, triangles, leaf, source, reversed, value) in the world frame; None
    when it is empty."""
    tris = np.asarray(out.tri_verts, dtype=np.int64).reshape(-1, 3)
    if not len(tris):
        return None
    verts = np.asarray(out.vert_properties, dtype=np.float64).reshape(len(out.vert_properties), -1)[:, :3]
    face = np.asarray(out.face_id, dtype=np.int64).reshape(-1)
    run_index = np.asarray(out.run_index, dtype=np.int64) // 3
    run_leaf = np.asarray(out.run_original_id, dtype=np.int64) - first_id
    leaf = np.repeat(run_leaf, np.diff(run_index)).astype(np.int32)
    ours = (leaf >= 0) & (leaf < len(bands))
    if not ours.all():  # a slab's cut faces: the neighbouring slab's result continues there
        keep_runs = (run_leaf >= 0) & (run_leaf < len(bands))
        tris, face, leaf = tris[ours], face[ours], leaf[ours]
        run_leaf = run_leaf[keep_runs]
        run_index = np.concatenate([[0], np.cumsum(np.diff(run_index)[keep_runs])])
    # The leaves' band triangles (of a trimmed leaf, those it kept), concatenated:
    # global index base[leaf] + the face's position among its leaf's.
    sizes = np.array([len(subset[i]) if i in subset else len(bands[i].triangles) for i in leaves_in], np.int64)
    base = np.zeros(len(bands), np.int64)
    base[leaves_in] = np.concatenate([[0], np.cumsum(sizes)[:-1]])
    pos = face.copy()
    for r0, r1, i in zip(run_index[:-1].tolist(), run_index[1:].tolist(), run_leaf.tolist()):
        if i in subset:
            pos[r0:r1] = np.searchsorted(subset[i], face[r0:r1])
    g = base[leaf] + pos

    def gather(i: int, a: NDArray[Any]) -> NDArray[Any]:
        return a[subset[i]] if i in subset else a

    normals = np.vstack([
        triangle_normals(np.asarray(bands[i].vertices, np.float64), gather(i, np.asarray(bands[i].triangles, np.int64)))
        for i in leaves_in
    ])
    vin = np.concatenate([gather(i, np.asarray(bands[i].value_in, np.float64)) for i in leaves_in])
    vout = np.concatenate([gather(i, np.asarray(bands[i].value_out, np.float64)) for i in leaves_in])
    on_shared = np.concatenate([shared[i] for i in leaves_in])[g]
    if on_shared.any():
        verts, tris, kept = cancel_coincident(verts, tris, np.flatnonzero(on_shared))
        if kept is not None:
            leaf, face, g = leaf[kept], face[kept], g[kept]
    rev = np.einsum("ij,ij->i", triangle_normals(verts, tris), normals[g]) < 0
    return (verts * half + centre, tris.astype(np.int32), leaf, face.astype(np.int32), rev,
            np.where(rev, vin[g], vout[g]))
