"""Make the certificate files the book ships and verifies (README, "Certificates as files").

Usage: python tools/make_certificates.py [MU ...]   (default: 0.1 0.2 0.25)

For each advance ratio, the default ``rotorlyap.certify`` of the trimmed helicopter (the Table I
blade in the forward-flight model, forward C.G.: ``BladeParameters.flight_case("forward")``) is
made about the periodic motion refined by shooting (``refine=True``: a table that solves the
equations to round-off, as ``rotorlyap.verify`` checks) and saved as
``book/certificates/forward_mu<100 mu>.json``. Its design (the augmented energy
in forward flight) takes minutes and its start radius depends on the last bits of the
floating-point environment, so it is made once, here, and committed; chapter 11 and the tests
verify each file from nothing (``rotorlyap.verify``) in every run, on any machine. Run it in the
ordinary environment; the progress of each design goes to standard error.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

from rotorlyap import BladeParameters, certify
from rotorlyap.progress import Lines, listening

FOLDER = Path(__file__).resolve().parents[1] / "book" / "certificates"


def path_for(mu: float) -> Path:
    """The file of the certificate at ``mu``: ``forward_mu010.json`` for 0.1."""
    return FOLDER / f"forward_mu{round(100 * mu):03d}.json"


def main(argv: list[str]) -> int:
    mus = [float(v) for v in argv] or [0.1, 0.2, 0.25]
    FOLDER.mkdir(parents=True, exist_ok=True)
    for mu in mus:
        start = time.perf_counter()
        with listening(Lines(sys.stderr, prefix=f"  mu = {mu:g}: ")):
            cert = certify(BladeParameters.flight_case("forward"), mu, refine=True)
        cert.save(path_for(mu))
        print(f"mu = {mu:g}: {cert.function}, certified {cert.certified}, A = {cert.bound:.4g}, "
              f"lambda0 = {cert.start_region:.4g}, {time.perf_counter() - start:.0f} s -> {path_for(mu).name}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
