"""isocsg.testing.reference on the trees that made it slow (thin rods and discs whose end faces lie
inside another leaf, coincident copies, empty results), against closed forms."""

from __future__ import annotations

import math

import pytest

from isocsg import Box, Cone, Cylinder, Intersection, Sphere, Union
from isocsg.testing import reference

R_ROD = 1e-3


def close(value: float, exact: float, rel: float = 1e-9) -> bool:
    return abs(value - exact) <= rel * abs(exact)


def test_rod_with_its_copy_ending_inside_a_box():
    # a rod of radius 1e-3 along y, y in [0.5, 1.5], twice, its lower half in the box [-1, 1]^3:
    # the box loses a disc of radius r where the rod leaves it, the rod keeps half its side and its top
    rod = lambda: Cylinder((0.0, 1.0, 0.0), (0.0, 1.0, 0.0), R_ROD)  # noqa: E731
    ref = reference(Union(Union(Box((0, 0, 0), (2, 2, 2)), rod()), rod()), tol=1e-9)
    assert close(ref.area, 24 + math.pi * R_ROD)
    assert close(ref.volume, 8 + math.pi * R_ROD**2 * 0.5)
    assert ref.area_error < 1e-9 * ref.area and ref.volume_error < 1e-9 * ref.volume


def test_disc_with_its_copy_half_inside_a_box():
    r, t = 0.5, 1e-3  # a disc centred on the face x = 0 of the box x in [-2, 0]: its half x > 0 stays
    disc = lambda: Cylinder((0, 0, 0), (0, 0, t), r)  # noqa: E731
    ref = reference(Union(Union(Box((-1, 0, 0), (2, 2, 2)), disc()), disc()), tol=1e-9)
    assert close(ref.area, 24 - 2 * r * t + math.pi * r * t + math.pi * r * r)
    assert close(ref.volume, 8 + math.pi * r * r * t / 2)


def test_rod_through_a_sphere():
    # a rod along x, x in [0.5, 1.5], through the sphere's side: outside from x = c = sqrt(1 - r^2);
    # the sphere loses the cap of height h = 1 - c that lies inside the rod
    r = R_ROD
    c = math.sqrt(1 - r * r)
    h = r * r / (1 + c)
    rod = lambda: Cylinder((1.0, 0, 0), (1.0, 0, 0), r)  # noqa: E731
    ref = reference(Union(Union(Sphere((0, 0, 0), 1.0), rod()), rod()), tol=1e-9)
    assert close(ref.area, 4 * math.pi - 2 * math.pi * h + 2 * math.pi * r * (1.5 - c) + math.pi * r * r)
    assert close(ref.volume, 4 * math.pi / 3 + math.pi * r * r * (1.5 - c) - math.pi * h * h * (3 - h) / 3)


def test_empty_intersection_of_curved_leaves():
    # case 406 of the 1000-tree run: the sphere ends at z = -0.5, the cylinder p3 starts at z = 0
    p0 = Cylinder(center=(0.0, 0.25, -0.75), axis=(0.075, -0.125, 0.25), radius=1.5)
    p1 = Sphere(center=(0.75, 0.25, -1.0), radius=0.5)
    p3 = Cylinder(center=(0.25, 0.25, 0.5), axis=(1.75, 0.0, 0.0), radius=0.5)
    p4 = Cone(center=(-0.25, 0.5, 1.0), axis=(0.25, 0.0, 0.0), radius=1.75)
    ref = reference(Intersection(Intersection(p0, p1), Intersection(p3, p4)), tol=1e-5)
    assert ref.area == 0.0 and ref.volume == 0.0
    assert ref.area_error < 1e-9


@pytest.mark.parametrize("tol", [1e-5, 1e-9])
def test_a_cut_rod_is_as_accurate_as_asked(tol):
    # the rod of the first test ending in the union of two boxes (the box [-1, 1]^3 grown to y = 1.2)
    rod = Cylinder((0.0, 1.0, 0.0), (0.0, 1.0, 0.0), R_ROD)
    tree = Union(Union(Box((0, 0, 0), (2, 2, 2)), Box((0, 1.1, 0), (2, 0.2, 2))), rod)  # y <= 1.2
    ref = reference(tree, tol=tol)
    exact = 24 + 4 * 2 * 0.2 + 2 * math.pi * R_ROD * 0.3  # its top disc replaces the hole it leaves
    assert abs(ref.area - exact) <= tol * exact
