"""Tests of ``rotorlyap.methods.floquet`` on systems whose Floquet multipliers are known independently.

Each test's docstring states the fact it checks and where the expected numbers come from.

Mathieu equation, DLMF ch. 28 / Abramowitz & Stegun ch. 20 notation:
``y'' + (a - 2 q cos 2t) y = 0``, state ``x = (y, y')``, period ``pi``. On the characteristic
curves ``a = a_r(q)`` (even periodic solution) and ``a = b_r(q)`` (odd periodic solution) the
equation has a solution of period ``pi`` (r even: double multiplier +1) or ``2 pi`` (r odd:
double multiplier -1), so the trace of the monodromy matrix is +2 or -2 there: these curves
are the boundaries of stability (DLMF 28.2(iv) and 28.17, A&S 20.3).

The characteristic values are computed here independently of the package by Hill's method
(DLMF 28.4(i), A&S 20.2.21-24: the Fourier-coefficient recurrences written as symmetric
tridiagonal eigenproblems, truncated at 60 terms, :func:`scipy.linalg.eigvalsh_tridiagonal`).
That computation is itself checked against the power series DLMF 28.6.1-28.6.5 (= A&S 20.2.25)
at q = 0.1, and against the 9-decimal values at q = 1 quoted in issue 5 (a_0 = -0.455138604,
b_1 = -0.110248816, a_1 = 1.859108072, b_2 = 3.917024772, a_2 = 4.371300982). Those digits
could not be read from a table (DLMF 28.35 lists Ince (1932), q = 0(1)10, 7D; A&S Table 20.1
starts at q = 5 in the copy reachable): they agree to 1e-9 with the Hill computation here
(for b_1 and b_2 the quoted 9th decimal is truncated, not rounded: true values -0.1102488170
and 3.9170247730) and with :func:`scipy.special.mathieu_a` / ``mathieu_b``.
"""

import numpy as np
import pytest
from scipy.linalg import eigvalsh_tridiagonal, expm

from rotorlyap.methods.examples import mathieu_matrix
from rotorlyap.methods.floquet import (
    METHODS,
    FloquetResult,
    floquet_multipliers,
    modal_properties,
    monodromy,
)

# --------------------------------------------------------------------------------------
# helpers
# --------------------------------------------------------------------------------------


def mathieu(a: float, q: float, c: float = 0.0):
    """A(t) of y'' + c y' + (a - 2 q cos 2t) y = 0, called with a scalar t and vectorised
    (one function, rotorlyap.methods.examples.mathieu_matrix, serves both)."""
    A = mathieu_matrix(a, q, c)
    return A, A


def hill(family: str, q: float, size: int = 60) -> np.ndarray:
    """Mathieu characteristic values by Hill's method (DLMF 28.4(i), A&S 20.2.21-24).

    family: "a_even" -> a_0, a_2, ... (cos 2rt); "b_even" -> b_2, b_4, ... (sin 2rt, r >= 1);
    "a_odd" -> a_1, a_3, ... (cos (2r+1)t); "b_odd" -> b_1, b_3, ... (sin (2r+1)t).
    The recurrence (a - k^2) A_k = q (A_{k-2} + A_{k+2}) is a symmetric tridiagonal eigenproblem
    with diagonal k^2 and off-diagonal q, except: a_even couples A_0 and A_2 by sqrt(2) q
    (after scaling A_0), a_odd / b_odd have the first diagonal 1 + q / 1 - q.
    """
    r = np.arange(size, dtype=float)
    e = np.full(size - 1, q)
    if family == "a_even":
        d = (2 * r) ** 2
        e[0] = np.sqrt(2.0) * q
    elif family == "b_even":
        d = (2 * r + 2) ** 2
    elif family == "a_odd":
        d = (2 * r + 1) ** 2
        d[0] += q
    elif family == "b_odd":
        d = (2 * r + 1) ** 2
        d[0] -= q
    else:
        raise ValueError(family)
    return eigvalsh_tridiagonal(d, e)


def characteristic_value(name: str, q: float) -> float:
    return {
        "a0": lambda: hill("a_even", q)[0],
        "a2": lambda: hill("a_even", q)[1],
        "b2": lambda: hill("b_even", q)[0],
        "a1": lambda: hill("a_odd", q)[0],
        "b1": lambda: hill("b_odd", q)[0],
    }[name]()


QUOTED_Q1 = {  # issue 5, q = 1
    "a0": -0.455138604,
    "b1": -0.110248816,
    "a1": 1.859108072,
    "b2": 3.917024772,
    "a2": 4.371300982,
}
# trace of the monodromy on the curve, and whether a slightly larger a is stable
BOUNDARY = {
    "a0": (+2.0, True),
    "b1": (-2.0, False),
    "a1": (-2.0, True),
    "b2": (+2.0, False),
    "a2": (+2.0, True),
}


# --------------------------------------------------------------------------------------
# damped oscillator: closed form
# --------------------------------------------------------------------------------------

ZETA, OMEGA, T_OSC = 0.1, 2.0, 2 * np.pi
A_OSC = np.array([[0.0, 1.0], [-OMEGA**2, -2 * ZETA * OMEGA]])
LAMBDA = np.array([-ZETA * OMEGA + 1j * OMEGA * np.sqrt(1 - ZETA**2),
                   -ZETA * OMEGA - 1j * OMEGA * np.sqrt(1 - ZETA**2)])


@pytest.mark.parametrize("method", METHODS)
def test_damped_oscillator_multipliers_are_exp_lambda_T(method):
    """x'' + 2 zeta w x' + w^2 x = 0: multipliers exp(lambda T), lambda = -zeta w +- i w_d.

    The equation has constant coefficients, so Phi(T) = expm(A T) and the multipliers are
    exp(lambda T) with lambda the roots of s^2 + 2 zeta w s + w^2 (closed form), to 1e-9,
    for every integrator with its default accuracy. The modulus is exp(-zeta w T) < 1:
    asymptotically stable.
    """
    res = floquet_multipliers(lambda psi: A_OSC, T_OSC, method=method)
    expected = np.exp(LAMBDA * T_OSC)
    expected = expected[np.argsort(-expected.imag)]  # equal moduli: +imag first
    assert isinstance(res, FloquetResult)
    np.testing.assert_allclose(res.multipliers, expected, atol=1e-9, rtol=0)
    np.testing.assert_allclose(np.exp(res.exponents * T_OSC), res.multipliers, atol=1e-12)
    np.testing.assert_allclose(res.monodromy, expm(A_OSC * T_OSC), atol=1e-9, rtol=0)
    assert res.spectral_radius == pytest.approx(np.exp(-ZETA * OMEGA * T_OSC), abs=1e-9)
    assert res.stable
    assert res.liouville_error < 1e-9


def test_constant_array_gives_exact_exponents_and_modal_properties():
    """A constant array: M = expm(A T) exactly and the exponents are the eigenvalues of A.

    So modal_properties with branch 0 returns the oscillator's natural frequency w, damping
    ratio zeta and damped frequency w sqrt(1 - zeta^2) (closed form, 1e-12).
    """
    res = floquet_multipliers(A_OSC, T_OSC)
    assert res.method == "expm"
    np.testing.assert_allclose(np.sort_complex(res.exponents), np.sort_complex(LAMBDA),
                               atol=1e-12)
    np.testing.assert_allclose(res.multipliers, np.exp(res.exponents * T_OSC), atol=1e-12)
    mp = res.modal_properties()
    np.testing.assert_allclose(mp.natural_frequency, OMEGA, rtol=1e-12)
    np.testing.assert_allclose(mp.damping_ratio, ZETA, rtol=1e-12)
    np.testing.assert_allclose(np.sort(mp.frequency), [-OMEGA * np.sqrt(1 - ZETA**2),
                                                       OMEGA * np.sqrt(1 - ZETA**2)], rtol=1e-12)
    np.testing.assert_allclose(mp.growth_rate, -ZETA * OMEGA, rtol=1e-12)
    np.testing.assert_allclose(mp.frequency_ratio, mp.frequency, rtol=1e-12)  # T = 2 pi


def test_principal_exponents_recover_frequency_with_the_right_branch():
    """Exponents from a callable A are principal values: Im eta in (-pi/T, pi/T].

    The true damped frequency w_d = 2 sqrt(0.99) = 1.990 (rad per unit psi) with T = 2 pi is
    outside (-1/2, 1/2], so the principal values are +-(w_d - 2); branches -+2 (k 2 pi / T
    with k = -+2) restore +-w_d, hence w and zeta exactly, while the growth rate -zeta w is
    branch-independent. With T = pi the frequency ratio is frequency / 2.
    """
    res = floquet_multipliers(lambda psi: A_OSC, T_OSC)
    assert np.all(np.abs(res.exponents.imag) <= np.pi / T_OSC + 1e-12)
    wd = OMEGA * np.sqrt(1 - ZETA**2)
    np.testing.assert_allclose(np.sort(res.exponents.imag), [wd - 2.0, 2.0 - wd], atol=1e-9)
    target = np.sign(-res.exponents.imag) * wd  # the principal value wd - 2 < 0 belongs to +wd
    branch = np.round((target - res.exponents.imag) * T_OSC / (2 * np.pi)).astype(int)
    assert sorted(branch) == [-2, 2]
    mp = modal_properties(res.exponents, T_OSC, branch=branch)
    np.testing.assert_allclose(mp.frequency, target, atol=1e-9)
    np.testing.assert_allclose(mp.natural_frequency, OMEGA, atol=1e-9)
    np.testing.assert_allclose(mp.damping_ratio, ZETA, atol=1e-9)
    np.testing.assert_allclose(mp.growth_rate, -ZETA * OMEGA, atol=1e-9)
    mp_pi = modal_properties(1j * np.array([1.5]), np.pi, branch=1)
    assert mp_pi.frequency[0] == pytest.approx(3.5)
    assert mp_pi.frequency_ratio[0] == pytest.approx(1.75)
    assert mp_pi.damping_ratio[0] == pytest.approx(0.0)


# --------------------------------------------------------------------------------------
# Mathieu equation
# --------------------------------------------------------------------------------------


def test_hill_characteristic_values_match_dlmf_series_and_quoted_values():
    """The independent Hill computation reproduces DLMF 28.6.1-28.6.5 and the quoted values.

    At q = 0.1 the power series (DLMF 28.6.1-5, A&S 20.2.25, terms to q^8) are accurate to
    about 1e-13, and Hill's method must agree to 1e-11. At q = 1 the 9-decimal values quoted
    in issue 5 must agree to 1e-9 (9 decimals, truncated or rounded).
    """
    q = 0.1
    series = {
        "a0": -q**2 / 2 + 7 * q**4 / 128 - 29 * q**6 / 2304 + 68687 * q**8 / 18874368,
        "a1": (1 + q - q**2 / 8 - q**3 / 64 - q**4 / 1536 + 11 * q**5 / 36864
               + 49 * q**6 / 589824 + 55 * q**7 / 9437184 - 83 * q**8 / 35389440),
        "b1": (1 - q - q**2 / 8 + q**3 / 64 - q**4 / 1536 - 11 * q**5 / 36864
               + 49 * q**6 / 589824 - 55 * q**7 / 9437184 - 83 * q**8 / 35389440),
        "b2": 4 - q**2 / 12 + 5 * q**4 / 13824 - 289 * q**6 / 79626240
        + 21391 * q**8 / 458647142400,
        "a2": 4 + 5 * q**2 / 12 - 763 * q**4 / 13824 + 1002401 * q**6 / 79626240
        - 1669068401 * q**8 / 458647142400,
    }
    for name, value in series.items():
        assert characteristic_value(name, q) == pytest.approx(value, abs=1e-11), name
    for name, value in QUOTED_Q1.items():
        assert characteristic_value(name, 1.0) == pytest.approx(value, abs=1e-9), name


@pytest.mark.parametrize("name", list(QUOTED_Q1))
def test_mathieu_trace_is_plus_minus_two_on_characteristic_curves(name):
    """On a_0, b_1, a_1, b_2, a_2 at q = 1 the monodromy trace is +2, -2, -2, +2, +2.

    With a from Hill's method (machine precision) |trace -+ 2| < 1e-9. The stability boundary
    also lies within 1e-8 of the quoted 9-decimal value: |trace| - 2 changes sign between
    a_quoted - 1e-8 and a_quoted + 1e-8, with the stable side (|trace| < 2) on the side the
    Ince-Strutt diagram gives (above a_0, a_1, a_2; below b_1, b_2).
    """
    q = 1.0
    sign, stable_above = BOUNDARY[name]
    a = characteristic_value(name, q)
    A, _ = mathieu(a, q)
    assert np.trace(monodromy(A, np.pi)) == pytest.approx(sign, abs=1e-9)

    def excess(a_):
        return abs(np.trace(monodromy(mathieu(a_, q)[0], np.pi))) - 2.0

    below, above = excess(QUOTED_Q1[name] - 1e-8), excess(QUOTED_Q1[name] + 1e-8)
    if stable_above:
        assert below > 0 > above
    else:
        assert below < 0 < above


@pytest.mark.parametrize("method", ["magnus6", "rk4"])
def test_mathieu_boundary_with_fixed_step_methods(method):
    """The fixed-step integrators also give trace(M) = +2 on a_0(1) to 1e-9 (default
    step doubling), sampling A on their grids with one vectorised call per refinement."""
    a = characteristic_value("a0", 1.0)
    _, Av = mathieu(a, 1.0)
    res = floquet_multipliers(Av, np.pi, method=method, vectorized=True)
    assert np.trace(res.monodromy) == pytest.approx(2.0, abs=1e-9)
    assert res.n_steps is not None and res.error_estimate < 1e-9


def test_inside_first_instability_tongue_a_multiplier_exceeds_one():
    """(a, q) = (1, 0.5) lies in the first tongue: b_1(0.5) = 0.4707 < 1 < a_1(0.5) = 1.4668.

    There the multipliers are a real negative pair mu, 1/mu (trace A = 0, so det M = 1 by
    Liouville) with |mu| > 1: unstable. At the centre of the tongue first-order perturbation
    theory gives the growth rate Re eta = q/2 + O(q^2); checked at q = 0.1 to q^2 / 10.
    """
    q = 0.5
    assert characteristic_value("b1", q) < 1.0 < characteristic_value("a1", q)
    res = floquet_multipliers(mathieu(1.0, q)[0], np.pi)
    assert res.spectral_radius > 1.0 and not res.stable
    assert np.all(np.abs(res.multipliers.imag) < 1e-12)
    assert np.all(res.multipliers.real < 0)
    assert np.prod(res.multipliers).real == pytest.approx(1.0, abs=1e-10)
    assert np.linalg.det(res.monodromy) == pytest.approx(1.0, abs=1e-10)
    # negative real multiplier: Im eta = pi / T exactly (branch ambiguity at its extreme)
    assert res.exponents[0].imag == pytest.approx(np.pi / np.pi)
    q = 0.1
    growth = floquet_multipliers(mathieu(1.0, q)[0], np.pi).exponents[0].real
    assert abs(growth - q / 2) < q**2 / 10


def test_stable_mathieu_multipliers_lie_on_the_unit_circle():
    """(a, q) = (2.5, 0.5) lies between a_1(0.5) = 1.4668 and b_2(0.5) = 3.9792: stable.

    The undamped Mathieu equation is Hamiltonian, so det M = exp(int trace A) = 1 (Liouville)
    and in a stable region both multipliers are a complex-conjugate pair on the unit circle:
    |mu| = 1 to 1e-10. That is marginal stability, so ``stable`` (asymptotic) is False.
    """
    q = 0.5
    assert characteristic_value("a1", q) < 2.5 < characteristic_value("b2", q)
    res = floquet_multipliers(mathieu(2.5, q)[0], np.pi)
    np.testing.assert_allclose(np.abs(res.multipliers), 1.0, atol=1e-10)
    assert abs(res.multipliers[0].imag) > 0.1
    assert res.multipliers[0] == pytest.approx(np.conj(res.multipliers[1]), abs=1e-12)
    assert abs(np.trace(res.monodromy)) < 2.0
    assert res.trace_integral == pytest.approx(0.0, abs=1e-12)
    assert np.linalg.det(res.monodromy) == pytest.approx(np.exp(res.trace_integral), abs=1e-10)
    assert not res.stable
    np.testing.assert_allclose(res.exponents.real, 0.0, atol=1e-10)


def test_damped_mathieu_obeys_liouville_and_is_stable():
    """With damping c: trace A = -c, so det M = exp(-c T) (Liouville), and in the stable
    region of the undamped equation the pair keeps equal moduli exp(-c T / 2) < 1."""
    c = 0.2
    res = floquet_multipliers(mathieu(2.5, 0.5, c)[0], np.pi)
    assert res.trace_integral == pytest.approx(-c * np.pi, rel=1e-12)
    assert np.linalg.det(res.monodromy) == pytest.approx(np.exp(-c * np.pi), rel=1e-10)
    np.testing.assert_allclose(np.abs(res.multipliers), np.exp(-c * np.pi / 2), rtol=1e-10)
    assert res.stable
    np.testing.assert_allclose(res.modal_properties().growth_rate, -c / 2, atol=1e-10)


# --------------------------------------------------------------------------------------
# integrators
# --------------------------------------------------------------------------------------


@pytest.mark.parametrize("method, order", [("magnus6", 6), ("magnus4", 4), ("rk4", 4)])
def test_fixed_step_methods_converge_at_their_order(method, order):
    """Halving the step divides the monodromy error by 2**order (6 for the sixth-order Magnus
    scheme, 4 for the fourth-order Magnus and RK4), measured against DOP853 at rtol 1e-13."""
    A, Av = mathieu(2.5, 0.5, 0.2)
    ref = monodromy(A, np.pi, rtol=1e-13, atol=1e-15)
    err = [np.abs(monodromy(Av, np.pi, method=method, n_steps=n, vectorized=True) - ref).max()
           for n in (16, 32)]
    assert np.log2(err[0] / err[1]) == pytest.approx(order, abs=0.15)


def test_vectorised_pieces_and_scalar_calls_agree():
    """The same monodromy (1e-10) from scalar calls, vectorised calls, and the period split
    into 8 pieces integrated simultaneously (one call of A with 8 azimuths per stage)."""
    A, Av = mathieu(2.5, 0.5, 0.2)
    ref = monodromy(A, np.pi)
    np.testing.assert_allclose(monodromy(Av, np.pi, vectorized=True), ref, atol=1e-10)
    res = floquet_multipliers(Av, np.pi, vectorized=True, n_intervals=8)
    np.testing.assert_allclose(res.monodromy, ref, atol=1e-10)
    assert (res.n_evaluations - 1) % 8 == 0  # 8 azimuths per stage, plus the first probe


def test_multipliers_sorted_by_decreasing_modulus():
    """A diagonal constant system with eigenvalues -0.3, 0.1, -1: multipliers exp(lambda T)
    sorted by decreasing modulus, exponents in the same order."""
    A = np.diag([-0.3, 0.1, -1.0])
    res = floquet_multipliers(lambda p: A, 1.0)
    np.testing.assert_allclose(res.multipliers.real, np.exp([0.1, -0.3, -1.0]), rtol=1e-10)
    np.testing.assert_allclose(res.exponents.real, [0.1, -0.3, -1.0], atol=1e-10)
    assert not res.stable and res.spectral_radius == pytest.approx(np.exp(0.1))
    assert "FloquetResult(n=3" in repr(res)


# --------------------------------------------------------------------------------------
# validation
# --------------------------------------------------------------------------------------


def test_invalid_inputs_raise_clear_errors():
    """Non-positive or non-finite period, non-square or non-finite A, A(psi) of the wrong
    shape or non-finite, unknown method, n_steps with dop853, bad branch, more evaluations of A
    than max_evaluations -> ValueError naming the problem; A neither callable nor array, or
    complex -> TypeError."""
    A = lambda p: A_OSC  # noqa: E731
    with pytest.raises(ValueError, match="period must be a finite number > 0"):
        floquet_multipliers(A, 0.0)
    with pytest.raises(ValueError, match="period"):
        floquet_multipliers(A, -1.0)
    with pytest.raises(ValueError, match="period"):
        floquet_multipliers(A, np.inf)
    with pytest.raises(ValueError, match="square"):
        floquet_multipliers(np.ones((2, 3)), 1.0)
    with pytest.raises(ValueError, match="square"):
        floquet_multipliers(lambda p: np.ones((2, 3)), 1.0)
    with pytest.raises(ValueError, match=r"returned shape \(3, 3\)"):
        floquet_multipliers(lambda p: np.eye(2) if p == 0 else np.eye(3), 1.0)
    with pytest.raises(ValueError, match=r"expected a square matrix of shape \(k, n, n\)"):
        floquet_multipliers(lambda p: np.eye(2), 1.0, vectorized=True)
    with pytest.raises(ValueError, match="non-finite value at psi="):
        floquet_multipliers(lambda p: np.eye(2) * (np.nan if p > 0.3 else 1.0), 1.0)
    with pytest.raises(ValueError, match="non-finite"):
        floquet_multipliers(np.array([[np.nan, 0], [0, 1]]), 1.0)
    with pytest.raises(ValueError, match="method must be one of"):
        floquet_multipliers(A, 1.0, method="euler")
    with pytest.raises(ValueError, match="n_steps applies to the fixed-step methods"):
        floquet_multipliers(A, 1.0, n_steps=100)
    with pytest.raises(ValueError, match="n_steps must be an integer >= 1"):
        floquet_multipliers(A, 1.0, method="rk4", n_steps=0)
    with pytest.raises(ValueError, match="branch must be an integer"):
        modal_properties([1j], 1.0, branch=0.5)
    with pytest.raises(ValueError, match="max_evaluations=50 would be exceeded"):
        floquet_multipliers(A, 1.0, max_evaluations=50)
    with pytest.raises(TypeError, match="callable"):
        floquet_multipliers("A", 1.0)
    with pytest.raises(TypeError, match="real"):
        floquet_multipliers(lambda p: 1j * np.eye(2), 1.0)


def test_public_names_at_the_package_top_level():
    """rotorlyap.floquet_multipliers and rotorlyap.blade_stability are the package's public
    entry points for Floquet theory and the blade in the engine."""
    import rotorlyap
    from rotorlyap.methods.floquet import floquet_multipliers as fm
    from rotorlyap.analysis.stability import blade_stability as bs

    assert rotorlyap.floquet_multipliers is fm and rotorlyap.blade_stability is bs
    assert {"floquet_multipliers", "blade_stability"} <= set(rotorlyap.__all__)
