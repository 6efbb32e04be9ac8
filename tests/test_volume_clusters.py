"""``volume()`` of large trees split into clusters, judged by closed forms and manifold3d.

The trees have 1000 leaves or more and volumes known in closed form, written
here independently of isocsg: a lattice of overlapping spheres (the balls minus
one lens per pair of neighbours), a chain of overlapping boxes, a plate minus
pairs of overlapping holes (each pair's section is two discs minus their
lens-shaped overlap), unions of disjoint drilled beads. Where three leaves
overlap pairwise (no closed form), manifold3d's volume of a fine mesh judges.
Nothing here is timed (``benchmarks/scale.py`` times these trees).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

from isocsg import Box, Cylinder, Sphere, difference, union_all
from isocsg.csg.volume import volume

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference.meshes import manifold_of  # noqa: E402
from reference.models import sphere_lattice  # noqa: E402


def _ball(r: float) -> float:
    return 4.0 / 3.0 * math.pi * r**3


def _lens(r: float, d: float) -> float:
    """Volume of the intersection of two balls of radius ``r`` whose centres are ``d`` apart."""
    return math.pi * (4 * r + d) * (2 * r - d) ** 2 / 12


def _lens_area(r: float, d: float) -> float:
    """Area of the intersection of two discs of radius ``r`` whose centres are ``d`` apart."""
    return 2 * r * r * math.acos(d / (2 * r)) - 0.5 * d * math.sqrt(4 * r * r - d * d)


@pytest.mark.parametrize("overlap", [1.2, 1.4], ids=lambda o: f"overlap{o}")
def test_lattice_of_1000_spheres_is_exact(overlap: float) -> None:
    """Neighbours along an axis meet in a lens; diagonal neighbours are sqrt(2) pitch apart, more
    than two radii while the overlap is below sqrt(2), so no point lies in three balls."""
    n_side, extent = 10, 3.0
    pitch = extent / n_side
    r = overlap * pitch / 2
    exact = n_side**3 * _ball(r) - 3 * n_side**2 * (n_side - 1) * _lens(r, pitch)
    assert volume(sphere_lattice(n_side, extent=extent, overlap=overlap)) == pytest.approx(exact, rel=1e-12)


def test_union_of_1000_spheres_of_two_radii_is_exact() -> None:
    """A row of alternating large and small balls, each meeting its two neighbours only."""
    R, r, d = 0.5, 0.3, 0.7
    balls = [Sphere((k * d, 0.0, 0.0), R if k % 2 == 0 else r) for k in range(1000)]
    # lens of balls R and r at distance d (the standard cap formula)
    lens = math.pi * (R + r - d) ** 2 * (d * d + 2 * d * r - 3 * r * r + 2 * d * R + 6 * r * R - 3 * R * R) / (12 * d)
    exact = 500 * (_ball(R) + _ball(r)) - 999 * lens
    assert volume(union_all(balls)) == pytest.approx(exact, rel=1e-12)


def test_chain_of_1000_boxes_is_exact() -> None:
    boxes = [Box((0.8 * k, 0.1 * (k % 3), 0.0), (1.0, 1.0, 1.0)) for k in range(1000)]
    overlap = [0.2 * (1.0 - 0.1 * abs((k % 3) - ((k + 1) % 3))) for k in range(999)]
    exact = 1000.0 - sum(overlap)
    assert volume(union_all(boxes)) == pytest.approx(exact, rel=1e-12)


@pytest.mark.parametrize("grouped", [False, True], ids=["loop", "grouped"])
def test_plate_minus_1000_overlapping_hole_pairs(grouped: bool) -> None:
    """500 pairs of through holes, the two holes of a pair overlapping: a plate minus 500
    clusters, each cut being two discs minus their lens times the plate's thickness."""
    r, d, t = 0.1, 0.12, 0.4
    cols, rows, pitch = 25, 20, 0.5
    holes = []
    for k in range(cols * rows):
        i, j = divmod(k, cols)
        x, y = (j - (cols - 1) / 2) * pitch, (i - (rows - 1) / 2) * pitch
        holes += [Cylinder((x - d / 2, y, 0.0), (0.0, 0.0, 3 * t), r), Cylinder((x + d / 2, y, 0.0), (0.0, 0.0, 3 * t), r)]
    plate = Box((0.0, 0.0, 0.0), (cols * pitch, rows * pitch, t))
    if grouped:
        solid = plate - union_all(holes)
    else:
        solid = plate
        for h in holes:
            solid = solid - h
    exact = cols * pitch * rows * pitch * t - cols * rows * t * (2 * math.pi * r * r - _lens_area(r, d))
    assert volume(solid, tol=1e-6) == pytest.approx(exact, rel=1e-6)


def test_union_of_disjoint_drilled_beads() -> None:
    """A sphere minus a coaxial cylinder through it keeps 4/3 pi (R^2 - r^2)^(3/2) (the napkin
    ring); beads far apart add up."""
    R, r = 0.4, 0.15
    beads = [Sphere((k, (k % 7) * 1.1, 0.0), R) - Cylinder((k, (k % 7) * 1.1, 0.0), (0.0, 0.0, 1.0), r) for k in range(40)]
    exact = 40 * 4 / 3 * math.pi * (R * R - r * r) ** 1.5
    assert volume(union_all(beads), tol=1e-6) == pytest.approx(exact, rel=1e-6)


def _extrapolated_volume(solid) -> float:
    """manifold3d's volume of inscribed meshes at 128 and 256 segments, extrapolated to the limit
    (the meshes' deficit shrinks as 1 / segments^2)."""
    v1, v2 = manifold_of(solid, 128).volume(), manifold_of(solid, 256).volume()
    return v2 + (v2 - v1) / 3


def test_clusters_of_three_overlapping_spheres_match_manifold3d() -> None:
    """Three balls overlapping pairwise have no pairwise closed form: the clusters are
    integrated, and fine meshes judge. Separate clusters add up."""
    clusters = []
    for k in range(2):
        c = np.array([3.0 * k, 0.0, 0.0])
        clusters += [Sphere(tuple(c + o), 0.6) for o in ((0, 0, 0), (0.7, 0, 0), (0.35, 0.6, 0.1))]
    solid = union_all(clusters)
    assert volume(solid, tol=1e-6) == pytest.approx(_extrapolated_volume(solid), rel=2e-6)


def test_plate_minus_mixed_clusters_matches_manifold3d() -> None:
    """Clusters of a sphere and a slanted cylinder crossing it, cut from a plate."""
    plate = Box((0.0, 0.0, 0.0), (6.0, 2.0, 1.0))
    cuts = []
    for k in range(2):
        x = -2.25 + 1.5 * k
        cuts += [Sphere((x, 0.0, 0.5), 0.4), Cylinder((x + 0.2, 0.0, 0.0), (0.3, 0.2, 2.0), 0.15)]
    solid = difference(plate, *cuts)
    ref = _extrapolated_volume(solid)
    assert abs(volume(solid, tol=1e-6) - ref) <= 3e-6 * (12.0 - ref)  # relative to the volume cut away


def test_progress_of_a_split_tree_counts_its_parts() -> None:
    calls: list[tuple[int, int]] = []
    beads = [Sphere((2.0 * k, 0.0, 0.0), 0.5) - Cylinder((2.0 * k, 0.0, 0.0), (0.2, 0.0, 1.0), 0.2) for k in range(5)]
    volume(union_all(beads), progress=lambda done, total: calls.append((done, total)))
    assert calls[-1] == (5, 5)
    assert all(0 < d <= t for d, t in calls)
