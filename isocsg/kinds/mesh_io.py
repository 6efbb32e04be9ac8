"""Triangle meshes from files, from polygon faces and from height maps.

- :func:`read_mesh`: STL, OFF, OBJ, PLY and 3MF through trimesh (3MF also needs the ``mesh``
  extra: networkx and lxml), every body of the file in one mesh (duplicate vertices merged, as
  OpenSCAD merges them);
- :func:`polygon_mesh`: the faces of an OpenSCAD ``polyhedron`` (planar polygons, convex or not,
  clockwise seen from outside as OpenSCAD wants them) triangulated without new vertices;
- :func:`height_map`, :func:`read_height_map`: OpenSCAD's ``surface()`` exactly as its
  ``SurfaceNode.cc`` builds it (see :func:`height_map`).
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import InvalidGeometryError, MissingDependencyError
from .mesh import TriangleMesh

__all__ = ["MESH_SUFFIXES", "read_mesh", "polygon_mesh", "polygon_triangles", "reoriented", "bodies", "height_map",
           "read_height_map", "MAX_HEIGHT_MAP_CELLS"]

#: The file types :func:`read_mesh` reads.
MESH_SUFFIXES = (".stl", ".off", ".obj", ".ply", ".3mf")

#: The most cells a height map may have (OpenSCAD makes 4 triangles per cell).
MAX_HEIGHT_MAP_CELLS = 4_000_000


def read_mesh(path: str | os.PathLike[str], *, repair: bool = False) -> TriangleMesh:
    """The closed mesh of a mesh file (every body in it, as one solid).

    Parameters
    ----------
    path : path-like
        A ``.stl``, ``.off``, ``.obj``, ``.ply`` or ``.3mf`` file.
    repair : bool
        Repair an open or inconsistently wound mesh (:meth:`TriangleMesh.repaired`).

    Raises
    ------
    InvalidGeometryError
        If the file is missing, of another type, unreadable, holds no triangles, or its mesh is not
        a valid closed solid (the message says why).
    MissingDependencyError
        For a 3MF file without networkx and lxml (the ``mesh`` extra).
    """
    import trimesh

    p = Path(path)
    suffix = p.suffix.lower()
    if suffix not in MESH_SUFFIXES:
        raise InvalidGeometryError(f"mesh file {str(p)!r} must be one of {', '.join(MESH_SUFFIXES)}, got {suffix!r}")
    if not p.is_file():
        raise InvalidGeometryError(f"mesh file {str(p)!r} does not exist")
    if suffix == ".3mf":
        from importlib.util import find_spec

        if find_spec("networkx") is None or find_spec("lxml") is None:
            raise MissingDependencyError("reading 3MF files needs networkx and lxml: pip install isocsg[mesh]")
    try:
        loaded = trimesh.load(str(p), force="mesh", process=True)
    except Exception as exc:  # noqa: BLE001 - trimesh's readers raise many kinds on a malformed file
        raise InvalidGeometryError(f"mesh file {str(p)!r} could not be read: {type(exc).__name__}: {exc}") from None
    faces = np.asarray(getattr(loaded, "faces", np.zeros((0, 3))))
    if faces.ndim != 2 or len(faces) == 0:
        raise InvalidGeometryError(f"mesh file {str(p)!r} holds no triangles")
    try:
        return TriangleMesh.from_trimesh(loaded, repair=repair)
    except InvalidGeometryError as exc:
        raise InvalidGeometryError(f"mesh file {str(p)!r}: {exc}") from None


def polygon_mesh(points: ArrayLike, faces: list[list[int]], *, clockwise: bool = True) -> TriangleMesh:
    """The solid bounded by planar polygon faces, each triangulated in its own plane (no new vertex).

    Parameters
    ----------
    points : array_like, shape (n, 3)
    faces : list of list of int
        Polygons of at least 3 point indices; faces of fewer distinct ones (after a point repeated
        in turn is taken once) are dropped: they have no area.
    clockwise : bool
        The faces are clockwise seen from outside (OpenSCAD's order). A mesh whose faces all wind
        the other way (a negative volume) is turned over, as OpenSCAD accepts either.

    Raises
    ------
    InvalidGeometryError
        When the faces do not bound a valid closed solid (see :class:`TriangleMesh`).
    """
    P = np.asarray(points, dtype=np.float64)
    return TriangleMesh(P, polygon_triangles(P, faces, clockwise=clockwise))


def polygon_triangles(points: ArrayLike, faces: list[list[int]], *, clockwise: bool = True) -> NDArray[np.int64]:
    """The triangles :func:`polygon_mesh` makes of the faces (counter-clockwise seen from outside
    when the faces agree), before the mesh is checked."""
    from .polygon_faces import triangulate_faces

    P = np.asarray(points, dtype=np.float64)
    T = triangulate_faces(P, faces)
    if clockwise:
        T = T[:, ::-1]
    if len(T) >= 4 and len(P):
        c = 0.5 * (P.min(axis=0) + P.max(axis=0))
        a, b, d = P[T[:, 0]] - c, P[T[:, 1]] - c, P[T[:, 2]] - c
        if float(np.einsum("ij,ij->i", a, np.cross(b, d)).sum()) < 0:
            T = T[:, ::-1]
    return T



def reoriented(vertices: ArrayLike, faces: ArrayLike) -> TriangleMesh:
    """The closed mesh of triangles some of which are wound the wrong way: each connected body's
    faces turned to agree with their neighbours and to face outwards (trimesh's ``fix_normals``).
    No vertex is merged, no face added or dropped.

    Raises
    ------
    InvalidGeometryError
        When an edge does not join exactly two faces (an open or non-manifold mesh, which no
        orientation makes a solid), or the result is not a valid solid (:class:`TriangleMesh`).
    """
    import trimesh

    V = np.asarray(vertices, dtype=np.float64)
    F = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    edges = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    pairs, inverse, counts = np.unique(edges, axis=0, return_inverse=True, return_counts=True)
    if len(counts) and np.any(counts % 2):
        k = int(np.argmax(counts % 2))
        raise InvalidGeometryError(
            f"TriangleMesh.faces cannot be reoriented: the edge {pairs[k, 0]} -> {pairs[k, 1]} joins "
            f"{counts[k]} faces (an open mesh)")
    tm = trimesh.Trimesh(V, F, process=False)
    trimesh.repair.fix_normals(tm, multibody=True)
    return TriangleMesh(np.asarray(tm.vertices), np.asarray(tm.faces))


def bodies(faces: ArrayLike) -> list[NDArray[np.int64]]:
    """The faces of each body of a closed mesh whose bodies touch along edges (an edge joining 4,
    6, ... faces): the sets of faces connected across the edges that join exactly two."""
    import scipy.sparse as sp
    from scipy.sparse.csgraph import connected_components

    F = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    edges = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    _, inverse, counts = np.unique(edges, axis=0, return_inverse=True, return_counts=True)
    inverse = inverse.reshape(-1)
    owner = np.tile(np.arange(len(F)), 3)
    order = np.argsort(inverse, kind="stable")
    e, o = inverse[order], owner[order]
    two = counts[e] == 2
    first = np.flatnonzero(two & (np.r_[True, e[1:] != e[:-1]]))  # the first face of each manifold edge
    a, b = o[first], o[first + 1]
    graph = sp.coo_matrix((np.ones(len(a)), (a, b)), shape=(len(F), len(F)))
    n, label = connected_components(graph, directed=False)
    return [F[label == k] for k in range(n)]


def height_map(heights: ArrayLike, *, center: bool = False, base: float | None = None) -> TriangleMesh:
    """OpenSCAD's ``surface()`` solid of a grid of heights, exactly as its ``SurfaceNode.cc`` builds it.

    Row ``i`` of ``heights`` lies at ``y = i``, column ``j`` at ``x = j`` (``center``: the grid
    centred on the origin, ``x - (columns - 1) / 2``, ``y - (lines - 1) / 2``). Each cell is four
    triangles meeting at its centre, raised to the mean of its four corners; walls go down from the
    boundary to the base ``z = base`` (OpenSCAD's: ``min(heights) - 1``; a ``.dat`` file's minimum
    also counts 1, see :func:`read_height_map`), closed by the flat bottom.

    Raises
    ------
    InvalidGeometryError
        On fewer than 2 rows or columns (OpenSCAD makes no solid), non-finite heights, or more than
        :data:`MAX_HEIGHT_MAP_CELLS` cells.
    """
    H = np.asarray(heights, dtype=np.float64)
    if H.ndim != 2 or H.shape[0] < 2 or H.shape[1] < 2:
        raise InvalidGeometryError(f"surface heights must be a grid of at least 2 x 2 values, got shape {H.shape}")
    if not np.all(np.isfinite(H)):
        raise InvalidGeometryError("surface heights must be finite")
    lines, cols = H.shape
    if (lines - 1) * (cols - 1) > MAX_HEIGHT_MAP_CELLS:
        raise InvalidGeometryError(f"surface heights must have at most {MAX_HEIGHT_MAP_CELLS} cells, got {H.shape}")
    zb = float(H.min() - 1.0 if base is None else base)
    ox = -(cols - 1) / 2.0 if center else 0.0
    oy = -(lines - 1) / 2.0 if center else 0.0
    jj, ii = np.meshgrid(np.arange(cols), np.arange(lines))
    grid = np.stack([ox + jj, oy + ii, H], axis=-1).reshape(-1, 3)  # index i * cols + j
    ci, cj = np.meshgrid(np.arange(1, lines), np.arange(1, cols), indexing="ij")
    vx = (H[:-1, :-1] + H[:-1, 1:] + H[1:, :-1] + H[1:, 1:]) / 4.0
    centres = np.stack([ox + cj - 0.5, oy + ci - 0.5, vx], axis=-1).reshape(-1, 3)
    n_grid = len(grid)
    v1 = ((ci - 1) * cols + (cj - 1)).reshape(-1)
    v2 = ((ci - 1) * cols + cj).reshape(-1)
    v3 = (ci * cols + (cj - 1)).reshape(-1)
    v4 = (ci * cols + cj).reshape(-1)
    c = n_grid + np.arange(len(centres))
    top = np.concatenate([np.stack(t, axis=1) for t in ((v1, v2, c), (v2, v4, c), (v4, v3, c), (v3, v1, c))])
    # the boundary ring of the grid, counter-clockwise seen from above, and its copy at the base
    ring = np.concatenate([np.arange(cols - 1), (np.arange(lines - 1) * cols + cols - 1),
                           (lines - 1) * cols + np.arange(cols - 1, 0, -1), np.arange(lines - 1, 0, -1) * cols])
    low = grid[ring].copy()
    low[:, 2] = zb
    b0 = n_grid + len(centres)
    bottom_c = b0 + len(ring)
    k = np.arange(len(ring))
    up0, up1 = ring, np.roll(ring, -1)
    dn0, dn1 = b0 + k, b0 + np.roll(k, -1)
    walls = np.concatenate([np.stack([dn0, dn1, up1], axis=1), np.stack([dn0, up1, up0], axis=1)])
    bottom = np.stack([np.full(len(ring), bottom_c), dn1, dn0], axis=1)
    V = np.vstack([grid, centres, low, [[ox + (cols - 1) / 2.0, oy + (lines - 1) / 2.0, zb]]])
    F = np.vstack([top, walls, bottom]).astype(np.int64)
    return TriangleMesh._simple(V, F)  # a height field over its grid, walls and a flat base: no crossing


def read_height_map(path: str | os.PathLike[str], *, invert: bool = False) -> tuple[NDArray[np.float64], float]:
    """A ``surface()`` file's heights and the base OpenSCAD puts under them.

    A PNG image (recognised by its signature, as OpenSCAD does): each pixel's luminance
    ``0.2126 R + 0.7152 G + 0.0722 B`` (8-bit channels) maps to ``z = 100 / 255 * pixel``, or with
    ``invert`` to OpenSCAD's ``100 / 255 * (1 - pixel)``; the image's top row is the last line
    (largest y); the base is ``min(z) - 1`` (today's OpenSCAD; 2021.01 put it at ``min(min(z) - 1, 0)``,
    the same for an image with a black pixel or with ``invert``). Otherwise a DAT text file: one line of numbers
    (separated by spaces or tabs) per row, ``#`` comment lines and blank lines skipped, short
    rows padded with 0 as OpenSCAD pads them; the base is ``min(min(values), 1) - 1``
    (``invert`` does not apply).

    Raises
    ------
    InvalidGeometryError
        If the file is missing, a PNG cannot be decoded, or a DAT value is not a number.
    """
    p = Path(path)
    if not p.is_file():
        raise InvalidGeometryError(f"surface file {str(p)!r} does not exist")
    head = p.read_bytes()[:8]
    if head == b"\x89PNG\r\n\x1a\n":
        from PIL import Image, UnidentifiedImageError

        try:
            with Image.open(p) as im:
                rgba = np.asarray(im.convert("RGBA"), dtype=np.float64)
        except (OSError, UnidentifiedImageError, ValueError) as exc:
            raise InvalidGeometryError(f"surface file {str(p)!r} is not a readable PNG image: {exc}") from None
        pixel = 0.2126 * rgba[..., 0] + 0.7152 * rgba[..., 1] + 0.0722 * rgba[..., 2]
        z = 100.0 / 255.0 * ((1.0 - pixel) if invert else pixel)
        z = z[::-1]  # image row 0 is the top: the last line
        return z, float(min(z.min(), 200.0) - 1.0)
    rows: list[list[float]] = []
    for number, raw in enumerate(p.read_text(encoding="utf-8", errors="replace").splitlines(), start=1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        try:
            rows.append([float(tok) for tok in line.replace("\t", " ").split()])
        except ValueError:
            raise InvalidGeometryError(
                f"surface file {str(p)!r}, line {number}: not a number in {line[:40]!r}") from None
    width = max((len(r) for r in rows), default=0)
    H = np.zeros((len(rows), width))
    for i, r in enumerate(rows):
        H[i, : len(r)] = r
    low = min([1.0] + [min(r) for r in rows if r])
    return H, low - 1.0
