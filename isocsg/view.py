"""Interactive (or off-screen) 3-D view of isoluminance bands with pyvista.

pyvista is an optional dependency (``pip install 'isocsg[view]'``); it is
imported only when :func:`show` is called.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .camera import Camera
from .csg.tree import leaves
from .errors import InvalidParameterError, MissingDependencyError
from .geometry.primitives import Solid
from .lighting.lights import Material
from .scene.model import SceneObject

__all__ = ["show"]


def _objects(objects: Any) -> list[SceneObject]:
    items = [objects] if isinstance(objects, (Solid, SceneObject)) else list(objects)
    out = []
    for i, o in enumerate(items):
        if isinstance(o, SceneObject):
            out.append(o)
        elif isinstance(o, Solid):
            out.append(SceneObject(o))
        else:
            raise InvalidParameterError(f"objects[{i}] must be a solid or SceneObject, got {type(o).__name__}")
    return out


def show(
    objects: Solid | SceneObject | Sequence[Solid | SceneObject],
    lights: Sequence[Any],
    *,
    contours: int = 64,
    camera: Camera | None = None,
    off_screen: bool = False,
    screenshot: str | os.PathLike[str] | None = None,
    window_size: tuple[int, int] = (800, 600),
    show_edges: bool = False,
    build_laminae: Callable[..., Any] | None = None,
) -> NDArray[np.uint8] | None:
    """Show the surface bands of each primitive, coloured by their intensity.

    Every band triangle is drawn flat with its ``value_out`` as a grey level
    (0 black, 1 white) and no extra lighting, so the view shows the
    isoluminance contours themselves. Primitives of a CSG tree are shown
    whole (the Boolean result is resolved by :func:`isocsg.render.render`).

    Parameters
    ----------
    objects : Solid, SceneObject or sequence of them
    lights : sequence of PointLight or DirectionalLight
    contours : int, default 64
        Contours per light family.
    camera : Camera, optional
        Initial view (eye, target, up, vertical field of view); also the eye of
        view-dependent (specular) bands. Defaults to pyvista's automatic view
        and an eye at the scene's bounding box corner.
    off_screen : bool, default False
        Render without a window and return the image.
    screenshot : str or path-like, optional
        Also save the rendered image as PNG.
    window_size : (int, int), default (800, 600)
    show_edges : bool, default False
        Draw the band triangles' edges.
    build_laminae : callable, optional
        Band builder; defaults to :func:`isocsg.laminae.build_laminae`.

    Returns
    -------
    ndarray of uint8, shape (h, w, 3), or None
        The rendered image when ``off_screen`` is true.

    Raises
    ------
    MissingDependencyError
        If pyvista is not installed.
    InvalidParameterError
        On objects that are not solids.

    Examples
    --------
    >>> from isocsg import PointLight, Sphere
    >>> img = show(Sphere((0, 0, 0), 1), [PointLight((3, -3, 5))], off_screen=True)  # doctest: +SKIP
    """
    try:
        import pyvista as pv
    except ImportError as exc:
        raise MissingDependencyError("isocsg.show needs pyvista; install the extra: pip install 'isocsg[view]'") from exc
    objs = _objects(objects)
    if build_laminae is None:
        from .laminae import build_laminae as build
    else:
        build = build_laminae
    if camera is not None:
        eye = camera.eye
    else:
        lo = np.min([o.shape.bounds[0] for o in objs], axis=0) if objs else np.zeros(3)
        hi = np.max([o.shape.bounds[1] for o in objs], axis=0) if objs else np.ones(3)
        eye = tuple(float(x) for x in hi + 2.0 * (hi - lo))
    plotter = pv.Plotter(off_screen=off_screen, window_size=list(window_size))
    plotter.set_background("#202040")
    for obj in objs:
        material = obj.material if isinstance(obj.material, Material) else Material()
        for prim in leaves(obj.shape):
            res = build(prim, tuple(lights), material, contours, eye=eye)
            bands = getattr(res, "bands", res)
            tris = np.asarray(bands.triangles, dtype=np.int64)
            faces = np.column_stack([np.full(len(tris), 3), tris]).ravel()
            mesh = pv.PolyData(np.asarray(bands.vertices, dtype=np.float64), faces)
            mesh.cell_data["intensity"] = np.clip(np.asarray(bands.value_out, dtype=np.float64), 0.0, 1.0)
            plotter.add_mesh(
                mesh, scalars="intensity", cmap="gray", clim=(0.0, 1.0), lighting=False,
                show_edges=show_edges, show_scalar_bar=False,
            )
    if camera is not None:
        plotter.camera_position = [camera.eye, camera.target, camera.up]
        plotter.camera.view_angle = camera.fov
    out = plotter.show(screenshot=None if screenshot is None else os.fspath(screenshot), return_img=off_screen)
    return np.asarray(out) if off_screen else None
