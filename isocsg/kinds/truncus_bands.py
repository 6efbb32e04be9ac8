"""Isoluminance laminae of a generalised truncus (the seed's appendix).

With ``a`` the axis (end E1 of radius R1 at ``ct + a/2``, E2 of radius R2 at
``ct - a/2``) and ``L_n`` the direction to the light:

- ``L_E = L_n - (a . L_n) a / |a|^2``, normalised to ``L_En``; when the light
  lies on the axis, any unit vector perpendicular to ``a``;
- ``gamma_ei = c_e + cos(i pi / N) R_e L_En`` and
  ``delta_ei = R_e sin(i pi / N) (L_En x a / |a|)`` on each end plane;
- the quadrilateral lamina ``phi_i = {gamma_1i - delta_1i, gamma_1i + delta_1i,
  gamma_2i + delta_2i, gamma_2i - delta_2i}``, ``0 <= i < N``;
- the normal ``N_i = p14 - (ct - h a / |a|)`` with ``p14`` the middle of
  ``p1 p4`` and ``h = (R2^2 - R1^2) / (2 |a|)``. It is the exact outward
  normal of the generator through ``p1`` and ``p4`` (the normal line through
  the generator's midpoint meets the axis at ``ct - h a/|a|``);
- two end laminae, M-sided polygons with normals ``+-a / |a|``.

These laminae are isoluminance only when ``|l - ct| >> size``. For a nearer
point light the truncus is split along its axis into slices, each with its
own ``L_En`` from its own centre (:func:`truncus_laminae`); the band mesh
(:func:`truncus_surface`) carries the exact incidence cosine at every vertex
and is cut along its exact level lines, near light or not.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import NamedTuple, Protocol

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..bands.families import diffuse_levels
from ..bands.lights import Light, is_directional, is_point
from ..bands.surface import (
    Surface,
    curvature_spacing,
    eye_reference_distance,
    light_reference_distance,
    orient_outward,
    pieces,
    refinement,
    specular_refinement,
)
from ..errors import InvalidGeometryError

__all__ = [
    "light_frame", "side_cosine_coefficients", "paper_levels", "appendix_normal",
    "Frustum", "truncus_laminae", "truncus_surface", "side_levels", "GENERATORS",
]

#: Uniform generators around the axis added to the contour generators (for the silhouette).
GENERATORS = 128
#: Samples around a ring when measuring how the fields bend about the axis.
RING_SAMPLES = 720
#: Most uniform generators (a point light very close to the side).
MAX_GENERATORS = 2048
#: Most contour generators added for a point light (its level lines are not generators).
POINT_LIGHT_CONTOURS = 64
#: Least ratio of consecutive ring radii towards a truncus's small end (see ``_graded_rings``).
RING_RATIO = 0.6
#: Smallest graded ring radius next to a cone's apex, as a fraction of the larger end radius.
APEX_FLOOR = 1e-2

class Frustum(Protocol):
    """What the truncus's bands read of it (:class:`~isocsg.kinds.Truncus`)."""

    @property
    def axis(self) -> tuple[float, float, float]: ...

    @property
    def r1(self) -> float: ...

    @property
    def r2(self) -> float: ...

    @property
    def bounds(self) -> NDArray[np.float64]: ...

    @property
    def center_array(self) -> NDArray[np.float64]: ...

    @property
    def end_centers(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]: ...

    @property
    def height(self) -> float: ...

    @property
    def slope(self) -> float: ...

    @property
    def unit_axis(self) -> NDArray[np.float64]: ...

    def radius_at(self, s: ArrayLike) -> NDArray[np.float64]: ...

    def stacked(self, k: int) -> Sequence[Frustum]: ...



def _to_light(light: Light, point: NDArray[np.float64]) -> NDArray[np.float64]:
    if is_directional(light):
        return light.unit_direction
    d = np.asarray(light.position, dtype=np.float64) - point
    n = float(np.linalg.norm(d))
    return d / n if n > 0 else np.zeros(3)


def light_frame(axis: NDArray[np.float64], ln: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """``L_En`` and ``L_En x a/|a|`` for a unit ``axis`` and a light direction ``ln``."""
    le = ln - (axis @ ln) * axis
    n = float(np.linalg.norm(le))
    if n < 1e-12:  # the light on the axis: any perpendicular will do
        helper = np.array([1.0, 0.0, 0.0]) if abs(axis[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
        le = np.cross(axis, helper)
        n = float(np.linalg.norm(le))
    len_ = le / n
    return len_, np.cross(len_, axis)


def side_cosine_coefficients(truncus: Frustum, ln: NDArray[np.float64]) -> tuple[float, float]:
    """``(A, B)`` with ``n(theta) . ln = B + A cos(theta)`` on the lateral surface.

    ``theta`` is the angle about the axis from ``L_En``; ``ln`` a unit direction.
    """
    a = truncus.unit_axis
    k = truncus.slope
    ca, sa = 1.0 / np.hypot(1.0, k), -k / np.hypot(1.0, k)
    le = ln - (a @ ln) * a
    return float(ca * np.linalg.norm(le)), float(sa * (a @ ln))


def paper_levels(truncus: Frustum, light: Light, contours: int) -> NDArray[np.float64]:
    """Incidence cosines of the generators through the laminae ``phi_i`` (``theta = i pi / N``).

    Taken with the light direction from the centre ``ct``; these are the
    levels the band mesh's lateral surface is cut at.
    """
    A, B = side_cosine_coefficients(truncus, _to_light(light, truncus.center_array))
    return B + A * np.cos(np.pi * np.arange(contours + 1) / contours)


def appendix_normal(truncus: Frustum, p1: NDArray[np.float64], p4: NDArray[np.float64]) -> NDArray[np.float64]:
    """The seed's ``N_i = p14 - (ct - h a/|a|)``, normalised (``p1``, ``p4`` of shape (..., 3))."""
    a = truncus.unit_axis
    h = (truncus.r2**2 - truncus.r1**2) / (2.0 * truncus.height)
    n = 0.5 * (np.asarray(p1) + np.asarray(p4)) - (truncus.center_array - h * a)
    return n / np.linalg.norm(n, axis=-1, keepdims=True)


def _slices(truncus: Frustum, light: Light) -> list[Frustum]:
    half_diagonal = 0.5 * float(np.linalg.norm(truncus.bounds[1] - truncus.bounds[0]))
    d = light_reference_distance([light], truncus.center_array, half_diagonal)
    k = refinement(truncus.height, d, per_distance=4.0, cap=32)
    if k == 1:
        return [truncus]
    while k > 1:
        try:
            return list(truncus.stacked(k))
        except InvalidGeometryError:
            # Slices below the documented smallest lengths (a tiny or flat truncus
            # far from the origin): fewer of them.
            k //= 2
    return [truncus]


def truncus_laminae(
    truncus: Frustum, light: Light, contours: int, *, slices: bool = True
) -> list[tuple[NDArray[np.float64], NDArray[np.float64], float, str]]:
    """The appendix laminae of one light: quads ``phi_i`` (i = 1 .. N-1) and the two ends.

    Parameters
    ----------
    truncus : Frustum
    light : PointLight or DirectionalLight
    contours : int
        N.
    slices : bool, default True
        Split along the axis for a near point light (each slice gets its own
        ``L_En``); False gives the seed's single-piece construction.

    Returns
    -------
    list of (vertices, normal, cosine, kind)
        ``normal`` is the lamina plane's unit normal; ``cosine`` the incidence
        cosine of the surface it stands for (``N_i . L_n`` with ``L_n`` taken
        from the generator's midpoint ``p14``, ends: ``+-a . L_n`` from their centres),
        ``kind`` ``"contour"`` or ``"end"``. Zero-area quads (a zero radius end
        and ``i = 0``) are omitted.
    """
    out = []
    pieces = _slices(truncus, light) if slices else [truncus]
    i = np.arange(1, contours)
    ci, si = np.cos(i * np.pi / contours)[:, None], np.sin(i * np.pi / contours)[:, None]
    for piece in pieces:
        ct = piece.center_array
        ln = _to_light(light, ct)
        len_, side = light_frame(piece.unit_axis, ln)
        c1, c2 = piece.end_centers
        g1, g2 = c1 + ci * piece.r1 * len_, c2 + ci * piece.r2 * len_
        d1, d2 = piece.r1 * si * side, piece.r2 * si * side
        quads = np.stack([g1 - d1, g1 + d1, g2 + d2, g2 - d2], axis=1)  # (N-1, 4, 3)
        # Plane normal from the longer pair of sides (one end may be a point).
        normal = np.cross(quads[:, 1] - quads[:, 0], quads[:, 3] - quads[:, 0])
        alt = np.cross(quads[:, 2] - quads[:, 3], quads[:, 0] - quads[:, 3])
        normal = np.where((np.linalg.norm(normal, axis=1) < np.linalg.norm(alt, axis=1))[:, None], alt, normal)
        size = np.linalg.norm(normal, axis=1)
        # The seed's N_i, and the light direction from the generator's midpoint p14:
        # its L_n for a distant light, exact at p14 for a near one.
        p14 = 0.5 * (quads[:, 0] + quads[:, 3])
        ni = appendix_normal(piece, quads[:, 0], quads[:, 3])
        if is_directional(light):
            l14 = np.broadcast_to(light.unit_direction, p14.shape)
        else:
            l14 = np.asarray(light.position, dtype=np.float64) - p14
            l14 = l14 / np.maximum(np.linalg.norm(l14, axis=1, keepdims=True), 1e-300)
        cos = np.einsum("ij,ij->i", ni, l14)
        for q, nrm, sz, c in zip(quads, normal, size, cos):
            if sz > 0:
                out.append((q, nrm / sz, float(c), "contour"))
    # The two end laminae of the whole truncus (M = 2N sides), cosines at their centres.
    a = truncus.unit_axis
    c1, c2 = truncus.end_centers
    len_, side = light_frame(a, _to_light(light, truncus.center_array))
    m = 2 * max(contours, 4)
    ang = 2.0 * np.pi * np.arange(m) / m
    ring = np.cos(ang)[:, None] * len_ + np.sin(ang)[:, None] * side
    for centre, r, n in ((c1, truncus.r1, a), (c2, truncus.r2, -a)):
        if r > 0:
            # (L_En, L_En x a) turns clockwise about a: reverse it for the outward E1.
            poly = centre + r * (ring[::-1] if n is a else ring)
            out.append((poly, n.copy(), float(n @ _to_light(light, centre)), "end"))
    return out


def side_levels(truncus: Frustum, light: Light, contours: int) -> NDArray[np.float64]:
    """The diffuse cut levels of the lateral surface for ``light`` seen from the centre.

    The side's incidence cosine ``B + A cos(theta)`` spans ``[B - A, B + A]``
    (exactly, for a directional light); the levels cut that range into ``N``
    equal steps on each side of the terminator (see
    :func:`~isocsg.bands.families.diffuse_levels`).
    """
    A, B = side_cosine_coefficients(truncus, _to_light(light, truncus.center_array))
    return diffuse_levels(np.array([B - A, B + A]), contours)


def _generator_angles(
    truncus: Frustum, light: Light | None, levels: NDArray[np.float64], uniform: int = GENERATORS
) -> NDArray[np.float64]:
    th = 2.0 * np.pi * np.arange(uniform) / uniform
    if light is not None:
        A, B = side_cosine_coefficients(truncus, _to_light(light, truncus.center_array))
        if A > 1e-12:
            x = (levels - B) / A
            x = x[np.abs(x) <= 1.0]
            t = np.arccos(x)
            th = np.concatenate([th, t, 2.0 * np.pi - t])
    th = np.sort(np.mod(th, 2.0 * np.pi))
    keep = np.concatenate([[True], np.diff(th) > 1e-9])
    th = th[keep]
    if 2.0 * np.pi - th[-1] <= 1e-9:
        th = th[:-1]
    return th


def _graded_rings(zs: list[float], truncus: Frustum) -> list[float]:
    """Axial ring positions (descending, ends exact) refined towards a small end.

    Near a cone's apex every field is a function of the angle about the axis only,
    and a triangle spanning two generators of very different lengths (a wedge) is
    a poor linear interpolant of it: off by up to the field's change from one
    generator to the next. Rings whose radii shrink by at most ``RING_RATIO`` keep
    each trapezoid close to a parallelogram, down to ``APEX_FLOOR`` of the larger
    radius (the wedge left at a zero-radius end is below a pixel).
    """
    h = truncus.height
    zs = list(zs)
    zs[0], zs[-1] = 0.5 * h, -0.5 * h
    r_max = max(truncus.r1, truncus.r2)
    if r_max <= 0 or truncus.r1 == truncus.r2:
        return zs
    out = [zs[0]]
    for za, zb in zip(zs[:-1], zs[1:]):
        ra, rb = float(truncus.radius_at(za)), float(truncus.radius_at(zb))
        lo, hi = min(ra, rb), max(ra, rb)
        floor = max(lo, APEX_FLOOR * r_max)
        if hi > 0 and floor < hi:
            # a ring at the floor too when fine uniform rings already come close to an apex
            k = int(np.ceil(np.log(floor / hi) / np.log(RING_RATIO))) if floor < RING_RATIO * hi else 1
            radii = hi * (floor / hi) ** (np.arange(1, k) / k)  # geometric, hi -> floor
            if lo < floor:
                radii = np.append(radii, floor)
            zr = zb + (radii - rb) * (za - zb) / (ra - rb)  # radius is linear in z
            zr = np.sort(zr[(zr < za) & (zr > zb)])[::-1]
            out.extend(float(z) for z in zr)
        out.append(zb)
    return out


def _disc_outside(centre: NDArray[np.float64], r: float, normal: NDArray[np.float64], box: tuple) -> bool:
    """Whether the disc (``centre``, radius ``r``, unit ``normal``) lies strictly beyond one face of
    the box ``(lo, hi)``: along axis k it spans ``centre[k] +- r sqrt(1 - normal[k]**2)``."""
    half = r * np.sqrt(np.maximum(1.0 - normal * normal, 0.0))
    lo, hi = np.asarray(box[0], dtype=np.float64), np.asarray(box[1], dtype=np.float64)
    return bool(((centre - half) > hi).any() or ((centre + half) < lo).any())


def truncus_surface(
    truncus: Frustum,
    lights: list[Light],
    contours: int,
    *,
    eye: NDArray[np.float64] | None = None,
    shininess: float = 1.0,
    weights: tuple[float, float] = (1.0, 1.0),
    segments: int = GENERATORS,
    hidden: tuple | None = None,
) -> Surface:
    """Band mesh base of a truncus, relative to its centre.

    Generators run at the first light's contour angles when it is directional
    (its level lines are generators: that family then cuts nothing), plus
    ``GENERATORS`` uniform ones. For a point light the level lines bend, the
    family cuts the mesh anyway, and at most ``POINT_LIGHT_CONTOURS`` contour
    generators are added (so that thousands of contours stay affordable).

    Rings along the axis and on the ends are added for near point lights,
    whose level lines are not straight generators, and for a specular
    material seen from ``eye`` (:func:`~isocsg.bands.surface.specular_refinement`).
    Towards a small end the rings are graded (``_graded_rings``) whenever some
    field is not constant along the generators: several lights, a point light
    or a specular material.

    ``segments`` (default ``GENERATORS``) is the least number of uniform
    generators: a renderer asks for fewer for a truncus small on screen (the
    chord error then stays a small fraction of a pixel), never fewer than the
    fields' bending needs.

    ``hidden`` (world ``(lo, hi)``, optional): the box outside which nothing
    of the truncus can be seen. An end disc lying entirely beyond one of its
    faces (a hole's end outside the plate) is a plain fan of its rim, not
    refined for the fields: its bands are not cut (see
    :func:`~isocsg.laminae.build_bands`), only its geometry counts.

    Parts: 0 the lateral surface, 1 the end E1, 2 the end E2.
    """
    first = lights[0] if lights else None
    a = truncus.unit_axis
    ct = truncus.center_array
    ln = _to_light(first, ct) if first is not None else np.array([1.0, 0.0, 0.0])
    e1, e2 = light_frame(a, ln)
    e2 = -e2  # right-handed (e1, e2, a): angles grow counter-clockwise about a
    if first is None:
        levels = np.zeros(0)
    else:
        n_gen = contours if is_directional(first) else min(contours, POINT_LIGHT_CONTOURS)
        levels = side_levels(truncus, first, n_gen)
    fields = _Fields(lights, contours, eye, shininess, weights)
    uniform = _uniform_generators(truncus, fields, e1, light_frame(a, ln)[1], int(segments))
    th = _generator_angles(truncus, first, levels, uniform)
    radial = np.cos(th)[:, None] * e1 + np.sin(th)[:, None] * e2  # (m, 3)
    size = 0.5 * float(np.linalg.norm(truncus.bounds[1] - truncus.bounds[0]))
    dist = light_reference_distance(lights, ct, size)
    d_eye = eye_reference_distance(eye, np.zeros(3), size)
    # The fields' bending along 16 generators and 8 radii of each end (see curvature_spacing).
    probe = radial[np.linspace(0, len(th) - 1, 16).astype(np.int64)]
    n_ax = _axial_pieces(truncus, fields, probe, dist, d_eye)
    verts: list[NDArray[np.float64]] = []
    norms: list[NDArray[np.float64]] = []
    tris: list[NDArray[np.int64]] = []
    parts: list[NDArray[np.int64]] = []
    _lateral_mesh(truncus, fields, radial, n_ax, (verts, norms, tris, parts))
    _end_discs(truncus, fields, radial, probe, (dist, d_eye), hidden, (verts, norms, tris, parts))
    vertices = np.vstack(verts)
    normals = np.vstack(norms)
    triangles = np.vstack(tris).astype(np.int64)
    return Surface(vertices, normals, orient_outward(vertices, normals, triangles), ct.copy(), np.concatenate(parts))


class _Fields(NamedTuple):
    """The shading fields a truncus's band mesh must follow."""

    lights: list[Light]
    contours: int
    eye: NDArray[np.float64] | None
    shininess: float
    weights: tuple[float, float]

    @property
    def straight(self) -> bool:
        """Whether every field is constant where the normal is: lights at infinity and no
        highlight (then nothing bends along a generator or across an end)."""
        return self.eye is None and all(is_directional(light) for light in self.lights)

    def spacing(self, points: NDArray[np.float64], normals: NDArray[np.float64], origin: NDArray[np.float64],
                **step: float) -> float:
        return curvature_spacing(points, normals, self.lights, origin, self.contours, eye=self.eye,
                                 shininess=self.shininess, weights=self.weights, **step)


def _uniform_generators(truncus: Frustum, fields: _Fields, e1: NDArray[np.float64], f2: NDArray[np.float64],
                        floor: int) -> int:
    """The number of uniform generators: the fields' bending around three rings (a point light
    close to the side turns the incidence within a few degrees), never fewer than ``floor``."""
    if not fields.lights:
        return floor
    a, h, k_ = truncus.unit_axis, truncus.height, truncus.slope
    ang = 2.0 * np.pi * np.arange(RING_SAMPLES + 1) / RING_SAMPLES
    circle = np.cos(ang)[:, None] * e1 - np.sin(ang)[:, None] * f2
    spacing = np.inf
    for z in (0.5 * h, 0.0, -0.5 * h):
        r = float(truncus.radius_at(z))
        if r <= 0:
            continue
        ring_pts = (z * a + r * circle)[None]
        ring_nrm = ((circle - k_ * a) / np.hypot(1.0, k_))[None]
        gap = fields.spacing(ring_pts, ring_nrm, truncus.center_array, step=2.0 * np.pi * r / RING_SAMPLES)
        spacing = min(spacing, gap / r)  # as an angle
    if np.isfinite(spacing) and spacing > 0:
        return int(np.clip(np.ceil(2.0 * np.pi / spacing), floor, MAX_GENERATORS))
    return floor


def _axial_pieces(truncus: Frustum, fields: _Fields, probe: NDArray[np.float64], dist: float, d_eye: float) -> int:
    """The number of rings along the axis: light and eye distances, and the fields' bending
    along the ``probe`` generators."""
    a, h, k = truncus.unit_axis, truncus.height, truncus.slope
    slant = float(np.hypot(h, truncus.r1 - truncus.r2))
    n_ax = max(refinement(h, dist), specular_refinement(slant, d_eye, fields.shininess, fields.contours))
    if fields.lights and not fields.straight:
        t = np.linspace(0.0, 1.0, 17)[None, :, None]
        top, bottom = 0.5 * h * a + truncus.r1 * probe, -0.5 * h * a + truncus.r2 * probe
        lines = top[:, None, :] + t * (bottom - top)[:, None, :]
        nrm = np.broadcast_to(((probe - k * a) / np.hypot(1.0, k))[:, None, :], lines.shape)
        n_ax = max(n_ax, pieces(slant, fields.spacing(lines, nrm, truncus.center_array)))
    return n_ax


def _lateral_mesh(truncus: Frustum, fields: _Fields, radial: NDArray[np.float64], n_ax: int, out: tuple) -> None:
    """Lateral surface (part 0): rings from E1 (z = +h/2) to E2 (z = -h/2), appended to ``out``."""
    verts, norms, tris, parts = out
    a, h, k = truncus.unit_axis, truncus.height, truncus.slope
    m = len(radial)
    side_normal = (radial - k * a) / np.hypot(1.0, k)
    zs = [0.5 * h - j * h / n_ax for j in range(n_ax + 1)]
    zs[-1] = -0.5 * h
    lights = fields.lights
    if fields.eye is not None or len(lights) > 1 or any(is_point(light) for light in lights):
        zs = _graded_rings(zs, truncus)
        n_ax = len(zs) - 1
    jj = np.arange(m)
    jn = (jj + 1) % m
    for j, z in enumerate(zs):
        r = truncus.r1 if j == 0 else truncus.r2 if j == n_ax else float(truncus.radius_at(z))
        verts.append(z * a + r * radial)
        norms.append(side_normal)
    for j in range(n_ax):
        p, q = j * m, (j + 1) * m
        tris.append(np.stack([p + jj, q + jj, q + jn], axis=1))
        tris.append(np.stack([p + jj, q + jn, p + jn], axis=1))
    parts.append(np.zeros((n_ax + 1) * m, np.int64))


def _end_discs(truncus: Frustum, fields: _Fields, radial: NDArray[np.float64], probe: NDArray[np.float64],
               distances: tuple[float, float], hidden: tuple | None, out: tuple) -> None:
    """Ends (parts 1 and 2): centre and concentric rings; the outer ring repeats the rim
    positions exactly. Appended to ``out`` after the lateral surface."""
    verts, norms, tris, parts = out
    dist, d_eye = distances
    a, h, ct = truncus.unit_axis, truncus.height, truncus.center_array
    m = len(radial)
    jj = np.arange(m)
    jn = (jj + 1) % m
    t = np.linspace(0.0, 1.0, 17)[None, :, None]
    count = sum(len(p) for p in parts)
    for part, (z, r, n) in enumerate(((0.5 * h, truncus.r1, a), (-0.5 * h, truncus.r2, -a)), start=1):
        if r <= 0:
            continue
        centre = z * a
        if hidden is not None and _disc_outside(ct + centre, r, a, hidden):
            n_rad = 1  # never seen: its geometry alone, a fan of the rim
        else:
            n_rad = max(refinement(r, dist), specular_refinement(r, d_eye, fields.shininess, fields.contours))
            if fields.lights and not fields.straight:
                spokes = centre + t * (r * probe[::2])[:, None, :]
                n_rad = max(n_rad, pieces(r, fields.spacing(spokes, np.broadcast_to(n, spokes.shape), ct)))
        verts.append(centre[None, :])
        verts.extend(z * a + (r * i / n_rad if i < n_rad else r) * radial for i in range(1, n_rad + 1))
        norms.append(np.tile(n, (1 + n_rad * m, 1)))
        tris.append(np.stack([np.full(m, count), count + 1 + jj, count + 1 + jn], axis=1))
        for i in range(n_rad - 1):
            p, q = count + 1 + i * m, count + 1 + (i + 1) * m
            tris.append(np.stack([p + jj, q + jj, q + jn], axis=1))
            tris.append(np.stack([p + jj, q + jn, p + jn], axis=1))
        count += 1 + n_rad * m
        parts.append(np.full(1 + n_rad * m, part, np.int64))
