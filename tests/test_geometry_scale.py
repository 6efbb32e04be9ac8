"""Sections, volumes and point membership of large trees, with their boundary semantics.

References: closed forms (a plate minus disjoint cylinders, inscribed regular
polygons, napkin rings, frusta), manifold3d's Booleans of its own meshes and
``Manifold.slice``, and exact point-in-hole arithmetic for the plates. Timing is
measured outside the tests (``docs/csg.md``).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import manifold3d as m3
import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from isocsg import Box, Cone, ConvexPolyhedron, Cylinder, InvalidParameterError, Sphere, Truncus, union_all
from isocsg.csg import section as section_module
from isocsg.csg.program import compile_program
from isocsg.csg.section import section
from isocsg.csg.volume import closed_form_volume, section_areas, volume

sys.path.insert(0, str(Path(__file__).resolve().parent))

from test_csg_geometry import _ref, manifold_slice  # noqa: E402

# --------------------------------------------------------------------------- plates

PLATE = (100.0, 100.0, 10.0)
R_HOLE = 0.3


def plate(n_side: int, *, depths: tuple[float, ...] = (), seed: int = 0):
    """A 100 x 100 x 10 plate (z in [-5, 5]) minus n_side^2 disjoint vertical holes on a jittered grid.

    Without ``depths`` the holes go through (z in [-7, 7]); with them, each
    hole is blind from the top face down to one of the depths (cycled).
    Returns the tree and the hole centres (x, y), radius and z range.
    """
    rng = np.random.default_rng(seed)
    pitch = 100.0 / n_side
    i, j = np.meshgrid(np.arange(n_side), np.arange(n_side), indexing="ij")
    jitter = rng.uniform(-0.2, 0.2, size=(2, n_side, n_side)) * (pitch - 2 * R_HOLE)
    x = (-50 + pitch * (i + 0.5) + jitter[0]).ravel()
    y = (-50 + pitch * (j + 0.5) + jitter[1]).ravel()
    holes = []
    z0 = np.full(len(x), -7.0)
    z1 = np.full(len(x), 7.0)
    for k, (cx, cy) in enumerate(zip(x, y)):
        if depths:
            z0[k] = 5.0 - depths[k % len(depths)]
        holes.append(Cylinder((cx, cy, 0.5 * (z0[k] + z1[k])), (0, 0, z1[k] - z0[k]), R_HOLE))
    tree = Box((0, 0, 0), PLATE) - union_all(holes)
    return tree, x, y, z0, z1


def plate_inside(pts, n_side, x, y, z0, z1):
    """Exact membership for the plate: each point can only be in the hole of its grid cell."""
    pitch = 100.0 / n_side
    inp = np.all(np.abs(pts) <= np.array(PLATE) / 2, axis=1)
    ci = np.clip(((pts[:, 0] + 50) // pitch).astype(int), 0, n_side - 1)
    cj = np.clip(((pts[:, 1] + 50) // pitch).astype(int), 0, n_side - 1)
    k = ci * n_side + cj
    in_hole = ((pts[:, 0] - x[k]) ** 2 + (pts[:, 1] - y[k]) ** 2 < R_HOLE**2) & (pts[:, 2] > z0[k]) & (pts[:, 2] < z1[k])
    return inp & ~in_hole


@pytest.fixture(scope="module")
def plate_1000():
    return plate(32)  # 1024 holes


@pytest.fixture(scope="module")
def plate_10000():
    return plate(100)


def test_plate_section_area_matches_closed_form(plate_1000):
    """Regression: a plate minus 1000 holes once gave 3.80 instead of about 9 700 (the
    packed program encoding; fixed by the flat program)."""
    tree, x, *_ = plate_1000
    n = len(x)
    exact = 100.0 * 100.0 - n * math.pi * R_HOLE**2
    s = section(tree, (0, 0, 0.3), (0, 0, 1), area_exact=True)
    assert s.area == pytest.approx(exact, rel=1e-12)
    # inscribed polygons: the holes are regular 256-gons, a closed form too
    s = section(tree, (0, 0, 0.3), (0, 0, 1), resolution=256)
    assert s.area == pytest.approx(100.0 * 100.0 - n * 128 * R_HOLE**2 * math.sin(2 * math.pi / 256), rel=1e-12)
    assert len(s.geometry.interiors) == n


def test_section_uses_only_the_leaves_the_plane_cuts(monkeypatch):
    """A 10 000-hole plate with blind holes of four depths: a plane cuts only the holes that reach it."""
    tree, x, _, z0, _ = plate(100, depths=(2.0, 4.0, 6.0, 8.0))
    seen: list[int] = []
    original = section_module.leaf_sections

    def spy(prog, F, resolution, **kw):
        seen.append(len(kw["ids"]))
        return original(prog, F, resolution, **kw)

    monkeypatch.setattr(section_module, "leaf_sections", spy)
    z = -0.5  # reached by the holes 6 and 8 deep only
    s = section(tree, (0, 0, z), (0, 0, 1), area_exact=True)
    cut = int(np.sum(z0 < z))
    assert cut == len(x) // 2
    assert sum(seen) == cut + 1  # the plate and the holes it meets
    assert s.area == pytest.approx(100.0 * 100.0 - cut * math.pi * R_HOLE**2, rel=1e-12)
    calls: list[tuple[int, int]] = []
    section(tree, (0, 0, 4.0), (0, 0, 1), progress=lambda d, t: calls.append((d, t)))
    assert calls[-1][0] == calls[-1][1] and len(calls) >= 2


def plate_reference(holes: tuple, segments: int, tiles: int = 32) -> list[m3.Manifold]:
    """manifold3d's plate minus its holes, as tiles x tiles disjoint pieces (each hole lies in one
    grid cell, and the tiles follow the cells): a tile's box minus its holes, composed into one
    manifold, in one Boolean each (one Boolean with 1000 holes in one face took manifold3d 16 s here)."""
    _, x, y, z0, z1 = holes
    width = 100.0 / tiles
    out = []
    for a in range(tiles):
        for b in range(tiles):
            lo = np.array([-50 + a * width, -50 + b * width, -PLATE[2] / 2])
            sel = (x >= lo[0]) & (x < lo[0] + width) & (y >= lo[1]) & (y < lo[1] + width)
            cyl = [
                m3.Manifold.cylinder(q - p, R_HOLE, R_HOLE, segments).translate((cx, cy, p))
                for cx, cy, p, q in zip(x[sel], y[sel], z0[sel], z1[sel])
            ]
            out.append(m3.Manifold.cube((width, width, PLATE[2])).translate(tuple(lo)) - m3.Manifold.compose(cyl))
    return out


def slice_tiles(tiles: list[m3.Manifold], frame: np.ndarray):
    """The plane section of the tiled reference: each tile's ``Manifold.slice``, joined."""
    R, o = frame[:3, :3], frame[:3, 3]
    to_frame = np.column_stack([R.T, -R.T @ o]).tolist()
    parts = []
    for t in tiles:
        rings = [np.asarray(r) for r in t.transform(to_frame).slice(0.0).to_polygons() if len(r) >= 3]
        if not rings:
            continue
        rings.sort(key=lambda r: -abs(shapely.Polygon(r).area))
        shell = shapely.Polygon(rings[0])
        assert all(shell.contains(shapely.Polygon(r)) for r in rings[1:])  # one shell per tile, holes inside
        parts.append(shapely.Polygon(rings[0], rings[1:]))
    return shapely.union_all(parts)


def test_section_with_a_tilted_plane_of_the_plate_matches_manifold_slice(plate_1000):
    tree, *_ = plate_1000
    o, n = (3.0, -2.0, 0.5), (0.2, -0.1, 0.97)
    s = section(tree, o, n, resolution=32)
    ref = slice_tiles(plate_reference(plate_1000, 32), s.frame)
    # both cut the holes' regular 32-gon prisms: ellipses' affine images of the 32-gon
    # (up to manifold3d's rounding of the transformed mesh: 1.5e-9 seen)
    assert abs(s.area / ref.area - 1) < 1e-8
    # ... whose vertices differ in phase: each differs from the true ellipse by less than its deficit
    deficit = 1 - 32 / (2 * math.pi) * math.sin(2 * math.pi / 32)
    holes = len(plate_1000[1]) * math.pi * R_HOLE**2 / abs(n[2] / np.linalg.norm(n))
    assert 0 < s.geometry.symmetric_difference(ref).area < 2 * deficit * holes


# --------------------------------------------------------------------------- faces in the plane

BASE = Box((0, 0, 0), (20, 20, 10))  # top face at z = 5
BOSS = Cylinder((0, 0, 10), (0, 0, 10), 5.0)  # bottom face at z = 5


@pytest.mark.parametrize(
    ("solid", "z", "expected"),
    [
        (BASE, 5.0, 0.0),  # the plane only touches the top face
        (BASE, -5.0, 0.0),  # ... or the bottom face
        (BOSS, 5.0, 0.0),
        (BASE | BOSS, 5.0, 25 * math.pi),  # solid on both sides only under the boss
        (BASE | Box((0, 0, 10), (20, 20, 10)), 5.0, 400.0),  # stacked boxes: the shared face once
        (BASE | BASE, 5.0, 0.0),
        (BASE | BASE, 0.0, 400.0),
        (BASE - Box((0, 0, 3), (4, 4, 4)), 5.0, 0.0),  # a pocket flush with the top face
        (BASE - Box((0, 0, 3), (4, 4, 4)), 1.0, 400.0 - 16.0),  # the pocket's floor
    ],
    ids=["touch-top", "touch-bottom", "touch-boss", "boss-on-plate", "stacked", "a|a-face", "a|a-middle",
         "pocket-rim", "pocket-floor"],
)
def test_section_in_the_plane_of_faces(solid, z, expected):
    """Regression: the section in the plane of two leaves' faces once returned both faces
    (126.36 where the regularised solid has 78.54 on a plate and a boss)."""
    s = section(solid, (0, 0, z), (0, 0, 1), area_exact=True)
    assert s.area == pytest.approx(expected, rel=1e-12, abs=1e-9)


def test_face_section_is_where_both_side_limits_agree():
    solid = BASE | BOSS
    above = section(solid, (0, 0, 5 + 1e-7), (0, 0, 1), area_exact=True).area
    below = section(solid, (0, 0, 5 - 1e-7), (0, 0, 1), area_exact=True).area
    at = section(solid, (0, 0, 5), (0, 0, 1), area_exact=True).area
    assert above == pytest.approx(25 * math.pi, rel=1e-12) and below == pytest.approx(400.0)
    assert at == pytest.approx(min(above, below), rel=1e-12)
    # manifold3d's slice just above and below agrees with both limits
    mesh = _ref(solid, 256)
    F = section(solid, (0, 0, 5 + 1e-7), (0, 0, 1)).frame
    assert manifold_slice(mesh, F).area == pytest.approx(256 / 2 * 25 * math.sin(2 * math.pi / 256), rel=1e-9)


# --------------------------------------------------------------------------- volumes


PRIMITIVES = {
    "sphere": Sphere((0.3, -1, 2), 0.7),
    "cylinder-tilted": Cylinder((0, 0, 0), (1, 2, 0.5), 0.4),
    "cone-tilted": Cone((1, 0, 0), (0.3, 0.1, -1.2), 0.8),
    "box": Box((1, 2, 3), (0.5, 1.5, 2.5)),
}


@pytest.mark.parametrize(
    ("solid", "exact"),
    [
        (Sphere((5, 0, 0), 1) | Sphere((0, 0, 0), 2) | Sphere((0, 0, 4), 1), 4 / 3 * math.pi * 10),
        (Sphere((0, 0, 0), 2) - Sphere((0.3, 0.2, 0.1), 1) - Box((0, 0, -1.5), (0.5, 0.5, 0.5)),
         4 / 3 * math.pi * 7 - 0.125),
        (Cylinder((0, 0, 0), (0, 0, 4), 2) - Cylinder((0, 0, 0), (0, 0, 6), 1), math.pi * 3 * 4),  # a tube
        (Cone((0, 0, 0), (0, 0, 3), 1.5) | Cylinder((0, 0, 2.5), (0, 0, 2), 0.5), math.pi * 2.25 + math.pi * 0.5),
        (Cylinder((0, 0, 0), (0, 0, 4), 2) - Sphere((0, 0, 0), 1) - Sphere((0, 0, 1.5), 0.4),
         math.pi * 16 - 4 / 3 * math.pi * (1 + 0.064)),
    ],
    ids=["disjoint-and-nested-spheres", "nested-difference", "tube", "cone-and-cylinder", "cylinder-minus-spheres"],
)
def test_volume_closed_forms_are_exact(solid, exact):
    """Nested and disjoint pieces: exact to rounding at the default tolerance (the old
    integrator stopped at its 1e-4)."""
    assert volume(solid) == pytest.approx(exact, rel=1e-9)


@pytest.mark.parametrize("name", list(PRIMITIVES))
def test_volume_of_primitives_is_their_closed_form(name):
    p = PRIMITIVES[name]
    assert volume(p) == pytest.approx(p.volume, rel=1e-12)
    assert closed_form_volume(p) == pytest.approx(p.volume, rel=1e-12)


def _frustum(r1, r2, h):
    return math.pi * h * (r1 * r1 + r1 * r2 + r2 * r2) / 3


@pytest.mark.parametrize(
    ("solid", "exact"),
    [
        # napkin ring: ball of radius 1 minus a coaxial cylinder of radius 0.45
        (Sphere((0.1, -0.2, 0.3), 1.0) - Cylinder((0.1, -0.2, 0.3), (0, 0, 3.0), 0.45), 4 / 3 * math.pi * (1 - 0.45**2) ** 1.5),
        # a cone along z (base radius 1.5 at z = 1.5, apex at z = -1.5) minus a cylinder of radius 0.5:
        # the frustum above z = -0.5 minus the cylinder over the same heights
        (Cone((0, 0, 0), (0, 0, 3), 1.5) - Cylinder((0, 0, 0), (0, 0, 5), 0.5), _frustum(1.5, 0.5, 2.0) - math.pi * 0.25 * 2.0),
        # two disjoint tilted cylinders joined by a third: the sum of the parts that do not overlap
        (Cylinder((0, 0, 0), (0.3, 0.2, 2), 0.5) | Cylinder((3, 0, 0), (-0.2, 0.4, 2), 0.4), math.pi * (0.25 * math.hypot(0.3, 0.2, 2) + 0.16 * math.hypot(0.2, 0.4, 2))),
    ],
    ids=["napkin-ring", "cone-minus-cylinder", "disjoint-tilted-cylinders"],
)
def test_volume_matches_closed_form_to_1e6(solid, exact):
    v = volume(solid, tol=1e-6)
    assert abs(v / exact - 1) < 1e-6


@pytest.mark.parametrize("depths", [(), (3.0, 7.0)], ids=["through", "blind"])
def test_plate_volume_is_exact(plate_1000, depths):
    tree, x, y, z0, z1 = plate_1000 if not depths else plate(32, depths=depths)
    inside = np.minimum(z1, 5.0) - np.maximum(z0, -5.0)
    exact = 100 * 100 * 10 - math.pi * R_HOLE**2 * inside.sum()
    assert volume(tree) == pytest.approx(exact, rel=1e-12)


def test_plate_10000_holes_of_random_depths_volume_is_exact():
    """10 000 blind holes of 10 000 different depths: one closed form per hole, not 20 000 pieces."""
    depths = tuple(np.random.default_rng(4).uniform(1.0, 12.0, 10_000))
    tree, x, y, z0, z1 = plate(100, depths=depths)
    exact = 100 * 100 * 10 - math.pi * R_HOLE**2 * (np.minimum(z1, 5.0) - np.maximum(z0, -5.0)).sum()
    assert volume(tree) == pytest.approx(exact, rel=1e-12)


def test_prism_minus_prisms_agrees_with_the_integrator():
    """Holes crossing the plate's outline (half circles, boxes over an edge): the closed form of
    prisms minus disjoint prisms and the sections integrated piece by piece agree."""
    from isocsg.csg.section import solid_program
    from isocsg.csg.volume import _integrate, _resolution

    holes = [Cylinder((50, y, 0), (0, 0, 20), 1.0) for y in (-20.0, 0.3, 20.0)]
    holes += [Box((-50, 0, 0), (4, 4, 6)), Box((0, 50, 4), (3, 3, 3)), Cylinder((10, 10, 4), (0, 0, 3), 2.0)]
    tree = Box((0, 0, 0), (100, 100, 10)) - union_all(holes)
    integrated = _integrate(solid_program(tree), np.array([0.0, 0.0, 1.0]), 1e-6, _resolution(1e-4), None)
    assert volume(tree) == pytest.approx(integrated, rel=1e-13)
    assert volume(tree) == pytest.approx(1e5 - 1.5 * math.pi * 10 - 2 * 4 * 6 - 1.5 * 3 * 2.5 - 4 * math.pi * 2.5, rel=1e-12)


def test_plate_10000_volume_is_exact(plate_10000):
    tree, x, *_ = plate_10000
    exact = 100 * 100 * 10 - math.pi * R_HOLE**2 * 10 * len(x)
    assert volume(tree) == pytest.approx(exact, rel=1e-12)


def test_plate_volume_matches_manifold3d(plate_1000):
    """manifold3d's holes are regular 32-gons: its volume is the plate minus those prisms."""
    tree, x, *_ = plate_1000
    ref = sum(t.volume() for t in plate_reference(plate_1000, 32))
    prisms = len(x) * 10 * 16 * R_HOLE**2 * math.sin(2 * math.pi / 32)
    assert ref == pytest.approx(100 * 100 * 10 - prisms, rel=1e-9)  # the reference is what it should be
    v = volume(tree, resolution=32)
    circles = len(x) * 10 * math.pi * R_HOLE**2
    assert v == pytest.approx(ref - (circles - prisms), rel=1e-12)


def machined_part():
    """A 56-primitive part: plate, boss, 8 fillet spheres, 40 holes, 4 pockets, a bore and a spherical cut."""
    body = Box((0, 0, 0), (100, 60, 10)) | Cylinder((0, 0, 10), (0, 0, 12), 12)
    body = body | union_all(Sphere((14 * math.cos(t), 14 * math.sin(t), 5), 4) for t in np.arange(8) * math.pi / 4)
    holes = [Cylinder((-45 + 10 * i, -25 + 50 / 3 * j, 0), (0, 0, 14), 2.0) for i in range(10) for j in range(4)]
    pockets = [Box((-30, 0, 4), (12, 8, 4)), Box((30, 0, 4), (12, 8, 4)), Box((0, 22, 4), (20, 6, 4)), Box((0, -22, 4), (20, 6, 4))]
    return body - union_all(holes) - union_all(pockets) - Cylinder((0, 0, 12), (0, 0, 30), 6) - Sphere((0, 0, 24), 8)


def test_machined_part_volume_matches_manifold3d():
    """The 56-primitive part at the default tolerance. manifold3d's volumes at 512 and 1024
    segments, extrapolated to the limit (error ~ 1 / n^2), give 57395.2607 (measured once:
    isocsg gives 57395.2649 at the default tol, 57395.2615 at 1e-6); at 128 segments manifold3d
    is 1.6e-6 above that limit, so the bar is 3e-6."""
    part = machined_part()
    assert compile_program(part).n_leaves == 56
    ref = _ref(part, 128).volume()
    assert abs(volume(part) / ref - 1) < 3e-6
    assert abs(volume(part, tol=1e-6) / ref - 1) < 3e-6


def test_volume_reports_progress():
    calls: list[tuple[int, int]] = []
    volume(Sphere((0, 0, 0), 1) - Cylinder((0, 0, 0), (0.2, 0, 3), 0.4), progress=lambda d, t: calls.append((d, t)))
    assert calls and calls[-1][0] == calls[-1][1]
    assert all(d <= t for d, t in calls)


def test_section_areas_are_exact_for_circles():
    a = section_areas(Sphere((0, 0, 0), 1) - Cylinder((0, 0, 0), (0, 0, 3), 0.5), [0.0, 0.5], resolution=32)
    np.testing.assert_allclose(a, [math.pi * 0.75, math.pi * (0.75 - 0.25)], rtol=1e-13)


# --------------------------------------------------------------------------- contains

A = Box((0, 0, 0), (2, 2, 2))
B = Box((1, 0, 0), (2, 2, 2))  # x in [0, 2]: cuts A at x = 0


def test_contains_cut_face_of_a_difference_is_inside():
    """Regression: a point on the cut face of A - B and one 1e-12 inside A - B were both outside."""
    t = A - B
    assert t.contains([[0.0, 0.3, 0.2], [-1e-12, 0.3, 0.2], [-0.5, 0, 0]]).tolist() == [True, True, True]
    assert t.contains([[1e-9, 0.3, 0.2], [0.5, 0, 0]]).tolist() == [False, False]


def test_contains_regularised_leftovers_are_outside():
    touching = A & Box((2, 0, 0), (2, 2, 2))  # the boxes share the face x = 1 only
    assert touching.contains([[1.0, 0.2, 0.3], [1.0, 0.0, 0.0]]).tolist() == [False, False]
    assert (A - A).contains([[1.0, 0.2, 0.3], [0, 0, 0], [1, 1, 1]]).tolist() == [False, False, False]
    pocket = A - Box((0, 0, 0.5), (1, 1, 1))  # flush with the top face z = 1
    assert pocket.contains([[0.0, 0.0, 1.0], [0.9, 0.9, 1.0], [0.0, 0.0, 0.0]]).tolist() == [False, True, True]
    stacked = A | Box((0, 0, 2), (2, 2, 2))
    assert stacked.contains([[0.2, 0.3, 1.0], [1.0, 1.0, 1.0], [1.0 + 1e-9, 0, 1.0]]).tolist() == [True, True, False]


def test_contains_tolerance():
    t = A - B
    p = [[-1.0 - 1e-6, 0, 0], [1e-6, 0.5, 0.5]]  # outside A's -x face; inside B by 1e-6
    assert t.contains(p).tolist() == [False, False]
    assert t.contains(p, tol=2e-6).tolist() == [True, True]
    assert t.contains(p, tol=0.5e-6).tolist() == [False, False]
    assert compile_program(t).default_tolerance() == pytest.approx(3e-12)  # extent 3 (x in [-1, 2])
    for bad in (-1e-9, float("nan"), "x"):
        with pytest.raises(InvalidParameterError, match=r"contains\(tol\)"):
            t.contains(p, tol=bad)
    with pytest.raises(InvalidParameterError, match=r"Sphere.contains\(tol\)"):
        Sphere((0, 0, 0), 1).contains(p, tol=-1.0)


def _surface_samples(prim, n, rng):
    """Points on the true surface of a primitive, away from its edges, with outward normals (closed forms)."""
    if isinstance(prim, Sphere):
        d = rng.normal(size=(n, 3))
        d /= np.linalg.norm(d, axis=1, keepdims=True)
        return np.asarray(prim.center) + prim.radius * d, d
    if isinstance(prim, Box):
        axis = rng.integers(0, 3, n)
        sign = rng.choice([-1.0, 1.0], n)
        t = rng.uniform(-0.9, 0.9, (n, 3)) * prim.half_size
        t[np.arange(n), axis] = sign * prim.half_size[axis]
        normal = np.zeros((n, 3))
        normal[np.arange(n), axis] = sign
        return np.asarray(prim.center) + t, normal
    a = prim.unit_axis
    e1 = np.cross(a, [0.3, 0.5, 0.7])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(a, e1)
    phi = rng.uniform(0, 2 * np.pi, n)
    er = np.cos(phi)[:, None] * e1 + np.sin(phi)[:, None] * e2
    h2, k = prim.height / 2, prim.slope
    side = rng.random(n) < 0.6
    s = np.where(side, rng.uniform(-0.9, 0.9, n) * h2, np.where(rng.random(n) < 0.5, h2, -h2))
    r_end = np.where(s > 0, prim.r1, prim.r2)
    rho = np.where(side, prim.r2 + k * (s + h2), rng.uniform(0.05, 0.9, n) * r_end)
    normal = np.where(side[:, None], (er - k * a) / math.hypot(1, k), np.sign(s)[:, None] * a)
    pts = prim.center_array + s[:, None] * a + rho[:, None] * er
    keep = ~(~side & (r_end == 0))
    return pts[keep], normal[keep]


@pytest.mark.parametrize("prim", list(PRIMITIVES.values()) + [Truncus((0, 1, 0), (0.5, 0.5, 1.5), 0.3, 0.9)], ids=str)
def test_primitive_contains_tolerance_is_a_distance(prim):
    """Points moved off the surface by d along the normal are inside exactly when d <= tol."""
    rng = np.random.default_rng(3)
    on, normal = _surface_samples(prim, 400, rng)
    tol = 1e-4 * float(np.max(np.ptp(prim.bounds, axis=0)))
    assert prim.contains(on).all()  # the surface itself, at the default tolerance
    d = rng.uniform(0.05, 0.95, size=len(on)) * tol
    assert prim.contains(on + d[:, None] * normal, tol=tol).all()
    assert not prim.contains(on + d[:, None] * normal).any()
    assert not prim.contains(on + (tol + d[:, None]) * normal, tol=tol).any()
    assert prim.contains(on - d[:, None] * normal, tol=0.0).all()


def test_contains_plate_10000_leaves(plate_10000):
    tree, x, y, z0, z1 = plate_10000
    rng = np.random.default_rng(5)
    pts = rng.uniform([-55, -55, -6], [55, 55, 6], size=(200_000, 3))
    got = tree.contains(pts)
    np.testing.assert_array_equal(got, plate_inside(pts, 100, x, y, z0, z1))
    # points exactly on the hole walls are inside the closed result, 1e-9 into a hole they are not
    k = np.arange(0, len(x), 97)
    ang = rng.uniform(0, 2 * np.pi, len(k))
    wall = np.column_stack([x[k] + R_HOLE * np.cos(ang), y[k] + R_HOLE * np.sin(ang), rng.uniform(-4, 4, len(k))])
    assert tree.contains(wall).all()
    inner = np.column_stack([x[k] + (R_HOLE - 1e-9) * np.cos(ang), y[k] + (R_HOLE - 1e-9) * np.sin(ang), wall[:, 2]])
    assert not tree.contains(inner).any()


# --------------------------------------------------------------------------- identities on large random trees

SETTINGS = settings(max_examples=5, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])


def random_tree(seed: int, n: int, *, round_leaves: bool = False):
    """A random tree of n leaves in a 20 m cube, nested by combining random groups of 2-4 operands
    with random operations: boxes, vertical cylinders and vertical hexagonal prisms (sections
    constant between breakpoints), plus vertical cones and spheres when ``round_leaves``."""
    rng = np.random.default_rng(seed)
    hexagon = np.column_stack([np.cos(np.arange(6) * np.pi / 3), np.sin(np.arange(6) * np.pi / 3)])
    items = []
    for _ in range(n):
        c = rng.uniform(-10, 10, 3)
        kind = rng.choice(5, p=[0.45, 0.35, 0.1, 0.05, 0.05] if round_leaves else [0.5, 0.4, 0.1, 0.0, 0.0])
        s = rng.uniform(0.5, 4.0, 3)
        if kind == 0:
            items.append(Box(c, s))
        elif kind == 1:
            items.append(Cylinder(c, (0, 0, s[2]), s[0] / 2))
        elif kind == 2:
            ring = c[:2] + s[0] / 2 * hexagon
            items.append(ConvexPolyhedron(np.vstack([np.column_stack([ring, np.full(6, c[2] + z)]) for z in (-s[2] / 2, s[2] / 2)])))
        elif kind == 3:
            items.append(Truncus(c, (0, 0, s[2]), s[0] / 2, s[1] / 4))
        else:
            items.append(Sphere(c, s[0] / 2))
    ops = [lambda xs: union_all(xs), lambda xs: xs[0] - union_all(xs[1:]), lambda xs: xs[0] & xs[1]]
    while len(items) > 1:
        k = int(min(rng.integers(2, 5), len(items)))
        idx = rng.choice(len(items), size=k, replace=False)
        group = [items[i] for i in idx]
        items = [it for i, it in enumerate(items) if i not in set(idx.tolist())]
        op = ops[int(rng.choice(3, p=[0.55, 0.35, 0.1]))]
        items.append(op(group))
    return items[0]


seeds = st.integers(0, 2**32 - 1)
#: (seed, number of leaves, with spheres and cones): up to 300 prismatic leaves or 120 with round ones
big_trees = st.one_of(
    st.builds(lambda s, n: random_tree(s, n), seeds, st.integers(20, 300)),
    st.builds(lambda s, n: random_tree(s, n, round_leaves=True), seeds, st.integers(20, 120)),
)


@SETTINGS
@given(big_trees, big_trees)
def test_inclusion_exclusion_on_large_trees(a, b):
    va, vb, vu, vi = (volume(s, tol=1e-6) for s in (a, b, a | b, a & b))
    assert abs((vu + vi) - (va + vb)) <= 1e-6 * max(va + vb, 1.0)


@SETTINGS
@given(big_trees, st.floats(-8, 8))
def test_a_minus_a_is_empty_on_large_trees(a, z):
    s = section(a - a, (0, 0, z), (0, 0, 1))
    assert s.is_empty and s.area == 0.0
    assert section_areas(a - a, [z, z + 0.37, z - 1.1]).tolist() == [0.0, 0.0, 0.0]
    assert volume(a - a) == 0.0


@SETTINGS
@given(big_trees, st.floats(-8, 8), st.floats(-0.3, 0.3))
def test_a_union_a_is_a_on_large_trees(a, z, tilt):
    normal = (tilt, 0.0, 1.0)
    s, s2 = section(a, (0, 0, z), normal), section(a | a, (0, 0, z), normal)
    assert s.geometry.symmetric_difference(s2.geometry).area <= 1e-9 * max(s.area, 1e-12)
    assert volume(a | a) == pytest.approx(volume(a), rel=1e-9, abs=1e-9)
