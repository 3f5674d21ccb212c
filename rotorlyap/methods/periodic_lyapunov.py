"""The periodic Lyapunov equation: a quadratic Liapunov function for ``x' = A(psi) x``.

Here ``A(psi)`` is the system matrix (the parameter ``A`` of :func:`periodic_lyapunov`; the
Jacobian ``J(psi)`` of chapter 7), not the bound ``A`` of the theorem.

For an asymptotically stable linear periodic system (every Floquet multiplier inside the unit
circle) and a symmetric positive-definite ``Q``, the equation

    ``P'(psi) + A(psi)^T P(psi) + P(psi) A(psi) = -Q``

has exactly one T-periodic solution; it is symmetric positive definite,

    ``P(psi) = int_psi^inf Phi(s, psi)^T Q Phi(s, psi) ds``,

and ``W(psi, x) = x^T P(psi) x`` decreases along the solutions: ``W' = -x^T Q x``. This module
knows nothing about rotor blades (:mod:`rotorlyap.methods.floquet` explains the conventions for
``A``).

Method
------
The period is split into ``K`` equal pieces ``[psi_j, psi_{j+1}]``. On every piece the
transition matrix ``S_j = Phi(psi_{j+1}, psi_j)`` and the Gramian
``G_j = int_{psi_j}^{psi_{j+1}} Phi(s, psi_j)^T Q Phi(s, psi_j) ds`` are computed (below), then

1. ``M = S_{K-1} ... S_0`` and ``G = sum_j Phi(psi_j)^T G_j Phi(psi_j)``;
2. ``P(0)`` from the discrete Lyapunov equation ``P0 = M^T P0 M + G``
   (:func:`scipy.linalg.solve_discrete_lyapunov`);
3. ``P(psi_j) = S_j^T P(psi_{j+1}) S_j + G_j`` backwards from ``P(T) = P0``: no inverse of a
   transition matrix is needed and errors are damped over the period. The mismatch between the
   ``P(0)`` so obtained and ``P0`` is reported as ``periodicity_error``;
4. ``P(psi)`` between the grid points is interpolated (``interpolation=``):

   ``"fourier"``
       trigonometric interpolant of the grid values, differentiated term by term for ``P'``:
       spectrally accurate when ``A`` is smooth, but a kink in ``A`` (a jump in ``A'``)
       spreads an error of ``P'`` over the whole period.
   ``"hermite"``
       piecewise cubic Hermite interpolant of the grid values and of the grid derivatives
       ``P'(psi_j) = -(A^T P + P A + Q)`` taken from the equation itself: fourth order in the
       grid spacing where ``A`` is smooth, and an error confined to the grid interval that
       contains a kink. The right choice with a fine grid for a piecewise-smooth ``A``.

``method="dop853"`` (default) integrates ``S_j`` and ``G_j`` for all pieces at once (one
vectorised call of ``A`` with ``K`` azimuths per stage), with error control; the grid is
``n_grid`` points and the default interpolation is ``"fourier"``. The fixed-step methods
(``"magnus6"``, ``"magnus4"``, ``"rk4"``, see :mod:`rotorlyap.methods.floquet`) take each step as a
piece, so the grid is the ``n_steps`` step points (default interpolation ``"hermite"``): they
integrate the augmented linear system ``Z' = [[-A^T, Q], [0, A]] Z``, whose transition matrix
over a step is ``[[S^-T, S^-T G], [0, S]]`` (the time-varying form of Van Loan's method), so
``G = S^T Z_12`` comes from the same integrator. ``A`` is sampled once on fixed nodes, which
is much cheaper than adaptive integration when ``A`` is not smooth.

The residual ``max |P' + A^T P + P A + Q|`` of the interpolant is evaluated on the grid and at
the midpoints (with ``"hermite"`` it vanishes on the grid by construction, so the midpoints are
the test). ``W' = -x^T (Q - R) x`` along the linear system, with ``R`` the residual matrix, so
a residual below the smallest eigenvalue of ``Q`` keeps ``W' < 0``.

For a constant array ``A`` the solution is constant and exact:
:func:`scipy.linalg.solve_continuous_lyapunov`.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np
from scipy.linalg import solve_continuous_lyapunov, solve_discrete_lyapunov

from .floquet import (
    METHODS,
    FloquetResult,
    SystemMatrix,
    _chain_product,
    _check_method,
    _dop853_pieces,
    _fixed_steps,
    _Monodromy,
    _nonnegative_float,
    _positive_float,
    _positive_int,
    _real_square,
    _result,
    _System,
    floquet_multipliers,
)
from ..errors import NotAsymptoticallyStableError
from ..jit import jit, use_compiled
from ..reporting import format_small

__all__ = ["INTERPOLATIONS", "PeriodicLyapunovSolution", "bilinear_form", "periodic_lyapunov"]

#: Interpolants of ``P(psi)`` between the grid points.
INTERPOLATIONS = ("fourier", "hermite")

_FIRST_GRID = 32
_MAX_GRID = 1024
_FIRST_STEPS = 64
_MAX_STEPS = 2**16


# --------------------------------------------------------------------------------------
# Interpolants
# --------------------------------------------------------------------------------------


def _series(coefficients: np.ndarray, period: float, psi, derivative: bool) -> np.ndarray:
    """The real trigonometric series ``Re sum_k c_k exp(i k 2 pi psi / T)`` or its derivative."""
    psi = np.asarray(psi, dtype=float)
    omega = 2.0 * np.pi / period
    k = np.arange(coefficients.shape[0])
    phase = np.exp(1j * omega * np.multiply.outer(psi, k))
    c = coefficients
    if derivative:
        c = c * (1j * omega * k)[:, None, None]
    return np.tensordot(phase, c, axes=1).real


def _fourier(P_grid: np.ndarray) -> np.ndarray:
    N = P_grid.shape[0]
    c = np.fft.rfft(P_grid, axis=0) / N
    last = c.shape[0] if N % 2 else c.shape[0] - 1  # the Nyquist term of even N is not doubled
    c[1:last] *= 2.0
    return c


def _hermite(P_grid: np.ndarray, D_grid: np.ndarray, period: float, psi,
             derivative: bool) -> np.ndarray:
    """Periodic piecewise cubic Hermite interpolant of values ``P_grid`` and slopes ``D_grid``."""
    psi = np.asarray(psi, dtype=float)
    N = P_grid.shape[0]
    h = period / N
    u = np.mod(psi, period) / h
    j = np.minimum(np.floor(u).astype(int), N - 1)
    t = (u - j)[..., None, None]
    j1 = (j + 1) % N
    P0, P1, D0, D1 = P_grid[j], P_grid[j1], h * D_grid[j], h * D_grid[j1]
    if not derivative:
        t2, t3 = t * t, t * t * t
        return ((2 * t3 - 3 * t2 + 1) * P0 + (t3 - 2 * t2 + t) * D0
                + (-2 * t3 + 3 * t2) * P1 + (t3 - t2) * D1)
    t2 = t * t
    return ((6 * t2 - 6 * t) * P0 + (3 * t2 - 4 * t + 1) * D0
            + (-6 * t2 + 6 * t) * P1 + (3 * t2 - 2 * t) * D1) / h


def _symmetric(X: np.ndarray) -> np.ndarray:
    return 0.5 * (X + np.swapaxes(X, -1, -2))


@jit
def _hermite_weights(psi, period, N):
    """The grid interval ``(j, j + 1 mod N)`` of the azimuth ``psi`` on ``N`` nodes over
    ``period`` and the weights of ``P_j, D_j, P_j+1, D_j+1`` in the cubic Hermite interpolant
    (``a0, b0, a1, b1``) and in its derivative (``da0, db0, da1, db1``)."""
    h = period / N
    u = (psi % period) / h
    j = min(int(math.floor(u)), N - 1)
    t = u - j
    t2 = t * t
    t3 = t2 * t
    return (j, (j + 1) % N, 2 * t3 - 3 * t2 + 1, (t3 - 2 * t2 + t) * h, -2 * t3 + 3 * t2, (t3 - t2) * h,
            (6 * t2 - 6 * t) / h, 3 * t2 - 4 * t + 1, (-6 * t2 + 6 * t) / h, 3 * t2 - 2 * t)


@jit
def _hermite_forms(psi, x, xdot, P_grid, D_grid, period, with_rate, w, dw):
    """``w = x^T P x`` and (``with_rate``) ``dw = x^T P' x + 2 x^T P xdot`` with ``P`` the
    periodic cubic Hermite interpolant of :func:`_hermite` of the *symmetric* grids ``P_grid``
    and ``D_grid``, one state at a time (no ``(m, n, n)`` array of matrices; the upper triangle
    only)."""
    N = P_grid.shape[0]
    n = x.shape[1]
    for i in range(x.shape[0]):
        j, j1, a0, b0, a1, b1, da0, db0, da1, db1 = _hermite_weights(psi[i], period, N)
        acc = 0.0
        acc_d = 0.0
        for r in range(n):
            xr = x[i, r]
            for c in range(r, n):
                p = (a0 * P_grid[j, r, c] + b0 * D_grid[j, r, c]
                     + a1 * P_grid[j1, r, c] + b1 * D_grid[j1, r, c])
                xc = x[i, c]
                if r == c:
                    acc += p * xr * xc
                else:
                    acc += 2.0 * p * xr * xc
                if with_rate:
                    d = (da0 * P_grid[j, r, c] + db0 * D_grid[j, r, c]
                         + da1 * P_grid[j1, r, c] + db1 * D_grid[j1, r, c])
                    if r == c:
                        acc_d += d * xr * xc + 2.0 * p * xr * xdot[i, c]
                    else:
                        acc_d += 2.0 * (d * xr * xc + p * (xr * xdot[i, c] + xc * xdot[i, r]))
        w[i] = acc
        if with_rate:
            dw[i] = acc_d


@jit
def _bilinear_rows(x, P, y, out):
    """``out[m] = sum_i sum_j x[m, i] P[i, j] y[m, j]``, in the order and with the products
    of ``numpy.einsum("mi,ij,mj->m", x, P, y)`` (so the same numbers, about three times faster
    for large batches)."""
    n = x.shape[1]
    for a in range(x.shape[0]):
        acc = 0.0
        for i in range(n):
            for j in range(n):
                acc += x[a, i] * P[i, j] * y[a, j]
        out[a] = acc


def bilinear_form(x: np.ndarray, P: np.ndarray, y: np.ndarray) -> np.ndarray:
    """``x_m^T P y_m`` for each row ``m`` of ``x`` and ``y`` (shape ``(m, n)``), ``P`` of shape
    ``(n, n)``: :func:`numpy.einsum` ``("mi,ij,mj->m")`` to the last bit, by a compiled loop
    where the compiled kernels run (:func:`rotorlyap.jit.use_compiled`)."""
    if not use_compiled():
        return np.einsum("mi,ij,mj->m", x, P, y)
    c = np.ascontiguousarray
    out = np.empty(x.shape[0])
    _bilinear_rows(c(x, dtype=float), c(P, dtype=float), c(y, dtype=float), out)
    return out


# --------------------------------------------------------------------------------------
# Result
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class PeriodicLyapunovSolution:
    """The periodic solution ``P(psi)`` computed by :func:`periodic_lyapunov`.

    Call :meth:`P` and :meth:`dP` for values at any azimuths, :meth:`W` and :meth:`dW` for the
    quadratic Liapunov function ``W = x^T P x`` and its derivative along motions.

    Attributes
    ----------
    period : float
        The period ``T``.
    Q : numpy.ndarray
        The weighting matrix, shape ``(n, n)``.
    psi : numpy.ndarray
        Grid ``psi_j = j T / K``, shape ``(K,)`` (``K = 1`` for a constant ``A``).
    P_grid : numpy.ndarray
        ``P(psi_j)``, shape ``(K, n, n)``, symmetric.
    dP_grid : numpy.ndarray
        ``P'(psi_j)`` of the interpolant, shape ``(K, n, n)`` (for ``"hermite"`` the value
        ``-(A^T P + P A + Q)`` from the equation).
    interpolation : str
        ``"fourier"``, ``"hermite"``, or ``"constant"`` for a constant ``A``.
    coefficients : numpy.ndarray or None
        ``"fourier"`` only: complex coefficients ``c_k``, ``k = 0 .. K // 2``, shape
        ``(K // 2 + 1, n, n)``, with ``P(psi) = Re sum_k c_k exp(i k 2 pi psi / T)``.
    floquet : FloquetResult
        Multipliers and monodromy matrix of ``x' = A x`` from the same integration.
    residual : float
        ``max |P' + A^T P + P A + Q|`` (entrywise) on the grid and at the midpoints.
    relative_residual : float
        ``residual`` divided by the largest entry of ``Q`` or of ``A^T P + P A`` at those
        points: the size of the terms that must cancel.
    residual_eigenvalue : float
        Largest eigenvalue of the symmetric residual matrix ``R`` at those points, divided by
        the smallest eigenvalue of ``Q``: ``W' = -x^T (Q - R) x`` along the linear system, so a
        value below 1 means ``W' < 0`` at the points checked.
    periodicity_error : float
        ``max |P(0) - P(T)| / max |P(T)|`` before ``P(0)`` is replaced by ``P(T)``: the mismatch
        after the backward sweep over one period (0 for a constant ``A``).
    min_eigenvalue, max_eigenvalue : float
        Extreme eigenvalues of ``P`` over the grid and the midpoints; ``min_eigenvalue > 0``
        confirms positive definiteness there. Their ratio bounds ``W`` by the squared norm.
    method : str
        Integrator (``"expm"`` for a constant ``A``).
    n_grid : int
        ``K``, the number of grid points (the steps of a fixed-step method).
    """

    period: float
    Q: np.ndarray
    psi: np.ndarray
    P_grid: np.ndarray
    dP_grid: np.ndarray
    interpolation: str
    coefficients: np.ndarray | None
    floquet: FloquetResult
    residual: float
    relative_residual: float
    residual_eigenvalue: float
    periodicity_error: float
    min_eigenvalue: float
    max_eigenvalue: float
    method: str
    n_grid: int

    def __post_init__(self) -> None:
        for name in ("Q", "psi", "P_grid", "dP_grid", "coefficients"):
            value = getattr(self, name)
            if value is None:
                continue
            arr = np.array(value, copy=True)
            arr.setflags(write=False)
            object.__setattr__(self, name, arr)

    @property
    def n(self) -> int:
        """State dimension."""
        return self.Q.shape[0]

    @property
    def constant(self) -> bool:
        """``A`` was a constant array (then ``P`` is constant and ``dP`` zero)."""
        return self.interpolation == "constant"

    def _eval(self, psi, derivative: bool) -> np.ndarray:
        psi = np.asarray(psi, dtype=float)
        if not np.all(np.isfinite(psi)):
            raise ValueError("psi must be finite")
        if self.interpolation == "constant":
            value = np.zeros_like(self.P_grid[0]) if derivative else self.P_grid[0]
            return np.broadcast_to(value, psi.shape + value.shape).copy()
        if self.interpolation == "fourier":
            out = _series(self.coefficients, self.period, psi, derivative)
        else:
            out = _hermite(self.P_grid, self.dP_grid, self.period, psi, derivative)
        return _symmetric(out)

    def P(self, psi) -> np.ndarray:
        """``P(psi)``: shape ``psi.shape + (n, n)`` (``(n, n)`` for a float ``psi``)."""
        return self._eval(psi, derivative=False)

    def dP(self, psi) -> np.ndarray:
        """``dP/dpsi`` of the interpolant: shape ``psi.shape + (n, n)``, units of ``P`` per
        unit of ``psi``."""
        return self._eval(psi, derivative=True)

    def W(self, psi, x) -> np.ndarray:
        """``W(psi, x) = x^T P(psi) x``, vectorised: ``x`` of shape ``(m, n)`` and ``psi``
        broadcasting to ``(m,)``; returns ``(m,)``."""
        x = self._states(x)
        psi = np.broadcast_to(np.asarray(psi, dtype=float), (x.shape[0],))
        if self.interpolation == "hermite" and use_compiled():
            return self._forms(psi, x, None)[0]
        return np.einsum("mi,mij,mj->m", x, self.P(psi), x)

    def dW(self, psi, x, xdot) -> np.ndarray:
        """Derivative of ``W`` along motions with velocity ``xdot = x'``:
        ``x^T P' x + 2 x^T P xdot``; shapes as :meth:`W` (``xdot`` like ``x``).

        For the linear system itself (``xdot = A(psi) x``) this equals ``-x^T Q x`` up to the
        residual.
        """
        x = self._states(x)
        xdot = np.asarray(xdot, dtype=float)
        if xdot.ndim == 1:
            xdot = xdot[None, :]
        if xdot.shape != x.shape:
            raise ValueError(f"xdot must have the shape of x, {x.shape}; got {xdot.shape}")
        psi = np.broadcast_to(np.asarray(psi, dtype=float), (x.shape[0],))
        if self.interpolation == "hermite" and use_compiled():
            return self._forms(psi, x, xdot)[1]
        return (np.einsum("mi,mij,mj->m", x, self.dP(psi), x)
                + 2.0 * np.einsum("mi,mij,mj->m", x, self.P(psi), xdot))

    def kernel_grids(self) -> tuple[np.ndarray, np.ndarray]:
        """The symmetric parts of ``P_grid`` and ``dP_grid``, contiguous: what the compiled
        Hermite kernel reads (computed once)."""
        grids = self.__dict__.get("_symmetric_grids")
        if grids is None:
            grids = tuple(np.ascontiguousarray(_symmetric(g)) for g in (self.P_grid, self.dP_grid))
            object.__setattr__(self, "_symmetric_grids", grids)
        return grids

    def _forms(self, psi, x, xdot):
        """``W`` and ``W'`` by the compiled kernel (hermite interpolation only)."""
        if not np.all(np.isfinite(psi)):
            raise ValueError("psi must be finite")
        grids = self.kernel_grids()
        m = x.shape[0]
        w, dw = np.empty(m), np.empty(m)
        with_rate = xdot is not None
        c = np.ascontiguousarray
        _hermite_forms(c(psi), c(x), c(xdot) if with_rate else c(x), *grids,
                       float(self.period), with_rate, w, dw)
        return w, dw

    def _states(self, x) -> np.ndarray:
        x = np.asarray(x, dtype=float)
        if x.ndim == 1:
            x = x[None, :]
        if x.ndim != 2 or x.shape[1] != self.n:
            raise ValueError(f"x must have shape (m, {self.n}), got {x.shape}")
        return x

    def __repr__(self) -> str:  # short and stable: no arrays, no addresses
        return (
            f"PeriodicLyapunovSolution(n={self.n}, period={self.period:.6g}, "
            f"method={self.method!r}, interpolation={self.interpolation!r}, "
            f"n_grid={self.n_grid}, relative residual {format_small(self.relative_residual)}, "
            f"eigenvalues of P in [{self.min_eigenvalue:.4g}, {self.max_eigenvalue:.4g}])"
        )


# --------------------------------------------------------------------------------------
# Computation
# --------------------------------------------------------------------------------------


def _check_Q(Q, n: int) -> np.ndarray:
    if Q is None:
        return np.eye(n)
    Q = _real_square("Q", Q)
    if Q.shape != (n, n):
        raise ValueError(f"Q must have the shape of A, ({n}, {n}); got {Q.shape}")
    scale = float(np.max(np.abs(Q)))
    if np.max(np.abs(Q - Q.T)) > 1e-12 * scale:
        raise ValueError("Q must be symmetric (Q == Q.T to 1e-12 relative)")
    Q = _symmetric(Q)
    lam = np.linalg.eigvalsh(Q)
    if lam[0] <= 0:
        raise ValueError(f"Q must be positive definite; its smallest eigenvalue is {lam[0]:.6g}")
    return Q


def _unstable_message(res: FloquetResult) -> str:
    return (
        f"x' = A(psi) x is not asymptotically stable: the spectral radius of the monodromy "
        f"matrix is {res.spectral_radius:.10g} (it must be < 1 - tol = {1 - res.tol:.10g}), "
        "so the periodic Lyapunov equation has no positive-definite periodic solution"
    )


def _residual_stats(A: np.ndarray, P: np.ndarray, dP: np.ndarray, Q: np.ndarray):
    ATP = np.swapaxes(A, -1, -2) @ P
    lyap = ATP + np.swapaxes(ATP, -1, -2)
    R = dP + lyap + Q
    residual = float(np.max(np.abs(R)))
    scale = max(float(np.max(np.abs(Q))), float(np.max(np.abs(lyap))))
    r_eig = float(np.max(np.linalg.eigvalsh(_symmetric(R))[..., -1]))
    q_min = float(np.linalg.eigvalsh(Q)[0])
    lam = np.linalg.eigvalsh(P)
    return residual, residual / scale, r_eig / q_min, float(lam[..., 0].min()), float(
        lam[..., -1].max())


def _constant_solution(A: np.ndarray, period: float, Q: np.ndarray, tol: float):
    res = floquet_multipliers(A, period, tol=tol)
    if not res.stable:
        lam = np.linalg.eigvals(A)
        raise NotAsymptoticallyStableError(
            _unstable_message(res)
            + f" (largest real part of an eigenvalue of A: {np.max(lam.real):.6g})",
            spectral_radius=float(res.spectral_radius), growth_rate=float(np.max(lam.real)),
        )
    P = _symmetric(solve_continuous_lyapunov(A.T, -Q))
    stats = _residual_stats(A, P, np.zeros_like(P), Q)
    return PeriodicLyapunovSolution(
        period=period, Q=Q, psi=np.zeros(1), P_grid=P[None], dP_grid=np.zeros((1,) + P.shape),
        interpolation="constant", coefficients=None, floquet=res, residual=stats[0],
        relative_residual=stats[1], residual_eigenvalue=stats[2], periodicity_error=0.0,
        min_eigenvalue=stats[3], max_eigenvalue=stats[4], method="expm", n_grid=1,
    )


class _Augmented:
    """``B(psi) = [[-A^T, Q], [0, A]]``, shape ``(k, 2n, 2n)``, for the fixed-step Gramians."""

    def __init__(self, sys: _System, Q: np.ndarray):
        self.sys, self.Q, self.n, self.constant = sys, Q, 2 * sys.n, None

    def __call__(self, psi) -> np.ndarray:
        A = self.sys(psi)
        n = self.sys.n
        B = np.zeros((A.shape[0], 2 * n, 2 * n))
        B[:, :n, :n] = -np.swapaxes(A, 1, 2)
        B[:, :n, n:] = self.Q
        B[:, n:, n:] = A
        return B


def _pieces(sys: _System, period: float, Q: np.ndarray, method: str, K: int,
            rtol: float, atol: float):
    """``(S, G, trace_integral)`` over ``K`` equal pieces of the period."""
    if method == "dop853":
        return _dop853_pieces(sys, period, K, rtol, atol, Q)
    n = sys.n
    Z, _ = _fixed_steps(_Augmented(sys, Q), period, method, K)
    S = Z[:, n:, n:]
    G = _symmetric(np.swapaxes(S, 1, 2) @ Z[:, :n, n:])
    # trace B = 0, so the integral of trace A is taken from det S_j = exp(int trace A) > 0
    # (then FloquetResult.liouville_error is no independent check)
    trace_integral = float(np.sum(np.log(np.abs(np.linalg.det(S)))))
    return S, G, trace_integral


def _gramian_sum_numpy(S: np.ndarray, G: np.ndarray) -> np.ndarray:
    """``sum_j Phi_j^T G_j Phi_j`` with ``Phi_0 = I``, ``Phi_{j+1} = S_j Phi_j``: the pieces'
    forcing carried to the start of the period (the numpy twin of :func:`_gramian_sum`)."""
    n = S.shape[1]
    Phi = np.eye(n)
    total = np.zeros((n, n))
    for j in range(S.shape[0]):
        total += Phi.T @ G[j] @ Phi
        Phi = S[j] @ Phi
    return total


@jit
def _product(X, Y, out, transpose_x):
    """``out = X @ Y``, or ``X^T @ Y`` with ``transpose_x``, for small square matrices (loops:
    no call into BLAS per piece)."""
    n = out.shape[0]
    for a in range(n):
        for b in range(n):
            acc = 0.0
            for k in range(n):
                acc += (X[k, a] if transpose_x else X[a, k]) * Y[k, b]
            out[a, b] = acc


@jit
def _gramian_sum(S, G):
    """:func:`_gramian_sum_numpy` compiled (one piece after the other; measured 14 ms -> under
    1 ms for 1024 pieces of a 6-state system)."""
    K, n = S.shape[0], S.shape[1]
    Phi = np.eye(n)
    nxt = np.empty((n, n))
    tmp = np.empty((n, n))
    term = np.empty((n, n))
    total = np.zeros((n, n))
    for j in range(K):
        _product(G[j], Phi, tmp, False)
        _product(Phi, tmp, term, True)
        total += term
        _product(S[j], Phi, nxt, False)
        Phi[:, :] = nxt
    return total


def _backward_sweep_numpy(S: np.ndarray, G: np.ndarray, P0: np.ndarray, out: np.ndarray) -> None:
    """``out[j] = sym(S_j^T P_{j+1} S_j + G_j)`` from ``P_K = P0`` down to ``j = 0``: ``P`` at the
    start of each piece (the numpy twin of :func:`_backward_sweep`)."""
    Pnext = P0
    for j in range(S.shape[0] - 1, -1, -1):
        X = S[j].T @ Pnext @ S[j] + G[j]
        Pnext = out[j] = 0.5 * (X + X.T)  # _symmetric of one matrix, without its call


@jit
def _backward_sweep(S, G, P0, out):
    """:func:`_backward_sweep_numpy` compiled."""
    K, n = S.shape[0], S.shape[1]
    Pnext = P0.copy()
    tmp = np.empty((n, n))
    X = np.empty((n, n))
    for j in range(K - 1, -1, -1):
        _product(Pnext, S[j], tmp, False)
        for a in range(n):
            for b in range(n):
                acc = G[j, a, b]
                for k in range(n):
                    acc += S[j, k, a] * tmp[k, b]
                X[a, b] = acc
        for a in range(n):
            for b in range(n):
                out[j, a, b] = 0.5 * (X[a, b] + X[b, a])
        Pnext[:, :] = out[j]


def _grid_values(sys: _System, period: float, Q: np.ndarray, S, G, trace_integral: float,
                 method: str, tol: float, count0: int):
    """Stability check, ``P0`` and the backward sweep: ``(floquet, P_grid, periodicity)``."""
    M = _chain_product(S)
    res = _result(
        _Monodromy(M, trace_integral, method, None if method == "dop853" else S.shape[0],
                   float("nan"), sys.count - count0),
        period, tol,
    )
    if not res.stable:
        raise NotAsymptoticallyStableError(_unstable_message(res), spectral_radius=float(res.spectral_radius),
                                           growth_rate=float(np.max(res.exponents.real)))
    n, K = sys.n, S.shape[0]
    compiled = use_compiled()
    S = np.ascontiguousarray(S, dtype=float)
    G = np.ascontiguousarray(G, dtype=float)
    Gtot = _gramian_sum(S, G) if compiled else _gramian_sum_numpy(S, G)
    P0 = _symmetric(solve_discrete_lyapunov(M.T, Gtot))
    P_grid = np.empty((K, n, n))
    (_backward_sweep if compiled else _backward_sweep_numpy)(S, G, np.ascontiguousarray(P0), P_grid)
    periodicity_error = float(np.max(np.abs(P_grid[0] - P0)) / np.max(np.abs(P0)))
    P_grid[0] = P0
    return res, P_grid, periodicity_error


def _finish(sys: _System, period: float, Q: np.ndarray, res: FloquetResult, P_grid,
            periodicity_error: float, interpolation: str, method: str):
    K = P_grid.shape[0]
    psi = period * np.arange(K) / K
    mid = psi + 0.5 * period / K
    A_grid, A_mid = sys(psi), sys(mid)
    coeffs = None
    if interpolation == "fourier":
        coeffs = _fourier(P_grid)
        dP_grid = _symmetric(_series(coeffs, period, psi, True))
        P_mid = _symmetric(_series(coeffs, period, mid, False))
        dP_mid = _symmetric(_series(coeffs, period, mid, True))
    else:
        ATP = np.swapaxes(A_grid, 1, 2) @ P_grid
        dP_grid = -(ATP + np.swapaxes(ATP, 1, 2) + Q)
        P_mid = _symmetric(_hermite(P_grid, dP_grid, period, mid, False))
        dP_mid = _symmetric(_hermite(P_grid, dP_grid, period, mid, True))
    stats = _residual_stats(
        np.concatenate([A_grid, A_mid]), np.concatenate([P_grid, P_mid]),
        np.concatenate([dP_grid, dP_mid]), Q,
    )
    return PeriodicLyapunovSolution(
        period=period, Q=Q, psi=psi, P_grid=P_grid, dP_grid=dP_grid,
        interpolation=interpolation, coefficients=coeffs, floquet=res, residual=stats[0],
        relative_residual=stats[1], residual_eigenvalue=stats[2],
        periodicity_error=periodicity_error, min_eigenvalue=stats[3], max_eigenvalue=stats[4],
        method=method, n_grid=K,
    )


def periodic_lyapunov(
    A: SystemMatrix,
    period: float,
    Q=None,
    *,
    method: str = "dop853",
    n_grid: int | None = None,
    n_steps: int | None = None,
    interpolation: str | None = None,
    residual_tol: float = 1e-8,
    vectorized: bool = False,
    rtol: float = 1e-11,
    atol: float = 1e-13,
    tol: float = 1e-9,
    max_evaluations: int | None = 1_000_000,
) -> PeriodicLyapunovSolution:
    """The T-periodic solution of ``P' + A(psi)^T P + P A(psi) = -Q``.

    Parameters
    ----------
    A : callable or array_like
        ``A(psi)`` returning a real ``(n, n)`` array (``(k, n, n)`` for ``psi`` of shape
        ``(k,)`` with ``vectorized=True``), period ``period``; or a constant ``(n, n)`` array,
        solved exactly by :func:`scipy.linalg.solve_continuous_lyapunov`.
    period : float
        The period ``T`` (> 0), units of ``psi``.
    Q : array_like, optional
        Symmetric positive-definite ``(n, n)`` weight, constant; default the identity. Then
        ``W' = -x^T Q x`` along the solutions of ``x' = A x``.
    method : {"dop853", "magnus6", "magnus4", "rk4"}
        Integrator of the pieces (module docstring). Prefer ``"magnus6"`` with a fine
        ``n_steps`` when ``A`` is not smooth (kinks, noise): adaptive integration then needs
        tiny steps.
    n_grid : int, optional
        ``"dop853"`` only: number ``K`` of grid points (pieces of the period). Default:
        doubled from 32 until ``relative_residual <= residual_tol``, up to 1024, stopping
        early (with a RuntimeWarning) when a doubling no longer halves the residual, the
        sign of a non-smooth ``A``.
    n_steps : int, optional
        Fixed-step methods only: steps per period, which are also the grid. Default: doubled
        from 64 until ``P(0)`` changes by less than ``rtol`` (relative, max norm), up to
        2**16 (RuntimeWarning if not reached).
    interpolation : {"fourier", "hermite"}, optional
        Interpolant between grid points (module docstring). Default ``"fourier"`` for
        ``"dop853"``, ``"hermite"`` for the fixed-step methods.
    residual_tol : float
        Target of the automatic grid refinement of ``"dop853"``.
    vectorized : bool
        ``A`` accepts an array of azimuths and returns ``(k, n, n)``.
    rtol, atol : float
        Tolerances of DOP853, or (``rtol``) of the step doubling of a fixed-step method.
    tol : float
        Stability margin: the spectral radius of the monodromy matrix must be ``< 1 - tol``.
    max_evaluations : int or None
        Limit on the number of azimuths at which ``A`` is evaluated (per call of this function;
        None: no limit).

    Returns
    -------
    PeriodicLyapunovSolution
        With ``P(psi)``, ``dP(psi)``, ``W``, ``dW`` and the accuracy checks ``residual``,
        ``relative_residual``, ``residual_eigenvalue``, ``periodicity_error``,
        ``min_eigenvalue``.

    Raises
    ------
    rotorlyap.errors.NotAsymptoticallyStableError
        ``x' = A x`` not asymptotically stable (a ``ValueError``; it carries the spectral
        radius of the monodromy matrix and the largest growth rate).
    ValueError
        Non-positive ``period``; ``Q`` not symmetric positive definite or of
        the wrong shape; ``A`` of the wrong shape or non-finite; bad ``method``,
        ``interpolation``, ``n_grid`` or ``n_steps``; more than ``max_evaluations``.
    TypeError
        ``A`` neither callable nor an array, or complex.
    """
    period = _positive_float("period", period)
    method = _check_method(method)
    residual_tol = _positive_float("residual_tol", residual_tol)
    rtol = _positive_float("rtol", rtol)
    atol = _positive_float("atol", atol)
    tol = _nonnegative_float("tol", tol)
    if max_evaluations is not None:
        max_evaluations = _positive_int("max_evaluations", max_evaluations)
    fixed = method != "dop853"
    if interpolation is None:
        interpolation = "hermite" if fixed else "fourier"
    if interpolation not in INTERPOLATIONS:
        raise ValueError(
            f"interpolation must be one of {', '.join(map(repr, INTERPOLATIONS))}; "
            f"got {interpolation!r}"
        )
    if fixed and n_grid is not None:
        raise ValueError(
            f"n_grid applies to method 'dop853' only; with {method!r} the grid is the "
            "n_steps step points"
        )
    if not fixed and n_steps is not None:
        raise ValueError(
            "n_steps applies to the fixed-step methods "
            f"({', '.join(repr(m) for m in METHODS if m != 'dop853')}) only"
        )
    if n_grid is not None:
        n_grid = _positive_int("n_grid", n_grid, 2)
    if n_steps is not None:
        n_steps = _positive_int("n_steps", n_steps, 2)

    sys = _System(A, vectorized, max_evaluations)
    Q = _check_Q(Q, sys.n)
    if sys.constant is not None:
        return _constant_solution(sys.constant, period, Q, tol)

    def solve(K: int):
        count0 = sys.count
        S, G, tr = _pieces(sys, period, Q, method, K, rtol, atol)
        return _grid_values(sys, period, Q, S, G, tr, method, tol, count0)

    if fixed:
        if n_steps is not None:
            grid = solve(n_steps)
        else:
            K = _FIRST_STEPS
            grid = solve(K)
            while True:
                new = solve(2 * K)
                change = float(np.max(np.abs(new[1][0] - grid[1][0])) / np.max(np.abs(new[1][0])))
                K, grid = 2 * K, new
                if change <= rtol:
                    break
                if K >= _MAX_STEPS:
                    warnings.warn(
                        f"periodic_lyapunov ({method}): P(0) still changes by {change:.3g} "
                        f"(relative) with {K} steps, more than rtol={rtol:g}; returning the last "
                        "result. Pass n_steps explicitly or loosen rtol.",
                        RuntimeWarning, stacklevel=2,
                    )
                    break
        return _finish(sys, period, Q, *grid, interpolation, method)

    if n_grid is not None:
        return _finish(sys, period, Q, *solve(n_grid), interpolation, method)
    N = _FIRST_GRID
    sol = _finish(sys, period, Q, *solve(N), interpolation, method)
    while sol.relative_residual > residual_tol:
        if 2 * N > _MAX_GRID:
            reason = f"with the largest grid, K={N}"
        else:
            new = _finish(sys, period, Q, *solve(2 * N), interpolation, method)
            stagnant = new.relative_residual > 0.5 * sol.relative_residual
            N, sol = 2 * N, new
            if not stagnant:
                continue
            reason = (f"and doubling the grid to K={N} no longer halves it: A(psi) is probably "
                      "not smooth; try method='magnus6' (interpolation 'hermite') with a fine "
                      "n_steps")
        warnings.warn(
            f"periodic_lyapunov: relative residual {sol.relative_residual:.3g} > "
            f"residual_tol={residual_tol:g} {reason}; returning it",
            RuntimeWarning, stacklevel=2,
        )
        break
    return sol
