"""Images of triangle meshes against the reference ray caster.

Two independent references: the ray caster's own brute-force mesh intervals
(``tests/reference/mesh.py``), and, for meshes of solids the caster knows in closed form, the
caster's image of those solids (an L-shaped prism mesh against the union of two boxes, a
comb-shaped mesh whose rays cross it up to four times). Views include rays through the mesh's
concavities, CSG with spheres and a point light (a face's luminance then varies across it).
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))

from reference import compare, raycast_scene  # noqa: E402
from test_mesh_kind import prism  # noqa: E402

import isocsg  # noqa: E402
from isocsg import Box, Camera, DirectionalLight, PointLight, Scene, Sphere, TriangleMesh  # noqa: E402

L_MESH = TriangleMesh(*prism([(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0), (1.0, 2.0), (0.0, 2.0)], 0.0, 1.0))
L_BOXES = Box((1.0, 0.5, 0.5), (2.0, 1.0, 1.0)) | Box((0.5, 1.5, 0.5), (1.0, 1.0, 1.0))
COMB = [(0.0, 0.0), (7.0, 0.0), (7.0, 3.0), (6.0, 3.0), (6.0, 1.0), (5.0, 1.0), (5.0, 3.0), (4.0, 3.0), (4.0, 1.0),
        (3.0, 1.0), (3.0, 3.0), (2.0, 3.0), (2.0, 1.0), (1.0, 1.0), (1.0, 3.0), (0.0, 3.0)]
COMB_MESH = TriangleMesh(*prism(COMB, 0.0, 1.0))
COMB_BOXES = isocsg.union(Box((3.5, 0.5, 0.5), (7.0, 1.0, 1.0)),
                          *[Box((2 * k + 0.5, 2.0, 0.5), (1.0, 2.0, 1.0)) for k in range(4)])

CAM_L = Camera(eye=(4.0, -3.0, 3.2), target=(0.9, 0.9, 0.4), width=96, height=72)
CAM_COMB = Camera(eye=(-4.0, 2.0, 3.5), target=(3.5, 1.5, 0.5), width=112, height=64)
LIGHTS = [DirectionalLight((0.4, -0.6, 1.0)), PointLight((1.5, -2.0, 3.0))]


def _check(scene: Scene, reference: Scene, contours: int = 64) -> None:
    image = isocsg.render(scene, contours=contours).image
    result = compare(image, raycast_scene(reference))
    assert result.iou >= 0.995, result
    assert result.fraction >= 0.99, result
    assert result.mean_error <= 0.01, result


@pytest.mark.parametrize("light", LIGHTS, ids=["directional", "point"])
def test_l_prism_mesh_is_the_union_of_two_boxes(light) -> None:
    _check(Scene(CAM_L, [light], [L_MESH]), Scene(CAM_L, [light], [L_BOXES]))


def test_l_prism_mesh_against_the_reference_mesh_caster() -> None:
    scene = Scene(CAM_L, [LIGHTS[1]], [L_MESH - Sphere((1.5, 0.2, 0.9), 0.5)])
    _check(scene, scene)


@pytest.mark.parametrize("csg", ["minus", "and", "or"])
def test_comb_mesh_in_csg_with_spheres(csg) -> None:
    """Rays from the side cross the comb's teeth up to four times; a sphere cuts across the teeth."""
    ball = Sphere((3.0, 2.2, 0.6), 1.1)
    mesh = {"minus": COMB_MESH - ball, "and": COMB_MESH & ball, "or": COMB_MESH | ball}[csg]
    boxes = {"minus": COMB_BOXES - ball, "and": COMB_BOXES & ball, "or": COMB_BOXES | ball}[csg]
    _check(Scene(CAM_COMB, LIGHTS[:1], [mesh]), Scene(CAM_COMB, LIGHTS[:1], [boxes]))


def test_mesh_seen_through_a_cut_and_from_inside_a_concavity() -> None:
    """A view from inside the comb's gap between two teeth, looking along the teeth: the near tooth's
    back faces show through a cut box (difference: the reversed normals)."""
    cam = Camera(eye=(2.5, 2.5, 2.5), target=(2.5, 0.5, 0.0), width=80, height=80)
    solid = COMB_MESH - Box((2.5, 2.0, 1.0), (4.0, 1.0, 1.0))
    ref = COMB_BOXES - Box((2.5, 2.0, 1.0), (4.0, 1.0, 1.0))
    _check(Scene(cam, [LIGHTS[1]], [solid]), Scene(cam, [LIGHTS[1]], [ref]))


def test_error_shrinks_with_contours_under_a_point_light() -> None:
    scene = Scene(CAM_L, [LIGHTS[1]], [L_MESH])
    ref = raycast_scene(Scene(CAM_L, [LIGHTS[1]], [L_BOXES]))
    errors = [compare(isocsg.render(scene, contours=n).image, ref).mean_error for n in (4, 16, 64)]
    assert errors[2] < errors[0] and errors[2] <= 0.01, errors


def test_many_faces_render_as_one_part(monkeypatch) -> None:
    """Above MAX_FACE_PARTS faces the mesh's bands are cut at common levels (lowered here so that a
    small mesh takes that path): still the exact image within the band step."""
    from isocsg.kinds import mesh_bands

    monkeypatch.setattr(mesh_bands, "MAX_FACE_PARTS", 8)
    V, F = prism(COMB, 0.0, 1.0)
    mesh = TriangleMesh(V, F[:, [1, 2, 0]])  # the same triangles, not the cached COMB_MESH
    assert len(mesh.faces) > 8
    for light in LIGHTS:
        _check(Scene(CAM_COMB, [light], [mesh]), Scene(CAM_COMB, [light], [COMB_BOXES]))


@pytest.mark.parametrize("csg", ["minus", "or"])
def test_comb_mesh_in_csg_through_screen_tiles(csg, monkeypatch) -> None:
    """The same through the tiled path (screen tiles, groups of equal leaves, layers per tile)."""
    from isocsg.rendering import policy

    monkeypatch.setattr(policy, "DENSE_MAX_LEAVES", 0)
    ball = Sphere((3.0, 2.2, 0.6), 1.1)
    mesh = COMB_MESH - ball if csg == "minus" else COMB_MESH | ball
    boxes = COMB_BOXES - ball if csg == "minus" else COMB_BOXES | ball
    image = isocsg.Renderer(csg="pixel").render(Scene(CAM_COMB, LIGHTS[1:], [mesh]), contours=64).image
    result = compare(image, raycast_scene(Scene(CAM_COMB, LIGHTS[1:], [boxes])))
    assert result.iou >= 0.995 and result.fraction >= 0.99 and result.mean_error <= 0.01, result
