"""The branch-free arc tangent of the compiled edge sums (``lambert.atan2_pos``) against libm's ``math.atan2``."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from isocsg.shadows.lambert import atan2_pos, edge_term_fast, edge_term_nb

positive = st.floats(min_value=1e-300, max_value=1e300, allow_nan=False, allow_infinity=False)
signed = st.floats(min_value=-1e300, max_value=1e300, allow_nan=False, allow_infinity=False)
coords = st.floats(min_value=-10.0, max_value=10.0, allow_nan=False)


# No deadline: the first example loads the compiled kernels (0.4 s in a fresh process).
@settings(deadline=None)
@given(positive, signed)
def test_atan2_pos_is_within_a_few_ulp_of_libm(s: float, d: float) -> None:
    exact = math.atan2(s, d)
    assert abs(atan2_pos(s, d) - exact) <= 4 * math.ulp(exact)


def test_atan2_pos_on_the_quadrant_and_reduction_boundaries() -> None:
    t8 = math.tan(math.pi / 8)
    for s, d in [(1.0, 0.0), (1.0, 1.0), (1.0, -1.0), (1.0, 1e-300), (1e-300, 1.0), (1e-300, -1.0), (t8, 1.0),
                 (1.0, t8), (1.0, -t8), (np.nextafter(t8, 1), 1.0), (5e-324, 0.0), (1e300, -1e-300)]:
        exact = math.atan2(s, d)
        assert abs(atan2_pos(s, d) - exact) <= 4 * math.ulp(exact), (s, d)


@settings(deadline=None)
@given(st.lists(coords, min_size=12, max_size=12))
def test_fast_edge_term_equals_the_libm_one(v: list[float]) -> None:
    p, n, a, b = v[0:3], v[3:6], v[6:9], v[9:12]
    ref = edge_term_nb(*p, *n, *a, *b)
    got = edge_term_fast(*p, *n, *a, *b)
    # the terms are beta (n . g) with beta in [0, pi] and |n . g| <= |n|
    assert abs(got - ref) <= 1e-14 * max(1.0, math.sqrt(sum(x * x for x in n)))


def test_fast_edge_term_of_a_degenerate_edge_is_zero() -> None:
    assert edge_term_fast(0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1) == 0.0  # zero length
    assert edge_term_fast(0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1) == 0.0  # through p
    assert edge_term_fast(0, 0, 0, 0, 0, 1, 1, 0, 0, 2, 0, 0) == 0.0  # in line with p
