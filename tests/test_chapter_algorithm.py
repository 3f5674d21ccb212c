"""rotorlyap.chapters.algorithm: what chapter 2 prints (summary) and quotes (facts), and its figures.

Each fact must be the data field it names, rounded to the digits the chapter states; each
summary must hold those numbers; each figure function must return a finished figure of the
book's size, closed in pyplot. The oscillator, its certificate and its motions are the
session's fixtures ``osc``, ``osc_cert`` and ``osc_history`` (tests/conftest.py).
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from rotorlyap.chapters import algorithm  # noqa: E402
from rotorlyap.chapters.export import figure_csv  # noqa: E402


@pytest.fixture(scope="module")
def levels(osc, osc_cert):
    return algorithm.level_sets_data(osc, osc_cert, n_grid=31, extent=1.15)


def _plain(value) -> bool:
    return type(value) in (int, float)


# ---- the certificate (steps 1 to 6)

def test_steps_facts_are_the_certificate_rounded_to_the_digits_chapter_2_quotes(osc_cert):
    facts = algorithm.steps_facts(osc_cert)
    assert facts == {
        "ch2_A_req": 1.0,
        "ch2_step3": round(osc_cert.step3_max_dW, 3),
        "ch2_A": round(osc_cert.A, 4),
        "ch2_alpha": round(osc_cert.alpha, 4),
        "ch2_lam_min": round(float(osc_cert.lambda0.min()), 4),
        "ch2_lam_max": round(float(osc_cert.lambda0.max()), 4),
        "ch2_n_stable": int(osc_cert.stable.sum()),
    }


def test_facts_are_plain_python_numbers_so_the_glued_text_carries_no_numpy_type(osc_cert, osc_history, levels):
    for facts in (algorithm.steps_facts(osc_cert), levels.facts(),
                  algorithm.max_norm_data(osc_history).facts()):
        assert all(_plain(v) for v in facts.values()), facts
        assert not any("np." in repr(v) for v in facts.values())


def test_facts_prefix_names_the_chapter_quoting_them(osc_cert):
    assert set(algorithm.steps_facts(osc_cert, prefix="ch9")) == {
        "ch9_A_req", "ch9_step3", "ch9_A", "ch9_alpha", "ch9_lam_min", "ch9_lam_max", "ch9_n_stable"}


def test_steps_summary_holds_every_step_number(osc_cert):
    lines = algorithm.steps_summary(osc_cert).splitlines()
    assert lines[0] == osc_cert.message and not any("TechnicalStabilityResult" in ln for ln in lines)
    assert lines[1] == "step 3: largest W' on ||x|| = 1.00: %.4f" % osc_cert.step3_max_dW
    assert lines[2] == "step 3: A = %.4f;  step 4: alpha = %.5f" % (osc_cert.A, osc_cert.alpha)
    j_min, j_max = int(np.argmin(osc_cert.lambda0)), int(np.argmax(osc_cert.lambda0))
    assert lines[3] == "step 5: lambda0 from %.4f (psi = %.0f deg) to %.4f (psi = %.0f deg)" % (
        osc_cert.lambda0[j_min], np.degrees(osc_cert.psi[j_min]),
        osc_cert.lambda0[j_max], np.degrees(osc_cert.psi[j_max]))
    assert lines[4].endswith("step 6 passes at %d of 24 azimuths" % osc_cert.stable.sum())
    assert "%.2e" % osc_cert.max_dW.max() in lines[4]


# ---- the largest norm per motion (of the motions of rotorlyap.chapters.norm_history)

def test_max_norm_data_has_one_row_per_motion_and_the_history_s_largest_ratio(osc_history):
    check = algorithm.max_norm_data(osc_history)
    assert check.start_psi_deg.shape == check.max_norm_over_A.shape == check.start_radius_over_A.shape == (12,)
    assert check.max_ratio == osc_history.max_ratio
    assert np.array_equal(np.unique(check.start_psi_deg), np.degrees(osc_history.psi_grid[[0, 6, 12]]))
    np.testing.assert_allclose(np.unique(check.start_radius_over_A * osc_history.A),
                               np.sort(osc_history.lambda0[[0, 6, 12]]), rtol=1e-12)
    assert check.summary() == "12 motions; largest ||x|| / A: %.3f" % osc_history.max_ratio
    assert check.facts() == {"ch2_max_ratio": round(osc_history.max_ratio, 3)}


def test_max_norm_csv_has_the_three_columns_one_row_per_motion(osc_history, tmp_path):
    text = figure_csv(algorithm.max_norm_data(osc_history), tmp_path / "m.csv").read_text().splitlines()
    assert text[0] == "start_psi_deg,max_norm_over_A,start_radius_over_A" and len(text) == 13


# ---- level sets (chapter 2)

def test_level_sets_panels_sit_at_the_smallest_start_region_and_the_tightest_shell(osc_cert, levels):
    assert levels.smallest.psi == osc_cert.psi[np.argmin(osc_cert.lambda0)]
    assert levels.tightest.psi == osc_cert.psi[np.argmax(osc_cert.max_dW)]
    assert levels.panels == (levels.smallest, levels.tightest)


def test_level_sets_facts_are_the_azimuths_in_degrees_and_the_positive_percentages(levels):
    assert levels.facts() == {
        "ch2_psi_small": int(round(np.degrees(levels.smallest.psi))),
        "ch2_psi_tight": int(round(np.degrees(levels.tightest.psi))),
        "ch2_pos_frac_small": round(100 * levels.smallest.positive_fraction_requested, 1),
        "ch2_pos_frac_tight": round(100 * levels.tightest.positive_fraction_requested, 1),
    }


def test_level_sets_summary_has_one_line_per_panel_with_its_numbers(levels):
    lines = levels.summary().splitlines()
    assert len(lines) == 2
    for line, panel in zip(lines, levels.panels):
        assert line == panel.summary()
        assert "lambda0 = %.4f;" % panel.lambda0 in line
        assert "from %.3f to %.3f" % (panel.dW.min(), panel.dW.max()) in line


def test_level_sets_export_is_every_third_line_of_the_figure_grid(levels):
    coarse = levels.export(step=3)
    assert len(coarse) == 2
    for small, panel in zip(coarse, levels.panels):
        assert small.y.shape == (11,) and small.W.shape == small.dW.shape == (11, 11)
        assert np.array_equal(small.y, panel.y[::3]) and np.array_equal(small.dW, panel.dW[::3, ::3])
        assert small.psi == panel.psi and small.alpha == panel.alpha


def test_level_set_subsampled_refuses_a_step_below_one(levels):
    with pytest.raises(ValueError, match="step"):
        levels.smallest.subsampled(0)


# ---- start region (chapter 2)

def test_start_region_summary_quotes_lambda0_and_max_dW_a_quarter_period_apart(osc_cert):
    region = algorithm.start_region_data(osc_cert)
    lam, dw = region.summary().splitlines()
    assert lam == f"lambda0 at psi = 0, 90, 180, 270 deg: {np.round(osc_cert.lambda0[::6], 4)}"
    assert dw == f"max W' on the shell at psi = 0, 90, 180, 270 deg: {np.round(osc_cert.max_dW[::6], 6)}"


def test_start_region_csv_has_one_row_per_azimuth(osc_cert, tmp_path):
    text = figure_csv(algorithm.start_region_data(osc_cert), tmp_path / "s.csv").read_text().splitlines()
    assert text[0] == "psi_deg,lambda0,A,A_requested,max_dW" and len(text) == 25


# ---- convergence (chapter 2)

def _convergence(A, lam_mean, n_sphere=(0, 16, 64)):
    n = len(n_sphere)
    return algorithm.ConvergenceData(
        n_sphere=np.array(n_sphere), A=np.array(A, dtype=float), alpha=np.ones(n), lambda0_min=np.ones(n),
        lambda0_mean=np.array(lam_mean, dtype=float), A_raw=np.ones(n), lambda0_mean_raw=np.ones(n))


def test_convergence_deviation_ignores_the_structured_directions_only_run():
    conv = _convergence(A=[0.5, 0.404, 0.4], lam_mean=[0.1, 0.3, 0.3])
    assert conv.largest_deviation == pytest.approx(0.01)
    assert conv.facts() == {"ch2_conv_dev": "1.00 %"}
    assert conv.summary().splitlines()[-1] == "largest deviation from the finest, refined, n_sphere >= 16: 1.00 %"


def test_a_convergence_deviation_below_the_printed_digits_is_not_printed_as_zero():
    """Chapter 2 printed "0.00 %" (issue 42): a deviation that rounds to zero is stated as the
    bound it lies below."""
    conv = _convergence(A=[0.5, 0.40001, 0.4], lam_mean=[0.1, 0.3, 0.3])
    assert conv.facts() == {"ch2_conv_dev": "< 0.005 %"}
    assert conv.summary().endswith("n_sphere >= 16: < 0.005 %")


def test_convergence_summary_prints_each_row_to_four_decimals():
    conv = _convergence(A=[0.44491, 0.41738, 0.40063], lam_mean=[0.3, 0.3, 0.3])
    lines = conv.summary().splitlines()
    assert lines[0] == "n_sphere:          [ 0 16 64]"
    assert lines[1] == "A (refined):       [0.4449 0.4174 0.4006]"


def test_convergence_without_sampled_runs_has_no_deviation():
    assert np.isnan(_convergence(A=[0.4], lam_mean=[0.3], n_sphere=(0,)).largest_deviation)


# ---- figures

def test_figure_functions_return_finished_figures_of_the_book_sizes_closed_in_pyplot(osc_cert, osc_history, levels):
    conv = _convergence(A=[0.44, 0.41, 0.40], lam_mean=[0.3, 0.29, 0.28])
    cases = [
        (algorithm.figure_level_sets(levels), (7.6, 4.2), 2),
        (algorithm.figure_start_region(algorithm.start_region_data(osc_cert)), (7, 3.6), 2),
        (algorithm.figure_max_norm(algorithm.max_norm_data(osc_history)), (7, 3.4), 1),
        (algorithm.figure_convergence(conv), (7, 3.8), 1),
    ]
    for fig, size, n_axes in cases:
        assert tuple(fig.get_size_inches()) == pytest.approx(size)
        assert len(fig.axes) == n_axes
        assert fig.number not in plt.get_fignums()


def test_all_names_exist():
    assert all(hasattr(algorithm, name) for name in algorithm.__all__)


def test_rule_comparison_shows_the_paper_rule_certifying_escaping_starts():
    """The chapter-2 counterexample: the paper's rule certifies azimuths whose motions pass A;
    the sound rule certifies none; the figure has its two panels with labelled axes."""
    data = algorithm.rule_comparison_data(n_periods=2.0)
    facts = data.facts()
    assert facts["ch2_cx_n_paper"] > 0 and facts["ch2_cx_n_sound"] == 0
    assert facts["ch2_cx_max_ratio"] > 1.0 and facts["ch2_cx_band_max"] > 0
    assert data.sim_norm.shape[1] == facts["ch2_cx_n_paper"]
    assert set(data.export()) == {"psi_deg", "lambda0_paper", "certified_paper", "certified_sound"}
    fig = algorithm.figure_rule_comparison(data)
    assert tuple(fig.get_size_inches()) == pytest.approx((7.6, 4.6))
    assert [ax.get_xlabel() for ax in fig.axes] == [r"azimuth $\psi$ (deg)", "revolutions after the start"]
    assert fig.number not in plt.get_fignums()
