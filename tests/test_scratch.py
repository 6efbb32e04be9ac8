"""The scratch pool that lends the per-pixel CSG buffers, and renders that share it."""

from __future__ import annotations

import threading

import numpy as np

from isocsg import Camera, Cylinder, Material, PointLight, Scene, SceneObject, Sphere
from isocsg.rendering import Renderer
from isocsg.rendering.scratch import ScratchPool


def _ranges(arrays):
    return sorted((a.ctypes.data, a.ctypes.data + a.nbytes) for a in arrays)


def test_lent_arrays_have_their_shapes_do_not_overlap_and_start_at_different_page_offsets():
    pool = ScratchPool()
    specs = [((3, 50, 70), np.float64)] * 2 + [((3, 50, 70), np.float32)] * 2
    block, arrays = pool.lend(specs)
    assert [(a.shape, a.dtype) for a in arrays] == [(s, np.dtype(d)) for s, d in specs]
    assert all(a.flags.c_contiguous and a.flags.writeable for a in arrays)
    spans = _ranges(arrays)
    assert all(end <= start for (_, end), (start, _) in zip(spans, spans[1:]))
    lo, hi = block.ctypes.data, block.ctypes.data + block.nbytes
    assert all(lo <= s and e <= hi for s, e in spans)
    assert len({a.ctypes.data % 4096 for a in arrays}) == len(arrays)
    for k, a in enumerate(arrays):  # writing one leaves the others alone
        a[...] = k
    assert [float(a.min()) for a in arrays] == [float(a.max()) for a in arrays] == [0.0, 1.0, 2.0, 3.0]


def test_a_returned_block_is_lent_again_and_the_limits_hold():
    pool = ScratchPool(limit=1 << 20, keep=2)
    block, _ = pool.lend([((100, 100), np.float64)])
    pool.give_back(block)
    again, _ = pool.lend([((90, 100), np.float64)])  # smaller: fits in the same block
    assert again is block
    other, _ = pool.lend([((90, 100), np.float64)])  # the first is still out: a new one
    assert other is not block
    big, _ = pool.lend([((400, 400), np.float64)])  # over the limit once given back
    for b in (again, other, big):
        pool.give_back(b)
    assert sum(b.size for b in pool._free) <= 1 << 20 and len(pool._free) <= 2
    assert all(b is not big for b in pool._free)
    pool.clear()
    assert pool._free == []


def test_renderers_rendering_at_once_get_their_own_buffers():
    # Two threads resolve different CSG objects per pixel at the same time:
    # each image must equal the one rendered alone.
    light = (PointLight((4, -3, 5)),)
    cam = Camera((3, -3.6, 2.4), (0, 0, 0), fov=36, width=200, height=200)
    shapes = [
        Sphere((0, 0, 0), 1.0) - Cylinder((0, 0, 0), (0, 0, 3), 0.45),
        Sphere((0, 0, 0), 1.0) & Sphere((0.6, 0, 0), 0.8),
    ]
    scenes = [Scene(cam, light, [SceneObject(s, Material())]) for s in shapes]
    alone = [Renderer(csg="pixel").render(s, contours=16).image for s in scenes]
    together: list[list[np.ndarray]] = [[], []]

    def work(k: int) -> None:
        r = Renderer(csg="pixel")
        for _ in range(6):
            together[k].append(r.render(scenes[k], contours=16).image)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for k in range(2):
        assert np.isfinite(alone[k]).sum() > 5000
        for img in together[k]:
            np.testing.assert_array_equal(img, alone[k])
