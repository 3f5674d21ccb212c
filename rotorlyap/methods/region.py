"""The region of stable motion of a periodic system, found by simulation: the yardstick.

A Liapunov certificate says that motions started within a start region stay within a bound.
This module measures, by simulating the full nonlinear system, how large a disturbance the
system actually survives, the reference every certificate is measured against. It knows
nothing of the blade: the system is any ``x' = f(psi, x)``, periodic in ``psi`` with period
``period`` (``2 pi`` by default, one revolution of azimuth), with ``f`` vectorised over states
*and* azimuths, ``f(psi (m,), x (m, n)) -> (m, n)``.

Definition
----------
The state ``x`` is the disturbance from the steady motion (for the blade, the components
``(beta, zeta, theta, beta', zeta', theta')`` in rad and rad/rad, derivatives with respect to
the azimuth ``psi = Omega t``), measured in the scaled norm ``||x|| = |x / a|`` with the
scales ``a`` (:data:`rotorlyap.conventions.DEFAULT_SCALES` for the blade). A start ``x0`` at
the azimuth ``psi0`` is **stable** (it "returns") if, over a horizon of ``n_periods``
periods,

1. the motion never leaves the bound: ``||x(psi)|| <= bound`` at every step, and
2. it decays toward the steady motion: the largest ``||x||`` over its last period is at most
   ``decay`` times ``||x0||``.

The start ``x0 = 0`` (the steady motion itself) is stable if it stays within the bound.
Both conditions are checked at the integrator's steps (:data:`DEFAULT_STEPS_PER_PERIOD` per
period), where the norm is sampled.

Defaults, and why
-----------------
``bound`` = :data:`DEFAULT_BOUND` = 45 scaled units: 90 deg of flap or lag, 45 deg of pitch
for the blade's default scales. A motion that reaches it has left every range in which a hinge
angle can be called a disturbance (the blade stands vertical, or is pitched into deep stall),
and for the blade its verdict is not sensitive to the value where the region has an edge of
its own: measured (``python benchmarks/bench_region.py --bound``) on the Table I hovers
(forward and backward C.G.) and the trimmed helicopter at mu = 0.1, the extents along the
hinge angles and the lag rate are the same with the bound 45 and 90 (beyond the edge the
blade runs off to flap near 50 deg and lag near 65 deg, or further); only the extent along the
flap rate is set by the bound (a flap-rate start throws the blade to about twice its size in
scaled units: 22-25 units with the bound 45, 35-38 with 90), and a bound of 30 cuts into the
flap extents too. The bound must exceed every start amplitude.

``decay`` = :data:`DEFAULT_DECAY` = 0.5: the motion must have lost at least half its start
amplitude by its last period. A motion that wanders off slowly, or settles on a limit cycle
of comparable size, fails; a returning motion at the edge of the region, which lingers near
a saddle before it decays, still passes if the horizon allows for twice the linear decay
(the horizon of :func:`horizon`). A motion that grows slowly is caught too: on the Table I
blade with the backward C.G. (slowest linear decay -0.0067 per rev, horizon 34 revolutions) a
flap start just beyond the edge has its largest norm in its last revolution, and leaves the
bound within 100 revolutions. What the ratio cannot tell from a return is a limit cycle smaller
than ``decay`` times the start: the verdict says "came back to within half its start"; a
smaller ratio and a longer horizon (:func:`horizon` scales it with ``ln(1/decay)``) tighten
it.

The horizon (:func:`horizon`) follows from the linearised system's slowest decay rate
``sigma`` (largest real part of the Floquet exponents, per unit of ``psi``; the amplitude
changes by ``exp(period * sigma)`` per period): the number of periods in which the linear
motion shrinks by ``decay**2``, ``n = ceil(2 ln(1/decay) / (period |sigma|))``, at least 10 and
at most ``max_periods`` (100). The factor 2 leaves room for transient (non-normal) growth and
for the slower decay of a large motion.

The integrator
--------------
:func:`integrate_batch`: classical fourth-order Runge-Kutta with a fixed step, many motions at
once, each with its own start azimuth (``f`` is given one azimuth per state), so that all
motions of a search are one batch for a vectorised right-hand side. A motion found beyond the
bound (or not finite) is frozen there: it is taken out of the batch and no longer updated,
so it neither overflows nor slows the others. :data:`DEFAULT_STEPS_PER_PERIOD` = 64 steps per
period was chosen by measurement on the blade against scipy's DOP853 (relative tolerance
1e-9): see its docstring.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

__all__ = [
    "DEFAULT_BOUND", "DEFAULT_DECAY", "DEFAULT_STEPS_PER_PERIOD", "MAX_PERIODS", "MIN_PERIODS",
    "BatchRun", "RayExtent", "SliceMap", "Verdicts", "horizon", "integrate_batch",
    "ray_extent", "slice_map", "verdicts",
]

Function = Callable[[np.ndarray, np.ndarray], np.ndarray]

TWO_PI = 2.0 * np.pi

DEFAULT_BOUND = 45.0
"""Default bound of the scaled norm, -: 45 units (90 deg of flap or lag, 45 deg of pitch for
the blade's default scales; module docstring)."""

DEFAULT_DECAY = 0.5
"""Default decay ratio, -: the largest norm over the last period must be at most half the start
norm (module docstring)."""

DEFAULT_STEPS_PER_PERIOD = 64
"""Default RK4 steps per period. Measured on the blade (``python benchmarks/bench_region.py
--steps``): the starts that bracket each ray's extent (the last stable and first unstable
amplitude of the bisection, 0.7 % apart) and 0.9 and 1.1 times them, for the Table I hovers
with the forward and the backward C.G. and the trimmed helicopter at mu = 0.2 (144 starts),
integrated over the default horizon by RK4 and by DOP853 (rtol 1e-9, atol 1e-12, the norm
sampled at the same 64 azimuths per revolution). Off the edge (0.9 and 1.1 times) every verdict
agrees with DOP853's at 32, 64, 128 and 256 steps; on the 0.7 % bracket itself 32 steps change
8 verdicts, 64 steps 3 (all at mu = 0.2), 128 steps 1, 256 steps none. The extents found with 64
steps differ from those found with 256 (which agree with DOP853 on every bracket) by at most one
bisection bracket (0.72 %) on any ray, and not at all for the smallest extent over the
azimuths; 64 steps take a quarter of the time of 256. Largest relative difference of the peak
norms from DOP853's at 64 steps: 3e-3 in hover, 1.2e-2 at mu = 0.2 (motions at the edge)."""

MIN_PERIODS = 10
"""Shortest default horizon, periods (:func:`horizon`)."""

MAX_PERIODS = 100
"""Longest default horizon, periods (:func:`horizon`)."""


# --------------------------------------------------------------------------------------
# Checks
# --------------------------------------------------------------------------------------


def _positive(name: str, value) -> float:
    v = float(value)
    if not (math.isfinite(v) and v > 0.0):
        raise ValueError(f"{name} must be a finite number > 0, got {value!r}")
    return v


def _integer(name: str, value, least: int) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < least:
        raise ValueError(f"{name} must be an integer >= {least}, got {value!r}")
    return int(value)


def _decay(value) -> float:
    v = float(value)
    if not (0.0 < v < 1.0):
        raise ValueError(f"decay must lie in (0, 1), got {value!r}")
    return v


def _scales(scales, n: int) -> np.ndarray:
    a = np.ones(n) if scales is None else np.asarray(scales, dtype=float)
    if a.shape != (n,) or not np.all(np.isfinite(a)) or np.any(a <= 0.0):
        raise ValueError(f"scales must be {n} finite numbers > 0, got {np.asarray(scales).tolist()!r}")
    return a


def _azimuths(psi0, m: int | None = None) -> np.ndarray:
    p = np.asarray(psi0, dtype=float)
    if m is not None and p.ndim == 0:
        p = np.full(m, float(p))
    if p.ndim != 1 or (m is not None and p.shape != (m,)) or not np.all(np.isfinite(p)):
        want = "a finite number or shape (m,)" if m is not None else "finite, shape (p,)"
        raise ValueError(f"psi0 must be {want}, got shape {p.shape}")
    return p


# --------------------------------------------------------------------------------------
# The horizon
# --------------------------------------------------------------------------------------


def horizon(sigma: float, decay: float = DEFAULT_DECAY, *, period: float = TWO_PI,
            min_periods: int = MIN_PERIODS, max_periods: int = MAX_PERIODS) -> int:
    """Default horizon in periods from the linearised system's slowest decay rate.

    ``n = max(min_periods, ceil(2 ln(1/decay) / (period |sigma|)))``, at most ``max_periods``:
    the periods in which the linear motion shrinks by ``decay**2``.

    Parameters
    ----------
    sigma : float
        Largest real part of the Floquet exponents, per unit of ``psi`` (for the blade per rad
        of azimuth: the amplitude changes by ``exp(2 pi sigma)`` per revolution); < 0.
    decay : float
        The decay ratio of the definition, in (0, 1).
    period : float
        The period of the system, in units of ``psi`` (``2 pi``).
    min_periods, max_periods : int
        Limits of the horizon.

    Returns
    -------
    int

    Raises
    ------
    ValueError
        If ``sigma >= 0`` (the linearised system does not decay: no motion returns, the region
        is empty or not measured by this definition) or the other arguments are bad.
    """
    sigma = float(sigma)
    if not math.isfinite(sigma) or sigma >= 0.0:
        raise ValueError(f"the linearised system does not decay (largest Floquet real part sigma = {sigma!r} "
                         ">= 0): no horizon, and no region of returning motions, can be defined")
    decay = _decay(decay)
    period = _positive("period", period)
    lo = _integer("min_periods", min_periods, 1)
    hi = _integer("max_periods", max_periods, lo)
    n = math.ceil(2.0 * math.log(1.0 / decay) / (period * abs(sigma)))
    return int(min(hi, max(lo, n)))


# --------------------------------------------------------------------------------------
# The integrator
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class BatchRun:
    """Motions integrated by :func:`integrate_batch`.

    Attributes
    ----------
    x : numpy.ndarray
        State at the end of the horizon, or where the motion was frozen, shape (m, n), in the
        units of ``x0``.
    norm0 : numpy.ndarray
        Scaled norm of each start, shape (m,).
    peak : numpy.ndarray
        Largest scaled norm at the steps, shape (m,) (for a frozen motion: at the step where
        it was found beyond the bound).
    last_peak : numpy.ndarray
        Largest scaled norm at the steps of the last period (start of it included), shape (m,);
        NaN for a frozen motion.
    left : numpy.ndarray
        Boolean, shape (m,): found beyond the bound (or not finite), and frozen.
    psi_left : numpy.ndarray
        Azimuth at which it was found beyond the bound, NaN if it stayed within, shape (m,).
    n_steps : int
        Steps of the horizon.
    steps_per_period : int
        Steps per period.
    """

    x: np.ndarray
    norm0: np.ndarray
    peak: np.ndarray
    last_peak: np.ndarray
    left: np.ndarray
    psi_left: np.ndarray
    n_steps: int
    steps_per_period: int


def integrate_batch(f: Function, x0, psi0, n_periods: float, *, scales=None, bound: float = math.inf,
                    steps_per_period: int = DEFAULT_STEPS_PER_PERIOD, period: float = TWO_PI) -> BatchRun:
    """Integrate ``x' = f(psi, x)`` from many starts at once by fixed-step classical RK4.

    Each motion has its own start azimuth and advances by the same step
    ``h = period / steps_per_period``, so motion ``i`` is at ``psi0[i] + k h`` after ``k``
    steps. A motion whose scaled norm exceeds ``bound`` (or is not finite) at a step is frozen:
    removed from the batch, its state kept as found.

    Parameters
    ----------
    f : callable
        Right-hand side, ``f(psi (m,), x (m, n)) -> (m, n)``, vectorised over states and
        azimuths.
    x0 : array_like
        Starts, shape (m, n) (or (n,) for one motion).
    psi0 : float or array_like
        Start azimuth(s), one or shape (m,), in the units of ``period`` (rad for the blade).
    n_periods : float
        Horizon in periods (> 0); the steps are ``ceil(n_periods * steps_per_period)``.
    scales : array_like, optional
        Scales ``a`` of the norm ``|x / a|``, shape (n,), > 0; default ones.
    bound : float
        Freeze a motion when its scaled norm exceeds this (> 0; default: never).
    steps_per_period : int
        RK4 steps per period (>= 4).
    period : float
        The period (> 0).

    Returns
    -------
    BatchRun

    Raises
    ------
    ValueError
        Bad shapes or arguments, or ``f`` returning another shape than its ``x``.
    """
    x0 = np.asarray(x0, dtype=float)
    if x0.ndim == 1:
        x0 = x0[None, :]
    if x0.ndim != 2 or x0.shape[1] == 0:
        raise ValueError(f"x0 must have shape (m, n), got {x0.shape}")
    if not np.all(np.isfinite(x0)):
        raise ValueError("x0 must be finite")
    m, n = x0.shape
    p0 = _azimuths(psi0, m)
    n_periods = _positive("n_periods", n_periods)
    period = _positive("period", period)
    bound = float(bound)
    if not bound > 0.0:
        raise ValueError(f"bound must be > 0, got {bound!r}")
    steps = _integer("steps_per_period", steps_per_period, 4)
    inv_a = 1.0 / _scales(scales, n)
    h = period / steps
    n_steps = int(math.ceil(n_periods * steps - 1e-9))
    first_last = max(0, n_steps - steps)

    def norm(x):
        y = x * inv_a
        return np.sqrt(np.einsum("ij,ij->i", y, y))

    norm0 = norm(x0)
    x_out = x0.copy()
    peak = norm0.copy()
    last_peak = np.full(m, np.nan)
    left = ~(norm0 <= bound)
    psi_left = np.where(left, p0, np.nan)
    idx = np.flatnonzero(~left)
    xa, pa0 = x0[idx].copy(), p0[idx]
    peak_a = norm0[idx].copy()
    last_a = norm0[idx].copy() if first_last == 0 else np.zeros(idx.size)
    checked = False
    with np.errstate(over="ignore", invalid="ignore"):
        for k in range(n_steps):
            if idx.size == 0:
                break
            pa = pa0 + k * h
            ph = pa + 0.5 * h
            k1 = f(pa, xa)
            if not checked:
                k1 = np.asarray(k1, dtype=float)
                if k1.shape != xa.shape:
                    raise ValueError(f"f returned shape {k1.shape} for states of shape {xa.shape}")
                checked = True
            k2 = f(ph, xa + (0.5 * h) * k1)
            k3 = f(ph, xa + (0.5 * h) * k2)
            k4 = f(pa + h, xa + h * k3)
            xa = xa + (h / 6.0) * (k1 + 2.0 * (k2 + k3) + k4)
            na = norm(xa)
            np.maximum(peak_a, na, out=peak_a)
            if k + 1 >= first_last:
                np.maximum(last_a, na, out=last_a)
            out = ~(na <= bound)
            if out.any():
                gone = idx[out]
                x_out[gone] = xa[out]
                peak[gone] = np.where(np.isfinite(na[out]), na[out], np.inf)
                left[gone] = True
                psi_left[gone] = pa[out] + h
                keep = ~out
                idx, xa, pa0, peak_a, last_a = idx[keep], xa[keep], pa0[keep], peak_a[keep], last_a[keep]
    x_out[idx] = xa
    peak[idx] = peak_a
    last_peak[idx] = last_a
    return BatchRun(x=x_out, norm0=norm0, peak=peak, last_peak=last_peak, left=left, psi_left=psi_left,
                    n_steps=n_steps, steps_per_period=steps)


# --------------------------------------------------------------------------------------
# Verdicts
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Verdicts:
    """Stable or not, per start (module docstring, "Definition").

    Attributes
    ----------
    stable : numpy.ndarray
        Boolean, shape (m,): stayed within the bound and decayed to ``decay`` times its start
        norm over the last period.
    left : numpy.ndarray
        Boolean, shape (m,): left the bound.
    norm0, peak, last_peak : numpy.ndarray
        Start norm, largest norm and largest norm over the last period (NaN for a motion that
        left), scaled, shape (m,).
    """

    stable: np.ndarray
    left: np.ndarray
    norm0: np.ndarray
    peak: np.ndarray
    last_peak: np.ndarray


def verdicts(f: Function, x0, psi0, *, n_periods: float, scales=None, bound: float = DEFAULT_BOUND,
             decay: float = DEFAULT_DECAY, steps_per_period: int = DEFAULT_STEPS_PER_PERIOD,
             period: float = TWO_PI) -> Verdicts:
    """Which starts are stable, by the definition of the module docstring, in one batch.

    Parameters
    ----------
    f : callable
        ``f(psi (m,), x (m, n)) -> (m, n)``.
    x0 : array_like
        Starts (disturbances), shape (m, n).
    psi0 : float or array_like
        Start azimuth(s), one or shape (m,).
    n_periods : float
        Horizon, periods (>= 1, so that a last period exists).
    scales : array_like, optional
        Norm scales, shape (n,).
    bound : float
        Bound of the scaled norm (> 0).
    decay : float
        Decay ratio, in (0, 1).
    steps_per_period : int
        RK4 steps per period.
    period : float
        The period.

    Returns
    -------
    Verdicts
    """
    decay = _decay(decay)
    bound = _positive("bound", bound)
    if not float(n_periods) >= 1.0:
        raise ValueError(f"n_periods must be >= 1 (the verdict looks at the last period), got {n_periods!r}")
    run = integrate_batch(f, x0, psi0, n_periods, scales=scales, bound=bound,
                          steps_per_period=steps_per_period, period=period)
    with np.errstate(invalid="ignore"):
        decayed = run.last_peak <= decay * run.norm0
    stable = ~run.left & (decayed | (run.norm0 == 0.0))
    return Verdicts(stable=stable, left=run.left, norm0=run.norm0, peak=run.peak, last_peak=run.last_peak)


# --------------------------------------------------------------------------------------
# Extent along rays
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class RayExtent:
    """Result of :func:`ray_extent`: how far along each direction every start is stable.

    Attributes
    ----------
    directions : numpy.ndarray
        Unit directions in scaled coordinates, shape (k, n).
    psi0 : numpy.ndarray
        Start azimuths, shape (p,), units of ``period`` (rad).
    extent : numpy.ndarray
        Largest amplitude ``s`` (scaled norm) such that every start ``s' u`` on the grid up to
        ``s`` is stable, refined by bisection; ``s_max`` where every grid start is stable; 0
        where even the smallest is not (refined by bisection below it). Shape (k, p).
    upper : numpy.ndarray
        Smallest amplitude found unstable above ``extent`` (the bisection's other end; inf where
        the extent hit ``s_max``), shape (k, p).
    hit_s_max : numpy.ndarray
        Boolean, shape (k, p): every grid start was stable (the extent is at least ``s_max``).
    non_monotone : numpy.ndarray
        Boolean, shape (k, p): a grid amplitude above the first unstable one was stable again
        (the stable set along the ray is not an interval; ``extent`` is the first interval).
    amplitudes : numpy.ndarray
        The grid of amplitudes, scaled norm, shape (g,).
    grid_stable : numpy.ndarray
        Verdicts on the grid, shape (g, k, p).
    s_max, bound, decay : float
        Largest amplitude tried, bound and decay ratio of the definition.
    n_periods : float
        Horizon, periods.
    steps_per_period : int
        RK4 steps per period.
    scales : numpy.ndarray
        Norm scales, shape (n,).
    """

    directions: np.ndarray
    psi0: np.ndarray
    extent: np.ndarray
    upper: np.ndarray
    hit_s_max: np.ndarray
    non_monotone: np.ndarray
    amplitudes: np.ndarray
    grid_stable: np.ndarray
    s_max: float
    bound: float
    decay: float
    n_periods: float
    steps_per_period: int
    scales: np.ndarray

    @property
    def min_extent(self) -> np.ndarray:
        """Smallest extent over the start azimuths, per direction, shape (k,)."""
        return self.extent.min(axis=1)


def ray_extent(f: Function, directions, psi0, *, scales=None, s_max: float = 30.0, s_min: float | None = None,
               n_grid: int = 16, n_bisect: int = 6, n_periods: float, bound: float = DEFAULT_BOUND,
               decay: float = DEFAULT_DECAY, steps_per_period: int = DEFAULT_STEPS_PER_PERIOD,
               period: float = TWO_PI) -> RayExtent:
    """Extent of the stable starts along many rays, at many start azimuths, by batched simulation.

    First the grid: ``n_grid`` amplitudes spaced geometrically from ``s_min`` to ``s_max``, all
    directions x amplitudes x azimuths in one batch. Along each ray (direction and azimuth) the
    extent is bracketed between the last stable grid amplitude before the first unstable one
    and that unstable one (between 0 and ``s_min`` if the first is unstable), then bisected
    ``n_bisect`` times, all rays in one batch per step (at the geometric mean of the bracket;
    the arithmetic one below ``s_min``). Grid spacing ratio ``r = (s_max / s_min)**(1 / (n_grid -
    1))``: the extent is known to a factor ``r**(1 / 2**n_bisect)`` (0.7 % with the defaults).

    Parameters
    ----------
    f : callable
        ``f(psi (m,), x (m, n)) -> (m, n)``, the disturbed system.
    directions : array_like
        Directions in scaled coordinates, shape (k, n) (normalised here; none may be zero).
    psi0 : float or array_like
        Start azimuths, shape (p,).
    scales : array_like, optional
        Norm scales ``a`` (units of ``x``), shape (n,); a start is ``s * u * a``.
    s_max : float
        Largest amplitude tried, scaled norm; below ``bound``.
    s_min : float, optional
        Smallest grid amplitude; default ``s_max / 1000``.
    n_grid : int
        Grid amplitudes (>= 2).
    n_bisect : int
        Bisection steps (>= 0).
    n_periods : float
        Horizon, periods (>= 1): :func:`horizon`.
    bound, decay : float
        The definition's bound (> ``s_max``) and decay ratio (in (0, 1)).
    steps_per_period : int
        RK4 steps per period.
    period : float
        The period.

    Returns
    -------
    RayExtent

    Raises
    ------
    ValueError
        Bad shapes or arguments.
    """
    u = np.asarray(directions, dtype=float)
    if u.ndim == 1:
        u = u[None, :]
    if u.ndim != 2 or u.shape[0] == 0 or u.shape[1] == 0 or not np.all(np.isfinite(u)):
        raise ValueError(f"directions must be finite, shape (k, n), got {np.shape(directions)}")
    lengths = np.linalg.norm(u, axis=1)
    if np.any(lengths == 0.0):
        raise ValueError("directions must be non-zero")
    u = u / lengths[:, None]
    k, n = u.shape
    psi = np.atleast_1d(_azimuths(np.atleast_1d(np.asarray(psi0, dtype=float))))
    if psi.size == 0:
        raise ValueError("give at least one start azimuth psi0")
    p = psi.size
    a = _scales(scales, n)
    s_max = _positive("s_max", s_max)
    s_min = s_max / 1000.0 if s_min is None else _positive("s_min", s_min)
    if s_min >= s_max:
        raise ValueError(f"s_min must be < s_max, got {s_min!r} >= {s_max!r}")
    bound = _positive("bound", bound)
    if s_max >= bound:
        raise ValueError(f"s_max ({s_max!r}) must be below the bound ({bound!r}): a start beyond it is unstable")
    decay = _decay(decay)
    n_grid = _integer("n_grid", n_grid, 2)
    n_bisect = _integer("n_bisect", n_bisect, 0)

    def judge(s: np.ndarray) -> np.ndarray:
        """Verdicts of the starts ``s[..., d, j] * u[d]`` at ``psi[j]``; ``s`` shape (..., k, p)."""
        s = np.broadcast_to(s, s.shape[:-2] + (k, p))
        x0 = (s[..., None] * u[:, None, :]) * a  # (..., k, p, n)
        ps = np.broadcast_to(psi, s.shape)
        v = verdicts(f, x0.reshape(-1, n), ps.reshape(-1), n_periods=n_periods, scales=a, bound=bound,
                     decay=decay, steps_per_period=steps_per_period, period=period)
        return v.stable.reshape(s.shape)

    amps = np.geomspace(s_min, s_max, n_grid)
    grid = judge(np.broadcast_to(amps[:, None, None], (n_grid, k, p)).copy())  # (g, k, p)
    unstable = ~grid
    any_unstable = unstable.any(axis=0)
    first = np.where(any_unstable, unstable.argmax(axis=0), n_grid)  # index of the first unstable
    lo = np.where(first > 0, amps[np.maximum(first - 1, 0)], 0.0)
    hi = np.where(any_unstable, amps[np.minimum(first, n_grid - 1)], np.inf)
    after = np.arange(n_grid)[:, None, None] > first[None]
    non_monotone = np.any(grid & after, axis=0)
    if n_bisect and any_unstable.any():
        sel = np.flatnonzero(any_unstable.reshape(-1))  # only the bracketed rays are integrated
        d_sel, p_sel = np.unravel_index(sel, (k, p))
        lo_s, hi_s = lo.reshape(-1)[sel], hi.reshape(-1)[sel]
        for _ in range(n_bisect):
            mid = np.where(lo_s > 0.0, np.sqrt(lo_s * hi_s), 0.5 * hi_s)
            v = verdicts(f, (mid[:, None] * u[d_sel]) * a, psi[p_sel], n_periods=n_periods, scales=a,
                         bound=bound, decay=decay, steps_per_period=steps_per_period, period=period)
            lo_s = np.where(v.stable, mid, lo_s)
            hi_s = np.where(v.stable, hi_s, mid)
        lo, hi = lo.reshape(-1).copy(), hi.reshape(-1).copy()
        lo[sel], hi[sel] = lo_s, hi_s
        lo, hi = lo.reshape(k, p), hi.reshape(k, p)
    extent = np.where(any_unstable, lo, s_max)
    return RayExtent(directions=u, psi0=psi, extent=extent, upper=hi, hit_s_max=~any_unstable,
                     non_monotone=non_monotone, amplitudes=amps, grid_stable=grid, s_max=s_max, bound=bound,
                     decay=decay, n_periods=float(n_periods), steps_per_period=int(steps_per_period), scales=a)


# --------------------------------------------------------------------------------------
# Slices
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class SliceMap:
    """Verdicts on a grid of starts in the plane of two state components (:func:`slice_map`).

    Attributes
    ----------
    i, j : int
        The state components varied; the others start at 0.
    axis_i, axis_j : numpy.ndarray
        Start values of components ``i`` and ``j`` in scaled units (``x_i / a_i``), shape (n,).
    psi0 : float
        Start azimuth (units of ``period``, rad).
    stable : numpy.ndarray
        Boolean, shape (n, n): ``stable[r, c]`` for the start ``x_i = axis_i[r] a_i``,
        ``x_j = axis_j[c] a_j``.
    peak : numpy.ndarray
        Largest scaled norm over the horizon, shape (n, n) (for a motion that left: where it was
        found beyond the bound).
    last_peak : numpy.ndarray
        Largest scaled norm over the last period, NaN for a motion that left, shape (n, n).
    left : numpy.ndarray
        Boolean, shape (n, n): left the bound.
    bound, decay, n_periods : float
        The definition's parameters.
    steps_per_period : int
        RK4 steps per period.
    """

    i: int
    j: int
    axis_i: np.ndarray
    axis_j: np.ndarray
    psi0: float
    stable: np.ndarray
    peak: np.ndarray
    last_peak: np.ndarray
    left: np.ndarray
    bound: float
    decay: float
    n_periods: float
    steps_per_period: int

    @property
    def stable_fraction(self) -> float:
        """Fraction of the grid's starts that are stable, -."""
        return float(self.stable.mean())


def slice_map(f: Function, i: int, j: int, extent_i: float, extent_j: float, n: int, psi0: float, *,
              n_states: int | None = None, scales=None, n_periods: float, bound: float = DEFAULT_BOUND,
              decay: float = DEFAULT_DECAY, steps_per_period: int = DEFAULT_STEPS_PER_PERIOD,
              period: float = TWO_PI) -> SliceMap:
    """Verdicts on an ``n x n`` grid of starts in the plane of state components ``i`` and ``j``.

    The starts are ``x_i = s_i a_i``, ``x_j = s_j a_j`` with ``s_i`` and ``s_j`` on uniform
    grids over ``[-extent_i, extent_i]`` and ``[-extent_j, extent_j]`` (scaled units), every
    other component 0, all at the azimuth ``psi0``, integrated as one batch.

    Parameters
    ----------
    f : callable
        ``f(psi (m,), x (m, n_states)) -> (m, n_states)``.
    i, j : int
        Two different state components.
    extent_i, extent_j : float
        Half-widths of the grid, scaled units (> 0).
    n : int
        Points per axis (>= 2; odd puts the steady motion at the centre).
    psi0 : float
        Start azimuth.
    n_states : int, optional
        Dimension of the state; default the length of ``scales`` (one of them is needed).
    scales : array_like, optional
        Norm scales, shape (n_states,).
    n_periods, bound, decay, steps_per_period, period
        As :func:`ray_extent`.

    Returns
    -------
    SliceMap
    """
    if scales is None and n_states is None:
        raise ValueError("give scales or n_states (the dimension of the state)")
    dim = int(np.size(scales)) if n_states is None else _integer("n_states", n_states, 2)
    a = _scales(scales, dim)
    for name, c in (("i", i), ("j", j)):
        if isinstance(c, bool) or not isinstance(c, (int, np.integer)) or not 0 <= c < dim:
            raise ValueError(f"{name} must be a state component in [0, {dim}), got {c!r}")
    if i == j:
        raise ValueError(f"i and j must differ, got {i} twice")
    ei, ej = _positive("extent_i", extent_i), _positive("extent_j", extent_j)
    n = _integer("n", n, 2)
    p0 = float(psi0)
    if not math.isfinite(p0):
        raise ValueError(f"psi0 must be finite, got {psi0!r}")
    si, sj = np.linspace(-ei, ei, n), np.linspace(-ej, ej, n)
    x0 = np.zeros((n, n, dim))
    x0[..., i] = si[:, None] * a[i]
    x0[..., j] = sj[None, :] * a[j]
    v = verdicts(f, x0.reshape(-1, dim), p0, n_periods=n_periods, scales=a, bound=bound, decay=decay,
                 steps_per_period=steps_per_period, period=period)
    shape = (n, n)
    return SliceMap(i=int(i), j=int(j), axis_i=si, axis_j=sj, psi0=p0, stable=v.stable.reshape(shape),
                    peak=v.peak.reshape(shape), last_peak=v.last_peak.reshape(shape), left=v.left.reshape(shape),
                    bound=float(bound), decay=float(decay), n_periods=float(n_periods),
                    steps_per_period=int(steps_per_period))
