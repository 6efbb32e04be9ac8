"""offset: rounded (exact), mitred and chamfered, against shapely's buffer and closed forms."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
import shapely
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon

from isocsg.errors import InvalidGeometryError
from isocsg.shapes2d import EMPTY, Circle, area, area_bounds, circle, offset, polygon, square, to_shapely
from isocsg.shapes2d.boundary import contains_points

L_SHAPE = [(0, 0), (4, 0), (4, 1), (1, 1), (1, 4), (0, 4)]


def _hausdorff(a, b):
    """Symmetric Hausdorff distance of two regions' boundaries, sampled at their (densified) vertices.

    GEOS's discrete Hausdorff distance can report a vertex-pair distance far above the true one on
    finely polygonised arcs, so the distances of each boundary's points to the other boundary are used.
    """
    pa = shapely.points(shapely.get_coordinates(shapely.segmentize(a.boundary, 0.01)))
    pb = shapely.points(shapely.get_coordinates(shapely.segmentize(b.boundary, 0.01)))
    return max(float(shapely.distance(pa, b.boundary).max()), float(shapely.distance(pb, a.boundary).max()))


def _star(radii):
    ang = np.linspace(0, 2 * np.pi, len(radii), endpoint=False)
    r = np.asarray(radii)
    return np.c_[r * np.cos(ang), r * np.sin(ang)]


def test_rounded_square_closed_form():
    assert area(offset(square(2), 1)) == pytest.approx(4 + 8 + math.pi, rel=1e-12)
    assert area(offset(square(4), -1)) == pytest.approx(4.0, rel=1e-12)
    assert area(offset(offset(square(4), -1), 1)) == pytest.approx(16 - (4 - math.pi), rel=1e-9)


@pytest.mark.parametrize("r", [0.3, -0.3, 1.5, -0.45])
def test_rounded_offset_converges_to_shapely_buffer(r):
    shape = polygon(L_SHAPE)
    ours = to_shapely(offset(shape, r), resolution=8192)
    exact_area = area(offset(shape, r))
    errors, distances = [], []
    for q in (4, 16, 64, 256):
        ref = Polygon(L_SHAPE).buffer(r, quad_segs=q)
        errors.append(abs(ref.area - exact_area))
        distances.append(_hausdorff(ours, ref))
    assert all(a > b for a, b in zip(errors, errors[1:])), errors
    assert all(a > b for a, b in zip(distances, distances[1:])), distances
    assert errors[-1] < 1e-4 * abs(exact_area) and distances[-1] < 1e-4


@pytest.mark.parametrize("d", [0.25, -0.25, 1.0, -0.4])
def test_mitred_offset_is_shapelys_mitre_buffer(d):
    shape = polygon(L_SHAPE) - square(0.5).translate([0.25, 2])
    ours = to_shapely(offset(shape, delta=d))
    ref = to_shapely(shape).buffer(d, join_style="mitre", mitre_limit=1e6)
    assert ours.symmetric_difference(ref).area < 1e-12
    assert area(offset(shape, delta=d)) == pytest.approx(ref.area, rel=1e-12)


def _chamfer_reference(points, d):
    """Chamfered offset of a convex polygon: the mitre offset cut by a line at distance d along each bisector."""
    poly = shapely.orient_polygons(Polygon(points))
    out = poly.buffer(d, join_style="mitre", mitre_limit=1e6)
    pts = np.asarray(poly.exterior.coords)[:-1]
    for i in range(len(pts)):
        t1, t2 = pts[i] - pts[i - 1], pts[(i + 1) % len(pts)] - pts[i]
        n1 = np.array([t1[1], -t1[0]]) / np.hypot(*t1)
        n2 = np.array([t2[1], -t2[0]]) / np.hypot(*t2)
        b = (n1 + n2) / np.hypot(*(n1 + n2))
        far = pts[i] + b * (d + 10), pts[i] + b * d
        side = np.array([-b[1], b[0]]) * 100
        cut = Polygon([far[1] + side, far[0] + side, far[0] - side, far[1] - side])
        out = out.difference(cut)
    return out


@settings(max_examples=30, deadline=None)
@given(st.lists(st.floats(1.0, 3.0), min_size=3, max_size=9), st.floats(0.05, 1.0))
def test_chamfer_of_convex_polygons_cuts_square_at_delta(radii, d):
    pts = np.asarray(shapely.convex_hull(shapely.multipoints(_star(radii))).exterior.coords)[:-1]
    shape = polygon(pts)
    ref = _chamfer_reference(pts, d)
    ours = to_shapely(offset(shape, delta=d, chamfer=True))
    assert ours.symmetric_difference(ref).area < 1e-9 * ref.area


def test_chamfered_square_closed_form():
    assert area(offset(square(2), delta=1, chamfer=True)) == pytest.approx(16 - 4 * (math.sqrt(2) - 1) ** 2, rel=1e-12)


def test_circles_stay_circles():
    assert offset(circle(1), 0.5) == Circle((0, 0), 1.5)
    assert offset(circle(1), delta=-0.25) == Circle((0, 0), 0.75)
    assert offset(circle(1), -1) == EMPTY
    shape = offset(circle(1) | circle(1).translate([3, 0]), 0.5)
    assert area(shape) == pytest.approx(2 * math.pi * 2.25, rel=1e-12)


def test_trees_offset_through_exact_identities():
    plate = square(6, center=True) - circle(1)
    eroded = offset(plate, -0.5)  # (A eroded) - (disc dilated): exact
    ref = to_shapely(plate, resolution=1 << 14).buffer(-0.5, quad_segs=1024)
    assert area(eroded) == pytest.approx(ref.area, rel=1e-7)
    grown = offset(square(2) | circle(1).translate([2, 1]), 0.5)  # a dilated union distributes
    ref = to_shapely(square(2) | circle(1).translate([2, 1]), resolution=1 << 14).buffer(0.5, quad_segs=1024)
    assert area(grown) == pytest.approx(ref.area, rel=1e-7)


def test_tolerance_offsets_a_polygonisation():
    shape = square(4) - circle(1)
    with pytest.raises(InvalidGeometryError, match=re.escape("offset.delta: the offset of a dilated difference with curved parts")):
        offset(shape, delta=0.5)
    grown = offset(shape, delta=0.5, tolerance=1e-5)
    # The mitre of the polygonisation (703 chords for a chord error of 1e-5 on the unit circle):
    # where an arc meets an edge, the corner's mitre depends on the chords, so no finer limit exists.
    ref = to_shapely(shape, resolution=703).buffer(0.5, join_style="mitre", mitre_limit=1e6)
    assert to_shapely(grown).symmetric_difference(ref).area < 1e-12


def test_rounded_offsets_of_any_tree_are_exact():
    ell = polygon(L_SHAPE)
    closing = offset(offset(ell, 1), -1)  # fills the inner corner with a quarter-round fillet
    assert area(closing) == pytest.approx(7 + 1 - math.pi / 4, rel=1e-13)
    opening = offset(offset(ell, -0.25), 0.25)  # rounds the five convex corners
    assert area(opening) == pytest.approx(7 - 5 * 0.0625 * (1 - math.pi / 4), rel=1e-13)
    plate = square(4) - circle(1)
    grown = offset(plate, 0.5)  # a dilated difference with a circle: through the boundary
    # Steiner: A + P r + (total turning) r^2 / 2, the offset being free of overlaps here.
    a, p = 16 - math.pi / 4, 14 + math.pi / 2
    assert area(grown) == pytest.approx(a + p * 0.5 + math.pi * 0.25, rel=1e-14)
    reference = to_shapely(plate, resolution=1 << 14).buffer(0.5, quad_segs=1024)
    assert area(grown) == pytest.approx(reference.area, rel=1e-6)


def _distance_judge(shape, r, n=160, margin=2e-3):
    """Membership of the offset by r, from the distance to a fine polygonisation of ``shape``.

    A point belongs to the dilation (r > 0) when it is inside or within r of the boundary, to the
    erosion (r < 0) when it is inside and at least |r| from the boundary. Points within ``margin``
    of the contour |r| (polygonisation error, rounding) are left out. Returns the sample points,
    the expected membership and the mask of points that are judged.
    """
    fine = to_shapely(shape, resolution=2048)
    x0, y0, x1, y1 = fine.bounds
    pad = max(r, 0.0) + 0.1
    xs, ys = np.meshgrid(np.linspace(x0 - pad, x1 + pad, n), np.linspace(y0 - pad, y1 + pad, n))
    pts = np.column_stack([xs.ravel(), ys.ravel()])
    inside = shapely.contains_xy(fine, pts[:, 0], pts[:, 1])
    dist = shapely.distance(shapely.points(pts), fine.boundary)
    expected = (inside | (dist <= r)) if r > 0 else (inside & (dist >= -r))
    return pts, expected, np.abs(dist - abs(r)) > margin


@settings(max_examples=15, deadline=None)
@given(
    st.lists(st.tuples(st.floats(-1, 1), st.floats(-1, 1), st.floats(0.3, 1.0), st.booleans()), min_size=2, max_size=4),
    st.floats(-0.3, 0.4).filter(lambda r: abs(r) > 0.02),
)
def test_random_trees_with_circles_offset_like_the_distance_function(parts, r):
    shape = square(2, center=True)
    for x, y, size, is_circle in parts:
        leaf = circle(size) if is_circle else square(size, center=True).rotate(30)
        shape = shape - leaf.translate([x, y]) if size < 0.6 else shape | leaf.translate([x + 1, y])
    try:
        ours = offset(shape, r)
    except InvalidGeometryError as exc:
        # The documented refusal: a boundary whose chain of pieces does not close (curves tangent
        # within rounding, e.g. a circle touching an edge from inside) has no exact offset here.
        assert "with curved parts has no exact form here; pass offset(..., tolerance=...)" in str(exc)
        assume(False)
    # The judge is the distance to the shape, not GEOS's buffer: a negative buffer of a union of a
    # square and a rotated square minus a disc came out 2 % too small (2.2102 against the exact
    # 2.25582, which a 1000 x 1000 grid of distances confirmed at 2.2555).
    pts, expected, judged = _distance_judge(shape, r)
    got = contains_points(ours, pts)
    assert np.array_equal(got[judged], expected[judged]), pts[judged & (got != expected)][:5]
    lo, hi = area_bounds(ours, resolution=256)
    assert lo - 1e-9 <= area(ours) <= hi + 1e-9


@settings(max_examples=20, deadline=None)
@given(st.lists(st.floats(1.0, 3.0), min_size=5, max_size=16), st.floats(-0.4, 0.6).filter(lambda r: abs(r) > 0.02))
def test_random_nonconvex_offsets_match_shapely(radii, r):
    pts = _star(radii)
    ours = offset(polygon(pts), r)
    ref = Polygon(pts).buffer(r, quad_segs=512)
    assert area(ours, resolution=1024) == pytest.approx(ref.area, rel=1e-5)
    assert _hausdorff(to_shapely(ours, resolution=1024), ref) < 1e-4


BAD = [
    (lambda: offset(square(1)), "offset takes one of r and delta"),
    (lambda: offset(square(1), 1, delta=1), "offset takes one of r and delta"),
    (lambda: offset(square(1), float("nan")), "offset.r must be a finite number"),
    (lambda: offset(square(1), delta="1"), "offset.delta must be a number, got '1'"),
    (lambda: offset(square(1), delta=1, chamfer="yes"), "offset.chamfer must be a boolean, got 'yes'"),
    (lambda: offset(square(1), 1, tolerance=0), "offset.tolerance must be > 0, got 0"),
    (lambda: offset(circle(1).scale([2, 1]), 1), "offset.r: the offset of an Ellipse with curved parts has no exact form"),
    (lambda: offset(circle(1) | circle(1).translate([1, 0]), delta=-0.1), "offset.delta: the offset of an eroded union with"),
    (lambda: offset("square", 1), "offset.shape must be a 2D shape, got str"),
]


@pytest.mark.parametrize("make, message", BAD, ids=[m for _, m in BAD])
def test_offset_errors_name_the_field(make, message):
    with pytest.raises(InvalidGeometryError, match=re.escape(message)):
        make()


def test_ellipses_offset_through_a_polygonisation():
    ellipse = circle(1).scale([2, 1])
    grown = offset(ellipse, 0.25, tolerance=1e-4)
    ref = to_shapely(ellipse, resolution=1 << 14).buffer(0.25, quad_segs=1024)
    assert area(grown, resolution=256) == pytest.approx(ref.area, rel=1e-4)
