"""The blade model: parameters -> equations of the blade -> its steady motions.

* :mod:`~rotorlyap.model.parameters`: :class:`BladeParameters`, Table I and every assumed datum;
  :mod:`~rotorlyap.model.parameter_files`: a blade described in a TOML file;
* :mod:`~rotorlyap.model.airfoil`, :mod:`~rotorlyap.model.c81`, :mod:`~rotorlyap.model.inflow`,
  :mod:`~rotorlyap.model.compressibility`: section coefficients (built-in models and C81
  tables), the induced inflow, and compressibility with the range of the section model;
* :mod:`~rotorlyap.model.derivation`: Lagrange's equations with sympy.physics.mechanics, and the
  generated code in ``_generated/``;
* :mod:`~rotorlyap.model.mass`, :mod:`~rotorlyap.model.aero`, :mod:`~rotorlyap.model.equations`:
  the blade's mass properties, its strip aerodynamics (with the pitch-damping couple) and its
  equations of motion (with the hinge dampers); :mod:`~rotorlyap.model.compiled`: their compiled
  kernels;
* :mod:`~rotorlyap.model.equilibrium`, :mod:`~rotorlyap.model.trim`,
  :mod:`~rotorlyap.model.forward_trim`, :mod:`~rotorlyap.model.blade`: the hover equilibrium,
  the hover trim, the trim in forward flight, and :class:`Blade`;
* :mod:`~rotorlyap.model.steady`: the steady-motion type and the periodic motion in forward flight;
* :mod:`~rotorlyap.model.modes`: derived quantities (Lock number, frequencies, modes).

The model imports nothing from :mod:`rotorlyap.analysis`, the figures or the command line.
"""

from .blade import Blade
from .parameters import BladeParameters
from .steady import PeriodicMotion, SteadyMotion, periodic_motion
from .trim import HoverTrim, hover_trim

__all__ = ["Blade", "BladeParameters", "HoverTrim", "PeriodicMotion", "SteadyMotion",
           "hover_trim", "periodic_motion"]
