"""rotorlyap: technical stability of a rotor blade by Liapunov's direct method.

A re-implementation of J. Narkiewicz & W. Lucjanek, "Investigation of helicopter rotor blade
motion stability by direct Liapunov method", 15th European Rotorcraft Forum, 1989.
"""

from .lyapunov import TechnicalStabilityResult, orbital_derivative, technical_stability

__all__ = ["TechnicalStabilityResult", "orbital_derivative", "technical_stability"]
