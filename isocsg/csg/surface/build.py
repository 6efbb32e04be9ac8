"""Building the clipped surface: a program and its leaves' band meshes to a :class:`CSGSurface`."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from ...errors import InvalidGeometryError, InvalidParameterError, ResourceLimitError
from ...laminae.model import BandMesh
from ...limits import check_memory, memory_budget
from ..program import Program
from ..tree import CSGNode
from .booleans import run_booleans
from .closing import close_soup
from .coincident import COINCIDENT_DISTANCE
from .planning import (
    BYTES_PER_BOOLEAN_TRIANGLE,
    BYTES_PER_PLAIN_TRIANGLE,
    Piece,
    Plan,
    trim_to_box,
)
from .result import CSGSurface, assemble, empty_surface

if TYPE_CHECKING:  # pragma: no cover
    from ...lighting.lights import Light, Material


def surface_from_bands(
    program: Program, bands: Sequence[BandMesh], *, trim: bool = False, max_bytes: int | None = None
) -> CSGSurface:
    """Clip the leaves' band meshes against each other along a CSG program.

    The tree is first evaluated on the leaves' boxes (see the module
    docstring): leaves that meet no operand they are combined with are kept
    as they are, the others go through manifold3d batch Booleans in a local
    frame. The memory that needs is checked against the budget
    (:func:`isocsg.limits.check_memory`) before any Boolean starts.

    Parameters
    ----------
    program : Program
        The tree's flat program (:meth:`isocsg.csg.CSGNode.program`).
    bands : sequence of BandMesh
        One band mesh per leaf, each tiling the leaf's closed surface.
    trim : bool, default False
        Cut each leaf that matters only inside a box (subtracted from an
        operand, or an operand of an intersection) to that box before the
        Booleans, capping the cuts (:data:`TRIM_MARGIN` outside the box): the
        same solid where it counts, with fewer triangles in the Booleans (a
        hole three times longer than its plate is thick keeps 44 % of its band
        triangles at 32 contours: its ends go, the cuts through its strips add
        caps). The Booleans then run one result at a time, and a difference of
        many cuts that does not fit at once is parted into slabs of its first
        operand (:meth:`Plan.split_difference`). Leaves must be convex, as
        isocsg's primitives are. The result's triangulation may differ from an
        untrimmed build's; under slabs its surface is open along their planes
        (both sides' triangles meet there).
    max_bytes : int, optional
        A bound on the Booleans' working memory besides the budget (e.g. the
        share of it a background build may take).

    Returns
    -------
    CSGSurface
        Empty (no triangles) when the result is empty.

    Raises
    ------
    InvalidGeometryError
        If a band mesh cannot be welded into a closed manifold surface.
    InvalidParameterError
        If the program and the band meshes do not match.
    ResourceLimitError
        If the Booleans would need more than the memory budget (or ``max_bytes``).
    """
    if not isinstance(program, Program) or program.n_leaves != len(bands):
        raise InvalidParameterError(f"{program!r} does not match {len(bands)} band meshes")
    frame = _local_frame(bands)
    if frame is None:
        return empty_surface()
    present, centre, half, box_lo, box_hi = frame
    plan = Plan()
    final = program.evaluate(
        lambda i, _: [Piece(box_lo[i], box_hi[i], i)] if present[i] else [], plan.combine
    )
    if not final:
        return empty_surface()
    boolean_leaves = {x for c in final if c.ref < 0 for x in plan.leaves(c.ref)}
    plain_leaves = [c.ref for c in final if c.ref >= 0]
    # Trimmed leaves, welded in the local frame: leaf -> (vertices, triangles, source).
    trimmed: dict[int, tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]]] = {}
    if trim:
        for i in sorted(boolean_leaves & set(plan.trim) - plan.whole):
            cut = _trimmed_leaf(bands[i], plan.trim[i], centre, half)
            if cut is not None:
                trimmed[i] = cut
    size = [len(trimmed[i][1]) if i in trimmed else len(b.triangles) for i, b in enumerate(bands)]
    bound = memory_budget() if max_bytes is None else min(memory_budget(), max_bytes)
    final = _fit_budget(plan, final, size, boolean_leaves, sum(size[i] for i in plain_leaves), bound, trim,
                        lambda r: (box_lo[r], box_hi[r]))
    members = {c.ref: plan.leaves(c.ref) for c in final if c.ref < 0}
    for i in list(trimmed):
        v, t, src = trimmed.pop(i)
        v, t, s2, ok = close_soup(v, t)
        if ok:  # else the whole leaf (a cut that did not close)
            trimmed[i] = (v, t, src[s2])

    closed: dict[int, tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64], bool]] = {}

    def weld(i: int, keep: bool = True) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64], bool]:
        bm = bands[i]
        key = id(bm)  # a repeated leaf shares its band mesh: weld it once
        if key in closed:
            return closed[key] if keep else closed.pop(key)
        out = close_soup(bm.vertices, bm.triangles)  # type: ignore[arg-type]  # int32 triangles: indexing only
        if keep:
            closed[key] = out
        return out

    pieces: list[tuple[Any, ...]] = []
    for k, c in enumerate(final):
        if c.ref < 0:
            continue
        v, t, src, ok = weld(c.ref)
        if not ok:
            # Open edges left after welding: manifold3d merges nearly equal vertices
            # on them, or says the mesh is not closed.
            final[k] = plan.node("as is", [c])
            members[final[k].ref] = [c.ref]
            continue
        vout = np.asarray(bands[c.ref].value_out, np.float64)
        pieces.append((v, t, np.full(len(t), c.ref, np.int32), src, np.zeros(len(t), bool), vout[src]))
    needed = plan.needed([c.ref for c in final])
    if needed.any():
        pieces.extend(run_booleans(plan, needed, final, members, bands, weld, centre, half, trimmed,
                                   one_at_a_time=trim))
    return assemble(pieces)


def _local_frame(bands: Sequence[BandMesh]) -> tuple[NDArray[np.bool_], NDArray[np.float64], float,
                                                     NDArray[np.float64], NDArray[np.float64]] | None:
    """The local frame of the Booleans: the leaves' box mapped to [-1, 1]^3 (manifold3d's
    tolerances are relative to its meshes' size and distance from the origin).

    Returns which leaves have triangles, the frame's centre and half-size, and each leaf's box
    in it (padded by :data:`COINCIDENT_DISTANCE`: boxes that nearly touch meet, their faces
    may coincide); None when no leaf has a triangle.
    """
    n = len(bands)
    raw_lo = np.full((n, 3), np.inf)
    raw_hi = np.full((n, 3), -np.inf)
    for i, bm in enumerate(bands):
        if len(bm.triangles):
            v = np.asarray(bm.vertices, np.float64).reshape(-1, 3)
            raw_lo[i], raw_hi[i] = v.min(axis=0), v.max(axis=0)
    present = np.isfinite(raw_lo[:, 0])
    if not present.any():
        return None
    glo, ghi = raw_lo[present].min(axis=0), raw_hi[present].max(axis=0)
    centre = (glo + ghi) / 2
    half = float((ghi - glo).max()) / 2
    half = half if half > 0 else 1.0
    pad = COINCIDENT_DISTANCE
    return present, centre, half, (raw_lo - centre) / half - pad, (raw_hi - centre) / half + pad


def _trimmed_leaf(
    bm: BandMesh, box: tuple[NDArray[np.float64], NDArray[np.float64]], centre: NDArray[np.float64], half: float
) -> tuple[NDArray[np.float64], NDArray[np.int64], NDArray[np.int64]] | None:
    """A leaf's band mesh in the local frame cut to its box (:func:`trim_to_box`), not yet
    welded (that waits until the budget is known to allow it); None when the box cut nothing.

    Kept whenever the box cut something away, even with as many triangles left or more: a
    leaf's parts that no view can show may come uncut (``build_bands(hidden=...)``), and cut
    away they make the same trimmed mesh as its fully cut bands would.
    """
    v, t, src = trim_to_box((np.asarray(bm.vertices, np.float64) - centre) / half,
                            np.asarray(bm.triangles, np.int64), box[0], box[1])
    if len(t) != len(bm.triangles) or not np.array_equal(src, np.arange(len(t))):
        return v, t, src
    return None


def _fit_budget(
    plan: Plan, final: list[Piece], size: list[int], boolean_leaves: set[int], n_plain: int, bound: int,
    trim: bool, leaf_box: Callable[[int], Any],
) -> list[Piece]:
    """Check the Booleans' working memory against the budget before any starts.

    Trimmed builds run their Booleans one result at a time (what one holds is released
    before the next), so a difference of many cuts is parted into slabs that each fit
    (:meth:`Plan.split_difference`); returns the pieces of the result, slabs parted.

    Raises
    ------
    ResourceLimitError
        If the Booleans would need more than ``bound`` bytes (or the memory budget).
    """
    n_bool = sum(size[i] for i in boolean_leaves)
    if trim:
        most = max(1, (bound - (n_bool + n_plain) * BYTES_PER_PLAIN_TRIANGLE) // BYTES_PER_BOOLEAN_TRIANGLE)
        counts: dict[int, int] = {}

        def count(ref: int) -> int:
            if ref not in counts:
                counts[ref] = size[ref] if ref >= 0 else sum(size[x] for x in plan.leaves(ref))
            return counts[ref]

        final = [p for c in final for p in (plan.split_difference(c, count, int(most), leaf_box)
                                            if c.ref < 0 else [c])]
        largest = max([sum(size[x] for x in plan.leaves(c.ref)) for c in final if c.ref < 0], default=0)
        what = (f"the clipped CSG surface ({n_bool} band triangles in Booleans, at most {largest} at a time, "
                f"{n_plain} kept as they are)")
        need = largest * BYTES_PER_BOOLEAN_TRIANGLE + (n_bool + n_plain) * BYTES_PER_PLAIN_TRIANGLE
    else:
        what = f"the clipped CSG surface ({n_bool} band triangles in Booleans, {n_plain} kept as they are)"
        need = n_bool * BYTES_PER_BOOLEAN_TRIANGLE + n_plain * BYTES_PER_PLAIN_TRIANGLE
    check_memory(what, need)
    if need > bound:
        raise ResourceLimitError(f"{what} needs about {need / 1e9:.2f} GB, over the {bound / 1e9:.2f} GB allowed")
    return final


def csg_surface(
    tree: CSGNode, lights: Sequence[Light], material: Material | None = None, contours: int = 64
) -> CSGSurface:
    """The view-independent band surface of a CSG tree.

    Parameters
    ----------
    tree : CSGNode
    lights : sequence of PointLight or DirectionalLight
    material : Material, optional
        Defaults to ``Material()``. A specular material depends on the eye:
        use :class:`isocsg.rendering.Renderer`, which passes it.
    contours : int, default 64

    Returns
    -------
    CSGSurface

    Examples
    --------
    >>> from isocsg import PointLight, Sphere
    >>> surf = csg_surface(Sphere((0, 0, 0), 1) - Sphere((1, 0, 0), 1), [PointLight((0, -4, 3))], contours=8)
    >>> sorted(set(surf.leaf.tolist())), bool(surf.reversed[surf.leaf == 1].all())
    ([0, 1], True)
    """
    # The laminae import the CSG package: import on use.
    from ...laminae import build_laminae
    from ...lighting.lights import Material

    if not isinstance(tree, CSGNode):
        raise InvalidGeometryError(f"tree must be a CSG node, got {type(tree).__name__}")
    program = tree.program()
    leaves = program.leaves
    mat = Material() if material is None else material
    bands = [build_laminae(p, tuple(lights), mat, contours).bands for p in leaves]
    return surface_from_bands(program, bands)
