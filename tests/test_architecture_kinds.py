"""No module outside ``isocsg/kinds/`` tests for a concrete primitive kind.

What a kind is and does goes through the kind interface (:class:`isocsg.kinds.Primitive`: its
members, its class attributes, its :meth:`~isocsg.kinds.Primitive.exact_form`), so that a kind
registered by user code is taken everywhere a built-in one is. This test parses every module of
the package outside ``isocsg/kinds/`` and fails on any ``isinstance`` / ``issubclass`` test,
``type(x) is K`` / ``==`` / ``in`` comparison or ``match`` class pattern against a class of the
live kind registry, and on comparisons of a ``kind`` name or class name with a kind's name.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import isocsg.kinds  # noqa: F401  (registers the built-in kinds)
from isocsg.kinds.registry import registered_kinds

PACKAGE = Path(isocsg.kinds.__file__).resolve().parent.parent
KINDS = PACKAGE / "kinds"


def kind_classes() -> set[str]:
    """The class names of every registered kind and of their registered bases (Cylinder, Truncus...)."""
    return {k.cls.__name__ for k in registered_kinds()}


def kind_names() -> set[str]:
    return {k.name for k in registered_kinds()}


def _names(node: ast.AST) -> list[str]:
    """The class names an expression mentions: ``K``, ``mod.K``, or a tuple / list / set of them."""
    if isinstance(node, ast.Name):
        return [node.id]
    if isinstance(node, ast.Attribute):
        return [node.attr]
    if isinstance(node, (ast.Tuple, ast.List, ast.Set)):
        return [n for e in node.elts for n in _names(e)]
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.BitOr):  # isinstance(x, A | B)
        return _names(node.left) + _names(node.right)
    return []


def _strings(node: ast.AST) -> list[str]:
    """The strings an expression holds: ``'K'``, or a tuple / list / set of them."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return [node.value]
    if isinstance(node, (ast.Tuple, ast.List, ast.Set)):
        return [v for e in node.elts for v in _strings(e)]
    return []


def _is_type_of(node: ast.AST) -> bool:
    """``type(x)`` or ``x.__class__``."""
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "type":
        return len(node.args) == 1
    return isinstance(node, ast.Attribute) and node.attr == "__class__"


def _is_name_of(node: ast.AST) -> bool:
    """``x.kind``, ``x.__name__`` or ``x.__qualname__`` (a kind named by a string)."""
    return isinstance(node, ast.Attribute) and node.attr in ("kind", "__name__", "__qualname__")


def kind_tests(source: str, classes: set[str], names: set[str]) -> list[tuple[int, str]]:
    """Every test for a concrete kind in ``source``, as (line, text)."""
    tree = ast.parse(source)
    aliases = dict.fromkeys(classes, "")
    for node in ast.walk(tree):  # `from ..kinds import Box as B`: B is a kind too
        if isinstance(node, ast.ImportFrom):
            for a in node.names:
                if a.name in classes and a.asname:
                    aliases[a.asname] = a.name
    hits: list[tuple[int, str]] = []

    def found(node: ast.AST) -> None:
        hits.append((node.lineno, ast.unparse(node)))  # type: ignore[attr-defined]

    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in ("isinstance", "issubclass"):
            if len(node.args) == 2 and any(n in aliases for n in _names(node.args[1])):
                found(node)
        elif isinstance(node, ast.Compare):
            sides = [node.left, *node.comparators]
            if any(_is_type_of(s) for s in sides) and any(n in aliases for s in sides for n in _names(s)):
                found(node)
            elif any(_is_name_of(s) for s in sides) and any(v in names | classes for s in sides for v in _strings(s)):
                found(node)
        elif isinstance(node, ast.MatchClass) and any(n in aliases for n in _names(node.cls)):
            found(node)
    return hits


def package_modules() -> list[Path]:
    return sorted(p for p in PACKAGE.rglob("*.py") if KINDS not in p.parents)


def test_the_registry_is_read():
    classes = kind_classes()
    assert {"Sphere", "Truncus", "Cylinder", "Box", "ConvexPolyhedron", "Torus", "TriangleMesh"} <= classes
    assert len(package_modules()) > 100


@pytest.mark.parametrize(
    "source",
    [
        "if isinstance(p, Sphere): pass",
        "ok = isinstance(p, (k.Box, Torus))",
        "ok = isinstance(p, Box | None)",
        "ok = type(p) is Truncus",
        "ok = type(p) in (Cylinder, Cone)",
        "ok = p.__class__ == Sphere",
        "ok = p.kind == 'sphere'",
        "ok = type(p).__name__ != 'ConvexPolyhedron'",
        "ok = type(p).__name__ in ('Box', 'ConvexPolyhedron')",
        "from ..kinds import Box as B\nok = issubclass(c, B)",
        "match p:\n    case Sphere(): pass",
    ],
)
def test_the_check_finds_kind_tests(source):
    assert kind_tests(source, kind_classes(), kind_names()), source


@pytest.mark.parametrize(
    "source",
    [
        "ok = isinstance(p, Primitive)",
        "ok = type(a) is type(b)",
        "ok = isinstance(form, AffineBall)",
        "s = Sphere((0, 0, 0), 1)",
        "ok = light.kind == 'point'",
    ],
)
def test_the_check_passes_what_is_no_kind_test(source):
    assert not kind_tests(source, kind_classes(), kind_names()), source


def test_no_kind_test_outside_the_kinds():
    classes, names = kind_classes(), kind_names()
    found = []
    for path in package_modules():
        for line, text in kind_tests(path.read_text(encoding="utf-8"), classes, names):
            found.append(f"{path.relative_to(PACKAGE.parent)}:{line}: {text}")
    assert not found, "tests for concrete kinds outside isocsg/kinds/:\n" + "\n".join(found)
