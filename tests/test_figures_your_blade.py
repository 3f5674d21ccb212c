"""What the chapter "Your own blade" prints and glues (rotorlyap.chapters.your_blade).

Each test names the fact it checks. The chapter's own numbers are compared by nbval; here the
data objects are checked against the package functions they gather, and their text against
the layout the chapter prints, on the chapter's blades with coarse grids.
"""

import dataclasses
from types import SimpleNamespace

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import rotorlyap  # noqa: E402
from rotorlyap.chapters import your_blade  # noqa: E402
from rotorlyap.chapters.export import figure_csv  # noqa: E402
from rotorlyap.model.modes import least_damped  # noqa: E402


@pytest.fixture(scope="module")
def base():
    return rotorlyap.BladeParameters.table_i(cg="neutral")


@pytest.fixture(scope="module")
def mine(base):
    """The chapter's variant."""
    return dataclasses.replace(
        base, mass_per_length=11.0, hub_elements=(0.01, -0.005, 0.04, 0.03, 0.0),
        pitch_stiffness=12_000.0, cg_position=0.22,
        airfoil=dataclasses.replace(base.airfoil, alpha_zero_lift=0.0, cm_ac=0.0),
    )


@pytest.fixture(scope="module")
def hover(base, mine):
    return your_blade.hover_comparison(rotorlyap.derived_quantities(base), rotorlyap.derived_quantities(mine))


@pytest.fixture(scope="module")
def readings(base, mine):
    return your_blade.both_readings(base, mine, 0.0, A=1.0, n_psi=4, n_sphere=32)


def _fake_motion(mu, offset):
    """A stand-in for a PeriodicMotion: only ``mu`` and ``harmonics_deg`` are read."""
    return SimpleNamespace(mu=mu, harmonics_deg=offset + np.arange(9.0).reshape(3, 3) / 100)


# --- step 1 ------------------------------------------------------------------------------


def test_parameter_changes_lists_changed_fields_in_table_order_with_units_then_airfoil_coefficients(base, mine):
    changes = your_blade.parameter_changes(base, mine)
    assert [r[0] for r in changes.rows] == ["hub_elements", "pitch_stiffness", "cg_position", "mass_per_length",
                                            "airfoil.alpha_zero_lift", "airfoil.cm_ac"]
    assert changes.rows[1] == ("pitch_stiffness", "6304.0", "12000.0", "N m/rad")
    assert changes.summary().splitlines() == [
        "changed fields:",
        "  hub_elements: (0.01, -0.005, 0.02, 0.03, 0.0) -> (0.01, -0.005, 0.04, 0.03, 0.0) R1",
        "  pitch_stiffness: 6304.0 -> 12000.0 N m/rad",
        "  cg_position: 0.235 -> 0.22 c",
        "  mass_per_length: 9.0 -> 11.0 kg/m",
        "  airfoil.alpha_zero_lift: -0.02094 -> 0",
        "  airfoil.cm_ac: -0.014 -> 0",
    ]


def test_parameter_changes_of_a_blade_against_itself_are_none(base):
    changes = your_blade.parameter_changes(base, base)
    assert changes.rows == ()
    assert changes.summary() == "changed fields:"


def test_refusals_give_the_error_type_and_the_constructors_message_and_mark_accepted_changes(mine):
    r = your_blade.refusals(mine, [dict(chord=-0.4), dict(inflow_model="vortex"), dict(pitch_stiffness=1.0)])
    assert r.errors[0][0] == "ValueError" and "chord must be > 0" in r.errors[0][1]
    assert r.errors[2] == (None, None)
    lines = r.summary().splitlines()
    assert lines[0].startswith("{'chord': -0.4}: ValueError: chord must be > 0 on the span")
    assert lines[1].startswith("{'inflow_model': 'vortex'}: ValueError: inflow_model must be one of")
    assert lines[2] == "{'pitch_stiffness': 1.0}: accepted"


# --- step 2 ------------------------------------------------------------------------------


def test_hover_summary_holds_the_derived_quantities_in_degrees_and_the_least_damped_air_mode(mine):
    d = rotorlyap.derived_quantities(mine)
    s = your_blade.hover_summary(d)
    worst = least_damped(d.air_modes)
    assert s.lock_number == pytest.approx(d.lock_number)
    assert s.collective_deg == pytest.approx(np.degrees(d.collective))
    assert (s.coning_deg, s.lag_angle_deg, s.pitch_angle_deg) == pytest.approx(np.degrees(d.equilibrium))
    assert s.largest_growth_rate == pytest.approx(worst.growth_rate)
    assert s.least_damped_hinge == worst.dominant_hinge
    assert all(m.growth_rate <= s.largest_growth_rate for m in d.air_modes)
    # the lag mode is the slow one, the pitch mode the fast one
    assert 0.0 < s.lag_frequency_vacuum < 1.0 < s.pitch_frequency_vacuum


def test_hover_facts_are_the_four_glued_names_with_growth_rates_rounded_to_three_decimals(hover):
    facts = hover.facts()
    assert list(facts) == ["own_growth_base", "own_growth_mine", "own_hinge_base", "own_hinge_mine"]
    assert facts["own_growth_base"] == round(hover.base.largest_growth_rate, 3)
    assert facts["own_growth_mine"] == round(hover.variant.largest_growth_rate, 3)
    assert facts["own_hinge_mine"] == hover.variant.least_damped_hinge
    # every linear hover mode of both blades decays (the chapter's statement)
    assert facts["own_growth_base"] < 0 and facts["own_growth_mine"] < 0


def test_hover_summary_table_has_a_header_and_one_row_per_quantity_with_label_wide_columns(hover):
    lines = hover.summary().splitlines()
    assert lines[0] == f"{'quantity':38s} {'Table I neutral':>16s} {'variant':>10s}"
    assert len(lines) == 1 + len(your_blade.HoverSummary.ROWS)
    assert lines[1] == f"{'Lock number':38s} {hover.base.lock_number:16.3f} {hover.variant.lock_number:10.3f}"
    assert lines[-1] == f"{'its hinge':38s} {hover.base.least_damped_hinge:>16s} {hover.variant.least_damped_hinge:>10s}"
    assert len({len(line) for line in lines}) == 1


def test_hover_comparison_needs_two_labels(base):
    d = rotorlyap.derived_quantities(base)
    with pytest.raises(ValueError, match="two blades"):
        your_blade.hover_comparison(d, d, labels=("only one",))


# --- step 3 ------------------------------------------------------------------------------


def test_both_readings_is_blade_stability_with_the_paper_directions_and_with_whole_spheres(base, mine, readings):
    assert readings.labels == your_blade.LABELS and readings.readings == ("practical", "strict")
    for label in readings.labels:
        assert readings[label, "practical"].reading == "practical"
        assert readings[label, "strict"].reading == "strict"
    direct = rotorlyap.blade_stability(mine, 0.0, A=1.0, n_psi=4, n_sphere=32)
    got = readings["variant", "strict"]
    assert got.A == direct.A and np.array_equal(got.stable, direct.stable)
    assert got.message == direct.message


def test_readings_summary_has_one_aligned_line_per_blade_and_reading_with_the_engine_message(readings):
    lines = readings.summary().splitlines()
    assert [line[:27] for line in lines] == ["Table I neutral  practical:", "Table I neutral  strict   :",
                                             "variant          practical:", "variant          strict   :"]
    res = readings["variant", "strict"]
    assert lines[3] == (f"variant          strict   : A = {res.A:.3f}, stable at {int(res.stable.sum()):2d}/4 "
                        f"azimuths; {res.message}")


def test_both_readings_needs_two_labels(base, mine):
    with pytest.raises(ValueError, match="two blades"):
        your_blade.both_readings(base, mine, labels=("a", "b", "c"))


def test_worst_state_is_the_argmax_of_w_dot_in_units_of_the_scales(readings):
    res = readings["variant", "strict"]
    w = your_blade.worst_state(res)
    assert w.psi == 0.0 and w.dW == res.max_dW[0]
    assert np.allclose(w.state * res.scales, res.argmax_dW[0])
    lines = w.summary().splitlines()
    assert lines[0] == "worst state at psi = 0, in units of the scales a_i:"
    assert lines[1].startswith("  beta ") and ", theta' " in lines[1]
    assert lines[2] == f"  W' there = {res.max_dW[0]:.3g} J/rad"


def test_worst_state_at_another_azimuth_states_it_in_degrees_and_refuses_a_missing_one(readings):
    res = readings["variant", "strict"]
    assert your_blade.worst_state(res, 1).summary().startswith("worst state at psi = 90 deg,")
    with pytest.raises(IndexError):
        your_blade.worst_state(res, 4)


# --- step 4 ------------------------------------------------------------------------------


def test_harmonic_data_stacks_the_harmonics_of_each_motion_in_order():
    data = your_blade.harmonic_data([_fake_motion(0.05, 1.0), _fake_motion(0.1, 2.0)])
    assert data.mu.tolist() == [0.05, 0.1]
    assert data.harmonics_deg.shape == (2, 3, 3)
    assert data.harmonics_deg[1, 2, 0] == pytest.approx(2.06)


def test_harmonic_data_of_a_real_motion_is_its_harmonics_deg(mine):
    pm = rotorlyap.periodic_motion(mine, 0.1)
    data = your_blade.harmonic_data([pm])
    assert np.array_equal(data.harmonics_deg[0], pm.harmonics_deg)
    # forward flight tilts the disc: a first harmonic of flapping of at least a few tenths of a degree
    assert np.hypot(*data.harmonics_deg[0, 0, 1:]) > 0.3


def test_harmonic_data_needs_a_motion():
    with pytest.raises(ValueError, match="at least one"):
        your_blade.harmonic_data([])


def test_harmonic_summary_prints_the_advance_ratios_and_per_hinge_triples_to_two_decimals():
    data = your_blade.harmonic_data([_fake_motion(0.05, 1.0), _fake_motion(0.2, -3.004)])
    assert data.summary().splitlines() == [
        "mu: (0.05, 0.2)",
        "flap  mean / cos / sin (deg): [[1.0, 1.01, 1.02], [-3.0, -2.99, -2.98]]",
        "lag   mean / cos / sin (deg): [[1.03, 1.04, 1.05], [-2.97, -2.96, -2.95]]",
        "pitch mean / cos / sin (deg): [[1.06, 1.07, 1.08], [-2.94, -2.93, -2.92]]",
    ]


def test_harmonic_csv_has_mu_then_mean_cos_sin_of_each_hinge_one_row_per_advance_ratio(tmp_path):
    data = your_blade.harmonic_data([_fake_motion(0.05, 1.0), _fake_motion(0.1, 2.0)])
    lines = figure_csv(data.export(), tmp_path / "h.csv").read_text().splitlines()
    assert lines[0] == ("mu,flap_mean_deg,flap_cos_deg,flap_sin_deg,lag_mean_deg,lag_cos_deg,lag_sin_deg,"
                        "pitch_mean_deg,pitch_cos_deg,pitch_sin_deg")
    assert lines[1].split(",")[:3] == ["0.05", "1", "1.01"]
    assert len(lines) == 3


def test_plot_harmonics_returns_a_closed_figure_of_three_panels_with_three_lines_each():
    data = your_blade.harmonic_data([_fake_motion(0.05, 1.0), _fake_motion(0.1, 2.0)])
    before = plt.get_fignums()
    fig = your_blade.plot_harmonics(data)
    assert plt.get_fignums() == before  # closed: shown only where glued or saved
    assert [ax.get_title() for ax in fig.axes] == ["flap angle", "lag angle", "pitch angle"]
    assert all(len(ax.get_lines()) == 3 for ax in fig.axes)
    assert np.allclose(fig.axes[1].get_lines()[0].get_ydata(), data.harmonics_deg[:, 1, 0])
    assert [t.get_text() for t in fig.axes[0].get_legend().get_texts()] == ["mean", "1st cosine", "1st sine"]


# --- a real blade: its file, its certificates, a sweep -------------------------------------

from rotorlyap.analysis.sweep import RESULT_COLUMNS, SweepResult  # noqa: E402
from rotorlyap.model.parameters import EXAMPLE_FILES  # noqa: E402


def test_read_blade_names_the_file_not_its_folder_and_lists_what_it_left_to_the_template():
    """The chapter prints the same on any machine: the warning carries the file's name only; the
    fields left out are exactly the blade fields the file has no key for."""
    b = your_blade.read_blade(EXAMPLE_FILES["sa330-puma"])
    assert b.name == "sa330_puma.toml"
    assert b.left_out == ("pitch_flap_coupling", "pitch_stiffness", "lag_damping")
    assert str(EXAMPLE_FILES["sa330-puma"].parent) not in b.warning
    assert b.warning.startswith("sa330_puma.toml leaves out 3 of the 22 blade fields")
    table = b.markdown()
    assert "| `pitch_flap_coupling` | -0.4 | - | template: Table I (tan delta3) |" in table
    assert "| `radius` | 7.49 | m | the file: {cite:p}`PumaBladeData` |" in table
    assert "| `hub_elements` | (0.05342, 0, 0, 0.02643, 0) | × R1 (blade length) |" in table
    assert "left to the template: pitch_flap_coupling, pitch_stiffness, lag_damping" in b.summary()


def _certificate(mu, certified):
    """A stand-in for a Certificate: the fields the table reads."""
    per = {"flap": (0.234, 6.44), "lag": (0.2, 1.6), "pitch": (0.11, 16.0)}
    reach = {"flap": (0.324, 19.84), "lag": (0.29, 2.8), "pitch": (0.57, 75.3)} if certified else {}
    return SimpleNamespace(mu=mu, certified=certified, growth_rate=-0.1234, start_region_per_hinge=per,
                           start_set_per_hinge=reach,
                           bound_per_hinge={h: (10 * a, 10 * b) for h, (a, b) in per.items()},
                           summary=lambda: f"mu = {mu:g}")


def test_certificate_table_reads_each_hinge_and_shows_no_region_where_nothing_is_certified():
    t = your_blade.certificate_table([_certificate(0.0, True), _certificate(0.3, False)])
    rows = t.markdown().splitlines()
    assert rows[2] == "| 0 | certified | 0.23 | 0.20 | 0.11 | 2.34 | 2.00 | 1.10 | -0.123 |"
    assert rows[3] == "| 0.3 | not certified | - | - | - | - | - | - | -0.123 |"
    facts = t.facts("x")
    assert facts["x_mu00_flap_start"] == "0.23" and facts["x_mu00_flap_rate_start"] == "6.4"
    assert facts["x_mu30_verdict"] == "not certified" and facts["x_mu00_flap_bound"] == "2.34"
    # the start set along one hinge alone, beside the ball (which holds for any mix of hinges)
    assert (facts["x_mu00_flap_set"], facts["x_mu00_flap_rate_set"], facts["x_mu30_flap_set"]) == ("0.32", "19.8", "–")
    with pytest.raises(ValueError, match="at least one certificate"):
        your_blade.certificate_table([])


def _sweep_result(missing=False):
    columns = ("k", "d") + RESULT_COLUMNS
    rows = []
    for k in (1.0, 2.0):
        for d in (-0.1, 0.0, 0.1):
            if missing and (k, d) == (2.0, 0.1):
                continue
            ok = d > -0.1
            numbers = {c: None for c in RESULT_COLUMNS}
            numbers.update(certified=ok, growth_rate_per_rev=d - 0.2 * k, start_flap_deg=(1 + d) if ok else 0.0,
                           error="")
            rows.append((k, d) + tuple(numbers[c] for c in RESULT_COLUMNS))
    return SweepResult(columns, tuple(rows))


def test_sweep_figure_data_arranges_a_full_grid_by_line_and_refuses_a_partial_one():
    """Each line is one value of the series column, x sorted, the growth and the start region
    taken from their columns; nothing certified has no start region (NaN, printed "–"), not 0."""
    data = your_blade.sweep_figure_data(_sweep_result(), "d", "k")
    assert data.series == (1.0, 2.0) and data.x.tolist() == [-0.1, 0.0, 0.1]
    np.testing.assert_allclose(data.growth[1], [-0.5, -0.4, -0.3])
    np.testing.assert_allclose(data.start_flap_deg[0], [np.nan, 1.0, 1.1])
    assert "  flap start (deg): [–, 1.00, 1.10]" in data.summary().splitlines()
    assert data.certified.tolist() == [[False, True, True], [False, True, True]]
    assert "k = 1: certified at [0.0, 0.1]" in data.summary()
    with pytest.raises(ValueError, match="not a full grid"):
        your_blade.sweep_figure_data(_sweep_result(missing=True), "d", "k")
    with pytest.raises(ValueError, match="no column 'q'"):
        your_blade.sweep_figure_data(_sweep_result(), "q", "k")


def test_plot_sweep_draws_two_panels_with_a_line_and_markers_per_series():
    fig = your_blade.plot_sweep(your_blade.sweep_figure_data(_sweep_result(), "d", "k"), x_label="d", series_label="k")
    a, b = fig.axes
    assert len(a.get_legend().get_texts()) == 2
    assert a.get_ylabel() == "largest Floquet real part (per rev)"
    assert b.get_ylabel() == "certified flap start region (deg)"
    # the not-certified points are crosses on the axis, not circles at a start region of 0
    crosses = [ln for ln in b.get_lines() if ln.get_marker() == "x"]
    assert crosses and all(np.all(ln.get_ydata() == 0.0) for ln in crosses)
    assert not any(ln.get_marker() in ("o", "s") and np.any(np.asarray(ln.get_ydata()) == 0.0) for ln in b.get_lines())
    assert not plt.fignum_exists(fig.number)
