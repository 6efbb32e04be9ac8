"""Every ```python block of README.md runs as written: in order, as one program, in an empty folder.

A block right after ``<!-- readme-test: requires NAME -->`` is skipped where NAME (the ``openscad``
program or a Python package) is missing; pyvista draws off screen.
"""

from __future__ import annotations

import importlib.util
import re
import shutil
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[1] / "README.md"
_BLOCK = re.compile(r"(?:<!-- readme-test: requires (?P<needs>[\w.-]+) -->\n)?```python\n(?P<code>.*?)```", re.DOTALL)


def readme_blocks(text: str) -> list[tuple[int, str | None, str]]:
    """``(line, requirement, code)`` of each python block."""
    return [(text.count("\n", 0, m.start("code")) + 1, m["needs"], m["code"]) for m in _BLOCK.finditer(text)]


def _available(name: str) -> bool:
    if name == "openscad":
        return shutil.which("openscad") is not None
    return importlib.util.find_spec(name) is not None


def test_blocks_are_found() -> None:
    blocks = readme_blocks(README.read_text(encoding="utf-8"))
    assert len(blocks) >= 10
    assert {needs for _, needs, _ in blocks} <= {None, "openscad", "pyvista", "matplotlib"}


def test_readme_code_runs(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    if _available("pyvista"):
        import pyvista

        monkeypatch.setattr(pyvista, "OFF_SCREEN", True)
    namespace: dict[str, object] = {"__name__": "readme"}
    skipped = []
    for line, needs, code in readme_blocks(README.read_text(encoding="utf-8")):
        if needs is not None and not _available(needs):
            skipped.append(needs)
            continue
        try:
            exec(compile(code, f"README.md:{line}", "exec"), namespace)  # noqa: S102
        except Exception as exc:  # noqa: BLE001 - any error of a block fails the test, naming its line
            pytest.fail(f"the README block at line {line} raised {type(exc).__name__}: {exc}")
    assert Path("part.png").is_file() and Path("scene.json").is_file()
    if skipped:
        pytest.skip(f"blocks needing {', '.join(sorted(set(skipped)))} were skipped")
