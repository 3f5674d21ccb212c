"""Tests of the general engine ``technical_stability`` on systems with hand-derived answers.

Each test's docstring states the fact it checks and how the expected numbers follow.
"""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from rotorlyap import technical_stability
from rotorlyap.methods.examples import mathieu_duffing
from rotorlyap.methods.lyapunov import orbital_derivative

REL = 0.02  # the tolerance for hand-derived answers


def radial_softening():
    """x' = -x (1 - |x|^2) in R^2, W = x1^2 + 2 x2^2.

    W' = 2 (x1 x1' + 2 x2 x2') = -2 (1 - r^2) (x1^2 + 2 x2^2): W' <= 0 exactly for r <= 1.
    """

    def f(psi, x):
        r2 = np.sum(x**2, axis=1, keepdims=True)
        return -x * (1.0 - r2)

    def W(psi, x):
        return x[:, 0] ** 2 + 2.0 * x[:, 1] ** 2

    return f, W


def test_step3_reduces_A_to_the_radius_where_dW_changes_sign():
    """Step 3: W' > 0 on ||x|| = 1.5 but W' <= 0 for r <= 1, so A1 = 1.

    Then alpha = min W on the unit circle = 1 (along x1), and sup W on the circle of radius
    lambda is 2 lambda^2 (along x2), so lambda0 = 1/sqrt(2) at every azimuth; W' < 0 on
    the shell, so every azimuth is certified.
    """
    f, W = radial_softening()
    res = technical_stability(f, W, 1.5, dim=2, n_psi=8)
    assert res.A_requested == 1.5
    assert res.step3_max_dW > 0
    assert res.A == pytest.approx(1.0, rel=REL)
    assert res.alpha == pytest.approx(1.0, rel=REL)
    np.testing.assert_allclose(res.lambda0, 1 / np.sqrt(2), rtol=REL)
    assert res.stable.all()
    assert "from 1.5 to 1" in res.message


def test_lambda0_follows_the_azimuth_dependence_of_W_with_scaled_norm():
    """lambda0 depends on psi; scales a = (2, 0.5) enter the norm.

    f = -x, W = (1 + e cos psi) x1^2 + x2^2 with e = 0.5. On ||x|| = rho, x = rho (2 u1,
    0.5 u2) with |u| = 1, so W = rho^2 (4 (1 + e cos psi) u1^2 + 0.25 u2^2).
    W' = x^T (P' - 2P) x < 0 for all x != 0 (e < 2/... holds), so A stays 1.
    alpha = min over psi and u at rho = 1 = min(4 (1 - e), 0.25) = 0.25;
    sup over the sphere lambda = 4 lambda^2 (1 + e cos psi), so
    lambda0(psi) = 0.25 / sqrt(1 + e cos psi).
    """
    e = 0.5

    def f(psi, x):
        return -x

    def W(psi, x):
        return (1 + e * np.cos(psi)) * x[:, 0] ** 2 + x[:, 1] ** 2

    res = technical_stability(f, W, 1.0, scales=[2.0, 0.5], n_psi=12)
    assert res.A == 1.0
    assert res.alpha == pytest.approx(0.25, rel=REL)
    np.testing.assert_allclose(res.lambda0, 0.25 / np.sqrt(1 + e * np.cos(res.psi)), rtol=REL)
    assert res.lambda0.max() / res.lambda0.min() == pytest.approx(np.sqrt(1.5 / 0.5), rel=REL)
    assert res.stable.all()
    assert np.all(res.max_dW < 0)
    np.testing.assert_allclose(res.psi, 2 * np.pi * np.arange(12) / 12)
    np.testing.assert_allclose(res.scales, [2.0, 0.5])


def caution_system(k1=1.0, k2=4.0, c=0.1, kappa=0.5):
    """Stable linear 2-DOF system whose energy cannot certify anything.

    q1'' = -k1 q1 - c q1' + kappa q2, q2'' = -k2 q2 - c q2' (triangular: eigenvalues of two
    damped oscillators, all with real part -c/2). With W = (v1^2 + v2^2 + k1 q1^2 +
    k2 q2^2)/2, W' = -c (v1^2 + v2^2) + kappa v1 q2: at q2 = rho cos t, v1 = rho sin t,
    W' = rho^2 sin t (kappa cos t - c sin t) > 0 for small t > 0, on every sphere.
    """

    def f(psi, x):
        q1, q2, v1, v2 = x.T
        return np.stack([v1, v2, -k1 * q1 - c * v1 + kappa * q2, -k2 * q2 - c * v2], axis=1)

    def W(psi, x):
        q1, q2, v1, v2 = x.T
        return 0.5 * (v1**2 + v2**2 + k1 * q1**2 + k2 * q2**2)

    return f, W


def test_nothing_certified_when_dW_is_positive_on_every_sphere():
    """Step 3 finds W' > 0 on every sphere: A = 0, all azimuths unstable, no exception."""
    f, W = caution_system()
    res = technical_stability(f, W, 1.0, dim=4, n_psi=6, n_sphere=256)
    assert res.A == 0.0
    assert res.alpha == 0.0
    assert not res.stable.any()
    assert not res.certified
    np.testing.assert_array_equal(res.lambda0, 0.0)
    assert np.all(res.max_dW > 0)
    assert "nothing certified" in res.message
    # the state found has q2 large and v1 small with the sign of kappa q2
    x = res.argmax_dW[0]
    assert x[2] * x[1] > 0


def test_orbital_derivative_matches_the_exact_formula():
    """The finite-difference W' along (1, f) equals the closed-form W' of the toy system."""
    sys = mathieu_duffing()
    rng = np.random.default_rng(1)
    x = rng.normal(size=(500, 2))
    psi = rng.uniform(0, 2 * np.pi, 500)
    exact = sys.dW(psi, x)
    approx = orbital_derivative(sys.f, sys.W, psi, x)
    np.testing.assert_allclose(approx, exact, rtol=1e-6, atol=1e-8 * np.abs(exact).max())


@pytest.fixture(scope="module")
def toy_certificate():
    """The engine on the toy oscillator with its exact ``W'`` at 12 azimuths (computed once for
    the tests below: some 5e7 evaluations of ``W'``, seconds of one core)."""
    sys = mathieu_duffing()
    return technical_stability(sys.f, sys.W, 1.0, dim=2, n_psi=12, dW=sys.dW)


def test_engine_with_and_without_exact_dW_agree(toy_certificate):
    """Computing W' internally gives the same certificate as passing the exact W'."""
    sys = mathieu_duffing()
    a = toy_certificate
    b = technical_stability(sys.f, sys.W, 1.0, dim=2, n_psi=12)
    assert a.A == pytest.approx(b.A, rel=1e-3)
    np.testing.assert_allclose(a.lambda0, b.lambda0, rtol=1e-3)
    np.testing.assert_array_equal(a.stable, b.stable)


def test_same_call_gives_the_same_numbers(toy_certificate):
    """Determinism: quasi-random sampling with a fixed seed (the same call as the module's
    certificate, made again)."""
    sys = mathieu_duffing()
    a = toy_certificate
    b = technical_stability(sys.f, sys.W, 1.0, dim=2, n_psi=12, dW=sys.dW)
    np.testing.assert_array_equal(a.lambda0, b.lambda0)
    assert a.A == b.A and a.alpha == b.alpha


@pytest.mark.slow
def test_trajectories_started_inside_lambda0_stay_inside_A(toy_certificate):
    """The theorem's conclusion, by simulation of the toy oscillator.

    From the worst starts (on the sphere of radius 0.999 lambda0 at the certified azimuths),
    integrated for 30 periods, the scaled norm never reaches A.
    """
    sys = mathieu_duffing()
    res = toy_certificate
    assert res.A < 1.0  # the softening spring forces step 3 to reduce A
    assert res.stable.all()
    assert np.ptp(res.lambda0) > 0.01 * res.lambda0.mean()  # lambda0 varies with psi
    t = np.linspace(0, 2 * np.pi, 16, endpoint=False)
    starts = np.stack([np.cos(t), np.sin(t)], axis=1)
    worst = 0.0
    for j in range(0, 12, 3):
        psi0 = res.psi[j]
        x0 = 0.999 * res.lambda0[j] * starts  # the 16 motions of one azimuth as one system
        sol = solve_ivp(
            lambda p, x: sys.f(np.full(len(starts), p), x.reshape(-1, 2)).reshape(-1),
            (psi0, psi0 + 30 * 2 * np.pi), x0.reshape(-1), rtol=1e-9, atol=1e-12, max_step=0.1,
        )
        worst = max(worst, np.linalg.norm(sol.y.reshape(len(starts), 2, -1), axis=1).max())
    assert worst < res.A


@pytest.mark.parametrize(
    "kwargs, match",
    [
        (dict(A=0.0), "A must be a finite number > 0"),
        (dict(A=-1.0), "A must be a finite number > 0"),
        (dict(A=np.nan), "A must be a finite number > 0"),
        (dict(period=0.0), "period must be a finite number > 0"),
        (dict(scales=[1.0, 0.0]), "every scale a_i must be finite and > 0"),
        (dict(scales=[1.0, -2.0]), "every scale a_i must be finite and > 0"),
        (dict(n_psi=0), "n_psi must be an integer >= 1"),
    ],
)
def test_bad_input_is_rejected_with_a_clear_message(kwargs, match):
    """Non-physical or inconsistent arguments raise ValueError naming the problem."""
    f, W = radial_softening()
    args = dict(A=1.0, scales=[1.0, 1.0])
    args.update(kwargs)
    A = args.pop("A")
    with pytest.raises(ValueError, match=match):
        technical_stability(f, W, A, **args)


def test_shapes_that_do_not_match_are_rejected():
    """f must return one row per state and as many columns as the norm has scales."""

    def f(psi, x):
        return -x[:, :2]

    def W(psi, x):
        return np.sum(x**2, axis=1)

    with pytest.raises(ValueError, match=r"f\(psi, x\) returned shape \(1, 2\) for x of shape \(1, 3\)"):
        technical_stability(f, W, 1.0, scales=[1.0, 1.0, 1.0])
    with pytest.raises(ValueError, match=r"W\(psi, x\) returned shape"):
        technical_stability(lambda p, x: -x, lambda p, x: x**2, 1.0, dim=2)
    with pytest.raises(ValueError, match="dim=3 does not match len"):
        technical_stability(f, W, 1.0, scales=[1.0, 1.0], dim=3)


def test_non_finite_W_is_reported_with_the_offending_state():
    """A W that returns NaN somewhere raises ValueError, never a silent NaN result."""
    f, _ = radial_softening()

    def W(psi, x):
        out = np.sum(x**2, axis=1)
        return np.where(x[:, 0] > 0.9, np.nan, out)

    with pytest.raises(ValueError, match="W\\(psi, x\\) returned a non-finite value at psi="):
        technical_stability(f, W, 1.0, dim=2, n_psi=4)


def test_type_errors_for_missing_dimension_and_non_callables():
    """Without scales the dimension is required; f and W must be callables."""
    f, W = radial_softening()
    with pytest.raises(TypeError, match="scales=.*or the state dimension dim"):
        technical_stability(f, W, 1.0)
    with pytest.raises(TypeError, match="f must be callable"):
        technical_stability(3.0, W, 1.0, dim=2)
    with pytest.raises(TypeError, match="W must be callable"):
        technical_stability(f, None, 1.0, dim=2)


def test_practical_reading_along_the_axes_misses_what_the_strict_reading_finds():
    """The practical reading is an indicator, not a certificate.

    For the caution system, W' = -c (v1^2 + v2^2) + kappa v1 q2 is <= 0 at every state with
    only one non-zero component (the signed coordinate axes), so the practical reading along
    the axes reports every azimuth stable, while the strict reading finds W' > 0 on every
    sphere and certifies nothing.
    """
    f, W = caution_system()
    axes = np.vstack([np.eye(4), -np.eye(4)])
    practical = technical_stability(f, W, 1.0, dim=4, n_psi=6, test_directions=axes)
    strict = technical_stability(f, W, 1.0, dim=4, n_psi=6, n_sphere=256)
    assert practical.reading == "practical" and strict.reading == "strict"
    assert practical.stable.all()
    assert not practical.certified  # the practical reading never certifies
    assert practical.message.startswith("the indicator holds")  # an indicator, never "certified"
    assert not strict.stable.any()
    # along the axes alpha = min(k1, k2, 1)/2 at A = 1, and sup W on the sphere lambda is
    # max(k1, k2, 1) lambda^2 / 2: lambda0 = sqrt(min/max) = sqrt(1/4)
    assert practical.alpha == pytest.approx(0.5, rel=REL)
    np.testing.assert_allclose(practical.lambda0, 0.5, rtol=REL)


def test_test_directions_are_validated():
    """Test directions must be non-zero rows of the state dimension."""
    f, W = radial_softening()
    with pytest.raises(ValueError, match=r"test_directions must have shape \(k, 2\)"):
        technical_stability(f, W, 1.0, dim=2, test_directions=np.eye(3))
    with pytest.raises(ValueError, match="finite and non-zero"):
        technical_stability(f, W, 1.0, dim=2, test_directions=[[0.0, 0.0]])
