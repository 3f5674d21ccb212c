"""The classical flap instability of a rotor blade at high advance ratio, and the package's blade.

A rigid, centrally hinged blade flapping with frequency ``nu = 1`` under linear aerodynamics
*with reverse flow* loses stability in forward flight at an advance ratio a little above 2 for
ordinary Lock numbers: the periodic coefficients of its flap equation become large enough for
a Floquet multiplier to leave the unit circle [Sissingh1968], [PetersHohenemser1971] (see also
[Johnson1980], ch. 8, flap dynamics in forward flight; the chapter was not re-read for this
test). No published number for this exact blade was at hand (none was found with the report's
search tools), so the tests check

(a) an independent Floquet computation of the classical flap equation, written here from
    scratch (closed-form span integrals, ``scipy.integrate.solve_ivp``, ``brentq``), against
    the closed-form hover multipliers and against a loose band around the literature's
    "about 2.2 for gamma near 8": 2.0 < mu* < 2.5 for gamma = 8;
(b) the package's three-hinge blade (:class:`rotorlyap.model.blade.Blade`), reduced to that
    classical blade, against (a): same multipliers, same boundary.

The flap equation (derivation)
------------------------------
Blade of radius ``R`` hinged on the shaft (centrally hinged, no spring: ``nu = 1``), uniform
chord ``c``, flap inertia ``I``, lift slope ``a``, no drag, zero pitch, twist and inflow; time
is the azimuth ``psi = Omega t`` and lengths are in ``R``. The air velocity relative to the
section at ``r`` has the tangential part ``u_T = r + mu sin psi`` (positive from the leading
to the trailing edge; negative in the reverse-flow region ``r < -mu sin psi`` of the
retreating side) and the perpendicular part ``u_P = r beta' + mu beta cos psi`` (positive
downwards through the disc: the blade's own flap velocity, and the free stream seen by the
coned blade).

* Forward flow (``u_T > 0``): angle of attack ``theta - u_P / u_T``, lift (upwards, to first
  order) ``(rho a c / 2) (u_T^2 theta - u_P u_T)``.
* Reverse flow (``u_T < 0``): the air meets the trailing edge first. Seen from that edge the
  section is the same thin plate flipped front to back (not upside down), with nose-up pitch
  ``-theta``; air coming from below (``u_P < 0``) still raises its angle of attack:
  ``-theta - u_P / |u_T|``, and the lift, perpendicular to the wind and towards the plate's
  upper surface for a positive angle, is ``(rho a c / 2) u_T^2 (-theta - u_P / |u_T|)``.

Both are ``F = (rho a c / 2) (u_T |u_T| theta - u_P |u_T|)`` per unit span: with ``theta = 0``
a plate with air from below is pushed up whichever edge leads (that is what
:class:`~rotorlyap.model.airfoil.LinearAirfoil` does: ``tests/test_airfoil.py`` and
``test_package_section_lift_is_the_classical_reverse_flow_lift`` below). The moment about the hinge balances inertia and centrifugal stiffness,
``I Omega^2 (beta'' + beta) = R^2 Omega^2 int r F dr``, so with the Lock number
``gamma = rho a c R^4 / I`` and ``theta = 0``::

    beta'' + C(psi) beta' + (1 + K(psi)) beta = 0,
    C(psi) = gamma/2 int_{r0}^1 r^2 |r + mu sin psi| dr,
    K(psi) = gamma/2 mu cos psi int_{r0}^1 r |r + mu sin psi| dr,

with ``r0`` the root cutout (0 for the textbook blade). In hover ``C = gamma/8``, ``K = 0``:
exponents ``-gamma/16 +- i sqrt(1 - (gamma/16)^2)`` per rev.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq

from rotorlyap.methods.floquet import floquet_multipliers
from rotorlyap.model.airfoil import LinearAirfoil
from rotorlyap.model.blade import Blade
from rotorlyap.model.parameters import BladeParameters

TWO_PI = 2.0 * math.pi
GAMMA = 8.0
#: Loose band around the literature's boundary for gamma ~ 8, nu = 1 (module docstring).
LITERATURE_BAND = (2.0, 2.5)
#: Root cutout of the package's blade, fraction of R (the package needs R1 < R); (a) uses the same.
ROOT = 1e-3


# ---------------------------------------------------------------- (a) the independent computation

def abs_moment(n: int, x: float, lo: float = 0.0, hi: float = 1.0) -> float:
    """``int_lo^hi r^n |r + x| dr`` in closed form.

    Parameters
    ----------
    n : int
        Power of ``r``, >= 0.
    x : float
        Shift (``mu sin psi``).
    lo, hi : float
        Limits, ``0 <= lo < hi``.

    Returns
    -------
    float
        The integral; ``r + x`` changes sign at ``r = -x``, where the integral is split.
    """
    def F(r):
        return r ** (n + 2) / (n + 2) + x * r ** (n + 1) / (n + 1)

    r0 = -x
    if lo < r0 < hi:
        return (F(hi) - F(r0)) - (F(r0) - F(lo))
    return math.copysign(1.0, 0.5 * (lo + hi) + x) * (F(hi) - F(lo))


def flap_coefficients(psi: float, gamma: float, mu: float, root: float = 0.0) -> tuple[float, float]:
    """Damping ``C(psi)`` and periodic stiffness ``K(psi)`` of the flap equation (module docstring)."""
    x = mu * math.sin(psi)
    C = 0.5 * gamma * abs_moment(2, x, root)
    K = 0.5 * gamma * mu * math.cos(psi) * abs_moment(1, x, root)
    return C, K


def flap_monodromy(gamma: float, mu: float, root: float = 0.0) -> np.ndarray:
    """Monodromy matrix of ``(beta, beta')`` over one revolution, ``solve_ivp`` (DOP853, rtol 1e-10).

    Parameters
    ----------
    gamma : float
        Lock number.
    mu : float
        Advance ratio.
    root : float
        Root cutout of the aerodynamic span, fraction of R.

    Returns
    -------
    numpy.ndarray, shape (2, 2)
    """
    def rhs(psi, y):
        C, K = flap_coefficients(psi, gamma, mu, root)
        Y = y.reshape(2, 2)
        return np.array([Y[1], -(1.0 + K) * Y[0] - C * Y[1]]).ravel()

    sol = solve_ivp(rhs, (0.0, TWO_PI), np.eye(2).ravel(), method="DOP853", rtol=1e-10, atol=1e-12)
    assert sol.success, sol.message
    return sol.y[:, -1].reshape(2, 2)


def flap_multipliers(gamma: float, mu: float, root: float = 0.0) -> np.ndarray:
    """Floquet multipliers of the classical flap equation, sorted by decreasing modulus."""
    m = np.linalg.eigvals(flap_monodromy(gamma, mu, root))
    return m[np.argsort(-np.abs(m))]


def flap_boundary(gamma: float, root: float = 0.0, bracket=(1.5, 3.0)) -> float:
    """Advance ratio where the largest flap multiplier's modulus crosses 1 (``brentq``)."""
    return brentq(lambda mu: abs(flap_multipliers(gamma, mu, root)[0]) - 1.0, *bracket, xtol=1e-10)


@pytest.fixture(scope="module")
def independent_boundary() -> float:
    """The boundary of (a) for gamma = 8 and the package blade's root cutout."""
    return flap_boundary(GAMMA, ROOT)


@pytest.mark.parametrize("n", [1, 2])
@pytest.mark.parametrize("x", [0.7, 0.0, -0.3, -0.999, -1.5, -2.4])
@pytest.mark.parametrize("lo", [0.0, ROOT, 0.2])
def test_span_integrals_match_numerical_quadrature(n, x, lo):
    """The closed-form span integrals of |u_T| (split where the reverse-flow boundary r = -mu sin
    psi crosses the span) equal adaptive quadrature of the integrand."""
    ref, _ = quad(lambda r: r ** n * abs(r + x), lo, 1.0, points=[-x] if lo < -x < 1.0 else None,
                  epsabs=1e-14, epsrel=1e-13)
    assert abs_moment(n, x, lo) == pytest.approx(ref, rel=1e-12, abs=1e-14)


def test_flap_damping_stays_positive_in_reverse_flow():
    """With the lift -u_P |u_T| the blade's own flap velocity is always resisted, in reverse flow
    too (a plate moving up meets air from above whichever edge leads): C(psi) > 0 on the whole
    revolution even when most of the retreating blade is in reverse flow (mu = 2.5)."""
    for mu in (0.5, 1.0, 2.5):
        C = [flap_coefficients(psi, GAMMA, mu)[0] for psi in np.linspace(0, TWO_PI, 721)]
        assert min(C) > 0.0
    # in hover it is the classical gamma/8
    assert flap_coefficients(0.3, GAMMA, 0.0)[0] == pytest.approx(GAMMA / 8.0, rel=1e-14)


@pytest.mark.parametrize("gamma", [4.0, 8.0, 12.0])
def test_hover_multipliers_are_the_closed_form(gamma):
    """In hover the flap equation is beta'' + gamma/8 beta' + beta = 0: multipliers exp(2 pi s)
    with s = -gamma/16 +- i sqrt(1 - (gamma/16)^2), of modulus exp(-2 pi gamma/16)."""
    s = complex(-gamma / 16.0, math.sqrt(1.0 - (gamma / 16.0) ** 2))
    expected = np.exp(TWO_PI * np.array([s, s.conjugate()]))
    m = flap_multipliers(gamma, 0.0)
    np.testing.assert_allclose(np.sort_complex(m), np.sort_complex(expected), rtol=1e-8, atol=1e-12)
    np.testing.assert_allclose(np.abs(m), math.exp(-TWO_PI * gamma / 16.0), rtol=1e-8)


def test_classical_flap_boundary_lies_in_the_literature_band(independent_boundary):
    """The centrally hinged blade (gamma = 8, nu = 1, reverse flow included) is stable from hover up
    to its first boundary mu*, which lies in the band 2.0 < mu* < 2.5 around the classical
    'about 2.2' [Sissingh1968, PetersHohenemser1971]; beyond mu* a multiplier leaves the unit
    circle. The 0.1 % root cutout of (b) moves it by less than 1e-5."""
    mu_star = independent_boundary
    assert LITERATURE_BAND[0] < mu_star < LITERATURE_BAND[1]
    # the first crossing: stable on a grid from hover up to just below mu*
    for mu in np.append(np.arange(0.0, mu_star - 0.02, 0.1), mu_star - 0.02):
        assert abs(flap_multipliers(GAMMA, mu, ROOT)[0]) < 1.0
    assert abs(flap_multipliers(GAMMA, mu_star + 0.02, ROOT)[0]) > 1.0
    assert flap_boundary(GAMMA, 0.0) == pytest.approx(mu_star, abs=1e-5)


# ---------------------------------------------------------------- (b) the package's blade

def classical_blade(gamma: float = GAMMA, n_stations: int = 12) -> BladeParameters:
    """The package's blade reduced to the classical flapping blade (Lock number ``gamma``).

    All hinges on the shaft (hub elements zero: a central flap hinge, nu = 1), blade root at
    0.1 % of R (the package needs ``R1 < R``), ``LinearAirfoil`` without drag, no gravity,
    inflow, collective, twist, delta3 or aerodynamic pitch damping; C.G., aerodynamic centre and
    pitch axis all at the quarter chord, so that at the trivial state neither pitch nor lag is
    driven by flap. Lag (about 2/rev) and pitch (about 8/rev) are held by springs and dampers
    (damping ratio about 0.5) so that their multipliers (< 2e-3) stay far below the flap ones.
    The mass per length is scaled so that ``params.lock_number == gamma``.
    """
    base = BladeParameters(
        radius=7.85, blade_length=(1.0 - ROOT) * 7.85, hub_elements=(0.0, 0.0, 0.0, 0.0, 0.0),
        chord=0.4, twist=0.0, pitch_flap_coupling=0.0,
        pitch_stiffness=23000.0, pitch_damping=100.0, lag_stiffness=4.7e6, lag_damping=8.3e4,
        flap_stiffness=0.0, flap_damping=0.0,
        aerodynamic_centre=0.25, pitch_axis=0.25, wind_point=None, cm_pitch_rate=0.0, cg_position=0.25,
        airfoil=LinearAirfoil(lift_slope=2.0 * math.pi, cd0=0.0),
        inflow_ratio=0.0, collective=0.0, cyclic_cos=0.0, cyclic_sin=0.0, gravity=0.0,
        shaft_tilt=0.0, n_stations=n_stations)
    return replace(base, mass_per_length=base.mass_per_length * base.lock_number / gamma)


@pytest.fixture(scope="module")
def params() -> BladeParameters:
    return classical_blade()


def package_multipliers(params: BladeParameters, mu: float) -> tuple[np.ndarray, np.ndarray]:
    """Floquet multipliers of the package's blade linearised about the trivial motion z = 0.

    ``blade.jacobian`` (central differences) integrated over one revolution with the package's
    sixth-order Magnus method, 1024 steps (measured: the multipliers change by < 1e-5 from 512
    to 2048 steps, by < 3e-7 from 1024 to 2048).

    Returns
    -------
    flap, others : numpy.ndarray
        The two multipliers whose eigenvectors lie in the flap coordinates (beta, beta'),
        sorted by decreasing modulus, and the other four.
    """
    blade = Blade(params, mu)
    res = floquet_multipliers(lambda psi: blade.jacobian(psi, np.zeros((np.size(psi), 6))), TWO_PI,
                              method="magnus6", n_steps=1024, vectorized=True)
    m, V = np.linalg.eig(res.monodromy)
    flap_share = np.linalg.norm(V[[0, 3], :], axis=0) / np.linalg.norm(V, axis=0)
    is_flap = flap_share > 0.999
    assert is_flap.sum() == 2, flap_share
    flap = m[is_flap]
    return flap[np.argsort(-np.abs(flap))], m[~is_flap]


def test_package_blade_is_the_classical_blade(params):
    """The reduced package blade has the classical blade's data: Lock number gamma = 8, a central
    flap hinge (flap frequency 1/rev) and hover flap exponents -gamma/16 +- i sqrt(1 - (gamma/16)^2)
    (damping gamma/8), the closed form of the classical hover flap equation."""
    assert params.lock_number == pytest.approx(GAMMA, rel=1e-12)
    assert params.flap_hinge_offset == 0.0 and params.root_r_over_R == pytest.approx(ROOT, rel=1e-9)
    lam = np.linalg.eigvals(Blade(params, 0.0).jacobian(0.0, np.zeros(6)))
    s = complex(-GAMMA / 16.0, math.sqrt(1.0 - (GAMMA / 16.0) ** 2))
    flap = lam[np.argsort(np.abs(lam - s))[0]]
    assert flap == pytest.approx(s, abs=1e-6)


@pytest.mark.parametrize("mu", [0.5, 1.5, 2.2, 3.0])
def test_package_blade_has_the_trivial_periodic_motion(params, mu):
    """With no pitch, inflow, gravity or drag, a blade lying in the disc plane meets the air edge-on
    at every section, forward or reverse flow: no load, so z = 0 is a (periodic) motion,
    rhs(psi, 0) = 0. (A lift curve wrapped to +-a pi at alpha = +-180 deg would load the reverse-
    flow region.)"""
    blade = Blade(params, mu)
    psi = np.linspace(0.0, TWO_PI, 73)
    f = blade.rhs(psi, np.zeros((psi.size, 6)))
    assert np.max(np.abs(f)) < 1e-12


def test_flap_is_not_coupled_into_lag_or_pitch_at_the_trivial_motion(params):
    """About z = 0 the lag and pitch equations have no flap terms (no drag and no lift at zero state,
    so no in-plane force from flapping; no pitching moment about the pitch axis; no delta3; C.G.
    on the pitch axis): the Jacobian is block-triangular and the flap multipliers are those of
    the flap equation alone, whatever the lag and pitch stiffnesses."""
    blade = Blade(params, 2.2)
    for psi in np.linspace(0.0, TWO_PI, 13):
        J = blade.jacobian(psi, np.zeros(6))
        flap_scale = np.max(np.abs(J[3][[0, 3]]))
        assert np.max(np.abs(J[np.ix_([1, 2, 4, 5], [0, 3])])) < 1e-8 * flap_scale


def test_package_section_lift_is_the_classical_reverse_flow_lift(params):
    """The blade's strip force (rotorlyap.model.aero: alpha = atan2(w_z, -w_y), F_z = qn (cd w_z -
    cl w_y), qn = rho c |w| / 2) with LinearAirfoil reduces, to first order in u_P, to the classical
    section lift -(rho a c / 2) u_P |u_T| in forward *and* reverse flow (w_y = -u_T, w_z = -u_P)."""
    af = params.airfoil
    u_T = np.concatenate([np.linspace(-2.5, -0.05, 50), np.linspace(0.05, 2.5, 50)])
    for u_P in (1e-6, -1e-6):
        w_y, w_z = -u_T, np.full_like(u_T, -u_P)
        cl, cd, _ = af.coefficients(np.arctan2(w_z, -w_y))
        Fz = 0.5 * np.hypot(w_y, w_z) * (cd * w_z - cl * w_y)  # per rho c
        np.testing.assert_allclose(Fz, -0.5 * af.lift_slope * u_P * np.abs(u_T), rtol=1e-8)


@pytest.mark.parametrize("mu", [1.0, 2.0, 2.5])
def test_package_flap_multipliers_match_the_classical_equation(params, mu):
    """The package blade's flap multipliers at mu = 1, 2, 2.5 equal those of the classical flap
    equation (a), computed with the same root cutout; lag and pitch multipliers stay far inside
    the unit circle."""
    flap, others = package_multipliers(params, mu)
    ref = flap_multipliers(GAMMA, mu, params.root_r_over_R)
    np.testing.assert_allclose(np.sort_complex(flap), np.sort_complex(ref), atol=1e-5)
    assert np.max(np.abs(others)) < 0.01


def test_package_flap_boundary_matches_the_classical_boundary(params, independent_boundary):
    """The package blade loses flap stability at the same advance ratio as the classical equation
    (a): |mu*_package - mu*_classical| < 1e-4 for gamma = 8 (measured: < 1e-6).

    Tolerance: both describe the same linearised equation (the previous tests: same Lock number,
    central hinge, same root cutout, lag and pitch decoupled), so what remains is numerical: the
    12-point Gauss-Legendre span quadrature across the kink of |u_T| at the reverse-flow boundary
    (changes the multipliers by ~2e-7 from 12 to 48 stations), the central-difference Jacobian
    (~1e-10) and the 1024-step Magnus integration across the kinks in psi (~3e-7). 1e-4 leaves a
    wide margin yet still resolves modelling differences: near gamma = 8 the boundary of (a) moves
    by about 0.011 per unit of gamma (1e-4 is a 1 % error of the Lock number), by 2e-6 for the
    0.1 % root cutout; dropping the reverse-flow lift pushes it beyond mu = 3, and a lift
    -u_P u_T (signed, no |u_T|) brings it below mu = 1.5."""
    p = params
    mu_pkg = brentq(lambda mu: abs(package_multipliers(p, mu)[0][0]) - 1.0, 2.0, 2.5, xtol=1e-9)
    assert mu_pkg == pytest.approx(independent_boundary, abs=1e-4)
    assert LITERATURE_BAND[0] < mu_pkg < LITERATURE_BAND[1]
