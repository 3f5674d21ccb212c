"""The start set a sound-rule certificate covers: every start below the level inside the bound.

Where the sound rule of :func:`rotorlyap.technical_stability` certifies, ``W' < 0`` on the band
``{||x|| <= A, W(psi, x) >= c}`` over the whole period, and ``W >= c`` on the sphere
``||x|| = A`` (``c`` is at most ``alpha``, the least ``W`` there). Then every start ``x0`` at any
azimuth ``psi0`` with

    ``||x0|| < A``  and  ``W(psi0, x0) < c``

stays inside ``||x|| < A`` for ever: to leave, the motion would have to reach the sphere, where
``W >= c``; at the first instant ``W`` climbs back to ``c`` the state lies on the band, where ``W``
decreases, so it cannot climb. The theorem's start ball (radius ``lambda0``, the largest ball
inside that set at each azimuth) is one part of it; the set itself is shaped by ``W`` and
reaches further along most directions, in particular along the hinges whose norm scale is small
against what the blade survives.

:func:`start_set` measures the set along given directions (by default the ``2 n`` signed
coordinate axes: one hinge angle or one rate disturbed alone): at each azimuth, the first
radius where ``W`` reaches ``c`` (closed form for a quadratic ``W``, else a scan of the ray and
a bracketing search, the side where ``W < c`` kept), capped at ``A``. The smallest over the
azimuths is what a start at an unknown azimuth may use: the grid's smallest, then refined by a
golden-section search of the azimuth about the three smallest grid values of each direction, all
of them together (:func:`golden_minima`; a start between two grid azimuths may reach less than
at either). For a ``W`` that is not a quadratic form
the reach rests on the scan (64 radii per ray, then the bracket narrowed to ``1e-13 A``), as the
rest of the certificate rests on searches: a numerical certificate.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from ._checks import positive_float as _positive_float
from ._checks import positive_int as _positive_int
from .lyapunov import _Checked, _ray_level

__all__ = ["N_SCAN", "StartSet", "golden_minima", "signed_axes", "start_set"]

N_SCAN = 64
"""Radii at which :func:`start_set` scans each ray for the first crossing of the level (a ``W``
that is not a quadratic form)."""

Function = Callable[[np.ndarray, np.ndarray], np.ndarray]


def signed_axes(n: int) -> np.ndarray:
    """The ``2 n`` signed unit axes, ``+e_0 .. +e_{n-1}`` then ``-e_0 .. -e_{n-1}``, shape ``(2 n, n)``."""
    n = _positive_int("n", n)
    eye = np.eye(n)
    return np.vstack([eye, -eye])


@dataclass(frozen=True)
class StartSet:
    """Result of :func:`start_set`: how far the certified start set reaches along given directions.

    Attributes
    ----------
    level : float
        The level ``c`` of ``W`` (the sound rule's ``alpha``).
    A : float
        The certified bound of the scaled norm.
    scales : numpy.ndarray
        The norm's ``a_i``, shape ``(n,)``.
    psi : numpy.ndarray
        The start azimuths examined, rad, shape ``(m,)`` (one where nothing depends on the azimuth).
    directions : numpy.ndarray
        Unit directions of the scaled state, shape ``(k, n)``.
    reach : numpy.ndarray
        Radius (scaled norm) up to which the ray ``r u`` stays in the set at each azimuth, shape
        ``(m, k)``: ``W < c`` on the whole segment before it, and at most ``A``.
    least : numpy.ndarray
        Reach along each direction at the worst start azimuth of the whole period, scaled norm,
        shape ``(k,)``: the grid's smallest, refined between the grid's azimuths (module docstring).
    """

    level: float
    A: float
    scales: np.ndarray
    psi: np.ndarray
    directions: np.ndarray
    reach: np.ndarray
    least: np.ndarray

    def __post_init__(self) -> None:
        for name in ("scales", "psi", "directions", "reach", "least"):
            arr = np.array(getattr(self, name), dtype=float, copy=True)
            arr.setflags(write=False)
            object.__setattr__(self, name, arr)

    @property
    def axis_reach(self) -> np.ndarray:
        """For the signed axes of :func:`signed_axes`: the reach along each coordinate, the smaller
        sign, at the worst start azimuth, scaled norm, shape ``(n,)``."""
        n = self.scales.size
        if self.directions.shape != (2 * n, n) or not np.array_equal(self.directions, signed_axes(n)):
            raise ValueError("axis_reach needs the signed axes as directions (signed_axes(n))")
        least = self.least
        return np.minimum(least[:n], least[n:])

    def __repr__(self) -> str:  # short and stable: no arrays
        return (f"StartSet(level={self.level:.4g}, A={self.A:.4g}, {self.psi.size} azimuths, "
                f"{self.directions.shape[0]} directions, reach in [{self.least.min():.4g}, {self.least.max():.4g}])")


def start_set(W: Function, level: float, A: float, scales, *, psi=None, period: float = 2 * np.pi,
              n_psi: int = 360, autonomous: bool = False, quadratic: bool = False, directions=None,
              n_scan: int = N_SCAN) -> StartSet:
    """Measure the start set ``{||x|| < A, W(psi, x) < level}`` along ``directions``.

    Parameters
    ----------
    W : callable
        The vectorised Liapunov function ``W(psi (m,), x (m, n)) -> (m,)`` of a sound-rule
        certificate (state units: ``x = a * y``).
    level : float
        The level ``c`` (the result's ``alpha``, or its ``level``), > 0.
    A : float
        The certified bound of the scaled norm, > 0.
    scales : array_like
        The norm's ``a_i``, shape ``(n,)``, all > 0.
    psi : array_like, optional
        Start azimuths, rad (default: ``n_psi`` uniform over the period; ``[0]`` if autonomous).
    period : float
        The period of ``W`` in ``psi``, rad.
    n_psi : int
        Azimuths of the default grid.
    autonomous : bool
        Nothing depends on the azimuth: one start azimuth, 0.
    quadratic : bool
        ``W`` is a quadratic form in ``x`` at each azimuth: the crossing in closed form,
        ``r = sqrt(c / W(psi, u a))``.
    directions : array_like, optional
        Unit directions of the scaled state, shape ``(k, n)`` (default :func:`signed_axes`).
    n_scan : int
        Radii of the scan of each ray (not quadratic).

    Returns
    -------
    StartSet

    Raises
    ------
    ValueError
        A level or bound not finite and > 0, bad scales or directions, or a ``W`` that returns
        a non-finite value or the wrong shape.
    """
    level = _positive_float("level", level)
    A = _positive_float("A", A)
    period = _positive_float("period", period)
    a = np.asarray(scales, dtype=float).reshape(-1)
    if a.size == 0 or not np.all(np.isfinite(a)) or np.any(a <= 0):
        raise ValueError(f"scales must be finite and > 0, got {a.tolist()}")
    n = a.size
    u = signed_axes(n) if directions is None else np.atleast_2d(np.asarray(directions, dtype=float))
    norms = np.linalg.norm(u, axis=1) if u.ndim == 2 else np.zeros(0)
    if u.ndim != 2 or u.shape[1] != n or u.shape[0] == 0 or not np.all(np.isfinite(u)) or np.any(norms == 0):
        raise ValueError(f"directions must be a (k, {n}) array of finite, non-zero vectors")
    u = u / norms[:, None]
    if autonomous:
        grid = np.zeros(1)
    elif psi is None:
        grid = period * np.arange(_positive_int("n_psi", n_psi)) / n_psi
    else:
        grid = np.asarray(psi, dtype=float).reshape(-1)
        if grid.size == 0 or not np.all(np.isfinite(grid)):
            raise ValueError("psi must hold at least one finite azimuth")
    m, k = grid.size, u.shape[0]
    n_scan = _positive_int("n_scan", n_scan)
    sys = _Checked(None, W, None, n, 0.0)

    def reach_at(psi, dirs):
        return _ray_level(sys, psi, dirs, a, level, A, True if quadratic else None, n_scan=n_scan, below=True)

    r = reach_at(np.repeat(grid, k), np.tile(u, (m, 1))).reshape(m, k)
    least = r.min(axis=0)
    if m > 1:  # between the grid's azimuths: a bounded search about the three smallest of each ray
        h = period / m
        ray = np.repeat(np.arange(k), min(3, m))
        centre = grid[np.argsort(r, axis=0)[:3].T.reshape(-1)]
        found = golden_minima(lambda p, rows: reach_at(p, u[ray[rows]]), centre - h, centre + h,
                              xatol=1e-9 * period)
        np.minimum.at(least, ray, found)
    return StartSet(level=level, A=A, scales=a, psi=grid, directions=u, reach=r, least=least)


def golden_minima(fun: Callable[[np.ndarray, np.ndarray], np.ndarray], lo, hi, *, xatol: float) -> np.ndarray:
    """The least value of each of many scalar functions, each on its own interval, found together
    by golden-section search: ``fun(x (j,), rows (j,)) -> (j,)`` evaluates the functions ``rows``
    at ``x``, one vectorised call per step for all of them.

    Each interval shrinks by the golden ratio a step until it is at most ``xatol`` wide (about
    33 steps for :func:`start_set`'s two grid spacings and ``xatol = 1e-9`` of the period); the
    least value of every point evaluated is returned (never more than the last bracket's).
    Replaces a bounded Brent search of one ray and start at a time (``scipy``'s
    ``minimize_scalar``): 36 of them took 5.8 s of the default ``certify`` at mu = 0.1, almost
    all of it the cost of a call of ``W`` on a single state.

    Parameters
    ----------
    fun : callable
        The functions, vectorised over the rows.
    lo, hi : array_like
        The intervals, shape ``(j,)``.
    xatol : float
        Final width of the intervals.

    Returns
    -------
    numpy.ndarray
        Shape ``(j,)``.
    """
    a = np.array(lo, dtype=float, copy=True)
    b = np.array(hi, dtype=float, copy=True)
    rows = np.arange(a.size)
    inv = (np.sqrt(5.0) - 1.0) / 2.0
    c, d = b - inv * (b - a), a + inv * (b - a)
    both = fun(np.concatenate([c, d]), np.concatenate([rows, rows]))
    fc, fd = both[:a.size], both[a.size:]
    best = np.minimum(fc, fd)
    while np.any(b - a > xatol):
        left = fc < fd  # the minimum in [a, d]: the new point left of c; else in [c, b]
        b = np.where(left, d, b)
        a = np.where(left, a, c)
        x = np.where(left, b - inv * (b - a), a + inv * (b - a))
        fx = fun(x, rows)
        best = np.minimum(best, fx)
        c, d, fc, fd = (np.where(left, x, d), np.where(left, c, x),
                        np.where(left, fx, fd), np.where(left, fc, fx))
    return best
