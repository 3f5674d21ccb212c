"""The blade in the engine: readings, the caution, and soundness of what is certified.

Soundness: whatever the strict reading certifies must be true of the model. The tests
simulate the full nonlinear equations from many states inside lambda0 and search the shell
in the directions the READING.md caution names (small rates with displacements).
"""

import dataclasses

import numpy as np
import pytest

from rotorlyap import Blade, BladeParameters, simulate
from rotorlyap.analysis.functions import energy_function, energy_rate_terms
from rotorlyap.analysis.stability import blade_stability
from rotorlyap.conventions import DEFAULT_SCALES, PAPER_TEST_DISTURBANCES


def test_energy_function_certifies_nothing_in_hover_strict_reading(forward):
    """READING.md's caution on the real model: W' > 0 on every sphere, so A = 0."""
    res = blade_stability(forward, 0.0, n_psi=8)
    assert res.reading == "strict"
    assert res.A == 0.0 and not res.stable.any() and not res.certified
    assert res.step3_max_dW > 0


@pytest.mark.parametrize("cg", ["forward", "neutral", "backward"])
def test_pitch_displacement_with_small_flap_rate_gives_positive_dW_on_every_sphere(cg):
    """The caution's mechanism, found by construction (no search).

    At x = rho (a_theta e_theta + eps a_beta' e_beta'), W' = eps rho^2 a_beta' (dQ_beta /
    dtheta) a_theta + O(eps^2): the aerodynamic flap moment due to pitch, with no matching
    pitch moment due to flap, makes W' > 0 for a small flap rate of the right sign, on
    spheres of every radius from 1e-3 to 1.
    """
    p = BladeParameters.table_i(cg=cg)
    blade = Blade(p, 0.0)
    fun = energy_function(blade)
    a = DEFAULT_SCALES
    for rho in (1e-3, 1e-2, 1e-1, 1.0):
        eps = np.linspace(-0.2, 0.2, 81)
        x = rho * np.outer(np.ones_like(eps), a * np.eye(6)[2]) + rho * np.outer(eps, a * np.eye(6)[3])
        assert fun.dW(0.0, x).max() > 0, rho


def test_practical_reading_sees_no_positive_dW_along_the_axes_in_hover(forward):
    """Along pure displacements W' = 0 (no rate, no work); along pure rates W' < 0.

    So the practical reading along the 12 signed axes reports every azimuth stable in hover
    (an indicator, never a certificate).
    """
    blade = Blade(forward, 0.0)
    fun = energy_function(blade)
    x = 0.5 * PAPER_TEST_DISTURBANCES * DEFAULT_SCALES
    dw = fun.dW(0.0, x)
    np.testing.assert_allclose(dw[[0, 1, 2, 6, 7, 8]], 0.0, atol=1e-9)
    assert np.all(dw[[3, 4, 5, 9, 10, 11]] < 0)
    res = blade_stability(forward, 0.0, n_psi=8, test_disturbances=PAPER_TEST_DISTURBANCES)
    assert res.reading == "practical" and res.stable.all() and not res.certified


def test_energy_rate_terms_add_up_to_dW(forward):
    """The damping and aerodynamic work rates per hinge sum to the energy function's W'."""
    xi = Blade(forward, 0.0).equilibrium()
    rng = np.random.default_rng(3)
    x = rng.normal(size=(50, 6)) * DEFAULT_SCALES
    psi = rng.uniform(0, 2 * np.pi, 50)
    for mu in (0.0, 0.2):
        blade = Blade(forward, mu)
        terms = energy_rate_terms(blade, xi, psi, x)
        np.testing.assert_allclose(terms["total"], energy_function(blade, xi).dW(psi, x), rtol=1e-9, atol=1e-9)


def vacuum_blade(**kw):
    """Table I blade in vacuum with dampers on every hinge: W' = -damping power <= 0."""
    return dataclasses.replace(
        BladeParameters.table_i(cg="forward"), air_density=0.0, collective=0.12, inflow_ratio=0.05,
        flap_damping=3000.0, pitch_damping=300.0, **kw,
    )


@pytest.mark.slow
@pytest.mark.parametrize("mu", [0.0, 0.15])
def test_certified_start_regions_are_bounded_in_simulation(mu):
    """Soundness: from states inside lambda0, the nonlinear motion stays inside ||x|| < A.

    Vacuum blade with hinge dampers: the energy function certifies, and 64 motions started
    at 0.99 lambda0 at four certified azimuths, integrated for 8 periods, never reach the
    bound. (In vacuum the advance ratio has no effect; certificates with air come from the
    quadratic Liapunov function, tested with it.) In vacuum nothing depends on the azimuth, so
    the paper's rule (step 6 at each start azimuth) is the theorem's (h); it is the rule used
    here because the energy's W' = -(damper rates)^2 is only semi-definite (zero wherever the
    hinge rates vanish), which the sound rule's margin, W' below a negative fraction of W,
    declines by design.
    """
    p = vacuum_blade()
    res = blade_stability(p, mu, n_psi=12, n_sphere=256, rule="paper")
    assert res.reading == "strict" and res.certified
    blade = Blade(p, mu)
    fun = energy_function(blade)
    rng = np.random.default_rng(7)
    worst = 0.0
    for j in np.flatnonzero(res.stable)[:: max(1, res.stable.sum() // 4)][:4]:
        u = rng.normal(size=(16, 6))
        u /= np.linalg.norm(u, axis=1, keepdims=True)
        x0 = 0.99 * res.lambda0[j] * u * res.scales
        sim = simulate(fun.f, x0, res.psi[j], 8, scales=res.scales, rtol=1e-8, atol=1e-10)
        worst = max(worst, sim.max_norm.max())
    assert worst < res.A


def test_nothing_certified_about_a_steady_motion_that_is_not_a_solution():
    """With cyclic pitch the hover equilibrium is no longer a solution: f(psi, 0) != 0.

    W' then has a term linear in the disturbed rates (the work of the cyclic spring force),
    -c |x_r|^2 + b(psi) . x_r, positive for small rates along b on every sphere: even in
    vacuum with dampers the energy function certifies nothing about the paper's choice of
    steady motion.
    """
    p = vacuum_blade(cyclic_sin=0.03)
    res = blade_stability(p, 0.15, n_psi=8, n_sphere=256)
    assert res.A == 0.0 and not res.certified


def test_targeted_search_finds_no_positive_dW_where_certified():
    """Where the paper's rule certifies, small rates combined with displacements (the
    caution's directions) give no W' > 0 on the shell lambda0 < ||x|| <= A.

    In vacuum the energy's W' is the hinge dampers' dissipation, zero wherever the rates are:
    W' <= 0 holds (the paper's rule certifies) but never below a negative margin, so the sound
    rule, which asks W' < -margin on the band, declines it.
    """
    p = vacuum_blade()
    res = blade_stability(p, 0.0, n_psi=4, n_sphere=256, rule="paper")
    assert res.certified
    assert not blade_stability(p, 0.0, n_psi=4, n_sphere=256).certified
    fun = energy_function(Blade(p, 0.0))
    eye = np.eye(6)
    dirs = []
    for i in range(3):
        for k in range(3, 6):
            for eps in (-0.3, -0.1, -0.03, 0.03, 0.1, 0.3):
                for s in (1.0, -1.0):
                    dirs.append(s * eye[i] + eps * eye[k])
    dirs = np.array(dirs)
    dirs /= np.linalg.norm(dirs, axis=1, keepdims=True)
    for j in range(res.psi.size):
        radii = np.linspace(res.lambda0[j], res.A, 7)
        x = (radii[:, None, None] * dirs[None] * res.scales).reshape(-1, 6)
        assert fun.dW(res.psi[j], x).max() <= res.tol


@pytest.mark.parametrize(
    "kwargs, error, match",
    [
        (dict(mu=-0.1), ValueError, r"mu must be an advance ratio in \[0, 3\]"),
        (dict(mu=3.5), ValueError, r"mu must be an advance ratio"),
        (dict(steady=[0.0, 0.0]), ValueError, "steady must be None"),
        (dict(lyapunov=3), TypeError, "lyapunov must be callable"),
        (dict(scales=[1.0] * 5), ValueError, "scales must hold 6 positive numbers"),
        (dict(A=-1.0), ValueError, "A must be a finite number > 0"),
    ],
)
def test_bad_arguments_are_rejected(forward, kwargs, error, match):
    """Bad advance ratio, steady motion, Liapunov function, scales or bound: clear errors."""
    mu = kwargs.pop("mu", 0.0)
    with pytest.raises(error, match=match):
        blade_stability(forward, mu, n_psi=4, **kwargs)
    with pytest.raises(TypeError, match="params must be a BladeParameters"):
        blade_stability({"radius": 7.85}, 0.0)


def _fields(res) -> dict:
    """Every field of a result, arrays as bytes (bit-for-bit comparison), the counts included."""
    out = {}
    for f in dataclasses.fields(res):
        v = getattr(res, f.name)
        out[f.name] = v.tobytes() if isinstance(v, np.ndarray) else v
    return out


@pytest.mark.parametrize("rule", ["sound", "paper"])
def test_the_psi_free_search_is_the_full_search_bit_for_bit(rule):
    """In hover without cyclic pitch nothing depends on the azimuth, so computing one azimuth for
    all (``psi_free``) must change nothing: the same bound, level, start radii, largest W' and
    evaluation counts as the full search, to the last bit."""
    from rotorlyap.analysis.functions import quadratic_function
    from rotorlyap.analysis.stability import psi_free_system

    p = BladeParameters.table_i("neutral")
    opts = dict(lyapunov=quadratic_function, n_psi=6, n_sphere=64, rule=rule)
    blade = Blade(p, 0.0)
    steady = blade.equilibrium()
    fun = quadratic_function(blade, steady)
    from rotorlyap.model.steady import as_steady_motion, disturbed_rhs
    assert psi_free_system(blade, as_steady_motion(steady), disturbed_rhs(blade, steady), fun, DEFAULT_SCALES)
    fast = blade_stability(p, 0.0, **opts)
    full = blade_stability(p, 0.0, psi_free=False, **opts)
    assert fast.A > 0 and fast.stable.all()
    assert _fields(fast) == _fields(full)


def test_psi_free_is_refused_where_the_azimuth_matters():
    """The free stream (mu > 0) and cyclic pitch make the blade's equations depend on psi, and
    the probe sees a W that depends on it in its last bits: no psi-free search there."""
    from rotorlyap.analysis.functions import quadratic_function
    from rotorlyap.analysis.stability import psi_free_system, same_at_every_azimuth
    from rotorlyap.model.steady import as_steady_motion, disturbed_rhs

    def check(params, mu):
        blade = Blade(params, mu)
        steady = as_steady_motion(Blade(params, 0.0).equilibrium())
        fun = quadratic_function(blade, steady)
        return psi_free_system(blade, steady, disturbed_rhs(blade, steady), fun, DEFAULT_SCALES)

    p = BladeParameters.table_i("neutral")
    assert check(p, 0.0)
    assert not check(p, 0.05)
    assert not check(dataclasses.replace(p, cyclic_cos=0.01), 0.0)

    # the probe itself: a W with an azimuth ripple in its last bits is seen
    blade = Blade(p, 0.0)
    fun = quadratic_function(blade)
    assert same_at_every_azimuth((fun.W, fun.dW), DEFAULT_SCALES)
    rippled = lambda psi, x: fun.W(psi, x) * (1.0 + 1e-15 * np.cos(psi))  # noqa: E731
    assert not same_at_every_azimuth((fun.W, rippled), DEFAULT_SCALES)
