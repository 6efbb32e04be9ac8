"""Regenerate the ``.csg`` exports and ``stl_volumes.json`` of these models with the ``openscad`` program.

Run from anywhere: ``python tests/data/openscad/projection22/regenerate.py`` (needs ``openscad`` 2021.01
and trimesh). Each model is exported with ``openscad -D '$fn=96' -o model.csg model.scad`` and
``openscad --render -D '$fn=96' -o model.stl model.scad`` (an explicit ``$fn`` in a model wins).
"""

from __future__ import annotations

import hashlib
import json
import subprocess
import tempfile
from pathlib import Path

import trimesh

DIR = Path(__file__).resolve().parent
FN = ["-D", "$fn=96"]


def main() -> None:
    models = {}
    for scad in sorted(DIR.glob("*.scad")):
        subprocess.run(["openscad", *FN, "-o", str(scad.with_suffix(".csg")), str(scad)], check=True,
                       capture_output=True)
        with tempfile.TemporaryDirectory() as tmp:
            stl = Path(tmp) / "m.stl"
            subprocess.run(["openscad", "--render", *FN, "-o", str(stl), str(scad)], check=True, capture_output=True)
            volume = float(trimesh.load(stl).volume)
        models[scad.stem] = {"fn": 96, "sha256": hashlib.sha256(scad.read_bytes()).hexdigest(), "volume": volume}
    about = ("volumes of OpenSCAD 2021.01's STL exports of these models, "
             "`openscad --render -D '$fn=96' -o model.stl model.scad` (an explicit $fn in a model wins), "
             "read with trimesh; sha256 of each .scad text")
    (DIR / "stl_volumes.json").write_text(json.dumps({"about": about, "models": models}, indent=1, sort_keys=True) + "\n")


if __name__ == "__main__":
    main()
