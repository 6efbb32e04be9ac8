"""The state of one render pass, handed to each path instead of long argument lists.

A :class:`RenderPass` holds what every object of a render shares: the camera
and its projection, the lights, the image buffers (depth key, value, label)
with what must still be reset and what was written, the progress reports and
where band meshes come from. A :class:`CSGObject` holds one CSG object of the
pass as the paths (union, per pixel, tiled) take it, all of it known before any
band is built.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol

import numpy as np
from numpy.typing import NDArray

from ..camera import Camera
from ..csg.program import OP_LEAF, OP_UNION, Program
from ..kinds import Primitive
from ..laminae.model import BandMesh
from .buffers import Rows, reset_rects
from .detail import LeafDetail, TreeDetail
from .meshes import FrontMesh, PreparedMesh
from .projection import camera_affine
from .tiles import LeafGeometry, combine_rects, leaf_geometry, leaf_rects

__all__ = ["RenderPass", "CSGObject", "MeshSource", "Progress", "Rect", "screen_rect", "is_union"]

Rect = tuple[int, int, int, int]  # (col0, row0, col1, row1), half-open
#: A leaf's band mesh as the builder gave it, and whether it depends on the view.
Built = tuple[BandMesh, bool]


class MeshSource(Protocol):
    """Where a pass gets its leaves' meshes (the :class:`~isocsg.rendering.Renderer` and its caches)."""

    def leaf_mesh(
        self, primitive: Primitive, lights: Sequence[Any], material: Any, detail: LeafDetail, eye: Any,
        built: Built | None = None, *, tiled: bool = False, hidden: Any = None,
    ) -> tuple[PreparedMesh, bool]: ...

    def front_mesh(
        self, primitive: Primitive, lights: Sequence[Any], material: Any, detail: LeafDetail, eye: Any,
        hidden: Any = None,
    ) -> FrontMesh: ...


class Progress:
    """``progress(done, total)`` calls, at most about 200 per render and always the last."""

    def __init__(self, callback: Callable[[int, int], None] | None, total: int) -> None:
        self.callback = callback
        self.total = total
        self.done = 0
        self._step = max(1, total // 200)
        self._last = -1

    def add(self, k: int) -> None:
        """``k`` more primitives done."""
        self.done += k
        if self.callback is not None and k and (self.done - self._last >= self._step or self.done >= self.total):
            self._last = self.done
            self.callback(self.done, self.total)

    def finish(self) -> None:
        """The last call, ``progress(total, total)``, unless it was made."""
        if self.callback is not None and self._last < self.total:
            self._last = self.total
            self.callback(self.total, self.total)


@dataclass(eq=False)
class RenderPass:
    """One render's shared state.

    Attributes
    ----------
    cam : Camera
    lights : tuple
        The scene's lights.
    meshes : MeshSource
        Where band meshes come from.
    zkey, value, gid : ndarray, shape (H, W)
        The image buffers: depth key (float64), value (float32, the image) and label (int32).
    report : Progress
    resets : list
        (buffer, rectangle, background) still to reset before anything is resolved into the
        buffers (empty once done).
    dirty : list of int
        Rows ``[dirty[0], dirty[1])`` and columns ``[dirty[2], dirty[3])`` written so far.
    """

    cam: Camera
    lights: tuple[Any, ...]
    meshes: MeshSource
    zkey: NDArray[np.float64]
    value: NDArray[np.float32]
    gid: NDArray[np.int32]
    report: Progress
    resets: list[tuple[NDArray[Any], Rows, Any]]
    dirty: list[int] = field(default_factory=list)
    persp: bool = field(init=False)
    a: NDArray[np.float64] = field(init=False)
    b: NDArray[np.float64] = field(init=False)
    eye: NDArray[np.float64] = field(init=False)

    def __post_init__(self) -> None:
        self.persp = not self.cam.orthographic
        self.a, self.b = camera_affine(self.cam)
        self.eye = self.cam.eye_array
        H, W = self.zkey.shape
        self.dirty = [H, 0, W, 0]

    def reset_now(self) -> None:
        """Reset the buffers to their background (once): before an object is resolved into them."""
        if self.resets:
            reset_rects(self.resets)
            self.resets = []

    def grow(self, rows: Sequence[int]) -> None:
        """Record that rows ``rows[0] .. rows[1]``, columns ``rows[2] .. rows[3]`` were written."""
        d = self.dirty
        if rows[0] < rows[1] and rows[2] < rows[3]:
            d[:] = [min(d[0], rows[0]), max(d[1], rows[1]), min(d[2], rows[2]), max(d[3], rows[3])]


@dataclass(eq=False)
class CSGObject:
    """One CSG object of a pass, as its path takes it.

    Attributes
    ----------
    leaves : sequence of Primitive
        The leaves to build (cut to where they can be seen under the level of detail).
    program : Program
    material : Material
    detail : TreeDetail
        Each leaf's contours and tessellation.
    geom : LeafGeometry
        The leaves' boxes.
    rects : ndarray of int64, shape (n, 4)
        Each leaf's screen rectangle (col0, row0, col1, row1).
    rect : Rect
        The object's screen rectangle.
    nears : ndarray, shape (n,)
        Each leaf's near plane.
    base : int
        The label of leaf 0 (leaf ``i`` is ``base + i``).
    hidden : optional
        The box outside which nothing of the object shows (for the default builder).
    built : list, optional
        The leaves' band meshes when obtained already.
    by_rays : ndarray of bool, shape (n,), optional
        Leaves drawn by exact rays instead of bands (:mod:`~isocsg.rendering.small_leaves`).
    """

    leaves: Sequence[Primitive]
    program: Program
    material: Any
    detail: TreeDetail
    geom: LeafGeometry
    rects: NDArray[np.int64]
    rect: Rect
    nears: NDArray[np.float64]
    base: int
    hidden: Any = None
    built: list[Built] | None = None
    by_rays: NDArray[np.bool_] | None = None

    @property
    def rows(self) -> Rows:
        """The object's rectangle as (row0, row1, col0, col1)."""
        return (self.rect[1], self.rect[3], self.rect[0], self.rect[2])


def screen_rect(program: Program, cam: Camera) -> Rect:
    """A pixel rectangle holding the projection of a solid, known before its bands exist.

    A primitive's rectangle bounds the projection of its bounding box (the
    hull of the corners' projections) and, for a sphere, of the sphere itself
    (exact, from the tangents in the camera's two vertical planes); a union
    takes the hull of its operands', an intersection their overlap, a
    difference its first operand's. The whole image when anything reaches
    behind its near plane (:func:`isocsg.rendering.tiles.leaf_rects`).
    """
    rects, _, _ = leaf_rects(leaf_geometry(program.leaves), cam)
    return tuple(int(x) for x in combine_rects(program.op, program.arg, rects))  # type: ignore[return-value]


def is_union(program: Program) -> bool:
    """Whether a program is a union of leaves (flattened, so one union instruction at most)."""
    return bool(np.all((program.op == OP_LEAF) | (program.op == OP_UNION)))
