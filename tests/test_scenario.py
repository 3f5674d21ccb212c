"""rotorlyap.methods.scenario: Liapunov functions designed by a linear program on sampled states.

Facts checked on systems whose answers are known:

* the rates of the monomial basis are the derivatives along the motions (a central difference
  along ``(1, f)`` in ``(psi, x)``), with and without harmonics of the azimuth;
* a hardening spring (a damped Duffing oscillator) is a conservative nonlinearity: with its
  energy in the basis the certificate reaches many times further than with quadratic forms alone,
  and the energy's semi-definite derivative (``-c v^2``, zero wherever the rate is) is made strict
  by the quadratic terms the program adds;
* van der Pol's oscillator run backwards has an unstable limit cycle round a stable origin: its
  energy ``(x^2 + v^2) / 2`` certifies nothing under the sound rule (``W' = -mu (1 - x^2) v^2``
  vanishes on the axis ``v = 0``), designed polynomials certify start regions that grow with
  their degree, and every one lies inside the limit cycle (no certificate may cross it);
* motions simulated from the certified start regions stay within the certified bound.
"""

from __future__ import annotations

import numpy as np
import pytest

from rotorlyap.methods.lyapunov import technical_stability
from rotorlyap.methods.scenario import Basis, BasisFunction, design, largest_design, monomial_basis, \
    monomial_exponents
from rotorlyap.methods.simulation import simulate

ONES = np.ones(2)


def duffing(c: float = 0.2):
    """x'' + c x' + x + x^3 = 0 and its energy E = v^2/2 + x^2/2 + x^4/4 (E' = -c v^2)."""
    f = lambda p, x: np.column_stack([x[:, 1], -x[:, 0] - x[:, 0] ** 3 - c * x[:, 1]])  # noqa: E731
    energy = Basis(("energy",),
                   lambda p, x: (0.5 * x[:, 1] ** 2 + 0.5 * x[:, 0] ** 2 + 0.25 * x[:, 0] ** 4)[:, None],
                   lambda p, x: (-c * x[:, 1] ** 2)[:, None])
    return f, energy


def van_der_pol(mu: float = 0.5):
    """x'' - mu (x^2 - 1) x' + x = 0: van der Pol's oscillator with time reversed (stable origin,
    unstable limit cycle)."""
    return lambda p, x: np.column_stack([x[:, 1], -x[:, 0] + mu * (x[:, 0] ** 2 - 1.0) * x[:, 1]])  # noqa: E731


def certify_design(f, d):
    return technical_stability(f, d.function.W, d.A, scales=ONES, n_psi=4, dW=d.function.dW,
                               autonomous=True, band="shell")


def test_monomial_exponents_count_every_monomial_once():
    """C(n + d - 1, d) monomials of degree d in n variables: 21 quadratic, 56 cubic in six."""
    e = monomial_exponents(6, (2, 3))
    assert e.shape == (21 + 56, 6)
    assert len({tuple(r) for r in e}) == e.shape[0]
    assert set(e.sum(axis=1)) == {2, 3}
    with pytest.raises(ValueError, match="degrees must be >= 1"):
        monomial_exponents(2, (0, 2))


@pytest.mark.parametrize("degrees, harmonics", [((2,), 0), ((2, 3, 4), 0), ((2,), 2), ((1, 3), 1)])
def test_monomial_rates_are_derivatives_along_the_motions(degrees, harmonics):
    """phi' = d phi / d psi + grad phi . f, checked by a central difference along (1, f)."""
    f = lambda p, x: np.column_stack([x[:, 1] * np.cos(p), -x[:, 0] + 0.3 * x[:, 0] ** 2, x[:, 0] * x[:, 2]])  # noqa: E731
    a = np.array([1.0, 2.0, 0.5])
    basis = monomial_basis(f, a, degrees, harmonics=harmonics, period=3.0)
    rng = np.random.default_rng(0)
    x, psi = rng.normal(size=(50, 3)), rng.uniform(0, 3, 50)
    h = 1e-6
    fx = f(psi, x)
    fd = (basis.values(psi + h, x + h * fx) - basis.values(psi - h, x - h * fx)) / (2 * h)
    exact = basis.rates(psi, x)
    assert exact.shape == (50, basis.size) == fd.shape
    assert np.abs(fd - exact).max() <= 1e-6 * max(1.0, np.abs(exact).max())


def test_basis_function_checks_its_coefficients():
    f, energy = duffing()
    with pytest.raises(ValueError, match="2 coefficients for a basis of 1"):
        BasisFunction(energy, [1.0, 2.0], f)


def test_design_refuses_a_start_radius_beyond_the_bound():
    f, energy = duffing()
    with pytest.raises(ValueError, match="must be below the bound"):
        design(energy, f, ONES, 1.0, 2.0, periodic=False)


@pytest.mark.slow
def test_the_energy_carries_a_hardening_spring_far_beyond_quadratic_forms():
    """Duffing: quadratic forms alone certify a start radius below one (the cubic spring turns
    their W' positive); with the energy in the basis the start radius is at least five times
    larger, W' strict on the shell although E' = -c v^2 is not, and simulated motions from the
    certified ball stay within the bound."""
    f, energy = duffing()
    quadratic = monomial_basis(f, ONES, (2,))
    results = {}
    for name, basis in (("quadratic", quadratic), ("energy", energy + quadratic)):
        d = largest_design(basis, f, ONES, lam_start=0.1, lam_max=50.0, periodic=False, ratios=(2.5, 4.0, 8.0))
        assert d.feasible
        results[name] = certify_design(f, d), d
    q, e = results["quadratic"][0], results["energy"][0]
    assert q.certified and e.certified
    assert q.lambda0.min() < 1.0
    assert e.lambda0.min() >= 5.0 * q.lambda0.min()
    # the energy's coefficient is used (not a quadratic form again) and W' is strict on the shell
    fun = results["energy"][1].function
    assert abs(fun.coefficients[0]) > 0
    u = np.column_stack([np.cos(np.linspace(0, 2 * np.pi, 721)), np.sin(np.linspace(0, 2 * np.pi, 721))])
    for r in np.linspace(e.lambda0.min(), e.A, 7):
        assert np.all(fun.dW(np.zeros(u.shape[0]), r * u) < 0)
    lam = 0.999 * e.lambda0.min()
    sim = simulate(f, lam * u[::30], 0.0, 20.0, scales=ONES)
    assert np.all(sim.max_norm <= e.A)


@pytest.mark.slow
def test_van_der_pol_certificates_grow_with_degree_and_stay_inside_the_limit_cycle():
    """Reversed van der Pol (mu = 0.5): its energy certifies nothing under the sound rule; designed
    polynomials of degree 2, 4 and 6 certify start radii that grow with the degree, each smaller
    than the smallest radius of the unstable limit cycle (found by integrating backwards), and
    motions from them stay within their bounds."""
    mu = 0.5
    f = van_der_pol(mu)
    energy = technical_stability(f, lambda p, x: 0.5 * (x ** 2).sum(axis=1), 1.5, scales=ONES, n_psi=4,
                                 dW=lambda p, x: -mu * (1 - x[:, 0] ** 2) * x[:, 1] ** 2, autonomous=True)
    assert energy.A == 0.0 and not energy.certified
    back = simulate(lambda p, x: -f(p, x), np.array([[2.5, 0.0]]), 0.0, 20.0)
    cycle = np.linalg.norm(back.x[-200:, 0, :], axis=1).min()
    assert 1.5 < cycle < 2.0
    radii = []
    for degrees in ((2,), (2, 3, 4), (2, 3, 4, 5, 6)):
        basis = monomial_basis(f, ONES, degrees)
        d = largest_design(basis, f, ONES, lam_start=0.1, lam_max=5.0, periodic=False, ratios=(1.5, 2.5, 4.0))
        res = certify_design(f, d)
        assert res.certified
        radii.append(res.lambda0.min())
        assert radii[-1] < cycle
        u = np.column_stack([np.cos(np.linspace(0, 2 * np.pi, 25)), np.sin(np.linspace(0, 2 * np.pi, 25))])
        sim = simulate(f, 0.999 * radii[-1] * u, 0.0, 10.0, scales=ONES)
        assert np.all(sim.max_norm <= res.A)
    assert radii[0] < radii[1] < radii[2]
    assert radii[0] > 0.5


def test_largest_design_bisects_below_a_start_radius_whose_thorough_design_fails(monkeypatch):
    """With a program that meets every start radius up to 3.5 in its search rounds but only up to
    2.5 thoroughly (a stand-in for ``design``, so that the order of the attempts is what is
    tested): the largest success, 3.2, fails thoroughly; without ``bisect_below`` the next largest,
    1.6, is returned; with it, three bisection steps between 1.6 and 3.2 (2.26 passes thoroughly,
    2.69 does not, 2.47 does) return a start radius that passes thoroughly within their resolution
    (a factor 2 ** (1 / 8)) of the largest that does, and never try above 3.2 again."""
    import rotorlyap.methods.scenario as scenario

    def fake(basis, f, scales, A, lam, thorough=False, **options):
        ok = lam <= (2.5 if thorough else 3.5)
        return scenario.Design(function=None, lam=lam, A=A, margin=1.0 if ok else -1.0, feasible=ok, rounds=1,
                               n_constraints=0)

    monkeypatch.setattr(scenario, "design", fake)
    plain = largest_design(None, None, ONES, lam_start=0.1, lam_max=50.0, ratios=(2.5,))
    below = largest_design(None, None, ONES, lam_start=0.1, lam_max=50.0, ratios=(2.5,), bisect_below=True)
    assert plain.feasible and plain.lam == pytest.approx(1.6)
    assert below.feasible and 2.5 / 2 ** (1 / 8) < below.lam <= 2.5
    hardened = [lam for lam, A, ok in below.tried[below.tried.index((3.2, 8.0, False)):]]
    assert max(hardened) == pytest.approx(3.2) and min(hardened) >= 1.6
    assert len(below.tried) == len(plain.tried) + 2 * 3 - 1  # three bisection steps (search + thorough
    # where the search passes), less the thorough design of 1.6, which the bisection makes needless
