"""The camera against geometric facts of the pinhole model in the conventions."""

import math

import numpy as np
import pytest

import isocsg as ic


def test_frame_is_right_handed_orthonormal_with_up_projected():
    cam = ic.Camera((3, -4, 2), (0, 0, 0.5), up=(0, 0, 1))
    f, r, u = cam.frame
    assert np.allclose([f @ f, r @ r, u @ u], 1)
    assert np.allclose([f @ r, f @ u, r @ u], 0, atol=1e-12)
    assert np.allclose(np.cross(r, u), -f)  # r x u = -f for r = f x up, u = r x f
    assert u[2] > 0 and abs(r[2]) < 1e-12


def test_vertical_and_horizontal_extent_match_fov_and_aspect():
    w, h, fov = 64, 32, 50.0
    cam = ic.Camera((0, -5, 0), (0, 0, 0), fov=fov, width=w, height=h)
    d = cam.ray_directions()
    f, r, u = cam.frame
    # The edge of the image (not the pixel centre) is at tan(fov/2): the top row centre is half a pixel lower.
    top = d[0, w // 2 - 1 : w // 2 + 1].mean(axis=0)
    angle_top = math.atan2(top @ u, top @ f)
    assert math.tan(angle_top) == pytest.approx(math.tan(math.radians(fov / 2)) * (1 - 1 / h), rel=1e-3)
    right = d[h // 2 - 1 : h // 2 + 1, -1].mean(axis=0)
    assert right @ r / (right @ f) == pytest.approx(math.tan(math.radians(fov / 2)) * (w / h) * (1 - 1 / w), rel=1e-3)
    assert (d[0, 0] @ u) > 0 and (d[0, 0] @ r) < 0  # row 0 is the top, column 0 the left


def test_project_inverts_ray_directions_at_pixel_centres():
    cam = ic.Camera((1, -6, 2), (0, 0.3, 0), fov=35, width=40, height=30)
    d = cam.ray_directions()
    pts = cam.eye_array + 3.7 * d.reshape(-1, 3)
    col, row, depth = cam.project(pts)
    jj, ii = np.meshgrid(np.arange(40) + 0.5, np.arange(30) + 0.5)
    assert np.allclose(col, jj.ravel()) and np.allclose(row, ii.ravel())
    assert np.all(depth > 0)


def test_orthographic_rays_are_parallel_and_span_height_m():
    cam = ic.Camera((0, -5, 0), (0, 0, 0), width=10, height=10, orthographic=True, height_m=2.0)
    o = cam.ray_origins()
    assert np.allclose(cam.ray_directions(), [0, 1, 0])
    assert o[0, 5, 2] - o[-1, 5, 2] == pytest.approx(2.0 * 9 / 10)


@pytest.mark.parametrize(
    "kwargs, field",
    [
        (dict(eye=(0, 0, 0), target=(0, 0, 0)), "camera.target"),
        (dict(eye=(0, 0, 5), target=(0, 0, 0)), "camera.up"),
        (dict(eye=(0, -5, 0), target=(0, 0, 0), fov=0), "camera.fov"),
        (dict(eye=(0, -5, 0), target=(0, 0, 0), fov=200), "camera.fov"),
        (dict(eye=(0, -5, 0), target=(0, 0, 0), width=10**6), "camera.width"),
        (dict(eye=(float("nan"), -5, 0), target=(0, 0, 0)), "camera.eye"),
    ],
    ids=["eye-equals-target", "up-parallel", "fov-zero", "fov-too-large", "absurd-width", "nan-eye"],
)
def test_bad_cameras_raise_parameter_errors_naming_the_field(kwargs, field):
    with pytest.raises(ic.InvalidParameterError, match=field.replace(".", r"\.")):
        ic.Camera(**kwargs)
