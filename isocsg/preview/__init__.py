"""Live preview: a model file shown in a local web page that re-renders when the file is saved.

``isocsg view model.scad`` (or ``.csg``, a ``.toml``/``.json`` scene, or a Python script that binds
``scene``, ``model`` or ``solid``) serves the page on ``127.0.0.1`` and opens it in the browser:
drag to orbit, wheel to zoom, double click for the first view. One warm
:class:`~isocsg.Renderer` draws every view, so only the first pays for loading kernels, and an
edit re-renders only what changed. In Jupyter, :func:`preview` returns the server, which shows the
same page in a frame.

- :mod:`~isocsg.preview.models`: what a file becomes (:func:`load_model`) and which files are
  watched;
- :mod:`~isocsg.preview.orbit`: a view as azimuth, elevation and zoom (:class:`OrbitView`);
- :mod:`~isocsg.preview.session`: the model, its version, the renderer and the watcher;
- :mod:`~isocsg.preview.server`: the HTTP server and the page.
"""

from __future__ import annotations

import os
import threading

from .models import LoadedModel, load_model, watched_files
from .orbit import OrbitView, initial_view, orbit_scene
from .server import PreviewServer
from .session import PreviewSession, ViewImage

__all__ = [
    "preview", "PreviewServer", "PreviewSession", "ViewImage", "OrbitView", "LoadedModel",
    "load_model", "watched_files", "initial_view", "orbit_scene",
]


def preview(path: str | os.PathLike[str], *, port: int = 0) -> PreviewServer:
    """Serve a live preview of a model file and return the running server.

    Parameters
    ----------
    path : str or path-like
        A ``.scad``, ``.csg``, ``.toml``, ``.json`` or ``.py`` file.
    port : int, default 0
        The local port; 0 picks a free one (:attr:`PreviewServer.url`).

    Returns
    -------
    PreviewServer
        Running on a thread of its own; in Jupyter it displays the page in a frame. Call
        :meth:`PreviewServer.close` to stop it.
    """
    session = PreviewSession(path)
    server = PreviewServer(session, port)
    server.start()
    # The first view loads the compiled kernels: start it now, while the browser opens.
    threading.Thread(target=session.warm, name="isocsg-preview-warm", daemon=True).start()
    return server
