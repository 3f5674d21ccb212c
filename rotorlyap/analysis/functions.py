"""Liapunov functions of the blade: the paper's energy function and quadratic functions.

Both take the blade and a steady motion (a :class:`~rotorlyap.model.steady.SteadyMotion`, or
anything :func:`~rotorlyap.model.steady.as_steady_motion` takes) and give the vectorised
``W(psi, x)``, ``dW(psi, x)`` and ``f(psi, x)`` that
:func:`rotorlyap.analysis.stability.blade_stability` and
:func:`rotorlyap.methods.lyapunov.technical_stability` take:

* :func:`energy_function`, :class:`EnergyFunction`: the energy of the disturbed motion, the
  paper's choice, with its derivative along the motion from generated code;
* :func:`quadratic_function`, :func:`optimised_quadratic_function`,
  :class:`QuadraticFunction`: ``x^T P(psi) x`` from the periodic Lyapunov equation of the
  linearised blade.

Quadratic functions
-------------------
The paper's energy function lacks the aerodynamic coupling of the blade (the flap moment due
to pitch has no matching pitch moment due to flap), so its derivative along the motions has
terms linear in the rates and of either sign, and it certifies nothing in the strict reading
(:mod:`rotorlyap.analysis.stability`). A quadratic form built from the *linearised* blade does not
have that defect: if the blade linearised about its steady motion ``xi(psi)``,

    ``x' = J(psi) x``,  ``J(psi) = dh/dz (psi, xi(psi))``  (:meth:`rotorlyap.Blade.jacobian`),

is asymptotically stable (every Floquet multiplier inside the unit circle), then for every
symmetric positive-definite ``Q`` the periodic Lyapunov equation
``P' + J^T P + P J = -Q`` has one periodic, positive-definite solution ``P(psi)``
(:func:`rotorlyap.methods.periodic_lyapunov.periodic_lyapunov`) and

    ``W(psi, x) = x^T P(psi) x``,
    ``W'(psi, x) = x^T P'(psi) x + 2 x^T P(psi) f(psi, x)``,

with ``f(psi, x) = h(psi, xi + x) - xi'`` the *full nonlinear* disturbed right-hand side (not
its linearisation), is the exact derivative of ``W`` along the motions of the nonlinear blade.
Near ``x = 0``, ``W' = -x^T Q x + O(|x|^3)`` is negative definite, so the technical-stability
engine (:func:`rotorlyap.technical_stability`) certifies a real start region; the higher-order
terms (aerodynamic and geometric nonlinearities, stall) decide how large a bound ``A`` can be.
If ``xi`` is not a solution of the equations (the paper's hover equilibrium reused in forward
flight), ``f(psi, 0) != 0`` and ``W'`` has a term linear in ``x``: nothing can be certified
near ``x = 0``, with this or any other smooth ``W`` with a minimum at ``x = 0``.

Units and scaling
-----------------
All computations are done in the scaled coordinates ``y_i = x_i / a_i`` of the norm
``||x|| = |y|`` (the ``a_i`` default to :data:`rotorlyap.conventions.DEFAULT_SCALES`), where the
six components are of order one; ``P`` is returned in state units. The default weight is
``Q = diag(1 / a_i**2)``, the identity in scaled coordinates: then ``W' = -||x||**2`` per rad of
azimuth along the linearised motions, and ``W`` (dimensionless, "norm squared times rad") is
the integral of ``||x||**2`` over the future linear motion from ``x``. Along a linear motion
``W`` decays at least as ``exp(-psi / max eig(P))`` (eigenvalues in scaled coordinates).

The start region
----------------
For a quadratic ``W`` the algorithm's steps 4 and 5 have closed forms: on the sphere
``||x|| = A``, ``inf W = A**2 min_psi l_min(psi)`` and at an azimuth ``psi_j``
``lambda0_j = A sqrt(min_psi l_min / l_max(psi_j))``, with ``l_min``, ``l_max`` the extreme
eigenvalues of the scaled ``P``. The ratio ``lambda0 / A`` is set by the condition number of
``P`` and the bound ``A`` by the nonlinear terms (step 3). :func:`optimised_quadratic_function`
chooses a diagonal ``Q`` that minimises that condition number, the largest certified
``lambda0`` for a given ``A``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import minimize

from ..conventions import DEFAULT_SCALES, TWO_PI
from ..errors import NotAsymptoticallyStableError
from ..jit import PARALLEL_MIN_STATES, threads, use_compiled
from ..methods.floquet import floquet_multipliers
from ..methods.periodic_lyapunov import PeriodicLyapunovSolution, bilinear_form, periodic_lyapunov
from ..methods.sampling import unit_sphere_points
from ..model import compiled
from ..model.blade import Blade
from ..model.equations import flatten_states, sym3_matvec
from ..model.steady import SteadyMotion, TabulatedMotion, as_steady_motion, disturbed_rhs
from ..reporting import format_small
from .fused import fused_arguments, quadratic_rate_about_tabulated, quadratic_rate_on_rays

__all__ = [
    "DEFAULT_N_STEPS",
    "EnergyFunction",
    "PositivityReport",
    "QuadraticFunction",
    "certified_radius_estimate",
    "energy_function",
    "energy_rate_terms",
    "linearisation",
    "optimised_quadratic_function",
    "quadratic_function",
]

#: Magnus steps per period for the periodic Lyapunov equation of the blade in forward flight
#: (the Jacobian has kinks where sections cross the airfoil's breakpoints; 4096 sixth-order
#: steps resolve ``P`` to about 1e-5 relative, see the residuals reported).
DEFAULT_N_STEPS = 4096

FloatArray = NDArray[np.float64]


# --------------------------------------------------------------------------------------
# The energy function (the paper's)
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class PositivityReport:
    """Local positivity of ``W`` at ``x = 0`` (condition (d) near the steady motion).

    Attributes
    ----------
    psi : numpy.ndarray
        Azimuths checked, rad.
    potential_eigenvalues : numpy.ndarray
        Eigenvalues of the Hessian of ``U`` at ``q_s(psi)``, J/rad^2, shape (n_psi, 3).
    kinetic_eigenvalues : numpy.ndarray
        Eigenvalues of ``Omega^2 M(q_s(psi))``, J/(rad/rad)^2, shape (n_psi, 3).
    positive_definite : bool
        All eigenvalues > 0: ``W`` has a strict local minimum 0 at ``x = 0`` for every psi.
    """

    psi: FloatArray
    potential_eigenvalues: FloatArray
    kinetic_eigenvalues: FloatArray
    positive_definite: bool

    def __str__(self) -> str:
        return (f"Hessian of W at x = 0: potential part eigenvalues in "
                f"[{self.potential_eigenvalues.min():.4g}, {self.potential_eigenvalues.max():.4g}] J/rad^2, "
                f"kinetic part in [{self.kinetic_eigenvalues.min():.4g}, "
                f"{self.kinetic_eigenvalues.max():.4g}] J; "
                + ("positive definite" if self.positive_definite else "NOT positive definite"))


@dataclass(frozen=True)
class EnergyFunction:
    """The energy of the disturbed motion, the paper's Liapunov function.

    For the disturbed state ``x = z - xi(psi)`` with ``q = q_s + x_q`` (``q_s = xi[:3]``) and
    the disturbed rates ``x_r = z[3:] - xi[3:]``,

        W(psi, x) = 1/2 Omega^2 x_r^T M(q) x_r + U(psi, q) - U(psi, q_s) - grad_q U(psi, q_s) . x_q,

    in J, with ``M`` the mass matrix (so the first term is the kinetic energy of the disturbance
    relative to the rotating hub) and ``U = V - T0`` the effective potential of the rotating
    frame (hinge springs with the control input and pitch-flap coupling, gravity and the
    centrifugal potential).  The linear term shifts ``U`` so that ``W(psi, 0) = 0`` and
    ``grad W(psi, 0) = 0`` even when ``q_s`` is not a conservative equilibrium (with
    aerodynamics the steady motion is held by the air loads, ``grad U(q_s) = Q_aero(q_s)``).
    In vacuum without dampers and with ``xi`` the equilibrium, ``W`` is Jacobi's integral
    ``T2 + U`` minus its value at rest, so ``W' = 0`` exactly.

    The derivative along the motion, ``W' = dW/dpsi + grad_x W . f(psi, x)`` with
    ``f = rhs(psi, xi + x) - xi'``, is computed analytically from generated code::

        grad_xq W = 1/2 Omega^2 x_r^T (dM/dq) x_r + grad U(q) - grad U(q_s),
        grad_xr W = Omega^2 M(q) x_r,
        dW/dpsi   = [1/2 Omega^2 x_r^T dM/dq x_r + grad U(q) - grad U(q_s)] . q_s'
                    - (Hess U(q_s) q_s') . x_q
                    + theta_c' [dU/dtheta_c(q) - dU/dtheta_c(q_s) - grad dU/dtheta_c(q_s) . x_q],

    where ``q_s' = xi'[:3]`` and ``theta_c'`` is the rate of the control input (the only
    explicit dependence of ``U`` on psi; ``dU/dtheta_c`` is affine in ``q``, so the last
    bracket vanishes identically and is kept only for generality).

    Conditions of the theorem (Narkiewicz & Lucjanek, section 2), on ``||x|| < H``:


    * (c) continuity and differentiability: ``W`` is analytic in ``x`` and ``psi`` (polynomial in
      the rates, trigonometric in the angles) for every state.

    * (d) positivity: ``W(psi, 0) = 0``, ``grad W(psi, 0) = 0``; ``W > 0`` for small ``x != 0``
      iff ``M(q_s)`` (always) and ``Hess U(q_s)`` are positive definite:
      :meth:`positivity` checks this.  Globally, ``W`` is not positive on every ball: the
      centrifugal potential is periodic in the angles and has other stationary points, so
      ``H`` must stay below the first of them (checked numerically by sampling, not here).

    * (e), (f) periodicity of ``W`` and its first derivatives: ``M`` and ``U`` depend on psi only
      through ``theta_c(psi)`` and ``xi(psi)``, both ``2 pi``-periodic.

    * (g) a property of the sphere extrema of ``W``, checked by the algorithm itself
      (:func:`rotorlyap.methods.lyapunov.technical_stability`).

    Attributes
    ----------
    blade : Blade
    steady : SteadyMotion
        The steady motion ``xi`` the disturbance is measured from.
    """

    blade: Blade
    steady: SteadyMotion
    _ps_const: FloatArray | None = field(init=False, repr=False, compare=False, default=None)

    # ------------------------------------------------------------------ helpers
    def steady_at(self, psi: ArrayLike) -> tuple[FloatArray, FloatArray]:
        """``xi(psi)`` and ``xi'(psi)``, each broadcastable to (..., 6)."""
        if self.steady.is_constant:
            return self.steady.state, np.zeros(6)
        psi = np.asarray(psi, dtype=np.float64)
        return (np.asarray(self.steady.xi_function(psi), dtype=np.float64),
                np.asarray(self.steady.dxi_function(psi), dtype=np.float64))

    def _steady_block(self, psi: FloatArray):
        """xi, xi' as (6, n) or (6, 1) arrays and the potential terms at q_s (rows first)."""
        xi, dxi = self.steady_at(psi)
        xi = np.asarray(xi).T.reshape(6, -1)
        dxi = np.asarray(dxi).T.reshape(6, -1)
        b = self.blade
        if self.steady.is_constant and not b.has_cyclic:
            if self._ps_const is None:
                object.__setattr__(self, "_ps_const", b.potential_terms(0.0, xi[:3]))
            ps = self._ps_const
        else:
            ps = b.potential_terms(psi, xi[:3])
        return xi, dxi, ps

    # ------------------------------------------------------------------ public
    def f(self, psi: ArrayLike, x: ArrayLike) -> FloatArray:
        """Disturbed right-hand side ``f(psi, x) = h(psi, xi + x) - xi'(psi)``, shape (..., 6)
        (:func:`rotorlyap.model.steady.disturbed_rhs`)."""
        return disturbed_rhs(self.blade, self.steady)(psi, x)

    def W(self, psi: ArrayLike, x: ArrayLike) -> FloatArray:
        """Liapunov function ``W(psi, x)``, J, shape ``x.shape[:-1]`` (broadcast with psi)."""
        b = self.blade
        if b.kernel is not None:
            pf, xf, shape = flatten_states(psi, x)
            xi, ps = self._steady_rows(pf)
            return compiled.energy_value(b, b.kernel, pf, xf, xi, ps).reshape(shape)

        def kernel(psi_b, xc):
            xi, _, ps = self._steady_block(psi_b)
            q = xi[:3] + xc[:3]
            thc = b.pitch_control(psi_b)
            kin, U = b.energy_terms(q, xc[3:], thc)
            return (kin + U - ps[0] - (ps[1:4] * xc[:3]).sum(axis=0))[None]

        return b.blocks(psi, x, kernel, 1)[..., 0]

    def dW(self, psi: ArrayLike, x: ArrayLike) -> FloatArray:
        """Derivative of ``W`` along the motion, ``W' = dW/dpsi + grad W . f``, J/rad.

        Analytic (generated code), no finite differences; shape ``x.shape[:-1]``.
        """
        b = self.blade
        if b.kernel is None:
            return b.blocks(psi, x, self._dw_block, 1)[..., 0]
        pf, xf, shape = flatten_states(psi, x)
        xi, ps, dxi = self._steady_rows(pf, rates=True)
        return compiled.energy_rate(b, b.kernel, pf, xf, xi, dxi, ps, self.steady.is_constant).reshape(shape)

    def dW_and_f(self, psi: ArrayLike, x: ArrayLike) -> tuple[FloatArray, FloatArray]:
        """``(W', f)`` at the states ``x`` (2-d, (m, 6)): :meth:`dW` and the disturbed right-hand
        side :meth:`f`, from one compiled kernel where the blade has the block kernels (the
        accelerations ``W'`` needs are ``f``'s), else the two calls. For functions built on this
        one whose other terms need ``f`` too (the augmented energy's quadratic forms)."""
        b = self.blade
        if b.kernel is None or not b.kernel.block:
            return self.dW(psi, x), self.f(psi, x)
        pf, xf, shape = flatten_states(psi, x)
        xi, ps, dxi = self._steady_rows(pf, rates=True)
        dw, fx = compiled.energy_rate_and_rhs(b, b.kernel, pf, xf, xi, dxi, ps, self.steady.is_constant)
        return dw.reshape(shape), fx.reshape(shape + (6,))

    def _steady_rows(self, pf: FloatArray, rates: bool = False):
        """``xi``, the potential terms at its hinge angles and (``rates``) ``xi'``, one row for a
        constant steady motion without cyclic pitch, else one row per azimuth of ``pf`` (each
        distinct azimuth computed once: searches repeat each)."""
        b = self.blade
        constant = self.steady.is_constant
        if constant and not b.has_cyclic:
            xi, dxi, ps = self.steady.state[None], np.zeros((1, 6)), self._steady_block(pf[:1])[2].T
        else:
            pu, inverse = np.unique(pf, return_inverse=True)
            if constant:
                xi_u, dxi_u = np.broadcast_to(self.steady.state, (pu.size, 6)), np.zeros((1, 6))
            else:  # xi' only where asked for (W itself does not need it)
                xi_u = np.asarray(self.steady.xi_function(pu), dtype=np.float64)
                dxi_u = np.asarray(self.steady.dxi_function(pu), dtype=np.float64)[inverse] if rates else None
            ps = b.potential_terms(pu, np.ascontiguousarray(xi_u[:, :3].T)).T[inverse]
            xi, dxi = (xi_u[:1], dxi_u[:1]) if constant else (xi_u[inverse], dxi_u)
        return (xi, ps, dxi) if rates else (xi, ps)

    def _dw_block(self, psi: FloatArray, xc: FloatArray) -> FloatArray:
        """W' for one block of disturbed states ``xc`` (6, n)."""
        b = self.blade
        om2 = b.omega * b.omega
        xi, dxi, ps = self._steady_block(psi)
        zc = xc + xi
        xq, xr = xc[:3], xc[3:]
        gU_s = ps[1:4]
        thc = b.pitch_control(psi)
        T = b.energy_rate_terms(zc, thc, xr)
        a = b.accelerations(psi, zc, T)
        dT2 = T[42:45]
        gU = T[45:48]
        gq = dT2 + gU - gU_s  # grad_xq W
        mx = sym3_matvec(T[0:6], xr[0], xr[1], xr[2])  # M x_r
        dW = (gq[0] * (zc[3] - dxi[0]) + gq[1] * (zc[4] - dxi[1]) + gq[2] * (zc[5] - dxi[2])
              + om2 * (mx[0] * (a[0] - dxi[3]) + mx[1] * (a[1] - dxi[4]) + mx[2] * (a[2] - dxi[5])))
        if not self.steady.is_constant:  # explicit psi-dependence through q_s(psi)
            hq = sym3_matvec(ps[4:10], dxi[0], dxi[1], dxi[2])
            dW = dW + ((dT2 + gU - gU_s) * dxi[0:3]).sum(axis=0) \
                - (hq[0] * xq[0] + hq[1] * xq[1] + hq[2] * xq[2])
        if b.has_cyclic:  # explicit psi-dependence through theta_c(psi)
            dthc = b.pitch_control_rate(psi)
            dW = dW + dthc * (T[48] - ps[10] - (ps[11:14] * xq).sum(axis=0))
        return dW[None]

    def positivity(self, n_psi: int = 36) -> PositivityReport:
        """Check that the Hessian of ``W`` at ``x = 0`` is positive definite (condition (d)).

        The Hessian is block diagonal: ``Hess U(psi, q_s)`` for the displacements and
        ``Omega^2 M(q_s)`` for the rates.

        Parameters
        ----------
        n_psi : int
            Number of azimuths on ``[0, 2 pi)``.

        Returns
        -------
        PositivityReport
        """
        psi = np.linspace(0.0, 2.0 * np.pi, n_psi, endpoint=False)
        xi, _ = self.steady_at(psi)
        xi = np.broadcast_to(xi, (n_psi, 6))
        ps = np.broadcast_to(self.blade.potential_terms(psi, xi[:, :3].T).T, (n_psi, 14))
        idx = np.array([[0, 1, 2], [1, 3, 4], [2, 4, 5]])
        H = ps[:, 4:10][:, idx]
        M = self.blade.mass_matrix(xi) * self.blade.omega ** 2
        eu = np.linalg.eigvalsh(H)
        ek = np.linalg.eigvalsh(M)
        return PositivityReport(psi=psi, potential_eigenvalues=eu, kinetic_eigenvalues=ek,
                                positive_definite=bool((eu > 0).all() and (ek > 0).all()))


def energy_function(blade: Blade, steady=None) -> EnergyFunction:
    """The paper's Liapunov function (energy of the disturbed motion) about a steady motion.

    Parameters
    ----------
    blade : Blade
        The blade at its advance ratio.
    steady : SteadyMotion, optional
        The steady motion, or anything :func:`~rotorlyap.model.steady.as_steady_motion` takes;
        default the hover equilibrium (the paper's choice).

    Returns
    -------
    EnergyFunction
    """
    return EnergyFunction(blade, as_steady_motion(steady, blade))


def energy_rate_terms(blade: Blade, xi, psi, x) -> dict[str, np.ndarray]:
    """Split the energy function's ``W'`` into the work rates of the forces on each hinge.

    For a constant steady motion ``xi`` and no cyclic pitch, Lagrange's equations give
    ``dW/dt = qdot . (Q_damp + Q_aero(z) + F_c(xi))``, where ``F_c(xi)`` is the conservative
    generalised force at ``xi`` at rest (minus the gradient of the effective potential), so
    that, per unit of azimuth,

    ``W' = sum_h q'_h [Q_damp,h + (Q_aero,h(psi, z) + F_c,h(xi))]``.

    At the hover equilibrium ``F_c(xi) = -Q_aero(xi)``: the second bracket is the change of
    the aerodynamic load caused by the disturbance. The sum of all terms equals
    ``energy_function(blade, xi).dW`` (a unit test checks it).

    Parameters
    ----------
    blade : Blade
        The blade (no cyclic pitch).
    xi : array_like
        Constant steady motion, shape (6,).
    psi : float or numpy.ndarray
        Azimuth(s), broadcasting with ``x[..., 0]``.
    x : numpy.ndarray
        Disturbed states, shape (..., 6).

    Returns
    -------
    dict
        ``"damping"`` and ``"aerodynamic"``: per-hinge work rates (J/rad), shape (..., 3),
        hinges in the order flap, lag, pitch; ``"total"``: their sum over hinges and kinds,
        shape (...).
    """
    if blade.has_cyclic:
        raise ValueError("energy_rate_terms needs a blade without cyclic pitch (W then has no explicit psi-dependence)")
    xi = np.asarray(xi, dtype=float)
    if xi.shape != (6,):
        raise ValueError(f"xi must be a constant state of shape (6,), got {xi.shape}")
    x = np.asarray(x, dtype=float)
    z = xi + x
    forces = blade.generalised_forces(psi, z)
    steady = blade.generalised_forces(0.0, np.concatenate([xi[:3], np.zeros(3)]))["conservative"]
    rates = z[..., 3:] - xi[3:]
    damping = rates * forces["damping"]
    aero = rates * (forces["aerodynamic"] + steady)
    return {"damping": damping, "aerodynamic": aero, "total": damping.sum(-1) + aero.sum(-1)}


# --------------------------------------------------------------------------------------
# Quadratic functions from the periodic Lyapunov equation
# --------------------------------------------------------------------------------------


def linearisation(blade: Blade, steady=None) -> Callable | np.ndarray:
    """The blade linearised about the steady motion: ``J(psi) = dh/dz(psi, xi(psi))``.

    ``steady`` is a :class:`~rotorlyap.model.steady.SteadyMotion` or anything
    :func:`~rotorlyap.model.steady.as_steady_motion` takes (None: the hover equilibrium).
    Returns a constant ``(6, 6)`` array when the linearisation does not depend on the azimuth
    (constant ``xi``, hover, no cyclic pitch), otherwise a vectorised callable
    ``J(psi (k,)) -> (k, 6, 6)``.
    """
    steady = as_steady_motion(steady, blade)
    if steady.is_constant:
        const = steady.state
        if blade.mu == 0.0 and not blade.has_cyclic:
            return blade.jacobian(0.0, const)
        return lambda psi: blade.jacobian(psi, np.broadcast_to(const, np.shape(psi) + (6,)))
    xi = steady.xi_function
    return lambda psi: blade.jacobian(psi, xi(psi))


class _Cached:
    """Memoise ``J(psi)`` on arrays of azimuths (several Lyapunov solves share the nodes)."""

    def __init__(self, fun):
        self.fun, self.memo = fun, {}

    def __call__(self, psi):
        psi = np.asarray(psi, dtype=float)
        key = psi.tobytes()
        if key not in self.memo:
            self.memo[key] = self.fun(psi)
        return self.memo[key]


def _scaled(J, a: np.ndarray):
    """``S^-1 J S`` with ``S = diag(a)``: the linearisation in scaled coordinates."""
    if callable(J):
        return lambda psi: J(psi) * (1.0 / a)[:, None] * a[None, :]
    return J * (1.0 / a)[:, None] * a[None, :]


@dataclass(frozen=True)
class QuadraticFunction:
    """``W(psi, x) = x^T P(psi) x`` from the periodic Lyapunov equation (module docstring).

    Has the vectorised ``W``, ``dW`` and ``f`` that :func:`rotorlyap.analysis.stability.blade_stability`
    and :func:`rotorlyap.technical_stability` take.

    Attributes
    ----------
    blade : Blade
        The blade (advance ratio, controls).
    steady : SteadyMotion
        The steady motion ``xi`` the disturbance is measured from.
    Q : numpy.ndarray
        The weight in state units, ``(6, 6)``: ``W' = -x^T Q x`` along the linearised motions.
    scales : numpy.ndarray
        The ``a_i`` of the scaled coordinates ``y = x / a`` in which ``P`` was computed.
    solution : PeriodicLyapunovSolution
        The solution in scaled coordinates (``P_s = S P S``, ``S = diag(a)``), with its
        Floquet result and accuracy checks.
    label : str
        A short name for tables and legends.
    """

    blade: Blade
    steady: SteadyMotion
    Q: np.ndarray
    scales: np.ndarray
    solution: PeriodicLyapunovSolution
    label: str = "quadratic"

    # ------------------------------------------------------------------ diagnostics
    @property
    def constant(self) -> bool:
        """``P`` does not depend on the azimuth (hover about the equilibrium)."""
        return self.solution.constant

    @property
    def spectral_radius(self) -> float:
        """Largest modulus of a Floquet multiplier of the linearised blade (< 1)."""
        return float(self.solution.floquet.spectral_radius)

    @property
    def growth_rate(self) -> float:
        """Largest real part of a characteristic exponent, per rev (< 0)."""
        return float(np.log(self.spectral_radius) / TWO_PI)

    @property
    def eigenvalue_range(self) -> tuple[float, float]:
        """Smallest and largest eigenvalue of the scaled ``P`` over the grid and midpoints."""
        return float(self.solution.min_eigenvalue), float(self.solution.max_eigenvalue)

    @property
    def condition_number(self) -> float:
        """``max l_max / min l_min`` of the scaled ``P`` over the period."""
        lo, hi = self.eigenvalue_range
        return hi / lo

    @property
    def lambda0_ratio(self) -> float:
        """``min_j lambda0_j / A = 1 / sqrt(condition_number)``: the smallest start region
        relative to the bound, if step 3 passes at ``A`` (module docstring)."""
        return float(1.0 / np.sqrt(self.condition_number))

    @property
    def relative_residual(self) -> float:
        """Relative residual of the periodic Lyapunov equation (see the solution)."""
        return float(self.solution.relative_residual)

    def summary(self) -> str:
        """One line with the rounded diagnostics (stable text, no arrays; the residual as a
        bound, :func:`rotorlyap.reporting.format_small`)."""
        lo, hi = self.eigenvalue_range
        return (f"{self.label}: spectral radius {self.spectral_radius:.4f}, growth rate "
                f"{self.growth_rate:+.4f}/rev, eig(P_scaled) in [{lo:.4g}, {hi:.4g}], "
                f"lambda0/A = {self.lambda0_ratio:.4f}, relative residual {format_small(self.relative_residual)}")

    # ------------------------------------------------------------------ P
    def P_scaled(self, psi) -> np.ndarray:
        """``P`` in scaled coordinates, shape ``psi.shape + (6, 6)``."""
        return self.solution.P(psi)

    def P(self, psi) -> np.ndarray:
        """``P(psi)`` in state units (1/rad^2 for angles), shape ``psi.shape + (6, 6)``."""
        inv = 1.0 / self.scales
        return self.solution.P(psi) * inv[:, None] * inv[None, :]

    def w_matrix(self, scales) -> Callable[[np.ndarray], np.ndarray]:
        """``S(psi) = diag(a) P(psi) diag(a)``: the matrix of ``W = y^T S y`` in the coordinates
        ``y = x / a`` of a norm with scales ``a`` (which :func:`rotorlyap.technical_stability`
        takes as ``w_matrix`` and finds by itself: the closed-form extrema of ``W`` on spheres).

        Parameters
        ----------
        scales : array_like
            The norm's scales ``a_i``, 6 positive numbers.

        Returns
        -------
        callable
            ``S(psi)``, shape ``psi.shape + (6, 6)``.
        """
        a = _check_scales(scales)
        return lambda psi: a[:, None] * self.P(psi) * a[None, :]

    def dP(self, psi) -> np.ndarray:
        """``P'(psi)`` in state units, shape ``psi.shape + (6, 6)``."""
        inv = 1.0 / self.scales
        return self.solution.dP(psi) * inv[:, None] * inv[None, :]

    # ------------------------------------------------------------------ W, W', f
    def _steady(self, psi: np.ndarray):
        if self.steady.is_constant:
            return self.steady.state, 0.0
        return (np.asarray(self.steady.xi_function(psi), dtype=float),
                np.asarray(self.steady.dxi_function(psi), dtype=float))

    def f(self, psi, x) -> np.ndarray:
        """Full nonlinear disturbed right-hand side ``h(psi, xi + x) - xi'(psi)``, shape of x
        (:func:`rotorlyap.model.steady.disturbed_rhs`)."""
        return disturbed_rhs(self.blade, self.steady)(psi, x)

    def W(self, psi, x) -> np.ndarray:
        """``W = x^T P(psi) x``: ``x`` of shape ``(m, 6)``, ``psi`` broadcasting to ``(m,)``."""
        y = np.atleast_2d(np.asarray(x, dtype=float)) / self.scales
        psi = np.broadcast_to(np.asarray(psi, dtype=float), y.shape[:1])
        if self.constant:
            return bilinear_form(y, self.solution.P_grid[0], y)
        return self.solution.W(psi, y)

    def dW(self, psi, x) -> np.ndarray:
        """``W' = x^T P' x + 2 x^T P f(psi, x)`` with the full nonlinear ``f``, shape ``(m,)``."""
        x = np.atleast_2d(np.asarray(x, dtype=float))
        psi = np.broadcast_to(np.asarray(psi, dtype=float), x.shape[:1])
        fused = self._fused_for(psi, x.shape[0])
        if fused is not None:  # the same numbers in one compiled call (rotorlyap.analysis.fused)
            return quadratic_rate_about_tabulated(psi, x, self.scales, *fused)
        y = x / self.scales
        fy = self.f(psi, x) / self.scales
        if self.constant:
            return 2.0 * bilinear_form(y, self.solution.P_grid[0], fy)
        return self.solution.dW(psi, y, fy)

    def ray_rate(self, psi, y, level: float, bound: float, scales) -> tuple[np.ndarray, np.ndarray] | None:
        """``W`` at ``u a`` and ``W'`` at the band's point of each search coordinate ``y`` of
        :func:`rotorlyap.methods.lyapunov.band_max_dw` (``u = y / |y|``, ``a = scales``; see
        :func:`rotorlyap.analysis.fused.quadratic_rate_on_rays`), in one compiled call; None
        where that call does not apply (as :meth:`dW`'s fused call, and batches that
        :meth:`dW` gives to the threaded kernels), and the search maps ``y`` itself."""
        y = np.asarray(y, dtype=float)
        if y.ndim != 2 or y.shape[1] != 6:
            return None
        psi = np.broadcast_to(np.asarray(psi, dtype=float), y.shape[:1])
        fused = self._fused_for(psi, y.shape[0])
        if fused is None:
            return None
        return quadratic_rate_on_rays(psi, y, level, bound, scales, self.scales, *fused)

    def _fused_for(self, psi: np.ndarray, m: int):
        """:meth:`_fused` for a batch of ``m`` states at azimuths ``psi`` (refused unless finite),
        or None for batches that go to the threaded kernels (``m >= PARALLEL_MIN_STATES`` with
        two threads or more)."""
        if not (m < PARALLEL_MIN_STATES or threads() < 2):
            return None
        fused = self._fused()
        if fused is not None and not np.all(np.isfinite(psi)):
            raise ValueError("psi must be finite")
        return fused

    def _fused(self):
        """The arguments of :func:`rotorlyap.analysis.fused.quadratic_rate_about_tabulated`
        after ``psi``, ``x`` and the scales, or None where it does not apply (a constant
        ``P``, a steady motion that is not a :class:`~rotorlyap.model.steady.TabulatedMotion`,
        the numpy kernels, the blade's one-state kernels)."""
        if self.constant or self.solution.interpolation != "hermite" or not use_compiled():
            return None
        args = self.__dict__.get("_fused_args", False)
        if args is False:  # once: whether it applies, and its arrays
            motion = getattr(self.steady.xi_function, "__self__", None)
            kernel = self.blade.kernel
            args = None
            if (isinstance(motion, TabulatedMotion) and getattr(self.steady.dxi_function, "__self__", None) is motion
                    and kernel is not None and kernel.block):
                args = fused_arguments(self.blade, motion, self.solution)
            object.__setattr__(self, "_fused_args", args)
        return args

    def dW_linear(self, psi, x) -> np.ndarray:
        """``W'`` along the linearised motion ``x' = J x`` (``-x^T Q x`` up to the residual)."""
        x = np.atleast_2d(np.asarray(x, dtype=float))
        psi = np.broadcast_to(np.asarray(psi, dtype=float), x.shape[:1])
        xi, _ = self._steady(psi)
        J = self.blade.jacobian(psi, np.broadcast_to(xi, x.shape))
        xdot = np.einsum("mij,mj->mi", J, x)
        y, fy = x / self.scales, xdot / self.scales
        P = self.solution.P(psi)
        return np.einsum("mi,mij,mj->m", y, self.solution.dP(psi), y) + 2.0 * np.einsum(
            "mi,mij,mj->m", y, P, fy)

    def __repr__(self) -> str:  # short and stable: no arrays, no addresses
        return f"QuadraticFunction({self.summary()})"


def _check_scales(scales) -> np.ndarray:
    a = np.array(DEFAULT_SCALES if scales is None else scales, dtype=float).reshape(-1)
    if a.shape != (6,) or not np.all(np.isfinite(a)) or np.any(a <= 0):
        raise ValueError(f"scales must be 6 finite numbers > 0 (rad, rad/rad), got {np.asarray(scales).tolist()}")
    return a


def _check_Q(Q, a: np.ndarray) -> np.ndarray:
    if Q is None:
        return np.diag(1.0 / a**2)
    Q = np.asarray(Q, dtype=float)
    if Q.ndim == 1:
        Q = np.diag(Q)
    if Q.shape != (6, 6) or not np.all(np.isfinite(Q)):
        raise ValueError(f"Q must be a finite (6, 6) matrix or 6 diagonal weights, got shape {Q.shape}")
    if np.max(np.abs(Q - Q.T)) > 1e-12 * np.max(np.abs(Q)):
        raise ValueError("Q must be symmetric")
    lam = np.linalg.eigvalsh(0.5 * (Q + Q.T))
    if lam[0] <= 0:
        raise ValueError(f"Q must be positive definite; its smallest eigenvalue is {lam[0]:.6g}")
    return 0.5 * (Q + Q.T)


def _solve(J_scaled, Q_scaled: np.ndarray, n_steps: int, where: str) -> PeriodicLyapunovSolution:
    try:
        if callable(J_scaled):
            return periodic_lyapunov(J_scaled, TWO_PI, Q_scaled, method="magnus6",
                                     n_steps=n_steps, vectorized=True)
        return periodic_lyapunov(J_scaled, TWO_PI, Q_scaled)
    except NotAsymptoticallyStableError as exc:
        if callable(J_scaled):
            res = floquet_multipliers(J_scaled, TWO_PI, method="magnus6", n_steps=min(n_steps, 1024),
                                      vectorized=True)
            rho = res.spectral_radius
            rate = float(np.max(res.exponents.real))
        else:
            lam = np.linalg.eigvals(J_scaled)
            rate = float(np.max(lam.real))
            rho = float(np.exp(TWO_PI * rate))
        raise NotAsymptoticallyStableError(
            f"the blade linearised about {where} is not asymptotically stable: the spectral "
            f"radius of its monodromy matrix is {rho:.6g} >= 1 (largest growth rate "
            f"{rate:+.4g} per rev), so no quadratic Liapunov function x^T P x with W' < 0 "
            "near x = 0 exists, and the steady motion is unstable: no certificate with a small "
            "bound A is possible",
            spectral_radius=rho, growth_rate=rate,
        ) from exc


def quadratic_function(blade: Blade, steady=None, Q=None, *, scales=None,
                       n_steps: int = DEFAULT_N_STEPS, label: str = "quadratic") -> QuadraticFunction:
    """The quadratic Liapunov function of the blade about a steady motion.

    Parameters
    ----------
    blade : Blade
        The blade at its advance ratio.
    steady : SteadyMotion, optional
        The steady motion, or anything :func:`~rotorlyap.model.steady.as_steady_motion` takes:
        None for the hover equilibrium (:meth:`Blade.equilibrium`), a constant state, a
        :class:`~rotorlyap.model.steady.PeriodicMotion` or
        :class:`~rotorlyap.model.steady.TabulatedMotion`.
    Q : array_like, optional
        Symmetric positive-definite weight ``(6, 6)``, or its 6 diagonal entries, in state
        units (1/rad^2 for angles, 1/(rad/rad)^2 for rates): ``W' = -x^T Q x`` along the
        linearised motions. Default ``diag(1 / a_i**2)``: the identity in scaled coordinates,
        ``W' = -||x||**2``.
    scales : array_like, optional
        The ``a_i`` of the scaled coordinates (and of the default ``Q``); default
        :data:`rotorlyap.conventions.DEFAULT_SCALES`. Use the scales of the norm the engine
        works with.
    n_steps : int
        Sixth-order Magnus steps per period for a periodic ``P`` (ignored in hover about the
        equilibrium, where ``P`` is constant and exact).
    label : str
        Name for tables and legends.

    Returns
    -------
    QuadraticFunction

    Raises
    ------
    rotorlyap.errors.NotAsymptoticallyStableError
        If the linearised blade is not asymptotically stable (a ``ValueError`` carrying the
        spectral radius of the monodromy matrix and the growth rate): then no quadratic
        function exists.
    ValueError
        For a bad ``Q``, ``scales`` or ``steady``.
    """
    a = _check_scales(scales)
    Q = _check_Q(Q, a)
    steady = as_steady_motion(steady, blade)
    J = linearisation(blade, steady)
    where = ("the hover equilibrium" if steady.is_constant and blade.mu == 0.0
             else "the constant state (hover equilibrium reused in forward flight)" if steady.is_constant
             else "the periodic steady motion")
    Qs = Q * a[:, None] * a[None, :]
    sol = _solve(_scaled(J, a), Qs, int(n_steps), where)
    return QuadraticFunction(blade=blade, steady=steady, Q=Q, scales=a, solution=sol, label=label)


def certified_radius_estimate(fun: QuadraticFunction, A: float, *, psi=None, n_directions: int = 256,
                              n_bisect: int = 10, seed: int = 0) -> tuple[float, float]:
    """A quick estimate of what the engine will certify with a quadratic function.

    Along each of the structured and ``n_directions`` quasi-random directions ``d`` of
    :func:`rotorlyap.methods.sampling.unit_sphere_points` (scaled coordinates) and at each azimuth of
    ``psi``, the radius ``r(d)`` where ``W'(psi, r d)`` first turns positive is bisected on
    ``(0, A]`` (``A`` if it does not); the estimate of step 3 is ``A1 = min r(d)``, and of
    steps 4-5 ``lambda0 = A1 sqrt(min l_min / max l_max)`` (module docstring). Not a
    certificate: the engine's sphere search decides; this is the objective of
    :func:`optimised_quadratic_function`.

    Returns
    -------
    (float, float)
        ``(A1, lambda0)`` estimates.
    """
    dirs = unit_sphere_points(6, n_directions, seed)
    psi = np.zeros(1) if psi is None or fun.constant else np.asarray(psi, dtype=float).reshape(-1)
    pp = np.repeat(psi, dirs.shape[0])
    dd = np.tile(dirs, (psi.size, 1)) * fun.scales
    lo, hi = np.zeros(pp.size), np.full(pp.size, float(A))
    ok = fun.dW(pp, hi[:, None] * dd) <= 0.0
    lo[ok] = A
    todo = ~ok
    for _ in range(n_bisect):
        if not todo.any():
            break
        mid = 0.5 * (lo + hi)
        neg = np.ones(pp.size, dtype=bool)
        neg[todo] = fun.dW(pp[todo], mid[todo, None] * dd[todo]) <= 0.0
        lo = np.where(todo & neg, mid, lo)
        hi = np.where(todo & ~neg, mid, hi)
    A1 = float(lo.min())
    return A1, A1 * fun.lambda0_ratio


def optimised_quadratic_function(blade: Blade, steady=None, *, A: float = 1.0, scales=None,
                                 n_steps: int = DEFAULT_N_STEPS, n_steps_search: int = 256,
                                 psi_search=None, n_directions: int = 128,
                                 max_evaluations: int = 200,
                                 label: str = "quadratic, optimised Q") -> QuadraticFunction:
    """The quadratic function whose diagonal weight maximises the estimated start region.

    Searches ``Q = diag(w_i / a_i**2)`` (``w`` normalised to a geometric mean of 1) for the
    largest ``lambda0`` estimated by :func:`certified_radius_estimate` for the bound ``A``,
    by Nelder-Mead on ``log w`` from ``w = 1`` (the default weight of
    :func:`quadratic_function`), keeping the start if nothing better is found. The
    condition number of ``P`` alone is a poor objective: it drives some weights to zero,
    where ``W' = -x^T Q x`` no longer dominates the nonlinear terms and step 3 shrinks ``A``
    to almost nothing; the estimate weighs both effects.
    In forward flight the search uses ``n_steps_search`` Magnus steps (the Jacobian is
    evaluated once and cached) and the azimuths ``psi_search`` (default 8); the final ``P``
    is computed with ``n_steps``.

    Parameters
    ----------
    blade, steady, scales, n_steps, label
        As :func:`quadratic_function`.
    A : float
        The bound of the scaled norm the engine will be asked for.
    n_steps_search : int
        Magnus steps per period during the search (forward flight only).
    psi_search : array_like, optional
        Azimuths of the estimate in forward flight.
    n_directions : int
        Quasi-random directions of the estimate.
    max_evaluations : int
        Largest number of objective evaluations (one Lyapunov solve each).

    Returns
    -------
    QuadraticFunction
        With the optimised diagonal ``Q``.

    Raises
    ------
    rotorlyap.errors.NotAsymptoticallyStableError
        As :func:`quadratic_function` (unstable linearisation).
    """
    a = _check_scales(scales)
    steady = as_steady_motion(steady, blade)
    J = linearisation(blade, steady)
    Js = _scaled(J, a)
    if callable(Js):
        Js = _Cached(Js)
    psi_search = TWO_PI * np.arange(8) / 8 if psi_search is None else psi_search

    def make(w, steps):
        sol = _solve(Js, np.diag(w), steps, "the steady motion")
        return QuadraticFunction(blade=blade, steady=steady, Q=np.diag(w / a**2),
                                 scales=a, solution=sol, label=label)

    def objective(logw):
        w = np.exp(logw - logw.mean())
        try:
            fun = make(w, n_steps_search)
        except NotAsymptoticallyStableError:
            return np.inf
        return -np.log(max(certified_radius_estimate(fun, A, psi=psi_search,
                                                     n_directions=n_directions)[1], 1e-300))

    start = objective(np.zeros(6))
    with np.errstate(invalid="ignore"):
        res = minimize(objective, np.zeros(6), method="Nelder-Mead",
                       options=dict(maxfev=int(max_evaluations), xatol=1e-2, fatol=1e-4,
                                    initial_simplex=np.vstack([np.zeros(6), np.eye(6)])))
    logw = res.x if np.isfinite(res.fun) and res.fun < start else np.zeros(6)
    w = np.exp(logw - logw.mean())
    return quadratic_function(blade, steady, np.diag(w / a**2), scales=a, n_steps=n_steps, label=label)
