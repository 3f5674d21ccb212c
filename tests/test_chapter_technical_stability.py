"""rotorlyap.chapters.technical_stability (chapter 1) and the motions it shares with chapter 2
(rotorlyap.chapters.norm_history): what chapter 1 prints (summary) and quotes (facts), and its
figures.

Each fact must be the data field it names, rounded to the digits the chapter states; each
summary must hold those numbers; each figure function must return a finished figure of the
book's size, closed in pyplot. The oscillator, its certificate and its motions are the
session's fixtures ``osc``, ``osc_cert`` and ``osc_history`` (tests/conftest.py).
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

from rotorlyap.chapters import norm_history, technical_stability  # noqa: E402


def _plain(value) -> bool:
    return type(value) in (int, float)


# ---- the certificate

def test_certificate_summary_is_the_message_then_A_alpha_and_the_range_of_lambda0(osc_cert):
    message, numbers = technical_stability.certificate_summary(osc_cert).splitlines()
    assert message == osc_cert.message
    assert numbers == "A = %.4f, alpha = %.4f, lambda0 from %.3g to %.3g" % (
        osc_cert.A, osc_cert.alpha, osc_cert.lambda0.min(), osc_cert.lambda0.max())


# ---- phase portrait

def test_phase_portrait_summary_gives_the_bounds_and_the_fate_of_each_outside_motion(osc, osc_cert):
    portrait = technical_stability.phase_portrait_data(osc, osc_cert, 0, n_starts=4, n_periods=2)
    lines = portrait.summary().splitlines()
    assert lines[0] == "phase portrait: A = %.4f, lambda0(psi0) = %.3g" % (portrait.A, portrait.lambda0)
    assert lines[1].endswith("%.4f" % portrait.max_inside_norm)
    assert portrait.max_inside_norm < portrait.lambda0  # unit scales: the theorem, in the plane
    assert len(lines) == 2 + len(portrait.outside)
    for line, path, esc in zip(lines[2:], portrait.outside, portrait.outside_escaped):
        assert line == "motion started at (y, y') = (%.2f, %.2f): %s" % (*path[0], "escapes" if esc else "bounded")


# ---- norm osc_history (rotorlyap.chapters.norm_history, drawn here, reduced in chapter 2)

def test_norm_history_facts_are_its_fields_rounded_to_three_decimals(osc_history):
    assert osc_history.facts() == {
        "ch1_max_ratio": round(osc_history.max_ratio, 3),
        "ch1_A": round(osc_history.A, 3),
        "ch1_lam_min": round(float(osc_history.lambda0.min()), 3),
        "ch1_lam_max": round(float(osc_history.lambda0.max()), 3),
    }


def test_norm_history_summary_counts_the_motions_and_periods(osc_history):
    assert osc_history.n_motions == 12 and osc_history.n_periods == 2.0 and osc_history.fraction == 0.999
    assert osc_history.summary() == "largest ||x|| / A over 12 motions and 2 periods: %.3f" % osc_history.max_ratio


def test_facts_are_plain_python_numbers_so_the_glued_text_carries_no_numpy_type(osc_history):
    facts = osc_history.facts()
    assert all(_plain(v) for v in facts.values()), facts
    assert not any("np." in repr(v) for v in facts.values())


def test_facts_prefix_names_the_chapter_quoting_them(osc_history):
    assert set(osc_history.facts(prefix="ch2")) == {"ch2_max_ratio", "ch2_A", "ch2_lam_min", "ch2_lam_max"}


def test_the_chapter_calls_the_shared_norm_history_data():
    assert technical_stability.norm_history_data is norm_history.norm_history_data


# ---- figures

def test_figure_functions_return_finished_figures_of_the_book_sizes_closed_in_pyplot(osc, osc_cert, osc_history):
    portrait = technical_stability.phase_portrait_data(osc, osc_cert, 0, n_starts=2, n_periods=1)
    cases = [
        (technical_stability.figure_phase_portrait(portrait, title="t"), (6, 7), 1),
        (technical_stability.figure_norm_history(osc_history), (7, 3.6), 1),
    ]
    for fig, size, n_axes in cases:
        assert tuple(fig.get_size_inches()) == pytest.approx(size)
        assert len(fig.axes) == n_axes
        assert fig.number not in plt.get_fignums()
    assert cases[0][0].axes[0].get_title() == "t"
    assert "0.999" in cases[1][0].axes[0].get_title()


def test_all_names_exist():
    for module in (technical_stability, norm_history):
        assert all(hasattr(module, name) for name in module.__all__)
