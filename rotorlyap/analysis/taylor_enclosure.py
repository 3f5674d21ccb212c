"""The blade's equations in Taylor-model arithmetic: enclosures that keep the cancellations.

:func:`taylor_evaluate` runs the same formulas as :class:`rotorlyap.analysis.enclosure.BladeEnclosure`
(the generated Lagrangian terms with :class:`rotorlyap.methods.taylor.TaylorMath` in place of
``math``, the parameters as exact float balls, the strip loads) on Taylor models
(:mod:`rotorlyap.methods.taylor`) of the disturbances over boxes ``|x_i - c_i| <= r_i``, with
forward differentiation (:class:`rotorlyap.methods.intervals.Jet` whose value and gradient are
models): every component of the right-hand side and every entry of the Jacobian is a polynomial
in the box variables with a rigorous remainder. Where the ball enclosure adds the widths of the
large inertial and centrifugal terms of the pitch equation that cancel to a small sum (issue 41:
its Jacobian some 430 times wider than the Jacobian varies, on every size of box), the models
cancel them in their coefficients.

The strip loads need two adapters: the angle of attack ``atan2(u_z, -u_y)`` on the branch of
:func:`rotorlyap.analysis.enclosure._angle_value` (chosen per box from the ranges), and the
piecewise-linear airfoil table (:func:`_tm_table`): the slopes of the segments the range of the
angle touches enclosed by a line in the angle plus a bound of their deviation from it, the value
the integral of that slope from the model's constant coefficient (exact where the range lies in
one segment). Its derivative is that slope (at a kink: every generalised derivative), as in the
ball enclosure, which takes the hull of the slopes instead: over a range of many segments of a
fine table (the NACA 23012's 65 536 nodes) the hull is as wide as the airfoil's curvature
times the range, a Jacobian remainder of first order in the box.

Scope: constant steady motions (hover about the equilibrium, no cyclic pitch, uniform inflow:
:attr:`BladeEnclosure.constant`) and incompressible sections. Not yet used by the prover.
"""

from __future__ import annotations

import types
from dataclasses import dataclass

import numpy as np

from ..methods import intervals as iv
from ..methods import taylor as tm
from ..methods.balls import Balls
from ..methods.intervals import Jet
from ..methods.taylor import TaylorMath, TaylorModel
from ..model._generated import blade_scalar as _scalar
from ..model.compiled import (_ACTIVE, _C0, _C1, _C2, _COMPRESSIBLE, _DN, _IA, _MN, _OMEGA, _PHI, _PITCH_DAMPED,
                              _QN, _RX, _RY, _RZ, _TWISTED)
from ..model.equations import solve_sym3
from .enclosure import BladeEnclosure, _strip_wind

__all__ = ["TaylorEvaluation", "taylor_evaluate"]

_rhs_terms = types.FunctionType(_scalar.rhs_terms_into.__code__,
                                {**_scalar.rhs_terms_into.__globals__, "math": TaylorMath},
                                "rhs_terms_into_taylor")


@dataclass(frozen=True)
class TaylorEvaluation:
    """Taylor models of the disturbed right-hand side and of its Jacobian over boxes.

    Attributes
    ----------
    value : TaylorModel, shape ``batch + (6,)``
        ``x' = h(xi + x) - xi'`` (rad/rad, rad/rad^2), hover: ``xi' = 0``.
    jacobian : TaylorModel, shape ``batch + (6, 6)``
        ``d x' / d x`` (per rad of azimuth, mixed units of the state).
    centre, radius : numpy.ndarray, shape ``batch + (6,)``
        The boxes ``|x_i - centre_i| <= radius_i`` (rad, rad/rad); the model variable ``t_i`` is
        ``(x_i - centre_i) / radius_i``.
    order : int
    """

    value: TaylorModel
    jacobian: TaylorModel
    centre: np.ndarray
    radius: np.ndarray
    order: int


def _unit_gradients(n: int, shape: tuple, sp) -> list[TaylorModel]:
    out = []
    for i in range(n):
        e = np.zeros((n,) + shape)
        e[i] = 1.0
        out.append(TaylorModel.constant(e, sp))
    return out


def _tm_angle(u_y: Jet, u_z: Jet) -> Jet:
    """``atan2(u_z, -u_y)`` of models on the branch of ``enclosure._angle_value``, chosen per box
    from the ranges (non-finite where the relative wind may vanish), with its gradient
    ``(-Y dX + X dY) / (X^2 + Y^2)``."""
    X, Y = -u_y, u_z
    xlo, xhi = X.v.bounds()
    ylo, yhi = Y.v.bounds()
    right = xlo > 0
    up = ~right & (ylo > 0)
    down = ~right & ~up & (yhi < 0)
    left = ~right & ~up & ~down & (xhi < 0)
    half = iv.pi() * 0.5
    parts = []
    if right.any() or left.any():
        parts.append((right | left, (Y.v / X.v).atan() + Balls(np.where(left, iv.pi().mid, 0.0),
                                                                np.where(left, iv.pi().rad, 0.0))))
    if up.any() or down.any():
        off = Balls(np.where(up, half.mid, -half.mid), half.rad)
        parts.append((up | down, (u_y.v / Y.v).atan() + off))
    ok = right | up | down | left
    value = None
    for mask, v in parts:
        value = v if value is None else tm.where(mask, v, value)
    if value is None or not ok.all():
        nan = TaylorModel(np.full(X.v.coef.shape, np.nan), np.nan, X.v.space)
        value = nan if value is None else tm.where(ok, value, nan)
    inv = (X.v * X.v + Y.v * Y.v).reciprocal()
    return iv.bivariate(X, Y, value, -Y.v * inv, X.v * inv)


def _slope_line(table, c: int, k_lo: int, k_hi: int, u0: float, du0: float):
    """A line ``s0 + kappa (u - u0)`` through the segment slopes of coefficient ``c`` of the table
    (per segment of the grid ``u = (alpha + pi) n / (2 pi)``) on the segments ``k_lo..k_hi``,
    and ``e``: a float with ``|d_k - s0 - kappa (u - u0)| <= e`` for every ``u`` of those segments
    (``d_k`` the exact node difference; ``u0`` known to ``du0``, see :func:`_tm_table`)."""
    k = np.arange(k_lo, k_hi + 1)
    idx = k % table.n
    d_lo, d_hi = table.d_lo[c][idx], table.d_hi[c][idx]
    m = k + 0.5 - u0
    if k.size == 1:
        s0, kappa = 0.5 * (d_lo[0] + d_hi[0]), 0.0
    else:
        kappa, s0 = np.polyfit(m, 0.5 * (d_lo + d_hi), 1)   # any line is valid: the error is bounded below
    offset = Balls(k + 0.5) - u0                       # k + 1/2 - u0, rounding enclosed
    dev = iv.hull(d_lo, d_hi) - (offset * float(kappa) + float(s0))
    # within segment k, |u - (k + 1/2)| <= 1/2, and u0 is known to du0
    e = Balls(float(np.max(dev.magnitude()))) + Balls(abs(float(kappa))) * (Balls(0.5) + du0)
    return float(s0), float(kappa), float(e.upper())


def _tm_table(enc: BladeEnclosure, alpha: Jet) -> tuple[Jet, Jet, Jet]:
    """cl, cd, cm (Jets of models) of the piecewise-linear table at the angle ``alpha``.

    With ``a0`` the model's constant coefficient, ``h = alpha - a0``, ``u`` the table's grid
    coordinate (``du/dalpha = F``, ``F = n / (2 pi)``) and the segment slopes ``d_k`` (per unit of
    ``u``) of the segments the range touches enclosed by a line,
    ``|d_k - s0 - kappa (u - u0)| <= e`` (:func:`_slope_line`): the slope is
    ``F (s0 + kappa F h) +- F e`` and the value ``f(a0) + F s0 h + F^2 kappa h^2 / 2 +- F e |h|``
    (the integral of the slope from ``a0``). Where the range lies in one segment, ``e = 0``: the
    table is linear there, exactly. The slope is the derivative (at a kink: every generalised
    derivative). A range over more than half the period falls back to the hull of every slope."""
    a = alpha.v
    a0 = a.coef[..., 0]
    sp = a.space
    with iv.arithmetic("balls"):
        table = enc.table
        fac = table.fac
        at_point = table.lookup(Balls(a0))
        u_range = (a.to_balls() + iv.pi()) * fac
        u_point = (Balls(a0) + iv.pi()) * fac
        k_lo = np.floor(u_range.lower())
        k_hi = np.floor(u_range.upper())
        wide = ~(k_hi - k_lo < table.n // 2)
        over_range = table.lookup(a.to_balls()) if np.any(wide) else None
    h = a - a0
    H = h.magnitude()
    out = []
    for c in range(3):
        s0 = np.zeros(a.shape)
        kap = np.zeros(a.shape)
        e = np.zeros(a.shape)
        for i in np.ndindex(a.shape):
            if wide[i]:
                continue
            s0[i], kap[i], e[i] = _slope_line(table, c, int(k_lo[i]), int(k_hi[i]), float(u_point.mid[i]),
                                              float(u_point.rad[i]))
        lin = fac * Balls(s0)                      # F s0
        quad = fac * fac * Balls(kap)              # F^2 kappa
        err = (fac * Balls(e)).magnitude()         # F e, rounded up
        slope = h * quad + lin + Balls(np.zeros(a.shape), err)
        value = h * lin + (h * h) * (quad * 0.5) + at_point[c][0] + Balls(np.zeros(a.shape), (Balls(err) * Balls(H)).upper())
        if np.any(wide):
            val_w, slope_w = over_range[c][1] * h + at_point[c][0], over_range[c][1]
            value = tm.where(wide, val_w, value)
            slope = tm.where(wide, TaylorModel.constant(slope_w, sp, a.shape), slope)
        out.append(iv.chain(alpha, value, slope, None))
    return tuple(out)


def _air_moments(enc: BladeEnclosure, z: list, T: list):
    """The strip loads' generalised forces (hover, uniform inflow, incompressible), as the
    ``_ACTIVE`` branch of ``BladeEnclosure._accelerations``."""
    sc, st = enc.sc, enc.st
    om = float(sc[_OMEGA])
    q_rel = T[12] - T[35] * om
    sFy = sFz = Mx = My = Mz = 0.0
    for k in range(st.shape[1]):
        rx = float(st[_RX, k])
        u_y, u_z, V2 = _strip_wind(T, st, k, Balls(float(st[_IA, k])))
        Vm = tm.sqrt(V2)
        alpha = _tm_angle(u_y, u_z)
        if sc[_TWISTED] != 0.0:
            alpha = alpha + float(st[_PHI, k])
        cl, cd, cm = _tm_table(enc, alpha)
        qn = Vm * float(st[_QN, k])
        Fy = qn * (cd * u_y + cl * u_z)
        Fz = qn * (cd * u_z - cl * u_y)
        Mx_ac = V2 * cm * float(st[_MN, k])
        if sc[_PITCH_DAMPED] != 0.0:
            Mx_ac = Mx_ac + Vm * q_rel * float(st[_DN, k])
        sFy = Fy + sFy
        sFz = Fz + sFz
        Mx = Fz * float(st[_RY, k]) - Fy * float(st[_RZ, k]) + Mx_ac + Mx
        My = My - Fz * rx
        Mz = Mz + Fy * rx
    return [T[18 + i] * sFy + T[21 + i] * sFz + T[24 + i] * Mx + T[27 + i] * My + T[30 + i] * Mz for i in range(3)]


def taylor_evaluate(enclosure: BladeEnclosure, centre, radius, order: int) -> TaylorEvaluation:
    """The disturbed equations of a hovering blade on Taylor models over boxes of disturbances.

    Parameters
    ----------
    enclosure : BladeEnclosure
        The blade and its constant steady motion (:attr:`BladeEnclosure.constant`), built with
        ``arithmetic="balls"``.
    centre : array_like, shape ``batch + (6,)``
        Centres of the boxes, disturbances ``x`` about the steady state (rad, rad/rad).
    radius : array_like, shape ``batch + (6,)``
        Half-widths ``>= 0`` of the boxes (rad, rad/rad).
    order : int
        Order of the Taylor models (1 to :data:`rotorlyap.methods.taylor.MAX_ORDER`).

    Returns
    -------
    TaylorEvaluation

    Raises
    ------
    ValueError
        Equations that depend on the azimuth, a compressible section, an enclosure in Arb
        arithmetic, bad boxes or order.
    """
    if not enclosure.constant:
        raise ValueError("taylor_evaluate encloses constant equations (hover about the equilibrium); "
                         "the azimuth is not a model variable yet")
    if enclosure.arithmetic != "balls":
        raise ValueError("taylor_evaluate needs a BladeEnclosure built with arithmetic='balls'")
    if enclosure.sc[_ACTIVE] != 0.0 and enclosure.sc[_COMPRESSIBLE] != 0.0:
        raise ValueError("taylor_evaluate does not enclose compressible sections yet")
    c = np.asarray(centre, dtype=float)
    r = np.asarray(radius, dtype=float)
    if c.shape[-1:] != (6,) or r.shape[-1:] != (6,):
        raise ValueError(f"centre and radius must have a last axis of 6, got {c.shape} and {r.shape}")
    c, r = np.broadcast_arrays(c, r)
    xs = tm.variables(enclosure.state + c, r, order)
    shape = xs[0].shape
    sp = xs[0].space
    grads = _unit_gradients(6, shape, sp)
    z = [Jet(x, g) for x, g in zip(xs, grads)]
    sc = enclosure.sc
    with iv.arithmetic("balls"):
        theta_c = iv.const(enclosure.controls[0])
        T = [None] * 42
        _rhs_terms(z[0], z[1], z[2], z[3], z[4], z[5], theta_c, enclosure.params, T)
        F = [T[6 + i] - z[3 + i] * float(sc[(_C0, _C1, _C2)[i]]) for i in range(3)]
        if sc[_ACTIVE] != 0.0:
            air = _air_moments(enclosure, z, T)
            F = [f + a for f, a in zip(F, air)]
        om = iv.const(float(sc[_OMEGA]))
        s = 1 / (om * om)
        acc = [a * s for a in solve_sym3(T[0:6], F[0], F[1], F[2])]
    rows = [z[3], z[4], z[5]] + acc
    value = tm.stack([_as_model(q.v, shape, sp) for q in rows], axis=-1)
    jac = tm.stack([_as_model(q.gradient(6), (6,) + shape, sp) for q in rows], axis=0)  # (6 rows, 6 cols) + batch
    jac = jac.moveaxis(0, -1).moveaxis(0, -1)
    return TaylorEvaluation(value=value, jacobian=jac, centre=c, radius=r, order=int(order))


def _as_model(x, shape: tuple, sp) -> TaylorModel:
    """A model of ``shape`` from a model, balls or a float."""
    if isinstance(x, TaylorModel):
        if x.shape != shape:
            return TaylorModel._new(np.broadcast_to(x.coef, shape + (sp.size,)), np.broadcast_to(x.rem, shape), sp)
        return x
    return TaylorModel.constant(x, sp, shape)
