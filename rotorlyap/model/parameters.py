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

import math
from dataclasses import dataclass, field, fields
from typing import Any, Callable, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .airfoil import NACA23012, Airfoil, LinearAirfoil

__all__ = [
    "BladeParameters",
    "CG_POSITIONS",
    "COMPRESSIBILITY_MODELS",
    "FIELD_INFO",
    "INFLOW_MODELS",
    "ISA_SPEED_OF_SOUND",
    "MAX_PITCH_ANGLE",
    "TABLE_I_AIRFOIL",
    "THIN_AIRFOIL_CM_Q",
    "parameter_table",
]

INFLOW_MODELS: tuple[str, ...] = ("uniform", "glauert", "drees", "pitt-peters", "coleman")
"""Inflow models :func:`rotorlyap.model.inflow.kx_factor` knows (``BladeParameters.inflow_model``)."""

COMPRESSIBILITY_MODELS: tuple[str, ...] = ("none", "prandtl-glauert")
"""Compressibility corrections of the section loads (``BladeParameters.compressibility``):
none, or the Prandtl-Glauert lift slope with a drag rise (:mod:`rotorlyap.model.compressibility`)."""

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

Profile = Union[float, Callable[[NDArray[np.float64]], ArrayLike]]

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
        must be < ``radius``.  Table I: 6.772 m.
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
        One of :data:`COMPRESSIBILITY_MODELS`: ``"none"`` (the paper's incompressible sections)
        or ``"prandtl-glauert"`` (:mod:`rotorlyap.model.compressibility`).  Assumed: "none".
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

        if self.blade_length >= self.radius:
            raise ValueError(f"blade_length must be < radius = {self.radius!r} m (the blade root lies "
                             f"outboard of the shaft), got {self.blade_length!r}")
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
        x, w = np.polynomial.legendre.leggauss(self.n_stations)
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
        x, w = np.polynomial.legendre.leggauss(n)
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


def parameter_table(params: BladeParameters) -> list[tuple[str, Any, str, str]]:
    """Rows (name, value, unit, source) for the book's parameter/assumption table.

    Parameters
    ----------
    params : BladeParameters

    Returns
    -------
    list of (str, object, str, str)
        One row per field, in field order; the value is shown as given
        (callables and the airfoil by their repr/name).
    """
    rows = []
    for f in fields(params):
        value = getattr(params, f.name)
        if f.name == "airfoil":
            value = getattr(value, "name", repr(value))
        elif callable(value):
            value = getattr(value, "__name__", repr(value))
        unit, source = FIELD_INFO[f.name]
        rows.append((f.name, value, unit, source))
    return rows
