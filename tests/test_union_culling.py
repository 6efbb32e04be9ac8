"""Unions of many leaves: the depth test with occlusion culling, against the ray caster.

A union of leaves is drawn by filling its leaves' front faces with the depth
test, nearest leaves first, skipping each leaf whose bounding ball is already
hidden everywhere on screen (:func:`isocsg.rendering.union.render_union`,
:func:`isocsg.rendering.occlusion.ball_covered`). Hypothesis draws clusters of 2 to
90 leaves of every kind (so the level of detail of trees over 64 leaves is
drawn too), many of them hidden behind others, under random cameras
(perspective and orthographic, any direction) and lights. Each image is
judged by the analytic ray caster with the catalogue's bars, and must be the
same, pixel for pixel, as the image drawn with culling turned off: a culled
leaf never shows.

``ISOCSG_SEARCH_EXAMPLES=500 python -m pytest tests/test_union_culling.py``
runs a longer search than the fixed set CI draws.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference import compare, fraction_within, raycast_scene  # noqa: E402
from test_csg_properties import primitives  # noqa: E402
from test_csg_random_views import MIN_FRACTION, MIN_IOU, MIN_PIXELS, cameras, lights, materials, placed  # noqa: E402

from isocsg import Camera, PointLight, RenderSettings, Scene, SceneObject, Sphere, Union  # noqa: E402
from isocsg.rendering import Renderer, union  # noqa: E402

EXAMPLES = int(os.environ.get("ISOCSG_SEARCH_EXAMPLES", "8"))
SIZE = 96


@st.composite
def clusters(draw):
    """A union of 2 to 90 leaves, each a drawn primitive shrunk and moved within the unit ball."""
    n = draw(st.integers(2, 90))
    leaves = []
    for _ in range(n):
        scale = draw(st.floats(0.12, 0.7))
        offset = tuple(draw(st.floats(-0.9, 0.9)) for _ in range(3))
        leaves.append(placed(draw(primitives), offset, scale))
    return Union(*leaves)


def _render(scene: Scene, cull: bool, monkeypatch) -> np.ndarray:
    if not cull:
        monkeypatch.setattr(union, "ball_covered", lambda *a: False)
    try:
        return Renderer().render(scene).image
    finally:
        monkeypatch.undo()


@settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=list(HealthCheck))
@given(clusters(), cameras(), lights(), materials)
def test_random_unions_match_the_ray_caster_and_culling_never_shows(union, camera, light_list, material):
    monkeypatch = pytest.MonkeyPatch()
    scene = Scene(camera, tuple(light_list), (SceneObject(union, material),), RenderSettings(contours=64))
    ref = raycast_scene(scene)
    assume(ref.mask.sum() >= MIN_PIXELS)
    image = _render(scene, True, monkeypatch)
    result = compare(image, ref)
    assert result.iou >= MIN_IOU, result.summary()
    assert fraction_within(image, ref, result) >= MIN_FRACTION, result.summary()
    assert np.array_equal(image, _render(scene, False, monkeypatch), equal_nan=True)


def test_culling_skips_the_hidden_leaves_of_a_lattice():
    """A 5 x 5 x 5 lattice of overlapping spheres seen from a corner: only the 61 spheres on
    the three faces in view are built (the other 64 are hidden by them), and the image is the
    one drawn without culling."""
    pitch = 0.4
    c = [(i - 2) * pitch for i in range(5)]
    balls = [Sphere((x, y, z), 0.6 * pitch) for x in c for y in c for z in c]
    cam = Camera((6.0, -7.0, 5.0), (0, 0, 0), fov=30.0, width=128, height=128)
    scene = Scene(cam, (PointLight((3.0, -4.0, 6.0)),), (SceneObject(Union(*balls)),))
    built = []
    real = Renderer.front_mesh

    def counting(self, primitive, *a, **kw):
        built.append(primitive)
        return real(self, primitive, *a, **kw)

    monkeypatch = pytest.MonkeyPatch()
    monkeypatch.setattr(Renderer, "front_mesh", counting)
    culled = Renderer().render(scene).image
    assert len(set(built)) == 5 * 5 * 5 - 4 * 4 * 4
    monkeypatch.setattr(union, "ball_covered", lambda *a: False)
    assert np.array_equal(culled, Renderer().render(scene).image, equal_nan=True)
    monkeypatch.undo()

