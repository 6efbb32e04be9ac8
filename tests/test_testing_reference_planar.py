"""isocsg.testing.reference on trees of planar leaves, judged by independent values: manifold3d's
Boolean (exact up to rounding when every leaf is planar) and isocsg.volume's plane sections.

The trees are manifold's fuzz domain (turned, scaled and moved unit cubes). Case 69 of the engine
findings (docs/testing_engines.md) once lost a sixteenth of random rings to rounding: 0.14 off in
volume at tol=1e-3, with an error estimate that did not cover it.
"""

from __future__ import annotations

import math

from hypothesis import HealthCheck, given, settings

from isocsg import Box, ConvexPolyhedron, Difference, Union, volume
from isocsg.csg.mesh import to_manifold
from isocsg.csg.section import solid_program
from isocsg.testing import closed_form_area, reference
from isocsg.testing.strategies import cube_fuzz, manifold_fuzz

#: manifold3d's exact Boolean in double precision: its figures are right to about this, relative
ROUNDING = 1e-11


def _case_69():
    """The reproducer of fuzz case 69 (docs/testing_engines_findings/fuzz.txt)."""
    p0 = Box(center=(27.493672963719668, 75.18601431564032, 24.65711991502435), size=(4.049099185185814, 8.892546665007643, 3.917866222306656), orientation=((-0.9851816355629731, -0.11914307543100876, -0.12337776350017869), (0.09739033186526096, -0.9807247131823245, 0.1693935069966423), (-0.1411816851034135, 0.15486757094462392, 0.9777953606256641)))  # noqa: E501
    p1 = ConvexPolyhedron(vertices=((0.0, 0.0, 0.0), (0.6258092221022711, 1.0841779925832993, 4.587695239040397), (-0.15699769349826728, -7.762099994799653, 0.6733829682869099), (0.46881152860400377, -6.677922002216354, 5.261078207327307), (-4.553748499714224, 0.4166063150313353, 0.607258485201289), (-3.9279392776119533, 1.5007843076146345, 5.194953724241686), (-4.710746193212492, -7.345493679768318, 1.280641453488199), (-4.084936971110221, -6.261315687185019, 5.8683366925285965)))  # noqa: E501
    n2 = Difference(p0, p1)
    p3 = Box(center=(0.5, 0.5, 0.5), size=(1.0, 1.0, 1.0))
    n4 = Union(n2, p3)
    p5 = Box(center=(-6.334570376119786, -9.451731914068551, 12.39488881416477), size=(2.662512931562613, 9.386055361745868, 9.21978108140218), orientation=((-0.9796574513612795, 0.12293957422771971, 0.15861002200690025), (-0.11213537174952452, -0.9908288461974774, 0.07539135192826378), (0.1664239658069664, 0.05607190590378015, 0.9844587370598117)))  # noqa: E501
    n6 = Union(n4, p5)
    p7 = ConvexPolyhedron(vertices=((20.419343758029473, -2.0538350037919404, -1.9483482469844169), (20.792712715046605, -1.8418529834060124, -2.3515770087061862), (20.903421751541917, -5.731894790323211, -1.9663855028010877), (21.27679070855905, -5.519912769937283, -2.369614264522857), (24.182601876002888, -1.6017479445760339, -1.9060220137540083), (24.55597083302002, -1.389765924190106, -2.3092507754757774), (24.666679869515335, -5.279807731107304, -1.924059269570679), (25.040048826532466, -5.067825710721376, -2.3272880312924484)))  # noqa: E501
    n8 = Difference(n6, p7)
    p9 = Box(center=(0.5, 0.5, 0.5), size=(1.0, 1.0, 1.0))
    n10 = Difference(n8, p9)
    p11 = ConvexPolyhedron(vertices=((0.0, 0.0, 0.0), (-0.9023738397099211, 0.8704763707265313, 9.82346380881342), (-0.9771460376141559, 7.030517797780679, -1.2982971229922047), (-1.879519877324077, 7.900994168507211, 8.525166685821215), (4.18828543202707, 1.1855347859529881, -0.6709807617724453), (3.2859115923171487, 2.0560111566795194, 9.152483047040974), (3.211139394412914, 8.216052583733667, -1.96927788476465), (2.308765554702993, 9.0865289544602, 7.85418592404877)))  # noqa: E501
    n12 = Union(n10, p11)
    p13 = Box(center=(0.5389541078609721, 0.49226986767421615, 0.4660459709082284), size=(1.0, 0.9999999999999999, 1.0), orientation=((0.9906640935062901, 0.12958392883640335, -0.04233980662074922), (-0.12352052578215868, 0.984636626430199, 0.1234236347003921), (0.05768304385050736, -0.11704152801240558, 0.9914504259783551)))  # noqa: E501
    tree = Difference(n12, p13)
    return tree


def _manifold_figures(tree):
    m = to_manifold(tree)
    return m.volume(), m.surface_area()


def _judge(tree, tol: float) -> None:
    ref = reference(tree, tol=tol)
    v, a = _manifold_figures(tree)
    scale = max(1.0, max(abs(float(x)) for x in ref.bounds.ravel()))
    assert abs(ref.volume - v) <= ref.volume_error + ROUNDING * scale**3, (ref.volume, ref.volume_error, v)
    assert abs(ref.area - a) <= ref.area_error + ROUNDING * scale**2, (ref.area, ref.area_error, a)
    # tol is relative to the whole figure (docs/testing_engines.md: the sum of the boundary
    # pieces' absolute contributions), at most the leaves' areas (times scale / 3 for the flux of
    # x / 3): an empty result (cube - cube - turned cube) still has an estimate of ~1e-9
    whole_area = sum(float(closed_form_area(leaf)) for leaf in solid_program(tree).leaves)
    assert ref.volume_error <= tol * max(abs(v), whole_area * scale / 3) * 10
    assert ref.area_error <= tol * max(a, whole_area) * 10


def test_fuzz_case_69_volume_against_sections_and_manifold3d():
    tree = _case_69()
    v_mf, _ = _manifold_figures(tree)
    v_sec = float(volume(tree, method="sections", tol=1e-7))
    for tol in (1e-3, 1e-9):
        ref = reference(tree, tol=tol)
        assert math.isclose(ref.volume, v_sec, rel_tol=1e-6)
        assert math.isclose(ref.volume, v_mf, rel_tol=1e-6)
        assert abs(ref.volume - v_mf) <= ref.volume_error + ROUNDING * abs(v_mf)


def test_fuzz_case_69_area_against_manifold3d():
    tree = _case_69()
    _, a_mf = _manifold_figures(tree)
    for tol in (1e-3, 1e-9):
        ref = reference(tree, tol=tol)
        assert math.isclose(ref.area, a_mf, rel_tol=1e-6)
        assert abs(ref.area - a_mf) <= ref.area_error + ROUNDING * a_mf


def _planar(tree) -> bool:
    return all(isinstance(p, (Box, ConvexPolyhedron)) for p in solid_program(tree).leaves)


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(manifold_fuzz(max_ops=5, max_transforms=3))
def test_manifold_fuzz_trees_against_manifold3d(tree):
    assert _planar(tree)
    _judge(tree, 1e-9)


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(cube_fuzz(max_cubes=4))
def test_overlapping_turned_cubes_against_manifold3d(tree):
    assert _planar(tree)
    _judge(tree, 1e-9)
