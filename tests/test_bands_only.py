"""The bands-only build (:func:`isocsg.laminae.build_bands`, what the renderer uses) against the full build.

The renderer fills only the band mesh; ``build_bands`` skips the paper's
laminae and the family descriptions. Its bands must be the very same arrays
(bit for bit) as those of :func:`isocsg.laminae.build_laminae`, for every
primitive kind and light configuration, each built from an empty cache so
that neither is a copy of the other.
"""

from __future__ import annotations

import numpy as np
import pytest

from isocsg import Box, Cone, ConvexPolyhedron, Cylinder, DirectionalLight, Material, PointLight, Sphere, Truncus
from isocsg.laminae import build_bands, build_laminae, cache_info, clear_cache

PRIMITIVES = {
    "sphere": Sphere((0.2, -0.1, 0.3), 0.8),
    "cylinder": Cylinder((0.0, 0.0, 0.0), (0.3, 0.2, 1.5), 0.4),
    "cone": Cone((0.1, 0.0, 0.0), (0.0, 0.4, 1.2), 0.5),
    "frustum": Truncus((0.0, 0.1, 0.0), (0.2, 0.0, 1.0), 0.6, 0.25),
    "disc": Cylinder((0.0, 0.0, 0.0), (0.0, 0.0, 0.05), 0.9),
    "box": Box((0.1, 0.2, -0.1), (1.0, 0.6, 0.4)),
    "polyhedron": ConvexPolyhedron([(0, 0, 0), (1.2, 0.1, 0), (0.2, 1.0, 0.1), (0.3, 0.4, 1.1), (0.9, 0.8, 0.7)]),
}
LIGHTS = {
    "point": (PointLight((3.0, -4.0, 6.0)),),
    "near-point": (PointLight((0.9, -0.6, 0.5)),),
    "directional": (DirectionalLight((0.3, -0.5, 0.8)),),
    "two-lights": (PointLight((3.0, -4.0, 6.0)), PointLight((-4.0, -2.0, 3.0), 0.4)),
    "no-light": (),
}
EYE = (2.5, -4.5, 4.0)


def _equal(a, b) -> None:
    for name in ("vertices", "triangles", "value_out", "value_in", "band"):
        x, y = getattr(a, name), getattr(b, name)
        assert x.dtype == y.dtype and x.shape == y.shape, name
        np.testing.assert_array_equal(x, y, err_msg=name)


@pytest.mark.parametrize("lights", list(LIGHTS), ids=str)
@pytest.mark.parametrize("kind", list(PRIMITIVES), ids=str)
def test_bands_only_equal_the_full_build(kind, lights):
    prim, li = PRIMITIVES[kind], LIGHTS[lights]
    clear_cache()
    full = build_laminae(prim, li, Material(), 16)
    clear_cache()
    only = build_bands(prim, li, Material(), 16)
    assert only.laminae == () and only.families == () and not only.view_dependent
    assert only.bands is not full.bands
    _equal(only.bands, full.bands)
    assert len(full.laminae) > 0


@pytest.mark.parametrize("kind", ["sphere", "cylinder", "box"], ids=str)
def test_bands_only_equal_the_full_build_with_a_specular_material(kind):
    mat = Material(ks=0.4, shininess=10)
    clear_cache()
    full = build_laminae(PRIMITIVES[kind], LIGHTS["point"], mat, 12, eye=EYE)
    clear_cache()
    only = build_bands(PRIMITIVES[kind], LIGHTS["point"], mat, 12, eye=EYE)
    assert only.view_dependent and full.view_dependent
    _equal(only.bands, full.bands)


def test_bands_only_and_full_sets_share_the_cache():
    prim, li = PRIMITIVES["cylinder"], LIGHTS["point"]
    clear_cache()
    only = build_bands(prim, li, Material(), 16)
    assert build_bands(prim, li, Material(), 16) is only
    full = build_laminae(prim, li, Material(), 16)  # reuses the bands: one band build in all
    assert full.bands is only.bands and len(full.laminae) > 0
    assert build_bands(prim, li, Material(), 16) is full  # the full set serves both from now on
    assert cache_info()["misses"] == 2 and cache_info()["size"] == 1
