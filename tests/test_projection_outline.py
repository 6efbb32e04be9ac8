"""Outlines (``projection(cut = false)``) of differences, intersections and trees of vertical prisms.

References, independent of ``isocsg.shapes2d.outline``: closed forms and shapely's Booleans of
discs and rectangles written here, and manifold3d's projection of the same trees built from its
own meshes (circles of ``SEGMENTS`` sides, inscribed).
"""

from __future__ import annotations

import math
import random

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from isocsg import Box, Cylinder, Sphere, Torus, Truncus
from isocsg.errors import NotExactError
from isocsg.shapes2d import EMPTY, area, to_shapely
from isocsg.shapes2d.projection import outline

manifold3d = pytest.importorskip("manifold3d")
shapely = pytest.importorskip("shapely")

SEGMENTS = 512  # the meshes' circles: inscribed, within 1.9e-5 of a radius
#: On shapes about 4 across: the meshes' sagitta times the perimeters, with room.
AREA_TOL = 2e-3


def _disc(x: float, y: float, r: float, n: int = 4096) -> object:
    t = 2 * np.pi * np.arange(n) / n
    return shapely.Polygon(np.column_stack([x + r * np.cos(t), y + r * np.sin(t)]))


def _compare(shape: object, reference: object, tol: float = AREA_TOL) -> None:
    if shape is EMPTY:
        assert reference.area <= tol  # type: ignore[attr-defined]
        return
    got = to_shapely(shape, resolution=2048)  # type: ignore[arg-type]
    assert area(shape) == pytest.approx(reference.area, abs=tol)  # type: ignore[arg-type,attr-defined]
    assert got.symmetric_difference(reference).area <= tol  # type: ignore[attr-defined]


def _mesh_outline(mesh: object) -> object:
    from isocsg.shapes2d.region import fill

    rings = [np.asarray(r, dtype=np.float64) for r in mesh.project().to_polygons()]  # type: ignore[attr-defined]
    return fill(rings, "nonzero") if rings else shapely.Polygon()


# ----------------------------------------------------------------------------- a long chain


def test_outline_of_a_2000_deep_difference_chain() -> None:
    """A plate minus 2000 holes, one per loop turn (``s = s - hole``): through holes and blind
    holes from the top and from the bottom. Expected: the plate minus the through holes' discs."""
    rng = random.Random(22)
    cols, rows, pitch, r = 50, 40, 1.0, 0.3
    plate = Box((cols * pitch / 2, rows * pitch / 2, 0.5), (cols * pitch, rows * pitch, 1.0))
    s, through = plate, []
    for k in range(cols * rows):
        i, j = divmod(k, cols)
        x, y = (j + 0.5) * pitch, (i + 0.5) * pitch
        kind = rng.choice(["through", "top", "bottom"])
        if kind == "through":
            s = s - Cylinder((x, y, 0.5), (0, 0, 3.0), r)
            through.append(_disc(x, y, r, 64))
        elif kind == "top":
            s = s - Cylinder((x, y, 1.0), (0, 0, 1.2), r)  # z in [0.4, 1.6]
        else:
            s = s - Cylinder((x, y, 0.0), (0, 0, 1.4), r)  # z in [-0.7, 0.7]
    shape = outline(s)
    assert area(shape) == pytest.approx(cols * rows * pitch**2 - len(through) * math.pi * r * r, rel=1e-12)
    reference = shapely.box(0, 0, cols * pitch, rows * pitch).difference(shapely.union_all(through))
    got = to_shapely(shape, resolution=64)  # the same inscribed 64-gons as the reference's
    assert got.symmetric_difference(reference).area <= 1e-9 * cols * rows


def test_blind_holes_from_both_sides_that_meet_cut_through() -> None:
    """Pairs of blind holes, one from the bottom up to z = 0.6 and one from the top down to 0.4,
    their axes ``d`` apart: together they remove the lens of their two discs (closed form)."""
    r, d = 0.3, 0.1
    s = Box((5, 1, 0.5), (10, 2, 1.0))
    for k in range(10):
        s = s - Cylinder((k + 0.5, 1, 0.0), (0, 0, 1.2), r) - Cylinder((k + 0.5 + d, 1, 1.0), (0, 0, 1.2), r)
    lens = 2 * r * r * math.acos(d / (2 * r)) - d / 2 * math.sqrt(4 * r * r - d * d)
    assert area(outline(s)) == pytest.approx(20.0 - 10 * lens, rel=1e-12)


# ----------------------------------------------------------------------------- exact cases


def test_blind_holes_and_pockets_leave_the_outline() -> None:
    plate = Box((0, 0, 0), (4, 3, 1))
    blind = [Cylinder((-1, 0, 0.5), (0, 0, 0.8), 0.4), Box((1, 0, -0.5), (1, 1, 0.6)), Sphere((0, 1, 0.5), 0.4)]
    s = plate
    for b in blind:
        s = s - b
    assert area(outline(s)) == pytest.approx(12.0, rel=1e-12)


def test_cuts_meeting_at_a_height_hold_the_column_together() -> None:
    """A hole from the bottom up to mid-height and a square pocket from there up: together they
    hold the columns of the hole's disc (inside the square), which the outline loses."""
    plate = Box((0, 0, 0), (4, 3, 1))
    s = plate - Cylinder((-1, 0, -0.5), (0, 0, 1), 0.25) - Box((-1, 0, 0.5), (0.6, 0.6, 1))
    assert area(outline(s)) == pytest.approx(12.0 - math.pi / 16, rel=1e-12)
    s = plate - Cylinder((-1, 0, -0.5), (0, 0, 1), 0.25) - Box((-1, 0, 0.55), (0.6, 0.6, 0.9))  # a gap
    assert area(outline(s)) == pytest.approx(12.0, rel=1e-12)


def test_a_convex_cut_removes_the_columns_it_holds_end_to_end() -> None:
    """A plate over z in [-0.5, 0.5] minus convex solids that do not run through it as prisms: each
    removes the columns it holds at both faces (the smaller of its two sections, here)."""
    plate = Box((0, 0, 0), (9, 4, 1))
    ball = Sphere((-3, 0, 0.2), 1.0)  # sections of radius^2 1 - 0.7^2 (bottom) and 1 - 0.3^2 (top)
    narrowing = Truncus((0, 0, 0), (0, 0, 3), 0.2, 1.0)  # radius 0.2 at z = 1.5, 1.0 at z = -1.5
    widening = Truncus((3, 0, 0), (0, 0, 3), 1.0, 0.2)
    shape = outline(plate - ball - narrowing - widening)
    top, bottom = 1.0 + (0.2 - 1.0) * 2 / 3, 1.0 + (0.2 - 1.0) * 1 / 3  # the narrowing cone's radii at 0.5, -0.5
    removed = math.pi * (1 - 0.7**2) + math.pi * top**2 + math.pi * top**2  # the widening cone: mirror image
    assert bottom > top
    assert area(shape) == pytest.approx(36.0 - removed, rel=1e-12)


def test_a_blind_hole_in_a_ball_takes_the_columns_within_its_heights() -> None:
    """A hole over z in [-1, 3] at 1.8 from the centre of a ball of radius 2: it takes the columns
    whose bottom is above -1, those farther than sqrt(3) from the centre (the reference: shapely's
    Booleans of finely polygonised discs)."""
    s = Sphere((0, 0, 0), 2) - Cylinder((1.8, 0, 1), (0, 0, 4), 0.5)
    taken = _disc(1.8, 0, 0.5, 8192).difference(_disc(0, 0, math.sqrt(3), 8192)).intersection(_disc(0, 0, 2, 8192))
    assert area(outline(s)) == pytest.approx(4 * math.pi - taken.area, abs=1e-6)
    assert area(outline(Sphere((0, 0, 0), 2) - Cylinder((0, 0, 2), (0, 0, 2), 0.5))) == pytest.approx(4 * math.pi)


def test_intersections_of_prisms_of_different_heights() -> None:
    box, cyl = Box((0, 0, 0.5), (2, 2, 1)), Cylinder((1, 1, 1.5), (0, 0, 2), 1.0)  # z in [0, 1], [0.5, 2.5]
    assert area(outline(box & cyl)) == pytest.approx(math.pi / 4, rel=1e-12)
    assert outline(box & Cylinder((1, 1, 3), (0, 0, 1), 1.0)) is EMPTY  # z in [2.5, 3.5]: no common height


def test_refusals_name_the_operand() -> None:
    plate = Box((0, 0, 0), (4, 4, 1))
    with pytest.raises(NotExactError, match="operand Sphere, not a vertical prism, overlaps 1 other"):
        outline(plate - Sphere((0, 0, 0.2), 0.8) - Sphere((0.5, 0, -0.2), 0.8))
    with pytest.raises(NotExactError, match="operand Torus is neither a vertical prism nor a convex solid"):
        outline(plate - Torus((0, 0, 0.5), (1, 0, 0), 1.0, 0.3))
    with pytest.raises(NotExactError, match="first operand .* which is not a vertical prism"):
        outline(Cylinder((0, 0, 0), (1, 0, 2), 1) - Cylinder((0, 0, 1.5), (0, 0, 2), 0.5))  # a tilted core
    with pytest.raises(NotExactError, match="difference of a Sphere and 2 overlapping vertical prisms"):
        outline(Sphere((0, 0, 0), 2) - Cylinder((0, 0, 1.5), (0, 0, 2), 0.5) - Cylinder((0.2, 0, -1.5), (0, 0, 2), 0.5))
    with pytest.raises(NotExactError, match=r"intersection of 2 solids that are not vertical prisms \(Sphere, Sphere\)"):
        outline(Sphere((0, 0, 0), 1) & Sphere((0.5, 0, 0), 1) & Cylinder((0, 0, 0), (0, 0, 5), 0.8))


# ----------------------------------------------------------------------------- hypothesis


def _cylinder(x: float, y: float, z0: float, z1: float, r: float) -> tuple[object, object]:
    mesh = manifold3d.Manifold.cylinder(z1 - z0, r, r, SEGMENTS).translate((x, y, z0))
    return Cylinder((x, y, (z0 + z1) / 2), (0, 0, z1 - z0), r), mesh


def _box(x: float, y: float, z0: float, z1: float, w: float, d: float) -> tuple[object, object]:
    mesh = manifold3d.Manifold.cube((w, d, z1 - z0)).translate((x - w / 2, y - d / 2, z0))
    return Box((x, y, (z0 + z1) / 2), (w, d, z1 - z0)), mesh


@st.composite
def prisms(draw: st.DrawFn, k: int, xs: tuple[float, float] = (-1.5, 1.5)) -> tuple[object, object]:
    """The ``k``-th upright cylinder or box of a list, over a random height range (through the
    plate, blind, inside). Its ends are moved by ``k`` times a few thousandths: the meshes' Booleans
    settle coincident faces by a perturbation that may keep a film of no thickness, whose shadow
    the reference would show; regularised Booleans have none."""
    x, y = draw(st.floats(*xs)), draw(st.floats(-1.0, 1.0))
    z0 = draw(st.floats(-1.0, 0.4)) + 0.0037 * (k + 1)
    z1 = draw(st.floats(z0 + 0.1, 1.0)) + 0.0061 * (k + 1)
    if draw(st.booleans()):
        return _cylinder(x, y, z0, z1, draw(st.floats(0.15, 0.45)))
    return _box(x, y, z0, z1, draw(st.floats(0.2, 0.8)), draw(st.floats(0.2, 0.8)))


@st.composite
def convex_cuts(draw: st.DrawFn, y: float) -> tuple[object, object]:
    """A sphere, a cone or a tilted cylinder about (1.2, y), within 0.7 of it in x and y."""
    kind = draw(st.sampled_from(["sphere", "cone", "tilted"]))
    z = draw(st.floats(-0.4, 0.4))
    if kind == "sphere":
        r = draw(st.floats(0.3, 0.65))
        return Sphere((1.2, y, z), r), manifold3d.Manifold.sphere(r, SEGMENTS).translate((1.2, y, z))
    if kind == "cone":
        r1, r2 = draw(st.floats(0.05, 0.6)), draw(st.floats(0.05, 0.6))
        mesh = manifold3d.Manifold.cylinder(2.0, r2, r1, SEGMENTS, True).translate((1.2, y, z))
        return Truncus((1.2, y, z), (0, 0, 2.0), r1, r2), mesh
    tilt = math.radians(draw(st.floats(-8.0, 8.0)))
    m = np.eye(4)
    m[:3, :3] = [[math.cos(tilt), 0, math.sin(tilt)], [0, 1, 0], [-math.sin(tilt), 0, math.cos(tilt)]]
    m[:3, 3] = (1.2, y, z)
    mesh = manifold3d.Manifold.cylinder(2.4, 0.35, 0.35, SEGMENTS, True).transform(m[:3])
    return Cylinder((0, 0, 0), (0, 0, 2.4), 0.35).transform(m), mesh


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(1, 6).flatmap(lambda n: st.tuples(*(prisms(k, xs=(-1.6, -0.75)) for k in range(n)))),
       st.one_of(st.just(()), st.tuples(convex_cuts(-0.8)), st.tuples(convex_cuts(-0.8), convex_cuts(0.8))),
       st.one_of(st.none(), st.floats(0.6, 1.2)), st.randoms(use_true_random=False))
def test_plate_with_blind_through_and_convex_cuts(holes: tuple[tuple[object, object], ...],
                                                  convex: tuple[tuple[object, object], ...], boss: float | None,
                                                  rnd: random.Random) -> None:
    """Prisms of any heights cut into the left half of a plate (overlapping one another), convex
    solids into the right half (one per cell), subtracted one by one in a random order; the plate
    has a boss (an upright cylinder up to ``boss``) or not."""
    cuts = [*holes, *convex]
    rnd.shuffle(cuts)
    solid, mesh = _box(0.0, 0.0, -0.5, 0.5, 4.0, 3.0)
    if boss is not None:
        c, cm = _cylinder(-0.6, 0.2, -0.5, boss, 0.7)
        solid, mesh = solid | c, mesh + cm  # type: ignore[operator]
    for s, mm in cuts:
        solid, mesh = solid - s, mesh - mm  # type: ignore[operator]
    _compare(outline(solid), _mesh_outline(mesh))  # type: ignore[arg-type]


@st.composite
def prism_trees(draw: st.DrawFn) -> tuple[object, object]:
    parts = [draw(prisms(k)) for k in range(draw(st.integers(2, 5)))]
    solid, mesh = parts[0]
    for s, mm in parts[1:]:
        op = draw(st.sampled_from(["union", "difference", "intersection"]))
        if op == "union":
            solid, mesh = solid | s, mesh + mm  # type: ignore[operator]
        elif op == "difference":
            solid, mesh = solid - s, mesh - mm  # type: ignore[operator]
        else:
            solid, mesh = solid & s, mesh ^ mm  # type: ignore[operator]
    return solid, mesh


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(prism_trees())
def test_trees_of_vertical_prisms(tree: tuple[object, object]) -> None:
    solid, mesh = tree
    _compare(outline(solid), _mesh_outline(mesh))  # type: ignore[arg-type]


@st.composite
def nested_cores(draw: st.DrawFn) -> tuple[object, object]:
    """A ball or an upright cone or frustum about the origin (horizontal sections: nested discs)."""
    if draw(st.booleans()):
        r = draw(st.floats(1.2, 1.8))
        return Sphere((0, 0, 0), r), manifold3d.Manifold.sphere(r, SEGMENTS)
    # a cone's apex (0) or a frustum's top; no radius so small that Truncus refuses it as degenerate
    r1, r2 = draw(st.one_of(st.just(0.0), st.floats(0.05, 1.8))), draw(st.floats(0.6, 1.8))
    mesh = manifold3d.Manifold.cylinder(2.0, r2, r1, SEGMENTS, True)
    return Truncus((0, 0, 0), (0, 0, 2.0), r1, r2), mesh


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(nested_cores(), st.integers(1, 3).flatmap(lambda n: st.tuples(*(prisms(k, xs=(0.0, 0.0)) for k in range(n)))))
def test_ball_or_cone_minus_vertical_prisms_through_or_not(core: tuple[object, object],
                                                           cuts: tuple[tuple[object, object], ...]) -> None:
    """Vertical prisms of any heights, one per cell (x = -1, 0, 1), cut from a ball or an upright
    cone: each takes out the columns of the core that lie within its height range."""
    solid, mesh = core
    for k, (s, mm) in enumerate(cuts):
        dx = (k - 1) * 1.0
        solid, mesh = solid - s.translate([dx, -float(s.center[1]), 0]), mesh - mm.translate((dx, -float(s.center[1]), 0))  # type: ignore[attr-defined,operator]
    _compare(outline(solid), _mesh_outline(mesh))  # type: ignore[arg-type]
