"""What chapters 5 and 6 share (:mod:`rotorlyap.chapters.cases`): the names of test
disturbances and the energy-balanced scales."""

import numpy as np

from rotorlyap.analysis.functions import energy_function
from rotorlyap.chapters import cases
from rotorlyap.conventions import DEFAULT_SCALES, PAPER_TEST_DISTURBANCES


def test_balanced_scales_give_every_axis_the_same_energy():
    from rotorlyap import Blade

    p = cases.case_params("forward")
    a = cases.balanced_scales(p)
    fun = energy_function(Blade(p, 0.0))
    w = fun.W(0.0, np.eye(6) * a)
    assert np.ptp(w) / w.mean() < 0.05
    assert np.all(DEFAULT_SCALES > 0)


def test_disturbance_names_name_the_twelve_signed_axes():
    names = cases.disturbance_names(PAPER_TEST_DISTURBANCES)
    assert names[:6] == ("+\\beta", "+\\zeta", "+\\theta", "+\\beta'", "+\\zeta'", "+\\theta'")
    assert names[6:] == tuple("-" + n[1:] for n in names[:6])
