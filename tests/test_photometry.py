"""Photometric files (IES LM-63, EULUMDAT) and point luminaires against closed forms.

References here are independent of the code under test: the inverse-square
and cosine laws written out, the analytic distributions the files are built
from, and a Gauss-Legendre x uniform quadrature of the intensity over the
sphere for the flux.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from isocsg import Box
from isocsg.errors import InvalidLightError
from isocsg.lighting.area import AreaLight
from isocsg.lighting.luminaire import PhotometricLight
from isocsg.lighting.photometry import Photometry, PhotometryFileError, read_photometry
from isocsg.shadows.direct import illuminance, illuminance_and_state

pytest.importorskip("photompy")
pytest.importorskip("pyldt")


def ies_text(gammas, cs, table, *, version="IES:LM-63-2002", lumens=1000.0, mult=1.0, units=2, width=0.0,
             length=0.0, ptype=1, tilt="NONE", ballast=1.0, future=1.0) -> str:
    head = [version, "[TEST] unit", "[MANUFAC] isocsg tests", "[LUMINAIRE] analytic", f"TILT={tilt}"]
    nums = [1, lumens, mult, len(gammas), len(cs), ptype, units, width, length, 0.0]
    head.append(" ".join(f"{x:.15g}" for x in nums))
    head.append(f"{ballast:g} {future:g} 10")
    head.append(" ".join(f"{g:.10g}" for g in gammas))
    head.append(" ".join(f"{c:.10g}" for c in cs))
    for row in np.asarray(table, dtype=float):
        head.append(" ".join(f"{v:.12g}" for v in row))
    return "\r\n".join(head) + "\r\n"


def ldt_text(isym, mc, ng, table_cdklm, *, flux=1000.0, lor=80.0, conv=1.0, lum=(600.0, 600.0), c_list=None) -> str:
    dc, dg = (360.0 / mc if c_list is None else 0.0), 180.0 / (ng - 1)
    lines = ["isocsg tests", "1", str(isym), str(mc), f"{dc:g}", str(ng), f"{dg:g}", "R-1", "analytic", "N-1",
             "t.ldt", "2026", "600", "600", "50", f"{lum[0]:g}", f"{lum[1]:g}", "0", "0", "0", "0", "100",
             f"{lor:g}", f"{conv:g}", "0", "1", "1", "LED", f"{flux:g}", "3000", "80", "40"]
    lines += ["0.5"] * 10
    lines += [f"{k * dc:g}" for k in range(mc)] if c_list is None else [f"{c:g}" for c in c_list]
    lines += [f"{k * dg:g}" for k in range(ng)]
    lines += [f"{v:.12g}" for row in table_cdklm for v in row]
    return "\r\n".join(lines) + "\r\n"


def write(tmp_path: Path, name: str, text: str) -> Path:
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def sphere_flux(intensity, panels=72, n_c=720) -> float:
    """Flux of an intensity function of world directions: composite Gauss-Legendre (8 points) over
    ``panels`` equal panels of the polar angle, with its sin weight, and the midpoint rule in azimuth.

    Tables with nodes every 180 / panels degrees of gamma and C planes on the azimuth cells' edges
    (an unturned luminaire) are piecewise smooth in each cell, where the rules converge fast.
    """
    x, w = np.polynomial.legendre.leggauss(8)
    edges = np.linspace(0, np.pi, panels + 1)
    half = 0.5 * np.diff(edges)
    th = (0.5 * (edges[:-1] + edges[1:]))[:, None] + half[:, None] * x[None, :]
    wt = (half[:, None] * w[None, :] * np.sin(th)).ravel()
    th = th.ravel()
    phi = (np.arange(n_c) + 0.5) * 2 * np.pi / n_c
    T, P = np.meshgrid(th, phi, indexing="ij")
    d = np.c_[(np.sin(T) * np.cos(P)).ravel(), (np.sin(T) * np.sin(P)).ravel(), np.cos(T).ravel()]
    val = intensity(d).reshape(T.shape)
    return float(np.sum(val * wt[:, None]) * 2 * np.pi / n_c)


# ----------------------------------------------------------------------------- isotropic and Lambertian files


@pytest.fixture(scope="module")
def iso_file(tmp_path_factory):
    d = tmp_path_factory.mktemp("phot")
    return write(d, "iso.ies", ies_text([0, 90, 180], [0], [[100, 100, 100]], lumens=1256.6370614359173))


@settings(max_examples=25, deadline=None)
@given(
    st.tuples(*[st.floats(-4, 4) for _ in range(2)]), st.floats(0.5, 5), st.floats(0.1, 1000),
    st.tuples(*[st.floats(-1, 1) for _ in range(3)]).filter(lambda v: np.linalg.norm(v) > 0.1),
)
def test_isotropic_file_is_a_uniform_point_source(iso_file, xy, h, mult, normal):
    lamp = PhotometricLight((0.0, 0.0, h), read_photometry(iso_file), multiplier=mult)
    p = np.array([[xy[0], xy[1], 0.0]])
    n = np.asarray(normal) / np.linalg.norm(normal)
    v = np.array([0.0, 0.0, h]) - p[0]
    r = np.linalg.norm(v)
    expected = mult * 100.0 * max(0.0, float(n @ v) / r) / r**2
    assert illuminance(p, n, [lamp])[0] == pytest.approx(expected, rel=1e-12, abs=1e-15)


def test_isotropic_flux_round_trip(iso_file):
    ph = read_photometry(iso_file)
    assert ph.flux() == pytest.approx(400 * math.pi, rel=1e-12)
    assert ph.computed_lor == pytest.approx(1.0, rel=1e-9)  # the file's lumens are 4 pi 100
    lamp = PhotometricLight((1, 2, 3), ph, tilt=37, rotation=20)
    assert sphere_flux(lamp.intensity_towards) == pytest.approx(400 * math.pi, rel=1e-12)


def test_lambertian_file_against_cos_law(tmp_path):
    g = np.arange(0, 91, 5.0)
    ph = read_photometry(write(tmp_path, "lamb.ies", ies_text(g, [0], [1000 * np.cos(np.radians(g))])))
    lamp = PhotometricLight((0.0, 0.0, 2.0), ph)
    # receivers whose direction from the lamp is at a tabulated gamma: exact cos law
    ang = np.radians(g[:-1])
    p = np.c_[2 * np.tan(ang), np.zeros_like(ang), np.zeros_like(ang)]
    E = illuminance(p, [0, 0, 1], [lamp])
    expected = 1000 * np.cos(ang) * np.cos(ang) / (4 / np.cos(ang) ** 2)
    np.testing.assert_allclose(E, expected, rtol=1e-12, atol=1e-12)
    # between nodes: within the linear-interpolation bound h^2/8 max|cos''| of the intensity
    a = np.radians(np.linspace(0.3, 84.7, 41))
    p = np.c_[2 * np.tan(a), np.zeros_like(a), np.zeros_like(a)]
    E = illuminance(p, [0, 0, 1], [lamp])
    geo = np.cos(a) / (4 / np.cos(a) ** 2)
    err_I = np.abs(E / geo - 1000 * np.cos(a))
    assert np.all(err_I <= 1000 * np.radians(5) ** 2 / 8 * (1 + 1e-9))
    # nothing above the horizontal (measured over 0..90 only)
    assert illuminance([[0, 0, 4]], [0, 0, -1], [lamp])[0] == 0.0
    # the chord under a cosine loses cos h^2 t (1 - t) / 2, h^2 / 12 on average: flux ~ pi I0 (1 - h^2 / 12)
    h = math.radians(5)
    assert ph.flux() == pytest.approx(1000 * math.pi * (1 - h * h / 12), rel=1e-5)
    assert sphere_flux(lamp.intensity_towards) == pytest.approx(ph.flux(), rel=1e-6)


# ----------------------------------------------------------------------------- symmetries


def analytic(c, g):
    """A distribution symmetric about both the C0-C180 and the C90-C270 planes (quadrant symmetric)."""
    c, g = np.radians(c), np.radians(g)
    return 500 * (1 + 0.5 * np.cos(2 * c)) * np.clip(np.cos(g), 0, None) ** 2 + 40 * np.sin(g) ** 2


@pytest.mark.parametrize("isym", [0, 1, 2, 3, 4])
def test_eulumdat_symmetries_against_the_full_table(tmp_path, isym):
    mc, ng = 24, 37
    C = np.arange(mc) * 360 / mc
    G = np.linspace(0, 180, ng)
    full = analytic(C[:, None], G[None, :]) if isym != 1 else np.repeat(analytic(0 * C[:1, None], G[None, :]), mc, 0)
    stored = {0: full, 1: full[:1], 2: full[: mc // 2 + 1], 4: full[: mc // 4 + 1]}.get(isym)
    if isym == 3:  # C270, C285, ..., C0, ..., C90 (the EULUMDAT order)
        stored = np.array([full[int(round(((270 + k * 15) % 360) / 15))] for k in range(mc // 2 + 1)])
    ph = read_photometry(write(tmp_path, f"s{isym}.ldt", ldt_text(isym, mc, ng, stored, flux=2000.0)))
    ref = read_photometry(write(tmp_path, "full.ldt", ldt_text(0, mc, ng, full, flux=2000.0)))
    cc, gg = np.meshgrid(np.linspace(0, 360, 97), np.linspace(0, 180, 61), indexing="ij")
    np.testing.assert_allclose(ph.intensity(cc, gg), ref.intensity(cc, gg), rtol=1e-12, atol=1e-9)
    # at the nodes: the analytic values times the lamps' 2 klm
    np.testing.assert_allclose(ph.intensity(C[:, None], G[None, :]), 2 * full, rtol=1e-12, atol=1e-9)
    assert ph.lor == pytest.approx(0.8)
    lamp = PhotometricLight((0, 0, 0), ph)
    assert sphere_flux(lamp.intensity_towards, 72, 960) == pytest.approx(ph.flux(), rel=1e-5)


def test_eulumdat_isym_3_with_unequal_c_planes(tmp_path):
    """Dc = 0: the C angles are listed, not spaced; Isym 3 stores C270, C330, C0, C30, C90 (from index 3 Mc / 4)."""
    C = np.array([0, 30, 90, 150, 180, 210, 270, 330.0])
    G = np.linspace(0, 180, 19)

    def f(c, g):  # symmetric about the C90-C270 plane: sin(180 - C) = sin(C)
        return (300 + 200 * np.cos(np.radians(g))) * (1 + 0.4 * np.sin(np.radians(c)) * np.sin(np.radians(g)))

    full = f(C[:, None], G[None, :])
    stored = full[[6, 7, 0, 1, 2]]
    ph = read_photometry(write(tmp_path, "u3.ldt", ldt_text(3, 8, 19, stored, c_list=C)))
    ref = read_photometry(write(tmp_path, "u0.ldt", ldt_text(0, 8, 19, full, c_list=C)))
    assert ph.c_angles.tolist() == [90, 150, 180, 210, 270]
    cc, gg = np.meshgrid(np.linspace(0, 360, 121), np.linspace(0, 180, 37), indexing="ij")
    np.testing.assert_allclose(ph.intensity(cc, gg), ref.intensity(cc, gg), rtol=1e-12, atol=1e-9)
    bad = ldt_text(3, 8, 19, stored, c_list=[0, 30, 90, 150, 180, 210, 260, 330])
    with pytest.raises(PhotometryFileError, match="angle number 7 must be 270"):
        read_photometry(write(tmp_path, "b3.ldt", bad))


def test_ies_in_latin_1_is_read(tmp_path):
    text = ies_text([0, 90], [0], [[10, 10]]).replace("[MANUFAC] isocsg tests", "[MANUFAC] Lumi\xe8re")
    p = tmp_path / "l1.ies"
    p.write_bytes(text.encode("latin-1"))  # byte 0xe8 alone: not UTF-8
    assert float(read_photometry(p).intensity(0, 45)) == pytest.approx(10.0)


def test_ies_bilateral_and_quadrant_files_match_the_full_file(tmp_path):
    G = np.linspace(0, 180, 19)
    for cs in ([0, 45, 90], [0, 45, 90, 135, 180]):
        C = np.asarray(cs, float)
        half = read_photometry(write(tmp_path, "h.ies", ies_text(G, C, analytic(C[:, None], G[None, :]))))
        Cf = np.arange(0, 361, 45.0)
        full = read_photometry(write(tmp_path, "f.ies", ies_text(G, Cf, analytic(Cf[:, None], G[None, :]))))
        cc, gg = np.meshgrid(np.linspace(-30, 400, 87), np.linspace(0, 180, 31), indexing="ij")
        np.testing.assert_allclose(half.intensity(cc, gg), full.intensity(cc, gg), rtol=1e-12, atol=1e-9)


def test_ies_2019_feet_and_multipliers(tmp_path):
    text = ies_text([0, 90], [0], [[10, 10]], version="IES:LM-63-2019", mult=3.0, ballast=0.5, units=1,
                    width=2.0, length=4.0)
    ph = read_photometry(write(tmp_path, "a.ies", text))
    assert float(ph.intensity(0, 10)) == pytest.approx(15.0)
    assert ph.opening[:2] == pytest.approx((4 * 0.3048, 2 * 0.3048))
    assert ph.file_format == "LM-63-2019" and ph.source == "a.ies"


# ----------------------------------------------------------------------------- luminaire frame, shadows, openings


def test_aim_points_the_nadir_and_shadows_are_hard(tmp_path):
    G = np.linspace(0, 90, 10)
    spot = Photometry([0], G, [1000 * np.cos(np.radians(G)) ** 8])
    lamp = PhotometricLight((0, 0, 3), spot, aim=(3, 0, 0))
    assert lamp.tilt == pytest.approx(45) and lamp.rotation == pytest.approx(0)
    d = np.array([[3, 0, -3]]) / math.sqrt(18)
    assert lamp.intensity_towards(d)[0] == pytest.approx(1000)
    box = Box((1.5, 0, 1.5), (0.4, 0.4, 0.4))  # on the segment from (3, 0, 0) to the lamp
    E, s = illuminance_and_state([[3, 0, 0], [3, 1, 0]], [0, 0, 1], [lamp], [box])
    assert E[0] == 0.0 and s[0] == 2 and s[1] == 0
    r2 = 9 + 1 + 9
    dd = np.array([3, 1, -3]) / math.sqrt(r2)
    assert E[1] == pytest.approx(float(lamp.intensity_towards(dd[None])[0]) * (3 / math.sqrt(r2)) / r2, rel=1e-12)
    with pytest.raises(InvalidLightError, match="aim replaces"):
        PhotometricLight((0, 0, 3), spot, aim=(1, 0, 0), tilt=10)


def test_opening_light_carries_the_flux(tmp_path):
    ph = read_photometry(write(tmp_path, "o.ldt", ldt_text(1, 4, 19, [analytic(0, np.linspace(0, 180, 19))],
                                                           lum=(600.0, 300.0))))
    lamp = PhotometricLight((0, 0, 3), ph, multiplier=0.8)
    area = lamp.opening_light()
    assert area.flux == pytest.approx(0.8 * ph.flux(), rel=1e-12)
    assert area.normal_array.tolist() == pytest.approx([0, 0, -1])
    assert np.ptp(area.vertices_array[:, 0]) == pytest.approx(0.6)


# ----------------------------------------------------------------------------- malformed files


@pytest.mark.parametrize(
    ("name", "text", "match"),
    [
        ("a.ies", "IES:LM-63-2002\n[TEST] x\n1 1000 1 2 1 1 2 0 0 0\n", "TILT= line missing"),
        ("b.ies", ies_text([0, 90], [0], [[1, 1]]).replace(" 1000 ", " abc "), "line 6: lumens per lamp: not a number"),
        ("c.ies", ies_text([0, 90], [0], [[1, 1]], ptype=2), "photometric type: only type C"),
        ("d.ies", ies_text([0, 90], [0], [[1, 1]])[:-12], "the candela table needs"),
        ("e.ies", ies_text([0, 90], [0], [[1, -5]]), "candela must be finite and >= 0"),
        ("f.ies", ies_text([90, 0], [0], [[1, 1]]), "gamma_angles must increase"),
        ("g.ies", ies_text([0, 90], [0], [[1, 1]], tilt="INCLUDE"), "only TILT=NONE"),
        ("h.ies", ies_text([0, 90], [0, 30], [[1, 1], [1, 1]]), "c_angles must be one angle"),
        ("i.ldt", ldt_text(7, 4, 3, [[1, 1, 1]]), "line 3: Isym"),
        ("j.ldt", ldt_text(2, 4, 3, [[1, 1, 1], [1, 1, 1]]), "luminous intensities: Isym 2 stores 3 C planes"),
        ("k.ldt", ldt_text(1, 4, 3, [[1, 1, 1]], flux=0), "total luminous flux of lamps"),
        ("l.txt", "x", "unknown photometric format"),
        ("m.ies", ies_text([0, 90], [90, 270], [[1, 1], [1, 1]]), "horizontal angles 90 .. 270"),
    ],
)
def test_malformed_files_name_the_field(tmp_path, name, text, match):
    with pytest.raises(PhotometryFileError, match=match):
        read_photometry(write(tmp_path, name, text))


def rodrigues(axis, deg):
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    a = math.radians(deg)
    return np.eye(3) + math.sin(a) * K + (1 - math.cos(a)) * K @ K


@settings(max_examples=30, deadline=None)
@given(st.floats(0, 360), st.floats(0, 180), st.floats(-180, 180), st.floats(0, 180))
def test_luminaire_frame_follows_the_type_c_convention(c, g, rot, tilt):
    """C0 along local +x, C90 along +y, gamma from the nadir; rotation about world z, tilt about the C90 axis
    swinging the nadir towards C0 (rotations written here by Rodrigues' formula)."""
    G = np.linspace(0, 180, 19)
    Cs = np.arange(0, 361, 30.0)
    cc, gg = np.radians(Cs)[:, None], np.radians(G)[None, :]
    # one value at each pole (C is undefined there), as a measured table has
    ph = Photometry(Cs, G, (300 + 200 * np.cos(gg)) * (1 + np.sin(gg) * (0.3 * np.sin(cc) + 0.2 * np.cos(2 * cc))))
    lamp = PhotometricLight((0, 0, 0), ph, rotation=rot, tilt=tilt)
    cr, gr = math.radians(c), math.radians(g)
    local = np.array([math.sin(gr) * math.cos(cr), math.sin(gr) * math.sin(cr), -math.cos(gr)])
    # tilt: about the C90 axis (+y) taking the nadir (-z) towards C0 (+x); then the turn about world z
    world = rodrigues((0, 0, 1), rot) @ rodrigues((0, 1, 0), -tilt) @ local
    assert rodrigues((0, 1, 0), -90) @ np.array([0, 0, -1.0]) == pytest.approx([1, 0, 0], abs=1e-12)
    assert lamp.intensity_towards(world[None])[0] == pytest.approx(float(ph.intensity(c, g)), rel=1e-9, abs=1e-9)


def test_luminaires_and_area_sources_add_up_from_any_iterable():
    lamp = PhotometricLight((0, 0, 2), Photometry.isotropic(50.0))
    area = AreaLight([(-1, -1, 3), (-1, 1, 3), (1, 1, 3), (1, -1, 3)], 100.0)
    p = [[0.3, 0.2, 0.0]]
    both = illuminance(p, [0, 0, 1], (li for li in (lamp, area)))[0]
    assert both == pytest.approx(illuminance(p, [0, 0, 1], lamp)[0] + illuminance(p, [0, 0, 1], [area])[0], rel=1e-12)
    assert illuminance(p, [0, 0, 1], (li for li in [area]))[0] == illuminance(p, [0, 0, 1], area)[0]
    with pytest.raises(InvalidLightError):
        illuminance(p, [0, 0, 1], [lamp, "lamp"])


def test_round_openings_keep_their_area(tmp_path):
    # LM-63: an elliptical opening is marked by negative width and length (metres here)
    ph = read_photometry(write(tmp_path, "e.ies", ies_text([0, 90], [0], [[100, 100]], width=-0.2, length=-0.5)))
    assert ph.opening[:2] == pytest.approx((0.5, -0.2))
    area = PhotometricLight((0, 0, 3), ph, rotation=30).opening_light()
    assert area.area == pytest.approx(math.pi * 0.25 * 0.1, rel=1e-12)
    # EULUMDAT: a width of 0 marks a circle of diameter the length
    ph = read_photometry(write(tmp_path, "c.ldt", ldt_text(1, 4, 19, [analytic(0, np.linspace(0, 180, 19))],
                                                           lum=(300.0, 0.0))))
    assert PhotometricLight((0, 0, 3), ph).opening_light().area == pytest.approx(math.pi * 0.15**2, rel=1e-12)


def _slab(p, d, lo, hi):
    """t-interval of p + t d (t in [0, 1]) inside the box [lo, hi] (slab method), or None."""
    t0, t1 = 0.0, 1.0
    for k in range(3):
        if abs(d[k]) < 1e-300:
            if not lo[k] < p[k] < hi[k]:
                return None
            continue
        a, b = sorted(((lo[k] - p[k]) / d[k], (hi[k] - p[k]) / d[k]))
        t0, t1 = max(t0, a), min(t1, b)
    return (t0, t1) if t1 > t0 else None


@settings(max_examples=20, deadline=None)
@given(st.lists(st.tuples(st.floats(-3, 3), st.floats(-3, 3)), min_size=20, max_size=60))
def test_hard_shadows_of_a_csg_frame_against_a_slab_ray_test(xy):
    """A slab with a square hole (box minus box): lit exactly where the segment to the lamp misses the slab
    or passes through the hole (reference: the slab method on the two boxes, written here)."""
    lamp = PhotometricLight((0.3, 0.2, 3.0), Photometry.isotropic(100.0))
    outer_lo, outer_hi = np.array([-1.0, -1.0, 1.4]), np.array([1.0, 1.0, 1.6])
    hole_lo, hole_hi = np.array([-0.1, -0.3, 1.2]), np.array([0.5, 0.3, 1.8])
    frame = Box((0, 0, 1.5), (2, 2, 0.2)) - Box((0.2, 0, 1.5), (0.6, 0.6, 0.6))
    p = np.array([[x, y, 0.0] for x, y in xy])
    E, s = illuminance_and_state(p, [0, 0, 1], [lamp], [frame])
    for i, q in enumerate(p):
        d = np.array([0.3, 0.2, 3.0]) - q
        a = _slab(q, d, outer_lo, outer_hi)
        h = _slab(q, d, hole_lo, hole_hi)
        # ties (a segment through an edge of the hole, to 1e-6 of its parameter) are not judged
        if a is not None and h is not None and min(abs(a[0] - h[0]), abs(a[1] - h[1])) < 1e-6:
            continue
        blocked = a is not None and not (h is not None and h[0] <= a[0] and h[1] >= a[1])
        assert s[i] == (2 if blocked else 0)
        if not blocked:
            r = np.linalg.norm(d)
            assert E[i] == pytest.approx(100.0 * d[2] / r**3, rel=1e-12)


@pytest.mark.parametrize(("first", "version"), [("IESNA91\r\n", "LM-63-1991"), ("", "LM-63-1986")])
def test_older_ies_layouts(tmp_path, first, version):
    text = first + "[TEST] x\r\nTILT=NONE\r\n1 1000 1 3 1 1 2 0 0 0\r\n1 1 10\r\n0 45 90\r\n0\r\n100 80 0\r\n"
    ph = read_photometry(write(tmp_path, "old.ies", text))
    assert ph.file_format == version and float(ph.intensity(0, 22.5)) == pytest.approx(90.0)
    with pytest.raises(PhotometryFileError, match="line 1: unknown IES version"):
        read_photometry(write(tmp_path, "new.ies", text.replace(first, "IESNA:LM-63-2031\r\n") if first else
                              "IESNA:LM-63-2031\r\n" + text))
