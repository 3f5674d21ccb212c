"""Rigorous enclosures: ball arithmetic (Arb) over numpy arrays, with first derivatives.

A proof that ``W' < 0`` on a whole band of states and a whole interval of azimuths needs
every quantity *enclosed*: an interval (here a ball, midpoint and radius) that contains
every value the exact function takes there, whatever the rounding. This module gives

* :class:`Jet`: a value and its gradient with respect to ``n`` inputs, each an array of
  Arb balls (:class:`flint.arb`, `python-flint <https://python-flint.readthedocs.io>`_, the
  Python interface of the FLINT/Arb library of rigorous ball arithmetic): forward-mode
  differentiation in which every operation is rigorous. Evaluating a function on a Jet whose
  value is a ball ``B`` gives a ball that contains ``f(x)`` for every ``x`` in ``B`` and a
  ball that contains every (generalised) gradient ``f'(x)``, ``x`` in ``B``. Arrays keep one
  ball per element (``numpy`` object arrays), so a whole set of azimuth intervals is
  evaluated in one call;
* :func:`symmetric_eigenvalue_bounds`: rigorous bounds of the extreme eigenvalues of every
  symmetric matrix in a ball matrix: Weyl's inequality about the midpoint matrix, whose
  eigenvalues a floating-point eigen-decomposition gives, made rigorous by Ostrowski's
  theorem and Gershgorin's discs;
* helpers that turn balls into outward-rounded floats (:func:`upper`, :func:`lower`,
  :func:`magnitude`).

Why Arb and this layout (measured on the 2-core machine, ``benchmarks/bench_intervals.py``,
issue 17 of the project): per element of numpy object arrays, an Arb product costs about
0.055 us, a sum 0.05 us, a sine 0.15 us; a hand-written numpy interval type on float arrays
(bounds, four products, min, max, ``nextafter`` outward rounding) costs 0.03, 0.009 and
0.024 us. Arb is two to six times slower per operation, and it is rigorous where the
numpy type is not: its ``sin``, ``cos``, ``atan`` and ``sqrt`` carry proved error bounds,
where the numpy type would have to assume one for the C library. The proofs need no more
speed than Arb gives: a hover proof takes seconds, the forward-flight proof of the book (the
blade's equations with Hessians on 512 azimuth intervals, with first derivatives on 4 096, a
dozen bounds tried) about four minutes.

Float balls (2026-12): every function here also takes :class:`rotorlyap.methods.balls.Balls`
(float64 arrays of midpoints and radii, Rump's midpoint-radius arithmetic, rigorous without
switching the rounding mode; ``sin``, ``cos``, ``atan`` by Taylor polynomials evaluated in that
arithmetic), and operations follow their operands' type. On arrays of thousands of balls they are
25 to 40 times faster than Arb (the forward-flight proof: 263 s with Arb, 7 s with float balls,
the same bound proved); on arrays of one element Arb stays faster. :data:`ARITHMETIC` (default
``"arb"``) and :func:`arithmetic` choose what the constructors build; the blade's proofs choose
per problem (:data:`rotorlyap.analysis.enclosure.DEFAULT_ARITHMETIC`).

Conventions: balls are :class:`flint.arb` at the default 53-bit precision; Python floats
enter exactly. An operation whose result cannot be enclosed (a division by a ball that
contains zero, a square root of a ball that reaches below zero) gives an Arb ``nan``/infinite
ball, which every bound of this module turns into ``inf``: a proof that meets one fails
there, it never silently passes.
"""

from __future__ import annotations

import math
from contextlib import contextmanager
from typing import Iterator

import numpy as np
from flint import arb

from . import balls as fb
from .balls import Balls

ARITHMETIC = "arb"
"""The arithmetic that new enclosures are built in: ``"arb"`` (numpy object arrays of
:class:`flint.arb`, the reference and the default here, so that code that fills object arrays
keeps working) or ``"balls"`` (:class:`rotorlyap.methods.balls.Balls`, float64 midpoint-radius
arrays, about ten times faster; the blade's proofs, :mod:`rotorlyap.analysis.proof`, build in it
by default). Operations follow their operands' type; this switch decides what the constructors
(:func:`balls`, :func:`hull`, :func:`zeros`, :func:`const`, ...) return. Change it with
:func:`arithmetic`."""

_ARITHMETICS = ("balls", "arb")


@contextmanager
def arithmetic(name: str) -> Iterator[None]:
    """Build enclosures in ``name`` (``"balls"`` or ``"arb"``) inside the ``with`` block."""
    global ARITHMETIC
    if name not in _ARITHMETICS:
        raise ValueError(f"arithmetic must be one of {_ARITHMETICS}, got {name!r}")
    old, ARITHMETIC = ARITHMETIC, name
    try:
        yield
    finally:
        ARITHMETIC = old


def _arb_mode() -> bool:
    return ARITHMETIC == "arb"

__all__ = [
    "ARITHMETIC", "Balls", "arithmetic", "asballs", "const", "ball", "pi", "full", "nan", "where", "stack",
    "moveaxis", "matmul", "roll", "broadcast_to", "union", "is_finite", "positive", "negative",
    "nonnegative_part", "absolute", "minimum", "atan",
    "Jet", "balls", "bivariate", "chain", "hull", "upper", "lower", "magnitude", "variables", "zeros", "sin",
    "cos", "sqrt", "symmetric_eigenvalue_bounds", "matrix_norm_upper", "norm_upper", "mid",
    "psi_intervals", "hermite_enclosure",
]

_sin = np.frompyfunc(lambda b: b.sin(), 1, 1)
_cos = np.frompyfunc(lambda b: b.cos(), 1, 1)
_sqrt = np.frompyfunc(lambda b: b.sqrt(), 1, 1)
_upper = np.frompyfunc(lambda b: float(b.upper()) if b.is_finite() else math.inf, 1, 1)
_lower = np.frompyfunc(lambda b: float(b.lower()) if b.is_finite() else -math.inf, 1, 1)
_mag = np.frompyfunc(lambda b: float(b.abs_upper()) if b.is_finite() else math.inf, 1, 1)
_mid = np.frompyfunc(lambda b: float(b.mid()) if b.is_finite() else math.nan, 1, 1)
_make = np.frompyfunc(lambda m, r: arb(float(m), float(r)), 2, 1)
_union = np.frompyfunc(lambda a, b: a.union(b), 2, 1)


def balls(mid, rad=0.0):
    """Balls of the broadcast shape of ``mid`` and ``rad`` (floats, exact), in :data:`ARITHMETIC`."""
    if not _arb_mode():
        return Balls(mid, rad)
    m, r = np.broadcast_arrays(np.asarray(mid, dtype=float), np.asarray(rad, dtype=float))
    out = _make(m, r)
    return np.asarray(out, dtype=object)


def hull(lo, hi):
    """Balls that contain the intervals ``[lo, hi]`` (floats, elementwise)."""
    lo, hi = np.broadcast_arrays(np.asarray(lo, dtype=float), np.asarray(hi, dtype=float))
    if not _arb_mode():
        return fb.from_bounds(lo, hi)
    a = balls(lo)
    b = balls(hi)
    return np.asarray(_union(a, b), dtype=object)


def _is_balls(x) -> bool:
    return isinstance(x, Balls)


def asballs(x):
    """``x`` unchanged if it is :class:`Balls`, else a numpy object array (of Arb balls)."""
    return x if isinstance(x, Balls) else np.asarray(x, dtype=object)


def const(x: float):
    """The float ``x`` as an exact scalar ball of :data:`ARITHMETIC`."""
    return arb(float(x)) if _arb_mode() else Balls(float(x))


def ball(m: float, r: float):
    """The scalar ball ``[m - r, m + r]`` (floats, exact) of :data:`ARITHMETIC`."""
    return arb(float(m), float(r)) if _arb_mode() else Balls(float(m), float(r))


def pi():
    """A scalar ball containing pi, of :data:`ARITHMETIC`."""
    return _PI if _arb_mode() else fb._PI


def full(shape, value):
    """Balls of ``shape``, each the scalar ball (or float, exact) ``value``, in the arithmetic of
    ``value`` (floats: :data:`ARITHMETIC`)."""
    if isinstance(value, Balls) or (not isinstance(value, arb) and not _arb_mode()):
        return fb.broadcast_to(fb.as_balls(value), shape)
    out = np.empty(shape, dtype=object)
    out[...] = value if isinstance(value, arb) else arb(float(value))
    return out


def nan(shape):
    """Non-finite balls of ``shape`` (no enclosure), in :data:`ARITHMETIC`."""
    if not _arb_mode():
        return Balls(np.full(shape, np.nan), np.full(shape, np.nan))
    return full(shape, arb.nan())


def where(mask, a, b):
    """Elementwise ``a`` where ``mask`` else ``b`` (balls or scalar balls of one arithmetic)."""
    if any(isinstance(x, Balls) for x in (a, b)) or (not _arb_mode() and not any(
            isinstance(x, (arb, np.ndarray)) for x in (a, b))):
        return fb.where(mask, a, b)
    return np.where(mask, a, b)


def stack(items, axis: int = 0):
    """``numpy.stack`` of balls."""
    items = list(items)
    if any(isinstance(x, Balls) for x in items):
        return fb.stack(items, axis=axis)
    return np.stack(items, axis=axis)


def moveaxis(x, source, destination):
    return fb.moveaxis(x, source, destination) if _is_balls(x) else np.moveaxis(x, source, destination)


def roll(x, shift: int, axis: int):
    return fb.roll(x, shift, axis) if _is_balls(x) else np.roll(x, shift, axis=axis)


def broadcast_to(x, shape):
    return fb.broadcast_to(x, shape) if _is_balls(x) else np.broadcast_to(x, shape)


def matmul(a, b):
    """Matrix products of balls (:func:`rotorlyap.methods.balls.matmul` for :class:`Balls`)."""
    if _is_balls(a) or _is_balls(b):
        return fb.matmul(a, b)
    return np.matmul(a, b)


def union(a, b):
    """Balls containing both balls, elementwise."""
    if _is_balls(a) or _is_balls(b):
        return fb.union(a, b)
    return np.asarray(_union(a, b), dtype=object)


_finite = np.frompyfunc(lambda b: b.is_finite(), 1, 1)
_pos = np.frompyfunc(lambda b: b > 0, 1, 1)
_neg = np.frompyfunc(lambda b: b < 0, 1, 1)
_nonneg = np.frompyfunc(lambda b: b.nonnegative_part(), 1, 1)
_abs = np.frompyfunc(abs, 1, 1)
_atan = np.frompyfunc(lambda b: b.atan(), 1, 1)


def _bool(x, fun) -> np.ndarray:
    x = np.asarray(x, dtype=object)
    return np.asarray(fun(x), dtype=bool).reshape(x.shape) if x.size else np.zeros(x.shape, dtype=bool)


def is_finite(x) -> np.ndarray:
    """True where the ball is finite (an enclosure)."""
    return x.finite() if _is_balls(x) else _bool(x, _finite)


def positive(x) -> np.ndarray:
    """True where every point of the ball is ``> 0``."""
    return x.positive() if _is_balls(x) else _bool(x, _pos)


def negative(x) -> np.ndarray:
    """True where every point of the ball is ``< 0``."""
    return x.negative() if _is_balls(x) else _bool(x, _neg)


def nonnegative_part(x):
    """Balls of ``max(x, 0)``."""
    return x.nonnegative_part() if _is_balls(x) else np.asarray(_nonneg(x), dtype=object)


def absolute(x):
    """Balls of ``|x|``."""
    return abs(x) if _is_balls(x) else np.asarray(_abs(x), dtype=object)


def minimum(x, cap: float):
    """Balls of ``min(x, cap)`` for a float ``cap``."""
    if _is_balls(x):
        return x.minimum(cap)
    return np.asarray(np.frompyfunc(lambda b: b.min(arb(cap)), 1, 1)(x), dtype=object)


def atan(x):
    """Balls of ``atan(x)`` (elementwise, no derivatives)."""
    return x.atan() if _is_balls(x) else np.asarray(_atan(x), dtype=object)


def _float_array(x, fun) -> np.ndarray:
    x = np.asarray(x, dtype=object)
    if x.size == 0:
        return np.zeros(x.shape)
    return np.asarray(fun(x), dtype=float).reshape(x.shape)


def upper(x) -> np.ndarray:
    """Floats ``>=`` every point of each ball (outward rounded; ``inf`` for a non-finite ball)."""
    if _is_balls(x):
        return x.upper()
    return np.nextafter(_float_array(x, _upper), np.inf)


def lower(x) -> np.ndarray:
    """Floats ``<=`` every point of each ball (outward rounded; ``-inf`` for a non-finite ball)."""
    if _is_balls(x):
        return x.lower()
    return np.nextafter(_float_array(x, _lower), -np.inf)


def magnitude(x) -> np.ndarray:
    """Floats ``>=`` ``|v|`` for every point ``v`` of each ball (``inf`` if non-finite)."""
    if _is_balls(x):
        return x.magnitude()
    return np.nextafter(_float_array(x, _mag), np.inf)


def mid(x) -> np.ndarray:
    """The midpoints of the balls as floats (not a bound: for decompositions only)."""
    if _is_balls(x):
        return np.where(x.finite(), x.mid, np.nan)
    return _float_array(x, _mid)


# --------------------------------------------------------------------------------------
# Jets: a value and its gradient, every entry a ball
# --------------------------------------------------------------------------------------


def _outer(a, b):
    """``a_i b_j`` for gradients (n, N): shape (n, n, N)."""
    return a[:, None] * b[None, :]


def _sym_outer(a, b):
    """``a b^T + b a^T`` for gradients (n, N): shape (n, n, N)."""
    o = _outer(a, b)
    return o + np.swapaxes(o, 0, 1)


def _add(x, y):
    if x is None:
        return y
    if y is None:
        return x
    return x + y


class Jet:
    """A function value, its gradient and (optionally) its Hessian, enclosed by balls.

    Attributes
    ----------
    v : numpy.ndarray of arb, shape (N,)
        The value, one ball per element (per azimuth interval).
    d : numpy.ndarray of arb, shape (n, N), or None
        The gradient with respect to the ``n`` inputs; None for a quantity that does not
        depend on them.
    h : numpy.ndarray of arb, shape (n, n, N), or None
        The Hessian (second order, see :func:`variables`); None for first-order Jets and for
        quantities linear in the inputs.

    Arithmetic with floats, balls, arrays of balls (shape (N,)) and other Jets follows the
    rules of differentiation; ``math``-like functions are :func:`sin`, :func:`cos` and
    :func:`sqrt`. Python floats enter exactly; numpy floats are converted to Python floats.
    """

    __slots__ = ("v", "d", "h")
    __array_ufunc__ = None  # numpy defers to the Jet's operators

    def __init__(self, v, d=None, h=None):
        self.v = v
        self.d = d
        self.h = h

    @staticmethod
    def _c(o):
        """A constant operand as something that multiplies object arrays exactly."""
        if isinstance(o, (np.floating, np.integer)):
            return float(o)
        return o

    # -------------------------------------------------------------- + -
    def __add__(self, o):
        if isinstance(o, Jet):
            return Jet(self.v + o.v, _add(self.d, o.d), _add(self.h, o.h))
        return Jet(self.v + self._c(o), self.d, self.h)

    __radd__ = __add__

    def __neg__(self):
        return Jet(-self.v, None if self.d is None else -self.d, None if self.h is None else -self.h)

    def __pos__(self):
        return self

    def __sub__(self, o):
        if isinstance(o, Jet):
            return self + (-o)
        return Jet(self.v - self._c(o), self.d, self.h)

    def __rsub__(self, o):
        return (-self) + o

    # -------------------------------------------------------------- * /
    def _scale(self, c):
        return Jet(self.v * c, None if self.d is None else self.d * c, None if self.h is None else self.h * c)

    def __mul__(self, o):
        if not isinstance(o, Jet):
            return self._scale(self._c(o))
        if o.d is None and o.h is None:
            return self._scale(o.v)
        if self.d is None and self.h is None:
            return o._scale(self.v)
        d = _add(None if self.d is None else self.d * o.v, None if o.d is None else o.d * self.v)
        h = None
        if self.h is not None or o.h is not None:  # second order (variables(order=2) carry Hessians)
            h = _add(None if self.h is None else self.h * o.v, None if o.h is None else o.h * self.v)
            if self.d is not None and o.d is not None:
                h = _add(h, _sym_outer(self.d, o.d))
        return Jet(self.v * o.v, d, h)

    __rmul__ = __mul__

    def reciprocal(self) -> "Jet":
        """``1 / self`` (a ball containing zero gives a non-finite result)."""
        r = 1 / self.v
        return chain(self, r, -(r * r), 2 * r * r * r)

    def __truediv__(self, o):
        if isinstance(o, Jet):
            if o.d is None and o.h is None:
                return self._scale(1 / o.v)
            return self * o.reciprocal()
        o = self._c(o)
        return Jet(self.v / o, None if self.d is None else self.d / o, None if self.h is None else self.h / o)

    def __rtruediv__(self, o):
        return self.reciprocal()._scale(self._c(o))

    def gradient(self, n: int):
        """The gradient as (n, N) balls (zeros where the Jet has none)."""
        if self.d is not None:
            return self.d
        return _zeros_like(self.v, (n,) + np.shape(self.v))

    def hessian(self, n: int):
        """The Hessian as (n, n, N) balls (zeros where the Jet has none)."""
        if self.h is not None:
            return self.h
        return _zeros_like(self.v, (n, n) + np.shape(self.v))


def zeros(shape):
    """Exact zero balls of :data:`ARITHMETIC`."""
    if not _arb_mode():
        return Balls(np.zeros(shape))
    out = np.empty(shape, dtype=object)
    out[...] = arb(0)
    return out


def _zeros_like(ref, shape):
    """Exact zero balls of the arithmetic of ``ref``."""
    if _is_balls(ref):
        return Balls(np.zeros(shape))
    with arithmetic("arb"):
        return zeros(shape)


def chain(x: Jet, f, f1, f2=None) -> Jet:
    """``g(x)`` from its value ``f``, first derivative ``f1`` and second ``f2`` (balls, (N,))
    at ``x``: the chain rule to first or second order (``f2=None``: the second derivative is
    not taken, as for a piecewise-linear ``g`` whose slope is frozen)."""
    if x.d is None:
        return Jet(f, None, None)
    d = x.d * f1
    h = None
    if x.h is not None:
        h = x.h * f1
        if f2 is not None:
            h = h + _outer(x.d, x.d) * f2
    return Jet(f, d, h)


def bivariate(x: Jet, y: Jet, f, fx, fy, fxx=None, fyy=None, fxy=None) -> Jet:
    """``g(x, y)`` from its value and partial derivatives (balls, (N,)) at ``(x, y)``."""
    if x.d is None and y.d is None:
        return Jet(f)
    n = (x.d if x.d is not None else y.d).shape[0]
    dx, dy = x.gradient(n), y.gradient(n)
    d = dx * fx + dy * fy
    h = None
    if x.h is not None or y.h is not None:
        h = x.hessian(n) * fx + y.hessian(n) * fy
        if fxx is not None:
            h = h + _outer(dx, dx) * fxx + _outer(dy, dy) * fyy + _sym_outer(dx, dy) * fxy
    return Jet(f, d, h)


def variables(values, order: int = 1) -> list[Jet]:
    """The inputs themselves: ``values`` a list of ``n`` arrays of balls (shape (N,)); the
    gradient of the i-th is the i-th unit vector; ``order=2`` carries Hessians (zero)."""
    if order not in (1, 2):
        raise ValueError(f"order must be 1 or 2, got {order!r}")
    n = len(values)
    out = []
    for i, v in enumerate(values):
        if _is_balls(v):
            unit = np.zeros((n,) + v.shape)
            unit[i, ...] = 1.0
            out.append(Jet(v, Balls(unit), Balls(np.zeros((n, n) + v.shape)) if order == 2 else None))
            continue
        v = np.asarray(v, dtype=object)
        d = _zeros_like(v, (n,) + v.shape)
        d[i, ...] = arb(1)
        out.append(Jet(v, d, _zeros_like(v, (n, n) + v.shape) if order == 2 else None))
    return out


def _apply(x, fv, f1, f2, fballs=None):
    """``g(x)`` for a Jet, a ball array or a float: ``fv(v)`` the value, ``f1(v, g)`` and
    ``f2(v, g)`` the derivatives (Arb object arrays); ``fballs(v) -> (g, g1, g2)`` the same for
    :class:`Balls` (``g2`` may be None)."""
    v = x.v if isinstance(x, Jet) else x
    if _is_balls(v) or (fballs is not None and not _arb_mode() and not isinstance(v, (arb, np.ndarray))):
        v = fb.as_balls(v)
        if not isinstance(x, Jet):
            return fballs(v, False)[0]
        if x.d is None:
            return Jet(fballs(v, False)[0])
        g, g1, g2 = fballs(v, x.h is not None)
        return chain(x, g, g1, g2)
    if isinstance(x, Jet):
        g = np.asarray(fv(x.v), dtype=object)
        if x.d is None:
            return Jet(g)
        return chain(x, g, np.asarray(f1(x.v, g), dtype=object),
                      None if x.h is None else np.asarray(f2(x.v, g), dtype=object))
    if isinstance(x, np.ndarray):
        return np.asarray(fv(x), dtype=object)
    b = x if isinstance(x, arb) else arb(float(x))
    return fv(np.asarray([b], dtype=object))[0]


def _sin_balls(v: Balls, second: bool):
    s, c = v.sin_cos()
    return s, c, -s


def _cos_balls(v: Balls, second: bool):
    s, c = v.sin_cos()
    return c, -s, -c


def _sqrt_balls(v: Balls, second: bool):
    s = v.sqrt()
    if second:
        r = s.reciprocal()
        return s, r * 0.5, r * r * r * -0.25
    return s, s.reciprocal() * 0.5, None


def sin(x):
    """Rigorous ``sin`` of a Jet, a ball array or a float."""
    return _apply(x, _sin, lambda v, s: _cos(v), lambda v, s: -s, _sin_balls)


def cos(x):
    """Rigorous ``cos`` of a Jet, a ball array or a float."""
    return _apply(x, _cos, lambda v, c: -_sin(v), lambda v, c: -c, _cos_balls)


def sqrt(x):
    """Rigorous ``sqrt`` (a ball reaching below zero gives a non-finite result)."""
    return _apply(x, _sqrt, lambda v, s: 0.5 / s, lambda v, s: -0.25 / (s * s * s), _sqrt_balls)


class JetMath:
    """Stands for the ``math`` module in generated scalar code evaluated on Jets."""

    sin = staticmethod(sin)
    cos = staticmethod(cos)
    sqrt = staticmethod(sqrt)


# --------------------------------------------------------------------------------------
# Azimuth intervals and piecewise cubic interpolants
# --------------------------------------------------------------------------------------

_PI = arb.pi()
_TWO_PI = 2 * _PI


def psi_intervals(n: int):
    """Balls containing the ``n`` uniform azimuth intervals ``[2 pi k / n, 2 pi (k + 1) / n]`` of
    one period, shape (n,)."""
    k = np.arange(n, dtype=float)
    return hull(k / n, (k + 1) / n) * (pi() * 2.0)


def hermite_enclosure(values: np.ndarray, slopes: np.ndarray, n: int, *, centre: bool = False,
                      second: bool = False, third: bool = False):
    """Enclosures of a periodic piecewise cubic Hermite interpolant and of its derivatives.

    The interpolant of ``values`` and ``slopes`` (shape ``(K,) + s``) on the grid
    ``2 pi j / K`` of one period ``2 pi``, evaluated on ``n`` uniform azimuth intervals, in
    the monomial form about the left knot of each piece,
    ``p(t) = P0 + t B0 + t^2 (3 dP - 2 B0 - B1) + t^3 (B0 + B1 - 2 dP)`` with ``t`` the
    position in the piece, ``B = h slope``, ``dP = P1 - P0``: the same polynomial as
    ``TabulatedMotion.xi`` of :mod:`rotorlyap.model.steady` and the ``"hermite"`` interpolant of
    :func:`rotorlyap.methods.periodic_lyapunov`, in a form whose ball evaluation is tight (its
    coefficients are of the size of the change over a piece, not of the values). With ``n``
    a divisor of ``K`` each interval spans several pieces and gets the hull of their balls.

    Parameters
    ----------
    values, slopes : numpy.ndarray
        Grid values and derivatives (per rad).
    n : int
        Azimuth intervals (a multiple or a divisor of ``K``).
    centre : bool
        Evaluate at the midpoints of the intervals instead of over them (``n`` a multiple of ``K``).
    second, third : bool
        Also return the second (and the third) derivative.

    Returns
    -------
    value, derivative[, second[, third derivative]] : numpy.ndarray of arb, shape ``(n,) + s``
        Derivatives with respect to the azimuth (per rad, per rad^2).
    """
    values = np.asarray(values, dtype=float)
    slopes = np.asarray(slopes, dtype=float)
    K = values.shape[0]
    if n < K and K % n == 0 and not centre:  # coarse intervals: the hull of the pieces each one spans
        parts = hermite_enclosure(values, slopes, K, second=second, third=third)
        return tuple(_hull_groups(p, K // n) for p in parts)
    if n % K:
        raise ValueError(f"the number of azimuth intervals ({n}) must be a multiple or a divisor "
                         f"of the grid ({K})")
    sub = n // K
    h = _TWO_PI / K
    P0 = balls(values)
    P1 = roll(P0, -1, axis=0)
    B0 = balls(slopes) * h
    B1 = roll(B0, -1, axis=0)
    dP = P1 - P0
    c2 = 3 * dP - 2 * B0 - B1
    c3 = B0 + B1 - 2 * dP
    j = np.arange(n) // sub
    s = np.arange(n) % sub
    t = balls((s + 0.5) / sub) if centre else hull(s / sub, (s + 1) / sub)
    t = t.reshape((n,) + (1,) * (values.ndim - 1))
    P0, B0, c2, c3 = P0[j], B0[j], c2[j], c3[j]
    value = P0 + t * (B0 + t * (c2 + t * c3))
    deriv = (B0 + t * (2 * c2 + t * (3 * c3))) / h
    if not (second or third):
        return value, deriv
    second_deriv = (2 * c2 + t * (6 * c3)) / (h * h)
    if not third:
        return value, deriv, second_deriv
    return value, deriv, second_deriv, broadcast_to(6 * c3 / (h * h * h), value.shape)


def _hull_groups(x: np.ndarray, group: int) -> np.ndarray:
    """Balls containing each run of ``group`` consecutive balls along the first axis."""
    x = x.reshape((x.shape[0] // group, group) + x.shape[1:])
    if _is_balls(x):
        return fb.from_bounds(x.lower().min(axis=1), x.upper().max(axis=1))
    out = x[:, 0]
    for i in range(1, group):
        out = np.asarray(_union(out, x[:, i]), dtype=object)
    return out


# --------------------------------------------------------------------------------------
# Matrices of balls
# --------------------------------------------------------------------------------------


def _sum_up(x, axis) -> np.ndarray:
    """An upper bound of the exact sum of the non-negative floats ``x`` along ``axis``: the
    float sum's error is at most ``(k - 1) u`` times the sum for ``k`` terms (``u = 2**-53``),
    far below the relative ``1e-12`` added here for any ``k`` below a thousand."""
    return np.nextafter(np.sum(x, axis=axis) * (1.0 + 1e-12), np.inf)


def norm_upper(x, axis=-1) -> np.ndarray:
    """An upper bound of the Euclidean (Frobenius) norm along ``axis`` of every array in the
    balls ``x``: the norm of the entrywise magnitudes."""
    mag = magnitude(x)
    return np.nextafter(np.sqrt(_sum_up(np.nextafter(mag * mag, np.inf), axis=axis)), np.inf)


def matrix_norm_upper(M) -> np.ndarray:
    """An upper bound of the spectral norm of every matrix in the ball matrices ``M``
    (shape (..., n, n)): the Frobenius norm of the entrywise magnitudes."""
    return norm_upper(M, axis=(-2, -1))


def _point_eigenvalue_bounds(C: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Rigorous bounds of the extreme eigenvalues of the exactly symmetric float matrices ``C``
    (N, n, n): Ostrowski's theorem and Gershgorin's discs on ``V^T C V`` in ball arithmetic, with
    ``V`` the floating-point eigenvectors (any accuracy: the off-diagonal balls of ``V^T C V`` are
    then of round-off size, whichever eigenvectors a LAPACK returns for close eigenvalues)."""
    n = C.shape[-1]
    _, V = np.linalg.eigh(C)
    Vb = balls(V)
    Vt = np.swapaxes(Vb, -1, -2)
    B = matmul(matmul(Vt, balls(C)), Vb)
    E = matmul(Vt, Vb) - np.eye(n)
    e = matrix_norm_upper(E)
    diag = B[:, np.arange(n), np.arange(n)]
    mag = magnitude(B)
    mag[:, np.arange(n), np.arange(n)] = 0.0
    radius = _sum_up(mag, axis=-1)
    g_hi = np.nextafter(upper(diag) + radius, np.inf).max(axis=-1)
    g_lo = np.nextafter(lower(diag) - radius, -np.inf).min(axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        lo_den = np.nextafter(1.0 - e, -np.inf)
        hi_den = np.nextafter(1.0 + e, np.inf)
        hi = np.where(g_hi >= 0, np.nextafter(g_hi / lo_den, np.inf), np.nextafter(g_hi / hi_den, np.inf))
        lo = np.where(g_lo >= 0, np.nextafter(g_lo / hi_den, -np.inf), np.nextafter(g_lo / lo_den, -np.inf))
    ok = (e < 0.5) & np.isfinite(hi) & np.isfinite(lo)
    return np.where(ok, lo, -np.inf), np.where(ok, hi, np.inf)


def symmetric_eigenvalue_bounds(M) -> tuple[np.ndarray, np.ndarray]:
    """Bounds of the smallest and largest eigenvalue of every symmetric matrix in ``M``.

    Parameters
    ----------
    M : numpy.ndarray of arb, shape (N, n, n)
        Ball matrices (the bounds hold for the symmetric matrices inside each).

    Returns
    -------
    lo, hi : numpy.ndarray, shape (N,)
        ``lo <= lambda_min(S)`` and ``lambda_max(S) <= hi`` for every symmetric ``S`` in the
        ball ``M[k]`` (``-inf``/``inf`` where no bound follows).

    Notes
    -----
    Weyl's inequality splits the ball into its centre and its spread: with ``C`` the symmetric
    float matrix of the midpoints (upper triangle mirrored) and ``R`` bounds of ``|S - C|``
    entrywise (the magnitudes of the balls ``M - C``), every eigenvalue of ``S`` lies within
    ``rho(R)`` of one of ``C`` (``||S - C||_2 <= rho(R)`` for the non-negative ``R``, bounded by
    the smaller of its largest row sum and its Frobenius norm). The eigenvalues of ``C`` are
    bounded by :func:`_point_eigenvalue_bounds`. Both steps are independent of which
    eigenvectors the floating-point eigen-solver returns (they are arbitrary where eigenvalues
    are close, as for ``-Q`` with ``Q = I``), so the bounds are the same, to round-off, on
    every machine.
    """
    M = asballs(M)
    n = M.shape[-1]
    C = mid(M)
    iu = np.triu_indices(n, 1)
    C[:, iu[1], iu[0]] = C[:, iu[0], iu[1]]
    bad = ~np.all(np.isfinite(C), axis=(-2, -1))
    C[bad] = 0.0
    with arithmetic("balls" if _is_balls(M) else "arb"):
        R = magnitude(M - balls(C))
        spread = np.minimum(_sum_up(R, axis=-1).max(axis=-1), matrix_norm_upper(M - balls(C)))
        lo_c, hi_c = _point_eigenvalue_bounds(C)
    hi = np.nextafter(hi_c + spread, np.inf)
    lo = np.nextafter(lo_c - spread, -np.inf)
    return np.where(bad, -np.inf, lo), np.where(bad, np.inf, hi)
