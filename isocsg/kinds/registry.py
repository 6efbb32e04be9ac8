"""The table of primitive kinds: scene-file names and fields, read live by every reader.

A kind registers itself in the module that defines it::

    @register_kind("capsule", required=("a", "b", "radius"))
    @dataclass(frozen=True, slots=True)
    class Capsule(Primitive):
        ...

Everything a kind does is a member of its class (:class:`~isocsg.kinds.base.Primitive`);
the table only maps scene-file names to classes and lists their fields. Scene files,
the OpenSCAD writer and the command line look kinds up here at the time they need
one, so a kind registered by user code at any time is read like a built-in one.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, TypeVar

from ..errors import InvalidParameterError

__all__ = ["PrimitiveKind", "kind_class", "kind_named", "kind_of", "register_kind", "registered_kinds"]

T = TypeVar("T", bound=type)


@dataclass(frozen=True, slots=True)
class PrimitiveKind:
    """One registered primitive kind.

    Attributes
    ----------
    name : str
        The scene-file tag (``"sphere"``, ``"ellipsoid"``, ...).
    cls : type
        The primitive class (subclasses such as ``Cylinder`` register their own kind).
    required, optional : tuple of str
        The constructor's keyword fields as written in scene files.
    """

    name: str
    cls: type[Any]
    required: tuple[str, ...]
    optional: tuple[str, ...] = ()

    def build(self, fields: dict[str, Any]) -> Any:
        """The primitive from its scene-file fields (through the class's ``from_dict``)."""
        return self.cls.from_dict(fields)


_BY_NAME: dict[str, PrimitiveKind] = {}
_BY_CLASS: dict[type, PrimitiveKind] = {}


def _add(kind: PrimitiveKind) -> PrimitiveKind:
    if kind.name in _BY_NAME:
        raise InvalidParameterError(f"kind.name {kind.name!r} is already registered")
    if kind.cls in _BY_CLASS:
        raise InvalidParameterError(f"kind.cls {kind.cls.__name__} is already registered")
    _BY_NAME[kind.name] = kind
    _BY_CLASS[kind.cls] = kind
    return kind


def register_kind(
    name: str | PrimitiveKind, *, required: tuple[str, ...] = (), optional: tuple[str, ...] = ()
) -> Any:
    """Register a primitive kind under a scene-file name.

    Used as a class decorator, ``@register_kind("sphere", required=("center", "radius"))``,
    or called with a :class:`PrimitiveKind`.

    Parameters
    ----------
    name : str or PrimitiveKind
        The scene-file name (the class's ``kind`` is set to it), or a whole kind.
    required, optional : tuple of str
        The constructor's keyword fields as written in scene files.

    Returns
    -------
    The class decorator, or the registered :class:`PrimitiveKind`.

    Raises
    ------
    InvalidParameterError
        If the name or the class is already registered.
    """
    if isinstance(name, PrimitiveKind):
        return _add(name)

    def decorate(cls: T) -> T:
        if cls.__dict__.get("kind") != name:
            type.__setattr__(cls, "kind", name)
        _add(PrimitiveKind(name, cls, tuple(required), tuple(optional)))
        return cls

    return decorate


def kind_of(prim: Any) -> PrimitiveKind | None:
    """The registered kind of a primitive, chosen by its class's inheritance (None if none)."""
    for c in type(prim).__mro__:
        k = _BY_CLASS.get(c)
        if k is not None:
            return k
    return None


def kind_named(name: str) -> PrimitiveKind | None:
    """The kind registered under a scene-file name, or None (read at call time: live)."""
    return _BY_NAME.get(name)


def kind_class(name: str) -> type[Any]:
    """The class registered under ``name``, for a kind whose values map onto another kind's (a
    ball's uneven image is an ellipsoid) without importing the module that builds on it.

    Raises
    ------
    InvalidParameterError
        If no kind is registered under ``name``.
    """
    kind = _BY_NAME.get(name)
    if kind is None:
        raise InvalidParameterError(f"kind {name!r} is not registered")
    return kind.cls


def registered_kinds() -> tuple[PrimitiveKind, ...]:
    """Every registered kind, in registration order."""
    return tuple(_BY_NAME.values())


def unregister_kind(name: str) -> None:
    """Remove a kind registered under ``name`` (tests that register their own kinds clean up)."""
    kind = _BY_NAME.pop(name, None)
    if kind is not None:
        _BY_CLASS.pop(kind.cls, None)


