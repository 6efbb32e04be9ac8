"""OpenSCAD corpus benchmark: load and render with isocsg beside openscad and manifold3d + pyvista.

Run from the repository root::

    python benchmarks/openscad.py            # every model of tests/data/openscad, 3 repeats
    python benchmarks/openscad.py --quick    # eight models, 1 repeat

Per model of the corpus (``tests/data/openscad/*.scad``):

- isocsg: ``openscad -o model.csg`` (the conversion, once; its time is shown
  apart), then ``load_openscad`` of the ``.csg`` (parse and lower), and the first
  render of a fresh ``Renderer`` at ``--size`` with 64 contours, the framing
  camera and light of ``isocsg render model.scad``;
- openscad: ``openscad --render -o x.stl model.scad`` at ``$fn = --segments``
  (CGAL Booleans and export; stopped after ``--timeout`` seconds);
- manifold3d + pyvista: the lowered model's leaves tessellated at ``--segments``
  and combined by manifold3d's batch Booleans (``isocsg.to_manifold``, then
  ``to_mesh``), then pyvista's
  off-screen first render of that mesh (plotter, upload, first frame).

Printed: medians over repeats and the ratios of the peers' times to isocsg's
load + render (above 1: isocsg is faster). The numba kernels are compiled, and
the OpenGL context made, before anything is timed.
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent / "tests"))

from _common import fmt_seconds, print_table  # noqa: E402

CORPUS_DIR = HERE.parent / "tests" / "data" / "openscad"
QUICK = ("cube_centered", "three_bores", "logo", "extrude_2d_difference", "extrude_star", "plate_with_holes",
         "module_posts", "rotate_cube")


def _timed(fn):
    t0 = time.perf_counter()
    out = fn()
    return time.perf_counter() - t0, out


def _median(times: list[float]) -> float | None:
    return statistics.median(times) if times else None


def _ratio(peer: float | None, ours: float | None) -> str:
    if peer is None or not ours:
        return "-"
    return f"{peer / ours:.2f}x"


def isocsg_times(name: str, size: int, repeats: int, tmp: Path) -> dict[str, float | None]:
    from isocsg import load_openscad
    from isocsg.openscad import scad_to_csg
    from isocsg.rendering import Renderer
    from isocsg.scene.framing import framed_scene

    csg = tmp / f"{name}.csg"
    t_convert, text = _timed(lambda: scad_to_csg(CORPUS_DIR / f"{name}.scad"))
    csg.write_text(text)
    loads, renders = [], []
    for _ in range(repeats):
        t_load, solid = _timed(lambda: load_openscad(csg))
        scene = framed_scene(solid, width=size, height=size, contours=64)
        t_render, _ = _timed(lambda: Renderer().render(scene))
        loads.append(t_load)
        renders.append(t_render)
    return {"convert": t_convert, "load": _median(loads), "render": _median(renders), "solid": solid}  # type: ignore[dict-item]


def openscad_time(name: str, segments: int, repeats: int, timeout: float, tmp: Path) -> float | None:
    times = []
    for _ in range(repeats):
        out = tmp / f"{name}.stl"
        t0 = time.perf_counter()
        try:
            subprocess.run(["openscad", "--render", "-o", str(out), "-D", f"$fn={segments}",
                            str(CORPUS_DIR / f"{name}.scad")],
                           capture_output=True, timeout=timeout, check=True, stdin=subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            return None
        times.append(time.perf_counter() - t0)
    return _median(times)


def peer_times(solid, segments: int, size: int, repeats: int) -> tuple[float | None, float | None]:
    import numpy as np

    from isocsg import to_manifold
    from isocsg.scene.framing import framed_scene

    booleans, firsts = [], []
    mesh = None
    for _ in range(repeats):
        t, mesh = _timed(lambda: to_manifold(solid, segments).to_mesh())
        booleans.append(t)
    try:
        import pyvista as pv

        cam = framed_scene(solid, width=size, height=size).camera
        for _ in range(repeats):
            def first():
                verts = np.asarray(mesh.vert_properties, dtype=np.float64)[:, :3]
                tris = np.asarray(mesh.tri_verts, dtype=np.int64)
                pl = pv.Plotter(off_screen=True, window_size=(size, size), lighting="none")
                pl.add_mesh(pv.PolyData.from_regular_faces(verts, tris), color="white", smooth_shading=True,
                            split_sharp_edges=True)
                pl.add_light(pv.Light(position=(1, -1, 1), light_type="scene light"))
                pl.camera.position, pl.camera.focal_point, pl.camera.up = cam.eye, cam.target, cam.up
                pl.camera.view_angle = cam.fov
                pl.reset_camera_clipping_range()
                pl.screenshot(return_img=True)
                pl.close()

            firsts.append(_timed(first)[0])
    except Exception as exc:  # noqa: BLE001 - report why pyvista could not render
        print(f"pyvista unavailable: {type(exc).__name__}: {exc}"[:200], file=sys.stderr)
    return _median(booleans), _median(firsts)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="eight models, one repeat")
    ap.add_argument("--repeats", type=int, default=None)
    ap.add_argument("--size", type=int, default=512, help="image side in pixels (default 512)")
    ap.add_argument("--segments", type=int, default=64, help="$fn of openscad and segments of the peer meshes")
    ap.add_argument("--timeout", type=float, default=120.0, help="seconds one openscad --render may take")
    ap.add_argument("--models", nargs="*", help="corpus model names (default: all, or the quick set)")
    args = ap.parse_args(argv)
    if shutil.which("openscad") is None:
        print("openscad is not installed (apt install openscad)", file=sys.stderr)
        return 1
    repeats = args.repeats or (1 if args.quick else 3)
    names = args.models or (list(QUICK) if args.quick else sorted(p.stem for p in CORPUS_DIR.glob("*.scad")))

    # Compile the kernels and make the OpenGL context before timing anything.
    with tempfile.TemporaryDirectory() as tmp:
        isocsg_times("cube_centered", 32, 1, Path(tmp))
        try:
            import pyvista as pv

            pl = pv.Plotter(off_screen=True, window_size=(16, 16))
            pl.add_mesh(pv.Sphere())
            pl.screenshot(return_img=True)
            pl.close()
        except Exception:  # noqa: BLE001
            pass

    rows = []
    ratios_os, ratios_m3 = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            try:
                ours = isocsg_times(name, args.size, repeats, Path(tmp))
            except Exception as exc:  # noqa: BLE001 - a model isocsg refuses is listed, not fatal
                rows.append([name, f"refused: {type(exc).__name__}", "", "", "", "", "", "", ""])
                continue
            total = (ours["load"] or 0.0) + (ours["render"] or 0.0)
            t_os = openscad_time(name, args.segments, repeats, args.timeout, Path(tmp))
            t_bool, t_pv = peer_times(ours["solid"], args.segments, args.size, repeats)
            peer = None if t_bool is None or t_pv is None else t_bool + t_pv
            if t_os is not None:
                ratios_os.append(t_os / total)
            if peer is not None:
                ratios_m3.append(peer / total)
            rows.append([
                name, fmt_seconds(ours["convert"]), fmt_seconds(ours["load"]), fmt_seconds(ours["render"]),
                fmt_seconds(t_os) if t_os is not None else f"> {args.timeout:g} s", _ratio(t_os, total),
                f"{fmt_seconds(t_bool)} + {fmt_seconds(t_pv)}", _ratio(peer, total),
            ])
    print_table(
        f"OpenSCAD corpus, {args.size} x {args.size}, 64 contours, peers at {args.segments} segments, "
        f"medians of {repeats}",
        ["model", "openscad -o .csg", "isocsg load", "isocsg render", "openscad --render .stl", "ratio",
         "manifold3d + pyvista first", "ratio"],
        rows,
    )
    if ratios_os:
        print(f"median ratio openscad --render / isocsg load + render: {statistics.median(ratios_os):.2f}x "
              f"over {len(ratios_os)} models (timeouts left out)")
    if ratios_m3:
        print(f"median ratio manifold3d + pyvista / isocsg load + render: {statistics.median(ratios_m3):.2f}x "
              f"over {len(ratios_m3)} models")
    return 0


if __name__ == "__main__":
    sys.exit(main())
