"""Building (and caching) the isoluminance representation of a primitive.

:func:`build_laminae` returns a :class:`~isocsg.laminae.model.LaminaSet`:

- ``laminae``: the seed's polygons, per light: sphere circles, truncus quads
  ``phi_i`` and ends, polyhedron faces; with a specular material also the
  laminae of the seed's *virtual light source* (the half-way direction
  between the light and the eye, seen from the primitive's centre), whose
  diffuse contours approximate the highlight's.
- ``bands``: what the renderer fills. The primitive's base surface mesh
  (vertices on the surface with exact normals, the first light's contour
  lines already on edges) is cut along the level lines of every contour
  family (one diffuse family per light, two Phong families per light with a
  specular material). Several lights give the seed's *composite contours*:
  the pieces where every family's band is constant. Each piece is filled
  with ``ambient + sum of its bands' values``, for the outward normal
  (``value_out``) and for the reversed normal (``value_in``, the inside of a
  CSG cut). A piece whose field is constant (a polyhedron face or a truncus
  end under a directional light) takes its exact value, as a single lamina.

Diffuse sets do not depend on the eye and are cached: rendering the same
scene from another viewpoint reuses them. Specular sets depend on the eye and
are built for each one.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .._cache import ByteCache
from .._jit import njit
from .._validation import integer, vector3
from ..bands.families import GRAZING, FieldFamily, diffuse_family, incidence, specular_families
from ..bands.lights import light_axis
from ..bands.surface import Surface
from ..errors import InvalidLightError, InvalidParameterError
from ..kinds.base import Primitive, provides
from ..lighting.lights import DirectionalLight, PointLight
from ..lighting.shading import TERMINATOR_COSINE, Material
from .model import BandMesh, ContourFamily, Lamina, LaminaSet
from .split import MAX_PIECES, split_by_levels

__all__ = ["build_laminae", "build_bands", "clear_cache", "cache_info", "cache_bytes", "MAX_CONTOURS"]

#: Largest number of contours per family.
MAX_CONTOURS = 4096
#: The tessellation's segments around a curved primitive by default
#: (``sphere.LONGITUDES``, ``truncus.GENERATORS``); see :func:`build_bands`.
DEFAULT_SEGMENTS = 128

Light = PointLight | DirectionalLight

#: Most bytes of lamina sets kept by the cache (never more than a quarter of
#: :func:`isocsg.limits.memory_budget`); the least recently used go first.
#: A renderer's prepared meshes keep the band meshes they were made from (by
#: request, so a renderer asks this cache only for what it does not hold), and
#: both caches' sets are alive at once: 256 MiB here leaves the memory to the
#: renderer (the union of 1000 spheres at 1024 x 1024 peaked at 1.54 GB with
#: 512 MiB under a 3 GB budget).
CACHE_BYTES = 256 << 20

# key -> lamina set (its bytes as counted by _nbytes); within a quarter of the memory budget.
_CACHE = ByteCache(lambda: CACHE_BYTES, share=4)
_LOCK = threading.Lock()
_STATS = {"hits": 0, "misses": 0}


def _nbytes(ls: LaminaSet) -> int:
    """Bytes held by a lamina set: its arrays, and 256 per lamina object."""
    b = ls.bands
    n = sum(a.nbytes for a in (b.vertices, b.triangles, b.value_out, b.value_in, b.band))
    return n + sum(lam.vertices.nbytes + 256 for lam in ls.laminae) + 1024


def clear_cache() -> None:
    """Forget every cached lamina set."""
    with _LOCK:
        _CACHE.clear()
        _STATS.update(hits=0, misses=0)


def cache_info() -> dict[str, int]:
    """Cache statistics: ``hits``, ``misses`` and ``size``.

    The cache keeps at most :data:`CACHE_BYTES` of lamina sets (and a quarter
    of the memory budget), dropping the least recently used first;
    :func:`cache_bytes` tells how many it holds.

    Examples
    --------
    >>> clear_cache(); cache_info()
    {'hits': 0, 'misses': 0, 'size': 0}
    """
    with _LOCK:
        return {**_STATS, "size": len(_CACHE)}


def cache_bytes() -> int:
    """Bytes of the lamina sets the cache holds (arrays, and 256 per lamina object)."""
    with _LOCK:
        return _CACHE.nbytes


def _check_lights(lights: Sequence[Any]) -> tuple[Light, ...]:
    if isinstance(lights, (PointLight, DirectionalLight)):
        lights = (lights,)
    try:
        out = tuple(lights)
    except TypeError:
        raise InvalidLightError(f"lights must be a sequence of lights, got {type(lights).__name__}") from None
    for i, light in enumerate(out):
        if not isinstance(light, (PointLight, DirectionalLight)):
            raise InvalidLightError(
                f"lights[{i}]: isoluminance contours need PointLight or DirectionalLight, got {type(light).__name__}"
            )
    return out


def build_laminae(
    primitive: Primitive,
    lights: Sequence[Light],
    material: Material | None = None,
    contours: int = 64,
    *,
    eye: ArrayLike | None = None,
) -> LaminaSet:
    """The isoluminance laminae and band mesh of one primitive.

    Parameters
    ----------
    primitive : Sphere, Truncus (Cylinder, Cone), Box or ConvexPolyhedron
    lights : sequence of PointLight or DirectionalLight
        Each light adds a contour family (composite contours for several).
    material : Material, optional
        Defaults to ``Material()``. With ``ks > 0`` the set depends on ``eye``.
    contours : int, default 64
        N, the contours per family (1 .. 4096).
    eye : array_like, shape (3,), optional
        The viewpoint; needed only for a specular material.

    Returns
    -------
    LaminaSet
        Cached for diffuse materials: the same object is returned for the same
        primitive, lights, material and N, whatever the eye.

    Raises
    ------
    InvalidParameterError
        On a bad ``contours``, ``material`` or ``eye`` (or a missing eye with ``ks > 0``),
        or when ``primitive`` is not a primitive.
    InvalidLightError
        When a light is not a point or directional light.

    Notes
    -----
    A point light inside a primitive is not an error: the primitive's outer
    surface faces away from it everywhere and is unlit (ambient only), while
    its reversed normals (``value_in``) are lit.

    Examples
    --------
    >>> from isocsg import PointLight, Sphere
    >>> ls = build_laminae(Sphere((0, 0, 0), 1.0), [PointLight((0, 0, 5))], contours=8)
    >>> len(ls.laminae), ls.laminae[0].kind
    (8, 'contour')
    >>> ls is build_laminae(Sphere((0, 0, 0), 1.0), [PointLight((0, 0, 5))], contours=8, eye=(9, 9, 9))
    True
    >>> float(ls.bands.value_out.min()), round(float(ls.bands.value_out.max()), 3)
    (0.1, 0.85)
    """
    return _cached(primitive, lights, material, contours, eye, None, bands_only=False)


def build_bands(
    primitive: Primitive,
    lights: Sequence[Light],
    material: Material | None = None,
    contours: int = 64,
    *,
    eye: ArrayLike | None = None,
    segments: int | None = None,
    hidden: ArrayLike | None = None,
    keep: bool = True,
) -> LaminaSet:
    """The band mesh of one primitive, without the laminae (what a renderer fills).

    The same as :func:`build_laminae` (same parameters, checks and cache)
    except that the paper's lamina polygons and the contour family
    descriptions, which only inspection and the SVG output read, are not
    built: the returned set's ``laminae`` and ``families`` are empty, and its
    ``bands`` are equal, array for array, to :func:`build_laminae`'s. When the
    full set is cached its bands are returned (the same objects), and a full
    build after this one reuses these bands.

    Parameters
    ----------
    segments : int, optional
        The tessellation's least number of segments around a curved
        primitive (a sphere's longitudes, a truncus's uniform generators;
        8 .. 4096): fewer than the defaults (128) for a primitive small on
        screen, as a renderer's level of detail asks. The fields' own needs
        (contour lines, bending near a point light) still refine it. ``None``:
        the defaults. Other kinds ignore it. Part of the cache key.
    hidden : array_like, shape (2, 3), optional
        ``(lo, hi)``: a box outside which nothing of this primitive can be
        seen (a renderer knows it for a CSG leaf: the box of the whole
        object, which holds every visible point). A part of the surface (a
        truncus end, a polyhedron face) lying entirely beyond one of the
        box's faces is not cut along the level lines: it keeps its base
        triangles with the ambient value (the exact value where its field
        is constant), so that its geometry still bounds the solid at the
        cost of its base mesh alone. Other parts are cut as without it.
        ``None``: every part is cut. Part of the cache key.
    keep : bool, default True
        Whether a set built here is kept in the cache. ``False`` for a caller
        that keeps what it needs itself (a renderer's prepared band meshes of
        a large tree): the cache would otherwise hold a second, different
        share of the same model (up to :data:`CACHE_BYTES` more memory). A
        cached set is returned either way.

    Returns
    -------
    LaminaSet
        With empty ``laminae`` and ``families`` unless the full set was cached.

    Raises
    ------
    InvalidParameterError, InvalidLightError
        As :func:`build_laminae`.

    Examples
    --------
    >>> from isocsg import PointLight, Sphere
    >>> ls = build_bands(Sphere((0, 0, 0), 1.0), [PointLight((0, 0, 5))], contours=8)
    >>> len(ls.laminae), ls.bands.n_triangles > 0
    (0, True)
    >>> full = build_laminae(Sphere((0, 0, 0), 1.0), [PointLight((0, 0, 5))], contours=8)
    >>> full.bands is ls.bands, len(full.laminae)
    (True, 8)

    A cylinder whose ends lie outside the box where it can be seen (a hole
    through a plate 0.4 thick) keeps its ends uncut:

    >>> from isocsg import Cylinder
    >>> hole = Cylinder((0, 0, 0), (0, 0, 1.2), 0.1)
    >>> cut = build_bands(hole, [PointLight((2, -3, 5))], contours=16).bands
    >>> seen = build_bands(hole, [PointLight((2, -3, 5))], contours=16, hidden=[(-2, -2, -0.2), (2, 2, 0.2)]).bands
    >>> bool(seen.n_triangles < cut.n_triangles)
    True
    """
    box = None if hidden is None else _hidden_box(hidden)
    return _cached(primitive, lights, material, contours, eye, segments, bands_only=True, hidden=box, keep=bool(keep))


def _hidden_box(hidden: ArrayLike) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
    """``hidden`` checked: a finite ``(lo, hi)`` box with ``lo <= hi``, as tuples (a cache key)."""
    try:
        box = np.asarray(hidden, dtype=np.float64)
    except (TypeError, ValueError):
        raise InvalidParameterError(
            "hidden must be a (2, 3) array of numbers "
            f"(lo, hi), got {type(hidden).__name__}"
        ) from None
    if box.shape != (2, 3):
        raise InvalidParameterError(f"hidden must have shape (2, 3) (lo, hi), got {box.shape}")
    if not np.all(np.isfinite(box)) or np.any(box[0] > box[1]):
        raise InvalidParameterError(f"hidden must be a finite box with lo <= hi, got {box.tolist()}")
    lo, hi = box.tolist()
    return (tuple(lo), tuple(hi))  # type: ignore[return-value]


def _cached(
    primitive: Primitive, lights: Sequence[Light], material: Material | None, contours: int, eye: ArrayLike | None,
    segments: int | None, *, bands_only: bool, hidden: tuple[Any, Any] | None = None, keep: bool = True,
) -> LaminaSet:
    if not isinstance(primitive, Primitive) or not provides(primitive, "band_surface"):
        raise InvalidParameterError(
            "primitive must be a Sphere, Truncus, Box, ConvexPolyhedron "
            "or another registered kind with a band surface, "
            f"got {type(primitive).__name__}"
        )
    lights_t = _check_lights(lights)
    mat = Material() if material is None else material
    if not isinstance(mat, Material):
        raise InvalidParameterError(f"material must be a Material, got {type(mat).__name__}")
    n = integer("contours", contours, low=1, high=MAX_CONTOURS, error=InvalidParameterError)
    specular = mat.ks > 0 and len(lights_t) > 0
    eye_t: tuple[float, ...] | None = None
    if specular:
        if eye is None:
            raise InvalidParameterError("eye is needed for a specular material (ks > 0)")
        eye_t = tuple(vector3("eye", eye, error=InvalidParameterError))
    _check_size(n, len(lights_t), specular)
    if segments is not None:
        segments = integer("segments", segments, low=8, high=MAX_CONTOURS, error=InvalidParameterError)
        if segments >= DEFAULT_SEGMENTS:
            segments = None  # the defaults
    key: tuple[Any, ...] = (primitive, lights_t, mat, n, eye_t)
    part = (*key, "bands") if segments is None else (*key, "bands", segments)  # a set without laminae
    if hidden is not None:
        part = (*part, "hidden", hidden)
    full_serves = bands_only and segments is None and hidden is None
    with _LOCK:
        # a full set serves a bands-only request too
        for k in (key, part) if full_serves else (part,) if bands_only else (key,):
            hit = _CACHE.get(k)
            if hit is not None:
                _STATS["hits"] += 1
                return hit  # type: ignore[no-any-return]
        _STATS["misses"] += 1
        # A full build after a bands-only one keeps its bands (the same objects).
        known = None if bands_only else _CACHE.pop(part)
    eye_a = None if eye_t is None else np.asarray(eye_t)
    if bands_only:
        out = LaminaSet(primitive, (), (), _build_bands(primitive, lights_t, mat, n, eye_a, segments, hidden),
                        view_dependent=eye_a is not None)
        key = part
    else:
        out = _build(primitive, lights_t, mat, n, eye_a, None if known is None else known.bands)
    if not keep:
        return out
    size = _nbytes(out)
    with _LOCK:
        _CACHE.put(key, out, size)
    return out


def _check_size(n: int, n_lights: int, specular: bool) -> None:
    """Refuse, before building anything, a request whose composite pieces cannot fit.

    One family (one diffuse light) works up to :data:`MAX_CONTOURS` on every
    kind. Two families crossing on a part cut it into about ``2 N**2``
    triangles (each family has ``N`` levels across every part it varies on),
    so ``F`` families (a diffuse one per light, and two Phong ones per light
    for a specular material) need about ``F (F - 1) N**2`` of them.
    """
    fams = n_lights * (3 if specular else 1)
    pairs = fams * (fams - 1) // 2
    if pairs and 2 * n * n * pairs > MAX_PIECES:
        most = int(math.isqrt(MAX_PIECES // (2 * pairs)))
        raise InvalidParameterError(
            f"contours: {n} contours with {n_lights} light(s){' and a specular material' if specular else ''} "
            f"would cut about {2 * n * n * pairs} band triangles (more than {MAX_PIECES}); "
            f"use at most {most} contours, fewer lights or a diffuse material"
        )


# ----------------------------------------------------------------------------- per primitive


def _origin(primitive: Primitive) -> NDArray[np.float64]:
    """The local origin the band mesh is built around (the primitive's centre)."""
    if hasattr(primitive, "center_array"):
        return primitive.center_array.copy()
    lo, hi = primitive.bounds
    return 0.5 * (lo + hi)


def _surface(
    primitive: Primitive, lights: tuple[Light, ...], n: int, eye: NDArray[np.float64] | None, shininess: float,
    weights: tuple[float, float] = (1.0, 1.0), segments: int | None = None, hidden: tuple[Any, Any] | None = None,
) -> Surface:
    # A kind that knows which of its parts lie outside the box ``hidden`` need not refine them.
    return primitive.band_surface(list(lights), n, eye, shininess, weights, segments, hidden=hidden)


def _paper_laminae(
    primitive: Primitive, light: Light, n: int,
) -> list[tuple[NDArray[np.float64], NDArray[np.float64], float, str]]:
    # curved kinds without planar contours (an ellipsoid): none, the bands carry the image
    return primitive.contour_laminae(light, n)


def _family_description(primitive: Primitive, light: Light, index: int, n: int, mat: Material) -> ContourFamily:
    """The inspectable contour family of one light (plane normal and offsets of the laminae)."""
    family = primitive.contour_family(light, n)
    w, offsets, levels = (np.zeros(3), np.zeros(0), np.zeros(0)) if family is None else family
    lv = np.asarray(levels, dtype=np.float64)
    mids = np.maximum(0.5 * (lv[:-1] + lv[1:]), 0.0)
    values = mat.ambient + mat.kd * light.intensity * mids if len(lv) > 1 else np.zeros(0)
    return ContourFamily(w, np.asarray(offsets, dtype=np.float64), lv, values, index)


def _virtual_light(primitive: Primitive, light: Light, eye: NDArray[np.float64]) -> DirectionalLight | None:
    """The seed's virtual light source: half-way between the light and the eye, from the centre."""
    lo, hi = primitive.bounds
    c = getattr(primitive, "center_array", 0.5 * (lo + hi))
    ln = light_axis(c, light) if isinstance(light, PointLight) else light.unit_direction
    v = eye - c
    nv = float(np.linalg.norm(v))
    if nv == 0:
        return None
    h = ln + v / nv
    if float(np.linalg.norm(h)) < 1e-12:
        return None
    return DirectionalLight(tuple(h / np.linalg.norm(h)), light.intensity)


def _build_bands(
    primitive: Primitive, lights: tuple[Light, ...], mat: Material, n: int, eye: NDArray[np.float64] | None,
    segments: int | None = None, hidden: tuple[Any, Any] | None = None,
) -> BandMesh:
    """The band mesh alone: the primitive's surface cut along its contour families' level lines."""
    origin = _origin(primitive)
    eye_local = None if eye is None else eye - origin
    surf = _surface(primitive, lights, n, eye_local, float(mat.shininess), (float(mat.kd), float(mat.ks)), segments,
                    hidden)
    fams: list[FieldFamily] = []
    for j, light in enumerate(lights):
        fams.append(diffuse_family(j, light, mat, incidence(light, surf.vertices, surf.normals, surf.origin)))
        if eye is not None:
            fams.extend(specular_families(j, light, mat, surf.vertices, surf.normals, eye - surf.origin, surf.origin))
    return _cut(surf, fams, mat, n, hidden)


def _build(
    primitive: Primitive, lights: tuple[Light, ...], mat: Material, n: int, eye: NDArray[np.float64] | None,
    bands: BandMesh | None = None,
) -> LaminaSet:
    """The full set: the band mesh (built unless given) and the paper's laminae and families."""
    if bands is None:
        bands = _build_bands(primitive, lights, mat, n, eye)
    laminae: list[Lamina] = []
    for j, light in enumerate(lights):
        w = light.intensity
        for verts, nrm, cos, kind in _paper_laminae(primitive, light, n):
            value = mat.ambient + mat.kd * w * max(cos, 0.0)
            family = j if kind == "contour" else -1
            laminae.append(Lamina(verts, nrm, float(value), float(nrm @ verts[0]), kind, family))
        if eye is not None:
            virtual = _virtual_light(primitive, light, eye)
            if virtual is not None:
                for verts, nrm, cos, _kind in _paper_laminae(primitive, virtual, n):
                    value = mat.ks * w * max(cos, 0.0) ** mat.shininess
                    laminae.append(Lamina(verts, nrm, float(value), float(nrm @ verts[0]), "specular", j))
    if not lights:
        for verts, nrm, _cos, kind in _paper_laminae(primitive, DirectionalLight((0.0, 0.0, 1.0), 0.0), n):
            laminae.append(Lamina(verts, nrm, float(mat.ambient), float(nrm @ verts[0]), kind, -1))
    families = tuple(_family_description(primitive, light, j, n, mat) for j, light in enumerate(lights))
    return LaminaSet(primitive, tuple(laminae), families, bands, view_dependent=eye is not None)


def _cut(
    surf: Surface, fams: list[FieldFamily], mat: Material, n: int, hidden: tuple[Any, Any] | None = None,
) -> BandMesh:
    """Cut the surface along every family's levels and give each piece its value.

    Each smooth part (sphere, truncus side or end, polyhedron face) is cut at
    its own levels (:meth:`FieldFamily.levels`, from the field's range on the
    part), so that a part whose field spans a narrow range still gets ``N``
    steps across it. Parts share no vertex, so cutting them apart changes
    nothing along their common rims (the fields differ there anyway). Work
    is done relative to the surface's origin; the output is in world
    coordinates. Parts lying entirely outside ``hidden`` (see :func:`build_bands`) are not cut.
    """
    local, triangles = surf.vertices, surf.triangles
    if not fams:
        t = len(triangles)
        amb = np.full(t, mat.ambient)
        return BandMesh(surf.origin + local, triangles.astype(np.int32), amb, amb.copy(), np.zeros(t, np.int32))
    fields = np.stack([f.field for f in fams], axis=1)
    tri_part = surf.parts[triangles[:, 0]]
    k = len(fams)
    tables_out: list[list[NDArray[np.float64]]] = [[] for _ in fams]
    tables_in: list[list[NDArray[np.float64]]] = [[] for _ in fams]
    offsets = np.zeros(k, np.int64)
    pieces_v, pieces_f, pieces_t, pieces_b, pieces_p = [], [], [], [], []
    n_v = 0
    counts = np.bincount(tri_part)
    single = np.count_nonzero(counts) == 1
    order = np.argsort(tri_part, kind="stable")
    ends = np.cumsum(counts)
    remap = np.full(len(local), -1, np.int64)
    box = None if hidden is None else (np.asarray(hidden[0]) - surf.origin, np.asarray(hidden[1]) - surf.origin)
    for part in np.flatnonzero(counts):
        if single:
            vertices, values, tri = local, fields, triangles
        else:
            tri = triangles[order[ends[part] - counts[part]: ends[part]]]
            used = np.zeros(len(local), bool)
            used[tri.reshape(-1)] = True
            used = np.flatnonzero(used)
            remap[used] = np.arange(len(used))
            vertices, values, tri = local[used], fields[used], remap[tri]
        _unlight_grazed(values, fams)
        unseen = box is not None and _outside(vertices, *box)
        band = np.zeros((len(tri), k), np.int64)
        for i, fam in enumerate(fams):
            col = _lit_side(values, fams, i)
            if unseen or float(col.max() - col.min()) <= 1e-12:
                # Constant on the part: every piece takes the exact value (see _pieces).
                lv = np.zeros(0)
            else:
                lv = fam.levels(col, n)
                out = split_by_levels(vertices, tri, values, i, lv)
                vertices, values, tri = out.vertices, out.values, out.triangles
                band = band[out.parent]
                band[:, i] = out.band
            t_out, t_in = fam.tables(lv) if len(lv) else (np.zeros(1), np.zeros(1))
            band[:, i] += offsets[i]
            offsets[i] += len(t_out)
            tables_out[i].append(t_out)
            tables_in[i].append(t_in)
        pieces_v.append(vertices)
        pieces_f.append(values)
        pieces_t.append(tri + n_v)
        pieces_b.append(band)
        pieces_p.append(np.full(len(tri), part, np.int64))
        n_v += len(vertices)
    vertices = np.vstack(pieces_v)
    values = np.vstack(pieces_f)
    triangles = np.vstack(pieces_t)
    band = np.vstack(pieces_b)
    part_of = np.concatenate(pieces_p)
    # Each family's band values side by side, padded to the longest table.
    width = int(offsets.max())
    tables = np.zeros((2, k, width))
    for i in range(k):
        tables[0, i, : offsets[i]] = np.concatenate(tables_out[i])
        tables[1, i, : offsets[i]] = np.concatenate(tables_in[i])
    kinds = np.array([_KIND_CODES[f.kind] for f in fams], np.int64)
    # The diffuse family of each specular family's light: it says which side of the terminator a piece is on.
    diffuse_of = {f.light_index: i for i, f in enumerate(fams) if f.kind == "diffuse"}
    partner = np.array([-1 if f.kind == "diffuse" else diffuse_of.get(f.light_index, -1) for f in fams], np.int64)
    laws = np.array([(f.exponent, f.weight_out, f.weight_in) for f in fams], np.float64)
    scale = float(np.max(np.abs(vertices))) if len(vertices) else 1.0
    tri32 = np.empty((len(triangles), 3), np.int32)
    v_out = np.empty(len(triangles))
    v_in = np.empty(len(triangles))
    kept = np.empty(len(triangles), np.int64)
    m = _pieces(vertices, triangles, values, band, tables, kinds, laws, partner, float(mat.ambient),
                1e-24 * scale**2, tri32, v_out, v_in, kept)
    band = band[kept[:m]]
    if k == 1:
        composite = band[:, 0]
    else:
        # One id per distinct (part, band of each family), built column by column
        # with 1-d uniques (much faster than a unique over rows).
        composite = part_of[kept[:m]]
        for i in range(k):
            ranks = np.unique(composite, return_inverse=True)[1].reshape(-1).astype(np.int64)
            key = ranks * int(offsets[i]) + band[:, i]
            composite = key
        composite = np.unique(composite, return_inverse=True)[1].reshape(-1)
    return BandMesh(surf.origin + vertices, tri32[:m], v_out[:m], v_in[:m], composite.astype(np.int32))


_KIND_CODES = {"diffuse": 0, "specular_out": 1, "specular_in": 2}


def _lit_side(values: NDArray[np.float64], fams: list[FieldFamily], i: int) -> NDArray[np.float64]:
    """Family ``i``'s column as its levels see it: a Phong field is -1 where its side is unlit
    (beyond ``TERMINATOR_COSINE`` by its light's diffuse field), so that its levels span the
    lit vertices only and an unlit part is not cut; the column cut keeps the smooth field."""
    fam = fams[i]
    col = values[:, i]
    if fam.kind == "diffuse":
        return col
    d = next((j for j, f in enumerate(fams) if f.kind == "diffuse" and f.light_index == fam.light_index), None)
    if d is None:
        return col
    side = 1.0 if fam.kind == "specular_out" else -1.0
    return np.where(side * values[:, d] >= -TERMINATOR_COSINE, col, -1.0)


def _outside(local: NDArray[np.float64], lo: NDArray[np.float64], hi: NDArray[np.float64]) -> bool:
    """Whether the points ``local`` all lie strictly beyond one face of the box ``[lo, hi]``.

    The part's triangles are then outside too (they are convex combinations of their corners)."""
    if not len(local):
        return False
    return bool((local.min(axis=0) > hi).any() or (local.max(axis=0) < lo).any())


def _unlight_grazed(values: NDArray[np.float64], fams: list[FieldFamily]) -> None:
    """No highlight on a part that lies in a light's plane (its ``n . l`` is 0 up to rounding).

    There the exact shading has no Phong term (``cos_i = 0``), but the rounded cosine is
    ``+-1e-17`` and vertices where it came out positive would carry the full grazing highlight
    ``(-l . v) ** n`` into the bands. ``values`` holds one part's columns and is changed in place.
    """
    diffuse = {f.light_index: i for i, f in enumerate(fams) if f.kind == "diffuse"}
    for i, fam in enumerate(fams):
        d = diffuse.get(fam.light_index)
        if fam.kind == "diffuse" or d is None or not len(values):
            continue
        if float(np.max(np.abs(values[:, d]))) <= GRAZING:
            values[:, i] = -1.0


@njit(cache=True, nogil=True)
def _lit(values: NDArray[np.float64], a: int, b: int, c: int, diffuse: int, side: float) -> bool:
    """Whether a piece is lit on ``side`` (+1 outward, -1 reversed) by its diffuse family's light."""
    if diffuse < 0:
        return True
    return side * (values[a, diffuse] + values[b, diffuse] + values[c, diffuse]) / 3.0 > TERMINATOR_COSINE


@njit(cache=True, nogil=True)
def _pieces(
    vertices: NDArray[np.float64], triangles: NDArray[np.int64], values: NDArray[np.float64], band: NDArray[np.int64],
    tables: NDArray[np.float64], kinds: NDArray[np.int64], laws: NDArray[np.float64], partner: NDArray[np.int64],
    ambient: float, min_area2: float,
    tri_out: NDArray[np.int32], v_out: NDArray[np.float64], v_in: NDArray[np.float64], kept: NDArray[np.int64],
) -> int:
    """The pieces that cover pixels and their values; returns their number.

    Pieces of zero area (a cone's apex, cuts through a vertex) are dropped.
    A piece takes ``ambient`` plus, per family, its band's table entry or,
    where the family's field is constant ``c`` on it (within 1e-12), the exact
    value: diffuse ``weight_out * max(0, c)`` outward and ``weight_in *
    max(0, -c)`` reversed; specular ``weight_out * max(0, c) ** exponent`` on
    the family's own side (see :class:`FieldFamily`). A specular family counts
    only on pieces lit on its side: the mean of its light's diffuse field
    (``partner``) over the piece beyond ``TERMINATOR_COSINE``. Every piece lies
    on one side of the terminator (0 is a diffuse level), so the highlight
    ends exactly there, and a part on the terminator shows none.
    """
    m = 0
    for t in range(triangles.shape[0]):
        a, b, c = triangles[t, 0], triangles[t, 1], triangles[t, 2]
        ux, uy, uz = vertices[b, 0] - vertices[a, 0], vertices[b, 1] - vertices[a, 1], vertices[b, 2] - vertices[a, 2]
        wx, wy, wz = vertices[c, 0] - vertices[a, 0], vertices[c, 1] - vertices[a, 1], vertices[c, 2] - vertices[a, 2]
        cx, cy, cz = uy * wz - uz * wy, uz * wx - ux * wz, ux * wy - uy * wx
        if not math.sqrt(cx * cx + cy * cy + cz * cz) > min_area2:
            continue
        o = ambient
        n = ambient
        for i in range(kinds.shape[0]):
            f0, f1, f2 = values[a, i], values[b, i], values[c, i]
            if max(f0, f1, f2) - min(f0, f1, f2) <= 1e-12:
                p = max(f0, 0.0)
                if kinds[i] == 0:
                    o += laws[i, 1] * p
                    n += laws[i, 2] * max(-f0, 0.0)
                elif kinds[i] == 1:
                    if _lit(values, a, b, c, partner[i], 1.0):
                        o += laws[i, 1] * p ** laws[i, 0]
                else:
                    if _lit(values, a, b, c, partner[i], -1.0):
                        n += laws[i, 1] * p ** laws[i, 0]
            elif kinds[i] == 0 or _lit(values, a, b, c, partner[i], 1.0 if kinds[i] == 1 else -1.0):
                o += tables[0, i, band[t, i]]
                n += tables[1, i, band[t, i]]
        tri_out[m, 0], tri_out[m, 1], tri_out[m, 2] = a, b, c
        v_out[m] = o
        v_in[m] = n
        kept[m] = t
        m += 1
    return m


@_pieces.twin
def _pieces_numpy(
    vertices: NDArray[np.float64], triangles: NDArray[np.int64], values: NDArray[np.float64], band: NDArray[np.int64],
    tables: NDArray[np.float64], kinds: NDArray[np.int64], laws: NDArray[np.float64], partner: NDArray[np.int64],
    ambient: float, min_area2: float,
    tri_out: NDArray[np.int32], v_out: NDArray[np.float64], v_in: NDArray[np.float64], kept: NDArray[np.int64],
) -> int:
    """:func:`_pieces` of every triangle at once: the same sums in the same order (the powers
    with ``math.pow``, the C library's as in the kernel, not NumPy's own)."""
    a, b, c = triangles[:, 0], triangles[:, 1], triangles[:, 2]
    u, w = vertices[b] - vertices[a], vertices[c] - vertices[a]
    cx = u[:, 1] * w[:, 2] - u[:, 2] * w[:, 1]
    cy = u[:, 2] * w[:, 0] - u[:, 0] * w[:, 2]
    cz = u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0]
    keep = np.flatnonzero(np.sqrt(cx * cx + cy * cy + cz * cz) > min_area2)
    a, b, c = a[keep], b[keep], c[keep]
    o = np.full(len(keep), ambient)
    n = np.full(len(keep), ambient)
    for i in range(kinds.shape[0]):
        f0, f1, f2 = values[a, i], values[b, i], values[c, i]
        flat = np.maximum(np.maximum(f0, f1), f2) - np.minimum(np.minimum(f0, f1), f2) <= 1e-12
        p = np.maximum(f0, 0.0)
        lit = np.ones(len(keep), bool)
        if kinds[i] != 0 and partner[i] >= 0:
            d = partner[i]
            side = 1.0 if kinds[i] == 1 else -1.0
            lit = side * (values[a, d] + values[b, d] + values[c, d]) / 3.0 > TERMINATOR_COSINE
        if kinds[i] == 0:
            o = np.where(flat, o + laws[i, 1] * p, o)
            n = np.where(flat, n + laws[i, 2] * np.maximum(-f0, 0.0), n)
        else:
            power = np.zeros(len(keep))
            at = np.flatnonzero(flat & lit)
            power[at] = [math.pow(x, float(laws[i, 0])) for x in p[at].tolist()]
            if kinds[i] == 1:
                o = np.where(flat & lit, o + laws[i, 1] * power, o)
            else:
                n = np.where(flat & lit, n + laws[i, 1] * power, n)
        banded = ~flat & lit
        k = band[keep, i]
        o = np.where(banded, o + tables[0, i, k], o)
        n = np.where(banded, n + tables[1, i, k], n)
    m = len(keep)
    tri_out[:m, 0], tri_out[:m, 1], tri_out[:m, 2] = a, b, c
    v_out[:m], v_in[:m], kept[:m] = o, n, keep
    return m
