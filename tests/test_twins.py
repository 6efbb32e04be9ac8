"""The NumPy twins of the render kernels (isocsg._jit) against the compiled kernels, on random input.

Judges: the numba-compiled kernels themselves, which the accuracy tests judge against the
analytic ray caster (tests/reference/). A twin must leave every output buffer with the same
bits: random polygons in any position (crossing the near plane, off screen, seen edge-on,
overlapping, both facings), random leaf intervals for per-pixel CSG, random meshes cut at
random levels.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

import isocsg
from isocsg import _jit
from isocsg.laminae.split import split_by_levels
from isocsg.rendering.pixel_csg import resolve_packed, truth_table
from isocsg.rendering.polygons import fill_front_kernel, fill_projected
from isocsg.rendering.projection import camera_affine, near_distance, project_kernel
from isocsg.rendering.quads import pair_quads

SEEDS = st.integers(0, 2**32 - 1)


def _copies(args: tuple[Any, ...]) -> list[Any]:
    return [a.copy() if isinstance(a, np.ndarray) else a for a in args]


def _twin_and_compiled(kernel: Any, args: tuple[Any, ...]) -> tuple[list[Any], list[Any], Any, Any]:
    """Both runs on copies of ``args``: the arguments afterwards (the outputs written in place) and the results."""
    plain, compiled = _copies(args), _copies(args)
    with _jit.use("python"):
        got = kernel(*plain)
    with _jit.use("numba"):
        want = kernel(*compiled)
    return plain, compiled, got, want


def _assert_same(a: Any, b: Any) -> None:
    if isinstance(a, tuple):
        for x, y in zip(a, b, strict=True):
            _assert_same(x, y)
    elif isinstance(a, np.ndarray):
        assert a.dtype == b.dtype and a.shape == b.shape
        assert np.array_equal(a.view(np.uint8), b.view(np.uint8)), "different bits"
    else:
        assert a == b or (a != a and b != b)


def _projected(seed: int, n_vertices: int, size: tuple[int, int], eye_inside: bool) -> tuple[Any, ...]:
    """Random vertices seen by a random camera, projected (``project_kernel``'s rows) with a near plane."""
    rng = np.random.default_rng(seed)
    camera = isocsg.Camera(tuple(rng.normal(0, 3, 3) + (0, -6, 2)), (0, 0, 0), fov=float(rng.uniform(25, 70)),
                           width=size[1], height=size[0])
    spread = 6.0 if eye_inside else 1.5
    vertices = rng.normal(0, spread, (n_vertices, 3))
    a, b = camera_affine(camera)
    proj = np.empty((7, n_vertices))
    eye = np.asarray(camera.eye, float)
    with _jit.use("numba"):
        far = project_kernel(vertices, eye, a, b, True, proj, 0, n_vertices)
    return proj, near_distance(np.array([far])), vertices, eye, a, b


def _polygons(rng: np.random.Generator, n_vertices: int, count: int) -> tuple[Any, Any, Any]:
    """Random triangles and quads (the quads of neighbouring triangles, so some flat, some not)."""
    polys = rng.integers(0, n_vertices, (count, 4)).astype(np.int32)
    polys[rng.random(count) < 0.4, 3] = -1
    vout = rng.random(count).astype(np.float32)
    vin = rng.random(count).astype(np.float32)
    return polys, vout, vin


@settings(max_examples=25, deadline=None)
@given(SEEDS, st.integers(4, 60), st.integers(1, 80), st.booleans(), st.sampled_from([(17, 23), (40, 31)]))
def test_the_polygon_fill_twins_give_the_same_buffers(seed: int, nv: int, count: int, inside: bool,
                                                       size: tuple[int, int]) -> None:
    proj, near, *_ = _projected(seed, nv, size, inside)
    rng = np.random.default_rng(seed + 1)
    polys, vout, vin = _polygons(rng, nv, count)
    h, w = size
    oy, ox = int(rng.integers(-3, 4)), int(rng.integers(-3, 4))
    zf = np.where(rng.random((h, w)) < 0.3, rng.normal(-0.2, 0.1, (h, w)), np.inf)
    zb = np.full((h, w), -np.inf)
    args = (proj, polys, vout, vin, near, True, ox, oy, zf, np.zeros((h, w), np.float32), zb,
            np.zeros((h, w), np.float32))
    plain, compiled, got, want = _twin_and_compiled(fill_projected, args)
    for a, b in zip(plain[8:], compiled[8:], strict=True):
        _assert_same(a, b)
    rows = h - 2
    front = (proj, polys, vout, near, True, int(rng.integers(-1, 5)), oy, zf[:rows].copy(),
             np.zeros((rows, w), np.float32), np.full((rows, w), -7, np.int32), np.array([1 << 30, -1, 1 << 30, -1]))
    plain, compiled, got, want = _twin_and_compiled(fill_front_kernel, front)
    for a, b in zip(plain[7:], compiled[7:], strict=True):
        _assert_same(a, b)


def _csg_case(seed: int, n: int, with_table: bool) -> tuple[Any, ...]:
    """Random packed leaf buffers and a random program of ``n`` leaves (``resolve_packed``'s arguments)."""
    rng = np.random.default_rng(seed)
    h, w = 9, 11
    # A random program over n leaves: a chain of random operations.
    ops, args_ = [0], [0]
    for i in range(1, n):
        ops += [0, int(rng.integers(1, 4))]
        args_ += [i, 2]
    op, arg = np.array(ops, np.int8), np.array(args_, np.int64)
    table = truth_table(op, arg, n) if with_table else np.zeros(0, np.bool_)
    lr0, lc0 = rng.integers(0, 4, n), rng.integers(0, 4, n)
    lh, lw = rng.integers(1, h - 2, n), rng.integers(1, w - 2, n)
    sizes = lh * lw
    off = np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(np.int64)
    total = int(sizes.sum())
    # Depth keys on a coarse grid, so that coincident and touching surfaces happen.
    front = rng.integers(-8, 8, total) / 4.0
    back = front + rng.integers(0, 5, total) / 4.0
    front[rng.random(total) < 0.15] = np.inf
    back[rng.random(total) < 0.15] = -np.inf
    zkey = np.where(rng.random((h, w)) < 0.2, 0.5, np.inf)
    return (front, rng.random(total).astype(np.float32), back, rng.random(total).astype(np.float32), off,
            lr0.astype(np.int64), lc0.astype(np.int64), lh.astype(np.int64), lw.astype(np.int64),
            np.arange(n, dtype=np.int64), op, arg, table, 3, 1, h, 0, w, zkey, np.zeros((h, w), np.float32),
            np.full((h, w), -1, np.int32), np.empty(n), np.empty(n, np.int8), np.zeros(n, np.bool_),
            np.zeros(len(op), np.bool_), np.zeros(n, np.int64))


@settings(max_examples=10, deadline=None)
@given(SEEDS, st.integers(1, 5), st.booleans())
def test_the_per_pixel_csg_twin_gives_the_same_image(seed: int, n: int, with_table: bool) -> None:
    plain, compiled, *_ = _twin_and_compiled(resolve_packed, _csg_case(seed, n, with_table))
    for a, b in zip(plain[18:21], compiled[18:21], strict=True):
        _assert_same(a, b)


def _run_both(func: Callable[[], Any]) -> tuple[Any, Any]:
    with _jit.use("python"):
        got = func()
    with _jit.use("numba"):
        want = func()
    return got, want


def _uv_sphere(n: int) -> tuple[Any, Any]:
    """A closed triangle mesh of a sphere: ``n`` rings of ``2 n`` vertices and two poles."""
    theta = np.pi * np.arange(1, n + 1) / (n + 1)
    phi = np.pi * np.arange(2 * n) / n
    ring = np.stack(np.meshgrid(theta, phi, indexing="ij"), axis=-1).reshape(-1, 2)
    v = np.vstack([[0, 0, 1], np.column_stack([np.sin(ring[:, 0]) * np.cos(ring[:, 1]),
                                                np.sin(ring[:, 0]) * np.sin(ring[:, 1]), np.cos(ring[:, 0])]),
                   [0, 0, -1]])
    m = 2 * n
    tris = [(0, 1 + j, 1 + (j + 1) % m) for j in range(m)]
    for i in range(n - 1):
        for j in range(m):
            a, b = 1 + i * m + j, 1 + i * m + (j + 1) % m
            tris += [(a, a + m, b), (b, a + m, b + m)]
    last = len(v) - 1
    tris += [(last, 1 + (n - 1) * m + (j + 1) % m, 1 + (n - 1) * m + j) for j in range(m)]
    return v, np.array(tris, np.int64)


@settings(max_examples=10, deadline=None)
@given(SEEDS, st.integers(1, 6))
def test_the_band_cut_and_quad_twins_give_the_same_meshes(seed: int, n_levels: int) -> None:
    rng = np.random.default_rng(seed)
    v, t = _uv_sphere(int(rng.integers(4, 12)))
    field = np.column_stack([v @ rng.normal(size=3), rng.normal(size=len(v))])
    field[rng.random(len(v)) < 0.2, 0] = 0.5  # values on a level
    levels = np.unique(np.concatenate([[0.5], rng.normal(0, 1, n_levels)]))
    got, want = _run_both(lambda: split_by_levels(v, t, field, 0, levels))
    for name in ("vertices", "values", "triangles", "parent", "band"):
        _assert_same(getattr(got, name), getattr(want, name))
    values = np.round(rng.random(len(want.triangles)) * 2) / 2
    quads = _run_both(lambda: pair_quads(want.vertices, want.triangles, values))
    _assert_same(*quads)
