"""Time-domain validation of certificates (rotorlyap.methods.validation)."""

import numpy as np
import pytest

from rotorlyap import Blade, BladeParameters
from rotorlyap.model.steady import disturbed_rhs
from rotorlyap.analysis.functions import quadratic_function
from rotorlyap.analysis.stability import blade_stability
from rotorlyap.conventions import DEFAULT_SCALES
from rotorlyap.methods.validation import (
    classify_motion, confusion_matrix, simulate_within, start_directions, validate,
)

A = DEFAULT_SCALES


@pytest.fixture(scope="module")
def hover_case(forward, forward_hover):
    res = blade_stability(forward, 0.0, lyapunov=quadratic_function, n_psi=4, n_sphere=128)
    return disturbed_rhs(forward_hover, forward_hover.equilibrium()), res


def test_confusion_matrix_counts_add_up():
    """The four counts partition the motions."""
    rng = np.random.default_rng(0)
    c, b = rng.random(50) < 0.3, rng.random(50) < 0.6
    cm = confusion_matrix(c, b)
    assert cm.sum() == 50 and cm[0].sum() == c.sum() and cm[:, 0].sum() == b.sum()
    with pytest.raises(ValueError):
        confusion_matrix(c, b[:10])


def test_simulate_within_stops_each_motion_when_it_leaves_the_ball():
    """x' = 0.1 x: a motion from 0.5 reaches 1 at psi = 10 ln 2; one from 0.01 does not
    within 2 periods; one outside is marked at once."""
    f = lambda psi, x: 0.1 * x  # noqa: E731
    run = simulate_within(f, [[0.5, 0.0], [0.01, 0.0], [1.5, 0.0]], 0.0, 2.0, 1.0,
                          points_per_period=200)
    assert run.left.tolist() == [True, False, True]
    assert abs(run.psi_left[0] - 10 * np.log(2)) < 2 * np.pi / 200 + 1e-9
    assert run.max_norm[1] == pytest.approx(0.01 * np.exp(0.1 * 4 * np.pi), rel=1e-5)


def test_soundness_in_hover_starts_at_099_lambda0_stay_within_A(hover_case):
    """Motions started at 0.99 lambda0 of the hover certificate stay within the certified
    bound A1 for 8 revolutions (16 seeded directions)."""
    f, res = hover_case
    x0 = 0.99 * res.lambda0[0] * start_directions(16) * A
    run = simulate_within(f, x0, 0.0, 8.0, res.A, scales=A)
    assert not run.left.any() and run.max_norm.max() < res.A


@pytest.mark.slow
@pytest.mark.parametrize("cg", ["forward", "neutral", "backward"])
def test_quadratic_function_certifies_every_table_i_hover_and_simulation_confirms_it(cg):
    """Every Table I case is linearly stable in hover, so the quadratic function (strict
    reading) certifies a non-empty start region lambda0 > 0 inside a bound A1 > 0 at every
    azimuth, and motions of the full nonlinear blade started just inside it (0.99 lambda0,
    16 seeded directions, two azimuths) stay within A1 for 8 revolutions."""
    p = BladeParameters.table_i(cg)
    b = Blade(p, 0.0)
    res = blade_stability(p, 0.0, lyapunov=quadratic_function,
                          n_psi=4, n_sphere=128)
    assert res.reading == "strict" and res.certified and res.stable.all()
    assert res.A > 0 and res.lambda0.min() > 0
    f = disturbed_rhs(b, b.equilibrium())
    for j in (0, 1):
        x0 = 0.99 * res.lambda0[j] * start_directions(16) * A
        run = simulate_within(f, x0, float(res.psi[j]), 8.0, res.A, scales=A)
        assert not run.left.any() and run.max_norm.max() < res.A


@pytest.mark.slow
def test_soundness_in_forward_flight_about_the_periodic_motion(forward, forward_periodic_015):
    """mu = 0.15 about the periodic motion: starts at 0.99 lambda0 at two azimuths stay within
    the certified bound for 5 revolutions."""
    tab = forward_periodic_015
    res = blade_stability(forward, 0.15, lyapunov=quadratic_function,
                          steady=tab, n_psi=4, n_sphere=128)
    assert res.certified
    f = disturbed_rhs(Blade(forward, 0.15), tab)
    for j in (0, 2):
        x0 = 0.99 * res.lambda0[j] * start_directions(8, seed=2) * A
        run = simulate_within(f, x0, float(res.psi[j]), 5.0, res.A, scales=A)
        assert not run.left.any() and run.max_norm.max() < res.A


def test_validate_never_observes_a_certified_motion_unbounded(hover_case):
    """validate(): the counts add up, and no certified start leaves A (or A1)."""
    f, res = hover_case
    v = validate(f, {"quadratic": res}, fractions=(0.25, 1.0), n_directions=6, n_periods=4)
    cm = v.confusion("quadratic")
    assert cm.sum() == v.n == 6 * 4  # 2 fractions of A and 2 of lambda0
    assert cm[0, 0] == 12 and cm[0, 1] == 0 and v.violations("quadratic") == 0
    assert v.readings == ("strict",)


def test_classify_motion():
    """Verdicts from per-revolution peaks."""
    assert classify_motion(np.array([0.5, 0.3, 0.2, 0.1, 0.05, 0.02]), 1.0, False) == "decays within A"
    assert classify_motion(np.array([0.5, 5.0, 20.0, 20.1, 20.05, 20.08, 20.06]), 1.0, False) == "limit cycle outside A"
    assert classify_motion(np.array([1.0, 2.0]), 1.0, True) == "unbounded"
    assert classify_motion(np.array([0.1, 1.0, 3.0, 9.0, 27.0]), 1.0, False) == "bounded, not settled"


def test_last_revolution_reproduces_a_periodic_motion():
    """x' = (-x2, x1): the last revolution of the circle x = (cos psi, sin psi), interpolated,
    is the circle at any azimuth (modulo 2 pi), plus the offset."""
    from rotorlyap.methods.validation import last_revolution, long_run

    f = lambda psi, x: np.stack([-x[..., 1], x[..., 0]], axis=-1)  # noqa: E731
    h = long_run(f, [[1.0, 0.0]], 0.0, 3, A=2.0, points_per_period=64, rtol=1e-10, atol=1e-12)
    g = last_revolution(h, offset=[0.5, 0.0])
    psi = np.array([0.3, 2.0, 7.5, -1.0])
    np.testing.assert_allclose(g(psi), np.stack([0.5 + np.cos(psi), np.sin(psi)], axis=-1), atol=1e-6)
