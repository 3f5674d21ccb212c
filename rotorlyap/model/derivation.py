"""Symbolic derivation of the three-hinge rigid blade and generation of its numeric code.

The model follows BLADE_SPEC.md (the developers' interface contract) and section 4 of
Narkiewicz & Lucjanek (ERF 1989): an isolated rigid blade on a shaft turning at constant
speed Omega, with the hinges in the order flap, lag, pitch separated by rigid hub elements,
a spring at every hinge (the pitch spring carries the control input and the pitch-flap
coupling), gravity, and all geometric nonlinearities kept.

Frames (all right-handed, built with :mod:`sympy.physics.mechanics`)
---------------------------------------------------------------------
``N``  inertial: X aft (downstream), Z up along the shaft.
``H``  hub, rotated ``psi = Omega t`` about ``Z``.
``F``  flap, rotated ``-beta`` about ``y_H`` (``beta > 0`` raises the tip).
``L``  lag, rotated ``-zeta`` about ``z_F`` (``zeta > 0`` moves the blade against the rotation).
``B``  blade (pitch), rotated ``+theta`` about ``x_L`` (``theta > 0`` is nose up).

Points: ``O`` on the shaft axis, flap hinge ``P1 = O + d1 x_H``, lag hinge
``P2 = P1 + d3 x_F + d2 y_F``, pitch hinge ``P3 = P2 + d4 x_L`` with ``d_i = e_i R1`` (m).
The chordwise offset ``e5`` of the feathering axis from the pitch hinge only moves the blade's
mass and its aerodynamic stations inside ``B``; it enters through the mass properties and the
station coordinates (computed in :mod:`rotorlyap.model.aero`), not through the derivation.

The blade
---------
Everything outboard of the pitch hinge is one rigid body described by its mass properties
about the pitch hinge ``P3`` in ``B`` components: mass ``m`` (kg), first moments
``S = m r_G = (S_x, S_y, S_z)`` (kg m) and the inertia tensor
``I_ij = integral (rho^2 delta_ij - rho_i rho_j) dm`` (kg m^2; off-diagonal entries are the
negative products of inertia).  Any mass distribution reduces to these ten numbers, and the
kinetic energy is exactly

    T = 1/2 m v_P.v_P + v_P.(w x S) + 1/2 w.I.w,

with ``v_P`` the inertial velocity of ``P3`` and ``w`` the angular velocity of ``B`` in ``N``.

Energies and equations
----------------------
``T = T2 + T1 + T0`` (quadratic, linear and free of the hinge rates), the potential
``V = V_springs + V_gravity`` with
``V_springs = 1/2 K_beta beta^2 + 1/2 K_zeta zeta^2 + 1/2 K_theta (theta - theta_c + k3 beta)^2``
(``k3 = tan(delta3)``, ``theta_c(psi)`` the control input), and Lagrange's equations
(``sympy.physics.mechanics.LagrangesMethod``) ``M(q) q_tt = F(q, q_t, theta_c)`` in time.
With ``q_t = Omega q'`` and ``q_tt = Omega^2 q''`` the generated code returns ``M`` and ``F``
evaluated at psi-rates ``q'``; :class:`rotorlyap.model.blade.Blade` adds the dampers and the
aerodynamic generalised forces and solves ``Omega^2 M q'' = F + Q``.
The effective potential of the rotating frame is ``U = V - T0`` (springs + gravity +
centrifugal); ``T1`` only produces gyroscopic (Coriolis) forces because nothing depends on
time explicitly once the shaft speed is constant and the shaft is not tilted.

Generated code
--------------
:func:`generate` writes ``rotorlyap/model/_generated/blade_model.py``: vectorised numpy functions,
one common-subexpression-eliminated block each, returning stacked arrays with the output
index first (shape ``(K,) + broadcast(inputs)``).  Run ``python -m rotorlyap.model.derivation`` to
regenerate; the package only imports the cached file.
"""

from __future__ import annotations

import hashlib
import inspect
import sys
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import sympy as sp
from sympy.physics.mechanics import (
    LagrangesMethod,
    Point,
    ReferenceFrame,
    dynamicsymbols,
    inertia,
)
from sympy.printing.numpy import NumPyPrinter
from sympy.printing.pycode import PythonCodePrinter

__all__ = [
    "BladeModel",
    "derive",
    "generated_functions",
    "generate_source",
    "generate",
    "generate_scalar_source",
    "generate_block_source",
    "derivation_hash",
    "GENERATED_PATH",
    "SCALAR_PATH",
    "SCALAR_FUNCTIONS",
    "BLOCK_PATH",
    "BLOCK_FUNCTIONS",
    "BLOCK_LAYOUT",
    "PARAMETER_NAMES",
]

GENERATED_PATH = Path(__file__).resolve().parent / "_generated" / "blade_model.py"
SCALAR_PATH = GENERATED_PATH.with_name("blade_scalar.py")

#: The functions also written as scalar code (one state, ``math`` functions, results written
#: into a given array) for the compiled kernels of :mod:`rotorlyap.model.compiled`.
SCALAR_FUNCTIONS: tuple[str, ...] = ("rhs_terms", "rhs_dw_terms", "potential_terms")

BLOCK_PATH = GENERATED_PATH.with_name("blade_block.py")

#: The functions also written as block code (a block of states innermost, every quantity a
#: row of one workspace array, so that the compiler vectorises the loop over the states) for
#: the block kernels of :mod:`rotorlyap.model.compiled`.
BLOCK_FUNCTIONS: tuple[str, ...] = ("rhs_terms", "rhs_dw_terms")

#: Layout of the block code's workspace ``W`` (float64, rows of ``BLOCK`` states, row ``r`` of
#: state ``i`` at ``W[r * BLOCK + i]``): (BLOCK, first input row, first row of the cosines and
#: sines, first output row, the cosines and sines in their row order). The inputs take at most
#: 10 rows, the cosines and sines 6, the outputs at most 49.
BLOCK_LAYOUT: tuple = (128, 0, 10, 16, (("cos", "beta"), ("sin", "beta"), ("cos", "zeta"),
                                         ("sin", "zeta"), ("cos", "theta"), ("sin", "theta")))

#: Order of the constant parameter tuple ``P`` taken by every generated function.
PARAMETER_NAMES: tuple[str, ...] = (
    "m", "S_x", "S_y", "S_z",
    "I_xx", "I_yy", "I_zz", "I_xy", "I_yz", "I_xz",
    "d_1", "d_2", "d_3", "d_4",
    "Omega", "g",
    "K_beta", "K_zeta", "K_theta", "k_3",
)


@dataclass(frozen=True)
class BladeModel:
    """The symbolic blade model (every expression in plain symbols, psi-rates).

    Attributes
    ----------
    q, qp : tuple of sympy.Symbol
        Hinge angles ``(beta, zeta, theta)`` (rad) and their psi-rates (rad/rad).
    psi, theta_c : sympy.Symbol
        Azimuth (rad) and pitch control input (rad).
    params : tuple of sympy.Symbol
        Constant parameters, in the order :data:`PARAMETER_NAMES`.
    M : sympy.Matrix
        3x3 mass matrix in time, kg m^2.
    F : sympy.Matrix
        Conservative generalised forces (centrifugal, Coriolis, gravity, springs) at
        ``q_t = Omega q'``, N m, so that ``M q_tt = F + Q_nonconservative``.
    T2, T1, T0, V : sympy.Expr
        Kinetic energy parts (quadratic, linear, free in the rates) at ``q_t = Omega q'``
        and potential energy, J.
    U : sympy.Expr
        Effective potential ``V - T0``, J.
    v_P, w : sympy.Matrix
        Inertial velocity of the pitch hinge (m/s) and angular velocity of ``B`` (rad/s), in
        ``B`` components, at ``q_t = Omega q'``.
    Pv, Pw : sympy.Matrix
        Partial velocities ``d v_P / d q_t`` (m/rad) and ``d w / d q_t`` (-), 3x3 with
        column k for hinge k, ``B`` components.
    C_BH, C_BN : sympy.Matrix
        Direction cosines ``C[i, j] = b_i . h_j`` (resp. ``b_i . n_j``), so that the ``B``
        components of a vector are ``C_BH @ a_H`` (resp. ``C_BN @ a_N``).
    """

    q: tuple
    qp: tuple
    psi: sp.Symbol
    theta_c: sp.Symbol
    params: tuple
    M: sp.Matrix
    F: sp.Matrix
    T2: sp.Expr
    T1: sp.Expr
    T0: sp.Expr
    V: sp.Expr
    U: sp.Expr
    v_P: sp.Matrix
    w: sp.Matrix
    Pv: sp.Matrix
    Pw: sp.Matrix
    C_BH: sp.Matrix
    C_BN: sp.Matrix


def _symbols():
    """Create the plain symbols of the model (deterministic names)."""
    q = sp.symbols("beta zeta theta", real=True)
    qp = sp.symbols("beta_p zeta_p theta_p", real=True)
    psi, theta_c = sp.symbols("psi theta_c", real=True)
    params = sp.symbols(" ".join(PARAMETER_NAMES), real=True)
    return q, qp, psi, theta_c, params


def _components(vec, frame) -> sp.Matrix:
    """Column of the components of a mechanics vector in ``frame``."""
    return sp.Matrix([vec.dot(frame.x), vec.dot(frame.y), vec.dot(frame.z)])


def _dcm_rows(frame_from, frame_to) -> sp.Matrix:
    """Matrix ``C`` with ``C[i, j] = frame_to_i . frame_from_j``.

    For a vector with components ``a`` in ``frame_from``, its components in ``frame_to``
    are ``C @ a``.
    """
    e_to = (frame_to.x, frame_to.y, frame_to.z)
    e_from = (frame_from.x, frame_from.y, frame_from.z)
    return sp.Matrix(3, 3, lambda i, j: sp.trigsimp(e_to[i].dot(e_from[j])))


@lru_cache(maxsize=1)
def derive() -> BladeModel:
    """Derive the blade's energies, equations of motion and kinematics symbolically.

    Returns
    -------
    BladeModel
        All expressions in plain symbols (see :class:`BladeModel`).  Takes a few seconds.
    """
    q, qp, psi, theta_c, P = _symbols()
    (m, Sx, Sy, Sz, Ixx, Iyy, Izz, Ixy, Iyz, Ixz,
     d1, d2, d3, d4, Omega, g, Kb, Kz, Kt, k3) = P

    t = dynamicsymbols._t
    qf = dynamicsymbols("beta zeta theta")
    qdf = [sp.diff(qi, t) for qi in qf]
    beta_f, zeta_f, theta_f = qf

    # Frames: N inertial, H hub (psi = Omega t about Z), F flap, L lag, B pitch.
    N = ReferenceFrame("N")
    H = ReferenceFrame("H")
    H.orient_axis(N, N.z, Omega * t)
    Ff = ReferenceFrame("F")
    Ff.orient_axis(H, H.y, -beta_f)
    L = ReferenceFrame("L")
    L.orient_axis(Ff, Ff.z, -zeta_f)
    B = ReferenceFrame("B")
    B.orient_axis(L, L.x, theta_f)

    # Hinge points from the hub elements.
    O = Point("O")
    O.set_vel(N, 0)
    P1 = O.locatenew("P1", d1 * H.x)
    P1.v2pt_theory(O, N, H)
    P2 = P1.locatenew("P2", d3 * Ff.x + d2 * Ff.z)
    P2.v2pt_theory(P1, N, Ff)
    P3 = P2.locatenew("P3", d4 * L.x)
    P3.v2pt_theory(P2, N, L)

    # Components, each trigonometrically simplified (small expressions, fast).  |v_P|^2 is
    # formed in L, where v_P does not involve theta, to avoid sin^2 + cos^2 residues.
    v_P_L = _components(P3.vel(N), L).applyfunc(sp.trigsimp)
    v_P = _components(P3.vel(N), B).applyfunc(sp.trigsimp)
    w = _components(B.ang_vel_in(N), B).applyfunc(sp.trigsimp)
    S = sp.Matrix([Sx, Sy, Sz])
    I_P = inertia(B, Ixx, Iyy, Izz, Ixy, Iyz, Ixz).to_matrix(B)
    T = (sp.Rational(1, 2) * m * v_P_L.dot(v_P_L) + v_P.dot(w.cross(S))
         + sp.Rational(1, 2) * (w.T * I_P * w)[0, 0])

    # Potential: gravity (height along Z) and the hinge springs.
    z_P = P3.pos_from(O).dot(N.z)
    z_S = (Sx * B.x + Sy * B.y + Sz * B.z).dot(N.z)
    V = (g * (m * z_P + z_S)
         + sp.Rational(1, 2) * Kb * beta_f**2
         + sp.Rational(1, 2) * Kz * zeta_f**2
         + sp.Rational(1, 2) * Kt * (theta_f - theta_c + k3 * beta_f) ** 2)

    lm = LagrangesMethod(T - V, list(qf))
    lm.form_lagranges_equations()
    M_t = lm.mass_matrix
    F_t = lm.forcing

    # Split T by its degree in the rates (T is exactly quadratic in them).
    zero_rates = {qd: 0 for qd in qdf}
    M_T = sp.hessian(T, qdf)
    T1_t = sum((sp.diff(T, qd).subs(zero_rates) * qd for qd in qdf), sp.S.Zero)
    T0_t = T.subs(zero_rates)
    T2_t = sp.Rational(1, 2) * (sp.Matrix(qdf).T * M_T * sp.Matrix(qdf))[0, 0]

    Pv = sp.Matrix(3, 3, lambda i, k: sp.diff(v_P[i], qdf[k]))
    Pw = sp.Matrix(3, 3, lambda i, k: sp.diff(w[i], qdf[k]))

    C_BH = _dcm_rows(H, B)
    C_BN = _dcm_rows(N, B)

    # Plain symbols: rates first (derivatives contain the functions), psi = Omega t.
    to_plain = {qd: Omega * r for qd, r in zip(qdf, qp)}
    to_plain_q = dict(zip(qf, q))

    def plain(e):
        e = e.subs(to_plain).subs(to_plain_q)
        return e.subs(t, psi / Omega)

    M_plain = M_t.applyfunc(plain)
    if (M_plain - M_T.applyfunc(plain)).applyfunc(sp.expand).applyfunc(sp.trigsimp) != sp.zeros(3, 3):
        raise AssertionError("LagrangesMethod mass matrix differs from the Hessian of T")
    T0 = plain(T0_t)
    V_plain = plain(V)
    model = BladeModel(
        q=q, qp=qp, psi=psi, theta_c=theta_c, params=P,
        M=M_plain,
        F=F_t.applyfunc(plain),
        T2=plain(T2_t), T1=plain(T1_t), T0=T0, V=V_plain, U=V_plain - T0,
        v_P=v_P.applyfunc(plain), w=w.applyfunc(plain),
        Pv=Pv.applyfunc(plain), Pw=Pw.applyfunc(plain),
        C_BH=C_BH.applyfunc(plain), C_BN=C_BN.applyfunc(plain),
    )
    return model


# --------------------------------------------------------------------------------------
# The generated functions: name -> (arguments, outputs, docstring)
# --------------------------------------------------------------------------------------

_UNIQUE = ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2))


def _flat(mat: sp.Matrix) -> list:
    """Row-major entries of a 3x3 matrix."""
    return [mat[i, j] for i in range(3) for j in range(3)]


def generated_functions(model: BladeModel | None = None) -> dict:
    """Specification of the generated numeric functions.

    Returns
    -------
    dict
        ``name -> (argument symbols, list of output expressions, docstring)``.
    """
    mdl = derive() if model is None else model
    q, qp, psi, thc = mdl.q, mdl.qp, mdl.psi, mdl.theta_c
    Omega = mdl.params[PARAMETER_NAMES.index("Omega")]
    xr = sp.symbols("x_beta_p x_zeta_p x_theta_p", real=True)
    xb, yb, zb = sp.symbols("x_b y_b z_b", real=True)

    M6 = [mdl.M[i, j] for i, j in _UNIQUE]
    rhs_out = M6 + list(mdl.F) + list(mdl.v_P) + list(mdl.w) + _flat(mdl.Pv) + _flat(mdl.Pw) \
        + _flat(mdl.C_BH)

    # 1/2 Omega^2 xr^T (dM/dq_k) xr, the q-gradient of the kinetic energy of the disturbance.
    xr_vec = sp.Matrix(xr)
    dT2 = [sp.Rational(1, 2) * Omega**2 * (xr_vec.T * mdl.M.diff(qk) * xr_vec)[0, 0] for qk in q]
    gradU = [sp.diff(mdl.U, qk) for qk in q]
    hessU = [sp.diff(mdl.U, q[i], q[j]) for i, j in _UNIQUE]
    dU_dthc = sp.diff(mdl.U, thc)
    grad_dU_dthc = [sp.diff(dU_dthc, qk) for qk in q]

    # Velocity of a body point (x_b, y_b, z_b) in B from the pitch hinge: v = v0 + J q'.
    rho = sp.Matrix([xb, yb, zb])
    zero_qp = {r: 0 for r in qp}
    v_pt = mdl.v_P + mdl.w.cross(rho)
    v0_pt = v_pt.subs(zero_qp)
    J_pt = sp.Matrix(3, 3, lambda i, k: sp.diff(v_pt[i], qp[k]))
    w0 = mdl.w.subs(zero_qp)
    Jw = Omega * mdl.Pw

    states = (*q, *qp, thc)
    return {
        "rhs_terms": (
            states,
            rhs_out,
            "Terms of the equations of motion and the aerodynamic kinematics.\n\n"
            "Rows: 0-5 mass matrix M (kg m^2) entries 00,01,02,11,12,22; 6-8 conservative\n"
            "generalised forces F (N m); 9-11 velocity of the pitch hinge v_P (m/s, B comps);\n"
            "12-14 angular velocity w of B (rad/s, B comps); 15-23 d v_P/d q_t (m/rad,\n"
            "row-major [component, hinge]); 24-32 d w/d q_t (-); 33-41 C_BH (row-major,\n"
            "B components = C_BH @ H components).",
        ),
        "rhs_dw_terms": (
            (*q, *qp, thc, *xr),
            rhs_out + dT2 + gradU + [dU_dthc],
            "rhs_terms rows 0-41, then 42-44 (1/2) Omega^2 xr^T dM/dq_k xr (J/rad),\n"
            "45-47 grad_q U (J/rad), 48 dU/dtheta_c (J/rad).",
        ),
        "w_terms": (
            (*q, *xr, thc),
            [sp.Rational(1, 2) * Omega**2 * (xr_vec.T * mdl.M * xr_vec)[0, 0], mdl.U],
            "Energy-function terms: rows 0 (1/2) Omega^2 xr^T M(q) xr (J), 1 U = V - T0 (J).",
        ),
        "energies": (
            states,
            [mdl.T2, mdl.T1, mdl.T0, mdl.V],
            "Rows: T2, T1, T0 (kinetic energy parts at q_t = Omega q'), V (J).",
        ),
        "potential_terms": (
            (*q, thc),
            [mdl.U] + gradU + hessU + [dU_dthc] + grad_dU_dthc,
            "Effective potential U = V - T0 and its derivatives.\n\n"
            "Rows: 0 U (J); 1-3 grad_q U (J/rad); 4-9 Hessian entries 00,01,02,11,12,22\n"
            "(J/rad^2); 10 dU/dtheta_c; 11-13 grad_q dU/dtheta_c.",
        ),
        "kinematics": (
            (psi, *q),
            list(v0_pt.subs({xb: 0, yb: 0, zb: 0})) + _flat(Omega * mdl.Pv)
            + list(w0) + _flat(Jw) + _flat(mdl.C_BN),
            "Kinematics of the pitch hinge and of B, psi-form v = v0 + J q'.\n\n"
            "Rows: 0-2 v0 of the pitch hinge (m/s, B comps); 3-11 J = Omega dv/dq_t (m/rad,\n"
            "row-major [component, hinge]); 12-14 w0 (rad/s); 15-23 Jw (rad/s per rad/rad);\n"
            "24-32 C_BN row-major (B components = C_BN @ N components).",
        ),
        "point_velocity": (
            (*q, *qp, xb, yb, zb),
            list(v0_pt) + _flat(J_pt),
            "Inertial velocity of the body point (x_b, y_b, z_b) (m, B components from the\n"
            "pitch hinge), psi-form v = v0 + J q'.\n\n"
            "Rows: 0-2 v0 (m/s, B comps); 3-11 J (m/rad, row-major [component, hinge]).",
        ),
    }


# --------------------------------------------------------------------------------------
# Code printing
# --------------------------------------------------------------------------------------


class _Printer(NumPyPrinter):
    """NumPy printer writing small integer powers as products."""

    def _print_Pow(self, expr, rational=False):  # noqa: D401 - sympy hook
        b, e = expr.as_base_exp()
        if e.is_Integer and 1 < abs(int(e)) <= 4:
            n = abs(int(e))
            base = self.parenthesize(b, sp.printing.precedence.PRECEDENCE["Mul"] + 1)
            prod = "*".join([base] * n)
            return prod if e > 0 else f"1.0/({prod})"
        if e == -1:
            return f"1.0/{self.parenthesize(b, sp.printing.precedence.PRECEDENCE['Mul'] + 1)}"
        return super()._print_Pow(expr, rational=rational)


class _ScalarPrinter(PythonCodePrinter):
    """``math`` printer for one state, writing small integer powers as products (the same
    expression trees as :class:`_Printer`, so the same operations in the same order)."""

    _print_Pow = _Printer._print_Pow


def _scalar_function_source(name: str, args, outputs, doc: str) -> str:
    """Python source of one scalar function with the same CSE as :func:`_function_source`:
    ``name_into(args..., P, out)`` writes the outputs into ``out[:len(outputs)]``."""
    printer = _ScalarPrinter({"fully_qualified_modules": True, "allow_unknown_functions": False})
    tmp = sp.numbered_symbols("_x")
    replacements, reduced = sp.cse(outputs, symbols=tmp, optimizations="basic", order="canonical")
    argnames = [str(a) for a in args]
    lines = [f"def {name}_into({', '.join(argnames)}, P, out):"]
    lines.append(f'    """One state of ``{name}``: floats {", ".join(argnames)}; P: parameters')
    lines.append(f"    in the order PARAMETER_NAMES (a float array); writes rows 0-{len(outputs) - 1} of out.")
    lines.append('    """')
    for k, pname in enumerate(PARAMETER_NAMES):
        lines.append(f"    {pname} = P[{k}]")
    for sym, expr in replacements:
        lines.append(f"    {sym} = {printer.doprint(expr)}")
    for k, expr in enumerate(reduced):
        lines.append(f"    out[{k}] = {printer.doprint(expr)}")
    return "\n".join(lines) + "\n"


def _block_function_source(name: str, args, outputs, doc: str) -> str:
    """Python source of one block function with the same CSE and the same printed expressions
    as :func:`_scalar_function_source`: ``name_block(n, P, W)`` evaluates the states
    ``0 <= i < n`` (``n <= BLOCK``) whose inputs and cosines and sines are rows of ``W``
    (:data:`BLOCK_LAYOUT`) and writes the outputs into rows of ``W``. Every row offset is a
    literal, so that the compiler sees one array with constant distances between the rows (no
    runtime alias checks) and vectorises the loop."""
    block, in_row, trig_row, out_row, trig = BLOCK_LAYOUT
    printer = _ScalarPrinter({"fully_qualified_modules": True, "allow_unknown_functions": False})
    tmp = sp.numbered_symbols("_x")
    replacements, reduced = sp.cse(outputs, symbols=tmp, optimizations="basic", order="canonical")
    argnames = [str(a) for a in args]
    if len(argnames) > trig_row - in_row or len(outputs) > 49:
        raise ValueError(f"{name}: too many inputs or outputs for BLOCK_LAYOUT")

    def row(r):
        return f"W[{r * block} + _i]"

    def rows(text):
        for k, (fn, arg) in enumerate(trig):
            text = text.replace(f"math.{fn}({arg})", row(trig_row + k))
        if "math." in text:
            raise ValueError(f"{name}: the block code has only the cosines and sines of BLOCK_LAYOUT")
        return text

    lines = [f"def {name}_block(n, P, W):"]
    lines.append(f'    """``{name}`` of the states 0 <= i < n <= {block} of the workspace W (float64,')
    lines.append(f"    row r of state i at W[r * {block} + i]): inputs {', '.join(argnames)} in rows")
    lines.append(f"    {in_row}-{in_row + len(argnames) - 1}, "
                 f"{', '.join(f'{fn} {arg}' for fn, arg in trig)} in rows {trig_row}-{trig_row + len(trig) - 1};")
    lines.append(f"    writes the outputs 0-{len(outputs) - 1} into rows {out_row}-{out_row + len(outputs) - 1}.")
    lines.append('    """')
    for k, pname in enumerate(PARAMETER_NAMES):
        lines.append(f"    {pname} = P[{k}]")
    lines.append("    for _i in range(n):")
    for j, a in enumerate(argnames):
        lines.append(f"        {a} = {row(in_row + j)}")
    for sym, expr in replacements:
        lines.append(f"        {sym} = {rows(printer.doprint(expr))}")
    for k, expr in enumerate(reduced):
        lines.append(f"        {row(out_row + k)} = {rows(printer.doprint(expr))}")
    return "\n".join(lines) + "\n"


def _function_source(name: str, args, outputs, doc: str) -> str:
    """Python source of one vectorised function with CSE."""
    printer = _Printer({"fully_qualified_modules": True, "allow_unknown_functions": False})
    tmp = sp.numbered_symbols("_x")
    replacements, reduced = sp.cse(outputs, symbols=tmp, optimizations="basic", order="canonical")
    argnames = [str(a) for a in args]
    lines = [f"def {name}({', '.join(argnames)}, P):"]
    lines.append('    """' + doc.replace("\n", "\n    ") + "\n")
    lines.append(f"    Arguments {', '.join(argnames)}: arrays broadcasting together.")
    lines.append("    P: parameters in the order PARAMETER_NAMES.")
    lines.append(f"    Returns an array of shape ({len(outputs)},) + broadcast shape.")
    lines.append('    """')
    lines.append(f"    ({', '.join(PARAMETER_NAMES)},) = P")
    for a in argnames:
        lines.append(f"    {a} = numpy.asarray({a}, dtype=numpy.float64)")
    lines.append(
        f"    _out = numpy.empty(({len(outputs)},) + numpy.broadcast_shapes("
        + ", ".join(f"{a}.shape" for a in argnames)
        + "))"
    )
    for sym, expr in replacements:
        lines.append(f"    {sym} = {printer.doprint(expr)}")
    for k, expr in enumerate(reduced):
        lines.append(f"    _out[{k}] = {printer.doprint(expr)}")
    lines.append("    return _out")
    return "\n".join(lines) + "\n"


def derivation_hash() -> str:
    """SHA-256 (first 16 hex digits) of the derivation inputs.

    The inputs are the source of this module's model and code-generation functions and the
    sympy version; the generated file records it so that a stale cache can be detected.
    """
    parts = [sp.__version__]
    for obj in (PARAMETER_NAMES, _symbols, _components, _dcm_rows, derive, _flat,
                generated_functions, _Printer, _function_source, _ScalarPrinter,
                _scalar_function_source, SCALAR_FUNCTIONS, _block_function_source,
                BLOCK_FUNCTIONS, BLOCK_LAYOUT):
        parts.append(repr(obj) if isinstance(obj, tuple) else inspect.getsource(obj))
    return hashlib.sha256("\n".join(parts).encode()).hexdigest()[:16]


def generate_source() -> str:
    """Full source text of ``rotorlyap/model/_generated/blade_model.py`` (deterministic)."""
    funcs = generated_functions()
    header = (
        '"""Generated by ``python -m rotorlyap.model.derivation``: do not edit.\n\n'
        "Vectorised numpy code of the three-hinge blade model derived symbolically in\n"
        "rotorlyap/model/derivation.py (common subexpressions eliminated).\n\n"
        f"sympy version: {sp.__version__}\n"
        f"derivation hash: {derivation_hash()}\n"
        '"""\n\n'
        "import numpy\n\n"
        f"SYMPY_VERSION = {sp.__version__!r}\n"
        f"DERIVATION_HASH = {derivation_hash()!r}\n"
        f"PARAMETER_NAMES = {PARAMETER_NAMES!r}\n\n"
    )
    body = "\n\n".join(_function_source(name, *spec) for name, spec in funcs.items())
    return header + "\n" + body


def generate_scalar_source() -> str:
    """Full source text of ``rotorlyap/model/_generated/blade_scalar.py`` (deterministic)."""
    funcs = generated_functions()
    header = (
        '"""Generated by ``python -m rotorlyap.model.derivation``: do not edit.\n\n'
        "Scalar code (one state, ``math`` functions) of the functions SCALAR_FUNCTIONS of the\n"
        "blade model, with the same common subexpressions as blade_model.py; compiled by\n"
        "rotorlyap/model/compiled.py.\n\n"
        f"sympy version: {sp.__version__}\n"
        f"derivation hash: {derivation_hash()}\n"
        '"""\n\n'
        "import math\n\n"
        f"SYMPY_VERSION = {sp.__version__!r}\n"
        f"DERIVATION_HASH = {derivation_hash()!r}\n"
        f"PARAMETER_NAMES = {PARAMETER_NAMES!r}\n\n"
    )
    body = "\n\n".join(_scalar_function_source(name, *funcs[name]) for name in SCALAR_FUNCTIONS)
    return header + "\n" + body


def generate_block_source() -> str:
    """Full source text of ``rotorlyap/model/_generated/blade_block.py`` (deterministic)."""
    funcs = generated_functions()
    block, in_row, trig_row, out_row, trig = BLOCK_LAYOUT
    header = (
        '"""Generated by ``python -m rotorlyap.model.derivation``: do not edit.\n\n'
        "Block code of the functions BLOCK_FUNCTIONS of the blade model: the expressions of\n"
        "blade_scalar.py (the same common subexpressions, the same operations in the same\n"
        "order) for a block of states, the loop over the states innermost and every quantity a\n"
        "row of one workspace array W, so that numba (LLVM) vectorises the loop; compiled by\n"
        "rotorlyap/model/compiled.py, which fills the input rows and the cosines and sines.\n\n"
        f"sympy version: {sp.__version__}\n"
        f"derivation hash: {derivation_hash()}\n"
        '"""\n\n'
        f"SYMPY_VERSION = {sp.__version__!r}\n"
        f"DERIVATION_HASH = {derivation_hash()!r}\n"
        f"PARAMETER_NAMES = {PARAMETER_NAMES!r}\n"
        f"BLOCK = {block!r}\n"
        f"IN_ROW = {in_row!r}\n"
        f"TRIG_ROW = {trig_row!r}\n"
        f"OUT_ROW = {out_row!r}\n"
        f"TRIG = {trig!r}\n\n"
    )
    body = "\n\n".join(_block_function_source(name, *funcs[name]) for name in BLOCK_FUNCTIONS)
    return header + "\n" + body


def generate(path: Path | str = GENERATED_PATH) -> Path:
    """Derive the model and write the generated module to ``path`` and its scalar and block
    companions (``blade_scalar.py``, ``blade_block.py``) beside it.

    Returns
    -------
    pathlib.Path
        The path of the vectorised module.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    init = path.parent / "__init__.py"
    if not init.exists():
        init.write_text('"""Cached generated code (see rotorlyap.model.derivation)."""\n')
    path.write_text(generate_source())
    path.with_name(SCALAR_PATH.name).write_text(generate_scalar_source())
    path.with_name(BLOCK_PATH.name).write_text(generate_block_source())
    return path


if __name__ == "__main__":  # pragma: no cover - command line entry
    out = generate(sys.argv[1] if len(sys.argv) > 1 else GENERATED_PATH)
    print(f"wrote {out} (derivation hash {derivation_hash()})")
