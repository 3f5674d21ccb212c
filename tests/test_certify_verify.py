"""certify(verify=True) proves the certificate it returns, its own function.

Facts checked:

* a designed hover function (here the augmented energy's basis with a weight on the energy) goes
  to the level-set prover, ``prove_designed_level``, which is asked for the fraction given of the
  numerical start radius (the wiring checked with a stand-in prover: the blade's level-set proof
  itself takes a minute, chapter 10 runs it and tests/test_level_set.py checks the prover on
  systems known in closed form);
* a designed function no prover takes (a cubic monomial; coefficients that depend on the
  azimuth) and one that certified nothing are "not proved", with the reason, and no prover runs;
  a fraction outside (0, 1] is refused.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from rotorlyap.analysis.certify import ProvedPart, prove_certificate
from rotorlyap.analysis.functions import quadratic_function
from rotorlyap.analysis.nonlinear_functions import energy_basis
from rotorlyap.conventions import STATE_NAMES
from rotorlyap.methods.scenario import monomial_basis
from rotorlyap.model.blade import Blade
from rotorlyap.model.parameters import BladeParameters
from rotorlyap.model.steady import as_steady_motion, disturbed_rhs

from designed_helpers import designed as _designed


@pytest.fixture(scope="module")
def hover():
    blade = Blade(BladeParameters.table_i("forward"), 0.0)
    return blade, as_steady_motion(None, blade)


def test_a_designed_hover_function_goes_to_the_level_set_prover(hover, monkeypatch):
    import rotorlyap.analysis.designed_proof as dp
    from rotorlyap.analysis.designed_proof import DesignedLevelProof
    from rotorlyap.methods.level_set import LevelProof

    blade, steady = hover
    basis = energy_basis(blade, steady)
    c = np.zeros(basis.size)
    c[0], c[1] = 0.5, 1.0  # a weight on the energy
    fun = _designed(blade, steady, basis, c)
    asked = {}

    def stand_in(f, start_radius, *, numerical_start):
        asked.update(start=start_radius, numerical=numerical_start)
        return DesignedLevelProof(LevelProof(True, 0.3, 2.0, start_radius, 1.5, 10, 8, 0.1), start_radius,
                                  numerical_start, 1.0, 3)

    monkeypatch.setattr(dp, "prove_designed_level", stand_in)
    proof, part = prove_certificate(fun, "energy", 1.0, 0.2, True, designed_fraction=0.25)
    assert asked == {"start": 0.25 * 0.2, "numerical": 0.2}
    assert part.proved and "prove_designed_level" in part.method and part.not_proved == ""
    assert part.start_region == proof.min_lambda0 == 0.05 and part.bound == proof.A == 1.5
    assert part.start_fraction == pytest.approx(0.25) and part.bound_fraction == pytest.approx(1.5)
    with pytest.raises(ValueError, match="designed_fraction"):
        prove_certificate(fun, "energy", 1.0, 0.2, True, designed_fraction=0.0)


def test_a_function_no_prover_takes_is_not_proved_and_says_why(hover):
    blade, steady = hover
    q = quadratic_function(blade, steady)
    cubic = monomial_basis(disturbed_rhs(blade, steady), q.scales, (2, 3), names=STATE_NAMES)
    c = np.zeros(cubic.size)
    c[0], c[-1] = 1.0, 0.1  # a weight on a cubic monomial
    proof, part = prove_certificate(_designed(blade, steady, cubic, c), "polynomial", 1.0, 0.1, True)
    assert proof is None and not part.proved and part.bound == 0.0 and part.bound_fraction == 0.0
    assert "terms the prover's models do not hold" in part.not_proved
    basis = energy_basis(blade, steady)
    e = np.zeros(basis.size)
    e[0], e[1] = 0.5, 1.0
    flight = _designed(blade, steady, basis, e, autonomous=False)
    assert "depend on the azimuth" in prove_certificate(flight, "energy", 1.0, 0.1, True)[1].not_proved
    proof, part = prove_certificate(flight, "energy", 0.0, 0.0, False)
    assert proof is None and "certified nothing" in part.not_proved and np.isnan(part.bound_fraction)
    assert "no function" in prove_certificate(None, "quadratic", 0.0, 0.0, False)[1].not_proved
    with pytest.raises(ValueError, match="family must be one of"):
        prove_certificate(None, "cubic", 0.0, 0.0, False)
    assert {f.name for f in dataclasses.fields(ProvedPart)} >= {"bound", "start_region", "bound_fraction",
                                                                 "start_fraction", "method", "not_proved"}
