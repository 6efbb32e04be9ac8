"""An engine's mesh against the true solid: errors, topology, and what the tessellation explains.

:func:`compare_mesh` measures a trimesh, manifold3d or pyvista mesh against a primitive or CSG
tree and against the *tessellation reference*: the same tree meshed by isocsg at the engine's
segment count (:func:`isocsg.csg.mesh.to_manifold`: the leaves tessellated as manifold3d does,
combined by manifold3d's exact mesh Booleans). The tessellation reference's own errors are what
the tessellation alone explains; an engine whose errors exceed them (by the factor ``slack`` and
a floor of 1e-9 of the solid's size) did something else, and the report says ``wrong``.

- volume and area errors against :func:`~isocsg.testing.figures.reference`. The volume is
  judged against a bound that no Boolean engine computes: the volume of a Boolean of the
  tessellated leaves differs from the true one by at most the sum over the leaves of
  ``V(leaf) - V(leaf's mesh)`` (the symmetric difference of the results lies in the union of
  the leaves' symmetric differences, and a mesh with its vertices on a convex leaf lies inside
  it; for a torus, not convex, the sum is of ``|V(leaf) - V(mesh)|`` and not a proof). The area
  has no such bound: it is judged against the tessellation reference's own area error;
- the two-sided Hausdorff distance, estimated by sampling: points on the mesh (its vertices and
  ``samples`` uniform surface samples) get the true solid's certified signed distance
  (:mod:`isocsg.testing.distance`), points on the true surface (a fine manifold3d mesh's
  samples projected onto the leaf they are nearest to and kept where that projection is on
  the result's boundary) get their distance to the mesh (VTK's exact point-to-triangle distance);
- watertightness, winding consistency, components and genus. The mesh's genus is
  ``components - chi / 2`` from its Euler characteristic ``chi = V - E + F``, in the mesh's own
  connectivity for a manifold3d mesh and with vertices merged by position for a triangle soup.
  The true solid's topology (:func:`true_topology`) of an all-planar tree (boxes and convex
  polyhedra) comes from its exact boundary polygons (:mod:`isocsg.testing.planar_topology`:
  no mesh engine is involved, so manifold3d is not judged by itself); for a tree with a curved
  leaf it is read from a fine manifold3d mesh (256 segments per circle) in its own
  connectivity. Where sheets of the result touch (at an edge or a vertex of the polygons; in
  the fine mesh, distinct vertices at one position: a tangential contact, where the
  regularised solid is not a manifold), components and genus depend on how a mesh separates
  or joins the sheets, and a differing mesh is reported ``not comparable``, not ``wrong``.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .._validation import integer
from ..csg.mesh import to_manifold
from ..csg.section import solid_program
from ..errors import InvalidParameterError
from ..kinds import Solid
from .area import _Tree
from .distance import signed_distance
from .figures import Reference, reference

__all__ = ["MeshComparison", "Topology", "as_trimesh", "compare_mesh", "compare_topology", "distance_to_mesh",
           "topology", "true_topology"]

#: The true solid's topology is read from a manifold3d mesh with this many segments per circle.
FINE_SEGMENTS = 256


@dataclass(frozen=True, slots=True)
class Topology:
    """Closed-surface topology of a mesh: ``components`` (connected surface pieces), ``genus``
    (summed over them), ``euler`` (V - E + F), ``watertight``, ``winding_consistent``,
    ``nonmanifold_edges`` (edges of more than two triangles), ``oriented`` (every edge used as
    often in one direction as in the other: closed and consistently wound, even where sheets meet
    at an edge), ``touching`` (distinct vertices of the mesh's own connectivity at one
    position: sheets that meet there), ``voids`` (components whose enclosed volume is negative:
    the inner shells of cavities) and ``source``: ``"mesh"`` (read from a mesh) or
    ``"polygons"`` (the exact boundary polygons of an all-planar tree, :func:`true_topology`)."""

    components: int
    genus: float
    euler: int
    watertight: bool
    winding_consistent: bool
    nonmanifold_edges: int = 0
    oriented: bool = True
    touching: bool = False
    voids: int = 0
    source: str = "mesh"


@dataclass(frozen=True, slots=True)
class MeshComparison:
    """What :func:`compare_mesh` measured (lengths in metres, signed errors mesh minus truth).

    ``tess_*`` are the same figures for the tessellation reference, ``tess_volume_bound`` the most
    volume error an exact Boolean of the tessellated leaves can have (the sum over the leaves of
    their meshes' volume deficits); ``verdicts`` maps each check to ``"exact"``,
    ``"tessellation"`` (within what the tessellation explains) or ``"wrong"``.
    """

    volume: float
    volume_true: float
    volume_error: float
    area: float
    area_true: float
    area_error: float
    hausdorff_mesh_to_true: float
    hausdorff_true_to_mesh: float
    topology: Topology
    topology_true: Topology
    segments: int | None
    tess_volume_error: float
    tess_volume_bound: float
    tess_area_error: float
    tess_hausdorff: float
    verdicts: tuple[tuple[str, str], ...]

    @property
    def wrong(self) -> list[str]:
        """The checks judged ``"wrong"``."""
        return [k for k, v in self.verdicts if v == "wrong"]

    @property
    def ok(self) -> bool:
        """No check is ``"wrong"``."""
        return not self.wrong

    def summary(self) -> str:
        """A few readable lines."""
        v = dict(self.verdicts)
        t, tt = self.topology, self.topology_true
        lines = [
            (f"volume    {self.volume:.9g} (true {self.volume_true:.9g}): error {self.volume_error:+.3e}, "
             f"tessellation {self.tess_volume_error:+.3e}, bound {self.tess_volume_bound:.3e} -> {v['volume']}"),
            (f"area      {self.area:.9g} (true {self.area_true:.9g}): error {self.area_error:+.3e}, "
             f"tessellation {self.tess_area_error:+.3e} -> {v['area']}"),
            (f"hausdorff mesh->true {self.hausdorff_mesh_to_true:.3e}, true->mesh {self.hausdorff_true_to_mesh:.3e}, "
             f"tessellation {self.tess_hausdorff:.3e} -> {v['hausdorff']}"),
            (f"topology  {t.components} components, genus {t.genus:g}, watertight {t.watertight}, winding "
             f"consistent {t.winding_consistent} (true: {tt.components}, genus {tt.genus:g}, from {tt.source}) "
             f"-> {v['topology']}"),
            "verdict   " + ("OK (tessellation only)" if self.ok else "WRONG: " + ", ".join(self.wrong)),
        ]
        return "\n".join(lines)

    def __str__(self) -> str:
        return self.summary()


def _manifold_mesh(mesh: Any) -> Any:
    """A manifold3d solid's mesh in double precision (``to_mesh`` rounds the coordinates to
    float32: a 1e-4 thick plate at z = -0.75 would come back 1.7e-8 thicker), or a mesh as given."""
    if hasattr(mesh, "to_mesh64"):
        return mesh.to_mesh64()
    return mesh.to_mesh() if hasattr(mesh, "to_mesh") else mesh


def as_trimesh(mesh: Any) -> Any:
    """A ``trimesh.Trimesh`` (vertices merged) from a trimesh, manifold3d or pyvista mesh.

    Raises
    ------
    InvalidParameterError
        For anything else (the message names ``mesh``).
    """
    import trimesh

    if isinstance(mesh, trimesh.Trimesh):
        v, f = np.array(mesh.vertices, dtype=np.float64), np.array(mesh.faces, dtype=np.int64)
    elif type(mesh).__module__.startswith("manifold3d"):
        m = _manifold_mesh(mesh)
        v = np.asarray(m.vert_properties, dtype=np.float64)[:, :3]
        f = np.asarray(m.tri_verts, dtype=np.int64).reshape(-1, 3)
    elif hasattr(mesh, "faces") and hasattr(mesh, "points") and hasattr(mesh, "triangulate"):
        tri = mesh.triangulate()
        v = np.asarray(tri.points, dtype=np.float64)
        f = np.asarray(tri.faces, dtype=np.int64).reshape(-1, 4)[:, 1:]
    else:
        raise InvalidParameterError(f"mesh must be a trimesh.Trimesh, manifold3d Manifold/Mesh or pyvista PolyData, "
                                    f"got {type(mesh).__name__}")
    out = trimesh.Trimesh(v, f, process=False)
    out.merge_vertices(merge_tex=True, merge_norm=True)
    return out


def _indexed(mesh: Any) -> tuple[NDArray[np.float64], NDArray[np.int64], bool]:
    """Vertices and triangles in the mesh's own connectivity, and whether it has one: a manifold3d
    mesh is indexed (its vertices are shared by construction; coincident ones stay apart), any
    other mesh is a triangle soup whose vertices are merged by position."""
    if type(mesh).__module__.startswith("manifold3d"):
        m = _manifold_mesh(mesh)
        v = np.asarray(m.vert_properties, dtype=np.float64)[:, :3]
        f = np.asarray(m.tri_verts, dtype=np.int64).reshape(-1, 3)
        src, dst = np.asarray(m.merge_from_vert, dtype=np.int64), np.asarray(m.merge_to_vert, dtype=np.int64)
        if len(src):  # property seams: the same vertex written twice
            to = np.arange(len(v))
            to[src] = dst
            f = to[f]
        return v, f, True
    t = as_trimesh(mesh)
    return np.asarray(t.vertices, dtype=np.float64), np.asarray(t.faces, dtype=np.int64), False


def topology(mesh: Any) -> Topology:
    """The :class:`Topology` of a mesh (any type :func:`as_trimesh` accepts).

    A manifold3d mesh is read in its own connectivity, so that sheets of the result that touch at
    coincident vertices (a tangential contact) stay separate surfaces; a triangle soup has its
    vertices merged by position, and touching sheets then show as non-manifold edges.
    """
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    v, f, indexed = _indexed(mesh)
    if len(f) == 0:
        return Topology(0, 0.0, 0, True, True)
    used = np.unique(f)
    touching = False
    if indexed:
        pos = np.ascontiguousarray(v[used]).view(np.dtype((np.void, 24))).ravel()
        touching = len(np.unique(pos)) < len(used)
    directed = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
    nv = int(f.max()) + 1
    dkey = directed[:, 0] * nv + directed[:, 1]  # edges as integers: np.unique on rows is slow
    ukey = np.minimum(directed[:, 0], directed[:, 1]) * nv + np.maximum(directed[:, 0], directed[:, 1])
    und, inverse, count = np.unique(ukey, return_inverse=True, return_counts=True)
    _, dcount = np.unique(dkey, return_counts=True)
    forward = np.bincount(inverse.ravel(), weights=directed[:, 0] < directed[:, 1], minlength=len(und))
    euler = len(used) - len(und) + len(f)
    # faces joined across the edges of exactly two triangles: touching sheets stay apart
    face = np.tile(np.arange(len(f)), 3)
    two = count[inverse.ravel()] == 2
    order = np.argsort(inverse.ravel()[two], kind="stable")
    pairs = face[two][order].reshape(-1, 2)
    adj = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(len(f), len(f)))
    comps, label = connected_components(adj, directed=False)
    c = v[used].mean(axis=0)  # the enclosed volume of each component, about a point near it
    a, b, d = v[f[:, 0]] - c, v[f[:, 1]] - c, v[f[:, 2]] - c
    vol = np.bincount(label, weights=np.einsum("ij,ij->i", a, np.cross(b, d)) / 6.0, minlength=comps)
    tiny = 1e-12 * float(np.max(np.ptp(v[used], axis=0))) ** 3  # a sliver's sign is rounding
    return Topology(int(comps), comps - euler / 2.0, int(euler), bool(np.all(count == 2)), bool(np.all(dcount == 1)),
                    int(np.count_nonzero(count > 2)), bool(np.all(2 * forward == count)), touching,
                    int(np.count_nonzero(vol < -tiny)))


def true_topology(solid: Solid) -> Topology:
    """The topology of the true solid's boundary.

    For an all-planar tree (boxes and convex polyhedra) from its exact boundary polygons
    (:func:`isocsg.testing.planar_topology.planar_topology`; ``source == "polygons"``): sheets
    that touch at an edge or a vertex are kept apart across the solid and ``touching`` says so.
    Otherwise, and where the polygons fail (an overlay that fails on both grids, or polygons
    that do not close), from a manifold3d mesh in its own connectivity (``source == "mesh"``):
    at 256 segments per circle with a curved leaf, or the exact Boolean of an all-planar tree.
    """
    from .planar_topology import planar_topology

    prog = solid_program(solid)
    planar = all(p.polyhedral and p.convex for p in prog.leaves)
    exact = planar_topology(solid) if planar else None
    if exact is None:
        return topology(to_manifold(solid, 8 if planar else FINE_SEGMENTS))
    return Topology(exact.components, float(exact.genus), exact.euler, True, True, 0, True, exact.touching,
                    exact.voids, "polygons")


def _true_surface_points(
    solid: Solid, n: int, rng: np.random.Generator, fine_mesh: Any = None,
) -> NDArray[np.float64]:
    """Points on the true boundary: a fine mesh's samples projected onto their nearest leaf, kept
    where the projection is on the result's boundary."""
    import trimesh

    fine = as_trimesh(to_manifold(solid, FINE_SEGMENTS) if fine_mesh is None else fine_mesh)
    if len(fine.faces) == 0:
        return np.zeros((0, 3))
    p, _ = trimesh.sample.sample_surface(fine, n, seed=int(rng.integers(2**31)))
    prog = solid_program(solid)
    tree = _Tree(prog)
    sd = np.stack([np.abs(np.asarray(lf.signed_distance(p))) for lf in prog.leaves])
    near = np.argmin(sd, axis=0)
    keep: list[NDArray[np.float64]] = []
    every = np.arange(prog.n_leaves)
    for i in np.unique(near).tolist():
        sel = np.flatnonzero(near == i)
        prim = prog.leaves[i]
        f = np.asarray(prim.signed_distance(p[sel]))
        q = p[sel] - f[:, None] * tree.normals(i, p[sel])
        on, _ = tree.classify(i, every[every != i], q, tree.normals(i, q), owner=False)
        keep.append(q[on & (np.abs(np.asarray(prim.signed_distance(q))) <= 1e3 * tree.tol)])
    return np.concatenate(keep) if keep else np.zeros((0, 3))


def _mesh_to_true(m: Any, solid: Solid, n: int, rng: np.random.Generator) -> float:
    import trimesh

    if len(m.faces) == 0:
        return math.inf
    p, _ = trimesh.sample.sample_surface(m, n, seed=int(rng.integers(2**31)))
    d = signed_distance(solid, np.concatenate([p, m.vertices]))
    return float(np.max(d.lower))  # certified not to overstate; equal to the distance where exact


def distance_to_mesh(mesh: Any, points: NDArray[np.float64]) -> NDArray[np.float64]:
    """Unsigned distance from points to a triangle mesh (VTK's exact point-to-cell distance,
    through pyvista's VTK; the ``view`` extra)."""
    try:
        import pyvista as pv
        from vtkmodules.vtkFiltersCore import vtkImplicitPolyDataDistance
    except ImportError:  # pragma: no cover
        raise InvalidParameterError(
            "compare_mesh needs pyvista for distances to a mesh: pip install isocsg[view]"
        ) from None
    m = as_trimesh(mesh)
    faces = np.hstack([np.full((len(m.faces), 1), 3), m.faces]).ravel()
    poly = pv.PolyData(np.asarray(m.vertices), faces)
    f = vtkImplicitPolyDataDistance()
    f.SetInput(poly)
    out = np.empty(len(points))
    for k, q in enumerate(np.asarray(points, dtype=np.float64).tolist()):
        out[k] = abs(f.EvaluateFunction(q))
    return out


def _topology_verdict(topo: Topology, tess: Topology, true: Topology) -> str:
    """``exact`` / ``tessellation`` when closed and equal to the true / tessellation reference's
    (the tessellation reference is not used where the truth comes from the polygons: an
    all-planar tree has no tessellation, and its reference mesh is manifold3d's own Boolean);
    ``not comparable`` where the true result has sheets that touch (a tangential contact: the
    regularised solid is not a manifold there, and an engine may join or separate the sheets)
    and the mesh differs but is closed and oriented at every edge (a soup whose merged vertices
    make the touching edges non-manifold); ``wrong`` otherwise (a hole or a flipped face stays
    wrong where sheets touch)."""
    same = lambda a, b: (a.components, a.genus) == (b.components, b.genus)  # noqa: E731
    closed = topo.watertight and topo.winding_consistent
    if closed and same(topo, true):
        return "exact"
    by_polygons = true.source == "polygons"
    if closed and not by_polygons and same(topo, tess):
        return "tessellation"
    touching = true.touching or (tess.touching and not by_polygons)
    return "not comparable" if touching and topo.oriented else "wrong"


def _verdict(err: float, tess: float, floor: float, slack: float) -> str:
    if abs(err) <= floor:
        return "exact"
    return "tessellation" if abs(err) <= slack * abs(tess) + floor else "wrong"


def compare_mesh(
    mesh: Any, solid: Solid, *, segments: int | None = None, samples: int = 4000, slack: float = 1.5,
    ref: Reference | None = None, seed: int = 0,
) -> MeshComparison:
    """Compare an engine's mesh of ``solid`` with the truth and with the tessellation reference.

    Parameters
    ----------
    mesh : trimesh.Trimesh, manifold3d.Manifold or pyvista.PolyData
    solid : Solid
        The primitive or CSG tree the mesh should be.
    segments : int, optional
        Segments per circle the engine used for the curved leaves; None for an all-planar tree
        (tessellation explains nothing) or to take the count (a power of two, 8 .. 512) whose
        isocsg mesh has the vertex count nearest the mesh's.
    samples : int, default 4000
        Surface samples on each side for the Hausdorff estimates, 100 .. 10**6.
    slack : float, default 1.5
        An error up to ``slack`` times the tessellation reference's (plus a floor) is "tessellation".
    ref : Reference, optional
        Reuse the truth (:func:`~isocsg.testing.figures.reference` at ``tol=1e-9``).
    seed : int, default 0
        Seeds the surface sampling.

    Returns
    -------
    MeshComparison

    Raises
    ------
    InvalidParameterError
        On an unsupported mesh type or bad parameters.
    """
    n = integer("samples", samples, low=100, high=10**6, error=InvalidParameterError)
    m = as_trimesh(mesh)
    truth = reference(solid) if ref is None else ref
    rng = np.random.default_rng(seed)
    prog = solid_program(solid)
    size = float(np.max(truth.bounds[1] - truth.bounds[0]))
    planar = all(p.polyhedral and p.convex for p in prog.leaves)
    if segments is None and not planar:
        segments = _guess_segments(solid, len(m.vertices))
    tess_seg = 8 if segments is None else integer("segments", segments, low=3, high=65536, error=InvalidParameterError)
    tz = _tessellation(solid, tess_seg, n, seed, planar)
    vol = float(m.volume) if len(m.faces) else 0.0
    area = float(m.area) if len(m.faces) else 0.0
    floor = 1e-9
    vol_floor = floor * size**3 + 2 * truth.volume_error
    # an empty mesh is right for a result whose volume is rounding (A - A: about 1e-17)
    h_mt = _mesh_to_true(m, solid, n, rng) if len(m.faces) else (0.0 if truth.volume <= vol_floor else math.inf)
    h_tm = 0.0
    if len(tz.true_points) and len(m.faces):
        h_tm = float(np.max(distance_to_mesh(m, tz.true_points)))
    elif len(tz.true_points):
        h_tm = math.inf
    topo = topology(mesh)
    topo_true = _true_topology(solid) if planar else tz.topology_true
    topo_v = _topology_verdict(topo, tz.topology, topo_true)
    vol_err = vol - truth.volume
    vol_v = "exact" if abs(vol_err) <= vol_floor else (
        "tessellation" if abs(vol_err) <= tz.volume_bound + vol_floor else "wrong")
    verdicts = (
        ("volume", vol_v),
        ("area", _verdict(area - truth.area, tz.area - truth.area, floor * size**2 + 2 * truth.area_error, slack)),
        ("hausdorff", _verdict(max(h_mt, h_tm), tz.hausdorff, floor * size, slack)),
        ("topology", topo_v),
    )
    tv, ta, h_tess = tz.volume, tz.area, tz.hausdorff
    return MeshComparison(vol, truth.volume, vol_err, area, truth.area, area - truth.area, h_mt, h_tm,
                          topo, topo_true, segments, tv - truth.volume, tz.volume_bound, ta - truth.area, h_tess,
                          verdicts)


@dataclass(frozen=True, slots=True, eq=False)
class _Tessellated:
    volume: float
    area: float
    hausdorff: float
    topology: Topology
    topology_true: Topology
    true_points: NDArray[np.float64]
    volume_bound: float


@functools.lru_cache(maxsize=4)
def _tessellation(solid: Solid, segments: int, n: int, seed: int, planar: bool) -> _Tessellated:
    """The tessellation reference's figures (kept for the few last solids: several engines' meshes
    of one tree are compared in a row)."""
    rng = np.random.default_rng(seed + 1)
    tess = as_trimesh(to_manifold(solid, segments))
    tv, ta = (float(tess.volume), float(tess.area)) if len(tess.faces) else (0.0, 0.0)
    fine = to_manifold(solid, FINE_SEGMENTS)
    tp = _true_surface_points(solid, n, rng, fine)
    h = _mesh_to_true(tess, solid, n, rng) if len(tess.faces) else 0.0
    if len(tp) and len(tess.faces):
        h = max(h, float(np.max(distance_to_mesh(tess, tp))))
    topo = topology(tess)
    topo_true = topology(fine) if not planar else topo  # compare_mesh takes a planar tree's from the polygons
    # |V(op(A', B', ...)) - V(op(A, B, ...))| <= sum |A' xor A| = sum (V(A) - V(A')) for meshes A'
    # inscribed in convex leaves A: the volume error any exact Boolean of the tessellated leaves may have
    bound = 0.0
    for leaf in solid_program(solid).leaves:
        lm = to_manifold(leaf, segments)
        bound += abs(float(leaf.volume) - float(lm.volume()))
    return _Tessellated(tv, ta, h, topo, topo_true, tp, bound)


def compare_topology(
    mesh: Any, solid: Solid, *, segments: int | None = None,
) -> tuple[Topology, Topology, str]:
    """Only the topology part of :func:`compare_mesh`: the mesh's :class:`Topology`, the true
    one (:func:`true_topology`) and the verdict, against the tessellation
    reference at ``segments`` (8 for an all-planar tree; None: guessed as in
    :func:`compare_mesh`). No volume, area or distance is computed.

    Raises
    ------
    InvalidParameterError
        On an unsupported mesh type or a bad ``segments``.
    """
    topo = topology(mesh)
    prog = solid_program(solid)
    planar = all(p.polyhedral and p.convex for p in prog.leaves)
    if segments is None and not planar:
        segments = _guess_segments(solid, len(as_trimesh(mesh).vertices))
    seg = 8 if segments is None else integer("segments", segments, low=3, high=65536, error=InvalidParameterError)
    tess = _tess_topology(solid, seg)
    true = _true_topology(solid) if planar else topology(to_manifold(solid, FINE_SEGMENTS))
    return topo, true, _topology_verdict(topo, tess, true)


@functools.lru_cache(maxsize=8)
def _true_topology(solid: Solid) -> Topology:
    return true_topology(solid)  # several engines' meshes of one tree are compared in a row


@functools.lru_cache(maxsize=4)
def _tess_topology(solid: Solid, segments: int) -> Topology:
    return topology(to_manifold(solid, segments))


def _guess_segments(solid: Solid, vertices: int) -> int:
    best, best_d = 32, math.inf
    for s in (8, 16, 32, 64, 128, 256, 512):
        v = len(to_manifold(solid, s).to_mesh().vert_properties)
        d = abs(math.log(max(v, 1) / max(vertices, 1)))
        if d < best_d:
            best, best_d = s, d
    return best
