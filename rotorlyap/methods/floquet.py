"""Floquet analysis of a linear periodic system ``x' = J(psi) x``.

This module knows nothing about rotor blades: the system matrix ``J`` (the argument ``A`` of
the functions below) is any real ``n x n`` matrix function of the independent variable ``psi``
with period ``T`` (for the blade ``psi`` is the azimuth ``Omega t`` in rad, ``T = 2 pi`` and
``J`` is the Jacobian about the steady motion, as in the book's validation chapter; the book's
``A`` is the bound of the direct method).

Theory in brief
---------------
The fundamental matrix ``Phi(psi)`` solves ``Phi' = J(psi) Phi``, ``Phi(0) = I``. Its value
after one period, the monodromy matrix ``M = Phi(T)``, maps the state at ``psi`` to the state
at ``psi + T``. Its eigenvalues ``mu_i`` are the Floquet (characteristic) multipliers: the
origin is asymptotically stable if and only if every ``|mu_i| < 1``. The characteristic
exponents ``eta_i = log(mu_i) / T`` play the part of eigenvalues of a constant system: the
solutions are ``p(psi) exp(eta psi)`` with ``p`` T-periodic. Their real part is unique (a decay
or growth rate per unit ``psi``) but their imaginary part, a frequency, is known only modulo
``2 pi / T``: any integer ``k`` gives the same multiplier with ``Im eta + k 2 pi / T``. This
module returns the principal value (``-pi/T < Im eta <= pi/T``), except for a constant ``J``,
whose exponents are the eigenvalues of ``J`` themselves; :func:`modal_properties` adds the
branch chosen by the caller (continuation from a constant system is the usual way to choose).

Liouville's formula ``det M = exp(int_0^T trace J dpsi)`` holds exactly; every method here also
integrates ``trace J`` so that :attr:`FloquetResult.liouville_error` measures the accuracy of
the computed monodromy matrix.

Methods (``method=``)
---------------------
``"dop853"`` (default)
    Adaptive explicit Runge-Kutta of order 8 (:func:`scipy.integrate.solve_ivp`) on the
    flattened matrix ODE, ``rtol = 1e-11``, ``atol = 1e-13`` by default: relative accuracy of
    the monodromy matrix about ``1e-10`` for well-scaled problems, with error control. ``J`` is
    called at one ``psi`` per stage, or, with ``n_intervals = m > 1``, at ``m`` azimuths per
    stage: the period is split into ``m`` pieces integrated simultaneously from the identity
    and their transition matrices are multiplied (helpful when ``J`` is vectorised and
    expensive, and more robust when the system is strongly unstable).
``"magnus6"``
    Sixth-order Magnus integrator with three Gauss-Legendre nodes per step (Blanes, Casas, Oteo
    & Ros, Phys. Rep. 470, 2009, sec. 5): global error ``O(h**6)``, ``J`` sampled once on the
    ``3 n_steps`` nodes (one call when ``J`` is vectorised), one matrix exponential per step.
    The step matrices are exponentials, so ``det`` follows Liouville's formula up to the
    quadrature error of ``trace J`` and a Hamiltonian ``J`` gives a symplectic ``M``.
``"magnus4"``
    Fourth-order Magnus (two Gauss-Legendre nodes per step), same structure.
``"rk4"``
    Classical fourth-order Runge-Kutta on a uniform grid, ``J`` sampled once on the
    ``2 n_steps + 1`` points ``j T / (2 n_steps)``; global error ``O(h**4)``.

Non-smooth ``J``
----------------
The error control of DOP853 assumes a smooth right-hand side. A ``J(psi)`` with kinks (for
example from piecewise-linear airfoil data crossed by the local angle of attack) or with
round-off noise (a finite-difference Jacobian, about 1e-11 relative) forces tiny steps at
``rtol = 1e-11``: millions of evaluations, minutes of computing, for an accuracy that the kinks
limit anyway (the fixed-step methods lose their order at a kink too, converging like
``h**2``). ``max_evaluations`` stops such runs with advice; for such ``J`` use
``method="magnus6"`` with ``vectorized=True`` and a fixed ``n_steps`` (1024-4096 steps per
period cost well under a second for a 6 x 6 system) and judge the accuracy by comparing two
step counts.

For the fixed-step methods ``n_steps=None`` doubles the number of steps from 16 until two
successive monodromy matrices agree to ``rtol * max|M| + atol`` (at most 2**16 steps, with a
warning if not reached); :attr:`FloquetResult.error_estimate` is then the Richardson estimate
``max|M_2h - M_h| / (2**p - 1)``. A constant ``J`` (an array) is handled exactly by
:func:`scipy.linalg.expm` whatever the method.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field
from typing import Callable, Union

import numpy as np

from ._checks import nonnegative_float as _nonnegative_float
from ._checks import positive_float as _positive_float
from ._checks import positive_int as _positive_int
from scipy.integrate import solve_ivp
from scipy.linalg import expm

__all__ = [
    "METHODS",
    "FloquetResult",
    "ModalProperties",
    "floquet_multipliers",
    "modal_properties",
    "monodromy",
]

#: Integration methods accepted by :func:`monodromy` and :func:`floquet_multipliers`.
METHODS = ("dop853", "magnus6", "magnus4", "rk4")

_ORDER = {"magnus6": 6, "magnus4": 4, "rk4": 4}
_MAX_STEPS = 2**16
_FIRST_STEPS = 16

MatrixFunction = Callable[..., np.ndarray]
SystemMatrix = Union[MatrixFunction, np.ndarray]


# --------------------------------------------------------------------------------------
# Input checking
# --------------------------------------------------------------------------------------





def _real_square(name: str, value) -> np.ndarray:
    """A finite real square matrix, or a clear error."""
    if np.iscomplexobj(value):
        raise TypeError(f"{name} must be real, got a complex array")
    try:
        arr = np.array(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise TypeError(
            f"{name} must be a real (n, n) array or a callable, got {type(value).__name__}"
        ) from exc
    if arr.ndim != 2 or arr.shape[0] != arr.shape[1] or arr.shape[0] == 0:
        raise ValueError(
            f"{name} must be a square (n, n) matrix with n >= 1, got shape {arr.shape}"
        )
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} has non-finite entries: every entry must be finite")
    return arr


def _check_method(method: str) -> str:
    if not isinstance(method, str) or method.lower() not in METHODS:
        raise ValueError(f"method must be one of {', '.join(map(repr, METHODS))}; got {method!r}")
    return method.lower()


class _System:
    """``A(psi)`` made uniform: evaluated on arrays of azimuths, shapes and values checked.

    Calling the object with azimuths of shape ``(k,)`` returns ``(k, n, n)``. A callable ``A``
    is called once per azimuth (``vectorized=False``) or once with the whole array
    (``vectorized=True``, then it must return ``(k, n, n)``).
    """

    def __init__(self, A: SystemMatrix, vectorized: bool = False,
                 max_evaluations: int | None = None):
        self.count = 0
        self.limit = max_evaluations
        if callable(A):
            self.fun = A
            self.vectorized = bool(vectorized)
            self.constant = None
            self.n = None
            first = self._call_raw(np.zeros(1))
            self.n = first.shape[-1]
        elif isinstance(A, (np.ndarray, list, tuple)):
            self.fun = None
            self.vectorized = True
            self.constant = _real_square("A", A)
            self.n = self.constant.shape[0]
        else:
            raise TypeError(
                "A must be a callable A(psi) returning an (n, n) array, or a constant (n, n) "
                f"array; got {type(A).__name__}"
            )

    def _check(self, out, psi: np.ndarray) -> np.ndarray:
        if np.iscomplexobj(out):
            raise TypeError("A(psi) must return a real array, got a complex one")
        try:
            out = np.asarray(out, dtype=float)
        except (TypeError, ValueError) as exc:
            raise TypeError(
                f"A(psi) must return a real array, got {type(out).__name__}"
            ) from exc
        k = psi.shape[0]
        if self.n is None:  # first call: learn n
            ok = out.ndim == 3 and out.shape[0] == k and out.shape[1] == out.shape[2] > 0
        else:
            ok = out.shape == (k, self.n, self.n)
        if not ok:
            per = "(k, n, n) for psi of shape (k,)" if self.vectorized else "(n, n) for a float psi"
            got = out.shape if self.vectorized else out.shape[1:]
            if self.n is not None:
                want = (k, self.n, self.n) if self.vectorized else (self.n, self.n)
                per += f", here {want}"
            raise ValueError(
                f"A(psi) returned shape {got}; expected a square matrix of shape {per}"
                + ("" if self.vectorized else " (pass vectorized=True if A takes arrays)")
            )
        bad = ~np.isfinite(out).reshape(k, -1).all(axis=1)
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            raise ValueError(
                f"A(psi) returned a non-finite value at psi={psi[i]:.6g}: every entry must be "
                "finite over the whole period"
            )
        return out

    def _call_raw(self, psi: np.ndarray) -> np.ndarray:
        if self.limit is not None and self.count + psi.size > self.limit:
            raise ValueError(
                f"A(psi) was evaluated at {self.count} azimuths and max_evaluations="
                f"{self.limit} would be exceeded: the adaptive integration is not converging, "
                "which usually means A(psi) is not smooth (kinks, e.g. from piecewise-linear "
                "airfoil data) or noisy (e.g. a finite-difference Jacobian). Loosen rtol "
                "(e.g. 1e-8), use a fixed-step method with n_steps (e.g. method='magnus6', "
                "n_steps=2048), or raise max_evaluations"
            )
        self.count += psi.size
        if self.vectorized:
            return self._check(self.fun(psi), psi)
        mats = []
        for p in psi:
            out = self.fun(float(p))
            if np.iscomplexobj(out):
                raise TypeError("A(psi) must return a real array, got a complex one")
            try:
                mats.append(np.asarray(out, dtype=float))
            except (TypeError, ValueError) as exc:
                raise TypeError(
                    f"A(psi) must return a real array, got {type(out).__name__}"
                ) from exc
        shapes = {m.shape for m in mats}
        if len(shapes) != 1:
            raise ValueError(f"A(psi) returned arrays of different shapes {sorted(shapes)}")
        return self._check(np.stack(mats), psi)

    def __call__(self, psi) -> np.ndarray:
        psi = np.asarray(psi, dtype=float).reshape(-1)
        if self.constant is not None:
            return np.broadcast_to(self.constant, (psi.size, self.n, self.n))
        return self._call_raw(psi)


# --------------------------------------------------------------------------------------
# Integrators: step (transition) matrices over consecutive pieces of the period
# --------------------------------------------------------------------------------------


def _chain_product(steps: np.ndarray) -> np.ndarray:
    """``S[-1] @ ... @ S[1] @ S[0]`` by pairwise (tree) multiplication, for ``(k, n, n)``."""
    mats = np.asarray(steps)
    while mats.shape[0] > 1:
        if mats.shape[0] % 2:
            eye = np.eye(mats.shape[1])[None]
            mats = np.concatenate([mats, eye])
        mats = mats[1::2] @ mats[0::2]
    return mats[0]


def _dop853_pieces(sys: _System, period: float, n_pieces: int, rtol: float, atol: float,
                   Q: np.ndarray | None = None):
    """Transition matrices of ``n_pieces`` equal pieces of the period, integrated together.

    Returns ``(S, G, trace_integral)`` with ``S[j] = Phi(psi_{j+1}, psi_j)``, and, if ``Q`` is
    given, ``G[j] = int_{psi_j}^{psi_{j+1}} Phi(s, psi_j)^T Q Phi(s, psi_j) ds`` (else None).
    The error control of DOP853 acts on the RMS over all pieces of the weighted error.
    """
    n, m = sys.n, n_pieces
    h = period / m
    start = h * np.arange(m)
    nn = m * n * n
    eye = np.broadcast_to(np.eye(n), (m, n, n))
    parts = [eye.ravel()]
    if Q is not None:
        parts.append(np.zeros(nn))
    parts.append(np.zeros(m))
    y0 = np.concatenate(parts)

    def rhs(s, y):
        Am = sys(start + s)
        Phi = y[:nn].reshape(m, n, n)
        out = [(Am @ Phi).ravel()]
        if Q is not None:
            out.append((np.swapaxes(Phi, 1, 2) @ Q @ Phi).ravel())
        out.append(np.trace(Am, axis1=1, axis2=2))
        return np.concatenate(out)

    sol = solve_ivp(rhs, (0.0, h), y0, method="DOP853", rtol=rtol, atol=atol)
    if sol.status != 0:
        raise ValueError(f"integration of Phi' = A Phi failed: {sol.message}")
    y = sol.y[:, -1]
    S = y[:nn].reshape(m, n, n)
    G = y[nn:2 * nn].reshape(m, n, n) if Q is not None else None
    return S, G, float(np.sum(y[-m:]))


def _expm_batch(X: np.ndarray) -> np.ndarray:
    """Matrix exponentials of a stack ``(k, n, n)``: Taylor series of degree 12 after scaling
    by ``2**-s`` to 1-norm <= 1/4 (truncation < 3e-18 relative), then ``s`` squarings.

    Vectorised over the stack (much faster than a loop of :func:`scipy.linalg.expm` for the
    many small, small-norm matrices of the Magnus steps).
    """
    norm = float(np.max(np.sum(np.abs(X), axis=-2))) if X.size else 0.0
    s = max(0, int(np.ceil(np.log2(norm / 0.25)))) if norm > 0 else 0
    Y = X / 2.0**s
    eye = np.eye(X.shape[-1])
    E = eye + Y / 12.0
    for j in range(11, 0, -1):
        E = eye + (Y @ E) / j
    for _ in range(s):
        E = E @ E
    return E


def _fixed_steps(sys: _System, period: float, method: str, n_steps: int):
    """Step matrices ``(n_steps, n, n)`` of a fixed-step method and the integral of trace A."""
    n = sys.n
    h = period / n_steps
    k = np.arange(n_steps)
    if method == "rk4":
        samples = sys(0.5 * h * np.arange(2 * n_steps + 1))
        A0, Am, A1 = samples[0:-1:2], samples[1::2], samples[2::2]
        eye = np.eye(n)
        K1 = A0
        K2 = Am @ (eye + 0.5 * h * K1)
        K3 = Am @ (eye + 0.5 * h * K2)
        K4 = A1 @ (eye + h * K3)
        steps = eye + (h / 6.0) * (K1 + 2.0 * K2 + 2.0 * K3 + K4)
        tr = np.trace(samples, axis1=1, axis2=2)
        trace_integral = (h / 6.0) * float(np.sum(tr[0:-1:2] + 4.0 * tr[1::2] + tr[2::2]))
        return steps, trace_integral
    if method == "magnus4":
        c = np.array([0.5 - np.sqrt(3.0) / 6.0, 0.5 + np.sqrt(3.0) / 6.0])
        A = sys(((k[:, None] + c[None, :]) * h).ravel()).reshape(n_steps, 2, n, n)
        A1, A2 = A[:, 0], A[:, 1]
        omega = 0.5 * h * (A1 + A2) + (np.sqrt(3.0) / 12.0) * h**2 * (A2 @ A1 - A1 @ A2)
        tr = np.trace(A, axis1=2, axis2=3)
        trace_integral = 0.5 * h * float(np.sum(tr))
        return _expm_batch(omega), trace_integral
    # magnus6: Blanes, Casas, Oteo & Ros (2009), sixth-order scheme with Gauss nodes
    r = np.sqrt(15.0) / 10.0
    c = np.array([0.5 - r, 0.5, 0.5 + r])
    A = sys(((k[:, None] + c[None, :]) * h).ravel()).reshape(n_steps, 3, n, n)
    A1, A2, A3 = A[:, 0], A[:, 1], A[:, 2]
    a1 = h * A2
    a2 = (np.sqrt(15.0) * h / 3.0) * (A3 - A1)
    a3 = (10.0 * h / 3.0) * (A3 - 2.0 * A2 + A1)

    def comm(X, Y):
        return X @ Y - Y @ X

    C1 = comm(a1, a2)
    C2 = -(1.0 / 60.0) * comm(a1, 2.0 * a3 + C1)
    omega = a1 + a3 / 12.0 + (1.0 / 240.0) * comm(-20.0 * a1 - a3 + C1, a2 + C2)
    tr = np.trace(A, axis1=2, axis2=3)
    trace_integral = (h / 18.0) * float(np.sum(5.0 * tr[:, 0] + 8.0 * tr[:, 1] + 5.0 * tr[:, 2]))
    return _expm_batch(omega), trace_integral


@dataclass(frozen=True)
class _Monodromy:
    M: np.ndarray
    trace_integral: float
    method: str
    n_steps: int | None
    error_estimate: float
    n_evaluations: int


def _compute_monodromy(sys: _System, period: float, method: str, n_steps, n_intervals: int,
                       rtol: float, atol: float) -> _Monodromy:
    if sys.constant is not None:
        return _Monodromy(
            expm(sys.constant * period), float(np.trace(sys.constant)) * period, "expm", None,
            0.0, 0,
        )
    if method == "dop853":
        if n_steps is not None:
            raise ValueError(
                "n_steps applies to the fixed-step methods ('magnus6', 'magnus4', 'rk4') only; "
                "method 'dop853' is adaptive (set rtol/atol instead)"
            )
        S, _, tr = _dop853_pieces(sys, period, n_intervals, rtol, atol)
        return _Monodromy(_chain_product(S), tr, method, None, float("nan"), sys.count)
    if n_intervals != 1:
        raise ValueError("n_intervals applies to method 'dop853' only")
    if n_steps is not None:
        n_steps = _positive_int("n_steps", n_steps)
        S, tr = _fixed_steps(sys, period, method, n_steps)
        return _Monodromy(_chain_product(S), tr, method, n_steps, float("nan"), sys.count)
    p = _ORDER[method]
    n = _FIRST_STEPS
    S, tr = _fixed_steps(sys, period, method, n)
    M = _chain_product(S)
    while True:
        n2 = 2 * n
        S, tr = _fixed_steps(sys, period, method, n2)
        M2 = _chain_product(S)
        diff = float(np.max(np.abs(M2 - M)))
        if diff <= rtol * float(np.max(np.abs(M2))) + atol:
            break
        if n2 >= _MAX_STEPS:
            warnings.warn(
                f"monodromy ({method}): successive results still differ by {diff:.3g} with "
                f"{n2} steps (tolerance rtol={rtol:g}, atol={atol:g}); returning the last one. "
                "Pass n_steps explicitly, loosen rtol, or use method='dop853'.",
                RuntimeWarning,
                stacklevel=3,
            )
            break
        n, M = n2, M2
    return _Monodromy(M2, tr, method, n2, diff / (2**p - 1), sys.count)


def monodromy(
    A: SystemMatrix,
    period: float,
    *,
    method: str = "dop853",
    n_steps: int | None = None,
    n_intervals: int = 1,
    vectorized: bool = False,
    rtol: float = 1e-11,
    atol: float = 1e-13,
    max_evaluations: int | None = 1_000_000,
) -> np.ndarray:
    """Monodromy matrix ``Phi(T)`` of ``x' = J(psi) x``: ``Phi' = J Phi`` from ``Phi(0) = I``.

    Parameters
    ----------
    A : callable or array_like
        The system matrix ``J``: ``A(psi)`` returning a real ``(n, n)`` array for a float ``psi`` (units of ``psi``: those
        of ``period``, e.g. rad of azimuth), or, with ``vectorized=True``, a ``(k, n, n)``
        array for ``psi`` of shape ``(k,)``. A constant real ``(n, n)`` array is also accepted
        (then ``expm(A T)`` is returned and ``method`` is not used).
    period : float
        The period ``T`` of ``J`` (> 0), same units as ``psi``.
    method : {"dop853", "magnus6", "magnus4", "rk4"}
        Integrator, see the module docstring. Default ``"dop853"`` (adaptive, error
        controlled; about 1e-10 relative accuracy with the default tolerances).
    n_steps : int, optional
        Steps per period of a fixed-step method. Default: doubled from 16 until converged to
        ``rtol`` (see the module docstring). Not allowed with ``"dop853"``.
    n_intervals : int
        ``"dop853"`` only: number of equal pieces of the period integrated simultaneously.
    vectorized : bool
        ``A`` accepts an array of azimuths and returns ``(k, n, n)``.
    rtol, atol : float
        Relative and absolute tolerances (of DOP853, or of the step doubling).
    max_evaluations : int or None
        Stop with a ValueError once ``A`` would be evaluated at more azimuths than this
        (None: no limit). A smooth 6 x 6 system needs a few thousand; a non-smooth or noisy
        ``A`` can make DOP853 at ``rtol = 1e-11`` take millions (minutes): see the error
        message for remedies.

    Returns
    -------
    numpy.ndarray
        The monodromy matrix, shape ``(n, n)``.

    Raises
    ------
    ValueError
        Non-positive ``period``; ``A`` not square, of the wrong shape or non-finite; unknown
        ``method``; bad ``n_steps``/``n_intervals``; failed integration; more than
        ``max_evaluations`` evaluations of ``A``.
    TypeError
        ``A`` neither callable nor an array, or complex.
    """
    return floquet_multipliers(
        A, period, method=method, n_steps=n_steps, n_intervals=n_intervals,
        vectorized=vectorized, rtol=rtol, atol=atol, max_evaluations=max_evaluations,
    ).monodromy


# --------------------------------------------------------------------------------------
# Results
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ModalProperties:
    """Frequencies and damping of Floquet modes, from :func:`modal_properties`.

    For an exponent ``eta = sigma + i omega`` (``omega`` already shifted by the chosen branch)
    these are the quantities of a damped oscillator with eigenvalue ``eta``:
    ``eta = -zeta w_n + i w_n sqrt(1 - zeta**2)``.

    Attributes
    ----------
    exponents : numpy.ndarray
        The exponents with the branch applied, complex, 1 / (unit of ``psi``).
    frequency : numpy.ndarray
        ``omega = Im eta + branch 2 pi / T``, rad per unit of ``psi``. With ``psi = Omega t``
        in rad (``T = 2 pi``) this is the frequency in per-rev units, ``omega_phys / Omega``.
    frequency_ratio : numpy.ndarray
        ``omega / (2 pi / T)``: the frequency in units of the angular rate of the period
        (equal to ``frequency`` when ``T = 2 pi``).
    growth_rate : numpy.ndarray
        ``sigma = Re eta``, 1 / (unit of ``psi``): negative for a decaying mode. Independent of
        the branch.
    natural_frequency : numpy.ndarray
        ``w_n = |eta|``, rad per unit of ``psi``.
    damping_ratio : numpy.ndarray
        ``zeta = -sigma / |eta|`` (dimensionless; NaN where ``eta = 0``). Depends on the branch
        through ``|eta|``.
    period : float
        The period ``T``.
    branch : numpy.ndarray
        The integer branch of each exponent.
    """

    exponents: np.ndarray
    frequency: np.ndarray
    frequency_ratio: np.ndarray
    growth_rate: np.ndarray
    natural_frequency: np.ndarray
    damping_ratio: np.ndarray
    period: float
    branch: np.ndarray

    def __post_init__(self) -> None:
        for name in ("exponents", "frequency", "frequency_ratio", "growth_rate",
                     "natural_frequency", "damping_ratio", "branch"):
            arr = np.array(getattr(self, name), copy=True)
            arr.setflags(write=False)
            object.__setattr__(self, name, arr)


def modal_properties(exponents, period: float, branch=0) -> ModalProperties:
    """Frequency and damping ratio of each Floquet mode from its characteristic exponent.

    The imaginary part of a characteristic exponent is only known modulo ``2 pi / T``; the
    integer ``branch`` ``k`` selects ``omega = Im eta + k 2 pi / T``. The growth rate does not
    depend on it; the damping ratio ``-sigma / |eta|`` does.

    Parameters
    ----------
    exponents : array_like
        Characteristic exponents ``eta`` (complex), 1 / (unit of ``psi``), any shape.
    period : float
        The period ``T`` (> 0).
    branch : int or array_like of int
        Branch ``k`` of each exponent, broadcast against ``exponents``. Default 0 (the
        principal value returned by :func:`floquet_multipliers`).

    Returns
    -------
    ModalProperties

    Raises
    ------
    ValueError
        Non-positive ``period``, non-integer ``branch``, shapes that do not broadcast, or
        NaN exponents.
    """
    period = _positive_float("period", period)
    eta = np.asarray(exponents, dtype=complex)
    if np.any(np.isnan(eta)):
        raise ValueError("exponents must not contain NaN")
    bad_branch = f"branch must be an integer or an array of integers, got {branch!r}"
    try:
        kf = np.asarray(branch, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ValueError(bad_branch) from exc
    is_bool = np.asarray(branch).dtype == bool
    if is_bool or not np.all(np.isfinite(kf)) or np.any(kf != np.round(kf)):
        raise ValueError(bad_branch)
    k = kf.astype(int)
    try:
        eta, k = np.broadcast_arrays(eta, k)
    except ValueError as exc:
        raise ValueError(
            f"branch of shape {k.shape} does not broadcast with exponents of shape {eta.shape}"
        ) from exc
    rate = 2.0 * np.pi / period
    omega = eta.imag + k * rate
    sigma = eta.real
    shifted = sigma + 1j * omega
    with np.errstate(invalid="ignore", divide="ignore"):
        wn = np.hypot(sigma, omega)
        zeta = np.where(wn > 0, -sigma / np.where(wn > 0, wn, 1.0), np.nan)
    return ModalProperties(
        exponents=shifted, frequency=omega, frequency_ratio=omega / rate, growth_rate=sigma,
        natural_frequency=wn, damping_ratio=zeta, period=period, branch=k,
    )


@dataclass(frozen=True)
class FloquetResult:
    """Outcome of :func:`floquet_multipliers`.

    Attributes
    ----------
    monodromy : numpy.ndarray
        The monodromy matrix ``M = Phi(T)``, shape ``(n, n)``.
    multipliers : numpy.ndarray
        Eigenvalues of ``M`` (complex), sorted by decreasing modulus (ties, such as complex
        conjugate pairs, by decreasing imaginary part).
    exponents : numpy.ndarray
        Characteristic exponents ``eta = log(mu) / T`` in the order of ``multipliers``, complex,
        1 / (unit of ``psi``). Principal branch, ``-pi/T < Im eta <= pi/T``: frequencies are
        known only modulo ``2 pi / T`` (see :func:`modal_properties`). For a constant ``A``
        they are the eigenvalues of ``A`` (the true frequencies). ``-inf`` real part for a
        zero multiplier. A multiplier much smaller than the largest carries an absolute error
        of about ``eps * max|M|``, so the real part of its exponent is less accurate.
    spectral_radius : float
        ``max |mu|``.
    stable : bool
        Asymptotic stability: every ``|mu| < 1 - tol``. False also for marginal stability
        (multipliers on the unit circle, e.g. an undamped Hamiltonian system).
    period : float
        The period ``T``.
    tol : float
        Margin used for ``stable``.
    trace_integral : float
        ``int_0^T trace A(psi) dpsi`` by the same integrator; Liouville: ``det M`` equals its
        exponential.
    method : str
        Integrator used (``"expm"`` for a constant array).
    n_steps : int or None
        Steps per period of a fixed-step method, None otherwise.
    error_estimate : float
        Richardson estimate of ``max |M - M_exact|`` for an automatically refined fixed-step
        method, 0 for ``"expm"``, NaN when not estimated.
    n_evaluations : int
        Number of azimuths at which ``A`` was evaluated (including the first call at
        ``psi = 0`` that checks its shape).
    """

    monodromy: np.ndarray
    multipliers: np.ndarray
    exponents: np.ndarray
    spectral_radius: float
    stable: bool
    period: float
    tol: float
    trace_integral: float
    method: str
    n_steps: int | None = None
    error_estimate: float = float("nan")
    n_evaluations: int = field(default=0, compare=False)

    def __post_init__(self) -> None:
        for name in ("monodromy", "multipliers", "exponents"):
            arr = np.array(getattr(self, name), copy=True)
            arr.setflags(write=False)
            object.__setattr__(self, name, arr)

    @property
    def liouville_error(self) -> float:
        """``|det M / exp(int_0^T trace A) - 1|``: a check of the integration accuracy.

        Meaningful when ``M`` is well conditioned. With strongly damped modes (multipliers
        many orders of magnitude below the largest) ``det M`` is dominated by the round-off
        in the smallest multipliers, about ``eps * max|M|`` each, and this check says little.
        """
        return float(abs(np.linalg.det(self.monodromy) * np.exp(-self.trace_integral) - 1.0))

    def modal_properties(self, branch=0) -> ModalProperties:
        """:func:`modal_properties` of :attr:`exponents` with this result's period."""
        return modal_properties(self.exponents, self.period, branch)

    def __repr__(self) -> str:  # short and stable: no arrays, no addresses
        mods = ", ".join(f"{abs(m):.6g}" for m in self.multipliers)
        return (
            f"FloquetResult(n={self.monodromy.shape[0]}, period={self.period:.6g}, "
            f"spectral_radius={self.spectral_radius:.6g}, stable={self.stable}, "
            f"|multipliers|=[{mods}], method={self.method!r})"
        )


def _sort_order(mu: np.ndarray, rel: float = 1e-10) -> np.ndarray:
    """Indices sorting ``mu`` by decreasing modulus; near-equal moduli by decreasing imag."""
    mod = np.abs(mu)
    order = list(np.argsort(-mod, kind="stable"))
    out: list[int] = []
    i = 0
    while i < len(order):
        j = i + 1
        while j < len(order) and mod[order[i]] - mod[order[j]] <= rel * max(mod[order[i]], 1e-300):
            j += 1
        group = order[i:j]
        group.sort(key=lambda g: (-mu[g].imag, -mu[g].real))
        out.extend(group)
        i = j
    return np.asarray(out, dtype=int)


def _result(mono: _Monodromy, period: float, tol: float, eigenvalues=None) -> FloquetResult:
    M = mono.M
    if eigenvalues is not None:  # constant A: exponents are the eigenvalues of A
        eta = np.asarray(eigenvalues, dtype=complex)
        mu = np.exp(eta * period)
    else:
        mu = np.linalg.eigvals(M).astype(complex)
        with np.errstate(divide="ignore"):
            eta = np.log(mu) / period
    order = _sort_order(mu)
    mu, eta = mu[order], eta[order]
    rho = float(np.max(np.abs(mu)))
    return FloquetResult(
        monodromy=M, multipliers=mu, exponents=eta, spectral_radius=rho,
        stable=bool(rho < 1.0 - tol), period=period, tol=tol,
        trace_integral=mono.trace_integral, method=mono.method, n_steps=mono.n_steps,
        error_estimate=mono.error_estimate, n_evaluations=mono.n_evaluations,
    )


def floquet_multipliers(
    A: SystemMatrix,
    period: float,
    *,
    method: str = "dop853",
    n_steps: int | None = None,
    n_intervals: int = 1,
    vectorized: bool = False,
    rtol: float = 1e-11,
    atol: float = 1e-13,
    tol: float = 1e-9,
    max_evaluations: int | None = 1_000_000,
) -> FloquetResult:
    """Floquet multipliers and characteristic exponents of ``x' = J(psi) x``.

    Parameters
    ----------
    A : callable or array_like
        The system matrix ``J``: ``A(psi)``, period ``period``; see :func:`monodromy` (also for a
        constant array).
    period : float
        The period ``T`` (> 0), units of ``psi``.
    method, n_steps, n_intervals, vectorized, rtol, atol, max_evaluations
        Integration of the monodromy matrix, see :func:`monodromy`.
    tol : float
        Margin of the stability test: ``stable`` is ``max |mu| < 1 - tol`` (>= 0).

    Returns
    -------
    FloquetResult
        Named fields ``monodromy, multipliers, exponents, spectral_radius, stable`` and more.

    Raises
    ------
    ValueError, TypeError
        As :func:`monodromy`; also a negative ``tol``.

    Examples
    --------
    A damped oscillator ``x'' + 2 zeta w x' + w**2 x = 0`` has the multipliers
    ``exp(lambda T)``, ``lambda = -zeta w +- i w sqrt(1 - zeta**2)``:

    >>> import numpy as np
    >>> res = floquet_multipliers(lambda p: np.array([[0.0, 1.0], [-4.0, -0.4]]), 2 * np.pi)
    >>> res.stable, bool(abs(res.spectral_radius - np.exp(-0.2 * 2 * np.pi)) < 1e-9)
    (True, True)
    """
    period = _positive_float("period", period)
    method = _check_method(method)
    n_intervals = _positive_int("n_intervals", n_intervals)
    rtol = _positive_float("rtol", rtol)
    atol = _positive_float("atol", atol)
    tol = _nonnegative_float("tol", tol)
    if max_evaluations is not None:
        max_evaluations = _positive_int("max_evaluations", max_evaluations)
    sys = _System(A, vectorized, max_evaluations)
    mono = _compute_monodromy(sys, period, method, n_steps, n_intervals, rtol, atol)
    eig = np.linalg.eigvals(sys.constant) if sys.constant is not None else None
    return _result(mono, period, tol, eig)
