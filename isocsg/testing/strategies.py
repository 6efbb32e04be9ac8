"""Hypothesis strategies for random CSG trees, and trees written back as Python code.

hypothesis is an optional dependency (the ``testing`` extra), imported when a strategy is made.

- :func:`primitives`: spheres, boxes (axis-aligned or turned), cylinders, cones, frusta,
  ellipsoids and tori with centres and sizes on a coarse grid (so that faces coincide and touch
  often), with an optional share of near-degenerate ones (thin rods and discs, nearly flat boxes);
- :func:`trees`: nested unions, intersections and differences of them;
- :func:`cube_fuzz`: manifold's fuzz domain, up to 100 unit cubes turned and moved at random,
  combined by unions and differences;
- :func:`to_python`: a tree as code that rebuilds it (``repr`` of every primitive is exact).
"""

from __future__ import annotations

from typing import Any

from ..csg.tree import CSGNode, Difference, Intersection, Union
from ..kinds import Box, Cone, Cylinder, Ellipsoid, Primitive, Solid, Sphere, Torus, Truncus

__all__ = ["cube_fuzz", "primitives", "to_python", "trees"]


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

    @st.composite
    def build(draw: Any) -> Solid:
        n = draw(st.integers(1, max_leaves))
        parts: list[Solid] = [draw(primitives(grid=grid, degenerate=degenerate)) for _ in range(n)]
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
