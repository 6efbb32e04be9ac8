"""Interreflections: the radiosity solve against exact relations and an independent path tracer.

- Flux balance of a closed room of uniform reflectance (the integrating-sphere
  relation in the form that holds for any enclosure): the reflected light
  incident on the walls adds up to rho Phi / (1 - rho). For a sphere it holds
  at every point; for a box it holds for the area integral, which is what the
  discrete solve conserves exactly when its form factors are exact (rows
  summing to 1, reciprocity) and the direct flux is exact (closed forms).
- The per-point form: surfaces of uniform exitance B around a point give
  E_ind = B at that point whatever its orientation (the "furnace"), occluder
  boxes included: this checks the indirect evaluation and its occlusion at
  single points exactly.
- A furnished room (box room + a reflecting table box) against the
  independent path tracer of ``tests/mc_paths.py``: agreement within the
  tracer's 4-sigma interval plus the discretisation error of constant
  radiosity per patch (documented in docs/interreflections.md).
"""

from __future__ import annotations

import math
import re
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from isocsg import AreaLight, Box, Sphere, illuminance
from isocsg.errors import InvalidParameterError, ResourceLimitError
from isocsg.shadows.patches import Room, surface_patches
from isocsg.shadows.radiosity import (
    Interreflections,
    RadiositySolution,
    _Blockers,
    _Columns,
    indirect_illuminance,
    solve_radiosity,
)

sys.path.insert(0, str(Path(__file__).resolve().parent))

from mc_paths import MCRoom, mc_indirect  # noqa: E402

LAMP = AreaLight([(-0.6, -0.3, 2.8), (-0.6, 0.3, 2.8), (0.6, 0.3, 2.8), (0.6, -0.3, 2.8)], radiance=1000.0)


@pytest.mark.parametrize("rho", [0.2, 0.5, 0.8])
def test_closed_room_flux_balance(rho):
    room = Room((0, 0, 1.5), (4, 3, 3), floor=rho, walls=rho, ceiling=rho)
    sol = solve_radiosity(LAMP, (), Interreflections(room=room, patch_size=1.0, refine=0, tolerance=1e-11))
    a = sol.patches.area
    phi = LAMP.flux
    assert float(a @ sol.direct) == pytest.approx(phi, rel=1e-9)  # every lumen lands on the walls
    assert float(a @ (sol.incident - sol.direct)) == pytest.approx(rho * phi / (1 - rho), rel=1e-6)
    mean_indirect = float(a @ (sol.incident - sol.direct)) / room.area
    assert mean_indirect == pytest.approx(rho * phi / (room.area * (1 - rho)), rel=1e-6)
    assert sol.residuals[-1] <= 1e-11
    assert np.all(np.diff(sol.residuals[: min(50, len(sol.residuals))]) <= 1e-15)


def _furnace(room, boxes, B=7.0):
    patches = surface_patches(room, boxes, [0.5] * len(boxes), 1.0)
    n = len(patches)
    return RadiositySolution(patches, np.full(n, B), np.zeros(n), np.zeros(0), tuple(boxes))


def test_uniform_exitance_gives_it_back_at_every_point():
    room = Room((0, 0, 1.5), (4, 4, 3))
    table = Box((0.8, 0.3, 0.375), (1.2, 0.8, 0.75))
    cube = Box((-1.0, -1.0, 2.0), (0.5, 0.5, 0.5))
    sol = _furnace(room, [table, cube])
    rng = np.random.default_rng(3)
    pts = np.array([[-1.5, 1.2, 0.0], [0.8, 0.3, 0.75], [1.9999, 0.3, 0.5], [-1.0, -1.0, 1.75], [0.3, -1.6, 3.0],
                    [0.1, 0.2, 1.3], [-1.0, 0.5, 2.0], [0.2, 0.3, 0.4]])
    nrm = np.array([[0, 0, 1], [0, 0, 1], [-1, 0, 0], [0, 0, -1], [0, 0, -1], [0.3, -0.5, 0.8],
                    [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]], dtype=float)
    nrm[5:7] += 0.3 * rng.normal(size=(2, 3))  # the last point lies on the table's -x face
    e = sol.indirect_illuminance(pts, nrm)
    assert e == pytest.approx(np.full(len(pts), 7.0), rel=1e-9)


def test_columns_closed_room_rows_sum_to_one_and_reciprocity():
    room = Room((0, 0, 1.5), (4, 3, 3))
    patches = surface_patches(room, [], [], 1.0)
    cols = _Columns(patches, [], _Blockers([], 4.0), 3, 64, 2**30)
    F = np.stack([cols(j) for j in range(len(patches))], axis=1)
    assert F.sum(axis=1) == pytest.approx(np.ones(len(patches)), rel=1e-10)
    AF = patches.area[:, None] * F
    assert AF == pytest.approx(AF.T, rel=1e-10, abs=1e-14)


def test_columns_with_an_occluder_still_close_the_enclosure():
    """Room + a floating reflecting box: the pairs the box may hide use Gauss points on the receiver.

    The rows' departure from 1 is that quadrature's error where the box's shadow
    crosses a patch: measured 1.5 % at 3 x 3 points, 0.12 % at 8 x 8 on 1 m patches; it
    must shrink with the order.
    """
    room = Room((0, 0, 1.5), (4, 4, 3))
    table = Box((0.8, 0.3, 0.6), (1.2, 0.8, 0.7))
    patches = surface_patches(room, [table], [0.4], 1.0)
    worst = []
    for order in (3, 8):
        cols = _Columns(patches, [table], _Blockers([table], 4.0), order, 64, 2**30)
        F = np.stack([cols(j) for j in range(len(patches))], axis=1)
        worst.append(np.max(np.abs(F.sum(axis=1) - 1)))
    assert worst[1] < worst[0] / 5
    assert worst[1] < 2e-3


MC_ROOM = MCRoom(np.array([-2, -2, 0.0]), np.array([2, 2, 3.0]), 0.2, 0.5, 0.7,
                 [(np.array([0.2, -0.1, 0.0]), np.array([1.4, 0.7, 0.75]), 0.4)],
                 np.array([-0.6, -0.3]), np.array([0.6, 0.3]), 2.8, 1000.0)
DISCRETISATION = 0.02  # relative error of constant radiosity on 0.5 m patches (docs/interreflections.md)


def test_furnished_room_against_path_tracer():
    room = Room((0, 0, 1.5), (4, 4, 3), floor=0.2, walls=0.5, ceiling=0.7)
    table = Box((0.8, 0.3, 0.375), (1.2, 0.8, 0.75))
    pts = np.array([[-1.2, -1.0, 0.0], [0.8, 0.3, 0.75], [0.8, -0.5, 0.0], [1.999999, 0.0, 1.2]])
    nrm = np.array([[0, 0, 1.0], [0, 0, 1.0], [0, 0, 1.0], [-1.0, 0, 0]])
    inter = Interreflections(room=room, reflectances=0.4, patch_size=0.5, refine=1, tolerance=1e-6)
    sol = solve_radiosity(LAMP, [table], inter)
    got = sol.indirect_illuminance(pts, nrm)
    ref, err = mc_indirect(MC_ROOM, pts, nrm, paths=10000, seed=11)
    assert np.all(np.abs(got - ref) <= 4 * err + DISCRETISATION * ref), (got, ref, err)


def test_illuminance_with_interreflections_adds_the_indirect_part():
    room = Room((0, 0, 1.5), (4, 4, 3))
    inter = Interreflections(room=room, patch_size=2.0, refine=0)
    pts, nrm = [[0.3, 0.2, 0.0], [1.0, -1.0, 0.0]], [0, 0, 1]
    total = illuminance(pts, nrm, LAMP, interreflections=inter)
    direct = illuminance(pts, nrm, LAMP)
    indirect = solve_radiosity(LAMP, (), inter).indirect_illuminance(pts, nrm)
    assert total == pytest.approx(direct + indirect, rel=1e-12)
    assert np.all(indirect > 0.05 * direct)


def test_refinement_follows_the_shadow_boundary():
    room = Room((0, 0, 1.5), (4, 4, 3))
    table = Box((0.0, 0.0, 0.375), (1.0, 1.0, 0.75))
    coarse = solve_radiosity(LAMP, [table], Interreflections(room=room, reflectances=0.3, patch_size=2.0, refine=0))
    fine = solve_radiosity(LAMP, [table], Interreflections(room=room, reflectances=0.3, patch_size=2.0, refine=1))
    assert len(fine.patches) > len(coarse.patches)

    def count(sol, z):
        cen = np.add.reduceat(sol.patches.verts, sol.patches.off[:-1], axis=0) / np.diff(sol.patches.off)[:, None]
        return int(np.sum((np.abs(cen[:, 2] - z) < 1e-9) & (sol.patches.owner == -1)))

    assert count(fine, 0.0) > count(coarse, 0.0)  # the table's shadow on the floor
    assert count(fine, 3.0) == count(coarse, 3.0)  # the ceiling is all umbra (behind the source)


def test_indirect_function_matches_solution():
    room = Room((0, 0, 1.5), (4, 4, 3))
    inter = Interreflections(room=room, patch_size=1.0, refine=0)
    e = indirect_illuminance([[0, 0, 0]], [0, 0, 1], LAMP, (), inter)
    assert e[0] == pytest.approx(solve_radiosity(LAMP, (), inter).indirect_illuminance([[0, 0, 0]], [0, 0, 1])[0])
    assert e[0] > 0


def test_black_room_gives_no_indirect_light():
    room = Room((0, 0, 1.5), (4, 4, 3), floor=0, walls=0, ceiling=0)
    e = indirect_illuminance([[0, 0, 0]], [0, 0, 1], LAMP, (), Interreflections(room=room))
    assert e[0] == 0.0


@pytest.mark.parametrize("kwargs,msg", [
    ({"patch_size": 0}, "interreflections.patch_size must be > 0"),
    ({"patch_size": float("nan")}, "interreflections.patch_size must be finite"),
    ({"refine": 9}, "interreflections.refine must be between 0 and 6"),
    ({"reflectances": 1.5}, "interreflections.reflectances must be <= 0.999"),
    ({"reflectances": (0.2, -1)}, "interreflections.reflectances[1] must be >= 0"),
    ({"tolerance": 0}, "interreflections.tolerance must be > 1e-15"),
    ({"room": "box"}, "interreflections.room must be a Room"),
])
def test_bad_settings_raise(kwargs, msg):
    with pytest.raises(InvalidParameterError, match=re.escape(msg)):
        Interreflections(**kwargs)


def test_bad_rooms_raise():
    with pytest.raises(InvalidParameterError, match=re.escape("room.size must be > 0")):
        Room((0, 0, 0), (1, 0, 1))
    with pytest.raises(InvalidParameterError, match=re.escape("room.walls must be <= 0.999")):
        Room((0, 0, 0), (1, 1, 1), walls=1.0)


def test_curved_reflector_and_count_mismatch_raise():
    room = Room((0, 0, 1.5), (4, 4, 3))
    with pytest.raises(InvalidParameterError, match="occluders\\[0\\] is a Sphere: only boxes and convex polyhedra"):
        solve_radiosity(LAMP, [Sphere((0, 0, 1), 0.3)], Interreflections(room=room, reflectances=0.5))
    # black curved occluders are fine
    solve_radiosity(LAMP, [Sphere((0, 0, 1), 0.3)], Interreflections(room=room, reflectances=0.0, patch_size=2.0,
                                                                      refine=0))
    with pytest.raises(InvalidParameterError, match="one value per occluder \\(1\\), got 2"):
        solve_radiosity(LAMP, [Box((0, 0, 1), (1, 1, 1))], Interreflections(room=room, reflectances=(0.1, 0.2)))


def test_limits_raise():
    room = Room((0, 0, 1.5), (4, 4, 3))
    with pytest.raises(ResourceLimitError, match="over interreflections.max_patches = 10"):
        solve_radiosity(LAMP, (), Interreflections(room=room, max_patches=10))
    with pytest.raises(ResourceLimitError, match="after 3 shots, above interreflections.tolerance"):
        solve_radiosity(LAMP, (), Interreflections(room=room, patch_size=1.0, refine=0, max_shots=3))


def test_memory_budget_zero_recomputes_columns_with_the_same_result():
    room = Room((0, 0, 1.5), (4, 4, 3))
    a = solve_radiosity(LAMP, (), Interreflections(room=room, patch_size=2.0, refine=0))
    b = solve_radiosity(LAMP, (), Interreflections(room=room, patch_size=2.0, refine=0, memory=0))
    assert b.radiosity == pytest.approx(a.radiosity, rel=1e-14)
    assert math.isclose(a.residuals[-1], b.residuals[-1], rel_tol=1e-12)


def test_illuminance_refuses_other_interreflection_values():
    with pytest.raises(InvalidParameterError, match="interreflections must be an Interreflections, got dict"):
        illuminance([[0, 0, 0]], [0, 0, 1], LAMP, interreflections={"room": None})


@settings(max_examples=5, deadline=None)
@given(
    st.tuples(st.floats(1.0, 6.0), st.floats(1.0, 6.0), st.floats(2.0, 4.0)),
    st.floats(0.05, 0.9),
    st.tuples(st.floats(-0.3, 0.3), st.floats(-0.3, 0.3)),
)
def test_flux_balance_in_random_rooms(size, rho, offset):
    """Any closed box room, any uniform reflectance, a panel anywhere below the ceiling."""
    sx, sy, sz = size
    room = Room((0, 0, sz / 2), size, floor=rho, walls=rho, ceiling=rho)
    cx, cy = offset[0] * sx, offset[1] * sy
    z = sz - 0.1
    lamp = AreaLight([(cx - 0.2, cy - 0.1, z), (cx - 0.2, cy + 0.1, z), (cx + 0.2, cy + 0.1, z),
                      (cx + 0.2, cy - 0.1, z)], radiance=500.0)
    sol = solve_radiosity(lamp, (), Interreflections(room=room, patch_size=max(sx, sy, sz) / 2, refine=0,
                                                     tolerance=1e-10))
    a = sol.patches.area
    assert float(a @ sol.direct) == pytest.approx(lamp.flux, rel=1e-9)
    assert float(a @ (sol.incident - sol.direct)) == pytest.approx(rho * lamp.flux / (1 - rho), rel=1e-6)
