"""The command line: ``python -m rotorlyap``.

``python -m rotorlyap analyse --cg forward --mu 0.15``
    one technical-stability analysis of a Table I case, printed as JSON;
``python -m rotorlyap figures --out DIR``
    regenerates the data (CSV) and pictures (PNG) of the paper's Figs 4-8 into ``DIR``.

Bad arguments give a one-line message and exit status 2; a failure of the analysis itself
(for example a trim that does not converge) gives a message and exit status 1.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

import numpy as np

from .conventions import MAX_ADVANCE_RATIO

__all__ = ["main"]

CG_CHOICES = ("forward", "neutral", "backward")


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
            f"--scales must be 6 positive numbers in deg and deg/rad (beta, zeta, theta and their rates), got {text!r}")
    return values


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of ``python -m rotorlyap``."""
    parser = argparse.ArgumentParser(
        prog="python -m rotorlyap",
        description="Technical stability of the Narkiewicz & Lucjanek (1989) rotor blade by "
                    "Liapunov's direct method.",
    )
    sub = parser.add_subparsers(dest="command", required=True, metavar="{analyse,figures}")

    a = sub.add_parser("analyse", help="one stability analysis of a Table I case, printed as JSON",
                       description="Run blade_stability for one Table I case and print the result as JSON.")
    a.add_argument("--cg", choices=CG_CHOICES, default="forward", help="section C.G. position (Table I)")
    a.add_argument("--mu", type=_float_in("--mu", 0.0, MAX_ADVANCE_RATIO), default=0.0,
                   help=f"advance ratio, 0..{MAX_ADVANCE_RATIO:g}")
    a.add_argument("--A", type=_float_in("--A", 0.0, 1e3, open_lo=True), default=None,
                   help="bound of the scaled norm (default: the report's choice, 1)")
    a.add_argument("--scales", type=_scales, default=None,
                   help="6 norm scales a_i in deg and deg/rad, e.g. '2 2 1 2 0.5 5' (the default)")
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
    a.add_argument("--n-psi", type=_int_at_least("--n-psi", 1), default=72, help="azimuths of the grid")
    a.add_argument("--n-sphere", type=_int_at_least("--n-sphere", 0), default=1024,
                   help="quasi-random directions per sphere (strict reading)")

    f = sub.add_parser("figures", help="regenerate the data (CSV) and PNGs of Figs 4-8 into a folder",
                       description="Regenerate the data (CSV) and pictures (PNG) of the paper's Figs 4-8.")
    f.add_argument("--out", type=Path, required=True, help="output folder (created if missing)")
    f.add_argument("--quick", action="store_true", help="coarse grids (seconds, for a smoke test)")
    return parser


def _result_json(res, params, mu: float, args) -> dict:
    deg = 180.0 / math.pi
    r6 = lambda a: [round(float(v), 6) for v in np.asarray(a).ravel()]  # noqa: E731
    return {
        "case": {"cg": args.cg, "mu": mu, "collective_deg": round(float(params.collective) * deg, 4),
                 "steady": args.steady, "lyapunov": args.lyapunov},
        "reading": res.reading,
        "rule": res.rule,
        # the paper's step 6 at one azimuth is not implied by the theorem when anything depends
        # on psi: only the sound rule's strict reading is a (numerical) certificate
        "certificate": res.reading == "strict" and res.rule == "sound",
        "A_requested": res.A_requested,
        "A": round(float(res.A), 6),
        "alpha": round(float(res.alpha), 6),
        "scales_deg": r6(np.degrees(res.scales)),
        "n_stable": int(res.stable.sum()),
        "n_psi": int(res.psi.size),
        "psi_deg": r6(np.degrees(res.psi)),
        "lambda0": r6(res.lambda0),
        "max_dW": r6(res.max_dW),
        "stable": [bool(s) for s in res.stable],
        "message": res.message,
    }


def _analyse(args) -> int:
    from .analysis.functions import quadratic_function
    from .analysis.stability import blade_stability
    from .conventions import PAPER_TEST_DISTURBANCES
    from .model.blade import Blade
    from .model.parameters import BladeParameters
    from .model.steady import periodic_motion, tabulate_motion

    params = BladeParameters.table_i(cg=args.cg)
    params = Blade(params, 0.0).params  # trimmed collective, kept at every mu
    # the periodic motion tabulated once (Hermite, 4096 azimuths): its Fourier series would be
    # summed again for every state of the searches
    steady = (tabulate_motion(periodic_motion(params, args.mu)) if args.steady == "periodic"
              else None)
    lyapunov = quadratic_function if args.lyapunov == "quadratic" else None
    scales = None if args.scales is None else np.radians(args.scales)
    print(f"analysing: cg={args.cg}, mu={args.mu:g}, {args.reading} reading ...", file=sys.stderr, flush=True)
    res = blade_stability(
        params, args.mu, lyapunov=lyapunov, A=args.A, scales=scales, n_psi=args.n_psi,
        steady=steady, n_sphere=args.n_sphere,
        test_disturbances=PAPER_TEST_DISTURBANCES if args.reading == "practical" else None,
        rule=args.rule,
    )
    json.dump(_result_json(res, params, args.mu, args), sys.stdout, indent=2)
    sys.stdout.write("\n")
    return 0


def _figures(args) -> int:
    from .figures.commands import regenerate_figures

    args.out.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()

    def progress(i: int, n: int, label: str) -> None:
        print(f"[{i}/{n}] {label} ({time.perf_counter() - start:.0f} s)", file=sys.stderr, flush=True)

    written = regenerate_figures(args.out, quick=args.quick, progress=progress)
    for path in written:
        print(path)
    return 0


def main(argv: list[str] | None = None) -> int:
    """Entry point; returns the exit status."""
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return _analyse(args) if args.command == "analyse" else _figures(args)
    except (ValueError, RuntimeError) as exc:
        print(f"python -m rotorlyap {args.command}: error: {exc}", file=sys.stderr)
        return 1
    except BrokenPipeError:  # output piped into a program that stopped reading (e.g. head)
        return 0
