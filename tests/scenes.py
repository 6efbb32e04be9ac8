"""A catalogue of canonical scenes shared by the accuracy tests.

Each scene is a small ``isocsg.Scene`` (160 x 160 pixels) chosen to exercise
one difficulty of the isoluminance method: the eye in the plane of a lamina
family, a light on a truncus axis, near point lights, specular highlights,
several lights, objects overlapping on screen and in depth, and CSG cuts
whose inner (reversed-normal) surfaces face the light.

Use with ``pytest.mark.parametrize("name", CORE_SCENES, ids=str)`` and look the
scene up by name, or parametrize over ``.items()``.
"""

from __future__ import annotations

import dataclasses

from isocsg import (
    Box,
    Camera,
    Cone,
    ConvexPolyhedron,
    Cylinder,
    DirectionalLight,
    Material,
    PointLight,
    RenderSettings,
    Scene,
    SceneObject,
    Sphere,
    Truncus,
)

__all__ = ["SIZE", "CORE_SCENES", "CSG_SCENES", "ALL_SCENES", "make_scene", "with_contours", "render_image"]

#: Image side in pixels.
SIZE = 160

SPECULAR = Material(ambient=0.1, kd=0.6, ks=0.5, shininess=20.0)
DARKER = Material(ambient=0.05, kd=0.7)


def make_scene(eye, objects, lights, *, target=(0.0, 0.0, 0.0), size: int = SIZE, fov: float = 40.0,
               contours: int = 64) -> Scene:
    """A scene with a square pinhole camera; ``objects`` holds solids or ``SceneObject``s."""
    cam = Camera(eye, target, fov=fov, width=size, height=size)
    objs = tuple(o if isinstance(o, SceneObject) else SceneObject(o) for o in objects)
    return Scene(cam, tuple(lights), objs, RenderSettings(contours=contours))


def with_contours(scene: Scene, contours: int) -> Scene:
    """The same scene rendered with another number of contours."""
    return dataclasses.replace(scene, render=dataclasses.replace(scene.render, contours=contours))


def render_image(scene: Scene, csg: str | None = None):
    """The library's float32 image of a scene (the thing the accuracy tests judge).

    ``csg`` picks the renderer's CSG method ("pixel" or "surface"); by
    default the module-wide renderer ("auto").
    """
    import numpy as np

    from isocsg.rendering import Renderer, render

    image = render(scene).image if csg is None else Renderer(csg=csg).render(scene).image
    assert image.dtype == np.float32
    assert image.shape == (scene.camera.height, scene.camera.width)
    return image


def _polyhedron() -> ConvexPolyhedron:
    # an irregular convex solid: skewed octahedron plus two corner points
    return ConvexPolyhedron([
        (1.0, 0.05, 0.0), (-0.95, 0.1, 0.05), (0.05, 1.1, 0.0), (0.1, -1.0, 0.1),
        (0.0, 0.05, 1.2), (0.2, 0.1, -1.0), (0.6, -0.55, 0.6), (-0.55, -0.5, -0.6),
    ])


def _core() -> dict[str, Scene]:
    unit = Sphere((0, 0, 0), 1.0)
    s: dict[str, Scene] = {}
    s["sphere_oblique_point_light"] = make_scene((0, -5, 1.5), [unit], [PointLight((4, -3, 6))])
    # the eye in the plane z = 0 of the sphere's contour family (light axis z): circles seen edge-on
    s["sphere_eye_in_lamina_plane"] = make_scene((0, -5, 0), [unit], [DirectionalLight((0, 0, 1))])
    # a point light 1.5 diameters from the centre: the lit cap shrinks, contours stay circles
    s["sphere_near_light"] = make_scene((0, -5, 1), [unit], [PointLight((1.5, -2.0, 1.8))])
    s["sphere_specular"] = make_scene((0, -5, 1.5), [SceneObject(unit, SPECULAR)], [PointLight((3, -5, 4))])
    s["cylinder_light_on_axis"] = make_scene(
        (3, -4, 2.5), [Cylinder((0, 0, 0), (0, 0, 2), 0.8)], [PointLight((0, 0, 5))])
    # light direction projects onto +x in the end planes: quads are the planes x = const, the eye is in x = 0
    s["cylinder_eye_in_quad_plane"] = make_scene(
        (0, -5, 1.5), [Cylinder((0, 0, 0), (0, 0, 2), 0.8)], [DirectionalLight((1, 0, 0.3))])
    s["cone_near_light"] = make_scene(
        (1, -5, 1.5), [Cone((0, 0, 0), (0, 0, -2), 1.0)], [PointLight((2.2, -1.5, 1.5))])
    s["frustum_specular"] = make_scene(
        (0.5, -5, 1.0), [SceneObject(Truncus((0, 0, 0), (0.6, 0, 1.6), 0.5, 1.0), SPECULAR)],
        [PointLight((4, -4, 5))])
    s["disc_tilted"] = make_scene(
        (3.5, -3, 1.2), [Cylinder((0, 0, 0), (0.1, -0.15, 0.2), 1.0)], [DirectionalLight((1, -2, 3))])
    s["rod_directional"] = make_scene(
        (0.5, -5, 1), [Cylinder((0, 0, 0), (1.2, 0.5, 1.6), 0.15)], [DirectionalLight((-1, -2, 2))])
    s["box_two_point_lights"] = make_scene(
        (3, -4.5, 3), [Box((0, 0, 0), (1.6, 1.2, 1.0))],
        [PointLight((3, -4, 4)), PointLight((-4, -3, 2), intensity=0.6)])
    s["polyhedron_point_light"] = make_scene((2.5, -4, 2), [_polyhedron()], [PointLight((3, -5, 4))])
    # separate objects that interpenetrate: the visible surface switches object along a curve
    s["sphere_box_interpenetrating"] = make_scene(
        (1, -5, 1.5),
        [Sphere((0, 0, 0.2), 0.9), SceneObject(Box((0.7, 0.3, -0.3), (1.2, 1.2, 1.2)), DARKER)],
        [PointLight((3, -4, 5))])
    s["cylinder_sphere_two_lights"] = make_scene(
        (0.5, -5, 2), [Cylinder((-0.5, 0.3, 0), (0.3, 0.2, 2.0), 0.6), SceneObject(Sphere((0.5, -0.2, 0.2), 0.7), SPECULAR)],
        [PointLight((3, -4, 3)), PointLight((-4, -2, 4), intensity=0.5)])
    return s


def _csg() -> dict[str, Scene]:
    s: dict[str, Scene] = {}
    ball = Sphere((0, 0, 0), 1.0)
    s["sphere_minus_cylinder"] = make_scene(
        (1.5, -4, 3.5), [ball - Cylinder((0, 0, 0), (0, 0, 3), 0.45)], [PointLight((2, -3, 5))])
    s["sphere_and_box"] = make_scene(
        (3, -4, 2.5), [ball & Box((0, 0, 0), (1.5, 1.5, 1.5))], [PointLight((4, -2, 5))])
    s["union_two_spheres"] = make_scene(
        (1, -5, 1.5), [Sphere((0, 0, 0), 1.0) | Sphere((0.9, -0.3, 0.4), 0.6)], [PointLight((-3, -4, 4))])
    s["cone_minus_sphere"] = make_scene(
        (2, -4.5, 1.5), [Cone((0, 0, 0), (0, 0, -2), 1.1) - Sphere((0.6, -0.6, 0.2), 0.6)],
        [PointLight((3, -4, 3))])
    cyl_x = Cylinder((0, 0, 0), (2.4, 0, 0), 0.45)
    cyl_y = Cylinder((0, 0, 0), (0, 2.4, 0), 0.45)
    s["nested_box_cylinders_sphere"] = make_scene(
        (3, -4, 3), [(Box((0, 0, 0), (1.6, 1.6, 1.6)) - (cyl_x | cyl_y)) & Sphere((0, 0, 0), 1.05)],
        [PointLight((4, -3, 5))])
    # a spherical dent in the top of a slab, lit from above: the inside of the cut faces the light
    s["dent_faces_light"] = make_scene(
        (1.5, -3.5, 3.5), [Box((0, 0, 0), (2, 2, 1.2)) - Sphere((0, 0, 0.6), 0.8)], [PointLight((0.5, -0.5, 4))])
    # the box's faces inside the cut, with reversed normals, face the light
    s["sphere_minus_box_corner"] = make_scene(
        (3, -4, 3.5), [ball - Box((0.6, -0.6, 0.6), (1.2, 1.2, 1.2))], [PointLight((4, -2, 3))])
    # eye in the plane z = 0 of both families (sphere circles and the cylinder's quads, light along z)
    s["edge_on_sphere_minus_cylinder"] = make_scene(
        (0, -5, 0), [ball - Cylinder((0, 0, 0), (1.2, 2.4, 0), 0.4)], [DirectionalLight((0, 0, 1))])
    s["two_csg_objects_overlap"] = make_scene(
        (0.5, -5, 1.5),
        [Sphere((-0.4, 0, 0), 0.9) - Cylinder((-0.4, 0, 0), (0, 0, 3), 0.35),
         SceneObject(Box((0.6, 0.8, 0.1), (1.2, 1.2, 1.2)) & Sphere((0.6, 0.8, 0.1), 0.8), DARKER)],
        [PointLight((3, -4, 4))])
    octa = ConvexPolyhedron([(1.3, 0.2, 0), (-1.2, -0.2, 0.1), (0.1, 1.3, -0.1), (-0.2, -1.25, 0),
                             (0, 0, 1.3), (0.1, 0, -1.3)])
    s["frustum_and_polyhedron"] = make_scene(
        (2.5, -4, 2), [Truncus((0, 0, 0), (0, 0, 2), 0.6, 1.1) & octa], [PointLight((4, -4, 4))])
    s["box_minus_three_cylinders"] = make_scene(
        (3, -4, 3.2),
        [Box((0, 0, 0), (1.6, 1.6, 1.6)) - Cylinder((0, 0, 0), (2.4, 0, 0), 0.5)
         - Cylinder((0, 0, 0), (0, 2.4, 0), 0.5) - Cylinder((0, 0, 0), (0, 0, 2.4), 0.5)],
        [PointLight((2, -4, 5))])
    s["three_cylinders_intersection_specular"] = make_scene(
        (3, -4, 2.5),
        [SceneObject(Cylinder((0, 0, 0), (2.4, 0, 0), 0.9) & Cylinder((0, 0, 0), (0, 2.4, 0), 0.9)
                     & Cylinder((0, 0, 0), (0, 0, 2.4), 0.9), SPECULAR)],
        [PointLight((3, -5, 4))])
    s["specular_sphere_minus_frustum"] = make_scene(
        (1, -4, 3.5), [SceneObject(ball - Truncus((0.2, 0, 0.5), (0, 0, 1.4), 0.6, 0.25), SPECULAR)],
        [PointLight((2, -3, 5)), PointLight((-3, -2, 1), intensity=0.4)])
    s["difference_leaves_nothing"] = make_scene(
        (1, -5, 1.5), [ball - Box((0, 0, 0), (3, 3, 3))], [PointLight((3, -4, 5))])
    return s


CORE_SCENES: dict[str, Scene] = _core()
CSG_SCENES: dict[str, Scene] = _csg()
ALL_SCENES: dict[str, Scene] = {**CORE_SCENES, **CSG_SCENES}
