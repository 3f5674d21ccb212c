"""Floquet analysis of the blade (rotorlyap.analysis.floquet)."""

import numpy as np
import pytest

from rotorlyap import Blade, BladeParameters
from rotorlyap.analysis.floquet import blade_floquet, floquet_sweep
from rotorlyap.model.steady import periodic_motion, tabulate_motion


def _match(a, b):
    """Largest distance between the multisets a and b (nearest-neighbour matching)."""
    b = list(b)
    worst = 0.0
    for z in a:
        k = int(np.argmin([abs(z - w) for w in b]))
        worst = max(worst, abs(z - b.pop(k)))
    return worst


@pytest.mark.parametrize("cg", ["forward", "backward"])
def test_hover_multipliers_equal_exp_of_the_jacobian_eigenvalues(cg):
    """In hover the Jacobian is constant, so the monodromy matrix integrated by the Magnus
    method must have the multipliers exp(2 pi eig(J)) (closed form)."""
    p = BladeParameters.table_i(cg)
    b = Blade(p, 0.0)
    lam = np.linalg.eigvals(b.jacobian(0.0, b.equilibrium()))
    pt = blade_floquet(p, 0.0, constant_shortcut=False, n_steps=256)
    expected = np.exp(2 * np.pi * lam)
    assert _match(pt.multipliers, expected) < 1e-8 * max(1.0, np.abs(expected).max())
    exact = blade_floquet(p, 0.0)
    assert _match(exact.exponents, lam) < 1e-12


def test_stability_verdicts_of_the_three_cases(forward):
    """All three C.G. positions stable in hover, the forward one also about its periodic motion
    at mu = 0.15 (slowest decay that of the lag mode, about -0.15/rev); without aerodynamic
    pitch damping the backward C.G. flutters in hover (spectral radius > 1)."""
    for cg in ("neutral", "backward"):
        assert blade_floquet(BladeParameters.table_i(cg), 0.0).stable
    assert blade_floquet(forward, 0.0).stable
    pt = blade_floquet(forward, 0.15)
    assert pt.found and pt.stable and -0.16 < pt.max_growth_rate < -0.13
    assert not blade_floquet(BladeParameters.table_i("backward", cm_pitch_rate=0.0), 0.0).stable


def test_sweep_follows_the_pitch_mode_by_continuity(forward):
    """The principal exponent of the pitch mode has |Im| < 1/2; continuity from hover
    restores its frequency near 5.09 per rev (the hover eigenvalue), and the flap mode keeps
    its hover frequency near 0.64 per rev."""
    sw = floquet_sweep(forward, [0.0, 0.025, 0.05], case="forward")
    t = sw.track("pitch+")
    np.testing.assert_allclose(sw.frequency[:, t], 5.09, atol=0.02)
    np.testing.assert_allclose(np.abs(sw.multipliers[:, t]), np.exp(2 * np.pi * sw.growth_rate[:, t]))
    np.testing.assert_allclose(np.abs(sw.frequency[:, sw.track("flap+")]), 0.64, atol=0.02)
    assert sw.found.all() and set(sw.dominant[0]) == {"flap", "lag", "pitch"}


def test_missing_periodic_motion_is_recorded_not_raised():
    """Where no periodic motion is found the point is marked, with the reason."""
    pt = blade_floquet(BladeParameters.table_i("backward"), 0.05)
    assert not pt.found and "no periodic solution" in pt.message and np.isnan(pt.spectral_radius)
    sw = floquet_sweep(BladeParameters.table_i("backward"), [0.0, 0.05], motions={0.05: "not found"})
    assert sw.found.tolist() == [True, False] and sw.messages[1] == "not found"


def test_tabulated_motion_is_consistent(forward):
    """The tabulated motion is within 1e-9 of the series and dxi is its exact derivative."""
    pm = periodic_motion(forward, 0.1)
    tab = tabulate_motion(pm, 2048)
    psi = np.linspace(0.01, 6.2, 37)
    assert tab.max_error < 1e-9
    np.testing.assert_allclose(tab.xi(psi), pm.xi(psi), atol=1e-9)
    h = 1e-6
    np.testing.assert_allclose((tab.xi(psi + h) - tab.xi(psi - h)) / (2 * h), tab.dxi(psi), atol=1e-7)
    with pytest.raises(ValueError):
        tabulate_motion(pm, 4.5)
