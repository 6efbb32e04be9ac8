"""CSG identities as rendered images, on random trees.

A - A renders as background only (from the first view, resolved per pixel,
and from the second, through the clipped surface); A | A renders exactly as A;
A & B renders as B & A. The renderer resolves trees per pixel on the leaves' depth
intervals, so these hold pixel for pixel: coincident surfaces produce
identical depth keys (same band mesh, same projection), which are applied
together as one event.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
from hypothesis import HealthCheck, given, settings

sys.path.insert(0, str(Path(__file__).resolve().parent))

from test_csg_properties import trees  # noqa: E402

from isocsg import Camera, PointLight, RenderSettings, Scene  # noqa: E402
from isocsg.csg import leaves  # noqa: E402
from isocsg.rendering import Renderer  # noqa: E402

IMAGE_SETTINGS = settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
RENDERER = Renderer()
CAMERA = Camera((2.5, -4.0, 2.0), (0, 0, 0), width=72, height=64)
LIGHTS = (PointLight((3, -4, 5)), PointLight((-4, -1, 2), 0.5))


def image(solid) -> np.ndarray:
    return RENDERER.render(Scene(CAMERA, LIGHTS, [solid], RenderSettings(contours=12))).image


@IMAGE_SETTINGS
@given(trees)
def test_a_minus_a_renders_nothing(a):
    if len(leaves(a)) > 3:
        return
    assert np.isnan(image(a - a)).all()
    # A second view of the same object goes through its clipped surface ("auto").
    assert np.isnan(image(a - a)).all()


@IMAGE_SETTINGS
@given(trees)
def test_a_union_a_renders_as_a(a):
    if len(leaves(a)) > 3:
        return
    np.testing.assert_array_equal(image(a | a), image(a))


@IMAGE_SETTINGS
@given(trees, trees)
def test_intersection_commutes_as_images(a, b):
    if len(leaves(a)) + len(leaves(b)) > 5:
        return
    ab, ba = image(a & b), image(b & a)
    np.testing.assert_array_equal(np.isnan(ab), np.isnan(ba))
    # Where A's and B's surfaces coincide exactly the two orders may show either
    # leaf's value; random trees almost never produce such pixels.
    differ = np.isfinite(ab) & (ab != ba)
    assert differ.sum() <= max(2, int(1e-3 * ab.size)), f"{differ.sum()} pixels differ"
