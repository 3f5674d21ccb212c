"""Frequencies and motions of a blade: the fan diagram, the Floquet modes of the trimmed periodic
motion, the disturbed nonlinear motion, and the tables and figures drawn from them."""

import csv
import json
from dataclasses import replace

import numpy as np
import pytest

from rotorlyap.analysis.certify import certify
from rotorlyap.analysis.disturbance import simulate_disturbance
from rotorlyap.analysis.modes import MODE_COLUMNS, fan_plot, floquet_modes
from rotorlyap.model.modes import closed_forms, hover_modes
from rotorlyap.model.parameters import BladeParameters

PNG = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def table_i():
    return BladeParameters.table_i("forward")


@pytest.fixture(scope="module")
def hover_certificate(table_i):
    return certify(table_i, 0.0, function="quadratic", n_psi=4, n_sphere=16)


def test_the_fan_plot_at_the_nominal_rotor_speed_equals_hover_modes(table_i):
    """At the blade's own rotor speed the fan diagram's modes are hover_modes' (same trim, same
    equilibrium); at another speed they differ."""
    omega = table_i.rotor_speed
    fan = fan_plot(table_i, [0.9 * omega, omega])
    expected = [m.eigenvalue for m in hover_modes(table_i)]
    assert fan.found.all()
    assert [m.eigenvalue for m in fan.modes[1]] == pytest.approx(expected, rel=1e-9, abs=1e-12)
    assert [m.eigenvalue for m in fan.modes[0]] != pytest.approx(expected, rel=1e-3)
    assert fan.frequency_hz(1) == pytest.approx([m.frequency * omega / (2 * np.pi) for m in fan.modes[1]])


def test_the_vacuum_fan_plot_follows_the_closed_forms(table_i):
    """In vacuum, with no flap spring, the flap frequency is sqrt(1 + e S/I) per rev at every rotor
    speed (closed_forms); the pitch frequency obeys nu^2 Omega^2 = K/I_theta + c Omega^2 with the
    propeller term c close to 1 (thin section, cos 2 theta): the control spring's share falls as
    1/Omega^2."""
    assert table_i.flap_stiffness == 0.0
    speeds = table_i.rotor_speed * np.array([0.5, 0.75, 1.0, 1.2])
    fan = fan_plot(table_i, speeds, air=False)
    nu_beta = closed_forms(table_i).flap_frequency
    pitch = []
    for i in range(speeds.size):
        flap = [m for m in fan.modes[i] if m.dominant_hinge == "flap"]
        assert len(flap) == 1 and flap[0].frequency == pytest.approx(nu_beta, rel=1e-3)
        assert abs(flap[0].growth_rate) < 1e-3  # no air, no flap damper (the lag damper's share is tiny)
        pitch.append(max(m.natural_frequency for m in fan.modes[i] if m.dominant_hinge == "pitch"))
    slope, intercept = np.polyfit(speeds ** 2, (np.array(pitch) * speeds) ** 2, 1)
    cf = closed_forms(table_i)
    assert 0.85 < slope <= 1.0
    # 3 % apart: the C.G. 0.035 c ahead of the pitch axis couples pitch to flap inertially
    assert intercept == pytest.approx(table_i.pitch_stiffness / cf.pitch_inertia, rel=0.05)


def test_rotor_speeds_must_be_positive_and_increasing(table_i):
    with pytest.raises(ValueError, match="must increase"):
        fan_plot(table_i, [30.0, 20.0])
    with pytest.raises(ValueError, match="positive and finite"):
        fan_plot(table_i, [0.0, 20.0])


def test_floquet_modes_in_hover_are_the_hover_eigenvalues(table_i):
    """At mu = 0 the Floquet exponents of the trimmed helicopter are the eigenvalues of the hover
    Jacobian: frequencies and growth rates of hover_modes, one per complex pair or real exponent."""
    fl = floquet_modes(table_i, [0.0])
    modes = hover_modes(table_i)
    assert fl.found.all() and len(fl.names) == len(modes)
    got = sorted(zip(fl.frequency[0], fl.growth_rate[0]))
    want = sorted((m.frequency, m.growth_rate) for m in modes)
    assert np.allclose(got, want, atol=1e-8)


def test_floquet_modes_are_followed_from_hover_and_reported_where_asked(table_i):
    """Asked at mu = 0.05 only, the modes are followed from hover (on 0.025 steps) and reported at 0.05:
    each frequency stays near its hover value (continuity picks the branch, not the principal value
    only), the stable Table I blade stays stable, and the table has a row per mode."""
    hover = floquet_modes(table_i, [0.0])
    fl = floquet_modes(table_i, [0.05])
    assert fl.mu.tolist() == [0.05] and fl.names == hover.names
    assert np.abs(fl.frequency[0] - hover.frequency[0]).max() < 0.05
    assert fl.stable.tolist() == [True]
    rows = fl.export()
    assert len(rows) == len(fl.names) and list(rows[0]) == list(MODE_COLUMNS)
    assert {r["kind"] for r in rows} == {"floquet"}
    assert rows[0]["frequency_hz"] == pytest.approx(rows[0]["frequency_per_rev"] * table_i.rotor_speed / (2 * np.pi))


def test_a_disturbed_stable_blade_returns_to_its_steady_motion(table_i):
    """Table I in hover is asymptotically stable (largest growth rate about -0.14 per rev): a 1 deg flap
    disturbance starts at the steady state plus 1 deg and has decayed below 5 % after 5 revolutions."""
    motion = simulate_disturbance(table_i, 0.0, {"flap": np.radians(1.0)}, 5.0)
    dev = motion.deviation_deg
    assert dev[0] == pytest.approx([1.0, 0.0, 0.0], abs=1e-9)
    assert motion.revolutions[-1] == pytest.approx(5.0) and not motion.escaped
    assert np.abs(dev[-1]).max() < 0.05
    assert motion.certified is None and motion.bound_deg is None


def test_a_disturbance_inside_the_start_region_stays_within_the_certified_bound(table_i, hover_certificate):
    """A flap disturbance of 90 % of the certified start region along the flap angle: inside the start
    region, and every hinge angle stays within the bound a_i A about the steady motion."""
    cert = hover_certificate
    assert cert.certified
    flap_deg = 0.9 * cert.start_region_per_hinge["flap"][0]
    motion = simulate_disturbance(table_i, 0.0, {"flap": np.radians(flap_deg)}, 3.0, certificate=cert)
    assert motion.inside_start_region is True
    assert motion.bound_deg == pytest.approx([cert.bound_per_hinge[h][0] for h in ("flap", "lag", "pitch")])
    assert np.all(np.abs(motion.deviation_deg) <= motion.bound_deg)
    assert motion.norm.max() <= cert.bound


def test_a_rate_disturbance_is_given_in_rad_per_s(table_i):
    """flap_rate in rad/s is the state's d(beta)/d(psi) times Omega: the recorded disturbance is in
    deg/s, and its scaled norm is (rate / Omega) / a_4."""
    motion = simulate_disturbance(table_i, 0.0, {"flap_rate": np.radians(10.0)}, 0.5)
    assert motion.disturbance[3] == pytest.approx(10.0)
    a4 = motion.scales[3]
    assert motion.start_norm == pytest.approx(np.radians(10.0) / table_i.rotor_speed / a4)


def test_bad_disturbances_and_certificates_are_refused(table_i, hover_certificate):
    with pytest.raises(ValueError, match="unknown disturbance 'flip': the names are flap, lag, pitch"):
        simulate_disturbance(table_i, 0.0, {"flip": 0.01}, 1.0)
    with pytest.raises(ValueError, match="n_revs must be a positive"):
        simulate_disturbance(table_i, 0.0, {"flap": 0.01}, -1.0)
    other = replace(table_i, lag_damping=2.0 * table_i.lag_damping)
    with pytest.raises(ValueError, match="the certificate is of another case"):
        simulate_disturbance(other, 0.0, {"flap": 0.01}, 1.0, certificate=hover_certificate)


def test_the_tables_and_figures_are_written_in_the_format_of_their_suffix(table_i, tmp_path):
    """write_table: CSV with the records' columns and JSON records (NaN as null); save_figure: PNG and
    SVG by the suffix (the file's signature), another suffix refused."""
    import matplotlib

    matplotlib.use("Agg")
    from rotorlyap.chapters.blade_commands import plot_modes, save_figure, write_table

    omega = table_i.rotor_speed
    fan = fan_plot(table_i, [0.9 * omega, omega])
    rows = fan.export()
    rows.append({**rows[0], "frequency_hz": float("nan")})
    with open(write_table(rows, tmp_path / "t.csv"), newline="") as fh:
        read = list(csv.DictReader(fh))
    assert list(read[0]) == list(MODE_COLUMNS) and len(read) == len(rows) and read[-1]["frequency_hz"] == "nan"
    records = json.loads(write_table(rows, tmp_path / "t.json").read_text())
    assert records[-1]["frequency_hz"] is None and records[0]["kind"] == "hover"
    fig = plot_modes(fan)
    assert save_figure(fig, tmp_path / "f.png").read_bytes()[:8] == PNG
    assert b"<svg" in save_figure(fig, tmp_path / "f.svg").read_bytes()[:400]
    with pytest.raises(ValueError, match="must end in .png or .svg"):
        save_figure(fig, tmp_path / "f.jpg")
    with pytest.raises(ValueError, match="must end in .csv or .json"):
        write_table(rows, tmp_path / "t.txt")


def test_a_blade_hinged_at_the_shaft_has_the_classical_spring_frequencies(table_i):
    """blade_length = radius with every hub element 0: the classical centrally hinged blade
    (Ormiston & Hodges' rigid blade). In vacuum, without gravity, pitch-flap coupling or C.G.
    offset from the pitch axis, and with the pitch hinge held stiff, its rotating frequencies
    are the textbook ones: flap ``nu^2 = 1 + K_beta / (I_beta Omega^2)`` (the centrifugal
    stiffness of a central hinge is ``I_beta Omega^2``), lag ``nu^2 = K_zeta / (I_zeta
    Omega^2)`` (none about the shaft), with ``I_beta = m R^3 / 3`` and ``I_zeta = I_beta + m R
    k^2`` (the section's chordwise radius of gyration ``k`` lies in the plane of the disc)."""
    import warnings

    from rotorlyap.errors import TemplateValuesWarning

    k_beta, k_zeta = 20000.0, 150000.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", TemplateValuesWarning)
        p = replace(table_i, blade_length=table_i.radius, hub_elements=(0.0, 0.0, 0.0, 0.0, 0.0),
                    flap_stiffness=k_beta, lag_stiffness=k_zeta, air_density=0.0, gravity=0.0,
                    lag_damping=0.0, collective=0.0, pitch_flap_coupling=0.0,
                    cg_position=table_i.pitch_axis, pitch_stiffness=1e7)
    assert p.root_cutout == 0.0
    m, R, om = p.mass_per_length, p.radius, p.rotor_speed
    k = p.pitch_radius_of_gyration * p.chord
    i_beta = m * R**3 / 3.0
    i_zeta = i_beta + m * R * k**2
    freq = {mode.dominant_hinge: abs(mode.eigenvalue.imag) for mode in hover_modes(p)}
    assert freq["flap"] == pytest.approx(np.sqrt(1.0 + k_beta / (i_beta * om**2)), rel=1e-10)
    assert freq["lag"] == pytest.approx(np.sqrt(k_zeta / (i_zeta * om**2)), rel=1e-10)

