"""Local maximisation of many starts at once: the polish of the searches for ``W'``.

The searches of :mod:`rotorlyap.methods.lyapunov` end by polishing their best candidates: a
local maximisation of ``fun(psi, y)`` over a ray parameter ``y = t u`` (``u`` a unit direction,
``t`` in ``[T_MIN, 1]``) and, when the azimuth is free, over ``psi`` too. Polished one start at
a time by scipy's L-BFGS-B (:func:`polish_scipy`), each iterate is one small call of ``fun``
(``2 d + 1`` states for the value and its central-difference gradient in ``d`` variables),
whose fixed cost dominates: 64 starts of a blade's ``W'`` took about 0.3 s, mostly call
overhead of the compiled model (measured, ``benchmarks/bench_speed.py``).

:func:`polish` moves every start together: one call of ``fun`` per iteration evaluates the
value and gradient of all of them. The method is a projected quasi-Newton ascent (BFGS on
each start's own ``d x d`` inverse Hessian, the bound of ``t`` handled by an active set as
L-BFGS-B handles it, a backtracking Armijo line search whose trial point carries its
gradient), with the stopping rules of L-BFGS-B (projected gradient ``<= gtol``, relative
change of the value ``<= ftol``, ``maxiter`` iterations). Each start moves independently:
the result of a start does not depend on the others (up to the rounding of a batched
evaluation of ``fun``).

Both functions return the starts' values where the polish does not improve them: never
worse than the starts.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

from .sampling import psi_free

__all__ = ["T_MIN", "ascend", "polish", "polish_scipy"]

T_MIN = 1e-9
"""Smallest ``t`` of the band's parametrisation ``y = t u`` (``t = 0``, the level set itself,
would lose the direction ``u``)."""

_H = 1e-6          # central-difference step of every variable
_FTOL = 1e-12      # relative change of the value (L-BFGS-B: 2.2e-9)
_GTOL = 1e-8       # largest projected gradient component (L-BFGS-B: 1e-5)
_ARMIJO = 1e-4     # sufficient increase of the line search
_MAX_HALVINGS = 30   # rounds of the line search (halvings and extrapolations)
_WOLFE = 0.9       # curvature condition: the slope along the step reduced to 0.9 of the start's


def _valid_starts(start) -> np.ndarray:
    t0 = np.linalg.norm(start.x, axis=1)
    return np.isfinite(start.value) & (t0 > 0.0)


class _Unpack:
    """Map the variables ``z = (v, t[, psi])`` of each start to ``(psi, y)``: ``u = v / |v|``
    (the start's direction where ``v`` is zero or overflows), ``t`` clipped to its bounds."""

    def __init__(self, u0: np.ndarray, t0: np.ndarray, psi0: np.ndarray, free_psi: bool):
        self.u0, self.t0, self.psi0, self.free_psi = u0, t0, psi0, free_psi
        self.n = u0.shape[1]

    def __call__(self, Z: np.ndarray, rows: np.ndarray):
        """``Z`` of shape ``(k, d)``; ``rows`` the start of each row."""
        n = self.n
        v = Z[:, :n]
        nv = np.linalg.norm(v, axis=1, keepdims=True)
        ok = np.isfinite(nv) & (nv > 0)
        u = np.where(ok, v / np.where(ok, nv, 1.0), self.u0[rows])
        t = np.clip(np.where(np.isnan(Z[:, n]), self.t0[rows], Z[:, n]), T_MIN, 1.0)
        if self.free_psi:
            p = np.where(np.isnan(Z[:, n + 1]), self.psi0[rows], Z[:, n + 1])
        else:
            p = self.psi0[rows]
        return p, u * t[:, None]


def ascend(fun: Callable[[np.ndarray, np.ndarray], np.ndarray], z0: np.ndarray, lower: np.ndarray,
           upper: np.ndarray, *, maxiter: int = 100, ftol: float = _FTOL, gtol: float = _GTOL,
           stop_above: float | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Local maxima of ``fun(Z, rows)`` from every row of ``z0`` at once, within the bounds.

    The core of :func:`polish`: a projected quasi-Newton ascent of each start (its own BFGS
    inverse Hessian; variables at a bound where the gradient pushes them out held fixed, as
    L-BFGS-B does; a line search that backtracks to the Armijo condition and extrapolates while
    the slope stays steep), the value and central-difference gradient of every moving start in
    one call of ``fun`` per round.

    Parameters
    ----------
    fun : callable
        ``fun(Z, rows)``: the values at the points ``Z`` (k, d), row ``j`` a point of the start
        ``rows[j]``; shape ``(k,)``.
    z0 : numpy.ndarray
        Starts, shape ``(m, d)``, within the bounds.
    lower, upper : numpy.ndarray
        Bounds, shape ``(m, d)`` (``-inf``/``inf`` where free).
    maxiter : int
        Largest number of iterations of each start.
    ftol, gtol : float
        A start stops when an iteration changes its value by at most ``ftol`` relative (to
        ``max(|f|, 1)``), when its largest projected gradient component is at most ``gtol``, or
        when no step along its direction increases the value.
    stop_above : float, optional
        Stop every start after the first iteration at whose end one of them has a value above
        it (enough to decide that a condition ``max <= stop_above`` fails).

    Returns
    -------
    value, z : numpy.ndarray
        The values (``nan`` where a start's own value is not finite) and points reached.
    """
    z = np.clip(np.array(z0, dtype=float, copy=True), lower, upper)
    m, d = z.shape
    steps = np.eye(d) * _H

    def value_and_gradient(Z: np.ndarray, rows: np.ndarray):
        """Minus ``fun`` and its central-difference gradient at the rows ``Z`` (k, d)."""
        k = Z.shape[0]
        # start by start (its 2 d + 1 points together, most at its azimuth: a kernel computes what
        # depends on the azimuth alone once for them); each point's value does not depend on its
        # place in the batch
        Zall = np.concatenate([Z[None], Z[None] + steps[:, None], Z[None] - steps[:, None]])
        Zall = Zall.transpose(1, 0, 2).reshape(-1, d)
        v = -np.asarray(fun(Zall, np.repeat(rows, 2 * d + 1)), dtype=float).reshape(k, 2 * d + 1).T
        return v[0], ((v[1:d + 1] - v[d + 1:]) / (2 * _H)).T

    def projected_gradient(zz, g, lo, hi):  # L-BFGS-B's: the step -g projected on the box
        return zz - np.clip(zz - g, lo, hi)

    rows = np.arange(m)
    F, G = value_and_gradient(z, rows)
    Hinv = np.repeat(np.eye(d)[None], m, axis=0)
    fresh = np.ones(m, dtype=bool)       # Hinv not yet updated: the first step is scaled
    active = np.isfinite(F) & np.all(np.isfinite(G), axis=1)
    active &= np.abs(projected_gradient(z, G, lower, upper)).max(axis=1) > gtol
    eye = np.eye(d)[None]
    for _ in range(maxiter):
        idx = np.flatnonzero(active)
        if idx.size == 0 or (stop_above is not None and np.any(-F > stop_above)):
            break
        zi, Fi, Gi, Hi = z[idx], F[idx], G[idx], Hinv[idx]
        lo, hi = lower[idx], upper[idx]
        # minimising F = -fun: a variable at a bound where the step -G leaves the box stays put
        held = ((zi <= lo) & (Gi > 0)) | ((zi >= hi) & (Gi < 0))
        free_mask = np.where(held, 0.0, 1.0)
        Gf = Gi * free_mask
        p = -np.einsum("kij,kj->ki", Hi * free_mask[:, :, None] * free_mask[:, None, :], Gf)
        bad = ~(np.einsum("ki,ki->k", Gf, p) < 0) | ~np.all(np.isfinite(p), axis=1)
        p = np.where(bad[:, None], -Gf, p)                       # not a descent direction: steepest
        first = fresh[idx] | bad
        # no curvature known yet: the first step at most 0.1 in the variables
        pnorm = np.linalg.norm(p, axis=1)
        p = p * np.where(first, np.minimum(1.0, 0.1 / np.maximum(pnorm, 1e-300)), 1.0)[:, None]
        # line search, every start at once: backtrack (halve) until the Armijo condition holds;
        # where the first accepted step still descends steeply (the curvature condition of
        # Wolfe fails), extrapolate (x4) while the value keeps decreasing
        s_len = np.ones(idx.size)
        pending = np.ones(idx.size, dtype=bool)     # no step accepted yet
        searching = np.ones(idx.size, dtype=bool)
        expanding = np.zeros(idx.size, dtype=bool)
        z_new, F_new, G_new = zi.copy(), Fi.copy(), Gi.copy()
        g_p = np.einsum("ki,ki->k", Gf, p)  # < 0: the slope along p at the start
        for _ in range(_MAX_HALVINGS):
            j = np.flatnonzero(searching)
            if j.size == 0:
                break
            raw = zi[j] + s_len[j, None] * p[j]
            trial = np.clip(raw, lo[j], hi[j])
            clipped = np.any(trial != raw, axis=1)
            Ft, Gt = value_and_gradient(trial, idx[j])
            dec = np.einsum("ki,ki->k", Gi[j], trial - zi[j])
            ok = np.isfinite(Ft) & np.all(np.isfinite(Gt), axis=1) & (Ft <= Fi[j] + _ARMIJO * np.minimum(dec, 0.0))
            ok &= ~expanding[j] | (Ft < F_new[j])   # an extrapolated step must improve on the accepted one
            acc = j[ok]
            z_new[acc], F_new[acc], G_new[acc] = trial[ok], Ft[ok], Gt[ok]
            pending[acc] = False
            steep = np.einsum("ki,ki->k", Gt * free_mask[j], p[j]) < _WOLFE * g_p[j]
            grow = ok & steep & ~clipped
            searching[j[ok & ~grow]] = False
            searching[j[~ok & expanding[j]]] = False       # the extrapolation went too far: keep the last
            expanding[j[grow]] = True
            s_len[j[grow]] *= 4.0
            s_len[j[~ok & ~expanding[j]]] *= 0.5
        moved = ~pending
        # BFGS update of the inverse Hessian where the curvature condition holds
        s = z_new - zi
        yv = G_new - Gi
        sy = np.einsum("ki,ki->k", s, yv)
        upd = moved & (sy > 1e-10 * np.linalg.norm(s, axis=1) * np.linalg.norm(yv, axis=1)) & (sy > 0)
        if upd.any():
            u_ = np.flatnonzero(upd)
            H = Hi[u_]
            fr = first[u_]
            if fr.any():  # Shanno-Phua scaling of the first inverse Hessian
                yy = np.einsum("ki,ki->k", yv[u_], yv[u_])
                H[fr] = eye * (sy[u_][fr] / yy[fr])[:, None, None]
            rho = 1.0 / sy[u_]
            V = eye - rho[:, None, None] * np.einsum("ki,kj->kij", s[u_], yv[u_])
            H = np.einsum("kij,kjl,kml->kim", V, H, V) + rho[:, None, None] * np.einsum("ki,kj->kij", s[u_], s[u_])
            Hi[u_] = H
            fresh[idx[u_]] = False
        reset = moved & ~upd   # no usable curvature: start again from the steepest direction
        Hi[reset] = np.eye(d)
        fresh[idx[reset]] = True
        Hinv[idx] = Hi
        change = Fi - F_new
        z[idx], F[idx], G[idx] = z_new, F_new, G_new
        done = pending.copy()                                       # no step increased the value
        done |= change <= ftol * np.maximum(np.maximum(np.abs(Fi), np.abs(F_new)), 1.0)
        done |= np.abs(projected_gradient(z_new, G_new, lo, hi)).max(axis=1) <= gtol
        active[idx[done]] = False
    return -F, z


def polish(fun: Callable[[np.ndarray, np.ndarray], np.ndarray], start, *, free_psi: bool,
           maxiter: int = 100, stop_above: float | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Local maximisation of ``fun(psi, y)`` from every start of ``start`` at once.

    The variables of each start: ``v`` (the direction ``v / |v|``, free in ``R^n``), ``t`` in
    ``[T_MIN, 1]`` and, if ``free_psi``, ``psi``; maximised by :func:`ascend`.

    Parameters
    ----------
    fun : callable
        ``fun(psi, y)`` with ``psi`` of shape ``(k,)`` and ``y`` of shape ``(k, n)``, returning
        shape ``(k,)``; ``y = t u`` with ``|u| = 1`` and ``t`` in ``[T_MIN, 1]``.
    start : rotorlyap.methods.sampling.Extremum
        The starts: ``value`` (their values of ``fun``), ``psi`` and ``x`` (their ``y``).
    free_psi : bool
        Let the azimuth move too.
    maxiter : int
        Largest number of iterations of each start.
    stop_above : float, optional
        Stop every start as soon as one has a value above it (:func:`ascend`).

    Returns
    -------
    values, psi, y : numpy.ndarray
        For each start, the best point found (the start itself where nothing better was).
    """
    values, psis, ys = (np.array(a, dtype=float, copy=True) for a in (start.value, start.psi, start.x))
    valid = np.flatnonzero(_valid_starts(start))
    if valid.size == 0:
        return values, psis, ys
    copies = None
    if psi_free(fun):  # each distinct start once: its copies at other azimuths move alike
        _, first, copies = np.unique(np.column_stack([values[valid], ys[valid]]), axis=0,
                                     return_index=True, return_inverse=True)
        copies = copies.reshape(-1)
        extra = np.bincount(copies) - 1
        everyone, valid = valid, valid[first]
    n = ys.shape[1]
    t0 = np.linalg.norm(ys[valid], axis=1)
    u0 = ys[valid] / t0[:, None]
    unpack = _Unpack(u0, t0, psis[valid], free_psi)
    z0 = np.concatenate([u0, t0[:, None], psis[valid][:, None]] if free_psi else [u0, t0[:, None]], axis=1)
    lower = np.full(z0.shape, -np.inf)
    upper = np.full(z0.shape, np.inf)
    lower[:, n], upper[:, n] = T_MIN, 1.0

    def evaluate(Z, rows):
        out = fun(*unpack(Z, rows))
        if copies is not None:
            fun.skip(int(extra[rows].sum()))
        return out

    F, z = ascend(evaluate, z0, lower, upper, maxiter=maxiter, stop_above=stop_above)
    p_best, y_best = unpack(z, np.arange(valid.size))
    if copies is not None:  # back to every start (the azimuth of each its own: it did not move)
        F, y_best, valid = F[copies], y_best[copies], everyone
        p_best = psis[valid]
    better = np.isfinite(F) & (F > values[valid])
    sel = valid[better]
    values[sel], psis[sel], ys[sel] = F[better], p_best[better], y_best[better]
    return values, psis, ys


def polish_scipy(fun: Callable[[np.ndarray, np.ndarray], np.ndarray], start, *, free_psi: bool,
                 maxiter: int = 100) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`polish` by scipy's L-BFGS-B, one start at a time (the reference it is measured and
    tested against): the same variables, bounds and central-difference gradients, one small call
    of ``fun`` per iterate."""
    from scipy.optimize import minimize

    values, psis, ys = (np.array(a, dtype=float, copy=True) for a in (start.value, start.psi, start.x))
    n = ys.shape[1]
    for i in np.flatnonzero(_valid_starts(start)):
        t0 = float(np.linalg.norm(ys[i]))
        unpack = _Unpack(ys[i:i + 1] / t0, np.array([t0]), psis[i:i + 1], free_psi)
        z0 = np.concatenate([ys[i] / t0, [t0], [psis[i]] if free_psi else []])
        d = z0.size
        steps = np.eye(d) * _H
        rows = np.zeros(2 * d + 1, dtype=int)

        def fg(z):
            v = np.asarray(fun(*unpack(np.vstack([z, z + steps, z - steps]), rows)), dtype=float)
            return -v[0], -(v[1:d + 1] - v[d + 1:]) / (2 * _H)

        bounds = [(None, None)] * n + [(T_MIN, 1.0)] + ([(None, None)] if free_psi else [])
        res = minimize(fg, z0, jac=True, method="L-BFGS-B", bounds=bounds, options={"maxiter": maxiter})
        if np.isfinite(res.fun) and -res.fun > values[i]:
            p, y = unpack(res.x[None, :], np.zeros(1, dtype=int))
            values[i], psis[i], ys[i] = -res.fun, p[0], y[0]
    return values, psis, ys
