"""The reference's volume and area where the ring measure has kinks: a cone, cylinder or sphere
less a thin plate through or near its axis, and a rod through a sphere's poles, judged by closed
forms (tests/reference/slab_closed_forms.py); each error must also be within the error estimate."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from isocsg import Box, Cone, Cylinder, Difference, EllipticTruncus, Sphere, Truncus, volume
from isocsg.testing import reference
from isocsg.testing.kinks import signature_breaks

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference.slab_closed_forms import (  # noqa: E402
    SlabCut,
    half_space_cut_volume,
    napkin_ring,
    sphere_cap_volume,
)

TOL = 1e-9


def _rotation(angle: float, axis: tuple[float, float, float]) -> np.ndarray:
    a = np.asarray(axis, dtype=np.float64)
    a = a / np.linalg.norm(a)
    K = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K  # type: ignore[no-any-return]


def _slab_tree(c: SlabCut, rot: np.ndarray | None = None, shift: float = 0.0) -> Difference:
    """The solid (axis along x, ``shift`` its centre's offset along x) less the plate, turned by ``rot``."""
    R = np.eye(3) if rot is None else rot
    ex = R @ np.array([1.0, 0.0, 0.0])
    centre = R @ np.array([shift, 0.0, 0.0])
    if c.kind == "cone":
        solid = Cone(center=tuple(centre), axis=tuple(c.h * ex), radius=c.r)
    elif c.kind == "cylinder":
        solid = Cylinder(center=tuple(centre), axis=tuple(c.h * ex), radius=c.r)
    else:
        solid = Sphere(tuple(centre), c.r)
    size = 4 * max(c.r, c.h)
    y0 = size / 2 if c.half else 0.0
    plate = Box(center=tuple(R @ np.array([shift, y0, c.z0])), size=(size, size, 2 * c.w), orientation=R)
    return Difference(solid, plate)


def _check(tree: Difference, volume: float, area: float, tol: float = TOL, *, estimates: bool = True) -> None:
    ref = reference(tree, tol=tol)
    dv, da = abs(ref.volume - volume), abs(ref.area - area)
    assert dv <= tol * volume, (ref.volume, volume, dv / volume)
    assert da <= tol * area, (ref.area, area, da / area)
    if estimates:  # the estimates bound the true errors, up to the reference's coincidence band
        # (a surface within 1e-11 of the scene's size of another is on it: a ring entering a rod
        # is located to that band, not to rounding)
        assert dv <= ref.volume_error + 1e-11 * volume, (dv, ref.volume_error)
        assert da <= ref.area_error + 1e-11 * area, (da, ref.area_error)


def test_case_520_closed_form() -> None:
    # the demonstration's case 520: a cone less a 1e-4 plate up to its axis (8.2e-9 off in volume
    # before the break search, 1.1e-9 in area with a 5e-11 estimate before the grading)
    tree = Difference(Cone(center=(0, 0, -0.75), axis=(0.25, 0, 0), radius=0.5),
                      Box(center=(0, 0.5, -0.75), size=(1, 1, 1e-4)))
    c = SlabCut("cone", 0.5, 0.25, 0.0, 5e-5, True)
    assert abs(c.volume() - (math.pi * 0.5**2 * 0.25 / 3 - 6.25e-6)) < 1e-12  # the wedge, to first order
    _check(tree, c.volume(), c.area())


@pytest.mark.parametrize(("kind", "z0", "w", "half"), [
    ("cone", 0.13, 5e-4, True),       # off the axis: the faces meet the cone in hyperbolas
    ("cylinder", 0.5 - 5e-3, 5e-3, False),  # a face tangent to the cylinder
    ("sphere", 0.2, 5e-4, True),
])
def test_slab_closed_forms(kind: str, z0: float, w: float, half: bool) -> None:
    c = SlabCut(kind, 0.5, 0.25 if kind != "sphere" else 0.0, z0, w, half)
    _check(_slab_tree(c), c.volume(), c.area())


@pytest.mark.parametrize("a", [1e-3, 0.05])
def test_rod_through_sphere_poles(a: float) -> None:
    # the sphere's rings enter the rod at |z| = sqrt(1 - a^2): a jump of the ring measure
    tree = Difference(Sphere((0, 0, 0), 1.0), Cylinder(center=(0, 0, 0), axis=(0, 0, 3), radius=a))
    v, ar = napkin_ring(1.0, a)
    _check(tree, v, ar)


def test_signature_breaks_locates_changes() -> None:
    # a step signature: its changes located to rounding, however close to a break point
    cuts = np.array([2.5e-5, 0.3, 0.3000001, 0.77])

    def sig(s: np.ndarray) -> np.ndarray:
        return np.searchsorted(cuts, s).astype(np.int64)

    got = np.sort(signature_breaks(sig, np.array([0.0, 0.5, 1.0])))
    assert np.allclose(got, cuts, rtol=0, atol=1e-14)


#: Where the plate's lower face is, in radii from the axis (or the centre): on it, within rounding
#: or a hair of it, or anywhere across the solid.
_FACE = st.one_of(st.just(0.0), st.floats(-1e-9, 1e-9), st.floats(-1e-4, 1e-4), st.floats(-0.6, 0.6))


@settings(max_examples=2, deadline=None)
@given(kind=st.sampled_from(["cone", "cylinder", "sphere"]),
       log_w=st.floats(-5.0, -2.0), face=_FACE, half=st.booleans(),
       angle=st.floats(0.0, math.pi), tilt=st.floats(-1.0, 1.0), shift=st.floats(-0.3, 0.3))
def test_slab_property(kind: str, log_w: float, face: float, half: bool, angle: float, tilt: float,
                       shift: float) -> None:
    # a plate whose face passes through, or within a hair of, the axis (the cone's apex, the
    # sphere's centre), turned and moved: volume and area against the closed forms, each error
    # within the reference's estimate
    r, h = 0.5, 0.4
    w = 10.0**log_w
    c = SlabCut(kind, r, h if kind != "sphere" else 0.0, face * r + w, w, half)
    rot = _rotation(angle, (tilt, 1.0, 0.3))
    _check(_slab_tree(c, rot, shift), c.volume(), c.area())


@settings(max_examples=2, deadline=None)
@given(kind=st.sampled_from(["cone", "cylinder", "sphere"]), offset=_FACE, along=st.floats(-0.4, 0.4),
       solid_turn=st.tuples(st.floats(-2.0, 2.0), st.floats(-2.0, 2.0), st.floats(-2.0, 2.0)),
       box_turn=st.tuples(st.floats(-2.0, 2.0), st.floats(-2.0, 2.0), st.floats(-2.0, 2.0)))
def test_box_face_near_the_axis_against_sections(
    kind: str, offset: float, along: float, solid_turn: tuple[float, float, float],
    box_turn: tuple[float, float, float],
) -> None:
    # a box at any orientation, one face through (or near) a point of the solid's axis: the
    # volume against the closed-form sections across the axis (a disc less a circular segment,
    # integrated by scipy's quadrature) or a sphere's cap, within the reference's tolerance and
    # estimate. (isocsg.volume's plane sections were the judge once; they were 8e-5 off on some of
    # these trees until the sweep split at the face's events: test_plane_sections_of_a_cone_cut_through_its_axis.)
    r, h = 0.5, 0.4
    R = _rotation(float(np.linalg.norm(solid_turn)), solid_turn if any(solid_turn) else (0.0, 0.0, 1.0))
    Q = _rotation(float(np.linalg.norm(box_turn)), box_turn if any(box_turn) else (0.0, 0.0, 1.0))
    ex, n = R @ np.array([1.0, 0.0, 0.0]), Q @ np.array([0.0, 0.0, 1.0])
    centre = np.array([0.05, -0.02, 0.03])
    if kind == "sphere":
        solid = Sphere(tuple(centre), r)
    else:
        solid = (Cone if kind == "cone" else Cylinder)(center=tuple(centre), axis=tuple(h * ex), radius=r)
    on_face = centre + along * h * ex + offset * r * n  # the box's face plane passes through this point
    box = Box(center=tuple(on_face - 1.0 * n), size=(2.0, 2.0, 2.0), orientation=Q)
    tree = Difference(solid, box)
    ref = reference(tree, tol=TOL)
    kept = _kept_volume(kind, centre, ex, r, h, on_face, n)
    scale = max(ref.volume, 1e-3 * float(solid.volume))
    assert abs(ref.volume - kept) <= TOL * scale + ref.volume_error, (ref.volume, kept, ref.volume_error)


def _kept_volume(kind: str, centre: np.ndarray, ex: np.ndarray, r: float, h: float, on_face: np.ndarray,
                 n: np.ndarray) -> float:
    """The closed-form volume of the solid on the face's outer side (the box reaches past the solid)."""
    if kind == "sphere":
        return sphere_cap_volume(tuple(centre), r, tuple(on_face), tuple(n))
    return half_space_cut_volume(kind, tuple(centre - 0.5 * h * ex), tuple(ex), r, h, tuple(on_face), tuple(n))


# Two trees of the property above where isocsg.volume's plane sections once missed by 5e-8 and
# 8e-5 (at any tol): a cone cut by a plane through a point of its axis. The sweep had no
# breakpoint where the sweep plane is tangent to the conic of the cut (the second tree's kept
# part starts there: a sliver no quadrature node saw); isocsg.csg.face_events adds them.
_SECTIONS_MISSES = [
    (-0.3040439277735567, (0.0, 0.0, 0.0), (0.7240095627567293, 1.75, 0.25)),
    (0.0, (1.75, 2.0, 0.0), (0.5, 0.0, 0.0)),
]


def _turn(v: tuple[float, float, float]) -> np.ndarray:
    """The rotation by ``|v|`` radians about ``v`` (none for a tiny ``v``)."""
    angle = float(np.linalg.norm(v))
    return _rotation(angle, v) if angle > 1e-9 else np.eye(3)


def _cut_by_box(kind: str, r: float, r0: float, h: float, solid_turn: tuple[float, float, float],
                box_turn: tuple[float, float, float], along: float, offset: float) -> tuple[Difference, float]:
    """A cone, frustum (radius ``r0`` at the E2 end) or cylinder turned by ``solid_turn``, less a
    box turned by ``box_turn`` whose face passes ``offset`` from the point ``along`` (in heights)
    of the axis; and the closed-form volume kept."""
    R, Q = _turn(solid_turn), _turn(box_turn)
    ex, n = R @ np.array([1.0, 0.0, 0.0]), Q @ np.array([0.0, 0.0, 1.0])
    centre = np.array([0.05, -0.02, 0.03])
    r2 = {"cone": 0.0, "cylinder": r}.get(kind, r0)
    solid = Truncus(center=tuple(centre), axis=tuple(h * ex), r1=r, r2=r2)
    on_face = centre + along * h * ex + offset * n
    tree = Difference(solid, Box(center=tuple(on_face - n), size=(2.0, 2.0, 2.0), orientation=Q))
    kept = half_space_cut_volume("frustum", tuple(centre - 0.5 * h * ex), tuple(ex), r, h, tuple(on_face),
                                 tuple(n), r0=r2)
    return tree, kept


def test_frustum_cut_closed_form() -> None:
    # the frustum's closed form: whole beyond the plane, half by a plane along its axis, and the
    # cone's where its small radius is 0
    r, r0, h, ex = 0.5, 0.2, 0.4, (0.0, 0.6, 0.8)
    whole = math.pi * h * (r * r + r * r0 + r0 * r0) / 3
    far = half_space_cut_volume("frustum", (0, 0, 0), ex, r, h, (0, 0, -1), (0, 0.6, 0.8), r0=r0)
    half = half_space_cut_volume("frustum", (0, 0, 0), ex, r, h, (0, 0, 0), (1, 0, 0), r0=r0)
    assert abs(far - whole) <= 1e-12 * whole and abs(half - whole / 2) <= 1e-12 * whole
    turned = ((0.2, 0.1, 0.3), (0.6, 0.0, 0.8))
    assert half_space_cut_volume("frustum", (0, 0, 0), ex, r, h, *turned, r0=0.0) == pytest.approx(
        half_space_cut_volume("cone", (0, 0, 0), ex, r, h, *turned), rel=1e-12)


@pytest.mark.parametrize(("along", "solid_turn", "box_turn"), _SECTIONS_MISSES)
def test_plane_sections_of_a_cone_cut_through_its_axis(along: float, solid_turn: tuple[float, float, float],
                                                       box_turn: tuple[float, float, float]) -> None:
    tree, kept = _cut_by_box("cone", 0.5, 0.0, 0.4, solid_turn, box_turn, along, 0.0)
    assert abs(volume(tree, tol=1e-8, method="sections") - kept) <= 1e-8 * kept


#: A box face through a point of the axis, or within 1e-9 to 1e-3 (metres, radii 0.2 to 0.5) of it.
_OFFSET = st.one_of(st.just(0.0), st.builds(lambda e, s: s * 10.0**e, st.floats(-9.0, -3.0), st.sampled_from([-1.0, 1.0])))
_TURN = st.tuples(st.floats(-2.0, 2.0), st.floats(-2.0, 2.0), st.floats(-2.0, 2.0))


@settings(max_examples=4, deadline=None)
@given(kind=st.sampled_from(["cone", "frustum", "cylinder"]), r=st.floats(0.2, 0.5), ratio=st.floats(0.05, 0.95),
       h=st.floats(0.1, 0.4), along=st.floats(-0.5, 0.5), offset=_OFFSET, solid_turn=_TURN, box_turn=_TURN)
def test_plane_sections_of_a_truncus_cut_near_its_axis(kind: str, r: float, ratio: float, h: float, along: float,
                                                      offset: float, solid_turn: tuple[float, float, float],
                                                      box_turn: tuple[float, float, float]) -> None:
    # a cone, frustum or cylinder turned at random less a box turned at random, one face through
    # or near a point of the axis: isocsg.volume's plane sections (tangencies of the sweep plane
    # to the cut's conic, rim crossings) against the closed form, at tol 1e-8. The bar is tol of
    # the solid's volume where the part kept is smaller: the polygons' error where the face's trace
    # crosses the curved outline is about tol of the cut leaf's sections, not of the part kept
    # (docs/csg.md; a frustum cut through an end's centre keeping 6 %: 2.2e-8 of the part kept,
    # 1.3e-9 of the frustum)
    tree, kept = _cut_by_box(kind, r, ratio * r, h, solid_turn, box_turn, along, offset)
    r2 = {"cone": 0.0, "cylinder": r}.get(kind, ratio * r)
    scale = max(kept, math.pi * h * (r * r + r * r2 + r2 * r2) / 3)
    got = volume(tree, tol=1e-8, method="sections")
    assert abs(got - kept) <= 1e-8 * scale, (got, kept, (got - kept) / scale)


@settings(max_examples=3, deadline=None)
@given(matrix=st.lists(st.floats(-0.2, 0.2), min_size=9, max_size=9), r1=st.floats(0.3, 1.0),
       r2=st.sampled_from([0.0, 0.2, 0.6]), along=st.floats(-0.5, 0.5), offset=_OFFSET, box_turn=_TURN)
def test_plane_sections_of_an_elliptic_truncus_cut_near_its_axis(matrix: list[float], r1: float, r2: float,
                                                                 along: float, offset: float,
                                                                 box_turn: tuple[float, float, float]) -> None:
    # an elliptic cone or frustum (a sheared, unevenly scaled truncus) less a turned box, one face
    # through or near a point of its axis: the volume kept is |det M| times the canonical
    # frustum's on the face's preimage (the closed form above), at tol 1e-8 of the solid's volume
    M = np.diag([0.3, 0.25, 0.35]) + np.array(matrix).reshape(3, 3)
    c = np.array([0.05, -0.02, 0.03])
    Q = _turn(box_turn)
    n = Q @ np.array([0.0, 0.0, 1.0])
    on_face = c + M @ np.array([0.0, 0.0, along]) + offset * n
    solid = EllipticTruncus(tuple(c), M, r1, r2)
    tree = Difference(solid, Box(center=tuple(on_face - 2.0 * n), size=(4.0, 4.0, 4.0), orientation=Q))
    N, D = M.T @ n, float(n @ (on_face - c))
    kept = abs(float(np.linalg.det(M))) * half_space_cut_volume(
        "frustum", (0.0, 0.0, -0.5), (0.0, 0.0, 1.0), r1, 1.0, tuple(N * D / (N @ N)), tuple(N / np.linalg.norm(N)),
        r0=r2)
    got = volume(tree, tol=1e-8, method="sections")
    assert abs(got - kept) <= 1e-8 * max(kept, float(solid.volume)), (got, kept, (got - kept) / kept)
