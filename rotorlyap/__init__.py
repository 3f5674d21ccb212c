"""rotorlyap: technical stability of a rotor blade by Liapunov's direct method.

A re-implementation of J. Narkiewicz & W. Lucjanek, "Investigation of helicopter rotor blade
motion stability by direct Liapunov method", 15th European Rotorcraft Forum, 1989.

Public names: the general engine (:func:`technical_stability`), simulation helpers, the
blade model (:class:`BladeParameters`, :class:`Blade`, :func:`hover_trim`), the blade in the
engine (:func:`blade_stability`) and Floquet theory (:func:`floquet_multipliers`).
"""

from .airfoil import Airfoil, LinearAirfoil, NACA23012
from .blade import Blade, EnergyFunction
from .floquet import FloquetResult, floquet_multipliers
from .lyapunov import TechnicalStabilityResult, orbital_derivative, technical_stability
from .parameters import BladeParameters
from .simulation import SimulationResult, scaled_norm, simulate
from .stability import blade_stability
from .trim import HoverTrim, hover_trim

__all__ = [
    "Airfoil", "LinearAirfoil", "NACA23012",
    "Blade", "EnergyFunction",
    "FloquetResult", "floquet_multipliers", "blade_stability",
    "TechnicalStabilityResult", "orbital_derivative", "technical_stability",
    "BladeParameters",
    "SimulationResult", "scaled_norm", "simulate",
    "HoverTrim", "hover_trim",
]
