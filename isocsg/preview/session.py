"""A live preview's state: the model, its version, one warm renderer, and the file watcher.

:class:`PreviewSession` knows nothing of HTTP (:mod:`isocsg.preview.server` serves it). It
loads the model once, renders views of it on request (one at a time, through one
:class:`~isocsg.Renderer`, so compiled kernels and the bands of unchanged leaves stay warm
between edits), and a watcher thread reloads the model when one of its files changes: the
model file and the files a ``.scad`` includes (:func:`~isocsg.preview.models.watched_files`).
A file that fails to load keeps the last good model on screen and shows the error; fixing the
file shows the new model.
"""

from __future__ import annotations

import io
import os
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .models import LoadedModel, load_model, watched_files
from .orbit import OrbitView, initial_view, orbit_scene

__all__ = ["PreviewSession", "ViewImage", "POLL_SECONDS", "BACKGROUND_RGB"]

#: How often the watcher looks at the files' modification times.
POLL_SECONDS = 0.25
#: The colour of pixels where no solid is (a dark blue, told apart from any grey band).
BACKGROUND_RGB = (32, 32, 64)


@dataclass(frozen=True)
class ViewImage:
    """One rendered view: PNG bytes, the model version it shows and the time it took."""

    png: bytes
    version: int
    seconds: float


def _png(image: np.ndarray) -> bytes:
    """An RGB PNG of a grey (H, W) or colour (H, W, 3) image in [0, 1] with NaN (nothing there) in
    :data:`BACKGROUND_RGB`."""
    from PIL import Image

    if image.ndim == 2:
        image = np.repeat(image[:, :, None], 3, axis=2)
    rgb = np.rint(np.clip(np.nan_to_num(image, nan=0.0), 0.0, 1.0) * 255.0).astype(np.uint8)
    rgb[np.isnan(image).any(axis=2)] = BACKGROUND_RGB
    out = io.BytesIO()
    Image.fromarray(rgb, mode="RGB").save(out, format="PNG", compress_level=1)
    return out.getvalue()


class PreviewSession:
    """A model file shown live.

    Parameters
    ----------
    path : str or Path
        A ``.scad``, ``.csg``, ``.toml``, ``.json`` or ``.py`` file
        (:func:`~isocsg.preview.models.load_model`).
    watch : bool, default True
        Start the watcher thread that reloads the model when its files change.

    Raises
    ------
    IsocsgError
        If the file cannot be loaded the first time (later failures are shown, not raised).
    """

    def __init__(self, path: str | os.PathLike[str], *, watch: bool = True) -> None:
        from ..rendering import Renderer

        self.path = Path(path)
        self._renderer = Renderer()
        self._render_lock = threading.Lock()
        self._model_lock = threading.Lock()
        self._model: LoadedModel = load_model(self.path)
        self._framed = self.path.suffix.lower() not in (".toml", ".json")
        self._version = 1
        self._error: str | None = None
        self._stamps = self._file_stamps()
        self._stop = threading.Event()
        self._watcher: threading.Thread | None = None
        if watch:
            self._watcher = threading.Thread(target=self._watch, name="isocsg-preview-watch", daemon=True)
            self._watcher.start()

    # ------------------------------------------------------------------ state
    @property
    def version(self) -> int:
        """Counts the models loaded: 1 for the first, one more for each successful reload."""
        return self._version

    def initial_view(self) -> OrbitView:
        """The view of the model's own camera (the framed view for OpenSCAD models and scripts)."""
        return initial_view(self._model.scene.camera)

    def state(self) -> dict[str, Any]:
        """What the page shows beside the image: version, file, error (or None), notes, first view."""
        view = self.initial_view()
        return {
            "version": self._version,
            "file": str(self.path),
            "error": self._error,
            "notes": list(self._model.notes),
            "initial": {"azimuth": view.azimuth, "elevation": view.elevation},
        }

    # ---------------------------------------------------------------- render
    def render(self, view: OrbitView) -> ViewImage:
        """Render the current model from ``view`` (one render at a time; others wait)."""
        with self._model_lock:
            model, version = self._model, self._version
        scene = orbit_scene(model.scene, view, turn_lights=self._framed)
        with self._render_lock:
            start = time.perf_counter()
            if scene.render.mode == "halftone":
                from ..shadows.halftone import render_halftone

                image = render_halftone(scene).display
            else:
                from ..rendering.colors import colored_image

                image = colored_image(self._renderer.render(scene), scene.objects)
            seconds = time.perf_counter() - start
        return ViewImage(_png(np.asarray(image, dtype=np.float64)), version, seconds)

    def warm(self) -> None:
        """Render a small first view so that the kernels are loaded before the page asks.

        A failure is not raised here: the page's own request meets it and shows it.
        """
        first = self.initial_view()
        try:
            self.render(OrbitView(first.azimuth, first.elevation, 1.0, 64, 64))
        except Exception:  # noqa: BLE001 - shown by the page's request, see above
            return

    # ---------------------------------------------------------------- reload
    def _file_stamps(self) -> dict[Path, tuple[int, int] | None]:
        stamps: dict[Path, tuple[int, int] | None] = {}
        for f in watched_files(self.path):
            try:
                st = f.stat()
                stamps[f] = (st.st_mtime_ns, st.st_size)
            except OSError:
                stamps[f] = None
        return stamps

    def check(self) -> bool:
        """Reload if a watched file changed since the last look; True if a new model loaded.

        A change is taken once the files have stayed the same for one poll (an editor that
        writes a file in several steps is read after its last step).
        """
        stamps = self._file_stamps()
        if stamps == self._stamps:
            return False
        time.sleep(POLL_SECONDS)
        settled = self._file_stamps()
        if settled != stamps:
            return False  # still being written: look again at the next poll
        self._stamps = settled
        try:
            model = load_model(self.path)
        except Exception as exc:  # noqa: BLE001 - isocsg errors, a missing file, a script error: shown, the last good model stays
            self._error = f"{type(exc).__name__}: {exc}"
            return False
        with self._model_lock:
            self._model = model
            self._version += 1
            self._error = None
        return True

    def _watch(self) -> None:
        while not self._stop.wait(POLL_SECONDS):
            self.check()

    def close(self) -> None:
        """Stop the watcher."""
        self._stop.set()
        if self._watcher is not None:
            self._watcher.join(timeout=5 * POLL_SECONDS)
