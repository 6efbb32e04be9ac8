"""Isoluminance rendering speed: the seed's tables revisited.

Run from the repository root::

    python benchmarks/render.py            # all sizes, 7 repeats
    python benchmarks/render.py --quick    # fewer repeats (a smoke run)

For a sphere and a cone at the seed's image areas (550, 4500, 9000, 55000 and
250000 pixels, square images) and at 1024 x 1024, with 64 contours and one
point light, the same run measures:

- isocsg: time to build the laminae (caches cleared), time to display them
  (band fill from a new viewpoint, laminae cached), pixels per second of the
  first render (build + display) and of a re-render;
- an exact per-pixel ray caster in numpy with Lambert shading (written here);
- Gouraud shading of triangle meshes by pyvista/VTK off screen (the seed's
  70-facet sphere and 15-facet cone, and 256-segment meshes): re-render after
  a camera move plus screenshot; skipped with the reason printed when no
  OpenGL context can be made;
- writing every pixel of the frame once (``frame[:] = value``, float32).

Medians over repeats; tables and ratios are printed, then the targets:
re-rendering a 1024^2 sphere (64 contours, laminae cached) >= 10x faster than
the numpy ray caster and no slower than pyvista re-rendering the 256-segment
mesh; the fill within 20x of the frame-write time.
"""

from __future__ import annotations

import argparse
import math
import os
import sys
from pathlib import Path

os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402
from _common import fmt_rate, fmt_seconds, median_time, print_table  # noqa: E402

from isocsg import Camera, Cone, Material, PointLight, Scene, Sphere  # noqa: E402

AREAS = (550, 4500, 9000, 55000, 250000, 1024 * 1024)
CONTOURS = 64
LIGHTS = (PointLight((5.0, -6.0, 8.0)),)
MATERIAL = Material()
SHAPES = {
    "sphere": Sphere((0.0, 0.0, 0.0), 1.0),
    "cone": Cone((0.0, 0.0, 0.0), (0.0, 0.0, 2.0), 1.0),
}
DISTANCE = 6.0
FOV = 30.0


def camera(side: int, angle_deg: float = 0.0) -> Camera:
    """The view of the tables; ``angle_deg`` turns the eye about the vertical axis (a new viewpoint)."""
    a = math.radians(-60.0 + angle_deg)
    eye = (DISTANCE * math.cos(a), DISTANCE * math.sin(a), 2.0)
    return Camera(eye, (0.0, 0.0, 0.0), fov=FOV, width=side, height=side)


# --------------------------------------------------------------- ray caster
def raycast(shape, cam: Camera) -> np.ndarray:
    """Exact image: analytic ray hits, the conventions' Lambert shading at each pixel (numpy)."""
    o = cam.ray_origins().reshape(-1, 3)
    d = cam.ray_directions().reshape(-1, 3)
    hits = shape.intersect_rays(o, d)
    t = np.where(hits.t_in > 0, hits.t_in, np.inf)
    ok = hits.hit & np.isfinite(t)
    p = o[ok] + t[ok, None] * d[ok]
    n = hits.n_in[ok]
    img = np.full(len(o), np.nan, np.float32)
    inten = np.full(len(p), MATERIAL.ambient)
    for light in LIGHTS:
        lv = np.asarray(light.position) - p
        lv /= np.linalg.norm(lv, axis=1, keepdims=True)
        inten += light.intensity * MATERIAL.kd * np.maximum(np.einsum("ij,ij->i", n, lv), 0.0)
    img[ok] = inten
    return img.reshape(cam.height, cam.width)


# ------------------------------------------------------------------ pyvista
def pyvista_reason() -> str | None:
    """None when pyvista can render off screen, else why not."""
    try:
        import pyvista as pv

        pl = pv.Plotter(off_screen=True, window_size=(16, 16))
        pl.add_mesh(pv.Sphere())
        pl.screenshot(return_img=True)
        pl.close()
    except Exception as exc:  # noqa: BLE001 - any failure means no OpenGL here
        return f"pyvista off-screen rendering unavailable ({type(exc).__name__}: {exc})"
    return None


def pyvista_mesh(name: str, segments: int | None):
    """The seed's 70-facet sphere / 15-facet cone (``segments=None``) or a finer mesh."""
    import pyvista as pv

    if name == "sphere":
        k = 7 if segments is None else segments
        return pv.Sphere(radius=1.0, theta_resolution=k, phi_resolution=k)
    k = 14 if segments is None else segments
    return pv.Cone(center=(0, 0, 0), direction=(0, 0, -1), height=2.0, radius=1.0, resolution=k)


def pyvista_rerender_time(mesh, side: int, repeats: int) -> float:
    """Median time of: move the camera, render, read the frame back (Gouraud shading)."""
    import pyvista as pv

    pl = pv.Plotter(off_screen=True, window_size=(side, side), lighting="none")
    pl.add_mesh(mesh, color="white", ambient=MATERIAL.ambient, diffuse=MATERIAL.kd, specular=0.0, smooth_shading=True)
    pl.add_light(pv.Light(position=LIGHTS[0].position, light_type="scene light", positional=True, cone_angle=180.0))
    state = {"k": 0}

    def frame():
        state["k"] += 1
        cam = camera(side, 5.0 * (state["k"] % 7))
        pl.camera.position, pl.camera.focal_point, pl.camera.up = cam.eye, cam.target, cam.up
        pl.camera.view_angle = cam.fov
        pl.reset_camera_clipping_range()
        pl.render()
        return pl.screenshot(return_img=True)

    t, _ = median_time(frame, repeats, warmup=2)
    pl.close()
    return t


# ------------------------------------------------------------------- isocsg
def clear_laminae_cache() -> None:
    """Empty the view-independent band caches so that the next build starts from nothing."""
    import isocsg.laminae as lam

    fn = getattr(lam, "clear_cache", None) or getattr(lam, "clear_caches", None)
    if callable(fn):
        fn()
        return
    for name, mod in list(sys.modules.items()):
        if name.startswith("isocsg.laminae"):
            for obj in list(vars(mod).values()):
                if callable(getattr(obj, "cache_clear", None)):
                    obj.cache_clear()


def isocsg_times(shape, side: int, repeats: int) -> dict[str, float]:
    """Build, first render, cached re-render and fill-only times for one shape and size."""
    from isocsg.laminae import build_laminae
    from isocsg.rendering import Renderer

    scene = Scene(camera(side), LIGHTS, [shape])
    cam0 = camera(side)

    def build():
        clear_laminae_cache()
        return build_laminae(shape, LIGHTS, MATERIAL, CONTOURS, eye=cam0.eye)

    t_build, _ = median_time(build, repeats)

    def first():
        clear_laminae_cache()
        return Renderer().render(scene, contours=CONTOURS)

    t_first, _ = median_time(first, repeats)
    r = Renderer()
    r.render(scene, contours=CONTOURS)  # bands cached
    state = {"k": 0}
    fills = []

    def again():
        state["k"] += 1
        res = r.render(scene, camera=camera(side, 5.0 * (state["k"] % 7 + 1)), contours=CONTOURS)
        fills.append(res.timings.fill)
        return res

    t_again, res = median_time(again, repeats, warmup=1)
    bands = build_laminae(shape, LIGHTS, MATERIAL, CONTOURS, eye=cam0.eye)
    n_tri = getattr(bands, "bands", bands).n_triangles
    return {
        "build": t_build, "first": t_first, "again": t_again, "fill": float(np.median(fills[1:] or fills)),
        "triangles": n_tri, "covered": int(np.isfinite(res.image).sum()),
    }


def frame_write_time(side: int, repeats: int) -> float:
    frame = np.empty((side, side), np.float32)

    def write():
        frame[:] = 0.5

    t, _ = median_time(write, max(repeats, 21), warmup=3)
    return t


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help="3 repeats instead of 7")
    args = ap.parse_args(argv)
    repeats = 3 if args.quick else 7
    reason = pyvista_reason()
    if reason:
        print(f"Gouraud columns skipped: {reason}\n")
    try:
        from isocsg.laminae import build_laminae  # noqa: F401
    except ImportError as exc:
        print(f"isocsg columns impossible: the laminae builder is unavailable ({exc})")
        return 1
    # Compile the numba kernels (cached on disk) outside the timings.
    from isocsg.rendering import Renderer

    Renderer().render(Scene(camera(16), LIGHTS, [SHAPES["sphere"]]), contours=4)

    summary: dict[str, dict[str, float]] = {}
    for name, shape in SHAPES.items():
        rows, ratio_rows = [], []
        for area in AREAS:
            side = int(round(math.sqrt(area)))
            px = side * side
            iso = isocsg_times(shape, side, repeats)
            cam = camera(side, 3.0)
            t_ray, _ = median_time(lambda: raycast(shape, cam), max(1, repeats // 2 if side >= 1024 else repeats))
            t_frame = frame_write_time(side, repeats)
            t_g_seed = t_g_256 = None
            if reason is None:
                t_g_seed = pyvista_rerender_time(pyvista_mesh(name, None), side, repeats)
                t_g_256 = pyvista_rerender_time(pyvista_mesh(name, 256), side, repeats)
            rows.append([
                f"{side}x{side}", px, iso["triangles"], fmt_seconds(iso["build"]), fmt_seconds(iso["fill"]),
                fmt_seconds(iso["first"]), fmt_seconds(iso["again"]),
                fmt_rate(px, iso["first"]), fmt_rate(px, iso["again"]),
                fmt_seconds(t_ray), fmt_seconds(t_g_seed), fmt_seconds(t_g_256), fmt_seconds(t_frame),
            ])
            ratio_rows.append([
                f"{side}x{side}", f"{t_ray / iso['again']:.1f}",
                "-" if t_g_256 is None else f"{t_g_256 / iso['again']:.2f}",
                "-" if t_g_seed is None else f"{t_g_seed / iso['again']:.2f}",
                f"{iso['first'] / iso['again']:.1f}", f"{iso['fill'] / t_frame:.1f}",
            ])
            summary[f"{name}-{side}"] = dict(iso, ray=t_ray, frame=t_frame, g256=t_g_256 or math.nan)
        print_table(
            f"{name}: {CONTOURS} contours, medians of {repeats} "
            "(display = band fill from a new viewpoint, laminae cached)",
            ["image", "pixels", "band tris", "build laminae", "display (fill)", "first render", "re-render",
             "px/s first", "px/s re-render", "numpy ray cast", "Gouraud seed mesh", "Gouraud 256", "frame write"],
            rows,
        )
        print_table(
            f"{name}: ratios (how many times the isocsg re-render is faster, and fill / frame write)",
            ["image", "ray cast / re-render", "Gouraud 256 / re-render", "Gouraud seed / re-render",
             "first / re-render", "fill / frame write"],
            ratio_rows,
        )
    s = summary["sphere-1024"]
    checks = [
        ("1024^2 sphere re-render >= 10x faster than the numpy ray caster", s["ray"] / s["again"] >= 10.0,
         f"{s['ray'] / s['again']:.1f}x"),
        ("1024^2 sphere re-render no slower than pyvista re-rendering the 256-segment mesh",
         None if math.isnan(s["g256"]) else s["again"] <= s["g256"],
         "skipped" if math.isnan(s["g256"]) else f"{fmt_seconds(s['again'])} vs {fmt_seconds(s['g256'])}"),
        ("1024^2 sphere fill within 20x of the frame-write time", s["fill"] <= 20.0 * s["frame"],
         f"{s['fill'] / s['frame']:.1f}x ({fmt_seconds(s['fill'])} vs {fmt_seconds(s['frame'])})"),
    ]
    print_table("targets", ["target", "met", "measured"],
                [[c, "-" if ok is None else ("yes" if ok else "NO"), m] for c, ok, m in checks])
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
