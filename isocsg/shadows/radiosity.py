"""Interreflections: a radiosity solve over patches on top of the exact direct illuminance.

Nishita and Nakamae (SIGGRAPH 1985) extend the contour integral of the direct
light to light reflected between diffuse surfaces. Here:

1. The reflecting surfaces (a :class:`~isocsg.shadows.patches.Room`'s inner
   faces, the faces of boxes and convex polyhedra given a reflectance) are cut
   into patches (:mod:`isocsg.shadows.patches`); patches whose points do not
   all share one direct shadow state (:func:`~isocsg.shadows.direct.shadow_state`)
   are cut into four, ``refine`` times: the radiosity changes fastest at
   shadow boundaries.
2. Each patch's mean direct illuminance E_i: where nothing can stand between
   the patch and an emitting polygon, exactly, ``pi L F(i -> source)`` with the
   closed-form polygon-to-polygon factor; otherwise the exact direct
   illuminance at the patch's Gauss points, averaged. A point luminaire lights
   the part of the patch it sees (the patch minus the occluders' hard
   shadows, :mod:`isocsg.shadows.pointflux`): ``I Omega / A`` exactly for an
   isotropic one, Gauss points over that part for a measured distribution.
3. The radiosity (exitance, lm/m^2) of each patch solves
   ``B_i = rho_i (E_i + sum_j F_ij B_j)``, by progressive refinement
   (Southwell's iteration: shoot the patch with the most unshot flux
   ``A_j U_j``). The residual after each shot is the unshot flux over the
   reflected flux so far, ``sum A U / sum A B``; the solve stops when it falls
   below ``tolerance``.
4. The indirect illuminance at a point x (normal n) is
   ``sum_j B_j F(x -> j)``: every patch is an area source of radiance
   ``B_j / pi`` and the direct light's machinery integrates its visible part
   exactly (occluders included).

Form factors F_ij (column j: every patch i towards patch j) come from the
closed form where no occluder's bounding box meets the pair's joint bounding
box (leaving out the patches' own convex owners, which hide nothing from their
faces), else from the point factor with occlusion at the Gauss points of i.

Memory: columns of F are computed when a patch first shoots and kept while
they fit in ``memory`` bytes (default 256 MiB: every column of up to 5792
patches); past that, columns are recomputed at each shot (slower, bounded
memory). More than ``max_patches`` patches raise
:class:`~isocsg.errors.ResourceLimitError` before anything is computed.

Assumptions: surfaces are Lambertian reflectors of uniform reflectance per
patch (radiosity constant over a patch: the discretisation error shrinks
with the patch size); light sources neither reflect nor block reflected
light; the room casts no shadow inside itself.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._validation import integer, scalar
from ..errors import InvalidLightError, InvalidParameterError, ResourceLimitError
from ..kinds import DEFAULT_RESOLUTION, Solid
from ..lighting.area import AreaLight, PolyhedronLight, as_light_list
from ..lighting.luminaire import PhotometricLight
from .convex_regions import ConvexPiece
from .direct import _fallback_point, illuminance, shadow_state
from .form_factors import pair_form_factors
from .lambert import _prepare
from .occluders import convex_pieces, occluder_list, shadow_pieces
from .patches import PatchSet, Room, surface_patches
from .pointflux import fan_quadrature, signed_solid_angles, visible_rings
from .visibility import PieceArrays, SourceArrays, visible_illuminance

__all__ = ["Interreflections", "RadiositySolution", "solve_radiosity", "indirect_illuminance"]

#: What lights a radiosity solve: area and polyhedron sources, and point luminaires.
SolveLight = AreaLight | PolyhedronLight | PhotometricLight

#: Default budget for cached form-factor columns (bytes).
DEFAULT_MEMORY = 256 * 2**20
#: Fields of a scene file's ``[interreflections]`` table.
TABLE_FIELDS = frozenset({"room_center", "room_size", "floor", "walls", "ceiling", "reflectances", "patch_size",
                          "refine", "order", "tolerance"})
#: Hard limit on the patch count (the per-patch Python work grows with it).
MAX_PATCHES = 50_000
#: Gauss points per direction on each fan triangle of a shaded patch's visible part (measured
#: distributions): the triangles reach across the whole patch, whatever ``order`` says.
FAN_ORDER = 8


@dataclass(frozen=True, slots=True)
class Interreflections:
    """Settings of the interreflection (radiosity) solve.

    Parameters
    ----------
    room : Room, optional
        A box room seen from inside (floor, walls, ceiling reflectances).
    reflectances : float or sequence of float, default 0
        Diffuse reflectance of the occluders, one value for all or one per
        occluder, in [0, 0.999]. Occluders of reflectance 0 stay black; only
        boxes and convex polyhedra may reflect.
    patch_size : float, default 0.5
        Largest patch edge before refinement (metres).
    refine : int, default 2
        Levels of four-way refinement of patches that straddle a direct
        shadow boundary (0 .. 6).
    order : int, default 3
        Gauss points per direction on each patch (1 .. 8).
    tolerance : float, default 1e-6
        Stop when the unshot flux falls below this fraction of the reflected
        flux.
    max_shots : int, optional
        Most shots (default ``1000`` times the patch count); past it the solve
        raises :class:`~isocsg.errors.ResourceLimitError`.
    memory : int, default 256 MiB
        Bytes for cached form-factor columns.
    max_patches : int, default 50000
        More patches raise :class:`~isocsg.errors.ResourceLimitError`.

    Raises
    ------
    InvalidParameterError
        On a value out of range (the message names the field).
    """

    room: Room | None = None
    reflectances: float | tuple[float, ...] = 0.0
    patch_size: float = 0.5
    refine: int = 2
    order: int = 3
    tolerance: float = 1e-6
    max_shots: int | None = None
    memory: int = DEFAULT_MEMORY
    max_patches: int = MAX_PATCHES

    def __post_init__(self) -> None:
        if self.room is not None and not isinstance(self.room, Room):
            raise InvalidParameterError(f"interreflections.room must be a Room, got {type(self.room).__name__}")
        rs = self.reflectances
        if isinstance(rs, (list, tuple, np.ndarray)):
            vals: float | tuple[float, ...] = tuple(
                scalar(f"interreflections.reflectances[{i}]", r, low=0.0, low_inclusive=True, high=0.999,
                       error=InvalidParameterError) for i, r in enumerate(rs))
        else:
            vals = scalar("interreflections.reflectances", rs, low=0.0, low_inclusive=True, high=0.999,
                          error=InvalidParameterError)
        object.__setattr__(self, "reflectances", vals)
        object.__setattr__(self, "patch_size", scalar("interreflections.patch_size", self.patch_size, low=0.0,
                                                      high=1e6, error=InvalidParameterError))
        object.__setattr__(self, "refine", integer("interreflections.refine", self.refine, low=0, high=6,
                                                   error=InvalidParameterError))
        object.__setattr__(self, "order", integer("interreflections.order", self.order, low=1, high=8,
                                                  error=InvalidParameterError))
        object.__setattr__(self, "tolerance", scalar("interreflections.tolerance", self.tolerance, low=1e-15,
                                                     high=1.0, error=InvalidParameterError))
        if self.max_shots is not None:
            object.__setattr__(self, "max_shots", integer("interreflections.max_shots", self.max_shots, low=1,
                                                          high=10**9, error=InvalidParameterError))
        object.__setattr__(self, "memory", integer("interreflections.memory", self.memory, low=0, high=2**40,
                                                   error=InvalidParameterError))
        object.__setattr__(self, "max_patches", integer("interreflections.max_patches", self.max_patches, low=1,
                                                        high=MAX_PATCHES, error=InvalidParameterError))

    @classmethod
    def from_dict(cls, table: Mapping[str, Any]) -> Interreflections:
        """Settings from a scene file's ``[interreflections]`` table.

        Fields: ``room_center``, ``room_size`` (the room, optional together),
        ``floor``, ``walls``, ``ceiling`` (its reflectances), ``reflectances``
        (the objects', one number or one per object), ``patch_size``,
        ``refine``, ``order``, ``tolerance``.

        Raises
        ------
        InvalidParameterError
            On an unknown or missing field or a bad value (named).

        Examples
        --------
        >>> Interreflections.from_dict({"room_center": [0, 0, 1.5], "room_size": [4, 4, 3], "walls": 0.6}).room.walls
        0.6
        """
        if not isinstance(table, Mapping):
            raise InvalidParameterError(f"interreflections must be a table, got {type(table).__name__}")
        unknown = sorted(set(table) - TABLE_FIELDS)
        if unknown:
            raise InvalidParameterError(
                f"interreflections.{unknown[0]}: unknown field (expected {', '.join(sorted(TABLE_FIELDS))})")
        room = None
        if ("room_center" in table) != ("room_size" in table):
            missing = "room_size" if "room_center" in table else "room_center"
            raise InvalidParameterError(f"interreflections.{missing}: missing (room_center and room_size go together)")
        if "room_center" in table:
            rho = {k: table[k] for k in ("floor", "walls", "ceiling") if k in table}
            room = Room(table["room_center"], table["room_size"], **rho)
        elif any(k in table for k in ("floor", "walls", "ceiling")):
            raise InvalidParameterError("interreflections.room_center: missing (floor, walls and ceiling need a room)")
        kw = {k: table[k] for k in ("patch_size", "refine", "order", "tolerance") if k in table}
        refl = table.get("reflectances", 0.0)
        return cls(room=room, reflectances=tuple(refl) if isinstance(refl, list) else refl, **kw)

    def indirect_illuminance(
        self, points: ArrayLike, normals: ArrayLike,
        lights: Sequence[SolveLight] | SolveLight,
        occluders: Sequence[Solid] | Solid = (), *, resolution: int = DEFAULT_RESOLUTION,
    ) -> NDArray[np.float64]:
        """Solve the radiosity for these lights and occluders; the indirect illuminance at points.

        What :func:`~isocsg.shadows.direct.illuminance` adds with ``interreflections=``.
        """
        return solve_radiosity(lights, occluders, self, resolution=resolution).indirect_illuminance(points, normals)

    def reflectance_list(self, n_occluders: int) -> list[float]:
        """One reflectance per occluder."""
        if isinstance(self.reflectances, tuple):
            if len(self.reflectances) != n_occluders:
                raise InvalidParameterError(
                    f"interreflections.reflectances must have one value per occluder ({n_occluders}), "
                    f"got {len(self.reflectances)}")
            return list(self.reflectances)
        return [float(self.reflectances)] * n_occluders


@dataclass(frozen=True, eq=False)
class RadiositySolution:
    """A converged radiosity solve.

    Attributes
    ----------
    patches : PatchSet
        The (refined) patches.
    radiosity : ndarray, shape (n,)
        Exitance B of each patch (lm/m^2 for radiances in cd/m^2).
    direct : ndarray, shape (n,)
        Mean direct illuminance E of each patch.
    residuals : ndarray
        Unshot over reflected flux after each shot (the convergence history).
    """

    patches: PatchSet
    radiosity: NDArray[np.float64]
    direct: NDArray[np.float64]
    residuals: NDArray[np.float64]
    occluders: tuple[Solid, ...] = field(repr=False)
    resolution: int = DEFAULT_RESOLUTION

    @property
    def shots(self) -> int:
        """Number of shots the solve took."""
        return len(self.residuals)

    @property
    def incident(self) -> NDArray[np.float64]:
        """Mean total illuminance of each patch, ``B / rho`` (direct + indirect)."""
        rho = self.patches.reflectance
        return np.where(rho > 0, self.radiosity / np.where(rho > 0, rho, 1.0), self.direct)

    def indirect_illuminance(self, points: ArrayLike, normals: ArrayLike) -> NDArray[np.float64]:
        """Indirect illuminance ``sum_j B_j F(x -> j)`` at points, occlusion included.

        Parameters
        ----------
        points, normals : array_like, shape (n, 3)

        Returns
        -------
        ndarray, shape (n,)
        """
        p, n = _prepare(points, normals)
        out = np.zeros(len(p))
        ps = self.patches
        for own in np.unique(ps.owner):
            idx = np.nonzero((ps.owner == own) & (self.radiosity > 0))[0]
            if len(idx) == 0:
                continue
            lights = [AreaLight(ps.polygon(int(k)), radiance=float(self.radiosity[k]) / math.pi) for k in idx]
            out += illuminance(p, n, lights, _without(self.occluders, int(own)), resolution=self.resolution)
        return out


def _without(occluders: Sequence[Solid], owner: int) -> list[Solid]:
    return [o for k, o in enumerate(occluders) if k != owner]


class _Blockers:
    """Bounding boxes of the occluders, to tell pairs that nothing can stand between."""

    def __init__(self, solids: Sequence[Solid], scale: float) -> None:
        b = np.array([np.asarray(o.bounds, dtype=np.float64) for o in solids]).reshape(-1, 2, 3)
        eps = 1e-9 * scale
        self.lo, self.hi = b[:, 0] + eps, b[:, 1] - eps

    def clear(self, lo: NDArray[np.float64], hi: NDArray[np.float64], own_a: NDArray[np.int64],
              own_b: NDArray[np.int64]) -> NDArray[np.bool_]:
        """Pairs (rows) whose joint box meets no occluder's box other than their owners'."""
        ok = np.ones(len(lo), dtype=bool)
        for k in range(len(self.lo)):
            meets = np.all(lo < self.hi[k], axis=1) & np.all(hi > self.lo[k], axis=1)
            ok &= ~meets | (own_a == k) | (own_b == k)
        return ok


def _refined(patches: PatchSet, interre: Interreflections, lights: list[SolveLight],
             solids: list[Solid], resolution: int) -> PatchSet:
    for _ in range(interre.refine):
        pts, _, idx = patches.samples(interre.order)
        # Corners pulled slightly inside, so that edges shared with other faces do not decide.
        cen = np.add.reduceat(patches.verts, patches.off[:-1], axis=0) / np.diff(patches.off)[:, None]
        owner_of_vert = np.repeat(np.arange(len(patches)), np.diff(patches.off))
        corners = patches.verts + 1e-6 * (cen[owner_of_vert] - patches.verts)
        allp = np.vstack([pts, corners])
        alli = np.concatenate([idx, owner_of_vert])
        st = shadow_state(allp, patches.normal[alli], lights, solids, resolution=resolution).astype(np.int64)
        lo = np.full(len(patches), 9)
        hi = np.full(len(patches), -1)
        np.minimum.at(lo, alli, st)
        np.maximum.at(hi, alli, st)
        split = (lo != hi) | (lo == 1)
        if not split.any():
            break
        _check_count(len(patches) + 3 * int(split.sum()), interre)
        patches = patches.split(split)
    return patches


def _check_count(n: int, interre: Interreflections) -> None:
    if n > interre.max_patches:
        raise ResourceLimitError(
            f"radiosity: {n} patches, over interreflections.max_patches = {interre.max_patches} "
            "(raise patch_size or lower refine)")


def _direct_means(patches: PatchSet, lights: list[SolveLight], solids: list[Solid],
                  blockers: _Blockers, order: int, resolution: int) -> NDArray[np.float64]:
    """Mean direct illuminance of each patch: closed form where unoccluded, else Gauss points."""
    n = len(patches)
    out = np.zeros(n)
    lo, hi = patches.bounds()
    pts, wts, idx = patches.samples(order)
    for light in lights:
        if isinstance(light, PhotometricLight):
            out += _point_means(patches, light, solids, blockers, (pts, wts, idx), resolution, order)
            continue
        for q in light.emitting_polygons():
            src = AreaLight(q, radiance=light.radiance)
            clear = blockers.clear(np.minimum(lo, q.min(axis=0)), np.maximum(hi, q.max(axis=0)),
                                   patches.owner, np.full(n, -2))
            k = np.nonzero(clear)[0]
            if len(k):
                verts = np.vstack([patches.verts, q])
                off = np.append(patches.off, patches.off[-1] + len(q))
                nrm = np.vstack([patches.normal, np.asarray(src.normal)])
                area = np.append(patches.area, src.area)
                f = pair_form_factors(verts, off, nrm, area, k, np.full(len(k), n))
                out[k] += math.pi * light.radiance * f
            sel = ~clear[idx]
            if sel.any():
                e = illuminance(pts[sel], patches.normal[idx[sel]], [src], solids, resolution=resolution)
                out += np.bincount(idx[sel], weights=wts[sel] * e, minlength=n) / patches.area
    return out


def _uniform_intensity(light: PhotometricLight) -> float | None:
    """The intensity (cd, multiplier included) of a luminaire that sends the same in every direction, else None."""
    ph = light.photometry
    v = ph.candela
    if ph.gamma_angles[0] == 0.0 and ph.gamma_angles[-1] == 180.0 and np.all(v == v.flat[0]):
        return light.multiplier * float(v.flat[0])
    return None


def _point_means(patches: PatchSet, light: PhotometricLight, solids: list[Solid], blockers: _Blockers,
                 rule: tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.int64]],
                 resolution: int, order: int) -> NDArray[np.float64]:
    """Mean direct illuminance of each patch from a point luminaire.

    Where nothing can hide the patch (no occluder's box meets the joint box
    of the luminaire and the patch, the patch's owner left out: a convex
    solid hides nothing from its own faces) the whole patch is lit; else its
    visible part is the patch minus the occluders' hard shadows
    (:func:`~isocsg.shadows.pointflux.visible_rings`). An isotropic luminaire
    sends exactly ``I Omega`` onto it (its solid angle); a measured
    distribution is integrated over it by Gauss points (the patch's rule on a
    whole patch, a signed fan of triangles on a visible part), the intensity
    interpolated as the standards say. A piece touching the luminaire leaves
    its patches to the exact illuminance at the patch's Gauss points.
    """
    n = len(patches)
    out = np.zeros(n)
    pts, wts, idx = rule
    P = np.asarray(light.position, dtype=np.float64)
    lo, hi = patches.bounds()
    clear = blockers.clear(np.minimum(lo, P), np.maximum(hi, P), patches.owner, np.full(n, -2))
    intensity = _uniform_intensity(light)
    done = clear.copy() if intensity is not None else np.zeros(n, dtype=bool)
    if intensity is not None:
        omega = np.maximum(signed_solid_angles(P, patches.verts, patches.off), 0.0)
        out[clear] = intensity * omega[clear] / patches.area[clear]
    pieces: dict[int, list[ConvexPiece]] = {}
    for k in np.nonzero(~clear)[0]:
        own = int(patches.owner[k])
        if own not in pieces:
            pieces[own] = convex_pieces(_without(solids, own), resolution=resolution)
        rings = visible_rings(P, patches.polygon(int(k)), pieces[own])
        if rings is None:
            continue
        done[k] = True
        if not rings:
            continue
        if intensity is not None:
            off = np.concatenate([[0], np.cumsum([len(r) for r in rings])])
            out[k] = intensity * float(signed_solid_angles(P, np.vstack(rings), off).sum()) / patches.area[k]
        else:
            q, w = fan_quadrature(rings, patches.normal[k], FAN_ORDER)
            out[k] = float(w @ _unshaded(light, q, patches.normal[k])) / patches.area[k]
    sel = ~done[idx]
    if sel.any():
        e = illuminance(pts[sel], patches.normal[idx[sel]], [light], solids, resolution=resolution)
        out += np.bincount(idx[sel], weights=wts[sel] * e, minlength=n) / patches.area
    return out


def _unshaded(light: PhotometricLight, pts: NDArray[np.float64], normal: NDArray[np.float64]) -> NDArray[np.float64]:
    """``I(C, gamma) cos / r^2`` at points of a plane (unit normal) the luminaire faces, no occlusion."""
    v = np.asarray(light.position, dtype=np.float64) - pts
    r2 = np.einsum("ij,ij->i", v, v)
    lvec = v / np.sqrt(r2)[:, None]
    return np.asarray(light.intensity_towards(-lvec) * np.maximum(lvec @ normal, 0.0) / r2, dtype=np.float64)


class _Columns:
    """Columns of the form-factor matrix (F_ij for every i, one j), cached within a byte budget."""

    def __init__(self, patches: PatchSet, solids: list[Solid], blockers: _Blockers, order: int,
                 resolution: int, memory: int, scale: float = 1.0) -> None:
        self.p, self.solids, self.blockers, self.resolution = patches, solids, blockers, resolution
        self.lo, self.hi = patches.bounds()
        self.pts, self.wts, self.idx = patches.samples(order)
        self.nrm = np.ascontiguousarray(patches.normal[self.idx])
        self.cache: dict[int, NDArray[np.float64]] = {}
        self.room_left = memory // max(8 * len(patches), 1)
        self.scale = scale
        self.pieces: dict[int, PieceArrays] = {}

    def _pieces(self, owner: int) -> PieceArrays:
        """Occluder pieces for sources on ``owner`` (left out), computed once per owner."""
        got = self.pieces.get(owner)
        if got is None:
            others = _without(self.solids, owner)
            pcs = shadow_pieces(others, self.pts, self.p.verts, resolution=self.resolution, scale=self.scale) \
                if others else []
            got = self.pieces[owner] = PieceArrays(pcs)
        return got

    def point_factors(self, sel: NDArray[np.bool_], j: int) -> NDArray[np.float64]:
        """``F(x -> j)`` at the selected Gauss points, occlusion included (the direct light's kernel)."""
        pa = self._pieces(int(self.p.owner[j]))
        src = SourceArrays([self.p.polygon(j)], [1.0 / math.pi], [0])
        pts, nrm = np.ascontiguousarray(self.pts[sel]), np.ascontiguousarray(self.nrm[sel])
        e, _, overflow = visible_illuminance(pts, nrm, src, pa, self.scale)
        for i in np.nonzero(overflow)[0]:
            e[i] = _fallback_point(pts[i], nrm[i], src, pa, self.scale)[0]
        return e

    def __call__(self, j: int) -> NDArray[np.float64]:
        got = self.cache.get(j)
        if got is not None:
            return got
        p = self.p
        n = len(p)
        col = np.zeros(n)
        clear = self.blockers.clear(np.minimum(self.lo, self.lo[j]), np.maximum(self.hi, self.hi[j]),
                                    p.owner, np.full(n, p.owner[j]))
        clear[j] = False
        k = np.nonzero(clear)[0]
        if len(k):
            col[k] = pair_form_factors(p.verts, p.off, p.normal, p.area, k, np.full(len(k), j))
        hidden = ~clear
        hidden[j] = False
        sel = hidden[self.idx]
        if sel.any():
            e = self.point_factors(sel, j)
            col += np.bincount(self.idx[sel], weights=self.wts[sel] * e, minlength=n) / p.area
        if self.room_left > 0:
            self.cache[j] = col
            self.room_left -= 1
        return col


def solve_radiosity(
    lights: Sequence[SolveLight] | SolveLight,
    occluders: Sequence[Solid] | Solid = (),
    interreflections: Interreflections | None = None,
    *,
    resolution: int = DEFAULT_RESOLUTION,
    progress: Callable[[int, float], None] | None = None,
) -> RadiositySolution:
    """Solve for the radiosity of the reflecting surfaces lit by the sources.

    Parameters
    ----------
    lights : AreaLight, PolyhedronLight, PhotometricLight or a sequence of them
        A point luminaire's mean over a patch is taken over the part of the
        patch it sees (the patch minus the occluders' hard shadows): exactly
        ``I Omega / A`` for an isotropic one
        (:meth:`~isocsg.lighting.luminaire.PhotometricLight.isotropic`; Omega
        the visible part's solid angle), by Gauss points over the visible
        part for a measured distribution.
    occluders : Solid or sequence of Solid, optional
        As for :func:`~isocsg.shadows.direct.illuminance`; those given a
        reflectance in ``interreflections`` also reflect.
    interreflections : Interreflections
        The room, the reflectances and the solve's settings.
    resolution : int, keyword-only
        Tessellation of curved occluders.
    progress : callable, optional
        Called as ``progress(shot, residual)`` after each shot.

    Returns
    -------
    RadiositySolution

    Raises
    ------
    InvalidParameterError
        On malformed settings, or a curved or CSG occluder given a reflectance.
    ResourceLimitError
        Past ``max_patches`` patches, or when ``max_shots`` shots do not reach
        the tolerance.

    Examples
    --------
    A closed white box lit by a small panel: the mean indirect illuminance of
    the walls is rho Phi / (A (1 - rho)) (the integrating-sphere relation).

    >>> room = Room((0, 0, 1), (2, 2, 2), floor=0.5, walls=0.5, ceiling=0.5)
    >>> lamp = AreaLight([(-.2, -.2, 1.9), (-.2, .2, 1.9), (.2, .2, 1.9), (.2, -.2, 1.9)], radiance=100)
    >>> sol = solve_radiosity(lamp, (), Interreflections(room=room, patch_size=1, tolerance=1e-10))
    >>> a = sol.patches.area
    >>> bool(np.isclose((a * (sol.incident - sol.direct)).sum(), 0.5 * lamp.flux / 0.5, rtol=1e-8))
    True
    """
    interre = interreflections if interreflections is not None else Interreflections()
    if not isinstance(interre, Interreflections):
        raise InvalidParameterError(f"interreflections must be an Interreflections, got {type(interre).__name__}")
    light_list = _solve_lights(lights)
    solids = occluder_list(occluders, resolution)
    patches = surface_patches(interre.room, solids, interre.reflectance_list(len(solids)), interre.patch_size)
    _check_count(len(patches), interre)
    if len(patches) and light_list:
        patches = _refined(patches, interre, light_list, solids, resolution)
    ext = [patches.verts] + [np.asarray(o.bounds, dtype=np.float64) for o in solids]
    ext += [np.asarray([li.position]) if isinstance(li, PhotometricLight) else np.vstack(li.emitting_polygons())
            for li in light_list]
    allpts = np.vstack(ext) if ext else np.zeros((1, 3))
    scale = float(max(np.max(np.ptp(allpts, axis=0)), np.max(np.abs(allpts)), 1e-300))
    blockers = _Blockers(solids, scale)
    n = len(patches)
    direct = _direct_means(patches, light_list, solids, blockers, interre.order, resolution) if n else np.zeros(0)
    B = patches.reflectance * direct
    unshot = B.copy()
    columns = _Columns(patches, solids, blockers, interre.order, resolution, interre.memory, scale)
    residuals: list[float] = []
    max_shots = interre.max_shots if interre.max_shots is not None else 1000 * max(n, 1)
    a = patches.area
    while n:
        reflected = float(a @ B)
        res = float(a @ unshot) / reflected if reflected > 0 else 0.0
        if res <= interre.tolerance:
            break
        if len(residuals) >= max_shots:
            raise ResourceLimitError(
                f"radiosity: residual {res:.3g} after {max_shots} shots, above interreflections.tolerance = "
                f"{interre.tolerance:g} (raise max_shots or tolerance)")
        j = int(np.argmax(a * unshot))
        dB = patches.reflectance * columns(j) * unshot[j]
        B += dB
        unshot += dB
        unshot[j] = 0.0
        residuals.append(float(a @ unshot) / float(a @ B))
        if progress is not None:
            progress(len(residuals), residuals[-1])
    return RadiositySolution(patches, B, direct, np.asarray(residuals), tuple(solids), resolution)


def _solve_lights(lights: Any) -> list[SolveLight]:
    """Area and polyhedron lights as :func:`~isocsg.lighting.area.as_light_list` takes them, and point luminaires."""
    if isinstance(lights, PhotometricLight):
        return [lights]
    if isinstance(lights, (list, tuple)):
        others = [li for li in lights if not isinstance(li, PhotometricLight)]
        for i, li in enumerate(lights):
            if not isinstance(li, (AreaLight, PolyhedronLight, PhotometricLight)):
                raise InvalidLightError(f"lights[{i}] must be an AreaLight, a PolyhedronLight or a PhotometricLight, "
                                        f"got {type(li).__name__}")
        as_light_list(others)
        return list(lights)
    return list(as_light_list(lights))


def indirect_illuminance(
    points: ArrayLike,
    normals: ArrayLike,
    lights: Sequence[SolveLight] | SolveLight,
    occluders: Sequence[Solid] | Solid = (),
    interreflections: Interreflections | None = None,
    *,
    resolution: int = DEFAULT_RESOLUTION,
) -> NDArray[np.float64]:
    """Illuminance at points from light reflected by the surfaces (no direct part).

    Solves :func:`solve_radiosity` and evaluates
    :meth:`RadiositySolution.indirect_illuminance`; add
    :func:`~isocsg.shadows.direct.illuminance` for the total, or call it with
    ``interreflections=``.

    Returns
    -------
    ndarray, shape (n,)
    """
    sol = solve_radiosity(lights, occluders, interreflections, resolution=resolution)
    return sol.indirect_illuminance(points, normals)

