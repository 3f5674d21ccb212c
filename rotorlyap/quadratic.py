"""Quadratic Liapunov functions of the blade, from the periodic Lyapunov equation.

The paper's energy function lacks the aerodynamic coupling of the blade (the flap moment due
to pitch has no matching pitch moment due to flap), so its derivative along the motions has
terms linear in the rates and of either sign, and it certifies nothing in the strict reading
(:mod:`rotorlyap.stability`). A quadratic form built from the *linearised* blade does not
have that defect: if the blade linearised about its steady motion ``xi(psi)``,

    ``x' = J(psi) x``,  ``J(psi) = dh/dz (psi, xi(psi))``  (:meth:`rotorlyap.Blade.jacobian`),

is asymptotically stable (every Floquet multiplier inside the unit circle), then for every
symmetric positive-definite ``Q`` the periodic Lyapunov equation
``P' + J^T P + P J = -Q`` has one periodic, positive-definite solution ``P(psi)``
(:func:`rotorlyap.periodic_lyapunov.periodic_lyapunov`) and

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
``||x|| = |y|`` (the ``a_i`` default to :data:`rotorlyap.stability.DEFAULT_SCALES`), where the
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
from scipy.optimize import minimize

from .periodic_lyapunov import PeriodicLyapunovSolution, periodic_lyapunov
from .reporting import format_small

__all__ = [
    "DEFAULT_N_STEPS",
    "QuadraticFunction",
    "certified_radius_estimate",
    "optimised_quadratic_function",
    "quadratic_function",
    "linearisation",
]

TWO_PI = 2.0 * np.pi

#: Magnus steps per period for the periodic Lyapunov equation of the blade in forward flight
#: (the Jacobian has kinks where sections cross the airfoil's breakpoints; 4096 sixth-order
#: steps resolve ``P`` to about 1e-5 relative, see the residuals reported).
DEFAULT_N_STEPS = 4096


def _default_scales() -> np.ndarray:
    from .stability import DEFAULT_SCALES

    return np.array(DEFAULT_SCALES, dtype=float)


def _steady(blade, xi, dxi):
    """Normalise the steady motion: ``(xi_const or None, xi, dxi)``.

    A callable ``xi`` that is constant (checked on 16 azimuths, e.g. the periodic motion at
    ``mu = 0``) is replaced by its constant value, so that the hover case gets the constant,
    exact solution.
    """
    if xi is None:
        xi = blade.equilibrium()
    if callable(xi):
        if not callable(dxi):
            raise ValueError("a callable steady motion xi(psi) needs its derivative dxi(psi)")
        grid = TWO_PI * np.arange(16) / 16
        vals = np.asarray(xi(grid), dtype=float)
        if vals.shape != (16, 6) or not np.all(np.isfinite(vals)):
            raise ValueError(f"xi(psi) must return finite states of shape (k, 6), got {vals.shape}")
        rates = np.asarray(dxi(grid), dtype=float)
        if np.ptp(vals, axis=0).max() < 1e-12 and np.abs(rates).max() < 1e-12:
            return vals[0].copy(), vals[0].copy(), None
        return None, xi, dxi
    xi = np.asarray(xi, dtype=float)
    if xi.shape != (6,) or not np.all(np.isfinite(xi)):
        raise ValueError(f"a constant steady motion xi must be a finite state of shape (6,), got {xi.shape}")
    return xi, xi, None


def linearisation(blade, xi=None, dxi=None) -> Callable | np.ndarray:
    """The blade linearised about the steady motion: ``J(psi) = dh/dz(psi, xi(psi))``.

    Returns a constant ``(6, 6)`` array when the linearisation does not depend on the azimuth
    (constant ``xi``, hover, no cyclic pitch), otherwise a vectorised callable
    ``J(psi (k,)) -> (k, 6, 6)``.
    """
    const, xi, dxi = _steady(blade, xi, dxi)
    if const is not None and blade.mu == 0.0 and not blade.has_cyclic:
        return blade.jacobian(0.0, const)
    if const is not None:
        return lambda psi: blade.jacobian(psi, np.broadcast_to(const, np.shape(psi) + (6,)))
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

    Has the vectorised ``W``, ``dW`` and ``f`` that :func:`rotorlyap.stability.blade_stability`
    and :func:`rotorlyap.technical_stability` take.

    Attributes
    ----------
    blade : Blade
        The blade (advance ratio, controls).
    xi, dxi : numpy.ndarray or callable
        The steady motion: a constant state (then ``dxi`` is None) or ``xi(psi)``, ``xi'(psi)``.
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

    blade: object
    xi: object
    dxi: object
    Q: np.ndarray
    scales: np.ndarray
    solution: PeriodicLyapunovSolution
    label: str = "quadratic"
    _const: np.ndarray | None = field(default=None, repr=False, compare=False)

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

    def dP(self, psi) -> np.ndarray:
        """``P'(psi)`` in state units, shape ``psi.shape + (6, 6)``."""
        inv = 1.0 / self.scales
        return self.solution.dP(psi) * inv[:, None] * inv[None, :]

    # ------------------------------------------------------------------ W, W', f
    def _steady(self, psi: np.ndarray):
        if self._const is not None:
            return self._const, 0.0
        return np.asarray(self.xi(psi), dtype=float), np.asarray(self.dxi(psi), dtype=float)

    def f(self, psi, x) -> np.ndarray:
        """Full nonlinear disturbed right-hand side ``h(psi, xi + x) - xi'(psi)``, shape of x."""
        x = np.asarray(x, dtype=float)
        psi = np.broadcast_to(np.asarray(psi, dtype=float), x.shape[:-1])
        xi, dxi = self._steady(psi)
        return self.blade.rhs(psi, xi + x) - dxi

    def W(self, psi, x) -> np.ndarray:
        """``W = x^T P(psi) x``: ``x`` of shape ``(m, 6)``, ``psi`` broadcasting to ``(m,)``."""
        y = np.atleast_2d(np.asarray(x, dtype=float)) / self.scales
        psi = np.broadcast_to(np.asarray(psi, dtype=float), y.shape[:1])
        if self.constant:
            return np.einsum("mi,ij,mj->m", y, self.solution.P_grid[0], y)
        return np.einsum("mi,mij,mj->m", y, self.solution.P(psi), y)

    def dW(self, psi, x) -> np.ndarray:
        """``W' = x^T P' x + 2 x^T P f(psi, x)`` with the full nonlinear ``f``, shape ``(m,)``."""
        x = np.atleast_2d(np.asarray(x, dtype=float))
        psi = np.broadcast_to(np.asarray(psi, dtype=float), x.shape[:1])
        y = x / self.scales
        fy = self.f(psi, x) / self.scales
        if self.constant:
            return 2.0 * np.einsum("mi,ij,mj->m", y, self.solution.P_grid[0], fy)
        return (np.einsum("mi,mij,mj->m", y, self.solution.dP(psi), y)
                + 2.0 * np.einsum("mi,mij,mj->m", y, self.solution.P(psi), fy))

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
    a = _default_scales() if scales is None else np.array(scales, dtype=float).reshape(-1)
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
    except ValueError as exc:
        if "not asymptotically stable" not in str(exc):
            raise
        if callable(J_scaled):
            from .floquet import floquet_multipliers

            res = floquet_multipliers(J_scaled, TWO_PI, method="magnus6", n_steps=min(n_steps, 1024),
                                      vectorized=True)
            rho = res.spectral_radius
            rate = float(np.max(res.exponents.real))
        else:
            lam = np.linalg.eigvals(J_scaled)
            rate = float(np.max(lam.real))
            rho = float(np.exp(TWO_PI * rate))
        raise ValueError(
            f"the blade linearised about {where} is not asymptotically stable: the spectral "
            f"radius of its monodromy matrix is {rho:.6g} >= 1 (largest growth rate "
            f"{rate:+.4g} per rev), so no quadratic Liapunov function x^T P x with W' < 0 "
            "near x = 0 exists, and the steady motion is unstable: no certificate with a small "
            "bound A is possible"
        ) from exc


def quadratic_function(blade, xi=None, Q=None, dxi=None, *, scales=None,
                       n_steps: int = DEFAULT_N_STEPS, label: str = "quadratic") -> QuadraticFunction:
    """The quadratic Liapunov function of the blade about the steady motion ``xi``.

    Parameters
    ----------
    blade : Blade
        The blade at its advance ratio.
    xi : None, array_like (6,) or callable
        Steady motion: None for the hover equilibrium (:meth:`Blade.equilibrium`), a constant
        state, or ``xi(psi) -> (k, 6)`` (e.g. :attr:`rotorlyap.periodic_motion.PeriodicMotion.xi`).
    Q : array_like, optional
        Symmetric positive-definite weight ``(6, 6)``, or its 6 diagonal entries, in state
        units (1/rad^2 for angles, 1/(rad/rad)^2 for rates): ``W' = -x^T Q x`` along the
        linearised motions. Default ``diag(1 / a_i**2)``: the identity in scaled coordinates,
        ``W' = -||x||**2``.
    dxi : callable, optional
        ``xi'(psi)``, required with a callable ``xi``.
    scales : array_like, optional
        The ``a_i`` of the scaled coordinates (and of the default ``Q``); default
        :data:`rotorlyap.stability.DEFAULT_SCALES`. Use the scales of the norm the engine
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
    ValueError
        If the linearised blade is not asymptotically stable (the message gives the spectral
        radius of the monodromy matrix and the growth rate): then no quadratic function
        exists. Also for a bad ``Q``, ``scales`` or ``xi``.
    """
    a = _check_scales(scales)
    Q = _check_Q(Q, a)
    const, xi_, dxi_ = _steady(blade, xi, dxi)
    J = linearisation(blade, const if const is not None else xi_, dxi_)
    where = ("the hover equilibrium" if const is not None and blade.mu == 0.0
             else "the constant state (hover equilibrium reused in forward flight)" if const is not None
             else "the periodic steady motion")
    Qs = Q * a[:, None] * a[None, :]
    sol = _solve(_scaled(J, a), Qs, int(n_steps), where)
    return QuadraticFunction(blade=blade, xi=xi_ if const is None else const,
                             dxi=dxi_ if const is None else None, Q=Q, scales=a, solution=sol,
                             label=label, _const=const)


def certified_radius_estimate(fun: QuadraticFunction, A: float, *, psi=None, n_directions: int = 256,
                              n_bisect: int = 10, seed: int = 0) -> tuple[float, float]:
    """A quick estimate of what the engine will certify with a quadratic function.

    Along each of the structured and ``n_directions`` quasi-random directions ``d`` of
    :func:`rotorlyap.sampling.unit_sphere_points` (scaled coordinates) and at each azimuth of
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
    from .sampling import unit_sphere_points

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


def optimised_quadratic_function(blade, xi=None, dxi=None, *, A: float = 1.0, scales=None,
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
    blade, xi, dxi, scales, n_steps, label
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
    ValueError
        As :func:`quadratic_function` (unstable linearisation).
    """
    a = _check_scales(scales)
    const, xi_, dxi_ = _steady(blade, xi, dxi)
    J = linearisation(blade, const if const is not None else xi_, dxi_)
    Js = _scaled(J, a)
    if callable(Js):
        Js = _Cached(Js)
    psi_search = TWO_PI * np.arange(8) / 8 if psi_search is None else psi_search

    def make(w, steps):
        sol = _solve(Js, np.diag(w), steps, "the steady motion")
        return QuadraticFunction(blade=blade, xi=xi_ if const is None else const,
                                 dxi=dxi_ if const is None else None, Q=np.diag(w / a**2),
                                 scales=a, solution=sol, label=label, _const=const)

    def objective(logw):
        w = np.exp(logw - logw.mean())
        try:
            fun = make(w, n_steps_search)
        except ValueError:
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
    return quadratic_function(blade, xi_ if const is None else const, np.diag(w / a**2), dxi_,
                              scales=a, n_steps=n_steps, label=label)
