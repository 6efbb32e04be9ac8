"""The live preview's local web page: a small HTTP server on the loopback interface.

Routes (all ``GET``):

- ``/``: the page (``isocsg/data/preview.html``): the image, mouse orbit (drag), zoom (wheel),
  double click for the first view, the model's notes and errors; the view is kept in the
  page's address (``#az=..&el=..&zoom=..``) so a link reopens it.
- ``/view.png?az=&el=&zoom=&w=&h=``: the model rendered from that view
  (:class:`~isocsg.preview.orbit.OrbitView`); the response's ``X-Isocsg-Version`` and
  ``X-Isocsg-Seconds`` headers say which model version it shows and how long it took.
- ``/state``: JSON (:meth:`~isocsg.preview.session.PreviewSession.state`); the page asks for it
  a few times a second and fetches a new image when the version changes.

The server binds ``127.0.0.1`` only: it runs the user's own files and is not meant to be reached
from other machines.
"""

from __future__ import annotations

import json
import threading
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from importlib import resources
from typing import Any
from urllib.parse import parse_qs, urlsplit

from ..errors import IsocsgError
from .orbit import OrbitView
from .session import PreviewSession

__all__ = ["PreviewServer", "page_html"]


def page_html() -> bytes:
    """The preview page, as shipped in ``isocsg/data/preview.html``."""
    return resources.files("isocsg").joinpath("data/preview.html").read_bytes()


def _view(query: dict[str, list[str]], first: OrbitView) -> OrbitView:
    """The view a query asks for; what it leaves out is the model's first view."""
    def value(key: str, default: float) -> float:
        values = query.get(key)
        return float(values[0]) if values else default

    return OrbitView(value("az", first.azimuth), value("el", first.elevation), value("zoom", first.zoom),
                     int(value("w", first.width)), int(value("h", first.height)))


class _Handler(BaseHTTPRequestHandler):
    server: PreviewServer

    def log_message(self, format: str, *args: Any) -> None:  # noqa: A002 - the base class's name
        pass  # a request per mouse move: not worth a line on the terminal

    def _send(self, status: int, body: bytes, content_type: str, headers: dict[str, str] | None = None) -> None:
        self.send_response(status)
        self.send_header("Content-Type", content_type)
        self.send_header("Content-Length", str(len(body)))
        self.send_header("Cache-Control", "no-store")
        for key, value in (headers or {}).items():
            self.send_header(key, value)
        self.end_headers()
        try:
            self.wfile.write(body)
        except (BrokenPipeError, ConnectionResetError):
            pass  # the page moved on (a newer view) and closed the request: nothing to deliver

    def do_GET(self) -> None:  # noqa: N802 - the name http.server calls
        url = urlsplit(self.path)
        session = self.server.session
        if url.path in ("/", "/index.html"):
            self._send(200, page_html(), "text/html; charset=utf-8")
        elif url.path == "/state":
            self._send(200, json.dumps(session.state()).encode(), "application/json")
        elif url.path == "/view.png":
            try:
                view = _view(parse_qs(url.query), session.initial_view())
            except (IsocsgError, ValueError) as exc:
                self._send(400, str(exc).encode(), "text/plain; charset=utf-8")
                return
            try:
                image = session.render(view)
            except IsocsgError as exc:
                self._send(500, f"{type(exc).__name__}: {exc}".encode(), "text/plain; charset=utf-8")
                return
            self._send(200, image.png, "image/png", {
                "X-Isocsg-Version": str(image.version), "X-Isocsg-Seconds": f"{image.seconds:.4f}"})
        else:
            self._send(404, b"not found", "text/plain; charset=utf-8")


class PreviewServer(ThreadingHTTPServer):
    """Serves a :class:`~isocsg.preview.session.PreviewSession` on ``127.0.0.1:port``.

    Parameters
    ----------
    session : PreviewSession
    port : int, default 0
        0 picks a free port (see :attr:`url`).

    Examples
    --------
    The server runs on a thread of its own until :meth:`close`::

        server = PreviewServer(PreviewSession("model.scad"))
        server.start()
        print(server.url)
    """

    daemon_threads = True

    def __init__(self, session: PreviewSession, port: int = 0) -> None:
        super().__init__(("127.0.0.1", port), _Handler)
        self.session = session
        self._thread: threading.Thread | None = None

    @property
    def url(self) -> str:
        """The page's address."""
        return f"http://127.0.0.1:{self.server_address[1]}/"

    def start(self) -> str:
        """Serve on a daemon thread; returns :attr:`url`."""
        self._thread = threading.Thread(target=self.serve_forever, name="isocsg-preview-http", daemon=True)
        self._thread.start()
        return self.url

    def close(self) -> None:
        """Stop serving and stop the session's watcher."""
        if self._thread is not None:
            self.shutdown()
            self._thread.join(timeout=5)
        self.server_close()
        self.session.close()

    def _repr_html_(self) -> str:
        """In Jupyter: the same page, in a frame."""
        return f'<iframe src="{self.url}" width="100%" height="560" style="border:0"></iframe>'
