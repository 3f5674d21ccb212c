"""Parameters a user cannot get wrong silently: which fields came from the template, parameter
files (TOML) and their round trip, the example blade from public data, and trims that fail with
the blade loading and what to change."""

from __future__ import annotations

import dataclasses
import math
import warnings
from pathlib import Path

import pytest

import rotorlyap.model.parameters as parameters_module
from rotorlyap.errors import TemplateValuesWarning, TrimError
from rotorlyap.model.parameters import (
    BLADE_FIELDS,
    EXAMPLE_FILES,
    BladeParameters,
    TabulatedProfile,
    field_origins,
    parameter_table,
)
from rotorlyap.model.trim import MAX_TRIMMED_PITCH, check_trimmed_pitch, hover_trim

PUMA = EXAMPLE_FILES["sa330-puma"]


@pytest.fixture(autouse=True)
def _fresh_warning_registry():
    """Each test sees the template warning afresh (it is issued once per rotor per process)."""
    parameters_module._WARNED.clear()
    yield
    parameters_module._WARNED.clear()


def _puma_like(**more):
    return BladeParameters(radius=7.49, blade_length=5.41, chord=0.537, rotor_speed=28.27,
                           hub_elements=(0.0534, 0.0, 0.0, 0.0264, 0.0), **more)


# ---------------------------------------------------------------- provenance
def test_another_rotor_built_on_the_template_is_warned_with_the_fields_it_kept():
    """A rotor of another radius that gives only its geometry keeps the paper's delta3, control
    stiffness and lag damper: the warning names them with their values."""
    with pytest.warns(TemplateValuesWarning, match=r"radius, blade_length, rotor_speed describe another rotor") as rec:
        _puma_like()
    text = str(rec[0].message)
    for kept in ("pitch_flap_coupling = -0.4", "pitch_stiffness = 6304.0 N m/rad", "lag_damping = 10000.0 N m s/rad",
                 "helicopter_mass = 6400.0 kg"):
        assert kept in text
    assert "chord" not in text.split("keep the template")[1]  # given, so not listed
    assert rec[0].filename == __file__  # points at the user's line


def test_the_warning_comes_once_per_blade_not_at_every_rebuild():
    """The trims and a user's studies rebuild a blade many times with dataclasses.replace: one
    warning per rotor, not at every rebuild (not even with other template fields)."""
    with pytest.warns(TemplateValuesWarning) as rec:
        p = _puma_like()
        dataclasses.replace(p, collective=0.1)
        dataclasses.replace(p, cyclic_cos=0.01)
        dataclasses.replace(p, pitch_flap_coupling=0.1)
    assert len(rec) == 1


def test_a_blade_read_from_a_file_is_warned_by_the_file_only():
    """The file knows which fields it gives: its warning names them; rebuilding its blade with
    dataclasses.replace adds no second, by-value warning (which would list fields the file gave
    equal to the template's, such as n_blades = 4)."""
    with pytest.warns(TemplateValuesWarning) as rec:
        p = BladeParameters.from_file(PUMA)
        dataclasses.replace(p, pitch_flap_coupling=0.0)
    assert len(rec) == 1 and "leaves out 3 of the 22 blade fields" in str(rec[0].message)


def test_variants_of_the_table_i_rotor_are_not_warned():
    """Changing the C.G., the mass or the lag damper of the paper's rotor is a study of that rotor."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", TemplateValuesWarning)
        dataclasses.replace(BladeParameters.table_i("backward"), mass_per_length=11.0, lag_damping=5000.0)


def test_a_blade_that_gives_every_blade_field_is_not_warned():
    """Nothing left to the template among the blade fields, nothing to warn about."""
    base = BladeParameters.table_i()
    given = {n: getattr(base, n) for n in BLADE_FIELDS}
    given.update(radius=8.0, blade_length=7.0, pitch_flap_coupling=0.1, pitch_stiffness=9000.0, lag_damping=8000.0,
                 hub_elements=(0.02, 0.0, 0.0, 0.02, 0.0), twist=-0.2, flap_stiffness=1.0, lag_stiffness=1.0,
                 flap_damping=1.0, pitch_damping=1.0, aerodynamic_centre=0.25, pitch_axis=0.24, cg_position=0.24,
                 mass_per_length=10.0, pitch_radius_of_gyration=0.21, n_blades=5, helicopter_mass=7000.0,
                 airfoil=dataclasses.replace(base.airfoil, cm_ac=0.0), flat_plate_area=2.0, chord=0.5,
                 rotor_speed=27.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error", TemplateValuesWarning)
        p = BladeParameters(**given)
    assert all(field_origins(p)[n] == "given" for n in BLADE_FIELDS)


def test_parameter_table_tells_template_values_from_given_ones():
    """The source column says 'given' for the user's values and 'template Table I: ...' for the
    values another rotor inherited; the paper's own blade keeps its plain sources."""
    with pytest.warns(TemplateValuesWarning):
        p = _puma_like()
    rows = {r[0]: r[3] for r in parameter_table(p)}
    assert rows["radius"] == rows["chord"] == "given"
    assert rows["pitch_flap_coupling"] == "template Table I: Table I (tan delta3)"
    assert rows["lag_damping"].startswith("template Table I: ")
    assert rows["mass_per_length"].startswith("template Table I: assumed")
    paper = {r[0]: r[3] for r in parameter_table(BladeParameters.table_i("neutral"))}
    assert paper["radius"] == "Table I" and paper["cg_position"].startswith("Table I computation")
    assert field_origins(BladeParameters.table_i("backward"))["cg_position"] == "template Table I"


# ---------------------------------------------------------------- files
@pytest.mark.parametrize("make", [
    lambda: BladeParameters.table_i("neutral"),
    lambda: BladeParameters.flight_case("backward", collective=0.15, inflow_ratio=0.05, wind_point=0.75),
    lambda: dataclasses.replace(
        BladeParameters.table_i(), chord=TabulatedProfile((0.14, 1.0), (0.45, 0.35)),
        mass_per_length=TabulatedProfile((0.1, 0.5, 1.0), (12.0, 9.0, 10.0)),
        airfoil=dataclasses.replace(BladeParameters().airfoil, alpha_zero_lift=0.0, cm_ac=0.0, name="sym")),
    lambda: BladeParameters.table_i(airfoil=parameters_module.FILE_AIRFOILS["linear"]),
], ids=["table-i", "options-and-controls", "tabulated-profiles-and-changed-airfoil", "linear-airfoil"])
def test_a_file_reads_back_equal_to_what_was_written(tmp_path, make):
    """to_file then from_file is the identity (floats written with repr are read back exactly)."""
    p = make()
    path = p.to_file(tmp_path / "blade.toml", name="round trip", sources={"radius": "Table I"})
    with warnings.catch_warnings():
        warnings.simplefilter("error", TemplateValuesWarning)  # a written file gives every field
        q = BladeParameters.from_file(path)
    assert q == p
    assert q.chord_at(0.5) == pytest.approx(p.chord_at(0.5), abs=0)


def test_a_written_file_says_each_fields_unit_and_origin(tmp_path):
    text = BladeParameters.table_i().to_file(tmp_path / "b.toml").read_text()
    assert 'schema = "rotorlyap.blade/1"' in text
    assert "lag_damping = 10000.0  # N m s/rad; template Table I" in text


@pytest.mark.parametrize("body, error, match", [
    ('radius = 7.0\n', ValueError, r'must declare schema = "rotorlyap.blade/1"'),
    ('schema = "rotorlyap.blade/2"\n', ValueError, r"must declare schema"),
    ('schema = "rotorlyap.blade/1"\nradius = [\n', ValueError, r"not a valid TOML file"),
    ('schema = "rotorlyap.blade/1"\nrotor_sped = 27.0\n', ValueError, r"unknown key\(s\) \['rotor_sped'\]; allowed: .*'rotor_speed'"),
    ('schema = "rotorlyap.blade/1"\nradius = -7.0\n', ValueError, r"b\.toml: radius must be > 0, got -7\.0"),
    ('schema = "rotorlyap.blade/1"\nradius = "7.0"\n', TypeError, r"b\.toml: radius must be a real number"),
    ('schema = "rotorlyap.blade/1"\nrotor_speed = 265.0\n', ValueError, r"if 265\.0 is in rpm, give 27\.75 rad/s"),
    ('schema = "rotorlyap.blade/1"\ntwist = -8.0\n', ValueError, r"twist = -8\.0 rad is -458 deg.*give -0\.1396 rad"),
    ('schema = "rotorlyap.blade/1"\nairfoil = "naca0012"\n', ValueError, r"airfoil must be one of \('table-i', 'naca23012', 'linear'\)"),
    ('schema = "rotorlyap.blade/1"\nairfoil = { base = "table-i", camber = 0.0 }\n', ValueError, r"unknown field\(s\) \['camber'\]"),
    ('schema = "rotorlyap.blade/1"\nchord = { r_over_R = [0.5, 0.2], values = [0.4, 0.3] }\n', ValueError, r"chord: the stations r_over_R .* must increase strictly"),
    ('schema = "rotorlyap.blade/1"\nhub_elements = 0.01\n', ValueError, r"hub_elements must be an array of 5 numbers"),
], ids=["no-schema", "later-schema", "not-toml", "typo", "negative", "string", "rpm", "degrees", "airfoil-name",
        "airfoil-field", "profile-order", "hub-scalar"])
def test_bad_files_are_refused_with_the_file_the_field_and_what_is_allowed(tmp_path, body, error, match):
    path = tmp_path / "b.toml"
    path.write_text(body)
    with pytest.raises(error, match=match):
        BladeParameters.from_file(path)


def test_a_callable_profile_cannot_be_written_and_says_what_can(tmp_path):
    p = dataclasses.replace(BladeParameters.table_i(), chord=lambda x: 0.4 - 0.05 * x)
    with pytest.raises(ValueError, match=r"chord is a callable profile.*TabulatedProfile"):
        p.to_file(tmp_path / "b.toml")


def test_a_file_that_leaves_out_blade_fields_warns_which():
    """The example Puma file leaves out what no public source gives (delta3, the control-system
    stiffness, the lag damper): reading it names exactly those three."""
    with pytest.warns(TemplateValuesWarning, match=r"leaves out 3 of the 22 blade fields") as rec:
        p = BladeParameters.from_file(PUMA)
    text = str(rec[0].message)
    assert "pitch_flap_coupling = -0.4" in text and "pitch_stiffness" in text and "lag_damping" in text
    assert p.radius == 7.49 and p.chord == 0.537 and p.n_blades == 4


def test_the_example_puma_file_holds_its_sources_numbers():
    """The Puma file's derived entries agree with the data they come from (PumaBladeData): the
    span outboard of the 2.080 m cutout, the hinges at 0.289 m and 0.432 m, the rotor speed
    4.5 Hz, the radius of gyration of 0.109 kg m on 8.929 kg/m."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", TemplateValuesWarning)
        p = BladeParameters.from_file(PUMA)
    assert p.root_cutout == pytest.approx(2.080, abs=1e-12)
    assert p.flap_hinge_offset == pytest.approx(0.289, abs=1e-12)
    assert p.pitch_hinge_radius == pytest.approx(0.432, abs=1e-12)
    assert p.rotor_speed == pytest.approx(4.5 * 2 * math.pi, rel=1e-15)
    assert (p.pitch_radius_of_gyration * p.chord) ** 2 * p.mass_per_length == pytest.approx(0.109, rel=1e-12)
    assert math.degrees(p.twist) == pytest.approx(-6.117 + 0.1584, abs=1e-9)


# ---------------------------------------------------------------- trims that say what to change
def test_an_overweight_helicopter_fails_with_its_blade_loading_and_what_to_change():
    """Ten times the weight: the trim reports C_T/sigma, the mean lift coefficient 6 C_T/sigma it
    needs against the section's cl_max, and the fields to check."""
    p = dataclasses.replace(BladeParameters.table_i(), helicopter_mass=64000.0)
    assert p.blade_loading == pytest.approx(10 * BladeParameters.table_i().blade_loading)
    with pytest.raises(TrimError, match=r"C_T/sigma = 0\.824 .*6 C_T/sigma = 4\.94 against the section's "
                                        r"cl_max = 1\.79.*check helicopter_mass \(kg\)"):
        hover_trim(p)


def test_a_trim_beyond_the_pitch_a_rotor_flies_at_is_refused():
    """A trimmed collective that sets the three-quarter-radius section beyond 25 deg is refused,
    with the blade loading; the twist counts (a twisted blade's root pitch may be larger); the
    paper's blade trims well inside."""
    paper = BladeParameters.table_i()
    assert abs(paper.pitch_at(0.75, hover_trim(paper).collective)) < MAX_TRIMMED_PITCH
    with pytest.raises(TrimError, match=r"hover_trim: the trimmed collective 30\.0 deg at the pitch hinge sets the "
                                        r"section at 0\.75 R to 30\.0 deg, beyond the \+-25 deg.*C_T/sigma = 0\.082"):
        check_trimmed_pitch(paper, math.radians(30.0), "hover_trim")
    twisted = BladeParameters.table_i(twist=math.radians(-18.0))  # the 0.75 R section is ~12 deg below the root
    check_trimmed_pitch(twisted, math.radians(30.0), "hover_trim")


def test_pitch_at_adds_the_linear_twist_over_the_blade():
    p = BladeParameters.table_i(twist=-0.2)
    assert p.pitch_at(p.root_r_over_R, 0.1) == pytest.approx(0.1)
    assert p.pitch_at(1.0, 0.1) == pytest.approx(-0.1)
    with pytest.raises(ValueError, match="pitch_at needs a collective"):
        p.pitch_at(0.75)
