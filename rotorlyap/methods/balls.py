"""Float balls: rigorous midpoint-radius arithmetic on numpy float64 arrays.

:class:`Balls` holds two float arrays of one shape, midpoints ``mid`` and radii ``rad >= 0``;
the ball ``k`` is the set of reals ``[mid[k] - rad[k], mid[k] + rad[k]]``. Every operation
returns balls that contain every exact result of the operation applied to points of its
operands: numpy's vectorised float arithmetic in the default rounding (to nearest), with the
rounding errors bounded and added to the radii as in

    S. M. Rump, "Fast and parallel interval arithmetic", BIT 39(3), 534-554 (1999).

The facts used (IEEE 754 binary64, round to nearest, ``u = 2**-53``, ``eta = 2**-1074``):

(F1) ``c = fl(a op b)`` for ``op`` in ``+ - * /`` and ``c = fl(sqrt(a))`` satisfy
     ``|c - a op b| <= u |c| + eta`` (Rump 1999, (2.3)); sums and differences are exact when
     subnormal, so for them ``eta`` may be dropped;
(F2) hence a non-negative real ``x`` rounded to ``fl(x)`` is at most ``fl(x) (1 + u) + eta``;
(F3) a sum of ``k`` terms in any order (numpy's pairwise summation, BLAS dot products with or
     without fused multiply-adds) is within ``gamma_{k-1} sum |x_i|`` of the exact sum,
     ``gamma_m = m u / (1 - m u) <= m u (1 + 2**-20)`` for ``m <= 2**31`` (Higham, *Accuracy and stability of numerical
     algorithms*, 2nd ed., (3.4)-(3.5)), plus ``k eta`` for underflowing products.

Every radius below is computed in floats from non-negative terms, each step's rounding
covered by (F2); the computed sum ``s`` is then passed through :func:`_up`,
``fl(fl(s K) + PAD)`` with ``K = 1 + 16 u`` and ``PAD = 2**-1020``, which is at least
``s (1 + 12 u) + 2**53 eta`` (proof in :func:`_up`): every radius formula here needs at most
``s (1 + u)**11 + 2**50 eta``, so the returned radius covers the exact one. Each operation
states its exact radius and the count of roundings in a comment.

Elementary functions: ``sqrt`` from the correctly rounded IEEE square root (F1) at the ends of
the ball (it is monotone); ``sin``, ``cos`` and ``atan`` from Taylor polynomials evaluated in
this ball arithmetic with their Lagrange remainders (argument reduction by ``pi / 2`` as a ball
from Arb, two argument halvings for ``atan``), at the midpoint, widened by a mean-value bound
over the ball: nothing trusts the C library's ``sin``, ``cos`` or ``atan``.

Where a result cannot be enclosed (a division by a ball that may contain 0, a square root of
a ball that reaches below 0, an overflow) the ball is ``nan`` or infinite, non-finite values
propagate through every operation, and :meth:`Balls.lower`, :meth:`Balls.upper`,
:meth:`Balls.magnitude` give ``-inf``/``inf`` for them: a proof that meets one fails, it never
passes.
"""

from __future__ import annotations

import math
from typing import Iterable, Sequence

import numpy as np
from flint import arb

__all__ = ["Balls", "as_balls", "from_arb", "from_bounds", "concatenate", "stack", "where", "matmul",
           "broadcast_to", "moveaxis", "roll", "union", "U", "ETA"]

U = 2.0 ** -53
"""Unit roundoff of binary64, round to nearest."""
ETA = 2.0 ** -1074
"""Smallest positive subnormal binary64."""
_K = 1.0 + 16 * U          # the radius' own inflation (exact float)
_PAD = 2.0 ** -1020        # covers the absolute errors ``eta`` of underflowing products


def _up(s: np.ndarray) -> np.ndarray:
    """An upper bound of every real ``R <= s (1 + u)**11 + 2**50 eta`` (``s >= 0`` floats).

    ``y = s K`` exact, ``fl(y) >= y (1 - u) - eta`` (F1); the sum with ``PAD`` is rounded with
    relative error ``u`` (sums have no ``eta``), so the result is at least
    ``(s (1 + 16 u)(1 - u) - eta + PAD)(1 - u) >= s (1 + 13 u) + PAD / 2``, and
    ``PAD / 2 = 2**53 eta``, ``(1 + u)**11 <= 1 + 12 u``. Overflow gives ``inf`` (still a bound).
    """
    return s * _K + _PAD


# The radius formulas of the four commonest operations as scalar functions, compiled into numpy
# ufuncs by numba when it is installed (one pass, one call instead of a dozen: the hover proofs'
# arrays have a handful of elements, where numpy's per-call cost dominates). Without fast-math
# numba keeps IEEE round-to-nearest; a fused multiply-add, if LLVM formed one, rounds once
# instead of twice, which every bound above allows. The plain functions are the numpy path.

def _rad_add(ma, ra, mb, rb):
    # exact: ra + rb + |c - (ma + mb)| <= ra + rb + u|c| (F1, no eta); 2 roundings
    return (ra + rb + U * abs(ma + mb)) * _K + _PAD


def _rad_add_point(ma, ra, b):
    # exact point b: ra + u|c|; 1 rounding (u|c| exact or eta lost: covered by _up)
    return (ra + U * abs(ma + b)) * _K + _PAD


def _rad_mul(ma, ra, mb, rb):
    # exact: |ma| rb + ra (|mb| + rb) + u|c| + eta (F1); the float terms: 3 products and 3 sums,
    # each a factor (1 + u) and the products an eta each (F2): <= s (1 + u)^4 + 4 eta
    return (abs(ma) * rb + ra * (abs(mb) + rb) + U * abs(ma * mb)) * _K + _PAD


def _rad_mul_point(ma, ra, b):
    # exact point b: |b| ra + u|c| + eta; 2 roundings, 2 eta
    return (abs(b) * ra + U * abs(ma * b)) * _K + _PAD


try:
    from numba import vectorize as _vectorize

    _SIG4, _SIG3 = ["float64(float64, float64, float64, float64)"], ["float64(float64, float64, float64)"]
    _rad_add = _vectorize(_SIG4, cache=True)(_rad_add)
    _rad_add_point = _vectorize(_SIG3, cache=True)(_rad_add_point)
    _rad_mul = _vectorize(_SIG4, cache=True)(_rad_mul)
    _rad_mul_point = _vectorize(_SIG3, cache=True)(_rad_mul_point)
except ImportError:  # pragma: no cover - the numpy path (the same formulas)
    pass


class Balls:
    """Arrays of balls: midpoints ``mid`` and radii ``rad`` (float64, one shape).

    Parameters
    ----------
    mid : array_like
        Midpoints (converted to float64; the floats are taken exactly).
    rad : array_like, optional
        Radii ``>= 0`` (default 0: exact balls), broadcast against ``mid``.

    Notes
    -----
    Arithmetic with other :class:`Balls`, Python or numpy floats and float arrays (taken as exact
    points) broadcasts as numpy does; :class:`flint.arb` scalars are converted rigorously
    (:func:`from_arb`). Instances are not modified in place by this module.
    """

    __slots__ = ("mid", "rad")
    __array_ufunc__ = None  # numpy defers to the operators below
    __array_priority__ = 1000

    def __init__(self, mid, rad=0.0):
        m = np.asarray(mid, dtype=float)
        r = np.asarray(rad, dtype=float)
        if r.shape != m.shape:
            m, r = np.broadcast_arrays(m, r)
            m, r = m.copy(), r.copy()
        self.mid = m
        self.rad = r

    @classmethod
    def _new(cls, mid: np.ndarray, rad: np.ndarray) -> "Balls":
        out = object.__new__(cls)
        out.mid = mid
        out.rad = rad
        return out

    # ------------------------------------------------------------------ array protocol
    @property
    def shape(self) -> tuple:
        return self.mid.shape

    @property
    def ndim(self) -> int:
        return self.mid.ndim

    @property
    def size(self) -> int:
        return self.mid.size

    def __len__(self) -> int:
        return len(self.mid)

    def __getitem__(self, index) -> "Balls":
        return Balls._new(self.mid[index], self.rad[index])

    def reshape(self, *shape) -> "Balls":
        return Balls._new(self.mid.reshape(*shape), self.rad.reshape(*shape))

    def swapaxes(self, a: int, b: int) -> "Balls":
        return Balls._new(self.mid.swapaxes(a, b), self.rad.swapaxes(a, b))

    def repeat(self, repeats, axis=None) -> "Balls":
        return Balls._new(self.mid.repeat(repeats, axis=axis), self.rad.repeat(repeats, axis=axis))

    def copy(self) -> "Balls":
        return Balls._new(self.mid.copy(), self.rad.copy())

    def __repr__(self) -> str:
        return f"Balls(mid={self.mid!r}, rad={self.rad!r})"

    # ------------------------------------------------------------------ bounds
    def finite(self) -> np.ndarray:
        """True where the ball is a finite ball (finite midpoint and radius)."""
        return np.isfinite(self.mid) & np.isfinite(self.rad)

    def lower(self) -> np.ndarray:
        """Floats ``<=`` every point of each ball (``-inf`` where the ball is not finite)."""
        with np.errstate(invalid="ignore", over="ignore"):
            lo = np.nextafter(self.mid - self.rad, -np.inf)  # fl is within one ulp: step down
        return np.where(self.finite(), lo, -np.inf)

    def upper(self) -> np.ndarray:
        """Floats ``>=`` every point of each ball (``inf`` where the ball is not finite)."""
        with np.errstate(invalid="ignore", over="ignore"):
            hi = np.nextafter(self.mid + self.rad, np.inf)
        return np.where(self.finite(), hi, np.inf)

    def magnitude(self) -> np.ndarray:
        """Floats ``>= |x|`` for every point ``x`` of each ball (``inf`` if not finite)."""
        with np.errstate(invalid="ignore", over="ignore"):
            mag = np.nextafter(np.abs(self.mid) + self.rad, np.inf)
        return np.where(self.finite(), mag, np.inf)

    def positive(self) -> np.ndarray:
        """True where every point of the ball is ``> 0``."""
        return self.lower() > 0

    def negative(self) -> np.ndarray:
        """True where every point of the ball is ``< 0``."""
        return self.upper() < 0

    # ------------------------------------------------------------------ + -
    def __neg__(self) -> "Balls":
        return Balls._new(-self.mid, self.rad)

    def __pos__(self) -> "Balls":
        return self

    def __add__(self, o) -> "Balls":
        o = _operand(o)
        if o is NotImplemented:
            return o
        if isinstance(o, Balls):
            return Balls._new(self.mid + o.mid, _rad_add(self.mid, self.rad, o.mid, o.rad))
        return Balls._new(self.mid + o, _rad_add_point(self.mid, self.rad, o))

    __radd__ = __add__

    def __sub__(self, o) -> "Balls":
        o = _operand(o)
        if o is NotImplemented:
            return o
        return self + (-o)

    def __rsub__(self, o) -> "Balls":
        return (-self) + o

    # ------------------------------------------------------------------ * /
    def __mul__(self, o) -> "Balls":
        o = _operand(o)
        if o is NotImplemented:
            return o
        if isinstance(o, Balls):
            return Balls._new(self.mid * o.mid, _rad_mul(self.mid, self.rad, o.mid, o.rad))
        return Balls._new(self.mid * o, _rad_mul_point(self.mid, self.rad, o))

    __rmul__ = __mul__

    def reciprocal(self) -> "Balls":
        """``1 / x``; a ball that may contain 0 gives ``nan``.

        With ``m = |mid| > r``: the image lies within ``r / (m (m - r))`` of ``1 / mid``. The
        float denominator ``d = fl(m fl(m - r))`` is at most the exact one times ``(1 + u)**2``
        (plus ``eta``, negligible as ``d >= 2**-1000`` is required), so
        ``r / (m (m - r)) <= fl(r / d) (1 + u)**4 + eta``; with ``u |c| + eta`` for the midpoint
        and one more sum: ``<= s (1 + u)**5 + 3 eta``. Where ``d`` overflows (then
        ``m - r >= 1``), ``fl(fl(r / m) / gap)`` instead: ``<= (1 + u)**3`` times it ``+ 4 eta``.
        """
        m = np.abs(self.mid)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore", under="ignore"):
            gap = m - self.rad          # fl is monotone: gap > 0 implies m > r exactly
            d = m * gap
            c = 1.0 / self.mid
            spread = np.where(np.isfinite(d), self.rad / d, (self.rad / m) / gap)
            s = spread + U * np.abs(c)
            ok = (gap > 0) & (d >= 2.0 ** -1000) & np.isfinite(s) & np.isfinite(c)
            return Balls._new(np.where(ok, c, np.nan), np.where(ok, _up(s), np.nan))

    def __truediv__(self, o) -> "Balls":
        o = _operand(o)
        if o is NotImplemented:
            return o
        if isinstance(o, Balls):
            return self * o.reciprocal()
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            c = self.mid / o
            # exact point o != 0: ra / |o| + u|c| + eta; 2 roundings (o = 0 gives inf/nan)
            s = self.rad / np.abs(o) + U * np.abs(c)
            ok = np.asarray(o) != 0
            return Balls._new(np.where(ok, c, np.nan), np.where(ok, _up(s), np.nan))

    def __rtruediv__(self, o) -> "Balls":
        return self.reciprocal() * o

    # ------------------------------------------------------------------ reductions
    def sum(self, axis=None, dtype=None, out=None, keepdims=False, **kwargs) -> "Balls":
        """The sum along ``axis``: midpoints summed in floats, the error by (F3)."""
        k = self.mid.size if axis is None else int(np.prod([self.mid.shape[a] for a in np.atleast_1d(axis)]))
        c = np.sum(self.mid, axis=axis, keepdims=keepdims)
        if k <= 1:
            return Balls._new(c, np.sum(self.rad, axis=axis, keepdims=keepdims))
        g = (k - 1) * U * (1.0 + 2.0 ** -20)     # >= gamma_{k-1} (k <= 2**31)
        # exact: sum r_i + gamma sum |m_i|; both float sums of non-negative terms are within a
        # factor 1 / (1 - g) <= 1 + 2 g of the exact ones; 1 + 4 g rounded is >= 1 + 2 g
        s = (np.sum(self.rad, axis=axis, keepdims=keepdims)
             + g * np.sum(np.abs(self.mid), axis=axis, keepdims=keepdims)) * (1.0 + 4.0 * g)
        return Balls._new(c, _up(s))

    # ------------------------------------------------------------------ elementary functions
    def sqrt(self) -> "Balls":
        """``sqrt`` (monotone): the hull of the correctly rounded square roots of the ends; a
        ball that reaches below 0 gives ``nan``."""
        lo, hi = self.lower(), self.upper()
        with np.errstate(invalid="ignore"):
            a = np.nextafter(np.sqrt(np.maximum(lo, 0.0)), -np.inf)   # <= sqrt(lo) (F1: one ulp)
            b = np.nextafter(np.sqrt(hi), np.inf)
        out = from_bounds(np.maximum(a, 0.0), b)
        bad = ~(lo >= 0)
        return Balls._new(np.where(bad, np.nan, out.mid), np.where(bad, np.nan, out.rad))

    def sin(self) -> "Balls":
        """``sin`` over the ball (:func:`_sin_cos_range`)."""
        return _sin_cos_range(self)[0]

    def cos(self) -> "Balls":
        """``cos`` over the ball (:func:`_sin_cos_range`)."""
        return _sin_cos_range(self)[1]

    def sin_cos(self) -> tuple["Balls", "Balls"]:
        """``(sin, cos)`` over the ball, from one evaluation at its ends."""
        return _sin_cos_range(self)

    def atan(self) -> "Balls":
        """``atan`` (monotone): the hull of the point enclosures at the two ends
        (:func:`_atan_point`)."""
        lo, hi = self.lower(), self.upper()
        ok = np.isfinite(lo) & np.isfinite(hi)
        ends = _atan_point(np.concatenate([np.where(ok, lo, 0.0).ravel(), np.where(ok, hi, 0.0).ravel()]))
        half = lo.size
        out = from_bounds(ends[:half].lower().reshape(lo.shape), ends[half:].upper().reshape(lo.shape))
        return Balls._new(np.where(ok, out.mid, np.nan), np.where(ok, out.rad, np.nan))

    def nonnegative_part(self) -> "Balls":
        """``max(x, 0)``."""
        lo, hi = self.lower(), self.upper()
        keep = lo >= 0
        out = from_bounds(np.maximum(lo, 0.0), np.maximum(hi, 0.0))
        return where(keep, self, out)

    def __abs__(self) -> "Balls":
        lo, hi = self.lower(), self.upper()
        out = from_bounds(np.zeros_like(lo), np.maximum(-lo, hi))
        return where(lo >= 0, self, where(hi <= 0, -self, out))

    def minimum(self, cap: float) -> "Balls":
        """``min(x, cap)`` for a float ``cap``."""
        lo, hi = self.lower(), self.upper()
        out = from_bounds(np.minimum(lo, cap), np.minimum(hi, cap))
        return where(hi <= cap, self, out)

    def union(self, o: "Balls") -> "Balls":
        """Balls containing both balls."""
        return from_bounds(np.minimum(self.lower(), o.lower()), np.maximum(self.upper(), o.upper()))


# --------------------------------------------------------------------------------------
# Constructors and array functions
# --------------------------------------------------------------------------------------


def from_arb(x) -> Balls:
    """A :class:`Balls` scalar containing the Arb ball ``x`` (its midpoint rounded to a float, the
    rounding's bound added to the radius, rounded up)."""
    if not x.is_finite():
        return Balls._new(np.array(np.nan), np.array(np.nan))
    m = float(x.mid())
    err = abs(x.mid() - arb(m)) + x.rad()
    r = float(err.upper())
    return Balls._new(np.array(m), np.array(np.nextafter(r, np.inf) if r > 0 else 0.0))


def _operand(o):
    """A :class:`Balls` or an exact float operand (float array) from what arithmetic accepts."""
    if isinstance(o, Balls):
        return o
    if isinstance(o, (float, int, np.floating, np.integer)):
        return float(o)
    if isinstance(o, np.ndarray):
        if o.dtype == object:
            raise TypeError("Balls do not mix with object arrays (Arb balls): convert with as_balls/from_arb")
        return o.astype(float, copy=False)
    if isinstance(o, arb):
        return from_arb(o)
    return NotImplemented


def as_balls(x) -> Balls:
    """``x`` as :class:`Balls` (floats and float arrays are exact balls)."""
    if isinstance(x, Balls):
        return x
    if isinstance(x, arb):
        return from_arb(x)
    a = np.asarray(x, dtype=float)
    return Balls._new(a, np.zeros_like(a))


def from_bounds(lo, hi) -> Balls:
    """Balls containing the intervals ``[lo, hi]`` (floats, ``lo <= hi``; a non-finite end gives a
    non-finite ball). ``m = fl(lo/2 + hi/2)``; ``max(hi - m, m - lo)`` rounded: 1 rounding."""
    lo = np.asarray(lo, dtype=float)
    hi = np.asarray(hi, dtype=float)
    with np.errstate(invalid="ignore", over="ignore"):
        m = 0.5 * lo + 0.5 * hi
        r = _up(np.maximum(hi - m, m - lo))
    ok = np.isfinite(lo) & np.isfinite(hi)
    return Balls._new(np.where(ok, m, np.nan), np.where(ok, r, np.inf))


def union(a: Balls, b: Balls) -> Balls:
    """Balls containing both ``a`` and ``b`` (elementwise)."""
    return as_balls(a).union(as_balls(b))


def where(mask, a, b) -> Balls:
    """Elementwise ``a`` where ``mask`` else ``b``."""
    a, b = as_balls(a), as_balls(b)
    return Balls._new(np.where(mask, a.mid, b.mid), np.where(mask, a.rad, b.rad))


def stack(items: Sequence, axis: int = 0) -> Balls:
    items = [as_balls(x) for x in items]
    return Balls._new(np.stack([x.mid for x in items], axis=axis), np.stack([x.rad for x in items], axis=axis))


def concatenate(items: Sequence, axis: int = 0) -> Balls:
    items = [as_balls(x) for x in items]
    return Balls._new(np.concatenate([x.mid for x in items], axis=axis),
                      np.concatenate([x.rad for x in items], axis=axis))


def broadcast_to(x, shape) -> Balls:
    x = as_balls(x)
    return Balls._new(np.broadcast_to(x.mid, shape), np.broadcast_to(x.rad, shape))


def moveaxis(x: Balls, source, destination) -> Balls:
    return Balls._new(np.moveaxis(x.mid, source, destination), np.moveaxis(x.rad, source, destination))


def roll(x: Balls, shift: int, axis: int) -> Balls:
    return Balls._new(np.roll(x.mid, shift, axis=axis), np.roll(x.rad, shift, axis=axis))


def matmul(a, b) -> Balls:
    """Matrix products of balls (numpy ``matmul`` broadcasting), Rump's midpoint-radius product.

    ``C = fl(Ma Mb)``; the exact products lie within
    ``|Ma| Rb + Ra (|Mb| + Rb) + gamma_k |Ma| |Mb| + k eta`` of ``C`` (F3, ``k`` the inner
    dimension); the radius is computed with float products of non-negative matrices, each within
    a factor ``1 / (1 - gamma_k) <= 1 + 2 g`` of exact (``g >= gamma_k``), so the sum is multiplied
    by ``1 + 4 g`` (rounded, still ``>= 1 + 2 g``).
    """
    a, b = as_balls(a), as_balls(b)
    k = a.shape[-1]
    g = k * U * (1.0 + 2.0 ** -20)  # >= gamma_k
    c = np.matmul(a.mid, b.mid)
    am = np.abs(a.mid)
    s = (np.matmul(am, b.rad) + np.matmul(a.rad, np.abs(b.mid) + b.rad)
         + g * np.matmul(am, np.abs(b.mid))) * (1.0 + 4.0 * g)
    return Balls._new(c, _up(s))


# --------------------------------------------------------------------------------------
# Elementary functions at points: Taylor polynomials in ball arithmetic
# --------------------------------------------------------------------------------------


def _const(x) -> Balls:
    return from_arb(x)


_PIO2 = _const(arb.pi() / 2)
_PI = _const(arb.pi())
_SIN_TERMS = 10   # |r| <= 0.79: remainder r^21 / 21! < 1e-21
_SIN_C = [_const((-1) ** j / arb(math.factorial(2 * j + 1))) for j in range(_SIN_TERMS)]
_COS_C = [_const((-1) ** j / arb(math.factorial(2 * j))) for j in range(_SIN_TERMS)]
_SIN_REM = float((arb(0.8) ** (2 * _SIN_TERMS + 1) / arb(math.factorial(2 * _SIN_TERMS + 1))).upper())
_COS_REM = float((arb(0.8) ** (2 * _SIN_TERMS) / arb(math.factorial(2 * _SIN_TERMS))).upper())
_ATAN_TERMS = 13  # |t| <= 0.2: remainder t^27 / 27 < 1e-20
_ATAN_C = [_const((-1) ** j / arb(2 * j + 1)) for j in range(_ATAN_TERMS)]
_ATAN_REM = float((arb(0.2) ** (2 * _ATAN_TERMS + 1) / arb(2 * _ATAN_TERMS + 1)).upper())
_REDUCE_LIMIT = 2.0 ** 20  # |x| beyond: sin and cos are only known to lie in [-1, 1]


def _horner(coeffs: Sequence[Balls], x: Balls) -> Balls:
    p = coeffs[-1] + 0.0 * x
    for c in coeffs[-2::-1]:
        p = p * x + c
    return p


def _sin_cos_point(m: np.ndarray) -> tuple[Balls, Balls]:
    """Balls containing ``sin(m)`` and ``cos(m)`` for floats ``m``.

    ``k = round(m / (pi/2))``, ``r = m - k (pi/2)`` in ball arithmetic (``pi/2`` a ball from Arb,
    so ``r`` contains the exact reduced argument, ``|r| <= 0.79`` for ``|m| <= 2**20``); the
    Taylor polynomials of degree 19 and 18 in ``r`` with the Lagrange remainders
    ``|r|^21 / 21!`` and ``|r|^20 / 20!`` (bounded at ``|r| = 0.8``) added to the radius; the
    quadrant ``k mod 4`` picks ``+-sin r`` or ``+-cos r``. Larger or non-finite ``|m|`` give
    ``[-1, 1]`` (non-finite: ``nan``).
    """
    m = np.asarray(m, dtype=float)
    ok = np.isfinite(m) & (np.abs(m) <= _REDUCE_LIMIT)
    mm = np.where(ok, m, 0.0)
    k = np.rint(mm / _PIO2.mid)
    r = as_balls(mm) - _PIO2 * k
    ok &= r.magnitude() <= 0.8    # the remainders below are bounded at |r| = 0.8 (always true)
    r2 = r * r
    sr = _horner(_SIN_C, r2) * r
    cr = _horner(_COS_C, r2)
    sr = Balls._new(sr.mid, _up(sr.rad + _SIN_REM))
    cr = Balls._new(cr.mid, _up(cr.rad + _COS_REM))
    q = np.mod(k, 4.0)
    s = where(q == 0, sr, where(q == 1, cr, where(q == 2, -sr, -cr)))
    c = where(q == 0, cr, where(q == 1, -sr, where(q == 2, -cr, sr)))
    fallback_rad = np.where(np.isfinite(m), 1.0, np.nan)
    s = Balls._new(np.where(ok, s.mid, 0.0), np.where(ok, s.rad, fallback_rad))
    c = Balls._new(np.where(ok, c.mid, 0.0), np.where(ok, c.rad, fallback_rad))
    return s, c


def _sin_cos_range(x: Balls) -> tuple[Balls, Balls]:
    """Balls of ``sin`` and ``cos`` over the balls ``x``: their ranges over ``[lo, hi]``.

    The point enclosures at the ends (:func:`_sin_cos_point`) bound the values there; on an
    interval shorter than pi each function has at most one critical point inside, and one
    exists only where its derivative may change sign between the ends: ``sin`` may reach its
    maximum 1 unless ``cos(lo) < 0`` or ``cos(hi) > 0`` is certain, its minimum -1 unless
    ``cos(lo) > 0`` or ``cos(hi) < 0`` is; ``cos`` likewise with ``-sin``. Intervals of length
    3 or more get ``[-1, 1]``; non-finite balls ``nan``.
    """
    lo, hi = x.lower(), x.upper()
    ok = np.isfinite(lo) & np.isfinite(hi)
    with np.errstate(invalid="ignore", over="ignore"):
        wide = ~(hi - lo < 3.0)   # fl(hi - lo) < 3 implies hi - lo < pi exactly
    n = lo.size
    s, c = _sin_cos_point(np.concatenate([np.where(ok, lo, 0.0).ravel(), np.where(ok, hi, 0.0).ravel()]))
    s0, s1, c0, c1 = s[:n], s[n:], c[:n], c[n:]

    def rng(f0: Balls, f1: Balls, max_possible: np.ndarray, min_possible: np.ndarray) -> Balls:
        top = np.where(max_possible | wide, 1.0, np.minimum(np.maximum(f0.upper(), f1.upper()), 1.0))
        bottom = np.where(min_possible | wide, -1.0, np.maximum(np.minimum(f0.lower(), f1.lower()), -1.0))
        out = from_bounds(bottom.reshape(lo.shape), top.reshape(lo.shape))
        return Balls._new(np.where(ok, out.mid, np.nan), np.where(ok, out.rad, np.nan))

    sin = rng(s0, s1, ~(c0.negative() | c1.positive()), ~(c0.positive() | c1.negative()))
    cos = rng(c0, c1, ~(s0.positive() | s1.negative()), ~(s0.negative() | s1.positive()))
    return sin, cos


def _atan_point(x: np.ndarray) -> Balls:
    """Balls containing ``atan(x)`` for finite floats ``x``.

    ``a = |x|``; ``t = a`` (``a <= 1``) or ``1 / a`` (``atan a = pi/2 - atan(1/a)``); two halvings
    ``t -> t / (1 + sqrt(1 + t^2))`` (``atan t = 2 atan t'``) bring ``t <= tan(pi/16) < 0.2``;
    the alternating series to ``t^25 / 25`` with the remainder ``t^27 / 27`` (bounded at
    ``t = 0.2``); all in ball arithmetic, so every step's rounding is enclosed.
    """
    x = np.asarray(x, dtype=float)
    a = np.abs(x)
    big = a > 1.0
    t = where(big, as_balls(1.0) / as_balls(np.where(big, a, 1.0)), as_balls(a))
    for _ in range(2):
        t = t / ((t * t + 1.0).sqrt() + 1.0)
    bad = ~(t.magnitude() <= 0.2)  # the remainder is bounded at t = 0.2 (always true)
    t2 = t * t
    s = _horner(_ATAN_C, t2) * t
    s = Balls._new(s.mid, _up(s.rad + _ATAN_REM)) * 4.0
    s = where(big, _PIO2 - s, s) * np.where(x < 0, -1.0, 1.0)
    return Balls._new(np.where(bad, np.nan, s.mid), np.where(bad, np.nan, s.rad))
