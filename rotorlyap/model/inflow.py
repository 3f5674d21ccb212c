"""Induced inflow of the rotor: momentum theory and linear (Glauert-type) inflow models.

All inflow ratios are positive downwards and non-dimensional by the tip speed
``Omega R``; the shaft is not tilted, so the inflow through the disc is the
induced inflow alone.  Azimuth ``psi = 0`` points downstream (the blade over
the tail), so ``cos psi = 1`` at the rear of the disc, where the linear models
give the larger inflow:

    lambda_i(r, psi) = lambda_0 (1 + k_x r cos psi),   r = r/R.

Thrust = weight at every advance ratio (no fuselage drag, no download), a
stated simplification consistent with the paper's steady motion.

Citation keys refer to the report's ``references.bib``.

References
----------
- [Glauert1926] H. Glauert, "A general theory of the autogyro", ARC R&M 1111, 1926.
- [Johnson1980] W. Johnson, *Helicopter Theory*, Princeton University Press, 1980
  (momentum theory in forward flight; the linear inflow variation).
- [Johnson2013] W. Johnson, *Rotorcraft Aeromechanics*, Cambridge University
  Press, 2013.
- [Leishman2006] J. G. Leishman, *Principles of Helicopter Aerodynamics*, 2nd
  ed., Cambridge University Press, 2006 (momentum theory; the linear inflow
  models and their k_x).
- [Coleman1945] R. P. Coleman, A. M. Feingold and C. W. Stempin, NACA ARR L5E10, 1945.
- [Drees1949] J. M. Drees, J. Helicopter Assoc. Great Britain 3(2), 1949.
- [PittPeters1981] D. M. Pitt and D. A. Peters, Vertica 5(1), 1981.
- [Chen1990] R. T. N. Chen, "A survey of nonuniform inflow models for rotorcraft flight
  dynamics and control applications", NASA TM-102219, 1989 (Vertica 14(2), 1990).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import InflowConvergenceError
from .parameters import INFLOW_MODELS, BladeParameters

__all__ = [
    "induced_inflow",
    "kx_factor",
    "mean_inflow",
    "momentum_inflow",
    "thrust_coefficient",
    "wake_skew",
]

#: Glauert's constant longitudinal inflow gradient [Glauert1926], [Johnson1980].
GLAUERT_KX = 1.2

#: The steady first-harmonic inflow of Pitt and Peters' model, ``k_x = 15 pi/32 tan(chi/2)``
#: [PittPeters1981], as tabulated by [Chen1990] (NASA TM-102219, whose survey lists every linear
#: model with its source; 15 pi/23 also appears in print, which this module used before).
PITT_PETERS_KX = 15.0 * math.pi / 32.0


def thrust_coefficient(params: BladeParameters) -> float:
    """Rotor thrust coefficient for thrust equal to the helicopter weight.

    ``C_T = W / (rho pi R^2 (Omega R)^2)`` with ``W = helicopter_mass * gravity``;
    used at every advance ratio (thrust = weight, no fuselage drag or download).

    Parameters
    ----------
    params : BladeParameters

    Returns
    -------
    float
        C_T, -.

    Raises
    ------
    ValueError
        If ``params.air_density`` is 0 (vacuum: no thrust coefficient), or the
        weight is 0 (``gravity == 0``).
    """
    if params.air_density <= 0.0:
        raise ValueError(f"thrust_coefficient: air_density must be > 0, got {params.air_density!r} (vacuum)")
    w = params.helicopter_mass * params.gravity
    if w <= 0.0:
        raise ValueError(f"thrust_coefficient: weight helicopter_mass*gravity must be > 0, got {w!r} N")
    r = params.radius
    return w / (params.air_density * math.pi * r * r * (params.rotor_speed * r) ** 2)


def _check_nonneg(name: str, x: ArrayLike) -> NDArray[np.float64]:
    a = np.asarray(x, dtype=np.float64)
    if not np.all(np.isfinite(a)):
        raise ValueError(f"{name} must be finite, got {x!r}")
    if np.any(a < 0):
        raise ValueError(f"{name} must be >= 0, got {x!r}")
    return a


def momentum_inflow(ct: ArrayLike, mu: ArrayLike, tol: float = 1e-13, maxiter: int = 50, *,
                    through_flow: ArrayLike = 0.0) -> float | NDArray[np.float64]:
    """Mean induced inflow ratio from momentum theory [Johnson1980], [Leishman2006].

    Hover: ``lambda_i = sqrt(C_T / 2)``.  Forward flight (Glauert's formula):
    ``lambda_i = C_T / (2 sqrt(mu^2 + (lambda_c + lambda_i)^2))`` with ``lambda_c =
    through_flow = mu tan(alpha_s)`` the free stream's flow down through a disc tilted forward
    by ``alpha_s`` (0 for an untilted disc), solved by Newton's method on ``f(lambda_i) = 2
    lambda_i sqrt(mu^2 + (lambda_c + lambda_i)^2) - C_T`` started from the hover value; for
    ``lambda_c >= 0``, ``f`` is increasing and convex for ``lambda_i > 0`` and ``f >= 0`` at the
    start, so the iterates decrease monotonically to the unique root. A small negative
    ``lambda_c`` (a disc tilted slightly aft) is allowed; a whole inflow ``lambda_c + lambda_i``
    that is not positive (the windmill states, where momentum theory fails) is refused.

    Parameters
    ----------
    ct : array_like
        Thrust coefficient, >= 0.
    mu : array_like
        Advance ratio ``V cos(alpha_s) / (Omega R)``, >= 0 (broadcast with ``ct``).
    tol : float
        Convergence tolerance on the Newton step, relative to the hover inflow.
    maxiter : int
        Maximum number of Newton iterations.
    through_flow : array_like
        ``lambda_c = mu tan(alpha_s)``, the free stream's inflow ratio through the disc (positive
        down, a disc tilted forward).

    Returns
    -------
    float or ndarray
        lambda_i, the induced inflow ratio, positive downwards, -; a float for scalar inputs.

    Raises
    ------
    ValueError
        For negative or non-finite ``ct`` or ``mu``.
    rotorlyap.errors.InflowConvergenceError
        If the iteration has not converged after ``maxiter`` steps.
    """
    ct_a = _check_nonneg("ct", ct)
    mu_a = _check_nonneg("mu", mu)
    lc_a = np.asarray(through_flow, dtype=np.float64)
    if not np.all(np.isfinite(lc_a)):
        raise ValueError(f"through_flow must be finite, got {through_flow!r}")
    ct_a, mu_a, lc_a = np.broadcast_arrays(ct_a, mu_a, lc_a)
    lam_h = np.sqrt(0.5 * ct_a)
    lam = lam_h.copy()
    scale = np.where(lam_h > 0, lam_h, 1.0)
    converged = False
    for _ in range(maxiter):
        tot = lc_a + lam
        s = np.sqrt(mu_a * mu_a + tot * tot)
        f = 2.0 * lam * s - ct_a
        fp = 2.0 * s + 2.0 * lam * tot / np.where(s > 0, s, 1.0)
        step = np.where(fp > 0, f / np.where(fp > 0, fp, 1.0), 0.0)
        lam = lam - step
        if np.all(np.abs(step) <= tol * scale):
            converged = True
            break
    if converged and not np.all((lam > 0) & (lc_a + lam > 0) | (ct_a == 0)):
        raise ValueError(f"momentum_inflow: the whole inflow through the disc is not positive (ct={ct!r}, "
                         f"mu={mu!r}, through_flow={through_flow!r}): a windmill state, outside momentum theory")
    if not converged:
        raise InflowConvergenceError(
            f"momentum_inflow did not converge in {maxiter} Newton iterations (ct={ct!r}, mu={mu!r})",
            residual=float(np.max(np.abs(step) / scale)), tolerance=tol, iterations=maxiter)
    return float(lam) if lam.ndim == 0 else lam


def wake_skew(mu: ArrayLike, lam: ArrayLike) -> float | NDArray[np.float64]:
    """Wake skew angle ``chi = atan2(mu, lambda)``, rad.

    0 in hover (wake straight down), pi/2 for an edgewise wake
    (``lambda -> 0``), untilted disc [Leishman2006].

    Parameters
    ----------
    mu : array_like
        Advance ratio, >= 0.
    lam : array_like
        Inflow ratio through the disc, positive downwards.

    Returns
    -------
    float or ndarray
        chi, rad.
    """
    chi = np.arctan2(np.asarray(mu, dtype=np.float64), np.asarray(lam, dtype=np.float64))
    return float(chi) if chi.ndim == 0 else chi


def kx_factor(model: str, mu: ArrayLike, lam: ArrayLike) -> float | NDArray[np.float64]:
    """Longitudinal inflow gradient ``k_x`` of a linear inflow model.

    =========== ======================================== =================================
    model       k_x                                      source
    =========== ======================================== =================================
    uniform     0                                        --
    glauert     1.2 for mu > 0, 0 in hover               [Glauert1926], [Johnson1980]
    drees       4/3 (1 - cos chi - 1.8 mu^2) / sin chi   [Drees1949], [Leishman2006]
    pitt-peters 15 pi / 32 tan(chi/2)                    [PittPeters1981], [Chen1990]
    coleman     tan(chi/2)                               [Coleman1945], [Leishman2006]
    =========== ======================================== =================================

    ``chi = atan2(mu, lam)`` is the wake skew angle.  All models give 0 in
    hover (mu = 0), where no direction on the disc is preferred; Glauert's
    constant is meant for forward flight and is switched off at mu = 0 only,
    so it jumps from 0 to 1.2 as soon as mu > 0.  Drees's expression is
    evaluated as ``4/3 (tan(chi/2) - 1.8 mu sqrt(mu^2 + lam^2))``, identical
    for ``chi = atan2(mu, lam)`` and free of the 0/0 in hover.

    Parameters
    ----------
    model : str
        One of :data:`INFLOW_MODELS`.
    mu : array_like
        Advance ratio, >= 0.
    lam : array_like
        Mean inflow ratio through the disc, positive downwards.

    Returns
    -------
    float or ndarray
        k_x, -; a float for scalar inputs.

    Raises
    ------
    ValueError
        For an unknown ``model`` (the message lists the allowed names).
    """
    if not isinstance(model, str) or model not in INFLOW_MODELS:
        raise ValueError(f"unknown inflow model {model!r}; allowed: {', '.join(INFLOW_MODELS)}")
    mu_a = np.asarray(mu, dtype=np.float64)
    lam_a = np.asarray(lam, dtype=np.float64)
    mu_a, lam_a = np.broadcast_arrays(mu_a, lam_a)
    chi = np.arctan2(mu_a, lam_a)
    if model == "uniform":
        kx = np.zeros_like(chi)
    elif model == "glauert":
        kx = np.where(mu_a > 0, GLAUERT_KX, 0.0)
    elif model == "drees":
        kx = 4.0 / 3.0 * (np.tan(0.5 * chi) - 1.8 * mu_a * np.hypot(mu_a, lam_a))
    elif model == "pitt-peters":
        kx = PITT_PETERS_KX * np.tan(0.5 * chi)
    else:  # coleman
        kx = np.tan(0.5 * chi)
    return float(kx) if kx.ndim == 0 else kx


def mean_inflow(params: BladeParameters, mu: float) -> float:
    """Mean induced inflow ratio lambda_0 used by the blade model.

    ``params.inflow_ratio`` if it is not None; otherwise momentum theory with
    thrust = weight (:func:`thrust_coefficient`, :func:`momentum_inflow`, with the
    through-flow ``mu tan(params.shaft_tilt)`` of a tilted shaft);
    0 in vacuum (``air_density == 0``: no air, no induced velocity).

    Parameters
    ----------
    params : BladeParameters
    mu : float
        Advance ratio, >= 0.

    Returns
    -------
    float
        lambda_0, positive downwards, -.
    """
    mu_f = float(_check_nonneg("mu", mu))
    if params.inflow_ratio is not None:
        return float(params.inflow_ratio)
    if params.air_density == 0.0:
        return 0.0
    return float(momentum_inflow(thrust_coefficient(params), mu_f,
                                 through_flow=mu_f * math.tan(params.shaft_tilt)))


def induced_inflow(params: BladeParameters, mu: float, r_over_R: ArrayLike, psi: ArrayLike) -> NDArray[np.float64]:
    """Induced inflow ratio over the disc, ``lambda_0 (1 + k_x r cos psi)``.

    Parameters
    ----------
    params : BladeParameters
        Uses ``inflow_model`` and ``inflow_ratio`` (see :func:`mean_inflow`).
    mu : float
        Advance ratio, >= 0.
    r_over_R : array_like
        Non-dimensional radius r/R.
    psi : array_like
        Azimuth, rad; 0 = downstream (rear of the disc), pi/2 = advancing side.

    Returns
    -------
    ndarray
        lambda_i, positive downwards, -, of the broadcast shape of
        ``r_over_R`` and ``psi``.
    """
    lam0 = mean_inflow(params, mu)
    # the wake skew follows the whole flow through the disc, free stream included
    kx = float(kx_factor(params.inflow_model, mu, lam0 + mu * math.tan(params.shaft_tilt)))
    r = np.asarray(r_over_R, dtype=np.float64)
    p = np.asarray(psi, dtype=np.float64)
    return lam0 * (1.0 + kx * r * np.cos(p))
