"""Data objects, figures and printed numbers of the Table I chapter (4), rotorlyap.chapters.table_i.

Each test names the fact it checks. The chapters print ``summary()`` and glue ``facts()``; these
tests check what those say (and that a glued value is a plain Python number, whose text is
the same on every machine), not the committed text itself, which nbval compares.
"""

import math

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from rotorlyap.chapters import table_i  # noqa: E402
from rotorlyap.chapters.export import figure_csv  # noqa: E402
from rotorlyap.reporting import Rounded  # noqa: E402


def _plain(facts: dict) -> bool:
    """Every value a Python int, float or str, or a :class:`rotorlyap.reporting.Rounded` (a
    float with its decimals): glued, it prints as ``0.25``, never as ``np.float64(0.25)``."""
    return all(type(v) in (int, float, str, Rounded) for v in facts.values())


# --------------------------------------------------------------------------------------
# Chapter 4
# --------------------------------------------------------------------------------------


def test_table_i_markdown_has_one_row_per_table_i_field(forward):
    lines = table_i.table_i_markdown(forward).splitlines()
    assert lines[0] == "| quantity | field | value | unit |"
    assert len(lines) == 2 + len(table_i.table_i_rows(forward))


def test_most_fields_rest_on_an_assumption(forward):
    data = table_i.assumption_data(forward)
    assert 0 < len(data.rows) < data.n_fields
    assert data.summary() == f"{len(data.rows)} of {data.n_fields} fields rest wholly or partly on an assumption"
    assert data.markdown().splitlines()[0] == "| field | value | unit | source or reason |"


def test_the_assumptions_table_says_what_a_field_left_unset_means_not_none(forward):
    """Chapter 4 printed "`inflow_ratio` | None | - | assumed: None = ..." (issue 42): a field
    left at None is printed as what it means, and no source keeps the word None."""
    data = table_i.assumption_data(forward)
    text = data.markdown()
    assert "None" not in text
    rows = {r[0]: r for r in data.rows}
    assert rows["`inflow_ratio`"][1] == "not given: computed (momentum theory)"
    assert rows["`inflow_ratio`"][3] == "assumed: momentum theory with thrust = weight"
    assert rows["`collective`"][1] == "not given: computed (hover trim)"


def test_printed_sources_name_authors_and_year_not_bibliography_keys(forward):
    """Chapter 4's tables printed raw bib keys ("Abbott1959: ...") (issue 42); every key the
    recorded sources use is translated, and every translated key exists in references.bib."""
    import pathlib
    import re

    text = table_i.airfoil_table_data(forward).markdown() + table_i.assumption_data(forward).markdown()
    assert "Abbott and von Doenhoff (1959): cm_ac = -0.014" in text
    assert not re.search(r"\b[A-Z][A-Za-z]+[0-9]{4}\b", text), re.findall(r"\b[A-Z][A-Za-z]+[0-9]{4}\b", text)
    bib = (pathlib.Path(__file__).resolve().parents[1] / "references.bib").read_text()
    for key in table_i.REFERENCE_NAMES:
        assert "{" + key + "," in bib, key


def test_airfoil_table_gives_angles_in_degrees_and_slopes_per_degree(forward):
    data = table_i.airfoil_table_data(forward)
    rows = {r[0]: r for r in data.rows}
    assert rows["`lift_slope`"][1:3] == (0.107, "1/deg")
    assert rows["`alpha_stall`"][2] == "deg" and 10 < rows["`alpha_stall`"][1] < 25
    assert rows["`cl_max`"][2] == ""
    assert data.summary() == ("model used by the blade: NACA 23012 with its moment reference moved to "
                              "0.235 c (Table I), cm_ac = -0.014")


def test_pitch_axis_reading_moves_every_cg_by_the_axis_to_centre_distance(forward):
    old = table_i.pitch_axis_reading(forward)
    assert old == {"forward": 0.23, "neutral": 0.25, "backward": 0.27}


def test_choices_facts_state_both_readings_of_e2_and_of_the_cg(forward):
    data = table_i.choices_data(forward)
    facts = data.facts()
    assert facts["ch4_chordwise_deg"] == 9.5
    assert 0 < facts["ch4_e2_precone"] < 1  # the vertical reading acts like a small precone
    assert facts["ch4_cg_bwd"] == 0.255 and facts["ch4_oldcg_bwd"] == 0.27
    assert facts["ch4_ac_ahead"] == 0.015 and facts["ch4_bwd_behind_pa"] == 0.005
    assert facts["ch4_cmq"] == -1.5708 and facts["ch4_tip_speed"] == 222.5
    assert _plain(facts) and len(data.summary().splitlines()) == 4


@pytest.fixture(scope="module")
def cases():
    """The derived quantities of the three Table I cases (trims cached per parameter set)."""
    return table_i.derived_table_data()


def test_derived_table_has_a_column_per_case_and_facts_of_the_forward_case(cases):
    header = cases.markdown().splitlines()[0]
    assert header == "| quantity | unit | I forward | II neutral | III backward |"
    facts = cases.facts()
    assert facts["ch4_coll_fwd"] > facts["ch4_coll_neu"] > facts["ch4_coll_bwd"]
    assert 0 < facts["ch4_g_droop"] < 0.5 and _plain(facts)
    assert cases["forward"] is cases.quantities[0]


def test_vacuum_pitch_frequency_lies_above_its_closed_form_in_every_case():
    data = table_i.vacuum_modes_data()
    facts = data.facts()
    assert all(facts["ch4_pitch_shift_" + s] >= 0 for s in ("fwd", "neu", "bwd"))
    assert facts["ch4_flap_pitch_shape"] == 0.4  # the pitch follows the flap at -tan(delta3)
    assert data.summary().splitlines()[0].startswith("forward C.G., vacuum (closed forms: flap 1.0064")


def test_air_modes_facts_give_the_forward_flap_mode_and_nu_e():
    data = table_i.air_modes_data()
    facts = data.facts()
    assert facts["ch4_nu_e"] == 0.78 and facts["ch4_flap_air_shape"].startswith("(1.00, ")
    assert sum(line.endswith("hover with air") for line in data.summary().splitlines()) == 3


def test_all_three_hover_equilibria_are_linearly_stable_with_shrinking_margins():
    data = table_i.hover_stability_data()
    facts = data.facts()
    assert all("linearly stable" in line for line in data.summary().splitlines())
    assert facts["ch4_slow_fwd"] < facts["ch4_slow_neu"] < facts["ch4_slow_bwd"] < 0
    # the backward case's slowest mode takes about a hundred revolutions to halve
    # halving time in revolutions: the growth rate is per rad of azimuth, a revolution is 2 pi rad
    assert facts["ch4_slow_bwd_halving"] == pytest.approx(math.log(2) / (2 * math.pi * -facts["ch4_slow_bwd"]),
                                                          rel=0.1)
    assert _plain(facts)


@pytest.mark.slow
def test_only_the_forward_case_is_stable_under_all_four_combinations():
    data = table_i.sensitivity_data()
    assert len(data.rows) == 12
    unstable = {(r.reading, r.damping, r.case) for r in data.rows if r.least_damped.unstable}
    assert {case for _, _, case in unstable} == {"neutral", "backward"}
    assert not any(reading == "a.c." and damping == "thin airfoil" for reading, damping, _ in unstable)
    facts = data.facts()
    assert facts["ch4_s_ac_0_bwd_pitch"] > 0 and facts["ch4_s_pa_q_bwd_max"] > 0
    assert len(data.summary().splitlines()) == 13 and _plain(facts)


@pytest.mark.slow
def test_the_pitch_damping_leaves_the_slow_real_lag_mode_where_it_is():
    data = table_i.variants_data()
    assert data.labels[0] == "Table I" and data.pitch_growth.shape == data.largest_real.shape == (4, 2)
    assert data.largest_real[0, 0] == pytest.approx(data.largest_real[0, 1], abs=1e-3)
    assert np.isnan(data.largest_real[1]).all()  # no pitch-flap coupling: no real mode
    assert data.facts() == {"ch4_bwd_real_q": -0.007, "ch4_bwd_real_0": -0.007}
    assert "without: pitch mode" in data.summary() and "no real root" in data.summary()
    table = data.markdown().splitlines()
    assert table[0].count("|") == 6 and len(table) == 2 + len(data.labels)
    assert "no real root" in table[3] and "nan" not in data.markdown()
    assert "nan" not in data.summary()


def test_cg_sweep_pair_exports_both_sweeps_with_complex_parts_split(tmp_path):
    data = table_i.cg_sweep_pair_data((0.22, 0.255, 0.27))
    cols = data.export()
    assert {"eigenvalues_real", "eigenvalues_imag", "no_pitch_damping_eigenvalues_real", "cg",
            "no_pitch_damping_flutter_cg"} <= set(cols)
    assert not any(np.iscomplexobj(v) for v in cols.values())
    assert figure_csv(cols, tmp_path / "sweep.csv").read_text().startswith("field,")
    facts = data.facts()
    assert facts["ch4_grid_lo"] == 0.22 and facts["ch4_grid_hi"] == 0.27
    assert 0.235 < facts["ch4_flutter_cg0"] < 0.255  # without pitch damping, just behind the a.c.
    assert np.isnan(data.with_damping.flutter_cg)
    assert data.summary().splitlines()[1] == "with pitch damping"
    fig = table_i.figure_cg_sweep(data)
    assert isinstance(fig, Figure) and len(fig.axes) == 2
    assert [ax.get_ylabel() for ax in fig.axes] == [r"growth rate Re $s$ (per rev)",
                                                    r"frequency Im $s$ (per rev)"]
