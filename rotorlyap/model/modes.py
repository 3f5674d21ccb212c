"""Derived quantities of a blade parameter set: the numbers a rotor dynamicist checks first.

:func:`derived_quantities` collects, for one :class:`~rotorlyap.model.parameters.BladeParameters`,

* mass data: blade mass, flap inertia, Lock number, solidity;
* hover performance: thrust coefficient, ``C_T / sigma``, mean induced inflow, the trimmed
  collective (:func:`rotorlyap.model.trim.hover_trim`), the hover equilibrium hinge angles and the
  pitch of the blade chord relative to the hub plane;
* the linearised modes at the hover equilibrium, from the eigenvalues of
  :meth:`rotorlyap.model.blade.Blade.jacobian`, once in vacuum (``air_density = 0``: inertia,
  centrifugal and gravity forces, hinge springs and dampers only) and once with air, each mode
  named after the hinge whose angle dominates its eigenvector;
* classical closed-form estimates to compare them with, and the blade-element-theory pitch
  and coning of an untwisted blade in uniform inflow.

Units: SI (kg, m, s, rad); eigenvalues and frequencies are per revolution, i.e. in units of
the rotor speed Omega, because the independent variable is the azimuth ``psi = Omega t``
(an eigenvalue ``s`` of the psi-form Jacobian means ``exp(s psi) = exp(s Omega t)``).

Closed forms (derived from the effective potential ``U = V - T0`` and the mass matrix at zero
hinge angles for a blade whose mass lies on its chord line; :mod:`rotorlyap.model.derivation`
gives the exact expressions, shown in the book):

* flap:  ``nu_beta^2 = 1 + e_beta S_beta / I_beta`` with the flap hinge offset
  ``e_beta = e1 R1``, and ``S_beta``, ``I_beta`` the first and second moments of the blade
  mass about the flap hinge;
* lag:   ``nu_zeta^2 = e_zeta S_zeta / I_zeta`` with the lag hinge radius
  ``e_zeta = (e1 + e3) R1`` and ``I_zeta`` the lag inertia about the lag hinge, which adds the
  sections' chordwise inertia to the radial one; the lag damper gives the decay rate
  ``C_zeta / (2 I_zeta Omega)`` per rev;
* pitch: ``nu_theta^2 = K_theta / (I_theta Omega^2) + (I_zz - I_yy) / I_theta cos(2 theta)``,
  the control-system spring plus the propeller (tennis-racket) moment; for a thin section
  ``I_zz - I_yy = I_theta`` and the second term is about 1.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import lru_cache

import numpy as np

from ..conventions import HINGES
from .blade import Blade
from .mass import mass_properties
from .inflow import mean_inflow
from .parameters import BladeParameters

__all__ = [
    "Mode",
    "ClosedForms",
    "DerivedQuantities",
    "closed_forms",
    "modes_from_jacobian",
    "chord_pitch_to_hub_plane",
    "chordwise_lag_offset_angle",
    "derived_quantities",
    "hover_modes",
    "least_damped",
    "pitch_mode",
]

# --------------------------------------------------------------------------------------
# Modes
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Mode:
    """One linear mode of the blade about an equilibrium.

    Attributes
    ----------
    eigenvalue : complex
        Eigenvalue of the psi-form Jacobian, per rev (units of Omega); for a complex pair the
        member with positive imaginary part.
    shape : tuple of 3 float
        Magnitudes of the flap, lag and pitch angles in the eigenvector, divided by the
        largest (rad per rad, so the hinges are compared as angles).
    dominant_hinge : str
        ``"flap"``, ``"lag"`` or ``"pitch"``: the hinge with the largest angle.
    """

    eigenvalue: complex
    shape: tuple[float, float, float]
    dominant_hinge: str

    @property
    def frequency(self) -> float:
        """Damped frequency ``|Im s|``, per rev (0 for a real eigenvalue)."""
        return abs(self.eigenvalue.imag)

    @property
    def natural_frequency(self) -> float:
        """``|s|``, per rev: the undamped natural frequency of a one-degree-of-freedom mode."""
        return abs(self.eigenvalue)

    @property
    def growth_rate(self) -> float:
        """``Re s``, per rev: negative = decaying, positive = growing."""
        return self.eigenvalue.real

    @property
    def damping_ratio(self) -> float:
        """``-Re s / |s|``, - (negative for a growing oscillation)."""
        return -self.eigenvalue.real / abs(self.eigenvalue)

    @property
    def oscillatory(self) -> bool:
        """True for a complex pair."""
        return self.eigenvalue.imag != 0.0

    @property
    def unstable(self) -> bool:
        """True if the mode grows (``Re s > 0``)."""
        return self.eigenvalue.real > 0.0


def modes_from_jacobian(J: np.ndarray) -> tuple[Mode, ...]:
    """Modes of a 6x6 psi-form Jacobian of the state ``(beta, zeta, theta, rates)``.

    A complex pair counts once (the member with ``Im s > 0``); a real eigenvalue is a mode of
    its own. The modes are ordered by dominant hinge (flap, lag, pitch), then by decreasing
    frequency, then by decreasing growth rate.

    Parameters
    ----------
    J : numpy.ndarray, shape (6, 6)

    Returns
    -------
    tuple of Mode
    """
    J = np.asarray(J, dtype=np.float64)
    if J.shape != (6, 6):
        raise ValueError(f"J must have shape (6, 6), got {J.shape}")
    values, vectors = np.linalg.eig(J)
    modes = []
    for s, v in zip(values, vectors.T):
        if s.imag < 0.0:
            continue
        a = np.abs(v[:3])
        a = a / a.max()
        modes.append(Mode(eigenvalue=complex(s), shape=tuple(float(x) for x in a),
                          dominant_hinge=HINGES[int(np.argmax(a))]))
    modes.sort(key=lambda m: (HINGES.index(m.dominant_hinge), -m.frequency, -m.growth_rate))
    return tuple(modes)


# --------------------------------------------------------------------------------------
# Closed forms
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ClosedForms:
    """Classical closed-form estimates of the rotating frequencies in vacuum.

    Attributes
    ----------
    flap_hinge_offset : float
        ``e_beta = e1 R1``, m.
    flap_first_moment, flap_inertia : float
        ``S_beta`` (kg m) and ``I_beta`` (kg m^2) about the flap hinge (zero hinge angles).
    flap_frequency : float
        ``sqrt(1 + e_beta S_beta / I_beta)``, per rev.
    lag_hinge_radius : float
        ``e_zeta = (e1 + e3) R1``, m.
    lag_first_moment, lag_inertia : float
        ``S_zeta`` (kg m) and ``I_zeta`` (kg m^2, including the chordwise section inertia)
        about the lag hinge.
    lag_frequency : float
        ``sqrt(e_zeta S_zeta / I_zeta)``, per rev (undamped).
    lag_decay_rate : float
        ``C_zeta / (2 I_zeta Omega)``, per rev: minus the real part of the lag eigenvalues.
    pitch_inertia : float
        ``I_theta``, about the feathering axis, kg m^2.
    propeller_term : float
        ``(I_zz - I_yy) / I_theta cos(2 theta)``, - (about 1 for a thin section).
    pitch_frequency : float
        ``sqrt(K_theta / (I_theta Omega^2) + propeller_term)``, per rev.
    """

    flap_hinge_offset: float
    flap_first_moment: float
    flap_inertia: float
    flap_frequency: float
    lag_hinge_radius: float
    lag_first_moment: float
    lag_inertia: float
    lag_frequency: float
    lag_decay_rate: float
    pitch_inertia: float
    propeller_term: float
    pitch_frequency: float


def closed_forms(params: BladeParameters, theta: float = 0.0) -> ClosedForms:
    """Closed-form rotating frequencies of the blade (zero flap and lag, pitch ``theta``).

    The mass moments come from :func:`rotorlyap.model.blade.mass_properties` (about the pitch hinge,
    blade axes) shifted to the flap and lag hinges along the radial hub elements. The vertical
    element e2 and the couplings between the hinges are left out; for the Table I blade the
    flap and lag forms match the vacuum eigenvalues to 1e-4, the pitch form to 1e-3 with the
    C.G. on the pitch axis and to 0.5 % with the C.G. 0.02 c off it (the product of inertia
    ``int x y dm`` then couples pitch to flap inertially).

    Parameters
    ----------
    params : BladeParameters
    theta : float
        Pitch angle at which the propeller moment is evaluated, rad.

    Returns
    -------
    ClosedForms
    """
    mp = mass_properties(params)
    m = mp.mass
    Sx = float(mp.first_moment[0])
    Ixx, Iyy, Izz = (float(mp.inertia[i, i]) for i in range(3))
    d1, _d2, d3, d4, _d5 = params.hub_element_lengths
    om = params.rotor_speed
    # flap hinge: the pitch hinge lies d3 + d4 outboard of it
    a = d3 + d4
    S_b = Sx + m * a
    I_b = Iyy + 2.0 * Sx * a + m * a * a  # about y through the flap hinge
    nu_b = math.sqrt(1.0 + d1 * S_b / I_b + params.flap_stiffness / (I_b * om * om))
    # lag hinge: the pitch hinge lies d4 outboard of it
    e_z = d1 + d3
    S_z = Sx + m * d4
    I_z = Izz + 2.0 * Sx * d4 + m * d4 * d4  # about z through the lag hinge
    nu_z = math.sqrt(e_z * S_z / I_z + params.lag_stiffness / (I_z * om * om))
    decay = params.lag_damping / (2.0 * I_z * om)
    prop = (Izz - Iyy) / Ixx * math.cos(2.0 * theta)
    nu_t = math.sqrt(params.pitch_stiffness / (Ixx * om * om) + prop)
    return ClosedForms(
        flap_hinge_offset=d1, flap_first_moment=S_b, flap_inertia=I_b, flap_frequency=nu_b,
        lag_hinge_radius=e_z, lag_first_moment=S_z, lag_inertia=I_z, lag_frequency=nu_z,
        lag_decay_rate=decay, pitch_inertia=Ixx, propeller_term=prop, pitch_frequency=nu_t,
    )


# --------------------------------------------------------------------------------------
# Geometry helpers
# --------------------------------------------------------------------------------------


def chord_pitch_to_hub_plane(beta: float, zeta: float, theta: float) -> float:
    """Pitch of the blade chord relative to the hub plane, rad.

    The angle of the chordwise axis ``y_B`` (towards the leading edge) above the hub plane,
    ``asin(y_B . z_H) = asin(sin theta cos beta + cos theta sin zeta sin beta)``: with the
    hinge order flap, lag, pitch, a coned (``beta > 0``) and lagged (``zeta > 0``) blade has
    its chord pitched up by about ``beta zeta`` more than the pitch-hinge angle ``theta``.

    Parameters
    ----------
    beta, zeta, theta : float
        Flap, lag and pitch hinge angles, rad.

    Returns
    -------
    float
        rad.
    """
    s = math.sin(theta) * math.cos(beta) + math.cos(theta) * math.sin(zeta) * math.sin(beta)
    return math.asin(s)


def chordwise_lag_offset_angle(params: BladeParameters) -> float:
    """Lag angle that a *chordwise* reading of e2 would impose by centrifugal force alone, rad.

    If the lag hinge sat ``|e2| R1`` beside the radial line through the flap hinge (in the hub
    plane) instead of below it, a blade free to turn about the lag hinge would settle, in the
    centrifugal field alone, with its mass on the line from the shaft through the lag hinge:
    turned by ``atan(|e2| R1 / ((e1 + e3) R1))`` from the hub's radial direction. (The
    centrifugal potential ``-1/2 Omega^2 int |P2 + s u|^2 dm`` of a blade along the unit vector
    ``u`` from the hinge ``P2`` is least when ``u`` is parallel to ``P2``.)

    Parameters
    ----------
    params : BladeParameters

    Returns
    -------
    float
        rad (positive).
    """
    e = params.hub_elements
    return math.atan2(abs(e[1]), e[0] + e[2])


# --------------------------------------------------------------------------------------
# Derived quantities
# --------------------------------------------------------------------------------------


@dataclass(frozen=True)
class DerivedQuantities:
    """Derived quantities of one parameter set in hover (see :func:`derived_quantities`).

    Attributes
    ----------
    blade_mass : float
        kg.
    flap_inertia : float
        ``I_beta`` about the flap hinge, point-mass sections, kg m^2.
    lift_slope : float
        Section lift-curve slope ``a``, 1/rad.
    lock_number : float
        ``gamma = rho a c R^4 / I_beta``, -.
    solidity : float
        ``sigma = N c / (pi R)``, -.
    thrust : float
        Rotor thrust at the hover equilibrium, N.
    thrust_coefficient : float
        ``C_T = T / (rho pi R^2 (Omega R)^2)``, -.
    ct_over_sigma : float
        ``C_T / sigma``, -.
    inflow_ratio : float
        Mean induced inflow ratio ``lambda_0`` in hover (momentum theory, ``sqrt(C_T/2)``), -.
    collective : float
        Collective pitch at the pitch hinge, rad (trimmed for thrust = weight if
        ``params.collective`` is None).
    equilibrium : tuple of 3 float
        Hover equilibrium ``(beta, zeta, theta)`` with air, rad.
    chord_pitch : float
        Pitch of the chord relative to the hub plane at that equilibrium, rad
        (:func:`chord_pitch_to_hub_plane`).
    vacuum_equilibrium : tuple of 3 float
        Equilibrium at the same collective in vacuum, rad.
    blade_element_pitch : float
        Blade pitch for the thrust from classical blade-element theory (untwisted blade,
        uniform inflow, no root cutout or tip loss), ``6 C_T / (sigma a) + 3/2 lambda_0 +
        alpha_0`` with ``alpha_0`` the airfoil's zero-lift angle (0 if it has none), rad;
        compare with ``chord_pitch``.
    blade_element_coning : float
        Classical hover coning ``gamma / nu_beta^2 ((theta - alpha_0)/8 - lambda_0/6)`` at
        ``theta = blade_element_pitch`` (no gravity, no vertical hinge offset), rad.
    air_modes, vacuum_modes : tuple of Mode
        Linear modes at the two equilibria (:func:`modes_from_jacobian`).
    closed_forms : ClosedForms
        Classical estimates at the vacuum equilibrium pitch.
    """

    blade_mass: float
    flap_inertia: float
    lift_slope: float
    lock_number: float
    solidity: float
    thrust: float
    thrust_coefficient: float
    ct_over_sigma: float
    inflow_ratio: float
    collective: float
    equilibrium: tuple[float, float, float]
    chord_pitch: float
    vacuum_equilibrium: tuple[float, float, float]
    blade_element_pitch: float
    blade_element_coning: float
    air_modes: tuple[Mode, ...]
    vacuum_modes: tuple[Mode, ...]
    closed_forms: ClosedForms

    def modes(self, hinge: str, air: bool = True) -> tuple[Mode, ...]:
        """The modes dominated by ``hinge`` ("flap", "lag" or "pitch"), with or without air."""
        if hinge not in HINGES:
            raise ValueError(f"hinge must be one of {HINGES}, got {hinge!r}")
        return tuple(m for m in (self.air_modes if air else self.vacuum_modes)
                     if m.dominant_hinge == hinge)

    @property
    def unstable_air_modes(self) -> tuple[Mode, ...]:
        """The growing modes with air (``Re s > 0``)."""
        return tuple(m for m in self.air_modes if m.unstable)


@lru_cache(maxsize=32)
def derived_quantities(params: BladeParameters) -> DerivedQuantities:
    """Derived quantities of a parameter set in hover (cached per parameter set).

    Parameters
    ----------
    params : BladeParameters
        With ``air_density > 0``; ``collective = None`` trims for thrust = weight.

    Returns
    -------
    DerivedQuantities

    Raises
    ------
    ValueError
        If ``params.air_density`` is 0 (no hover thrust, no Lock number).
    """
    if params.air_density <= 0.0:
        raise ValueError("derived_quantities: air_density must be > 0 (hover with air); "
                         f"got {params.air_density!r}")
    blade = Blade(params)  # trims if params.collective is None
    z = blade.equilibrium()
    collective = float(blade.params.collective)
    thrust = float(blade.rotor_thrust(0.0, z))
    R = params.radius
    ct = thrust / (params.air_density * math.pi * R * R * (params.rotor_speed * R) ** 2)
    air_modes = hover_modes(params)

    vac = Blade(replace(params, air_density=0.0, collective=collective))
    zv = vac.equilibrium()
    vac_modes = modes_from_jacobian(vac.jacobian(0.0, zv))
    cf = closed_forms(params, theta=float(zv[2]))

    lam = mean_inflow(params, 0.0)
    a = params.lift_slope
    alpha0 = float(getattr(params.airfoil, "alpha_zero_lift", 0.0))
    theta_bet = 6.0 * ct / (params.solidity * a) + 1.5 * lam + alpha0
    beta_bet = params.lock_number / cf.flap_frequency ** 2 * ((theta_bet - alpha0) / 8.0 - lam / 6.0)

    return DerivedQuantities(
        blade_mass=params.blade_mass,
        flap_inertia=params.flap_inertia,
        lift_slope=params.lift_slope,
        lock_number=params.lock_number,
        solidity=params.solidity,
        thrust=thrust,
        thrust_coefficient=ct,
        ct_over_sigma=ct / params.solidity,
        inflow_ratio=lam,
        collective=collective,
        equilibrium=tuple(float(v) for v in z[:3]),
        chord_pitch=chord_pitch_to_hub_plane(*z[:3]),
        vacuum_equilibrium=tuple(float(v) for v in zv[:3]),
        blade_element_pitch=theta_bet,
        blade_element_coning=beta_bet,
        air_modes=air_modes,
        vacuum_modes=vac_modes,
        closed_forms=cf,
    )


@lru_cache(maxsize=64)
def pitch_mode(modes) -> Mode:
    """The oscillatory mode dominated by the pitch hinge (of highest frequency if there are
    several): the pitch-flap flutter candidate.

    Raises
    ------
    ValueError
        If no mode is oscillatory and pitch-dominated.
    """
    candidates = [m for m in modes if m.oscillatory and m.dominant_hinge == "pitch"]
    if not candidates:
        raise ValueError("no oscillatory pitch-dominated mode among the modes given")
    return max(candidates, key=lambda m: m.frequency)


def least_damped(modes) -> Mode:
    """The mode with the largest growth rate (the first to go unstable)."""
    return max(modes, key=lambda m: m.growth_rate)


def hover_modes(params: BladeParameters) -> tuple[Mode, ...]:
    """Linear modes with air at the hover equilibrium (trimmed if ``params.collective`` is
    None): the ``air_modes`` of :func:`derived_quantities` without the vacuum analysis."""
    blade = Blade(params)
    return modes_from_jacobian(blade.jacobian(0.0, blade.equilibrium()))
