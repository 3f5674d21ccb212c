"""The falsifier on every certificate chapter 7 reports for the backward C.G. (:mod:`falsifier_scan`).

Fact checked: each certificate of the scan survives an independent adversary (other
optimisers, 10 x the engine's evaluations) and worst-case simulated starts for 20 revolutions;
in hover it agrees with its closed forms and is tight to 1 %.
"""

from __future__ import annotations

import pytest

from falsifier_scan import CELLS, falsify, scan_of

CASE = "backward"


@pytest.fixture(scope="module")
def scan():
    return scan_of(CASE)


@pytest.mark.slow
@pytest.mark.parametrize("key, mu", CELLS)
def test_certificate_survives_the_falsifier(scan, key, mu):
    falsify(*scan, CASE, key, mu)
