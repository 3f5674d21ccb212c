"""certify(verify=True) proves the certificate it returns, its own function.

Facts checked:

* a designed function that is a quadratic form in hover is proved by ``prove_designed``, up to the
  numerical bound, and the proved part's fractions are the proof's over the numerical
  certificate's (the same matrix as the quadratic function's, so the same proof as ``prove_blade``);
* a designed function no prover takes (a weight on the energy; coefficients that depend on the
  azimuth) and one that certified nothing are "not proved", with the reason, and no prover runs;
* end to end (slow): the forward C.G. in hover, where ``certify`` returns the augmented energy (a
  start region some 36 times the quadratic function's), ``verify=True`` proves that function, not
  the quadratic one, and the proof lies inside the numerical certificate.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from rotorlyap.analysis.certify import ProvedPart, prove_certificate
from rotorlyap.analysis.functions import quadratic_function
from rotorlyap.analysis.nonlinear_functions import energy_basis
from rotorlyap.analysis.proof import prove_blade
from rotorlyap.conventions import STATE_NAMES
from rotorlyap.methods.scenario import monomial_basis
from rotorlyap.model.blade import Blade
from rotorlyap.model.parameters import BladeParameters
from rotorlyap.model.steady import as_steady_motion, disturbed_rhs

from designed_helpers import designed as _designed, weights as _weights


@pytest.fixture(scope="module")
def hover():
    blade = Blade(BladeParameters.table_i("forward"), 0.0)
    return blade, as_steady_motion(None, blade)


def test_a_designed_quadratic_form_is_proved_by_prove_designed(hover):
    blade, steady = hover
    q = quadratic_function(blade, steady)
    S = q.solution.P_grid[0]
    S = np.triu(S) + np.triu(S, 1).T
    fun = _designed(blade, steady, monomial_basis(disturbed_rhs(blade, steady), q.scales, (2,), names=STATE_NAMES),
                    _weights(S), A=0.5)
    proof, part = prove_certificate(fun, "energy", 0.5, 0.1, True)
    direct = prove_blade(q, 0.5)
    assert part.proved and "prove_designed" in part.method and part.not_proved == ""
    assert part.bound == proof.A == direct.A and 0 < part.bound <= 0.5
    assert part.bound_fraction == pytest.approx(proof.A / 0.5, rel=1e-15)
    assert part.start_fraction == pytest.approx(proof.min_lambda0 / 0.1, rel=1e-15)
    assert "proved" in str(part)


def test_a_function_no_prover_takes_is_not_proved_and_says_why(hover):
    blade, steady = hover
    basis = energy_basis(blade, steady)
    c = np.zeros(basis.size)
    c[0], c[1] = 0.5, 1.0  # a weight on the energy
    proof, part = prove_certificate(_designed(blade, steady, basis, c), "energy", 1.0, 0.1, True)
    assert proof is None and not part.proved and part.bound == 0.0 and part.bound_fraction == 0.0
    assert "not a quadratic form" in part.not_proved and "energy" in part.not_proved
    flight = _designed(blade, steady, basis, c, autonomous=False)
    assert "depend on the azimuth" in prove_certificate(flight, "energy", 1.0, 0.1, True)[1].not_proved
    proof, part = prove_certificate(flight, "energy", 0.0, 0.0, False)
    assert proof is None and "certified nothing" in part.not_proved and np.isnan(part.bound_fraction)
    assert "no function" in prove_certificate(None, "quadratic", 0.0, 0.0, False)[1].not_proved
    with pytest.raises(ValueError, match="family must be one of"):
        prove_certificate(None, "cubic", 0.0, 0.0, False)
    assert {f.name for f in dataclasses.fields(ProvedPart)} >= {"bound", "start_region", "bound_fraction",
                                                                 "start_fraction", "method", "not_proved"}


@pytest.mark.slow
def test_verify_proves_the_designed_function_certify_returns():
    from rotorlyap import certify

    cert = certify(BladeParameters.table_i("forward"), 0.0, verify=True)
    part = cert.proved_part
    assert cert.certified and cert.function == "energy"  # the designed function, not the quadratic one
    quadratic = next(k for k in cert.candidates if k.function == "quadratic")
    assert cert.start_region > 10 * quadratic.start_region
    assert part.function == "energy" and "prove_designed" in part.method
    assert part.proved and cert.proof.proved
    assert 0 < part.bound <= cert.bound and 0 < part.start_region <= cert.start_region
    assert part.start_fraction == pytest.approx(part.start_region / cert.start_region)
    assert "prove_designed" in cert.summary()
