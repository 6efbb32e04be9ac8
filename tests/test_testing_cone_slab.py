"""A cone minus a slab through its axis (the demonstration's case 520 family, docs/testing_engines.md,
"Findings"). The reference was 6.5e-5 off with an error estimate of 5e-12: a sample of a slab
face's ring on the cone's base plane hid the next crossing, and the sweep did not break where the
cone's rings become tangent to the slab's faces (the ring measure's square-root end). The true
volume is the cone's closed form minus the slab's part, integrated here over the cone's axis from
the closed-form area of a disc cut by a band (scipy's quad, split where the cone's radius equals
the slab's half thickness)."""

from __future__ import annotations

import math

from scipy.integrate import quad

from isocsg import Box, Cone, Difference
from isocsg.testing import reference


def _cone_less_slab(r: float, h: float, w: float) -> float:
    """Volume of the cone of base radius ``r`` and height ``h`` less the slab ``|z| < w``
    through its axis."""

    def band(x: float) -> float:  # the disc of radius rho at x, within |z| < w
        rho = r * (1 - x / h)
        if rho <= w:
            return math.pi * rho * rho
        return 2 * (w * math.sqrt(rho * rho - w * w) + rho * rho * math.asin(w / rho))

    x_w = h * (1 - w / r)
    inside = quad(band, 0, x_w, epsabs=1e-15, epsrel=1e-12)[0] + quad(band, x_w, h, epsabs=1e-15, epsrel=1e-12)[0]
    return math.pi * r * r * h / 3 - inside


def test_closed_form_of_a_cone_less_a_slab_is_right():
    # the reference function itself, at a slab too thin to matter to 1e-12 and at none
    assert math.isclose(_cone_less_slab(0.5, 0.25, 1e-15), math.pi * 0.25 * 0.25 / 3, rel_tol=1e-12)


def test_cone_less_a_slab_through_its_axis():
    r, h, w = 0.5, 0.25, 0.05
    tree = Difference(Cone((0, 0, 0), (h, 0, 0), r), Box((0, 0, 0), (2, 2, 2 * w)))
    ref = reference(tree, tol=1e-9)
    true = _cone_less_slab(r, h, w)
    assert abs(ref.volume - true) <= 1e-9 * true
    assert abs(ref.volume - true) <= ref.volume_error + 1e-13 * true  # the estimate bounds the error
