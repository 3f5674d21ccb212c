"""Points on scaled spheres and batched searches for the sup and inf over them.

The direct method needs suprema and infima of smooth scalar functions ``g(psi, x)`` over
spheres ``||x|| = rho`` of the scaled norm ``||x|| = sqrt(sum((x_i / a_i)**2))`` (and over
shells ``lambda0 < ||x|| <= A``). No closed form exists for a general ``g``, so this module
does what a careful analyst does by hand, but for many azimuths at once:

1. evaluate ``g`` on a dense, deterministic set of directions: the coordinate axes and the
   diagonals of every coordinate plane (structured points that catch "one component large,
   another small" states), plus a scrambled Sobol' sequence mapped to the unit sphere through
   the inverse normal distribution function (``scipy.stats.qmc``);
2. take the best few samples of each azimuth and refine them by a batched projected-gradient
   ascent on the sphere (central-difference gradients, per-point step control), optionally
   letting the azimuth and the radius move too.

Everything is vectorised: one call of ``g`` evaluates all azimuths and all directions.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Callable

import numpy as np
from scipy.special import ndtri
from scipy.stats import qmc

Function = Callable[[np.ndarray, np.ndarray], np.ndarray]

__all__ = ["unit_sphere_points", "Extremum", "PsiFree", "psi_free", "sphere_extremum", "refine_extremum"]


@lru_cache(maxsize=64)
def _sphere_points_cached(dim: int, n_random: int, seed: int) -> np.ndarray:
    eye = np.eye(dim)
    structured = [eye, -eye]
    for i in range(dim):
        for j in range(i + 1, dim):
            for si in (1.0, -1.0):
                for sj in (1.0, -1.0):
                    v = np.zeros(dim)
                    v[i], v[j] = si, sj
                    structured.append(v[None, :] / np.sqrt(2.0))
    points = [np.vstack(structured)]
    if dim > 1 and n_random > 0:
        m = int(np.ceil(np.log2(n_random)))
        sobol = qmc.Sobol(d=dim, scramble=True, seed=seed).random_base2(m)
        normal = ndtri(np.clip(sobol, 1e-12, 1.0 - 1e-12))
        points.append(normal / np.linalg.norm(normal, axis=1, keepdims=True))
    out = np.vstack(points)
    out.setflags(write=False)
    return out


def unit_sphere_points(dim: int, n_random: int = 1024, seed: int = 0) -> np.ndarray:
    """Deterministic directions on the unit sphere of ``R**dim``.

    Parameters
    ----------
    dim : int
        Dimension of the state space (>= 1).
    n_random : int
        Number of quasi-random directions; rounded up to a power of two, as the balance
        properties of a Sobol' sequence require. 0 gives the structured points only.
    seed : int
        Seed of the Sobol' scrambling: the same seed gives the same points.

    Returns
    -------
    numpy.ndarray
        Read-only array of shape ``(N, dim)`` of unit vectors: the ``2 dim`` signed axes, the
        ``2 dim (dim - 1)`` signed diagonals of the coordinate planes, then the Sobol' points.
        The array is cached: repeated calls cost nothing.
    """
    if int(dim) != dim or dim < 1:
        raise ValueError(f"dim must be a positive integer, got {dim!r}")
    if int(n_random) != n_random or n_random < 0:
        raise ValueError(f"n_random must be a non-negative integer, got {n_random!r}")
    return _sphere_points_cached(int(dim), int(n_random), int(seed))


@dataclass(frozen=True)
class Extremum:
    """Best value of a search, one per azimuth (or one overall).

    Attributes
    ----------
    value : numpy.ndarray
        The extreme value found, shape ``(k,)``.
    psi : numpy.ndarray
        Azimuth where it is attained, shape ``(k,)`` (rad, or the unit of the period).
    x : numpy.ndarray
        State where it is attained, shape ``(k, n)``.
    """

    value: np.ndarray
    psi: np.ndarray
    x: np.ndarray


class PsiFree:
    """A search function whose values do not depend on the azimuth, to the last bit (a blade in
    hover without cyclic pitch, about a constant steady motion, with a constant ``W``).

    The searches of this module (and :func:`rotorlyap.methods.polish.polish`) recognise it: they
    evaluate one azimuth for all, refine each distinct start once, and give the result they
    give without it, bit for bit. ``skip(n)`` is told how many states were not evaluated because
    their values were known; it credits the counters of ``counter`` (any object with integer
    attributes ``count`` and ``count_dw``) with what evaluating them would have added, at the
    rate the calls made so far added (so that evaluation counts, and the budgets drawn from
    them, stay those of the full search).

    Parameters
    ----------
    fun : callable
        ``fun(psi, x)``, vectorised.
    counter : object, optional
        The counters to credit.
    """

    psi_free = True

    def __init__(self, fun: Function, counter=None):
        self.fun, self.counter = fun, counter
        self.states = 0
        self.added = np.zeros(2)  # what the calls made so far added to count and count_dw

    def __call__(self, psi: np.ndarray, x: np.ndarray) -> np.ndarray:
        before = self._counts()
        out = self.fun(psi, x)
        self.states += len(x)
        self.added += self._counts() - before
        return out

    def _counts(self) -> np.ndarray:
        c = self.counter
        return np.zeros(2) if c is None else np.array([c.count, c.count_dw], dtype=float)

    def skip(self, n: int) -> None:
        """Credit ``n`` states whose values were known without evaluating them."""
        if self.counter is None or n <= 0 or self.states == 0:
            return
        add = np.rint(self.added * (n / self.states)).astype(int)
        self.counter.count += int(add[0])
        self.counter.count_dw += int(add[1])


def psi_free(fun) -> bool:
    """Whether ``fun`` is a :class:`PsiFree` function."""
    return bool(getattr(fun, "psi_free", False))


def _normalise(u: np.ndarray) -> np.ndarray:
    return u / np.linalg.norm(u, axis=-1, keepdims=True)


def refine_extremum(
    fun: Function,
    psi: np.ndarray,
    rho: np.ndarray,
    u: np.ndarray,
    scales: np.ndarray,
    *,
    sign: float = 1.0,
    free_psi: bool = False,
    period: float = 2 * np.pi,
    rho_bounds: tuple[np.ndarray, np.ndarray] | None = None,
    n_iter: int = 40,
    h: float = 1e-6,
    initial_step: float = 0.2,
    min_step: float = 1e-7,
    multiplicity: np.ndarray | None = None,
    stop_above: float | None = None,
    groups: np.ndarray | None = None,
    settle_at: float | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Batched local ascent of ``sign * fun(psi, rho * scales * u)`` over unit ``u``.

    Each of the ``m`` candidates moves independently: a central-difference gradient in the
    ambient coordinates of ``u`` (its tangential part is the gradient on the sphere), a
    normalised step along it, accepted if it improves the value (the step then grows by 1.5)
    and otherwise rejected (the step halves). All candidates and all finite-difference
    perturbations are evaluated in one call of ``fun`` per iteration.

    Parameters
    ----------
    fun : callable
        ``fun(psi, x)`` with ``psi`` of shape ``(m,)`` and ``x`` of shape ``(m, n)``,
        returning shape ``(m,)``.
    psi, rho : numpy.ndarray
        Start azimuths and radii, shape ``(m,)``.
    u : numpy.ndarray
        Start directions, shape ``(m, n)`` (normalised here).
    scales : numpy.ndarray
        Norm scales ``a_i``, shape ``(n,)``.
    sign : float
        +1 to maximise, -1 to minimise.
    free_psi : bool
        Let the azimuth move too (for extrema over the whole period).
    period : float
        Period of ``fun`` in ``psi``.
    rho_bounds : tuple of arrays, optional
        ``(lo, hi)`` of shape ``(m,)``: let the radius move within these bounds (a shell).
    n_iter : int
        Maximum number of iterations.
    h : float
        Relative finite-difference step.
    initial_step, min_step : float
        Initial and smallest step (radians on the sphere; fractions of the period/shell
        width for psi and rho). A candidate whose step falls below ``min_step`` stops.
    multiplicity : numpy.ndarray, optional
        With a :class:`PsiFree` ``fun``: how many identical starts (at other azimuths) each
        candidate stands for; their evaluations are credited to ``fun.skip``.
    stop_above : float, optional
        Only with ``sign = 1``: stop after the first iteration at whose end a candidate's value
        exceeds it (enough to decide that a condition ``max <= stop_above`` fails; the
        candidates are then where that iteration left them).
    groups, settle_at : optional
        Only with ``sign = 1``: ``groups`` (m,) labels the candidates (for example by azimuth);
        once a candidate's value reaches ``settle_at`` (``>=``), every candidate of its group
        stops where it is (the group's maximum is then known to reach ``settle_at``, all that a
        decision ``max < settle_at`` needs). The other groups move exactly as without it.

    Returns
    -------
    value, psi, rho, u : numpy.ndarray
        Best values (in the original sign), azimuths, radii and unit directions.
    """
    psi = np.array(psi, dtype=float, copy=True)
    rho = np.array(rho, dtype=float, copy=True)
    u = _normalise(np.array(u, dtype=float, copy=True))
    m, n = u.shape
    if m == 0:
        return np.empty(0), psi, rho, u
    free_rho = rho_bounds is not None
    if free_rho:
        lo, hi = (np.asarray(b, dtype=float) for b in rho_bounds)
        width = np.maximum(hi - lo, 0.0)
        free_rho_mask = width > 0
    psi_scale = period / (2 * np.pi)

    extra = None if multiplicity is None else np.asarray(multiplicity) - 1  # the copies skipped

    def evaluate(p, r, uu, cand=None):
        out = sign * np.asarray(fun(p, (r[:, None] * uu) * scales), dtype=float)
        if extra is not None:  # cand: the candidates evaluated, each p.size // cand.size times
            idx = np.arange(m) if cand is None else cand
            fun.skip(int(extra[idx].sum()) * (p.size // idx.size))
        return out

    val = evaluate(psi, rho, u)
    step = np.full(m, float(initial_step))
    eye = np.eye(n)
    # the perturbations of u, in the order (+h e_0, -h e_0, +h e_1, ...)
    offsets = np.array([s * h * eye[i] for i in range(n) for s in (1.0, -1.0)])[:, None, :]
    n_var = n + int(free_psi) + int(free_rho)
    stop = stop_above if stop_above is not None and sign > 0 else None
    settle = settle_at if settle_at is not None and groups is not None and sign > 0 else None
    for _ in range(n_iter):
        if stop is not None and val.max() > stop:
            break
        if settle is not None:  # groups whose maximum reaches settle_at: decided, stopped
            step[np.isin(groups, groups[val >= settle])] = 0.0
        act = np.flatnonzero(step > min_step)
        if act.size == 0:
            break
        ua, pa, ra = u[act], psi[act], rho[act]
        k = act.size
        # perturbed copies: (2 * n_var, k, ...)
        up = [_normalise(ua[None] + offsets).reshape(-1, n)]  # all 2 n at once: the same numbers
        pp = [pa] * (2 * n)
        rp = [ra] * (2 * n)
        if free_psi:
            for s in (1.0, -1.0):
                up.append(ua)
                pp.append(pa + s * h * psi_scale)
                rp.append(ra)
        if free_rho:
            for s in (1.0, -1.0):
                up.append(ua)
                pp.append(pa)
                rp.append(np.where(free_rho_mask[act], ra + s * h * width[act], ra))
        # evaluated candidate by candidate (the 2 n_var points of a candidate together, most of
        # them at its azimuth: a kernel computes what depends on the azimuth alone once for them)
        # and put back perturbation by perturbation: each point's value does not depend on its
        # place in the batch
        nv = 2 * n_var
        pp = np.concatenate(pp).reshape(nv, k).T.reshape(-1)
        rp = np.concatenate(rp).reshape(nv, k).T.reshape(-1)
        up = np.concatenate(up).reshape(nv, k, n).transpose(1, 0, 2).reshape(-1, n)
        vals = evaluate(pp, rp, up, act).reshape(k, nv).T
        grad = (vals[0::2] - vals[1::2]) / (2 * h)  # (n_var, k)
        g_u = grad[:n].T
        g_u = g_u - np.sum(g_u * ua, axis=1, keepdims=True) * ua  # tangential part
        parts = [g_u]
        if free_psi:
            parts.append(grad[n][:, None])
        if free_rho:
            parts.append(np.where(free_rho_mask[act], grad[-1], 0.0)[:, None])
        g = np.hstack(parts)
        gnorm = np.linalg.norm(g, axis=1)
        flat = gnorm <= 1e-300
        d = g / np.where(flat, 1.0, gnorm)[:, None]
        s = step[act]
        u_t = _normalise(ua + s[:, None] * d[:, :n])
        p_t = pa + (s * d[:, n] * psi_scale if free_psi else 0.0)
        if free_rho:
            r_t = np.clip(ra + s * d[:, -1] * width[act], lo[act], hi[act])
        else:
            r_t = ra
        v_t = evaluate(p_t, r_t, u_t, act)
        better = (v_t > val[act]) & ~flat
        idx = act[better]
        u[idx], psi[idx], val[idx] = u_t[better], p_t[better] if free_psi else psi[idx], v_t[better]
        if free_rho:
            rho[idx] = r_t[better]
        step[act] = np.where(better, np.minimum(s * 1.5, 1.0), s * 0.5)
        step[act[flat]] = 0.0
    if free_psi:
        psi = np.mod(psi, period)
    return sign * val, psi, rho, u


def sphere_extremum(
    fun: Function,
    psi: np.ndarray,
    radius: np.ndarray | float,
    scales: np.ndarray,
    directions: np.ndarray,
    *,
    kind: str = "max",
    per_psi: bool = True,
    free_psi: bool = False,
    period: float = 2 * np.pi,
    shell: tuple[np.ndarray, np.ndarray] | None = None,
    n_levels: int = 1,
    n_refine: int = 4,
    n_iter: int = 40,
    stop_above: float | None = None,
    keep: int = 1,
    settle_at: float | None = None,
) -> Extremum:
    """Sup or inf of ``fun`` over scaled spheres (or shells), sampled then refined.

    A :class:`PsiFree` ``fun`` is sampled at the first azimuth only (where the radii are the same
    at every azimuth) and each distinct start refined once: the same answer.

    Parameters
    ----------
    fun : callable
        ``fun(psi, x)``, vectorised: ``psi`` shape ``(m,)``, ``x`` shape ``(m, n)``.
    psi : numpy.ndarray
        Azimuths, shape ``(k,)``.
    radius : float or numpy.ndarray
        Sphere radius (scaled norm), scalar or one per azimuth, shape ``(k,)``. Ignored when
        ``shell`` is given.
    scales : numpy.ndarray
        Norm scales ``a_i``, shape ``(n,)``.
    directions : numpy.ndarray
        Unit directions to sample, shape ``(N, n)`` (see :func:`unit_sphere_points`).
    kind : {"max", "min"}
        Which extremum.
    per_psi : bool
        One extremum per azimuth (``True``) or one over all azimuths (``False``).
    free_psi : bool
        During refinement let the azimuth move (extremum over the whole period).
    period : float
        Period in ``psi``.
    shell : tuple of arrays, optional
        ``(lo, hi)`` radii per azimuth, shape ``(k,)``: search the shell
        ``lo <= ||x|| <= hi`` instead of a sphere, sampling ``n_levels`` equally spaced radii
        from ``lo`` to ``hi`` (both included) and refining with a free radius.
    n_levels : int
        Number of sampled radii in a shell.
    n_refine : int
        Number of best samples refined per azimuth (or overall).
    n_iter : int
        Iterations of the refinement.
    stop_above : float, optional
        Only with ``kind="max"`` and ``per_psi=False``: return as soon as a sample, or a
        candidate of the refinement, exceeds this value (the answer is then a lower bound of the
        max, enough to decide that a condition ``max <= stop_above`` fails).
    keep : int
        Only with ``per_psi=False``: return the best ``keep`` refined candidates, best first
        (starts for a further local search), instead of the best one.
    settle_at : float, optional
        Only with ``kind="max"`` and ``per_psi=True``: an azimuth whose samples or refined
        candidates reach this value (``>=``) is settled, its refinement stopped there (its value
        returned is then a lower bound of its maximum that reaches ``settle_at``); the others
        are searched as without it. Each azimuth's verdict ``max < settle_at`` is the one the
        full search gives (a refinement only raises a value), at a fraction of the cost where
        many azimuths reach it: :func:`rotorlyap.methods.lyapunov._start_radii`.

    Returns
    -------
    Extremum
        Values, azimuths and states, shape ``(k,)`` or ``(1,)``.
    """
    if kind not in ("max", "min"):
        raise ValueError(f"kind must be 'max' or 'min', got {kind!r}")
    sign = 1.0 if kind == "max" else -1.0
    psi = np.atleast_1d(np.asarray(psi, dtype=float))
    k = psi.size
    nd, n = directions.shape
    if shell is not None:
        lo, hi = (np.broadcast_to(np.asarray(b, dtype=float), (k,)) for b in shell)
        levels = lo[:, None] + (hi - lo)[:, None] * np.linspace(0.0, 1.0, max(n_levels, 1))[None, :]
        if n_levels <= 1:
            levels = hi[:, None]
    else:
        levels = np.broadcast_to(np.asarray(radius, dtype=float), (k,))[:, None]
    n_lev = levels.shape[1]

    # sample: shape (k, n_lev, nd); evaluated azimuth by azimuth in blocks to bound memory
    samples = np.empty((k, n_lev, nd))
    block = max(1, 200_000 // max(nd * n_lev, 1))
    same = psi_free(fun) and k > 1 and bool(np.all(levels == levels[:1]))
    for start in range(0, 1 if same else k, block):
        sl = slice(start, min(start + block, k))
        kb = sl.stop - sl.start
        p = np.repeat(psi[sl], n_lev * nd)
        r = np.repeat(levels[sl].reshape(-1), nd)
        x = (r[:, None] * np.tile(directions, (kb * n_lev, 1))) * scales
        if same:  # every azimuth's samples are the first's
            sl, kb = slice(0, 1), 1
            p, x = p[:n_lev * nd], x[:n_lev * nd]
        vals = sign * np.asarray(fun(p, x), dtype=float).reshape(kb, n_lev, nd)
        if same:
            fun.skip((k - 1) * n_lev * nd)
        samples[slice(0, k) if same else sl] = vals
        if stop_above is not None and sign > 0 and not per_psi and vals.max() > stop_above:
            flat = int(np.argmax(vals))
            ib, il, idir = np.unravel_index(flat, vals.shape)
            j = sl.start + ib
            xbest = levels[j, il] * directions[idir] * scales
            return Extremum(np.array([vals.max()]), np.array([psi[j]]), xbest[None, :])

    flat_samples = samples.reshape(k, -1)
    n_ref = max(1, min(n_refine, flat_samples.shape[1]))
    if per_psi:
        top = np.argsort(-flat_samples, axis=1)[:, :n_ref]  # (k, n_ref)
        rows = np.repeat(np.arange(k), n_ref)
        cols = top.reshape(-1)
    else:
        order = np.argsort(-flat_samples, axis=None)[: max(n_ref, 1) * 2]
        rows, cols = np.unravel_index(order, flat_samples.shape)
    il, idir = np.divmod(cols, nd)
    p0, r0, u0 = psi[rows], levels[rows, il], directions[idir]
    bounds = (lo[rows], hi[rows]) if shell is not None else None
    refine_stop = stop_above if sign > 0 and not per_psi else None
    settle = settle_at if per_psi and sign > 0 else None
    if n_iter > 0 and psi_free(fun):  # each distinct start refined once (its azimuth stays put)
        key = np.column_stack([r0, idir] + (list(bounds) if bounds is not None else []))
        _, first, inverse = np.unique(key, axis=0, return_index=True, return_inverse=True)
        inverse = inverse.reshape(-1)
        # the distinct starts are one azimuth's (every azimuth has the same): one group, which
        # settles at the iteration each azimuth's group of the full search settles at
        val, _, r1, u1 = refine_extremum(
            fun, p0[first], r0[first], u0[first], scales, sign=sign, free_psi=free_psi,
            period=period, rho_bounds=None if bounds is None else (bounds[0][first], bounds[1][first]),
            n_iter=n_iter, multiplicity=np.bincount(inverse), stop_above=refine_stop,
            groups=np.zeros(first.size, dtype=int) if settle is not None else None, settle_at=settle,
        )
        val, r1, u1 = sign * val[inverse], r1[inverse], u1[inverse]
        p1 = np.mod(p0, period) if free_psi else p0
    elif n_iter > 0:
        val, p1, r1, u1 = refine_extremum(
            fun, p0, r0, u0, scales, sign=sign, free_psi=free_psi, period=period,
            rho_bounds=bounds, n_iter=n_iter, stop_above=refine_stop,
            groups=rows if settle is not None else None, settle_at=settle,
        )
        val = sign * val
    else:
        val, p1, r1, u1 = flat_samples[rows, cols], p0, r0, u0
    x1 = (r1[:, None] * u1) * scales
    if per_psi:
        val = val.reshape(k, n_ref)
        best = np.argmax(val, axis=1)
        sel = np.arange(k) * n_ref + best
        # sampled optimum may beat a refined start that wandered (it cannot, but be safe)
        return Extremum(sign * val[np.arange(k), best], p1[sel], x1[sel])
    if keep > 1:
        order = np.argsort(-val)[:keep]
        return Extremum(sign * val[order], p1[order], x1[order])
    best = int(np.argmax(val))
    return Extremum(np.array([sign * val[best]]), np.array([p1[best]]), x1[best][None, :])
