"""Scene files: round trips, TOML == JSON, built-in scenes, and exact error messages."""

from __future__ import annotations

import copy
import json
import re
from pathlib import Path
from typing import Any

import pytest

from isocsg import (
    Box,
    Camera,
    Cone,
    ConvexPolyhedron,
    Cylinder,
    DirectionalLight,
    IsocsgError,
    Material,
    PointLight,
    SceneFileError,
    Sphere,
    Truncus,
)
from isocsg.csg import Difference, Intersection, Union
from isocsg.scene import (
    BUILTIN_SCENES,
    RenderSettings,
    Scene,
    SceneObject,
    builtin_scene,
    dumps_scene,
    load_scene,
    loads_scene,
    save_scene,
    scene_from_dict,
    scene_to_dict,
)

TETRA = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]

# A document that uses every node kind; the expected Scene is built by hand below.
DOC: dict[str, Any] = {
    "camera": {"eye": [6, -8, 5], "target": [0, 0, 0.5], "up": [0, 0, 1], "fov": 35, "width": 64, "height": 48},
    "render": {"contours": 16, "mode": "isoluminance", "exposure": 1.5, "interval": 2},
    "lights": [
        {"kind": "point", "position": [5, -5, 8], "intensity": 0.7},
        {"kind": "directional", "direction": [-1, -1, 2]},
    ],
    "objects": [
        {
            "material": {"ambient": 0.2, "kd": 0.6, "ks": 0.3, "shininess": 12},
            "shape": {
                "difference": [
                    {"box": {"center": [0, 0, 0], "size": [2, 2, 2]}},
                    {"sphere": {"center": [1, 1, 1], "radius": 0.8}},
                    {
                        "union": [
                            {"cylinder": {"center": [0, 0, 0], "axis": [0, 0, 3], "radius": 0.3}},
                            {"cone": {"center": [-1, 0, 0], "axis": [1, 0, 0], "radius": 0.4}},
                        ]
                    },
                ]
            },
        },
        {
            "shape": {
                "intersection": [
                    {"truncus": {"center": [3, 0, 0], "axis": [0, 1, 1], "r1": 0.5, "r2": 0.25}},
                    {"polyhedron": {"vertices": [[3 + x, y, z] for x, y, z in [[-1, -1, -1], [1, -1, -1], [0, 1, -1], [0, 0, 1]]]}},
                ]
            }
        },
    ],
}


def expected_scene() -> Scene:
    part = Difference(
        Box((0, 0, 0), (2, 2, 2)),
        Sphere((1, 1, 1), 0.8),
        Union(Cylinder((0, 0, 0), (0, 0, 3), 0.3), Cone((-1, 0, 0), (1, 0, 0), 0.4)),
    )
    other = Intersection(
        Truncus((3, 0, 0), (0, 1, 1), 0.5, 0.25),
        ConvexPolyhedron([[2, -1, -1], [4, -1, -1], [3, 1, -1], [3, 0, 1]]),
    )
    return Scene(
        Camera((6, -8, 5), (0, 0, 0.5), (0, 0, 1), 35, 64, 48),
        (PointLight((5, -5, 8), 0.7), DirectionalLight((-1, -1, 2))),
        (SceneObject(part, Material(0.2, 0.6, 0.3, 12)), SceneObject(other)),
        RenderSettings(contours=16, mode="isoluminance", exposure=1.5, interval=2),
    )


TOML_TEXT = """
[camera]
eye = [6, -8, 5]
target = [0, 0, 0.5]
up = [0, 0, 1]
fov = 35
width = 64
height = 48

[render]
contours = 16
mode = "isoluminance"
exposure = 1.5
interval = 2

[[lights]]
kind = "point"
position = [5, -5, 8]
intensity = 0.7

[[lights]]
kind = "directional"
direction = [-1, -1, 2]

[[objects]]
material = { ambient = 0.2, kd = 0.6, ks = 0.3, shininess = 12 }
shape = { difference = [
    { box = { center = [0, 0, 0], size = [2, 2, 2] } },
    { sphere = { center = [1, 1, 1], radius = 0.8 } },
    { union = [
        { cylinder = { center = [0, 0, 0], axis = [0, 0, 3], radius = 0.3 } },
        { cone = { center = [-1, 0, 0], axis = [1, 0, 0], radius = 0.4 } },
    ] },
] }

[[objects]]
[objects.shape]
intersection = [
    { truncus = { center = [3, 0, 0], axis = [0, 1, 1], r1 = 0.5, r2 = 0.25 } },
    { polyhedron = { vertices = [[2, -1, -1], [4, -1, -1], [3, 1, -1], [3, 0, 1]] } },
]
"""


# ----------------------------------------------------------------------------- reading


def test_toml_file_matches_hand_built_scene(tmp_path: Path) -> None:
    path = tmp_path / "scene.toml"
    path.write_text(TOML_TEXT)
    assert load_scene(path) == expected_scene()


def test_json_file_matches_hand_built_scene(tmp_path: Path) -> None:
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(DOC))
    assert load_scene(str(path)) == expected_scene()


def test_defaults_fill_optional_tables() -> None:
    doc = {
        "camera": {"eye": [0, -5, 0], "target": [0, 0, 0]},
        "objects": [{"shape": {"sphere": {"center": [0, 0, 0], "radius": 1}}}],
    }
    scene = scene_from_dict(doc)
    assert scene == Scene(Camera((0, -5, 0), (0, 0, 0)), (), (SceneObject(Sphere((0, 0, 0), 1)),), RenderSettings())
    assert scene.objects[0].material == Material()


def test_primitive_kinds_keep_their_types() -> None:
    part = scene_from_dict(DOC).objects[0].shape
    assert isinstance(part, Difference)
    kinds = [type(c).__name__ for c in part.children]
    assert kinds == ["Box", "Sphere", "Union"]
    assert [type(c).__name__ for c in part.children[2].children] == ["Cylinder", "Cone"]


# ----------------------------------------------------------------------------- round trips


@pytest.mark.parametrize("fmt", ["toml", "json"])
def test_dumps_loads_round_trip(fmt: str) -> None:
    scene = expected_scene()
    assert loads_scene(dumps_scene(scene, format=fmt), format=fmt) == scene


def test_scene_to_dict_round_trip_through_json_text() -> None:
    scene = expected_scene()
    doc = json.loads(json.dumps(scene_to_dict(scene)))
    assert scene_from_dict(doc) == scene


def test_orthographic_camera_round_trip() -> None:
    scene = Scene(Camera((0, -5, 0), (0, 0, 0), orthographic=True, height_m=3.0), [], [Box((0, 0, 0), (1, 1, 1))])
    back = loads_scene(dumps_scene(scene))
    assert back == scene and back.camera.orthographic and back.camera.height_m == 3.0


@pytest.mark.parametrize("suffix", [".toml", ".json"])
def test_save_scene_then_load(tmp_path: Path, suffix: str) -> None:
    scene = expected_scene()
    path = save_scene(scene, tmp_path / f"s{suffix}")
    assert load_scene(path) == scene


def test_area_and_polyhedron_lights_round_trip() -> None:
    lights = pytest.importorskip("isocsg.lighting.area")
    square = [[-1, -1, 3], [-1, 1, 3], [1, 1, 3], [1, -1, 3]]
    doc = copy.deepcopy(DOC)
    doc["render"]["mode"] = "halftone"
    doc["lights"] = [
        {"kind": "area", "vertices": square, "radiance": 2.5},
        {"kind": "polyhedron", "vertices": [[x, y, z + 4] for x, y, z in TETRA]},
    ]
    scene = scene_from_dict(doc)
    assert scene.lights[0] == lights.AreaLight(square, radiance=2.5)
    assert scene.lights[1] == lights.PolyhedronLight([[x, y, z + 4] for x, y, z in TETRA])
    assert loads_scene(dumps_scene(scene)) == scene


@pytest.mark.parametrize("name", BUILTIN_SCENES)
def test_builtin_scenes_load_and_round_trip(name: str) -> None:
    if name == "halftone":
        pytest.importorskip("isocsg.lighting.area")
    scene = builtin_scene(name)
    assert len(scene.objects) >= 1
    assert loads_scene(dumps_scene(scene)) == scene


def test_demo_scene_has_a_csg_part() -> None:
    scene = builtin_scene("demo")
    assert scene.render.mode == "isoluminance"
    assert any(isinstance(o.shape, Difference) for o in scene.objects)


# ----------------------------------------------------------------------------- errors


def _doc(**changes: Any) -> dict[str, Any]:
    """A deep copy of DOC with dotted-path edits (``None`` deletes the key)."""
    d = copy.deepcopy(DOC)
    for dotted, value in changes.items():
        keys: list[Any] = [int(k) if k.isdigit() else k for k in dotted.split("__")]
        node = d
        for k in keys[:-1]:
            node = node[k]
        if value is _DELETE:
            del node[keys[-1]]
        else:
            node[keys[-1]] = value
    return d


_DELETE = object()
SPHERE_PATH = "objects__0__shape__difference__1__sphere"

# (id, edits, message after "scene.json: ")
DOC_ERRORS = [
    ("negative-radius", {f"{SPHERE_PATH}__radius": -1},
     "objects[0].shape.difference[1].sphere.radius: must be > 0, got -1"),
    ("nan-center", {f"{SPHERE_PATH}__center": [float("nan"), 0, 0]},
     "objects[0].shape.difference[1].sphere.center: must be finite, got (nan, 0.0, 0.0)"),
    ("short-center", {f"{SPHERE_PATH}__center": [1, 2]},
     "objects[0].shape.difference[1].sphere.center: must have shape (3,), got (2,)"),
    ("string-radius", {f"{SPHERE_PATH}__radius": "big"},
     "objects[0].shape.difference[1].sphere.radius: must be a number, got 'big'"),
    ("bool-radius", {f"{SPHERE_PATH}__radius": True},
     "objects[0].shape.difference[1].sphere.radius: must be a number, got True"),
    ("unknown-field", {f"{SPHERE_PATH}__radus": 2},
     "objects[0].shape.difference[1].sphere: unknown key 'radus' (expected center, radius)"),
    ("missing-field", {f"{SPHERE_PATH}__radius": _DELETE},
     "objects[0].shape.difference[1].sphere.radius: missing required field"),
    ("box-size", {"objects__0__shape__difference__0__box__size": [1, 0, 1]},
     "objects[0].shape.difference[0].box.size: must be > 0 in every axis, got (1.0, 0.0, 1.0)"),
    ("truncus-radii", {"objects__1__shape__intersection__0__truncus__r1": 0,
                       "objects__1__shape__intersection__0__truncus__r2": 0},
     "objects[1].shape.intersection[0].truncus: r1 and r2 must not both be 0"),
    ("truncus-axis", {"objects__1__shape__intersection__0__truncus__axis": [0, 0, 0]},
     "objects[1].shape.intersection[0].truncus.axis: must be a non-zero vector, got (0.0, 0.0, 0.0)"),
    ("cylinder-radius", {"objects__0__shape__difference__2__union__0__cylinder__radius": 0},
     "objects[0].shape.difference[2].union[0].cylinder.radius: must be > 0, got 0"),
    ("flat-polyhedron", {"objects__1__shape__intersection__1__polyhedron__vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]]},
     "objects[1].shape.intersection[1].polyhedron.vertices: are coplanar or degenerate: their hull has no volume"),
    ("few-vertices", {"objects__1__shape__intersection__1__polyhedron__vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]},
     "objects[1].shape.intersection[1].polyhedron.vertices: needs at least 4 rows, got 3"),
    ("empty-union", {"objects__0__shape__difference__2__union": []},
     "objects[0].shape.difference[2].union: needs at least one operand, got none"),
    ("union-not-array", {"objects__0__shape__difference__2__union": {"sphere": {"center": [0, 0, 0], "radius": 1}}},
     "objects[0].shape.difference[2].union: must be an array, got a table"),
    ("unknown-node", {"objects__0__shape": {"klein_bottle": {"center": [0, 0, 0]}}},
     ("objects[0].shape: unknown shape 'klein_bottle' (expected one of sphere, truncus, cylinder, cone, box, polyhedron, "
      "ellipsoid, elliptic_truncus, torus, mesh, extrude, union, intersection, difference, translate, rotate, scale, mirror, multmatrix, transform)")),
    ("two-keys", {"objects__0__shape": {"sphere": {"center": [0, 0, 0], "radius": 1}, "box": {"center": [0, 0, 0], "size": [1, 1, 1]}}},
     ("objects[0].shape: a shape node must have exactly one key (sphere, truncus, cylinder, cone, box, polyhedron, "
      "ellipsoid, elliptic_truncus, torus, mesh, extrude, union, intersection, difference, translate, rotate, scale, mirror, multmatrix, transform), "
      "got 2 ('sphere', 'box')")),
    ("empty-node", {"objects__0__shape": {}},
     ("objects[0].shape: a shape node must have exactly one key (sphere, truncus, cylinder, cone, box, polyhedron, "
      "ellipsoid, elliptic_truncus, torus, mesh, extrude, union, intersection, difference, translate, rotate, scale, mirror, multmatrix, transform), got none")),
    ("node-is-array", {"objects__0__shape__difference__1": [1, 2]},
     ("objects[0].shape.difference[1]: a shape node must be a table with one key (sphere, truncus, cylinder, cone, box, "
      "polyhedron, ellipsoid, elliptic_truncus, torus, mesh, extrude, union, intersection, difference, translate, rotate, scale, mirror, multmatrix, transform), "
      "got an array")),
    ("missing-shape", {"objects__0__shape": _DELETE}, "objects[0].shape: missing required field"),
    ("object-unknown-key", {"objects__0__colour": "red"},
     "objects[0]: unknown key 'colour' (expected shape, material, color, leaf_colors)"),
    ("no-objects", {"objects": []}, "objects: needs at least one object, got none"),
    ("objects-not-array", {"objects": {"shape": {}}}, "objects: must be an array, got a table"),
    ("material-negative", {"objects__0__material__kd": -0.5}, "objects[0].material.kd: must be >= 0, got -0.5"),
    ("material-unknown", {"objects__0__material__gloss": 1},
     "objects[0].material: unknown key 'gloss' (expected ambient, kd, ks, shininess)"),
    ("shininess-zero", {"objects__0__material__shininess": 0}, "objects[0].material.shininess: must be > 0, got 0"),
    ("missing-camera", {"camera": _DELETE}, "camera: missing required field"),
    ("camera-not-table", {"camera": [1, 2, 3]}, "camera: must be a table, got an array"),
    ("camera-eye-target", {"camera__target": [6, -8, 5]},
     "camera: target must differ from eye, both are (6.0, -8.0, 5.0)"),
    ("camera-fov", {"camera__fov": 200}, "camera.fov: must be <= 179, got 200"),
    ("camera-width", {"camera__width": 100000}, "camera.width: must be between 1 and 16384, got 100000"),
    ("camera-width-string", {"camera__width": "64"}, "camera.width: must be an integer, got '64'"),
    ("camera-unknown", {"camera__zoom": 2},
     "camera: unknown key 'zoom' (expected eye, target, up, fov, width, height, orthographic, height_m)"),
    ("render-contours", {"render__contours": 0}, "render.contours: must be between 1 and 4096, got 0"),
    ("render-mode", {"render__mode": "raytrace"},
     "render.mode: must be one of ('isoluminance', 'halftone'), got 'raytrace'"),
    ("render-mode-type", {"render__mode": 3}, "render.mode: must be a string, got int 3"),
    ("light-kind-missing", {"lights__0__kind": _DELETE},
     "lights[0].kind: missing required field (one of point, directional, area, polyhedron)"),
    ("light-kind-unknown", {"lights__0__kind": "spot"},
     "lights[0].kind: unknown light kind 'spot' (expected one of point, directional, area, polyhedron)"),
    ("light-unknown-key", {"lights__1__position": [0, 0, 1]},
     "lights[1]: unknown key 'position' (expected kind, direction, intensity)"),
    ("light-missing-position", {"lights__0__position": _DELETE}, "lights[0].position: missing required field"),
    ("light-intensity", {"lights__0__intensity": -1}, "lights[0].intensity: must be >= 0, got -1"),
    ("light-zero-direction", {"lights__1__direction": [0, 0, 0]},
     "lights[1].direction: must be a non-zero vector, got (0.0, 0.0, 0.0)"),
    ("lights-not-array", {"lights": {"kind": "point"}}, "lights: must be an array, got a table"),
    ("unknown-top-level", {"shadows": True}, "unknown key 'shadows' (expected camera, objects, render, lights)"),
    ("unknown-top-level-two", {"shadows": True, "fog": 1},
     "unknown keys 'shadows', 'fog' (expected camera, objects, render, lights)"),
]


@pytest.mark.parametrize("edits, message", [(e, m) for _, e, m in DOC_ERRORS], ids=[i for i, _, _ in DOC_ERRORS])
def test_scene_file_errors_name_file_and_field(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, edits: dict[str, Any], message: str) -> None:
    monkeypatch.chdir(tmp_path)
    Path("scene.json").write_text(json.dumps(_doc(**edits)))
    with pytest.raises(SceneFileError, match=f"^{re.escape('scene.json: ' + message)}$"):
        load_scene("scene.json")


def test_scene_from_dict_without_source_has_no_file_prefix() -> None:
    with pytest.raises(SceneFileError, match=f"^{re.escape('render.contours: must be between 1 and 4096, got 0')}$"):
        scene_from_dict(_doc(render__contours=0))


def test_document_must_be_a_table(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    Path("scene.json").write_text("[1, 2]")
    with pytest.raises(SceneFileError, match=re.escape("scene.json: the document must be a table, got an array")):
        load_scene("scene.json")


def test_toml_errors_carry_the_same_paths(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    Path("scene.toml").write_text(TOML_TEXT.replace("radius = 0.8", "radius = -1"))
    with pytest.raises(SceneFileError, match=re.escape("scene.toml: objects[0].shape.difference[1].sphere.radius: must be > 0, got -1")):
        load_scene("scene.toml")


@pytest.mark.parametrize(
    "old, new, message",
    [
        ("center = [1, 1, 1], radius = 0.8", "center = [nan, 1, 1], radius = 0.8",
         "objects[0].shape.difference[1].sphere.center: must be finite, got (nan, 1.0, 1.0)"),
        ("radius = 0.8", "radius = 0", "objects[0].shape.difference[1].sphere.radius: must be > 0, got 0"),
        ("r1 = 0.5, r2 = 0.25", "r1 = 0, r2 = 0.0", "objects[1].shape.intersection[0].truncus: r1 and r2 must not both be 0"),
        ("axis = [0, 1, 1], r1", "axis = [0, 0, 0], r1", "objects[1].shape.intersection[0].truncus.axis: must be a non-zero vector, got (0.0, 0.0, 0.0)"),
        ("contours = 16", "contours = 0", "render.contours: must be between 1 and 4096, got 0"),
        ("contours = 16", "contours = 10_000_000", "render.contours: must be between 1 and 4096, got 10000000"),
        ("radius = 0.8", "radius = 0.8, colour = 3", "objects[0].shape.difference[1].sphere: unknown key 'colour'"),
        ("[render]", "[render]\nshadows = true", "render: unknown key 'shadows'"),
    ],
    ids=["nan-center", "zero-radius", "truncus-radii-zero", "zero-axis", "contours-zero", "contours-absurd",
         "unknown-shape-key", "unknown-render-key"],
)
def test_toml_bad_values_name_file_and_field(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, old: str, new: str, message: str) -> None:
    monkeypatch.chdir(tmp_path)
    assert old in TOML_TEXT
    Path("scene.toml").write_text(TOML_TEXT.replace(old, new, 1))
    with pytest.raises(SceneFileError, match="^" + re.escape(f"scene.toml: {message}")):
        load_scene("scene.toml")


@pytest.mark.parametrize(
    "name, text, message",
    [
        ("scene.toml", "[camera\neye = [0, 0, 0]\n", "scene.toml: invalid TOML: "),
        ("scene.toml", "[camera]\nfov = 40 40\n", "scene.toml: invalid TOML: "),
        ("scene.json", '{"camera": {"eye": [0, 0, 0]},}', "scene.json: invalid JSON: "),
        ("scene.json", "", "scene.json: invalid JSON: "),
    ],
    ids=["toml-bracket", "toml-two-values", "json-trailing-comma", "json-empty"],
)
def test_malformed_files(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, name: str, text: str, message: str) -> None:
    monkeypatch.chdir(tmp_path)
    Path(name).write_text(text)
    # The decoder's own words follow, with the line of the fault.
    with pytest.raises(SceneFileError, match=f"^{re.escape(message)}.*line [12]"):
        load_scene(name)


def test_missing_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SceneFileError, match=f"^{re.escape('nope.toml: cannot read the file: No such file or directory')}$"):
        load_scene("nope.toml")


def test_unknown_extension(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    Path("scene.yaml").write_text("camera: {}")
    with pytest.raises(SceneFileError, match=re.escape("scene.yaml: unknown scene file extension '.yaml' (expected .toml or .json)")):
        load_scene("scene.yaml")


def test_unknown_builtin() -> None:
    with pytest.raises(SceneFileError, match=re.escape("unknown built-in scene 'nope' (expected one of demo, halftone)")):
        builtin_scene("nope")


def test_scene_file_error_is_value_error_and_isocsg_error() -> None:
    with pytest.raises(ValueError) as info:
        scene_from_dict(_doc(render__contours=0))
    assert isinstance(info.value, IsocsgError) and isinstance(info.value, SceneFileError)


def test_errors_have_no_chained_traceback() -> None:
    # Users see one clean message: the value type's own error is not chained.
    with pytest.raises(SceneFileError) as info:
        scene_from_dict(_doc(render__contours=0))
    assert info.value.__cause__ is None and info.value.__suppress_context__


@pytest.mark.parametrize(
    "light, message",
    [
        ({"kind": "area", "vertices": [[0, 0, 3], [1, 0, 3], [2, 0, 3]]}, "lights[0].vertices: are collinear: the polygon has zero area"),
        ({"kind": "area", "vertices": [[0, 0, 3], [0, 1, 3], [1, 1, 3]], "radiance": -1}, "lights[0].radiance: must be >= 0, got -1"),
        ({"kind": "area", "vertices": [[0, 0, 3], [0, 1, 3]]}, "lights[0].vertices: needs at least 3 rows, got 2"),
        ({"kind": "area", "position": [0, 0, 3]}, "lights[0]: unknown key 'position' (expected kind, vertices, radiance, flux)"),
        ({"kind": "polyhedron", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]]},
         "lights[0].vertices: are coplanar or degenerate: their hull has no volume"),
    ],
    ids=["area-collinear", "area-radiance", "area-two-vertices", "area-unknown-key", "polyhedron-flat"],
)
def test_area_and_polyhedron_light_errors(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, light: dict[str, Any], message: str) -> None:
    pytest.importorskip("isocsg.lighting.area")
    monkeypatch.chdir(tmp_path)
    doc = _doc(lights=[light])
    doc["render"]["mode"] = "halftone"
    Path("scene.json").write_text(json.dumps(doc))
    with pytest.raises(SceneFileError, match=f"^{re.escape('scene.json: ' + message)}$"):
        load_scene("scene.json")


def test_trees_built_by_a_loop_are_written_flat_and_read_back(tmp_path):
    # 5000 subtractions nest 5000 levels; the file holds one difference of 5001 operands.
    part = Box((0, 0, 0), (100, 100, 1))
    for i in range(5000):
        part = part - Sphere((i % 70 - 35.0, i // 70 - 36.0, 0.5), 0.2)
    scene = Scene(Camera((0, -5, 3), (0, 0, 0)), [PointLight((1, 2, 3))], [part])
    for ext in ("json", "toml"):
        path = tmp_path / f"loop.{ext}"
        save_scene(scene, path)
        back = load_scene(path)
        shape = back.objects[0].shape
        assert isinstance(shape, Difference) and len(shape.children) == 5001
        assert list(shape.children) == [part.program().leaves[0], *part.program().leaves[1:]]


def test_trees_that_alternate_too_deeply_are_refused_naming_the_object(tmp_path):
    part = Box((0, 0, 0), (100, 100, 1))
    for i in range(300):
        s = Sphere((i % 70 - 35.0, i // 70 - 36.0, 0.5), 0.2)
        part = part - s if i % 2 else part | s
    scene = Scene(Camera((0, -5, 3), (0, 0, 0)), [PointLight((1, 2, 3))], [Sphere((0, 0, 0), 1), part])
    with pytest.raises(SceneFileError, match=re.escape("objects[1].shape: the tree nests 301 levels deep")):
        save_scene(scene, tmp_path / "deep.json")


def test_kind_registered_after_import_is_read() -> None:
    # Regression: the reader copied the table of kinds once at import, so a kind registered
    # later by user code was an "unknown shape"; the table is now read when a file is read.
    from dataclasses import dataclass

    from isocsg.kinds import register_kind, unregister_kind
    from isocsg.scene import io as scene_io

    @dataclass(frozen=True, slots=True)
    class Ball(Sphere):
        pass

    text = """
[camera]
eye = [0.0, -4.0, 1.0]
target = [0.0, 0.0, 0.0]

[[objects]]
shape = { ball = { center = [0.0, 0.0, 0.0], radius = 1.0 } }
"""
    with pytest.raises(SceneFileError, match=re.escape("objects[0].shape: unknown shape 'ball'")):
        loads_scene(text)
    register_kind("ball", required=("center", "radius"))(Ball)
    try:
        assert "ball" in scene_io.shape_kinds() and "ball" in scene_io.SHAPE_KINDS
        shape = loads_scene(text).objects[0].shape
        assert type(shape) is Ball and shape.radius == 1.0
    finally:
        unregister_kind("ball")
    with pytest.raises(SceneFileError, match=re.escape("objects[0].shape: unknown shape 'ball'")):
        loads_scene(text)
