"""Interactive (or off-screen) 3-D view of isoluminance bands with pyvista.

pyvista is an optional dependency (``pip install 'isocsg[view]'``); it is
imported only when :func:`show` is called.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from .camera import Camera
from .csg.tree import CSGNode
from .errors import InvalidParameterError
from .kinds import Solid
from .lighting.lights import Material
from .scene.model import SceneObject

__all__ = ["show", "BACKGROUND"]

#: Background colour of :func:`show`'s plotters (a dark blue, told apart from any grey band).
BACKGROUND = (32, 32, 64)


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
    plotter: Any = None,
    off_screen: bool = False,
    screenshot: str | os.PathLike[str] | None = None,
    window_size: tuple[int, int] = (800, 600),
    show_edges: bool = False,
    build_laminae: Callable[..., Any] | None = None,
) -> Any:
    """Show the surface bands of each object, coloured by their intensity.

    Every band triangle is drawn flat with its value as a grey level
    (0 black, 1 white) and no extra lighting, so the view shows the
    isoluminance contours themselves. A CSG tree is drawn as its Boolean
    result: the leaves' bands clipped in 3D
    (:func:`isocsg.csg.surface.surface_from_bands`), so a subtracted hole is a
    hole and the inside of a cut shows the reversed-normal values.

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
    plotter : pyvista.Plotter, optional
        Add the meshes to this plotter (and set its camera if ``camera`` is
        given) without showing it: the caller composes the view and shows it.
    off_screen : bool, default False
        For a new plotter: render without a window (nothing is shown; read
        the image with ``plotter.screenshot()``).
    screenshot : str or path-like, optional
        Save the rendered image as PNG.
    window_size : (int, int), default (800, 600)
        For a new plotter.
    show_edges : bool, default False
        Draw the band triangles' edges.
    build_laminae : callable, optional
        Band builder; defaults to :func:`isocsg.laminae.build_laminae`.

    Returns
    -------
    pyvista.Plotter
        The plotter (the given one, or a new one: shown in a window unless
        ``off_screen``, and not closed, so that it can still be read).

    Raises
    ------
    MissingDependencyError
        If pyvista is not installed.
    InvalidParameterError
        On objects that are not solids.

    Examples
    --------
    >>> from isocsg import PointLight, Sphere
    >>> p = show(Sphere((0, 0, 0), 1), [PointLight((3, -3, 5))], off_screen=True)  # doctest: +SKIP
    >>> image = p.screenshot()  # doctest: +SKIP
    """
    from .csg.surface import surface_from_bands
    from .interop.pyvista import import_pyvista, to_pyvista

    pv = import_pyvista()
    objs = _objects(objects)
    if build_laminae is None:
        from .laminae import build_laminae as build
    else:
        build = build_laminae
    if camera is not None:
        eye: tuple[float, ...] = camera.eye
    else:
        lo = np.min([o.shape.bounds[0] for o in objs], axis=0) if objs else np.zeros(3)
        hi = np.max([o.shape.bounds[1] for o in objs], axis=0) if objs else np.ones(3)
        eye = tuple(float(x) for x in hi + 2.0 * (hi - lo))
    given = plotter is not None
    if not given:
        plotter = pv.Plotter(off_screen=off_screen, window_size=list(window_size))
        plotter.set_background([c / 255 for c in BACKGROUND])

    def bands_of(prim: Any, material: Material) -> Any:
        res = build(prim, tuple(lights), material, contours, eye=eye)
        return getattr(res, "bands", res)

    for obj in objs:
        material = obj.material if isinstance(obj.material, Material) else Material()
        if isinstance(obj.shape, CSGNode):
            program = obj.shape.program()
            mesh = to_pyvista(surface_from_bands(program, [bands_of(p, material) for p in program.leaves]))
        else:
            mesh = to_pyvista(bands_of(obj.shape, material))
        if mesh.n_cells == 0:
            continue
        mesh.cell_data["intensity"] = np.clip(mesh.cell_data["intensity"], 0.0, 1.0)
        plotter.add_mesh(
            mesh, scalars="intensity", cmap="gray", clim=(0.0, 1.0), lighting=False,
            show_edges=show_edges, show_scalar_bar=False,
        )
    if camera is not None:
        plotter.camera_position = [camera.eye, camera.target, camera.up]
        plotter.camera.view_angle = camera.fov
    if given:
        return plotter
    if off_screen:
        plotter.render()
        if screenshot is not None:
            plotter.screenshot(os.fspath(screenshot))
        return plotter
    plotter.show(screenshot=None if screenshot is None else os.fspath(screenshot), auto_close=False)
    return plotter
