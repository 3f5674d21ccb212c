"""Blade, rotor and flight parameters: Table I of the paper plus every omitted datum.

:class:`BladeParameters` is a frozen dataclass in SI units (m, kg, s, rad, N).
Each field's docstring entry says where its value comes from: "Table I" (the
paper's blade data, Narkiewicz & Lucjanek 1989, realigned in
``shared/seed/READING.md``) or "assumed: <reason>".  :data:`FIELD_INFO` holds
the same information in machine-readable form and :func:`parameter_table`
turns a parameter set into rows for the book's assumptions table.

Geometry (``.notes/BLADE_SPEC.md``): the hub elements e1..e5 are fractions of
the blade length R1; e1, e3, e4 are radial (shaft -> flap hinge, flap hinge ->
lag hinge, lag hinge -> pitch hinge), e2 normal to the flap frame's plane
(height of the lag hinge above the flap hinge, along z_F; negative: below) and
e5 chordwise (feathering-axis offset from the pitch hinge, positive towards
the leading edge).  A chordwise reading of e2 (-3.4 cm towards the trailing
edge) would cock the blade 9.5 deg aft in lag by centrifugal force alone, a
hub no designer would build; the vertical reading has no such static effect.  The aerodynamic and massive blade runs from
``r = R - R1`` (the root cutout) to ``r = R``; between the pitch hinge and the
blade root is a rigid, massless cuff.  Chordwise positions are fractions of
chord behind the leading edge.

Spanwise variation: ``chord``, ``cg_position``, ``aerodynamic_centre`` and
``mass_per_length`` may each be a float or a callable ``f(r_over_R) ->
ndarray`` of the non-dimensional radius ``r/R``; use :meth:`BladeParameters.chord_at`
and friends to evaluate them.
"""

from __future__ import annotations

import functools
import math
import warnings
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import Any, Callable, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import TemplateValuesWarning
from .parameter_files import read_file, write_file
from .airfoil import NACA23012, Airfoil, LinearAirfoil


@functools.lru_cache(maxsize=16)
def gauss_legendre(n: int) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Nodes and weights of the ``n``-point Gauss-Legendre rule on ``[-1, 1]``
    (:func:`numpy.polynomial.legendre.leggauss`), computed once per ``n`` and kept read-only:
    every blade, trim iteration and mass integral asks for the same few rules, and numpy's
    eigenvalue computation of them cost more than the integrals."""
    x, w = np.polynomial.legendre.leggauss(int(n))
    x.setflags(write=False)
    w.setflags(write=False)
    return x, w


__all__ = [
    "BladeParameters",
    "BLADE_FIELDS",
    "CG_POSITIONS",
    "COMPRESSIBILITY_MODELS",
    "FIELD_INFO",
    "EXAMPLE_FILES",
    "FILE_AIRFOILS",
    "ROTOR_IDENTITY_FIELDS",
    "TEMPLATE_NAME",
    "TabulatedProfile",
    "INFLOW_MODELS",
    "ISA_SPEED_OF_SOUND",
    "MAX_PITCH_ANGLE",
    "TABLE_I_AIRFOIL",
    "THIN_AIRFOIL_CM_Q",
    "field_origins",
    "parameter_table",
]

INFLOW_MODELS: tuple[str, ...] = ("uniform", "glauert", "drees", "pitt-peters", "coleman")
"""Inflow models :func:`rotorlyap.model.inflow.kx_factor` knows (``BladeParameters.inflow_model``)."""

COMPRESSIBILITY_MODELS: tuple[str, ...] = ("none", "prandtl-glauert", "table")
"""Compressibility corrections of the section loads (``BladeParameters.compressibility``):
none, the Prandtl-Glauert lift slope with a drag rise (:mod:`rotorlyap.model.compressibility`),
or the section's own Mach dependence (``"table"``: a C81 table with several Mach columns,
:class:`rotorlyap.model.c81.C81Section`, read at the section Mach number; no correction on top)."""

#: ISA sea-level speed of sound, m/s (ICAO standard atmosphere: 340.294 m/s at 288.15 K).
ISA_SPEED_OF_SOUND: float = 340.294


#: Section centre-of-gravity positions of the paper's three cases, fraction of
#: chord behind the leading edge: neutral = at the Table I aerodynamic centre,
#: 0.235 c (the only chordwise reference Table I gives, and the point where a
#: C.G. is neutral for pitch-flap flutter); forward/backward = 0.02 c either
#: side (Table I computation parameters).
CG_POSITIONS: dict[str, float] = {"forward": 0.215, "neutral": 0.235, "backward": 0.255}

#: Pitch-damping derivative of quasi-steady thin-airfoil theory: the couple
#: ``-pi rho b^3 U q`` (b = c/2) of Theodorsen's loads with C(k) = 1, as a
#: moment coefficient per unit of the non-dimensional pitch rate ``q c / (2U)``.
THIN_AIRFOIL_CM_Q: float = -0.5 * math.pi

#: The Table I section: the NACA 23012 model with its moment reference moved
#: to the Table I aerodynamic centre, 0.235 c, so that the airfoil's ``cm`` is
#: about the point at which the blade applies the lift and drag.
TABLE_I_AIRFOIL: Airfoil = Airfoil(
    **{f.name: getattr(NACA23012, f.name) for f in fields(NACA23012) if f.init and f.name != "aerodynamic_centre"},
    aerodynamic_centre=0.235,
)

#: Parameter files of real blades from public data, shipped with the package (name -> path).
EXAMPLE_FILES: dict[str, Path] = {
    "sa330-puma": Path(__file__).resolve().parents[1] / "data" / "sa330_puma.toml",
}

#: Named sections a parameter file may use for ``airfoil`` (:meth:`BladeParameters.from_file`).
FILE_AIRFOILS: dict[str, Any] = {
    "table-i": TABLE_I_AIRFOIL,   # NACA 23012 with its moment about the Table I a.c. (the default)
    "naca23012": NACA23012,       # NACA 23012 with its moment about its own a.c., 0.247 c
    "linear": LinearAirfoil(),    # thin-airfoil linear section, cl = 2 pi alpha', either edge leading
}

Profile = Union[float, Callable[[NDArray[np.float64]], ArrayLike]]


@dataclass(frozen=True)
class TabulatedProfile:
    """A spanwise profile given as a table: piecewise linear in ``r/R`` between the stations,
    constant beyond the first and the last.

    A callable ``f(r_over_R)`` like any profile of :class:`BladeParameters` (chord, C.G.,
    aerodynamic centre, mass per length), and the one kind of callable a parameter file
    (:meth:`BladeParameters.to_file`) can hold.

    Parameters
    ----------
    r_over_R : tuple of float
        Stations, non-dimensional radius r/R, strictly increasing, at least 2.
    values : tuple of float
        The profile's value at each station, in the field's unit.
    """

    r_over_R: tuple[float, ...]
    values: tuple[float, ...]

    def __post_init__(self) -> None:
        r = tuple(_real(f"r_over_R[{i}]", v, "a radius r/R") for i, v in enumerate(self.r_over_R))
        v = tuple(_real(f"values[{i}]", x, "a finite value") for i, x in enumerate(self.values))
        if len(r) < 2 or len(r) != len(v):
            raise ValueError(f"a tabulated profile needs at least 2 stations and as many values as stations, "
                             f"got {len(r)} stations and {len(v)} values")
        if any(b <= a for a, b in zip(r, r[1:])):
            raise ValueError(f"the stations r_over_R of a tabulated profile must increase strictly, got {r}")
        object.__setattr__(self, "r_over_R", r)
        object.__setattr__(self, "values", v)

    def __call__(self, r_over_R: ArrayLike) -> NDArray[np.float64]:
        return np.interp(np.asarray(r_over_R, dtype=np.float64), self.r_over_R, self.values)

    @property
    def __name__(self) -> str:  # shown by parameter_table like a function's name
        return f"table of {len(self.r_over_R)} stations"

_M = "m"
#: (unit, source or reason) of every field; ``parameter_table`` uses it.
FIELD_INFO: dict[str, tuple[str, str]] = {
    "radius": (_M, "Table I"),
    "blade_length": (_M, "Table I"),
    "hub_elements": ("R1", "Table I (directions: assumed, our reading of the lost Fig. 3)"),
    "chord": (_M, "Table I"),
    "twist": ("rad", "Table I"),
    "pitch_flap_coupling": ("-", "Table I (tan delta3)"),
    "rotor_speed": ("rad/s", "Table I"),
    "pitch_stiffness": ("N m/rad", "Table I"),
    "lag_damping": ("N m s/rad", "Table I"),
    "flap_stiffness": ("N m/rad", "assumed: articulated hub, no flap spring"),
    "lag_stiffness": ("N m/rad", "assumed: articulated hub, no lag spring (the lag damper is the only restraint)"),
    "flap_damping": ("N m s/rad", "assumed: no flap damper on an articulated hub"),
    "pitch_damping": ("N m s/rad", "assumed: no damping in the control system (not given)"),
    "aerodynamic_centre": ("c", "Table I"),
    "pitch_axis": ("c", "assumed: quarter chord, the usual feathering-axis position"),
    "wind_point": ("c", "assumed: None, the angle of attack at the aerodynamic centre (steady coefficients at the instantaneous angle of attack, as the paper states); 0.75 is the quasi-steady three-quarter-chord option"),
    "cm_pitch_rate": ("-", "assumed: -pi/2, the pitch damping of quasi-steady thin-airfoil theory (Theodorsen, C(k) = 1); "
                           "0 = static coefficients only"),
    "cg_position": ("c", "Table I computation parameters (I 0.02c forward, II neutral, III 0.02c aft of the "
                         "aerodynamic centre; neutral = at the a.c. assumed)"),
    "mass_per_length": ("kg/m", "assumed: uniform, chosen for a Lock number of about 8 (typical articulated rotor)"),
    "pitch_radius_of_gyration": ("c", "assumed: 0.2 c about the section C.G., a spar-dominated section "
                                      "(a homogeneous plate would give 0.29 c)"),
    "n_blades": ("-", "assumed: 4, the PZL W-3 Sokol (R = 7.85 m, Omega = 28.35 rad/s)"),
    "helicopter_mass": ("kg", "assumed: 6400 kg, maximum take-off mass of the PZL W-3 Sokol"),
    "air_density": ("kg/m^3", "assumed: ISA sea level"),
    "gravity": ("m/s^2", "assumed: standard gravity"),
    "airfoil": ("-", "assumed: NACA 23012 (Table I a.c. at 0.235 c suggests a 230-series section)"),
    "inflow_model": ("-", "paper: Glauert's induced velocity (k_x = 1.2 assumed), table_i(); default: Pitt-Peters "
                          "(k_x grows with the wake skew, 0 in hover)"),
    "inflow_ratio": ("-", "assumed: None = momentum theory with thrust = weight"),
    "collective": ("rad", "assumed: None = trimmed so that hover thrust = weight"),
    "cyclic_cos": ("rad", "assumed: no cyclic pitch"),
    "cyclic_sin": ("rad", "assumed: no cyclic pitch"),
    "n_stations": ("-", "assumed: 12 Gauss-Legendre stations on the aerodynamic span"),
    "flat_plate_area": ("m^2", "assumed: 2.4 m^2, the UH-1B's 19.5 ft^2 at 9500 lb (Prouty1986, Table 4.3) "
                               "scaled to 6400 kg by weight^(2/3); f/A = 0.012"),
    "shaft_tilt": ("rad", "assumed: 0, untilted shaft (the paper's condition); set by the forward-flight trim"),
    "compressibility": ("-", "assumed: none (the paper's section model has no Mach dependence)"),
    "speed_of_sound": ("m/s", "assumed: ISA sea level, 340.294 m/s"),
}

_POSITIVE = ("radius", "blade_length", "rotor_speed", "helicopter_mass", "pitch_radius_of_gyration",
             "speed_of_sound")
_NONNEGATIVE = ("pitch_stiffness", "lag_damping", "flap_stiffness", "lag_stiffness", "flap_damping",
                "pitch_damping", "air_density", "gravity", "flat_plate_area")
_FINITE = ("twist", "pitch_flap_coupling", "cyclic_cos", "cyclic_sin", "cm_pitch_rate")
_FRACTION = ("pitch_axis",)
# profiles (float or callable of r/R) and what they must satisfy
_PROFILES = {"chord": "positive", "mass_per_length": "positive",
             "cg_position": "fraction", "aerodynamic_centre": "fraction"}
_RADIAL_HUB = (0, 2, 3)  # e1, e3, e4


def _is_real(v: Any) -> bool:
    return (not isinstance(v, (bool, np.bool_))) and isinstance(v, (int, float, np.integer, np.floating))


def _real(name: str, value: Any, allowed: str) -> float:
    """``value`` as a finite float, or TypeError/ValueError naming ``name``."""
    if not _is_real(value):
        raise TypeError(f"{name} must be a real number ({allowed}), got {value!r} of type {type(value).__name__}")
    v = float(value)
    if not math.isfinite(v):
        raise ValueError(f"{name} must be finite ({allowed}), got {v!r}")
    return v


def _int(name: str, value: Any, minimum: int) -> int:
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be an int >= {minimum}, got {value!r} of type {type(value).__name__}")
    if value < minimum:
        raise ValueError(f"{name} must be an int >= {minimum}, got {value!r}")
    return int(value)


def _profile_values(value: Profile, r: NDArray[np.float64]) -> NDArray[np.float64]:
    """Evaluate a float-or-callable spanwise profile at ``r`` (= r/R)."""
    if callable(value):
        return np.broadcast_to(np.asarray(value(r), dtype=np.float64), r.shape)
    return np.full(r.shape, float(value))


#: Largest pretwist accepted, rad: 40 deg. Larger values are almost always degrees given where
#: radians are expected.
MAX_PITCH_ANGLE: float = math.radians(40.0)


def _check_unit_slips(p: "BladeParameters") -> None:
    """Refuse values that are almost certainly in the wrong unit, saying the allowed range and
    the likely slip: a tip faster than sound at sea level (rpm given for rad/s; the check does not
    use ``speed_of_sound``, which a study may lower on purpose), a pretwist beyond 40 deg
    (degrees given for radians)."""
    tip_speed = p.rotor_speed * p.radius
    if tip_speed >= ISA_SPEED_OF_SOUND:
        raise ValueError(
            f"rotor_speed = {p.rotor_speed!r} rad/s gives a tip speed of {tip_speed:.0f} m/s, "
            f"{tip_speed / ISA_SPEED_OF_SOUND:.2f} times the sea-level speed of sound: the tip speed must be "
            f"below {ISA_SPEED_OF_SOUND} m/s. rotor_speed is in rad/s; if {p.rotor_speed!r} is in rpm, give "
            f"{p.rotor_speed * math.pi / 30.0:.4g} rad/s")
    # the controls (collective, cyclic) are left alone: the trims try wild values on their way
    for name in ("twist",):
        v = getattr(p, name)
        if v is not None and abs(v) > MAX_PITCH_ANGLE:
            raise ValueError(
                f"{name} = {v!r} rad is {math.degrees(v):.0f} deg, beyond the +-40 deg (+-0.698 rad) allowed: "
                f"{name} is in rad; if {v!r} is in degrees, give {math.radians(v):.4g} rad")


def _check_section_mach(airfoil: Any, compressibility: str) -> None:
    """Refuse a compressibility model that contradicts the section's own Mach dependence."""
    dependent = bool(getattr(airfoil, "mach_dependent", False))
    name = getattr(airfoil, "name", type(airfoil).__name__)
    if dependent and compressibility != "table":
        what = ("would apply the package's Prandtl-Glauert factor and drag rise on top of the table's "
                "own Mach dependence (compressibility twice)" if compressibility == "prandtl-glauert"
                else "asks for incompressible loads, but the table has no incompressible column to use")
        raise ValueError(f"compressibility = {compressibility!r} with the Mach-dependent section {name!r} "
                         f"{what}; use compressibility = 'table' (the table read at the section Mach number)")
    if compressibility == "table" and not dependent:
        raise ValueError(f"compressibility = 'table' reads the section's own Mach dependence, but the section "
                         f"{name!r} has none (a C81 table with one Mach column, or a package section); use "
                         f"'none' or 'prandtl-glauert', or a C81 table with two or more Mach columns")


@dataclass(frozen=True)
class BladeParameters:
    """Parameters of the isolated rigid blade, its rotor and the flight condition.

    All SI; see the module docstring for the geometry.  Construct the paper's
    cases with :meth:`table_i` and variants with :func:`dataclasses.replace`
    (which re-validates).

    Parameters
    ----------
    radius : float
        Rotor radius R, m.  Table I: 7.850 m.
    blade_length : float
        Blade length R1 (aerodynamic and massive span, root at ``R - R1``), m;
        must be <= ``radius`` (equal: the root at the shaft, the classical centrally
        hinged blade, whose radial hub elements e1, e3, e4 must then be 0).  Table I: 6.772 m.
    hub_elements : tuple of 5 float
        Hub element lengths e1..e5 divided by ``blade_length``, -.  Table I:
        (0.01, -0.005, 0.02, 0.03, 0.0); directions assumed (lost Fig. 3):
        e1, e3, e4 radial (>= 0), e2 vertical (lag hinge above the flap
        hinge, along z_F), e5 chordwise (positive towards the leading edge).
    chord : float or callable
        Chord c, m (or ``f(r/R)``).  Table I: 0.4 m, constant.
    twist : float
        Linear pretwist, tip minus root pitch angle, rad.  Table I: 0.
    pitch_flap_coupling : float
        tan(delta3), -; enters ``V = 0.5 K_theta (theta - theta_c + tan(delta3) beta)^2``.
        Table I: -0.4.
    rotor_speed : float
        Rotor speed Omega, rad/s.  Table I: 28.35 rad/s.
    pitch_stiffness : float
        Pitch-hinge (control-system) stiffness K_theta, N m/rad.  Table I: 6304.
    lag_damping : float
        Lag-hinge damper C_zeta, N m s/rad.  Table I: 10000.
    flap_stiffness, lag_stiffness : float
        Flap and lag hinge springs, N m/rad.  Assumed: 0 (articulated hub).
    flap_damping, pitch_damping : float
        Flap and pitch hinge dampers, N m s/rad.  Assumed: 0.
    aerodynamic_centre : float or callable
        Aerodynamic centre, fraction of chord behind the leading edge.
        Table I: 0.235.
    pitch_axis : float
        Feathering (pitch) axis, fraction of chord behind the leading edge.
        Assumed: 0.25, the usual quarter-chord feathering axis.
    wind_point : float or None
        Chordwise point, fraction of chord behind the leading edge, whose air
        velocity defines the section's relative wind and angle of attack; the
        loads act at the aerodynamic centre either way. Assumed: None, the
        aerodynamic centre itself: the paper's "steady coefficients at the
        instantaneous angle of attack" with no pitch-rate term. 0.75 gives the
        three-quarter-chord point of quasi-steady thin-airfoil theory
        (Pistolesi), which adds the lift due to pitch rate (but not the
        apparent-mass pitch damping).
    cm_pitch_rate : float
        Pitch-damping derivative ``cm_q`` of the section, -: a couple
        ``0.5 rho U^2 c^2 cm_q (q c / (2 U))`` about the spanwise axis, where
        ``U`` is the section's in-plane air speed and ``q`` its pitch rate
        relative to the rotating hub frame (which carries the rotational
        relative wind; rad/s).  Assumed: ``-pi/2``
        (:data:`THIN_AIRFOIL_CM_Q`), the couple ``-pi rho b^3 U q`` of
        quasi-steady thin-airfoil theory (Theodorsen's loads with C(k) = 1,
        about the quarter chord): the paper's "quasi-steady" aerodynamics with
        its one pitch-rate term.  0 keeps the static coefficients only, with no
        aerodynamic pitch damping at all; must be <= 0 (a negative damping
        derivative would feed energy into pitch).
    cg_position : float or callable
        Section centre of gravity, fraction of chord behind the leading edge.
        Table I computation parameters: 0.215 / 0.235 / 0.255 (forward /
        neutral / backward, 0.02 c about the aerodynamic centre; "neutral" = at
        the Table I aerodynamic centre is assumed).  Default: forward.
    mass_per_length : float or callable
        Blade mass per unit span, kg/m.  Assumed: 9.0 kg/m, uniform, which gives
        a Lock number of about 8 (typical of articulated rotors) with the
        NACA 23012 lift slope; blade mass 61 kg.
    pitch_radius_of_gyration : float
        Radius of gyration of the section mass about its C.G. in pitch,
        fraction of chord.  Assumed: 0.2 (mass concentrated in a spar near the
        quarter chord and a leading-edge balance weight; a homogeneous flat
        plate would give 1/sqrt(12) = 0.29); with K_theta this places the
        rotating pitch frequency near 4.6/rev, the usual range for a
        flexible control system.
    n_blades : int
        Number of blades, -.  Assumed: 4 (PZL W-3 Sokol, which R = 7.85 m and
        Omega = 28.35 rad/s match).
    helicopter_mass : float
        Helicopter mass supported by the rotor (thrust = weight), kg.
        Assumed: 6400 kg, the W-3 Sokol maximum take-off mass.
    air_density : float
        Air density rho, kg/m^3, >= 0 (0 = vacuum).  Assumed: 1.225, ISA sea level.
    gravity : float
        Gravitational acceleration along -Z, m/s^2, >= 0 (0 switches gravity
        off).  Assumed: 9.80665, standard gravity.
    airfoil : Airfoil or LinearAirfoil
        Section aerodynamics (constant along the span), any object with a
        ``coefficients(alpha) -> (cl, cd, cm)`` method.  Assumed: NACA 23012
        (:data:`TABLE_I_AIRFOIL`, moment about the Table I a.c.).
    inflow_model : str
        One of :data:`INFLOW_MODELS`.  Default: "pitt-peters", whose gradient ``k_x = 15 pi/32
        tan(chi/2)`` grows smoothly with the wake skew from 0 in hover; :meth:`table_i` uses the
        paper's Glauert ("glauert", a constant k_x = 1.2 switched on by any forward speed).
    inflow_ratio : float or None
        Mean induced inflow ratio lambda_0 = v_i / (Omega R), >= 0; None: from
        momentum theory with thrust = weight (:mod:`rotorlyap.model.inflow`).
    collective : float or None
        Collective pitch theta_0 at the pitch hinge, rad; None: trimmed so that
        the hover thrust equals the weight.
    cyclic_cos, cyclic_sin : float
        Cyclic pitch, ``theta_c = theta_0 + cyclic_cos cos psi + cyclic_sin sin psi``, rad.
        Assumed: 0 (the paper does not say whether cyclic is applied).
    n_stations : int
        Number of Gauss-Legendre stations on the aerodynamic span, >= 1.
        Assumed: 12.
    flat_plate_area : float
        Equivalent flat-plate (parasite drag) area ``f`` of the helicopter without its rotor, m^2,
        >= 0: the fuselage drag is ``0.5 rho V^2 f``, which the forward-flight trim balances.
        Assumed: 2.4 m^2, the UH-1B's 19.5 ft^2 (1.81 m^2) at 9500 lb [Prouty1986, Table 4.3]
        scaled to 6400 kg as weight^(2/3) (f/A = 0.012 of the Sokol's disc; the same table's
        UH-1B has 0.013, Prouty advises adding 20 % to such estimates).
    shaft_tilt : float
        Forward tilt of the rotor shaft from the vertical, rad, in (-30, 30) deg: the free stream
        ``V`` then has the in-plane part ``mu Omega R = V cos(shaft_tilt)`` and flows down through
        the disc at ``mu tan(shaft_tilt) Omega R``, added to the induced inflow. Assumed: 0 (the
        paper's untilted disc); :func:`rotorlyap.model.forward_trim.forward_flight_trim` sets it so
        that the rotor force balances the weight and the fuselage drag.
    compressibility : str
        One of :data:`COMPRESSIBILITY_MODELS`: ``"none"`` (the paper's incompressible sections),
        ``"prandtl-glauert"`` (:mod:`rotorlyap.model.compressibility`) or ``"table"`` (the
        airfoil's own Mach dependence, a Mach-dependent C81 table read at the section Mach number
        ``|w| / speed_of_sound``, with no correction on top). A Mach-dependent airfoil (attribute
        ``mach_dependent`` True) needs ``"table"``, and ``"table"`` needs one: the other
        combinations would apply compressibility twice or not use the table's. Assumed: "none".
    speed_of_sound : float
        Speed of sound, m/s, > 0 (the section Mach number is the section air speed over it).
        Assumed: 340.294, ISA sea level.
    """

    radius: float = 7.85
    blade_length: float = 6.772
    hub_elements: tuple[float, float, float, float, float] = (0.01, -0.005, 0.02, 0.03, 0.0)
    chord: Profile = 0.4
    twist: float = 0.0
    pitch_flap_coupling: float = -0.4
    rotor_speed: float = 28.35
    pitch_stiffness: float = 6304.0
    lag_damping: float = 10000.0
    flap_stiffness: float = 0.0
    lag_stiffness: float = 0.0
    flap_damping: float = 0.0
    pitch_damping: float = 0.0
    aerodynamic_centre: Profile = 0.235
    pitch_axis: float = 0.25
    wind_point: float | None = None
    cm_pitch_rate: float = THIN_AIRFOIL_CM_Q
    cg_position: Profile = 0.215
    mass_per_length: Profile = 9.0
    pitch_radius_of_gyration: float = 0.2
    n_blades: int = 4
    helicopter_mass: float = 6400.0
    air_density: float = 1.225
    gravity: float = 9.80665
    airfoil: Any = field(default=TABLE_I_AIRFOIL)
    inflow_model: str = "pitt-peters"
    inflow_ratio: float | None = None
    collective: float | None = None
    cyclic_cos: float = 0.0
    cyclic_sin: float = 0.0
    n_stations: int = 12
    flat_plate_area: float = 2.4
    shaft_tilt: float = 0.0
    compressibility: str = "none"
    speed_of_sound: float = ISA_SPEED_OF_SOUND

    # ------------------------------------------------------------------ validation
    def __post_init__(self) -> None:
        set_ = lambda name, v: object.__setattr__(self, name, v)  # noqa: E731

        for name in _POSITIVE:
            v = _real(name, getattr(self, name), "> 0")
            if not v > 0:
                raise ValueError(f"{name} must be > 0, got {v!r}")
            set_(name, v)
        for name in _NONNEGATIVE:
            v = _real(name, getattr(self, name), ">= 0")
            if v < 0:
                raise ValueError(f"{name} must be >= 0, got {v!r}")
            set_(name, v)
        for name in _FINITE:
            set_(name, _real(name, getattr(self, name), "any finite value"))
        if self.cm_pitch_rate > 0:
            raise ValueError(f"cm_pitch_rate must be <= 0 (a damping derivative; 0 = no aerodynamic pitch "
                             f"damping, -pi/2 = thin-airfoil theory), got {self.cm_pitch_rate!r}")
        for name in _FRACTION:
            v = _real(name, getattr(self, name), "a fraction of chord in [0, 1]")
            if not 0.0 <= v <= 1.0:
                raise ValueError(f"{name} must lie in [0, 1] (fraction of chord behind the leading edge), got {v!r}")
            set_(name, v)
        if self.wind_point is not None:
            v = _real("wind_point", self.wind_point, "None or a fraction of chord in [0, 1]")
            if not 0.0 <= v <= 1.0:
                raise ValueError(f"wind_point must be None or lie in [0, 1] (fraction of chord behind the leading edge), got {v!r}")
            set_("wind_point", v)
        for name in ("inflow_ratio", "collective"):
            v = getattr(self, name)
            if v is not None:
                allowed = "None or a finite value >= 0" if name == "inflow_ratio" else "None or a finite value"
                v = _real(name, v, allowed)
                if name == "inflow_ratio" and v < 0:
                    raise ValueError(f"inflow_ratio must be None or >= 0, got {v!r}")
                set_(name, v)
        tilt = _real("shaft_tilt", self.shaft_tilt, "a tilt in (-30, 30) deg = (-0.5236, 0.5236) rad")
        if not abs(tilt) < math.radians(30.0):
            raise ValueError(f"shaft_tilt must lie in (-30, 30) deg = (-0.5236, 0.5236) rad (positive forward), "
                             f"got {tilt!r}")
        set_("shaft_tilt", tilt)
        if not isinstance(self.compressibility, str) or self.compressibility not in COMPRESSIBILITY_MODELS:
            raise ValueError(f"compressibility must be one of {COMPRESSIBILITY_MODELS}, got {self.compressibility!r}")
        set_("n_blades", _int("n_blades", self.n_blades, 1))
        set_("n_stations", _int("n_stations", self.n_stations, 1))

        if self.blade_length > self.radius:
            raise ValueError(f"blade_length must be <= radius = {self.radius!r} m (the blade root lies "
                             f"at or outboard of the shaft; equal: a blade hinged at the shaft, with "
                             f"every radial hub element 0), got {self.blade_length!r}")
        _check_unit_slips(self)

        he = self.hub_elements
        if isinstance(he, (str, bytes)) or not hasattr(he, "__len__"):
            raise TypeError(f"hub_elements must be a sequence of 5 real numbers, got {he!r}")
        if len(he) != 5:
            raise ValueError(f"hub_elements must have 5 entries (e1..e5), got {len(he)}: {he!r}")
        he = tuple(_real(f"hub_elements[{i}] (e{i + 1})", e, "finite, fraction of blade_length")
                   for i, e in enumerate(he))
        for i in _RADIAL_HUB:
            if he[i] < 0:
                raise ValueError(f"hub_elements[{i}] (e{i + 1}, radial) must be >= 0, got {he[i]!r}")
        reach = (he[0] + he[2] + he[3]) * self.blade_length
        if reach > self.root_cutout * (1.0 + 1e-12):
            raise ValueError(f"hub_elements: the pitch hinge at (e1 + e3 + e4) R1 = {reach!r} m lies outboard "
                             f"of the blade root R - R1 = {self.root_cutout!r} m; allowed: <= R - R1")
        set_("hub_elements", he)

        r = self.span_grid(65)
        for name, kind in _PROFILES.items():
            v = getattr(self, name)
            if callable(v):
                try:
                    vals = _profile_values(v, r)
                except Exception as exc:  # a failing user callable
                    raise ValueError(f"{name}: callable f(r_over_R) failed on the span "
                                     f"[{r[0]:.4f}, 1]: {exc}") from exc
            else:
                v = _real(name, v, "> 0" if kind == "positive" else "a fraction of chord in [0, 1]")
                set_(name, v)
                vals = np.array([v])
            if not np.all(np.isfinite(vals)):
                raise ValueError(f"{name} must be finite on the span, got {v!r}")
            if kind == "positive" and not np.all(vals > 0):
                raise ValueError(f"{name} must be > 0 on the span, got {v!r} (smallest value on the span: {float(vals.min()):.6g})")
            if kind == "fraction" and not np.all((vals >= 0) & (vals <= 1)):
                raise ValueError(f"{name} must lie in [0, 1] (fraction of chord behind the leading edge) "
                                 f"on the span, got {v!r}")

        if not isinstance(self.inflow_model, str):
            raise TypeError(f"inflow_model must be a str, one of {INFLOW_MODELS}, got {self.inflow_model!r}")
        if self.inflow_model not in INFLOW_MODELS:
            raise ValueError(f"inflow_model must be one of {INFLOW_MODELS}, got {self.inflow_model!r}")

        if not (isinstance(self.airfoil, (Airfoil, LinearAirfoil))
                or callable(getattr(self.airfoil, "coefficients", None))):
            raise TypeError("airfoil must be an Airfoil, a LinearAirfoil or an object with a "
                            f"coefficients(alpha) method, got {self.airfoil!r}")
        _check_section_mach(self.airfoil, self.compressibility)
        _warn_template(self)

    # ------------------------------------------------------------------ cases
    @classmethod
    def table_i(cls, cg: str = "forward", **overrides: Any) -> "BladeParameters":
        """The paper's blade (Table I) with one of its three C.G. positions, and the paper's
        Glauert inflow (``inflow_model="glauert"`` unless overridden).

        Parameters
        ----------
        cg : {"forward", "neutral", "backward"}
            Section C.G. 0.02 c ahead of, on, or 0.02 c behind the Table I
            aerodynamic centre (0.215, 0.235, 0.255 c behind the leading edge).
        **overrides
            Further field values (e.g. ``air_density=0.0``).

        Returns
        -------
        BladeParameters

        Raises
        ------
        ValueError
            If ``cg`` is not one of the three names.
        """
        if not isinstance(cg, str) or cg not in CG_POSITIONS:
            raise ValueError(f"cg must be one of {tuple(CG_POSITIONS)}, got {cg!r}")
        overrides.setdefault("inflow_model", "glauert")  # the paper's inflow
        return cls(cg_position=CG_POSITIONS[cg], **overrides)

    @classmethod
    def flight_case(cls, cg: str = "forward", **overrides: Any) -> "BladeParameters":
        """The Table I blade in the report's forward-flight model: the paper's blade and
        helicopter (:meth:`table_i`) with a skew-dependent inflow ("pitt-peters") and compressible
        sections ("prandtl-glauert"), for :func:`rotorlyap.model.forward_trim.forward_flight_trim`.

        Parameters
        ----------
        cg : {"forward", "neutral", "backward"}
            As in :meth:`table_i`.
        **overrides
            Further field values.

        Returns
        -------
        BladeParameters
        """
        overrides.setdefault("inflow_model", "pitt-peters")
        overrides.setdefault("compressibility", "prandtl-glauert")
        return cls.table_i(cg, **overrides)

    # ------------------------------------------------------------------ files
    @classmethod
    def from_file(cls, path: str | Path) -> "BladeParameters":
        """Read a parameter file (TOML, schema ``rotorlyap.blade/1``: :mod:`rotorlyap.model.parameter_files`).

        Parameters
        ----------
        path : str or pathlib.Path

        Returns
        -------
        BladeParameters

        Raises
        ------
        ValueError, TypeError
            A file of another schema, an unknown key or a value the field does not allow; the
            message names the file and the field.

        Warns
        -----
        rotorlyap.errors.TemplateValuesWarning
            Blade fields the file leaves out (they take the Table I template's values).
        """
        path = Path(path)
        values = read_file(path, [f.name for f in fields(cls)], FILE_AIRFOILS, TabulatedProfile)
        with warnings.catch_warnings():
            # the file says exactly which fields it gives: the warning below names those it leaves out
            warnings.simplefilter("ignore", TemplateValuesWarning)
            try:
                params = cls(**values)
            except (TypeError, ValueError) as exc:
                raise type(exc)(f"{path}: {exc}") from exc
        missing = [n for n in BLADE_FIELDS if n not in values]
        _WARNED.add(_rotor_key(params))  # this warning, not the by-value one, for the file's rotor
        if missing:
            warnings.warn(
                f"{path} leaves out {len(missing)} of the {len(BLADE_FIELDS)} blade fields, which take the "
                f"template {TEMPLATE_NAME} values: "
                + "; ".join(_describe(n, getattr(params, n)) for n in missing)
                + ". Give your blade's value of each, or filter rotorlyap.errors.TemplateValuesWarning to keep "
                  "them knowingly.", TemplateValuesWarning, stacklevel=2)
        return params

    def to_file(self, path: str | Path, *, name: str | None = None,
                sources: dict[str, str] | None = None) -> Path:
        """Write the parameters as a TOML file that :meth:`from_file` reads back equal
        (:func:`rotorlyap.model.parameter_files.write_parameters`).

        Parameters
        ----------
        path : str or pathlib.Path
        name : str, optional
            The blade's name (``[about]``).
        sources : dict, optional
            ``{field: citation}`` (``[about.sources]``).

        Returns
        -------
        pathlib.Path
        """
        origins = field_origins(self)
        entries = [(f.name, getattr(self, f.name), f"{FIELD_INFO[f.name][0]}; {origins[f.name]}")
                   for f in fields(self)]
        return write_file(path, entries, FILE_AIRFOILS, TabulatedProfile, name=name,
                                          sources=sources)

    # ------------------------------------------------------------------ geometry
    @property
    def hub_element_lengths(self) -> tuple[float, float, float, float, float]:
        """Hub elements e1..e5 in metres (``hub_elements * blade_length``)."""
        return tuple(e * self.blade_length for e in self.hub_elements)  # type: ignore[return-value]

    @property
    def root_cutout(self) -> float:
        """Radial distance from the shaft to the blade root, ``R - R1``, m."""
        return self.radius - self.blade_length

    @property
    def root_r_over_R(self) -> float:
        """Non-dimensional radius of the blade root, ``(R - R1)/R``, -."""
        return self.root_cutout / self.radius

    @property
    def flap_hinge_offset(self) -> float:
        """Radial position of the flap hinge, ``e1 R1``, m."""
        return self.hub_elements[0] * self.blade_length

    @property
    def pitch_hinge_radius(self) -> float:
        """Radial position of the pitch hinge at zero hinge angles, ``(e1 + e3 + e4) R1``, m."""
        e = self.hub_elements
        return (e[0] + e[2] + e[3]) * self.blade_length

    @property
    def tip_speed(self) -> float:
        """Tip speed ``Omega R``, m/s."""
        return self.rotor_speed * self.radius

    def span_grid(self, n: int = 65) -> NDArray[np.float64]:
        """``n`` equally spaced values of r/R from the blade root to the tip."""
        return np.linspace(self.root_r_over_R, 1.0, n)

    def stations(self) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
        """Gauss-Legendre quadrature on the aerodynamic span.

        Returns
        -------
        r_over_R : ndarray, shape (n_stations,)
            Station radii, r/R.
        weights : ndarray, shape (n_stations,)
            Weights for integrals in r/R: ``sum(w f(r)) ~ int_{(R-R1)/R}^1 f dx``
            (multiply by R for integrals in metres).
        """
        x, w = gauss_legendre(self.n_stations)
        a, b = self.root_r_over_R, 1.0
        return 0.5 * (b - a) * x + 0.5 * (b + a), 0.5 * (b - a) * w

    # ------------------------------------------------------------------ spanwise profiles
    def chord_at(self, r_over_R: ArrayLike) -> NDArray[np.float64]:
        """Chord at ``r_over_R`` (broadcast), m."""
        return _profile_values(self.chord, np.asarray(r_over_R, dtype=np.float64))

    def cg_position_at(self, r_over_R: ArrayLike) -> NDArray[np.float64]:
        """Section C.G. at ``r_over_R``, fraction of chord behind the leading edge."""
        return _profile_values(self.cg_position, np.asarray(r_over_R, dtype=np.float64))

    def aerodynamic_centre_at(self, r_over_R: ArrayLike) -> NDArray[np.float64]:
        """Aerodynamic centre at ``r_over_R``, fraction of chord behind the leading edge."""
        return _profile_values(self.aerodynamic_centre, np.asarray(r_over_R, dtype=np.float64))

    def mass_per_length_at(self, r_over_R: ArrayLike) -> NDArray[np.float64]:
        """Mass per unit span at ``r_over_R``, kg/m."""
        return _profile_values(self.mass_per_length, np.asarray(r_over_R, dtype=np.float64))

    # ------------------------------------------------------------------ derived quantities
    def _span_integral(self, f: Callable[[NDArray[np.float64]], NDArray[np.float64]], n: int = 64) -> float:
        """int_{R-R1}^{R} f(r/R) dr in metres-units, by n-point Gauss-Legendre."""
        x, w = gauss_legendre(n)
        a, b = self.root_r_over_R, 1.0
        xr = 0.5 * (b - a) * x + 0.5 * (b + a)
        return float(np.sum(0.5 * (b - a) * w * f(xr)) * self.radius)

    @property
    def blade_mass(self) -> float:
        """Blade mass (the cuff is massless), kg."""
        return self._span_integral(self.mass_per_length_at)

    @property
    def flap_inertia(self) -> float:
        """Flap moment of inertia I_beta of the blade about the flap hinge, kg m^2.

        Point-mass sections (chordwise and pitch inertia ignored), zero hinge angles.
        """
        e = self.flap_hinge_offset
        return self._span_integral(lambda x: self.mass_per_length_at(x) * (x * self.radius - e) ** 2)

    @property
    def lift_slope(self) -> float:
        """Lift-curve slope of the section, 1/rad (``airfoil.lift_slope`` or a +-1 deg difference)."""
        a = getattr(self.airfoil, "lift_slope", None)
        if a is not None:
            return float(a)
        d = math.radians(1.0)
        cl_p = self.airfoil.coefficients(np.array(d))[0]
        cl_m = self.airfoil.coefficients(np.array(-d))[0]
        return float((cl_p - cl_m) / (2 * d))

    @property
    def lock_number(self) -> float:
        """Lock number ``gamma = rho a c R^4 / I_beta`` (c at 0.75 R), -."""
        c = float(self.chord_at(0.75))
        return self.air_density * self.lift_slope * c * self.radius ** 4 / self.flap_inertia

    @property
    def solidity(self) -> float:
        """Rotor solidity ``N c / (pi R)`` (c at 0.75 R, the conventional definition), -."""
        return self.n_blades * float(self.chord_at(0.75)) / (math.pi * self.radius)

    @property
    def weight(self) -> float:
        """Helicopter weight ``helicopter_mass * gravity``, N."""
        return self.helicopter_mass * self.gravity

    @property
    def blade_loading(self) -> float:
        """Blade loading ``C_T / sigma`` of a thrust equal to the weight, -:
        ``W / (rho pi R^2 (Omega R)^2 sigma)`` (infinite in vacuum)."""
        disc = self.air_density * math.pi * self.radius ** 2 * self.tip_speed ** 2 * self.solidity
        return self.weight / disc if disc > 0 else math.inf

    def pitch_at(self, r_over_R: float, collective: float | None = None) -> float:
        """Pitch of the section at ``r_over_R`` for a collective at the pitch hinge (root pitch),
        rad: ``collective + twist (r - (R - R1)) / R1`` (``collective`` defaults to the field)."""
        c = self.collective if collective is None else collective
        if c is None:
            raise ValueError("pitch_at needs a collective: the field is None (trimmed) and none was given")
        return float(c + self.twist * (r_over_R * self.radius - self.root_cutout) / self.blade_length)


# ---------------------------------------------------------------------- provenance
#: The template every field not given comes from: the class defaults are the paper's blade
#: (Table I) with the report's assumptions for what the paper omits.
TEMPLATE_NAME: str = "Table I"

#: The fields that describe the blade, its hub and the helicopter (the others are the flight
#: condition and the options of the model). A user describing another blade must give each.
BLADE_FIELDS: tuple[str, ...] = (
    "radius", "blade_length", "hub_elements", "chord", "twist", "pitch_flap_coupling", "rotor_speed",
    "pitch_stiffness", "lag_damping", "flap_stiffness", "lag_stiffness", "flap_damping", "pitch_damping",
    "aerodynamic_centre", "pitch_axis", "cg_position", "mass_per_length", "pitch_radius_of_gyration",
    "n_blades", "helicopter_mass", "airfoil", "flat_plate_area",
)

#: The fields that identify a rotor: a parameter set with another value of any of them describes
#: another rotor than the paper's, and its other blade fields must not silently stay Table I's.
ROTOR_IDENTITY_FIELDS: tuple[str, ...] = ("radius", "blade_length", "rotor_speed", "n_blades")

#: Rotors already warned about (key: the values of :data:`ROTOR_IDENTITY_FIELDS`): the trims,
#: analyses and a user's studies rebuild a blade many times with ``dataclasses.replace``; one
#: warning per rotor and process is enough (a file read warns once, precisely, for its rotor).
_WARNED: set = set()


def _same(a: Any, b: Any) -> bool:
    try:
        return type(a) is type(b) and bool(a == b)
    except Exception:  # noqa: BLE001 (an exotic airfoil object)
        return False


def _template_values(name: str) -> tuple:
    """The values of field ``name`` that count as the template's: the class default, the paper's
    inflow model (:meth:`BladeParameters.table_i`) and the three Table I C.G. positions."""
    f = BladeParameters.__dataclass_fields__[name]
    values = [f.default]
    if name == "cg_position":
        values += list(CG_POSITIONS.values())
    elif name == "inflow_model":
        values.append("glauert")
    return tuple(values)


def _is_template(name: str, value: Any) -> bool:
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return any(isinstance(t, (int, float)) and float(t) == float(value) for t in _template_values(name))
    return any(_same(value, t) for t in _template_values(name))


def field_origins(params: BladeParameters) -> dict[str, str]:
    """Where each field's value comes from: ``"given"`` or ``"template Table I"``.

    A field whose value equals the template's (:data:`TEMPLATE_NAME`: the class default, any of the
    three Table I C.G. positions, the paper's Glauert inflow) is ``"template Table I"``, whether it
    was left out or given equal; any other value is ``"given"``. The comparison is by value, so it
    survives :func:`dataclasses.replace` and files (:meth:`BladeParameters.from_file`).

    Parameters
    ----------
    params : BladeParameters

    Returns
    -------
    dict
        ``{field name: "given" | "template Table I"}`` in field order.
    """
    return {f.name: (f"template {TEMPLATE_NAME}" if _is_template(f.name, getattr(params, f.name)) else "given")
            for f in fields(params)}


def _other_rotor(params: BladeParameters) -> tuple[str, ...]:
    """The identity fields in which ``params`` differs from the template (empty: the Table I rotor)."""
    return tuple(n for n in ROTOR_IDENTITY_FIELDS if not _is_template(n, getattr(params, n)))


def _describe(name: str, value: Any) -> str:
    unit = FIELD_INFO[name][0]
    if name == "airfoil":
        return f"airfoil = {getattr(value, 'name', value)!s}"
    unit = "" if unit in ("-", "") else f" {unit}"
    return f"{name} = {value!r}{unit}"


def _rotor_key(params: BladeParameters) -> tuple:
    return tuple(repr(getattr(params, n)) for n in ROTOR_IDENTITY_FIELDS)


def _warn_template(params: BladeParameters) -> None:
    """Warn (once per rotor) when another rotor keeps blade fields of the Table I template."""
    other = _other_rotor(params)
    if not other:
        return
    kept = tuple(n for n in BLADE_FIELDS if _is_template(n, getattr(params, n)))
    if not kept:
        return
    key = _rotor_key(params)
    if key in _WARNED:
        return
    _WARNED.add(key)
    warnings.warn(
        f"BladeParameters: {', '.join(other)} {'describe' if len(other) > 1 else 'describes'} another rotor than Table I's, but {len(kept)} of its "
        f"{len(BLADE_FIELDS)} blade fields keep the template {TEMPLATE_NAME} values: "
        + "; ".join(_describe(n, getattr(params, n)) for n in kept)
        + ". Give your blade's value of each (parameter_table(params) marks every field 'given' or "
          f"'template {TEMPLATE_NAME}'); to keep them knowingly, filter "
          "rotorlyap.errors.TemplateValuesWarning.",
        TemplateValuesWarning, stacklevel=_caller_level())


def _caller_level() -> int:
    """``stacklevel`` for a warning issued two calls below here that names the first caller
    outside rotorlyap and :mod:`dataclasses` (the user's line, also through ``replace``)."""
    import sys
    frame, level = sys._getframe(2), 2
    package = str(Path(__file__).resolve().parents[1])
    while frame is not None:
        filename = frame.f_code.co_filename
        if not (filename.startswith(package) or filename.endswith("dataclasses.py") or filename == "<string>"):
            return level
        frame, level = frame.f_back, level + 1
    return 2


def parameter_table(params: BladeParameters) -> list[tuple[str, Any, str, str]]:
    """Rows (name, value, unit, source) for the book's parameter/assumption table.

    The source tells a given value from a template one (:func:`field_origins`): ``"given"`` for a
    value that differs from the template's; otherwise the template's source or reason
    (:data:`FIELD_INFO`: "Table I", "assumed: ..."), prefixed ``"template Table I: "`` when
    ``params`` describes another rotor than Table I's (:data:`ROTOR_IDENTITY_FIELDS`), where such a
    value is a leftover of the template rather than a datum of the blade.

    Parameters
    ----------
    params : BladeParameters

    Returns
    -------
    list of (str, object, str, str)
        One row per field, in field order; the value is shown as given
        (callables and the airfoil by their repr/name).
    """
    origins = field_origins(params)
    prefix = f"template {TEMPLATE_NAME}: " if _other_rotor(params) else ""
    rows = []
    for f in fields(params):
        value = getattr(params, f.name)
        if f.name == "airfoil":
            value = getattr(value, "name", repr(value))
        elif callable(value):
            value = getattr(value, "__name__", repr(value))
        unit, source = FIELD_INFO[f.name]
        rows.append((f.name, value, unit, "given" if origins[f.name] == "given" else prefix + source))
    return rows
