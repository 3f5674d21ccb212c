"""Checks of rotorlyap.model.modes: the derived quantities against independent facts.

Each test names the fact it checks.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from rotorlyap.model._generated import blade_model as gen
from rotorlyap.model.blade import Blade
from rotorlyap.conventions import HINGES
from rotorlyap.model.modes import (
    chord_pitch_to_hub_plane,
    chordwise_lag_offset_angle,
    derived_quantities,
    modes_from_jacobian,
)
from rotorlyap.model.parameters import BladeParameters
from rotorlyap.model.trim import hover_trim


@pytest.fixture(scope="module", params=["forward", "neutral", "backward"])
def case(request):
    p = BladeParameters.table_i(request.param)
    return request.param, p, derived_quantities(p)


@pytest.fixture(scope="module")
def forward():
    p = BladeParameters.table_i("forward")
    return p, derived_quantities(p)


def _uniform_flap_inertia(p: BladeParameters) -> float:
    """int_{R-R1}^{R} m (r - e)^2 dr for the uniform blade, in closed form."""
    e = p.hub_elements[0] * p.blade_length
    return p.mass_per_length * ((p.radius - e) ** 3 - (p.radius - p.blade_length - e) ** 3) / 3.0


def test_lock_number_equals_rho_a_c_R4_over_flap_inertia_computed_independently(forward):
    p, d = forward
    I_beta = _uniform_flap_inertia(p)
    gamma = p.air_density * p.airfoil.lift_slope * p.chord * p.radius ** 4 / I_beta
    assert d.flap_inertia == pytest.approx(I_beta, rel=1e-12)
    assert d.lock_number == pytest.approx(gamma, rel=1e-12)
    assert 7.5 < d.lock_number < 8.5  # the chosen blade mass targets a Lock number near 8


def test_blade_mass_is_mass_per_length_times_blade_length(forward):
    p, d = forward
    assert d.blade_mass == pytest.approx(p.mass_per_length * p.blade_length, rel=1e-12)


def test_solidity_is_n_c_over_pi_R(forward):
    p, d = forward
    assert d.solidity == pytest.approx(p.n_blades * p.chord / (math.pi * p.radius), rel=1e-14)


def test_hover_thrust_coefficient_is_weight_over_rho_pi_R2_tip_speed_squared(case):
    _, p, d = case
    ct = p.helicopter_mass * p.gravity / (p.air_density * math.pi * p.radius ** 2
                                          * (p.rotor_speed * p.radius) ** 2)
    assert d.thrust == pytest.approx(p.helicopter_mass * p.gravity, rel=1e-9)
    assert d.thrust_coefficient == pytest.approx(ct, rel=1e-9)
    assert d.ct_over_sigma == pytest.approx(ct / d.solidity, rel=1e-9)


def test_hover_inflow_is_momentum_theory_sqrt_ct_over_2(forward):
    _, d = forward
    assert d.inflow_ratio == pytest.approx(math.sqrt(d.thrust_coefficient / 2.0), rel=1e-9)


def test_collective_and_equilibrium_are_those_of_the_hover_trim(case):
    _, p, d = case
    trim = hover_trim(p)
    assert d.collective == trim.collective
    np.testing.assert_allclose(d.equilibrium, trim.equilibrium[:3], rtol=0, atol=1e-12)


def test_forward_cg_needs_more_collective_for_the_same_blade_pitch():
    """A C.G. ahead of the pitch axis gives a nose-down centrifugal moment on the coned blade,
    which the pitch spring must hold: more collective, same blade pitch at the hinge."""
    d = {cg: derived_quantities(BladeParameters.table_i(cg)) for cg in ("forward", "neutral", "backward")}
    assert d["forward"].collective > d["neutral"].collective > d["backward"].collective
    pitches = [d[cg].equilibrium[2] for cg in d]
    assert max(pitches) - min(pitches) < math.radians(0.05)


def test_chord_pitch_formula_matches_the_generated_direction_cosines():
    """asin(y_B . z_H) from the hand formula equals the generated C_BH entry (frames check)."""
    rng = np.random.default_rng(3)
    P = Blade(BladeParameters.table_i("forward", collective=0.1)).parameter_values
    for b, z, t in rng.uniform(-0.4, 0.4, (5, 3)):
        C = gen.rhs_terms(b, z, t, 0.0, 0.0, 0.0, 0.0, P)[33:42]  # C_BH row-major
        assert chord_pitch_to_hub_plane(b, z, t) == pytest.approx(math.asin(C[5]), abs=1e-13)


def test_coned_and_lagged_blade_has_its_chord_pitched_up_by_about_beta_zeta(forward):
    _, d = forward
    beta, zeta, theta = d.equilibrium
    assert d.chord_pitch - theta == pytest.approx(beta * zeta, rel=0.05)
    assert d.chord_pitch > theta


def test_vacuum_frequencies_match_the_closed_forms(case):
    """Flap nu^2 = 1 + e S/I, lag nu^2 = e S/I (undamped, |s| of the damped pair) and the lag
    decay C/(2 I Omega) to 1e-4; pitch nu^2 = K/(I Omega^2) + propeller term to 1e-3 plus an
    error quadratic in the C.G. offset d from the pitch axis, 12 (d/c)^2 (the product of inertia
    int x y dm ~ d couples pitch inertially to flap, which the one-hinge formula leaves out,
    and shifts the frequency by a term of second order in it)."""
    cg, _, d = case
    cf = d.closed_forms
    (flap,) = d.modes("flap", air=False)
    (lag,) = d.modes("lag", air=False)
    (pitch,) = d.modes("pitch", air=False)
    assert flap.frequency == pytest.approx(cf.flap_frequency, rel=1e-4)
    assert abs(flap.growth_rate) < 1e-4
    assert lag.natural_frequency == pytest.approx(cf.lag_frequency, rel=1e-4)
    assert -lag.growth_rate == pytest.approx(cf.lag_decay_rate, rel=1e-4)
    d = BladeParameters.table_i(cg).cg_position - BladeParameters.table_i(cg).pitch_axis
    assert pitch.frequency == pytest.approx(cf.pitch_frequency, rel=1e-3 + 12.0 * d * d)


def test_vacuum_modes_are_one_per_hinge_and_nearly_uncoupled(case):
    _, _, d = case
    assert [m.dominant_hinge for m in d.vacuum_modes] == list(HINGES)
    lag = d.modes("lag", air=False)[0]
    assert max(lag.shape[0], lag.shape[2]) < 0.01


def test_vacuum_flap_mode_carries_pitch_following_the_pitch_flap_coupling(forward):
    """In the flap mode the stiff pitch spring stays unstrained, so theta = -tan(delta3) beta."""
    p, d = forward
    (flap,) = d.modes("flap", air=False)
    assert flap.shape[2] == pytest.approx(-p.pitch_flap_coupling, rel=0.01)


def test_closed_form_frequencies_are_in_the_usual_articulated_rotor_ranges(forward):
    _, d = forward
    cf = d.closed_forms
    assert 1.0 < cf.flap_frequency < 1.05
    assert 0.15 < cf.lag_frequency < 0.35
    assert 3.0 < cf.pitch_frequency < 6.0


def test_table_i_hover_is_stable_and_less_so_as_the_cg_moves_aft():
    """The paper's hover claims (Figs 5 and 8): every Table I case is stable in hover, and the
    stability decreases as the C.G. moves aft (slowest decay and pitch-mode damping both
    fall); without the aerodynamic pitch damping (cm_q = 0) the C.G. behind the aerodynamic
    centre flutters in pitch, the classical pitch-flap flutter condition."""
    cases = ("forward", "neutral", "backward")
    d = {cg: derived_quantities(BladeParameters.table_i(cg)) for cg in cases}
    assert all(not d[cg].unstable_air_modes for cg in cases)
    slowest = [max(m.growth_rate for m in d[cg].air_modes) for cg in cases]
    pitch = [max(m.growth_rate for m in d[cg].air_modes if m.dominant_hinge == "pitch" and m.oscillatory)
             for cg in cases]
    assert slowest[0] < slowest[1] < slowest[2] < 0.0
    assert pitch[0] < pitch[1] < pitch[2] < 0.0
    static = derived_quantities(BladeParameters.table_i("backward", cm_pitch_rate=0.0))
    (m,) = static.unstable_air_modes
    assert m.oscillatory and m.dominant_hinge == "pitch"


def test_modes_from_jacobian_of_uncoupled_oscillators():
    """Three uncoupled damped oscillators q_k'' + 2 z w q_k' + w^2 q_k = 0 give three modes,
    each dominated by its own hinge, with the right frequency and damping ratio."""
    w = np.array([1.0, 0.25, 4.5])
    zr = np.array([0.1, 0.5, 0.02])
    J = np.zeros((6, 6))
    J[:3, 3:] = np.eye(3)
    J[3:, :3] = -np.diag(w ** 2)
    J[3:, 3:] = -np.diag(2 * zr * w)
    modes = modes_from_jacobian(J)
    assert [m.dominant_hinge for m in modes] == list(HINGES)
    for m, wk, zk in zip(modes, w, zr):
        assert m.natural_frequency == pytest.approx(wk, rel=1e-12)
        assert m.damping_ratio == pytest.approx(zk, rel=1e-10)
        assert m.oscillatory and not m.unstable


def test_chordwise_e2_would_cock_the_blade_by_atan_e2_over_lag_hinge_radius():
    """A chordwise lag-hinge offset |e2| R1 beside the radial line: the centrifugal potential
    -1/2 Omega^2 int |P2 + s u|^2 dm of the blade is least with u along P2 (minimised here
    numerically), i.e. atan(|e2| / (e1 + e3)), about 9.5 deg for Table I."""
    p = BladeParameters.table_i()
    e1, e2, e3 = (p.hub_element_lengths[i] for i in (0, 1, 2))
    P2 = np.array([e1 + e3, -abs(e2)])  # beside the radial line, towards the trailing edge
    s = np.linspace(p.pitch_hinge_radius - (e1 + e3), p.radius - (e1 + e3), 400)

    def U(phi):  # blade direction phi from x_H, rad; uniform blade from the pitch hinge out
        return -0.5 * ((P2[0] + s * np.cos(phi)) ** 2 + (P2[1] + s * np.sin(phi)) ** 2).sum()

    phi_min = minimize_scalar(U, bounds=(-0.4, 0.4), method="bounded", options={"xatol": 1e-9}).x
    assert abs(phi_min) == pytest.approx(chordwise_lag_offset_angle(p), abs=1e-7)
    assert math.degrees(chordwise_lag_offset_angle(p)) == pytest.approx(9.46, abs=0.01)


def test_derived_quantities_reject_vacuum():
    with pytest.raises(ValueError, match="air_density"):
        derived_quantities(replace(BladeParameters.table_i(), air_density=0.0, collective=0.1))


def test_modes_rejects_unknown_hinge(forward):
    _, d = forward
    with pytest.raises(ValueError, match="hinge must be one of"):
        d.modes("torsion")


def test_chord_pitch_agrees_with_blade_element_theory_for_the_thrust(case):
    """Untwisted blade, uniform inflow: theta = 6 C_T/(sigma a) + 3/2 lambda + alpha_0 from
    blade-element theory; the model's chord pitch (root cutout, coning, lag) within 0.1 deg."""
    _, p, d = case
    a0 = p.airfoil.alpha_zero_lift
    theta = 6 * d.thrust_coefficient / (d.solidity * p.airfoil.lift_slope) + 1.5 * d.inflow_ratio + a0
    assert d.blade_element_pitch == pytest.approx(theta, rel=1e-12)
    assert abs(d.chord_pitch - theta) < math.radians(0.1)


def test_hover_coning_is_near_blade_element_theory_and_in_the_usual_range(case):
    """Coning 3-6 deg, within 0.5 deg of gamma/nu^2 (theta/8 - lambda/6) (which leaves out
    gravity and the vertical lag-hinge offset)."""
    _, _, d = case
    beta = d.equilibrium[0]
    assert math.radians(3.0) < beta < math.radians(6.0)
    assert abs(beta - d.blade_element_coning) < math.radians(0.5)


def test_hover_modes_are_the_air_modes_of_derived_quantities(forward):
    from rotorlyap.model.modes import hover_modes

    p, d = forward
    assert hover_modes(p) == d.air_modes
