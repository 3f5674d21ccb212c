"""The command line: ``rotorlyap`` (installed by ``pip install -e .``) or ``python -m rotorlyap``.

``python -m rotorlyap analyse [--params FILE | --cg forward] --mu 0.15``
    one technical-stability analysis (any function, reading and rule of
    :func:`rotorlyap.analysis.stability.blade_stability`), printed as JSON; ``certified`` is
    true only for a numerical certificate (strict reading, sound rule, every azimuth certified),
    and ``warnings`` name the combinations that cannot certify;
``python -m rotorlyap certify [--params FILE | --cg forward] --mu 0.1``
    :func:`rotorlyap.certify`: the trimmed helicopter, its own steady motion, the quadratic
    function and the sound rule; the certificate per hinge in deg and deg/s, printed as JSON;
``python -m rotorlyap certify ... --save cert.json`` and ``python -m rotorlyap verify cert.json [--prove]``
    the certificate written as a file (:meth:`rotorlyap.Certificate.save`), and checked again from
    nothing but the file (:func:`rotorlyap.verify`): the checks printed, exit status 0 if every
    claim holds, 1 if one fails, 2 for a file that cannot be read as a certificate (a one-line
    message);
``python -m rotorlyap sweep --mu 0:0.3:0.1 --cg forward,backward --set lag_damping=5000,10000 --out t.csv``
    :func:`rotorlyap.analysis.sweep.sweep`: the certificate over a full-factorial grid, one table
    (CSV or JSON), on every core or on a Dask cluster (``--scheduler``), with a progress bar;
``python -m rotorlyap modes [--params FILE] --rotor-speed-ratios 0.8:1.2:0.05 --mu 0:0.2:0.05 --out m.csv --plot m.png``
    the blade's modes: :func:`rotorlyap.analysis.modes.fan_plot` (the hover modes' frequencies, per
    rev and in Hz, and damping at each rotor speed, given as fractions of the blade's own or in rad/s
    with ``--rotor-speeds``; ``--vacuum`` for the fan diagram without air) and
    :func:`rotorlyap.analysis.modes.floquet_modes` (the Floquet modes of the trimmed helicopter's
    periodic motion at each advance ratio); one table, a JSON summary, a figure with the 1/rev to
    4/rev lines;
``python -m rotorlyap simulate [--params FILE] --mu 0.1 --disturb flap=2deg,lag=1deg --revs 10 --certify --out s.csv --plot s.png``
    :func:`rotorlyap.analysis.disturbance.simulate_disturbance`: the nonlinear motion of the trimmed
    blade from a disturbance (angles in deg or rad, rates ``flap_rate=...`` in deg/s or rad/s), the
    hinge angles against revolutions, with ``--certify`` the quadratic certificate's bound per hinge;
``python -m rotorlyap figures --out DIR``
    regenerates the data (CSV) and pictures (PNG) of the paper's Figs 4-8 into ``DIR``.

``--plot FILE.png|FILE.svg`` draws a figure (matplotlib's Agg backend, files only): on ``certify`` the
certified start region and bound per hinge, on ``sweep`` the largest Floquet real part and the
certified flap start region against ``mu``, on ``modes`` and ``simulate`` as above. Tables are CSV
or JSON by the suffix of ``--out``.

A blade is Table I's (``--cg`` chooses its C.G. case, default forward) or read from a parameter
file (``--params FILE``, TOML, :meth:`rotorlyap.BladeParameters.from_file`); with a file,
``--cg`` given explicitly overrides the file's ``cg_position`` by the Table I case's.

Printed numbers carry 4 significant digits (angles in deg, rates in deg/s, the bound and start
radius in units of the scaled norm), except the per-azimuth arrays of ``analyse`` (6 decimals).
Warnings go to stderr as well as into the JSON. The command line runs one BLAS thread unless
``OPENBLAS_NUM_THREADS`` (or ``MKL_NUM_THREADS``) says otherwise: the searches work on tiny arrays,
where more threads only wait for a busy core.

Bad arguments (an unknown hinge or unit in ``--disturb``, a file suffix, a negative ``--revs``...)
give a one-line message and exit status 2; a failure of the analysis itself
(for example a trim that does not converge, a parameter file with a bad value, or a missing
optional dependency) gives a message and exit status 1.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time
from decimal import Decimal, InvalidOperation
from pathlib import Path
from typing import Any, Callable, TextIO

from .progress import listening

# numpy is imported where it is used, after main() has chosen the BLAS threads (_one_blas_thread)

__all__ = ["build_parser", "main"]

CG_CHOICES = ("forward", "neutral", "backward")
CONDITIONS = ("propulsive", "flapping", "none")  # rotorlyap.model.forward_trim.TRIM_TARGETS
FUNCTION_CHOICES = ("auto", "quadratic", "energy", "polynomial")  # rotorlyap.analysis.certify.FUNCTIONS
DESIGN_CHOICES = ("default", "thorough")  # rotorlyap.analysis.nonlinear_functions.DESIGN_EFFORTS
HINGE_SYMBOLS = ("flap", "lag", "pitch")  # rotorlyap.conventions.HINGES: the order of the state
SIGNIFICANT = 4  # digits of a printed number
MAX_LIST = 10_000  # values of one grid axis (a start:stop:step typo should not start a week of work)


# ---------------------------------------------------------------------- argument types


def _float_in(name: str, lo: float, hi: float, *, open_lo: bool = False):
    def parse(text: str) -> float:
        try:
            v = float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{name} must be a number, got {text!r}") from None
        ok = math.isfinite(v) and (v > lo if open_lo else v >= lo) and v <= hi
        if not ok:
            left = "(" if open_lo else "["
            raise argparse.ArgumentTypeError(f"{name} must lie in {left}{lo:g}, {hi:g}], got {text!r}")
        return v
    return parse


def _int_at_least(name: str, lo: int):
    def parse(text: str) -> int:
        try:
            v = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{name} must be an integer, got {text!r}") from None
        if v < lo:
            raise argparse.ArgumentTypeError(f"{name} must be an integer >= {lo}, got {text!r}")
        return v
    return parse


def _scales(text: str) -> list[float]:
    parts = [p for p in text.replace(",", " ").split() if p]
    try:
        values = [float(p) for p in parts]
    except ValueError:
        raise argparse.ArgumentTypeError(f"--scales must be 6 numbers (deg, deg/rad), got {text!r}") from None
    if len(values) != 6 or not all(math.isfinite(v) and v > 0 for v in values):
        raise argparse.ArgumentTypeError(
            f"--scales must be 6 positive numbers in deg and deg/rad (flap, lag, pitch and their rates), got {text!r}")
    return values


def _existing_file(text: str) -> Path:
    path = Path(text)
    if not path.is_file():
        raise argparse.ArgumentTypeError(f"--params: no such file: {text!r}")
    return path


def _number_list(name: str, text: str, *, integer: bool = False) -> list:
    """Numbers ``"a,b,c"`` or ``"start:stop:step"`` (stop included, decimal steps exact:
    ``0:0.3:0.1`` gives 0, 0.1, 0.2, 0.3)."""
    def number(t: str) -> Decimal:
        try:
            d = Decimal(t.strip())
        except InvalidOperation:
            raise argparse.ArgumentTypeError(
                f"{name} must be numbers 'a,b,c' or a range 'start:stop:step', got {text!r}") from None
        if not d.is_finite():
            raise argparse.ArgumentTypeError(f"{name} values must be finite, got {text!r}")
        return d

    if ":" in text:
        parts = text.split(":")
        if len(parts) != 3:
            raise argparse.ArgumentTypeError(f"{name} range must be 'start:stop:step', got {text!r}")
        start, stop, step = (number(p) for p in parts)
        if step <= 0 or stop < start:
            raise argparse.ArgumentTypeError(
                f"{name} range 'start:stop:step' needs step > 0 and stop >= start, got {text!r}")
        count = int((stop - start) / step) + 1
        if count > MAX_LIST:
            raise argparse.ArgumentTypeError(f"{name} range gives {count} values, more than {MAX_LIST}: {text!r}")
        values = [start + k * step for k in range(count)]
    else:
        values = [number(p) for p in text.split(",") if p.strip()]
        if not values:
            raise argparse.ArgumentTypeError(f"{name} needs at least one value, got {text!r}")
    if integer:
        if any(v != v.to_integral_value() for v in values):
            raise argparse.ArgumentTypeError(f"{name} values must be integers, got {text!r}")
        return [int(v) for v in values]
    return [float(v) for v in values]


def _float_list(name: str, lo: float, hi: float, *, open_lo: bool = False):
    def parse(text: str) -> list[float]:
        values = _number_list(name, text)
        for v in values:
            if not ((v > lo if open_lo else v >= lo) and v <= hi):
                left = "(" if open_lo else "["
                raise argparse.ArgumentTypeError(f"{name} values must lie in {left}{lo:g}, {hi:g}], got {text!r}")
        return values
    return parse


def _name_list(name: str, choices: tuple[str, ...]):
    def parse(text: str) -> list[str]:
        values = [p.strip() for p in text.split(",") if p.strip()]
        bad = [v for v in values if v not in choices]
        if not values or bad:
            raise argparse.ArgumentTypeError(
                f"{name} must be a comma-separated list of {', '.join(choices)}, got {text!r}")
        return values
    return parse


def _setting(text: str) -> tuple[str, list]:
    """``NAME=LIST`` of ``--set``: a numeric field of BladeParameters and its values."""
    from .analysis.sweep import grid_value_type, sweep_fields

    name, sep, values = text.partition("=")
    name = name.strip()
    allowed = sweep_fields()
    if not sep or name not in allowed:
        raise argparse.ArgumentTypeError(
            f"--set must be NAME=VALUES with NAME a numeric field of BladeParameters ({', '.join(allowed)}), "
            f"got {text!r}")
    return name, _number_list(f"--set {name}", values, integer=grid_value_type(name) is int)


def _table_path(text: str) -> Path:
    path = Path(text)
    if path.suffix.lower() not in (".csv", ".json"):
        raise argparse.ArgumentTypeError(f"--out must end in .csv or .json (the table's format), got {text!r}")
    return path


def _figure_path(text: str) -> Path:
    path = Path(text)
    if path.suffix.lower() not in (".png", ".svg"):
        raise argparse.ArgumentTypeError(f"--plot must end in .png or .svg (the figure's format), got {text!r}")
    return path


_ANGLE_UNITS = {"deg": math.pi / 180.0, "rad": 1.0}
_RATE_UNITS = {"deg/s": math.pi / 180.0, "rad/s": 1.0}


def _disturbance(text: str) -> dict[str, float]:
    """``--disturb flap=2deg,lag=1deg,pitch_rate=10deg/s``: hinge angles (deg or rad) and rates
    (deg/s or rad/s) -> ``{name: rad or rad/s}`` (:func:`rotorlyap.analysis.disturbance.simulate_disturbance`)."""
    names = HINGE_SYMBOLS + tuple(f"{h}_rate" for h in HINGE_SYMBOLS)
    usage = ("--disturb must be NAME=VALUEUNIT items separated by commas, NAME one of "
             f"{', '.join(names)}, UNIT deg or rad for an angle and deg/s or rad/s for a rate, e.g. "
             "flap=2deg,lag=1deg")
    out: dict[str, float] = {}
    for item in (p.strip() for p in text.split(",")):
        if not item:
            continue
        name, sep, value = (x.strip() for x in item.partition("="))
        if not sep or name not in names:
            raise argparse.ArgumentTypeError(f"{usage}; got {item!r}")
        if name in out:
            raise argparse.ArgumentTypeError(f"--disturb gives {name} twice: {text!r}")
        units = _RATE_UNITS if name.endswith("_rate") else _ANGLE_UNITS
        unit = next((u for u in sorted(units, key=len, reverse=True) if value.endswith(u)), None)
        if unit is None:
            raise argparse.ArgumentTypeError(
                f"--disturb {name} needs a unit, {' or '.join(units)}, after its number (e.g. {name}=2"
                f"{next(iter(units))}); got {value!r}")
        try:
            v = float(value[: -len(unit)])
        except ValueError:
            raise argparse.ArgumentTypeError(f"--disturb {name} must be a number and a unit, got {value!r}") from None
        if not math.isfinite(v):
            raise argparse.ArgumentTypeError(f"--disturb {name} must be finite, got {value!r}")
        out[name] = v * units[unit]
    if not out:
        raise argparse.ArgumentTypeError(f"{usage}; got {text!r}")
    return out


# ---------------------------------------------------------------------- the parser
#
# build_parser() adds one subcommand each with _add_<command>(sub); the options two or more
# commands share are added by the small helpers below (the help texts that differ are passed in).


def _blade_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("--params", type=_existing_file, default=None, metavar="FILE",
                   help="the blade from a parameter file (TOML, BladeParameters.from_file); default: Table I")
    p.add_argument("--cg", choices=CG_CHOICES, default=None,
                   help="section C.G. position, a Table I case (default forward); with --params, given "
                        "explicitly, it overrides the file's cg_position")


def _mu_option(p: argparse.ArgumentParser) -> None:
    """``--mu``: one advance ratio (analyse, certify, simulate)."""
    from .conventions import MAX_ADVANCE_RATIO

    p.add_argument("--mu", type=_float_in("--mu", 0.0, MAX_ADVANCE_RATIO), default=0.0,
                   help=f"advance ratio, 0..{MAX_ADVANCE_RATIO:g}")


def _mu_list_option(p: argparse.ArgumentParser, default: list[float], help: str) -> None:
    """``--mu``: a list of advance ratios (sweep, modes)."""
    from .conventions import MAX_ADVANCE_RATIO

    p.add_argument("--mu", type=_float_list("--mu", 0.0, MAX_ADVANCE_RATIO), default=default, help=help)


def _norm_options(p: argparse.ArgumentParser, bound_help: str) -> None:
    """``--A`` and ``--scales``: the bound of the scaled norm and its scales (analyse, certify)."""
    p.add_argument("--A", type=_float_in("--A", 0.0, 1e3, open_lo=True), default=None, help=bound_help)
    p.add_argument("--scales", type=_scales, default=None,
                   help="6 norm scales a_i in deg and deg/rad, e.g. '2 2 1 2 0.5 5' (the default)")


def _search_options(p: argparse.ArgumentParser, *, n_psi: int = 36, psi_help: str,
                    sphere_help: str = "quasi-random directions per sphere") -> None:
    """``--n-psi`` and ``--n-sphere``: the sizes of the search (analyse, certify, sweep, simulate)."""
    p.add_argument("--n-psi", type=_int_at_least("--n-psi", 1), default=n_psi, help=psi_help)
    p.add_argument("--n-sphere", type=_int_at_least("--n-sphere", 0), default=1024, help=sphere_help)


def _condition_option(p: argparse.ArgumentParser, help: str) -> None:
    """``--condition``: one flight condition (certify, modes, simulate)."""
    p.add_argument("--condition", choices=CONDITIONS, default="propulsive", help=help)


def _function_option(p: argparse.ArgumentParser, default: str, help: str) -> None:
    """``--function``: the Liapunov function (certify, sweep)."""
    p.add_argument("--function", choices=FUNCTION_CHOICES, default=default, help=help)


def _table_option(p: argparse.ArgumentParser, *, required: bool = False) -> None:
    """``--out``: the table, CSV or JSON by its suffix (sweep, modes, simulate)."""
    p.add_argument("--out", type=_table_path, default=None, required=required,
                   help="the table: FILE.csv or FILE.json")


def _plot_option(p: argparse.ArgumentParser, help: str) -> None:
    """``--plot``: the figure, PNG or SVG by its suffix (certify, sweep, modes, simulate)."""
    p.add_argument("--plot", type=_figure_path, default=None, metavar="FILE.png|FILE.svg", help=help)


def _add_analyse(sub) -> None:
    a = sub.add_parser("analyse", help="one stability analysis of a blade, printed as JSON",
                       description="Run blade_stability for one blade and print the result as JSON. "
                                   "'certified' is true only for a numerical certificate: strict reading, "
                                   "sound rule and every azimuth certified.")
    _blade_options(a)
    _mu_option(a)
    _norm_options(a, "bound of the scaled norm (default: the report's choice, 1)")
    a.add_argument("--reading", choices=("strict", "practical"), default="strict",
                   help="strict: whole spheres (a certificate); practical: the 12 signed axes only (an indicator)")
    a.add_argument("--rule", choices=("paper", "sound"), default=None,
                   help="sound (default of the strict reading): the theorem's (h) on the band over "
                        "the whole period, a numerical certificate; paper (default of the practical "
                        "reading): step 6 at each start azimuth, the paper's algorithm")
    a.add_argument("--steady", choices=("hover", "periodic"), default="hover",
                   help="steady motion: the hover equilibrium (the paper) or the true periodic motion")
    a.add_argument("--lyapunov", choices=("energy", "quadratic"), default="energy",
                   help="Liapunov function: the paper's energy, or x^T P x from the periodic Lyapunov equation")
    _search_options(a, n_psi=72, psi_help="azimuths of the grid",
                    sphere_help="quasi-random directions per sphere (strict reading)")


def _add_certify(sub) -> None:
    c = sub.add_parser("certify", help="certify the trimmed blade (rotorlyap.certify), printed as JSON",
                       description="Trim the helicopter, take the blade's own steady motion, a Liapunov "
                                   "function (by default the larger certificate of the quadratic function and "
                                   "the augmented energy) and the sound rule (rotorlyap.certify); print what is "
                                   "certified, per hinge in deg and deg/s, as JSON.")
    _blade_options(c)
    _mu_option(c)
    _condition_option(c, "propulsive: the trimmed helicopter (default); flapping: hover collective, cyclic "
                         "for zero flapping; none: the paper's hover controls")
    _norm_options(c, "requested bound of the scaled norm (default 1; the sound rule reduces it until it holds)")
    _search_options(c, psi_help="azimuths of the grid")
    _function_option(c, "auto", "the Liapunov function: auto (default: the quadratic function and the augmented "
                                "energy, the larger certificate; tens of seconds), quadratic (seconds, the linear "
                                "range), energy (the augmented energy), polynomial")
    c.add_argument("--design", choices=DESIGN_CHOICES, default="default",
                   help="the design program's effort for a designed function: default (tens of seconds in "
                        "forward flight), thorough (more counterexample rounds and bisection steps: larger "
                        "start regions, minutes; how the book's certificate files are made)")
    c.add_argument("--harmonics", type=_int_at_least("--harmonics", 0), default=None, metavar="K",
                   help="in forward flight, the harmonics of the azimuth in a designed function's quadratic "
                        "coefficients (default 1; hover: 0 only)")
    c.add_argument("--verify", action="store_true",
                   help="also prove the certificate's own function by ball arithmetic (rotorlyap.certify("
                        "verify=True)): seconds in hover, minutes in forward flight; adds 'proof' and "
                        "'proved_part' (what is proved, or why nothing is) to the JSON")
    _plot_option(c, "also draw the certified start region and bound per hinge (deg, deg/s)")
    c.add_argument("--save", type=Path, default=None, metavar="FILE.json",
                   help="also write the certificate as a file that 'verify' checks from nothing "
                        "(rotorlyap.Certificate.save; an error if nothing is certified)")


def _add_verify(sub) -> None:
    v = sub.add_parser("verify", help="check a certificate file from nothing (rotorlyap.verify)",
                       description="Rebuild the blade, the steady motion and the function of a certificate file "
                                   "(written by 'certify --save') and check every claim again: the steady "
                                   "motion against the equations, the level facts and condition (h) on the band "
                                   "by the sound rule's final check. Exit status 0 if every claim holds, 1 if one "
                                   "fails, 2 for a file that cannot be read as a certificate.")
    v.add_argument("file", type=Path, metavar="FILE", help="the certificate file (JSON)")
    v.add_argument("--prove", action="store_true",
                   help="also prove a quadratic function's certificate by ball arithmetic (seconds in hover, "
                        "minutes in forward flight; an error, exit status 1, for a designed function)")


def _add_sweep(sub) -> None:
    s = sub.add_parser("sweep", help="certify over a grid (mu, C.G., A, any parameter), one CSV/JSON table",
                       description="Run the certificate (as the certify command) at every point of a "
                                   "full-factorial grid and write one table, a row per point. Lists are "
                                   "'a,b,c' or 'start:stop:step' (stop included). The table's columns: "
                                   "condition, cg (if given), each --set in order, A (if given), mu (the last "
                                   "varies fastest), then the results.")
    s.add_argument("--params", type=_existing_file, default=None, metavar="FILE",
                   help="the base blade from a parameter file (TOML); default: Table I")
    s.add_argument("--cg-base", dest="cg_base", choices=CG_CHOICES, default=None,
                   help="the base blade's C.G. case (Table I; with --params it overrides the file's)")
    _mu_list_option(s, [0.0], "advance ratios, e.g. 0,0.1,0.2 or 0:0.3:0.05 (default 0)")
    s.add_argument("--cg", type=_name_list("--cg", CG_CHOICES), default=None,
                   help="C.G. cases to sweep, e.g. forward,backward")
    s.add_argument("--A", type=_float_list("--A", 0.0, 1e3, open_lo=True), default=None,
                   help="requested bounds of the scaled norm, e.g. 0.5,1")
    s.add_argument("--set", type=_setting, action="append", default=[], metavar="NAME=VALUES",
                   help="sweep a numeric field of BladeParameters (SI units), e.g. lag_damping=5000,10000; "
                        "repeat for more fields")
    s.add_argument("--condition", type=_name_list("--condition", CONDITIONS), default=["propulsive"],
                   help="flight conditions, e.g. propulsive,none (default propulsive)")
    _table_option(s, required=True)
    _function_option(s, "quadratic", "the Liapunov function of every point: quadratic (default: seconds a point), "
                                     "auto (the larger of the quadratic function and the augmented energy: tens of "
                                     "seconds a point), energy, polynomial")
    s.add_argument("--workers", type=_int_at_least("--workers", 1), default=None,
                   help="processes (or local Dask workers); default every core; 1 runs in this process")
    s.add_argument("--scheduler", default=None, metavar="local|ADDRESS",
                   help="run on Dask: 'local' (a local cluster) or a scheduler address tcp://host:port; "
                        'needs pip install "dask[distributed]"')
    _search_options(s, psi_help="azimuths of each certificate")
    _plot_option(s, "also draw the sweep: the largest Floquet real part and the certified flap start "
                    "region against mu (or the last column that varies), a line per value of the others")


def _add_modes(sub) -> None:
    m = sub.add_parser("modes", help="the blade's modes: a fan diagram against rotor speed and Floquet modes "
                                     "against mu, a table (CSV/JSON) and a figure",
                       description="The hover modes (frequency in /rev and Hz, damping ratio) at each rotor "
                                   "speed, the blade trimmed to hover at each speed (rotorlyap.fan_plot), and the "
                                   "Floquet modes of the trimmed helicopter's periodic motion at each advance "
                                   "ratio (rotorlyap.floquet_modes). Rotor speeds are fractions of the blade's "
                                   "own (--rotor-speed-ratios, default 0.8:1.2:0.05) or in rad/s "
                                   "(--rotor-speeds). One table, a row per mode: kind (hover, vacuum or "
                                   "floquet), rotor_speed_rad_s, rotor_speed_ratio, mu, mode, hinge, "
                                   "frequency_per_rev, frequency_hz, growth_rate_per_rev, damping_ratio, error. "
                                   "Prints a JSON summary.")
    _blade_options(m)
    speeds = m.add_mutually_exclusive_group()
    speeds.add_argument("--rotor-speed-ratios", type=_float_list("--rotor-speed-ratios", 0.0, 3.0, open_lo=True),
                        default=None, metavar="LIST",
                        help="rotor speeds as fractions of the blade's rotor_speed, e.g. 0.8:1.2:0.05 (the default)")
    speeds.add_argument("--rotor-speeds", type=_float_list("--rotor-speeds", 0.0, 1e4, open_lo=True), default=None,
                        metavar="LIST", help="rotor speeds in rad/s, e.g. 20,25,30 or 20:32:2")
    m.add_argument("--vacuum", action="store_true",
                   help="the fan diagram in vacuum (no air: springs, centrifugal and inertial forces) at the "
                        "nominal hover collective, instead of the hover trim at each speed")
    _mu_list_option(m, [0.0, 0.05, 0.1, 0.15, 0.2],
                    "advance ratios of the Floquet modes, e.g. 0:0.3:0.05 (default 0:0.2:0.05); the modes "
                    "are followed from hover on steps of at most 0.025")
    m.add_argument("--no-floquet", action="store_true", help="the fan diagram only")
    _condition_option(m, "the trim of the Floquet modes (as certify; default propulsive)")
    _table_option(m)
    _plot_option(m, "the figure: fan diagram (Hz against rad/s, 1/rev to 4/rev lines) and damping; "
                    "Floquet frequency and growth rate against mu")


def _add_simulate(sub) -> None:
    d = sub.add_parser("simulate", help="the nonlinear motion of the trimmed blade after a disturbance, a table "
                                        "and a figure",
                       description="Trim the helicopter at --mu, disturb the blade's steady motion at azimuth 0 "
                                   "and integrate the nonlinear equations (rotorlyap.simulate_disturbance). The "
                                   "table has a row per output time: revolution, time_s, per hinge <hinge>_deg, "
                                   "<hinge>_steady_deg, <hinge>_deviation_deg, scaled_norm (and <hinge>_bound_deg "
                                   "with --certify). Prints a JSON summary.")
    _blade_options(d)
    _mu_option(d)
    d.add_argument("--disturb", type=_disturbance, required=True, metavar="NAME=VALUEUNIT,...",
                   help="the disturbance at azimuth 0: flap, lag, pitch in deg or rad, flap_rate, lag_rate, "
                        "pitch_rate in deg/s or rad/s, e.g. flap=2deg,lag=1deg,pitch=0.5deg")
    d.add_argument("--revs", type=_float_in("--revs", 0.0, 1e4, open_lo=True), default=10.0,
                   help="length of the motion, revolutions (default 10)")
    _condition_option(d, "the trim (as certify; default propulsive)")
    d.add_argument("--certify", action="store_true",
                   help="also certify the trim with the quadratic function (seconds in hover, tens of seconds in "
                        "forward flight) and draw its bound per hinge about the steady motion")
    _search_options(d, psi_help="azimuths of the certificate",
                    sphere_help="quasi-random directions per sphere of the certificate")
    _table_option(d)
    _plot_option(d, "the figure: the hinge angles against revolutions, the steady motion and the bound")


def _add_figures(sub) -> None:
    f = sub.add_parser("figures", help="regenerate the data (CSV) and PNGs of Figs 4-8 into a folder",
                       description="Regenerate the data (CSV) and pictures (PNG) of the paper's Figs 4-8.")
    f.add_argument("--out", type=Path, required=True, help="output folder (created if missing)")
    f.add_argument("--quick", action="store_true", help="coarse grids (seconds, for a smoke test)")


def build_parser(prog: str = "python -m rotorlyap") -> argparse.ArgumentParser:
    """The argument parser of ``python -m rotorlyap`` (and of the ``rotorlyap`` command, ``prog``)."""
    parser = argparse.ArgumentParser(
        prog=prog,
        description="Technical stability of the Narkiewicz & Lucjanek (1989) rotor blade by "
                    "Liapunov's direct method.",
    )
    sub = parser.add_subparsers(dest="command", required=True, metavar="{" + ",".join(_COMMANDS) + "}")
    for add in (_add_analyse, _add_certify, _add_verify, _add_sweep, _add_modes, _add_simulate, _add_figures):
        add(sub)
    return parser


# ---------------------------------------------------------------------- shared helpers


def _sig(value: float, digits: int = SIGNIFICANT) -> float:
    """``value`` rounded to ``digits`` significant digits (a printed number without round-off)."""
    v = float(value)
    if v == 0.0 or not math.isfinite(v):
        return 0.0 if v == 0.0 else v
    return float(f"{v:.{digits - 1}e}")


def _blade(params_file: Path | None, cg: str | None):
    """The blade of ``--params``/``--cg`` and a description of it for the JSON's ``case``."""
    from dataclasses import replace

    from .model.parameters import CG_POSITIONS, BladeParameters

    if params_file is None:
        name = cg or "forward"
        return BladeParameters.table_i(cg=name), {"params": "Table I", "cg": name, "cg_position": CG_POSITIONS[name]}
    import warnings as _warnings

    from .errors import TemplateValuesWarning

    with _warnings.catch_warnings(record=True) as caught:
        _warnings.simplefilter("always", TemplateValuesWarning)
        params = BladeParameters.from_file(params_file)
    # the file's fields left to the template: one line on stderr, like the other warnings
    _warn([str(w.message) for w in caught if issubclass(w.category, TemplateValuesWarning)])
    if cg is not None:
        params = replace(params, cg_position=CG_POSITIONS[cg])
    cg_position = params.cg_position
    if isinstance(cg_position, (int, float)):
        # the Table I case the file's C.G. is, if it is one
        cg = cg or next((k for k, v in CG_POSITIONS.items() if v == cg_position), None)
        shown = _sig(cg_position)
    else:
        shown = getattr(cg_position, "__name__", "a spanwise profile")
    return params, {"params": str(params_file), "cg": cg, "cg_position": shown}


def _per_hinge(radius, scales, omega: float) -> dict:
    """``{flap|lag|pitch: {"deg", "deg_per_s"}}``: a radius of the scaled norm (or one per state
    component, (6,)) along each hinge angle (scale a_i, rad) and rate (a_(i+3), rad/rad of azimuth,
    times Omega rad/s)."""
    import numpy as np

    a = np.degrees(np.asarray(scales, dtype=float)) * np.asarray(radius, dtype=float)
    return {h: {"deg": _sig(a[i]), "deg_per_s": _sig(a[i + 3] * omega)} for i, h in enumerate(HINGE_SYMBOLS)}


def _warn(warnings: list[str]) -> None:
    for w in warnings:
        print(f"warning: {w}", file=sys.stderr, flush=True)


def _dump(data: dict) -> None:
    json.dump(data, sys.stdout, indent=2)
    sys.stdout.write("\n")


# ---------------------------------------------------------------------- analyse


def analyse_warnings(reading: str, rule: str, lyapunov: str, steady: str, mu: float) -> list[str]:
    """The warnings of ``analyse`` for combinations that cannot certify technical stability.

    Parameters
    ----------
    reading, rule, lyapunov, steady : str
        The options (``rule`` as used: ``"sound"`` or ``"paper"``).
    mu : float
        Advance ratio, -.

    Returns
    -------
    list of str
        One sentence each; empty for a combination that can certify.
    """
    out = []
    if reading == "practical":
        out.append("--reading practical examines W and W' along the 12 signed hinge axes only: an indicator, "
                   "not a certificate (--reading strict, the default, searches whole spheres)")
    elif rule == "paper":  # the practical reading's own rule: its warning says enough
        out.append("--rule paper (step 6 at each start azimuth, the paper's algorithm) is not implied by the "
                   "theorem when anything depends on the azimuth: not a certificate (--rule sound checks "
                   "condition (h) over the whole period)")
    if lyapunov == "quadratic" and steady == "hover" and mu > 0.0:
        out.append(f"--lyapunov quadratic about --steady hover at mu = {mu:g}: the hover equilibrium is not the "
                   "blade's steady motion in forward flight, so nothing can be certified; use --steady periodic, "
                   "or the certify command (the trimmed helicopter and its own periodic motion)")
    return out


def _kind(reading: str, rule: str) -> str:
    """What a run of this reading and rule can give."""
    if reading == "practical":
        return "practical reading (the 12 signed axes): an indicator, never a certificate"
    if rule == "paper":
        return "strict reading, paper rule (the paper's algorithm): never a certificate"
    return "strict reading, sound rule: a numerical certificate where certified"


def _result_json(res, params, case: dict, args, warnings: list[str]) -> dict:
    import numpy as np

    r6 = lambda a: [round(float(v), 6) for v in np.asarray(a).ravel()]  # noqa: E731
    lam_min = float(np.min(res.lambda0)) if res.lambda0.size else 0.0
    certified = bool(res.reading == "strict" and res.rule == "sound" and np.all(res.stable))
    return {
        "case": {**case, "mu": args.mu, "collective_deg": _sig(math.degrees(params.collective)),
                 "steady": args.steady, "lyapunov": args.lyapunov},
        # a numerical certificate only: the paper's step 6 at one azimuth is not implied by the
        # theorem when anything depends on psi, and the practical reading samples 12 directions
        "certified": certified,
        "kind": _kind(res.reading, res.rule),
        "reading": res.reading,
        "rule": res.rule,
        "warnings": warnings,
        "A_requested": res.A_requested,
        "A": round(float(res.A), 6),
        "alpha": round(float(res.alpha), 6),
        "scales_deg": r6(np.degrees(res.scales)),
        "n_stable": int(res.stable.sum()),
        "n_psi": int(res.psi.size),
        "psi_deg": r6(np.degrees(res.psi)),
        "lambda0_scaled_norm": r6(res.lambda0),
        "lambda0_min_scaled_norm": _sig(lam_min),
        "lambda0_per_hinge": _per_hinge(lam_min, res.scales, params.rotor_speed),
        "max_dW": r6(res.max_dW),
        "stable": [bool(s) for s in res.stable],
        "message": res.message,
    }


def _analyse(args) -> int:
    import numpy as np

    from .analysis.functions import quadratic_function
    from .analysis.stability import blade_stability
    from .conventions import PAPER_TEST_DISTURBANCES
    from .model.blade import Blade
    from .model.steady import periodic_motion, tabulate_motion

    params, case = _blade(args.params, args.cg)
    rule = args.rule or ("sound" if args.reading == "strict" else "paper")
    warnings = analyse_warnings(args.reading, rule, args.lyapunov, args.steady, args.mu)
    _warn(warnings)
    params = Blade(params, 0.0).params  # trimmed collective, kept at every mu
    # the periodic motion tabulated once (Hermite, 4096 azimuths): its Fourier series would be
    # summed again for every state of the searches
    steady = (tabulate_motion(periodic_motion(params, args.mu)) if args.steady == "periodic"
              else None)
    lyapunov = quadratic_function if args.lyapunov == "quadratic" else None
    scales = None if args.scales is None else np.radians(args.scales)
    print(f"analysing: {case['params']}, cg={case['cg']}, mu={args.mu:g}, {args.reading} reading ...",
          file=sys.stderr, flush=True)
    res = blade_stability(
        params, args.mu, lyapunov=lyapunov, A=args.A, scales=scales, n_psi=args.n_psi,
        steady=steady, n_sphere=args.n_sphere,
        test_disturbances=PAPER_TEST_DISTURBANCES if args.reading == "practical" else None,
        rule=args.rule,
    )
    _dump(_result_json(res, params, case, args, warnings))
    return 0


# ---------------------------------------------------------------------- certify


def certificate_json(cert, case: dict, *, n_psi: int, n_sphere: int) -> dict:
    """The JSON object of the ``certify`` command: a :class:`rotorlyap.Certificate`, 4 significant digits.

    Parameters
    ----------
    cert : Certificate
    case : dict
        What was certified (the blade, the C.G.), copied into ``case``.
    n_psi, n_sphere : int
        The search's sizes, recorded.

    Returns
    -------
    dict
        ``certified``; ``bound`` and ``start_region`` (scaled norm); ``start_region_per_hinge``
        and ``bound_per_hinge`` (``{flap|lag|pitch: {"deg", "deg_per_s"}}``);
        ``start_set_per_hinge`` where certified (how far the certified start set
        ``{||x|| < A, W < alpha}`` reaches along each hinge angle and rate alone, at the worst
        start azimuth);
        ``growth_rate_per_rev``; ``trim`` (controls and shaft tilt in deg, ``CT_over_sigma``);
        ``message`` (which says "numerical certificate" where one was given); with ``verify=True``
        ``proof``: ``proved``, ``bound``, ``level``, ``start_region`` (scaled norm) and per hinge,
        ``n_intervals``, ``message`` (where a prover took the function), and ``proved_part``:
        ``function``, ``proved``, ``method``, ``bound``, ``start_region``, ``bound_fraction``,
        ``start_fraction`` (of the numerical certificate; null where nothing was certified) and ``not_proved`` (why, where nothing is).
    """
    import numpy as np

    from .analysis.certificate_file import FAMILY_WORDS
    from .analysis.nonlinear_functions import FAMILIES

    p = cert.trim.params
    collective, cyc_c, cyc_s = cert.trim.controls_deg
    omega = p.rotor_speed
    function = FAMILY_WORDS[cert.function] + (" (designed)" if cert.function in FAMILIES else "")
    return {
        "case": {**case, "mu": cert.mu, "condition": cert.condition},
        "certified": bool(cert.certified),
        "kind": f"strict reading, sound rule, {function} about the trim's steady "
                "motion: a numerical certificate where certified",
        "function": cert.function,
        **({"design": cert.lyapunov.effort, "harmonics": cert.lyapunov.harmonics}
           if cert.function in FAMILIES and cert.lyapunov is not None else {}),
        "candidates": [{"function": k.function, "certified": bool(k.certified), "bound": _sig(k.bound),
                        "start_region": _sig(k.start_region)} for k in cert.candidates],
        "bound": _sig(cert.bound),
        "start_region": _sig(cert.start_region),
        "start_region_per_hinge": _per_hinge(cert.start_region, cert.scales, omega),
        **({} if cert.start_set is None else {
            "start_set_per_hinge": _per_hinge(cert.start_set.axis_reach, cert.scales, omega)}),
        "bound_per_hinge": _per_hinge(cert.bound, cert.scales, omega),
        "growth_rate_per_rev": _sig(cert.growth_rate),
        "trim": {"collective_deg": _sig(collective), "cyclic_cos_deg": _sig(cyc_c), "cyclic_sin_deg": _sig(cyc_s),
                 "shaft_tilt_deg": _sig(math.degrees(cert.trim.shaft_tilt)),
                 "CT_over_sigma": _sig(cert.trim.thrust_coefficient / p.solidity)},
        "scales_deg": [_sig(v) for v in np.degrees(cert.scales)],
        "n_psi": n_psi,
        "n_sphere": n_sphere,
        "message": cert.message,
        **({} if cert.proof is None else {"proof": {
            "proved": bool(cert.proof.proved),
            "kind": "proved by ball arithmetic for the model in exact arithmetic (rotorlyap.methods.proof)",
            "bound": _sig(cert.proof.A),
            "level": _sig(cert.proof.level),
            "start_region": _sig(cert.proof.min_lambda0),
            "start_region_per_hinge": _per_hinge(cert.proof.min_lambda0, cert.scales, omega),
            "bound_per_hinge": _per_hinge(cert.proof.A, cert.scales, omega),
            "n_intervals": int(cert.proof.n_intervals),
            "message": cert.proof.message}}),
        **({} if cert.proved_part is None else {"proved_part": {
            "function": cert.proved_part.function,
            "proved": bool(cert.proved_part.proved),
            "method": cert.proved_part.method,
            "bound": _sig(cert.proved_part.bound),
            "start_region": _sig(cert.proved_part.start_region),
            "bound_fraction": _sig(cert.proved_part.bound_fraction) if math.isfinite(cert.proved_part.bound_fraction) else None,
            "start_fraction": _sig(cert.proved_part.start_fraction) if math.isfinite(cert.proved_part.start_fraction) else None,
            "not_proved": cert.proved_part.not_proved}}),
    }


def _certify(args) -> int:
    import numpy as np

    from .analysis.certify import certify

    function = args.function
    params, case = _blade(args.params, args.cg)
    scales = None if args.scales is None else np.radians(args.scales)
    print(f"certifying: {case['params']}, cg={case['cg']}, mu={args.mu:g}, {args.condition} ...",
          file=sys.stderr, flush=True)
    with listening(_progress_listener()):
        cert = certify(params, args.mu, condition=args.condition, function=function, A=args.A, scales=scales,
                       n_psi=args.n_psi, n_sphere=args.n_sphere, verify=args.verify, design=args.design,
                       harmonics=args.harmonics)
    data = certificate_json(cert, case, n_psi=args.n_psi, n_sphere=args.n_sphere)
    if args.plot is not None:
        from .chapters.blade_commands import plot_certificate

        data["plot"] = str(_save(plot_certificate(cert), args.plot))
    if args.save is not None:
        data["saved"] = str(cert.save(args.save))
    _dump(data)
    return 0


def _verify(args) -> int:
    from .analysis.certificate_file import verify
    from .errors import CertificateFileError

    try:
        result = verify(args.file, prove=args.prove)
    except (CertificateFileError, OSError) as exc:
        print(f"rotorlyap verify: bad certificate file: {exc}", file=sys.stderr)
        return 2
    print(result.summary())
    return 0 if result.holds else 1


def _progress_listener():
    """What the long commands tell on standard error while they work (:mod:`rotorlyap.progress`): a
    progress bar on a terminal, one line per stage otherwise (a log); never on standard output."""
    from .progress import Bar, Lines

    return Bar(sys.stderr) if sys.stderr.isatty() else Lines(sys.stderr, prefix="  ")


# ---------------------------------------------------------------------- sweep


def progress_bar(stream: TextIO = sys.stderr, width: int = 30) -> Callable[[int, int], None]:
    """A ``progress(done, total)`` hook for the sweep. On a terminal, a ``tqdm`` bar (the
    maintained library :class:`rotorlyap.progress.Bar` draws the stages with); off a terminal (a
    log file), a line ``[#####     ] 12/40  35 s`` every 5 %, which a log keeps readable where a
    redrawn bar would leave carriage returns."""
    if stream.isatty():
        from tqdm import tqdm

        bar = []

        def tick(done: int, total: int) -> None:
            if not bar:
                bar.append(tqdm(total=total, desc="points", file=stream, dynamic_ncols=True))
            bar[0].n = done
            bar[0].refresh()
            if done >= total:
                bar[0].close()
        return tick
    start = time.perf_counter()
    last = [-1]

    def draw(done: int, total: int) -> None:
        step = 20 * done // max(total, 1)
        if step == last[0] and done < total:
            return
        last[0] = step
        filled = width * done // max(total, 1)
        stream.write(f"[{'#' * filled}{' ' * (width - filled)}] {done}/{total}  {time.perf_counter() - start:.0f} s\n")
        stream.flush()
    return draw


def sweep_grid(args) -> dict[str, list]:
    """The grid of the ``sweep`` command's options, in the table's column order: condition, cg, each
    ``--set``, A, mu."""
    grid: dict[str, list] = {"condition": args.condition}
    if args.cg is not None:
        grid["cg"] = args.cg
    for name, values in args.set:
        if name in grid:
            raise ValueError(f"--set {name} is given twice: give all its values in one --set {name}=a,b,c")
        if name == "cg_position" and args.cg is not None:
            raise ValueError("--cg (Table I cases) and --set cg_position (fractions of chord) cannot be swept together")
        grid[name] = values
    if args.A is not None:
        grid["A"] = args.A
    grid["mu"] = args.mu
    return grid


def _sweep(args) -> int:
    from .analysis.sweep import sweep, worker_count

    params, case = _blade(args.params, args.cg_base)
    grid = sweep_grid(args)
    n = math.prod(len(v) for v in grid.values())
    if args.scheduler:
        where = f"the Dask scheduler {args.scheduler}"
    elif args.workers == 1 or n == 1:
        where = "this process"
    else:
        where = f"{worker_count(args.workers, n)} processes"
    print(f"sweeping: {case['params']}, {n} point{'s' if n != 1 else ''} on {where} ...", file=sys.stderr, flush=True)
    result = sweep(params, grid, n_psi=args.n_psi, workers=args.workers, scheduler=args.scheduler,
                   function=args.function, progress=progress_bar(sys.stderr), n_sphere=args.n_sphere)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    path = result.write(args.out)
    errors = sum(1 for e in result.column("error") if e)
    print(path)
    if args.plot is not None:
        from .chapters.blade_commands import plot_sweep_table

        print(_save(plot_sweep_table(result), args.plot))
    print(f"certified {result.n_certified} of {len(result)} points" + (f" ({errors} failed: see the error column)"
                                                                         if errors else ""))
    return 0


# ---------------------------------------------------------------------- modes and simulate


def _save(fig, path: Path) -> Path:
    """Save a figure (PNG or SVG, by the suffix) where asked, the folder created."""
    from .chapters.blade_commands import save_figure

    path.parent.mkdir(parents=True, exist_ok=True)
    return save_figure(fig, path)


def _write(rows: list[dict], path: Path) -> Path:
    from .chapters.blade_commands import write_table

    path.parent.mkdir(parents=True, exist_ok=True)
    return write_table(rows, path)


def _modes(args) -> int:
    from .analysis.modes import fan_plot, floquet_modes

    params, case = _blade(args.params, args.cg)
    if args.rotor_speeds is not None:
        speeds = sorted(set(args.rotor_speeds))
    else:
        ratios = args.rotor_speed_ratios or _number_list("--rotor-speed-ratios", "0.8:1.2:0.05")
        speeds = [r * params.rotor_speed for r in sorted(set(ratios))]
    mu = sorted(set(args.mu))
    print(f"modes: {case['params']}, cg={case['cg']}, {len(speeds)} rotor speeds"
          + ("" if args.no_floquet else f", {len(mu)} advance ratios ({args.condition})") + " ...",
          file=sys.stderr, flush=True)
    fan = fan_plot(params, speeds, air=not args.vacuum)
    floquet = None if args.no_floquet else floquet_modes(params, mu, condition=args.condition)
    lost = [f"rotor speed {w:.4g} rad/s: {m}" for w, m in zip(fan.rotor_speed, fan.messages) if m]
    if floquet is not None:
        lost += [f"mu = {m:g}: {msg}" for m, msg in zip(floquet.mu, floquet.messages) if msg]
    _warn(lost)
    if not fan.found.any() and (floquet is None or not floquet.found.any()):
        raise RuntimeError("no modes found at any rotor speed or advance ratio (see the warnings)")
    rows = fan.export() + ([] if floquet is None else floquet.export())
    data: dict[str, Any] = {"case": {**case, "rotor_speed_rad_s": _sig(params.rotor_speed),
                                     "condition": None if floquet is None else args.condition},
                            "units": "frequency per rev and Hz, growth rate per rev, damping ratio -"}
    nominal = [i for i, w in enumerate(fan.rotor_speed) if math.isclose(w, params.rotor_speed, rel_tol=1e-9)]
    if nominal and fan.found[nominal[0]]:
        i = nominal[0]
        data["hover_modes"] = [{"mode": n, "frequency_per_rev": _sig(m.frequency),
                                "frequency_hz": _sig(m.frequency * params.rotor_speed / (2 * math.pi)),
                                "growth_rate_per_rev": _sig(m.growth_rate),
                                "damping_ratio": _sig(m.damping_ratio)} for n, m in zip(fan.names(i), fan.modes[i])]
    if floquet is not None:
        data["floquet_stable"] = {f"{m:g}": bool(ok) for m, ok in zip(floquet.mu, floquet.stable)}
    if args.out is None:
        data["rows"] = [{k: (_sig(v) if isinstance(v, float) and math.isfinite(v) else
                             None if isinstance(v, float) else v) for k, v in r.items()} for r in rows]
    else:
        data["table"] = str(_write(rows, args.out))
    if args.plot is not None:
        from .chapters.blade_commands import plot_modes

        data["plot"] = str(_save(plot_modes(fan, floquet), args.plot))
    _dump(data)
    return 0


def _simulate(args) -> int:
    from .analysis.disturbance import simulate_disturbance

    params, case = _blade(args.params, args.cg)
    cert = None
    if args.certify:
        from .analysis.certify import certify

        print(f"certifying: {case['params']}, cg={case['cg']}, mu={args.mu:g}, {args.condition} (quadratic) ...",
              file=sys.stderr, flush=True)
        cert = certify(params, args.mu, condition=args.condition, function="quadratic", n_psi=args.n_psi,
                       n_sphere=args.n_sphere)
    print(f"simulating: {case['params']}, cg={case['cg']}, mu={args.mu:g}, {args.revs:g} revolutions ...",
          file=sys.stderr, flush=True)
    motion = simulate_disturbance(params, args.mu, args.disturb, args.revs, condition=args.condition,
                                  certificate=cert)
    dev = abs(motion.deviation_deg)
    names = HINGE_SYMBOLS + tuple(f"{h}_rate" for h in HINGE_SYMBOLS)
    data: dict[str, Any] = {
        "case": {**case, "mu": motion.mu, "condition": motion.condition},
        "disturbance": {n: {("deg" if i < 3 else "deg_per_s"): _sig(v)}
                        for i, (n, v) in enumerate(zip(names, motion.disturbance)) if v != 0.0},
        "start_scaled_norm": _sig(motion.start_norm),
        "revolutions": _sig(motion.revolutions[-1]),
        "escaped": motion.escaped,
        "largest_deviation_deg": {h: _sig(dev[:, i].max()) for i, h in enumerate(HINGE_SYMBOLS)},
        "final_deviation_deg": {h: _sig(dev[-1, i]) for i, h in enumerate(HINGE_SYMBOLS)},
    }
    if cert is not None:
        data["certified"] = bool(cert.certified)
        data["bound_deg"] = (None if motion.bound_deg is None else
                             {h: _sig(motion.bound_deg[i]) for i, h in enumerate(HINGE_SYMBOLS)})
        data["inside_start_region"] = motion.inside_start_region
    if args.out is not None:
        data["table"] = str(_write(motion.export(), args.out))
    if args.plot is not None:
        from .chapters.blade_commands import plot_disturbed_motion

        data["plot"] = str(_save(plot_disturbed_motion(motion), args.plot))
    _dump(data)
    return 0


# ---------------------------------------------------------------------- figures


def _figures(args) -> int:
    from .chapters.commands import regenerate_figures

    args.out.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()

    def progress(i: int, n: int, label: str) -> None:
        print(f"[{i}/{n}] {label} ({time.perf_counter() - start:.0f} s)", file=sys.stderr, flush=True)

    written = regenerate_figures(args.out, quick=args.quick, progress=progress)
    for path in written:
        print(path)
    return 0


_COMMANDS: dict[str, Callable[[Any], int]] = {"analyse": _analyse, "certify": _certify, "verify": _verify,
                                              "sweep": _sweep, "modes": _modes, "simulate": _simulate,
                                              "figures": _figures}

#: Commands that draw with matplotlib: the Agg backend (files only, no display) is chosen first.
_DRAWING = ("modes", "simulate", "figures")


def _one_blas_thread() -> None:
    """One BLAS thread unless the environment says otherwise, set before numpy is first imported
    (afterwards it has no effect on this process). The searches call BLAS on tiny arrays
    (L-BFGS-B on 6 unknowns, 6 x 6 products), where OpenBLAS's threads give nothing and wait for a
    busy core: on two cores ``certify --n-psi 6 --n-sphere 64`` took 3.7 s with two threads and
    3.4 s with one when idle, 12.6 s and 8.0 s with the other core busy. The worker processes of
    ``sweep`` run one thread each anyway, and so the in-process route gives their numbers."""
    if "numpy" not in sys.modules:
        for name in ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
            os.environ.setdefault(name, "1")


def main(argv: list[str] | None = None) -> int:
    """Entry point of ``python -m rotorlyap`` and of the ``rotorlyap`` command; returns the exit status
    (bad arguments exit at once with status 2, through ``argparse``)."""
    _one_blas_thread()
    prog = "rotorlyap" if Path(sys.argv[0]).name == "rotorlyap" else "python -m rotorlyap"
    parser = build_parser(prog)
    args = parser.parse_args(argv)
    if args.command in _DRAWING or getattr(args, "plot", None) is not None:
        import matplotlib

        matplotlib.use("Agg")
    try:
        return _COMMANDS[args.command](args)
    except BrokenPipeError:  # output piped into a program that stopped reading (e.g. head)
        return 0
    except (ValueError, TypeError, RuntimeError, ImportError, OSError) as exc:
        # bad values (a parameter file, a grid), a trim that does not converge, a missing optional
        # dependency, a table that cannot be written
        print(f"{prog} {args.command}: error: {exc}", file=sys.stderr)
        return 1
