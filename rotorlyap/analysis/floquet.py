"""Floquet analysis of the blade: the standard linear cross-check of the direct method.

The blade's equations ``z' = h(psi, z)`` are linearised (:meth:`rotorlyap.Blade.jacobian`)
about a steady motion ``xi(psi)``, ``x' = J(psi) x`` with ``J(psi) = dh/dz(psi, xi(psi))``, and
the monodromy matrix of that periodic linear system is integrated over one revolution
(:func:`rotorlyap.methods.floquet.floquet_multipliers`, sixth-order Magnus, 1024 steps by default:
the Jacobian has kinks where sections cross breakpoints of the airfoil model, and a fixed-step
method of high order copes with them far better than adaptive integration). Two steady
motions are offered:

``"periodic"``
    the true periodic solution of the forward-flight equations
    (:func:`rotorlyap.model.steady.periodic_motion`); in hover the equilibrium. Floquet
    theory then decides the (local, asymptotic) stability of that motion.
``"hover"``
    the paper's choice: the hover equilibrium reused at every advance ratio. In forward flight
    it is *not* a solution of the equations, so the Floquet multipliers of ``J`` along it
    describe the linearisation about a state the blade does not stay in; they are shown for
    comparison only.

Modes, frequencies and the branch
---------------------------------
A multiplier ``m = exp(2 pi eta)`` fixes the characteristic exponent ``eta = sigma + i omega``
(per rev) only modulo ``i``: ``omega`` is known modulo 1/rev. In hover (constant ``J``) the
exponents are the eigenvalues of ``J`` and the frequencies are the true ones. For ``mu > 0``
the branch is resolved *by continuity from hover*: the exponents are followed along the
advance-ratio grid, each multiplier being matched to one of the previous point
(:func:`scipy.optimize.linear_sum_assignment` on the distance between multipliers plus one
minus the modal assurance criterion of their eigenvectors, the state at ``psi = 0`` of the
Floquet mode), and the integer ``k`` of ``omega = Im(log m) / (2 pi) + k`` chosen closest to
the previous frequency of that track. Each track keeps the name it had in hover, where it is
named after the hinge whose angle dominates its eigenvector (flap, lag or pitch, as
:func:`rotorlyap.model.modes.modes_from_jacobian`); the dominant hinge at every advance ratio is
recorded too. A fine grid (steps of 0.025 or less) keeps the matching unambiguous.

Damping is given as the growth rate ``sigma`` (per rev; negative = decaying, independent of
the branch) and as the damping ratio ``-sigma / |eta|`` (which depends on the branch).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import linear_sum_assignment

from ..conventions import HINGES, TWO_PI
from ..errors import PeriodicMotionError
from ..methods.floquet import FloquetResult, floquet_multipliers
from ..model.blade import Blade
from ..model.parameters import BladeParameters
from ..model.steady import as_steady_motion, steady_motion

__all__ = ["BladeFloquetPoint", "FloquetSweep", "blade_floquet", "floquet_sweep"]

#: Magnus steps per period (see the module docstring).
DEFAULT_N_STEPS = 1024


@dataclass(frozen=True)
class BladeFloquetPoint:
    """Floquet analysis of the blade at one advance ratio.

    Attributes
    ----------
    mu : float
        Advance ratio.
    steady : str
        ``"periodic"`` or ``"hover"`` (module docstring).
    found : bool
        False when no periodic motion was found (``"periodic"`` only); the arrays are then NaN.
    message : str
        Empty, or why no result.
    multipliers : numpy.ndarray
        Floquet multipliers, complex, shape (6,), in the order of :attr:`eigenvectors`.
    exponents : numpy.ndarray
        Principal characteristic exponents ``log(m) / (2 pi)``, per rev (for hover: the
        eigenvalues of ``J``).
    eigenvectors : numpy.ndarray
        Eigenvectors of the monodromy matrix (columns), unit length, complex, shape (6, 6).
    dominant : tuple of str
        Dominant hinge of each eigenvector (largest of the three angle amplitudes).
    spectral_radius : float
        ``max |m|``.
    floquet : FloquetResult or None
        The full result (monodromy matrix, accuracy checks).
    """

    mu: float
    steady: str
    found: bool
    message: str
    multipliers: np.ndarray
    exponents: np.ndarray
    eigenvectors: np.ndarray
    dominant: tuple
    spectral_radius: float
    floquet: FloquetResult | None = None

    @property
    def stable(self) -> bool:
        """Asymptotically stable: every multiplier inside the unit circle (with the margin of
        :func:`rotorlyap.methods.floquet.floquet_multipliers`)."""
        return bool(self.found and self.floquet is not None and self.floquet.stable)

    @property
    def max_growth_rate(self) -> float:
        """Largest growth rate, per rev: ``log(spectral_radius) / (2 pi)``."""
        return float(np.log(self.spectral_radius) / TWO_PI) if self.found else float("nan")

    def __repr__(self) -> str:  # short and stable
        if not self.found:
            return f"BladeFloquetPoint(mu={self.mu:.4g}, {self.steady}, not found)"
        return (f"BladeFloquetPoint(mu={self.mu:.4g}, {self.steady}, spectral_radius="
                f"{self.spectral_radius:.6g}, stable={self.stable})")


def _dominant(vectors: np.ndarray) -> tuple:
    amp = np.abs(vectors[:3, :])
    return tuple(HINGES[int(i)] for i in np.argmax(amp, axis=0))


def _not_found(mu: float, steady: str, message: str) -> BladeFloquetPoint:
    nan6 = np.full(6, np.nan + 0j)
    return BladeFloquetPoint(mu=mu, steady=steady, found=False, message=message,
                             multipliers=nan6, exponents=nan6, eigenvectors=np.full((6, 6), np.nan + 0j),
                             dominant=("",) * 6, spectral_radius=float("nan"), floquet=None)


def blade_floquet(params: BladeParameters, mu: float, *, steady="periodic",
                  n_steps: int = DEFAULT_N_STEPS, constant_shortcut: bool = True
                  ) -> BladeFloquetPoint:
    """Floquet multipliers of the blade linearised about its steady motion at ``mu``.

    Parameters
    ----------
    params : BladeParameters
        The blade (a ``None`` collective is trimmed in hover and kept).
    mu : float
        Advance ratio (>= 0).
    steady : {"periodic", "hover"} or a steady motion
        The steady motion to compute by name (module docstring), or one already at hand (a
        :class:`~rotorlyap.model.steady.SteadyMotion`, a
        :class:`~rotorlyap.model.steady.PeriodicMotion`, or anything
        :func:`~rotorlyap.model.steady.as_steady_motion` takes); a given motion is labelled
        ``"hover"`` if it is constant at ``mu > 0``, ``"periodic"`` otherwise.
    n_steps : int
        Magnus steps per revolution.
    constant_shortcut : bool
        In hover the Jacobian is constant: use ``expm`` exactly (True) or integrate it like a
        periodic one (False; a check of the integrator).

    Returns
    -------
    BladeFloquetPoint
        ``found=False`` (not an exception) if no periodic motion is found.
    """
    mu = float(mu)
    if not (np.isfinite(mu) and mu >= 0.0):
        raise ValueError(f"mu must be an advance ratio >= 0, got {mu!r}")
    blade = Blade(params, mu)
    if isinstance(steady, str):
        label = steady
        try:
            motion = steady_motion(params, mu, steady)
        except PeriodicMotionError as exc:
            return _not_found(mu, steady, str(exc))
    else:
        motion = as_steady_motion(steady, blade)
        label = "hover" if (motion.is_constant and mu > 0.0) else "periodic"
    xi = motion.xi
    if mu == 0.0 and not blade.has_cyclic and constant_shortcut:
        A = blade.jacobian(0.0, xi(np.zeros(1))[0])
        res = floquet_multipliers(A, TWO_PI)
    else:
        res = floquet_multipliers(lambda psi: blade.jacobian(psi, xi(psi)), TWO_PI, method="magnus6",
                                  n_steps=int(n_steps), vectorized=True)
    m, V = np.linalg.eig(res.monodromy)
    # order as the result (decreasing modulus), exponents from the result where they match
    order = np.argsort(-np.abs(m), kind="stable")
    m, V = m[order], V[:, order]
    if mu == 0.0 and not blade.has_cyclic and constant_shortcut:
        lam, W = np.linalg.eig(A)
        o = np.argsort(-lam.real, kind="stable")
        lam, W = lam[o], W[:, o]
        m, V, eta = np.exp(TWO_PI * lam), W, lam
    else:
        with np.errstate(divide="ignore"):
            eta = np.log(m.astype(complex)) / TWO_PI
    V = V / np.linalg.norm(V, axis=0)
    return BladeFloquetPoint(mu=mu, steady=label, found=True, message="", multipliers=m.astype(complex),
                             exponents=eta.astype(complex), eigenvectors=V.astype(complex),
                             dominant=_dominant(V), spectral_radius=float(res.spectral_radius),
                             floquet=res)


@dataclass(frozen=True)
class FloquetSweep:
    """Floquet modes of the blade followed over a grid of advance ratios.

    Attributes
    ----------
    case : str
        Label of the parameter set.
    steady : str
        ``"periodic"`` or ``"hover"``.
    mu : numpy.ndarray
        Advance ratios, shape (k,), starting at 0.
    names : tuple of str
        Name of each of the 6 tracks, from its dominant hinge in hover, with ``+``/``-`` for
        the two members of a complex pair and ``1``/``2`` for two real exponents of the same
        hinge (e.g. ``"pitch+"``, ``"lag1"``).
    growth_rate : numpy.ndarray
        ``sigma``, per rev, shape (k, 6); NaN where no steady motion was found.
    frequency : numpy.ndarray
        ``omega`` with the branch resolved by continuity, per rev, shape (k, 6).
    damping_ratio : numpy.ndarray
        ``-sigma / |eta|``, shape (k, 6).
    multipliers : numpy.ndarray
        Complex, shape (k, 6).
    dominant : numpy.ndarray
        Dominant hinge of each track at each advance ratio, strings, shape (k, 6).
    spectral_radius : numpy.ndarray
        Shape (k,).
    found : numpy.ndarray
        Boolean, shape (k,).
    messages : tuple of str
        Why no result, per advance ratio (empty strings where found).
    """

    case: str
    steady: str
    mu: np.ndarray
    names: tuple
    growth_rate: np.ndarray
    frequency: np.ndarray
    damping_ratio: np.ndarray
    multipliers: np.ndarray
    dominant: np.ndarray
    spectral_radius: np.ndarray
    found: np.ndarray
    messages: tuple

    def track(self, name: str) -> int:
        """Index of the track called ``name``."""
        return self.names.index(name)

    def modes(self, hinge: str) -> list[int]:
        """Tracks named after ``hinge`` with a non-negative hover frequency (one per mode)."""
        return [i for i, n in enumerate(self.names)
                if n.startswith(hinge) and not n.endswith("-")]

    @property
    def max_growth_rate(self) -> np.ndarray:
        """Largest growth rate at each advance ratio, per rev (NaN where not found)."""
        return np.log(self.spectral_radius) / TWO_PI


def _names(eta: np.ndarray, dominant: tuple) -> tuple:
    names = []
    for e, d in zip(eta, dominant):
        if abs(e.imag) > 1e-12:
            names.append(d + ("+" if e.imag > 0 else "-"))
        else:
            names.append(d)
    # number repeated names
    out = []
    for i, n in enumerate(names):
        if names.count(n) > 1:
            out.append(n + str(names[:i + 1].count(n)))
        else:
            out.append(n)
    return tuple(out)


def _mac(U: np.ndarray, V: np.ndarray) -> np.ndarray:
    """Modal assurance criterion between the columns of U and V (complex), shape (6, 6)."""
    num = np.abs(U.conj().T @ V) ** 2
    den = np.outer(np.sum(np.abs(U) ** 2, axis=0), np.sum(np.abs(V) ** 2, axis=0))
    return num / den


def floquet_sweep(params: BladeParameters, mu_values, *, steady: str = "periodic", case: str = "",
                  n_steps: int = DEFAULT_N_STEPS, motions: dict | None = None,
                  blades: dict | None = None) -> FloquetSweep:
    """Floquet modes along a grid of advance ratios, followed by continuity from hover.

    Parameters
    ----------
    params : BladeParameters
    mu_values : array_like
        Increasing advance ratios; the first must be 0 (hover names the tracks).
    steady : {"periodic", "hover"}
    case : str
        Label stored in the result.
    n_steps : int
        Magnus steps per revolution.
    motions : dict, optional
        ``{mu: motion}`` periodic motions already computed (any steady motion
        :func:`~rotorlyap.model.steady.as_steady_motion` takes; others are computed); a string
        or an exception as the value records a failure (no periodic motion) without retrying.
    blades : dict, optional
        ``{mu: BladeParameters}`` the blade at an advance ratio where it is not ``params`` (a trim's
        controls, shaft tilt and inflow: ``ForwardFlightTrim.params``); its motion then comes from
        ``motions``.

    Returns
    -------
    FloquetSweep
    """
    mu = np.asarray(mu_values, dtype=float)
    if mu.ndim != 1 or mu.size < 1 or mu[0] != 0.0 or np.any(np.diff(mu) <= 0):
        raise ValueError("mu_values must increase from 0")
    k = mu.size
    sig = np.full((k, 6), np.nan)
    om = np.full((k, 6), np.nan)
    mult = np.full((k, 6), np.nan + 0j)
    dom = np.full((k, 6), "", dtype=object)
    rho = np.full(k, np.nan)
    found = np.zeros(k, dtype=bool)
    msgs = []
    prev = None  # (multipliers, vectors, frequency) of the tracks
    names = None
    for i, m_ in enumerate(mu):
        motion = None if motions is None else motions.get(float(m_))
        if isinstance(motion, (str, Exception)):  # a failure recorded by the caller
            pt = _not_found(float(m_), steady, str(motion))
        else:
            here = params if blades is None else blades.get(float(m_), params)
            pt = blade_floquet(here, m_, steady=steady if motion is None else motion, n_steps=n_steps)
        msgs.append(pt.message)
        if not pt.found:
            continue
        found[i] = True
        rho[i] = pt.spectral_radius
        if prev is None:
            names = _names(pt.exponents, pt.dominant)
            perm = np.arange(6)
            freq = pt.exponents.imag.copy()
        else:
            cost = np.abs(prev[0][:, None] - pt.multipliers[None, :]) + (1.0 - _mac(prev[1], pt.eigenvectors))
            rows, cols = linear_sum_assignment(cost)
            perm = cols[np.argsort(rows)]
            principal = pt.exponents.imag[perm]
            freq = principal + np.round(prev[2] - principal)
        m_sorted = pt.multipliers[perm]
        V_sorted = pt.eigenvectors[:, perm]
        sig[i] = np.log(np.abs(m_sorted)) / TWO_PI
        om[i] = freq
        mult[i] = m_sorted
        dom[i] = [pt.dominant[j] for j in perm]
        prev = (m_sorted, V_sorted, freq)
    if names is None:
        names = tuple(f"mode{j}" for j in range(6))
    with np.errstate(invalid="ignore", divide="ignore"):
        zeta = -sig / np.hypot(sig, om)
    return FloquetSweep(case=case, steady=steady, mu=mu, names=names, growth_rate=sig, frequency=om,
                        damping_ratio=zeta, multipliers=mult, dominant=dom, spectral_radius=rho,
                        found=found, messages=tuple(msgs))
