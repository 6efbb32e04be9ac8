"""Exact illuminance and shadow states from area and polyhedron sources with occluders.

The illuminance at p (unit normal n) is Lambert's contour integral over the
part of each source visible from p (:mod:`isocsg.shadows.visibility`):

- an :class:`~isocsg.lighting.area.AreaLight` lights only its lit side;
  the part behind p's receiving plane is cut away first (type-B receivers);
- a :class:`~isocsg.lighting.area.PolyhedronLight` is the sum of its faces
  that face p (each a one-sided polygon): their shared edges cancel, which is
  the seed's contour-line integral; occluders are handled face by face;
- a :class:`~isocsg.lighting.luminaire.PhotometricLight` (a point luminaire
  with a measured intensity distribution) gives the inverse-square and cosine
  law with hard shadows (:mod:`isocsg.shadows.pointsource`): state 0 or 2;
- several lights add up.

Shadow state of a point, per light (the conventions: 0 lit when the source is
fully visible, 1 penumbra when partly, 2 umbra when not at all): 0 when the
part of the source in front of the receiving plane is fully visible, 1 when
partly, 2 when none of it is. A point that has *nothing* of a source in front
of its receiving plane (its plane cuts the whole source away: a face turned
away from the light, the seed's type C, or a point behind an area source or
in its plane) receives none of the source: state 2 for that light, and
illuminance 0 from it. Over several lights the state is the worst (largest)
one. Umbra means a visible area below ``1e-9`` of the source part in front of
the plane.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, Protocol

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import normalize_rows, points_array
from ..errors import InvalidLightError, InvalidParameterError
from ..kinds import DEFAULT_RESOLUTION, Solid
from ..lighting.area import AreaLight, PolyhedronLight, as_light_list
from ..lighting.lights import PointLight
from ..lighting.luminaire import PhotometricLight
from .lambert import _prepare, edge_terms
from .occluders import ConvexPiece, occluder_list, shadow_pieces
from .tiles import bounding_box, class_indices, classify_receivers, lit_illuminance
from .visibility import UMBRA_TOL, PieceArrays, SourceArrays, blockers_single, visible_illuminance


class IndirectLight(Protocol):
    """What ``illuminance(..., interreflections=)`` needs: :class:`~isocsg.shadows.radiosity.Interreflections`."""

    def indirect_illuminance(
        self, points: NDArray[np.float64], normals: NDArray[np.float64],
        lights: Sequence[AreaLight | PolyhedronLight | PhotometricLight], occluders: Sequence[Solid], *,
        resolution: int,
    ) -> NDArray[np.float64]: ...


__all__ = ["illuminance", "shadow_state", "illuminance_and_state", "receiver_tiles", "LIT", "PENUMBRA", "UMBRA"]

LIT = 0
PENUMBRA = 1
UMBRA = 2

FEW_PIECES = 32  # up to this many pieces every receiver sees them all
CHUNK_POINTS = 1 << 20  # receivers evaluated together (bounds the memory beyond the results)
TILE_POINTS = 2500  # otherwise receivers per group that gets its own occluder pieces
MAX_TILES = 16


def _sources(lights: list[AreaLight | PolyhedronLight]) -> SourceArrays:
    polys, rads, groups = [], [], []
    for g, light in enumerate(lights):
        for q in light.emitting_polygons():
            polys.append(np.asarray(q, dtype=np.float64))
            rads.append(light.radiance)
            groups.append(g)
    return SourceArrays(polys, rads, groups)


class _Normals:
    """The receivers' normals, one for all or one a row, normalised chunk by chunk (no full copy)."""

    def __init__(self, raw: NDArray[np.float64], count: int) -> None:
        self.raw, self.count = raw, count

    def chunk(self, sl: slice) -> NDArray[np.float64]:
        """Unit normals of the receivers ``sl``: one row for all of them when a single normal was given."""
        if len(self.raw) == 1 and self.count != 1:
            return normalize_rows(self.raw)
        return normalize_rows(np.ascontiguousarray(self.raw[sl]))


def _rows(n: NDArray[np.float64], idx: NDArray[np.int64]) -> NDArray[np.float64]:
    """The normals of receivers ``idx`` (``n`` has a row a receiver, or one row for all)."""
    return np.ascontiguousarray(np.broadcast_to(n, (len(idx), 3))) if len(n) == 1 else n[idx]


def _receivers(points: ArrayLike, normals: ArrayLike) -> tuple[NDArray[np.float64], _Normals]:
    """Points and normals validated as :func:`~isocsg.shadows.lambert._prepare` does, normals kept lazy."""
    p = points_array("points", points, error=InvalidParameterError)
    n = points_array("normals", normals, error=InvalidParameterError)
    if n.shape != p.shape and not (n.shape[0] == 1 and p.shape[0] != 1):
        raise InvalidParameterError(f"normals must have the shape of points {p.shape}, got {n.shape}")
    zero = np.linalg.norm(n, axis=1) <= 1e-300
    if np.any(zero):
        raise InvalidParameterError(f"normals must be non-zero, row {int(np.argmax(zero))} is zero")
    return p, _Normals(n, len(p))


def _split_lights(lights: Any) -> tuple[list[AreaLight | PolyhedronLight], list[PhotometricLight]]:
    """Area and polyhedron sources apart from point luminaires (a luminaire's type is checked here)."""
    if isinstance(lights, PhotometricLight):
        return [], [lights]
    seq = lights if isinstance(lights, (list, tuple)) else None
    if seq is None and not isinstance(lights, (AreaLight, PolyhedronLight)):
        try:
            seq = list(lights)
        except TypeError:
            seq = None
    for i, li in enumerate(seq or [lights]):
        if isinstance(li, PointLight):
            raise InvalidLightError(
                f"lights[{i}] must be an AreaLight or a PolyhedronLight, or a PhotometricLight for a point source; "
                "got a PointLight, a rendering light without photometric units (an isotropic point source of "
                "I cd is PhotometricLight.isotropic(position, I))")
    if seq is not None and any(isinstance(li, PhotometricLight) for li in seq):
        return (as_light_list([li for li in seq if not isinstance(li, PhotometricLight)]),
                [li for li in seq if isinstance(li, PhotometricLight)])
    return as_light_list(lights if seq is None else seq), []


def _fallback_point(
    p: NDArray[np.float64], n: NDArray[np.float64], sources: SourceArrays, pieces: PieceArrays, scale: float,
    sel: NDArray[np.int64] | None = None,
) -> tuple[float, int]:
    """One point through the 2D Boolean path (shapely): many overlapping silhouettes."""
    import shapely
    from shapely.geometry import Polygon
    from shapely.geometry.polygon import orient

    e = 0.0
    gstat = np.full(sources.ngroups, -1, dtype=np.int64)
    for s in range(len(sources.radiance)):
        P2, blocked = blockers_single(p, n, s, sources, pieces, scale, sel)
        if len(P2) < 3:
            continue
        sp = Polygon(P2)
        a0 = sp.area
        if a0 <= 0:
            continue
        g = sources.group[s]
        gstat[g] = max(gstat[g], 0)
        if blocked:
            vis = sp.difference(shapely.union_all([Polygon(c).buffer(0) for c in blocked]))
        else:
            vis = sp
        avis = vis.area
        if not blocked:
            gstat[g] |= 1
        elif avis <= UMBRA_TOL * a0:
            gstat[g] |= 2
            continue
        else:
            gstat[g] |= 3
        if vis.geom_type == "Polygon":
            polys = [vis]
        else:
            polys = [g_ for g_ in getattr(vis, "geoms", []) if g_.geom_type == "Polygon"]
        total = 0.0
        q0, u, w = sources.q0[s], sources.u[s], sources.w[s]
        for poly in polys:
            poly = orient(poly, sign=1.0)  # exterior counter-clockwise, holes clockwise
            for ring in [poly.exterior, *poly.interiors]:
                xy = np.asarray(ring.coords)[:-1]
                q = q0 + xy[:, :1] * u + xy[:, 1:2] * w
                total += float(edge_terms(p, n, q, np.roll(q, -1, axis=0)).sum())
        e += 0.5 * sources.radiance[s] * max(total, 0.0)
    worst = 0
    for st in gstat:
        if st == 2 or st < 0:
            worst = 2
        elif st == 3:
            worst = max(worst, 1)
    return e, worst


def illuminance_and_state(
    points: ArrayLike,
    normals: ArrayLike,
    lights: Sequence[AreaLight | PolyhedronLight | PhotometricLight] | AreaLight | PolyhedronLight | PhotometricLight,
    occluders: Sequence[Solid] | Solid = (),
    *,
    resolution: int = DEFAULT_RESOLUTION,
) -> tuple[NDArray[np.float64], NDArray[np.int8]]:
    """Illuminance and shadow state in one pass (see :func:`illuminance`, :func:`shadow_state`).

    Examples
    --------
    >>> from isocsg import Box
    >>> lamp = AreaLight([(-1, -1, 3), (-1, 1, 3), (1, 1, 3), (1, -1, 3)])
    >>> e, s = illuminance_and_state([[0, 0, 0], [5, 0, 0]], [[0, 0, 1]] * 2, [lamp], [Box((0, 0, 1), (4, 4, .2))])
    >>> np.round(e, 4).tolist(), s.tolist()
    ([0.0, 0.0326], [2, 0])
    """
    p, n = _receivers(points, normals)
    light_list, luminaires = _split_lights(lights)
    solids = occluder_list(occluders, resolution)
    if luminaires:
        # point luminaires: hard shadows (shadows/pointsource.py), added to the area sources
        p, nfull = _prepare(points, normals)
        from .pointsource import point_illuminance_and_state

        ext0 = [p, *(np.asarray(lu.position)[None, :] for lu in luminaires)]
        ext0 += [np.asarray(o.bounds, dtype=np.float64) for o in solids]
        ext0 += [np.asarray(q) for li in light_list for q in li.emitting_polygons()]
        all0 = np.vstack(ext0)
        scale0 = float(max(np.max(np.ptp(all0, axis=0)), np.max(np.abs(all0)), 1e-300))
        E_pt, s_pt = point_illuminance_and_state(p, nfull, luminaires, solids, resolution=resolution, scale=scale0)
        if not light_list:
            return E_pt, s_pt
        E_ar, s_ar = illuminance_and_state(p, nfull, light_list, solids, resolution=resolution)
        return E_pt + E_ar, np.maximum(s_pt, s_ar)
    sources = _sources(light_list)
    # Chunks of receivers, each on its own: the memory beyond the results stays bounded. Their
    # bounding boxes (one pass) give the scene's scale and each chunk's occluder pieces.
    chunks = [slice(c0, c0 + CHUNK_POINTS) for c0 in range(0, max(len(p), 1), CHUNK_POINTS)]
    boxes = [np.vstack(bounding_box(p[sl])) if len(p) else p for sl in chunks]
    ext = [*boxes, sources.verts]
    ext += [np.asarray(o.bounds, dtype=np.float64) for o in solids]
    allpts = np.vstack(ext)
    scale = float(max(np.max(np.ptp(allpts, axis=0)), np.max(np.abs(allpts)), 1e-300))
    E = np.zeros(len(p))
    state = np.zeros(len(p), dtype=np.int8)
    for sl, box in zip(chunks, boxes):
        E[sl], state[sl] = _area_sources(p[sl], n.chunk(sl), sources, solids, resolution, scale, box)
    return E, state


def _area_sources(
    p: NDArray[np.float64], n: NDArray[np.float64], sources: SourceArrays, solids: list[Solid], resolution: int,
    scale: float, box: NDArray[np.float64],
) -> tuple[NDArray[np.float64], NDArray[np.int8]]:
    """Illuminance and state of one chunk of receivers from the area and polyhedron sources.

    ``n`` has a row a receiver, or a single row for all; ``box`` is the receivers' bounding box
    (rows lo, hi).
    """
    # The pieces the receivers' bounding box needs; when they are many, each group of nearby
    # receivers gets its own (fewer) pieces.
    whole = shadow_pieces(solids, box, sources.verts, resolution=resolution, scale=scale) if solids and len(p) else []
    groups = receiver_tiles(p) if len(whole) > FEW_PIECES else [np.arange(len(p), dtype=np.int64)]
    ids: dict[int, int] = {}
    pieces: list[ConvexPiece] = []
    own_ids = []
    for idx in groups:
        own = whole if len(groups) == 1 else shadow_pieces(
            solids, np.vstack(bounding_box(p[idx])), sources.verts, resolution=resolution, scale=scale)
        own_ids.append(np.array([ids.setdefault(id(pc), len(ids)) for pc in own], dtype=np.int64))
        for pc in own:
            if ids[id(pc)] == len(pieces):
                pieces.append(pc)
    E = np.zeros(len(p))
    state = np.zeros(len(p), dtype=np.int8)
    if len(p) == 0 or len(sources.radiance) == 0:
        return E, state
    # Receivers classified by the shadow volumes (shadows/tiles.py): lit ones take Lambert's
    # formula alone, umbra ones nothing; the rest are clipped against the pieces their tile needs.
    lit_parts, exact_parts, tile_of, t_off, t_idx = [], [], [], [0], []
    for idx, own_idx in zip(groups, own_ids):
        rc = classify_receivers(p if len(groups) == 1 else p[idx], sources, [pieces[k] for k in own_idx], scale,
                                box=box if len(groups) == 1 else None)
        lit, umbra, ex, tiles_used, local = class_indices(rc.cls, rc.tile, len(rc.needed))
        lit_parts.append(idx[lit] if len(groups) > 1 else lit)
        state[idx[umbra]] = UMBRA
        if not len(ex):
            continue
        exact_parts.append(idx[ex] if len(groups) > 1 else ex)
        tile_of.append(local + len(t_off) - 1)
        for t in tiles_used:
            t_idx.extend(own_idx[rc.needed[t]].tolist())
            t_off.append(len(t_idx))
    lit_illuminance(p, n, np.concatenate(lit_parts), sources, scale, E, state)
    if exact_parts:
        ex_idx = np.concatenate(exact_parts)
        pa = PieceArrays(pieces)
        tiles = (np.concatenate(tile_of), np.asarray(t_off, dtype=np.int64), np.asarray(t_idx, dtype=np.int64))
        Ex, Sx, overflow = visible_illuminance(p[ex_idx], _rows(n, ex_idx), sources, pa, scale, tiles)
        for i in np.nonzero(overflow)[0]:
            sel = tiles[2][tiles[1][tiles[0][i]] : tiles[1][tiles[0][i] + 1]]
            Ex[i], Sx[i] = _fallback_point(p[ex_idx[i]], n[0 if len(n) == 1 else ex_idx[i]], sources, pa, scale, sel)
        E[ex_idx], state[ex_idx] = Ex, Sx
    return E, state


def receiver_tiles(
    points: NDArray[np.float64], *, per_tile: int = TILE_POINTS, max_tiles: int = MAX_TILES,
) -> list[NDArray[np.int64]]:
    """Groups of nearby receivers (index arrays): the cells of a grid over their bounding box.

    About ``len(points) / per_tile`` cells (at most ``max_tiles``), more along
    the longer sides; empty cells are dropped. Each group gets its own
    occluder pieces (:func:`~isocsg.shadows.occluders.shadow_pieces` leaves
    out what its bounding box cannot see).

    Examples
    --------
    >>> x, y = np.meshgrid(np.linspace(0, 2, 10), np.linspace(0, 1, 10))
    >>> tiles = receiver_tiles(np.c_[x.ravel(), y.ravel(), 0 * x.ravel()], per_tile=50)
    >>> [len(t) for t in tiles]
    [50, 50]
    """
    n = len(points)
    want = min(max_tiles, -(-n // max(per_tile, 1)))
    if want <= 1:
        return [np.arange(n, dtype=np.int64)]
    lo, hi = points.min(axis=0), points.max(axis=0)
    ext = hi - lo
    cells = np.ones(3, dtype=np.int64)
    while True:
        ax = int(np.argmax(ext / cells))
        if ext[ax] <= 0 or np.prod(cells) * (cells[ax] + 1) // cells[ax] > want:
            break
        cells[ax] += 1
    ijk = np.minimum(((points - lo) / np.where(ext > 0, ext, 1.0) * cells).astype(np.int64), cells - 1)
    key = (ijk[:, 0] * cells[1] + ijk[:, 1]) * cells[2] + ijk[:, 2]
    order = np.argsort(key, kind="stable")
    cuts = np.nonzero(np.diff(key[order]))[0] + 1
    return np.split(order, cuts)


def illuminance(
    points: ArrayLike,
    normals: ArrayLike,
    lights: Sequence[AreaLight | PolyhedronLight | PhotometricLight] | AreaLight | PolyhedronLight | PhotometricLight,
    occluders: Sequence[Solid] | Solid = (),
    *,
    resolution: int = DEFAULT_RESOLUTION,
    interreflections: IndirectLight | None = None,
) -> NDArray[np.float64]:
    """Exact illuminance at points from area and polyhedron sources, with soft shadows.

    Parameters
    ----------
    points : array_like, shape (n, 3)
        Receiving points.
    normals : array_like, shape (n, 3) or (3,)
        Their normals (normalised here; one normal may serve every point).
    lights : AreaLight, PolyhedronLight, PhotometricLight or a sequence of them
        The sources; their contributions add up (point luminaires with hard shadows).
    occluders : Solid or sequence of Solid, optional
        Primitives and CSG trees casting shadows. Curved primitives are
        tessellated with ``resolution`` (the shadows are exact for that
        tessellation).
    resolution : int, keyword-only, default 64
        Tessellation of spheres and frusta.
    interreflections : Interreflections, keyword-only, optional
        Add the light reflected by a room and the occluders
        (:mod:`isocsg.shadows.radiosity`); by default direct light only.

    Returns
    -------
    ndarray, shape (n,)
        Illuminance, ``(L/2) sum beta_i (n . g_i)`` over the visible part of
        each source (``pi L`` for a source filling the hemisphere): lux for
        radiances in cd/m^2. Direct light only (occluders black) unless
        ``interreflections`` is given.

    Raises
    ------
    InvalidParameterError
        On malformed points, normals (zero rows) or resolution.
    InvalidLightError
        If ``lights`` holds something else than area or polyhedron lights.
    InvalidGeometryError
        If an occluder is not a solid.

    Examples
    --------
    A disc-like 64-gon of radius 1 at height 1 above the point, facing down:

    >>> ang = np.linspace(0, 2 * np.pi, 64, endpoint=False)
    >>> disc = AreaLight(np.c_[np.cos(ang), -np.sin(ang), np.ones(64)])
    >>> round(float(illuminance([[0, 0, 0]], [[0, 0, 1]], [disc])[0]), 4)  # pi R^2 / (R^2 + h^2) = 1.5708
    1.5695
    """
    direct = illuminance_and_state(points, normals, lights, occluders, resolution=resolution)[0]
    if interreflections is None:
        return direct
    if not callable(getattr(interreflections, "indirect_illuminance", None)):
        raise InvalidParameterError(
            f"interreflections must be an Interreflections, got {type(interreflections).__name__}")
    p, n = _prepare(points, normals)
    areas, luminaires = _split_lights(lights)
    return direct + interreflections.indirect_illuminance(
        p, n, [*areas, *luminaires], occluder_list(occluders, resolution), resolution=resolution)


def shadow_state(
    points: ArrayLike,
    normals: ArrayLike,
    lights: Sequence[AreaLight | PolyhedronLight | PhotometricLight] | AreaLight | PolyhedronLight | PhotometricLight,
    occluders: Sequence[Solid] | Solid = (),
    *,
    resolution: int = DEFAULT_RESOLUTION,
) -> NDArray[np.int8]:
    """Shadow state of each point: 0 lit, 1 penumbra, 2 umbra (worst over the lights).

    A point with nothing of a source in front of its receiving plane receives
    none of it: state 2 for that source; see the module docstring.

    Parameters
    ----------
    points, normals, lights, occluders, resolution
        As for :func:`illuminance`.

    Returns
    -------
    ndarray of int8, shape (n,)

    Examples
    --------
    >>> from isocsg import Box
    >>> lamp = AreaLight([(-1, -1, 3), (-1, 1, 3), (1, 1, 3), (1, -1, 3)])
    >>> shadow_state([[0, 0, 0], [1.2, 0, 0], [9, 0, 0]], [0, 0, 1], lamp, Box((0, 0, 1), (2, 2, .2))).tolist()
    [2, 1, 0]
    """
    return illuminance_and_state(points, normals, lights, occluders, resolution=resolution)[1]
