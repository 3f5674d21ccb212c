"""The theorem's condition (h) over the whole period (``rule="sound"``) against the paper's rule,
and certificates put to an independent adversary.

Facts checked:

* a counterexample: on ``pulsed_growth`` the paper's step 6 (at the start azimuth alone)
  certifies starts from which simulated motions leave the bound ``A``; the sound rule
  certifies nothing there;
* the closed forms of a quadratic ``W = y^T S y`` on a sphere of radius ``r``: ``inf W = r^2
  lambda_min(S)``, ``sup W = r^2 lambda_max(S)``; the engine's ``alpha`` and ``lambda0`` with
  ``w_matrix`` equal them, and an independent optimiser (scipy's differential evolution) finds
  no smaller ``W`` on the sphere ``A`` and no larger ``W`` inside ``lambda0``;
* on every certificate, differential evolution with more evaluations than the engine finds no
  ``W' >= 0`` on the band ``||x|| <= A, W >= alpha``, and motions from the worst start
  directions found by optimisation (not random draws) stay inside ``A`` for 20 periods.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import differential_evolution

from rotorlyap.analysis.functions import quadratic_function
from rotorlyap.analysis.stability import blade_stability
from rotorlyap.conventions import DEFAULT_SCALES
from rotorlyap.methods.examples import mathieu_duffing, pulsed_growth
from rotorlyap.methods.lyapunov import technical_stability
from rotorlyap.methods.simulation import simulate
from rotorlyap.model.blade import Blade
from rotorlyap.model.parameters import BladeParameters
from rotorlyap.model.steady import disturbed_rhs


# --------------------------------------------------------------------------------------
# Helpers: points of the unit sphere from angles, the adversaries
# --------------------------------------------------------------------------------------

def _unit(angles: np.ndarray, n: int) -> np.ndarray:
    """Hyperspherical coordinates ``(k, n - 1)`` -> unit vectors ``(k, n)``."""
    angles = np.atleast_2d(angles)
    k = angles.shape[0]
    out = np.ones((k, n))
    for i in range(n - 1):
        out[:, i] *= np.cos(angles[:, i])
        out[:, i + 1:] *= np.sin(angles[:, i])[:, None]
    return out


def _bounds(n: int, period: float):
    return [(0.0, period)] + [(0.0, np.pi)] * (n - 2) + [(0.0, 2.0 * np.pi)] * (n > 1)


def _de(fun, bounds, evaluations: int, seed: int = 1):
    """The minimum of ``fun`` over the box ``bounds`` found by an adversary independent of the
    engine's search (Sobol' directions refined by projected gradient ascent): ``evaluations``
    pseudo-random points in batches, differential evolution (at most 200 000 evaluations,
    vectorised over the population), and L-BFGS-B from the best of both."""
    from scipy.optimize import minimize

    rng = np.random.default_rng(seed)
    lo, hi = np.array(bounds, dtype=float).T
    best_v = np.inf
    pool = []
    done = 0
    while done < evaluations:
        m = min(100_000, evaluations - done)
        z = lo + (hi - lo) * rng.random((m, lo.size))
        v = np.asarray(fun(z), dtype=float)
        order = np.argsort(v)[:8]
        pool += [(float(v[i]), z[i]) for i in order]
        done += m
    dim = lo.size
    popsize = 15
    maxiter = max(10, min(evaluations, 200_000) // (popsize * dim) - 1)
    res = differential_evolution(
        lambda z: fun(z.T), bounds, popsize=popsize, maxiter=maxiter, tol=0.0, atol=0.0,
        seed=seed, vectorized=True, polish=False, updating="deferred",
    )
    pool.append((float(res.fun), np.asarray(res.x)))
    pool.sort(key=lambda item: item[0])
    for v0, z0 in pool[:8]:
        r = minimize(lambda z: float(fun(z[None, :])[0]), z0, method="L-BFGS-B", bounds=bounds)
        for v, z in ((v0, z0), (float(r.fun), r.x)):
            if v < best_v:
                best_v = v
    return best_v


def _adversary(W, dW, result, *, evaluations: int, quadratic: bool = False):
    """Independent searches on a certificate (:func:`_de`): min W on the sphere A and
    max (W - alpha) on the boundaries of the certified start balls (``evaluations`` each), max W'
    on the band (10 x ``evaluations``). For a quadratic W the band's inner boundary along a ray follows from
    W(r u) = r^2 W(u) (no eigenvalues); otherwise by bisection."""
    n = result.scales.size
    a = result.scales
    A, c, T = result.A, result.alpha, result.period
    lam = float(result.lambda0[result.stable].min())

    def w_on_sphere(z):
        return W(z[:, 0], A * _unit(z[:, 1:], n) * a)

    min_w = _de(w_on_sphere, _bounds(n, T), evaluations)

    # start regions: sup W at psi_j on the sphere lambda0_j, over the certified azimuths
    def w_in_ball(z):
        j = np.clip(z[:, 0].astype(int), 0, result.psi.size - 1)
        return -(W(result.psi[j], result.lambda0[j, None] * _unit(z[:, 1:], n) * a) - c)

    idx = np.flatnonzero(result.stable)
    sup_ball = -_de(w_in_ball, [(float(idx.min()), float(idx.max()) + 0.999)] + _bounds(n, T)[1:],
                    evaluations)

    # the band: along each ray from the level c out to A (bisection for the level)
    def level(psi, u):
        if quadratic:
            return np.minimum(np.sqrt(c / W(psi, u * a)), A)
        lo, hi = np.zeros(len(psi)), np.full(len(psi), A)
        for _ in range(50):
            mid = 0.5 * (lo + hi)
            up = W(psi, mid[:, None] * u * a) >= c
            hi, lo = np.where(up, mid, hi), np.where(up, lo, mid)
        return hi

    def dw_on_band(z):
        psi, u, t = z[:, 0], _unit(z[:, 1:-1], n), z[:, -1]
        r0 = level(psi, u)
        return -dW(psi, (r0 + t * (A - r0))[:, None] * u * a)

    max_dw = -_de(dw_on_band, _bounds(n, T) + [(0.0, 1.0)], 10 * evaluations)
    return min_w, sup_ball, max_dw, lam


def _worst_start_peak(f, result, *, n_periods: float = 20.0, n_dir: int = 64, rounds: int = 6):
    """Largest peak norm / A of motions started at 0.99 lambda0_j, the start direction chosen
    by optimisation: the best of ``n_dir`` directions per certified azimuth, then improved by
    rounds of perturbations (all motions of a round integrated together)."""
    n, a = result.scales.size, result.scales
    rng = np.random.default_rng(7)
    worst = 0.0
    for j in np.flatnonzero(result.stable)[::max(1, int(result.stable.sum()) // 4)]:
        r0 = 0.99 * result.lambda0[j]

        def peaks(u):
            sim = simulate(f, r0 * u * a, result.psi[j], n_periods, period=result.period, scales=a,
                           escape=10.0 * result.A)
            return np.where(sim.escaped, np.inf, sim.max_norm)

        u = rng.normal(size=(n_dir, n))
        u /= np.linalg.norm(u, axis=1, keepdims=True)
        p = peaks(u)
        best_u, best_p = u[np.argmax(p)], p.max()
        step = 0.3
        for _ in range(rounds):
            cand = best_u + step * rng.normal(size=(16, n))
            cand /= np.linalg.norm(cand, axis=1, keepdims=True)
            pc = peaks(cand)
            if pc.max() > best_p:
                best_u, best_p = cand[np.argmax(pc)], pc.max()
            else:
                step *= 0.5
        worst = max(worst, best_p / result.A)
    return worst


# --------------------------------------------------------------------------------------
# The counterexample
# --------------------------------------------------------------------------------------

def test_paper_rule_certifies_escaping_starts_and_the_sound_rule_does_not():
    """pulsed_growth: the paper's rule certifies azimuths near 90 deg (lambda0 up to A); motions
    started there at 0.99 lambda0 grow past A on the next pulse. The sound rule: nothing."""
    s = pulsed_growth()
    paper = technical_stability(s.f, s.W, 1.0, scales=[1.0], n_psi=24, dW=s.dW, rule="paper")
    assert paper.stable.any()
    escaped = []
    for j in np.flatnonzero(paper.stable):
        sim = simulate(s.f, [[0.99 * paper.lambda0[j]]], paper.psi[j], 20.0)
        escaped.append(sim.max_norm[0] > paper.A)
    assert all(escaped), "the paper's rule certified starts whose motions stay inside A"
    sound = technical_stability(s.f, s.W, 1.0, scales=[1.0], n_psi=24, dW=s.dW, rule="sound")
    assert not sound.stable.any() and sound.A == 0.0
    assert sound.band_max_dW > 0  # the evidence: W' > 0 on the band


def test_sound_rule_certifies_mathieu_duffing_and_motions_stay_inside():
    """Where (h) does hold over the period, the sound rule certifies (here as many azimuths as
    the paper's rule) and the worst simulated starts stay inside A."""
    s = mathieu_duffing()
    res = technical_stability(s.f, s.W, 1.5, scales=[1.0, 1.0], n_psi=24, dW=s.dW, rule="sound")
    assert res.stable.all() and res.band_max_dW < 0
    assert _worst_start_peak(s.f, res, n_periods=20.0, n_dir=32, rounds=4) < 1.0


def test_sound_rule_rejects_bad_options():
    s = mathieu_duffing()
    with pytest.raises(ValueError, match="rule must be one of"):
        technical_stability(s.f, s.W, 1.0, scales=[1.0, 1.0], rule="lenient")
    with pytest.raises(ValueError, match="only with rule='sound'"):
        technical_stability(s.f, s.W, 1.0, scales=[1.0, 1.0], w_matrix=lambda p: np.eye(2))
    with pytest.raises(ValueError, match="practical reading"):
        technical_stability(s.f, s.W, 1.0, scales=[1.0, 1.0], rule="sound",
                            test_directions=np.eye(2))


# --------------------------------------------------------------------------------------
# Closed forms and the adversary on the blade's hover certificates
# --------------------------------------------------------------------------------------

@pytest.mark.slow
@pytest.mark.parametrize("cg", ["forward", "neutral", "backward"])
def test_hover_quadratic_certificates_survive_an_independent_adversary(cg):
    """Hover, Q = I, sound rule with closed forms: alpha = A^2 min lambda_min(S), lambda0 =
    sqrt(alpha / lambda_max(S)); differential evolution (10 x the engine's evaluations on the band)
    finds W on the sphere A no smaller than alpha (within 1 %, never below), W at the start
    balls' boundary no larger than alpha, and W' < 0 on the band; the worst simulated starts
    stay inside A for 20 revolutions."""
    params = BladeParameters.table_i(cg)
    blade = Blade(params, 0.0)
    xi = blade.equilibrium()
    fun = quadratic_function(blade, xi)
    f = disturbed_rhs(blade, xi)
    a = DEFAULT_SCALES
    res = technical_stability(f, fun.W, 1.0, scales=a, dW=fun.dW, n_psi=24, rule="sound",
                              w_matrix=lambda psi: a[:, None] * fun.P(psi) * a[None, :])
    assert res.stable.all()
    # the same verdict through the blade's entry point
    assert blade_stability(params, 0.0, lyapunov=quadratic_function, n_psi=24, rule="sound").stable.all()
    S = a[:, None] * fun.P(0.0) * a[None, :]
    ev = np.linalg.eigvalsh(0.5 * (S + S.T))  # x^T S x sees only the symmetric part
    roundoff = 1e-11 * ev[-1]  # a symmetric eigen-solver's error is ~ n eps lambda_max
    assert abs(res.alpha - res.A ** 2 * ev[0]) <= res.A ** 2 * roundoff
    assert res.alpha <= res.A ** 2 * ev[0], "alpha on the unsafe side of the closed form"
    np.testing.assert_allclose(res.lambda0, np.sqrt(res.alpha / ev[-1]), rtol=1e-9)

    min_w, sup_ball, max_dw, _ = _adversary(fun.W, fun.dW, res, evaluations=res.n_evaluations,
                                            quadratic=True)
    assert res.alpha <= min_w * (1 + 1e-9), "alpha larger than a W found on the sphere A"
    assert min_w <= res.alpha * 1.01, "the independent search does not reach alpha within 1 %"
    assert sup_ball <= 1e-9 * res.alpha, "a start on the boundary of lambda0 has W above the level"
    assert max_dw < 0, "W' >= 0 found on the band by differential evolution"
    assert _worst_start_peak(f, res, n_periods=20.0, n_dir=32, rounds=3) < 1.0


def test_band_search_finds_the_closed_form_maximum_of_pulsed_growth():
    """On pulsed_growth (a = 0.5, b = 2, k = 1, A = 1) the band's largest W' has a closed form:
    W' = 2 p x^2 (a - k x^2) is largest at x^2 = a / (2 k) and p = exp(2 b) (psi = 270 deg),
    where the band reaches (its level x^2 = alpha / p = exp(-4 b) is below a / 2k):
    max W' = exp(2 b) a^2 / (2 k)."""
    from rotorlyap.methods.lyapunov import band_max_dw

    s = pulsed_growth()
    a, b, k = 0.5, 2.0, 1.0
    alpha = np.exp(-2 * b)
    ext = band_max_dw(s.f, s.W, s.dW, alpha, 1.0, scales=[1.0], psi=np.arange(24) * np.pi / 12)
    exact = np.exp(2 * b) * a * a / (2 * k)
    assert ext.value[0] == pytest.approx(exact, rel=1e-6)
    assert np.degrees(ext.psi[0]) % 360 == pytest.approx(270.0, abs=0.1)
    assert ext.x[0, 0] ** 2 == pytest.approx(a / (2 * k), rel=1e-4)


def test_sphere_extremum_keeps_the_best_candidates_in_order():
    """keep=k returns the k best refined candidates, best first."""
    from rotorlyap.methods.sampling import sphere_extremum, unit_sphere_points

    dirs = unit_sphere_points(2, 64, 0)
    ext = sphere_extremum(lambda p, x: x[:, 0] + 0.1 * np.cos(p), np.arange(8) * np.pi / 4, 1.0,
                          np.ones(2), dirs, per_psi=False, free_psi=True, keep=3)
    assert ext.value.shape == (3,) and np.all(np.diff(ext.value) <= 0)
    assert ext.value[0] == pytest.approx(1.1, abs=1e-6)


@pytest.mark.slow
def test_forward_flight_quadratic_certificate_survives_an_independent_adversary(forward, forward_periodic_015):
    """mu = 0.15, forward C.G., Q = I about the periodic motion (the certificate chapters 6 and
    7 report), sound rule: the adversary (10 x the engine's evaluations on the band, the
    azimuth free) finds W on the sphere A no smaller than alpha, no start on the boundary of a
    certified ball above the level, no W' >= 0 on the band; the worst simulated starts stay
    inside A for 20 revolutions."""
    params = Blade(forward, 0.0).params  # the hover trim's collective, kept in forward flight
    blade = Blade(params, 0.15)
    fun = quadratic_function(blade, forward_periodic_015)
    f = disturbed_rhs(blade, forward_periodic_015)
    a = DEFAULT_SCALES
    res = technical_stability(f, fun.W, 1.0, scales=a, dW=fun.dW, n_psi=24, rule="sound",
                              w_matrix=lambda psi: a[:, None] * fun.P(psi) * a[None, :])
    assert res.stable.all()
    min_w, sup_ball, max_dw, _ = _adversary(fun.W, fun.dW, res, evaluations=res.n_evaluations,
                                            quadratic=True)
    assert res.alpha <= min_w * (1 + 1e-9) and min_w <= res.alpha * 1.01
    assert sup_ball <= 1e-9 * res.alpha
    assert max_dw < 0
    assert _worst_start_peak(f, res, n_periods=20.0, n_dir=32, rounds=3) < 1.0
