"""Rich display in Jupyter: the PNG shows the object where the analytic ray caster sees it."""

from __future__ import annotations

import io
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from isocsg import Box, Camera, Cylinder, Material, PointLight, RenderSettings, Scene, Sphere, Truncus, render
from isocsg.interop.notebook import DISPLAY_SIZE, default_light, framing_camera
from isocsg.rendering.image import to_uint8

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference import raycast  # noqa: E402
from reference.metrics import neighbourhood_all  # noqa: E402

SOLIDS = [
    Sphere((1.0, 2.0, 3.0), 0.5),
    Box((0, 0, 0), (2, 2, 0.4)) - Cylinder((0, 0, 0), (0, 0, 1), 0.5),
    Truncus((0, 0, 0), (0, 0, 3), 0.2, 0.8) | Sphere((0, 0, -1.5), 0.9),
]


def _decode(data: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(data)))


@pytest.mark.parametrize("solid", SOLIDS, ids=["sphere", "plate-minus-cylinder", "frustum-union-sphere"])
def test_solid_png_shows_the_object_where_it_is(solid) -> None:
    bundle = solid._repr_mimebundle_()
    assert bundle["text/plain"] == repr(solid)
    img = _decode(bundle["image/png"])
    assert img.shape == (DISPLAY_SIZE[1], DISPLAY_SIZE[0])
    b = solid.bounds
    ref = raycast(framing_camera(b), [(solid, Material())], [default_light(b)])
    mask = ref.mask
    # framed: the object is whole inside the picture, and fills a good part of it
    assert not (mask[0].any() or mask[-1].any() or mask[:, 0].any() or mask[:, -1].any())
    assert mask.mean() > 0.05
    inside, outside = neighbourhood_all(mask), neighbourhood_all(~mask)
    assert (img[inside] > 0).all(), "object pixels are drawn"
    assert (img[outside] == 0).all(), "background pixels stay background"
    # the grey levels are the shading (isoluminance bands at 24 contours)
    assert np.abs(img[inside] / 255.0 - ref.image[inside]).mean() < 0.03


def test_scene_bundle_has_png_and_svg_at_display_size() -> None:
    cam = Camera((3, -4, 3), (0, 0, 0), width=640, height=400)
    # 16 contours: the SVG stays under SVG_MAX_CHARS
    scene = Scene(cam, [PointLight((2, -3, 4))], [Sphere((0, 0, 0), 1), Box((2.5, 0, 0), (1, 1, 1))], RenderSettings(16))
    bundle = scene._repr_mimebundle_()
    img = _decode(bundle["image/png"])
    assert img.shape == (200, 320)  # 640 x 400 scaled to fit 320 x 240, aspect kept
    svg = ET.fromstring(bundle["image/svg+xml"])
    assert svg.tag.endswith("svg") and len(list(svg.iter("{http://www.w3.org/2000/svg}polygon"))) > 100
    assert _decode(scene._repr_png_()).shape == (200, 320)
    # a CSG scene has no vector image
    csg = Scene(cam, [PointLight((2, -3, 4))], [SOLIDS[1]])
    assert "image/svg+xml" not in csg._repr_mimebundle_()
    assert "image/svg+xml" not in scene._repr_mimebundle_(exclude={"image/svg+xml"})


def test_render_result_png_is_its_image() -> None:
    cam = Camera((0, -5, 1), (0, 0, 0), width=40, height=30)
    result = render(Scene(cam, [PointLight((2, -3, 4))], [Sphere((0, 0, 0), 1)]))
    np.testing.assert_array_equal(_decode(result._repr_png_()), to_uint8(result.image))


def test_halftone_result_png_is_its_display_image() -> None:
    from isocsg.shadows import AreaLight
    from isocsg.shadows.halftone import render_halftone

    lamp = AreaLight([(-0.5, -0.5, 3), (-0.5, 0.5, 3), (0.5, 0.5, 3), (0.5, -0.5, 3)], radiance=1.0)
    scene = Scene(Camera((0, -5, 3), (0, 0, 0), width=24, height=16), [lamp],
                  [Box((0, 0, -0.05), (4, 4, 0.1)), Box((0, 0, 0.5), (0.5, 0.5, 1))], RenderSettings(mode="halftone"))
    result = render_halftone(scene)
    np.testing.assert_array_equal(_decode(result._repr_png_()), to_uint8(result.display))
