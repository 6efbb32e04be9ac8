"""Half-tone rendering under area and polyhedron sources (seed 001, sections 2.2 and 2.5).

Each pixel shows the illuminance ``E`` of the first visible surface point:
the sum over the scene's area and polyhedron lights of Lambert's contour
integral over the part of the source the point sees (soft shadows, the
occluders being the scene's objects decomposed into convex pieces).

The procedure follows the seed:

1. hidden surfaces: exact first hits of the pixel rays (primitives'
   ``intersect_rays``, CSG trees by interval arithmetic along each ray);
2. shadow detection before illuminance: every visible point is classified,
   light by light, with the penumbra and umbra volumes of every convex piece
   (:mod:`isocsg.shadows.volumes`): inside an umbra volume ``E = 0`` for that
   light; outside every penumbra volume the source is fully visible (no
   occluder is looked at); otherwise only the pieces whose penumbra volume
   holds the point are passed to the exact visibility computation;
3. the speed-up: along each scanline ``E`` is computed exactly every
   ``interval`` pixels and linearly interpolated in between, but never
   across a boundary of faces or shadows: a run between two exact samples is
   interpolated only if every pixel in it sees the same surface part (object,
   leaf, entry/exit side, face or cap) with the same face type and the same
   shadow code for every light (lit, umbra, or penumbra of the same set of
   pieces); otherwise each pixel of the run is computed exactly.
   ``interval = 1`` is the exact mode.

Receiver points are moved off their surface by a tiny distance along the
normal so that their own surface does not occlude them. Curved primitives
cast the shadows of their inscribed tessellation (``resolution``); a visible
point on the inside of a curved cut can then lie inside the tessellated
material and come out dark: raise ``resolution`` for such scenes.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np
from numpy.typing import NDArray

from .._late import late
from .._validation import integer
from ..camera import Camera
from ..csg.program import combine_masks, compile_program
from ..csg.tree import CSGNode
from ..errors import InvalidGeometryError, InvalidLightError, InvalidParameterError
from ..kinds.base import DEFAULT_RESOLUTION, Primitive
from ..kinds.polyhedron import ConvexPolyhedron
from ..lighting.area import AreaLight, PolyhedronLight

__all__ = ["FirstHits", "HalftoneResult", "first_hits", "render_halftone", "shadow_codes"]

ProgressCallback = Callable[[int, int], None]

# Rows handled per batch (bounds memory; one progress step each).
ROW_BATCH = 16
# Receiver points move this fraction of the scene size off their surface.
NUDGE = 1e-7


@dataclass(frozen=True, slots=True, eq=False)
class FirstHits:
    """The first visible surface point along each ray.

    Attributes
    ----------
    t : ndarray, shape (n,)
        Ray parameter of the hit (``inf`` where nothing is hit).
    normal : ndarray, shape (n, 3)
        Unit normal of the visible surface (reversed on the inside of a cut).
    object_index : ndarray of int32, shape (n,)
        Index of the object hit, -1 for none.
    surface_id : ndarray of int64, shape (n,)
        Identifies the surface part hit (object, leaf, entry or exit, face or
        cap); -1 for none. Equal ids mean one smooth surface.
    """

    t: NDArray[np.float64]
    normal: NDArray[np.float64]
    object_index: NDArray[np.int32]
    surface_id: NDArray[np.int64]




def _object_hits(
    shape: Any, o: NDArray[np.float64], d: NDArray[np.float64], t_min: float,
) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.int64]]:
    """First hit of rays with one object: t, normal, part id (leaf * 2 + side) * 1024 + face."""
    n = len(o)
    if isinstance(shape, (Primitive, CSGNode)):
        program = compile_program(shape) if isinstance(shape, Primitive) else shape.program()
        leaves = program.leaves
    else:
        raise InvalidParameterError(f"scene object must be a primitive or a CSG tree, got {type(shape).__name__}")
    k = len(leaves)
    hits = [leaf.intersect_rays(o, d) for leaf in leaves]
    t_in = np.stack([h.t_in for h in hits], axis=1)  # (n, k)
    t_out = np.stack([h.t_out for h in hits], axis=1)
    valid = np.isfinite(t_in) & np.isfinite(t_out) & (t_in <= t_out) & (t_out >= t_min)
    inside0 = valid & (t_in < t_min)  # the ray starts inside this leaf
    # events: entries (only in front of t_min) and exits
    ev_t = np.concatenate([np.where(valid & ~inside0, t_in, np.inf), np.where(valid, t_out, np.inf)], axis=1)
    ev_leaf = np.concatenate([np.arange(k), np.arange(k)])[None, :].repeat(n, axis=0)
    ev_enter = np.concatenate([np.ones(k, bool), np.zeros(k, bool)])[None, :].repeat(n, axis=0)
    order = np.argsort(ev_t, axis=1, kind="stable")
    ev_t = np.take_along_axis(ev_t, order, axis=1)
    ev_leaf = np.take_along_axis(ev_leaf, order, axis=1)
    ev_enter = np.take_along_axis(ev_enter, order, axis=1)
    inside = inside0.copy()
    state = program.evaluate(lambda i, _: inside[:, i].copy(), combine_masks)
    found = np.zeros(n, bool)
    t_hit = np.full(n, np.inf)
    leaf_hit = np.zeros(n, np.int64)
    enter_hit = np.zeros(n, bool)
    rows = np.arange(n)
    for j in range(2 * k):
        tj = ev_t[:, j]
        live = np.isfinite(tj)
        inside[rows[live], ev_leaf[live, j]] = ev_enter[live, j]
        # events at one depth act together (regularised operations): decide at the group's last one
        last = ev_t[:, j + 1] != tj if j < 2 * k - 1 else np.ones(n, dtype=bool)
        now = program.evaluate(lambda i, _: inside[:, i].copy(), combine_masks)
        new = last & live & now & ~state & ~found
        t_hit[new] = tj[new]
        leaf_hit[new] = ev_leaf[new, j]
        enter_hit[new] = ev_enter[new, j]
        found |= new
        state = np.where(last & live, now, state)
    normal = np.zeros((n, 3))
    part = np.full(n, -1, dtype=np.int64)
    for i, (leaf, h) in enumerate(zip(leaves, hits)):
        sel = found & (leaf_hit == i)
        if not np.any(sel):
            continue
        nn = np.where(enter_hit[sel, None], h.n_in[sel], -h.n_out[sel])
        normal[sel] = nn
        pts = o[sel] + t_hit[sel, None] * d[sel]
        face = leaf.part_index(pts, np.where(enter_hit[sel, None], nn, -nn))
        part[sel] = (i * 2 + (~enter_hit[sel]).astype(np.int64)) * 1024 + np.minimum(face, 1023)
    return t_hit, normal, part


def first_hits(objects: Sequence[Any], origins: Any, directions: Any, *, t_min: float = 0.0) -> FirstHits:
    """Exact first visible points of rays against solids (primitives or CSG trees).

    Parameters
    ----------
    objects : sequence of Solid or SceneObject
    origins, directions : array_like, shape (n, 3)
    t_min : float, keyword-only
        Hits before this ray parameter are ignored.

    Returns
    -------
    FirstHits

    Raises
    ------
    InvalidParameterError
        If an object is not a primitive or a CSG tree.

    Examples
    --------
    >>> from isocsg import Box, Sphere
    >>> h = first_hits([Box((0, 0, 0), (2, 2, 2)) - Sphere((0, 0, 1), 0.5)], [[0, 0, 5]] * 2, [[0, 0, -1], [0, 1, 0]])
    >>> h.t.tolist(), h.normal[0].tolist(), h.object_index.tolist()
    ([4.5, inf], [-0.0, -0.0, 1.0], [0, -1])
    """
    from .._validation import points_array

    o = points_array("origins", origins)
    d = points_array("directions", directions)
    if o.shape[0] == 1 and d.shape[0] > 1:
        o = np.broadcast_to(o, d.shape).copy()
    n = len(d)
    best = np.full(n, np.inf)
    normal = np.zeros((n, 3))
    obj = np.full(n, -1, dtype=np.int32)
    sid = np.full(n, -1, dtype=np.int64)
    for idx, ob in enumerate(objects):
        shape = getattr(ob, "shape", ob)
        t, nn, part = _object_hits(shape, o, d, t_min)
        better = t < best
        best[better] = t[better]
        normal[better] = nn[better]
        obj[better] = idx
        sid[better] = idx * (1 << 24) + part[better]
    return FirstHits(best, normal, obj, sid)


@dataclass(frozen=True, slots=True, eq=False)
class HalftoneResult:
    """A half-tone image: illuminance per pixel and what each pixel shows.

    Attributes
    ----------
    image : ndarray, float32, shape (H, W)
        Illuminance ``E`` (unscaled), NaN on the background.
    display : ndarray, float32, shape (H, W)
        ``E * exposure`` clipped to [0, 1], NaN on the background.
    shadow : ndarray, int8, shape (H, W)
        Worst shadow state over the lights from the shadow volumes: 0 lit,
        1 penumbra (of at least one piece; possibly a true umbra of several),
        2 umbra; -1 on the background.
    object_index : ndarray, int32, shape (H, W)
        Index into ``scene.objects``, -1 on the background.
    surface_id : ndarray, int64, shape (H, W)
        The surface part seen (see :class:`FirstHits`).
    exact : ndarray, bool, shape (H, W)
        Pixels whose ``E`` was computed exactly (the others were interpolated).
    camera : Camera
    interval : int
    seconds : float
        Wall-clock time of the render.
    """

    image: NDArray[np.float32]
    display: NDArray[np.float32]
    shadow: NDArray[np.int8]
    object_index: NDArray[np.int32]
    surface_id: NDArray[np.int64]
    exact: NDArray[np.bool_]
    camera: Camera
    interval: int
    seconds: float

    def _repr_mimebundle_(self, include: Any = None, exclude: Any = None) -> dict[str, Any]:
        """Rich display in Jupyter: a small PNG image (see :mod:`isocsg.interop.notebook`)."""
        return late("mimebundle")(self, include, exclude)

    def _repr_png_(self) -> bytes | None:
        """A small PNG image of the object (see :mod:`isocsg.interop.notebook`)."""
        return late("mimebundle")(self, ("image/png",)).get("image/png")

    @property
    def exact_fraction(self) -> float:
        """Fraction of the visible pixels computed exactly."""
        vis = self.object_index >= 0
        return float(self.exact[vis].sum() / max(int(vis.sum()), 1))


@dataclass(frozen=True, slots=True, eq=False)
class _LightPlan:
    light: Any
    vertices: NDArray[np.float64]
    pieces: tuple[int, ...]
    penumbra: tuple[Any, ...]
    umbra: tuple[Any, ...]
    piece_vertices: tuple[NDArray[np.float64], ...]


class _PointRegion(Protocol):
    """What a light's plan needs of a shadow volume: which points it holds."""

    def contains(self, points: NDArray[np.float64]) -> NDArray[np.bool_]: ...


class _Everywhere:
    """A shadow volume holding every point (``contains`` is all True), or none of them."""

    def __init__(self, inside: bool) -> None:
        self.inside = inside

    def contains(self, points: NDArray[np.float64]) -> NDArray[np.bool_]:
        return np.full(len(points), self.inside)


def _plan(lights: list[Any], pieces: list[Any], bounds: NDArray[np.float64]) -> list[_LightPlan]:
    from .volumes import SourceGeometry, shadow_volumes

    plans = []
    for light in lights:
        src = SourceGeometry.from_light(light)
        idx: list[int] = []
        pen: list[_PointRegion] = []
        umb: list[_PointRegion] = []
        pv: list[NDArray[np.float64]] = []
        for i, pc in enumerate(pieces):
            try:
                sv = shadow_volumes(src, pc)
            except InvalidGeometryError:
                # The source reaches into the piece (a lamp inside an object): no shadow
                # volumes exist. Every point is then decided by the exact visibility.
                sv = None
                idx.append(i)
                pen.append(_Everywhere(True))
                umb.append(_Everywhere(False))
                pv.append(np.asarray(pc.vertices, dtype=np.float64))
                continue
            if sv is None:
                continue
            sv = sv.reduced(bounds)
            idx.append(i)
            pen.append(sv.penumbra)
            umb.append(sv.umbra)
            pv.append(np.asarray(pc.vertices, dtype=np.float64))
        plans.append(_LightPlan(light, src.vertices, tuple(idx), tuple(pen), tuple(umb), tuple(pv)))
    return plans


def shadow_codes(
    plan: _LightPlan, points: NDArray[np.float64], normals: NDArray[np.float64],
) -> tuple[NDArray[np.int8], NDArray[np.bool_], NDArray[np.int8]]:
    """Per point: state (0 lit / 1 penumbra / 2 umbra), penumbra membership (n, pieces), face type."""
    n = len(points)
    k = len(plan.pieces)
    member = np.zeros((n, k), dtype=bool)
    umbra = np.zeros(n, dtype=bool)
    pn = np.einsum("nj,nj->n", normals, points)
    scale = max(float(np.max(np.abs(plan.vertices))), 1.0)
    tol = 1e-9 * scale
    for j in range(k):
        # eq. (5) per point: a piece behind the receiving plane casts nothing on it
        front = np.max(normals @ plan.piece_vertices[j].T, axis=1) - pn > tol
        member[front, j] = plan.penumbra[j].contains(points[front])
        sel = member[:, j] & ~umbra
        if np.any(sel):
            umbra[sel] |= plan.umbra[j].contains(points[sel])
    state = np.where(umbra, 2, np.where(member.any(axis=1), 1, 0)).astype(np.int8)
    # face type of the receiving point for this source (its tangent plane against the source vertices)
    f = np.einsum("nj,kj->nk", normals, plan.vertices) - pn[:, None]
    pos, neg = np.all(f >= -tol, axis=1), np.all(f <= tol, axis=1)
    ftype = np.where(pos, 0, np.where(neg, 2, 1)).astype(np.int8)
    if isinstance(plan.light, AreaLight):
        behind = (points - plan.vertices[0]) @ np.asarray(plan.light.normal) <= tol
        ftype = np.where(behind, 2, ftype).astype(np.int8)
    # nothing of the source in front of the receiving plane (type C, or behind an area source):
    # none of it reaches the point, state 2 (the conventions)
    state = np.where(ftype == 2, 2, state).astype(np.int8)
    return state, member, ftype


def _exact_E(plans: list[_LightPlan], solids: list[Any], points: NDArray[np.float64], normals: NDArray[np.float64],
             codes: list[tuple[NDArray[np.int8], NDArray[np.bool_], NDArray[np.int8]]]) -> NDArray[np.float64]:
    """Exact illuminance, each light using only the pieces whose penumbra volume holds the point."""
    from .direct import illuminance

    E = np.zeros(len(points))
    for plan, (state, member, ftype) in zip(plans, codes):
        need = (state != 2) & (ftype != 2)
        lit = need & (state == 0)
        if np.any(lit):
            E[lit] += illuminance(points[lit], normals[lit], plan.light, [])
        pen = need & (state == 1)
        if np.any(pen):
            idx = np.nonzero(pen)[0]
            groups, inv = np.unique(member[idx], axis=0, return_inverse=True)
            inv = inv.ravel()
            for g, row in enumerate(groups):
                sel = idx[inv == g]
                occ = [solids[plan.pieces[j]] for j in np.nonzero(row)[0]]
                E[sel] += illuminance(points[sel], normals[sel], plan.light, occ)
    return E


@dataclass(frozen=True, slots=True, eq=False)
class _Receivers:
    """What every row batch of a half-tone image shares: the first hits of the camera's rays,
    the visible points nudged off their surfaces, each light's plan and the occluders' pieces."""

    hits: FirstHits
    visible: NDArray[np.bool_]
    points: NDArray[np.float64]
    plans: list[_LightPlan]
    solids: list[ConvexPolyhedron]


def _receivers(scene: Any, cam: Camera, lights: list[Any], resolution: int) -> _Receivers:
    from .occluders import convex_pieces

    pieces = convex_pieces([o.shape for o in scene.objects], resolution=resolution)
    solids = [ConvexPolyhedron(pc.vertices) for pc in pieces]
    origins = cam.ray_origins().reshape(-1, 3)
    dirs = cam.ray_directions().reshape(-1, 3)
    hits = first_hits(scene.objects, origins, dirs)
    vis = np.isfinite(hits.t)
    pts = origins + np.where(vis, hits.t, 0.0)[:, None] * dirs
    light_pts = [np.asarray(li.vertices, dtype=float).reshape(-1, 3) for li in lights]
    all_parts = [pts[vis]] + [pc.vertices for pc in pieces] + light_pts
    allp = np.vstack([a for a in all_parts if len(a)])
    lo, hi = allp.min(axis=0), allp.max(axis=0)
    scale = max(float(np.max(hi - lo)), float(np.max(np.abs(allp))), 1e-300)
    bounds = np.stack([lo - 0.01 * scale - 1e-9, hi + 0.01 * scale + 1e-9])
    plans = _plan(lights, pieces, bounds)
    recv = pts + NUDGE * scale * hits.normal  # off the surface: not self-occluded
    return _Receivers(hits, vis, recv, plans, solids)


ShadowCodes = tuple[NDArray[np.int8], NDArray[np.bool_], NDArray[np.int8]]


def _take(codes: list[ShadowCodes], rows: NDArray[np.int64]) -> list[ShadowCodes]:
    return [(c[0][rows], c[1][rows], c[2][rows]) for c in codes]


def _pixel_keys(
    codes: list[ShadowCodes], surface_id: NDArray[np.int64], local: NDArray[np.int64], shape: tuple[int, int]
) -> tuple[NDArray[np.int64], NDArray[np.bool_], NDArray[np.bool_]]:
    """Per pixel of a row batch (``local``: the visible ones): a key that two pixels share when
    one formula gives both (surface part + per light: face type, state, penumbra set; -1 on
    the background), pixels always computed exactly, pixels in the penumbra of several pieces."""
    key_cols = [surface_id[:, None]]
    always = np.zeros(len(local), dtype=bool)
    multi = np.zeros(len(local), dtype=bool)
    for state, member, ftype in codes:
        if member.shape[1]:
            _, grp = np.unique(member, axis=0, return_inverse=True)
            grp = grp.ravel()
        else:
            grp = np.zeros(len(local), np.int64)
        key_cols += [ftype[:, None].astype(np.int64), state[:, None].astype(np.int64), grp[:, None]]
        # a type-B point in a penumbra: its clipped source has shadow edges the volumes do not show
        always |= (ftype == 1) & (state == 1)
        multi |= (state == 1) & (member.sum(axis=1) >= 2)
    key_full = np.full(shape[0] * shape[1], -1, dtype=np.int64)
    if len(local):
        _, kid = np.unique(np.hstack(key_cols), axis=0, return_inverse=True)
        key_full[local] = kid.ravel()
    always_img = np.zeros(shape[0] * shape[1], dtype=bool)
    always_img[local] = always
    multi_img = np.zeros(shape[0] * shape[1], dtype=bool)
    multi_img[local] = multi
    return key_full.reshape(shape), always_img.reshape(shape), multi_img.reshape(shape)


def _exact_samples(
    key_img: NDArray[np.int64], always_img: NDArray[np.bool_], step: int
) -> tuple[NDArray[np.int64], NDArray[np.bool_], NDArray[np.bool_]]:
    """The sample columns (every ``step`` pixels and the last), the pixels computed exactly and,
    per row and run between two samples, whether the run may be interpolated."""
    rows, W = key_img.shape
    want = np.zeros((rows, W), dtype=bool)
    cols = np.unique(np.r_[np.arange(0, W, step), W - 1])
    want[:, cols] = True
    want |= always_img
    # runs between samples whose pixels do not all share one key: computed exactly
    seg_ok = np.ones((rows, len(cols) - 1), dtype=bool)
    for s in range(len(cols) - 1):
        a, b = cols[s], cols[s + 1]
        block = key_img[:, a:b + 1]
        one_key = np.all(block == block[:, :1], axis=1) & (block[:, 0] >= 0)
        seg_ok[:, s] = one_key & ~np.any(always_img[:, a:b + 1], axis=1)
        want[~seg_ok[:, s], a:b + 1] = True
    want &= key_img >= 0
    return cols, want, seg_ok


def _zero_end_runs(
    Eimg: NDArray[np.float64], cols: NDArray[np.int64], seg_ok: NDArray[np.bool_], multi_img: NDArray[np.bool_]
) -> NDArray[np.bool_]:
    """Inner pixels of the interpolable runs in the penumbra of several pieces with a zero end:
    they may hide a true-umbra edge, so they are computed exactly."""
    extra = np.zeros(Eimg.shape, dtype=bool)
    for s in range(len(cols) - 1):
        a, b = cols[s], cols[s + 1]
        zero_end = (Eimg[:, a] == 0) | (Eimg[:, b] == 0)
        risky = seg_ok[:, s] & zero_end & multi_img[:, a]
        extra[risky, a + 1:b] = True
    return extra


def _interpolate_runs(
    Eimg: NDArray[np.float64], cols: NDArray[np.int64], seg_ok: NDArray[np.bool_], extra: NDArray[np.bool_],
) -> None:
    """Linear interpolation, in place, inside the runs left to it."""
    for s in range(len(cols) - 1):
        a, b = cols[s], cols[s + 1]
        if b - a < 2:
            continue
        rows = np.nonzero(seg_ok[:, s] & ~extra[:, a + 1])[0]
        if len(rows) == 0:
            continue
        w = (np.arange(a + 1, b) - a) / (b - a)
        Eimg[rows, a + 1:b] = Eimg[rows, a][:, None] * (1 - w)[None, :] + Eimg[rows, b][:, None] * w[None, :]


def _render_rows(
    rx: _Receivers, r0: int, r1: int, W: int, step: int
) -> tuple[NDArray[np.float64], NDArray[np.int8], NDArray[np.bool_]]:
    """Rows ``r0 .. r1`` of the image, flat: illuminance, worst shadow state, pixels computed exactly."""
    shape = (r1 - r0, W)
    idx = np.nonzero(rx.visible[r0 * W:r1 * W])[0] + r0 * W
    local = idx - r0 * W
    p, nrm = rx.points[idx], rx.hits.normal[idx]
    codes = [shadow_codes(plan, p, nrm) for plan in rx.plans]
    shadow = np.full(shape[0] * shape[1], -1, dtype=np.int8)
    shadow[local] = np.max(np.stack([c[0] for c in codes]), axis=0) if codes else np.zeros(len(idx), np.int8)
    key_img, always_img, multi_img = _pixel_keys(codes, rx.hits.surface_id[idx], local, shape)
    cols, want, seg_ok = _exact_samples(key_img, always_img, step)
    Erow = np.full(shape[0] * shape[1], np.nan)
    sel = np.nonzero(want.ravel()[local])[0]
    if len(sel):
        Erow[local[sel]] = _exact_E(rx.plans, rx.solids, p[sel], nrm[sel], _take(codes, sel))
    Eimg = Erow.reshape(shape)
    extra = _zero_end_runs(Eimg, cols, seg_ok, multi_img) & ~want & (key_img >= 0)
    if np.any(extra):
        flat = np.nonzero(extra.ravel())[0]
        pos = np.searchsorted(local, flat)
        Erow[flat] = _exact_E(rx.plans, rx.solids, p[pos], nrm[pos], _take(codes, pos))
        want |= extra
    _interpolate_runs(Eimg, cols, seg_ok, extra)
    return Erow, shadow, want.ravel()


def render_halftone(
    scene: Any,
    *,
    camera: Camera | None = None,
    interval: int | None = None,
    resolution: int = DEFAULT_RESOLUTION,
    progress: ProgressCallback | None = None,
) -> HalftoneResult:
    """Render the illuminance of a scene lit by area and polyhedron sources, with soft shadows.

    Parameters
    ----------
    scene : Scene
        Its area and polyhedron lights light the scene; its objects are both
        receivers and occluders. Point and directional lights are ignored.
    camera : Camera, optional
        Default ``scene.camera``.
    interval : int, optional
        Exact values every ``interval`` pixels along each scanline, linear
        interpolation in between except across face and shadow boundaries;
        1 is the exact mode. Default ``scene.render.interval``.
    resolution : int, keyword-only, default 64
        Tessellation of curved primitives as occluders.
    progress : callable, optional
        ``progress(done_rows, total_rows)``.

    Returns
    -------
    HalftoneResult

    Raises
    ------
    InvalidLightError
        If the scene has no area or polyhedron light.
    InvalidParameterError
        On a bad ``interval`` or ``resolution``.

    Examples
    --------
    >>> from isocsg import Box, Camera, Scene
    >>> lamp = AreaLight([(-.5, -.5, 2), (-.5, .5, 2), (.5, .5, 2), (.5, -.5, 2)])
    >>> scene = Scene(Camera((0, 0, 6), (0, 0, 0), up=(0, 1, 0), width=8, height=8),
    ...               [lamp], [Box((0, 0, -0.05), (4, 4, 0.1))])
    >>> r = render_halftone(scene)
    >>> r.image.shape, bool(np.all(r.image > 0)), int(r.shadow.max())
    ((8, 8), True, 0)
    """
    start = time.perf_counter()
    cam = scene.camera if camera is None else camera
    if not isinstance(cam, Camera):
        raise InvalidParameterError(f"camera must be a Camera, got {type(cam).__name__}")
    step = scene.render.interval if interval is None else interval
    step = integer("interval", step, low=1, high=256, error=InvalidParameterError)
    lights = [li for li in scene.lights if isinstance(li, (AreaLight, PolyhedronLight))]
    if not lights:
        raise InvalidLightError("scene.lights has no area or polyhedron light: a half-tone image needs one")
    receivers = _receivers(scene, cam, lights, resolution)
    hits = receivers.hits
    H, W = cam.height, cam.width
    E = np.full(H * W, np.nan)
    shadow = np.full(H * W, -1, dtype=np.int8)
    exact = np.zeros(H * W, dtype=bool)
    for r0 in range(0, H, ROW_BATCH):
        r1 = min(H, r0 + ROW_BATCH)
        sl = slice(r0 * W, r1 * W)
        E[sl], shadow[sl], exact[sl] = _render_rows(receivers, r0, r1, W, step)
        if progress is not None:
            progress(r1, H)
    E_img = E.reshape(H, W).astype(np.float32)
    disp = np.where(np.isnan(E_img), np.nan, np.clip(E_img * scene.render.exposure, 0.0, 1.0)).astype(np.float32)
    return HalftoneResult(
        image=E_img,
        display=disp,
        shadow=shadow.reshape(H, W),
        object_index=hits.object_index.reshape(H, W),
        surface_id=hits.surface_id.reshape(H, W),
        exact=exact.reshape(H, W),
        camera=cam,
        interval=step,
        seconds=time.perf_counter() - start,
    )
