"""The pyvista view, rendered off screen."""

from __future__ import annotations

import sys

import numpy as np
import pytest

from isocsg import Camera, MissingDependencyError, PointLight, Sphere, shade
from isocsg.laminae.model import BandMesh
from isocsg.view import show

pv = pytest.importorskip("pyvista")


def mesh_bands(primitive, lights, material, contours, *, eye):
    """Faceted stand-in for the laminae: the exact shading at each face centre."""
    mesh = primitive.to_trimesh(32)
    v = np.asarray(mesh.vertices, dtype=float)
    t = np.asarray(mesh.faces, dtype=np.int32)
    n = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
    c = v[t].mean(axis=1)
    vals = shade(c, n, eye, lights, material)
    return BandMesh(v, t, vals, vals, np.zeros(len(t), np.int32))


def test_off_screen_view_shows_graded_bands(tmp_path):
    from PIL import Image

    out = tmp_path / "view.png"
    cam = Camera((0, -6, 2), (0, 0, 0), fov=30)
    img = show(
        [Sphere((0, 0, 0), 1), Sphere((1.5, 0.5, 0), 0.6) - Sphere((1.9, 0.0, 0.3), 0.4)],
        [PointLight((4, -5, 6))],
        contours=16,
        camera=cam,
        off_screen=True,
        screenshot=out,
        window_size=(240, 180),
        build_laminae=mesh_bands,
    )
    saved = np.asarray(Image.open(out).convert("RGB"))
    assert saved.shape == (180, 240, 3)
    assert img.shape[:2] == (180, 240)
    background = saved[0, 0]
    fg = np.any(saved != background, axis=-1)
    assert 0.05 < fg.mean() < 0.9  # the objects fill part of the frame
    grey = saved[fg].astype(int)
    # grey-level bands: R = G = B, and many distinct levels from dark to bright
    assert np.abs(grey[:, 0] - grey[:, 1]).max() <= 2
    assert len(np.unique(grey[:, 0])) > 10
    assert grey[:, 0].max() - grey[:, 0].min() > 100


def test_missing_pyvista_names_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "pyvista", None)
    with pytest.raises(MissingDependencyError, match=r"isocsg\[view\]"):
        show(Sphere((0, 0, 0), 1), [PointLight((0, 0, 5))], off_screen=True, build_laminae=mesh_bands)
