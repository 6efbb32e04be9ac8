"""Issue 22: a valid part of any aspect loads and renders. Cylinders, cones and frusta as thin as
``MIN_TRUNCUS_ASPECT`` (1e-12) of their larger extent, judged independently.

- Cylinders of aspect 1e-5 to 1e-12, discs and rods, turned at random, against the tests' ray
  caster (``tests/reference``: exact for cylinders at any aspect: no quadric term there).
- Cones and frusta against the ray caster down to 1e-6; thinner, the ray caster's lateral quadric
  (its coefficient ``((r1 - r2) / h)^2`` up to 1e24) loses the digits, so their silhouettes are
  judged against the ray caster's image of the cylinder of the larger radius and the same
  thickness (a flat frustum covers on screen what that coin covers, to the thickness).
- Volumes against closed forms (a washer, a half disc, OpenSCAD's ``minkowski`` of a 1e-5 x 3
  disc and a cube: a rounded box).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference import compare, raycast_scene  # noqa: E402
from reference.metrics import fraction_within, silhouette_iou  # noqa: E402

from isocsg import (  # noqa: E402
    Box,
    Camera,
    Cone,
    Cylinder,
    DirectionalLight,
    InvalidGeometryError,
    Material,
    PointLight,
    RenderSettings,
    Scene,
    SceneObject,
    Truncus,
    loads_openscad,
    volume,
)
from isocsg.rendering import render  # noqa: E402

MIN_IOU = 0.99
MIN_FRACTION = 0.98


def _scene(solid: object, centre: np.ndarray, extent: float, view: np.ndarray, *, far: bool = False) -> Scene:
    """A view of ``solid`` from ``1.5 extent`` along ``view``; a point light near it, or with ``far``
    a directional one (a rod's laminae are isoluminance for a light far against its length)."""
    d = view / np.linalg.norm(view)
    up = (0, 0, 1) if abs(d[2]) < 0.9 else (0, 1, 0)
    camera = Camera(tuple(centre + 1.5 * extent * d), tuple(centre), up, fov=40, width=48, height=48)
    light: PointLight | DirectionalLight = PointLight(tuple(centre + extent * np.array([0.5, -1.0, 0.7])))
    if far:
        light = DirectionalLight((0.5, -1.0, 0.7))
    return Scene(camera, (light,), (SceneObject(solid, Material()),), RenderSettings(contours=16))


def _turn(axis: np.ndarray, seed: int) -> np.ndarray:
    from scipy.spatial.transform import Rotation

    return Rotation.random(random_state=seed).as_matrix() @ axis  # type: ignore[no-any-return]


views = st.sampled_from([(0.3, 0.4, 1.0), (0.2, 1.0, 0.05), (0.1, 0.2, -1.0), (1.0, -0.5, 0.3)])


@settings(max_examples=10, deadline=None)
@given(log_aspect=st.floats(-12, -5), rod=st.booleans(), seed=st.integers(0, 1000), view=views,
       scale=st.sampled_from([1.0, 1e3]))
def test_thin_cylinders_match_the_ray_caster(log_aspect: float, rod: bool, seed: int, view: tuple[float, ...],
                                             scale: float) -> None:
    aspect = max(10.0**log_aspect, 2e-9 / scale)  # the thin extent above the length floor (1e-9 here)
    radius, height = (scale * aspect, scale) if rod else (scale, scale * aspect)
    axis = _turn(np.array([0.0, 0.0, height]), seed)
    centre = np.array([0.1, -0.2, 0.3])
    solid = Cylinder(centre, axis, radius)
    # a rod is seen from where its radius shows: 20 radii away along the view (across its axis)
    extent = 2 * max(radius, height) if not rod else 20 * radius
    target = centre if not rod else centre + 0.2 * axis
    scene = _scene(solid, target, extent, np.cross(axis, np.cross(np.array(view), axis)) if rod else np.array(view), far=rod)
    image, ref = render(scene).image, raycast_scene(scene)
    result = compare(image, ref)
    assert result.iou >= MIN_IOU, result.summary()
    assert fraction_within(image, ref, result) >= MIN_FRACTION, result.summary()
    assert volume(solid) == pytest.approx(math.pi * radius**2 * height, rel=1e-12)


@settings(max_examples=8, deadline=None)
@given(log_aspect=st.floats(-9, -5), cone=st.booleans(), seed=st.integers(0, 1000), view=views)
def test_thin_cones_and_frusta_cover_their_coin(log_aspect: float, cone: bool, seed: int,
                                                view: tuple[float, ...]) -> None:
    aspect = max(10.0**log_aspect, 2e-9)
    axis = _turn(np.array([0.0, 0.0, aspect]), seed)
    centre = np.array([0.3, 0.1, -0.2])
    solid = Cone(centre, axis, 1.0) if cone else Truncus(centre, axis, 1.0, 0.6)
    scene = _scene(solid, centre, 2.0, np.array(view))
    image = render(scene).image
    if aspect >= 1e-6:  # the ray caster's quadric still holds its digits
        ref = raycast_scene(scene)
        result = compare(image, ref)
        assert result.iou >= MIN_IOU, result.summary()
        assert fraction_within(image, ref, result) >= MIN_FRACTION, result.summary()
    coin = _scene(Cylinder(centre, axis, 1.0), centre, 2.0, np.array(view))
    assert silhouette_iou(image, raycast_scene(coin).image) >= MIN_IOU
    want = math.pi * aspect / 3 * (1.0 if cone else 1 + 0.6 + 0.36)
    assert volume(solid) == pytest.approx(want, rel=1e-12)


@pytest.mark.parametrize("aspect", [1e-6, 1e-9])
def test_thin_discs_cut_keep_exact_volumes(aspect: float) -> None:
    disc = Cylinder((0, 0, 0), (0, 0, aspect), 1.0)
    washer = disc - Cylinder((0, 0, 0), (0, 0, 1), 0.5)
    assert volume(washer) == pytest.approx(math.pi * 0.75 * aspect, rel=1e-9)
    half = disc - Box((1, 0, 0), (2, 3, 1))
    assert volume(half) == pytest.approx(math.pi / 2 * aspect, rel=1e-9)


def test_openscad_thin_cylinders_load() -> None:
    """A real-world model's ``minkowski() { cylinder(h = 1e-05, r = 3); cube(...); }`` (a rounded
    box: the cube's footprint grown by the disc, over its height plus 1e-5), and a 0.001 x 128 rod."""
    text = ("minkowski() { cylinder(h = 1e-05, r1 = 3, r2 = 3, center = false); "
            "cube(size = [22.89, 22.89, 26.9], center = false); }")
    a, r, c = 22.89, 3.0, 26.9
    # isocsg.volume of a union of round pieces is within 1e-7 (9e-8 here, the same with h = 1)
    assert volume(loads_openscad(text)) == pytest.approx((a * a + 4 * a * r + math.pi * r * r) * (c + 1e-5), rel=1e-6)
    rod = loads_openscad("cylinder(h = 128, r1 = 0.001, r2 = 0.001, center = false);")
    assert volume(rod) == pytest.approx(math.pi * 1e-6 * 128, rel=1e-12)
    coin = loads_openscad("cylinder(h = 0.001, r1 = 64, r2 = 64, center = false);")
    assert volume(coin) == pytest.approx(math.pi * 64**2 * 1e-3, rel=1e-12)


def test_thinner_than_the_bound_is_refused_naming_the_field() -> None:
    with pytest.raises(InvalidGeometryError, match=r"Cylinder\.axis must be at least 1e-12 x the larger radius"):
        Cylinder((0, 0, 0), (0, 0, 1e-9), 1e4)
    with pytest.raises(InvalidGeometryError, match=r"Cone\.radius must be 0 or >= 1e-05 \(the smallest length"):
        Cone((0, 0, 0), (0, 0, 1e4), 1e-9)  # a needle meets the length floor at its ends first
