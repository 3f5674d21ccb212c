"""Time (azimuth) simulation of many motions of a periodic system at once.

The right-hand sides in this package are vectorised over states, so ``m`` motions of an
``n``-state system are integrated as one system of ``m * n`` equations by
:func:`scipy.integrate.solve_ivp`: one call, no Python loop over motions.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np
from scipy.integrate import solve_ivp

__all__ = ["SimulationResult", "simulate", "scaled_norm"]

Function = Callable[[np.ndarray, np.ndarray], np.ndarray]


def scaled_norm(x: np.ndarray, scales=None) -> np.ndarray:
    """The paper's norm ``||x|| = sqrt(sum((x_i / a_i)**2))`` over the last axis.

    Parameters
    ----------
    x : numpy.ndarray
        States, shape ``(..., n)``.
    scales : array_like, optional
        The ``a_i`` (> 0), shape ``(n,)``; default ones.

    Returns
    -------
    numpy.ndarray
        Shape ``x.shape[:-1]``.
    """
    x = np.asarray(x, dtype=float)
    a = np.ones(x.shape[-1]) if scales is None else np.asarray(scales, dtype=float)
    return np.sqrt(np.sum((x / a) ** 2, axis=-1))


@dataclass(frozen=True)
class SimulationResult:
    """Motions computed by :func:`simulate`.

    Attributes
    ----------
    psi : numpy.ndarray
        Output azimuths, shape ``(k,)``.
    x : numpy.ndarray
        States, shape ``(k, m, n)``: output azimuth, motion, component.
    norm : numpy.ndarray
        Scaled norm of each state, shape ``(k, m)``.
    max_norm : numpy.ndarray
        Largest scaled norm of each motion over the output azimuths, shape ``(m,)``.
    escaped : numpy.ndarray
        Boolean per motion: the integration stopped because the norm exceeded ``escape``.
    """

    psi: np.ndarray
    x: np.ndarray
    norm: np.ndarray
    max_norm: np.ndarray
    escaped: np.ndarray


def simulate(
    f: Function,
    x0,
    psi0: float,
    n_periods: float,
    *,
    period: float = 2 * np.pi,
    scales=None,
    points_per_period: int = 64,
    escape: float | None = None,
    rtol: float = 1e-9,
    atol: float = 1e-12,
) -> SimulationResult:
    """Integrate ``x' = f(psi, x)`` from many initial states at once.

    Parameters
    ----------
    f : callable
        Vectorised right-hand side, ``(psi (m,), x (m, n)) -> (m, n)``.
    x0 : array_like
        Initial states, shape ``(m, n)`` (or ``(n,)`` for one motion).
    psi0 : float
        Initial azimuth.
    n_periods : float
        Length of the simulation in periods (> 0).
    period : float
        The period (> 0).
    scales : array_like, optional
        Norm scales for ``norm`` and ``escape``.
    points_per_period : int
        Output azimuths per period.
    escape : float, optional
        Stop the whole integration when any motion's norm exceeds this value (an unbounded
        motion would otherwise stall the integrator); those motions are marked ``escaped``.
    rtol, atol : float
        Tolerances of the integrator (DOP853).

    Returns
    -------
    SimulationResult

    Raises
    ------
    ValueError
        Bad shapes or lengths, or an integration failure (the solver's message is given).
    """
    x0 = np.atleast_2d(np.asarray(x0, dtype=float))
    if x0.ndim != 2:
        raise ValueError(f"x0 must have shape (m, n), got {x0.shape}")
    if not (np.isfinite(n_periods) and n_periods > 0):
        raise ValueError(f"n_periods must be > 0, got {n_periods!r}")
    if not (np.isfinite(period) and period > 0):
        raise ValueError(f"period must be > 0, got {period!r}")
    m, n = x0.shape
    a = np.ones(n) if scales is None else np.asarray(scales, dtype=float)
    k = int(np.ceil(n_periods * points_per_period)) + 1
    t_eval = psi0 + np.linspace(0.0, n_periods * period, k)

    def rhs(p, y):
        x = y.reshape(m, n)
        return np.asarray(f(np.full(m, p), x), dtype=float).reshape(-1)

    events = None
    if escape is not None:
        def leave(p, y):
            return escape - scaled_norm(y.reshape(m, n), a).max()

        leave.terminal = True
        events = leave

    sol = solve_ivp(
        rhs, (t_eval[0], t_eval[-1]), x0.reshape(-1), method="DOP853", t_eval=t_eval,
        rtol=rtol, atol=atol, events=events,
    )
    if sol.status == -1:
        raise ValueError(f"integration failed: {sol.message}")
    x = sol.y.T.reshape(-1, m, n)
    norm = scaled_norm(x, a)
    escaped = np.zeros(m, dtype=bool)
    if escape is not None and sol.status == 1:
        y_end = sol.y_events[0][-1].reshape(m, n)
        escaped = scaled_norm(y_end, a) >= escape * (1 - 1e-9)
    return SimulationResult(
        psi=sol.t, x=x, norm=norm, max_norm=norm.max(axis=0) if norm.size else np.zeros(m),
        escaped=escaped,
    )
