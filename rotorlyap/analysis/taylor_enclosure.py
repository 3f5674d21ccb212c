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

Hover (:attr:`BladeEnclosure.constant`) has six model variables; elsewhere (``n_intervals``) the
azimuth offset within each of ``n`` intervals is the seventh, the tabulated steady motion enters
as its exact piecewise cubic, and the compressible sections' kinks (the Mach cap, ``|cl|``, Lock's
drag rise ``max(dm, 0)^4``) are enclosed by mean values about the model's centre with the
generalised derivative's range (exact where the box stays on one side). Boxes where the relative
wind may vanish or a compressible section's angle of attack may cross +-90 deg get non-finite
models. On coarse azimuth intervals (a divisor of the motion's grid) the steady motion is a cubic in
the azimuth fitted to the Hermite pieces the interval spans, with its deviation from them bounded
(:func:`_fitted_motion`; the hull of the pieces, as before, widened the Jacobian's models by the
motion's change over the interval). The prover uses the Jacobian's models
(:meth:`rotorlyap.analysis.proof.BladeProofSystem.jacobian_models`).
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
from ..model.compiled import (_ACTIVE, _C0, _C1, _C2, _COMPRESSIBLE, _CYCLIC, _IA, _IB, _INV_A, _MACH_CAP, _MCRIT0,
                              _MUVR, _OMEGA, _PHI, _PITCH_DAMPED, _TWISTED, _UNIFORM)
from ..model.compressibility import WAVE_DRAG_FACTOR
from ..model.equations import solve_sym3
from .enclosure import BladeEnclosure, _add_strip, _generalised_air_forces, _strip_wind

__all__ = ["TaylorEvaluation", "taylor_evaluate"]

_rhs_terms = types.FunctionType(_scalar.rhs_terms_into.__code__,
                                {**_scalar.rhs_terms_into.__globals__, "math": TaylorMath},
                                "rhs_terms_into_taylor")
_rhs_dw_terms = types.FunctionType(_scalar.rhs_dw_terms_into.__code__,
                                   {**_scalar.rhs_dw_terms_into.__globals__, "math": TaylorMath},
                                   "rhs_dw_terms_into_taylor")


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
    n_intervals : int or None
        The azimuth intervals (batch ``(n,)``; the seventh variable ``tau``:
        ``psi = 2 pi (k + 1/2) / n + (pi / n) tau``), or None (hover, six variables). Boxes with no
        enclosure (the relative wind may vanish; a compressible section's angle of attack may
        cross +-90 deg) have non-finite models.
    angles : numpy.ndarray or None
        Shape ``batch + (n_strips, 2)``: the range (lower, upper bound) of each strip's angle of
        attack over each box, rad (NaN where the relative wind may vanish); None for a blade
        without air loads.
    state : list of TaylorModel or None
        The models of the six state components ``xi + x`` the equations were evaluated on (hover:
        the box variables plus the steady state), for functions of the state that must use the
        same model variables (:mod:`rotorlyap.analysis.designed_proof`).
    terms : list or None
        With ``energy_terms``: the generated ``rhs_dw_terms`` rows (0-5 the mass matrix's unique
        entries, 42-44 ``1/2 Omega^2 x_r^T dM/dq x_r``, 45-47 ``grad U``, in J) as models of the
        state, for the energy's derivative; None otherwise.
    """

    value: TaylorModel
    jacobian: TaylorModel | None
    centre: np.ndarray
    radius: np.ndarray
    order: int
    n_intervals: int | None = None
    angles: np.ndarray | None = None
    state: list | None = None
    terms: list | None = None


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


def _slope_lines(table, k_lo: np.ndarray, k_hi: np.ndarray, u0: np.ndarray, du0: np.ndarray):
    """Per coefficient ``c`` of the table (cl, cd, cm) and range ``j``: a line
    ``s0_j + kappa_j (u - u0_j)`` through the segment slopes (per segment of the grid
    ``u = (alpha + pi) n / (2 pi)``) on the segments ``k_lo_j..k_hi_j``, and ``e_j``: floats with
    ``|d_k - s0_j - kappa_j (u - u0_j)| <= e_j`` for every ``u`` of those segments (``d_k`` the exact
    node difference; the exact ``u0_j`` within ``du0_j`` of the float ``u0_j``). The line is a
    least-squares fit (any line is valid: the deviation is bounded in ball arithmetic), one pass
    over all the segments of all ranges, its index arithmetic shared by the three coefficients.
    Returns ``[(s0, kappa, e)]`` per coefficient."""
    count = (k_hi - k_lo).astype(np.int64) + 1
    starts = np.concatenate([[0], np.cumsum(count)[:-1]])
    owner = np.repeat(np.arange(count.size), count)
    k = np.repeat(k_lo.astype(np.int64), count) + np.arange(int(count.sum())) - np.repeat(starts, count)
    idx = k % table.n
    m = k + 0.5 - u0[owner]
    sum_m, sum_mm = (np.add.reduceat(v, starts) for v in (m, m * m))
    var = sum_mm - sum_m * sum_m / count
    offset = Balls(k + 0.5) - u0[owner]                    # k + 1/2 - u0, rounding enclosed
    out = []
    for c in range(3):
        d_lo, d_hi = table.d_lo[c][idx], table.d_hi[c][idx]
        d = 0.5 * (d_lo + d_hi)
        sum_d, sum_md = (np.add.reduceat(v, starts) for v in (d, m * d))
        with np.errstate(divide="ignore", invalid="ignore"):
            kappa = np.where((count > 1) & (var > 0), (sum_md - sum_m * sum_d / count) / var, 0.0)
        s0 = (sum_d - kappa * sum_m) / count
        dev = iv.hull(d_lo, d_hi) - (offset * kappa[owner] + s0[owner])
        worst = np.maximum.reduceat(dev.magnitude(), starts)
        # within segment k, |u - (k + 1/2)| <= 1/2, and u0 is known to du0
        e = Balls(worst) + Balls(np.abs(kappa)) * (Balls(0.5) + du0)
        out.append((s0, kappa, e.upper()))
    return out


def _tm_table(enc: BladeEnclosure, alpha: Jet) -> tuple[Jet, Jet, Jet]:
    """cl, cd, cm (Jets of models) of the piecewise-linear table at the angle ``alpha``.

    With ``a0`` the model's constant coefficient, ``h = alpha - a0``, ``u`` the table's grid
    coordinate (``du/dalpha = F``, ``F = n / (2 pi)``) and the segment slopes ``d_k`` (per unit of
    ``u``) of the segments the range touches enclosed by a line,
    ``|d_k - s0 - kappa (u - u0)| <= e`` (:func:`_slope_lines`): the slope is
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
    narrow = ~wide.reshape(-1)
    lines = None
    if np.any(narrow):
        lines = _slope_lines(table, k_lo.reshape(-1)[narrow], k_hi.reshape(-1)[narrow],
                             u_point.mid.reshape(-1)[narrow], u_point.rad.reshape(-1)[narrow])
    for c in range(3):
        s0, kap, e = np.zeros(narrow.size), np.zeros(narrow.size), np.zeros(narrow.size)
        if lines is not None:
            s0[narrow], kap[narrow], e[narrow] = lines[c]
        s0, kap, e = s0.reshape(a.shape), kap.reshape(a.shape), e.reshape(a.shape)
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


def _tm_select(mask, a: Jet, b: Jet, n: int) -> Jet:
    """Elementwise ``a`` where ``mask`` (per box) else ``b``, for Jets of models (the values alone
    where neither has a gradient: ``taylor_evaluate(..., jacobian=False)``)."""
    if a.d is None and b.d is None:
        return Jet(tm.where(mask, a.v, b.v))
    return Jet(tm.where(mask, a.v, b.v), tm.where(mask, a.gradient(n), b.gradient(n)))


def _constant_jet(value, like: Jet, n: int) -> Jet:
    """The constant ``value`` (float or balls) as a Jet of the models of ``like`` (zero gradient)."""
    sp, shape = like.v.space, like.v.shape
    if like.d is None:
        return Jet(TaylorModel.constant(value, sp, shape))
    return Jet(TaylorModel.constant(value, sp, shape), TaylorModel.constant(np.zeros((n,) + shape), sp))


def _kink(x: Jet, f0, slope: Balls, certain: list) -> Jet:
    """A piecewise-linear (or Lipschitz) function of ``x`` over boxes where it may not be smooth:
    ``f(x0) + S (x - x0)`` about the constant coefficient ``x0`` (``f0`` its value, balls), ``S``
    the balls of every slope over the range (mean-value theorem with the generalised derivative),
    and ``S`` as the derivative; ``certain``: ``[(mask, Jet)]`` that replace it where the branch is
    certain over the whole box."""
    h = x.v - x.v.coef[..., 0]
    out = iv.chain(x, h * slope + f0, slope, None)
    n = x.gradient(6).shape[0]
    for mask, jet in certain:
        if np.any(mask):
            out = _tm_select(mask, jet, out, n)
    return out


def _tm_min_const(x: Jet, cap: float) -> Jet:
    """``min(x, cap)``: ``x`` below, ``cap`` above, slope in [0, 1] where the range reaches ``cap``."""
    lo, hi = x.v.bounds()
    x0 = x.v.coef[..., 0]
    n = x.gradient(6).shape[0]
    return _kink(x, Balls(np.minimum(x0, cap)), Balls(np.full(lo.shape, 0.5), 0.5),
                 [(hi < cap, x), (lo > cap, _constant_jet(np.full(lo.shape, cap), x, n))])


def _tm_abs(x: Jet) -> Jet:
    """``|x|``: ``+-x`` where the sign is certain, slope in [-1, 1] elsewhere."""
    lo, hi = x.v.bounds()
    x0 = x.v.coef[..., 0]
    return _kink(x, Balls(np.abs(x0)), Balls(np.zeros(lo.shape), 1.0), [(lo > 0, x), (hi < 0, -x)])


def _tm_pos4(x: Jet) -> Jet:
    """``max(x, 0)^4``: ``x^4`` where ``x > 0`` on the box, 0 where ``x < 0``; elsewhere its value
    about ``x0`` with the slope ``4 max(xi, 0)^3`` in ``[0, 4 max(hi, 0)^3]``."""
    lo, hi = x.v.bounds()
    x0 = x.v.coef[..., 0]
    n = x.gradient(6).shape[0]
    p0 = Balls(np.maximum(x0, 0.0))
    p0 = p0 * p0
    top = Balls(np.maximum(hi, 0.0))
    slope_hi = (top * top * top * 4.0).upper()
    power = x * x
    power = power * power
    return _kink(x, p0 * p0, Balls(0.5 * slope_hi, 0.5 * slope_hi),
                 [(lo > 0, power), (hi < 0, _constant_jet(np.zeros(lo.shape), x, n))])


def _air_moments(enc: BladeEnclosure, z: list, T: list, psi, strips=None):
    """The strip loads' generalised forces, as the ``_ACTIVE`` branch of
    ``BladeEnclosure._accelerations``; ``psi`` the azimuth (a model, or None in hover), a
    boolean array of the boxes where no enclosure exists (the relative wind may vanish, or a
    compressible section's angle of attack may cross +-90 deg), and the range of each strip's
    angle of attack (``batch + (n_strips, 2)``, rad). ``strips``: a boolean per strip, whose loads
    are summed (None: all)."""
    sc, st = enc.sc, enc.st
    om = float(sc[_OMEGA])
    q_rel = T[12] - T[35] * om
    muVR = float(sc[_MUVR])
    n = 6
    cpsi = None if psi is None else tm.cos(psi)
    advance = (cpsi * muVR, tm.sin(psi) * -muVR) if muVR != 0.0 else None
    compressible = sc[_COMPRESSIBLE] != 0.0
    blocked = np.zeros(z[0].v.shape, dtype=bool)
    sums = (0.0,) * 5
    angles = np.full(z[0].v.shape + (st.shape[1], 2), np.nan)
    for k in range(st.shape[1]):
        az = Balls(float(st[_IA, k])) if sc[_UNIFORM] != 0.0 else cpsi * float(st[_IB, k]) + float(st[_IA, k])
        u_y, u_z, V2 = _strip_wind(T, st, k, az, advance)
        Vm = tm.sqrt(V2)
        alpha = _tm_angle(u_y, u_z)
        blocked |= ~alpha.v.finite()
        if sc[_TWISTED] != 0.0:
            alpha = alpha + float(st[_PHI, k])
        with np.errstate(invalid="ignore"):
            angles[..., k, 0], angles[..., k, 1] = alpha.v.bounds()
        if strips is not None and not strips[k]:
            continue
        cl, cd, cm = _tm_table(enc, alpha)
        pg = 1.0
        if compressible:
            mach = Vm * float(sc[_INV_A])
            me = _tm_min_const(mach, float(sc[_MACH_CAP]))
            clo, chi = tm.cos(alpha.v).bounds()
            fwd, rev = clo > 0, chi < 0
            blocked |= ~(fwd | rev)
            pg_f = 1.0 / tm.sqrt(1.0 - me * me)
            pg = _tm_select(fwd, pg_f, _constant_jet(np.where(rev, 1.0, np.nan), cl, n), n)
            cl = cl * pg
            cm = cm * pg
            dm = mach - (float(sc[_MCRIT0]) - 0.1 * _tm_abs(cl))
            cd = cd + WAVE_DRAG_FACTOR * _tm_pos4(dm)
        sums = _add_strip(sums, st, k, u_y, u_z, V2, Vm, (cl, cd, cm), q_rel, pg, sc[_PITCH_DAMPED] != 0.0,
                          compressible)
    return _generalised_air_forces(T, sums), blocked, angles


def _steady_models(enc: BladeEnclosure, tau: TaylorModel, n: int):
    """Models of the steady motion and of its derivative over the ``n`` azimuth intervals, in the
    azimuth variable ``tau`` (``psi = psi_k + (pi / n) tau``): the cubic Hermite piece of each
    interval (``n`` a multiple of the grid ``K``), exactly as a polynomial in ``tau``, its
    coefficients balls as :func:`rotorlyap.methods.intervals.hermite_enclosure` forms them; for
    ``n`` a divisor of ``K`` (coarse intervals over several pieces) a cubic in ``tau`` fitted to the
    pieces with its deviation bounded (:func:`_fitted_motion`), and the derivative as the hull of
    the pieces (balls that do not follow ``tau``; the Jacobian does not use it)."""
    if enc.motion is None:
        state = np.broadcast_to(enc.state, (n, 6))
        return [Balls(state[:, i]) for i in range(6)], [Balls(np.zeros(n)) for _ in range(6)]
    values, slopes = np.asarray(enc.motion.values, float), np.asarray(enc.motion.slopes, float)
    K = values.shape[0]
    if n < K and K % n == 0:
        # coarse intervals: the motion as a cubic in tau fitted to the pieces each interval spans,
        # with the deviation from every piece bounded (_fitted_motion); its derivative the hull
        _, dxi = iv.hermite_enclosure(values, slopes, n)
        coeffs, err = _fitted_motion(values, slopes, n)
        xi = []
        for i in range(6):
            c = coeffs[:, :, i]                                   # (n, 4) floats, tau^0..tau^3
            model = tau * float(0.0) + c[:, 3]
            for d in (2, 1, 0):
                model = model * tau + c[:, d]
            xi.append(model + Balls(np.zeros(n), err[:, i]))
        return xi, [dxi[:, i] for i in range(6)]
    if n % K:
        raise ValueError(f"n_intervals ({n}) must be a multiple or a divisor of the steady motion's grid ({K})")
    sub = n // K
    j = np.arange(n) // sub
    pos = np.arange(n) % sub
    h = iv.pi() * 2.0 / float(K)
    P0 = Balls(values[j])
    P1 = Balls(values[(j + 1) % K])
    B0 = Balls(slopes[j]) * h
    B1 = Balls(slopes[(j + 1) % K]) * h
    dP = P1 - P0
    c2 = dP * 3.0 - B0 * 2.0 - B1
    c3 = B0 + B1 - dP * 2.0
    # the position in the piece: t = (pos + 1/2) / sub + tau / (2 sub)
    t = tau * (Balls(1.0) / float(2 * sub)) + Balls((pos + 0.5)) / float(sub)
    xi, dxi = [], []
    for i in range(6):
        xi.append(t * (t * (t * c3[:, i] + c2[:, i]) + B0[:, i]) + P0[:, i])
        dxi.append((t * (t * (c3[:, i] * 3.0) + c2[:, i] * 2.0) + B0[:, i]) / h)
    return xi, dxi


def _fitted_motion(values: np.ndarray, slopes: np.ndarray, n: int, degree: int = 3):
    """A polynomial of ``degree`` in ``tau`` per interval for the periodic cubic Hermite interpolant
    of the steady motion (grid ``K``, ``n`` a divisor of ``K``; interval ``k``:
    ``psi = 2 pi (k + 1/2) / n + (pi / n) tau``), fitted by least squares at four points per piece,
    and floats ``err`` with ``|xi(psi) - fit(tau)| <= err`` over the interval.

    The bound: on the piece ``q`` of interval ``k`` (``tau = a_q + b t``, ``t`` in ``[0, 1]``, the
    piece's own variable, ``a_q = -1 + 2 q / s``, ``b = 2 / s``, ``s = K / n``, exact floats for
    ``K`` and ``n`` powers of 2) the deviation is a cubic in ``t``: its coefficients in ball
    arithmetic (the fit composed with ``a_q + b t`` by Horner's rule, the piece's coefficients as
    :func:`rotorlyap.methods.intervals.hermite_enclosure` forms them), bounded by the sum of their
    magnitudes. Returns ``(coeffs (n, degree + 1, 6), err (n, 6))``.
    """
    K = values.shape[0]
    sub = K // n
    j = np.arange(K)
    h = iv.pi() * 2.0 / float(K)
    P0, P1 = Balls(values), Balls(values[(j + 1) % K])
    B0, B1 = Balls(slopes) * h, Balls(slopes[(j + 1) % K]) * h
    dP = P1 - P0
    c = [P0, B0, dP * 3.0 - B0 * 2.0 - B1, B0 + B1 - dP * 2.0]    # piece(t) = sum c_i t^i, (K, 6) each
    # least squares at t = 0, 1/3, 2/3, 1 of every piece (float: any fit is valid, its error is bounded)
    t = np.array([0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0])
    val = sum(ci.mid[:, None, :] * t[None, :, None] ** i for i, ci in enumerate(c))    # (K, 4, 6)
    q = np.arange(sub)
    tau = -1.0 + (2.0 * q[:, None] + 2.0 * t[None, :]) / sub                          # (sub, 4)
    V = tau.reshape(-1)[:, None] ** np.arange(degree + 1)[None, :]                     # (4 sub, d + 1)
    Y = val.reshape(n, sub * 4, 6)
    coeffs = np.einsum("pm,kmi->kpi", np.linalg.pinv(V), Y)                            # (n, d + 1, 6)
    # the fit in each piece's variable: f(a_q + b t) = sum g_i t^i (balls), Horner's rule
    a_q = Balls(-1.0 + 2.0 * q / sub)                                                  # (sub,)
    b = Balls(2.0 / sub)
    C = coeffs[:, None, :, :]                                                          # (n, 1, d + 1, 6)
    g = [Balls(C[:, :, degree, :] + 0.0 * a_q.mid[None, :, None])]                     # (n, sub, 6)
    for d in range(degree - 1, -1, -1):
        # g(t) <- g(t) (a_q + b t) + C_d
        new = [g[0] * a_q.mid[None, :, None] + C[:, :, d, :]]
        for i in range(1, len(g)):
            new.append(g[i] * a_q.mid[None, :, None] + g[i - 1] * b)
        new.append(g[-1] * b)
        g = new
    err = None
    for i in range(max(len(g), 4)):
        piece = c[i].reshape(n, sub, 6) if i < 4 else Balls(np.zeros((n, sub, 6)))
        fit = g[i] if i < len(g) else Balls(np.zeros((n, sub, 6)))
        term = (piece - fit).magnitude()
        err = term if err is None else err + term
    err = Balls(err).upper() * (1.0 + 1e-12)                                           # the sums' roundings
    return coeffs, np.max(err, axis=1)


def taylor_evaluate(enclosure: BladeEnclosure, centre, radius, order: int, *,
                    n_intervals: int | None = None, strips=None, jacobian: bool = True,
                    energy_terms: bool = False) -> TaylorEvaluation:
    """The disturbed equations of the blade on Taylor models over boxes of disturbances.

    Parameters
    ----------
    enclosure : BladeEnclosure
        The blade and its steady motion, built with ``arithmetic="balls"``.
    centre : array_like, shape ``batch + (6,)``
        Centres of the boxes, disturbances ``x`` about the steady motion (rad, rad/rad).
    radius : array_like, shape ``batch + (6,)``
        Half-widths ``>= 0`` of the boxes (rad, rad/rad).
    order : int
        Order of the Taylor models (1 to :data:`rotorlyap.methods.taylor.MAX_ORDER`).
    n_intervals : int, optional
        None: equations that do not depend on the azimuth (:attr:`BladeEnclosure.constant`,
        hover), six model variables. Else the ``n`` uniform azimuth intervals of one period: the
        azimuth offset within each interval is a seventh variable (the last), ``batch`` must
        broadcast to ``(n,)`` (one box per interval), and the steady motion (a multiple ``n`` of
        its grid) enters as its exact piecewise cubic (``n`` a divisor of the grid: a cubic in the
        azimuth fitted to the pieces each interval spans, its deviation bounded, :func:`_fitted_motion`).
    strips : array_like of bool, optional
        The strips whose air loads enter (one flag per aerodynamic station; default all). Leaving
        some out encloses another blade than this one: it measures what each strip's loads add to
        the models' remainders (:func:`rotorlyap.analysis.proof.remainder_sources`), and proves
        nothing about the blade.
    jacobian : bool
        Also the Jacobian's models (default). Without, the state carries no gradient and the
        evaluation costs about a seventh (the right-hand side's models are the same).
    energy_terms : bool
        Evaluate the equations' terms by the generated ``rhs_dw_terms`` (the same rows and the
        energy's, :attr:`TaylorEvaluation.terms`), for the energy's ``W'`` on the same models.

    Returns
    -------
    TaylorEvaluation

    Raises
    ------
    ValueError
        Equations that depend on the azimuth without ``n_intervals``, an enclosure in Arb
        arithmetic, bad boxes or order.
    """
    if enclosure.arithmetic != "balls":
        raise ValueError("taylor_evaluate needs a BladeEnclosure built with arithmetic='balls'")
    if n_intervals is None and not enclosure.constant:
        raise ValueError("the equations depend on the azimuth: give n_intervals (the azimuth becomes a "
                         "model variable)")
    c = np.asarray(centre, dtype=float)
    r = np.asarray(radius, dtype=float)
    if c.shape[-1:] != (6,) or r.shape[-1:] != (6,):
        raise ValueError(f"centre and radius must have a last axis of 6, got {c.shape} and {r.shape}")
    c, r = np.broadcast_arrays(c, r)
    if strips is not None:
        strips = np.asarray(strips, dtype=bool).reshape(-1)
        if strips.size != enclosure.st.shape[1]:
            raise ValueError(f"strips must hold one flag per aerodynamic station ({enclosure.st.shape[1]}), "
                             f"got {strips.size}")
    sc = enclosure.sc
    with iv.arithmetic("balls"):
        if n_intervals is None:
            xs = tm.variables(enclosure.state + c, r, order)
            psi, dxi = None, None
        else:
            N = int(n_intervals)
            if N < 1:
                raise ValueError(f"n_intervals must be >= 1, got {n_intervals!r}")
            c, r = np.broadcast_to(c, (N, 6)), np.broadcast_to(r, (N, 6))
            ones = np.ones((N, 1))
            vs = tm.variables(np.hstack([c, 0 * ones]), np.hstack([r, ones]), order)
            tau = vs[6]
            psi = tau * (iv.pi() / float(N)) + Balls(np.arange(N) + 0.5) / float(N) * (iv.pi() * 2.0)
            xi, dxi = _steady_models(enclosure, tau, N)
            xs = [vs[i] + xi[i] for i in range(6)]
        shape = xs[0].shape
        sp = xs[0].space
        grads = _unit_gradients(6, shape, sp) if jacobian else [None] * 6
        z = [Jet(x, g) for x, g in zip(xs, grads)]
        c0, c1, c2 = enclosure.controls
        if psi is not None and sc[_CYCLIC] != 0.0:
            theta_c = tm.cos(psi) * c1 + tm.sin(psi) * c2 + c0
        else:
            theta_c = iv.const(c0)
        if energy_terms:
            T = [None] * 49
            x_r = [z[3 + i] - float(xi_rate) for i, xi_rate in enumerate(_steady_rates(enclosure))]
            _rhs_dw_terms(z[0], z[1], z[2], z[3], z[4], z[5], theta_c, x_r[0], x_r[1], x_r[2], enclosure.params, T)
        else:
            T = [None] * 42
            _rhs_terms(z[0], z[1], z[2], z[3], z[4], z[5], theta_c, enclosure.params, T)
        F = [T[6 + i] - z[3 + i] * float(sc[(_C0, _C1, _C2)[i]]) for i in range(3)]
        blocked = np.zeros(shape, dtype=bool)
        angles = None
        if sc[_ACTIVE] != 0.0:
            air, blocked, angles = _air_moments(enclosure, z, T, psi, strips)
            F = [f + a for f, a in zip(F, air)]
        om = iv.const(float(sc[_OMEGA]))
        s = 1 / (om * om)
        acc = [a * s for a in solve_sym3(T[0:6], F[0], F[1], F[2])]
    rows = [z[3], z[4], z[5]] + acc
    value = tm.stack([_as_model(q.v if dxi is None else q.v - dxi[i], shape, sp) for i, q in enumerate(rows)],
                     axis=-1)
    jac = None
    if jacobian:
        jac = tm.stack([_as_model(q.gradient(6), (6,) + shape, sp) for q in rows], axis=0)  # (6 rows, 6 cols) + batch
        jac = jac.moveaxis(0, -1).moveaxis(0, -1)
    if np.any(blocked):
        value = tm.where(~blocked[..., None], value, TaylorModel(np.full(value.coef.shape, np.nan), np.nan, sp))
        if jac is not None:
            jac = tm.where(~blocked[..., None, None], jac, TaylorModel(np.full(jac.coef.shape, np.nan), np.nan, sp))
    return TaylorEvaluation(value=value, jacobian=jac, centre=c, radius=r, order=int(order),
                            n_intervals=None if n_intervals is None else int(n_intervals), angles=angles,
                            state=list(xs), terms=[_value(t) for t in T] if energy_terms else None)


def _steady_rates(enclosure: BladeEnclosure) -> np.ndarray:
    """The steady motion's hinge rates (hover: its constant state's), rad/rad."""
    if enclosure.motion is not None:
        raise ValueError("energy_terms takes a constant steady motion (hover)")
    return np.asarray(enclosure.state[3:6], dtype=float)


def _value(t):
    """The value of a Jet (a model, balls or a float), else ``t``."""
    return t.v if isinstance(t, Jet) else t


def _as_model(x, shape: tuple, sp) -> TaylorModel:
    """A model of ``shape`` from a model, balls or a float."""
    if isinstance(x, TaylorModel):
        if x.shape != shape:
            return TaylorModel._new(np.broadcast_to(x.coef, shape + (sp.size,)), np.broadcast_to(x.rem, shape), sp)
        return x
    return TaylorModel.constant(x, sp, shape)
