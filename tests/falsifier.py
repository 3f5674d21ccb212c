"""An adversary for certificates: searches independent of the engine's, and worst-case motions.

Not a test module: the falsifier tests (``test_sound_rule*.py``, ``test_falsifier_*.py``) import
it. What it attacks is a :class:`~rotorlyap.methods.lyapunov.TechnicalStabilityResult` of the
sound rule, the claim "every motion started at ``psi_j`` with ``||x|| < lambda0_j`` stays inside
``||x|| < A``", through the three facts the theorem draws it from:

* ``W >= alpha`` on the sphere ``||x|| = A`` at every azimuth;
* ``W < alpha`` inside every certified start ball (at its azimuth);
* ``W' < 0`` on the band ``||x|| <= A, W >= alpha`` at every azimuth;

and, beside the theorem, through the motion itself: starts on the boundary of the certified
region in the directions that maximise the peak norm (found by optimisation, not by random
draws), integrated for 20 periods.

The searches share nothing with the engine's (Sobol' directions refined by projected gradient
ascent on spheres): pseudo-random points in hyperspherical coordinates, scipy's differential
evolution over the box of those coordinates and the azimuth, and L-BFGS-B from the best of both.
"""

from __future__ import annotations

from dataclasses import dataclass

import math

import numpy as np
from numba import njit
from scipy.optimize import differential_evolution, minimize

from rotorlyap.methods.region import integrate_batch


@njit(cache=True)
def _unit_vectors(angles, out):
    n = out.shape[1]
    for i in range(out.shape[0]):
        prod = 1.0
        for j in range(n - 1):
            a = angles[i, j]
            out[i, j] = prod * math.cos(a)
            prod *= math.sin(a)
        out[i, n - 1] = prod


def unit_vectors(angles: np.ndarray, n: int) -> np.ndarray:
    """Hyperspherical coordinates ``(k, n - 1)`` -> unit vectors ``(k, n)``:
    ``x_j = sin a_0 ... sin a_(j-1) cos a_j`` (``x_(n-1)`` without the cosine), in one compiled
    loop (the same numbers as numpy's ``cumprod`` of the sines times the cosines: the same
    products in the same order, glibc's ``sin`` and ``cos``; a third of the time)."""
    angles = np.ascontiguousarray(np.atleast_2d(angles)[:, :max(n - 1, 0)], dtype=float)
    out = np.empty((angles.shape[0], n))
    if n == 1:
        out[:] = 1.0
        return out
    _unit_vectors(angles, out)
    return out


def box(n: int, period: float) -> list[tuple[float, float]]:
    """Bounds of (azimuth, hyperspherical angles) for an ``n``-state sphere."""
    return [(0.0, period)] + [(0.0, np.pi)] * (n - 2) + [(0.0, 2.0 * np.pi)] * (n > 1)


def adversary_minimum(fun, bounds, evaluations: int, seed: int = 1) -> float:
    """The minimum of the vectorised ``fun(z)`` (``z`` of shape ``(k, d)``) over the box ``bounds``:
    ``evaluations`` pseudo-random points in batches, differential evolution (at most 200 000
    evaluations, vectorised over the population), and L-BFGS-B from the best eight of both (its
    forward-difference gradient evaluated in one call per point)."""
    rng = np.random.default_rng(seed)
    lo, hi = np.array(bounds, dtype=float).T
    pool = []
    done = 0
    while done < evaluations:
        m = min(100_000, evaluations - done)
        z = lo + (hi - lo) * rng.random((m, lo.size))
        v = np.asarray(fun(z), dtype=float)
        best = np.argpartition(v, 7)[:8] if v.size > 8 else np.arange(v.size)
        order = best[np.argsort(v[best], kind="stable")]
        pool += [(float(v[i]), z[i]) for i in order]
        done += m
    popsize = 15
    maxiter = max(10, min(evaluations, 200_000) // (popsize * lo.size) - 1)
    res = differential_evolution(
        lambda z: fun(z.T), bounds, popsize=popsize, maxiter=maxiter, tol=0.0, atol=0.0,
        seed=seed, vectorized=True, polish=False, updating="deferred",
    )
    pool.append((float(res.fun), np.asarray(res.x)))
    pool.sort(key=lambda item: item[0])
    best = pool[0][0]

    def value_and_gradient(z):
        # L-BFGS-B's own forward difference (scipy's "2-point" step, sqrt(eps) max(1, |z|),
        # turned back at an upper bound), with the point and its d neighbours in one call
        h = np.sqrt(np.finfo(float).eps) * np.where(z >= 0, 1.0, -1.0) * np.maximum(1.0, np.abs(z))
        h = np.where(z + h > hi, -h, h)
        pts = np.vstack([z, z + np.diag(h)])
        v = np.asarray(fun(pts), dtype=float)
        dz = np.diag(pts[1:]) - z
        return float(v[0]), (v[1:] - v[0]) / dz

    for _, z0 in pool[:8]:
        r = minimize(value_and_gradient, z0, jac=True, method="L-BFGS-B", bounds=bounds)
        best = min(best, float(r.fun))
    return best


@dataclass(frozen=True)
class Attack:
    """What the adversary found on one certificate.

    Attributes
    ----------
    min_w_sphere : float
        Smallest ``W`` found on the sphere ``||x|| = A`` over the period (must be >= alpha).
    sup_w_balls : float
        Largest ``W - alpha`` found on the boundaries of the certified start balls (must be <= 0).
    max_dw_band : float
        Largest ``W'`` found on the band ``||x|| <= A, W >= alpha`` over the period (must be < 0).
    evaluations : int
        Evaluations of ``W'`` spent on the band.
    """

    min_w_sphere: float
    sup_w_balls: float
    max_dw_band: float
    evaluations: int


#: Radii of the first scan along each ray in :func:`band_level` (the level's bracket).
LEVEL_GRID = 16

#: Width, relative to ``A``, to which :func:`band_level` narrows the bracket of the level (about
#: 1e-9): there the round-off of a ``W`` without closed form decides the side (the augmented
#: energy's is up to about 5e-9 of ``alpha``, some 1e-9 of ``A`` in the radius), so narrowing
#: further only chooses among round-off; the rays' points are the band's all the same, since the
#: bracket's upper end, where ``W >= c`` was computed, is returned.
LEVEL_WIDTH = 2.0**-30


def band_level(W, psi, u, a, c: float, A: float, *, quadratic: bool) -> np.ndarray:
    """Radius where the ray ``r u`` first meets the level ``W = c`` (capped at ``A``): from
    ``W(r u) = r^2 W(u)`` for a quadratic ``W``; otherwise ``W`` at ``LEVEL_GRID + 1`` radii from
    0 to ``A`` in one call brackets the first crossing, which the Illinois variant of regula falsi
    narrows to ``LEVEL_WIDTH A`` (in about a fifth of the calls of the bisection it replaces);
    the bracket's upper end, where ``W >= c``, is returned (``A`` where the ray stays below, 0
    where it starts at or above the level)."""
    if quadratic:
        return np.minimum(np.sqrt(c / W(psi, u * a)), A)
    m, n = u.shape
    grid = A * np.arange(LEVEL_GRID + 1) / LEVEL_GRID
    ua = u * a
    f = (W(np.repeat(psi, grid.size), (grid[None, :, None] * ua[:, None, :]).reshape(-1, n))
         .reshape(m, grid.size) - c)
    up = f >= 0
    has = up.any(axis=1) & ~up[:, 0]
    first = np.where(has, np.argmax(up, axis=1), 1)
    rows = np.arange(m)
    lo, hi = grid[first - 1], np.where(has, grid[first], np.where(up[:, 0], 0.0, A))
    f_lo, f_hi = f[rows, first - 1], f[rows, first]
    side = np.zeros(m, dtype=int)  # the end moved last: +1 the upper, -1 the lower
    act = np.flatnonzero(has)
    for _ in range(200):
        act = act[hi[act] - lo[act] > A * LEVEL_WIDTH]
        if act.size == 0:
            break
        l, h, fl, fh = lo[act], hi[act], f_lo[act], f_hi[act]
        x = h - fh * ((h - l) / (fh - fl))
        x = np.where((x > l) & (x < h), x, 0.5 * (l + h))  # no progress or not finite: halve
        fx = W(psi[act], x[:, None] * ua[act]) - c
        upx = fx >= 0
        # Illinois: an end kept twice running has its value halved (superlinear on both sides)
        keep_lo, keep_hi = upx & (side[act] == 1), ~upx & (side[act] == -1)
        f_lo[act] = np.where(upx, np.where(keep_lo, 0.5 * fl, fl), fx)
        f_hi[act] = np.where(upx, fx, np.where(keep_hi, 0.5 * fh, fh))
        lo[act], hi[act] = np.where(upx, l, x), np.where(upx, x, h)
        side[act] = np.where(upx, 1, -1)
    return hi


def band_maximum(W, dW, scales, period: float, c: float, A: float, evaluations: int, *,
                 quadratic: bool) -> float:
    """Largest ``W'`` the adversary finds on the band ``||x|| <= A, W >= c``, the azimuth free,
    along rays from the level out to ``A``."""
    n, a = scales.size, scales

    def dw_on_band(z):
        psi, u, t = z[:, 0], unit_vectors(z[:, 1:-1], n), z[:, -1]
        r0 = band_level(W, psi, u, a, c, A, quadratic=quadratic)
        return -dW(psi, (r0 + t * (A - r0))[:, None] * u * a)

    return -adversary_minimum(dw_on_band, box(n, period) + [(0.0, 1.0)], evaluations)


def attack(W, dW, result, *, evaluations: int, quadratic: bool = False) -> Attack:
    """Independent searches on a certificate: min ``W`` on the sphere ``A`` and max ``W - alpha``
    on the boundaries of the certified start balls (``evaluations`` each), max ``W'`` on the
    band (10 x ``evaluations``)."""
    n, a = result.scales.size, result.scales
    A, c, T = result.A, result.alpha, result.period

    def w_on_sphere(z):
        return W(z[:, 0], A * unit_vectors(z[:, 1:], n) * a)

    min_w = adversary_minimum(w_on_sphere, box(n, T), evaluations)

    idx = np.flatnonzero(result.stable)

    def w_in_ball(z):  # the azimuth index as a continuous coordinate, truncated
        j = idx[np.clip(z[:, 0].astype(int), 0, idx.size - 1)]
        return -(W(result.psi[j], result.lambda0[j, None] * unit_vectors(z[:, 1:], n) * a) - c)

    sup_ball = -adversary_minimum(w_in_ball, [(0.0, idx.size - 1e-9)] + box(n, T)[1:], evaluations)
    max_dw = band_maximum(W, dW, a, T, c, A, 10 * evaluations, quadratic=quadratic)
    return Attack(min_w, sup_ball, max_dw, 10 * evaluations)


#: RK4 steps per period of the worst-start motions (:func:`worst_start_peak`). Measured on the
#: trimmed helicopter's designed certificate at mu = 0.1, from 0.97 of its start set's boundary:
#: 64 steps give the peaks of scipy's adaptive RK45 (rtol 1e-9, rotorlyap.methods.simulation) to 3e-4, and 128 steps catch the
#: peaks between RK45's output points, up to 0.25 % higher than RK45 reports, 8 times faster.
PEAK_STEPS = 128


def worst_start_peak(f, result, *, n_periods: float = 20.0, n_dir: int = 32, rounds: int = 3,
                     n_azimuths: int = 4, W=None, quadratic: bool = False) -> float:
    """Largest peak norm / ``A`` of motions started at ``0.99 lambda0_j``, the start direction
    chosen by optimisation: the best of ``n_dir`` directions at each of ``n_azimuths`` certified
    azimuths (evenly spread; one if nothing depends on the azimuth), then improved by ``rounds``
    of 16 perturbations per azimuth (fixed-step RK4 with :data:`PEAK_STEPS` steps per period, the
    peak taken at every step). The azimuths are searched independently, but the motions of a
    round, of every azimuth, are integrated together in one batch (each with its own start
    azimuth): four batches in all instead of four per azimuth.

    With ``W`` (the certificate's function) the starts lie in the whole start set
    ``{||x|| < A, W < alpha}`` instead (:mod:`rotorlyap.methods.start_set`): at 0.97 of the first
    radius where ``W`` reaches ``alpha`` along each direction, so that the claim about the set, not
    only about its inner ball, meets the worst motions."""
    n, a = result.scales.size, result.scales
    rng = np.random.default_rng(7)
    certified = np.flatnonzero(result.stable)
    js = certified[::max(1, certified.size // n_azimuths)][:n_azimuths]
    k = js.size

    def peaks(u, per):
        """Peaks of the motions from directions ``u`` (``per`` rows for each azimuth of ``js``)."""
        psi = np.repeat(result.psi[js], per)
        if W is None:
            r = 0.99 * np.repeat(result.lambda0[js], per)
        else:
            r = 0.97 * band_level(W, psi, u, a, result.level, result.A, quadratic=quadratic)
        run = integrate_batch(f, r[:, None] * u * a, psi, n_periods, scales=a, bound=10.0 * result.A,
                              steps_per_period=PEAK_STEPS, period=result.period)
        return np.where(run.left, np.inf, run.peak).reshape(k, per)

    def unit(v):
        return v / np.linalg.norm(v, axis=-1, keepdims=True)

    u = unit(rng.normal(size=(k, n_dir, n)))
    p = peaks(u.reshape(-1, n), n_dir)
    rows = np.arange(k)
    best = np.argmax(p, axis=1)
    best_u, best_p = u[rows, best], p[rows, best]
    step = np.full(k, 0.3)
    for _ in range(rounds):
        cand = unit(best_u[:, None, :] + step[:, None, None] * rng.normal(size=(k, 16, n)))
        pc = peaks(cand.reshape(-1, n), 16)
        i = np.argmax(pc, axis=1)
        better = pc[rows, i] > best_p
        best_u = np.where(better[:, None], cand[rows, i], best_u)
        best_p = np.where(better, pc[rows, i], best_p)
        step = np.where(better, step, 0.5 * step)
    return float(np.max(best_p)) / result.A


def start_set_excess(W, start, *, evaluations: int, seed: int = 5) -> float:
    """Largest ``W - level`` the adversary finds on the segments a start set is said to reach:
    along each of its directions, from 0 to the reported reach at the worst azimuth, at
    pseudo-random azimuths and radii (``evaluations`` points), then the best 64 refined by
    L-BFGS-B over (azimuth, fraction of the reach). Must be < 0: the reported reach lies in the
    set ``{W < level}`` at every start azimuth."""
    rng = np.random.default_rng(seed)
    u = start.directions
    k = u.shape[0]
    reach = start.least
    period = 2 * np.pi if start.psi.size > 1 else 0.0
    d = rng.integers(0, k, evaluations)
    psi = rng.uniform(0.0, 2 * np.pi, evaluations) if period else np.zeros(evaluations)
    t = rng.uniform(0.0, 1.0, evaluations)
    vals = W(psi, (t * reach[d])[:, None] * u[d] * start.scales) - start.level
    best = float(vals.max())
    for i in np.argsort(-vals)[:64]:
        di = d[i]

        def g(z, di=di):
            return -float(W(np.array([z[0]]), (z[1] * reach[di]) * u[di][None, :] * start.scales)[0] - start.level)

        r = minimize(g, np.array([psi[i], t[i]]), method="L-BFGS-B",
                     bounds=[(0.0, period), (0.0, 1.0)])
        best = max(best, -float(r.fun))
    return best


def falsify_certificate(cert, *, evaluations: int | None = None, n_azimuths: int = 4) -> Attack:
    """Attack a :class:`rotorlyap.Certificate` of the sound rule whole: the theorem's three facts
    (:func:`attack`, ``evaluations`` each on ``W``, ten times as many on ``W'``; default: the
    engine's own final check, so that the band sees ten times its evaluations), the start set's
    reported reach (:func:`start_set_excess`) and the worst motions from 0.97 of the start set's
    boundary for 20 revolutions (:func:`worst_start_peak`; one start azimuth where nothing
    depends on it). Asserts each; returns what the searches found."""
    res, fun = cert.result, cert.lyapunov
    assert cert.certified and res.rule == "sound" and res.stable.all(), cert.message
    quadratic = cert.function == "quadratic"
    budget = res.check_evaluations if evaluations is None else evaluations
    assert budget > 0
    hit = attack(fun.W, fun.dW, res, evaluations=budget, quadratic=quadratic)
    assert hit.min_w_sphere >= res.alpha * (1 - 1e-9), f"W = {hit.min_w_sphere:.6g} < alpha on the sphere A"
    assert hit.sup_w_balls <= 1e-9 * abs(res.alpha), "a start on the boundary of lambda0 has W above the level"
    assert hit.max_dw_band < 0, f"W' = {hit.max_dw_band:.3g} >= 0 found on the band"
    start = cert.start_set
    assert start is not None and np.all(start.axis_reach >= cert.start_region * (1 - 1e-12))
    excess = start_set_excess(fun.W, start, evaluations=min(budget, 20_000))
    # the reach is the supremum of the open set (a quadratic's is the closed-form crossing, where
    # W = alpha to round-off): W above the level by more than round-off inside it is a hit
    assert excess <= 1e-9 * abs(start.level), f"W - alpha = {excess:.3g} > 0 inside the start set's reported reach"
    peak = worst_start_peak(fun.f, res, n_periods=20.0, n_azimuths=1 if start.psi.size == 1 else n_azimuths,
                            W=fun.W, quadratic=quadratic)
    assert np.isfinite(peak) and peak < 1.0, f"a motion from a worst-case start reached {peak:.3f} A"
    return hit


def falsify_file(path, *, evaluations: int, n_azimuths: int = 4) -> Attack:
    """:func:`falsify_certificate` on a certificate file (:func:`rotorlyap.verify`'s input): the
    function, level, bound and start radii as the file states them, rebuilt by
    :func:`rotorlyap.analysis.certificate_file.read_certificate`, attacked as a certificate made
    in this process would be. The attack does not run ``verify`` (chapter 10 does, on the same
    files): it searches for what ``verify``'s searches would have missed."""
    from types import SimpleNamespace

    from rotorlyap.analysis.certificate_file import read_certificate
    from rotorlyap.analysis.certify import function_start_set

    stored = read_certificate(path)
    fun = stored.function
    n = stored.lambda0.size
    result = SimpleNamespace(rule="sound", scales=stored.scales, A=stored.A, alpha=stored.level, level=stored.level,
                             period=stored.period, psi=stored.period * np.arange(n) / n, lambda0=stored.lambda0,
                             stable=np.ones(n, dtype=bool), check_evaluations=evaluations, message=path.name)
    cert = SimpleNamespace(result=result, lyapunov=fun, certified=True, function=stored.family,
                           start_region=float(stored.lambda0.min()), message=path.name,
                           start_set=function_start_set(fun, stored.family, stored.level, stored.A, stored.scales,
                                                        stored.period))
    return falsify_certificate(cert, evaluations=evaluations, n_azimuths=n_azimuths)
