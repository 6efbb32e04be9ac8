"""Reflecting surfaces cut into patches: a box room's inner faces and the occluders' faces.

A patch is a planar convex polygon (a parallelogram from a rectangular face,
a triangle otherwise), counter-clockwise about the normal of the side that
reflects, with a diffuse reflectance and an *owner*: the convex solid whose
face it lies on (-1 for the room). A convex owner never hides anything from
its own faces, so the form factors of a patch leave its owner out of the
occluders.

- :class:`Room`: an axis-aligned box seen from inside (floor, four walls,
  ceiling), each with its reflectance; it reflects but casts no shadow on
  what is inside it.
- Occluders that reflect are :class:`~isocsg.kinds.Box` and
  :class:`~isocsg.kinds.ConvexPolyhedron`; curved kinds and CSG trees are
  refused when given a reflectance above 0 (they stay black occluders):
  faceting them would reflect from the facets, not from the solid.

Subdivision: a parallelogram face into ``ceil(|e1| / size) x ceil(|e2| /
size)`` parallelograms; another convex face is fanned into triangles, each
cut into ``m^2`` similar triangles (``m = ceil(longest edge / size)``).
:meth:`PatchSet.split` halves the selected patches along both directions
(4 children each), which is how shadow boundaries are refined.

Each patch carries a tensor Gauss-Legendre rule (a collapsed one on
triangles) whose weights sum to its area.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .._validation import Vec3, scalar, vector3
from ..errors import InvalidParameterError
from ..kinds import Primitive, Solid

__all__ = ["Room", "PatchSet", "surface_patches", "reflector_faces", "ROOM_OWNER"]

ROOM_OWNER = -1


def _reflectance(name: str, value: float) -> float:
    return scalar(name, value, low=0.0, low_inclusive=True, high=0.999, error=InvalidParameterError)


@dataclass(frozen=True, slots=True)
class Room:
    """An axis-aligned box room seen from inside, with diffuse reflectances.

    Parameters
    ----------
    center, size : array_like, shape (3,)
        The box (metres); ``size`` > 0 in every axis. The floor is its bottom
        face (-z), the ceiling its top face.
    floor, walls, ceiling : float
        Diffuse reflectances in [0, 0.999] (defaults 0.2, 0.5 and 0.7, the
        usual assumptions of lighting design).

    Raises
    ------
    InvalidParameterError
        On a malformed vector, a size not > 0 or a reflectance out of range.

    Examples
    --------
    >>> room = Room((0, 0, 1.5), (4, 4, 3))
    >>> [name for _, _, name in room.faces()]
    ['wall -x', 'wall +x', 'wall -y', 'wall +y', 'floor', 'ceiling']
    """

    center: Vec3
    size: Vec3
    floor: float = 0.2
    walls: float = 0.5
    ceiling: float = 0.7

    def __post_init__(self) -> None:
        object.__setattr__(self, "center", vector3("room.center", self.center, error=InvalidParameterError))
        size = vector3("room.size", self.size, error=InvalidParameterError)
        if min(size) <= 0:
            raise InvalidParameterError(f"room.size must be > 0 in every axis, got {size}")
        object.__setattr__(self, "size", size)
        for name in ("floor", "walls", "ceiling"):
            object.__setattr__(self, name, _reflectance(f"room.{name}", getattr(self, name)))

    @property
    def area(self) -> float:
        """Total inner surface area."""
        sx, sy, sz = self.size
        return 2.0 * (sx * sy + sy * sz + sz * sx)

    def faces(self) -> list[tuple[NDArray[np.float64], float, str]]:
        """The six inner faces: (polygon counter-clockwise seen from inside, reflectance, name)."""
        out = []
        names = ["wall -x", "wall +x", "wall -y", "wall +y", "floor", "ceiling"]
        rho = [self.walls] * 4 + [self.floor, self.ceiling]
        c = np.asarray(self.center)
        h = 0.5 * np.asarray(self.size)
        for k in range(6):
            ax, sign = k // 2, (-1.0 if k % 2 == 0 else 1.0)
            u, v = (ax + 1) % 3, (ax + 2) % 3
            q = np.zeros((4, 3))
            for m, (a, b) in enumerate([(-1, -1), (1, -1), (1, 1), (-1, 1)]):
                q[m, ax] = c[ax] + sign * h[ax]
                q[m, u] = c[u] + a * h[u]
                q[m, v] = c[v] + b * h[v]
            # (u, v, ax) is right-handed: this winding faces +ax; the inner side of the +ax face is -ax.
            out.append((q[::-1].copy() if sign > 0 else q, rho[k], names[k]))
        return out


def reflector_faces(solid: Solid, index: int) -> list[NDArray[np.float64]]:
    """Outer faces of a reflecting occluder (counter-clockwise seen from outside).

    Raises
    ------
    InvalidParameterError
        If the occluder is not a box or a convex polyhedron.
    """
    if isinstance(solid, Primitive) and type(solid).polyhedral and solid.convex:  # its hull is itself
        return [np.asarray(f, dtype=np.float64) for f in solid.to_polyhedron().face_polygons()]
    raise InvalidParameterError(
        f"occluders[{index}] is a {type(solid).__name__}: only boxes and convex polyhedra reflect "
        "(give it reflectance 0 to keep it as a black occluder)"
    )


def _gauss_square(n: int) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
    x, w = np.polynomial.legendre.leggauss(n)
    x, w = 0.5 * (x + 1.0), 0.5 * w
    u, v = np.meshgrid(x, x, indexing="ij")
    return u.ravel(), v.ravel(), np.outer(w, w).ravel()


def _is_parallelogram(q: NDArray[np.float64]) -> bool:
    if len(q) != 4:
        return False
    return bool(np.linalg.norm(q[0] + q[2] - q[1] - q[3]) <= 1e-12 * np.max(np.abs(q)) + 1e-300)


@dataclass(frozen=True)
class PatchSet:
    """Patches packed in arrays (polygon ``k`` is ``verts[off[k]:off[k+1]]``).

    Attributes
    ----------
    verts, off, normal, area, reflectance, owner
        Polygons (counter-clockwise about ``normal``), unit normals, areas,
        reflectances and owners (occluder index, -1 for the room).
    """

    verts: NDArray[np.float64]
    off: NDArray[np.int64]
    normal: NDArray[np.float64]
    area: NDArray[np.float64]
    reflectance: NDArray[np.float64]
    owner: NDArray[np.int64]

    def __len__(self) -> int:
        return len(self.area)

    @classmethod
    def from_polygons(
        cls, polys: Sequence[NDArray[np.float64]], rho: Sequence[float], owner: Sequence[int],
    ) -> PatchSet:
        """Pack polygons (counter-clockwise about their reflecting side) with reflectances and owners."""
        off = np.zeros(len(polys) + 1, dtype=np.int64)
        off[1:] = np.cumsum([len(p) for p in polys])
        verts = np.vstack(polys) if polys else np.zeros((0, 3))
        nn = np.array([0.5 * np.sum(np.cross(p, np.roll(p, -1, axis=0)), axis=0) for p in polys]).reshape(-1, 3)
        area = np.linalg.norm(nn, axis=1)
        return cls(verts, off, nn / np.where(area > 0, area, 1.0)[:, None], area,
                   np.asarray(rho, dtype=np.float64), np.asarray(owner, dtype=np.int64))

    def polygon(self, k: int) -> NDArray[np.float64]:
        """Polygon ``k`` as a (m, 3) array."""
        return self.verts[self.off[k]:self.off[k + 1]]

    def bounds(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Per-patch axis-aligned bounds (lo, hi), each (n, 3)."""
        lo = np.minimum.reduceat(self.verts, self.off[:-1], axis=0)
        hi = np.maximum.reduceat(self.verts, self.off[:-1], axis=0)
        return lo, hi

    def samples(self, order: int) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.int64]]:
        """Quadrature points, weights (summing to each area) and their patch indices.

        ``order`` x ``order`` Gauss-Legendre points on parallelograms, the
        collapsed (Duffy) rule on triangles.
        """
        u, v, w = _gauss_square(order)
        pts, wts, idx = [], [], []
        for k in range(len(self)):
            q = self.polygon(k)
            if len(q) == 4:
                p = q[0] + u[:, None] * (q[1] - q[0]) + v[:, None] * (q[3] - q[0])
                pts.append(p)
                wts.append(w * self.area[k])
            else:
                # (u, v) -> u on the edge q0 q1 side, collapsed towards q2: Jacobian 2 A (1 - v).
                a = q[0] + u[:, None] * (q[1] - q[0])
                p = a + v[:, None] * (q[2] - a)
                pts.append(p)
                wts.append(2.0 * self.area[k] * w * (1.0 - v))
            idx.append(np.full(len(u), k, dtype=np.int64))
        if not pts:
            return np.zeros((0, 3)), np.zeros(0), np.zeros(0, dtype=np.int64)
        return np.vstack(pts), np.concatenate(wts), np.concatenate(idx)

    def split(self, which: NDArray[np.bool_]) -> PatchSet:
        """The patches with those in ``which`` cut into four (midpoints of the edges)."""
        polys, rho, owner = [], [], []
        for k in range(len(self)):
            q = self.polygon(k)
            kids = _quarter(q) if which[k] else [q]
            polys += kids
            rho += [self.reflectance[k]] * len(kids)
            owner += [int(self.owner[k])] * len(kids)
        return PatchSet.from_polygons(polys, rho, owner)


def _quarter(q: NDArray[np.float64]) -> list[NDArray[np.float64]]:
    if len(q) == 4:
        c = q.mean(axis=0)
        m = 0.5 * (q + np.roll(q, -1, axis=0))
        return [np.array([q[0], m[0], c, m[3]]), np.array([m[0], q[1], m[1], c]),
                np.array([c, m[1], q[2], m[2]]), np.array([m[3], c, m[2], q[3]])]
    a, b, c = q
    ab, bc, ca = 0.5 * (a + b), 0.5 * (b + c), 0.5 * (c + a)
    return [np.array([a, ab, ca]), np.array([ab, b, bc]), np.array([ca, bc, c]), np.array([ab, bc, ca])]


def _subdivide(q: NDArray[np.float64], size: float) -> list[NDArray[np.float64]]:
    if _is_parallelogram(q):
        e1, e2 = q[1] - q[0], q[3] - q[0]
        n1 = max(1, math.ceil(np.linalg.norm(e1) / size - 1e-9))
        n2 = max(1, math.ceil(np.linalg.norm(e2) / size - 1e-9))
        out = []
        for i in range(n1):
            for j in range(n2):
                p0 = q[0] + e1 * (i / n1) + e2 * (j / n2)
                out.append(np.array([p0, p0 + e1 / n1, p0 + e1 / n1 + e2 / n2, p0 + e2 / n2]))
        return out
    out = []
    for t in range(1, len(q) - 1):
        a, b, c = q[0], q[t], q[t + 1]
        m = max(1, math.ceil(max(np.linalg.norm(b - a), np.linalg.norm(c - b), np.linalg.norm(a - c)) / size - 1e-9))
        u, v = (b - a) / m, (c - a) / m
        for i in range(m):
            for j in range(m - i):
                p = a + i * u + j * v
                out.append(np.array([p, p + u, p + v]))
                if i + j < m - 1:
                    out.append(np.array([p + u, p + u + v, p + v]))
    return out


def surface_patches(
    room: Room | None, occluders: Sequence[Solid], reflectances: Sequence[float], size: float,
) -> PatchSet:
    """Patches of at most about ``size`` over the room's faces and the reflecting occluders' faces.

    Occluders of reflectance 0 are left out (they stay black occluders).
    """
    polys: list[NDArray[np.float64]] = []
    rho: list[float] = []
    owner: list[int] = []
    if room is not None:
        for q, r, _ in room.faces():
            if r > 0:
                kids = _subdivide(q, size)
                polys += kids
                rho += [r] * len(kids)
                owner += [ROOM_OWNER] * len(kids)
    for k, (solid, r) in enumerate(zip(occluders, reflectances, strict=True)):
        if r <= 0:
            continue
        for q in reflector_faces(solid, k):
            kids = _subdivide(q, size)
            polys += kids
            rho += [r] * len(kids)
            owner += [k] * len(kids)
    return PatchSet.from_polygons(polys, rho, owner)
