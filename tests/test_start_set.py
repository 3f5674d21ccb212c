"""The certified start set {||x|| < A, W < level} measured along rays (rotorlyap.methods.start_set)."""

import numpy as np
import pytest

from rotorlyap import certify
from rotorlyap.methods.start_set import StartSet, signed_axes, start_set

A_SCALES = np.array([0.5, 2.0, 1.0])


def _quadratic(P):
    def W(psi, x):
        return np.einsum("mi,ij,mj->m", x, P, x)
    return W


def test_a_quadratic_forms_reach_along_each_axis_is_its_closed_form():
    """Along e_i (scaled), W = r^2 a_i^2 P_ii, so the level c is met at r = sqrt(c / (a_i^2 P_ii)),
    capped at A; the scan-and-bracket path (quadratic=False) finds the same radius."""
    P = np.array([[2.0, 0.1, 0.0], [0.1, 0.05, 0.1], [0.0, 0.1, 8.0]])
    c, A = 0.7, 1.5
    exact = np.minimum(np.sqrt(c / (A_SCALES**2 * np.diag(P))), A)
    closed = start_set(_quadratic(P), c, A, A_SCALES, autonomous=True, quadratic=True)
    scanned = start_set(_quadratic(P), c, A, A_SCALES, autonomous=True)
    np.testing.assert_allclose(closed.axis_reach, exact, rtol=1e-12)
    np.testing.assert_allclose(scanned.axis_reach, exact, rtol=1e-9)
    assert np.all(scanned.axis_reach <= exact * (1 + 1e-12))  # the side where W < c
    assert closed.axis_reach[1] == A  # the lag-like axis stays below the level up to the bound


def test_the_reach_is_the_first_crossing_not_a_later_one():
    """W = r^2 (2 - r)^2 along the axis rises to 1 at r = 1 and falls again: with the level 0.9 the
    set along the ray ends at the first crossing, r = 1 - sqrt(1 - sqrt(0.9))."""
    def W(psi, x):
        r = np.abs(x[:, 0])
        return r**2 * (2 - r) ** 2 + x[:, 1] ** 2

    s = start_set(W, 0.9, 1.9, np.ones(2), autonomous=True)
    np.testing.assert_allclose(s.axis_reach[0], 1 - np.sqrt(1 - np.sqrt(0.9)), rtol=1e-9)


@pytest.mark.parametrize("quadratic", [True, False])
def test_a_periodic_function_reports_its_worst_start_azimuth_between_the_grids_azimuths(quadratic):
    """W = (2 + cos(psi - psi_w)) x^2 in one variable, psi_w halfway between two azimuths of the
    grid: the reach sqrt(c / (2 + cos(psi - psi_w))) is least at psi_w, sqrt(c / 3), where no grid
    azimuth lies; the reported least is that (the search between the grid's azimuths), not the
    grid's smallest, which is larger."""
    psi_w = 2 * np.pi * 10.5 / 72

    def W(psi, x):
        return (2 + np.cos(psi - psi_w)) * x[:, 0] ** 2

    s = start_set(W, 0.6, 5.0, np.ones(1), n_psi=72, quadratic=quadratic)
    assert s.reach.shape == (72, 2)
    np.testing.assert_allclose(s.axis_reach, [np.sqrt(0.6 / 3)], rtol=1e-9)
    assert s.reach.min() > np.sqrt(0.6 / 3) * (1 + 1e-5)
    np.testing.assert_allclose(s.reach.max(), np.sqrt(0.6), rtol=1e-3)


def test_the_start_set_holds_the_theorems_ball_on_the_blade(forward):
    """The sound rule's start ball lambda0 lies inside {W < alpha}: the set reaches at least lambda0
    along every hinge axis, and further along some (the set is not a ball)."""
    cert = certify(forward, 0.0, condition="none", function="quadratic")
    s = cert.start_set
    assert isinstance(s, StartSet) and s.level == cert.result.level and s.A == cert.bound
    assert np.all(s.axis_reach >= cert.start_region * (1 - 1e-12))
    assert s.axis_reach.max() > 1.5 * cert.start_region
    per_hinge = cert.start_set_per_hinge
    for h, (deg, rate) in cert.start_region_per_hinge.items():
        assert per_hinge[h][0] >= deg * (1 - 1e-12) and per_hinge[h][1] >= rate * (1 - 1e-12)
    assert "start set, each hinge alone" in cert.summary()


def test_bad_arguments_are_refused_with_what_is_allowed():
    W = _quadratic(np.eye(2))
    with pytest.raises(ValueError, match="level must be a finite number > 0"):
        start_set(W, 0.0, 1.0, np.ones(2))
    with pytest.raises(ValueError, match="A must be a finite number > 0"):
        start_set(W, 1.0, np.inf, np.ones(2))
    with pytest.raises(ValueError, match="scales must be finite and > 0"):
        start_set(W, 1.0, 1.0, [1.0, -1.0])
    with pytest.raises(ValueError, match="directions must be a"):
        start_set(W, 1.0, 1.0, np.ones(2), directions=np.zeros((1, 2)))
    with pytest.raises(ValueError, match="W\\(psi, x\\) returned a non-finite value"):
        start_set(lambda psi, x: np.full(x.shape[0], np.nan), 1.0, 1.0, np.ones(2), autonomous=True)
    with pytest.raises(ValueError, match="axis_reach needs the signed axes"):
        _ = start_set(W, 1.0, 1.0, np.ones(2), autonomous=True, directions=[[1.0, 1.0]]).axis_reach
    assert signed_axes(2).tolist() == [[1, 0], [0, 1], [-1, 0], [0, -1]]
