"""``.scad`` files that need no ``openscad`` run: read in this process, the same model.

A ``.scad`` file goes through the ``openscad`` program (its ``.csg`` export), which costs a
process start (about 0.05 s of CPU, 0.1 s of wall-clock time) on every read. A file that
calls only ``cube``, ``sphere``, ``cylinder``, ``translate``, ``union``, ``difference`` and
``intersection`` with constant arguments is already ``.csg`` syntax, and OpenSCAD's export
changes nothing in it but the spelling (named arguments, a ``multmatrix`` for ``translate``,
the default ``$fn``/``$fa``/``$fs``) and the numbers, which it prints to 6 significant digits.
:func:`read_plain_scad` reads such a file directly when every number is already one that
survives that printing, so that the model is the one the program's export gives; any other
file (variables, modules, loops, other calls, ``$`` variables, modifiers, longer numbers,
``d =`` diameters, positional cylinder radii, ...) is left to the program. ``echo`` statements
with constant arguments, and OpenSCAD's examples' ``echo(version=version());``, are read too:
they print to the program's log, which isocsg does not show, and leave nothing in its export.
``tests/test_openscad_plain.py`` compares the two reads on random files of this subset.

A file outside that subset is then tried with :func:`isocsg.openscad.evaluate.evaluate_scad`,
which evaluates a conservative subset of the language (variables, loops, ``if``, modules and
functions, the common primitives and maps) as OpenSCAD 2021.01 does and builds the tree its
export gives; whatever it declines goes to the program.
"""

from __future__ import annotations

import math
import os
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

from ..errors import IsocsgError, OpenSCADError
from .lowering import LoweredModel, lower
from .parser import CSGCall, parse_csg

__all__ = ["PLAIN_CALLS", "PLAIN_SCAD_BYTES", "plain_calls", "read_plain_scad"]

#: Largest file tried in-process (a larger model's own work outweighs a process start).
PLAIN_SCAD_BYTES = 1 << 16


def _number(v: Any) -> bool:
    """A finite float that OpenSCAD's 6-digit printing keeps (``-0`` left to the program)."""
    return (isinstance(v, float) and math.isfinite(v) and float(f"{v:.6g}") == v
            and not (v == 0.0 and math.copysign(1.0, v) < 0))


def _positive(v: Any) -> bool:
    return _number(v) and v > 0


def _vector(v: Any, element: Callable[[Any], bool] = _number) -> bool:
    return isinstance(v, list) and len(v) == 3 and all(element(x) for x in v)


def _named(call: CSGCall, positional: tuple[str, ...]) -> dict[str, Any] | None:
    """The arguments by name (positional ones named in OpenSCAD's order), or None if too many."""
    if len(call.args) > len(positional) or any(name in call.kwargs for name in positional[:len(call.args)]):
        return None
    return {**dict(zip(positional, call.args, strict=False)), **call.kwargs}


def _cube(call: CSGCall) -> bool:
    args = _named(call, ("size", "center"))
    return (args is not None and set(args) <= {"size", "center"}
            and (_positive(args.get("size")) or _vector(args.get("size"), _positive))
            and isinstance(args.get("center", False), bool))


def _sphere(call: CSGCall) -> bool:
    args = _named(call, ("r",))
    return args is not None and set(args) == {"r"} and _positive(args["r"])


def _cylinder(call: CSGCall) -> bool:
    # named only: OpenSCAD's positional r2 defaults to r (1), not to r1
    if call.args or not isinstance(call.kwargs.get("center", False), bool):
        return False
    radii = set(call.kwargs) - {"h", "center"}
    if "h" not in call.kwargs or not _positive(call.kwargs["h"]):
        return False
    if radii == {"r"}:
        return _positive(call.kwargs["r"])
    if radii == {"r1", "r2"}:
        r1, r2 = call.kwargs["r1"], call.kwargs["r2"]
        return _number(r1) and _number(r2) and r1 >= 0 and r2 >= 0 and max(r1, r2) > 0
    return False


def _translate(call: CSGCall) -> bool:
    args = _named(call, ("v",))
    return args is not None and set(args) == {"v"} and _vector(args["v"])


def _boolean(call: CSGCall) -> bool:
    return not call.args and not call.kwargs


def _echo(call: CSGCall) -> bool:
    # constant arguments (the parser reads no other), no children: nothing in the export
    return not call.children


#: The calls read in-process, each with the check of its arguments.
PLAIN_CALLS: dict[str, Callable[[CSGCall], bool]] = {
    "cube": _cube, "sphere": _sphere, "cylinder": _cylinder, "translate": _translate,
    "union": _boolean, "difference": _boolean, "intersection": _boolean, "echo": _echo,
}
_LEAVES = ("cube", "sphere", "cylinder")
#: OpenSCAD's examples end with it; ``version()`` is the one call of an expression read here.
_ECHO_VERSION = re.compile(r"(?<![\w$])(echo\s*\()(\s*version\s*=\s*version\s*\(\s*\)\s*)(\)\s*;)")


def _blank(match: re.Match[str]) -> str:
    """``echo();`` in the statement's place (newlines kept: the lines of what follows stay)."""
    return match.group(1) + re.sub(r"[^\n]", " ", match.group(2)) + match.group(3)


def plain_calls(text: str) -> list[CSGCall] | None:
    """The statements of ``.scad`` text if it is within the subset OpenSCAD's export leaves as
    it is (module docstring), else None.

    Examples
    --------
    >>> [c.name for c in plain_calls("difference() { cube(10, center=true); sphere(6.5); }")]
    ['difference']
    >>> plain_calls("$fn = 12; sphere(1);") is None  # a variable: the program's to evaluate
    True
    >>> plain_calls("sphere(1.0000001);") is None  # OpenSCAD's .csg keeps 6 digits
    True
    """
    try:
        calls = parse_csg(_ECHO_VERSION.sub(_blank, text))
    except OpenSCADError:
        return None
    todo = [calls]
    while todo:  # iterative: any depth
        block = todo.pop()
        for call in block:
            check = PLAIN_CALLS.get(call.name)
            if check is None or call.modifiers or not check(call) or (call.name in _LEAVES and call.children):
                return None
            todo.append(call.children)
        block[:] = [call for call in block if call.name != "echo"]
    return calls or None


def read_plain_scad(path: str | os.PathLike[str], *, skip_unsupported: bool = False,
                    polygonal: bool = False) -> LoweredModel | None:
    """:func:`~isocsg.openscad.read_openscad` of a ``.scad`` file within the plain subset or
    the evaluated one (:mod:`isocsg.openscad.evaluate`), read without the ``openscad`` program;
    None for any other file, and for a model that does not
    lower (read it with the program, whose error names the line as it always did).

    Parameters
    ----------
    path : path-like
        The ``.scad`` file.
    skip_unsupported, polygonal : bool
        As for :func:`~isocsg.openscad.read_openscad` (no node of the subset is affected).
    """
    p = Path(path)
    try:
        if p.suffix.lower() != ".scad" or not p.is_file() or p.stat().st_size > PLAIN_SCAD_BYTES:
            return None
        text = p.read_bytes().decode("utf-8")
    except (OSError, UnicodeDecodeError):
        return None  # the program's read says what is wrong
    calls = plain_calls(text)
    if calls is None:
        from .evaluate import evaluate_scad

        calls = evaluate_scad(text, path=p)  # variables, loops, modules, ...: OpenSCAD's export computed here
    if calls is None:
        return None
    try:
        return lower(calls, source=str(p), skip_unsupported=skip_unsupported, polygonal=polygonal)
    except IsocsgError:
        return None  # the program's read raises it, naming the line of its .csg as before
