"""The compiled visibility kernel: its point order and its threads.

The values themselves are judged by Monte Carlo and closed forms in
``test_illuminance.py``; here: the hull's written-out sort against numpy's
stable argsorts, and values that do not depend on how the points are shared
between threads (nor on a fork of the process).
"""

from __future__ import annotations

import functools
import multiprocessing
import sys

import numpy as np
import pytest

from isocsg import Box, Sphere
from isocsg.shadows import AreaLight, PolyhedronLight, visibility
from isocsg.shadows import direct as illuminance_module
from isocsg.shadows.occluders import shadow_pieces


@pytest.mark.parametrize("n", [0, 1, 2, 3, 7, 64, 257])
def test_order_xy_is_numpys_two_stable_argsorts(n: int) -> None:
    rng = np.random.default_rng(n)
    # few distinct coordinates: many ties in x, in y and in both; signed zeros compare equal
    pts = rng.integers(-3, 4, size=(n + 5, 2)).astype(np.float64)
    pts[rng.random(pts.shape) < 0.2] = -0.0
    o1 = np.argsort(pts[:n, 1], kind="mergesort")
    expected = o1[np.argsort(pts[o1, 0], kind="mergesort")]
    assert np.array_equal(visibility._order_xy(pts, n), expected)


@functools.cache
def _scene() -> tuple[np.ndarray, list, list]:
    rng = np.random.default_rng(3)
    lamp = AreaLight([(-0.6, -0.3, 2.8), (-0.6, 0.3, 2.8), (0.6, 0.3, 2.8), (0.6, -0.3, 2.8)], 1000.0)
    cube = PolyhedronLight([(x, y, z) for x in (-0.3, 0.3) for y in (-0.3, 0.3) for z in (2.0, 2.6)], 1.5)
    # 60 short rods under the sources: points below them see more overlapping silhouettes than the kernel
    # holds (flagged for the 2D fallback), points farther out see the sources whole
    rods = [Box((x, y, 1.5), (0.05, 0.05, 0.3)) for x, y in rng.uniform((-0.35, -0.15), (0.35, 0.15), (60, 2))]
    pts = np.c_[rng.uniform(-3.0, 3.0, (800, 2)), np.zeros(800)]
    return pts, [lamp, cube], [*rods, Sphere((1.0, 0.5, 1.2), 0.3), Box((-2.0, 1.5, 0.5), (1.0, 1.0, 0.1))]


@functools.cache
def _kernel_input() -> tuple:
    """The arguments of :func:`visibility.visible_illuminance` for the scene, as illuminance_and_state makes them."""
    pts, lights, occ = _scene()
    sources = illuminance_module._sources(lights)
    scale = float(np.max(np.abs(np.vstack([pts, sources.verts]))))
    pieces = visibility.PieceArrays(shadow_pieces(occ, pts, sources.verts, scale=scale))
    return pts, np.tile([0.0, 0.0, 1.0], (len(pts), 1)), sources, pieces, scale


@pytest.mark.parametrize(("threads", "per_thread"), [(2, 1), (3, 4), (4, 8)])
def test_values_do_not_depend_on_the_threads(monkeypatch: pytest.MonkeyPatch, threads: int, per_thread: int) -> None:
    monkeypatch.setattr(visibility, "_threads", lambda: 1)
    one = visibility.visible_illuminance(*_kernel_input())
    E, state, overflow = one
    assert overflow.any() and (~overflow).any()
    assert all((state[~overflow] == k).any() for k in (0, 1, 2))
    monkeypatch.setattr(visibility, "_threads", lambda: threads)
    monkeypatch.setattr(visibility, "CHUNKS_PER_THREAD", per_thread)
    many = visibility.visible_illuminance(*_kernel_input())
    assert all(np.array_equal(a, b) for a, b in zip(one, many))


def _in_child(queue: multiprocessing.Queue) -> None:
    queue.put(visibility.visible_illuminance(*_kernel_input()))


@pytest.mark.skipif(sys.platform != "linux", reason="fork start method")
def test_a_forked_child_gets_its_own_threads(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(visibility, "_threads", lambda: 2)
    expected = visibility.visible_illuminance(*_kernel_input())  # the parent's pool exists now
    assert visibility._POOL is not None
    ctx = multiprocessing.get_context("fork")
    queue = ctx.Queue()
    child = ctx.Process(target=_in_child, args=(queue,))
    child.start()
    got = queue.get(timeout=120)
    child.join(timeout=60)
    assert child.exitcode == 0
    assert all(np.array_equal(a, b) for a, b in zip(got, expected))
