"""The exact shading formula against hand-computed values."""

import math

import numpy as np
import pytest

import isocsg as ic


def test_lambert_cosine_and_ambient():
    m = ic.Material(ambient=0.1, kd=0.8)
    pts = np.zeros((3, 3))
    normals = [[0, 0, 1], [math.sin(0.5), 0, math.cos(0.5)], [0, 0, -1]]
    out = ic.shade(pts, normals, (0, -5, 0), [ic.DirectionalLight((0, 0, 1))], m)
    assert out == pytest.approx([0.9, 0.1 + 0.8 * math.cos(0.5), 0.1])


def test_point_light_direction_depends_on_the_point_and_no_attenuation():
    out = ic.shade([[0, 0, 0], [3, 0, 0]], [[0, 0, 1], [0, 0, 1]], (0, -5, 5), [ic.PointLight((0, 0, 4), intensity=0.5)])
    assert out == pytest.approx([0.1 + 0.5 * 0.8, 0.1 + 0.5 * 0.8 * 4 / 5])


def test_phong_highlight_peaks_at_the_mirror_direction():
    m = ic.Material(ambient=0.0, kd=0.0, ks=1.0, shininess=10)
    # light and eye symmetric about the normal: rf . v = 1
    assert ic.shade([[0, 0, 0]], [[0, 0, 1]], (1, 0, 1), [ic.PointLight((-1, 0, 1))], m)[0] == pytest.approx(1.0)
    # eye rotated by 30 degrees off the mirror direction: cos(30)^10
    e = (math.sin(math.radians(75)), 0, math.cos(math.radians(75)))
    val = ic.shade([[0, 0, 0]], [[0, 0, 1]], e, [ic.DirectionalLight((-1, 0, 1))], m)[0]
    assert val == pytest.approx(math.cos(math.radians(30)) ** 10)
    # no specular where the light is behind the surface
    assert ic.shade([[0, 0, 0]], [[0, 0, 1]], (0, 0, 1), [ic.DirectionalLight((0, 0, -1))], m)[0] == 0.0


def test_lights_add_up():
    lights = [ic.DirectionalLight((0, 0, 1)), ic.DirectionalLight((1, 0, 0))]
    n = [[0, 0, 1]]
    assert ic.shade([[0, 0, 0]], n, (0, -1, 0), lights)[0] == pytest.approx(0.9)
    n2 = [[1 / math.sqrt(2), 0, 1 / math.sqrt(2)]]
    assert ic.shade([[0, 0, 0]], n2, (0, -1, 0), lights)[0] == pytest.approx(0.1 + 2 * 0.8 / math.sqrt(2))


def test_shape_mismatch_is_reported():
    with pytest.raises(ic.InvalidParameterError, match="normals"):
        ic.shade(np.zeros((2, 3)), np.ones((3, 3)), (0, 0, 1), [])
