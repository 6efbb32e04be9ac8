"""Writes this directory's mesh files, OpenSCAD models, their ``.csg`` exports and STL volumes.

Run from anywhere with ``python tests/data/openscad/mesh22/generate.py`` (needs trimesh, Pillow,
manifold3d and the ``openscad`` program). The meshes are built here from closed forms, not by
isocsg: an L-shaped bracket (STL), a gridded ring (OFF), a stepped block (OBJ: OpenSCAD 2021.01
imports no OBJ, so no model uses it; the tests read it alone), a notched prism (3MF), a height
field (DAT) and a colour image (PNG).
"""

from __future__ import annotations

import hashlib
import json
import subprocess
import tempfile
from pathlib import Path

import numpy as np

DIR = Path(__file__).resolve().parent


def _extruded(outline: list[tuple[float, float]], height: float) -> tuple[np.ndarray, np.ndarray]:
    """A prism over a simple counter-clockwise outline, triangulated by manifold3d."""
    import manifold3d

    m = manifold3d.Manifold.extrude(manifold3d.CrossSection([outline]), height)
    mesh = m.to_mesh()
    return np.asarray(mesh.vert_properties[:, :3], np.float64), np.asarray(mesh.tri_verts, np.int64)


def meshes() -> None:
    import trimesh

    v, f = _extruded([(0, 0), (30, 0), (30, 5), (5, 5), (5, 20), (0, 20)], 12.0)
    trimesh.Trimesh(v, f).export(DIR / "bracket.stl")
    ring = trimesh.creation.annulus(r_min=4.0, r_max=7.0, height=3.0, sections=24)
    ring.export(DIR / "ring.off")
    v, f = _extruded([(0, 0), (10, 0), (10, 3), (7, 3), (7, 6), (3, 6), (3, 3), (0, 3)], 4.0)
    trimesh.Trimesh(v, f).export(DIR / "steps.obj")
    v, f = _extruded([(0, 0), (8, 0), (8, 8), (5, 8), (4, 4), (3, 8), (0, 8)], 2.5)
    trimesh.Trimesh(v, f).export(DIR / "notch.3mf")
    x, y = np.meshgrid(np.arange(7), np.arange(5))
    h = 2.0 + np.sin(x / 2.0) + 0.5 * np.cos(y) + 0.25 * x
    lines = ["# a height field: 5 rows of 7 columns"] + [" ".join(f"{z:.4f}" for z in row) for row in h]
    (DIR / "field.dat").write_text("\n".join(lines) + "\n")
    from PIL import Image

    g = (40 + 20 * x + 15 * y).astype(np.uint8)
    rgb = np.stack([g, (g * 0.7).astype(np.uint8), (255 - g)], axis=-1).astype(np.uint8)
    rgb[0, 0] = 0  # a black pixel: z = 0, so OpenSCAD 2021.01's base (min(z_min - 1, 0)) is today's (z_min - 1)
    Image.fromarray(rgb, "RGB").save(DIR / "grey.png")


def exports() -> None:
    import trimesh

    table = {}
    for scad in sorted(DIR.glob("*.scad")):
        subprocess.run(["openscad", "-o", str(scad.with_suffix(".csg")), str(scad)], check=True,
                       capture_output=True, timeout=300)
        with tempfile.TemporaryDirectory() as tmp:
            stl = Path(tmp) / "m.stl"
            subprocess.run(["openscad", "-o", str(stl), str(scad)], check=True, capture_output=True, timeout=300)
            vol = float(trimesh.load(stl, force="mesh").volume)
        table[scad.stem] = {"volume": vol, "sha256": hashlib.sha256(scad.read_bytes()).hexdigest()}
    (DIR / "stl_volumes.json").write_text(json.dumps({"models": table}, indent=1, sort_keys=True) + "\n")


if __name__ == "__main__":
    meshes()
    exports()
