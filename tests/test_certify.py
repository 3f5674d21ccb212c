"""rotorlyap.certify: one call from a blade to a certificate read per hinge."""

from __future__ import annotations

import numpy as np
import pytest

from rotorlyap import certify
from rotorlyap.analysis.floquet import blade_floquet
from rotorlyap.methods.simulation import simulate
from rotorlyap.model.blade import Blade
from rotorlyap.model.parameters import BladeParameters
from rotorlyap.model.steady import disturbed_rhs


@pytest.fixture(scope="module")
def hover_certificate():
    return certify(BladeParameters.flight_case("forward"), 0.0, function="quadratic")


def test_the_forward_cg_hover_is_certified_and_read_per_hinge(hover_certificate):
    """The certificate's start region and bound along each hinge are the scaled norm's radii
    times the scales: angle a_i lambda0 in degrees, rate a_(i+3) lambda0 Omega in degrees per
    second (rad/rad of azimuth times Omega rad/s)."""
    c = hover_certificate
    assert c.certified and "numerical certificate" in c.message
    assert c.function == "quadratic" and [k.function for k in c.candidates] == ["quadratic"]
    assert 0.0 < c.start_region < c.bound <= 1.0
    omega = c.trim.params.rotor_speed
    flap_deg, flap_rate = c.start_region_per_hinge["flap"]
    assert flap_deg == pytest.approx(np.degrees(c.scales[0]) * c.start_region, rel=1e-12)
    assert flap_rate == pytest.approx(np.degrees(c.scales[3]) * c.start_region * omega, rel=1e-12)
    assert c.bound_per_hinge["pitch"][0] == pytest.approx(np.degrees(c.scales[2]) * c.bound, rel=1e-12)
    assert "start within" in c.summary()


def test_certified_starts_stay_within_the_bound_in_simulation(hover_certificate):
    """What the certificate promises: motions of the nonlinear blade from the start region's
    boundary (here along each signed hinge axis) stay within the bound for ten revolutions."""
    c = hover_certificate
    blade = Blade(c.trim.params, 0.0)
    f = disturbed_rhs(blade, c.trim.steady)
    x0 = 0.999 * c.start_region * np.vstack([np.eye(6), -np.eye(6)]) * c.scales
    sim = simulate(f, x0, 0.0, 10, scales=c.scales)
    assert np.all(sim.max_norm <= c.bound)


def test_an_unstable_blade_is_not_certified_and_says_why():
    """The backward C.G. with compressible sections is unstable in hover in linear theory
    (chapter 8): no quadratic function exists, so nothing is certified, and the message says so."""
    c = certify(BladeParameters.flight_case("backward"), 0.0)
    assert not c.certified and c.result is None and c.bound == 0.0
    assert "linearised blade is unstable" in c.message
    # the growth rate once, in one message without nested parentheses (issue 42)
    assert c.summary().count("per rev") == 1 and "((" not in c.summary() and "nothing can be certified (" not in c.message
    assert c.growth_rate == pytest.approx(
        blade_floquet(c.trim.params, 0.0, steady=c.trim.steady).exponents.real.max(), abs=1e-12)
    assert c.growth_rate > 0.0


def test_certify_refuses_an_unknown_condition():
    with pytest.raises(ValueError, match="condition must be one of"):
        certify(BladeParameters.flight_case("forward"), 0.1, condition="cruise")


def test_certify_refuses_an_unknown_function():
    with pytest.raises(ValueError, match="function must be one of"):
        certify(BladeParameters.table_i("forward"), 0.0, function="cubic")


def test_certify_and_the_design_refuse_an_unknown_design_effort():
    """The efforts allowed are named in the error, before any work (certify) or design."""
    from rotorlyap.analysis.nonlinear_functions import designed_function

    with pytest.raises(ValueError, match=r"design must be one of \('default', 'thorough'\), got 'heroic'"):
        certify(BladeParameters.table_i("forward"), 0.0, design="heroic")
    with pytest.raises(ValueError, match=r"effort must be one of \('default', 'thorough'\)"):
        designed_function(Blade(BladeParameters.table_i("forward"), 0.0), None, "energy", effort="heroic")


@pytest.mark.parametrize("harmonics", [-1, 1.5, True, "2"])
def test_certify_refuses_harmonics_that_are_not_a_count(harmonics):
    """Before any work, with what is allowed."""
    with pytest.raises(ValueError, match="harmonics must be None or an integer >= 0"):
        certify(BladeParameters.flight_case("forward"), 0.1, harmonics=harmonics)


def test_harmonics_of_the_azimuth_are_refused_where_the_blade_does_not_depend_on_it():
    """In hover the engine searches a designed function at one azimuth: a W with harmonics of the
    azimuth would be checked at psi = 0 only, so none is designed or built (certify, the design and
    both bases say why)."""
    from rotorlyap.analysis.nonlinear_functions import designed_function, energy_basis, polynomial_basis

    with pytest.raises(ValueError, match=r"0 or None in hover"):
        certify(BladeParameters.table_i("forward"), 0.0, harmonics=1)
    blade = Blade(BladeParameters.table_i("forward"), 0.0)
    for build in (energy_basis, polynomial_basis):
        with pytest.raises(ValueError, match="harmonics must be 0 where the disturbed blade does not depend"):
            build(blade, None, harmonics=2)
    with pytest.raises(ValueError, match="harmonics must be 0 where the disturbed blade does not depend"):
        designed_function(blade, None, "energy", harmonics=1)
    assert energy_basis(blade, None, harmonics=0).size == 22  # the energy and 21 quadratic forms
