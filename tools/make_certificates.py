"""Make the certificate files the book ships and verifies (README, "Certificates as files").

Usage: python tools/make_certificates.py [CASE ...]
(CASE: an advance ratio, or ``forward``, ``neutral`` or ``backward`` for a Table I hover;
default: every file the book ships, the three hovers and mu = 0.1, 0.2 and 0.25)

For each advance ratio, ``rotorlyap.certify`` of the trimmed helicopter (the Table I
blade in the forward-flight model, forward C.G.: ``BladeParameters.flight_case("forward")``), with
the thorough design (``design="thorough"``, :data:`DESIGN`) and the harmonics of :data:`HARMONICS`,
is made about the periodic motion
refined by shooting (``refine=True``: a table that solves the
equations to round-off, as ``rotorlyap.verify`` checks), in the norm scales of chapter 10's
case (``rotorlyap.chapters.large_disturbances.CASES``; the default ones where it gives none), and
saved as ``book/certificates/forward_mu<100 mu>.json``. Its design (the augmented energy
in forward flight) takes minutes and its start radius depends on the last bits of the
floating-point environment, so it is made once, here, and committed; chapter 10 and the tests
verify each file from nothing (``rotorlyap.verify``) in every run, on any machine.

For each Table I hover, the default ``certify(BladeParameters.table_i(cg), 0.0,
condition="none", scales=...)`` (the paper's controls; the augmented energy, designed on the
shell of the band; the norm scales of chapter 10's case,
``rotorlyap.chapters.large_disturbances.SCALE_FACTORS``: the pitch angle's and pitch rate's
scales larger than the default, so that the start set reaches further along the hinge where it
reaches least) is saved as
``book/certificates/hover_<cg>.json``. Its design takes half a minute to a
minute, and the backward C.G.'s start radius depends on the last bits of the floating-point
environment (its design program works at the edge of feasibility); made once here, each file is
verified by chapter 10 and attacked by the falsifier in every test run instead of being designed
again by both.

Run it in the ordinary environment; the progress of each design goes to standard error.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

from rotorlyap import BladeParameters, certify
from rotorlyap.progress import Lines, listening

FOLDER = Path(__file__).resolve().parents[1] / "book" / "certificates"


#: The design program's effort (``rotorlyap.certify(design=...)``,
#: ``rotorlyap.analysis.nonlinear_functions.DESIGN_EFFORTS``) per kind of case. In forward flight the
#: thorough one: its extra rounds and bisection steps reach larger start regions in minutes (made
#: once, so the time is spent once; measured 2026-12-06 with the periodic motion refined, the files'
#: start radii at mu = 0.1, 0.2 and 0.25: 1.6 -> 3.6, 2.6 -> 2.6 and 1.7 -> 2.2 against the default
#: effort's files). In hover the default one: the thorough effort met the same start radii there
#: (forward C.G. 3.7, neutral 2.2) and no larger start set, the flap rate limiting both.
DESIGN = {"hover": "default", "forward flight": "thorough"}

#: Harmonics of the azimuth in the designed function's quadratic coefficients, per advance ratio
#: (``rotorlyap.certify(harmonics=...)``; the package's default is 1). Chosen by measurement: the
#: thorough design in each file's norm, about the refined motion, with 1 and 2 harmonics, side by
#: side (2026-12-06, an AMD EPYC of CI's kind; start radius, and the least reach of the start set
#: along a hinge as a share of chapter 10's simulated region): mu = 0.1: 3.65 and 17.7 % with one,
#: 3.21 and 14.9 % with two; mu = 0.2: 2.84 and 14.0 %, 3.06 and 15.6 %; mu = 0.25: 1.63 and 7.9 %, 2.48
#: and 11.3 %. Three harmonics at mu = 0.2 met only 2.28 (9.7 %): the design's rounds do not keep
#: up with 148 coefficients.
HARMONICS = {0.1: 1, 0.2: 2, 0.25: 2}

#: The Table I hovers whose default certificate the book ships as a file.
HOVERS = ("forward", "neutral", "backward")

#: The advance ratios of the trimmed helicopter's files.
ADVANCE_RATIOS = (0.1, 0.2, 0.25)


def path_for(case: float | str) -> Path:
    """The file of a case: ``forward_mu010.json`` for the advance ratio 0.1, ``hover_forward.json``
    for the forward C.G.'s hover."""
    if isinstance(case, str):
        return FOLDER / f"hover_{case}.json"
    return FOLDER / f"forward_mu{round(100 * case):03d}.json"


def case_scales(case: float | str):
    """The norm scales of a case's certificate (a Table I hover's C.G. or an advance ratio of the
    trimmed helicopter): chapter 10's for the case (:data:`rotorlyap.chapters.large_disturbances.CASES`;
    None: the default scales)."""
    from rotorlyap.chapters.large_disturbances import CASES

    if isinstance(case, str):
        return next(c.scales for c in CASES if c.mu == 0.0 and c.blade == ("table_i", case))
    return next((c.scales for c in CASES if c.mu == case and c.blade == ("flight_case", "forward")), None)


def _case(word: str) -> float | str:
    if word in HOVERS:
        return word
    try:
        return float(word)
    except ValueError:
        raise SystemExit(f"make_certificates: a case is an advance ratio or one of {', '.join(HOVERS)}, "
                         f"got {word!r}") from None


def main(argv: list[str]) -> int:
    cases = [_case(v) for v in argv] or [*HOVERS, *ADVANCE_RATIOS]
    FOLDER.mkdir(parents=True, exist_ok=True)
    for case in cases:
        start = time.perf_counter()
        name = f"{case} C.G. hover" if isinstance(case, str) else f"mu = {case:g}"
        with listening(Lines(sys.stderr, prefix=f"  {name}: ")):
            if isinstance(case, str):
                cert = certify(BladeParameters.table_i(case), 0.0, condition="none", scales=case_scales(case),
                               design=DESIGN["hover"])
            else:
                cert = certify(BladeParameters.flight_case("forward"), case, refine=True, scales=case_scales(case),
                               design=DESIGN["forward flight"], harmonics=HARMONICS.get(case))
        cert.save(path_for(case))
        print(f"{name}: {cert.function}, certified {cert.certified}, A = {cert.bound:.4g}, "
              f"lambda0 = {cert.start_region:.4g}, {time.perf_counter() - start:.0f} s -> {path_for(case).name}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
