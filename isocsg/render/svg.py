"""Vector output: a scene's front bands as SVG polygons, back to front.

Within one convex primitive the front-facing band triangles do not overlap on
screen, so their order does not matter. Between objects, the order comes from
the depth test itself: each object is filled alone, and wherever two objects
cover the same pixel the farther one must be drawn first. A topological sort
of these relations is a true back-to-front order when one exists (it does for
objects that do not interpenetrate and do not overlap cyclically).
"""

from __future__ import annotations

import os
from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

from ..camera import Camera
from ..errors import InvalidParameterError
from ..geometry.primitives import Primitive
from ..scene.model import Scene
from .image import save_svg
from .painter import Renderer, default_renderer
from .raster import homogeneous

__all__ = ["scene_polygons", "save_scene_svg"]


def _order(depths: Sequence[NDArray[np.float64]]) -> list[int]:
    """Back-to-front order of objects from their per-pixel depths (inf where absent)."""
    n = len(depths)
    behind = [set() for _ in range(n)]  # behind[a]: objects that must be drawn before a
    for a in range(n):
        for b in range(a + 1, n):
            both = np.isfinite(depths[a]) & np.isfinite(depths[b])
            if not both.any():
                continue
            a_front = depths[a][both] < depths[b][both]
            if a_front.all():
                behind[a].add(b)
            elif not a_front.any():
                behind[b].add(a)
            else:
                raise InvalidParameterError(
                    f"objects {a} and {b} are each in front of the other somewhere: no back-to-front order"
                )
    order: list[int] = []
    done: set[int] = set()
    while len(order) < n:
        ready = [k for k in range(n) if k not in done and behind[k] <= done]
        if not ready:
            raise InvalidParameterError("the objects overlap cyclically: no back-to-front order")
        # Farthest first among the ready ones keeps the file stable and readable.
        ready.sort(key=lambda k: -float(np.nanmax(np.where(np.isfinite(depths[k]), depths[k], np.nan), initial=-np.inf)))
        order.append(ready[0])
        done.add(ready[0])
    return order


def scene_polygons(
    scene: Scene,
    *,
    camera: Camera | None = None,
    contours: int | None = None,
    renderer: Renderer | None = None,
) -> tuple[list[NDArray[np.float64]], NDArray[np.float64]]:
    """Screen polygons of the visible bands, back to front.

    Parameters
    ----------
    scene : Scene
        Every object must be a single primitive (CSG trees have no polygon
        form here; render them as images).
    camera : Camera, optional
    contours : int, optional
    renderer : Renderer, optional
        Supplies the band meshes (and their cache); the default renderer otherwise.

    Returns
    -------
    polygons : list of ndarray, each shape (3, 2)
        Front-facing band triangles in pixel coordinates ``(col, row)``.
    values : ndarray, shape (n,)
        Their intensities.

    Raises
    ------
    InvalidParameterError
        For CSG objects, geometry behind the eye, or objects without a
        back-to-front order.
    """
    r = default_renderer() if renderer is None else renderer
    cam = scene.camera if camera is None else camera
    n_contours = scene.render.contours if contours is None else contours
    per_object: list[tuple[NDArray[np.float64], NDArray[np.float64]]] = []
    depths = []
    for k, obj in enumerate(scene.objects):
        if not isinstance(obj.shape, Primitive):
            raise InvalidParameterError(f"objects[{k}] is a CSG tree; SVG output takes primitives only")
        bands = r.bands(obj.shape, scene.lights, obj.material, n_contours, cam.eye)
        h = homogeneous(cam, bands.vertices)
        if np.any(h[3] <= 0):
            raise InvalidParameterError(f"objects[{k}] reaches behind the eye; SVG output needs it in front")
        xy = np.stack([h[0] / h[2], h[1] / h[2]], axis=1)
        tri = xy[np.asarray(bands.triangles)]
        e1, e2 = tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]
        front = e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0] < 0  # rows grow downwards
        per_object.append((tri[front], np.asarray(bands.value_out, dtype=np.float64)[front]))
        alone = r.render(Scene(cam, scene.lights, [obj], scene.render), contours=n_contours)
        depths.append(alone.depth.copy())
    polys: list[NDArray[np.float64]] = []
    vals: list[NDArray[np.float64]] = []
    for k in _order(depths):
        tri, v = per_object[k]
        polys.extend(tri)
        vals.append(v)
    return polys, (np.concatenate(vals) if vals else np.zeros(0))


def save_scene_svg(
    path: str | os.PathLike[str],
    scene: Scene,
    *,
    camera: Camera | None = None,
    contours: int | None = None,
    decimals: int = 2,
) -> None:
    """Write the scene's visible bands as an SVG file (see :func:`scene_polygons`).

    Examples
    --------
    >>> import os, tempfile
    >>> from isocsg import Box, Camera, PointLight, Scene
    >>> from isocsg.laminae.model import BandMesh
    >>> from isocsg.render import Renderer
    >>> def faces(primitive, lights, material, contours, *, eye):
    ...     poly = primitive.to_polyhedron()
    ...     t = np.asarray(poly.triangles, dtype=np.int32)
    ...     level = np.full(len(t), 0.5)
    ...     return BandMesh(poly.hull_vertices, t, level, level, np.zeros(len(t), np.int32))
    >>> scene = Scene(Camera((2, -5, 3), (0, 0, 0), width=40, height=30),
    ...               [PointLight((3, -5, 4))], [Box((0, 0, 0), (1, 1, 1))])
    >>> polys, values = scene_polygons(scene, renderer=Renderer(build_laminae=faces))
    >>> len(polys)  # three faces seen, two triangles each
    6
    """
    cam = scene.camera if camera is None else camera
    polys, vals = scene_polygons(scene, camera=cam, contours=contours)
    save_svg(path, polys, vals, width=cam.width, height=cam.height, decimals=decimals)
