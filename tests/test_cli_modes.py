"""The command line's blade commands: the ``rotorlyap`` console script, ``modes``, ``simulate`` and
``--plot`` on ``certify`` and ``sweep``: the files they write, and clear refusals of bad arguments."""

import csv
import importlib
import json
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from rotorlyap.analysis.modes import MODE_COLUMNS
from rotorlyap.cli import main

ROOT = Path(__file__).resolve().parents[1]
PUMA = str(ROOT / "rotorlyap" / "data" / "sa330_puma.toml")
PNG = b"\x89PNG\r\n\x1a\n"


def test_pyproject_declares_the_rotorlyap_command_and_its_target_exists():
    """pip install gives a `rotorlyap` command: [project.scripts] names rotorlyap.cli:main, which exists
    and is the function `python -m rotorlyap` runs (the generated script exits with its status)."""
    scripts = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["scripts"]
    module, _, name = scripts["rotorlyap"].partition(":")
    target = getattr(importlib.import_module(module), name)
    assert callable(target) and target is main
    assert "sys.exit(main())" in (ROOT / "rotorlyap" / "__main__.py").read_text()


def test_help_lists_the_new_commands(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["--help"])
    assert exc.value.code == 0
    out = capsys.readouterr().out
    assert "modes" in out and "simulate" in out


def test_modes_writes_the_table_and_the_figure(capsys, tmp_path):
    """modes --params (the Puma) writes the CSV with the announced columns (hover rows at each rotor
    speed, Floquet rows at each mu) and a PNG, and prints the hover modes at the nominal speed."""
    out, fig = tmp_path / "modes.csv", tmp_path / "sub" / "modes.png"
    assert main(["modes", "--params", PUMA, "--rotor-speed-ratios", "0.9,1", "--mu", "0,0.05",
                 "--out", str(out), "--plot", str(fig)]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["table"] == str(out) and data["plot"] == str(fig)
    assert {m["mode"] for m in data["hover_modes"]} >= {"flap", "pitch"}
    with out.open(newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert list(rows[0]) == list(MODE_COLUMNS)
    hover = [r for r in rows if r["kind"] == "hover"]
    assert sorted({r["rotor_speed_ratio"] for r in hover}) == ["0.9", "1"]
    assert sorted({r["mu"] for r in rows if r["kind"] == "floquet"}) == ["0", "0.05"]
    assert all(r["error"] == "" for r in rows)
    assert fig.read_bytes()[:8] == PNG


def test_modes_in_vacuum_as_json_and_svg_without_floquet(capsys, tmp_path):
    """--vacuum --no-floquet --out .json --plot .svg: the table holds vacuum rows only, in rad/s as asked."""
    out, fig = tmp_path / "fan.json", tmp_path / "fan.svg"
    assert main(["modes", "--rotor-speeds", "20,28.35", "--vacuum", "--no-floquet", "--out", str(out),
                 "--plot", str(fig)]) == 0
    capsys.readouterr()
    records = json.loads(out.read_text())
    assert {r["kind"] for r in records} == {"vacuum"}
    assert sorted({r["rotor_speed_rad_s"] for r in records}) == [20.0, 28.35]
    assert b"<svg" in fig.read_bytes()[:400]


def test_simulate_writes_the_motion_and_draws_the_certified_bound(capsys, tmp_path):
    """simulate --certify (Table I, hover): the CSV has a row per output time with the announced columns
    and the bound per hinge, the PNG is written, and a disturbance inside the start region is reported so."""
    out, fig = tmp_path / "motion.csv", tmp_path / "motion.png"
    assert main(["simulate", "--mu", "0", "--disturb", "flap=0.1deg,pitch_rate=1deg/s", "--revs", "2",
                 "--certify", "--n-psi", "4", "--n-sphere", "16", "--out", str(out), "--plot", str(fig)]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["disturbance"] == {"flap": {"deg": 0.1}, "pitch_rate": {"deg_per_s": 1.0}}
    assert data["certified"] is True and data["inside_start_region"] is True
    assert all(data["largest_deviation_deg"][h] <= data["bound_deg"][h] for h in ("flap", "lag", "pitch"))
    with out.open(newline="") as fh:
        rows = list(csv.DictReader(fh))
    hinges = ("flap", "lag", "pitch")
    assert list(rows[0]) == (["revolution", "time_s"]
                             + [f"{h}_{k}" for h in hinges for k in ("deg", "steady_deg", "deviation_deg")]
                             + ["scaled_norm"] + [f"{h}_bound_deg" for h in hinges])
    assert float(rows[0]["flap_deviation_deg"]) == pytest.approx(0.1) and float(rows[-1]["revolution"]) == 2.0
    assert fig.read_bytes()[:8] == PNG


def test_certify_draws_the_region_per_hinge_with_plot(capsys, tmp_path):
    fig = tmp_path / "cert.png"
    assert main(["certify", "--mu", "0", "--n-psi", "4", "--n-sphere", "16", "--function", "quadratic",
                 "--plot", str(fig)]) == 0
    assert json.loads(capsys.readouterr().out)["plot"] == str(fig)
    assert fig.read_bytes()[:8] == PNG


def test_sweep_draws_its_table_with_plot(capsys, tmp_path):
    table, fig2 = tmp_path / "t.csv", tmp_path / "sweep.svg"
    assert main(["sweep", "--n-psi", "4", "--n-sphere", "16", "--workers", "1", "--out", str(table),
                 "--plot", str(fig2)]) == 0
    assert capsys.readouterr().out.splitlines()[:2] == [str(table), str(fig2)]
    assert b"<svg" in fig2.read_bytes()[:400]


@pytest.mark.parametrize(
    "args, message",
    [
        (["simulate", "--disturb", "flip=2deg"], "NAME one of flap, lag, pitch, flap_rate"),
        (["simulate", "--disturb", "flap=2"], "--disturb flap needs a unit, deg or rad"),
        (["simulate", "--disturb", "flap=2km"], "--disturb flap needs a unit, deg or rad"),
        (["simulate", "--disturb", "lag_rate=1deg"], "--disturb lag_rate needs a unit, deg/s or rad/s"),
        (["simulate", "--disturb", "flap=xdeg"], "--disturb flap must be a number and a unit"),
        (["simulate", "--disturb", "flap=1deg,flap=2deg"], "--disturb gives flap twice"),
        (["simulate", "--disturb", "flap=1deg", "--revs", "-1"], "--revs must lie in (0, 10000]"),
        (["simulate", "--disturb", "flap=1deg", "--plot", "m.jpg"], "--plot must end in .png or .svg"),
        (["simulate", "--disturb", "flap=1deg", "--out", "m.txt"], "--out must end in .csv or .json"),
        (["simulate", "--mu", "0.1"], "the following arguments are required: --disturb"),
        (["modes", "--rotor-speeds", "0,20"], "--rotor-speeds values must lie in (0, 10000]"),
        (["modes", "--rotor-speeds", "20", "--rotor-speed-ratios", "1"], "not allowed with argument"),
        (["modes", "--mu", "0,4"], "--mu values must lie in [0, 3]"),
        (["modes", "--plot", "fan.pdf"], "--plot must end in .png or .svg"),
        (["certify", "--plot", "c.txt"], "--plot must end in .png or .svg"),
        (["sweep", "--out", "t.csv", "--plot", "s"], "--plot must end in .png or .svg"),
    ],
)
def test_bad_arguments_give_one_line_and_exit_status_2(args, message, capsys):
    """argparse refuses bad arguments before any work: exit status 2, the message says what is allowed,
    no traceback."""
    with pytest.raises(SystemExit) as exc:
        main(args)
    assert exc.value.code == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err
    assert err.strip().splitlines()[-1].startswith("python -m rotorlyap ")


def test_a_bad_argument_in_a_fresh_process_exits_2_without_a_traceback():
    out = subprocess.run([sys.executable, "-m", "rotorlyap", "simulate", "--disturb", "flap=2"],
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 2 and "Traceback" not in out.stderr and "needs a unit" in out.stderr


def test_a_rotor_speed_the_blade_refuses_is_an_analysis_error_with_status_1(capsys):
    """A rotor speed whose tip passes the speed of sound is refused by the parameter checks: one line,
    exit status 1."""
    assert main(["modes", "--rotor-speeds", "28,60", "--no-floquet"]) == 1
    err = capsys.readouterr().err
    assert "python -m rotorlyap modes: error: rotor_speed = 60.0 rad/s gives a tip speed" in err
    assert "Traceback" not in err
