"""Time-domain validation of the direct method: certificates against simulated motions.

A certificate of technical stability (:func:`rotorlyap.technical_stability`, strict reading)
says: every motion that starts at the azimuth ``psi_j`` with ``||x|| < lambda0_j`` stays within
``||x|| < A`` for ever. This module measures such statements against the motion itself, by
simulating the full nonlinear disturbed equations (:func:`rotorlyap.simulate`, many motions
at once) from deterministic, seeded sets of initial disturbances, inside and outside the
certified start regions, and tabulating *certified* against *observed bounded* (a confusion
matrix per Liapunov function). "Observed bounded" means: stayed within the bound ``A`` over
the simulated periods; a motion that reaches ``||x|| = A`` is stopped there
(:func:`simulate_within`), since its verdict is then known.

Where a reading marks instability, :func:`long_run` follows single motions for longer, with
a generous escape radius, and :func:`classify_motion` says what they do: grow without bound,
settle on a limit cycle (inside or outside ``A``), or stay bounded all along.

Everything is deterministic: the same arguments give the same motions and counts.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Mapping

import numpy as np

from .lyapunov import TechnicalStabilityResult
from .sampling import unit_sphere_points
from .simulation import scaled_norm, simulate

__all__ = [
    "BoundedRuns", "simulate_within", "start_directions", "Validation", "validate",
    "confusion_matrix", "certified_mask", "MotionHistory", "long_run", "classify_motion",
    "last_revolution",
]

TWO_PI = 2.0 * np.pi

#: Default tolerances of the validation simulations (DOP853). Loose enough for many motions
#: at once; a motion's verdict (left ``A`` or not) changes only for motions that graze ``A``.
DEFAULT_RTOL, DEFAULT_ATOL = 1e-6, 1e-9


# --------------------------------------------------------------------------------------
# Simulation until a motion leaves the ball
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class BoundedRuns:
    """Outcome of :func:`simulate_within`.

    Attributes
    ----------
    max_norm : numpy.ndarray
        Largest scaled norm seen at the output azimuths (``A`` for a motion that left), (m,).
    left : numpy.ndarray
        Boolean: the motion reached ``||x|| = A`` (or started outside), (m,).
    psi_left : numpy.ndarray
        Azimuth at which it was found outside (last output azimuth before the event; NaN if it
        stayed inside), (m,).
    n_periods : float
        Periods simulated for the motions that stayed inside.
    n_restarts : int
        Integrations started (one more per group of motions that left).
    """

    max_norm: np.ndarray
    left: np.ndarray
    psi_left: np.ndarray
    n_periods: float
    n_restarts: int


def simulate_within(f: Callable, x0, psi0: float, n_periods: float, A: float, *, scales=None,
                    period: float = TWO_PI, points_per_period: int = 32,
                    rtol: float = DEFAULT_RTOL, atol: float = DEFAULT_ATOL) -> BoundedRuns:
    """Simulate many motions and stop each one when it leaves ``||x|| <= A``.

    :func:`rotorlyap.simulate` stops the whole integration when one motion escapes; here the
    motions that left are removed and the others are restarted from the last output azimuth
    before the event, until ``n_periods`` have passed.

    Parameters
    ----------
    f : callable
        Vectorised disturbed right-hand side ``f(psi, x)``.
    x0 : array_like
        Initial disturbances, shape ``(m, n)``.
    psi0 : float
        Initial azimuth.
    n_periods : float
        Periods to simulate.
    A : float
        The bound of the scaled norm.
    scales : array_like, optional
        The ``a_i`` of the norm.
    period, points_per_period, rtol, atol
        As :func:`rotorlyap.simulate`.

    Returns
    -------
    BoundedRuns
    """
    x0 = np.atleast_2d(np.asarray(x0, dtype=float))
    m, n = x0.shape
    a = np.ones(n) if scales is None else np.asarray(scales, dtype=float)
    A = float(A)
    norm0 = scaled_norm(x0, a)
    max_norm = norm0.copy()
    left = norm0 > A
    psi_left = np.where(left, psi0, np.nan)
    active = np.flatnonzero(~left)
    x = x0.copy()
    psi, end = float(psi0), float(psi0) + n_periods * period
    restarts = 0
    while active.size and end - psi > 1e-9 * period:
        restarts += 1
        s = simulate(f, x[active], psi, (end - psi) / period, period=period, scales=a,
                     points_per_period=points_per_period, escape=A, rtol=rtol, atol=atol)
        max_norm[active] = np.maximum(max_norm[active], s.max_norm)
        done = s.psi[-1] >= end - 1e-9 * period
        if not s.escaped.any():
            if not done and s.psi[-1] <= psi:
                raise RuntimeError(f"simulate_within made no progress at psi = {psi:.6g}")
            x[active] = s.x[-1]
            psi = float(s.psi[-1])
            if done:
                break
            continue
        gone = active[s.escaped]
        left[gone] = True
        max_norm[gone] = np.maximum(max_norm[gone], A)
        psi_left[gone] = s.psi[-1]
        keep = ~s.escaped
        x[active[keep]] = s.x[-1][keep]
        active = active[keep]
        psi = float(s.psi[-1])
    return BoundedRuns(max_norm=max_norm, left=left, psi_left=psi_left, n_periods=float(n_periods),
                       n_restarts=restarts)


def start_directions(n: int, dim: int = 6, seed: int = 1) -> np.ndarray:
    """``n`` deterministic unit directions (scaled coordinates) from a scrambled Sobol'
    sequence with the given seed (:func:`rotorlyap.methods.sampling.unit_sphere_points` without its
    structured part), shape ``(n, dim)``."""
    pts = unit_sphere_points(dim, max(n, 2), seed)
    structured = 2 * dim + 2 * dim * (dim - 1)
    return np.array(pts[structured:structured + n])


# --------------------------------------------------------------------------------------
# Certificates against motions
# --------------------------------------------------------------------------------------


def certified_mask(result: TechnicalStabilityResult, psi_index: np.ndarray, radius: np.ndarray) -> np.ndarray:
    """Which starts ``(psi_j, ||x0|| = radius)`` the result covers: ``stable[j]`` and
    ``radius < lambda0[j]``. For a practical-reading result this is the set where the indicator
    passes (not a certificate)."""
    psi_index = np.asarray(psi_index, dtype=int)
    radius = np.asarray(radius, dtype=float)
    return np.asarray(result.stable)[psi_index] & (radius < np.asarray(result.lambda0)[psi_index])


def confusion_matrix(covered: np.ndarray, bounded: np.ndarray) -> np.ndarray:
    """2 x 2 counts: rows covered (certified or indicated) yes / no, columns observed bounded
    yes / no. ``[[covered & bounded, covered & left], [not covered & bounded, not covered &
    left]]``; the four add up to the number of motions."""
    c = np.asarray(covered, dtype=bool)
    b = np.asarray(bounded, dtype=bool)
    if c.shape != b.shape:
        raise ValueError(f"covered and bounded must have the same shape, got {c.shape} and {b.shape}")
    return np.array([[np.sum(c & b), np.sum(c & ~b)], [np.sum(~c & b), np.sum(~c & ~b)]], dtype=int)


@dataclass(frozen=True)
class Validation:
    """Simulated motions from many starts, with the verdicts of several Liapunov functions.

    Attributes
    ----------
    label : str
        Case and flight condition.
    A : float
        The bound of the observation: bounded means ``max ||x|| <= A`` over the run.
    n_periods : float
        Periods simulated.
    psi : numpy.ndarray
        The azimuth grid of the results, shape (n_psi,).
    psi_index : numpy.ndarray
        Start azimuth of each motion, as an index into ``psi``, shape (N,).
    radius : numpy.ndarray
        Start norm ``||x0||``, shape (N,).
    x0 : numpy.ndarray
        Start disturbances, shape (N, 6).
    max_norm : numpy.ndarray
        Largest norm seen (``A`` for a motion stopped on leaving), shape (N,).
    bounded : numpy.ndarray
        Observed bounded, shape (N,).
    names : tuple of str
        The Liapunov functions (keys of the results).
    readings : tuple of str
        ``"strict"`` (certificate) or ``"practical"`` (indicator) per name.
    covered : numpy.ndarray
        Boolean, shape (len(names), N): certified (strict) or passing the indicator (practical).
    A_used : numpy.ndarray
        Each result's bound after step 3, shape (len(names),).
    n_restarts : int
        Integrations run.
    """

    label: str
    A: float
    n_periods: float
    psi: np.ndarray
    psi_index: np.ndarray
    radius: np.ndarray
    x0: np.ndarray
    max_norm: np.ndarray
    bounded: np.ndarray
    names: tuple
    readings: tuple
    covered: np.ndarray
    A_used: np.ndarray
    n_restarts: int = field(default=0, compare=False)

    def confusion(self, name: str) -> np.ndarray:
        """:func:`confusion_matrix` of the function ``name``."""
        return confusion_matrix(self.covered[self.names.index(name)], self.bounded)

    def violations(self, name: str) -> int:
        """Certified motions that went beyond the certified bound ``A_used`` (must be 0 for a
        strict certificate; for a practical indicator, the false alarms of "stable")."""
        k = self.names.index(name)
        return int(np.sum(self.covered[k] & (self.max_norm > self.A_used[k] * (1 + 1e-9))))

    @property
    def n(self) -> int:
        """Number of motions."""
        return int(self.radius.size)


def validate(f: Callable, results: Mapping[str, TechnicalStabilityResult], *, label: str = "",
             psi_indices=(0,), fractions=(0.1, 0.25, 0.5, 0.75, 1.0), lambda0_fractions=(0.5, 0.99),
             n_directions: int = 16, n_periods: float = 10.0, A: float | None = None, seed: int = 1,
             rtol: float = DEFAULT_RTOL, atol: float = DEFAULT_ATOL) -> Validation:
    """Simulate from many starts and compare with the verdicts of several results.

    The starts at each azimuth ``psi_j`` (``j`` in ``psi_indices``) are ``n_directions``
    seeded directions (:func:`start_directions`) times the radii ``fractions * A`` and, for
    every result stable at ``psi_j`` (certified, or indicated in the practical reading),
    ``lambda0_fractions * lambda0_j`` (so that each start region is probed just inside its
    edge). All results must share the
    azimuth grid and the norm scales.

    Parameters
    ----------
    f : callable
        The disturbed right-hand side the results were computed for.
    results : mapping of str to TechnicalStabilityResult
        The verdicts to compare (any reading).
    label : str
        Stored in the result.
    psi_indices : sequence of int
        Start azimuths, as indices into the results' grid.
    fractions : sequence of float
        Start radii relative to ``A``.
    lambda0_fractions : sequence of float
        Start radii relative to each certified ``lambda0_j``.
    n_directions : int
        Directions per radius.
    n_periods : float
        Periods simulated.
    A : float, optional
        The observation bound; default the requested bound of the first result.
    seed : int
        Seed of the directions.
    rtol, atol : float
        Tolerances of the integrator.

    Returns
    -------
    Validation
    """
    if not results:
        raise ValueError("give at least one result")
    names = tuple(results)
    first = results[names[0]]
    psi = np.asarray(first.psi)
    scales = np.asarray(first.scales)
    for name in names:
        r = results[name]
        if r.psi.shape != psi.shape or not np.allclose(r.psi, psi) or not np.allclose(r.scales, scales):
            raise ValueError(f"result {name!r} has another azimuth grid or other scales")
    A = float(first.A_requested if A is None else A)
    dirs = start_directions(n_directions, scales.size, seed)
    p_idx, rad, starts = [], [], []
    max_norm, bounded = [], []
    restarts = 0
    for j in psi_indices:
        radii = [fr * A for fr in fractions]
        for name in names:
            r = results[name]
            if r.stable[j]:
                radii += [fr * float(r.lambda0[j]) for fr in lambda0_fractions]
        radii = np.unique(np.round(np.asarray(radii, dtype=float), 12))
        x0 = (radii[:, None, None] * dirs[None, :, :]).reshape(-1, scales.size) * scales
        run = simulate_within(f, x0, float(psi[j]), n_periods, A, scales=scales, rtol=rtol, atol=atol)
        restarts += run.n_restarts
        p_idx.append(np.full(x0.shape[0], j))
        rad.append(np.repeat(radii, dirs.shape[0]))
        starts.append(x0)
        max_norm.append(run.max_norm)
        bounded.append(~run.left)
    p_idx = np.concatenate(p_idx)
    rad = np.concatenate(rad)
    covered = np.array([certified_mask(results[nm], p_idx, rad) for nm in names])
    return Validation(
        label=label, A=A, n_periods=float(n_periods), psi=psi, psi_index=p_idx, radius=rad,
        x0=np.concatenate(starts), max_norm=np.concatenate(max_norm), bounded=np.concatenate(bounded),
        names=names, readings=tuple(results[nm].reading for nm in names), covered=covered,
        A_used=np.array([results[nm].A for nm in names], dtype=float), n_restarts=restarts,
    )


# --------------------------------------------------------------------------------------
# What the motion does
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class MotionHistory:
    """Long simulations of a few motions, with their per-revolution peaks and a verdict.

    Attributes
    ----------
    label : str
    psi : numpy.ndarray
        Output azimuths, shape (k,).
    x : numpy.ndarray
        Disturbed states, shape (k, m, 6).
    norm : numpy.ndarray
        Scaled norms, shape (k, m).
    peaks : numpy.ndarray
        Largest norm in each full revolution, shape (n_rev, m).
    escaped : numpy.ndarray
        Boolean, shape (m,).
    verdict : tuple of str
        :func:`classify_motion` per motion.
    A : float
        The bound used in the verdicts.
    """

    label: str
    psi: np.ndarray
    x: np.ndarray
    norm: np.ndarray
    peaks: np.ndarray
    escaped: np.ndarray
    verdict: tuple
    A: float


def classify_motion(peaks: np.ndarray, A: float, escaped: bool, *, n_tail: int = 4,
                    rel_spread: float = 0.02) -> str:
    """What one motion does, from its per-revolution peak norms.

    * ``"unbounded"``: it passed the escape radius;
    * ``"decays within A"``: it stayed within ``A`` and its last peak is below its first;
    * ``"limit cycle outside A"`` / ``"limit cycle within A"``: the last ``n_tail`` peaks agree
      to ``rel_spread`` (relative) and do not decay to zero, with the level above / below ``A``;
    * ``"bounded, not settled"``: none of these.
    """
    peaks = np.asarray(peaks, dtype=float)
    if escaped:
        return "unbounded"
    tail = peaks[-n_tail:]
    level = float(tail.mean())
    if peaks.max() <= A and tail[-1] < peaks[0] and (tail[-1] < 0.5 * peaks[0] or np.ptp(tail) > rel_spread * level):
        return "decays within A"
    if level > 0 and np.ptp(tail) <= rel_spread * level:
        return "limit cycle " + ("outside A" if level > A else "within A")
    return "bounded, not settled"


def long_run(f: Callable, x0, psi0: float, n_periods: int, *, A: float = 1.0, scales=None,
             label: str = "", escape: float = 1000.0, points_per_period: int = 64,
             rtol: float = 1e-5, atol: float = 1e-8) -> MotionHistory:
    """Follow a few motions for ``n_periods`` revolutions and classify them.

    The tolerances are looser than :func:`simulate_within`'s: a motion that grows into stall
    meets the kinks of the airfoil model at every revolution, and the verdict (growth, limit
    cycle or decay) does not hinge on the last digits.
    """
    s = simulate(f, x0, psi0, n_periods, scales=scales, points_per_period=points_per_period,
                 escape=escape, rtol=rtol, atol=atol)
    k = points_per_period
    n_rev = (s.norm.shape[0] - 1) // k
    peaks = np.array([s.norm[i * k:(i + 1) * k + 1].max(axis=0) for i in range(n_rev)]) if n_rev \
        else s.norm.max(axis=0, keepdims=True)
    verdict = tuple(classify_motion(peaks[:, i], A, bool(s.escaped[i])) for i in range(s.norm.shape[1]))
    return MotionHistory(label=label, psi=s.psi, x=s.x, norm=s.norm, peaks=peaks, escaped=s.escaped,
                         verdict=verdict, A=float(A))


def last_revolution(history: MotionHistory, offset=None, index: int = 0) -> Callable:
    """The last full revolution of one motion of ``history`` as a function of azimuth.

    Parameters
    ----------
    history : MotionHistory
        From :func:`long_run`.
    offset : array_like, optional
        The steady state the disturbances are measured from (shape ``(6,)``): the result is
        ``offset + x``, the blade's own states. Default: 0.
    index : int
        Which motion.

    Returns
    -------
    callable
        ``g(psi)`` -> states of shape ``psi.shape + (n,)``, a cubic interpolant of the last
        revolution with ``psi`` taken modulo the period: a start for
        :func:`rotorlyap.model.steady.periodic_motion` when a simulation has settled onto
        a periodic motion that Newton's method does not reach from the hover equilibrium.
    """
    from scipy.interpolate import CubicSpline

    step = history.psi[1] - history.psi[0]
    k = int(round(TWO_PI / step))
    if history.psi.size < k + 1:
        raise ValueError("last_revolution: the history is shorter than one revolution")
    psi = history.psi[-k - 1:]
    states = history.x[-k - 1:, index]
    if offset is not None:
        states = states + np.asarray(offset, dtype=float)
    spline = CubicSpline(psi, states, axis=0)
    psi0 = float(psi[0])
    return lambda az: spline(psi0 + np.mod(np.asarray(az, dtype=float) - psi0, TWO_PI))
