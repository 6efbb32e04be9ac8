"""A parser of a conservative subset of the OpenSCAD language, for :mod:`isocsg.openscad.evaluate`.

It reads statements (assignments, module instantiations with ``;``, one child or a ``{ }``
block, a bare ``{ }`` block (its statements are those of the scope around, as OpenSCAD's
grammar has them), ``for``, ``if``/``else``, ``module`` and ``function`` definitions) and expressions
(numbers, strings, ``true``/``false``/``undef``, vectors, ranges, the operators of OpenSCAD
2021.01's grammar with its precedence, indexing, ``.x``/``.y``/``.z`` and calls of named
functions, ``let``, list comprehensions with ``for``, C-style ``for``, ``each``, ``if``/``else``
and ``let``) into tuples, the ``let`` statement, and ``include``/``use`` of a file found
(:mod:`~isocsg.openscad.scad_files`). Anything else (function
literals, ``assert``, modifiers ``* ! # %``, ...) raises
:class:`Declined`: the file is left to the ``openscad`` program.

The parser is recursive descent with a depth limit (:data:`MAX_DEPTH`): a deeper file raises
:class:`Declined` too, never a ``RecursionError``.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any, Protocol

__all__ = ["Declined", "MAX_DEPTH", "parse_scad"]

#: Deepest nesting of expressions and statements read (deeper files go to the program).
MAX_DEPTH = 60


class Files(Protocol):
    """What finds and reads the files of ``include`` and ``use`` (:class:`isocsg.openscad.scad_files.Files`)."""

    def find(self, name: str, source: Path | None, open_files: tuple[Path, ...]) -> Path: ...

    def read(self, path: Path, open_files: tuple[Path, ...]) -> str: ...


class Declined(Exception):  # noqa: N818 (a signal, not an error: the program reads the file)
    """The text is outside the subset read in-process."""


_TOKEN = re.compile(
    r"""
    (?P<ws>[ \t\r\f\v]+)
  | (?P<nl>\n)
  | (?P<comment>//[^\n]*|/\*.*?\*/)
  | (?P<number>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)
  | (?P<string>"(?:[^"\\\n]|\\[nrt"\\])*")
  | (?P<name>\$?[A-Za-z_][A-Za-z0-9_]*)
  | (?P<op><=|>=|==|!=|&&|\|\||[-+*/%^<>!?:=(){}\[\],;.])
    """,
    re.VERBOSE | re.DOTALL,
)
#: What OpenSCAD's lexer reads as ``include <...>`` and ``use <...>``.
_FILE_STATEMENT = re.compile(r"(include|use)[ \t\r\n>]*<([^\t\r\n>]*)>")
_ESCAPES = {"n": "\n", "t": "\t", "r": "\r", '"': '"', "\\": "\\"}
# names the subset does not read; each one declines the file wherever it appears
_REFUSED = {"assert", "function_literal",
            "import", "surface", "text", "projection", "resize", "render", "parent_module",
            "search", "str", "chr", "ord", "is_undef",
            "is_num", "is_string", "is_list", "is_bool", "is_function", "rands", "dxf_dim",
            "dxf_cross", "roof", "fill", "object", "import_dxf", "import_stl"}
_KEYWORDS = {"true": ("bool", True), "false": ("bool", False), "undef": ("undef",)}
#: Words of OpenSCAD's grammar that name nothing (no variable, parameter or module).
_RESERVED = {*_KEYWORDS, "module", "function", "for", "if", "else", "let", "each"}
#: Names whose value OpenSCAD sets itself (an assignment or argument of one is declined).
_SET_BY_OPENSCAD = {"$children", "$parent_modules", "$preview"}
#: What starts an element of a list comprehension.
_ELEMENTS = {"for", "each", "if", "let"}
_BINARY = [  # loosest first, as OpenSCAD 2021.01's parser.y
    ("||",), ("&&",), ("==", "!="), ("<", "<=", ">", ">="), ("+", "-"), ("*", "/", "%"),
]


def _tokens(text: str, files: Files | None = None, path: Path | None = None,
            open_files: tuple[Path, ...] = ()) -> list[tuple[str, str, int]]:
    """The tokens of ``text`` (of the file ``path``): an ``include``'s file's tokens in its place,
    a ``use`` as one token of the path found (:mod:`~isocsg.openscad.scad_files`)."""
    out: list[tuple[str, str, int]] = []
    line, pos, n = 1, 0, len(text)
    while pos < n:
        m = _TOKEN.match(text, pos)
        if m is None:
            raise Declined(f"line {line}: unexpected {text[pos]!r}")
        kind, tok = m.lastgroup or "", m.group()
        if kind == "number" and m.end() < n and (text[m.end()].isalnum() or text[m.end()] in "_$"):
            raise Declined(f"line {line}: a name that starts with a digit")  # OpenSCAD's lexer reads one
        if kind == "nl":
            line += 1
        elif kind == "comment":
            line += tok.count("\n")
        elif kind != "ws":
            if kind == "name" and tok in _REFUSED:
                raise Declined(f"line {line}: {tok}")
            if kind == "name" and tok in ("include", "use"):
                pos = _file_statement(text, pos, line, files, path, open_files, out)
                line += text.count("\n", m.start(), pos)
                continue
            out.append((kind, tok, line))
        pos = m.end()
    out.append(("eof", "", line))
    return out


def _file_statement(text: str, pos: int, line: int, files: Files | None, path: Path | None,
                    open_files: tuple[Path, ...], out: list[tuple[str, str, int]]) -> int:
    """``include <f>`` (``f``'s tokens appended) or ``use <f>`` (a ``use`` token) at ``pos``; where it ends."""
    m = _FILE_STATEMENT.match(text, pos)
    if m is None or files is None:
        raise Declined(f"line {line}: include or use")
    found = files.find(m.group(2), None if path is None else path.parent, open_files)
    if m.group(1) == "use":
        out.append(("use", str(found), line))
    else:
        inner = (*open_files, found)
        out.extend(_tokens(files.read(found, inner), files, found, inner)[:-1])
    return m.end()


class _Parser:
    def __init__(self, text: str, files: Files | None = None, path: Path | None = None) -> None:
        self.toks = _tokens(text, files, path, () if path is None else (path,))
        self.i = 0
        self.depth = 0

    # -- tokens
    def peek(self, k: int = 0) -> tuple[str, str, int]:
        return self.toks[min(self.i + k, len(self.toks) - 1)]

    def at(self, text: str, k: int = 0) -> bool:
        kind, tok, _ = self.peek(k)
        return kind == "op" and tok == text

    def take(self, text: str) -> None:
        if not self.at(text):
            raise Declined(f"line {self.peek()[2]}: expected {text!r}, got {self.peek()[1]!r}")
        self.i += 1

    def name(self) -> str:
        kind, tok, line = self.peek()
        if kind != "name" or tok in _RESERVED:
            raise Declined(f"line {line}: expected a name, got {tok!r}")
        if tok in _SET_BY_OPENSCAD:
            raise Declined(f"line {line}: {tok} set in the file")
        self.i += 1
        return tok

    def enter(self) -> None:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise Declined("nested too deeply")

    # -- statements
    def statements(self, until: str, defs: bool = True) -> list[Any]:
        out: list[Any] = []
        while not (self.at(until) if until else self.peek()[0] == "eof"):
            if self.peek()[0] == "eof":
                raise Declined("unclosed block")
            st = self.statement(defs)
            if st is not None and st[0] == "block":  # a bare { } block: its statements are the scope's
                out.extend(st[1])
            elif st is not None:
                out.append(st)
        return out

    def body(self, defs: bool = False) -> list[Any]:
        """A child: one statement or a ``{ }`` block; ``module`` and ``function`` definitions only
        in a module's body (``defs``), as OpenSCAD's grammar has them (not under a call, ``for`` or
        ``if``)."""
        if self.at("{"):
            self.i += 1
            out = self.statements("}", defs)
            self.i += 1
            return out
        st = self.statement(defs)
        if st is not None and st[0] == "assign" and not defs:
            raise Declined(f"line {st[3]}: an assignment as a child without braces (a syntax error)")
        return [] if st is None else [st]

    def statement(self, defs: bool = True) -> Any:
        self.enter()
        try:
            return self._statement(defs)
        finally:
            self.depth -= 1

    def _statement(self, defs: bool) -> Any:
        kind, tok, line = self.peek()
        if kind == "op" and tok == ";":
            self.i += 1
            return None
        if kind == "op" and tok == "{":
            self.i += 1
            block = self.statements("}", defs)
            self.i += 1
            return ("block", block, line)
        if kind == "use":
            if self.depth != 1:
                raise Declined(f"line {line}: use below the top level (a syntax error)")
            self.i += 1
            return ("use", tok, line)
        if kind != "name":
            raise Declined(f"line {line}: {tok!r} starts no statement read here")
        if tok in ("module", "function") and not defs:
            raise Declined(f"line {line}: a {tok} definition under a call, for or if (a syntax error)")
        if tok == "module":
            self.i += 1
            name = self.name()
            params = self.params()
            return ("module", name, params, self.body(defs=True), line)
        if tok == "function":
            self.i += 1
            name = self.name()
            params = self.params()
            self.take("=")
            expr = self.expr()
            self.take(";")
            return ("function", name, params, expr, line)
        if tok == "for":
            self.i += 1
            args = self.args()
            if not args or any(n is None for n, _ in args):
                raise Declined(f"line {line}: for without a variable")
            return ("for", args, self.body(), line)
        if tok == "if":
            self.i += 1
            self.take("(")
            cond = self.expr()
            self.take(")")
            then = self.body()
            other = None
            if self.peek()[:2] == ("name", "else"):
                self.i += 1
                other = self.body()
            return ("if", cond, then, other, line)
        if tok == "let":
            self.i += 1
            return ("let", self.assignments(")"), self.body(), line)
        if tok in _RESERVED:
            raise Declined(f"line {line}: {tok}")
        if self.at("=", 1):
            self.name()
            self.i += 1
            expr = self.expr()
            self.take(";")
            return ("assign", tok, expr, line)
        self.i += 1
        args = self.args()
        if self.at(";"):
            self.i += 1
            return ("inst", tok, args, [], line)
        return ("inst", tok, args, self.body(), line)

    def params(self) -> list[tuple[str, Any]]:
        self.take("(")
        out: list[tuple[str, Any]] = []
        while not self.at(")"):
            name = self.name()
            default = None
            if self.at("="):
                self.i += 1
                default = self.expr()
            out.append((name, default))
            if not self.at(")"):
                self.take(",")
        self.i += 1
        if len({n for n, _ in out}) != len(out):
            raise Declined("a parameter named twice")
        return out

    def args(self) -> list[tuple[str | None, Any]]:
        self.take("(")
        out: list[tuple[str | None, Any]] = []
        while not self.at(")"):
            name = None
            if self.peek()[0] == "name" and self.at("=", 1):
                name = self.name()
                self.i += 1
            out.append((name, self.expr()))
            if not self.at(")"):
                self.take(",")
                if self.at(")") or self.at(","):  # OpenSCAD: no trailing comma in a call
                    raise Declined(f"line {self.peek()[2]}: a comma before ')'")
        self.i += 1
        return out

    def assignments(self, close: str) -> list[tuple[str, Any]]:
        """``(a = 1, b = a + 1)`` of ``let``: named, each name once (OpenSCAD warns otherwise)."""
        self.take("(")
        out = self.bindings((close,))
        self.take(close)
        return out

    def bindings(self, ends: tuple[str, ...]) -> list[tuple[str, Any]]:
        """``a = 1, b = a + 1`` up to one of ``ends`` (not taken)."""
        out: list[tuple[str, Any]] = []
        while not any(self.at(end) for end in ends):
            line = self.peek()[2]
            name = self.name()
            self.take("=")
            out.append((name, self.expr()))
            if not any(self.at(end) for end in ends):
                self.take(",")
                if any(self.at(end) for end in (*ends, ",")):  # no trailing comma, as in a call
                    raise Declined(f"line {line}: a comma before {self.peek()[1]!r}")
        if len({n for n, _ in out}) != len(out):
            raise Declined("a variable bound twice in one let or for (a warning)")
        return out

    # -- expressions
    def expr(self) -> Any:
        self.enter()
        try:
            if self.peek()[:2] == ("name", "let"):  # let (a = 1, b = a + 1) expr
                self.i += 1
                return ("let", self.assignments(")"), self.expr())
            cond = self.binary(0)
            if self.at("?"):
                self.i += 1
                a = self.expr()
                self.take(":")
                return ("tern", cond, a, self.expr())
            return cond
        finally:
            self.depth -= 1

    def binary(self, level: int) -> Any:
        if level == len(_BINARY):
            return self.unary()
        left = self.binary(level + 1)
        while self.peek()[0] == "op" and self.peek()[1] in _BINARY[level]:
            op = self.peek()[1]
            self.i += 1
            left = ("bin", op, left, self.binary(level + 1))
        return left

    def unary(self) -> Any:
        if self.peek()[0] == "op" and self.peek()[1] in "+-!":
            op = self.peek()[1]
            self.i += 1
            self.enter()
            try:
                inner = self.unary()
            finally:
                self.depth -= 1
            return inner if op == "+" else ("un", op, inner)
        base = self.postfix()
        if self.at("^"):
            self.i += 1
            self.enter()
            try:
                return ("bin", "^", base, self.unary())
            finally:
                self.depth -= 1
        return base

    def postfix(self) -> Any:
        e = self.primary()
        while True:
            if self.at("["):
                self.i += 1
                e = ("index", e, self.expr())
                self.take("]")
            elif self.at("."):
                self.i += 1
                e = ("member", e, self.name())
            elif self.at("("):
                if e[0] != "var":
                    raise Declined("a call of an expression")
                e = ("call", e[1], self.args())
            else:
                return e

    def primary(self) -> Any:
        kind, tok, line = self.peek()
        self.i += 1
        if kind == "number":
            return ("num", float(tok))
        if kind == "string":
            return ("str", re.sub(r"\\(.)", lambda m: _ESCAPES[m.group(1)], tok[1:-1]))
        if kind == "name":
            if tok in _KEYWORDS:
                return _KEYWORDS[tok]
            if tok in _RESERVED:
                raise Declined(f"line {line}: {tok} in an expression")
            return ("var", tok)
        if kind == "op" and tok == "(":
            e = self.expr()
            self.take(")")
            return e
        if kind == "op" and tok == "[":
            return self.vector(line)
        raise Declined(f"line {line}: {tok!r} in an expression")

    def vector(self, line: int) -> Any:
        while self.at(","):  # OpenSCAD reads [,] as []
            self.i += 1
            if not self.at("]"):
                raise Declined(f"line {line}: a vector that starts with a comma")
        if self.at("]"):
            self.i += 1
            return ("vec", [])
        first = self.element()
        if self.at(":"):
            if first[0].startswith("lc_"):
                raise Declined(f"line {line}: a list comprehension in a range")
            self.i += 1
            second = self.expr()
            if self.at(":"):
                self.i += 1
                third = self.expr()
                self.take("]")
                return ("range", first, second, third)
            self.take("]")
            return ("range", first, None, second)
        items = [first]
        while self.at(","):
            while self.at(","):  # repeated and trailing commas, as OpenSCAD's grammar allows
                self.i += 1
            if self.at("]"):
                break
            items.append(self.element())
        self.take("]")
        return ("vec", items)

    def element(self) -> Any:
        """An element of a vector: an expression, or an element of a list comprehension
        (``for``, C-style ``for``, ``each``, ``if``/``else``, ``let``; their values are spliced in)."""
        kind, tok, line = self.peek()
        if kind != "name" or tok not in _ELEMENTS:
            return self.expr()
        self.enter()
        try:
            return self._element(tok, line)
        finally:
            self.depth -= 1

    def _element(self, tok: str, line: int) -> Any:
        self.i += 1
        if tok == "let":
            bound = self.assignments(")")
            body = self.element()
            return ("lc_let", bound, body) if body[0].startswith("lc_") else ("let", bound, body)
        if tok == "each":
            return ("lc_each", self.element())
        if tok == "if":
            self.take("(")
            cond = self.expr()
            self.take(")")
            then = self.element()
            other = None
            if self.peek()[:2] == ("name", "else"):
                self.i += 1
                other = self.element()
            return ("lc_if", cond, then, other)
        self.take("(")  # for
        first = self.bindings((")", ";"))
        if self.at(";"):  # for (i = 0; i < n; i = i + 1)
            self.i += 1
            cond = self.expr()
            self.take(";")
            step = self.bindings((")",))
            self.take(")")
            if not first or not {n for n, _ in step} <= {n for n, _ in first}:
                raise Declined(f"line {line}: a C-style for that sets a variable it does not start with")
            return ("lc_forc", first, cond, step, self.element())
        self.take(")")
        if not first:
            raise Declined(f"line {line}: for without a variable")
        return ("lc_for", first, self.element())


def parse_scad(text: str, files: Files | None = None, path: Path | None = None) -> list[Any]:
    """The statements of ``.scad`` text as tuples (module docstring); with ``files`` and the
    text's ``path`` (resolved), its ``include``s are read in place and its ``use``s are
    ``("use", path found, line)`` statements.

    Raises
    ------
    Declined
        For text outside the subset (the ``openscad`` program reads it).
    """
    p = _Parser(text, files, path)
    return p.statements("")
