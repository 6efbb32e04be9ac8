"""The command line's server warms up on models that cover what people's models use.

Judge: the modules a command's child imports. After the server's warm-up
(``isocsg.cli.server_process._warm_up``, run in a process of its own, as the server runs it),
a command drawing a model with the common kinds of OpenSCAD nodes (extrusions of a polygon, a
circle and an offset square, a revolved outline, a polyhedron, an intersection, a hull, a
polygonal cylinder, a colour, a tree drawn tile by tile) must import no module of isocsg,
shapely, trimesh or scipy: each would be imported again by every command's child. And every
model of the warm-up must draw (the warm-up hides its output: a model that failed would leave
its modules cold without a word). Without numba's disk cache the warm-up draws everything
with Python and NumPy: it must compile nothing (a server started in passing spends no minute
of CPU) and leave its children to choose as a new process would.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from importlib import resources
from pathlib import Path

import pytest

from isocsg.cli import main
from isocsg.cli.server_process import _WARM_MODELS

ROOT = Path(__file__).resolve().parent.parent

#: A model unlike the warm-up's own (other numbers, other nesting), with the same kinds of nodes.
MODEL = """\
difference() {
  union() {
    linear_extrude(height = 5, center = true, convexity = 2, scale = [1, 1], $fn = 0, $fa = 12, $fs = 2) {
      polygon(points = [[0, 0], [9, 0], [9, 4], [5, 2], [0, 4]], paths = undef, convexity = 1);
    }
    multmatrix([[1, 0, 0, 20], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
      rotate_extrude(angle = 360, convexity = 2, $fn = 0, $fa = 12, $fs = 2) {
        polygon(points = [[2, 0], [4, 0], [3, 3]], paths = undef, convexity = 1);
      }
    }
    multmatrix([[0, -1, 0, 0], [1, 0, 0, 12], [0, 0, 1, 0], [0, 0, 0, 1]]) {
      linear_extrude(height = 3, center = false, convexity = 1, twist = 45, scale = [0.8, 0.8], $fn = 0, $fa = 12, $fs = 2) {
        offset(r = 1, $fn = 0, $fa = 12, $fs = 2) {
          square(size = [3, 2], center = true);
        }
      }
    }
    color([0, 0, 1, 1]) {
      multmatrix([[1, 0, 0, -10], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {
        polyhedron(points = [[0, 0, 0], [3, 0, 0], [0, 3, 0], [0, 0, 3]], faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]], convexity = 1);
      }
    }
    intersection() {
      cube(size = [4, 4, 4], center = true);
      sphere($fn = 0, $fa = 12, $fs = 2, r = 2.5);
    }
    hull() {
      cylinder($fn = 8, $fa = 12, $fs = 2, h = 2, r1 = 1, r2 = 1, center = false);
      multmatrix([[1, 0, 0, 0], [0, 1, 0, -9], [0, 0, 1, 0], [0, 0, 0, 1]]) {
        cube(size = [1, 1, 1], center = false);
      }
    }
  }
  cylinder($fn = 0, $fa = 12, $fs = 2, h = 20, r1 = 0.8, r2 = 0.8, center = true);
  multmatrix([[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cylinder($fn = 6, $fa = 12, $fs = 2, h = 20, r1 = 0.5, r2 = 0.5, center = true);
  multmatrix([[1, 0, 0, 6], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) cylinder($fn = 0, $fa = 12, $fs = 2, h = 20, r1 = 0.5, r2 = 0.5, center = true);
  multmatrix([[1, 0, 0, 20], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) sphere($fn = 0, $fa = 12, $fs = 2, r = 2);
}
"""

CHILD = """\
import os, sys
from isocsg.cli import server_process
server_process._warm_up()
before = set(sys.modules)
code = server_process._run(["render", sys.argv[1], "-o", sys.argv[2], "--no-progress"])
watched = ("isocsg", "shapely", "trimesh", "scipy", "manifold3d", "numba")
new = sorted(m for m in set(sys.modules) - before if m.split(".")[0] in watched)
print("exit", code, "new", new)
"""


@pytest.mark.parametrize("file", _WARM_MODELS)
def test_every_warm_up_model_draws(file: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    model = tmp_path / file
    model.write_bytes(resources.files("isocsg").joinpath("data", "warm", file).read_bytes())
    assert main(["render", str(model), "-o", str(tmp_path / "out.png"), "--no-progress"]) == 0
    assert capsys.readouterr().err == ""
    assert (tmp_path / "out.png").stat().st_size > 0


def test_a_command_after_the_warm_up_imports_nothing_more(tmp_path: Path) -> None:
    (tmp_path / "model.csg").write_text(MODEL)
    # Python kernels only: whether numba's cache is there or not, nothing is compiled here.
    env = {**os.environ, "ISOCSG_SERVER": "0", "ISOCSG_JIT": "python", "PYTHONPATH": str(ROOT)}
    proc = subprocess.run([sys.executable, "-c", CHILD, str(tmp_path / "model.csg"), str(tmp_path / "m.png")],
                          env=env, cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert proc.stdout.splitlines()[-1] == "exit 0 new []", proc.stdout + proc.stderr


def test_without_the_kernel_cache_the_warm_up_compiles_nothing(tmp_path: Path) -> None:
    shutil.copytree(ROOT / "isocsg", tmp_path / "isocsg", ignore=shutil.ignore_patterns("__pycache__"))
    code = ("import sys\nfrom isocsg import _jit\nfrom isocsg.cli import server_process\n"
            "compiled = server_process._warm_up()\n"
            "print(compiled, _jit.engaged(), _jit._state['spent'], 'numba' in sys.modules)\n")
    env = {**os.environ, "ISOCSG_SERVER": "0", "PYTHONPATH": str(tmp_path)}
    env.pop("ISOCSG_JIT", None)
    proc = subprocess.run([sys.executable, "-c", code], env=env, cwd=tmp_path, capture_output=True, text=True,
                          timeout=600)
    assert proc.stdout.splitlines()[-1:] == ["False False 0.0 False"], proc.stdout + proc.stderr
