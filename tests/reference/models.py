"""Large CSG models shared by the scale tests and the scale benchmark.

Each builder uses the library's public constructors only (primitives,
``|``, ``&``, ``-``, ``union_all``, ``difference``) and returns the model
with the closed forms a reference needs (exact volume, exact area of a
section) where they exist.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from isocsg import (
    Box,
    Cone,
    ConvexPolyhedron,
    Cylinder,
    Difference,
    Intersection,
    Sphere,
    Truncus,
    Union,
    difference,
    union_all,
)

__all__ = ["Plate", "plate_with_holes", "sphere_lattice", "nested_model", "random_tree", "loop_tree"]


@dataclass(frozen=True)
class Plate:
    """A box plate pierced by ``n`` vertical cylindrical holes on a grid (the holes stay inside it).

    ``volume`` and ``area_mid`` (the section by the plate's mid-plane z = 0) are exact.
    """

    plate: Any
    holes: tuple[Any, ...]
    size: tuple[float, float, float]
    radius: float

    @property
    def n(self) -> int:
        return len(self.holes)

    def loop(self) -> Any:
        """``for h in holes: part = part - h`` (one nesting level per hole)."""
        part = self.plate
        for h in self.holes:
            part = part - h
        return part

    def flat(self) -> Any:
        """``difference(plate, *holes)``: one node."""
        return difference(self.plate, *self.holes)

    def grouped(self) -> Any:
        """``plate - union_all(holes)``."""
        return self.plate - union_all(self.holes)

    @property
    def volume(self) -> float:
        sx, sy, sz = self.size
        return sx * sy * sz - self.n * math.pi * self.radius**2 * sz

    @property
    def area_mid(self) -> float:
        sx, sy, _ = self.size
        return sx * sy - self.n * math.pi * self.radius**2


def plate_with_holes(n: int, *, width: float = 4.0, thickness: float = 0.4) -> Plate:
    """A plate ``width`` x ``0.75 width`` with ``n`` holes filling a grid of about 4:3 cells.

    Hole radius: 0.3 of the grid pitch; the holes are 3x longer than the plate is thick.
    """
    cols = max(1, math.ceil(math.sqrt(n * 4 / 3)))
    rows = max(1, math.ceil(n / cols))
    pitch = min(width / cols, 0.75 * width / rows)
    radius = 0.3 * pitch
    sx, sy = cols * pitch, rows * pitch
    holes = []
    for k in range(n):
        i, j = divmod(k, cols)
        x = -sx / 2 + (j + 0.5) * pitch
        y = -sy / 2 + (i + 0.5) * pitch
        holes.append(Cylinder((x, y, 0.0), (0.0, 0.0, 3 * thickness), radius))
    return Plate(Box((0.0, 0.0, 0.0), (sx, sy, thickness)), tuple(holes), (sx, sy, thickness), radius)


def sphere_lattice(n_side: int = 10, *, extent: float = 3.0, overlap: float = 1.2) -> Any:
    """The union of ``n_side**3`` spheres on a cubic lattice centred at the origin; neighbours
    overlap (radius ``overlap`` times half the pitch)."""
    pitch = extent / n_side
    r = overlap * pitch / 2
    c = (np.arange(n_side) - (n_side - 1) / 2) * pitch
    return union_all(Sphere((float(x), float(y), float(z)), r) for x in c for y in c for z in c)


def _fibonacci(n: int) -> np.ndarray:
    """``n`` nearly evenly spread unit vectors."""
    k = np.arange(n) + 0.5
    z = 1 - 2 * k / n
    phi = math.pi * (3 - math.sqrt(5)) * k
    s = np.sqrt(1 - z * z)
    return np.column_stack([s * np.cos(phi), s * np.sin(phi), z])


def nested_model(n: int = 1000) -> Any:
    """``(Intersection of n balls) - union_all(n dimples) | union_all(n studs)``.

    The intersection of ``n`` balls of radius 2 centred 1.1 from the origin is a
    rounded convex body (every ray through it meets all n balls); dimples
    (small spheres) are cut into its upper half, studs (small boxes) stand on
    its lower half: three n-operand nodes nested in a union and a difference.
    """
    body = Intersection(*(Sphere(tuple(float(v) for v in 1.1 * d), 2.0) for d in _fibonacci(n)))
    spots = _fibonacci(int(2.3 * n) + 4)
    pick_up = spots[spots[:, 2] > 0.05][:n]
    pick_down = spots[spots[:, 2] < -0.05][-n:]
    dimple_r = 1.2 / math.sqrt(n)
    stud = 1.4 / math.sqrt(n)
    dimples = [Sphere(tuple(float(v) for v in 0.9 * d), dimple_r) for d in pick_up]
    studs = [Box(tuple(float(v) for v in 0.9 * d), (stud, stud, stud)) for d in pick_down]
    return (body - union_all(dimples)) | union_all(studs)


def _random_primitive(rng: np.random.Generator, centre: np.ndarray) -> Any:
    kind = rng.integers(6)
    s = rng.uniform(0.25, 0.6)
    c = tuple(float(v) for v in centre)
    axis = rng.normal(size=3)
    axis = tuple(float(v) for v in axis / np.linalg.norm(axis) * rng.uniform(0.5, 1.3))
    if kind == 0:
        return Sphere(c, s)
    if kind == 1:
        return Box(c, tuple(float(v) for v in rng.uniform(0.3, 1.0, 3)))
    if kind == 2:
        return Cylinder(c, axis, 0.6 * s)
    if kind == 3:
        return Cone(c, axis, s)
    if kind == 4:
        return Truncus(c, axis, s, 0.5 * s)
    octa = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=float)
    return ConvexPolyhedron(centre + s * (octa + 0.3 * rng.uniform(-1, 1, (6, 3))))


def random_tree(n_leaves: int, seed: int, *, weights: tuple[float, float, float] = (0.6, 0.15, 0.25)) -> Any:
    """A random tree of ``n_leaves`` primitives of every kind, built bottom up.

    The primitives are scattered in a cube whose volume grows with their
    number (the density stays the same) and sorted along a space-filling
    order, so that neighbours in the list overlap; each level combines runs of
    2 to 4 consecutive items with a union, intersection or difference
    (probabilities ``weights`` for the first level; above it, where groups
    of neighbours rarely overlap, unions and differences only, 0.7 and 0.3,
    so that most trees are not empty).
    """
    rng = np.random.default_rng(seed)
    side = 0.9 * n_leaves ** (1 / 3)
    centres = rng.uniform(-side / 2, side / 2, (n_leaves, 3))
    # Morton order of a 1024^3 grid: neighbours in the list are neighbours in space
    q = np.clip(((centres + side / 2) / side * 1023).astype(np.int64), 0, 1023)
    key = np.zeros(n_leaves, dtype=np.int64)
    for bit in range(10):
        for axis in range(3):
            key |= ((q[:, axis] >> bit) & 1) << (3 * bit + axis)
    items: list[Any] = [_random_primitive(rng, centres[i]) for i in np.argsort(key, kind="stable")]
    ops = (Union, Intersection, Difference)
    p = np.asarray(weights, dtype=np.float64) / sum(weights)
    while len(items) > 1:
        nxt: list[Any] = []
        i = 0
        while i < len(items):
            k = int(rng.integers(2, 5))
            group = items[i : i + k]
            i += k
            nxt.append(group[0] if len(group) == 1 else ops[rng.choice(3, p=p)](*group))
        items = nxt
        p = np.array([0.7, 0.0, 0.3])
    return items[0]


def loop_tree(n_ops: int, *, distinct: int | None = None) -> tuple[Any, Plate]:
    """A plate minus holes built by a loop of ``n_ops`` differences, nesting one level each.

    With ``distinct`` set, the loop cycles through that many different holes
    (each subtracted ``n_ops / distinct`` times): the same set as the plate
    minus the distinct holes.
    """
    plate = plate_with_holes(distinct or n_ops)
    part = plate.plate
    holes = plate.holes
    for i in range(n_ops):
        part = part - holes[i % len(holes)]
    return part, plate
