"""Float balls against Arb balls: the blade's proofs on both arithmetics.

Run: ``python benchmarks/bench_balls.py [--flight]``.

For the three Table I hover cases (and, with ``--flight``, the forward-flight case of the proofs
chapter, ``certify(BladeParameters.flight_case('forward'), 0.1)``: minutes with Arb) prints the
proved bound ``A``, the smallest start radius and the wall time of
:func:`rotorlyap.analysis.proof.prove_blade` with ``arithmetic="arb"`` and ``"balls"``.
Single-threaded numerics. Figures, not tests: nothing here fails.
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import time  # noqa: E402


def main() -> None:
    from rotorlyap.analysis.functions import quadratic_function
    from rotorlyap.analysis.proof import prove_blade
    from rotorlyap.model.blade import Blade
    from rotorlyap.model.forward_trim import forward_flight_trim
    from rotorlyap.model.parameters import BladeParameters
    from rotorlyap.model.steady import refine_motion

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--flight", action="store_true", help="also the forward-flight proof (minutes with Arb)")
    args = parser.parse_args()
    cases = [(f"hover {cg}", BladeParameters.table_i(cg), 0.0) for cg in ("forward", "neutral", "backward")]
    if args.flight:
        cases.append(("flight mu=0.1", BladeParameters.flight_case("forward"), 0.1))
    for label, params, mu in cases:
        trim = forward_flight_trim(params, mu)
        blade = Blade(trim.params, mu)
        steady = trim.steady if mu == 0.0 else refine_motion(blade, trim.motion).steady
        fun = quadratic_function(blade, steady)
        for arithmetic in ("arb", "balls"):
            t = time.perf_counter()
            proof = prove_blade(fun, 0.1, arithmetic=arithmetic, method="balls")
            print(f"{label:14s} {arithmetic:5s}: A = {proof.A:.12g}, min lambda0 = {proof.min_lambda0:.12g}, "
                  f"{time.perf_counter() - t:.2f} s", flush=True)


if __name__ == "__main__":
    main()
