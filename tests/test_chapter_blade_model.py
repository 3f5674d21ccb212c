"""Data objects, figures and printed numbers of the blade-model chapter (3), rotorlyap.chapters.blade_model.

Each test names the fact it checks. The chapters print ``summary()`` and glue ``facts()``; these
tests check what those say (and that a glued value is a plain Python number, whose text is
the same on every machine), not the committed text itself, which nbval compares.
"""

import math

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from rotorlyap.chapters import blade_model as bm  # noqa: E402
from rotorlyap.chapters.export import figure_csv  # noqa: E402
from rotorlyap.model.airfoil import LinearAirfoil  # noqa: E402
from rotorlyap.model.modes import closed_forms, hover_modes, pitch_mode  # noqa: E402
from rotorlyap.model.parameters import CG_POSITIONS, BladeParameters  # noqa: E402
from rotorlyap.reporting import Rounded  # noqa: E402


def _plain(facts: dict) -> bool:
    """Every value a Python int, float or str, or a :class:`rotorlyap.reporting.Rounded` (a
    float with its decimals): glued, it prints as ``0.25``, never as ``np.float64(0.25)``."""
    return all(type(v) in (int, float, str, Rounded) for v in facts.values())


# --------------------------------------------------------------------------------------
# Chapter 3
# --------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def geo(forward):
    return bm.schematic_data(forward)


@pytest.fixture(scope="module")
def coeff(forward):
    linear = LinearAirfoil(lift_slope=forward.lift_slope, cd0=forward.airfoil.cd_min, name="linear option")
    return bm.coefficient_data([forward.airfoil, linear], n=361)


@pytest.fixture(scope="module")
def aoa(forward):
    return bm.angle_of_attack_data(forward, n_fine=24)


def test_schematic_facts_give_the_hub_elements_in_metres_and_the_chordwise_points(geo):
    facts = geo.facts()
    assert [facts[f"ch3_e{k}"] for k in range(1, 5)] == [0.0677, -0.0339, 0.1354, 0.2032]
    assert facts["ch3_pitch_hinge"] == 0.406 and facts["ch3_cutout"] == 1.078 and facts["ch3_cuff"] == 0.672
    assert facts["ch3_n_stations"] == 12
    assert facts["ch3_xc_pitch_axis"] == 0.25 and facts["ch3_xc_ac"] == 0.235
    assert {k: facts["ch3_xc_cg_" + k] for k in CG_POSITIONS} == CG_POSITIONS
    assert facts["ch3_cg_step"] == 0.02
    assert _plain(facts)


def test_schematic_summary_has_the_hub_cutout_stations_and_chordwise_lines(geo):
    lines = geo.summary().splitlines()
    assert len(lines) == 5
    assert lines[0] == "hub elements e1..e5 (m): [ 0.0677 -0.0339  0.1354  0.2032  0.    ]"
    assert lines[3] == "12 aerodynamic stations from r/R = 0.1453 to 0.9920"
    assert lines[4].endswith("C.G. forward 0.215, neutral 0.235, backward 0.255")


def test_schematic_export_is_every_field_but_the_cg_mapping(geo, tmp_path):
    cols = geo.export()
    assert "cg_positions" not in cols and "stations" in cols and "radius" in cols
    text = figure_csv(cols, tmp_path / "schematic.csv").read_text()
    assert text.startswith("field,") and "stations" in text


def test_figure_functions_return_figures_closed_in_pyplot(geo, coeff, aoa):
    before = plt.get_fignums()
    figs = [(bm.figure_blade_schematic(geo), 4, (9, 10)),
            (bm.figure_airfoil_coefficients(coeff), 6, (8.6, 7.6)),
            (bm.figure_angle_of_attack(aoa), 2, (8.6, 4.0))]
    for fig, n_axes, size in figs:
        assert isinstance(fig, Figure) and len(fig.axes) == n_axes
        assert tuple(fig.get_size_inches()) == pytest.approx(size)  # at most 9.3 in: 8 pt text legible
    assert plt.get_fignums() == before  # nothing for the notebook to close, nothing shown twice


def test_schematic_section_enlarges_the_chord_near_the_pitch_axis(geo):
    section = bm.figure_blade_schematic(geo).axes[3]
    (inset,) = section.child_axes
    labels = " ".join(t.get_text() for t in inset.texts)
    for name, xc in CG_POSITIONS.items():
        assert f"({name}) {xc:.3g}$c$" in labels
    assert "pitch axis" in labels and "aerodynamic centre" in labels


def test_closed_form_facts_are_the_closed_forms_rounded(forward):
    data = bm.closed_form_data(forward)
    cf = closed_forms(forward)
    assert data.facts() == {"ch3_nu_beta": round(cf.flap_frequency, 4), "ch3_nu_zeta": round(cf.lag_frequency, 3),
                            "ch3_nu_theta": round(cf.pitch_frequency, 2)}
    assert data.summary().startswith("closed forms (zero pitch): nu_beta = 1.0064")


def test_moments_about_each_hinge_balance_at_the_hover_equilibrium(forward_hover):
    data = bm.hinge_balance_data(forward_hover)
    total = data.conservative + data.aerodynamic + data.damping
    assert np.all(np.abs(total) < 1e-6 * np.abs(data.conservative).max())
    assert data.case == "forward C.G."
    lines = data.summary().splitlines()
    assert len(lines) == 5 and lines[1].startswith("moments about the hinges (N m)")
    assert all(line.split()[-1] == "0.0" for line in lines[2:])  # the sum, in the header's unit
    assert data.facts() == {"ch3_flap_aero": 98840, "ch3_lag_aero": 6040}


def test_negative_delta3_lowers_the_classical_flap_frequency(forward):
    data = bm.pitch_flap_coupling_data(forward)
    assert data.pitch_flap_coupling == -0.4
    assert data.effective_flap_frequency < data.flap_frequency
    assert data.effective_flap_frequency == pytest.approx(
        math.sqrt(data.flap_frequency ** 2 + data.lock_number / 8 * data.pitch_flap_coupling))
    facts = data.facts()
    assert facts["ch3_kp"] == 0.4 and facts["ch3_delta3_deg"] == -21.8 and _plain(facts)


def test_pitch_damping_estimate_is_negative_and_vanishes_without_the_couple(forward):
    from dataclasses import replace

    assert bm.pitch_damping_estimate(forward) == pytest.approx(-1.16, abs=0.01)
    assert bm.pitch_damping_estimate(replace(forward, cm_pitch_rate=0.0)) == 0.0


@pytest.mark.slow
def test_the_couple_makes_the_backward_pitch_mode_decay():
    data = bm.pitch_damping_data()
    facts = data.facts()
    assert facts["ch3_n_pitch_decay_on"] == "all three" and facts["ch3_n_pitch_decay_off"] == "two"
    assert facts["ch3_pitch_off_backward"] > 0 > facts["ch3_pitch_on_backward"]
    assert data.with_couple[0] == pitch_mode(hover_modes(BladeParameters.table_i("forward")))
    assert len(data.summary().splitlines()) == 4 and _plain(facts)


def test_coefficient_summary_says_the_linear_option_has_the_same_lift_slope(coeff):
    assert coeff.lift_slope[0] == coeff.lift_slope[1]
    lines = coeff.summary().splitlines()
    assert lines[0].startswith("NACA 23012 model: cl(0) = ")
    assert lines[2].endswith("/deg (linear option: the same)")


def test_coefficient_summary_prints_a_different_lift_slope(forward):
    other = LinearAirfoil(lift_slope=2 * math.pi, name="flat plate")
    data = bm.coefficient_data([forward.airfoil, other], n=73)
    assert data.summary().splitlines()[2].endswith("(flat plate: 6.283 /rad)")


def test_angle_of_attack_facts_count_the_reverse_flow_stations(aoa):
    facts = aoa.facts()
    assert facts["ch3_n_reverse"] == int((np.abs(aoa.alpha_stations[-1]) > 90).sum()) > 0
    assert facts["ch3_alpha_root"] < 0 < facts["ch3_alpha_tip"]  # inflow angle exceeds the pitch at the root
    assert len(aoa.summary().splitlines()) >= 1 + len(aoa.cases) and _plain(facts)


def test_number_words_say_all_for_every_case():
    assert [bm._how_many(n, 3) for n in range(4)] == ["none", "one", "two", "all three"]
    assert bm._how_many(2, 2) == "two"


@pytest.mark.slow
def test_generated_code_matches_a_fresh_derivation(forward_hover):
    from rotorlyap.model import derivation

    check = bm.generated_code_check(derivation.derive(), forward_hover)
    assert check.hash_current and check.mass_matrix_agrees
    assert "rhs_terms" in check.functions
    assert check.summary().splitlines()[1] == "cached code matches the current derivation hash: True"


@pytest.mark.slow
def test_energy_function_is_positive_definite_in_all_three_cases():
    data = bm.positivity_data()
    facts = data.facts()
    assert facts["ch3_n_posdef"] == "all three"
    assert all(6000 < facts["ch3_hessU_min_" + cg] < 7000 for cg in CG_POSITIONS)
    assert len(data.summary().splitlines()) == 3 and _plain(facts)
