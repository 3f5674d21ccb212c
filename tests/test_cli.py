"""The command line ``python -m rotorlyap``: answers, help and clear errors."""

import csv
import io
import json
import subprocess
import sys

import numpy as np
import pytest

from rotorlyap.cli import _number_list, main, progress_bar
from rotorlyap.model.parameters import BladeParameters

OMEGA = 28.35  # Table I rotor speed, rad/s


def run(*args):
    return subprocess.run([sys.executable, "-m", "rotorlyap", *args], capture_output=True, text=True, timeout=600)


def significant_digits_at_most(value: float, digits: int = 4) -> bool:
    return value == float(f"{value:.{digits - 1}e}")


def test_help_lists_the_commands():
    """--help exits 0 and names every sub-command."""
    out = run("--help")
    assert out.returncode == 0
    for command in ("analyse", "certify", "sweep", "figures"):
        assert command in out.stdout


# ---------------------------------------------------------------------- analyse


def test_analyse_sound_rule_is_certified_and_the_paper_rule_is_not(capsys):
    """The strict reading's default rule is the sound one, which checks (h) over the whole period:
    with every azimuth certified, 'certified' is true and nothing is warned. --rule paper is the
    paper's algorithm: 'certified' false and a warning, in the JSON and on stderr."""
    assert main(["analyse", "--cg", "forward", "--mu", "0", "--n-psi", "6", "--n-sphere", "64",
                 "--lyapunov", "quadratic"]) == 0
    out = capsys.readouterr()
    data = json.loads(out.out)
    assert data["rule"] == "sound" and all(data["stable"]) and data["certified"] is True
    assert data["warnings"] == [] and "warning" not in out.err
    assert "numerical certificate" in data["kind"]
    assert main(["analyse", "--cg", "forward", "--mu", "0", "--rule", "paper", "--n-psi", "6", "--n-sphere", "64",
                 "--lyapunov", "quadratic"]) == 0
    out = capsys.readouterr()
    data = json.loads(out.out)
    assert data["rule"] == "paper" and data["certified"] is False and "never a certificate" in data["kind"]
    assert len(data["warnings"]) == 1 and "--rule paper" in data["warnings"][0]
    assert f"warning: {data['warnings'][0]}" in out.err


def test_analyse_prints_the_result_as_json_and_lambda0_per_hinge(capsys):
    """analyse prints a JSON object with the engine's named fields; the practical reading is never
    certified and says so in a warning; lambda0 is given per azimuth in the scaled norm, and its
    smallest value per hinge: a_i lambda0 in deg and a_(i+3) lambda0 Omega in deg/s."""
    assert main(["analyse", "--cg", "forward", "--mu", "0", "--reading", "practical", "--n-psi", "6"]) == 0
    out = capsys.readouterr()
    data = json.loads(out.out)
    assert data["reading"] == "practical" and data["certified"] is False
    assert len(data["warnings"]) == 1 and "--reading practical" in data["warnings"][0]
    assert "--reading practical" in out.err
    assert data["n_psi"] == 6 and len(data["lambda0_scaled_norm"]) == 6 and len(data["stable"]) == 6
    assert data["case"]["cg"] == "forward" and data["A_requested"] == 1.0
    lam = data["lambda0_min_scaled_norm"]
    assert lam == pytest.approx(min(data["lambda0_scaled_norm"]), rel=1e-3) and lam > 0
    per_hinge = data["lambda0_per_hinge"]
    assert set(per_hinge) == {"flap", "lag", "pitch"}
    scales = data["scales_deg"]  # 2 2 1 deg, 2 0.5 5 deg/rad
    for i, h in enumerate(("flap", "lag", "pitch")):
        assert per_hinge[h]["deg"] == pytest.approx(scales[i] * lam, rel=1e-3)
        assert per_hinge[h]["deg_per_s"] == pytest.approx(scales[i + 3] * lam * OMEGA, rel=1e-3)
        assert significant_digits_at_most(per_hinge[h]["deg"])


def test_quadratic_function_about_hover_in_forward_flight_warns_and_is_not_certified(capsys):
    """--lyapunov quadratic about the hover equilibrium at mu > 0 cannot certify (the hover state is
    not the steady motion in forward flight): a warning pointing to --steady periodic or certify,
    and 'certified' false though the reading is strict and the rule sound."""
    assert main(["analyse", "--mu", "0.1", "--lyapunov", "quadratic", "--n-psi", "4", "--n-sphere", "16"]) == 0
    out = capsys.readouterr()
    data = json.loads(out.out)
    assert data["reading"] == "strict" and data["rule"] == "sound"
    assert data["certified"] is False and not all(data["stable"])
    assert len(data["warnings"]) == 1
    assert "--steady periodic" in data["warnings"][0] and "certify command" in data["warnings"][0]
    assert "hover equilibrium is not the" in out.err


def test_params_file_gives_the_same_analysis_as_the_table_i_case(capsys, tmp_path):
    """--params FILE (TOML, BladeParameters.to_file) with the Table I backward C.G. gives the
    analysis of --cg backward, the C.G. case recognised; --cg with --params overrides the file's
    cg_position."""
    path = BladeParameters.table_i("backward").to_file(tmp_path / "blade.toml")
    common = ["--reading", "practical", "--n-psi", "4"]
    assert main(["analyse", "--cg", "backward", *common]) == 0
    by_name = json.loads(capsys.readouterr().out)
    assert main(["analyse", "--params", str(path), *common]) == 0
    by_file = json.loads(capsys.readouterr().out)
    assert by_file["case"]["params"] == str(path) and by_file["case"]["cg"] == "backward"
    assert by_file["case"]["cg_position"] == 0.255
    by_file["case"]["params"] = by_name["case"]["params"]
    assert by_file == by_name
    assert main(["analyse", "--params", str(path), "--cg", "forward", *common]) == 0
    overridden = json.loads(capsys.readouterr().out)
    assert overridden["case"]["cg"] == "forward" and overridden["case"]["cg_position"] == 0.215


def test_a_bad_parameter_file_gives_a_message_and_exit_status_1(capsys, tmp_path):
    """A parameter file the reader refuses gives a one-line message naming the file, exit status 1."""
    path = tmp_path / "bad.toml"
    path.write_text('schema = "something/9"\n')
    assert main(["analyse", "--params", str(path), "--n-psi", "4"]) == 1
    err = capsys.readouterr().err
    assert "python -m rotorlyap analyse: error:" in err and "bad.toml" in err


def test_a_file_that_leaves_blade_fields_to_the_template_warns_on_stderr(capsys, tmp_path):
    """The file's fields left to the template are named in a 'warning:' line on stderr (the JSON on
    stdout stays parseable)."""
    path = tmp_path / "short.toml"
    path.write_text('schema = "rotorlyap.blade/1"\nlag_damping = 8000.0\n')
    assert main(["analyse", "--params", str(path), "--n-psi", "2", "--n-sphere", "8", "--A", "0.5"]) == 0
    out = capsys.readouterr()
    assert "warning: " in out.err and "short.toml leaves out 21 of the 22 blade fields" in out.err
    assert "pitch_flap_coupling = -0.4" in out.err
    json.loads(out.out)


# ---------------------------------------------------------------------- certify


def test_certify_prints_the_certificate_per_hinge(capsys):
    """certify prints certified, the bound and start region (scaled norm) and per hinge in deg and
    deg/s (a_i r and a_(i+3) r Omega), the growth rate, the trim in degrees and C_T/sigma, with 4
    significant digits, and the message's 'numerical certificate'; the function it rests on and
    every candidate tried."""
    assert main(["certify", "--mu", "0", "--n-psi", "4", "--n-sphere", "16", "--function", "quadratic"]) == 0
    printed = capsys.readouterr()
    data = json.loads(printed.out)  # the progress went to stderr, one line per stage (not a terminal)
    assert "  sound rule: final check of the band" in printed.err and "start set" not in printed.out
    assert data["certified"] is True and "numerical certificate" in data["message"]
    # the start set holds the ball along every hinge
    for h, v in data["start_set_per_hinge"].items():
        assert v["deg"] >= data["start_region_per_hinge"][h]["deg"]
    assert data["function"] == "quadratic" and "quadratic function" in data["kind"]
    assert [c["function"] for c in data["candidates"]] == ["quadratic"]
    assert data["candidates"][0]["start_region"] == data["start_region"]
    assert data["case"] == {"params": "Table I", "cg": "forward", "cg_position": 0.215, "mu": 0.0,
                            "condition": "propulsive"}
    assert 0.0 < data["start_region"] < data["bound"] <= 1.0
    for key, radius in (("start_region_per_hinge", data["start_region"]), ("bound_per_hinge", data["bound"])):
        assert data[key]["flap"]["deg"] == pytest.approx(2.0 * radius, rel=1e-3)
        assert data[key]["pitch"]["deg_per_s"] == pytest.approx(5.0 * radius * OMEGA, rel=1e-3)
    assert data["growth_rate_per_rev"] < 0.0
    trim = data["trim"]
    assert set(trim) == {"collective_deg", "cyclic_cos_deg", "cyclic_sin_deg", "shaft_tilt_deg", "CT_over_sigma"}
    assert 5.0 < trim["collective_deg"] < 15.0 and 0.05 < trim["CT_over_sigma"] < 0.12
    numbers = [data["bound"], data["start_region"], data["growth_rate_per_rev"], *trim.values(),
               *(v for h in data["start_region_per_hinge"].values() for v in h.values())]
    assert all(significant_digits_at_most(v) for v in numbers)


def test_certify_verify_adds_the_proof(capsys):
    """certify --verify (hover, the quadratic function): the JSON has 'proof', proved, with a bound
    and start region inside the numerical certificate's, per hinge in the same units, and
    'proved_part': the function proved and its fractions of the numerical certificate."""
    assert main(["certify", "--mu", "0", "--n-psi", "4", "--n-sphere", "16", "--function", "quadratic",
                 "--verify"]) == 0
    data = json.loads(capsys.readouterr().out)
    proof = data["proof"]
    assert proof["proved"] is True and "ball arithmetic" in proof["kind"]
    assert 0.0 < proof["start_region"] < proof["bound"] <= data["bound"]
    assert proof["bound_per_hinge"]["flap"]["deg"] == pytest.approx(2.0 * proof["bound"], rel=1e-3)
    assert proof["n_intervals"] == 1
    part = data["proved_part"]
    assert part["function"] == "quadratic" and part["proved"] is True and part["not_proved"] == ""
    assert part["bound"] == proof["bound"] and 0 < part["bound_fraction"] <= 1
    assert part["start_fraction"] == pytest.approx(proof["start_region"] / data["start_region"], rel=1e-3)


# ---------------------------------------------------------------------- sweep


def test_sweep_writes_the_table_and_counts_the_certified_points(capsys, tmp_path):
    """sweep writes one table (format from the suffix), prints its path and 'certified k of n'; a
    failing point (no air) is a row with its error, the sweep goes on; the progress goes to stderr."""
    out = tmp_path / "table.csv"
    assert main(["sweep", "--set", "air_density=0,1.225", "--n-psi", "4", "--n-sphere", "16", "--workers", "1",
                 "--out", str(out)]) == 0
    captured = capsys.readouterr()
    lines = captured.out.splitlines()
    assert lines[0] == str(out)
    assert lines[1].startswith("certified 1 of 2 points") and "1 failed" in lines[1]
    assert "2/2" in captured.err
    with out.open(newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert [r["air_density"] for r in rows] == ["0.0", "1.225"]
    assert [r["condition"] for r in rows] == ["propulsive"] * 2 and [r["mu"] for r in rows] == ["0.0"] * 2
    assert rows[0]["certified"] == "False" and "needs air" in rows[0]["error"]
    assert rows[1]["certified"] == "True" and rows[1]["error"] == ""


# ---------------------------------------------------------------------- figures


@pytest.mark.slow
def test_figures_writes_each_figure_whole_with_its_data(capsys, tmp_path):
    """figures --quick writes a PNG and a CSV per figure (Fig 8 once per reading, with the
    category legend) and names them on stdout; each PNG is saved whole (bbox_inches='tight'),
    so a white margin runs round every edge: no tick label or legend is cut off."""
    import matplotlib.image

    assert main(["figures", "--out", str(tmp_path), "--quick"]) == 0
    out = capsys.readouterr()
    stems = ["fig4_hover_trim", "fig5_hover_rate", "fig6_w_spheres", "fig7_rate_azimuth",
             "fig8_regions_practical", "fig8_regions_strict"]
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(f"{s}.{e}" for s in stems for e in ("csv", "png"))
    assert out.out.split() == [str(tmp_path / f"{s}.{e}") for s in stems for e in ("png", "csv")]
    assert "[5/5] Fig 8" in out.err
    for stem in stems:
        img = matplotlib.image.imread(tmp_path / f"{stem}.png")[..., :3]
        frame = np.concatenate([img[:3].reshape(-1, 3), img[-3:].reshape(-1, 3),
                                img[:, :3].reshape(-1, 3), img[:, -3:].reshape(-1, 3)])
        assert frame.min() == 1.0, f"{stem}: something reaches the edge of the picture"


def test_the_fig8_picture_of_one_reading_has_the_category_legend():
    """The command line's Fig 8 (one reading per picture) carries the legend of the verdicts."""
    from rotorlyap.chapters import forward_flight

    data = forward_flight.regions_data(("forward",), (0.0, 0.1), reading="practical", n_psi=4)
    fig = forward_flight.figure_regions_polar(data)
    [legend] = fig.legends
    assert [t.get_text().replace("\n", " ") for t in legend.get_texts()][:4] == list(forward_flight.CATEGORY_NAMES)


def test_the_command_line_knows_the_trims_conditions():
    """The --condition choices (kept in the CLI so that --help loads no model) are the trim's."""
    from rotorlyap.cli import CONDITIONS
    from rotorlyap.model.forward_trim import TRIM_TARGETS

    assert CONDITIONS == TRIM_TARGETS


def test_the_command_line_knows_the_design_efforts():
    """The --design choices (kept in the CLI so that --help loads no model) are the design program's."""
    from rotorlyap.analysis.nonlinear_functions import DESIGN_EFFORTS
    from rotorlyap.cli import DESIGN_CHOICES

    assert DESIGN_CHOICES == tuple(DESIGN_EFFORTS)


def test_sweep_lists_and_ranges():
    """A list is 'a,b,c' or 'start:stop:step' with the stop included and decimal steps exact."""
    assert _number_list("--mu", "0:0.3:0.1") == [0.0, 0.1, 0.2, 0.3]
    assert _number_list("--mu", "0,0.05, 0.2") == [0.0, 0.05, 0.2]
    assert _number_list("--set n_blades", "3:5:1", integer=True) == [3, 4, 5]


def test_the_progress_bar_draws_a_line_per_step_in_a_log():
    """Off a terminal the progress bar writes '[###   ] k/n' lines (at most every 5 %)."""
    stream = io.StringIO()
    draw = progress_bar(stream, width=10)
    for done in range(5):
        draw(done, 4)
    lines = stream.getvalue().splitlines()
    assert lines[0].startswith("[          ] 0/4") and lines[-1].startswith("[##########] 4/4")
    assert len(lines) == 5


def test_the_progress_bar_on_a_terminal_is_a_tqdm_bar_ending_at_the_total():
    """On a terminal the sweep's progress is drawn by tqdm (the library the other commands' bars
    use): its last state shows every point done."""

    class Terminal(io.StringIO):
        def isatty(self):
            return True

    stream = Terminal()
    draw = progress_bar(stream)
    for done in range(5):
        draw(done, 4)
    text = stream.getvalue()
    assert "\r" in text and "4/4" in text.split("\r")[-1] and "[#" not in text


@pytest.mark.parametrize(
    "args, message",
    [
        (["analyse", "--mu", "3.5"], "--mu must lie in [0, 3]"),
        (["analyse", "--mu", "fast"], "--mu must be a number"),
        (["analyse", "--cg", "middle"], "invalid choice: 'middle'"),
        (["certify", "--design", "heroic"], "invalid choice: 'heroic' (choose from 'default', 'thorough')"),
        (["certify", "--harmonics", "-1"], "--harmonics must be an integer >= 0"),
        (["analyse", "--A", "-1"], "--A must lie in (0, 1000]"),
        (["analyse", "--scales", "1 2 3"], "--scales must be 6 positive numbers"),
        (["analyse", "--n-psi", "0"], "--n-psi must be an integer >= 1"),
        (["analyse", "--rule", "lenient"], "invalid choice: 'lenient'"),
        (["analyse", "--params", "no/such/blade.toml"], "--params: no such file"),
        (["certify", "--condition", "cruise"], "invalid choice: 'cruise'"),
        (["sweep", "--out", "t.txt"], "--out must end in .csv or .json"),
        (["sweep", "--out", "t.csv", "--set", "lag_dampin=5"], "--set must be NAME=VALUES with NAME a numeric field"),
        (["sweep", "--out", "t.csv", "--set", "n_blades=3.5"], "--set n_blades values must be integers"),
        (["sweep", "--out", "t.csv", "--mu", "0:1:0"], "needs step > 0"),
        (["sweep", "--out", "t.csv", "--mu", "0,4"], "--mu values must lie in [0, 3]"),
        (["sweep", "--out", "t.csv", "--cg", "forward,middle"], "--cg must be a comma-separated list of forward"),
        (["sweep", "--out", "t.csv", "--workers", "0"], "--workers must be an integer >= 1"),
        (["figures"], "the following arguments are required: --out"),
        (["rotate"], "invalid choice: 'rotate'"),
    ],
)
def test_bad_arguments_give_a_message_and_a_non_zero_exit(args, message):
    """argparse refuses bad arguments with exit status 2 and says what is allowed."""
    out = run(*args)
    assert out.returncode == 2
    assert message in out.stderr


def test_harmonics_in_hover_are_refused_before_any_design_with_exit_status_1():
    """The library's refusal (certify: a designed function of the autonomous blade has constant
    coefficients) reaches the shell as one line, exit status 1, no traceback."""
    out = run("certify", "--harmonics", "2")
    assert out.returncode == 1
    assert "harmonics must be None or an integer >= 0, and 0 or None in hover" in out.stderr
    assert "Traceback" not in out.stderr


def test_a_bad_grid_value_gives_a_message_and_exit_status_1(capsys, tmp_path):
    """A value the blade does not allow (a negative damper) is refused before any work: one line,
    exit status 1, no table written."""
    out = tmp_path / "t.csv"
    assert main(["sweep", "--set", "lag_damping=-5", "--out", str(out)]) == 1
    err = capsys.readouterr().err
    assert "python -m rotorlyap sweep: error: grid['lag_damping'] = -5.0 is not allowed" in err
    assert not out.exists()
