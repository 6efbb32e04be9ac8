"""Parser of OpenSCAD's flattened CSG text (``.csg``).

OpenSCAD exports a model as a tree of calls with constant arguments::

    difference() {
        multmatrix([[1, 0, 0, 0.5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
            cube(size = [1, 2, 3], center = true);
        }
        sphere($fn = 32, $fa = 12, $fs = 2, r = 0.7);
    }

Each statement is ``[modifiers] name(arguments)`` followed by ``;`` or a
``{ ... }`` block of children; arguments are positional or ``name = value``
with values that are numbers, strings, ``true``/``false``/``undef`` and
nested ``[...]`` lists. The same text is valid ``.scad``, so files written by
:func:`isocsg.openscad.save_openscad` read back here without ``openscad``.

The parser is iterative (explicit stacks for blocks and lists): a file's
nesting depth is bounded by memory only. Every node keeps its line number,
and every error is an :class:`~isocsg.errors.OpenSCADError` naming the line.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass, field
from typing import Any

from ..errors import OpenSCADError

__all__ = ["CSGCall", "parse_csg", "MAX_CSG_TEXT"]

#: Largest ``.csg`` text read, in characters (a runaway file fails fast, not after minutes).
MAX_CSG_TEXT = 256 * 2**20

_TOKEN = re.compile(
    r"""
    (?P<ws>[ \t\r\f\v]+)
  | (?P<nl>\n)
  | (?P<comment>//[^\n]*|/\*.*?\*/)
  | (?P<number>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)
  | (?P<string>"(?:[^"\\\n]|\\.)*")
  | (?P<name>\$?[A-Za-z_][A-Za-z0-9_]*)
  | (?P<punct>[(){}\[\],;=\-+:!#%*])
    """,
    re.VERBOSE | re.DOTALL,
)

# A list of plain numbers (a polyhedron's points and faces, a matrix) is read in one step by the
# JSON reader, as floats, when its text is digits, signs, points, exponents, commas, brackets and
# blanks only; anything else (names, strings, `.5`, a number that overflows) takes the token path.
_JSON = json.JSONDecoder(parse_int=float)
_PLAIN_LIST = re.compile(r"[\d\s.,eE+\-\[\]]*")
_HUGE_NUMBER = re.compile(r"\d{300}|[eE][+-]?\d{3}")


def _plain_list(text: str, pos: int) -> tuple[list[Any], int] | None:
    """The list of numbers starting at ``text[pos] == '['`` and the end of its text, or None."""
    try:
        value, end = _JSON.raw_decode(text, pos)
    except (ValueError, RecursionError):
        return None
    span = text[pos:end]
    if not isinstance(value, list) or not _PLAIN_LIST.fullmatch(span) or _HUGE_NUMBER.search(span):
        return None
    return value, end


_KEYWORDS: dict[str, Any] = {"true": True, "false": False, "undef": None, "inf": math.inf, "nan": math.nan}
_MODIFIERS = "!#%*"


@dataclass(slots=True, repr=False, eq=False)  # no generated repr or == : they would recurse over children
class CSGCall:
    """One statement of a ``.csg`` file.

    Attributes
    ----------
    name : str
        The module called (``cube``, ``multmatrix``, ``union``, ...).
    args : list
        Positional argument values.
    kwargs : dict
        Named argument values (``$fn`` and friends included).
    children : list of CSGCall
        The statements of its block (empty for ``name(...);``).
    line : int
        1-based line of the name.
    modifiers : str
        Any of ``!#%*`` written before the name, in order.
    """

    name: str
    args: list[Any] = field(default_factory=list)
    kwargs: dict[str, Any] = field(default_factory=dict)
    children: list[CSGCall] = field(default_factory=list)
    line: int = 0
    modifiers: str = ""

    def __repr__(self) -> str:
        return (
            f"CSGCall({self.modifiers}{self.name}, line={self.line}, args={len(self.args)}, "
            f"kwargs={sorted(self.kwargs)}, children={len(self.children)})"
        )


@dataclass(slots=True)
class _Tok:
    kind: str
    text: str
    line: int
    value: Any = None  # a "list" token's numbers, read at once


def _show(tok: _Tok) -> str:
    if tok.kind == "list":
        return repr("[")  # where the list starts, as the token path names it
    return "the end of the file" if tok.kind == "eof" else repr(tok.text[:40])


class _Tokens:
    """The token stream of a text, with one token of look-ahead."""

    def __init__(self, text: str, source: str | None) -> None:
        self.source = source
        self.toks: list[_Tok] = []
        line, pos, n = 1, 0, len(text)
        while pos < n:
            if text[pos] == "[":
                plain = _plain_list(text, pos)
                if plain is not None:
                    self.toks.append(_Tok("list", text[pos:plain[1]], line, plain[0]))
                    line += text.count("\n", pos, plain[1])
                    pos = plain[1]
                    continue
            m = _TOKEN.match(text, pos)
            if m is None:
                if text.startswith("/*", pos):
                    raise self.error(line, "unterminated /* comment")
                if text[pos] == '"':
                    raise self.error(line, "unterminated string")
                raise self.error(line, f"unexpected character {text[pos]!r}")
            kind = m.lastgroup or ""
            tok = m.group()
            if kind == "nl":
                line += 1
            elif kind == "comment":
                line += tok.count("\n")
            elif kind != "ws":
                self.toks.append(_Tok(kind, tok, line))
            pos = m.end()
        self.toks.append(_Tok("eof", "", line))
        self.i = 0

    def error(self, line: int, message: str, node: str | None = None) -> OpenSCADError:
        prefix = f"{self.source}:{line}: " if self.source else f"line {line}: "
        return OpenSCADError(prefix + message, line=line, node=node)

    def peek(self) -> _Tok:
        return self.toks[self.i]

    def next(self) -> _Tok:
        tok = self.toks[self.i]
        if tok.kind != "eof":
            self.i += 1
        return tok

    def expect(self, text: str, where: str) -> _Tok:
        tok = self.next()
        if tok.text != text or tok.kind not in ("punct",):
            raise self.error(tok.line, f"expected {text!r} {where}, got {_show(tok)}")
        return tok


def _value(ts: _Tokens, where: str) -> Any:
    """One argument value; nested lists with an explicit stack."""
    stack: list[list[Any]] = []
    while True:
        tok = ts.next()
        sign = 1.0
        if tok.text in ("-", "+") and tok.kind == "punct":
            sign = -1.0 if tok.text == "-" else 1.0
            tok = ts.next()
            if tok.kind != "number" and tok.text not in ("inf", "nan"):
                raise ts.error(tok.line, f"expected a number after the sign {where}, got {_show(tok)}")
        if tok.kind == "list":
            value: Any = tok.value
        elif tok.kind == "punct" and tok.text == "[":
            if ts.peek().text == "]" and ts.peek().kind == "punct":
                ts.next()
                value = []
            else:
                stack.append([])
                continue
        elif tok.kind == "number":
            value = sign * float(tok.text)
            if not math.isfinite(value):
                raise ts.error(tok.line, f"number {tok.text[:40]} {where} is too large for a float")
        elif tok.kind == "string":
            value = _unescape(tok.text[1:-1])
        elif tok.kind == "name" and tok.text in _KEYWORDS:
            value = _KEYWORDS[tok.text]
            if isinstance(value, float):
                value = sign * value
        else:
            raise ts.error(tok.line, f"expected a value {where}, got {_show(tok)}")
        # Hand the value to the open lists; close those that end here.
        while True:
            if not stack:
                return value
            stack[-1].append(value)
            tok = ts.next()
            if tok.kind == "punct" and tok.text == ",":
                break
            if tok.kind == "punct" and tok.text == "]":
                value = stack.pop()
                continue
            if tok.kind == "punct" and tok.text == ":":
                raise ts.error(tok.line, f"ranges [a:b] are not supported {where}")
            raise ts.error(tok.line, f"expected ',' or ']' in a list {where}, got {_show(tok)}")


def _unescape(body: str) -> str:
    return re.sub(r"\\(.)", lambda m: {"n": "\n", "t": "\t", "r": "\r"}.get(m.group(1), m.group(1)), body)


def _arguments(ts: _Tokens, call: CSGCall) -> None:
    where = f"in the arguments of {call.name}"
    ts.expect("(", f"after {call.name}")
    if ts.peek().kind == "punct" and ts.peek().text == ")":
        ts.next()
        return
    while True:
        tok = ts.peek()
        nxt = ts.toks[ts.i + 1] if ts.i + 1 < len(ts.toks) else tok
        if tok.kind == "name" and nxt.kind == "punct" and nxt.text == "=":
            ts.next()
            ts.next()
            if tok.text in call.kwargs:
                raise ts.error(tok.line, f"argument {tok.text!r} given twice to {call.name}", call.name)
            call.kwargs[tok.text] = _value(ts, where)
        else:
            if call.kwargs:
                raise ts.error(tok.line, f"positional argument after named ones {where}", call.name)
            call.args.append(_value(ts, where))
        tok = ts.next()
        if tok.kind == "punct" and tok.text == ")":
            return
        if not (tok.kind == "punct" and tok.text == ","):
            raise ts.error(tok.line, f"expected ',' or ')' {where}, got {_show(tok)}", call.name)


def parse_csg(text: str, *, source: str | None = None) -> list[CSGCall]:
    """Parse ``.csg`` text into its top-level statements.

    Parameters
    ----------
    text : str
        The file's text.
    source : str, optional
        Name that starts every error message (usually the file name).

    Returns
    -------
    list of CSGCall
        The top-level statements in file order.

    Raises
    ------
    OpenSCADError
        On malformed text; the message names the line and what was expected.

    Examples
    --------
    >>> (call,) = parse_csg("difference() {\\n  cube(size = [1, 1, 1]);\\n  sphere(r = 0.6);\\n}")
    >>> call.name, [c.name for c in call.children], call.children[1].line, call.children[1].kwargs
    ('difference', ['cube', 'sphere'], 3, {'r': 0.6})
    """
    if len(text) > MAX_CSG_TEXT:
        raise OpenSCADError(f"{source or 'text'}: larger than {MAX_CSG_TEXT} characters")
    ts = _Tokens(text, source)
    top: list[CSGCall] = []
    # Open blocks, each with a flag: True for a single child without braces (``translate(v) cube();``),
    # which closes when its one statement ends.
    open_blocks: list[tuple[CSGCall, bool]] = []

    def statement_done() -> None:
        while open_blocks and open_blocks[-1][1]:
            open_blocks.pop()

    while True:
        tok = ts.next()
        if tok.kind == "eof":
            if open_blocks:
                b = open_blocks[-1][0]
                raise ts.error(tok.line, f"the block of {b.name} opened at line {b.line} is not closed", b.name)
            return top
        if tok.kind == "punct" and tok.text == "}":
            if not open_blocks or open_blocks[-1][1]:
                raise ts.error(tok.line, "'}' without an open block")
            open_blocks.pop()
            statement_done()
            continue
        if tok.kind == "punct" and tok.text == ";":
            if open_blocks and open_blocks[-1][1]:
                statement_done()  # ``translate(v);``: an empty child
            continue  # an empty statement
        modifiers = ""
        while tok.kind == "punct" and tok.text in _MODIFIERS:
            modifiers += tok.text
            tok = ts.next()
        if tok.kind != "name" or tok.text in _KEYWORDS:
            raise ts.error(tok.line, f"expected a module name such as cube or union, got {_show(tok)}")
        call = CSGCall(tok.text, line=tok.line, modifiers=modifiers)
        _arguments(ts, call)
        (open_blocks[-1][0].children if open_blocks else top).append(call)
        tok = ts.peek()
        if tok.kind == "punct" and tok.text in ";{":
            ts.next()
            if tok.text == ";":
                statement_done()
            else:
                open_blocks.append((call, False))
            continue
        if (tok.kind == "name" and tok.text not in _KEYWORDS) or (tok.kind == "punct" and tok.text in _MODIFIERS):
            open_blocks.append((call, True))  # one child statement follows
            continue
        raise ts.error(tok.line, f"expected ';' or '{{' after {call.name}(...), got {_show(tok)}", call.name)
