"""Conversions to pyvista meshes: band meshes, CSG surfaces, shadow volumes and regions, lux grids.

pyvista (and vtk) are imported when a conversion is called. Every mesh keeps
isocsg's values as cell or point data with their units in the name, so a
plot's scalar bar says what it shows:

- band meshes and surfaces: cell data ``"intensity"`` (the shading value of
  each triangle, 0 black, 1 white), plus ``"value_in"`` and ``"band"`` for a
  :class:`~isocsg.laminae.model.BandMesh`, ``"leaf"`` and ``"reversed"`` for a
  :class:`~isocsg.csg.surface.CSGSurface`;
- shadow volumes: closed convex meshes (clipped to the ``bounds`` given);
- shadow regions on a face: triangulated planar polygons with cell data
  ``"state"`` (0 lit, 1 penumbra, 2 umbra);
- lux grids: a structured grid with point data ``"illuminance_lx"``.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import InvalidParameterError, MissingDependencyError

__all__ = ["import_pyvista", "to_pyvista"]


def import_pyvista() -> Any:
    """The pyvista module, or :class:`MissingDependencyError` naming the extra to install."""
    try:
        import pyvista
    except ImportError as exc:
        raise MissingDependencyError("this needs pyvista; install the extra: pip install 'isocsg[view]'") from exc
    return pyvista


def _triangles(pv: Any, vertices: ArrayLike, triangles: ArrayLike) -> Any:
    v = np.asarray(vertices, dtype=np.float64).reshape(-1, 3)
    t = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    if len(t) == 0:
        return pv.PolyData(v) if len(v) else pv.PolyData()
    return pv.PolyData.from_regular_faces(v, t)


def _polygons_2d(geometry: Any) -> tuple[NDArray[np.float64], NDArray[np.int64]]:
    """Triangulate a shapely (multi)polygon in its plane: points (n, 2), triangles (m, 3)."""
    import manifold3d
    import shapely
    from shapely.geometry.polygon import orient

    pts: list[NDArray[np.float64]] = []
    tris: list[NDArray[np.int64]] = []
    base = 0
    for part in shapely.get_parts(geometry):
        if part.geom_type != "Polygon" or part.is_empty or part.area <= 0:
            continue
        p = orient(part, 1.0)  # exterior counter-clockwise, holes clockwise (manifold3d's rule)
        rings = [np.asarray(p.exterior.coords)[:-1]] + [np.asarray(r.coords)[:-1] for r in p.interiors]
        t = np.asarray(manifold3d.triangulate([np.ascontiguousarray(r[:, :2]) for r in rings]), dtype=np.int64)
        flat = np.vstack([r[:, :2] for r in rings])
        pts.append(flat)
        tris.append(t.reshape(-1, 3) + base)
        base += len(flat)
    if not pts:
        return np.zeros((0, 2)), np.zeros((0, 3), np.int64)
    return np.vstack(pts), np.vstack(tris)


def _face_shadows(pv: Any, fs: Any) -> Any:
    """The lit part, penumbra and umbra of a face as one mesh with cell data ``state``."""
    pieces = [(fs.polygon.difference(fs.penumbra.union(fs.umbra)), 0), (fs.penumbra, 1), (fs.umbra, 2)]
    from ..shadows.classify import FaceType

    if fs.face_type == FaceType.C:
        pieces = [(fs.polygon, 2)]  # a type-C face receives nothing: all umbra
    verts, tris, state = [], [], []
    base = 0
    for geom, s in pieces:
        p2, t = _polygons_2d(geom)
        if not len(t):
            continue
        verts.append(fs.to_3d(p2))
        tris.append(t + base)
        state.append(np.full(len(t), s, np.int8))
        base += len(p2)
    if not verts:
        return pv.PolyData()
    mesh = _triangles(pv, np.vstack(verts), np.vstack(tris))
    mesh.cell_data["state"] = np.concatenate(state)
    return mesh


def _bounds(bounds: ArrayLike | None, what: str) -> NDArray[np.float64]:
    if bounds is None:
        raise InvalidParameterError(
            f"bounds must be given for a {what} (it may be "
            "unbounded), e.g. [[-5, -5, 0], [5, 5, 5]]"
        )
    b = np.asarray(bounds, dtype=np.float64)
    if b.shape != (2, 3) or not np.all(np.isfinite(b)) or np.any(b[1] <= b[0]):
        raise InvalidParameterError(
            "bounds must be a finite [[lo], [hi]] box of "
            f"shape (2, 3) with lo < hi, got {b.tolist()}"
        )
    return b


def _intensity_mesh(
    pv: Any, vertices: ArrayLike, triangles: ArrayLike, intensity: ArrayLike, **cells: NDArray[Any],
) -> Any:
    """Triangles with cell data ``intensity`` (active) and further cell arrays."""
    mesh = _triangles(pv, vertices, triangles)
    mesh.cell_data["intensity"] = np.asarray(intensity, dtype=np.float64)
    for name, values in cells.items():
        mesh.cell_data[name] = values
    mesh.set_active_scalars("intensity", preference="cell")
    return mesh


def _multiblock(pv: Any, blocks: dict[str, Any]) -> Any:
    block = pv.MultiBlock()
    for name, mesh in blocks.items():
        block[name] = mesh
    return block


def _lux_grid(pv: Any, grid: Any, E: ArrayLike | None) -> Any:
    """A lux grid's nodes as a ``StructuredGrid``, with point data ``illuminance_lx`` when ``E`` is given."""
    p = grid.points()  # (ny, nx, 3)
    # StructuredGrid wants x-fastest point order with dimensions (nx, ny, 1).
    sg = pv.StructuredGrid(
        np.ascontiguousarray(p[..., 0].T)[..., None], np.ascontiguousarray(p[..., 1].T)[..., None],
        np.ascontiguousarray(p[..., 2].T)[..., None],
    )
    if E is not None:
        sg.point_data["illuminance_lx"] = np.asarray(E, dtype=np.float64).reshape(-1)
        sg.set_active_scalars("illuminance_lx")
    return sg


def to_pyvista(
    obj: Any,
    *,
    lights: Any = None,
    material: Any = None,
    contours: int | None = None,
    eye: ArrayLike | None = None,
    bounds: ArrayLike | None = None,
    resolution: int = 64,
) -> Any:
    """A pyvista mesh of an isocsg object.

    Parameters
    ----------
    obj : object
        One of:

        - :class:`~isocsg.laminae.model.BandMesh` or
          :class:`~isocsg.laminae.model.LaminaSet`: ``PolyData``, cell data
          ``intensity`` (``value_out``), ``value_in``, ``band``;
        - :class:`~isocsg.csg.surface.CSGSurface` or
          :class:`~isocsg.interop.ShadedSurface`: ``PolyData``, cell data
          ``intensity`` (and ``leaf``, ``reversed`` for a CSG surface);
        - a solid with ``lights``: its shaded surface (the Boolean result for
          a CSG tree, :func:`isocsg.interop.object_surface`); without lights
          its plain triangle mesh (``resolution`` segments per curve);
        - a :class:`~isocsg.scene.Scene`: a ``MultiBlock`` of its objects'
          shaded surfaces;
        - :class:`~isocsg.shadows.volumes.ConvexVolume`: ``PolyData`` of the
          volume inside ``bounds``; :class:`~isocsg.shadows.volumes.ShadowVolumes`:
          ``MultiBlock`` with blocks ``"penumbra"`` and ``"umbra"``;
        - :class:`~isocsg.shadows.regions.FaceShadows`: ``PolyData`` of the
          face with cell data ``state`` (0 lit, 1 penumbra, 2 umbra); a list
          of them: a ``MultiBlock``;
        - :class:`~isocsg.shadows.luxmap.LuxMap`: ``StructuredGrid`` with point
          data ``illuminance_lx``; a :class:`~isocsg.shadows.luxmap.LuxGrid`:
          the grid's nodes.
    lights, material, contours, eye : keyword-only
        For solids: how the bands are built (see :func:`isocsg.build_laminae`;
        ``contours`` defaults to 64, for a scene to ``scene.render.contours``).
    bounds : array_like, shape (2, 3), keyword-only
        The box a shadow volume (possibly unbounded) is clipped to.
    resolution : int, keyword-only, default 64
        Segments per curve for a solid's plain mesh.

    Returns
    -------
    pyvista.DataSet

    Raises
    ------
    MissingDependencyError
        If pyvista is not installed.
    InvalidParameterError
        On an unsupported object, or a shadow volume without ``bounds``.

    Examples
    --------
    >>> from isocsg import Box, Cylinder, PointLight
    >>> plate = Box((0, 0, 0), (2, 2, 0.2)) - Cylinder((0, 0, 0), (0, 0, 1), 0.4)
    >>> mesh = to_pyvista(plate, lights=[PointLight((2, -3, 4))], contours=8)  # doctest: +SKIP
    >>> mesh.n_cells == len(mesh.cell_data["intensity"])  # doctest: +SKIP
    True
    """
    from ..csg.surface import CSGSurface
    from ..kinds import Solid
    from ..laminae.model import BandMesh, LaminaSet
    from ..scene.model import Scene
    from ..shadows.luxmap import LuxGrid, LuxMap
    from ..shadows.regions import FaceShadows
    from ..shadows.volumes import ConvexVolume, ShadowVolumes
    from .bands import ShadedSurface, object_surface, scene_surfaces

    pv = import_pyvista()
    if isinstance(obj, LaminaSet):
        obj = obj.bands
    if isinstance(obj, BandMesh):
        return _intensity_mesh(
            pv, obj.vertices, obj.triangles, obj.value_out,
            value_in=np.asarray(obj.value_in, dtype=np.float64), band=np.asarray(obj.band, dtype=np.int32),
        )
    if isinstance(obj, CSGSurface):
        return _intensity_mesh(
            pv, obj.vertices, obj.triangles, obj.value,
            leaf=np.asarray(obj.leaf, dtype=np.int32), reversed=np.asarray(obj.reversed, dtype=np.uint8),
        )
    if isinstance(obj, ShadedSurface):
        return _intensity_mesh(pv, obj.vertices, obj.triangles, obj.value)
    if isinstance(obj, Scene):
        return _multiblock(pv, {s.name: to_pyvista(s) for s in scene_surfaces(obj, contours=contours)})
    if isinstance(obj, Solid):
        if lights is None:
            return pv.wrap(obj.to_trimesh(resolution))
        return to_pyvista(object_surface(obj, lights, material, 64 if contours is None else contours, eye=eye))
    if isinstance(obj, ShadowVolumes):
        b = _bounds(bounds, "shadow volume")
        parts = {"penumbra": to_pyvista(obj.penumbra, bounds=b), "umbra": to_pyvista(obj.umbra, bounds=b)}
        return _multiblock(pv, parts)
    if isinstance(obj, ConvexVolume):
        tm = obj.to_trimesh(_bounds(bounds, "shadow volume"))
        return pv.PolyData() if tm is None else pv.wrap(tm)
    if isinstance(obj, FaceShadows):
        return _face_shadows(pv, obj)
    if isinstance(obj, (list, tuple)) and obj and all(isinstance(f, FaceShadows) for f in obj):
        return _multiblock(pv, {f"face{k}": _face_shadows(pv, f) for k, f in enumerate(obj)})
    if isinstance(obj, (LuxMap, LuxGrid)):
        return _lux_grid(pv, obj.grid if isinstance(obj, LuxMap) else obj, obj.E if isinstance(obj, LuxMap) else None)
    raise InvalidParameterError(f"to_pyvista: unsupported object of type {type(obj).__name__}")
