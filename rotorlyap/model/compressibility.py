"""Compressibility of the blade sections: a Prandtl-Glauert lift factor, a drag rise, a validity map.

The paper's section model (:mod:`rotorlyap.model.airfoil`) has no Mach dependence. With
``BladeParameters.compressibility = "prandtl-glauert"`` the strip loads
(:class:`rotorlyap.model.aero.StripAerodynamics` and the compiled kernels of
:mod:`rotorlyap.model.compiled`) correct the incompressible coefficients ``cl``, ``cd``, ``cm``
and the pitch-damping couple at each station by the section Mach number ``M = |w| / a`` (``|w|`` the in-plane air speed of the
section, ``a`` = ``BladeParameters.speed_of_sound``) as follows.

Lift: the Prandtl-Glauert factor, ``cl = cl_inc / sqrt(1 - M_e^2)`` with
``M_e = min(M, MACH_CAP)`` and ``MACH_CAP = 0.8``, applied in forward flow only (``|alpha| <= 90 deg``, ``alpha`` wrapped to [-180, 180) deg).
Linearised subsonic potential flow scales every pressure coefficient of a thin section by
``1/beta``, ``beta = sqrt(1 - M^2)`` [Glauert1928]; the zero-lift angle does not move, so the
whole attached lift curve, camber included, is scaled. Evidence, from the public C81 table of
the NACA 0012 (:data:`C81_NACA0012_CL_2DEG`, [C81NACA0012]): at 2 deg the table's ``cl``
follows ``cl(M=0) / beta`` within about 2 % for M <= 0.5 and 3 % at M = 0.6, and lies above it by
6 % at M = 0.7 and 12 % at M = 0.8; at M = 0.9 the table's lift collapses (0.20 against 0.211
at M = 0): shocks, which no linear factor describes. The factor diverges at M = 1, so it is
held at its value at ``MACH_CAP`` (5/3) above it; stations there are outside the model's range
anyway (above the drag-divergence Mach number, see below) and :func:`validity_map` flags them.
The cap keeps the loads finite and continuous in ``M`` for the occasional transonic excursion
(the advancing tip at high advance ratio).

Choices and their limits (stated, not hidden):

* the factor multiplies the whole forward-flow half-circle of ``cl``, post-stall included. At
  +-90 deg the full-range :class:`~rotorlyap.model.airfoil.Airfoil` has ``cl = 0``, so the
  corrected ``cl`` stays continuous there (a linear section's ``cl`` jumps there anyway, its
  force along the chord-normal stays continuous because ``w_y = 0``); in reverse flow
  (``|alpha| > 90 deg``, the retreating side at low ``M``) nothing changes. The factor also
  scales ``cl_max``, whereas the tabulated ``cl_max`` *falls* with Mach (the same C81 table:
  1.33 at M = 0 and 0.2, 0.98 at M = 0.6, 0.85 at M = 0.75): the corrected model is not
  meant for stalled sections at high Mach, and :func:`validity_map` flags stalled sections;
* ``cm`` and the quasi-steady pitch-damping couple (``BladeParameters.cm_pitch_rate``) take
  the same factor in forward flow: the linearised theory scales every pressure coefficient
  alike, and correcting the lift alone would weaken the aerodynamic pitch damping against the
  pitch-flap coupling by the factor, a bias of exactly the stability margins this report measures.

Drag: Lock's fourth-power drag rise with Korn's drag-divergence Mach number, in the form used
in conceptual design [GurMasonSchetz2010], Korn's equation as given by [Mason1990] and Lock's
empirical fourth-power law as quoted there (C. N. H. Lock's original report was not read)::

    M_dd   = kappa_A - t/c - |cl| / 10                 (Korn's equation, unswept section)
    M_crit = M_dd - (0.1 / 80)^(1/3)                    (so that d cd/dM = 0.1 at M_dd)
    cd     = cd_inc + 20 (M - M_crit)^4   for M > M_crit, else cd_inc.

The offset ``(0.1/80)^(1/3) = 0.1077`` makes the slope ``80 (M - M_crit)^3`` of the rise equal
0.1 at ``M_dd``: the usual definition of drag divergence. ``kappa_A = 0.87`` is the airfoil
technology factor of a conventional (NACA 6-series like) section, 0.95 for a supercritical one
[GurMasonSchetz2010]; ``t/c = 0.12`` is the NACA 23012's thickness [Abbott1959]. Korn's
equation is written for positive design lift; here ``|cl|`` (the corrected ``cl``) is used, a
symmetric extension, on the whole circle (reverse flow occurs where ``M`` is low, inboard on
the retreating side, so the rise is zero there in practice).
Check against the C81 NACA 0012 table at 0 deg (:data:`C81_NACA0012_CD_0DEG`): it gives
``cd = 0.008`` up to M = 0.75, 0.0137 at 0.8, 0.078 at 0.9; the law gives increments 0.0027,
0.0124 and 0.088 at 0.75, 0.8 and 0.9 (``M_crit = 0.642``): the right onset and size, a little
early.

A section with its own Mach dependence (a C81 table with several Mach columns,
:class:`rotorlyap.model.c81.C81Section`) takes ``compressibility = "table"`` instead: the strip
loads read its coefficients at ``M = |w| (1/a)`` and apply neither factor nor drag rise (the
table already holds them; ``BladeParameters`` refuses ``"prandtl-glauert"`` with such a section,
which would count compressibility twice). The quasi-steady pitch-damping couple then takes no
Mach factor (a C81 table gives no pitch-rate derivative).

Functions here are pure; the load kernels repeat the same operations in the same order (so the
numpy and compiled paths agree to round-off).

References (keys of the report's ``references.bib``)
----------------------------------------------------
- [Glauert1928] H. Glauert, "The effect of compressibility on the lift of an aerofoil",
  Proc. R. Soc. Lond. A 118, 113-119, 1928.
- [Mason1990] W. H. Mason, "Analytic models for technology integration in aircraft design",
  AIAA 90-3262, 1990: Korn's equation (D. Korn's unpublished rule, after Mason).
- [GurMasonSchetz2010] O. Gur, W. H. Mason and J. A. Schetz, "Full-configuration drag
  estimation", J. Aircraft 47(4), 2010: the Korn-Lock wave-drag model above (Korn's equation
  with the technology factor, Lock's fourth-power law).
- [C81NACA0012] the C81 table ``naca0012.c81`` of the public repository
  federico-savorgnan/paraglidyn (GitHub); the file does not say whether its numbers are
  wind-tunnel data or computed, so it is evidence of the usual C81 practice, not a measurement.
- [Abbott1959] I. H. Abbott and A. E. von Doenhoff, *Theory of Wing Sections*, 1959.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "C81_NACA0012_CD_0DEG", "C81_NACA0012_CL_2DEG", "CRITICAL_MACH_OFFSET", "DEFAULT_STALL_ANGLE",
    "KORN_KAPPA_CONVENTIONAL", "MACH_CAP", "THICKNESS_RATIO", "WAVE_DRAG_FACTOR",
    "CompressibilityConstants", "ValidityMap", "apply_to_coefficients", "compressibility_constants",
    "critical_mach", "drag_divergence_mach", "mach_factors", "prandtl_glauert_factor",
    "section_mach", "validity_map", "wave_drag",
]

FloatArray = NDArray[np.float64]

MACH_CAP: float = 0.8
"""Mach number above which the Prandtl-Glauert factor is held constant (at 1/0.6 = 5/3), -.
Up to it the C81 NACA 0012 table's small-angle lift still rises at least as fast as the factor;
at M = 0.9 it has collapsed (module docstring)."""

KORN_KAPPA_CONVENTIONAL: float = 0.87
"""Korn's airfoil technology factor ``kappa_A`` of a conventional section, -
[GurMasonSchetz2010]; 0.95 for a supercritical section."""

THICKNESS_RATIO: float = 0.12
"""Thickness-to-chord ratio of the NACA 23012, - [Abbott1959]: the default ``t/c`` of the
sections (an airfoil object may carry its own as an attribute ``thickness_ratio``)."""

WAVE_DRAG_FACTOR: float = 20.0
"""Coefficient of Lock's fourth-power drag rise ``20 (M - M_crit)^4`` [GurMasonSchetz2010], -."""

CRITICAL_MACH_OFFSET: float = (0.1 / 80.0) ** (1.0 / 3.0)
"""``M_dd - M_crit = (0.1/80)^(1/3)`` = 0.1077: the drag rise's slope ``80 (M - M_crit)^3`` is
0.1 at ``M_dd`` (the definition of drag divergence) [GurMasonSchetz2010]."""

DEFAULT_STALL_ANGLE: float = math.radians(15.0)
"""Stall angle (either sign), rad, that :func:`validity_map` assumes for airfoil objects without
``alpha_stall``/``alpha_stall_negative`` (e.g. :class:`rotorlyap.model.airfoil.LinearAirfoil`):
about the stall of 12 % sections at Reynolds numbers of a few million (NACA 0012: 16 deg,
[Abbott1959]); an assumption, recorded in the result."""

#: ``cl`` at 2 deg of the C81 NACA 0012 table [C81NACA0012], by Mach number: the evidence
#: for the Prandtl-Glauert factor quoted in the module docstring (a test checks the quoted
#: agreement against these numbers).
C81_NACA0012_CL_2DEG: dict[float, float] = {
    0.0: 0.211, 0.2: 0.211, 0.3: 0.22, 0.4: 0.228, 0.5: 0.247, 0.6: 0.272, 0.7: 0.313,
    0.75: 0.350, 0.8: 0.395, 0.9: 0.2, 1.0: 0.2,
}

#: ``cd`` at 0 deg of the same table, by Mach number: the evidence for the drag rise.
C81_NACA0012_CD_0DEG: dict[float, float] = {
    0.0: 0.008, 0.2: 0.008, 0.3: 0.008, 0.4: 0.008, 0.5: 0.008, 0.6: 0.008, 0.7: 0.008,
    0.75: 0.008, 0.8: 0.0137, 0.9: 0.078, 1.0: 0.095,
}


def _mach_array(mach: ArrayLike, name: str = "mach") -> FloatArray:
    m = np.asarray(mach, dtype=np.float64)
    if not np.all(np.isfinite(m)):
        raise ValueError(f"{name} must be finite, got {mach!r}")
    if np.any(m < 0.0):
        raise ValueError(f"{name} must be >= 0 (a Mach number is a speed over the speed of sound), "
                         f"got a minimum of {float(m.min())!r}")
    return m


def _fraction(name: str, value: float, low: float, high: float) -> float:
    v = float(value)
    if not (math.isfinite(v) and low < v < high):
        raise ValueError(f"{name} must lie in ({low}, {high}), got {value!r}")
    return v


def prandtl_glauert_factor(mach: ArrayLike, mach_cap: float = MACH_CAP) -> FloatArray:
    """The Prandtl-Glauert lift factor ``1 / sqrt(1 - min(M, mach_cap)^2)`` [Glauert1928].

    Parameters
    ----------
    mach : array_like
        Section Mach numbers, -, >= 0.
    mach_cap : float
        Mach number above which the factor is held constant, in (0, 1). Default
        :data:`MACH_CAP`.

    Returns
    -------
    numpy.ndarray
        The factor, >= 1, same shape as ``mach``.

    Raises
    ------
    ValueError
        A negative or non-finite Mach number, or ``mach_cap`` outside (0, 1).
    """
    m = _mach_array(mach)
    cap = _fraction("mach_cap", mach_cap, 0.0, 1.0)
    me = np.minimum(m, cap)
    return 1.0 / np.sqrt(1.0 - me * me)


def drag_divergence_mach(cl: ArrayLike = 0.0, t_over_c: float = THICKNESS_RATIO,
                         kappa: float = KORN_KAPPA_CONVENTIONAL) -> FloatArray:
    """Korn's drag-divergence Mach number ``kappa - t/c - |cl|/10`` of an unswept section
    [Mason1990], [GurMasonSchetz2010].

    Parameters
    ----------
    cl : array_like
        Section lift coefficient, -; its magnitude is used (a symmetric extension of Korn's
        equation, written for positive lift).
    t_over_c : float
        Thickness-to-chord ratio, in (0, 0.5).
    kappa : float
        Airfoil technology factor, in (0, 1.5): 0.87 conventional, 0.95 supercritical.

    Returns
    -------
    numpy.ndarray
        ``M_dd``, -, same shape as ``cl``.
    """
    tc = _fraction("t_over_c", t_over_c, 0.0, 0.5)
    k = _fraction("kappa", kappa, 0.0, 1.5)
    c = np.asarray(cl, dtype=np.float64)
    if not np.all(np.isfinite(c)):
        raise ValueError(f"cl must be finite, got {cl!r}")
    return (k - tc) - 0.1 * np.abs(c)


def critical_mach(cl: ArrayLike = 0.0, t_over_c: float = THICKNESS_RATIO,
                  kappa: float = KORN_KAPPA_CONVENTIONAL) -> FloatArray:
    """The onset of the drag rise, ``M_crit = M_dd - (0.1/80)^(1/3)`` [GurMasonSchetz2010].

    Same parameters as :func:`drag_divergence_mach`; computed as the load kernels do:
    ``(kappa - t/c - 0.1077) - 0.1 |cl|``.
    """
    tc = _fraction("t_over_c", t_over_c, 0.0, 0.5)
    k = _fraction("kappa", kappa, 0.0, 1.5)
    c = np.asarray(cl, dtype=np.float64)
    if not np.all(np.isfinite(c)):
        raise ValueError(f"cl must be finite, got {cl!r}")
    return (k - tc - CRITICAL_MACH_OFFSET) - 0.1 * np.abs(c)


def wave_drag(mach: ArrayLike, cl: ArrayLike = 0.0, t_over_c: float = THICKNESS_RATIO,
              kappa: float = KORN_KAPPA_CONVENTIONAL) -> FloatArray:
    """Lock's drag rise ``20 (M - M_crit)^4`` above ``M_crit``, 0 below [GurMasonSchetz2010].

    Parameters
    ----------
    mach : array_like
        Section Mach numbers, -, >= 0.
    cl, t_over_c, kappa
        As in :func:`drag_divergence_mach`; broadcast with ``mach``.

    Returns
    -------
    numpy.ndarray
        The drag-coefficient increment, >= 0, shape ``broadcast(mach, cl)``.
    """
    m = _mach_array(mach)
    d = m - critical_mach(cl, t_over_c, kappa)
    d = np.maximum(d, 0.0)
    return WAVE_DRAG_FACTOR * (d * d) * (d * d)


def mach_factors(mach: ArrayLike, cl: ArrayLike = 0.0, t_over_c: float = THICKNESS_RATIO,
                 kappa: float = KORN_KAPPA_CONVENTIONAL,
                 mach_cap: float = MACH_CAP) -> tuple[FloatArray, FloatArray]:
    """The lift factor and the drag increment at the section Mach numbers ``mach``.

    Parameters
    ----------
    mach : array_like
        Section Mach numbers, -, >= 0.
    cl : array_like
        Section lift coefficient (compressible) entering Korn's equation, -. Default 0.
    t_over_c : float
        Thickness-to-chord ratio. Default 0.12 (NACA 23012).
    kappa : float
        Korn's technology factor. Default 0.87 (conventional section).
    mach_cap : float
        Cap of the Prandtl-Glauert factor. Default 0.8.

    Returns
    -------
    lift_factor : numpy.ndarray
        ``1 / sqrt(1 - min(M, mach_cap)^2)``, multiplies the forward-flow ``cl``.
    cd_wave : numpy.ndarray
        ``20 (M - M_crit)^4`` above ``M_crit``, else 0; adds to ``cd``.

    Raises
    ------
    ValueError
        Negative or non-finite Mach numbers, or constants outside their ranges.
    """
    return prandtl_glauert_factor(mach, mach_cap), wave_drag(mach, cl, t_over_c, kappa)


def section_mach(speed: ArrayLike, speed_of_sound: float) -> FloatArray:
    """Section Mach number ``|w| / a``, computed as the load kernels do: ``|w| * (1/a)``.

    Parameters
    ----------
    speed : array_like
        In-plane air speed of the sections, m/s, >= 0.
    speed_of_sound : float
        m/s, > 0.
    """
    a = float(speed_of_sound)
    if not (math.isfinite(a) and a > 0.0):
        raise ValueError(f"speed_of_sound must be a finite speed > 0 m/s, got {speed_of_sound!r}")
    return _mach_array(np.asarray(speed, dtype=np.float64) * (1.0 / a), "speed")


@dataclass(frozen=True)
class CompressibilityConstants:
    """The numbers the strip loads need (numpy and compiled paths alike).

    Attributes
    ----------
    enabled : bool
        ``params.compressibility == "prandtl-glauert"``.
    inverse_speed_of_sound : float
        ``1 / a``, s/m.
    mach_cap : float
        Cap of the Prandtl-Glauert factor, -.
    critical_mach_zero_lift : float
        ``kappa - t/c - (0.1/80)^(1/3)``: ``M_crit`` at zero lift, -.
    section_mach : bool
        ``params.compressibility == "table"``: the section's own Mach dependence (a
        Mach-dependent C81 table, :class:`rotorlyap.model.c81.C81Section`) is read at the section
        Mach number ``|w| (1/a)``; ``enabled`` is then False (no correction on top).
    """

    enabled: bool
    inverse_speed_of_sound: float
    mach_cap: float
    critical_mach_zero_lift: float
    section_mach: bool = False


def compressibility_constants(params: Any) -> CompressibilityConstants:
    """The :class:`CompressibilityConstants` of a :class:`~rotorlyap.model.parameters.BladeParameters`.

    ``t/c`` is ``params.airfoil.thickness_ratio`` if the airfoil object has it, else
    :data:`THICKNESS_RATIO`; ``kappa_A`` is :data:`KORN_KAPPA_CONVENTIONAL`. With ``"table"``
    (a Mach-dependent section) the correction is off (``enabled`` False) and ``section_mach``
    on: the table's own Mach dependence replaces it, so compressibility is not applied twice.

    Raises
    ------
    ValueError
        An unknown ``params.compressibility`` or a bad speed of sound or thickness.
    """
    model = params.compressibility
    if model not in ("none", "prandtl-glauert", "table"):
        raise ValueError(f"compressibility must be one of ('none', 'prandtl-glauert', 'table'), got {model!r}")
    a = float(params.speed_of_sound)
    if not (math.isfinite(a) and a > 0.0):
        raise ValueError(f"speed_of_sound must be a finite speed > 0 m/s, got {params.speed_of_sound!r}")
    tc = _fraction("thickness_ratio", getattr(params.airfoil, "thickness_ratio", THICKNESS_RATIO), 0.0, 0.5)
    return CompressibilityConstants(
        enabled=model == "prandtl-glauert", inverse_speed_of_sound=1.0 / a, mach_cap=MACH_CAP,
        critical_mach_zero_lift=float(critical_mach(0.0, tc, KORN_KAPPA_CONVENTIONAL)),
        section_mach=model == "table")


def apply_to_coefficients(alpha: FloatArray, speed: FloatArray, cl: FloatArray, cd: FloatArray,
                          cm: FloatArray, constants: CompressibilityConstants
                          ) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """The corrected ``(cl, cd, cm)`` of the strip loads (module docstring), elementwise, and the
    factor applied to the section's pressures.

    The operations, in order, of the compiled kernel (:mod:`rotorlyap.model.compiled`):
    ``M = |w| (1/a)``; ``f = 1/sqrt(1 - min(M, cap)^2)`` where ``mod(alpha + pi, 2 pi)`` lies in
    ``[pi/2, 3 pi/2]`` (forward flow), 1 elsewhere; ``cl *= f``, ``cm *= f``;
    ``d = M - (M_crit0 - 0.1 |cl|)``; ``cd += 20 d^2 d^2`` where ``d > 0``. Prandtl-Glauert scales
    every pressure coefficient of the section alike, so the moment and the quasi-steady
    pitch-damping couple take the factor ``f`` too (the strip loads multiply the couple by the
    returned factor): scaling the lift alone would weaken the pitch damping against the
    pitch-flap coupling by the same factor and bias a flutter margin.

    Parameters
    ----------
    alpha : numpy.ndarray
        Angles of attack, rad (any range).
    speed : numpy.ndarray
        Section air speeds ``|w|``, m/s.
    cl, cd, cm : numpy.ndarray
        Incompressible coefficients at ``alpha``.
    constants : CompressibilityConstants
        From :func:`compressibility_constants`.

    Returns
    -------
    cl, cd, cm, factor : numpy.ndarray
    """
    two_pi = 2.0 * math.pi
    mach = speed * constants.inverse_speed_of_sound
    me = np.minimum(mach, constants.mach_cap)
    u = np.mod(alpha + math.pi, two_pi)
    forward = (u >= 0.5 * math.pi) & (u <= 1.5 * math.pi)
    factor = np.where(forward, 1.0 / np.sqrt(1.0 - me * me), 1.0)
    cl = cl * factor
    cm = cm * factor
    d = mach - (constants.critical_mach_zero_lift - 0.1 * np.abs(cl))
    d = np.maximum(d, 0.0)
    cd = cd + WAVE_DRAG_FACTOR * (d * d) * (d * d)
    return cl, cd, cm, factor


# --------------------------------------------------------------------------------------
# Validity map
# --------------------------------------------------------------------------------------

@dataclass(frozen=True)
class ValidityMap:
    """Where on the disc the section model is within its range, on an (azimuth, station) grid.

    Attributes
    ----------
    psi : numpy.ndarray, shape (n_psi,)
        Azimuths, rad.
    r_over_R : numpy.ndarray, shape (n_stations,)
        Station radii over the rotor radius (at zero hinge angles).
    mach : numpy.ndarray, shape (n_psi, n_stations)
        Section Mach number ``|w| / a``, -.
    alpha : numpy.ndarray, shape (n_psi, n_stations)
        Angle of attack wrapped to [-pi, pi), rad (pretwist included).
    cl : numpy.ndarray, shape (n_psi, n_stations)
        Section lift coefficient of the loads (compressibility applied if the blade's
        parameters ask for it), -.
    drag_divergence_mach : numpy.ndarray, shape (n_psi, n_stations)
        Korn's ``M_dd`` at the section's ``cl``, -.
    reverse_flow : numpy.ndarray of bool
        ``|alpha| > 90 deg``: the trailing edge leads.
    stalled : numpy.ndarray of bool
        Forward flow beyond the stall angles (``alpha > stall_angles[1]`` or
        ``alpha < stall_angles[0]``); reverse-flow points are marked by ``reverse_flow`` only.
    transonic : numpy.ndarray of bool
        ``M > M_dd`` or ``M > mach_cap``: compressible beyond the model's range.
    outside : numpy.ndarray of bool
        Any of the three.
    fraction_outside : float
        Fraction of the grid points outside the range, -.
    stall_angles : tuple of float
        The (negative, positive) stall angles used, rad.
    stall_angles_assumed : bool
        True where the airfoil had no stall angles and :data:`DEFAULT_STALL_ANGLE` was used.
    mach_cap : float
        The Prandtl-Glauert cap, -.
    """

    psi: FloatArray
    r_over_R: FloatArray
    mach: FloatArray
    alpha: FloatArray
    cl: FloatArray
    drag_divergence_mach: FloatArray
    reverse_flow: NDArray[np.bool_]
    stalled: NDArray[np.bool_]
    transonic: NDArray[np.bool_]
    outside: NDArray[np.bool_]
    fraction_outside: float
    stall_angles: tuple[float, float]
    stall_angles_assumed: bool
    mach_cap: float


def _stall_angles(airfoil: Any) -> tuple[tuple[float, float], bool]:
    hi = getattr(airfoil, "alpha_stall", None)
    lo = getattr(airfoil, "alpha_stall_negative", None)
    if hi is None or lo is None:
        return (-DEFAULT_STALL_ANGLE, DEFAULT_STALL_ANGLE), True
    return (float(lo), float(hi)), False


def _steady_states(steady: Any, psi: FloatArray) -> FloatArray:
    """The states at ``psi`` (n_psi, 6) from a constant state, a table or a callable."""
    if callable(steady):
        z = np.asarray(steady(psi), dtype=np.float64)
        if z.shape == (6, psi.size):
            z = z.T
        if z.shape != (psi.size, 6):
            z = np.array([np.asarray(steady(float(p)), dtype=np.float64) for p in psi])
    else:
        z = np.asarray(steady, dtype=np.float64)
        if z.shape == (6,):
            z = np.broadcast_to(z, (psi.size, 6))
    if z.shape != (psi.size, 6):
        raise ValueError(f"steady must be a state of shape (6,), states of shape (n_psi, 6) = "
                         f"({psi.size}, 6) or a callable xi(psi) giving them, got shape {z.shape}")
    if not np.all(np.isfinite(z)):
        raise ValueError("the steady states must be finite")
    return np.ascontiguousarray(z)


def validity_map(blade: Any, steady: ArrayLike | Callable[[Any], Any], psi: ArrayLike | None = None,
                 n_azimuth: int = 72, stall_angles: tuple[float, float] | None = None) -> ValidityMap:
    """Map the section Mach number, angle of attack and range of the section model over the disc.

    Parameters
    ----------
    blade : rotorlyap.model.equations.BladeEquations
        The blade (e.g. :class:`rotorlyap.model.blade.Blade`), at its advance ratio.
    steady : array_like or callable
        The steady motion: one state ``(6,)`` held at every azimuth (e.g. the hover
        equilibrium), states ``(n_psi, 6)`` at ``psi``, or a callable ``xi(psi)`` returning
        ``(n_psi, 6)`` (or ``(6, n_psi)``) for an array of azimuths, or ``(6,)`` for one.
    psi : array_like, optional
        Azimuths, rad, 1-D. Default: ``n_azimuth`` equally spaced over [0, 2 pi).
    n_azimuth : int
        Number of azimuths when ``psi`` is None, >= 1.
    stall_angles : (float, float), optional
        (negative, positive) stall angles of forward flow, rad. Default: the airfoil's
        ``alpha_stall_negative`` and ``alpha_stall``, or +-:data:`DEFAULT_STALL_ANGLE` for
        airfoil objects without them.

    Returns
    -------
    ValidityMap

    Raises
    ------
    ValueError
        Bad azimuths, states or stall angles.
    """
    if psi is None:
        n = int(n_azimuth)
        if n < 1:
            raise ValueError(f"n_azimuth must be >= 1, got {n_azimuth!r}")
        psi_a = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    else:
        psi_a = np.asarray(psi, dtype=np.float64)
        if psi_a.ndim != 1 or psi_a.size == 0 or not np.all(np.isfinite(psi_a)):
            raise ValueError("psi must be a non-empty 1-D array of finite azimuths (rad)")
    z = _steady_states(steady, psi_a)
    p = blade.params
    if stall_angles is None:
        angles, assumed = _stall_angles(p.airfoil)
    else:
        lo, hi = (float(v) for v in stall_angles)
        if not (-0.5 * math.pi < lo < 0.0 < hi < 0.5 * math.pi):
            raise ValueError(f"stall_angles must be (negative, positive) angles within +-90 deg, rad, "
                             f"got {stall_angles!r}")
        angles, assumed = (lo, hi), False
    consts = compressibility_constants(p)
    w = np.asarray(blade.relative_wind(psi_a, z), dtype=np.float64)
    speed = np.sqrt(w[..., 0] * w[..., 0] + w[..., 1] * w[..., 1])
    mach = section_mach(speed, p.speed_of_sound)
    alpha_raw = np.asarray(blade.angle_of_attack(psi_a, z), dtype=np.float64)
    alpha = np.mod(alpha_raw + math.pi, 2.0 * math.pi) - math.pi
    if consts.section_mach:
        cl = np.asarray(p.airfoil.coefficients(alpha_raw, mach)[0], dtype=np.float64)
    else:
        cl = np.asarray(p.airfoil.coefficients(alpha_raw)[0], dtype=np.float64)
    if consts.enabled:
        cl = apply_to_coefficients(alpha_raw, speed, cl, np.zeros_like(cl), np.zeros_like(cl), consts)[0]
    mdd = (consts.critical_mach_zero_lift - 0.1 * np.abs(cl)) + CRITICAL_MACH_OFFSET
    reverse = np.abs(alpha) > 0.5 * math.pi
    stalled = ~reverse & ((alpha > angles[1]) | (alpha < angles[0]))
    transonic = (mach > mdd) | (mach > consts.mach_cap)
    outside = reverse | stalled | transonic
    return ValidityMap(
        psi=psi_a, r_over_R=np.asarray(blade.r_over_R, dtype=np.float64).copy(), mach=mach,
        alpha=alpha, cl=cl, drag_divergence_mach=mdd, reverse_flow=reverse, stalled=stalled,
        transonic=transonic, outside=outside, fraction_outside=float(outside.mean()),
        stall_angles=angles, stall_angles_assumed=assumed, mach_cap=consts.mach_cap)
