"""Vectors and list comprehensions of OpenSCAD 2021.01, for :mod:`isocsg.openscad.evaluate`.

A vector's elements are expressions, whose values it holds, and elements of a list
comprehension, whose values it splices in (an element of an element too: ``[for (i = a) for
(j = b) [i, j]]`` is a list of pairs): ``for (i = range_or_vector, j = ...)`` (nested, each
sequence evaluated with the variables before it bound; a number or a boolean is iterated over
once, ``undef`` not at all), the C-style ``for (i = 0; i < n; i = i +
1)`` (its steps assigned in turn, each seeing the ones before), ``if``/``else``, ``let`` (bound in
turn) and ``each`` (a vector's elements, a range's values, any other value but a string or
``undef`` itself). A loop over a string, ``each`` of a string or ``undef``, and a vector of more
than a million values raise :class:`~isocsg.openscad.scad_syntax.Declined`; every element
evaluated and every value spliced counts towards the evaluator's work bound.
"""

from __future__ import annotations

from typing import Any, Protocol

from .scad_syntax import Declined
from .scad_values import MAX_RANGE, Range, Scope, truthy

__all__ = ["loop_values", "vector"]

#: Most values of one vector.
MAX_VALUES = MAX_RANGE * 100


class _Evaluates(Protocol):
    """What the comprehensions need of the evaluator: expressions, ``let`` scopes, the work count."""

    steps: int

    def expr(self, e: Any, f: Scope) -> Any: ...

    def let_scope(self, bindings: list[tuple[str, Any]], f: Scope) -> Scope: ...


def vector(ev: _Evaluates, elements: list[Any], f: Scope) -> list[Any]:
    """The value of ``[e1, e2, ...]``."""
    out: list[Any] = []
    for x in elements:
        _emit(ev, x, f, out)
    return out


def _emit(ev: _Evaluates, x: Any, f: Scope, out: list[Any]) -> None:
    """Appends an expression's value to ``out``, or splices in a comprehension element's values."""
    kind = x[0]
    if not kind.startswith("lc_"):
        out.append(ev.expr(x, f))
    elif kind == "lc_for":
        _for(ev, x[1], x[2], f, out)
    elif kind == "lc_forc":
        _for_c(ev, x, f, out)
    elif kind == "lc_if":
        if truthy(ev.expr(x[1], f)):
            _emit(ev, x[2], f, out)
        elif x[3] is not None:
            _emit(ev, x[3], f, out)
    elif kind == "lc_let":
        _emit(ev, x[2], ev.let_scope(x[1], f), out)
    else:  # lc_each
        values: list[Any] = []
        _emit(ev, x[1], f, values)
        if x[1][0].startswith("lc_"):  # each of a comprehension: each of its every value
            for v in values:
                _each(ev, v, out)
        else:
            _each(ev, values[0], out)
    if len(out) > MAX_VALUES:
        raise Declined("a vector of more than a million values")


def _each(ev: _Evaluates, v: Any, out: list[Any]) -> None:
    if isinstance(v, Range):
        v = v.values()
    if isinstance(v, list):
        ev.steps += len(v)
        out.extend(v)
    elif v is None or isinstance(v, str):
        raise Declined("each of undef or of a string")
    else:
        out.append(v)


def _for(ev: _Evaluates, variables: list[tuple[str, Any]], body: Any, f: Scope, out: list[Any]) -> None:
    """``for (i = ..., j = ...) body``: the body for every combination, the last variable fastest."""
    todo: list[tuple[int, dict[str, Any]]] = [(0, {})]
    while todo:
        k, values = todo.pop()
        frame = Scope(f, f, values)
        if k == len(variables):
            _emit(ev, body, frame, out)
            continue
        name, x = variables[k]
        items = loop_values(ev.expr(x, frame))
        ev.steps += len(items)
        todo.extend((k + 1, {**values, name: v}) for v in reversed(items))


def loop_values(seq: Any) -> list[Any]:
    """What ``for (i = seq)`` (a statement or a comprehension) iterates over: a range's values, a
    vector's elements, a number or a boolean once, nothing for ``undef``. A string (OpenSCAD
    iterates over its characters) is declined."""
    if isinstance(seq, Range):
        return seq.values()
    if isinstance(seq, list):
        return seq
    if seq is None:
        return []
    if type(seq) in (float, bool):
        return [seq]
    raise Declined("a loop over a string")


def _for_c(ev: _Evaluates, x: Any, f: Scope, out: list[Any]) -> None:
    """``for (init; condition; step) body``: the body while the condition holds."""
    _, init, cond, step, body = x
    frame = ev.let_scope(init, f)
    while truthy(ev.expr(cond, frame)):
        _emit(ev, body, frame, out)
        nxt = Scope(f, f, frame.vars)
        for name, e in step:
            nxt.vars[name] = ev.expr(e, nxt)
        frame = nxt
