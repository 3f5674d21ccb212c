"""Condition (h) of a quadratic Liapunov function shown from a polynomial: branch and bound over directions.

For ``W(y) = y^T S y`` and ``y' = g0 + K(y) y`` (scaled coordinates, ``K`` the averaged Jacobian,
:mod:`rotorlyap.methods.proof`), let the Taylor models of ``K`` over the cube ``|y_i| <= A_c``
(:meth:`rotorlyap.methods.taylor.TaylorModel.ray_average`) give, for ``t = y / A_c`` in
``[-1, 1]^n``,

    ``K(A_c t) = sum_alpha C_alpha t^alpha + E``,  ``|E_ij| <= R_ij``.

Then

    ``W'(A_c t) / A_c^2 = p(t) + 2 t^T S E t + 2 t^T S g0 / A_c``,
    ``p(t) = t^T S' t + 2 sum_alpha (t^T S C_alpha t) t^alpha``,

and ``p`` has no term of degree below 2. Every ``t != 0`` is ``t = sigma v`` with
``sigma = max_i |t_i|`` and ``v`` on a face of the cube (``v_i = +-1`` for one ``i``, the other
coordinates in ``[-1, 1]``), so

    ``W' / (A_c sigma)^2 = F(v, sigma) + 2 v^T S E v + 2 v^T S g0 / (A_c sigma)``,
    ``F(v, sigma) = sum_beta p_beta sigma^(|beta| - 2) v^beta``,

a polynomial in the ``n - 1`` free coordinates of ``v`` and ``sigma``: the dependence on the
disturbance that the cancellations of the equations leave, kept exactly, and the remainder ``R``
apart. The band ``|y| <= A, W >= c`` of the theorem's condition (h) is, on a face,
``sigma |v| <= rho`` and ``sigma^2 v^T S v >= c / A_c^2`` (``rho = A / A_c <= 1``).

:func:`largest_bound` shows ``W' < 0`` on the band out to the largest bound it can, by branch and
bound over boxes of ``(v, sigma)`` on each of the ``2 n`` faces. ``p``'s quadratic part is
``t^T (S' + C_0^T S + S C_0) t <= n0 |t|^2`` (``n0`` from rigorous eigenvalue bounds), and the rest
is ``sigma^3 H(v, sigma)`` with ``H`` a polynomial, so on a box

    ``W' / (A_c sigma)^2 <= n0 min|v|^2 + sigma H + 2 sum_jk |S v|_j R_jk |v_k| + 2 |S g0| |v| / (A_c sigma_lo)``,

``H`` bounded above by the smaller of its mean-value form ``H(centre) + sum_i |dH/dx_i (box)| w_i``
and its second-order form ``H(centre) + sum_i |dH/dx_i (centre)| w_i + sum_i max(d2H/dx_i^2 (box), 0)
w_i^2 / 2 + sum_{i<j} |d2H/dx_i dx_j (box)| w_i w_j`` (Taylor's theorem with the Lagrange remainder;
the values, gradients and Hessians in ball arithmetic: Rump's midpoint-radius formulas of
:mod:`rotorlyap.methods.balls`, compiled by numba when it is installed), ``sigma H`` by
``sigma_hi H`` or ``sigma_lo H`` after its sign, every other term in ball arithmetic. The box's
``sigma`` range is cut to the band (``sigma_lo = sqrt(c / (A_c^2 max v^T S v))``,
``sigma_hi = rho / min |v|``, both rounded outwards) and a box with no point of the band is dropped.
A box whose bound is negative is closed; one that is not is split at the middle of the coordinate
that contributes most to its mean-value term (the boxes are kept as float end points, so a split
covers its box exactly). The bound steps down (:data:`STEPS`) where a box centre in the band has a
polynomial part that is not negative (the models cannot show the condition there) or after
``patience`` boxes without closing the search, every closed box staying closed; after ``max_boxes``
boxes it drops below the nearest open box. At the end every point of the band lies in a closed box:
``W' < 0`` there, for the model as the Taylor models enclose it (every step rigorous).

With ``level_set`` the search covers the level set ``W = c`` alone (within ``|y| <= A``): each box's
``sigma`` range is cut also to ``sigma_hi = sqrt(c / (A_c^2 min v^T S v))``, the quadratic part is
bounded by ``v^T N0 v`` over the box as well (``N0 = S' + C_0^T S + S C_0``, ``n0`` the bound of
its largest eigenvalue: in the directions where ``S`` is large, where the level set comes near
the origin, ``v^T N0 v`` is far below ``n0 |v|^2``), and a box is cut along a coordinate of ``v``
(its ``sigma`` range shrinks with it). That ``W' < 0`` on the level set makes ``{W <= c}``
invariant (:func:`rotorlyap.methods.proof.prove_quadratic_models`).

Vectorised over azimuth intervals (one polynomial and one ``S`` per interval: ``S`` may be
balls, ``p``'s coefficients are balls) and faces: every box carries its interval and face.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import balls as fb
from . import intervals as iv
from .balls import Balls, U as _U
from .balls import _K, _PAD

__all__ = ["BandPolynomial", "BandResult", "band_polynomial", "hopeless", "largest_bound"]


@dataclass(frozen=True)
class BandPolynomial:
    """``W'`` on the cube of the models, as :func:`negative_on_band` needs it (module docstring).

    Attributes
    ----------
    n : int
        Dimension of the state.
    exponents : numpy.ndarray of int, shape (M, n)
        The exponents ``(gamma, d)`` of the face polynomials ``H``: the ``n - 1`` free coordinates
        of ``v`` in order, then ``sigma`` (the same table for every face).
    coef : Balls, shape (N, 2 n, M)
        ``H``'s coefficients per azimuth interval and face (face ``2 i`` is ``v_i = +1``, ``2 i + 1``
        is ``v_i = -1``).
    n0 : numpy.ndarray, shape (N,)
        Upper bounds of ``lambda_max(S' + C_0^T S + S C_0)``: the quadratic part, ``v^T (...) v <= n0 |v|^2``.
    S : Balls, shape (N, n, n)
        ``S`` over each interval.
    R : numpy.ndarray, shape (N, n, n)
        The remainders of the averaged Jacobian's models (scaled coordinates).
    residual : numpy.ndarray, shape (N,)
        Upper bounds of ``|S g0|`` (scaled coordinates).
    cube : float
        ``A_c``, the half-width of the models' cube (scaled norm).
    N0 : Balls, shape (N, n, n), optional
        The quadratic part's matrix over each interval (``v^T N0 v`` bounds it per box of ``v``: the
        search on the level set, where ``n0 |v|^2`` is too coarse in the directions where ``S`` is
        large); None: ``n0`` alone.
    """

    n: int
    exponents: np.ndarray
    coef: Balls
    n0: np.ndarray
    S: Balls
    R: np.ndarray
    residual: np.ndarray
    cube: float
    N0: Balls | None = None


@dataclass(frozen=True)
class BandResult:
    """Outcome of :func:`largest_bound`.

    Attributes
    ----------
    A : float
        The bound shown (scaled norm): ``W' < 0`` on ``|y| <= A, W >= level`` of every interval.
    boxes : int
        Boxes bounded.
    estimate : numpy.ndarray, shape (N,)
        Per interval, the largest ``W' / |y|^2`` of the polynomial part at the box centres in the
        band (an estimate of the worst, not a bound).
    message : str
    """

    A: float
    boxes: int
    estimate: np.ndarray
    message: str


def _monomial_index(exps: np.ndarray) -> dict:
    return {tuple(int(v) for v in e): i for i, e in enumerate(exps)}


def band_polynomial(S: Balls, dS: Balls, coef: Balls, K_exponents: np.ndarray, R: np.ndarray,
                    residual: np.ndarray, cube: float, n0: np.ndarray | None = None,
                    keep: int | None = 2, N0: Balls | None = None) -> BandPolynomial:
    """The face polynomials ``F`` of ``W'`` from the averaged Jacobian's models.

    Parameters
    ----------
    S, dS : Balls, shape (N, n, n)
        ``S`` and ``S'`` (per rad) over each of ``N`` azimuth intervals (scaled coordinates).
    coef : Balls, shape (N, M_K, n, n)
        ``C_alpha``: the coefficients of the averaged Jacobian's models in ``t = y / A_c``
        (scaled coordinates), per monomial of ``K_exponents``.
    K_exponents : numpy.ndarray of int, shape (M_K, n)
        The monomials ``alpha`` of the models.
    R : numpy.ndarray, shape (N, n, n)
        Remainders of the models (``|K - sum C_alpha t^alpha| <= R`` entrywise on the cube).
    residual : numpy.ndarray, shape (N,)
        Upper bounds of ``|S g0|``.
    cube : float
        ``A_c`` (> 0).
    keep : int or None
        The models' terms of degree above ``keep`` are moved into the remainder (``|t^alpha| <= 1``
        on the cube): ``W'``'s polynomial then has degree ``keep + 2``, cheaper to bound (default 2;
        None keeps every term).
    n0 : numpy.ndarray, shape (N,), optional
        Upper bounds of ``lambda_max`` of the quadratic part, given (for example from the
        Jacobian at the steady motion on finer intervals, ``R`` then covering ``K - J0``'s
        departure from the models' non-constant terms); default: from ``S'`` and ``C_0``.
    N0 : Balls, shape (N, n, n), optional
        With ``n0``: balls of the quadratic part's matrix whose ``lambda_max`` ``n0`` bounds
        (:attr:`BandPolynomial.N0`); default: ``S' + C_0^T S + S C_0`` where ``n0`` is not given,
        else None.

    Returns
    -------
    BandPolynomial
    """
    S, dS, coef = fb.as_balls(S), fb.as_balls(dS), fb.as_balls(coef)
    K_exponents = np.asarray(K_exponents, dtype=int)
    if keep is not None and np.any(K_exponents.sum(axis=1) > keep):
        high = K_exponents.sum(axis=1) > keep
        moved = Balls(coef.mid[:, high], coef.rad[:, high]).magnitude()
        R = (Balls(np.asarray(R, dtype=float)) + Balls(moved).sum(axis=1)).upper()
        coef = Balls(coef.mid[:, ~high], coef.rad[:, ~high])
        K_exponents = K_exponents[~high]
    N, n = S.shape[0], S.shape[-1]
    # p(t) = t^T S' t + 2 sum_alpha sum_ij (S C_alpha)_ij t_i t_j t^alpha
    SC = fb.matmul(S[:, None, :, :], coef) * 2.0                    # (N, M_K, n, n)
    deg_K = int(K_exponents.sum(axis=1).max())
    p_exps = []
    for d in range(3, deg_K + 3):
        p_exps += _exponents_of_degree(n, d)
    p_exps = np.asarray(p_exps, dtype=int).reshape(-1, n)
    index = _monomial_index(p_exps)
    P = len(p_exps)
    mid = np.zeros((N, P))
    rad = np.zeros((N, P))
    p = Balls(mid, rad)
    eye = np.eye(n, dtype=int)
    nonconstant = K_exponents.sum(axis=1) > 0
    SC = SC[:, nonconstant]
    for i in range(n):
        for j in range(n):
            target = np.array([index[tuple(a + eye[i] + eye[j])] for a in K_exponents[nonconstant]])
            term = SC[:, :, i, j]
            if target.size != np.unique(target).size:  # pragma: no cover - injective for fixed i, j
                raise AssertionError("monomial map not injective")
            full = Balls(np.zeros((N, P)), np.zeros((N, P)))
            full.mid[:, target] = term.mid
            full.rad[:, target] = term.rad
            p = p + full
    # the quadratic part: n0 >= lambda_max(S' + C_0^T S + S C_0)
    if n0 is None:
        C0 = coef[:, int(np.flatnonzero(~nonconstant)[0])]
        SC0 = fb.matmul(S, C0)
        N0 = dS + SC0 + SC0.swapaxes(-1, -2)
        with iv.arithmetic("balls"):
            _, n0 = iv.symmetric_eigenvalue_bounds(N0)
    # faces: v_i = s; exponent of F: (beta without i, |beta| - 3), coefficient p_beta s^beta_i
    deg = p_exps.sum(axis=1)
    f_exps = None
    cm = np.zeros((N, 2 * n, P))
    cr = np.zeros((N, 2 * n, P))
    for i in range(n):
        red = np.hstack([np.delete(p_exps, i, axis=1), (deg - 3)[:, None]])
        if f_exps is None:
            f_exps = red
            f_index = _monomial_index(f_exps)
            order = np.arange(P)
        else:
            order = np.array([f_index[tuple(int(v) for v in e)] for e in red])
        for s, face in ((1.0, 2 * i), (-1.0, 2 * i + 1)):
            sign = np.where(p_exps[:, i] % 2 == 1, s, 1.0)
            cm[:, face, order] = p.mid * sign[None, :]
            cr[:, face, order] = p.rad
    return BandPolynomial(n=n, exponents=f_exps, coef=Balls(cm, cr), n0=np.asarray(n0, dtype=float), S=S,
                          R=np.asarray(R, dtype=float),
                          residual=np.asarray(residual, dtype=float).reshape(N), cube=float(cube),
                          N0=None if N0 is None else fb.as_balls(N0))


def _exponents_of_degree(n: int, d: int) -> list:
    import itertools

    out = []
    for combo in itertools.combinations_with_replacement(range(n), d):
        out.append(np.bincount(np.asarray(combo, dtype=int), minlength=n))
    return out


SPLIT_BY_SHARE = False
"""Split a box along the coordinate with the largest share of its bound's excess, the remainder's
and the quadratic part's included (True), or of ``H``'s mean-value term alone (False, the default).
Measured (2026-12-05, :func:`rotorlyap.analysis.proof.prove_blade`'s defaults): True raises the
trimmed helicopter's mu = 0.1 proof from 0.60 to 0.64 of the numerical bound, leaves the Table I
hovers at 0.90, 0.90, 0.95, and lowers the Puma hover's (``tests/test_c81_model.py``) from 0.87
and 0.80 (built-in section, C81 table) to 0.83 and 0.68: not better everywhere, so off."""

STEPS = (1.0, 0.95, 0.9, 0.85, 0.8, 0.75, 0.7, 0.65, 0.6, 0.5, 0.4, 0.3, 0.2, 0.1, 0.05, 0.02, 0.01)
"""The bounds :func:`largest_bound` tries, as fractions of the cap (the largest bound asked, or the
smallest radius of a box centre where the polynomial part was found not negative), in order."""


class _Evaluator:
    """The face polynomials and their gradients over boxes, in ball arithmetic."""

    def __init__(self, bp: BandPolynomial):
        E = bp.exponents
        m = E.shape[1]
        index = _monomial_index(E)
        exps = [tuple(int(v) for v in e) for e in E]

        def add(e):
            if e not in index:
                index[e] = len(exps)
                exps.append(e)
            return index[e]

        grads = []
        for i in range(m):
            keep = E[:, i] > 0
            d = E[keep].copy()
            d[:, i] -= 1
            grads.append((np.flatnonzero(keep), np.array([add(tuple(int(v) for v in e)) for e in d], dtype=int),
                          E[keep, i].astype(float)))
        hess = []
        self.pairs = [(i, j) for i in range(m) for j in range(i, m)]
        for i, j in self.pairs:
            d = E.copy()
            d[:, i] -= 1
            d[:, j] -= 1
            keep = np.all(d >= 0, axis=1)
            mult = (E[keep, i] * (E[keep, i] - 1) if i == j else E[keep, i] * E[keep, j]).astype(float)
            hess.append((np.flatnonzero(keep), np.array([add(tuple(int(v) for v in e)) for e in d[keep]], dtype=int),
                         mult))
        # close downwards along the first nonzero exponent (each monomial = its parent times one variable)
        j = 0
        while j < len(exps):
            e = exps[j]
            nz = [i for i, v in enumerate(e) if v]
            if nz:
                parent = list(e)
                parent[nz[0]] -= 1
                add(tuple(parent))
            j += 1
        all_exps = np.asarray(exps, dtype=int).reshape(-1, m)
        self.all_exps = all_exps
        self.M = E.shape[0]
        self.grads = grads
        self.m = m
        deg = all_exps.sum(axis=1)
        self.levels = []
        for d in range(1, int(deg.max()) + 1 if deg.size else 1):
            idx = np.flatnonzero(deg == d)
            var = np.argmax(all_exps[idx] > 0, axis=1)
            par = all_exps[idx].copy()
            par[np.arange(idx.size), var] -= 1
            self.levels.append((idx, np.array([index[tuple(int(v) for v in e)] for e in par], dtype=int), var))
        self.one = index[(0,) * m]
        self.order = np.argsort(deg, kind="stable").astype(np.int64)
        parent = np.full(len(all_exps), -1, dtype=np.int64)
        var = np.zeros(len(all_exps), dtype=np.int64)
        for idx_, par, vv in self.levels:
            parent[idx_] = par
            var[idx_] = vv
        self.parent, self.var = parent, var
        self.gsrc = np.concatenate([g[0] for g in grads]).astype(np.int64) if grads else np.zeros(0, np.int64)
        self.gtgt = np.concatenate([g[1] for g in grads]).astype(np.int64) if grads else np.zeros(0, np.int64)
        self.gmul = np.concatenate([g[2] for g in grads]) if grads else np.zeros(0)
        self.gstart = np.concatenate([[0], np.cumsum([g[0].size for g in grads])]).astype(np.int64)
        self.hsrc = np.concatenate([h[0] for h in hess] + [np.zeros(0, int)]).astype(np.int64)
        self.htgt = np.concatenate([h[1] for h in hess] + [np.zeros(0, int)]).astype(np.int64)
        self.hmul = np.concatenate([h[2] for h in hess] + [np.zeros(0)])
        self.hstart = np.concatenate([[0], np.cumsum([h[0].size for h in hess])]).astype(np.int64)
        self.pi = np.array([i for i, _ in self.pairs], dtype=int)
        self.pj = np.array([j for _, j in self.pairs], dtype=int)

    def second_order(self, coef: Balls, xc: np.ndarray, xw: np.ndarray):
        """``(floats >= |dH/dx_i (centre)| (B, m), Hessian entries over the boxes as balls (B, pairs))``
        (compiled only; None without numba)."""
        if not _COMPILED:
            return None
        B = xc.shape[0]
        P = len(self.pairs)
        g, hm, hr = np.empty((B, self.m)), np.empty((B, P)), np.empty((B, P))
        _second_kernel(np.ascontiguousarray(coef.mid), np.ascontiguousarray(coef.rad), np.ascontiguousarray(xc),
                       np.ascontiguousarray(xw), self.order, self.parent, self.var, self.gsrc, self.gtgt, self.gmul,
                       self.gstart, self.hsrc, self.htgt, self.hmul, self.hstart, g, hm, hr)
        return g, Balls._new(hm, hr)

    def centre_and_gradient(self, coef: Balls, xc: np.ndarray, xw: np.ndarray):
        """``(H(centre) as balls (B,), floats >= |dH/dx_i| over the boxes (B, m))``."""
        if not _COMPILED:
            return self.value(coef, Balls(xc)), self.gradient_magnitudes(coef, Balls(xc, xw))
        B = xc.shape[0]
        out_m, out_r, out_g = np.empty(B), np.empty(B), np.empty((B, self.m))
        _bound_kernel(np.ascontiguousarray(coef.mid), np.ascontiguousarray(coef.rad), np.ascontiguousarray(xc),
                      np.ascontiguousarray(xw), self.order, self.parent, self.var, self.gsrc, self.gtgt, self.gmul,
                      self.gstart, out_m, out_r, out_g)
        return Balls._new(out_m, out_r), out_g

    def monomials(self, x: Balls) -> Balls:
        """Every monomial of ``all_exps`` at the balls ``x`` (B, m): Balls (B, M_all), one ball product per
        degree."""
        B = x.shape[0]
        mid = np.empty((B, len(self.all_exps)))
        rad = np.empty((B, len(self.all_exps)))
        mid[:, self.one] = 1.0
        rad[:, self.one] = 0.0
        for idx, par, var in self.levels:
            prod = Balls._new(mid[:, par], rad[:, par]) * Balls._new(x.mid[:, var], x.rad[:, var])
            mid[:, idx] = prod.mid
            rad[:, idx] = prod.rad
        return Balls._new(mid, rad)

    def value(self, coef: Balls, x: Balls) -> Balls:
        mono = self.monomials(x)
        return (coef * Balls._new(mono.mid[:, :self.M], mono.rad[:, :self.M])).sum(axis=-1)

    def gradient_magnitudes(self, coef: Balls, x: Balls) -> np.ndarray:
        """Floats ``>= |dH/dx_i|`` over the boxes ``x``: (B, m)."""
        mono = self.monomials(x)
        out = np.zeros((x.shape[0], self.m))
        for i, (src, tgt, mult) in enumerate(self.grads):
            if src.size == 0:
                continue
            c = Balls._new(coef.mid[:, src], coef.rad[:, src]) * mult[None, :]
            g = (c * Balls._new(mono.mid[:, tgt], mono.rad[:, tgt])).sum(axis=-1)
            out[:, i] = g.magnitude()
        return out


def _ball_mul(ma, ra, mb, rb):
    """Rump's ball product, the radius formula of :mod:`rotorlyap.methods.balls` (F1-F2)."""
    c = ma * mb
    return c, (abs(ma) * rb + ra * (abs(mb) + rb) + _U * abs(c)) * _K + _PAD


def _ball_add(ma, ra, mb, rb):
    """Rump's ball sum, the radius formula of :mod:`rotorlyap.methods.balls` (F1, no eta)."""
    c = ma + mb
    return c, (ra + rb + _U * abs(c)) * _K + _PAD


def _monomials(b, order, parent, var, xc, xw, pm, pr, bm, br):
    """Box ``b``'s monomials as balls, each by one ball product (its parent times a variable, in the
    order ``order``): at the box's centre (``pm``, ``pr``) and over the box (``bm``, ``br``)."""
    for q in range(parent.shape[0]):
        j = order[q]
        if parent[j] < 0:
            pm[j] = 1.0
            pr[j] = 0.0
            bm[j] = 1.0
            br[j] = 0.0
        else:
            v = var[j]
            pm[j], pr[j] = _ball_mul(pm[parent[j]], pr[parent[j]], xc[b, v], 0.0)
            bm[j], br[j] = _ball_mul(bm[parent[j]], br[parent[j]], xc[b, v], xw[b, v])


def _derivative_ball(b, lo, hi, cm, cr, src, tgt, mul, xm, xr):
    """The ball of one derivative of box ``b``'s polynomial: ``sum_q c[src_q] mul_q x[tgt_q]`` over
    the terms ``lo <= q < hi`` (coefficients ``cm``, ``cr``; monomials ``xm``, ``xr`` at the
    centre or over the box), one ball sum at a time."""
    sm, sr = 0.0, 0.0
    for q in range(lo, hi):
        am, ar = _ball_mul(cm[b, src[q]], cr[b, src[q]], mul[q], 0.0)
        tm_, tr_ = _ball_mul(am, ar, xm[tgt[q]], xr[tgt[q]])
        sm, sr = _ball_add(sm, sr, tm_, tr_)
    return sm, sr


def _bound_kernel(cm, cr, xc, xw, order, parent, var, gsrc, gtgt, gmul, gstart, out_m, out_r, out_g):
    """Per box ``b``: the ball of ``H`` at the centre (``out_m``, ``out_r``) and floats ``>= |dH/dx_i|``
    over the box (``out_g``): the monomials by one ball product each (parent times a variable, in
    the order ``order``), every sum accumulated one ball sum at a time (each step rigorous)."""
    B, Mall = cm.shape[0], parent.shape[0]
    m = xc.shape[1]
    M = cm.shape[1]
    pm = np.empty(Mall)
    pr = np.empty(Mall)
    bm = np.empty(Mall)
    br = np.empty(Mall)
    for b in range(B):
        _monomials(b, order, parent, var, xc, xw, pm, pr, bm, br)
        sm, sr = 0.0, 0.0
        for j in range(M):
            tm_, tr_ = _ball_mul(cm[b, j], cr[b, j], pm[j], pr[j])
            sm, sr = _ball_add(sm, sr, tm_, tr_)
        out_m[b] = sm
        out_r[b] = sr
        for i in range(m):
            sm, sr = _derivative_ball(b, gstart[i], gstart[i + 1], cm, cr, gsrc, gtgt, gmul, bm, br)
            out_g[b, i] = np.nextafter(abs(sm) + sr, np.inf)


def _second_kernel(cm, cr, xc, xw, order, parent, var, gsrc, gtgt, gmul, gstart, hsrc, htgt, hmul, hstart,
                   out_g, out_hm, out_hr):
    """Per box ``b``: floats ``>= |dH/dx_i|`` at the centre (``out_g``) and the balls of the second
    derivatives over the box (``out_hm``, ``out_hr``, one per pair ``i <= j``), as :func:`_bound_kernel`."""
    B, Mall = cm.shape[0], parent.shape[0]
    m = xc.shape[1]
    P = hstart.shape[0] - 1
    pm = np.empty(Mall)
    pr = np.empty(Mall)
    bm = np.empty(Mall)
    br = np.empty(Mall)
    for b in range(B):
        _monomials(b, order, parent, var, xc, xw, pm, pr, bm, br)
        for i in range(m):
            sm, sr = _derivative_ball(b, gstart[i], gstart[i + 1], cm, cr, gsrc, gtgt, gmul, pm, pr)
            out_g[b, i] = np.nextafter(abs(sm) + sr, np.inf)
        for p in range(P):
            sm, sr = _derivative_ball(b, hstart[p], hstart[p + 1], cm, cr, hsrc, htgt, hmul, bm, br)
            out_hm[b, p] = sm
            out_hr[b, p] = sr


try:
    from numba import njit as _njit

    _ball_mul = _njit(cache=True)(_ball_mul)
    _ball_add = _njit(cache=True)(_ball_add)
    _monomials = _njit(cache=True)(_monomials)
    _derivative_ball = _njit(cache=True)(_derivative_ball)
    _bound_kernel = _njit(cache=True)(_bound_kernel)
    _second_kernel = _njit(cache=True)(_second_kernel)
    _COMPILED = True
except ImportError:  # pragma: no cover - the numpy path of _Evaluator
    _COMPILED = False


def _centre_width(lo: np.ndarray, hi: np.ndarray):
    """Float centres and half-widths whose balls contain the boxes ``[lo, hi]``."""
    c = 0.5 * (lo + hi)
    w = np.nextafter(np.maximum(hi - c, c - lo), np.inf)
    return c, np.maximum(w, 0.0)


def _full_v(face: np.ndarray, lo: np.ndarray, hi: np.ndarray, n: int):
    """Float centres and half-widths of the full vectors ``v`` (B, n) of boxes on their faces: the
    free coordinates' balls, the face's fixed coordinate (+-1) inserted, exact."""
    axis = face // 2
    sign = np.where(face % 2 == 0, 1.0, -1.0)
    if n == 1:
        return sign[:, None].copy(), np.zeros((face.size, 1))
    free = np.arange(n)[None, :] != axis[:, None]
    src = np.where(free, np.cumsum(free, axis=1) - 1, 0)
    fc, fw = _centre_width(lo[:, :n - 1], hi[:, :n - 1])
    vc = np.where(free, np.take_along_axis(fc, src, axis=1), sign[:, None])
    vw = np.where(free, np.take_along_axis(fw, src, axis=1), 0.0)
    return vc, vw


def _sigma_range(bp: BandPolynomial, k: np.ndarray, vc: np.ndarray, vw: np.ndarray,
                 rho: Balls, level: Balls, level_set: bool = False):
    """Floats ``lo <= sigma_lo(v)`` and ``hi >= sigma_hi(v)`` over the boxes of ``v`` (full
    vectors (B, n), the fixed coordinate exact), and magnitudes of ``v`` and ``S v``. With
    ``level_set``, ``sigma_hi`` also at most ``sqrt(level / min v^T S v)``: the level set
    ``W = level`` instead of the band ``W >= level``."""
    v = Balls(vc, vw)
    S = bp.S[k]                                                     # (B, n, n)
    Sv = (S * Balls._new(v.mid[:, None, :], v.rad[:, None, :])).sum(axis=-1)
    vSv = (v * Sv).sum(axis=-1)
    mig = np.maximum(np.nextafter(np.abs(vc) - vw, -np.inf), 0.0)   # min |v_i| over the box
    norm2_lo = Balls(mig * mig).sum(axis=-1).lower()
    with np.errstate(divide="ignore", invalid="ignore"):
        hi = (rho / Balls(np.maximum(norm2_lo, 1.0)).sqrt()).upper()  # |v| >= 1 on every face
        top = np.maximum(vSv.upper(), 0.0)
        lo = (level / Balls(top)).sqrt().lower()
        if level_set:
            bottom = vSv.lower()
            cap = (level / Balls(np.where(bottom > 0, bottom, 1.0))).sqrt().upper()
            hi = np.where(bottom > 0, np.minimum(hi, cap), hi)
    lo = np.where(np.isfinite(lo) & (top > 0), np.maximum(lo, 0.0), 0.0)
    return lo, hi, v.magnitude(), Sv.magnitude(), norm2_lo


def largest_bound(bp: BandPolynomial, A_max: float, level: float, *, max_boxes: int = 200_000,
                  patience: int = 50_000, steps=STEPS, batch: int = 8192, initial_split: int = 1,
                  reserve: float = 0.25, sigma_floor: float = 0.0, complete: bool = False,
                  level_set: bool = False) -> BandResult:
    """The largest bound ``A <= A_max`` for which ``W' < 0`` is shown on ``|y| <= A, W(y) >= level``.

    Branch and bound (module docstring), breadth first, ``batch`` boxes at a time (each step costs
    its batch's work: an open box's sigma range is cut to the band when it is made and again only
    after the bound steps down, the same open boxes as cutting every box at every step; measured
    2026-12-06, a search of 1.2 million boxes at mu = 0.1 in 12.5 s instead of 26 s): a box whose
    bound is negative is closed; a box centre in the band where the polynomial part alone is not
    negative caps the bound at that centre's radius (the models cannot show the condition there),
    the bound then the next of ``steps`` times the cap; after ``patience`` boxes at one bound, the
    next step; boxes wholly beyond the bound are dropped, closed boxes stay closed. In the last
    ``reserve`` of ``max_boxes`` the open boxes nearest the origin go first; when ``max_boxes``
    boxes have been bounded, the bound drops below the nearest open box. At the end every point of
    ``|y| <= A, W >= level`` lies in a closed box: ``W' < 0`` there.

    Parameters
    ----------
    bp : BandPolynomial
        ``W'`` from the models over the cube ``|y_i| <= bp.cube``.
    A_max : float
        The largest bound tried (> 0). Above ``bp.cube`` only the cube's part of the band is
        searched, its points with ``|y| <= A_max`` (the whole cube from ``sqrt(n) bp.cube`` on): for a
        search over shells of cubes (``sigma_floor``, ``complete``).
    level : float
        ``c > 0``, the band's level: the result holds for every bound ``A`` with
        ``A^2 min l >= level`` (the certificate's level at ``A`` is at least this one).
    max_boxes : int
        Boxes bounded before the search stops.
    patience : int
        Boxes bounded at one bound before the next step down.
    steps : sequence of float
        The bounds tried, as fractions of the cap (:data:`STEPS`).
    batch : int
        Boxes bounded per step.
    initial_split : int
        Each free coordinate of each face split in ``2**initial_split`` to start.
    reserve : float
        The last fraction of ``max_boxes`` goes to the open boxes nearest the origin (best first,
        no more steps down), so that a search cut short ends with its bound as far out as it can.
    sigma_floor : float
        The search covers only the band's points with ``max_i |y_i| >= sigma_floor bp.cube``, in
        ``[0, 1)`` (default 0, all of it): the shell of the cube outside a smaller cube, which
        another search covers.
    complete : bool
        True: show ``W' < 0`` on all of ``|y| <= A_max`` (within the cube and above the floor) or
        nothing: the search stops with ``A = 0`` where the bound would step down (a box centre
        where the polynomial part is not negative, ``patience``, ``max_boxes``).
    level_set : bool
        Only the points where ``W = level`` (module docstring), with ``complete``: ``W' < 0`` on
        the level set within ``|y| <= A_max``, or nothing.

    Returns
    -------
    BandResult
        ``A`` (0 if nothing is shown).
    """
    n, N = bp.n, bp.S.shape[0]
    if not (0 < A_max <= bp.cube or (sigma_floor > 0 or complete) and 0 < A_max < np.inf):
        raise ValueError(f"A_max must lie in (0, cube = {bp.cube}] (any bound > 0 with sigma_floor or complete), "
                         f"got {A_max!r}")
    if not (0 <= sigma_floor < 1):
        raise ValueError(f"sigma_floor must lie in [0, 1), got {sigma_floor!r}")
    if not (level > 0):
        raise ValueError(f"level must be > 0, got {level!r}")
    if level_set and not complete:
        raise ValueError("level_set needs complete=True (a fixed level: the bound cannot step down)")
    ev = _Evaluator(bp)
    m = n  # n - 1 free coordinates and sigma
    level_t = Balls(float(level)) / (Balls(bp.cube) * Balls(bp.cube))
    # initial boxes (lower and upper ends: a split at a float point covers its box exactly): per
    # interval and face, the free coordinates split into 2**initial_split, sigma in [0, 1]
    parts = 2 ** int(initial_split)
    edges = -1.0 + 2.0 * np.arange(parts + 1) / parts              # exact (parts a power of 2)
    if n > 1:
        cells = np.array(np.meshgrid(*[np.arange(parts)] * (n - 1), indexing="ij")).reshape(n - 1, -1).T
        G = cells.shape[0]
    else:
        G = 1
    k = np.repeat(np.arange(N), 2 * n * G)
    face = np.tile(np.repeat(np.arange(2 * n), G), N)
    lo = np.zeros((k.size, m))
    lo[:, -1] = sigma_floor
    hi = np.ones((k.size, m))
    if n > 1:
        lo[:, :n - 1] = np.tile(edges[cells], (N * 2 * n, 1))
        hi[:, :n - 1] = np.tile(edges[cells + 1], (N * 2 * n, 1))
    # rho: the bound in units of the cube, a float whose band |t| <= rho the search covers
    rho = float(np.nextafter(float((Balls(float(A_max)) / Balls(bp.cube)).lower()), -np.inf))
    if not (sigma_floor > 0 or complete):
        rho = min(rho, 1.0)
    estimate = np.full(N, -np.inf)
    count = 0
    R = bp.R
    res = bp.residual
    stop = "every box closed"
    since = 0
    cap, step = rho, 0
    steps = tuple(steps)
    rho = rho * steps[0]
    # each open box's sigma range cut to the band and its smallest |t| (rmin) at the bound rho_cut;
    # a box is cut again only when it is new (a split) or the bound has stepped down since: the
    # cut is idempotent at one bound, so that the open boxes are the same as when every box was cut
    # at every step, and a step costs the batch's work, not the open boxes'
    rmin = np.zeros(k.size)
    fresh = np.ones(k.size, dtype=bool)
    rho_cut = None
    while k.size:
        if rho != rho_cut:
            fresh[:] = True
            rho_cut = rho
        if np.any(fresh):
            idx = np.flatnonzero(fresh)
            vc, vw = _full_v(face[idx], lo[idx], hi[idx], n)
            s_lo, s_hi, _, _, norm2_lo = _sigma_range(bp, k[idx], vc, vw, Balls(rho), level_t, level_set)
            # sigma cut to the band; boxes without band points dropped
            lo[idx, -1] = np.maximum(lo[idx, -1], s_lo)
            hi[idx, -1] = np.minimum(hi[idx, -1], s_hi)
            # the smallest |t| = sigma |v| of each box (rounded down)
            rmin[idx] = (Balls(lo[idx, -1]) * Balls(norm2_lo).sqrt()).lower()
            drop = idx[~((lo[idx, -1] <= hi[idx, -1]) & (rmin[idx] <= rho))]
            if drop.size:
                keep = np.ones(k.size, dtype=bool)
                keep[drop] = False
                k, face, lo, hi, rmin = k[keep], face[keep], lo[keep], hi[keep], rmin[keep]
            fresh = np.zeros(k.size, dtype=bool)
            if not k.size:
                break
        if count >= max_boxes:
            rho = 0.0 if complete else min(rho, float(np.nextafter(np.min(rmin), -np.inf)))
            where = np.bincount(k, minlength=N)
            top = np.argsort(where)[::-1][:3]
            stop = (f"stopped after {count} boxes ({k.size} open, most in intervals "
                    + ", ".join(f"{int(i)} ({int(where[i])})" for i in top if where[i]) + ")")
            break
        # the next batch: first in first out (breadth first); in the last ``reserve`` of the boxes,
        # the open boxes nearest the origin (they set the bound if the search stops)
        final = count >= (1.0 - reserve) * max_boxes
        if k.size > batch:
            sel = np.argpartition(rmin, batch - 1)[:batch] if final else np.arange(batch)
            rest = np.ones(k.size, dtype=bool)
            rest[sel] = False
            held = (k[rest], face[rest], lo[rest], hi[rest], rmin[rest])
            k, face, lo, hi = k[sel], face[sel], lo[sel], hi[sel]
        else:
            held = None
        # the batch's v and the magnitudes of v and S v (its sigma range is already cut: as cut)
        vc, vw = _full_v(face, lo, hi, n)
        _, _, v_mag, Sv_mag, _ = _sigma_range(bp, k, vc, vw, Balls(rho), level_t)
        xc, xw = _centre_width(lo, hi)
        count += k.size
        coef = Balls._new(bp.coef.mid[k, face], bp.coef.rad[k, face])   # (B, M)
        centre, grad = ev.centre_and_gradient(coef, xc, xw)
        spread = Balls(np.zeros(k.size), np.zeros(k.size))
        for i in range(m):
            spread = spread + Balls(np.zeros(k.size), grad[:, i]) * xw[:, i]
        h_up = (centre + spread).upper()                             # H <= h_up on the box
        # the quadratic part n0 |v|^2 <= n0 min |v|^2 (n0 < 0), else n0 max |v|^2
        n0 = bp.n0[k]
        mig = np.maximum(np.nextafter(np.abs(vc) - vw, -np.inf), 0.0)
        v2 = np.where(n0 < 0, Balls(mig * mig).sum(axis=-1).lower(), Balls(v_mag * v_mag).sum(axis=-1).upper())
        # the remainder's term 2 sum_jk |S v|_j R_jk |v_k| and the residual's 2 e |v| / (A_c sigma_lo)
        quad = Balls(n0) * Balls(v2)
        if level_set and bp.N0 is not None:
            # on the level set: v^T N0 v over the box of v as well (the smaller upper bound)
            v = Balls(vc, vw)
            N0 = Balls._new(bp.N0.mid[k], bp.N0.rad[k])
            vNv = (v * (N0 * Balls._new(v.mid[:, None, :], v.rad[:, None, :])).sum(axis=-1)).sum(axis=-1)
            quad = Balls(np.minimum(quad.upper(), vNv.upper()))
        rterm = (Balls(Sv_mag[:, :, None]) * Balls(R[k]) * Balls(v_mag[:, None, :])).sum(axis=(1, 2)) * 2.0
        eterm = None
        if np.any(res[k] > 0):
            vnorm = Balls(v_mag * v_mag).sum(axis=-1).sqrt()
            with np.errstate(divide="ignore", invalid="ignore"):
                eterm = Balls(res[k]) * vnorm * 2.0 / (Balls(bp.cube) * Balls(lo[:, -1]))
            eterm = np.where(res[k] > 0, eterm.upper(), 0.0)

        def upper_bound(h, rows):
            """The box bound from ``H <= h`` on the boxes ``rows``: G = sigma H <= sigma_hi h
            (h >= 0) or sigma_lo h (h < 0), plus the other terms."""
            g_up = (Balls(np.where(h >= 0, hi[rows, -1], lo[rows, -1])) * Balls(h)).upper()
            b = (Balls(g_up) + Balls._new(quad.mid[rows], quad.rad[rows])
                 + Balls._new(rterm.mid[rows], rterm.rad[rows]))
            if eterm is not None:
                b = b + Balls(eterm[rows])
            return b.upper()

        every = np.arange(k.size)
        bound = upper_bound(h_up, every)
        # the second-order form where the mean-value form leaves the box open (a closed box stays
        # closed: the bound grows with h): H(c) + grad H(c) h + h^T Hess(box) h / 2, each term bounded
        rows = every[~(bound < 0)]
        second = ev.second_order(Balls._new(coef.mid[rows], coef.rad[rows]), xc[rows], xw[rows]) if rows.size else None
        if second is not None:
            g_c, hess = second
            wr = xw[rows]
            lin = Balls(np.zeros(rows.size), np.zeros(rows.size))
            for i in range(m):
                lin = lin + Balls(np.zeros(rows.size), g_c[:, i]) * wr[:, i]
            for p, (i, j) in enumerate(ev.pairs):
                if i == j:
                    top = np.maximum(hess[:, p].upper(), 0.0)
                    lin = lin + Balls(np.zeros(rows.size), top) * wr[:, i] * (wr[:, i] * 0.5)
                else:
                    lin = lin + Balls(np.zeros(rows.size), hess[:, p].magnitude()) * wr[:, i] * wr[:, j]
            h_rows = np.minimum(h_up[rows], (Balls._new(centre.mid[rows], centre.rad[rows]) + lin).upper())
            bound[rows] = upper_bound(h_rows, rows)
        # the polynomial part at the centres, W' / |y|^2 (an estimate, not a bound)
        vc2 = np.sum(vc ** 2, axis=1)
        point = (xc[:, -1] * centre.mid + n0 * vc2) / vc2
        r_c = xc[:, -1] * np.sqrt(vc2)
        in_band = (r_c <= rho) & (xc[:, -1] ** 2 * np.einsum("bi,bij,bj->b", vc, bp.S.mid[k], vc) >= float(level_t.mid))
        if np.any(in_band):
            np.maximum.at(estimate, k[in_band], point[in_band])
        # (on the level set alone a centre of the band may have W' >= 0 and the proof still hold)
        bad = in_band & (point >= 0) & (not level_set)
        if complete and (np.any(bad) or count - since > patience):
            rho, stop = 0.0, ("the polynomial part is not negative at a box centre in the band" if np.any(bad)
                              else f"not closed after {count} boxes")
            break
        if np.any(bad) or (count - since > patience and not final):
            # the models cannot show W' < 0 at a centre in the band (the cap drops to it), or the
            # step ran out of patience (the next step): every closed box stays closed
            if np.any(bad):
                cap = min(cap, float(np.min(r_c[bad])))
            else:
                step += 1
            rho = min(rho, float(np.nextafter(cap * (steps[step] if step < len(steps) else 0.0) * (1 - 1e-12),
                                              -np.inf)))
            since = count
            if rho <= 0:
                break
        # each coordinate's share of the bound's excess over the box (the split direction): sigma H's
        # mean-value term sigma_hi |dH/dx_i| w_i; for the free coordinates of v also the first-order
        # change of the remainder's term and of the quadratic part across the box (floats: a choice
        # of direction, nothing rests on it); for sigma also |H(centre)| w (the product sigma H)
        share = grad * xw
        if n > 1 and SPLIT_BY_SHARE:
            share = share * hi[:, -1:]
            Rk = R[k]
            sens = 2.0 * (np.einsum("bjl,bj->bl", np.abs(bp.S.mid[k]), np.einsum("bjl,bl->bj", Rk, v_mag))
                          + np.einsum("bjl,bj->bl", Rk, Sv_mag)) + 2.0 * np.abs(n0)[:, None] * v_mag
            full = np.arange(n - 1)[None, :] + (np.arange(n - 1)[None, :] >= (face // 2)[:, None])
            share[:, :n - 1] += np.take_along_axis(sens, full, axis=1) * xw[:, :n - 1]
            share[:, -1] += np.abs(centre.mid) * xw[:, -1]
        open_ = ~(bound < 0)
        tiny = open_ & (np.max(xw, axis=1) < 1e-9)
        if np.any(tiny) and complete:
            rho, stop = 0.0, "boxes too small to split"
            break
        if np.any(tiny):  # boxes too small to split: the bound stays below them
            rmin_b = (Balls(lo[tiny, -1]) * Balls(np.sum(mig[tiny] ** 2, axis=1)).sqrt()).lower()
            rho = min(rho, float(np.nextafter(np.min(rmin_b), -np.inf)))
            open_ &= ~tiny
        k, face, lo, hi, share = k[open_], face[open_], lo[open_], hi[open_], share[open_]
        # split each open box at the middle of the coordinate with the largest share; on the level
        # set a coordinate of v (the box's sigma range, cut to the level set, shrinks with it;
        # cutting sigma alone would leave points off the level set in every part)
        if level_set and n > 1:
            share = share.copy()
            share[:, -1] = -np.inf
        if k.size:
            dim = np.argmax(share, axis=1)
            rows = np.arange(k.size)
            cut = 0.5 * (lo[rows, dim] + hi[rows, dim])
            lo2, hi1 = lo.copy(), hi.copy()
            hi1[rows, dim] = cut
            lo2[rows, dim] = cut
            k = np.concatenate([k, k])
            face = np.concatenate([face, face])
            lo = np.vstack([lo, lo2])
            hi = np.vstack([hi1, hi])
        if held is not None:
            k = np.concatenate([held[0], k])
            face = np.concatenate([held[1], face])
            lo = np.vstack([held[2], lo])
            hi = np.vstack([held[3], hi])
            rmin = np.concatenate([held[4], np.zeros(k.size - held[4].size)])
            fresh = np.arange(k.size) >= held[4].size
        else:
            rmin = np.zeros(k.size)
            fresh = np.ones(k.size, dtype=bool)
    # A: the bound rho in state units of the scaled norm, rounded down
    rho = max(rho, 0.0)
    A = float((Balls(rho) * Balls(bp.cube)).lower()) if rho > 0 else 0.0
    A = max(A, 0.0)
    return BandResult(A=A, boxes=count, estimate=estimate,
                      message=f"W' < 0 shown on |y| <= {A:.4g}, W >= {level:.4g} ({stop}; {count} boxes)")


def hopeless(bp: BandPolynomial, samples: int = 2000, seed: int = 0) -> bool:
    """True where the models cannot show any bound: at a sampled direction ``v`` on a face, the
    remainder's term ``2 sum_jk |S v|_j R_jk |v_k|`` (at the midpoint of ``S``) reaches
    ``-n0 |v|^2``, so the bound of :func:`largest_bound` is not negative however near the origin
    (the remainder does not shrink with the radius). A float screen to skip a hopeless search: it
    decides nothing about the proof."""
    n = bp.n
    rng = np.random.default_rng(seed)
    u = rng.normal(size=(samples, n))
    v = u / np.max(np.abs(u), axis=1, keepdims=True)
    Sv = np.abs(np.einsum("kij,sj->ksi", bp.S.mid, v))                # (N, samples, n)
    rterm = 2.0 * np.einsum("ksj,kjl,sl->ks", Sv, bp.R, np.abs(v))
    return bool(np.any(rterm + bp.n0[:, None] * np.sum(v * v, axis=1)[None, :] >= 0))
