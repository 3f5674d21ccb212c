"""Summaries, facts and figures of chapter 7 ("Validation and beyond"), on small data.

Each test names the fact it checks. The data objects are built by hand (or, for the quadratic
functions, computed in hover, which is cheap), so the tests check what the chapter prints and
glues from given numbers: the rounding, the glue names and the selections, not the physics.
"""

import dataclasses

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from rotorlyap.analysis.floquet import FloquetSweep  # noqa: E402
from rotorlyap.conventions import DEFAULT_SCALES  # noqa: E402
from rotorlyap.chapters import validation as fv  # noqa: E402
from rotorlyap.chapters.export import figure_csv  # noqa: E402
from rotorlyap.methods.validation import MotionHistory, Validation  # noqa: E402
from rotorlyap.model.parameters import BladeParameters  # noqa: E402

TWO_PI = 2 * np.pi


def _closed(fig) -> bool:
    return not plt.fignum_exists(fig.number)


# --------------------------------------------------------------------------------------
# Steady motions, inflow, fold
# --------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def motions():
    mu = np.array([0.0, 0.025, 0.25])
    found = np.array([[1, 1, 1], [1, 1, 1], [1, 0, 1]], dtype=bool)
    dist = np.array([[0.0, 2.44, 6.76], [0.0, 2.65, 7.86], [0.0, np.nan, 9.98]])
    harm = np.zeros((3, 3, 3, 3))
    harm[0, -1] = [[7.45, -2.4, -4.17], [2.84, -0.81, 0.55], [7.08, -0.53, -2.81]]
    res = np.array([[1e-14, 5e-8, 2.2e-3], [1e-14, 2e-7, 1.6e-3], [1e-14, np.nan, 3.4e-3]])
    psi = np.linspace(0.0, TWO_PI, 9)
    ang = np.zeros((3, 3, 9, 3)) + np.linspace(0, 5, 9)[None, None, :, None]
    ang[2, 1] = np.nan
    hov = np.array([[6.0, 3.0, 7.0], [6.0, 5.0, 7.0], [6.0, 10.46, 7.0]])
    return fv.SteadyMotions(cases=fv.CASES, mu_values=mu, found=found, distance=dist, harmonics_deg=harm,
                            residual=res, psi_plot=psi, angles_deg=ang, hover_deg=hov,
                            messages=(("", "", ""), ("", "", ""), ("", "no periodic solution", "")))


def test_grid_summary_states_the_scales_in_degrees_and_both_grids():
    lines = fv.grid_summary().splitlines()
    assert lines[0] == "scales a_i (deg, deg/rad): [2.  2.  1.  2.  0.5 5. ] ; A = 1.0"
    assert lines[1] == f"advance ratios, Floquet: {fv.MU_FLOQUET}"
    assert lines[2] == f"advance ratios, scans:   {fv.MU_SCAN}"


def test_max_distance_of_a_constant_state_is_its_offset_in_the_scaled_norm():
    class Shifted:
        def xi(self, psi):
            return np.broadcast_to(np.array([2.0, 0, 0, 0, 0, 0]) * DEFAULT_SCALES, np.shape(psi) + (6,))

    assert fv.max_distance(Shifted(), np.zeros(6)) == pytest.approx(2.0)


def test_steady_motion_facts_round_the_distances_and_list_the_missing_advance_ratios(motions):
    facts = motions.facts()
    assert facts == {"ch7_dist_025": 2.4, "ch7_dist_25": 6.8, "ch7_res_fw": 0.002, "ch7_res_all": 0.003,
                     "ch7_b1s_25": -4.2, "ch7_b1c_25": -2.4, "ch7_beta0_25": 7.5, "ch7_th1s_25": -2.8,
                     "ch7_n_mu": 3, "ch7_found_fn": 6, "ch7_miss_bwd": "0.025",
                     "ch7_found_fn_text": "all 6: 2 C.G. positions × 3 advance ratios", "ch7_kx": 1.2,
                     **fv.settings_facts()}
    # the settings the text quotes are the functions' defaults (not typed in the text)
    assert fv.settings_facts() == {"ch7_colloc_test": 64, "ch7_colloc_n": 256, "ch7_table_n": 4096,
                                   "ch7_floquet_steps": 1024, "ch7_lyap_steps": 4096, "ch7_opt_dirs": 128,
                                   "ch7_opt_evals": 200}
    assert all(type(v) in (float, int, str) for v in facts.values())


def test_steady_motion_summary_bounds_round_off_residuals_and_names_the_gaps(motions):
    text = motions.summary()
    assert "          residual: [< 1e-10, 5e-08, 2e-03]" in text.splitlines()
    assert "backward  found:    [1 0 1]" in text.splitlines()
    assert text.splitlines()[-1] == ("advance ratios without a periodic motion: "
                                     "{'forward': [], 'neutral': [], 'backward': [0.025]}")
    assert "forward C.G., mu = 0.25, (mean, cos, sin) harmonics (deg):" in text


def test_steady_motion_figure_has_four_panels_and_is_closed(motions, tmp_path):
    fig = fv.figure_steady_motions(motions)
    assert len(fig.axes) == 4 and _closed(fig)
    assert figure_csv(motions.export(), tmp_path / "m.csv").read_text().startswith("field,")


def test_inflow_facts_are_named_after_model_and_first_advance_ratio():
    d = fv.InflowData(case="forward", models=("glauert", "drees"), mu_values=np.array([0.0125, 0.025]),
                      distance=np.array([[2.304, 2.44], [0.4261, 0.92]]))
    assert d.facts() == {"ch7_dist_glauert_0125": 2.3, "ch7_dist_drees_0125": 0.43}
    assert d.summary().splitlines()[1] == (
        "inflow drees   : distance of the hover equilibrium at mu = 0.0125, 0.025: [0.43 0.92]")


def test_fold_summary_prints_the_largest_real_multiplier_to_four_decimals():
    d = fv.FoldData(case="backward", mu=0.005, mean_lag_deg=12.153, largest_real_multiplier=1.10371,
                    fail_mu=0.01, fail_message="no periodic solution", hover_lag_deg=10.456)
    assert d.summary().splitlines() == [
        "backward C.G., mu = 0.005: mean lag 12.15 deg, largest real multiplier 1.1037",
        "backward C.G., mu = 0.01: no periodic solution",
        "hover equilibrium: mean lag 10.46 deg"]
    assert d.facts() == {"ch7_fold_0": 1.104}


# --------------------------------------------------------------------------------------
# Floquet
# --------------------------------------------------------------------------------------

NAMES = ("lag+", "lag-", "flap+", "flap-", "pitch+", "pitch-")


def _sweep(case, steady, spectral_radius, multipliers=None):
    mu = np.array([0.0, 0.1, 0.25])
    sigma = np.tile([-0.145, -0.145, -0.381, -0.381, -1.294, -1.294], (3, 1))
    omega = np.tile([0.086, -0.086, 0.641, -0.641, 5.091, -5.091], (3, 1))
    mult = np.tile(np.exp(TWO_PI * (sigma[0] + 1j * omega[0])), (3, 1)) if multipliers is None else multipliers
    return FloquetSweep(case=case, steady=steady, mu=mu, names=NAMES, growth_rate=sigma, frequency=omega,
                        damping_ratio=np.zeros((3, 6)), multipliers=mult,
                        dominant=np.array([[n.rstrip("+-") for n in NAMES]] * 3),
                        spectral_radius=np.asarray(spectral_radius, dtype=float),
                        found=np.ones(3, dtype=bool), messages=("", "", ""))


@pytest.fixture(scope="module")
def floquet():
    mult = np.full((3, 6), 0.5 + 0j)
    mult[1, 2] = -1.1
    periodic = (_sweep("forward", "periodic", [0.4, 0.4, 0.4]), _sweep("neutral", "periodic", [0.54, 0.6, 0.5]),
                _sweep("backward", "periodic", [0.96, 1.1, 0.6], mult))
    hover = tuple(_sweep(c, "hover", [0.4, 0.4, 0.4]) for c in fv.CASES)
    return fv.FloquetData(cases=fv.CASES, mu_values=np.array([0.0, 0.1, 0.25]), periodic=periodic, hover=hover)


def test_floquet_facts_find_the_flip_instability_of_the_backward_cg(floquet):
    facts = floquet.facts()
    assert facts["ch7_flip_mu"] == 0.1 and facts["ch7_flip_m"] == -1.1 and facts["ch7_n_unstable_bwd"] == 1
    assert facts["ch7_n_unstable_bwd_text"] == "this advance ratio of the grid only"  # not "at 1 advance ratio"
    assert facts["ch7_bwd_sig_max"] == round(np.log(1.1) / TWO_PI, 3)
    assert facts["ch7_bwd_sig0"] == round(np.log(0.96) / TWO_PI, 4)
    assert facts["ch7_pitch_om0"] == 5.09 and facts["ch7_flap_om25"] == 0.64 and facts["ch7_lag_om0"] == 0.086
    assert len(facts) == 22 and facts["ch7_lag_sig0"] < 0  # the lag mode is damped in hover


def test_floquet_summary_lists_every_forward_track_and_the_largest_unstable_multiplier(floquet):
    lines = floquet.summary().splitlines()
    assert "forward C.G. tracks: ('lag+', 'lag-', 'flap+', 'flap-', 'pitch+', 'pitch-')" in lines
    assert sum(line.startswith("  pitch") for line in lines) == 2
    assert "backward C.G., unstable about the periodic motion at mu = [0.1]" in lines
    assert lines[-1] == "  mu = 0.1: largest multiplier (-1.1+0j)"


def test_floquet_figure_has_two_rows_per_case_and_is_closed(floquet):
    fig = fv.figure_floquet(floquet)
    assert len(fig.axes) == 6 and _closed(fig)


# --------------------------------------------------------------------------------------
# Quadratic functions and W' near the origin
# --------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def quadratic():
    return fv.quadratic_data("forward", mu=0.15)


def test_quadratic_summary_and_facts_round_what_the_chapter_quotes():
    d = fv.QuadraticData(
        case="forward", mu=0.15, summaries=("quadratic: ...", "quadratic, optimised Q: ..."),
        condition_number=43.77, lambda0_ratio=0.15115, lambda0_ratio_optimised=0.44862,
        weights=np.array([0.1302, 0.1881, 0.1084, 10.657, 2.376, 14.924]), other_cases=("neutral", "backward"),
        other_summaries=("quadratic: n", "quadratic: b"), other_lambda0_ratio=np.array([0.1272, 0.0347]),
        other_condition_number=np.array([61.8, 828.3]), other_growth_rate=np.array([-0.0975, -0.00672]),
        flutter_message="x" * 200, psi=np.radians([0.0, 30.0]), eps=np.array([1e-2, 1e-4]),
        dW_ratio=np.array([[0.0, 2.31], [0.0, 2.33]]), linear_term=np.array([0.0, -12.8]))
    assert d.facts() == {"ch7_q_ratio_neu": 0.127, "ch7_q_ratio_bwd": 0.035, "ch7_q_kappa_bwd": 828.0,
                         "ch7_q_growth_bwd": -0.0067, "ch7_q_kappa": 43.8, "ch7_q_ratio": 0.151, "ch7_qo_ratio": 0.449,
                         "ch7_w_pitch": 0.108, "ch7_w_flaprate": 10.7, "ch7_lin_max": 13.0}
    lines = d.summary().splitlines()
    assert lines[2] == ("optimised weights w_i (Q = diag(w_i / a_i^2)), flap, lag, pitch, rates: "
                        "[ 0.13   0.188  0.108 10.657  2.376 14.924]")
    assert lines[3:5] == ["neutral C.G.: quadratic: n", "backward C.G.: quadratic: b"]
    assert lines[5] == "backward C.G., cm_pitch_rate = 0: ValueError: " + "x" * 150 + " ..."
    assert lines[-3:] == ["  W'(psi, eps d) / eps, eps = 1e-2: [0.  2.3]", "  W'(psi, eps d) / eps, eps = 1e-4: [0.  2.3]",
                          "  2 d^T P f(psi, 0):                [  0.  -12.8]"]


@pytest.mark.slow
def test_quadratic_data_linear_term_is_the_small_disturbance_limit_of_dW(quadratic):
    big = np.abs(quadratic.linear_term) > 1.0
    assert big.any()
    np.testing.assert_allclose(quadratic.dW_ratio[-1][big], quadratic.linear_term[big], rtol=1e-2)


@pytest.mark.slow
def test_quadratic_data_says_why_the_flutter_case_has_no_function(quadratic):
    assert "not asymptotically stable" in quadratic.flutter_message
    assert "ValueError: the blade linearised" in quadratic.summary()


@pytest.mark.slow
def test_quadratic_facts_are_rounded_python_numbers(quadratic):
    facts = quadratic.facts()
    assert set(facts) == {"ch7_q_ratio_neu", "ch7_q_ratio_bwd", "ch7_q_kappa_bwd", "ch7_q_growth_bwd", "ch7_q_kappa",
                          "ch7_q_ratio", "ch7_qo_ratio", "ch7_w_pitch", "ch7_w_flaprate", "ch7_lin_max"}
    assert all(type(v) is float for v in facts.values())
    assert facts["ch7_qo_ratio"] > facts["ch7_q_ratio"]
    assert facts["ch7_q_ratio"] == pytest.approx(facts["ch7_q_kappa"] ** -0.5, abs=2e-3)


@pytest.mark.slow
def test_origin_functions_are_the_six_of_the_chapter_in_order(quadratic, forward_periodic_015, motions):
    mot = dataclasses.replace(motions, motions={("forward", 0.15): forward_periodic_015})
    funcs = quadratic.origin_functions(mot)
    assert list(funcs)[:2] == ["energy, hover", "quadratic Q = I, hover"]
    assert list(funcs)[-1] == "quadratic Q = I, mu = 0.15, periodic motion"
    assert [constant for _, constant in funcs.values()] == [True, True, True, False, False, False]


@pytest.fixture(scope="module")
def origin():
    labels = ("energy, hover", "quadratic Q = I, hover", "quadratic, optimised Q, hover",
              "energy, mu = 0.15, periodic motion", "quadratic Q = I, mu = 0.15, hover equilibrium",
              "quadratic Q = I, mu = 0.15, periodic motion")
    dw = np.array([[0.137] * 4, [-0.075, -0.07, -0.01, 0.06], [-0.01] * 4, [1.0, 0.5, 0.3, 0.2],
                   [160.0, 16.0, 1.6, 0.16], [0.9, -0.02, -0.05, 0.08]])
    return fv.OriginData(radii=np.array([1e-3, 1e-2, 1e-1, 1.0]), labels=labels, max_dW=dw, max_W=np.ones((6, 4)))


def test_origin_facts_bracket_where_the_quadratic_functions_change_sign(origin):
    assert origin.facts() == {"ch7_org_energy": 0.137, "ch7_org_quad": -0.075, "ch7_org_quad_pos": 1.0,
                              "ch7_org_quad_neg": 0.1, "ch7_org_per_lo": 0.01, "ch7_org_per_hi": 0.1}


def test_origin_summary_rounds_the_periodic_motion_rows_to_one_digit(origin):
    lines = origin.summary().splitlines()
    assert lines[0] == "radii: [1e-03 1e-02 1e-01 1e+00]"
    assert lines[2] == f"{'quadratic Q = I, hover':46s} [-0.075 -0.07 -0.01 0.06]"
    assert lines[-1] == f"{'quadratic Q = I, mu = 0.15, periodic motion':46s} [0.9 -0.02 -0.05 0.08]"


def test_origin_figure_has_one_panel_and_exports_its_arrays(origin, tmp_path):
    fig = fv.figure_origin(origin)
    assert len(fig.axes) == 1 and _closed(fig)
    assert set(origin.export()) == {"radius", "labels", "max_dW", "max_W"}
    figure_csv(origin.export(), tmp_path / "o.csv")


# --------------------------------------------------------------------------------------
# Checks of the scan: the paper's rule, the finer search
# --------------------------------------------------------------------------------------


def test_rule_changes_list_the_cells_whose_verdict_or_bounds_moved():
    """A cell changes when its azimuth count differs or A or the smallest lambda0 moves by more
    than 10 % (well beyond the 2.6 % by which another floating-point environment moves the paper
    rule's bound); cells without a result (-1) never count."""
    nan = np.nan
    d = fv.RuleChanges(labels=("quadratic Q = I, forward C.G.", "quadratic Q = I, backward C.G."),
                       mu_values=np.array([0.0, 0.2]), n_paper=np.array([[24, 24], [24, 8]]),
                       n_sound=np.array([[24, 24], [24, 0]]), A_paper=np.array([[0.56, 0.42], [0.0476, 0.3]]),
                       A_sound=np.array([[0.5601, 0.42], [0.0427, 0.0]]),
                       lambda0_paper=np.array([[0.085, 0.05], [0.0019, 0.01]]),
                       lambda0_sound=np.array([[0.085, 0.05], [0.0015, 0.0]]), n_psi=24)
    np.testing.assert_array_equal(d.changed(), [[False, False], [True, True]])
    assert d.rows()[0][3] == "0.048 -> 0.043"
    near = fv.RuleChanges(labels=("x",), mu_values=np.array([0.1]), n_paper=np.array([[24]]),
                          n_sound=np.array([[24]]), A_paper=np.array([[0.286]]), A_sound=np.array([[0.275]]),
                          lambda0_paper=np.array([[0.0314]]), lambda0_sound=np.array([[0.0301]]), n_psi=24)
    assert not near.changed().any()  # 3.8 % and 4.1 %: within what the searches determine
    assert d.rows()[1] == ("quadratic Q = I, backward C.G.", "0.2", "8 -> 0", "0.30 -> 0", "0.010 -> -")
    assert d.facts() == {"ch7_rule_changed": 2, "ch7_rule_cells": 4, "ch7_rule_rtol_pct": 10.0, "ch7_rule_lost": 1,
                         "ch7_rule_gained": 0}
    assert d.summary() == ("changed: 2 of 4 cells; passed by the paper's rule, not certified "
                           "by the sound rule: 1; certified by the sound rule, not passed by the paper's: none")
    assert d.markdown().splitlines()[0].startswith("| function, case | mu | azimuths of 24, paper's -> sound |")
    e = fv.RuleChanges(labels=("x",), mu_values=np.array([0.1]), n_paper=np.array([[-1]]),
                       n_sound=np.array([[-1]]), A_paper=np.array([[nan]]), A_sound=np.array([[nan]]),
                       lambda0_paper=np.zeros((1, 1)), lambda0_sound=np.zeros((1, 1)), n_psi=24)
    assert not e.changed().any()


def test_search_check_reports_the_largest_relative_change_in_percent():
    """Over both finer searches; a cell certified by one search only is an infinite change."""
    d = fv.SearchCheck(case="forward", keys=("quadratic", "quadratic-opt"), mu_values=np.array([0.0, 0.25]),
                       n_sphere=1024, n_iter=160, A=np.array([[0.5595, 0.5595, 0.5595], [0.1985, 0.1985, 0.1984]]),
                       min_lambda0=np.array([[0.0848, 0.0848, 0.0848], [0.0541, 0.0540, 0.0541]]),
                       n_stable=np.array([[24, 24, 24], [20, 20, 20]]))
    # 1 - 0.0540 / 0.0541 = 0.18 %: within two bound searches' resolution (BOUND_RTOL each)
    assert d.facts() == {"ch7_conv": "at most 0.2 %, the resolution of two bound searches of 0.1 % each"}
    wider = dataclasses.replace(d, min_lambda0=np.array([[0.0848, 0.0848, 0.0848], [0.0541, 0.0530, 0.0541]]))
    assert wider.facts() == {"ch7_conv": "2.0 %"}  # beyond the resolution: to one decimal
    lines = d.summary().splitlines()
    assert lines[0] == "scan -> n_sphere 1024 -> n_iter 160"
    # three digits: the engine finds a bound to BOUND_RTOL (0.1 %)
    assert lines[1] == ("quadratic      mu = 0.00: A 0.559 -> 0.559 -> 0.559, "
                        "min lambda0 0.0848 -> 0.0848 -> 0.0848, azimuths 24 -> 24 -> 24")
    e = fv.SearchCheck(case="forward", keys=("quadratic",), mu_values=np.array([0.25]), n_sphere=1024,
                       n_iter=160, A=np.array([[0.0, 0.0, 0.1]]), min_lambda0=np.array([[0.0, 0.0, 0.01]]),
                       n_stable=np.array([[0, 0, 24]]))
    assert np.isinf(e.relative_change[0])


# --------------------------------------------------------------------------------------
# Validation
# --------------------------------------------------------------------------------------


def _validation(label, names, readings, radius, max_norm, covered, A_used):
    radius, max_norm = np.asarray(radius, dtype=float), np.asarray(max_norm, dtype=float)
    return Validation(label=label, A=1.0, n_periods=10.0, psi=np.zeros(1), psi_index=np.zeros(radius.size, dtype=int),
                      radius=radius, x0=np.zeros((radius.size, 6)), max_norm=max_norm, bounded=max_norm < 1.0,
                      names=names, readings=readings, covered=np.asarray(covered, dtype=bool),
                      A_used=np.asarray(A_used, dtype=float))


@pytest.fixture(scope="module")
def validations():
    fw = _validation("forward C.G., mu = 0", ("energy-practical", "energy", "quadratic", "quadratic-opt"),
                     ("practical", "strict", "strict", "strict"), [0.1, 0.1, 0.5, 0.5, 1.0, 1.0],
                     [0.09, 0.12, 0.4, 0.6, 1.0, 0.8],
                     [[1, 1, 0, 0, 0, 0], [0] * 6, [1, 1, 0, 0, 0, 0], [1, 1, 1, 1, 0, 0]], [1.0, 0.0, 0.2, 0.7])
    hover = tuple(_validation(f"{case} C.G., mu = 0", ("paper", "energy", "quadratic", "quadratic-opt"),
                              ("practical", "strict", "strict", "strict"), [0.1, 1.0], [0.05, 1.0],
                              [[1, 1], [0, 0], [1, 0], [1, 0]], [1.0, 0.0, 0.5, 0.5])
                  for case in ("neutral", "backward"))
    return fv.ValidationData(forward=(fw,), hover=hover, hover_cases=("neutral", "backward"),
                             labels={c.key: c.label for c in fv.CANDIDATES}, lambda0_hover=(0.05, 0.25))


def test_validation_counts_each_certified_motion_once(validations):
    assert validations.counts() == (10, 6, 0)
    assert validations.summary().splitlines()[-2] == "motions: 10 ; certified (strict): 6 ; certified but beyond their bound: 0"


def test_validation_facts_compare_the_observed_bounded_region_with_the_certified_one(validations):
    f = validations.facts()
    assert (f["ch7_obs_all_bounded"], f["ch7_obs_ratio_q"], f["ch7_obs_ratio_o"]) == (0.5, 10.0, 2.0)
    assert f["ch7_growth_ratio"] == 1.2
    assert (f["ch7_hov_cert_neu"], f["ch7_hov_viol_bwd"], f["ch7_hov_paper_left_bwd"]) == (1, 0, 1)
    # the starts on ||x|| = A "reach A" at once; none inside A reached it
    assert (f["ch7_on_sphere_hover"], f["ch7_on_sphere_fwd"], f["ch7_inside_reached_fwd"]) == (2, 2, 0)
    assert (f["ch7_inside_reached_neu"], f["ch7_inside_reached_bwd"]) == (0, 0)


def test_validation_table_has_a_row_per_function_and_validation(validations, tmp_path):
    table = validations.confusion_table().splitlines()
    assert table[0] == "| " + " | ".join(fv.CONFUSION_HEADER) + " |"
    assert len(table) == 2 + 12
    assert validations.summary().splitlines()[0] == ("forward C.G., mu = 0: starts on ||x|| = A 2, started inside A "
                                                     "and reached it 0")
    figure_csv(validations.export(), tmp_path / "v.csv")
    fig = fv.figure_validation(validations)
    assert len(fig.axes) == 1 and _closed(fig)


def test_validation_legend_names_every_group_drawn_in_any_panel(validations):
    """A start certified by Q = I alone, drawn only in the second panel, is named in the first
    panel's legend (the only legend), as are the certified bounds."""
    import matplotlib.pyplot as plt
    only_q = _validation(
        "forward C.G., mu = 0.25", ("quadratic", "quadratic-opt"), ("strict", "strict"), [0.1, 0.5],
        [0.1, 0.5], [[1, 0], [0, 0]], [0.3, 0.0])
    fig, axes = plt.subplots(1, 2)
    fv.plot_validation((validations.forward[0], only_q), axes)
    labels = [t.get_text() for t in axes[0].get_legend().get_texts()]
    plt.close(fig)
    assert "certified by Q = I only" in labels and "certified $A$, Q = I" in labels


# --------------------------------------------------------------------------------------
# What the motion does
# --------------------------------------------------------------------------------------

K = 16  # output points per revolution


def _history(label, n_rev=8, peaks=(0.5, 1.0, 2.0, 4.0, 5.0, 5.05, 5.0, 5.0)):
    psi = np.linspace(0.0, TWO_PI * n_rev, n_rev * K + 1)
    x = np.zeros((psi.size, 2, 6))
    x[:, :, 2] = 0.1 * np.sin(4 * psi + 0.3)[:, None]  # four pitch oscillations per revolution
    peaks = np.column_stack([peaks, peaks])
    return MotionHistory(label=label, psi=psi, x=x, norm=np.abs(x[:, :, 2]) / DEFAULT_SCALES[2], peaks=peaks,
                         escaped=np.zeros(2, dtype=bool), verdict=("limit cycle outside A",) * 2, A=1.0)


@pytest.fixture(scope="module")
def long_runs():
    params = (BladeParameters.table_i("backward", cm_pitch_rate=0.0), BladeParameters.table_i("backward"),
              BladeParameters.table_i("forward"))
    hist = tuple(_history(label) for label in ("flutter", "drift", "forward"))
    off = tuple(np.broadcast_to(np.radians([6.0, 10.0, 6.9, 0, 0, 0]), (h.psi.size, 6)).copy() for h in hist)
    return fv.MotionData(histories=hist, labels=tuple(h.label for h in hist), start_labels=(("a", "b"),) * 3,
                         offsets=off, reference=(None, None, np.full(hist[2].psi.size, 4.6712)),
                         check=(3e-4, 1e-5, 2e-4), parameters=params, mu_values=(0.0, 0.05, 0.15))


def test_motion_summary_bounds_the_tolerance_check_by_a_power_of_ten(long_runs):
    lines = long_runs.summary().splitlines()
    assert lines[-1] == "relative change of the last peak with ten times tighter tolerances: < 1e-03 for every motion"
    assert lines[0].startswith("flutter: both starts: settles on a periodic motion outside A; peak norm in the last "
                               "revolution 5.0 5.0; pitch 1.4 to 12.4 deg")
    assert long_runs.facts() == {"ch7_lc_check": 0.001, "ch7_ff_ref_max": 4.67, "ch7_ff_peak": 5.0}


def test_flutter_cycle_counts_pitch_oscillations_and_the_revolution_it_settles_in(long_runs):
    d = fv.flutter_cycle(long_runs)
    assert d.oscillations_per_rev == 4.0
    assert d.settle_revolution == 5
    f = d.facts()
    assert (f["ch7_lc_thmin"], f["ch7_lc_thmax"], f["ch7_lc_th0"]) == (1, 12, 6.9)
    assert f["ch7_stall"] == round(float(np.degrees(long_runs.parameters[0].airfoil.alpha_stall)), 1)
    assert d.summary().startswith("flutter limit cycle: largest angle of attack ")


def test_motion_figure_has_three_panels_and_is_closed(long_runs, tmp_path):
    fig = fv.figure_motions(long_runs)
    assert len(fig.axes) == 3 and _closed(fig)
    figure_csv(long_runs.export(), tmp_path / "l.csv")


def test_far_motion_prints_its_residual_as_a_bound():
    d = fv.FarMotion(label="backward C.G., mu = 0.05", residual=3e-14, mean_lag_deg=30.94, hover_lag_deg=10.46,
                     spectral_radius=0.6004, distance_end=0.0131, distance_hover=17.48, peak=17.46)
    assert d.summary().splitlines() == [
        "backward C.G., mu = 0.05: Newton from the last simulated revolution converges, residual < 1e-10; "
        "mean lag 30.9 deg (hover 10.5 deg), spectral radius 0.600; distance of the simulated last revolution "
        "from it 1.3e-02",
        "   distance from the hover equilibrium: 17.5"]
    assert d.facts() == {"ch7_far_lag": 30.9, "ch7_far_lag_hover": 10.5, "ch7_far_res": "< 1e-10",
                         "ch7_far_rho": 0.6, "ch7_far_dist": 17.5, "ch7_far_peak": 17.5}
