"""Tests of rotorlyap.model.parameters: Table I, the omitted data and validation."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from rotorlyap.model.airfoil import NACA23012, LinearAirfoil
from rotorlyap.model.parameters import (
    CG_POSITIONS,
    FIELD_INFO,
    TABLE_I_AIRFOIL,
    BladeParameters,
    parameter_table,
)


def test_table_i_values_are_reproduced(forward):
    """Every Table I datum (READING.md, realigned) is the table_i value, in SI units."""
    assert forward.radius == 7.85
    assert forward.blade_length == 6.772
    assert forward.hub_elements == (0.01, -0.005, 0.02, 0.03, 0.0)
    assert forward.chord == 0.4
    assert forward.pitch_flap_coupling == -0.4
    assert forward.rotor_speed == 28.35
    assert forward.twist == 0.0
    assert forward.pitch_stiffness == 6304.0  # 6.304 kNm/rad
    assert forward.lag_damping == 10000.0  # 10.0 kNms/rad
    assert forward.aerodynamic_centre == 0.235


@pytest.mark.parametrize("cg, x", [("forward", 0.215), ("neutral", 0.235), ("backward", 0.255)])
def test_table_i_three_cg_positions_are_0p02c_about_the_aerodynamic_centre(cg, x):
    """Cases I-III: C.G. 0.02c ahead of, at, and 0.02c behind the Table I aerodynamic centre."""
    q = BladeParameters.table_i(cg)
    assert q.cg_position == pytest.approx(x)
    assert q.cg_position - q.aerodynamic_centre == pytest.approx(
        {"forward": -0.02, "neutral": 0.0, "backward": 0.02}[cg])
    assert CG_POSITIONS[cg] == x


def test_default_construction_is_the_forward_cg_case_with_a_skew_dependent_inflow(forward):
    """The defaults are the Table I blade, forward C.G.; only the inflow differs: the paper's
    Glauert in table_i(), Pitt-Peters (k_x = 0 in hover, growing with the wake skew) by default."""
    assert BladeParameters() == dataclasses.replace(forward, inflow_model="pitt-peters")
    assert forward.inflow_model == "glauert"


def test_flight_case_is_table_i_with_the_reports_forward_flight_models():
    q = BladeParameters.flight_case("backward")
    assert (q.inflow_model, q.compressibility) == ("pitt-peters", "prandtl-glauert")
    assert dataclasses.replace(q, inflow_model="glauert", compressibility="none") == BladeParameters.table_i("backward")


def test_table_i_unknown_cg_name_is_rejected_listing_allowed_names():
    with pytest.raises(ValueError, match=r"cg must be one of \('forward', 'neutral', 'backward'\), got 'middle'"):
        BladeParameters.table_i("middle")


def test_table_i_accepts_overrides():
    q = BladeParameters.table_i("backward", air_density=0.0, gravity=0.0)
    assert q.air_density == 0.0 and q.gravity == 0.0 and q.cg_position == 0.255


def test_lock_number_is_about_8(forward):
    """gamma = rho a c R^4 / I_beta is close to 8, a typical articulated-rotor value (the design choice)."""
    assert 7.8 < forward.lock_number < 8.3


def test_flap_inertia_equals_closed_form_of_the_uniform_blade(forward):
    """I_beta = m/3 [(R - e)^3 - (R - R1 - e)^3] for a uniform blade from R - R1 to R, hinge at e = e1 R1."""
    e = 0.01 * 6.772
    closed = forward.mass_per_length / 3.0 * ((7.85 - e) ** 3 - (7.85 - 6.772 - e) ** 3)
    assert forward.flap_inertia == pytest.approx(closed, rel=1e-12)
    assert forward.blade_mass == pytest.approx(forward.mass_per_length * 6.772, rel=1e-12)


def test_lock_number_uses_the_airfoil_lift_slope(forward):
    q = dataclasses.replace(forward, airfoil=LinearAirfoil(lift_slope=2 * math.pi))
    assert q.lock_number / forward.lock_number == pytest.approx(2 * math.pi / TABLE_I_AIRFOIL.lift_slope)


def test_hub_element_lengths_and_root_cutout_in_metres(forward):
    assert forward.hub_element_lengths == pytest.approx((0.06772, -0.03386, 0.13544, 0.20316, 0.0))
    assert forward.root_cutout == pytest.approx(1.078)
    assert forward.root_r_over_R == pytest.approx(1.078 / 7.85)
    assert forward.flap_hinge_offset == pytest.approx(0.06772)
    assert forward.pitch_hinge_radius == pytest.approx(0.06 * 6.772)
    assert forward.tip_speed == pytest.approx(28.35 * 7.85)


def test_solidity_and_weight(forward):
    assert forward.solidity == pytest.approx(4 * 0.4 / (math.pi * 7.85))
    assert forward.weight == pytest.approx(6400 * 9.80665)


def test_stations_integrate_over_the_aerodynamic_span(forward):
    """Gauss-Legendre weights sum to R1/R and integrate r^3 exactly."""
    r, w = forward.stations()
    assert r.shape == w.shape == (12,)
    assert np.all((r > forward.root_r_over_R) & (r < 1.0))
    assert w.sum() == pytest.approx(6.772 / 7.85)
    a = forward.root_r_over_R
    assert np.sum(w * r**3) == pytest.approx((1 - a**4) / 4)


def test_spanwise_profiles_accept_floats_and_callables(forward):
    x = np.array([[0.2, 0.5], [0.8, 1.0]])
    assert forward.chord_at(x).shape == (2, 2) and np.all(forward.chord_at(x) == 0.4)
    q = dataclasses.replace(forward, chord=lambda r: 0.5 - 0.1 * r, mass_per_length=lambda r: 10.0 + 0 * r)
    assert q.chord_at(1.0) == pytest.approx(0.4)
    assert q.chord_at(x).shape == (2, 2)
    assert q.blade_mass == pytest.approx(67.72)
    assert np.all(q.cg_position_at(x) == 0.215)
    assert np.all(q.aerodynamic_centre_at(x) == 0.235)
    assert np.all(q.mass_per_length_at(x) == 10.0)


def test_replace_gives_a_variant_and_revalidates(forward):
    q = dataclasses.replace(forward, air_density=1.0)
    assert q.air_density == 1.0 and forward.air_density == 1.225
    with pytest.raises(ValueError, match="air_density must be >= 0, got -1.0"):
        dataclasses.replace(forward, air_density=-1.0)


def test_parameters_are_frozen_and_hashable(forward):
    with pytest.raises(dataclasses.FrozenInstanceError):
        forward.radius = 8.0  # type: ignore[misc]
    assert hash(forward) == hash(BladeParameters.table_i("forward"))


def test_ints_are_normalised_to_floats_and_lists_to_tuples():
    q = BladeParameters(radius=8, hub_elements=[0.01, 0, 0.02, 0.03, 0])
    assert isinstance(q.radius, float)
    assert q.hub_elements == (0.01, 0.0, 0.02, 0.03, 0.0)


def test_vacuum_and_no_gravity_are_allowed():
    q = BladeParameters(air_density=0.0, gravity=0.0)
    assert q.lock_number == 0.0


def test_default_airfoil_is_naca23012_with_table_i_aerodynamic_centre(forward):
    assert forward.airfoil.name == "NACA 23012"
    assert forward.airfoil.aerodynamic_centre == 0.235
    assert forward.airfoil.lift_slope == NACA23012.lift_slope


def test_parameter_table_lists_every_field_with_unit_and_source(forward):
    rows = parameter_table(forward)
    names = [f.name for f in dataclasses.fields(forward)]
    assert [r[0] for r in rows] == names
    assert set(FIELD_INFO) == set(names)
    for name, value, unit, source in rows:
        assert unit and source
        assert source.startswith(("Table I", "assumed", "paper")), (name, source)
    table_i_fields = {r[0] for r in rows if r[3].startswith("Table I")}
    assert {"radius", "blade_length", "chord", "rotor_speed", "pitch_stiffness", "lag_damping"} <= table_i_fields
    assert dict((r[0], r[1]) for r in rows)["airfoil"] == "NACA 23012"


# ---------------------------------------------------------------- validation errors
BAD_VALUES = [
    # (field, value, exception, message regex)
    ("radius", 0.0, ValueError, r"radius must be > 0, got 0.0"),
    ("radius", -7.85, ValueError, r"radius must be > 0, got -7.85"),
    ("blade_length", -1.0, ValueError, r"blade_length must be > 0, got -1.0"),
    ("blade_length", 9.0, ValueError, r"blade_length must be <= radius = 7.85 m .*got 9.0"),
    ("blade_length", 7.85, ValueError, r"the pitch hinge at \(e1 \+ e3 \+ e4\) R1 = .* lies outboard of the blade root"),
    ("rotor_speed", 0.0, ValueError, r"rotor_speed must be > 0, got 0.0"),
    ("helicopter_mass", -1.0, ValueError, r"helicopter_mass must be > 0, got -1.0"),
    ("pitch_radius_of_gyration", 0.0, ValueError, r"pitch_radius_of_gyration must be > 0"),
    ("chord", 0.0, ValueError, r"chord must be > 0 on the span, got 0.0"),
    ("chord", -0.4, ValueError, r"chord must be > 0 on the span"),
    ("mass_per_length", 0.0, ValueError, r"mass_per_length must be > 0 on the span, got 0.0"),
    ("air_density", -1.225, ValueError, r"air_density must be >= 0, got -1.225"),
    ("gravity", -9.81, ValueError, r"gravity must be >= 0, got -9.81"),
    ("pitch_stiffness", -1.0, ValueError, r"pitch_stiffness must be >= 0, got -1.0"),
    ("flap_stiffness", -1.0, ValueError, r"flap_stiffness must be >= 0"),
    ("lag_stiffness", -1.0, ValueError, r"lag_stiffness must be >= 0"),
    ("lag_damping", -10.0, ValueError, r"lag_damping must be >= 0, got -10.0"),
    ("flap_damping", -1.0, ValueError, r"flap_damping must be >= 0"),
    ("pitch_damping", -1.0, ValueError, r"pitch_damping must be >= 0"),
    ("radius", float("nan"), ValueError, r"radius must be finite \(> 0\), got nan"),
    ("air_density", float("inf"), ValueError, r"air_density must be finite"),
    ("twist", float("nan"), ValueError, r"twist must be finite"),
    ("pitch_flap_coupling", float("-inf"), ValueError, r"pitch_flap_coupling must be finite"),
    ("cyclic_cos", float("nan"), ValueError, r"cyclic_cos must be finite"),
    ("collective", float("nan"), ValueError, r"collective must be finite \(None or a finite value\)"),
    ("inflow_ratio", -0.01, ValueError, r"inflow_ratio must be None or >= 0, got -0.01"),
    ("inflow_ratio", float("nan"), ValueError, r"inflow_ratio must be finite"),
    ("hub_elements", (0.01, 0.0, 0.02), ValueError, r"hub_elements must have 5 entries \(e1..e5\), got 3"),
    ("hub_elements", (0.01, 0.0, 0.02, float("nan"), 0.0), ValueError, r"hub_elements\[3\] \(e4\) must be finite"),
    ("hub_elements", (-0.01, 0.0, 0.02, 0.03, 0.0), ValueError, r"hub_elements\[0\] \(e1, radial\) must be >= 0"),
    ("hub_elements", (0.1, 0.0, 0.1, 0.1, 0.0), ValueError, r"pitch hinge .* lies outboard of the blade root"),
    ("hub_elements", 0.01, TypeError, r"hub_elements must be a sequence of 5 real numbers"),
    ("hub_elements", (0.01, "a", 0.02, 0.03, 0.0), TypeError, r"hub_elements\[1\] \(e2\) must be a real number"),
    ("pitch_axis", 1.2, ValueError, r"pitch_axis must lie in \[0, 1\] .*got 1.2"),
    ("cm_pitch_rate", 0.5, ValueError, r"cm_pitch_rate must be <= 0 \(a damping derivative.*got 0.5"),
    ("cm_pitch_rate", float("nan"), ValueError, r"cm_pitch_rate must be finite"),
    ("cm_pitch_rate", "-pi/2", TypeError, r"cm_pitch_rate must be a real number"),
    ("cg_position", -0.1, ValueError, r"cg_position must lie in \[0, 1\] .*got -0.1"),
    ("aerodynamic_centre", 1.5, ValueError, r"aerodynamic_centre must lie in \[0, 1\]"),
    ("inflow_model", "vortex", ValueError, r"inflow_model must be one of \('uniform', 'glauert', 'drees', "
                                           r"'pitt-peters', 'coleman'\), got 'vortex'"),
    ("inflow_model", 3, TypeError, r"inflow_model must be a str"),
    ("airfoil", "NACA 23012", TypeError, r"airfoil must be an Airfoil, a LinearAirfoil or an object with a "
                                         r"coefficients\(alpha\) method"),
    ("n_blades", 0, ValueError, r"n_blades must be an int >= 1, got 0"),
    ("n_blades", 4.0, TypeError, r"n_blades must be an int >= 1, got 4.0 of type float"),
    ("n_stations", 0, ValueError, r"n_stations must be an int >= 1, got 0"),
    ("n_stations", True, TypeError, r"n_stations must be an int"),
    ("radius", "7.85", TypeError, r"radius must be a real number \(> 0\), got '7.85' of type str"),
    ("radius", True, TypeError, r"radius must be a real number"),
    ("air_density", 1 + 0j, TypeError, r"air_density must be a real number"),
    ("chord", lambda r: 0.4 - r, ValueError, r"chord must be > 0 on the span"),
    ("chord", lambda r: r / 0.0, ValueError, r"chord must be finite on the span"),
    ("cg_position", lambda r: 2.0 * r, ValueError, r"cg_position must lie in \[0, 1\]"),
    ("mass_per_length", lambda r: [1, 2, 3], ValueError, r"mass_per_length: callable f\(r_over_R\) failed"),
]


@pytest.mark.parametrize("field, value, exc, match", BAD_VALUES,
                         ids=[f"{f}={'callable' if callable(v) else repr(v)}-{k}" for k, (f, v, _, _) in enumerate(BAD_VALUES)])
def test_invalid_parameter_is_rejected_naming_field_value_and_allowed_range(field, value, exc, match):
    with np.errstate(all="ignore"):
        with pytest.raises(exc, match=match):
            BladeParameters(**{field: value})


def test_duck_typed_airfoil_is_accepted():
    class Flat:
        def coefficients(self, alpha):
            a = np.asarray(alpha)
            return 1.98 * np.sin(a) * np.cos(a), 1.98 * np.sin(a) ** 2, 0 * a

    q = BladeParameters(airfoil=Flat())
    assert q.lift_slope == pytest.approx(1.98, rel=1e-3)


@pytest.mark.parametrize("changes, match", [
    (dict(rotor_speed=258.0), r"tip speed of 2025 m/s, 5\.95 times.*if 258\.0 is in rpm, give 27\.02 rad/s"),
    (dict(twist=-18.0), r"twist = -18\.0 rad is -1031 deg.*if -18\.0 is in degrees, give -0\.3142 rad"),
])
def test_unit_slips_are_refused_with_the_likely_mistake(changes, match):
    """A rotor speed in rpm (a tip faster than sound) or a pretwist in degrees (beyond 40 deg) is
    refused with the allowed range and the value it probably should have been."""
    with pytest.raises(ValueError, match=match):
        BladeParameters(**changes)


def test_the_largest_plausible_values_pass():
    """A tip just subsonic and a 34 deg pretwist are accepted (the checks catch unit slips only)."""
    BladeParameters(rotor_speed=0.99 * 340.294 / 7.85, twist=-0.6)


def test_gauss_legendre_rules_are_numpys_computed_once_and_read_only():
    """The cached rule is numpy's (nodes and weights to the bit), the same arrays on each call,
    and cannot be changed in place by a caller (which would change every later blade)."""
    from rotorlyap.model.parameters import gauss_legendre

    x, w = gauss_legendre(16)
    x_np, w_np = np.polynomial.legendre.leggauss(16)
    assert np.array_equal(x, x_np) and np.array_equal(w, w_np)
    assert gauss_legendre(16)[0] is x
    with pytest.raises(ValueError):
        x[0] = 0.0
