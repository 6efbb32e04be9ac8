"""The public API: every exported name resolves, names load on first use, no function hides a module.

Imports are checked in fresh processes (``sys.modules`` of this one holds what other tests loaded).
"""

from __future__ import annotations

import importlib
import pkgutil
import subprocess
import sys
import types

import pytest

import isocsg

PUBLIC_PACKAGES = ["isocsg", "isocsg.shadows", "isocsg.interop"]


def _modules_after(code: str) -> set[str]:
    """The modules a fresh interpreter holds after running ``code``."""
    probe = f"{code}\nimport sys\nprint('\\n'.join(sorted(sys.modules)))"
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=300, check=True)
    return set(done.stdout.split())


@pytest.mark.parametrize("package", PUBLIC_PACKAGES)
def test_all_lists_exactly_the_lazy_table(package: str) -> None:
    mod = importlib.import_module(package)
    assert set(mod.__all__) - {"__version__"} == set(mod._EXPORTS)
    assert len(mod.__all__) == len(set(mod.__all__))


@pytest.mark.parametrize("package", PUBLIC_PACKAGES)
def test_every_exported_name_resolves_to_its_module(package: str) -> None:
    mod = importlib.import_module(package)
    for name in mod.__all__:
        assert getattr(mod, name) is not None, name
    for name, where in mod._EXPORTS.items():
        source = importlib.import_module(where, package)
        assert getattr(mod, name) is getattr(source, name), name
    assert set(mod.__all__) <= set(dir(mod))


def test_unknown_name_is_an_attribute_error() -> None:
    with pytest.raises(AttributeError, match="module 'isocsg' has no attribute 'no_such_name'"):
        isocsg.no_such_name  # noqa: B018


def test_import_isocsg_loads_no_heavy_dependency() -> None:
    loaded = _modules_after("import isocsg")
    assert not {"numpy", "numba", "shapely", "scipy", "PIL", "isocsg.rendering", "isocsg.csg"} & loaded


def test_a_name_loads_only_its_own_modules() -> None:
    loaded = _modules_after("from isocsg.shadows import AreaLight")
    assert "isocsg.lighting.area" in loaded
    assert not {"numba", "isocsg.shadows.direct", "isocsg.shadows.halftone", "isocsg.rendering"} & loaded


def test_command_line_help_imports_no_sub_command() -> None:
    loaded = _modules_after("from isocsg.cli import main\ntry:\n    main(['--help'])\nexcept SystemExit:\n    pass")
    assert not {"numpy", "numba", "isocsg.cli.render", "isocsg.cli.illuminance", "isocsg.cli.demo"} & loaded


@pytest.mark.parametrize("command", ["render", "demo", "warmup"])
def test_a_sub_command_imports_only_its_module(command: str) -> None:
    code = f"from isocsg.cli import main\ntry:\n    main([{command!r}, '--help'])\nexcept SystemExit:\n    pass"
    loaded = _modules_after(code)
    assert f"isocsg.cli.{command}" in loaded
    others = {f"isocsg.cli.{c}" for c in ("render", "demo", "warmup", "illuminance")} - {f"isocsg.cli.{command}"}
    assert not (others | {"numpy", "numba", "isocsg.shadows.halftone"}) & loaded, "its help loads nothing heavy"


def test_render_stays_the_function_when_the_renderer_package_loads_first() -> None:
    code = "import isocsg.rendering.image, isocsg\nprint(callable(isocsg.render) and not isinstance(isocsg.render, type(isocsg)))"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300, check=True)
    assert done.stdout.strip() == "True"


def test_no_function_hides_a_module_of_the_same_name() -> None:
    """``isocsg.render`` and ``isocsg.shadows.illuminance`` are functions; no module of the same name
    sits beside them (the renderer's package is ``isocsg.rendering``, the direct light's module
    ``isocsg.shadows.direct``)."""
    allowed: set[tuple[str, str]] = set()
    for package in PUBLIC_PACKAGES:
        mod = importlib.import_module(package)
        submodules = {m.name for m in pkgutil.iter_modules(mod.__path__)}
        for name in mod.__all__:
            if name in submodules and (package, name) not in allowed:
                assert isinstance(getattr(mod, name), types.ModuleType), f"{package}.{name} hides a module"
