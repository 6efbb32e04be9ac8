"""CSG geometry against independent references.

References: closed-form volumes, manifold3d Booleans of fine meshes built here
from manifold3d's own constructors (not through isocsg.csg.mesh), manifold3d's
``slice`` of those meshes transformed into the section plane, and point
membership (``Solid.contains``) of random points of the section plane.
"""

from __future__ import annotations

import functools
import math

import manifold3d as m3
import numpy as np
import pytest
import shapely
from shapely.geometry import Polygon

from isocsg import Box, Cone, ConvexPolyhedron, Cylinder, Difference, Intersection, Sphere, Truncus, Union
from isocsg.csg.mesh import to_manifold, to_trimesh
from isocsg.csg.section import section
from isocsg.csg.volume import volume

REF_SEGMENTS = 512

# --------------------------------------------------------------------------- scenes

R_BIG, R_HOLE = 1.0, 0.45
TETRA_ISH = ConvexPolyhedron([(1.2, 0, -1.1), (-1, 1.1, -1), (-1, -1.2, -1.1), (0.1, 0, 1.6), (0.55, 0.5, 0.8)])

SCENES = {
    "sphere-minus-cylinder": Sphere((0.1, -0.2, 0.3), R_BIG) - Cylinder((0.1, -0.2, 0.3), (0.4, 0.3, 3.0), R_HOLE),
    "sphere-and-box": Sphere((0, 0, 0), 1.0) & Box((0.3, 0.2, 0.1), (1.4, 1.5, 1.2)),
    "two-spheres": Sphere((0, 0, 0), 1.0) | Sphere((0.9, 0.3, 0.1), 0.6),
    "cone-minus-sphere": Cone((0, 0, 0), (0.2, 0.1, 2.0), 1.0) - Sphere((0.2, 0, 0.6), 0.5),
    "nested": Intersection(
        Difference(
            Box((0, 0, 0), (1.6, 1.6, 1.6)),
            Union(Cylinder((0, 0, 0), (2.4, 0, 0), 0.4), Cylinder((0, 0, 0), (0, 2.4, 0), 0.4)),
        ),
        Sphere((0, 0, 0), 1.05),
    ),
    "frustum-and-polyhedron": Truncus((0, 0, 0), (0.1, -0.2, 2.0), 1.0, 0.5) & TETRA_ISH,
}
IDS = list(SCENES)


def _lens(R: float, r: float, d: float) -> float:
    """Volume of the intersection of two balls of radii R, r at distance d (|R - r| < d < R + r)."""
    return math.pi * (R + r - d) ** 2 * (d * d + 2 * d * r - 3 * r * r + 2 * d * R + 6 * r * R - 3 * R * R) / (12 * d)


EXACT = {
    # Napkin ring: the volume of a ball minus a coaxial cylinder through it
    "sphere-minus-cylinder": 4 / 3 * math.pi * (R_BIG**2 - R_HOLE**2) ** 1.5,
    "two-spheres": 4 / 3 * math.pi * (1.0 + 0.6**3) - _lens(1.0, 0.6, math.dist((0, 0, 0), (0.9, 0.3, 0.1))),
}

# --------------------------------------------------------------------------- independent reference meshes


def _ref_leaf(p, segments=REF_SEGMENTS):
    M = m3.Manifold
    if isinstance(p, Sphere):
        return M.sphere(p.radius, segments).translate(p.center)
    if isinstance(p, Truncus):
        # manifold3d's cylinder: radius_low at z=0, radius_high at z=h; map z to the axis (E2 -> E1)
        a = np.asarray(p.axis, float) / p.height
        x = np.cross(a, [0.3, 0.5, 0.7])
        x /= np.linalg.norm(x)
        y = np.cross(a, x)
        mat = np.column_stack([x, y, a, np.asarray(p.center) - np.asarray(p.axis) / 2])
        return M.cylinder(p.height, p.r2, p.r1, segments).transform(mat.tolist())
    if isinstance(p, Box):
        return M.cube(p.size).translate(tuple(np.asarray(p.center) - np.asarray(p.size) / 2))
    if isinstance(p, ConvexPolyhedron):
        return M.hull_points([list(v) for v in p.vertices])
    raise AssertionError(type(p))


def _ref(solid, segments=REF_SEGMENTS):
    """manifold3d's Boolean of the tree, from manifold3d's own primitives at ``segments`` per circle."""
    if isinstance(solid, (Union, Intersection, Difference)):
        kids = [_ref(c, segments) for c in solid.children]
        if isinstance(solid, Union):
            return M_batch(kids, m3.OpType.Add)
        if isinstance(solid, Intersection):
            return M_batch(kids, m3.OpType.Intersect)
        return kids[0] - M_batch(kids[1:], m3.OpType.Add) if len(kids) > 1 else kids[0]
    return _ref_leaf(solid, segments)


def M_batch(kids, op):
    return kids[0] if len(kids) == 1 else m3.Manifold.batch_boolean(kids, op)


@functools.cache
def reference(name: str) -> m3.Manifold:
    return _ref(SCENES[name])


def reference_slice(name: str, frame: np.ndarray) -> Polygon:
    """manifold3d's section of a catalogue scene in the plane of ``frame``."""
    return manifold_slice(reference(name), frame)


def manifold_slice(mesh: m3.Manifold, frame: np.ndarray) -> Polygon:
    """``Manifold.slice`` in the plane of ``frame``: transform the plane to z = 0, then slice."""
    R, o = frame[:3, :3], frame[:3, 3]
    to_frame = np.column_stack([R.T, -R.T @ o])
    cs = mesh.transform(to_frame.tolist()).slice(0.0)
    g = Polygon()
    for ring in cs.to_polygons():
        if len(ring) >= 3:
            g = g.symmetric_difference(Polygon(ring))  # even-odd: holes cancel
    return g


# --------------------------------------------------------------------------- volumes


@pytest.mark.parametrize("name", IDS, ids=IDS)
def test_volume_matches_manifold3d(name):
    v = volume(SCENES[name], tol=1e-4, method="sections")  # independent of manifold3d
    ref = reference(name).volume()
    assert abs(v / ref - 1) < 5e-3
    # both are far better than the 0.5 % bar; the fine mesh is inscribed (a few 1e-5 small)
    assert abs(v / ref - 1) < 5e-4


@pytest.mark.parametrize("name", list(EXACT), ids=list(EXACT))
@pytest.mark.parametrize("axis", [(0, 0, 1), (0.3, -0.5, 0.8)], ids=["z", "tilted"])
def test_volume_matches_closed_form(name, axis):
    v = volume(SCENES[name], tol=1e-4, axis=axis)
    assert abs(v / EXACT[name] - 1) < 5e-4


PRIMS = {
    "sphere": Sphere((0.3, -1, 2), 0.7),
    "cylinder-tilted": Cylinder((0, 0, 0), (1, 2, 0.5), 0.4),
    "cone-tilted": Cone((1, 0, 0), (0.3, 0.1, -1.2), 0.8),
    "frustum-tilted": Truncus((0, 1, 0), (0.5, 0.5, 1.5), 0.3, 0.9),
    "disc": Truncus((0, 0, 0), (0.0, 0.02, 0.01), 1.0, 1.0),
    "box": Box((1, 2, 3), (0.5, 1.5, 2.5)),
    "polyhedron": TETRA_ISH,
}


@pytest.mark.parametrize("name", list(PRIMS), ids=list(PRIMS))
@pytest.mark.parametrize("axis", [(0, 0, 1), (-0.6, 0.2, 0.7)], ids=["z", "tilted"])
def test_primitive_volume_matches_exact(name, axis):
    p = PRIMS[name]
    assert abs(volume(p, tol=1e-4, axis=axis) / p.volume - 1) < 5e-4


# --------------------------------------------------------------------------- sections

PLANES = {
    "xy": ((0.0, 0.0, 0.1), (0.0, 0.0, 1.0)),
    "tilted": ((0.05, -0.1, 0.2), (0.3, -0.4, 0.87)),
    "steep": ((0.1, 0.2, -0.1), (0.9, 0.25, -0.2)),
    "off-centre": ((0.0, 0.0, 0.55), (-0.2, 0.6, 0.77)),
}


@pytest.mark.parametrize("plane", list(PLANES), ids=list(PLANES))
@pytest.mark.parametrize("name", IDS, ids=IDS)
def test_section_matches_manifold_slice(name, plane):
    o, n = PLANES[plane]
    s = section(SCENES[name], o, n, resolution=512)
    ref = reference_slice(name, s.frame)
    assert ref.area > 0.05  # every plane really cuts every scene
    assert abs(s.area / ref.area - 1) < 5e-3
    assert s.geometry.symmetric_difference(ref).area < 1e-2 * ref.area


@pytest.mark.parametrize("plane", list(PLANES), ids=list(PLANES))
@pytest.mark.parametrize("name", IDS, ids=IDS)
def test_section_frame_and_membership(name, plane):
    o, n = PLANES[plane]
    solid = SCENES[name]
    s = section(solid, o, n)
    F = s.frame
    np.testing.assert_allclose(F[:3, :3].T @ F[:3, :3], np.eye(3), atol=1e-12)
    assert np.linalg.det(F[:3, :3]) == pytest.approx(1.0)
    np.testing.assert_allclose(F[:3, 2], np.asarray(n) / np.linalg.norm(n), atol=1e-12)
    np.testing.assert_allclose(F[:3, 3], o)
    np.testing.assert_allclose(F[3], [0, 0, 0, 1])
    # random points of the plane: in the section polygon <=> inside the solid, away from the boundary
    rng = np.random.default_rng(7)
    xy = rng.uniform(-1.6, 1.6, size=(6000, 2))
    pts3 = s.to_3d(xy)
    np.testing.assert_allclose((pts3 - o) @ F[:3, 2], 0.0, atol=1e-12)
    inside_2d = shapely.contains_xy(s.geometry, xy[:, 0], xy[:, 1])
    inside_3d = solid.contains(pts3)
    dist = shapely.distance(s.geometry.boundary, shapely.points(xy))
    far = dist > 1e-3
    assert far.sum() > 5000
    np.testing.assert_array_equal(inside_2d[far], inside_3d[far])
    # ring vertices lie in the plane
    for ring in s.rings_3d():
        np.testing.assert_allclose((ring - o) @ F[:3, 2], 0.0, atol=1e-9)


@pytest.mark.parametrize(
    ("solid", "o", "n", "expected"),
    [
        (Cylinder((0, 0, 0), (0, 0, 2), 1.0), (0.5, 0, 0), (1, 0, 0), 2 * 2 * math.sqrt(0.75)),
        (Cone((0, 0, 0), (0, 0, 2), 1.0), (0, 0, 0), (0, 1, 0), 2.0),
        (Cone((0, 0, 0), (0, 0, 2), 1.0), (0, 0, -1), (0, 1, 1), 0.0),
        (Cylinder((0, 0, 0), (0, 0, 2), 1.0), (0, 0, 1.0001), (0, 0, 1), 0.0),
        (Sphere((0, 0, 0), 1.0), (0, 0, 0.6), (0, 0, 1), math.pi * 0.64),
        (Box((0, 0, 0), (2, 2, 2)), (0, 0, 0), (1, 1, 1), 3 * math.sqrt(3)),  # regular hexagon of side sqrt(2)
        (Truncus((0, 0, 0), (0, 0, 2), 1.0, 0.5), (0, 0, 0.5), (0, 0, -1), math.pi * 0.875**2),
    ],
    ids=["cylinder-parallel-to-axis", "cone-through-axis", "cone-touching-apex", "cylinder-missed",
         "sphere-cap", "box-hexagon", "frustum-normal-cut"],
)
def test_section_closed_forms(solid, o, n, expected):
    s = section(solid, o, n, resolution=1024)
    assert s.area == pytest.approx(expected, rel=1e-4, abs=1e-12)


# A cone and a coaxial cone that shares its base centre, met by a random tree:
# shapely nodes A's boundary inside A | B with 1e-16 perturbations, so
# A - (A | B) once left slivers of area 1e-17 instead of nothing.
_CONE_A = Cone((0.25423156048603834, 0.0, 0.0001), (-0.07265381656163997, -0.33691987242677474, 0.6661129202342149), 0.8125)
_CONE_B = Cone((0.25423156048603834, 0.0, 0.0001), (-0.18542695941879425, -0.8598863826907363, 1.7000523754153112),
               0.3717012975809501)
_SLIVER_PLANE = ((0.25423156048603834, 0.0, 0.0001), (-0.867512454867703, 0.25879071320683233, 0.4247934879530412))


@pytest.mark.parametrize("solid", [Difference(_CONE_A, _CONE_A, _CONE_B), _CONE_A - (_CONE_A | _CONE_B),
                                   (_CONE_A - _CONE_A) | (_CONE_A - _CONE_A - _CONE_B)],
                         ids=["a-a-b", "a-(a|b)", "(a-a)|(a-a-b)"])
def test_empty_results_have_no_rounding_slivers(solid):
    o, n = _SLIVER_PLANE
    assert section(_CONE_A, o, n).area > 0.5 and section(_CONE_B, o, n).area > 0.4  # both leaves are cut
    s = section(solid, o, n)
    assert s.is_empty and s.area == 0.0
    assert volume(solid) == 0.0


def test_sliver_filter_keeps_thin_but_real_parts():
    """Only parts thinner than SLIVER_WIDTH of the leaves' extent go: a 1e-6 wide slot stays."""
    from isocsg.csg.section import SLIVER_WIDTH

    assert SLIVER_WIDTH <= 1e-9
    # x in [-1, 1] without x >= 0.5 + 1e-6 and without x <= 0.5: a slot 1e-6 wide, 2 long
    slot = Box((0, 0, 0), (2, 2, 2)) - Box((1.5 + 1e-6, 0, 0), (2, 3, 3)) - Box((-0.5, 0, 0), (2, 3, 3))
    s = section(slot, (0, 0, 0), (0, 0, 1))
    assert s.area == pytest.approx(2e-6, rel=1e-6)


# --------------------------------------------------------------------------- meshes


@pytest.mark.parametrize("name", IDS, ids=IDS)
def test_to_manifold_matches_reference(name):
    m = to_manifold(SCENES[name], resolution=256)
    ref = reference(name)
    assert abs(m.volume() / ref.volume() - 1) < 5e-3
    diff = (m - ref).volume() + (ref - m).volume()
    assert diff < 5e-3 * ref.volume()


@pytest.mark.parametrize("name", list(PRIMS), ids=list(PRIMS))
def test_to_trimesh_is_closed_inscribed_and_converges(name):
    p = PRIMS[name]
    mesh = to_trimesh(p, resolution=256)
    assert mesh.is_watertight and mesh.is_winding_consistent
    assert mesh.volume > 0  # outward orientation
    assert abs(mesh.volume / p.volume - 1) < 1e-3
    # inscribed: every vertex is in the closed solid (up to float32 storage: shrink by 1e-5 about the middle)
    mid = p.bounds.mean(axis=0)
    assert p.contains(mid + (1 - 1e-5) * (mesh.vertices - mid)).all()


# --------------------------------------------------------------------------- clipped laminae


def _disc_lamina(center, normal, radius, m=720, intensity=0.5):
    from isocsg.laminae.model import Lamina

    n = np.asarray(normal, float) / np.linalg.norm(normal)
    a = np.cross(n, [0.31, 0.52, 0.79])
    a /= np.linalg.norm(a)
    b = np.cross(n, a)
    t = np.linspace(0, 2 * np.pi, m, endpoint=False)
    verts = np.asarray(center, float) + radius * (np.cos(t)[:, None] * a + np.sin(t)[:, None] * b)
    return Lamina(verts, n, intensity, float(n @ verts[0]), "contour", 0)


@pytest.mark.parametrize("z", [-0.6, 0.0, 0.35], ids=["below", "equator", "above"])
def test_clipped_sphere_laminae_are_annuli(z):
    from isocsg.csg.clip import clip_lamina_set

    R, r = 1.0, 0.4
    tree = Sphere((0, 0, 0), R) - Cylinder((0, 0, 0), (0, 0, 3), r)
    rho = math.sqrt(R * R - z * z)
    (c_sphere,) = clip_lamina_set(tree, 0, [_disc_lamina((0, 0, z), (0, 0, 1), rho, intensity=0.7)], resolution=1024)
    (c_hole,) = clip_lamina_set(tree, 1, [_disc_lamina((0, 0, z), (0, 0, 1), r)], resolution=1024)
    assert c_sphere.polarity == 1 and c_hole.polarity == -1
    assert c_sphere.intensity == 0.7
    assert c_sphere.area == pytest.approx(math.pi * (rho * rho - r * r), rel=1e-4)
    # the subtracted cylinder's lamina keeps what it carves out of the sphere: its whole disc here
    assert c_hole.area == pytest.approx(math.pi * r * r, rel=1e-4)
    for ring in c_sphere.rings_3d():
        np.testing.assert_allclose(ring[:, 2], z, atol=1e-12)


@pytest.mark.parametrize("name", ["sphere-and-box", "nested", "cone-minus-sphere"], ids=str)
def test_clipped_tilted_lamina_matches_manifold_slice(name):
    from isocsg.csg.clip import clip_lamina_set

    n = np.array([0.3, -0.4, 0.87])
    lam = _disc_lamina((0.05, -0.05, 0.15), n, 0.9)
    (c,) = clip_lamina_set(SCENES[name], 0, [lam], resolution=512)
    ref = reference_slice(name, c.frame)
    disc2d = Polygon((lam.vertices - c.frame[:3, 3]) @ c.frame[:3, :2])
    expected = ref.intersection(disc2d)
    assert expected.area > 0.05
    assert c.area == pytest.approx(expected.area, rel=5e-3)
    assert c.geometry.symmetric_difference(expected).area < 1e-2 * expected.area
