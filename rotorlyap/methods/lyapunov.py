"""Technical (Lagrange) stability of a periodic system by Liapunov's direct method.

This is the general algorithm of Narkiewicz & Lucjanek (1989, section 3) for any system
``x' = f(psi, x)`` with ``f`` periodic in ``psi``, and a candidate Liapunov function
``W(psi, x)``. It does not know about rotor blades.

The six steps, with the scaled norm ``||x|| = sqrt(sum((x_i / a_i)**2))``:

1. the bound ``A`` (given);
2. the function ``W`` (given; conditions (c)-(g) of the theorem are the caller's duty);
3. check ``W' <= 0`` on the sphere ``||x|| = A`` over the whole period; if it fails, find the
   largest ``A1 < A`` for which it holds (0 if none);
4. ``alpha = inf W(psi, x)`` over the period and the sphere ``||x|| = A``;
5. for each azimuth ``psi_j``, ``lambda0_j`` = the greatest radius whose ball has
   ``sup W(psi_j, x) < alpha``;
6. for each azimuth, check ``W'(psi_j, x) <= 0`` on the shell ``lambda0_j < ||x|| <= A``.

Suprema and infima are found by :mod:`rotorlyap.methods.sampling` (dense quasi-random sampling
refined by local ascent), so a result is exactly as trustworthy as that search: the
resolution parameters are documented below and their effect is shown in the book.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from ._checks import positive_float as _positive_float
from ._checks import positive_int as _positive_int
from .sampling import sphere_extremum, unit_sphere_points

__all__ = ["TechnicalStabilityResult", "technical_stability", "orbital_derivative"]

Function = Callable[[np.ndarray, np.ndarray], np.ndarray]


@dataclass(frozen=True)
class TechnicalStabilityResult:
    """Outcome of :func:`technical_stability`.

    Attributes
    ----------
    A_requested : float
        The bound asked for (step 1).
    scales : numpy.ndarray
        The norm scales ``a_i`` as used, shape ``(n,)``.
    A : float
        The bound after step 3: ``A_requested`` when ``W' <= 0`` on that sphere over the whole
        period, otherwise the largest ``A1 < A_requested`` found for which it holds, 0 if none.
    alpha : float
        ``inf W`` over the period on ``||x|| = A`` (step 4); 0 when ``A`` is 0.
    psi : numpy.ndarray
        The ``n_psi`` azimuths, uniform on ``[0, period)``.
    lambda0 : numpy.ndarray
        Radius of the certified start region at each azimuth (step 5); 0 where none.
    max_dW : numpy.ndarray
        Largest ``W'`` found on the shell ``lambda0_j < ||x|| <= A`` at each azimuth (step 6).
        When ``A`` is 0 there is no shell, and this holds instead the largest ``W'`` found on
        the requested sphere at each azimuth: the evidence that step 3 failed.
    argmax_dW : numpy.ndarray
        The state where each ``max_dW`` was found, shape ``(n_psi, n)``.
    stable : numpy.ndarray
        Boolean per azimuth: ``lambda0_j > 0`` and ``max_dW_j <= tol``. Certified bounded
        motion for starts ``||x(psi_j)|| < lambda0_j``.
    period : float
        The period ``T``.
    step3_max_dW : float
        Largest ``W'`` found on the requested sphere over the whole period (step 3).
    tol : float
        Round-off allowance in the tests ``W' <= 0``: ``rtol`` times the largest ``|W|``
        sampled on the requested sphere.
    message : str
        A sentence saying what was certified, or why nothing was.
    reading : str
        ``"strict"``: suprema and infima over whole spheres (the theorem as stated; a
        ``stable`` azimuth is a certificate, as far as the search is exhaustive).
        ``"practical"``: ``W`` and ``W'`` examined only along given test directions; an
        indicator, never a certificate.
    n_evaluations : int
        Number of states at which ``W'`` or ``W`` was evaluated.
    """

    A_requested: float
    scales: np.ndarray
    A: float
    alpha: float
    psi: np.ndarray
    lambda0: np.ndarray
    max_dW: np.ndarray
    argmax_dW: np.ndarray
    stable: np.ndarray
    period: float
    step3_max_dW: float
    tol: float
    message: str
    reading: str = "strict"
    n_evaluations: int = field(default=0, compare=False)

    def __post_init__(self) -> None:
        for name in ("scales", "psi", "lambda0", "max_dW", "argmax_dW", "stable"):
            arr = np.array(getattr(self, name), copy=True)
            arr.setflags(write=False)
            object.__setattr__(self, name, arr)

    @property
    def certified(self) -> bool:
        """True if at least one azimuth is certified stable (strict reading only)."""
        return self.reading == "strict" and bool(np.any(self.stable))

    def __repr__(self) -> str:  # short and stable: no arrays, no addresses
        return (
            f"TechnicalStabilityResult({self.reading}, A_requested={self.A_requested:.4g}, A={self.A:.4g}, "
            f"alpha={self.alpha:.4g}, stable={int(np.sum(self.stable))}/{self.stable.size} "
            f"azimuths, lambda0 in [{np.min(self.lambda0):.4g}, {np.max(self.lambda0):.4g}])"
        )


class _Checked:
    """Wraps ``f`` and ``W``: checks shapes and finiteness, counts evaluations."""

    def __init__(self, f: Function, W: Function, dW: Function | None, n: int, fd_step: float):
        self.f, self.W, self.dW_user, self.n, self.h = f, W, dW, n, fd_step
        self.count = 0

    def _check(self, name: str, out, shape, psi, x) -> np.ndarray:
        try:
            out = np.asarray(out, dtype=float)
        except (TypeError, ValueError) as exc:
            raise TypeError(f"{name} must return a float array, got {type(out).__name__}") from exc
        if out.shape != shape:
            raise ValueError(
                f"{name}(psi, x) returned shape {out.shape} for x of shape {x.shape}; "
                f"expected {shape} (it must be vectorised over the first axis of x)"
            )
        bad = ~np.isfinite(out)
        if bad.any():
            i = int(np.flatnonzero(bad.reshape(shape[0], -1).any(axis=1))[0])
            raise ValueError(
                f"{name}(psi, x) returned a non-finite value at psi={psi[i]:.6g}, "
                f"x={np.array2string(x[i], precision=6)}: it must be finite on the whole "
                "domain searched (reduce A or the scales, or fix the function)"
            )
        return out

    def w(self, psi: np.ndarray, x: np.ndarray) -> np.ndarray:
        self.count += x.shape[0]
        return self._check("W", self.W(psi, x), (x.shape[0],), psi, x)

    def rhs(self, psi: np.ndarray, x: np.ndarray) -> np.ndarray:
        return self._check("f", self.f(psi, x), x.shape, psi, x)

    def dw(self, psi: np.ndarray, x: np.ndarray) -> np.ndarray:
        if self.dW_user is not None:
            self.count += x.shape[0]
            return self._check("dW", self.dW_user(psi, x), (x.shape[0],), psi, x)
        fx = self.rhs(psi, x)
        h = self.h
        self.count += 2 * x.shape[0]
        wp = self._check("W", self.W(psi + h, x + h * fx), (x.shape[0],), psi, x)
        wm = self._check("W", self.W(psi - h, x - h * fx), (x.shape[0],), psi, x)
        return (wp - wm) / (2 * h)


def orbital_derivative(
    f: Function, W: Function, psi: np.ndarray, x: np.ndarray, *, h: float = 1e-4
) -> np.ndarray:
    """Derivative of ``W`` along the solutions of ``x' = f(psi, x)``, by central differences.

    ``W' = dW/dpsi + grad W . f`` is the directional derivative of ``W`` along ``(1, f)`` in
    ``(psi, x)`` space, so one central difference along that direction gives it:
    ``W' ~ [W(psi + h, x + h f) - W(psi - h, x - h f)] / (2 h)``. The truncation error is
    ``h**2 / 6`` times the third derivative of ``W`` along the direction (about 1e-9
    relative for ``h = 1e-4`` and smooth ``W`` of unit scale) and the round-off error about
    ``eps |W| / h`` (about 1e-12 relative).

    Parameters
    ----------
    f, W : callable
        Vectorised right-hand side and Liapunov function.
    psi : numpy.ndarray
        Azimuths, shape ``(m,)``.
    x : numpy.ndarray
        States, shape ``(m, n)``.
    h : float
        Step along ``(1, f)``.

    Returns
    -------
    numpy.ndarray
        ``W'`` at each state, shape ``(m,)``.
    """
    x = np.asarray(x, dtype=float)
    psi = np.broadcast_to(np.asarray(psi, dtype=float), (x.shape[0],))
    return _Checked(f, W, None, x.shape[1], h).dw(psi, x)




def technical_stability(
    f: Function,
    W: Function,
    A: float,
    *,
    period: float = 2 * np.pi,
    scales=None,
    n_psi: int = 72,
    dW: Function | None = None,
    dim: int | None = None,
    n_sphere: int = 1024,
    n_radii: int = 12,
    n_shells: int = 5,
    n_bisect: int = 12,
    n_refine: int = 4,
    n_iter: int = 40,
    rtol: float = 1e-9,
    fd_step: float = 1e-4,
    seed: int = 0,
    test_directions=None,
) -> TechnicalStabilityResult:
    """Certify bounded motion of ``x' = f(psi, x)`` with the Liapunov function ``W``.

    Runs steps 3-6 of Narkiewicz & Lucjanek's algorithm (module docstring) and returns, for
    each of ``n_psi`` azimuths, the radius ``lambda0`` of a start region from which every
    motion stays inside ``||x|| < A``.

    Parameters
    ----------
    f : callable
        ``f(psi, x)``: right-hand side, ``x`` of shape ``(m, n)``, ``psi`` of shape ``(m,)``;
        returns ``(m, n)``. Periodic in ``psi`` with period ``period``.
    W : callable
        ``W(psi, x)``: candidate Liapunov function, returns ``(m,)``. The caller is
        responsible for conditions (c)-(g) of the theorem (continuity, positivity,
        periodicity); the engine checks only what the algorithm needs.
    A : float
        Requested bound of the scaled norm (> 0).
    period : float
        The period ``T`` (> 0).
    scales : array_like, optional
        The ``a_i`` of the norm ``||x|| = sqrt(sum((x_i / a_i)**2))``, all > 0. Default: ones
        (then ``dim`` is required).
    n_psi : int
        Number of azimuths ``psi_j = j T / n_psi`` for steps 5 and 6, and the azimuth grid of
        the sampling in steps 3 and 4 (refinement then lets the azimuth move freely).
    dW : callable, optional
        ``dW(psi, x)`` = ``W'`` along the solutions, returns ``(m,)``. If omitted it is
        computed by :func:`orbital_derivative` (one central difference along ``(1, f)``).
    dim : int, optional
        State dimension ``n``; needed only when ``scales`` is omitted.
    n_sphere : int
        Quasi-random directions per sphere (rounded up to a power of two), in addition to the
        ``2 n**2`` structured directions. Default 1024: the book's convergence study shows
        ``lambda0`` converged to better than 1 % on its examples.
    n_radii : int
        Radii of the scan used to find ``A1`` (step 3) and to bracket ``lambda0`` (step 5).
    n_shells : int
        Sampled radii across each shell in step 6.
    n_bisect : int
        Bisection steps refining ``A1`` and each ``lambda0``.
    n_refine : int
        Best samples refined by local ascent, per azimuth (or overall).
    n_iter : int
        Iterations of each local ascent.
    rtol : float
        Round-off allowance: ``W' <= rtol * max|W|`` counts as ``W' <= 0``.
    fd_step : float
        Step of :func:`orbital_derivative` when ``dW`` is omitted.
    seed : int
        Seed of the quasi-random directions (results are deterministic for a given seed).
    test_directions : array_like, optional
        Shape ``(k, n)``: the *practical reading*. Spheres are represented only by the states
        ``rho * a * d / |d|`` for these directions ``d`` (in scaled coordinates), at the grid
        azimuths, with no quasi-random sampling and no refinement. The result then has
        ``reading="practical"``: an indicator of where ``W'`` is positive along the chosen
        disturbances, not a certificate.

    Returns
    -------
    TechnicalStabilityResult
        Named fields ``A_requested, scales, A, alpha, psi, lambda0, max_dW, stable``, and
        more; ``stable`` all False (not an exception) when nothing can be certified.

    Raises
    ------
    ValueError
        Non-positive ``A``, ``period`` or scale; wrong shapes; non-finite values returned by
        ``f``, ``W`` or ``dW``; bad resolution parameters.
    TypeError
        ``f``, ``W`` or ``dW`` not callable; neither ``scales`` nor ``dim`` given.
    """
    for name, fun in (("f", f), ("W", W)):
        if not callable(fun):
            raise TypeError(f"{name} must be callable as {name}(psi, x), got {type(fun).__name__}")
    if dW is not None and not callable(dW):
        raise TypeError(f"dW must be callable as dW(psi, x) or None, got {type(dW).__name__}")
    A = _positive_float("A", A)
    period = _positive_float("period", period)
    if scales is None:
        if dim is None:
            raise TypeError("give the norm scales (scales=[a_1, ..., a_n]) or the state dimension dim")
        n = _positive_int("dim", dim)
        scales = np.ones(n)
    else:
        scales = np.array(scales, dtype=float).reshape(-1)
        if scales.size == 0:
            raise ValueError("scales must hold one positive number per state component")
        if dim is not None and int(dim) != scales.size:
            raise ValueError(f"dim={dim} does not match len(scales)={scales.size}")
        if not np.all(np.isfinite(scales)) or np.any(scales <= 0):
            raise ValueError(f"every scale a_i must be finite and > 0, got {scales.tolist()}")
        n = scales.size
    n_psi = _positive_int("n_psi", n_psi)
    n_sphere = _positive_int("n_sphere", n_sphere, 0)
    n_radii = _positive_int("n_radii", n_radii)
    n_shells = _positive_int("n_shells", n_shells)
    n_bisect = _positive_int("n_bisect", n_bisect, 0)
    n_refine = _positive_int("n_refine", n_refine)
    n_iter = _positive_int("n_iter", n_iter, 0)
    rtol = float(rtol)
    if not (np.isfinite(rtol) and rtol >= 0):
        raise ValueError(f"rtol must be finite and >= 0, got {rtol!r}")
    fd_step = _positive_float("fd_step", fd_step)

    sys = _Checked(f, W, dW, n, fd_step * period / (2 * np.pi))
    if test_directions is None:
        reading = "strict"
        dirs = unit_sphere_points(n, n_sphere, seed)
        free = True
    else:
        reading = "practical"
        dirs = np.array(test_directions, dtype=float)
        if dirs.ndim != 2 or dirs.shape[1] != n or dirs.shape[0] == 0:
            raise ValueError(f"test_directions must have shape (k, {n}) with k >= 1, got {dirs.shape}")
        norms = np.linalg.norm(dirs, axis=1)
        if not np.all(np.isfinite(dirs)) or np.any(norms == 0):
            raise ValueError("test_directions must be finite and non-zero")
        dirs = dirs / norms[:, None]
        n_iter, free = 0, False
    psi = period * np.arange(n_psi) / n_psi
    common = dict(period=period, n_refine=n_refine, n_iter=n_iter)

    # shape check with one state before any heavy work
    x0 = (0.5 * A * dirs[:1]) * scales
    sys.rhs(psi[:1], x0)
    sys.w(psi[:1], x0)

    # round-off allowance from the size of W on the requested sphere
    w_scale = sphere_extremum(
        lambda p, x: np.abs(sys.w(p, x)), psi, A, scales, dirs, per_psi=False,
        period=period, n_refine=1, n_iter=0,
    ).value[0]
    tol = rtol * w_scale

    def sphere_max_dw(radius: float, stop: bool) -> float:
        ext = sphere_extremum(
            sys.dw, psi, radius, scales, dirs, per_psi=False, free_psi=free,
            stop_above=tol if stop else None, **common,
        )
        return float(ext.value[0])

    # step 3
    step3 = sphere_max_dw(A, stop=False)
    if step3 <= tol:
        A_used = A
    else:
        grid = np.unique(np.concatenate([
            A * np.arange(1, n_radii) / n_radii,
            np.geomspace(A * 1e-4, A, n_radii, endpoint=False),
        ]))[::-1]
        A_used, failing = 0.0, A
        for radius in grid:
            if sphere_max_dw(radius, stop=True) <= tol:
                A_used = radius
                break
            failing = radius
        if A_used > 0:
            lo, hi = A_used, failing
            for _ in range(n_bisect):
                mid = 0.5 * (lo + hi)
                if sphere_max_dw(mid, stop=True) <= tol:
                    lo = mid
                else:
                    hi = mid
            A_used = lo

    if A_used == 0.0:
        ext = sphere_extremum(sys.dw, psi, A, scales, dirs, **common)
        return TechnicalStabilityResult(
            A_requested=A, scales=scales, A=0.0, alpha=0.0, psi=psi,
            lambda0=np.zeros(n_psi), max_dW=ext.value, argmax_dW=ext.x,
            stable=np.zeros(n_psi, dtype=bool), period=period, step3_max_dW=step3, tol=tol,
            message=(
                f"nothing {'certified' if reading == 'strict' else 'indicated stable'}: W' > 0 "
                f"was found on every sphere tested for radii from {A * 1e-4:.3g} to A = {A:.3g} "
                f"(step 3); max W' on ||x|| = A is {step3:.3g}"
            ),
            reading=reading, n_evaluations=sys.count,
        )

    # step 4
    alpha = float(sphere_extremum(
        sys.w, psi, A_used, scales, dirs, kind="min", per_psi=False, free_psi=free, **common,
    ).value[0])

    # step 5: lambda0_j = largest radius whose ball has sup W < alpha
    radii = A_used * np.arange(1, n_radii + 1) / n_radii
    sup_w = np.empty((n_psi, n_radii))
    for i, radius in enumerate(radii):
        sup_w[:, i] = sphere_extremum(sys.w, psi, radius, scales, dirs, **common).value
    running = np.maximum.accumulate(sup_w, axis=1)
    reach = running >= alpha
    first = np.where(reach.any(axis=1), np.argmax(reach, axis=1), n_radii)
    lo = np.where(first > 0, radii[np.maximum(first - 1, 0)], 0.0)
    hi = np.where(first < n_radii, radii[np.minimum(first, n_radii - 1)], A_used)
    todo = first < n_radii
    for _ in range(n_bisect):
        if not todo.any():
            break
        mid = 0.5 * (lo + hi)
        s = np.full(n_psi, np.inf)
        s[todo] = sphere_extremum(sys.w, psi[todo], mid[todo], scales, dirs, **common).value
        below = s < alpha
        lo = np.where(todo & below, mid, lo)
        hi = np.where(todo & ~below, mid, hi)
    lambda0 = np.where(todo, lo, A_used)

    # step 6: max W' on the shell lambda0_j < ||x|| <= A
    ext = sphere_extremum(
        sys.dw, psi, None, scales, dirs, shell=(lambda0, np.full(n_psi, A_used)),
        n_levels=n_shells, **common,
    )
    stable = (lambda0 > 0) & (ext.value <= tol)
    n_ok = int(stable.sum())
    reduced = "" if A_used == A else f" (step 3 reduced A from {A:.4g} to {A_used:.4g})"
    verb = "certified" if reading == "strict" else "indicated stable (practical reading, not a certificate)"
    message = f"{verb} at {n_ok} of {n_psi} azimuths{reduced}"
    return TechnicalStabilityResult(
        A_requested=A, scales=scales, A=float(A_used), alpha=alpha, psi=psi,
        lambda0=lambda0, max_dW=ext.value, argmax_dW=ext.x, stable=stable, period=period,
        step3_max_dW=step3, tol=tol, message=message, reading=reading, n_evaluations=sys.count,
    )
