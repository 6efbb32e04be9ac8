"""The isocsg error hierarchy.

Every error raised on purpose by isocsg derives from :class:`IsocsgError`.
Each subclass also inherits the builtin exception it refines, so callers may
catch either ``isocsg.InvalidGeometryError`` or plain ``ValueError``.

Messages always name the offending field, say what was expected and what was
received, e.g. ``Sphere.radius must be > 0, got -1.0``.
"""

from __future__ import annotations

__all__ = [
    "IsocsgError",
    "InvalidGeometryError",
    "NotExactError",
    "InvalidLightError",
    "InvalidParameterError",
    "SceneFileError",
    "MissingDependencyError",
    "ResourceLimitError",
    "OpenSCADError",
    "UnsupportedOpenSCADError",
]


class IsocsgError(Exception):
    """Base class of every error that isocsg raises deliberately."""


class InvalidGeometryError(IsocsgError, ValueError):
    """A primitive, CSG node or occluder is malformed (NaN, zero size, ...)."""


class NotExactError(InvalidGeometryError):
    """An operation (``hull``, ``minkowski``) whose result is no exact union of isocsg kinds.

    The message names the operation and the operands that stop it, e.g. ``hull: a hull of
    Cylinder, Sphere of different shapes or directions is not an exact union ...``.
    """


class InvalidLightError(IsocsgError, ValueError):
    """A light or material is malformed (non-convex source, bad radiance, ...)."""


class InvalidParameterError(IsocsgError, ValueError):
    """A rendering or evaluation parameter is out of range (contours, camera, ...)."""


class SceneFileError(IsocsgError, ValueError):
    """A scene file cannot be read or does not follow the documented structure.

    The message starts with the file name (when known) and the dotted path of
    the offending field, e.g. ``scene.toml: objects[0].shape.sphere.radius: ...``.
    """


class MissingDependencyError(IsocsgError, ImportError):
    """An optional dependency needed by the called function is not installed."""


class ResourceLimitError(IsocsgError, MemoryError):
    """A request would need more memory than the budget allows (see :mod:`isocsg.limits`).

    Raised before anything is allocated; the message names the request, the
    estimate and the budget, e.g. ``render: 4096 x 4096 image with ... needs
    about 3.2 GB, over the memory budget of 2.0 GB (isocsg.limits.set_memory_budget)``.
    """


class OpenSCADError(IsocsgError, ValueError):
    """An OpenSCAD file (``.scad`` or ``.csg``) cannot be read.

    The message starts with the file name (when known) and the line, e.g.
    ``model.csg:12: expected ')' after the arguments of cube, got ';'``.
    ``line`` holds the 1-based line number (``None`` when the error is not
    about one line, such as a failed ``openscad`` run).
    """

    def __init__(self, message: str, *, line: int | None = None, node: str | None = None) -> None:
        super().__init__(message)
        self.line = line
        self.node = node


class UnsupportedOpenSCADError(OpenSCADError):
    """An OpenSCAD node that has no exact isocsg equivalent (``hull``, ``minkowski``, ...).

    ``node`` holds the node's name and ``line`` its line; the message names
    both, e.g. ``model.csg:7: hull() is not supported (...)``.
    ``load_openscad(..., skip_unsupported=True)`` skips such nodes instead.
    """
