"""The boundary of a CSG solid as isoluminance bands: view-independent CSG.

Each leaf's surface bands (planar triangles of constant value, see
:mod:`isocsg.laminae`) are clipped in 3D against the other operands: the
band meshes are closed (:func:`close_mesh`), turned into manifold3d solids
whose triangles remember their band triangle, and combined with manifold3d's
exact mesh Booleans along the tree. Every triangle of the result lies on one
leaf's band triangle, so it keeps that band's constant value; where the
result's triangle faces the other way (the inside of a cut: the boundary of a
subtracted leaf, or of a leaf of an intersection seen from inside another),
it shows the band's reversed-normal value ``value_in``.

This is the design notes' "clip contour-aligned surface bands" resolution of
lamina ownership: each visible surface point takes the value of the leaf whose
boundary it lies on, decided once in object space. The renderer then fills
the result like any primitive (front faces, depth test), so a new viewpoint
costs a plain fill. Coincident faces of different leaves are resolved by
manifold3d's symbolic perturbation (regularised results); the zero-volume
shells it can leave there are dropped (:data:`SHEET_THICKNESS`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numba import njit
from numpy.typing import NDArray

from ..errors import InvalidGeometryError, InvalidParameterError
from ..laminae.model import BandMesh
from ..laminae.split import mesh_edges
from .mesh import _manifold3d
from .program import OP_DIFFERENCE, OP_INTERSECTION, OP_UNION, Program
from .tree import CSGNode

if TYPE_CHECKING:  # pragma: no cover
    from ..lighting.lights import Light, Material

__all__ = ["CSGSurface", "close_mesh", "csg_surface", "surface_from_bands"]

# Relative distance (to the mesh size) within which a vertex lies on an open edge.
_ON_EDGE_RELATIVE = 1e-9
#: Connected parts of a Boolean result whose mean thickness (2 volume / area) is
#: below this fraction of the leaves' size are sheets, not solid: where faces of
#: two operands coincide (``A - A``, flush cuts) manifold3d can leave closed
#: shells of zero volume, which a fill would show from either side.
SHEET_THICKNESS = 1e-9
_OPS = {OP_UNION: "Add", OP_INTERSECTION: "Intersect", OP_DIFFERENCE: "Subtract"}


@dataclass(frozen=True, slots=True, eq=False)
class CSGSurface:
    """The boundary of a CSG solid: triangles of constant value, each on one leaf.

    Attributes
    ----------
    vertices : ndarray, shape (V, 3), float64
    triangles : ndarray, shape (T, 3), int32
        Counter-clockwise seen from outside the result.
    value : ndarray, shape (T,), float64
        The value each triangle shows: its band's ``value_out``, or
        ``value_in`` where the triangle is reversed.
    leaf : ndarray, shape (T,), int32
        Index of the leaf (in ``CSGNode.program()`` order) it lies on.
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

    @property
    def n_triangles(self) -> int:
        """Number of triangles."""
        return int(len(self.triangles))

    def leaf_bands(self, i: int) -> BandMesh:
        """The part on leaf ``i`` as a :class:`BandMesh` (both values set to the shown value).

        Vertices are shared with the whole surface (unused ones included).
        """
        sel = self.leaf == i
        shown = self.value[sel]
        return BandMesh(self.vertices, self.triangles[sel], shown, shown, self.source[sel])


def close_mesh(
    vertices: NDArray[np.float64], triangles: NDArray[np.int64]
) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]:
    """Weld a triangle soup that tiles a closed surface into a closed mesh.

    Band meshes are cut face by face: equal vertices may be repeated, and a
    vertex of one face may lie inside an edge of its neighbour (a
    T-junction). Repeated vertices are merged, and each open edge with such
    vertices inside is split at them (its triangle becomes a fan, in the same
    plane, so the surface and the orientation are unchanged).

    Parameters
    ----------
    vertices : ndarray, shape (V, 3)
    triangles : ndarray of int, shape (T, 3)

    Returns
    -------
    vertices : ndarray, shape (V', 3)
    triangles : ndarray of int64, shape (T', 3)
    source : ndarray of int64, shape (T',)
        The input triangle each output triangle lies in.

    Examples
    --------
    A unit square whose right half is split at the middle of the shared edge:

    >>> v = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [1, 0.5, 0], [2, 0, 0], [2, 1, 0]], float)
    >>> t = np.array([[0, 1, 2], [0, 2, 3], [1, 5, 4], [4, 5, 6], [4, 6, 2]])
    >>> _, t2, src = close_mesh(v, t)
    >>> len(t2), sorted(src.tolist())
    (6, [0, 0, 1, 2, 3, 4])
    """
    v = np.ascontiguousarray(vertices, dtype=np.float64).reshape(-1, 3)
    t = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    src = np.arange(len(t), dtype=np.int64)
    if not len(t):
        return v, t, src
    # Bit-equal vertices are one vertex.
    rows = np.ascontiguousarray(v + 0.0).view(np.dtype((np.void, 24))).ravel()  # +0.0: -0.0 == 0.0
    _, first, inverse = np.unique(rows, return_index=True, return_inverse=True)
    v = v[first]
    t = inverse.reshape(-1)[t]
    tol = _ON_EDGE_RELATIVE * max(float(np.ptp(v, axis=0).max()), 1e-300)
    for _ in range(8):  # each pass splits one open edge per triangle
        u = t.ravel()
        w = t[:, [1, 2, 0]].ravel()
        open_h = _open_half_edges(t)
        if not len(open_h):
            break
        ends = np.unique(np.concatenate([u[open_h], w[open_h]]))
        split_e, split_v, split_s = _points_on_edges(v, u[open_h], w[open_h], ends, tol)
        if not len(split_e):
            break
        # One open edge per triangle this pass (the others in the next).
        h = open_h[split_e]
        tri = h // 3
        first_e = np.unique(tri, return_index=True)[1]
        keep_edge = np.zeros(len(open_h), bool)
        keep_edge[split_e[first_e]] = True
        sel = keep_edge[split_e]
        split_e, split_v, split_s = split_e[sel], split_v[sel], split_s[sel]
        edges = np.unique(split_e)
        eh = open_h[edges]
        # Chains u -> inner vertices (by position) -> w on every split edge.
        chain_e = np.concatenate([edges, split_e, edges])
        chain_v = np.concatenate([u[eh], split_v, w[eh]])
        chain_s = np.concatenate([np.zeros(len(edges)), split_s, np.ones(len(edges))])
        order = np.lexsort((chain_s, chain_e))
        chain_e, chain_v = chain_e[order], chain_v[order]
        link = np.flatnonzero(chain_e[1:] == chain_e[:-1])
        link_h = open_h[chain_e[link]]
        link_t = link_h // 3
        apex = t[link_t, (link_h % 3 + 2) % 3]
        fan = np.column_stack([chain_v[link], chain_v[link + 1], apex])
        drop = np.zeros(len(t), bool)
        drop[eh // 3] = True
        t = np.vstack([t[~drop], fan])
        src = np.concatenate([src[~drop], src[link_t]])
    return v, t, src


def _open_half_edges(t: NDArray[np.int64]) -> NDArray[np.int64]:
    """Half-edges (corner j to j + 1 of each triangle, flattened) whose undirected edge is not used exactly twice."""
    tri_edge = mesh_edges(t)[1].ravel()
    return np.flatnonzero(np.bincount(tri_edge)[tri_edge] != 2)


@njit(cache=True)
def _points_on_edges(
    v: NDArray[np.float64], a: NDArray[np.int64], b: NDArray[np.int64], cand: NDArray[np.int64], tol: float
) -> tuple[NDArray[np.int64], NDArray[np.int64], NDArray[np.float64]]:
    """(edge, vertex, parameter) of candidate vertices strictly inside edges ``a -> b``."""
    out_e = []
    out_v = []
    out_s = []
    for e in range(len(a)):
        ax, ay, az = v[a[e], 0], v[a[e], 1], v[a[e], 2]
        dx, dy, dz = v[b[e], 0] - ax, v[b[e], 1] - ay, v[b[e], 2] - az
        length2 = dx * dx + dy * dy + dz * dz
        if length2 == 0.0:
            continue
        lox, hix = min(ax, ax + dx) - tol, max(ax, ax + dx) + tol
        loy, hiy = min(ay, ay + dy) - tol, max(ay, ay + dy) + tol
        loz, hiz = min(az, az + dz) - tol, max(az, az + dz) + tol
        for k in range(len(cand)):
            c = cand[k]
            px, py, pz = v[c, 0], v[c, 1], v[c, 2]
            if px < lox or px > hix or py < loy or py > hiy or pz < loz or pz > hiz or c == a[e] or c == b[e]:
                continue
            rx, ry, rz = px - ax, py - ay, pz - az
            s = (rx * dx + ry * dy + rz * dz) / length2
            if s <= 1e-7 or s >= 1.0 - 1e-7:  # strictly inside: not an end point
                continue
            qx, qy, qz = rx - s * dx, ry - s * dy, rz - s * dz
            if qx * qx + qy * qy + qz * qz <= tol * tol:
                out_e.append(e)
                out_v.append(c)
                out_s.append(s)
    return np.array(out_e, np.int64), np.array(out_v, np.int64), np.array(out_s, np.float64)


def surface_from_bands(program: Program, bands: Sequence[BandMesh]) -> CSGSurface:
    """Clip the leaves' band meshes against each other along a CSG program.

    Parameters
    ----------
    program : Program
        The tree's flat program (:meth:`isocsg.csg.CSGNode.program`).
    bands : sequence of BandMesh
        One band mesh per leaf, each tiling the leaf's closed surface.

    Returns
    -------
    CSGSurface
        Empty (no triangles) when the result is empty.

    Raises
    ------
    InvalidGeometryError
        If a band mesh cannot be welded into a closed manifold surface.
    InvalidParameterError
        If the program and the band meshes do not match.
    """
    m3 = _manifold3d()
    if not isinstance(program, Program) or program.n_leaves != len(bands):
        raise InvalidParameterError(f"{program!r} does not match {len(bands)} band meshes")
    solids, normals = [], []
    # One original id per leaf: manifold3d tags each result triangle with it.
    first_id = int(m3.Manifold.reserve_ids(len(bands)))
    for i, bm in enumerate(bands):
        v, t, src = close_mesh(bm.vertices, bm.triangles)
        mesh = m3.Mesh64(
            vert_properties=np.ascontiguousarray(v),
            tri_verts=np.ascontiguousarray(t, dtype=np.uint64),
            face_id=np.ascontiguousarray(src, dtype=np.uint64),
            run_index=np.array([0, 3 * len(t)], dtype=np.uint64),
            run_original_id=np.array([first_id + i], dtype=np.uint32),
        )
        mesh.merge()  # nearly equal vertices on open edges (rounding of the cuts)
        solid = m3.Manifold(mesh)
        if solid.status() != m3.Error.NoError:
            raise InvalidGeometryError(f"the band mesh of leaf {i} is not a closed surface ({solid.status()})")
        solids.append(solid)
        normals.append(_triangle_normals(np.asarray(bm.vertices, np.float64), np.asarray(bm.triangles, np.int64)))
    result = program.evaluate(
        lambda i, _: solids[i],
        lambda op, args: args[0] if len(args) == 1 else m3.Manifold.batch_boolean(args, getattr(m3.OpType, _OPS[op])),
    )
    size = max(float(np.ptp(np.asarray(bm.vertices, np.float64), axis=0).max(initial=0.0)) for bm in bands)
    out = _without_sheets(result, size).to_mesh64()  # type: ignore[attr-defined]
    verts = np.asarray(out.vert_properties, dtype=np.float64)[:, :3].reshape(-1, 3)
    tris = np.asarray(out.tri_verts, dtype=np.int64).reshape(-1, 3)
    face = np.asarray(out.face_id, dtype=np.int64).reshape(-1)
    leaf = np.empty(len(tris), np.int32)
    run_index = np.asarray(out.run_index, dtype=np.int64) // 3
    for r, oid in enumerate(np.asarray(out.run_original_id, dtype=np.int64)):
        leaf[run_index[r] : run_index[r + 1]] = int(oid) - first_id
    value = np.empty(len(tris))
    rev = np.zeros(len(tris), bool)
    mine = _triangle_normals(verts, tris)
    for i, bm in enumerate(bands):
        sel = np.flatnonzero(leaf == i)
        s = face[sel]
        rev[sel] = np.einsum("ij,ij->i", mine[sel], normals[i][s]) < 0
        value[sel] = np.where(rev[sel], np.asarray(bm.value_in)[s], np.asarray(bm.value_out)[s])
    return CSGSurface(verts, tris.astype(np.int32), value, leaf, face.astype(np.int32), rev)


def _without_sheets(solid: Any, size: float) -> Any:
    """``solid`` without its connected parts thinner than :data:`SHEET_THICKNESS` times ``size``."""
    parts = solid.decompose()
    keep = [p for p in parts if 2.0 * abs(p.volume()) >= SHEET_THICKNESS * size * p.surface_area()]
    if len(keep) == len(parts):
        return solid
    return type(solid).compose(keep) if keep else type(solid)()


def _triangle_normals(v: NDArray[np.float64], t: NDArray[np.int64]) -> NDArray[np.float64]:
    if not len(t):
        return np.zeros((0, 3))
    return np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])


def csg_surface(
    tree: CSGNode, lights: Sequence[Light], material: Material | None = None, contours: int = 64
) -> CSGSurface:
    """The view-independent band surface of a CSG tree.

    Parameters
    ----------
    tree : CSGNode
    lights : sequence of PointLight or DirectionalLight
    material : Material, optional
        Defaults to ``Material()``. A specular material depends on the eye:
        use :class:`isocsg.render.Renderer`, which passes it.
    contours : int, default 64

    Returns
    -------
    CSGSurface

    Examples
    --------
    >>> from isocsg import PointLight, Sphere
    >>> surf = csg_surface(Sphere((0, 0, 0), 1) - Sphere((1, 0, 0), 1), [PointLight((0, -4, 3))], contours=8)
    >>> sorted(set(surf.leaf.tolist())), bool(surf.reversed[surf.leaf == 1].all())
    ([0, 1], True)
    """
    from ..laminae import build_laminae  # the laminae import the CSG package: import on use
    from ..lighting.lights import Material

    if not isinstance(tree, CSGNode):
        raise InvalidGeometryError(f"tree must be a CSG node, got {type(tree).__name__}")
    program = tree.program()
    leaves = program.leaves
    mat = Material() if material is None else material
    bands = [build_laminae(p, tuple(lights), mat, contours).bands for p in leaves]
    return surface_from_bands(program, bands)
