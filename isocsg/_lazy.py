"""Lazy re-exports for package ``__init__`` modules (PEP 562), as pyvista and scipy do.

A package lists its public names and the submodule defining each; a name's
module is imported on first access, so ``import isocsg`` costs little and a
command imports only what it uses.

Examples
--------
>>> getattr_, dir_ = lazy_exports({"__name__": "isocsg"}, {"Camera": ".camera"})
>>> getattr_("Camera").__name__
'Camera'
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Mapping
from typing import Any

__all__ = ["lazy_exports"]


def lazy_exports(
    namespace: dict[str, Any], table: Mapping[str, str]
) -> tuple[Callable[[str], Any], Callable[[], list[str]]]:
    """A module ``__getattr__`` and ``__dir__`` that import each exported name's module on first use.

    Parameters
    ----------
    namespace : dict
        The package's ``globals()``: looked-up values are stored there, so each
        name is imported once; relative module names are resolved against its ``__name__``.
    table : mapping of str to str
        Exported name -> module defining it (``".csg.tree"``).

    Returns
    -------
    (__getattr__, __dir__)
        For the package's namespace.
    """
    package = namespace["__name__"]

    def __getattr__(name: str) -> Any:
        module = table.get(name)
        if module is None:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(importlib.import_module(module, package), name)
        namespace[name] = value
        return value

    def __dir__() -> list[str]:
        return sorted(set(namespace) | set(table))

    return __getattr__, __dir__
