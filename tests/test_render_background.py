"""A process ends as soon as its views are done, whatever is built in the background.

A process that rendered two views of a CSG tree started its clipped surface
in the background and then waited at exit for that build, which it never used
(OpenSCAD's example017: views done in 0.8 s, process ended after 29 s); a
thread still inside manifold3d at finalisation could abort the process.
Background builds now run on daemon threads, are asked to stop at exit and
stop at their next check; their Booleans run in a helper process that exit
kills (tests/test_helper_process.py). The build here is a Python function
defined in the script, which the helper cannot import: it runs in the thread.
"""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

SCRIPT = textwrap.dedent(
    """
    import sys, time
    from isocsg import Box, Camera, Cylinder, PointLight, Scene, Sphere
    from isocsg.rendering import Renderer, surfaces

    real = surfaces.surface_from_bands
    started = []

    def slow(program, bands, **kw):  # a Boolean that takes a long time
        started.append(time.perf_counter())
        time.sleep(float(sys.argv[1]))
        return real(program, bands, **kw)

    surfaces.surface_from_bands = slow
    solid = (Sphere((0, 0, 0), 1.0) - Cylinder((0, 0, 0), (0, 0, 3), 0.4)) & Box((0, 0, 0), (1.6, 1.6, 1.6))
    cam = Camera((3, -4, 2.5), (0, 0, 0), width=48, height=48)
    scene = Scene(cam, [PointLight((3, -5, 4))], [solid])
    r = Renderer()
    r.render(scene, contours=8)
    r.render(scene, camera=cam.with_view((-3.0, -4.0, 2.0)), contours=8)
    t = time.perf_counter()
    while not started and time.perf_counter() - t < 30:
        time.sleep(0.01)
    print("views done", bool(started), flush=True)
    """
)


def _run(seconds: float) -> tuple[float, subprocess.CompletedProcess[str]]:
    env = {**os.environ, "PYTHONPATH": str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", "")}
    t = time.perf_counter()
    done = subprocess.run([sys.executable, "-c", SCRIPT, str(seconds)], env=env, capture_output=True, text=True,
                          timeout=300)
    return time.perf_counter() - t, done


def test_exit_does_not_wait_for_a_background_surface():
    # A warm-up run compiles the kernels (the disk cache), so that the timed run measures the exit.
    _run(0.0)
    elapsed, done = _run(60.0)
    assert done.returncode == 0, done.stderr
    assert "views done True" in done.stdout  # the build had started when the process ended
    assert elapsed < 30.0, f"the process took {elapsed:.1f} s: it waited for the background build"


def test_background_surface_build_waits_while_another_renderer_draws(monkeypatch):
    # After one renderer has drawn two views of a large tree, its clipped surface is built in
    # the background; a new renderer's first view was about 3x slower (OpenSCAD's example024:
    # 2.4-2.9 s against 0.55-0.9 s) because the build's band work ran beside it. The build now
    # waits while any view is rendered: at most the band build in progress when the view began
    # runs beside it.
    import threading

    from isocsg import Box, Camera, Cylinder, PointLight, Scene
    from isocsg.rendering import Renderer

    plate = Box((0, 0, 0), (2.0, 2.0, 0.2))
    for i in range(100):
        plate = plate - Cylinder(((i % 10) / 5 - 0.9, (i // 10) / 5 - 0.9, 0), (0, 0, 0.5), 0.05)
    cam = Camera((2.0, -3.0, 3.0), (0, 0, 0), width=64, height=64)
    scene = Scene(cam, [PointLight((3, -5, 4))], [plate])
    calls: list[tuple[str, float]] = []
    real = Renderer._bands

    def spy(self, *a, **kw):
        name = threading.current_thread().name
        if name.startswith("isocsg-large-surface"):
            time.sleep(0.01)  # band builds of a larger model take longer
        calls.append((name, time.perf_counter()))
        return real(self, *a, **kw)

    monkeypatch.setattr(Renderer, "_bands", spy)
    first = Renderer()
    first.render(scene, contours=16)
    first.render(scene, camera=cam.with_view((-2.0, -3.0, 3.0)), contours=16)  # starts the build
    t0 = time.perf_counter()
    Renderer().render(scene, contours=16)
    t1 = time.perf_counter()
    beside = [t for name, t in calls if name.startswith("isocsg-large-surface") and t0 < t < t1]
    assert len(beside) <= 1, f"{len(beside)} band builds of the background surface ran beside the view"
    first.wait_surfaces(120)
    assert any(name.startswith("isocsg-large-surface") for name, _ in calls)  # the build did go on after it


def test_checkpoint_waits_for_the_foreground_and_raises_once_cancelled(monkeypatch):
    from isocsg import _workers

    steps: list[float] = []

    def task() -> None:
        _workers.checkpoint()
        steps.append(time.perf_counter())

    with _workers.foreground():
        fut = _workers.background("test", task)
        time.sleep(0.3)
        assert not steps  # waiting while the view is drawn
        ended = time.perf_counter()
    fut.result(10)
    assert steps and steps[0] >= ended
    monkeypatch.setattr(_workers, "_cancel", __import__("threading").Event())
    _workers._cancel.set()
    fut = _workers.background("test", task)
    try:
        fut.result(10)
    except _workers.Cancelled:
        pass
    else:
        raise AssertionError("a cancelled task went on")


def test_pools_are_made_once_and_forgotten_in_a_forked_child():
    # A forked child inherits the parent's pool objects but none of their threads: a pool
    # asked for there must be a new one that runs its work.
    import threading

    import pytest

    from isocsg import _workers

    if not hasattr(os, "fork"):
        pytest.skip("no fork on this platform")
    made: list[object] = []
    threads = [threading.Thread(target=lambda: made.append(_workers.pool("test-fork", 1))) for _ in range(8)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    pool = made[0]
    assert all(p is pool for p in made) and pool.submit(lambda: 1).result(10) == 1
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: answer through the pipe, never return into pytest
        try:
            fresh = _workers.pool("test-fork", 1)
            ok = fresh is not pool and fresh.submit(lambda: 2).result(10) == 2
        except BaseException:  # noqa: BLE001  # any failure is a failed check (the forked child must not raise)
            ok = False
        os.write(write, b"1" if ok else b"0")
        os._exit(0)
    os.waitpid(pid, 0)
    assert os.read(read, 1) == b"1"
