"""Certificates as files anyone can check (rotorlyap.analysis.certificate_file, issue 40).

A certificate saved by Certificate.save is verified by rotorlyap.verify from nothing but the file;
every kind of stored field, edited so that its claim breaks, is refused by the check of that claim
(never by a checksum), an edit that keeps the claims verifies, and a file that cannot be read as a
certificate is a CertificateFileError (from the command line: exit status 2, one line, no
traceback).
"""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import rotorlyap
from rotorlyap.analysis.certificate_file import FORMAT, VERSION, read_certificate
from rotorlyap.cli import main
from rotorlyap.errors import CertificateFileError

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def quadratic(tmp_path_factory):
    """The Table I forward C.G. in hover with the paper's controls, the quadratic function: the
    certificate and its file."""
    cert = rotorlyap.certify(rotorlyap.BladeParameters.table_i("forward"), 0.0, condition="none",
                             function="quadratic")
    assert cert.certified
    path = cert.save(tmp_path_factory.mktemp("certificates") / "hover_quadratic.json")
    return cert, path


def _edited(path: Path, tmp_path: Path, edit, name: str = "edited.json") -> Path:
    data = json.loads(path.read_text())
    edit(data)
    out = tmp_path / name
    out.write_text(json.dumps(data))
    return out


def _failing(result) -> set[str]:
    return {c.name for c in result.checks if not c.holds}


# ------------------------------------------------------------------------------- round trip


def test_a_saved_hover_quadratic_certificate_verifies_every_check(quadratic):
    cert, path = quadratic
    result = rotorlyap.verify(path)
    assert result.holds and [c.name for c in result.checks] == ["steady motion", "level", "start", "band"]
    assert all(c.holds and c.margin >= 0 for c in result.checks)
    assert result.summary().startswith("VERIFIED")
    # the final check is the engine's own: the same search finds the same worst W' in the same states
    assert result["band"].value <= result["band"].limit < 0
    assert result["band"].value == cert.result.band_max_dW
    assert f"{cert.result.check_evaluations} states searched" in result["band"].detail


def test_every_stored_float_reads_back_bit_for_bit(quadratic):
    cert, path = quadratic
    stored = read_certificate(path)
    res, fun = cert.result, cert.lyapunov
    assert stored.params == cert.trim.params and stored.mu == cert.mu and stored.condition == cert.condition
    assert (stored.A, stored.level, stored.band_max_dW, stored.tol) == (res.A, res.level, res.band_max_dW, res.tol)
    for got, want in ((stored.lambda0, res.lambda0), (stored.scales, cert.scales),
                      (stored.steady.state, fun.steady.state), (stored.function.Q, fun.Q),
                      (stored.function.solution.P_grid, fun.solution.P_grid),
                      (stored.function.solution.dP_grid, fun.solution.dP_grid),
                      (stored.function.solution.floquet.monodromy, fun.solution.floquet.monodromy)):
        assert got.dtype == want.dtype and np.array_equal(got, want)
    # and the rebuilt function is the same function, to the bit
    x = np.random.default_rng(0).normal(size=(64, 6)) * cert.scales * 0.3
    psi = np.linspace(0.0, 2 * np.pi, 64)
    assert np.array_equal(stored.function.W(psi, x), fun.W(psi, x))
    assert np.array_equal(stored.function.dW(psi, x), fun.dW(psi, x))


# ------------------------------------------------------------------ edits refused by their checks


def _scale(key: str, factor: float):
    def edit(d):
        c = d["claims"]
        c[key] = [v * factor for v in c[key]] if isinstance(c[key], list) else c[key] * factor
    return edit


def test_a_coefficient_edited_so_that_w_rate_turns_positive_on_the_band_is_refused_by_the_band_check(quadratic,
                                                                                                      tmp_path):
    """The pitch-rate weight of P raised: W grows (the level and a halved start region still hold),
    but W' >= -margin on the band."""
    def edit(d):
        P = d["function"]["solution"]["P_grid"]
        P[0][5][5] += 0.5
        _scale("lambda0", 0.5)(d)

    result = rotorlyap.verify(_edited(quadratic[1], tmp_path, edit))
    assert not result.holds and _failing(result) == {"band"}
    assert "FAILS" in result["band"].detail and result["band"].value > result["band"].limit


def test_a_bound_raised_beyond_what_holds_is_refused_by_the_band_check(quadratic, tmp_path):
    result = rotorlyap.verify(_edited(quadratic[1], tmp_path, _scale("A", 1.05)))
    assert _failing(result) == {"band"}


def test_a_level_raised_above_inf_w_on_the_sphere_is_refused_by_the_level_check(quadratic, tmp_path):
    result = rotorlyap.verify(_edited(quadratic[1], tmp_path, _scale("level", 1.01)))
    assert _failing(result) == {"level"}
    assert "ABOVE" in result["level"].detail and result["level"].margin == pytest.approx(-0.01, rel=1e-3)


def test_start_radii_raised_so_the_ball_leaves_the_level_set_are_refused_by_the_start_check(quadratic, tmp_path):
    result = rotorlyap.verify(_edited(quadratic[1], tmp_path, _scale("lambda0", 1.01)))
    assert _failing(result) == {"start"}
    assert "LEAVE the level set" in result["start"].detail


def test_a_steady_motion_entry_perturbed_off_the_equations_is_refused_by_the_steady_motion_check(quadratic, tmp_path):
    def edit(d):
        d["steady_motion"]["state"][0] += 1e-3  # rad of flap

    result = rotorlyap.verify(_edited(quadratic[1], tmp_path, edit))
    assert "steady motion" in _failing(result)
    assert "does NOT solve the equations" in result["steady motion"].detail


def test_edits_that_keep_the_claims_verify(quadratic, tmp_path):
    """Smaller start radii; and the bound, the level and the start radii lowered together as the
    quadratic W scales (c ~ A^2, lambda0 ~ A). No checksum: only the claims decide."""
    smaller = rotorlyap.verify(_edited(quadratic[1], tmp_path, _scale("lambda0", 0.9)))
    assert smaller.holds and smaller["start"].margin == pytest.approx(1 - 0.81, abs=1e-6)

    def together(d):
        for key, power in (("A", 1), ("level", 2), ("lambda0", 1)):
            _scale(key, 0.98 ** power)(d)

    assert rotorlyap.verify(_edited(quadratic[1], tmp_path, together)).holds


# ------------------------------------------------------------------------------- bad files


def _bad_files(path: Path, tmp_path: Path) -> dict[str, tuple[Path, str]]:
    text = path.read_text()
    files = {}

    def write(name, content, expect):
        out = tmp_path / f"{name}.json"
        (out.write_bytes if isinstance(content, bytes) else out.write_text)(content)
        files[name] = (out, expect)

    write("truncated", text[: len(text) // 2], "not a complete JSON document")
    write("garbage", b"\x00\xff\xfe garbage \x81", "not a text file")
    write("not json", "certified: yes", "not a complete JSON document")
    write("unknown version", text.replace(f'"version": {VERSION}', '"version": 99', 1), "version 99 is not known")
    write("other format", text.replace(f'"{FORMAT}"', '"something.else"', 1), "not a rotorlyap certificate file")
    data = json.loads(text)
    del data["claims"]["level"]
    write("missing field", json.dumps(data), "claims.level: missing")
    data = json.loads(text)
    data["claims"]["A"] = float("nan")
    write("non-finite", json.dumps(data), "finite numbers only")
    data = json.loads(text)
    data["flight"]["controls"]["collective"] += 0.01
    write("controls differ from the blade", json.dumps(data), "differs from the blade's")
    data = json.loads(text)
    data["search"]["n_sphere"] = 16
    write("weaker search", json.dumps(data), "weaker check")
    data = json.loads(text)
    data["claims"]["period"] = np.pi
    write("half the period", json.dumps(data), "the blade's period 2 pi")
    return files


def test_bad_files_raise_a_certificate_file_error_saying_what_is_wrong(quadratic, tmp_path):
    for name, (path, expect) in _bad_files(quadratic[1], tmp_path).items():
        with pytest.raises(CertificateFileError, match=expect):
            rotorlyap.verify(path)
        assert issubclass(CertificateFileError, ValueError), name


def test_the_command_line_exits_0_1_or_2_and_prints_no_traceback(quadratic, tmp_path, capsys):
    assert main(["verify", str(quadratic[1])]) == 0
    out = capsys.readouterr().out
    assert out.startswith("VERIFIED") and "band" in out
    assert main(["verify", str(_edited(quadratic[1], tmp_path, _scale("level", 1.01)))]) == 1
    assert "FAILS  level" in capsys.readouterr().out
    for name, (path, _) in _bad_files(quadratic[1], tmp_path).items():
        assert main(["verify", str(path)]) == 2, name
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "Traceback" not in err and "bad certificate file" in err, name
    assert main(["verify", str(tmp_path / "no such file.json")]) == 2
    assert "No such file" in capsys.readouterr().err


def test_an_uncertified_result_is_not_saved(quadratic, tmp_path):
    import dataclasses

    cert = dataclasses.replace(quadratic[0], certified=False)
    with pytest.raises(ValueError, match="nothing is certified"):
        cert.save(tmp_path / "none.json")


def test_certify_save_writes_a_file_that_verifies(tmp_path, capsys):
    out = tmp_path / "c.json"
    assert main(["certify", "--mu", "0", "--condition", "none", "--function", "quadratic", "--n-psi", "4",
                 "--save", str(out)]) == 0
    assert json.loads(capsys.readouterr().out)["saved"] == str(out)
    assert rotorlyap.verify(out).holds


def test_a_c81_airfoil_is_embedded_and_a_table_a_file_would_round_is_refused(quadratic, tmp_path):
    """A blade whose section is a C81 file: its table travels inside the certificate and the blade
    read back is the same blade; a table off the printed grid of a C81 file (which its parameter
    file would round) is refused when saving, saying why."""
    import dataclasses

    from rotorlyap.model.c81 import C81Section, read_c81, table_from_section, write_c81
    from rotorlyap.model.parameters import TABLE_I_AIRFOIL

    table = tmp_path / "section.c81"
    write_c81(table_from_section(TABLE_I_AIRFOIL, name="Table I section"), table)
    blade = dataclasses.replace(rotorlyap.BladeParameters.table_i("forward"), airfoil=C81Section(read_c81(table)))
    cert = rotorlyap.certify(blade, 0.0, condition="none", function="quadratic", n_psi=4)
    path = cert.save(tmp_path / "c81.json")
    data = json.loads(path.read_text())
    assert list(data["blade"]["files"]) == ["blade.c81"] and 'airfoil = "blade.c81"' in data["blade"]["parameters_toml"]
    assert read_certificate(path).params == cert.trim.params
    assert rotorlyap.verify(path).holds

    exact = C81Section(table_from_section(TABLE_I_AIRFOIL))  # 6-digit coefficients: a C81 file prints 4
    params = dataclasses.replace(quadratic[0].trim.params, airfoil=exact)
    unsaveable = dataclasses.replace(quadratic[0], trim=dataclasses.replace(quadratic[0].trim, params=params))
    with pytest.raises(ValueError, match="cannot be stored in a certificate file"):
        unsaveable.save(tmp_path / "rounded.json")


def test_a_polynomial_function_is_rebuilt_from_its_description_and_coefficients(quadratic, tmp_path):
    """The polynomial family (degrees 2 to 4; in hover its coefficients are constant): its basis
    rebuilt from family, harmonics and degrees has the stored names, and with the stored
    coefficients it is the same W and W' to the bit (the file's claims are the quadratic
    certificate's, so only the reading is checked here); a description that does not match the
    names is a CertificateFileError. (Harmonics of the azimuth are read back by chapter 10's
    forward-flight files, which hold two.)"""
    import dataclasses

    from rotorlyap.analysis.nonlinear_functions import DesignedFunction, polynomial_basis
    from rotorlyap.methods.scenario import BasisFunction, Design

    cert = quadratic[0]
    fun = cert.lyapunov
    basis = polynomial_basis(fun.blade, fun.steady, scales=cert.scales)
    c = np.random.default_rng(2).normal(size=basis.size)
    bf = BasisFunction(basis, c, fun.f, "polynomial")
    designed = DesignedFunction(fun.blade, fun.steady, "polynomial", Design(bf, 0.1, 0.3, 0.01, True, 1, 10),
                                cert.scales, True, "polynomial")
    path = dataclasses.replace(cert, lyapunov=designed, function="polynomial").save(tmp_path / "poly.json")
    data = json.loads(path.read_text())["function"]
    assert (data["harmonics"], data["degrees"], len(data["names"])) == (0, [2, 3, 4], basis.size) == (0, [2, 3, 4], 203)
    back = read_certificate(path).function
    x = np.random.default_rng(3).normal(size=(32, 6)) * cert.scales * 0.5
    psi = np.linspace(0.0, 6.0, 32)
    assert np.array_equal(back.W(psi, x), bf.W(psi, x)) and np.array_equal(back.dW(psi, x), bf.dW(psi, x))
    with pytest.raises(CertificateFileError, match="function.names"):
        read_certificate(_edited(path, tmp_path, lambda d: d["function"].__setitem__("degrees", [2, 3])))


def test_prove_adds_the_ball_arithmetic_proof_of_a_quadratic_function(quadratic):
    result = rotorlyap.verify(quadratic[1], prove=True)
    assert result.holds and result.checks[-1].name == "proof"
    assert 0 < result["proof"].value <= quadratic[0].bound


# ------------------------------------------------------------------------------- slow


@pytest.mark.slow
def test_a_designed_energy_certificate_round_trips_and_a_coefficient_edit_is_refused(tmp_path):
    """The augmented energy in hover, designed at one start radius (0.5, A = 2: a few seconds, where
    certify's search of the largest takes half a minute) and certified by the engine: saved,
    verified with its own coefficients (bit-equal), the final check finding the engine's worst W';
    one quadratic coefficient raised (and the start radii halved, which keeps the start claim) is
    refused by the band check alone, one azimuth's start radius raised by the start check."""
    from rotorlyap.analysis.certify import Certificate
    from rotorlyap.analysis.nonlinear_functions import designed_function
    from rotorlyap.model.forward_trim import forward_flight_trim

    trim = forward_flight_trim(rotorlyap.BladeParameters.table_i("forward"), 0.0, "none")
    fun = designed_function(rotorlyap.Blade(trim.params, 0.0), trim.steady, "energy", lam_start=0.5, lam_max=0.5,
                            ratios=(4.0,))
    res = rotorlyap.blade_stability(trim.params, 0.0, lyapunov=lambda blade, steady: fun, steady=trim.steady,
                                    n_psi=8)
    assert fun.designed and np.all(res.stable)
    cert = Certificate(certified=True, mu=0.0, condition="none", trim=trim, growth_rate=math.nan, bound=res.A,
                       start_region=float(res.lambda0.min()), scales=fun.scales, result=res, message=res.message,
                       function="energy", lyapunov=fun)
    path = cert.save(tmp_path / "hover_energy.json")
    stored = read_certificate(path)
    assert np.array_equal(stored.function.function.coefficients, cert.lyapunov.function.coefficients)
    assert stored.function.function.basis.names == cert.lyapunov.function.basis.names
    x = np.random.default_rng(1).normal(size=(64, 6)) * cert.scales * 3.0
    psi = np.zeros(64)
    assert np.array_equal(stored.function.W(psi, x), cert.lyapunov.W(psi, x))
    result = rotorlyap.verify(path)
    assert result.holds and result["band"].value == cert.result.band_max_dW
    k = stored.data["function"]["names"].index("theta'^2")

    def edit(d):
        d["function"]["coefficients"][k] += 0.2
        _scale("lambda0", 0.5)(d)

    assert _failing(rotorlyap.verify(_edited(path, tmp_path, edit))) == {"band"}

    def one_ball(d):  # W does not depend on the azimuth in hover: the search is at one, the claim at all
        d["claims"]["lambda0"][5] *= 1.5

    assert "start" in _failing(rotorlyap.verify(_edited(path, tmp_path, one_ball)))
    # the design's effort is recorded for the reader and read back (and told by the command line's
    # JSON); an unknown one is refused by name
    assert stored.data["function"]["design"]["effort"] == "default" == stored.function.effort
    from rotorlyap.cli import certificate_json

    told = certificate_json(cert, {"params": "Table I", "cg": "forward"}, n_psi=8, n_sphere=1024)
    assert (told["design"], told["harmonics"]) == ("default", 0) == (stored.function.effort, stored.function.harmonics)

    def unknown_effort(d):
        d["function"]["design"]["effort"] = "heroic"

    with pytest.raises(CertificateFileError, match="function.design.effort.*'default', 'thorough'"):
        read_certificate(_edited(path, tmp_path, unknown_effort))

    # a hover function said to depend on the azimuth (names and coefficients of one harmonic, which
    # would keep every claim at psi = 0): refused, since the search of an autonomous blade is at one
    # azimuth only
    from rotorlyap.analysis.nonlinear_functions import energy_basis

    def with_harmonic(d):
        d["function"]["harmonics"] = 1
        d["function"]["names"] = ["energy"] + [n for n in energy_basis(stored.function.blade, stored.function.steady,
                                                                        scales=cert.scales).names[1:]] * 3
        d["function"]["coefficients"] = d["function"]["coefficients"] + [0.0] * 42

    with pytest.raises(CertificateFileError, match=r"function.harmonics: harmonics must be 0 where the disturbed blade"):
        read_certificate(_edited(path, tmp_path, with_harmonic))


@pytest.mark.slow
def test_a_forward_flight_certificate_round_trips_and_a_perturbed_table_entry_is_refused(tmp_path):
    """The trimmed helicopter at mu = 0.1, quadratic function: the Hermite table of the periodic
    motion (4096 azimuths) and P on its grid stored and read back bit for bit, verified; one
    tabulated flap angle moved by 1e-3 rad no longer solves the equations."""
    cert = rotorlyap.certify(rotorlyap.BladeParameters.table_i("forward"), 0.1, function="quadratic")
    assert cert.certified
    path = cert.save(tmp_path / "mu01.json")
    stored = read_certificate(path)
    table = cert.lyapunov.steady.xi_function.__self__
    assert np.array_equal(stored.steady.xi_function.__self__.values, table.values)
    assert np.array_equal(stored.function.solution.P_grid, cert.lyapunov.solution.P_grid)
    result = rotorlyap.verify(path)
    assert result.holds and result["band"].value == cert.result.band_max_dW

    def edit(d):
        d["steady_motion"]["values"][100][0] += 1e-3

    assert "steady motion" in _failing(rotorlyap.verify(_edited(path, tmp_path, edit)))


@pytest.mark.slow
def test_a_file_saved_here_verifies_in_a_perturbed_floating_point_environment(quadratic):
    env = dict(os.environ, OPENBLAS_CORETYPE="SandyBridge", OPENBLAS_NUM_THREADS="1",
               NPY_DISABLE_CPU_FEATURES="X86_V4 AVX512_ICL AVX512_SPR",
               PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    run = subprocess.run([sys.executable, "-m", "rotorlyap", "verify", str(quadratic[1])], env=env,
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stdout + run.stderr
    assert run.stdout.startswith("VERIFIED")
