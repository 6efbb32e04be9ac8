"""Loading what a live preview shows: an OpenSCAD model, a scene file or a Python script.

Every kind of file becomes a :class:`LoadedModel`: the :class:`~isocsg.Scene` to draw (its
camera is the starting view) and the notes to show beside it (what OpenSCAD nodes were left
out). :func:`watched_files` lists the files whose change reloads the model: the file itself
and, for ``.scad`` models, the files it names in ``include <...>`` and ``use <...>``
(followed transitively, relative to the including file as OpenSCAD resolves them first).
"""

from __future__ import annotations

import re
import runpy
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from ..errors import InvalidParameterError
from ..kinds import Solid
from ..scene.framing import framed_scene
from ..scene.model import Scene, SceneObject

__all__ = ["LoadedModel", "load_model", "watched_files", "MODEL_SUFFIXES", "SCRIPT_NAMES"]

#: The files a preview reads, by suffix.
MODEL_SUFFIXES = (".scad", ".csg", ".toml", ".json", ".py")
#: The names a Python script binds its model to, looked up in this order: a ``Scene``, or a solid
#: or a sequence of solids.
SCRIPT_NAMES = ("scene", "model", "solid")

_INCLUDE = re.compile(r"\b(?:include|use)\s*<([^>]+)>")


@dataclass(frozen=True)
class LoadedModel:
    """A model as loaded for the preview.

    Attributes
    ----------
    scene : Scene
        What is drawn; its camera is the first view.
    notes : tuple of str
        Lines to show beside the view (OpenSCAD nodes left out, with their line and reason).
    """

    scene: Scene
    notes: tuple[str, ...] = ()


def load_model(path: str | Path, *, skip_unsupported: bool = True) -> LoadedModel:
    """Load a ``.scad``/``.csg`` model, a ``.toml``/``.json`` scene or a ``.py`` script.

    Parameters
    ----------
    path : str or Path
    skip_unsupported : bool, default True
        OpenSCAD models: leave out the nodes without an exact equivalent, each named in
        :attr:`LoadedModel.notes` (a preview shows what it can, and says what it left out).

    Raises
    ------
    InvalidParameterError
        On another suffix, or a script that binds none of :data:`SCRIPT_NAMES` to a scene or
        solids.
    IsocsgError
        Whatever reading the file raises (its subclasses name the file and the line).
    """
    p = Path(path)
    suffix = p.suffix.lower()
    if suffix in (".scad", ".csg"):
        from ..openscad import read_openscad

        lowered = read_openscad(p, skip_unsupported=skip_unsupported)
        scene = framed_scene(SceneObject(lowered.solid, leaf_colors=lowered.leaf_colors))
        return LoadedModel(scene, tuple(f"left out {line}" for line in lowered.left_out))
    if suffix in (".toml", ".json"):
        from ..scene.io import load_scene

        return LoadedModel(load_scene(p))
    if suffix == ".py":
        return LoadedModel(_script_scene(p))
    raise InvalidParameterError(f"model file {str(p)!r} must end in one of {', '.join(MODEL_SUFFIXES)}")


def _script_scene(path: Path) -> Scene:
    """The scene a Python script builds: its ``scene``, or its ``model``/``solid`` framed."""
    names = runpy.run_path(str(path), run_name="__isocsg_preview__")
    for name in SCRIPT_NAMES:
        if name not in names:
            continue
        value = names[name]
        if isinstance(value, Scene):
            return value
        if isinstance(value, (Solid, SceneObject)):
            value = [value]
        if isinstance(value, Sequence) and value and all(isinstance(v, (Solid, SceneObject)) for v in value):
            return framed_scene(list(value))
        raise InvalidParameterError(
            f"{path}: {name} must be a Scene, a solid or a list of solids, got {type(value).__name__}")
    raise InvalidParameterError(f"{path}: the script must bind one of {', '.join(SCRIPT_NAMES)} to a Scene or solids")


def watched_files(path: str | Path) -> list[Path]:
    """The model file and, for ``.scad``, the files it includes or uses (transitively).

    A named file that does not exist is still listed: creating it reloads the model.
    The walk is iterative and visits each file once.
    """
    root = Path(path)
    found: list[Path] = [root]
    if root.suffix.lower() != ".scad":
        return found
    todo, seen = [root], {root.resolve()}
    while todo:
        current = todo.pop()
        try:
            text = current.read_text(encoding="utf-8", errors="replace")
        except OSError:
            continue
        for name in _INCLUDE.findall(text):
            child = (current.parent / name.strip()).resolve()
            if child not in seen:
                seen.add(child)
                found.append(child)
                todo.append(child)
    return found
