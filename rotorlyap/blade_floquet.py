"""Floquet analysis of the blade: the standard linear cross-check of the direct method.

The blade's equations ``z' = h(psi, z)`` are linearised (:meth:`rotorlyap.Blade.jacobian`)
about a steady motion ``xi(psi)``, ``x' = J(psi) x`` with ``J(psi) = dh/dz(psi, xi(psi))``, and
the monodromy matrix of that periodic linear system is integrated over one revolution
(:func:`rotorlyap.floquet.floquet_multipliers`, sixth-order Magnus, 1024 steps by default:
the Jacobian has kinks where sections cross breakpoints of the airfoil model, and a fixed-step
method of high order copes with them far better than adaptive integration). Two steady
motions are offered:

``"periodic"``
    the true periodic solution of the forward-flight equations
    (:func:`rotorlyap.periodic_motion.periodic_motion`); in hover the equilibrium. Floquet
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
:func:`rotorlyap.derived.modes_from_jacobian`); the dominant hinge at every advance ratio is
recorded too. A fine grid (steps of 0.025 or less) keeps the matching unambiguous.

Damping is given as the growth rate ``sigma`` (per rev; negative = decaying, independent of
the branch) and as the damping ratio ``-sigma / |eta|`` (which depends on the branch).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import linear_sum_assignment

from .blade import Blade
from .floquet import FloquetResult, floquet_multipliers
from .parameters import BladeParameters

__all__ = [
    "HINGES", "STEADY_CHOICES", "BladeFloquetPoint", "FloquetSweep", "blade_floquet",
    "floquet_sweep", "TabulatedMotion", "tabulate_motion", "steady_motion",
]

TWO_PI = 2.0 * np.pi

#: Hinge names in the order of the state vector.
HINGES = ("flap", "lag", "pitch")

#: The steady motions :func:`blade_floquet` linearises about.
STEADY_CHOICES = ("periodic", "hover")

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
        :func:`rotorlyap.floquet.floquet_multipliers`)."""
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


@dataclass(frozen=True)
class TabulatedMotion:
    """A periodic steady motion as a piecewise cubic Hermite interpolant: fast to evaluate.

    :class:`rotorlyap.periodic_motion.PeriodicMotion` evaluates its Fourier series with one
    complex exponential per harmonic and azimuth, several times the cost of the blade's
    right-hand side for the large batches of the sphere searches. This class samples ``xi``
    and ``xi'`` once on ``n`` uniform azimuths and interpolates them by the periodic cubic
    Hermite interpolant; :meth:`dxi` is the *exact derivative of the interpolant*, so that
    ``(xi, dxi)`` is a consistent, continuously differentiable steady motion and the disturbed
    equations about it are exact (a certificate about it is a certificate for the blade). It
    differs from the series by ``max_error`` (of order ``h**4`` times the fourth derivative,
    ``h = 2 pi / n``).

    Attributes
    ----------
    values, slopes : numpy.ndarray
        ``xi`` and ``xi'`` on the grid ``2 pi j / n``, shape (n, 6).
    max_error : float
        Largest ``|xi_interpolated - xi|`` found at the grid midpoints (rad, rad/rad).
    """

    values: np.ndarray
    slopes: np.ndarray
    max_error: float

    def _eval(self, psi, derivative: bool) -> np.ndarray:
        psi = np.asarray(psi, dtype=float)
        n = self.values.shape[0]
        h = TWO_PI / n
        u = np.mod(psi, TWO_PI) / h
        j = np.minimum(np.floor(u).astype(int), n - 1)
        t = (u - j)[..., None]
        j1 = (j + 1) % n
        P0, P1 = self.values[j], self.values[j1]
        D0, D1 = h * self.slopes[j], h * self.slopes[j1]
        t2 = t * t
        if derivative:
            return ((6 * t2 - 6 * t) * (P0 - P1) + (3 * t2 - 4 * t + 1) * D0 + (3 * t2 - 2 * t) * D1) / h
        t3 = t2 * t
        return ((2 * t3 - 3 * t2 + 1) * P0 + (t3 - 2 * t2 + t) * D0 + (-2 * t3 + 3 * t2) * P1
                + (t3 - t2) * D1)

    def xi(self, psi) -> np.ndarray:
        """The interpolated motion, shape ``psi.shape + (6,)``."""
        return self._eval(psi, False)

    def dxi(self, psi) -> np.ndarray:
        """The derivative of the interpolant, shape ``psi.shape + (6,)``."""
        return self._eval(psi, True)

    @property
    def steady(self) -> tuple:
        """``(xi, dxi)``, the form :func:`rotorlyap.stability.blade_stability` takes."""
        return (self.xi, self.dxi)


def tabulate_motion(xi, dxi, n: int = 4096) -> TabulatedMotion:
    """:class:`TabulatedMotion` of the steady motion ``(xi, dxi)`` on ``n`` azimuths."""
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 8:
        raise ValueError(f"n must be an integer >= 8, got {n!r}")
    grid = TWO_PI * np.arange(n) / n
    tab = TabulatedMotion(values=np.asarray(xi(grid), dtype=float), slopes=np.asarray(dxi(grid), dtype=float),
                          max_error=0.0)
    mid = grid + 0.5 * TWO_PI / n
    err = float(np.abs(tab.xi(mid) - np.asarray(xi(mid))).max())
    return TabulatedMotion(values=tab.values, slopes=tab.slopes, max_error=err)


def steady_motion(params: BladeParameters, mu: float, steady: str = "periodic"):
    """``(xi, dxi)`` callables of the chosen steady motion, or raise
    :class:`rotorlyap.periodic_motion.PeriodicMotionError` if no periodic motion is found."""
    if steady not in STEADY_CHOICES:
        raise ValueError(f"steady must be one of {STEADY_CHOICES}, got {steady!r}")
    if steady == "hover" or mu == 0.0:
        xi = Blade(params, 0.0).equilibrium()
        return (lambda psi: np.broadcast_to(xi, np.shape(psi) + (6,)).copy(),
                lambda psi: np.zeros(np.shape(psi) + (6,)))
    from .periodic_motion import periodic_motion

    return periodic_motion(params, mu).steady


def blade_floquet(params: BladeParameters, mu: float, *, steady: str = "periodic",
                  motion=None, n_steps: int = DEFAULT_N_STEPS, constant_shortcut: bool = True
                  ) -> BladeFloquetPoint:
    """Floquet multipliers of the blade linearised about its steady motion at ``mu``.

    Parameters
    ----------
    params : BladeParameters
        The blade (a ``None`` collective is trimmed in hover and kept).
    mu : float
        Advance ratio (>= 0).
    steady : {"periodic", "hover"}
        The steady motion (module docstring).
    motion : (callable, callable), optional
        ``(xi, dxi)`` to use instead of computing it (e.g. a
        :attr:`rotorlyap.periodic_motion.PeriodicMotion.steady` already at hand).
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
    from .periodic_motion import PeriodicMotionError

    mu = float(mu)
    if not (np.isfinite(mu) and mu >= 0.0):
        raise ValueError(f"mu must be an advance ratio >= 0, got {mu!r}")
    blade = Blade(params, mu)
    try:
        xi, _ = motion if motion is not None else steady_motion(params, mu, steady)
    except PeriodicMotionError as exc:
        return _not_found(mu, steady, str(exc))
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
    return BladeFloquetPoint(mu=mu, steady=steady, found=True, message="", multipliers=m.astype(complex),
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
                  n_steps: int = DEFAULT_N_STEPS, motions: dict | None = None) -> FloquetSweep:
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
        ``{mu: (xi, dxi)}`` periodic motions already computed (others are computed); a string
        or an exception as the value records a failure (no periodic motion) without retrying.

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
            pt = blade_floquet(params, m_, steady=steady, motion=motion, n_steps=n_steps)
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
