"""Tests of ``rotorlyap.methods.periodic_lyapunov`` against facts that hold for the exact solution.

Each test's docstring states the fact it checks. The periodic system used is the damped
Mathieu equation ``y'' + c y' + (a - 2 q cos 2t) y = 0`` (period pi) at (a, q) = (2.5, 0.5),
in the stable region of the undamped equation (between a_1 and b_2, see tests/test_floquet.py),
so with c > 0 both multipliers have modulus exp(-c pi / 2) < 1.
"""

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.linalg import solve_continuous_lyapunov

from rotorlyap.methods.examples import mathieu_matrix
from rotorlyap.methods.periodic_lyapunov import PeriodicLyapunovSolution, periodic_lyapunov

A_CONST = np.array([[0.0, 1.0, 0.0], [-4.0, -0.4, 0.5], [0.3, 0.0, -1.0]])
Q3 = np.diag([1.0, 2.0, 0.5])


def damped_mathieu(a=2.5, q=0.5, c=0.3):
    return mathieu_matrix(a, q, c)  # works for a float t (2, 2) and, vectorised, for t of shape (k,)


def coupled_periodic(n=4, seed=3):
    """A random n x n system with harmonics 1 and 3 of period 2 pi, shifted to be stable."""
    rng = np.random.default_rng(seed)
    C = rng.normal(size=(4, n, n))

    def A(p):
        p = np.asarray(p, dtype=float)[..., None, None]
        return (C[0] - 3.0 * np.eye(n) + 1.2 * C[1] * np.cos(p) + 1.2 * C[2] * np.sin(p)
                + 0.8 * C[3] * np.cos(3 * p))

    return A


def test_constant_A_gives_solve_continuous_lyapunov():
    """For a constant stable A the periodic solution is the constant solution of
    A^T P + P A = -Q (scipy.linalg.solve_continuous_lyapunov): exact for an array (dP = 0),
    and to 1e-9 relative through the periodic machinery when A is given as a callable."""
    P_ref = solve_continuous_lyapunov(A_CONST.T, -Q3)
    sol = periodic_lyapunov(A_CONST, 2 * np.pi, Q3)
    assert isinstance(sol, PeriodicLyapunovSolution) and sol.constant
    psi = np.linspace(0, 7, 5)
    np.testing.assert_allclose(sol.P(psi), np.broadcast_to(P_ref, (5, 3, 3)), rtol=1e-14)
    np.testing.assert_array_equal(sol.dP(psi), 0.0)
    assert sol.relative_residual < 1e-13
    sol2 = periodic_lyapunov(lambda p: A_CONST, 2 * np.pi, Q3)
    assert not sol2.constant
    scale = np.abs(P_ref).max()
    assert np.abs(sol2.P(psi) - P_ref).max() < 1e-9 * scale
    assert np.abs(sol2.dP(psi)).max() < 1e-9 * scale


def test_damped_mathieu_residual_symmetry_positivity_periodicity():
    """Damped Mathieu: the returned P solves P' + A^T P + P A = -Q (relative residual < 1e-6,
    on the grid and at the midpoints), is symmetric positive definite at 400 azimuths, and is
    T-periodic: P(0) = P(T) from the interpolant, and the backward sweep over one period
    returns to P0 (periodicity_error < 1e-9). The residual is also checked independently at
    azimuths off the grid with A evaluated by the test."""
    A = damped_mathieu()
    T = np.pi
    sol = periodic_lyapunov(A, T)
    assert sol.relative_residual < 1e-6
    assert sol.periodicity_error < 1e-9
    psi = np.linspace(0, T, 400)
    P = sol.P(psi)
    np.testing.assert_array_equal(P, np.swapaxes(P, 1, 2))
    assert np.linalg.eigvalsh(P)[:, 0].min() > 0
    assert sol.min_eigenvalue > 0
    np.testing.assert_allclose(sol.P(T), sol.P(0.0), rtol=1e-12, atol=0)
    np.testing.assert_allclose(sol.P(0.3 + 5 * T), sol.P(0.3), rtol=1e-10)
    Ap = A(psi)
    R = sol.dP(psi) + np.swapaxes(Ap, 1, 2) @ P + P @ Ap + np.eye(2)
    assert np.abs(R).max() < 1e-6 * np.abs(P).max()


def test_P_equals_the_integral_definition():
    """P(psi0) = int_psi0^inf Phi(s, psi0)^T Q Phi(s, psi0) ds: computed here independently by
    integrating x' = A x and the Gramian over 40 periods (|mu|^80 < 1e-16 truncation) from the
    off-grid azimuth psi0 = 0.7; agreement 1e-8 relative."""
    A = damped_mathieu()
    T, psi0 = np.pi, 0.7
    sol = periodic_lyapunov(A, T)

    def rhs(t, y):
        Phi = y[:4].reshape(2, 2)
        return np.concatenate([(A(t) @ Phi).ravel(), (Phi.T @ Phi).ravel()])

    y = solve_ivp(rhs, (psi0, psi0 + 40 * T), np.concatenate([np.eye(2).ravel(), np.zeros(4)]),
                  method="DOP853", rtol=1e-12, atol=1e-14).y[:, -1]
    P_ref = y[4:].reshape(2, 2)
    np.testing.assert_allclose(sol.P(psi0), P_ref, rtol=1e-8)


def test_W_decreases_along_simulated_motions_with_dW_equal_minus_xQx():
    """Along solutions of x' = A(psi) x, W = x^T P x has W' = -x^T Q x < 0.

    Three motions are simulated over three periods (DOP853, rtol 1e-12); W sampled at 3001
    azimuths (h = pi / 1000) decreases monotonically, its fourth-order central finite
    difference matches -x^T Q x to 1e-7 relative (truncation h^4/30 |W^(5)| ~ 1e-10,
    round-off eps |W| / h ~ 1e-13), and the analytic dW(psi, x, A x) matches -x^T Q x to
    1e-8 relative.
    """
    A = damped_mathieu()
    T = np.pi
    Q = np.array([[2.0, 0.3], [0.3, 1.0]])
    sol = periodic_lyapunov(A, T, Q)
    psi = np.linspace(0.2, 0.2 + 3 * T, 3001)
    h = psi[1] - psi[0]
    for x0 in ([1.0, 0.0], [0.0, 1.0], [-0.4, 0.9]):
        traj = solve_ivp(lambda t, x: A(t) @ x, (psi[0], psi[-1]), x0, method="DOP853",
                         t_eval=psi, rtol=1e-12, atol=1e-14)
        x = traj.y.T
        W = sol.W(psi, x)
        assert np.all(np.diff(W) < 0)
        xQx = np.einsum("mi,ij,mj->m", x, Q, x)
        fd = (-W[4:] + 8 * W[3:-1] - 8 * W[1:-3] + W[:-4]) / (12 * h)
        np.testing.assert_allclose(fd, -xQx[2:-2], rtol=1e-7)
        xdot = np.einsum("mij,mj->mi", A(psi), x)
        np.testing.assert_allclose(sol.dW(psi, x, xdot), -xQx, rtol=1e-8)


def test_coupled_four_state_system_with_several_harmonics():
    """A 4 x 4 system with harmonics 1 and 3 (non-normal, coupled): the automatic grid reaches
    relative residual <= 1e-8, P is positive definite, periodic (periodicity_error < 1e-9), and
    the vectorised call gives the same P (1e-9 relative)."""
    A = coupled_periodic()
    scalar = lambda p: A(p)  # noqa: E731
    sol = periodic_lyapunov(scalar, 2 * np.pi)
    assert sol.floquet.stable
    assert sol.relative_residual <= 1e-8
    assert sol.min_eigenvalue > 0 and sol.periodicity_error < 1e-9
    solv = periodic_lyapunov(A, 2 * np.pi, vectorized=True, n_grid=sol.n_grid)
    psi = np.linspace(0, 2 * np.pi, 37)
    np.testing.assert_allclose(solv.P(psi), sol.P(psi), rtol=0, atol=1e-9 * sol.max_eigenvalue)
    assert "PeriodicLyapunovSolution(n=4" in repr(sol)


def test_unstable_A_raises_naming_the_spectral_radius():
    """No positive-definite periodic solution exists when a multiplier is outside the unit
    circle: the damped Mathieu equation inside the first tongue (a, q, c) = (1, 0.5, 0.1)
    grows (|mu| = 1.84) and a constant A with eigenvalues 0.05 +- i as well; both raise a
    ValueError that gives the spectral radius."""
    with pytest.raises(ValueError, match=r"spectral radius of the monodromy matrix is 1\.8"):
        periodic_lyapunov(damped_mathieu(1.0, 0.5, 0.1), np.pi)
    with pytest.raises(ValueError, match="spectral radius"):
        periodic_lyapunov(np.array([[0.05, 1.0], [-1.0, 0.05]]), 2 * np.pi)
    with pytest.raises(ValueError, match="spectral radius"):  # marginal: |mu| = 1
        periodic_lyapunov(damped_mathieu(2.5, 0.5, 0.0), np.pi)


def test_invalid_inputs_raise_clear_errors():
    """Q not symmetric, not positive definite or of the wrong shape; bad period; bad n_grid;
    x of the wrong shape -> ValueError naming the problem."""
    A = damped_mathieu()
    with pytest.raises(ValueError, match="symmetric"):
        periodic_lyapunov(A, np.pi, np.array([[1.0, 0.5], [0.0, 1.0]]))
    with pytest.raises(ValueError, match="positive definite"):
        periodic_lyapunov(A, np.pi, np.diag([1.0, -1.0]))
    with pytest.raises(ValueError, match=r"shape of A, \(2, 2\)"):
        periodic_lyapunov(A, np.pi, np.eye(3))
    with pytest.raises(ValueError, match="period"):
        periodic_lyapunov(A, 0.0)
    with pytest.raises(ValueError, match="n_grid must be an integer >= 2"):
        periodic_lyapunov(A, np.pi, n_grid=1)
    sol = periodic_lyapunov(A_CONST, 1.0)
    with pytest.raises(ValueError, match=r"x must have shape \(m, 3\)"):
        sol.W(0.0, np.ones((4, 2)))


def kinked_mathieu(a=2.5, q=0.5, c=0.3, shift=0.3):
    """y'' + c y' + (a - 2 q |cos(t - shift)|) y = 0: A has a kink (jump of A') at
    t = shift + pi/2, off every uniform grid of the period pi used below."""

    def A(t):
        t = np.asarray(t, dtype=float)
        out = np.zeros(t.shape + (2, 2))
        out[..., 0, 1] = 1.0
        out[..., 1, 0] = -(a - 2.0 * q * np.abs(np.cos(t - shift)))
        out[..., 1, 1] = -c
        return out

    return A


def test_fixed_step_hermite_solution_matches_dop853_fourier():
    """On the smooth damped Mathieu equation the sixth-order Magnus pieces (Van Loan augmented
    system for the Gramians) with cubic Hermite interpolation reproduce the DOP853/Fourier P
    to 1e-7 relative at 301 azimuths, with residual_eigenvalue < 1e-6 and P periodic."""
    A = damped_mathieu()
    ref = periodic_lyapunov(A, np.pi, vectorized=True)
    sol = periodic_lyapunov(A, np.pi, method="magnus6", vectorized=True)
    assert sol.interpolation == "hermite" and sol.method == "magnus6"
    psi = np.linspace(0, 2 * np.pi, 301)
    np.testing.assert_allclose(sol.P(psi), ref.P(psi), rtol=0, atol=1e-7 * ref.max_eigenvalue)
    assert sol.residual_eigenvalue < 1e-6
    assert sol.periodicity_error < 1e-9
    np.testing.assert_allclose(sol.floquet.multipliers, ref.floquet.multipliers, atol=1e-10)


def test_kinked_A_hermite_keeps_W_decreasing():
    """A with a kink: the Fourier interpolant converges only slowly (its residual spreads over
    the period; the automatic grid ends with a RuntimeWarning), while magnus6 with 1024 steps
    and Hermite interpolation keeps the residual matrix below 1e-3 Q (residual_eigenvalue),
    and W = x^T P x still has W' = -x^T Q x to 1e-3 relative along a simulated motion."""
    A = kinked_mathieu()
    with pytest.warns(RuntimeWarning, match="relative residual"):
        fourier = periodic_lyapunov(A, np.pi, vectorized=True)
    sol = periodic_lyapunov(A, np.pi, method="magnus6", n_steps=1024, vectorized=True)
    assert fourier.relative_residual > 1e-6
    assert sol.residual_eigenvalue < 1e-3
    psi = np.linspace(0.0, 2 * np.pi, 2001)
    traj = solve_ivp(lambda t, x: A(t) @ x, (psi[0], psi[-1]), [1.0, 0.5], method="DOP853",
                     t_eval=psi, rtol=1e-12, atol=1e-14)
    x = traj.y.T
    xdot = np.einsum("mij,mj->mi", A(psi), x)
    xQx = np.sum(x * x, axis=1)
    np.testing.assert_allclose(sol.dW(psi, x, xdot), -xQx, rtol=1e-3)
    assert np.all(np.diff(sol.W(psi, x)) < 0)


def test_method_options_are_validated():
    """n_grid belongs to 'dop853', n_steps to the fixed-step methods; unknown interpolation or
    method names are rejected with the allowed values."""
    A = damped_mathieu()
    with pytest.raises(ValueError, match="n_grid applies to method 'dop853' only"):
        periodic_lyapunov(A, np.pi, method="magnus6", n_grid=64)
    with pytest.raises(ValueError, match="n_steps applies to the fixed-step methods"):
        periodic_lyapunov(A, np.pi, n_steps=64)
    with pytest.raises(ValueError, match="interpolation must be one of 'fourier', 'hermite'"):
        periodic_lyapunov(A, np.pi, interpolation="linear")
    with pytest.raises(ValueError, match="method must be one of"):
        periodic_lyapunov(A, np.pi, method="euler")
