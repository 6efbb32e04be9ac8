"""Exact illuminance and shadow states from area and polyhedron sources with occluders.

The illuminance at p (unit normal n) is Lambert's contour integral over the
part of each source visible from p (:mod:`isocsg.shadows.visibility`):

- an :class:`~isocsg.shadows.lights.AreaLight` lights only its lit side;
  the part behind p's receiving plane is cut away first (type-B receivers);
- a :class:`~isocsg.shadows.lights.PolyhedronLight` is the sum of its faces
  that face p (each a one-sided polygon): their shared edges cancel, which is
  the seed's contour-line integral; occluders are handled face by face;
- several lights add up.

Shadow state of a point, per light: 0 (lit) when the part of the source in
front of the receiving plane is fully visible, 1 (penumbra) when partly,
2 (umbra) when none of it is. A point that has *nothing* of a source in front
of its receiving plane (a face turned away from the light, the seed's type C,
or a point behind an area source) is in no shadow of that light: it counts as
0 for it, and its illuminance from it is 0. Over several lights the state is
the worst (largest) one. Umbra means a visible area below ``1e-9`` of the
source part in front of the plane.
"""

from __future__ import annotations

from collections.abc import Sequence
import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..geometry.primitives import DEFAULT_RESOLUTION, Solid
from .lambert import _prepare, edge_terms
from .lights import AreaLight, PolyhedronLight, as_light_list
from .occluders import convex_pieces
from .visibility import UMBRA_TOL, PieceArrays, SourceArrays, blockers_single, visible_illuminance

__all__ = ["illuminance", "shadow_state", "illuminance_and_state", "LIT", "PENUMBRA", "UMBRA"]

LIT = 0
PENUMBRA = 1
UMBRA = 2


def _sources(lights: list[AreaLight | PolyhedronLight]) -> SourceArrays:
    polys, rads, groups = [], [], []
    for g, light in enumerate(lights):
        for q in light.emitting_polygons():
            polys.append(np.asarray(q, dtype=np.float64))
            rads.append(light.radiance)
            groups.append(g)
    return SourceArrays(polys, rads, groups)


def _fallback_point(
    p: NDArray[np.float64], n: NDArray[np.float64], sources: SourceArrays, pieces: PieceArrays, scale: float
) -> tuple[float, int]:
    """One point through the 2D Boolean path (shapely): many overlapping silhouettes."""
    import shapely
    from shapely.geometry import Polygon
    from shapely.geometry.polygon import orient

    e = 0.0
    gstat = np.full(sources.ngroups, -1, dtype=np.int64)
    for s in range(len(sources.radiance)):
        P2, blocked = blockers_single(p, n, s, sources, pieces, scale)
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
        polys = [vis] if vis.geom_type == "Polygon" else [g_ for g_ in getattr(vis, "geoms", []) if g_.geom_type == "Polygon"]
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
        if st == 2:
            worst = 2
        elif st == 3:
            worst = max(worst, 1)
    return e, worst


def illuminance_and_state(
    points: ArrayLike,
    normals: ArrayLike,
    lights: Sequence[AreaLight | PolyhedronLight] | AreaLight | PolyhedronLight,
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
    p, n = _prepare(points, normals)
    light_list = as_light_list(lights)
    pieces = convex_pieces(occluders, resolution=resolution)
    sources = _sources(light_list)
    pa = PieceArrays(pieces)
    ext = [p] + [sources.verts] + ([pa.verts] if len(pa.verts) else [])
    allpts = np.vstack(ext)
    scale = float(max(np.max(np.ptp(allpts, axis=0)), np.max(np.abs(allpts)), 1e-300))
    E, state, overflow = visible_illuminance(p, n, sources, pa, scale)
    for i in np.nonzero(overflow)[0]:
        E[i], state[i] = _fallback_point(p[i], n[i], sources, pa, scale)
    return E, state


def illuminance(
    points: ArrayLike,
    normals: ArrayLike,
    lights: Sequence[AreaLight | PolyhedronLight] | AreaLight | PolyhedronLight,
    occluders: Sequence[Solid] | Solid = (),
    *,
    resolution: int = DEFAULT_RESOLUTION,
) -> NDArray[np.float64]:
    """Exact illuminance at points from area and polyhedron sources, with soft shadows.

    Parameters
    ----------
    points : array_like, shape (n, 3)
        Receiving points.
    normals : array_like, shape (n, 3) or (3,)
        Their normals (normalised here; one normal may serve every point).
    lights : AreaLight, PolyhedronLight or a sequence of them
        The sources; their contributions add up.
    occluders : Solid or sequence of Solid, optional
        Primitives and CSG trees casting shadows. Curved primitives are
        tessellated with ``resolution`` (the shadows are exact for that
        tessellation).
    resolution : int, keyword-only, default 64
        Tessellation of spheres and frusta.

    Returns
    -------
    ndarray, shape (n,)
        Illuminance, ``(L/2) sum beta_i (n . g_i)`` over the visible part of
        each source (``pi L`` for a source filling the hemisphere).

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
    return illuminance_and_state(points, normals, lights, occluders, resolution=resolution)[0]


def shadow_state(
    points: ArrayLike,
    normals: ArrayLike,
    lights: Sequence[AreaLight | PolyhedronLight] | AreaLight | PolyhedronLight,
    occluders: Sequence[Solid] | Solid = (),
    *,
    resolution: int = DEFAULT_RESOLUTION,
) -> NDArray[np.int8]:
    """Shadow state of each point: 0 lit, 1 penumbra, 2 umbra (worst over the lights).

    A point with nothing of a source in front of its receiving plane is in no
    shadow of that source (state 0 for it); see the module docstring.

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
