"""What chapters 5 and 6 share (:mod:`rotorlyap.chapters.cases`): the test-disturbance sets,
their names, the energy-balanced scales and the reverse-flow boundary."""

import numpy as np
import pytest

from rotorlyap.analysis.functions import energy_function
from rotorlyap.chapters import cases
from rotorlyap.conventions import DEFAULT_SCALES, PAPER_TEST_DISTURBANCES


def test_fig8_reverse_flow_reaches_the_root_only_on_the_retreating_side():
    p = cases.case_params("forward")
    psi = np.radians([90.0, 270.0])
    b = cases.reverse_flow_boundary(p, psi)
    assert np.isinf(b[0])
    assert b[1] == pytest.approx(p.root_r_over_R)


def test_balanced_scales_give_every_axis_the_same_energy():
    from rotorlyap import Blade

    p = cases.case_params("forward")
    a = cases.balanced_scales(p)
    fun = energy_function(Blade(p, 0.0))
    w = fun.W(0.0, np.eye(6) * a)
    assert np.ptp(w) / w.mean() < 0.05
    assert np.all(DEFAULT_SCALES > 0)


def test_paper_test_disturbances_are_the_twelve_signed_axes():
    assert PAPER_TEST_DISTURBANCES.shape == (12, 6)
    assert cases.AXES_AND_DIAGONALS.shape == (72, 6)
    assert cases.FLAP_LAG_TEST_DISTURBANCES.shape == (8, 6)
    assert np.all(cases.FLAP_LAG_TEST_DISTURBANCES[:, [2, 5]] == 0)


def test_disturbance_names_name_the_twelve_signed_axes():
    names = cases.disturbance_names(PAPER_TEST_DISTURBANCES)
    assert names[:6] == ("+\\beta", "+\\zeta", "+\\theta", "+\\beta'", "+\\zeta'", "+\\theta'")
    assert names[6:] == tuple("-" + n[1:] for n in names[:6])
