"""Primitives against independent references: closed-form volumes, brute-force ray sampling."""

import math

import numpy as np
import pytest

import isocsg as ic

PRIMS = {
    "sphere": ic.Sphere((0.2, -0.1, 0.3), 0.9),
    "cylinder": ic.Cylinder((0, 0, 0), (0.3, 0.4, 1.5), 0.6),
    "cone": ic.Cone((0.1, 0.2, 0), (1.0, 0.2, -0.3), 0.7),
    "flat_cone": ic.Cone((0, 0, 0), (0, 0, 0.3), 2.0),
    "frustum": ic.Truncus((0, 0, 0.2), (0, 0.5, 1.0), 0.9, 0.3),
    "disc": ic.Truncus((0, 0, 0), (0, 0, 0.05), 1.0, 1.0),
    "rod": ic.Truncus((0, 0, 0), (2.5, 0, 0), 0.08, 0.08),
    "box": ic.Box((0.1, 0, 0), (1.0, 2.0, 0.5)),
    "polyhedron": ic.ConvexPolyhedron(np.random.default_rng(3).normal(size=(25, 3))),
}


def _sampled_interval(prim, origin, direction, ts):
    inside = prim.contains(origin + ts[:, None] * direction)
    if not inside.any():
        return None
    return ts[inside].min(), ts[inside].max()


@pytest.mark.parametrize("name", PRIMS, ids=list(PRIMS))
def test_intersect_rays_matches_dense_sampling_of_contains(name):
    prim = PRIMS[name]
    rng = np.random.default_rng(11)
    origins = rng.normal(size=(150, 3)) * 2.5
    dirs = rng.normal(size=(150, 3))
    dirs[:30] = np.tile(np.asarray(getattr(prim, "unit_axis", (0, 0, 1.0))), (30, 1))
    dirs /= np.linalg.norm(dirs, axis=1, keepdims=True)
    hits = prim.intersect_rays(origins, dirs)
    ts = np.linspace(-9, 9, 18001)
    step = ts[1] - ts[0]
    for k in range(len(origins)):
        ref = _sampled_interval(prim, origins[k], dirs[k], ts)
        if ref is None:
            assert not hits.hit[k] or hits.t_out[k] - hits.t_in[k] < 2 * step
        else:
            assert hits.hit[k]
            assert hits.t_in[k] == pytest.approx(ref[0], abs=2 * step)
            assert hits.t_out[k] == pytest.approx(ref[1], abs=2 * step)


@pytest.mark.parametrize("name", PRIMS, ids=list(PRIMS))
def test_entry_normals_are_outward_unit_and_face_the_ray(name):
    prim = PRIMS[name]
    rng = np.random.default_rng(5)
    origins = rng.normal(size=(400, 3)) * 4
    dirs = -origins + rng.normal(size=(400, 3)) * 0.3
    dirs /= np.linalg.norm(dirs, axis=1, keepdims=True)
    h = prim.intersect_rays(origins, dirs)
    m = h.hit & (h.t_in > 0)
    assert m.sum() > 50
    assert np.allclose(np.linalg.norm(h.n_in[m], axis=1), 1.0)
    assert np.all(np.einsum("ij,ij->i", h.n_in[m], dirs[m]) <= 1e-9)
    # a point slightly outside along the normal is outside, slightly inside is inside
    p = origins[m] + h.t_in[m, None] * dirs[m]
    assert not prim.contains(p + 1e-6 * h.n_in[m]).any()
    assert prim.contains(p - 1e-6 * h.n_in[m]).mean() > 0.99


def _closed_form_volume(prim):
    if isinstance(prim, ic.Sphere):
        return 4 / 3 * math.pi * prim.radius**3
    if isinstance(prim, ic.Truncus):
        h = math.dist(prim.axis, (0, 0, 0))
        return math.pi * h / 3 * (prim.r1**2 + prim.r1 * prim.r2 + prim.r2**2)
    if isinstance(prim, ic.Box):
        return float(np.prod(prim.size))
    return None


@pytest.mark.parametrize("name", [n for n in PRIMS if n != "polyhedron"], ids=[n for n in PRIMS if n != "polyhedron"])
def test_monte_carlo_volume_of_contains_matches_closed_form(name):
    prim = PRIMS[name]
    lo, hi = prim.bounds
    rng = np.random.default_rng(2)
    n = 200_000
    pts = lo + rng.random((n, 3)) * (hi - lo)
    frac = prim.contains(pts).mean()
    box_vol = float(np.prod(hi - lo))
    sigma = box_vol * math.sqrt(frac * (1 - frac) / n)
    assert abs(frac * box_vol - _closed_form_volume(prim)) < 4.5 * sigma + 1e-12


@pytest.mark.parametrize("name", PRIMS, ids=list(PRIMS))
def test_bounds_are_tight(name):
    prim = PRIMS[name]
    mesh = prim.to_trimesh(256)
    lo, hi = prim.bounds
    assert np.all(mesh.vertices >= lo - 1e-9) and np.all(mesh.vertices <= hi + 1e-9)
    # the inscribed mesh reaches the bounds up to the tessellation sagitta
    size = float(np.max(hi - lo))
    assert np.allclose(mesh.bounds, prim.bounds, atol=2e-3 * size)


@pytest.mark.parametrize("name", [n for n in PRIMS if n != "polyhedron"], ids=[n for n in PRIMS if n != "polyhedron"])
def test_tessellation_volume_converges(name):
    prim = PRIMS[name]
    exact = _closed_form_volume(prim)
    errs = [abs(prim.to_trimesh(res).volume - exact) / exact for res in (16, 64, 256)]
    assert errs[2] < errs[0] or errs[0] < 1e-12
    assert errs[2] < 2e-3
    assert prim.to_trimesh(64).is_watertight


def test_polyhedron_volume_matches_scipy_hull():
    from scipy.spatial import ConvexHull

    pts = np.random.default_rng(3).normal(size=(25, 3))
    assert ic.ConvexPolyhedron(pts).volume == pytest.approx(ConvexHull(pts).volume, rel=1e-12)


def test_polyhedron_faces_are_ccw_from_outside_and_merged():
    cube = ic.Box((0, 0, 0), (2, 2, 2)).to_polyhedron()
    assert len(cube.faces) == 6
    for poly, n in zip(cube.face_polygons(), cube.face_normals):
        assert len(poly) == 4
        area_vec = np.cross(poly[1] - poly[0], poly[2] - poly[0])
        assert area_vec @ n > 0


def test_values_are_hashable_and_compare_exactly():
    a = ic.Sphere((0, 0, 0), 1)
    assert a == ic.Sphere([0.0, 0.0, 0.0], 1.0) and hash(a) == hash(ic.Sphere((0, 0, 0), 1.0))
    assert a != ic.Sphere((0, 0, 0), 1.0 + 1e-12)
    assert ic.Cylinder((0, 0, 0), (0, 0, 1), 1) != ic.Truncus((0, 0, 0), (0, 0, 1), 1, 1)
    with pytest.raises(AttributeError):
        a.radius = 2  # type: ignore[misc]


def test_cone_and_cylinder_follow_the_end_convention():
    k = ic.Cone((0, 0, 0), (0, 0, 2), 1.0)
    # base (E1) at center + axis/2, apex (E2) at center - axis/2
    assert k.contains([[0.9, 0, 0.95], [0, 0, -0.99]]).tolist() == [True, True]
    assert k.contains([[0.5, 0, -0.9]]).tolist() == [False]
    assert k.volume == pytest.approx(math.pi * 2 / 3)


def test_kind_interface_members():
    """The members the shared machinery calls instead of testing for a concrete kind."""
    from isocsg import Box, ConvexPolyhedron, Cylinder, Ellipsoid, Sphere, Truncus
    from isocsg.kinds import LeafForm

    t = Truncus((0, 0, 0), (0, 0, 2), 1.0, 0.5)
    pts = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, -1.0], [0.75, 0.0, 0.0]])
    assert t.part_index(pts, np.zeros((3, 3))).tolist() == [1, 2, 0]
    b = Box((0, 0, 0), (2, 2, 2))
    assert b.part_index(np.zeros((2, 3)), np.array([[0.0, 0, 1], [-1.0, 0, 0]])).tolist() == [4, 1]
    assert Sphere((0, 0, 0), 1).part_index(np.zeros((2, 3)), np.zeros((2, 3))).tolist() == [0, 0]
    assert b.hull_points().shape == (8, 3) and Sphere((0, 0, 0), 1).hull_points() is None
    forms = [p.leaf_row().form for p in (Sphere((0, 0, 0), 1), Cylinder((0, 0, 0), (0, 0, 1), 1), b, b.rotate((0, 0, 30)),
                                         ConvexPolyhedron([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]), Ellipsoid((0, 0, 0), (1, 2, 3)))]
    assert forms == [LeafForm.BALL, LeafForm.FRUSTUM, LeafForm.AXIS_BOX, LeafForm.HULL, LeafForm.HULL, LeafForm.GENERIC]
    assert t.leaf_row().axis_vector.tolist() == [0.0, 0.0, 2.0]
    # ray intervals: (n, 1, 2) for a convex kind, NaN where a ray misses
    iv = Sphere((0, 0, 0), 1).ray_intervals([[0, 0, -5], [3, 0, -5]], [[0, 0, 1], [0, 0, 1]])
    assert iv.shape == (2, 1, 2) and iv[0, 0].tolist() == [4.0, 6.0] and np.isnan(iv[1]).all()
    # the extents of every kind bound its tessellation and are reached by it
    for p in (t, b.rotate((10, 20, 30)), Ellipsoid((0, 0, 0), (1, 2, 3)), Sphere((1, 2, 3), 2)):
        n = np.array([0.36, -0.48, 0.8])
        lo, hi = p.extent(n)
        proj = p.to_polyhedron(256).hull_vertices @ n
        assert lo <= proj.min() + 1e-12 and proj.max() <= hi + 1e-12 and hi - proj.max() < 1e-3 * (hi - lo)


def test_clipped_to_box_matches_the_tiles_cut():
    """``clipped_to_box`` is the cut the renderer's clip_leaves makes of trunci and boxes."""
    from isocsg import Box, Cone, ConvexPolyhedron, Cylinder
    from isocsg.csg.program import compile_program
    from isocsg.rendering.tiles import clip_leaves, leaf_geometry

    tree = Box((0, 0, 0), (2, 2, 0.4)) - Cylinder((0.1, 0, 0), (0.2, 0.1, 3), 0.2) - Cone((0.5, 0.3, 0), (0, 0.3, -4), 0.3) \
        - Box((0.9, 0.9, 0), (0.1, 0.1, 5)) - ConvexPolyhedron([(0, 0, -3), (0.1, 0, 3), (0, 0.1, 3), (0.1, 0.1, 0)])
    prog = compile_program(tree)
    g = leaf_geometry(prog.leaves)
    lo, hi = prog.bounds(g.lo, g.hi)
    want = clip_leaves(prog.leaves, g, lo, hi)
    margin = 1e-3 * float(np.linalg.norm(hi - lo))
    got = [p.clipped_to_box(lo - margin, hi + margin) for p in prog.leaves]
    assert got == want
    assert got[1] != prog.leaves[1] and got[-1] is prog.leaves[-1]


def test_an_axis_aligned_box_gives_its_hull_faces_without_a_hull():
    # Box.local_faces builds an axis-aligned box's faces directly (no qhull at start-up): the
    # same polygons, in the same order and from the same corner, as the convex hull's.
    rng = np.random.default_rng(7)
    for i in range(200):
        size = 10.0 ** rng.uniform(-3, 3, 3) if i % 2 else np.full(3, 10.0 ** rng.uniform(-3, 3))
        box = ic.Box(tuple(rng.uniform(-1e3, 1e3, 3)), tuple(size))
        hull = ic.Box((0.0, 0.0, 0.0), tuple(size)).to_polyhedron().face_polygons()
        centre, faces = box.local_faces()
        np.testing.assert_array_equal(centre, box.center_array)
        assert len(faces) == len(hull) == 6
        for got, want in zip(faces, hull):
            assert np.array_equal(got, want) and np.array_equal(np.signbit(got), np.signbit(want))
