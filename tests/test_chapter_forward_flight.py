"""Data and drawing functions of chapter 6, forward flight (the paper's Figs 6-8,
:mod:`rotorlyap.chapters.forward_flight`), on coarse grids.

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

from rotorlyap.chapters import cases, forward_flight  # noqa: E402
from rotorlyap.chapters.export import figure_csv  # noqa: E402
from rotorlyap.chapters.style import MIN_TEXT_PX, check_legible  # noqa: E402
from rotorlyap.conventions import DEFAULT_SCALES, PAPER_TEST_DISTURBANCES  # noqa: E402


@pytest.fixture(scope="module")
def wsph():
    return forward_flight.w_spheres_data("forward", 0.15, (0.5, 1.0, 2.0), n_psi=6, n_sphere=16)


def test_fig6_energy_does_not_depend_on_azimuth_and_grows_as_A_squared(wsph):
    d = wsph
    assert d.strict_inf.shape == (3, 6) and d.practical_max.shape == (3, 6)
    assert np.allclose(d.strict_inf, d.strict_inf[:, :1], rtol=1e-9)
    assert np.all(np.diff(d.strict_inf.mean(axis=1)) > 0)
    ratio = d.strict_inf.mean(axis=1) / d.A_values ** 2
    assert np.allclose(ratio, ratio[0], rtol=0.02)
    assert np.all(d.strict_inf <= d.practical_min + 1e-12)
    assert np.all(d.strict_sup >= d.practical_max - 1e-12)
    fig, axes = plt.subplots(1, 2)
    forward_flight.plot_w_spheres(d, axes)
    plt.close(fig)


@pytest.fixture(scope="module")
def rate7():
    return forward_flight.rate_azimuth_data("forward", (0.0, 0.15), n_psi=8, n_sphere=16)


def test_fig7_shapes_hover_zero_and_forward_flight_positive(rate7):
    """Pure displacement disturbances (zero rates) have W' = 0 exactly, so the practical maximum
    is never negative; in hover it is 0 (damping only), about the hover equilibrium reused at
    mu = 0.15 a rate disturbance gains energy at most azimuths."""
    d = rate7
    assert d.strict_max.shape == (2, 8) == d.practical_max.shape
    assert np.allclose(d.practical_max[0], 0.0, atol=1e-9)
    assert np.all(d.practical_max[1] >= 0) and (d.practical_max[1] > 1.0).sum() >= 5
    assert np.all(d.strict_max >= d.practical_max - 1e-9)
    fig, axes = plt.subplots(1, 2)
    forward_flight.plot_rate_azimuth(d, axes)
    plt.close(fig)


@pytest.fixture(scope="module")
def regions():
    return forward_flight.regions_data(("forward",), (0.0, 0.1), reading="practical", n_psi=8)


def test_fig8_practical_reading_is_labelled_and_hover_is_indicated_stable(regions):
    assert regions.reading == "practical"
    assert regions.label == "practical (indicator, not a certificate)"
    assert regions.category.shape == (1, 2, 8) == regions.stable.shape
    assert regions.stable[0, 0].all()
    assert not regions.stable[0, 1].any()
    assert set(np.unique(regions.category)) <= {0, 1, 2, 3}


def test_fig8_strict_reading_is_labelled_and_certifies_nothing_in_hover():
    reg = forward_flight.regions_data(("forward",), (0.0,), reading="strict", n_psi=4, n_sphere=64)
    assert reg.label == "strict (numerical certificate)"
    assert not reg.stable.any()
    assert np.all(reg.A_used == 0.0)


def test_fig8_polar_plot_puts_the_tail_at_psi_0_and_the_advancing_side_at_psi_90(regions):
    fig = plt.figure()
    ax = fig.add_subplot(projection="polar")
    forward_flight.plot_regions_polar(regions, ax, 0)
    # psi = 0 points down (the tail), psi increases counter-clockwise: psi = 90 deg is on the right
    assert np.cos(ax.get_theta_offset()) == pytest.approx(0.0, abs=1e-12)
    assert np.sin(ax.get_theta_offset()) == pytest.approx(-1.0)
    assert ax.get_theta_direction() == 1
    to_xy = lambda th: (np.cos(th * ax.get_theta_direction() + ax.get_theta_offset()),  # noqa: E731
                        np.sin(th * ax.get_theta_direction() + ax.get_theta_offset()))
    assert to_xy(0.0)[1] == pytest.approx(-1.0)
    assert to_xy(np.pi / 2)[0] == pytest.approx(1.0)
    fig.canvas.draw()
    labels = {lab.get_text(): theta for lab, theta in zip(ax.get_xticklabels(), ax.get_xticks())}
    for word, angle in (("advancing", 90), ("retreating", 270), ("tail", 0), ("nose", 180)):
        [(text, theta)] = [(k, v) for k, v in labels.items() if word in k]
        assert theta == pytest.approx(np.radians(angle)), word
    plt.close(fig)


def test_fig8_plane_plot_draws(regions):
    fig, ax = plt.subplots()
    forward_flight.plot_regions_plane(regions, ax, 0)
    plt.close(fig)


def test_sensitivity_variants_keep_their_labels_and_directions():
    d = forward_flight.sensitivity_data("forward", (0.0, 0.1), {"default": {}, "flap-lag": dict(
        test_disturbances=forward_flight.FLAP_LAG_TEST_DISTURBANCES)}, n_psi=4)
    assert d.names == ("default", "flap-lag")
    assert d.n_tests == (12, 8)
    assert all(r.reading == "practical" for r in d.regions)
    assert len(d.first_unstable()) == 2
    fig, axes = plt.subplots(1, 3)
    forward_flight.plot_sensitivity(d, axes)
    plt.close(fig)


def test_practical_threshold_is_below_the_first_forward_flight_grid_point():
    mu = forward_flight.practical_threshold_mu("forward", mu_lo=1e-4, n_psi=8, n_bisect=2)
    assert 0 < mu <= cases.MU_GRID[1]


def test_markdown_table_escapes_pipes():
    t = forward_flight.markdown_table(("a", "b"), [("x|y", "z")])
    assert t.splitlines()[0] == "| a | b |"
    assert "x\\|y" in t


# --------------------------------------------------------------------------------------
# The chapter's printed summaries and glued facts (chapter 6)
# --------------------------------------------------------------------------------------


def _closed_figure(fig, size, n_axes):
    assert isinstance(fig, Figure)
    assert not plt.fignum_exists(fig.number)  # returned, not left open for the notebook to show
    assert tuple(fig.get_size_inches()) == pytest.approx(size)
    assert len(fig.axes) == n_axes


def test_unbalanced_loads_vanish_in_hover_and_not_in_forward_flight():
    hover = forward_flight.unbalanced_loads_data("forward", 0.0, psi_step_deg=90.0)
    assert np.allclose(hover.delta_q, 0.0, atol=1e-6)
    loads = forward_flight.unbalanced_loads_data("forward", 0.15, psi_step_deg=45.0)
    f = loads.facts()
    assert set(f) == {f"ch6_dq_{h}_{e}" for h in ("flap", "lag", "pitch") for e in ("min", "max")}
    assert f["ch6_dq_flap_max"] > 1e5 > f["ch6_dq_flap_min"]
    assert loads.summary().splitlines()[0].startswith("Delta Q(psi, x = 0) at mu = 0.15, forward C.G.")


def test_fig6_pitch_displacement_is_the_axis_with_the_least_energy(wsph):
    assert int(np.argmin(wsph.axis_W)) == 2
    f = wsph.facts()
    assert f["ch6_w_theta"] < f["ch6_w_fl_min"]
    assert f["ch6_w_var"] == "< 1e-12"  # W has no azimuth in it: zero to round-off, as text
    assert {f"ch6_winf_{i}" for i in range(3)} <= set(f) and abs(f["ch6_rinf_change"]) < 2
    assert wsph.summary().splitlines()[-1].startswith("W along each axis at ||x|| = 1 (J): beta ")
    assert "\\" not in wsph.summary() and "$" not in wsph.summary()  # TeX only in the figures


def test_threshold_summary_says_where_the_indicator_fails_already_and_where_it_passes():
    """A threshold equal to the smallest advance ratio tried is a failure there, not "stable up
    to" it; the indicator's verdict is "passes", never "stable"."""
    thr = forward_flight.ThresholdData(cg="forward", models=("glauert", "drees"), test_sets=("12 axes",),
                              threshold=np.array([[1e-7], [0.0015]]), speed_model="drees",
                              hover_lambda0=np.array([0.04]), speed=np.array([0.33]), mu_lo=1e-7)
    lines = thr.summary().splitlines()
    assert lines[0].endswith("fails already at mu = 1e-07 (threshold below it)")
    assert lines[1].endswith("passes at every azimuth below mu = 0.0015")
    assert "stable" not in thr.summary()


def test_unbalanced_load_facts_keep_three_significant_figures():
    """A moment below 10 N m is glued with its decimal (9.3, not 9.0)."""
    data = forward_flight.UnbalancedLoadsData.__new__(forward_flight.UnbalancedLoadsData)
    object.__setattr__(data, "delta_q", np.array([[1.2345e5, -3.3, 9.27], [2.5e5, 2.0, 104.6]]))
    f = data.facts()
    assert f["ch6_dq_pitch_min"] == 9.27 and f["ch6_dq_pitch_max"] == 105.0 and f["ch6_dq_flap_max"] == 2.5e5


def test_fig6_figure_is_the_books_two_panels(wsph):
    _closed_figure(forward_flight.figure_w_spheres(wsph), (8.6, 6.6), 2)


def test_fig7_the_largest_axis_maximum_is_the_practical_maximum(rate7):
    assert rate7.axis_max.shape == (2, 12)
    assert np.allclose(rate7.axis_max.max(axis=1), rate7.practical_max.max(axis=1))
    f = rate7.facts()
    assert f["ch6_f7_ax_betadot"] > f["ch6_f7_ax_thetadot"]  # the flap rate carries W'
    assert f["ch6_f7_npos_005"] + f["ch6_f7_nzero_005"] == 8
    assert rate7.summary().splitlines()[-2] == "mu = 0.15: largest W' over the azimuth along each axis (J/rad):"


def test_fig7_figure_is_the_books_two_panels(rate7):
    _closed_figure(forward_flight.figure_rate_azimuth(rate7), (9.0, 4.2), 2)


@pytest.fixture(scope="module")
def maps():
    return forward_flight.region_maps(("forward",), (0.0, 0.0125, 0.1), (0.0, 0.25), n_psi=8, n_sphere_strict=16)


def test_fig8_facts_practical_hover_stable_forward_flight_not_strict_nothing(maps):
    f = maps.facts()
    assert f["ch6_p_hover_stable"] == f["ch6_p_n_hover"] == 8
    assert f["ch6_p_fw_stable"] == 0 and f["ch6_s_stable"] == 0 and f["ch6_s_cells"] == 16
    assert f["ch6_p_mu1"] == 0.0125 and f["ch6_p_mu_mid"] == 0.1
    assert 0 <= f["ch6_p_adv_mid"] <= 1 and f["ch6_root"] == round(cases.case_params("forward").root_r_over_R, 3)
    text = maps.summary()
    assert "practical, W' > 0 on the sphere: the same map for every C.G.: True" in text
    assert text.splitlines()[0] == "practical (indicator, not a certificate)"


def test_fig8_export_has_one_row_per_case_mu_and_azimuth(maps, tmp_path):
    cols = dict(maps.practical.export())
    assert all(len(v) == 3 * 8 for v in cols.values())
    assert list(cols) == ["case", "mu", "psi_deg", "category", "stable", "max_dW"]
    assert figure_csv(maps.practical.export(), tmp_path / "r.csv").read_text().startswith("case,mu,psi_deg")


def test_fig8_figures_have_a_panel_per_reading_and_case_and_the_legend(maps):
    # one column per reading, one row per case (here one), the legend below: 0.75 in
    for fig, size in ((forward_flight.figure_regions_polar(maps.practical, maps.strict), (8.6, 3.75 + 0.75)),
                      (forward_flight.figure_regions_plane(maps.practical, maps.strict), (8.6, 2.75 + 0.75))):
        _closed_figure(fig, size, 2)
        [legend] = fig.legends
        assert len(legend.get_texts()) == len(forward_flight.CATEGORY_NAMES) + 1
        left, right = fig.axes
        assert left.get_position().x0 < right.get_position().x0  # practical left, strict right
        assert maps.practical.label in left.get_title() and maps.strict.label in right.get_title()


def test_fig8_one_reading_puts_its_cases_two_to_a_row_and_the_legend_in_the_spare_cell(regions):
    three = dataclasses.replace(regions, cases=("forward", "neutral", "backward"),
                                **{k: np.repeat(getattr(regions, k), 3, axis=0)
                                   for k in ("stable", "category", "max_dW", "A_used", "lambda0")})
    fig = forward_flight.figure_regions_polar(three)
    _closed_figure(fig, (8.6, 2 * 3.75), 4)  # three discs and the spare cell
    assert not fig.axes[3].axison and len(fig.legends) == 1
    assert check_legible(fig) >= MIN_TEXT_PX


def test_fig8_every_verdict_has_its_hatch_in_the_map_and_the_legend(regions):
    """The second cue: each verdict's cells carry its hatch (none for 'stable'), the legend patch
    the same hatch, and the reverse-flow region a hatch of its own, outlined."""
    from matplotlib.collections import PolyCollection

    from rotorlyap.chapters.style import CATEGORY_HATCHES

    handles = forward_flight.category_legend_handles()
    assert [h.get_hatch() or "" for h in handles[:-1]] == list(CATEGORY_HATCHES)
    assert handles[-1].get_hatch() == forward_flight.REVERSE_FLOW_HATCH not in CATEGORY_HATCHES
    reg = dataclasses.replace(regions, mu_values=np.array([0.0, 0.2]))  # reverse flow reaches the root
    cat = reg.category.copy()
    cat[0, 1, :4] = [0, 1, 2, 3]
    reg = dataclasses.replace(reg, category=cat)
    for projection in ("polar", None):
        fig = plt.figure()
        ax = fig.add_subplot(projection=projection)
        (forward_flight.plot_regions_polar if projection else forward_flight.plot_regions_plane)(reg, ax, 0)
        hatched = {c.get_hatch(): len(c.get_paths()) for c in ax.collections
                   if isinstance(c, PolyCollection) and c.get_hatch()}
        for k, h in enumerate(CATEGORY_HATCHES):
            assert hatched.get(h, 0) == (int((cat[0] == k).sum()) if h else 0), (projection, h)
        assert hatched.get(forward_flight.REVERSE_FLOW_HATCH, 0) >= 1
        plt.close(fig)


def test_practical_reading_calls_a_fluttering_blade_stable_in_hover():
    check = forward_flight.hover_flutter_check(("forward",), "backward", n_psi=4)
    assert check.growth_rate[0] < 0 < check.flutter_growth_rate
    assert check.flutter_stable == 4
    assert check.facts() == {"ch6_flut_re": f"{check.flutter_growth_rate:+.3f}", "ch6_flut_stable": 4}


@pytest.mark.slow
def test_drees_inflow_has_a_practical_threshold_above_glauerts():
    thr = forward_flight.practical_threshold_data("forward", ("glauert", "drees"), ("12 axes",), n_psi=4, n_bisect=2)
    assert thr.threshold_of("glauert", "12 axes") == 1e-7  # any forward speed switches Glauert's gradient on
    assert thr.threshold_of("drees", "12 axes") > 1e-5
    assert set(thr.facts()) == {"ch6_thr_dr_12", "ch6_lam_dr_12", "ch6_v_dr_12"}
    p = cases.case_params("forward")
    assert thr.speed[0] == pytest.approx(thr.threshold_of("drees", "12 axes") * p.rotor_speed * p.radius)
    assert len(thr.summary().splitlines()) == 3


def _synthetic_sensitivity(regions):
    """The default variants of sensitivity_data made from one practical map (hover and mu = 0.1),
    with mu = 0.2 added as a copy of mu = 0.1: 'A = 4' keeps its bound up to mu = 0.1 and is
    stable at psi = 90 and 270 deg there."""
    def grow(a):
        return np.concatenate([a, a[:, -1:]], axis=1)

    base = dataclasses.replace(regions, mu_values=np.append(regions.mu_values, 0.2), stable=grow(regions.stable),
                               category=grow(regions.category), max_dW=grow(regions.max_dW),
                               A_used=grow(regions.A_used), lambda0=grow(regions.lambda0))
    stable = base.stable.copy()
    stable[0, 1, [2, 6]] = True
    a4 = dataclasses.replace(base, stable=stable, A_used=np.array([[4.0, 4.0, 0.0]]))
    names = ("default: 12 axes, A = 1", "A = 0.5", "A = 2", "A = 4", "energy-balanced a_i",
             "axes + diagonals (72)", "flap and lag axes only (8)")
    return forward_flight.SensitivityData(names=names, regions=tuple(a4 if n == "A = 4" else base for n in names),
                                 scales=tuple(np.array(DEFAULT_SCALES) for _ in names), n_tests=(12,) * 7)


def test_sensitivity_facts_find_the_stable_cells_of_the_large_bound(regions):
    sens = _synthetic_sensitivity(regions)
    f = sens.facts()
    assert f["ch6_a4_mu_last"] == 0.1 and f["ch6_a4_mu_fail"] == 0.2
    assert f["ch6_a4_stable"] == 2 and f["ch6_a4_stable_mu"] == 0.1 and f["ch6_a4_stable_psi"] == "90, 270"
    assert f["ch6_sens_fw_stable"] == 2 and f["ch6_diag_A0"] == 1.0
    assert sens.stable_forward_flight("default: 12 axes, A = 1")[0] == 0
    lines = sens.summary().splitlines()
    assert len(lines) == 2 + 7 + 2 and lines[-1].startswith("A = 4: step 3 keeps A up to mu = 0.1 ;")
    assert lines[-2].endswith("cell by cell: True")
    cols = dict(sens.export())
    assert list(cols)[:2] == ["v0_category", "v0_A_used"] and list(cols)[-2:] == ["mu", "psi_deg"]
    _closed_figure(forward_flight.figure_sensitivity(sens), (8.6, 10.4), 8)


def _synthetic_convergence():
    return forward_flight.ConvergenceData(
        n_sphere=np.array([0, 64, 256]), sup_dW_hover=np.array([[90.0, 92.0, 92.001]] * 3),
        n_stations=np.array([6, 12, 24]), collective=np.array([[0.15, 0.1501, 0.15]] * 3),
        sup_dW_stations=np.array([92.5, 92.0, 92.0]), practical_rate_stations=np.array([1125.2, 1125.1, 1125.1]),
        n_psi=np.array([36, 72]), unstable_fraction_psi=np.array([[0.0, 1.0], [0.0, 1.0]]),
        positive_fraction_psi=np.array([[0.0, 0.6], [0.0, 0.64]]), mu_values=np.array([0.0, 0.1]),
        mu_check=0.15, variant="flap and lag axes only (8)")


def test_convergence_facts_state_deviations_as_the_decade_above_them():
    conv = _synthetic_convergence()
    assert conv.default_stations_index == 1
    dev_ns, dev_st, dev_psi = conv.deviations()
    assert dev_ns == pytest.approx(1e-3 / 92.001)
    assert dev_st == pytest.approx(1e-4 / 0.15)
    assert dev_psi == pytest.approx(0.04)
    assert conv.facts() == {"ch6_dev_ns": 0.01, "ch6_dev_st": 0.1, "ch6_dev_psi": 0.04}
    assert conv.summary().splitlines()[-2] == "largest deviation: n_sphere >= 64: < 1e-02 %; 12 stations vs 24: < 1e-01 %"


def test_convergence_figure_is_the_books_three_panels():
    _closed_figure(forward_flight.figure_convergence(_synthetic_convergence()), (9.0, 7.4), 3)


def test_claims_table_has_a_row_per_claim_and_both_readings(wsph, rate7, maps, regions):
    flutter = forward_flight.HoverFlutterCheck(case_names=cases.CASES, growth_rate=np.array([-0.145, -0.097, -0.007]),
                                      flutter_case="backward", flutter_growth_rate=0.116, flutter_stable=72, n_psi=72)
    threshold = forward_flight.ThresholdData(cg="forward", models=("glauert", "drees"), test_sets=("12 axes",),
                                    threshold=np.array([[1e-7], [0.0015]]), speed_model="drees",
                                    hover_lambda0=np.array([0.039]), speed=np.array([0.33]))
    sens = _synthetic_sensitivity(regions)
    table = forward_flight.claims_table(_synthetic_convergence(), wsph, rate7, maps, flutter, threshold, sens)
    assert len(table.rows) == 7 and all(len(r) == len(forward_flight.CLAIMS_HEADER) for r in table.rows)
    assert table.markdown().splitlines()[0].startswith("| claim (the paper's figure numbers) | strict (numerical certificate) |")
    lines = table.summary().splitlines()
    assert len(lines) == 7 and "| strict: not reproduced" in lines[1]
    assert "-0.145 / -0.097 / -0.007" in table.rows[1][3]
    assert "0.0015 (Drees inflow)" in table.rows[5][3]


def test_fig8_reverse_flow_reaches_the_root_only_on_the_retreating_side():
    p = cases.case_params("forward")
    psi = np.radians([90.0, 270.0])
    b = forward_flight.reverse_flow_boundary(p, psi)
    assert np.isinf(b[0])
    assert b[1] == pytest.approx(p.root_r_over_R)


def test_paper_test_disturbances_are_the_twelve_signed_axes():
    assert PAPER_TEST_DISTURBANCES.shape == (12, 6)
    assert forward_flight.AXES_AND_DIAGONALS.shape == (72, 6)
    assert forward_flight.FLAP_LAG_TEST_DISTURBANCES.shape == (8, 6)
    assert np.all(forward_flight.FLAP_LAG_TEST_DISTURBANCES[:, [2, 5]] == 0)
