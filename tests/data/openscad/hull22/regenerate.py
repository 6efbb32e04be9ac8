"""Regenerate this directory's ``.csg`` exports and ``stl_volumes.json`` with the ``openscad`` program.

Run from anywhere: ``python tests/data/openscad/hull22/regenerate.py [model ...]`` (needs ``openscad``
and trimesh); with model names, only those are redone.
The ``.csg`` is ``openscad -o model.csg model.scad``; the volume is that of
``openscad -D '$fn=96' -o model.stl model.scad``, read with trimesh.
"""

from __future__ import annotations

import hashlib
import json
import subprocess
import sys
import tempfile
from pathlib import Path

import trimesh

HERE = Path(__file__).resolve().parent
FN = 96


def main(names: list[str]) -> None:
    table = HERE / "stl_volumes.json"
    models = json.loads(table.read_text())["models"] if names and table.is_file() else {}
    for scad in sorted(HERE.glob("*.scad")):
        if names and scad.stem not in names:
            continue
        subprocess.run(["openscad", "-o", str(scad.with_suffix(".csg")), str(scad)], check=True, capture_output=True)
        with tempfile.TemporaryDirectory() as tmp:
            stl = Path(tmp) / "m.stl"
            subprocess.run(["openscad", "-D", f"$fn={FN}", "-o", str(stl), str(scad)], check=True, capture_output=True)
            mesh = trimesh.load_mesh(stl)
        models[scad.stem] = {"fn": FN, "sha256": hashlib.sha256(scad.read_bytes()).hexdigest(), "volume": float(mesh.volume)}
    about = (f"volumes of OpenSCAD's STL exports of these models, `openscad -D '$fn={FN}' -o model.stl model.scad`, "
             "read with trimesh; sha256 of each .scad text")
    table.write_text(json.dumps({"about": about, "models": models}, indent=1, sort_keys=True) + "\n")


if __name__ == "__main__":
    main(sys.argv[1:])
