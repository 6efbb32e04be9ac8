"""The base surface mesh a primitive's bands are cut from.

Vertices lie exactly on the primitive's surface and carry its exact outward
normal (so the shading fields are exact at every vertex); triangles are
counter-clockwise seen from outside. Each primitive module builds one with
its contour lines for the first light already on mesh edges.

Vertices are kept relative to a local origin (the primitive's centre): far
from the world origin, absolute coordinates would leave only a few
significant digits for face normals, cut points and areas.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._jit import njit
from .families import GRAZING, light_direction_at
from .lights import is_point

__all__ = ["Surface", "orient_outward", "light_reference_distance", "refinement", "specular_refinement",
           "eye_reference_distance", "curvature_spacing", "mixed_spacing", "pieces", "ring_triangles"]


@dataclass(frozen=True, slots=True, eq=False)
class Surface:
    """A triangle mesh with exact per-vertex normals.

    Attributes
    ----------
    vertices : ndarray, shape (V, 3)
        Positions relative to ``origin``.
    normals : ndarray, shape (V, 3)
    triangles : ndarray, shape (T, 3), int64
    origin : ndarray, shape (3,)
        The local origin (world position of local ``(0, 0, 0)``).
    parts : ndarray, shape (V,), int64
        Smooth part of each vertex (a truncus's side and ends, a polyhedron's
        faces). Parts share no vertex; every triangle lies in one part.
    """

    vertices: NDArray[np.float64]
    normals: NDArray[np.float64]
    triangles: NDArray[np.int64]
    origin: NDArray[np.float64]
    parts: NDArray[np.int64]


def orient_outward(vertices: NDArray[np.float64], normals: NDArray[np.float64],
                   triangles: NDArray[np.int64]) -> NDArray[np.int64]:
    """Reorder triangle corners so that each is counter-clockwise about its vertex normals.

    Degenerate (zero-area) triangles are left as they are.

    Examples
    --------
    >>> v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0.0]])
    >>> up = np.tile([0, 0, 1.0], (3, 1))
    >>> orient_outward(v, up, np.array([[0, 2, 1]])).tolist()
    [[0, 1, 2]]
    """
    t = np.array(triangles, dtype=np.int64).reshape(-1, 3)
    _orient(np.ascontiguousarray(vertices, dtype=np.float64), np.ascontiguousarray(normals, dtype=np.float64), t)
    return t


@njit(cache=True, nogil=True)
def _orient(v: NDArray[np.float64], nrm: NDArray[np.float64], t: NDArray[np.int64]) -> None:
    for i in range(t.shape[0]):
        a, b, c = t[i, 0], t[i, 1], t[i, 2]
        ux, uy, uz = v[b, 0] - v[a, 0], v[b, 1] - v[a, 1], v[b, 2] - v[a, 2]
        wx, wy, wz = v[c, 0] - v[a, 0], v[c, 1] - v[a, 1], v[c, 2] - v[a, 2]
        gx, gy, gz = uy * wz - uz * wy, uz * wx - ux * wz, ux * wy - uy * wx
        s = 0.0
        for k in (a, b, c):
            s += gx * nrm[k, 0] + gy * nrm[k, 1] + gz * nrm[k, 2]
        if s < 0.0:
            t[i, 1], t[i, 2] = c, b


@_orient.twin
def _orient_numpy(v: NDArray[np.float64], nrm: NDArray[np.float64], t: NDArray[np.int64]) -> None:
    """:func:`_orient` vectorised, each product and sum in the kernel's order (the same bits)."""
    a, b, c = t[:, 0], t[:, 1], t[:, 2]
    ux, uy, uz = v[b, 0] - v[a, 0], v[b, 1] - v[a, 1], v[b, 2] - v[a, 2]
    wx, wy, wz = v[c, 0] - v[a, 0], v[c, 1] - v[a, 1], v[c, 2] - v[a, 2]
    gx, gy, gz = uy * wz - uz * wy, uz * wx - ux * wz, ux * wy - uy * wx
    s = np.zeros(len(t))
    for k in (a, b, c):
        s += gx * nrm[k, 0] + gy * nrm[k, 1] + gz * nrm[k, 2]
    flip = s < 0.0
    t[flip, 1], t[flip, 2] = c[flip], b[flip]


def light_reference_distance(lights: object, center: NDArray[np.float64], radius: float) -> float:
    """Smallest distance from a point light to the bounding sphere (``inf`` with no point light).

    The primitive modules refine their meshes where a light this close makes
    the incidence angle vary across a face or along a generator.
    """
    d = np.inf
    for light in lights:  # type: ignore[attr-defined]
        if is_point(light):
            gap = float(np.linalg.norm(np.asarray(light.position) - center)) - radius
            d = min(d, max(gap, 0.05 * radius))
    return d


def refinement(size: float, distance: float, per_distance: float = 16.0, cap: int = 48) -> int:
    """Subdivisions of a length ``size`` lit from ``distance``: about ``per_distance`` per unit of distance."""
    if not np.isfinite(distance):
        return 1
    return int(np.clip(np.ceil(per_distance * size / distance), 1, cap))


#: Contours beyond which :func:`specular_refinement` refines no further.
SPECULAR_CONTOURS = 256


def specular_refinement(size: float, eye_distance: float, shininess: float, contours: int, cap: int = 64) -> int:
    """Subdivisions of a flat length ``size`` for a Phong term seen from ``eye_distance``.

    On a plane (fixed ``rf``), ``rf . v`` turns with the view direction, at
    most ``1 / d`` per unit length; the term ``(rf . v) ** s`` then bends by
    about ``s / d**2``, and a linear interpolant over a length ``h`` misses it
    by ``s h**2 / (8 d**2)`` (in units of ``ks``). Keeping that below a
    quarter of a band step ``1 / N`` gives ``h <= d sqrt(2 / (s N))``: finer
    for sharper highlights and more contours, so that the error keeps
    shrinking with N (up to ``cap``).
    """
    if not (np.isfinite(eye_distance) and size > 0):
        return 1
    # Beyond SPECULAR_CONTOURS the mesh stays put: thousands of contours would
    # otherwise multiply an already fine mesh.
    h = eye_distance * np.sqrt(2.0 / (max(shininess, 1.0) * min(contours, SPECULAR_CONTOURS)))
    return int(np.clip(np.ceil(size / h), 1, cap))


def eye_reference_distance(eye: NDArray[np.float64] | None, center: NDArray[np.float64], radius: float) -> float:
    """Distance from the eye to the bounding sphere (at least 5 % of its radius; ``inf`` without an eye)."""
    if eye is None:
        return np.inf
    return max(float(np.linalg.norm(np.asarray(eye, dtype=np.float64) - center)) - radius, 0.05 * radius)


def _terms(
    points: NDArray[np.float64], normals: NDArray[np.float64], lights: list, origin: NDArray[np.float64],
    eye: NDArray[np.float64] | None, shininess: float, weights: tuple[float, float] = (1.0, 1.0),
) -> list[tuple[NDArray[np.float64], NDArray[np.bool_], float, int, float]]:
    """Each family's field in the units its levels are uniform in (points and ``eye`` relative to
    ``origin``): ``n . l`` per light, and ``(rf . v) ** s`` on each lit side with an eye; with the
    samples where it is smooth, its weight in the image (``weights`` = (kd, ks) times the
    light's intensity), the image it shows in (0 outward, 1 the reversed normal) and its range
    there.

    The diffuse field appears once per image: its levels cut the lit range of each side into N
    steps (``families.diffuse_levels``), so its band step in the outward image is the range of
    ``max(n . l, 0)`` over N, and in the reversed one that of ``max(-n . l, 0)``."""
    out = []
    for light in lights:
        ldir = light_direction_at(light, points, origin)
        ndl = np.einsum("ij,ij->i", normals, ldir)
        wd = weights[0] * light.intensity
        everywhere = np.ones(len(ndl), bool)
        for side, lit in ((0, np.maximum(ndl, 0.0)), (1, np.maximum(-ndl, 0.0))):
            out.append((ndl, everywhere, wd, side, float(lit.max() - lit.min()) if lit.size else 0.0))
        if eye is not None:
            rf = 2.0 * ndl[:, None] * normals - ldir
            v = eye - points
            v /= np.maximum(np.linalg.norm(v, axis=1, keepdims=True), 1e-300)
            rv = np.einsum("ij,ij->i", rf, v)
            # The term jumps at the terminator and has a kink at the highlight's edge: both are
            # levels the cut follows (0 of the diffuse and of the Phong family), so only samples
            # inside the highlight on the lit side measure how the term bends.
            w = weights[1] * light.intensity
            lit_out, lit_in = ndl > GRAZING, ndl < -GRAZING
            for side, lit in ((0, lit_out), (1, lit_in)):
                f = np.where(lit, np.maximum(rv, 0.0) ** shininess, 0.0)
                out.append((f, lit & (rv > 0), w, side, float(f.max() - f.min()) if f.size else 0.0))
    return out


def _dominant(terms: list) -> list[float]:
    """The largest weighted range ``w R`` of the families shown in each image (outward, reversed):
    the band step of that image is at least it over N. A family is followed within a quarter of
    the step of the image it shows in; a family bright in the other image (a light behind the
    part, lit for the reversed normal) says nothing of this one's step."""
    dom = [0.0, 0.0]
    for _, _, w, side, r in terms:
        dom[side] = max(dom[side], w * r)
    return dom


def curvature_spacing(
    lines: NDArray[np.float64],
    normals: NDArray[np.float64],
    lights: list,
    origin: NDArray[np.float64],
    contours: int,
    *,
    eye: NDArray[np.float64] | None = None,
    shininess: float = 1.0,
    step: float | None = None,
    weights: tuple[float, float] = (1.0, 1.0),
) -> float:
    """The longest mesh spacing along sample lines that follows every field within a quarter band step.

    Parameters
    ----------
    lines : ndarray, shape (L, m, 3)
        Straight, evenly sampled segments across one smooth part, relative to ``origin``.
    normals : ndarray, shape (L, m, 3)
        The exact normals at the samples.
    lights, origin, contours, eye, shininess
        The families' lights, the local origin, N, and the eye (relative to
        ``origin``) and shininess of a specular material.
    step : float, optional
        The distance between samples along the surface (curved lines such as
        a truncus's rings); by default the chord of each straight line over ``m - 1``.
    weights : (float, float), default (1, 1)
        The material's ``kd`` and ``ks``: what each family adds to the image.

    Returns
    -------
    float
        ``inf`` when no field bends. A field whose range on the samples is ``R``
        has levels ``R / N`` apart (see :mod:`~isocsg.bands.families`); a
        linear interpolant over a length ``h`` misses it by ``|f''| h**2 / 8``
        (``f''`` from second differences of the samples). Keeping that below
        ``R / (4 N)`` gives ``h = sqrt(2 R / (N |f''|))``, with N taken up to
        ``SPECULAR_CONTOURS``. A family whose weighted range ``w R`` is below the
        largest one ``D`` of the image it shows in (outward or reversed normal) is
        followed within ``D / (4 N w)`` instead: its error in that image stays below
        a quarter of the image's band step (a faint highlight's edge spanning 1e-5
        would otherwise ask for thousands of generators). ``R`` of a diffuse field
        is the range of its lit side. Only samples where the field is smooth count
        (see ``_terms``).
    """
    n_lines, m, _ = lines.shape
    if step is None:
        steps = np.linalg.norm(lines[:, -1] - lines[:, 0], axis=1) / max(m - 1, 1)
    else:
        steps = np.full(n_lines, float(step))
    if m < 3 or not np.all(steps > 0):
        return np.inf
    n = min(contours, SPECULAR_CONTOURS)
    best = np.inf
    terms = [(f.reshape(n_lines, m), smooth.reshape(n_lines, m), w, side, r)
             for f, smooth, w, side, r in _terms(lines.reshape(-1, 3), normals.reshape(-1, 3), lights, origin, eye,
                                                 shininess, weights)
             if r > 1e-12 and w > 0]
    dominant = _dominant(terms)
    for f, smooth, w, side, _r in terms:
        inside = smooth[:, :-2] & smooth[:, 1:-1] & smooth[:, 2:]
        if not inside.any():
            continue
        second = np.abs(f[:, :-2] - 2.0 * f[:, 1:-1] + f[:, 2:])
        d2 = float(np.max(np.where(inside, second, 0.0) / (steps[:, None] ** 2)))
        if d2 > 0:
            best = min(best, float(np.sqrt(2.0 * dominant[side] / (n * w * d2))))
    return best


def pieces(length: float, spacing: float, cap: int = 64) -> int:
    """Equal pieces of ``length`` no longer than ``spacing`` (1 .. ``cap``)."""
    if not np.isfinite(spacing) or spacing <= 0:
        return 1
    return int(np.clip(np.ceil(length / spacing), 1, cap))


def mixed_spacing(
    grid: NDArray[np.float64],
    normals: NDArray[np.float64],
    lights: list,
    origin: NDArray[np.float64],
    contours: int,
    step0: float,
    step1: float,
    *,
    eye: NDArray[np.float64] | None = None,
    shininess: float = 1.0,
    weights: tuple[float, float] = (1.0, 1.0),
) -> float:
    """The longest spacing along the first parameter of a grid whose cells' triangles follow every
    field within a quarter band step, given the spacing ``step1`` along the second.

    A triangle of a cell ``h0 x h1`` of a parametric grid interpolates ``f`` linearly, missing
    the mixed term ``f_01 h0 h1`` by up to about ``|f_01| h0 h1 / 4``, which
    :func:`curvature_spacing` (along straight lines) does not see: a long triangle spanning a
    truncus's side between two generators misses how the field's slope around the axis changes
    along it. Keeping it below ``R / (4 N)`` gives ``h0 = R / (N |f_01| h1)``.

    Parameters
    ----------
    grid, normals : ndarray, shape (m0, m1, 3)
        Surface points (relative to ``origin``) and exact normals on a grid of the two
        parameters, with spacings ``step0`` and ``step1`` between samples.
    """
    m0, m1, _ = grid.shape
    if m0 < 2 or m1 < 2:
        return np.inf
    n = min(contours, SPECULAR_CONTOURS)
    best = np.inf
    terms = [(f.reshape(m0, m1), smooth.reshape(m0, m1), w, side, r)
             for f, smooth, w, side, r in _terms(grid.reshape(-1, 3), normals.reshape(-1, 3), lights, origin, eye,
                                                 shininess, weights)
             if r > 1e-12 and w > 0]
    # As in curvature_spacing: a faint family is followed within the largest band step of the
    # image it shows in, and only cells where the field is smooth (all four corners) measure its
    # mixed term.
    dominant = _dominant(terms)
    for f, smooth, w, side, _ in terms:
        cells = smooth[:-1, :-1] & smooth[1:, :-1] & smooth[:-1, 1:] & smooth[1:, 1:]
        if not cells.any():
            continue
        mixed = float(np.max(np.where(cells, np.abs(np.diff(np.diff(f, axis=0), axis=1)), 0.0))) / (step0 * step1)
        if mixed > 0:
            best = min(best, dominant[side] / (n * w * mixed * step1))
    return best

def ring_triangles(n_rings: int, m: int) -> NDArray[np.int64]:
    """Triangles of a closed latitude-longitude mesh: vertex 0 a pole, ``n_rings`` rings of ``m``
    vertices each (ring k starts at ``1 + k m``), and the opposite pole last."""
    j = np.arange(m)
    jn = (j + 1) % m
    a = 1 + m * np.arange(n_rings - 1)[:, None]  # ring k's first vertex, (rings - 1, 1)
    b = a + m
    quads = np.stack([np.stack([a + j, b + j, b + jn], axis=-1), np.stack([a + j, b + jn, a + jn], axis=-1)], axis=1)
    south = 1 + n_rings * m
    last = 1 + (n_rings - 1) * m
    return np.vstack([
        np.stack([np.zeros(m, np.int64), 1 + j, 1 + jn], axis=1),
        quads.reshape(-1, 3),
        np.stack([np.full(m, south), last + jn, last + j], axis=1),
    ]).astype(np.int64)
