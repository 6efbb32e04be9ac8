"""Late-bound operations: the one sanctioned way for a lower layer to offer what an upper one does.

``Solid``'s conveniences (the Boolean operators ``| & -``, notebook display), ``Program.contains``
and ``Program.to_solid``, and the notebook display of render results, half-tone images and
scenes are written where their users find them, in modules below the ones that implement them
(:mod:`isocsg.csg.tree`, :mod:`isocsg.csg.membership`, :mod:`isocsg.interop.notebook`). Those
modules never import upward: they call the operation by
name here, and the root package (``isocsg/__init__.py``, which Python always runs before any
submodule) binds each name to a function that imports its implementation on first call. The
import graph (and ``lint-imports``) thus sees each upward edge once, from the root package,
which stands outside the layers.

Examples
--------
>>> import isocsg
>>> from isocsg._late import late
>>> late("union").__name__
'_union'
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from typing import Any

__all__ = ["bind", "late"]

#: The root package, whose namespace holds the table (``_LATE_BOUND``): a second copy of this
#: module (a test runner importing the file again) then reads the same bindings.
_ROOT = __name__.rpartition(".")[0]


def _table() -> dict[str, Callable[..., Any]]:
    table: dict[str, Callable[..., Any]] = vars(sys.modules[_ROOT]).setdefault("_LATE_BOUND", {})
    return table


def bind(name: str, fn: Callable[..., Any]) -> None:
    """Bind the operation ``name`` to ``fn`` (the root package does, at import)."""
    _table()[name] = fn


def late(name: str) -> Callable[..., Any]:
    """The function bound to ``name``.

    Raises
    ------
    LookupError
        When nothing is bound to it (the root package binds every name it lists).
    """
    try:
        return _table()[name]
    except KeyError:
        raise LookupError(f"no operation bound to {name!r} (isocsg/__init__.py binds them)") from None
