"""The pyvista view and conversions, rendered off screen and judged by their pixels."""

from __future__ import annotations

import sys

import numpy as np
import pytest

from isocsg import Box, Camera, Cylinder, MissingDependencyError, PointLight, Sphere, shade
from isocsg.laminae import build_laminae
from isocsg.laminae.model import BandMesh
from isocsg.view import BACKGROUND, show

pv = pytest.importorskip("pyvista")

PLATE = Box((0, 0, 0), (2, 2, 0.4)) - Cylinder((0, 0, 0), (0, 0, 1), 0.5)
LIGHT = PointLight((1.0, -1.0, 5.0))


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
    plotter = show(
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
    img = plotter.screenshot()
    plotter.close()
    assert img.shape[:2] == (180, 240)
    background = saved[0, 0]
    assert background.tolist() == list(BACKGROUND)
    fg = np.any(saved != background, axis=-1)
    assert 0.05 < fg.mean() < 0.9  # the objects fill part of the frame
    grey = saved[fg].astype(int)
    # grey-level bands: R = G = B, and many distinct levels from dark to bright
    assert np.abs(grey[:, 0] - grey[:, 1]).max() <= 2
    assert len(np.unique(grey[:, 0])) > 10
    assert grey[:, 0].max() - grey[:, 0].min() > 100


def _top_view(plotter_or_none=None, **kw):
    cam = Camera((0, 0, 6), (0, 0, 0), up=(0, 1, 0), fov=30, width=160, height=160)
    return show(PLATE, [LIGHT], contours=8, camera=cam, window_size=(160, 160), plotter=plotter_or_none, **kw), cam


def test_subtracted_hole_is_background_not_a_peg():
    plotter, cam = _top_view(off_screen=True)
    img = plotter.screenshot()
    plotter.close()
    # The analytic picture from above: the hole (r = 0.5) shows the background,
    # the plate around it (|x|, |y| <= 1) is lit, the corners of the frame are background.
    h, w = img.shape[:2]
    t = np.tan(np.radians(cam.fov) / 2) * 6.0  # half-width of the view at the plate's distance (z ~ 6)
    def pixel(x, y):
        return img[int(round((1 - (y / t + 1) / 2) * h - 0.5)), int(round((x / t + 1) / 2 * w - 0.5))]
    bg = np.array(BACKGROUND)
    for x, y in [(0, 0), (0.3, 0), (-0.2, 0.25), (0, -0.35)]:  # inside the hole
        assert pixel(x, y).tolist() == bg.tolist(), (x, y)
    # The top of the plate (z = 0.2) shows its band value as grey.
    expect = shade([[0.75, 0.75, 0.2]], [[0, 0, 1]], cam.eye, [LIGHT])[0]
    for x, y in [(0.75, 0.75), (-0.8, 0.6), (0.7, -0.8)]:
        p = pixel(x, y).astype(int)
        assert p[0] == p[1] == p[2] and p[0] > 60 and abs(p[0] / 255 - expect) < 0.12, (x, y, p)
    assert pixel(1.3, 1.3).tolist() == bg.tolist()


def test_show_adds_to_a_given_plotter_and_returns_it():
    own = pv.Plotter(off_screen=True, window_size=[160, 160])
    own.set_background("white")
    plotter, _ = _top_view(own)
    assert plotter is own and len(own.renderer.actors) == 1
    img = own.screenshot()
    own.close()
    assert img[80, 80].tolist() == [255, 255, 255]  # the hole shows the caller's background
    assert img[40, 80].tolist() != [255, 255, 255]  # the plate at y = 0.8


def test_band_mesh_cell_scalars_are_the_band_values():
    from isocsg.interop.pyvista import to_pyvista

    bands = build_laminae(Sphere((0, 0, 0), 1), (LIGHT,), None, 12).bands
    mesh = to_pyvista(bands)
    assert mesh.n_cells == len(bands.triangles)
    np.testing.assert_array_equal(mesh.cell_data["intensity"], bands.value_out)
    np.testing.assert_array_equal(mesh.points, bands.vertices)
    np.testing.assert_array_equal(mesh.regular_faces, bands.triangles)


def test_csg_surface_has_the_hole():
    from isocsg.interop.pyvista import to_pyvista

    mesh = to_pyvista(PLATE, lights=[LIGHT], contours=8)
    # manifold3d's volume of the Boolean on fine meshes is the judge.
    judge = PLATE.to_manifold(256).volume()
    assert mesh.is_manifold and abs(mesh.volume - judge) < 2e-3 * judge
    assert abs(mesh.volume - (2 * 2 * 0.4 - np.pi * 0.25 * 0.4)) < 5e-3
    assert set(mesh.cell_data.keys()) >= {"intensity"}


def test_shadow_volumes_regions_and_lux_grid():
    from isocsg.interop.pyvista import to_pyvista
    from isocsg.shadows import AreaLight, illuminance, shadow_state
    from isocsg.shadows.luxmap import LuxGrid, illuminance_map
    from isocsg.shadows.regions import face_shadow_regions
    from isocsg.shadows.volumes import shadow_volumes

    lamp = AreaLight([(-0.5, -0.5, 3), (-0.5, 0.5, 3), (0.5, 0.5, 3), (0.5, -0.5, 3)], radiance=4.0)
    blocker = Box((0, 0, 1), (0.4, 0.4, 0.4))
    sv = shadow_volumes(lamp, blocker)
    block = to_pyvista(sv, bounds=[[-3, -3, -0.5], [3, 3, 3]])
    assert set(block.keys()) == {"penumbra", "umbra"}
    assert block["umbra"].volume < block["penumbra"].volume
    # regions on the floor: each cell's centre has the exact state of its cell
    floor = [(-2, -2, 0), (2, -2, 0), (2, 2, 0), (-2, 2, 0)]
    mesh = to_pyvista(face_shadow_regions(floor, lamp, [blocker]))
    assert abs(mesh.area - 16.0) < 1e-9
    centres = mesh.cell_centers().points
    np.testing.assert_array_equal(mesh.cell_data["state"], shadow_state(centres, (0, 0, 1), [lamp], [blocker]))
    assert set(np.unique(mesh.cell_data["state"]).tolist()) == {0, 1, 2}
    # lux grid: the node values are the illuminance at the nodes, in lux
    m = illuminance_map(LuxGrid.from_bounds(-2, -2, 2, 2, 0, 7, 5), lamp, [blocker])
    sg = to_pyvista(m)
    assert sg.dimensions == (7, 5, 1)
    np.testing.assert_allclose(sg.point_data["illuminance_lx"], illuminance(sg.points, (0, 0, 1), [lamp], [blocker]), atol=1e-12)


def test_conversion_errors():
    from isocsg import InvalidParameterError
    from isocsg.interop.pyvista import to_pyvista
    from isocsg.shadows import AreaLight
    from isocsg.shadows.volumes import shadow_volumes

    with pytest.raises(InvalidParameterError, match="unsupported object of type str"):
        to_pyvista("plate")
    lamp = AreaLight([(-0.5, -0.5, 3), (-0.5, 0.5, 3), (0.5, 0.5, 3), (0.5, -0.5, 3)])
    with pytest.raises(InvalidParameterError, match="bounds must be given"):
        to_pyvista(shadow_volumes(lamp, Box((0, 0, 1), (0.4, 0.4, 0.4))).umbra)


def test_missing_pyvista_names_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "pyvista", None)
    with pytest.raises(MissingDependencyError, match=r"isocsg\[view\]"):
        show(Sphere((0, 0, 0), 1), [PointLight((0, 0, 5))], off_screen=True, build_laminae=mesh_bands)
