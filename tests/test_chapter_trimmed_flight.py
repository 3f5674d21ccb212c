"""The trimmed-flight chapter's data: each function checked against an independent fact on a
small grid (the chapter itself runs the full grids under nbval)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rotorlyap.analysis.floquet import blade_floquet
from rotorlyap.chapters import trimmed_flight
from rotorlyap.model.blade import Blade
from rotorlyap.model.mass import mass_properties
from rotorlyap.model.parameters import BladeParameters


def test_trim_data_puts_the_trimmed_rotor_at_the_weight_and_the_paper_above_it():
    """The paper's condition lifts more than the weight at mu > 0 (the review's 1.5-1.6 W), the
    trim's controls are those of forward_flight_trim, hover is the same state for both."""
    td = trimmed_flight.trim_data(cases=("forward",), mu_values=(0.0, 0.15))
    assert td.paper_lift_ratio[0, 0] == pytest.approx(1.0, abs=1e-6)
    assert td.paper_lift_ratio[0, 1] > 1.4
    assert td.shaft_tilt_deg[0, 1] > 0.0
    assert td.retreating_alpha_deg[1, 1] < td.retreating_alpha_deg[0, 1]
    assert set(td.facts()) >= {"ch8_paper_lw_fw_hi", "ch8_bw_stable_from"}


def test_disc_data_marks_reverse_flow_inside_the_reverse_flow_circle():
    """Reverse flow at a station lies where r/R < mu |sin psi| on the retreating side (the blade's
    own flapping and inflow move the boundary only a little), and nowhere on the advancing side."""
    dd = trimmed_flight.disc_data("forward", 0.25, n_azimuth=36, n_stations=12)
    psi, r = dd.psi[:, None], dd.r_over_R[None, :]
    circle = (np.sin(psi) < 0) & (r < 0.25 * np.abs(np.sin(psi)) - 0.02)
    assert np.all(dd.reverse_flow[1][circle])
    assert not np.any(dd.reverse_flow[1][(np.sin(dd.psi) > 0.1)[:, None] & np.ones_like(r, bool)])
    assert dd.mach.max() == pytest.approx(1.25 * BladeParameters().tip_speed / BladeParameters().speed_of_sound, rel=0.02)


def test_delta3_data_reproduces_the_classical_effective_flap_frequency():
    """nu_e^2 = nu_beta^2 + (gamma/8) tan(delta3): the two signs differ by (gamma/8) * 0.8."""
    d3 = trimmed_flight.delta3_data(cases=("forward",))
    gamma = BladeParameters.table_i("forward").lock_number
    assert d3.flap_frequency_sq[1] - d3.flap_frequency_sq[0] == pytest.approx(gamma / 8 * 0.8, rel=1e-12)
    assert d3.growth.shape == (2, 1)


def test_pitch_inertia_data_matches_the_mass_properties_and_the_floquet_analysis():
    """Each point's inertia is the blade's about the pitch axis, its growth rate the hover
    Floquet result, and the Puma reference is the section's sqrt(0.109 / 8.929) / 0.537."""
    pi = trimmed_flight.pitch_inertia_data("backward", radii=(0.2, 0.3))
    p = BladeParameters.table_i("backward", pitch_radius_of_gyration=0.3)
    assert pi.pitch_inertia[1] == pytest.approx(mass_properties(p).inertia[0, 0], rel=1e-12)
    assert pi.growth[1] == pytest.approx(blade_floquet(p, 0.0).exponents.real.max(), abs=1e-12)
    assert pi.reference[0] == pytest.approx(math.sqrt(0.109 / 8.929) / 0.537, rel=1e-12)
    assert pi.pitch_inertia[1] > pi.pitch_inertia[0]


def test_the_verdicts_use_the_trims_own_hover_state():
    """The backward C.G. with compressible sections is unstable in hover at its trimmed state:
    no quadratic function exists there, so nothing may be certified (a continuation to a new
    equilibrium at the trimmed collective would find a stable one and certify it: unsafe)."""
    scan = trimmed_flight.verdict_data(cases=("backward",), mu_values=(0.0,), n_psi=8, workers=1)
    assert blade_floquet(BladeParameters.flight_case("backward"), 0.0).exponents.real.max() > 0
    assert not scan.stable[1:].any()
    assert np.all(scan.category[1:] == 4)  # no quadratic function: marked, not called unstable
    assert "no quadratic function at 1 advance ratio)" in trimmed_flight.verdict_summary(scan)


def test_forensic_sides_and_codes():
    """The side classifier: azimuths between 0 and 180 deg are the advancing side."""
    psi = np.radians([0, 45, 90, 135, 180, 225, 270, 315])
    assert trimmed_flight._side(np.array([0, 0, 0, 0, 0, 1, 1, 0], bool), psi) == "retreating"
    assert trimmed_flight._side(np.array([0, 1, 1, 0, 0, 0, 0, 0], bool), psi) == "advancing"
    assert trimmed_flight._side(np.array([0, 1, 0, 0, 0, 0, 1, 0], bool), psi) == "both"
    assert trimmed_flight._side(np.ones(8, bool), psi) == "whole disc"
    assert trimmed_flight._side(np.zeros(8, bool), psi) == "none"


def test_forensic_data_on_the_papers_own_row():
    """The paper's own reading (hover angles, Glauert, tan delta3 = -0.4, energy, practical):
    hover stable for the forward C.G., a region on both sides from the first advance ratio
    (chapter 6's finding), so not the paper's picture."""
    base = {n: v[0] for n, v in trimmed_flight.FORENSIC_FACTORS.items()}
    fd = trimmed_flight.forensic_data([base], cases=("forward",), mu_values=(0.0, 0.05), n_psi=12)
    assert fd.hover_stable[0, 0]
    assert fd.first_side[0][0] == "both" and fd.first_mu[0, 0] == 0.05
    assert not fd.matches.any()
    assert "0.05B" in fd.pivot_markdown()


def test_printouts_and_tables_use_the_books_words_and_units():
    """No "nan" in a printout (a missing value is "–"), a thrust choice is the weight it carries in
    kN, the pitch-flap coupling is written with its symbol, and the quoted model parameters are
    the package's own (the C81 agreement within the 3.5 % the compressibility tests allow)."""
    assert trimmed_flight._fmt([1.0, float("nan"), 2.666], 2) == "[1.00 – 2.67]"
    assert trimmed_flight._short("4800 kg") == "weight of 4800 kg (47.1 kN)"
    assert trimmed_flight._short(-0.4) == "tan δ₃ = −0.4"
    facts = trimmed_flight.model_facts()
    p = BladeParameters.table_i("forward")
    assert facts["ch8_flat_plate_area"] == f"{p.flat_plate_area:.1f}" and facts["ch8_mass_t"] == "6.4"
    assert facts["ch8_mach_cap"] == "0.8" and facts["ch8_c81_mach"] == "0.6"
    assert 0.0 < float(facts["ch8_c81_dev"].split()[0]) <= 3.5


def test_the_disc_figure_is_round_and_fits_the_column():
    """Fig. 8.2's discs have equal aspect and the figure is not wider than the book's column,
    so the page shows it at its own size (a rescaled figure drew them as ellipses)."""
    import matplotlib.pyplot as plt

    from rotorlyap.chapters.style import BOOK_DPI, PAGE_WIDTH_PX

    dd = trimmed_flight.disc_data("forward", 0.25, n_azimuth=12, n_stations=6)
    fig = trimmed_flight.figure_disc(dd)
    fig.draw_without_rendering()
    assert all(ax.get_aspect() == 1.0 for ax in fig.axes[:2])
    width_px = (fig.get_tightbbox(fig._get_renderer()).width + 0.2) * BOOK_DPI
    assert width_px <= PAGE_WIDTH_PX
    plt.close(fig)
