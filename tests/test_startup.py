"""Start-up: small models drawn without numba (isocsg._jit), and the same images as with it.

Judges: the numba-compiled kernels, which the accuracy tests judge against the analytic ray
caster (tests/reference/): the kernels' Python runs (and their NumPy twins) must give the same
images bit for bit, on every kind (round ones included) and on small random trees; and,
structurally, the modules a fresh process has imported after drawing a cube, a sphere, a
cylinder or a cube minus a sphere from the command line. tests/test_twins.py compares the
twins with the compiled kernels on random input.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import isocsg
from isocsg import _jit
from isocsg.errors import InvalidParameterError
from isocsg.rendering import Renderer

ROOT = Path(__file__).resolve().parents[1]
HEAVY = ("numba", "scipy", "trimesh", "manifold3d", "shapely", "PIL", "pyvista", "matplotlib")


def _scene(shape: isocsg.Solid, size: int = 28) -> isocsg.Scene:
    camera = isocsg.Camera((2.6, -3.4, 2.2), (0, 0, 0), fov=40, width=size, height=size)
    return isocsg.Scene(camera, (isocsg.DirectionalLight((3, -2, 4)),), (isocsg.SceneObject(shape),),
                        isocsg.RenderSettings(contours=4))


def _both(scene: isocsg.Scene, plain: str = "python") -> tuple[isocsg.RenderResult, isocsg.RenderResult]:
    out = []
    for choice in ("numba", plain):
        with _jit.use(choice):
            out.append(Renderer().render(scene))
    return out[0], out[1]


def _same(compiled: isocsg.RenderResult, plain: isocsg.RenderResult) -> None:
    assert np.array_equal(compiled.image, plain.image, equal_nan=True)
    assert np.array_equal(compiled.primitive_index, plain.primitive_index)
    assert np.array_equal(compiled.depth, plain.depth, equal_nan=True)


KINDS = {
    "sphere": lambda: isocsg.Sphere((0, 0, 0), 0.9),
    "cylinder": lambda: isocsg.Cylinder((0, 0, 0), (0, 0, 1.6), 0.6),
    "cone": lambda: isocsg.Cone((0, 0, 0), (0.3, 0, 1.5), 0.8),
    "frustum": lambda: isocsg.Truncus((0, 0, 0), (0, 0, 1.2), 0.7, 0.3),
    "box": lambda: isocsg.Box((0, 0, 0), (1.2, 0.8, 1.0)),
    "polyhedron": lambda: isocsg.ConvexPolyhedron([(1, 0, -0.5), (-0.5, 0.9, -0.5), (-0.5, -0.9, -0.5), (0, 0, 1)]),
    "ellipsoid": lambda: isocsg.Ellipsoid((0, 0, 0), (1.0, 0.6, 0.4)),
    "elliptic": lambda: isocsg.EllipticTruncus((0, 0, 0), np.diag([1.0, 0.5, 1.4]), 0.6, 0.3),
    "torus": lambda: isocsg.Torus((0, 0, 0), (0.3, 0, 1), 0.8, 0.25),
    "mesh": lambda: isocsg.TriangleMesh(
        [(1, 1, 1), (-1, -1, 1), (-1, 1, -1), (1, -1, -1)], [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]),
}


@pytest.mark.parametrize("kind", list(KINDS), ids=str)
def test_every_kind_draws_the_same_without_numba(kind: str) -> None:
    _same(*_both(_scene(KINDS[kind]())))


# A new process starts in "auto": Python and NumPy runs until a large input compiles its kernel.
@pytest.mark.parametrize("kind", ("sphere", "torus"), ids=str)
def test_round_kinds_draw_the_same_when_numba_starts_midway(kind: str) -> None:
    _same(*_both(_scene(KINDS[kind]()), plain="auto"))


def test_a_csg_tree_of_flat_kinds_draws_the_same_without_numba() -> None:
    tree = isocsg.Box((0, 0, 0), (1.4, 1.4, 1.4)) - isocsg.Box((0.5, -0.5, 0.5), (1, 1, 1))
    tree = tree | isocsg.ConvexPolyhedron([(1.2, 0, 0), (0.6, 0.5, 0), (0.6, -0.5, 0), (0.9, 0, 0.8)])
    _same(*_both(_scene(tree, size=40)))


LEAVES = st.sampled_from(list(KINDS))
OFFSETS = st.tuples(*[st.floats(-0.5, 0.5)] * 3)


@st.composite
def small_trees(draw: st.DrawFn) -> isocsg.Solid:
    """Two or three leaves of random kinds, moved apart a little, under random Booleans."""
    leaves = [KINDS[draw(LEAVES)]().translate(draw(OFFSETS)) for _ in range(draw(st.integers(2, 3)))]
    tree = leaves[0]
    for leaf in leaves[1:]:
        op = draw(st.sampled_from(["|", "&", "-"]))
        tree = tree | leaf if op == "|" else tree & leaf if op == "&" else tree - leaf
    return tree


@settings(max_examples=4, deadline=None)
@given(small_trees())
def test_small_random_trees_draw_the_same_without_numba(tree: isocsg.Solid) -> None:
    _same(*_both(_scene(tree, size=20)))


@settings(max_examples=3, deadline=None)
@given(small_trees(), st.sampled_from([24, 61]))
def test_random_trees_draw_the_same_at_odd_sizes_and_with_point_lights(tree: isocsg.Solid, size: int) -> None:
    camera = isocsg.Camera((2.2, -3.1, 1.4), (0.1, 0, 0), fov=45, width=size, height=size - 3)
    lights = (isocsg.PointLight((2, -3, 3)), isocsg.DirectionalLight((-1, -2, 1)))
    scene = isocsg.Scene(camera, lights, (isocsg.SceneObject(tree),), isocsg.RenderSettings(contours=5))
    _same(*_both(scene))


def test_small_inputs_run_as_python_large_ones_compiled() -> None:
    from isocsg.bands.surface import _orient

    small = (np.zeros((3, 3)), np.zeros((3, 3)), np.zeros((1, 3), np.int64))
    large = (np.zeros((3, 3)), np.zeros((3, 3)), np.zeros((isocsg.limits.JIT_TWIN_WORK + 1, 3), np.int64))
    assert _orient.small(*small) and not _orient.small(*large)
    with pytest.raises(InvalidParameterError, match="choice"):
        with _jit.use("sometimes"):
            pass


_MODELS = """
import json, sys
from isocsg.cli import main
codes = [main(["render", model, "-o", model + ".png", "--no-progress"]) for model in sys.argv[1:]]
print(json.dumps([codes, sorted(m for m in {heavy!r} if m in sys.modules)]))
"""

# What OpenSCAD writes for cube(1); sphere(10); cylinder(h=10, r=3); a cube minus a sphere.
_CSG = {
    "cube": "group() {\n  cube(size = [1, 1, 1], center = false);\n}\n",
    "sphere": "group() {\n  sphere($fn = 0, $fa = 12, $fs = 2, r = 10);\n}\n",
    "cylinder": "group() {\n  cylinder($fn = 0, $fa = 12, $fs = 2, h = 10, r1 = 3, r2 = 3, center = false);\n}\n",
    "difference": "difference() {\n  cube(size = [10, 10, 10], center = true);\n"
                  "  sphere($fn = 0, $fa = 12, $fs = 2, r = 6.5);\n}\n",
}


@pytest.mark.parametrize("name", list(_CSG), ids=str)
def test_a_fresh_process_draws_a_small_model_without_numba(tmp_path: Path, name: str) -> None:
    model = tmp_path / f"{name}.csg"
    model.write_text(_CSG[name])
    env = {k: v for k, v in os.environ.items() if k != "ISOCSG_JIT"}
    proc = subprocess.run([sys.executable, "-c", _MODELS.format(heavy=HEAVY), str(model)],
                          capture_output=True, text=True, timeout=300, env={**env, "PYTHONPATH": str(ROOT)})
    assert proc.returncode == 0, proc.stderr
    codes, loaded = json.loads(proc.stdout.splitlines()[-1])
    assert codes == [0] and loaded == []
    assert Path(str(model) + ".png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


#: Modules a plain ``.scad`` model's command line has no use for: running ``openscad``, reading
#: scene files (``json`` too, but the script above imports it), hashing meshes, writing SVG.
_UNUSED = ("subprocess", "tempfile", "tomllib", "hashlib", "xml.etree.ElementTree")

_SCAD = {
    "cube": "cube(1);\n",
    "sphere": "sphere(10);\n",
    "cylinder": "cylinder(h=10, r=3);\n",
    "difference": "difference() { cube(10, center=true); sphere(6.5); }\n",
}


def test_a_fresh_process_reads_plain_scad_models_in_process(tmp_path: Path) -> None:
    """The same four models as ``.scad`` files: read without the ``openscad`` program (no process
    started: the plain subset, :mod:`isocsg.openscad.plain`), nor the heavy or unused modules."""
    models = []
    for name, text in _SCAD.items():
        models.append(tmp_path / f"{name}.scad")
        models[-1].write_text(text)
    env = {k: v for k, v in os.environ.items() if k != "ISOCSG_JIT"}
    # a program that is not there: were it needed, the read would fall back to it and fail
    env["ISOCSG_OPENSCAD"] = str(tmp_path / "no-such-openscad")
    proc = subprocess.run([sys.executable, "-c", _MODELS.format(heavy=HEAVY + _UNUSED), *map(str, models)],
                          capture_output=True, text=True, timeout=300, env={**env, "PYTHONPATH": str(ROOT)})
    assert proc.returncode == 0, proc.stderr
    codes, loaded = json.loads(proc.stdout.splitlines()[-1])
    assert codes == [0, 0, 0, 0] and loaded == []
    assert "PlainSubsetWarning" not in proc.stderr
