"""Band meshes as the fills take them: converted arrays, quads, projection scratch.

A :class:`PreparedMesh` is a leaf's band mesh for per-pixel CSG (front and back
faces); a :class:`FrontMesh` what a union's leaf needs for its front faces only;
:class:`SurfaceRuns` a large tree's clipped surface as one mesh of consecutive
runs, one per leaf. :func:`prepare_mesh` checks and converts a builder's mesh.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from ..errors import InvalidParameterError
from ..laminae.model import BandMesh
from . import policy
from .quads import pair_quads

__all__ = ["PreparedMesh", "FrontMesh", "SurfaceRuns", "prepare_mesh", "mesh_bytes", "band_bytes"]

_QUADS_LOCK = threading.Lock()


class Projected:
    """A mesh's projection scratch: one (7, V) array per fill thread, made on first use and reused."""

    __slots__ = ()
    vertices: NDArray[np.float64]
    projs: list[NDArray[np.float64]]

    def proj(self, k: int = 0) -> NDArray[np.float64]:
        while len(self.projs) <= k:
            self.projs.append(np.empty((7, len(self.vertices))))
        return self.projs[k]


@dataclass(frozen=True, slots=True, eq=False)
class PreparedMesh(Projected):
    vertices: NDArray[np.float64]
    triangles: NDArray[np.int32]
    value_out: NDArray[np.float32]
    value_in: NDArray[np.float32]
    projs: list[NDArray[np.float64]]  # (7, V) scratch of project_kernel per fill thread, reused
    _quads: list[tuple[NDArray[np.int32], NDArray[np.float32], NDArray[np.float32]]] = field(default_factory=list)

    def quads(self) -> tuple[NDArray[np.int32], NDArray[np.float32], NDArray[np.float32]]:
        """pair_quads of the triangles and their ``value_out`` and ``value_in`` (made when first needed)."""
        if not self._quads:
            with _QUADS_LOCK:  # made once, by whichever thread asks first
                if not self._quads:
                    quads, source = pair_quads(self.vertices, self.triangles, self.value_out, self.value_in)
                    self._quads.append((quads, self.value_out[source], self.value_in[source]))
        return self._quads[0]

    @property
    def nbytes(self) -> int:
        """About the bytes held: the arrays, the quads (made or to be made: about 12 bytes per
        triangle, half as many quads as triangles at 24 bytes) and the projections made so far
        (a tiled fill projects into its own scratch; a plain fill keeps one per thread)."""
        nv, nt = len(self.vertices), len(self.triangles)
        quads = sum(a.nbytes for a in self._quads[0]) if self._quads else 12 * nt
        projs = sum(p.nbytes for p in self.projs) if self.projs else 56 * nv
        return self.vertices.nbytes + self.triangles.nbytes + 8 * nt + quads + projs

    @property
    def tiled_nbytes(self) -> int:
        """:attr:`nbytes` of a mesh filled only in screen tiles (which project into their own scratch)."""
        return self.nbytes - (0 if self.projs else 56 * len(self.vertices))


@dataclass(frozen=True, slots=True, eq=False)
class FrontMesh:
    """What the front-face fill of a union's leaf needs of its band mesh: the vertices, the
    quads and their outside values (about half the bytes of a :class:`PreparedMesh`, so that
    twice as many leaves stay cached)."""

    vertices: NDArray[np.float64]
    polys: NDArray[np.int32]
    values: NDArray[np.float32]

    @property
    def nbytes(self) -> int:
        return self.vertices.nbytes + self.polys.nbytes + self.values.nbytes


@dataclass(eq=False)
class SurfaceRuns(Projected):
    """A large tree's clipped surface as one mesh to fill: the leaves' parts' quads in
    consecutive runs, one per leaf, so a view projects and fills it in one call each."""

    vertices: NDArray[np.float64]
    polys: NDArray[np.int32]
    values: NDArray[np.float32]
    starts: NDArray[np.int64]  # run r: polys starts[r] .. starts[r + 1]
    vstarts: NDArray[np.int64]  # run r's polygons use vertices vstarts[r] .. vstarts[r + 1]
    leaves: NDArray[np.int64]  # the leaf of each run
    projs: list[NDArray[np.float64]] = field(default_factory=list)

    @classmethod
    def of(cls, parts: list[tuple[int, PreparedMesh]]) -> SurfaceRuns:
        if not parts:  # an empty result
            return cls(np.zeros((0, 3)), np.zeros((0, 4), np.int32), np.zeros(0, np.float32), np.zeros(1, np.int64),
                       np.zeros(1, np.int64), np.zeros(0, np.int64))
        nv = np.cumsum([0] + [len(p.vertices) for _, p in parts])
        quads = [p.quads() for _, p in parts]
        polys = np.vstack([np.where(q[0] >= 0, q[0] + np.int32(o), -1)
                           for q, o in zip(quads, nv[:-1])]).astype(np.int32)
        values = np.concatenate([q[1] for q in quads]).astype(np.float32)
        starts = np.cumsum([0] + [len(q[0]) for q in quads]).astype(np.int64)
        vertices = np.vstack([p.vertices for _, p in parts])
        return cls(vertices, polys, values, starts, nv.astype(np.int64), np.array([i for i, _ in parts], np.int64))

    def quads(self) -> tuple[NDArray[np.int32], NDArray[np.float32]]:
        return self.polys, self.values

    @property
    def nbytes(self) -> int:
        """The arrays and the projection scratch (made or to be made, one per fill thread)."""
        arrays = sum(a.nbytes for a in (self.vertices, self.polys, self.values, self.starts, self.vstarts, self.leaves))
        return arrays + max(len(self.projs), policy.STRIPES) * 56 * len(self.vertices)


def mesh_bytes(bands: BandMesh) -> int:
    """Bytes of a band mesh's arrays."""
    return sum(a.nbytes for a in (bands.vertices, bands.triangles, bands.value_out, bands.value_in, bands.band))


def band_bytes(bands: BandMesh) -> int:
    """Bytes of a band mesh's arrays that a prepared mesh does not share."""
    return sum(a.nbytes for a in (bands.value_out, bands.value_in, bands.band))


def prepare_mesh(bands: BandMesh) -> PreparedMesh:
    """A band mesh's arrays converted for the kernels, checked.

    Raises
    ------
    InvalidParameterError
        When the arrays' shapes disagree or a triangle indexes no vertex.
    """
    vertices = np.ascontiguousarray(bands.vertices, dtype=np.float64)
    triangles = np.ascontiguousarray(bands.triangles, dtype=np.int32)
    value_out = np.ascontiguousarray(bands.value_out, dtype=np.float32)
    value_in = np.ascontiguousarray(bands.value_in, dtype=np.float32)
    nt, nv = len(triangles), len(vertices)
    if (
        vertices.ndim != 2 or vertices.shape[1] != 3 or triangles.ndim != 2
        or triangles.shape[1] != 3 or value_out.shape != (nt,) or value_in.shape != (nt,)
        or (nt and (triangles.min() < 0 or triangles.max() >= nv))
    ):
        raise InvalidParameterError(
            f"band mesh of {nv} vertices and {nt} triangles is malformed: vertices {vertices.shape}, "
            f"triangles {triangles.shape}, value_out {value_out.shape}, value_in {value_in.shape}"
        )
    return PreparedMesh(vertices, triangles, value_out, value_in, [])
