"""Tests of rotorlyap.model.airfoil: cited NACA 23012 facts, full-range behaviour, linear model."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from rotorlyap.model.airfoil import NACA23012, Airfoil, LinearAirfoil, wrap_angle

DEG = math.pi / 180.0
MODELS = [NACA23012, dataclasses.replace(NACA23012, table_size=0)]
IDS = ["tabulated", "exact"]


def cl_of(af, a):
    return af.coefficients(np.asarray(a, dtype=float))[0]


@pytest.mark.parametrize("af", MODELS, ids=IDS)
def test_lift_slope_is_abbott_0p107_per_deg(af):
    """Attached-flow lift slope = 0.107 /deg (Abbott1959, NACA 23012, Re 6e6)."""
    slope = (cl_of(af, 6 * DEG) - cl_of(af, -4 * DEG)) / (10.0)
    assert slope == pytest.approx(0.107, rel=1e-6)


@pytest.mark.parametrize("af", MODELS, ids=IDS)
def test_zero_lift_angle_is_minus_1p2_deg(af):
    """alpha_L0 = -1.2 deg (Abbott1959)."""
    assert abs(cl_of(af, -1.2 * DEG)) < 1e-9


@pytest.mark.parametrize("af", MODELS, ids=IDS)
def test_maximum_and_minimum_lift_at_the_stall_angles(af):
    """cl_max = 1.79 reached at 18 deg (Abbott1959); cl_min = -1.2 at -15 deg (assumed); nowhere exceeded."""
    a = np.linspace(-math.pi, math.pi, 720001)
    cl = cl_of(af, a)
    assert cl.max() == pytest.approx(1.79, abs=1e-6)
    assert a[np.argmax(cl)] == pytest.approx(18 * DEG, abs=2e-4)
    assert cl.min() == pytest.approx(-1.20, abs=1e-6)
    assert a[np.argmin(cl)] == pytest.approx(-15 * DEG, abs=2e-4)


def test_lift_falls_after_stall():
    """Past the stall the lift decreases (negative slope): the ingredient of stall flutter."""
    cl = cl_of(NACA23012, np.array([18.0, 20.0, 22.0, 25.0]) * DEG)
    assert np.all(np.diff(cl) < 0)


def test_minimum_drag_and_moment_in_attached_flow():
    """cd_min = 0.006 at cl = 0.1 (Abbott1959); cm = cm_ac = -0.014 throughout attached flow."""
    a = np.linspace(-9, 17, 2601) * DEG
    cl, cd, cm = NACA23012.coefficients(a)
    assert cd.min() == pytest.approx(0.006, rel=1e-6)
    assert cl[np.argmin(cd)] == pytest.approx(0.1, abs=2e-3)
    assert np.allclose(cm, -0.014)


@pytest.mark.parametrize("af", MODELS, ids=IDS)
def test_coefficients_are_continuous_over_the_full_circle(af):
    """No jump larger than (max slope x step) on a fine grid over [-pi, pi], wrap-around included."""
    n = 200000
    a = np.linspace(-math.pi, math.pi, n + 1)
    h = 2 * math.pi / n
    for c in af.coefficients(a):
        jumps = np.abs(np.diff(c))
        assert jumps.max() < 7.0 * h  # |dc/dalpha| < 7 /rad everywhere (lift slope 6.13)
    # the first and last grid points are the same angle
    for c0, c1 in zip(af.coefficients(np.array([-math.pi])), af.coefficients(np.array([math.pi]))):
        assert c0 == pytest.approx(c1, abs=1e-12)


@pytest.mark.parametrize("af", MODELS, ids=IDS)
def test_coefficients_are_2pi_periodic(af):
    a = np.linspace(-3 * math.pi, 3 * math.pi, 1001)
    for c, c2 in zip(af.coefficients(a), af.coefficients(a + 2 * math.pi)):
        np.testing.assert_allclose(c, c2, atol=1e-9)
    # near +-pi from either side
    eps = 1e-7
    for c_lo, c_hi in zip(af.coefficients(math.pi - eps), af.coefficients(-math.pi + eps)):
        assert c_lo == pytest.approx(c_hi, abs=1e-5)


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_flat_plate_limit_at_90_deg(sign):
    """Broadside: cl = 0, cd = cd_max = 1.98 (Hoerner1965), normal force at mid-chord."""
    cl, cd, cm = NACA23012.coefficients(sign * math.pi / 2)
    assert abs(cl) < 1e-6
    assert cd == pytest.approx(1.98, abs=1e-6)
    assert cm == pytest.approx(-sign * 1.98 * (0.5 - NACA23012.aerodynamic_centre), abs=1e-5)
    a = np.linspace(60, 120, 61) * DEG * sign
    cl, cd, _ = NACA23012.coefficients(a)
    np.testing.assert_allclose(cd, 1.98 * np.sin(a) ** 2, atol=0.1)  # Viterna B2 cos(a) term
    np.testing.assert_allclose(cl, 1.98 * np.sin(a) * np.cos(a), atol=0.25)


def test_post_stall_follows_viterna_corrigan_from_the_stall_point():
    """Beyond the blend, cl and cd equal the Viterna-Corrigan (1982) formulas anchored at (18 deg, 1.79, cd_s)."""
    af = NACA23012
    a_s, cl_s = af.alpha_stall, af.cl_max
    cd_s = af.cd_min + af.drag_rise * (cl_s - af.cl_cd_min) ** 2
    b1 = af.cd_max
    a1 = b1 / 2
    a2 = (cl_s - b1 * math.sin(a_s) * math.cos(a_s)) * math.sin(a_s) / math.cos(a_s) ** 2
    b2 = (cd_s - b1 * math.sin(a_s) ** 2) / math.cos(a_s)
    a = np.array([25.0, 45.0, 70.0]) * DEG
    cl, cd, _ = af.coefficients(a)
    np.testing.assert_allclose(cl, a1 * np.sin(2 * a) + a2 * np.cos(a) ** 2 / np.sin(a), atol=1e-6)
    np.testing.assert_allclose(cd, b1 * np.sin(a) ** 2 + b2 * np.cos(a), atol=1e-6)


def test_reverse_flow_acts_as_a_plate_with_trailing_edge_leading():
    """Near 180 deg: low drag, lift slope a_r, camber lift towards the upper surface (cl < 0), a.c. at 3/4 chord."""
    af = dataclasses.replace(NACA23012, table_size=0)
    cl, cd, cm = af.coefficients(math.pi)
    assert cd == pytest.approx(af.reverse_cd_min + af.drag_rise * cl**2)
    assert cd < 0.02
    assert cl == pytest.approx(af.reverse_lift_slope * af.alpha_zero_lift)  # = a_r (0 - delta0) < 0
    cn = -cl  # cos(pi) = -1, sin(pi) = 0
    assert cn > 0
    assert cm == pytest.approx(-cn * (0.75 - af.aerodynamic_centre))
    d = 1 * DEG
    slope = (cl_of(af, -math.pi + d) - cl_of(af, math.pi - d)) / (2 * d)
    assert slope == pytest.approx(af.reverse_lift_slope, rel=1e-9)
    a = np.linspace(150, 210, 601) * DEG
    assert np.abs(cl_of(af, a)).max() <= 1.05  # bounded near the flat-plate value cd_max/2 = 0.99


def test_drag_is_positive_everywhere_and_at_most_cd_max():
    a = np.linspace(-math.pi, math.pi, 100001)
    cd = NACA23012.coefficients(a)[1]
    assert cd.min() > 0 and cd.max() <= 1.98 + 1e-9


def test_table_interpolation_matches_exact_model():
    rng = np.random.default_rng(0)
    a = rng.uniform(-4, 4, 200000)
    exact = dataclasses.replace(NACA23012, table_size=0)
    for c_t, c_e in zip(NACA23012.coefficients(a), exact.coefficients(a)):
        assert np.max(np.abs(c_t - c_e)) < 1e-5


@pytest.mark.parametrize("shape", [(), (7,), (3, 4, 5)])
def test_coefficients_are_vectorised_over_any_shape(shape):
    a = np.full(shape, 0.1)
    for af in (NACA23012, LinearAirfoil()):
        for c in af.coefficients(a):
            assert np.shape(c) == shape
    assert np.shape(NACA23012.coefficients(0.1)[0]) == ()


def test_linear_airfoil_closed_form():
    """LinearAirfoil: cl = a alpha, cd = cd0, cm = 0 (thin-airfoil a = 2 pi by default)."""
    af = LinearAirfoil(lift_slope=5.7, cd0=0.01)
    a = np.linspace(-0.3, 0.3, 13)
    cl, cd, cm = af.coefficients(a)
    np.testing.assert_allclose(cl, 5.7 * a, rtol=1e-15)
    assert np.all(cd == 0.01) and np.all(cm == 0.0)
    assert LinearAirfoil().lift_slope == 2 * math.pi
    assert LinearAirfoil().coefficients(2 * math.pi + 0.1)[0] == pytest.approx(2 * math.pi * 0.1)


# ---------------------------------------------------------------- LinearAirfoil in reverse flow

def _plate_force(af, w_y, w_z):
    """Force (F_y, F_z) per unit qn of the blade's strip formula (rotorlyap.model.aero) on ``af``."""
    alpha = np.arctan2(w_z, -w_y)
    cl, cd, _ = af.coefficients(alpha)
    speed = np.hypot(w_y, w_z)
    return speed * (cd * w_y + cl * w_z), speed * (cd * w_z - cl * w_y)


def test_linear_airfoil_flow_angle_is_the_angle_to_the_chord_line():
    """alpha' is the angle between the flow and the chord *line*: |alpha'| <= 90 deg and
    tan(alpha') = tan(alpha) (the same line, whichever edge the flow meets first), on any turn."""
    a = np.linspace(-3 * math.pi, 3 * math.pi, 20001)
    a = a[np.abs(np.cos(a)) > 1e-9]  # tan undefined at +-90 deg
    ap = LinearAirfoil.flow_angle(a)
    assert np.all(np.abs(ap) <= 0.5 * math.pi)
    np.testing.assert_allclose(np.tan(ap), np.tan(a), rtol=1e-9, atol=1e-9)
    # forward flow unchanged; reverse flow measured from the trailing edge
    assert LinearAirfoil.flow_angle(0.2) == pytest.approx(0.2, abs=1e-15)
    assert LinearAirfoil.flow_angle(math.pi - 0.2) == pytest.approx(-0.2, abs=1e-12)
    assert LinearAirfoil.flow_angle(-math.pi + 0.2) == pytest.approx(0.2, abs=1e-12)


def test_linear_airfoil_lift_has_period_pi_like_a_symmetric_plate():
    """A thin symmetric plate looks the same to a flow turned by 180 deg, so cl(alpha + pi) =
    cl(alpha) (the flat plate's cl = cd_max sin a cos a has period pi too), and cl is odd."""
    af = LinearAirfoil(lift_slope=5.7, cd0=0.01)
    a = np.linspace(-0.5 * math.pi + 1e-6, 0.5 * math.pi - 1e-6, 1001)
    np.testing.assert_allclose(cl_of(af, a + math.pi), cl_of(af, a), rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(cl_of(af, a - math.pi), cl_of(af, a), rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(cl_of(af, -a), -cl_of(af, a), rtol=1e-12, atol=1e-15)
    # so the reverse-flow lift is bounded by the forward one, not a pi (the wrapped-angle error)
    full = np.linspace(-math.pi, math.pi, 10001)
    assert np.max(np.abs(cl_of(af, full))) <= 5.7 * 0.5 * math.pi * (1 + 1e-12)


@pytest.mark.parametrize("eps", [0.02, 0.1])
def test_linear_airfoil_air_from_below_pushes_a_plate_up_whichever_edge_leads(eps):
    """Air coming from below at a small angle eps pushes a flat plate upwards (F_z > 0) with the
    leading edge first (w_y < 0) and with the trailing edge first (w_y > 0), with the same thin-
    airfoil force a eps V^2 (small angle); air from above pushes it down. Blade formula:
    alpha = atan2(w_z, -w_y), F_z = qn (cd w_z - cl w_y)."""
    af = LinearAirfoil(lift_slope=2 * math.pi, cd0=0.0)
    V = 3.0
    for sign in (+1.0, -1.0):  # air from below (+) or from above (-)
        w_z = sign * V * math.sin(eps)
        for w_y in (-V * math.cos(eps), V * math.cos(eps)):  # forward, reverse flow
            _, Fz = _plate_force(af, w_y, w_z)
            assert np.sign(Fz) == sign
            assert float(Fz) == pytest.approx(sign * 2 * math.pi * eps * V * V * math.cos(eps), rel=1e-12)


def test_linear_airfoil_symmetric_full_range_airfoil_agrees_in_both_linear_ranges():
    """LinearAirfoil is the thin-airfoil limit of the full-range Airfoil's treatment of reverse
    flow: for a symmetric section (zero camber, equal reverse slope) both give the same cl on
    the attached part of either edge's lift curve."""
    a = 2 * math.pi
    sym = Airfoil(lift_slope=a, alpha_zero_lift=0.0, cl_max=1.5, alpha_stall=16 * DEG, cl_min=-1.5,
                  alpha_stall_negative=-16 * DEG, cd_min=0.006, cl_cd_min=0.0, drag_rise=0.01, cm_ac=0.0,
                  aerodynamic_centre=0.25, reverse_lift_slope=a, reverse_stall_angle=8 * DEG, table_size=0)
    lin = LinearAirfoil(lift_slope=a)
    fwd = np.linspace(-10 * DEG, 10 * DEG, 41)  # below the rounding into stall (11.4 deg)
    rev = np.linspace(-3.9 * DEG, 3.9 * DEG, 41)  # reverse branch linear over half its 8 deg stall range
    for al in (fwd, math.pi + rev[rev < 0], -math.pi + rev[rev > 0]):
        np.testing.assert_allclose(cl_of(lin, al), cl_of(sym, al), rtol=1e-12, atol=1e-12)


def test_linear_airfoil_cl_jumps_at_90_deg_but_the_normal_force_is_continuous():
    """At |alpha| = 90 deg the flow meets the section broadside: cl jumps between +-a pi/2, but the
    chordwise speed w_y is zero there, so F_z = qn (cd w_z - cl w_y) is continuous (-> cd0 V^2)
    while F_y = qn (cd w_y + cl w_z) jumps by 2 (a pi/2) V^2."""
    a, cd0, V = 5.7, 0.02, 2.0
    af = LinearAirfoil(lift_slope=a, cd0=cd0)
    for side in (+1.0, -1.0):  # alpha = +90 deg (air from below), -90 deg (air from above)
        d = 1e-7
        before = side * (0.5 * math.pi - d)  # forward flow
        after = side * (0.5 * math.pi + d)  # reverse flow
        assert float(cl_of(af, before)) == pytest.approx(side * a * 0.5 * math.pi, rel=1e-6)
        assert float(cl_of(af, after)) == pytest.approx(-side * a * 0.5 * math.pi, rel=1e-6)
        Fy0, Fz0 = _plate_force(af, -V * math.cos(before), V * math.sin(before))
        Fy1, Fz1 = _plate_force(af, -V * math.cos(after), V * math.sin(after))
        assert float(Fz1 - Fz0) == pytest.approx(0.0, abs=1e-5)
        assert float(Fz0) == pytest.approx(side * cd0 * V * V, abs=1e-5)
        assert float(Fy0 - Fy1) == pytest.approx(2 * a * 0.5 * math.pi * V * V, rel=1e-6)


def test_wrap_angle_range():
    a = wrap_angle(np.array([-math.pi, math.pi, 3 * math.pi / 2, -7.0]))
    assert np.all((a >= -math.pi) & (a < math.pi))
    np.testing.assert_allclose(np.cos(a), np.cos([-math.pi, math.pi, 3 * math.pi / 2, -7.0]), atol=1e-15)


def test_every_naca23012_number_has_a_source():
    from rotorlyap.model.airfoil import NACA23012_SOURCES

    cited = {f.name for f in dataclasses.fields(Airfoil) if f.init and f.name not in ("name", "table_size")}
    assert set(NACA23012_SOURCES) == cited
    for src in NACA23012_SOURCES.values():
        assert any(k in src for k in ("Abbott1959", "Hoerner1965", "ViternaCorrigan1982", "assumed"))


BAD = [
    (dict(lift_slope=0.0), ValueError, r"lift_slope must be > 0 1/rad, got 0.0"),
    (dict(lift_slope=float("nan")), ValueError, r"lift_slope must be finite"),
    (dict(lift_slope="6"), TypeError, r"lift_slope must be a real number"),
    (dict(cl_max=-1.0), ValueError, r"cl_max must be > 0"),
    (dict(cl_min=0.5), ValueError, r"cl_min must be < 0"),
    (dict(alpha_stall=1.0), ValueError, r"alpha_stall must lie in \(0, 45 deg\)"),
    (dict(alpha_stall=10 * DEG), ValueError, r"alpha_stall must exceed alpha_zero_lift \+ cl_max/lift_slope"),
    (dict(alpha_stall_negative=-5 * DEG), ValueError, r"alpha_stall_negative must be below"),
    (dict(cd_min=0.0), ValueError, r"cd_min must be > 0"),
    (dict(drag_rise=-0.1), ValueError, r"drag_rise must be >= 0"),
    (dict(aerodynamic_centre=1.2), ValueError, r"aerodynamic_centre must lie in \[0, 1\]"),
    (dict(cd_max=0.001), ValueError, r"cd_max must exceed cd_min"),
    (dict(stall_blend=0.0), ValueError, r"stall_blend must lie in"),
    (dict(reverse_stall_angle=1.0), ValueError, r"reverse_stall_angle must lie in"),
    (dict(reverse_lift_slope=-1.0), ValueError, r"reverse_lift_slope must be > 0"),
    (dict(alpha_zero_lift=0.5), ValueError, r"alpha_zero_lift must lie within"),
    (dict(table_size=10), ValueError, r"table_size must be 0 \(exact evaluation\) or >= 1024, got 10"),
    (dict(table_size=1024.0), TypeError, r"table_size must be an int"),
    (dict(name=3), TypeError, r"name must be a str"),
]


@pytest.mark.parametrize("kw, exc, match", BAD, ids=[next(iter(k)) + "=" + repr(next(iter(k.values()))) for k, _, _ in BAD])
def test_invalid_airfoil_parameters_are_rejected(kw, exc, match):
    with pytest.raises(exc, match=match):
        dataclasses.replace(NACA23012, **kw)


@pytest.mark.parametrize("kw, exc, match", [
    (dict(lift_slope=0.0), ValueError, r"lift_slope must be > 0"),
    (dict(cd0=-0.01), ValueError, r"cd0 must be >= 0"),
    (dict(cd0=float("inf")), ValueError, r"cd0 must be finite"),
    (dict(lift_slope=None), TypeError, r"lift_slope must be a real number"),
])
def test_invalid_linear_airfoil_is_rejected(kw, exc, match):
    with pytest.raises(exc, match=match):
        LinearAirfoil(**kw)
