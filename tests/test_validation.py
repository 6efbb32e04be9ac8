"""Bad input: every value type rejects it with the documented error and an exact message."""

from __future__ import annotations

import math
import re
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from isocsg import (
    Box,
    Camera,
    Cone,
    ConvexPolyhedron,
    Cylinder,
    DirectionalLight,
    InvalidGeometryError,
    InvalidLightError,
    InvalidParameterError,
    IsocsgError,
    Material,
    PointLight,
    Sphere,
    Truncus,
)
from isocsg.csg import Difference, Intersection, Union
from isocsg.scene import RenderSettings, Scene, SceneObject

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference import raycast_scene  # noqa: E402

NAN, INF = math.nan, math.inf
EYE, TARGET = (0.0, -5.0, 1.0), (0.0, 0.0, 0.0)
SQUARE = [(0, 0, 3), (0, 1, 3), (1, 1, 3), (1, 0, 3)]

# (id, constructor, error type, exact message)
CASES: list[tuple[str, Callable[[], Any], type[Exception], str]] = [
    # --- primitives
    ("sphere-nan-center", lambda: Sphere((NAN, 0, 0), 1), InvalidGeometryError, "Sphere.center must be finite, got (nan, 0.0, 0.0)"),
    ("sphere-inf-center", lambda: Sphere((0, -INF, 0), 1), InvalidGeometryError, "Sphere.center must be finite, got (0.0, -inf, 0.0)"),
    ("sphere-huge-center", lambda: Sphere((1e13, 0, 0), 1), InvalidGeometryError,
     "Sphere.center must lie within +-1e+12, got (10000000000000.0, 0.0, 0.0)"),
    ("sphere-2d-center", lambda: Sphere((0, 0), 1), InvalidGeometryError, "Sphere.center must have shape (3,), got (2,)"),
    ("sphere-text-center", lambda: Sphere("abc", 1), InvalidGeometryError, "Sphere.center must be 3 numbers, got 'abc'"),
    ("sphere-inf-radius", lambda: Sphere((0, 0, 0), INF), InvalidGeometryError, "Sphere.radius must be finite, got inf"),
    ("sphere-nan-radius", lambda: Sphere((0, 0, 0), NAN), InvalidGeometryError, "Sphere.radius must be finite, got nan"),
    ("sphere-zero-radius", lambda: Sphere((0, 0, 0), 0), InvalidGeometryError, "Sphere.radius must be > 0, got 0"),
    ("sphere-negative-radius", lambda: Sphere((0, 0, 0), -2), InvalidGeometryError, "Sphere.radius must be > 0, got -2"),
    ("sphere-bool-radius", lambda: Sphere((0, 0, 0), True), InvalidGeometryError, "Sphere.radius must be a number, got True"),
    ("truncus-both-radii-zero", lambda: Truncus((0, 0, 0), (0, 0, 1), 0, 0), InvalidGeometryError,
     "Truncus.r1 and Truncus.r2 must not both be 0"),
    ("truncus-negative-r1", lambda: Truncus((0, 0, 0), (0, 0, 1), -1, 1), InvalidGeometryError, "Truncus.r1 must be >= 0, got -1"),
    ("truncus-negative-r2", lambda: Truncus((0, 0, 0), (0, 0, 1), 1, -0.5), InvalidGeometryError, "Truncus.r2 must be >= 0, got -0.5"),
    ("truncus-zero-axis", lambda: Truncus((0, 0, 0), (0, 0, 0), 1, 1), InvalidGeometryError,
     "Truncus.axis must be a non-zero vector, got (0.0, 0.0, 0.0)"),
    ("truncus-inf-axis", lambda: Truncus((0, 0, 0), (0, 0, INF), 1, 1), InvalidGeometryError,
     "Truncus.axis must be finite, got (0.0, 0.0, inf)"),
    ("cylinder-zero-radius", lambda: Cylinder((0, 0, 0), (0, 0, 1), 0), InvalidGeometryError, "Cylinder.radius must be > 0, got 0"),
    ("cylinder-zero-axis", lambda: Cylinder((0, 0, 0), (0, 0, 0), 1), InvalidGeometryError,
     "Cylinder.axis must be a non-zero vector, got (0.0, 0.0, 0.0)"),
    ("cone-negative-radius", lambda: Cone((0, 0, 0), (0, 0, 1), -1), InvalidGeometryError, "Cone.radius must be > 0, got -1"),
    ("box-zero-size", lambda: Box((0, 0, 0), (1, 0, 1)), InvalidGeometryError, "Box.size must be > 0 in every axis, got (1.0, 0.0, 1.0)"),
    ("box-negative-size", lambda: Box((0, 0, 0), (1, 1, -1)), InvalidGeometryError,
     "Box.size must be > 0 in every axis, got (1.0, 1.0, -1.0)"),
    ("box-nan-center", lambda: Box((0, NAN, 0), (1, 1, 1)), InvalidGeometryError, "Box.center must be finite, got (0.0, nan, 0.0)"),
    ("polyhedron-three-vertices", lambda: ConvexPolyhedron([(0, 0, 0), (1, 0, 0), (0, 1, 0)]), InvalidGeometryError,
     "ConvexPolyhedron.vertices needs at least 4 rows, got 3"),
    ("polyhedron-coplanar", lambda: ConvexPolyhedron([(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0), (0.5, 0.2, 0)]),
     InvalidGeometryError, "ConvexPolyhedron.vertices are coplanar or degenerate: their hull has no volume"),
    ("polyhedron-collinear", lambda: ConvexPolyhedron([(0, 0, 0), (1, 1, 1), (2, 2, 2), (3, 3, 3)]),
     InvalidGeometryError, "ConvexPolyhedron.vertices are coplanar or degenerate: their hull has no volume"),
    ("polyhedron-one-point", lambda: ConvexPolyhedron([(1, 2, 3)] * 5), InvalidGeometryError,
     "ConvexPolyhedron.vertices are all the same point"),
    ("polyhedron-nan", lambda: ConvexPolyhedron([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, NAN)]), InvalidGeometryError,
     "ConvexPolyhedron.vertices must be finite, row 3 is [0.0, 0.0, nan]"),
    ("polyhedron-2d", lambda: ConvexPolyhedron([(0, 0), (1, 0), (0, 1), (1, 1)]), InvalidGeometryError,
     "ConvexPolyhedron.vertices must have shape (n, 3), got (4, 2)"),
    # --- CSG
    ("union-empty", lambda: Union([]), InvalidGeometryError, "Union needs at least one operand, got none"),
    ("intersection-not-solid", lambda: Intersection(Sphere((0, 0, 0), 1), 3), InvalidGeometryError,
     "Intersection operand 1 must be a solid (primitive or CSG node), got int"),
    ("difference-empty", lambda: Difference(), InvalidGeometryError, "Difference needs at least one operand, got none"),
    # --- camera
    ("camera-eye-is-target", lambda: Camera((1, 2, 3), (1, 2, 3)), InvalidParameterError,
     "camera.target must differ from camera.eye, both are (1.0, 2.0, 3.0)"),
    ("camera-up-parallel", lambda: Camera((0, 0, 5), (0, 0, 0)), InvalidParameterError,
     "camera.up (0.0, 0.0, 1.0) must not be parallel to the view direction (0.0, 0.0, -1.0)"),
    ("camera-up-zero", lambda: Camera(EYE, TARGET, up=(0, 0, 0)), InvalidParameterError,
     "camera.up must be a non-zero vector, got (0.0, 0.0, 0.0)"),
    ("camera-nan-eye", lambda: Camera((NAN, -5, 0), TARGET), InvalidParameterError, "camera.eye must be finite, got (nan, -5.0, 0.0)"),
    ("camera-inf-target", lambda: Camera(EYE, (0, INF, 0)), InvalidParameterError, "camera.target must be finite, got (0.0, inf, 0.0)"),
    ("camera-fov-zero", lambda: Camera(EYE, TARGET, fov=0), InvalidParameterError, "camera.fov must be > 0, got 0"),
    ("camera-fov-negative", lambda: Camera(EYE, TARGET, fov=-10), InvalidParameterError, "camera.fov must be > 0, got -10"),
    ("camera-fov-180", lambda: Camera(EYE, TARGET, fov=180), InvalidParameterError, "camera.fov must be <= 179, got 180"),
    ("camera-fov-nan", lambda: Camera(EYE, TARGET, fov=NAN), InvalidParameterError, "camera.fov must be finite, got nan"),
    ("camera-width-zero", lambda: Camera(EYE, TARGET, width=0), InvalidParameterError,
     "camera.width must be between 1 and 16384, got 0"),
    ("camera-width-absurd", lambda: Camera(EYE, TARGET, width=100_000), InvalidParameterError,
     "camera.width must be between 1 and 16384, got 100000"),
    ("camera-height-absurd", lambda: Camera(EYE, TARGET, height=10**9), InvalidParameterError,
     "camera.height must be between 1 and 16384, got 1000000000"),
    ("camera-height-fraction", lambda: Camera(EYE, TARGET, height=2.5), InvalidParameterError,
     "camera.height must be an integer, got 2.5"),
    ("camera-ortho-height", lambda: Camera(EYE, TARGET, orthographic=True, height_m=0), InvalidParameterError,
     "camera.height_m must be > 0, got 0"),
    # --- render settings
    ("contours-zero", lambda: RenderSettings(contours=0), InvalidParameterError, "render.contours must be between 1 and 4096, got 0"),
    ("contours-negative", lambda: RenderSettings(contours=-3), InvalidParameterError,
     "render.contours must be between 1 and 4096, got -3"),
    ("contours-absurd", lambda: RenderSettings(contours=10**9), InvalidParameterError,
     "render.contours must be between 1 and 4096, got 1000000000"),
    ("contours-fraction", lambda: RenderSettings(contours=2.5), InvalidParameterError, "render.contours must be an integer, got 2.5"),
    ("render-mode", lambda: RenderSettings(mode="raytrace"), InvalidParameterError,
     "render.mode must be one of ('isoluminance', 'halftone'), got 'raytrace'"),
    ("render-exposure", lambda: RenderSettings(exposure=0), InvalidParameterError, "render.exposure must be > 0, got 0"),
    ("render-interval", lambda: RenderSettings(interval=0), InvalidParameterError, "render.interval must be between 1 and 256, got 0"),
    # --- materials
    ("material-ambient", lambda: Material(ambient=-0.1), InvalidLightError, "Material.ambient must be >= 0, got -0.1"),
    ("material-kd", lambda: Material(kd=-1), InvalidLightError, "Material.kd must be >= 0, got -1"),
    ("material-ks", lambda: Material(ks=-0.2), InvalidLightError, "Material.ks must be >= 0, got -0.2"),
    ("material-shininess", lambda: Material(shininess=0), InvalidLightError, "Material.shininess must be > 0, got 0"),
    ("material-nan", lambda: Material(kd=NAN), InvalidLightError, "Material.kd must be finite, got nan"),
    # --- lights
    ("point-light-inf", lambda: PointLight((0, 0, INF)), InvalidLightError, "PointLight.position must be finite, got (0.0, 0.0, inf)"),
    ("point-light-intensity", lambda: PointLight((0, 0, 1), -1), InvalidLightError, "PointLight.intensity must be >= 0, got -1"),
    ("directional-zero", lambda: DirectionalLight((0, 0, 0)), InvalidLightError,
     "DirectionalLight.direction must be a non-zero vector, got (0.0, 0.0, 0.0)"),
    ("directional-intensity", lambda: DirectionalLight((0, 0, 1), NAN), InvalidLightError,
     "DirectionalLight.intensity must be finite, got nan"),
]

AREA_CASES: list[tuple[str, Callable[[Any], Any], str]] = [
    ("area-two-vertices", lambda m: m.AreaLight([(0, 0, 0), (1, 0, 0)]), "AreaLight.vertices needs at least 3 rows, got 2"),
    ("area-collinear", lambda m: m.AreaLight([(0, 0, 0), (1, 0, 0), (2, 0, 0)]),
     "AreaLight.vertices are collinear: the polygon has zero area"),
    ("area-radiance", lambda m: m.AreaLight(SQUARE, radiance=-1), "AreaLight.radiance must be >= 0, got -1"),
    ("area-nan", lambda m: m.AreaLight([(0, 0, 0), (1, 0, 0), (0, NAN, 0)]), "AreaLight.vertices must be finite, row 2 is [0.0, nan, 0.0]"),
    ("polyhedron-light-flat", lambda m: m.PolyhedronLight([(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)]),
     "PolyhedronLight.vertices are coplanar or degenerate: their hull has no volume"),
]


@pytest.mark.parametrize("make, error, message", [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_bad_input_raises_documented_error(make: Callable[[], Any], error: type[Exception], message: str) -> None:
    with pytest.raises(error, match=f"^{re.escape(message)}$") as info:
        make()
    # Every deliberate error is an IsocsgError and the builtin it refines.
    assert isinstance(info.value, IsocsgError)
    assert isinstance(info.value, ValueError)


@pytest.mark.parametrize("make, message", [c[1:] for c in AREA_CASES], ids=[c[0] for c in AREA_CASES])
def test_bad_area_and_polyhedron_sources(make: Callable[[Any], Any], message: str) -> None:
    lights = pytest.importorskip("isocsg.lighting.area")
    with pytest.raises(InvalidLightError, match=f"^{re.escape(message)}$") as info:
        make(lights)
    assert isinstance(info.value, ValueError)


def test_numpy_inputs_are_accepted_and_stored_as_tuples() -> None:
    s = Sphere(np.array([1, 2, 3], dtype=np.int32), np.float32(0.5))
    assert s.center == (1.0, 2.0, 3.0) and type(s.radius) is float and s.radius == 0.5


def test_scene_rejects_a_non_solid_object() -> None:
    with pytest.raises(InvalidGeometryError, match=re.escape("SceneObject.shape must be a solid, got str")):
        Scene(Camera(EYE, TARGET), (), ("sphere",))


# ----------------------------------------------------------------------------- a light inside an object


def _render_function():
    try:
        from isocsg.rendering import render
    except ImportError:
        pytest.skip("isocsg.rendering is not available")
    return render


def _ray_distance(camera: Camera, center: np.ndarray) -> np.ndarray:
    """Distance from ``center`` to each pixel-centre ray (independent of isocsg)."""
    f = np.subtract(camera.target, camera.eye)
    f /= np.linalg.norm(f)
    r = np.cross(f, camera.up)
    r /= np.linalg.norm(r)
    u = np.cross(r, f)
    t = math.tan(math.radians(camera.fov) / 2)
    x = (2 * (np.arange(camera.width) + 0.5) / camera.width - 1) * t * camera.width / camera.height
    y = (1 - 2 * (np.arange(camera.height) + 0.5) / camera.height) * t
    d = f + x[None, :, None] * r + y[:, None, None] * u
    d /= np.linalg.norm(d, axis=-1, keepdims=True)
    oc = np.asarray(camera.eye) - center
    b = d @ oc
    return np.sqrt(np.maximum(oc @ oc - b * b, 0.0))


@pytest.mark.parametrize(
    "light",
    [PointLight((0.0, 0.0, 0.0)), PointLight((0.3, -0.2, 0.4))],
    ids=["at-centre", "off-centre"],
)
def test_light_inside_an_object_leaves_only_ambient(light: PointLight) -> None:
    render = _render_function()
    material = Material(ambient=0.15, kd=0.8)
    camera = Camera((0.0, -5.0, 1.5), (0, 0, 0), fov=30, width=48, height=40)
    scene = Scene(camera, [light], [SceneObject(Sphere((0, 0, 0), 1.0), material)])
    image = render(scene, contours=8).image  # not an error
    dist = _ray_distance(camera, np.zeros(3))
    seen = np.isfinite(image)
    # The band mesh is inscribed in the sphere: rays that miss the sphere see
    # nothing; rays well inside the silhouette see the sphere.
    assert not seen[dist > 1.0].any()
    assert seen[dist < 0.97].all()
    # Every surface point faces away from a light inside the convex solid: ambient only.
    np.testing.assert_allclose(image[seen], material.ambient, rtol=0, atol=1e-6)


def test_light_inside_a_box_leaves_only_ambient() -> None:
    render = _render_function()
    material = Material(ambient=0.2, kd=0.7)
    camera = Camera((3.0, -4.0, 2.5), (0, 0, 0), fov=35, width=40, height=40)
    scene = Scene(camera, [PointLight((0.1, 0.2, -0.1)), PointLight((5, -5, 5))], [SceneObject(Box((0, 0, 0), (1, 1, 1)), material)])
    lit_from_outside = render(scene, contours=8).image
    alone = render(Scene(camera, [PointLight((0.1, 0.2, -0.1))], scene.objects), contours=8).image
    assert np.isfinite(alone).any()
    np.testing.assert_allclose(alone[np.isfinite(alone)], material.ambient, rtol=0, atol=1e-6)
    # The inside light adds nothing to the exact image (the ray caster's). Its
    # near point subdivides the faces more finely, so the outside light's level
    # lines, linear on each triangle, follow their curves more closely: a band
    # edge may move by a pixel, never away from the exact image.
    outside = Scene(camera, [PointLight((5, -5, 5))], scene.objects)
    outside_only = render(outside, contours=8).image
    exact = raycast_scene(scene).image
    np.testing.assert_array_equal(exact, raycast_scene(outside).image)
    np.testing.assert_array_equal(np.isnan(lit_from_outside), np.isnan(outside_only))
    seen = np.isfinite(outside_only)
    err_with = np.abs(lit_from_outside - exact)[seen]
    err_without = np.abs(outside_only - exact)[seen]
    assert err_with.max() <= err_without.max() + 1e-6
    moved = np.abs(lit_from_outside - outside_only)[seen] > 1e-6
    assert moved.mean() <= 0.02, f"{moved.sum()} of {seen.sum()} pixels differ"
    assert np.all(err_with[moved] <= err_without[moved] + 1e-6)


# ----------------------------------------------------------------------------- the contour limit, as documented


def test_the_documented_contour_limit_is_the_enforced_one() -> None:
    """README's "Limits" row on contours states the constants of the code, and the code enforces it."""
    from isocsg import AreaLight
    from isocsg._validation import MAX_LIGHT_CONTOURS
    from isocsg.laminae import MAX_CONTOURS as LAMINAE_MAX_CONTOURS
    from isocsg.scene import MAX_CONTOURS

    readme = (Path(__file__).resolve().parents[1] / "README.md").read_text(encoding="utf-8")
    rows = [line for line in readme.splitlines() if line.startswith("| contours |")]
    assert len(rows) == 1, "one statement of the contour limit"
    row = rows[0]
    assert f"N x (point + directional lights) <= {MAX_LIGHT_CONTOURS} (`MAX_LIGHT_CONTOURS`)" in row
    assert f"at most {MAX_LIGHT_CONTOURS} with one such light, {MAX_LIGHT_CONTOURS // 2} with two" in row
    assert f"N <= {MAX_CONTOURS} (" in row and "`MAX_CONTOURS`" in row
    assert LAMINAE_MAX_CONTOURS == MAX_CONTOURS
    toml_comment = f"at most {MAX_LIGHT_CONTOURS} / (point + directional lights)"
    assert toml_comment in readme

    cam = Camera((0, -5, 0), (0, 0, 0), width=8, height=8)
    ball = [Sphere((0, 0, 0), 1)]
    for n_lights in (1, 2, 3):
        lights = [PointLight((k, -4, 5)) for k in range(n_lights)]
        most = MAX_LIGHT_CONTOURS // n_lights
        Scene(cam, lights, ball, RenderSettings(contours=most))
        with pytest.raises(InvalidParameterError, match=re.escape(f"render.contours must be at most {most}")):
            Scene(cam, lights, ball, RenderSettings(contours=most + 1))
    area = AreaLight([(0, 0, 3), (0, 1, 3), (1, 1, 3), (1, 0, 3)])
    Scene(cam, [area], ball, RenderSettings(mode="halftone", contours=MAX_CONTOURS))
    with pytest.raises(InvalidParameterError, match="render.contours"):
        RenderSettings(contours=MAX_CONTOURS + 1)
