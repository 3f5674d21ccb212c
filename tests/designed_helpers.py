"""Designed functions made by hand for the proof tests (not a test module):
``test_proof_designed.py`` and ``test_certify_verify.py`` share them."""

from __future__ import annotations

import numpy as np

from rotorlyap.analysis.nonlinear_functions import DesignedFunction
from rotorlyap.conventions import DEFAULT_SCALES
from rotorlyap.methods.scenario import BasisFunction, Design
from rotorlyap.model.steady import disturbed_rhs


def designed(blade, steady, basis, coefficients, A: float = 1.0, autonomous: bool = True) -> DesignedFunction:
    """A :class:`DesignedFunction` of the given basis and coefficients, as if a design at the start
    radius 0.1 and the bound ``A`` had made it (default scales)."""
    fn = BasisFunction(basis, coefficients, disturbed_rhs(blade, steady), "test")
    design = Design(function=fn, lam=0.1, A=A, margin=0.1, feasible=True, rounds=1, n_constraints=1)
    return DesignedFunction(blade=blade, steady=steady, family="energy", design=design,
                            scales=np.asarray(DEFAULT_SCALES, dtype=float), autonomous=autonomous, label="test")


def weights(S: np.ndarray) -> np.ndarray:
    """The quadratic monomials' weights of ``y^T S y`` in the order of ``monomial_basis``."""
    iu = np.triu_indices(6)
    return np.where(iu[0] == iu[1], S[iu], 2 * S[iu])
