"""The theorem's condition (h) over the whole period (``rule="sound"``) against the paper's rule,
and certificates put to an independent adversary.

Facts checked:

* a counterexample: on ``pulsed_growth`` the paper's step 6 (at the start azimuth alone)
  certifies starts from which simulated motions leave the bound ``A``; the sound rule
  certifies nothing there;
* the band search finds the closed-form largest ``W'`` of ``pulsed_growth``;
* the oscillator certificate of chapters 1 and 2 survives the falsifier (:mod:`falsifier`;
  the blade's certificates: ``test_falsifier_*.py``).
"""

from __future__ import annotations

import numpy as np
import pytest

from rotorlyap.methods.examples import mathieu_duffing, pulsed_growth
from rotorlyap.methods.lyapunov import technical_stability
from rotorlyap.methods.simulation import simulate

from falsifier import attack, worst_start_peak


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


@pytest.mark.slow
@pytest.mark.parametrize("rule", ["sound", "paper"])
def test_the_oscillator_certificate_of_chapters_1_and_2_survives_the_falsifier(rule):
    """The oscillator of chapters 1 and 2 (A = 1, 72 azimuths; chapter 2 walks through the paper's
    rule, chapter 1 reports the sound one; here they agree): the adversary (10 x the engine's
    evaluations) finds W >= alpha on the sphere A, W <= alpha on the start balls' boundaries and
    W' < 0 on the band, and the worst simulated starts stay inside A for 20 periods."""
    s = mathieu_duffing(damping=0.4, modulation=0.3, softening=1.0)
    res = technical_stability(s.f, s.W, 1.0, dim=s.dim, dW=s.dW, n_psi=72, rule=rule)
    assert res.stable.all()
    # W is a quadratic form in (y, y'), so the band's inner boundary along a ray is a closed form
    hit = attack(s.W, s.dW, res, evaluations=res.check_evaluations if rule == "sound" else res.n_evaluations,
                 quadratic=True)
    assert hit.min_w_sphere >= res.alpha * (1 - 1e-9)
    assert hit.min_w_sphere <= res.alpha * 1.01
    assert hit.sup_w_balls <= 1e-9 * res.alpha
    assert hit.max_dw_band < 0
    assert worst_start_peak(s.f, res, n_periods=20.0) < 1.0


def test_sound_rule_rejects_bad_options():
    s = mathieu_duffing()
    with pytest.raises(ValueError, match="rule must be one of"):
        technical_stability(s.f, s.W, 1.0, scales=[1.0, 1.0], rule="lenient")
    with pytest.raises(ValueError, match="not used by the practical reading"):
        technical_stability(s.f, s.W, 1.0, scales=[1.0, 1.0], rule="paper", w_matrix=lambda p: np.eye(2),
                            test_directions=np.eye(2))
    with pytest.raises(ValueError, match="one square matrix per azimuth"):
        technical_stability(s.f, s.W, 1.0, scales=[1.0, 1.0], w_matrix=lambda p: np.eye(2))
    with pytest.raises(ValueError, match="practical reading"):
        technical_stability(s.f, s.W, 1.0, scales=[1.0, 1.0], rule="sound",
                            test_directions=np.eye(2))


# --------------------------------------------------------------------------------------
# The band search
# --------------------------------------------------------------------------------------

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


def test_an_early_stopped_band_search_gives_the_full_searchs_verdict():
    """stop_above (the sound rule asks only whether max W' <= -margin): on pulsed_growth, for
    thresholds below and above its largest W' on the band (closed form above), the stopped
    search reports a value above the threshold exactly where the full search does; that value is
    W' at the point it returns and no more than the full maximum; above the maximum the stopped
    search is the full one to the last bit."""
    from rotorlyap.methods.lyapunov import band_max_dw

    s = pulsed_growth()
    alpha, psi = np.exp(-4.0), np.arange(24) * np.pi / 12
    full = band_max_dw(s.f, s.W, s.dW, alpha, 1.0, scales=[1.0], psi=psi)
    top = float(full.value[0])
    for stop in (-1.0, 0.0, 0.5 * top, 0.999 * top, 1.001 * top, 2.0 * top):
        ext = band_max_dw(s.f, s.W, s.dW, alpha, 1.0, scales=[1.0], psi=psi, stop_above=stop)
        assert (ext.value[0] > stop) == (top > stop)
        assert ext.value[0] <= top
        assert ext.value[0] == pytest.approx(float(s.dW(ext.psi, ext.x)[0]), rel=1e-12)
        if top <= stop:
            assert all(np.array_equal(getattr(ext, k), getattr(full, k)) for k in ("value", "psi", "x"))


def test_sphere_extremum_keeps_the_best_candidates_in_order():
    """keep=k returns the k best refined candidates, best first."""
    from rotorlyap.methods.sampling import sphere_extremum, unit_sphere_points

    dirs = unit_sphere_points(2, 64, 0)
    ext = sphere_extremum(lambda p, x: x[:, 0] + 0.1 * np.cos(p), np.arange(8) * np.pi / 4, 1.0,
                          np.ones(2), dirs, per_psi=False, free_psi=True, keep=3)
    assert ext.value.shape == (3,) and np.all(np.diff(ext.value) <= 0)
    assert ext.value[0] == pytest.approx(1.1, abs=1e-6)
