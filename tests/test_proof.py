"""Proofs by ball arithmetic (rotorlyap.methods.intervals, rotorlyap.methods.proof,
rotorlyap.analysis.enclosure, rotorlyap.analysis.proof).

Facts checked:

* enclosures contain what they enclose: Jets (values, gradients, Hessians against sympy's exact
  derivatives at random points of the balls), eigenvalue bounds (every symmetric matrix sampled
  in the ball), the Hermite interpolants, the blade's right-hand side and Jacobian (the float
  model at random azimuths and states of the boxes, hover and the compressible forward flight)
  and the steady motion's residual;
* a linear periodic system whose Lyapunov matrix is known in closed form (a constant system seen
  from rotating axes, ``P(psi) = R(psi) P0 R(psi)^T``): the proof holds for every bound and its
  start radius is the closed form ``A sqrt(l_min(P0) / l_max(P0))``;
* the Mathieu-Duffing oscillator of chapter 1: proved, within the numerical certificate, and
  simulated motions from the proved start region stay inside the proved bound;
* the counterexample of chapter 2 (``pulsed_growth``, whose starts certified by the paper's rule
  escape): never proved;
* the blade: every Table I hover proved, the proof inside the numerical certificate, and ``W' < 0``
  at sampled states of the proved band (the float model); forward flight (slow).
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from rotorlyap.conventions import DEFAULT_SCALES
from rotorlyap.methods import intervals as iv
from rotorlyap.methods.examples import mathieu_duffing, mathieu_duffing_proof, pulsed_growth_proof
from rotorlyap.methods.lyapunov import technical_stability
from rotorlyap.methods.periodic_lyapunov import periodic_lyapunov
from rotorlyap.methods.proof import lyapunov_enclosure, prove_quadratic
from rotorlyap.methods.simulation import simulate
from rotorlyap.model.blade import Blade
from rotorlyap.analysis.enclosure import BladeEnclosure
from rotorlyap.methods.intervals import hermite_enclosure
from rotorlyap.model.parameters import BladeParameters
from rotorlyap.model.steady import tabulate_motion

RNG_SEED = 17


def _inside(x: float, ball, slack: float = 0.0) -> bool:
    lo, hi = iv.lower(np.asarray([ball], dtype=object))[0], iv.upper(np.asarray([ball], dtype=object))[0]
    return lo - slack <= x <= hi + slack


# --------------------------------------------------------------------------------------
# Ball arithmetic
# --------------------------------------------------------------------------------------

def composite_function():
    """f = sin(x y) + sqrt(1 + x^2) / (2 + cos y) - x / y: ``(exact, mid, rad, enclose)``, the exact
    value, gradient and Hessian (sympy, lambdified), three boxes (midpoints, radii) and the Jet of
    f over them in the current arithmetic (``enclose()``)."""
    X, Y = sp.symbols("x y")
    expr = sp.sin(X * Y) + sp.sqrt(1 + X**2) / (2 + sp.cos(Y)) - X / Y
    grad = [sp.diff(expr, v) for v in (X, Y)]
    hess = [[sp.diff(expr, u, v) for v in (X, Y)] for u in (X, Y)]
    mid = np.array([[0.3, 1.2], [-0.7, 2.5], [1.5, -0.8]])
    rad = np.array([0.05, 0.02])

    def enclose():
        x, y = iv.variables([iv.balls(mid[:, 0], rad[0]), iv.balls(mid[:, 1], rad[1])], order=2)
        return iv.sin(x * y) + iv.sqrt(1 + x * x) / (2 + iv.cos(y)) - x / y

    return sp.lambdify((X, Y), [expr, grad, hess]), mid, rad, enclose


def test_jets_enclose_values_gradients_and_hessians_of_a_composite_function():
    """f = sin(x y) + sqrt(1 + x^2) / (2 + cos y) - x / y: the Jet over a box contains the exact
    value, gradient and Hessian (sympy) at random points of the box."""
    f, mid, rad, enclose = composite_function()
    out = enclose()
    rng = np.random.default_rng(RNG_SEED)
    for k in range(mid.shape[0]):
        for _ in range(50):
            p = mid[k] + rad * rng.uniform(-1, 1, 2)
            value, g, h = f(*p)
            assert _inside(value, out.v[k])
            for i in range(2):
                assert _inside(g[i], out.d[i, k])
                for j in range(2):
                    assert _inside(h[i][j], out.h[i, j, k])


def test_eigenvalue_bounds_contain_every_symmetric_matrix_of_the_ball_and_are_tight():
    """symmetric_eigenvalue_bounds: the eigenvalues of symmetric matrices sampled in the ball lie
    within the bounds; for a thin ball the bounds are the eigenvalues to 1e-12."""
    rng = np.random.default_rng(RNG_SEED)
    n = 6
    C = rng.normal(size=(4, n, n))
    C = C + np.swapaxes(C, 1, 2)
    R = np.full((4, n, n), 1e-3)
    lo, hi = iv.symmetric_eigenvalue_bounds(iv.balls(C, R))
    for _ in range(200):
        E = rng.uniform(-1, 1, size=(4, n, n)) * R
        ev = np.linalg.eigvalsh(C + 0.5 * (E + np.swapaxes(E, 1, 2)))
        assert np.all(ev[:, 0] >= lo) and np.all(ev[:, -1] <= hi)
    lo0, hi0 = iv.symmetric_eigenvalue_bounds(iv.balls(C))
    ev = np.linalg.eigvalsh(C)
    assert np.allclose(lo0, ev[:, 0], rtol=0, atol=1e-12 * np.abs(ev).max())
    assert np.allclose(hi0, ev[:, -1], rtol=0, atol=1e-12 * np.abs(ev).max())


def test_a_ball_that_cannot_be_enclosed_gives_no_bound():
    """1 / [-1, 1] and sqrt([-1, 1]) are not finite: every bound is infinite, never a number."""
    x = iv.balls([0.0], [1.0])
    assert not np.isfinite(iv.upper(1 / x)).all()
    assert not np.isfinite(iv.magnitude(iv.sqrt(x))).all()


def test_hermite_enclosure_contains_the_interpolant_and_its_derivatives():
    """The balls of hermite_enclosure contain TabulatedMotion.xi and .dxi at random azimuths of
    each interval (fine intervals, 4 per piece, and coarse ones spanning 4 pieces)."""
    params = BladeParameters.table_i("forward", collective=np.radians(8.0))
    from rotorlyap.model.steady import periodic_motion

    tab = tabulate_motion(periodic_motion(params, 0.2, n_points=16), n=64)
    rng = np.random.default_rng(RNG_SEED)
    for n in (256, 16):
        value, deriv = hermite_enclosure(tab.values, tab.slopes, n)
        lo_v, hi_v, lo_d, hi_d = iv.lower(value), iv.upper(value), iv.lower(deriv), iv.upper(deriv)
        k = rng.integers(0, n, 400)
        psi = 2 * np.pi * (k + rng.uniform(0, 1, k.size)) / n
        xi, dxi = tab.xi(psi), tab.dxi(psi)
        tol = 1e-12
        assert np.all((lo_v[k] - tol <= xi) & (xi <= hi_v[k] + tol))
        assert np.all((lo_d[k] - tol <= dxi) & (dxi <= hi_d[k] + tol))


# --------------------------------------------------------------------------------------
# The blade's enclosures
# --------------------------------------------------------------------------------------

def _check_blade_box(blade, tab, n, radius, n_samples=40, arithmetic=None):
    """The enclosure (``arithmetic`` as BladeEnclosure takes it) contains the float right-hand
    side and its central-difference Jacobian at random states of the box; returns it."""
    enc = BladeEnclosure(blade, tab, arithmetic=arithmetic)
    ev = enc.evaluate(n, radius=radius)
    assert not ev.blocked
    lo_v, hi_v = iv.lower(ev.value), iv.upper(ev.value)
    lo_j, hi_j = iv.lower(ev.jacobian), iv.upper(ev.jacobian)
    rng = np.random.default_rng(RNG_SEED)
    k = rng.integers(0, n, n_samples)
    psi = 2 * np.pi * (k + rng.uniform(0, 1, k.size)) / n
    if tab is None:
        xi, dxi = np.broadcast_to(blade.equilibrium(), (k.size, 6)), np.zeros((k.size, 6))
    else:
        xi, dxi = tab.xi(psi), tab.dxi(psi)
    z = xi + radius * rng.uniform(-1, 1, (k.size, 6))
    value = blade.rhs(psi, z) - dxi
    scale = np.abs(value).max() + 1.0
    assert np.all(lo_v[k] - 1e-12 * scale <= value) and np.all(value <= hi_v[k] + 1e-12 * scale)
    J = blade.jacobian(psi, z)  # central differences: about 1e-8 relative
    slack = 1e-6 * (np.abs(J).max() + 1.0)
    assert np.all(lo_j[k] - slack <= J) and np.all(J <= hi_j[k] + slack)
    return ev


def test_blade_enclosure_contains_the_float_model_in_hover():
    """Hover, backward C.G.: the right-hand side and its Jacobian at random states of the box
    |x_i| <= 0.2 a_i lie in the balls."""
    blade = Blade(BladeParameters.table_i("backward"), 0.0)
    _check_blade_box(blade, None, 1, 0.2 * DEFAULT_SCALES)


def test_blade_enclosure_contains_the_float_model_in_compressible_forward_flight():
    """The trimmed helicopter at mu = 0.1 (Pitt-Peters inflow, compressible sections, cyclic pitch)
    about its tabulated periodic motion, on 64 azimuth intervals."""
    from rotorlyap.model.forward_trim import forward_flight_trim

    trim = forward_flight_trim(BladeParameters.flight_case("forward"), 0.1)
    blade = Blade(trim.params, 0.1)
    assert blade.params.compressibility == "prandtl-glauert"
    _check_blade_box(blade, tabulate_motion(trim.motion, n=256), 64, 0.1 * DEFAULT_SCALES)


def test_reverse_flow_blocks_the_enclosure_on_the_retreating_side_only():
    """At mu = 0.15 the inboard station enters reverse flow on the retreating side, where the angle
    of attack of a compressible section crosses 90 deg and the Prandtl-Glauert factor jumps: the
    enclosure marks those intervals (180 < psi < 360 deg) and no others."""
    from rotorlyap.model.forward_trim import forward_flight_trim

    trim = forward_flight_trim(BladeParameters.flight_case("forward"), 0.15)
    ev = BladeEnclosure(Blade(trim.params, 0.15), tabulate_motion(trim.motion, n=256)).evaluate(64)
    (reason, mask), = ev.blocked.items()
    assert "90 deg" in reason and mask.any()
    psi = 360.0 * (np.flatnonzero(mask) + 0.5) / 64
    assert np.all((psi > 180) & (psi < 360))
    assert not np.isfinite(iv.upper(ev.value[mask])).all()


def test_residual_enclosure_contains_the_float_residual():
    """BladeEnclosure.residual (the mean-value form in the azimuth) contains h(psi, xi) - xi' at
    random azimuths of each interval."""
    from rotorlyap.model.forward_trim import forward_flight_trim

    trim = forward_flight_trim(BladeParameters.flight_case("forward"), 0.1)
    blade = Blade(trim.params, 0.1)
    tab = tabulate_motion(trim.motion, n=128)
    g0, blocked = BladeEnclosure(blade, tab).residual(256)
    assert not blocked
    lo, hi = iv.lower(g0), iv.upper(g0)
    rng = np.random.default_rng(RNG_SEED)
    k = rng.integers(0, 256, 200)
    psi = 2 * np.pi * (k + rng.uniform(0, 1, k.size)) / 256
    r = blade.rhs(psi, tab.xi(psi)) - tab.dxi(psi)
    slack = 1e-12 * (np.abs(r).max() + 1)
    assert np.all(lo[k] - slack <= r) and np.all(r <= hi[k] + slack)


def test_blade_enclosure_rejects_what_it_cannot_enclose():
    """An airfoil without a table, a periodic motion that is not tabulated: clear errors."""
    import dataclasses

    params = BladeParameters.table_i("forward")
    no_table = dataclasses.replace(params, airfoil=dataclasses.replace(params.airfoil, table_size=0))
    with pytest.raises(ValueError, match="tabulated airfoil"):
        BladeEnclosure(Blade(no_table, 0.0))
    blade = Blade(params, 0.1)
    with pytest.raises(ValueError, match="TabulatedMotion"):
        BladeEnclosure(blade, (lambda p: np.zeros(np.shape(p) + (6,)) + np.cos(p)[..., None],
                               lambda p: np.zeros(np.shape(p) + (6,)) - np.sin(p)[..., None]))


def test_prove_blade_rejects_options_that_do_not_go_together():
    """The level set's proof needs its shells (a fixed level per bound), the Taylor models float
    balls, and the method is one of two: clear errors, not a silent other proof."""
    from rotorlyap.analysis.functions import quadratic_function
    from rotorlyap.analysis.proof import prove_blade

    fun = quadratic_function(Blade(BladeParameters.table_i("forward"), 0.0))
    with pytest.raises(ValueError, match="level_set needs the proof over shells"):
        prove_blade(fun, 0.1, shells=False)
    with pytest.raises(ValueError, match="float balls"):
        prove_blade(fun, 0.1, arithmetic="arb")
    with pytest.raises(ValueError, match="method must be"):
        prove_blade(fun, 0.1, method="sos")


# --------------------------------------------------------------------------------------
# Systems with known answers
# --------------------------------------------------------------------------------------

class _Rotating:
    """``x' = A(psi) x`` with ``A = R' R^T + R A0 R^T`` (``R`` the rotation by ``psi``): the
    constant system ``z' = A0 z`` seen from rotating axes. ``P(psi) = R P0 R^T`` with
    ``A0^T P0 + P0 A0 = -I`` solves the periodic Lyapunov equation with ``Q = I``."""

    n = 2
    A0 = np.array([[-0.3, 1.0], [-2.0, -0.5]])

    @staticmethod
    def A(psi):
        c, s = np.cos(psi), np.sin(psi)
        R = np.array([[c, -s], [s, c]])
        Rp = np.array([[-s, -c], [c, -s]])
        return Rp @ R.T + R @ _Rotating.A0 @ R.T

    def _balls(self, N):
        psi = iv.psi_intervals(N)
        c, s = iv.cos(psi), iv.sin(psi)
        (a, b), (cc, d) = self.A0
        J = iv.zeros((N, 2, 2))
        # R A0 R^T written out, plus R' R^T = [[0, -1], [1, 0]]
        J[:, 0, 0] = a * c * c - (b + cc) * c * s + d * s * s
        J[:, 0, 1] = b * c * c + (a - d) * c * s - cc * s * s - 1
        J[:, 1, 0] = cc * c * c + (a - d) * c * s - b * s * s + 1
        J[:, 1, 1] = d * c * c + (b + cc) * c * s + a * s * s
        return J

    def residual(self, N):
        return iv.zeros((N, 2)), {}

    def linear(self, N):
        return self._balls(N)

    def averaged_jacobian(self, N, radius):
        return self._balls(N), {}


def test_linear_periodic_system_reproduces_the_closed_form_start_radius():
    """The rotating system: its closed-form A(psi) is what the ball version encloses; the proof
    holds at any bound (here 1e3, the first tried); its start radius never exceeds the closed form
    A sqrt(l_min(P0) / l_max(P0)) and converges to it as the azimuth intervals shrink (the
    eigenvalue bounds over an interval widen with its length h: the shortfall falls like h)."""
    from scipy.linalg import solve_continuous_lyapunov

    sys = _Rotating()
    J = sys._balls(8)
    for k in range(8):
        psi = 2 * np.pi * (k + 0.37) / 8
        assert np.all(iv.lower(J[k]) <= sys.A(psi)) and np.all(sys.A(psi) <= iv.upper(J[k]))
    sol = periodic_lyapunov(lambda p: np.stack([sys.A(q) for q in np.atleast_1d(p)]).reshape(np.shape(p) + (2, 2)),
                            2 * np.pi, np.eye(2), method="magnus6", n_steps=256, vectorized=True)
    P0 = solve_continuous_lyapunov(_Rotating.A0.T, -np.eye(2))
    ev = np.linalg.eigvalsh(P0)
    closed = 1e3 * np.sqrt(ev[0] / ev[1])
    shortfall, linear = [], []
    for N in (512, 2048):
        proof = prove_quadratic(sys, lyapunov_enclosure(sol), 1e3, scales=[1.0, 1.0], n_intervals=N)
        assert proof.proved and proof.A == 1e3 and proof.tried == ((1e3, True),)
        assert proof.min_lambda0 <= closed * (1 + 1e-6)
        linear.append(np.max(proof.terms["linear"]))  # S' + A^T S + S A = -I, enclosed over intervals
        shortfall.append(1 - proof.min_lambda0 / closed)
    assert shortfall[1] < 0.005 and 3.0 < shortfall[0] / shortfall[1] < 5.0
    assert linear[1] < linear[0] < 0 and linear[1] < -0.9


def test_the_oscillator_of_chapter_1_is_proved_within_its_numerical_certificate():
    """Mathieu-Duffing (chapter 1): a proof exists; its bound is below the numerical certificate's
    (the proof is conservative, never the other way round), and motions simulated from the proved
    start radius at 24 azimuths, in 16 directions each, stay inside the proved bound for 20
    periods."""
    system, quadratic = mathieu_duffing_proof()
    proof = prove_quadratic(system, quadratic, 1.0, scales=[1.0, 1.0], n_intervals=256)
    assert proof.proved
    s = mathieu_duffing()
    numerical = technical_stability(s.f, s.W, 1.0, dim=2, dW=s.dW, n_psi=72, rule="sound")
    assert 0 < proof.A <= numerical.A * 1.001
    assert proof.level <= numerical.alpha * (proof.A / numerical.A) ** 2 * (1 + 1e-9)
    angles = 2 * np.pi * np.arange(16) / 16
    u = np.stack([np.cos(angles), np.sin(angles)], axis=1)
    for j in range(0, 256, 256 // 24):
        sim = simulate(s.f, 0.999 * proof.lambda0[j] * u, proof.psi[j], 20.0)
        assert np.all(sim.max_norm < proof.A)


def test_the_counterexample_is_never_proved():
    """pulsed_growth (chapter 2: the paper's rule certifies starts that escape): the linearised
    motion grows, and the proof says so at every bound tried."""
    system, quadratic = pulsed_growth_proof()
    proof = prove_quadratic(system, quadratic, 1.0, scales=[1.0], n_intervals=64)
    assert not proof.proved and proof.A == 0.0 and not np.any(proof.lambda0)
    assert all(not ok for _, ok in proof.tried)
    assert "linear part" in proof.message


def test_prove_quadratic_rejects_bad_input():
    system, quadratic = mathieu_duffing_proof()
    for A in (0.0, -1.0, np.inf):
        with pytest.raises(ValueError, match="A must be"):
            prove_quadratic(system, quadratic, A, scales=[1.0, 1.0])
    with pytest.raises(ValueError, match="scales"):
        prove_quadratic(system, quadratic, 1.0, scales=[1.0])
    with pytest.raises(ValueError, match="n_intervals"):
        prove_quadratic(system, quadratic, 1.0, scales=[1.0, 1.0], n_intervals=0)


# --------------------------------------------------------------------------------------
# The blade
# --------------------------------------------------------------------------------------

@pytest.mark.parametrize("cg", ["forward", "neutral", "backward"])
def test_every_table_i_hover_is_proved_within_its_numerical_certificate(cg):
    """certify(verify=True) of the quadratic function in hover: a proof exists, its bound and start
    region lie inside the numerical certificate's (the start radius up to round-off: both are
    ``A sqrt(min l / max s)``, the proof's from rigorous eigenvalue bounds), and the float W' is
    negative at 2000 states sampled on the proved level set ``W = c``."""
    from rotorlyap import certify

    cert = certify(BladeParameters.table_i(cg), 0.0, function="quadratic", verify=True)
    assert cert.proved_part.function == "quadratic" and cert.proved_part.proved
    proof = cert.proof
    assert cert.certified and proof.proved
    assert 0 < proof.A <= cert.bound and 0 < proof.min_lambda0 <= cert.start_region * (1 + 1e-9)
    assert "level set" in proof.message
    from rotorlyap.analysis.functions import quadratic_function

    q = quadratic_function(Blade(cert.trim.params, 0.0), cert.trim.steady)
    rng = np.random.default_rng(RNG_SEED)
    u = rng.normal(size=(2000, 6))
    u /= np.linalg.norm(u, axis=1)[:, None]
    S = q.solution.P_grid[0]
    w_unit = np.einsum("mi,ij,mj->m", u, S, u)
    r_in = np.sqrt(proof.level / w_unit)  # where W = c along each ray: the level set
    assert np.all(r_in <= proof.A * (1 + 1e-9))
    x = u * r_in[:, None] * q.scales
    assert np.all(q.dW(np.zeros(x.shape[0]), x) < 0)


@pytest.mark.slow
def test_a_forward_flight_case_is_proved():
    """The trimmed helicopter at mu = 0.1 (forward C.G., compressible sections, Pitt-Peters):
    certify(verify=True) refines the periodic motion by shooting and proves the certificate, and the
    float W' is negative on the proved level set."""
    from rotorlyap import certify

    from rotorlyap.analysis.functions import quadratic_function
    from rotorlyap.model.steady import refine_motion

    cert = certify(BladeParameters.flight_case("forward"), 0.1, function="quadratic", verify=True)
    proof = cert.proof
    assert cert.certified and proof.proved
    assert 0 < proof.A <= cert.bound
    assert proof.n_intervals == 4096
    # the float W' is negative at 4000 states sampled on the proved level set W = c, at random azimuths
    blade = Blade(cert.trim.params, 0.1)
    motion = refine_motion(blade, cert.trim.motion)
    q = quadratic_function(blade, motion.steady)
    rng = np.random.default_rng(RNG_SEED)
    psi = rng.uniform(0, 2 * np.pi, 4000)
    u = rng.normal(size=(psi.size, 6))
    u /= np.linalg.norm(u, axis=1)[:, None]
    w_unit = q.W(psi, u * q.scales)
    r_in = np.sqrt(proof.level / w_unit)
    assert np.all(r_in <= proof.A * (1 + 1e-9))
    x = u * r_in[:, None] * q.scales
    assert np.all(q.dW(psi, x) < 0)
    # what limits it (chapter 9's account, on 16 model intervals to keep the test short): the
    # models' remainder over the cube of the proved bound is largest on the retreating side, it
    # comes from the innermost strips, whose angle of attack there reaches past the airfoil's
    # negative stall, and without their air loads it is no larger than on the advancing side
    from rotorlyap.analysis.proof import remainder_sources

    src = remainder_sources(cert.lyapunov, proof.A, n_models=16)
    k = src.worst
    assert src.psi[k] > np.pi
    assert len(src.sources) >= 1 and src.sources == tuple(range(len(src.sources)))
    assert np.min(src.angles[list(src.sources), 0]) < cert.trim.params.airfoil.alpha_stall_negative
    assert np.all(src.without[list(src.sources)] < src.remainder[k])
    assert src.without_sources <= src.remainder[src.psi < np.pi].max()
    assert f"psi = {np.degrees(src.psi[k]):.0f} deg" in src.summary()


def test_remainder_sources_in_hover_and_bad_input():
    """In hover (one interval) the Table I blade's small remainder is carried by no single strip;
    a bound that is not finite and > 0 is refused; strips of the wrong count are refused."""
    from rotorlyap.analysis.enclosure import BladeEnclosure
    from rotorlyap.analysis.functions import quadratic_function
    from rotorlyap.analysis.proof import remainder_sources
    from rotorlyap.analysis.taylor_enclosure import taylor_evaluate

    blade = Blade(BladeParameters.table_i("forward"), 0.0)
    fun = quadratic_function(blade)
    src = remainder_sources(fun, 0.5)
    assert src.psi.shape == (1,) and src.sources == () and src.without_sources == src.remainder[0]
    assert np.all(np.isfinite(src.angles)) and np.all(src.angles[:, 0] <= src.angles[:, 1])
    assert "no strip" in src.summary()
    for bad in (0.0, -1.0, np.nan, np.inf):
        with pytest.raises(ValueError, match="bound must be finite"):
            remainder_sources(fun, bad)
    enc = BladeEnclosure(blade, None, arithmetic="balls")
    with pytest.raises(ValueError, match="one flag per aerodynamic station"):
        taylor_evaluate(enc, np.zeros(6), np.full(6, 1e-3), 2, strips=[True, False])
