"""The proofs chapter's data and figures (rotorlyap.chapters.proofs).

Facts checked: the nonlinear term starts at the linear part (-1 for Q = I) for a small tube and
grows with the bound, the enclosure above the sampled estimate (an enclosure contains the exact
term, a sample lies below it); the examples of the method chapters: the oscillator proved inside
its numerical certificate, the counterexample not proved; the figures are drawn and legible; the
printed account of the sources of a forward-flight model's remainder.
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


def test_range_text_gives_one_value_where_the_ends_round_alike():
    assert proofs._range_text([0.9, 0.95, 0.9001]) == "0.900 to 0.950"
    assert proofs._range_text([1.0000000000223, 0.99999999]) == "1.000"


def test_bound_text_states_round_off_as_a_floor():
    assert proofs._bound_text(3e-11) == "< 1e-08"
    assert proofs._bound_text(3.2e-6) == "< 1e-05"


def test_remainder_sources_summary_names_the_strips_and_their_angles():
    """The printed account of where a forward-flight model's remainder comes from
    (:class:`rotorlyap.analysis.proof.RemainderSources`): the worst azimuth, the strips whose loads
    carry it with their angle ranges, and the remainder without them."""
    from rotorlyap.analysis.proof import RemainderSources

    psi = 2 * np.pi * (np.arange(8) + 0.5) / 8
    remainder = np.array([0.004, 0.003, 0.002, 0.003, 0.005, 0.02, 0.065, 0.01])
    angles = np.radians(np.array([[-26.3, -16.6], [-15.4, -8.9], [2.0, 5.0]]))
    src = RemainderSources(bound=0.4, psi=psi, remainder=remainder, worst=6, station=np.array([0.15, 0.18, 0.5]),
                           angles=angles, without=np.array([0.045, 0.023, 0.065]), sources=(0, 1),
                           without_sources=0.0037)
    text = src.summary()
    assert "psi = 292 deg" in text
    assert "r/R = 0.15 (angle of attack -26 to -17 deg; without it 0.045)" in text
    one = RemainderSources(bound=0.4, psi=psi, remainder=remainder, worst=6, station=np.array([0.15, 0.18, 0.5]),
                           angles=angles, without=np.array([0.065, 0.065, 0.01]), sources=(2,), without_sources=0.01)
    assert "from the strips at r/R = 0.50 (angle of attack 2 to 5 deg; without it 0.01)" in one.summary()
