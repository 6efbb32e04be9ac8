"""Batch views and illuminance grids: threads and a local 2-worker Dask cluster equal the serial results."""

from __future__ import annotations

import os

import numpy as np
import pytest

from isocsg import Box, Camera, Cylinder, InvalidParameterError, PointLight, Scene, Sphere, render
from isocsg.batch import illuminance_grid, render_views, turntable
from isocsg.shadows import AreaLight
from isocsg.shadows.luxmap import LuxGrid, illuminance_map

SCENE = Scene(
    Camera((4, -3, 2.5), (0, 0, 0), width=48, height=36),
    [PointLight((3, -4, 6))],
    [Box((0, 0, 0), (2, 2, 0.4)) - Cylinder((0, 0, 0), (0, 0, 1), 0.5), Sphere((1.6, 1.2, 0.5), 0.5)],
)
LAMP = AreaLight([(-0.5, -0.5, 2.5), (-0.5, 0.5, 2.5), (0.5, 0.5, 2.5), (0.5, -0.5, 2.5)], radiance=1000.0)
OCCLUDERS = [Box((0.35, 0.25, 0.4), (0.6, 0.6, 0.8)), Sphere((-0.8, -0.6, 0.6), 0.3)]
GRID = LuxGrid.from_bounds(-2, -2, 2, 2, 0, 33, 29)


def test_turntable_keeps_distance_and_height():
    cams = turntable(SCENE.camera, 6)
    e0 = np.subtract(SCENE.camera.eye, SCENE.camera.target)
    for k, c in enumerate(cams):
        e = np.subtract(c.eye, c.target)
        assert np.hypot(*e[:2]) == pytest.approx(np.hypot(*e0[:2])) and e[2] == pytest.approx(e0[2])
        assert np.degrees(np.arctan2(e[1], e[0]) - np.arctan2(e0[1], e0[0])) % 360 == pytest.approx(60 * k, abs=1e-9)


def _serial_views(cams):
    return [render(SCENE, camera=c).image for c in cams]


def test_threaded_views_equal_serial():
    cams = turntable(SCENE.camera, 4)
    views = render_views(SCENE, cams, workers=2)
    for v, ref in zip(views, _serial_views(cams)):
        np.testing.assert_array_equal(v.image, ref)


def test_threaded_grid_equals_serial():
    serial = illuminance_map(GRID, LAMP, OCCLUDERS)
    m = illuminance_grid(GRID, LAMP, OCCLUDERS, rows_per_task=5, workers=2)
    np.testing.assert_array_equal(m.E, serial.E)
    np.testing.assert_array_equal(m.occluded, serial.occluded)


def test_dask_cluster_equals_serial() -> None:
    distributed = pytest.importorskip("distributed")
    cams = turntable(SCENE.camera, 3)
    serial_map = illuminance_map(GRID, LAMP, OCCLUDERS)
    serial_views = _serial_views(cams)
    saved = dict(os.environ)  # dask's nanny sets *_NUM_THREADS and PYTHONHASHSEED in this process
    try:
        with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                      dashboard_address=None) as cluster, distributed.Client(cluster) as client:
            m = illuminance_grid(GRID, LAMP, OCCLUDERS, rows_per_task=4, client=client)
            views = render_views(SCENE, cams, client=client)
    finally:
        os.environ.clear()
        os.environ.update(saved)
    np.testing.assert_array_equal(m.E, serial_map.E)
    for v, ref in zip(views, serial_views):
        np.testing.assert_array_equal(v.image, ref)


def test_errors():
    with pytest.raises(InvalidParameterError, match=r"cameras\[1\] must be a Camera, got str"):
        render_views(SCENE, [SCENE.camera, "top"])
    with pytest.raises(InvalidParameterError, match="rows_per_task must be"):
        illuminance_grid(GRID, LAMP, rows_per_task=0)


class _RecordingClient:
    """The part of dask.distributed.Client that the batch functions use, run in this process."""

    def __init__(self, nthreads: dict[str, int]) -> None:
        self._nthreads = nthreads
        self.tasks: list[int] = []
        self.runs: list[tuple] = []

    def scatter(self, values, broadcast=False):
        return list(values)

    def nthreads(self):
        return self._nthreads

    def run(self, fn, *args):
        self.runs.append(args)
        return {w: fn(*args) for w in self._nthreads}

    def submit(self, fn, *args, pure=True):
        self.tasks.append(len(args[2]))  # _chunk(fn, shared, chunk)
        return fn(*args)

    def gather(self, futures):
        return list(futures)


def test_a_cluster_gets_one_contiguous_run_of_views_per_worker_thread():
    cams = turntable(SCENE.camera, 5)
    client = _RecordingClient({"a": 1, "b": 1})
    views = render_views(SCENE, cams, client=client)
    assert client.tasks == [3, 2] and client.runs == [(("isoluminance", "surface"),)]
    for v, ref in zip(views, _serial_views(cams), strict=True):
        np.testing.assert_array_equal(v.image, ref)
    client = _RecordingClient({"a": 2, "b": 1})
    m = illuminance_grid(GRID, LAMP, OCCLUDERS, rows_per_task=2, client=client)
    assert client.tasks == [1] * -(-GRID.ny // 2)  # long, unequal blocks: one task each
    np.testing.assert_array_equal(m.E, illuminance_map(GRID, LAMP, OCCLUDERS).E)
