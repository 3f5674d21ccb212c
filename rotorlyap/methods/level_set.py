"""A proof that a sublevel set of a Liapunov function is invariant: branch and bound over boxes.

For any continuously differentiable ``W`` of the scaled state ``y`` (not only a quadratic form:
the augmented energy of :mod:`rotorlyap.analysis.nonlinear_functions`), a level ``c`` and a cube
``K = [-R, R]^n``, suppose

(a) ``W > c`` on the boundary of ``K``, and
(b) ``W' < 0`` at every point of ``K`` where ``W = c``.

Then a motion that starts in ``K`` with ``W <= c`` keeps ``W <= c`` and never leaves ``K``: while
it is in ``K``, ``W`` cannot rise through ``c`` (where ``W = c``, ``W`` decreases), and it cannot
reach the boundary of ``K`` without doing so, by (a). If every point of ``K`` with ``W >= c`` lies
at least ``lambda`` from the origin and every point with ``W <= c`` at most ``A``, every motion that
starts within ``lambda`` stays within ``A``: technical stability of the paper's kind with the
start radius ``lambda`` and the bound ``A``, shown on the one level set ``W = c``. Nothing of ``W``
near the origin enters (a function designed for the nonlinear range may have a thin linear part
there), and no positivity of ``W`` is needed.

:func:`prove_level` covers ``K`` with boxes (the cube cut into ``SPLIT_START^n`` boxes). Each box
gets Taylor models of ``W`` (and of ``W'``, once it is no wider than ``rate_width``) from the
caller (:class:`rotorlyap.methods.taylor.TaylorModel`: polynomials with rigorous remainders).
A model's range over its box takes every monomial at its extreme separately, which for the
large boxes this needs is far too wide; over small sub-boxes of the same model
(:func:`rotorlyap.methods.taylor.split`, the polynomial re-expanded exactly on each half, its
remainder kept) it is tight. So each box is decided on sub-boxes: ``2^n`` halves, and the open ones cut again, up to
``SUB_DEPTH`` levels. A sub-box is closed

* where ``W > c`` on all of it (outside the level set), or ``W < c`` (inside);
* where, for one of the multipliers ``kappa >= 0`` of :data:`KAPPAS`, ``W' + kappa W < kappa c``
  on all of it: then where ``W = c`` in it, ``W' < 0``. The multiplier lets a box that reaches
  into ``W < c``, where ``W'`` of a function negative only away from the origin may be small, be
  closed by the margin ``W' + kappa W`` has on the level set (an S-procedure with a fixed
  multiplier).

A box is closed when all its sub-boxes are; one wider than ``rate_width``, or one meeting the
boundary of ``K``, hands its open halves on as new boxes (decided on ``W``'s models alone: a
box on the boundary must lie outside the level set); one whose sub-boxes do not all close is
taken again over its halves that hold an open sub-box, with new models (half the width, a
remainder some ``2^(order + 1)`` times smaller); a box that does not close at :data:`MIN_WIDTH`
of the cube ends the search (no proof at this level). The boxes are dyadic centres and half-widths (``R`` rounded up to a multiple of
``2^-6``): every split covers its box exactly; the caller widens each box it models by the
rounding of its change of variables.

``A`` is the largest distance from the origin of the closed sub-boxes where ``W <= c`` may hold;
``lambda`` is shown on its own (:func:`start_radius`): the largest ball on which the model of
``W`` over the ball's cube, its quadratic part bounded by its largest eigenvalue (rigorous
bounds) and the rest by its range, stays below ``c``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from .balls import U
from .taylor import TaylorModel, _up, split

__all__ = ["KAPPAS", "MIN_WIDTH", "SPLIT_START", "SUB_DEPTH", "LevelProof", "ball_maximum", "prove_level", "start_radius"]

KAPPAS: tuple[float, ...] = (0.0, 0.01, 0.02, 0.04, 0.08, 0.16)
"""The multipliers ``kappa`` tried on each box (per rad of azimuth, like ``W'/W``): 0 asks
``W' < 0`` on the whole box; the others ``W' + kappa W < kappa c``."""

MIN_WIDTH = 1.0 / 512.0
"""The smallest half-width of a box that :func:`prove_level` splits further, as a share of the
cube's half-width."""

SPLIT_START = 4
"""Boxes per side of the first cover of the cube."""

SUB_DEPTH = 2
"""Levels of sub-boxes (each a cut into ``2^n``) on which a box's models are bounded."""


ModelFunction = Callable[[np.ndarray, np.ndarray, bool], tuple[TaylorModel, TaylorModel | None]]


@dataclass(frozen=True)
class LevelProof:
    """The result of :func:`prove_level`.

    Attributes
    ----------
    proved : bool
        Conditions (a) and (b) of the module docstring shown on every box.
    level : float
        ``c``.
    cube : float
        ``R``, the half-width of the cube ``K`` (scaled norm).
    start_radius : float
        ``lambda``: the ball of this radius (scaled norm) lies in ``{W < c}`` (0 where not proved).
    bound : float
        ``A``: ``{y in K: W(y) <= c}`` lies in the ball of this radius (inf where not proved).
    boxes : int
        Boxes evaluated.
    rate_boxes : int
        Boxes on which ``W'`` was evaluated (those that may meet the level set).
    smallest : float
        The finest resolution the proof needed: over the boxes, the least of the largest
        half-width of the sub-boxes that closed each.
    reason : str
        Why the proof failed ("" where it holds).
    """

    proved: bool
    level: float
    cube: float
    start_radius: float
    bound: float
    boxes: int
    rate_boxes: int
    smallest: float
    reason: str = ""

    def __repr__(self) -> str:  # short and stable
        if not self.proved:
            return f"LevelProof(not proved at c = {self.level:.4g}: {self.reason})"
        return (f"LevelProof(c = {self.level:.4g}, start radius {self.start_radius:.4g}, bound {self.bound:.4g}, "
                f"{self.boxes} boxes)")


def _norms(C: np.ndarray, H: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Lower and upper bounds of the Euclidean norm over boxes (rounded outwards)."""
    near = np.maximum(np.abs(C) - H, 0.0)
    far = np.abs(C) + H
    lo = np.sqrt(np.sum(near * near, axis=-1)) * (1.0 - 1e-14)
    hi = np.sqrt(np.sum(far * far, axis=-1)) * (1.0 + 1e-14)
    return lo, hi


def _extent(box, C, H, sc, sr, within, A):
    """Update the greatest distance ``A`` from the origin, per box, of its sub-boxes ``sc +- sr``
    where ``W <= c`` may hold (``within``)."""
    if box.size == 0:
        return
    hi = _norms(C[box] + H[box] * sc, H[box] * sr)[1]         # exact: dyadic
    np.maximum.at(A, box[within], hi[within])


def _range(model: TaylorModel) -> tuple[np.ndarray, np.ndarray]:
    """The bounds of :meth:`TaylorModel.bounds` (each odd monomial in ``[-1, 1]``, each even one in
    ``[0, 1]``) from three matrix-vector products over one array of magnitudes: the sums of the
    positive and negative parts of the even monomials' coefficients as ``(sum |a| +- sum a) / 2``,
    with the rounding of every sum and of that cancellation added (``4 (M + 2) u`` times the sums
    of magnitudes) before rounding up as the model does. The many sub-box models' bounds are most
    of the work."""
    sp = model.space
    c = model.coef
    mag = np.abs(c)
    odd = mag @ sp.odd.astype(float)
    even_mag = mag @ sp.even.astype(float)
    even = c @ sp.even.astype(float)
    slack = 4.0 * (sp.size + 2) * U * (odd + even_mag)
    pos = _up(odd + 0.5 * (even_mag + even) + slack)
    neg = _up(odd + 0.5 * (even_mag - even) + slack)
    c0 = c[..., 0]
    with np.errstate(invalid="ignore", over="ignore"):
        lo = np.nextafter(np.nextafter(c0 - neg, -np.inf) - model.rem, -np.inf)
        hi = np.nextafter(np.nextafter(c0 + pos, np.inf) + model.rem, np.inf)
    ok = np.isfinite(lo) & np.isfinite(hi)
    return np.where(ok, lo, -np.inf), np.where(ok, hi, np.inf)


def _sub_boxes(W: TaylorModel, dW: TaylorModel, C: np.ndarray, H: np.ndarray, level: float, kap: np.ndarray,
               kc: np.ndarray, depth: int):
    """Decide each box by its models on sub-boxes (:func:`rotorlyap.methods.taylor.split`: the
    models over the ``2^n`` halves, and over the halves of each open half, ``depth`` levels at
    most). A sub-box is closed when ``W > c`` on it, ``W < c`` on it, or ``W' + kappa W < kappa c``
    for one ``kappa``. Returns, per box: closed, the least distance from the origin of its closed
    sub-boxes where ``W >= c`` may hold, the greatest of those where ``W <= c`` may, and the largest
    half-width of its closed sub-boxes (scaled norm)."""
    m, n = C.shape
    closed = np.ones(m, dtype=bool)
    A = np.zeros(m)
    width = np.zeros(m)
    box = np.arange(m)
    sc = np.zeros((m, n))
    sr = np.ones((m, n))
    Wr, Dr = W, dW
    first = None                                 # each row's half of depth 1 (centre, in t)
    reopen = (np.zeros(0, dtype=int), np.zeros((0, n)))
    for d in range(1, depth + 1):
        both, corners = split(tm_stack_rows(Wr, Dr))
        k = corners.shape[0]
        rows = box.size
        Wr = both[:rows].reshape(rows * k)
        Dr = both[rows:].reshape(rows * k)
        sc = np.repeat(sc, k, axis=0) + np.tile(corners, (rows, 1)) * np.repeat(sr, k, axis=0)   # exact
        sr = np.repeat(sr * 0.5, k, axis=0)
        box = np.repeat(box, k)
        first = sc.copy() if first is None else np.repeat(first, k, axis=0)
        wlo, whi = _range(Wr)
        outside = wlo > level
        inside = whi < level
        ok = outside | inside
        for kk, kck in zip(kap, kc):
            todo = np.flatnonzero(~ok)
            if todo.size == 0:
                break
            g = Dr[todo] if kk == 0.0 else Dr[todo] + Wr[todo] * float(kk)
            ok[todo] |= _range(g)[1] < kck
        yh = H[box] * sr
        np.maximum.at(width, box[ok], yh[ok].max(axis=-1))
        _extent(box[ok], C, H, sc[ok], sr[ok], ~outside[ok], A)
        open_ = ~ok
        if not open_.any():
            break
        if d == depth:
            closed[box[open_]] = False
            pairs = np.unique(np.concatenate([box[open_, None].astype(float), first[open_]], axis=1), axis=0)
            reopen = (pairs[:, 0].astype(int), pairs[:, 1:])
            break
        Wr, Dr = Wr[open_], Dr[open_]
        box, sc, sr, first = box[open_], sc[open_], sr[open_], first[open_]
    return closed, A, width, reopen


def tm_stack_rows(a: TaylorModel, b: TaylorModel) -> TaylorModel:
    """Two models of shape ``(m,)`` as one of shape ``(2 m,)``."""
    return TaylorModel._new(np.concatenate([a.coef, b.coef]), np.concatenate([np.broadcast_to(a.rem, a.shape),
                                                                               np.broadcast_to(b.rem, b.shape)]),
                            a.space)


def prove_level(models: ModelFunction, level: float, cube: float, n: int, *, kappas=KAPPAS,
                min_width: float | None = None, max_boxes: int = 2_000_000, batch: int = 384,
                rate_width: float = np.inf, depth: int = SUB_DEPTH) -> LevelProof:
    """Show that ``{W <= level}`` in the cube ``[-cube, cube]^n`` is invariant (module docstring).

    Parameters
    ----------
    models : callable
        ``models(centre, half_width, rates)`` with arrays of shape ``(m, n)`` (scaled state, the
        boxes ``|y - centre| <= half_width``) returns Taylor models of ``W`` and (``rates`` true)
        of ``W'`` over each box, shape ``(m,)`` (``W'`` None when not asked). Non-finite models
        count as not decided.
    level : float
        ``c``.
    cube : float
        ``R > 0``, rounded up to a multiple of ``2^-6``.
    n : int
        Dimension of the state.
    kappas : sequence of float
        Multipliers ``>= 0`` tried on each box.
    min_width : float, optional
        Half-width below which a box that is not closed ends the search (default
        :data:`MIN_WIDTH` times the cube's half-width).
    max_boxes : int
        Boxes evaluated at most.
    batch : int
        Boxes per call of ``models``.
    rate_width : float
        Boxes wider than this (largest half-width) are split without evaluating ``W'`` (it would
        not close them), unless ``W`` alone closes them.
    depth : int
        Levels of sub-boxes on which each box's models are bounded (:func:`_sub_boxes`).
    Returns
    -------
    LevelProof

    Raises
    ------
    ValueError
        A level or cube that is not finite and positive, a negative multiplier.
    """
    level = float(level)
    if not (np.isfinite(level) and np.isfinite(cube) and cube > 0):
        raise ValueError(f"level and cube must be finite, cube > 0; got {level!r}, {cube!r}")
    kap = np.asarray(kappas, dtype=float)
    if kap.ndim != 1 or kap.size == 0 or np.any(~np.isfinite(kap) | (kap < 0)):
        raise ValueError(f"kappas must be finite numbers >= 0, got {kappas!r}")
    R = float(np.ceil(float(cube) * 64.0) / 64.0)
    min_width = MIN_WIDTH * R if min_width is None else float(min_width)
    k = int(SPLIT_START)
    g = (np.arange(k) + 0.5) * (2.0 * R / k) - R                 # dyadic: exact
    C = np.stack(np.meshgrid(*[g] * n, indexing="ij"), -1).reshape(-1, n)
    todo = [(C, np.full_like(C, R / k))]
    A = 0.0
    boxes = rate_boxes = 0
    smallest = np.inf
    # the multipliers' kappa c rounded down (the test is sup(W' + kappa W) < kappa c)
    kc = np.nextafter(kap * level, -np.inf)
    kc = np.where(kap == 0.0, 0.0, kc)

    def fail(reason: str) -> LevelProof:
        return LevelProof(False, level, R, 0.0, np.inf, boxes, rate_boxes, smallest, reason)

    while todo:
        C, H = todo.pop()
        if len(C) > batch:
            todo.append((C[batch:], H[batch:]))
            C, H = C[:batch], H[:batch]
        boxes += len(C)
        if boxes > max_boxes:
            return fail(f"more than {max_boxes} boxes")
        edge = np.any(np.abs(C) + H >= R, axis=-1)
        rated = ~edge & (H.max(axis=-1) <= rate_width)
        closed = np.zeros(len(C), dtype=bool)
        children = []
        if (~rated).any():        # W alone; its models cut into 2^n children decide them or pass them on
            idx = np.flatnonzero(~rated)
            W, _ = models(C[idx], H[idx], False)
            halves, corners = split(W)
            box = np.repeat(np.arange(idx.size), corners.shape[0])
            sc = np.tile(corners, (idx.size, 1))
            sr = np.full_like(sc, 0.5)
            wlo, whi = _range(halves.reshape(-1))
            cc = C[idx][box] + H[idx][box] * sc
            ch = H[idx][box] * sr
            outside = wlo > level
            inside = (whi < level) & ~np.any(np.abs(cc) + ch >= R, axis=-1)
            A = max(A, float(np.max(_norms(cc, ch)[1][inside], initial=0.0)))
            open_ = ~(outside | inside)
            if np.any(ch[open_].max(axis=-1, initial=np.inf) < min_width):
                return fail(f"a box of half-width {ch[open_].max():.3g} meets the cube's boundary with W <= c")
            children.append((cc[open_], ch[open_]))
            closed[idx] = True                   # handed on to its children
        if rated.any():                          # W and W', on sub-boxes of the models
            idx = np.flatnonzero(rated)
            rate_boxes += idx.size
            W, dW = models(C[idx], H[idx], True)
            ok, A_b, h_b, (which, centre) = _sub_boxes(W, dW, C[idx], H[idx], level, kap, kc, depth)
            closed[idx] = True                   # closed, or handed on to its open halves
            if which.size:
                b = idx[which]
                hh = H[b] * 0.5
                if np.any(hh.max(axis=-1) < min_width):
                    return fail(f"a box of half-width {hh.max():.3g} at |y| = {np.linalg.norm(C[b[0]]):.3g}: "
                                "W' + kappa W not below kappa c")
                children.append((C[b] + H[b] * centre, hh))
            # every closed sub-box counts, also those of a box handed on: its halves that closed are not
            # taken again
            A = max(A, float(np.max(A_b, initial=0.0)))
            if ok.any():
                smallest = min(smallest, float(np.min(h_b[ok])))
        for cc, ch in children:
            if len(cc):
                todo.append((cc, ch))
    lam = start_radius(models, level, n, R)
    if not lam > 0:
        return fail("W >= c at the origin's box: no start radius")
    return LevelProof(True, level, R, float(lam), float(A), boxes, rate_boxes, float(smallest))


def ball_maximum(models: ModelFunction, n: int, r: float) -> float:
    """An upper bound of ``W`` on the ball ``|y| <= r`` (inf where none follows): with the model of
    ``W`` over the cube ``|y_i| <= r`` in ``t = y / r``, ``W`` is its quadratic part ``t^T Q t``
    plus the rest (the other monomials, bounded over the cube, and the remainder), and on the
    ball ``|t| <= 1`` the quadratic part is at most ``max(lambda_max(Q), 0)``
    (:func:`rotorlyap.methods.intervals.symmetric_eigenvalue_bounds`, rigorous)."""
    from . import intervals as iv

    W, _ = models(np.zeros((1, n)), np.full((1, n), float(r)), False)
    sp = W.space
    E = sp.exponents
    quad = sp.degree == 2
    Q = np.zeros((n, n))
    for k in np.flatnonzero(quad):
        idx = np.flatnonzero(E[k])
        if idx.size == 1:
            Q[idx[0], idx[0]] = W.coef[0, k]
        else:
            Q[idx[0], idx[1]] = Q[idx[1], idx[0]] = 0.5 * W.coef[0, k]          # exact
    rest = TaylorModel._new(np.where(quad, 0.0, W.coef), W.rem, sp)
    with iv.arithmetic("balls"):
        hi_q = iv.symmetric_eigenvalue_bounds(iv.balls(Q[None]))[1][0]
    top = rest.bounds()[1][0]
    out = np.nextafter(max(hi_q, 0.0) + top, np.inf)
    return float(out) if np.isfinite(out) else np.inf


def start_radius(models: ModelFunction, level: float, n: int, r_max: float, *, steps: int = 30) -> float:
    """The largest radius (bisected, ``steps`` halvings, at most ``r_max``) whose ball is shown inside
    ``{W < c}`` by :func:`ball_maximum`; 0 where none is."""
    lo, hi = 0.0, float(r_max)
    if ball_maximum(models, n, hi) < level:
        return hi
    for _ in range(steps):
        mid = 0.5 * (lo + hi)
        if ball_maximum(models, n, mid) < level:
            lo = mid
        else:
            hi = mid
    return lo
