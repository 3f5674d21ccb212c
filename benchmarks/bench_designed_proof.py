"""Time the level-set proofs of the book's designed hover functions (issue 41).

Usage: ``python benchmarks/bench_designed_proof.py [--fraction 0.5] [--case forward neutral backward]``

For each of the book's hover certificate files (book/certificates/hover_*.json), proves the
designed function's level set through the ball of ``fraction`` times the file's start radius
invariant (:func:`rotorlyap.analysis.designed_proof.prove_designed_level`) and prints what is
proved, the boxes and the seconds (one process, warm).
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from rotorlyap.analysis.certificate_file import read_certificate
from rotorlyap.analysis.designed_proof import prove_designed_level

BOOK = Path(__file__).resolve().parents[1] / "book" / "certificates"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--fraction", type=float, default=0.5)
    parser.add_argument("--case", nargs="+", default=["forward", "neutral", "backward"],
                        choices=["forward", "neutral", "backward"])
    args = parser.parse_args()
    for name in args.case:
        stored = read_certificate(BOOK / f"hover_{name}.json")
        lam = float(stored.lambda0.min())
        t0 = time.perf_counter()
        res = prove_designed_level(stored.function, args.fraction * lam, numerical_start=lam)
        dt = time.perf_counter() - t0
        if res.proved:
            print(f"{name}: proved, start radius {res.min_lambda0:.3g} ({res.start_fraction:.3g} of the numerical "
                  f"{lam:.3g}), bound {res.A:.3g}, level {res.level:.4g}, {res.proof.rate_boxes} boxes with W', "
                  f"{dt:.0f} s")
        else:
            print(f"{name}: not proved at {args.fraction:g} of the start radius {lam:.3g}: {res.proof.reason} "
                  f"({dt:.0f} s)")


if __name__ == "__main__":
    main()
