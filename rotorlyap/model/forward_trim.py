"""Trim of the helicopter in forward flight: the rotor carries the weight and pulls against the drag.

The paper keeps the hover collective, no cyclic pitch and an untilted disc at every advance
ratio. Its blade then lifts far more than the weight in forward flight (the advancing side
gains more than the retreating side loses). A trimmed helicopter instead balances, in the
longitudinal plane and with the rotor as the only lifting and propulsive surface,

* the weight ``W = helicopter_mass * gravity`` (vertical),
* the drag of the airframe, ``D = 0.5 rho V^2 f`` with the equivalent flat-plate area ``f =
  params.flat_plate_area`` (horizontal, aft),
* the rotor's mean force: the thrust ``T`` along the shaft and the H-force ``H`` in the shaft
  plane, aft, both the mean over a revolution of the blade's aerodynamic force resolved in the
  non-rotating hub axes, times the number of blades (the blade's inertial force has zero mean
  over a period of a periodic motion, so the aerodynamic mean is the whole hub force).

With the shaft tilted forward by ``alpha_s`` (``params.shaft_tilt``) the balance reads
[Johnson1980, ch. 5], [Leishman2006, ch. 5]::

    T cos(alpha_s) + H sin(alpha_s) = W            (vertical)
    T sin(alpha_s) - H cos(alpha_s) = D            (horizontal)

and the flight speed is ``V = mu Omega R / cos(alpha_s)`` (``mu`` is the in-plane advance ratio
of the blade model). The induced inflow is Glauert's momentum value for the thrust the blade
actually produces and the whole flow through the disc, ``lambda_i = C_T / (2 sqrt(mu^2 + (mu
tan(alpha_s) + lambda_i)^2))``. The cyclic pitch makes the first harmonics of flapping zero (the
tip-path plane stays perpendicular to the shaft; with the small hinge offset of Table I, about
1 % of the radius, the hub moment is then small too). The periodic motion (Fourier collocation,
as :func:`rotorlyap.model.steady.periodic_motion`), the collective, the cyclic, the shaft tilt
and the inflow are solved together by one Newton iteration from the trimmed hover state;
where it does not converge, by continuation in ``mu`` from hover.

Simplifications, stated: no fuselage pitching moment or download, no tail rotor, the lateral
(side) force is reported but not balanced (a small roll of the helicopter would), and the blade's
weight stays along the shaft (the tilt of a few degrees turns a fraction ``sin(alpha_s)`` of the
blade weight, under 1 % of the centrifugal force, into the disc plane).

The three conditions of the report (:data:`TRIM_TARGETS`):

``"propulsive"``
    the trimmed helicopter above (the report's default for forward flight);
``"flapping"``
    the paper's hover collective and inflow (thrust = weight in momentum theory, untilted disc),
    with cyclic pitch for zero first-harmonic flapping;
``"none"``
    the paper's condition: hover collective, no cyclic, untilted disc, inflow for thrust = weight.

Citation keys refer to the report's ``references.bib``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import lru_cache

import numpy as np

from ..conventions import MAX_ADVANCE_RATIO, TWO_PI
from ..errors import PeriodicMotionError, TrimError
from .blade import Blade
from .inflow import mean_inflow, momentum_inflow
from .parameters import BladeParameters
from .steady import PeriodicMotion, SteadyMotion, _differentiation_matrix, _first_harmonics, periodic_motion
from .trim import _with_advice, check_trimmed_pitch

__all__ = ["TRIM_TARGETS", "ForwardFlightTrim", "forward_flight_trim", "rotor_forces"]

TRIM_TARGETS: tuple[str, ...] = ("propulsive", "flapping", "none")
"""Flight conditions :func:`forward_flight_trim` computes (see the module docstring)."""

_N_AZIMUTH = 64  # collocation points of the periodic motion; the rotor forces are means over them


@dataclass(frozen=True)
class ForwardFlightTrim:
    """Result of :func:`forward_flight_trim`.

    Attributes
    ----------
    target : str
        One of :data:`TRIM_TARGETS`.
    mu : float
        In-plane advance ratio ``V cos(alpha_s) / (Omega R)``, -.
    params : BladeParameters
        The blade with the trimmed controls and flight state: ``collective``, ``cyclic_cos``,
        ``cyclic_sin`` (rad), ``shaft_tilt`` (rad) and ``inflow_ratio`` (the induced inflow).
    motion : PeriodicMotion
        The periodic motion of the blade at that trim.
    thrust : float
        Rotor thrust ``T``, the mean force along the shaft, N.
    h_force : float
        Rotor H-force, the mean in-plane force, positive aft (downstream), N.
    side_force : float
        Rotor side force, positive towards the advancing side, N (not balanced).
    weight : float
        Helicopter weight, N.
    drag : float
        Airframe drag ``0.5 rho V^2 f``, N.
    flight_speed : float
        ``V``, m/s.
    induced_inflow : float
        Induced inflow ratio ``lambda_i``, -.
    iterations : int
        Newton iterations of the trim (0 for ``"none"`` and ``"flapping"``).
    """

    target: str
    mu: float
    params: BladeParameters
    motion: PeriodicMotion
    thrust: float
    h_force: float
    side_force: float
    weight: float
    drag: float
    flight_speed: float
    induced_inflow: float
    iterations: int

    @property
    def steady(self) -> SteadyMotion:
        """The trim's steady motion for the analyses (``steady=`` of
        :func:`rotorlyap.analysis.stability.blade_stability` and
        :func:`rotorlyap.analysis.floquet.blade_floquet`): the periodic motion, or in hover its
        constant state. Pass it rather than leaving the steady motion to :class:`Blade`: past a
        fold of the hover branch, a new equilibrium at the trimmed collective is another one."""
        if self.mu == 0.0:
            return SteadyMotion.constant(self.motion.z0.copy(), "trimmed hover")
        return self.motion.steady

    @property
    def shaft_tilt(self) -> float:
        """Forward shaft tilt ``alpha_s``, rad."""
        return self.params.shaft_tilt

    @property
    def vertical_force(self) -> float:
        """``T cos(alpha_s) + H sin(alpha_s)``, the rotor force upwards, N."""
        a = self.params.shaft_tilt
        return self.thrust * math.cos(a) + self.h_force * math.sin(a)

    @property
    def propulsive_force(self) -> float:
        """``T sin(alpha_s) - H cos(alpha_s)``, the rotor force forwards, N."""
        a = self.params.shaft_tilt
        return self.thrust * math.sin(a) - self.h_force * math.cos(a)

    @property
    def lift_over_weight(self) -> float:
        """Vertical rotor force over the weight, -: 1 for a trimmed helicopter."""
        return self.vertical_force / self.weight

    @property
    def thrust_coefficient(self) -> float:
        """``C_T = T / (rho pi R^2 (Omega R)^2)``, -."""
        p = self.params
        return self.thrust / (p.air_density * math.pi * p.radius ** 2 * p.tip_speed ** 2)

    @property
    def controls_deg(self) -> tuple[float, float, float]:
        """Collective, ``cyclic_cos`` and ``cyclic_sin``, deg."""
        p = self.params
        return (math.degrees(p.collective), math.degrees(p.cyclic_cos), math.degrees(p.cyclic_sin))


def rotor_forces(params: BladeParameters, motion: PeriodicMotion) -> tuple[float, float, float]:
    """Mean rotor force of ``n_blades`` blades on a periodic motion, non-rotating shaft axes.

    The blade's aerodynamic force in the rotating hub frame (radial ``F_r``, in-plane towards
    the rotation ``F_t``, along the shaft ``F_z``) is turned to the non-rotating axes (x aft,
    y towards the advancing side, z up the shaft) at each of the motion's collocation azimuths
    and averaged: ``H = N <F_r cos psi - F_t sin psi>``, ``Y = N <F_r sin psi + F_t cos psi>``,
    ``T = N <F_z>`` (the mean of a trigonometric polynomial sampled on its collocation grid).

    Parameters
    ----------
    params : BladeParameters
        The blade, with its collective.
    motion : PeriodicMotion
        Its periodic motion.

    Returns
    -------
    thrust, h_force, side_force : float
        N (see :class:`ForwardFlightTrim`).
    """
    psi = TWO_PI * np.arange(_N_AZIMUTH) / _N_AZIMUTH
    f = Blade(params, motion.mu).blade_aerodynamic_force(psi, motion.xi(psi))
    c, s = np.cos(psi), np.sin(psi)
    n = params.n_blades
    h = n * float(np.mean(f[:, 0] * c - f[:, 1] * s))
    y = n * float(np.mean(f[:, 0] * s + f[:, 1] * c))
    t = n * float(np.mean(f[:, 2]))
    return t, h, y


def _drag(params: BladeParameters, mu: float, tilt: float) -> tuple[float, float]:
    v = mu * params.tip_speed / math.cos(tilt)
    return 0.5 * params.air_density * v * v * params.flat_plate_area, v


def _frozen(trim: ForwardFlightTrim) -> ForwardFlightTrim:
    """``trim`` with the arrays of its motion made read-only (the result is cached and shared)."""
    for a in (trim.motion.z0, trim.motion.coefficients, trim.motion.harmonics_deg):
        a.flags.writeable = False
    return trim


@lru_cache(maxsize=128)
def forward_flight_trim(params: BladeParameters, mu: float, target: str = "propulsive", *,
                        tol: float = 1e-9, max_iter: int = 30) -> ForwardFlightTrim:
    """Trim the blade's rotor at advance ratio ``mu`` for the flight condition ``target``.

    Parameters
    ----------
    params : BladeParameters
        The blade and helicopter (``helicopter_mass``, ``flat_plate_area``). Its
        ``collective``, ``cyclic_*``, ``shaft_tilt`` and ``inflow_ratio`` are replaced for
        ``"propulsive"``; for ``"flapping"`` and ``"none"`` they are used as given (a ``None``
        collective is trimmed in hover, the paper's choice).
    mu : float
        In-plane advance ratio, in ``[0, MAX_ADVANCE_RATIO]``; at 0 the helicopter hovers.
    target : str
        One of :data:`TRIM_TARGETS`.
    tol : float
        Convergence of ``"propulsive"``: the collocation residuals of the periodic motion
        (rad/rad, rad/rad^2), its first flapping harmonics (rad), the force-balance residuals over
        the weight and the momentum residual over the hover inflow, all below ``tol``.
    max_iter : int
        Largest number of Newton iterations.

    Returns
    -------
    ForwardFlightTrim
        Kept (``functools.lru_cache``): its arrays are read-only.

    Raises
    ------
    ValueError
        Unknown ``target``, bad ``mu``, or a helicopter without weight or air.
    rotorlyap.errors.TrimError
        If the trim does not converge (with the residual reached), or no periodic motion is
        found on the way.
    """
    if not isinstance(target, str) or target not in TRIM_TARGETS:
        raise ValueError(f"target must be one of {TRIM_TARGETS}, got {target!r}")
    mu = float(mu)
    if not (math.isfinite(mu) and 0.0 <= mu <= MAX_ADVANCE_RATIO):
        raise ValueError(f"mu must be an advance ratio in [0, {MAX_ADVANCE_RATIO:g}], got {mu!r}")
    if params.air_density <= 0.0 or params.weight <= 0.0:
        raise ValueError("forward_flight_trim needs air (air_density > 0) and a weight (helicopter_mass * "
                         f"gravity > 0), got air_density = {params.air_density!r}, weight = {params.weight!r} N")
    base = Blade(params, 0.0).params  # the hover collective filled in if it was None
    weight = params.weight

    def solve(p: BladeParameters, start=None) -> PeriodicMotion:
        try:
            return periodic_motion(p, mu, trim_flapping=(target != "none"), n_points=_N_AZIMUTH,
                                   start=start)
        except PeriodicMotionError as exc:
            raise TrimError(f"forward_flight_trim ({target}, mu = {mu:g}): {exc}") from exc

    if target != "propulsive":
        if target == "none":
            base = replace(base, cyclic_cos=0.0, cyclic_sin=0.0)
        base = replace(base, shaft_tilt=0.0)
        motion = solve(base)
        t, h, y = rotor_forces(motion.params, motion)
        drag, v = _drag(base, mu, 0.0)
        return _frozen(ForwardFlightTrim(target=target, mu=mu, params=motion.params, motion=motion, thrust=t,
                                         h_force=h, side_force=y, weight=weight, drag=drag, flight_speed=v,
                                         induced_inflow=mean_inflow(base, mu), iterations=0))

    # Newton from the drag-tilted hover state; where it does not converge (a heavily coupled
    # blade far from hover), continuation in mu from hover in steps of at most 0.05
    try:
        trim = _propulsive_with_continuation(params, base, mu, tol, max_iter)
    except TrimError as exc:
        raise _with_advice(exc, params) from exc.__cause__
    check_trimmed_pitch(params, trim.params.collective, f"forward_flight_trim (mu = {mu:g})")
    return trim


def _propulsive_with_continuation(params: BladeParameters, base: BladeParameters, mu: float, tol: float,
                                  max_iter: int) -> ForwardFlightTrim:
    try:
        return _frozen(_propulsive(params, base, mu, None, tol, max_iter))
    except TrimError as first:
        n = max(2, int(math.ceil(mu / 0.05)))
        guess = None
        try:
            for m in np.linspace(0.0, mu, n + 1)[1:]:
                tr = _propulsive(params, base, float(m), guess, tol, max_iter)
                p_ = tr.params
                guess = (np.array([p_.collective, p_.cyclic_cos, p_.cyclic_sin, p_.shaft_tilt, tr.induced_inflow]),
                         tr.motion.xi(TWO_PI * np.arange(_N_AZIMUTH) / _N_AZIMUTH))
        except TrimError as exc:
            raise TrimError(f"{first}; continuation in mu from hover failed too: {exc}") from exc
        return _frozen(tr)


def _propulsive(params: BladeParameters, base: BladeParameters, mu: float, guess, tol: float,
                max_iter: int) -> ForwardFlightTrim:
    """Newton's method on the whole trim at one ``mu``; ``guess`` = (controls, states) or None.

    One system holds the collocation equations of the periodic motion (the states at
    ``_N_AZIMUTH`` azimuths, as in :func:`rotorlyap.model.steady.periodic_motion`), the two
    first flapping harmonics, the two force balances and the momentum equation; the unknowns
    are the states and ``c = (collective, cyclic_cos, cyclic_sin, shaft_tilt, lambda_i)``. The
    Jacobian is exact in the states (the blade's Jacobian) and by finite differences in ``c``;
    the force rows' dependence on the states is differenced one state component at a time over
    all azimuths at once (each azimuth's force depends on its own state only).
    """
    weight = params.weight
    n = _N_AZIMUTH
    psi = TWO_PI * np.arange(n) / n
    D = _differentiation_matrix(n)
    cos_w, sin_w = 2.0 * np.cos(psi) / n, 2.0 * np.sin(psi) / n
    cp, sp = np.cos(psi), np.sin(psi)
    N = params.n_blades
    disc = params.air_density * math.pi * params.radius ** 2 * params.tip_speed ** 2  # T = C_T * disc
    lam_hover = math.sqrt(0.5 * weight / disc)

    if guess is None:
        d0, _ = _drag(params, mu, 0.0)
        tilt0 = math.atan2(d0, weight)
        lam0 = float(momentum_inflow(math.hypot(weight, d0) / disc, mu, through_flow=mu * math.tan(tilt0)))
        c = np.array([base.collective, 0.0, 0.0, tilt0, lam0])
        Z = np.tile(Blade(params, 0.0).equilibrium(), (n, 1))  # the trimmed hover state
    else:
        c, Z = np.array(guess[0], dtype=float), np.array(guess[1], dtype=float)

    def blade_for(c: np.ndarray) -> Blade:
        theta0, c1, s1, tilt, lam = (float(v) for v in c)
        if not abs(tilt) < math.radians(30.0) or lam <= 0.0 or lam + mu * math.tan(tilt) <= 0.0:
            raise TrimError(f"forward_flight_trim (mu = {mu:g}): the iteration left the physical range "
                            f"(shaft tilt {math.degrees(tilt):.3g} deg, induced inflow {lam:.3g}); "
                            "allowed: tilt in (-30, 30) deg, induced and whole inflow > 0")
        return Blade(replace(base, collective=theta0, cyclic_cos=c1, cyclic_sin=s1, shaft_tilt=tilt,
                             inflow_ratio=lam), mu)

    def forces(blade: Blade, Z: np.ndarray) -> np.ndarray:
        f = blade.blade_aerodynamic_force(psi, Z)
        return np.array([N * np.mean(f[:, 2]), N * np.mean(f[:, 0] * cp - f[:, 1] * sp)])  # T, H

    def residual(c: np.ndarray, Z: np.ndarray, blade: Blade | None = None):
        blade = blade_for(c) if blade is None else blade
        t, h = forces(blade, Z)
        tilt, lam = float(c[3]), float(c[4])
        drag, _ = _drag(params, mu, tilt)
        ca, sa = math.cos(tilt), math.sin(tilt)
        r = np.concatenate([
            (D @ Z - blade.rhs(psi, Z)).reshape(-1),
            [cos_w @ Z[:, 0], sin_w @ Z[:, 0]],
            [(t * ca + h * sa - weight) / weight,
             (t * sa - h * ca - drag) / weight,
             (lam - (t / disc) / (2.0 * math.hypot(mu, mu * math.tan(tilt) + lam))) / lam_hover],
        ])
        return r, blade

    r, blade = residual(c, Z)
    err = float(np.abs(r).max())
    m = 6 * n
    steps_c = np.array([1e-6, 1e-6, 1e-6, 1e-6, 1e-7])
    it = 0
    while not err < tol:
        if it >= max_iter:
            raise TrimError(f"forward_flight_trim (propulsive, mu = {mu:g}) did not converge in {max_iter} "
                            f"Newton iterations: residual {err:.2g} (converged means < {tol:.1g})",
                            residual=err, tolerance=tol, iterations=it)
        J = np.zeros((m + 5, m + 5))
        J[:m, :m] = np.kron(D, np.eye(6))
        jac = blade.jacobian(psi, Z)
        for j in range(n):
            J[6 * j:6 * j + 6, 6 * j:6 * j + 6] -= jac[j]
        J[m, 0:m:6] = cos_w
        J[m + 1, 0:m:6] = sin_w
        # force and momentum rows against the states: one component at a time, all azimuths
        h_z = 1e-7
        tilt, lam = float(c[3]), float(c[4])
        ca, sa = math.cos(tilt), math.sin(tilt)
        g = 1.0 / (2.0 * math.hypot(mu, mu * math.tan(tilt) + lam) * disc * lam_hover)
        f0 = blade.blade_aerodynamic_force(psi, Z)
        for k in range(6):
            Zp = Z.copy()
            Zp[:, k] += h_z
            fp = blade.blade_aerodynamic_force(psi, Zp)
            dT = N * (fp[:, 2] - f0[:, 2]) / (n * h_z)
            dH = N * ((fp[:, 0] - f0[:, 0]) * cp - (fp[:, 1] - f0[:, 1]) * sp) / (n * h_z)
            J[m + 2, k:m:6] = (dT * ca + dH * sa) / weight
            J[m + 3, k:m:6] = (dT * sa - dH * ca) / weight
            J[m + 4, k:m:6] = -dT * g
        for k in range(5):
            dc = c.copy()
            dc[k] += steps_c[k]
            J[:, m + k] = (residual(dc, Z)[0] - r) / steps_c[k]
        try:
            step = np.linalg.solve(J, -r)
        except np.linalg.LinAlgError as exc:
            raise TrimError(f"forward_flight_trim (mu = {mu:g}): singular trim Jacobian") from exc
        a = 1.0
        while True:  # damped Newton: halve the step until the residual falls
            Z_new = Z + a * step[:m].reshape(n, 6)
            c_new = c + a * step[m:]
            try:
                r_new, blade_new = residual(c_new, Z_new)
                err_new = float(np.abs(r_new).max())
            except TrimError:
                err_new = np.inf
            if err_new < err:
                break
            a *= 0.5
            if a < 1e-3:
                raise TrimError(f"forward_flight_trim (mu = {mu:g}): Newton's step does not reduce the "
                                f"residual {err:.2g}", residual=err, iterations=it)
        Z, c, r, blade, err = Z_new, c_new, r_new, blade_new, err_new
        it += 1
    coeffs = np.fft.rfft(Z, axis=0) / n
    coeffs[-1] *= 0.5  # the Nyquist term is shared between +-n/2
    motion = PeriodicMotion(params=blade.params, mu=mu, z0=Z[0].copy(), coefficients=coeffs,
                            residual=float(np.abs(r[:m]).max()),
                            fourier_error=float(np.abs(coeffs[-4:]).max() * 2.0),
                            harmonics_deg=np.degrees(_first_harmonics(Z[:, :3]).T))
    t, h, y = rotor_forces(blade.params, motion)
    drag, v = _drag(params, mu, float(c[3]))
    return ForwardFlightTrim(target="propulsive", mu=mu, params=blade.params, motion=motion, thrust=t,
                             h_force=h, side_force=y, weight=weight, drag=drag, flight_speed=v,
                             induced_inflow=float(c[4]), iterations=it)
