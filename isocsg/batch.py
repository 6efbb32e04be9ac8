"""Many views and large illuminance grids at once: plain threads, or a Dask cluster when given.

:func:`render_views` renders one scene from many cameras (e.g. the
:func:`turntable` around its target); :func:`illuminance_grid` computes a
large lux map in row blocks. Both run the blocks on a ``dask.distributed``
client when one is passed (scenes, lights and solids are plain picklable
values, sent to each worker once; each worker loads the kernels it needs
before the tasks; each worker thread gets one task, a contiguous run of the
views, while row blocks are one task each, dealt as threads free up),
otherwise on a local thread pool. Results are in input order and equal to
the serial ones: every view and every node is computed by the same code as
:func:`isocsg.rendering.render` and
:func:`isocsg.shadows.luxmap.illuminance_map`.

Threads are safe under every numba threading layer: no compiled kernel on
these paths is a parallel (``prange``) one, whose concurrent launches abort
under ``workqueue``.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor
from typing import Any

import numpy as np

from .camera import Camera
from .errors import InvalidParameterError
from .scene.model import Scene

__all__ = ["turntable", "render_views", "illuminance_grid"]

_local = threading.local()


def turntable(camera: Camera, n: int, *, degrees: float = 360.0) -> list[Camera]:
    """``n`` cameras turned about the vertical (+z) axis through ``camera.target``.

    The first is ``camera`` itself; the others follow counter-clockwise seen
    from above, ``degrees / n`` apart (a full turn by default).

    Raises
    ------
    InvalidParameterError
        If ``n`` is not a positive integer or ``camera`` is not a Camera.

    Examples
    --------
    >>> cams = turntable(Camera((4, 0, 1), (0, 0, 0)), 4)
    >>> [tuple(round(x, 9) + 0.0 for x in c.eye) for c in cams]
    [(4.0, 0.0, 1.0), (0.0, 4.0, 1.0), (-4.0, 0.0, 1.0), (0.0, -4.0, 1.0)]
    """
    from ._validation import integer

    if not isinstance(camera, Camera):
        raise InvalidParameterError(f"camera must be a Camera, got {type(camera).__name__}")
    n = integer("n", n, low=1, high=100_000, error=InvalidParameterError)
    t = np.asarray(camera.target, dtype=np.float64)
    e = np.asarray(camera.eye, dtype=np.float64) - t
    out = []
    for k in range(n):
        a = math.radians(degrees) * k / n
        c, s = math.cos(a), math.sin(a)
        eye = t + np.array([c * e[0] - s * e[1], s * e[0] + c * e[1], e[2]])
        out.append(camera if k == 0 else camera.with_view(eye))
    return out


def _renderer() -> Any:
    # One renderer per thread: a renderer renders one image at a time, and keeps
    # its band meshes and buffers for the next view.
    r = getattr(_local, "renderer", None)
    if r is None:
        from .rendering import Renderer

        r = _local.renderer = Renderer()
    return r


def _render_one(scene: Scene, camera: Camera, contours: int | None) -> Any:
    if scene.render.mode == "halftone":
        import dataclasses

        from .shadows.halftone import render_halftone

        return render_halftone(dataclasses.replace(scene, camera=camera))
    return _renderer().render(scene, camera=camera, contours=contours)


def _run(
    fn: Callable[..., Any], shared: tuple[Any, ...], args: list[tuple[Any, ...]], client: Any, workers: int | None,
    paths: Sequence[str] = (),
    *,
    chunk: bool = True,
) -> list[Any]:
    """``[fn(*shared, *a) for a in args]`` on the client, on threads or serially."""
    if client is not None:
        # The shared values (the scene; the lights and occluders) go to every
        # worker once, and every task of a worker gets the same object: the
        # renderer's caches (band meshes, CSG surfaces) then serve its later
        # views, as they do in one process, instead of one fresh copy per task.
        held = tuple(client.scatter([x], broadcast=True)[0] for x in shared)
        # With ``chunk``, one task per worker thread, each a contiguous run of
        # the items: a view after the second is shorter than a task's round
        # trip. Without, one task per item, dealt as threads free up: blocks of
        # a lux grid are long and unequal (those in penumbra cost most).
        slots = sum(client.nthreads().values()) or 1
        if paths:
            client.run(_warm, tuple(paths))  # each worker loads its kernels once, not inside a timed task
        size = max(1, math.ceil(len(args) / slots)) if chunk else 1
        chunks = [args[i : i + size] for i in range(0, len(args), size)]
        futures = [client.submit(_chunk, fn, held, chunk, pure=False) for chunk in chunks]
        return [r for part in client.gather(futures) for r in part]
    if workers == 1 or len(args) <= 1:
        return [fn(*shared, *a) for a in args]
    with ThreadPoolExecutor(max_workers=workers) as pool:
        return list(pool.map(lambda a: fn(*shared, *a), args))


def _chunk(fn: Callable[..., Any], shared: tuple[Any, ...], chunk: list[tuple[Any, ...]]) -> list[Any]:
    return [fn(*shared, *a) for a in chunk]


_warmed: set[str] = set()


def _warm(paths: tuple[str, ...]) -> None:
    """Load the listed kernels of ``paths`` into this worker process (compiling what the disk cache lacks), once."""
    from .kernels import _compile, path_kernels

    for path in paths:
        if path not in _warmed:
            _compile(path_kernels(path))
            _warmed.add(path)


def render_views(
    scene: Scene,
    cameras: Sequence[Camera],
    *,
    contours: int | None = None,
    client: Any = None,
    workers: int | None = None,
) -> list[Any]:
    """Render ``scene`` from every camera.

    Parameters
    ----------
    scene : Scene
    cameras : sequence of Camera
    contours : int, keyword-only, optional
        Isoluminance contours per light (default ``scene.render.contours``).
    client : dask.distributed.Client, keyword-only, optional
        Render on its workers; otherwise on local threads.
    workers : int, keyword-only, optional
        Local threads (default: Python's thread pool default); 1 renders serially.

    Returns
    -------
    list of RenderResult (or HalftoneResult for half-tone scenes)
        In the order of ``cameras``; with a client each result is a copy sent back.

    Raises
    ------
    InvalidParameterError
        On a non-scene or a camera that is not a Camera.

    Examples
    --------
    >>> from isocsg import PointLight, Sphere
    >>> camera = Camera((4, 0, 1), (0, 0, 0), width=24, height=16)
    >>> scene = Scene(camera, [PointLight((3, 3, 5))], [Sphere((0, 0, 0), 1)])
    >>> views = render_views(scene, turntable(scene.camera, 3))
    >>> [v.image.shape for v in views]
    [(16, 24), (16, 24), (16, 24)]
    """
    if not isinstance(scene, Scene):
        raise InvalidParameterError(f"scene must be a Scene, got {type(scene).__name__}")
    cams = list(cameras)
    for i, c in enumerate(cams):
        if not isinstance(c, Camera):
            raise InvalidParameterError(f"cameras[{i}] must be a Camera, got {type(c).__name__}")
    halftone = scene.render.mode == "halftone"
    paths = ("halftone",) if halftone else ("isoluminance", "surface")
    return _run(_render_one, (scene,), [(c, contours) for c in cams], client, workers, paths)


def _rows(lights: Any, occluders: Any, points: np.ndarray, normal: np.ndarray, resolution: int) -> np.ndarray:
    from .shadows.direct import illuminance

    return illuminance(points.reshape(-1, 3), normal, lights, occluders,
                       resolution=resolution).reshape(points.shape[:-1])


def illuminance_grid(
    grid: Any,
    lights: Any,
    occluders: Any = (),
    *,
    resolution: int | None = None,
    rows_per_task: int | None = None,
    client: Any = None,
    workers: int | None = None,
) -> Any:
    """:func:`~isocsg.shadows.luxmap.illuminance_map` in row blocks, on threads or a Dask cluster.

    Parameters
    ----------
    grid : LuxGrid
    lights : AreaLight, PolyhedronLight or a sequence of them
        Radiance in cd/m^2: the map is in lux.
    occluders : Solid or sequence of Solid, optional
    resolution : int, keyword-only, optional
        Tessellation of curved occluders (the library's default when None).
    rows_per_task : int, keyword-only, optional
        Grid rows per task (default: about 16 tasks).
    client : dask.distributed.Client, keyword-only, optional
    workers : int, keyword-only, optional
        Local threads when no client is given.

    Returns
    -------
    LuxMap
        Equal to ``illuminance_map(grid, lights, occluders)`` (nodes inside
        occluders marked the same way).

    Raises
    ------
    InvalidParameterError
        If ``grid`` is not a LuxGrid or ``rows_per_task`` is not positive.
    """
    from ._validation import integer
    from .kinds import DEFAULT_RESOLUTION
    from .shadows.luxmap import LuxGrid, LuxMap, occluded_nodes

    if not isinstance(grid, LuxGrid):
        raise InvalidParameterError(f"grid must be a LuxGrid, got {type(grid).__name__}")
    res = DEFAULT_RESOLUTION if resolution is None else resolution
    step = max(1, math.ceil(grid.ny / 16)) if rows_per_task is None else integer(
        "rows_per_task", rows_per_task, low=1, high=1 << 20, error=InvalidParameterError)
    pts = grid.points()
    n = grid.normal
    blocks = [(np.ascontiguousarray(pts[j : j + step]), n, res) for j in range(0, grid.ny, step)]
    E = np.vstack(_run(_rows, (lights, occluders), blocks, client, workers, ("halftone",), chunk=False))
    return LuxMap(grid, E, occluded_nodes(grid, occluders))
