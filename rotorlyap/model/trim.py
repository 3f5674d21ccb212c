"""Hover trim: the collective pitch for which the rotor thrust equals the helicopter weight.

The thrust is ``n_blades`` times the vertical aerodynamic force of one blade at its hover
equilibrium (:func:`rotorlyap.model.equilibrium.hover_equilibrium`), with the induced inflow of
:mod:`rotorlyap.model.inflow` (momentum theory for thrust = weight, or ``params.inflow_ratio``).
Since that inflow already assumes thrust = weight, the trimmed state is self-consistent.

The equilibrium is followed by continuation along the flap angle from the unloaded blade, so
the trim lands on the branch of equilibria connected to it.  With destabilising pitch-flap
coupling this branch can fold in the collective (past a largest collective there is no
equilibrium near it), which a continuation in the collective could not pass.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import lru_cache

import numpy as np
from scipy.optimize import brentq, root

from ..errors import TrimError
from .equations import BladeEquations
from .equilibrium import hover_equilibrium
from .inflow import mean_inflow
from .parameters import BladeParameters

__all__ = ["HoverTrim", "MAX_TRIMMED_PITCH", "check_trimmed_pitch", "hover_trim", "loading_advice"]

#: Largest pitch of the three-quarter-radius section a trim may reach, rad (25 deg): beyond it
#: every section of the blade is deep in stall, and the trim has found a parameter mistake (a
#: weight in pounds, a chord or a rotor speed in the wrong unit), not a flight condition.
MAX_TRIMMED_PITCH: float = math.radians(25.0)


def loading_advice(params: BladeParameters) -> str:
    """What a failed trim asks of the blade, in one sentence: its blade loading ``C_T/sigma``,
    the mean lift coefficient ``6 C_T/sigma`` that blade-element theory (uniform inflow, untwisted
    blade) needs to carry it, the section's ``cl_max``, and what to change."""
    cts = params.blade_loading
    cl_max = getattr(params.airfoil, "cl_max", None)
    need = (f"a mean lift coefficient 6 C_T/sigma = {6 * cts:.2f}"
            + (f" against the section's cl_max = {cl_max:.2f}" if cl_max is not None else ""))
    paper = BladeParameters.table_i().blade_loading
    return (f"the weight asks a blade loading C_T/sigma = {cts:.3f} of this rotor ({need}; the paper's "
            f"rotor hovers at C_T/sigma = {paper:.3f}): check helicopter_mass (kg), rotor_speed (rad/s), "
            f"chord (m), radius (m) and n_blades, or lower the weight")


def _with_advice(exc: TrimError, params: BladeParameters) -> TrimError:
    new = TrimError(f"{exc}; {loading_advice(params)}", thrust=exc.thrust, weight=exc.weight,
                    flap_angle=exc.flap_angle, residual=exc.residual, tolerance=exc.tolerance,
                    iterations=exc.iterations)
    new.__cause__ = exc.__cause__
    return new


def check_trimmed_pitch(params: BladeParameters, collective: float, where: str) -> None:
    """Refuse a trimmed collective whose three-quarter-radius pitch exceeds
    :data:`MAX_TRIMMED_PITCH`, with the blade loading and the likely mistake."""
    p75 = params.pitch_at(0.75, collective)
    if abs(p75) > MAX_TRIMMED_PITCH:
        raise TrimError(
            f"{where}: the trimmed collective {math.degrees(collective):.1f} deg at the pitch hinge sets the "
            f"section at 0.75 R to {math.degrees(p75):.1f} deg, beyond the +-{math.degrees(MAX_TRIMMED_PITCH):.0f} "
            f"deg a flying rotor needs; {loading_advice(params)}; a twist in degrees for radians, or the "
            f"template's pitch-flap coupling and pitch stiffness on another blade, also do this")

@dataclass(frozen=True)
class HoverTrim:
    """Result of :func:`hover_trim`.

    Attributes
    ----------
    collective : float
        Collective pitch at the pitch hinge (pitch of the root section), rad.
    equilibrium : numpy.ndarray
        Hover equilibrium state ``(beta, zeta, theta, 0, 0, 0)`` at that collective, rad.
    thrust : float
        Rotor thrust at the equilibrium, N.
    weight : float
        Target thrust (helicopter weight), N.
    inflow : float
        Mean induced inflow ratio lambda_0 used, -.
    thrust_coefficient : float
        ``thrust / (rho pi R^2 (Omega R)^2)``, -.
    iterations : int
        Function evaluations of the root finder.
    """

    collective: float
    equilibrium: np.ndarray
    thrust: float
    weight: float
    inflow: float
    thrust_coefficient: float
    iterations: int


class _Branch:
    """Hover equilibria of one blade parametrised by the flap angle (continuation).

    For a given flap angle ``beta`` the lag angle, the pitch angle and the collective that
    make the blade an equilibrium are solved together; unlike the collective, ``beta`` grows
    monotonically along the branch that starts at the unloaded blade, so the parametrisation
    passes folds of the branch in the collective.
    """

    def __init__(self, params: BladeParameters):
        self.blade = BladeEquations(replace(params, collective=0.0, cyclic_cos=0.0, cyclic_sin=0.0))
        self.calls = 0

    def at(self, beta: float, start: np.ndarray) -> tuple[float, np.ndarray, float]:
        """Thrust (N), equilibrium state and collective at flap angle ``beta``.

        ``start`` holds the starting (lag, pitch, collective), rad.
        """
        self.calls += 1

        def residual(u):
            b = self.blade.with_collective(u[2])
            return b.rhs(0.0, np.array([beta, u[0], u[1], 0.0, 0.0, 0.0]))[3:]

        sol = root(residual, start, method="hybr", options={"xtol": 1e-13})
        # scale-free acceptance: the Newton correction (finite-difference Jacobian) in rad
        h = 1e-7
        J = np.column_stack([(residual(sol.x + h * e) - residual(sol.x - h * e)) / (2 * h)
                             for e in np.eye(3)])
        try:
            du = np.linalg.solve(J, residual(sol.x))
            err = float(np.abs(du).max())
        except np.linalg.LinAlgError:
            err = np.inf
        if not err < 1e-9:
            raise TrimError(f"hover_trim: no equilibrium found at flap angle {beta:.5f} rad "
                            f"({sol.message}, Newton correction {err:.3g} rad)",
                            flap_angle=float(beta), residual=err, tolerance=1e-9)
        b = self.blade.with_collective(sol.x[2])
        z = np.array([beta, sol.x[0], sol.x[1], 0.0, 0.0, 0.0])
        return float(b.rotor_thrust(0.0, z)), z, float(sol.x[2])


@lru_cache(maxsize=64)
def hover_trim(params: BladeParameters, step: float = 0.01, max_flap: float = 0.5,
               xtol: float = 1e-13) -> HoverTrim:
    """Trim the collective so that the hover thrust equals the weight.

    The hover equilibria are followed along the flap angle from the unloaded blade (``beta``
    where the collective is zero, found first) upwards in steps of ``step`` until the thrust
    exceeds the weight; Brent's method then finds the flap angle, hence the collective, at
    which thrust = weight.  Parametrising by ``beta`` rather than by the collective passes
    folds of the branch (where, past a largest collective, equilibria cease to exist).

    Parameters
    ----------
    params : BladeParameters
        ``params.collective`` is ignored (replaced by the trimmed value).
    step : float
        Flap-angle step of the continuation, rad.
    max_flap : float
        Largest flap angle tried, rad.
    xtol : float
        Tolerance on the flap angle, rad.

    Returns
    -------
    HoverTrim

    Raises
    ------
    rotorlyap.errors.TrimError
        (a ``RuntimeError``) In vacuum, if the weight is not positive, if no equilibrium is found along the branch,
        if the thrust does not reach the weight below ``max_flap``, or if the trimmed pitch at 0.75 R
        exceeds :data:`MAX_TRIMMED_PITCH`; the message gives the blade loading ``C_T/sigma`` and
        what to change (:func:`loading_advice`).
    """
    try:
        trim = _hover_trim(params, step, max_flap, xtol)
    except TrimError as exc:
        raise _with_advice(exc, params) from exc.__cause__
    check_trimmed_pitch(params, trim.collective, "hover_trim")
    return trim


def _hover_trim(params: BladeParameters, step: float, max_flap: float, xtol: float) -> HoverTrim:
    weight = params.helicopter_mass * params.gravity
    if params.air_density <= 0.0:
        raise TrimError("hover_trim: no thrust in vacuum (air_density = 0); give a collective", weight=weight)
    if weight <= 0.0:
        raise TrimError(f"hover_trim: the weight helicopter_mass * gravity = {weight!r} N must be > 0")
    branch = _Branch(params)
    # the unloaded blade: zero collective
    z0 = hover_equilibrium(branch.blade)
    b_lo = float(z0[0])
    t_lo, z_lo, c_lo = branch.at(b_lo, np.array([z0[1], z0[2], 0.0]))
    if t_lo >= weight:
        raise TrimError(f"hover_trim: thrust {t_lo:.6g} N at zero collective already reaches the "
                        f"weight {weight:.6g} N", thrust=t_lo, weight=weight, flap_angle=b_lo)
    while True:
        b_hi = b_lo + step
        if b_hi > max_flap:
            raise TrimError(f"hover_trim: thrust {t_lo:.6g} N at flap angle {b_lo:.4g} rad is still "
                            f"below the weight {weight:.6g} N (max_flap = {max_flap} rad)",
                            thrust=t_lo, weight=weight, flap_angle=b_lo)
        t_hi, z_hi, c_hi = branch.at(b_hi, np.array([z_lo[1], z_lo[2], c_lo]))
        if t_hi >= weight:
            break
        b_lo, t_lo, z_lo, c_lo = b_hi, t_hi, z_hi, c_hi
    start = np.array([z_lo[1], z_lo[2], c_lo])
    try:
        beta0, res = brentq(lambda b: branch.at(b, start)[0] - weight, b_lo, b_hi,
                            xtol=xtol, full_output=True, maxiter=100)
    except (RuntimeError, ValueError) as exc:
        raise TrimError(f"hover_trim: Brent's method failed between flap angles {b_lo:.4f} and "
                        f"{b_hi:.4f} rad: {exc}", weight=weight, flap_angle=b_lo) from exc
    if not res.converged:  # pragma: no cover
        raise TrimError(f"hover_trim: Brent's method did not converge ({res.flag})", weight=weight,
                        iterations=res.iterations)
    thrust, z, theta0 = branch.at(beta0, start)
    R = params.radius
    ct = thrust / (params.air_density * math.pi * R * R * (params.rotor_speed * R) ** 2)
    return HoverTrim(collective=theta0, equilibrium=z, thrust=thrust, weight=weight,
                     inflow=mean_inflow(params, 0.0), thrust_coefficient=ct,
                     iterations=branch.calls)
