"""Checks of the symbolic derivation and of its cached generated code.

Each test names the fact it checks.
"""

from __future__ import annotations

import zlib

import numpy as np
import pytest
import sympy as sp

from rotorlyap.model import derivation
from rotorlyap.model._generated import blade_model as gen


def _random_parameters(rng: np.random.Generator) -> tuple[float, ...]:
    """A random but physical parameter tuple P (positive inertia from point masses)."""
    masses, rho = _point_masses(rng)
    m, S, I = _mass_properties(masses, rho)
    d = rng.uniform(-0.1, 0.3, 4)
    values = dict(m=m, S_x=S[0], S_y=S[1], S_z=S[2], I_xx=I[0, 0], I_yy=I[1, 1], I_zz=I[2, 2],
                  I_xy=I[0, 1], I_yz=I[1, 2], I_xz=I[0, 2], d_1=d[0], d_2=d[1], d_3=d[2], d_4=d[3],
                  Omega=rng.uniform(10, 40), g=9.81, K_beta=rng.uniform(0, 1e4),
                  K_zeta=rng.uniform(0, 1e4), K_theta=rng.uniform(0, 1e4), k_3=rng.uniform(-1, 1))
    return tuple(values[n] for n in derivation.PARAMETER_NAMES)


def _point_masses(rng: np.random.Generator, n: int = 7):
    masses = rng.uniform(1.0, 10.0, n)
    rho = np.column_stack([rng.uniform(0.0, 7.0, n), rng.uniform(-0.3, 0.3, n),
                           rng.uniform(-0.05, 0.05, n)])
    return masses, rho


def _mass_properties(masses, rho):
    m = masses.sum()
    S = masses @ rho
    I = np.einsum("i,ijk->jk", masses,
                  np.einsum("i,jk->ijk", (rho * rho).sum(1), np.eye(3)) - np.einsum("ij,ik->ijk", rho, rho))
    return m, S, I


def _rot(axis: int, a: float) -> np.ndarray:
    """Rotation matrix whose columns are the rotated frame's axes (right-handed, angle a)."""
    c, s = np.cos(a), np.sin(a)
    if axis == 0:
        return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    if axis == 1:
        return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def _frames(psi, q):
    """Axes of H, F, L, B as columns in N, built independently of sympy (BLADE_SPEC.md)."""
    beta, zeta, theta = q
    RH = _rot(2, psi)
    RF = RH @ _rot(1, -beta)
    RL = RF @ _rot(2, -zeta)
    RB = RL @ _rot(0, theta)
    return RH, RF, RL, RB


def _positions(P, psi, q, rho):
    """Inertial positions of body points rho (n, 3) given in B from the pitch hinge."""
    p = dict(zip(derivation.PARAMETER_NAMES, P))
    RH, RF, RL, RB = _frames(psi, q)
    hinge = (RH @ [p["d_1"], 0, 0] + RF @ [p["d_3"], 0, p["d_2"]] + RL @ [p["d_4"], 0, 0])
    return hinge + rho @ RB.T


def _velocities(P, q, qp, rho, psi=0.3, h=1e-6):
    """Inertial velocities of body points by central differences in time."""
    Om = dict(zip(derivation.PARAMETER_NAMES, P))["Omega"]
    q, qp = np.asarray(q), np.asarray(qp)

    def pos(dt):
        return _positions(P, psi + Om * dt, q + Om * qp * dt, rho)

    return (pos(h) - pos(-h)) / (2 * h)


def test_kinetic_and_potential_energy_equal_point_mass_sums():
    """T = T2 + T1 + T0 and V (gravity + springs) equal sums over point masses whose
    velocities come from an independent numpy model of the frames (BLADE_SPEC.md)."""
    rng = np.random.default_rng(1)
    masses, rho = _point_masses(rng)
    m, S, I = _mass_properties(masses, rho)
    P = list(_random_parameters(rng))
    names = derivation.PARAMETER_NAMES
    for k, v in zip(("m", "S_x", "S_y", "S_z", "I_xx", "I_yy", "I_zz", "I_xy", "I_yz", "I_xz"),
                    (m, *S, I[0, 0], I[1, 1], I[2, 2], I[0, 1], I[1, 2], I[0, 2])):
        P[names.index(k)] = v
    p = dict(zip(names, P))
    for _ in range(3):
        q = rng.uniform(-0.6, 0.6, 3)
        qp = rng.uniform(-1, 1, 3)
        thc = rng.uniform(-0.2, 0.3)
        v = _velocities(P, q, qp, rho)
        T_ref = 0.5 * float(masses @ (v * v).sum(1))
        T2, T1, T0, V = gen.energies(*q, *qp, thc, P)
        assert T2 + T1 + T0 == pytest.approx(T_ref, rel=1e-8)
        # rate-free part: the same with q' = 0
        v0 = _velocities(P, q, np.zeros(3), rho)
        assert T0 == pytest.approx(0.5 * float(masses @ (v0 * v0).sum(1)), rel=1e-8)
        z = _positions(P, 0.3, q, rho)[:, 2]
        V_ref = (p["g"] * float(masses @ z) + 0.5 * p["K_beta"] * q[0] ** 2
                 + 0.5 * p["K_zeta"] * q[1] ** 2
                 + 0.5 * p["K_theta"] * (q[2] - thc + p["k_3"] * q[0]) ** 2)
        assert V == pytest.approx(V_ref, rel=1e-12, abs=1e-9 * abs(V_ref))


def test_aerodynamic_kinematics_equal_finite_differences():
    """point_velocity (v0 + J q') and the direction cosines C_BN, C_BH of the generated
    kinematics equal an independent numpy model differentiated numerically."""
    rng = np.random.default_rng(2)
    P = _random_parameters(rng)
    Om = dict(zip(derivation.PARAMETER_NAMES, P))["Omega"]
    psi = 0.3
    for _ in range(3):
        q = rng.uniform(-0.6, 0.6, 3)
        qp = rng.uniform(-1, 1, 3)
        rho = rng.uniform(-1, 5, (1, 3))
        v_ref = _velocities(P, q, qp, rho, psi=psi)[0]
        RB = _frames(psi, q)[3]
        out = gen.point_velocity(*q, *qp, *rho[0], P)
        v = out[0:3] + out[3:12].reshape(3, 3) @ qp  # B components
        np.testing.assert_allclose(RB @ v, v_ref, rtol=1e-8, atol=1e-8 * np.abs(v_ref).max())
        kin = gen.kinematics(psi, *q, P)
        np.testing.assert_allclose(kin[24:33].reshape(3, 3), RB.T, atol=1e-14)
        RH = _frames(psi, q)[0]
        T = gen.rhs_terms(*q, *qp, 0.1, P)
        np.testing.assert_allclose(T[33:42].reshape(3, 3), RB.T @ RH, atol=1e-14)
        # hinge velocity and angular velocity in psi-form v0 + J q'
        v_hinge = kin[0:3] + kin[3:12].reshape(3, 3) @ qp
        np.testing.assert_allclose(v_hinge, T[9:12], rtol=1e-12, atol=1e-12)
        w = kin[12:15] + kin[15:24].reshape(3, 3) @ qp
        np.testing.assert_allclose(w, T[12:15], rtol=1e-12, atol=1e-12)
        # partial velocities: time-domain d v/d q_t = J / Omega
        np.testing.assert_allclose(T[15:24], kin[3:12] / Om, rtol=1e-12, atol=1e-12)


def test_mass_matrix_and_forces_satisfy_lagrange_numerically():
    """M q_tt = F reproduces d/dt(dT/dq_t) - dT/dq + dV/dq computed by finite differences of
    the generated energies (Lagrange's equations, independently of LagrangesMethod)."""
    rng = np.random.default_rng(3)
    P = _random_parameters(rng)
    Om = dict(zip(derivation.PARAMETER_NAMES, P))["Omega"]
    q = rng.uniform(-0.5, 0.5, 3)
    qt = rng.uniform(-20, 20, 3)  # time rates, rad/s
    qtt = rng.uniform(-200, 200, 3)
    thc = 0.1
    h = 1e-6

    def L(qq, qqt):
        T2, T1, T0, V = gen.energies(*qq, *(qqt / Om), thc, P)
        return T2 + T1 + T0 - V

    def dL_dqt(qq, qqt):
        return np.array([(L(qq, qqt + h * e) - L(qq, qqt - h * e)) / (2 * h) for e in np.eye(3)])

    def dL_dq(qq, qqt):
        return np.array([(L(qq + h * e, qqt) - L(qq - h * e, qqt)) / (2 * h) for e in np.eye(3)])

    dt = 1e-5
    ddt = (dL_dqt(q + qt * dt + 0.5 * qtt * dt**2, qt + qtt * dt)
           - dL_dqt(q - qt * dt + 0.5 * qtt * dt**2, qt - qtt * dt)) / (2 * dt)
    lhs = ddt - dL_dq(q, qt)  # = generalised forces needed = 0 for a free motion
    T = gen.rhs_terms(*q, *(qt / Om), thc, P)
    M = T[0:6][[0, 1, 2, 1, 3, 4, 2, 4, 5]].reshape(3, 3)
    resid = M @ qtt - T[6:9]
    scale = np.abs(M @ qtt).max() + np.abs(T[6:9]).max()
    np.testing.assert_allclose(resid, lhs, atol=1e-5 * scale)


def _sympy_values(exprs, subs):
    return np.array([float(sp.sympify(e).xreplace(subs).evalf(30)) for e in exprs])


@pytest.mark.parametrize("name", ["rhs_terms", "rhs_dw_terms", "w_terms", "energies",
                                  "potential_terms", "kinematics", "point_velocity"])
@pytest.mark.slow
def test_generated_code_equals_sympy_substitution(name):
    """Every generated function equals direct sympy evaluation (substitution) of the
    derivation's expressions at random states and parameters."""
    funcs = derivation.generated_functions()
    args, exprs, _ = funcs[name]
    rng = np.random.default_rng(zlib.crc32(name.encode()))
    P = _random_parameters(rng)
    params = derivation.derive().params
    for _ in range(2):
        vals = rng.uniform(-0.8, 0.8, len(args))
        subs = {s: sp.Float(v, 30) for s, v in zip(args, vals)}
        subs.update({s: sp.Float(v, 30) for s, v in zip(params, P)})
        ref = _sympy_values(exprs, subs)
        got = getattr(gen, name)(*vals, P)
        np.testing.assert_allclose(got, ref, rtol=1e-10, atol=1e-10 * (np.abs(ref).max() + 1))


def test_generated_code_broadcasts_over_leading_axes():
    """Generated functions take arrays with leading axes and broadcast them."""
    rng = np.random.default_rng(5)
    P = _random_parameters(rng)
    q = rng.uniform(-0.5, 0.5, (3, 4, 5))
    out = gen.rhs_terms(q[0], q[1], q[2], 0.1, 0.2, 0.3, np.zeros((1, 5)), P)
    assert out.shape == (42, 4, 5)
    one = gen.rhs_terms(q[0, 2, 3], q[1, 2, 3], q[2, 2, 3], 0.1, 0.2, 0.3, 0.0, P)
    np.testing.assert_allclose(out[:, 2, 3], one, rtol=1e-14, atol=1e-14)


@pytest.mark.slow
def test_cached_code_is_current_and_equals_fresh_derivation():
    """The cached generated files (numpy, scalar and block code) record the current derivation
    hash and equal a fresh derivation byte for byte (deterministic output)."""
    hint = "stale cache: run `python -m rotorlyap.model.derivation` and commit the generated file"
    assert gen.DERIVATION_HASH == derivation.derivation_hash(), hint
    assert gen.SYMPY_VERSION == sp.__version__, hint
    assert derivation.GENERATED_PATH.read_text() == derivation.generate_source(), hint
    assert derivation.SCALAR_PATH.read_text() == derivation.generate_scalar_source(), hint
    assert derivation.BLOCK_PATH.read_text() == derivation.generate_block_source(), hint
