"""The periodic Lyapunov equation: a quadratic Liapunov function for ``x' = A(psi) x``.

For an asymptotically stable linear periodic system (every Floquet multiplier inside the unit
circle) and a symmetric positive-definite ``Q``, the equation

    ``P'(psi) + A(psi)^T P(psi) + P(psi) A(psi) = -Q``

has exactly one T-periodic solution; it is symmetric positive definite,

    ``P(psi) = int_psi^inf Phi(s, psi)^T Q Phi(s, psi) ds``,

and ``W(psi, x) = x^T P(psi) x`` decreases along the solutions: ``W' = -x^T Q x``. This module
knows nothing about rotor blades (:mod:`rotorlyap.floquet` explains the conventions for
``A``).

Method
------
The period is split into ``N`` equal pieces ``[psi_j, psi_{j+1}]``. On every piece the
transition matrix ``S_j = Phi(psi_{j+1}, psi_j)`` and the Gramian
``G_j = int_{psi_j}^{psi_{j+1}} Phi(s, psi_j)^T Q Phi(s, psi_j) ds`` are integrated from the
identity, all pieces at once (DOP853, ``rtol = 1e-11``; ``A`` called with ``N`` azimuths per
stage when vectorised). Then

1. ``M = S_{N-1} ... S_0`` and ``G = sum_j Phi(psi_j)^T G_j Phi(psi_j)``;
2. ``P(0)`` from the discrete Lyapunov equation ``P0 = M^T P0 M + G``
   (:func:`scipy.linalg.solve_discrete_lyapunov`);
3. ``P(psi_j) = S_j^T P(psi_{j+1}) S_j + G_j`` backwards from ``P(T) = P0``: no inverse of a
   transition matrix is needed, and errors are damped over the period. The mismatch between the
   ``P(0)`` so obtained and ``P0`` is reported as ``periodicity_error``;
4. ``P(psi)`` between the grid points is the trigonometric (Fourier) interpolant of the ``N``
   grid values, differentiated term by term for ``P'(psi)``: spectrally accurate for a smooth
   ``A``.

The residual ``max |P' + A^T P + P A + Q|`` is evaluated on the grid and at the midpoints (the
latter checks the interpolant too). With ``n_grid=None`` the grid is doubled from 32 until the
relative residual is below ``residual_tol`` (at most 1024 points, with a warning otherwise).

For a constant array ``A`` the solution is constant and exact:
:func:`scipy.linalg.solve_continuous_lyapunov`.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np
from scipy.linalg import solve_continuous_lyapunov, solve_discrete_lyapunov

from .floquet import (
    FloquetResult,
    SystemMatrix,
    floquet_multipliers,
    _chain_product,
    _dop853_pieces,
    _Monodromy,
    _nonnegative_float,
    _positive_float,
    _positive_int,
    _real_square,
    _result,
    _System,
)

__all__ = ["PeriodicLyapunovSolution", "periodic_lyapunov"]

_FIRST_GRID = 32
_MAX_GRID = 1024


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
        Grid ``psi_j = j T / N``, shape ``(N,)`` (``N = 1`` for a constant ``A``).
    P_grid : numpy.ndarray
        ``P(psi_j)``, shape ``(N, n, n)``, symmetric.
    coefficients : numpy.ndarray
        Complex Fourier coefficients ``c_k``, ``k = 0 .. N // 2``, shape ``(N // 2 + 1, n, n)``:
        ``P(psi) = Re sum_k c_k exp(i k 2 pi psi / T)``.
    constant : bool
        ``A`` was a constant array (then ``P`` is constant and ``dP`` zero).
    floquet : FloquetResult
        Multipliers and monodromy matrix of ``x' = A x`` from the same integration.
    residual : float
        ``max |P' + A^T P + P A + Q|`` (entrywise) on the grid and at the midpoints.
    relative_residual : float
        ``residual`` divided by the largest entry of ``Q`` or of ``A^T P + P A`` at those
        points: the size of the terms that must cancel.
    periodicity_error : float
        ``max |P(0) - P(T)| / max |P(T)|`` before ``P(0)`` is replaced by ``P(T)``: the mismatch
        after the backward sweep over one period (0 for a constant ``A``).
    min_eigenvalue, max_eigenvalue : float
        Extreme eigenvalues of ``P`` over the grid and the midpoints; ``min_eigenvalue > 0``
        confirms positive definiteness there. Their ratio bounds ``W`` by the squared norm.
    n_grid : int
        ``N``.
    """

    period: float
    Q: np.ndarray
    psi: np.ndarray
    P_grid: np.ndarray
    coefficients: np.ndarray
    constant: bool
    floquet: FloquetResult
    residual: float
    relative_residual: float
    periodicity_error: float
    min_eigenvalue: float
    max_eigenvalue: float
    n_grid: int

    def __post_init__(self) -> None:
        for name in ("Q", "psi", "P_grid", "coefficients"):
            arr = np.array(getattr(self, name), copy=True)
            arr.setflags(write=False)
            object.__setattr__(self, name, arr)

    @property
    def n(self) -> int:
        """State dimension."""
        return self.Q.shape[0]

    def P(self, psi) -> np.ndarray:
        """``P(psi)``: shape ``psi.shape + (n, n)`` (``(n, n)`` for a float ``psi``)."""
        return _series(self.coefficients, self.period, psi, derivative=False)

    def dP(self, psi) -> np.ndarray:
        """``dP/dpsi``: shape ``psi.shape + (n, n)``, 1 / (unit of ``psi``) times ``P``."""
        return _series(self.coefficients, self.period, psi, derivative=True)

    def W(self, psi, x) -> np.ndarray:
        """``W(psi, x) = x^T P(psi) x``, vectorised: ``x`` of shape ``(m, n)`` and ``psi``
        broadcasting to ``(m,)``; returns ``(m,)``."""
        x = self._states(x)
        psi = np.broadcast_to(np.asarray(psi, dtype=float), (x.shape[0],))
        return np.einsum("mi,mij,mj->m", x, self.P(psi), x)

    def dW(self, psi, x, xdot) -> np.ndarray:
        """Derivative of ``W`` along motions with velocity ``xdot = x'``:
        ``x^T P' x + 2 x^T P xdot``; shapes as :meth:`W` (``xdot`` like ``x``).

        For the linear system itself (``xdot = A(psi) x``) this equals ``-x^T Q x`` up to
        :attr:`residual`.
        """
        x = self._states(x)
        xdot = np.asarray(xdot, dtype=float)
        if xdot.shape != x.shape:
            raise ValueError(f"xdot must have the shape of x, {x.shape}; got {xdot.shape}")
        psi = np.broadcast_to(np.asarray(psi, dtype=float), (x.shape[0],))
        return (np.einsum("mi,mij,mj->m", x, self.dP(psi), x)
                + 2.0 * np.einsum("mi,mij,mj->m", x, self.P(psi), xdot))

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
            f"n_grid={self.n_grid}, constant={self.constant}, "
            f"relative_residual={self.relative_residual:.3g}, "
            f"eigenvalues of P in [{self.min_eigenvalue:.4g}, {self.max_eigenvalue:.4g}])"
        )


def _series(coefficients: np.ndarray, period: float, psi, derivative: bool) -> np.ndarray:
    """The real trigonometric series ``Re sum_k c_k exp(i k 2 pi psi / T)`` or its derivative."""
    psi = np.asarray(psi, dtype=float)
    if not np.all(np.isfinite(psi)):
        raise ValueError("psi must be finite")
    omega = 2.0 * np.pi / period
    k = np.arange(coefficients.shape[0])
    phase = np.exp(1j * omega * np.multiply.outer(psi, k))
    c = coefficients
    if derivative:
        c = c * (1j * omega * k)[:, None, None]
    out = np.tensordot(phase, c, axes=1).real
    return 0.5 * (out + np.swapaxes(out, -1, -2))


def _check_Q(Q, n: int) -> np.ndarray:
    if Q is None:
        return np.eye(n)
    Q = _real_square("Q", Q)
    if Q.shape != (n, n):
        raise ValueError(f"Q must have the shape of A, ({n}, {n}); got {Q.shape}")
    scale = float(np.max(np.abs(Q)))
    if np.max(np.abs(Q - Q.T)) > 1e-12 * scale:
        raise ValueError("Q must be symmetric (Q == Q.T to 1e-12 relative)")
    Q = 0.5 * (Q + Q.T)
    lam = np.linalg.eigvalsh(Q)
    if lam[0] <= 0:
        raise ValueError(
            f"Q must be positive definite; its smallest eigenvalue is {lam[0]:.6g}"
        )
    return Q


def _unstable_message(res: FloquetResult) -> str:
    return (
        f"x' = A(psi) x is not asymptotically stable: the spectral radius of the monodromy "
        f"matrix is {res.spectral_radius:.10g} (it must be < 1 - tol = {1 - res.tol:.10g}), "
        "so the periodic Lyapunov equation has no positive-definite periodic solution"
    )


def _extreme_eigenvalues(P: np.ndarray) -> tuple[float, float]:
    lam = np.linalg.eigvalsh(P)
    return float(lam[..., 0].min()), float(lam[..., -1].max())


def _constant_solution(sys: _System, period: float, Q: np.ndarray, tol: float):
    A = sys.constant
    res = floquet_multipliers(A, period, tol=tol)
    if not res.stable:
        lam = np.linalg.eigvals(A)
        raise ValueError(
            _unstable_message(res)
            + f" (largest real part of an eigenvalue of A: {np.max(lam.real):.6g})"
        )
    P = solve_continuous_lyapunov(A.T, -Q)
    P = 0.5 * (P + P.T)
    R = A.T @ P + P @ A + Q
    scale = max(float(np.max(np.abs(Q))), float(np.max(np.abs(A.T @ P + P @ A))))
    lo, hi = _extreme_eigenvalues(P)
    return PeriodicLyapunovSolution(
        period=period, Q=Q, psi=np.zeros(1), P_grid=P[None], coefficients=P[None].astype(complex),
        constant=True, floquet=res, residual=float(np.max(np.abs(R))),
        relative_residual=float(np.max(np.abs(R))) / scale, periodicity_error=0.0,
        min_eigenvalue=lo, max_eigenvalue=hi, n_grid=1,
    )


def _fourier(P_grid: np.ndarray) -> np.ndarray:
    N = P_grid.shape[0]
    c = np.fft.rfft(P_grid, axis=0) / N
    last = c.shape[0] if N % 2 else c.shape[0] - 1  # the Nyquist term of even N is not doubled
    c[1:last] *= 2.0
    return c


def _solve_on_grid(sys: _System, period: float, Q: np.ndarray, N: int, tol: float,
                   rtol: float, atol: float) -> PeriodicLyapunovSolution:
    count0 = sys.count
    S, G, trace_integral = _dop853_pieces(sys, period, N, rtol, atol, Q)
    M = _chain_product(S)
    res = _result(
        _Monodromy(M, trace_integral, "dop853", None, float("nan"), sys.count - count0),
        period, tol,
    )
    if not res.stable:
        raise ValueError(_unstable_message(res))

    # G = sum_j Phi(psi_j)^T G_j Phi(psi_j), Phi(psi_j) = S_{j-1} ... S_0
    n = sys.n
    Phi = np.eye(n)
    Gtot = np.zeros((n, n))
    for j in range(N):
        Gtot += Phi.T @ G[j] @ Phi
        Phi = S[j] @ Phi
    P0 = solve_discrete_lyapunov(M.T, Gtot)
    P0 = 0.5 * (P0 + P0.T)

    P_grid = np.empty((N, n, n))
    Pnext = P0
    for j in range(N - 1, -1, -1):
        Pj = S[j].T @ Pnext @ S[j] + G[j]
        P_grid[j] = 0.5 * (Pj + Pj.T)
        Pnext = P_grid[j]
    periodicity_error = float(np.max(np.abs(P_grid[0] - P0)) / np.max(np.abs(P0)))
    P_grid[0] = P0

    psi = period * np.arange(N) / N
    coeffs = _fourier(P_grid)

    # residual on the grid and at the midpoints
    check = np.concatenate([psi, psi + 0.5 * period / N])
    A = sys(check)
    P = _series(coeffs, period, check, derivative=False)
    dP = _series(coeffs, period, check, derivative=True)
    ATP = np.swapaxes(A, 1, 2) @ P
    lyap = ATP + np.swapaxes(ATP, 1, 2)
    R = dP + lyap + Q
    residual = float(np.max(np.abs(R)))
    scale = max(float(np.max(np.abs(Q))), float(np.max(np.abs(lyap))))
    lo, hi = _extreme_eigenvalues(P)
    return PeriodicLyapunovSolution(
        period=period, Q=Q, psi=psi, P_grid=P_grid, coefficients=coeffs, constant=False,
        floquet=res, residual=residual, relative_residual=residual / scale,
        periodicity_error=periodicity_error, min_eigenvalue=lo, max_eigenvalue=hi, n_grid=N,
    )


def periodic_lyapunov(
    A: SystemMatrix,
    period: float,
    Q=None,
    *,
    n_grid: int | None = None,
    residual_tol: float = 1e-8,
    vectorized: bool = False,
    rtol: float = 1e-11,
    atol: float = 1e-13,
    tol: float = 1e-9,
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
    n_grid : int, optional
        Number ``N`` of grid points (pieces of the period). Default: doubled from 32 until
        ``relative_residual <= residual_tol`` (at most 1024, with a RuntimeWarning otherwise).
    residual_tol : float
        Target of the automatic grid refinement.
    vectorized : bool
        ``A`` accepts an array of azimuths (then it is called with ``N`` azimuths per stage).
    rtol, atol : float
        Tolerances of the DOP853 integration of the pieces.
    tol : float
        Stability margin: the spectral radius of the monodromy matrix must be ``< 1 - tol``.

    Returns
    -------
    PeriodicLyapunovSolution
        With ``P(psi)``, ``dP(psi)``, ``W``, ``dW`` and the accuracy checks ``residual``,
        ``relative_residual``, ``periodicity_error``, ``min_eigenvalue``.

    Raises
    ------
    ValueError
        ``x' = A x`` not asymptotically stable (the message gives the spectral radius of the
        monodromy matrix); non-positive ``period``; ``Q`` not symmetric positive definite or of
        the wrong shape; ``A`` of the wrong shape or non-finite; bad ``n_grid``.
    TypeError
        ``A`` neither callable nor an array, or complex.
    """
    period = _positive_float("period", period)
    residual_tol = _positive_float("residual_tol", residual_tol)
    rtol = _positive_float("rtol", rtol)
    atol = _positive_float("atol", atol)
    tol = _nonnegative_float("tol", tol)
    if n_grid is not None:
        n_grid = _positive_int("n_grid", n_grid, 2)
    sys = _System(A, vectorized)
    Q = _check_Q(Q, sys.n)
    if sys.constant is not None:
        return _constant_solution(sys, period, Q, tol)
    if n_grid is not None:
        return _solve_on_grid(sys, period, Q, n_grid, tol, rtol, atol)
    N = _FIRST_GRID
    while True:
        sol = _solve_on_grid(sys, period, Q, N, tol, rtol, atol)
        if sol.relative_residual <= residual_tol:
            return sol
        if 2 * N > _MAX_GRID:
            warnings.warn(
                f"periodic_lyapunov: relative residual {sol.relative_residual:.3g} > "
                f"residual_tol={residual_tol:g} with the largest grid, N={N}; returning it",
                RuntimeWarning,
                stacklevel=2,
            )
            return sol
        N *= 2
