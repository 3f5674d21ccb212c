"""Tests of rotorlyap.model.inflow: momentum theory, wake skew, k_x models, induced inflow."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from rotorlyap.model.inflow import (
    INFLOW_MODELS,
    induced_inflow,
    kx_factor,
    mean_inflow,
    momentum_inflow,
    thrust_coefficient,
    wake_skew,
)
from rotorlyap.errors import InflowConvergenceError

CT = 0.0053


def test_thrust_coefficient_is_weight_over_rho_pi_R2_tip_speed_squared(forward):
    """C_T = m g / (rho pi R^2 (Omega R)^2) = 0.00534 for the W-3-like data."""
    expected = 6400 * 9.80665 / (1.225 * math.pi * 7.85**2 * (28.35 * 7.85) ** 2)
    assert thrust_coefficient(forward) == pytest.approx(expected, rel=1e-14)
    assert thrust_coefficient(forward) == pytest.approx(0.005344, abs=1e-6)


def test_thrust_coefficient_in_vacuum_is_an_error(forward):
    with pytest.raises(ValueError, match=r"air_density must be > 0, got 0.0 \(vacuum\)"):
        thrust_coefficient(dataclasses.replace(forward, air_density=0.0))
    with pytest.raises(ValueError, match="weight"):
        thrust_coefficient(dataclasses.replace(forward, gravity=0.0))


def test_hover_inflow_is_sqrt_ct_over_2():
    assert momentum_inflow(CT, 0.0) == pytest.approx(math.sqrt(CT / 2), rel=1e-15)


def test_high_speed_inflow_tends_to_ct_over_2mu():
    """lambda -> C_T / (2 mu) as mu >> lambda_h (Glauert's high-speed limit)."""
    for mu in (0.3, 0.5, 1.0):
        lam = momentum_inflow(CT, mu)
        assert lam / (CT / (2 * mu)) == pytest.approx(1.0, abs=(CT / (2 * mu * mu)) ** 2)


@pytest.mark.parametrize("mu", [0.0, 0.01, 0.03, 0.05, 0.1, 0.15, 0.25, 0.5])
def test_momentum_equation_residual_is_zero(mu):
    lam = momentum_inflow(CT, mu)
    assert 2 * lam * math.sqrt(mu * mu + lam * lam) - CT == pytest.approx(0.0, abs=1e-15)


def test_newton_solution_equals_closed_form_root_of_the_quartic():
    """For an untilted disc lambda^2 = (-mu^2 + sqrt(mu^4 + C_T^2)) / 2 exactly; Newton must agree."""
    mu = np.linspace(0.0, 0.4, 81)
    lam = momentum_inflow(CT, mu)
    closed = np.sqrt(0.5 * (-(mu**2) + np.sqrt(mu**4 + CT**2)))
    np.testing.assert_allclose(lam, closed, rtol=1e-12)
    assert lam.shape == mu.shape
    assert np.all(np.diff(lam) < 0)  # inflow falls with speed


def test_momentum_inflow_broadcasts_and_returns_float_for_scalars():
    assert isinstance(momentum_inflow(CT, 0.1), float)
    lam = momentum_inflow(np.array([[0.004], [0.008]]), np.array([0.0, 0.1, 0.2]))
    assert lam.shape == (2, 3)
    assert momentum_inflow(0.0, 0.2) == 0.0


def test_momentum_inflow_reports_non_convergence():
    with pytest.raises(InflowConvergenceError, match="did not converge in 1 Newton iterations"):
        momentum_inflow(CT, 0.2, maxiter=1)


@pytest.mark.parametrize("ct, mu, match", [(-0.001, 0.1, "ct must be >= 0"), (CT, -0.1, "mu must be >= 0"),
                                           (float("nan"), 0.1, "ct must be finite")])
def test_momentum_inflow_rejects_bad_input(ct, mu, match):
    with pytest.raises(ValueError, match=match):
        momentum_inflow(ct, mu)


def test_wake_skew_is_zero_in_hover_and_90_deg_edgewise():
    assert wake_skew(0.0, 0.05) == 0.0
    assert wake_skew(0.2, 0.0) == pytest.approx(math.pi / 2)
    assert wake_skew(0.05, 0.05) == pytest.approx(math.pi / 4)


def test_kx_published_values_at_90_deg_skew():
    """At chi = 90 deg: Pitt-Peters 15 pi/32 (Chen1990, Table 1), Coleman tan 45 = 1, Drees 4/3 (1 - 1.8 mu^2), Glauert 1.2."""
    mu, lam = 0.2, 0.0
    assert kx_factor("pitt-peters", mu, lam) == pytest.approx(15 * math.pi / 32)
    assert kx_factor("coleman", mu, lam) == pytest.approx(1.0)
    assert kx_factor("drees", mu, lam) == pytest.approx(4 / 3 * (1 - 1.8 * mu**2))
    assert kx_factor("glauert", mu, lam) == 1.2
    assert kx_factor("uniform", mu, lam) == 0.0


def test_drees_equals_its_published_form_at_intermediate_skew():
    mu, lam = 0.1, 0.03
    chi = math.atan2(mu, lam)
    published = 4 / 3 * (1 - math.cos(chi) - 1.8 * mu**2) / math.sin(chi)
    assert kx_factor("drees", mu, lam) == pytest.approx(published, rel=1e-13)
    assert kx_factor("coleman", mu, lam) == pytest.approx(math.tan(chi / 2))
    assert kx_factor("pitt-peters", mu, lam) == pytest.approx(15 * math.pi / 32 * math.tan(chi / 2))


@pytest.mark.parametrize("model", INFLOW_MODELS)
def test_kx_is_zero_in_hover(model):
    assert kx_factor(model, 0.0, 0.05) == 0.0


def test_kx_is_vectorised():
    mu = np.linspace(0, 0.3, 7)
    kx = kx_factor("pitt-peters", mu, momentum_inflow(CT, mu))
    assert kx.shape == (7,) and kx[0] == 0.0 and np.all(np.diff(kx) > 0)


def test_unknown_inflow_model_lists_allowed_names():
    with pytest.raises(ValueError, match=r"unknown inflow model 'mangler'; allowed: uniform, glauert, drees, "
                                         r"pitt-peters, coleman"):
        kx_factor("mangler", 0.1, 0.03)


def test_induced_inflow_is_larger_at_the_rear_of_the_disc(forward):
    """psi = 0 points downstream: lambda_i(r, 0) > lambda_0 > lambda_i(r, pi) (Glauert, k_x = 1.2)."""
    mu = 0.15
    lam0 = momentum_inflow(thrust_coefficient(forward), mu)
    rear, side, front = induced_inflow(forward, mu, 1.0, np.array([0.0, math.pi / 2, math.pi]))
    assert rear == pytest.approx(lam0 * 2.2)
    assert side == pytest.approx(lam0)
    assert front == pytest.approx(lam0 * (1 - 1.2))


def test_induced_inflow_broadcasts_and_averages_to_lambda0(forward):
    r = np.linspace(0.2, 1.0, 5)[:, None]
    psi = np.linspace(0, 2 * math.pi, 64, endpoint=False)[None, :]
    lam = induced_inflow(forward, 0.2, r, psi)
    assert lam.shape == (5, 64)
    np.testing.assert_allclose(lam.mean(axis=1), mean_inflow(forward, 0.2), rtol=1e-12)


def test_induced_inflow_in_hover_does_not_depend_on_azimuth(forward):
    lam = induced_inflow(forward, 0.0, 0.7, np.linspace(0, 2 * math.pi, 9))
    np.testing.assert_allclose(lam, math.sqrt(thrust_coefficient(forward) / 2), rtol=1e-14)


def test_inflow_ratio_override_and_uniform_model(forward):
    q = dataclasses.replace(forward, inflow_ratio=0.04, inflow_model="uniform")
    lam = induced_inflow(q, 0.25, np.array([0.3, 1.0]), np.array([[0.0], [math.pi]]))
    np.testing.assert_array_equal(lam, 0.04)


def test_induced_inflow_in_vacuum_is_zero(forward):
    q = dataclasses.replace(forward, air_density=0.0)
    assert np.all(induced_inflow(q, 0.1, 1.0, np.array([0.0, 1.0])) == 0.0)


@pytest.mark.parametrize("mu, tilt_deg", [(0.05, 2.0), (0.15, 4.0), (0.3, 8.0), (1.0, 10.0)])
def test_momentum_inflow_with_a_tilted_disc_satisfies_glauerts_formula(mu, tilt_deg):
    """Glauert's momentum formula for a disc tilted forward by alpha_s (Johnson 1980, eq. 4.1):
    lambda = mu tan(alpha_s) + C_T / (2 sqrt(mu^2 + lambda^2)), lambda the whole inflow; the
    tilt's through-flow lowers the induced part below the untilted value."""
    ct = 0.008
    lc = mu * math.tan(math.radians(tilt_deg))
    li = momentum_inflow(ct, mu, through_flow=lc)
    lam = lc + li
    assert lam == pytest.approx(lc + ct / (2.0 * math.sqrt(mu * mu + lam * lam)), rel=1e-12)
    assert li < momentum_inflow(ct, mu)


def test_momentum_inflow_refuses_a_windmill_state():
    """A disc tilted so far aft that the free stream flows up through it faster than the induced
    flow goes down (whole inflow < 0) is outside momentum theory: a clear error, not a number."""
    with pytest.raises(ValueError, match="windmill state"):
        momentum_inflow(0.008, 0.2, through_flow=-0.1)
