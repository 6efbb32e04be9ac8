"""Regenerate the ``.csg`` exports and ``stl_volumes.json`` of these models with the ``openscad`` program.

Run from anywhere: ``python tests/data/openscad/extrude22/regenerate.py`` (needs ``openscad`` and trimesh).
"""

from __future__ import annotations

import hashlib
import json
import subprocess
import tempfile
from pathlib import Path

import trimesh

DIR = Path(__file__).resolve().parent


def main() -> None:
    models = {}
    for scad in sorted(DIR.glob("*.scad")):
        subprocess.run(["openscad", "-o", str(scad.with_suffix(".csg")), str(scad)], check=True, capture_output=True)
        with tempfile.TemporaryDirectory() as tmp:
            stl = Path(tmp) / "m.stl"
            subprocess.run(["openscad", "--render", "-o", str(stl), str(scad)], check=True, capture_output=True)
            volume = float(trimesh.load(stl).volume)
        models[scad.stem] = {"sha256": hashlib.sha256(scad.read_bytes()).hexdigest(), "volume": volume}
    about = "volumes of OpenSCAD 2021.01's STL exports of these models (each sets $fn = 96), read with trimesh"
    (DIR / "stl_volumes.json").write_text(json.dumps({"about": about, "models": models}, indent=1, sort_keys=True) + "\n")


if __name__ == "__main__":
    main()
