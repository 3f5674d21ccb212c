"""The falsifier on chapter 10's quadratic certificates: the quadratic function of the Lyapunov
equation in each case's own norm (:data:`rotorlyap.chapters.large_disturbances.CASES`), certified
by ``certify`` as the chapter certifies it beside the designed file, survives an independent
adversary (:func:`falsifier.falsify_certificate`: the theorem's three facts, the start set's
reported reach, the worst motions from the start set for 20 revolutions). The designed
certificates of the same cases are attacked by ``tests/test_falsifier_files.py`` and
``tests/test_falsifier_designed_*.py``. A case whose quadratic function certifies nothing has
nothing to attack (the chapter says "not certified"). About 2 s per hover case and 5 s per
advance ratio on an AMD EPYC of CI's kind (2026-12-06)."""

import pytest

from falsifier import falsify_certificate
from rotorlyap import certify
from rotorlyap.chapters.large_disturbances import CASES


@pytest.mark.slow
@pytest.mark.parametrize("case", CASES, ids=[c.key for c in CASES])
def test_the_chapters_quadratic_certificates_survive_the_falsifier(case):
    cert = certify(case.params(), case.mu, condition=case.condition, function="quadratic", scales=case.scales)
    if not cert.certified:
        pytest.skip(f"{case.label}: the quadratic function certifies nothing in this norm ({cert.message[:60]}...)")
    falsify_certificate(cert, evaluations=20_000)
