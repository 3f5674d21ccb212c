"""The command line ``python -m rotorlyap``: answers, help and clear errors."""

import json
import subprocess
import sys

import pytest

from rotorlyap.cli import main


def run(*args):
    return subprocess.run([sys.executable, "-m", "rotorlyap", *args], capture_output=True, text=True, timeout=600)


def test_help_lists_the_commands():
    """--help exits 0 and names both sub-commands."""
    out = run("--help")
    assert out.returncode == 0
    assert "analyse" in out.stdout and "figures" in out.stdout


def test_analyse_sound_rule_is_the_certificate(capsys):
    """The strict reading's default rule is the sound one, which checks (h) over the whole
    period and is called a certificate; --rule paper is reported as the paper's algorithm."""
    assert main(["analyse", "--cg", "forward", "--mu", "0", "--n-psi", "6", "--lyapunov", "quadratic"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["rule"] == "sound" and data["certificate"] is True and all(data["stable"])
    assert main(["analyse", "--cg", "forward", "--mu", "0", "--rule", "paper", "--n-psi", "6",
                 "--lyapunov", "quadratic"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["rule"] == "paper" and data["certificate"] is False


def test_analyse_prints_the_result_as_json(capsys):
    """analyse prints a JSON object with the engine's named fields; the practical reading is
    never called a certificate."""
    assert main(["analyse", "--cg", "forward", "--mu", "0", "--reading", "practical", "--n-psi", "6"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["reading"] == "practical" and data["certificate"] is False
    assert data["n_psi"] == 6 and len(data["lambda0"]) == 6 and len(data["stable"]) == 6
    assert data["case"]["cg"] == "forward" and data["A_requested"] == 1.0


@pytest.mark.parametrize(
    "args, message",
    [
        (["analyse", "--mu", "3.5"], "--mu must lie in [0, 3]"),
        (["analyse", "--mu", "fast"], "--mu must be a number"),
        (["analyse", "--cg", "middle"], "invalid choice: 'middle'"),
        (["analyse", "--A", "-1"], "--A must lie in (0, 1000]"),
        (["analyse", "--scales", "1 2 3"], "--scales must be 6 positive numbers"),
        (["analyse", "--n-psi", "0"], "--n-psi must be an integer >= 1"),
        (["analyse", "--rule", "lenient"], "invalid choice: 'lenient'"),
        (["figures"], "the following arguments are required: --out"),
        (["rotate"], "invalid choice: 'rotate'"),
    ],
)
def test_bad_arguments_give_a_message_and_a_non_zero_exit(args, message):
    """argparse refuses bad arguments with exit status 2 and says what is allowed."""
    out = run(*args)
    assert out.returncode == 2
    assert message in out.stderr
