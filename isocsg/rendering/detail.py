"""Level of detail: each leaf's contour count and tessellation from its size on screen.

Large CSG trees (more than :data:`~isocsg.rendering.policy.LOD_MIN_LEAVES` leaves)
spend most of a render building bands; a leaf a few pixels across needs few
contours and a coarse tessellation. A leaf's choice is a :class:`LeafDetail`,
a tree's a :class:`TreeDetail` (one entry per leaf); :class:`LevelOfDetail`
makes them for a view and remembers what earlier views used.
"""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Hashable, Iterator, Sequence
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from ..camera import Camera
from ..csg.program import Program
from ..kinds import Primitive
from ..laminae.builder import DEFAULT_SEGMENTS
from . import policy
from .tiles import LeafGeometry, leaf_screen_sizes

__all__ = ["LeafDetail", "TreeDetail", "LevelOfDetail", "screen_contours", "screen_segments"]


class LeafDetail(NamedTuple):
    """One leaf's level of detail: its contour count and the segments around its
    tessellation (:data:`~isocsg.laminae.builder.DEFAULT_SEGMENTS`: the builder's full one).

    Examples
    --------
    >>> LeafDetail(32, 64).builder_options(), LeafDetail(64).builder_options()
    ({'segments': 64}, {})
    """

    contours: int
    segments: int = DEFAULT_SEGMENTS

    def builder_options(self) -> dict[str, int]:
        """The band builder's keywords beyond the contour count (none for the full tessellation)."""
        return {"segments": self.segments} if self.segments < DEFAULT_SEGMENTS else {}


@dataclass(frozen=True, slots=True, eq=False)
class TreeDetail:
    """The level of detail of every leaf of a tree (or of one primitive).

    Attributes
    ----------
    contours, segments : ndarray of int64, shape (n,)
        Leaf ``i``'s contour count and tessellation segments.
    sizes : ndarray of float64, shape (n,), optional
        Leaf ``i``'s size on screen in pixels (:func:`~isocsg.rendering.tiles.leaf_screen_sizes`),
        where the level of detail applies.
    """

    contours: NDArray[np.int64]
    segments: NDArray[np.int64]
    sizes: NDArray[np.float64] | None = None

    @classmethod
    def uniform(cls, n: int, contours: int) -> TreeDetail:
        """``n`` leaves at ``contours`` and the full tessellation."""
        return cls(np.full(n, contours, np.int64), np.full(n, DEFAULT_SEGMENTS, np.int64))

    def __len__(self) -> int:
        return len(self.contours)

    def __getitem__(self, i: int) -> LeafDetail:
        return LeafDetail(int(self.contours[i]), int(self.segments[i]))

    def __iter__(self) -> Iterator[LeafDetail]:
        return map(LeafDetail, self.contours.tolist(), self.segments.tolist())

    def covers(self, need: TreeDetail) -> bool:
        """Whether a large tree's surface built at this detail serves a view asking ``need``:
        every leaf has the contours asked and at least half the segments (a chord error within
        four times :data:`~isocsg.rendering.policy.CHORD_PIXELS`, 0.05 pixel), so a view that finds
        a few leaves grown on screen does not wait for a new Boolean of the whole tree."""
        return bool(np.all(self.contours >= need.contours) and np.all(2 * self.segments >= need.segments))

    def finer(self, other: TreeDetail) -> TreeDetail:
        """The finer of two details, leaf by leaf."""
        return TreeDetail(np.maximum(self.contours, other.contours), np.maximum(self.segments, other.segments))

def screen_contours(extent: NDArray[np.float64], contours: int) -> NDArray[np.int64]:
    """Contour count of each leaf from its screen size in pixels (see :data:`~isocsg.rendering.policy.LOD_PIXELS`).

    Parameters
    ----------
    extent : ndarray, shape (n,)
        The larger side of each leaf's unclipped screen rectangle in pixels
        (``inf`` for a leaf reaching behind the eye).
    contours : int
        N, the requested count.

    Returns
    -------
    ndarray of int64, shape (n,)

    Examples
    --------
    >>> screen_contours(np.array([3.0, 40.0, 64.0, 65.0, 1000.0, np.inf]), 64).tolist()
    [32, 32, 32, 64, 64, 64]
    >>> screen_contours(np.array([3.0, 40.0, 64.0, 65.0, 1000.0]), 256).tolist()
    [128, 128, 128, 256, 256]
    >>> screen_contours(np.array([3.0, 40.0, 1000.0]), 16).tolist()
    [16, 16, 16]
    >>> screen_contours(np.array([3.0, 40.0]), 8).tolist()
    [8, 8]
    """
    e = np.nan_to_num(np.asarray(extent, dtype=np.float64), nan=np.inf, posinf=np.inf)
    need = contours * e / policy.LOD_PIXELS
    half = min(contours, max(policy.MIN_CONTOURS, (contours + 1) // 2))
    return np.where(need > contours / 2, contours, half).astype(np.int64)


def screen_segments(extent: NDArray[np.float64]) -> NDArray[np.int64]:
    """Tessellation segments of each leaf from its screen size in pixels
    (see :data:`~isocsg.rendering.policy.CHORD_PIXELS`).

    Examples
    --------
    >>> screen_segments(np.array([4.0, 20.0, 60.0, 200.0, 400.0, np.inf])).tolist()
    [32, 64, 128, 128, 128, 128]
    """
    r = np.nan_to_num(np.asarray(extent, dtype=np.float64), nan=np.inf, posinf=np.inf) / 2
    with np.errstate(invalid="ignore", over="ignore"):
        m = np.pi * np.sqrt(np.maximum(r, 1.0) / (2.0 * policy.CHORD_PIXELS))  # sagitta r pi^2 / (2 m^2)
        m = np.exp2(np.ceil(np.log2(np.minimum(m, 1e6))))
    return np.clip(m, policy.MIN_SEGMENTS, DEFAULT_SEGMENTS).astype(np.int64)


class LevelOfDetail:
    """A renderer's level of detail: :meth:`tree` gives each leaf of a view its :class:`LeafDetail`.

    Parameters
    ----------
    adaptive : bool
        ``Renderer(adaptive_contours=...)``; without it every leaf gets the
        requested count and the full tessellation.
    tessellate : bool
        Whether the builder takes a tessellation (the default builder does).
    """

    def __init__(self, adaptive: bool, tessellate: bool) -> None:
        self.adaptive = bool(adaptive)
        self.tessellate = bool(tessellate)
        # (leaf, lights, material, N) -> the detail its last view used under the level of
        # detail (below N only): a later view needing less reuses those bands.
        self._used: OrderedDict[Hashable, tuple[int, int]] = OrderedDict()

    def applies(self, program: Program | None) -> bool:
        """Whether the level of detail applies to an object (a tree of more than
        :data:`~isocsg.rendering.policy.LOD_MIN_LEAVES` leaves, when adaptive)."""
        return self.adaptive and program is not None and program.n_leaves > policy.LOD_MIN_LEAVES

    def tree(
        self, leaves: Sequence[Primitive], lights: Any, material: Any, geom: LeafGeometry, cam: Camera,
        program: Program | None, contours: int,
    ) -> TreeDetail:
        """Each leaf's detail: :func:`screen_contours` of its size on screen (its box cut to
        the object's, :func:`~isocsg.rendering.tiles.leaf_screen_sizes`), or more when an earlier
        view used more (up to ``contours``): those bands are likely still cached, and a leaf
        that shrank on screen is only more accurate with them than it needs to be."""
        if program is None or not self.applies(program):
            return TreeDetail.uniform(len(leaves), contours)
        box = program.bounds(geom.lo, geom.hi)
        # A truncus's diameter caps its size (holes, rods), alone or in a tree alike, so that
        # a primitive and a tree of it (A | A) get the same bands.
        sizes = leaf_screen_sizes(geom, cam, *box)
        counts = screen_contours(sizes, contours)
        segs = screen_segments(sizes) if self.tessellate else np.full(len(leaves), DEFAULT_SEGMENTS, np.int64)
        out, seg = counts.tolist(), segs.tolist()
        used = self._used
        for i, leaf in enumerate(leaves):
            key = (leaf, lights, material, contours)
            before = used.get(key)
            if before is not None:
                out[i], seg[i] = max(out[i], before[0]), max(seg[i], before[1])
            if before != (out[i], seg[i]):
                used[key] = (out[i], seg[i])
        while len(used) > policy.LOD_MEMORY:
            used.popitem(last=False)
        return TreeDetail(np.asarray(out, np.int64), np.minimum(np.asarray(seg, np.int64), DEFAULT_SEGMENTS), sizes)

    def clear(self) -> None:
        """Forget what earlier views used."""
        self._used.clear()
