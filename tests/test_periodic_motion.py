"""The blade's true periodic steady motion (Fourier collocation)."""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from rotorlyap import Blade, BladeParameters
from rotorlyap.errors import PeriodicMotionError
from rotorlyap.model.steady import periodic_motion


def test_hover_periodic_motion_is_the_equilibrium(forward):
    """At mu = 0 the periodic solution is the constant hover equilibrium."""
    m = periodic_motion(forward, 0.0)
    xi = m.xi(np.linspace(0, 2 * np.pi, 7))
    np.testing.assert_allclose(xi, np.tile(Blade(forward, 0.0).equilibrium(), (7, 1)), atol=1e-10)
    np.testing.assert_allclose(m.dxi(np.array([0.3, 2.0])), 0.0, atol=1e-10)


def test_collocation_solution_is_a_periodic_orbit_of_the_full_equations(forward):
    """Integrating the nonlinear equations for one period from xi(0) returns to xi(0), and
    passes through xi(pi) half way (independent check by a Runge-Kutta integrator)."""
    m = periodic_motion(forward, 0.15)
    blade = Blade(forward, 0.15)
    sol = solve_ivp(lambda p, z: blade.rhs(p, z), (0, 2 * np.pi), m.z0, method="DOP853",
                    rtol=1e-10, atol=1e-12, t_eval=[np.pi, 2 * np.pi])
    np.testing.assert_allclose(sol.y[:, 0], m.xi(np.pi), atol=1e-5)
    np.testing.assert_allclose(sol.y[:, 1], m.z0, atol=1e-5)
    # the derivative of the series is the right-hand side along the orbit
    psi = np.linspace(0, 2 * np.pi, 9)
    np.testing.assert_allclose(m.dxi(psi), blade.rhs(psi, m.xi(psi)), atol=1e-4)
    assert m.harmonics_deg.shape == (3, 3)
    assert abs(m.harmonics_deg[0, 2]) > 0.5  # forward flight flaps once per revolution


def test_flapping_trim_removes_the_first_harmonics(forward):
    """With trim_flapping the cyclic pitch cancels the once-per-rev flapping."""
    m = periodic_motion(forward, 0.15, trim_flapping=True)
    np.testing.assert_allclose(m.harmonics_deg[0, 1:], 0.0, atol=1e-6)
    assert m.params.cyclic_cos != 0.0 or m.params.cyclic_sin != 0.0


def test_bad_arguments(forward):
    """Advance ratio and resolution are checked."""
    with pytest.raises(ValueError, match="mu must be an advance ratio"):
        periodic_motion(forward, -0.1)
    with pytest.raises(ValueError, match="n_points must be an even integer"):
        periodic_motion(forward, 0.1, n_points=7)
    with pytest.raises(PeriodicMotionError, match="no periodic solution found"):
        periodic_motion(forward, 0.15, max_iter=1, tol=1e-30)


def test_start_option_seeds_newton_and_bad_starts_are_refused():
    """A start equal to the default (the hover equilibrium at every azimuth) gives the same
    motion; a start of the wrong shape, or not callable, is refused with a clear error."""
    p = BladeParameters.table_i("forward")
    xh = Blade(p, 0.0).equilibrium()
    pm0 = periodic_motion(p, 0.1)
    pm1 = periodic_motion(p, 0.1, start=lambda psi: np.tile(xh, (psi.size, 1)))
    np.testing.assert_allclose(pm1.coefficients, pm0.coefficients, atol=1e-12)
    with pytest.raises(ValueError, match=r"start\(psi\) must return finite states of shape \(64, 6\)"):
        periodic_motion(p, 0.1, start=lambda psi: np.zeros((psi.size, 3)))
    with pytest.raises(TypeError, match="start must be None or a callable"):
        periodic_motion(p, 0.1, start=xh)


def test_shooting_stops_at_its_noise_floor_and_refuses_a_motion_it_cannot_reach(forward):
    """The return map's mismatch cannot fall below the integration's own error (near 1e-11 at
    rtol 1e-12): asked for 1e-16, shooting stops where Newton no longer halves the mismatch and
    keeps its best start, whose motion returns to itself to the floor; asked to reach the floor
    itself below 1e-20, it refuses with the mismatch reached."""
    from rotorlyap.model.steady import refine_motion

    blade = Blade(forward, 0.15)
    m = periodic_motion(forward, 0.15, n_points=32)
    tab = refine_motion(blade, m, n=64, tol=1e-16)
    sol = solve_ivp(lambda p, z: blade.rhs(p, z), (0, 2 * np.pi), tab.values[0], method="DOP853",
                    rtol=1e-12, atol=1e-14)
    assert np.max(np.abs(sol.y[:, -1] - tab.values[0])) < 1e-9
    with pytest.raises(PeriodicMotionError, match=r"\|z\(2 pi\) - z\(0\)\| = "):
        refine_motion(blade, m, n=64, tol=1e-16, floor_tol=1e-20)
