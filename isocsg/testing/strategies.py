"""Hypothesis strategies for random CSG trees, and trees written back as Python code.

hypothesis is an optional dependency (the ``testing`` extra), imported when a strategy is made.

- :func:`primitives`: spheres, boxes (axis-aligned or turned), cylinders, cones, frusta,
  ellipsoids and tori with centres and sizes on a coarse grid (so that faces coincide and touch
  often), with an optional share of near-degenerate ones (thin rods and discs, nearly flat boxes);
- :func:`trees`: nested unions, intersections and differences of them;
- :func:`cube_fuzz`: up to 100 unit cubes turned and moved at random, combined by unions and
  differences (a simple form of manifold's fuzz domain);
- :func:`manifold_fuzz`: manifold's own fuzz domain (its ``ManifoldFuzz.SimpleCube`` test);
- :func:`to_python`: a tree as code that rebuilds it (``repr`` of every primitive is exact).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..csg.tree import CSGNode, Difference, Intersection, Union
from ..kinds import Box, Cone, Cylinder, Ellipsoid, Primitive, Solid, Sphere, Torus, Truncus

__all__ = ["cube_fuzz", "manifold_cube", "manifold_fuzz", "primitives", "to_python", "trees"]


def _hyp() -> Any:
    try:
        import hypothesis.strategies as st
    except ImportError:  # pragma: no cover
        from ..errors import IsocsgError

        raise IsocsgError("isocsg.testing.strategies needs hypothesis: pip install isocsg[testing]") from None
    return st


def primitives(*, grid: float = 0.25, degenerate: bool = True) -> Any:
    """A strategy for primitives near the origin (coordinates on multiples of ``grid``)."""
    st = _hyp()
    coord = st.integers(-4, 4).map(lambda k: k * grid)
    size = st.integers(1, 8).map(lambda k: k * grid)
    centre = st.tuples(coord, coord, coord)
    axis = st.sampled_from([(0.0, 0.0, 1.0), (0.0, 1.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 1.0), (0.3, -0.5, 1.0)])
    angle = st.sampled_from([0.0, 30.0, 45.0, 90.0, 17.0])
    leaves = [
        st.builds(Sphere, centre, size),
        st.builds(lambda c, s, a: Box(c, s).rotate((0.0, 0.0, a), ) if a else Box(c, s),
                  centre, st.tuples(size, size, size), angle),
        st.builds(lambda c, a, h, r: Cylinder(c, tuple(h * x for x in a), r), centre, axis, size, size),
        st.builds(lambda c, a, h, r: Cone(c, tuple(h * x for x in a), r), centre, axis, size, size),
        st.builds(lambda c, a, h, r1, r2: Truncus(c, tuple(h * x for x in a), r1, r2), centre, axis, size, size, size),
        st.builds(Ellipsoid, centre, st.tuples(size, size, size)),
        st.builds(lambda c, a, R, k: Torus(c, a, R + grid, (R + grid) * k), centre, axis, size,
                  st.sampled_from([0.2, 0.35, 0.5])),
    ]
    if degenerate:
        leaves += [
            st.builds(lambda c, a: Cylinder(c, a, 1e-3), centre, axis),  # a thin rod
            st.builds(lambda c: Cylinder(c, (0.0, 0.0, 1e-3), 0.5), centre),  # a thin disc
            st.builds(lambda c: Box(c, (1.0, 1.0, 1e-4)), centre),  # a nearly flat plate
        ]
    return st.one_of(*leaves)


def trees(*, max_leaves: int = 6, grid: float = 0.25, degenerate: bool = True) -> Any:
    """A strategy for CSG trees of 1 .. ``max_leaves`` primitives (see :func:`primitives`)."""
    st = _hyp()
    ops = [Union, Intersection, Difference]
    leaf = primitives(grid=grid, degenerate=degenerate)  # built once: hypothesis validates it on first use

    @st.composite
    def build(draw: Any) -> Solid:
        n = draw(st.integers(1, max_leaves))
        parts: list[Solid] = [draw(leaf) for _ in range(n)]
        while len(parts) > 1:  # join two neighbours at a time: any binary shape
            k = draw(st.integers(0, len(parts) - 2))
            op = draw(st.sampled_from(ops))
            parts[k: k + 2] = [op(parts[k], parts[k + 1])]
        return parts[0]

    return build()


def cube_fuzz(*, max_cubes: int = 100) -> Any:
    """manifold's fuzz domain: up to ``max_cubes`` unit cubes, each turned by random Euler angles and
    moved within [-1, 1]^3 (its ``Boolean.Fuzz`` test), folded left to right by unions and
    differences."""
    st = _hyp()
    num = st.floats(-1.0, 1.0, allow_nan=False, allow_infinity=False)
    ang = st.floats(0.0, 360.0, allow_nan=False, allow_infinity=False)
    cube = st.builds(lambda r, t: Box((0.0, 0.0, 0.0), (1.0, 1.0, 1.0)).rotate(r).translate(t),
                     st.tuples(ang, ang, ang), st.tuples(num, num, num))

    @st.composite
    def build(draw: Any) -> Solid:
        n = draw(st.integers(2, max_cubes))
        out: Solid = draw(cube)
        for _ in range(n - 1):
            c = draw(cube)
            out = (out | c) if draw(st.booleans()) else (out - c)
        return out

    return build()


def manifold_cube(transforms: Sequence[tuple[str, Sequence[float]]]) -> Solid:
    """manifold's ``Manifold::Cube()`` (the unit cube ``[0, 1]^3``) moved by ``transforms`` in
    order, each ``("translate" | "rotate" | "scale", (x, y, z))`` as manifold's ``Translate``,
    ``Rotate`` (Euler angles in degrees, about x, then y, then z) and ``Scale``.

    Raises
    ------
    InvalidParameterError
        On an unknown transform name (the message names it).
    InvalidGeometryError
        When the result is degenerate or too thin (see :meth:`isocsg.kinds.Primitive.transform`).

    Examples
    --------
    >>> c = manifold_cube([("scale", (2.0, 1.0, 1.0)), ("translate", (1.0, 0.0, 0.0))])
    >>> round(float(c.volume), 12), float(c.bounds[0][0]), float(c.bounds[1][0])
    (2.0, 1.0, 3.0)
    """
    m = _fuzz_matrix(transforms)
    unit = Box((0.5, 0.5, 0.5), (1.0, 1.0, 1.0))
    return unit if np.array_equal(m, np.eye(4)) else unit.transform(m)


def _fuzz_matrix(transforms: Sequence[tuple[str, Sequence[float]]]) -> NDArray[np.float64]:
    from ..errors import InvalidParameterError
    from ..kinds.affine import rotation_matrix, scale_matrix, translation_matrix

    make = {"translate": translation_matrix, "rotate": rotation_matrix, "scale": scale_matrix}
    m = np.eye(4)
    for kind, v in transforms:  # each transform applies to the cube as moved so far
        if kind not in make:
            raise InvalidParameterError(f"transforms: unknown transform {kind!r} (translate, rotate or scale)")
        m = np.asarray(make[kind](v), dtype=np.float64) @ m
    return m


def manifold_fuzz(*, max_ops: int = 100, max_transforms: int = 20) -> Any:
    """manifold's fuzz domain (``test/manifold_fuzz.cpp``, ``ManifoldFuzz.SimpleCube``): up to
    ``max_ops`` cubes ``[0, 1]^3``, each moved by up to ``max_transforms`` translations, rotations
    (Euler angles in degrees) and scalings (:func:`manifold_cube`), every number in ``[0.1, 10]``
    or ``[-10, -0.1]``, each added to or subtracted from the running result.

    manifold's running result starts empty, so operations before the first union change nothing:
    here the first operation is a union. A cube scaled unevenly after a turn is a parallelepiped
    (a :class:`~isocsg.kinds.ConvexPolyhedron`); chains whose linear part has a condition number
    over :data:`isocsg.kinds.affine.MAX_CONDITION` (slivers isocsg refuses) are not drawn.
    """
    from ..kinds.affine import MAX_CONDITION

    st = _hyp()
    mag = st.floats(0.1, 10.0, allow_nan=False, allow_infinity=False)
    good = st.one_of(mag, mag.map(lambda x: -x))
    step = st.tuples(st.sampled_from(["rotate", "scale", "translate"]), st.tuples(good, good, good))

    def sane(steps: list[tuple[str, tuple[float, float, float]]]) -> bool:
        m = _fuzz_matrix(steps)
        sv = np.linalg.svd(m[:3, :3], compute_uv=False)
        return bool(np.all(np.isfinite(m)) and sv[-1] > 0 and sv[0] / sv[-1] <= MAX_CONDITION)

    cube = st.lists(step, max_size=max_transforms).filter(sane).map(manifold_cube)

    @st.composite
    def build(draw: Any) -> Solid:
        n = draw(st.integers(1, max_ops))
        out: Solid = draw(cube)
        for _ in range(n - 1):
            c = draw(cube)
            out = (out | c) if draw(st.booleans()) else (out - c)
        return out

    return build()


def to_python(solid: Solid, name: str = "tree") -> str:
    """Python code that rebuilds ``solid`` exactly (``from isocsg import *`` first).

    Examples
    --------
    >>> from isocsg import Box, Sphere
    >>> code = to_python(Sphere((0, 0, 0), 1) - Box((0, 0, 1), (1, 1, 1)))
    >>> print(code)
    from isocsg import *
    p0 = Sphere(center=(0.0, 0.0, 0.0), radius=1.0)
    p1 = Box(center=(0.0, 0.0, 1.0), size=(1.0, 1.0, 1.0))
    tree = Difference(p0, p1)
    >>> ns: dict = {}
    >>> exec(code, ns)
    >>> ns["tree"] == Sphere((0, 0, 0), 1) - Box((0, 0, 1), (1, 1, 1))
    True
    """
    lines = ["from isocsg import *"]
    names: dict[int, str] = {}
    todo: list[tuple[Solid, bool]] = [(solid, False)]
    k = 0
    while todo:
        s, expanded = todo.pop()
        if id(s) in names:
            continue
        if isinstance(s, CSGNode) and not expanded:
            todo.append((s, True))
            todo.extend((c, False) for c in reversed(s.children))
            continue
        if isinstance(s, CSGNode):
            args = ", ".join(names[id(c)] for c in s.children)
            expr = f"{type(s).__name__}({args})"
            var = f"n{k}"
        else:
            assert isinstance(s, Primitive)
            expr = repr(s)
            var = f"p{k}"
        k += 1
        names[id(s)] = var
        lines.append(f"{var} = {expr}")
    last = lines[-1].split(" = ", 1)
    lines[-1] = f"{name} = {last[1]}"
    return "\n".join(lines)
