"""A conservative subset of the OpenSCAD language, evaluated in this process.

:func:`evaluate_scad` reads ``.scad`` text with variables, vectors, ranges, arithmetic,
comparisons, the trigonometric and other numeric built-in functions, ``let``, list
comprehensions (:mod:`~isocsg.openscad.scad_comprehensions`), ``for`` loops, ``if``/``else``,
the ``let`` statement, module and function definitions (not recursive), ``children()`` in
modules, ``echo``, ``$fn``/``$fa``/``$fs`` and, for text read from a file, ``include`` and ``use``
(:mod:`~isocsg.openscad.scad_files`), and builds the tree of
:class:`~isocsg.openscad.parser.CSGCall` that :func:`~isocsg.openscad.parser.parse_csg` reads
from OpenSCAD 2021.01's ``.csg`` export of the same file: the same nodes (a ``group()`` for each
loop, ``if``, ``let``, module instance and ``children()`` but ``children(i)``, ``multmatrix`` for
the maps, computed as OpenSCAD's ``transform.cc`` computes them), the same
default arguments, and every number rounded to the 6 significant digits the export prints.

Anything outside the subset, or that OpenSCAD would answer with a warning (an undefined
variable, a bad argument, a variable assigned twice in a scope, ...), raises
:class:`~isocsg.openscad.scad_syntax.Declined` inside and makes :func:`evaluate_scad` return
None: the ``openscad`` program reads that file. Nesting (of the text and of module calls) is
limited to :data:`~isocsg.openscad.scad_syntax.MAX_DEPTH`; a deeper file is declined.
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Any

from .parser import CSGCall
from .scad_comprehensions import loop_values, vector
from .scad_files import MAX_FILE_DEPTH, Files
from .scad_modules import builtin_module
from .scad_syntax import MAX_DEPTH, Declined, parse_scad
from .scad_values import Range, Scope, binary, builtin_function, truthy, unary

__all__ = ["MAX_NODES", "MAX_STEPS", "declined_because", "evaluate_scad"]

#: Most nodes built (a larger model's own work outweighs an ``openscad`` run).
MAX_NODES = 20000
#: Most expressions evaluated (functions calling functions can take exponential time); the
#: values a list comprehension's ``each`` splices in, and the elements of the vectors an
#: operator or a built-in function other than ``len`` reads or gives, count too.
MAX_STEPS = 1_000_000
#: The statements that instantiate (what ``children()`` counts and indexes).
INSTANTIATIONS = ("inst", "for", "if", "let")


class _Evaluator:
    def __init__(self, files: Files | None = None) -> None:
        self.files = files
        self.libraries: dict[str, Scope] = {}  # the used files read, by path
        self.loading: list[str] = []  # the used files being read (a cycle is declined)
        self.depth = 0
        self.nodes = 0
        self.steps = 0
        self.active: set[int] = set()  # the definitions being evaluated (recursion declined)

    def enter(self) -> None:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise Declined("nested too deeply")

    # -- expressions
    def expr(self, e: Any, f: Scope) -> Any:
        self.steps += 1
        if self.steps > MAX_STEPS:
            raise Declined("too much work (nested function calls)")
        self.enter()
        try:
            return self._expr(e, f)
        finally:
            self.depth -= 1

    def _expr(self, e: Any, f: Scope) -> Any:
        kind = e[0]
        if kind in ("num", "str", "bool"):
            return e[1]
        if kind == "undef":
            return None
        if kind == "var":
            return f.lookup(e[1])
        if kind == "vec":
            return vector(self, e[1], f)
        if kind == "let":
            return self.expr(e[2], self.let_scope(e[1], f))
        if kind == "range":
            b = self.expr(e[1], f)
            s = 1.0 if e[2] is None else self.expr(e[2], f)
            end = self.expr(e[3], f)
            if not all(type(x) is float for x in (b, s, end)):
                raise Declined("a range of non-numbers")
            if e[2] is None and b > end:
                raise Declined("a range [begin:end] with begin > end (deprecated, a warning)")
            if (s > 0 and b > end) or (s < 0 and b < end):
                raise Declined("a range whose step goes away from its end (a warning)")
            return Range(b, s, end)
        if kind == "un":
            return unary(e[1], self.counted(self.expr(e[2], f)))
        if kind == "bin":
            op = e[1]
            a = self.expr(e[2], f)
            if op == "&&":
                return truthy(a) and truthy(self.expr(e[3], f))
            if op == "||":
                return truthy(a) or truthy(self.expr(e[3], f))
            b = self.expr(e[3], f)
            if op not in ("==", "!="):
                return binary(op, self.counted(a), self.counted(b))
            if isinstance(a, list) and isinstance(b, list) and len(a) == len(b):  # compared all the way down
                self.steps += _size(a, MAX_STEPS)
            return binary(op, a, b)
        if kind == "tern":
            return self.expr(e[2] if truthy(self.expr(e[1], f)) else e[3], f)
        if kind == "index":
            return _index(self.expr(e[1], f), self.expr(e[2], f))
        if kind == "member":
            v = self.expr(e[1], f)
            if e[2] not in ("x", "y", "z") or not isinstance(v, list):
                raise Declined(f".{e[2]}")
            return _index(v, float("xyz".index(e[2])))
        if kind == "call":
            return self.call_function(e[1], e[2], f)
        raise Declined(kind)

    def counted(self, v: Any) -> Any:
        """``v``, its length counted as work when it is a vector (an operator or a built-in
        function goes through it: ``concat`` of long vectors in a loop takes long)."""
        if isinstance(v, list):
            self.steps += len(v)
        return v

    def call_function(self, name: str, args: list[Any], f: Scope) -> Any:
        found = f.find("functions", name)
        if found is None:
            if any(n is not None for n, _ in args):
                raise Declined(f"{name} with named arguments")
            values = [self.expr(x, f) for _, x in args]
            if name != "len":  # the others read every element
                for v in values:
                    self.counted(v)
            return self.counted(builtin_function(name, values))
        (_, _, params, body, _), home = found
        if id(found[0]) in self.active:
            raise Declined(f"recursive function {name}")
        frame = Scope(home, f, self.bind(params, args, f, home, name))
        self.active.add(id(found[0]))
        try:
            return self.expr(body, frame)
        finally:
            self.active.discard(id(found[0]))

    def bind(self, params: list[tuple[str, Any]], args: list[Any], f: Scope, home: Scope,
             name: str) -> dict[str, Any]:
        """Parameters' values: arguments evaluated in the caller, defaults in the definition's scope."""
        names = [p for p, _ in params]
        values: dict[str, Any] = {}
        for i, (arg_name, x) in enumerate(args):
            key = arg_name if arg_name is not None else (names[i] if i < len(names) else None)
            if key is None or key in values or (not key.startswith("$") and key not in names):
                raise Declined(f"an argument of {name} that is not a parameter")
            if arg_name is None and any(a is not None for a, _ in args[:i]):
                raise Declined("a positional argument after named ones")
            values[key] = self.expr(x, f)
        for p, default in params:
            if p not in values:
                if default is not None and (_names(default) & set(names)
                                            or any(n.startswith("$") for n in _names(default))):
                    raise Declined(f"a default of {name} that names a parameter or a $ variable")
                values[p] = None if default is None else self.expr(default, home)
        return values

    def let_scope(self, bindings: list[tuple[str, Any]], f: Scope) -> Scope:
        """``let (a = 1, b = a + 1)``: a scope whose values are bound in turn, each seeing the ones before."""
        frame = Scope(f, f)
        for name, x in bindings:
            frame.vars[name] = self.expr(x, frame)
        return frame

    # -- statements
    def scope(self, statements: list[Any], f: Scope) -> list[CSGCall]:
        """The nodes of a scope's statements: definitions first, then assignments, then the rest."""
        self.prepare(statements, f)
        out: list[CSGCall] = []
        for s in statements:
            if s[0] in INSTANTIATIONS:
                out.extend(self.child(s, f))
        return out

    def child(self, s: Any, f: Scope) -> list[CSGCall]:
        """The node of one instantiation (none for a false ``if`` or an ``echo``)."""
        self.enter()
        try:
            return self.statement(s, f)
        finally:
            self.depth -= 1

    def prepare(self, statements: list[Any], f: Scope) -> None:
        """A scope's definitions and assignments (in turn: a variable read before its assignment is declined)."""
        assigned = [s[1] for s in statements if s[0] == "assign"]
        if len(set(assigned)) != len(assigned) or "$preview" in assigned:
            raise Declined("a variable assigned twice in one scope")
        if set(assigned) & set(f.vars):
            raise Declined("an assignment of a parameter or a loop variable")
        for s in statements:
            if s[0] in ("module", "function"):
                table = f.modules if s[0] == "module" else f.functions
                if s[1] in table:
                    raise Declined(f"{s[0]} {s[1]} defined twice")
                table[s[1]] = (s, f)
        for path in dict.fromkeys(s[1] for s in statements if s[0] == "use"):
            f.uses.append(self.library(path))
        f.pending = set(assigned)
        for s in statements:
            if s[0] == "assign":
                f.vars[s[1]] = self.expr(s[2], f)
                f.pending.discard(s[1])

    def library(self, path: str) -> Scope:
        """The scope of a used file: its modules, functions and uses, and its top-level variables,
        which its definitions see (OpenSCAD 2021.01 evaluates them in the used file's scope, where
        the user's variables are unknown); its geometry is not read. A used file's top-level
        ``$`` variable (set or read) is declined: OpenSCAD evaluates those at each call."""
        if path in self.libraries:
            return self.libraries[path]
        if path in self.loading or len(self.loading) >= MAX_FILE_DEPTH or self.files is None:
            raise Declined(f"use <{path}>: a cycle or nested too deeply")
        self.loading.append(path)
        try:
            found = Path(path)
            statements = parse_scad(self.files.read(found, (found,)), self.files, found)
            if any(s[0] == "assign" and s[1].startswith("$") for s in statements):
                raise Declined(f"{path}: a $ variable set at its top level")
            lib = Scope(None, _LIBRARY_TOP)
            self.prepare(statements, lib)
        finally:
            self.loading.pop()
        self.libraries[path] = lib
        return lib

    def statement(self, s: Any, f: Scope) -> list[CSGCall]:
        self.nodes += 1
        if self.nodes > MAX_NODES:
            raise Declined("too many nodes")
        if s[0] == "for":
            children: list[CSGCall] = []
            self.loop(s[1], s[2], f, {}, children)
            return [CSGCall("group", children=children, line=s[3])]
        if s[0] == "if":
            if truthy(self.expr(s[1], f)):
                body = s[2]
            elif s[3] is not None:
                body = s[3]
            else:
                return []  # a false if without else leaves no node in the export
            return [CSGCall("group", children=self.scope(body, Scope(f, f)), line=s[4])]
        if s[0] == "let":  # a group of its children, in a scope of its values
            return [CSGCall("group", children=self.scope(s[2], self.let_scope(s[1], f)), line=s[3])]
        return self.instance(s, f)

    def loop(self, variables: list[Any], body: list[Any], f: Scope, bound: dict[str, Any],
             out: list[CSGCall]) -> None:
        """``for (i = ..., j = ...)``: the body for every combination, in one group."""
        todo: list[tuple[int, dict[str, Any]]] = [(0, bound)]
        while todo:
            k, values = todo.pop()
            if k == len(variables):
                out.extend(self.scope(body, Scope(f, f, values)))
                continue
            name, x = variables[k]
            items = loop_values(self.expr(x, Scope(f, f, values)))
            todo.extend((k + 1, {**values, name: v}) for v in reversed(items))

    def instance(self, s: Any, f: Scope) -> list[CSGCall]:
        _, name, args, children, line = s
        if name == "echo":
            if children:
                raise Declined("echo with children")
            for _, x in args:  # echo(version=version()) ends OpenSCAD's examples
                if x[0] != "call" or x[1:] not in (("version", []), ("version_num", [])):
                    self.expr(x, f)
            return []
        found = f.find("modules", name)
        if found is not None:
            if name == "children":
                raise Declined("a module named children")
            return [self.user_module(found, args, children, f, line)]
        if name == "children":
            if children:
                raise Declined("children() with children")
            return self.children(args, f, line)
        if name == "intersection_for":  # the nodes of every iteration, flat, in an intersection()
            if not args or any(n is None for n, _ in args):
                raise Declined("intersection_for without a variable")
            nodes: list[CSGCall] = []
            self.loop(args, children, f, {}, nodes)
            return [CSGCall("intersection", children=nodes, line=line)]
        return [builtin_module(self, name, args, children, f, line)]

    def user_module(self, found: tuple[Any, Scope], args: list[Any], children: list[Any], f: Scope,
                    line: int) -> CSGCall:
        """A ``group()`` of the module's body. The children's assignments are evaluated here, once,
        in the caller's scope (as OpenSCAD does, whether or not the body calls ``children()``); the
        body's ``$`` variables see them (they are below the module's own on OpenSCAD's stack)."""
        (_, name, params, body, _), home = found
        if id(found[0]) in self.active:
            raise Declined(f"recursive module {name}")
        block = Scope(f, f)
        self.prepare(children, block)
        frame = Scope(home, block, self.bind(params, args, f, home, name))
        instances = [s for s in children if s[0] in INSTANTIATIONS]
        frame.vars["$children"] = float(len(instances))
        frame.call = (instances, block, set(self.active))
        self.active.add(id(found[0]))
        try:
            return CSGCall("group", children=self.scope(body, frame), line=line)
        finally:
            self.active.discard(id(found[0]))

    def children(self, args: list[Any], f: Scope, line: int) -> list[CSGCall]:
        """``children()`` (a group of all), ``children(i)`` (the child's node itself, or none),
        ``children([i, j])`` and ``children(range)`` (a group): the children of the nearest user
        module call around (through the definitions), each evaluated in the caller's scope for
        names and in this one for ``$`` variables, as OpenSCAD 2021.01 does."""
        frame: Scope | None = f
        while frame is not None and frame.call is None:
            frame = frame.lex
        if frame is None:
            raise Declined("children() outside a module")
        instances, block, active = frame.call
        group = True
        picked: list[int] = list(range(len(instances)))
        if args:
            if len(args) > 1 or args[0][0] is not None:
                raise Declined("children() with a named argument or more than one")
            v = self.expr(args[0][1], f)
            group = type(v) is not float
            if isinstance(v, Range):
                v = v.values()
                if len(v) >= 10000:
                    raise Declined("children() of a range of 10000 values or more")
            picked = [_child_index(x, len(instances)) for x in (v if isinstance(v, list) else [v])]
        nodes: list[CSGCall] = []
        saved, self.active = self.active, set(active)  # the children's calls are the caller's
        try:
            for k in picked:
                nodes.extend(self.child(instances[k], Scope(block, f)))
        finally:
            self.active = saved
        return [CSGCall("group", children=nodes, line=line)] if group else nodes


#: Below a used file's top-level scope for ``$`` names: OpenSCAD reads them from the stack of
#: the call that evaluates the file's variables, which is not known here (declined).
_LIBRARY_TOP = Scope(None, None)
_LIBRARY_TOP.pending = {"$fn", "$fa", "$fs", "$t"}


def _size(v: Any, limit: int) -> int:
    """The count of the values a vector holds, nested ones too (declined beyond ``limit``)."""
    count = 0
    todo = [v]
    while todo:
        x = todo.pop()
        if isinstance(x, list):
            count += len(x)
            if count > limit:
                raise Declined("too much work (comparing long vectors)")
            todo.extend(y for y in x if isinstance(y, list))
    return count


def _child_index(v: Any, count: int) -> int:
    """``children(v)``'s index: a number truncated, within the children (OpenSCAD warns otherwise)."""
    if type(v) is not float or not abs(v) < 2**31:
        raise Declined("children() of something else than a number, a vector or a range")
    k = int(math.trunc(v))
    if not 0 <= k < count:
        raise Declined("a children() index out of range")
    return k


def _index(v: Any, i: Any) -> Any:
    if not isinstance(v, list) or type(i) is not float or i != math.floor(i) or not 0 <= i < len(v):
        raise Declined("an index out of range or of something else than a vector")
    return v[int(i)]


def _names(e: Any) -> set[str]:
    """The variable names an expression reads."""
    out: set[str] = set()
    todo = [e]
    while todo:
        x = todo.pop()
        if isinstance(x, tuple):
            if x and x[0] == "var":
                out.add(x[1])
            todo.extend(x[1:])
        elif isinstance(x, list):
            todo.extend(x)
    return out


def _evaluate(text: str, path: str | os.PathLike[str] | None) -> list[CSGCall]:
    try:
        root = None if path is None else Path(path).resolve()
        files = None if root is None else Files(root)
        return _Evaluator(files).scope(parse_scad(text, files, root), Scope(None, None))
    except (RecursionError, OverflowError, ValueError, ZeroDivisionError, TypeError, IndexError, KeyError) as exc:
        raise Declined(f"{type(exc).__name__}: {exc}") from None


def declined_because(text: str, *, path: str | os.PathLike[str] | None = None) -> str | None:
    """Why :func:`evaluate_scad` leaves this text to the program, or None if it reads it.

    >>> declined_because("cube(size = x);")
    'unknown variable x'
    """
    try:
        _evaluate(text, path)
    except Declined as exc:
        return str(exc)
    return None


def evaluate_scad(text: str, *, path: str | os.PathLike[str] | None = None) -> list[CSGCall] | None:
    """The top-level nodes OpenSCAD 2021.01's ``.csg`` export of this ``.scad`` text gives, as
    :func:`~isocsg.openscad.parser.parse_csg` reads them; None for text outside the subset
    (:func:`declined_because` says why) and for text that makes no node. ``path`` is the text's
    file: its ``include <f>`` and ``use <f>`` are read (:mod:`~isocsg.openscad.scad_files`);
    text without one declines them.

    Examples
    --------
    >>> (loop,) = evaluate_scad("n = 3; for (i = [0:n - 1]) translate([2 * i, 0, 0]) cube(1);")
    >>> loop.name, [c.name for c in loop.children], loop.children[2].args[0][0][3]
    ('group', ['multmatrix', 'multmatrix', 'multmatrix'], 4.0)
    >>> evaluate_scad("include <lib.scad>\\ncube(1);") is None
    True
    """
    try:
        calls = _evaluate(text, path)
    except Declined:
        return None
    return calls or None
