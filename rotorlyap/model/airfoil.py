"""Static section aerodynamics over the full angle-of-attack range.

Two models share one interface, ``coefficients(alpha) -> (cl, cd, cm)``:

* :class:`Airfoil` -- a parametric full-range model of a cambered section:
  a linear lift curve rounded quadratically into the maximum lift, the
  Viterna-Corrigan post-stall extrapolation [ViternaCorrigan1982] out to
  90 deg, and a reverse-flow branch around +-180 deg in which the section acts
  as a thin, early-stalling plate with its trailing edge leading.
* :class:`LinearAirfoil` -- ``cl = a alpha``, ``cd = cd0``, ``cm = 0`` for
  closed-form checks against classical blade-element theory.

Conventions (see ``.notes/BLADE_SPEC.md``): ``alpha`` in rad, wrapped to
[-pi, pi); lift perpendicular and drag parallel to the relative wind;
``cm`` about the aerodynamic centre, positive nose up.  With these
conventions a flat plate has ``cl = cd_max sin(alpha) cos(alpha)`` and
``cd = cd_max sin(alpha)**2`` on the whole circle, so lift has period pi and
positive ``cl`` at ``alpha`` near pi means a force *towards the lower
surface*.  The normal-force coefficient (towards the upper surface) is
``cn = cl cos(alpha) + cd sin(alpha)``.

Citation keys refer to the report's ``references.bib``.

References
----------
- [Abbott1959] I. H. Abbott and A. E. von Doenhoff, *Theory of Wing
  Sections*, Dover, 1959, Appendix IV (NACA 23012 data).
- [JacobsClay1935] E. N. Jacobs and W. C. Clay, "Characteristics of the
  N.A.C.A. 23012 airfoil from tests in the full-scale and variable-density
  tunnels", NACA Report 530, 1935.
- [ViternaCorrigan1982] L. A. Viterna and R. D. Corrigan, "Fixed pitch rotor
  performance of large horizontal axis wind turbines", NASA CP-2230, 1982.
- [Hoerner1965] S. F. Hoerner, *Fluid-Dynamic Drag*, 1965.
- [SheldahlKlimas1981] R. E. Sheldahl and P. C. Klimas, "Aerodynamic
  characteristics of seven symmetrical airfoil sections through
  180-degree angle of attack ...", SAND80-2114, Sandia, 1981.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["Airfoil", "LinearAirfoil", "NACA23012", "grid_position", "wrap_angle"]

_DEG = math.pi / 180.0


def grid_position(alpha: ArrayLike, n: int) -> tuple[NDArray[np.intp], NDArray[np.float64]]:
    """The interval ``i`` and the fraction ``u`` in it of each angle ``alpha`` (rad) on the
    uniform periodic grid ``-pi + 2 pi k / n`` of a tabulated section: its coefficient is
    ``v[i] + u * d[i]`` (node values ``v``, increments ``d`` to the next node). The operations
    the compiled kernels repeat (:mod:`rotorlyap.model.compiled`), shared by
    :class:`Airfoil` and :class:`rotorlyap.model.c81.C81Section`."""
    u = np.mod(np.asarray(alpha, dtype=np.float64) + math.pi, 2.0 * math.pi)
    u *= n / (2.0 * math.pi)
    i = np.minimum(u.astype(np.intp), n - 1)  # u == n only through rounding
    return i, u - i


def wrap_angle(alpha: ArrayLike) -> NDArray[np.float64]:
    """Wrap angles to [-pi, pi).

    Parameters
    ----------
    alpha : array_like
        Angles, rad.

    Returns
    -------
    ndarray
        ``alpha`` wrapped to [-pi, pi), rad, same shape, float64.
    """
    a = np.asarray(alpha, dtype=np.float64)
    inside = (a >= -math.pi) & (a < math.pi)  # leave these bit-exact
    return np.where(inside, a, np.mod(a + math.pi, 2.0 * math.pi) - math.pi)


def _check_real(name: str, value: Any) -> float:
    """Return ``value`` as float; TypeError if not a real number, ValueError if not finite."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TypeError(f"{name} must be a real number, got {value!r} of type {type(value).__name__}")
    v = float(value)
    if not math.isfinite(v):
        raise ValueError(f"{name} must be finite, got {v!r}")
    return v


def _smoothstep(t: NDArray[np.float64]) -> NDArray[np.float64]:
    """C1 step from 0 (t <= 0) to 1 (t >= 1): 3 t^2 - 2 t^3."""
    t = np.clip(t, 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


@dataclass(frozen=True)
class _Branch:
    """One half-circle branch (|x| <= pi/2) of the full-range model; internal.

    Attached lift ``a (x - x0)``, rounded quadratically (C1) into ``cl_max`` at
    ``x_s`` and ``cl_min`` at ``x_sn``; beyond stall a smooth step of width
    ``blend`` takes the coefficients onto the Viterna-Corrigan curves anchored
    at the stall points; at |x| = pi/2 the branch reaches cl = 0, cd = cd_max.
    """

    a: float
    x0: float
    cl_max: float
    x_s: float
    cl_min: float
    x_sn: float
    cd0: float
    cl_i: float
    k: float
    cd_max: float
    blend: float

    @property
    def d_pos(self) -> float:
        """Width of the positive rounding interval, rad."""
        return 2.0 * (self.x_s - self.x0 - self.cl_max / self.a)

    @property
    def d_neg(self) -> float:
        """Width of the negative rounding interval, rad."""
        return 2.0 * (self.x0 + self.cl_min / self.a - self.x_sn)

    def _polar(self, cl: NDArray[np.float64]) -> NDArray[np.float64]:
        return self.cd0 + self.k * (cl - self.cl_i) ** 2

    def _viterna(self, x: NDArray[np.float64], xs: float, cls: float, cds: float):
        """Viterna-Corrigan curves through (xs, cls, cds), reaching (0, cd_max) at +-pi/2."""
        s, c = math.sin(xs), math.cos(xs)
        a1 = 0.5 * self.cd_max
        a2 = (cls - self.cd_max * s * c) * s / (c * c)
        b2 = (cds - self.cd_max * s * s) / c
        sx, cx = np.sin(x), np.cos(x)
        # the A2 term is only used on the side of the stall angle, where |sin x| >= |sin xs| > 0
        sx_safe = np.where(np.abs(sx) < 1e-6, np.copysign(1e-6, xs), sx)
        cl = a1 * np.sin(2.0 * x) + a2 * cx * cx / sx_safe
        cd = self.cd_max * sx * sx + b2 * cx
        return cl, cd

    def evaluate(self, x: NDArray[np.float64]):
        """Lift, drag and post-stall weight on the branch, for |x| <= pi/2."""
        a, x0 = self.a, self.x0
        cl_att = a * (x - x0)
        dp, dn = self.d_pos, self.d_neg
        if dp > 1e-12:
            rp = x > self.x_s - dp
            xc = np.minimum(x, self.x_s)  # hold cl_max beyond the stall angle
            cl_att = np.where(rp, self.cl_max - a / (2.0 * dp) * (self.x_s - xc) ** 2, cl_att)
        if dn > 1e-12:
            rn = x < self.x_sn + dn
            xc = np.maximum(x, self.x_sn)
            cl_att = np.where(rn, self.cl_min + a / (2.0 * dn) * (xc - self.x_sn) ** 2, cl_att)
        cl_att = np.clip(cl_att, self.cl_min, self.cl_max)  # holds the peaks beyond stall
        cd_att = self._polar(cl_att)

        pos = x >= self.x_s
        neg = x <= self.x_sn
        w = np.zeros_like(x)
        w = np.where(pos, _smoothstep((x - self.x_s) / self.blend), w)
        w = np.where(neg, _smoothstep((self.x_sn - x) / self.blend), w)

        clp, cdp = self._viterna(x, self.x_s, self.cl_max, float(self._polar(np.float64(self.cl_max))))
        cln, cdn = self._viterna(x, self.x_sn, self.cl_min, float(self._polar(np.float64(self.cl_min))))
        cl_post = np.where(x >= 0.5 * (self.x_s + self.x_sn), clp, cln)
        cd_post = np.where(x >= 0.5 * (self.x_s + self.x_sn), cdp, cdn)
        cl = (1.0 - w) * cl_att + w * cl_post
        cd = (1.0 - w) * cd_att + w * cd_post
        return cl, cd, w


@dataclass(frozen=True)
class Airfoil:
    """Parametric full-range static model of a cambered airfoil section.

    The angle of attack is wrapped to [-pi, pi) and split into a forward-flow
    half-circle (``|alpha| <= pi/2``) and a reverse-flow half-circle (around
    +-pi, local angle ``delta = alpha -+ pi``).  On each half:

    * attached flow: ``cl = a (alpha - alpha_0)``, rounded by a parabola (C1,
      slope ``a`` to slope 0) into ``cl_max`` at ``alpha_stall`` and into
      ``cl_min`` at ``alpha_stall_negative``; drag from the polar
      ``cd = cd_min + drag_rise (cl - cl_cd_min)**2``; ``cm = cm_ac``;
    * post stall: the Viterna-Corrigan extrapolation [ViternaCorrigan1982]
      anchored at the stall point, ``cl = cd_max/2 sin 2a + A2 cos^2 a / sin a``,
      ``cd = cd_max sin^2 a + B2 cos a``, entered through a C1 smooth step of
      width ``stall_blend``; it tends to the flat plate at 90 deg
      (``cl = 0``, ``cd = cd_max``) where the two halves join continuously;
    * moment: beyond stall and in reverse flow the normal force
      ``cn = cl cos a + cd sin a`` acts at a centre of pressure that travels
      linearly with the angle, ``x_cp = 0.25 + |alpha| / (2 pi)``: quarter
      chord at 0, mid-chord at 90 deg (flat plate broadside, [Hoerner1965]),
      three-quarter chord -- the quarter chord measured from the trailing
      edge -- at 180 deg; so ``cm = -cn (x_cp - x_ac)``.

    In reverse flow the section is a thin plate with its trailing edge leading:
    lift slope ``reverse_lift_slope``, zero lift at ``delta = -alpha_zero_lift``
    (the camber keeps pushing towards the upper surface, which in reverse flow
    is negative ``cl``), linear over the first half of the stall range and
    rounded (C1) over the second half into ``+-reverse_cl_max = +-0.75 a_r
    reverse_stall_angle`` at ``delta0 +- reverse_stall_angle``, then the same
    Viterna-Corrigan post-stall; drag ``reverse_cd_min + drag_rise cl**2``.

    The model is continuous on the whole circle and C1 except at +-90 deg
    (a small corner in ``cd``, where the forward and reverse Viterna drag
    curves meet) and at +-180 deg (a corner in the centre-of-pressure travel,
    hence in ``cm``).

    Parameters
    ----------
    lift_slope : float
        Lift-curve slope ``a`` of attached forward flow, 1/rad.
    alpha_zero_lift : float
        Zero-lift angle ``alpha_0``, rad (negative for positive camber).
    cl_max : float
        Maximum lift coefficient (positive stall), -.
    alpha_stall : float
        Angle of maximum lift, rad; must exceed ``alpha_0 + cl_max/a``.
    cl_min : float
        Minimum (most negative) lift coefficient, -.
    alpha_stall_negative : float
        Angle of minimum lift, rad; must be below ``alpha_0 + cl_min/a``.
    cd_min : float
        Minimum profile drag coefficient, -.
    cl_cd_min : float
        Lift coefficient at minimum drag, -.
    drag_rise : float
        Quadratic drag-rise factor ``k`` of the attached-flow polar, -.
    cm_ac : float
        Pitching moment coefficient about the aerodynamic centre (attached
        flow), positive nose up, -.
    aerodynamic_centre : float
        Chordwise position of the aerodynamic centre, fraction of chord behind
        the leading edge; the reference point of ``cm``.
    cd_max : float
        Drag coefficient of the section broadside to the flow (2-D flat plate),
        -.
    stall_blend : float
        Width of the smooth step from the rounded attached curve onto the
        post-stall curves, rad.
    reverse_lift_slope : float
        Lift-curve slope in reverse flow (near +-180 deg), 1/rad.
    reverse_stall_angle : float
        Stall angle in reverse flow, measured from the reverse zero-lift angle,
        rad.
    reverse_cd_min : float
        Drag coefficient at zero lift in reverse flow, -.
    name : str
        Label for plots and tables.
    table_size : int
        Number of intervals of the interpolation table used by
        :meth:`coefficients` (0: evaluate the model directly every call).
    """

    lift_slope: float
    alpha_zero_lift: float
    cl_max: float
    alpha_stall: float
    cl_min: float
    alpha_stall_negative: float
    cd_min: float
    cl_cd_min: float
    drag_rise: float
    cm_ac: float
    aerodynamic_centre: float
    cd_max: float = 1.98
    stall_blend: float = 3.0 * _DEG
    reverse_lift_slope: float | None = None
    reverse_stall_angle: float = 8.0 * _DEG
    reverse_cd_min: float | None = None
    name: str = "airfoil"
    table_size: int = 65536
    _forward: _Branch = field(init=False, repr=False, compare=False)
    _reverse: _Branch = field(init=False, repr=False, compare=False)
    _table: tuple = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        ts = self.table_size
        if isinstance(ts, (bool, np.bool_)) or not isinstance(ts, (int, np.integer)):
            raise TypeError(f"table_size must be an int (0 or >= 1024), got {ts!r}")
        if ts != 0 and ts < 1024:
            raise ValueError(f"table_size must be 0 (exact evaluation) or >= 1024, got {ts!r}")
        object.__setattr__(self, "table_size", int(ts))
        for f in fields(self):
            if f.name.startswith("_") or f.name in ("name", "table_size"):
                continue
            v = getattr(self, f.name)
            if v is None and f.name in ("reverse_lift_slope", "reverse_cd_min"):
                continue
            object.__setattr__(self, f.name, _check_real(f.name, v))
        if not isinstance(self.name, str):
            raise TypeError(f"name must be a str, got {self.name!r}")
        if self.reverse_lift_slope is None:
            object.__setattr__(self, "reverse_lift_slope", self.lift_slope)
        if self.reverse_cd_min is None:
            object.__setattr__(self, "reverse_cd_min", 2.0 * self.cd_min)

        def need(cond: bool, msg: str) -> None:
            if not cond:
                raise ValueError(msg)

        a = self.lift_slope
        need(a > 0, f"lift_slope must be > 0 1/rad, got {a!r}")
        need(abs(self.alpha_zero_lift) < 10 * _DEG,
             f"alpha_zero_lift must lie within +-10 deg (0.1745 rad), got {self.alpha_zero_lift!r} rad")
        need(self.cl_max > 0, f"cl_max must be > 0, got {self.cl_max!r}")
        need(self.cl_min < 0, f"cl_min must be < 0, got {self.cl_min!r}")
        need(0 < self.alpha_stall < 45 * _DEG,
             f"alpha_stall must lie in (0, 45 deg) = (0, 0.785) rad, got {self.alpha_stall!r}")
        need(-45 * _DEG < self.alpha_stall_negative < 0,
             f"alpha_stall_negative must lie in (-45 deg, 0) = (-0.785, 0) rad, got {self.alpha_stall_negative!r}")
        need(self.alpha_stall > self.alpha_zero_lift + self.cl_max / a,
             "alpha_stall must exceed alpha_zero_lift + cl_max/lift_slope "
             f"= {self.alpha_zero_lift + self.cl_max / a!r} rad (the lift curve bends over before stall), "
             f"got {self.alpha_stall!r}")
        need(self.alpha_stall_negative < self.alpha_zero_lift + self.cl_min / a,
             "alpha_stall_negative must be below alpha_zero_lift + cl_min/lift_slope "
             f"= {self.alpha_zero_lift + self.cl_min / a!r} rad, got {self.alpha_stall_negative!r}")
        need(self.cd_min > 0, f"cd_min must be > 0, got {self.cd_min!r}")
        need(self.drag_rise >= 0, f"drag_rise must be >= 0, got {self.drag_rise!r}")
        need(0.0 <= self.aerodynamic_centre <= 1.0,
             f"aerodynamic_centre must lie in [0, 1] (fraction of chord), got {self.aerodynamic_centre!r}")
        need(self.cd_max > max(self.cd_min, self.reverse_cd_min),
             f"cd_max must exceed cd_min and reverse_cd_min, got {self.cd_max!r}")
        need(0 < self.stall_blend <= 20 * _DEG,
             f"stall_blend must lie in (0, 20 deg] = (0, 0.349] rad, got {self.stall_blend!r}")
        need(self.reverse_lift_slope > 0, f"reverse_lift_slope must be > 0 1/rad, got {self.reverse_lift_slope!r}")
        need(0 < self.reverse_stall_angle < 30 * _DEG,
             f"reverse_stall_angle must lie in (0, 30 deg) = (0, 0.524) rad, got {self.reverse_stall_angle!r}")
        need(self.reverse_cd_min > 0, f"reverse_cd_min must be > 0, got {self.reverse_cd_min!r}")

        fwd = _Branch(a=a, x0=self.alpha_zero_lift, cl_max=self.cl_max, x_s=self.alpha_stall,
                      cl_min=self.cl_min, x_sn=self.alpha_stall_negative, cd0=self.cd_min,
                      cl_i=self.cl_cd_min, k=self.drag_rise, cd_max=self.cd_max, blend=self.stall_blend)
        d0 = -self.alpha_zero_lift
        ar, ds = self.reverse_lift_slope, self.reverse_stall_angle
        # reverse flow: linear over the first half of the stall range, rounded over the second
        # half (rounding width ds/2), so cl_max_r = a_r * (ds - ds/4)
        rev = _Branch(a=ar, x0=d0, cl_max=self.reverse_cl_max, x_s=d0 + ds, cl_min=-self.reverse_cl_max,
                      x_sn=d0 - ds, cd0=self.reverse_cd_min, cl_i=0.0, k=self.drag_rise,
                      cd_max=self.cd_max, blend=self.stall_blend)
        object.__setattr__(self, "_forward", fwd)
        object.__setattr__(self, "_reverse", rev)
        if self.table_size:
            n = self.table_size
            grid = np.linspace(-math.pi, math.pi, n + 1)
            tabs = []
            for t in self.exact_coefficients(grid):
                t = t.copy()
                t[-1] = t[0]  # periodic closure (alpha = pi is wrapped to -pi)
                v, d = t[:-1].copy(), np.diff(t)
                v.flags.writeable = False
                d.flags.writeable = False
                tabs.append((v, d))
            object.__setattr__(self, "_table", tuple(tabs))
        else:
            object.__setattr__(self, "_table", ())

    def table_rows(self) -> NDArray[np.float64] | None:
        """The table of :meth:`coefficients` as one read-only array, one row per grid point, or
        None with ``table_size = 0``. Made at the first call and kept.

        Returns
        -------
        numpy.ndarray, shape (table_size, 6) or None
            Columns: value and increment of cl, cd and cm on the grid
            ``-pi + 2 pi k / table_size`` (the compiled kernels of
            :mod:`rotorlyap.model.compiled` interpolate in it; one lookup reads one row).
        """
        if not self._table:
            return None
        rows = self.__dict__.get("_table_rows")
        if rows is None:
            rows = np.ascontiguousarray(np.stack([a for pair in self._table for a in pair], axis=1))
            rows.flags.writeable = False
            object.__setattr__(self, "_table_rows", rows)
        return rows

    @property
    def reverse_cl_max(self) -> float:
        """Largest lift coefficient of the reverse-flow branch (at its stall), -."""
        return 0.75 * self.reverse_lift_slope * self.reverse_stall_angle

    def coefficients(self, alpha: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
        """Lift, drag and moment coefficients at the angles of attack ``alpha``.

        With ``table_size > 0`` (default) the model is tabulated once on a
        uniform periodic grid of ``table_size`` intervals over [-pi, pi) and
        interpolated linearly: exact on the linear part of the lift curve,
        within about 1e-7 on the curved parts and 1e-4 at the few corners of
        the model (e.g. the drag at +-90 deg), about ten times faster than
        :meth:`exact_coefficients`.  ``table_size = 0`` always evaluates the
        model directly.

        Parameters
        ----------
        alpha : array_like
            Angle of attack, rad, any shape; wrapped to [-pi, pi).

        Returns
        -------
        cl, cd, cm : ndarray
            Lift, drag and pitching-moment (about the aerodynamic centre,
            positive nose up) coefficients, same shape as ``alpha``.
        """
        if not self._table:
            return self.exact_coefficients(alpha)
        i, u = grid_position(alpha, self.table_size)
        (v_l, d_l), (v_d, d_d), (v_m, d_m) = self._table
        cl = v_l[i] + u * d_l[i]
        cd = v_d[i] + u * d_d[i]
        cm = v_m[i] + u * d_m[i]
        return cl, cd, cm

    def exact_coefficients(self, alpha: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
        """The model evaluated directly (no table); same interface as :meth:`coefficients`."""
        al = wrap_angle(alpha)
        shape = al.shape
        al = al.ravel()
        fwd = np.abs(al) <= 0.5 * math.pi
        cl = np.empty_like(al)
        cd = np.empty_like(al)
        w = np.empty_like(al)
        xf = al[fwd]
        cl[fwd], cd[fwd], w[fwd] = self._forward.evaluate(xf)
        rv = ~fwd
        xr = al[rv]
        xr = xr - np.copysign(math.pi, xr)
        clr, cdr, _ = self._reverse.evaluate(xr)
        cl[rv], cd[rv] = clr, cdr
        w[rv] = 1.0  # reverse flow: moment always from the normal force at x_cp
        ca, sa = np.cos(al), np.sin(al)
        cn = cl * ca + cd * sa
        x_cp = 0.25 + np.abs(al) / (2.0 * math.pi)
        cm_post = -cn * (x_cp - self.aerodynamic_centre)
        cm = (1.0 - w) * self.cm_ac + w * cm_post
        return cl.reshape(shape), cd.reshape(shape), cm.reshape(shape)


@dataclass(frozen=True)
class LinearAirfoil:
    """Thin-airfoil linear section, either edge leading: ``cl = a alpha'``, ``cd = cd0``, ``cm = 0``.

    For closed-form checks against classical blade-element theory (e.g. the
    hover coning angle, or the flap stability of a rotor at high advance
    ratio).  ``alpha`` is wrapped to [-pi, pi) like :class:`Airfoil`, and
    ``alpha'`` is the angle between the relative wind and the chord line,
    measured from whichever edge the air meets first:

    * forward flow, ``|alpha| <= pi/2``: ``alpha' = alpha``;
    * reverse flow, ``|alpha| > pi/2`` (the air meets the trailing edge first):
      ``alpha' = alpha - copysign(pi, alpha)``, i.e. ``alpha - pi`` for
      ``alpha > pi/2`` and ``alpha + pi`` for ``alpha < -pi/2``,

    so ``alpha'`` lies in [-pi/2, pi/2] and ``cl = a alpha'`` is the lift of a
    thin plate with the other edge leading, exactly as :class:`Airfoil` treats
    reverse flow with its reverse branch (lift slope ``a`` for either edge
    leading, as thin-airfoil theory gives for a symmetric plate).  This is the
    classical linear treatment of reverse flow in blade-element theory at high
    advance ratio: to first order in the perpendicular velocity ``u_P`` the
    section lift is ``(rho a c / 2) (u_T |u_T| theta - u_P |u_T|)`` with the
    signed tangential velocity ``u_T`` (negative in reverse flow), the form of
    the classical flap-stability analyses [Sissingh1968], [PetersHohenemser1971]
    (see also [Johnson1980]); ``tests/test_high_mu.py`` checks the blade built
    on it against that equation.

    Direction of the force (the blade's convention, :mod:`rotorlyap.model.aero`):
    ``alpha = atan2(w_z, -w_y)`` with ``(w_y, w_z)`` the in-plane air velocity
    relative to the section, and ``F_y = qn (cd w_y + cl w_z)``, ``F_z = qn
    (cd w_z - cl w_y)`` with ``qn > 0``.  A flat plate (``cd0 = 0``) with the
    air coming from below at a small angle ``eps`` (``w_z = V sin eps``,
    ``eps > 0``):

    * forward flow, ``w_y = -V cos eps``: ``alpha = eps``, ``cl = a eps``,
      ``F_z = qn a eps V cos eps > 0``;
    * reverse flow, ``w_y = +V cos eps``: ``alpha = pi - eps``,
      ``alpha' = -eps``, ``cl = -a eps``, ``F_z = qn a eps V cos eps > 0``;

    upwards in both, as for a plate pushed up by an up-going air stream
    whichever edge leads.  (Wrapping alone, ``cl = a alpha``, would give
    ``cl ~ a pi`` and a large downward force in reverse flow.)

    ``cl`` jumps from ``a pi/2`` to ``-a pi/2`` (and back) at ``|alpha| =
    pi/2``, where the flow meets the section broadside.  There the in-plane
    speed along the chord ``w_y`` is zero, so ``F_z`` (the ``cl`` term is
    ``-cl w_y``) stays continuous; ``F_y`` (``cl w_z``) jumps sign.  The linear
    model is meant for small ``|alpha'|``; near 90 deg it is as unphysical as
    any linear lift curve, only the weighting by ``w_y`` makes the jump
    harmless for ``F_z``.

    Parameters
    ----------
    lift_slope : float
        Lift-curve slope ``a``, 1/rad (thin-airfoil theory: 2 pi), either edge leading.
    cd0 : float
        Constant profile drag coefficient, -, >= 0.
    name : str
        Label.
    """

    lift_slope: float = 2.0 * math.pi
    cd0: float = 0.0
    name: str = "linear"

    def __post_init__(self) -> None:
        object.__setattr__(self, "lift_slope", _check_real("lift_slope", self.lift_slope))
        object.__setattr__(self, "cd0", _check_real("cd0", self.cd0))
        if self.lift_slope <= 0:
            raise ValueError(f"lift_slope must be > 0 1/rad, got {self.lift_slope!r}")
        if self.cd0 < 0:
            raise ValueError(f"cd0 must be >= 0, got {self.cd0!r}")
        if not isinstance(self.name, str):
            raise TypeError(f"name must be a str, got {self.name!r}")

    @staticmethod
    def flow_angle(alpha: ArrayLike) -> NDArray[np.float64]:
        """Angle ``alpha'`` between the relative wind and the chord line, from the leading edge of the flow.

        Parameters
        ----------
        alpha : array_like
            Angle of attack, rad, any shape; wrapped to [-pi, pi).

        Returns
        -------
        ndarray
            ``alpha`` for ``|alpha| <= pi/2`` (forward flow), ``alpha - copysign(pi, alpha)``
            beyond (reverse flow); in [-pi/2, pi/2], rad, same shape as ``alpha``.
        """
        al = wrap_angle(alpha)
        return np.where(np.abs(al) <= 0.5 * math.pi, al, al - np.copysign(math.pi, al))

    def coefficients(self, alpha: ArrayLike) -> tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]:
        """Linear coefficients at ``alpha`` (rad, any shape, wrapped to [-pi, pi)).

        Returns
        -------
        cl, cd, cm : ndarray
            ``a alpha'`` (``alpha'`` from :meth:`flow_angle`: ``alpha`` in forward flow,
            ``alpha -+ pi`` in reverse flow), ``cd0`` and 0, same shape as ``alpha``.
        """
        al = self.flow_angle(alpha)
        return self.lift_slope * al, np.full_like(al, self.cd0), np.zeros_like(al)


#: NACA 23012 at Reynolds number about 6e6, smooth surface: see the field notes
#: in :data:`NACA23012_SOURCES` for the source of every number.
NACA23012 = Airfoil(
    lift_slope=0.107 / _DEG,
    alpha_zero_lift=-1.2 * _DEG,
    cl_max=1.79,
    alpha_stall=18.0 * _DEG,
    cl_min=-1.20,
    alpha_stall_negative=-15.0 * _DEG,
    cd_min=0.0060,
    cl_cd_min=0.10,
    drag_rise=0.010,
    cm_ac=-0.014,
    aerodynamic_centre=0.247,
    cd_max=1.98,
    stall_blend=3.0 * _DEG,
    reverse_lift_slope=None,
    reverse_stall_angle=8.0 * _DEG,
    reverse_cd_min=None,
    name="NACA 23012",
)

#: Source or reason of each number of :data:`NACA23012` (keys of the report's ``references.bib``).
#: The Abbott1959 numbers are the section summary values of the book's Appendix IV
#: (the same data as NACA Report 824, AbbottEtAl1945); they were not re-read from a
#: scanned page when this module was written: check them against the book.
NACA23012_SOURCES: dict[str, str] = {
    "lift_slope": "Abbott1959 (App. IV, NACA 23012, Re 6e6): a0 = 0.107 /deg",
    "alpha_zero_lift": "Abbott1959: alpha_L0 = -1.2 deg",
    "cl_max": "Abbott1959: cl_max = 1.79 (Re 6e6, smooth)",
    "alpha_stall": "Abbott1959: maximum lift near 18 deg",
    "cl_min": "assumed from Abbott1959 negative-lift curves (about -1.2)",
    "alpha_stall_negative": "assumed from Abbott1959 negative-lift curves (about -15 deg)",
    "cd_min": "Abbott1959: cd_min = 0.006 (smooth, Re 6e6)",
    "cl_cd_min": "Abbott1959 drag polar: minimum drag near cl = 0.1",
    "drag_rise": "assumed: cd about 0.035 at cl_max, typical of a section near stall",
    "cm_ac": "Abbott1959: cm_ac = -0.014",
    "aerodynamic_centre": "Abbott1959: x_ac = 0.247 c",
    "cd_max": "Hoerner1965: 2-D flat plate normal to the flow, cd = 1.98; ViternaCorrigan1982 use 2.01 for AR > 50",
    "stall_blend": "assumed: 3 deg, an abrupt leading-edge stall (JacobsClay1935)",
    "reverse_lift_slope": "assumed: equal to the forward slope (thin-airfoil theory, 2 pi for either edge leading)",
    "reverse_stall_angle": "assumed: 8 deg, a sharp (trailing) edge leading stalls early (SheldahlKlimas1981)",
    "reverse_cd_min": "assumed: twice cd_min, blunt edge trailing (SheldahlKlimas1981)",
}
