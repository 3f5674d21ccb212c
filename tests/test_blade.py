"""Physical checks of the blade model, its aerodynamics, trim and energy function.

Each test names the fact it checks.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from rotorlyap.model.airfoil import LinearAirfoil
from rotorlyap.model.blade import Blade
from rotorlyap.model.mass import mass_properties
from rotorlyap.analysis.functions import energy_function
from rotorlyap.methods.lyapunov import orbital_derivative
from rotorlyap.model.parameters import BladeParameters
from rotorlyap.errors import TrimError
from rotorlyap.model.trim import hover_trim

TWO_PI = 2.0 * np.pi


def _random_disturbances(rng, n, angle=0.1, rate=0.3):
    return np.column_stack([rng.uniform(-angle, angle, (n, 3)), rng.uniform(-rate, rate, (n, 3))])


# ------------------------------------------------------------------ 1. Jacobi's integral
@pytest.mark.slow
def test_conservative_blade_conserves_energy_function_jacobi_integral(forward):
    """Vacuum, no dampers, hover, steady motion = that case's equilibrium: W is Jacobi's
    integral T2 + U (minus its rest value), so W' = 0 to round-off at random states."""
    p = replace(forward, air_density=0.0, lag_damping=0.0, collective=0.1)
    blade = Blade(p)
    xi = blade.equilibrium()
    E = energy_function(blade, xi)
    rng = np.random.default_rng(0)
    x = _random_disturbances(rng, 200, angle=0.3, rate=0.5)
    psi = rng.uniform(0, TWO_PI, 200)
    dW = E.dW(psi, x)
    # scale of the terms that cancel: |grad W| |f|
    f = E.f(psi, x)
    h = 1e-6
    grad = np.stack([(E.W(psi, x + h * e) - E.W(psi, x - h * e)) / (2 * h) for e in np.eye(6)], -1)
    scale = np.abs(grad * f).sum(-1)
    assert np.all(np.abs(dW) <= 1e-10 * scale)
    assert np.all(scale > 1.0)  # the cancelling terms are not trivially zero
    # and W itself is constant along a simulated motion
    from scipy.integrate import solve_ivp

    sol = solve_ivp(lambda s, y: E.f(s, y), (0.0, 4 * np.pi), x[0], rtol=1e-11, atol=1e-12,
                    dense_output=True)
    Ws = E.W(sol.t, sol.y.T)
    assert np.ptp(Ws) <= 1e-7 * abs(Ws[0])


# ------------------------------------------------------------------ 2. rotating frequencies
def _single_offset_blade(R1: float = 7.0, k: float = 0.05) -> Blade:
    R = 7.85
    e = R - R1
    p = BladeParameters(radius=R, blade_length=R1, hub_elements=(e / R1, 0.0, 0.0, 0.0, 0.0),
                        air_density=0.0, gravity=0.0, lag_damping=0.0, pitch_stiffness=1e9,
                        pitch_flap_coupling=0.0, cg_position=0.25, aerodynamic_centre=0.25,
                        collective=0.0, pitch_radius_of_gyration=k)
    return Blade(p)


@pytest.mark.parametrize("R1", [7.0, 7.5, 7.8])
def test_rotating_flap_and_lag_frequencies_of_uniform_blade_with_hinge_offset(R1):
    """Uniform blade from a single flap-and-lag hinge at offset e to the tip (length L):
    nu_beta^2 = 1 + e S/I = 1 + 1.5 e/L exactly, and nu_zeta^2 = e S/(I + m k^2 c^2), which is
    1.5 e/L when the chordwise radius of gyration k c vanishes (S, I first and second moments of
    the blade mass about the hinge)."""
    blade = _single_offset_blade(R1)
    z = blade.equilibrium()
    np.testing.assert_allclose(z, 0.0, atol=1e-12)
    ev = np.linalg.eigvals(blade.jacobian(0.0, z))
    freqs = np.sort(np.abs(ev.imag))[::2]  # conjugate pairs
    assert np.all(np.abs(ev.real) < 1e-7 * np.abs(ev).max())  # undamped
    L = blade.params.blade_length
    e = blade.params.radius - L
    eps = e / L
    mp = blade.mass_properties
    S, I = mp.first_moment[0], mp.inertia[1, 1]
    k2c2 = (blade.params.pitch_radius_of_gyration * blade.params.chord) ** 2
    nu_beta_exact = np.sqrt(1 + e * S / I)
    nu_zeta_exact = np.sqrt(e * S / (I + mp.mass * k2c2))
    assert nu_beta_exact == pytest.approx(np.sqrt(1 + 1.5 * eps), rel=1e-12)  # uniform blade
    assert freqs[0] == pytest.approx(nu_zeta_exact, rel=1e-8)
    assert freqs[1] == pytest.approx(nu_beta_exact, rel=1e-8)
    # the classical formulas, loosely (the chordwise inertia is small)
    assert freqs[0] ** 2 == pytest.approx(1.5 * eps, rel=1e-3)
    assert freqs[1] ** 2 == pytest.approx(1 + 1.5 * eps, rel=1e-9)


# ------------------------------------------------------------------ 3. hover coning
def _central_hinge_params(theta0: float, lam: float) -> BladeParameters:
    R = 7.85
    return BladeParameters(
        radius=R, blade_length=R - 1e-3, hub_elements=(0.0, 0.0, 0.0, 0.0, 0.0), gravity=0.0,
        lag_damping=0.0, pitch_stiffness=1e9, lag_stiffness=1e9, pitch_flap_coupling=0.0,
        cg_position=0.25, aerodynamic_centre=0.25, airfoil=LinearAirfoil(5.7, 0.0),
        inflow_model="uniform", inflow_ratio=lam, collective=theta0, n_stations=24)


def test_hover_coning_tends_to_blade_element_theory():
    """Linear aerodynamics, uniform inflow, centrally hinged blade without root cutout, no
    gravity, stiff pitch and lag springs: the hover coning tends to
    beta_0 = gamma (theta_0/8 - lambda/6) as the angles go to zero."""
    errors = []
    for s in (1.0, 0.5, 0.25):
        theta0, lam = 0.02 * s, 0.005 * s
        blade = Blade(_central_hinge_params(theta0, lam))
        z = blade.equilibrium()
        p = blade.params
        gamma = p.air_density * 5.7 * p.chord * p.radius**4 / blade.mass_properties.inertia[1, 1]
        beta0 = gamma * (theta0 / 8 - lam / 6)
        errors.append(abs(z[0] / beta0 - 1))
        assert abs(z[1]) < 1e-5 * z[0] and abs(z[2] - theta0) < 1e-5 * theta0
    assert errors[0] < 1e-4
    assert errors[2] < errors[1] < errors[0]  # tends to the formula


# ------------------------------------------------------------------ 4. periodicity
def test_hover_rhs_independent_of_azimuth_and_forward_flight_rhs_periodic(forward):
    """In hover the right-hand side does not depend on psi; for mu > 0 (with cyclic pitch)
    it is 2 pi-periodic and does depend on psi."""
    rng = np.random.default_rng(4)
    hover = Blade(forward)
    z = hover.equilibrium() + _random_disturbances(rng, 50)
    psi = rng.uniform(0, TWO_PI, 50)
    f0 = hover.rhs(0.0, z)
    np.testing.assert_allclose(hover.rhs(psi, z), f0, rtol=1e-12, atol=1e-12 * np.abs(f0).max())
    ff = Blade(replace(forward, cyclic_cos=0.02, cyclic_sin=-0.03), mu=0.2)
    f1 = ff.rhs(psi, z)
    np.testing.assert_allclose(ff.rhs(psi + TWO_PI, z), f1, rtol=1e-10, atol=1e-10 * np.abs(f1).max())
    np.testing.assert_allclose(ff.rhs(psi - 3 * TWO_PI, z), f1, rtol=1e-9, atol=1e-9 * np.abs(f1).max())
    assert np.abs(ff.rhs(psi + 1.0, z) - f1).max() > 1e-3 * np.abs(f1).max()


# ------------------------------------------------------------------ signs
def test_positive_collective_gives_lift_upward_flap_and_thrust(forward):
    """Positive collective (small given inflow): positive thrust, positive aerodynamic flap
    moment, upward coning, positive angle of attack outboard; more collective, more thrust."""
    out = []
    for c in (0.08, 0.11):
        b = Blade(replace(forward, collective=c, inflow_ratio=0.02))
        z = b.equilibrium()
        Q = b.aerodynamic_forces(0.0, z)
        assert Q[0] > 0 and z[0] > 0
        assert np.all(b.angle_of_attack(0.0, z)[-4:] > 0)
        out.append(b.rotor_thrust(0.0, z))
    assert 0 < out[0] < out[1]


def test_drag_lags_the_blade_and_lag_damper_opposes_lag_rate(forward_hover):
    """Aerodynamic drag pushes the blade back (positive lag moment); the lag damper's
    generalised force is -C_zeta Omega zeta' and opposes the lag rate."""
    z = forward_hover.equilibrium()
    assert forward_hover.aerodynamic_forces(0.0, z)[1] > 0 and z[1] > 0
    zr = z + np.array([0, 0, 0, 0, 0.1, 0])
    Qd = forward_hover.generalised_forces(0.0, zr)["damping"]
    assert Qd[1] == pytest.approx(-forward_hover.params.lag_damping * forward_hover.omega * 0.1)
    assert Qd[0] == 0 and Qd[2] == 0


def test_advancing_side_at_90_degrees(forward):
    """psi = 90 deg is the advancing side: the relative air speed at the tip is larger there
    than at 270 deg by 2 mu Omega R (rigid blade at rest in the hub frame), and the retreating
    blade root sees reverse flow at mu = 0.25."""
    mu = 0.25
    b = Blade(forward, mu=mu)
    z = np.zeros(6)
    VR = forward.rotor_speed * forward.radius

    def speed(psi):
        return float(np.hypot(*b.relative_wind(psi, z)[-1]))

    r_tip = b.r[-1]
    assert speed(np.pi / 2) == pytest.approx(forward.rotor_speed * r_tip + mu * VR, rel=1e-3)
    assert speed(3 * np.pi / 2) == pytest.approx(forward.rotor_speed * r_tip - mu * VR, rel=1e-3)
    alpha = b.angle_of_attack(3 * np.pi / 2, z)
    assert abs(alpha[0]) > np.pi / 2  # reverse flow at the root on the retreating side
    assert np.all(np.abs(b.angle_of_attack(np.pi / 2, z)) < 0.3)


# ------------------------------------------------------------------ energy function
def test_energy_function_vanishes_with_zero_gradient_at_steady_motion(forward_hover):
    """W(psi, 0) = 0 and grad W(psi, 0) = 0; the Hessian is positive definite at the Table I
    forward_hover equilibrium (condition (d) locally)."""
    E = energy_function(forward_hover)
    psi = np.linspace(0, TWO_PI, 7)
    assert np.all(np.abs(E.W(psi, np.zeros((7, 6)))) < 1e-9)
    h = 1e-5
    for e in np.eye(6):
        g = (E.W(psi, h * e) - E.W(psi, -h * e)) / (2 * h)
        assert np.all(np.abs(g) < 1e-4)
    rep = E.positivity()
    assert rep.positive_definite
    rng = np.random.default_rng(7)
    assert np.all(E.W(0.0, _random_disturbances(rng, 100, 0.05, 0.05)) > 0)


@pytest.mark.parametrize("case", ["constant", "cyclic", "periodic_xi"])
def test_analytic_dW_equals_finite_difference_orbital_derivative(forward, case):
    """The analytic W' = dW/dpsi + grad W . f equals a central difference of W along (1, f)
    in forward flight with aerodynamics, with cyclic pitch and for a psi-periodic xi."""
    p = forward if case == "constant" else replace(forward, cyclic_cos=0.02, cyclic_sin=-0.03)
    b = Blade(p, mu=0.2)
    xi0 = b.equilibrium()
    if case == "periodic_xi":
        def xi(s):
            return xi0 + 0.01 * np.stack([np.cos(np.asarray(s) + k) for k in range(6)], -1)

        def dxi(s):
            return -0.01 * np.stack([np.sin(np.asarray(s) + k) for k in range(6)], -1)

        E = energy_function(b, (xi, dxi))
    else:
        E = energy_function(b, xi0)
    rng = np.random.default_rng(11)
    x = _random_disturbances(rng, 40, 0.1, 0.2)
    psi = rng.uniform(0, TWO_PI, 40)
    ref = orbital_derivative(E.f, E.W, psi, x, h=1e-5)
    np.testing.assert_allclose(E.dW(psi, x), ref, rtol=1e-6, atol=1e-6 * np.abs(ref).max())


def test_vectorised_shapes_and_scalar_psi(forward_hover):
    """Methods broadcast psi against the leading axes of z and x."""
    rng = np.random.default_rng(3)
    z = forward_hover.equilibrium() + _random_disturbances(rng, 12).reshape(3, 4, 6)
    psi = rng.uniform(0, TWO_PI, 4)
    f = forward_hover.rhs(psi, z)
    assert f.shape == (3, 4, 6)
    np.testing.assert_allclose(f[1, 2], forward_hover.rhs(psi[2], z[1, 2]), rtol=1e-13, atol=1e-13)
    assert forward_hover.jacobian(0.0, z).shape == (3, 4, 6, 6)
    assert forward_hover.kinetic_energy(psi, z).shape == (3, 4)
    assert forward_hover.potential_energy(0.0, z).shape == (3, 4)
    E = energy_function(forward_hover)
    x = z - forward_hover.equilibrium()
    assert E.W(psi, x).shape == (3, 4) and E.dW(0.0, x).shape == (3, 4)
    np.testing.assert_allclose(E.dW(psi, x)[2], E.dW(psi, x[2]), rtol=1e-13)


def test_kinetic_energy_split_and_effective_potential(forward_hover):
    """T = T2 + T1 + T0 with T2 = 1/2 Omega^2 q'^T M q' and U = V - T0."""
    rng = np.random.default_rng(5)
    z = forward_hover.equilibrium() + _random_disturbances(rng, 5)
    T2, T1, T0 = np.moveaxis(forward_hover.kinetic_energy_parts(0.0, z), -1, 0)
    M = forward_hover.mass_matrix(z)
    qp = z[:, 3:]
    np.testing.assert_allclose(T2, 0.5 * forward_hover.omega**2 * np.einsum("ni,nij,nj->n", qp, M, qp),
                               rtol=1e-12)
    np.testing.assert_allclose(forward_hover.kinetic_energy(0.0, z), T2 + T1 + T0, rtol=1e-14)
    np.testing.assert_allclose(forward_hover.effective_potential(0.0, z),
                               forward_hover.potential_energy(0.0, z) - T0, rtol=1e-12)


# ------------------------------------------------------------------ mass properties, trim
def test_mass_properties_of_uniform_blade(forward):
    """Mass, first moment and inertia about the pitch hinge from the spanwise quadrature equal
    the closed forms of a uniform blade with a chordwise C.G. offset."""
    mp = mass_properties(forward)
    mpl, R, R1 = forward.mass_per_length, forward.radius, forward.blade_length
    a = R - R1 - forward.pitch_hinge_radius  # root of the blade from the pitch hinge
    b = R - forward.pitch_hinge_radius
    m = mpl * R1
    y = (forward.pitch_axis - forward.cg_position) * forward.chord
    assert mp.mass == pytest.approx(m, rel=1e-13)
    np.testing.assert_allclose(mp.first_moment, [mpl * (b**2 - a**2) / 2, m * y, 0.0], atol=1e-10)
    Ix2 = mpl * (b**3 - a**3) / 3
    k2 = (forward.pitch_radius_of_gyration * forward.chord) ** 2
    np.testing.assert_allclose(np.diag(mp.inertia), [m * (y * y + k2), Ix2, Ix2 + m * (y * y + k2)],
                               rtol=1e-12)
    assert mp.inertia[0, 1] == pytest.approx(-mpl * (b**2 - a**2) / 2 * y, rel=1e-12)


def test_hover_trim_gives_thrust_equal_weight(forward, forward_hover):
    """The trimmed collective gives rotor thrust = weight at the forward_hover equilibrium."""
    tr = hover_trim(forward)
    assert tr.thrust == pytest.approx(forward.weight, rel=1e-9)
    assert forward_hover.params.collective == tr.collective
    np.testing.assert_allclose(forward_hover.equilibrium(), tr.equilibrium)
    np.testing.assert_allclose(forward_hover.rhs(0.0, tr.equilibrium)[3:], 0.0, atol=1e-9)
    assert forward_hover.rotor_thrust(0.0, tr.equilibrium) == pytest.approx(forward.weight, rel=1e-9)


def test_trim_and_equilibrium_errors_are_clear(forward):
    """Trim in vacuum raises TrimError; a bad mu raises ValueError."""
    with pytest.raises(TrimError, match="vacuum"):
        hover_trim(replace(forward, air_density=0.0))
    with pytest.raises(ValueError, match="mu"):
        Blade(forward, mu=-0.1)


def test_lift_at_aerodynamic_centre_ahead_of_pitch_axis_pitches_nose_up(forward):
    """Moving the aerodynamic centre from 0.05 c behind to 0.05 c ahead of the pitch axis
    (cm = 0) adds a nose-up pitch moment equal to the blade lift times 0.1 c."""
    base = replace(forward, airfoil=LinearAirfoil(5.7, 0.0), collective=0.1, inflow_ratio=0.02,
                   cg_position=0.25)
    z = np.array([0.05, 0.0, 0.1, 0.0, 0.0, 0.0])
    Q = {}
    for ac in (0.20, 0.30):
        b = Blade(replace(base, aerodynamic_centre=ac))
        Q[ac] = b.aerodynamic_forces(0.0, z)[2]
        lift = b.rotor_thrust(0.0, z) / b.params.n_blades
    assert Q[0.20] - Q[0.30] > 0
    assert Q[0.20] - Q[0.30] == pytest.approx(lift * 0.1 * base.chord, rel=0.02)


# ------------------------------------------------------------------ aerodynamic pitch damping
def test_pitch_damping_couple_is_the_thin_airfoil_value_pi_rho_b3_U_q():
    """Quasi-steady thin-airfoil theory (Theodorsen, C(k) = 1): a section pitching at rate q in
    a stream U feels the couple -pi rho b^3 U q (b = c/2). At zero hinge angles, no inflow and
    no lift (zero collective, linear section without drag or moment), a pitch rate theta'
    gives U = Omega r and q = Omega theta' exactly, so the generalised pitch force changes by
    -pi/8 rho c^3 Omega^2 theta' (R^2 - r_0^2)/2 (Gauss quadrature is exact for r), and the
    flap and lag forces do not change."""
    base = BladeParameters(airfoil=LinearAirfoil(5.7, 0.0), collective=0.0, inflow_ratio=0.0,
                           inflow_model="uniform", gravity=0.0, pitch_flap_coupling=0.0)
    rate = 1e-3
    z = np.array([0.0, 0.0, 0.0, 0.0, 0.0, rate])
    q_damped = Blade(base).aerodynamic_forces(0.0, z)
    q_static = Blade(replace(base, cm_pitch_rate=0.0)).aerodynamic_forces(0.0, z)
    p = base
    r0 = p.radius - p.blade_length
    expected = -np.pi / 8 * p.air_density * p.chord ** 3 * p.rotor_speed ** 2 * rate * (p.radius ** 2 - r0 ** 2) / 2
    assert q_damped[2] - q_static[2] == pytest.approx(expected, rel=1e-6)
    np.testing.assert_allclose(q_damped[:2], q_static[:2], atol=1e-12 * abs(expected))


def test_pitch_damping_leaves_the_equilibrium_and_only_dissipates(forward):
    """The couple acts on the pitch rate relative to the rotating hub, which is zero at rest:
    the hover equilibrium is the same with and without it; in motion it only removes energy,
    so W' (energy about the equilibrium) is lower with it at every disturbed state."""
    static = replace(forward, cm_pitch_rate=0.0)
    b1, b0 = Blade(forward), Blade(static)
    np.testing.assert_allclose(b1.equilibrium(), b0.equilibrium(), atol=1e-12)
    x = np.random.default_rng(5).normal(size=(400, 6)) * np.array([0.02, 0.02, 0.01, 0.02, 0.005, 0.05])
    d1 = energy_function(b1).dW(0.0, x)
    d0 = energy_function(Blade(replace(static, collective=b1.params.collective)), b1.equilibrium()).dW(0.0, x)
    assert np.all(d1 <= d0 + 1e-9 * np.abs(d0).max())
    assert np.mean(d1 < d0 - 1e-6 * np.abs(d0).max()) > 0.9
