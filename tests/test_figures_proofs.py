"""The proofs chapter's data and figures (rotorlyap.chapters.proofs).

Facts checked: the nonlinear term starts at the linear part (-1 for Q = I) for a small tube and
grows with the bound, the enclosure above the sampled estimate (an enclosure contains the exact
term, a sample lies below it); the examples of the method chapters: the oscillator proved inside
its numerical certificate, the counterexample not proved; the figures are drawn and legible.
"""

from __future__ import annotations

import numpy as np
import pytest

from rotorlyap.chapters import proofs


@pytest.fixture(scope="module")
def growth():
    return proofs.nonlinear_growth(cases=("forward",), A=np.geomspace(1e-3, 0.1, 5), n_samples=200)


def test_the_nonlinear_term_starts_at_the_linear_part_and_the_enclosure_lies_above_the_samples(growth):
    enc, smp = growth.enclosed[0], growth.sampled[0]
    assert -1.01 < smp[0] < -0.95 and -1.01 < enc[0] < -0.9  # Q = I: the linear part is -1
    assert np.all(np.diff(enc) > 0)
    assert np.all(enc >= smp - 1e-9)
    # on 1e-3 .. 0.1 the enclosed term crosses zero, the sampled one does not (it does at about 0.5)
    assert np.isfinite(growth.crossing()[0]) and np.all(smp < 0) and np.isnan(growth.crossing("sampled")[0])
    assert set(growth.facts()) == {"ch10_cross_forward_enc", "ch10_cross_forward_smp", "ch10_cross_forward_gap",
                                   "ch10_gap_lo", "ch10_gap_hi"}
    fig = proofs.figure_nonlinear_growth(growth)
    assert len(fig.axes) == 1


def test_the_examples_of_the_method_chapters():
    ex = proofs.example_proofs()
    (na, nl), (pa, pl) = ex.oscillator_numerical, ex.oscillator_proved
    assert 0 < pa <= na and 0 < pl <= nl
    assert not ex.counterexample_proved and ex.facts()["ch10_cx_proved"] == "not proved"
    assert ex.summary().splitlines()[1] == "counterexample of chapter 2: not proved"  # not "proved False"


def test_bound_text_states_round_off_as_a_floor():
    assert proofs._bound_text(3e-11) == "< 1e-08"
    assert proofs._bound_text(3.2e-6) == "< 1e-05"
