"""Data and drawing functions of chapter 5, hover (the paper's Figs 4 and 5,
:mod:`rotorlyap.chapters.hover`), on coarse grids.

Each test names the fact it checks. The grids are far coarser than the book's; what is
checked is the structure of the data, the readings' labels and the physical facts the
chapter rests on.
"""

import matplotlib

matplotlib.use("Agg")

import dataclasses  # noqa: E402

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from rotorlyap.chapters import cases, hover  # noqa: E402
from rotorlyap.chapters.export import figure_csv  # noqa: E402


@pytest.fixture(scope="module")
def trim():
    return hover.hover_trim_data(cg_values=(0.22, 0.25))


def test_fig4_thrust_equals_the_weight_for_every_trim(trim):
    assert np.allclose(trim.thrust, trim.weight, rtol=0, atol=1e-6)
    assert np.allclose(trim.case_thrust, trim.weight, rtol=0, atol=1e-6)
    assert trim.weight == pytest.approx(6400.0 * 9.80665)


def test_fig4_collective_decreases_as_the_cg_moves_aft_and_the_pitch_angle_stays(trim):
    assert trim.case_names == ("forward", "neutral", "backward")
    assert np.all(np.diff(trim.case_collective) < 0)
    assert np.ptp(trim.case_equilibrium[:, 2]) < np.radians(0.1)
    assert trim.equilibrium.shape == (2, 3) and trim.case_equilibrium.shape == (3, 3)


def test_fig4_draws_and_writes_its_csv(trim, tmp_path):
    fig, axes = plt.subplots(1, 2)
    hover.plot_hover_trim(trim, axes)
    plt.close(fig)
    out = figure_csv(trim, tmp_path / "trim.csv")
    assert out.read_text().startswith("field,")


@pytest.fixture(scope="module")
def rate():
    """Fig. 5 on the three cases and one C.G. behind them that linear theory finds unstable."""
    return hover.hover_rate_data((0.215, 0.235, 0.255, 0.265), n_sphere=64, n_refine=4, n_fraction=512, n_grid=11)


def test_fig5_strict_positive_practical_zero_and_labelled(rate):
    d = rate
    assert d.strict_label == "strict (numerical certificate)"
    assert d.practical_label == "practical (indicator, not a certificate)"
    # the caution on the real model: W' > 0 on the sphere at every C.G., found by the search
    assert np.all(d.strict_max > 50.0)
    assert np.all(d.strict_positive_fraction > 0.05)
    # the argmax is mostly a pitch displacement with a flap rate
    assert np.all(np.abs(d.strict_argmax[:, 2]) > 0.8) and np.all(np.abs(d.strict_argmax[:, 3]) > 0.1)
    # and its work is the aerodynamic flap moment on the flap rate
    assert np.all(d.terms_aero[:, 0] > 0.9 * d.strict_max)
    # practical: pure displacements do no work, pure rates are damped
    assert np.all(d.practical_max <= 1e-9)
    disp = np.abs(d.test_disturbances[:, :3]).max(axis=1) > 0.5
    assert np.allclose(d.practical_dW[:, disp], 0.0, atol=1e-9)
    assert np.all(d.practical_dW[:, ~disp] < 0.0)
    # linear theory: the three cases stable, 0.01 c behind the backward one unstable
    assert np.all(d.eig_max_real[:3] < 0) and d.eig_max_real[3] > 0
    assert d.slice_dW.shape == (11, 11)
    fig, axes = plt.subplots(2, 2)
    hover.plot_hover_rate(d, axes.ravel())
    plt.close(fig)


# --------------------------------------------------------------------------------------
# The chapter's printed summaries and glued facts (chapter 5)
# --------------------------------------------------------------------------------------


def _closed_figure(fig, size, n_axes):
    assert isinstance(fig, Figure)
    assert not plt.fignum_exists(fig.number)  # returned, not left open for the notebook to show
    assert tuple(fig.get_size_inches()) == pytest.approx(size)
    assert len(fig.axes) == n_axes


def test_hover_sweep_is_the_three_cases_and_0_01_c_steps_to_0_02_c_beyond_them():
    sweep = hover.hover_sweep()
    assert np.allclose(sweep.cg, np.arange(0.195, 0.2751, 0.01))
    assert all(np.isclose(sweep.cg, c).any() for c in sweep.case_cg)
    assert sweep.facts() == {"ch5_cg_forward": 0.215, "ch5_cg_neutral": 0.235, "ch5_cg_backward": 0.255,
                             "ch5_sweep_lo": 0.195, "ch5_sweep_hi": 0.275}
    lines = sweep.summary().splitlines()
    assert lines[0] == "C.G. of the cases (c): forward 0.215, neutral 0.235, backward 0.255"
    assert lines[-1].startswith("scales a_i") and not any("strict" in ln or "practical" in ln for ln in lines)


def test_fig4_facts_quote_a_collective_falling_as_the_cg_moves_aft_at_equal_angles(trim):
    f = trim.facts()
    assert f["ch5_col_slope"] < 0
    assert f["ch5_col_forward"] > f["ch5_col_neutral"] > f["ch5_col_backward"]
    assert f["ch5_eq_spread"] < 0.5
    assert f["ch5_weight"] == pytest.approx(62.76)
    assert {f"ch5_{q}_{c}" for q in ("col", "beta", "zeta", "theta") for c in cases.CASES} <= set(f)
    assert all(isinstance(v, float) for v in f.values())  # plain floats: glued as their repr


def test_fig4_summary_confirms_thrust_equals_weight_for_every_case(trim):
    lines = trim.summary().splitlines()
    assert len(lines) == 8
    assert all(line.endswith("below 1e-6") for line in lines[1:4])
    assert "|thrust - weight| < 1e-6 N for every trim: True" in lines[6]


def test_fig4_figure_is_the_books_two_panels(trim):
    _closed_figure(hover.figure_hover_trim(trim), (9.0, 4.2), 2)


@pytest.mark.slow
def test_trim_limit_lies_between_a_trimmable_and_an_untrimmable_cg():
    lim = hover.trim_limit_data(0.28, 0.30, tol=1e-2)
    assert 0.28 <= lim.cg_limit < lim.cg_untrimmable <= 0.30
    assert lim.cg_untrimmable - lim.cg_limit <= 1e-2
    assert lim.facts() == {"ch5_trim_limit": round(lim.cg_limit, 3)}
    assert lim.summary().startswith("hover trim with positive collective exists up to a C.G. of 0.2")


def test_trim_limit_needs_an_untrimmable_upper_end():
    with pytest.raises(ValueError, match="untrimmable"):
        hover.trim_limit_data(0.215, 0.225, tol=1e-2)


@pytest.fixture(scope="module")
def modes():
    return hover.hover_modes_data()


def test_hover_modes_all_cases_stable_and_the_forward_least_damped_a_slow_lag_pair(modes):
    for case in cases.CASES:
        assert modes.least_damped(case).growth_rate < 0
    fwd = modes.least_damped("forward")
    assert fwd.oscillatory and fwd.dominant_hinge == "lag" and fwd.frequency < 0.2
    assert not modes.least_damped("neutral").oscillatory and not modes.least_damped("backward").oscillatory
    f = modes.facts()
    assert f["ch5_re_forward"] < f["ch5_re_neutral"] < f["ch5_re_backward"] < 0
    assert f["ch5_lag_share_forward"] < 0.5 and f["ch5_tau_backward"] > 10


def test_hover_pitch_mode_is_the_fastest_mode_and_almost_pure_pitch(modes):
    for case, ms in zip(modes.case_names, modes.modes):
        pm = modes.pitch(case)
        assert pm.frequency == max(m.frequency for m in ms)
        assert pm.shape[2] == 1.0 and max(pm.shape[:2]) < 0.1


def test_backward_cg_flutters_without_the_aerodynamic_pitch_damping(modes):
    assert modes.pitch("backward", pitch_damping=False).growth_rate > 0
    assert modes.pitch("forward", pitch_damping=False).growth_rate < 0
    assert modes.facts()["ch5_pitch_re0_backward"] > 0


def test_hover_modes_summary_lists_each_mode_once_least_damped_first(modes):
    for ms in modes.modes:
        rates = [m.growth_rate for m in ms]
        assert rates == sorted(rates, reverse=True)
    rows = modes.summary().splitlines()[1:1 + sum(len(ms) for ms in modes.modes)]
    assert [r.split()[0] for r in rows] == ["forward"] * 3 + ["neutral"] * 4 + ["backward"] * 4
    assert rows[0].split()[2:5] == ["-0.145", "+-", "0.086j"]


@pytest.fixture(scope="module")
def readings():
    return hover.hover_readings_data(("forward",), n_psi=4)


def test_hover_readings_strict_certifies_nothing_practical_every_azimuth(readings):
    (s,), (q,) = readings.strict, readings.practical
    assert s.reading == "strict" and q.reading == "practical"
    assert not s.stable.any() and q.stable.all()
    f = readings.facts()
    assert f["ch5_prac_stable_forward"] == 4 and f["ch5_step3_forward"] > 50
    assert 0 < f["ch5_prac_lambda0"] < 1
    assert readings.summary().splitlines()[1].startswith("  strict (numerical certificate): nothing certified")


def test_search_check_the_engines_default_search_finds_the_refined_maximum(readings, rate):
    check = hover.search_check(readings, rate)
    assert check.case_names == ("forward",)
    assert check.gap < 1.0
    assert check.facts() == {"ch5_search_gap": round(check.gap, 2)}
    assert check.summary().splitlines()[1].startswith("forward   ") and "refined (Fig. 5)" in check.summary()


def test_fig5_facts_quote_a_flat_strict_maximum_and_the_forward_maximiser(rate):
    f = rate.facts()
    assert abs(f["ch5_smax_change"]) < 2
    assert f["ch5_smax_forward"] == round(float(rate.strict_max[0]), 1)
    assert f["ch5_pmax"] == "< 1e-10"  # exactly 0 J/rad to round-off, as text
    assert f["ch5_arg_theta"] > 0.8 and f["ch5_aero_flap"] > 0.9 * f["ch5_smax_forward"]
    assert f["ch5_cg_most_stable"] == 0.215 and f["ch5_eig_hi"] > 0 > f["ch5_eig_lo"]
    lines = rate.summary().splitlines()
    assert len(lines) == 11 and lines[7].startswith("argmax x_i/a_i at 0.215 c:")


def test_fig5_case_index_needs_the_case_in_the_sweep(rate):
    assert rate.case_index("backward") == 2
    short = dataclasses.replace(rate, cg=rate.cg + 0.001)
    with pytest.raises(ValueError, match="does not contain"):
        short.case_index("forward")


def test_fig5_figure_is_the_books_four_panels_and_a_colour_bar(rate):
    _closed_figure(hover.figure_hover_rate(rate), (9.0, 8.8), 5)


@pytest.mark.slow
def test_linear_divergence_sets_in_just_behind_the_backward_case_as_a_real_root(rate):
    div = hover.hover_divergence_data(rate, n_psi=4, xtol=1e-3)
    assert 0.255 < div.cg_cross < 0.265
    assert not div.cross_mode.oscillatory and abs(div.cross_mode.growth_rate) < 1e-2
    assert np.all(np.diff(div.pitch_re) > 0)  # the pitch mode loses damping monotonically aft
    f = div.facts()
    assert f["ch5_n_div"] == 1 and f["ch5_n_div_prac_min"] == 4  # the practical reading still says stable
    assert 0 < f["ch5_div_behind_backward"] < 0.01
    assert div.summary().splitlines()[0].endswith("(there: a real root, frequency 0.000/rev)")


def test_linear_divergence_needs_a_sweep_that_turns_unstable(rate):
    stable = dataclasses.replace(rate, eig_max_real=-np.abs(rate.eig_max_real))
    with pytest.raises(ValueError, match="turn unstable"):
        hover.hover_divergence_data(stable)
