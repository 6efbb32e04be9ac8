"""Vector output: a scene's visible bands as SVG polygons, back to front.

An SVG viewer paints polygons in file order, so the file must hold a true
back-to-front order of polygons that do not interpenetrate. It is built in two
levels:

- **Within one object.** The object is a single convex primitive and only its
  front-facing band triangles are kept (the ones the renderer fills). On a
  closed convex surface these do not overlap on screen, so any order is
  correct; they are nevertheless written farthest first (by their farthest
  vertex), which also keeps band meshes that are only nearly convex (points on
  a curved surface) in a sensible order.
- **Between objects.** Each object is filled alone with the depth-tested
  renderer; wherever two objects cover the same pixel, the farther one must be
  drawn first. A topological sort of these pairwise relations is a true
  back-to-front order whenever one exists.

Limits:

- CSG trees have no polygon form here (their visible surface is decided per
  pixel); objects that are CSG trees are rejected: render them as images.
- Objects that interpenetrate, or that overlap cyclically (A before B before
  C before A), have no back-to-front order of whole objects and are rejected.
  Objects that merely touch may swap depth order on a few pixels of the
  contact line (the band mesh is inscribed in the curved surface): a pair is
  ordered by its majority when the contrary pixels are at most
  :data:`CONTACT_FRACTION` of the pixels they share.
- Perspective views need every object in front of the eye.
- The SVG has no background rectangle: uncovered areas are transparent (the
  PNG shows them black).
"""

from __future__ import annotations

import os
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..camera import Camera
from ..errors import InvalidParameterError
from ..kinds import Primitive
from ..scene.model import Scene
from .image import save_svg
from .painter import Renderer, default_renderer
from .raster import homogeneous

__all__ = ["ScenePolygons", "scene_polygons", "save_scene_svg", "CONTACT_FRACTION"]

#: Largest fraction of two objects' shared pixels that may contradict their
#: majority depth order (contact lines of touching objects) before the pair is
#: declared interpenetrating.
CONTACT_FRACTION = 0.01


@dataclass(frozen=True, slots=True, eq=False)
class ScenePolygons:
    """Screen triangles of the visible bands, in painting (back-to-front) order.

    Attributes
    ----------
    polygons : ndarray, shape (n, 3, 2), float64
        Triangle vertices in continuous pixel coordinates ``(col, row)``
        (pixel ``(i, j)`` has its centre at ``(j + 0.5, i + 0.5)``).
    values : ndarray, shape (n,), float64
        Intensity of each triangle (its band's ``value_out``).
    object_index : ndarray, shape (n,), int32
        Index into ``scene.objects`` of each triangle.
    depth : ndarray, shape (n,), float64
        Depth (along the view direction) of each triangle's farthest vertex.
    object_order : tuple of int
        The objects' back-to-front order.
    """

    polygons: NDArray[np.float64]
    values: NDArray[np.float64]
    object_index: NDArray[np.int32]
    depth: NDArray[np.float64]
    object_order: tuple[int, ...]

    def __len__(self) -> int:
        return int(len(self.values))


def _order(depths: list[NDArray[np.float64]]) -> list[int]:
    """Back-to-front order of objects from their per-pixel depths (``inf`` where absent)."""
    n = len(depths)
    before: list[set[int]] = [set() for _ in range(n)]  # before[a]: objects drawn before a
    for a in range(n):
        for b in range(a + 1, n):
            both = np.isfinite(depths[a]) & np.isfinite(depths[b])
            if not both.any():
                continue
            da, db = depths[a][both], depths[b][both]
            tie = np.abs(da - db) <= 1e-9 * np.maximum(np.abs(da), np.abs(db))
            a_front = int(np.count_nonzero((da < db) & ~tie))
            b_front = int(np.count_nonzero((db < da) & ~tie))
            minority = min(a_front, b_front)
            if minority > CONTACT_FRACTION * int(both.sum()):
                raise InvalidParameterError(
                    f"objects[{a}] and objects[{b}] are each in front of the other ({a_front} and {b_front} pixels): "
                    "they interpenetrate, so no back-to-front order of whole objects exists"
                )
            if a_front > b_front:
                before[a].add(b)
            elif b_front > a_front:
                before[b].add(a)
    # Farthest first among the objects that are free to go: a stable, readable file.
    far = [float(np.max(d[np.isfinite(d)])) if np.isfinite(d).any() else np.inf for d in depths]
    order: list[int] = []
    done: set[int] = set()
    while len(order) < n:
        ready = [k for k in range(n) if k not in done and before[k] <= done]
        if not ready:
            rest = ", ".join(f"objects[{k}]" for k in range(n) if k not in done)
            raise InvalidParameterError(f"{rest} overlap cyclically: no back-to-front order of whole objects exists")
        k = max(ready, key=lambda j: far[j])
        order.append(k)
        done.add(k)
    return order


def scene_polygons(
    scene: Scene,
    *,
    camera: Camera | None = None,
    contours: int | None = None,
    renderer: Renderer | None = None,
) -> ScenePolygons:
    """Screen triangles of the visible bands, back to front.

    Parameters
    ----------
    scene : Scene
        Every object must be a single primitive.
    camera : Camera, optional
        Defaults to ``scene.camera``.
    contours : int, optional
        Defaults to ``scene.render.contours``.
    renderer : Renderer, optional
        Supplies the band meshes (and their cache) and the per-object depth
        used to order the objects; the default renderer otherwise.

    Returns
    -------
    ScenePolygons
        Front-facing, non-degenerate band triangles that reach into the image,
        objects back to front and each object's triangles farthest first.

    Raises
    ------
    InvalidParameterError
        For an object that is a CSG tree, an object reaching behind the eye
        of a perspective camera, or objects without a back-to-front order
        (interpenetrating or cyclically overlapping).

    Examples
    --------
    A box under a directional light has one lamina per face:

    >>> from isocsg import Box, Camera, DirectionalLight, Scene
    >>> scene = Scene(Camera((2, -5, 3), (0, 0, 0), width=40, height=30),
    ...               [DirectionalLight((3, -5, 4))], [Box((0, 0, 0), (1, 1, 1))])
    >>> out = scene_polygons(scene)
    >>> len(out), out.polygons.shape  # three faces seen, two triangles each
    (6, (6, 3, 2))
    """
    r = default_renderer() if renderer is None else renderer
    cam = scene.camera if camera is None else camera
    n_contours = scene.render.contours if contours is None else contours
    per_object: list[tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]] = []
    depths: list[NDArray[np.float64]] = []
    for k, obj in enumerate(scene.objects):
        if not isinstance(obj.shape, Primitive):
            raise InvalidParameterError(
                f"objects[{k}] is a CSG tree; SVG output takes objects "
                "that are single primitives (render CSG as an image)"
            )
        bands = r.bands(obj.shape, scene.lights, obj.material, n_contours, cam.eye)
        h = homogeneous(cam, bands.vertices)
        if not cam.orthographic and np.any(h[2] <= 0):
            raise InvalidParameterError(
                f"objects[{k}] reaches behind the eye; SVG "
                "output needs it in front of the camera"
            )
        xy = np.stack([h[0] / h[2], h[1] / h[2]], axis=1)
        t = np.asarray(bands.triangles, dtype=np.intp)
        tri = xy[t]
        e1, e2 = tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]
        # Counter-clockwise from outside turns clockwise on screen (rows grow
        # downwards): the renderer's front faces; zero area covers no pixel.
        front = e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0] < 0
        lo, hi = tri.min(axis=1), tri.max(axis=1)
        on_screen = (hi[:, 0] > 0) & (lo[:, 0] < cam.width) & (hi[:, 1] > 0) & (lo[:, 1] < cam.height)
        keep = front & on_screen
        far = h[3][t[keep]].max(axis=1)
        by_depth = np.argsort(-far, kind="stable")
        values = np.asarray(bands.value_out, dtype=np.float64)[keep]
        per_object.append((tri[keep][by_depth], values[by_depth], far[by_depth]))
        alone = r.render(Scene(cam, scene.lights, [obj], scene.render), contours=n_contours)
        depths.append(np.array(alone.depth, dtype=np.float64))
    order = _order(depths)
    n = [len(per_object[k][1]) for k in order]
    return ScenePolygons(
        polygons=np.concatenate([per_object[k][0] for k in order]) if order else np.zeros((0, 3, 2)),
        values=np.concatenate([per_object[k][1] for k in order]) if order else np.zeros(0),
        object_index=np.repeat(np.asarray(order, dtype=np.int32), n).astype(np.int32),
        depth=np.concatenate([per_object[k][2] for k in order]) if order else np.zeros(0),
        object_order=tuple(order),
    )


def save_scene_svg(
    path: str | os.PathLike[str],
    scene: Scene,
    *,
    camera: Camera | None = None,
    contours: int | None = None,
    renderer: Renderer | None = None,
    decimals: int = 2,
) -> ScenePolygons:
    """Write the scene's visible bands as an SVG file, back to front.

    Parameters
    ----------
    path : str or path-like
    scene : Scene
        Every object must be a single primitive (see :func:`scene_polygons`).
    camera, contours, renderer : optional
        As in :func:`scene_polygons`.
    decimals : int, default 2
        Fixed precision of the coordinates in the file.

    Returns
    -------
    ScenePolygons
        The polygons written, in file order.

    Raises
    ------
    InvalidParameterError
        As :func:`scene_polygons`.

    Examples
    --------
    >>> import os, tempfile
    >>> from isocsg import Box, Camera, DirectionalLight, Scene
    >>> scene = Scene(Camera((2, -5, 3), (0, 0, 0), width=40, height=30),
    ...               [DirectionalLight((3, -5, 4))], [Box((0, 0, 0), (1, 1, 1))])
    >>> p = os.path.join(tempfile.mkdtemp(), "box.svg")
    >>> written = save_scene_svg(p, scene)
    >>> open(p).read().count("<polygon"), len(written)
    (6, 6)
    """
    cam = scene.camera if camera is None else camera
    out = scene_polygons(scene, camera=cam, contours=contours, renderer=renderer)
    save_svg(path, list(out.polygons), out.values, width=cam.width, height=cam.height, decimals=decimals)
    return out
