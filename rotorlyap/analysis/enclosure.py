"""The blade's equations in ball arithmetic: enclosures of the right-hand side and its Jacobian.

:class:`BladeEnclosure` evaluates the disturbed equations ``x' = h(psi, xi(psi) + x) - xi'(psi)``
of :mod:`rotorlyap.model.steady` on *balls* (:mod:`rotorlyap.methods.intervals`): for arrays of
azimuth intervals and boxes of disturbances it returns balls that contain every value of the
right-hand side and every (generalised) Jacobian there. These are the facts a proof of
``W' < 0`` (:mod:`rotorlyap.methods.proof`) is made of.

The model enclosed
------------------
The same formulas as the compiled kernel (:mod:`rotorlyap.model.compiled`), in exact arithmetic:

* the generated Lagrangian terms (``_generated/blade_scalar.py``, run with the functions of
  :class:`rotorlyap.methods.intervals.JetMath` in place of ``math`` and the parameters as exact
  balls, so that no product of two parameters is rounded);
* the strip loads: wind, angle of attack ``atan2(u_z, -u_y)`` on a branch continuous over each
  ball (the airfoil table is periodic in the angle, so any branch gives the same loads), the
  airfoil table as the periodic piecewise-linear interpolant of its node values on the grid
  ``-pi + 2 pi k / n`` (:meth:`rotorlyap.model.airfoil.Airfoil.table_rows`, or the same rows of a
  Mach-independent C81 table, :meth:`rotorlyap.model.c81.C81Section.table_rows`, whose grid holds
  every angle of the table, so that every kink of the table is a node; the float kernel
  evaluates it to round-off), its slope over a ball the hull of the slopes of the segments the
  ball touches (the generalised derivative at a kink); the Prandtl-Glauert factor with its
  cap and Lock's drag rise for compressible sections;
* the steady motion and its derivative as the piecewise cubic Hermite interpolant of
  :class:`rotorlyap.model.steady.TabulatedMotion` (or a constant state), with period ``2 pi``.

What cannot be enclosed is reported, not hidden: a ball in which the relative wind may vanish
(the angle of attack is undefined), or in which the angle of attack of a compressible section
crosses +-90 deg (the Prandtl-Glauert factor jumps there, so the equations are not Lipschitz),
marks its azimuth interval in :attr:`Evaluation.blocked` with the reason.
"""

from __future__ import annotations

import math
import types
from dataclasses import dataclass

import numpy as np
from flint import arb

from ..methods import intervals as iv
from ..methods.balls import Balls
from ..methods.intervals import Jet, hermite_enclosure, psi_intervals
from ..model import compiled as _compiled
from ..model._generated import blade_scalar as _scalar
from ..model.compiled import (_ACTIVE, _C0, _C1, _C2, _COMPRESSIBLE, _CYCLIC, _DN, _IA, _IB, _INV_A,
                              _MACH_CAP, _MCRIT0, _MN, _MUVR, _OMEGA, _PHI, _PITCH_DAMPED, _QN, _RX,
                              _RY, _RZ, _TWISTED, _UNIFORM, _WY, _WZ)
from ..model.compressibility import WAVE_DRAG_FACTOR
from ..model.equations import solve_sym3
from ..model.steady import TabulatedMotion, as_steady_motion

__all__ = ["BladeEnclosure", "DEFAULT_ARITHMETIC", "Evaluation"]

DEFAULT_ARITHMETIC = "auto"
"""The arithmetic of :class:`BladeEnclosure` when none is given: ``"balls"`` (float balls,
:mod:`rotorlyap.methods.balls`), ``"arb"`` (Arb balls in object arrays, the reference) or
``"auto"``: Arb where the equations do not depend on the azimuth (:attr:`BladeEnclosure.constant`,
hover: one interval, arrays of one element, where Arb's cost per element beats numpy's cost per
call; measured 0.35 s against 0.75 s for a Table I hover proof), float balls elsewhere (the
forward-flight proof: 4 096 intervals, about 25 times faster than Arb)."""

_PI = arb.pi()
_TWO_PI = 2 * _PI

# the generated code with ball functions for ``math``
_rhs_terms = types.FunctionType(_scalar.rhs_terms_into.__code__,
                                {**_scalar.rhs_terms_into.__globals__, "math": iv.JetMath},
                                "rhs_terms_into_balls")


@dataclass(frozen=True)
class Evaluation:
    """Balls of the disturbed right-hand side on azimuth intervals and disturbance boxes.

    Attributes
    ----------
    value : balls (Balls or object array of arb), shape (N, 6)
        ``x'`` (rad/rad, rad/rad^2) for every azimuth and disturbance in the boxes.
    jacobian : balls (Balls or object array of arb), shape (N, 6, 6)
        ``d x' / d x``: every Jacobian (at kinks of the airfoil table: every generalised
        Jacobian) in the boxes.
    hessian : balls (Balls or object array of arb), shape (N, 6, 6, 6), or None
        ``order=2``: ``d^2 x'_i / dx_j dx_k`` in the boxes, with the slopes of the piecewise-linear
        pieces frozen at their hulls over the box (module docstring of :mod:`rotorlyap.methods.proof`).
    blocked : dict
        ``{reason: boolean array (N,)}``: intervals where the enclosure is not valid; the
        balls there are non-finite.
    slopes : list
        The slope balls of the piecewise-linear pieces, in the order of evaluation.
    """

    value: np.ndarray
    jacobian: np.ndarray
    hessian: np.ndarray | None
    blocked: dict
    slopes: list


class _Table:
    """The airfoil table as a periodic piecewise-linear function of the angle, in balls.

    One lookup gives the three coefficients over an array of angle balls: the segments each
    ball touches found in floats (outward rounded), the values and slopes over them as the
    hull of the node values and of the segment slopes (every float difference of two nodes is
    within one unit in the last place of the exact one); where a ball lies in one segment, the
    interpolant itself in ball arithmetic."""

    _GATHER = 1 << 22  # node indices gathered at once (memory of a chunk of wide balls)

    def __init__(self, rows: np.ndarray):
        self.n = rows.shape[0]
        self.nodes = [np.append(rows[:, 2 * c], rows[0, 2 * c]) for c in range(3)]  # periodic closure
        diff = [np.diff(v) for v in self.nodes]
        self.d_lo = [np.nextafter(d, -np.inf) for d in diff]
        self.d_hi = [np.nextafter(d, np.inf) for d in diff]
        self.fac = iv.const(self.n) / iv.pi() * 0.5  # segments per rad
        # the hull over the whole period (a ball wider than the period touches every segment)
        self.whole = [(iv.hull(v.min(), v.max())[()], iv.hull(lo.min(), hi.max())[()] * self.fac)
                      for v, lo, hi in zip(self.nodes, self.d_lo, self.d_hi)]

    def _spans(self, lo_f: np.ndarray, hi_f: np.ndarray, many: np.ndarray):
        """For the balls ``many`` that touch several segments (``lo_f``, ``hi_f`` their first and
        last segment, floats): chunks of at most ``_GATHER`` gathered nodes, each ``(idx, hulls)``
        with ``idx`` positions in ``lo_f`` and per coefficient the floats ``(smallest node value,
        largest node value, smallest segment slope, largest segment slope)`` over each ball's
        segments (slopes per segment, outward rounded)."""
        n = self.n
        start = 0
        while start < many.size:
            span = (hi_f[many[start:]] - lo_f[many[start:]]).astype(np.int64) + 1
            stop = start + max(1, int(np.searchsorted(np.cumsum(span), self._GATHER)))
            idx = many[start:stop]
            k = span[:stop - start]
            first = lo_f[idx].astype(np.int64)
            seg_start = np.concatenate([[0], np.cumsum(k)[:-1]])
            seg = (np.repeat(first, k) + np.arange(k.sum()) - np.repeat(seg_start, k)) % n
            node_start = np.concatenate([[0], np.cumsum(k + 1)[:-1]])
            node = (np.repeat(first, k + 1) + np.arange((k + 1).sum()) - np.repeat(node_start, k + 1)) % n
            hulls = []
            for c in range(3):
                v = self.nodes[c][node]
                hulls.append((np.minimum.reduceat(v, node_start), np.maximum.reduceat(v, node_start),
                              np.minimum.reduceat(self.d_lo[c][seg], seg_start),
                              np.maximum.reduceat(self.d_hi[c][seg], seg_start)))
            yield idx, hulls
            start = stop

    def _lookup_balls(self, alpha: Balls) -> list:
        """:meth:`lookup` for float balls: the same cases, vectorised."""
        shape, flat = alpha.shape, alpha.reshape(-1)
        n, m = self.n, flat.size
        vm = [[np.full(m, np.nan) for _ in range(4)] for _ in range(3)]  # value mid, rad, slope mid, rad
        finite = flat.finite()
        f = np.flatnonzero(finite)
        s = (flat[f] + iv.pi()) * self.fac
        lo_f, hi_f = np.floor(s.lower()), np.floor(s.upper())
        whole = hi_f - lo_f >= n

        def put(c, idx, val, slope):
            val, slope = Balls._new(np.broadcast_to(val.mid, idx.shape), np.broadcast_to(val.rad, idx.shape)), \
                Balls._new(np.broadcast_to(slope.mid, idx.shape), np.broadcast_to(slope.rad, idx.shape))
            vm[c][0][idx], vm[c][1][idx], vm[c][2][idx], vm[c][3][idx] = val.mid, val.rad, slope.mid, slope.rad

        for c in range(3):
            put(c, f[whole], self.whole[c][0], self.whole[c][1])
        one = ~whole & (lo_f == hi_f)
        if one.any():  # inside one segment: the interpolant in ball arithmetic
            lo = lo_f[one]
            i = lo.astype(np.int64) % n
            frac = s[one] - lo
            for c in range(3):
                v0 = Balls(self.nodes[c][i])
                dv = Balls(self.nodes[c][i + 1]) - v0
                put(c, f[one], v0 + frac * dv, dv * self.fac)
        for idx, hulls in self._spans(lo_f, hi_f, np.flatnonzero(~whole & ~one)):
            for c, (vmin, vmax, dmin, dmax) in enumerate(hulls):
                put(c, f[idx], iv.hull(vmin, vmax), iv.hull(dmin, dmax) * self.fac)
        return [(Balls._new(a.reshape(shape), b.reshape(shape)), Balls._new(d.reshape(shape), e.reshape(shape)))
                for a, b, d, e in vm]

    def lookup(self, alpha) -> list:
        """``[(value, slope), ...]`` balls (per rad) of cl, cd and cm over the angle balls ``alpha``."""
        if isinstance(alpha, Balls):
            return self._lookup_balls(alpha)
        alpha = np.asarray(alpha, dtype=object)
        shape, flat = alpha.shape, alpha.reshape(-1)
        n, m = self.n, flat.size
        out = [(iv.zeros(m), iv.zeros(m)) for _ in range(3)]
        finite = np.asarray(_finite(flat), dtype=bool) if m else np.zeros(0, dtype=bool)
        for val, slope in out:
            val[~finite] = arb.nan()
            slope[~finite] = arb.nan()
        f = np.flatnonzero(finite)
        s = (flat[f] + _PI) * self.fac
        lo_f, hi_f = np.floor(iv.lower(s)), np.floor(iv.upper(s))
        whole = hi_f - lo_f >= n
        for c, (val, slope) in enumerate(out):
            val[f[whole]] = self.whole[c][0]
            slope[f[whole]] = self.whole[c][1]
        one = ~whole & (lo_f == hi_f)
        if one.any():  # inside one segment: the interpolant in ball arithmetic
            lo = lo_f[one]
            i = lo.astype(np.int64) % n
            frac = s[one] - lo
            for c, (val, slope) in enumerate(out):
                v0 = iv.balls(self.nodes[c][i])
                dv = iv.balls(self.nodes[c][i + 1]) - v0
                val[f[one]] = v0 + frac * dv
                slope[f[one]] = dv * self.fac
        for idx, hulls in self._spans(lo_f, hi_f, np.flatnonzero(~whole & ~one)):
            for c, ((val, slope), (vmin, vmax, dmin, dmax)) in enumerate(zip(out, hulls)):
                val[f[idx]] = iv.hull(vmin, vmax)
                slope[f[idx]] = iv.hull(dmin, dmax) * self.fac
        return [(val.reshape(shape), slope.reshape(shape)) for val, slope in out]

    def __call__(self, alpha: Jet, tape: "_Slopes") -> tuple:
        """cl, cd and cm (Jets) at the angle ``alpha``, their slopes recorded in that order."""
        return tuple(_piecewise_linear(alpha, val, slope, tape) for val, slope in self.lookup(alpha.v))


_finite = np.frompyfunc(lambda b: b.is_finite(), 1, 1)


def _angle_balls(uz: Balls, uy: Balls) -> Balls:
    """:func:`_angle_value` for float balls, vectorised: the same branches."""
    X = -uy
    right = X.positive()
    up = ~right & uz.positive()
    down = ~right & ~up & uz.negative()
    left = ~right & ~up & ~down & X.negative()
    by_x = right | left
    with np.errstate(all="ignore"):
        ratio = iv.where(by_x, uz, uy) / iv.where(by_x, X, iv.where(up | down, uz, 1.0))
    half = iv.pi() * 0.5
    offset = iv.where(right, 0.0, iv.where(up, half, iv.where(down, -half, iv.pi())))
    out = ratio.atan() + offset
    ok = right | up | down | left
    return Balls._new(np.where(ok, out.mid, np.nan), np.where(ok, out.rad, np.nan))


def _angle_value(uz: arb, uy: arb) -> arb:
    """``atan2(uz, -uy)`` on a branch continuous over the balls (mod 2 pi); nan if the relative
    wind may vanish."""
    X = -uy
    if X > 0:
        return (uz / X).atan()
    if uz > 0:
        return _PI / 2 + (uy / uz).atan()
    if uz < 0:
        return -_PI / 2 + (uy / uz).atan()
    if X < 0:
        return _PI + (uz / X).atan()
    return arb.nan()


_angle = np.frompyfunc(_angle_value, 2, 1)


def _select(mask, a: Jet, b: Jet, n: int) -> Jet:
    """Elementwise ``a`` where ``mask`` else ``b`` (gradients and Hessians filled in)."""
    v = iv.where(mask, a.v, b.v)
    d = iv.where(mask[None, :], a.gradient(n), b.gradient(n))
    h = None
    if a.h is not None or b.h is not None:
        h = iv.where(mask[None, None, :], a.hessian(n), b.hessian(n))
    return Jet(v, d, h)


def _pos4(x: Jet) -> Jet:
    """``max(x, 0)**4`` (twice continuously differentiable)."""
    p = iv.nonnegative_part(x.v)
    p2 = p * p
    return iv.chain(x, p2 * p2, 4 * p2 * p, 12 * p2)


class _Slopes:
    """The slopes of the piecewise-linear pieces of the model (airfoil table, ``|cl|``, the Mach
    cap), in the order of evaluation: recorded over a box, replayed at its centre."""

    def __init__(self, replay=None):
        self.record = [] if replay is None else None
        self._replay = None if replay is None else iter(replay)

    def __call__(self, slope):
        if self._replay is not None:
            return next(self._replay)
        self.record.append(slope)
        return slope


def _piecewise_linear(x: Jet, value, slope, tape: _Slopes) -> Jet:
    """A piecewise-linear function of ``x``: its value, and as derivative the ball ``slope`` of
    the slopes it takes over the ball of ``x`` (or, when ``tape`` replays, over the box recorded
    before); its second derivative is not taken (the slope is frozen, module docstring)."""
    slope = tape(iv.asballs(slope))
    return iv.chain(x, iv.asballs(value), slope, None)


def _abs(x: Jet, tape: _Slopes) -> Jet:
    """``|x|``: slope +-1 where the sign is certain, the ball [-1, 1] elsewhere."""
    pos, neg = iv.positive(x.v), iv.negative(x.v)
    slope = iv.where(pos, iv.const(1), iv.where(neg, iv.const(-1), iv.ball(0, 1)))
    return _piecewise_linear(x, iv.absolute(x.v), slope, tape)


def _min_const(x: Jet, cap: float, tape: _Slopes) -> Jet:
    """``min(x, cap)``: slope 1 below, 0 above, the ball [0, 1] where ``x`` may reach ``cap``."""
    below = iv.upper(x.v) < cap if isinstance(x.v, Balls) else \
        np.asarray(np.frompyfunc(lambda b: b < cap, 1, 1)(x.v), dtype=bool)
    above = iv.lower(x.v) > cap if isinstance(x.v, Balls) else \
        np.asarray(np.frompyfunc(lambda b: b > cap, 1, 1)(x.v), dtype=bool)
    slope = iv.where(below, iv.const(1), iv.where(above, iv.const(0), iv.ball(0.5, 0.5)))
    return _piecewise_linear(x, iv.minimum(x.v, cap), slope, tape)


def _strip_wind(T: list, st: np.ndarray, k: int, az, advance=None) -> tuple:
    """The relative wind ``(u_y, u_z)`` at the strip ``k`` and its square ``V2``: the air's
    velocity (inflow ``az``; ``advance = (ax, ay)`` in forward flight) in the blade's axes less the
    blade's own (its velocity ``T[10:12]`` and angular velocity ``T[12:15]`` at the strip's point)."""
    if advance is not None:
        ax, ay = advance
        air_y = T[36] * ax + T[37] * ay + T[38] * az
        air_z = T[39] * ax + T[40] * ay + T[41] * az
    else:
        air_y = T[38] * az
        air_z = T[41] * az
    vPy, vPz, wx, wy, wz = T[10], T[11], T[12], T[13], T[14]
    rx = float(st[_RX, k])
    u_y = air_y - (vPy + wz * rx - wx * float(st[_WZ, k]))
    u_z = air_z - (vPz + wx * float(st[_WY, k]) - wy * rx)
    return u_y, u_z, u_y * u_y + u_z * u_z


def _add_strip(sums: tuple, st: np.ndarray, k: int, u_y, u_z, V2, Vm, coefficients: tuple, q_rel, pg,
               damped: bool, compressible: bool) -> tuple:
    """The strip ``k``'s loads added to ``sums = (sFy, sFz, Mx, My, Mz)`` (forces and moments about
    the hinge): lift and drag from the coefficients ``(cl, cd, cm)`` and the wind, the pitching
    moment about the pitch axis (with the pitch-rate damping couple, times the Prandtl-Glauert
    factor ``pg`` for compressible sections)."""
    cl, cd, cm = coefficients
    sFy, sFz, Mx, My, Mz = sums
    rx = float(st[_RX, k])
    qn = Vm * float(st[_QN, k])
    Fy = qn * (cd * u_y + cl * u_z)
    Fz = qn * (cd * u_z - cl * u_y)
    Mx_ac = V2 * cm * float(st[_MN, k])
    if damped:
        couple = Vm * q_rel * float(st[_DN, k])
        Mx_ac = Mx_ac + (couple * pg if compressible else couple)
    return (Fy + sFy, Fz + sFz, Fz * float(st[_RY, k]) - Fy * float(st[_RZ, k]) + Mx_ac + Mx, My - Fz * rx,
            Mz + Fy * rx)


def _generalised_air_forces(T: list, sums: tuple) -> list:
    """The three generalised forces of the summed strip loads ``(sFy, sFz, Mx, My, Mz)``."""
    sFy, sFz, Mx, My, Mz = sums
    return [T[18 + i] * sFy + T[21 + i] * sFz + T[24 + i] * Mx + T[27 + i] * My + T[30 + i] * Mz for i in range(3)]


def _attack_angle(u_y: Jet, u_z: Jet) -> Jet:
    """``alpha = atan2(u_z, -u_y)`` with its derivatives: ``X = -u_y``, ``Y = u_z``,
    ``alpha_X = -Y / V^2``, ``alpha_Y = X / V^2``, ``alpha_XX = -alpha_YY = 2 X Y / V^4``,
    ``alpha_XY = (Y^2 - X^2) / V^4``."""
    X, Y = -u_y, u_z
    if isinstance(u_z.v, Balls):
        value = _angle_balls(u_z.v, u_y.v)
    else:
        value = np.asarray(_angle(u_z.v, u_y.v), dtype=object)
    V2 = X.v * X.v + Y.v * Y.v
    inv = 1 / V2
    inv2 = inv * inv
    return iv.bivariate(X, Y, value, -Y.v * inv, X.v * inv, 2 * X.v * Y.v * inv2, -2 * X.v * Y.v * inv2,
                        (Y.v * Y.v - X.v * X.v) * inv2)


class BladeEnclosure:
    """The disturbed equations of a blade about a steady motion, evaluated on balls.

    Parameters
    ----------
    blade : rotorlyap.model.blade.Blade
        The blade (advance ratio, controls); its airfoil must be tabulated (``table_size > 0``):
        an :class:`~rotorlyap.model.airfoil.Airfoil` or a Mach-independent
        :class:`~rotorlyap.model.c81.C81Section`.
    steady : SteadyMotion, TabulatedMotion or anything ``as_steady_motion`` takes
        A constant state, or a :class:`~rotorlyap.model.steady.TabulatedMotion` (whose piecewise
        cubic interpolant is enclosed exactly).
    arithmetic : {"auto", "balls", "arb"}, optional
        The ball arithmetic of every enclosure (default :data:`DEFAULT_ARITHMETIC`): float balls
        (:mod:`rotorlyap.methods.balls`), Arb balls in object arrays (the reference, faster only
        for one azimuth interval), or ``"auto"`` (Arb for constant equations, else float balls).
        :attr:`arithmetic` holds the one chosen.

    Raises
    ------
    ValueError
        An airfoil without a table, a Mach-dependent C81 section (no Mach axis in the
        enclosures), or a periodic steady motion that is not tabulated.
    """

    def __init__(self, blade, steady=None, arithmetic: str | None = None):
        arithmetic = DEFAULT_ARITHMETIC if arithmetic is None else arithmetic
        if arithmetic not in ("auto", "balls", "arb"):
            raise ValueError(f"arithmetic must be 'auto', 'balls' or 'arb', got {arithmetic!r}")
        self.arithmetic = "arb" if arithmetic == "auto" else arithmetic
        with iv.arithmetic(self.arithmetic):
            self._init(blade, steady)
        if arithmetic == "auto" and not self.constant:
            self.arithmetic = "balls"
            with iv.arithmetic(self.arithmetic):
                self._init(blade, steady)

    def _init(self, blade, steady):
        airfoil = blade.params.airfoil
        if getattr(airfoil, "mach_dependent", False) or blade.aero.compressibility.section_mach:
            raise ValueError(f"the proof does not support the Mach-dependent section {airfoil.name!r} "
                             "(compressibility = 'table'): the enclosures have no Mach axis. Supported: "
                             "the package's tabulated sections and C81 tables with one Mach column "
                             "(with compressibility 'none' or 'prandtl-glauert')")
        rows = getattr(airfoil, "table_rows", lambda: None)()
        if rows is None:
            raise ValueError("the proof needs a tabulated airfoil (Airfoil with table_size > 0); "
                             f"{type(blade.params.airfoil).__name__} without a table is not supported")
        self.blade = blade
        data = _compiled.KernelData(blade, rows)
        self.params = [iv.const(float(p)) for p in data.P]
        self.sc = data.scalars
        self.st = data.stations
        self.table = _Table(rows)
        self.controls = [float(v) for v in _compiled._controls(blade)]
        if isinstance(steady, TabulatedMotion):
            self.motion = steady
            self.state = None
        else:
            motion = as_steady_motion(steady, blade)
            if not motion.is_constant:
                raise ValueError("a periodic steady motion must be a TabulatedMotion "
                                 "(rotorlyap.model.steady.tabulate_motion): its interpolant is enclosed exactly")
            self.motion = None
            self.state = np.asarray(motion.state, dtype=float)

    @property
    def constant(self) -> bool:
        """The disturbed equations do not depend on the azimuth (hover about an equilibrium, no
        cyclic pitch, uniform inflow)."""
        sc = self.sc
        return self.motion is None and sc[_MUVR] == 0.0 and sc[_UNIFORM] != 0.0 and sc[_CYCLIC] == 0.0

    def _steady_balls(self, n: int, *, centre: bool = False, second: bool = False, third: bool = False):
        """Balls of the steady motion and of its first (and second, third) derivatives on ``n``
        uniform azimuth intervals (or at their midpoints), shape (n, 6) each."""
        if self.motion is None:
            zero = iv.balls(np.zeros((n, 6)))
            xi = iv.balls(np.broadcast_to(self.state, (n, 6)))
            return (xi, zero) + (zero,) * (int(second or third) + int(third))
        return hermite_enclosure(self.motion.values, self.motion.slopes, n, centre=centre,
                                 second=second or third, third=third)


    def steady_balls(self, n: int, *, centre: bool = False, second: bool = False, third: bool = False):
        """Balls of the steady motion and of its first (and second, third) derivatives on ``n``
        uniform azimuth intervals (or at their midpoints), shape (n, 6) each."""
        with iv.arithmetic(self.arithmetic):
            return self._steady_balls(n, centre=centre, second=second, third=third)

    def rhs(self, psi, z: list, tape: "_Slopes | None" = None) -> tuple[list, dict]:
        """``h(psi, z)`` on balls: ``psi`` balls (N,), ``z`` six Jets (values (N,)); returns six
        Jets and the ``blocked`` dict of :class:`Evaluation`. ``tape`` records (or replays) the
        slopes of the piecewise-linear pieces."""
        with iv.arithmetic(self.arithmetic):
            return self._rhs(psi, z, tape)

    def residual(self, n: int) -> tuple:
        """Balls of the steady motion's residual ``g0 = h(psi, xi) - xi'`` over ``n`` azimuth
        intervals (:meth:`_residual`: a second-order mean-value form in the azimuth)."""
        with iv.arithmetic(self.arithmetic):
            return self._residual(n)

    def evaluate(self, n: int, radius=None, *, order: int = 1, slopes=None) -> Evaluation:
        """The disturbed equations on ``n`` azimuth intervals and boxes of disturbances
        (parameters and result: :meth:`_evaluate`)."""
        with iv.arithmetic(self.arithmetic):
            return self._evaluate(n, radius, order=order, slopes=slopes)

    # ------------------------------------------------------------------ the equations
    def _accelerations(self, psi, shape, z, T, n: int, blocked: dict, tape: _Slopes):
        sc, st = self.sc, self.st
        om = iv.const(float(sc[_OMEGA]))
        F0 = T[6] - z[3] * float(sc[_C0])
        F1 = T[7] - z[4] * float(sc[_C1])
        F2 = T[8] - z[5] * float(sc[_C2])
        if sc[_ACTIVE] != 0.0:
            cpsi = iv.cos(psi)
            muVR = float(sc[_MUVR])
            if muVR != 0.0:
                ax = cpsi * muVR
                ay = -iv.sin(psi) * muVR
            compressible = sc[_COMPRESSIBLE] != 0.0
            q_rel = T[12] - T[35] * om
            sums = (0.0,) * 5
            for k in range(st.shape[1]):
                if sc[_UNIFORM] != 0.0:
                    az = iv.const(float(st[_IA, k]))
                else:
                    az = cpsi * float(st[_IB, k]) + float(st[_IA, k])
                u_y, u_z, V2 = _strip_wind(T, st, k, az, (ax, ay) if muVR != 0.0 else None)
                Vm = iv.sqrt(V2)
                alpha = _attack_angle(u_y, u_z)
                wind = ~iv.is_finite(alpha.v)
                if wind.any():
                    blocked.setdefault("the relative wind may vanish (angle of attack undefined)",
                                       np.zeros(shape, dtype=bool))[:] |= wind
                if sc[_TWISTED] != 0.0:
                    alpha = alpha + float(st[_PHI, k])
                cl, cd, cm = self.table(alpha, tape)
                pg = 1.0
                if compressible:
                    mach = Vm * float(sc[_INV_A])
                    me = _min_const(mach, float(sc[_MACH_CAP]), tape)
                    ca = iv.cos(alpha.v)
                    fwd = iv.positive(ca)
                    rev = iv.negative(ca)
                    jump = ~(fwd | rev)
                    if jump.any():
                        blocked.setdefault("the angle of attack of a compressible section may cross +-90 deg "
                                           "(the Prandtl-Glauert factor jumps)",
                                           np.zeros(shape, dtype=bool))[:] |= jump
                    one = Jet(iv.full(shape, 1.0), None)
                    pg_f = 1.0 / iv.sqrt(1.0 - me * me)
                    bad = Jet(iv.nan(shape), iv.nan((n,) + shape), None if pg_f.h is None else iv.nan((n, n) + shape))
                    pg = _select(fwd, pg_f, _select(rev, one, bad, n), n)
                    cl = cl * pg
                    cm = cm * pg
                    dm = mach - (float(sc[_MCRIT0]) - 0.1 * _abs(cl, tape))
                    cd = cd + WAVE_DRAG_FACTOR * _pos4(dm)
                sums = _add_strip(sums, st, k, u_y, u_z, V2, Vm, (cl, cd, cm), q_rel, pg,
                                  sc[_PITCH_DAMPED] != 0.0, compressible)
            air = _generalised_air_forces(T, sums)
            F0 = F0 + air[0]
            F1 = F1 + air[1]
            F2 = F2 + air[2]
        s = 1 / (om * om)
        return tuple(acc * s for acc in solve_sym3(T[0:6], F0, F1, F2))

    def _rhs(self, psi: np.ndarray, z: list, tape: _Slopes | None = None) -> tuple[list, dict]:
        """``h(psi, z)`` on balls: ``psi`` balls (N,), ``z`` six Jets (values (N,)); returns six
        Jets and the ``blocked`` dict of :class:`Evaluation`. ``tape`` records (or replays) the
        slopes of the piecewise-linear pieces."""
        n = next((zz.d.shape[0] for zz in z if zz.d is not None), 1)
        shape = psi.v.shape if isinstance(psi, Jet) else psi.shape
        tape = _Slopes() if tape is None else tape
        c0, c1, c2 = self.controls
        if self.sc[_CYCLIC] != 0.0:
            theta_c = iv.cos(psi) * c1 + iv.sin(psi) * c2 + c0
        else:
            theta_c = iv.const(c0)
        T = [None] * 42
        _rhs_terms(z[0], z[1], z[2], z[3], z[4], z[5], theta_c, self.params, T)
        T = [t if isinstance(t, Jet) else Jet(iv.full(shape, t)) for t in T]
        blocked: dict = {}
        acc = self._accelerations(psi, shape, z, T, n, blocked, tape)
        return [z[3], z[4], z[5], acc[0], acc[1], acc[2]], blocked

    def _residual(self, n: int) -> tuple[np.ndarray, dict]:
        """Balls of the steady motion's residual ``g0 = h(psi, xi) - xi'`` over ``n`` azimuth intervals.

        A second-order mean-value form in the azimuth. With ``psi_c`` the midpoint of the
        interval ``Psi``, ``|d| <= w`` the offset from it, ``g0' = G(psi; sigma)`` the derivative
        in the azimuth computed with the slopes ``sigma`` of the piecewise-linear pieces (the
        airfoil table, ...) and ``S`` their hulls over ``Psi``:
        ``g0(psi_c + d) in g0(psi_c) + G(psi_c; S) d + G'(Psi; S) d^2 / 2``
        (for fixed slopes the residual is smooth in the azimuth; the true slopes lie in ``S``).
        The residual of a good steady motion is small everywhere, and so are its derivatives, so
        this is far tighter than ``g0`` evaluated over the interval, where the large terms that
        cancel in ``h`` each carry their own change over the interval.

        Returns
        -------
        g0 : balls (Balls or object array of arb), shape (n, 6)
        blocked : dict
        """
        k = np.arange(n, dtype=float)
        two_pi = iv.pi() * 2.0
        psi_c = iv.balls((k + 0.5) / n) * two_pi
        xi_c, dxi_c, ddxi_c = self.steady_balls(n, centre=True, second=True)
        if self.constant:
            out, blocked = self.rhs(psi_c, [Jet(xi_c[:, i]) for i in range(6)])
            return iv.stack([o.v for o in out], axis=1) - dxi_c, blocked
        one = iv.zeros((1, n)) + 1
        # over the interval, second order in the azimuth, recording the slopes
        Psi = psi_intervals(n)
        xi, dxi, ddxi, dddxi = self.steady_balls(n, third=True)
        z = [Jet(xi[:, i], dxi[None, :, i], ddxi[None, None, :, i]) for i in range(6)]
        tape = _Slopes()
        out, blocked = self.rhs(Jet(Psi, one, iv.zeros((1, 1, n))), z, tape)
        curvature = iv.stack([o.hessian(1)[0, 0] for o in out], axis=1) - dddxi
        # at the midpoint: the value, and the first derivative with the slopes of the interval
        out, _ = self.rhs(psi_c, [Jet(xi_c[:, i]) for i in range(6)])
        g_c = iv.stack([o.v for o in out], axis=1) - dxi_c
        z = [Jet(xi_c[:, i], dxi_c[None, :, i]) for i in range(6)]
        out, _ = self.rhs(Jet(psi_c, one), z, _Slopes(tape.record))
        slope = iv.stack([o.d[0] for o in out], axis=1) - ddxi_c
        w = iv.pi() / n
        d = iv.ball(0, 1) * w                 # the offset from the midpoint, |d| <= w
        d2 = iv.ball(0.5, 0.5) * (w * w)      # its square, in [0, w^2]
        return g_c + slope * d + curvature * (d2 * 0.5), blocked

    def _evaluate(self, n: int, radius=None, *, order: int = 1, slopes=None) -> Evaluation:
        """The disturbed equations on ``n`` azimuth intervals and boxes of disturbances.

        Parameters
        ----------
        n : int
            Uniform azimuth intervals over one period (a multiple of the steady motion's grid).
        radius : array_like (6,), optional
            Half-widths of the box of disturbances ``|x_i| <= radius_i`` (rad, rad/rad); None for
            ``x = 0`` (the steady motion itself).
        order : {1, 2}
            2 also encloses the Hessians (with the slopes of the piecewise-linear pieces frozen).
        slopes : list, optional
            The :attr:`Evaluation.slopes` of an evaluation over a box (same ``n``): the
            piecewise-linear pieces take those slopes instead of their own (the Jacobian at the
            centre with the slopes of the box).

        Returns
        -------
        Evaluation
            ``value``: ``h(psi, xi + x) - xi'(psi)``; ``jacobian``: ``dh/dz`` there.
        """
        if order not in (1, 2):
            raise ValueError(f"order must be 1 or 2, got {order!r}")
        psi = psi_intervals(n)
        xi, dxi = self.steady_balls(n)
        if radius is not None:
            r = np.asarray(radius, dtype=float)
            if r.shape != (6,) or not np.all(np.isfinite(r) & (r >= 0)):
                raise ValueError(f"radius must be 6 finite half-widths >= 0, got {radius!r}")
            xi = xi + iv.balls(np.zeros((n, 6)), np.broadcast_to(r, (n, 6)))
        z = iv.variables([xi[:, i] for i in range(6)], order=order)
        tape = _Slopes(slopes)
        out, blocked = self.rhs(psi, z, tape)
        value = iv.stack([o.v for o in out], axis=1) - dxi
        jac = iv.moveaxis(iv.stack([o.gradient(6) for o in out], axis=0), -1, 0)  # (N, 6, 6)
        hess = None
        if order == 2:
            hess = iv.moveaxis(iv.stack([o.hessian(6) for o in out], axis=0), -1, 0)  # (N, 6, 6, 6)
        return Evaluation(value=value, jacobian=jac, hessian=hess, blocked=blocked,
                          slopes=tape.record if slopes is None else list(slopes))
