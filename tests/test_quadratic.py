"""The quadratic Liapunov function of the blade (rotorlyap.analysis.functions)."""

import numpy as np
import pytest

from rotorlyap import Blade, BladeParameters
from rotorlyap.analysis.functions import (
    certified_radius_estimate, optimised_quadratic_function, quadratic_function,
)
from rotorlyap.errors import NotAsymptoticallyStableError
from rotorlyap.methods.sampling import unit_sphere_points
from rotorlyap.analysis.stability import blade_stability
from rotorlyap.conventions import DEFAULT_SCALES

A = DEFAULT_SCALES


@pytest.fixture(scope="module")
def hover(forward, forward_hover):
    """Forward-C.G. blade in hover, its quadratic function and certificate."""
    q = quadratic_function(forward_hover)
    res = blade_stability(forward, 0.0, lyapunov=quadratic_function, n_psi=4, n_sphere=128)
    return forward, forward_hover, q, res


@pytest.fixture(scope="module")
def forward_flight(forward, forward_periodic_015):
    """Forward C.G. at mu = 0.15 about its periodic motion (256 collocation points, tabulated)."""
    b = Blade(forward, 0.15)
    return forward, b, forward_periodic_015, quadratic_function(b, forward_periodic_015)


def test_hover_quadratic_function_decreases_near_the_origin(hover):
    """Linearly stable hover (forward C.G.): W' = -x^T Q x + O(|x|^3) < 0 on small spheres,
    with the full nonlinear right-hand side; with the default Q = diag(1/a^2), W' = -||x||^2."""
    _, _, q, _ = hover
    assert q.constant and q.spectral_radius < 1.0 and q.growth_rate < 0.0
    dirs = unit_sphere_points(6, 256, 3)
    for r in (1e-4, 1e-2, 0.1):
        x = r * dirs * A
        dw = q.dW(np.zeros(len(x)), x)
        assert np.all(dw < 0.0)
        if r == 1e-4:
            np.testing.assert_allclose(dw, -r**2, rtol=1e-3)
    assert np.all(q.W(np.zeros(len(dirs)), 0.1 * dirs * A) > 0.0)


def test_engine_certifies_a_nonempty_hover_region_in_the_strict_reading(hover):
    """The engine certifies a real start region with the quadratic function (strict reading),
    where the energy function certifies nothing."""
    p, _, _, res = hover
    assert res.reading == "strict" and res.certified
    assert res.stable.all() and res.A > 0.1 and res.lambda0.min() > 0.01
    energy = blade_stability(p, 0.0, n_psi=4, n_sphere=128)
    assert not energy.certified


def test_targeted_search_finds_no_positive_derivative_on_the_certified_shell(hover):
    """The energy's failure mode (one hinge displaced, another hinge's rate small) does not
    occur for the quadratic function: W' <= 0 on such states across the certified shell."""
    _, _, q, res = hover
    lam, A1 = float(res.lambda0.min()), float(res.A)
    states = []
    for i in range(3):  # displaced hinge
        for j in range(3, 6):  # small rate
            for s_i in (1.0, -1.0):
                for s_j in (1.0, -1.0):
                    for eps in (1e-3, 1e-2, 0.1, 0.3):
                        d = np.zeros(6)
                        d[i], d[j] = s_i, s_j * eps
                        states.append(d / np.linalg.norm(d))
    states = np.array(states)
    for r in np.linspace(lam * 1.0001, A1, 7):
        dw = q.dW(np.zeros(len(states)), r * states * A)
        assert dw.max() <= res.tol


def test_periodic_P_solves_the_lyapunov_equation(forward_flight):
    """About the periodic motion at mu = 0.15, W' along the *linearised* motion equals
    -x^T Q x up to the residual of the periodic Lyapunov equation."""
    _, _, _, q = forward_flight
    assert not q.constant and q.spectral_radius < 1.0 and q.relative_residual < 1e-3
    psi = np.linspace(0.1, 2 * np.pi, 9)
    x = 1e-3 * unit_sphere_points(6, 0, 0)[:9] * A
    np.testing.assert_allclose(q.dW_linear(psi, x), -np.sum((x / A) ** 2, axis=1), rtol=2e-2)
    # the interpolated P and its derivative are consistent (P' is the derivative of P)
    h = 1e-5
    np.testing.assert_allclose((q.P(psi + h) - q.P(psi - h)) / (2 * h), q.dP(psi), rtol=1e-4,
                               atol=1e-6 * np.abs(q.P(psi)).max())


def test_the_fused_rate_is_the_rate_of_the_separate_kernels_to_the_last_bit(forward_flight):
    """About a tabulated periodic motion W' runs in one compiled call
    (rotorlyap.analysis.fused): the same numbers, bit for bit, as the motion's, the blade's and
    the Hermite form's kernels called one after the other, for one state, a block and more,
    azimuths outside [0, 2 pi) included."""
    import copy

    _, _, _, q = forward_flight
    separate = copy.copy(q)
    object.__setattr__(separate, "_fused_args", None)  # the path of the separate kernels
    assert q._fused() is not None and separate._fused() is None
    rng = np.random.default_rng(3)
    for m in (1, 7, 300):
        psi = rng.uniform(-5.0, 15.0, m)
        x = 0.05 * rng.normal(size=(m, 6))
        assert np.array_equal(q.dW(psi, x), separate.dW(psi, x)), m
    with pytest.raises(ValueError, match="psi must be finite"):
        q.dW(np.array([np.nan]), np.zeros((1, 6)))


def test_the_rays_rate_is_the_search_map_and_rate_to_the_last_bit(forward_flight):
    """The band search's map of a search coordinate to its state on the ray and W' there, in
    one compiled call (QuadraticFunction.ray_rate): the numbers of the search's own numpy map
    (rotorlyap.methods.lyapunov.band_max_dw) followed by W', bit for bit; a zero coordinate
    (the ray's level point) and coordinates beyond the sphere (clipped) included."""
    from rotorlyap.methods import lyapunov

    _, _, _, q = forward_flight
    rng = np.random.default_rng(5)
    c, bound = 0.3 * 0.05**2, 0.05
    w_matrix = lambda psi: A[:, None] * q.P(psi) * A[None, :]  # noqa: E731
    for m in (1, 9, 400):
        psi = rng.uniform(-5.0, 15.0, m)
        y = rng.normal(size=(m, 6)) * rng.uniform(0.0, 0.8, (m, 1))
        y[0] = 0.0
        checked = lyapunov._Checked(q.f, q.W, q.dW, 6, 1e-4)
        t = np.linalg.norm(y, axis=1)
        u = y / np.maximum(t, 1e-300)[:, None]
        rc = lyapunov._ray_level(checked, psi, u, A, c, bound, w_matrix)
        x = (u * (rc + np.clip(t, 0.0, 1.0) * (bound - rc))[:, None]) * A
        w_unit, rate = q.ray_rate(psi, y, c, bound, A)
        assert np.array_equal(rate, q.dW(psi, x)), m
        assert np.array_equal(w_unit, q.W(psi, u * A)), m
    with pytest.raises(ValueError, match="psi must be finite"):
        q.ray_rate(np.array([np.inf]), np.ones((1, 6)), c, bound, A)


@pytest.mark.slow
def test_certificate_about_the_periodic_motion_in_forward_flight(forward_flight):
    """The engine certifies the forward-flight blade about its periodic motion (strict)."""
    p, _, tab, q = forward_flight
    res = blade_stability(p, 0.15, lyapunov=lambda bl, steady: q, steady=tab, n_psi=6, n_sphere=128)
    assert res.certified and res.stable.all() and res.lambda0.min() > 0.01


def test_paper_steady_motion_gives_a_derivative_linear_in_x():
    """About the hover equilibrium reused at mu = 0.15 (not a solution), W'(eps d)/eps tends
    to 2 d^T P f(psi, 0) != 0, of either sign: W' > 0 on every small sphere."""
    p = BladeParameters.table_i("forward")
    b = Blade(p, 0.15)
    q = quadratic_function(b, Blade(p, 0.0).equilibrium())
    psi = np.radians([30.0, 120.0, 210.0, 300.0])
    d = np.tile(np.array([0, 0, 0, 1.0, 0, 0]) * A, (4, 1))
    lin = 2 * np.einsum("mi,mij,mj->m", d, q.P(psi), q.f(psi, np.zeros((4, 6))))
    for eps in (1e-4, 1e-5):
        np.testing.assert_allclose(q.dW(psi, eps * d) / eps, lin, rtol=1e-2)
    assert np.abs(lin).min() > 0.1
    assert (q.dW(psi, 1e-5 * d) > 0).any() or (q.dW(psi, -1e-5 * d) > 0).any()


def test_unstable_linearisation_raises_a_clear_error():
    """Backward C.G. without aerodynamic pitch damping (hover flutter): no quadratic function
    exists; the error says why."""
    b = Blade(BladeParameters.table_i("backward", cm_pitch_rate=0.0), 0.0)
    with pytest.raises(NotAsymptoticallyStableError, match=r"not asymptotically stable.*spectral radius.*2\.0") as info:
        quadratic_function(b)
    assert info.value.spectral_radius > 2.0 and info.value.growth_rate > 0  # the numbers travel with it
    assert isinstance(info.value, ValueError)


def test_default_steady_motion_is_the_hover_equilibrium_and_a_bad_Q_is_refused(hover):
    """quadratic_function(b) is the function about the hover equilibrium; a bad Q is refused."""
    _, b, q, _ = hover
    np.testing.assert_allclose(quadratic_function(b, b.equilibrium()).P(0.0), q.P(0.0))
    with pytest.raises(ValueError, match="positive definite"):
        quadratic_function(b, Q=-np.ones(6))
    with pytest.raises(ValueError, match="scales"):
        quadratic_function(b, scales=[1.0, 2.0])


def test_optimised_weights_enlarge_the_estimated_start_region(hover):
    """The optimised diagonal Q gives a larger estimated lambda0 than Q = I (the objective)."""
    _, b, q, _ = hover
    qo = optimised_quadratic_function(b, max_evaluations=60)
    assert certified_radius_estimate(qo, 1.0)[1] > 1.5 * certified_radius_estimate(q, 1.0)[1]
    assert np.allclose(qo.Q, np.diag(np.diag(qo.Q)))
