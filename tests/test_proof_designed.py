"""The proof of designed quadratic forms and the measured width of the blade's enclosure
(rotorlyap.analysis.proof: designed_quadratic_form, prove_designed, enclosure_width).

Facts checked:

* a designed function whose weights sit on the quadratic monomials alone is the quadratic form
  ``y^T S y`` with the ``S`` read from its weights (values at random states agree to round-off);
  a weight on anything else (the energy) is refused with its name;
* the same matrix reaches the same proof by both routes: a designed function holding the
  Lyapunov equation's ``S`` is proved to exactly the bound and start radius that
  :func:`rotorlyap.analysis.proof.prove_blade` proves for the quadratic function itself;
* the enclosure of the blade's Jacobian is sound (every sampled Jacobian lies in its balls, with
  and without air loads), its radius shrinks in proportion to the box, and the sampled variation
  does too (both first order in the box), so the ratio between them does not depend on the box.
"""

from __future__ import annotations

import numpy as np
import pytest

from rotorlyap.analysis.functions import quadratic_function
from rotorlyap.analysis.nonlinear_functions import DesignedFunction, energy_basis
from rotorlyap.analysis.proof import designed_quadratic_form, enclosure_width, prove_blade, prove_designed
from rotorlyap.conventions import DEFAULT_SCALES, STATE_NAMES
from rotorlyap.methods.scenario import monomial_basis
from rotorlyap.model.blade import Blade
from rotorlyap.model.parameters import BladeParameters
from rotorlyap.model.steady import as_steady_motion, disturbed_rhs

from designed_helpers import designed as _designed, weights as _weights


@pytest.fixture(scope="module")
def hover():
    blade = Blade(BladeParameters.table_i("forward"), 0.0)
    return blade, as_steady_motion(None, blade)


def test_a_designed_quadratic_form_is_read_back_exactly(hover):
    blade, steady = hover
    a = np.asarray(DEFAULT_SCALES, dtype=float)
    basis = monomial_basis(disturbed_rhs(blade, steady), a, (2,), names=STATE_NAMES)
    rng = np.random.default_rng(3)
    M = rng.normal(size=(6, 6))
    S = M @ M.T
    fun = _designed(blade, steady, basis, _weights(S))
    read = designed_quadratic_form(fun)
    assert np.array_equal(read, read.T)
    x = rng.normal(size=(50, 6)) * a
    y = x / a
    np.testing.assert_allclose(fun.W(0.0, x), np.einsum("mi,ij,mj->m", y, read, y), rtol=1e-13)


def test_a_weight_on_the_energy_is_refused(hover):
    blade, steady = hover
    basis = energy_basis(blade, steady)
    c = np.zeros(basis.size)
    c[0], c[1] = 0.5, 1.0
    with pytest.raises(ValueError, match="energy"):
        designed_quadratic_form(_designed(blade, steady, basis, c))
    c[0] = 0.0  # no weight on the energy: a quadratic form
    assert designed_quadratic_form(_designed(blade, steady, basis, c))[0, 0] == 1.0


def test_the_same_matrix_is_proved_alike_by_both_routes(hover):
    blade, steady = hover
    q = quadratic_function(blade, steady)
    S = q.solution.P_grid[0]
    S = np.triu(S) + np.triu(S, 1).T  # the upper triangle mirrored, as the proof encloses it
    basis = monomial_basis(disturbed_rhs(blade, steady), q.scales, (2,), names=STATE_NAMES)
    fun = _designed(blade, steady, basis, _weights(S), A=0.5)
    designed = prove_designed(fun)
    direct = prove_blade(q, 0.5)
    assert designed.proved and direct.proved
    assert designed.A == direct.A
    np.testing.assert_allclose(designed.min_lambda0, direct.min_lambda0, rtol=1e-12)


def test_prove_designed_refuses_forward_flight(hover):
    blade, steady = hover
    basis = monomial_basis(disturbed_rhs(blade, steady), DEFAULT_SCALES, (2,), names=STATE_NAMES)
    fun = _designed(blade, steady, basis, _weights(np.eye(6)))
    fun = DesignedFunction(**{**fun.__dict__, "autonomous": False})
    with pytest.raises(ValueError, match="autonomous"):
        prove_designed(fun)


@pytest.mark.parametrize("aerodynamics", [True, False])
def test_the_enclosure_contains_every_sampled_jacobian(hover, aerodynamics):
    blade, steady = hover
    w = enclosure_width(blade, steady, 0.1, samples=128, aerodynamics=aerodynamics)
    assert w.contained
    assert w.ratio > 1.0


def test_the_enclosure_and_the_variation_both_shrink_with_the_box(hover):
    blade, steady = hover
    big = enclosure_width(blade, steady, 0.1, samples=64)
    small = enclosure_width(blade, steady, 0.01, samples=64)
    assert big.entry == small.entry
    np.testing.assert_allclose(small.radius.max() / big.radius.max(), 0.1, rtol=0.05)
    np.testing.assert_allclose(small.variation.max() / big.variation.max(), 0.1, rtol=0.05)


def test_enclosure_width_rejects_bad_input(hover):
    blade, steady = hover
    with pytest.raises(ValueError, match="bound"):
        enclosure_width(blade, steady, -1.0)
