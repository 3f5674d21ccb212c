"""Taylor models: multivariate polynomials with a rigorous remainder, vectorised over many boxes.

A Taylor model of order ``k`` in ``n`` variables (Berz & Makino; M. Berz and K. Makino,
"Verified integration of ODEs and flows using differential algebraic methods on high-order
Taylor models", Reliable Computing 4, 361-369 (1998); A. Neumaier, "Taylor forms - use and
limits", Reliable Computing 9, 43-79 (2003)) is a pair ``(p, r)``: a polynomial ``p`` of total
degree at most ``k`` in the box variables ``t in [-1, 1]^n`` with float coefficients, and a
radius ``r >= 0``. It *encloses* a function ``f`` on the box if ``|f(t) - p(t)| <= r`` for every
``t`` of the box. The variables are normalised: a quantity ``x_i`` that ranges over
``[c_i - w_i, c_i + w_i]`` is the exact model ``c_i + w_i t_i``.

Arithmetic keeps the dependence on the variables in the coefficients, so that terms that cancel
in the exact function cancel in the polynomial (to round-off) instead of adding their widths, as
ball arithmetic does (the dependency problem). Where interval arithmetic over-estimates by a
factor that does not shrink with the box, a Taylor model of order ``k`` over-estimates by a
remainder of order ``w^(k+1)`` (Neumaier 2003, section 3).

What is rigorous here
---------------------
Coefficients are floats computed with numpy in round to nearest; every rounding error, every
truncated product term of degree above ``k`` and every Lagrange remainder of an elementary
function is bounded and added to ``r`` (each monomial is at most 1 in magnitude on the box, so a
coefficient error ``e`` changes the function by at most ``|e|``). The bounds use the facts of
:mod:`rotorlyap.methods.balls` (IEEE binary64, ``u = 2**-53``): a float sum or product is within
``u |result|`` (plus ``eta = 2**-1074`` for products) of the exact one, a sum of ``m`` products
within ``gamma_m`` times the sum of their magnitudes (Higham, *Accuracy and stability of
numerical algorithms*, (3.4)-(3.5)). Every remainder formula below is a sum of non-negative
float terms computed with at most a few thousand roundings; :func:`_up` multiplies it by
``1 + 1e-10`` and adds ``2**-1000``, which covers the relative error ``gamma_(10^5) < 1.2e-11`` of
up to ``10^5`` such roundings and every underflow. Constants of the elementary functions
(``sin(c)``, ``1 / c``, ``atan(c)``, ...) are float balls (:class:`rotorlyap.methods.balls.Balls`),
whose radii are swept into the remainder.

What cannot be enclosed (a reciprocal of a model whose range may contain 0, a square root of one
that may reach below 0, an overflow) gives a non-finite remainder; :meth:`TaylorModel.bounds`
then gives ``-inf``/``inf``: a proof that meets one fails, it never passes.

Layout
------
:class:`TaylorModel` holds ``coef``, shape ``batch + (M,)`` (``M`` monomials of the
:class:`TaylorSpace`, graded: the constant, the ``n`` linear monomials in variable order, then
degree 2, ...), and ``rem``, shape ``batch``: an array of models over one box each, combined
elementwise with numpy broadcasting. A product is one pass over the table of coefficient pairs
whose degrees sum to at most ``k`` (a numba generalised ufunc, or a numpy gather and
``numpy.add.reduceat`` without numba): 455 pairs for 6 variables at order 3. :class:`TaylorMath` stands for ``math`` in generated scalar code run on
models, or on :class:`rotorlyap.methods.intervals.Jet` objects whose values and gradients are
models (forward differentiation: each Jacobian entry is a Taylor model of its own).
"""

from __future__ import annotations

import functools
import itertools
import math
from typing import Sequence

import numpy as np
from flint import arb

from . import balls as fb
from .balls import U, Balls
from .intervals import Jet, chain

__all__ = ["TaylorMath", "TaylorModel", "TaylorSpace", "atan", "cos", "sin", "space", "split", "sqrt", "stack",
           "variables", "where"]

MAX_ORDER = 8
"""The largest order accepted (the product tables grow as ``C(n + k, k)^2``)."""

_REL = 1e-10              # covers gamma_(10^5) < 1.2e-11: any float sum/product chain used below
_PAD = 2.0 ** -1000       # covers every eta (underflow) of up to 2**70 products
_GAMMA_SLACK = 1.0 + 2.0 ** -20


def _up(s):
    """An upper bound of the exact value of a non-negative float expression ``s`` computed with at
    most ``10^5`` roundings (module docstring); ``inf`` and ``nan`` propagate."""
    return s * (1.0 + _REL) + _PAD


def _product_numpy(a, b, sp):
    """The kept coefficients of the product: each target's products summed in sequence."""
    return np.add.reduceat(a[..., sp.pair_i] * b[..., sp.pair_j], sp.pair_starts, axis=-1)


# The product as a compiled generalised ufunc (numba, when installed): per box, the products of
# the coefficient pairs accumulated into their targets in sequence, as the numpy path does (any
# order of the sum is covered by the bound gamma_m; without fast-math numba keeps IEEE round to
# nearest, and a fused multiply-add, if LLVM formed one, rounds once instead of twice).
try:
    from numba import guvectorize as _guvectorize

    @_guvectorize(["void(float64[:], float64[:], int64[:], int64[:], int64[:], float64[:])"],
                  "(m),(m),(p),(p),(p)->(m)", cache=True)
    def _product_kernel(a, b, pi, pj, pt, out):  # pragma: no cover - compiled
        for t in range(out.shape[0]):
            out[t] = 0.0
        for q in range(pi.shape[0]):
            out[pt[q]] += a[pi[q]] * b[pj[q]]

    from numba import njit as _njit

    @_njit(cache=True)
    def _product_columns(at, bt, pi, pj, pt, out):  # pragma: no cover - compiled
        # the same sums as _product_kernel, in the same order per coefficient, with the boxes
        # innermost (contiguous: the loop vectorises; measured 4 times faster for 384 boxes)
        n = at.shape[1]
        for q in range(pi.shape[0]):
            t, i, j = pt[q], pi[q], pj[q]
            for k in range(n):
                out[t, k] += at[i, k] * bt[j, k]

    _CHUNK = 512  # boxes per pass: the three (M, chunk) arrays stay in cache

    def _product(a, b, sp):
        shape = np.broadcast_shapes(a.shape, b.shape)
        a2 = np.broadcast_to(a, shape).reshape(-1, sp.size)
        b2 = np.broadcast_to(b, shape).reshape(-1, sp.size)
        n = a2.shape[0]
        if n < 16:
            return _product_kernel(a, b, sp.pair_i, sp.pair_j, sp.pair_target)
        out = np.empty((n, sp.size))
        for lo in range(0, n, _CHUNK):
            at = np.ascontiguousarray(a2[lo:lo + _CHUNK].T)
            bt = np.ascontiguousarray(b2[lo:lo + _CHUNK].T)
            ot = np.zeros_like(at)
            _product_columns(at, bt, sp.pair_i, sp.pair_j, sp.pair_target, ot)
            out[lo:lo + _CHUNK] = ot.T
        return out.reshape(shape)
except ImportError:  # pragma: no cover - the numpy path
    _product = _product_numpy


# --------------------------------------------------------------------------------------
# The space: monomials and product tables
# --------------------------------------------------------------------------------------


class TaylorSpace:
    """The monomials of total degree ``<= order`` in ``n`` variables and their product tables.

    Get one with :func:`space` (cached). Attributes are read-only numpy arrays.

    Attributes
    ----------
    n, order : int
    exponents : numpy.ndarray of int, shape (M, n)
        Graded order: degree 0, then degree 1 (``t_0, ..., t_{n-1}``), then degree 2, ...
    degree : numpy.ndarray of int, shape (M,)
    even : numpy.ndarray of bool, shape (M,)
        Monomials of degree >= 1 with every exponent even (their values lie in [0, 1]).
    """

    def __init__(self, n: int, order: int):
        self.n, self.order = int(n), int(order)
        exps = []
        for d in range(order + 1):
            for combo in itertools.combinations_with_replacement(range(n), d):
                exps.append(np.bincount(np.asarray(combo, dtype=int), minlength=n))
        self.exponents = np.asarray(exps, dtype=int).reshape(-1, n)
        self.size = self.exponents.shape[0]
        self.degree = self.exponents.sum(axis=1)
        self.even = (self.degree > 0) & np.all(self.exponents % 2 == 0, axis=1)
        self.odd = (self.degree > 0) & ~self.even
        self.degree_starts = np.searchsorted(self.degree, np.arange(order + 1))
        index = {tuple(e): i for i, e in enumerate(self.exponents)}
        pi, pj, pt = [], [], []
        for i in range(self.size):
            for j in range(self.size):
                if self.degree[i] + self.degree[j] <= order:
                    pi.append(i)
                    pj.append(j)
                    pt.append(index[tuple(self.exponents[i] + self.exponents[j])])
        perm = np.argsort(np.asarray(pt), kind="stable")
        self.pair_i = np.asarray(pi)[perm]
        self.pair_j = np.asarray(pj)[perm]
        target = np.asarray(pt)[perm]
        self.pair_target = target.astype(np.int64)
        self.pair_i = self.pair_i.astype(np.int64)
        self.pair_j = self.pair_j.astype(np.int64)
        self.pair_starts = np.searchsorted(target, np.arange(self.size))
        counts = np.bincount(target, minlength=self.size)
        # gamma_m >= the error of a dot product of m terms (Higham (3.4)), per coefficient
        self.gamma = float(counts.max()) * U * _GAMMA_SLACK
        deg = np.arange(order + 1)
        self.kept = (deg[:, None] + deg[None, :] <= order).astype(float)   # (k+1, k+1) masks
        self.dropped = 1.0 - self.kept
        for a in (self.exponents, self.degree, self.even, self.odd, self.pair_i, self.pair_j, self.pair_starts,
                  self.pair_target):
            a.setflags(write=False)

    def __repr__(self) -> str:
        return f"TaylorSpace(n={self.n}, order={self.order}, monomials={self.size})"


@functools.lru_cache(maxsize=None)
def space(n: int, order: int) -> TaylorSpace:
    """The :class:`TaylorSpace` of ``n >= 1`` variables and order ``1 <= order <= MAX_ORDER``.

    Raises
    ------
    ValueError
        ``order`` or ``n`` out of range.
    """
    if not isinstance(order, (int, np.integer)) or not 1 <= order <= MAX_ORDER:
        raise ValueError(f"the order of a Taylor model must be an integer in 1..{MAX_ORDER}, got {order!r}")
    if not isinstance(n, (int, np.integer)) or n < 1:
        raise ValueError(f"a Taylor model needs at least one variable, got n={n!r}")
    return TaylorSpace(int(n), int(order))


# --------------------------------------------------------------------------------------
# Taylor models
# --------------------------------------------------------------------------------------


class TaylorModel:
    """Arrays of Taylor models over the box ``[-1, 1]^n`` (module docstring).

    Parameters
    ----------
    coef : array_like, shape ``batch + (M,)``
        Float coefficients in the order of ``space.exponents``.
    rem : array_like, shape broadcastable to ``batch``
        Remainder radii ``>= 0``.
    space : TaylorSpace

    Notes
    -----
    Arithmetic with other models of the same space, floats, float arrays (exact, broadcast against
    the batch) and :class:`~rotorlyap.methods.balls.Balls` (broadcast against the batch) is
    rigorous; models of different spaces raise ``ValueError``. Instances are not modified in place
    (each caches its polynomial bound and degree sums).
    """

    __slots__ = ("coef", "rem", "space", "_mag", "_dsums")   # _mag, _dsums: cached, models are not mutated
    __array_ufunc__ = None
    __array_priority__ = 2000   # above Balls: Balls op model defers to the model

    def __init__(self, coef, rem, space: TaylorSpace):
        c = np.asarray(coef, dtype=float)
        if c.ndim < 1 or c.shape[-1] != space.size:
            raise ValueError(f"coefficients must have shape batch + ({space.size},), got {c.shape}")
        r = np.broadcast_to(np.asarray(rem, dtype=float), c.shape[:-1])
        if np.any(r < 0):
            raise ValueError("remainder radii must be >= 0 (or nan: no enclosure)")
        self.coef = c
        self.rem = r
        self.space = space
        self._mag = self._dsums = None

    @classmethod
    def _new(cls, coef, rem, sp):
        out = object.__new__(cls)
        out.coef, out.rem, out.space = coef, rem, sp
        out._mag = out._dsums = None
        return out

    @classmethod
    def constant(cls, value, sp: TaylorSpace, shape: tuple = ()) -> "TaylorModel":
        """The exact models of the float (array) ``value`` or the balls ``value`` (radius in the
        remainder), broadcast to ``shape``."""
        b = fb.as_balls(value)
        shape = np.broadcast_shapes(tuple(shape), b.shape)
        coef = np.zeros(shape + (sp.size,))
        coef[..., 0] = b.mid
        return cls._new(coef, np.broadcast_to(b.rad, shape).copy(), sp)

    # ------------------------------------------------------------------ array protocol
    @property
    def shape(self) -> tuple:
        return self.coef.shape[:-1]

    @property
    def ndim(self) -> int:
        return self.coef.ndim - 1

    def __len__(self) -> int:
        return self.coef.shape[0]

    def __getitem__(self, index) -> "TaylorModel":
        if not isinstance(index, tuple):
            index = (index,)
        full = index + (slice(None),) if any(i is Ellipsis for i in index) else index
        return TaylorModel._new(self.coef[full], self.rem[index], self.space)

    def reshape(self, *shape) -> "TaylorModel":
        shape = shape[0] if len(shape) == 1 and isinstance(shape[0], tuple) else shape
        return TaylorModel._new(self.coef.reshape(tuple(shape) + (self.space.size,)), self.rem.reshape(shape),
                                self.space)

    def ray_average(self, over=None) -> "TaylorModel":
        """The models of ``F(t) = int_0^1 f(s t) ds``: ``f`` averaged along the segment from the
        box's centre (``t = 0``) to ``t``, in the variables ``over`` (default all; the others,
        e.g. the azimuth, held fixed).

        Each coefficient is divided by its degree in those variables plus one; the remainder is
        kept (the segment lies in the box, so ``|f - p| <= r`` all along it), plus the divisions'
        rounding. For the Jacobian ``J`` of ``g`` over a box centred at a point ``x0`` this
        encloses the averaged Jacobian ``K(x) = int_0^1 J(x0 + s (x - x0)) ds`` of
        ``g(x) = g(x0) + K(x) (x - x0)`` (:mod:`rotorlyap.methods.proof`), whose linear terms
        are half those of ``J``.

        Parameters
        ----------
        over : sequence of int, optional
            Indices of the variables averaged (default: every variable).
        """
        sp = self.space
        if over is None:
            degree = sp.degree
        else:
            idx = np.asarray(list(over), dtype=int)
            if idx.size and (idx.min() < 0 or idx.max() >= sp.n):
                raise ValueError(f"variables to average must lie in 0..{sp.n - 1}, got {list(over)!r}")
            degree = sp.exponents[:, idx].sum(axis=1)
        c = self.coef / (degree + 1.0)
        # each quotient within u |c_k| + eta (F1 of rotorlyap.methods.balls)
        return TaylorModel._new(c, _up(self.rem + U * np.abs(c).sum(axis=-1)), self.space)

    def moveaxis(self, source: int, destination: int) -> "TaylorModel":
        """``numpy.moveaxis`` of the batch axes."""
        nd = self.ndim
        src, dst = source % nd, destination % nd
        return TaylorModel._new(np.moveaxis(self.coef, src, dst), np.moveaxis(self.rem, src, dst), self.space)

    def __repr__(self) -> str:
        return f"TaylorModel(shape={self.shape}, n={self.space.n}, order={self.space.order})"

    # ------------------------------------------------------------------ bounds
    def _sums(self):
        """Upper bounds of ``sum |a|`` over the odd monomials and of the positive and negative
        parts of the even ones (degree >= 1)."""
        c, sp = self.coef, self.space
        odd = np.abs(c[..., sp.odd]).sum(axis=-1)
        ev = c[..., sp.even]
        return _up(odd + np.maximum(ev, 0.0).sum(axis=-1)), _up(odd + np.maximum(-ev, 0.0).sum(axis=-1))

    def poly_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Floats ``lo <= p(t) <= hi`` for the polynomial part over the box: the constant, each
        odd monomial in ``[-1, 1]``, each even one in ``[0, 1]``."""
        pos, neg = self._sums()
        c0 = self.coef[..., 0]
        with np.errstate(invalid="ignore", over="ignore"):
            lo = np.nextafter(c0 - neg, -np.inf)
            hi = np.nextafter(c0 + pos, np.inf)
        return lo, hi

    def poly_magnitude(self) -> np.ndarray:
        """A float ``>= |p(t)|`` over the box."""
        if self._mag is None:
            lo, hi = self.poly_bounds()
            self._mag = np.maximum(-lo, hi)
        return self._mag

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Floats ``lo <= f(t) <= hi`` for every function the models enclose (``-inf``/``inf``
        where a model is not finite)."""
        lo, hi = self.poly_bounds()
        with np.errstate(invalid="ignore", over="ignore"):
            lo = np.nextafter(lo - self.rem, -np.inf)
            hi = np.nextafter(hi + self.rem, np.inf)
        ok = np.isfinite(lo) & np.isfinite(hi) & np.all(np.isfinite(self.coef), axis=-1)
        return np.where(ok, lo, -np.inf), np.where(ok, hi, np.inf)

    def magnitude(self) -> np.ndarray:
        """A float ``>= |f(t)|`` over the box (``inf`` where not finite)."""
        lo, hi = self.bounds()
        return np.maximum(-lo, hi)

    def to_balls(self) -> Balls:
        """Balls containing the range over the box."""
        lo, hi = self.bounds()
        return fb.from_bounds(lo, hi)

    def finite(self) -> np.ndarray:
        return np.isfinite(self.rem) & np.all(np.isfinite(self.coef), axis=-1)

    def __call__(self, t) -> np.ndarray:
        """The polynomial part at the points ``t`` (shape ``(..., n)``, in ``[-1, 1]``), in floats
        (not rigorous: for tests and plots)."""
        t = np.asarray(t, dtype=float)
        mono = np.prod(t[..., None, :] ** self.space.exponents, axis=-1)
        return np.sum(self.coef * mono, axis=-1)

    # ------------------------------------------------------------------ operands
    def _operand(self, o):
        if isinstance(o, TaylorModel):
            if o.space is not self.space:
                raise ValueError(f"Taylor models of different spaces: {self.space} and {o.space}")
            return o
        return fb._operand(o)   # balls, exact floats and float arrays, Arb scalars; else NotImplemented

    # ------------------------------------------------------------------ + -
    def __neg__(self) -> "TaylorModel":
        return TaylorModel._new(-self.coef, self.rem, self.space)

    def __pos__(self) -> "TaylorModel":
        return self

    def __add__(self, o):
        o = self._operand(o)
        if o is NotImplemented:
            return o
        if isinstance(o, TaylorModel):
            c = self.coef + o.coef
            # each coefficient sum within u |c_k| (no eta for sums)
            return TaylorModel._new(c, _up(self.rem + o.rem + U * np.abs(c).sum(axis=-1)), self.space)
        if isinstance(o, Balls):
            m, r = o.mid, o.rad
        else:
            m, r = o, 0.0
        shape = np.broadcast_shapes(self.shape, np.shape(m))
        c = np.broadcast_to(self.coef, shape + (self.space.size,)).copy()
        c[..., 0] = c[..., 0] + m
        return TaylorModel._new(c, _up(self.rem + r + U * np.abs(c[..., 0])), self.space)

    __radd__ = __add__

    def __sub__(self, o):
        o = self._operand(o)
        if o is NotImplemented:
            return o
        return self + (-o)

    def __rsub__(self, o):
        return (-self) + o

    # ------------------------------------------------------------------ * /
    def __mul__(self, o):
        o = self._operand(o)
        if o is NotImplemented:
            return o
        if isinstance(o, TaylorModel):
            return self._mul_model(o)
        if isinstance(o, Balls):
            m, r = o.mid, o.rad
            c = self.coef * m[..., None]
            # |m| ra + rho (|p| + ra) + rounding u sum|c| + M eta
            rem = np.abs(m) * self.rem + r * (self.poly_magnitude() + self.rem) + U * np.abs(c).sum(axis=-1)
            return TaylorModel._new(c, _up(rem), self.space)
        s = np.asarray(o, dtype=float)
        c = self.coef * s[..., None]
        return TaylorModel._new(c, _up(np.abs(s) * self.rem + U * np.abs(c).sum(axis=-1)), self.space)

    __rmul__ = __mul__

    def _degree_sums(self) -> np.ndarray:
        """``A_d = sum |a_i|`` over the monomials of degree ``d``, shape ``batch + (k + 1,)``."""
        if self._dsums is None:
            self._dsums = np.add.reduceat(np.abs(self.coef), self.space.degree_starts, axis=-1)
        return self._dsums

    def _mul_model(self, o: "TaylorModel") -> "TaylorModel":
        sp = self.space
        a, b = self.coef, o.coef
        c = _product(a, b, sp)
        A, B = self._degree_sums(), o._degree_sums()
        # sum_{d+e<=k} A_d B_e: the kept products (their rounding: gamma_m each coefficient);
        # sum_{d+e>k} A_d B_e: the truncated terms, each monomial at most 1 on the box
        kept = np.einsum("...d,de,...e->...", A, sp.kept, B)
        dropped = np.einsum("...d,de,...e->...", A, sp.dropped, B)
        ma, mb = self.poly_magnitude(), o.poly_magnitude()
        rem = ma * o.rem + self.rem * mb + self.rem * o.rem + dropped + sp.gamma * kept
        return TaylorModel._new(c, _up(rem), sp)

    def reciprocal(self) -> "TaylorModel":
        """``1 / f``: the Taylor polynomial of ``1 / x`` about the constant coefficient ``x0`` with
        the Lagrange remainder ``|h|^(k+1) / min|x|^(k+2)`` (``h = x - x0``); a model whose range
        may contain 0 gives a non-finite remainder."""
        lo, hi = self.bounds()
        k = self.space.order
        x0 = self.coef[..., 0]
        q = Balls(1.0) / Balls(x0)
        coeffs = [q]
        for _ in range(k):
            coeffs.append(coeffs[-1] * q * -1.0)
        m = np.where(lo > 0, lo, np.where(hi < 0, -hi, np.nan))
        m = np.where(m > 1e-100, m, np.nan)
        H = self._offset_magnitude()
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            rem = _up(_ipow(H / m, k + 1) / m + _PAD / m)  # PAD / m: underflow
        return _clamp(self._compose(coeffs, rem), self.to_balls().reciprocal())

    def __truediv__(self, o):
        o = self._operand(o)
        if o is NotImplemented:
            return o
        if isinstance(o, TaylorModel):
            return self * o.reciprocal()
        if isinstance(o, Balls):
            return self * o.reciprocal()
        return self * (Balls(1.0) / Balls(o))

    def __rtruediv__(self, o):
        o = self._operand(o)
        if o is NotImplemented:
            return o
        return self.reciprocal() * o

    def __pow__(self, p: int) -> "TaylorModel":
        if not isinstance(p, (int, np.integer)) or p < 0:
            raise ValueError(f"Taylor models take integer powers >= 0, got {p!r}")
        out = TaylorModel.constant(np.ones(self.shape), self.space)
        base = self
        while p:
            if p & 1:
                out = out * base
            p >>= 1
            if p:
                base = base * base
        return out

    # ------------------------------------------------------------------ composition
    def _offset_magnitude(self) -> np.ndarray:
        """A float ``>= |f(t) - x0|`` over the box, ``x0`` the constant coefficient."""
        h = self._offset()
        return _up(h.poly_magnitude() + h.rem)

    def _offset(self) -> "TaylorModel":
        c = self.coef.copy()
        c[..., 0] = 0.0
        return TaylorModel._new(c, self.rem, self.space)

    def _compose(self, coeffs: Sequence[Balls], rem: np.ndarray) -> "TaylorModel":
        """``sum_j coeffs[j] h^j + [-rem, rem]`` with ``h = self - x0`` (Horner in model arithmetic);
        ``coeffs`` balls broadcast against the batch (the Taylor coefficients about ``x0``)."""
        h = self._offset()
        p = h * coeffs[-1] + coeffs[-2]
        for cj in coeffs[-3::-1]:
            p = p * h + cj
        return TaylorModel._new(p.coef, _up(p.rem + rem), self.space)

    def sin_cos(self) -> tuple["TaylorModel", "TaylorModel"]:
        """``(sin f, cos f)``: Taylor polynomials about ``x0`` (derivatives ``+-sin x0``,
        ``+-cos x0`` as balls) with the Lagrange remainder ``max|sin^(k+1)| |h|^(k+1) / (k+1)!``,
        the derivative bounded by the ball range of ``sin`` or ``cos`` over the model's range."""
        k = self.space.order
        s0, c0 = Balls(self.coef[..., 0]).sin_cos()
        cycle_s = [s0, c0, -s0, -c0]
        cycle_c = [c0, -s0, -c0, s0]
        fact = [float(math.factorial(j)) for j in range(k + 2)]
        cs = [cycle_s[j % 4] / fact[j] for j in range(k + 1)]
        cc = [cycle_c[j % 4] / fact[j] for j in range(k + 1)]
        sr, cr = self.to_balls().sin_cos()
        ms, mc = np.minimum(sr.magnitude(), 1.0), np.minimum(cr.magnitude(), 1.0)
        d_s = ms if (k + 1) % 2 == 0 else mc     # |sin^(k+1)| is |sin| or |cos|
        d_c = mc if (k + 1) % 2 == 0 else ms
        H = self._offset_magnitude()
        with np.errstate(over="ignore", invalid="ignore"):
            hk = _ipow(H, k + 1) / fact[k + 1]
            return _clamp(self._compose(cs, _up(d_s * hk)), sr), _clamp(self._compose(cc, _up(d_c * hk)), cr)

    def sin(self) -> "TaylorModel":
        return self.sin_cos()[0]

    def cos(self) -> "TaylorModel":
        return self.sin_cos()[1]

    def atan(self) -> "TaylorModel":
        """``atan f``: the Taylor coefficients of ``atan`` about ``x0`` from those of
        ``1 / (1 + x^2)`` (``t_0 = 1 / q``, ``t_j = -(2 x0 t_{j-1} + t_{j-2}) / q``, ``q = 1 + x0^2``;
        ``a_j = t_{j-1} / j``) in ball arithmetic, the Lagrange remainder from
        ``|atan^(m)(x)| = (m - 1)! cos^m(atan x) <= (m - 1)! (1 + x^2)^(-m/2)``."""
        k = self.space.order
        x0 = Balls(self.coef[..., 0])
        inv_q = (x0 * x0 + 1.0).reciprocal()
        t = [inv_q]
        if k >= 2:
            t.append(x0 * inv_q * inv_q * -2.0)
        for j in range(2, k):
            t.append((x0 * t[j - 1] * 2.0 + t[j - 2]) * inv_q * -1.0)
        lo, hi = self.bounds()
        centre = fb._atan_point(self.coef[..., 0])
        coeffs = [centre] + [t[j - 1] / float(j) for j in range(1, k + 1)]
        xmin = np.where((lo <= 0) & (hi >= 0), 0.0, np.minimum(np.abs(lo), np.abs(hi)))
        H = self._offset_magnitude()
        with np.errstate(over="ignore", invalid="ignore"):
            # (1 + xmin^2)^(-(k+1)/2) from products and the correctly rounded sqrt: relative
            # roundings only, covered by _up
            q = 1.0 + xmin * xmin
            den = _ipow(q, (k + 1) // 2) * (np.sqrt(q) if (k + 1) % 2 else 1.0)
            rem = _up(_ipow(H, k + 1) / (k + 1) / den)
        rem = np.where(np.isfinite(lo) & np.isfinite(hi), rem, np.nan)
        return _clamp(self._compose(coeffs, rem), self.to_balls().atan())

    def sqrt(self) -> "TaylorModel":
        """``sqrt f`` for a model whose range lies above 0: ``sqrt(x0) sum_j binom(1/2, j)
        (h / x0)^j`` with the Lagrange remainder ``|binom(1/2, k+1)| |h|^(k+1) lo^(1/2-(k+1))``."""
        k = self.space.order
        lo, hi = self.bounds()
        x0 = self.coef[..., 0]
        ok = lo > 0
        x0b = Balls(np.where(ok, x0, 1.0))
        root = x0b.sqrt()
        inv = x0b.reciprocal()
        coeffs, power = [], root
        for j in range(k + 1):
            coeffs.append(power * fb.from_arb(_binom_half(j)))
            power = power * inv
        bk = abs(float(_binom_half(k + 1).mid())) * (1.0 + 1e-15)
        H = self._offset_magnitude()
        lo_ok = np.where(ok, lo, np.nan)
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            rem = _up((bk * _ipow(H / lo_ok, k + 1) + _PAD) * np.sqrt(lo_ok))  # PAD: underflow
        return _clamp(self._compose(coeffs, np.where(ok, rem, np.nan)), self.to_balls().sqrt())


def _clamp(model: TaylorModel, ball: Balls) -> TaylorModel:
    """``model``, or the constant model of ``ball`` where the model's remainder alone is wider than
    that ball or not finite (both enclose the function: ``ball`` is its ball enclosure over the
    argument's range; over wide ranges a Taylor polynomial's remainder can exceed the function's
    whole range, and then the polynomial carries no information worth its remainder)."""
    with np.errstate(invalid="ignore", over="ignore"):
        narrower = ball.finite() & ~(ball.upper() - ball.lower() >= 2.0 * model.rem)
    if not np.any(narrower):
        return model
    return where(narrower, TaylorModel.constant(ball, model.space, model.shape), model)


def _ipow(x, p: int):
    """``x**p`` for an integer ``p >= 1`` by float products (relative roundings only, no ``pow``)."""
    out = x
    for _ in range(p - 1):
        out = out * x
    return out


def _binom_half(j: int) -> arb:
    """``binom(1/2, j)`` exactly (an Arb ball)."""
    out = arb(1)
    for i in range(j):
        out = out * (arb(1) / 2 - i) / (i + 1)
    return out


# --------------------------------------------------------------------------------------
# Constructors and functions
# --------------------------------------------------------------------------------------


def variables(centre, radius, order: int) -> list[TaylorModel]:
    """The box variables as exact models: ``x_i = centre_i + radius_i t_i``.

    Parameters
    ----------
    centre, radius : array_like, shape ``batch + (n,)``
        Centres and half-widths ``>= 0`` of the boxes (the units of the quantities).
    order : int
        Order of the models (1 to :data:`MAX_ORDER`).

    Returns
    -------
    list of TaylorModel
        ``n`` models of shape ``batch``.

    Raises
    ------
    ValueError
        Mismatched shapes, a negative or non-finite radius, a bad order.
    """
    c = np.asarray(centre, dtype=float)
    r = np.asarray(radius, dtype=float)
    if c.ndim < 1:
        raise ValueError("centre must have a last axis of the n variables")
    try:
        c, r = np.broadcast_arrays(c, r)
    except ValueError:
        raise ValueError(f"centre and radius do not match: shapes {np.shape(centre)} and {np.shape(radius)}") from None
    if not np.all(np.isfinite(r) & (r >= 0)) or not np.all(np.isfinite(c)):
        raise ValueError("centre and radius must be finite, radius >= 0")
    n = c.shape[-1]
    sp = space(n, order)
    out = []
    for i in range(n):
        coef = np.zeros(c.shape[:-1] + (sp.size,))
        coef[..., 0] = c[..., i]
        coef[..., 1 + i] = r[..., i]
        out.append(TaylorModel._new(coef, np.zeros(c.shape[:-1]), sp))
    return out


@functools.lru_cache(maxsize=None)
def _shift_pairs(n: int, order: int):
    """Pairs ``(e, f)`` of monomials of the space with ``f <= e`` componentwise: their indices, the
    product of binomials ``prod_i C(e_i, f_i)`` and the exponents ``e - f`` and ``f``."""
    sp = space(n, order)
    E = sp.exponents
    ei, fi = np.nonzero(np.all(E[None, :, :] <= E[:, None, :], axis=-1))      # rows e, columns f <= e
    binom = np.ones(ei.size)
    for i in range(n):
        binom *= np.array([math.comb(int(a), int(b)) for a, b in zip(E[ei, i], E[fi, i])], dtype=float)
    return ei, fi, binom, E[ei] - E[fi], E[fi]


def _pair_factors(sp: TaylorSpace, c: np.ndarray, r: np.ndarray) -> np.ndarray:
    """``C(e, f) c^(e - f) r^f`` per sub-box (rows of ``c``, ``r``) and pair of
    :func:`_shift_pairs`, shape (rows, pairs): exact for dyadic ``c``, ``r`` such as the halves'
    ``+-1/2`` (the powers by products, the binomials small integers)."""
    _, _, binom, pc, pr = _shift_pairs(sp.n, sp.order)
    k = np.arange(sp.n)
    cp = np.ones((sp.order + 1,) + c.shape)
    rp = np.ones((sp.order + 1,) + r.shape)
    for d in range(1, sp.order + 1):
        cp[d] = cp[d - 1] * c
        rp[d] = rp[d - 1] * r
    return binom * np.prod(cp[pc, :, k] * rp[pr, :, k], axis=1).T


@functools.lru_cache(maxsize=4400)
def _shift_matrix(sp: TaylorSpace, c: bytes, r: bytes) -> tuple[np.ndarray, np.ndarray]:
    """``T[e, f] = C(e, f) c^(e - f) r^f`` for one sub-box (``c``, ``r`` as bytes of float arrays:
    a cache key) and the row sums of ``|T|``."""
    ei, fi, _, _, _ = _shift_pairs(sp.n, sp.order)
    factor = _pair_factors(sp, np.frombuffer(c)[None, :], np.frombuffer(r)[None, :])[0]
    T = np.zeros((sp.size, sp.size))
    T[ei, fi] = factor
    T_abs = np.abs(T).sum(axis=1)
    T.setflags(write=False)
    T_abs.setflags(write=False)
    return T, T_abs


@functools.lru_cache(maxsize=None)
def _halves(n: int, order: int):
    """The ``2^n`` halves of ``[-1, 1]^n`` (centres ``+-1/2``, in ``itertools.product`` order) and
    the expansion matrices side by side, ``(M, 2^n M)``, with the row sums of their magnitudes
    ``(M, 2^n)``."""
    sp = space(n, order)
    corners = np.array(list(itertools.product((-0.5, 0.5), repeat=n)))
    half = np.full(n, 0.5)
    mats = [_shift_matrix(sp, c.tobytes(), half.tobytes()) for c in corners]
    T = np.concatenate([t for t, _ in mats], axis=1)
    B = np.stack([b for _, b in mats], axis=1)
    for a in (corners, T, B):
        a.setflags(write=False)
    return corners, T, B


def split(model: TaylorModel) -> tuple[TaylorModel, np.ndarray]:
    """Models over the ``2^n`` halves of the box (centre ``+-1/2``, radius ``1/2`` in every variable),
    by one product with the expansion matrices: the coefficient of ``s^f`` in a half is
    ``sum_(e >= f) a_e C(e, f) c^(e - f) r^f``, the binomials and powers exact, so the only roundings
    are the products with ``a_e`` and their sum, bounded by ``gamma_(M + 1) sum |a_e| |T[e, f]|`` (a
    float dot product's error bound whatever the order of summation) and added to the remainder,
    which is otherwise the model's. The range of a polynomial over small sub-boxes is far tighter
    than its bound over the whole box (:meth:`TaylorModel.bounds`, which takes every monomial at its
    extreme separately).

    Parameters
    ----------
    model : TaylorModel, shape ``(m,)``

    Returns
    -------
    halves : TaylorModel, shape ``(m, 2^n)``
        In each half's own variables ``s`` (``t = centre + s / 2``).
    centres : numpy.ndarray, shape ``(2^n, n)``
        The halves' centres in the box's variables.
    """
    sp = model.space
    if model.ndim != 1:
        raise ValueError(f"split takes models of shape (m,), got {model.shape}")
    if sp.order > 6:
        raise ValueError(f"split takes models of order <= 6 (exact expansion factors), got {sp.order}")
    corners, T, B = _halves(sp.n, sp.order)
    k = corners.shape[0]
    m = model.coef.shape[0]
    coef = (model.coef @ T).reshape(m, k, sp.size)
    err = np.abs(model.coef) @ B
    gamma = (sp.size + 1) * U * _GAMMA_SLACK / (1.0 - (sp.size + 1) * U)
    rem = _up(np.asarray(model.rem)[:, None] + _up(gamma * err))
    return TaylorModel._new(coef, rem, sp), corners


def stack(items: Sequence[TaylorModel], axis: int = 0) -> TaylorModel:
    """Models of one space stacked along a new batch axis ``axis``."""
    items = list(items)
    sp = items[0].space
    if any(x.space is not sp for x in items):
        raise ValueError("stack: Taylor models of different spaces")
    shape = np.broadcast_shapes(*[x.shape for x in items])
    ax = axis if axis >= 0 else len(shape) + 1 + axis
    coef = np.stack([np.broadcast_to(x.coef, shape + (sp.size,)) for x in items], axis=ax)
    rem = np.stack([np.broadcast_to(x.rem, shape) for x in items], axis=ax)
    return TaylorModel._new(coef, rem, sp)


def where(mask, a: TaylorModel, b: TaylorModel) -> TaylorModel:
    """Elementwise ``a`` where ``mask`` (boolean, broadcast against the batch) else ``b``."""
    mask = np.asarray(mask, dtype=bool)
    return TaylorModel._new(np.where(mask[..., None], a.coef, b.coef), np.where(mask, a.rem, b.rem), a.space)


def _apply(x, name: str):
    """``name`` (sin, cos, sqrt, atan) of a model, a Jet of models, or balls/floats."""
    if isinstance(x, Jet):
        v = x.v
        if not isinstance(v, TaylorModel):
            from . import intervals as iv
            return getattr(iv, name)(x) if name != "atan" else _jet_atan_balls(x)
        if name in ("sin", "cos"):
            s, c = v.sin_cos()
            return chain(x, s, c) if name == "sin" else chain(x, c, -s)
        if name == "sqrt":
            r = v.sqrt()
            return chain(x, r, r.reciprocal() * 0.5)
        f = v.atan()
        return chain(x, f, (v * v + 1.0).reciprocal())
    if isinstance(x, TaylorModel):
        return getattr(x, name)()
    b = fb.as_balls(x)
    return getattr(b, name)()


def _jet_atan_balls(x: Jet) -> Jet:
    v = fb.as_balls(x.v)
    return chain(x, v.atan(), (v * v + 1.0).reciprocal())


def sin(x):
    """``sin`` of a :class:`TaylorModel`, a Jet of models, balls or floats (rigorous)."""
    return _apply(x, "sin")


def cos(x):
    """``cos`` of a :class:`TaylorModel`, a Jet of models, balls or floats (rigorous)."""
    return _apply(x, "cos")


def sqrt(x):
    """``sqrt`` of a :class:`TaylorModel`, a Jet of models, balls or floats (rigorous)."""
    return _apply(x, "sqrt")


def atan(x):
    """``atan`` of a :class:`TaylorModel`, a Jet of models, balls or floats (rigorous)."""
    return _apply(x, "atan")


class TaylorMath:
    """Stands for the ``math`` module in generated scalar code run on Taylor models (or on
    :class:`~rotorlyap.methods.intervals.Jet` objects whose values and gradients are models)."""

    sin = staticmethod(sin)
    cos = staticmethod(cos)
    sqrt = staticmethod(sqrt)
    atan = staticmethod(atan)
