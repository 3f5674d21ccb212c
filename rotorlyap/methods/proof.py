"""Proofs of technical stability with a quadratic Liapunov function, by ball arithmetic.

The sound rule of :mod:`rotorlyap.methods.lyapunov` checks the theorem's condition (h) by
searches: a *numerical* certificate. This module proves it, for ``W(psi, y) = y^T S(psi) y`` in
scaled coordinates ``y = x / a`` about a steady motion, by enclosing every term of ``W'`` on
every interval of azimuth (:mod:`rotorlyap.methods.intervals`).

The inequality
--------------
Write the disturbed equations in scaled coordinates as ``y' = g(psi, y)`` and split

    ``g(psi, y) = g0(psi) + K(psi, y) y``,  ``K(psi, y) = int_0^1 J(psi, t y) dt``,

with ``g0`` the residual of the steady motion (zero for an exact one) and ``J`` the Jacobian
(at kinks of a piecewise-linear model, a generalised Jacobian: the integral form holds for
Lipschitz ``g``). Then

    ``W' = y^T S' y + 2 y^T S g = y^T N y + 2 y^T S g0``,  ``N = S' + K^T S + S K``.

If ``K(psi, y)`` lies in a ball matrix ``K(psi, rho)`` for every ``|y_i| <= rho`` (the system
provides it, :class:`ProofSystem`), then for ``|y| <= rho``

    ``W' <= n(psi) |y|^2 + 2 s(psi) e(psi) |y|``,

with ``n`` an upper bound of the largest eigenvalue of every symmetric matrix in the ball
``S' + K^T S + S K``, ``s`` of the largest eigenvalue of ``S`` and ``e`` of ``|g0|`` (all from
:func:`rotorlyap.methods.intervals.symmetric_eigenvalue_bounds`). For ``rho -> 0`` the ball
shrinks to ``J0``, the Jacobian at the steady motion, and ``n`` to the largest eigenvalue of
``S' + J0^T S + S J0 = -Q`` (up to the residual of the Lyapunov equation): the linear part.

The certificate
---------------
For a bound ``A``: the level ``c = A^2 min_psi l(psi)`` (``l`` a lower bound of the smallest
eigenvalue of ``S``, which must be positive) is at most ``W`` on the sphere ``|y| = A``; on the
band ``|y| <= A, W >= c`` at an azimuth in interval ``k``, ``|y| >= r_k = sqrt(c / s_k)``
(``s_k`` an upper bound of the largest eigenvalue of ``S``). The bound above is
``|y| (n_k |y| + 2 e_k)``, negative on the whole band if ``n_k < 0`` and ``n_k r_k + 2 e_k < 0``. If that holds on every interval, condition (h) holds over the
whole period, and every motion that starts at an azimuth in interval ``k`` with
``|y| < lambda0_k = r_k`` stays inside ``|y| < A`` for ever: a proof, for the model as it is
enclosed (exact arithmetic; the floating-point code evaluates the same functions to round-off).
:func:`prove_quadratic` finds the largest ``A`` (up to the one requested) for which it holds,
or says which interval and which term prevented it.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Protocol

import numpy as np

from . import intervals as iv

__all__ = ["Proof", "ProofSystem", "lyapunov_enclosure", "nonlinear_bounds", "prove_quadratic",
           "prove_quadratic_models"]


class ProofSystem(Protocol):
    """What :func:`prove_quadratic` needs from a system ``x' = f(psi, x)`` (state units), on
    ``N`` uniform azimuth intervals of one period.

    ``residual(N)`` returns ``(g0, blocked)``: balls (N, n) of ``f(psi, 0)`` over each interval,
    and a dict ``{reason: boolean (N,)}`` of intervals where no enclosure exists.
    ``linear(N)`` returns balls (N, n, n) of the Jacobian ``J0`` at ``x = 0`` (for the report).
    ``averaged_jacobian(N, radius)`` returns ``(K, blocked)``: balls (N, n, n) that contain the
    averaged Jacobian ``int_0^1 J(psi, t x) dt`` for every ``|x_i| <= radius_i`` and every
    ``psi`` of the interval, so that ``f(psi, x) = f(psi, 0) + K x``.
    """

    n: int

    def residual(self, N: int): ...

    def linear(self, N: int): ...

    def averaged_jacobian(self, N: int, radius: np.ndarray): ...


@dataclass(frozen=True)
class Proof:
    """Outcome of :func:`prove_quadratic`.

    Attributes
    ----------
    proved : bool
        True if condition (h) is proved on every azimuth interval for the bound ``A``.
    A : float
        The proved bound of the scaled norm (0 if nothing is proved).
    A_requested : float
        The largest bound tried.
    level : float
        ``c``: a lower bound of ``W`` on the sphere ``|y| = A`` over the period (0 if nothing).
    psi : numpy.ndarray
        Left ends of the ``N`` azimuth intervals, rad.
    lambda0 : numpy.ndarray
        Proved start radius per interval (scaled norm): motions that start in interval ``k``
        with ``|y| < lambda0[k]`` stay inside ``|y| < A``. Zeros if nothing is proved.
    n_intervals : int
        ``N``.
    terms : dict
        At the proved bound (or, if nothing is proved, at the smallest bound tried), per interval
        (arrays (N,)): ``"linear"`` (upper bound of ``lambda_max(S' + J0^T S + S J0)``: about
        ``-1`` for ``Q = I``), ``"nonlinear"`` (the same with the deviation ``D``: ``n``),
        ``"deviation"`` (upper bound of ``||D||_2``), ``"residual"`` (``e``, an upper bound of ``|S g0|``
        with ``g0`` the steady motion's residual), ``"s_max"``, ``"s_min"`` (eigenvalue bounds of ``S``).
    tried : tuple of (float, bool)
        Every bound tried and whether it was proved, in order.
    message : str
        What was proved, or which interval and which term prevented the proof.
    """

    proved: bool
    A: float
    A_requested: float
    level: float
    psi: np.ndarray
    lambda0: np.ndarray
    n_intervals: int
    terms: dict
    tried: tuple
    message: str

    @property
    def min_lambda0(self) -> float:
        """The smallest proved start radius over the period (0 if nothing)."""
        return float(np.min(self.lambda0)) if self.proved else 0.0

    def __repr__(self) -> str:  # short and stable: no arrays
        return (f"Proof(proved={self.proved}, A={self.A:.4g}, min lambda0={self.min_lambda0:.4g}, "
                f"N={self.n_intervals})")


def lyapunov_enclosure(solution) -> Callable[[int], tuple[np.ndarray, np.ndarray]]:
    """Enclosures of ``S(psi)`` and ``S'(psi)`` of a :class:`~rotorlyap.methods.periodic_lyapunov.PeriodicLyapunovSolution`.

    The matrix is the one ``W`` is computed with: the upper triangle of the computed grid
    values mirrored (so exactly symmetric), interpolated as the solution interpolates it
    (constant, or the periodic cubic Hermite interpolant, enclosed by
    :func:`rotorlyap.methods.intervals.hermite_enclosure`; the period must be ``2 pi``).

    Returns
    -------
    callable
        ``enclose(N) -> (S, dS)``, balls of shape (N, n, n) on ``N`` uniform azimuth intervals.
    """
    P = np.asarray(solution.P_grid, dtype=float)
    D = np.asarray(solution.dP_grid, dtype=float)
    upper_mask = np.triu(np.ones(P.shape[-2:], dtype=bool))
    P = np.where(upper_mask, P, np.swapaxes(P, -1, -2))
    D = np.where(upper_mask, D, np.swapaxes(D, -1, -2))
    if solution.interpolation == "constant":
        def enclose(N: int):
            S = iv.balls(np.broadcast_to(P[0], (N,) + P.shape[1:]))
            return S, iv.zeros(S.shape)
        return enclose
    if solution.interpolation != "hermite":
        raise ValueError(f"the proof encloses constant and 'hermite' solutions, got {solution.interpolation!r} "
                         "(solve with a fixed-step method, e.g. method='magnus6')")
    if not np.isclose(solution.period, 2 * np.pi, rtol=0, atol=1e-12):
        raise ValueError(f"the proof encloses solutions of period 2 pi, got {solution.period!r}")

    def enclose(N: int):
        return iv.hermite_enclosure(P, D, N)
    return enclose


def _scaled_matrix(J, a: np.ndarray):
    """Balls of ``diag(1/a) J diag(a)`` (J balls (N, n, n)): each entry times ``a_j``, then
    divided by ``a_i`` (two rounded operations, as an entry at a time)."""
    return (J * a[None, None, :]) / a[None, :, None]


def _quadratic_form_matrix(S, X):
    """``X^T S + S X`` (balls (N, n, n))."""
    SX = iv.matmul(S, X)
    return SX + np.swapaxes(SX, -1, -2)


def _reasons(blocked: dict, psi: np.ndarray) -> str:
    parts = []
    for reason, mask in blocked.items():
        if np.any(mask):
            k = int(np.flatnonzero(mask)[0])
            parts.append(f"{reason} ({int(np.sum(mask))} intervals, the first at psi = {np.degrees(psi[k]):.1f} deg)")
    return "; ".join(parts)


class _Base:
    """What every bound shares: ``S`` and its eigenvalue bounds, the residual term, the linear part."""

    def __init__(self, system: ProofSystem, quadratic, a: np.ndarray, N: int):
        self.system, self.a, self.N = system, a, N
        S, dS = quadratic(N)
        self.S = iv.asballs(S)
        self.dS = iv.asballs(dS)
        self.s_lo, self.s_hi = iv.symmetric_eigenvalue_bounds(self.S)
        g0, self.blocked = system.residual(N)
        self.J0y = _scaled_matrix(iv.asballs(system.linear(N)), a)
        g0y = iv.asballs(g0) / a[None, :]
        self.N0 = self.dS + _quadratic_form_matrix(self.S, self.J0y)      # the linear part's matrix
        _, self.m_hi = iv.symmetric_eigenvalue_bounds(self.N0)
        self.e = iv.norm_upper(iv.matmul(self.S, g0y[:, :, None])[:, :, 0])  # |S g0|

    def nonlinear(self, bound: float):
        """``n`` per interval (upper bound of ``lambda_max(S' + K^T S + S K)``), ``K`` scaled, blocked."""
        K, blocked = self.system.averaged_jacobian(self.N, bound * self.a)
        Ky = _scaled_matrix(iv.asballs(K), self.a)
        _, n_hi = iv.symmetric_eigenvalue_bounds(self.dS + _quadratic_form_matrix(self.S, Ky))
        return n_hi, Ky, blocked


SHELL_CORE = 0.45
"""The smallest cube of a proof over shells (:func:`prove_quadratic_models`, ``shells``), as a
fraction of the bound: its search covers all of it. Measured on the trimmed helicopter at mu = 0.1
(2026-12-06; cubes in the ratio 0.8): 0.45 leaves four cubes, the bound 0.70 of the numerical one
proved in 34 s; 0.35 seven cubes, 38 s; down to the band's inner edge nineteen cubes, 54 s."""


def _level_and_radii(bound: float, s_min: float, s_hi: np.ndarray) -> tuple[float, np.ndarray]:
    """The level ``c = A^2 min l`` (rounded down) and the start radii ``sqrt(c / s_k)`` (rounded down)."""
    c = float(np.nextafter(bound * bound * s_min * (1 - 1e-15), -np.inf))
    with np.errstate(divide="ignore", invalid="ignore"):
        r = np.nextafter(np.sqrt(np.nextafter(c / s_hi, -np.inf)) * (1 - 1e-15), -np.inf)
    return c, np.asarray(r, dtype=float)


def _prove_by_shells(models, first: float, ratio: float, A: float, s_min: float, s_hi, terms: dict, psi,
                     blocked0: dict, N: int, group: int, order: int, max_boxes: int, tries: int,
                     level_set: bool = False):
    """:func:`prove_quadratic_models` over shells of cubes (its ``shells``): the largest of the first
    ``tries`` bounds ``first`` times :data:`rotorlyap.methods.band.STEPS` whose every cube's search
    closes. Returns ``(proof or None, the bounds tried)``."""
    from .band import STEPS, hopeless, largest_bound

    tried = []
    for step in STEPS[:tries]:
        T = first * step
        level, radii = _level_and_radii(T, s_min, s_hi)
        cubes = [T]
        while cubes[-1] * ratio > SHELL_CORE * T:
            cubes.append(cubes[-1] * ratio)
        boxes, deviation, estimate, ok = 0, np.zeros(N), np.full(N, -np.inf), True
        for j, cube in enumerate(cubes):
            bp, blocked, _, dev = models(cube)
            if bp is None or _reasons({**blocked0, **blocked}, psi) or hopeless(bp):
                ok = False
                break
            # the cube's shell: max |y_i| from the next cube's (a little below it) up to this cube
            floor = 0.0 if j == len(cubes) - 1 else float(np.nextafter(cubes[j + 1] / cube * (1 - 1e-12), 0.0))
            res = largest_bound(bp, T, level, max_boxes=max_boxes, patience=max_boxes, sigma_floor=floor,
                                complete=True, level_set=level_set)
            boxes += res.boxes
            if not res.A > 0:
                ok = False
                break
            deviation = np.maximum(deviation, dev)
            estimate = np.maximum(estimate, np.repeat(res.estimate, group))
        tried.append((T, ok))
        if ok:
            where = (f"the level set W = c over the whole period, so that {{W <= c}} (within |y| <= A = {T:.4g}) "
                     "is invariant" if level_set else
                     f"the band |y| <= A = {T:.4g}, W >= c over the whole period")
            message = (f"proved: W' < 0 on {where} ({N} azimuth intervals; Taylor models of order {order} over "
                       f"{len(cubes)} shells of cubes, branch and bound over directions and radii: {boxes} boxes)")
            proof = Proof(proved=True, A=float(T), A_requested=A, level=level, psi=psi, lambda0=radii, n_intervals=N,
                          terms={**terms, "deviation": deviation, "nonlinear": estimate}, tried=tuple(tried),
                          message=message)
            return proof, tried
    return None, tried


def nonlinear_bounds(system: ProofSystem, quadratic: Callable[[int], tuple], bounds, *, scales,
                     n_intervals: int = 1) -> np.ndarray:
    """The proof's nonlinear term at several bounds: the largest over the period of ``n``, the upper
    bound of ``lambda_max(S' + K^T S + S K)`` over the tube ``|y_i| <= A`` (module docstring).

    ``n`` starts at the linear part (about ``-1`` for ``Q = I``) for small ``A`` and grows with
    ``A``; the proof needs it negative. Parameters as :func:`prove_quadratic`.

    Returns
    -------
    numpy.ndarray
        ``max_k n_k`` for each bound, shape ``(len(bounds),)``.
    """
    a = np.asarray(scales, dtype=float)
    base = _Base(system, quadratic, a, int(n_intervals))
    return np.array([float(np.max(base.nonlinear(float(A))[0])) for A in np.atleast_1d(bounds)])


def _checked_problem(system: ProofSystem, A, scales, n_intervals) -> tuple[float, np.ndarray, int]:
    """The bound, the scales and the number of intervals of a proof, checked: ``A`` finite and
    > 0, ``scales`` the system's ``n`` finite numbers > 0, ``n_intervals`` >= 1."""
    A = float(A)
    if not (np.isfinite(A) and A > 0):
        raise ValueError(f"A must be a finite bound > 0, got {A!r}")
    a = np.asarray(scales, dtype=float)
    if a.shape != (system.n,) or not np.all(np.isfinite(a) & (a > 0)):
        raise ValueError(f"scales must be {system.n} finite numbers > 0, got {scales!r}")
    N = int(n_intervals)
    if N < 1:
        raise ValueError(f"n_intervals must be >= 1, got {n_intervals!r}")
    return A, a, N


def prove_quadratic(system: ProofSystem, quadratic: Callable[[int], tuple], A: float, *, scales,
                    n_intervals: int = 1, period: float = 2 * np.pi, n_bisect: int = 10,
                    A_min: float | None = None) -> Proof:
    """Prove condition (h) for ``W = y^T S y``, ``y = x / a``, and find the largest bound that holds.

    Parameters
    ----------
    system : ProofSystem
        Enclosures of the disturbed equations (state units).
    quadratic : callable
        ``quadratic(N) -> (S, dS)``: balls of ``S(psi)`` and ``S'(psi)`` (per rad) in scaled
        coordinates on ``N`` uniform azimuth intervals (:func:`lyapunov_enclosure`).
    A : float
        The largest bound to prove (scaled norm, > 0).
    scales : array_like
        The ``a_i`` of the scaled coordinates (> 0).
    n_intervals : int
        ``N``, the azimuth intervals (1 for a system and ``S`` that do not depend on psi).
    period : float
        Period of the system (the intervals split it).
    n_bisect : int
        Bisection steps on ``A`` (between ``A_min`` and ``A``) when ``A`` itself is not proved.
    A_min : float, optional
        The smallest bound tried, default ``A * 1e-4``.

    Returns
    -------
    Proof
    """
    A, a, N = _checked_problem(system, A, scales, n_intervals)
    A_min = A * 1e-4 if A_min is None else float(A_min)
    psi = period * np.arange(N) / N
    base = _Base(system, quadratic, a, N)
    s_lo, s_hi, e, m_hi, blocked0 = base.s_lo, base.s_hi, base.e, base.m_hi, base.blocked
    s_min = float(np.min(s_lo))

    def attempt(bound: float):
        n_hi, Ky, blocked = base.nonlinear(bound)
        J0y = base.J0y
        c = np.nextafter(bound * bound * s_min * (1 - 1e-15), -np.inf) if s_min > 0 else 0.0
        with np.errstate(divide="ignore", invalid="ignore"):
            r = np.nextafter(np.sqrt(np.nextafter(c / s_hi, -np.inf)) * (1 - 1e-15), -np.inf)
        slope_ok = n_hi < 0
        # n_hi r < 0: shrunk towards zero, the positive term enlarged, so the sum is an upper bound
        offset = np.nextafter(n_hi * r * (1 - 1e-15) + 2 * e * (1 + 1e-15), np.inf)
        ok_k = slope_ok & (offset < 0) & np.isfinite(offset)
        all_blocked = {**blocked0, **blocked}
        for mask in all_blocked.values():
            ok_k &= ~np.asarray(mask, dtype=bool)
        terms = {"linear": m_hi, "nonlinear": n_hi, "deviation": iv.matrix_norm_upper(Ky - J0y),
                 "residual": e, "s_max": s_hi, "s_min": s_lo}
        proved = bool(s_min > 0 and np.all(ok_k))
        return proved, ok_k, terms, c, r, all_blocked

    tried = []
    best = None
    ok, ok_k, terms, c, r, blocked = attempt(A)
    tried.append((A, ok))
    first_fail = (ok_k, terms, blocked, A)
    if ok:
        best = (A, terms, c, r)
    else:
        lo, hi = 0.0, A
        # a geometric search down to A_min, then bisection between the last failure and the first success
        bound = A
        while bound > A_min:
            bound = max(bound / 4, A_min)
            ok_b, ok_k_b, terms_b, c_b, r_b, blocked_b = attempt(bound)
            tried.append((bound, ok_b))
            if ok_b:
                best, lo = (bound, terms_b, c_b, r_b), bound
                break
            hi = bound
            first_fail = (ok_k_b, terms_b, blocked_b, bound)
        if best is not None:
            for _ in range(n_bisect):
                mid = np.sqrt(lo * hi)
                ok_m, _, terms_m, c_m, r_m, _ = attempt(mid)
                tried.append((mid, ok_m))
                if ok_m:
                    best, lo = (mid, terms_m, c_m, r_m), mid
                else:
                    hi = mid
    if best is not None:
        bound, terms, c, r = best
        worst = int(np.argmax(terms["nonlinear"] * r + 2 * terms["residual"]))
        return Proof(
            proved=True, A=float(bound), A_requested=A, level=float(c), psi=psi, lambda0=np.asarray(r, dtype=float),
            n_intervals=N, terms=terms, tried=tuple(tried),
            message=(f"proved: W' < 0 on the band |y| <= A = {bound:.4g}, W >= c over the whole period "
                     f"({N} azimuth intervals, ball arithmetic); the tightest interval is at psi = "
                     f"{np.degrees(psi[worst]):.1f} deg"))
    ok_k, terms, blocked, bound = first_fail
    k = int(np.flatnonzero(~ok_k)[0]) if np.any(~ok_k) else 0
    where = f"psi in [{np.degrees(psi[k]):.2f}, {np.degrees(psi[k] + period / N):.2f}] deg"
    if s_min <= 0:
        why = f"S is not proved positive definite (smallest eigenvalue bound {s_min:.3g})"
    elif _reasons(blocked, psi):
        why = "no enclosure: " + _reasons(blocked, psi)
    elif not terms["linear"][k] < 0:
        why = (f"the linear part: lambda_max(S' + J0^T S + S J0) <= {terms['linear'][k]:.3g} is not proved "
               "negative (the linearised motion is not shown to decay in W)")
    elif not terms["nonlinear"][k] < 0:
        why = (f"the nonlinear part at the smallest bound tried, A = {bound:.3g}: lambda_max(N) <= "
               f"{terms['nonlinear'][k]:.3g} with the linear part {terms['linear'][k]:.3g} and ||K - J0|| <= "
               f"{terms['deviation'][k]:.3g}")
    else:
        why = (f"the steady motion's residual, |S g0| <= {terms['residual'][k]:.3g}, against the band's inner "
               f"radius at A = {bound:.3g}")
    return Proof(proved=False, A=0.0, A_requested=A, level=0.0, psi=psi, lambda0=np.zeros(N), n_intervals=N,
                 terms=terms, tried=tuple(tried), message=f"not proved at {where}: {why}")


def prove_quadratic_models(system, quadratic: Callable[[int], tuple], A: float, *, scales,
                           n_intervals: int = 1, period: float = 2 * np.pi, order: int = 3,
                           n_models: int | None = None, max_boxes: int = 200_000, patience: int = 50_000,
                           floor: float = 0.25, refits: int = 4, first_cube: float = 1.0,
                           shells: float | None = None, level_set: bool = False) -> Proof:
    """Prove condition (h) for ``W = y^T S y`` from Taylor models of the averaged Jacobian, and find
    the largest bound that holds.

    The system gives, besides what :class:`ProofSystem` asks, ``jacobian_models(N, radius, order)``:
    ``(coef, rem, exponents, blocked)``, the Taylor models of order ``order`` of the averaged
    Jacobian ``K`` over the cube ``|x_i| <= radius_i`` (state units; ``coef`` balls (N, M, n, n)
    per monomial of ``exponents`` (M, n) in ``t = x / radius``, ``rem`` (N, n, n) floats with
    ``|K - sum coef t^alpha| <= rem``). ``W'`` is then a polynomial in the disturbance plus a
    remainder (the cancellations of the equations kept in the polynomial, not widened by balls),
    and :func:`rotorlyap.methods.band.largest_bound` shows ``W' < 0`` on the band by a best-first
    branch and bound over directions and radii, out to the largest bound it can (at most ``A``:
    the models are taken over the cube of ``A``).

    The certificate is the one of :func:`prove_quadratic`: level ``c = A^2 min l`` (``l`` a lower
    bound of the smallest eigenvalue of ``S``), start radius per interval ``sqrt(c / s_k)``.

    Parameters
    ----------
    system : ProofSystem with ``jacobian_models``
    quadratic : callable
        As :func:`prove_quadratic`.
    A : float
        The largest bound to prove (scaled norm, > 0).
    scales : array_like
        The ``a_i`` (> 0).
    n_intervals : int
        ``N`` azimuth intervals.
    period : float
        Period of the system.
    order : int
        Order of the Taylor models.
    n_models : int, optional
        Azimuth intervals of the models and of the branch and bound (a divisor of ``N``; default
        ``N``). With fewer, the quadratic part is bounded on the ``N`` fine intervals
        (``lambda_max(S' + J0^T S + S J0)``, the largest over each coarse interval), the models'
        non-constant terms and ``S`` are taken over the coarse interval (the azimuth's monomials
        moved into the coefficients' radii), and the remainder doubled: ``K - J0`` lies in the
        non-constant terms plus ``2 R`` (the models' constant term is within ``R`` of ``J0``).
    max_boxes : int
        Boxes of the branch and bound before it stops (the bound then stays below the open boxes).
    patience : int
        Boxes spent on one bound before the next smaller one is tried
        (:func:`rotorlyap.methods.band.largest_bound`).
    floor : float
        The band is searched down to the level of ``floor`` times the cube (the proved bound must
        reach it; else the search is repeated with the floor at a quarter of the bound found).
    refits : int
        Where the bound found is below half the cube of the models (or nothing is found, or the
        remainder alone defeats the quadratic part at a sampled direction,
        :func:`rotorlyap.methods.band.hopeless`), the models are taken again over the cube of 1.5
        times the bound found (0.4 of the cube; at least half of it after a search cut short by
        ``max_boxes``): their remainders shrink with the cube; where the
        bound found fills the cube, over a larger cube (below the smallest that was too big), up to
        ``refits`` times. The largest bound proved is returned.
    first_cube : float
        The first cube of the models, as a fraction of ``A`` (the bound proved is at most the
        largest cube tried); with ``shells``, the first bound tried.
    level_set : bool
        Show ``W' < 0`` on the level set ``W = c`` of each bound tried, not on the whole band
        (with ``shells`` only: the level is fixed per bound). The set ``{W <= c}`` is then invariant
        (where ``W = c``, ``W`` decreases; ``W`` is positive definite, so the set is the closed
        ellipsoid about the steady motion at every azimuth), and it holds the ball of the start
        radius and lies in the ball of the bound: the same certificate, from a condition that asks
        less than (h) (the band reaches the sphere ``|y| = A`` in every direction, the level set
        only where ``S`` is smallest). :func:`rotorlyap.methods.band.largest_bound` cuts each box's
        radius range to the level set and bounds the linear part per box of directions. Where no
        bound closes every shell, the search over one cube that follows is the band's.
    shells : float, optional
        The proof over shells of cubes (None, the default: one cube at a time, above). A bound
        ``T`` is proved with models over the cubes ``c_0 = T``, ``c_j = shells^j T`` down to the
        last above :data:`SHELL_CORE` ``T``: the search of cube ``c_j`` covers the band's points
        with ``c_(j+1) <= max_i |y_i| <= c_j`` (:func:`rotorlyap.methods.band.largest_bound` with
        ``sigma_floor`` and ``complete``), the smallest cube all of its points, so that every
        point of the band lies in the search of a cube whose models are taken over a box little
        larger than the point's own. The models' remainder grows with the cube (for the trimmed
        helicopter on the retreating side, where the angle of attack of the innermost strips
        crosses the airfoil's stall: :func:`rotorlyap.analysis.proof.remainder_sources`), so that the points near the
        origin, which one cube of ``T`` leaves to its largest remainder, are shown with small
        ones. Each cube's search must close (``max_boxes`` boxes at most); where one does not, the
        next bound of :data:`rotorlyap.methods.band.STEPS` times ``first_cube A`` is tried, up to
        ``refits + 1`` bounds; where none is proved, the search over one cube follows, from the
        cube of ``first_cube A`` (``Proof.tried`` lists both).

    Returns
    -------
    Proof
        ``terms["nonlinear"]``: per interval, the largest ``W' / |y|^2`` of the polynomial part
        at the centres of the boxes in the band (an estimate of how near 0 the band comes, not a
        bound); ``terms["deviation"]``: the largest remainder of the models (scaled); the other
        terms as :func:`prove_quadratic`.
    """
    from . import balls as fb
    from .band import band_polynomial, hopeless, largest_bound

    A, a, N = _checked_problem(system, A, scales, n_intervals)
    if not 0 < floor < 1:
        raise ValueError(f"floor must lie in (0, 1), got {floor!r}")
    psi = period * np.arange(N) / N
    base = _Base(system, quadratic, a, N)
    s_lo, s_hi, e, m_hi, blocked0 = base.s_lo, base.s_hi, base.e, base.m_hi, base.blocked
    s_min = float(np.min(s_lo))
    Nc = N if n_models is None else int(n_models)
    if Nc < 1 or N % Nc:
        raise ValueError(f"n_models ({n_models!r}) must divide n_intervals ({N})")
    group = N // Nc
    N0_c = None
    if Nc != N and level_set:
        # the linear part's matrix over each coarse interval: the hull of the fine intervals' balls
        N0 = fb.as_balls(base.N0)
        lo = N0.lower().reshape((Nc, group) + N0.shape[1:]).min(axis=1)
        hi = N0.upper().reshape((Nc, group) + N0.shape[1:]).max(axis=1)
        mid = 0.5 * (lo + hi)
        N0_c = fb.Balls(mid, np.nextafter(np.nextafter(np.maximum(hi - mid, mid - lo), np.inf), np.inf))

    def models(cube: float):
        """The band polynomial from the models over the cube of ``cube``, the blocked intervals,
        whether the models are finite everywhere, and the remainders (scaled)."""
        coef, rem, exps, blocked = system.jacobian_models(Nc, cube * a, order)
        blocked = {key: np.repeat(np.asarray(v, dtype=bool), group) for key, v in blocked.items()}
        coef = fb.as_balls(coef)
        # scaled coordinates: C_ij a_j / a_i (rounded outwards), the remainder likewise (upper bounds)
        coef_y = (coef * a[None, None, None, :]) / a[None, None, :, None]
        rem_y = fb.Balls(np.asarray(rem, dtype=float) * a[None, None, :] / a[None, :, None]).upper()
        finite = np.repeat(np.all(np.isfinite(coef_y.mid) & np.isfinite(coef_y.rad), axis=(1, 2, 3))
                           & np.all(np.isfinite(rem_y), axis=(1, 2)), group)
        bp = None
        if np.all(finite):
            if Nc == N:
                bp = band_polynomial(base.S, base.dS, coef_y, exps, rem_y, e, cube)
            else:
                S_c, dS_c = quadratic(Nc)
                n0 = np.max(m_hi.reshape(Nc, group), axis=1)
                e_c = np.max(e.reshape(Nc, group), axis=1)
                bp = band_polynomial(fb.as_balls(S_c), fb.as_balls(dS_c), coef_y, exps,
                                     fb.Balls(rem_y * 2.0).upper(), e_c, cube, n0=n0, N0=N0_c)
        deviation = np.repeat(np.max(np.where(np.isfinite(rem_y), rem_y, np.inf), axis=(1, 2)), group)
        return bp, blocked, finite, deviation

    if not 0 < first_cube <= 1:
        raise ValueError(f"first_cube must lie in (0, 1], got {first_cube!r}")
    if shells is not None and not 0 < shells < 1:
        raise ValueError(f"shells must lie in (0, 1), got {shells!r}")
    if level_set and shells is None:
        raise ValueError("level_set needs shells (a fixed level per bound tried); got shells=None")
    terms = {"linear": m_hi, "deviation": np.full(N, np.nan), "residual": e, "s_max": s_hi, "s_min": s_lo,
             "nonlinear": np.full(N, np.nan)}
    base_ok = bool(s_min > 0 and np.all(m_hi < 0) and not _reasons(blocked0, psi))
    tried = []
    if shells is not None and base_ok:
        proof, tried = _prove_by_shells(models, A * first_cube, float(shells), A, s_min, s_hi, terms, psi, blocked0,
                                        N, group, order, max_boxes, refits + 1, level_set)
        if proof is not None:
            return proof
        # none of the bounds tried closed every shell: the search over one cube
    res = None
    best = None
    cube = A * first_cube
    finite = np.ones(N, dtype=bool)
    all_blocked = dict(blocked0)
    too_big = None            # the smallest cube whose models could not reach half of it
    for _ in range(refits + 1 if base_ok else 0):
        bp, blocked, finite, deviation = models(cube)
        all_blocked = {**blocked0, **blocked}
        if bp is None or _reasons(all_blocked, psi) or hopeless(bp):
            found = 0.0
            res = None
            tried.append((0.0, False))
        else:
            low = floor * cube
            for _ in range(2):
                c_low = float(np.nextafter(low * low * s_min * (1 - 1e-15), -np.inf))
                res = largest_bound(bp, cube, c_low, max_boxes=max_boxes, patience=patience)
                proved = res.A >= low and res.A > 0
                tried.append((res.A, proved))
                if proved or res.A <= 0 or res.boxes >= max_boxes:  # a search cut short: no retry
                    break
                low = res.A / 4
            found = res.A if proved else 0.0
            if proved and (best is None or found > best[0]):
                best = (found, res, deviation)
        if found >= 0.5 * cube:
            if found < 0.95 * cube or cube >= A:
                break
            # the cube limited the bound: a larger one, below the one that was too big
            nxt = min(A, 2.0 * cube if too_big is None else np.sqrt(cube * too_big))
            if nxt <= cube * 1.05:
                break
            cube = float(nxt)
            continue
        too_big = cube if too_big is None else min(too_big, cube)
        # the models over a smaller cube: smaller remainders (a search cut short by max_boxes says
        # little about where it would have ended: a quarter smaller)
        cut_short = res is not None and res.boxes >= max_boxes
        cube = max(1.5 * found, 0.5 * cube) if cut_short else (1.5 * found if found > 0 else 0.4 * cube)
    if best is not None:
        res = best[1]
        terms["deviation"] = best[2]
        terms["nonlinear"] = np.repeat(res.estimate, group)
    if best is not None:
        bound = res.A
        c, r = _level_and_radii(bound, s_min, s_hi)
        return Proof(proved=True, A=float(bound), A_requested=A, level=c, psi=psi, lambda0=r,
                     n_intervals=N, terms=terms, tried=tuple(tried),
                     message=(f"proved: W' < 0 on the band |y| <= A = {bound:.4g}, W >= c over the whole period "
                              f"({N} azimuth intervals; Taylor models of order {order}, branch and bound over "
                              f"directions and radii: {res.boxes} boxes)"))
    if s_min <= 0:
        why = f"S is not proved positive definite (smallest eigenvalue bound {s_min:.3g})"
    elif _reasons(all_blocked, psi) or not np.all(finite):
        why = "no enclosure: " + (_reasons(all_blocked, psi) or "the Taylor models are not finite")
    elif res is None:
        why = ("the models' remainder alone defeats the quadratic part (rotorlyap.methods.band.hopeless) "
               "on every cube tried" if tried else "nothing was tried")
    elif not np.all(m_hi < 0):
        k = int(np.flatnonzero(~(m_hi < 0))[0])
        why = (f"the linear part at psi = {np.degrees(psi[k]):.1f} deg: lambda_max(S' + J0^T S + S J0) <= "
               f"{m_hi[k]:.3g} is not proved negative")
    else:
        why = f"the branch and bound: {res.message}"
    return Proof(proved=False, A=0.0, A_requested=A, level=0.0, psi=psi, lambda0=np.zeros(N), n_intervals=N,
                 terms=terms, tried=tuple(tried), message=f"not proved: {why}")
