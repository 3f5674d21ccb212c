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

Step 6 at one azimuth is the paper's algorithm (``rule="paper"``); it is not the theorem when
``f`` or ``W`` depends on ``psi``, since a motion started at ``psi_j`` lives at later azimuths.
The default strict reading (``rule="sound"``) checks the theorem's condition (h) over the
whole period on the band between the level ``alpha`` and the bound ``A`` (:func:`band_max_dw`)
and certifies all azimuths or none.

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
from ..progress import report
from .polish import T_MIN, polish
from .sampling import Extremum, PsiFree, sphere_extremum, unit_sphere_points
from .sampling import psi_free as _is_psi_free

__all__ = ["RULES", "TechnicalStabilityResult", "band_max_dw", "technical_stability",
           "orbital_derivative", "quadratic_matrix"]

RULES = ("paper", "sound")
"""How :func:`technical_stability` checks condition (h): the paper's step 6 at each start
azimuth, or the theorem's (h) over the whole period."""

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
    rule : str
        ``"paper"`` (step 6 at each start azimuth: the paper's algorithm) or ``"sound"`` (the
        theorem's (h) over the whole period); see :func:`technical_stability`.
    level : float
        ``rule="sound"``: the level ``c`` of ``W`` that bounds the start regions (``alpha``);
        NaN for the paper's rule.
    band_max_dW : float
        ``rule="sound"``: the largest ``W'`` found on the band ``||x|| <= A, W >= c`` over the
        whole period (negative, below the margin, where certified); NaN for the paper's rule.
    check_evaluations : int
        ``rule="sound"``: the states at which the final check of the certified bound (the
        thorough band search at ``A``) evaluated ``W'``: the search an adversary must beat. (The
        ``W`` evaluations that place each point on the band, up to some 60 per point where
        ``W`` is not a quadratic form, are counted in ``n_evaluations`` only.)
    A_step3 : float
        Step 3's bound ``A1``: the largest radius up to ``A_requested`` with ``W' <= 0`` on the
        sphere itself over the period (0 if none). The paper's rule uses it as ``A``; the sound
        rule may reduce ``A`` further, until (h) holds on the whole band.
    alpha_source : str
        How ``alpha`` (and the start radii) were found: ``"closed form"`` (a quadratic ``W``:
        the least eigenvalue of its matrix in the norm's scaling, minimised over the period,
        widened by :data:`EIGENVALUE_ROUNDOFF`; the start radii from the largest eigenvalue),
        ``"search"`` (the least ``W`` a sphere search found: at or *above* the exact infimum, so
        with the paper's rule an indicator, not a bound; measured: on the Table I hover quadratic
        functions, before the closed form was used, the search overshot the infimum by 0.6 %,
        1.1 % and 33 % for the forward, neutral and backward C.G.; on chapter 2's oscillator
        (:func:`rotorlyap.methods.examples.mathieu_duffing`, ``n_psi=72``) it lies within 1e-8 of
        the least value on a grid of 2001 azimuths by 20001 directions), ``"test directions"`` (the
        practical reading: the least ``W`` along the test directions, the paper's indicator)
        or ``""`` (nothing certified, no level).
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
    rule: str = "paper"
    check_evaluations: int = field(default=0, compare=False)
    level: float = float("nan")
    band_max_dW: float = float("nan")
    A_step3: float = float("nan")
    alpha_source: str = ""

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
        self.count = 0     # states at which W or W' was evaluated
        self.count_dw = 0  # states at which W' was evaluated (the points a search examined)

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
        self.count_dw += x.shape[0]
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
    rule: str | None = None,
    w_matrix: Callable[[np.ndarray], np.ndarray] | None = None,
    margin: float = 1e-6,
    autonomous: bool = False,
    band: str = "level",
    psi_free: bool = False,
) -> TechnicalStabilityResult:
    """Run the six-step algorithm for ``x' = f(psi, x)`` with the Liapunov function ``W``: a
    numerical certificate of bounded motion with the sound rule, the paper's indicator with the
    paper's rule.

    Runs steps 3-6 of Narkiewicz & Lucjanek's algorithm (module docstring) and returns, for
    each of ``n_psi`` azimuths, the radius ``lambda0`` of a start region. With
    ``rule="sound"`` every motion started inside it stays inside ``||x|| < A`` as far as the
    search of the band can tell (a numerical certificate, not a proof); with ``rule="paper"``
    step 6 is checked at the start azimuth alone, and an azimuth where it holds only passes
    the paper's indicator (its motions can leave the bound, chapter 2 of the book).

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
        Bisection steps refining ``A1`` and each ``lambda0``; with ``rule="sound"`` also the
        most steps refining the bound below ``A1`` where (h) holds on the band (which stops
        once known to :data:`BOUND_RTOL`).
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
    rule : {"paper", "sound"}, optional
        How condition (h) of the theorem is checked. Default: ``"sound"`` for the strict
        reading (the certificate), ``"paper"`` for the practical reading (``test_directions``
        given: the paper's indicator). ``"paper"``: the paper's algorithm, step 6
        at each start azimuth alone (``W' <= 0`` on the shell ``lambda0_j < ||x|| <= A`` at
        ``psi_j``); when ``f`` or ``W`` depends on ``psi`` this does not follow from the theorem
        (a motion started at ``psi_j`` lives at later azimuths), so its verdicts are the
        paper's, not certificates. ``"sound"``: the theorem's (h) over the whole period: with
        ``c = alpha``, ``W' < 0`` at every ``psi`` and every ``x`` of the band
        ``||x|| <= A, W(psi, x) >= c`` (searched over the period, the azimuth free), below
        ``-margin``; ``A`` is reduced until it holds, and then every azimuth with
        ``lambda0_j > 0`` is certified (all or nothing). See :func:`band_max_dw`.
    w_matrix : callable, optional
        For a quadratic ``W(psi, x) = y^T S(psi) y`` in the scaled coordinates ``y_i = x_i /
        a_i``: ``w_matrix(psi)`` returns ``S`` of shape ``psi.shape + (n, n)``, symmetric.
        Then the extrema of ``W`` on spheres are closed forms (``rho^2`` times the extreme
        eigenvalues of ``S``: steps 4 and 5 without a search, in both rules) and, with
        ``rule="sound"``, the band's inner boundary along each ray too. Default: where ``W``
        is the bound method of an object with a ``w_matrix(scales)`` method (a
        :class:`rotorlyap.analysis.functions.QuadraticFunction`), that (:func:`quadratic_matrix`);
        else None (searches). Not used by the practical reading (``test_directions``), whose
        level is the least ``W`` along the test directions by definition.
    margin : float
        ``rule="sound"``: certify only where the largest ``W'`` found on the band is below
        ``-margin`` times the largest ``|W|`` on the sphere ``||x|| = A`` (per unit azimuth), a
        relative margin against the search missing the true maximum by a little.
    autonomous : bool
        Only with ``rule="sound"``: ``f`` and ``W`` do not depend on ``psi`` (an autonomous
        system, such as the blade in hover about its equilibrium, and a function without
        azimuth). The searches then keep the azimuth at 0 instead of moving it over the period,
        and every azimuth of the grid gets the same start radius: the same theorem, searched
        in one azimuth instead of ``n_psi``. The caller vouches that nothing depends on ``psi``.
    psi_free : bool
        ``f``, ``W`` and ``W'`` do not depend on ``psi``, to the last bit (the blade in hover
        without cyclic pitch about its equilibrium, a constant ``W``). Unlike ``autonomous``
        the search is not changed: every azimuth is searched as without it, but the values
        of one azimuth stand for all and each distinct start is refined once
        (:class:`rotorlyap.methods.sampling.PsiFree`), so the result is the same, bit for bit;
        the skipped states are credited to the evaluation counts at the rate of those evaluated
        (exact where every state costs the same). The caller vouches for the independence
        (:func:`rotorlyap.analysis.stability.blade_stability` checks it).
    band : {"level", "shell"}
        Only with ``rule="sound"``: where (h) is searched. ``"level"``: the band ``||x|| <= A,
        W >= c`` itself, ray by ray from the level set (closed form for a quadratic ``W``, a
        root search along each ray otherwise). ``"shell"``: the shell ``rho <= ||x|| <= A``, with
        ``rho`` the largest radius whose ball lies in ``{W < c}`` at every azimuth of the period
        (a search of ``sup W`` on spheres, the azimuth free): it contains the band, so (h) there
        implies (h) on the band; it asks more of ``W'`` (also on the states of the shell inside
        the level set) and costs many times less where ``W`` has no closed form. For functions
        designed to decrease on a shell (:mod:`rotorlyap.methods.scenario`), whose ``W`` has
        several local extrema on a sphere: the searches of ``W`` (the level ``alpha``, the start
        radii and ``rho``) then refine 64 of the best samples for 200 iterations, not
        ``n_refine`` for ``n_iter``, the 32 best minima on the sphere are polished (:func:`rotorlyap.methods.polish.polish`),
        and the level is set :data:`SHELL_LEVEL_MARGIN` below the smallest ``W`` found (the start
        radii, with no closed form, where the largest ``W`` found reaches the level less the same
        margin).
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
    if rule is None:
        rule = "paper" if test_directions is not None else "sound"
    if rule not in RULES:
        raise ValueError(f"rule must be one of {RULES} (or None for the reading's default), got {rule!r}")
    if w_matrix is not None and not callable(w_matrix):
        raise TypeError(f"w_matrix must be callable as w_matrix(psi) or None, got {type(w_matrix).__name__}")
    if w_matrix is not None and test_directions is not None:
        raise ValueError("w_matrix is not used by the practical reading (test_directions): its level "
                         "is the least W along the test directions")
    if w_matrix is None and test_directions is None:  # a quadratic W that knows its matrix
        w_matrix = quadratic_matrix(W, scales)
    margin = float(margin)
    if not (np.isfinite(margin) and margin >= 0):
        raise ValueError(f"margin must be finite and >= 0, got {margin!r}")
    if autonomous and rule != "sound":
        raise ValueError("autonomous=True is an option of rule='sound' only")
    if band not in ("level", "shell"):
        raise ValueError(f"band must be 'level' or 'shell', got {band!r}")
    if band == "shell" and rule != "sound":
        raise ValueError("band='shell' is an option of rule='sound' only")
    if rule == "sound" and test_directions is not None:
        raise ValueError("rule='sound' searches whole spheres; the practical reading "
                         "(test_directions) is the paper's rule only")

    sys = _Checked(f, W, dW, n, fd_step * period / (2 * np.pi))
    if psi_free:  # one azimuth's values stand for all (the same answer, less work)
        sys.dw, sys.w = PsiFree(sys.dw, sys), PsiFree(sys.w, sys)
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
    if rule == "sound":
        return _sound(sys, w_matrix, A, psi, period, scales, dirs, common, n_radii=n_radii,
                      n_shells=n_shells, n_bisect=n_bisect, rtol=rtol, margin=margin,
                      autonomous=bool(autonomous), shell=band == "shell", psi_free=bool(psi_free))

    # round-off allowance from the size of W on the requested sphere
    w_scale = sphere_extremum(
        _like(sys.w, lambda p, x: np.abs(sys.w(p, x))), psi, A, scales, dirs, per_psi=False,
        period=period, n_refine=1, n_iter=0,
    ).value[0]
    tol = rtol * w_scale

    # step 3
    A_used, step3 = _step3(sys, A, psi, scales, dirs, free, common, tol, n_radii, n_bisect)

    if A_used == 0.0:
        ext = sphere_extremum(sys.dw, psi, A, scales, dirs, **common)
        return TechnicalStabilityResult(
            A_requested=A, scales=scales, A=0.0, alpha=0.0, psi=psi,
            lambda0=np.zeros(n_psi), max_dW=ext.value, argmax_dW=ext.x,
            stable=np.zeros(n_psi, dtype=bool), period=period, step3_max_dW=step3, tol=tol,
            message=(
                f"the indicator fails at every azimuth: W' > 0 "
                f"was found on every sphere tested for radii from {A * 1e-4:.3g} to A = {A:.3g} "
                f"(step 3); max W' on ||x|| = A is {step3:.3g}"
            ),
            reading=reading, n_evaluations=sys.count, A_step3=0.0,
        )

    # step 4: alpha = inf W on the sphere A over the period; a quadratic W's in closed form (the
    # sound rule's), else the least W a search found (at or above the infimum: the paper's indicator)
    if w_matrix is not None:
        alpha = _Level(sys, w_matrix, psi, period, scales, dirs, common, free=free, shell=False,
                       n_radii=n_radii, n_bisect=n_bisect).sphere_min(A_used)
        alpha_source = "closed form"
    else:
        alpha = float(sphere_extremum(
            sys.w, psi, A_used, scales, dirs, kind="min", per_psi=False, free_psi=free, **common,
        ).value[0])
        alpha_source = "search" if reading == "strict" else "test directions"

    # step 5: lambda0_j = largest radius whose ball has sup W < alpha
    if w_matrix is not None:
        lambda0 = _closed_form_start_radii(w_matrix, psi, alpha, A_used)
    else:
        lambda0 = _start_radii(sys, psi, A_used, alpha, scales, dirs, common, n_radii, n_bisect)

    # step 6: max W' on the shell lambda0_j < ||x|| <= A
    ext = sphere_extremum(
        sys.dw, psi, None, scales, dirs, shell=(lambda0, np.full(n_psi, A_used)),
        n_levels=n_shells, **common,
    )
    stable = (lambda0 > 0) & (ext.value <= tol)
    n_ok = int(stable.sum())
    reduced = "" if A_used == A else f" (step 3 reduced A from {A:.4g} to {A_used:.4g})"
    # the paper's rule is an indicator in either reading, never a certificate (the book's glossary)
    message = f"the indicator holds at {n_ok} of {n_psi} azimuths{reduced}"
    return TechnicalStabilityResult(
        A_requested=A, scales=scales, A=float(A_used), alpha=alpha, psi=psi,
        lambda0=lambda0, max_dW=ext.value, argmax_dW=ext.x, stable=stable, period=period,
        step3_max_dW=step3, tol=tol, message=message, reading=reading, n_evaluations=sys.count,
        A_step3=float(A_used), alpha_source=alpha_source,
    )


def _start_radii(sys, psi, A_used, level, scales, dirs, common, n_radii, n_bisect,
                 rtol: float = 0.0) -> np.ndarray:
    """Step 5: at each azimuth the largest radius (at most ``A_used``) whose ball has
    ``sup W < level``: a scan of ``n_radii`` spheres, then at most ``n_bisect`` bisection steps,
    an azimuth's ending once its bracket is within ``rtol`` of its upper end (0: all steps).

    Only each sphere's verdict ``sup W < level`` matters, so an azimuth's scan ends at its first
    sphere that reaches the level, and every search stops refining an azimuth once a value
    reaches the level (``settle_at`` of :func:`~rotorlyap.methods.sampling.sphere_extremum`):
    the verdicts, and so the radii, of the full searches of every sphere, for about half their
    work (the spheres beyond the crossing and the searches that cross are most of it)."""
    n_psi = psi.size
    radii = A_used * np.arange(1, n_radii + 1) / n_radii
    first = np.full(n_psi, n_radii)  # the first sphere of each azimuth whose search reaches the level
    for i, radius in enumerate(radii):
        scanning = np.flatnonzero(first == n_radii)
        if scanning.size == 0:
            break
        report("sound rule: start radii", i + 1, n_radii + n_bisect)
        top = sphere_extremum(sys.w, psi[scanning], radius, scales, dirs, settle_at=level, **common).value
        first[scanning[top >= level]] = i
    lo = np.where(first > 0, radii[np.maximum(first - 1, 0)], 0.0)
    hi = np.where(first < n_radii, radii[np.minimum(first, n_radii - 1)], A_used)
    todo = first < n_radii
    for k in range(n_bisect):
        todo &= hi - lo > rtol * hi
        if not todo.any():
            break
        report("sound rule: start radii", n_radii + k + 1, n_radii + n_bisect)
        mid = 0.5 * (lo + hi)
        s = np.full(n_psi, np.inf)
        s[todo] = sphere_extremum(sys.w, psi[todo], mid[todo], scales, dirs, settle_at=level, **common).value
        below = s < level
        lo = np.where(todo & below, mid, lo)
        hi = np.where(todo & ~below, mid, hi)
    return np.where(first < n_radii, lo, A_used)


#: With ``band="shell"`` the level is set this fraction below the smallest ``W`` the search found
#: on the sphere ``A`` (a ``W`` without closed form: a search misses its minimum by a little).
SHELL_LEVEL_MARGIN = 1e-3


def _inner_radius(sys, psi, A, level, scales, dirs, common, n_radii, n_bisect, free) -> float:
    """The largest radius (at most ``A``) whose ball lies in ``{W(psi, .) < level}`` at every
    azimuth of the period: :func:`_start_radii` with the azimuth free in the searches (a scan of
    ``n_radii`` spheres, then ``n_bisect`` bisection steps), less 0.1 % for the search's error.
    Only each sphere's verdict ``sup W >= level`` matters: a search stops at the first value
    above the level (``stop_above``), the verdict of the full search."""
    def top(radius):
        return float(sphere_extremum(sys.w, psi, radius, scales, dirs, per_psi=False, free_psi=free,
                                     stop_above=level, **common).value[0])

    radii = A * np.arange(1, n_radii + 1) / n_radii
    lo, hi = 0.0, None
    for radius in radii:
        if top(radius) >= level:
            hi = radius
            break
        lo = radius
    if hi is None:
        return A
    for _ in range(n_bisect):
        mid = 0.5 * (lo + hi)
        if top(mid) < level:
            lo = mid
        else:
            hi = mid
    return 0.999 * lo


def _step3(sys, A, psi, scales, dirs, free, common, tol, n_radii, n_bisect, *, A_max=None):
    """Step 3: ``(A_used, max W' on the sphere A)`` with ``A_used`` the largest radius found
    with ``W' <= tol`` on its sphere over the whole period (0 if none). ``tol``: a number, or a
    function of the radius."""
    tol_of = tol if callable(tol) else (lambda radius: tol)

    def sphere_max_dw(radius: float, stop: bool) -> float:
        ext = sphere_extremum(
            sys.dw, psi, radius, scales, dirs, per_psi=False, free_psi=free,
            stop_above=tol_of(radius) if stop else None, **common,
        )
        return float(ext.value[0])

    step3 = sphere_max_dw(A, stop=False)
    if step3 <= tol_of(A):
        return A, step3
    grid = np.unique(np.concatenate([
        A * np.arange(1, n_radii) / n_radii,
        np.geomspace(A * 1e-4, A, n_radii, endpoint=False),
    ]))[::-1]
    A_used, failing = 0.0, A
    for radius in grid:
        if sphere_max_dw(radius, stop=True) <= tol_of(radius):
            A_used = radius
            break
        failing = radius
    if A_used > 0:
        lo, hi = A_used, failing
        for _ in range(n_bisect):
            mid = 0.5 * (lo + hi)
            if sphere_max_dw(mid, stop=True) <= tol_of(mid):
                lo = mid
            else:
                hi = mid
        A_used = lo
    return float(A_used), step3


# --------------------------------------------------------------------------------------
# The theorem's condition (h) over the whole period (rule="sound")
# --------------------------------------------------------------------------------------


EIGENVALUE_ROUNDOFF = 1e-12
"""Allowance for the round-off of a symmetric eigen-solver, relative to the largest eigenvalue
(its error bound is a small multiple of ``n eps ||S||``): the closed-form extrema of a
quadratic ``W`` are widened by it, on the safe side (``inf W`` lower, ``sup W`` higher)."""


def _extreme_eigenvalues(w_matrix, psi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Smallest and largest eigenvalues of the symmetric part of ``w_matrix(psi)``, widened by
    :data:`EIGENVALUE_ROUNDOFF` so that they bound the exact ones."""
    psi = np.asarray(psi, dtype=float)
    S = np.asarray(w_matrix(psi), dtype=float)
    if S.ndim < 2 or S.shape[:-2] != psi.shape or S.shape[-1] != S.shape[-2]:
        raise ValueError(f"w_matrix(psi) must return one square matrix per azimuth, shape "
                         f"{psi.shape} + (n, n), got {S.shape} for psi of shape {psi.shape}")
    if not np.all(np.isfinite(S)):
        raise ValueError("w_matrix(psi) returned non-finite values")
    ev = np.linalg.eigvalsh(0.5 * (S + np.swapaxes(S, -1, -2)))
    slack = EIGENVALUE_ROUNDOFF * np.abs(ev).max(axis=-1)
    return ev[..., 0] - slack, ev[..., -1] + slack


def _closed_form_start_radii(w_matrix, psi: np.ndarray, level: float, A: float) -> np.ndarray:
    """Step 5 for a quadratic ``W = y^T S(psi) y``: at each azimuth the largest radius (at most
    ``A``) whose ball has ``sup W < level``, ``sqrt(level / l_max(S(psi_j)))`` (the largest
    eigenvalue widened by :data:`EIGENVALUE_ROUNDOFF`: on the safe side)."""
    lam_max = _extreme_eigenvalues(w_matrix, psi)[1]
    return np.minimum(np.sqrt(level / lam_max), A)


def quadratic_matrix(W: Function, scales: np.ndarray) -> Callable[[np.ndarray], np.ndarray] | None:
    """The matrix ``S(psi)`` of a quadratic ``W = y^T S y`` in the scaled coordinates ``y = x / a``
    (``a = scales``), where ``W`` is the bound method of an object with a ``w_matrix(scales)``
    method (:meth:`rotorlyap.analysis.functions.QuadraticFunction.w_matrix`); else None.

    Parameters
    ----------
    W : callable
        The function ``W(psi, x)``.
    scales : numpy.ndarray
        The norm's scales ``a_i``.

    Returns
    -------
    callable or None
        ``S(psi)``, shape ``psi.shape + (n, n)``, or None where ``W`` does not say it is quadratic.
    """
    owner = getattr(W, "__self__", None)
    make = getattr(owner, "w_matrix", None)
    if make is None or getattr(owner, "W", None) != W or not callable(make):
        return None
    return make(np.asarray(scales, dtype=float))


def _min_over_period(g: Callable[[np.ndarray], np.ndarray], period: float, n: int = 4096) -> float:
    """Minimum over one period of a smooth periodic scalar function of psi: a uniform grid of
    ``n`` points, then a bounded scalar search around each of the best three."""
    from scipy.optimize import minimize_scalar

    grid = period * np.arange(n) / n
    vals = np.asarray(g(grid), dtype=float)
    best = float(vals.min())
    h = period / n
    for i in np.argsort(vals)[:3]:
        res = minimize_scalar(lambda p: float(g(np.array([p]))[0]), bounds=(grid[i] - h, grid[i] + h),
                              method="bounded", options={"xatol": 1e-12 * period})
        best = min(best, float(res.fun))
    return best


def _ray_level(sys, psi: np.ndarray, u: np.ndarray, scales: np.ndarray, c: float, A: float,
               w_matrix, n_scan: int = 16, n_bisect: int = 40, below: bool = False) -> np.ndarray:
    """First radius along each ray ``r u`` (``u`` unit, scaled coordinates) where ``W >= c``,
    at most ``A`` (``A`` where ``W < c`` on the whole ray up to ``A``). ``below=True`` returns
    the lower end of the final bracket instead (``W < c`` there and at every scanned radius
    before it, 1e-13 ``A`` or less below the crossing): the side a start set may use."""
    if w_matrix is not None:  # W = r^2 u^T S u = r^2 W(psi, u a): no matrix needed
        q = sys.w(psi, u * scales)
        with np.errstate(divide="ignore", invalid="ignore"):
            r = np.sqrt(c / q)
        return np.where(q > 0, np.minimum(r, A), A)
    m = u.shape[0]
    radii = A * np.arange(1, n_scan + 1) / n_scan
    w = sys.w(np.repeat(psi, n_scan), (np.repeat(u, n_scan, axis=0) * np.tile(radii, m)[:, None]) * scales)
    above = w.reshape(m, n_scan) >= c
    first = np.where(above.any(axis=1), np.argmax(above, axis=1), n_scan)
    hi = np.where(first < n_scan, radii[np.minimum(first, n_scan - 1)], A)
    lo = np.where(first > 0, radii[np.maximum(first - 1, 0)], 0.0)
    todo = first < n_scan
    # the bracket [lo, hi] (W < c at lo, W >= c at hi) narrowed by the Illinois variant of
    # regula falsi: superlinear for a smooth W, never leaving the bracket, and a bisection step
    # wherever an end has stayed put twice (so at most as slow as bisection)
    flat = w.reshape(m, n_scan)
    w_hi = np.where(todo, flat[np.arange(m), np.minimum(first, n_scan - 1)] - c, 0.0)
    w_lo = flat[np.arange(m), np.maximum(first - 1, 0)] - c
    at_0 = todo & (first == 0)
    if at_0.any():
        w_lo[at_0] = sys.w(psi[at_0], np.zeros((int(at_0.sum()), u.shape[1]))) - c
    stale = np.zeros(m, dtype=int)  # +k: lo kept k times in a row, -k: hi kept
    tol = 1e-13 * A
    for _ in range(n_bisect):
        todo &= hi - lo > tol
        if not todo.any():
            break
        idx = np.flatnonzero(todo)
        a_, b_, fa, fb = lo[idx], hi[idx], w_lo[idx], w_hi[idx]
        with np.errstate(invalid="ignore", divide="ignore"):
            fa_w = np.where(stale[idx] >= 2, 0.5 * fa, fa)   # Illinois: halve the stale end's value
            fb_w = np.where(stale[idx] <= -2, 0.5 * fb, fb)
            x = (a_ * fb_w - b_ * fa_w) / (fb_w - fa_w)
        bad = ~np.isfinite(x) | (x <= a_) | (x >= b_) | (np.abs(stale[idx]) >= 4)
        x = np.where(bad, 0.5 * (a_ + b_), x)
        wx = sys.w(psi[idx], (u[idx] * x[:, None]) * scales) - c
        up = wx >= 0
        hi[idx] = np.where(up, x, b_)
        w_hi[idx] = np.where(up, wx, fb)
        lo[idx] = np.where(up, a_, x)
        w_lo[idx] = np.where(up, fa, wx)
        st = stale[idx]
        stale[idx] = np.where(up, np.where(st > 0, st + 1, 1), np.where(st < 0, st - 1, -1))
        stale[idx] = np.where(bad, 0, stale[idx])
    return np.where(first < n_scan, lo, hi) if below else hi


def band_max_dw(f: Function, W: Function, dW: Function | None, c: float, A: float, *,
                scales, period: float = 2 * np.pi, psi=None, w_matrix=None, per_psi: bool = False,
                n_sphere: int = 1024, n_levels: int = 5, n_refine: int = 4, n_iter: int = 40,
                seed: int = 0, stop_above: float | None = None, fd_step: float = 1e-4,
                directions=None, n_polish: int = 256, n_sweep: int = 1024, starts: str = "levels",
                n_lbfgs: int = 64, autonomous: bool = False, inner: float | None = None,
                psi_free: bool = False):
    """Largest ``W'`` on the band ``||x|| <= A, W(psi, x) >= c`` (condition (h) of the theorem).

    The band is searched ray by ray: along each direction ``u`` (scaled coordinates) at each
    azimuth, from the first radius ``r_c(psi, u)`` where ``W`` reaches ``c`` (closed form for a
    quadratic ``W`` given by ``w_matrix``, else a scan of 16 radii and bisection) out to ``A``,
    the point ``(r_c + t (A - r_c)) u`` for ``t`` in ``[0, 1]``. Points of a ray beyond
    ``r_c`` where ``W`` dips below ``c`` again are searched too: a superset of the band, on the
    safe side. The search samples ``n_levels`` values of ``t`` and the directions of
    :func:`rotorlyap.methods.sampling.unit_sphere_points`, refines the best of each level with
    ``u`` and the azimuth free (the best of every level, not of all together: ``W'`` near the
    level set is often larger than almost everywhere on the sphere ``||x|| = A``, where a narrow
    cap may hold its maximum), then polishes them with ``t`` free too. With ``per_psi``: one
    search per azimuth over the whole band, the azimuth fixed.

    Where ``W`` and ``dW`` are bound methods of one object with a ``ray_rate`` method (a
    :class:`rotorlyap.analysis.functions.QuadraticFunction` about a tabulated motion) and
    ``w_matrix`` is given, the map from search coordinates to the band's points and ``W'``
    there run in one compiled call of it: the same numbers, counted as here.

    Parameters
    ----------
    f, W, dW : callable
        As :func:`technical_stability` takes them (``dW`` None: a central difference).
    c, A : float
        The level and the bound (scaled norm).
    scales : array_like
        Norm scales ``a_i``.
    period : float
        Period of ``f`` and ``W``.
    psi : array_like, optional
        Azimuths to start from (default 72 uniform).
    w_matrix : callable, optional
        ``S(psi)`` of a quadratic ``W`` (see :func:`technical_stability`).
    per_psi : bool
        One maximum per azimuth with the azimuth fixed (a map), instead of one over the period.
    n_sphere, n_levels, n_refine, n_iter, seed :
        Resolution of the search (as :func:`technical_stability`); ``n_levels`` values of ``t``.
    stop_above : float, optional
        Return as soon as a value found exceeds it (a sample, a candidate of a local search, a
        point of the azimuth sweep; not with ``per_psi``): then the value returned is a lower
        bound of the maximum, enough to decide that ``max W' <= stop_above`` fails.
    directions : array_like, optional
        Unit directions to sample instead of ``unit_sphere_points(n, n_sphere, seed)``.
    n_polish : int
        Without ``per_psi``: the best ``n_polish`` samples are refined by the batched ascent
        (split evenly between the levels with ``starts="levels"``).
    n_lbfgs : int
        Of those, the best ``n_lbfgs`` are polished, all at once (:func:`rotorlyap.methods.polish.polish`;
        with ``per_psi``, the one of each azimuth). On the blade's optimised hover functions the
        largest ``W'`` sits in a small cap near the flap axis, which 16 polished candidates miss
        and 256 find; the final check of :func:`technical_stability` polishes 256.
    starts : {"levels", "band"}
        Without ``per_psi``, how the starts of the local searches are chosen: ``"levels"``, the
        best samples of each level ``t`` apart; ``"band"``, the best of all samples together
        (the two find different maxima; :func:`technical_stability` verifies its certificate
        with both).
    n_sweep : int
        Without ``per_psi``: the best 256 polished candidates are then swept over ``n_sweep``
        azimuths of the period (each its ray and ``t`` kept), and the best 16 of the sweep are
        polished again. The largest ``W'`` about a computed periodic motion ripples in ``psi``
        with the period of its collocation grid (the motion's residual between nodes, ~2.8 deg
        for 256 points; 1024 azimuths put eight points on each ripple), and a local ascent
        started at a grid azimuth stops on the nearest ripple; an independent search found
        ``W' > 0`` on bands that the polish alone called negative. 0 switches the sweep off.
    autonomous : bool
        ``f`` and ``W`` do not depend on ``psi``: the azimuth stays fixed (no free azimuth in the
        local searches, no sweep).
    inner : float, optional
        Search the shell ``inner <= ||x|| <= A`` instead of the band: a superset of the band
        when the ball of radius ``inner`` lies in ``{W < c}`` at every azimuth (no level to find
        along each ray, so many times cheaper for a ``W`` without closed forms).
    psi_free : bool
        ``f``, ``W`` and ``W'`` do not depend on ``psi`` to the last bit: the same search and
        the same answer, with the work of every azimuth but one skipped
        (:class:`rotorlyap.methods.sampling.PsiFree`).

    Returns
    -------
    rotorlyap.methods.sampling.Extremum
        ``value`` (J per unit azimuth), ``psi`` and ``x`` of the maxima.
    """
    scales = np.asarray(scales, dtype=float)
    n = scales.size
    sys = f if isinstance(f, _Checked) else _Checked(f, W, dW, n, fd_step * period / (2 * np.pi))
    psi = period * np.arange(72) / 72 if psi is None else np.atleast_1d(np.asarray(psi, dtype=float))
    dirs = unit_sphere_points(n, n_sphere, seed) if directions is None else np.asarray(directions, dtype=float)

    def state(p, y):
        t = np.linalg.norm(y, axis=1)
        u = y / np.maximum(t, 1e-300)[:, None]
        rc = np.full(t.size, float(inner)) if inner is not None else _ray_level(sys, p, u, scales, c, A, w_matrix)
        r = rc + np.clip(t, 0.0, 1.0) * (A - rc)
        return (u * r[:, None]) * scales

    k = psi.size
    g = lambda p, y: sys.dw(p, state(p, y))  # noqa: E731
    ray = _ray_function(sys) if w_matrix is not None and inner is None else None
    if ray is not None:  # the map y -> x and W' in one compiled call: the same numbers
        g = _RayRate(sys, ray, g, c, A, scales)
    if psi_free:
        g = PsiFree(g, sys)
    if per_psi:
        ext = sphere_extremum(g, psi, None, np.ones(n), dirs, per_psi=True, free_psi=False,
                              period=period, shell=(np.full(k, T_MIN), np.ones(k)),
                              n_levels=n_levels, n_refine=n_refine, n_iter=n_iter)
    else:
        # the starts of the local searches are taken level by level (t fixed: the level set,
        # the sphere ||x|| = A and between), then polished with t free: W' near the level set
        # is often larger than almost everywhere on the sphere, and ranking all samples together
        # would start every local search there, missing a narrow cap of W' > 0 on the sphere
        if starts not in ("levels", "band"):
            raise ValueError(f"starts must be 'levels' or 'band', got {starts!r}")
        if starts == "band":  # one search of the whole band (t sampled at n_levels values)
            searches = [dict(radius=None, shell=(np.full(k, T_MIN), np.ones(k)), n_levels=n_levels,
                             keep=n_polish)]
        else:  # one sphere search per level t
            levels = np.linspace(T_MIN, 1.0, n_levels) if n_levels > 1 else np.ones(1)
            per = max(1, -(-n_polish // levels.size))
            searches = [dict(radius=float(t), keep=per) for t in levels]
        parts = []
        for opts in searches:
            radius = opts.pop("radius")
            e = sphere_extremum(g, psi, radius, np.ones(n), dirs, per_psi=False, free_psi=not autonomous,
                                period=period, n_refine=max(n_refine, opts["keep"]), n_iter=n_iter,
                                stop_above=stop_above, **opts)
            if stop_above is not None and e.value[0] > stop_above:
                return Extremum(e.value[:1], e.psi[:1], state(e.psi[:1], e.x[:1]))
            parts.append(e)
        ext = Extremum(np.concatenate([e.value for e in parts]), np.concatenate([e.psi for e in parts]),
                       np.concatenate([e.x for e in parts]))
    if not per_psi and ext.value.size > n_lbfgs:  # the batched ascent refined them all;
        top = np.argsort(-ext.value)[:n_lbfgs]    # quasi-Newton for the best of those
        ext = Extremum(ext.value[top], ext.psi[top], ext.x[top])
    value, p_best, y_best = polish(g, ext, free_psi=not (per_psi or autonomous),
                                   stop_above=None if per_psi else stop_above)
    if per_psi:
        return Extremum(value, p_best, state(p_best, y_best))
    if n_sweep > 0 and not autonomous and not (stop_above is not None and value.max() > stop_above):
        value, p_best, y_best = _sweep_azimuth(g, value, p_best, y_best, period, int(n_sweep),
                                               stop_above=stop_above)
    i = int(np.argmax(value))
    return Extremum(value[i:i + 1], p_best[i:i + 1], state(p_best[i:i + 1], y_best[i:i + 1]))


def _ray_function(sys: _Checked):
    """``ray_rate`` of the object that both ``W`` and ``dW`` are bound to (a
    :class:`rotorlyap.analysis.functions.QuadraticFunction`), else None."""
    owner = getattr(sys.dW_user, "__self__", None)
    ray = getattr(owner, "ray_rate", None)
    if ray is None or getattr(sys.W, "__self__", None) is not owner:
        return None
    return ray


class _RayRate:
    """``W'`` at the band's points of search coordinates ``y`` (:func:`band_max_dw`) by
    ``ray(psi, y, c, A, scales) -> (W(psi, u a), W')`` (or None: then by ``generic``), counted
    as the generic path counts; a non-finite value goes to the generic path, whose checks say
    what is wrong."""

    def __init__(self, sys: _Checked, ray, generic, c: float, A: float, scales: np.ndarray):
        self.sys, self.ray, self.generic, self.c, self.A, self.scales = sys, ray, generic, c, A, scales

    def __call__(self, psi: np.ndarray, y: np.ndarray) -> np.ndarray:
        res = self.ray(psi, y, self.c, self.A, self.scales)
        if res is None or not (np.all(np.isfinite(res[0])) and np.all(np.isfinite(res[1]))):
            return self.generic(psi, y)
        m = y.shape[0]
        self.sys.count += 2 * m  # W on the ray and W' at its point, as the generic path
        self.sys.count_dw += m
        return res[1]


def _sweep_azimuth(fun: Function, value, psi, y, period: float, n_sweep: int, n_keep: int = 16,
                   n_candidates: int = 256, stop_above: float | None = None):
    """Each candidate ``(psi_i, y_i)`` evaluated at ``n_sweep`` azimuths of the period with its
    ``y`` kept (all candidates in blocks of one vectorised call); the best ``n_keep`` new
    points polished (:func:`rotorlyap.methods.polish.polish`) with the azimuth free. Returns (values, psi, y) of the
    candidates, each never worse than before. With ``stop_above``: where the sweep finds a value
    above it, those points are returned without the polish (:func:`band_max_dw`'s early stop)."""
    grid = period * np.arange(n_sweep) / n_sweep
    value, psi, y = value.copy(), psi.copy(), y.copy()
    new_v, new_p = np.full(value.size, -np.inf), np.zeros(value.size)
    top = np.argsort(-value)[:n_candidates]
    block = max(1, 262_144 // n_sweep)
    same = _is_psi_free(fun)  # then every azimuth of the sweep gives the first's value
    for s in range(0, top.size, block):
        idx = top[s:s + block]
        if same:
            v = np.repeat(np.asarray(fun(np.full(idx.size, grid[0]), y[idx]), dtype=float)[:, None],
                          n_sweep, axis=1)
            fun.skip(idx.size * (n_sweep - 1))
        else:  # azimuth by azimuth (a kernel computes what depends on it alone once for them)
            v = np.asarray(fun(np.repeat(grid, idx.size), np.tile(y[idx], (n_sweep, 1))),
                           dtype=float).reshape(n_sweep, idx.size).T
        v = v.reshape(idx.size, n_sweep)
        j = np.argmax(v, axis=1)
        new_v[idx], new_p[idx] = v[np.arange(idx.size), j], grid[j]
    best = np.argsort(-new_v)[:n_keep]
    best = best[new_v[best] > -np.inf]
    start = Extremum(new_v[best], new_p[best], y[best])
    if stop_above is not None and start.value.size and start.value.max() > stop_above:
        v2, p2, y2 = start.value, start.psi, start.x
    else:
        v2, p2, y2 = polish(fun, start, free_psi=True, stop_above=stop_above)
    better = v2 > value[best]
    value[best[better]], psi[best[better]], y[best[better]] = v2[better], p2[better], y2[better]
    return value, psi, y


def _like(model, fun):
    """``fun`` made :class:`~rotorlyap.methods.sampling.PsiFree` (crediting the same counters)
    where ``model`` is."""
    return PsiFree(fun, model.counter) if _is_psi_free(model) else fun


class _Level:
    """The searches of ``W`` that the sound rule needs (:func:`_sound`,
    :func:`rotorlyap.methods.certificate_check.check_claims`):
    its infimum on a sphere over the period (the level), the size of ``|W|`` on a sphere (the
    margin's scale) and, with the shell, the largest ball inside a level set. Closed forms for a
    quadratic ``W`` (``w_matrix``), else the engine's sphere searches."""

    def __init__(self, sys, w_matrix, psi, period, scales, dirs, common, *, free, shell, n_radii, n_bisect):
        self.sys, self.w_matrix, self.psi, self.period, self.scales = sys, w_matrix, psi, period, scales
        self.dirs, self.common, self.free, self.shell = dirs, common, free, shell
        self.n_radii, self.n_bisect = n_radii, n_bisect
        if w_matrix is not None:  # W = r^2 W(unit): its extrema on every sphere from two numbers
            self.unit_min = _min_over_period(lambda p: _extreme_eigenvalues(w_matrix, p)[0], period)
            self.unit_size = float(np.max(np.abs(_extreme_eigenvalues(w_matrix, psi))))
        # the searches of W itself (no closed form): with the shell, whose functions have several
        # local extrema of W on a sphere, many more of the best samples are refined, and longer
        self.w_common = dict(common, n_refine=max(64, common["n_refine"]), n_iter=max(200, common["n_iter"])) \
            if shell else common
        self.inner_radii = {}  # shell: (r, alpha) -> the largest ball in {W < alpha} over the period
        self.sphere_minima, self.sizes = {}, {}  # r -> the searches' results (each sphere searched once)

    def sphere_min(self, r: float) -> float:
        """The smallest ``W`` found on the sphere ``||x|| = r`` over the period (closed form for a
        quadratic ``W``; a sphere searched before gives its result again: the search is
        deterministic, and the sound rule's final check asks for the level of the bound its
        bisection tested)."""
        if r not in self.sphere_minima:
            self.sphere_minima[r] = self._sphere_min(r)
        return self.sphere_minima[r]

    def _sphere_min(self, r: float) -> float:
        sys, psi, scales, dirs, free = self.sys, self.psi, self.scales, self.dirs, self.free
        if self.w_matrix is not None:
            return r * r * self.unit_min
        if not self.shell:
            return float(sphere_extremum(sys.w, psi, r, scales, dirs, kind="min", per_psi=False,
                                         free_psi=free, **self.w_common).value[0])
        # the best 32 refined minima polished (the direction and the azimuth free)
        ext = sphere_extremum(sys.w, psi, r, scales, dirs, kind="min", per_psi=False, free_psi=free,
                              keep=32, **self.w_common)
        on_sphere = _like(sys.w, lambda p, y: -sys.w(p, (r * y / np.linalg.norm(y, axis=1, keepdims=True)) * scales))
        start = Extremum(-ext.value, ext.psi, ext.x / scales / r)
        value, _, _ = polish(on_sphere, start, free_psi=free)
        return float(min(ext.value.min(), -value.max()))

    def alpha(self, r: float) -> float:
        """The level of the bound ``r``: :meth:`sphere_min`, with the shell
        :data:`SHELL_LEVEL_MARGIN` below it (a search that misses the true minimum of a ``W``
        without closed form by a little must not put the level above it)."""
        found = self.sphere_min(r)
        return found * (1.0 - SHELL_LEVEL_MARGIN) if self.shell and self.w_matrix is None else found

    def size(self, r: float) -> float:
        """The largest ``|W|`` found on the sphere ``||x|| = r`` (the margin's scale; each sphere
        searched once)."""
        if self.w_matrix is not None:
            return r * r * self.unit_size
        if r in self.sizes:
            return self.sizes[r]
        sys = self.sys
        self.sizes[r] = float(sphere_extremum(_like(sys.w, lambda p, x: np.abs(sys.w(p, x))), self.psi, r,
                                              self.scales, self.dirs, per_psi=False, n_refine=1, n_iter=0,
                                              period=self.period).value[0])
        return self.sizes[r]

    def inner(self, r: float, alpha: float) -> float | None:
        """With the shell: the largest ball in ``{W < alpha}`` at every azimuth (None without)."""
        if not self.shell:
            return None
        key = (r, alpha)
        if key not in self.inner_radii:
            self.inner_radii[key] = _inner_radius(self.sys, self.psi, r, alpha, self.scales, self.dirs,
                                                  self.w_common, self.n_radii, self.n_bisect, self.free)
        return self.inner_radii[key]


def _band_searches(band, need: float, dirs, dirs_2, thorough: bool) -> list:
    """The searches of (h) on one band, in the order :func:`_band_verdict` runs them: over the
    period with the azimuth free, then the map at the grid azimuths with the azimuth fixed (two
    searches started differently: the one can find what the other misses); ``thorough`` (the
    final check of the certified bound): also the band searches started from the best samples of
    the whole band, and from a second set of directions ``dirs_2``. ``band(stop, per_psi,
    starts, directions, n_lbfgs)`` is :func:`band_max_dw` on the band."""
    searches = [lambda: band(stop=need).value[0],
                lambda: band(stop=None, per_psi=True).value.max()]
    if thorough:
        searches += [lambda starts=starts, d=d: band(stop=need, starts=starts, directions=d,
                                                     n_lbfgs=256).value[0]
                     for starts, d in (("band", dirs), ("levels", dirs_2), ("band", dirs_2))]
    return searches


def _band_verdict(searches, need: float, first: int = 0) -> tuple[bool, float, int]:
    """``(holds, worst, k)``: the searches run (search ``first`` first) until one finds
    ``W' > need``; ``worst`` the largest value found (a NaN is kept, and fails), ``k`` the search
    that failed (``first`` if none did). The verdict, and where it holds the worst ``W'`` (the
    largest of every search's), do not depend on the order."""
    worst = -np.inf
    for k in [first] + [k for k in range(len(searches)) if k != first]:
        value = float(searches[k]())
        worst = value if not value <= worst else worst
        if not worst <= need:
            return False, worst, k
    return True, worst, first


def _second_directions(dirs: np.ndarray, n: int) -> np.ndarray:
    """The final check's second set of directions: another scrambling, as many points as the
    quasi-random part of ``dirs``."""
    return unit_sphere_points(n, max(dirs.shape[0] - 2 * n * n, 16), 1)


BOUND_RTOL = 1e-3
"""Relative precision of the sound rule's search for the largest bound ``A`` below ``A1`` where
condition (h) holds on the band: the bound found is within this fraction of the smallest bound
found to fail (a numerical certificate's bound is printed to three digits). Each trial bound costs
a search of the band over the period; the search stops there instead of after ``n_bisect``
halvings of a twelfth of ``A1`` (a relative precision of 2e-5 that no printed digit shows).
The near misses just inside ``A1`` are tried first, from step 3's resolution up: where (h) fails
only on the sphere ``A1`` itself the bound is then ``A1`` less that resolution, as before, in two
band searches instead of fourteen. Measured 2026-12-06: chapter 7's scan 97 s -> 77 s on
two cores, its cells of the quadratic function about the periodic motion at mu = 0.2 11 s -> 5-6
s; every verdict the same, the bounds within -0.1 % and +0.5 % of the finer search's (the band
changes with its bound, so (h) need not fail at every bound above one where it fails). The start
radii of a ``W`` without closed form (step 5 of the sound rule) stop at the same precision, each
azimuth's bisection once its bracket is within this fraction of its upper end: measured
2026-12-06, the default certify of the trimmed helicopter at mu = 0.1 spent 9.7 s -> 6.0 s on
them (of 42 s -> 36 s), its smallest start radius 1.49707 -> 1.49609, within 0.1 % below."""


def _sound(sys, w_matrix, A, psi, period, scales, dirs, common, *, n_radii, n_shells, n_bisect,
           rtol, margin, autonomous=False, shell=False, psi_free=False) -> TechnicalStabilityResult:
    """:func:`technical_stability` with ``rule="sound"``."""
    n_psi = psi.size
    n = scales.size
    psi_grid = psi
    free = not autonomous
    if autonomous:  # one azimuth stands for all (the results are spread over the grid at the end)
        psi = psi[:1]

    def spread(v):
        v = np.asarray(v)
        return np.repeat(v[:1], n_psi, axis=0) if autonomous else v

    levels = _Level(sys, w_matrix, psi, period, scales, dirs, common, free=free, shell=shell,
                    n_radii=n_radii, n_bisect=n_bisect)
    alpha_of, w_size, inner_of, w_common = levels.alpha, levels.size, levels.inner, levels.w_common
    dirs_2 = _second_directions(dirs, n)

    searched = {}  # (r, alpha, options) -> (result, evaluations it took): each search run once

    def band(r: float, alpha: float, stop: float | None, per_psi: bool = False, starts: str = "levels",
             directions=None, n_lbfgs: int = 64):
        """:func:`band_max_dw` on the band of ``r`` and ``alpha``. The searches are deterministic,
        so one asked again with the same arguments (the final check repeats the two searches the
        bound's own test ran at the same bound and level, and the map of ``W'`` per azimuth is
        the final check's second search) is not run again: its result is returned and the
        evaluations it took are counted again, as the states it examined belong to the check."""
        key = (float(r), float(alpha), stop, per_psi, starts, 1 if directions is dirs_2 else 0, n_lbfgs)
        if key not in searched:
            before = (sys.count, sys.count_dw)
            ext = band_max_dw(sys, None, None, alpha, r, scales=scales, period=period, psi=psi,
                              w_matrix=w_matrix, per_psi=per_psi, autonomous=autonomous,
                              inner=inner_of(r, alpha),
                              directions=dirs if directions is None else directions,
                              n_levels=n_shells, stop_above=stop, n_refine=common["n_refine"],
                              n_iter=common["n_iter"], starts=starts, n_lbfgs=n_lbfgs,
                              psi_free=psi_free)
            searched[key] = (ext, sys.count - before[0], sys.count_dw - before[1])
            return ext
        ext, count, count_dw = searched[key]
        sys.count += count
        sys.count_dw += count_dw
        return ext

    failed_first = [0]  # the thorough check's search that failed last (passes)

    def passes(r: float, thorough: bool = False):
        """(h) on the band of radius r (:func:`_band_searches`; ``thorough``: the final check of
        the certified bound, which :func:`rotorlyap.methods.certificate_check.check_claims` runs
        again on a stored certificate)."""
        report(f"sound rule: {'final check of ' if thorough else ''}the band at bound {r:.3g}")
        alpha = alpha_of(r)
        need = -margin * w_size(r)
        if not alpha > 0:
            return False, alpha, np.inf, need
        searches = _band_searches(lambda **kw: band(r, alpha, **kw), need, dirs, dirs_2, thorough)
        # the thorough check runs first the search that failed its last radius
        ok, worst, k = _band_verdict(searches, need, failed_first[0] if thorough else 0)
        if thorough and not ok:
            failed_first[0] = k
        return ok, alpha, worst, need

    # W' on the sphere itself (a part of the band): the paper's step 3 bounds A from above
    # the margin relative to the size of W on each sphere, as on the band
    report("sound rule: W' on the sphere (step 3)")
    A1, step3 = _step3(sys, A, psi, scales, dirs, free, common, lambda r: -margin * w_size(r),
                       n_radii, n_bisect)
    first_worst = step3
    A_used, alpha, worst, need = 0.0, 0.0, first_worst, -margin * w_size(A)
    if A1 > 0:
        ok, alpha_1, worst_1, need_1 = passes(A1)
        first_worst = worst_1  # the band's worst at the sphere's bound: reported if nothing passes
        if not ok and alpha_1 > 0:  # the search stopped at the first W' > -margin: its maximum
            first_worst = max(worst_1, float(band(A1, alpha_1, stop=None).value[0]))
        if ok:
            A_used, alpha, worst, need = A1, alpha_1, worst_1, need_1
        else:
            failing = A1
            # Near misses first: the band's worst W' lies most often on the sphere itself, where
            # W' is close to its tolerance at A1 by the construction of step 3, so (h) mostly
            # fails just inside A1, and whether it fails at A1 at all can change with the last
            # bits of the arithmetic, and so can A1 itself. Radii A1 (1 - s), s growing fourfold
            # from step 3's own resolution (so that such a failure moves the bound about as
            # little as step 3's last bisections do: measured, the environment of .ci/run moved
            # A1 of a cell of chapter 7 by 5e-5 of it) up to the first radius of the grid; then
            # the grid; the bracket found is bisected until it is narrower than BOUND_RTOL of its
            # upper end (at most n_bisect steps).
            ladder = [1.0 / (n_radii * 2.0**n_bisect)]
            while 1.0 - 4.0 * ladder[-1] > (n_radii - 1) / n_radii:
                ladder.append(4.0 * ladder[-1])
            for step in ladder:
                radius = A1 * (1.0 - step)
                ok_r, alpha_r, worst_r, need_r = passes(radius)
                if ok_r:
                    A_used, alpha, worst, need = radius, alpha_r, worst_r, need_r
                    break
                failing = radius
            grid = np.unique(np.concatenate([
                A1 * np.arange(1, n_radii) / n_radii, np.geomspace(A1 * 1e-4, A1, n_radii, endpoint=False),
            ]))[::-1]
            for radius in (grid[grid < failing] if A_used == 0.0 else ()):
                ok_r, alpha_r, worst_r, need_r = passes(float(radius))
                if ok_r:
                    A_used, alpha, worst, need = float(radius), alpha_r, worst_r, need_r
                    break
                failing = float(radius)
            if A_used > 0:
                lo, hi = A_used, failing
                for _ in range(n_bisect):
                    if hi - lo <= BOUND_RTOL * hi:
                        break
                    mid = 0.5 * (lo + hi)
                    ok_m, alpha_m, worst_m, need_m = passes(mid)
                    if ok_m:
                        lo, alpha, worst, need = mid, alpha_m, worst_m, need_m
                    else:
                        hi = mid
                A_used = lo
    # the final check of the bound with the thorough search; where it finds what the bisection's
    # search missed, the bound steps down (0.5 % steps, then 3 %) until the thorough search passes
    check_evaluations = 0
    for step in range(70 if A_used > 0 else 0):
        count = sys.count_dw
        ok_t, alpha_t, worst_t, need_t = passes(A_used, thorough=True)
        check_evaluations = sys.count_dw - count
        if ok_t:
            alpha, worst, need = alpha_t, worst_t, need_t
            break
        A_used *= 0.995 if step < 10 else 0.97
    else:
        A_used = 0.0

    if A_used == 0.0:
        ext = sphere_extremum(sys.dw, psi, A, scales, dirs, **common)  # where (h) fails, per azimuth
        return TechnicalStabilityResult(
            A_requested=A, scales=scales, A=0.0, alpha=0.0, psi=psi_grid, lambda0=np.zeros(n_psi),
            max_dW=spread(ext.value), argmax_dW=spread(ext.x),
            stable=np.zeros(n_psi, dtype=bool), period=period, step3_max_dW=step3,
            tol=need, reading="strict", n_evaluations=sys.count, rule="sound",
            level=float("nan"), band_max_dW=first_worst, A_step3=float(A1),
            message=(
                f"nothing certified: W' > -margin was found on every sphere tested for radii from "
                f"{A * 1e-4:.3g} to A = {A:.3g} (condition (h) fails on the sphere itself); max W' "
                f"on ||x|| = A is {step3:.3g}" if A1 == 0.0 else
                f"nothing certified: for every bound tried from {A1 * 1e-4:.3g} to A1 = {A1:.3g} "
                "(where W' < 0 on the sphere), W' > -margin was found on the band ||x|| <= A1, "
                f"W >= alpha over the period (condition (h)); at A1, max W' on the band = {first_worst:.3g}"),
        )

    c = alpha
    # the map of W' on the band at each start azimuth (a diagnostic: where (h) is tightest)
    report("sound rule: the map of W' on the band per azimuth")
    ext = band(A_used, c, stop=None, per_psi=True)
    # start regions: the largest ball inside {W(psi_j, .) < c}
    if w_matrix is not None:
        lambda0 = _closed_form_start_radii(w_matrix, psi, c, A_used)
    else:  # searched: the level less the margin, so that a search that misses the true sup of W
        # on a sphere by a little does not put the start ball across the level
        lambda0 = _start_radii(sys, psi, A_used, c * (1.0 - SHELL_LEVEL_MARGIN), scales, dirs,
                               w_common, n_radii, n_bisect, rtol=BOUND_RTOL)
    lambda0 = spread(lambda0)
    worst = max(worst, float(ext.value.max()))
    certified = worst <= need
    stable = (lambda0 > 0) & certified
    reduced = "" if A_used == A else f" (A reduced from {A:.4g} to {A_used:.4g})"
    where = (f"the shell {inner_of(A_used, c):.4g} <= ||x|| <= A (which holds the band W >= alpha)" if shell
             else "the band ||x|| <= A, W >= alpha")
    message = (f"certified at {int(stable.sum())} of {n_psi} azimuths{reduced}: W' < 0 on {where} "
               "over the whole period (numerical certificate)"
               if certified else "nothing certified: W' > -margin found on the band")
    return TechnicalStabilityResult(
        A_requested=A, scales=scales, A=float(A_used), alpha=float(c), psi=psi_grid, lambda0=lambda0,
        max_dW=spread(ext.value), argmax_dW=spread(ext.x), stable=stable, period=period, step3_max_dW=step3,
        tol=need, message=message, reading="strict", n_evaluations=sys.count, rule="sound",
        level=float(c), band_max_dW=worst, A_step3=float(A1), check_evaluations=int(check_evaluations),
        alpha_source="closed form" if w_matrix is not None else "search",
    )
