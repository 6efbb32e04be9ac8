"""Band meshes are closed surfaces: after welding, each is a 2-manifold that bounds the primitive.

The clipped CSG surface (``isocsg/csg/surface.py``) welds each leaf's band mesh
(:func:`~isocsg.csg.surface.close_mesh`: equal and nearly equal vertices merged,
T-junctions split) and hands it to manifold3d. Here every primitive kind, under
random lights and materials, at scales from 1e-3 to 1e3 and far from the
origin, must weld into a mesh whose every edge is used by exactly two
triangles, that manifold3d accepts (``status() == NoError``) and whose volume
lies between the primitive's exact volume (computed here from its parameters,
or by scipy's hull for a polyhedron) and the volume of the inscribed mesh the
band mesh's vertex count allows.

Found by the random CSG view search: the cut points of two faces along their
common edge came out a few ulps apart (262 open edges on a polyhedron), and a
cone's apex was two vertices 1.6e-16 apart.
"""

from __future__ import annotations

import math

import manifold3d
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from scipy.spatial import ConvexHull

from isocsg import Box, ConvexPolyhedron, DirectionalLight, Material, PointLight, Sphere, Truncus, build_laminae
from isocsg.csg.surface import close_mesh
from isocsg.laminae.split import mesh_edges

#: Contours of the property test (closure does not depend on N; small keeps it fast).
CONTOURS = 16
#: Relative volume a curved primitive's inscribed band mesh may lack: 128 generators or
#: longitudes leave (m / 2 pi) sin(2 pi / m) = 1 - 4e-4 of a circle's area; a sphere's
#: latitudes lose as much again.
CURVED_DEFICIT = 2e-3


def exact_volume(prim) -> float:
    if isinstance(prim, Sphere):
        return 4.0 / 3.0 * math.pi * prim.radius**3
    if isinstance(prim, Truncus):
        h = float(np.linalg.norm(prim.axis))
        return math.pi * h * (prim.r1**2 + prim.r1 * prim.r2 + prim.r2**2) / 3.0
    if isinstance(prim, Box):
        return float(np.prod(prim.size))
    return float(ConvexHull(np.asarray(prim.vertices, dtype=float)).volume)


def check_closed(bands, prim) -> None:
    v, t, _ = close_mesh(bands.vertices, bands.triangles)
    _, tri_edge = mesh_edges(t)
    uses = np.bincount(tri_edge.ravel())
    assert np.all(uses == 2), f"{int(np.sum(uses == 1))} open edges, {int(np.sum(uses > 2))} used more than twice"
    # manifold3d in a unit frame (as the CSG surface does), the volume scaled back
    centre = 0.5 * (v.min(axis=0) + v.max(axis=0))
    half = 0.5 * float(np.ptp(v, axis=0).max())
    mesh = manifold3d.Mesh64(vert_properties=np.ascontiguousarray((v - centre) / half),
                             tri_verts=np.ascontiguousarray(t, dtype=np.uint64))
    solid = manifold3d.Manifold(mesh)
    assert solid.status() == manifold3d.Error.NoError, solid.status()
    volume = solid.volume() * half**3
    exact = exact_volume(prim)
    curved = isinstance(prim, (Sphere, Truncus))
    low = exact * (1.0 - (CURVED_DEFICIT if curved else 1e-9))
    assert low <= volume <= exact * (1.0 + 1e-9), (volume, exact, volume / exact - 1.0)


@st.composite
def primitives(draw):
    kind = draw(st.sampled_from(["sphere", "cylinder", "cone", "frustum", "disc", "box", "polyhedron"]))
    axis = np.array([draw(st.floats(-1, 1)) for _ in range(3)])
    if np.linalg.norm(axis) < 0.1:
        axis = np.array([0.0, 0.0, 1.0])
    axis = axis / np.linalg.norm(axis) * draw(st.floats(0.3, 2.0))
    r = draw(st.floats(0.3, 1.2))
    if kind == "sphere":
        return lambda o, s: Sphere(o, s * r)
    if kind == "cylinder":
        return lambda o, s: Truncus(o, tuple(s * axis), s * r, s * r)
    if kind == "cone":
        top = draw(st.booleans())
        return lambda o, s: Truncus(o, tuple(s * axis), s * r if top else 0.0, 0.0 if top else s * r)
    if kind == "frustum":
        k = draw(st.floats(0.1, 0.9))
        return lambda o, s: Truncus(o, tuple(s * axis), s * r, s * r * k)
    if kind == "disc":
        return lambda o, s: Truncus(o, tuple(s * 0.05 * axis / np.linalg.norm(axis)), s * r, s * r)
    if kind == "box":
        size = np.array([draw(st.floats(0.2, 2.0)) for _ in range(3)])
        return lambda o, s: Box(o, tuple(s * size))
    n = draw(st.integers(5, 12))
    pts = np.array([[draw(st.floats(-1, 1)) for _ in range(3)] for _ in range(n)])
    # random points about an octahedron (so that the hull always has a volume)
    pts = np.vstack([0.6 * np.eye(3), -0.6 * np.eye(3), pts / np.maximum(np.linalg.norm(pts, axis=1, keepdims=True), 0.3)])
    return lambda o, s: ConvexPolyhedron(np.asarray(o) + s * pts)


@st.composite
def light_sets(draw):
    out = []
    for k in range(draw(st.integers(1, 2))):
        d = np.array([draw(st.floats(-1, 1)) for _ in range(3)])
        d = d / np.linalg.norm(d) if np.linalg.norm(d) > 0.1 else np.array([0.3, -0.4, 0.87])
        intensity = 1.0 if k == 0 else 0.5
        if draw(st.booleans()):
            out.append(("directional", d, intensity))
        else:
            out.append(("point", d * draw(st.floats(1.6, 20.0)), intensity))
    return out


def placed_lights(lights, origin, scale):
    return [DirectionalLight(tuple(d), i) if kind == "directional" else PointLight(tuple(np.asarray(origin) + scale * d), i)
            for kind, d, i in lights]


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    make=primitives(),
    lights=light_sets(),
    specular=st.booleans(),
    placement=st.sampled_from([((0.0, 0.0, 0.0), 1.0), ((0.0, 0.0, 0.0), 1e-3), ((0.0, 0.0, 0.0), 1e3),
                               ((1e4, -2e4, 5e3), 1.0), ((3.0, 1.0, -2.0), 50.0)]),
)
def test_band_meshes_weld_into_closed_manifolds(make, lights, specular, placement):
    origin, scale = placement
    prim = make(origin, scale)
    mat = Material(0.1, 0.6, 0.3, 20.0) if specular else Material()
    eye = tuple(np.asarray(origin) + scale * np.array([4.0, -5.0, 3.0]))
    ls = build_laminae(prim, placed_lights(lights, origin, scale), mat, CONTOURS, eye=eye)
    check_closed(ls.bands, prim)



def test_the_found_cone_welds_into_a_closed_manifold():
    # The cone of a random CSG view (two lights, Phong): 12 open edges, 9 edges used four times.
    cone = Truncus((0.140824489531859, 0.0, -0.27894955952863615), (1.237962246836256, 0.0, -1.3649590137402514),
                   0.8181560425149027, 0.0)
    lights = [PointLight((6.73600082401685, 7.092117516495353, -4.476557540157528)),
              DirectionalLight((-0.17261483859126808, 0.5052604650370058, -0.8455270427187407), 0.6450224105532074)]
    ls = build_laminae(cone, lights, Material(0.1, 0.6, 0.35224982768333457, 5.0), 64,
                       eye=(0.8220449381467546, -7.230369660421692, -3.0640655642770125))
    check_closed(ls.bands, cone)


@pytest.mark.parametrize("scale", [1e-3, 1.0, 1e3], ids=str)
def test_the_found_polyhedra_weld_into_closed_manifolds(scale):
    # Two of the random CSG view's polyhedra (a point light and a directional one): 262 open edges.
    polys = [
        ConvexPolyhedron(np.array([(1.202467858223185, -0.011210419032952335, -0.05681952271636919),
                                   (-0.5038903474325956, -0.0544325769890075, -0.17186516858930617),
                                   (0.408694296781272, 0.9434300926714598, 0.14707774841635446),
                                   (0.408694296781272, -0.7269384368403192, 0.0),
                                   (0.6581454913591093, -0.0544325764784659, 1.0671854013486162),
                                   (0.4429847400424366, -0.0544325769890075, -1.104579875616399)]) * scale),
        ConvexPolyhedron(np.array([(1.3165333460045398, 0.04023536153427824, 0.001),
                                   (-0.6819636216116844, -0.28725527215499986, 0.001),
                                   (0.6630651555291278, 1.2655147559832761, -0.21448598246928457),
                                   (0.46803637838834536, -1.0036615561060985, 0.25075367925288873),
                                   (0.6463957143554675, 0.2189366417334065, 0.866360546064901),
                                   (0.6042205389918271, 0.25083906047923137, -0.9989999999999999)]) * scale),
    ]
    lights = [PointLight(tuple(scale * np.array([9.491501416623215, 14.781812496718099, -13.258902566233143]))),
              DirectionalLight((0.034247641998224054, 0.8939388027943891, -0.4468786366297855), 0.5993698496935583)]
    for poly in polys:
        check_closed(build_laminae(poly, lights, Material(), 64).bands, poly)
