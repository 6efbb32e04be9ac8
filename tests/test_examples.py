"""Every ``examples/*.py`` runs: ``run(output_dir)`` writes images and returns their paths."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType

import numpy as np
import pytest
from PIL import Image

EXAMPLES_DIR = Path(__file__).resolve().parent.parent / "examples"
EXAMPLES = sorted(p for p in EXAMPLES_DIR.glob("*.py") if not p.name.startswith("_"))


def _load(path: Path) -> ModuleType:
    name = f"isocsg_example_{path.stem}"
    spec = importlib.util.spec_from_file_location(name, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    try:
        spec.loader.exec_module(module)
    finally:
        sys.modules.pop(name, None)
    return module


def test_examples_exist() -> None:
    assert any(p.name.startswith("iso_") for p in EXAMPLES)


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_example_runs_and_returns_what_it_wrote(path: Path, tmp_path: Path) -> None:
    module = _load(path)
    assert callable(getattr(module, "run", None)), f"{path.name} must define run(output_dir=None)"
    written = [Path(p) for p in module.run(tmp_path)]
    assert written, f"{path.name}: run() returned no paths"
    # run() writes into the folder it is given and returns exactly what it wrote.
    on_disk = {p.resolve() for p in tmp_path.rglob("*") if p.is_file()}
    assert {p.resolve() for p in written} == on_disk
    for p in written:
        assert p.stat().st_size > 0, p
        if p.suffix == ".png":
            with Image.open(p) as im:
                pixels = np.asarray(im.convert("L"))
            # A drawn picture, not a blank canvas.
            assert pixels.size > 0 and pixels.max() > pixels.min(), f"{p.name} is uniform"
