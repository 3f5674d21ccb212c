"""Compressibility of the sections (rotorlyap.model.compressibility) and its use in the loads.

Each test names the fact it checks.
"""

from __future__ import annotations

import math
from dataclasses import replace
from types import SimpleNamespace

import numpy as np
import pytest

from rotorlyap.analysis.functions import energy_function
from rotorlyap.jit import numba_available
from rotorlyap.model import compressibility as comp
from rotorlyap.model._generated import blade_model as gen
from rotorlyap.model.airfoil import LinearAirfoil
from rotorlyap.model.blade import Blade
from rotorlyap.model.equations import BladeEquations
from rotorlyap.model.parameters import BladeParameters
from rotorlyap.model.trim import hover_trim

PG = "prandtl-glauert"
TWO_PI = 2.0 * np.pi


# ------------------------------------------------------------------ the formulas
def test_factor_is_one_over_beta_below_the_cap_and_tends_to_one_at_rest():
    """1/sqrt(1 - M^2) below the cap; -> 1 as M -> 0 (to O(M^2): 1 + M^2/2)."""
    m = np.linspace(0.0, comp.MACH_CAP, 81)
    assert np.allclose(comp.prandtl_glauert_factor(m), 1.0 / np.sqrt(1.0 - m ** 2), rtol=1e-15, atol=0)
    small = np.array([1e-2, 1e-3, 1e-4])
    excess = comp.prandtl_glauert_factor(small) - 1.0
    assert np.allclose(excess, 0.5 * small ** 2, rtol=1e-3)
    assert comp.prandtl_glauert_factor(0.0) == 1.0


def test_factor_is_held_at_its_cap_value_above_the_cap():
    """Above M_cap the factor is constant (finite at M >= 1), continuous at the cap."""
    cap = comp.MACH_CAP
    held = 1.0 / math.sqrt(1.0 - cap * cap)
    above = comp.prandtl_glauert_factor(np.array([cap, cap + 1e-9, 0.95, 1.0, 1.5]))
    assert np.all(above == held)
    assert comp.prandtl_glauert_factor(cap - 1e-9) == pytest.approx(held, rel=1e-8)


def test_factor_agrees_with_the_c81_naca0012_table_up_to_mach_06():
    """The evidence quoted in the module: at 2 deg the C81 NACA 0012 cl is cl(M=0)/beta within
    3 % up to M = 0.6; it exceeds the factor at 0.7-0.8 and has collapsed at 0.9."""
    table = comp.C81_NACA0012_CL_2DEG
    cl0 = table[0.0]
    for m, cl in table.items():
        ratio = cl / (cl0 * float(comp.prandtl_glauert_factor(min(m, 0.99))))
        if m <= 0.6:
            assert abs(ratio - 1.0) <= 0.035, (m, ratio)
        elif m <= 0.8:
            assert ratio > 1.0, (m, ratio)
    assert table[0.9] < cl0  # shocks: no linear factor describes it


def test_drag_rise_is_zero_below_critical_and_positive_monotone_above():
    """20 (M - M_crit)^4: zero up to M_crit, positive and increasing above, slope 0.1 at M_dd
    (the definition that fixes M_dd - M_crit = (0.1/80)^(1/3))."""
    for cl in (0.0, 0.5, -0.5):
        mc = float(comp.critical_mach(cl))
        mdd = float(comp.drag_divergence_mach(cl))
        assert mdd - mc == pytest.approx(comp.CRITICAL_MACH_OFFSET, abs=1e-15)
        below = np.linspace(0.0, mc, 50)
        assert np.all(comp.wave_drag(below, cl) == 0.0)
        above = np.linspace(mc + 1e-3, 1.2, 200)
        rise = comp.wave_drag(above, cl)
        assert np.all(rise > 0.0) and np.all(np.diff(rise) > 0.0)
        h = 1e-6
        slope = (comp.wave_drag(mdd + h, cl) - comp.wave_drag(mdd - h, cl)) / (2 * h)
        assert slope == pytest.approx(0.1, rel=1e-6)
    # Korn's equation for the NACA 23012 defaults: 0.87 - 0.12 - |cl|/10
    assert float(comp.drag_divergence_mach(0.3)) == pytest.approx(0.87 - 0.12 - 0.03, abs=1e-15)
    # more lift or more thickness: earlier divergence
    assert comp.drag_divergence_mach(0.6) < comp.drag_divergence_mach(0.2)
    assert comp.drag_divergence_mach(0.0, t_over_c=0.15) < comp.drag_divergence_mach(0.0, t_over_c=0.09)


def test_drag_rise_has_the_onset_and_size_of_the_c81_naca0012_table():
    """At 0 deg the table's cd rises between M = 0.75 and 0.8 and by 0.07 at 0.9; the law
    (M_crit = 0.642) gives under 0.003 up to 0.75 and within 30 % of the table at 0.9."""
    table = comp.C81_NACA0012_CD_0DEG
    rise = {m: table[m] - table[0.0] for m in table}
    assert float(comp.wave_drag(0.6)) == 0.0 and rise[0.6] == 0.0
    assert float(comp.wave_drag(0.75)) < 0.003 and rise[0.75] == 0.0
    assert rise[0.8] > 0.0 and float(comp.wave_drag(0.8)) > 0.0
    assert float(comp.wave_drag(0.9)) == pytest.approx(rise[0.9], rel=0.3)


def test_mach_factors_returns_the_lift_factor_and_the_drag_increment():
    """mach_factors = (prandtl_glauert_factor, wave_drag) for the same arguments."""
    m = np.array([0.0, 0.3, 0.65, 0.75, 0.9])
    f, cdw = comp.mach_factors(m, cl=0.4)
    assert np.array_equal(f, comp.prandtl_glauert_factor(m))
    assert np.array_equal(cdw, comp.wave_drag(m, 0.4))


def test_bad_input_raises_a_clear_value_error():
    """Negative or non-finite Mach numbers, bad constants and unknown models are refused."""
    with pytest.raises(ValueError, match="mach must be >= 0"):
        comp.prandtl_glauert_factor(-0.1)
    with pytest.raises(ValueError, match="mach must be >= 0"):
        comp.mach_factors(np.array([0.2, -1e-3]))
    with pytest.raises(ValueError, match="mach must be finite"):
        comp.wave_drag(np.nan)
    with pytest.raises(ValueError, match="mach_cap must lie in"):
        comp.prandtl_glauert_factor(0.5, mach_cap=1.0)
    with pytest.raises(ValueError, match="t_over_c must lie in"):
        comp.drag_divergence_mach(0.0, t_over_c=-0.1)
    with pytest.raises(ValueError, match="speed_of_sound must be"):
        comp.section_mach(100.0, 0.0)
    with pytest.raises(ValueError, match="compressibility must be one of"):
        BladeParameters(compressibility="karman-tsien")
    with pytest.raises(ValueError, match="compressibility must be one of"):
        comp.compressibility_constants(SimpleNamespace(compressibility="karman-tsien",
                                                       speed_of_sound=340.0, airfoil=None))
    with pytest.raises(ValueError, match="speed_of_sound must be > 0"):
        BladeParameters(speed_of_sound=-340.0)


# ------------------------------------------------------------------ the loads
def _terms(eq, psi, z):
    """The generated rows T for a block of states z (n, 6) at azimuths psi (n,)."""
    zc = np.ascontiguousarray(np.asarray(z, dtype=np.float64).T)
    return gen.rhs_terms(*zc, eq.pitch_control(psi), eq.parameter_values)


def _states(rng, n, spread, base=(0.05, 0.02, 0.15, 0.0, 0.0, 0.0)):
    z = np.array(base) + rng.normal(scale=spread, size=(n, 6))
    return rng.uniform(0.0, TWO_PI, n), z


def test_none_gives_the_incompressible_loads_bit_for_bit(monkeypatch):
    """With "none" the loads are those of the incompressible coefficients, bit for bit, and the
    speed of sound does not enter (numpy and compiled paths)."""
    base = replace(BladeParameters.table_i("forward"), collective=0.15)
    eq = BladeEquations(replace(base, twist=-0.1), 0.3)
    assert not eq.aero.compressibility.enabled
    rng = np.random.default_rng(5)
    psi, z = _states(rng, 300, 0.5)
    T = _terms(eq, psi, z)
    sFy, sFz, Mx, My, Mz, alpha = eq.aero.loads(psi, T)
    u_y, u_z = eq.aero.wind(psi, T)
    Vm = np.sqrt(u_y * u_y + u_z * u_z)
    cl, cd, _ = eq.params.airfoil.coefficients(alpha)
    qn = eq.aero._qn * Vm
    assert np.array_equal(sFz, (qn * (cd * u_z - cl * u_y)).sum(axis=0))
    assert np.array_equal(sFy, (qn * (cd * u_y + cl * u_z)).sum(axis=0))
    for kernel in (["numpy", "compiled"] if numba_available() else ["numpy"]):
        monkeypatch.setenv("ROTORLYAP_KERNEL", kernel)
        a = Blade(base, 0.3)
        b = Blade(replace(base, speed_of_sound=150.0), 0.3)
        assert np.array_equal(a.rhs(psi, z), b.rhs(psi, z))


@pytest.mark.parametrize("speed_of_sound", [340.294, 190.0])
def test_hover_lift_is_incompressible_lift_times_the_prandtl_glauert_factor(speed_of_sound):
    """One station, hover: the force normal to the wind (lift) with "prandtl-glauert" equals the
    incompressible one times 1/sqrt(1 - M^2), M = |w|/a of the station; the force along the
    wind (drag) grows by cd_wave(M, cl)/cd; at a = 190 m/s the station is past M_crit."""
    p = replace(BladeParameters.table_i("forward"), collective=0.15, n_stations=1,
                speed_of_sound=speed_of_sound)
    inc = BladeEquations(p, 0.0)
    com = BladeEquations(replace(p, compressibility=PG), 0.0)
    psi = np.linspace(0.0, TWO_PI, 7)
    z = np.tile([0.06, 0.01, 0.14, 0.0, 0.0, 0.0], (psi.size, 1))
    z[:, 3:] = np.random.default_rng(7).normal(scale=0.01, size=(psi.size, 3))
    T = _terms(inc, psi, z)
    u_y, u_z = (w[0] for w in inc.aero.wind(psi, T))
    V = np.hypot(u_y, u_z)
    mach = V / speed_of_sound
    Fy0, Fz0, *_, alpha = inc.aero.loads(psi, T)
    Fy1, Fz1, *_ = com.aero.loads(psi, T)
    lift0 = (Fy0 * u_z - Fz0 * u_y) / V
    lift1 = (Fy1 * u_z - Fz1 * u_y) / V
    drag0 = (Fy0 * u_y + Fz0 * u_z) / V
    drag1 = (Fy1 * u_y + Fz1 * u_z) / V
    factor = 1.0 / np.sqrt(1.0 - mach ** 2)
    assert np.all(np.abs(alpha[0]) < 0.5 * np.pi) and np.all(mach < comp.MACH_CAP)
    assert np.all(lift0 > 0.0)
    assert np.allclose(lift1, factor * lift0, rtol=1e-12)
    cl0, cd0, _ = p.airfoil.coefficients(alpha[0])
    cd_wave = comp.wave_drag(mach, factor * cl0)
    assert np.allclose(drag1, drag0 * (1.0 + cd_wave / cd0), rtol=1e-12)
    if speed_of_sound < 300.0:
        assert np.all(cd_wave > 0.0)  # the drag rise is on and checked
    else:
        assert np.all(cd_wave == 0.0)


CASES = [
    ("hover, Table I forward C.G.", {}, 0.0),
    ("forward flight, cyclic and twist", {"cyclic_cos": 0.02, "cyclic_sin": -0.05, "twist": -0.1}, 0.3),
    ("transonic: low speed of sound, past the cap", {"speed_of_sound": 170.0}, 0.4),
]


@pytest.mark.skipif(not numba_available(), reason="numba is not installed")
@pytest.mark.parametrize("label, changes, mu", CASES, ids=[c[0] for c in CASES])
def test_compiled_equals_numpy_with_compressibility(kernel_pair, label, changes, mu):
    """With "prandtl-glauert" the compiled kernels equal the numpy path to 1e-13 relative (rhs
    and the energy function's W'), over every branch: forward and reverse flow, stall, below and
    above M_crit and the cap."""
    params = replace(BladeParameters.table_i("forward"), collective=0.15, compressibility=PG, **changes)
    fast, slow = kernel_pair(params, mu)

    def close(a, b):
        scale = np.max(np.abs(b), axis=0, keepdims=True)
        assert np.all(np.abs(a - b) <= 1e-13 * scale + 1e-300)

    rng = np.random.default_rng(11)
    for spread in (0.01, 0.5, 3.0):
        psi, z = _states(rng, 2000, spread)
        close(fast.rhs(psi, z), slow.rhs(psi, z))
    psi = np.repeat(np.linspace(0.0, TWO_PI, 12, endpoint=False), 40)
    x = rng.normal(scale=0.1, size=(psi.size, 6))
    xi = np.array([0.05, 0.01, 0.15, 0.0, 0.0, 0.0])
    close(energy_function(fast, xi).dW(psi, x)[:, None], energy_function(slow, xi).dW(psi, x)[:, None])
    # the compressibility branch is exercised: the loads differ from the incompressible ones
    inc = Blade(replace(params, compressibility="none"), mu)
    psi, z = _states(rng, 50, 0.01)
    assert not np.allclose(inc.rhs(psi, z), slow.rhs(psi, z), rtol=1e-6, atol=0)


def test_hover_trim_with_compressibility_needs_less_collective():
    """Compressibility raises the effective lift slope (factor > 1 at every station), so thrust
    = weight is met with less collective; the trim still converges."""
    inc = hover_trim(BladeParameters())
    pg = hover_trim(BladeParameters(compressibility=PG))
    assert np.isfinite(pg.collective) and 0.0 < pg.collective < inc.collective
    blade = Blade(replace(BladeParameters(compressibility=PG), collective=pg.collective), 0.0)
    thrust = float(blade.rotor_thrust(0.0, np.asarray(pg.equilibrium)))
    weight = blade.params.helicopter_mass * blade.params.gravity
    assert thrust == pytest.approx(weight, rel=1e-6)


# ------------------------------------------------------------------ the validity map
OMEGA_R_OVER_A = 28.35 * 7.85 / 340.294


@pytest.fixture(scope="module")
def pg_blade():
    return Blade(BladeParameters(compressibility=PG), 0.0)


def test_validity_map_in_hover_has_no_reverse_flow_and_the_tip_mach_omega_r_over_a(pg_blade):
    """Hover equilibrium: no reverse flow, the same Mach at every azimuth, and at the outermost
    station M = Omega r / a (= 0.654 r/R) within 1 %."""
    vm = comp.validity_map(pg_blade, pg_blade.equilibrium(), n_azimuth=16)
    assert vm.mach.shape == vm.alpha.shape == (16, pg_blade.params.n_stations)
    assert not vm.reverse_flow.any()
    assert np.allclose(vm.mach, vm.mach[0], rtol=1e-12)
    r_tip = vm.r_over_R[-1]
    assert vm.mach[0, -1] == pytest.approx(OMEGA_R_OVER_A * r_tip, rel=0.01)
    assert np.all(np.diff(vm.mach[0]) > 0.0)  # faster outboard
    assert vm.fraction_outside == pytest.approx(vm.outside.mean())
    assert vm.stall_angles == (pg_blade.params.airfoil.alpha_stall_negative,
                               pg_blade.params.airfoil.alpha_stall)
    assert not vm.stall_angles_assumed


def test_validity_map_at_mu_03_shows_reverse_flow_retreating_inboard_and_a_fast_advancing_tip(pg_blade):
    """mu = 0.3, the hover state at every azimuth: reverse flow at psi = 270 deg exactly inboard
    of r/R = mu (stations farther than 0.03 R from it), none on the advancing side; the
    advancing tip's Mach is (r/R + mu) Omega R / a within 1 %, beyond Korn's M_dd (flagged)."""
    mu = 0.3
    blade = Blade(BladeParameters(compressibility=PG), mu)
    vm = comp.validity_map(blade, pg_blade.equilibrium(), n_azimuth=24)
    k270 = int(np.argmin(np.abs(vm.psi - 1.5 * np.pi)))
    clear = np.abs(vm.r_over_R - mu) > 0.03
    assert np.array_equal(vm.reverse_flow[k270][clear], (vm.r_over_R < mu)[clear])
    assert vm.reverse_flow[k270].any()
    advancing = vm.psi <= np.pi
    assert not vm.reverse_flow[advancing].any()
    k90 = int(np.argmin(np.abs(vm.psi - 0.5 * np.pi)))
    assert vm.mach[k90, -1] == pytest.approx((vm.r_over_R[-1] + mu) * OMEGA_R_OVER_A, rel=0.01)
    assert np.argmax(vm.mach) % vm.mach.shape[1] == vm.mach.shape[1] - 1  # fastest at the tip
    assert vm.mach.max() == pytest.approx(vm.mach[k90, -1], rel=0.01)  # near psi = 90 deg
    assert vm.mach[k90, -1] > (1.0 + mu) * OMEGA_R_OVER_A * 0.98
    assert vm.transonic[k90, -1] and vm.mach[k90, -1] > vm.drag_divergence_mach[k90, -1]
    assert vm.outside[k270][vm.r_over_R < mu - 0.03].all()
    assert 0.0 < vm.fraction_outside < 1.0


def test_validity_map_accepts_tables_and_callables_and_falls_back_for_other_airfoils():
    """A constant state, a table (n_psi, 6) and a callable xi(psi) give the same map; an airfoil
    without stall angles uses +-DEFAULT_STALL_ANGLE and says so; bad shapes raise."""
    p = replace(BladeParameters(), airfoil=LinearAirfoil(), collective=0.15)
    blade = Blade(p, 0.2)
    xi = np.array([0.05, 0.0, 0.15, 0.0, 0.0, 0.0])
    psi = np.linspace(0.0, TWO_PI, 9, endpoint=False)
    a = comp.validity_map(blade, xi, psi=psi)
    b = comp.validity_map(blade, np.tile(xi, (psi.size, 1)), psi=psi)
    c = comp.validity_map(blade, lambda s: np.tile(xi, (np.size(s), 1)), psi=psi)
    for other in (b, c):
        assert np.array_equal(a.mach, other.mach) and np.array_equal(a.outside, other.outside)
    assert a.stall_angles_assumed
    assert a.stall_angles == (-comp.DEFAULT_STALL_ANGLE, comp.DEFAULT_STALL_ANGLE)
    # stalled exactly where forward flow is beyond the angles
    fwd = ~a.reverse_flow
    assert np.array_equal(a.stalled, fwd & (np.abs(a.alpha) > comp.DEFAULT_STALL_ANGLE))
    with pytest.raises(ValueError, match="steady must be a state of shape"):
        comp.validity_map(blade, np.zeros(5), psi=psi)
    with pytest.raises(ValueError, match="stall_angles must be"):
        comp.validity_map(blade, xi, psi=psi, stall_angles=(0.1, 0.2))


def test_the_prandtl_glauert_factor_scales_lift_moment_and_pitch_damping_alike():
    """Linearised subsonic flow scales every pressure coefficient of a section by 1/beta: the
    corrected lift and moment, and the factor the strip loads apply to the pitch-damping couple,
    are all 1/sqrt(1 - M^2) in forward flow and 1 in reverse flow (where nothing is corrected)."""
    from rotorlyap.model.compressibility import apply_to_coefficients, compressibility_constants
    from rotorlyap.model.parameters import BladeParameters

    consts = compressibility_constants(BladeParameters(compressibility="prandtl-glauert"))
    a = BladeParameters().speed_of_sound
    alpha = np.array([0.05, -0.1, np.pi - 0.05])
    speed = np.array([0.5, 0.3, 0.2]) * a
    cl0, cd0, cm0 = np.array([0.5, -0.6, -0.4]), np.zeros(3), np.array([-0.01, 0.02, 0.03])
    cl, _, cm, f = apply_to_coefficients(alpha, speed, cl0, cd0, cm0, consts)
    beta_inv = 1.0 / np.sqrt(1.0 - (speed / a) ** 2)
    np.testing.assert_allclose(f, [beta_inv[0], beta_inv[1], 1.0], rtol=1e-14)
    np.testing.assert_allclose(cl, cl0 * f, rtol=1e-14)
    np.testing.assert_allclose(cm, cm0 * f, rtol=1e-14)
