"""Timings of triangle meshes (:class:`isocsg.TriangleMesh`) beside manifold3d and pyvista.

Usage: ``python benchmarks/mesh.py [--size 512] [--repeat 3] [--faces 10000 100000]``

For a polygonal torus of about F triangles (trimesh's), at ``size x size`` pixels, medians of:

- ``build``: ``TriangleMesh(vertices, faces)`` (validation: closed, oriented, volume);
- ``rays``: :meth:`TriangleMesh.ray_intervals` of one ray per pixel (every interval of each line),
  the bounding-volume hierarchy included on the first call only (``bvh``: its build alone);
- ``render``: ``isocsg.render`` of the mesh alone, a new (slightly moved) mesh each time
  (validation, hierarchy, band surface and image: nothing cached), and of ``mesh - sphere``
  (per-pixel CSG);
- peers: manifold3d's Boolean ``mesh - sphere`` (the sphere at 96 segments) and pyvista's
  off-screen image of the mesh and of that Boolean's mesh (VTK, software OpenGL here).

The ratio columns are isocsg over the peer (manifold3d's Boolean plus pyvista's image, for the
CSG). isocsg's images are exact per pixel (the surface's own faces); pyvista rasterises them.
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")  # no X display probe

import numpy as np  # noqa: E402
from _common import fmt_seconds, median_time, print_table  # noqa: E402

import isocsg  # noqa: E402
from isocsg import Camera, DirectionalLight, Scene, Sphere, TriangleMesh  # noqa: E402


def torus(faces: int) -> tuple[np.ndarray, np.ndarray]:
    import trimesh

    minor = max(8, int(round(np.sqrt(faces / 10.0))))
    major = max(8, faces // (2 * minor))
    t = trimesh.creation.torus(2.0, 0.6, major_sections=major, minor_sections=minor)
    return np.asarray(t.vertices), np.asarray(t.faces)


def pyvista_image(vertices: np.ndarray, faces: np.ndarray, size: int, cam: Camera) -> float:
    import pyvista as pv

    mesh = pv.PolyData.from_regular_faces(vertices, faces)
    pl = pv.Plotter(off_screen=True, window_size=(size, size))
    pl.add_mesh(mesh, color="white")
    pl.camera.position, pl.camera.focal_point, pl.camera.up = cam.eye, cam.target, (0.0, 0.0, 1.0)
    pl.camera.view_angle = 40.0
    pl.screenshot(return_img=True)
    pl.close()
    return 0.0


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--size", type=int, default=512)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--faces", type=int, nargs="+", default=[10_000, 100_000])
    args = ap.parse_args()
    import manifold3d

    size = args.size
    cam = Camera(eye=(5.0, -6.0, 4.0), target=(0.0, 0.0, 0.0), width=size, height=size)
    light = DirectionalLight((0.3, -0.5, 1.0))
    ball = Sphere((1.8, -0.8, 0.3), 0.7)
    from isocsg.rendering.small_leaves import PixelRays

    rows, peers = [], []
    for f in args.faces:
        V, F = torus(f)
        t_build, mesh = median_time(lambda: TriangleMesh(V, F), args.repeat)
        from isocsg.kinds.mesh_bvh import build_bvh

        build_bvh(V, F)  # compiled once
        t_bvh, _ = median_time(lambda: build_bvh(mesh.vertices, mesh.faces), args.repeat)
        o, d = PixelRays(cam).rect(0, 0, size, size)
        mesh.ray_intervals(o[:10], d[:10])
        t_rays, iv = median_time(lambda: mesh.ray_intervals(o, d), args.repeat)
        isocsg.render(Scene(cam, [light], [TriangleMesh(V + 1e-6, F)]), contours=32)  # compiled once
        fresh = iter(range(1, 1000))  # equal meshes share cached work: each call gets a new one

        def cold(csg: bool) -> object:
            m = TriangleMesh(V + 1e-9 * next(fresh), F)
            return isocsg.render(Scene(cam, [light], [m - ball if csg else m]), contours=32)

        t_render, _ = median_time(lambda: cold(False), args.repeat)
        t_csg, _ = median_time(lambda: cold(True), args.repeat)
        sphere_m = manifold3d.Manifold.sphere(0.7, 96).translate([1.8, -0.8, 0.3])
        t_bool, cut = median_time(lambda: (mesh.to_manifold() - sphere_m).to_mesh(), args.repeat)
        pyvista_image(V, F, size, cam)
        t_pv, _ = median_time(lambda: pyvista_image(V, F, size, cam), args.repeat)
        cv, cf = np.asarray(cut.vert_properties[:, :3], np.float64), np.asarray(cut.tri_verts, np.int64)
        t_pv_cut, _ = median_time(lambda: pyvista_image(cv, cf, size, cam), args.repeat)
        rows.append([f"{len(F)}", fmt_seconds(t_build), fmt_seconds(t_bvh), fmt_seconds(t_rays),
                     f"{int(np.isfinite(iv[:, 0, 0]).sum())}", str(iv.shape[1]), fmt_seconds(t_render),
                     fmt_seconds(t_csg)])
        peers.append([f"{len(F)}", fmt_seconds(t_bool), fmt_seconds(t_pv), fmt_seconds(t_pv_cut),
                      f"{t_render / t_pv:.2f}", f"{t_csg / (t_bool + t_pv_cut):.2f}"])
    print_table(f"isocsg, {size} x {size} pixels (medians of {args.repeat})",
                ["faces", "build", "bvh", "rays", "rays hit", "most intervals", "render", "render mesh - ball"], rows)
    print_table("peers: manifold3d Boolean, pyvista off-screen image; ratios isocsg / peer",
                ["faces", "manifold3d mesh - ball", "pyvista mesh", "pyvista cut", "render / pyvista",
                 "csg / (manifold3d + pyvista)"], peers)


if __name__ == "__main__":
    main()
