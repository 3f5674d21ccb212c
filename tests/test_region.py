"""The region of stable motion by simulation (:mod:`rotorlyap.methods.region`,
:mod:`rotorlyap.analysis.region`): systems with known answers, the integrator against DOP853,
the input checks, and the blade."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from rotorlyap.methods.region import (
    DEFAULT_BOUND, horizon, integrate_batch, ray_extent, slice_map, verdicts,
)

C = 0.3  # damping of the oscillators, per unit of psi


def linear(psi, x):
    """x'' + C x' + x = 0."""
    return np.stack([x[:, 1], -C * x[:, 1] - x[:, 0]], axis=1)


def softening(psi, x):
    """x'' + C x' + x - x**3 = 0: wells at 0, saddles at x = +-1 (energy 1/4)."""
    return np.stack([x[:, 1], -C * x[:, 1] - x[:, 0] + x[:, 0] ** 3], axis=1)


def mathieu(psi, x):
    """Damped Mathieu equation x'' + 0.2 x' + (1 + 0.4 cos psi) x = 0 (stable, periodic in psi)."""
    return np.stack([x[:, 1], -0.2 * x[:, 1] - (1.0 + 0.4 * np.cos(psi)) * x[:, 0]], axis=1)


N_PERIODS = horizon(-C / 2)  # the oscillators' slowest decay rate is -C/2


def test_horizon_follows_the_slowest_linear_decay_rate():
    assert horizon(-0.1446) == 10  # fast decay: the floor of 10 periods
    assert horizon(-0.0067) == math.ceil(2 * math.log(2) / (2 * math.pi * 0.0067))  # 33
    assert horizon(-1e-5) == 100  # the cap
    assert horizon(-0.0067, 0.25) == math.ceil(2 * math.log(4) / (2 * math.pi * 0.0067))


def test_a_linear_damped_oscillator_returns_from_every_start():
    rays = ray_extent(linear, [[1, 0], [-1, 0], [0, 1], [1, 1]], [0.0, 1.0], s_max=30.0,
                      n_periods=N_PERIODS)
    assert rays.extent.shape == (4, 2)
    assert np.all(rays.extent == 30.0) and np.all(rays.hit_s_max) and not rays.non_monotone.any()
    assert np.all(rays.upper == np.inf)
    np.testing.assert_allclose(np.linalg.norm(rays.directions, axis=1), 1.0)


def test_the_softening_oscillator_from_rest_returns_iff_it_starts_below_the_saddle():
    x0 = np.array([[0.9, 0.0], [0.97, 0.0], [1.03, 0.0], [1.1, 0.0], [-0.97, 0.0], [-1.03, 0.0]])
    v = verdicts(softening, x0, 0.0, n_periods=N_PERIODS)
    assert v.stable.tolist() == [True, True, False, False, True, False]
    assert v.left.tolist() == [False, False, True, True, False, True]  # beyond the saddle it runs away


def test_the_softening_oscillators_extent_along_x_is_the_saddle():
    rays = ray_extent(softening, [[1, 0], [-1, 0]], 0.0, s_max=3.0, n_periods=N_PERIODS)
    assert np.all(np.abs(rays.extent - 1.0) < 0.03), rays.extent
    assert np.all(rays.upper > 1.0) and np.all(rays.upper < 1.03)
    assert not rays.hit_s_max.any()


def test_the_softening_oscillators_slice_holds_the_well_below_the_saddle_energy():
    m = slice_map(softening, 0, 1, 1.5, 1.5, 21, 0.0, n_states=2, n_periods=N_PERIODS)
    X, V = np.meshgrid(m.axis_i, m.axis_j, indexing="ij")
    energy = 0.5 * V**2 + 0.5 * X**2 - 0.25 * X**4
    inside = (np.abs(X) < 1.0) & (energy < 0.24)  # damping keeps these in the well: they return
    assert np.all(m.stable[inside])
    outward = ((X > 1.0) & (V >= 0.0)) | ((X < -1.0) & (V <= 0.0))  # beyond a saddle, moving out:
    assert not m.stable[outward].any()  # x'' = x**3 - x - C x' keeps x' from changing sign
    assert m.stable[10, 10] and m.stable.shape == (21, 21) and m.peak.shape == (21, 21)


def test_rk4_with_64_steps_agrees_with_dop853():
    x0 = np.array([[0.5, 0.0], [0.0, 0.6], [-0.8, 0.1]])
    run = integrate_batch(softening, x0, 0.0, 3.0)
    for i in range(3):
        sol = solve_ivp(lambda t, y: softening(np.array([t]), y[None])[0], (0, 6 * np.pi), x0[i],
                        method="DOP853", rtol=1e-11, atol=1e-13)
        np.testing.assert_allclose(run.x[i], sol.y[:, -1], atol=2e-6)


def test_per_motion_start_azimuths_match_separate_integrations():
    psi0 = np.array([0.0, 1.0, 2.5, 4.0])
    x0 = np.array([[1.0, 0.0], [0.5, 0.5], [0.0, 1.0], [-1.0, 0.3]])
    batch = integrate_batch(mathieu, x0, psi0, 2.0)
    for i in range(4):
        alone = integrate_batch(mathieu, x0[i], psi0[i], 2.0)
        np.testing.assert_allclose(batch.x[i], alone.x[0], rtol=1e-12, atol=1e-15)
        sol = solve_ivp(lambda t, y: mathieu(np.array([t]), y[None])[0], (psi0[i], psi0[i] + 4 * np.pi), x0[i],
                        method="DOP853", rtol=1e-11, atol=1e-13)
        np.testing.assert_allclose(batch.x[i], sol.y[:, -1], atol=2e-5)  # RK4's error, h**4
    # the same start at another azimuth is another motion of a periodic system
    assert not np.allclose(batch.x[0], integrate_batch(mathieu, x0[0], 1.0, 2.0).x[0])


def test_motions_beyond_the_bound_are_frozen_and_the_others_unaffected():
    def runaway(psi, x):  # x0' = x0**2 blows up in finite time; x1' = -x1 decays
        return np.stack([x[:, 0] ** 2, -x[:, 1]], axis=1)

    run = integrate_batch(runaway, [[1.0, 0.0], [0.0, 1.0]], 0.0, 2.0, bound=10.0)
    assert run.left.tolist() == [True, False]
    assert np.all(np.isfinite(run.x[0])) and run.peak[0] > 10.0 and np.isnan(run.last_peak[0])
    assert 0.0 < run.psi_left[0] < 1.0 and np.isnan(run.psi_left[1])
    z = -2 * np.pi / 64  # RK4 multiplies x1 by its stability polynomial R(z) at each of the 128 steps
    np.testing.assert_allclose(run.x[1, 1], (1 + z + z**2 / 2 + z**3 / 6 + z**4 / 24) ** 128, rtol=1e-12)
    np.testing.assert_allclose(run.x[1, 1], np.exp(-4 * np.pi), rtol=2e-5)


@pytest.mark.parametrize("kwargs, match", [
    (dict(bound=0.0), "bound"),
    (dict(bound=-1.0), "bound"),
    (dict(decay=0.0), "decay"),
    (dict(decay=1.0), "decay"),
    (dict(s_max=50.0), "below the bound"),
    (dict(s_max=-1.0), "s_max"),
    (dict(n_grid=1), "n_grid"),
    (dict(n_bisect=-1), "n_bisect"),
    (dict(scales=[1.0, 0.0]), "scales"),
    (dict(scales=[1.0, 1.0, 1.0]), "scales"),
    (dict(n_periods=0.5), "n_periods"),
    (dict(steps_per_period=2), "steps_per_period"),
])
def test_ray_extent_refuses_bad_arguments(kwargs, match):
    args = dict(scales=None, s_max=3.0, n_periods=N_PERIODS)
    args.update(kwargs)
    with pytest.raises(ValueError, match=match):
        ray_extent(linear, [[1.0, 0.0]], 0.0, **args)


def test_bad_shapes_and_systems_are_refused():
    with pytest.raises(ValueError, match="non-zero"):
        ray_extent(linear, [[0.0, 0.0]], 0.0, n_periods=10)
    with pytest.raises(ValueError, match="directions"):
        ray_extent(linear, np.ones((2, 2, 2)), 0.0, n_periods=10)
    with pytest.raises(ValueError, match="psi0"):
        integrate_batch(linear, np.ones((3, 2)), [0.0, 1.0], 1.0)
    with pytest.raises(ValueError, match="x0"):
        integrate_batch(linear, np.ones((3, 2, 1)), 0.0, 1.0)
    with pytest.raises(ValueError, match="returned shape"):
        integrate_batch(lambda p, x: x[:, :1], np.ones((3, 2)), 0.0, 1.0)
    with pytest.raises(ValueError, match="does not decay"):
        horizon(0.0)
    with pytest.raises(ValueError, match="differ"):
        slice_map(linear, 0, 0, 1.0, 1.0, 5, 0.0, n_states=2, n_periods=10)
    with pytest.raises(ValueError, match="component"):
        slice_map(linear, 0, 2, 1.0, 1.0, 5, 0.0, n_states=2, n_periods=10)
    with pytest.raises(ValueError, match="extent_j"):
        slice_map(linear, 0, 1, 1.0, 0.0, 5, 0.0, n_states=2, n_periods=10)
    with pytest.raises(ValueError, match="decay"):
        verdicts(linear, [[1.0, 0.0]], 0.0, n_periods=10, decay=1.5)


def test_the_default_bound_is_90_degrees_of_flap():
    from rotorlyap.conventions import DEFAULT_SCALES

    assert DEFAULT_BOUND * np.degrees(DEFAULT_SCALES[0]) == pytest.approx(90.0)


@pytest.mark.slow
def test_the_forward_cg_hover_blade_returns_from_a_degree_of_flap_and_from_ten():
    from rotorlyap.analysis.region import stable_region
    from rotorlyap.conventions import DEFAULT_SCALES, HINGES
    from rotorlyap.model.blade import Blade
    from rotorlyap.model.forward_trim import forward_flight_trim
    from rotorlyap.model.parameters import BladeParameters
    from rotorlyap.model.steady import disturbed_rhs

    params = BladeParameters.table_i("forward")
    trim = forward_flight_trim(params, 0.0, "none")
    f = disturbed_rhs(Blade(trim.params, 0.0), trim.steady)
    one_degree = np.radians([[1.0, 0, 0, 0, 0, 0], [-1.0, 0, 0, 0, 0, 0]])
    assert verdicts(f, one_degree, 0.0, n_periods=10, scales=DEFAULT_SCALES).stable.all()

    region = stable_region(params, 0.0, condition="none", slices=False)
    assert region.psi0.tolist() == [0.0] and region.n_periods == 10  # sigma = -0.14 per rev: the floor
    assert set(region.per_hinge) == set(HINGES)  # the layout of Certificate.start_region_per_hinge
    assert region.per_hinge["flap"][0] >= 10.0
    assert region.extent.shape == (12,) and np.all(region.extent > 0.0)
    assert "flap" in region.summary()


@pytest.mark.slow
def test_halving_the_rk4_step_changes_no_extent_of_the_trimmed_helicopter_at_mu_0_1():
    """Convergence of the yardstick (chapter 10): the extents along every hinge of the trimmed
    forward-C.G. helicopter at mu = 0.1 (periodic coefficients, four start azimuths) found with
    the default 64 RK4 steps per revolution and with 128 agree to the ray search's resolution
    (the grid's ratio to the power 1 / 2**n_bisect: 0.7 % with the defaults); measured
    2026-12-05, they agree to every digit, and with 256 steps too."""
    from rotorlyap.analysis.region import stable_region
    from rotorlyap.model.parameters import BladeParameters

    params = BladeParameters.flight_case("forward")
    coarse = stable_region(params, 0.1, slices=False)
    fine = stable_region(params, 0.1, slices=False, steps_per_period=128)
    assert (coarse.steps_per_period, fine.steps_per_period) == (64, 128)
    grid_ratio = 1000.0 ** (1.0 / (16 - 1))  # ray_extent's defaults: 16 amplitudes from s_max / 1000
    resolution = grid_ratio ** (1.0 / 2 ** 6) - 1.0  # after its 6 bisections
    assert resolution == pytest.approx(0.0072, abs=1e-4)
    np.testing.assert_allclose(fine.extent, coarse.extent, rtol=resolution)
    assert coarse.extent.min() > 1.0  # the test is about the nonlinear range, far from the origin
